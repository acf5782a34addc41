// The trigonometry-free cone merge a refit uses (snch/cone.h), against the
// exact merge worked out in long double: the merged cone holds both cones,
// and is wider than the smallest one only by its rounding margin.
#include "snch/cone.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

namespace prox {
namespace {

using Real = long double;

Real angle_between_l(const Vec3& a, const Vec3& b) {
  const Real ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
  const Real cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), ax * bx + ay * by + az * bz);
}

Real half_angle_l(const CosCone& c) { return std::atan2(static_cast<Real>(c.sin), static_cast<Real>(c.cos)); }

// The smallest cone's half-angle holding cones (axis a, half ha) and (b, hb):
// pi or more when it would hold every direction.
Real exact_merged_half(const Vec3& a, Real ha, const Vec3& b, Real hb) {
  const Real theta = angle_between_l(a, b);
  if (theta + hb <= ha) return ha;
  if (theta + ha <= hb) return hb;
  return (theta + ha + hb) / 2;
}

Vec3 random_axis(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  for (;;) {
    const Vec3 v(n(rng), n(rng), n(rng));
    if (glm::length(v) > 1e-3) return glm::normalize(v);
  }
}

// A unit vector at `angle` from `axis`.
Vec3 tilted(const Vec3& axis, double angle, std::mt19937_64& rng) {
  Vec3 side = glm::cross(axis, random_axis(rng));
  side = glm::normalize(side);
  return glm::normalize(std::cos(angle) * axis + std::sin(angle) * side);
}

TEST(CosCone, MergeHoldsBothAndIsNoWiderThanTheExactMergeBeyondItsMargin) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr Real kPiL = 3.14159265358979323846264338327950288L;
  int everything = 0, contained = 0, general = 0;
  for (int i = 0; i < 200000; ++i) {
    // Half-angles from 1e-12 rad to near pi, and axes from equal to opposite,
    // weighted towards the nearly flat cones of a smooth surface.
    const auto half = [&] {
      const double u = unit(rng);
      return u < 0.5 ? std::pow(10.0, -12.0 + 11.0 * unit(rng)) : 3.1 * unit(rng);
    };
    const Cone a{random_axis(rng), half()};
    // Angles between the axes: tiny, any, or a hair short of opposite.
    const double pick = unit(rng);
    const double theta = pick < 0.3   ? std::pow(10.0, -14.0 + 13.0 * unit(rng))
                         : pick < 0.4 ? kPi - std::pow(10.0, -12.0 + 11.0 * unit(rng))
                                      : kPi * unit(rng);
    const Cone b{tilted(a.axis, theta, rng), half()};
    const CosCone ca = CosCone::of(a), cb = CosCone::of(b);
    const CosCone m = merge(ca, cb);
    const Real exact = exact_merged_half(a.axis, half_angle_l(ca), b.axis, half_angle_l(cb));
    if (exact >= kPiL - 1e-9L) {
      // At the edge a rounding either way is fine; past it, everything.
      if (exact > kPiL + 1e-9L) {
        EXPECT_TRUE(m.unbounded()) << i;
      }
      ++everything;
      continue;
    }
    if (m.unbounded()) {
      ADD_FAILURE() << "case " << i << ": everything where the exact merge is " << static_cast<double>(exact);
      continue;
    }
    EXPECT_NEAR(glm::length(m.axis), 1.0, 1e-15) << i;
    const Real hm = half_angle_l(m);
    // A unit pair to a few hundred roundings: the searches' products of
    // cosines and sines are off by no more.
    EXPECT_NEAR(static_cast<double>(m.cos * m.cos + m.sin * m.sin), 1.0, 1e-12) << i;
    // Holds both: each axis's angle plus its half-angle within the merged one.
    for (const CosCone* c : {&ca, &cb}) {
      const Real need = angle_between_l(m.axis, c->axis) + half_angle_l(*c);
      EXPECT_LE(need, hm + 1e-15L) << "case " << i << ": misses a cone by " << static_cast<double>(need - hm);
    }
    // And no wider than the exact merge beyond the margin and its rounding
    // (more for nearly opposite axes, whose plane is known less well).
    const Real slack = 2e-14L + 2e-15L / std::sin(angle_between_l(a.axis, b.axis)) * std::sin(exact - half_angle_l(ca));
    EXPECT_LE(hm, exact + slack) << "case " << i << ": wider by " << static_cast<double>(hm - exact);
    (exact == half_angle_l(ca) || exact == half_angle_l(cb) ? contained : general) += 1;
  }
  // The cases cover every branch.
  EXPECT_GT(everything, 1000);
  EXPECT_GT(contained, 1000);
  EXPECT_GT(general, 1000);
}

TEST(CosCone, MergingEqualConesUpATreeGrowsByTheMarginOnly) {
  // A flat sheet: every leaf cone the same, 20 levels of merges.
  CosCone c{Vec3(0.0, 0.0, 1.0), 1.0, 0.0};
  for (int level = 0; level < 20; ++level) c = merge(c, c);
  EXPECT_FALSE(c.unbounded());
  EXPECT_LE(half_angle_l(c), 20 * 1.01e-14L);
  EXPECT_GT(half_angle_l(c), 0.0L);  // widened: a bound, not the rounded exact zero
}

TEST(CosCone, OppositeOrUnboundedConesHoldEverything) {
  const CosCone up{Vec3(0.0, 0.0, 1.0), std::cos(0.1), std::sin(0.1)};
  const CosCone down{Vec3(0.0, 0.0, -1.0), std::cos(0.1), std::sin(0.1)};
  // Exactly opposite axes: pi/2 + 0.1 would do, about any axis at right
  // angles to both; no plane picks one, so the merge holds everything.
  EXPECT_TRUE(merge(up, down).unbounded());
  const CosCone wide_up{Vec3(0.0, 0.0, 1.0), std::cos(1.6), std::sin(1.6)};
  const CosCone wide_down{Vec3(0.0, 0.0, -1.0), std::cos(1.6), std::sin(1.6)};
  EXPECT_TRUE(merge(wide_up, wide_down).unbounded());  // (1.6 + pi + 1.6) / 2 > pi
  EXPECT_TRUE(merge(up, CosCone::everything()).unbounded());
  EXPECT_TRUE(merge(CosCone::everything(), up).unbounded());
}

}  // namespace
}  // namespace prox
