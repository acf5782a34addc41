// Devices: the application's callbacks, and the built-in scripted device.
#include "capi/common.h"
#include "capi/device_table.h"

#include "io/poses.h"
#include "runtime/scripted_device.h"

using namespace prox;
using namespace prox::capi;

namespace {

// The application's callbacks, one more device: converts on the haptic
// thread (no allocation, no lock).
class CallbackDevice final : public runtime::HapticDevice {
 public:
  // `keep`: what the def's userData points to, when the table owns it (a
  // def from a GetDeviceDef whose writeWrench the application replaced).
  CallbackDevice(const proxDeviceDef& def, std::shared_ptr<runtime::HapticDevice> keep)
      : def_(def), keep_(std::move(keep)) {}

  runtime::DeviceLimits limits() const override { return {def_.maxStiffness, def_.damping}; }

  bool read_pose(runtime::DevicePose* out) override {
    proxPose p{};
    if (!def_.readPose(def_.userData, &p)) return false;
    out->position[0] = p.position.x, out->position[1] = p.position.y, out->position[2] = p.position.z;
    out->rotation[0] = p.rotation.w, out->rotation[1] = p.rotation.x, out->rotation[2] = p.rotation.y,
    out->rotation[3] = p.rotation.z;
    return true;
  }
  void write_wrench(const runtime::DeviceWrench& w) override {
    if (!def_.writeWrench) return;
    const proxWrench out{{w.force[0], w.force[1], w.force[2]},
                         {w.torque[0], w.torque[1], w.torque[2]},
                         w.limited ? 1 : 0};
    def_.writeWrench(def_.userData, &out);
  }

 private:
  proxDeviceDef def_;
  std::shared_ptr<runtime::HapticDevice> keep_;
};

constexpr DeviceKind kScripted = DeviceKind::Scripted;

proxScriptedDeviceId add_scripted(proxWorldId world, std::vector<runtime::ScriptedPose> poses,
                                  double seconds_per_pose, bool loop) {
  const DeviceSlot slot = add_device(
      world, kScripted, std::make_shared<runtime::ScriptedDevice>(std::move(poses), seconds_per_pose, loop));
  return {slot.index1, slot.generation, world};
}

DeviceSlot slot_of(proxScriptedDeviceId id) { return {id.index1, id.reserved}; }

}  // namespace

