// The runtime's tracking threads (threads.h): local tracking, which moves a
// constrained tool's verified proxy and hands the haptic loop its contact
// snapshots, and the global search, which hands local tracking its pairs.
// The haptic loop, the pacing and the game thread's side are in threads.cpp.
#include "runtime/threads.h"

#include "common/worker_pool.h"
#include "coupling/haptic_proxy.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstring>

namespace prox::runtime {
namespace {

void count(std::atomic<std::uint64_t>& counter, std::uint64_t n = 1) {
  counter.fetch_add(n, std::memory_order_relaxed);
}

}  // namespace

// ---- local tracking ----------------------------------------------------------------

void Threads::local_main() {
  configure(Role::Local);
  const double period = settings_.local_rate > 0.0 ? 1.0 / settings_.local_rate : 0.0;
  double deadline = now(), previous = -1.0;
  std::vector<const LmdPair*> scratch;
  while (!stop_.load(std::memory_order_relaxed)) {
    if (wait_while_stalled(Role::Local)) {
      deadline = now();
      previous = -1.0;
      continue;
    }
    const double start = now();
    // The set first: a tool made since is in the view taken after it.
    const ToolSet& set = acquire(Role::Local);
    if (world_.latest_view(local_view_))
      for (Tool* tool : set.tools) adopt_view(*tool);
    for (Tool* tool : set.tools)
      if (tool->retiring.load(std::memory_order_relaxed) == 0) track(*tool, set, scratch);
    pace(Role::Local, period, start, previous, deadline);
  }
}

void Threads::adopt_view(Tool& tool) {
  const SceneView& view = *local_view_;
  const std::size_t before = tool.local_pairs.size();
  tool.local_pairs.erase(std::remove_if(tool.local_pairs.begin(), tool.local_pairs.end(),
                                        [&view](const LocalPair& lp) {
                                          return !view.alive(lp.other, lp.other_generation);
                                        }),
                         tool.local_pairs.end());
  // A constrained proxy's clearance was measured against what is gone or
  // has changed shape: it is measured again.
  if (tool.constrained) tool.proxy_state.clearance = -1.0;
  if (tool.local_pairs.size() != before) tool.losses.fetch_add(1, std::memory_order_relaxed);
}

void Threads::track(Tool& tool, const ToolSet& set, std::vector<const LmdPair*>& scratch) {
  const bool adopted = tool.global.update();
  // A global result searched on a newer scene than this thread's: the
  // bodies it names are in that version or a later one.
  if (adopted && tool.global.front().view > local_view_->version && world_.latest_view(local_view_))
    for (Tool* t : set.tools) adopt_view(*t);
  const SceneView& view = *local_view_;
  const MeshData& tool_mesh = *view.bodies[tool.body].mesh;
  const WorldSettings& ws = world_.settings();
  const Method method = ws.method;

  // A new global result replaces the set of pairs; each pair's tracked LMDs
  // join the global ones (the tracker's cache drops the duplicates). Patches
  // are the exception: a tracked seed and a new one may stand for the same
  // LMDs from two different minima of a flat field, and both would count
  // them; the new patches replace the tracked ones.
  const bool join_tracked = method == Method::Original || !ws.patches.enabled();
  if (adopted) {
    const GlobalResult& g = tool.global.front();
    std::vector<LocalPair> next;
    next.reserve(g.pairs.size());
    // A constrained proxy's clearance was measured against the bodies (and
    // the poses) of the last result: when they change it is measured again,
    // or the reach handed to the haptic loop could count on it for a body
    // it never saw.
    bool same_obstacles = g.pairs.size() == tool.local_pairs.size();
    for (std::size_t i = 0; i < g.pairs.size(); ++i) {
      const GlobalPair& gp = g.pairs[i];
      // A body destroyed since the search: its pair is not taken up.
      if (!view.alive(gp.other, gp.other_generation)) {
        same_obstacles = false;
        continue;
      }
      LocalPair& lp = next.emplace_back();
      lp.other = gp.other;
      lp.other_generation = gp.other_generation;
      lp.other_pose = gp.other_pose;
      lp.lmds = gp.lmds;
      if (method == Method::Original) lp.tracker = LocalTracker::original();
      bool seen = false;
      for (LocalPair& old : tool.local_pairs)
        if (old.other == gp.other && old.other_generation == gp.other_generation) {
          seen = std::memcmp(&old.other_pose, &gp.other_pose, sizeof(Pose)) == 0;
          lp.tracker = std::move(old.tracker);
          if (join_tracked) lp.lmds.insert(lp.lmds.end(), old.lmds.begin(), old.lmds.end());
          break;
        }
      same_obstacles = same_obstacles && seen;
    }
    if (tool.constrained && !same_obstacles) tool.proxy_state.clearance = -1.0;
    tool.local_pairs = std::move(next);
    tool.anchor = g.tool_pose;
    tool.anchored = true;
  }

  PoseSample sample = tool.pose.load();
  // Until the global search has seen the proxy nothing says what is near
  // it: it waits.
  if (tool.constrained && tool.anchored) move_proxy(tool, sample);
  if (tool.constrained) {
    sample.pose = tool.proxy_state.pose;  // contacts are tracked at the proxy
  }
  std::size_t total = 0;
  std::uint32_t dropped = 0;
  for (LocalPair& lp : tool.local_pairs) {
    LocalTrackingStats stats;
    track_pair(*view.bodies[lp.other].mesh, lp.other_pose, tool_mesh, sample.pose, ws.cutoff(), lp.tracker, lp.lmds,
               stats);
    total += lp.lmds.size();
    dropped += stats.dropped_out_of_range + stats.duplicates_dropped;
  }
  // Adopting a result drops the tracked LMDs it already has; that loses
  // nothing.
  if (dropped > 0 && !adopted) tool.losses.fetch_add(1, std::memory_order_relaxed);

  // The snapshot for the haptic loop: the closest max_contacts contacts,
  // the tool's points in its own frame.
  scratch.clear();
  for (const LocalPair& lp : tool.local_pairs)
    for (const LmdPair& p : lp.lmds) scratch.push_back(&p);
  ContactSnapshot& s = tool.snapshots.back();
  const auto capacity = static_cast<std::size_t>(settings_.max_contacts);  // <= the reserved storage
  if (scratch.size() > capacity) {
    std::nth_element(scratch.begin(), scratch.begin() + static_cast<std::ptrdiff_t>(capacity), scratch.end(),
                     [](const LmdPair* a, const LmdPair* b) { return a->distance < b->distance; });
    scratch.resize(capacity);
  }
  const Pose to_local = sample.pose.inverse();
  s.contacts.clear();
  HapticContact c;
  for (const LmdPair* p : scratch)
    if (to_haptic_contact(*p, to_local, c)) s.contacts.push_back(c);
  s.constraints.clear();
  s.reach = 0.0;
  if (tool.constrained) {
    const Vec3 reference = sample.pose.apply(tool.reference_local);
    coupling::ProxyConstraint constraint;
    for (const LmdPair* p : scratch)
      if (coupling::make_constraint(*p, reference, constraint)) s.constraints.push_back(constraint);
    // Until a global search has seen the proxy nothing says what is near it.
    if (tool.anchored) {
      const double from_anchor = coupling::twist_displacement(
          coupling::twist_between(tool.anchor, sample.pose, tool.reference_local), view.bodies[tool.body].radius);
      s.reach = coupling::unchecked_reach(tool.proxy_state.clearance, from_anchor,
                                          ws.force.safety_distance, ws.cutoff());
    }
  }
  s.tool_pose = sample.pose;
  s.radius = view.bodies[tool.body].radius;
  s.time = sample.time;
  s.sequence = ++tool.published;
  s.dropped = static_cast<std::uint32_t>(total - scratch.size());
  s.checksum = snapshot_checksum(s);
  tool.snapshots.publish();
  if (s.dropped) count(dropped_contacts_, s.dropped);

  // Until the first global result local tracking has nothing to say: the
  // game thread keeps reading the contacts the tool started with (a step's),
  // rather than an empty set for a moment.
  if (!tool.anchored) return;
  std::lock_guard<std::mutex> lock(results_mutex_);
  tool.contacts.clear();
  for (const LocalPair& lp : tool.local_pairs)
    for (const LmdPair& p : lp.lmds) tool.contacts.push_back({lp.other, p});
}

void Threads::move_proxy(Tool& tool, const PoseSample& device) {
  const SceneView& view = *local_view_;
  const MeshData& tool_mesh = *view.bodies[tool.body].mesh;
  coupling::ProxyState& state = tool.proxy_state;
  // The constraints: the pairs' LMDs, tracked at the proxy at the last
  // update (or, just adopted, at the global search's pose).
  state.constraints.clear();
  tool.obstacles.clear();
  const Vec3 reference = state.pose.apply(tool.reference_local);
  coupling::ProxyConstraint c;
  for (const LocalPair& lp : tool.local_pairs) {
    for (const LmdPair& p : lp.lmds)
      if (coupling::make_constraint(p, reference, c)) state.constraints.push_back(c);
    const MeshData& other_mesh = *view.bodies[lp.other].mesh;
    tool.obstacles.push_back({&other_mesh.mesh, other_mesh.snch.get(), lp.other_pose});
  }
  const coupling::ProxyTool proxy_tool{&tool_mesh.mesh, tool_mesh.snch.get(), tool.reference_local,
                                       view.bodies[tool.body].radius};
  const coupling::ProxySettings settings{world_.settings().force.safety_distance, world_.settings().cutoff()};
  coupling::ProxyStats stats;
  // Bodies beyond the global search's range were farther than the cutoff
  // from the anchor; the proxy stays close enough to it that they cannot
  // come within the safety distance.
  coupling::update_proxy(tool.coupling, settings, proxy_tool, tool.obstacles.data(), tool.obstacles.size(),
                         device.pose, &tool.anchor, state, stats);
  tool.proxy.store({state.pose, device.time});
}

// ---- global search -------------------------------------------------------------

void Threads::global_main() {
  configure(Role::Global);
  const double period = settings_.global_rate > 0.0 ? 1.0 / settings_.global_rate : 0.0;
  double deadline = now(), previous = -1.0;
  const WorldSettings& ws = world_.settings();
  GlobalPass pass(ws.method, ws.cutoff(), ws.patches);
  // The global search's own helpers, where asked for: each pair's search
  // split over them (never the haptic or local thread's cores by itself).
  std::unique_ptr<WorkerPool> pool;
  if (settings_.global_workers > 1)
    pool = std::make_unique<WorkerPool>(static_cast<unsigned>(settings_.global_workers));
  std::uint64_t sequence = 0;
  while (!stop_.load(std::memory_order_relaxed)) {
    if (wait_while_stalled(Role::Global)) {
      deadline = now();
      previous = -1.0;
      continue;
    }
    const double start = now();
    // The set first: a tool made since is in the view taken after it.
    const ToolSet& set = acquire(Role::Global);
    // The game thread's moves: copied (and the tree rebuilt) only when
    // something other than a tool moved.
    global_view_ = world_.snapshot(pass);
    const SceneView& view = *global_view_;
    // The tools' poses from the haptic loop; a version that moves only when
    // the pose does, so a still tool costs no search.
    std::vector<BodyPose>& poses = pass.poses();
    for (Tool* tool : set.tools) {
      // A constrained tool is searched where its proxy is.
      const PoseSample sample = tool->constrained ? tool->proxy.load() : tool->pose.load();
      const bool moved = std::memcmp(&sample.pose, &tool->searched_pose, sizeof(Pose)) != 0;
      // A tool whose mesh took a new shape is searched again too.
      const std::uint64_t shape = view.bodies[tool->body].mesh->version;
      if (moved || tool->searched_version == 0 || shape != tool->searched_shape)
        ++tool->searched_version, tool->searched_pose = sample.pose;
      tool->searched_shape = shape;
      poses[tool->body] = {tool->searched_pose, tool->searched_version};
    }
    StepStats stats;
    for (Tool* tool : set.tools) {
      if (tool->retiring.load(std::memory_order_relaxed) != 0) continue;
      const int searched_before = stats.pairs_searched;
      const std::vector<PairInRange>& in_range = pass.search(tool->body, view, stats, pool.get());
      for (const PairInRange& p : in_range) stats.contacts += static_cast<int>(p.slot->lmds.size());
      // Nothing searched, the same pairs in range and no LMDs lost since:
      // the local thread already has this answer (and has tracked it
      // further); don't make it merge the same set again.
      const std::uint64_t losses = tool->losses.load(std::memory_order_relaxed);
      bool same_pairs = in_range.size() == tool->published_others.size();
      for (std::size_t i = 0; same_pairs && i < in_range.size(); ++i)
        same_pairs = in_range[i].other == tool->published_others[i];
      // A constrained tool's proxy must also learn that nothing is in range
      // where it now is (its anchor moves with each result).
      const bool proxy_moved = tool->constrained && tool->published_version != tool->searched_version;
      if (stats.pairs_searched == searched_before && same_pairs && !proxy_moved &&
          losses == tool->published_losses && tool->published_view == view.version)
        continue;
      tool->published_view = view.version;
      tool->published_version = tool->searched_version;
      tool->published_losses = losses;
      tool->published_others.clear();
      for (const PairInRange& p : in_range) tool->published_others.push_back(p.other);
      GlobalResult& r = tool->global.back();
      r.pairs.resize(in_range.size());
      for (std::size_t i = 0; i < in_range.size(); ++i) {
        r.pairs[i].other = in_range[i].other;
        r.pairs[i].other_generation = view.bodies[in_range[i].other].generation;
        r.pairs[i].other_pose = poses[in_range[i].other].pose;
        r.pairs[i].lmds = in_range[i].slot->lmds;
      }
      r.tool_pose = poses[tool->body].pose;
      r.view = view.version;
      r.sequence = ++sequence;
      tool->global.publish();
    }
    pass.end();
    stats.seconds = now() - start;
    {
      std::lock_guard<std::mutex> lock(results_mutex_);
      step_stats_ = stats;
    }
    pace(Role::Global, period, start, previous, deadline);
    // Nothing moved: nothing new to find. Idle a millisecond rather than spin.
    if (period == 0.0 && stats.pairs_searched == 0) sleep_until(now() + 1e-3);
  }
}

}  // namespace prox::runtime
