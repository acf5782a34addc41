// Normal cones: a set of unit directions within a half-angle of an axis.
#pragma once

#include "geometry/types.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace prox {

inline constexpr double kPi = 3.14159265358979323846;

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

}  // namespace prox
