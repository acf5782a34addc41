#include "io/gltf.h"

#include "io/file.h"
#include "io/gltf_precheck.h"
// These include tinygltf's declarations; the implementation, below, is
// then included once (its part after the header guard is not guarded).
#include "io/gltf_accessor.h"
#include "io/gltf_rig.h"

// tinygltf is compiled here and nowhere else, without any image support: no
// stb_image, external images are not even opened, embedded ones go to a no-op
// callback. External buffers are read through the file callbacks below, not
// tinygltf's own. (TINYGLTF_NO_FS would drop those, but does not compile in
// 2.7.) Its header lives in a system include directory, so its warnings do not
// reach -Werror.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <new>
#include <set>
#include <system_error>
#include <utility>

namespace prox::io {
namespace {

using gltf_detail::AccessorReader;
using gltf_detail::AccessorUse;
using gltf_detail::check_glb;
using gltf_detail::component_size;
using gltf_detail::component_type_name;
using gltf_detail::GlbLayout;
using gltf_detail::kMaxU32;
using gltf_detail::LocalMesh;
using gltf_detail::MeshInstance;
using gltf_detail::precheck_json;
using gltf_detail::type_name;

// ---------------------------------------------------------------------------
// Files

// tinygltf's file system: external buffers only (images are never opened).
struct FsContext {
  std::string io_error;  // the first read failure, for an IoError
  bool allowed = true;   // GltfLoadOptions::external_buffers
};

// Always "exists", so that tinygltf tries only the path beside the .gltf (not
// the working directory) and the read below reports the real failure.
bool fs_file_exists(const std::string&, void*) { return true; }
std::string fs_expand_path(const std::string& path, void*) { return path; }
bool fs_read_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  auto* context = static_cast<FsContext*>(user);
  const Status status =
      context->allowed
          ? read_file(path, *out)
          : Status{StatusCode::IoError,
                   "the external buffer '" + std::filesystem::path(path).filename().string() +
                       "' cannot be read: glTF from memory must embed its buffers (data: URIs) or be a GLB"};
  if (status) return true;
  if (context->io_error.empty()) context->io_error = status.message();
  if (err != nullptr) *err += status.message() + "\n";
  return false;
}
bool fs_write_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err != nullptr) *err += "writing is disabled\n";
  return false;
}
// Images carry nothing Proxima uses: accept them undecoded.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                void*) {
  return true;
}

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

// ---------------------------------------------------------------------------
// The scene

class Decoder {
 public:
  Decoder(const tinygltf::Model& model, const std::string& name, std::vector<std::string>* warnings)
      : model_(model), name_(name), warnings_(warnings), reader_(model, name) {}

