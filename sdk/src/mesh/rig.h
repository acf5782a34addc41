// A glTF scene's rig: its node hierarchy with rest transforms, skins (joints
// and inverse bind matrices), morph targets and animations, and their
// evaluation into vertex positions (docs/dynamic-scenes.md, "glTF skins,
// morph targets and animation"). Independent of the file format: the glTF
// reader (io/gltf_rig.cpp) fills it.
//
// Vertices are the reader's input vertices: every mesh instance of the scene
// in scene order, each listing its mesh's vertices (unwelded). Mesh::build
// welds them; Mesh::welded_vertex maps an input vertex to its welded one.
#pragma once

#include "common/status.h"
#include "geometry/types.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace prox::rig {

// Column-major, as glTF and glm: m[column][row].
using Mat4 = glm::dmat4;
// A quaternion x, y, z, w (glTF's order).
using Quat = glm::dvec4;

struct Trs {
  Vec3 translation{0.0};
  Quat rotation{0.0, 0.0, 0.0, 1.0};
  Vec3 scale{1.0};
};
// T * R * S, the rotation normalized first (a zero quaternion is the identity).
Mat4 trs_matrix(const Trs& trs);

struct Node {
  std::string name;
  int parent = -1;
  bool has_matrix = false;  // its local transform is `matrix`, never animated
  Mat4 matrix{1.0};
  Trs rest;                     // its local transform otherwise
  std::vector<double> weights;  // its mesh's default morph weights (empty: no morph targets)
};

struct Skin {
  std::string name;
  std::vector<std::uint32_t> joints;  // node indices
  std::vector<Mat4> inverse_bind;     // one per joint
};

// One glTF mesh's vertices, in its own coordinates.
struct RigMesh {
  std::vector<Vec3> positions;
  std::vector<std::vector<Vec3>> targets;  // per morph target: a POSITION delta per vertex
  // Skin influences: `influences` per vertex (4 per JOINTS_n/WEIGHTS_n
  // pair; 0 when the mesh has none), joints as indices into the skin's joint
  // list, weights summing to 1.
  std::uint32_t influences = 0;
  std::vector<std::uint32_t> joints;
  std::vector<double> weights;
};

// A node that instantiates a mesh; its vertices are the input vertices
// [first_vertex, first_vertex + mesh's vertex count).
struct Instance {
  std::uint32_t node = 0;
  std::uint32_t mesh = 0;
  int skin = -1;  // skinned: the node's transform is ignored (glTF 2.0)
  std::uint32_t first_vertex = 0;
};

enum class Interpolation { Step, Linear, CubicSpline };
enum class Path { Translation, Rotation, Scale, Weights };

// Keyframes: `times` strictly increasing; `values` holds, per keyframe,
// `width` values (3 for T and S, 4 for R, the morph target count for
// weights), or for CubicSpline three such groups: in-tangent, value,
// out-tangent.
struct Sampler {
  Interpolation interpolation = Interpolation::Linear;
  std::vector<double> times;
  std::vector<double> values;
  std::uint32_t width = 0;
};

struct Channel {
  std::uint32_t node = 0;
  Path path = Path::Translation;
  std::uint32_t sampler = 0;  // in the animation's samplers (channels may share one)
};

struct Animation {
  std::string name;
  std::vector<Sampler> samplers;
  std::vector<Channel> channels;
  double start = 0.0, end = 0.0;  // the first and last keyframe times over the channels
};

// What animates: every node's local TRS and morph weights.
struct Pose {
  std::vector<Trs> local;                    // per node
  std::vector<std::vector<double>> weights;  // per node (empty for nodes without morph targets)
};

// Sampler `s` at time `t` into `out` (s.width values): clamped to the first
// and last keyframes; Step holds a keyframe, Linear interpolates (spherically
// for rotations, along the shorter arc), CubicSpline is glTF's Hermite
// spline. `rotation`: the result is a quaternion (normalized).
void sample(const Sampler& s, double t, bool rotation, double* out);
// The glTF 2.0 specification's slerp: along the shorter arc, linear (then
// normalized) when the two are within 1e-6 of parallel.
Quat slerp(const Quat& a, const Quat& b, double t);

class Rig {
 public:
  std::vector<Node> nodes;
  std::vector<Skin> skins;
  std::vector<RigMesh> meshes;
  std::vector<Instance> instances;
  std::vector<Animation> animations;
  std::uint32_t vertex_count = 0;  // input vertices over the instances

  // Checks that every index is in range and every array has its size, and
  // orders the nodes parents first; false with `status` naming the problem
  // (a cycle, a joint past the nodes, ...). Call once after filling.
  bool finalize(Status& status);

  Pose rest_pose() const;
  // The channels of animation `a` at `seconds`, over `pose` (properties the
  // animation does not drive keep their value). `a` must be in range.
  void animate(std::size_t a, double seconds, Pose& pose) const;
  // Every node's world (scene root) transform.
  std::vector<Mat4> world_matrices(const Pose& pose) const;
  // The input vertices at `pose`: morph targets by the node's weights, then
  // the skin (linear blend of joint world x inverse bind) or the node's
  // world transform. `joint_worlds[s]`, when not empty, replaces skin s's
  // joints' world matrices (one per joint).
  void positions(const Pose& pose, const std::vector<std::vector<Mat4>>& joint_worlds,
                 std::vector<Vec3>& out) const;

  // The morph weights of every instance with morph targets, one after the
  // other in instance order: what proxMesh_SetMorphWeights takes.
  std::uint32_t morph_weight_count() const;
  void set_morph_weights(const double* weights, Pose& pose) const;

 private:
  std::vector<std::uint32_t> order_;  // nodes, parents before children
};

}  // namespace prox::rig
