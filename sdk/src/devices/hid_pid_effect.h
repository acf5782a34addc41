// One constant-force effect on a HID PID device, driven from the device's
// own thread (docs/devices.md, "Force-feedback devices"): the host sequence
// of ../shared/devices/pid/PROTOCOL.md (reset, enable actuators, create the
// effect and read its block index from Block Load, set it, start it), then
// at most one output report per USB frame: the renewal of its finite
// duration, its direction when that changes, its magnitude when that
// changes. The duration is finite and renewed, so a host that dies with
// the cable in leaves a force that stops on its own. hid_write may block
// for a USB frame: none of this runs on the haptic thread.
#pragma once

#include "devices/hid_pid.h"
#include "devices/hid_pid_reports.h"

#include <cstdint>
#include <vector>

struct hid_device_;

namespace prox::devices {

// Where the effect is.
enum class PidEffectState {
  None = 0,       // not created (input only: no PID reports, or not opened yet)
  Playing = 1,    // created, started, renewed
  Full = 2,       // Block Load said the device has no free effect block
  Error = 3,      // Block Load said the device could not create it
  NoAnswer = 4,   // Block Load never answered (60 tries), or a feature report failed
  Stopped = 5,    // stopped and freed (closed, or unplugged)
};
const char* pid_effect_state_name(PidEffectState state);

struct PidEffectSettings {
  double max_force = 5.0;           // N (N m for a wheel) at full magnitude
  double sign[2] = {1.0, 1.0};      // per device axis: -1 where the firmware pushes the other way
  double duration = 0.1;            // s: the effect stops on its own this long after its last renewal
  double renew_interval = 0.04;     // s between renewals (Effect Operation Start)
  double report_interval = 1e-3;    // s: one output report per USB frame
};

class PidEffect {
 public:
  PidEffect(const PidLayout& layout, const PidEffectSettings& settings);

  // The host sequence; false when the effect could not be created (the
  // state names why: the device then works as an input-only stick).
  bool start(hid_device_* handle, double now);
  // At most one report: a renewal when due, else the direction when it
  // changed, else the magnitude when it changed. `fx` to the right and `fy`
  // towards the user in newtons (a wheel: `fx` is the torque about its
  // axle, N m), in the device's frame. Returns whether it wrote one.
  bool update(hid_device_* handle, double now, double fx, double fy);
  // Stop, Block Free, Stop All, Disable Actuators (writes that fail are
  // ignored: the device may be gone).
  void stop(hid_device_* handle);
  // The device went away (unplugged): no report can reach it.
  void lost() { state_ = PidEffectState::Stopped, last_magnitude_ = 0.0; }

  PidEffectState state() const { return state_; }
  std::int32_t block_index() const { return index_; }
  std::uint64_t force_updates() const { return force_updates_; }
  std::uint64_t reports_written() const { return written_; }
  std::uint64_t failed_writes() const { return failed_; }
  double last_magnitude() const { return last_magnitude_; }

 private:
  bool write(hid_device_* handle, const std::vector<std::uint8_t>& report, double now);
  bool create(hid_device_* handle);
  std::uint32_t duration_ms() const;

  PidLayout layout_;
  PidEffectSettings settings_;
  PidEffectState state_ = PidEffectState::None;
  std::int32_t index_ = 0;
  std::uint32_t direction_ = 0;  // centidegrees, as last set
  std::vector<std::uint8_t> last_force_;  // the last Set Constant Force written
  double last_magnitude_ = 0.0, last_write_ = -1e9, last_start_ = -1e9;
  std::uint64_t force_updates_ = 0, written_ = 0, failed_ = 0;
};

}  // namespace prox::devices