  Status run(GltfSceneMode mode, const std::string& stem, std::vector<GltfMesh>& out) {
    std::vector<int> roots;
    Status status = scene_roots(roots);
    if (!status) return status;
    meshes_.assign(model_.meshes.size(), LocalMesh{});
    std::vector<char> visited(model_.nodes.size(), 0);
    if (mode == GltfSceneMode::Merged) {
      out.emplace_back();
      out.back().name = stem;
    }

    // Depth first, in the file's order, without recursion (hierarchies can be
    // deep). Each entry holds its parent's world transform. Nodes are marked
    // when pushed, so the stack never holds more than every node once.
    std::vector<std::pair<int, glm::dmat4>> stack;
    const auto push = [&](int index, const glm::dmat4& parent) -> Status {
      if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size())
        return error("node " + std::to_string(index) + " does not exist (the file has " +
                     std::to_string(model_.nodes.size()) + " nodes)");
      if (visited[static_cast<std::size_t>(index)])
        return error(
            "node " + std::to_string(index) +
            " is reached twice from the scene: the node hierarchy has a cycle or a node with two parents");
      visited[static_cast<std::size_t>(index)] = 1;
      stack.emplace_back(index, parent);
      return Status::ok();
    };
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
      status = push(*it, glm::dmat4(1.0));
      if (!status) return status;
    }
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
      glm::dmat4 local;
      status = local_transform(index, local);
      if (!status) return status;
      const glm::dmat4 world = parent * local;
      if (node.mesh != -1) {
        status = instantiate(index, world, mode, out);
        if (!status) return status;
      }
      for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
        status = push(*it, world);
        if (!status) return status;
      }
    }

    std::size_t triangles = 0;
    for (const GltfMesh& mesh : out) triangles += mesh.indices.size() / 3;
    if (triangles == 0) {
      out.clear();
      return {StatusCode::Unsupported,
              name_ + ": the scene has no triangles (point and line primitives are not read)"};
    }
    return gltf_detail::has_rig(model_, instances_) ? pose_at_rest(mode, out) : Status::ok();
  }

 private:
  Status error(const std::string& message) const { return {StatusCode::ParseError, name_ + ": " + message}; }

  // The default scene, else scene 0, else (a file without scenes) every node
  // that is nobody's child.
  Status scene_roots(std::vector<int>& roots) const {
    if (!model_.scenes.empty()) {
      const int scene = model_.defaultScene != -1 ? model_.defaultScene : 0;
      if (scene < 0 || static_cast<std::size_t>(scene) >= model_.scenes.size())
        return error("the default scene " + std::to_string(scene) + " does not exist (the file has " +
                     std::to_string(model_.scenes.size()) + " scenes)");
      roots = model_.scenes[static_cast<std::size_t>(scene)].nodes;
      return Status::ok();
    }
    std::vector<char> is_child(model_.nodes.size(), 0);
    for (std::size_t i = 0; i < model_.nodes.size(); ++i)
      for (const int child : model_.nodes[i].children) {
        if (child < 0 || static_cast<std::size_t>(child) >= model_.nodes.size())
          return error("node " + std::to_string(i) + " has a child " + std::to_string(child) +
                       " that does not exist");
        is_child[static_cast<std::size_t>(child)] = 1;
      }
    for (std::size_t i = 0; i < model_.nodes.size(); ++i)
      if (!is_child[i]) roots.push_back(static_cast<int>(i));
    return Status::ok();
  }

  // glTF matrices are column-major, as glm's; TRS is T * R * S with the
  // rotation a unit quaternion (x, y, z, w), normalized here.
  Status local_transform(int index, glm::dmat4& m) const {
    const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
    const std::string where =
        "node " + std::to_string(index) + (node.name.empty() ? "" : " '" + node.name + "'");
    const auto finite = [](const std::vector<double>& v) {
      for (const double x : v)
        if (!std::isfinite(x)) return false;
      return true;
    };
    m = glm::dmat4(1.0);
    if (!node.matrix.empty()) {
      if (node.matrix.size() != 16)
        return error(where + ": matrix has " + std::to_string(node.matrix.size()) + " values; 16 are needed");
      if (!finite(node.matrix)) return error(where + ": matrix has a non-finite value");
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[static_cast<std::size_t>(4 * c + r)];
      // A node matrix must decompose into T * R * S, so its last row is
      // (0, 0, 0, 1); allow only rounding noise and then make it exact.
      constexpr double kTolerance = 1e-6;
      if (std::abs(m[0][3]) > kTolerance || std::abs(m[1][3]) > kTolerance ||
          std::abs(m[2][3]) > kTolerance || std::abs(m[3][3] - 1.0) > kTolerance)
        return error(where + ": matrix is not affine (its last row is not 0, 0, 0, 1)");
      m[0][3] = m[1][3] = m[2][3] = 0.0;
      m[3][3] = 1.0;
      return Status::ok();
    }
    const auto check = [&](const std::vector<double>& v, std::size_t n, const char* what) -> Status {
      if (!v.empty() && v.size() != n)
        return error(where + ": " + what + " has " + std::to_string(v.size()) + " values; " +
                     std::to_string(n) + " are needed");
      if (!finite(v)) return error(where + ": " + what + " has a non-finite value");
      return Status::ok();
    };
    Status status = check(node.translation, 3, "translation");
    if (status) status = check(node.rotation, 4, "rotation");
    if (status) status = check(node.scale, 3, "scale");
    if (!status) return status;
    glm::dvec3 scale(1.0);
    if (!node.scale.empty()) scale = {node.scale[0], node.scale[1], node.scale[2]};
    if (!node.rotation.empty()) {
      double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
      const double norm = std::sqrt(x * x + y * y + z * z + w * w);
      if (!(norm > 0.0) || !std::isfinite(norm))
        return error(where + ": rotation quaternion has zero or non-finite length");
      x /= norm, y /= norm, z /= norm, w /= norm;
      // Column c is the image of axis c.
      m[0] = glm::dvec4(1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0.0);
      m[1] = glm::dvec4(2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0.0);
      m[2] = glm::dvec4(2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0.0);
    }
    m[0] *= scale.x;
    m[1] *= scale.y;
    m[2] *= scale.z;
    if (!node.translation.empty())
      m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    return Status::ok();
  }

  // The mesh of node `index`, transformed by `world`, appended to `out`.
  Status instantiate(int index, const glm::dmat4& world, GltfSceneMode mode, std::vector<GltfMesh>& out) {
    const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
    if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= model_.meshes.size())
      return error("node " + std::to_string(index) + " refers to mesh " + std::to_string(node.mesh) +
                   ", which does not exist (the file has " + std::to_string(model_.meshes.size()) +
                   " meshes)");
    LocalMesh& mesh = meshes_[static_cast<std::size_t>(node.mesh)];
    if (!mesh.decoded) {
      const Status status = decode_mesh(node.mesh, mesh);
      if (!status) return status;
      mesh.decoded = true;
    }
    if (mesh.indices.empty()) return Status::ok();  // only points or lines

    if (mode == GltfSceneMode::PerNode) {
      out.emplace_back();
      const std::string& mesh_name = model_.meshes[static_cast<std::size_t>(node.mesh)].name;
      out.back().name = !node.name.empty()   ? node.name
                        : !mesh_name.empty() ? mesh_name
                                             : "node " + std::to_string(index);
    }
    GltfMesh& target = out.back();
    const std::size_t base = target.positions.size() / 3;
    instances_.push_back({index, node.mesh, static_cast<std::uint32_t>(flat_vertices_)});
    flat_vertices_ += mesh.positions.size();
    if (base == 0) {  // a fresh soup (per node); merged ones grow geometrically
      target.positions.reserve(3 * mesh.positions.size());
      target.indices.reserve(mesh.indices.size());
    }
    if (base + mesh.positions.size() > kMaxU32)
      return {StatusCode::Unsupported,
              name_ + ": the scene has more than 4294967295 vertices; load it per node"};
    for (const glm::dvec3& p : mesh.positions) {
      const glm::dvec4 q = world * glm::dvec4(p, 1.0);
      if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
        return error("node " + std::to_string(index) + ": a vertex of mesh " + std::to_string(node.mesh) +
                     " overflows to infinity under the node transforms");
      target.positions.insert(target.positions.end(), {q.x, q.y, q.z});
    }
    for (const std::uint32_t i : mesh.indices) target.indices.push_back(static_cast<std::uint32_t>(base + i));
    return Status::ok();
  }

  // A file with skins, morph targets or animations: its rig (gltf_rig.cpp)
  // poses the vertices at rest, replacing the node-transformed ones above.
  // That differs for skinned meshes (glTF ignores their node's transform and
  // places them by joint world x inverse bind matrix) and morphed ones (their
  // default weights). Merged: the soup keeps the rig.
  Status pose_at_rest(GltfSceneMode mode, std::vector<GltfMesh>& out) {
    if (flat_vertices_ > kMaxU32)
      return {StatusCode::Unsupported, name_ + ": a rigged scene has more than 4294967295 vertices"};
    std::shared_ptr<rig::Rig> rig;
    Status status = gltf_detail::read_rig(model_, name_, meshes_, instances_, warnings_, rig);
    if (!status) return status;
    std::vector<Vec3> rest;
    rig->positions(rig->rest_pose(), {}, rest);
    for (std::size_t i = 0; i < rig->instances.size(); ++i) {
      const rig::Instance& in = rig->instances[i];
      GltfMesh& target = out[mode == GltfSceneMode::Merged ? 0 : i];
      const std::size_t base = mode == GltfSceneMode::Merged ? in.first_vertex : 0;
      const std::size_t count = rig->meshes[in.mesh].positions.size();
      for (std::size_t v = 0; v < count; ++v) {
        const Vec3& p = rest[in.first_vertex + v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          return error("node " + std::to_string(in.node) +
                       ": a vertex of its mesh overflows to infinity at rest");
        std::copy(&p.x, &p.x + 3, target.positions.begin() + static_cast<std::ptrdiff_t>(3 * (base + v)));
      }
    }
    if (mode == GltfSceneMode::Merged) out[0].rig = std::move(rig);
    return Status::ok();
  }

  // Every triangle primitive of a mesh, in the mesh's coordinates, with
  // each primitive's vertex range (for the rig). A skinned mesh quantized by
  // KHR_mesh_quantization keeps its dequantization in the inverse bind
  // matrices; it comes out right only through the rig.
  Status decode_mesh(int mesh_index, LocalMesh& mesh) {
    const tinygltf::Mesh& source = model_.meshes[static_cast<std::size_t>(mesh_index)];
    // POSITION accessor -> (its first vertex in `mesh`, its vertex count).
    std::map<int, std::pair<std::uint32_t, std::size_t>> position_base;
    std::vector<double> values;
    std::vector<std::uint32_t> vertex;  // the primitive's vertex sequence
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = source.primitives[p];
      const std::string where = "mesh " + std::to_string(mesh_index) +
                                (source.name.empty() ? "" : " '" + source.name + "'") + " primitive " +
                                std::to_string(p);
      // POINTS (0), LINES (1), LINE_LOOP (2) and LINE_STRIP (3) have no
      // surface to touch: skipped without reading their accessors.
      if (primitive.mode >= TINYGLTF_MODE_POINTS && primitive.mode <= TINYGLTF_MODE_LINE_STRIP) continue;
      if (primitive.mode < TINYGLTF_MODE_TRIANGLES || primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN)
        return error(where + ": unknown mode " + std::to_string(primitive.mode));
      // glTF: a primitive without POSITION is not rendered; nothing to read.
      const auto position = primitive.attributes.find("POSITION");
      if (position == primitive.attributes.end()) continue;
      for (const auto& [attribute, accessor] : primitive.attributes)
        if (attribute != "POSITION") check_unused(attribute, accessor, where);

      // Primitives sharing a POSITION accessor share its vertices.
      auto found = position_base.find(position->second);
      if (found == position_base.end()) {
        const Status status =
            reader_.read(position->second, where + ": POSITION", AccessorUse::Position, values);
        if (!status) return status;
        const std::size_t count = values.size() / 3;
        if (mesh.positions.size() + count > kMaxU32)
          return {StatusCode::Unsupported,
                  name_ + ": " + where + ": more than 4294967295 vertices in one mesh"};
        for (std::size_t v = 0; v < count; ++v) {
          const glm::dvec3 x(values[3 * v], values[3 * v + 1], values[3 * v + 2]);
          if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z))
            return error(where + ": POSITION accessor " + std::to_string(position->second) + ": vertex " +
                         std::to_string(v) + " has a non-finite coordinate");
        }
        found = position_base
                    .emplace(position->second,
                             std::make_pair(static_cast<std::uint32_t>(mesh.positions.size()), count))
                    .first;
        for (std::size_t v = 0; v < count; ++v)
          mesh.positions.emplace_back(values[3 * v], values[3 * v + 1], values[3 * v + 2]);
      }
      const std::uint32_t base = found->second.first;
      const std::size_t vertex_count = found->second.second;
      mesh.primitives.push_back({static_cast<int>(p), base, static_cast<std::uint32_t>(vertex_count)});

      vertex.clear();
      if (primitive.indices != -1) {
        const Status status =
            reader_.read(primitive.indices, where + ": indices", AccessorUse::Index, values);
        if (!status) return status;
        vertex.reserve(values.size());
        for (std::size_t k = 0; k < values.size(); ++k) {
          if (values[k] >= static_cast<double>(vertex_count))
            return error(where + ": indices accessor " + std::to_string(primitive.indices) + ": index " +
                         std::to_string(static_cast<std::uint64_t>(values[k])) + " (entry " +
                         std::to_string(k) + ") is out of range: POSITION accessor " +
                         std::to_string(position->second) + " has " + std::to_string(vertex_count) +
                         " vertices");
          vertex.push_back(static_cast<std::uint32_t>(values[k]));
        }
      } else {
        vertex.resize(vertex_count);
        for (std::size_t k = 0; k < vertex_count; ++k) vertex[k] = static_cast<std::uint32_t>(k);
      }

      const std::size_t n = vertex.size();
      const auto add = [&](std::size_t a, std::size_t b, std::size_t c) {
        mesh.indices.insert(mesh.indices.end(), {base + vertex[a], base + vertex[b], base + vertex[c]});
      };
      switch (primitive.mode) {
        case TINYGLTF_MODE_TRIANGLES:
          if (n % 3 != 0)
            return error(where + ": " + std::to_string(n) + " vertices for TRIANGLES, not a multiple of 3");
          for (std::size_t i = 0; i < n; i += 3) add(i, i + 1, i + 2);
          break;
        case TINYGLTF_MODE_TRIANGLE_STRIP:  // every other triangle is reversed to keep the winding
          for (std::size_t i = 0; i + 2 < n; ++i) {
            if (i % 2 == 0)
              add(i, i + 1, i + 2);
            else
              add(i, i + 2, i + 1);
          }
          break;
        default:  // TRIANGLE_FAN
          for (std::size_t i = 0; i + 2 < n; ++i) add(i + 1, i + 2, 0);
          break;
      }
    }
    return Status::ok();
  }

  // An attribute Proxima does not read (NORMAL, TEXCOORD_0, ...): one that is
  // invalid is skipped, not an error, and reported once per accessor.
  void check_unused(const std::string& attribute, int index, const std::string& where) {
    if (warnings_ == nullptr || !warned_.insert(index).second) return;
    const std::string what = where + ": " + attribute + " accessor " + std::to_string(index);
    Status status;
    if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) {
      status = error(what + " does not exist (the file has " + std::to_string(model_.accessors.size()) + ")");
    } else {
      const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(index)];
      const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
      const std::size_t size = component_size(accessor.componentType);
      if (components <= 0 || size == 0) {
        status = error(what + ": " + type_name(accessor.type) + " of " +
                       component_type_name(accessor.componentType) + " is not a valid accessor type");
      } else if (accessor.bufferView != -1) {
        const std::size_t element = size * static_cast<std::size_t>(components);
        const unsigned char* data = nullptr;
        std::size_t length = 0;
        status = reader_.buffer_view(accessor.bufferView, what, data, length);
        if (status) {
          const std::size_t view_stride =
              model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)].byteStride;
          if (view_stride != 0 && view_stride < element)
            status = error(what + ": byteStride " + std::to_string(view_stride) + " is less than the " +
                           std::to_string(element) + "-byte element");
          else
            status = reader_.check_span(accessor.byteOffset, accessor.count,
                                        view_stride != 0 ? view_stride : element, element, length, what);
        }
      }
    }
    if (!status)
      warnings_->push_back(status.message() + " (skipped: Proxima reads only POSITION and indices)");
  }

  const tinygltf::Model& model_;
  const std::string& name_;
  std::vector<std::string>* warnings_;
  AccessorReader reader_;
  std::set<int> warned_;
  std::vector<LocalMesh> meshes_;
  std::vector<MeshInstance> instances_;  // in `out`'s order, for the rig
  std::uint64_t flat_vertices_ = 0;      // over every instance (the merged soup's count)
};

