// Hand-derived cases for the triangle-triangle distance; the stress suite
// covers the random families against the quad-precision reference.
#include "geometry/triangle_distance.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace prox::geometry {
namespace {

constexpr FeatureKind V = FeatureKind::Vertex, E = FeatureKind::Edge, F = FeatureKind::Face;

const Triangle kUnitXY{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}};

void expect_point(const Vec3& got, const Vec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-15);
  EXPECT_NEAR(got.y, want.y, 1e-15);
  EXPECT_NEAR(got.z, want.z, 1e-15);
}

TEST(TriangleDistance, VertexAboveFaceInterior) {
  const Triangle b{{Vec3(0.25, 0.25, 2.0), Vec3(3, 3, 5), Vec3(-3, 2, 6)}};
  const TriangleDistance r = triangle_distance(kUnitXY, b);
  EXPECT_FALSE(r.intersects);
  EXPECT_DOUBLE_EQ(r.distance, 2.0);
  expect_point(r.point_a, Vec3(0.25, 0.25, 0));
  expect_point(r.point_b, Vec3(0.25, 0.25, 2.0));
  EXPECT_EQ(r.feature_a, (Feature{F, 0}));
  EXPECT_EQ(r.feature_b, (Feature{V, 0}));
}

TEST(TriangleDistance, SkewEdgesCrossingAbove) {
  // b's edge 0 runs along y at x = 0.5, z = 1, over a's hypotenuse-free edge 0 (the x axis).
  const Triangle b{{Vec3(0.5, -1, 1), Vec3(0.5, 1, 1), Vec3(0.5, 0, 3)}};
  const Triangle a{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0, -1)}};
  const TriangleDistance r = triangle_distance(a, b);
  EXPECT_DOUBLE_EQ(r.distance, 1.0);
  expect_point(r.point_a, Vec3(0.5, 0, 0));
  expect_point(r.point_b, Vec3(0.5, 0, 1));
  EXPECT_EQ(r.feature_a, (Feature{E, 0}));
  EXPECT_EQ(r.feature_b, (Feature{E, 0}));
}

TEST(TriangleDistance, VertexToVertex) {
  const Triangle b{{Vec3(2, 2, 0), Vec3(3, 2, 0), Vec3(2, 3, 0)}};
  const Triangle a{{Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0.5)}};
  const TriangleDistance r = triangle_distance(a, b);
  EXPECT_DOUBLE_EQ(r.distance, std::sqrt(2.0));
  EXPECT_EQ(r.feature_a, (Feature{V, 1}));
  EXPECT_EQ(r.feature_b, (Feature{V, 0}));
}

TEST(TriangleDistance, ParallelFacesReportFacesAndTheMiddleOfTheOverlap) {
  const Triangle big{{Vec3(-10, -10, 0), Vec3(10, -10, 0), Vec3(0, 10, 0)}};
  const Triangle small{{Vec3(-1, -1, 0.5), Vec3(1, -1, 0.5), Vec3(0, 2, 0.5)}};
  const TriangleDistance r = triangle_distance(big, small);
  EXPECT_DOUBLE_EQ(r.distance, 0.5);
  EXPECT_EQ(r.feature_a, (Feature{F, 0}));
  EXPECT_EQ(r.feature_b, (Feature{F, 0}));
  // The whole small triangle is closest: the middle of its candidates lies inside it.
  EXPECT_NEAR(r.point_b.z, 0.5, 1e-15);
  EXPECT_NEAR(r.point_a.z, 0.0, 1e-15);
  EXPECT_NEAR(r.point_a.x, r.point_b.x, 1e-15);
  EXPECT_NEAR(r.point_a.y, r.point_b.y, 1e-15);
}

TEST(TriangleDistance, ParallelEdgesReportEdges) {
  const Triangle a{{Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(2, -3, 0)}};
  const Triangle b{{Vec3(1, 1, 0), Vec3(6, 1, 0), Vec3(3, 4, 1)}};
  const TriangleDistance r = triangle_distance(a, b);
  EXPECT_DOUBLE_EQ(r.distance, 1.0);
  EXPECT_EQ(r.feature_a, (Feature{E, 0}));
  EXPECT_EQ(r.feature_b, (Feature{E, 0}));
  // Closest set: x in [1, 4] on both; its middle is x = 2.5.
  expect_point(r.point_a, Vec3(2.5, 0, 0));
  expect_point(r.point_b, Vec3(2.5, 1, 0));
}

