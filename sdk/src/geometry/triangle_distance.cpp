#include "geometry/triangle_distance.h"

#include "geometry/predicates.h"
#include "geometry/triangle_intersection.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace prox::geometry {
namespace {

double length2(const Vec3& v) { return glm::dot(v, v); }

double longest_edge(const Triangle& t) {
  return std::sqrt(std::max({length2(t.v[1] - t.v[0]), length2(t.v[2] - t.v[1]), length2(t.v[0] - t.v[2])}));
}

Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double dd = length2(d);
  if (dd == 0.0) return a;
  return a + std::clamp(glm::dot(p - a, d) / dd, 0.0, 1.0) * d;
}

// A candidate closest pair. Non-intersecting triangles reach their minimum
// distance at a vertex of one against the other triangle, or between the
// interiors of two edges; every extreme point of the (convex) set of closest
// pairs is one of these candidates, which is what lets ties name features.
struct Candidate {
  Vec3 pa, pb;
  double d2;
};

struct CandidateList {
  Candidate c[15];
  int n = 0;
  void add(const Vec3& pa, const Vec3& pb) { c[n++] = {pa, pb, length2(pb - pa)}; }
};

// Distance from a point to a set of points, the largest over the set.
double max_distance_to_point(const Vec3* pts, int n, const Vec3& x) {
  double worst = 0.0;
  for (int i = 0; i < n; ++i) worst = std::max(worst, length2(pts[i] - x));
  return std::sqrt(worst);
}

double max_distance_to_segment(const Vec3* pts, int n, const Vec3& a, const Vec3& b) {
  double worst = 0.0;
  for (int i = 0; i < n; ++i)
    worst = std::max(worst, length2(pts[i] - closest_point_on_segment(pts[i], a, b)));
  return std::sqrt(worst);
}

// The lowest-dimensional feature of t that holds every point of pts within
// `tol`. Several vertices or edges qualify only on (near-)degenerate
// triangles; the choice must not depend on vertex order, so it is the nearest
// vertex (coincident vertices are the same place) and the longest edge (on a
// collinear triangle it spans the others).
Feature feature_holding(const Triangle& t, const Vec3* pts, int n, double tol) {
  int best_vertex = -1;
  double best = tol;
  for (int k = 0; k < 3; ++k) {
    const double d = max_distance_to_point(pts, n, t.v[k]);
    if (d <= best) best_vertex = k, best = d;
  }
  if (best_vertex >= 0) return {FeatureKind::Vertex, static_cast<std::uint8_t>(best_vertex)};
  int best_edge = -1;
  double best_length2 = -1.0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 &a = t.v[k], &b = t.v[(k + 1) % 3];
    const double len2 = length2(b - a);
    if (len2 > best_length2 && max_distance_to_segment(pts, n, a, b) <= tol)
      best_edge = k, best_length2 = len2;
  }
  if (best_edge >= 0) return {FeatureKind::Edge, static_cast<std::uint8_t>(best_edge)};
  return {FeatureKind::Face, 0};
}

Triangle translated(const Triangle& t, const Vec3& origin) {
  return {{t.v[0] - origin, t.v[1] - origin, t.v[2] - origin}};
}

// Middle of the bounding box of both triangles. It does not depend on vertex
// or argument order, so the translated coordinates are bit-identical under
// every permutation, and subtracting it is exact for coordinates far from the
// world origin (Sterbenz), which keeps full precision relative to the
// triangles' size wherever they are.
Vec3 local_origin(const Triangle& a, const Triangle& b) {
  Vec3 lo = a.v[0], hi = a.v[0];
  for (const Triangle* t : {&a, &b})
    for (const Vec3& v : t->v) lo = glm::min(lo, v), hi = glm::max(hi, v);
  return 0.5 * lo + 0.5 * hi;
}

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

