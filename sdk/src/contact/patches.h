// Patches: LMD pairs merged where the distance field is flat (docs/patches.md).
//
// Where two surfaces run parallel or cross, nearly every triangle pair is a
// local minimum of the distance: the LMD set is legitimately huge and says
// little more than "a sheet is this far". A patch keeps one representative,
// its closest LMD (the seed), for all the LMDs whose closest points on the
// tool lie within a radius of the seed's and whose directions agree with the
// seed's within an angle; the seed carries the patch's count, extent, spread
// of distances and largest angle, so the force can weigh it and its error
// against the unmerged set is bounded (patch_force_error_bound).
#pragma once

#include "contact/force.h"
#include "contact/lmd.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace prox {

struct PatchStats {
  std::uint32_t lmds_in = 0;  // before merging
  std::uint32_t patches = 0;  // after: one contact per patch
  std::uint32_t merged = 0;   // lmds_in - patches: LMDs folded into another's patch
  std::uint32_t largest = 0;  // LMDs in the largest patch

  PatchStats& operator+=(const PatchStats& s) {
    lmds_in += s.lmds_in, patches += s.patches, merged += s.merged;
    largest = largest > s.largest ? largest : s.largest;
    return *this;
  }
};

// The direction an LMD's force pushes the tool: point_b - point_a made unit,
// or, at zero distance, the tool triangle's face normal turned away from A's
// (zero when neither is defined).
Vec3 lmd_direction(const PairQuery& query, const LmdPair& lmd);

// Merges `lmds` (A = the other body, B = the tool) into patches in place:
// sorted by distance (ties by triangle ids and features, so the result does
// not depend on the input order), the closest LMD not yet in a patch seeds
// one, and every later LMD joins the first seed whose closest point on B is
// within radius_over_cutoff * cutoff of its own and whose direction is
// within max_angle_degrees of its own; otherwise it seeds a patch. The seeds
// remain, in that order, each with patch_count, patch_extent, patch_spread
// and patch_angle set. A grid hash with the radius as its cell makes it
// O(n) for a bounded number of seeds per cell. Keeps its scratch memory.
class PatchMerger {
 public:
  void merge(const PairQuery& query, const PatchSettings& settings, std::vector<LmdPair>& lmds,
             PatchStats& stats);

 private:
  std::vector<std::uint32_t> order_, seed_of_;
  std::vector<Vec3> directions_;
  std::vector<LmdPair> seeds_;
  std::vector<std::uint32_t> seed_index_, next_in_cell_;
  std::unordered_map<std::uint64_t, std::uint32_t> cells_;  // cell -> first seed + 1
};

// The stated bound on |force(merged) - force(unmerged)|, with the merged
// set's seeds weighing their counts: for each patch, every member i other
// than the seed s is off by at most
//   |F(d_i) u_i - F(d_s) u_s| <= (F(d_s) - F(d_i)) + F(d_s) |u_i - u_s|
//                             <= (F(d_s) - F(d_s + spread)) + F(d_s) 2 sin(angle / 2),
// F the (decreasing) force curve, u the unit directions; the sum's error is
// at most the sum of these, and clipping the sum to max_force (a projection
// onto a ball, 1-Lipschitz) keeps the bound.
double patch_force_error_bound(const ForceSettings& settings, const std::vector<LmdPair>& seeds);

}  // namespace prox
