// The flight recorder through the C API (proxBody_GetHapticTrace): what it
// holds is what the device was handed, tick by tick, consecutive, from the
// running loop and after a stop; off by default; misuse refused by name.
#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "expect.h"
#include "two_cubes.h"

#include <atomic>
#include <cstring>
#include <memory>
#include <vector>

namespace {

using capi_test::at;
using capi_test::length;
using capi_test::wait_until;

// A device of the application's own: a fixed pose, and every wrench it is
// handed kept in order (storage reserved up front: the haptic thread must
// not allocate).
struct RecordingDevice {
  static constexpr int kMax = 1 << 20;
  proxPose pose = at(0.103);
  std::unique_ptr<proxWrench[]> wrenches{new proxWrench[kMax]};
  std::atomic<int> writes{0};
  static proxBool read(void* user, proxPose* pose) {
    *pose = static_cast<RecordingDevice*>(user)->pose;
    return 1;
  }
  static void write(void* user, const proxWrench* w) {
    auto* self = static_cast<RecordingDevice*>(user);
    const int n = self->writes.load(std::memory_order_relaxed);
    if (n < kMax) self->wrenches[n] = *w;
    self->writes.store(n + 1, std::memory_order_release);
  }
  proxDeviceDef def() {
    proxDeviceDef d = proxDefaultDeviceDef();
    d.readPose = &read;
    d.writeWrench = &write;
    d.userData = this;
    return d;
  }
};

// The tool held 3 mm from the wall (inside the 10 mm cutoff).
class Trace : public capi_test::TwoCubes {
 protected:
  void SetUp() override {
    ASSERT_NO_FATAL_FAILURE(create_scene(0.103));
    const proxDeviceDef d = device.def();
    ASSERT_OK(proxBody_SetDevice(tool, &d));
  }
  RecordingDevice device;
};

TEST_F(Trace, IsOffByDefault) {
  const proxThreadsDef def = proxDefaultThreadsDef();
  EXPECT_EQ(def.traceCapacity, 0);
  proxHapticSample s[4];
  int32_t count = -1;
  EXPECT_OK(proxBody_GetHapticTrace(tool, s, 4, &count));
  EXPECT_EQ(count, 0) << "the threads never ran";
  ASSERT_OK(proxWorld_StartThreads(world, &def));
  ASSERT_TRUE(wait_until([&] { return device.writes.load() > 50; }));
  EXPECT_OK(proxBody_GetHapticTrace(tool, s, 4, &count));
  EXPECT_EQ(count, 0) << "recorder off";
}

TEST_F(Trace, HoldsWhatTheDeviceWasHandedTickByTick) {
  proxThreadsDef def = proxDefaultThreadsDef();
  def.traceCapacity = 512;
  ASSERT_OK(proxWorld_StartThreads(world, &def));
  // Closed on what is measured: enough ticks to wrap the ring, and the
  // contact's force reached.
  ASSERT_TRUE(wait_until([&] {
    const int n = device.writes.load(std::memory_order_acquire);
    return n > 1200 && length(device.wrenches[n - 1].force) > 0.0;
  }));
  std::vector<proxHapticSample> trace(600);
  int32_t count = 0;
  ASSERT_OK(proxBody_GetHapticTrace(tool, trace.data(), 600, &count));
  // While the loop runs a reader as slow as a sanitizer's may lose the
  // oldest few to the writer; after the stop below the ring is read whole.
  ASSERT_GT(count, 0);
  ASSERT_LE(count, 512) << "at most its capacity, however many are asked for";
  // Every sample is what the device got at that tick: tick k is its k-th write.
  auto expect_the_devices = [&](int n) {
    const int written = device.writes.load(std::memory_order_acquire);
    for (int i = 0; i < n; ++i) {
      const proxHapticSample& s = trace[std::size_t(i)];
      SCOPED_TRACE(s.tick);
      if (i > 0) {
        ASSERT_EQ(s.tick, trace[std::size_t(i) - 1].tick + 1) << "consecutive ticks";
        ASSERT_GT(s.time, trace[std::size_t(i) - 1].time);
      }
      ASSERT_LT(s.tick, static_cast<uint64_t>(written));
      const proxWrench& w = device.wrenches[s.tick];
      ASSERT_EQ(std::memcmp(&s.force, &w.force, sizeof w.force), 0);
      ASSERT_EQ(std::memcmp(&s.torque, &w.torque, sizeof w.torque), 0);
      ASSERT_EQ((s.flags & PROX_HAPTIC_CLIPPED) != 0, w.clipped != 0);
      EXPECT_EQ(s.devicePose.position.x, 0.103);
      EXPECT_EQ(s.proxyPose.position.x, 0.103) << "a free tool's force is rendered at the device pose";
      EXPECT_NEAR(s.devicePose.rotation.w, 1.0, 1e-15);
    }
  };
  expect_the_devices(count);
  const proxHapticSample& newest = trace[std::size_t(count) - 1];
  EXPECT_GT(newest.contactCount, 0);
  EXPECT_NEAR(newest.closestDistance, 0.003, 1e-9);
  EXPECT_EQ(newest.flags & (PROX_HAPTIC_FADED | PROX_HAPTIC_STALE | PROX_HAPTIC_NO_POSE), 0u);
  EXPECT_GT(length(newest.force), 0.0);

  // After a stop: the last run's ticks, ending with the fade-out, at zero.
  ASSERT_OK(proxWorld_StopThreads(world));
  ASSERT_OK(proxBody_GetHapticTrace(tool, trace.data(), 512, &count));
  ASSERT_EQ(count, 512);
  expect_the_devices(count);
  const proxHapticSample& last = trace[511];
  EXPECT_EQ(length(last.force), 0.0);
  EXPECT_NE(last.flags & PROX_HAPTIC_STOPPING, 0u);
  EXPECT_NE(last.flags & PROX_HAPTIC_FADED, 0u);
  EXPECT_EQ(last.tick + 1, static_cast<uint64_t>(device.writes.load())) << "every write recorded";
  int stopping = 0;
  for (int i = 0; i < count; ++i) stopping += (trace[std::size_t(i)].flags & PROX_HAPTIC_STOPPING) != 0;
  EXPECT_GT(stopping, 1) << "the force faded over several ticks, each recorded";
}

TEST_F(Trace, MisuseIsRefusedByName) {
  proxHapticSample s[2];
  int32_t count = 0;
  EXPECT_FAILS(proxBody_GetHapticTrace(tool, s, -1, &count), PROX_ERROR_INVALID_ARGUMENT, "capacity");
  EXPECT_FAILS(proxBody_GetHapticTrace(tool, nullptr, 2, &count), PROX_ERROR_INVALID_ARGUMENT, "samples");
  EXPECT_FAILS(proxBody_GetHapticTrace(tool, s, 2, nullptr), PROX_ERROR_INVALID_ARGUMENT, "count");
  EXPECT_FAILS(proxBody_GetHapticTrace(wall, s, 2, &count), PROX_ERROR_INVALID_ARGUMENT, "tool");
  EXPECT_FAILS(proxBody_GetHapticTrace(proxBodyId{}, s, 2, &count), PROX_ERROR_INVALID_HANDLE, "null id");
  proxThreadsDef def = proxDefaultThreadsDef();
  for (const int32_t bad : {-1, (1 << 20) + 1}) {
    def.traceCapacity = bad;
    EXPECT_FAILS(proxWorld_StartThreads(world, &def), PROX_ERROR_INVALID_ARGUMENT, "trace capacity");
  }
}

}  // namespace
