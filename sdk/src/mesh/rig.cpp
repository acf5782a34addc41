#include "mesh/rig.h"

#include <algorithm>
#include <cmath>

namespace prox::rig {
namespace {

Status invalid(std::string message) { return {StatusCode::InvalidArgument, "rig: " + std::move(message)}; }

Quat normalized(const Quat& q) {
  const double n = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  return n > 0.0 && std::isfinite(n) ? q / n : Quat(0.0, 0.0, 0.0, 1.0);
}

double dot4(const Quat& a, const Quat& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

Vec3 transform_point(const Mat4& m, const Vec3& p) {
  return Vec3(m[0][0] * p.x + m[1][0] * p.y + m[2][0] * p.z + m[3][0],
              m[0][1] * p.x + m[1][1] * p.y + m[2][1] * p.z + m[3][1],
              m[0][2] * p.x + m[1][2] * p.y + m[2][2] * p.z + m[3][2]);
}

}  // namespace

Mat4 trs_matrix(const Trs& trs) {
  const Quat q = normalized(trs.rotation);
  const double x = q.x, y = q.y, z = q.z, w = q.w;
  Mat4 m(1.0);
  // Column c is the image of axis c.
  m[0] = glm::dvec4(1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0.0) * trs.scale.x;
  m[1] = glm::dvec4(2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0.0) * trs.scale.y;
  m[2] = glm::dvec4(2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0.0) * trs.scale.z;
  m[3] = glm::dvec4(trs.translation, 1.0);
  return m;
}

Quat slerp(const Quat& a, const Quat& b_in, double t) {
  Quat b = b_in;
  double d = dot4(a, b);
  if (d < 0.0) {  // the shorter arc
    b = -b;
    d = -d;
  }
  if (d > 1.0 - 1e-6) return normalized(a + t * (b - a));
  const double theta = std::acos(std::min(d, 1.0));
  const double s = std::sin(theta);
  return (std::sin((1.0 - t) * theta) / s) * a + (std::sin(t * theta) / s) * b;
}

void sample(const Sampler& s, double t, bool rotation, double* out) {
  const std::size_t n = s.times.size();
  const std::size_t w = s.width;
  const bool cubic = s.interpolation == Interpolation::CubicSpline;
  const std::size_t stride = cubic ? 3 * w : w;
  const std::size_t offset = cubic ? w : 0;  // the value within a keyframe's group
  const auto value = [&](std::size_t k) { return s.values.data() + k * stride + offset; };
  const auto finish = [&] {
    if (!rotation) return;
    const Quat q = normalized(Quat(out[0], out[1], out[2], out[3]));
    out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
  };
  if (n == 0) return;
  if (!(t > s.times.front()) || n == 1) {  // also NaN
    std::copy(value(0), value(0) + w, out);
    return finish();
  }
  if (t >= s.times.back()) {
    std::copy(value(n - 1), value(n - 1) + w, out);
    return finish();
  }
  // The keyframe k with times[k] <= t < times[k + 1].
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(s.times.begin(), s.times.end(), t) - s.times.begin()) - 1;
  const double t0 = s.times[k], t1 = s.times[k + 1];
  const double td = t1 - t0;
  const double u = (t - t0) / td;
  const double* v0 = value(k);
  const double* v1 = value(k + 1);
  switch (s.interpolation) {
    case Interpolation::Step:
      std::copy(v0, v0 + w, out);
      break;
    case Interpolation::Linear:
      if (rotation) {
        const Quat q = slerp(Quat(v0[0], v0[1], v0[2], v0[3]), Quat(v1[0], v1[1], v1[2], v1[3]), u);
        out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
      } else {
        for (std::size_t c = 0; c < w; ++c) out[c] = v0[c] + u * (v1[c] - v0[c]);
      }
      break;
    case Interpolation::CubicSpline: {
      const double* b0 = v0 + w;  // out-tangent of k
      const double* a1 = v1 - w;  // in-tangent of k + 1
      const double u2 = u * u, u3 = u2 * u;
      const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
      for (std::size_t c = 0; c < w; ++c)
        out[c] = h00 * v0[c] + td * h10 * b0[c] + h01 * v1[c] + td * h11 * a1[c];
      break;
    }
  }
  finish();
}

bool Rig::finalize(Status& status) {
  const std::size_t node_count = nodes.size();
  for (std::size_t n = 0; n < node_count; ++n)
    if (nodes[n].parent < -1 || nodes[n].parent >= static_cast<int>(node_count)) {
      status = invalid("node " + std::to_string(n) + " has parent " + std::to_string(nodes[n].parent) +
                       ", past the " + std::to_string(node_count) + " nodes");
      return false;
    }
  // Parents first: a node is placed once its parent is; what is never placed
  // sits on a cycle.
  std::vector<std::vector<std::uint32_t>> children(node_count);
  order_.clear();
  for (std::size_t n = 0; n < node_count; ++n) {
    if (nodes[n].parent == -1)
      order_.push_back(static_cast<std::uint32_t>(n));
    else
      children[static_cast<std::size_t>(nodes[n].parent)].push_back(static_cast<std::uint32_t>(n));
  }
  for (std::size_t i = 0; i < order_.size(); ++i)
    for (const std::uint32_t c : children[order_[i]]) order_.push_back(c);
  if (order_.size() != node_count) {
    status = invalid(std::to_string(node_count - order_.size()) + " nodes are on a cycle of parents");
    return false;
  }
  for (std::size_t s = 0; s < skins.size(); ++s) {
    const Skin& skin = skins[s];
    if (skin.inverse_bind.size() != skin.joints.size()) {
      status = invalid("skin " + std::to_string(s) + " has " + std::to_string(skin.joints.size()) +
                       " joints but " + std::to_string(skin.inverse_bind.size()) + " inverse bind matrices");
      return false;
    }
    for (const std::uint32_t j : skin.joints)
      if (j >= node_count) {
        status = invalid("skin " + std::to_string(s) + " has joint node " + std::to_string(j) +
                         ", past the " + std::to_string(node_count) + " nodes");
        return false;
      }
  }
  std::uint64_t vertices = 0;
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const Instance& in = instances[i];
    const std::string what = "instance " + std::to_string(i);
    if (in.node >= node_count || in.mesh >= meshes.size() || in.skin >= static_cast<int>(skins.size())) {
      status = invalid(what + " refers to a node, mesh or skin that does not exist");
      return false;
    }
    const RigMesh& m = meshes[in.mesh];
    if (in.first_vertex != vertices) {
      status = invalid(what + " starts at vertex " + std::to_string(in.first_vertex) + ", not " +
                       std::to_string(vertices));
      return false;
    }
    vertices += m.positions.size();
    if (nodes[in.node].weights.size() != m.targets.size()) {
      status = invalid(what + ": node " + std::to_string(in.node) + " has " +
                       std::to_string(nodes[in.node].weights.size()) + " morph weights for " +
                       std::to_string(m.targets.size()) + " morph targets");
      return false;
    }
    if (in.skin >= 0) {
      const std::size_t joints = skins[static_cast<std::size_t>(in.skin)].joints.size();
      if (m.influences == 0) {
        status = invalid(what + " is skinned but its mesh has no joints and weights");
        return false;
      }
      for (const std::uint32_t j : m.joints)
        if (j >= joints) {
          status = invalid(what + ": joint " + std::to_string(j) + " is past skin " +
                           std::to_string(in.skin) + "'s " + std::to_string(joints) + " joints");
          return false;
        }
    }
  }
  if (vertices != vertex_count) {
    status = invalid("the instances hold " + std::to_string(vertices) + " vertices, not " +
                     std::to_string(vertex_count));
    return false;
  }
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const RigMesh& mesh = meshes[m];
    const std::size_t n = mesh.positions.size();
    bool ok = mesh.joints.size() == n * mesh.influences && mesh.weights.size() == n * mesh.influences;
    for (const auto& target : mesh.targets) ok = ok && target.size() == n;
    if (!ok) {
      status = invalid("mesh " + std::to_string(m) +
                       "'s joints, weights or morph targets do not have one "
                       "entry per vertex");
      return false;
    }
  }
  for (std::size_t a = 0; a < animations.size(); ++a)
    for (std::size_t c = 0; c < animations[a].channels.size(); ++c) {
      const Channel& ch = animations[a].channels[c];
      const std::string what = "animation " + std::to_string(a) + " channel " + std::to_string(c);
      if (ch.node >= node_count || ch.sampler >= animations[a].samplers.size()) {
        status = invalid(what + " refers to a node or sampler that does not exist");
        return false;
      }
      const Sampler& s = animations[a].samplers[ch.sampler];
      const std::size_t width = ch.path == Path::Rotation  ? 4
                                : ch.path == Path::Weights ? nodes[ch.node].weights.size()
                                                           : 3;
      const std::size_t groups = s.interpolation == Interpolation::CubicSpline ? 3 : 1;
      if (s.width != width || s.times.empty() || s.values.size() != s.times.size() * groups * width ||
          (ch.path != Path::Weights && nodes[ch.node].has_matrix)) {
        status = invalid(what + " does not fit its node or its sampler's sizes");
        return false;
      }
    }
  status = Status::ok();
  return true;
}

