// A device's declared limits (proxDeviceDef.maxStiffness, damping) through
// the C API, with real threads: an application's device that moves its
// tool into the wall a fixed step a tick is handed a force that grows by no
// more than the stiffness it declared per metre moved, tick by tick in the
// flight recorder; the same motion without the limit feels the curve's far
// stiffer contact (so the check can fail); a bad limit is refused by name.
#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "expect.h"
#include "two_cubes.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

namespace {

using capi_test::length;
using capi_test::wait_until;

// Moves the tool from x = 0.11 towards the wall by 10 um each haptic tick
// (10 mm/s), stopping 6 mm from it, where the contacts' force is about
// half the world's maximum.
struct ApproachingDevice {
  static constexpr double kStart = 0.11, kStep = 1e-5, kStop = 0.106;
  std::atomic<long> reads{0};
  static proxBool read(void* user, proxPose* pose) {
    auto* self = static_cast<ApproachingDevice*>(user);
    const long n = self->reads.fetch_add(1, std::memory_order_relaxed);
    *pose = capi_test::at(std::max(kStop, kStart - kStep * double(n)));
    return 1;
  }
  static void write(void*, const proxWrench*) {}
  proxDeviceDef def(double max_stiffness) {
    proxDeviceDef d = proxDefaultDeviceDef();
    d.readPose = &read;
    d.writeWrench = &write;
    d.userData = this;
    d.maxStiffness = max_stiffness;
    return d;
  }
};

class DeviceLimits : public capi_test::TwoCubes {
 protected:
  void SetUp() override { ASSERT_NO_FATAL_FAILURE(create_scene(ApproachingDevice::kStart)); }

  // Runs the approach and returns the recorded ticks once the tool is held
  // at its stop and its force no longer changes.
  std::vector<proxHapticSample> approach(double max_stiffness) {
    ApproachingDevice device;
    const proxDeviceDef d = device.def(max_stiffness);
    EXPECT_OK(proxBody_SetDevice(tool, &d));
    proxThreadsDef td = proxDefaultThreadsDef();
    td.traceCapacity = 1 << 14;
    EXPECT_OK(proxWorld_StartThreads(world, &td));
    const long held = long((ApproachingDevice::kStart - ApproachingDevice::kStop) / ApproachingDevice::kStep) + 300;
    EXPECT_TRUE(wait_until([&] { return device.reads.load() > held; }));
    std::vector<proxHapticSample> trace(1 << 14);
    int32_t count = 0;
    EXPECT_OK(proxBody_GetHapticTrace(tool, trace.data(), int32_t(trace.size()), &count));
    EXPECT_OK(proxWorld_StopThreads(world));
    EXPECT_OK(proxBody_SetDevice(tool, nullptr));
    trace.resize(std::size_t(count));
    return trace;
  }

  // The largest growth of the force's size per metre the tool moved, over
  // consecutive ticks that moved it.
  static double steepest(const std::vector<proxHapticSample>& t, double* final_force) {
    double worst = 0.0;
    for (std::size_t i = 1; i < t.size(); ++i) {
      if (t[i].tick != t[i - 1].tick + 1) continue;
      const double moved = std::fabs(t[i].devicePose.position.x - t[i - 1].devicePose.position.x);
      const double grew = length(t[i].force) - length(t[i - 1].force);
      if (moved > 0.0 && grew > 0.0) worst = std::max(worst, grew / moved);
    }
    *final_force = t.empty() ? 0.0 : length(t.back().force);
    return worst;
  }
};

}  // namespace

TEST_F(DeviceLimits, TheForceGrowsNoStifferThanTheDeviceDeclared) {
  // Unlimited, the contact at 10 mm/s stiffens well past 100 N/m.
  double free_force = 0.0;
  const double curve = steepest(approach(0.0), &free_force);
  ASSERT_GT(free_force, 0.5) << "the approach ends in contact";
  EXPECT_GT(curve, 300.0) << "the force curve is stiffer than the limit below: the check could not fail";
  // Limited to 100 N/m: each tick's growth is within 100 N/m times its motion.
  double limited_force = 0.0;
  const double limited = steepest(approach(100.0), &limited_force);
  EXPECT_LE(limited, 100.0 * (1.0 + 1e-9));
  EXPECT_GT(limited, 50.0) << "the limit binds, it does not switch the force off";
  // Held, the hand feels the device's spring, not the curve's: at most 100
  // N/m times the 4 mm the tool moved.
  EXPECT_LE(limited_force, 100.0 * (ApproachingDevice::kStart - ApproachingDevice::kStop) + 1e-9);
  EXPECT_LT(limited_force, free_force);
}

TEST_F(DeviceLimits, BadLimitsAreRefusedByName) {
  ApproachingDevice device;
  proxDeviceDef d = device.def(-1.0);
  EXPECT_FAILS(proxBody_SetDevice(tool, &d), PROX_ERROR_INVALID_ARGUMENT, "maxStiffness");
  d = device.def(NAN);
  EXPECT_FAILS(proxBody_SetDevice(tool, &d), PROX_ERROR_INVALID_ARGUMENT, "maxStiffness");
  d = device.def(100.0);
  d.damping = -2.0;
  EXPECT_FAILS(proxBody_SetDevice(tool, &d), PROX_ERROR_INVALID_ARGUMENT, "damping");
  d.damping = 2.0;
  EXPECT_OK(proxBody_SetDevice(tool, &d));
}

// Each kind declares its own: an application's device in its def, a
// streamed device (an engine's hand, perhaps on a grounded device) in its
// def, a HID device in its def (hid_pid_device_test.cpp); a scripted path
// has none. A built-in device's def hands its limits back, and the tool
// that takes the def as it came reads them from the device.
TEST_F(DeviceLimits, EveryKindOfDeviceDeclaresItsOwn) {
  proxStreamDeviceDef sd = proxDefaultStreamDeviceDef();
  EXPECT_EQ(sd.maxStiffness, 0.0);
  EXPECT_EQ(sd.damping, 0.0);
  proxStreamDeviceId stream{};
  sd.maxStiffness = -1.0;
  EXPECT_FAILS(proxWorld_CreateStreamDevice(world, &sd, &stream), PROX_ERROR_INVALID_ARGUMENT, "maxStiffness");
  sd.maxStiffness = 250.0;
  sd.damping = 0.5;
  ASSERT_OK(proxWorld_CreateStreamDevice(world, &sd, &stream));
  proxDeviceDef d{};
  ASSERT_OK(proxStreamDevice_GetDeviceDef(stream, &d));
  EXPECT_EQ(d.maxStiffness, 250.0);
  EXPECT_EQ(d.damping, 0.5);
  EXPECT_OK(proxBody_SetDevice(tool, &d));
  const proxPose path = capi_test::at(0.2);
  proxScriptedDeviceDef scd = proxDefaultScriptedDeviceDef();
  scd.poses = &path;
  scd.poseCount = 1;
  proxScriptedDeviceId scripted{};
  ASSERT_OK(proxWorld_CreateScriptedDevice(world, &scd, &scripted));
  ASSERT_OK(proxScriptedDevice_GetDeviceDef(scripted, &d));
  EXPECT_EQ(d.maxStiffness, 0.0);
  EXPECT_EQ(proxDefaultDeviceDef().maxStiffness, 0.0);
}
