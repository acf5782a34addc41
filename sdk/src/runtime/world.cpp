#include "runtime/world.h"

#include "common/worker_pool.h"
#include "runtime/threads.h"

#include <glm/geometric.hpp>

#include <chrono>

namespace prox::runtime {
namespace {

// The coupling's wrench within the maxima, as tool_wrench clips its own.
Wrench clip_wrench(Wrench w, const ForceSettings& settings) {
  const double f = glm::length(w.force), t = glm::length(w.torque);
  if (f > settings.max_force) w.force *= settings.max_force / f, w.clipped = true;
  if (t > settings.max_torque) w.torque *= settings.max_torque / t, w.clipped = true;
  return w;
}

}  // namespace

World::World(const WorldSettings& settings)
    : settings_(settings), global_(settings.method, settings.cutoff(), settings.patches) {
  if (settings_.workers > 1) pool_ = std::make_unique<WorkerPool>(settings_.workers);
}

World::~World() { stop_threads(); }

void World::set_pose(Handle h, const Pose& pose) {
  BodySlot& b = bodies_[h.index];
  if (running() && b.type == BodyType::Tool) {
    threads_->set_tool_pose(h.index, pose);  // the haptic loop reads it from there
    return;
  }
  if (constrained(h)) {
    b.device_pose = pose;  // the proxy follows at the next step
    return;
  }
  std::unique_lock<std::mutex> lock(scene_mutex_, std::defer_lock);
  if (running()) lock.lock();
  b.pose = pose;
  b.pose_version += 1;
  if (b.type != BodyType::Tool) ++scene_version_;
}

int World::device_holder(const HapticDevice* device) const {
  for (std::uint32_t i = 0; i < bodies_.size(); ++i)
    if (device && bodies_[i].alive && bodies_[i].type == BodyType::Tool && bodies_[i].device.impl.get() == device)
      return static_cast<int>(i);
  return -1;
}

void World::set_device(Handle tool, const Device& device) {
  BodySlot& b = bodies_[tool.index];
  if (!running()) {
    b.device = device;
    return;
  }
  // While the threads run: the old device fades out and is let go of, and
  // the tool is driven anew from where it was, its force fading in once its
  // contacts come (docs/dynamic-scenes.md).
  const Pose device_pose = threads_->tool_pose(tool.index);
  const Pose proxy = threads_->proxy_pose(tool.index);
  threads_->remove_tool(tool.index);
  b.device = device;
  b.device_pose = device_pose;
  {
    std::lock_guard<std::mutex> lock(scene_mutex_);
    b.pose = constrained(tool) ? proxy : device_pose;
    b.pose_version += 1;
  }
  b.contacts.clear();
  b.wrench = Wrench{};
  threads_->add_tool(tool.index);
}

Pose World::current_pose(Handle h) const {
  if (running() && bodies_[h.index].type == BodyType::Tool) return threads_->tool_pose(h.index);
  return constrained(h) ? bodies_[h.index].device_pose : bodies_[h.index].pose;
}

Pose World::proxy_pose(Handle h) const {
  if (running() && bodies_[h.index].type == BodyType::Tool) return threads_->proxy_pose(h.index);
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
  if (!Threads::check(settings, status)) return false;  // before any storage is reserved
  view();  // the threads start from the scene's latest version
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
    b.device_pose = threads_->tool_pose(i);
    b.pose = threads_->proxy_pose(i);
    b.pose_version += 1;
    b.searched_pose = b.pose;
    b.track_pending = false;
    b.proxy.clearance = -1.0;  // measured again at the next step
    b.offset_rate.reset();
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

void World::refresh_poses(GlobalPass& pass) const {
  std::vector<BodyPose>& poses = pass.poses();
  if (pass.scene_version() != scene_version_ || poses.size() != bodies_.size()) {
    poses.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) poses[i] = {bodies_[i].pose, bodies_[i].pose_version};
    return;
  }
  for (std::uint32_t t : pass.tools()) poses[t] = {bodies_[t].pose, bodies_[t].pose_version};
}

std::shared_ptr<const SceneView> World::snapshot(GlobalPass& pass) const {
  // The view and the poses in one piece: a body made since is in both.
  const std::lock_guard<std::mutex> lock(scene_mutex_);
  std::shared_ptr<const SceneView> view = view_;
  refresh_poses(pass);
  pass.begin(scene_version_, *view);
  return view;
}

bool World::is_tool(std::uint32_t slot) const {
  return slot < bodies_.size() && bodies_[slot].alive && bodies_[slot].type == BodyType::Tool;
}

World::ToolStart World::tool_start(std::uint32_t slot) const {
  const BodySlot& b = bodies_[slot];
  return {b.device, b.reference_point, b.radius, b.pose, b.device_pose, b.tool, b.wrench, b.contacts};
}

void World::step_proxy(std::uint32_t t, coupling::ProxyStats& stats) {
  BodySlot& tool = bodies_[t];
  const MeshData& tool_mesh = *meshes_[tool.mesh].data;
  coupling::ProxyState& proxy = tool.proxy;
  proxy.pose = tool.pose;
  proxy.constraints.clear();
  const Vec3 reference = tool.pose.apply(tool.reference_point);
  coupling::ProxyConstraint constraint;
  for (const Contact& c : tool.contacts)
    if (coupling::make_constraint(c.lmd, reference, constraint)) proxy.constraints.push_back(constraint);
  // Every body a step can reach: a step moves no tool point farther than
  // the cutoff (update_proxy's limit).
  std::vector<coupling::Obstacle> obstacles;
  const Aabb box = world_box(tool_mesh.mesh.bounds(), tool.pose, settings_.cutoff());
  for (std::uint32_t o = 0; o < bodies_.size(); ++o) {
    const BodySlot& other = bodies_[o];
    if (o == t || !other.alive) continue;
    const MeshData& m = *meshes_[other.mesh].data;
    if (boxes_overlap(box, world_box(m.mesh.bounds(), other.pose, 0.0)))
      obstacles.push_back({&m.mesh, m.snch.get(), other.pose});
  }
  const coupling::ProxyTool proxy_tool{&tool_mesh.mesh, tool_mesh.snch.get(), tool.reference_point,
                                       tool.radius};
  const coupling::ProxySettings settings{settings_.force.safety_distance, settings_.cutoff()};
  coupling::update_proxy(tool.tool.coupling, settings, proxy_tool, obstacles.data(), obstacles.size(),
                         tool.device_pose, nullptr, proxy, stats);
  if (!stats.moved) return;
  tool.pose = proxy.pose;
  // A new global search once the proxy has moved a quarter of the margin
  // between cutoff and safety distance from where the last one saw it;
  // local tracking in between, as the local thread does. The safety check
  // above does not depend on it: it is exact against every body in reach.
  const double moved = coupling::twist_displacement(
      coupling::twist_between(tool.searched_pose, tool.pose, tool.reference_point), tool.radius);
  if (moved > kResearchFraction * (settings_.cutoff() - settings_.force.safety_distance)) {
    tool.pose_version += 1;
    tool.searched_pose = tool.pose;
    tool.track_pending = false;
  } else {
    tool.track_pending = true;
  }
}

void World::step() {
  const auto start = std::chrono::steady_clock::now();
  stats_ = StepStats{};
  for (std::uint32_t t = 0; t < bodies_.size(); ++t)
    if (bodies_[t].alive && constrained({t, bodies_[t].generation})) step_proxy(t, bodies_[t].proxy_stats);
  // The pipeline's stages in order, on this thread (the tracking threads
  // run the same ones on their own schedule): the global pass, local
  // tracking where a constrained tool's proxy moved without a new search,
  // then the force.
  refresh_poses(global_);
  const SceneView& scene = *view();
  global_.begin(scene_version_, scene);
  std::vector<LmdPair> all;
  for (std::uint32_t t : global_.tools()) {
    BodySlot& tool = bodies_[t];
    const std::vector<PairInRange>& in_range = global_.search(t, scene, stats_, pool_.get());
    if (tool.track_pending) {
      // The proxy moved without a new search: the pairs' LMDs follow it.
      for (const PairInRange& p : in_range) {
        PairSlot& pair = *global_.find(t, p.other);
        LocalTrackingStats local;
        track_pair(*scene.bodies[p.other].mesh, global_.poses()[p.other].pose, *scene.bodies[t].mesh, tool.pose,
                   settings_.cutoff(), pair.tracker(settings_.method), pair.lmds, local);
      }
      tool.track_pending = false;
    }
    tool.contacts.clear();
    all.clear();
    for (const PairInRange& p : in_range)
      for (const LmdPair& lmd : p.slot->lmds) {
        tool.contacts.push_back({p.other, lmd});
        all.push_back(lmd);
      }
    if (tool.tool.mode == coupling::ToolMode::Constrained) {
      const coupling::Twist offset =
          coupling::twist_between(tool.device_pose, tool.pose, tool.reference_point);
      tool.offset_rate.update(offset, kStepSeconds);
    }
    tool.wrench = wrench_of(tool, all);
    stats_.contacts += static_cast<int>(tool.contacts.size());
  }
  global_.end();
  stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Wrench World::wrench_of(const BodySlot& tool, const std::vector<LmdPair>& lmds) const {
  if (tool.tool.mode == coupling::ToolMode::Constrained)
    return clip_wrench(coupling::coupling_wrench(tool.tool.coupling, tool.device_pose, tool.pose,
                                                 tool.reference_point, tool.offset_rate.rate()),
                       settings_.force);
  return tool_wrench(settings_.force, lmds, tool.pose.apply(tool.reference_point));
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
      PairSlot* pair = global_.find(t, o);
      if (pair == nullptr || pair->tool_generation != tool.generation || pair->body_generation != other.generation)
        continue;
      LocalTrackingStats local;
      track_pair(*meshes_[other.mesh].data, other.pose, tool_mesh, tool.pose, settings_.cutoff(),
                 pair->tracker(settings_.method), pair->lmds, local);
      track_stats_.local += local;
      ++track_stats_.pairs;
      for (const LmdPair& p : pair->lmds) {
        tool.contacts.push_back({o, p});
        all.push_back(p);
      }
    }
    tool.wrench = wrench_of(tool, all);
  }
  track_stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double World::distance(Handle a_handle, Handle b_handle, double bound) const {
  const BodySlot& a = bodies_[a_handle.index];
  const BodySlot& b = bodies_[b_handle.index];
  const MeshData& ma = *meshes_[a.mesh].data;
  const MeshData& mb = *meshes_[b.mesh].data;
  // While the threads run a tool is where its device last put it (a
  // constrained tool: where its proxy is).
  const PairQuery q{
      &ma.mesh, ma.snch.get(), proxy_pose(a_handle), &mb.mesh, mb.snch.get(), proxy_pose(b_handle), 0.0};
  return minimum_distance(q, bound);
}

void World::intersections(Handle tool_handle, std::vector<std::pair<std::uint32_t, Polyline>>& out) {
  out.clear();
  BodySlot& tool = bodies_[tool_handle.index];
  tool.intersection_stats = PolylineStats{};
  const Pose tool_pose = proxy_pose(tool_handle);
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
