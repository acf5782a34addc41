#include "contact/force.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

namespace prox {
namespace {

LmdPair lmd(const Vec3& a, const Vec3& b) {
  LmdPair p;
  p.point_a = a;
  p.point_b = b;
  p.distance = glm::length(b - a);
  return p;
}

TEST(Force, CurvesReachTheMaximumAtTheSafetyDistanceAndZeroAtTheCutoff) {
  for (const ForceSettings& s : {hard_force_settings(), soft_force_settings()}) {
    EXPECT_EQ(force_magnitude(s, 0.0), s.max_force);
    EXPECT_EQ(force_magnitude(s, s.safety_distance), s.max_force);
    EXPECT_EQ(force_magnitude(s, s.cutoff), 0.0);
    EXPECT_EQ(force_magnitude(s, 2 * s.cutoff), 0.0);
    EXPECT_EQ(force_magnitude(s, NAN), 0.0);
    // Continuous at both ends, and decreasing in between.
    EXPECT_NEAR(force_magnitude(s, s.safety_distance * (1 + 1e-9)), s.max_force, 1e-5 * s.max_force);
    EXPECT_NEAR(force_magnitude(s, s.cutoff * (1 - 1e-9)), 0.0, 1e-5 * s.max_force);
    double previous = s.max_force;
    for (int i = 1; i <= 1000; ++i) {
      const double d = s.safety_distance + (s.cutoff - s.safety_distance) * i / 1000.0;
      const double f = force_magnitude(s, d);
      EXPECT_LE(f, previous);
      EXPECT_GE(f, 0.0);
      previous = f;
    }
  }
}

TEST(Force, LinearCurveIsHalfWayAtTheMiddle) {
  ForceSettings s = soft_force_settings();
  EXPECT_NEAR(force_magnitude(s, 0.5 * (s.safety_distance + s.cutoff)), 0.5 * s.max_force, 1e-12);
}

TEST(Force, ExponentialCurveFallsByEOverTheDecayLengthNearTheSafetyDistance) {
  ForceSettings s = hard_force_settings();
  s.cutoff = 1.0;  // far away, so the shift to zero at the cutoff is negligible
  const double ratio = force_magnitude(s, s.safety_distance + s.decay_length) / s.max_force;
  EXPECT_NEAR(ratio, std::exp(-1.0), 1e-9);
}

TEST(Force, OneContactPushesTheToolAwayWithATorqueAboutItsReference) {
  const ForceSettings s = hard_force_settings();
  // b (the tool) is 1 mm above a, 10 cm to the side of its reference point.
  const std::vector<LmdPair> lmds = {lmd(Vec3(0.1, 0, 0), Vec3(0.1, 0, 0.001))};
  const Wrench w = tool_wrench(s, lmds, Vec3(0, 0, 0.001));
  const double f = force_magnitude(s, 0.001);
  EXPECT_NEAR(w.force.z, f, 1e-12);
  EXPECT_NEAR(w.force.x, 0.0, 1e-12);
  // torque = r x F = (0.1, 0, 0) x (0, 0, f) = (0, -0.1 f, 0)
  EXPECT_NEAR(w.torque.y, -0.1 * f, 1e-12);
  EXPECT_FALSE(w.clipped);
}

TEST(Force, ManyParallelContactsAreClippedToTheMaximum) {
  const ForceSettings s = hard_force_settings();
  std::vector<LmdPair> lmds;
  for (int i = 0; i < 50; ++i) lmds.push_back(lmd(Vec3(0.001 * i, 0, 0), Vec3(0.001 * i, 0, 0.0002)));
  const Wrench w = tool_wrench(s, lmds, Vec3(0.0));
  EXPECT_TRUE(w.clipped);
  EXPECT_NEAR(glm::length(w.force), s.max_force, 1e-12);
  EXPECT_LE(glm::length(w.torque), s.max_torque * (1 + 1e-12));
}

TEST(Force, RandomContactSetsGiveFiniteBoundedWrenches) {
  const ForceSettings s = hard_force_settings();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (int trial = 0; trial < 1000; ++trial) {
    std::vector<LmdPair> lmds;
    for (int i = 0; i < trial % 40; ++i) {
      const Vec3 a(u(rng), u(rng), u(rng));
      lmds.push_back(lmd(a, a + 0.05 * Vec3(u(rng), u(rng), u(rng))));
    }
    lmds.push_back(lmd(Vec3(0.0), Vec3(0.0)));  // a degenerate touching pair adds nothing
    const Wrench w = tool_wrench(s, lmds, Vec3(u(rng), u(rng), u(rng)));
    ASSERT_TRUE(std::isfinite(w.force.x + w.force.y + w.force.z + w.torque.x + w.torque.y + w.torque.z));
    EXPECT_LE(glm::length(w.force), s.max_force * (1 + 1e-12));
    EXPECT_LE(glm::length(w.torque), s.max_torque * (1 + 1e-12));
  }
}

}  // namespace
}  // namespace prox

