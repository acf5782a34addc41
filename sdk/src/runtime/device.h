// A haptic device as the haptic loop sees it: two plain callbacks and the
// caller's pointer, called from the haptic thread only (docs/threading.md).
#pragma once

#include <limits>
#include <memory>

namespace prox::runtime {

struct DevicePose {
  double position[3];
  double rotation[4];  // unit quaternion w, x, y, z
};

// No contact: the closest distance of an empty contact set.
inline constexpr double kNoContact = std::numeric_limits<double>::infinity();
// Not known: a wrench that came through the C API's proxWrench, which
// carries no distance.
inline constexpr double kUnknownDistance = std::numeric_limits<double>::quiet_NaN();

struct DeviceWrench {
  double force[3];   // N, world frame
  double torque[3];  // N m, about the tool's reference point, world frame
  bool limited;      // the safety gate changed what the contacts asked for
  // The closest distance of the tool's contact set this tick (m): re-measured
  // at the device pose for a free tool, the proxy's for a constrained one;
  // 0 when pushed through; kNoContact when there is none; the last trusted
  // tick's when the contacts are not trusted this tick; kUnknownDistance
  // when not known.
  double closest_distance = kNoContact;
  // The world's, for a device that maps the distance (m).
  double safety_distance = 0.0, cutoff = 0.0;
};

struct Device {
  // Fills *pose and returns true, or returns false when the device has no
  // pose this tick (the force then fades out).
  bool (*read_pose)(void* user, DevicePose* pose) = nullptr;
  // Receives the wrench to render; may be null (a device that only moves).
  void (*write_wrench)(void* user, const DeviceWrench* wrench) = nullptr;
  void* user = nullptr;
  // Keeps what `user` points to alive while a tool holds the device (set
  // by owners such as the C API's adapters; may be empty).
  std::shared_ptr<void> owner;

  bool attached() const { return read_pose != nullptr; }
};

}  // namespace prox::runtime
