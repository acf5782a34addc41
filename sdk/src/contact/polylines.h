// Intersection polylines between two meshes (paper section 4.4).
#pragma once

#include "contact/lmd.h"

#include <cstdint>
#include <vector>

namespace prox {

struct Polyline {
  std::vector<Vec3> points;  // world coordinates
  bool closed = false;       // the last point connects back to the first
};

struct PolylineStats {
  std::uint64_t node_pairs = 0;
  std::uint64_t triangle_pairs = 0;      // pairs whose spheres overlap
  std::uint64_t intersecting_pairs = 0;  // pairs that share a point (exact)
  std::uint64_t coplanar_pairs = 0;  // overlapping in one plane: a region, not a curve; not in the polylines
  std::uint64_t segments = 0;
  double seconds = 0.0;

  PolylineStats& operator+=(const PolylineStats& s) {
    node_pairs += s.node_pairs, triangle_pairs += s.triangle_pairs,
        intersecting_pairs += s.intersecting_pairs;
    coplanar_pairs += s.coplanar_pairs, segments += s.segments, seconds += s.seconds;
    return *this;
  }
};

// Where the surfaces of the two meshes cross: the intersection segments of
// every intersecting triangle pair, found by the hierarchy descent, chained
// through the meshes' adjacency into polylines. On closed meshes in general
// position every polyline is closed. Costs nothing unless called.
void intersection_polylines(const PairQuery& query, std::vector<Polyline>& out, PolylineStats& stats);

}  // namespace prox
