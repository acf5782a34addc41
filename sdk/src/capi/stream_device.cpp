// The streamed device. PushPose and GetWrench may be called from any
// thread and must neither lock nor allocate, so they go through the device
// table's lock-free lookup (device_table.h), never the world registry (its
// mutex, its game-thread check).
#include "capi/common.h"
#include "capi/device_table.h"

#include "runtime/stream_device.h"

using namespace prox;
using namespace prox::capi;

namespace {

constexpr DeviceKind kStream = DeviceKind::Stream;

DeviceSlot slot_of(proxStreamDeviceId id) { return {id.index1, id.reserved}; }

// A streamed device in use for the length of one call.
struct StreamUse : DeviceUse {
  explicit StreamUse(const proxStreamDeviceId& id) : DeviceUse(kStream, slot_of(id), &id.world) {}
  runtime::StreamDevice& device() const { return as<runtime::StreamDevice>(); }
};

bool finite3(double a, double b, double c) {
  return std::isfinite(a) && std::isfinite(b) && std::isfinite(c);
}

// Checks a pushed sample without building strings on the way (PushPose must
// not allocate); the message is only made for a refusal.
void check_sample(const proxPose& pose, double time, runtime::StreamSample& out) {
  const proxQuat& q = pose.rotation;
  if (!finite3(pose.position.x, pose.position.y, pose.position.z))
    fail(PROX_ERROR_INVALID_ARGUMENT, "pose->position is not finite");
  if (!(finite3(q.w, q.x, q.y) && std::isfinite(q.z)))
    fail(PROX_ERROR_INVALID_ARGUMENT, "pose->rotation is not finite");
  double unit[4] = {q.w, q.x, q.y, q.z};
  if (!normalize_quaternion(unit)) fail(PROX_ERROR_INVALID_ARGUMENT, "pose->rotation is a zero quaternion");
  if (!(std::isfinite(time) && time >= 0.0))
    fail(PROX_ERROR_INVALID_ARGUMENT, "timeSeconds must be finite and >= 0 (on proxGetTime's clock)");
  out.time = time;
  out.position[0] = pose.position.x, out.position[1] = pose.position.y, out.position[2] = pose.position.z;
  for (int i = 0; i < 4; ++i) out.rotation[i] = unit[i];
}

}  // namespace

extern "C" {

double proxGetTime(void) { return runtime::stream_clock(); }

proxStreamDeviceDef proxDefaultStreamDeviceDef(void) {
  const runtime::StreamSettings s;
  proxStreamDeviceDef d{};
  d.mode = PROX_STREAM_INTERPOLATE;
  d.delay = s.delay;
  d.maxExtrapolation = s.max_extrapolation;
  d.staleAfter = s.stale_after;
  d.apiVersion = PROX_API_VERSION;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateStreamDevice(proxWorldId world, const proxStreamDeviceDef* def,
                                        proxStreamDeviceId* device) {
  return guard("proxWorld_CreateStreamDevice", [&] {
    need(device, "device");
    *device = proxStreamDeviceId{};
    world_of(world);
    need(def, "def");
    need_def(*def, "proxDefaultStreamDeviceDef");
    runtime::StreamSettings s;
    switch (enum_value(def->mode)) {
      case PROX_STREAM_HOLD:
        s.mode = runtime::StreamMode::Hold;
        break;
      case PROX_STREAM_INTERPOLATE:
        s.mode = runtime::StreamMode::Interpolate;
        break;
      case PROX_STREAM_EXTRAPOLATE:
        s.mode = runtime::StreamMode::Extrapolate;
        break;
      default:
        fail(PROX_ERROR_INVALID_ARGUMENT, "def->mode is not a proxStreamMode");
    }
    need_finite(def->delay, "def->delay");
    if (def->delay < 0.0) fail(PROX_ERROR_INVALID_ARGUMENT, "def->delay must be >= 0 s");
    need_finite(def->maxExtrapolation, "def->maxExtrapolation");
    if (def->maxExtrapolation < 0.0)
      fail(PROX_ERROR_INVALID_ARGUMENT, "def->maxExtrapolation must be >= 0 s");
    need_positive(def->staleAfter, "def->staleAfter");
    s.delay = def->delay;
    s.max_extrapolation = def->maxExtrapolation;
    s.stale_after = def->staleAfter;
    need_non_negative(def->maxStiffness, "def->maxStiffness");
    need_non_negative(def->damping, "def->damping");
    s.limits = {def->maxStiffness, def->damping};

    const DeviceSlot slot = add_device(world, kStream, std::make_shared<runtime::StreamDevice>(s));
    *device = {slot.index1, slot.generation, world};
  });
}

proxResult proxStreamDevice_PushPose(proxStreamDeviceId device, const proxPose* pose, double timeSeconds) {
  return guard("proxStreamDevice_PushPose", [&] {
    const StreamUse use(device);
    runtime::StreamDevice& d = use.device();
    if (!d.begin_push())
      fail(PROX_ERROR_WRONG_THREAD,
           "another thread is pushing to this device at the same time (one at a time)");
    // Ended on every way out, so the next pusher (on any thread) sees this
    // one's writes.
    struct Done {
      runtime::StreamDevice& d;
      ~Done() { d.end_push(); }
    } done{d};
    if (!pose) {
      use.device().count_refused();
      fail(PROX_ERROR_INVALID_ARGUMENT, "pose is NULL");
    }
    runtime::StreamSample sample;
    try {
      check_sample(*pose, timeSeconds, sample);
    } catch (const Failure&) {
      use.device().count_refused();
      throw;
    }
    use.device().push(sample);
  });
}

proxResult proxStreamDevice_GetWrench(proxStreamDeviceId device, proxWrench* wrench) {
  return guard("proxStreamDevice_GetWrench", [&] {
    need(wrench, "wrench");
    const StreamUse use(device);
    const runtime::DeviceWrench w = use.device().wrench();
    *wrench = {
        {w.force[0], w.force[1], w.force[2]}, {w.torque[0], w.torque[1], w.torque[2]}, w.limited ? 1 : 0};
  });
}

proxResult proxStreamDevice_GetDeviceDef(proxStreamDeviceId device, proxDeviceDef* def) {
  return guard("proxStreamDevice_GetDeviceDef", [&] {
    need(def, "def");
    world_of(device.world, "device's world");
    const StreamUse use(device);
    *def = device_def(use);
  });
}

proxResult proxStreamDevice_GetStats(proxStreamDeviceId device, proxStreamDeviceStats* stats) {
  return guard("proxStreamDevice_GetStats", [&] {
    need(stats, "stats");
    *stats = proxStreamDeviceStats{};
    world_of(device.world, "device's world");
    const StreamUse use(device);
    const runtime::StreamStats s = use.device().stats();
    stats->samplesPushed = s.pushed;
    stats->samplesDropped = s.dropped;
    stats->samplesRefused = s.refused;
    stats->reads = s.reads;
    stats->staleTicks = s.stale_ticks;
    stats->extrapolatedTicks = s.extrapolated_ticks;
    stats->meanSampleInterval = s.mean_interval;
    stats->maxSampleInterval = s.max_interval;
    stats->maxExtrapolation = s.max_extrapolation;
    stats->lastSampleAge = s.last_sample_age;
  });
}

proxResult proxStreamDevice_Destroy(proxStreamDeviceId device) {
  return guard("proxStreamDevice_Destroy", [&] { destroy_device(kStream, slot_of(device), &device.world); });
}

proxBool proxStreamDevice_IsValid(proxStreamDeviceId device) {
  return valid("proxStreamDevice_IsValid", [&] { StreamUse use(device); });
}

}  // extern "C"
