// A mock OpenXR runtime for the tests and the headless sample: no display,
// no devices. It offers XR_MND_headless and XR_KHR_convert_timespec_time,
// one system with one scripted right-hand controller (its grip pose follows
// the script of mock_control.h) and logs every vibration. Just enough of the
// API for an app that makes a headless session, actions and a frame loop,
// checked strictly, so a wrong call fails here as it would on a real
// runtime. Loaded by the real OpenXR loader through a manifest
// (XR_RUNTIME_JSON); the one OpenXR symbol it exports is
// xrNegotiateLoaderRuntimeInterface (beside it, the control panel's
// proxMockXr_* functions for the bindings' tests, mock_control.h). On
// request it plays real runtimes' habits (mock_control.h). This file: instances, paths, actions,
// sessions, events, frames and time; spaces and haptics are in
// mock_spaces.cpp, the grip's script and the control panel in
// mock_control.cpp.
#include "loader_negotiation.h"
#include "mock_state.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

namespace prox::mock_xr {

State g;
std::atomic<std::uint64_t> g_locates{0};
std::atomic<int> g_inside{0}, g_max_inside{0};
std::atomic<std::uint64_t> g_waits{0}, g_syncs{0};
std::uintptr_t g_next_handle = 0x10000;

std::string path_string(XrPath p) { return p >= 1 && p <= g.paths.size() ? g.paths[p - 1] : std::string(); }

void set_state(XrSessionState s) {
  g.state = s;
  g.events.push_back(s);
}

bool action_active(XrAction action, XrPath subaction) {
  const auto a = g.actions.find(action);
  if (a == g.actions.end() || !answers()) return false;
  if (std::find(g.synced.begin(), g.synced.end(), a->second->set) == g.synced.end()) return false;
  return subaction == XR_NULL_PATH || path_string(subaction) == "/user/hand/right";
}

namespace {

XrPath path_of(const std::string& s) {
  for (std::size_t i = 0; i < g.paths.size(); ++i)
    if (g.paths[i] == s) return XrPath(i + 1);
  g.paths.push_back(s);
  return XrPath(g.paths.size());
}

// ---- the API ---------------------------------------------------------------------

const char* const kExtensions[] = {XR_MND_HEADLESS_EXTENSION_NAME,
                                   XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME};
const uint32_t kExtensionVersions[] = {XR_MND_headless_SPEC_VERSION,
                                       XR_KHR_convert_timespec_time_SPEC_VERSION};

XRAPI_ATTR XrResult XRAPI_CALL EnumerateInstanceExtensionProperties(const char* layer, uint32_t capacity,
                                                                    uint32_t* count,
                                                                    XrExtensionProperties* props) {
  if (layer) return XR_ERROR_API_LAYER_NOT_PRESENT;
  // Before an instance: the habits a new one would have.
  const uint32_t n = (habits_for_new_instance() & PROX_MOCK_XR_HABIT_NO_TIMESPEC) ? 1 : 2;
  *count = n;
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < n) return XR_ERROR_SIZE_INSUFFICIENT;
  for (uint32_t i = 0; i < n; ++i) {
    std::snprintf(props[i].extensionName, sizeof props[i].extensionName, "%s", kExtensions[i]);
    props[i].extensionVersion = kExtensionVersions[i];
  }
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateInstance(const XrInstanceCreateInfo* info, XrInstance* instance) {
  std::lock_guard<std::mutex> lock(g.mutex);
  if (g.instance) return XR_ERROR_LIMIT_REACHED;
  bool headless = false, timespec = false;
  const std::uint32_t habits = habits_for_new_instance();
  for (uint32_t i = 0; i < info->enabledExtensionCount; ++i) {
    const std::string e = info->enabledExtensionNames[i];
    if (e == kExtensions[0])
      headless = true;
    else if (e == kExtensions[1] && !(habits & PROX_MOCK_XR_HABIT_NO_TIMESPEC))
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
  g.habits = habits;
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
  g.session_begun = 0;
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
  // For a test of a separate process (the sample): how fast its loop ran.
  if (std::getenv("PROX_MOCK_XR_REPORT") && g.session_begun > 0)
    std::fprintf(stderr, "mock runtime: %llu xrSyncActions, %llu xrWaitFrame in %.3f s since xrBeginSession\n",
                 static_cast<unsigned long long>(g_syncs.load()), static_cast<unsigned long long>(g_waits.load()),
                 double(now_ns() - g.session_begun) * 1e-9);
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
  g.session_begun = now_ns();
  if (habit(PROX_MOCK_XR_HABIT_STAYS_READY)) return XR_SUCCESS;
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
  g_syncs.fetch_add(1);
  if (!answers()) {
    g.synced.clear();
    return XR_SESSION_NOT_FOCUSED;
  }
  g.synced.clear();
  for (uint32_t i = 0; i < info->countActiveActionSets; ++i)
    g.synced.push_back(info->activeActionSets[i].actionSet);
  return XR_SUCCESS;
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

constexpr XrDuration kPeriod = 11111111;  // 90 Hz

XRAPI_ATTR XrResult XRAPI_CALL WaitFrame(XrSession session, const XrFrameWaitInfo*, XrFrameState* state) {
  XrTime last;
  {
    std::lock_guard<std::mutex> lock(g.mutex);
    CHECK_SESSION(session);
    if (!g.running) return XR_ERROR_SESSION_NOT_RUNNING;
    g_waits.fetch_add(1);
    // A headless session must not render (XR_MND_headless).
    state->shouldRender = XR_FALSE;
    if (habit(PROX_MOCK_XR_HABIT_ZERO_DISPLAY_TIME)) {  // no pacing, no time
      state->predictedDisplayTime = 0;
      state->predictedDisplayPeriod = 0;
      return XR_SUCCESS;
    }
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
}  // namespace prox::mock_xr

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
  request->getInstanceProcAddr = &prox::mock_xr::GetInstanceProcAddr;
  return XR_SUCCESS;
}
