// The scene's shape (world.h): meshes and bodies made, destroyed and deformed,
// also while the threads run, and the views of it the tracking threads read
// (scene.h, docs/dynamic-scenes.md).
#include "runtime/threads.h"
#include "runtime/world.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace prox::runtime {
namespace {

template <typename Slot>
std::uint32_t free_slot(std::vector<Slot>& slots) {
  for (std::uint32_t i = 0; i < slots.size(); ++i)
    if (!slots[i].alive) return i;
  slots.emplace_back();
  return static_cast<std::uint32_t>(slots.size() - 1);
}

// `data` as a published shape that, once no one holds it, goes back to
// `recycler` for the next deformation (or is freed when it has one already,
// or the mesh is gone).
std::shared_ptr<const MeshData> recyclable(std::unique_ptr<MeshData> data,
                                           const std::shared_ptr<MeshRecycler>& recycler) {
  std::weak_ptr<MeshRecycler> to = recycler;
  return std::shared_ptr<const MeshData>(data.release(), [to](const MeshData* retired) {
    std::unique_ptr<MeshData> owned(const_cast<MeshData*>(retired));
    if (const auto r = to.lock()) {
      const std::lock_guard<std::mutex> lock(r->mutex);
      if (!r->spare) r->spare = std::move(owned);
    }
  });
}

}  // namespace

double World::radius_about(const Aabb& box, const Vec3& point) {
  double radius = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                 (corner & 4) ? box.max.z : box.min.z);
    radius = std::max(radius, glm::length(p - point));
  }
  return radius;
}

Handle World::create_mesh(const MeshInput& input, Status& status) {
  // Built here, on the calling thread, before any lock is taken.
  auto data = std::make_unique<MeshData>();
  data->mesh = Mesh::build(input, status);
  if (!status) return {};
  data->snch = std::make_shared<Snch>(data->mesh);
  data->version = ++mesh_versions_;
  auto recycler = std::make_shared<MeshRecycler>();
  std::shared_ptr<const MeshData> shape = recyclable(std::move(data), recycler);
  std::unique_lock<std::mutex> lock(scene_mutex_, std::defer_lock);
  if (running()) lock.lock();
  const std::uint32_t i = free_slot(meshes_);
  MeshSlot& slot = meshes_[i];
  slot.generation += 1;
  slot.alive = true;
  slot.data = std::move(shape);
  slot.recycler = std::move(recycler);
  slot.users = 0;
  slot.warnings.clear();
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
  std::shared_ptr<const MeshData> gone;  // freed after the lock is let go,
  std::shared_ptr<MeshRecycler> recycler;  // with a spare shape
  std::unique_lock<std::mutex> lock(scene_mutex_, std::defer_lock);
  if (running()) lock.lock();
  slot.alive = false;
  gone = std::move(slot.data);
  recycler = std::move(slot.recycler);
  slot.warnings.clear();
  rigs_.erase(h.index);
  return true;
}

bool World::set_vertices(Handle h, const std::vector<Vec3>& positions, Status& status) {
  std::vector<double> xyz(3 * positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v)
    for (int c = 0; c < 3; ++c) xyz[3 * v + static_cast<std::size_t>(c)] = positions[v][c];
  if (positions.size() > 0xFFFFFFFFu) {
    status = Status(StatusCode::InvalidArgument, "too many positions");
    return false;
  }
  return set_vertices(h, xyz.data(), static_cast<std::uint32_t>(positions.size()), status);
}

