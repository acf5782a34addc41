#include "geometry/triangle_intersection.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>

namespace prox::geometry {
namespace {

const Triangle kUnitXY{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}};

TEST(TriangleIntersection, CrossingGivesTheSegment) {
  // b stands in the plane x = 0.25 and crosses a along x = 0.25, y in [0, 0.75].
  const Triangle b{{Vec3(0.25, -1, -1), Vec3(0.25, -1, 1), Vec3(0.25, 3, 0)}};
  const TriangleIntersection r = intersect_triangles(kUnitXY, b);
  ASSERT_TRUE(r.intersects);
  EXPECT_FALSE(r.coplanar);
  ASSERT_EQ(r.count, 2);
  const double y0 = std::min(r.points[0].y, r.points[1].y), y1 = std::max(r.points[0].y, r.points[1].y);
  EXPECT_NEAR(y0, 0.0, 1e-15);
  EXPECT_NEAR(y1, 0.75, 1e-15);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(r.points[i].x, 0.25, 1e-15);
    EXPECT_NEAR(r.points[i].z, 0.0, 1e-15);
  }
}

TEST(TriangleIntersection, TouchingAtAVertexIsOnePoint) {
  const Triangle b{{Vec3(0.25, 0.25, 0), Vec3(1, 1, 1), Vec3(-1, 1, 1)}};
  const TriangleIntersection r = intersect_triangles(kUnitXY, b);
  ASSERT_TRUE(r.intersects);
  ASSERT_EQ(r.count, 1);
  EXPECT_EQ(r.points[0], Vec3(0.25, 0.25, 0));
}

TEST(TriangleIntersection, SeparatedByAHairIsNotTouching) {
  // b's vertex is one ulp above a's plane: exact predicates say no.
  const double z = std::nextafter(0.0, 1.0);
  const Triangle b{{Vec3(0.25, 0.25, z), Vec3(1, 1, 1), Vec3(-1, 1, 1)}};
  EXPECT_FALSE(triangles_intersect(kUnitXY, b));
  const Triangle touching{{Vec3(0.25, 0.25, 0), Vec3(1, 1, 1), Vec3(-1, 1, 1)}};
  EXPECT_TRUE(triangles_intersect(kUnitXY, touching));
}

TEST(TriangleIntersection, CoplanarOverlapIsAPolygon) {
  // The unit triangle and its copy shifted by (0.5, 0): overlap is the
  // triangle (0.5,0), (1,0), (0.5,0.5), area 1/8.
  const Triangle b{{Vec3(0.5, 0, 0), Vec3(1.5, 0, 0), Vec3(0.5, 1, 0)}};
  const TriangleIntersection r = intersect_triangles(kUnitXY, b);
  ASSERT_TRUE(r.intersects);
  ASSERT_TRUE(r.coplanar);
  ASSERT_EQ(r.count, 3);
  double area2 = 0.0;  // shoelace, counter-clockwise around +z means positive
  for (int i = 0; i < r.count; ++i) {
    const Vec3 &p = r.points[i], &q = r.points[(i + 1) % r.count];
    area2 += p.x * q.y - q.x * p.y;
  }
  EXPECT_NEAR(area2 / 2.0, 0.125, 1e-15);
}

TEST(TriangleIntersection, CoplanarHexagon) {
  // Two triangles forming a star of David: overlap is a hexagon.
  const double h = std::sqrt(3.0) / 2.0;
  const Triangle up{{Vec3(-1, -h / 3 * 2 + h / 3, 0), Vec3(1, -h / 3, 0), Vec3(0, 2 * h * 2 / 3 - h / 3, 0)}};
  const Triangle down{{Vec3(-1, h / 3, 0), Vec3(0, -2 * h * 2 / 3 + h / 3, 0), Vec3(1, h / 3, 0)}};
  const TriangleIntersection r = intersect_triangles(up, down);
  ASSERT_TRUE(r.intersects);
  ASSERT_TRUE(r.coplanar);
  EXPECT_EQ(r.count, 6);
}

TEST(TriangleIntersection, CoplanarDisjointAndParallel) {
  const Triangle apart{{Vec3(2, 2, 0), Vec3(3, 2, 0), Vec3(2, 3, 0)}};
  EXPECT_FALSE(triangles_intersect(kUnitXY, apart));
  const Triangle above{{Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1)}};
  EXPECT_FALSE(triangles_intersect(kUnitXY, above));
}

TEST(TriangleIntersection, DegenerateTriangles) {
  // A segment piercing the face.
  const Triangle needle{{Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), Vec3(0.2, 0.2, 1)}};
  TriangleIntersection r = intersect_triangles(kUnitXY, needle);
  ASSERT_TRUE(r.intersects);
  ASSERT_EQ(r.count, 1);
  EXPECT_NEAR(glm::length(r.points[0] - Vec3(0.2, 0.2, 0)), 0.0, 1e-15);
  // A segment lying in the plane across the triangle: the clipped part.
  const Triangle lying{{Vec3(-1, 0.5, 0), Vec3(2, 0.5, 0), Vec3(2, 0.5, 0)}};
  r = intersect_triangles(kUnitXY, lying);
  ASSERT_TRUE(r.intersects);
  ASSERT_EQ(r.count, 2);
  EXPECT_NEAR(std::abs(r.points[0].x - r.points[1].x), 0.5, 1e-15);
  // Two collinear segments overlapping on [1, 2].
  const Triangle s1{{Vec3(0, 0, 5), Vec3(2, 0, 5), Vec3(1, 0, 5)}};
  const Triangle s2{{Vec3(1, 0, 5), Vec3(3, 0, 5), Vec3(3, 0, 5)}};
  r = intersect_triangles(s1, s2);
  ASSERT_TRUE(r.intersects);
  ASSERT_EQ(r.count, 2);
  EXPECT_NEAR(std::abs(r.points[0].x - r.points[1].x), 1.0, 1e-15);
  // Two points, equal and not.
  const Triangle p{{Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3)}};
  EXPECT_TRUE(triangles_intersect(p, p));
  const Triangle q{{Vec3(1, 2, 3.5), Vec3(1, 2, 3.5), Vec3(1, 2, 3.5)}};
  EXPECT_FALSE(triangles_intersect(p, q));
}

}  // namespace
}  // namespace prox::geometry
