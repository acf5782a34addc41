// The OpenXR device end to end: an app that owns its OpenXR session (through
// Debian's loader and the core validation layer, on the mock runtime) hands
// Proxima its right controller; the scripted grip drives the tool, contact
// comes back as vibration; focus and tracking come and go; devices are
// destroyed in either order; both pose modes, with and without the timespec
// extension.
#include "openxr/xr_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>
#include <tuple>
#include <vector>

using namespace prox::test;

namespace {


void sleep_s(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

// Pose mode x timespec extension.
class XrPoseModes : public ::testing::TestWithParam<std::tuple<proxXrPoseMode, bool>> {};

TEST_P(XrPoseModes, ScriptedGripDrivesTheTool) {
  const auto [mode, timespec] = GetParam();
  XrApp app(XrAppOptions{timespec});
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  scene.hold(scene.far_tool());
  proxXrDeviceDef def = scene.def(app);
  def.poseMode = mode;
  const proxXrDeviceId device = scene.start(app, def);

  // Two places, each held: the tool follows within 1e-6 m (the grip's
  // floats are the only rounding).
  const prox::test::Rigid a =
      scene.far_tool() * Rigid{glm::angleAxis(0.4, glm::dvec3(0, 0, 1)), {0, 0.01, 0}};
  const prox::test::Rigid b =
      scene.far_tool() *
      Rigid{glm::angleAxis(-0.7, glm::normalize(glm::dvec3(1, 1, 0))), {0.05, -0.02, 0.03}};
  for (const Rigid& target : {a, b}) {
    const Rigid expected = scene.follow_to(app, target);
    ASSERT_LT(scene.error(expected), 1e-6) << "the tool is " << scene.error(expected) << " m from the script";
    app.pump_for(0.1);
    EXPECT_LT(scene.error(expected), 1e-6);
  }

  const proxXrDeviceStats s = stats_of(device);
  EXPECT_GT(s.posesPushed, 100u);
  EXPECT_EQ(s.timeFromFrames != 0, !timespec);
  EXPECT_EQ(s.sessionState, XR_SESSION_STATE_FOCUSED);
  // LOCATE_EACH_TICK locates every tick; EXTRAPOLATE_FRAME once a frame (90 Hz).
  if (mode == PROX_XR_LOCATE_EACH_TICK)
    EXPECT_GT(double(s.locates), 0.9 * double(s.ticks - s.untrackedTicks));
  else
    EXPECT_LT(double(s.locates), 0.3 * double(s.ticks));
  EXPECT_GT(mock_control().locateCalls(), 0u);

  prox_check(proxWorld_StopThreads(scene.world), "proxWorld_StopThreads");
  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

INSTANTIATE_TEST_SUITE_P(
    , XrPoseModes,
    ::testing::Combine(::testing::Values(PROX_XR_LOCATE_EACH_TICK, PROX_XR_EXTRAPOLATE_FRAME),
                       ::testing::Bool()),
    [](const auto& p) {
      return std::string(std::get<0>(p.param) == PROX_XR_LOCATE_EACH_TICK ? "EachTick" : "Extrapolate") +
             (std::get<1>(p.param) ? "Timespec" : "FrameTime");
    });

// A grip moving at 0.4 m/s: with "now" from the timespec extension the tool
// is where the script has the grip now, to within a few milliseconds of
// motion, in both modes (EXTRAPOLATE_FRAME predicts from the frame's
// location, which is one or two frames in the future).
class XrMotion : public ::testing::TestWithParam<proxXrPoseMode> {};

TEST_P(XrMotion, ToolFollowsTheMovingGripAtNow) {
  XrApp app(XrAppOptions{true});
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  proxXrDeviceDef def = scene.def(app);
  def.poseMode = GetParam();
  const Rigid from = scene.far_tool();
  const glm::dvec3 travel(0.3, 0.0, 0.0);  // away from the rock: no contact
  const double seconds = 0.75;
  const XrTime t0 = mock_control().now() + 300000000;
  const XrTime t1 = t0 + XrTime(seconds * 1e9);
  const ProxMockXrKey keys[2] = {{t0, to_xr(scene.grip_for(from))},
                                 {t1, to_xr(scene.grip_for({from.q, from.p + travel}))}};
  mock_control().setScript(keys, 2);
  const Rigid start = scene.tool_for(keys[0].pose), end = scene.tool_for(keys[1].pose);
  const proxXrDeviceId device = scene.start(app, def);

  std::vector<double> errors = scene.motion_errors(app, t0, t1, t1 - 100000000, start, end);
  ASSERT_GT(errors.size(), 20u);
  std::sort(errors.begin(), errors.end());
  const double median = errors[errors.size() / 2];
  // 3 mm is 7.5 ms of this motion; a pose from the frame's predicted time
  // without extrapolation is 11-22 ms off (4.4-8.8 mm).
  EXPECT_LT(median, 0.003) << "median " << median << " m behind or ahead of the grip, max " << errors.back();

  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

INSTANTIATE_TEST_SUITE_P(, XrMotion, ::testing::Values(PROX_XR_LOCATE_EACH_TICK, PROX_XR_EXTRAPOLATE_FRAME),
                         [](const auto& p) {
                           return std::string(p.param == PROX_XR_LOCATE_EACH_TICK ? "EachTick"
                                                                                  : "Extrapolate");
                         });

// Contact comes back as vibration at most at vibrationRate, pulses longer
// than the interval, frequency unspecified; it stops when contact ends and
// none is sent while far.
TEST(XrDevice, VibrationWhileInContactOnly) {
  XrApp app;
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  scene.hold(scene.far_tool());
  const proxXrDeviceId device = scene.start(app, scene.def(app));

  app.pump_for(0.3);
  EXPECT_EQ(vibration_count(), 0) << "vibrations while far from anything";
  EXPECT_EQ(scene.force(), 0.0);

  const int32_t before = vibration_count();
  scene.hold(scene.near_tool());
  ASSERT_TRUE(app.pump_until([&] { return scene.force() > 0.0 && vibration_count() > before + 20; }))
      << "force " << scene.force() << " N, " << vibration_count() - before << " vibrations";
  std::vector<ProxMockXrVibration> in_contact = vibrations_since(before);
  for (std::size_t i = 0; i < in_contact.size(); ++i) {
    const ProxMockXrVibration& v = in_contact[i];
    ASSERT_FALSE(v.stop) << "a stop while in contact";
    EXPECT_EQ(v.result, XR_SUCCESS);
    EXPECT_GT(v.amplitude, 0.0f);
    EXPECT_LE(v.amplitude, 1.0f);
    EXPECT_EQ(v.frequency, XR_FREQUENCY_UNSPECIFIED);
    EXPECT_EQ(v.duration, 20000000);  // 20 ms: longer than the 10 ms between sends
    // The device spaces its sends by its own clock; the mock stamps them as
    // they arrive, a scheduling delay later, so one gap may look shorter
    // than 10 ms. Without the limit they would come every tick (1 ms).
    if (i > 0) {
      EXPECT_GE(v.time - in_contact[i - 1].time, 5000000) << "sent faster than 200 Hz";
    }
  }
  // Over the whole contact, at most 100 Hz (5% for the stamps' jitter).
  const double span = double(in_contact.back().time - in_contact.front().time) * 1e-9;
  EXPECT_LE(double(in_contact.size() - 1) / span, 105.0) << in_contact.size() << " sends in " << span << " s";
  // The amplitude is the rendered force over forceForFullAmplitude (1 N).
  const double felt = scene.force();
  EXPECT_NEAR(stats_of(device).lastAmplitude, std::min(1.0, felt), 0.05 + 0.5 * felt);

  scene.hold(scene.far_tool());
  ASSERT_TRUE(app.pump_until([&] {
    const std::vector<ProxMockXrVibration> v = vibrations_since(before);
    return !v.empty() && v.back().stop;
  })) << "no xrStopHapticFeedback after contact ended";
  const int32_t after_stop = vibration_count();
  app.pump_for(0.3);
  EXPECT_EQ(vibration_count(), after_stop) << "vibrations after contact ended";
  EXPECT_EQ(scene.force(), 0.0);
  EXPECT_GE(stats_of(device).stopsSent, 1u);

  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

// Focus goes (the runtime refuses haptics at once; the device counts that,
// then the app forwards the state: no pose, the force fades, no call) and
// comes back.
TEST(XrDevice, FocusLossAndRegain) {
  XrApp app;
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  scene.hold(scene.near_tool());
  const proxXrDeviceId device = scene.start(app, scene.def(app));
  ASSERT_TRUE(app.pump_until([&] { return scene.force() > 0.0 && stats_of(device).vibrationsSent > 5; }));

  mock_control().setFocused(0);
  sleep_s(0.1);  // the app has not polled the change yet: the device still sends, and is refused
  EXPECT_GT(stats_of(device).vibrationsRefused, 0u);
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_VISIBLE; }));
  ASSERT_TRUE(app.pump_until([&] { return scene.force() == 0.0; })) << "the force did not fade without focus";
  const proxXrDeviceStats unfocused = stats_of(device);
  EXPECT_EQ(unfocused.sessionState, XR_SESSION_STATE_VISIBLE);
  const int32_t log = vibration_count();
  const uint64_t locates = mock_control().locateCalls();
  app.pump_for(0.2);
  EXPECT_GT(stats_of(device).notFocusedTicks, unfocused.notFocusedTicks);
  EXPECT_EQ(vibration_count(), log) << "haptic calls while not focused";
  EXPECT_EQ(mock_control().locateCalls(), locates) << "locates while not focused";
  EXPECT_GT(app.syncsNotFocused, 0);

  mock_control().setFocused(1);
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  const uint64_t sent = stats_of(device).vibrationsSent;
  ASSERT_TRUE(app.pump_until([&] {
    return scene.force() > 0.0 && stats_of(device).vibrationsSent > sent + 5;
  })) << "force and vibration did not come back with focus";

  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

// Tracking lost: located without the valid bits, the pose is gone and the
// force fades (and the vibration stops); back when tracking is.
TEST(XrDevice, TrackingLossFadesTheForce) {
  XrApp app;
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  scene.hold(scene.near_tool());
  const proxXrDeviceId device = scene.start(app, scene.def(app));
  ASSERT_TRUE(app.pump_until([&] { return scene.force() > 0.0; }));

  const uint64_t untracked = stats_of(device).untrackedTicks;
  mock_control().setTracked(0);
  ASSERT_TRUE(app.pump_until([&] { return scene.force() == 0.0; })) << "the force did not fade";
  EXPECT_GT(stats_of(device).untrackedTicks, untracked + 10);
  ASSERT_TRUE(app.pump_until([&] {
    const std::vector<ProxMockXrVibration> v = vibrations_since(0);
    return !v.empty() && v.back().stop;
  })) << "the vibration did not stop";
  proxSafetyStats safety;
  prox_check(proxWorld_GetSafetyStats(scene.world, &safety), "proxWorld_GetSafetyStats");

  mock_control().setTracked(1);
  ASSERT_TRUE(app.pump_until([&] { return scene.force() > 0.0; })) << "the force did not come back";

  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

// A runtime reporting a non-finite pose with its valid bits set: the device
// treats it as untracked, and no NaN reaches the tool or the force.
TEST(XrDevice, NonFinitePoseNeverReachesTheTool) {
  XrApp app;
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  scene.hold(scene.near_tool());
  const proxXrDeviceId device = scene.start(app, scene.def(app));
  ASSERT_TRUE(app.pump_until([&] { return scene.force() > 0.0; }));

  ProxMockXrKey key{mock_control().now(), to_xr(scene.grip_for(scene.near_tool()))};
  key.pose.position.y = std::numeric_limits<float>::quiet_NaN();
  mock_control().setScript(&key, 1);
  const uint64_t untracked = stats_of(device).untrackedTicks;
  ASSERT_TRUE(app.pump_until([&] { return scene.force() == 0.0; })) << "the force did not fade";
  EXPECT_GT(stats_of(device).untrackedTicks, untracked + 10);
  const proxPose p = scene.tool_pose();
  EXPECT_TRUE(std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z));
  EXPECT_TRUE(std::isfinite(scene.force()));

  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

// Destroyed while the haptic loop and the app's frame loop run: no OpenXR
// call after it returns, the tool's force fades, the id is dead; then the app
// tears its session down cleanly.
TEST(XrDevice, DestroyWhileRunning) {
  XrApp app;
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  scene.hold(scene.near_tool());
  const proxXrDeviceId device = scene.start(app, scene.def(app));
  ASSERT_TRUE(app.pump_until([&] { return scene.force() > 0.0 && vibration_count() > 3; }));

  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.set_device({});
  const uint64_t locates = mock_control().locateCalls();
  const int32_t log = vibration_count();
  ASSERT_TRUE(app.pump_until([&] { return scene.force() == 0.0; })) << "the force did not fade";
  app.pump_for(0.1);
  EXPECT_EQ(mock_control().locateCalls(), locates) << "located after destroy";
  EXPECT_EQ(vibration_count(), log) << "haptics after destroy";
  EXPECT_TRUE(vibrations_since(0).back().stop) << "the playing vibration was not stopped";
  proxXrDeviceStats s;
  EXPECT_EQ(proxXrDevice_GetStats(device, &s), PROX_ERROR_INVALID_HANDLE);
  EXPECT_EQ(proxXrDevice_Destroy(device), PROX_ERROR_INVALID_HANDLE);

  app.exit_session();
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

// The world goes first: its XR device goes with it (its thread stopped, its
// action space destroyed), so the app may end the session right after.
TEST(XrDevice, WorldDestroyedFirst) {
  XrApp app;
  proxXrDeviceId device{};
  {
    XrScene scene;
    ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
    scene.hold(scene.near_tool());
    device = scene.start(app, scene.def(app));
    ASSERT_TRUE(app.pump_until([&] { return scene.force() > 0.0; }));
  }
  EXPECT_FALSE(proxXrDevice_IsValid(device));
  app.set_device({});  // the app forwards frames to it no more
  proxXrDeviceStats s;
  EXPECT_EQ(proxXrDevice_GetStats(device, &s), PROX_ERROR_INVALID_HANDLE);
  EXPECT_EQ(proxXrDevice_Destroy(device), PROX_ERROR_INVALID_HANDLE);
  const uint64_t locates = mock_control().locateCalls();
  app.pump_for(0.2);
  EXPECT_EQ(mock_control().locateCalls(), locates) << "located after its world was destroyed";
  app.exit_session();
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

// The session stops under the device: the app forwards STOPPING and the
// device makes no call before the app ends and destroys the session.
TEST(XrDevice, SessionStopping) {
  XrApp app;
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  scene.hold(scene.near_tool());
  const proxXrDeviceId device = scene.start(app, scene.def(app));
  ASSERT_TRUE(app.pump_until([&] { return scene.force() > 0.0; }));
  app.exit_session();
  EXPECT_EQ(stats_of(device).sessionState, XR_SESSION_STATE_EXITING);
  const uint64_t locates = mock_control().locateCalls();
  sleep_s(0.1);
  EXPECT_EQ(mock_control().locateCalls(), locates);
  ASSERT_TRUE(app.pump_until([&] { return scene.force() == 0.0; }));
  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

}  // namespace
