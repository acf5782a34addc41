// One scene run: every method side by side at every pose of the path, one
// row per method and pose.
#pragma once

#include "bench_common.h"
#include "contact/force.h"
#include "models.h"
#include "scenes.h"

#include <string>
#include <vector>

namespace prox::bench {

struct Options {
  std::string scene = "all";
  int poses = 1000;
  std::string out = "bench-results";
  int reference_every = 1;              // 0: never
  int local_reps = 5;                   // local updates per step and method; the median time is kept
  int force_reps = 7;                   // batches of kForceBatch force evaluations; the median is kept
  std::string meshes = "bench-meshes";  // where scripts/decimate.py wrote the decimated bunnies
  int scaling_poses = 200;              // poses per scaling scene (at most --poses)
  int scaling_reference_every = 20;     // the reference on the scaling scenes (0: never)
  int max_triangles = 0;                // skip the scaling levels above this (0: none)
  int cad_poses = 300;                  // poses per CAD scene (at most --poses)
  int builds = 3;                       // hierarchy builds per mesh and library; the median is reported
  int workers = 1;                      // threads the precise global search splits over (PairQuery::pool)
  std::string coal_version;             // the peer's, when it runs
};

constexpr int kForceBatch = 100;
// The original's points are feature points: they are also matched within
// 0.4 cutoffs (2 mm on the bunny pair).
constexpr double kLooseMatchOverCutoff = 0.4;

// One row of the per-step CSV: one method at one pose. NaN: not applicable.
struct Row {
  int step = 0;
  double s = 0.0, x = 0.0, target_gap = kNaN, exact_min = kNaN;
  std::string method;
  double query_ms = kNaN;  // precise/original: global search + reduction; others: the one query
  double global_ms = kNaN, reduction_ms = kNaN;
  double local_ms = kNaN, local_in = kNaN, local_out = kNaN, local_cache_hits = kNaN;
  double local_distance_evaluations = kNaN;
  double force_eval_ns = kNaN;
  double candidates = kNaN, lmds = kNaN;
  double node_pairs = kNaN, leaf_pairs = kNaN, visibility_rejections = kNaN, normal_rejections = kNaN;
  double distance_evaluations = kNaN, reduction_cache_hits = kNaN;
  double min_distance = kNaN;
  Vec3 force{kNaN}, torque{kNaN};
  // Against the reference at this pose (when it was computed).
  double ref_lmds = kNaN, recalled = kNaN, confirmed = kNaN, recalled_loose = kNaN, confirmed_loose = kNaN;
  double min_distance_error = kNaN, force_error = kNaN, torque_error = kNaN;
  double local_recalled = kNaN, local_confirmed = kNaN;  // the locally updated set at this pose
};

struct SceneRun {
  const Scene* scene = nullptr;
  const Model* a = nullptr;
  const Model* b = nullptr;
  double far = 0.0, near = 0.0;  // the path's first and last minimum distance
  ForceSettings force;
  std::vector<PosePoint> path;
  std::vector<Row> rows;
  double seconds = 0.0;
  double path_seconds = 0.0;
  int reference_every = 1;
};

// The scene's force settings; CAD scenes scale the hard ones to their size.
ForceSettings scene_force(const Scene& scene, const Model& a, const Model& b);

// `coal` is null when Coal is not built in.
SceneRun run_scene(const Scene& scene, const Model& a, const Model& b, int poses, int reference_every,
                   const Options& opt, CoalPeer* coal);

}  // namespace prox::bench
