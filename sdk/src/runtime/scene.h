// Versions of a world's scene (docs/dynamic-scenes.md). The game thread owns
// the world; what the tracking threads read of its shape, while they run, is
// an immutable SceneView it publishes at every change of that shape (a body
// made or destroyed, a mesh deformed). A thread keeps the view it works with
// alive, so the game thread never waits for it, and it for the game thread
// only as long as it takes to copy a pointer. The haptic loop reads none of
// it: it sees the scene through the contact snapshots local tracking hands it.
#pragma once

#include "mesh/mesh.h"
#include "snch/snch.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace prox::runtime {

enum class BodyType { Static, Movable, Tool };

// One shape of a mesh: never changed once published. A deformation makes a
// new one (its hierarchy refitted or rebuilt) with a new version.
struct MeshData {
  Mesh mesh;
  std::shared_ptr<const Snch> snch;
  std::uint64_t version = 0;  // unique in its world: a new shape, a new version
};

// Where a deforming mesh's retired shape goes once no thread holds it: its
// storage (vertices, normals, hierarchy) is written over for the next
// shape, which then costs no allocation and no copy of the hierarchy. The
// thread that lets a shape go last puts it here, under the mutex (never the
// haptic thread: it holds no shape).
struct MeshRecycler {
  std::mutex mutex;
  std::unique_ptr<MeshData> spare;
};

struct SceneBody {
  bool alive = false;
  std::uint32_t generation = 0;
  BodyType type = BodyType::Static;
  std::shared_ptr<const MeshData> mesh;  // null when not alive
  // A tool's: the radius of its mesh's bounds about its reference point.
  double radius = 0.0;
};

struct SceneView {
  std::uint64_t version = 0;
  std::vector<SceneBody> bodies;  // by body slot

  // Whether `index` names a live body of generation `generation`.
  bool alive(std::uint32_t index, std::uint32_t generation) const {
    return index < bodies.size() && bodies[index].alive && bodies[index].generation == generation;
  }
};

}  // namespace prox::runtime
