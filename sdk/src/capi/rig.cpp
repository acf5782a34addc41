// glTF skins, morph targets and animation: what a rigged mesh holds, and
// posing it (its vertices replaced through World::set_vertices).
#include "capi/rig.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace prox;
using namespace prox::capi;

namespace prox::capi {

void attach_rig(runtime::World& world, const proxMeshId& id, std::shared_ptr<const rig::Rig> rig) {
  const runtime::Handle h{id.index1 - 1, id.generation};
  Status status;
  if (world.set_rig(h, std::move(rig), status)) return;
  Status ignored;
  world.destroy_mesh(h, ignored);
  fail(PROX_ERROR_INTERNAL, "the mesh's rig does not fit its vertices: " + status.message());
}

}  // namespace prox::capi

namespace {

const rig::Rig* rig_of(const runtime::World& w, runtime::Handle h) {
  const runtime::MeshRig* r = w.rig(h);
  return r ? &r->rig() : nullptr;
}

void copy_name(const std::string& name, char (&out)[64]) {
  const std::size_t n = std::min(name.size(), sizeof out - 1);
  std::memcpy(out, name.data(), n);
  out[n] = '\0';
}

// A rigged mesh's rig for posing, checked as proxMesh_SetVertices checks.
runtime::MeshRig& posable(runtime::World& w, runtime::Handle h) {
  runtime::MeshRig* r = w.rig(h);
  if (!r)
    fail(PROX_ERROR_INVALID_ARGUMENT,
         "the mesh has no rig (it was not loaded from a glTF scene with skins, morph targets or animations)");
  return *r;
}

// Runs `change` on the rig, then moves the mesh's vertices to its new pose;
// on any failure the rig keeps its pose and the mesh its vertices.
template <typename Change>
void pose(runtime::World& w, runtime::Handle h, Change&& change) {
  runtime::MeshRig& r = posable(w, h);
  const runtime::MeshRig before = r;
  Status status;
  if (!change(r, status)) fail(PROX_ERROR_INVALID_ARGUMENT, status.message());
  std::vector<Vec3> positions;
  r.welded_positions(w.mesh(h), positions);
  for (std::size_t v = 0; v < positions.size(); ++v)
    for (int c = 0; c < 3; ++c)
      if (!(std::abs(positions[v][c]) <= kMaxCoordinate)) {
        r = before;
        char value[32];
        std::snprintf(value, sizeof value, "%g", positions[v][c]);
        fail(PROX_ERROR_INVALID_ARGUMENT, "the pose puts vertex " + std::to_string(v) +
                                              " at a coordinate of " + value +
                                              ", beyond the +-1e50 Proxima supports");
      }
  if (!w.set_vertices(h, positions, status)) {
    r = before;
    fail(PROX_ERROR_INVALID_ARGUMENT, status.message());
  }
}

}  // namespace

extern "C" {

proxResult proxMesh_GetRigInfo(proxMeshId mesh, proxRigInfo* info) {
  return guard("proxMesh_GetRigInfo", [&] {
    need(info, "info");
    *info = proxRigInfo{};
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    const rig::Rig* r = rig_of(*w, h);
    if (!r) return;
    std::size_t joints = 0;
    for (const rig::Skin& s : r->skins) joints += s.joints.size();
    *info = {static_cast<int32_t>(r->skins.size()), static_cast<int32_t>(joints),
             static_cast<int32_t>(r->morph_weight_count()), static_cast<int32_t>(r->animations.size())};
  });
}

proxResult proxMesh_GetSkinInfo(proxMeshId mesh, int32_t skin, proxSkinInfo* info) {
  return guard("proxMesh_GetSkinInfo", [&] {
    need(info, "info");
    *info = proxSkinInfo{};
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    const rig::Rig* r = rig_of(*w, h);
    const std::size_t count = r ? r->skins.size() : 0;
    if (skin < 0 || static_cast<std::size_t>(skin) >= count)
      fail(PROX_ERROR_INVALID_ARGUMENT,
           "skin " + std::to_string(skin) + " does not exist (the mesh has " + std::to_string(count) + ")");
    const rig::Skin& s = r->skins[static_cast<std::size_t>(skin)];
    copy_name(s.name, info->name);
    info->jointCount = static_cast<int32_t>(s.joints.size());
  });
}

proxResult proxMesh_GetAnimationCount(proxMeshId mesh, int32_t* count) {
  return guard("proxMesh_GetAnimationCount", [&] {
    need(count, "count");
    *count = 0;
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    const rig::Rig* r = rig_of(*w, h);
    *count = r ? static_cast<int32_t>(r->animations.size()) : 0;
  });
}

proxResult proxMesh_GetAnimationInfo(proxMeshId mesh, int32_t index, proxAnimationInfo* info) {
  return guard("proxMesh_GetAnimationInfo", [&] {
    need(info, "info");
    *info = proxAnimationInfo{};
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    const rig::Rig* r = rig_of(*w, h);
    const std::size_t count = r ? r->animations.size() : 0;
    if (index < 0 || static_cast<std::size_t>(index) >= count)
      fail(PROX_ERROR_INVALID_ARGUMENT, "index " + std::to_string(index) +
                                            " names no animation (the mesh has " + std::to_string(count) +
                                            ")");
    const rig::Animation& a = r->animations[static_cast<std::size_t>(index)];
    copy_name(a.name, info->name);
    info->duration = a.end;
    info->start = a.start;
    info->channelCount = static_cast<int32_t>(a.channels.size());
  });
}

proxResult proxMesh_Animate(proxMeshId mesh, int32_t animation, double seconds) {
  return guard("proxMesh_Animate", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    pose(*w, h, [&](runtime::MeshRig& r, Status& s) { return r.animate(animation, seconds, s); });
  });
}

proxResult proxMesh_SetJointMatrices(proxMeshId mesh, int32_t skin, const double* matrices, int32_t count) {
  return guard("proxMesh_SetJointMatrices", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    pose(*w, h,
         [&](runtime::MeshRig& r, Status& s) { return r.set_joint_matrices(skin, matrices, count, s); });
  });
}

proxResult proxMesh_SetMorphWeights(proxMeshId mesh, const double* weights, int32_t count) {
  return guard("proxMesh_SetMorphWeights", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    pose(*w, h, [&](runtime::MeshRig& r, Status& s) { return r.set_morph_weights(weights, count, s); });
  });
}

}  // extern "C"
