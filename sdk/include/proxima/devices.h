/* Proxima's devices: what holds a tool while the threads run. The
 * application's own (two callbacks), the scripted device (a path of poses)
 * and the streamed device (poses pushed from the application's thread).
 * Part of the core API: proxima/proxima.h includes this header. The same
 * conventions as proxima.h. */
#ifndef PROXIMA_DEVICES_H
#define PROXIMA_DEVICES_H

#include "proxima/proxima.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- devices ---------------------------------------------------------------- */

/* A haptic device: two callbacks and your pointer, called from the haptic
 * thread at its rate while the world's threads run. They must return
 * quickly and must not call Proxima. */
typedef struct proxDeviceDef {
  int32_t apiVersion; /* PROX_API_VERSION, set by proxDefaultDeviceDef() */
  /* Writes the tool's world pose and returns nonzero, or returns 0 when the
   * device has no pose this tick (the force then fades out). A non-finite
   * pose or a quaternion far from unit length counts as none. Required. */
  proxBool (*readPose)(void* userData, proxPose* pose);
  /* Receives the force and torque to render: always finite, within the
   * world's maxima and rate-limited (clipped is set when the safety gate
   * changed it). May be NULL. */
  void (*writeWrench)(void* userData, const proxWrench* wrench);
  void* userData;
  /* What the device renders stably at the haptic rate, as CHAI3D's
   * cHapticDeviceInfo declares it: the stiffest contact in N/m (>= 0; 0,
   * the default: no limit) and the damping in N s/m it needs (>= 0, default
   * 0). The force it is handed never grows faster than maxStiffness per
   * metre the tool moves, and a constrained tool's coupling is no stiffer
   * (docs/devices.md, "A device's limits"). */
  double maxStiffness;
  double damping;
  int32_t internalValue;
  int32_t reserved;
} proxDeviceDef;

PROX_API proxDeviceDef proxDefaultDeviceDef(void);

/* Lets a device hold a tool while the threads run (def NULL: none; the
 * game thread's proxBody_SetPose then moves the tool). The def is copied. A
 * built-in device (scripted, streamed, HID, XR) holds one tool at a time:
 * handed to another, PROX_ERROR_INVALID_ARGUMENT. Game thread; also while
 * the threads run: the old device's wrench fades to zero before this returns,
 * and it is called no more; the new one's force fades in once its contacts
 * come (docs/dynamic-scenes.md). */
PROX_API proxResult proxBody_SetDevice(proxBodyId tool, const proxDeviceDef* def);

/* Every device of Proxima's (scripted, streamed, HID, XR) is made by its
 * world, lives until its Destroy or its world's destruction, and is let go
 * of the same way: Destroy closes it (stops its thread, if it has one), so
 * a tool that holds it has no pose from then on and its force fades out,
 * until the tool is given another device or NULL; its id is then invalid
 * everywhere. Its ids carry a generation (the field `reserved`):
 * copy them whole, never make one by hand. At most 4096 devices of every
 * kind together exist at once in the process (PROX_ERROR_CAPACITY beyond).
 *
 * The built-in scripted device: a tool moved along a path of poses, for
 * tests, demos and replays. */
typedef struct proxScriptedDeviceId {
  uint32_t index1;   /* index + 1; 0 is null */
  uint32_t reserved; /* the slot's generation */
  proxWorldId world;
} proxScriptedDeviceId;

typedef struct proxScriptedDeviceDef {
  int32_t apiVersion; /* PROX_API_VERSION, set by proxDefaultScriptedDeviceDef() */
  const proxPose* poses; /* the path; copied */
  int32_t poseCount;     /* >= 1 */
  proxBool loop;         /* start over after the last pose, or hold it */
  double secondsPerPose; /* > 0: the device moves through the poses at this pace, interpolating */
  int32_t internalValue;
  int32_t reserved;
} proxScriptedDeviceDef;

PROX_API proxScriptedDeviceDef proxDefaultScriptedDeviceDef(void);
/* Game thread. */
PROX_API proxResult proxWorld_CreateScriptedDevice(proxWorldId world, const proxScriptedDeviceDef* def,
                                                   proxScriptedDeviceId* device);
/* Reads the path from a file: one pose per line, "tx ty tz qw qx qy qz",
 * '#' comments (the CLI's --poses format). Game thread. */
PROX_API proxResult proxWorld_LoadScriptedDevice(proxWorldId world, const char* path, double secondsPerPose,
                                                 proxBool loop, proxScriptedDeviceId* device);
/* The def that attaches it with proxBody_SetDevice. Game thread. */
PROX_API proxResult proxScriptedDevice_GetDeviceDef(proxScriptedDeviceId device, proxDeviceDef* def);

/* What the scripted device has been handed so far. */
typedef struct proxScriptedDeviceRecord {
  uint64_t reads, writes;
  double progress;     /* poses into the path (fractional) */
  double maxForce;     /* N: largest |force| written */
  double maxTorque;    /* N m: largest |torque| written */
  double maxForceStep; /* N: largest |force change| between consecutive writes */
  proxVec3 lastForce, lastTorque;
  proxBool allFinite; /* every value written was finite */
  int32_t reserved;
} proxScriptedDeviceRecord;

/* Game thread. */
PROX_API proxResult proxScriptedDevice_GetRecord(proxScriptedDeviceId device,
                                                 proxScriptedDeviceRecord* record);
/* Lets the device go (see above). Game thread. */
PROX_API proxResult proxScriptedDevice_Destroy(proxScriptedDeviceId device);
/* Whether the id names a live scripted device (proxGetLastError says why
 * not). Any thread. */
