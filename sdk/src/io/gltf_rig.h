// Reading a glTF scene's skins, morph targets and animations into a
// rig::Rig (mesh/rig.h), beside the geometry gltf.cpp reads. Private to
// sdk/src/io.
#pragma once

#include "common/status.h"
#include "io/gltf_accessor.h"
#include "mesh/rig.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace prox::io::gltf_detail {

// A primitive's vertices within its mesh's vertex list (primitives sharing a
// POSITION accessor share them).
struct PrimitiveRange {
  int primitive = 0;
  std::uint32_t first = 0;
  std::uint32_t count = 0;
};

// One mesh's triangles in its own coordinates, as gltf.cpp decodes it.
struct LocalMesh {
  bool decoded = false;
  std::vector<glm::dvec3> positions;
  std::vector<std::uint32_t> indices;
  std::vector<PrimitiveRange> primitives;  // the triangle primitives read, in order
};

// A node whose mesh has triangles, in scene order; its vertices follow the
// previous instances' (input vertex `first`, in the merged soup).
struct MeshInstance {
  int node = 0;
  int mesh = 0;
  std::uint32_t first = 0;
};

// Whether the file has anything a rig holds: a skin or morph target on a
// mesh instance, or an animation.
bool has_rig(const tinygltf::Model& model, const std::vector<MeshInstance>& instances);

// The rig of the scene's mesh instances (`meshes` indexed by glTF mesh).
// Refuses what glTF 2.0 forbids (a MUST) with the accessor named: negative
// weights, normalized integer weights not summing to 255 or 65535, joints
// past the skin's, JOINTS_n without WEIGHTS_n; float weights not summing to
// 1 (a SHOULD) are normalized with a warning.
Status read_rig(const tinygltf::Model& model, const std::string& name, const std::vector<LocalMesh>& meshes,
                const std::vector<MeshInstance>& instances, std::vector<std::string>* warnings,
                std::shared_ptr<rig::Rig>& out);

}  // namespace prox::io::gltf_detail
