// The numerical stress suite: every family, thousands of seeded cases, against
// the quad-precision reference, with the bounds of families.cpp asserted.
#include "stress/evaluate.h"
#include "stress/quad_reference.h"

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

// Whether feature `outer` of a triangle holds feature `inner` (a face holds
// everything, edge k its vertices k and k + 1).
bool holds(Feature outer, Feature inner) {
  if (outer == inner || outer.kind == FeatureKind::Face) return true;
  return outer.kind == FeatureKind::Edge && inner.kind == FeatureKind::Vertex &&
         (inner.index == outer.index || inner.index == (outer.index + 1) % 3);
}

// triangle_distance computes only the candidates that can tie with the
// minimum; the full enumeration of all 15 must give the same verdict and
// features on every case, and the same distance to rounding. One difference
// is allowed: the full enumeration may name a feature holding the pruned
// kernel's. Near a sliver's tip both long edges' candidates lie within the
// tie tolerance; the full enumeration averages them and names the face,
// where the pruned kernel, which skips edge pairs that end at a vertex,
// names the one edge (or vertex) the point is nearest. (The reported
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
      const bool feature = !holds(every.feature_a, fast.feature_a) || !holds(every.feature_b, fast.feature_b);
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

// Edges at a small angle, 1.09 um apart: the lines' critical point carries
// an error of eps / sin along them, which cost 5.3e-15 in distance (2.5x the
// family's bound; found with 20,000 cases at seed 77) before one polishing
// projection step. Now within the bound of 8 ulps of the size.
TEST(StressCase, NearParallelEdgesInteriorPointIsPolished) {
  const Triangle a{{Vec3(-0.0085011831679639993, -0.49820796994491118, -0.2162089905363368),
                    Vec3(0.79084457800687757, -1.0952350552290457, -0.28406924052809523),
                    Vec3(0.09338074551951725, -0.99842204277823787, 0.64366716070169905)}};
  const Triangle b{{Vec3(0.24645479158835953, -0.68863309592291178, -0.23785449398933933),
                    Vec3(0.88822444348812601, -1.1679675484056062, -0.29233736967684343),
                    Vec3(0.50777125994145456, -0.97238877342899799, -0.9526605228099646)}};
  const double reference = to_double(reference_distance(a, b).distance);
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  for (const geometry::TriangleDistance& r :
       {geometry::triangle_distance(a, b), geometry::triangle_distance_every_candidate(a, b)})
    EXPECT_NEAR(r.distance, reference, 8.0 * kEps * glm::length(a.v[1] - a.v[0]));
}

// Both argument orders and the full enumeration within 8 ulps of `size` of
// the quad-precision distance.
void expect_distance_to_reference(const Triangle& a, const Triangle& b, double size) {
  const double reference = to_double(reference_distance(a, b).distance);
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  EXPECT_NEAR(geometry::triangle_distance(a, b).distance, reference, 8.0 * kEps * size) << "a, b";
  EXPECT_NEAR(geometry::triangle_distance(b, a).distance, reference, 8.0 * kEps * size) << "b, a";
  EXPECT_NEAR(geometry::triangle_distance_every_candidate(a, b).distance, reference, 8.0 * kEps * size);
}

// A vertex of b 8.5e-10 behind the tip of a sliver (tip angle 3.0e-8) and
// 1.9e-9 above its plane: each long edge's test, taken from the edge's far
// end, rounded to "inside", and the vertex was projected onto the face,
// 1.8e-10 nearer than it is (10^5 times the bound of 8 ulps of the size;
// found by a first version of the family sliver_apex, needles only,
// 20,000 cases at seed 77). Taken from the nearer end, the tests see it
// outside.
TEST(StressCase, VertexBehindASliversTipIsNotProjectedOntoItsFace) {
  const Triangle a{{Vec3(0.63830855550458621, -0.86556930151255385, -0.23987045500317972),
                    Vec3(0.22794511458709277, -1.6138921626282055, -0.76103716718848391),
                    Vec3(0.21868934024349168, -1.6307706280481109, -0.77279214926118689)}};
  const Triangle b{{Vec3(0.6383085575555062, -0.86556930170277624, -0.23987045470595134),
                    Vec3(0.64389830399375381, -0.90977603221266845, -0.24580734957698921),
                    Vec3(0.666615673157124, -0.85804517214860554, -0.22304652732970703)}};
  expect_distance_to_reference(a, b, glm::length(a.v[2] - a.v[0]));
}

// The other way round: a vertex of b 1.8e-10 above a cap sliver (its obtuse
// angle pi - 1.5e-8), inside it 9.4e-10 from the obtuse vertex. A short
// edge's test, taken from its far end, rounded to "outside", and the
// distance to the edge, 9.6e-10, was reported (4e5 times the bound; the
// worst of the family sliver_apex's 2,000 cases at the suite's seed).
TEST(StressCase, VertexAboveACapSliversObtuseVertexIsProjectedOntoItsFace) {
  const Triangle a{{Vec3(-0.64724444752910815, 0.59657902375678939, -0.56395061195168794),
                    Vec3(-1.1574803501753674, 0.54500002651941171, 0.29453580651673728),
                    Vec3(-0.85776479071705736, 0.57529783082762775, -0.20974414220415077)}};
  const Triangle b{{Vec3(-0.85776479115651372, 0.57529783094811626, -0.20974414136165315),
                    Vec3(-0.84242944461918845, 0.58615623107491133, -0.19406130657090737),
                    Vec3(-0.8621456152437037, 0.59031902023238758, -0.20209095222982199)}};
  expect_distance_to_reference(a, b, glm::length(a.v[1] - a.v[0]));
}

INSTANTIATE_TEST_SUITE_P(Families, StressFamily, ::testing::ValuesIn(families()),
                         [](const ::testing::TestParamInfo<Family>& param) {
                           return std::string(param.param.name);
                         });

}  // namespace
}  // namespace prox::stress
