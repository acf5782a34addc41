// The mock OpenXR runtime's own state, shared by its parts: the API entry
// points of instances, sessions, actions and frames (mock_runtime.cpp), of
// spaces and haptics (mock_spaces.cpp), and the scripted grip with the
// test's control panel (mock_control.cpp). One runtime, one global state,
// one mutex.
#pragma once

#include "mock_control.h"
#include "mock_math.h"

#include <time.h>

#define XR_USE_TIMESPEC
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include <atomic>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace prox::mock_xr {

inline XrTime now_ns() {
  timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return XrTime(t.tv_sec) * 1000000000 + t.tv_nsec;
}

// ---- the runtime's state -----------------------------------------------------------
struct ActionSet {
  std::string name;
  bool attached = false;
};
struct Action {
  XrActionSet set;
  XrActionType type;
  std::string name;
  std::vector<XrPath> subactions;
};
struct Space {
  bool action = false;
  XrReferenceSpaceType reference = XR_REFERENCE_SPACE_TYPE_LOCAL;
  XrAction poseAction = XR_NULL_HANDLE;
  XrPath subaction = XR_NULL_PATH;
  Pose offset;
};

constexpr int kMaxKeys = 64;

struct State {
  std::mutex mutex;
  bool instance = false;
  bool headless = false, timespec = false;
  std::vector<std::string> paths;  // XrPath i + 1
  std::map<XrActionSet, std::unique_ptr<ActionSet>> sets;
  std::map<XrAction, std::unique_ptr<Action>> actions;
  std::map<XrSpace, std::unique_ptr<Space>> spaces;
  bool session = false, running = false, exit_requested = false, frame_begun = false;
  bool attached = false;
  XrSessionState state = XR_SESSION_STATE_UNKNOWN;
  std::deque<XrSessionState> events;
  std::vector<XrActionSet> synced;  // the sets of the last xrSyncActions
  XrTime last_wait = 0;
  XrTime first_located = 0;  // the default motion starts at rest when the grip is first located
  std::vector<ProxMockXrKey> script;
  bool tracked = true;
  std::vector<ProxMockXrVibration> log;
  std::uint32_t habits = 0;  // PROX_MOCK_XR_HABIT_*, fixed at xrCreateInstance
  XrTime session_begun = 0;
};

extern State g;
extern std::atomic<std::uint64_t> g_locates;
extern std::atomic<int> g_inside, g_max_inside;
extern std::atomic<std::uint64_t> g_waits, g_syncs;

// Counts overlapping calls (from the app's and Proxima's threads).
struct Inside {
  Inside() {
    const int n = g_inside.fetch_add(1) + 1;
    int m = g_max_inside.load();
    while (n > m && !g_max_inside.compare_exchange_weak(m, n)) {
    }
  }
  ~Inside() { g_inside.fetch_sub(1); }
};

inline const XrInstance kInstance = reinterpret_cast<XrInstance>(std::uintptr_t(0x1001));
inline const XrSession kSession = reinterpret_cast<XrSession>(std::uintptr_t(0x2001));
constexpr XrSystemId kSystem = 7;
extern std::uintptr_t g_next_handle;

template <typename H>
H new_handle() {
  return reinterpret_cast<H>(g_next_handle++);
}

#define CHECK_INSTANCE(i) \
  if ((i) != kInstance || !g.instance) return XR_ERROR_HANDLE_INVALID
#define CHECK_SESSION(s) \
  if ((s) != kSession || !g.session) return XR_ERROR_HANDLE_INVALID

// With g.mutex held.
std::string path_string(XrPath p);
void set_state(XrSessionState s);  // queues the event too
inline bool focused() { return g.state == XR_SESSION_STATE_FOCUSED; }
inline bool habit(std::uint32_t h) { return (g.habits & h) != 0; }
// Input and haptics answer: focused, or a runtime that answers regardless.
inline bool answers() { return focused() || habit(PROX_MOCK_XR_HABIT_ANSWERS_UNFOCUSED); }
// The habits for a new instance: the panel's and the environment's.
std::uint32_t habits_for_new_instance();
bool action_active(XrAction action, XrPath subaction);
// The default motion (mock_control.h) or the script, at a time.
Pose grip_at(XrTime t, V* velocity, V* angular);

const ProxMockXrControl* get_control();

// mock_spaces.cpp's entry points, for the dispatch table.
XRAPI_ATTR XrResult XRAPI_CALL CreateReferenceSpace(XrSession session, const XrReferenceSpaceCreateInfo* info,
                                                    XrSpace* space);
XRAPI_ATTR XrResult XRAPI_CALL EnumerateReferenceSpaces(XrSession session, uint32_t capacity, uint32_t* count,
                                                        XrReferenceSpaceType* spaces);
XRAPI_ATTR XrResult XRAPI_CALL CreateActionSpace(XrSession session, const XrActionSpaceCreateInfo* info,
                                                 XrSpace* space);
XRAPI_ATTR XrResult XRAPI_CALL DestroySpace(XrSpace space);
XRAPI_ATTR XrResult XRAPI_CALL LocateSpace(XrSpace space, XrSpace base, XrTime time, XrSpaceLocation* location);
XRAPI_ATTR XrResult XRAPI_CALL ApplyHapticFeedback(XrSession session, const XrHapticActionInfo* info,
                                                   const XrHapticBaseHeader* haptic);
XRAPI_ATTR XrResult XRAPI_CALL StopHapticFeedback(XrSession session, const XrHapticActionInfo* info);

}  // namespace prox::mock_xr
