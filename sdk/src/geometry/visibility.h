// The visibility pre-test of the improved method (paper section 4.1, Fig. 6).
#pragma once

#include "geometry/types.h"

namespace prox::geometry {

// Each triangle's vertices are projected onto the other triangle's plane along
// their own vertex normals; when the projected triangle does not overlap the
// other one, the pair cannot form a local-minimum-distance pair and is culled.
// The test runs in both directions and passes only when both pass.
//
// It is a conservative culler: whenever a projection is undefined (a vertex
// normal parallel to the other plane, a degenerate triangle, a zero normal) the
// pair passes. `margin` widens the 2D overlap test by that fraction of the
// triangles' size, so that rounding never culls a pair that touches the edge.
// Vertex normals need not be unit length; their sign does not matter.
bool visibility_pretest(const Triangle& a, const Vec3 normals_a[3], const Triangle& b,
                        const Vec3 normals_b[3], double margin = 1e-9);

// One direction of the test: does `a`, projected along `normals_a` onto the
// plane of `b`, overlap `b`?
bool projects_onto(const Triangle& a, const Vec3 normals_a[3], const Triangle& b, double margin);

}  // namespace prox::geometry
