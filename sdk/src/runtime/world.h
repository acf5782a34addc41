// A world of meshes and bodies: what the C API drives. Engine objects live in
// generation-checked slots so that stale ids are detected, never followed.
#pragma once

#include "contact/force.h"
#include "contact/polylines.h"
#include "contact/proximity.h"
#include "coupling/proxy.h"
#include "runtime/device.h"
#include "runtime/global_pass.h"
#include "runtime/mesh_rig.h"
#include "runtime/scene.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace prox {
class WorkerPool;
}

namespace prox::runtime {

class Threads;
struct ThreadSettings;

// How a tool follows what moves it (docs/coupling.md): Free, the tool is
// where the device puts it and the force comes from the LMDs (the paper);
// Constrained, a proxy follows the device but stays outside every other
// body, and the force is the virtual coupling between the two.
struct ToolSettings {
  coupling::ToolMode mode = coupling::ToolMode::Free;
  coupling::CouplingSettings coupling;
};

// The deterministic step of a constrained tool is one haptic period for the
// coupling's dampers.
inline constexpr double kStepSeconds = 0.001;
// A constrained tool's step searches globally again once its proxy has
// moved this share of (cutoff - safety distance) since the last search, and
// tracks its LMDs in between.
inline constexpr double kResearchFraction = 0.25;

struct WorldSettings {
  Method method = Method::Precise;
  // The distance-to-force curve, and in it the cutoff (contacts farther
  // apart are not wanted), stored here alone.
  ForceSettings force = hard_force_settings();
  PatchSettings patches;  // how LMDs merge into patches (docs/patches.md)
  // Threads the game thread's own heavy work splits over, itself included:
  // a deforming mesh's normals and refit, the step's global searches. 1
  // starts none (the haptic and tracking threads keep their cores).
  unsigned workers = 1;

  double cutoff() const { return force.cutoff; }
};

// A slot index and the generation it had when the object was created.
struct Handle {
  std::uint32_t index = 0;
  std::uint32_t generation = 0;
};

struct Contact {
  std::uint32_t other = 0;  // body slot
  LmdPair lmd;              // A = the other body, B = the tool
};

// What the last track() did, summed over the pairs tracked.
struct TrackStats {
  int pairs = 0;
  LocalTrackingStats local;
  double seconds = 0.0;
};

class World {
 public:
  explicit World(const WorldSettings& settings);

  // Meshes. create_mesh validates and builds, on the calling thread; on
  // error `status` says why. Also while the threads run.
  Handle create_mesh(const MeshInput& input, Status& status);
  bool mesh_alive(Handle h) const;
  // Fails (false) while bodies use the mesh.
  bool destroy_mesh(Handle h, Status& status);
  const Mesh& mesh(Handle h) const { return meshes_[h.index].data->mesh; }
  // What reading a mesh's file skipped (one line each; empty: nothing), for
  // its owner to read back. Game thread.
  void set_mesh_warnings(Handle h, std::string warnings) { meshes_[h.index].warnings = std::move(warnings); }
  const std::string& mesh_warnings(Handle h) const { return meshes_[h.index].warnings; }
  const Snch& snch(Handle h) const { return *meshes_[h.index].data->snch; }
  // Moves a mesh's vertices (x, y, z per welded vertex, in Mesh order; the
  // same count), keeping its topology: a new shape of the mesh, its
  // hierarchy refitted on the calling thread, or rebuilt when the refit has
  // loosened it past Snch::kRebuildDegradation. Every body using the mesh
  // takes the new shape: at the next step, or, while the threads run, at the
  // tracking threads' next iteration. Fails (false, with `status`) on a
  // count that differs or a non-finite coordinate, changing nothing.
  bool set_vertices(Handle mesh, const double* positions, std::uint32_t count, Status& status);
  bool set_vertices(Handle mesh, const std::vector<Vec3>& positions, Status& status);

  // glTF rigs (runtime/mesh_rig.h, docs/dynamic-scenes.md): the rig a mesh
  // was loaded with, whose input vertices must be the mesh's, and the game
  // thread's pose of it; nullptr for a mesh without one. Game thread.
  bool set_rig(Handle mesh, std::shared_ptr<const rig::Rig> rig, Status& status);
  const MeshRig* rig(Handle mesh) const;
  MeshRig* rig(Handle mesh);

