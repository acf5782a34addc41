// The pipeline's stages over a read-only scene (docs/architecture.md, "One
// pipeline"): the global pass (the broadphase, then per pair in range the
// global search and its reduction, paper 4.3) and local tracking of a pair
// (paper 4.2). proxWorld_Step runs them in order on the calling thread; the
// tracking threads run the same stages on their own schedule, each with its
// own GlobalPass. Neither reads the World: the scene comes in as a
// SceneView and the bodies' poses, the settings at construction.
#pragma once

#include "contact/proximity.h"
#include "runtime/body_tree.h"
#include "runtime/scene.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace prox {
class WorkerPool;
}

namespace prox::runtime {

// What the searches of one step (or one pass of the global thread) did.
struct StepStats {
  int pairs_in_range = 0;
  int pairs_searched = 0;
  int contacts = 0;
  long candidates = 0;
  double seconds = 0.0;
  // Summed over the pairs searched: the global searches and the reduction
  // passes that follow them.
  GlobalSearchStats search;
  double reduction_seconds = 0.0;
  std::uint64_t reduction_cache_hits = 0;
  // The reduced LMDs merged into patches, over the pairs searched; the
  // crossing pairs are in search.intersecting_pairs, and the pairs searched
  // that had any in intersecting_bodies.
  PatchStats patches;
  int intersecting_bodies = 0;
};

// A body's pose as a search sees it, with a version that changes whenever
// the pose does (equal versions: the same pose, the same answer).
struct BodyPose {
  Pose pose;
  std::uint64_t version = 0;
};

// What a tool-body pair keeps between searches.
struct PairSlot {
  PairState state;
  std::vector<LmdPair> lmds;
  std::uint64_t tool_version = ~0ull, body_version = ~0ull;
  std::uint32_t tool_generation = 0, body_generation = 0;
  bool seen = false;  // in range in the current search

  // The tracker the pair's method reduces and tracks with (the reference
  // has none of its own: it is tracked like the precise method).
  LocalTracker& tracker(Method method) { return method == Method::Original ? state.original : state.precise; }
};

// A pair the broadphase kept in a search, and its state after it.
struct PairInRange {
  std::uint32_t other = 0;
  const PairSlot* slot = nullptr;
};

// The box in the world frame of a box in a body's frame, grown by margin.
Aabb world_box(const Aabb& local, const Pose& pose, double margin);

class GlobalPass {
 public:
  GlobalPass(Method method, double cutoff, const PatchSettings& patches);

  // The poses the searches see, one per body slot: the caller writes them
  // (all of them when the scene version moved, else the tools'), then
  // calls begin().
  std::vector<BodyPose>& poses() { return poses_; }
  // The scene version the broadphase was last brought to.
  std::uint64_t scene_version() const { return scene_version_; }
  // The tools of `view`, as of the last begin().
  const std::vector<std::uint32_t>& tools() const { return tools_; }
  // Brings the broadphase to `view` at scene version `version`: its tree of
  // static and movable bodies' boxes is rebuilt only when the version moved.
  void begin(std::uint64_t version, const SceneView& view);
  // One tool's search against the bodies in range at poses(): per pair the
  // global search and reduction, skipped where neither pose changed since
  // the pair's last search. Returns the pairs kept, by body index. A pool,
  // where there is one, splits each pair's search (the caller's own: one
  // run at a time).
  const std::vector<PairInRange>& search(std::uint32_t tool, const SceneView& view, StepStats& stats,
                                         WorkerPool* pool = nullptr);
  // The pair's state, or null when no search kept it.
  PairSlot* find(std::uint32_t tool, std::uint32_t other);
  // Drops the pairs no search has seen since the last end().
  void end();

 private:
  Method method_;
  double cutoff_;
  PatchSettings patches_;
  std::vector<BodyPose> poses_;
  std::vector<std::uint32_t> tools_;
  BodyTree tree_;
  std::uint64_t scene_version_ = ~0ull;
  std::vector<std::uint32_t> near_;
  std::unordered_map<std::uint64_t, PairSlot> pairs_;
  std::vector<PairInRange> in_range_;
};

// Local tracking of one pair (paper 4.2): its LMDs carried by `tracker` to
// the bodies' poses.
void track_pair(const MeshData& other, const Pose& other_pose, const MeshData& tool, const Pose& tool_pose,
                double cutoff, LocalTracker& tracker, std::vector<LmdPair>& lmds, LocalTrackingStats& stats);

}  // namespace prox::runtime
