// Local minimum distance (LMD) pairs between two meshes, and the query that
// produces them.
#pragma once

#include "contact/pose.h"
#include "mesh/mesh.h"
#include "snch/snch.h"

#include <cstdint>
#include <vector>

namespace prox {

class WorkerPool;

// A feature named mesh-wide: a welded vertex id, an edge id (Mesh::edge_id)
// or a triangle id. Two LMDs on the same pair of mesh features are one.
struct MeshFeature {
  FeatureKind kind = FeatureKind::Face;
  std::uint32_t id = 0;

  friend bool operator==(MeshFeature a, MeshFeature b) { return a.kind == b.kind && a.id == b.id; }
  friend bool operator!=(MeshFeature a, MeshFeature b) { return !(a == b); }
};

MeshFeature mesh_feature(const Mesh& mesh, std::uint32_t triangle, Feature f);

// The triangles around feature f of triangle t, where local tracking looks
// next (paper Fig. 5): the triangle for a face, the triangles sharing an edge,
// a vertex's one-ring. Replaces `out`'s contents.
void feature_neighbourhood(const Mesh& mesh, std::uint32_t t, Feature f, std::vector<std::uint32_t>& out);

// A triangle pair as one 64-bit key.
inline std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }

struct LmdPair {
  std::uint32_t tri_a = 0, tri_b = 0;
  Vec3 point_a{0.0}, point_b{0.0};  // closest points, world coordinates
  double distance = 0.0;            // |point_b - point_a|, mesh units
  Feature feature_a, feature_b;     // on tri_a and tri_b
  MeshFeature mesh_feature_a, mesh_feature_b;
  // The patch this LMD represents (contact/patches.h): how many LMDs it
  // stands for (itself included), the farthest of their closest points on B
  // from its own, how much farther the farthest of them is than it, and the
  // largest angle between their directions and its own (radians).
  std::uint32_t patch_count = 1;
  double patch_extent = 0.0, patch_spread = 0.0, patch_angle = 0.0;
};

// The patch rule (contact/patches.h, docs/patches.md). The radius is a share of the query's cutoff, so one
// setting fits models of any scale; 0 turns merging off.
struct PatchSettings {
  double radius_over_cutoff = 1.0;
  double max_angle_degrees = 5.0;
  // Members are at most this share of the cutoff farther than the seed: a
  // flat field, not a second feature nearby.
  double max_spread_over_cutoff = 0.002;
  // The precise search's work bound on flat fields and crossings: after this
  // many leaf pairs, one representative per patch-sized node pair
  // (global_search_precise); 0: no bound.
  std::uint64_t leaf_budget = kDefaultLeafBudget;
  static constexpr std::uint64_t kDefaultLeafBudget = 50000;
  bool enabled() const { return radius_over_cutoff > 0.0; }
  // The node pairs the bounded search cuts have both bounding spheres within
  // this radius: half the patch radius, so that all the points on the tool
  // below one are within a patch radius of each other (half the cutoff with
  // merging off).
  double cut_radius(double cutoff) const { return 0.5 * (enabled() ? radius_over_cutoff : 1.0) * cutoff; }
};

// Two meshes, each with its hierarchy and world pose, and the cutoff beyond
// which pairs are not wanted.
struct PairQuery {
  const Mesh* mesh_a = nullptr;
  const Snch* snch_a = nullptr;
  Pose pose_a;
  const Mesh* mesh_b = nullptr;
  const Snch* snch_b = nullptr;
  Pose pose_b;
  double cutoff = 0.0;  // mesh units, >= 0
  // The precise search's visibility pre-test: Sound (widened by each
  // vertex's normal spread, docs/engine.md), Paper (as published: it loses
  // contacts at sharp features), or Off. For measurement.
  enum class Visibility { Sound, Paper, Off } visibility = Visibility::Sound;
  // The normal-cone tests G2/G3 (switch off only to measure them).
  bool use_cones = true;
  // How find_lmds merges the precise and reference LMDs into patches.
  PatchSettings patches = PatchSettings{};
  // Workers the precise search may split its descent over (null or one
  // thread: it runs alone). The answer is the same bit for bit either way.
  WorkerPool* pool = nullptr;
};

}  // namespace prox
