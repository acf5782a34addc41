// What the haptic loop computes each tick: contacts re-evaluated at the
// current pose (checked against the engine's own wrench and a fresh search),
// and the safety gate (checked against its promises under faults).
#include "runtime/haptic.h"
#include "runtime/scripted_device.h"
#include "support/scenes.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace prox::runtime {
namespace {

using prox::testing::load_obj_model;
using prox::testing::make_query;
using prox::testing::pose_at_gap;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

ContactSnapshot snapshot_of(const std::vector<LmdPair>& lmds, const Pose& tool_pose) {
  ContactSnapshot s;
  const Pose to_local = tool_pose.inverse();
  for (const LmdPair& p : lmds) {
    HapticContact c;
    EXPECT_TRUE(to_haptic_contact(p, to_local, c)) << "LMDs are never touching";
    s.contacts.push_back(c);
  }
  s.tool_pose = tool_pose;
  s.sequence = 1;
  return s;
}

double length(const Vec3& v) { return glm::length(v); }

// At the pose the contacts were tracked at, the haptic evaluation is the
// engine's wrench; moved a little, it follows a fresh search to first order.
TEST(HapticEvaluation, MatchesTheEngineAndFollowsTheHand) {
  const auto bunny = load_obj_model("bunny.obj");
  ASSERT_TRUE(bunny);
  std::mt19937_64 rng(7);
  ForceSettings force = soft_force_settings();
  int checked = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Pose pose_b = pose_at_gap(*bunny, *bunny, 0.008, rng);
    const PairQuery q = make_query(*bunny, Pose{}, *bunny, pose_b, force.cutoff);
    PairState state;
    ProximityResult r;
    find_lmds(q, Method::Precise, state, r);
    ASSERT_FALSE(r.lmds.empty());
    const Vec3 ref_local = bunny->centre;
    const ContactSnapshot s = snapshot_of(r.lmds, pose_b);
    const Wrench engine = tool_wrench(force, r.lmds, pose_b.apply(ref_local));
    double closest = -1.0;
    const Wrench haptic = evaluate_contacts(force, s, pose_b, ref_local, &closest);
    // The closest distance at the tracked pose: the least of the engine's
    // exact LMD distances.
    double least = std::numeric_limits<double>::infinity();
    for (const LmdPair& p : r.lmds) least = std::min(least, p.distance);
    EXPECT_NEAR(closest, least, 1e-12);
    EXPECT_NEAR(closest_tracked_distance(s), least, 1e-15);
    EXPECT_LE(length(haptic.force - engine.force), 1e-12 * (1.0 + length(engine.force)));
    EXPECT_LE(length(haptic.torque - engine.torque), 1e-12 * (1.0 + length(engine.torque)));

    // Move the tool 10 um towards the bunny along the force's direction (as
    // a hand pushing in would), then compare with a fresh search there.
    const Vec3 push = -10e-6 * glm::normalize(engine.force);
    const Pose moved{pose_b.rotation, pose_b.translation + push};
    ProximityResult fresh;
    PairState fresh_state;
    find_lmds(make_query(*bunny, Pose{}, *bunny, moved, force.cutoff), Method::Precise, fresh_state, fresh);
    const Wrench truth = tool_wrench(force, fresh.lmds, moved.apply(ref_local));
    double followed_closest = -1.0;
    const Wrench followed = evaluate_contacts(force, s, moved, ref_local, &followed_closest);
    // It follows the hand too: against the fresh search's least distance
    // (10 um in, first order).
    double fresh_least = std::numeric_limits<double>::infinity();
    for (const LmdPair& p : fresh.lmds) fresh_least = std::min(fresh_least, p.distance);
    EXPECT_LT(followed_closest, closest);
    EXPECT_NEAR(followed_closest, fresh_least, 1e-6);
    // The stale wrench (what a loop without re-evaluation would render)
    // against the followed one: following must be much closer to the truth.
    const double stale_error = length(engine.force - truth.force);
    const double followed_error = length(followed.force - truth.force);
    if (engine.clipped || truth.clipped) continue;  // the clip hides the motion
    EXPECT_GT(length(followed.force), length(engine.force)) << "pushing in must push back harder";
    auto pairs_of = [](const std::vector<LmdPair>& lmds) {
      std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
      for (const LmdPair& p : lmds) out.emplace_back(p.tri_a, p.tri_b);
      std::sort(out.begin(), out.end());
      return out;
    };
    if (pairs_of(fresh.lmds) == pairs_of(r.lmds)) {  // the same minima: first order holds
      EXPECT_LT(followed_error, 0.2 * stale_error)
          << "trial " << trial << ": " << r.lmds.size() << " LMDs, |F| " << length(engine.force) << " -> "
          << length(truth.force);
      ++checked;
    }
  }
  EXPECT_GE(checked, 4) << "too few trials kept their LMD set to check the first-order claim";
}

