// The OpenXR device on the mock runtime taught real runtimes' habits
// (mock_control.h): display times of 0 from an xrWaitFrame that does not
// block, no timespec extension, a session that stays READY, and input and
// haptics that still answer while the session is not focused.
#include "openxr/xr_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

using namespace prox::test;

namespace {


// The strict runtime again for whatever runs next in this process.
struct HabitsReset {
  ~HabitsReset() { mock_control().setHabits(0); }
};

std::string mode_name(proxXrPoseMode m) { return m == PROX_XR_LOCATE_EACH_TICK ? "EachTick" : "Extrapolate"; }

// The tool follows the scripted grip to two held places, within the grip's
// float rounding (the test fails where it does not).
void follows_the_grip(XrApp& app, XrScene& scene) {
  const Rigid a = scene.far_tool() * Rigid{glm::angleAxis(0.4, glm::dvec3(0, 0, 1)), {0, 0.01, 0}};
  const Rigid b = scene.far_tool() * Rigid{glm::angleAxis(-0.7, glm::dvec3(1, 0, 0)), {0.05, -0.02, 0.03}};
  for (const Rigid& target : {a, b}) {
    const Rigid expected = scene.follow_to(app, target);
    ASSERT_LT(scene.error(expected), 1e-6) << "the tool is " << scene.error(expected) << " m from the script";
  }
}

class XrHabitsModes : public ::testing::TestWithParam<proxXrPoseMode> {};

// Monado's headless habit: xrWaitFrame returns at once with display time and
// period 0. The app stops its frame calls and never reports a frame; with
// the timespec extension the device still has "now", in both pose modes
// (PROX_XR_EXTRAPOLATE_FRAME has no frame to locate at, so it locates at
// "now" each tick).
TEST_P(XrHabitsModes, ZeroDisplayTimes) {
  const HabitsReset reset;
  XrApp app(XrAppOptions{true, PROX_MOCK_XR_HABIT_ZERO_DISPLAY_TIME});
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  scene.hold(scene.far_tool());
  app.pump_for(0.05);
  EXPECT_FALSE(app.frameCalls) << "the habit is off: xrWaitFrame gave a display time";
  EXPECT_EQ(mock_control().waitFrameCalls(), 1u) << "the app kept calling xrWaitFrame after a time of 0";
  proxXrDeviceDef def = scene.def(app);
  def.poseMode = GetParam();
  const proxXrDeviceId device = scene.start(app, def);
  follows_the_grip(app, scene);
  const proxXrDeviceStats s = stats_of(device);
  EXPECT_EQ(s.timeSource, PROX_XR_TIME_TIMESPEC);
  EXPECT_EQ(s.timeFromFrames, 0);
  EXPECT_EQ(s.untrackedTicks, 0u) << "ticks without a pose: the runtime's time was there all along";
  EXPECT_GT(s.posesPushed, 0u);
  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

// No time conversion extension and display times of 0: the runtime's only
// time is an event's. The app hands the newest over (advanced by its own
// clock) and the device runs its own monotonic clock from it: a pose on
// every tick from the first, in both modes.
TEST_P(XrHabitsModes, NoClockButTheRuntimesTime) {
  const HabitsReset reset;
  const uint32_t habits = PROX_MOCK_XR_HABIT_ZERO_DISPLAY_TIME | PROX_MOCK_XR_HABIT_NO_TIMESPEC;
  EXPECT_THROW(XrApp(XrAppOptions{true, habits}), std::runtime_error)
      << "the habit is off: XR_KHR_convert_timespec_time could be enabled";
  XrApp app(XrAppOptions{false, habits});
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  ASSERT_GT(app.lastEventTime, 0) << "the mock's events carry no time";
  scene.hold(scene.far_tool());
  proxXrDeviceDef def = scene.def(app);
  def.poseMode = GetParam();
  const proxXrDeviceId device = scene.start(app, def);
  follows_the_grip(app, scene);
  // The device's clock is the runtime's: a grip moving by the script's
  // times puts the tool where the script has it (the motion test's bound).
  const Rigid from = scene.far_tool();
  const XrTime t0 = mock_control().now() + 100000000, t1 = t0 + 500000000;
  const ProxMockXrKey keys[2] = {{t0, to_xr(scene.grip_for(from))},
                                 {t1, to_xr(scene.grip_for({from.q, from.p + glm::dvec3(0.2, 0, 0)}))}};
  mock_control().setScript(keys, 2);
  const Rigid start = scene.tool_for(keys[0].pose), end = scene.tool_for(keys[1].pose);
  std::vector<double> errors = scene.motion_errors(app, t0, t1, t1 - 50000000, start, end);
  ASSERT_GT(errors.size(), 10u);
  std::sort(errors.begin(), errors.end());
  EXPECT_LT(errors[errors.size() / 2], 0.003) << "the device's clock is not the runtime's";

  const proxXrDeviceStats s = stats_of(device);
  EXPECT_EQ(s.timeSource, PROX_XR_TIME_OWN_CLOCK);
  EXPECT_EQ(s.untrackedTicks, 0u) << "ticks without a pose for want of a time";
  EXPECT_GT(s.posesPushed, 0u);
  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

INSTANTIATE_TEST_SUITE_P(, XrHabitsModes, ::testing::Values(PROX_XR_LOCATE_EACH_TICK, PROX_XR_EXTRAPOLATE_FRAME),
                         [](const auto& p) { return mode_name(p.param); });

// Stock Monado's habit: a runtime that still locates the grip and plays
// haptics while the session is not FOCUSED, and does not stop a vibration
// when focus goes. The device's rule holds anyway (docs/openxr.md): not
// focused, no locate and no vibration; and it stops the vibration it
// started, once, when the lost focus is forwarded.
TEST(XrHabits, UnfocusedRuntimeThatStillAnswers) {
  const HabitsReset reset;
  XrApp app(XrAppOptions{true, PROX_MOCK_XR_HABIT_ANSWERS_UNFOCUSED});
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_FOCUSED; }));
  scene.hold(scene.near_tool());
  proxXrDeviceDef def = scene.def(app);
  def.pulseDuration = 0.5;  // a pulse that outlives the focus unless stopped
  const proxXrDeviceId device = scene.start(app, def);
  ASSERT_TRUE(app.pump_until([&] { return scene.force() > 0.0 && stats_of(device).vibrationsSent > 5; }));

