// Decoding every profile's reports, the calibration, the dead zone and
// response curve, the rate integration and the output reports, against
// values worked out by hand from the layouts in the shared devices folder
// (spacemouse.md, ds4v2.md, dualsense.md): byte offsets, sizes, scaling.
#include "devices/hid_motion.h"
#include "devices/hid_output.h"
#include "devices/hid_profiles.h"

#include <gtest/gtest.h>

#include <array>
#include <limits>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <vector>

using namespace prox::devices;

namespace {

using Bytes = std::vector<std::uint8_t>;

DecodeResult decode(HidProfile p, const Bytes& b, HidInput& s, const MotionCalibration& c = {}) {
  return decode_hid_report(p, b.data(), b.size(), c, s);
}

Bytes pad_report(std::size_t size = 64) {
  Bytes b(size, 0);
  b[0] = 0x01;
  return b;
}

// The calibration feature report: 17 little-endian words from byte 1.
Bytes calibration_report(std::uint8_t id, std::size_t size) {
  Bytes b(size, 0);
  b[0] = id;
  const int words[] = {4,   -3,  2,    8000,  -8000, 8100,  -8100, 7900, -7900,
                       540, 540, 8200, -8100, 8300,  -8000, 8150,  -8250};
  for (int i = 0; i < 17; ++i) {
    b[std::size_t(1 + 2 * i)] = std::uint8_t(words[i] & 0xff);
    b[std::size_t(2 + 2 * i)] = std::uint8_t((words[i] >> 8) & 0xff);
  }
  return b;
}

}  // namespace

TEST(HidProfiles, TableAndCollections) {
  EXPECT_EQ(hid_profile_of(0x046d, 0xc626, 0x01, 0x08, 0), HidProfile::SpaceMouseSplit);
  // The SpaceNavigator's two vendor collections are not its motion.
  EXPECT_EQ(hid_profile_of(0x046d, 0xc626, 0xff00, 0x01, 0), HidProfile::None);
  EXPECT_EQ(hid_profile_of(0x046d, 0xc626, 0xff00, 0x3a, 0), HidProfile::None);
  EXPECT_EQ(hid_profile_of(0x256f, 0xc62e, 0x01, 0x08, 0), HidProfile::SpaceMouseCombined);
  EXPECT_EQ(hid_profile_of(0x054c, 0x05c4, 0x01, 0x05, 3), HidProfile::DualShock4);
  EXPECT_EQ(hid_profile_of(0x054c, 0x09cc, 0x01, 0x05, 3), HidProfile::DualShock4);
  EXPECT_EQ(hid_profile_of(0x054c, 0x09cc, 0x01, 0x05, 0), HidProfile::None);  // an audio interface
  EXPECT_EQ(hid_profile_of(0x054c, 0x0ce6, 0x01, 0x05, 3), HidProfile::DualSense);
  EXPECT_EQ(hid_profile_of(0x054c, 0x0ce6, 0x01, 0x05, -1),
            HidProfile::DualSense);                                            // Bluetooth: no interface
  EXPECT_EQ(hid_profile_of(0x045e, 0x028e, 0x01, 0x05, 0), HidProfile::None);  // not ours
  std::size_t n = 0;
  const KnownHidDevice* k = known_hid_devices(&n);
  ASSERT_GE(n, 4u);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NE(k[i].profile, HidProfile::None) << k[i].name;
}

