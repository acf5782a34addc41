// A haptic device as the haptic loop sees it: two plain callbacks and the
// caller's pointer, called from the haptic thread only (docs/threading.md).
#pragma once

#include <memory>

namespace prox::runtime {

struct DevicePose {
  double position[3];
  double rotation[4];  // unit quaternion w, x, y, z
};

struct DeviceWrench {
  double force[3];   // N, world frame
  double torque[3];  // N m, about the tool's reference point, world frame
  bool limited;      // the safety gate changed what the contacts asked for
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