Pose Rig::rest_pose() const {
  Pose pose;
  pose.local.reserve(nodes.size());
  pose.weights.reserve(nodes.size());
  for (const Node& node : nodes) {
    pose.local.push_back(node.rest);
    pose.weights.push_back(node.weights);
  }
  return pose;
}

void Rig::animate(std::size_t a, double seconds, Pose& pose) const {
  double value[4];
  std::vector<double> weights;
  for (const Channel& ch : animations[a].channels) {
    const Sampler& sampler = animations[a].samplers[ch.sampler];
    Trs& trs = pose.local[ch.node];
    switch (ch.path) {
      case Path::Translation:
        sample(sampler, seconds, false, value);
        trs.translation = Vec3(value[0], value[1], value[2]);
        break;
      case Path::Rotation:
        sample(sampler, seconds, true, value);
        trs.rotation = Quat(value[0], value[1], value[2], value[3]);
        break;
      case Path::Scale:
        sample(sampler, seconds, false, value);
        trs.scale = Vec3(value[0], value[1], value[2]);
        break;
      case Path::Weights:
        weights.resize(sampler.width);
        sample(sampler, seconds, false, weights.data());
        pose.weights[ch.node] = weights;
        break;
    }
  }
}

std::vector<Mat4> Rig::world_matrices(const Pose& pose) const {
  std::vector<Mat4> world(nodes.size(), Mat4(1.0));
  for (const std::uint32_t n : order_) {
    const Node& node = nodes[n];
    const Mat4 local = node.has_matrix ? node.matrix : trs_matrix(pose.local[n]);
    world[n] = node.parent == -1 ? local : world[static_cast<std::size_t>(node.parent)] * local;
  }
  return world;
}