  // Bodies.
  Handle create_body(Handle mesh, BodyType type, const Pose& pose, const Vec3& reference_point,
                     const ToolSettings& tool = {});
  bool body_alive(Handle h) const;
  void destroy_body(Handle h);
  void set_pose(Handle h, const Pose& pose);
  const Pose& pose(Handle h) const { return bodies_[h.index].pose; }
  BodyType type(Handle h) const { return bodies_[h.index].type; }
  bool constrained(Handle h) const {
    return bodies_[h.index].type == BodyType::Tool &&
           bodies_[h.index].tool.mode == coupling::ToolMode::Constrained;
  }
  std::uint32_t body_generation(std::uint32_t index) const { return bodies_[index].generation; }

  // The deterministic step: every tool against the bodies in range, on the
  // calling thread. Not while the threads run.
  void step();
  // The latest results: of the last step, or of the threads while they run
  // (contacts from local tracking, the wrench the haptic loop last handed
  // to the device, the pose it last read). Game thread.
  void contacts(Handle tool, std::vector<Contact>& out) const;
  Wrench wrench(Handle tool) const;
  // A body's pose; for a constrained tool, the device's pose (where the
  // hand is), not the proxy's.
  Pose current_pose(Handle body) const;
  // Where the body is as rendered and as contacts are computed: its pose,
  // or a constrained tool's proxy (while the threads run, local tracking's
  // latest). Distances and intersections are taken here.
  Pose proxy_pose(Handle body) const;
  StepStats stats() const;
  // Local tracking alone: every tool's contacts from the last step carried
  // to the current poses by the pair's tracker (what the local thread does
  // between global searches), and the wrenches recomputed. Pairs the last
  // step did not keep are not tracked; no new pair is found. Not while the
  // threads run.
  void track();
  // The patch rule from the next step on; the pairs' cached results, merged
  // by the old rule, are dropped. Not while the threads run.
  void set_patches(const PatchSettings& patches) {
    settings_.patches = patches;
    global_ = GlobalPass(settings_.method, settings_.cutoff(), patches);
  }
  const TrackStats& track_stats() const { return track_stats_; }
  // A constrained tool's last proxy update in step().
  const coupling::ProxyStats& proxy_stats(Handle tool) const { return bodies_[tool.index].proxy_stats; }
  // The intersection polylines of a tool with every body whose box meets
  // its box, at the current poses; computed on each call. The call's
  // figures are kept with the tool.
  void intersections(Handle tool, std::vector<std::pair<std::uint32_t, Polyline>>& out);
  const PolylineStats& intersection_stats(Handle tool) const {
    return bodies_[tool.index].intersection_stats;
  }
  // The exact minimum distance between two bodies at their current poses (0
  // when they intersect); +infinity when they are farther apart than `bound`.
  double distance(Handle a, Handle b, double bound) const;
  int body_count() const;
  int tool_count() const;

  // A device holds the tool while the threads run (none: the game thread's
  // set_pose moves it then). While they run, the old device is faded out
  // and let go of before this returns.
  void set_device(Handle tool, const Device& device);
  const Device& device(Handle tool) const { return bodies_[tool.index].device; }
  // The live tool `device` holds, or -1.
  int device_holder(const HapticDevice* device) const;

  // The threads (docs/threading.md). start_threads fails (false, with
  // `status`) on bad settings; while they run, meshes and bodies may be
  // created, destroyed and deformed (the C API refuses deforming a mesh a
  // tool holds), devices changed, and step() is refused.
  bool start_threads(const ThreadSettings& settings, Status& status);
  void stop_threads();
  bool running() const;
  // The running threads, or the last ones stopped (their statistics stay
  // readable); nullptr before the first start.
  Threads* threads() { return threads_.get(); }
  const Threads* threads() const { return threads_.get(); }
  const WorldSettings& settings() const { return settings_; }

  // What the threads take over of a tool's body when they start or it is
  // made while they run. Game thread.
  struct ToolStart {
    Device device;
    Vec3 reference_point{0.0};
    double radius = 0.0;  // of the mesh's bounds about the reference point
    Pose pose;            // what searches see: a constrained tool's proxy
    Pose device_pose;     // a constrained tool's device pose
    ToolSettings tool;
    Wrench wrench;
    std::vector<Contact> contacts;
  };
  std::uint32_t body_slots() const { return static_cast<std::uint32_t>(bodies_.size()); }
  bool is_tool(std::uint32_t slot) const;
  ToolStart tool_start(std::uint32_t slot) const;

