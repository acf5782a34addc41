// The named scenes: which meshes, which path of poses, which force settings.
#pragma once

#include "contact/pose.h"
#include "contact/proximity.h"
#include "models.h"

#include <string>
#include <vector>

namespace prox::bench {

enum class PathKind {
  Translate,  // B along `direction`, linear in the offset between the offsets of two gaps
  Rotate,     // path R: B turned about its centroid, x set per pose for a gap
};

MeshSource bunny_source();

struct Scene {
  std::string name;
  std::string description;
  std::string group;  // "bunny", "cad" or "scaling"
  MeshSource a, b;    // A fixed at the identity, B held and moved
  PathKind kind = PathKind::Translate;
  double far = 0.05, near = 0.0005;  // minimum distance at the first and the last pose
  bool soft = false;                 // force settings: soft, else hard
  std::string same_as;               // another name for the same scene
  Vec3 direction{1.0, 0.0, 0.0};     // Translate: B moves along this (unit)
  bool centre_b_on_a = false;  // offset 0 puts B's box centre on A's; else B stays where its file has it
  // > 0: the hard settings scaled so that the cutoff is this times the larger
  // bounding-box diagonal (the bunny pair's 5 mm on 0.249 m is 0.020), and
  // the path runs from 3 to 0.1 cutoffs: the bunny's 10 would spend two
  // thirds of the CAD scenes' run far from contact, where the exact
  // minimum distance and the reference still cost 0.1 s a pose.
  double cutoff_over_size = 0.0;
};

constexpr double kCadCutoffOverSize = 0.02;
constexpr double kCadFarOverCutoff = 3.0;

// Every scene, in the order `--scene all` runs them (path T first).
const std::vector<Scene>& scenes();

struct PosePoint {
  Pose pose;
  double s = 0.0, x = 0.0, target_gap = 0.0;
};

PairQuery make_query(const Model& a, const Model& b, const Pose& pose_b, double cutoff);

// The scene's `poses` poses from `far` to `near` (minimum distances).
std::vector<PosePoint> make_path(const Scene& scene, double far, double near, const Model& a, const Model& b,
                                 int poses);

}  // namespace prox::bench