// With the triangle's robust_normal computed once by the caller.
Vec3 closest_point_with_normal(const Vec3& p, const Triangle& t, const Vec3& n) {
  const Vec3 &a = t.v[0], &b = t.v[1], &c = t.v[2];
  const double nn = length2(n);
  if (nn > 0.0) {
    // Project onto the plane; keep the projection when it falls inside
    // (edge tests against the normal, so any winding works).
    const Vec3 q = p - (glm::dot(p - a, n) / nn) * n;
    if (glm::dot(glm::cross(b - a, q - a), n) >= 0.0 && glm::dot(glm::cross(c - b, q - b), n) >= 0.0 &&
        glm::dot(glm::cross(a - c, q - c), n) >= 0.0)
      return q;
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

}  // namespace

Vec3 closest_point_on_triangle(const Vec3& p, const Triangle& t) {
  return closest_point_with_normal(p, t, robust_normal(t));
}

Vec2 closest_params_segment_segment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d = p1 - p0, e = q1 - q0;
  const double dd = length2(d), ee = length2(e);
  // Candidates: each endpoint against the other segment (the minimum on the
  // boundary of the parameter square), then the interior critical point of
  // non-parallel lines. Taking the best by the distance actually achieved
  // keeps near-parallel segments accurate: an ill-conditioned interior
  // solution can only lose to an endpoint candidate, never win wrongly.
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
  const Vec3 n = glm::cross(d, e);
  const double nn = length2(n);
  if (nn > 0.0) {
    // Lines p0 + s d and q0 + t e: s = ((q0 - p0) x e) . n / |n|^2 and
    // t = ((q0 - p0) x d) . n / |n|^2. The cross product keeps more accuracy
    // than the normal equations' |d|^2 |e|^2 - (d.e)^2 for near-parallel lines.
    const Vec3 r = q0 - p0;
    const double s = glm::dot(glm::cross(r, e), n) / nn;
    const double t = glm::dot(glm::cross(r, d), n) / nn;
    if (s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0) consider(s, t);
  } else if (dd > 0.0 && ee > 0.0) {
    // Exactly parallel: prefer the middle of the overlap, a canonical choice.
    const double u0 = glm::dot(q0 - p0, d) / dd, u1 = glm::dot(q1 - p0, d) / dd;
    const double lo = std::max(0.0, std::min(u0, u1)), hi = std::min(1.0, std::max(u0, u1));
    if (lo <= hi) {
      const double s = 0.5 * (lo + hi);
      const double t = param_on(p0 + s * d, q0, e, ee);
      const double d2 = length2((p0 + s * d) - (q0 + t * e));
      if (d2 <= best_d2) best_d2 = d2, best = Vec2(s, t);
    }
  }
  return best;
}

TriangleDistance triangle_distance(const Triangle& a_world, const Triangle& b_world) {
  TriangleDistance r;
  const double size_a = longest_edge(a_world), size_b = longest_edge(b_world);

  const TriangleIntersection hit = intersect_triangles(a_world, b_world);
  if (hit.intersects) {
    Vec3 middle(0.0);
    for (int i = 0; i < hit.count; ++i) middle += hit.points[i];
    middle /= static_cast<double>(hit.count);
    r.intersects = true;
    r.distance = 0.0;
    r.point_a = r.point_b = middle;
    r.feature_a = feature_holding(a_world, hit.points, hit.count, kFeatureTolerance * size_a);
    r.feature_b = feature_holding(b_world, hit.points, hit.count, kFeatureTolerance * size_b);
    return r;
  }

  const Vec3 origin = local_origin(a_world, b_world);
  const Triangle a = translated(a_world, origin), b = translated(b_world, origin);
  const bool a_flat = collinear3d(a_world.v[0], a_world.v[1], a_world.v[2]);
  const bool b_flat = collinear3d(b_world.v[0], b_world.v[1], b_world.v[2]);

  CandidateList cand;
  // Vertex against face (each triangle's normal computed once). A degenerate
  // triangle's "face" is its edges, which the edge-edge candidates cover.
  const Vec3 normal_a = a_flat ? Vec3(0.0) : robust_normal(a);
  const Vec3 normal_b = b_flat ? Vec3(0.0) : robust_normal(b);
  for (int i = 0; i < 3; ++i) {
    if (!b_flat) cand.add(a.v[i], closest_point_with_normal(a.v[i], b, normal_b));
    if (!a_flat) cand.add(closest_point_with_normal(b.v[i], a, normal_a), b.v[i]);
  }
  // Edge against edge.
  for (int i = 0; i < 3; ++i) {
    const Vec3 &p0 = a.v[i], &p1 = a.v[(i + 1) % 3];
    for (int j = 0; j < 3; ++j) {
      const Vec3 &q0 = b.v[j], &q1 = b.v[(j + 1) % 3];
      const Vec2 st = closest_params_segment_segment(p0, p1, q0, q1);
      cand.add(p0 + st.x * (p1 - p0), q0 + st.y * (q1 - q0));
    }
  }

  double min_d2 = INFINITY;
  for (int i = 0; i < cand.n; ++i) min_d2 = std::min(min_d2, cand.c[i].d2);
  const double min_d = std::sqrt(min_d2);

  // Every candidate within the tie tolerance of the minimum is a closest pair
  // (up to rounding); together they span the closest set.
  const double tie = min_d + kTieTolerance * std::max(size_a, size_b);
  const double tie2 = std::max(tie * tie, min_d2);  // sqrt(x)^2 may round below x
  Vec3 on_a[15], on_b[15];
  int ties = 0;
  Vec3 sum_a(0.0), sum_b(0.0);
  for (int i = 0; i < cand.n; ++i) {
    if (cand.c[i].d2 > tie2) continue;
    on_a[ties] = cand.c[i].pa;
    on_b[ties] = cand.c[i].pb;
    sum_a += cand.c[i].pa;
    sum_b += cand.c[i].pb;
    ++ties;
  }
  r.distance = min_d;
  r.point_a = sum_a / static_cast<double>(ties) + origin;
  r.point_b = sum_b / static_cast<double>(ties) + origin;
  r.feature_a = feature_holding(a, on_a, ties, kFeatureTolerance * size_a);
  r.feature_b = feature_holding(b, on_b, ties, kFeatureTolerance * size_b);
  return r;
}

}  // namespace prox::geometry
