// The constrained tool (docs/coupling.md): a proxy pose that follows the
// device's pose but never comes closer to another body than the safety
// distance (a 6-DOF god-object), and the virtual coupling, a spring-damper
// between the two, that gives the force.
#pragma once

#include "contact/force.h"
#include "contact/lmd.h"

#include <cstdint>
#include <vector>

namespace prox::coupling {

enum class ToolMode { Free, Constrained };

// The spring-damper between the device pose and the proxy pose.
struct CouplingSettings {
  double linear_stiffness = 1000.0;  // N/m
  double linear_damping = 2.0;       // N s/m
  double angular_stiffness = 1.0;    // N m/rad
  double angular_damping = 0.002;    // N m s/rad
};

// A small rigid motion about the tool's reference point: the reference
// point moves by `linear`, the tool turns by the rotation vector `angular`
// (world frame).
struct Twist {
  Vec3 linear{0.0};
  Vec3 angular{0.0};
};

// The rotation vector of r (axis times angle, angle in [0, pi]).
Vec3 rotation_vector(const glm::dmat3& r);
// exp of a rotation vector.
glm::dmat3 rotation_matrix(const Vec3& rotation_vector);

// The twist that takes `from` to `to` about the reference point (tool frame).
Twist twist_between(const Pose& from, const Pose& to, const Vec3& reference_local);
// `pose` moved by `s` times `twist` about the reference point.
Pose apply_twist(const Pose& pose, const Vec3& reference_local, const Twist& twist, double s = 1.0);
// The largest distance any tool point within `radius` of the reference
// point moves along the twist's path: a bound, |linear| + |angular| radius.
double twist_displacement(const Twist& twist, double radius);

// One LMD as a constraint on the proxy's motion: the tool's closest point
// relative to the reference point (world), the unit normal from the other
// body to the tool, the distance.
struct ProxyConstraint {
  Vec3 arm{0.0};
  Vec3 normal{0.0, 0.0, 1.0};
  double distance = 0.0;
};

// The constraints of `lmds` (A the other body, B the tool) for a tool whose
// reference point is at `reference` (world), appended to `out`; pairs
// touching (no direction) are skipped.
void append_constraints(const std::vector<LmdPair>& lmds, const Vec3& reference,
                        std::vector<ProxyConstraint>& out);
// One of them; false for a touching pair.
bool make_constraint(const LmdPair& lmd, const Vec3& reference, ProxyConstraint& out);

// The proxy's step: the twist u that minimises the coupling energy
// 1/2 k_t |v - v*|^2 + 1/2 k_r |w - w*|^2 towards `desired` subject to every
// constraint's distance, linearised along its normal, staying at or above
// `target_distance`: n . (v + w x arm) >= target - d. Solved on its dual by
// projected Gauss-Seidel (a few constraints, microseconds); constraints
// farther than `reach` cannot become active within a step and are ignored.
// Allocates nothing once `lambda` has grown to the constraint count.
Twist solve_step(const CouplingSettings& settings, const Twist& desired,
                 const std::vector<ProxyConstraint>& constraints, double target_distance, double reach,
                 std::vector<double>& lambda);

// The coupling's wrench on the tool held by the device, about the device
// pose's reference point: springs pulling the device towards the proxy
// (position and rotation) and dampers on the rate of that offset
// (`offset_rate`: d/dt of twist_between(device, proxy)).
Wrench coupling_wrench(const CouplingSettings& settings, const Pose& device, const Pose& proxy,
                       const Vec3& reference_local, const Twist& offset_rate);

// Smooths the offset rate the dampers act on: the proxy moves at the local
// rate, the device at the haptic rate, so the raw difference is stepwise.
class OffsetRate {
 public:
  // The filtered rate after the offset became `offset`, `dt` seconds after
  // the last call (dt <= 0 or the first call: zero rate).
  const Twist& update(const Twist& offset, double dt);
  const Twist& rate() const { return rate_; }
  void reset() { has_last_ = false, rate_ = Twist{}; }
  // Takes `offset` as the last one without a rate from it: the offset
  // jumped for a reason that is no motion (a new constraint set).
  void rebase(const Twist& offset) {
    if (has_last_) last_ = offset;
  }

 private:
  static constexpr double kTimeConstant = 0.002;  // s: a first-order low-pass
  Twist last_, rate_;
  bool has_last_ = false;
};

}  // namespace prox::coupling
