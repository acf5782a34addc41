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
} ProxMockXrControl;

typedef const ProxMockXrControl* (*ProxMockXrGetControlFn)(void);

#ifdef __cplusplus
}
#endif

#endif
