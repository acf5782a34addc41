// The HID devices Proxima knows (docs/devices.md#hid-devices): which ids and
// HID collections are which profile, and how each profile's input reports
// decode. Pure functions on byte buffers: every read is bounds-checked
// against the report's documented size, so a short, long or unknown report
// is refused, never decoded past its end.
#pragma once

#include <cstddef>
#include <cstdint>

namespace prox::devices {

enum class HidProfile {
  None = 0,
  SpaceMouseSplit = 1,
  SpaceMouseCombined = 2,
  DualShock4 = 3,
  DualSense = 4,
  // Grounded force feedback over HID PID (hid_pid.h), recognised from the
  // descriptor: two force axes, or one.
  PidJoystick = 5,
  PidWheel = 6
};

inline bool is_pid(HidProfile p) { return p == HidProfile::PidJoystick || p == HidProfile::PidWheel; }

struct KnownHidDevice {
  std::uint16_t vendor_id, product_id;
  HidProfile profile;
  const char* name;
};

// The table of known ids; `count` receives its length.
const KnownHidDevice* known_hid_devices(std::size_t* count);

// The profile of a device hidapi enumerated, or None: known ids on the right
// collection (usage page 1, usage 8 for the pucks, 5 for the gamepads) and,
// for the Sony pads, USB interface 3 (or -1 when not on USB).
HidProfile hid_profile_of(std::uint16_t vendor_id, std::uint16_t product_id, std::uint16_t usage_page,
                          std::uint16_t usage, int interface_number);
const char* hid_profile_name(HidProfile profile);

// The six motion axes in the device's frame (x right, y up, z towards the
// user; rotations about those axes, right-handed), each in [-1, 1], and the
// buttons that matter.
struct HidAxes {
  double axis[6] = {0, 0, 0, 0, 0, 0};  // tx, ty, tz, rx, ry, rz
  bool recentre = false;                // the re-centre button is held
};

// Everything a report says, for the decoding tests and the mapping.
struct HidInput {
  // Raw fields as the layouts name them.
  std::int16_t puck[6] = {0, 0, 0, 0, 0, 0};     // SpaceMouse X, Y, Z, Rx, Ry, Rz (-350..350)
  std::uint32_t buttons = 0;                     // SpaceMouse: bit0 button 1, bit1 button 2
  std::uint8_t stick[4] = {128, 128, 128, 128};  // pads: left X, Y, right X, Y
  std::uint8_t trigger[2] = {0, 0};              // pads: L2, R2 analog
  std::uint8_t hat = 8;                          // pads: 0 = N .. 7 = NW, 8 released
  // Pads: bit0 square, 1 cross, 2 circle, 3 triangle, 4 L1, 5 R1, 6 L2, 7 R2,
  // 8 share/create, 9 options, 10 L3, 11 R3, 12 PS, 13 touchpad click.
  std::uint32_t pad_buttons = 0;
  std::int16_t gyro_raw[3] = {0, 0, 0}, accel_raw[3] = {0, 0, 0};
  double gyro[3] = {0, 0, 0};   // deg/s, calibrated
  double accel[3] = {0, 0, 0};  // g, calibrated
  int battery = -1;             // percent, when the report says
};

// Gyro and accelerometer calibration from the pads' feature report
// (DualShock 4: 0x02, 37 bytes; DualSense: 0x05, 41 bytes; USB word order),
// with the kernel driver's formulas. Axes whose range is zero keep the
// uncalibrated default scale.
struct MotionCalibration {
  double gyro_bias[3] = {0, 0, 0};
  double gyro_scale[3] = {2000.0 / 32767.0, 2000.0 / 32767.0, 2000.0 / 32767.0};  // deg/s per count
  double accel_bias[3] = {0, 0, 0};
  double accel_scale[3] = {4.0 / 32767.0, 4.0 / 32767.0, 4.0 / 32767.0};  // g per count
  bool valid = false;
};

// The calibration feature report's id and size for a profile (0 when none).
std::uint8_t calibration_report_id(HidProfile profile);
std::size_t calibration_report_size(HidProfile profile);
// Parses it; false (and `out` untouched) when `size` or the id is wrong.
bool parse_calibration(HidProfile profile, const std::uint8_t* data, std::size_t size,
                       MotionCalibration& out);

enum class DecodeResult { Decoded, Ignored, Malformed };

// Decodes one input report (byte 0 = report id) into `state`, which keeps
// what earlier reports said (the split SpaceMouse sends translation and
// rotation apart). Ignored: a known report that carries no motion (a
// battery level). Malformed: an unknown id, or a size other than the
// layout's; `state` is then untouched.
DecodeResult decode_hid_report(HidProfile profile, const std::uint8_t* data, std::size_t size,
                               const MotionCalibration& calibration, HidInput& state);

// The motion axes a decoded state gives (docs/devices.md: the per-profile mapping).
HidAxes hid_axes(HidProfile profile, const HidInput& state);

}  // namespace prox::devices
