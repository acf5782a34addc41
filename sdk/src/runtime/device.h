// A haptic device as the runtime sees it: an object that reads the tool's
// pose and takes the wrench, called from the haptic thread only
// (docs/threading.md).
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

// What a device renders stably at the haptic rate (CHAI3D's
// cHapticDeviceInfo): the stiffest contact and the damping it needs.
struct DeviceLimits {
  double max_stiffness = 0.0;  // N/m; 0: no limit
  double damping = 0.0;        // N s/m
};

// Every device a tool can hold implements this: Proxima's own (scripted,
// streamed, HID, OpenXR) and the application's callbacks alike. The runtime
// holds the device itself; nothing is recognised by its callbacks.
class HapticDevice {
 public:
  virtual ~HapticDevice() = default;
  // Haptic thread (no lock, no allocation, no system call): fills *pose and
  // returns true, or returns false when the device has no pose this tick
  // (the force then fades out).
  virtual bool read_pose(DevicePose* pose) = 0;
  // Haptic thread, as read_pose: the wrench to render. The default is a
  // device that only moves.
  virtual void write_wrench(const DeviceWrench& wrench) { (void)wrench; }
  // Any thread: what the device declared it renders stably (none by
  // default). Read when a tool takes the device.
  virtual DeviceLimits limits() const { return {}; }
  // Game thread: stops what the device runs of its own (a thread, an
  // effect on the hardware); from then on it has no pose. Called when its
  // owner lets it go (its id destroyed, its world destroyed); idempotent.
  virtual void close() {}
};

// What a tool holds. Shared, so that a device its owner lets go of lives
// on until the threads have let go of the tool too: the last holder is the
// game thread (the threads free retired tools there), never the haptic one.
struct Device {
  std::shared_ptr<HapticDevice> impl;

  bool attached() const { return impl != nullptr; }
  HapticDevice* operator->() const { return impl.get(); }
  // A device its caller keeps alive for as long as any tool holds it
  // (tests and benchmarks that own theirs on the stack).
  static Device borrowed(HapticDevice& device) {
    return {std::shared_ptr<HapticDevice>(std::shared_ptr<void>(), &device)};
  }
};

}  // namespace prox::runtime
