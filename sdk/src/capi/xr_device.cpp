// The OpenXR device through the C API (proxima_openxr.h): checks the def,
// resolves the OpenXR functions and makes the device
// (devices/xr/xr_device.h), which lives in the device table as every device
// does (device_table.h). Calls on one device come from the game thread that
// created it, but for GetStats.
#include "capi/common.h"
#include "capi/device_table.h"

#include "devices/xr/xr_device.h"

#include <proxima/proxima_openxr.h>

using namespace prox;
using namespace prox::capi;

namespace {

using devices::xr::XrDevice;

constexpr DeviceKind kXr = DeviceKind::Xr;

// An XR device in use for the length of one call, from the thread that
// created it (or any, for `game_thread` false).
struct XrUse : DeviceUse {
  explicit XrUse(const proxXrDeviceId& id, bool game_thread = true)
      : DeviceUse(kXr, {id.index1, id.generation}, nullptr) {
    if (game_thread && device().owner() != std::this_thread::get_id())
      fail(PROX_ERROR_WRONG_THREAD, "called from a thread other than the one that created the XR device");
  }
  XrDevice& device() const { return as<XrDevice>(); }
};

template <typename Pfn>
Pfn resolve(const proxXrDeviceDef& def, const char* name, bool required = true) {
  PFN_xrVoidFunction f = nullptr;
  const XrResult r = def.getInstanceProcAddr(def.instance, name, &f);
  if (XR_FAILED(r) || !f) {
    if (!required) return nullptr;
    fail(PROX_ERROR_INVALID_ARGUMENT, std::string("def->getInstanceProcAddr gives no ") + name +
                                          " (XrResult " + std::to_string(int(r)) +
                                          "): is def->instance live?");
  }
  return reinterpret_cast<Pfn>(f);
}

bool valid_state(XrSessionState s) { return s >= XR_SESSION_STATE_UNKNOWN && s <= XR_SESSION_STATE_EXITING; }

void check_def(const proxXrDeviceDef& d) {
  need_def(d, "proxDefaultXrDeviceDef");
  if (!d.getInstanceProcAddr) fail(PROX_ERROR_INVALID_ARGUMENT, "def->getInstanceProcAddr is NULL");
  if (d.instance == XR_NULL_HANDLE) fail(PROX_ERROR_INVALID_ARGUMENT, "def->instance is XR_NULL_HANDLE");
  if (d.session == XR_NULL_HANDLE) fail(PROX_ERROR_INVALID_ARGUMENT, "def->session is XR_NULL_HANDLE");
  if (d.baseSpace == XR_NULL_HANDLE) fail(PROX_ERROR_INVALID_ARGUMENT, "def->baseSpace is XR_NULL_HANDLE");
  if (d.poseAction == XR_NULL_HANDLE) fail(PROX_ERROR_INVALID_ARGUMENT, "def->poseAction is XR_NULL_HANDLE");
  to_pose(d.toolInGrip, "def->toolInGrip");
  to_pose(d.baseToWorld, "def->baseToWorld");
  if (enum_value(d.poseMode) != PROX_XR_LOCATE_EACH_TICK &&
      enum_value(d.poseMode) != PROX_XR_EXTRAPOLATE_FRAME)
    fail(PROX_ERROR_INVALID_ARGUMENT, "def->poseMode is not a proxXrPoseMode");
  need_positive(d.vibrationRate, "def->vibrationRate");
  if (d.vibrationRate > 1000.0) fail(PROX_ERROR_INVALID_ARGUMENT, "def->vibrationRate must be <= 1000 Hz");
  need_positive(d.forceForFullAmplitude, "def->forceForFullAmplitude");
  need_positive(d.pulseDuration, "def->pulseDuration");
  need_finite(d.tickRate, "def->tickRate");
  if (d.tickRate < 10.0 || d.tickRate > 10000.0)
    fail(PROX_ERROR_INVALID_ARGUMENT, "def->tickRate must be in [10, 10000] Hz");
  need_finite(d.maxExtrapolation, "def->maxExtrapolation");
  if (d.maxExtrapolation < 0.0) fail(PROX_ERROR_INVALID_ARGUMENT, "def->maxExtrapolation must be >= 0 s");
  if (!valid_state(d.sessionState))
    fail(PROX_ERROR_INVALID_ARGUMENT, "def->sessionState is not an XrSessionState");
  if (d.runtimeTime < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "def->runtimeTime must be >= 0 (0: none)");
}

// The def's poses, normalised (the device thread composes them every tick).
runtime::DevicePose normalised(const proxPose& p, const char* name) {
  const proxPose n = to_c(to_pose(p, name));
  return {{n.position.x, n.position.y, n.position.z}, {n.rotation.w, n.rotation.x, n.rotation.y, n.rotation.z}};
}

}  // namespace