  const XrTime lost = mock_control().now();
  mock_control().setFocused(0);
  ASSERT_TRUE(app.pump_until([&] { return app.state == XR_SESSION_STATE_VISIBLE; }));
  ASSERT_TRUE(app.pump_until([&] {
    const std::vector<ProxMockXrVibration> v = vibrations_since(0);
    return !v.empty() && v.back().stop && v.back().time > lost;
  }, 2.0)) << "no xrStopHapticFeedback after focus went: the last pulse plays on";
  EXPECT_EQ(app.syncsNotFocused, 0) << "the habit is off: xrSyncActions said XR_SESSION_NOT_FOCUSED";
  EXPECT_EQ(vibrations_since(0).back().result, XR_SUCCESS) << "the habit is off: the stop was refused";

  // Not focused: no more calls, though the runtime would answer them.
  const int32_t log = vibration_count();
  const uint64_t locates = mock_control().locateCalls();
  const uint64_t not_focused = stats_of(device).notFocusedTicks;
  ASSERT_TRUE(app.pump_until([&] { return stats_of(device).notFocusedTicks > not_focused + 100; }));
  EXPECT_EQ(vibration_count(), log) << "haptic calls while not focused";
  EXPECT_EQ(mock_control().locateCalls(), locates) << "locates while not focused";
  ASSERT_TRUE(app.pump_until([&] { return scene.force() == 0.0; })) << "the force did not fade without focus";

  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

// Stock Monado's other habit: a begun headless session that stays READY.
// A device made in that state (as the app's def says) never locates or
// vibrates, though this runtime would answer, and says where it is.
TEST(XrHabits, SessionThatStaysReady) {
  const HabitsReset reset;
  XrApp app(XrAppOptions{true, PROX_MOCK_XR_HABIT_STAYS_READY | PROX_MOCK_XR_HABIT_ANSWERS_UNFOCUSED});
  XrScene scene;
  ASSERT_TRUE(app.pump_until([&] { return app.running; }));
  app.pump_for(0.2);
  EXPECT_EQ(app.state, XR_SESSION_STATE_READY) << "the habit is off: the session moved on";
  scene.hold(scene.near_tool());
  const proxXrDeviceId device = scene.start(app, scene.def(app));
  const uint64_t locates = mock_control().locateCalls();
  ASSERT_TRUE(app.pump_until([&] { return stats_of(device).ticks > 100; }));
  const proxXrDeviceStats s = stats_of(device);
  EXPECT_EQ(s.sessionState, XR_SESSION_STATE_READY);
  EXPECT_EQ(s.notFocusedTicks, s.ticks);
  EXPECT_EQ(s.posesPushed, 0u);
  EXPECT_EQ(mock_control().locateCalls(), locates);
  EXPECT_EQ(vibration_count(), 0);
  EXPECT_EQ(scene.force(), 0.0);
  prox_check(proxXrDevice_Destroy(device), "proxXrDevice_Destroy");
  app.set_device({});
  app.exit_session();
  app.destroy();
  EXPECT_EQ(validation_errors(app), "");
}

}  // namespace
