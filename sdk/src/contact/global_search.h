// The global search for LMD candidates (paper sections 3.2.1 and 4.1) and the
// brute-force reference.
#pragma once

#include "contact/lmd.h"

#include <cstdint>
#include <vector>

namespace prox {

struct GlobalSearchStats {
  std::uint64_t node_pairs = 0;             // node pairs visited
  std::uint64_t rejected_g1 = 0;            // spheres (or, precise, boxes) farther apart than the cutoff
  std::uint64_t rejected_g2 = 0;            // cones hold no opposite normals
  std::uint64_t rejected_g3 = 0;            // cones miss the lines between the spheres
  std::uint64_t leaf_pairs = 0;             // triangle pairs reaching the leaf tests
  std::uint64_t visibility_rejections = 0;  // precise: culled by the visibility pre-test
  std::uint64_t plane_rejections =
      0;  // precise: one triangle beyond the other's plane by more than the cutoff
  std::uint64_t normal_rejections = 0;     // original: culled by the G5 normal check
  std::uint64_t distance_evaluations = 0;  // exact distances (precise) or 7x7 samplings (original)
  std::uint64_t candidates = 0;            // pairs output, before any reduction
  // precise: pairs whose exact distance found them crossing; they are an
  // intersection of the two bodies, not contacts, and are not output
  std::uint64_t intersecting_pairs = 0;
  // precise, over its leaf budget (PatchSettings::leaf_budget): node pairs
  // of patch size searched for one representative leaf pair each instead of
  // every leaf pair below them
  std::uint64_t cut_node_pairs = 0;
  double seconds = 0.0;

  GlobalSearchStats& operator+=(const GlobalSearchStats& s) {
    node_pairs += s.node_pairs, rejected_g1 += s.rejected_g1, rejected_g2 += s.rejected_g2;
    rejected_g3 += s.rejected_g3, leaf_pairs += s.leaf_pairs,
        visibility_rejections += s.visibility_rejections;
    plane_rejections += s.plane_rejections, normal_rejections += s.normal_rejections;
    distance_evaluations += s.distance_evaluations, candidates += s.candidates, seconds += s.seconds;
    intersecting_pairs += s.intersecting_pairs, cut_node_pairs += s.cut_node_pairs;
    return *this;
  }
};

// The improved method: G1, G2, G3.a/b on node pairs; at leaves the visibility
// pre-test and the exact triangle distance. Appends every non-intersecting
// pair within the cutoff that passes (the candidates, before reduction).
// Once query.patches.leaf_budget leaf pairs have been tested, each node pair
// that passes and whose two bounding spheres are both within half the patch
// radius (half the cutoff with patches off) is cut: the first candidate of
// at most 8 of its leaf pairs, taken closest first, stands for it
// (docs/patches.md, "The bounded search").
void global_search_precise(const PairQuery& query, std::vector<LmdPair>& out, GlobalSearchStats& stats);

// The Johnson-Cohen baseline: G1, G2 and the original G3 on node pairs; at
// leaves the closest of the 7 x 7 feature points (vertices, edge midpoints,
// centroid) and the G5 check of that direction against the features' normals.
void global_search_original(const PairQuery& query, std::vector<LmdPair>& out, GlobalSearchStats& stats);

// The exact minimum distance between the two meshes (0 when they intersect),
// by branch and bound on the sphere trees; `bound` caps the search: when the
// meshes are farther apart than `bound` the result is +infinity. The closest
// triangle pair is written to `tri_a`, `tri_b` when finite.
double minimum_distance(const PairQuery& query, double bound, std::uint32_t* tri_a = nullptr,
                        std::uint32_t* tri_b = nullptr);

// Whether any pair of triangles is closer than `distance` (or intersects):
// the decision version of minimum_distance, which stops at the first such
// pair. For bisection on poses.
bool any_closer_than(const PairQuery& query, double distance);

// The brute-force truth (docs/reference-lmd.md): every triangle pair within
// the cutoff, exact distances, and the LMD definition applied literally. Slow
// on purpose; for tests and error measurement.
void reference_lmds(const PairQuery& query, std::vector<LmdPair>& out);

// Whether every vertex of `other` is more than `limit` from the plane of
// `t` (unit normal `n`; a zero normal proves nothing), all on one side: then
// the two triangles are more than `limit` apart. The precise search's and
// the tracker's cheap lower bound.
bool beyond_plane(const Triangle& t, const Vec3& n, const Triangle& other, double limit);

}  // namespace prox