TEST(TriangleDistance, IntersectingIsZeroWithPointsOnBoth) {
  const Triangle b{{Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), Vec3(2, 2, 0)}};
  const TriangleDistance r = triangle_distance(kUnitXY, b);
  EXPECT_TRUE(r.intersects);
  EXPECT_EQ(r.distance, 0.0);
  EXPECT_EQ(r.point_a, r.point_b);
  EXPECT_NEAR(r.point_a.z, 0.0, 1e-15);
  EXPECT_NEAR(r.point_a.x, r.point_a.y, 1e-15);  // on the diagonal x = y where b's plane cuts a
}

TEST(TriangleDistance, DegenerateTrianglesAreTheirSegmentOrPoint) {
  // a repeats a vertex (as CAD exports do): it is the segment (0,0,1)-(1,0,1).
  const Triangle a{{Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 0, 1)}};
  const TriangleDistance r = triangle_distance(a, kUnitXY);
  EXPECT_DOUBLE_EQ(r.distance, 1.0);
  EXPECT_EQ(r.feature_b.kind, E);  // the closest set on the unit triangle is its edge 0
  EXPECT_EQ(r.feature_a.kind, E);
  // A point triangle.
  const Triangle p{{Vec3(0.2, 0.2, -3), Vec3(0.2, 0.2, -3), Vec3(0.2, 0.2, -3)}};
  const TriangleDistance q = triangle_distance(kUnitXY, p);
  EXPECT_DOUBLE_EQ(q.distance, 3.0);
  EXPECT_EQ(q.feature_a, (Feature{F, 0}));
  EXPECT_EQ(q.feature_b.kind, V);
}

TEST(TriangleDistance, FarFromTheOriginKeepsPrecisionRelativeToSize) {
  // 1 mm triangles 1e6 m from the origin (coordinates are multiples of 2^-23,
  // so the inputs are exact), 1 um apart.
  const double far = 1e6, mm = std::ldexp(1.0, -10), um = std::ldexp(1.0, -20);
  const Triangle a{{Vec3(far, far, far), Vec3(far + mm, far, far), Vec3(far, far + mm, far)}};
  const Triangle b{{Vec3(far, far, far + um), Vec3(far + mm, far, far + um), Vec3(far, far + mm, far + mm)}};
  const TriangleDistance r = triangle_distance(a, b);
  EXPECT_EQ(r.distance, um);
  EXPECT_EQ(r.feature_a, (Feature{E, 0}));
  EXPECT_EQ(r.feature_b, (Feature{E, 0}));
}

// Coordinates near 1e75-1e81: the in-plane edge tests of a vertex's
// projection overflow to NaN, which must count as "outside" (the edges
// decide), not as inside the other triangle. Triangles of size ~3e75 about
// 2.7e81 apart; the quad-precision reference gives 2.6829e81.
TEST(TriangleDistance, HugeCoordinatesWhoseEdgeTestsOverflow) {
  const double s = std::ldexp(1.0, 251);
  const Triangle a{{Vec3(1, 0, -1) * s, Vec3(-2, -1, 1) * s, Vec3(-2, 2, 2) * s}};
  const Triangle b{
      {Vec3(-524289, 0, 524288) * s, Vec3(-524290, -2, 524288) * s, Vec3(-524286, -3, 524287) * s}};
  const TriangleDistance r = triangle_distance(a, b);
  const TriangleDistance every = triangle_distance_every_candidate(a, b);
  EXPECT_NEAR(r.distance, 2.6829e81, 1e-4 * 2.6829e81);
  EXPECT_NEAR(r.distance, every.distance, 1e-12 * every.distance);
  EXPECT_LE(r.point_b.x, -524286 * s * (1 - 1e-12));  // on b, not on its plane beyond it
  EXPECT_EQ(r.feature_a, every.feature_a);
  EXPECT_EQ(r.feature_b, every.feature_b);
}

TEST(TriangleDistance, ClosestPointOnTriangleRegions) {
  expect_point(closest_point_on_triangle(Vec3(0.2, 0.3, 5), kUnitXY), Vec3(0.2, 0.3, 0));
  expect_point(closest_point_on_triangle(Vec3(-1, -1, 0), kUnitXY), Vec3(0, 0, 0));
  expect_point(closest_point_on_triangle(Vec3(0.5, -2, 1), kUnitXY), Vec3(0.5, 0, 0));
  expect_point(closest_point_on_triangle(Vec3(1, 1, 0), kUnitXY), Vec3(0.5, 0.5, 0));
}

