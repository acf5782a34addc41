#include "runtime/world.h"

#include "runtime/threads.h"

#include <glm/geometric.hpp>

#include <chrono>

namespace prox::runtime {
namespace {

template <typename Slot>
std::uint32_t free_slot(std::vector<Slot>& slots) {
  for (std::uint32_t i = 0; i < slots.size(); ++i)
    if (!slots[i].alive) return i;
  slots.emplace_back();
  return static_cast<std::uint32_t>(slots.size() - 1);
}

}  // namespace

World::World(const WorldSettings& settings) : settings_(settings) {
  settings_.force.cutoff = settings_.cutoff;
}

World::~World() { stop_threads(); }

Handle World::create_mesh(const MeshInput& input, Status& status) {
  auto data = std::make_unique<MeshData>();
  data->mesh = Mesh::build(input, status);
  if (!status) return {};
  data->snch = std::make_unique<Snch>(data->mesh);
  const std::uint32_t i = free_slot(meshes_);
  MeshSlot& slot = meshes_[i];
  slot.generation += 1;
  slot.alive = true;
  slot.data = std::move(data);
  slot.users = 0;
  return {i, slot.generation};
}

bool World::mesh_alive(Handle h) const {
  return h.index < meshes_.size() && meshes_[h.index].alive && meshes_[h.index].generation == h.generation;
}

bool World::destroy_mesh(Handle h, Status& status) {
  MeshSlot& slot = meshes_[h.index];
  if (slot.users > 0) {
    status = Status(StatusCode::InvalidArgument,
                    "mesh is used by " + std::to_string(slot.users) + " bodies; destroy them first");
    return false;
  }
  slot.alive = false;
  slot.data.reset();
  return true;
}

Handle World::create_body(Handle mesh, BodyType type, const Pose& pose, const Vec3& reference_point) {
  const std::uint32_t i = free_slot(bodies_);
  BodySlot& b = bodies_[i];
  b.generation += 1;
  b.alive = true;
  b.mesh = mesh.index;
  b.type = type;
  b.pose = pose;
  b.reference_point = reference_point;
  b.pose_version += 1;
  b.contacts.clear();
  b.wrench = Wrench{};
  b.device = Device{};
  b.intersection_stats = PolylineStats{};
  meshes_[mesh.index].users += 1;
  ++scene_version_;
  return {i, b.generation};
}

bool World::body_alive(Handle h) const {
  return h.index < bodies_.size() && bodies_[h.index].alive && bodies_[h.index].generation == h.generation;
}

void World::destroy_body(Handle h) {
  BodySlot& b = bodies_[h.index];
  b.alive = false;
  b.contacts.clear();
  b.device = Device{};
  meshes_[b.mesh].users -= 1;
  ++scene_version_;
}

void World::set_pose(Handle h, const Pose& pose) {
  BodySlot& b = bodies_[h.index];
  if (running() && b.type == BodyType::Tool) {
    threads_->set_tool_pose(h.index, pose);  // the haptic loop reads it from there
    return;
  }
  std::unique_lock<std::mutex> lock(scene_mutex_, std::defer_lock);
  if (running()) lock.lock();
  b.pose = pose;
  b.pose_version += 1;
  if (b.type != BodyType::Tool) ++scene_version_;
}

void World::set_device(Handle tool, const Device& device) { bodies_[tool.index].device = device; }

std::uint32_t World::add_scripted_device(std::unique_ptr<ScriptedDevice> device) {
  scripted_devices_.push_back(std::move(device));
  return static_cast<std::uint32_t>(scripted_devices_.size() - 1);
}

std::uint32_t World::add_stream_device(std::unique_ptr<StreamDevice> device) {
  stream_devices_.push_back(std::move(device));
  return static_cast<std::uint32_t>(stream_devices_.size() - 1);
}

Pose World::current_pose(Handle h) const {
  if (running() && bodies_[h.index].type == BodyType::Tool) return threads_->tool_pose(h.index);
  return bodies_[h.index].pose;
}

void World::contacts(Handle tool, std::vector<Contact>& out) const {
  if (running()) {
    threads_->contacts(tool.index, out);
    return;
  }
  out = bodies_[tool.index].contacts;
}

Wrench World::wrench(Handle tool) const {
  return running() ? threads_->wrench(tool.index) : bodies_[tool.index].wrench;
}

StepStats World::stats() const { return running() ? threads_->step_stats() : stats_; }

bool World::start_threads(const ThreadSettings& settings, Status& status) {
  if (running()) return true;
  auto threads = std::make_unique<Threads>(*this, settings);
  if (!threads->start(status)) return false;
  threads_ = std::move(threads);
  return true;
}

bool World::running() const { return threads_ && threads_->running(); }

void World::stop_threads() {
  if (!running()) return;
  threads_->stop();
  // Hand the last results back to the bodies, so that the game thread reads
  // the same contacts, wrench and pose after stopping as just before.
  for (std::uint32_t i = 0; i < bodies_.size(); ++i) {
    BodySlot& b = bodies_[i];
    if (!b.alive || b.type != BodyType::Tool) continue;
    threads_->contacts(i, b.contacts);
    b.wrench = threads_->wrench(i);
    b.pose = threads_->tool_pose(i);
    b.pose_version += 1;
  }
  stats_ = threads_->step_stats();
  // The stopped threads' statistics stay readable until the next start.
}

int World::body_count() const {
  int n = 0;
  for (const BodySlot& b : bodies_) n += b.alive;
  return n;
}

int World::tool_count() const {
  int n = 0;
  for (const BodySlot& b : bodies_) n += b.alive && b.type == BodyType::Tool;
  return n;
}

Aabb World::world_box(const Aabb& local, const Pose& pose, double margin) const {
  // The box of the rotated box: centre moved, half-extents through |R|.
  const Vec3 centre = pose.apply(0.5 * (local.min + local.max));
  const Vec3 half = 0.5 * (local.max - local.min);
  Vec3 extent(0.0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) extent[r] += std::abs(pose.rotation[c][r]) * half[c];
  return {centre - extent - Vec3(margin), centre + extent + Vec3(margin)};
}

void World::refresh_poses(Broadphase& bp) const {
  if (bp.scene_version != scene_version_ || bp.poses.size() != bodies_.size()) {
    bp.poses.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) bp.poses[i] = {bodies_[i].pose, bodies_[i].pose_version};
    return;
  }
  for (std::uint32_t t : bp.tools) bp.poses[t] = {bodies_[t].pose, bodies_[t].pose_version};
}

