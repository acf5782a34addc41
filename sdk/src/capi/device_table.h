// Every device the C API hands out (scripted, streamed, HID, OpenXR) lives
// in one table: made, found, let go of and released with its world the same
// way whatever its kind. A slot is named by its index and a generation, so a
// destroyed device's id stays invalid when its slot is reused.
//
// Some calls come from any thread and must neither lock nor allocate (a
// streamed device's PushPose and GetWrench, an XR device's stats), so a
// lookup never takes the table's mutex: a caller announces itself in the
// slot's user count before it checks the slot's owner and generation; the
// game thread letting a device go clears the owner first and then waits for
// the users to leave, so no call ever touches a device that is gone.
// Private to sdk/src/capi.
#pragma once

#include "capi/common.h"

#include <atomic>
#include <cstdint>
#include <memory>

namespace prox::capi {

enum class DeviceKind : std::uint32_t { Scripted = 1, Stream = 2, Hid = 3, Xr = 4 };

// At most this many devices of every kind together exist at once.
inline constexpr std::uint32_t kMaxDevices = 4096;

struct DeviceSlot {
  std::uint32_t index1 = 0;  // index + 1; 0: none
  std::uint32_t generation = 0;
};

// A world as one integer, for the slots that name their world.
inline std::uint64_t world_key(proxWorldId w) { return (std::uint64_t(w.index1) << 32) | w.generation; }

// Game thread of `world`: a slot for `device` (PROX_ERROR_CAPACITY when the
// table is full).
DeviceSlot add_device(proxWorldId world, DeviceKind kind, std::shared_ptr<runtime::HapticDevice> device);

// A live device of `kind` in use for the length of one call. Any thread;
// lock-free. `world` null: a kind whose ids do not name their world (XR).
class DeviceUse {
 public:
  DeviceUse(DeviceKind kind, DeviceSlot slot, const proxWorldId* world);
  ~DeviceUse();
  DeviceUse(const DeviceUse&) = delete;
  DeviceUse& operator=(const DeviceUse&) = delete;

  runtime::HapticDevice& device() const { return *device_; }
  // The device as the type its kind is made of.
  template <typename T>
  T& as() const {
    return static_cast<T&>(*device_);
  }
  proxWorldId world() const { return world_; }

 private:
  std::atomic<std::uint32_t>* users_ = nullptr;
  runtime::HapticDevice* device_ = nullptr;
  proxWorldId world_{};
};

// Game thread of the device's world: lets a device go. Its id becomes
// invalid and it is closed (its thread stopped, its effect stopped): a tool
// that holds it has no pose from then on, so its force fades out. The
// object stays until its world goes (device_table.cpp says why).
void destroy_device(DeviceKind kind, DeviceSlot slot, const proxWorldId* world);

// Before `world` is destroyed, with its threads stopped: every device of the
// world is let go of as destroy_device does.
void release_devices(proxWorldId world);

// The def that attaches a device with proxBody_SetDevice.
proxDeviceDef device_def(const DeviceUse& use);

// proxBody_SetDevice's side: the table's device a def from device_def
// names (*direct: both of the def's callbacks are still the table's, so the
// tool may hold the device itself), or null for any other def. Fails when
// that device was destroyed or is of another world than `world`.
std::shared_ptr<runtime::HapticDevice> table_device(const proxDeviceDef& def, proxWorldId world, bool* direct);

}  // namespace prox::capi
