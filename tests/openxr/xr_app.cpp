#include "openxr/xr_app.h"

#include "openxr/loader_negotiation.h"

#include <time.h>
#define XR_USE_TIMESPEC
#include <openxr/openxr_platform.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include <dlfcn.h>
#include <unistd.h>

// Debian's OpenXR loader 1.0.20 keeps a few objects from each
// xrCreateInstance after xrDestroyInstance (about 1.5 kB, all allocated
// inside the loader): not ours to fix (tests/openxr/lsan_openxr_loader.supp
// says the same for the sample).
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() { return "leak:libopenxr_loader.so\n"; }

namespace prox::test {
namespace {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

void xr_check(XrResult r, const char* what) {
  if (XR_FAILED(r))
    throw std::runtime_error(std::string(what) + " failed: XrResult " + std::to_string(int(r)));
}

const ProxMockXrControl& mock_control() {
  static const ProxMockXrControl* control = [] {
    void* lib = dlopen(PROX_MOCK_XR_RUNTIME, RTLD_NOW | RTLD_LOCAL);
    if (!lib) throw std::runtime_error(std::string("dlopen of the mock runtime: ") + dlerror());
    auto negotiate = reinterpret_cast<ProxMockXrNegotiateFn>(dlsym(lib, "xrNegotiateLoaderRuntimeInterface"));
    if (!negotiate) throw std::runtime_error("the mock runtime exports no xrNegotiateLoaderRuntimeInterface");
    ProxMockXrNegotiateLoaderInfo info{PROX_MOCK_XR_LOADER_INTERFACE_STRUCT_LOADER_INFO,
                                       PROX_MOCK_XR_LOADER_INFO_STRUCT_VERSION,
                                       sizeof(ProxMockXrNegotiateLoaderInfo),
                                       1,
                                       1,
                                       XR_MAKE_VERSION(1, 0, 0),
                                       XR_CURRENT_API_VERSION};
    ProxMockXrNegotiateRuntimeRequest request{PROX_MOCK_XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST,
                                              PROX_MOCK_XR_RUNTIME_INFO_STRUCT_VERSION,
                                              sizeof(ProxMockXrNegotiateRuntimeRequest),
                                              0,
                                              0,
                                              nullptr};
    xr_check(negotiate(&info, &request), "negotiating with the mock runtime");
    PFN_xrVoidFunction f = nullptr;
    xr_check(request.getInstanceProcAddr(XR_NULL_HANDLE, "proxMockXr_GetControl", &f),
             "proxMockXr_GetControl");
    return reinterpret_cast<ProxMockXrGetControlFn>(f)();
  }();
  return *control;
}

XrApp::XrApp(const XrAppOptions& options) : timespec_(options.timespec) {
  // The real loader, told to load the mock runtime and the core validation
  // layer, as a user's environment would tell it.
  setenv("XR_RUNTIME_JSON", PROX_MOCK_XR_RUNTIME_JSON, 1);
  setenv("XR_ENABLE_API_LAYERS", "XR_APILAYER_LUNARG_core_validation", 1);
  mock_control().setHabits(options.habits);  // loaded before the loader loads it: the control outlives instances
  // The core validation layer reads where to write once per process: one
  // log for the process, and each app reads what was added since it began.
  static const std::string log = [] {
    const std::string path =
        std::string(::testing::TempDir()) + "proxima_xr_validation_" + std::to_string(getpid()) + ".txt";
    std::remove(path.c_str());
    setenv("XR_CORE_VALIDATION_EXPORT_TYPE", "text", 1);
    setenv("XR_CORE_VALIDATION_FILE_NAME", path.c_str(), 1);
    return path;
  }();
  validationLog = log;
  {
    std::ifstream in(log, std::ios::ate);
    validationStart = in ? std::size_t(in.tellg()) : 0;
  }

  std::vector<const char*> extensions = {XR_MND_HEADLESS_EXTENSION_NAME};
  if (timespec_) extensions.push_back(XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME);
  XrInstanceCreateInfo ci{};
  ci.type = XR_TYPE_INSTANCE_CREATE_INFO;
  std::snprintf(ci.applicationInfo.applicationName, sizeof ci.applicationInfo.applicationName,
                "proxima-tests");
  ci.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  ci.enabledExtensionCount = uint32_t(extensions.size());
  ci.enabledExtensionNames = extensions.data();
  xr_check(xrCreateInstance(&ci, &instance), "xrCreateInstance");

  XrSystemGetInfo sys{};

  sys.type = XR_TYPE_SYSTEM_GET_INFO;
  sys.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  xr_check(xrGetSystem(instance, &sys, &system), "xrGetSystem");

  // Actions: the app's own set, with Proxima's merged in.
  XrActionSetCreateInfo si{};
  si.type = XR_TYPE_ACTION_SET_CREATE_INFO;
  std::snprintf(si.actionSetName, sizeof si.actionSetName, "gameplay");
  std::snprintf(si.localizedActionSetName, sizeof si.localizedActionSetName, "Gameplay");
  xr_check(xrCreateActionSet(instance, &si, &set), "xrCreateActionSet");
  XrPath left = XR_NULL_PATH;
  xr_check(xrStringToPath(instance, "/user/hand/left", &left), "xrStringToPath");
  xr_check(xrStringToPath(instance, "/user/hand/right", &right), "xrStringToPath");
  XrActionCreateInfo ai{};
  ai.type = XR_TYPE_ACTION_CREATE_INFO;
  ai.actionType = XR_ACTION_TYPE_POSE_INPUT;
  std::snprintf(ai.actionName, sizeof ai.actionName, "off_hand");
  std::snprintf(ai.localizedActionName, sizeof ai.localizedActionName, "Off hand");
  ai.countSubactionPaths = 1;
  ai.subactionPaths = &left;
  xr_check(xrCreateAction(set, &ai, &appAction), "xrCreateAction");
  if (proxXrCreateActions(xrGetInstanceProcAddr, instance, set, "proxima", &pose, &haptic) != PROX_SUCCESS)
    throw std::runtime_error(std::string("proxXrCreateActions: ") + proxGetLastError());

  const char* profile = "/interaction_profiles/khr/simple_controller";
  std::vector<XrActionSuggestedBinding> bindings(1);
  bindings[0].action = appAction;
  xr_check(xrStringToPath(instance, "/user/hand/left/input/grip/pose", &bindings[0].binding),
           "xrStringToPath");
  XrActionSuggestedBinding ours[4];
  int32_t count = 0;
  if (proxXrGetSuggestedBindings(xrGetInstanceProcAddr, instance, profile, "right", pose, haptic, ours, 4,
                                 &count) != PROX_SUCCESS)
    throw std::runtime_error(std::string("proxXrGetSuggestedBindings: ") + proxGetLastError());
  bindings.insert(bindings.end(), ours, ours + count);
  XrInteractionProfileSuggestedBinding suggested{};
  suggested.type = XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING;
  xr_check(xrStringToPath(instance, profile, &suggested.interactionProfile), "xrStringToPath");
  suggested.countSuggestedBindings = uint32_t(bindings.size());
  suggested.suggestedBindings = bindings.data();
  xr_check(xrSuggestInteractionProfileBindings(instance, &suggested), "xrSuggestInteractionProfileBindings");

  // A headless session: no graphics binding.
  XrSessionCreateInfo session_info{};
  session_info.type = XR_TYPE_SESSION_CREATE_INFO;
  session_info.systemId = system;
  xr_check(xrCreateSession(instance, &session_info, &session), "xrCreateSession");
  XrReferenceSpaceCreateInfo ri{};
  ri.type = XR_TYPE_REFERENCE_SPACE_CREATE_INFO;
  ri.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  ri.poseInReferenceSpace.orientation.w = 1.0f;
  xr_check(xrCreateReferenceSpace(session, &ri, &local), "xrCreateReferenceSpace");
  XrSessionActionSetsAttachInfo attach{};
  attach.type = XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO;
  attach.countActionSets = 1;
  attach.actionSets = &set;
  xr_check(xrAttachSessionActionSets(session, &attach), "xrAttachSessionActionSets");
}

XrApp::~XrApp() {
  try {
    destroy();
  } catch (...) {
  }
}

proxXrDeviceDef XrApp::device_def() const {
  proxXrDeviceDef d = proxDefaultXrDeviceDef();
  d.getInstanceProcAddr = xrGetInstanceProcAddr;
  d.instance = instance;
  d.session = session;
  d.baseSpace = local;
  d.poseAction = pose;
  d.hapticAction = haptic;
  d.subactionPath = right;
  d.timespecTime = timespec_ ? 1 : 0;
  d.sessionState = state;
  d.runtimeTime = runtime_now();
  return d;
}

void XrApp::set_device(proxXrDeviceId device) {
  device_ = device;
  if (device_.index1 != 0 && lastEventTime > 0 &&
      proxXrDevice_OnRuntimeTime(device_, runtime_now()) != PROX_SUCCESS)
    throw std::runtime_error(std::string("proxXrDevice_OnRuntimeTime: ") + proxGetLastError());
}

XrTime XrApp::runtime_now() const {
  if (lastEventTime <= 0) return 0;
  return lastEventTime + XrTime((steady_seconds() - lastEventPolled) * 1e9);
}

void XrApp::frame() {
  XrEventDataBuffer event{};
  event.type = XR_TYPE_EVENT_DATA_BUFFER;
  while (xrPollEvent(instance, &event) == XR_SUCCESS) {
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
      const auto& changed = reinterpret_cast<const XrEventDataSessionStateChanged&>(event);
      state = changed.state;
      if (device_.index1 != 0 && proxXrDevice_OnSessionState(device_, state) != PROX_SUCCESS)
        throw std::runtime_error(std::string("proxXrDevice_OnSessionState: ") + proxGetLastError());
      if (changed.time > lastEventTime) {
        lastEventTime = changed.time;
        lastEventPolled = steady_seconds();
        if (device_.index1 != 0 && proxXrDevice_OnRuntimeTime(device_, changed.time) != PROX_SUCCESS)
          throw std::runtime_error(std::string("proxXrDevice_OnRuntimeTime: ") + proxGetLastError());
      }
      if (state == XR_SESSION_STATE_READY) {
        XrSessionBeginInfo begin{};
        begin.type = XR_TYPE_SESSION_BEGIN_INFO;
        begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
        xr_check(xrBeginSession(session, &begin), "xrBeginSession");
        running = true;
      } else if (state == XR_SESSION_STATE_STOPPING) {
        xr_check(xrEndSession(session), "xrEndSession");
        running = false;
      }
    }
    event = {};
    event.type = XR_TYPE_EVENT_DATA_BUFFER;
  }
  if (!running) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return;
  }
  XrFrameState fs{};
  fs.type = XR_TYPE_FRAME_STATE;
  if (frameCalls) {
    xr_check(xrWaitFrame(session, nullptr, &fs), "xrWaitFrame");
    frameCalls = fs.predictedDisplayTime > 0;
    if (frameCalls) xr_check(xrBeginFrame(session, nullptr), "xrBeginFrame");
  }
  XrActiveActionSet active{set, XR_NULL_PATH};
  XrActionsSyncInfo sync{};
  sync.type = XR_TYPE_ACTIONS_SYNC_INFO;
  sync.countActiveActionSets = 1;
  sync.activeActionSets = &active;
  const XrResult r = xrSyncActions(session, &sync);
  xr_check(r, "xrSyncActions");
  if (r == XR_SESSION_NOT_FOCUSED) ++syncsNotFocused;
  if (!frameCalls) {  // headless pacing: nothing else waits
    std::this_thread::sleep_for(std::chrono::microseconds(11111));
    return;
  }
  if (device_.index1 != 0 &&
      proxXrDevice_OnFrame(device_, fs.predictedDisplayTime, fs.predictedDisplayPeriod) != PROX_SUCCESS)
    throw std::runtime_error(std::string("proxXrDevice_OnFrame: ") + proxGetLastError());
  XrFrameEndInfo end{};
  end.type = XR_TYPE_FRAME_END_INFO;
  end.displayTime = fs.predictedDisplayTime;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  xr_check(xrEndFrame(session, &end), "xrEndFrame");
}

bool XrApp::pump_until(const std::function<bool()>& done, double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    frame();
    if (done()) return true;
  }
  return false;
}

void XrApp::pump_for(double seconds) {
  pump_until([] { return false; }, seconds);
}

void XrApp::exit_session() {
  if (!running) return;
  xr_check(xrRequestExitSession(session), "xrRequestExitSession");
  pump_until([&] { return state == XR_SESSION_STATE_EXITING; }, 10.0);
}

void XrApp::destroy() {
  if (instance == XR_NULL_HANDLE) return;
  if (session != XR_NULL_HANDLE) {
    if (local != XR_NULL_HANDLE) xrDestroySpace(local);
    xrDestroySession(session);
  }
  xrDestroyActionSet(set);
  xrDestroyInstance(instance);
  instance = XR_NULL_HANDLE;
  session = XR_NULL_HANDLE;
}

std::string validation_errors(const XrApp& app) {
  std::ifstream in(app.validationLog);
  std::stringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  const std::string ours = app.validationStart < text.size() ? text.substr(app.validationStart) : "";
  return ours.find("VALID_ERROR") != std::string::npos ? ours : "";
}

}  // namespace prox::test
