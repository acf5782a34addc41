// HID devices through hidapi (proxima_hid.h), in the device table as
// every device is (device_table.h): proxHidDevice_Destroy lets the tool go,
// stops the device's thread and closes it.
#include "capi/common.h"
#include "capi/device_table.h"

#include <proxima/proxima_hid.h>

#include "devices/hid_device.h"

using namespace prox;
using namespace prox::capi;

namespace {

constexpr DeviceKind kHid = DeviceKind::Hid;

DeviceSlot slot_of(proxHidDeviceId id) { return {id.index1, id.reserved}; }

// A HID device in use for the length of one call, from its world's game
// thread.
struct HidUse : DeviceUse {
  explicit HidUse(const proxHidDeviceId& id) : DeviceUse(kHid, slot_of(id), &id.world) {}
  devices::HidDevice& device() const { return as<devices::HidDevice>(); }
};

void copy(char* out, std::size_t capacity, const std::string& s) {
  const std::size_t n = std::min(s.size(), capacity - 1);
  std::memcpy(out, s.data(), n);
  out[n] = '\0';
}

void need_range(double v, double lo, double hi, const char* name) {
  need_finite(v, name);
  if (v < lo || v > hi)
    fail(PROX_ERROR_INVALID_ARGUMENT, std::string(name) + " must be in [" + std::to_string(lo) + ", " +
                                          std::to_string(hi) + "] (it is " + std::to_string(v) + ")");
}

}  // namespace

