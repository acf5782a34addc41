// From LMD pairs to a force and torque on the held tool (paper section 4.5).
#pragma once

#include "contact/lmd.h"

#include <vector>

namespace prox {

enum class ForceCurve {
  Exponential,  // the improved method: sharp gain near the safety distance
  Linear,       // the original's linear spring, for comparison
};

// Every length in metres (mesh units), forces in newtons, torques in
// newton-metres.
struct ForceSettings {
  ForceCurve curve = ForceCurve::Exponential;
  double max_force = 3.0;           // per LMD at the safety distance, and the clip of the sum
  double max_torque = 0.3;          // clip of the summed torque's magnitude
  double safety_distance = 0.0005;  // the force reaches max_force here and stays there closer in
  double cutoff = 0.005;            // the force falls to zero here (continuously) and beyond
  double decay_length = 0.0005;     // exponential curve: the force falls by e over this length
};

// The "hard" and "soft" settings of the paper's benchmarks (section 6.1):
// hard lets the tool come close and feel small features; soft keeps it away
// with a gentle, linear-like gain.
ForceSettings hard_force_settings();
ForceSettings soft_force_settings();

// Magnitude of one LMD's force at `distance`: max_force at or inside the
// safety distance, falling to exactly zero at the cutoff, never negative.
double force_magnitude(const ForceSettings& settings, double distance);

struct Wrench {
  Vec3 force{0.0};   // on the tool, newtons, world frame
  Vec3 torque{0.0};  // on the tool about its reference point, newton-metres
  bool clipped = false;
};

// Sums per-contact forces and their torques, then clips: what tool_wrench
// and the haptic loop share. Allocates nothing.
class WrenchSum {
 public:
  explicit WrenchSum(const Vec3& reference_point) : reference_point_(reference_point) {}
  // One contact: its point on the tool, the unit direction the force pushes
  // the tool in, the distance the force magnitude is taken at, and how many
  // contacts it stands for (a patch's count, contact/patches.h).
  void add(const ForceSettings& settings, const Vec3& point_b, const Vec3& direction, double distance,
           double weight = 1.0);
  // The sum, clipped as tool_wrench describes.
  Wrench finish(const ForceSettings& settings) const;

 private:
  Vec3 reference_point_;
  Vec3 force_{0.0}, torque_{0.0};
};

// The force and torque on mesh B (the held tool) from its LMD pairs with A:
// each pair pushes B away from A along point_b - point_a, weighing its
// patch_count (a patch's seed stands for its members); the forces are
// summed and the sum clipped to max_force (which keeps many parallel LMDs
// from adding up to a spike; the torque is scaled alike), the torque taken
// about `reference_point` (world) and clipped to max_torque.
Wrench tool_wrench(const ForceSettings& settings, const std::vector<LmdPair>& lmds,
                   const Vec3& reference_point);

}  // namespace prox
