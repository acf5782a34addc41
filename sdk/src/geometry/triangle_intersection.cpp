#include "geometry/triangle_intersection.h"

#include "geometry/predicates.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace prox::geometry {
namespace {

// Two closed triangles share a point exactly when some edge of one meets the
// other (the intersection of two convex sets is a convex set whose extreme
// points lie on edges of one of them). That reduces every case, coplanar and
// degenerate ones included, to exact segment-triangle and segment-segment
// tests built on orient3d/orient2d.

bool on_segment_2d(const Vec2& p, const Vec2& a, const Vec2& b) {
  // p is known to be collinear with a and b; check the bounding box.
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool segments_intersect_2d(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b) {
  const int o1 = orient2d(p, q, a);
  const int o2 = orient2d(p, q, b);
  const int o3 = orient2d(a, b, p);
  const int o4 = orient2d(a, b, q);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  if (o1 == 0 && on_segment_2d(a, p, q)) return true;
  if (o2 == 0 && on_segment_2d(b, p, q)) return true;
  if (o3 == 0 && on_segment_2d(p, a, b)) return true;
  if (o4 == 0 && on_segment_2d(q, a, b)) return true;
  return false;
}

bool point_in_triangle_2d(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  const int o = orient2d(a, b, c);
  if (o == 0) return false;  // degenerate: callers test the edges separately
  return orient2d(a, b, p) * o >= 0 && orient2d(b, c, p) * o >= 0 && orient2d(c, a, p) * o >= 0;
}

// Closed segment vs closed triangle, all in one 2D projection.
bool segment_triangle_2d(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b, const Vec2& c) {
  return point_in_triangle_2d(p, a, b, c) || point_in_triangle_2d(q, a, b, c) ||
         segments_intersect_2d(p, q, a, b) || segments_intersect_2d(p, q, b, c) ||
         segments_intersect_2d(p, q, c, a);
}

// For point sets known to lie in one plane: they intersect in 3D exactly when
// they intersect in all three axis projections. Intersection survives any
// projection, and at least one axis projection is injective on the plane (the
// plane's normal has a non-zero component), so a disjoint pair shows disjoint
// there. This avoids choosing a projection axis from a rounded normal.
bool coplanar_segment_triangle(const Vec3& p, const Vec3& q, const Triangle& t) {
  for (int axis = 0; axis < 3; ++axis) {
    if (!segment_triangle_2d(drop_axis(p, axis), drop_axis(q, axis), drop_axis(t.v[0], axis),
                             drop_axis(t.v[1], axis), drop_axis(t.v[2], axis)))
      return false;
  }
  return true;
}

bool coplanar_segments_intersect(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b) {
  for (int axis = 0; axis < 3; ++axis) {
    if (!segments_intersect_2d(drop_axis(p, axis), drop_axis(q, axis), drop_axis(a, axis),
                               drop_axis(b, axis)))
      return false;
  }
  return true;
}

bool segments_intersect_3d(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b) {
  if (orient3d(p, q, a, b) != 0) return false;  // skew lines never meet
  return coplanar_segments_intersect(p, q, a, b);
}

// Closed segment [p, q] vs closed triangle t. `sp`, `sq` are the sides of p and
// q relative to t's plane (orient3d(t, p), orient3d(t, q)), passed in because
// the caller has them already; `t_degenerate` says t's vertices are collinear.
bool segment_triangle(const Vec3& p, const Vec3& q, int sp, int sq, const Triangle& t, bool t_degenerate) {
  if (t_degenerate) {
    return segments_intersect_3d(p, q, t.v[0], t.v[1]) || segments_intersect_3d(p, q, t.v[1], t.v[2]) ||
           segments_intersect_3d(p, q, t.v[2], t.v[0]);
  }
  if (sp == sq && sp != 0) return false;  // both strictly on one side
  if (sp == 0 && sq == 0) return coplanar_segment_triangle(p, q, t);
  // The segment crosses or touches the plane at exactly one point, which lies
  // in the closed triangle iff the line pq passes on the same side of all
  // three edges (or touches one).
  const int s0 = orient3d(p, q, t.v[0], t.v[1]);
  const int s1 = orient3d(p, q, t.v[1], t.v[2]);
  const int s2 = orient3d(p, q, t.v[2], t.v[0]);
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

struct PlaneSides {
  int side[3] = {0, 0, 0};  // orient3d of each vertex against the other triangle
  bool degenerate = false;  // the *other* triangle has no plane
};

PlaneSides plane_sides(const Triangle& of, const Triangle& against, bool against_degenerate) {
  PlaneSides s;
  s.degenerate = against_degenerate;
  if (!against_degenerate) {
    for (int i = 0; i < 3; ++i) s.side[i] = orient3d(against.v[0], against.v[1], against.v[2], of.v[i]);
  }
  return s;
}

bool strictly_one_side(const PlaneSides& s) {
  return !s.degenerate && ((s.side[0] > 0 && s.side[1] > 0 && s.side[2] > 0) ||
                           (s.side[0] < 0 && s.side[1] < 0 && s.side[2] < 0));
}

bool degenerate(const Triangle& t) { return collinear3d(t.v[0], t.v[1], t.v[2]); }

bool any_edge_meets(const Triangle& a, const PlaneSides& sa, const Triangle& b, bool b_degenerate) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (segment_triangle(a.v[i], a.v[j], sa.side[i], sa.side[j], b, b_degenerate)) return true;
  }
  return false;
}

// ---- construction -----------------------------------------------------------

struct PointSet {
  Vec3 p[TriangleIntersection::kMaxPoints];
  int n = 0;
  void add(const Vec3& x) {
    if (n < TriangleIntersection::kMaxPoints) p[n++] = x;
  }
};

// Largest |component| index of v.
int dominant_axis(const Vec3& v) {
  const Vec3 a = glm::abs(v);
  return a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
}

// Clips segment [p, q] to triangle t (coplanar with it) in the projection
// along t's dominant normal axis; adds the ends of the clipped part.
void clip_coplanar_segment(const Vec3& p, const Vec3& q, const Triangle& t, const Vec3& normal,
                           PointSet& out) {
  const int axis = dominant_axis(normal);
  const Vec2 a = drop_axis(t.v[0], axis), b = drop_axis(t.v[1], axis), c = drop_axis(t.v[2], axis);
  const Vec2 p2 = drop_axis(p, axis), d2 = drop_axis(q, axis) - p2;
  const double orientation = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  const Vec2 corners[3] = {a, b, c};
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 3; ++k) {
    const Vec2 e0 = corners[k], e1 = corners[(k + 1) % 3];
    // Inside is where orientation * cross(e1 - e0, x - e0) >= 0.
    const Vec2 e = e1 - e0;
    const double f0 = orientation * (e.x * (p2.y - e0.y) - e.y * (p2.x - e0.x));
    const double df = orientation * (e.x * d2.y - e.y * d2.x);
    if (df == 0.0) {
      if (f0 < 0.0) return;
      continue;
    }
    const double t_cross = -f0 / df;
    if (df > 0.0)
      lo = std::max(lo, t_cross);
    else
      hi = std::min(hi, t_cross);
  }
  // The exact test said the segment meets t; rounding may make the clipped
  // interval empty by a hair, in which case its middle is still on both.
  if (lo > hi) lo = hi = 0.5 * (lo + hi);
  out.add(p + std::clamp(lo, 0.0, 1.0) * (q - p));
  out.add(p + std::clamp(hi, 0.0, 1.0) * (q - p));
}

