// What the 1 kHz haptic loop computes each tick (docs/threading.md): the
// tracked contacts re-evaluated at the device's current pose, then made safe
// for a device. Nothing here locks or allocates.
#pragma once

#include "contact/force.h"
#include "contact/pose.h"
#include "coupling/coupling.h"

#include <cstdint>
#include <vector>

namespace prox::runtime {

// One tracked contact as the haptic loop uses it: the tool's closest point in
// the tool's own frame (it moves with the hand), the other body's closest
// point and the contact normal in the world (the other body does not move at
// haptic time scales).
struct HapticContact {
  Vec3 tool_point_local{0.0};
  Vec3 other_point{0.0};
  Vec3 normal{0.0, 0.0, 1.0};  // unit, from the other body to the tool
  double distance = 0.0;       // when tracked
  double weight = 1.0;         // the LMDs it stands for: its patch's count
};

// An LMD pair (A the other body, B the tool) as the haptic loop keeps it;
// `tool_to_local` is the inverse of the tool's pose it was tracked at. False
// for a pair with no direction (touching: distance 0).
bool to_haptic_contact(const LmdPair& lmd, const Pose& tool_to_local, HapticContact& out);

// A tool's contacts as the local tracking thread last saw them. Its storage
// is reserved once, before the threads start; the writer fills at most
// capacity() contacts (the closest ones) and never reallocates.
struct ContactSnapshot {
  std::vector<HapticContact> contacts;  // reserved; size() is the count
  Pose tool_pose;                       // the tool's pose the contacts were tracked at
  double time = 0.0;                    // steady-clock seconds when tracked
  std::uint64_t sequence = 0;           // 0: nothing published yet
  std::uint32_t dropped = 0;            // contacts beyond the capacity
  // A constrained tool's: tool_pose is its verified proxy, these are the
  // constraints tracked there (reserved like `contacts`), and `reach` how
  // far from it the haptic tick may move the proxy unchecked
  // (coupling/haptic_proxy.h).
  std::vector<coupling::ProxyConstraint> constraints;
  double reach = 0.0;
  // The radius of the tool's bounds about its reference point, of the shape
  // the contacts were tracked on (a deforming tool's changes).
  double radius = 0.0;
  std::uint64_t checksum = 0;           // snapshot_checksum(), set last by the writer
};

// A cheap fingerprint of a snapshot's contents, so the haptic loop can check
// that it never reads one half written (a bug the handoff rules out; the
// check keeps it ruled out).
std::uint64_t snapshot_checksum(const ContactSnapshot& snapshot);

// The force and torque the snapshot's contacts give at the tool pose `pose`:
// each contact's separation is re-measured along its normal (first order in
// the motion since tracking), so the force follows the hand between local
// updates; at the snapshot's own pose it is exactly tool_wrench's. When
// `closest` is given it receives the least of those separations (0 when
// pushed through, +infinity with no contacts).
Wrench evaluate_contacts(const ForceSettings& settings, const ContactSnapshot& snapshot, const Pose& pose,
                         const Vec3& reference_point_local, double* closest = nullptr);

// The least distance the snapshot's contacts were tracked at (+infinity with
// none): a constrained tool's, whose contacts are its proxy's.
double closest_tracked_distance(const ContactSnapshot& snapshot);

// How far the contacts may be trusted from the pose they were tracked at:
// the largest distance any point of the tool within `radius` of its
// reference point has moved (translation plus rotation times radius).
double pose_displacement(const Pose& from, const Pose& to, const Vec3& reference_point_local, double radius);

// The force continuous in time (docs/haptic-fidelity.md): when a new
// snapshot replaces the old one, what it changes at the same pose (a free
// tool's contacts born or lost inside the cutoff and patch weights, a
// constrained tool's constraint set) would step the force by the
// difference between the two at that pose. That difference is
// carried over and fades out as a critically damped spring does, so a
// contact born inside the cutoff fades in, one lost there fades out, with
// no corner: a step s fades as s (1 + t/T) exp(-t/T), whose steepest change
// is s / (e T), 0.055 N a millisecond for a 3 N step. The rendered force
// differs from the instantaneous one by the carried part alone: at most the
// sum of the recent switches' steps, each shrinking as above (to 10% in
// 3.9 T, 1% in 6.6 T), and exactly zero once below kZero.
class ContinuityFilter {
 public:
  static constexpr double kTimeConstant = 0.02;  // s: T
  static constexpr double kZero = 1e-7;          // N (and N m): below it, carried is dropped
  // A switch at this tick: what the old and the new contacts give at this
  // tick's pose.
  void switched(const Wrench& old_contacts, const Wrench& new_contacts) {
    carried_.force += old_contacts.force - new_contacts.force;
    carried_.torque += old_contacts.torque - new_contacts.torque;
  }
  // The wrench to render after `dt` s: `instantaneous` and what is carried,
  // the carried part faded by dt first.
  Wrench step(const Wrench& instantaneous, double dt);
  const Wrench& carried() const { return carried_; }
  void reset() { carried_ = rate_ = Wrench{}; }

 private:
  Wrench carried_, rate_;  // the part carried over and its rate of change (per s)
};

// The last gate before a device: whatever comes in (NaN, a spike, nothing),
// what goes out is finite, within the maxima, and changes by at most the
// configured rates, so a stale or invalid input fades to zero smoothly.
struct SafetySettings {
  double max_force = 3.0;       // N
  double max_torque = 0.3;      // N m
  double max_force_rate = 300;  // N/s
  double max_torque_rate = 30;  // N m/s
};

class SafetyFilter {
 public:
  explicit SafetyFilter(const SafetySettings& settings = {}) : settings_(settings) {}
  // The wrench to hand to the device after `dt` seconds, moving towards
  // `target` (a zero wrench when !valid or when the target is not finite).
  // Sets *limited when the output is not the target.
  Wrench step(const Wrench& target, bool valid, double dt, bool* limited = nullptr);
  const Wrench& output() const { return output_; }
  void reset() { output_ = Wrench{}; }

 private:
  // The longest time step honoured (s): a longer gap between ticks (the
  // haptic thread itself was held up) must not license a jump.
  static constexpr double kMaxStep = 0.005;
  SafetySettings settings_;
  Wrench output_;
};

}  // namespace prox::runtime
