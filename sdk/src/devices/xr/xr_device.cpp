#include "devices/xr/xr_device.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#if defined(_WIN32)
#ifndef NOMINMAX
#define NOMINMAX  // std::min and std::clamp stay usable
#endif
#include <windows.h>
#endif

namespace prox::devices::xr {
namespace {

glm::dquat quat(const runtime::DevicePose& p) { return glm::dquat(p.rotation[0], p.rotation[1], p.rotation[2], p.rotation[3]); }
glm::dvec3 vec(const runtime::DevicePose& p) { return {p.position[0], p.position[1], p.position[2]}; }

// The streamed device's settings: the newest pose held, stale after 20
// ticks (at least 50 ms).
runtime::StreamSettings stream_settings(const XrSettings& s) {
  runtime::StreamSettings out;
  out.mode = runtime::StreamMode::Hold;
  out.stale_after = std::max(0.05, 20.0 / s.tick_rate);
  return out;
}

XrTime ns(double seconds) { return XrTime(std::llround(seconds * 1e9)); }

bool finite(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

}  // namespace

XrDevice::XrDevice(const XrSettings& settings)
    : settings_(settings), stream_(stream_settings(settings)), state_(settings.session_state) {}

XrDevice::~XrDevice() { close(); }

void XrDevice::start() {
  running_.store(true);
  thread_ = std::thread([this] { run(); });
}

void XrDevice::close() {
  stream_.close();
  if (thread_.joinable()) {
    running_.store(false);
    thread_.join();
  }
  if (settings_.pose_space != XR_NULL_HANDLE) {
    settings_.fn.destroySpace(settings_.pose_space);
    settings_.pose_space = XR_NULL_HANDLE;
  }
}

void XrDevice::on_frame(XrTime predicted, XrDuration period, double clock_now) {
  frame_.store({predicted, period, clock_now});
}

void XrDevice::run() {
  using clock = std::chrono::steady_clock;
  const auto period = std::chrono::duration_cast<clock::duration>(
      std::chrono::duration<double>(1.0 / settings_.tick_rate));
  auto next = clock::now();
  while (running_.load(std::memory_order_acquire)) {
    tick();
    next += period;
    const auto now = clock::now();
    if (next < now) next = now;  // late: no burst of catch-up ticks
    std::this_thread::sleep_until(next);
  }
  if (vibrating_ && state_.load() == XR_SESSION_STATE_FOCUSED) stop_vibration();
}

void XrDevice::on_runtime_time(XrTime time, double clock_now) {
  if (time <= runtime_time_given_) return;  // the newest only: times never run back
  runtime_time_given_ = time;
  runtime_time_.store({time, clock_now});
}

// "Now" from the app's time conversion extension; false without one, or
// when the runtime refuses the conversion (recorded in lastXrResult).
bool XrDevice::convert_now(XrTime* time, XrTimeSource* source) {
  XrResult r = XR_ERROR_FUNCTION_UNSUPPORTED;
#if defined(_WIN32)
  if (!settings_.fn.convertWin32) return false;
  using Convert = XrResult(XRAPI_PTR*)(XrInstance, const LARGE_INTEGER*, XrTime*);
  LARGE_INTEGER counter;
  QueryPerformanceCounter(&counter);
  r = reinterpret_cast<Convert>(settings_.fn.convertWin32)(settings_.instance, &counter, time);
  *source = XrTimeSource::Win32PerformanceCounter;
#else
  if (!settings_.fn.convertTimespec) return false;
  timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  r = settings_.fn.convertTimespec(settings_.instance, &ts, time);
  *source = XrTimeSource::Timespec;
#endif
  if (XR_SUCCEEDED(r) && *time > 0) return true;
  if (XR_FAILED(r)) fail_result(r);
  return false;
}

// "Now" as an XrTime, from the first source that has one: the app's time
// conversion extension; the last predicted display time the app reported,
// advanced by the monotonic clock; else the device's own monotonic clock
// from the newest time the runtime accepted (a locate of its own that
// succeeded, or a time the app handed over). A runtime that has no time
// to give, or stops giving it, costs no pose once it accepted one.
bool XrDevice::now_xr(double clock, XrTime* time) {
  XrTimeSource source = XrTimeSource::None;
  *time = 0;
  if (!convert_now(time, &source)) {
    source = XrTimeSource::None;
    const Frame f = frame_.load();
    const Anchor given = runtime_time_.load();
    const Anchor& own = given.clock > accepted_.clock ? given : accepted_;  // the newer news
    if (f.predicted > 0) {
      *time = f.predicted + ns(clock - f.clock);
      source = XrTimeSource::Frames;
    } else if (own.time > 0) {
      *time = own.time + ns(clock - own.clock);
      source = XrTimeSource::OwnClock;
    }
  }
  time_source_.store(source, std::memory_order_relaxed);
  return source != XrTimeSource::None && *time > 0;
}

bool XrDevice::locate(XrTime time, Located* out, bool with_velocity) {
  XrSpaceVelocity velocity{};
  velocity.type = XR_TYPE_SPACE_VELOCITY;
  XrSpaceLocation location{};
  location.type = XR_TYPE_SPACE_LOCATION;
  if (with_velocity) location.next = &velocity;
  locates_.fetch_add(1, std::memory_order_relaxed);
  const XrResult r = settings_.fn.locateSpace(settings_.pose_space, settings_.base_space, time, &location);
  out->valid = false;
  if (XR_FAILED(r)) {
    fail_result(r);
    return false;
  }
  const XrSpaceLocationFlags need =
      XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT;
  if ((location.locationFlags & need) != need) return false;
  const XrPosef& p = location.pose;
  out->time = time;
  out->position[0] = p.position.x, out->position[1] = p.position.y, out->position[2] = p.position.z;
  out->rotation[0] = p.orientation.w, out->rotation[1] = p.orientation.x, out->rotation[2] = p.orientation.y,
  out->rotation[3] = p.orientation.z;
  for (int k = 0; k < 3; ++k) out->velocity[k] = out->angular[k] = 0.0;
  if (with_velocity && (velocity.velocityFlags & XR_SPACE_VELOCITY_LINEAR_VALID_BIT)) {
    out->velocity[0] = velocity.linearVelocity.x, out->velocity[1] = velocity.linearVelocity.y,
    out->velocity[2] = velocity.linearVelocity.z;
  }
  if (with_velocity && (velocity.velocityFlags & XR_SPACE_VELOCITY_ANGULAR_VALID_BIT)) {
    out->angular[0] = velocity.angularVelocity.x, out->angular[1] = velocity.angularVelocity.y,
    out->angular[2] = velocity.angularVelocity.z;
  }
  // A runtime's bad numbers never reach the haptic loop.
  out->valid = finite(out->position, 3) && finite(out->rotation, 4) && finite(out->velocity, 3) &&
               finite(out->angular, 3);
  return out->valid;
}

// The tool's pose in Proxima's world: baseToWorld * grip(now) * toolInGrip,
// the grip moved `ahead` seconds along its velocity (0 when located now).
void XrDevice::push(const Located& grip, double ahead, double clock) {
  glm::dvec3 position(grip.position[0], grip.position[1], grip.position[2]);
  glm::dquat rotation(grip.rotation[0], grip.rotation[1], grip.rotation[2], grip.rotation[3]);
  if (ahead != 0.0) {
    position += glm::dvec3(grip.velocity[0], grip.velocity[1], grip.velocity[2]) * ahead;
    const glm::dvec3 w(grip.angular[0], grip.angular[1], grip.angular[2]);
    const double speed = glm::length(w);
    if (speed > 0.0) rotation = glm::angleAxis(speed * ahead, w / speed) * rotation;  // omega is in base axes
  }
  const double norm = glm::length(rotation);
  if (!(norm > 1e-6)) return;
  rotation /= norm;
  const XrSettings& d = settings_;
  const glm::dquat base_q = quat(d.base_to_world), tool_q = quat(d.tool_in_grip);
  const glm::dvec3 in_base = position + rotation * vec(d.tool_in_grip);
  const glm::dvec3 world = vec(d.base_to_world) + base_q * in_base;
  const glm::dquat q = glm::normalize(base_q * rotation * tool_q);
  const runtime::StreamSample sample{clock, {world.x, world.y, world.z}, {q.w, q.x, q.y, q.z}};
  if (!finite(sample.position, 3) || !finite(sample.rotation, 4)) return;
  if (stream_.push(sample)) pushed_.fetch_add(1, std::memory_order_relaxed);
}

void XrDevice::stop_vibration() {
  vibrating_ = false;
  if (settings_.haptic_action == XR_NULL_HANDLE) return;
  XrHapticActionInfo info{};
  info.type = XR_TYPE_HAPTIC_ACTION_INFO;
  info.action = settings_.haptic_action;
  info.subactionPath = settings_.subaction_path;
  const XrResult r = settings_.fn.stopHaptic(settings_.session, &info);
  stops_.fetch_add(1, std::memory_order_relaxed);
  if (XR_FAILED(r) || r == XR_SESSION_NOT_FOCUSED) fail_result(r);
}

// The rendered force as vibration: a pulse longer than the send interval at
// most vibrationRate times a second, so one replaces the last before it
// ends; stopped as soon as the force is gone.
void XrDevice::vibrate(double clock) {
  const XrSettings& d = settings_;
  if (d.haptic_action == XR_NULL_HANDLE) return;
  const runtime::DeviceWrench w = stream_.wrench();
  double force = std::sqrt(w.force[0] * w.force[0] + w.force[1] * w.force[1] + w.force[2] * w.force[2]);
  if (!std::isfinite(force)) force = 0.0;
  const double amplitude = std::min(1.0, force / d.force_for_full_amplitude);
  if (amplitude < 1e-3) {
    if (vibrating_) stop_vibration();
    return;
  }
  if (clock - last_send_ < 1.0 / d.vibration_rate) return;
  last_send_ = clock;
  XrHapticActionInfo info{};
  info.type = XR_TYPE_HAPTIC_ACTION_INFO;
  info.action = d.haptic_action;
  info.subactionPath = d.subaction_path;
  XrHapticVibration v{};
  v.type = XR_TYPE_HAPTIC_VIBRATION;
  v.amplitude = float(amplitude);
  v.duration = XrDuration(std::llround(d.pulse_duration * 1e9));
  v.frequency = XR_FREQUENCY_UNSPECIFIED;
  const XrResult r =
      settings_.fn.applyHaptic(d.session, &info, reinterpret_cast<const XrHapticBaseHeader*>(&v));
  if (r == XR_SUCCESS) {
    sent_.fetch_add(1, std::memory_order_relaxed);
    last_amplitude_.store(v.amplitude, std::memory_order_relaxed);
    vibrating_ = true;
  } else {
    refused_.fetch_add(1, std::memory_order_relaxed);
    fail_result(r);
  }
}

void XrDevice::tick() {
  ticks_.fetch_add(1, std::memory_order_relaxed);
  const XrSessionState state = state_.load(std::memory_order_acquire);
  if (state != XR_SESSION_STATE_FOCUSED) {
    // No pose (the stream goes stale and the force fades) and no call, but
    // for one stop of a vibration that plays: not every runtime stops
    // haptics itself when focus goes (stock Monado lets them play).
    not_focused_.fetch_add(1, std::memory_order_relaxed);
    if (vibrating_) stop_vibration();
    frame_grip_.valid = false;
    return;
  }
  const double clock = runtime::stream_clock();
  XrTime now = 0;
  bool tracked = now_xr(clock, &now);
  std::uint64_t version = 0;
  const Frame f = frame_.load(&version);
  if (tracked && settings_.pose_mode == XrPoseMode::ExtrapolateFrame && f.predicted > 0) {
    if (version != frame_seen_) {
      frame_seen_ = version;
      locate(f.predicted, &frame_grip_, true);
    }
    tracked = frame_grip_.valid;
    if (tracked) {
      const double ahead = std::clamp(double(now - frame_grip_.time) * 1e-9, -settings_.max_extrapolation,
                                      settings_.max_extrapolation);
      push(frame_grip_, ahead, clock);
    }
  } else if (tracked) {
    // Each tick; and PROX_XR_EXTRAPOLATE_FRAME while the app reports no
    // frame (a headless runtime whose display times are 0).
    Located grip;
    tracked = locate(now, &grip, false);
    if (tracked) {
      accepted_ = {now, clock};
      push(grip, 0.0, clock);
    }
  }
  if (!tracked) untracked_.fetch_add(1, std::memory_order_relaxed);
  vibrate(clock);
}

XrStats XrDevice::stats() const {
  XrStats s;
  s.ticks = ticks_.load(std::memory_order_relaxed);
  s.locates = locates_.load(std::memory_order_relaxed);
  s.untracked = untracked_.load(std::memory_order_relaxed);
  s.not_focused = not_focused_.load(std::memory_order_relaxed);
  s.vibrations_sent = sent_.load(std::memory_order_relaxed);
  s.vibrations_refused = refused_.load(std::memory_order_relaxed);
  s.stops_sent = stops_.load(std::memory_order_relaxed);
  s.poses_pushed = pushed_.load(std::memory_order_relaxed);
  s.time_source = time_source_.load(std::memory_order_relaxed);
  s.last_result = last_result_.load(std::memory_order_relaxed);
  s.last_amplitude = last_amplitude_.load(std::memory_order_relaxed);
  s.session_state = state_.load(std::memory_order_relaxed);
  return s;
}

}  // namespace prox::devices::xr
