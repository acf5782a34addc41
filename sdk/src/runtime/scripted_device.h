// The built-in device: a tool moved along a scripted path of poses, for
// tests, the CLI and the samples, and a record of what the haptic loop
// handed it. Its callbacks run on the haptic thread and neither lock nor
// allocate; its record can be read from any thread.
#pragma once

#include "contact/pose.h"
#include "runtime/device.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace prox::runtime {

struct ScriptedPose {
  Vec3 position{0.0};
  double rotation[4] = {1.0, 0.0, 0.0, 0.0};  // unit quaternion w, x, y, z

  static ScriptedPose of(const Pose& pose);
};

// What the device has been handed so far.
struct ScriptedRecord {
  std::uint64_t reads = 0, writes = 0;
  double progress = 0.0;        // poses into the path (fractional); the path's length when done
  double max_force = 0.0;       // largest |force| written, N
  double max_torque = 0.0;      // largest |torque| written, N m
  double max_force_step = 0.0;  // largest |force change| between consecutive writes, N
  bool finite = true;           // every value written was finite
  Vec3 last_force{0.0}, last_torque{0.0};
};

class ScriptedDevice final : public HapticDevice {
 public:
  // `poses`: at least one; the device moves through them at
  // `seconds_per_pose` (> 0), interpolating (linearly, and along the
  // shortest arc for rotations), from its first read on; it then holds the
  // last pose, or starts over when `loop`.
  ScriptedDevice(std::vector<ScriptedPose> poses, double seconds_per_pose, bool loop);

  bool read_pose(DevicePose* pose) override;
  void write_wrench(const DeviceWrench& wrench) override;
  // From then on, no pose.
  void close() override { closed_.store(true, std::memory_order_release); }
  ScriptedRecord record() const;
  // The pose at `t` seconds into the path.
  ScriptedPose pose_at(double t) const;

 private:
  std::vector<ScriptedPose> poses_;
  double seconds_per_pose_;
  bool loop_;
  // Written by the haptic thread only; atomics so any thread may read them.
  std::atomic<std::int64_t> start_ns_{-1};
  std::atomic<std::uint64_t> reads_{0}, writes_{0};
  std::atomic<double> progress_{0.0}, max_force_{0.0}, max_torque_{0.0}, max_force_step_{0.0};
  std::atomic<bool> finite_{true}, closed_{false};
  std::atomic<double> last_[6] = {};
};

}  // namespace prox::runtime
