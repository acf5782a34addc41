/* Proxima's OpenXR device: an XR controller's grip pose holds the tool, the
 * rendered force comes back as the controller's vibration.
 *
 * The application owns OpenXR; Proxima borrows it. The app hands over its
 * XrInstance, XrSession, world space, actions and its xrGetInstanceProcAddr,
 * and Proxima makes every OpenXR call through that pointer (libproxima links
 * no OpenXR loader). The app keeps polling events (forwarding session state
 * changes), syncing actions (with the set that holds Proxima's actions) and
 * running its frame loop; Proxima's own thread only locates the pose space
 * and sends vibrations, which OpenXR allows concurrently. The integrator's
 * checklist and the engine hooks are in docs/openxr.md; the walkthrough is
 * samples/openxr/openxr_sample.c.
 *
 * Built when libproxima was configured with PROX_WITH_OPENXR; needs the
 * OpenXR headers (Debian: libopenxr-dev), not its loader. */
#ifndef PROXIMA_PROXIMA_OPENXR_H
#define PROXIMA_PROXIMA_OPENXR_H

#include <openxr/openxr.h>

#include "proxima/proxima.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct proxXrDeviceId {
  uint32_t index1; /* 0: the null id */
  uint32_t generation;
} proxXrDeviceId;

typedef enum proxXrPoseMode {
  /* Locate the pose space at "now" on every tick of the device's 1 kHz
   * thread (the freshest pose; one xrLocateSpace per millisecond). */
  PROX_XR_LOCATE_EACH_TICK = 0,
  /* Locate it once a frame, at the frame's predicted display time, with its
   * velocity (XrSpaceVelocity), and extrapolate to "now" on every tick. */
  PROX_XR_EXTRAPOLATE_FRAME = 1,
  PROX_XR_POSE_MODE_FORCE32 = 0x7FFFFFFF
} proxXrPoseMode;

/* Where the device's "now" (an XrTime) comes from, first that has one:
 * the app's time conversion extension, the frames the app reports, else
 * the device's own monotonic clock (docs/openxr.md, "Threads and time"). */
typedef enum proxXrTimeSource {
  /* No time yet: no locate, the tick counts as untracked. */
  PROX_XR_TIME_NONE = 0,
  /* XR_KHR_convert_timespec_time (def.timespecTime). */
  PROX_XR_TIME_TIMESPEC = 1,
  /* XR_KHR_win32_convert_performance_counter_time (def.win32PerformanceCounterTime). */
  PROX_XR_TIME_WIN32_PERFORMANCE_COUNTER = 2,
  /* The last predicted display time (proxXrDevice_OnFrame), advanced by the monotonic clock. */
  PROX_XR_TIME_FRAMES = 3,
  /* The device's monotonic clock from the newest time the runtime accepted
   * (a locate that succeeded, def.runtimeTime, proxXrDevice_OnRuntimeTime). */
  PROX_XR_TIME_OWN_CLOCK = 4,
  PROX_XR_TIME_SOURCE_FORCE32 = 0x7FFFFFFF
} proxXrTimeSource;

typedef struct proxXrDeviceDef {
  int32_t apiVersion; /* PROX_API_VERSION, set by proxDefaultXrDeviceDef() */
  PFN_xrGetInstanceProcAddr getInstanceProcAddr; /* the app's: every call goes through it */
  XrInstance instance;
  XrSession session;
  XrSpace baseSpace;            /* the app's world space (LOCAL or STAGE) */
  XrAction poseAction;          /* XR_ACTION_TYPE_POSE_INPUT, in a set the app attached and syncs */
  XrAction hapticAction;        /* XR_ACTION_TYPE_VIBRATION_OUTPUT, or XR_NULL_HANDLE: no vibration */
  XrPath subactionPath;         /* e.g. /user/hand/right, or XR_NULL_PATH */
  proxPose toolInGrip;          /* the tool's pose in the grip space (default identity) */
  proxPose baseToWorld;         /* baseSpace's pose in Proxima's world (default identity) */
  proxXrPoseMode poseMode;      /* default PROX_XR_LOCATE_EACH_TICK */
  double vibrationRate;         /* Hz, in (0, 1000]: vibrations sent at most this often (default 100) */
  double forceForFullAmplitude; /* N: the force rendered as amplitude 1 (default 5; above it, 1) */
  proxBool timespecTime; /* the app enabled XR_KHR_convert_timespec_time: "now" comes from it (default 0) */
  /* The state the session is in when the device is created (default
   * XR_SESSION_STATE_FOCUSED); forward every later change. */
  XrSessionState sessionState;
  double tickRate;      /* Hz, in [10, 10000]: the device thread (default 1000) */
  double pulseDuration; /* s: each vibration's length, longer than 1/vibrationRate so pulses overlap (default
                           0.02) */
  double maxExtrapolation; /* s: PROX_XR_EXTRAPOLATE_FRAME predicts at most this far (default 0.05) */
  int32_t internalValue;   /* do not touch */
  /* Windows: the app enabled XR_KHR_win32_convert_performance_counter_time,
   * "now" comes from it (default 0; refused elsewhere). */
  proxBool win32PerformanceCounterTime;
  /* An XrTime the runtime gave the app or accepted from it, about now (as
   * for proxXrDevice_OnRuntimeTime), or 0 (default): a device with no other
   * source of "now" has a clock from its first tick. */
  XrTime runtimeTime;
} proxXrDeviceDef;

