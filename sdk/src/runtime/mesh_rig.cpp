#include "runtime/mesh_rig.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace prox::runtime {
namespace {

Status invalid(std::string message) { return {StatusCode::InvalidArgument, std::move(message)}; }

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

}  // namespace

MeshRig::MeshRig(std::shared_ptr<const rig::Rig> rig)
    : rig_(std::move(rig)), pose_(rig_->rest_pose()), joint_worlds_(rig_->skins.size()) {}

bool MeshRig::animate(std::int64_t animation, double seconds, Status& status) {
  const std::size_t count = rig_->animations.size();
  if (animation < 0 || static_cast<std::uint64_t>(animation) >= count) {
    status = invalid("animation " + std::to_string(animation) + " does not exist (the mesh has " +
                     std::to_string(count) + ")");
    return false;
  }
  if (!std::isfinite(seconds)) {
    status = invalid("seconds is " + number(seconds));
    return false;
  }
  pose_ = rig_->rest_pose();
  rig_->animate(static_cast<std::size_t>(animation), seconds, pose_);
  for (auto& m : joint_worlds_) m.clear();
  status = Status::ok();
  return true;
}

bool MeshRig::set_joint_matrices(std::int64_t skin, const double* matrices, std::int64_t count,
                                 Status& status) {
  const std::size_t skins = rig_->skins.size();
  if (skin < 0 || static_cast<std::uint64_t>(skin) >= skins) {
    status = invalid("skin " + std::to_string(skin) + " does not exist (the mesh has " +
                     std::to_string(skins) + ")");
    return false;
  }
  const std::size_t joints = rig_->skins[static_cast<std::size_t>(skin)].joints.size();
  if (count < 0 || static_cast<std::uint64_t>(count) != joints) {
    status = invalid("count is " + std::to_string(count) + " but skin " + std::to_string(skin) + " has " +
                     std::to_string(joints) + " joints (one matrix each)");
    return false;
  }
  if (matrices == nullptr) {
    status = invalid("matrices is NULL");
    return false;
  }
  std::vector<rig::Mat4> m(joints);
  for (std::size_t j = 0; j < joints; ++j) {
    const double* a = matrices + 16 * j;
    for (int e = 0; e < 16; ++e)
      if (!std::isfinite(a[e])) {
        status = invalid("matrices[" + std::to_string(j) + "] (joint " + std::to_string(j) + ") element " +
                         std::to_string(e) + " (column " + std::to_string(e / 4) + ", row " +
                         std::to_string(e % 4) + ") is " + number(a[e]));
        return false;
      }
    // Column-major: the last row is elements 3, 7, 11, 15.
    constexpr double kTolerance = 1e-6;
    if (std::abs(a[3]) > kTolerance || std::abs(a[7]) > kTolerance || std::abs(a[11]) > kTolerance ||
        std::abs(a[15] - 1.0) > kTolerance) {
      status = invalid("matrices[" + std::to_string(j) + "] (joint " + std::to_string(j) +
                       ") is not affine: its last row (elements 3, 7, 11, 15 in column-major order) is " +
                       number(a[3]) + ", " + number(a[7]) + ", " + number(a[11]) + ", " + number(a[15]) +
                       ", not 0, 0, 0, 1");
      return false;
    }
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[j][c][r] = a[4 * c + r];
    m[j][0][3] = m[j][1][3] = m[j][2][3] = 0.0;
    m[j][3][3] = 1.0;
  }
  joint_worlds_[static_cast<std::size_t>(skin)] = std::move(m);
  status = Status::ok();
  return true;
}

bool MeshRig::set_morph_weights(const double* weights, std::int64_t count, Status& status) {
  const std::uint32_t want = rig_->morph_weight_count();
  if (count < 0 || static_cast<std::uint64_t>(count) != want) {
    status = invalid("count is " + std::to_string(count) + " but the mesh has " + std::to_string(want) +
                     " morph weights");
    return false;
  }
  if (weights == nullptr && count > 0) {
    status = invalid("weights is NULL");
    return false;
  }
  for (std::int64_t i = 0; i < count; ++i)
    if (!std::isfinite(weights[i])) {
      status = invalid("weights[" + std::to_string(i) + "] is " + number(weights[i]));
      return false;
    }
  rig_->set_morph_weights(weights, pose_);
  status = Status::ok();
  return true;
}

void MeshRig::welded_positions(const Mesh& mesh, std::vector<Vec3>& out) const {
  std::vector<Vec3> input;
  rig_->positions(pose_, joint_worlds_, input);
  out.assign(mesh.vertex_count(), Vec3(0.0));
  std::vector<char> set(mesh.vertex_count(), 0);
  const std::uint32_t n = std::min<std::uint32_t>(mesh.input_vertex_count(), rig_->vertex_count);
  for (std::uint32_t v = 0; v < n; ++v) {
    const std::uint32_t w = mesh.welded_vertex(v);
    if (w == kNoVertex || set[w]) continue;  // the first input vertex wins
    set[w] = 1;
    out[w] = input[v];
  }
}

}  // namespace prox::runtime