// `path` names the file in messages and gives its extension, stem and the
// directory external buffers are read from.
Status load(std::vector<unsigned char>& bytes, const std::string& path, const GltfLoadOptions& options,
            std::vector<GltfMesh>& out, std::vector<std::string>* warnings) {
  Status status;
  // Binary or text by content: a GLB starts with the magic "glTF".
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  const std::filesystem::path fs_path(path);
  std::string extension = fs_path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!binary && extension == ".glb")
    return {StatusCode::ParseError, path + ": not a GLB file (no 'glTF' magic at the start)"};

  GlbLayout glb;
  const char* json = reinterpret_cast<const char*>(bytes.data());
  std::size_t json_size = bytes.size();
  if (binary) {
    status = check_glb(bytes, path, glb);
    if (!status) return status;
    json += glb.json_offset;
    json_size = glb.json_size;
  }
  if (json_size > kMaxU32) return {StatusCode::Unsupported, path + ": JSON larger than 4 GiB"};
  status = precheck_json(json, json_size, path);
  if (!status) return status;

  FsContext fs_context;
  fs_context.allowed = options.external_buffers;
  tinygltf::TinyGLTF reader;
  reader.SetFsCallbacks({&fs_file_exists, &fs_expand_path, &fs_read_file, &fs_write_file, &fs_context});
  reader.SetImageLoader(&skip_image, nullptr);
  tinygltf::Model model;
  std::string err;
  std::string warn;
  std::string base_dir = fs_path.parent_path().string();
  if (base_dir.empty()) base_dir = ".";
  const bool loaded = binary ? reader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                           static_cast<unsigned>(glb.length), base_dir)
                             : reader.LoadASCIIFromString(&model, &err, &warn, json,
                                                          static_cast<unsigned>(json_size), base_dir);
  if (!loaded) {
    if (!fs_context.io_error.empty()) return {StatusCode::IoError, path + ": " + fs_context.io_error};
    return {StatusCode::ParseError, path + ": " + (err.empty() ? std::string("tinygltf failed") : trim(err))};
  }
  bytes = {};  // tinygltf keeps its own copy of the buffers

  return Decoder(model, path, warnings).run(options.mode, fs_path.stem().string(), out);
}

}  // namespace

