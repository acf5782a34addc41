// The reports a host writes to a HID PID device to play one constant force
// (the sequence Linux's hid-pidff runs, ../shared/devices/pid/PROTOCOL.md),
// encoded into the device's own layout (hid_pid.h). Pure functions on byte
// buffers, for the device thread that sends them: nothing here blocks.
#pragma once

#include "devices/hid_pid.h"

#include <cstdint>
#include <vector>

namespace prox::devices {

// How a firmware turns a constant force's direction into a push. DirectInput
// (and OpenFFBoard): a magnitude M at direction theta pushes the grip along
// (-sin theta, cos theta), x to the right and y towards the user. The
// Arduino library computes the opposite sign (../shared/devices/pid/
// PROTOCOL.md, section 7). Which one a device follows is the device's
// calibration, not its descriptor's.
enum class PidForceSign { DirectInput = 1, Opposite = -1 };

// One constant force as a PID device takes it.
struct PidForce {
  std::uint32_t direction_centidegrees = 0;  // [0, 36000), clockwise from north (away from the user)
  double magnitude = 0.0;                    // [-1, 1] of the device's full scale
};

// The force to play for a push (fx to the right, fy towards the user, in
// newtons, in the device's frame: what is left of the tool's force once its
// component along the shaft is dropped) on a device whose full scale is
// `max_force` newtons. Two axes: the push's direction and its size, clipped
// to full scale. One axis (a wheel, whose only axis is X): direction fixed
// at east, the magnitude signed, fy ignored. A zero or non-finite push is no
// force (direction 0).
PidForce pid_force_of(double fx, double fy, double max_force, int axes, PidForceSign sign);

enum class PidControl { EnableActuators, DisableActuators, StopAllEffects, Reset };

enum class PidLoadStatus { Pending, Success, Full, Error };

struct PidBlockLoad {
  PidLoadStatus status = PidLoadStatus::Pending;
  std::int32_t index = 0;  // the new effect's block index, on success
};

// Each report is sized as the descriptor says, byte 0 its id.
// PID Device Control: a command, as a bit mask or an index as the device declares.
std::vector<std::uint8_t> pid_device_control(const PidLayout& p, PidControl command);
// Device Gain, `gain` in [0, 1] of the field's range.
std::vector<std::uint8_t> pid_device_gain(const PidLayout& p, double gain);
// Create New Effect (a feature report the host sets): a constant force.
std::vector<std::uint8_t> pid_create_constant_force(const PidLayout& p);
// The buffer to get PID Block Load with (its id in byte 0), and its answer.
std::vector<std::uint8_t> pid_block_load_request(const PidLayout& p);
PidBlockLoad pid_parse_block_load(const PidLayout& p, const std::uint8_t* report, std::size_t size);

// Set Effect for a constant force: its block index, a duration in ms
// (clamped to the field; never the field's "infinite"), full gain, and a
// direction in hundredths of a degree, clockwise from north (away from the
// user), where the force comes from, as DirectInput and the descriptors
// have it (only instance 1 is used; a one-axis device has no other).
std::vector<std::uint8_t> pid_set_constant_effect(const PidLayout& p, std::int32_t index, std::uint32_t duration_ms,
                                                  std::uint32_t direction_centidegrees);
// Set Constant Force: `magnitude` in [-1, 1] of the device's full scale
// (clamped; each sign rounds onto its own end of the range, as hid-pidff
// rescales).
std::vector<std::uint8_t> pid_set_constant_force(const PidLayout& p, std::int32_t index, double magnitude);
// Effect Operation: start (played `loops` times) or stop.
std::vector<std::uint8_t> pid_effect_start(const PidLayout& p, std::int32_t index, std::int32_t loops);
std::vector<std::uint8_t> pid_effect_stop(const PidLayout& p, std::int32_t index);
// PID Block Free.
std::vector<std::uint8_t> pid_block_free(const PidLayout& p, std::int32_t index);

}  // namespace prox::devices
