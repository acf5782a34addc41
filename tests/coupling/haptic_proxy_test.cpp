// The constrained tool's proxy at the haptic rate (coupling/haptic_proxy.h)
// and the free tool's force continuity (runtime/haptic.h, ContinuityFilter),
// each against what is worked out by hand here.
#include "coupling/haptic_proxy.h"
#include "runtime/haptic.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <vector>

namespace prox::coupling {
namespace {

Pose at(double x, double y = 0.0, double z = 0.0) {
  Pose p;
  p.translation = Vec3(x, y, z);
  return p;
}

bool same(const Pose& a, const Pose& b) { return std::memcmp(&a, &b, sizeof(Pose)) == 0; }

// A wall below the tool: one contact straight under the reference point,
// normal +z, `distance` away, at the verified proxy.
std::vector<ProxyConstraint> floor_at(double distance) {
  ProxyConstraint c;
  c.arm = Vec3(0.0, 0.0, -0.01);
  c.normal = Vec3(0.0, 0.0, 1.0);
  c.distance = distance;
  return {c};
}

const Vec3 kReference(0.0);
constexpr double kRadius = 0.05;

TEST(HapticProxy, FreeOfConstraintsItIsTheDevicePoseBitForBit) {
  std::vector<double> lambda;
  const Pose device = at(0.1234567, -0.01, 0.003);
  const HapticProxy p =
      haptic_proxy({}, {at(0.12, -0.01, 0.003), 0.01}, {}, 0.001, device, kReference, kRadius, lambda);
  EXPECT_FALSE(p.constrained);
  EXPECT_TRUE(p.within_reach);
  EXPECT_TRUE(same(p.ideal, device));
  EXPECT_TRUE(same(p.pose, device));
}

TEST(HapticProxy, NeverFartherFromTheVerifiedProxyThanItsReach) {
  std::vector<double> lambda;
  const Pose verified = at(0.0);
  const HapticProxy p = haptic_proxy({}, {verified, 0.002}, {}, 0.001, at(0.034), kReference, kRadius, lambda);
  EXPECT_FALSE(p.constrained);
  EXPECT_FALSE(p.within_reach);
  EXPECT_TRUE(same(p.ideal, at(0.034))) << "the force's ideal is the device: no pull in free air";
  EXPECT_NEAR(p.pose.translation.x, 0.002, 1e-15);
  EXPECT_LE(twist_displacement(twist_between(verified, p.pose, kReference), kRadius), 0.002 * (1 + 1e-12));
}

TEST(HapticProxy, HeldAtTheTargetDistanceAndSlidesAlongTheWall) {
  std::vector<double> lambda;
  // The proxy 3 mm above the floor; the device 5 mm below the proxy and
  // 4 mm along x: the ideal stops 1 mm above the floor (the target), and
  // goes the whole 4 mm along it.
  const HapticProxy p = haptic_proxy({}, {at(0.0), 0.01}, floor_at(0.003), 0.001, at(0.004, 0.0, -0.005),
                                     kReference, kRadius, lambda);
  EXPECT_TRUE(p.constrained);
  const Vec3 reference = p.ideal.apply(kReference);
  EXPECT_NEAR(reference.z, -0.002, 1e-6) << "held at the target distance";
  EXPECT_NEAR(reference.x, 0.004, 1e-6) << "free along the wall";
}

TEST(HapticProxy, ReachIsTheClearanceOrTheAnchorsMarginLessTheSafetyDistance) {
  EXPECT_DOUBLE_EQ(unchecked_reach(0.004, 0.0, 0.001, 0.01), 0.003);
  EXPECT_DOUBLE_EQ(unchecked_reach(0.009, 0.004, 0.001, 0.01), 0.005);  // cutoff - from anchor
  EXPECT_EQ(unchecked_reach(0.0005, 0.0, 0.001, 0.01), 0.0) << "closer than safe: never leaves it";
  EXPECT_EQ(unchecked_reach(-1.0, 0.0, 0.001, 0.01), 0.0) << "not measured";
  EXPECT_EQ(unchecked_reach(0.004, NAN, 0.001, 0.01), 0.0);
}

}  // namespace
}  // namespace prox::coupling

namespace prox::runtime {
namespace {

Wrench force_x(double fx) {
  Wrench w;
  w.force = Vec3(fx, 0.0, 0.0);
  return w;
}

// A 3 N step at a switch: carried as s (1 + t/T) exp(-t/T), the rendered
// force continuous, its steepest change s / (e T) per second, and exactly
// the instantaneous force once the carried part is below kZero.
TEST(ContinuityFilterTest, AStepFadesAsACriticallyDampedSpring) {
  ContinuityFilter f;
  const double T = ContinuityFilter::kTimeConstant, dt = 0.001;
  f.switched(force_x(0.0), force_x(3.0));  // a contact born at 3 N
  double last = 0.0, steepest = 0.0, t = 0.0;
  bool exact = false;
  for (int tick = 0; tick < 2000; ++tick) {
    t += dt;
    const Wrench w = f.step(force_x(3.0), dt);
    const double want = 3.0 - 3.0 * (1.0 + t / T) * std::exp(-t / T);
    if (!exact) {
      EXPECT_NEAR(w.force.x, want, 1e-12 + ContinuityFilter::kZero * (w.force.x == 3.0)) << "t " << t;
    }
    steepest = std::max(steepest, w.force.x - last);
    last = w.force.x;
    if (w.force.x == 3.0) exact = true;
  }
  EXPECT_TRUE(exact) << "the carried part never dropped to zero";
  EXPECT_LE(steepest, 3.0 / (std::exp(1.0) * T) * dt * (1.0 + 1e-9));
  EXPECT_GT(steepest, 0.9 * 3.0 / (std::exp(1.0) * T) * dt);
}

// Switches accumulate, a non-finite input is dropped, and reset forgets.
TEST(ContinuityFilterTest, SwitchesAccumulateAndNothingNonFiniteSurvives) {
  ContinuityFilter f;
  f.switched(force_x(1.0), force_x(0.0));
  f.switched(force_x(0.5), force_x(0.0));
  EXPECT_DOUBLE_EQ(f.step(force_x(0.0), 0.0).force.x, 1.5) << "no time passed: both steps carried whole";
  f.switched(force_x(NAN), force_x(0.0));
  EXPECT_EQ(f.step(force_x(0.0), 0.001).force.x, 0.0) << "a NaN carried is dropped";
  f.switched(force_x(2.0), force_x(0.0));
  f.reset();
  EXPECT_EQ(f.step(force_x(0.25), 0.001).force.x, 0.25);
}

}  // namespace
}  // namespace prox::runtime
