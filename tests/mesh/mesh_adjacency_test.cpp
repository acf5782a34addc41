// Mesh adjacency and edge normals: non-manifold edges, opposite faces,
// hand-built adjacency, a large soup welded in linear time, and the bunny.
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
  // The angles are weights good to 1e-12 (geometry::angle_from), not to
  // the last bit; a weighting by area or by count would be 0.1 off.
  expect_vec(m.vertex_normal(1), glm::normalize(sum), 1e-12);
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
