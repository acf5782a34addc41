// Runs the kernel on a family's cases against the quad-precision reference and
// the invariance checks, and summarises the errors.
#pragma once

#include "stress/families.h"

#include <string>
#include <vector>

namespace prox::stress {

struct FamilyStats {
  std::string name;
  int cases = 0;
  int nan_count = 0;  // non-finite distance or point
  // Distance error |d - d_ref| relative to L (the longest edge, or the
  // distance when larger: point triangles have no edges) ...
  double max_size_error = 0.0, median_size_error = 0.0;
  // ... and relative to d_ref itself, over cases with d_ref > 0.
  double max_rel_error = 0.0, median_rel_error = 0.0;
  int bound_violations = 0;                    // distance error above the family's Bound
  double max_bound_ratio = 0.0;                // largest error / allowed error
  int verdict_mismatches = 0;                  // intersection verdict vs construction/reference
  int ambiguous_verdicts = 0;                  // reference within rounding of touching: not judged
  double max_point_error = 0.0;                // closest points off their triangle, / L
  int point_violations = 0;                    // a closest or intersection point off beyond the bound
  double max_gap_error = 0.0;                  // | |pb - pa| - d |, / L
  int feature_errors = 0;                      // point not on its named feature, or known feature wrong
  int invariance_violations = 0;               // any of the 18 orders/rotations disagrees
  double max_invariance_spread = 0.0;          // distance spread over them, / L
  int intersection_invariance_violations = 0;  // any of the 72 permutations disagrees
  double max_intersection_point_error = 0.0;   // intersection points off either triangle, / L
  std::vector<std::string> examples;           // a few failing cases, printed for debugging
};

FamilyStats evaluate_family(const Family& family, std::uint64_t seed, int count);

}  // namespace prox::stress
