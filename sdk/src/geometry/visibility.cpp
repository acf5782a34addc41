#include "geometry/visibility.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace prox::geometry {
namespace {

// Closed convex polygons (here: triangles, possibly degenerate) overlap in 2D
// unless one of their edge normals separates them by more than `slack`.
bool separated_along_edges(const Vec2* p, const Vec2* q, double slack) {
  for (int k = 0; k < 3; ++k) {
    const Vec2 e = p[(k + 1) % 3] - p[k];
    const Vec2 axis(-e.y, e.x);
    const double len = std::sqrt(glm::dot(axis, axis));
    if (len == 0.0) continue;
    double p_lo = INFINITY, p_hi = -INFINITY, q_lo = INFINITY, q_hi = -INFINITY;
    for (int i = 0; i < 3; ++i) {
      const double sp = glm::dot(axis, p[i]) / len, sq = glm::dot(axis, q[i]) / len;
      p_lo = std::min(p_lo, sp), p_hi = std::max(p_hi, sp);
      q_lo = std::min(q_lo, sq), q_hi = std::max(q_hi, sq);
    }
    if (q_lo > p_hi + slack || p_lo > q_hi + slack) return true;
  }
  return false;
}

// A degenerate (segment-like) pair needs the segment's own normal as an axis
// too; the edge normals of a collinear triangle all coincide with it, so the
// loop above already has it unless the triangle is a single point.

double longest_edge(const Triangle& t) {
  double m = 0.0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = t.v[(k + 1) % 3] - t.v[k];
    m = std::max(m, glm::dot(e, e));
  }
  return std::sqrt(m);
}

}  // namespace

namespace {

// A cone whose widest direction is within this angle's sine of the plane
// (1e-6 rad) reaches along it: the projection is undefined, the pair passes.
const double kFlatCos = std::sin(1e-6);

bool projects_onto_spread(const Triangle& a, const Vec3 normals_a[3], const Spread* spread_a,
                          const Triangle& b, double margin) {
  const Vec3 n = glm::cross(b.v[1] - b.v[0], b.v[2] - b.v[0]);
  const double n_len = std::sqrt(glm::dot(n, n));
  if (!(n_len > 0.0)) return true;  // b has no plane
  const Vec3 unit_n = n / n_len;

  // An orthonormal basis (u, w) of b's plane, with b.v[0] as the origin.
  const Vec3 u = glm::normalize(b.v[1] - b.v[0]);
  const Vec3 w = glm::cross(unit_n, u);

  const double scale = std::max(longest_edge(a), longest_edge(b));
  Vec2 pa[3], pb[3];
  double grow = 0.0;  // the largest deviation of a cone's hits from its axis's
  for (int i = 0; i < 3; ++i) {
    const Vec3 m = normals_a[i];
    const double m_len = std::sqrt(glm::dot(m, m));
    const double along = glm::dot(m, unit_n);  // cosine times |m|
    // A normal (nearly) parallel to the plane projects to infinity: undefined,
    // so the pair passes. The cut-off is an angle (about 1e-6 rad), not a length.
    if (!(m_len > 0.0) || std::abs(along) <= 1e-6 * m_len) return true;
    const double height = glm::dot(b.v[0] - a.v[i], unit_n);
    if (spread_a) {
      // tan(tilt + spread) - tan(tilt) from cosines and sines: the tilt's
      // (theta, from the plane's normal) from a dot and a cross product, the
      // spread's as kept; tan(far) is their sum's sine over its cosine, which
      // a common factor of the spread's pair leaves unchanged.
      const Spread& spread = spread_a[i];
      if (!(spread.cos > 0.0)) return true;  // nothing known of the cone
      const Vec3 side = glm::cross(m, unit_n);
      const double cos_tilt = std::abs(along) / m_len, sin_tilt = std::sqrt(glm::dot(side, side)) / m_len;
      const double cos_far = cos_tilt * spread.cos - sin_tilt * spread.sin;
      const double sin_far = sin_tilt * spread.cos + cos_tilt * spread.sin;
      if (cos_far <= kFlatCos) return true;  // the cone reaches along the plane
      grow = std::max(grow, std::abs(height) * (sin_far / cos_far - sin_tilt / cos_tilt));
    }
    const double t = height / along;
    const Vec3 projected = a.v[i] + t * m - b.v[0];
    pa[i] = Vec2(glm::dot(projected, u), glm::dot(projected, w));
    const Vec3 rb = b.v[i] - b.v[0];
    pb[i] = Vec2(glm::dot(rb, u), glm::dot(rb, w));
  }
  const double slack = margin * scale + grow;
  return !separated_along_edges(pa, pb, slack) && !separated_along_edges(pb, pa, slack);
}

}  // namespace

bool projects_onto(const Triangle& a, const Vec3 normals_a[3], const Triangle& b, double margin) {
  return projects_onto_spread(a, normals_a, nullptr, b, margin);
}

bool visibility_pretest(const Triangle& a, const Vec3 normals_a[3], const Triangle& b,
                        const Vec3 normals_b[3], double margin) {
  return projects_onto(a, normals_a, b, margin) && projects_onto(b, normals_b, a, margin);
}

bool visibility_pretest(const Triangle& a, const Vec3 normals_a[3], const Spread spread_a[3],
                        const Triangle& b, const Vec3 normals_b[3], const Spread spread_b[3], double margin) {
  return projects_onto_spread(a, normals_a, spread_a, b, margin) &&
         projects_onto_spread(b, normals_b, spread_b, a, margin);
}

bool visibility_pretest(const Triangle& a, const Vec3 normals_a[3], const double spread_a[3],
                        const Triangle& b, const Vec3 normals_b[3], const double spread_b[3], double margin) {
  const Spread sa[3] = {Spread::of_angle(spread_a[0]), Spread::of_angle(spread_a[1]), Spread::of_angle(spread_a[2])};
  const Spread sb[3] = {Spread::of_angle(spread_b[0]), Spread::of_angle(spread_b[1]), Spread::of_angle(spread_b[2])};
  return visibility_pretest(a, normals_a, sa, b, normals_b, sb, margin);
}

Spread Spread::of_angle(double radians) {
  if (!(radians < 0.5 * kPi)) return {};
  return {std::cos(radians), std::sin(radians)};
}

}  // namespace prox::geometry