void World::update_broadphase(Broadphase& bp, std::uint64_t version) const {
  if (bp.scene_version == version) return;
  bp.scene_version = version;
  bp.tools.clear();
  std::vector<BodyTree::Item> items;
  for (std::uint32_t i = 0; i < bodies_.size(); ++i) {
    const BodySlot& b = bodies_[i];
    if (!b.alive) continue;
    if (b.type == BodyType::Tool) {
      bp.tools.push_back(i);
    } else {
      items.push_back({world_box(meshes_[b.mesh].data->mesh.bounds(), bp.poses[i].pose, 0.0), i});
    }
  }
  bp.tree.build(std::move(items));
}

void World::search_tool(std::uint32_t t, Broadphase& bp, PairMap& pairs, std::vector<PairInRange>& in_range,
                        StepStats& stats) const {
  in_range.clear();
  const std::vector<BodyPose>& poses = bp.poses;
  const BodySlot& tool = bodies_[t];
  const MeshData& tool_mesh = *meshes_[tool.mesh].data;
  const Pose& tool_pose = poses[t].pose;
  // Broadphase: only bodies whose boxes meet the tool's box grown by the
  // cutoff cost any narrow work; the tree finds the static and movable
  // ones, the other tools (few, and moving every step) are tested here.
  const Aabb tool_box = world_box(tool_mesh.mesh.bounds(), tool_pose, settings_.cutoff);
  std::vector<std::uint32_t>& near = bp.scratch;
  near.clear();
  bp.tree.query(tool_box, [&near](std::uint32_t id) { near.push_back(id); });
  for (std::uint32_t o : bp.tools)
    if (o != t &&
        boxes_overlap(tool_box, world_box(meshes_[bodies_[o].mesh].data->mesh.bounds(), poses[o].pose, 0.0)))
      near.push_back(o);
  std::sort(near.begin(), near.end());  // results in body order, whatever the tree's
  for (std::uint32_t o : near) {
    const BodySlot& other = bodies_[o];
    const MeshData& other_mesh = *meshes_[other.mesh].data;
    ++stats.pairs_in_range;
    PairSlot& pair = pairs[pair_key(t, o)];
    if (pair.tool_generation != tool.generation || pair.body_generation != other.generation) {
      pair = PairSlot{};  // the slots were reused by new bodies
      pair.tool_generation = tool.generation;
      pair.body_generation = other.generation;
    }
    pair.seen = true;
    // An unchanged pose pair has the same answer: skip the search.
    if (pair.tool_version != poses[t].version || pair.body_version != poses[o].version) {
      const PairQuery q{&other_mesh.mesh, other_mesh.snch.get(), poses[o].pose,
                        &tool_mesh.mesh,  tool_mesh.snch.get(),  tool_pose,
                        settings_.cutoff};
      ProximityResult r;
      find_lmds(q, settings_.method, pair.state, r);
      pair.lmds = std::move(r.lmds);
      pair.tool_version = poses[t].version;
      pair.body_version = poses[o].version;
      ++stats.pairs_searched;
      stats.candidates += r.candidates;
      stats.search += r.global;
      for (const LocalTrackingStats& pass : r.reduction) {
        stats.reduction_seconds += pass.seconds;
        stats.reduction_cache_hits += pass.cache_hits;
      }
    }
    in_range.push_back({o, &pair});
  }
}