PROX_API proxBool proxScriptedDevice_IsValid(proxScriptedDeviceId device);

/* ---- the streamed device ----------------------------------------------------------
 * The device for engines, bindings and XR (docs/devices.md): the application
 * pushes timestamped tool poses from a thread of its own at its own rate (a
 * frame's 60-120 Hz), the haptic loop renders the pose at its 1 kHz from the
 * latest samples, and the wrench it renders is read back from any thread
 * (for a rumble or an XR vibration the application drives itself). Pushing
 * and reading never lock, allocate or wait, and the haptic loop never waits
 * on the pusher. Attach it to one tool with proxBody_SetDevice. */
typedef struct proxStreamDeviceId {
  uint32_t index1;   /* index + 1; 0 is null */
  uint32_t reserved; /* the slot's generation */
  proxWorldId world;
} proxStreamDeviceId;

typedef enum proxStreamMode {
  PROX_STREAM_HOLD = 0, /* the newest sample's pose */
  PROX_STREAM_INTERPOLATE =
      1, /* the pose `delay` ago, between the samples around it; holds past the newest */
  PROX_STREAM_EXTRAPOLATE = 2, /* the pose now: between samples, or predicted from the newest two (at most
                                  maxExtrapolation past the newest, then held) */
  PROX_STREAM_MODE_FORCE32 = 0x7FFFFFFF
} proxStreamMode;

typedef struct proxStreamDeviceDef {
  int32_t apiVersion; /* PROX_API_VERSION, set by proxDefaultStreamDeviceDef() */
  proxStreamMode mode; /* default PROX_STREAM_INTERPOLATE */
  double delay;        /* s, >= 0: INTERPOLATE's latency (default 1/90: one 90 Hz frame) */
  double
      maxExtrapolation; /* s, >= 0: EXTRAPOLATE's furthest prediction past the newest sample (default 0.02) */
  double staleAfter; /* s, > 0: nothing pushed for this long: no pose, the force fades out (default 0.05) */
  /* What the device behind the stream renders stably, as
   * proxDeviceDef.maxStiffness and damping say (0, the default: no limit). */
  double maxStiffness;
  double damping;
  int32_t internalValue;
  int32_t reserved;
} proxStreamDeviceDef;

/* What a streamed device saw. Counts since it was created. */
typedef struct proxStreamDeviceStats {
  uint64_t samplesPushed;  /* accepted */
  uint64_t samplesDropped; /* no newer than the newest accepted: late (out of order) or duplicate */
  uint64_t samplesRefused; /* invalid (non-finite, zero quaternion, bad time): PROX_ERROR_INVALID_ARGUMENT */
  uint64_t reads;          /* haptic ticks that asked for the pose */
  uint64_t staleTicks;     /* ... and got none: nothing pushed yet, or not for staleAfter */
  uint64_t extrapolatedTicks; /* ... rendered past the newest sample (EXTRAPOLATE: predicted; else held) */
  double meanSampleInterval;  /* s, between accepted samples' times */
  double maxSampleInterval;   /* s */
  double maxExtrapolation;    /* s: the furthest a rendered pose was predicted past the newest sample */
  double lastSampleAge;       /* s: now minus the newest sample's time, at the last read */
} proxStreamDeviceStats;

/* Seconds on the steady, monotonic clock proxStreamDevice_PushPose's times
 * are on (CLOCK_MONOTONIC on Linux; std::chrono::steady_clock). Any thread. */
PROX_API double proxGetTime(void);

PROX_API proxStreamDeviceDef proxDefaultStreamDeviceDef(void);
/* Game thread. */
PROX_API proxResult proxWorld_CreateStreamDevice(proxWorldId world, const proxStreamDeviceDef* def,
                                                 proxStreamDeviceId* device);
/* Hands the device the tool's world pose at `timeSeconds` (on proxGetTime's
 * clock; when the pose was or will be true). Any thread, but one at a time:
 * a second thread pushing at the same moment gets PROX_ERROR_WRONG_THREAD.
 * Lock-free and allocation-free. A sample no newer than the newest accepted
 * is dropped (counted, not an error); a non-finite pose, a zero quaternion,
 * or a NaN, infinite or negative time is refused with
 * PROX_ERROR_INVALID_ARGUMENT and never reaches the haptic loop. Other
 * quaternions are normalised. PROX_ERROR_INVALID_HANDLE once the device or
 * its world is destroyed. */
PROX_API proxResult proxStreamDevice_PushPose(proxStreamDeviceId device, const proxPose* pose,
                                              double timeSeconds);
/* The wrench the haptic loop last handed the device (zero before the
 * first), never torn. Any thread; lock-free. */
PROX_API proxResult proxStreamDevice_GetWrench(proxStreamDeviceId device, proxWrench* wrench);
/* The def that attaches it with proxBody_SetDevice. Game thread. */
PROX_API proxResult proxStreamDevice_GetDeviceDef(proxStreamDeviceId device, proxDeviceDef* def);
/* Game thread. */
PROX_API proxResult proxStreamDevice_GetStats(proxStreamDeviceId device, proxStreamDeviceStats* stats);
/* Lets the device go (see proxScriptedDeviceId); a push under way on
 * another thread finishes first, later ones get PROX_ERROR_INVALID_HANDLE.
 * Game thread. */
PROX_API proxResult proxStreamDevice_Destroy(proxStreamDeviceId device);
/* Whether the id names a live streamed device. Any thread. */
PROX_API proxBool proxStreamDevice_IsValid(proxStreamDeviceId device);

#ifdef __cplusplus
}
#endif

#endif /* PROXIMA_DEVICES_H */
