// One update of a constrained tool's proxy (docs/coupling.md): the
// constrained solve towards the device pose, limited as conservative
// advancement limits a step, and accepted only where the exact distance
// says it is safe. What the deterministic step and the local tracking
// thread both run.
#pragma once

#include "coupling/clearance.h"
#include "coupling/coupling.h"

#include <vector>

namespace prox::coupling {

// A body the proxy must stay away from, at its pose.
struct Obstacle {
  const Mesh* mesh = nullptr;
  const Snch* snch = nullptr;
  Pose pose;
};

struct ProxyTool {
  const Mesh* mesh = nullptr;
  const Snch* snch = nullptr;
  Vec3 reference_local{0.0};
  double radius = 0.0;  // of the tool's bounds about the reference point
};

// The distance the proxy's solve holds it at: the safety distance and as
// much again. The linearisation's second-order error (rotation, curvature)
// then rarely takes the exact distance below the safety distance, and the
// clearance it leaves is what lets the next step slide (a step is bounded
// by the clearances at both ends).
inline double target_distance(double safety_distance) { return 2.0 * safety_distance; }

struct ProxySettings {
  double safety_distance = 0.0005;  // the proxy's exact distance never goes below this
  double cutoff = 0.005;            // the LMDs' cutoff: the constraints cover what is closer
};

// What an update keeps: the proxy, what it knows of its distance, and the
// solver's memory (so that a warm update allocates nothing).
struct ProxyState {
  Pose pose;
  // A lower bound of the proxy's exact distance to every obstacle, capped
  // at the cutoff; negative: not measured yet.
  double clearance = -1.0;
  std::vector<ProxyConstraint> constraints;  // the caller fills them (append_constraints)
  std::vector<double> lambda;
  NodeStack stack;
};

struct ProxyStats {
  int constraints = 0;  // within reach of the step
  int halvings = 0;     // steps halved before one was safe
  int distance_checks = 0;
  bool moved = false;
  bool at_device = false;      // the proxy is the device pose (nothing in the way)
  double solve_seconds = 0.0;  // the constrained solve
  double seconds = 0.0;        // the whole update, checks included
};

// The proxy's exact distance to the obstacles, capped at `cap` (the
// obstacles' exact minimum distance when closer).
double clearance(const ProxyTool& tool, const Pose& pose, const Obstacle* obstacles, std::size_t count,
                 double cap);
// Whether no obstacle is closer than `distance` (exact; the decision stops
// at the first closer pair, far cheaper than the distance itself).
bool clear_of(const ProxyTool& tool, const Pose& pose, const Obstacle* obstacles, std::size_t count,
              double distance, NodeStack& stack);

// Moves state.pose towards `device` as far as the constraints allow. A step
// is taken only when, with d0 the clearance before and d1 the exact
// distance after, d1 >= the safety distance and the step's largest point
// displacement is at most d0 + d1 - safety distance: the distance is
// 1-Lipschitz in the displacement, so along the whole step the proxy stays
// at least half the safety distance from every obstacle and never tunnels.
// Both are one exact decision (clear_of) at the distance they need; a step
// that fails it is halved.
// `anchor` (optional) is where the constraints were found complete (the
// last global search): the proxy stays within half the margin between
// cutoff and safety distance of it, so nothing beyond the cutoff there can
// come within the safety distance.
void update_proxy(const CouplingSettings& coupling, const ProxySettings& settings, const ProxyTool& tool,
                  const Obstacle* obstacles, std::size_t count, const Pose& device, const Pose* anchor,
                  ProxyState& state, ProxyStats& stats);

}  // namespace prox::coupling