void World::prune(PairMap& pairs) {
  // Pairs out of range lose their state (and their memory).
  for (auto it = pairs.begin(); it != pairs.end();) {
    if (!it->second.seen) {
      it = pairs.erase(it);
    } else {
      it->second.seen = false;
      ++it;
    }
  }
}

void World::step() {
  const auto start = std::chrono::steady_clock::now();
  stats_ = StepStats{};
  refresh_poses(broadphase_);
  update_broadphase(broadphase_, scene_version_);
  std::vector<PairInRange> in_range;
  std::vector<LmdPair> all;
  for (std::uint32_t t : broadphase_.tools) {
    BodySlot& tool = bodies_[t];
    search_tool(t, broadphase_, pairs_, in_range, stats_);
    tool.contacts.clear();
    all.clear();
    for (const PairInRange& p : in_range)
      for (const LmdPair& lmd : p.slot->lmds) {
        tool.contacts.push_back({p.other, lmd});
        all.push_back(lmd);
      }
    tool.wrench = tool_wrench(settings_.force, all, tool.pose.apply(tool.reference_point));
    stats_.contacts += static_cast<int>(tool.contacts.size());
  }
  prune(pairs_);
  stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void World::track() {
  const auto start = std::chrono::steady_clock::now();
  track_stats_ = TrackStats{};
  std::vector<LmdPair> all;
  for (std::uint32_t t = 0; t < bodies_.size(); ++t) {
    BodySlot& tool = bodies_[t];
    if (!tool.alive || tool.type != BodyType::Tool) continue;
    tool.contacts.clear();
    all.clear();
    const MeshData& tool_mesh = *meshes_[tool.mesh].data;
    for (std::uint32_t o = 0; o < bodies_.size(); ++o) {
      const BodySlot& other = bodies_[o];
      if (o == t || !other.alive) continue;
      const auto it = pairs_.find(pair_key(t, o));
      if (it == pairs_.end()) continue;
      PairSlot& pair = it->second;
      if (pair.tool_generation != tool.generation || pair.body_generation != other.generation) continue;
      const MeshData& other_mesh = *meshes_[other.mesh].data;
      const PairQuery q{&other_mesh.mesh, other_mesh.snch.get(), other.pose,
                        &tool_mesh.mesh,  tool_mesh.snch.get(),  tool.pose,
                        settings_.cutoff};
      // The tracker the pair's method reduces with (the reference has none
      // of its own: it is tracked like the precise method).
      LocalTracker& tracker = settings_.method == Method::Original ? pair.state.original : pair.state.precise;
      LocalTrackingStats local;
      tracker.update(q, pair.lmds, local);
      track_stats_.local += local;
      ++track_stats_.pairs;
      for (const LmdPair& p : pair.lmds) {
        tool.contacts.push_back({o, p});
        all.push_back(p);
      }
    }
    tool.wrench = tool_wrench(settings_.force, all, tool.pose.apply(tool.reference_point));
  }
  track_stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double World::distance(Handle a_handle, Handle b_handle, double bound) const {
  const BodySlot& a = bodies_[a_handle.index];
  const BodySlot& b = bodies_[b_handle.index];
  const MeshData& ma = *meshes_[a.mesh].data;
  const MeshData& mb = *meshes_[b.mesh].data;
  // While the threads run a tool is where its device last put it.
  const PairQuery q{
      &ma.mesh, ma.snch.get(), current_pose(a_handle), &mb.mesh, mb.snch.get(), current_pose(b_handle), 0.0};
  return minimum_distance(q, bound);
}

void World::intersections(Handle tool_handle, std::vector<std::pair<std::uint32_t, Polyline>>& out) {
  out.clear();
  BodySlot& tool = bodies_[tool_handle.index];
  tool.intersection_stats = PolylineStats{};
  const Pose tool_pose = current_pose(tool_handle);
  const MeshData& tool_mesh = *meshes_[tool.mesh].data;
  const Aabb tool_box = world_box(tool_mesh.mesh.bounds(), tool_pose, 0.0);
  for (std::uint32_t o = 0; o < bodies_.size(); ++o) {
    const BodySlot& other = bodies_[o];
    if (o == tool_handle.index || !other.alive) continue;
    const MeshData& other_mesh = *meshes_[other.mesh].data;
    if (!boxes_overlap(tool_box, world_box(other_mesh.mesh.bounds(), other.pose, 0.0))) continue;
    const PairQuery q{&other_mesh.mesh,
                      other_mesh.snch.get(),
                      other.pose,
                      &tool_mesh.mesh,
                      tool_mesh.snch.get(),
                      tool_pose,
                      0.0};
    std::vector<Polyline> lines;
    PolylineStats stats;
    intersection_polylines(q, lines, stats);
    tool.intersection_stats += stats;
    for (Polyline& line : lines) out.emplace_back(o, std::move(line));
  }
}

}  // namespace prox::runtime
