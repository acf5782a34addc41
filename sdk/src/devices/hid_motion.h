// A rate device's motion (docs/devices.md#hid-devices): each axis past a dead
// zone and through a response curve is a velocity, integrated into the tool's
// pose: the reference point moves at the linear velocity and the tool turns
// about it at the angular velocity, both in the world frame. Exact for
// constant deflection however the time is cut into steps.
#pragma once

#include "devices/hid_profiles.h"

namespace prox::devices {

struct MotionSettings {
  double linear_speed = 0.1;                 // m/s at full deflection
  double angular_speed = 1.0;                // rad/s at full deflection
  double dead_zone = 0.1;                    // fraction of travel
  double exponent = 2.0;                     // response curve
  double device_to_world[4] = {1, 0, 0, 0};  // unit quaternion w, x, y, z
};

// One axis in [-1, 1] after the dead zone and the curve: 0 within the dead
// zone, then the rest of the travel rescaled to [0, 1] and raised to
// `exponent`, with the axis's sign.
double shape_axis(double value, double dead_zone, double exponent);

struct ToolMotion {
  double reference[3] = {0, 0, 0};    // the reference point, world
  double rotation[4] = {1, 0, 0, 0};  // the tool's rotation, w x y z
  double reference_local[3] = {0, 0, 0};

  // Starts at the tool pose (position, rotation) with its reference point
  // in the tool's frame.
  void reset(const double position[3], const double rotation[4], const double reference_local[3]);
  // Moves `seconds` at the velocities the axes give.
  void step(const HidAxes& axes, const MotionSettings& settings, double seconds);
  // Position control (a grounded stick or wheel: its position is the
  // hand's): the tool at `home` with its reference point moved by `offset`
  // and turned by `angle` (rad) about `axis` through it, both in the
  // device's frame (settings.device_to_world takes them to the world's).
  void place(const ToolMotion& home, const MotionSettings& settings, const double offset[3], const double axis[3],
             double angle);
  // The tool's pose: position of its frame's origin, and rotation.
  void pose(double position[3], double rotation[4]) const;
};

}  // namespace prox::devices