extern "C" {

proxResult proxEnumerateHidDevices(proxHidDeviceInfo* infos, int32_t capacity, int32_t* count) {
  return guard("proxEnumerateHidDevices", [&] {
    need(count, "count");
    *count = 0;
    if (capacity < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "capacity must be >= 0");
    if (capacity > 0) need(infos, "infos");
    const std::vector<devices::HidFound> found = devices::enumerate_hid_devices();
    *count = int32_t(found.size());
    for (std::size_t i = 0; i < found.size() && i < std::size_t(capacity); ++i) {
      const devices::HidFound& f = found[i];
      proxHidDeviceInfo& o = infos[i];
      o = proxHidDeviceInfo{};
      o.vendorId = f.vendor_id, o.productId = f.product_id;
      o.profile = static_cast<proxHidProfile>(f.profile);
      o.interfaceNumber = f.interface_number;
      o.usagePage = f.usage_page, o.usage = f.usage;
      copy(o.name, sizeof o.name, f.name);
      copy(o.serial, sizeof o.serial, f.serial);
      copy(o.path, sizeof o.path, f.path);
    }
    if (found.size() > std::size_t(capacity))
      fail(PROX_ERROR_CAPACITY,
           std::to_string(found.size()) + " devices are present; capacity is " + std::to_string(capacity));
  });
}

proxHidDeviceDef proxDefaultHidDeviceDef(void) {
  const devices::HidDeviceSettings s;
  proxHidDeviceDef d{};
  d.initialPose.rotation.w = 1.0;
  d.linearSpeed = s.motion.linear_speed;
  d.angularSpeed = s.motion.angular_speed;
  d.deadZone = s.motion.dead_zone;
  d.responseExponent = s.motion.exponent;
  d.deviceToWorld.w = 1.0;
  d.rumbleForce = s.output.rumble_force;
  d.triggerForce = s.output.trigger_force;
  d.outputRate = s.output_rate;
  d.workspace = s.workspace;
  d.maxForce = s.max_force;
  d.apiVersion = PROX_API_VERSION;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateHidDevice(proxWorldId world, const proxHidDeviceDef* def, proxHidDeviceId* device) {
  return guard("proxWorld_CreateHidDevice", [&] {
    need(device, "device");
    *device = proxHidDeviceId{};
    world_of(world);
    need(def, "def");
    need_def(*def, "proxDefaultHidDeviceDef");
    devices::HidDeviceSettings s;
    if (def->path) s.path = def->path;
    s.vendor_id = def->vendorId, s.product_id = def->productId;
    const Pose start = to_pose(def->initialPose, "def->initialPose");
    const glm::dquat q = glm::quat_cast(start.rotation);
    const double rotation[4] = {q.w, q.x, q.y, q.z};
    for (int i = 0; i < 3; ++i) s.initial_position[i] = start.translation[i];
    for (int i = 0; i < 4; ++i) s.initial_rotation[i] = rotation[i];
    const Vec3 ref = to_vec(def->referencePoint, "def->referencePoint");
    for (int i = 0; i < 3; ++i) s.reference_local[i] = ref[i];
    need_range(def->linearSpeed, 0.0, 100.0, "def->linearSpeed");
    need_range(def->angularSpeed, 0.0, 100.0, "def->angularSpeed");
    need_range(def->deadZone, 0.0, 0.9, "def->deadZone");
    need_range(def->responseExponent, 1.0, 5.0, "def->responseExponent");
    need_positive(def->rumbleForce, "def->rumbleForce");
    need_positive(def->triggerForce, "def->triggerForce");
    need_range(def->outputRate, 1e-3, 250.0, "def->outputRate");
    double m[4] = {def->deviceToWorld.w, def->deviceToWorld.x, def->deviceToWorld.y, def->deviceToWorld.z};
    for (const double v : m) need_finite(v, "def->deviceToWorld");
    if (!normalize_quaternion(m))
      fail(PROX_ERROR_INVALID_ARGUMENT, "def->deviceToWorld is a zero quaternion");
    s.motion.linear_speed = def->linearSpeed;
    s.motion.angular_speed = def->angularSpeed;
    s.motion.dead_zone = def->deadZone;
    s.motion.exponent = def->responseExponent;
    for (int i = 0; i < 4; ++i) s.motion.device_to_world[i] = m[i];
    s.output.rumble_force = def->rumbleForce;
    s.output.trigger_force = def->triggerForce;
    s.output_rate = def->outputRate;
    need_range(def->workspace, 0.0, 100.0, "def->workspace");
    need_positive(def->maxForce, "def->maxForce");
    const int32_t signs[2] = {def->forceSignX, def->forceSignY};
    for (int k = 0; k < 2; ++k) {
      if (signs[k] < -1 || signs[k] > 1)
        fail(PROX_ERROR_INVALID_ARGUMENT, std::string("def->forceSign") + "XY"[k] + " must be -1, 0 or 1 (it is " +
                                              std::to_string(signs[k]) + ")");
      s.force_sign[k] = signs[k];
    }
    need_non_negative(def->maxStiffness, "def->maxStiffness");
    need_non_negative(def->damping, "def->damping");
    s.limits = {def->maxStiffness, def->damping};
    s.workspace = def->workspace;
    s.max_force = def->maxForce;
    std::string error;
    std::unique_ptr<devices::HidDevice> d = devices::HidDevice::open(s, &error);
    if (!d) fail(PROX_ERROR_FILE, error);
    const DeviceSlot slot = add_device(world, kHid, std::shared_ptr<devices::HidDevice>(std::move(d)));
    *device = {slot.index1, slot.generation, world};
  });
}

proxResult proxHidDevice_GetDeviceDef(proxHidDeviceId device, proxDeviceDef* def) {
  return guard("proxHidDevice_GetDeviceDef", [&] {
    need(def, "def");
    world_of(device.world, "device's world");
    *def = device_def(HidUse(device));
  });
}

proxResult proxHidDevice_GetStats(proxHidDeviceId device, proxHidDeviceStats* stats) {
  return guard("proxHidDevice_GetStats", [&] {
    need(stats, "stats");
    *stats = proxHidDeviceStats{};
    world_of(device.world, "device's world");
    const devices::HidStats s = HidUse(device).device().stats();
    stats->profile = static_cast<proxHidProfile>(s.profile);
    stats->connected = s.connected ? 1 : 0;
    stats->reportsRead = s.reports_read;
    stats->malformed = s.malformed;
    stats->outputsWritten = s.outputs_written;
    stats->failedWrites = s.failed_writes;
    stats->disconnects = s.disconnects;
    stats->reconnects = s.reconnects;
    stats->poseReads = s.pose_reads;
    stats->noPoseTicks = s.no_pose_ticks;
    stats->lastReportAge = s.last_report_age;
    stats->forceUpdates = s.force_updates;
    stats->effectsCreated = s.effects_created;
    stats->lastForceMagnitude = s.last_force_magnitude;
    stats->maxForceMagnitude = s.max_force_magnitude;
    stats->forceEffect = static_cast<proxHidForceEffect>(s.effect);
  });
}

proxResult proxHidDevice_GetPose(proxHidDeviceId device, proxPose* pose) {
  return guard("proxHidDevice_GetPose", [&] {
    need(pose, "pose");
    world_of(device.world, "device's world");
    const runtime::DevicePose p = HidUse(device).device().pose();
    *pose = {{p.position[0], p.position[1], p.position[2]},
             {p.rotation[0], p.rotation[1], p.rotation[2], p.rotation[3]}};
  });
}

proxResult proxHidDevice_Destroy(proxHidDeviceId device) {
  return guard("proxHidDevice_Destroy", [&] { destroy_device(kHid, slot_of(device), &device.world); });
}

proxResult proxWorld_OpenHidDevice(proxWorldId world, const proxHidDeviceDef* def, proxHidDeviceId* device) {
  return proxWorld_CreateHidDevice(world, def, device);
}

proxResult proxHidDevice_Close(proxHidDeviceId device) {
  return guard("proxHidDevice_Close", [&] { destroy_device(kHid, slot_of(device), &device.world); });
}

proxBool proxHidDevice_IsValid(proxHidDeviceId device) {
  return valid("proxHidDevice_IsValid", [&] { HidUse use(device); });
}

}  // extern "C"
