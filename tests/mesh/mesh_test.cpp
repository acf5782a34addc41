// Mesh building: validation, welding, degenerate triangles, normals and
// adjacency on hand-built meshes, and the real bunny asset.
#include "mesh/mesh.h"
#include "io/obj.h"

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

constexpr double kHalfTurn = 3.14159265358979323846;  // pi (snch/cone.h has its own kPi)

struct Soup {
  std::vector<double> positions;
  std::vector<std::uint32_t> indices;

  std::uint32_t add(const Vec3& p) {
    positions.insert(positions.end(), {p.x, p.y, p.z});
    return static_cast<std::uint32_t>(positions.size() / 3 - 1);
  }
  MeshInput input() const {
    MeshInput in;
    in.positions = positions.data();
    in.vertex_count = static_cast<std::uint32_t>(positions.size() / 3);
    in.indices = indices.data();
    in.triangle_count = static_cast<std::uint32_t>(indices.size() / 3);
    return in;
  }
};

Mesh build_ok(const Soup& soup) {
  Status status(StatusCode::InvalidArgument, "not run");
  Mesh mesh = Mesh::build(soup.input(), status);
  EXPECT_TRUE(status.is_ok()) << status.message();
  return mesh;
}

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

void expect_vec(const Vec3& got, const Vec3& want, double tol = 1e-15) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

std::vector<std::uint32_t> vertex_ring(const Mesh& m, std::uint32_t v) {
  return {m.vertex_triangles_begin(v), m.vertex_triangles_end(v)};
}

std::vector<std::uint32_t> edge_tris(const Mesh& m, std::uint32_t t, int k) {
  return {m.edge_triangles_begin(t, k), m.edge_triangles_end(t, k)};
}

// Each edge counted once: at its lowest triangle (edge lists ascend).
std::uint32_t edge_count(const Mesh& m) {
  std::uint32_t n = 0;
  for (std::uint32_t t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) n += *m.edge_triangles_begin(t, k) == t ? 1u : 0u;
  return n;
}

// The unit cube as a glTF exporter writes it: six quads with their own four
// corners each (24 vertices), counter-clockwise seen from outside, each split
// into (q0, q1, q2) and (q0, q2, q3).
Soup split_cube() {
  const int quads[6][4][3] = {
      {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}},  // +x
      {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}},  // -x
      {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},  // +y
      {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}},  // -y
      {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},  // +z
      {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}},  // -z
  };
  Soup soup;
  for (const auto& quad : quads) {
    std::uint32_t q[4];
    for (int i = 0; i < 4; ++i) q[i] = soup.add(Vec3(quad[i][0], quad[i][1], quad[i][2]));
    soup.indices.insert(soup.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  }
  return soup;
}

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

TEST(Mesh, NonManifoldEdgeIsCounted) {
  Soup soup;
  soup.add(Vec3(0, 0, 0));
  soup.add(Vec3(1, 0, 0));
  soup.add(Vec3(0, 1, 0));
  soup.add(Vec3(0, -1, 0));
  soup.add(Vec3(0, 0, 1));
  soup.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};  // three fins on edge 0-1
  const Mesh m = build_ok(soup);
  EXPECT_EQ(m.stats().nonmanifold_edges, 1u);
  EXPECT_EQ(m.stats().boundary_edges, 6u);
  EXPECT_EQ(edge_count(m), 7u);
  const std::vector<std::uint32_t> fins{0, 1, 2};
  EXPECT_EQ(edge_tris(m, 0, 0), fins);
  EXPECT_EQ(edge_tris(m, 1, 0), fins);
  EXPECT_EQ(edge_tris(m, 2, 0), fins);
  // Normals +z, +z (the second fin is wound the other way round) and -y.
  expect_vec(m.edge_normal(0, 0), glm::normalize(Vec3(0, -1, 2)));
}

TEST(Mesh, OppositeFacesCancelInTheEdgeNormal) {
  Soup soup;
  soup.add(Vec3(0, 0, 0));
  soup.add(Vec3(1, 0, 0));
  soup.add(Vec3(0, 1, 0));
  soup.indices = {0, 1, 2, 0, 2, 1};  // a two-sided sheet
  const Mesh m = build_ok(soup);
  EXPECT_EQ(m.stats().boundary_edges, 0u);
  expect_vec(m.edge_normal(0, 0), Vec3(0.0), 0.0);
  for (std::uint32_t v = 0; v < 3; ++v) expect_vec(m.vertex_normal(v), Vec3(0.0), 0.0);
}

