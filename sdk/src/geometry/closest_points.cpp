#include "geometry/closest_points.h"

#include <utility>

namespace prox::geometry {
namespace detail {
namespace {

Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double dd = length2(d);
  if (dd == 0.0) return a;
  return a + std::clamp(glm::dot(p - a, d) / dd, 0.0, 1.0) * d;
}

}  // namespace

// The plane normal of t, unnormalised, or zero for a degenerate triangle. The
// rounding of a cross product of nearly parallel edges (a sliver) leaves an
// error of relative size eps / aspect in every direction; the part along the
// longest edge would tilt the plane where it matters, so it is projected out.
// What remains only turns the plane about that edge, which moves points
// within the sliver's width by a negligible amount.
Vec3 robust_normal(const Triangle& t) {
  const Vec3 e[3] = {t.v[1] - t.v[0], t.v[2] - t.v[1], t.v[0] - t.v[2]};
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (length2(e[i]) > length2(e[k])) k = i;
  const Vec3& longest = e[k];
  Vec3 n = glm::cross(longest, e[(k + 1) % 3]);
  const double ll = length2(longest);
  if (ll > 0.0) n -= (glm::dot(n, longest) / ll) * longest;
  return n;
}

Vec3 closest_point_with_normal(const Vec3& p, const Triangle& t, const Vec3& n) {
  const Vec3 &a = t.v[0], &b = t.v[1], &c = t.v[2];
  const double nn = length2(n);
  if (nn > 0.0) {
    // Project onto the plane; keep the projection when it falls inside
    // (edge tests against the normal, so any winding works).
    const Vec3 q = p - (glm::dot(p - a, n) / nn) * n;
    const Vec3 d[3] = {q - a, q - b, q - c};
    const double dd[3] = {length2(d[0]), length2(d[1]), length2(d[2])};
    const Vec3 m[3] = {glm::cross(n, b - a), glm::cross(n, c - b), glm::cross(n, a - c)};
    if (!edge_outside(m, d, dd, 0) && !edge_outside(m, d, dd, 1) && !edge_outside(m, d, dd, 2)) return q;
  }
  // Outside (or a degenerate triangle): the closest point is on an edge.
  Vec3 best = closest_point_on_segment(p, a, b);
  double best_d2 = length2(p - best);
  for (const auto& [u, v] : {std::pair<const Vec3&, const Vec3&>{b, c}, {c, a}}) {
    const Vec3 x = closest_point_on_segment(p, u, v);
    const double d2 = length2(p - x);
    if (d2 < best_d2) best = x, best_d2 = d2;
  }
  return best;
}

}  // namespace detail

using detail::closest_point_with_normal;
using detail::interior_params_segment_segment;
using detail::length2;
using detail::polished;
using detail::robust_normal;

Vec3 closest_point_on_triangle(const Vec3& p, const Triangle& t) {
  return closest_point_with_normal(p, t, robust_normal(t));
}

Vec2 closest_params_segment_segment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d = p1 - p0, e = q1 - q0;
  const double dd = length2(d), ee = length2(e);
  // Candidates: each endpoint against the other segment (the minimum on the
  // boundary of the parameter square), then the interior one. Taking the
  // best by the distance actually achieved keeps near-parallel segments
  // accurate: an ill-conditioned interior solution can only lose to an
  // endpoint candidate, never win wrongly.
  auto param_on = [](const Vec3& x, const Vec3& a, const Vec3& dir, double len2) {
    return len2 == 0.0 ? 0.0 : std::clamp(glm::dot(x - a, dir) / len2, 0.0, 1.0);
  };
  Vec2 best(0.0);
  double best_d2 = INFINITY;
  auto consider = [&](double s, double t) {
    const double d2 = length2((p0 + s * d) - (q0 + t * e));
    if (d2 < best_d2) best_d2 = d2, best = Vec2(s, t);
  };
  consider(0.0, param_on(p0, q0, e, ee));
  consider(1.0, param_on(p1, q0, e, ee));
  consider(param_on(q0, p0, d, dd), 0.0);
  consider(param_on(q1, p0, d, dd), 1.0);
  // Then the interior critical point of non-parallel lines, or the middle of
  // exactly parallel segments' overlap, which wins ties: a canonical choice.
  Vec2 st;
  bool near_parallel = false;
  if (interior_params_segment_segment(p0, d, dd, q0, e, ee, st, near_parallel)) {
    if (near_parallel) st = polished(p0, d, dd, q0, e, ee, st);
    const double d2 = length2((p0 + st.x * d) - (q0 + st.y * e));
    if (d2 < best_d2 || (d2 == best_d2 && length2(glm::cross(d, e)) == 0.0)) best_d2 = d2, best = st;
  }
  return best;
}

}  // namespace prox::geometry
