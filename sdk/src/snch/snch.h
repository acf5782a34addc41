// Spatialized Normal Cone Hierarchy (Johnson and Cohen 2001): a bounding
// sphere tree over a mesh's triangles with a cone of normals at every node.
#pragma once

#include "mesh/mesh.h"
#include "geometry/visibility.h"
#include "snch/cone.h"

#include <cstdint>
#include <vector>

namespace prox {

class WorkerPool;

struct SnchNode {
  Vec3 center{0.0};  // bounding sphere of the node's triangles, mesh units
  double radius = 0.0;
  // Directions along which a local minimum distance pair can leave the
  // surface of any triangle below this node (see docs/snch.md), as the
  // cosine and sine of its half-angle, which the searches test with.
  CosCone cone;
  // Inner node: children `first` and `second`. Leaf: `first` is the
  // triangle, `second` is kLeaf.
  std::uint32_t first = 0, second = 0;

  static constexpr std::uint32_t kLeaf = 0xFFFFFFFFu;
  bool is_leaf() const { return second == kLeaf; }
};

// A node's triangles' axis-aligned box in the mesh's frame. All boxes of a
// mesh share its axes, so under a pose the rotation between two meshes'
// boxes is the same for every node pair, and the separating-axis bound costs
// no per-pair matrix product. Far tighter than the sphere around long, thin
// or flat triangles (CAD), which is where the sphere test lets most through.
struct SnchBox {
  Vec3 center{0.0};
  Vec3 half{0.0};  // half extents, rounded outward
};

// How far a node's triangles reach along its cone's axis, from its sphere's
// centre: every vertex v below the node has lo <= dot(v - center, axis) <=
// hi. Where the triangles below are nearly flat, a thin slab, whatever the
// pose: a bound between two nodes that faces each other as an oriented box
// would, which the axis-aligned boxes cannot where a mesh is turned.
struct SnchSlab {
  double lo = 0.0, hi = 0.0;  // rounded outward
};

struct SnchStats {
  std::uint32_t nodes = 0;
  std::uint32_t leaves = 0;
  std::uint32_t depth = 0;             // edges on the longest root-to-leaf path
  std::uint32_t unbounded_leaves = 0;  // leaves whose cone holds every direction
  double build_seconds = 0.0;
  std::size_t memory_bytes = 0;
  // Refits since the last build, and the last one's time.
  std::uint32_t refits = 0;
  double refit_seconds = 0.0;
  // How far refitting has loosened the tree (docs/dynamic-scenes.md): the
  // inner nodes' summed radii over the root's radius, now, over the same
  // ratio when the tree was built. 1 after a build; a rebuild is due once it
  // passes kRebuildDegradation.
  double degradation = 1.0;
};

// Built once per mesh, top-down: each node's triangles are split at the median
// of their centroids along the widest axis of the centroids' box. Deterministic:
// the same mesh gives the same tree on every run and platform.
class Snch {
 public:
  explicit Snch(const Mesh& mesh);

  // Past this degradation (stats().degradation) a refitted tree is rebuilt.
  static constexpr double kRebuildDegradation = 1.5;

  // Refits the tree to `mesh`, the mesh it was built for with its vertices
  // moved (same topology): every node's sphere, box and cone bottom-up from
  // the triangles' new positions, keeping the tree's shape; the slabs are
  // dropped (has_slabs()) until the next build. Linear time; the
  // bounds stay conservative, only looser than a fresh build's
  // (stats().degradation says how much). With a pool, the vertices and the
  // subtrees are refitted on its threads; the tree is the same bit for bit.
  void refit(const Mesh& mesh, WorkerPool* pool = nullptr);
  // Becomes `current` refitted to `mesh` (current's mesh moved), reusing
  // this tree's storage: what a deforming mesh's next shape is made from
  // when a retired shape's tree is at hand. Where this tree is an older
  // refit of the same build, only the bounds are written (refit() writes
  // them all); else current is copied first.
  void refit_as(const Snch& current, const Mesh& mesh, WorkerPool* pool = nullptr);