TEST(TriangleDistance, SegmentSegmentParameters) {
  // Crossing at right angles.
  Vec2 st = closest_params_segment_segment(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, -1, 1), Vec3(1, 1, 1));
  EXPECT_NEAR(st.x, 0.5, 1e-15);
  EXPECT_NEAR(st.y, 0.5, 1e-15);
  // Parallel, overlapping on x in [1, 2]: the middle of the overlap.
  st = closest_params_segment_segment(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0), Vec3(3, 1, 0));
  EXPECT_NEAR(st.x, 0.75, 1e-15);
  EXPECT_NEAR(st.y, 0.25, 1e-15);
  // Zero-length segments.
  st = closest_params_segment_segment(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(-1, 1, 0), Vec3(1, 1, 0));
  EXPECT_NEAR(st.y, 0.5, 1e-15);
}

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }
bool same_bits(const Vec3& x, const Vec3& y) { return std::memcmp(&x, &y, sizeof x) == 0; }

// triangle_distance_within and triangle_distance_value against
// triangle_distance, every field bit for bit, at limits below, at and above
// each pair's distance, over the families whose pruning differs: close,
// far, crossing, parallel faces (many tied candidates), parallel edges,
// slivers, far from the origin and touching, in both argument orders.
TEST(TriangleDistance, WithinALimitItIsTheFullAnswerBitForBitAndPastItNothing) {
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> u(-0.5, 0.5), scale(0.0, 2.0);
  auto vec = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  const double inf = std::numeric_limits<double>::infinity();
  int within = 0, past = 0, mismatches = 0;
  for (int k = 0; k < 16000; ++k) {
    Triangle a, b;
    for (Vec3& v : a.v) v = vec();
    const Vec3 n = glm::normalize(glm::cross(a.v[1] - a.v[0], a.v[2] - a.v[0]));
    const int family = k % 8;
    const double gap = family == 0 ? 0.0 : family == 1 ? 0.1 : family == 2 ? 1.0 : 0.01;
    for (Vec3& v : b.v) v = 0.9 * vec() + n * (0.5 + gap * 2.0 * (u(rng) + 0.5));
    if (family == 3)  // tilted by 1e-7, or by 1e-13: candidates tied within the tie tolerance, not rounding
      for (int i = 0; i < 3; ++i) b.v[i] = a.v[i] + 0.01 * n + (k % 16 == 3 ? 1e-7 : 1e-13) * vec();
    if (family == 4) b.v[0] = a.v[0] + 1e-3 * n, b.v[1] = a.v[1] + 1e-3 * n;
    if (family == 5) a.v[2] = 0.5 * (a.v[0] + a.v[1]) + 1e-9 * n;
    if (family == 6)
      for (Triangle* t : {&a, &b})
        for (Vec3& v : t->v) v += Vec3(1e4, -3e3, 7e2);
    if (family == 7) b.v[0] = a.v[1];
    for (const bool swap : {false, true}) {
      const Triangle& x = swap ? b : a;
      const Triangle& y = swap ? a : b;
      const TriangleDistance full = triangle_distance(x, y);
      for (const double limit : {scale(rng) * full.distance, full.distance, std::nextafter(full.distance, 0.0), 0.0,
                                 inf}) {
        TriangleDistance got;
        const bool in = triangle_distance_within(x, y, limit, got);
        const double value = triangle_distance_value(x, y, limit);
        const bool want_in = !(full.distance > limit);
        (want_in ? within : past) += 1;
        const bool same = in == want_in && same_bits(value, want_in ? full.distance : inf) &&
                          (!in || (same_bits(got.distance, full.distance) && same_bits(got.point_a, full.point_a) &&
                                   same_bits(got.point_b, full.point_b) && got.feature_a == full.feature_a &&
                                   got.feature_b == full.feature_b && got.intersects == full.intersects));
        if (!same && ++mismatches <= 5)
          ADD_FAILURE() << "family " << family << " pair " << k << (swap ? " swapped" : "") << " limit " << limit
                        << " distance " << full.distance << " within " << in << " value " << value;
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
  // Both outcomes were exercised in earnest.
  EXPECT_GT(within, 60000);
  EXPECT_GT(past, 30000);
}

}  // namespace
}  // namespace prox::geometry