TEST(HapticEvaluation, PushedThroughTheTangentPlaneGivesFullForceNotNegative) {
  ContactSnapshot s;
  s.contacts.push_back({Vec3(0.0, 0.0, 0.001), Vec3(0.0), Vec3(0.0, 0.0, 1.0), 0.001});
  s.sequence = 1;
  const ForceSettings force = hard_force_settings();
  const Pose through{glm::dmat3(1.0), Vec3(0.0, 0.0, -0.003)};  // the point now 2 mm below the plane
  double closest = -1.0;
  const Wrench w = evaluate_contacts(force, s, through, Vec3(0.0), &closest);
  EXPECT_NEAR(w.force.z, force.max_force, 1e-12);
  EXPECT_EQ(w.force.x, 0.0);
  EXPECT_EQ(closest, 0.0) << "pushed through is the closest there is, never negative";
}

TEST(HapticEvaluation, ClosestDistanceOfContactsAndOfNone) {
  ContactSnapshot s;
  s.sequence = 1;
  const ForceSettings force = hard_force_settings();
  double closest = 0.0;
  evaluate_contacts(force, s, Pose{}, Vec3(0.0), &closest);
  EXPECT_EQ(closest, std::numeric_limits<double>::infinity()) << "no contacts";
  EXPECT_EQ(closest_tracked_distance(s), std::numeric_limits<double>::infinity());
  // Two planes under the tool, 3 mm and 2 mm away along their normals; the
  // tool then raised 0.5 mm: 3.5 and 2.5 mm.
  s.contacts.push_back({Vec3(0.0, 0.0, 0.003), Vec3(0.0), Vec3(0.0, 0.0, 1.0), 0.003});
  s.contacts.push_back({Vec3(0.01, 0.0, 0.0), Vec3(0.01, 0.0, -0.002), Vec3(0.0, 0.0, 1.0), 0.002});
  const Pose raised{glm::dmat3(1.0), Vec3(0.0, 0.0, 0.0005)};
  evaluate_contacts(force, s, raised, Vec3(0.0), &closest);
  EXPECT_NEAR(closest, 0.0025, 1e-15);
  EXPECT_EQ(closest_tracked_distance(s), 0.002);  // at the pose they were tracked at
}

TEST(PoseDisplacement, TranslationPlusAngleTimesRadius) {
  const Pose a{};
  const Pose moved{glm::dmat3(1.0), Vec3(0.003, 0.004, 0.0)};
  EXPECT_NEAR(pose_displacement(a, moved, Vec3(0.0), 1.0), 0.005, 1e-15);
  const double angle = 0.01;
  const Pose turned{glm::mat3_cast(glm::angleAxis(angle, glm::dvec3(0.0, 0.0, 1.0))), Vec3(0.0)};
  EXPECT_NEAR(pose_displacement(a, turned, Vec3(0.0), 0.2), angle * 0.2, 1e-12);
  // About an off-centre reference point, the rotation also moves it.
  EXPECT_GT(pose_displacement(a, turned, Vec3(1.0, 0.0, 0.0), 0.2), angle * 0.2 + 0.009);
}

// ---- the safety gate ------------------------------------------------------------

SafetySettings gate() { return {3.0, 0.3, 300.0, 30.0}; }

Wrench wrench(double fx, double fy, double fz, double tz = 0.0) {
  return {Vec3(fx, fy, fz), Vec3(0, 0, tz), false};
}

TEST(SafetyFilter, RampsAtTheRateAndClipsToTheMaximum) {
  SafetyFilter f(gate());
  const double dt = 0.001;
  // Asking for 10 N at once: 0.3 N per millisecond, up to 3 N.
  Wrench out;
  for (int i = 1; i <= 20; ++i) {
    bool limited = false;
    out = f.step(wrench(10.0, 0, 0), true, dt, &limited);
    EXPECT_TRUE(limited);
    EXPECT_NEAR(out.force.x, std::min(3.0, 0.3 * i), 1e-12) << "tick " << i;
  }
  // A target within the limits and the rate is passed as is.
  bool limited = true;
  out = f.step(wrench(2.9, 0, 0), true, dt, &limited);
  EXPECT_FALSE(limited);
  EXPECT_EQ(out.force.x, 2.9);
}