TEST(HidDecode, SpaceNavigatorSplitReports) {
  HidInput s;
  // X = 0x012c = 300, Y = 0xff9c = -100, Z = 0x015e = 350.
  EXPECT_EQ(decode(HidProfile::SpaceMouseSplit, {0x01, 0x2c, 0x01, 0x9c, 0xff, 0x5e, 0x01}, s),
            DecodeResult::Decoded);
  // The captured rotation report: Ry = 0xffe2 = -30.
  EXPECT_EQ(decode(HidProfile::SpaceMouseSplit, {0x02, 0x00, 0x00, 0xe2, 0xff, 0x00, 0x00}, s),
            DecodeResult::Decoded);
  EXPECT_EQ(s.puck[0], 300);
  EXPECT_EQ(s.puck[1], -100);
  EXPECT_EQ(s.puck[2], 350);
  EXPECT_EQ(s.puck[3], 0);
  EXPECT_EQ(s.puck[4], -30);
  EXPECT_EQ(s.puck[5], 0);
  EXPECT_EQ(decode(HidProfile::SpaceMouseSplit, {0x03, 0x02, 0x00}, s), DecodeResult::Decoded);
  EXPECT_EQ(s.buttons, 2u);
  EXPECT_EQ(decode(HidProfile::SpaceMouseSplit, {0x03, 0x03, 0xfc}, s), DecodeResult::Decoded);
  EXPECT_EQ(s.buttons, 3u);  // the 14 padding bits are ignored
  const HidAxes a = hid_axes(HidProfile::SpaceMouseSplit, s);
  EXPECT_DOUBLE_EQ(a.axis[0], 300.0 / 350.0);   // right
  EXPECT_DOUBLE_EQ(a.axis[1], -1.0);            // pressed down
  EXPECT_DOUBLE_EQ(a.axis[2], -100.0 / 350.0);  // pushed away from the user
  EXPECT_DOUBLE_EQ(a.axis[3], 0.0);
  EXPECT_DOUBLE_EQ(a.axis[4], 0.0);
  EXPECT_DOUBLE_EQ(a.axis[5], -30.0 / 350.0);
  EXPECT_TRUE(a.recentre);  // button 1
}

TEST(HidDecode, SpaceNavigatorRefusesWrongSizesAndIds) {
  HidInput s;
  s.puck[0] = 7;
  EXPECT_EQ(decode(HidProfile::SpaceMouseSplit, {0x01, 0x2c, 0x01, 0x9c, 0xff, 0x5e}, s),
            DecodeResult::Malformed);
  EXPECT_EQ(decode(HidProfile::SpaceMouseSplit, {0x01, 0x2c, 0x01, 0x9c, 0xff, 0x5e, 0x01, 0x00}, s),
            DecodeResult::Malformed);
  EXPECT_EQ(decode(HidProfile::SpaceMouseSplit, {0x09, 0x2c, 0x01, 0x9c, 0xff, 0x5e, 0x01}, s),
            DecodeResult::Malformed);
  EXPECT_EQ(decode(HidProfile::SpaceMouseSplit, {0x03, 0x01}, s), DecodeResult::Malformed);
  EXPECT_EQ(decode(HidProfile::SpaceMouseSplit, {}, s), DecodeResult::Malformed);
  EXPECT_EQ(s.puck[0], 7);  // untouched
  EXPECT_EQ(s.buttons, 0u);
}

TEST(HidDecode, SpaceMouseWirelessCombinedReport) {
  HidInput s;
  // X 10, Y -10, Z 0, Rx 350, Ry -350, Rz 1.
  const Bytes r = {0x01, 0x0a, 0x00, 0xf6, 0xff, 0x00, 0x00, 0x5e, 0x01, 0xa2, 0xfe, 0x01, 0x00};
  EXPECT_EQ(decode(HidProfile::SpaceMouseCombined, r, s), DecodeResult::Decoded);
  const std::int16_t want[6] = {10, -10, 0, 350, -350, 1};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(s.puck[i], want[i]) << i;
  const HidAxes a = hid_axes(HidProfile::SpaceMouseCombined, s);
  EXPECT_DOUBLE_EQ(a.axis[0], 10.0 / 350.0);
  EXPECT_DOUBLE_EQ(a.axis[1], 0.0);
  EXPECT_DOUBLE_EQ(a.axis[2], -10.0 / 350.0);
  EXPECT_DOUBLE_EQ(a.axis[3], 1.0);
  EXPECT_DOUBLE_EQ(a.axis[4], -1.0 / 350.0);
  EXPECT_DOUBLE_EQ(a.axis[5], -1.0);
  EXPECT_FALSE(a.recentre);
  EXPECT_EQ(decode(HidProfile::SpaceMouseCombined, {0x17, 0x50, 0x01}, s), DecodeResult::Ignored);
  EXPECT_EQ(s.battery, 80);
  EXPECT_EQ(decode(HidProfile::SpaceMouseCombined, {0x03, 0x01, 0x00}, s), DecodeResult::Decoded);
  EXPECT_TRUE(hid_axes(HidProfile::SpaceMouseCombined, s).recentre);
  // The split layout's 7-byte reports are not this device's.
  EXPECT_EQ(decode(HidProfile::SpaceMouseCombined, {0x02, 0, 0, 0xe2, 0xff, 0, 0}, s),
            DecodeResult::Malformed);
  EXPECT_EQ(decode(HidProfile::SpaceMouseCombined, Bytes(r.begin(), r.end() - 1), s),
            DecodeResult::Malformed);
}

