// USB HID PID (Physical Interface Device, usage page 0x0F): where a
// force-feedback joystick or wheel base keeps each field the host writes to
// play a constant force, read from its report descriptor. The two firmwares
// Proxima is tested with disagree on encodings (a 16- or 8-bit direction, a
// Device Control bit mask or index, a ±32767 or ±10000 magnitude), so
// nothing here is assumed: every value comes from the descriptor.
#pragma once

#include "common/status.h"
#include "devices/hid_descriptor.h"

#include <cstdint>

namespace prox::devices {

inline constexpr std::uint16_t kPidPage = 0x0F;

// One field of one report: where it is and what it may hold.
struct PidSlot {
  bool present = false;
  std::uint8_t report_id = 0;
  std::uint32_t bit = 0, bits = 0;  // in hidapi's buffer, byte 0 the report id when numbered
  std::int32_t min = 0, max = 0;    // logical range; signed when min < 0
  std::uint32_t report_bytes = 0;   // the whole report's size
};

struct PidLayout {
  // Whether the descriptor has the reports a constant force needs; then
  // `axes` is 1 (a wheel) or 2 (a joystick).
  bool pid = false;
  int axes = 0;

  // Output reports.
  PidSlot effect_block;                 // Set Effect: Effect Block Index
  PidSlot effect_type;                  // Set Effect: Effect Type (a selector)
  std::int32_t constant_force_type = 0;  // ... its value for ET Constant Force
  PidSlot duration, trigger_repeat, sample_period, start_delay, gain, trigger_button;
  PidSlot axis_enable[2], direction_enable, direction[2];
  PidSlot constant_block, magnitude;  // Set Constant Force
  PidSlot operation_block, operation, loop_count;  // Effect Operation
  std::int32_t op_start = 0, op_stop = 0;
  PidSlot control;  // PID Device Control: a bit mask (OpenFFBoard) or an index (Arduino)
  bool control_is_mask = false;
  std::int32_t control_enable = 0, control_disable = 0, control_stop_all = 0, control_reset = 0;
  PidSlot device_gain;
  PidSlot free_block;  // PID Block Free
  // Feature reports.
  PidSlot create_type, create_byte_count;  // Create New Effect (the host sets it)
  PidSlot load_block, load_status, load_ram_available;  // PID Block Load (the host gets it)
  std::int32_t load_success = 0, load_full = 0, load_error = 0;
  PidSlot pool_ram_size, pool_max_effects;  // PID Pool (the host gets it)
  // Input: where the stick is (Generic Desktop X and Y of the first input
  // report that has them; a wheel has X only). Its position is the hand's.
  PidSlot position[2];
};

// The layout of a parsed descriptor. A descriptor without PID reports gives
// `pid` false and Ok; one with PID reports of which a field a constant force
// needs is missing is an error naming it.
Status pid_layout_of(const HidDescriptor& descriptor, PidLayout& out);

}  // namespace prox::devices
