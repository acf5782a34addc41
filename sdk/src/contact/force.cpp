#include "contact/force.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace prox {

ForceSettings hard_force_settings() {
  ForceSettings s;
  s.curve = ForceCurve::Exponential;
  s.safety_distance = 0.0003;
  s.decay_length = 0.0003;
  s.cutoff = 0.005;
  return s;
}

ForceSettings soft_force_settings() {
  ForceSettings s;
  s.curve = ForceCurve::Linear;
  s.safety_distance = 0.002;
  s.cutoff = 0.01;
  return s;
}

double force_magnitude(const ForceSettings& s, double distance) {
  if (!(distance < s.cutoff)) return 0.0;  // also NaN
  if (distance <= s.safety_distance) return s.max_force;
  const double span = s.cutoff - s.safety_distance;
  if (s.curve == ForceCurve::Linear) return s.max_force * (s.cutoff - distance) / span;
  // exp(-(d - ds)/L), shifted and rescaled so that it is max_force at the
  // safety distance and exactly zero at the cutoff: no jump when an LMD
  // crosses the cutoff.
  const double tail = std::exp(-span / s.decay_length);
  const double e = std::exp(-(distance - s.safety_distance) / s.decay_length);
  return s.max_force * std::max(0.0, (e - tail) / (1.0 - tail));
}

void WrenchSum::add(const ForceSettings& s, const Vec3& point_b, const Vec3& direction, double distance,
                    double weight) {
  const Vec3 f = (weight * force_magnitude(s, distance)) * direction;
  force_ += f;
  torque_ += glm::cross(point_b - reference_point_, f);
}

Wrench WrenchSum::finish(const ForceSettings& s) const {
  Wrench w{force_, torque_, false};
  // Clipping the force scales the torque alike, keeping the wrench's line of
  // action; the torque then has its own limit.
  const double f = glm::length(w.force);
  if (f > s.max_force) {
    const double k = s.max_force / f;
    w.force *= k, w.torque *= k, w.clipped = true;
  }
  const double t = glm::length(w.torque);
  if (t > s.max_torque) w.torque *= s.max_torque / t, w.clipped = true;
  return w;
}

Wrench tool_wrench(const ForceSettings& s, const std::vector<LmdPair>& lmds, const Vec3& reference_point) {
  WrenchSum sum(reference_point);
  for (const LmdPair& p : lmds) {
    const Vec3 d = p.point_b - p.point_a;
    const double len = glm::length(d);
    if (!(len > 0.0)) continue;  // touching: no direction (intersections are not LMDs)
    sum.add(s, p.point_b, d / len, p.distance, p.patch_count);
  }
  return sum.finish(s);
}

}  // namespace prox
