#include "runtime/haptic_render.h"

#include "coupling/proxy.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace prox::runtime {

HapticRenderer::HapticRenderer(const RenderSettings& settings)
    : settings_(settings), stiffness_(settings.constrained ? DeviceLimits{} : settings.limits),
      last_proxy_(settings.start) {
  if (settings_.constrained) {
    lambda_.reserve(settings_.capacity);
    // A constrained tool's coupling is the virtual coupling: no stiffer than
    // the device renders, damped as much as it needs.
    coupling::CouplingSettings& c = settings_.coupling;
    if (settings_.limits.max_stiffness > 0.0) c.linear_stiffness = std::min(c.linear_stiffness, settings_.limits.max_stiffness);
    c.linear_damping = std::max(c.linear_damping, settings_.limits.damping);
  }
}

Wrench StiffnessLimit::step(const Wrench& target, const Vec3& point, double dt, const Wrench& current) {
  if (!started_) {
    last_point_ = point;
    started_ = true;
  }
  const Vec3 moved = point - last_point_;
  last_point_ = point;
  Wrench next = target;
  if (limits_.max_stiffness > 0.0 && glm::length(target.force) > glm::length(current.force)) {
    // Growing: by at most the device's stiffness times the motion; the
    // torque keeps pace with the force.
    const Vec3 gap = target.force - current.force;
    const double budget = limits_.max_stiffness * glm::length(moved), size = glm::length(gap);
    if (size > budget) {
      const double f = budget / size;
      next.force = current.force + gap * f;
      next.torque = current.torque + (target.torque - current.torque) * f;
    }
  }
  // Damping against motion into the force (pushing it in), never pulling.
  const double size = glm::length(next.force);
  if (limits_.damping > 0.0 && size > 0.0 && dt > 0.0) {
    const Vec3 n = next.force / size;
    const double into = -glm::dot(moved, n) / dt;  // m/s against the force
    if (into > 0.0) next.force += limits_.damping * into * n;
  }
  return next;
}

namespace {

// What the spring pulls the device towards, or null for nothing: the ideal
// proxy where the verified proxy's reach covers it; beyond it, with
// something within the cutoff of the verified proxy, the proxy at the reach
// (the hand is ahead of what has been checked, towards a surface); with
// nothing there, nothing (a proxy still joining its device in free air).
const Pose* spring_target(const coupling::HapticProxy& proxy, const ContactSnapshot& snapshot) {
  if (proxy.within_reach) return proxy.constrained ? &proxy.ideal : nullptr;
  return snapshot.constraints.empty() ? nullptr : &proxy.pose;
}

}  // namespace

Wrench HapticRenderer::instantaneous(const ContactSnapshot& snapshot, const Pose& device,
                                     coupling::HapticProxy* proxy, double* closest) {
  if (!settings_.constrained)
    return evaluate_contacts(settings_.force, snapshot, device, settings_.reference_local, closest);
  *proxy = coupling::haptic_proxy(settings_.coupling, {snapshot.tool_pose, snapshot.reach}, snapshot.constraints,
                                  coupling::target_distance(settings_.force.safety_distance), device,
                                  settings_.reference_local, snapshot.radius > 0.0 ? snapshot.radius : settings_.radius,
                                  lambda_);
  if (closest) *closest = closest_tracked_distance(snapshot);
  // The spring alone (no damper): free of every constraint the ideal is the
  // device pose itself, and the spring exactly nothing.
  const Pose* target = spring_target(*proxy, snapshot);
  if (!target) return Wrench{};
  return coupling::coupling_wrench(settings_.coupling, device, *target, settings_.reference_local, {});
}

void HapticRenderer::replacing(const ContactSnapshot& outgoing, const Pose& device) {
  if (!rendered_) return;  // nothing was rendered from it: no jump to carry
  coupling::HapticProxy proxy;
  outgoing_ = instantaneous(outgoing, device, &proxy, nullptr);
  const Pose* target = settings_.constrained ? spring_target(proxy, outgoing) : nullptr;
  outgoing_offset_ = target ? coupling::twist_between(device, *target, settings_.reference_local) : coupling::Twist{};
  replaced_ = true;
}

Wrench HapticRenderer::render(const ContactSnapshot& snapshot, const Pose& device, double dt, bool valid,
                              const Wrench& gate_output, Pose* proxy_out, double* closest) {
  const bool replaced = replaced_;
  replaced_ = false;
  if (!valid) {
    // The gate fades what is not trusted; the proxy stays where it was.
    continuity_.reset();
    stiffness_.reset();
    offset_rate_.reset();
    rendered_ = false;
    *proxy_out = settings_.constrained ? last_proxy_ : device;
    return Wrench{};
  }
  coupling::HapticProxy proxy;
  Wrench now = instantaneous(snapshot, device, &proxy, closest);
  if (settings_.constrained) {
    last_proxy_ = proxy.pose;
    // The damper on the offset's low-passed rate. Across a replaced
    // snapshot the rate is taken on the outgoing one's offset, so the jump
    // of the ideal it brings is no velocity.
    const Pose* target = spring_target(proxy, snapshot);
    const coupling::Twist offset =
        target ? coupling::twist_between(device, *target, settings_.reference_local) : coupling::Twist{};
    const coupling::Twist& rate =
        offset_rate_.update(replaced ? outgoing_offset_ : offset, rendered_ ? dt : 0.0);
    if (replaced) offset_rate_.rebase(offset);
    const Vec3 damper_force = settings_.coupling.linear_damping * rate.linear;
    const Vec3 damper_torque = settings_.coupling.angular_damping * rate.angular;
    now.force += damper_force, now.torque += damper_torque;
    if (replaced) outgoing_.force += damper_force, outgoing_.torque += damper_torque;
    // Free of every constraint the damper dies out with the offset's rate;
    // below what a device can render it is dropped, so free air is exactly
    // silent.
    if (!target && glm::length(damper_force) < ContinuityFilter::kZero &&
        glm::length(damper_torque) < ContinuityFilter::kZero)
      offset_rate_.reset();
    *proxy_out = proxy.pose;
  } else {
    *proxy_out = device;
  }
  if (replaced)
    continuity_.switched(outgoing_, now);
  else if (!rendered_)
    continuity_.switched(gate_output, now);  // trusted again (or the first tick): from what the device has
  rendered_ = true;
  const Wrench smooth = continuity_.step(now, dt);
  if (!stiffness_.active()) return smooth;
  return stiffness_.step(smooth, device.apply(settings_.reference_local), dt, gate_output);
}

}  // namespace prox::runtime
