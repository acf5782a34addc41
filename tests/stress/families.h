// Seeded generators of triangle pairs for the numerical stress suite. The test
// and the report use the same generators, so the report shows exactly what the
// test asserts.
#pragma once

#include "geometry/types.h"

#include <cstdint>
#include <vector>

namespace prox::stress {

struct Case {
  Triangle a, b;
  // What the construction guarantees, when it guarantees something.
  enum class Known { Unknown, Disjoint, Intersecting } known = Known::Unknown;
  bool known_features = false;  // true: the kinds below are certain
  FeatureKind kind_a = FeatureKind::Face, kind_b = FeatureKind::Face;
};

// Allowed errors. Distance: |d - d_ref| <= size_ulps * eps * L + coord_ulps * eps * M,
// with L the longest edge of the pair (or the distance, when larger), M the
// largest |coordinate| and eps = 2^-52. Far from the origin M dominates: a
// point in world coordinates can only be written to eps * M. Closest and
// intersection points lie on their triangles within point_rel * L plus the
// same coordinate term.
struct Bound {
  double size_ulps;
  double coord_ulps;
  double point_rel;
};

struct Family {
  const char* name;
  const char* what;
  std::vector<Case> (*generate)(std::uint64_t seed, int count);
  Bound bound;
};

const std::vector<Family>& families();

}  // namespace prox::stress
