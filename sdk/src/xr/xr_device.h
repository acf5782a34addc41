// The OpenXR device's thread (docs/openxr.md). It ticks at 1 kHz on its own
// thread: locates the app's pose action space (each tick, or once a frame
// and extrapolates), pushes the tool's pose into a streamed device of the
// world, reads back the wrench the haptic loop rendered and turns it into
// the controller's vibration. The game thread forwards session states and
// frame times through atomics and a seqlock, so neither side waits; the
// haptic loop meets this thread through the streamed device's seqlocks and
// never calls OpenXR.
#pragma once

#include <proxima/proxima_openxr.h>

#include "runtime/handoff.h"

#include <atomic>
#include <cstdint>
#include <thread>

#include <time.h>

namespace prox::xr {

// The OpenXR functions the device calls, resolved through the app's
// xrGetInstanceProcAddr at creation.
struct XrFunctions {
  PFN_xrLocateSpace locateSpace = nullptr;
  PFN_xrApplyHapticFeedback applyHaptic = nullptr;
  PFN_xrStopHapticFeedback stopHaptic = nullptr;
  PFN_xrCreateActionSpace createActionSpace = nullptr;
  PFN_xrDestroySpace destroySpace = nullptr;
  // XR_KHR_convert_timespec_time (its PFN is in openxr_platform.h behind
  // XR_USE_TIMESPEC); null without the extension.
  XrResult(XRAPI_PTR* convertTimespec)(XrInstance, const struct timespec*, XrTime*) = nullptr;
  // Windows: xrConvertWin32PerformanceCounterToTimeKHR (its PFN needs
  // windows.h's LARGE_INTEGER, so it is cast where it is called); null
  // without the extension.
  PFN_xrVoidFunction convertWin32 = nullptr;
};

struct XrSettings {
  proxXrDeviceDef def;
  XrFunctions fn;
  XrSpace poseSpace = XR_NULL_HANDLE;  // the action space the device created
  proxStreamDeviceId stream{};         // where poses go and the wrench comes from
};

class XrDevice {
 public:
  explicit XrDevice(const XrSettings& settings);
  ~XrDevice();  // stops the thread
  XrDevice(const XrDevice&) = delete;
  XrDevice& operator=(const XrDevice&) = delete;

  void start();
  // Joins the thread; a vibration playing is stopped first (when focused).
  void stop();

  void on_session_state(XrSessionState state) { state_.store(state, std::memory_order_release); }
  void on_frame(XrTime predicted, XrDuration period, double clock_now);
  // An XrTime the runtime gave or accepted, about `clock_now` (the game
  // thread: one writer).
  void on_runtime_time(XrTime time, double clock_now);
  proxXrDeviceStats stats() const;
  const XrSettings& settings() const { return settings_; }

 private:
  struct Frame {
    XrTime predicted = 0;
    XrDuration period = 0;
    double clock = 0.0;  // stream clock when the app reported it
  };
  // An XrTime and the stream clock it was "now" at.
  struct Anchor {
    XrTime time = 0;
    double clock = 0.0;
  };
  // The grip located once a frame (PROX_XR_EXTRAPOLATE_FRAME).
  struct Located {
    bool valid = false;
    XrTime time = 0;
    double position[3] = {0, 0, 0};
    double rotation[4] = {1, 0, 0, 0};  // w, x, y, z
    double velocity[3] = {0, 0, 0};
    double angular[3] = {0, 0, 0};
  };

  void run();
  void tick();
  bool now_xr(double clock, XrTime* time);
  bool convert_now(XrTime* time, proxXrTimeSource* source);
  bool locate(XrTime time, Located* out, bool with_velocity);
  void push(const Located& grip, double seconds_ahead, double clock);
  void vibrate(double clock);
  void stop_vibration();
  void fail_result(XrResult r) { last_result_.store(int32_t(r), std::memory_order_relaxed); }

  XrSettings settings_;
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::atomic<XrSessionState> state_;
  runtime::SeqLock<Frame> frame_;           // game -> device thread
  runtime::SeqLock<Anchor> runtime_time_;   // game -> device thread (proxXrDevice_OnRuntimeTime)
  XrTime runtime_time_given_ = 0;           // the game thread's: the newest handed over
  // The device thread's own.
  std::uint64_t frame_seen_ = 0;
  Located frame_grip_;
  Anchor accepted_;  // the newest "now" a locate succeeded at
  bool vibrating_ = false;
  double last_send_ = -1e9;
  // Counters (written by the device thread, read by GetStats).
  std::atomic<std::uint64_t> ticks_{0}, locates_{0}, untracked_{0}, not_focused_{0}, sent_{0}, refused_{0},
      stops_{0}, pushed_{0};
  std::atomic<proxXrTimeSource> time_source_{PROX_XR_TIME_NONE};
  std::atomic<int32_t> last_result_{XR_SUCCESS};
  std::atomic<float> last_amplitude_{0.0f};
};

}  // namespace prox::xr
