// The OpenXR device's C API refusing bad input, each refusal naming what is
// wrong; and a check that the validation layer really is on (else the other
// tests' "no validation error" would hold vacuously).
#include "openxr/xr_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <thread>

using namespace prox::test;

namespace {

// The call fails with `code` and the last error mentions `words`.
#define EXPECT_REFUSED(call, code, words)                                            \
  do {                                                                               \
    const proxResult r_ = (call);                                                    \
    EXPECT_EQ(r_, code) << #call;                                                    \
    EXPECT_NE(std::string(proxGetLastError()).find(words), std::string::npos)        \
        << #call << ": \"" << proxGetLastError() << "\" does not mention " << words; \
  } while (0)

TEST(XrValidationLayer, IsOnAndReportsMisuse) {
  XrApp app;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  XrSpaceLocation location{};
  location.type = XR_TYPE_UNKNOWN;  // wrong on purpose
  EXPECT_EQ(xrLocateSpace(app.local, app.local, 1000, &location), XR_ERROR_VALIDATION_FAILURE);
  app.destroy();
  EXPECT_NE(validation_errors(app), "") << "the core validation layer raised nothing: is it enabled?";
}

TEST(XrDeviceMisuse, BadDefsAreRefused) {
  XrApp app(XrAppOptions{false});
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  proxXrDeviceId device{};
  const proxXrDeviceDef good = scene.def(app);
  proxXrDeviceDef d = good;

  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, nullptr, &device), PROX_ERROR_INVALID_ARGUMENT, "def");
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, nullptr), PROX_ERROR_INVALID_ARGUMENT, "device");
  EXPECT_REFUSED(proxWorld_CreateXrDevice(proxWorldId{}, &d, &device), PROX_ERROR_INVALID_HANDLE, "world");
  d = {};
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "proxDefaultXrDeviceDef");
  d = good, d.apiVersion = PROX_API_VERSION + 1;  // made by a newer minor version's header
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_VERSION_MISMATCH,
                 "proxDefaultXrDeviceDef");
  d = good, d.getInstanceProcAddr = nullptr;
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "getInstanceProcAddr");
  d = good, d.session = XR_NULL_HANDLE;
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "def->session");
  d = good, d.baseSpace = XR_NULL_HANDLE;
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "def->baseSpace");
  d = good, d.poseAction = XR_NULL_HANDLE;
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "def->poseAction");
  d = good, d.toolInGrip.position.y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "def->toolInGrip");
  d = good, d.baseToWorld.rotation = {0, 0, 0, 0};
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "def->baseToWorld.rotation is a zero quaternion");
  d = good, d.poseMode = static_cast<proxXrPoseMode>(7);
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "def->poseMode");
  d = good, d.vibrationRate = 0.0;
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "def->vibrationRate");
  d = good, d.forceForFullAmplitude = -1.0;
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "def->forceForFullAmplitude");
  d = good, d.tickRate = 1.0;
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "def->tickRate");
  d = good, d.runtimeTime = -5;
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "def->runtimeTime");
#if !defined(_WIN32)
  d = good, d.win32PerformanceCounterTime = 1;
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "Windows only");
#endif
  // A vibration action where a pose action belongs: the runtime refuses the space.
  d = good, d.poseAction = app.haptic;
  EXPECT_REFUSED(proxWorld_CreateXrDevice(scene.world, &d, &device), PROX_ERROR_INVALID_ARGUMENT,
                 "xrCreateActionSpace");
  EXPECT_EQ(device.index1, 0u);

  // From another thread than the world's.
  std::thread([&] {
    proxXrDeviceId other{};
    EXPECT_EQ(proxWorld_CreateXrDevice(scene.world, &good, &other), PROX_ERROR_WRONG_THREAD);
  }).join();
  app.destroy();
}

