#include "devices/hid_profiles.h"

#include <algorithm>
#include <cstdlib>

namespace prox::devices {
namespace {

// 3Dconnexion's ids (Logitech-era 046d and 3Dconnexion's own 256f) and Sony's.
// The split-report pucks are the older Logitech-era ones.
constexpr KnownHidDevice kKnown[] = {
    {0x046d, 0xc626, HidProfile::SpaceMouseSplit, "3Dconnexion SpaceNavigator"},
    {0x046d, 0xc627, HidProfile::SpaceMouseSplit, "3Dconnexion SpaceExplorer"},
    {0x046d, 0xc628, HidProfile::SpaceMouseSplit, "3Dconnexion SpaceNavigator for Notebooks"},
    {0x046d, 0xc629, HidProfile::SpaceMouseSplit, "3Dconnexion SpacePilot Pro"},
    {0x046d, 0xc62b, HidProfile::SpaceMouseSplit, "3Dconnexion SpaceMouse Pro"},
    {0x046d, 0xc603, HidProfile::SpaceMouseSplit, "3Dconnexion SpaceMouse Plus XT"},
    {0x046d, 0xc606, HidProfile::SpaceMouseSplit, "3Dconnexion SpaceMouse Classic"},
    {0x046d, 0xc621, HidProfile::SpaceMouseSplit, "3Dconnexion SpaceBall 5000"},
    {0x046d, 0xc623, HidProfile::SpaceMouseSplit, "3Dconnexion SpaceTraveler"},
    {0x046d, 0xc625, HidProfile::SpaceMouseSplit, "3Dconnexion SpacePilot"},
    {0x256f, 0xc62e, HidProfile::SpaceMouseCombined, "3Dconnexion SpaceMouse Wireless (cabled)"},
    {0x256f, 0xc62f, HidProfile::SpaceMouseCombined, "3Dconnexion SpaceMouse Wireless (receiver)"},
    {0x256f, 0xc631, HidProfile::SpaceMouseCombined, "3Dconnexion SpaceMouse Pro Wireless (cabled)"},
    {0x256f, 0xc632, HidProfile::SpaceMouseCombined, "3Dconnexion SpaceMouse Pro Wireless (receiver)"},
    {0x256f, 0xc635, HidProfile::SpaceMouseCombined, "3Dconnexion SpaceMouse Compact"},
    {0x256f, 0xc652, HidProfile::SpaceMouseCombined, "3Dconnexion Universal Receiver"},
    {0x054c, 0x05c4, HidProfile::DualShock4, "Sony DualShock 4"},
    {0x054c, 0x09cc, HidProfile::DualShock4, "Sony DualShock 4 (v2)"},
    {0x054c, 0x0ce6, HidProfile::DualSense, "Sony DualSense"},
};

std::int16_t le16s(const std::uint8_t* p) { return std::int16_t(std::uint16_t(p[0] | (p[1] << 8))); }

double clamp1(double v) { return std::clamp(v, -1.0, 1.0); }
double puck(std::int16_t v) { return clamp1(double(v) / 350.0); }
double stick(std::uint8_t v) { return clamp1((double(v) - 128.0) / 127.0); }

void calibrate(const MotionCalibration& c, HidInput& s) {
  for (int i = 0; i < 3; ++i) {
    s.gyro[i] = (double(s.gyro_raw[i]) - c.gyro_bias[i]) * c.gyro_scale[i];
    s.accel[i] = (double(s.accel_raw[i]) - c.accel_bias[i]) * c.accel_scale[i];
  }
}

// The pads' button bits, gathered into HidInput::pad_buttons' order from
// the byte with square..triangle in its high nibble and the two after it.
std::uint32_t pad_buttons(std::uint8_t face, std::uint8_t shoulders, std::uint8_t system) {
  return std::uint32_t(face >> 4) | (std::uint32_t(shoulders) << 4) | (std::uint32_t(system & 0x03) << 12);
}

}  // namespace

const KnownHidDevice* known_hid_devices(std::size_t* count) {
  *count = sizeof kKnown / sizeof kKnown[0];
  return kKnown;
}

HidProfile hid_profile_of(std::uint16_t vendor_id, std::uint16_t product_id, std::uint16_t usage_page,
                          std::uint16_t usage, int interface_number) {
  for (const KnownHidDevice& k : kKnown) {
    if (k.vendor_id != vendor_id || k.product_id != product_id) continue;
    if (usage_page != 0x01) return HidProfile::None;  // the pucks' vendor collections
    const bool pad = k.profile == HidProfile::DualShock4 || k.profile == HidProfile::DualSense;
    if (pad && (usage != 0x05 || (interface_number != 3 && interface_number != -1))) return HidProfile::None;
    if (!pad && usage != 0x08) return HidProfile::None;
    return k.profile;
  }
  return HidProfile::None;
}

const char* hid_profile_name(HidProfile profile) {
  switch (profile) {
    case HidProfile::SpaceMouseSplit:
      return "spacemouse-split";
    case HidProfile::SpaceMouseCombined:
      return "spacemouse";
    case HidProfile::DualShock4:
      return "dualshock4";
    case HidProfile::DualSense:
      return "dualsense";
    case HidProfile::PidJoystick:
      return "pid-joystick";
    case HidProfile::PidWheel:
      return "pid-wheel";
    case HidProfile::None:
      break;
  }
  return "none";
}

std::uint8_t calibration_report_id(HidProfile profile) {
  return profile == HidProfile::DualShock4 ? 0x02 : profile == HidProfile::DualSense ? 0x05 : 0;
}

std::size_t calibration_report_size(HidProfile profile) {
  return profile == HidProfile::DualShock4 ? 37 : profile == HidProfile::DualSense ? 41 : 0;
}

bool parse_calibration(HidProfile profile, const std::uint8_t* d, std::size_t size, MotionCalibration& out) {
  const std::size_t need = calibration_report_size(profile);
  if (need == 0 || size < need || d[0] != calibration_report_id(profile)) return false;
  // USB word order: gyro bias pitch/yaw/roll; pitch +/-, yaw +/-, roll +/-;
  // gyro speed +/-; accel x +/-, y +/-, z +/-.
  const int bias[3] = {le16s(d + 1), le16s(d + 3), le16s(d + 5)};
  const int plus[3] = {le16s(d + 7), le16s(d + 11), le16s(d + 15)};
  const int minus[3] = {le16s(d + 9), le16s(d + 13), le16s(d + 17)};
  const int speed = le16s(d + 19) + le16s(d + 21);
  MotionCalibration c;
  for (int i = 0; i < 3; ++i) {
    // The kernel's hid-playstation: the gyro's bias is not subtracted, its
    // scale is the speed over the measured span; a zero span keeps the default.
    const int span = std::abs(plus[i] - bias[i]) + std::abs(minus[i] - bias[i]);
    if (span != 0) c.gyro_scale[i] = double(speed) / double(span);
    const int ap = le16s(d + 23 + 4 * i), am = le16s(d + 25 + 4 * i);
    const int range = ap - am;  // counts for 2 g
    if (range != 0) {
      c.accel_bias[i] = double(ap - range / 2);
      c.accel_scale[i] = 2.0 / double(range);
    }
  }
  c.valid = true;
  out = c;
  return true;
}

DecodeResult decode_hid_report(HidProfile profile, const std::uint8_t* d, std::size_t size,
                               const MotionCalibration& calibration, HidInput& s) {
  if (size < 1) return DecodeResult::Malformed;
  const std::uint8_t id = d[0];
  switch (profile) {
    case HidProfile::SpaceMouseSplit:
      if ((id == 1 || id == 2) && size == 7) {
        for (int i = 0; i < 3; ++i) s.puck[(id - 1) * 3 + i] = le16s(d + 1 + 2 * i);
        return DecodeResult::Decoded;
      }
      if (id == 3 && size == 3) {
        s.buttons = std::uint32_t(d[1] | (d[2] << 8)) & 0x3u;
        return DecodeResult::Decoded;
      }
      return DecodeResult::Malformed;
    case HidProfile::SpaceMouseCombined:
      if (id == 1 && size == 13) {
        for (int i = 0; i < 6; ++i) s.puck[i] = le16s(d + 1 + 2 * i);
        return DecodeResult::Decoded;
      }
      if (id == 3 && size == 3) {
        s.buttons = std::uint32_t(d[1] | (d[2] << 8)) & 0x3u;
        return DecodeResult::Decoded;
      }
      if (id == 0x17 && size == 3) {
        s.battery = std::min<int>(d[1], 100);
        return DecodeResult::Ignored;
      }
      return DecodeResult::Malformed;
    case HidProfile::DualShock4:
      if (id != 1 || size != 64) return DecodeResult::Malformed;
      for (int i = 0; i < 4; ++i) s.stick[i] = d[1 + i];
      s.hat = d[5] & 0x0f;
      s.pad_buttons = pad_buttons(d[5], d[6], d[7]);
      s.trigger[0] = d[8], s.trigger[1] = d[9];
      for (int i = 0; i < 3; ++i)
        s.gyro_raw[i] = le16s(d + 13 + 2 * i), s.accel_raw[i] = le16s(d + 19 + 2 * i);
      s.battery = std::min((d[30] & 0x0f) * 10 + 5, 100);
      calibrate(calibration, s);
      return DecodeResult::Decoded;
    case HidProfile::DualSense:
      if (id != 1 || size != 64) return DecodeResult::Malformed;
      for (int i = 0; i < 4; ++i) s.stick[i] = d[1 + i];
      s.trigger[0] = d[5], s.trigger[1] = d[6];
      s.hat = d[8] & 0x0f;
      s.pad_buttons = pad_buttons(d[8], d[9], d[10]);
      for (int i = 0; i < 3; ++i)
        s.gyro_raw[i] = le16s(d + 16 + 2 * i), s.accel_raw[i] = le16s(d + 22 + 2 * i);
      s.battery = std::min((d[53] & 0x0f) * 10 + 5, 100);
      calibrate(calibration, s);
      return DecodeResult::Decoded;
    case HidProfile::PidJoystick:  // decoded from their descriptor (hid_device.cpp)
    case HidProfile::PidWheel:
    case HidProfile::None:
      break;
  }
  return DecodeResult::Malformed;
}

HidAxes hid_axes(HidProfile profile, const HidInput& s) {
  HidAxes a;
  if (profile == HidProfile::SpaceMouseSplit || profile == HidProfile::SpaceMouseCombined) {
    // The puck reports x right, y towards the user, z down (pressed), and
    // rotations about those: into x right, y up, z towards the user.
    a.axis[0] = puck(s.puck[0]), a.axis[1] = -puck(s.puck[2]), a.axis[2] = puck(s.puck[1]);
    a.axis[3] = puck(s.puck[3]), a.axis[4] = -puck(s.puck[5]), a.axis[5] = puck(s.puck[4]);
    a.recentre = (s.buttons & 0x1u) != 0;
  } else if (profile == HidProfile::DualShock4 || profile == HidProfile::DualSense) {
    // Left stick: x and z (down = towards the user); R2 up, L2 down; right
    // stick: nose up with the stick up, yaw right with it right; L1/R1 roll
    // left/right. Options re-centres.
    a.axis[0] = stick(s.stick[0]);
    a.axis[1] = (double(s.trigger[1]) - double(s.trigger[0])) / 255.0;
    a.axis[2] = stick(s.stick[1]);
    a.axis[3] = -stick(s.stick[3]);
    a.axis[4] = -stick(s.stick[2]);
    a.axis[5] = ((s.pad_buttons >> 4) & 1u ? 1.0 : 0.0) - ((s.pad_buttons >> 5) & 1u ? 1.0 : 0.0);
    a.recentre = ((s.pad_buttons >> 9) & 1u) != 0;
  }
  return a;
}

}  // namespace prox::devices
