#include "contact/polylines.h"
#include "geometry/triangle_distance.h"
#include "geometry/triangle_intersection.h"
#include "support/scenes.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace prox::testing {
namespace {

// The unit cube [0, 1]^3, outward winding, as 8 vertices and 12 triangles.
std::shared_ptr<const Model> unit_cube() {
  const std::vector<double> p = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  const std::vector<std::uint32_t> i = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                        2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
  return model_from_arrays(p, i);
}

double length(const Polyline& line) {
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < line.points.size(); ++k)
    sum += glm::length(line.points[k + 1] - line.points[k]);
  if (line.closed && line.points.size() > 1) sum += glm::length(line.points.front() - line.points.back());
  return sum;
}

// Distance from p (world) to the surface of a posed model, by brute force
// over triangles whose box is near p.
double distance_to_surface(const Model& m, const Pose& pose, const Vec3& p) {
  const Vec3 local = pose.inverse().apply(p);
  double best = INFINITY;
  for (std::uint32_t t = 0; t < m.mesh.triangle_count(); ++t) {
    const Triangle tri = m.mesh.triangle(t);
    const Vec3 lo = glm::min(glm::min(tri.v[0], tri.v[1]), tri.v[2]);
    const Vec3 hi = glm::max(glm::max(tri.v[0], tri.v[1]), tri.v[2]);
    const Vec3 gap = glm::max(glm::max(lo - local, local - hi), Vec3(0.0));
    if (glm::length(gap) > best) continue;
    best = std::min(best, glm::length(geometry::closest_point_on_triangle(local, tri) - local));
  }
  return best;
}

TEST(Polylines, OffsetCubesCrossInOneClosedLoop) {
  const auto cube = unit_cube();
  ASSERT_TRUE(cube);
  // B = A + (0.5, 0.3, 0.4): the surfaces cross along six segments (A's faces
  // x = 1, y = 1, z = 1 against B's x = 0.5, y = 0.3, z = 0.4) of lengths
  // 0.6 + 0.7 + 0.6 + 0.5 + 0.7 + 0.5 = 3.6, one closed loop.
  const Pose pose_b{glm::dmat3(1.0), Vec3(0.5, 0.3, 0.4)};
  std::vector<Polyline> lines;
  PolylineStats stats;
  intersection_polylines(make_query(*cube, Pose{}, *cube, pose_b, 0.0), lines, stats);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(lines[0].closed);
  EXPECT_NEAR(length(lines[0]), 3.6, 1e-12);
  for (const Vec3& p : lines[0].points) {
    EXPECT_LT(distance_to_surface(*cube, Pose{}, p), 1e-15);
    EXPECT_LT(distance_to_surface(*cube, pose_b, p), 1e-15);
  }
  EXPECT_EQ(stats.coplanar_pairs, 0u);
}

TEST(Polylines, CoplanarFacesAreReportedNotTraced) {
  const auto cube = unit_cube();
  ASSERT_TRUE(cube);
  // Sharing the face x = 1 region: B = A + (1, 0.25, 0.25) touches A along a
  // coplanar square, which is a region, not a curve.
  std::vector<Polyline> lines;
  PolylineStats stats;
  intersection_polylines(make_query(*cube, Pose{}, *cube, {glm::dmat3(1.0), Vec3(1, 0.25, 0.25)}, 0.0), lines,
                         stats);
  EXPECT_GT(stats.coplanar_pairs, 0u);
}

TEST(Polylines, SeparateMeshesHaveNone) {
  const auto cube = unit_cube();
  ASSERT_TRUE(cube);
  std::vector<Polyline> lines;
  PolylineStats stats;
  intersection_polylines(make_query(*cube, Pose{}, *cube, {glm::dmat3(1.0), Vec3(1.5, 0, 0)}, 0.0), lines,
                         stats);
  EXPECT_TRUE(lines.empty());
  EXPECT_EQ(stats.intersecting_pairs, 0u);
}

TEST(Polylines, IntersectingBunniesGiveClosedLoopsOnBothSurfaces) {
  const auto bunny = load_obj_model("bunny.obj");
  ASSERT_TRUE(bunny);
  const Pose turn{glm::mat3_cast(glm::angleAxis(0.3, glm::normalize(Vec3(0.3, 1, 0.2)))), Vec3(0.0)};
  const Pose pose_b = Pose{glm::dmat3(1.0), bunny->centre + Vec3(0.03, 0.01, -0.005)} * turn *
                      Pose{glm::dmat3(1.0), -bunny->centre};
  std::vector<Polyline> lines;
  PolylineStats stats;
  intersection_polylines(make_query(*bunny, Pose{}, *bunny, pose_b, 0.0), lines, stats);
  ASSERT_FALSE(lines.empty());
  double total = 0.0;
  std::size_t points = 0;
  for (const Polyline& line : lines) {
    EXPECT_TRUE(line.closed) << "a polyline of " << line.points.size() << " points is open";
    total += length(line);
    points += line.points.size();
    for (std::size_t k = 0; k < line.points.size(); k += 7) {  // a sample of the vertices
      EXPECT_LT(distance_to_surface(*bunny, Pose{}, line.points[k]), 1e-12 * bunny->size);
      EXPECT_LT(distance_to_surface(*bunny, pose_b, line.points[k]), 1e-12 * bunny->size);
    }
  }
  EXPECT_EQ(points, stats.segments);  // closed loops: as many points as segments

  // Brute force: every triangle pair whose boxes overlap (a sweep over x,
  // independent of the hierarchy), the length of its intersection segment.
  struct Box {
    Vec3 lo, hi;
    Triangle t;
  };
  auto boxes = [](const Model& m, const Pose& pose) {
    std::vector<Box> out;
    for (std::uint32_t i = 0; i < m.mesh.triangle_count(); ++i) {
      const Triangle t = m.mesh.triangle(i);
      const Triangle w{{pose.apply(t.v[0]), pose.apply(t.v[1]), pose.apply(t.v[2])}};
      out.push_back(
          {glm::min(glm::min(w.v[0], w.v[1]), w.v[2]), glm::max(glm::max(w.v[0], w.v[1]), w.v[2]), w});
    }
    std::sort(out.begin(), out.end(), [](const Box& x, const Box& y) { return x.lo.x < y.lo.x; });
    return out;
  };
  const std::vector<Box> ba = boxes(*bunny, Pose{}), bb = boxes(*bunny, pose_b);
  double brute = 0.0;
  std::size_t first = 0;
  for (const Box& x : ba) {
    while (first < bb.size() && bb[first].hi.x < x.lo.x - 1e-3) ++first;  // no B box this far left matters
    for (std::size_t j = first; j < bb.size() && bb[j].lo.x <= x.hi.x; ++j) {
      const Box& y = bb[j];
      if (y.hi.x < x.lo.x || y.hi.y < x.lo.y || y.lo.y > x.hi.y || y.hi.z < x.lo.z || y.lo.z > x.hi.z)
        continue;
      const geometry::TriangleIntersection hit = geometry::intersect_triangles(x.t, y.t);
      if (hit.intersects && !hit.coplanar && hit.count == 2)
        brute += glm::length(hit.points[1] - hit.points[0]);
    }
  }
  EXPECT_NEAR(total, brute, 1e-9 * brute);
  std::printf("[ polylines ] %zu loops, %zu points, total length %.6f m (brute force %.6f m), %.2f ms\n",
              lines.size(), points, total, brute, stats.seconds * 1e3);
}

}  // namespace
}  // namespace prox::testing