TEST(HidDecode, CalibrationReports) {
  MotionCalibration c;
  EXPECT_FALSE(parse_calibration(HidProfile::DualShock4, calibration_report(0x02, 36).data(), 36, c));
  EXPECT_FALSE(parse_calibration(HidProfile::DualShock4, calibration_report(0x05, 37).data(), 37, c));
  EXPECT_FALSE(c.valid);
  ASSERT_TRUE(parse_calibration(HidProfile::DualShock4, calibration_report(0x02, 37).data(), 37, c));
  // Gyro: speed (540 + 540) over |plus - bias| + |minus - bias|, bias not subtracted.
  EXPECT_DOUBLE_EQ(c.gyro_scale[0], 1080.0 / 16000.0);  // 7996 + 8004
  EXPECT_DOUBLE_EQ(c.gyro_scale[1], 1080.0 / 16200.0);  // 8103 + 8097
  EXPECT_DOUBLE_EQ(c.gyro_scale[2], 1080.0 / 15800.0);  // 7898 + 7902
  // Accel: 2 g over plus - minus, about plus - (plus - minus) / 2.
  EXPECT_DOUBLE_EQ(c.accel_bias[0], 50.0);  // 8200 - 16300 / 2
  EXPECT_DOUBLE_EQ(c.accel_scale[0], 2.0 / 16300.0);
  EXPECT_DOUBLE_EQ(c.accel_bias[1], 150.0);  // 8300 - 16300 / 2
  EXPECT_DOUBLE_EQ(c.accel_bias[2], -50.0);  // 8150 - 16400 / 2
  EXPECT_DOUBLE_EQ(c.accel_scale[2], 2.0 / 16400.0);
  MotionCalibration ds;
  ASSERT_TRUE(parse_calibration(HidProfile::DualSense, calibration_report(0x05, 41).data(), 41, ds));
  EXPECT_DOUBLE_EQ(ds.gyro_scale[1], 1080.0 / 16200.0);
}

TEST(HidDecode, DualShock4) {
  Bytes b = pad_report();
  b[1] = 0x00, b[2] = 0xff, b[3] = 0x80, b[4] = 0x40;  // sticks
  b[5] = 0x28;                                         // hat released (8), cross
  b[6] = 0x21;                                         // L1, options
  b[7] = 0x01 | (5 << 2);                              // PS, counter 5
  b[8] = 0x40, b[9] = 0xc0;                            // L2 64, R2 192
  b[13] = 0x00, b[14] = 0x01;                          // gyro x 256
  b[15] = 0x00, b[16] = 0xff;                          // gyro y -256
  b[17] = 0x10, b[18] = 0x00;                          // gyro z 16
  b[19] = 0x00, b[20] = 0x20;                          // accel x 8192
  b[21] = 0x00, b[22] = 0xe0;                          // accel y -8192
  b[30] = 0x03;                                        // battery 3 of 10
  MotionCalibration c;
  ASSERT_TRUE(parse_calibration(HidProfile::DualShock4, calibration_report(0x02, 37).data(), 37, c));
  HidInput s;
  ASSERT_EQ(decode(HidProfile::DualShock4, b, s, c), DecodeResult::Decoded);
  EXPECT_EQ(s.stick[0], 0x00);
  EXPECT_EQ(s.stick[1], 0xff);
  EXPECT_EQ(s.stick[2], 0x80);
  EXPECT_EQ(s.stick[3], 0x40);
  EXPECT_EQ(s.hat, 8);
  EXPECT_EQ(s.pad_buttons, (1u << 1) | (1u << 4) | (1u << 9) | (1u << 12));  // cross, L1, options, PS
  EXPECT_EQ(s.trigger[0], 64);
  EXPECT_EQ(s.trigger[1], 192);
  EXPECT_EQ(s.gyro_raw[0], 256);
  EXPECT_EQ(s.gyro_raw[1], -256);
  EXPECT_EQ(s.gyro_raw[2], 16);
  EXPECT_DOUBLE_EQ(s.gyro[0], 256.0 * 1080.0 / 16000.0);  // 17.28 deg/s
  EXPECT_DOUBLE_EQ(s.gyro[1], -256.0 * 1080.0 / 16200.0);
  EXPECT_DOUBLE_EQ(s.gyro[2], 16.0 * 1080.0 / 15800.0);
  EXPECT_DOUBLE_EQ(s.accel[0], (8192.0 - 50.0) * 2.0 / 16300.0);
  EXPECT_DOUBLE_EQ(s.accel[1], (-8192.0 - 150.0) * 2.0 / 16300.0);
  EXPECT_DOUBLE_EQ(s.accel[2], 50.0 * 2.0 / 16400.0);
  EXPECT_EQ(s.battery, 35);
  const HidAxes a = hid_axes(HidProfile::DualShock4, s);
  EXPECT_DOUBLE_EQ(a.axis[0], -1.0);                    // (0 - 128) / 127, clamped
  EXPECT_DOUBLE_EQ(a.axis[1], (192.0 - 64.0) / 255.0);  // R2 - L2
  EXPECT_DOUBLE_EQ(a.axis[2], 1.0);                     // (255 - 128) / 127
  EXPECT_DOUBLE_EQ(a.axis[3], 64.0 / 127.0);            // right stick up: nose up
  EXPECT_DOUBLE_EQ(a.axis[4], 0.0);
  EXPECT_DOUBLE_EQ(a.axis[5], 1.0);  // L1: roll left
  EXPECT_TRUE(a.recentre);           // options
  // Short, long, other ids.
  HidInput t;
  EXPECT_EQ(decode(HidProfile::DualShock4, pad_report(63), t), DecodeResult::Malformed);
  EXPECT_EQ(decode(HidProfile::DualShock4, pad_report(65), t), DecodeResult::Malformed);
  Bytes other = pad_report();
  other[0] = 0x11;
  EXPECT_EQ(decode(HidProfile::DualShock4, other, t), DecodeResult::Malformed);
  EXPECT_EQ(t.stick[0], 128);
}

