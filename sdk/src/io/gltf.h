// glTF 2.0 reading (.gltf with external or embedded buffers, and .glb):
// triangle geometry of the default scene only, in double precision. Built when
// PROX_WITH_GLTF is on (the default); it needs tinygltf and nlohmann-json.
#pragma once

#include "common/status.h"
#include "mesh/rig.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace prox::io {

enum class GltfSceneMode {
  Merged,   // one soup holding every mesh instance of the scene
  PerNode,  // one soup per node that instantiates a mesh with triangles, in scene order
};

// One triangle soup in world (scene root) coordinates: every node transform
// from the root down to the mesh is applied, in double precision.
struct GltfMesh {
  std::string name;  // node name (else mesh name, else "node N") for PerNode; file stem for Merged
  std::vector<double> positions;       // x, y, z per vertex
  std::vector<std::uint32_t> indices;  // three per triangle, 0-based into positions
  // Merged, for a file with skins, morph targets or animations: the scene's
  // rig; `positions` are its input vertices at rest (mesh/rig.h).
  std::shared_ptr<const rig::Rig> rig;
};

struct GltfLoadOptions {
  GltfSceneMode mode = GltfSceneMode::Merged;
  // Whether a .gltf's buffers may be read from files beside it. Off for bytes
  // that came from memory, where no file is theirs: such a buffer is then
  // an IoError that names its URI (data: URIs and GLB chunks are read either way).
  bool external_buffers = true;
};

// Reads the default scene of `path` (scene 0 if the file names none; every
// root node if it has no scenes). What is read:
// - every triangle primitive (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN; indexed
//   or not) of every mesh instance, once per node that instantiates it;
//   POINTS and LINES primitives are skipped;
// - POSITION only: float, or the integer types of KHR_mesh_quantization
//   (normalized or not), with byteStride, byteOffset and sparse accessors;
// - node matrices and translation/rotation/scale;
// - skins (JOINTS_n, WEIGHTS_n, inverse bind matrices), morph targets
//   (POSITION deltas, default weights from node.weights or mesh.weights) and
//   animations, into GltfMesh::rig (gltf_rig.h); the vertices are posed at
//   rest: a skinned mesh by its joints at their nodes' own transforms (its
//   node's transform ignored, as glTF requires), a morphed one by its default
//   weights. glTF's MUST rules on skins are checked; float weights not summing
//   to 1 are normalized with a warning.
// Images are never read or decoded.
//
// Errors name the file and the offending part ("mesh 3 'Gear' primitive 0:
// POSITION accessor 12: ..."): IoError when a file cannot be read (the file
// itself or an external buffer), Unsupported for an extension in
// extensionsRequired that changes geometry (e.g. KHR_draco_mesh_compression),
// another glTF major version, or a scene without triangles, and ParseError for
// anything malformed (truncated or corrupt container or JSON, out-of-range
// references or bytes, index values past the vertex count, non-finite
// positions). `out` is empty after an error.
//
// `warnings`, when given, receives what was skipped or mended: attributes
// Proxima does not read (NORMAL, TEXCOORD_0, ...) of the primitives it reads,
// when they are invalid (an accessor running past its bufferView, say), and
// float skin weights normalized, one message each naming the file, mesh,
// primitive and accessor.
Status load_gltf(const std::string& path, const GltfLoadOptions& options, std::vector<GltfMesh>& out,
                 std::vector<std::string>* warnings = nullptr);
// The same, from the file's bytes already in memory; `path` is used in
// messages, and its directory for external buffers.
Status load_gltf_bytes(std::vector<unsigned char> bytes, const std::string& path,
                       const GltfLoadOptions& options, std::vector<GltfMesh>& out,
                       std::vector<std::string>* warnings = nullptr);

}  // namespace prox::io
