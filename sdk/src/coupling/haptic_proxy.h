// The constrained tool's proxy at the haptic rate (docs/coupling.md, "At the
// haptic rate"): the intermediate representation of Mark et al. (1996) and
// of a god-object. The local tracking thread moves a verified proxy with
// exact distance checks and hands over the constraints it tracked there and
// how far from it the proxy may go unchecked; every haptic tick solves the
// small projection of this tick's device pose on those constraints. No
// exact distance, no allocation (once `lambda` has its capacity).
#pragma once

#include "coupling/coupling.h"

#include <vector>

namespace prox::coupling {

// What the local thread hands over, beside the constraints: the verified
// proxy and the radius of the ball about it (in the largest displacement
// of any tool point, twist_displacement) inside which every pose keeps the
// safety distance.
struct VerifiedProxy {
  Pose pose;
  double reach = 0.0;
};

// The radius a verified proxy may be left by: with `clearance` a lower bound
// of its exact distance to the bodies the last global search found near
// the anchor, and `from_anchor` its displacement from where that search
// was made, every body is at least min(clearance, cutoff - from_anchor)
// away, and the distance is 1-Lipschitz in the displacement.
double unchecked_reach(double clearance, double from_anchor, double safety_distance, double cutoff);

struct HapticProxy {
  // This tick's device pose projected on the constraints (linearised at the
  // verified proxy): where a god-object would be, and what the coupling's
  // spring pulls the device towards. The device pose itself when no
  // constraint holds it back.
  Pose ideal;
  // The verified proxy moved towards `ideal`, no farther than its reach:
  // never closer than the safety distance to anything. `ideal` when it is
  // within reach.
  Pose pose;
  bool constrained = false;  // a constraint held the ideal back from the device
  bool within_reach = true;  // pose == ideal
};

HapticProxy haptic_proxy(const CouplingSettings& settings, const VerifiedProxy& verified,
                         const std::vector<ProxyConstraint>& constraints, double target_distance,
                         const Pose& device, const Vec3& reference_local, double radius,
                         std::vector<double>& lambda);

}  // namespace prox::coupling
