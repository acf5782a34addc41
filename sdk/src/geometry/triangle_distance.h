// Exact triangle-triangle distance with closest points and closest features.
#pragma once

#include "geometry/closest_points.h"
#include "geometry/types.h"

#include <cmath>
#include <limits>

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
// never a sampled approximation; the intersection verdict is exact. A
// single-precision screen with an error bound settles most pairs first and
// leaves only the candidates that can be the closest to double precision
// (docs/precision.md); the answers are the exact kernel's bit for bit. Swapping
// the arguments or rotating either triangle's vertices gives the same
// distance, the same verdict and the same features (re-indexed).
TriangleDistance triangle_distance(const Triangle& a, const Triangle& b);

// The same from all 15 candidates (each vertex against the other triangle,
// each edge pair), where triangle_distance computes only those that can tie
// with the minimum (docs/precision.md). Slower; the reference the pruning is
// tested against: the same verdict and features, the distance to rounding.
TriangleDistance triangle_distance_every_candidate(const Triangle& a, const Triangle& b);

// triangle_distance(a, b), bit for bit, into `out` when its distance is at
// most `limit` (returns true); false when it is more, found as soon as that
// is certain, often before any closest pair is computed. For a search that
// keeps only the pairs within a cutoff.
bool triangle_distance_within(const Triangle& a, const Triangle& b, double limit, TriangleDistance& out);

// triangle_distance(a, b).distance, bit for bit, when it is at most
// `limit`; +infinity when it is more. Neither points nor features are
// worked out, nor the candidates that could only tie with the closest: for
// a branch and bound on the distance alone.
double triangle_distance_value(const Triangle& a, const Triangle& b, double limit = INFINITY);

// The three above without the single-precision screen that runs before the
// exact candidates (triangle_screen.h): the same answers bit for bit. The
// reference the screen is tested against, and the faster choice for pairs
// at a local minimum, whose candidates tie and which the screen settles
// seldom (local tracking's updates).
TriangleDistance triangle_distance_unscreened(const Triangle& a, const Triangle& b);
bool triangle_distance_within_unscreened(const Triangle& a, const Triangle& b, double limit, TriangleDistance& out);
double triangle_distance_value_unscreened(const Triangle& a, const Triangle& b,
                                          double limit = std::numeric_limits<double>::infinity());

// Relative tolerances, as fractions of a triangle's longest edge, used to
// name features and to treat near-equal candidate distances as ties.
inline constexpr double kFeatureTolerance = 1e-9;
inline constexpr double kTieTolerance = 1e-12;

}  // namespace prox::geometry
