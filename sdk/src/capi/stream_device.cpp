// The streamed device. PushPose and GetWrench may be called from any
// thread and must neither lock nor allocate, so they cannot go through the
// world registry (its mutex, its game-thread check): streamed devices live in
// a fixed table of their own. A caller announces itself in a slot's user
// count before it checks the slot's owner; a world being destroyed clears
// the owner first and then waits for the users to leave, so no call ever
// touches a device that is gone.
#include "capi/builtin_device.h"
#include "capi/common.h"

#include "runtime/stream_device.h"

#include <atomic>

using namespace prox;
using namespace prox::capi;

namespace {

constexpr std::uint32_t kMaxStreamDevices = 1024;

struct StreamSlot {
  std::atomic<std::uint64_t> owner{0};  // world_key() of the world that owns it; 0: free
  std::atomic<std::uint32_t> users{0};  // calls using the device right now
  std::atomic<runtime::StreamDevice*> device{nullptr};
  std::atomic<bool> pushing{false};  // a PushPose is under way (one pusher at a time)
};

StreamSlot g_slots[kMaxStreamDevices];
std::mutex g_slots_mutex;  // creation and release, on game threads only

// A device in use for the length of one call.
class DeviceUse {
 public:
  explicit DeviceUse(proxStreamDeviceId id) {
    if (id.index1 == 0) fail(PROX_ERROR_INVALID_HANDLE, "device is a null id");
    if (id.index1 > kMaxStreamDevices || id.world.index1 == 0)
      fail(PROX_ERROR_INVALID_HANDLE, "device does not name a streamed device");
    StreamSlot& slot = g_slots[id.index1 - 1];
    slot.users.fetch_add(1);
    if (slot.owner.load() != world_key(id.world)) {
      slot.users.fetch_sub(1);
      fail(PROX_ERROR_INVALID_HANDLE,
           "device does not name a live streamed device (its world was destroyed, or it was never created)");
    }
    slot_ = &slot;
    device_ = slot.device.load();
  }
  ~DeviceUse() { slot_->users.fetch_sub(1); }
  DeviceUse(const DeviceUse&) = delete;
  DeviceUse& operator=(const DeviceUse&) = delete;

  runtime::StreamDevice& device() const { return *device_; }
  StreamSlot& slot() const { return *slot_; }

 private:
  StreamSlot* slot_ = nullptr;
  runtime::StreamDevice* device_ = nullptr;
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

namespace prox::capi {

void release_stream_devices(proxWorldId world) {
  const std::uint64_t key = world_key(world);
  std::lock_guard<std::mutex> lock(g_slots_mutex);
  for (StreamSlot& slot : g_slots) {
    if (slot.owner.load() != key) continue;
    slot.owner.store(0);
    while (slot.users.load() != 0) std::this_thread::yield();
    slot.device.store(nullptr);
  }
}

}  // namespace prox::capi

extern "C" {

double proxGetTime(void) { return runtime::stream_clock(); }

proxStreamDeviceDef proxDefaultStreamDeviceDef(void) {
  const runtime::StreamSettings s;
  proxStreamDeviceDef d{};
  d.mode = PROX_STREAM_INTERPOLATE;
  d.delay = s.delay;
  d.maxExtrapolation = s.max_extrapolation;
  d.staleAfter = s.stale_after;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateStreamDevice(proxWorldId world, const proxStreamDeviceDef* def,
                                        proxStreamDeviceId* device) {
  return guard("proxWorld_CreateStreamDevice", [&] {
    need(device, "device");
    *device = proxStreamDeviceId{};
    runtime::World& w = world_of(world);
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

    std::lock_guard<std::mutex> lock(g_slots_mutex);
    std::uint32_t i = 0;
    while (i < kMaxStreamDevices && (g_slots[i].owner.load() != 0 || g_slots[i].device.load() != nullptr))
      ++i;
    if (i == kMaxStreamDevices)
      fail(PROX_ERROR_CAPACITY, "there are already " + std::to_string(kMaxStreamDevices) +
                                    " streamed devices; destroy a world to free some");
    const std::uint32_t index = w.add_stream_device(std::make_unique<runtime::StreamDevice>(s));
    g_slots[i].device.store(w.stream_device(index));
    g_slots[i].owner.store(world_key(world));
    *device = {i + 1, 0, world};
  });
}

proxResult proxStreamDevice_PushPose(proxStreamDeviceId device, const proxPose* pose, double timeSeconds) {
  return guard("proxStreamDevice_PushPose", [&] {
    const DeviceUse use(device);
    StreamSlot& slot = use.slot();
    if (slot.pushing.exchange(true, std::memory_order_acquire))
      fail(PROX_ERROR_WRONG_THREAD,
           "another thread is pushing to this device at the same time (one at a time)");
    // Released on every way out, so the next pusher (on any thread) sees
    // this one's writes.
    struct Done {
      StreamSlot& slot;
      ~Done() { slot.pushing.store(false, std::memory_order_release); }
    } done{slot};
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
    const DeviceUse use(device);
    const runtime::DeviceWrench w = use.device().wrench();
    *wrench = {
        {w.force[0], w.force[1], w.force[2]}, {w.torque[0], w.torque[1], w.torque[2]}, w.limited ? 1 : 0};
  });
}

proxResult proxStreamDevice_GetDeviceDef(proxStreamDeviceId device, proxDeviceDef* def) {
  return guard("proxStreamDevice_GetDeviceDef", [&] {
    need(def, "def");
    world_of(device.world, "device's world");
    const DeviceUse use(device);
    *def = BuiltinDevice<runtime::StreamDevice>::def_of(use.device());
  });
}

proxResult proxStreamDevice_GetStats(proxStreamDeviceId device, proxStreamDeviceStats* stats) {
  return guard("proxStreamDevice_GetStats", [&] {
    need(stats, "stats");
    *stats = proxStreamDeviceStats{};
    world_of(device.world, "device's world");
    const DeviceUse use(device);
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

}  // extern "C"
