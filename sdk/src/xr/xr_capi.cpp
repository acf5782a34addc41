// The OpenXR device through the C API (proxima_openxr.h). Each XR device
// owns a streamed device of its world (the haptic loop's side, which lives
// as long as the world, so a tool never reads a freed device) and a thread
// that feeds it. Its ids live in a table of their own; calls on one device
// are made from the game thread that created it.
#include "capi/common.h"

#include "runtime/stream_device.h"
#include "xr/xr_device.h"

#include <proxima/proxima_openxr.h>

using namespace prox;
using namespace prox::capi;

namespace {

struct XrSlot {
  std::uint32_t generation = 0;
  std::unique_ptr<xr::XrDevice> device;
  std::thread::id owner;
};

std::mutex g_xr_mutex;  // the table's shape; GetStats may come from any thread
std::vector<XrSlot> g_xr_slots;

XrSlot& slot_of(proxXrDeviceId id, bool game_thread = true) {
  if (id.index1 == 0) fail(PROX_ERROR_INVALID_HANDLE, "device is a null id");
  if (id.index1 > g_xr_slots.size() || g_xr_slots[id.index1 - 1].generation != id.generation ||
      !g_xr_slots[id.index1 - 1].device)
    fail(PROX_ERROR_INVALID_HANDLE, "device does not name a live XR device (destroyed, or never created)");
  XrSlot& s = g_xr_slots[id.index1 - 1];
  if (game_thread && s.owner != std::this_thread::get_id())
    fail(PROX_ERROR_WRONG_THREAD, "called from a thread other than the one that created the XR device");
  return s;
}

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
proxPose normalised(const proxPose& p, const char* name) { return to_c(to_pose(p, name)); }

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
    xr::XrSettings s;
    s.def = *def;
    s.def.toolInGrip = normalised(def->toolInGrip, "def->toolInGrip");
    s.def.baseToWorld = normalised(def->baseToWorld, "def->baseToWorld");
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
    // Poses and vibrations go through a streamed device that holds the last
    // pose (the device thread pushes one every tick).
    proxStreamDeviceDef stream_def = proxDefaultStreamDeviceDef();
    stream_def.mode = PROX_STREAM_HOLD;
    stream_def.staleAfter = std::max(0.05, 20.0 / def->tickRate);
    proxStreamDeviceId stream{};
    if (const proxResult r = proxWorld_CreateStreamDevice(world, &stream_def, &stream); r != PROX_SUCCESS)
      fail(r, g_last_error);
    s.stream = stream;

    XrActionSpaceCreateInfo info{};

    info.type = XR_TYPE_ACTION_SPACE_CREATE_INFO;
    info.action = def->poseAction;
    info.subactionPath = def->subactionPath;
    info.poseInActionSpace.orientation.w = 1.0f;
    const XrResult r = s.fn.createActionSpace(def->session, &info, &s.poseSpace);
    if (XR_FAILED(r))
      fail(PROX_ERROR_INVALID_ARGUMENT, "xrCreateActionSpace for def->poseAction failed (XrResult " +
                                            std::to_string(int(r)) +
                                            "): are def->session and def->poseAction live, the action a "
                                            "POSE_INPUT and def->subactionPath one of its subaction paths?");

    std::lock_guard<std::mutex> lock(g_xr_mutex);
    std::size_t i = 0;
    while (i < g_xr_slots.size() && g_xr_slots[i].device) ++i;
    if (i == g_xr_slots.size()) g_xr_slots.emplace_back();
    XrSlot& slot = g_xr_slots[i];
    slot.generation += 1;
    slot.owner = std::this_thread::get_id();
    slot.device = std::make_unique<xr::XrDevice>(s);
    if (def->runtimeTime > 0) slot.device->on_runtime_time(def->runtimeTime, runtime::stream_clock());
    slot.device->start();
    *device = {std::uint32_t(i + 1), slot.generation};
  });
}

proxResult proxXrDevice_OnSessionState(proxXrDeviceId device, XrSessionState state) {
  return guard("proxXrDevice_OnSessionState", [&] {
    std::lock_guard<std::mutex> lock(g_xr_mutex);
    XrSlot& s = slot_of(device);
    if (!valid_state(state)) fail(PROX_ERROR_INVALID_ARGUMENT, "state is not an XrSessionState");
    s.device->on_session_state(state);
  });
}

proxResult proxXrDevice_OnFrame(proxXrDeviceId device, XrTime predictedDisplayTime,
                                XrDuration predictedDisplayPeriod) {
  return guard("proxXrDevice_OnFrame", [&] {
    std::lock_guard<std::mutex> lock(g_xr_mutex);
    XrSlot& s = slot_of(device);
    if (predictedDisplayTime <= 0) fail(PROX_ERROR_INVALID_ARGUMENT, "predictedDisplayTime must be > 0");
    if (predictedDisplayPeriod < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "predictedDisplayPeriod must be >= 0");
    s.device->on_frame(predictedDisplayTime, predictedDisplayPeriod, runtime::stream_clock());
  });
}

proxResult proxXrDevice_OnRuntimeTime(proxXrDeviceId device, XrTime time) {
  return guard("proxXrDevice_OnRuntimeTime", [&] {
    std::lock_guard<std::mutex> lock(g_xr_mutex);
    XrSlot& s = slot_of(device);
    if (time <= 0)
      fail(PROX_ERROR_INVALID_ARGUMENT,
           "time must be > 0: an XrTime the runtime gave (an event's time) or accepted (a locate's)");
    s.device->on_runtime_time(time, runtime::stream_clock());
  });
}

proxResult proxXrDevice_GetDeviceDef(proxXrDeviceId device, proxDeviceDef* def) {
  return guard("proxXrDevice_GetDeviceDef", [&] {
    need(def, "def");
    proxStreamDeviceId stream;
    {
      std::lock_guard<std::mutex> lock(g_xr_mutex);
      stream = slot_of(device).device->settings().stream;
    }
    if (const proxResult r = proxStreamDevice_GetDeviceDef(stream, def); r != PROX_SUCCESS)
      fail(r, g_last_error);
  });
}

proxResult proxXrDevice_GetStats(proxXrDeviceId device, proxXrDeviceStats* stats) {
  return guard("proxXrDevice_GetStats", [&] {
    need(stats, "stats");
    std::lock_guard<std::mutex> lock(g_xr_mutex);
    *stats = slot_of(device, false).device->stats();
  });
}

proxResult proxXrDevice_Destroy(proxXrDeviceId device) {
  return guard("proxXrDevice_Destroy", [&] {
    std::unique_ptr<xr::XrDevice> gone;
    {
      std::lock_guard<std::mutex> lock(g_xr_mutex);
      gone = std::move(slot_of(device).device);
    }
    gone->stop();  // no OpenXR call from its thread after this
    const xr::XrSettings& s = gone->settings();
    s.fn.destroySpace(s.poseSpace);
  });
}

}  // extern "C"
