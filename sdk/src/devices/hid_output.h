// What a device is sent back (docs/devices.md#hid-devices): the rendered
// force as rumble, the DualSense's right-trigger resistance, the light bar's
// colour, the puck's LED. Pure: the device thread writes what these build.
#pragma once

#include "devices/hid_profiles.h"

#include <cstddef>
#include <cstdint>

namespace prox::devices {

struct OutputSettings {
  double rumble_force = 3.0;   // N for full rumble
  double trigger_force = 3.0;  // N for full trigger resistance
};

struct OutputReport {
  std::uint8_t bytes[64] = {};
  std::size_t size = 0;  // 0: the profile has no output
  bool operator==(const OutputReport& o) const;
  bool operator!=(const OutputReport& o) const { return !(*this == o); }
};

// The output report for a force of `force` N (its magnitude; finite, >= 0).
// At 0 it is the rest report: motors off, trigger effect off, light bar
// green, LED off.
OutputReport build_output(HidProfile profile, double force, const OutputSettings& settings);

// The strength in 0..255 of `force` against `full`.
std::uint8_t output_level(double force, double full);

}  // namespace prox::devices
