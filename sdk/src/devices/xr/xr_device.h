// The OpenXR device (docs/openxr.md). It ticks at 1 kHz on its own thread:
// locates the app's pose action space (each tick, or once a frame and
// extrapolates), pushes the tool's pose into the streamed device it is
// built on, reads back the wrench the haptic loop rendered and turns it
// into the controller's vibration. The game thread forwards session states
// and frame times through atomics and a seqlock, so neither side waits; the
// haptic loop meets this thread through the streamed device's seqlocks and
// never calls OpenXR.
#pragma once

#include <openxr/openxr.h>

#include "runtime/device.h"
#include "runtime/handoff.h"
#include "runtime/stream_device.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>

#include <time.h>

namespace prox::devices::xr {

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

enum class XrPoseMode : std::int32_t { LocateEachTick = 0, ExtrapolateFrame = 1 };

// Where a tick's "now" came from (the values of proxXrTimeSource).
enum class XrTimeSource : std::int32_t { None = 0, Timespec = 1, Win32PerformanceCounter = 2, Frames = 3, OwnClock = 4 };

struct XrSettings {
  XrInstance instance = XR_NULL_HANDLE;
  XrSession session = XR_NULL_HANDLE;
  XrSpace base_space = XR_NULL_HANDLE;  // the app's world space
  XrAction pose_action = XR_NULL_HANDLE, haptic_action = XR_NULL_HANDLE;  // haptic: none when null
  XrPath subaction_path = XR_NULL_PATH;
  // Unit quaternions, w first.
  runtime::DevicePose tool_in_grip{{0, 0, 0}, {1, 0, 0, 0}}, base_to_world{{0, 0, 0}, {1, 0, 0, 0}};
  XrPoseMode pose_mode = XrPoseMode::LocateEachTick;
  double vibration_rate = 100.0, force_for_full_amplitude = 5.0, pulse_duration = 0.02;  // Hz, N, s
  double tick_rate = 1000.0, max_extrapolation = 0.05;                                  // Hz, s
  XrSessionState session_state = XR_SESSION_STATE_FOCUSED;
  XrFunctions fn;
  XrSpace pose_space = XR_NULL_HANDLE;  // the action space made for it: the device destroys it
};

struct XrStats {
  std::uint64_t ticks = 0, locates = 0, untracked = 0, not_focused = 0, vibrations_sent = 0,
                vibrations_refused = 0, stops_sent = 0, poses_pushed = 0;
  XrTimeSource time_source = XrTimeSource::None;
  std::int32_t last_result = XR_SUCCESS;
  float last_amplitude = 0.0f;
  XrSessionState session_state = XR_SESSION_STATE_UNKNOWN;
};

class XrDevice final : public runtime::HapticDevice {
 public:
  explicit XrDevice(const XrSettings& settings);
  ~XrDevice() override;  // closes
  XrDevice(const XrDevice&) = delete;
  XrDevice& operator=(const XrDevice&) = delete;

  void start();
  // Joins the thread (a vibration playing is stopped first, when focused)
  // and destroys the pose space: no OpenXR call after this. Game thread.
  void close() override;

  // The haptic thread's side: the streamed device's.
  bool read_pose(runtime::DevicePose* pose) override { return stream_.read_pose(pose); }
  void write_wrench(const runtime::DeviceWrench& wrench) override { stream_.write_wrench(wrench); }

  void on_session_state(XrSessionState state) { state_.store(state, std::memory_order_release); }
  void on_frame(XrTime predicted, XrDuration period, double clock_now);
  // An XrTime the runtime gave or accepted, about `clock_now` (the game
  // thread: one writer).
  void on_runtime_time(XrTime time, double clock_now);
  XrStats stats() const;
  const XrSettings& settings() const { return settings_; }
  // The thread that made it: its game-thread calls come from there.
  std::thread::id owner() const { return owner_; }

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
  bool convert_now(XrTime* time, XrTimeSource* source);
  bool locate(XrTime time, Located* out, bool with_velocity);
  void push(const Located& grip, double seconds_ahead, double clock);
  void vibrate(double clock);
  void stop_vibration();
  void fail_result(XrResult r) { last_result_.store(int32_t(r), std::memory_order_relaxed); }

  XrSettings settings_;
  std::thread::id owner_ = std::this_thread::get_id();
  runtime::StreamDevice stream_;  // holds the newest pose the thread pushed
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
  std::atomic<XrTimeSource> time_source_{XrTimeSource::None};
  std::atomic<int32_t> last_result_{XR_SUCCESS};
  std::atomic<float> last_amplitude_{0.0f};
};

}  // namespace prox::devices::xr