TEST(SafetyFilter, NonFiniteOrInvalidFadesOutSmoothly) {
  const double dt = 0.001;
  // Non-finite targets flagged valid, and a finite target flagged invalid.
  const std::pair<Wrench, bool> faults[] = {{wrench(kNaN, 0, 0), true},
                                            {wrench(0, std::numeric_limits<double>::infinity(), 0), true},
                                            {wrench(1, 0, 0, kNaN), true},
                                            {wrench(1.0, 1.0, 0.0), false}};
  for (const auto& [bad, valid] : faults) {
    SafetyFilter f(gate());
    for (int i = 0; i < 20; ++i) f.step(wrench(0, 0, 2.0, 0.2), true, dt);
    Vec3 previous = f.output().force;
    ASSERT_NEAR(previous.z, 2.0, 1e-12);
    int ticks = 0;
    while (length(f.output().force) > 0.0 || length(f.output().torque) > 0.0) {
      const Wrench out = f.step(bad, valid, dt);
      ASSERT_TRUE(std::isfinite(out.force.x + out.force.y + out.force.z + out.torque.x + out.torque.y +
                                out.torque.z));
      EXPECT_LE(length(out.force - previous), 0.3 + 1e-12);
      previous = out.force;
      ASSERT_LT(++ticks, 100) << "did not fade out";
    }
    EXPECT_EQ(ticks, 7) << "2 N at 0.3 N/ms (and 0.2 N m at 0.03 N m/ms) take 7 ticks";
  }
}

TEST(SafetyFilter, AStalledLoopDoesNotLicenseAJump) {
  SafetyFilter f(gate());
  const Wrench out = f.step(wrench(3.0, 0, 0), true, 10.0);  // ten seconds since the last tick
  EXPECT_LE(out.force.x, 300.0 * 0.005 + 1e-12);
  const Wrench nan_dt = f.step(wrench(3.0, 0, 0), true, kNaN);
  EXPECT_EQ(nan_dt.force.x, out.force.x) << "a NaN time step changes nothing";
  const Wrench negative_dt = f.step(wrench(3.0, 0, 0), true, -1.0);
  EXPECT_EQ(negative_dt.force.x, out.force.x);
}

TEST(SafetyFilter, TorqueClippedAndRateLimited) {
  SafetyFilter f(gate());
  Wrench out;
  for (int i = 0; i < 50; ++i) out = f.step(wrench(0, 0, 0, 5.0), true, 0.001);
  EXPECT_NEAR(out.torque.z, 0.3, 1e-12);
  out = f.step(wrench(0, 0, 0, -5.0), true, 0.001);
  EXPECT_NEAR(out.torque.z, 0.3 - 0.03, 1e-12);
}

// ---- the scripted device -----------------------------------------------------

TEST(ScriptedDevice, InterpolatesAndHolds) {
  ScriptedPose a, b;
  a.position = Vec3(0.0);
  b.position = Vec3(1.0, 0.0, 0.0);
  const glm::dquat q = glm::angleAxis(1.0, glm::dvec3(0.0, 1.0, 0.0));
  b.rotation[0] = q.w, b.rotation[1] = q.x, b.rotation[2] = q.y, b.rotation[3] = q.z;
  ScriptedDevice device({a, b}, 0.5, false);
  const ScriptedPose mid = device.pose_at(0.25);
  EXPECT_NEAR(mid.position.x, 0.5, 1e-15);
  const glm::dquat half(mid.rotation[0], mid.rotation[1], mid.rotation[2], mid.rotation[3]);
  EXPECT_NEAR(glm::angle(half), 0.5, 1e-12);
  EXPECT_EQ(device.pose_at(7.0).position.x, 1.0) << "holds the last pose";
  ScriptedDevice looping({a, b}, 0.5, true);
  EXPECT_NEAR(looping.pose_at(1.0 + 0.25).position.x, 0.5, 1e-12) << "starts over";
  EXPECT_THROW(ScriptedDevice({}, 0.5, false), std::invalid_argument);
  EXPECT_THROW(ScriptedDevice({a}, 0.0, false), std::invalid_argument);
}

TEST(ScriptedDevice, RecordsWhatItIsHanded) {
  ScriptedDevice device({ScriptedPose{}}, 1.0, false);
  HapticDevice& d = device;  // as the haptic loop holds it
  DevicePose pose{};
  ASSERT_TRUE(d.read_pose(&pose));
  EXPECT_EQ(pose.rotation[0], 1.0);
  const DeviceWrench w1{{1.0, 0.0, 0.0}, {0.0, 0.0, 0.1}, false, kNoContact, 0.0, 0.0};
  const DeviceWrench w2{{1.0, 0.5, 0.0}, {0.0, 0.0, 0.0}, false, kNoContact, 0.0, 0.0};
  d.write_wrench(w1);
  d.write_wrench(w2);
  const ScriptedRecord r = device.record();
  EXPECT_EQ(r.reads, 1u);
  EXPECT_EQ(r.writes, 2u);
  EXPECT_NEAR(r.max_force, std::sqrt(1.25), 1e-15);
  EXPECT_NEAR(r.max_force_step, 0.5, 1e-15);
  EXPECT_NEAR(r.max_torque, 0.1, 1e-15);
  EXPECT_TRUE(r.finite);
  EXPECT_EQ(r.last_force.y, 0.5);
}

}  // namespace
}  // namespace prox::runtime
