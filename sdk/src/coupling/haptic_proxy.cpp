#include "coupling/haptic_proxy.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prox::coupling {

double unchecked_reach(double clearance, double from_anchor, double safety_distance, double cutoff) {
  if (!(clearance >= 0.0) || !std::isfinite(from_anchor)) return 0.0;
  return std::max(0.0, std::min(clearance, cutoff - from_anchor) - safety_distance);
}

HapticProxy haptic_proxy(const CouplingSettings& settings, const VerifiedProxy& verified,
                         const std::vector<ProxyConstraint>& constraints, double target_distance,
                         const Pose& device, const Vec3& reference_local, double radius,
                         std::vector<double>& lambda) {
  HapticProxy out;
  const Twist desired = twist_between(verified.pose, device, reference_local);
  // Every constraint counts: they are the LMDs within the cutoff, and the
  // step is not bounded here (the reach bounds the pose, not the ideal).
  const Twist u = solve_step(settings, desired, constraints, target_distance,
                             std::numeric_limits<double>::infinity(), lambda);
  for (std::size_t i = 0; i < constraints.size(); ++i) out.constrained |= lambda[i] != 0.0;
  // Unconstrained, the ideal is the device pose itself, not its
  // reconstruction through the twist: free air renders exactly nothing.
  out.ideal = out.constrained ? apply_twist(verified.pose, reference_local, u) : device;
  const Twist to_ideal = twist_between(verified.pose, out.ideal, reference_local);
  const double step = twist_displacement(to_ideal, radius);
  if (step <= verified.reach) {
    out.pose = out.ideal;
    return out;
  }
  out.within_reach = false;
  const double s = step > 0.0 && std::isfinite(step) ? verified.reach / step : 0.0;
  out.pose = apply_twist(verified.pose, reference_local, to_ideal, s);
  return out;
}

}  // namespace prox::coupling