TEST(HidDecode, DualSense) {
  Bytes b = pad_report();
  b[1] = 0xff, b[2] = 0x80, b[3] = 0xc0, b[4] = 0x00;  // sticks
  b[5] = 0x10, b[6] = 0xf0;                            // L2 16, R2 240
  b[8] = 0x13;                                         // hat 3 (SE), square
  b[9] = 0x22;                                         // R1, options
  b[10] = 0x02;                                        // touchpad click
  b[16] = 0x00, b[17] = 0x02;                          // gyro x 512
  b[20] = 0xff, b[21] = 0xff;                          // gyro z -1
  b[24] = 0x00, b[25] = 0x40;                          // accel y 16384
  b[53] = 0x0a;                                        // battery 10
  // Bytes where the DualShock 4 keeps its triggers and gyro: not read here.
  b[13] = 0x7f, b[14] = 0x7f;
  MotionCalibration c;
  ASSERT_TRUE(parse_calibration(HidProfile::DualSense, calibration_report(0x05, 41).data(), 41, c));
  HidInput s;
  ASSERT_EQ(decode(HidProfile::DualSense, b, s, c), DecodeResult::Decoded);
  EXPECT_EQ(s.trigger[0], 16);
  EXPECT_EQ(s.trigger[1], 240);
  EXPECT_EQ(s.hat, 3);
  EXPECT_EQ(s.pad_buttons, (1u << 0) | (1u << 5) | (1u << 9) | (1u << 13));  // square, R1, options, touchpad
  EXPECT_EQ(s.gyro_raw[0], 512);
  EXPECT_EQ(s.gyro_raw[1], 0);
  EXPECT_EQ(s.gyro_raw[2], -1);
  EXPECT_EQ(s.accel_raw[1], 16384);
  EXPECT_DOUBLE_EQ(s.gyro[0], 512.0 * 1080.0 / 16000.0);
  EXPECT_DOUBLE_EQ(s.accel[1], (16384.0 - 150.0) * 2.0 / 16300.0);
  EXPECT_EQ(s.battery, 100);
  const HidAxes a = hid_axes(HidProfile::DualSense, s);
  EXPECT_DOUBLE_EQ(a.axis[0], 1.0);  // (255 - 128) / 127
  EXPECT_DOUBLE_EQ(a.axis[1], (240.0 - 16.0) / 255.0);
  EXPECT_DOUBLE_EQ(a.axis[2], 0.0);
  EXPECT_DOUBLE_EQ(a.axis[3], 1.0);            // right stick fully up: (0 - 128) / 127 clamped, negated
  EXPECT_DOUBLE_EQ(a.axis[4], -64.0 / 127.0);  // right stick right: yaw right
  EXPECT_DOUBLE_EQ(a.axis[5], -1.0);           // R1: roll right
  EXPECT_TRUE(a.recentre);
  EXPECT_EQ(decode(HidProfile::DualSense, pad_report(10), s), DecodeResult::Malformed);
}