  const std::vector<SnchNode>& nodes() const { return nodes_; }
  const SnchNode& root() const { return nodes_[0]; }
  const SnchNode& node(std::uint32_t i) const { return nodes_[i]; }
  // The box of node i (same index as nodes()).
  const SnchBox& box(std::uint32_t i) const { return boxes_[i]; }
  // The slab of node i along its cone's axis (same index as nodes()), when
  // has_slabs(): a built tree has them, a refitted one not (refit()).
  const SnchSlab& slab(std::uint32_t i) const { return slabs_[i]; }
  bool has_slabs() const { return slabs_valid_; }
  const SnchStats& stats() const { return stats_; }
  // False for a closed, consistently wound surface, which has an inside: a
  // contact can only reach it from outside, along its normals. True for an
  // open, non-manifold or folded surface, which can be touched from either
  // side: the searches then take each normal cone together with its reverse.
  bool two_sided() const { return two_sided_; }
  // The half-angle of the cone of directions in which a closest pair can
  // leave the surface at vertex v, about its vertex normal, as its cosine
  // and sine: the largest angle to a face normal around it; a right angle
  // (nothing known) where the surface is open or folded. Used by the
  // visibility pre-test.
  const geometry::Spread& vertex_spread(std::uint32_t v) const { return vertex_spread_[v]; }

  // The leaf cone of triangle t (also stored in its leaf): it bounds the
  // normals of every triangle sharing a vertex with t, or holds every
  // direction where the surface is open or folded there (`open`, by vertex).
  static Cone leaf_cone(const Mesh& mesh, std::uint32_t t, const std::vector<std::uint8_t>& open);

 private:
  Snch() = default;

  std::vector<SnchNode> nodes_;
  std::vector<SnchBox> boxes_;
  std::vector<SnchSlab> slabs_;
  bool slabs_valid_ = true;
  std::vector<geometry::Spread> vertex_spread_;
  // By vertex: the surface around it is open or folded (topology alone, so
  // a refit keeps it).
  std::vector<std::uint8_t> open_;
  // The cone of the face normals around vertex v about its vertex normal,
  // as a refit computes it; everything where the surface is open there.
  CosCone refit_vertex_cone(const Mesh& mesh, std::uint32_t v) const;
  // Triangle t's leaf cone in a refit, from its vertices' cones: it holds
  // what leaf_cone() holds.
  static CosCone refit_leaf_cone(const Mesh& mesh, std::uint32_t t, const CosCone* vertex_cone);
  // A refit's unit of work: the subtree under `root`, whose descendants are
  // exactly the nodes [begin, end) (a node's children are made side by side
  // and the first one's subtree is built whole before the second's, so a
  // subtree's descendants are contiguous).
  struct RefitTask {
    std::uint32_t root, begin, end;
  };
  // The subtrees a refit splits into (at most kRefitTasks, about equal), and
  // the nodes above them, in ascending order.
  std::vector<RefitTask> refit_tasks_;
  std::vector<std::uint32_t> refit_top_;
  static constexpr std::size_t kRefitTasks = 64;
  void plan_refit();
  // Calls refit_node(i) on every node, children before their parent, the
  // subtrees on the pool's threads where there is one; returns the inner
  // nodes' summed radii over the root's (how much room they take for the
  // size of the whole; scale-free, and blind to the leaves, which are the
  // triangles' own spheres whatever the tree), summed in a fixed order.
  template <class RefitNode>
  double sweep(const RefitNode& refit_node, WorkerPool* pool);
  // Inner node i's sphere, box and cone from its children's.
  void refit_inner(std::uint32_t i);
  // That ratio for the built tree, its inner nodes as a refit fits them.
  double built_ratio_ = 1.0;
  // Every vertex's spread (vertex_spread) from the mesh's normals, as a
  // build takes it (a refit takes it from its vertex cones).
  void compute_vertex_spread(const Mesh& mesh);
  bool two_sided_ = false;
  SnchStats stats_;
  // Unique to each build; copies and refits keep it, so two trees with the
  // same id have the same nodes' children and leaves' triangles.
  std::uint64_t build_id_ = 0;
};

}  // namespace prox
