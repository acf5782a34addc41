/* The mock OpenXR runtime's control panel, for tests: scripted grip poses,
 * tracking and focus switches, and the log of what was sent to the
 * controller's vibration. Not an OpenXR interface: a test reaches it through
 * the runtime's own xrGetInstanceProcAddr (from its negotiation function)
 * under the name "proxMockXr_GetControl". */
#ifndef PROX_TESTS_OPENXR_MOCK_CONTROL_H
#define PROX_TESTS_OPENXR_MOCK_CONTROL_H

#include <openxr/openxr.h>

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The right hand's grip pose in the runtime's world (every reference space
 * is that world with its poseInReferenceSpace) at a time; between keys the
 * grip moves linearly (slerp for the rotation), before the first and after
 * the last it holds. */
typedef struct ProxMockXrKey {
  XrTime time;
  XrPosef pose;
} ProxMockXrKey;

typedef struct ProxMockXrVibration {
  XrTime time;  /* when the call was made */
  int32_t stop; /* xrStopHapticFeedback */
  float amplitude;
  XrDuration duration;
  float frequency;
  XrResult result; /* what the call returned */
} ProxMockXrVibration;

/* Habits of real runtimes (docs/openxr.md), each selectable: bits for
 * setHabits, or names in the environment variable PROX_MOCK_XR_HABITS
 * ("zero_display_time,no_timespec,..."), read at xrCreateInstance, for a
 * process that cannot reach this panel (the sample). The default is none:
 * the strict runtime. */
enum {
  /* xrWaitFrame returns at once with predictedDisplayTime and
   * predictedDisplayPeriod 0 (Monado's headless sessions); xrEndFrame still
   * refuses a displayTime of 0. */
  PROX_MOCK_XR_HABIT_ZERO_DISPLAY_TIME = 1,
  /* No XR_KHR_convert_timespec_time (the Windows runtimes). */
  PROX_MOCK_XR_HABIT_NO_TIMESPEC = 2,
  /* xrBeginSession leaves the session in READY: it never becomes FOCUSED
   * (stock Monado's headless sessions). */
  PROX_MOCK_XR_HABIT_STAYS_READY = 4,
  /* While not FOCUSED, xrSyncActions still syncs (XR_SUCCESS), action
   * spaces are still located and xrApplyHapticFeedback returns XR_SUCCESS;
   * nothing stops a vibration when focus goes (stock Monado). */
  PROX_MOCK_XR_HABIT_ANSWERS_UNFOCUSED = 8
};

typedef struct ProxMockXrControl {
  /* Replaces the script (at most 64 keys). With none (the default) the
   * grip moves forward and back along -z from (0.1, 1.2, -0.3) by 0.15 m
   * every 4 s,
   * starting at rest when it is first located. */
  void (*setScript)(const ProxMockXrKey* keys, int32_t count);
  /* 0: the grip is untracked (located with no valid bit). */
  void (*setTracked)(int32_t tracked);
  /* 0: the session goes FOCUSED -> VISIBLE (an event is queued; haptics
   * and action states are refused at once); 1: back to FOCUSED. */
  void (*setFocused)(int32_t focused);
  /* Copies up to `capacity` log entries starting at entry `first`; returns
   * how many entries the log holds. */
  int32_t (*vibrations)(ProxMockXrVibration* out, int32_t first, int32_t capacity);
  /* xrLocateSpace calls on action spaces so far, and the most made at once
   * from different threads. */
  uint64_t (*locateCalls)(void);
  int32_t (*maxConcurrentCalls)(void);
  /* The runtime's clock (CLOCK_MONOTONIC in ns, the XrTime it uses). */
  XrTime (*now)(void);
  /* The habits from the next xrCreateInstance on (PROX_MOCK_XR_HABIT_*,
   * or'ed with those of PROX_MOCK_XR_HABITS). */
  void (*setHabits)(uint32_t habits);
  /* xrWaitFrame and xrSyncActions calls so far. */
  uint64_t (*waitFrameCalls)(void);
  uint64_t (*syncCalls)(void);
} ProxMockXrControl;

typedef const ProxMockXrControl* (*ProxMockXrGetControlFn)(void);

/* The same panel as plain C functions the mock runtime's library exports,
 * for the bindings' tests, which load that library themselves (Python's
 * ctypes, C#'s P/Invoke) and cannot easily call through a table of function
 * pointers. Test-only, like everything here: the names say "mock". */
void proxMockXr_SetScript(const ProxMockXrKey* keys, int32_t count);
void proxMockXr_SetTracked(int32_t tracked);
void proxMockXr_SetFocused(int32_t focused);
int32_t proxMockXr_Vibrations(ProxMockXrVibration* out, int32_t first, int32_t capacity);
uint64_t proxMockXr_LocateCalls(void);
XrTime proxMockXr_Now(void);
void proxMockXr_SetHabits(uint32_t habits);

#ifdef __cplusplus
}
#endif

#endif
