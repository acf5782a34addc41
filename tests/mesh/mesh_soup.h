// What the mesh tests share: a triangle soup to build meshes from, checks of
// vectors and adjacency, and the unit cube as a glTF exporter writes it.
#pragma once

#include "mesh/mesh.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace prox::mesh_testing {

inline constexpr double kHalfTurn = 3.14159265358979323846;  // pi (snch/cone.h has its own kPi)

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

inline Mesh build_ok(const Soup& soup) {
  Status status(StatusCode::InvalidArgument, "not run");
  Mesh mesh = Mesh::build(soup.input(), status);
  EXPECT_TRUE(status.is_ok()) << status.message();
  return mesh;
}

inline bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

inline void expect_vec(const Vec3& got, const Vec3& want, double tol = 1e-15) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

inline std::vector<std::uint32_t> vertex_ring(const Mesh& m, std::uint32_t v) {
  return {m.vertex_triangles_begin(v), m.vertex_triangles_end(v)};
}

inline std::vector<std::uint32_t> edge_tris(const Mesh& m, std::uint32_t t, int k) {
  return {m.edge_triangles_begin(t, k), m.edge_triangles_end(t, k)};
}

// Each edge counted once: at its lowest triangle (edge lists ascend).
inline std::uint32_t edge_count(const Mesh& m) {
  std::uint32_t n = 0;
  for (std::uint32_t t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) n += *m.edge_triangles_begin(t, k) == t ? 1u : 0u;
  return n;
}

// The unit cube as a glTF exporter writes it: six quads with their own four
// corners each (24 vertices), counter-clockwise seen from outside, each split
// into (q0, q1, q2) and (q0, q2, q3).
inline Soup split_cube() {
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

}  // namespace prox::mesh_testing
