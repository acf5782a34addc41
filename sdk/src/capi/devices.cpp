// Devices: the application's callbacks, and the built-in scripted device.
#include "capi/builtin_device.h"
#include "capi/common.h"

#include "io/poses.h"
#include "runtime/stream_device.h"

using namespace prox;
using namespace prox::capi;

namespace {

// A C device behind the runtime's device: converts on the haptic thread
// (no allocation, no lock).
struct DeviceAdapter {
  explicit DeviceAdapter(const proxDeviceDef& d) : def(d) {}
  static bool read(void* user, runtime::DevicePose* out) {
    const auto* self = static_cast<const DeviceAdapter*>(user);
    proxPose p{};
    if (!self->def.readPose(self->def.userData, &p)) return false;
    out->position[0] = p.position.x, out->position[1] = p.position.y, out->position[2] = p.position.z;
    out->rotation[0] = p.rotation.w, out->rotation[1] = p.rotation.x, out->rotation[2] = p.rotation.y,
    out->rotation[3] = p.rotation.z;
    return true;
  }
  static void write(void* user, const runtime::DeviceWrench* w) {
    const auto* self = static_cast<const DeviceAdapter*>(user);
    const proxWrench out{{w->force[0], w->force[1], w->force[2]},
                         {w->torque[0], w->torque[1], w->torque[2]},
                         w->limited ? 1 : 0};
    self->def.writeWrench(self->def.userData, &out);
  }
  proxDeviceDef def;
};

proxScriptedDeviceId add_scripted(proxWorldId world, runtime::World& w,
                                  std::vector<runtime::ScriptedPose> poses, double seconds_per_pose,
                                  bool loop) {
  const std::uint32_t i = w.add_scripted_device(
      std::make_unique<runtime::ScriptedDevice>(std::move(poses), seconds_per_pose, loop));
  return {i + 1, 0, world};
}

runtime::ScriptedDevice& scripted_of(proxScriptedDeviceId id) {
  const runtime::World& w = world_of(id.world, "device's world");
  if (id.index1 == 0) fail(PROX_ERROR_INVALID_HANDLE, "device is a null id");
  runtime::ScriptedDevice* d = w.scripted_device(id.index1 - 1);
  if (!d) fail(PROX_ERROR_INVALID_HANDLE, "device does not name a scripted device of its world");
  return *d;
}

using ScriptedDef = BuiltinDevice<runtime::ScriptedDevice>;

// A def that reads through a built-in device of type D must name one of the
// tool's world (one of another world would be gone while this one still
// calls it); one exactly as Proxima made it sets `out` to that device.
template <typename D>
void take_builtin(const proxDeviceDef& def, const runtime::World& w, runtime::Device& out) {
  if (!BuiltinDevice<D>::claims(def)) return;
  if (!w.owns_device(static_cast<const D*>(def.userData)))
    fail(PROX_ERROR_INVALID_ARGUMENT,
         "def is a built-in device of another world (a device can hold only its own world's tools)");
  if (D* device = BuiltinDevice<D>::of(def)) out = device->device();
}

}  // namespace

extern "C" {

proxDeviceDef proxDefaultDeviceDef(void) {
  proxDeviceDef d{};
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
    // Proxima's own devices, as they came, are held directly (and are
    // handed the closest distance); any other def through its callbacks.
    runtime::Device d;
    take_builtin<runtime::ScriptedDevice>(*def, *w, d);
    take_builtin<runtime::StreamDevice>(*def, *w, d);
#if PROX_WITH_HIDAPI
    hid_device_def(*def, tool.world, d);
#endif
    if (d.attached()) {
      // One device, one hand: a built-in device drives one tool at a time.
      const int holder = w->device_holder(d.user);
      if (holder >= 0 && static_cast<std::uint32_t>(holder) != h.index)
        fail(PROX_ERROR_INVALID_ARGUMENT, "the device already holds another tool (body slot " +
                                              std::to_string(holder) +
                                              "); give that tool another device or NULL first");
      w->set_device(h, d);
      return;
    }
    auto adapter = std::make_shared<DeviceAdapter>(*def);
    d.read_pose = &DeviceAdapter::read;
    d.write_wrench = def->writeWrench ? &DeviceAdapter::write : nullptr;
    d.user = adapter.get();
    d.owner = adapter;
    w->set_device(h, d);
  });
}

proxScriptedDeviceDef proxDefaultScriptedDeviceDef(void) {
  proxScriptedDeviceDef d{};
  d.secondsPerPose = 0.001;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateScriptedDevice(proxWorldId world, const proxScriptedDeviceDef* def,
                                          proxScriptedDeviceId* device) {
  return guard("proxWorld_CreateScriptedDevice", [&] {
    need(device, "device");
    *device = proxScriptedDeviceId{};
    runtime::World& w = world_of(world);
    need(def, "def");
    need_def(*def, "proxDefaultScriptedDeviceDef");
    if (def->poseCount < 1) fail(PROX_ERROR_INVALID_ARGUMENT, "def->poseCount must be >= 1");
    need(def->poses, "def->poses");
    need_positive(def->secondsPerPose, "def->secondsPerPose");
    std::vector<runtime::ScriptedPose> path(static_cast<std::size_t>(def->poseCount));
    for (int32_t i = 0; i < def->poseCount; ++i)
      path[std::size_t(i)] =
          runtime::ScriptedPose::of(to_pose(def->poses[i], "def->poses[" + std::to_string(i) + "]"));
    *device = add_scripted(world, w, std::move(path), def->secondsPerPose, def->loop != 0);
  });
}

proxResult proxWorld_LoadScriptedDevice(proxWorldId world, const char* path, double secondsPerPose,
                                        proxBool loop, proxScriptedDeviceId* device) {
  return guard("proxWorld_LoadScriptedDevice", [&] {
    need(device, "device");
    *device = proxScriptedDeviceId{};
    runtime::World& w = world_of(world);
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
    *device = add_scripted(world, w, std::move(poses), secondsPerPose, loop != 0);
  });
}

proxResult proxScriptedDevice_GetDeviceDef(proxScriptedDeviceId device, proxDeviceDef* def) {
  return guard("proxScriptedDevice_GetDeviceDef", [&] {
    need(def, "def");
    *def = ScriptedDef::def_of(scripted_of(device));
  });
}

proxResult proxScriptedDevice_GetRecord(proxScriptedDeviceId device, proxScriptedDeviceRecord* record) {
  return guard("proxScriptedDevice_GetRecord", [&] {
    need(record, "record");
    const runtime::ScriptedRecord r = scripted_of(device).record();
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

}  // extern "C"