TEST(Mesh, RoundingResidueOfOppositeFacesIsNotANormal) {
  // Off the axes the two windings of a triangle round differently, so their
  // normals need not cancel exactly; the residue is noise, not a direction.
  int inexact = 0;
  for (int i = 1; i <= 20; ++i) {
    Soup soup;
    soup.add(Vec3(0.1 * i, 0.3, -0.7));
    soup.add(Vec3(1.3, 0.2 / i, 0.9));
    soup.add(Vec3(-0.4, 1.1, 0.3 * i));
    soup.indices = {0, 1, 2, 0, 2, 1};
    const Mesh m = build_ok(soup);
    inexact += m.face_normal(0) + m.face_normal(1) != Vec3(0.0) ? 1 : 0;
    for (std::uint32_t v = 0; v < 3; ++v) expect_vec(m.vertex_normal(v), Vec3(0.0), 0.0);
    for (int k = 0; k < 3; ++k) expect_vec(m.edge_normal(0, k), Vec3(0.0), 0.0);
  }
  EXPECT_GT(inexact, 0) << "no case exercises an inexact cancellation";
}

TEST(Mesh, SquareAdjacency) {
  Soup soup;
  soup.add(Vec3(0, 0, 0));
  soup.add(Vec3(1, 0, 0));
  soup.add(Vec3(1, 1, 0));
  soup.add(Vec3(0, 1, 0));
  soup.indices = {0, 1, 2, 0, 2, 3};
  const Mesh m = build_ok(soup);
  EXPECT_EQ(vertex_ring(m, 0), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(vertex_ring(m, 1), (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(vertex_ring(m, 2), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(vertex_ring(m, 3), (std::vector<std::uint32_t>{1}));
  // The diagonal is edge 2 (2 -> 0) of triangle 0 and edge 0 (0 -> 2) of triangle 1.
  EXPECT_EQ(edge_tris(m, 0, 2), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(edge_tris(m, 1, 0), (std::vector<std::uint32_t>{0, 1}));
  const std::pair<std::uint32_t, int> outer[] = {{0, 0}, {0, 1}, {1, 1}, {1, 2}};
  for (const auto& [t, k] : outer) EXPECT_EQ(edge_tris(m, t, k), std::vector<std::uint32_t>{t});
  EXPECT_EQ(m.stats().boundary_edges, 4u);
  EXPECT_EQ(edge_count(m), 5u);
}

TEST(Mesh, TetrahedronAdjacencyAndNormals) {
  Soup soup;
  soup.add(Vec3(0, 0, 0));
  soup.add(Vec3(1, 0, 0));
  soup.add(Vec3(0, 1, 0));
  soup.add(Vec3(0, 0, 1));
  // Outward: -z, -y, -x, and (1, 1, 1).
  soup.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  const Mesh m = build_ok(soup);
  EXPECT_EQ(m.stats().boundary_edges, 0u);
  EXPECT_EQ(edge_count(m), 6u);
  EXPECT_EQ(vertex_ring(m, 0), (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(vertex_ring(m, 1), (std::vector<std::uint32_t>{0, 1, 3}));
  EXPECT_EQ(vertex_ring(m, 2), (std::vector<std::uint32_t>{0, 2, 3}));
  EXPECT_EQ(vertex_ring(m, 3), (std::vector<std::uint32_t>{1, 2, 3}));
  // edge_triangles[t][k], worked out from the index list above.
  const std::uint32_t want[4][3][2] = {
      {{0, 2}, {0, 3}, {0, 1}},
      {{0, 1}, {1, 3}, {1, 2}},
      {{1, 2}, {2, 3}, {0, 2}},
      {{0, 3}, {2, 3}, {1, 3}},
  };
  for (std::uint32_t t = 0; t < 4; ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(edge_tris(m, t, k), (std::vector<std::uint32_t>{want[t][k][0], want[t][k][1]}))
          << "triangle " << t << " edge " << k;

  expect_vec(m.face_normal(3), Vec3(1.0) / std::sqrt(3.0));
  // Vertex 0: three right angles on the -x, -y, -z faces.
  expect_vec(m.vertex_normal(0), Vec3(-1.0) / std::sqrt(3.0));
  // Vertex 1: 45 degrees on the -z and -y faces, 60 on the equilateral one.
  const Vec3 sum =
      kHalfTurn / 4 * Vec3(0, 0, -1) + kHalfTurn / 4 * Vec3(0, -1, 0) + kHalfTurn / 3 * Vec3(1, 1, 1) / std::sqrt(3.0);
  expect_vec(m.vertex_normal(1), glm::normalize(sum));
  // Edge 1-2 joins the -z face and the slanted one.
  expect_vec(m.edge_normal(3, 0), glm::normalize(Vec3(0, 0, -1) + Vec3(1, 1, 1) / std::sqrt(3.0)));
}

// A torus grid of n x n quads, with every triangle given its own three
// vertices, as a non-indexed export would: it must weld back to n^2 vertices.
TEST(Mesh, LargeTriangleSoupWeldsInLinearTime) {
  const std::uint32_t n = 475;  // 451,250 triangles
  std::vector<Vec3> grid(std::size_t{n} * n);
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < n; ++j) {
      const double u = 2 * kHalfTurn * i / n, w = 2 * kHalfTurn * j / n;
      grid[std::size_t{i} * n + j] = Vec3((2 + 0.5 * std::cos(w)) * std::cos(u),
                                          (2 + 0.5 * std::cos(w)) * std::sin(u), 0.5 * std::sin(w));
    }
  const auto at = [&](std::uint32_t i, std::uint32_t j) { return grid[std::size_t{i % n} * n + j % n]; };
  Soup soup;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < n; ++j)
      for (const Vec3& p :
           {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)})
        soup.indices.push_back(soup.add(p));

  const auto start = std::chrono::steady_clock::now();
  const Mesh m = build_ok(soup);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[ timing   ] " << m.triangle_count() << " triangles from " << m.stats().input_vertices
            << " input vertices built in " << seconds * 1e3 << " ms\n";
  // A quadratic step would take minutes; the bound leaves room for sanitizers.
  EXPECT_LT(seconds, 10.0);

  EXPECT_EQ(m.vertex_count(), n * n);
  EXPECT_EQ(m.triangle_count(), 2 * n * n);
  EXPECT_EQ(m.stats().boundary_edges, 0u);
  EXPECT_EQ(m.stats().nonmanifold_edges, 0u);
  EXPECT_EQ(edge_count(m), 3 * n * n);  // Euler characteristic 0: a torus
}

std::string shared_asset(const std::string& name) { return std::string(PROX_SHARED_ASSETS_DIR) + "/" + name; }

TEST(Mesh, Bunny) {
  ASSERT_TRUE(std::filesystem::is_directory(PROX_SHARED_ASSETS_DIR))
      << "the shared test assets are missing: expected them in " << PROX_SHARED_ASSETS_DIR;
  const auto t0 = std::chrono::steady_clock::now();
  io::ObjData obj;
  const Status read = io::read_obj(shared_asset("bunny.obj"), obj);
  ASSERT_TRUE(read.is_ok()) << read.message();
  const auto t1 = std::chrono::steady_clock::now();
  MeshInput in;
  in.positions = obj.positions.data();
  in.vertex_count = static_cast<std::uint32_t>(obj.positions.size() / 3);
  in.indices = obj.indices.data();
  in.triangle_count = static_cast<std::uint32_t>(obj.indices.size() / 3);
  Status status;
  const Mesh m = Mesh::build(in, status);
  const auto t2 = std::chrono::steady_clock::now();
  ASSERT_TRUE(status.is_ok()) << status.message();
  std::cout << "[ timing   ] bunny: read " << std::chrono::duration<double, std::milli>(t1 - t0).count()
            << " ms, build " << std::chrono::duration<double, std::milli>(t2 - t1).count() << " ms\n";

  const MeshStats& s = m.stats();
  EXPECT_EQ(s.input_vertices, 13934u);
  EXPECT_EQ(s.vertices, 13934u);
  EXPECT_EQ(s.triangles, 27864u);
  EXPECT_EQ(s.dropped_triangles, 0u);
  EXPECT_EQ(s.zero_area_triangles, 0u);
  EXPECT_EQ(s.boundary_edges, 0u);
  EXPECT_EQ(s.nonmanifold_edges, 0u);
  const std::int64_t euler = std::int64_t{m.vertex_count()} - edge_count(m) + m.triangle_count();
  EXPECT_EQ(euler, 2);

  const Vec3 size = m.bounds().max - m.bounds().min;
  EXPECT_NEAR(size.x, 0.155, 1e-3);
  EXPECT_NEAR(size.y, 0.154, 1e-3);
  EXPECT_NEAR(size.z, 0.120, 1e-3);

  double volume = 0.0;
  for (std::uint32_t t = 0; t < m.triangle_count(); ++t) {
    const Triangle tri = m.triangle(t);
    EXPECT_NEAR(glm::length(m.face_normal(t)), 1.0, 1e-14) << "triangle " << t;
    EXPECT_GT(glm::dot(m.face_normal(t), glm::cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0])), 0.0);
    volume += glm::dot(tri.v[0], glm::cross(tri.v[1], tri.v[2])) / 6.0;
    // Consistent winding: the other triangle on each edge runs it backwards.
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = m.indices(t)[k], b = m.indices(t)[(k + 1) % 3];
      const std::vector<std::uint32_t> sharing = edge_tris(m, t, k);
      ASSERT_EQ(sharing.size(), 2u);
      const std::uint32_t other = sharing[0] == t ? sharing[1] : sharing[0];
      ASSERT_NE(other, t);
      const auto& o = m.indices(other);
      bool reversed = false;
      for (int j = 0; j < 3; ++j) reversed = reversed || (o[j] == b && o[(j + 1) % 3] == a);
      EXPECT_TRUE(reversed) << "triangle " << t << " edge " << k << " and triangle " << other;
    }
  }
  // Outward normals enclose a positive volume, less than the bounding box's.
  EXPECT_GT(volume, 0.0);
  EXPECT_LT(volume, size.x * size.y * size.z);
  for (std::uint32_t v = 0; v < m.vertex_count(); ++v)
    EXPECT_NEAR(glm::length(m.vertex_normal(v)), 1.0, 1e-14) << "vertex " << v;
}

}  // namespace
}  // namespace prox
