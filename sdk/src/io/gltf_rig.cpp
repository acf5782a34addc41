#include "io/gltf_rig.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

namespace prox::io::gltf_detail {
namespace {

using rig::Interpolation;
using rig::Mat4;
using rig::Path;

std::string named(const std::string& kind, std::size_t index, const std::string& name) {
  return kind + " " + std::to_string(index) + (name.empty() ? "" : " '" + name + "'");
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

bool all_finite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double x) { return std::isfinite(x); });
}

// The attributes of one JOINTS_n/WEIGHTS_n pair or morph target a primitive
// names, to compare primitives that share a POSITION accessor.
std::vector<int> rig_accessors(const tinygltf::Primitive& p) {
  std::vector<int> out;
  for (const auto& [attribute, accessor] : p.attributes)
    if (attribute.rfind("JOINTS_", 0) == 0 || attribute.rfind("WEIGHTS_", 0) == 0) out.push_back(accessor);
  out.push_back(-2);
  for (const auto& target : p.targets) {
    const auto it = target.find("POSITION");
    out.push_back(it == target.end() ? -1 : it->second);
  }
  return out;
}

class RigReader {
 public:
  RigReader(const tinygltf::Model& model, const std::string& name, std::vector<std::string>* warnings)
      : model_(model), name_(name), warnings_(warnings), reader_(model, name) {}