// Adds the ends of the overlap of two collinear segments (known to overlap),
// measured along the longer one.
void add_collinear_overlap(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, PointSet& out) {
  const Vec3 d = q - p, e = b - a;
  const bool first_longer = glm::dot(d, d) >= glm::dot(e, e);
  const Vec3& base = first_longer ? p : a;
  const Vec3 dir = first_longer ? d : e;
  const double len2 = glm::dot(dir, dir);
  if (len2 == 0.0) {  // both are points, and they coincide
    out.add(p);
    return;
  }
  auto param = [&](const Vec3& x) { return glm::dot(x - base, dir) / len2; };
  const double u0 = param(p), u1 = param(q), w0 = param(a), w1 = param(b);
  double lo = std::max(std::min(u0, u1), std::min(w0, w1));
  double hi = std::min(std::max(u0, u1), std::max(w0, w1));
  if (lo > hi) lo = hi = 0.5 * (lo + hi);
  out.add(base + lo * dir);
  out.add(base + hi * dir);
}

// Adds where segment [p, q] meets triangle t (known to meet it).
void add_segment_triangle_points(const Vec3& p, const Vec3& q, int sp, int sq, const Triangle& t,
                                 bool t_degenerate, PointSet& out) {
  const Vec3 normal = glm::cross(t.v[1] - t.v[0], t.v[2] - t.v[0]);
  if (t_degenerate) {
    // t is a segment or a point: meet each of its edges.
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = t.v[k], &b = t.v[(k + 1) % 3];
      if (!segments_intersect_3d(p, q, a, b)) continue;
      // Coplanar segments: the ends of their overlap are among the four
      // endpoints' projections; for crossing ones, the crossing point.
      const Vec3 d = q - p, e = b - a;
      const Vec3 n = glm::cross(d, e);
      const double nn = glm::dot(n, n);
      if (nn > 0.0) {
        const double s = glm::dot(glm::cross(a - p, e), n) / nn;
        out.add(p + std::clamp(s, 0.0, 1.0) * d);
      } else {
        add_collinear_overlap(p, q, a, b, out);
      }
    }
    return;
  }
  if (sp == 0 && sq == 0) {
    clip_coplanar_segment(p, q, t, normal, out);
    return;
  }
  if (sp == 0) {
    out.add(p);
    return;
  }
  if (sq == 0) {
    out.add(q);
    return;
  }
  // A proper crossing: interpolate the signed plane distances. The exact
  // signs already fixed that a crossing exists; clamping keeps the point on
  // the segment whatever the rounding.
  const double dp = glm::dot(normal, p - t.v[0]);
  const double dq = glm::dot(normal, q - t.v[0]);
  const double s = dp == dq ? 0.5 : dp / (dp - dq);
  out.add(p + std::clamp(s, 0.0, 1.0) * (q - p));
}