  // For the global search thread: under the scene lock, the latest view,
  // the bodies' poses into `pass` (all of them when the scene's version
  // moved, else the tools') and its broadphase brought to that version.
  std::shared_ptr<const SceneView> snapshot(GlobalPass& pass) const;

  // The scene's latest version. Game thread.
  const std::shared_ptr<const SceneView>& view();
  // For the tracking threads while they run: replaces `view` with the
  // latest version when it is not that one (true), taking the scene lock
  // only then. A thread keeps its view alive as long as it uses it.
  bool latest_view(std::shared_ptr<const SceneView>& view) const;
  ~World();

 private:
  struct MeshSlot {
    std::uint32_t generation = 0;
    bool alive = false;
    std::shared_ptr<const MeshData> data;  // the mesh's current shape
    std::shared_ptr<MeshRecycler> recycler;  // its retired shapes' storage
    int users = 0;
    std::string warnings;  // the game thread's
  };
  struct BodySlot {
    std::uint32_t generation = 0;
    bool alive = false;
    std::uint32_t mesh = 0;
    BodyType type = BodyType::Static;
    Pose pose;
    Vec3 reference_point{0.0};
    std::uint64_t pose_version = 0;    // bumped by every set_pose
    std::vector<Contact> contacts;     // tools: after the last step
    Wrench wrench;                     // tools: after the last step
    Device device;                     // tools: what holds it while the threads run
    PolylineStats intersection_stats;  // tools: of the last intersections() call
    // Tools. For a constrained one `pose` is the proxy (what searches see)
    // and `device_pose` what set_pose gave.
    ToolSettings tool;
    Pose device_pose;
    coupling::ProxyState proxy;
    coupling::OffsetRate offset_rate;
    coupling::ProxyStats proxy_stats;  // of the last step's proxy update
    Pose searched_pose;                // where the last global search saw the proxy
    bool track_pending = false;        // the proxy moved since, without a new search
    double radius = 0.0;               // of the mesh's bounds about the reference point
  };

  // The radius of a mesh's bounds about a point of its frame.
  static double radius_about(const Aabb& box, const Vec3& point);
  // Marks the scene's shape changed: a new view is made when next asked
  // for, and at once while the threads run (under scene_mutex_ then).
  void shape_changed();
  std::shared_ptr<SceneView> make_view() const;
  // Copies every body's pose into `pass` when the scene version moved, else
  // only the tools'.
  void refresh_poses(GlobalPass& pass) const;
  // A constrained tool's proxy update in the deterministic step: towards its
  // device pose, constrained by the last step's contacts.
  void step_proxy(std::uint32_t tool, coupling::ProxyStats& stats);
  // A tool's wrench in the deterministic step: its coupling's for a
  // constrained one, else the force curve's over `lmds`.
  Wrench wrench_of(const BodySlot& tool, const std::vector<LmdPair>& lmds) const;

  WorldSettings settings_;
  std::vector<MeshSlot> meshes_;
  std::vector<BodySlot> bodies_;
  // glTF rigs, by mesh slot (rigged meshes only).
  std::unordered_map<std::uint32_t, MeshRig> rigs_;
  GlobalPass global_;  // the deterministic step's
  // Moves with every change the broadphase must see: bodies created or
  // destroyed, static and movable bodies moved (tools move every step and
  // are tested on their own).
  std::uint64_t scene_version_ = 0;
  std::uint64_t mesh_versions_ = 0;  // the last MeshData::version handed out
  // The scene's shape as the tracking threads read it; remade when stale.
  std::shared_ptr<const SceneView> view_;
  bool view_stale_ = true;
  std::uint64_t view_versions_ = 0;
  std::atomic<std::uint64_t> view_version_{0};  // view_'s, for latest_view
  StepStats stats_;
  TrackStats track_stats_;
  // While the threads run, the game thread's changes to the bodies, the
  // meshes' slots and the view, and the tracking threads' reading of the
  // poses and the view, meet here (never on the haptic path).
  mutable std::mutex scene_mutex_;
  std::unique_ptr<Threads> threads_;
  // The game thread's helpers (settings_.workers > 1), else null.
  std::unique_ptr<WorkerPool> pool_;
};

}  // namespace prox::runtime
