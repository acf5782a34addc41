#include "runtime/haptic.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace prox::runtime {
namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Moves `from` towards `to` by at most `step`; true when it had to stop short.
bool approach(Vec3& from, const Vec3& to, double step) {
  const Vec3 d = to - from;
  const double len = glm::length(d);
  if (len <= step) {
    from = to;
    return false;
  }
  from += (step / len) * d;
  return true;
}

// Scales v down to length at most `limit`; true when it did.
bool clamp_length(Vec3& v, double limit) {
  const double len = glm::length(v);
  if (len <= limit) return false;
  v *= limit / len;
  return true;
}

}  // namespace

bool to_haptic_contact(const LmdPair& lmd, const Pose& tool_to_local, HapticContact& out) {
  const Vec3 d = lmd.point_b - lmd.point_a;
  const double len = glm::length(d);
  if (!(len > 0.0)) return false;
  out = {tool_to_local.apply(lmd.point_b), lmd.point_a, d / len, lmd.distance,
         static_cast<double>(lmd.patch_count)};
  return true;
}

std::uint64_t snapshot_checksum(const ContactSnapshot& snapshot) {
  auto bits = [](double v) {
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
  };
  std::uint64_t h = snapshot.sequence * 0x9E3779B97F4A7C15ull ^ snapshot.contacts.size();
  for (const HapticContact& c : snapshot.contacts)
    h = (h ^ bits(c.distance) ^ (bits(c.tool_point_local.x) << 1) ^ bits(c.other_point.y)) * 0x100000001B3ull;
  for (const coupling::ProxyConstraint& c : snapshot.constraints)
    h = (h ^ bits(c.distance) ^ (bits(c.normal.x) << 1) ^ bits(c.arm.y)) * 0x100000001B3ull;
  return h ^ bits(snapshot.time) ^ bits(snapshot.tool_pose.translation.x) ^ (bits(snapshot.reach) << 3) ^
         (bits(snapshot.radius) << 5);
}

Wrench evaluate_contacts(const ForceSettings& settings, const ContactSnapshot& snapshot, const Pose& pose,
                         const Vec3& reference_point_local, double* closest) {
  WrenchSum sum(pose.apply(reference_point_local));
  double least = std::numeric_limits<double>::infinity();
  for (const HapticContact& c : snapshot.contacts) {
    const Vec3 b = pose.apply(c.tool_point_local);
    // Closer than zero along the normal means the hand has pushed through
    // the tangent plane since tracking: full force, never a negative one.
    const double d = std::max(0.0, glm::dot(b - c.other_point, c.normal));
    sum.add(settings, b, c.normal, d, c.weight);
    least = std::min(least, d);
  }
  if (closest) *closest = least;
  return sum.finish(settings);
}

Wrench ContinuityFilter::step(const Wrench& instantaneous, double dt) {
  if (dt > 0.0 && std::isfinite(dt)) {
    // x'' = -2 x' / T - x / T^2, solved exactly over dt.
    constexpr double T = kTimeConstant;
    const double k = std::exp(-dt / T);
    auto advance = [&](Vec3& x, Vec3& v) {
      const Vec3 b = v + x / T;
      x = (x + b * dt) * k;
      v = (v - b * (dt / T)) * k;
    };
    advance(carried_.force, rate_.force);
    advance(carried_.torque, rate_.torque);
  }
  const double T = kTimeConstant;
  if (!finite(carried_.force) || !finite(carried_.torque) || !finite(rate_.force) || !finite(rate_.torque) ||
      (glm::length(carried_.force) < kZero && glm::length(carried_.torque) < kZero &&
       glm::length(rate_.force) * T < kZero && glm::length(rate_.torque) * T < kZero))
    reset();
  Wrench out = instantaneous;
  out.force += carried_.force;
  out.torque += carried_.torque;
  return out;
}

double closest_tracked_distance(const ContactSnapshot& snapshot) {
  double least = std::numeric_limits<double>::infinity();
  for (const HapticContact& c : snapshot.contacts) least = std::min(least, std::max(0.0, c.distance));
  return least;
}

double pose_displacement(const Pose& from, const Pose& to, const Vec3& reference_point_local, double radius) {
  const double moved = glm::length(to.apply(reference_point_local) - from.apply(reference_point_local));
  // The relative rotation's angle from its trace.
  const glm::dmat3 r = to.rotation * glm::transpose(from.rotation);
  const double c = std::clamp(0.5 * (r[0][0] + r[1][1] + r[2][2] - 1.0), -1.0, 1.0);
  return moved + std::acos(c) * radius;
}

Wrench SafetyFilter::step(const Wrench& target_in, bool valid, double dt, bool* limited) {
  Wrench target;
  bool changed = false;
  if (valid && finite(target_in.force) && finite(target_in.torque)) {
    target = target_in;
    changed |= clamp_length(target.force, settings_.max_force);
    changed |= clamp_length(target.torque, settings_.max_torque);
  } else {
    changed = true;
  }
  dt = std::isfinite(dt) ? std::clamp(dt, 0.0, kMaxStep) : 0.0;
  changed |= approach(output_.force, target.force, settings_.max_force_rate * dt);
  changed |= approach(output_.torque, target.torque, settings_.max_torque_rate * dt);
  output_.clipped = target_in.clipped || changed;
  if (limited) *limited = changed;
  return output_;
}

}  // namespace prox::runtime
