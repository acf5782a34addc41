// The streamed device's pose against analytic motion: interpolation exact
// to rounding for constant linear and angular velocity, extrapolation exact
// for both and capped, late and duplicate samples dropped, staleness.
#include "runtime/stream_device.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace prox::runtime {
namespace {

// A screw motion: constant velocity along a direction and constant angular
// velocity about a fixed world axis, from a tilted start.
struct Motion {
  glm::dvec3 p0{0.1, -0.2, 0.3};
  glm::dvec3 velocity{0.25, -0.1, 0.05};  // m/s
  glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, 1.0, -0.2));
  double omega = 2.0;  // rad/s
  glm::dquat q0 = glm::normalize(glm::dquat(0.9, 0.1, -0.3, 0.2));

  StreamSample at(double t) const {
    StreamSample s;
    s.time = t;
    const glm::dvec3 p = p0 + velocity * t;
    const glm::dquat q = glm::angleAxis(omega * t, axis) * q0;
    for (int k = 0; k < 3; ++k) s.position[k] = p[k];
    s.rotation[0] = q.w, s.rotation[1] = q.x, s.rotation[2] = q.y, s.rotation[3] = q.z;
    return s;
  }
};

double position_error(const StreamSample& a, const StreamSample& b) {
  return glm::length(glm::dvec3(a.position[0], a.position[1], a.position[2]) -
                     glm::dvec3(b.position[0], b.position[1], b.position[2]));
}

// The angle between two rotations, in radians.
double rotation_error(const StreamSample& a, const StreamSample& b) {
  const glm::dquat qa(a.rotation[0], a.rotation[1], a.rotation[2], a.rotation[3]);
  const glm::dquat qb(b.rotation[0], b.rotation[1], b.rotation[2], b.rotation[3]);
  const glm::dquat d = glm::conjugate(qa) * qb;  // precise near zero, unlike acos of a dot product
  return 2.0 * std::atan2(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), std::fabs(d.w));
}

TEST(StreamPose, InterpolationFollowsAnalyticMotion) {
  const Motion m;
  std::vector<StreamSample> samples;
  // 90 Hz with uneven spacing: the interpolation must not assume a rate.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> jitter(-0.004, 0.004);
  for (int i = 0; i < StreamDevice::kHistory; ++i) samples.push_back(m.at(1.0 + i / 90.0 + jitter(rng)));
  StreamSettings s;
  s.mode = StreamMode::Interpolate;
  s.delay = 0.0;
  const double first = samples.front().time, last = samples.back().time;
  for (int k = 0; k <= 1000; ++k) {
    const double t = first + (last - first) * k / 1000.0;
    double past = -1.0;
    const StreamSample got = stream_pose_at(samples.data(), int(samples.size()), t, s, &past);
    const StreamSample want = m.at(t);
    // The motion's scale: about a metre and a radian over the window.
    EXPECT_LE(position_error(got, want), 1e-9) << "t = " << t;
    EXPECT_LE(rotation_error(got, want), 1e-9) << "t = " << t;
    EXPECT_EQ(past, 0.0);
  }
}

TEST(StreamPose, InterpolationRendersTheDelayedPoseAndHoldsAtTheEnds) {
  const Motion m;
  std::vector<StreamSample> samples = {m.at(0.0), m.at(0.01), m.at(0.02)};
  StreamSettings s;
  s.mode = StreamMode::Interpolate;
  s.delay = 0.005;
  double past = 0.0;
  EXPECT_LE(position_error(stream_pose_at(samples.data(), 3, 0.017, s, &past), m.at(0.012)), 1e-12);
  // Past the newest: held, and how far past is said.
  EXPECT_LE(position_error(stream_pose_at(samples.data(), 3, 0.040, s, &past), m.at(0.02)), 0.0);
  EXPECT_NEAR(past, 0.015, 1e-15);
  // Before the oldest: the oldest.
  EXPECT_LE(position_error(stream_pose_at(samples.data(), 3, -1.0, s, &past), m.at(0.0)), 0.0);
}

