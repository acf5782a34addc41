// Indexed triangle meshes with the topology the engine walks on.
#pragma once

#include "common/status.h"
#include "geometry/types.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace prox {

class WorkerPool;

inline constexpr std::uint32_t kNoTriangle = 0xFFFFFFFFu;
inline constexpr std::uint32_t kNoVertex = 0xFFFFFFFFu;

struct Aabb {
  Vec3 min{0.0}, max{0.0};
};

// What building a mesh found in its input.
struct MeshStats {
  std::uint32_t input_vertices = 0;
  std::uint32_t input_triangles = 0;
  std::uint32_t vertices = 0;             // after welding identical positions
  std::uint32_t triangles = 0;            // after dropping index-degenerate ones
  std::uint32_t dropped_triangles = 0;    // repeated a vertex after welding: dropped
  std::uint32_t zero_area_triangles = 0;  // distinct vertices but collinear: kept
  std::uint32_t boundary_edges = 0;       // edges with one triangle
  std::uint32_t nonmanifold_edges = 0;    // edges with three or more triangles
};

// Input to Mesh::build. Positions are x, y, z triples; each triangle is three
// indices into them.
struct MeshInput {
  const double* positions = nullptr;
  std::uint32_t vertex_count = 0;
  const std::uint32_t* indices = nullptr;
  std::uint32_t triangle_count = 0;
};

// A mesh of fixed topology: vertices welded by exact position (glTF and OBJ split
// vertices at UV and normal seams; adjacency must follow the surface), with
// vertex -> triangles and edge -> triangles adjacency and face, edge and
// vertex normals. Triangles keep the input's winding; normals point to the
// side from which the triangle's vertices turn counter-clockwise.
class Mesh {
 public:
  // Validates the input (non-empty, finite coordinates, indices in range) and
  // builds the topology. On error `status` names the offending input and the
  // returned mesh is empty.
  static Mesh build(const MeshInput& input, Status& status);

  // Moves the vertices (x, y, z per welded vertex, `count` of them: the
  // same number), keeping the topology; the normals, bounds and longest
  // edge follow. On error (a count that differs, a non-finite coordinate,
  // named by vertex) nothing changes. With a pool the normals are computed
  // on its threads, the same bit for bit.
  Status set_vertices(const double* positions, std::uint32_t count, WorkerPool* pool = nullptr);

  std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(vertices_.size()); }
  std::uint32_t triangle_count() const { return static_cast<std::uint32_t>(topology_->triangles.size()); }
  bool empty() const { return topology_->triangles.empty(); }

  const Vec3& vertex(std::uint32_t v) const { return vertices_[v]; }
  const std::array<std::uint32_t, 3>& indices(std::uint32_t t) const { return topology_->triangles[t]; }
  Triangle triangle(std::uint32_t t) const {
    const auto& i = topology_->triangles[t];
    return {{vertices_[i[0]], vertices_[i[1]], vertices_[i[2]]}};
  }
  // The input triangle this triangle came from (dropped ones leave gaps).
  std::uint32_t input_triangle(std::uint32_t t) const { return topology_->input_triangle[t]; }
  // The vertex input vertex `input` was welded into, or kNoVertex when no
  // kept triangle uses it. Several input vertices share one when they had
  // the same position (a glTF UV seam); a deformation that moves them apart
  // later keeps the mesh's topology, so one of them must speak for the
  // vertex: the rig (mesh/rig.h) takes the first in input order.
  std::uint32_t welded_vertex(std::uint32_t input) const { return topology_->input_vertex[input]; }
  std::uint32_t input_vertex_count() const { return static_cast<std::uint32_t>(topology_->input_vertex.size()); }

  // Unit face normal; zero for a zero-area triangle.
  const Vec3& face_normal(std::uint32_t t) const { return face_normals_[t]; }
  // Unit vertex normal: the angle-weighted mean of the incident face normals
  // (zero if they cancel or all incident triangles have zero area).
  const Vec3& vertex_normal(std::uint32_t v) const { return vertex_normals_[v]; }
  // Unit normal of edge k of triangle t: the mean of the normals of the
  // triangles sharing the edge.
  Vec3 edge_normal(std::uint32_t t, int k) const;

  // Triangles incident to vertex v (its one-ring), ascending.
  const std::uint32_t* vertex_triangles_begin(std::uint32_t v) const;
  const std::uint32_t* vertex_triangles_end(std::uint32_t v) const;
  // Triangles sharing edge k (vertex k to vertex k+1) of triangle t,
  // including t, ascending: one on a boundary, two on a manifold edge.
  const std::uint32_t* edge_triangles_begin(std::uint32_t t, int k) const;
  const std::uint32_t* edge_triangles_end(std::uint32_t t, int k) const;

  // Mesh-wide id of edge k of triangle t (the same for every triangle
  // sharing the edge), in [0, edge_count()).
  std::uint32_t edge_id(std::uint32_t t, int k) const {
    return topology_->triangle_edge[3 * t + static_cast<std::uint32_t>(k)];
  }
  std::uint32_t edge_count() const {
    return topology_->edge_tri_offsets.empty() ? 0u : static_cast<std::uint32_t>(topology_->edge_tri_offsets.size() - 1);
  }

  const Aabb& bounds() const { return bounds_; }
  const MeshStats& stats() const { return stats_; }
  // The longest edge of the mesh; sizes relative tolerances.
  double longest_edge() const { return longest_edge_; }

 private:
  // What never changes after build: the triangles, the welding maps and the
  // adjacency. Shared by every copy, so that a deformed copy of the mesh
  // (set_vertices on a copy, as a scene's new version is made) copies only
  // the vertices and normals.
  struct Topology {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<std::uint32_t> input_triangle;
    std::vector<std::uint32_t> input_vertex;  // input vertex -> vertex, or kNoVertex
    // CSR adjacency: vertex -> triangles.
    std::vector<std::uint32_t> vertex_tri_offsets, vertex_tri;
    // Per triangle edge (3 t + k) -> an edge id; edge id -> triangles (CSR).
    std::vector<std::uint32_t> triangle_edge;
    std::vector<std::uint32_t> edge_tri_offsets, edge_tri;
  };
  static std::shared_ptr<const Topology> empty_topology();

  // Bounds, face and vertex normals, zero-area count and longest edge from
  // the vertices, triangles and the vertex -> triangles adjacency.
  void compute_geometry(WorkerPool* pool = nullptr);

  std::shared_ptr<const Topology> topology_ = empty_topology();
  std::vector<Vec3> vertices_;
  std::vector<Vec3> face_normals_;
  std::vector<Vec3> vertex_normals_;
  Aabb bounds_;
  MeshStats stats_;
  double longest_edge_ = 0.0;
};

}  // namespace prox
