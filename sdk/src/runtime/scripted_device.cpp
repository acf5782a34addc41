#include "runtime/scripted_device.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace prox::runtime {
namespace {

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

glm::dquat quat(const ScriptedPose& p) {
  return glm::normalize(glm::dquat(p.rotation[0], p.rotation[1], p.rotation[2], p.rotation[3]));
}

}  // namespace

ScriptedPose ScriptedPose::of(const Pose& pose) {
  const glm::dquat q = glm::quat_cast(pose.rotation);
  ScriptedPose p;
  p.position = pose.translation;
  p.rotation[0] = q.w, p.rotation[1] = q.x, p.rotation[2] = q.y, p.rotation[3] = q.z;
  return p;
}

ScriptedDevice::ScriptedDevice(std::vector<ScriptedPose> poses, double seconds_per_pose, bool loop)
    : poses_(std::move(poses)), seconds_per_pose_(seconds_per_pose), loop_(loop) {
  if (poses_.empty()) throw std::invalid_argument("a scripted path needs at least one pose");
  if (!(std::isfinite(seconds_per_pose) && seconds_per_pose > 0.0))
    throw std::invalid_argument("seconds per pose must be > 0");
}

ScriptedPose ScriptedDevice::pose_at(double t) const {
  const double last = double(poses_.size() - 1);
  double u = std::max(0.0, t / seconds_per_pose_);
  if (loop_ && poses_.size() > 1) u = std::fmod(u, double(poses_.size()));
  if (u >= last) return poses_.back();
  const auto i = static_cast<std::size_t>(u);
  const double f = u - double(i);
  const ScriptedPose& a = poses_[i];
  // When looping, the stretch from the last pose back to the first.
  const ScriptedPose& b = poses_[i + 1 < poses_.size() ? i + 1 : 0];
  ScriptedPose p;
  p.position = glm::mix(a.position, b.position, f);
  const glm::dquat q = glm::slerp(quat(a), quat(b), f);  // glm takes the shortest arc
  p.rotation[0] = q.w, p.rotation[1] = q.x, p.rotation[2] = q.y, p.rotation[3] = q.z;
  return p;
}

bool ScriptedDevice::read_pose(DevicePose* pose) {
  if (closed_.load(std::memory_order_acquire)) return false;
  const std::int64_t now = now_ns();
  std::int64_t start = start_ns_.load(std::memory_order_relaxed);
  if (start < 0) start_ns_.store(start = now, std::memory_order_relaxed);
  const double t = double(now - start) * 1e-9;
  const ScriptedPose p = pose_at(t);
  for (int k = 0; k < 3; ++k) pose->position[k] = p.position[k];
  for (int k = 0; k < 4; ++k) pose->rotation[k] = p.rotation[k];
  const double progress = t / seconds_per_pose_;
  progress_.store(loop_ ? progress : std::min(progress, double(poses_.size() - 1)),
                  std::memory_order_relaxed);
  reads_.fetch_add(1, std::memory_order_relaxed);
  return true;
}

void ScriptedDevice::write_wrench(const DeviceWrench& w) {
  const Vec3 f(w.force[0], w.force[1], w.force[2]);
  const Vec3 t(w.torque[0], w.torque[1], w.torque[2]);
  const bool finite = std::isfinite(f.x + f.y + f.z + t.x + t.y + t.z);
  if (!finite) finite_.store(false, std::memory_order_relaxed);
  const Vec3 previous(last_[0].load(std::memory_order_relaxed), last_[1].load(std::memory_order_relaxed),
                      last_[2].load(std::memory_order_relaxed));
  auto raise = [](std::atomic<double>& max, double v) {
    if (!(v <= max.load(std::memory_order_relaxed))) max.store(v, std::memory_order_relaxed);
  };
  raise(max_force_, glm::length(f));
  raise(max_torque_, glm::length(t));
  if (writes_.load(std::memory_order_relaxed) > 0) raise(max_force_step_, glm::length(f - previous));
  for (int k = 0; k < 3; ++k) {
    last_[k].store(f[k], std::memory_order_relaxed);
    last_[3 + k].store(t[k], std::memory_order_relaxed);
  }
  writes_.fetch_add(1, std::memory_order_release);
}

ScriptedRecord ScriptedDevice::record() const {
  ScriptedRecord r;
  r.writes = writes_.load(std::memory_order_acquire);
  r.reads = reads_.load(std::memory_order_relaxed);
  r.progress = progress_.load(std::memory_order_relaxed);
  r.max_force = max_force_.load(std::memory_order_relaxed);
  r.max_torque = max_torque_.load(std::memory_order_relaxed);
  r.max_force_step = max_force_step_.load(std::memory_order_relaxed);
  r.finite = finite_.load(std::memory_order_relaxed);
  for (int k = 0; k < 3; ++k) {
    r.last_force[k] = last_[k].load(std::memory_order_relaxed);
    r.last_torque[k] = last_[3 + k].load(std::memory_order_relaxed);
  }
  return r;
}

}  // namespace prox::runtime