TEST(HidMotion, DeadZoneAndCurve) {
  EXPECT_EQ(shape_axis(0.05, 0.1, 2.0), 0.0);
  EXPECT_EQ(shape_axis(-0.1, 0.1, 2.0), 0.0);
  EXPECT_NEAR(shape_axis(0.55, 0.1, 2.0), 0.25, 1e-15);   // (0.45 / 0.9)^2
  EXPECT_NEAR(shape_axis(-0.55, 0.1, 1.0), -0.5, 1e-15);  // linear
  EXPECT_EQ(shape_axis(1.0, 0.1, 3.0), 1.0);
  EXPECT_EQ(shape_axis(-1.0, 0.0, 2.0), -1.0);
  EXPECT_EQ(shape_axis(std::nan(""), 0.1, 2.0), 0.0);
}

TEST(HidMotion, ConstantDeflectionIntegratesExactly) {
  MotionSettings s;
  s.linear_speed = 0.1, s.angular_speed = 1.0, s.dead_zone = 0.0, s.exponent = 1.0;
  ToolMotion m;
  const double start[3] = {0.2, 0.0, -0.1}, identity[4] = {1, 0, 0, 0}, ref[3] = {0.05, 0.05, 0.05};
  m.reset(start, identity, ref);
  HidAxes a;
  a.axis[0] = 1.0;   // x at full speed
  a.axis[2] = -0.5;  // -z at half
  a.axis[4] = 1.0;   // about y at full speed
  // 0.5 s in uneven steps.
  const double steps[] = {0.001, 0.1, 0.0375, 0.2, 0.1605, 0.0003, 0.0007};
  double total = 0.0;
  for (const double dt : steps) m.step(a, s, dt), total += dt;
  ASSERT_NEAR(total, 0.5, 1e-15);
  // The reference point moved 0.05 m along x and -0.025 m along z; the tool
  // turned 0.5 rad about +y through it.
  const glm::dvec3 ref0(0.25, 0.05, -0.05);
  const glm::dvec3 ref1 = ref0 + glm::dvec3(0.05, 0.0, -0.025);
  const glm::dquat q = glm::angleAxis(0.5, glm::dvec3(0, 1, 0));
  const glm::dvec3 origin = ref1 - q * glm::dvec3(0.05, 0.05, 0.05);
  double p[3], r[4];
  m.pose(p, r);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p[i], origin[i], 1e-12) << i;
  EXPECT_NEAR(r[0], q.w, 1e-12);
  EXPECT_NEAR(r[1], 0.0, 1e-12);
  EXPECT_NEAR(r[2], q.y, 1e-12);
  EXPECT_NEAR(r[3], 0.0, 1e-12);
}

TEST(HidMotion, DeviceToWorldRotatesTheAxes) {
  MotionSettings s;
  s.linear_speed = 1.0, s.dead_zone = 0.0, s.exponent = 1.0;
  // A quarter turn about z: the device's x is the world's y.
  const glm::dquat q = glm::angleAxis(1.5707963267948966, glm::dvec3(0, 0, 1));
  s.device_to_world[0] = q.w, s.device_to_world[1] = q.x, s.device_to_world[2] = q.y,
  s.device_to_world[3] = q.z;
  ToolMotion m;
  const double zero[3] = {0, 0, 0}, identity[4] = {1, 0, 0, 0};
  m.reset(zero, identity, zero);
  HidAxes a;
  a.axis[0] = 1.0;
  m.step(a, s, 0.25);
  double p[3], r[4];
  m.pose(p, r);
  EXPECT_NEAR(p[0], 0.0, 1e-12);
  EXPECT_NEAR(p[1], 0.25, 1e-12);
  EXPECT_NEAR(p[2], 0.0, 1e-12);
}