TEST(StreamPose, ExtrapolationIsExactForConstantVelocityAndCapped) {
  const Motion m;
  const std::vector<StreamSample> samples = {m.at(0.5), m.at(0.5 + 1.0 / 90.0)};
  StreamSettings s;
  s.mode = StreamMode::Extrapolate;
  s.max_extrapolation = 0.02;
  const double newest = samples.back().time;
  for (double ahead : {0.0, 0.001, 0.005, 0.0125, 0.02}) {
    double past = 0.0;
    const StreamSample got = stream_pose_at(samples.data(), 2, newest + ahead, s, &past);
    EXPECT_LE(position_error(got, m.at(newest + ahead)), 1e-12) << ahead;
    EXPECT_LE(rotation_error(got, m.at(newest + ahead)), 1e-12) << ahead;
  }
  // Beyond the cap the prediction stops where the cap is.
  double past = 0.0;
  const StreamSample capped = stream_pose_at(samples.data(), 2, newest + 0.5, s, &past);
  EXPECT_LE(position_error(capped, m.at(newest + 0.02)), 1e-12);
  EXPECT_NEAR(past, 0.5, 1e-12);
  // Within the samples, extrapolation mode interpolates.
  const StreamSample mid = stream_pose_at(samples.data(), 2, 0.505, s, &past);
  EXPECT_LE(position_error(mid, m.at(0.505)), 1e-12);
  EXPECT_EQ(past, 0.0);
}

TEST(StreamPose, HoldRendersTheNewestSample) {
  const Motion m;
  const std::vector<StreamSample> samples = {m.at(0.0), m.at(0.01)};
  StreamSettings s;
  s.mode = StreamMode::Hold;
  double past = 0.0;
  for (double t : {-1.0, 0.005, 0.01, 5.0})
    EXPECT_EQ(position_error(stream_pose_at(samples.data(), 2, t, s, &past), samples[1]), 0.0);
}

TEST(StreamDevice, DropsLateAndDuplicateSamplesAndCountsThem) {
  StreamDevice d({});
  const Motion m;
  EXPECT_TRUE(d.push(m.at(1.00)));
  EXPECT_TRUE(d.push(m.at(1.02)));
  EXPECT_FALSE(d.push(m.at(1.02)));  // duplicate
  EXPECT_FALSE(d.push(m.at(1.01)));  // out of order
  EXPECT_TRUE(d.push(m.at(1.03)));
  const StreamStats s = d.stats();
  EXPECT_EQ(s.pushed, 3u);
  EXPECT_EQ(s.dropped, 2u);
  EXPECT_NEAR(s.mean_interval, 0.015, 1e-12);
  EXPECT_NEAR(s.max_interval, 0.02, 1e-12);
}

TEST(StreamDevice, ReadsThroughTheHistoryRingAndGoesStale) {
  StreamSettings settings;
  settings.mode = StreamMode::Interpolate;
  settings.delay = 0.0;
  settings.stale_after = 0.05;
  StreamDevice d(settings);
  DevicePose pose{};
  const double now = stream_clock();
  EXPECT_FALSE(d.read_pose_at(now, &pose)) << "nothing pushed: no pose";
  const Motion m;
  // More samples than the ring holds, so it wraps; the newest one now.
  const int n = 3 * StreamDevice::kHistory;
  for (int i = 0; i < n; ++i) d.push(m.at(now - 0.01 * (n - 1 - i)));
  const double t = now - 0.0137;
  ASSERT_TRUE(d.read_pose_at(t, &pose));
  const StreamSample want = m.at(t);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(pose.position[k], want.position[k], 1e-12);
  // No push for longer than stale_after after the last one arrived.
  EXPECT_FALSE(d.read_pose_at(stream_clock() + 0.06, &pose));
  const StreamStats s = d.stats();
  EXPECT_EQ(s.reads, 3u);
  EXPECT_EQ(s.stale_ticks, 2u);
}

TEST(StreamDevice, ExtrapolationStatisticsSayHowFarItPredicted) {
  StreamSettings settings;
  settings.mode = StreamMode::Extrapolate;
  settings.max_extrapolation = 0.02;
  StreamDevice d(settings);
  const Motion m;
  const double now = stream_clock();
  d.push(m.at(now - 0.011));
  d.push(m.at(now - 0.001));
  DevicePose pose{};
  ASSERT_TRUE(d.read_pose_at(now + 0.009, &pose));  // 10 ms past the newest
  const StreamSample want = m.at(now + 0.009);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(pose.position[k], want.position[k], 1e-9);
  ASSERT_TRUE(d.read_pose_at(now + 0.039, &pose));  // 40 ms past: capped at 20
  const StreamStats s = d.stats();
  EXPECT_EQ(s.extrapolated_ticks, 2u);
  EXPECT_NEAR(s.max_extrapolation, 0.02, 1e-12);
}

}  // namespace
}  // namespace prox::runtime