#include "support/scenes.h"

namespace prox::testing {
namespace {

// The largest force change between consecutive steps that keep the same
// LMDs (same mesh features), along B approaching A in `steps` poses.
double largest_jump_with_the_same_lmds(const Model& m, const Vec3& dir, double from, double to, int steps,
                                       const ForceSettings& force, int& comparable) {
  PairState state;
  std::vector<std::pair<MeshFeature, MeshFeature>> previous_set;
  Vec3 previous_force(0.0);
  double jump = 0.0;
  comparable = 0;
  for (int i = 0; i < steps; ++i) {
    const double s = from + (to - from) * i / (steps - 1);
    const Pose pose{glm::dmat3(1.0), s * dir};
    ProximityResult r;
    find_lmds(make_query(m, Pose{}, m, pose, force.cutoff), Method::Precise, state, r);
    const Wrench w = tool_wrench(force, r.lmds, pose.apply(m.centre));
    EXPECT_TRUE(std::isfinite(w.force.x + w.force.y + w.force.z));
    EXPECT_LE(glm::length(w.force), force.max_force * (1 + 1e-12));
    std::vector<std::pair<MeshFeature, MeshFeature>> set;
    for (const LmdPair& p : r.lmds) set.emplace_back(p.mesh_feature_a, p.mesh_feature_b);
    if (i > 0 && set == previous_set && !set.empty()) {
      jump = std::max(jump, glm::length(w.force - previous_force));
      ++comparable;
    }
    previous_set = set;
    previous_force = w.force;
  }
  return jump;
}

TEST(Force, ContinuousAlongAPathWhereTheLmdsAreContinuous) {
  const auto bunny = load_obj_model("bunny.obj");
  ASSERT_TRUE(bunny);
  const ForceSettings force = hard_force_settings();
  // B = A shifted along +x: the stretch of path T from 5 mm to 0.5 mm apart.
  const Vec3 dir(1.0, 0.0, 0.0);
  auto shift_at_gap = [&](double gap) {
    double lo = 0.0, hi = bunny->size;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (any_closer_than(make_query(*bunny, Pose{}, *bunny, {glm::dmat3(1.0), mid * dir}, 0.0), gap) ? lo
                                                                                                   : hi) =
          mid;
    }
    return hi;
  };
  const double from = shift_at_gap(0.005), to = shift_at_gap(0.0005);
  int coarse_pairs = 0, fine_pairs = 0;
  const double coarse = largest_jump_with_the_same_lmds(*bunny, dir, from, to, 100, force, coarse_pairs);
  const double fine = largest_jump_with_the_same_lmds(*bunny, dir, from, to, 400, force, fine_pairs);
  std::printf("[ force ] largest jump with unchanged LMDs: %.4f N at 100 steps, %.4f N at 400 steps\n",
              coarse, fine);
  ASSERT_GT(coarse_pairs, 20);
  ASSERT_GT(fine_pairs, 80);
  // A continuous force changes about 4 times less over a 4 times shorter step.
  EXPECT_LT(fine, 0.35 * coarse);
}

}  // namespace
}  // namespace prox::testing
