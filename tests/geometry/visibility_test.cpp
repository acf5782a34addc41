#include "geometry/visibility.h"

#include <gtest/gtest.h>

#include <cmath>

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

namespace prox::geometry {
namespace {

// A's vertex (1, 0, 0) and B's vertex (1.3, 0, 1) are a local minimum pair
// when each vertex's cone of normals is wide enough: d = (0.3, 0, 1) is
// 16.7 degrees off both normals. Straight projections miss each other, so
// the paper's test culls the pair; the sound test must keep it when the
// spreads are 30 degrees, and may cull it when they are 10.
TEST(Visibility, SoundTestKeepsPairsTheConesCanReach) {
  const Triangle a{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}};
  const Triangle b{{Vec3(1.3, 0, 1), Vec3(1.3, 1, 1), Vec3(2.3, 0, 1)}};
  const Vec3 up[3] = {Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1)};
  const Vec3 down[3] = {Vec3(0, 0, -1), Vec3(0, 0, -1), Vec3(0, 0, -1)};
  EXPECT_FALSE(visibility_pretest(a, up, b, down));
  const double deg = 3.14159265358979323846 / 180.0;
  const double wide[3] = {30 * deg, 30 * deg, 30 * deg};
  const double narrow[3] = {10 * deg, 10 * deg, 10 * deg};
  const double none[3] = {0.0, 0.0, 0.0};
  EXPECT_TRUE(visibility_pretest(a, up, wide, b, down, wide));
  EXPECT_FALSE(visibility_pretest(a, up, narrow, b, down, narrow));
  EXPECT_EQ(visibility_pretest(a, up, none, b, down, none), visibility_pretest(a, up, b, down));
  // A cone reaching along the plane (tilt + spread >= 90 degrees) makes that
  // direction pass; the pair then depends on the other direction alone.
  const double flat[3] = {90 * deg, 90 * deg, 90 * deg};
  EXPECT_TRUE(visibility_pretest(a, up, flat, b, down, flat));
}

// The spreads as the hierarchy keeps them, cosine and sine: the decision
// turns where the angle says (the pair above needs 16.7 degrees), whatever
// positive factor the pair carries (a refit's cone rounds its cosine down
// and its sine up, unnormalised), and no known cone passes everything.
TEST(Visibility, SpreadsAsCosineAndSineDecideAsTheirAngle) {
  const Triangle a{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}};
  const Triangle b{{Vec3(1.3, 0, 1), Vec3(1.3, 1, 1), Vec3(2.3, 0, 1)}};
  const Vec3 up[3] = {Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1)};
  const Vec3 down[3] = {Vec3(0, 0, -1), Vec3(0, 0, -1), Vec3(0, 0, -1)};
  const double deg = 3.14159265358979323846 / 180.0;
  const auto at = [&](double degrees, double factor) {
    const Spread s = Spread::of_angle(degrees * deg);
    const Spread scaled{factor * s.cos, factor * s.sin};
    const Spread three[3] = {scaled, scaled, scaled};
    return visibility_pretest(a, up, three, b, down, three);
  };
  for (const double factor : {1.0, 0.5, 1.0 + 1e-12, 3.0}) {
    SCOPED_TRACE(factor);
    EXPECT_FALSE(at(10.0, factor));
    EXPECT_FALSE(at(16.0, factor));
    EXPECT_TRUE(at(17.5, factor));
    EXPECT_TRUE(at(45.0, factor));
  }
  const Spread unknown[3] = {Spread{}, Spread{}, Spread{}};
  EXPECT_TRUE(visibility_pretest(a, up, unknown, b, down, unknown));
  const Spread negative[3] = {Spread{-0.1, 1.0}, Spread{-0.1, 1.0}, Spread{-0.1, 1.0}};
  EXPECT_TRUE(visibility_pretest(a, up, negative, b, down, negative));
  EXPECT_EQ(Spread::of_angle(90 * deg).cos, 0.0);
  EXPECT_EQ(Spread::of_angle(std::nan("")).cos, 0.0);
}

}  // namespace
}  // namespace prox::geometry
