// Closest points of a point and a segment or a triangle, and of two
// segments: the pieces the triangle-triangle distance is built from
// (triangle_distance.h), each exact to rounding and robust on degenerate
// input.
#pragma once

#include "geometry/types.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace prox::geometry {

// The closest point of triangle t to p. A
// degenerate triangle is treated as the segment or point it spans.
Vec3 closest_point_on_triangle(const Vec3& p, const Triangle& t);

// Closest points of segments [p0, p1] and [q0, q1]: returns the parameters
// s, t in [0, 1] of the closest points p0 + s (p1 - p0) and q0 + t (q1 - q0).
// For parallel overlapping segments the middle of the overlap is returned.
Vec2 closest_params_segment_segment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

// The parts the triangle distance's kernel calls in its inner loops, inline.
namespace detail {

inline double length2(const Vec3& v) { return glm::dot(v, v); }

// Edges closer to parallel than sin^2 = 1e-6 (0.06 degrees) polish their
// interior closest points (interior_params_segment_segment).
inline constexpr double kNearParallel = 1e-6;

// The plane normal of t, unnormalised, or zero for a degenerate triangle. The
// rounding of a cross product of nearly parallel edges (a sliver) leaves an
// error of relative size eps / aspect in every direction; the part along the
// longest edge would tilt the plane where it matters, so it is projected out.
// What remains only turns the plane about that edge, which moves points
// within the sliver's width by a negligible amount.
Vec3 robust_normal(const Triangle& t);

// Whether q is beyond edge k (from vertex k to k + 1), given m[k], a normal
// of the edge in the triangle's plane pointing inwards, and d[i] = q - v[i]
// with dd[i] its squared length. The test is taken from the edge's end
// nearer q: its error is then relative to that distance, not to the
// triangle's size. Taken from a far end, a point within rounding of a line
// passes its test either way, and a point just behind a sliver's sharp
// vertex (within eps L / angle of it) could pass both long edges' tests and
// be projected onto the face, off by up to that much. A test that overflows
// to NaN (coordinates near 1e80) counts as outside, so the edges decide.
inline bool edge_outside(const Vec3 (&m)[3], const Vec3 (&d)[3], const double (&dd)[3], int k) {
  const int j = k == 2 ? 0 : k + 1;
  return !(glm::dot(m[k], dd[j] < dd[k] ? d[j] : d[k]) >= 0.0);
}

// The closest point of triangle t to p, t's robust_normal computed once by
// the caller.
Vec3 closest_point_with_normal(const Vec3& p, const Triangle& t, const Vec3& n);

// Nearly parallel lines (sin^2 of their angle below kNearParallel): the
// critical point's s and t carry errors of eps / sin along the lines. One
// step of projecting each line's point onto the other, each well
// conditioned and never farther, takes the distance back to rounding
// (5e-15 -> 2e-17 of the size at 1 um in the stress family
// near_parallel_edges). Clamped to the segments, which the critical point
// was inside.
inline Vec2 polished(const Vec3& p0, const Vec3& d, double dd, const Vec3& q0, const Vec3& e, double ee, Vec2 st) {
  const double s = std::clamp(glm::dot(q0 + st.y * e - p0, d) / dd, 0.0, 1.0);
  const double t = std::clamp(glm::dot(p0 + s * d - q0, e) / ee, 0.0, 1.0);
  return Vec2(s, t);
}

// The closest points of segments p0 + s d and q0 + t e, s, t in [0, 1],
// when they lie inside both (the lines' critical point), or, for exactly
// parallel segments that overlap, the middle of the overlap; false when the
// closest points include an end of a segment. Inlined by force: it is in
// the kernel's inner loop, and called from two places GCC would not inline
// it into both (3% more instructions a call).
[[gnu::always_inline]] inline bool interior_params_segment_segment(const Vec3& p0, const Vec3& d, double dd,
                                                                   const Vec3& q0, const Vec3& e, double ee,
                                                                   Vec2& st, bool& near_parallel) {
  const Vec3 n = glm::cross(d, e);
  const double nn = length2(n);
  const Vec3 r = q0 - p0;
  if (nn > 0.0) {
    // Lines p0 + s d and q0 + t e: s = ((q0 - p0) x e) . n / |n|^2 and
    // t = ((q0 - p0) x d) . n / |n|^2. The cross product keeps more accuracy
    // than the normal equations' |d|^2 |e|^2 - (d.e)^2 for near-parallel lines.
    const double s = glm::dot(glm::cross(r, e), n) / nn;
    const double t = glm::dot(glm::cross(r, d), n) / nn;
    st = Vec2(s, t);
    near_parallel = nn < kNearParallel * dd * ee;
    return s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0;
  }
  near_parallel = false;
  if (!(dd > 0.0 && ee > 0.0)) return false;
  const double u0 = glm::dot(r, d) / dd, u1 = glm::dot(r + e, d) / dd;
  const double lo = std::max(0.0, std::min(u0, u1)), hi = std::min(1.0, std::max(u0, u1));
  if (!(lo <= hi)) return false;
  const double s = 0.5 * (lo + hi);
  st = Vec2(s, std::clamp(glm::dot(p0 + s * d - q0, e) / ee, 0.0, 1.0));
  return true;
}

}  // namespace detail
}  // namespace prox::geometry
