// The numerical stress suite: every family, thousands of seeded cases, against
// the quad-precision reference, with the bounds of families.cpp asserted.
#include "stress/evaluate.h"

#include "geometry/triangle_distance.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include <ostream>

namespace prox::stress {

// gtest prints a failing parameter with this.
void PrintTo(const Family& family, std::ostream* os) { *os << family.name; }

namespace {

constexpr int kCasesPerFamily = 2000;
constexpr std::uint64_t kSeed = 20261123;

class StressFamily : public ::testing::TestWithParam<Family> {};

TEST_P(StressFamily, MeetsItsBounds) {
  const Family& family = GetParam();
  const FamilyStats s = evaluate_family(family, kSeed, kCasesPerFamily);
  std::string examples;
  for (const std::string& e : s.examples) examples += "\n  " + e;
  SCOPED_TRACE("first failures:" + examples);

  EXPECT_EQ(s.cases, kCasesPerFamily);
  EXPECT_EQ(s.nan_count, 0);
  EXPECT_EQ(s.bound_violations, 0) << "max error / bound = " << s.max_bound_ratio;
  EXPECT_EQ(s.verdict_mismatches, 0);
  EXPECT_EQ(s.feature_errors, 0);
  EXPECT_EQ(s.invariance_violations, 0) << "max spread / L = " << s.max_invariance_spread;
  EXPECT_EQ(s.intersection_invariance_violations, 0);
  // Random families may graze touching within the reference's rounding; that
  // must stay rare, or the family is not testing the verdict at all.
  EXPECT_LE(s.ambiguous_verdicts, s.cases / 100);

  // Reported points sit on their triangles and are the distance apart (bounds
  // per case, families.cpp).
  EXPECT_EQ(s.point_violations, 0) << "max off / L = " << s.max_point_error
                                   << ", max gap error / L = " << s.max_gap_error;
}

// triangle_distance computes only the candidates that can tie with the
// minimum; the full enumeration of all 15 must give the same verdict and
// features on every case, and the same distance to rounding. (The reported
// points may differ where the closest set is not a point: both are the
// average of tied candidates, the full one with repeats; the stress test
// above checks they lie on their triangles the distance apart.)
TEST_P(StressFamily, PrunedCandidatesAgreeWithEveryCandidate) {
  const Family& family = GetParam();
  const std::vector<Case> cases = family.generate(kSeed + 1, kCasesPerFamily);
  int verdicts = 0, features = 0, distances = 0;
  std::string first;
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  for (const Case& c : cases) {
    for (int swap = 0; swap < 2; ++swap) {
      const Triangle& a = swap ? c.b : c.a;
      const Triangle& b = swap ? c.a : c.b;
      const geometry::TriangleDistance fast = geometry::triangle_distance(a, b);
      const geometry::TriangleDistance every = geometry::triangle_distance_every_candidate(a, b);
      double size = 0.0, coord = 0.0;
      for (const Triangle* t : {&a, &b})
        for (int k = 0; k < 3; ++k) {
          size = std::max(size, glm::length(t->v[(k + 1) % 3] - t->v[k]));
          coord = std::max({coord, std::abs(t->v[k].x), std::abs(t->v[k].y), std::abs(t->v[k].z)});
        }
      const bool verdict = fast.intersects != every.intersects;
      const bool feature = fast.feature_a != every.feature_a || fast.feature_b != every.feature_b;
      const bool distance = !(std::abs(fast.distance - every.distance) <=
                              16.0 * kEps * std::max(size, every.distance) + 4.0 * kEps * coord);
      verdicts += verdict, features += feature, distances += distance;
      if ((verdict || feature || distance) && first.empty())
        first = std::string(verdict ? "verdict " : "") + (feature ? "features " : "") +
                (distance ? "distance " : "") + "differ: distance " + std::to_string(fast.distance) +
                " against " + std::to_string(every.distance);
    }
  }
  EXPECT_EQ(verdicts, 0) << first;
  EXPECT_EQ(features, 0) << first;
  EXPECT_EQ(distances, 0) << first;
}

INSTANTIATE_TEST_SUITE_P(Families, StressFamily, ::testing::ValuesIn(families()),
                         [](const ::testing::TestParamInfo<Family>& param) {
                           return std::string(param.param.name);
                         });

}  // namespace
}  // namespace prox::stress
