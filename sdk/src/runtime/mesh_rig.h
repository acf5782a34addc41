// A mesh's glTF rig at runtime (docs/dynamic-scenes.md, "glTF skins, morph
// targets and animation"): the rig the mesh was loaded with (shared, never
// changed) and the game thread's current pose of it. World keeps one per
// rigged mesh; its deformations replace the mesh's vertices through
// World::set_vertices.
#pragma once

#include "common/status.h"
#include "mesh/mesh.h"
#include "mesh/rig.h"

#include <memory>
#include <vector>

namespace prox::runtime {

class MeshRig {
 public:
  MeshRig() = default;
  explicit MeshRig(std::shared_ptr<const rig::Rig> rig);

  const rig::Rig& rig() const { return *rig_; }

  // Each returns false with `status` naming the bad argument and leaves the
  // pose unchanged. animate: the rest pose with animation `animation` at
  // `seconds` (clamped to its keyframes), given joint matrices and morph
  // weights dropped.
  bool animate(std::int64_t animation, double seconds, Status& status);
  // Skin `skin`'s joints' world matrices, `count` column-major 4 x 4
  // doubles in the mesh's frame, one per joint in the skin's order; they
  // stand for the joints' nodes until the next animate.
  bool set_joint_matrices(std::int64_t skin, const double* matrices, std::int64_t count, Status& status);
  // Every morphed instance's weights, one after the other in scene order
  // (rig::Rig::morph_weight_count), until the next animate.
  bool set_morph_weights(const double* weights, std::int64_t count, Status& status);

  // The mesh's vertices (welded order) at the current pose: each from the
  // first input vertex welded into it.
  void welded_positions(const Mesh& mesh, std::vector<Vec3>& out) const;

 private:
  std::shared_ptr<const rig::Rig> rig_;
  rig::Pose pose_;
  std::vector<std::vector<rig::Mat4>> joint_worlds_;  // per skin; empty: from the nodes
};

}  // namespace prox::runtime
