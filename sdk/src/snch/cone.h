// Normal cones: a set of unit directions within a half-angle of an axis.
#pragma once

#include "geometry/types.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace prox {

// The angle between two unit vectors, robust near 0 and pi (atan2 of the
// cross and dot products instead of acos of a rounded dot product).
inline double angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

struct Cone {
  Vec3 axis{0.0, 0.0, 1.0};  // unit
  double half_angle = kPi;   // radians; pi holds every direction

  bool unbounded() const { return half_angle >= kPi; }
  static Cone everything() { return {}; }
};

// The smallest cone holding both (exact for the union of two circular cones).
inline Cone merge(const Cone& a, const Cone& b) {
  if (a.unbounded() || b.unbounded()) return Cone::everything();
  const double theta = angle_between(a.axis, b.axis);
  if (theta + b.half_angle <= a.half_angle) return a;
  if (theta + a.half_angle <= b.half_angle) return b;
  const double half = 0.5 * (theta + a.half_angle + b.half_angle);
  if (half >= kPi) return Cone::everything();
  // Rotate a's axis towards b's by (half - a.half_angle) in their plane.
  const double turn = half - a.half_angle;
  const Vec3 ortho = b.axis - glm::dot(b.axis, a.axis) * a.axis;
  const double ortho_len = glm::length(ortho);
  if (!(ortho_len > 0.0)) return Cone::everything();  // opposite axes
  const Vec3 axis = std::cos(turn) * a.axis + std::sin(turn) * (ortho / ortho_len);
  return {glm::normalize(axis), half};
}

// A cone kept as the cosine and sine of its half-angle, the form the
// searches test with (their sums of angles become products) and a refit
// computes without trigonometry. Both are bounds: cos never above, sin never
// below the true half-angle's, so a cone built from rounded products still
// holds what it must.
struct CosCone {
  Vec3 axis{0.0, 0.0, 1.0};  // unit
  double cos = -1.0, sin = 0.0;  // of the half-angle; cos -1 holds every direction

  bool unbounded() const { return cos <= -1.0; }
  static CosCone everything() { return {}; }
  static CosCone of(const Cone& c) {
    if (c.unbounded()) return everything();
    return {c.axis, std::cos(c.half_angle), std::sin(c.half_angle)};
  }
};

namespace cone_detail {

// Each rounded product below is within a few 1e-16 of its exact value; every
// merged cone is widened by this much (radians, as a rotation) to stay a
// bound, and two angles within it of each other count as equal.
inline constexpr double kMergeMargin = 1e-14;

// Whether angle x is at most angle y, both in [0, 2 pi) and given by their
// cosines and sines, within kMergeMargin: the sine of y - x, which keeps its
// precision for small angles where a cosine would lose it.
inline bool at_most(double cx, double sx, double cy, double sy) {
  const bool x_past_pi = sx < 0.0, y_past_pi = sy < 0.0;
  if (x_past_pi != y_past_pi) return y_past_pi;
  return sy * cx - cy * sx >= -kMergeMargin;
}

// c widened by m radians (at least kMergeMargin): its half-angle's cosine
// and sine rotated.
inline CosCone widened(const Vec3& axis, double c, double s, double m = kMergeMargin) {
  const double cm = 1.0 - 0.5 * m * m;  // cos m, to rounding for m below 1e-3
  const double cw = c * cm - m * s, sw = s * cm + m * c;
  if (cw <= -1.0 || sw < 0.0) return CosCone::everything();
  return {axis, cw, sw};
}

}  // namespace cone_detail

// The smallest cone holding both, as merge(Cone, Cone) computes it, with
// sums and halvings of angles done on their cosines and sines (square roots,
// no trigonometry), then widened by a margin for the rounding.
inline CosCone merge(const CosCone& a, const CosCone& b) {
  using cone_detail::at_most;
  if (a.unbounded() || b.unbounded()) return CosCone::everything();
  // theta, the angle between the axes, in [0, pi].
  const double ct = std::clamp(glm::dot(a.axis, b.axis), -1.0, 1.0);
  const double st = glm::length(glm::cross(a.axis, b.axis));
  // u = theta + b's half-angle and v = theta + a's, each in [0, 2 pi).
  const double cu = ct * b.cos - st * b.sin, su = st * b.cos + ct * b.sin;
  if (at_most(cu, su, a.cos, a.sin)) return cone_detail::widened(a.axis, a.cos, a.sin);  // b inside a
  const double cv = ct * a.cos - st * a.sin, sv = st * a.cos + ct * a.sin;
  if (at_most(cv, sv, b.cos, b.sin)) return cone_detail::widened(b.axis, b.cos, b.sin);  // a inside b
  // S = v + b's half-angle, in [0, 3 pi). Its half is the merged half-angle;
  // pi or more holds every direction: S >= 2 pi, b's half-angle >= 2 pi - v.
  if (sv < 0.0 && at_most(cv, -sv, b.cos, b.sin)) return CosCone::everything();
  const double cs = cv * b.cos - sv * b.sin, ss = sv * b.cos + cv * b.sin;
  // The half of S, in [0, pi): the larger of its cosine and sine by a
  // square root, the other by division, each accurate where it is small.
  double ch, sh;
  if (cs >= 0.0) {
    ch = std::sqrt(0.5 * (1.0 + cs));
    if (ss < 0.0) ch = -ch;
    sh = ss / (2.0 * ch);
  } else {
    sh = std::sqrt(0.5 * (1.0 - cs));
    ch = ss / (2.0 * sh);
  }
  // Rotate a's axis towards b's by the half minus a's half-angle.
  const Vec3 ortho = b.axis - ct * a.axis;
  const double ortho_len = glm::length(ortho);
  // Exactly opposite axes leave no plane to turn in (equal ones returned
  // above). Otherwise the plane's direction is known to about
  // 5e-16 / ortho_len radians, and the axis turned in it by as much times
  // the sine of the turn: the margin grows by that.
  if (!(ortho_len > 0.0)) return CosCone::everything();
  const double cturn = ch * a.cos + sh * a.sin, sturn = sh * a.cos - ch * a.sin;
  const double inv_ortho = 1.0 / ortho_len;
  const double noise = 1e-15 * inv_ortho * std::abs(sturn);
  if (!(noise < 1e-3)) return CosCone::everything();
  const Vec3 turned = cturn * a.axis + (sturn * inv_ortho) * ortho;
  const Vec3 axis = turned * (1.0 / std::sqrt(glm::dot(turned, turned)));
  return cone_detail::widened(axis, ch, sh, cone_detail::kMergeMargin + noise);
}

}  // namespace prox
