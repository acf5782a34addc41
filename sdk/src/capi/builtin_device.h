// Proxima's own devices (scripted, streamed, HID) seen through the C API's
// device callbacks. Each device type gets one pair of trampolines, so a def
// that Proxima made is known by its callbacks: proxBody_SetDevice checks
// that such a device belongs to the tool's world, and a def as Proxima made
// it (both callbacks its own) is held by the tool directly, so the haptic
// loop hands it the whole DeviceWrench (the closest distance too, which
// proxWrench does not carry). Private to sdk/src/capi.
#pragma once

#include "capi/common.h"

namespace prox::capi {

// A world as one integer, for the device tables that name their world.
inline std::uint64_t world_key(proxWorldId w) { return (std::uint64_t(w.index1) << 32) | w.generation; }

// D has read_pose(runtime::DevicePose*) -> bool, write_wrench(const
// runtime::DeviceWrench&) and device() -> runtime::Device. The trampolines
// run on the haptic thread: no allocation, no lock.
template <typename D>
struct BuiltinDevice {
  static proxBool read(void* user, proxPose* pose) {
    runtime::DevicePose p{};
    if (!static_cast<D*>(user)->read_pose(&p)) return 0;
    *pose = {{p.position[0], p.position[1], p.position[2]},
             {p.rotation[0], p.rotation[1], p.rotation[2], p.rotation[3]}};
    return 1;
  }
  static void write(void* user, const proxWrench* w) {
    static_cast<D*>(user)->write_wrench(device_wrench_of(*w));
  }

  // The def that attaches `device` with proxBody_SetDevice.
  static proxDeviceDef def_of(D& device) {
    proxDeviceDef def = proxDefaultDeviceDef();
    def.readPose = &read;
    def.writeWrench = &write;
    def.userData = &device;
    return def;
  }
  // Whether the def reads through this type's trampoline, so that its
  // userData is taken for a D (whatever its writeWrench is).
  static bool claims(const proxDeviceDef& def) { return def.readPose == &read; }
  // The device of a def exactly as def_of made it, else null.
  static D* of(const proxDeviceDef& def) {
    return def.readPose == &read && def.writeWrench == &write ? static_cast<D*>(def.userData) : nullptr;
  }
};

}  // namespace prox::capi