TEST(XrDeviceMisuse, BadIdsAndCallsAreRefused) {
  XrApp app;
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  proxXrDeviceStats stats;
  proxDeviceDef dd;
  EXPECT_REFUSED(proxXrDevice_GetStats(proxXrDeviceId{}, &stats), PROX_ERROR_INVALID_HANDLE, "null id");
  EXPECT_REFUSED(proxXrDevice_OnFrame(proxXrDeviceId{5, 1}, 1, 1), PROX_ERROR_INVALID_HANDLE,
                 "live XR device");
  EXPECT_REFUSED(proxXrDevice_OnRuntimeTime(proxXrDeviceId{}, 1), PROX_ERROR_INVALID_HANDLE, "null id");

  proxXrDeviceId device{};
  const proxXrDeviceDef d = scene.def(app);
  prox_check(proxWorld_CreateXrDevice(scene.world, &d, &device), "proxWorld_CreateXrDevice");
  EXPECT_REFUSED(proxXrDevice_GetStats(device, nullptr), PROX_ERROR_INVALID_ARGUMENT, "stats");
  EXPECT_REFUSED(proxXrDevice_GetDeviceDef(device, nullptr), PROX_ERROR_INVALID_ARGUMENT, "def");
  EXPECT_REFUSED(proxXrDevice_OnFrame(device, 0, 1), PROX_ERROR_INVALID_ARGUMENT, "predictedDisplayTime");
  EXPECT_REFUSED(proxXrDevice_OnRuntimeTime(device, 0), PROX_ERROR_INVALID_ARGUMENT, "time must be > 0");
  EXPECT_REFUSED(proxXrDevice_OnSessionState(device, static_cast<XrSessionState>(99)),
                 PROX_ERROR_INVALID_ARGUMENT, "XrSessionState");
  std::thread([&] {
    EXPECT_EQ(proxXrDevice_OnFrame(device, 1, 1), PROX_ERROR_WRONG_THREAD);
    EXPECT_EQ(proxXrDevice_OnRuntimeTime(device, 1), PROX_ERROR_WRONG_THREAD);
    EXPECT_EQ(proxXrDevice_Destroy(device), PROX_ERROR_WRONG_THREAD);
    proxXrDeviceStats s;
    EXPECT_EQ(proxXrDevice_GetStats(device, &s), PROX_SUCCESS);  // any thread
  }).join();
  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  EXPECT_REFUSED(proxXrDevice_GetDeviceDef(device, &dd), PROX_ERROR_INVALID_HANDLE, "live XR device");
  EXPECT_REFUSED(proxXrDevice_OnSessionState(device, XR_SESSION_STATE_FOCUSED), PROX_ERROR_INVALID_HANDLE,
                 "live XR device");
  // A new device in the freed slot does not answer to the old id.
  proxXrDeviceId again{};
  prox_check(proxWorld_CreateXrDevice(scene.world, &d, &again), "proxWorld_CreateXrDevice");
  EXPECT_EQ(again.index1, device.index1);
  EXPECT_REFUSED(proxXrDevice_GetStats(device, &stats), PROX_ERROR_INVALID_HANDLE, "live XR device");
  prox_check(proxXrDevice_Destroy(again), "proxXrDevice_Destroy");
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

TEST(XrHelpers, ActionsAndBindings) {
  XrApp app;
  XrAction pose = XR_NULL_HANDLE, haptic = XR_NULL_HANDLE;
  // The app's set is attached already: the runtime refuses new actions.
  EXPECT_REFUSED(proxXrCreateActions(xrGetInstanceProcAddr, app.instance, app.set, "late", &pose, &haptic),
                 PROX_ERROR_INVALID_ARGUMENT, "xrCreateAction");
  EXPECT_EQ(pose, XR_NULL_HANDLE);
  EXPECT_REFUSED(
      proxXrCreateActions(xrGetInstanceProcAddr, app.instance, app.set, "Bad Name", &pose, &haptic),
      PROX_ERROR_INVALID_ARGUMENT, "namePrefix");
  EXPECT_REFUSED(proxXrCreateActions(nullptr, app.instance, app.set, "p", &pose, &haptic),
                 PROX_ERROR_INVALID_ARGUMENT, "gipa");

  XrActionSuggestedBinding b[2];
  int32_t count = -1;
  EXPECT_REFUSED(
      proxXrGetSuggestedBindings(xrGetInstanceProcAddr, app.instance, "/interaction_profiles/acme/glove",
                                 "right", app.pose, app.haptic, b, 2, &count),
      PROX_ERROR_UNSUPPORTED, "/interaction_profiles/acme/glove");
  EXPECT_REFUSED(proxXrGetSuggestedBindings(xrGetInstanceProcAddr, app.instance,
                                            "/interaction_profiles/khr/simple_controller", "middle", app.pose,
                                            app.haptic, b, 2, &count),
                 PROX_ERROR_INVALID_ARGUMENT, "hand");
  EXPECT_REFUSED(proxXrGetSuggestedBindings(xrGetInstanceProcAddr, app.instance,
                                            "/interaction_profiles/khr/simple_controller", "left", app.pose,
                                            app.haptic, b, 1, &count),
                 PROX_ERROR_CAPACITY, "2 are needed");
  EXPECT_EQ(count, 2);
  // The paths a profile's spec names for the grip and the haptic output.
  ASSERT_EQ(proxXrGetSuggestedBindings(xrGetInstanceProcAddr, app.instance,
                                       "/interaction_profiles/valve/index_controller", "left", app.pose,
                                       app.haptic, b, 2, &count),
            PROX_SUCCESS);
  ASSERT_EQ(count, 2);
  char path[XR_MAX_PATH_LENGTH];
  uint32_t n = 0;
  xr_check(xrPathToString(app.instance, b[0].binding, sizeof path, &n, path), "xrPathToString");
  EXPECT_STREQ(path, "/user/hand/left/input/grip/pose");
  EXPECT_EQ(b[0].action, app.pose);
  xr_check(xrPathToString(app.instance, b[1].binding, sizeof path, &n, path), "xrPathToString");
  EXPECT_STREQ(path, "/user/hand/left/output/haptic");
  // The hand's path names it too.
  ASSERT_EQ(proxXrGetSuggestedBindings(xrGetInstanceProcAddr, app.instance,
                                       "/interaction_profiles/khr/simple_controller", "/user/hand/right",
                                       app.pose, app.haptic, b, 2, &count),
            PROX_SUCCESS);
  xr_check(xrPathToString(app.instance, b[0].binding, sizeof path, &n, path), "xrPathToString");
  EXPECT_STREQ(path, "/user/hand/right/input/grip/pose");
  // A profile without a haptic output gets the pose only.
  ASSERT_EQ(proxXrGetSuggestedBindings(xrGetInstanceProcAddr, app.instance,
                                       "/interaction_profiles/oculus/go_controller", "right", app.pose,
                                       app.haptic, b, 2, &count),
            PROX_SUCCESS);
  EXPECT_EQ(count, 1);
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

}  // namespace