void Rig::positions(const Pose& pose, const std::vector<std::vector<Mat4>>& joint_worlds,
                    std::vector<Vec3>& out) const {
  const std::vector<Mat4> world = world_matrices(pose);
  // Per skin: joint world x inverse bind matrix.
  std::vector<std::vector<Mat4>> skinning(skins.size());
  for (std::size_t s = 0; s < skins.size(); ++s) {
    const Skin& skin = skins[s];
    const bool given = s < joint_worlds.size() && !joint_worlds[s].empty();
    skinning[s].resize(skin.joints.size());
    for (std::size_t j = 0; j < skin.joints.size(); ++j)
      skinning[s][j] = (given ? joint_worlds[s][j] : world[skin.joints[j]]) * skin.inverse_bind[j];
  }
  out.resize(vertex_count);
  for (const Instance& in : instances) {
    const RigMesh& mesh = meshes[in.mesh];
    const std::vector<double>& weights = pose.weights[in.node];
    const std::size_t targets = std::min(weights.size(), mesh.targets.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      Vec3 p = mesh.positions[v];
      for (std::size_t t = 0; t < targets; ++t)
        if (weights[t] != 0.0) p += weights[t] * mesh.targets[t][v];
      Vec3& q = out[in.first_vertex + v];
      if (in.skin < 0) {
        q = transform_point(world[in.node], p);
        continue;
      }
      const std::vector<Mat4>& m = skinning[static_cast<std::size_t>(in.skin)];
      q = Vec3(0.0);
      for (std::size_t k = 0; k < mesh.influences; ++k) {
        const double w = mesh.weights[v * mesh.influences + k];
        if (w != 0.0) q += w * transform_point(m[mesh.joints[v * mesh.influences + k]], p);
      }
    }
  }
}

std::uint32_t Rig::morph_weight_count() const {
  std::size_t count = 0;
  for (const Instance& in : instances) count += nodes[in.node].weights.size();
  return static_cast<std::uint32_t>(count);
}

void Rig::set_morph_weights(const double* weights, Pose& pose) const {
  for (const Instance& in : instances) {
    std::vector<double>& w = pose.weights[in.node];
    w.assign(weights, weights + nodes[in.node].weights.size());
    weights += w.size();
  }
}

}  // namespace prox::rig
