// Exact triangle-triangle distance with closest points and closest features.
#pragma once

#include "geometry/types.h"

namespace prox::geometry {

struct TriangleDistance {
  double distance = 0.0;  // >= 0, in the input's units; exactly 0 when the triangles intersect
  Vec3 point_a{0.0};      // closest point on a (world coordinates, as the input)
  Vec3 point_b{0.0};      // closest point on b; point_b - point_a points from a to b
  // The lowest-dimensional feature of each triangle that holds *all* its
  // closest points. When the closest points are not unique (parallel edges or
  // faces) this is the feature spanning the whole closest set, and the points
  // reported are the middle of that set. Intersecting triangles report the
  // middle of their intersection set and the features holding it.
  Feature feature_a;
  Feature feature_b;
  bool intersects = false;
};

// Exact in the sense that matters for the engine: the distance is the true
// Euclidean distance between the closed triangles up to floating-point
// rounding of order 1e-16 times the triangles' size (see docs/precision.md),
// never a sampled approximation; the intersection verdict is exact. Swapping
// the arguments or rotating either triangle's vertices gives the same
// distance, the same verdict and the same features (re-indexed).
TriangleDistance triangle_distance(const Triangle& a, const Triangle& b);

// The same from all 15 candidates (each vertex against the other triangle,
// each edge pair), where triangle_distance computes only those that can tie
// with the minimum (docs/precision.md). Slower; the reference the pruning is
// tested against: the same verdict and features, the distance to rounding.
TriangleDistance triangle_distance_every_candidate(const Triangle& a, const Triangle& b);

// Relative tolerances, as fractions of a triangle's longest edge, used to
// name features and to treat near-equal candidate distances as ties.
inline constexpr double kFeatureTolerance = 1e-9;
inline constexpr double kTieTolerance = 1e-12;

// The closest point of triangle t to p. A
// degenerate triangle is treated as the segment or point it spans.
Vec3 closest_point_on_triangle(const Vec3& p, const Triangle& t);

// Closest points of segments [p0, p1] and [q0, q1]: returns the parameters
// s, t in [0, 1] of the closest points p0 + s (p1 - p0) and q0 + t (q1 - q0).
// For parallel overlapping segments the middle of the overlap is returned.
Vec2 closest_params_segment_segment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

}  // namespace prox::geometry