extern "C" {

proxXrDeviceDef proxDefaultXrDeviceDef(void) {
  proxXrDeviceDef d{};
  d.subactionPath = XR_NULL_PATH;
  d.toolInGrip.rotation.w = 1.0;
  d.baseToWorld.rotation.w = 1.0;
  d.poseMode = PROX_XR_LOCATE_EACH_TICK;
  d.vibrationRate = 100.0;
  d.forceForFullAmplitude = 5.0;
  d.sessionState = XR_SESSION_STATE_FOCUSED;
  d.tickRate = 1000.0;
  d.pulseDuration = 0.02;
  d.maxExtrapolation = 0.05;
  d.apiVersion = PROX_API_VERSION;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateXrDevice(proxWorldId world, const proxXrDeviceDef* def, proxXrDeviceId* device) {
  return guard("proxWorld_CreateXrDevice", [&] {
    need(device, "device");
    *device = proxXrDeviceId{};
    world_of(world);
    need(def, "def");
    check_def(*def);
    devices::xr::XrSettings s;
    s.instance = def->instance;
    s.session = def->session;
    s.base_space = def->baseSpace;
    s.pose_action = def->poseAction;
    s.haptic_action = def->hapticAction;
    s.subaction_path = def->subactionPath;
    s.tool_in_grip = normalised(def->toolInGrip, "def->toolInGrip");
    s.base_to_world = normalised(def->baseToWorld, "def->baseToWorld");
    s.pose_mode = enum_value(def->poseMode) == PROX_XR_EXTRAPOLATE_FRAME ? devices::xr::XrPoseMode::ExtrapolateFrame
                                                                         : devices::xr::XrPoseMode::LocateEachTick;
    s.vibration_rate = def->vibrationRate;
    s.force_for_full_amplitude = def->forceForFullAmplitude;
    s.pulse_duration = def->pulseDuration;
    s.tick_rate = def->tickRate;
    s.max_extrapolation = def->maxExtrapolation;
    s.session_state = def->sessionState;
    s.fn.locateSpace = resolve<PFN_xrLocateSpace>(*def, "xrLocateSpace");
    s.fn.applyHaptic = resolve<PFN_xrApplyHapticFeedback>(*def, "xrApplyHapticFeedback");
    s.fn.stopHaptic = resolve<PFN_xrStopHapticFeedback>(*def, "xrStopHapticFeedback");
    s.fn.createActionSpace = resolve<PFN_xrCreateActionSpace>(*def, "xrCreateActionSpace");
    s.fn.destroySpace = resolve<PFN_xrDestroySpace>(*def, "xrDestroySpace");
#if defined(_WIN32)
    if (def->timespecTime)
      fail(PROX_ERROR_INVALID_ARGUMENT,
           "def->timespecTime is set on Windows: use def->win32PerformanceCounterTime with "
           "XR_KHR_win32_convert_performance_counter_time");
    if (def->win32PerformanceCounterTime) {
      // Trusted, not tried, as the timespec function is elsewhere.
      s.fn.convertWin32 =
          resolve<PFN_xrVoidFunction>(*def, "xrConvertWin32PerformanceCounterToTimeKHR", false);
      if (!s.fn.convertWin32)
        fail(PROX_ERROR_INVALID_ARGUMENT,
             "def->win32PerformanceCounterTime is set but xrConvertWin32PerformanceCounterToTimeKHR is not "
             "available: enable XR_KHR_win32_convert_performance_counter_time in xrCreateInstance, or leave "
             "def->win32PerformanceCounterTime 0");
    }
#else
    if (def->win32PerformanceCounterTime)
      fail(PROX_ERROR_INVALID_ARGUMENT,
           "def->win32PerformanceCounterTime is set, but XR_KHR_win32_convert_performance_counter_time is "
           "Windows only: use def->timespecTime with XR_KHR_convert_timespec_time here");
    if (def->timespecTime) {
      s.fn.convertTimespec =
          resolve<decltype(s.fn.convertTimespec)>(*def, "xrConvertTimespecTimeToTimeKHR", false);
      // Trusted, not tried: the loader and its layers hand the function out
      // whether or not the app enabled the extension, and calling it then is
      // undefined (Debian's core validation layer 1.0.20 crashes).
      if (!s.fn.convertTimespec)
        fail(PROX_ERROR_INVALID_ARGUMENT,
             "def->timespecTime is set but xrConvertTimespecTimeToTimeKHR is not available: enable "
             "XR_KHR_convert_timespec_time in xrCreateInstance, or leave def->timespecTime 0");
    }
#endif
    XrActionSpaceCreateInfo info{};

    info.type = XR_TYPE_ACTION_SPACE_CREATE_INFO;
    info.action = def->poseAction;
    info.subactionPath = def->subactionPath;
    info.poseInActionSpace.orientation.w = 1.0f;
    const XrResult r = s.fn.createActionSpace(def->session, &info, &s.pose_space);
    if (XR_FAILED(r))
      fail(PROX_ERROR_INVALID_ARGUMENT, "xrCreateActionSpace for def->poseAction failed (XrResult " +
                                            std::to_string(int(r)) +
                                            "): are def->session and def->poseAction live, the action a "
                                            "POSE_INPUT and def->subactionPath one of its subaction paths?");

    // From here on the device owns the space (and destroys it when closed).
    auto made = std::make_shared<XrDevice>(s);
    if (def->runtimeTime > 0) made->on_runtime_time(def->runtimeTime, runtime::stream_clock());
    XrDevice& started = *made;
    const DeviceSlot slot = add_device(world, kXr, std::move(made));
    started.start();
    *device = {slot.index1, slot.generation};
  });
}

proxResult proxXrDevice_OnSessionState(proxXrDeviceId device, XrSessionState state) {
  return guard("proxXrDevice_OnSessionState", [&] {
    const XrUse s(device);
    if (!valid_state(state)) fail(PROX_ERROR_INVALID_ARGUMENT, "state is not an XrSessionState");
    s.device().on_session_state(state);
  });
}

proxResult proxXrDevice_OnFrame(proxXrDeviceId device, XrTime predictedDisplayTime,
                                XrDuration predictedDisplayPeriod) {
  return guard("proxXrDevice_OnFrame", [&] {
    const XrUse s(device);
    if (predictedDisplayTime <= 0) fail(PROX_ERROR_INVALID_ARGUMENT, "predictedDisplayTime must be > 0");
    if (predictedDisplayPeriod < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "predictedDisplayPeriod must be >= 0");
    s.device().on_frame(predictedDisplayTime, predictedDisplayPeriod, runtime::stream_clock());
  });
}

proxResult proxXrDevice_OnRuntimeTime(proxXrDeviceId device, XrTime time) {
  return guard("proxXrDevice_OnRuntimeTime", [&] {
    const XrUse s(device);
    if (time <= 0)
      fail(PROX_ERROR_INVALID_ARGUMENT,
           "time must be > 0: an XrTime the runtime gave (an event's time) or accepted (a locate's)");
    s.device().on_runtime_time(time, runtime::stream_clock());
  });
}

proxResult proxXrDevice_GetDeviceDef(proxXrDeviceId device, proxDeviceDef* def) {
  return guard("proxXrDevice_GetDeviceDef", [&] {
    need(def, "def");
    *def = device_def(XrUse(device));
  });
}

proxResult proxXrDevice_GetStats(proxXrDeviceId device, proxXrDeviceStats* stats) {
  return guard("proxXrDevice_GetStats", [&] {
    need(stats, "stats");
    const devices::xr::XrStats s = XrUse(device, false).device().stats();
    *stats = proxXrDeviceStats{};
    stats->ticks = s.ticks;
    stats->locates = s.locates;
    stats->untrackedTicks = s.untracked;
    stats->notFocusedTicks = s.not_focused;
    stats->vibrationsSent = s.vibrations_sent;
    stats->vibrationsRefused = s.vibrations_refused;
    stats->stopsSent = s.stops_sent;
    stats->posesPushed = s.poses_pushed;
    stats->timeSource = static_cast<proxXrTimeSource>(s.time_source);
    stats->timeFromFrames = s.time_source == devices::xr::XrTimeSource::Frames ? 1 : 0;
    stats->lastXrResult = s.last_result;
    stats->lastAmplitude = s.last_amplitude;
    stats->sessionState = s.session_state;
  });
}

proxResult proxXrDevice_Destroy(proxXrDeviceId device) {
  return guard("proxXrDevice_Destroy", [&] {
    { const XrUse use(device); }  // from the thread that made it
    destroy_device(kXr, {device.index1, device.generation}, nullptr);
  });
}

proxBool proxXrDevice_IsValid(proxXrDeviceId device) {
  return valid("proxXrDevice_IsValid", [&] { XrUse use(device, false); });
}

}  // extern "C"
