#include "stress/quad_reference.h"

#include <algorithm>
#include <cmath>
#if defined(__x86_64__) || defined(__i386__)
#include <quadmath.h>
#endif

namespace prox::stress {
namespace {

QVec3 operator-(const QVec3& a, const QVec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
QVec3 operator+(const QVec3& a, const QVec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
QVec3 operator*(Quad s, const QVec3& a) { return {s * a.x, s * a.y, s * a.z}; }
Quad dot(const QVec3& a, const QVec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
QVec3 cross(const QVec3& a, const QVec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Quad clamp01(Quad s) { return s < 0 ? Quad(0) : (s > 1 ? Quad(1) : s); }

struct Pair {
  QVec3 pa, pb;
  Quad d2;
};

QVec3 point_segment(const QVec3& p, const QVec3& a, const QVec3& b) {
  const QVec3 d = b - a;
  const Quad dd = dot(d, d);
  if (dd == 0) return a;
  return a + clamp01(dot(p - a, d) / dd) * d;
}

// Closest point of a triangle by barycentrics from the 2x2 Gram system; a
// singular system (degenerate triangle) or a projection outside falls back
// to the three edges.
QVec3 point_triangle(const QVec3& p, const QVec3& a, const QVec3& b, const QVec3& c) {
  const QVec3 e0 = b - a, e1 = c - a, r = p - a;
  const Quad g00 = dot(e0, e0), g01 = dot(e0, e1), g11 = dot(e1, e1);
  const Quad det = g00 * g11 - g01 * g01;
  if (det > 0) {
    const Quad r0 = dot(r, e0), r1 = dot(r, e1);
    const Quad u = (g11 * r0 - g01 * r1) / det, v = (g00 * r1 - g01 * r0) / det;
    if (u >= 0 && v >= 0 && u + v <= 1) return a + u * e0 + v * e1;
  }
  QVec3 best = point_segment(p, a, b);
  Quad best_d2 = dot(p - best, p - best);
  for (const QVec3* e : {&b, &c}) {
    const QVec3& from = *e;
    const QVec3& to = e == &b ? c : a;
    const QVec3 x = point_segment(p, from, to);
    const Quad d2 = dot(p - x, p - x);
    if (d2 < best_d2) best = x, best_d2 = d2;
  }
  return best;
}

Pair segment_segment(const QVec3& p0, const QVec3& p1, const QVec3& q0, const QVec3& q1) {
  Pair best{p0, q0, dot(p0 - q0, p0 - q0)};
  auto consider = [&](const QVec3& pa, const QVec3& pb) {
    const Quad d2 = dot(pa - pb, pa - pb);
    if (d2 < best.d2) best = {pa, pb, d2};
  };
  consider(p0, point_segment(p0, q0, q1));
  consider(p1, point_segment(p1, q0, q1));
  consider(point_segment(q0, p0, p1), q0);
  consider(point_segment(q1, p0, p1), q1);
  // Interior critical point from the normal equations.
  const QVec3 d = p1 - p0, e = q1 - q0, r = p0 - q0;
  const Quad a = dot(d, d), b = dot(d, e), c = dot(e, e), f = dot(d, r), g = dot(e, r);
  const Quad det = a * c - b * b;
  if (det > 0) {
    const Quad s = (b * g - c * f) / det, t = (a * g - b * f) / det;
    if (s > 0 && s < 1 && t > 0 && t < 1) consider(p0 + s * d, q0 + t * e);
  }
  return best;
}

// Does segment [p, q] pierce triangle (a, b, c) at a single point? Cramer's
// rule on p + s (q - p) = a + u (b - a) + v (c - a). Coplanar or degenerate
// configurations (zero determinant) are left to the distance candidates, which
// reach zero there.
bool segment_pierces(const QVec3& p, const QVec3& q, const QVec3& a, const QVec3& b, const QVec3& c) {
  const QVec3 d = q - p, e0 = b - a, e1 = c - a, r = p - a;
  const Quad det = -dot(d, cross(e0, e1));
  if (det == 0) return false;
  const Quad s = dot(r, cross(e0, e1)) / det;
  const Quad u = -dot(d, cross(r, e1)) / det;
  const Quad v = -dot(d, cross(e0, r)) / det;
  return s >= 0 && s <= 1 && u >= 0 && v >= 0 && u + v <= 1;
}

}  // namespace

QVec3 to_quad(const Vec3& v) { return {Quad(v.x), Quad(v.y), Quad(v.z)}; }
Vec3 to_double(const QVec3& v) { return {to_double(v.x), to_double(v.y), to_double(v.z)}; }
double to_double(Quad x) { return static_cast<double>(x); }
Quad qsqrt(Quad x) {
#if defined(__x86_64__) || defined(__i386__)
  return sqrtq(x);
#else
  return std::sqrt(x);
#endif
}

Quad reference_point_triangle_distance(const QVec3& p, const Triangle& t) {
  const QVec3 x = point_triangle(p, to_quad(t.v[0]), to_quad(t.v[1]), to_quad(t.v[2]));
  return qsqrt(dot(p - x, p - x));
}

ReferenceDistance reference_distance(const Triangle& ta, const Triangle& tb) {
  const QVec3 a[3] = {to_quad(ta.v[0]), to_quad(ta.v[1]), to_quad(ta.v[2])};
  const QVec3 b[3] = {to_quad(tb.v[0]), to_quad(tb.v[1]), to_quad(tb.v[2])};
  Pair best{a[0], b[0], dot(a[0] - b[0], a[0] - b[0])};
  auto consider = [&](const Pair& p) {
    if (p.d2 < best.d2) best = p;
  };
  for (int i = 0; i < 3; ++i) {
    const QVec3 qb = point_triangle(a[i], b[0], b[1], b[2]);
    consider({a[i], qb, dot(a[i] - qb, a[i] - qb)});
    const QVec3 qa = point_triangle(b[i], a[0], a[1], a[2]);
    consider({qa, b[i], dot(qa - b[i], qa - b[i])});
    for (int j = 0; j < 3; ++j) consider(segment_segment(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3]));
  }
  bool pierced = false;
  for (int i = 0; i < 3 && !pierced; ++i) {
    pierced = segment_pierces(a[i], a[(i + 1) % 3], b[0], b[1], b[2]) ||
              segment_pierces(b[i], b[(i + 1) % 3], a[0], a[1], a[2]);
  }
  // Size scale for "touching": the largest coordinate difference involved.
  Quad scale = 0;
  for (const QVec3* t : {a, b})
    for (int i = 0; i < 3; ++i)
      for (const QVec3* u : {a, b})
        for (int j = 0; j < 3; ++j) {
          const QVec3 d = t[i] - u[j];
          scale = std::max(scale, dot(d, d));
        }
  const bool touching = best.d2 <= Quad(1e-60) * scale;
  ReferenceDistance r;
  r.intersects = pierced || touching;
  if (r.intersects) {
    r.distance = 0;
    r.point_a = r.point_b = best.pa;
  } else {
    r.distance = qsqrt(best.d2);
    r.point_a = best.pa;
    r.point_b = best.pb;
  }
  return r;
}

}  // namespace prox::stress