extern "C" {

proxDeviceDef proxDefaultDeviceDef(void) {
  proxDeviceDef d{};
  d.apiVersion = PROX_API_VERSION;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxBody_SetDevice(proxBodyId tool, const proxDeviceDef* def) {
  return guard("proxBody_SetDevice", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = tool_of(tool, w);
    if (!def) {
      w->set_device(h, runtime::Device{});
      return;
    }
    need_def(*def, "proxDefaultDeviceDef");
    if (!def->readPose) fail(PROX_ERROR_INVALID_ARGUMENT, "def->readPose is NULL");
    need_non_negative(def->maxStiffness, "def->maxStiffness");
    need_non_negative(def->damping, "def->damping");
    // A device Proxima made, as it came, is held directly (and is handed
    // the closest distance, which proxWrench does not carry); any other def
    // through its callbacks.
    bool direct = false;
    std::shared_ptr<runtime::HapticDevice> own = table_device(*def, tool.world, &direct);
    if (own) {
      // One device, one hand: a device of Proxima's drives one tool at a time.
      const int holder = w->device_holder(own.get());
      if (holder >= 0 && static_cast<std::uint32_t>(holder) != h.index)
        fail(PROX_ERROR_INVALID_ARGUMENT, "the device already holds another tool (body slot " +
                                              std::to_string(holder) +
                                              "); give that tool another device or NULL first");
    }
    if (direct) {
      w->set_device(h, runtime::Device{std::move(own)});
      return;
    }
    w->set_device(h, runtime::Device{std::make_shared<CallbackDevice>(*def, std::move(own))});
  });
}

proxScriptedDeviceDef proxDefaultScriptedDeviceDef(void) {
  proxScriptedDeviceDef d{};
  d.secondsPerPose = 0.001;
  d.apiVersion = PROX_API_VERSION;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateScriptedDevice(proxWorldId world, const proxScriptedDeviceDef* def,
                                          proxScriptedDeviceId* device) {
  return guard("proxWorld_CreateScriptedDevice", [&] {
    need(device, "device");
    *device = proxScriptedDeviceId{};
    world_of(world);
    need(def, "def");
    need_def(*def, "proxDefaultScriptedDeviceDef");
    if (def->poseCount < 1) fail(PROX_ERROR_INVALID_ARGUMENT, "def->poseCount must be >= 1");
    need(def->poses, "def->poses");
    need_positive(def->secondsPerPose, "def->secondsPerPose");
    std::vector<runtime::ScriptedPose> path(static_cast<std::size_t>(def->poseCount));
    for (int32_t i = 0; i < def->poseCount; ++i)
      path[std::size_t(i)] =
          runtime::ScriptedPose::of(to_pose(def->poses[i], "def->poses[" + std::to_string(i) + "]"));
    *device = add_scripted(world, std::move(path), def->secondsPerPose, def->loop != 0);
  });
}

proxResult proxWorld_LoadScriptedDevice(proxWorldId world, const char* path, double secondsPerPose,
                                        proxBool loop, proxScriptedDeviceId* device) {
  return guard("proxWorld_LoadScriptedDevice", [&] {
    need(device, "device");
    *device = proxScriptedDeviceId{};
    world_of(world);
    need(path, "path");
    need_positive(secondsPerPose, "secondsPerPose");
    std::vector<io::PoseRecord> records;
    check(io::read_poses(path, records));
    std::vector<runtime::ScriptedPose> poses;
    for (const io::PoseRecord& r : records) {
      runtime::ScriptedPose p;
      p.position = Vec3(r.position[0], r.position[1], r.position[2]);
      for (int k = 0; k < 4; ++k) p.rotation[k] = r.rotation[k];
      poses.push_back(p);
    }
    *device = add_scripted(world, std::move(poses), secondsPerPose, loop != 0);
  });
}

proxResult proxScriptedDevice_GetDeviceDef(proxScriptedDeviceId device, proxDeviceDef* def) {
  return guard("proxScriptedDevice_GetDeviceDef", [&] {
    need(def, "def");
    world_of(device.world, "device's world");
    *def = device_def(DeviceUse(kScripted, slot_of(device), &device.world));
  });
}

proxResult proxScriptedDevice_GetRecord(proxScriptedDeviceId device, proxScriptedDeviceRecord* record) {
  return guard("proxScriptedDevice_GetRecord", [&] {
    need(record, "record");
    world_of(device.world, "device's world");
    const runtime::ScriptedRecord r =
        DeviceUse(kScripted, slot_of(device), &device.world).as<runtime::ScriptedDevice>().record();
    *record = proxScriptedDeviceRecord{};
    record->reads = r.reads;
    record->writes = r.writes;
    record->progress = r.progress;
    record->maxForce = r.max_force;
    record->maxTorque = r.max_torque;
    record->maxForceStep = r.max_force_step;
    record->lastForce = to_c(r.last_force);
    record->lastTorque = to_c(r.last_torque);
    record->allFinite = r.finite ? 1 : 0;
  });
}

proxResult proxScriptedDevice_Destroy(proxScriptedDeviceId device) {
  return guard("proxScriptedDevice_Destroy", [&] { destroy_device(kScripted, slot_of(device), &device.world); });
}

proxBool proxScriptedDevice_IsValid(proxScriptedDeviceId device) {
  return valid("proxScriptedDevice_IsValid", [&] { DeviceUse(kScripted, slot_of(device), &device.world); });
}

}  // extern "C"