Status load_gltf(const std::string& path, const GltfLoadOptions& options, std::vector<GltfMesh>& out,
                 std::vector<std::string>* warnings) {
  out.clear();
  if (warnings != nullptr) warnings->clear();
  std::vector<unsigned char> bytes;
  const Status status = read_file(path, bytes);
  if (!status) return status;
  return load_gltf_bytes(std::move(bytes), path, options, out, warnings);
}

Status load_gltf_bytes(std::vector<unsigned char> bytes, const std::string& path,
                       const GltfLoadOptions& options, std::vector<GltfMesh>& out,
                       std::vector<std::string>* warnings) {
  out.clear();
  if (warnings != nullptr) warnings->clear();
  Status status;
  try {
    status = load(bytes, path, options, out, warnings);
  } catch (const std::bad_alloc&) {
    status = {StatusCode::ParseError, path + ": out of memory (sizes in the file are too large)"};
  } catch (const std::exception& e) {
    // tinygltf 2.7 can throw on malformed input (e.g. std::out_of_range for a
    // GLB buffer of byteLength 0).
    status = {StatusCode::ParseError, path + ": malformed glTF (" + e.what() + ")"};
  }
  if (!status) {
    out.clear();
    if (warnings != nullptr) warnings->clear();
  }
  return status;
}

}  // namespace prox::io
