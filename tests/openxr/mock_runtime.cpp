// A mock OpenXR runtime for the tests and the headless sample: no display,
// no devices. It offers XR_MND_headless and XR_KHR_convert_timespec_time,
// one system with one scripted right-hand controller (its grip pose follows
// the script of mock_control.h) and logs every vibration. Just enough of the
// API for an app that makes a headless session, actions and a frame loop,
// checked strictly, so a wrong call fails here as it would on a real
// runtime. Loaded by the real OpenXR loader through a manifest
// (XR_RUNTIME_JSON); the one symbol it exports is
// xrNegotiateLoaderRuntimeInterface.
#include "loader_negotiation.h"
#include "mock_control.h"
#include "mock_math.h"

#include <time.h>

#define XR_USE_TIMESPEC
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <time.h>

namespace {

using namespace prox::mock_xr;

XrTime now_ns() {
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
};

State g;
std::atomic<std::uint64_t> g_locates{0};
std::atomic<int> g_inside{0}, g_max_inside{0};

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

const XrInstance kInstance = reinterpret_cast<XrInstance>(std::uintptr_t(0x1001));
const XrSession kSession = reinterpret_cast<XrSession>(std::uintptr_t(0x2001));
constexpr XrSystemId kSystem = 7;
std::uintptr_t g_next_handle = 0x10000;

template <typename H>
H new_handle() {
  return reinterpret_cast<H>(g_next_handle++);
}

XrPath path_of(const std::string& s) {
  for (std::size_t i = 0; i < g.paths.size(); ++i)
    if (g.paths[i] == s) return XrPath(i + 1);
  g.paths.push_back(s);
  return XrPath(g.paths.size());
}
std::string path_string(XrPath p) { return p >= 1 && p <= g.paths.size() ? g.paths[p - 1] : std::string(); }

void set_state(XrSessionState s) {
  g.state = s;
  g.events.push_back(s);
}

// The default motion (mock_control.h) or the script, at a time.
Pose grip_at(XrTime t, V* velocity, V* angular) {
  *velocity = {0, 0, 0};
  *angular = {0, 0, 0};
  if (g.script.empty()) {
    if (g.first_located == 0) g.first_located = t;
    const double s = double(std::max<XrTime>(0, t - g.first_located) % 4000000000LL) * 1e-9,
                 w = 2 * M_PI / 4.0;
    const double z = -0.3 - 0.075 * (1 - std::cos(w * s));
    velocity->z = -0.075 * w * std::sin(w * s);
    return {{1, 0, 0, 0}, {0.1, 1.2, z}};
  }
  const std::vector<ProxMockXrKey>& k = g.script;
  if (t <= k.front().time) return of(k.front().pose);
  if (t >= k.back().time) return of(k.back().pose);
  std::size_t i = 0;
  while (k[i + 1].time < t) ++i;
  const Pose a = of(k[i].pose), b = of(k[i + 1].pose);
  const double dt = double(k[i + 1].time - k[i].time) * 1e-9, f = double(t - k[i].time) * 1e-9 / dt;
  *velocity = {(b.p.x - a.p.x) / dt, (b.p.y - a.p.y) / dt, (b.p.z - a.p.z) / dt};
  Q d = mul(b.q, conj(a.q));  // world-frame rotation from a to b
  if (d.w < 0) d = {-d.w, -d.x, -d.y, -d.z};
  const double sn = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  if (sn > 1e-12) {
    const double angle = 2 * std::atan2(sn, d.w) / dt;
    *angular = {d.x / sn * angle, d.y / sn * angle, d.z / sn * angle};
  }
  Pose p;
  p.q = slerp(a.q, b.q, f);
  p.p = {a.p.x + (b.p.x - a.p.x) * f, a.p.y + (b.p.y - a.p.y) * f, a.p.z + (b.p.z - a.p.z) * f};
  return p;
}

bool focused() { return g.state == XR_SESSION_STATE_FOCUSED; }

// ---- the API ---------------------------------------------------------------------
#define CHECK_INSTANCE(i) \
  if ((i) != kInstance || !g.instance) return XR_ERROR_HANDLE_INVALID
#define CHECK_SESSION(s) \
  if ((s) != kSession || !g.session) return XR_ERROR_HANDLE_INVALID

const char* const kExtensions[] = {XR_MND_HEADLESS_EXTENSION_NAME,
                                   XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME};
const uint32_t kExtensionVersions[] = {XR_MND_headless_SPEC_VERSION,
                                       XR_KHR_convert_timespec_time_SPEC_VERSION};

XRAPI_ATTR XrResult XRAPI_CALL EnumerateInstanceExtensionProperties(const char* layer, uint32_t capacity,
                                                                    uint32_t* count,
                                                                    XrExtensionProperties* props) {
  if (layer) return XR_ERROR_API_LAYER_NOT_PRESENT;
  *count = 2;
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
  for (int i = 0; i < 2; ++i) {
    std::snprintf(props[i].extensionName, sizeof props[i].extensionName, "%s", kExtensions[i]);
    props[i].extensionVersion = kExtensionVersions[i];
  }
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateInstance(const XrInstanceCreateInfo* info, XrInstance* instance) {
  std::lock_guard<std::mutex> lock(g.mutex);
  if (g.instance) return XR_ERROR_LIMIT_REACHED;
  bool headless = false, timespec = false;
  for (uint32_t i = 0; i < info->enabledExtensionCount; ++i) {
    const std::string e = info->enabledExtensionNames[i];
    if (e == kExtensions[0])
      headless = true;
    else if (e == kExtensions[1])
      timespec = true;
    else
      return XR_ERROR_EXTENSION_NOT_PRESENT;
  }
  // A fresh runtime each time (a test may keep the library loaded).
  g.paths.clear();
  g.sets.clear();
  g.actions.clear();
  g.spaces.clear();
  g.events.clear();
  g.log.clear();
  g.script.clear();
  g.tracked = true;
  g.session = g.running = g.attached = g.exit_requested = g.frame_begun = false;
  g.state = XR_SESSION_STATE_UNKNOWN;
  g.instance = true;
  g.first_located = 0;
  g.headless = headless;
  g.timespec = timespec;
  *instance = kInstance;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroyInstance(XrInstance instance) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_INSTANCE(instance);
  g.instance = g.session = false;
  g.sets.clear();
  g.actions.clear();
  g.spaces.clear();
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetInstanceProperties(XrInstance instance, XrInstanceProperties* props) {
  CHECK_INSTANCE(instance);
  props->runtimeVersion = XR_MAKE_VERSION(0, 1, 0);
  std::snprintf(props->runtimeName, sizeof props->runtimeName, "Proxima mock runtime (tests)");
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL ResultToString(XrInstance instance, XrResult value, char* buffer) {
  CHECK_INSTANCE(instance);
  std::snprintf(buffer, XR_MAX_RESULT_STRING_SIZE, "XrResult(%d)", int(value));
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL StructureTypeToString(XrInstance instance, XrStructureType value,
                                                     char* buffer) {
  CHECK_INSTANCE(instance);
  std::snprintf(buffer, XR_MAX_STRUCTURE_NAME_SIZE, "XrStructureType(%d)", int(value));
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetSystem(XrInstance instance, const XrSystemGetInfo* info, XrSystemId* id) {
  CHECK_INSTANCE(instance);
  if (info->formFactor != XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY) return XR_ERROR_FORM_FACTOR_UNSUPPORTED;
  *id = kSystem;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetSystemProperties(XrInstance instance, XrSystemId id,
                                                   XrSystemProperties* props) {
  CHECK_INSTANCE(instance);
  if (id != kSystem) return XR_ERROR_SYSTEM_INVALID;
  props->systemId = kSystem;
  props->vendorId = 0;
  std::snprintf(props->systemName, sizeof props->systemName, "mock headset");
  props->graphicsProperties = {2048, 2048, 1};
  props->trackingProperties = {XR_TRUE, XR_TRUE};
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EnumerateViewConfigurations(XrInstance instance, XrSystemId id,
                                                           uint32_t capacity, uint32_t* count,
                                                           XrViewConfigurationType* types) {
  CHECK_INSTANCE(instance);
  if (id != kSystem) return XR_ERROR_SYSTEM_INVALID;
  *count = 1;
  if (capacity >= 1) types[0] = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EnumerateEnvironmentBlendModes(XrInstance instance, XrSystemId id,
                                                              XrViewConfigurationType, uint32_t capacity,
                                                              uint32_t* count,
                                                              XrEnvironmentBlendMode* modes) {
  CHECK_INSTANCE(instance);
  if (id != kSystem) return XR_ERROR_SYSTEM_INVALID;
  *count = 1;
  if (capacity >= 1) modes[0] = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL StringToPath(XrInstance instance, const char* string, XrPath* path) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_INSTANCE(instance);
  if (!string[0] || string[0] != '/') return XR_ERROR_PATH_FORMAT_INVALID;
  *path = path_of(string);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL PathToString(XrInstance instance, XrPath path, uint32_t capacity,
                                            uint32_t* count, char* buffer) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_INSTANCE(instance);
  const std::string s = path_string(path);
  if (s.empty()) return XR_ERROR_PATH_INVALID;
  *count = uint32_t(s.size() + 1);
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < s.size() + 1) return XR_ERROR_SIZE_INSUFFICIENT;
  std::memcpy(buffer, s.c_str(), s.size() + 1);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateActionSet(XrInstance instance, const XrActionSetCreateInfo* info,
                                               XrActionSet* set) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_INSTANCE(instance);
  for (const auto& s : g.sets)
    if (s.second->name == info->actionSetName) return XR_ERROR_NAME_DUPLICATED;
  *set = new_handle<XrActionSet>();
  g.sets[*set] = std::make_unique<ActionSet>(ActionSet{info->actionSetName, false});
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroyActionSet(XrActionSet set) {
  std::lock_guard<std::mutex> lock(g.mutex);
  if (!g.sets.erase(set)) return XR_ERROR_HANDLE_INVALID;
  for (auto it = g.actions.begin(); it != g.actions.end();)
    it = it->second->set == set ? g.actions.erase(it) : std::next(it);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateAction(XrActionSet set, const XrActionCreateInfo* info,
                                            XrAction* action) {
  std::lock_guard<std::mutex> lock(g.mutex);
  const auto s = g.sets.find(set);
  if (s == g.sets.end()) return XR_ERROR_HANDLE_INVALID;
  if (s->second->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
  for (const auto& a : g.actions)
    if (a.second->set == set && a.second->name == info->actionName) return XR_ERROR_NAME_DUPLICATED;
  *action = new_handle<XrAction>();
  auto a = std::make_unique<Action>();
  a->set = set;
  a->type = info->actionType;
  a->name = info->actionName;
  a->subactions.assign(info->subactionPaths, info->subactionPaths + info->countSubactionPaths);
  g.actions[*action] = std::move(a);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroyAction(XrAction action) {
  std::lock_guard<std::mutex> lock(g.mutex);
  return g.actions.erase(action) ? XR_SUCCESS : XR_ERROR_HANDLE_INVALID;
}

XRAPI_ATTR XrResult XRAPI_CALL
SuggestInteractionProfileBindings(XrInstance instance, const XrInteractionProfileSuggestedBinding* info) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_INSTANCE(instance);
  if (g.attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
  const std::string profile = path_string(info->interactionProfile);
  if (profile.rfind("/interaction_profiles/", 0) != 0) return XR_ERROR_PATH_UNSUPPORTED;
  for (uint32_t i = 0; i < info->countSuggestedBindings; ++i) {
    if (!g.actions.count(info->suggestedBindings[i].action)) return XR_ERROR_HANDLE_INVALID;
    if (path_string(info->suggestedBindings[i].binding).rfind("/user/hand/", 0) != 0)
      return XR_ERROR_PATH_UNSUPPORTED;
  }
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateSession(XrInstance instance, const XrSessionCreateInfo* info,
                                             XrSession* session) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_INSTANCE(instance);
  if (info->systemId != kSystem) return XR_ERROR_SYSTEM_INVALID;
  if (info->next != nullptr || !g.headless) return XR_ERROR_GRAPHICS_DEVICE_INVALID;
  if (g.session) return XR_ERROR_LIMIT_REACHED;
  g.session = true;
  g.running = g.attached = g.exit_requested = g.frame_begun = false;
  g.synced.clear();
  set_state(XR_SESSION_STATE_IDLE);
  set_state(XR_SESSION_STATE_READY);
  *session = kSession;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroySession(XrSession session) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  g.session = false;
  g.spaces.clear();
  for (auto& s : g.sets) s.second->attached = false;
  g.attached = false;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL BeginSession(XrSession session, const XrSessionBeginInfo* info) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  if (g.running) return XR_ERROR_SESSION_RUNNING;
  if (g.state != XR_SESSION_STATE_READY) return XR_ERROR_SESSION_NOT_READY;
  if (info->primaryViewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
    return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
  g.running = true;
  set_state(XR_SESSION_STATE_SYNCHRONIZED);
  set_state(XR_SESSION_STATE_VISIBLE);
  set_state(XR_SESSION_STATE_FOCUSED);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EndSession(XrSession session) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  if (!g.running) return XR_ERROR_SESSION_NOT_RUNNING;
  if (g.state != XR_SESSION_STATE_STOPPING) return XR_ERROR_SESSION_NOT_STOPPING;
  g.running = false;
  set_state(XR_SESSION_STATE_IDLE);
  if (g.exit_requested) set_state(XR_SESSION_STATE_EXITING);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL RequestExitSession(XrSession session) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  if (!g.running) return XR_ERROR_SESSION_NOT_RUNNING;
  g.exit_requested = true;
  if (g.state == XR_SESSION_STATE_FOCUSED) set_state(XR_SESSION_STATE_VISIBLE);
  if (g.state == XR_SESSION_STATE_VISIBLE) set_state(XR_SESSION_STATE_SYNCHRONIZED);
  set_state(XR_SESSION_STATE_STOPPING);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL PollEvent(XrInstance instance, XrEventDataBuffer* event) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_INSTANCE(instance);
  if (g.events.empty()) return XR_EVENT_UNAVAILABLE;
  auto* e = reinterpret_cast<XrEventDataSessionStateChanged*>(event);
  e->type = XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED;
  e->next = nullptr;
  e->session = kSession;
  e->state = g.events.front();
  e->time = now_ns();
  g.events.pop_front();
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL AttachSessionActionSets(XrSession session,
                                                       const XrSessionActionSetsAttachInfo* info) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  if (g.attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
  for (uint32_t i = 0; i < info->countActionSets; ++i) {
    const auto s = g.sets.find(info->actionSets[i]);
    if (s == g.sets.end()) return XR_ERROR_HANDLE_INVALID;
    s->second->attached = true;
  }
  g.attached = true;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL SyncActions(XrSession session, const XrActionsSyncInfo* info) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  for (uint32_t i = 0; i < info->countActiveActionSets; ++i) {
    const auto s = g.sets.find(info->activeActionSets[i].actionSet);
    if (s == g.sets.end()) return XR_ERROR_HANDLE_INVALID;
    if (!s->second->attached) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
  }
  if (!focused()) {
    g.synced.clear();
    return XR_SESSION_NOT_FOCUSED;
  }
  g.synced.clear();
  for (uint32_t i = 0; i < info->countActiveActionSets; ++i)
    g.synced.push_back(info->activeActionSets[i].actionSet);
  return XR_SUCCESS;
}

bool action_active(XrAction action, XrPath subaction) {
  const auto a = g.actions.find(action);
  if (a == g.actions.end() || !focused()) return false;
  if (std::find(g.synced.begin(), g.synced.end(), a->second->set) == g.synced.end()) return false;
  return subaction == XR_NULL_PATH || path_string(subaction) == "/user/hand/right";
}

XRAPI_ATTR XrResult XRAPI_CALL GetActionStatePose(XrSession session, const XrActionStateGetInfo* info,
                                                  XrActionStatePose* state) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  const auto a = g.actions.find(info->action);
  if (a == g.actions.end()) return XR_ERROR_HANDLE_INVALID;
  if (a->second->type != XR_ACTION_TYPE_POSE_INPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
  state->isActive = action_active(info->action, info->subactionPath) && g.tracked ? XR_TRUE : XR_FALSE;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateReferenceSpace(XrSession session, const XrReferenceSpaceCreateInfo* info,
                                                    XrSpace* space) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  if (info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_LOCAL &&
      info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_STAGE &&
      info->referenceSpaceType != XR_REFERENCE_SPACE_TYPE_VIEW)
    return XR_ERROR_REFERENCE_SPACE_UNSUPPORTED;
  auto s = std::make_unique<Space>();
  s->reference = info->referenceSpaceType;
  s->offset = of(info->poseInReferenceSpace);
  *space = new_handle<XrSpace>();
  g.spaces[*space] = std::move(s);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EnumerateReferenceSpaces(XrSession session, uint32_t capacity, uint32_t* count,
                                                        XrReferenceSpaceType* spaces) {
  CHECK_SESSION(session);
  const XrReferenceSpaceType all[] = {XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL,
                                      XR_REFERENCE_SPACE_TYPE_STAGE};
  *count = 3;
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < 3) return XR_ERROR_SIZE_INSUFFICIENT;
  std::copy(all, all + 3, spaces);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateActionSpace(XrSession session, const XrActionSpaceCreateInfo* info,
                                                 XrSpace* space) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  const auto a = g.actions.find(info->action);
  if (a == g.actions.end()) return XR_ERROR_HANDLE_INVALID;
  if (a->second->type != XR_ACTION_TYPE_POSE_INPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
  auto s = std::make_unique<Space>();
  s->action = true;
  s->poseAction = info->action;
  s->subaction = info->subactionPath;
  s->offset = of(info->poseInActionSpace);
  *space = new_handle<XrSpace>();
  g.spaces[*space] = std::move(s);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroySpace(XrSpace space) {
  std::lock_guard<std::mutex> lock(g.mutex);
  return g.spaces.erase(space) ? XR_SUCCESS : XR_ERROR_HANDLE_INVALID;
}

// A space's pose in the runtime's world, or false when it is not located.
bool world_pose(const Space& s, XrTime t, Pose* pose, V* velocity, V* angular) {
  *velocity = *angular = {0, 0, 0};
  if (!s.action) {
    *pose = s.offset;
    return true;
  }
  if (!action_active(s.poseAction, s.subaction)) return false;
  const Pose grip = grip_at(t, velocity, angular);
  // The offset's lever arm adds omega x r to the linear velocity.
  const V r = rotate(grip.q, s.offset.p);
  const V& w = *angular;
  velocity->x += w.y * r.z - w.z * r.y;
  velocity->y += w.z * r.x - w.x * r.z;
  velocity->z += w.x * r.y - w.y * r.x;
  *pose = compose(grip, s.offset);
  return true;
}

XRAPI_ATTR XrResult XRAPI_CALL LocateSpace(XrSpace space, XrSpace base, XrTime time,
                                           XrSpaceLocation* location) {
  const Inside inside;
  std::lock_guard<std::mutex> lock(g.mutex);
  const auto s = g.spaces.find(space), b = g.spaces.find(base);
  if (s == g.spaces.end() || b == g.spaces.end()) return XR_ERROR_HANDLE_INVALID;
  if (time <= 0) return XR_ERROR_TIME_INVALID;
  if (s->second->action) g_locates.fetch_add(1);
  auto* velocity = static_cast<XrSpaceVelocity*>(location->next);
  if (velocity && velocity->type != XR_TYPE_SPACE_VELOCITY) velocity = nullptr;
  location->locationFlags = 0;
  location->pose = {{0, 0, 0, 1}, {0, 0, 0}};
  if (velocity) velocity->velocityFlags = 0;
  Pose ps, pb;
  V vs, ws, vb, wb;
  if (!world_pose(*s->second, time, &ps, &vs, &ws) || !world_pose(*b->second, time, &pb, &vb, &wb))
    return XR_SUCCESS;
  const Pose inv = inverse(pb);
  location->pose = to_xr(compose(inv, ps));
  // Untracked: the pose is left where the script has it (a runtime's pose
  // without valid bits means nothing), so a caller that ignores the bits
  // keeps the tool in contact and is caught.
  if (s->second->action && !g.tracked) return XR_SUCCESS;
  location->locationFlags = XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT |
                            XR_SPACE_LOCATION_POSITION_TRACKED_BIT |
                            XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
  if (velocity) {  // reference spaces do not move: the velocities in base's axes
    const V v = rotate(inv.q, vs), w = rotate(inv.q, ws);
    velocity->linearVelocity = {float(v.x), float(v.y), float(v.z)};
    velocity->angularVelocity = {float(w.x), float(w.y), float(w.z)};
    velocity->velocityFlags = XR_SPACE_VELOCITY_LINEAR_VALID_BIT | XR_SPACE_VELOCITY_ANGULAR_VALID_BIT;
  }
  return XR_SUCCESS;
}

XrResult log_haptic(XrSession session, const XrHapticActionInfo* info, const XrHapticVibration* v) {
  const Inside inside;
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  const auto a = g.actions.find(info->action);
  if (a == g.actions.end()) return XR_ERROR_HANDLE_INVALID;
  if (a->second->type != XR_ACTION_TYPE_VIBRATION_OUTPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
  ProxMockXrVibration e{};
  e.time = now_ns();
  e.stop = v ? 0 : 1;
  if (v) e.amplitude = v->amplitude, e.duration = v->duration, e.frequency = v->frequency;
  e.result = focused() ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
  if (v && !(v->amplitude >= 0.0f && v->amplitude <= 1.0f)) e.result = XR_ERROR_VALIDATION_FAILURE;
  g.log.push_back(e);
  return e.result;
}

XRAPI_ATTR XrResult XRAPI_CALL ApplyHapticFeedback(XrSession session, const XrHapticActionInfo* info,
                                                   const XrHapticBaseHeader* haptic) {
  if (haptic->type != XR_TYPE_HAPTIC_VIBRATION) return XR_ERROR_VALIDATION_FAILURE;
  return log_haptic(session, info, reinterpret_cast<const XrHapticVibration*>(haptic));
}

XRAPI_ATTR XrResult XRAPI_CALL StopHapticFeedback(XrSession session, const XrHapticActionInfo* info) {
  return log_haptic(session, info, nullptr);
}

constexpr XrDuration kPeriod = 11111111;  // 90 Hz

XRAPI_ATTR XrResult XRAPI_CALL WaitFrame(XrSession session, const XrFrameWaitInfo*, XrFrameState* state) {
  XrTime last;
  {
    std::lock_guard<std::mutex> lock(g.mutex);
    CHECK_SESSION(session);
    if (!g.running) return XR_ERROR_SESSION_NOT_RUNNING;
    last = g.last_wait;
  }
  // Paces the app at 90 Hz, as a compositor would.
  const XrTime wake = last + kPeriod;
  const XrTime now = now_ns();
  if (wake > now) std::this_thread::sleep_for(std::chrono::nanoseconds(wake - now));
  std::lock_guard<std::mutex> lock(g.mutex);
  g.last_wait = std::max(wake, now);
  state->predictedDisplayTime = g.last_wait + 2 * kPeriod;
  state->predictedDisplayPeriod = kPeriod;
  state->shouldRender = g.state == XR_SESSION_STATE_VISIBLE || focused() ? XR_TRUE : XR_FALSE;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL BeginFrame(XrSession session, const XrFrameBeginInfo*) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  if (!g.running) return XR_ERROR_SESSION_NOT_RUNNING;
  const bool discarded = g.frame_begun;
  g.frame_begun = true;
  return discarded ? XR_FRAME_DISCARDED : XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EndFrame(XrSession session, const XrFrameEndInfo* info) {
  std::lock_guard<std::mutex> lock(g.mutex);
  CHECK_SESSION(session);
  if (!g.frame_begun) return XR_ERROR_CALL_ORDER_INVALID;
  if (info->displayTime <= 0) return XR_ERROR_TIME_INVALID;
  g.frame_begun = false;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL ConvertTimespecTimeToTimeKHR(XrInstance instance, const struct timespec* t,
                                                            XrTime* time) {
  CHECK_INSTANCE(instance);
  if (!g.timespec) return XR_ERROR_FUNCTION_UNSUPPORTED;
  *time = XrTime(t->tv_sec) * 1000000000 + t->tv_nsec;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL ConvertTimeToTimespecTimeKHR(XrInstance instance, XrTime time,
                                                            struct timespec* t) {
  CHECK_INSTANCE(instance);
  if (!g.timespec) return XR_ERROR_FUNCTION_UNSUPPORTED;
  t->tv_sec = time / 1000000000;
  t->tv_nsec = time % 1000000000;
  return XR_SUCCESS;
}

// ---- the control panel ---------------------------------------------------------------
void set_script(const ProxMockXrKey* keys, int32_t count) {
  std::lock_guard<std::mutex> lock(g.mutex);
  g.script.assign(keys, keys + std::min(count, kMaxKeys));
}
void set_tracked(int32_t tracked) {
  std::lock_guard<std::mutex> lock(g.mutex);
  g.tracked = tracked != 0;
}
void set_focused(int32_t on) {
  std::lock_guard<std::mutex> lock(g.mutex);
  if (on && g.state == XR_SESSION_STATE_VISIBLE) set_state(XR_SESSION_STATE_FOCUSED);
  if (!on && g.state == XR_SESSION_STATE_FOCUSED) set_state(XR_SESSION_STATE_VISIBLE);
}
int32_t vibrations(ProxMockXrVibration* out, int32_t first, int32_t capacity) {
  std::lock_guard<std::mutex> lock(g.mutex);
  for (int32_t i = 0; i < capacity && first + i < int32_t(g.log.size()); ++i)
    out[i] = g.log[std::size_t(first + i)];
  return int32_t(g.log.size());
}
uint64_t locate_calls() { return g_locates.load(); }
int32_t max_concurrent() { return g_max_inside.load(); }

const ProxMockXrControl kControl = {set_script,   set_tracked,    set_focused, vibrations,
                                    locate_calls, max_concurrent, now_ns};
const ProxMockXrControl* get_control() { return &kControl; }

struct Entry {
  const char* name;
  PFN_xrVoidFunction fn;
};
#define ENTRY(n) \
  { "xr" #n, reinterpret_cast<PFN_xrVoidFunction>(&n) }
const Entry kEntries[] = {
    ENTRY(EnumerateInstanceExtensionProperties),
    ENTRY(CreateInstance),
    ENTRY(DestroyInstance),
    ENTRY(GetInstanceProperties),
    ENTRY(ResultToString),
    ENTRY(StructureTypeToString),
    ENTRY(GetSystem),
    ENTRY(GetSystemProperties),
    ENTRY(EnumerateViewConfigurations),
    ENTRY(EnumerateEnvironmentBlendModes),
    ENTRY(StringToPath),
    ENTRY(PathToString),
    ENTRY(CreateActionSet),
    ENTRY(DestroyActionSet),
    ENTRY(CreateAction),
    ENTRY(DestroyAction),
    ENTRY(SuggestInteractionProfileBindings),
    ENTRY(CreateSession),
    ENTRY(DestroySession),
    ENTRY(BeginSession),
    ENTRY(EndSession),
    ENTRY(RequestExitSession),
    ENTRY(PollEvent),
    ENTRY(AttachSessionActionSets),
    ENTRY(SyncActions),
    ENTRY(GetActionStatePose),
    ENTRY(CreateReferenceSpace),
    ENTRY(EnumerateReferenceSpaces),
    ENTRY(CreateActionSpace),
    ENTRY(DestroySpace),
    ENTRY(LocateSpace),
    ENTRY(ApplyHapticFeedback),
    ENTRY(StopHapticFeedback),
    ENTRY(WaitFrame),
    ENTRY(BeginFrame),
    ENTRY(EndFrame),
    ENTRY(ConvertTimespecTimeToTimeKHR),
    ENTRY(ConvertTimeToTimespecTimeKHR),
};

XRAPI_ATTR XrResult XRAPI_CALL GetInstanceProcAddr(XrInstance instance, const char* name,
                                                   PFN_xrVoidFunction* function) {
  *function = nullptr;
  if (std::strcmp(name, "proxMockXr_GetControl") == 0) {
    *function = reinterpret_cast<PFN_xrVoidFunction>(&get_control);
    return XR_SUCCESS;
  }
  const bool global = std::strcmp(name, "xrEnumerateInstanceExtensionProperties") == 0 ||
                      std::strcmp(name, "xrCreateInstance") == 0 ||
                      std::strcmp(name, "xrEnumerateApiLayerProperties") == 0;
  if (instance == XR_NULL_HANDLE && !global) return XR_ERROR_HANDLE_INVALID;
  if (instance != XR_NULL_HANDLE && instance != kInstance) return XR_ERROR_HANDLE_INVALID;
  if (std::strcmp(name, "xrGetInstanceProcAddr") == 0) {
    *function = reinterpret_cast<PFN_xrVoidFunction>(&GetInstanceProcAddr);
    return XR_SUCCESS;
  }
  if (std::strstr(name, "TimespecTime") && !g.timespec) return XR_ERROR_FUNCTION_UNSUPPORTED;
  for (const Entry& e : kEntries)
    if (std::strcmp(e.name, name) == 0) {
      *function = e.fn;
      return XR_SUCCESS;
    }
  return XR_ERROR_FUNCTION_UNSUPPORTED;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) XrResult xrNegotiateLoaderRuntimeInterface(
    const ProxMockXrNegotiateLoaderInfo* info, ProxMockXrNegotiateRuntimeRequest* request) {
  if (!info || !request || info->structType != PROX_MOCK_XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
      info->structVersion != PROX_MOCK_XR_LOADER_INFO_STRUCT_VERSION ||
      info->structSize != sizeof(ProxMockXrNegotiateLoaderInfo) ||
      request->structType != PROX_MOCK_XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST ||
      request->structVersion != PROX_MOCK_XR_RUNTIME_INFO_STRUCT_VERSION ||
      request->structSize != sizeof(ProxMockXrNegotiateRuntimeRequest) ||
      info->minInterfaceVersion > PROX_MOCK_XR_LOADER_INTERFACE_VERSION ||
      info->maxInterfaceVersion < PROX_MOCK_XR_LOADER_INTERFACE_VERSION)
    return XR_ERROR_INITIALIZATION_FAILED;
  request->runtimeInterfaceVersion = PROX_MOCK_XR_LOADER_INTERFACE_VERSION;
  request->runtimeApiVersion = XR_CURRENT_API_VERSION;
  request->getInstanceProcAddr = &GetInstanceProcAddr;
  return XR_SUCCESS;
}
