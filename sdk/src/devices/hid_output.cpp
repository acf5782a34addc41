#include "devices/hid_output.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace prox::devices {

bool OutputReport::operator==(const OutputReport& o) const {
  return size == o.size && std::memcmp(bytes, o.bytes, size) == 0;
}

std::uint8_t output_level(double force, double full) {
  if (!(force > 0.0) || !(full > 0.0)) return 0;
  const double t = std::fmin(force / full, 1.0);
  return std::uint8_t(std::lround(t * 255.0));
}

namespace {

std::uint8_t blend(std::uint8_t from, std::uint8_t to, double t) {
  return std::uint8_t(std::lround(double(from) + (double(to) - double(from)) * t));
}

}  // namespace

Rgb light_bar_colour(const OutputInput& in, const OutputSettings& s) {
  const double d = in.closest_distance;
  if (std::isnan(d)) {
    const std::uint8_t level = output_level(in.force, s.rumble_force);
    return {level, std::uint8_t(255 - level), 0};
  }
  if (d <= in.safety_distance) return kContactColour;
  if (!(d < in.cutoff)) return kRestColour;  // beyond the cutoff, or no contact
  // safety < d < cutoff, so the span is positive.
  const double t = (in.cutoff - d) / (in.cutoff - in.safety_distance);
  return {blend(kRestColour.r, kWarningColour.r, t), blend(kRestColour.g, kWarningColour.g, t),
          blend(kRestColour.b, kWarningColour.b, t)};
}

OutputReport build_output(HidProfile profile, double force, const OutputSettings& s) {
  OutputInput in;
  in.force = force;
  in.closest_distance = std::numeric_limits<double>::quiet_NaN();
  return build_output(profile, in, s);
}

OutputReport build_output(HidProfile profile, const OutputInput& in, const OutputSettings& s) {
  OutputReport r;
  const double force = in.force;
  const std::uint8_t rumble = output_level(force, s.rumble_force);
  const Rgb colour = light_bar_colour(in, s);
  const std::uint8_t red = colour.r, green = colour.g, blue = colour.b;
  switch (profile) {
    case HidProfile::DualShock4:
      // Report 0x05 (USB, 32 bytes): flags motors | light bar colour; weak
      // (right) then strong (left) motor; red, green, blue.
      r.size = 32;
      r.bytes[0] = 0x05;
      r.bytes[1] = 0x01 | 0x02;
      r.bytes[4] = rumble;
      r.bytes[5] = rumble;
      r.bytes[6] = red, r.bytes[7] = green, r.bytes[8] = blue;
      break;
    case HidProfile::DualSense: {
      // Report 0x02 (USB, 48 bytes): flags rumble (0x01 | 0x02) and right
      // trigger effect (0x04); light bar colour (flag1 0x04); motors at 3, 4;
      // the right trigger's effect at 11..21; colour at 45..47.
      r.size = 48;
      r.bytes[0] = 0x02;
      r.bytes[1] = 0x01 | 0x02 | 0x04;
      r.bytes[2] = 0x04;
      r.bytes[3] = rumble;
      r.bytes[4] = rumble;
      const std::uint8_t resistance = output_level(force, s.trigger_force);
      if (resistance == 0) {
        r.bytes[11] = 0x05;  // effect off
      } else {
        r.bytes[11] = 0x01;  // constant resistance from position 0 ...
        r.bytes[12] = 0x00;
        r.bytes[13] = resistance;  // ... of this strength
      }
      r.bytes[45] = red, r.bytes[46] = green, r.bytes[47] = blue;
      break;
    }
    case HidProfile::SpaceMouseSplit:
    case HidProfile::SpaceMouseCombined:
      // Report 0x04: the LED, lit while a force is felt.
      r.size = 2;
      r.bytes[0] = 0x04;
      r.bytes[1] = rumble > 0 ? 1 : 0;
      break;
    case HidProfile::PidJoystick:  // a force effect (hid_pid_effect.h), not these outputs
    case HidProfile::PidWheel:
    case HidProfile::None:
      break;
  }
  return r;
}

}  // namespace prox::devices
