#include "support/scenes.h"

#include "io/obj.h"
#if PROX_WITH_GLTF
#include "io/gltf.h"
#endif

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace prox::testing {

std::string asset_path(const std::string& relative) {
  return std::string(PROX_SHARED_ASSETS_DIR) + "/" + relative;
}

std::shared_ptr<const Model> model_from_arrays(const std::vector<double>& positions,
                                               const std::vector<std::uint32_t>& indices) {
  MeshInput input{positions.data(), static_cast<std::uint32_t>(positions.size() / 3), indices.data(),
                  static_cast<std::uint32_t>(indices.size() / 3)};
  Status status;
  auto model = std::make_shared<Model>();
  model->mesh = Mesh::build(input, status);
  EXPECT_TRUE(status.is_ok()) << status.message();
  if (!status.is_ok()) return nullptr;
  model->snch = std::make_unique<Snch>(model->mesh);
  model->size = glm::length(model->mesh.bounds().max - model->mesh.bounds().min);
  model->centre = 0.5 * (model->mesh.bounds().max + model->mesh.bounds().min);
  return model;
}

std::shared_ptr<const Model> load_obj_model(const std::string& relative) {
  io::ObjData obj;
  const Status status = io::read_obj(asset_path(relative), obj);
  EXPECT_TRUE(status.is_ok())
      << status.message()
      << " (the shared assets: ../shared/assets beside the repository, or -DPROX_SHARED_ASSETS_DIR)";
  if (!status.is_ok()) return nullptr;
  return model_from_arrays(obj.positions, obj.indices);
}

std::shared_ptr<const Model> square_sheet(int n, double side, bool facing_down) {
  std::vector<double> positions;
  std::vector<std::uint32_t> indices;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) positions.insert(positions.end(), {side * i / n, side * j / n, 0.0});
  const auto row = static_cast<std::uint32_t>(n + 1);
  for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(n); ++j)
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
      const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      if (facing_down)
        indices.insert(indices.end(), {a, d, b, a, c, d});
      else
        indices.insert(indices.end(), {a, b, d, a, d, c});
    }
  return model_from_arrays(positions, indices);
}

std::shared_ptr<const Model> load_gltf_model(const std::string& relative, int part) {
#if PROX_WITH_GLTF
  std::vector<io::GltfMesh> meshes;
  io::GltfLoadOptions options;
  options.mode = part < 0 ? io::GltfSceneMode::Merged : io::GltfSceneMode::PerNode;
  const Status status = io::load_gltf(asset_path(relative), options, meshes);
  EXPECT_TRUE(status.is_ok()) << status.message();
  if (!status.is_ok()) return nullptr;
  const std::size_t i = part < 0 ? 0 : static_cast<std::size_t>(part);
  EXPECT_LT(i, meshes.size());
  if (i >= meshes.size()) return nullptr;
  return model_from_arrays(meshes[i].positions, meshes[i].indices);
#else
  ADD_FAILURE() << "built without glTF support (PROX_WITH_GLTF=OFF): cannot load " << relative << " part "
                << part;
  return nullptr;
#endif
}

PairQuery make_query(const Model& a, const Pose& pose_a, const Model& b, const Pose& pose_b, double cutoff) {
  return {&a.mesh, a.snch.get(), pose_a, &b.mesh, b.snch.get(), pose_b, cutoff};
}

Pose pose_at_gap(const Model& a, const Model& b, double gap, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Pose pose = Pose::from_quaternion(Vec3(0.0), u(rng), u(rng), u(rng), u(rng));
  Vec3 dir;
  do dir = Vec3(u(rng), u(rng), u(rng));
  while (glm::dot(dir, dir) > 1.0 || glm::dot(dir, dir) < 1e-4);
  dir = glm::normalize(dir);
  // b's centre on a's centre, then out along dir: from overlapping (lo) to
  // well apart (hi).
  const Vec3 base = a.centre - pose.rotation * b.centre;
  double lo = 0.0, hi = a.size + b.size + gap;
  for (int i = 0; i < 60 && hi - lo > 1e-10 * a.size; ++i) {
    const double mid = 0.5 * (lo + hi);
    pose.translation = base + mid * dir;
    (any_closer_than(make_query(a, Pose{}, b, pose, 0.0), gap) ? lo : hi) = mid;
  }
  pose.translation = base + hi * dir;
  return pose;
}

Match match_lmds(const std::vector<LmdPair>& reference, const std::vector<LmdPair>& found, double tolerance) {
  auto same = [tolerance](const LmdPair& x, const LmdPair& y) {
    return glm::length(x.point_a - y.point_a) <= tolerance && glm::length(x.point_b - y.point_b) <= tolerance;
  };
  Match m;
  m.reference = static_cast<int>(reference.size());
  m.found = static_cast<int>(found.size());
  for (const LmdPair& r : reference)
    for (const LmdPair& f : found)
      if (same(r, f)) {
        ++m.recalled;
        break;
      }
  for (const LmdPair& f : found)
    for (const LmdPair& r : reference)
      if (same(r, f)) {
        ++m.confirmed;
        break;
      }
  return m;
}

}  // namespace prox::testing
