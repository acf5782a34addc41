#include "runtime/global_pass.h"

#include <algorithm>
#include <cmath>

namespace prox::runtime {

Aabb world_box(const Aabb& local, const Pose& pose, double margin) {
  // The box of the rotated box: centre moved, half-extents through |R|.
  const Vec3 centre = pose.apply(0.5 * (local.min + local.max));
  const Vec3 half = 0.5 * (local.max - local.min);
  Vec3 extent(0.0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) extent[r] += std::abs(pose.rotation[c][r]) * half[c];
  return {centre - extent - Vec3(margin), centre + extent + Vec3(margin)};
}

GlobalPass::GlobalPass(Method method, double cutoff, const PatchSettings& patches)
    : method_(method), cutoff_(cutoff), patches_(patches) {}

void GlobalPass::begin(std::uint64_t version, const SceneView& view) {
  if (scene_version_ == version) return;
  scene_version_ = version;
  tools_.clear();
  std::vector<BodyTree::Item> items;
  for (std::uint32_t i = 0; i < view.bodies.size(); ++i) {
    const SceneBody& b = view.bodies[i];
    if (!b.alive) continue;
    if (b.type == BodyType::Tool) {
      tools_.push_back(i);
    } else {
      items.push_back({world_box(b.mesh->mesh.bounds(), poses_[i].pose, 0.0), i});
    }
  }
  tree_.build(std::move(items));
}

const std::vector<PairInRange>& GlobalPass::search(std::uint32_t t, const SceneView& view, StepStats& stats,
                                                   WorkerPool* pool) {
  in_range_.clear();
  const SceneBody& tool = view.bodies[t];
  const MeshData& tool_mesh = *tool.mesh;
  const Pose& tool_pose = poses_[t].pose;
  // Broadphase: only bodies whose boxes meet the tool's box grown by the
  // cutoff cost any narrow work; the tree finds the static and movable
  // ones, the other tools (few, and moving every step) are tested here.
  const Aabb tool_box = world_box(tool_mesh.mesh.bounds(), tool_pose, cutoff_);
  near_.clear();
  tree_.query(tool_box, [this](std::uint32_t id) { near_.push_back(id); });
  for (std::uint32_t o : tools_)
    if (o != t && boxes_overlap(tool_box, world_box(view.bodies[o].mesh->mesh.bounds(), poses_[o].pose, 0.0)))
      near_.push_back(o);
  std::sort(near_.begin(), near_.end());  // results in body order, whatever the tree's
  for (std::uint32_t o : near_) {
    const SceneBody& other = view.bodies[o];
    const MeshData& other_mesh = *other.mesh;
    ++stats.pairs_in_range;
    PairSlot& pair = pairs_[pair_key(t, o)];  // references stay valid as the map grows
    if (pair.tool_generation != tool.generation || pair.body_generation != other.generation) {
      pair = PairSlot{};  // the slots were reused by new bodies
      pair.tool_generation = tool.generation;
      pair.body_generation = other.generation;
    }
    pair.seen = true;
    // An unchanged pose pair has the same answer: skip the search.
    if (pair.tool_version != poses_[t].version || pair.body_version != poses_[o].version) {
      PairQuery q{&other_mesh.mesh, other_mesh.snch.get(), poses_[o].pose,
                  &tool_mesh.mesh,  tool_mesh.snch.get(),  tool_pose,
                  cutoff_};
      q.patches = patches_;
      q.pool = pool;
      ProximityResult r;
      find_lmds(q, method_, pair.state, r);
      pair.lmds = std::move(r.lmds);
      pair.tool_version = poses_[t].version;
      pair.body_version = poses_[o].version;
      ++stats.pairs_searched;
      stats.candidates += r.candidates;
      stats.search += r.global;
      stats.patches += r.patches;
      if (r.global.intersecting_pairs > 0) ++stats.intersecting_bodies;
      for (const LocalTrackingStats& pass : r.reduction) {
        stats.reduction_seconds += pass.seconds;
        stats.reduction_cache_hits += pass.cache_hits;
      }
    }
    in_range_.push_back({o, &pair});
  }
  return in_range_;
}

PairSlot* GlobalPass::find(std::uint32_t tool, std::uint32_t other) {
  const auto it = pairs_.find(pair_key(tool, other));
  return it == pairs_.end() ? nullptr : &it->second;
}

void GlobalPass::end() {
  // Pairs out of range lose their state (and their memory).
  for (auto it = pairs_.begin(); it != pairs_.end();) {
    if (!it->second.seen) {
      it = pairs_.erase(it);
    } else {
      it->second.seen = false;
      ++it;
    }
  }
}

void track_pair(const MeshData& other, const Pose& other_pose, const MeshData& tool, const Pose& tool_pose,
                double cutoff, LocalTracker& tracker, std::vector<LmdPair>& lmds, LocalTrackingStats& stats) {
  const PairQuery q{&other.mesh, other.snch.get(), other_pose, &tool.mesh, tool.snch.get(), tool_pose, cutoff};
  tracker.update(q, lmds, stats);
}

}  // namespace prox::runtime
