// Triangle-triangle intersection: an exact verdict and the intersection set.
#pragma once

#include "geometry/types.h"

namespace prox::geometry {

// True when the two closed triangles share at least one point (touching counts).
// Exact for all finite input: every decision is an exact orientation predicate.
// Degenerate triangles count as the segment or point they span.
bool triangles_intersect(const Triangle& a, const Triangle& b);

struct TriangleIntersection {
  static constexpr int kMaxPoints = 12;

  bool intersects = false;
  // Both triangles are non-degenerate and lie exactly in one plane: `points`
  // is then their overlap, a convex polygon in counter-clockwise order around
  // a's normal (3 to 6 points, fewer when the overlap is itself degenerate).
  bool coplanar = false;
  // Otherwise: 1 point where the triangles touch in a point, or 2 points, the
  // ends of the intersection segment.
  int count = 0;
  Vec3 points[kMaxPoints];
};

// The intersection set. The verdict is exact (identical to
// triangles_intersect); the points are constructed in floating point and are
// accurate to a few ulps of the triangles' size.
TriangleIntersection intersect_triangles(const Triangle& a, const Triangle& b);
// The same, for a caller that has already asked collinear3d of each triangle.
TriangleIntersection intersect_triangles(const Triangle& a, const Triangle& b, bool a_degenerate,
                                         bool b_degenerate);

// Where segment [p, q] crosses triangle t, for segments not lying in t's
// plane: false when they do not meet (an exact verdict), else true and the
// crossing point. The point does not depend on the segment's direction, so
// the two triangles sharing an edge get bit-identical crossings of it, which
// is what lets intersection segments chain into polylines. Degenerate
// triangles and segments in t's plane report no crossing.
bool segment_crosses_triangle(const Vec3& p, const Vec3& q, const Triangle& t, Vec3& point);

}  // namespace prox::geometry