void collect_points(const Triangle& a, const PlaneSides& sa, const Triangle& b, bool b_degenerate,
                    PointSet& out) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (segment_triangle(a.v[i], a.v[j], sa.side[i], sa.side[j], b, b_degenerate))
      add_segment_triangle_points(a.v[i], a.v[j], sa.side[i], sa.side[j], b, b_degenerate, out);
  }
}

// The two points of `s` farthest apart (or one, if they all coincide).
void farthest_pair(const PointSet& s, TriangleIntersection& r) {
  int bi = 0, bj = 0;
  double best = -1.0;
  for (int i = 0; i < s.n; ++i)
    for (int j = i + 1; j < s.n; ++j) {
      const Vec3 d = s.p[i] - s.p[j];
      const double dd = glm::dot(d, d);
      if (dd > best) best = dd, bi = i, bj = j;
    }
  r.points[0] = s.p[bi];
  r.count = 1;
  if (best > 0.0) {
    r.points[1] = s.p[bj];
    r.count = 2;
  }
}

// Convex hull (counter-clockwise around `normal`) of coplanar points, by the
// monotone chain in the projection along the normal's dominant axis. Points
// closer than `merge` (rounding duplicates: the same polygon corner reached
// from both triangles) are merged first; collinear points are dropped.
void coplanar_hull(const PointSet& s, const Vec3& normal, double merge, TriangleIntersection& r) {
  struct Item {
    Vec2 q;
    Vec3 p;
  };
  const int axis = dominant_axis(normal);
  Item items[TriangleIntersection::kMaxPoints];
  int n = 0;
  for (int i = 0; i < s.n; ++i) {
    bool duplicate = false;
    for (int j = 0; j < n && !duplicate; ++j) duplicate = glm::length(items[j].p - s.p[i]) <= merge;
    if (!duplicate) items[n++] = {drop_axis(s.p[i], axis), s.p[i]};
  }
  if (n == 0) {
    r.count = 0;
    return;
  }
  for (int i = 1; i < n; ++i) {  // insertion sort, lexicographic: n <= 12
    const Item x = items[i];
    int j = i;
    for (; j > 0 && (items[j - 1].q.x > x.q.x || (items[j - 1].q.x == x.q.x && items[j - 1].q.y > x.q.y));
         --j)
      items[j] = items[j - 1];
    items[j] = x;
  }
  auto turn = [](const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  Item hull[2 * TriangleIntersection::kMaxPoints]{};
  int h = 0;
  for (int i = 0; i < n; ++i) {  // lower chain
    while (h >= 2 && turn(hull[h - 2].q, hull[h - 1].q, items[i].q) <= 0.0) --h;
    hull[h++] = items[i];
  }
  for (int i = n - 2, lower = h + 1; i >= 0; --i) {  // upper chain
    while (h >= lower && turn(hull[h - 2].q, hull[h - 1].q, items[i].q) <= 0.0) --h;
    hull[h++] = items[i];
  }
  if (n > 1) --h;  // the last point repeats the first
  // drop_axis keeps orientation seen from +axis; flip if the normal points the other way.
  const bool reverse = normal[axis] < 0.0;
  // A hull of n points has at most n. Non-finite coordinates (whose turns
  // compare false) can chain up to 2n - 2, more than r holds: the engine
  // never passes them (meshes and poses refuse them), but a direct call
  // must stay inside its arrays (the kernel fuzzer found it).
  r.count = std::min(h, TriangleIntersection::kMaxPoints);
  for (int i = 0; i < r.count; ++i) r.points[i] = hull[reverse ? (r.count - 1 - i) : i].p;
}

}  // namespace

