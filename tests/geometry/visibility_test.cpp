#include "geometry/visibility.h"

#include <gtest/gtest.h>

namespace prox::geometry {
namespace {

const Vec3 kUp[3] = {Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1)};
const Vec3 kDown[3] = {Vec3(0, 0, -1), Vec3(0, 0, -1), Vec3(0, 0, -1)};
const Triangle kFloor{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}};

Triangle lifted(const Triangle& t, const Vec3& offset) {
  return {{t.v[0] + offset, t.v[1] + offset, t.v[2] + offset}};
}

TEST(Visibility, FacingTrianglesSeeEachOther) {
  const Triangle ceiling = lifted(kFloor, Vec3(0.3, 0.3, 1));
  EXPECT_TRUE(visibility_pretest(kFloor, kUp, ceiling, kDown));
}

TEST(Visibility, SidewaysOffsetIsCulled) {
  // Straight normals project each triangle onto the other's plane unchanged;
  // 3 units sideways they cannot overlap.
  const Triangle ceiling = lifted(kFloor, Vec3(3, 0, 1));
  EXPECT_FALSE(visibility_pretest(kFloor, kUp, ceiling, kDown));
  // ... and the test is needed in both directions: project only one way and
  // a tilted vertex normal can make it pass.
  const Vec3 leaning[3] = {Vec3(3, 0, 1), Vec3(3, 0, 1), Vec3(3, 0, 1)};
  EXPECT_TRUE(projects_onto(kFloor, leaning, ceiling, 0.0));
  EXPECT_FALSE(projects_onto(ceiling, kDown, kFloor, 0.0));
  EXPECT_FALSE(visibility_pretest(kFloor, leaning, ceiling, kDown));
}

TEST(Visibility, VertexNormalsSpreadTheProjection) {
  // Normals fanning outwards (a convex patch): the projection grows and
  // reaches a triangle that the face normal alone would miss.
  const Triangle neighbour = lifted(kFloor, Vec3(1.2, 0, 1));
  EXPECT_FALSE(projects_onto(kFloor, kUp, neighbour, 0.0));
  const Vec3 fan[3] = {Vec3(-1, -1, 1), Vec3(1, -0.2, 1), Vec3(-0.2, 1, 1)};
  EXPECT_TRUE(projects_onto(kFloor, fan, neighbour, 0.0));
}

TEST(Visibility, EdgeContactPassesWithinTheMargin) {
  // Projections that share exactly an edge overlap (closed sets).
  const Triangle beside{{Vec3(1, 0, 1), Vec3(0, 1, 1), Vec3(1, 1, 1)}};
  EXPECT_TRUE(visibility_pretest(kFloor, kUp, beside, kDown));
}

TEST(Visibility, UndefinedProjectionsPass) {
  const Triangle ceiling = lifted(kFloor, Vec3(5, 5, 1));
  const Vec3 sideways[3] = {Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0)};
  EXPECT_TRUE(projects_onto(kFloor, sideways, ceiling, 0.0));  // normal parallel to the plane
  const Vec3 zero[3] = {Vec3(0.0), Vec3(0.0), Vec3(0.0)};
  EXPECT_TRUE(projects_onto(kFloor, zero, ceiling, 0.0));
  const Triangle flat{{Vec3(5, 5, 1), Vec3(6, 5, 1), Vec3(7, 5, 1)}};  // collinear: no plane
  EXPECT_TRUE(projects_onto(kFloor, kUp, flat, 0.0));
}

TEST(Visibility, NormalSignDoesNotMatter) {
  const Triangle ceiling = lifted(kFloor, Vec3(0.3, 0.3, 1));
  EXPECT_EQ(visibility_pretest(kFloor, kDown, ceiling, kUp), visibility_pretest(kFloor, kUp, ceiling, kDown));
  const Triangle away = lifted(kFloor, Vec3(3, 0, 1));
  EXPECT_EQ(visibility_pretest(kFloor, kDown, away, kUp), visibility_pretest(kFloor, kUp, away, kDown));
}

}  // namespace
}  // namespace prox::geometry
