#include "runtime/stream_device.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace prox::runtime {
namespace {

glm::dquat quat(const StreamSample& s) {
  return glm::dquat(s.rotation[0], s.rotation[1], s.rotation[2], s.rotation[3]);
}

void set_quat(StreamSample& s, const glm::dquat& q) {
  const glm::dquat n = glm::normalize(q);
  s.rotation[0] = n.w, s.rotation[1] = n.x, s.rotation[2] = n.y, s.rotation[3] = n.z;
}

StreamSample interpolate(const StreamSample& a, const StreamSample& b, double t) {
  const double f = (t - a.time) / (b.time - a.time);  // b.time > a.time: push() keeps them increasing
  StreamSample s;
  s.time = t;
  for (int k = 0; k < 3; ++k) s.position[k] = a.position[k] + (b.position[k] - a.position[k]) * f;
  set_quat(s, glm::slerp(quat(a), quat(b), f));  // glm takes the shortest arc
  return s;
}

// `seconds` past b along the motion from a to b: constant linear velocity,
// and constant angular velocity about the world axis of the rotation from a
// to b (both exact when the motion is).
StreamSample extrapolate(const StreamSample& a, const StreamSample& b, double seconds) {
  const double k = seconds / (b.time - a.time);
  StreamSample s;
  s.time = b.time + seconds;
  for (int i = 0; i < 3; ++i) s.position[i] = b.position[i] + (b.position[i] - a.position[i]) * k;
  glm::dquat d = quat(b) * glm::conjugate(quat(a));  // world-frame rotation from a to b
  if (d.w < 0.0) d = -d;                             // the shorter way round
  const glm::dvec3 v(d.x, d.y, d.z);
  const double sin_half = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  glm::dquat step(1.0, 0.0, 0.0, 0.0);
  if (sin_half > 0.0) {
    const double half = std::atan2(sin_half, d.w) * k;
    const glm::dvec3 axis = v / sin_half;
    step = glm::dquat(std::cos(half), axis * std::sin(half));
  }
  set_quat(s, step * quat(b));
  return s;
}

void raise(std::atomic<double>& max, double v) {
  if (v > max.load(std::memory_order_relaxed)) max.store(v, std::memory_order_relaxed);
}

}  // namespace

double stream_clock() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

StreamSample stream_pose_at(const StreamSample* samples, int count, double t, const StreamSettings& settings,
                            double* past_newest) {
  *past_newest = 0.0;
  const StreamSample& newest = samples[count - 1];
  if (settings.mode == StreamMode::Hold) return newest;
  const double q = settings.mode == StreamMode::Interpolate ? t - settings.delay : t;
  if (q >= newest.time) {
    *past_newest = q - newest.time;
    if (settings.mode == StreamMode::Interpolate || count < 2) return newest;
    return extrapolate(samples[count - 2], newest, std::min(*past_newest, settings.max_extrapolation));
  }
  if (q <= samples[0].time) return samples[0];
  int i = count - 2;
  while (i > 0 && samples[i].time > q) --i;
  return interpolate(samples[i], samples[i + 1], q);
}

bool StreamDevice::push(const StreamSample& sample) {
  const int newest = (own_.head + kHistory - 1) % kHistory;
  if (own_.count > 0 && !(sample.time > own_.samples[newest].time)) {
    dropped_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  if (own_.count > 0) {
    const double interval = sample.time - own_.samples[newest].time;
    interval_sum_.store(interval_sum_.load(std::memory_order_relaxed) + interval, std::memory_order_relaxed);
    raise(max_interval_, interval);
  }
  own_.samples[own_.head] = sample;
  own_.head = (own_.head + 1) % kHistory;
  own_.count = std::min(own_.count + 1, kHistory);
  own_.arrival = stream_clock();
  history_.store(own_);
  pushed_.fetch_add(1, std::memory_order_relaxed);
  return true;
}

bool StreamDevice::read_pose(DevicePose* pose) { return read_pose_at(stream_clock(), pose); }

bool StreamDevice::read_pose_at(double now, DevicePose* pose) {
  reads_.fetch_add(1, std::memory_order_relaxed);
  const History h = history_.load();
  if (h.count == 0 || now - h.arrival > settings_.stale_after || closed_.load(std::memory_order_acquire)) {
    stale_ticks_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  StreamSample ordered[kHistory];
  const int first = (h.head + kHistory - h.count) % kHistory;
  for (int i = 0; i < h.count; ++i) ordered[i] = h.samples[(first + i) % kHistory];
  double past = 0.0;
  const StreamSample s = stream_pose_at(ordered, h.count, now, settings_, &past);
  if (past > 0.0) {
    extrapolated_ticks_.fetch_add(1, std::memory_order_relaxed);
    if (settings_.mode == StreamMode::Extrapolate && h.count >= 2)
      raise(max_extrapolation_, std::min(past, settings_.max_extrapolation));
  }
  last_sample_age_.store(now - ordered[h.count - 1].time, std::memory_order_relaxed);
  for (int k = 0; k < 3; ++k) pose->position[k] = s.position[k];
  for (int k = 0; k < 4; ++k) pose->rotation[k] = s.rotation[k];
  return true;
}

void StreamDevice::write_wrench(const DeviceWrench& wrench) { wrench_.store(wrench); }

StreamStats StreamDevice::stats() const {
  StreamStats s;
  s.pushed = pushed_.load(std::memory_order_relaxed);
  s.dropped = dropped_.load(std::memory_order_relaxed);
  s.refused = refused_.load(std::memory_order_relaxed);
  s.reads = reads_.load(std::memory_order_relaxed);
  s.stale_ticks = stale_ticks_.load(std::memory_order_relaxed);
  s.extrapolated_ticks = extrapolated_ticks_.load(std::memory_order_relaxed);
  s.mean_interval = s.pushed > 1 ? interval_sum_.load(std::memory_order_relaxed) / double(s.pushed - 1) : 0.0;
  s.max_interval = max_interval_.load(std::memory_order_relaxed);
  s.max_extrapolation = max_extrapolation_.load(std::memory_order_relaxed);
  s.last_sample_age = last_sample_age_.load(std::memory_order_relaxed);
  return s;
}

}  // namespace prox::runtime