bool triangles_intersect(const Triangle& a, const Triangle& b) {
  const bool a_deg = degenerate(a), b_deg = degenerate(b);
  const PlaneSides sa = plane_sides(a, b, b_deg);
  if (strictly_one_side(sa)) return false;
  const PlaneSides sb = plane_sides(b, a, a_deg);
  if (strictly_one_side(sb)) return false;
  return any_edge_meets(a, sa, b, b_deg) || any_edge_meets(b, sb, a, a_deg);
}

TriangleIntersection intersect_triangles(const Triangle& a, const Triangle& b) {
  return intersect_triangles(a, b, degenerate(a), degenerate(b));
}

TriangleIntersection intersect_triangles(const Triangle& a, const Triangle& b, bool a_deg, bool b_deg) {
  TriangleIntersection r;
  const PlaneSides sa = plane_sides(a, b, b_deg);
  if (strictly_one_side(sa)) return r;
  const PlaneSides sb = plane_sides(b, a, a_deg);
  if (strictly_one_side(sb)) return r;

  PointSet points;
  collect_points(a, sa, b, b_deg, points);
  collect_points(b, sb, a, a_deg, points);
  if (points.n == 0) return r;
  r.intersects = true;

  const bool coplanar = !a_deg && !b_deg && sa.side[0] == 0 && sa.side[1] == 0 && sa.side[2] == 0;
  if (coplanar) {
    r.coplanar = true;
    double size = 0.0;
    for (const Triangle* t : {&a, &b})
      for (int k = 0; k < 3; ++k) size = std::max(size, glm::length(t->v[(k + 1) % 3] - t->v[k]));
    coplanar_hull(points, glm::cross(a.v[1] - a.v[0], a.v[2] - a.v[0]), 1e-12 * size, r);
  } else {
    farthest_pair(points, r);
  }
  return r;
}

bool segment_crosses_triangle(const Vec3& p_in, const Vec3& q_in, const Triangle& t, Vec3& point) {
  if (degenerate(t)) return false;
  // A canonical direction (lexicographic), so that (p, q) and (q, p) run the
  // same arithmetic.
  const bool swap =
      q_in.x < p_in.x || (q_in.x == p_in.x && (q_in.y < p_in.y || (q_in.y == p_in.y && q_in.z < p_in.z)));
  const Vec3& p = swap ? q_in : p_in;
  const Vec3& q = swap ? p_in : q_in;
  const int sp = orient3d(t.v[0], t.v[1], t.v[2], p);
  const int sq = orient3d(t.v[0], t.v[1], t.v[2], q);
  if (sp == 0 && sq == 0) return false;
  if (!segment_triangle(p, q, sp, sq, t, false)) return false;
  PointSet one;
  add_segment_triangle_points(p, q, sp, sq, t, false, one);
  point = one.p[0];
  return true;
}

}  // namespace prox::geometry
