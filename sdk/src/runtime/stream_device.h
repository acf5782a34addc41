// The streamed device (docs/devices.md): an engine, a binding or an XR
// integration pushes timestamped tool poses from one thread of its own at
// its own rate (a frame's 60-120 Hz); the haptic loop reads the pose at its
// 1 kHz from the latest samples, holding, interpolating or extrapolating, and
// the wrench it renders is read back from any thread. Pusher, haptic loop and
// readers meet through seqlocks: nobody waits, locks or allocates.
#pragma once

#include "runtime/device.h"
#include "runtime/handoff.h"

#include <atomic>
#include <cstdint>

namespace prox::runtime {

enum class StreamMode { Hold = 0, Interpolate = 1, Extrapolate = 2 };

struct StreamSettings {
  StreamMode mode = StreamMode::Interpolate;
  // s: INTERPOLATE renders the pose `delay` in the past, between the two
  // samples around it (one 90 Hz frame: there is nearly always a sample on
  // each side).
  double delay = 1.0 / 90.0;
  // s: EXTRAPOLATE predicts at most this far past the newest sample, then holds.
  double max_extrapolation = 0.02;
  // s: with nothing pushed for this long the device has no pose (the safety
  // gate fades the force out).
  double stale_after = 0.05;
  // What the device behind the stream renders stably (none by default).
  DeviceLimits limits;
};

// One timestamped pose, as pushed.
struct StreamSample {
  double time = 0.0;                          // s, on stream_clock()'s clock
  double position[3] = {0.0, 0.0, 0.0};       // world
  double rotation[4] = {1.0, 0.0, 0.0, 0.0};  // unit quaternion w, x, y, z
};

struct StreamStats {
  std::uint64_t pushed = 0;              // samples accepted
  std::uint64_t dropped = 0;             // not newer than the newest: out of order or duplicate
  std::uint64_t refused = 0;             // invalid: non-finite, zero quaternion, bad time
  std::uint64_t reads = 0;               // haptic ticks that asked for a pose
  std::uint64_t stale_ticks = 0;         // ... and got none: nothing pushed yet, or not for stale_after
  std::uint64_t extrapolated_ticks = 0;  // ... rendered past the newest sample (predicted or held)
  double mean_interval = 0.0;            // s, between accepted samples' times
  double max_interval = 0.0;             // s
  double max_extrapolation = 0.0;  // s: the furthest a rendered pose was predicted past the newest sample
  double last_sample_age = 0.0;    // s: the newest sample's age at the last read
};

// Seconds on a steady, monotonic clock (CLOCK_MONOTONIC on Linux): the clock
// push() times are on. Any thread.
double stream_clock();

// The pose of a stream of samples at time `t`, as `settings.mode` renders
// it; `samples` oldest first, `count` >= 1. `*past_newest` is how far past
// the newest sample the pose was predicted or held (0 when within them).
StreamSample stream_pose_at(const StreamSample* samples, int count, double t, const StreamSettings& settings,
                            double* past_newest);

class StreamDevice final : public HapticDevice {
 public:
  static constexpr int kHistory = 16;  // samples kept for interpolation

  explicit StreamDevice(const StreamSettings& settings) : settings_(settings) {}

  // One pushing thread at a time. A valid sample newer than the newest is
  // taken (true); an older or equally old one is dropped and counted
  // (false). The caller validates (finite, non-zero quaternion, time >= 0).
  bool push(const StreamSample& sample);
  // The one-pusher rule: begin_push is false while another push is under
  // way; end_push hands the device (and what was pushed) to the next.
  bool begin_push() { return !pushing_.exchange(true, std::memory_order_acquire); }
  void end_push() { pushing_.store(false, std::memory_order_release); }
  void count_refused() { refused_.fetch_add(1, std::memory_order_relaxed); }

  // The haptic thread's side: the pose at the current time, or false when
  // there is none.
  bool read_pose(DevicePose* pose) override;
  bool read_pose_at(double now, DevicePose* pose);
  void write_wrench(const DeviceWrench& wrench) override;
  DeviceLimits limits() const override { return settings_.limits; }
  // From then on, no pose.
  void close() override { closed_.store(true, std::memory_order_release); }

  // Any thread: the wrench last handed to the device (zero before the first).
  DeviceWrench wrench() const { return wrench_.load(); }
  StreamStats stats() const;
  const StreamSettings& settings() const { return settings_; }

 private:
  struct History {
    StreamSample samples[kHistory];  // a ring; samples[(head + kHistory - 1) % kHistory] is the newest
    std::int32_t head = 0;
    std::int32_t count = 0;
    double arrival = 0.0;  // stream_clock() when the newest was pushed
  };

  StreamSettings settings_;
  SeqLock<History> history_;      // pusher -> haptic
  History own_;                   // pusher's own copy
  SeqLock<DeviceWrench> wrench_;  // haptic -> any
  std::atomic<bool> pushing_{false}, closed_{false};
  // Pusher's counters.
  std::atomic<std::uint64_t> pushed_{0}, dropped_{0}, refused_{0};
  std::atomic<double> interval_sum_{0.0}, max_interval_{0.0};
  // Haptic's counters.
  std::atomic<std::uint64_t> reads_{0}, stale_ticks_{0}, extrapolated_ticks_{0};
  std::atomic<double> max_extrapolation_{0.0}, last_sample_age_{0.0};
};

}  // namespace prox::runtime
