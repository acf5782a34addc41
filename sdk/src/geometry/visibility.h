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

// A vertex's spread (below) as the cosine and sine of its half-angle, the
// form the hierarchy keeps and the test takes, so that neither a refit nor
// the test runs trigonometry. Any positive multiple of the pair names the
// same angle; cos <= 0: a right angle or more, nothing known.
struct Spread {
  double cos = 0.0, sin = 1.0;
  // From an angle in radians; pi/2 or more: nothing known.
  static Spread of_angle(double radians);
};

// The sound form Proxima uses. `spread_a[i]` is the half-angle (radians) of
// the cone of directions in which a closest pair can leave the surface at
// vertex i: the largest angle between its vertex normal and the normals of
// the faces around it (pi/2 or more: unknown, the pair passes). Projecting
// along any direction of that cone lands within h (tan(theta + spread) -
// tan(theta)) of the projection along the vertex normal (h: the vertex's
// distance to the plane, theta: the normal's tilt from the plane's normal),
// and projection along a fixed direction is affine, so growing the 2D test by
// the largest such radius keeps every pair that can be a local minimum. With
// zero spreads it is the paper's test. See docs/engine.md for what the
// paper's test loses at sharp features.
bool visibility_pretest(const Triangle& a, const Vec3 normals_a[3], const double spread_a[3],
                        const Triangle& b, const Vec3 normals_b[3], const double spread_b[3],
                        double margin = 1e-9);
// The same with the spreads as cosines and sines (what the searches pass).
bool visibility_pretest(const Triangle& a, const Vec3 normals_a[3], const Spread spread_a[3],
                        const Triangle& b, const Vec3 normals_b[3], const Spread spread_b[3],
                        double margin = 1e-9);

}  // namespace prox::geometry
