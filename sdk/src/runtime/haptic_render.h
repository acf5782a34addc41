// What one tool's haptic tick renders (docs/haptic-fidelity.md): from the
// latest contact snapshot and this tick's device pose, the wrench to hand
// the safety gate. A free tool's is its contacts' force re-measured at the
// device pose; a constrained tool's the virtual coupling to its proxy,
// moved every tick against the snapshot's constraints
// (coupling/haptic_proxy.h). Either way, what a new snapshot changes at the
// same pose (contacts born or lost inside the cutoff, a patch's weight, the
// constraint set) is carried over and faded (ContinuityFilter), and so is
// the jump from what the device has when the contacts are trusted again.
// The haptic thread's own; nothing here locks or allocates once made.
#pragma once

#include "coupling/haptic_proxy.h"
#include "runtime/device.h"
#include "runtime/haptic.h"

#include <vector>

namespace prox::runtime {

struct RenderSettings {
  ForceSettings force;
  bool constrained = false;
  coupling::CouplingSettings coupling;
  Vec3 reference_local{0.0};
  double radius = 0.0;        // of the tool's bounds about the reference point
  std::size_t capacity = 0;   // the snapshots' contact capacity (the proxy solve's storage)
  Pose start;                 // a constrained tool's proxy until the first trusted tick: where it was made
  DeviceLimits limits;        // what the tool's device renders stably
};

// A device that renders at most `max_stiffness` N/m stably: the force it is
// handed grows by no more than that per metre its tool's reference point
// moves (a virtual coupling between the hand and the contact force where
// the force curve is stiffer than the device: pushed further in, the hand
// feels the device's stiffness, not the curve's), and falls as the contacts
// say (less force on the way out is never unstable). `damping` resists
// motion into a contact's force. The haptic thread's own.
class StiffnessLimit {
 public:
  explicit StiffnessLimit(const DeviceLimits& limits = {}) : limits_(limits) {}
  bool active() const { return limits_.max_stiffness > 0.0 || limits_.damping > 0.0; }
  // The wrench for the device, from the contacts' `target` with the
  // reference point at `point`; `current` is what the device has now (the
  // safety gate's last output): the growth is measured from it, so what
  // the device is handed grows within the limit whatever the gate held back.
  Wrench step(const Wrench& target, const Vec3& point, double dt, const Wrench& current);
  void reset() { started_ = false; }

 private:
  DeviceLimits limits_;
  Vec3 last_point_{0.0};
  bool started_ = false;
};

class HapticRenderer {
 public:
  explicit HapticRenderer(const RenderSettings& settings = {});

  // Called just before a new snapshot replaces `outgoing` (which was
  // rendered at the last tick): what it gives at this tick's `device`.
  void replacing(const ContactSnapshot& outgoing, const Pose& device);
  // The wrench for the gate this tick. `valid`: the snapshot is trusted (not
  // stale, not torn, a pose this tick); `gate_output` what the device has
  // now. Sets *proxy to the constrained tool's proxy this tick (the device
  // pose for a free tool) and *closest to the contacts' closest distance.
  Wrench render(const ContactSnapshot& snapshot, const Pose& device, double dt, bool valid,
                const Wrench& gate_output, Pose* proxy, double* closest);

 private:
  // The instantaneous wrench of `snapshot` at `device`, without the damper.
  Wrench instantaneous(const ContactSnapshot& snapshot, const Pose& device, coupling::HapticProxy* proxy,
                       double* closest);

  RenderSettings settings_;
  ContinuityFilter continuity_;
  StiffnessLimit stiffness_;  // a free tool's, when its device declared a limit
  coupling::OffsetRate offset_rate_;  // a constrained tool's damper
  std::vector<double> lambda_;        // the proxy solve's, reserved
  bool rendered_ = false;             // the last tick rendered a trusted snapshot
  bool replaced_ = false;             // replacing() came this tick
  Wrench outgoing_;                   // ... and what the outgoing snapshot gave
  coupling::Twist outgoing_offset_;   // ... and a constrained tool's offset to its ideal
  Pose last_proxy_;
};

}  // namespace prox::runtime
