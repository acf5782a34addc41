// The scene from the C API: one world with mesh A as a static body and mesh
// B as the held tool, the device that drives it, and what the viewer reads
// from it once per frame (poses, contacts, wrench, polylines, thread stats).
#pragma once

#include "options.h"
#include "render_mesh.h"

#include <proxima/proxima.h>

#include <glm/glm.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace viewer {

// A failed C API call: the library's message.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Polyline {
  std::vector<glm::dvec3> points;  // world
  bool closed = false;
};

// What one frame shows, read from the world in update().
struct FrameData {
  glm::dmat4 model_a{1.0}, model_tool{1.0};  // body to world (the tool: its proxy)
  // A constrained tool's device pose, when it is not where the proxy is.
  bool ghost = false;
  glm::dmat4 model_ghost{1.0};
  proxPose tool_pose{}, device_pose{};  // the proxy's and the device's
  glm::dvec3 reference_point{0.0};      // the tool's, world: where the force is drawn
  std::vector<proxContact> contacts;
  std::vector<proxContactPatch> patches;  // contacts[i]'s patch: how many LMDs it stands for
  std::vector<Polyline> polylines;
  bool polylines_valid = false;  // computed at polylines_pose: kept while the tool stays there
  proxPose polylines_pose{};
  std::vector<proxVec3> polyline_points;         // the C API's output buffers, kept
  std::vector<proxPolylineInfo> polyline_infos;  // from frame to frame
  proxWrench wrench{};
  bool threads = false;               // the world's threads run (else it was stepped)
  proxThreadStats thread_stats[3]{};  // haptic, local, global
};

class Scene {
 public:
  // Builds the world and starts its threads when a device drives the tool.
  // Throws SceneError with the library's message (a missing mesh, a bad
  // poses file).
  Scene(const Options& options, const std::string& path_a, const std::string& path_b);
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  // Reads this frame's data into `frame` (the previous frame's, reused);
  // polylines only when asked, as they are computed on the call, and only
  // when the tool has moved since they were.
  void update(FrameData& frame, bool polylines) const;
  // The mouse and gamepad devices: hands the streamed device holding the
  // tool where the input has taken it, now (once a frame).
  void push_tool_pose(const proxPose& pose);
  // What the streamed device saw; false when no streamed device drives the tool.
  bool stream_stats(proxStreamDeviceStats* stats) const;
  proxPose tool_pose() const;
  // A line about the HID device driving the tool; empty when none does.
  std::string hid_summary() const;
  // The triangles of mesh A, or of the tool's mesh, to draw (the world's own,
  // welded: any file the library reads).
  RenderMesh render_mesh(bool tool) const;
  // A and the tool use one mesh (the same file, not animated otherwise).
  bool shares_mesh() const { return mesh_b_.index1 == mesh_a_.index1; }

  // --animate, --animate-b: poses the animated meshes at `seconds` since the
  // animation started, each looping over its keyframes (proxMesh_Animate),
  // and steps a world without threads so that its contacts are on the new
  // shape. False (and nothing done) when no mesh is animated.
  bool animate(double seconds);
  bool animated() const { return animations_[0].index >= 0 || animations_[1].index >= 0; }
  // The posed vertices of A or the tool's mesh into `positions` (x, y, z
  // per vertex, the order render_mesh() gave), through buffers kept from
  // call to call: no allocation after the first.
  void read_vertices(bool tool, std::vector<float>& positions);

  // The box the camera frames: both bodies over the tool's whole path, each
  // over its whole animation.
  glm::dvec3 bounds_min() const { return bounds_min_; }
  glm::dvec3 bounds_max() const { return bounds_max_; }
  double cutoff() const { return cutoff_; }
  const proxForceSettings& force() const { return force_; }
  // Each contact's share of the summed force magnitude, by the force curve.
  // Each contact's share of the summed force, a patch weighing its count.
  std::vector<double> force_shares(const std::vector<proxContact>& contacts,
                                   const std::vector<proxContactPatch>& patches) const;

 private:
  void build(const Options& options, const std::string& path_a, const std::string& path_b);
  double x_at_gap(double gap) const;
  void read_positions(proxMeshId mesh);  // into positions_ (and indices_)
  // Checks --animate's index against the file and keeps what playing it needs.
  struct Animation {
    proxMeshId mesh{};
    int32_t index = -1;  // -1: not animated
    double start = 0.0, length = 0.0;
  };
  Animation animation(proxMeshId mesh, int index, const std::string& option, const std::string& path) const;
  // The mesh's box over its whole animation (sampled at 60 Hz, at most 601
  // poses), left posed at the animation's start; its box as loaded when it
  // is not animated.
  void animated_bounds(const Animation& a, glm::dvec3* lo, glm::dvec3* hi);
  bool constrained_ = false;

  proxWorldId world_{};
  proxBodyId a_{}, tool_{};
  proxMeshId mesh_a_{}, mesh_b_{};
  bool threads_ = false;
  proxStreamDeviceId stream_{};  // the mouse or gamepad device
  uint64_t hid_ = 0;             // the HID device (hid_input.h), as one integer
  double cutoff_ = 0.0;
  proxForceSettings force_{};
  glm::dvec3 reference_local_{0.0};
  glm::dvec3 bounds_min_{0.0}, bounds_max_{0.0};
  Animation animations_[2];        // A's, the tool's (not when it shares A's mesh)
  std::vector<double> positions_;  // proxMesh_GetTriangles' output, kept
  std::vector<uint32_t> indices_;  // from frame to frame
};

}  // namespace viewer
