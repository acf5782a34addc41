#include "coupling/coupling.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace prox::coupling {

Vec3 rotation_vector(const glm::dmat3& r) {
  // Through the quaternion: stable at small angles and near pi alike.
  glm::dquat q = glm::quat_cast(r);
  if (q.w < 0.0) q = -q;
  const Vec3 axis(q.x, q.y, q.z);
  const double s = glm::length(axis);
  if (!(s > 1e-300)) return Vec3(0.0);
  const double angle = 2.0 * std::atan2(s, q.w);
  return axis * (angle / s);
}

glm::dmat3 rotation_matrix(const Vec3& v) {
  const double angle = glm::length(v);
  if (!(angle > 0.0)) return glm::dmat3(1.0);
  const Vec3 axis = v / angle;
  const double s = std::sin(0.5 * angle);
  return glm::mat3_cast(glm::dquat(std::cos(0.5 * angle), axis.x * s, axis.y * s, axis.z * s));
}

Twist twist_between(const Pose& from, const Pose& to, const Vec3& reference_local) {
  return {to.apply(reference_local) - from.apply(reference_local),
          rotation_vector(to.rotation * glm::transpose(from.rotation))};
}

Pose apply_twist(const Pose& pose, const Vec3& reference_local, const Twist& twist, double s) {
  Pose out;
  out.rotation = rotation_matrix(s * twist.angular) * pose.rotation;
  const Vec3 reference = pose.apply(reference_local) + s * twist.linear;
  out.translation = reference - out.rotation * reference_local;
  return out;
}

double twist_displacement(const Twist& twist, double radius) {
  // A point at r from the reference point turning by angle a moves along an
  // arc of length a r, and the reference point along a line.
  return glm::length(twist.linear) + glm::length(twist.angular) * radius;
}

bool make_constraint(const LmdPair& lmd, const Vec3& reference, ProxyConstraint& out) {
  const Vec3 d = lmd.point_b - lmd.point_a;
  const double len = glm::length(d);
  if (!(len > 0.0)) return false;
  out = {lmd.point_b - reference, d / len, lmd.distance};
  return true;
}

void append_constraints(const std::vector<LmdPair>& lmds, const Vec3& reference,
                        std::vector<ProxyConstraint>& out) {
  ProxyConstraint c;
  for (const LmdPair& p : lmds)
    if (make_constraint(p, reference, c)) out.push_back(c);
}

Twist solve_step(const CouplingSettings& settings, const Twist& desired,
                 const std::vector<ProxyConstraint>& constraints, double target_distance, double reach,
                 std::vector<double>& lambda) {
  const double inv_kt = 1.0 / settings.linear_stiffness, inv_kr = 1.0 / settings.angular_stiffness;
  if (lambda.size() < constraints.size()) lambda.resize(constraints.size());
  std::fill(lambda.begin(), lambda.begin() + static_cast<std::ptrdiff_t>(constraints.size()), 0.0);
  Twist u = desired;
  // Projected Gauss-Seidel on the dual: u = u* + W^-1 J^T lambda, lambda >= 0,
  // with J_i = [n_i, arm_i x n_i] and W = diag(k_t, k_r). Each sweep is
  // exact for one constraint at a time; a handful of sweeps settle the few
  // active ones. The exact distance check after the solve is the guarantee,
  // not this tolerance.
  constexpr int kSweeps = 64;
  const double tolerance = 1e-6 * target_distance;
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    double largest = 0.0;
    for (std::size_t i = 0; i < constraints.size(); ++i) {
      const ProxyConstraint& c = constraints[i];
      if (c.distance - target_distance > reach) continue;  // cannot become active within a step
      const Vec3 an = glm::cross(c.arm, c.normal);
      const double rhs = target_distance - c.distance;
      const double residual = rhs - (glm::dot(c.normal, u.linear) + glm::dot(an, u.angular));
      if (residual <= 0.0 && lambda[i] == 0.0) continue;
      const double a = inv_kt + glm::dot(an, an) * inv_kr;
      const double next = std::max(0.0, lambda[i] + residual / a);
      const double change = next - lambda[i];
      if (change == 0.0) continue;
      lambda[i] = next;
      u.linear += (change * inv_kt) * c.normal;
      u.angular += (change * inv_kr) * an;
      largest = std::max(largest, std::abs(change) * a);
    }
    if (largest <= tolerance) break;
  }
  return u;
}

Wrench coupling_wrench(const CouplingSettings& settings, const Pose& device, const Pose& proxy,
                       const Vec3& reference_local, const Twist& offset_rate) {
  const Twist offset = twist_between(device, proxy, reference_local);
  Wrench w;
  w.force = settings.linear_stiffness * offset.linear + settings.linear_damping * offset_rate.linear;
  w.torque = settings.angular_stiffness * offset.angular + settings.angular_damping * offset_rate.angular;
  return w;
}

const Twist& OffsetRate::update(const Twist& offset, double dt) {
  if (!has_last_ || !(dt > 0.0) || !std::isfinite(dt)) {
    has_last_ = true;
    last_ = offset;
    rate_ = Twist{};
    return rate_;
  }
  const double k = dt / (dt + kTimeConstant);
  rate_.linear += k * ((offset.linear - last_.linear) / dt - rate_.linear);
  rate_.angular += k * ((offset.angular - last_.angular) / dt - rate_.angular);
  last_ = offset;
  return rate_;
}

}  // namespace prox::coupling
