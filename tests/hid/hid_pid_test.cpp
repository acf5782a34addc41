// HID PID force-feedback devices recognised from their report descriptors
// (sdk/src/devices/hid_descriptor.h, hid_pid.h): the two real firmwares'
// descriptors from the shared devices folder, against what their layouts
// (../shared/devices/pid/LAYOUT.md) say of each field. Every field's offset
// is also checked against the shared folder's own decoder by
// hid_descriptor_test.py, through proxima_hid_descriptor_dump.
#include "devices/hid_descriptor.h"
#include "devices/hid_pid.h"
#include "devices/hid_pid_reports.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace prox::devices {
namespace {

std::vector<std::uint8_t> read(const std::string& name) {
  std::ifstream in(std::string(PROX_SHARED_DEVICES_DIR) + "/" + name, std::ios::binary);
  if (!in) ADD_FAILURE() << "missing " << PROX_SHARED_DEVICES_DIR << "/" << name;
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

PidLayout layout_of(const std::string& name) {
  const std::vector<std::uint8_t> bytes = read(name);
  HidDescriptor d;
  const Status s = parse_hid_descriptor(bytes.data(), bytes.size(), d);
  EXPECT_TRUE(s.is_ok()) << name << ": " << s.message();
  PidLayout p;
  const Status l = pid_layout_of(d, p);
  EXPECT_TRUE(l.is_ok()) << name << ": " << l.message();
  return p;
}

// Byte.bit of a slot, as LAYOUT.md writes it.
std::string at(const PidSlot& s) { return std::to_string(s.bit / 8) + "." + std::to_string(s.bit % 8); }

TEST(HidPid, OpenFfBoardIsATwoAxisJoystickWithSixteenBitDirectionsAndAMaskedControl) {
  const PidLayout p = layout_of("pid/openffboard_1209_ffb0.rdesc.bin");
  ASSERT_TRUE(p.pid);
  EXPECT_EQ(p.axes, 2);
  // Set Effect, report 0x01, 22 bytes.
  EXPECT_EQ(p.effect_block.report_id, 0x01);
  EXPECT_EQ(p.effect_block.report_bytes, 22u);
  EXPECT_EQ(at(p.effect_type), "2.0");
  EXPECT_EQ(p.constant_force_type, 1);
  EXPECT_EQ(at(p.duration), "3.0");
  EXPECT_EQ(p.duration.bits, 16u);
  EXPECT_EQ(at(p.start_delay), "9.0");
  EXPECT_EQ(at(p.gain), "11.0");
  EXPECT_EQ(at(p.axis_enable[0]), "13.0");
  EXPECT_EQ(at(p.axis_enable[1]), "13.1");
  EXPECT_EQ(at(p.direction_enable), "13.2");
  EXPECT_EQ(at(p.direction[0]), "14.0");
  EXPECT_EQ(at(p.direction[1]), "16.0");
  EXPECT_EQ(p.direction[0].bits, 16u);
  EXPECT_EQ(p.direction[0].max, 36000);
  // Set Constant Force, report 0x05: magnitude +-32767 at byte 2.
  EXPECT_EQ(p.magnitude.report_id, 0x05);
  EXPECT_EQ(p.magnitude.report_bytes, 4u);
  EXPECT_EQ(at(p.magnitude), "2.0");
  EXPECT_EQ(p.magnitude.bits, 16u);
  EXPECT_EQ(p.magnitude.min, -32767);
  EXPECT_EQ(p.magnitude.max, 32767);
  // Effect Operation, report 0x0A: 1 start, 3 stop.
  EXPECT_EQ(p.operation.report_id, 0x0A);
  EXPECT_EQ(p.op_start, 1);
  EXPECT_EQ(p.op_stop, 3);
  // Device Control, report 0x0C: a bit mask; reset is 0C 08.
  EXPECT_EQ(p.control.report_id, 0x0C);
  EXPECT_TRUE(p.control_is_mask);
  EXPECT_EQ(p.control.bits, 8u);
  EXPECT_EQ(p.control_enable, 0x01);
  EXPECT_EQ(p.control_reset, 0x08);
  EXPECT_EQ(p.device_gain.report_id, 0x0D);
  EXPECT_EQ(p.free_block.report_id, 0x0B);
  // Feature reports: Create New Effect 0x11, Block Load 0x12, PID Pool 0x13.
  EXPECT_EQ(p.create_type.report_id, 0x11);
  EXPECT_EQ(p.create_type.report_bytes, 4u);
  EXPECT_EQ(p.create_byte_count.bits, 10u);
  EXPECT_EQ(p.load_block.report_id, 0x12);
  EXPECT_EQ(p.load_block.report_bytes, 5u);
  EXPECT_EQ(at(p.load_status), "2.0");
  EXPECT_EQ(p.load_success, 1);
  EXPECT_EQ(p.load_full, 2);
  EXPECT_EQ(p.load_error, 3);
  EXPECT_EQ(at(p.load_ram_available), "3.0");
  EXPECT_EQ(p.pool_ram_size.report_id, 0x13);
  EXPECT_EQ(at(p.pool_max_effects), "3.0");
  // The stick: gamepad report 0x01 (25 bytes), X at 9 and Y at 11, int16.
  EXPECT_EQ(p.position[0].report_id, 0x01);
  EXPECT_EQ(p.position[0].report_bytes, 25u);
  EXPECT_EQ(at(p.position[0]), "9.0");
  EXPECT_EQ(at(p.position[1]), "11.0");
  EXPECT_EQ(p.position[0].bits, 16u);
  EXPECT_EQ(p.position[0].min, -32767);
  EXPECT_EQ(p.position[0].max, 32767);
}

TEST(HidPid, TheArduinoLibraryHasEightBitDirectionsAnIndexedControlAndTenThousandSteps) {
  const PidLayout p = layout_of("pid/arduino_joystick_ffb_2341_8036.rdesc.bin");
  ASSERT_TRUE(p.pid);
  EXPECT_EQ(p.axes, 2);
  EXPECT_EQ(p.effect_block.report_bytes, 18u);
  EXPECT_FALSE(p.start_delay.present);
  EXPECT_EQ(at(p.gain), "9.0");
  EXPECT_EQ(at(p.axis_enable[1]), "11.1");
  EXPECT_EQ(at(p.direction[0]), "12.0");
  EXPECT_EQ(at(p.direction[1]), "13.0");
  EXPECT_EQ(p.direction[0].bits, 8u);
  EXPECT_EQ(p.direction[0].max, 255);
  EXPECT_EQ(p.magnitude.min, -10000);
  EXPECT_EQ(p.magnitude.max, 10000);
  // Device Control: an index; reset is 0C 04.
  EXPECT_FALSE(p.control_is_mask);
  EXPECT_EQ(p.control.bits, 8u);
  EXPECT_EQ(p.control_enable, 1);
  EXPECT_EQ(p.control_reset, 4);
  EXPECT_EQ(p.create_type.report_id, 0x05);
  EXPECT_EQ(p.load_block.report_id, 0x06);
  EXPECT_EQ(p.pool_ram_size.report_id, 0x07);
  // The stick: gamepad report 0x01 (10 bytes), X at 2 and Y at 4.
  EXPECT_EQ(p.position[0].report_bytes, 10u);
  EXPECT_EQ(at(p.position[0]), "2.0");
  EXPECT_EQ(at(p.position[1]), "4.0");
}

TEST(HidPid, TheOneAxisBuildIsAWheel) {
  const PidLayout p = layout_of("pid/openffboard_1209_ffb0_1axis.rdesc.bin");
  ASSERT_TRUE(p.pid);
  EXPECT_EQ(p.axes, 1);
  EXPECT_FALSE(p.axis_enable[1].present);
  EXPECT_FALSE(p.direction[1].present);
}

TEST(HidPid, DevicesWithoutPidReportsAreNotForceFeedback) {
  for (const char* name : {"ds4v2_054c_09cc.rdesc.bin", "dualsense_054c_0ce6.rdesc.bin",
                           "spacemouse_wireless_256f_c62e.rdesc.bin", "spacenavigator_046d_c626_228b.rdesc.bin"}) {
    const std::vector<std::uint8_t> bytes = read(name);
    HidDescriptor d;
    ASSERT_TRUE(parse_hid_descriptor(bytes.data(), bytes.size(), d).is_ok()) << name;
    EXPECT_FALSE(d.fields.empty()) << name;
    PidLayout p;
    EXPECT_TRUE(pid_layout_of(d, p).is_ok()) << name;
    EXPECT_FALSE(p.pid) << name;
  }
}

TEST(HidPid, APidDescriptorMissingWhatAConstantForceNeedsIsNamed) {
  // The OpenFFBoard descriptor with its Set Constant Force report's
  // Magnitude usage (0x70) made another (0x71, Phase).
  std::vector<std::uint8_t> bytes = read("pid/openffboard_1209_ffb0.rdesc.bin");
  bool changed = false;
  for (std::size_t i = 0; i + 3 < bytes.size() && !changed; ++i)
    if (bytes[i] == 0x09 && bytes[i + 1] == 0x73) {  // Usage (Set Constant Force Report)
      for (std::size_t j = i + 2; j + 1 < bytes.size(); ++j)
        if (bytes[j] == 0x09 && bytes[j + 1] == 0x70) {
          bytes[j + 1] = 0x71;
          changed = true;
          break;
        }
    }
  ASSERT_TRUE(changed);
  HidDescriptor d;
  ASSERT_TRUE(parse_hid_descriptor(bytes.data(), bytes.size(), d).is_ok());
  PidLayout p;
  const Status s = pid_layout_of(d, p);
  EXPECT_FALSE(s.is_ok());
  EXPECT_NE(s.message().find("Set Constant Force report's Magnitude"), std::string::npos) << s.message();
  EXPECT_FALSE(p.pid);
}

using Bytes = std::vector<std::uint8_t>;

// The host sequence's bytes, as ../shared/devices/pid/PROTOCOL.md gives
// them for each device (its tables in sections 2 to 6).
TEST(HidPidReports, TheHostSequenceIsByteForByteTheProtocols) {
  const PidLayout offb = layout_of("pid/openffboard_1209_ffb0.rdesc.bin");
  const PidLayout ard = layout_of("pid/arduino_joystick_ffb_2341_8036.rdesc.bin");
  ASSERT_TRUE(offb.pid && ard.pid);
  // (a) Reset, stop all, enable; full device gain.
  EXPECT_EQ(pid_device_control(offb, PidControl::Reset), (Bytes{0x0c, 0x08}));
  EXPECT_EQ(pid_device_control(ard, PidControl::Reset), (Bytes{0x0c, 0x04}));
  EXPECT_EQ(pid_device_control(offb, PidControl::StopAllEffects), (Bytes{0x0c, 0x04}));
  EXPECT_EQ(pid_device_control(ard, PidControl::StopAllEffects), (Bytes{0x0c, 0x03}));
  EXPECT_EQ(pid_device_control(offb, PidControl::EnableActuators), (Bytes{0x0c, 0x01}));
  EXPECT_EQ(pid_device_control(ard, PidControl::EnableActuators), (Bytes{0x0c, 0x01}));
  EXPECT_EQ(pid_device_gain(offb, 1.0), (Bytes{0x0d, 0xff}));
  EXPECT_EQ(pid_device_gain(ard, 1.0), (Bytes{0x0d, 0xff}));
  // (b) Create a constant force; get Block Load; its answer.
  EXPECT_EQ(pid_create_constant_force(offb), (Bytes{0x11, 0x01, 0x00, 0x00}));
  EXPECT_EQ(pid_create_constant_force(ard), (Bytes{0x05, 0x01, 0x00, 0x00}));
  EXPECT_EQ(pid_block_load_request(offb), (Bytes{0x12, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(pid_block_load_request(ard), (Bytes{0x06, 0x00, 0x00, 0x00, 0x00}));
  const Bytes loaded{0x12, 0x01, 0x01, 0x34, 0x12}, full{0x06, 0x00, 0x02, 0x00, 0x00};
  const Bytes error{0x12, 0x00, 0x03, 0x00, 0x00}, pending{0x12, 0x00, 0x00, 0x00, 0x00};
  EXPECT_EQ(pid_parse_block_load(offb, loaded.data(), loaded.size()).status, PidLoadStatus::Success);
  EXPECT_EQ(pid_parse_block_load(offb, loaded.data(), loaded.size()).index, 1);
  EXPECT_EQ(pid_parse_block_load(ard, full.data(), full.size()).status, PidLoadStatus::Full);
  EXPECT_EQ(pid_parse_block_load(offb, error.data(), error.size()).status, PidLoadStatus::Error);
  EXPECT_EQ(pid_parse_block_load(offb, pending.data(), pending.size()).status, PidLoadStatus::Pending);
  EXPECT_EQ(pid_parse_block_load(ard, loaded.data(), loaded.size()).status, PidLoadStatus::Pending)
      << "another report's id";
  EXPECT_EQ(pid_parse_block_load(offb, loaded.data(), 3).status, PidLoadStatus::Pending) << "short";
  // Set Effect: block 1, direction 90 degrees (9000), full gain. PROTOCOL's
  // example has an infinite duration (ff ff); a finite one is sent here:
  // 100 ms, 64 00.
  EXPECT_EQ(pid_set_constant_effect(offb, 1, 100, 9000),
            (Bytes{0x01, 0x01, 0x01, 0x64, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                   0xff, 0x00, 0x04, 0x28, 0x23, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(pid_set_constant_effect(ard, 1, 100, 9000),
            (Bytes{0x01, 0x01, 0x01, 0x64, 0x00, 0x00, 0x00, 0x00, 0x00, 0xff, 0x00, 0x04, 0x3f, 0x00, 0x00, 0x00,
                   0x00, 0x00}));
  // A duration past the field stops one short of its top, which the
  // Arduino library takes for "infinite".
  const Bytes forever = pid_set_constant_effect(ard, 1, 1000000, 0);
  EXPECT_EQ(read_hid_bits(forever.data(), forever.size(), 24, 16, false), 32766);
  // (c) Set Constant Force: Linux's levels +0x4000 and -0x4000.
  EXPECT_EQ(pid_set_constant_force(offb, 1, 16384.0 / 32767.0), (Bytes{0x05, 0x01, 0x00, 0x40}));
  EXPECT_EQ(pid_set_constant_force(ard, 1, 16384.0 / 32767.0), (Bytes{0x05, 0x01, 0x88, 0x13}));
  EXPECT_EQ(pid_set_constant_force(offb, 1, -16384.0 / 32768.0), (Bytes{0x05, 0x01, 0x00, 0xc0}));
  EXPECT_EQ(pid_set_constant_force(ard, 1, -16384.0 / 32768.0), (Bytes{0x05, 0x01, 0x78, 0xec}));
  // Beyond full scale, or not a number: clamped, or nothing.
  EXPECT_EQ(pid_set_constant_force(ard, 1, 7.0), (Bytes{0x05, 0x01, 0x10, 0x27}));
  EXPECT_EQ(pid_set_constant_force(offb, 1, NAN), (Bytes{0x05, 0x01, 0x00, 0x00}));
  // (d) Start once, stop; (e) free.
  EXPECT_EQ(pid_effect_start(offb, 1, 1), (Bytes{0x0a, 0x01, 0x01, 0x01}));
  EXPECT_EQ(pid_effect_start(ard, 1, 1), (Bytes{0x0a, 0x01, 0x01, 0x01}));
  EXPECT_EQ(pid_effect_stop(offb, 1), (Bytes{0x0a, 0x01, 0x03, 0x01}));
  EXPECT_EQ(pid_block_free(ard, 1), (Bytes{0x0b, 0x01}));
}

// What each firmware does with a direction and a magnitude (PROTOCOL.md,
// section 7), to check the rendering against.
void firmware_push(const PidForce& f, PidForceSign sign, double& fx, double& fy) {
  const double theta = f.direction_centidegrees * 3.14159265358979323846 / 18000.0;
  const double s = static_cast<double>(static_cast<int>(sign));
  fx = -s * f.magnitude * std::sin(theta);  // OpenFFBoard: torque_x = -M sin theta
  fy = s * f.magnitude * std::cos(theta);   //              torque_y = +M cos theta
}

TEST(HidPidReports, AForceIsRenderedAsTheFirmwarePushesIt) {
  // RENDERING.md's checks: a push to the right is 27000, towards the user 0.
  EXPECT_EQ(pid_force_of(2.0, 0.0, 4.0, 2, PidForceSign::DirectInput).direction_centidegrees, 27000u);
  EXPECT_EQ(pid_force_of(0.0, 2.0, 4.0, 2, PidForceSign::DirectInput).direction_centidegrees, 0u);
  EXPECT_EQ(pid_force_of(0.0, -2.0, 4.0, 2, PidForceSign::DirectInput).direction_centidegrees, 18000u);
  EXPECT_EQ(pid_force_of(-2.0, 0.0, 4.0, 2, PidForceSign::DirectInput).direction_centidegrees, 9000u);
  EXPECT_EQ(pid_force_of(2.0, 0.0, 4.0, 2, PidForceSign::Opposite).direction_centidegrees, 9000u);
  EXPECT_DOUBLE_EQ(pid_force_of(2.0, 0.0, 4.0, 2, PidForceSign::DirectInput).magnitude, 0.5);
  // Many pushes, both firmwares: what the firmware makes of the force is the
  // push itself, to the direction's quantum (0.01 degree), or full scale.
  for (const PidForceSign sign : {PidForceSign::DirectInput, PidForceSign::Opposite}) {
    for (int k = 0; k < 720; ++k) {
      const double a = k * 0.5 * 3.14159265358979323846 / 180.0 + 0.001, size = 0.25 + 0.01 * (k % 100);
      const double fx = size * std::cos(a), fy = size * std::sin(a);
      const PidForce f = pid_force_of(fx, fy, 1.0, 2, sign);
      ASSERT_LT(f.direction_centidegrees, 36000u);
      double gx = 0, gy = 0;
      firmware_push(f, sign, gx, gy);
      const double want = std::min(size, 1.0) / size;  // clipped to full scale
      EXPECT_NEAR(gx, fx * want, 2e-4) << k;
      EXPECT_NEAR(gy, fy * want, 2e-4) << k;
    }
  }
  // A wheel: east, signed; the firmware's push along x is the force's.
  for (const PidForceSign sign : {PidForceSign::DirectInput, PidForceSign::Opposite})
    for (const double fx : {-3.0, -0.5, 0.0, 0.5, 3.0}) {
      const PidForce f = pid_force_of(fx, 7.0, 2.0, 1, sign);
      EXPECT_EQ(f.direction_centidegrees, 9000u);
      double gx = 0, gy = 0;
      firmware_push(f, sign, gx, gy);
      EXPECT_NEAR(gx * 2.0, std::clamp(fx, -2.0, 2.0), 1e-12) << fx;
    }
  // Nothing to push, or nonsense: no force.
  EXPECT_EQ(pid_force_of(0.0, 0.0, 1.0, 2, PidForceSign::DirectInput).magnitude, 0.0);
  EXPECT_EQ(pid_force_of(NAN, 1.0, 1.0, 2, PidForceSign::DirectInput).magnitude, 0.0);
  EXPECT_EQ(pid_force_of(1.0, 1.0, 0.0, 2, PidForceSign::DirectInput).magnitude, 0.0);
}

TEST(HidDescriptor, BrokenDescriptorsAreRefusedWithTheByteNamed) {
  struct Case {
    std::vector<std::uint8_t> bytes;
    const char* says;
  };
  const Case cases[] = {
      {{0x05, 0x01, 0x09, 0x04, 0xA1, 0x01}, "left open"},            // collection never closed
      {{0xC0}, "End Collection without"},                               // closed, never opened
      {{0x05}, "past the end"},                                         // truncated item
      {{0xB4}, "Pop without a Push"},                                   //
      {{0x85, 0x00}, "report id 0"},                                    //
      {{0x29, 0x05}, "Usage Maximum without"},                          //
      {{0x75, 0x08, 0x97, 0xFF, 0xFF, 0x00, 0x00, 0x81, 0x02}, "report count"},  // 65,535 slots
      {{0x75, 0x40, 0x95, 0x01, 0x81, 0x02}, "64-bit data field"},      //
      {{0xFE, 0x10}, "truncated long item"},                            //
  };
  for (const Case& c : cases) {
    HidDescriptor d;
    const Status s = parse_hid_descriptor(c.bytes.data(), c.bytes.size(), d);
    EXPECT_FALSE(s.is_ok()) << c.says;
    EXPECT_NE(s.message().find(c.says), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("byte "), std::string::npos) << s.message();
    EXPECT_TRUE(d.fields.empty());
  }
}

TEST(HidDescriptor, BitFieldsReadAndWriteLittleEndianAndSigned) {
  std::uint8_t report[4] = {0x05, 0, 0, 0};
  write_hid_bits(report, 4, 16, 16, -32767);  // Set Constant Force's magnitude
  EXPECT_EQ(report[2], 0x01);
  EXPECT_EQ(report[3], 0x80);
  EXPECT_EQ(read_hid_bits(report, 4, 16, 16, true), -32767);
  EXPECT_EQ(read_hid_bits(report, 4, 16, 16, false), 0x8001);
  write_hid_bits(report, 4, 9, 3, 5);  // inside a byte, across nothing else
  EXPECT_EQ(report[1], 0x0A);
  EXPECT_EQ(read_hid_bits(report, 4, 9, 3, false), 5);
  write_hid_bits(report, 4, 30, 8, 0xFF);  // past the end: nothing
  EXPECT_EQ(report[3], 0x80);
  EXPECT_EQ(read_hid_bits(report, 4, 30, 8, false), 0);
}

}  // namespace
}  // namespace prox::devices
