// The viewer's HID device (--device hid, docs/devices.md#hid-devices): a
// SpaceMouse, DualShock 4 or DualSense driving the tool through libproxima's
// hidapi devices, when libproxima was built with them.
#pragma once

#include <proxima/proxima.h>

#include <string>

namespace viewer {

// Whether this viewer can drive the tool from a HID device at all.
bool hid_supported();
// Whether a supported HID device is plugged in now (false when unsupported).
bool hid_present();

// Opens the first supported HID device and lets it hold `tool`, which starts
// at `start` and turns about `reference` (its frame). Returns the device's
// id as one integer (0: none); throws std::runtime_error with the library's
// message.
uint64_t attach_hid(proxWorldId world, proxBodyId tool, const proxPose& start, const proxVec3& reference);

// A line about the device: its profile, reports read, outputs written and the
// pose it holds the tool at; empty when `device` is 0.
std::string hid_summary(proxWorldId world, uint64_t device);

}  // namespace viewer