bool World::set_vertices(Handle h, const double* positions, std::uint32_t count, Status& status) {
  MeshSlot& slot = meshes_[h.index];
  // The new shape is made beside the published one, which the tracking
  // threads may be reading: the mesh moved and its hierarchy refitted (or
  // built anew once refitting has loosened it too far), in a retired
  // shape's storage where one is back from the threads, else in new.
  std::unique_ptr<MeshData> data;
  {
    const std::lock_guard<std::mutex> lock(slot.recycler->mutex);
    data = std::move(slot.recycler->spare);
  }
  if (!data) data = std::make_unique<MeshData>();
  data->mesh = slot.data->mesh;  // vertices and normals; the topology is shared
  status = data->mesh.set_vertices(positions, count, pool_.get());
  if (!status) return false;
  // Only a MeshData holds its hierarchy, and a spare is held by no one.
  auto snch = std::const_pointer_cast<Snch>(std::move(data->snch));
  if (snch) {
    snch->refit_as(*slot.data->snch, data->mesh, pool_.get());
  } else {
    snch = std::make_shared<Snch>(*slot.data->snch);
    snch->refit(data->mesh, pool_.get());
  }
  if (snch->stats().degradation > Snch::kRebuildDegradation) snch = std::make_shared<Snch>(data->mesh);
  data->snch = std::move(snch);
  data->version = ++mesh_versions_;
  std::shared_ptr<const MeshData> shape = recyclable(std::move(data), slot.recycler);

  std::shared_ptr<const MeshData> old;  // freed after the lock is let go
  std::unique_lock<std::mutex> lock(scene_mutex_, std::defer_lock);
  if (running()) lock.lock();
  old = std::move(slot.data);
  slot.data = std::move(shape);
  // Every body using the mesh has a new shape: its pairs are searched again
  // (a pose version is what a pair's answer is kept by), and the broadphase
  // takes the new bounds.
  for (BodySlot& b : bodies_) {
    if (!b.alive || b.mesh != h.index) continue;
    b.pose_version += 1;
    b.radius = radius_about(slot.data->mesh.bounds(), b.reference_point);
  }
  ++scene_version_;
  shape_changed();
  return true;
}

Handle World::create_body(Handle mesh, BodyType type, const Pose& pose, const Vec3& reference_point,
                          const ToolSettings& tool) {
  std::unique_lock<std::mutex> lock(scene_mutex_, std::defer_lock);
  if (running()) lock.lock();
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
  b.tool = type == BodyType::Tool ? tool : ToolSettings{};
  b.device_pose = pose;
  b.proxy = coupling::ProxyState{};
  b.offset_rate.reset();
  b.searched_pose = pose;
  b.track_pending = false;
  b.radius = radius_about(meshes_[mesh.index].data->mesh.bounds(), reference_point);
  meshes_[mesh.index].users += 1;
  ++scene_version_;
  shape_changed();
  if (lock.owns_lock()) lock.unlock();
  // A tool made while the threads run: published to them after the view
  // that holds its body.
  if (type == BodyType::Tool && running()) threads_->add_tool(i);
  return {i, b.generation};
}

bool World::body_alive(Handle h) const {
  return h.index < bodies_.size() && bodies_[h.index].alive && bodies_[h.index].generation == h.generation;
}

void World::destroy_body(Handle h) {
  // A tool's device is faded out and let go of before its body goes.
  if (running() && bodies_[h.index].type == BodyType::Tool) threads_->remove_tool(h.index);
  std::unique_lock<std::mutex> lock(scene_mutex_, std::defer_lock);
  if (running()) lock.lock();
  BodySlot& b = bodies_[h.index];
  b.alive = false;
  b.contacts.clear();
  b.device = Device{};
  meshes_[b.mesh].users -= 1;
  ++scene_version_;
  shape_changed();
}

std::shared_ptr<SceneView> World::make_view() const {
  auto view = std::make_shared<SceneView>();
  view->bodies.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const BodySlot& b = bodies_[i];
    SceneBody& s = view->bodies[i];
    s.alive = b.alive;
    s.generation = b.generation;
    s.type = b.type;
    if (!b.alive) continue;
    s.mesh = meshes_[b.mesh].data;
    s.radius = b.radius;
  }
  return view;
}

void World::shape_changed() {
  view_stale_ = true;
  // The tracking threads ask for the view without the game thread: while
  // they run it is made at once (the caller holds scene_mutex_).
  if (running()) view();
}

const std::shared_ptr<const SceneView>& World::view() {
  if (view_stale_ || !view_) {
    auto next = make_view();
    next->version = ++view_versions_;
    view_ = std::move(next);
    view_stale_ = false;
    view_version_.store(view_->version, std::memory_order_release);
  }
  return view_;
}

bool World::latest_view(std::shared_ptr<const SceneView>& view) const {
  if (view && view->version == view_version_.load(std::memory_order_acquire)) return false;
  std::lock_guard<std::mutex> lock(scene_mutex_);
  if (view == view_) return false;
  view = view_;
  return true;
}

}  // namespace prox::runtime
