#include "capi/device_table.h"

#include <algorithm>
#include <string>
#include <vector>

namespace prox::capi {
namespace {

struct Slot {
  std::atomic<std::uint64_t> owner{0};  // world_key() of its world; 0: free, or being let go
  std::atomic<std::uint32_t> users{0};  // calls using the device right now
  std::atomic<std::uint32_t> generation{0};
  std::atomic<std::uint32_t> kind{0};
  std::atomic<runtime::HapticDevice*> raw{nullptr};
  // Written under g_mutex while the slot has no owner and no users; read by
  // users once they have seen the owner.
  proxWorldId world{};
  std::shared_ptr<runtime::HapticDevice> device;
};

// A device let go of, kept (closed) until its world goes: an application
// may have wrapped its def's callbacks in its own, which then read "no
// pose" from it rather than freed memory.
struct Retired {
  std::uint64_t world = 0;
  DeviceKind kind{};
  std::shared_ptr<runtime::HapticDevice> device;
};

Slot g_slots[kMaxDevices];
std::vector<Retired> g_retired;
std::mutex g_mutex;  // adding and letting go of, on game threads only

const char* kind_name(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::Scripted:
      return "scripted device";
    case DeviceKind::Stream:
      return "streamed device";
    case DeviceKind::Hid:
      return "HID device";
    case DeviceKind::Xr:
      return "XR device";
  }
  return "device";
}

// Under g_mutex, with the owner cleared: waits for the calls under way to
// leave, then empties the slot and hands back its device.
std::shared_ptr<runtime::HapticDevice> empty(Slot& slot) {
  while (slot.users.load() != 0) std::this_thread::yield();
  slot.raw.store(nullptr);
  slot.world = proxWorldId{};
  return std::move(slot.device);
}

// The table's callbacks: every device kind behind one pair.
proxBool read_pose(void* user, proxPose* pose) {
  runtime::DevicePose p{};
  if (!static_cast<runtime::HapticDevice*>(user)->read_pose(&p)) return 0;
  *pose = {{p.position[0], p.position[1], p.position[2]},
           {p.rotation[0], p.rotation[1], p.rotation[2], p.rotation[3]}};
  return 1;
}

void write_wrench(void* user, const proxWrench* w) {
  static_cast<runtime::HapticDevice*>(user)->write_wrench(device_wrench_of(*w));
}

}  // namespace

DeviceSlot add_device(proxWorldId world, DeviceKind kind, std::shared_ptr<runtime::HapticDevice> device) {
  std::lock_guard<std::mutex> lock(g_mutex);
  std::uint32_t i = 0;
  while (i < kMaxDevices && (g_slots[i].owner.load() != 0 || g_slots[i].device)) ++i;
  if (i == kMaxDevices)
    fail(PROX_ERROR_CAPACITY, "there are already " + std::to_string(kMaxDevices) +
                                  " devices; destroy one (or a world) to free a slot");
  Slot& slot = g_slots[i];
  std::uint32_t generation = slot.generation.load() + 1;
  if (generation == 0) generation = 1;  // an id of zeros never names a device
  slot.generation.store(generation);
  slot.kind.store(std::uint32_t(kind));
  slot.world = world;
  slot.raw.store(device.get());
  slot.device = std::move(device);
  slot.owner.store(world_key(world));  // published: lookups may find it from here on
  return {i + 1, generation};
}

DeviceUse::DeviceUse(DeviceKind kind, DeviceSlot id, const proxWorldId* world) {
  if (id.index1 == 0) fail(PROX_ERROR_INVALID_HANDLE, "device is a null id");
  const char* name = kind_name(kind);
  if (id.index1 > kMaxDevices || (world && world->index1 == 0))
    fail(PROX_ERROR_INVALID_HANDLE, std::string("device does not name a ") + name);
  Slot& slot = g_slots[id.index1 - 1];
  slot.users.fetch_add(1);
  const std::uint64_t owner = slot.owner.load();
  if (owner == 0 || (world && owner != world_key(*world)) || slot.generation.load() != id.generation ||
      slot.kind.load() != std::uint32_t(kind)) {
    slot.users.fetch_sub(1);
    fail(PROX_ERROR_INVALID_HANDLE, std::string("device does not name a live ") + name +
                                        " (destroyed or closed, its world destroyed, or never created)");
  }
  users_ = &slot.users;
  device_ = slot.raw.load();
  world_ = slot.world;
}

DeviceUse::~DeviceUse() { users_->fetch_sub(1); }

void destroy_device(DeviceKind kind, DeviceSlot id, const proxWorldId* world) {
  proxWorldId owner{};
  {
    const DeviceUse use(kind, id, world);
    owner = use.world();
  }
  world_of(owner, "device's world");  // its game thread only
  std::shared_ptr<runtime::HapticDevice> gone;
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    Slot& slot = g_slots[id.index1 - 1];
    // Only the world's game thread lets its devices go, so the slot is as
    // the lookup above saw it.
    slot.owner.store(0);
    gone = empty(slot);
    g_retired.push_back({world_key(owner), kind, gone});
  }
  gone->close();  // outside the lock: it may join the device's thread
}

void release_devices(proxWorldId world) {
  const std::uint64_t key = world_key(world);
  std::vector<std::shared_ptr<runtime::HapticDevice>> gone;
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    for (Slot& slot : g_slots) {
      if (slot.owner.load() != key) continue;
      slot.owner.store(0);
      gone.push_back(empty(slot));
    }
    for (Retired& r : g_retired)
      if (r.world == key) gone.push_back(std::move(r.device));
    g_retired.erase(std::remove_if(g_retired.begin(), g_retired.end(), [](const Retired& r) { return !r.device; }),
                    g_retired.end());
  }
  for (const auto& d : gone) d->close();
}

proxDeviceDef device_def(const DeviceUse& use) {
  proxDeviceDef def = proxDefaultDeviceDef();
  def.readPose = &read_pose;
  def.writeWrench = &write_wrench;
  def.userData = &use.device();
  const runtime::DeviceLimits limits = use.device().limits();
  def.maxStiffness = limits.max_stiffness;
  def.damping = limits.damping;
  return def;
}

std::shared_ptr<runtime::HapticDevice> table_device(const proxDeviceDef& def, proxWorldId world, bool* direct) {
  *direct = false;
  if (def.readPose != &read_pose) return nullptr;
  std::lock_guard<std::mutex> lock(g_mutex);
  for (const Slot& slot : g_slots) {
    if (slot.owner.load() == 0 || slot.raw.load() != def.userData) continue;
    if (slot.owner.load() != world_key(world))
      fail(PROX_ERROR_INVALID_ARGUMENT,
           "def is a device of another world (a device can hold only its own world's tools)");
    *direct = def.writeWrench == &write_wrench;
    return slot.device;
  }
  for (const Retired& r : g_retired)
    if (r.device.get() == def.userData)
      fail(PROX_ERROR_INVALID_ARGUMENT, std::string("def is a ") + kind_name(r.kind) +
                                            " that was destroyed or closed (or one of another world)");
  fail(PROX_ERROR_INVALID_ARGUMENT, "def reads through a device of Proxima's that does not exist");
}

}  // namespace prox::capi
