// Mesh building: validation, welding, degenerate triangles and normals on
// hand-built meshes (adjacency: mesh_adjacency_test.cpp).
#include "mesh/mesh.h"
#include "io/obj.h"
#include "mesh_soup.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace prox {
namespace {

using namespace mesh_testing;

TEST(Mesh, SplitCubeWeldsIntoAClosedManifold) {
  const Mesh m = build_ok(split_cube());
  const MeshStats& s = m.stats();
  EXPECT_EQ(s.input_vertices, 24u);
  EXPECT_EQ(s.input_triangles, 12u);
  EXPECT_EQ(s.vertices, 8u);
  EXPECT_EQ(m.vertex_count(), 8u);
  EXPECT_EQ(s.triangles, 12u);
  EXPECT_EQ(s.dropped_triangles, 0u);
  EXPECT_EQ(s.zero_area_triangles, 0u);
  EXPECT_EQ(s.boundary_edges, 0u);
  EXPECT_EQ(s.nonmanifold_edges, 0u);
  // 12 cube edges and 6 quad diagonals; V - E + F = 8 - 18 + 12 = 2.
  EXPECT_EQ(edge_count(m), 18u);
  for (std::uint32_t t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(edge_tris(m, t, k).size(), 2u) << "triangle " << t << " edge " << k;

  std::set<std::vector<double>> corners;
  for (std::uint32_t v = 0; v < m.vertex_count(); ++v) {
    const Vec3& p = m.vertex(v);
    corners.insert({p.x, p.y, p.z});
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(p[c] == 0.0 || p[c] == 1.0);
  }
  EXPECT_EQ(corners.size(), 8u);
  expect_vec(m.bounds().min, Vec3(0.0), 0.0);
  expect_vec(m.bounds().max, Vec3(1.0), 0.0);
  EXPECT_DOUBLE_EQ(m.longest_edge(), std::sqrt(2.0));
}

TEST(Mesh, SplitCubeNormals) {
  const Mesh m = build_ok(split_cube());
  const Vec3 center(0.5);
  for (std::uint32_t t = 0; t < m.triangle_count(); ++t) {
    // Outward along the axis on which the triangle's centroid sits off-center.
    const Triangle tri = m.triangle(t);
    const Vec3 off = (tri.v[0] + tri.v[1] + tri.v[2]) / 3.0 - center;
    Vec3 want(0.0);
    for (int c = 0; c < 3; ++c)
      if (std::abs(off[c]) == 0.5) want[c] = off[c] > 0 ? 1.0 : -1.0;
    expect_vec(m.face_normal(t), want);
    // Edge midpoints of the cube's edges sit on two faces, those of the
    // diagonals on one: in both cases the mean normal points away from the
    // center through the midpoint.
    for (int k = 0; k < 3; ++k) {
      const Vec3 mid = 0.5 * (tri.v[k] + tri.v[(k + 1) % 3]);
      expect_vec(m.edge_normal(t, k), glm::normalize(mid - center));
    }
  }
  // Each corner sees three faces, and on each face the triangles at the corner
  // add up to the face's 90 degree angle whether or not the split diagonal
  // starts there: angle weighting gives every face the same weight, so the
  // normal is the diagonal direction. Weighting by triangle count or area
  // would not: corners meet 3 to 6 triangles in this split.
  std::set<std::size_t> valences;
  for (std::uint32_t v = 0; v < m.vertex_count(); ++v) {
    valences.insert(vertex_ring(m, v).size());
    expect_vec(m.vertex_normal(v), glm::normalize(m.vertex(v) - center));
  }
  EXPECT_GT(valences.size(), 1u) << "the split must be uneven for this test to discriminate";
}

TEST(Mesh, WeldingIsExactAndFoldsNegativeZero) {
  Soup soup;
  const double next = std::nextafter(1.0, 2.0);
  soup.add(Vec3(-0.0, -0.0, -0.0));
  soup.add(Vec3(1.0, 0.0, 0.0));
  soup.add(Vec3(0.0, 1.0, 0.0));
  soup.add(Vec3(0.0, 0.0, 0.0));   // the same point as vertex 0
  soup.add(Vec3(next, 0.0, 0.0));  // one ulp from vertex 1: a different point
  soup.add(Vec3(0.0, -1.0, 0.0));
  soup.indices = {0, 1, 2, 3, 5, 4};
  const Mesh m = build_ok(soup);
  EXPECT_EQ(m.vertex_count(), 5u);
  EXPECT_EQ(m.indices(0)[0], m.indices(1)[0]);
  EXPECT_NE(m.indices(0)[1], m.indices(1)[2]);
  for (int c = 0; c < 3; ++c) EXPECT_FALSE(std::signbit(m.vertex(m.indices(1)[0])[c]));
}

TEST(Mesh, WeldedOrderIsFirstAppearanceWithoutUnreferencedVertices) {
  Soup soup;
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(1, 1, 0);
  soup.add(Vec3(9, 9, 9));  // unreferenced
  soup.add(a);
  soup.add(b);
  soup.add(c);
  soup.add(a);
  soup.add(d);
  soup.indices = {5, 2, 4, 1, 2, 3};
  const Mesh m = build_ok(soup);
  ASSERT_EQ(m.vertex_count(), 4u);
  expect_vec(m.vertex(0), a, 0.0);
  expect_vec(m.vertex(1), b, 0.0);
  expect_vec(m.vertex(2), c, 0.0);
  expect_vec(m.vertex(3), d, 0.0);
  EXPECT_EQ(m.indices(0), (std::array<std::uint32_t, 3>{3, 1, 0}));
  EXPECT_EQ(m.indices(1), (std::array<std::uint32_t, 3>{0, 1, 2}));
  expect_vec(m.bounds().min, Vec3(0, 0, 0), 0.0);
  expect_vec(m.bounds().max, Vec3(1, 1, 0), 0.0);
}

TEST(Mesh, SingleTriangle) {
  Soup soup;
  soup.add(Vec3(0, 0, 0));
  soup.add(Vec3(2, 0, 0));
  soup.add(Vec3(0, 1, 0));
  soup.indices = {0, 1, 2};
  const Mesh m = build_ok(soup);
  EXPECT_EQ(m.triangle_count(), 1u);
  EXPECT_EQ(m.stats().boundary_edges, 3u);
  EXPECT_EQ(m.stats().nonmanifold_edges, 0u);
  EXPECT_EQ(edge_count(m), 3u);
  EXPECT_EQ(m.input_triangle(0), 0u);
  expect_vec(m.face_normal(0), Vec3(0, 0, 1), 0.0);
  for (std::uint32_t v = 0; v < 3; ++v) {
    expect_vec(m.vertex_normal(v), Vec3(0, 0, 1), 0.0);
    EXPECT_EQ(vertex_ring(m, v), std::vector<std::uint32_t>{0});
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(edge_tris(m, 0, k), std::vector<std::uint32_t>{0});
    expect_vec(m.edge_normal(0, k), Vec3(0, 0, 1), 0.0);
  }
  EXPECT_DOUBLE_EQ(m.longest_edge(), std::sqrt(5.0));
  expect_vec(m.bounds().min, Vec3(0, 0, 0), 0.0);
  expect_vec(m.bounds().max, Vec3(2, 1, 0), 0.0);
}

TEST(Mesh, ClockwiseTriangleFacesDown) {
  Soup soup;
  soup.add(Vec3(0, 0, 0));
  soup.add(Vec3(0, 1, 0));
  soup.add(Vec3(1, 0, 0));
  soup.indices = {0, 1, 2};
  expect_vec(build_ok(soup).face_normal(0), Vec3(0, 0, -1), 0.0);
}

TEST(Mesh, RepeatedIndexIsDropped) {
  Soup soup;
  soup.add(Vec3(0, 0, 0));
  soup.add(Vec3(1, 0, 0));
  soup.add(Vec3(0, 1, 0));
  soup.add(Vec3(1, 0, 0));  // welds with vertex 1
  soup.indices = {0, 0, 1, 0, 1, 2, 1, 3, 2};
  const Mesh m = build_ok(soup);
  EXPECT_EQ(m.stats().input_triangles, 3u);
  EXPECT_EQ(m.stats().dropped_triangles, 2u);
  EXPECT_EQ(m.stats().triangles, 1u);
  ASSERT_EQ(m.triangle_count(), 1u);
  EXPECT_EQ(m.input_triangle(0), 1u);
}

TEST(Mesh, OnlyDegenerateTrianglesIsAnError) {
  Soup soup;
  soup.add(Vec3(0, 0, 0));
  soup.add(Vec3(1, 0, 0));
  soup.add(Vec3(0, 0, 0));
  soup.indices = {0, 1, 2, 1, 1, 1};
  Status status;
  const Mesh m = Mesh::build(soup.input(), status);
  EXPECT_EQ(status.code(), StatusCode::InvalidArgument);
  EXPECT_TRUE(contains(status.message(), "mesh has no non-degenerate triangles")) << status.message();
  EXPECT_TRUE(m.empty());
  EXPECT_EQ(m.vertex_count(), 0u);
}

TEST(Mesh, CollinearTriangleIsKeptWithoutNormal) {
  Soup soup;
  soup.add(Vec3(0, 0, 0));
  soup.add(Vec3(1, 0, 0));
  soup.add(Vec3(0, 1, 0));
  soup.add(Vec3(3, 0, 0));
  // The collinear triangle shares edge 0-1 with the proper one.
  soup.indices = {0, 1, 2, 1, 0, 3};
  const Mesh m = build_ok(soup);
  EXPECT_EQ(m.triangle_count(), 2u);
  EXPECT_EQ(m.stats().zero_area_triangles, 1u);
  EXPECT_EQ(m.stats().dropped_triangles, 0u);
  expect_vec(m.face_normal(0), Vec3(0, 0, 1), 0.0);
  expect_vec(m.face_normal(1), Vec3(0.0), 0.0);
  // Vertex 3 lies only on the collinear triangle; the others keep the proper
  // triangle's normal, and so does the shared edge.
  expect_vec(m.vertex_normal(3), Vec3(0.0), 0.0);
  expect_vec(m.vertex_normal(0), Vec3(0, 0, 1), 0.0);
  expect_vec(m.edge_normal(1, 0), Vec3(0, 0, 1), 0.0);
  expect_vec(m.edge_normal(1, 1), Vec3(0.0), 0.0);
  EXPECT_EQ(edge_tris(m, 1, 0), (std::vector<std::uint32_t>{0, 1}));
}

TEST(Mesh, ExtremeScalesAndSliversGiveUnitNormals) {
  // Squares of these lengths under- or overflow; the normal must not. (Below
  // about 1e-160 the exact predicate's products underflow, see predicates.cpp.)
  for (const double scale : {1e-150, 1e-100, 1.0, 1e100, 1e150, 1e300}) {
    SCOPED_TRACE(scale);
    Soup soup;
    soup.add(Vec3(0, 0, 0));
    soup.add(Vec3(scale, 0, 0));
    soup.add(Vec3(0, scale, 0));
    soup.indices = {0, 1, 2};
    const Mesh m = build_ok(soup);
    expect_vec(m.face_normal(0), Vec3(0, 0, 1), 0.0);
    expect_vec(m.vertex_normal(1), Vec3(0, 0, 1), 0.0);
    EXPECT_NEAR(m.longest_edge() / (std::sqrt(2.0) * scale), 1.0, 1e-15) << scale;
  }
  // Further down the predicate may call a triangle collinear: it then has no
  // normal and is counted, and nothing is NaN.
  Soup tiny;
  tiny.add(Vec3(0, 0, 0));
  tiny.add(Vec3(1e-300, 0, 0));
  tiny.add(Vec3(0, 1e-300, 0));
  tiny.indices = {0, 1, 2};
  const Mesh t = build_ok(tiny);
  const double len = glm::length(t.face_normal(0));
  EXPECT_TRUE(len == 1.0 || (len == 0.0 && t.stats().zero_area_triangles == 1u)) << len;
  EXPECT_FALSE(std::isnan(glm::length(t.vertex_normal(0))));

  // A sliver 1e-200 thick: its cross product squared underflows.
  Soup sliver;
  sliver.add(Vec3(0, 0, 0));
  sliver.add(Vec3(1, 0, 0));
  sliver.add(Vec3(2, 1e-200, 0));
  sliver.indices = {0, 1, 2};
  const Mesh m = build_ok(sliver);
  EXPECT_EQ(m.stats().zero_area_triangles, 0u);
  expect_vec(m.face_normal(0), Vec3(0, 0, 1), 0.0);
  for (std::uint32_t v = 0; v < 3; ++v) expect_vec(m.vertex_normal(v), Vec3(0, 0, 1), 0.0);
}

TEST(Mesh, NearlyCollinearTrianglesNeverGiveNaN) {
  // The third vertex walks off the line 0.1, 0.2, 0.3 by a few ulps: the
  // exact cross product is non-zero but rounding may cancel it.
  int with_normal = 0;
  for (int i = -8; i <= 8; ++i) {
    Soup soup;
    soup.add(Vec3(0.1, 0.2, 0.3));
    soup.add(Vec3(0.3, 0.6, 0.9));
    double z = 1.5;
    for (int s = 0; s < std::abs(i); ++s) z = std::nextafter(z, i > 0 ? 2.0 : 1.0);
    soup.add(Vec3(0.5, 1.0, z));
    soup.indices = {0, 1, 2};
    const Mesh m = build_ok(soup);
    const double len = glm::length(m.face_normal(0));
    EXPECT_TRUE(len == 0.0 || std::abs(len - 1.0) < 1e-15) << i << ": " << len;
    with_normal += len > 0.0 ? 1 : 0;
    for (std::uint32_t v = 0; v < 3; ++v) {
      const double vlen = glm::length(m.vertex_normal(v));
      EXPECT_TRUE(vlen == 0.0 || std::abs(vlen - 1.0) < 1e-15) << i << ": " << vlen;
    }
  }
  EXPECT_GT(with_normal, 0);
}

TEST(Mesh, NonFiniteCoordinatesAreNamed) {
  struct Case {
    std::uint32_t vertex;
    int axis;
    double value;
    const char* axis_name;
    const char* value_name;
  };
  const double inf = std::numeric_limits<double>::infinity();
  for (const Case& c : {Case{17, 1, std::numeric_limits<double>::quiet_NaN(), "y", "nan"},
                        Case{3, 2, -inf, "z", "-inf"}, Case{0, 0, inf, "x", "inf"}}) {
    Soup soup;
    for (int i = 0; i < 20; ++i) soup.add(Vec3(i, 2 * i, 3 * i + 1));
    soup.indices = {0, 1, 2};
    soup.positions[3 * c.vertex + static_cast<std::uint32_t>(c.axis)] = c.value;
    Status status;
    const Mesh m = Mesh::build(soup.input(), status);
    EXPECT_EQ(status.code(), StatusCode::InvalidArgument);
    const std::string want = "vertex " + std::to_string(c.vertex) + " has a non-finite " + c.axis_name +
                             " coordinate (" + c.value_name + ")";
    EXPECT_TRUE(contains(status.message(), want)) << status.message();
    EXPECT_TRUE(m.empty());
  }
}

TEST(Mesh, OutOfRangeIndexIsNamed) {
  Soup soup;
  for (int i = 0; i < 5; ++i) soup.add(Vec3(i, i * i, 0));
  soup.indices = {0, 1, 2, 1, 2, 3, 2, 7, 4};
  Status status;
  const Mesh m = Mesh::build(soup.input(), status);
  EXPECT_EQ(status.code(), StatusCode::InvalidArgument);
  EXPECT_TRUE(contains(status.message(), "triangle 2")) << status.message();
  EXPECT_TRUE(contains(status.message(), "index 7")) << status.message();
  EXPECT_TRUE(m.empty());
}

TEST(Mesh, EmptyAndNullInputs) {
  Soup soup;
  soup.add(Vec3(0, 0, 0));
  soup.add(Vec3(1, 0, 0));
  soup.add(Vec3(0, 1, 0));
  soup.indices = {0, 1, 2};
  Status status;

  MeshInput in = soup.input();
  in.triangle_count = 0;
  EXPECT_TRUE(Mesh::build(in, status).empty());
  EXPECT_EQ(status.code(), StatusCode::InvalidArgument);
  EXPECT_TRUE(contains(status.message(), "mesh has no triangles")) << status.message();

  EXPECT_TRUE(Mesh::build(MeshInput{}, status).empty());
  EXPECT_TRUE(contains(status.message(), "mesh has no triangles")) << status.message();

  in = soup.input();
  in.indices = nullptr;
  EXPECT_TRUE(Mesh::build(in, status).empty());
  EXPECT_EQ(status.code(), StatusCode::InvalidArgument);
  EXPECT_TRUE(contains(status.message(), "indices")) << status.message();

  in = soup.input();
  in.positions = nullptr;
  EXPECT_TRUE(Mesh::build(in, status).empty());
  EXPECT_EQ(status.code(), StatusCode::InvalidArgument);
  EXPECT_TRUE(contains(status.message(), "positions")) << status.message();

  // No vertices at all: every index is out of range.
  in = soup.input();
  in.positions = nullptr;
  in.vertex_count = 0;
  EXPECT_TRUE(Mesh::build(in, status).empty());
  EXPECT_EQ(status.code(), StatusCode::InvalidArgument);
  EXPECT_TRUE(contains(status.message(), "triangle 0")) << status.message();

  // A successful build clears an earlier error.
  EXPECT_FALSE(Mesh::build(soup.input(), status).empty());
  EXPECT_TRUE(status.is_ok()) << status.message();
}

}  // namespace
}  // namespace prox
