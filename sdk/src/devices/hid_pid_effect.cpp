#include "devices/hid_pid_effect.h"

#include <hidapi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace prox::devices {
namespace {

// Block Load polls before the device is taken for one that never answers
// (hid-pidff's count).
constexpr int kBlockLoadTries = 60;

// A direction change this large (centidegrees) passes through zero force:
// the old magnitude must not push the new way for a frame.
constexpr std::uint32_t kTurnThroughZero = 9000;

std::uint32_t angle_between(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t d = a > b ? a - b : b - a;
  return std::min(d, 36000u - d);
}

}  // namespace

const char* pid_effect_state_name(PidEffectState state) {
  switch (state) {
    case PidEffectState::None:
      return "none";
    case PidEffectState::Playing:
      return "playing";
    case PidEffectState::Full:
      return "full";
    case PidEffectState::Error:
      return "error";
    case PidEffectState::NoAnswer:
      return "no answer";
    case PidEffectState::Stopped:
      return "stopped";
  }
  return "unknown";
}

PidEffect::PidEffect(const PidLayout& layout, const PidEffectSettings& settings)
    : layout_(layout), settings_(settings) {}

std::uint32_t PidEffect::duration_ms() const {
  return static_cast<std::uint32_t>(std::lround(std::clamp(settings_.duration, 1e-3, 30.0) * 1000.0));
}

bool PidEffect::write(hid_device_* handle, const std::vector<std::uint8_t>& report, double now) {
  last_write_ = now;
  if (hid_write(handle, report.data(), report.size()) == static_cast<int>(report.size())) {
    ++written_;
    return true;
  }
  ++failed_;
  return false;
}

bool PidEffect::create(hid_device_* handle) {
  const std::vector<std::uint8_t> create = pid_create_constant_force(layout_);
  if (hid_send_feature_report(handle, create.data(), create.size()) < 0) {
    state_ = PidEffectState::NoAnswer;
    return false;
  }
  const std::vector<std::uint8_t> request = pid_block_load_request(layout_);
  for (int tries = 0; tries < kBlockLoadTries; ++tries) {
    std::vector<std::uint8_t> buf(std::max<std::size_t>(request.size(), 64), 0);
    std::copy(request.begin(), request.end(), buf.begin());
    const int n = hid_get_feature_report(handle, buf.data(), buf.size());
    if (n > 0) {
      const PidBlockLoad load = pid_parse_block_load(layout_, buf.data(), static_cast<std::size_t>(n));
      if (load.status == PidLoadStatus::Success) {
        index_ = load.index;
        return true;
      }
      if (load.status == PidLoadStatus::Full || load.status == PidLoadStatus::Error) {
        state_ = load.status == PidLoadStatus::Full ? PidEffectState::Full : PidEffectState::Error;
        return false;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));  // the device's thread: it may wait
  }
  state_ = PidEffectState::NoAnswer;
  return false;
}

bool PidEffect::start(hid_device_* handle, double now) {
  index_ = 0;
  direction_ = 0;
  last_force_.clear();
  last_magnitude_ = 0.0;
  // Reset twice (hid-pidff's "sometimes one is not enough"), stop all,
  // enable the actuators, full device gain.
  write(handle, pid_device_control(layout_, PidControl::Reset), now);
  write(handle, pid_device_control(layout_, PidControl::Reset), now);
  write(handle, pid_device_control(layout_, PidControl::StopAllEffects), now);
  write(handle, pid_device_control(layout_, PidControl::EnableActuators), now);
  if (layout_.device_gain.present) write(handle, pid_device_gain(layout_, 1.0), now);
  if (!create(handle)) return false;
  const std::uint32_t east = layout_.axes == 1 ? 9000u : 0u;
  direction_ = east;
  write(handle, pid_set_constant_effect(layout_, index_, duration_ms(), direction_), now);
  last_force_ = pid_set_constant_force(layout_, index_, 0.0);
  write(handle, last_force_, now);
  write(handle, pid_effect_start(layout_, index_, 1), now);
  last_start_ = now;
  state_ = PidEffectState::Playing;
  return true;
}

bool PidEffect::update(hid_device_* handle, double now, double fx, double fy) {
  if (state_ != PidEffectState::Playing || now - last_write_ < settings_.report_interval) return false;
  if (now - last_start_ >= settings_.renew_interval) {
    last_start_ = now;
    return write(handle, pid_effect_start(layout_, index_, 1), now);
  }
  const PidForce f = pid_force_of(settings_.sign[0] * fx, settings_.sign[1] * fy, settings_.max_force,
                                  layout_.axes, PidForceSign::DirectInput);
  // No force keeps the direction it had: no Set Effect for nothing.
  if (f.magnitude != 0.0 && f.direction_centidegrees != direction_) {
    if (last_magnitude_ != 0.0 && angle_between(f.direction_centidegrees, direction_) >= kTurnThroughZero) {
      last_force_ = pid_set_constant_force(layout_, index_, 0.0);
      last_magnitude_ = 0.0;
      ++force_updates_;
      return write(handle, last_force_, now);
    }
    direction_ = f.direction_centidegrees;
    return write(handle, pid_set_constant_effect(layout_, index_, duration_ms(), direction_), now);
  }
  std::vector<std::uint8_t> force = pid_set_constant_force(layout_, index_, f.magnitude);
  if (force == last_force_) return false;
  last_force_ = std::move(force);
  // What the device was sent, as a fraction: the magnitude as encoded.
  const PidSlot& m = layout_.magnitude;
  const double sent = double(read_hid_bits(last_force_.data(), last_force_.size(), m.bit, m.bits, m.min < 0));
  last_magnitude_ = sent > 0.0 ? sent / double(m.max) : sent < 0.0 && m.min < 0 ? -sent / double(m.min) : 0.0;
  ++force_updates_;
  return write(handle, last_force_, now);
}

void PidEffect::stop(hid_device_* handle) {
  if (state_ == PidEffectState::Playing) {
    const double now = last_write_;
    write(handle, pid_effect_stop(layout_, index_), now);
    if (layout_.free_block.present) write(handle, pid_block_free(layout_, index_), now);
  }
  if (state_ != PidEffectState::None && state_ != PidEffectState::Stopped) {
    write(handle, pid_device_control(layout_, PidControl::StopAllEffects), last_write_);
    if (layout_.control_disable != 0)
      write(handle, pid_device_control(layout_, PidControl::DisableActuators), last_write_);
  }
  state_ = PidEffectState::Stopped;
  last_magnitude_ = 0.0;
}

}  // namespace prox::devices