  Status run(const std::vector<LocalMesh>& meshes, const std::vector<MeshInstance>& instances,
             rig::Rig& rig) {
    Status status = read_nodes(rig);
    std::map<int, std::uint32_t> mesh_of, skin_of;
    for (std::size_t i = 0; status && i < instances.size(); ++i) {
      const MeshInstance& in = instances[i];
      const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(in.node)];
      auto found = mesh_of.find(in.mesh);
      if (found == mesh_of.end()) {
        found = mesh_of.emplace(in.mesh, static_cast<std::uint32_t>(rig.meshes.size())).first;
        rig.meshes.emplace_back();
        status = read_mesh(in.mesh, meshes[static_cast<std::size_t>(in.mesh)], rig.meshes.back());
        if (!status) break;
      }
      rig::Instance instance;
      instance.node = static_cast<std::uint32_t>(in.node);
      instance.mesh = found->second;
      instance.first_vertex = in.first;
      const rig::RigMesh& mesh = rig.meshes[found->second];
      if (node.skin != -1) {
        auto skin = skin_of.find(node.skin);
        if (skin == skin_of.end()) {
          skin = skin_of.emplace(node.skin, static_cast<std::uint32_t>(rig.skins.size())).first;
          rig.skins.emplace_back();
          status = read_skin(node.skin, rig.skins.back());
          if (!status) break;
        }
        instance.skin = static_cast<int>(skin->second);
        status = check_joints(in, rig.skins[skin->second].joints.size(), mesh);
        if (!status) break;
      }
      status = morph_weights(in, mesh.targets.size(), rig.nodes[static_cast<std::size_t>(in.node)].weights);
      rig.instances.push_back(instance);
      rig.vertex_count = in.first + static_cast<std::uint32_t>(mesh.positions.size());
    }
    for (std::size_t a = 0; status && a < model_.animations.size(); ++a) {
      rig.animations.emplace_back();
      status = read_animation(a, rig, rig.animations.back());
    }
    if (status && !rig.finalize(status)) return error(status.message());
    return status;
  }

 private:
  Status error(const std::string& message) const { return reader_.error(message); }
  void warn(const std::string& message) {
    if (warnings_ != nullptr) warnings_->push_back(name_ + ": " + message);
  }

  // Every node's local transform and parent (joints can lie outside the
  // scene); gltf.cpp has checked the scene's nodes the same way.
  Status read_nodes(rig::Rig& rig) {
    const std::size_t count = model_.nodes.size();
    rig.nodes.resize(count);
    for (std::size_t n = 0; n < count; ++n) {
      const tinygltf::Node& node = model_.nodes[n];
      rig::Node& out = rig.nodes[n];
      const std::string where = named("node", n, node.name);
      out.name = node.name;
      for (const int child : node.children) {
        if (child < 0 || static_cast<std::size_t>(child) >= count)
          return error(where + " has a child " + std::to_string(child) + " that does not exist");
        rig::Node& c = rig.nodes[static_cast<std::size_t>(child)];
        if (c.parent != -1)
          return error("node " + std::to_string(child) + " has two parents (nodes " +
                       std::to_string(c.parent) + " and " + std::to_string(n) + ")");
        c.parent = static_cast<int>(n);
      }
      if (!all_finite(node.matrix) || !all_finite(node.translation) || !all_finite(node.rotation) ||
          !all_finite(node.scale))
        return error(where + ": a transform has a non-finite value");
      if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) return error(where + ": matrix does not have 16 values");
        out.has_matrix = true;
        for (int c = 0; c < 4; ++c)
          for (int r = 0; r < 4; ++r) out.matrix[c][r] = node.matrix[static_cast<std::size_t>(4 * c + r)];
        out.matrix[0][3] = out.matrix[1][3] = out.matrix[2][3] = 0.0;  // affine (gltf.cpp checks it)
        out.matrix[3][3] = 1.0;
        continue;
      }
      if ((!node.translation.empty() && node.translation.size() != 3) ||
          (!node.rotation.empty() && node.rotation.size() != 4) ||
          (!node.scale.empty() && node.scale.size() != 3))
        return error(where + ": translation, rotation or scale has the wrong number of values");
      if (!node.translation.empty())
        out.rest.translation = {node.translation[0], node.translation[1], node.translation[2]};
      if (!node.rotation.empty())
        out.rest.rotation = {node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]};
      if (!node.scale.empty()) out.rest.scale = {node.scale[0], node.scale[1], node.scale[2]};
    }
    return Status::ok();
  }

  // Morph targets and skin influences of every primitive range.
  Status read_mesh(int index, const LocalMesh& local, rig::RigMesh& out) {
    const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(index)];
    out.positions = local.positions;
    std::size_t targets = 0, sets = 0;
    for (std::size_t k = 0; k < local.primitives.size(); ++k) {
      const tinygltf::Primitive& p = mesh.primitives[static_cast<std::size_t>(local.primitives[k].primitive)];
      if (k > 0 && p.targets.size() != targets)
        return error(named("mesh", static_cast<std::size_t>(index), mesh.name) + ": primitive " +
                     std::to_string(local.primitives[k].primitive) + " has " +
                     std::to_string(p.targets.size()) + " morph targets, primitive " +
                     std::to_string(local.primitives[0].primitive) + " has " + std::to_string(targets) +
                     " (glTF: every primitive has the same number)");
      targets = p.targets.size();
      std::size_t joints = 0, weights = 0;
      for (const auto& attribute : p.attributes) {
        joints += attribute.first.rfind("JOINTS_", 0) == 0;
        weights += attribute.first.rfind("WEIGHTS_", 0) == 0;
      }
      const std::string where = named("mesh", static_cast<std::size_t>(index), mesh.name) + " primitive " +
                                std::to_string(local.primitives[k].primitive);
      if (joints != weights)
        return error(where + " has " + std::to_string(joints) + " JOINTS_n and " + std::to_string(weights) +
                     " WEIGHTS_n attributes (glTF: as many of each)");
      for (std::size_t s = 0; s < joints; ++s)
        if (!p.attributes.count("JOINTS_" + std::to_string(s)) ||
            !p.attributes.count("WEIGHTS_" + std::to_string(s)))
          return error(where + " has no JOINTS_" + std::to_string(s) + " or WEIGHTS_" + std::to_string(s) +
                       " but " + std::to_string(joints) + " JOINTS_n (they are numbered from 0)");
      if (joints == 0 && lacking_joints_.count(index) == 0)
        lacking_joints_[index] = local.primitives[k].primitive;
      sets = std::max(sets, joints);
    }
    const std::size_t n = out.positions.size();
    // A few morph targets' accessors can be named by thousands of targets:
    // bound what they unfold to (2^26 deltas, 1.5 GiB).
    constexpr std::uint64_t kMaxDeltas = std::uint64_t{1} << 26;
    if (targets > 0 && std::uint64_t{n} * targets > kMaxDeltas)
      return {StatusCode::Unsupported,
              name_ + ": " + named("mesh", static_cast<std::size_t>(index), mesh.name) + ": " +
                  std::to_string(targets) + " morph targets of " + std::to_string(n) +
                  " vertices are more than the " + std::to_string(kMaxDeltas) + " deltas Proxima reads"};
    out.targets.assign(targets, std::vector<Vec3>(n, Vec3(0.0)));
    out.influences = static_cast<std::uint32_t>(4 * sets);
    out.joints.assign(n * out.influences, 0);
    out.weights.assign(n * out.influences, 0.0);
    std::map<std::uint32_t, int> first_primitive;  // range start -> the primitive that read it
    for (const PrimitiveRange& range : local.primitives) {
      const tinygltf::Primitive& p = mesh.primitives[static_cast<std::size_t>(range.primitive)];
      const auto [seen, fresh] = first_primitive.emplace(range.first, range.primitive);
      if (!fresh) {
        const tinygltf::Primitive& q = mesh.primitives[static_cast<std::size_t>(seen->second)];
        if (rig_accessors(p) != rig_accessors(q))
          return {StatusCode::Unsupported,
                  name_ + ": " + named("mesh", static_cast<std::size_t>(index), mesh.name) + ": primitives " +
                      std::to_string(seen->second) + " and " + std::to_string(range.primitive) +
                      " share their POSITION accessor but not their JOINTS_n, WEIGHTS_n or morph targets"};
        continue;
      }
      const std::string where = named("mesh", static_cast<std::size_t>(index), mesh.name) + " primitive " +
                                std::to_string(range.primitive);
      Status status = read_targets(p, range, where, out);
      if (status) status = read_influences(p, range, where, out);
      if (!status) return status;
    }
    if (targets > 0 && !mesh.weights.empty() && mesh.weights.size() != targets)
      return error(named("mesh", static_cast<std::size_t>(index), mesh.name) + ": weights has " +
                   std::to_string(mesh.weights.size()) + " values for " + std::to_string(targets) +
                   " morph targets");
    return Status::ok();
  }

  Status read_targets(const tinygltf::Primitive& p, const PrimitiveRange& range, const std::string& where,
                      rig::RigMesh& out) {
    std::vector<double> values;
    for (std::size_t t = 0; t < p.targets.size(); ++t) {
      const auto it = p.targets[t].find("POSITION");
      if (it == p.targets[t].end()) continue;  // no POSITION delta: zero
      const std::string what = where + " morph target " + std::to_string(t) + " POSITION";
      Status status = reader_.read(it->second, what, AccessorUse::MorphPosition, values);
      if (!status) return status;
      if (values.size() != 3 * std::size_t{range.count})
        return error(what + " accessor " + std::to_string(it->second) + ": " +
                     std::to_string(values.size() / 3) + " elements for the primitive's " +
                     std::to_string(range.count) + " vertices");
      if (!all_finite(values))
        return error(what + " accessor " + std::to_string(it->second) + ": a non-finite delta");
      for (std::uint32_t v = 0; v < range.count; ++v)
        out.targets[t][range.first + v] = Vec3(values[3 * v], values[3 * v + 1], values[3 * v + 2]);
    }
    return Status::ok();
  }

  // JOINTS_n and WEIGHTS_n, checked by glTF 2.0's rules.
  Status read_influences(const tinygltf::Primitive& p, const PrimitiveRange& range, const std::string& where,
                         rig::RigMesh& out) {
    std::size_t sets = 0;
    while (p.attributes.count("JOINTS_" + std::to_string(sets))) ++sets;
    if (sets == 0) return Status::ok();
    const std::size_t stride = out.influences;
    std::vector<double> joints, weights;
    std::vector<int> weight_types(sets);
    std::vector<int> weight_accessors(sets);
    for (std::size_t s = 0; s < sets; ++s) {
      const int ja = p.attributes.at("JOINTS_" + std::to_string(s));
      const int wa = p.attributes.at("WEIGHTS_" + std::to_string(s));
      const std::string jname = where + ": JOINTS_" + std::to_string(s);
      const std::string wname = where + ": WEIGHTS_" + std::to_string(s);
      Status status = reader_.read(ja, jname, AccessorUse::Joints, joints);
      if (status) status = reader_.read(wa, wname, AccessorUse::Weights, weights);
      if (!status) return status;
      if (joints.size() != 4 * std::size_t{range.count} || weights.size() != 4 * std::size_t{range.count})
        return error(where + ": JOINTS_" + std::to_string(s) + " accessor " + std::to_string(ja) +
                     " or WEIGHTS_" + std::to_string(s) + " accessor " + std::to_string(wa) +
                     " does not have one element per vertex (" + std::to_string(range.count) + ")");
      weight_types[s] = model_.accessors[static_cast<std::size_t>(wa)].componentType;
      weight_accessors[s] = wa;
      for (std::uint32_t v = 0; v < range.count; ++v)
        for (std::size_t c = 0; c < 4; ++c) {
          const double w = weights[4 * v + c];
          if (!(w >= 0.0))
            return error(wname + " accessor " + std::to_string(wa) + ": vertex " + std::to_string(v) +
                         " has weight " + number(w) + " (glTF: weights are not negative)");
          const std::size_t slot = (range.first + v) * stride + 4 * s + c;
          out.joints[slot] = static_cast<std::uint32_t>(joints[4 * v + c]);
          out.weights[slot] = w;
        }
    }
    // Normalized integers must sum to exactly 255 or 65535 (a MUST); floats
    // should sum to 1 and are normalized when they do not.
    const bool floats = std::any_of(weight_types.begin(), weight_types.end(),
                                    [](int t) { return t == TINYGLTF_COMPONENT_TYPE_FLOAT; });
    const bool same_type =
        std::all_of(weight_types.begin(), weight_types.end(), [&](int t) { return t == weight_types[0]; });
    std::size_t strayed = 0;
    std::uint32_t worst_vertex = 0;
    double worst_sum = 1.0;
    for (std::uint32_t v = 0; v < range.count; ++v) {
      double* w = &out.weights[(range.first + v) * stride];
      double sum = 0.0;
      for (std::size_t k = 0; k < 4 * sets; ++k) sum += w[k];
      if (!floats) {
        const double scale = weight_types[0] == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? 255.0 : 65535.0;
        if (same_type ? std::round(sum * scale) != scale : std::abs(sum - 1.0) > 1e-6)
          return error(where + ": WEIGHTS_0 accessor " + std::to_string(weight_accessors[0]) + ": vertex " +
                       std::to_string(v) + "'s normalized integer weights sum to " +
                       (same_type ? number(std::round(sum * scale)) + ", not " + number(scale)
                                  : number(sum) + ", not 1") +
                       " (glTF: they sum to 255 for UNSIGNED_BYTE, 65535 for UNSIGNED_SHORT)");
        continue;
      }
      if (std::abs(sum - 1.0) > kWeightTolerance) {
        if (strayed == 0 || std::abs(sum - 1.0) > std::abs(worst_sum - 1.0))
          worst_vertex = v, worst_sum = sum;
        ++strayed;
      }
      if (sum > 0.0) {
        for (std::size_t k = 0; k < 4 * sets; ++k) w[k] /= sum;
      } else {
        w[0] = 1.0;  // as three.js: the first joint alone
      }
    }
    if (strayed > 0)
      warn(where + ": WEIGHTS_0 accessor " + std::to_string(weight_accessors[0]) + ": the float weights of " +
           std::to_string(strayed) + " of " + std::to_string(range.count) +
           " vertices do not sum to 1 (vertex " + std::to_string(worst_vertex) + "'s sum to " +
           number(worst_sum) + "); each vertex's weights were divided by their sum");
    return Status::ok();
  }

  // Every joint a skinned instance's mesh names must be one of its skin's.
  Status check_joints(const MeshInstance& in, std::size_t joint_count, const rig::RigMesh& mesh) const {
    const tinygltf::Mesh& source = model_.meshes[static_cast<std::size_t>(in.mesh)];
    const std::string who = named("node", static_cast<std::size_t>(in.node),
                                  model_.nodes[static_cast<std::size_t>(in.node)].name);
    const auto lacking = lacking_joints_.find(in.mesh);
    if (lacking != lacking_joints_.end())
      return error(who + " has skin " + std::to_string(model_.nodes[static_cast<std::size_t>(in.node)].skin) +
                   " but " + named("mesh", static_cast<std::size_t>(in.mesh), source.name) + " primitive " +
                   std::to_string(lacking->second) + " has no JOINTS_0 and WEIGHTS_0");
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      for (std::size_t k = 0; k < mesh.influences; ++k) {
        const std::uint32_t j = mesh.joints[v * mesh.influences + k];
        if (j < joint_count) continue;
        // Name the accessor: find the primitive and set that hold vertex v.
        std::string accessor = "JOINTS_" + std::to_string(k / 4);
        for (const tinygltf::Primitive& p : source.primitives) {
          const auto it = p.attributes.find(accessor);
          if (it != p.attributes.end()) {
            accessor += " accessor " + std::to_string(it->second);
            break;
          }
        }
        return error(who + ": " + named("mesh", static_cast<std::size_t>(in.mesh), source.name) + " " +
                     accessor + ": a vertex has joint " + std::to_string(j) + ", but skin " +
                     std::to_string(model_.nodes[static_cast<std::size_t>(in.node)].skin) + " has " +
                     std::to_string(joint_count) + " joints (glTF: joints are in range)");
      }
    return Status::ok();
  }

  // The node's own weights, else its mesh's, else zeros.
  Status morph_weights(const MeshInstance& in, std::size_t targets, std::vector<double>& out) const {
    const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(in.node)];
    const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(in.mesh)];
    out.clear();
    if (targets == 0) return Status::ok();
    if (!node.weights.empty() && node.weights.size() != targets)
      return error(named("node", static_cast<std::size_t>(in.node), node.name) + ": weights has " +
                   std::to_string(node.weights.size()) + " values for its mesh's " + std::to_string(targets) +
                   " morph targets");
    out = !node.weights.empty()   ? node.weights
          : !mesh.weights.empty() ? mesh.weights
                                  : std::vector<double>(targets, 0.0);
    if (!all_finite(out))
      return error(named("node", static_cast<std::size_t>(in.node), node.name) +
                   ": a morph weight is not finite");
    return Status::ok();
  }

  Status read_skin(int index, rig::Skin& out) {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.skins.size())
      return error("skin " + std::to_string(index) + " does not exist (the file has " +
                   std::to_string(model_.skins.size()) + ")");
    const tinygltf::Skin& skin = model_.skins[static_cast<std::size_t>(index)];
    const std::string where = named("skin", static_cast<std::size_t>(index), skin.name);
    out.name = skin.name;
    if (skin.joints.empty()) return error(where + " has no joints");
    for (const int j : skin.joints) {
      if (j < 0 || static_cast<std::size_t>(j) >= model_.nodes.size())
        return error(where + ": joint " + std::to_string(j) + " is not a node (the file has " +
                     std::to_string(model_.nodes.size()) + ")");
      out.joints.push_back(static_cast<std::uint32_t>(j));
    }
    out.inverse_bind.assign(out.joints.size(), Mat4(1.0));
    if (skin.inverseBindMatrices == -1) return Status::ok();
    std::vector<double> values;
    const Status status = reader_.read(skin.inverseBindMatrices, where + ": inverseBindMatrices",
                                       AccessorUse::InverseBindMatrix, values);
    if (!status) return status;
    const std::string what =
        where + ": inverseBindMatrices accessor " + std::to_string(skin.inverseBindMatrices);
    if (values.size() < 16 * out.joints.size())
      return error(what + ": " + std::to_string(values.size() / 16) + " matrices for " +
                   std::to_string(out.joints.size()) + " joints");
    if (!all_finite(values)) return error(what + ": a non-finite value");
    for (std::size_t j = 0; j < out.joints.size(); ++j)
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
          out.inverse_bind[j][c][r] = values[16 * j + static_cast<std::size_t>(4 * c + r)];
    return Status::ok();
  }

  Status read_animation(std::size_t index, const rig::Rig& rig, rig::Animation& out) {
    const tinygltf::Animation& animation = model_.animations[index];
    const std::string where = named("animation", index, animation.name);
    out.name = animation.name.empty() ? "animation " + std::to_string(index) : animation.name;
    bool first = true;
    std::map<int, std::uint32_t> sampler_of;  // glTF sampler -> out.samplers
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
      const tinygltf::AnimationChannel& channel = animation.channels[c];
      const std::string at = where + " channel " + std::to_string(c);
      if (channel.target_node == -1) continue;  // targets something an extension names
      if (channel.target_node < 0 || static_cast<std::size_t>(channel.target_node) >= rig.nodes.size())
        return error(at + ": target node " + std::to_string(channel.target_node) + " does not exist");
      const rig::Node& node = rig.nodes[static_cast<std::size_t>(channel.target_node)];
      rig::Channel ch;
      ch.node = static_cast<std::uint32_t>(channel.target_node);
      AccessorUse use = AccessorUse::Vec3Output;
      if (channel.target_path == "translation") {
        ch.path = Path::Translation;
      } else if (channel.target_path == "rotation") {
        ch.path = Path::Rotation;
        use = AccessorUse::RotationOutput;
      } else if (channel.target_path == "scale") {
        ch.path = Path::Scale;
      } else if (channel.target_path == "weights") {
        ch.path = Path::Weights;
        use = AccessorUse::WeightsOutput;
        // Weights of a node no scene instance morphs change nothing.
        if (node.weights.empty()) continue;
      } else {
        warn(at + ": path '" + channel.target_path + "' is not animated (skipped)");
        continue;
      }
      if (ch.path != Path::Weights && node.has_matrix)
        return error(at + ": node " + std::to_string(channel.target_node) +
                     " has a matrix (glTF: an animated node has translation, rotation and scale)");
      if (channel.sampler < 0 || static_cast<std::size_t>(channel.sampler) >= animation.samplers.size())
        return error(at + ": sampler " + std::to_string(channel.sampler) + " does not exist");
      // Channels may share a sampler: it is read once, for the first, and
      // must fit every other (the same width).
      const std::uint32_t width = ch.path == Path::Rotation  ? 4
                                  : ch.path == Path::Weights ? static_cast<std::uint32_t>(node.weights.size())
                                                             : 3;
      const auto [known, fresh] =
          sampler_of.emplace(channel.sampler, static_cast<std::uint32_t>(out.samplers.size()));
      ch.sampler = known->second;
      if (fresh) {
        out.samplers.emplace_back();
        const Status status = read_sampler(animation, where, channel.sampler, use, width, channel.target_path,
                                           out.samplers.back());
        if (!status) return status;
      } else if (out.samplers[known->second].width != width) {
        return error(at + ": sampler " + std::to_string(channel.sampler) + " gives " +
                     std::to_string(out.samplers[known->second].width) +
                     " values per keyframe to an earlier "
                     "channel but " +
                     channel.target_path + " here needs " + std::to_string(width));
      }
      const rig::Sampler& s = out.samplers[known->second];
      out.start = first ? s.times.front() : std::min(out.start, s.times.front());
      out.end = first ? s.times.back() : std::max(out.end, s.times.back());
      first = false;
      out.channels.push_back(std::move(ch));
    }
    return Status::ok();
  }

  // Sampler `index` of `animation`, `width` values per keyframe (its output read for `use`).
  Status read_sampler(const tinygltf::Animation& animation, const std::string& where, int index,
                      AccessorUse use, std::uint32_t width, const std::string& path, rig::Sampler& s) const {
    const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<std::size_t>(index)];
    const std::string sat = where + " sampler " + std::to_string(index);
    if (sampler.interpolation == "LINEAR" || sampler.interpolation.empty())
      s.interpolation = Interpolation::Linear;
    else if (sampler.interpolation == "STEP")
      s.interpolation = Interpolation::Step;
    else if (sampler.interpolation == "CUBICSPLINE")
      s.interpolation = Interpolation::CubicSpline;
    else
      return error(sat + ": unknown interpolation '" + sampler.interpolation + "'");
    Status status = reader_.read(sampler.input, sat + ": input", AccessorUse::Time, s.times);
    if (status) status = reader_.read(sampler.output, sat + ": output", use, s.values);
    if (!status) return status;
    const std::string input = sat + ": input accessor " + std::to_string(sampler.input);
    if (s.times.empty()) return error(input + " has no keyframes");
    for (std::size_t k = 0; k < s.times.size(); ++k)
      if (!std::isfinite(s.times[k]) || s.times[k] < 0.0 || (k > 0 && !(s.times[k] > s.times[k - 1])))
        return error(input + ": keyframe " + std::to_string(k) + " at " + number(s.times[k]) +
                     " s (glTF: times are finite, not negative and strictly increasing)");
    s.width = width;
    const std::size_t groups = s.interpolation == Interpolation::CubicSpline ? 3 : 1;
    const std::size_t want = s.times.size() * groups * width;
    if (s.values.size() != want)
      return error(sat + ": output accessor " + std::to_string(sampler.output) + " has " +
                   std::to_string(s.values.size()) + " values; " + std::to_string(s.times.size()) +
                   " keyframes of " + path + " need " + std::to_string(want));
    if (!all_finite(s.values))
      return error(sat + ": output accessor " + std::to_string(sampler.output) + ": a non-finite value");
    return Status::ok();
  }

  // Float weights whose sum strays from 1 by more than float32 rounding over
  // a handful of terms are reported.
  static constexpr double kWeightTolerance = 1e-3;

  const tinygltf::Model& model_;
  const std::string& name_;
  std::vector<std::string>* warnings_;
  AccessorReader reader_;
  std::map<int, int> lacking_joints_;  // mesh -> its first triangle primitive without JOINTS_0
};

}  // namespace

bool has_rig(const tinygltf::Model& model, const std::vector<MeshInstance>& instances) {
  if (!model.animations.empty()) return true;
  for (const MeshInstance& in : instances) {
    if (model.nodes[static_cast<std::size_t>(in.node)].skin != -1) return true;
    for (const tinygltf::Primitive& p : model.meshes[static_cast<std::size_t>(in.mesh)].primitives)
      if (!p.targets.empty()) return true;
  }
  return false;
}

Status read_rig(const tinygltf::Model& model, const std::string& name, const std::vector<LocalMesh>& meshes,
                const std::vector<MeshInstance>& instances, std::vector<std::string>* warnings,
                std::shared_ptr<rig::Rig>& out) {
  auto rig = std::make_shared<rig::Rig>();
  const Status status = RigReader(model, name, warnings).run(meshes, instances, *rig);
  if (status) out = std::move(rig);
  return status;
}

}  // namespace prox::io::gltf_detail