TEST(HidOutput, Reports) {
  OutputSettings s;  // 3 N for full rumble and trigger
  const OutputReport rest4 = build_output(HidProfile::DualShock4, 0.0, s);
  ASSERT_EQ(rest4.size, 32u);
  EXPECT_EQ(rest4.bytes[0], 0x05);
  EXPECT_EQ(rest4.bytes[1], 0x03);
  EXPECT_EQ(rest4.bytes[4], 0);
  EXPECT_EQ(rest4.bytes[5], 0);
  EXPECT_EQ(rest4.bytes[7], 255);  // green
  const OutputReport half4 = build_output(HidProfile::DualShock4, 1.5, s);
  EXPECT_EQ(half4.bytes[4], 128);  // 127.5 rounded
  EXPECT_EQ(half4.bytes[5], 128);
  EXPECT_EQ(half4.bytes[6], 128);
  EXPECT_EQ(half4.bytes[7], 127);
  EXPECT_EQ(build_output(HidProfile::DualShock4, 30.0, s).bytes[5], 255);

  const OutputReport rest5 = build_output(HidProfile::DualSense, 0.0, s);
  ASSERT_EQ(rest5.size, 48u);
  EXPECT_EQ(rest5.bytes[0], 0x02);
  EXPECT_EQ(rest5.bytes[1], 0x07);
  EXPECT_EQ(rest5.bytes[2], 0x04);
  EXPECT_EQ(rest5.bytes[11], 0x05);  // trigger effect off
  EXPECT_EQ(rest5.bytes[13], 0);
  EXPECT_EQ(rest5.bytes[46], 255);
  const OutputReport some = build_output(HidProfile::DualSense, 0.6, s);
  EXPECT_EQ(some.bytes[3], 51);     // 0.2 * 255
  EXPECT_EQ(some.bytes[11], 0x01);  // constant resistance
  EXPECT_EQ(some.bytes[12], 0x00);  // from the start of the pull
  EXPECT_EQ(some.bytes[13], 51);
  EXPECT_EQ(some.bytes[45], 51);
  EXPECT_EQ(some.bytes[46], 204);
  EXPECT_NE(some, rest5);

  EXPECT_EQ(build_output(HidProfile::SpaceMouseSplit, 0.0, s).bytes[1], 0);
  const OutputReport lit = build_output(HidProfile::SpaceMouseCombined, 0.5, s);
  ASSERT_EQ(lit.size, 2u);
  EXPECT_EQ(lit.bytes[0], 0x04);
  EXPECT_EQ(lit.bytes[1], 1);
}

// The light bar from the closest distance, by the mapping in
// docs/devices.md: cutoff 10 mm, safety distance 1 mm.
TEST(HidOutput, LightBarFollowsTheClosestDistance) {
  OutputSettings s;
  OutputInput in;
  in.safety_distance = 0.001, in.cutoff = 0.010;
  auto colour = [&](HidProfile p, double d, double force = 0.0) {
    in.closest_distance = d, in.force = force;
    const OutputReport r = build_output(p, in, s);
    const std::size_t at = p == HidProfile::DualShock4 ? 6 : 45;
    return std::array<int, 3>{r.bytes[at], r.bytes[at + 1], r.bytes[at + 2]};
  };
  using C = std::array<int, 3>;
  for (const HidProfile p : {HidProfile::DualShock4, HidProfile::DualSense}) {
    EXPECT_EQ(colour(p, std::numeric_limits<double>::infinity()), (C{0, 255, 0})) << "no contact: rest";
    EXPECT_EQ(colour(p, 0.020), (C{0, 255, 0})) << "beyond the cutoff";
    EXPECT_EQ(colour(p, 0.010), (C{0, 255, 0})) << "at the cutoff";
    // 7 mm: a third of the way from the cutoff to the safety distance,
    // t = 1/3: 85 red, 255 - 95 / 3 = 223.3 green.
    EXPECT_EQ(colour(p, 0.007), (C{85, 223, 0}));
    // 4 mm: t = 2/3: 170 red, 191.7 green.
    EXPECT_EQ(colour(p, 0.004), (C{170, 192, 0}));
    EXPECT_EQ(colour(p, 0.001), (C{255, 0, 0})) << "at the safety distance: contact";
    EXPECT_EQ(colour(p, 0.0), (C{255, 0, 0})) << "pushed through";
    // The force does not change the colour when the distance is known ...
    EXPECT_EQ(colour(p, 0.020, 2.0), (C{0, 255, 0}));
    // ... and gives it when it is not (a def wrapped in the application's
    // callbacks): 1.5 N of 3 is 127.5 -> 128 red.
    EXPECT_EQ(colour(p, std::numeric_limits<double>::quiet_NaN(), 1.5), (C{128, 127, 0}));
  }
}
