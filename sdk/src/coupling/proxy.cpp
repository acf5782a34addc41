#include "coupling/proxy.h"

#include "contact/global_search.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace prox::coupling {
namespace {

constexpr int kMaxHalvings = 8;
// Steps shorter than this share of the safety distance are not taken.
constexpr double kNegligibleStep = 1e-3;
// The share of the predicted distance after a step that the exact check
// asks for (the rest absorbs the linearisation's error).
constexpr double kExpectedFraction = 0.9;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void update(const CouplingSettings& coupling, const ProxySettings& settings, const ProxyTool& tool,
            const Obstacle* obstacles, std::size_t count, const Pose& device, const Pose* anchor,
            ProxyState& state, ProxyStats& stats);

}  // namespace

double clearance(const ProxyTool& tool, const Pose& pose, const Obstacle* obstacles, std::size_t count,
                 double cap) {
  double best = cap;
  for (std::size_t i = 0; i < count; ++i) {
    const PairQuery q{
        obstacles[i].mesh, obstacles[i].snch, obstacles[i].pose, tool.mesh, tool.snch, pose, 0.0};
    best = std::min(best, minimum_distance(q, best));
  }
  return best;
}

bool clear_of(const ProxyTool& tool, const Pose& pose, const Obstacle* obstacles, std::size_t count,
              double distance, NodeStack& stack) {
  for (std::size_t i = 0; i < count; ++i) {
    const PairQuery q{
        obstacles[i].mesh, obstacles[i].snch, obstacles[i].pose, tool.mesh, tool.snch, pose, 0.0};
    if (closer_than(q, distance, stack)) return false;
  }
  return true;
}

void update_proxy(const CouplingSettings& coupling, const ProxySettings& settings, const ProxyTool& tool,
                  const Obstacle* obstacles, std::size_t count, const Pose& device, const Pose* anchor,
                  ProxyState& state, ProxyStats& stats) {
  const auto start = Clock::now();
  update(coupling, settings, tool, obstacles, count, device, anchor, state, stats);
  stats.seconds = seconds_since(start);
}

namespace {
void update(const CouplingSettings& coupling, const ProxySettings& settings, const ProxyTool& tool,
            const Obstacle* obstacles, std::size_t count, const Pose& device, const Pose* anchor,
            ProxyState& state, ProxyStats& stats) {
  stats = ProxyStats{};
  const double ds = settings.safety_distance;
  // Conservative advancement: whatever the constraints miss was farther than
  // the cutoff where they were found; a proxy within half the margin of
  // there cannot reach the safety distance of it.
  const double max_step = 0.5 * (settings.cutoff - ds);
  if (state.clearance < 0.0) {
    state.clearance = clearance(tool, state.pose, obstacles, count, settings.cutoff);
    ++stats.distance_checks;
  }
  const Twist desired = twist_between(state.pose, device, tool.reference_local);
  const double target = target_distance(ds);
  const auto solve_start = Clock::now();
  const Twist u = solve_step(coupling, desired, state.constraints, target, max_step, state.lambda);
  stats.solve_seconds = seconds_since(solve_start);
  for (const ProxyConstraint& c : state.constraints) stats.constraints += c.distance - target <= max_step;
  bool free = true;  // no constraint changed the desired step
  for (std::size_t i = 0; i < state.constraints.size(); ++i) free &= state.lambda[i] == 0.0;

  const double delta = twist_displacement(u, tool.radius);
  // A step of next to nothing (held against a wall, the solve's residual)
  // is not worth a check.
  if (!(delta > kNegligibleStep * ds) || !std::isfinite(delta)) {
    stats.at_device = free && !(delta > 0.0);
    return;
  }
  double s = std::min(1.0, max_step / delta);
  // A proxy that starts closer than the safety distance (created there) may
  // not go deeper; it is held to the safety distance once out.
  const double required = std::min(ds, state.clearance);
  // What the constraints predict the distance after the step to be (the
  // cutoff when none is near): most of it is asked of the exact check, so
  // that a step that passes leaves a clearance the next step can use.
  double predicted = settings.cutoff;
  for (const ProxyConstraint& c : state.constraints)
    if (c.distance - target <= max_step)
      predicted = std::min(predicted, c.distance + s * (glm::dot(c.normal, u.linear) +
                                                        glm::dot(glm::cross(c.arm, c.normal), u.angular)));
  const double expected = std::min(std::max(required, kExpectedFraction * predicted), 0.5 * settings.cutoff);
  // The longest step the Lipschitz bound allows if the check at `expected`
  // passes.
  s = std::min(s, std::max(0.0, state.clearance + expected - required) / delta);
  for (int k = 0; k <= kMaxHalvings; ++k, s *= 0.5) {
    const bool whole = free && s == 1.0;
    // Nothing in the way: land on the device pose exactly, not on its
    // reconstruction through the twist.
    const Pose candidate = whole ? device : apply_twist(state.pose, tool.reference_local, u, s);
    const double step = s * delta;
    if (anchor &&
        twist_displacement(twist_between(*anchor, candidate, tool.reference_local), tool.radius) > max_step) {
      ++stats.halvings;
      continue;
    }
    // The distance the candidate needs: at least `required`, and enough
    // that the step cannot have passed through anything on the way.
    const double needed = std::max(required, step + required - state.clearance);
    const double asked = std::max(needed, expected);
    ++stats.distance_checks;
    bool clear = clear_of(tool, candidate, obstacles, count, asked, state.stack);
    double known = asked;
    if (!clear && asked > needed) {
      ++stats.distance_checks;
      clear = clear_of(tool, candidate, obstacles, count, needed, state.stack);
      known = needed;
    }
    if (clear) {
      state.pose = candidate;
      state.clearance = known;
      stats.moved = true;
      stats.at_device = whole;
      return;
    }
    ++stats.halvings;
  }
}

}  // namespace

}  // namespace prox::coupling
