// What a device is sent back (docs/devices.md#hid-devices): the rendered
// force as rumble, the DualSense's right-trigger resistance, the light bar's
// colour from the closest distance, the puck's LED. Pure: the device thread
// writes what these build.
#pragma once

#include "devices/hid_profiles.h"

#include <cstddef>
#include <cstdint>
#include <limits>

namespace prox::devices {

struct OutputSettings {
  double rumble_force = 3.0;   // N for full rumble
  double trigger_force = 3.0;  // N for full trigger resistance
};

// What the outputs are built from: the rendered force and the closest
// distance of the tool's contacts, with the world's distances to map it.
struct OutputInput {
  double force = 0.0;  // N, the wrench's force magnitude (finite, >= 0)
  // m: +infinity with no contact; NaN when not known (the wrench came
  // through the C callbacks), and the light bar then follows the force.
  double closest_distance = std::numeric_limits<double>::infinity();
  double safety_distance = 0.0, cutoff = 0.0;  // m, the world's
};

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};

// The light bar's colours: at rest (no contact, or none closer than the
// cutoff), the warning colour it blends to from the cutoff in to the safety
// distance, and the contact colour at or inside the safety distance.
inline constexpr Rgb kRestColour{0, 255, 0};
inline constexpr Rgb kWarningColour{255, 160, 0};
inline constexpr Rgb kContactColour{255, 0, 0};

// The light bar's colour for `in` (docs/devices.md#hid-devices): rest at or
// beyond the cutoff; between the cutoff c and the safety distance s, rest
// blended linearly to warning by t = (c - d) / (c - s) (each channel
// rounded); contact at or inside s. A distance not known: from the force,
// red its share of rumble_force (0..255) and green the rest, no blue.
Rgb light_bar_colour(const OutputInput& in, const OutputSettings& settings);

struct OutputReport {
  std::uint8_t bytes[64] = {};
  std::size_t size = 0;  // 0: the profile has no output
  bool operator==(const OutputReport& o) const;
  bool operator!=(const OutputReport& o) const { return !(*this == o); }
};

// The output report for `in`. With no force and no contact it is the rest
// report: motors off, trigger effect off, light bar at rest, LED off.
OutputReport build_output(HidProfile profile, const OutputInput& in, const OutputSettings& settings);
// With only a force (`force` N), the distance not known.
OutputReport build_output(HidProfile profile, double force, const OutputSettings& settings);

// The strength in 0..255 of `force` against `full`.
std::uint8_t output_level(double force, double full);

}  // namespace prox::devices