typedef struct proxXrDeviceStats {
  uint64_t ticks;   /* the device thread's ticks */
  uint64_t locates; /* xrLocateSpace calls */
  uint64_t
      untrackedTicks; /* focused ticks without a valid pose (no valid bit, no time yet, a failed locate) */
  uint64_t notFocusedTicks; /* ticks while the session was not FOCUSED (no pose, no vibration) */
  uint64_t vibrationsSent;  /* xrApplyHapticFeedback calls that succeeded */
  uint64_t
      vibrationsRefused;   /* ... that failed (XR_SESSION_NOT_FOCUSED and the like): counted, never fatal */
  uint64_t stopsSent;      /* xrStopHapticFeedback calls (contact ended, focus lost, destroyed) */
  uint64_t posesPushed;    /* poses handed to the haptic loop */
  proxBool timeFromFrames; /* "now" is anchored on the last predicted display time (timeSource is
                              PROX_XR_TIME_FRAMES) */
  int32_t lastXrResult;    /* the last failing OpenXR result, or XR_SUCCESS */
  float lastAmplitude;     /* the last amplitude sent */
  XrSessionState sessionState; /* as last forwarded */
  proxXrTimeSource timeSource; /* where the last tick's "now" came from */
} proxXrDeviceStats;

PROX_API proxXrDeviceDef proxDefaultXrDeviceDef(void);
/* Creates the device and starts its thread (it creates an action space for
 * poseAction). Call after the app attached its action sets. The world's
 * game thread. */
PROX_API proxResult proxWorld_CreateXrDevice(proxWorldId world, const proxXrDeviceDef* def,
                                             proxXrDeviceId* device);
/* Forward every session state change the app polls. The game thread. */
PROX_API proxResult proxXrDevice_OnSessionState(proxXrDeviceId device, XrSessionState state);
/* Once a frame, after xrWaitFrame and xrSyncActions, with a predicted
 * display time > 0 (a headless runtime that returns 0 has no frame to
 * report: skip the call). The game thread. */
PROX_API proxResult proxXrDevice_OnFrame(proxXrDeviceId device, XrTime predictedDisplayTime,
                                         XrDuration predictedDisplayPeriod);
/* Optional: an XrTime the runtime gave the app or accepted from it, about
 * now (an event's time > 0, the time of a locate that just succeeded). The
 * device's last resort for "now" when the runtime offers neither time
 * conversion extension and no predicted display time: it runs its own
 * monotonic clock from the newest such time. The game thread. */
PROX_API proxResult proxXrDevice_OnRuntimeTime(proxXrDeviceId device, XrTime time);
/* The def that attaches it with proxBody_SetDevice. The game thread. */
PROX_API proxResult proxXrDevice_GetDeviceDef(proxXrDeviceId device, proxDeviceDef* def);
/* Any thread. */
PROX_API proxResult proxXrDevice_GetStats(proxXrDeviceId device, proxXrDeviceStats* stats);
/* Stops the device's thread (a vibration playing is stopped) and destroys
 * its action space: call it, or destroy the world (which destroys its XR
 * devices), before the app destroys its session, spaces or actions. The
 * tool it held loses its pose and its force fades. The game thread. */
PROX_API proxResult proxXrDevice_Destroy(proxXrDeviceId device);
/* Whether the id names a live XR device. Any thread. */
PROX_API proxBool proxXrDevice_IsValid(proxXrDeviceId device);

/* Optional helper: creates Proxima's pose (POSE_INPUT) and vibration
 * (VIBRATION_OUTPUT) actions, "<namePrefix>_grip" and "<namePrefix>_haptic",
 * in the app's action set, for /user/hand/left and /user/hand/right. Before
 * the app attaches the set. Any thread. */
PROX_API proxResult proxXrCreateActions(PFN_xrGetInstanceProcAddr gipa, XrInstance instance, XrActionSet set,
                                        const char* namePrefix, XrAction* poseAction, XrAction* hapticAction);
/* Fills the bindings Proxima's actions need in an interaction profile
 * ("/interaction_profiles/khr/simple_controller", ...) for a hand ("left"
 * or "right", or its path "/user/hand/left"), for the app to merge into its one
 * xrSuggestInteractionProfileBindings call for that profile. hapticAction
 * may be XR_NULL_HANDLE. PROX_ERROR_CAPACITY when capacity is too small
 * (*count says how many). Any thread. */
PROX_API proxResult proxXrGetSuggestedBindings(PFN_xrGetInstanceProcAddr gipa, XrInstance instance,
                                               const char* interactionProfile, const char* hand,
                                               XrAction poseAction, XrAction hapticAction,
                                               XrActionSuggestedBinding* bindings, int32_t capacity,
                                               int32_t* count);

#ifdef __cplusplus
}
#endif

#endif /* PROXIMA_PROXIMA_OPENXR_H */
