#include "models.h"

#include "io/obj.h"
#if PROX_WITH_GLTF
#include "io/gltf.h"
#endif
#ifdef PROX_BENCH_WITH_COAL
#include "coal_peer.h"
#endif
#ifdef PROX_BENCH_WITH_FCL
#include "fcl_peer.h"
#endif

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unordered_map>
#include <utility>

namespace prox::bench {

namespace {

// Splits every triangle into four at its edge midpoints (shared between the
// two triangles of an edge, so the mesh stays welded). The surface is the
// same, so distances stay comparable across levels.
void subdivide(std::vector<double>& positions, std::vector<std::uint32_t>& indices) {
  std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
  auto midpoint = [&](std::uint32_t i, std::uint32_t j) {
    const std::uint64_t key = (std::uint64_t{std::min(i, j)} << 32) | std::max(i, j);
    const auto found = midpoints.find(key);
    if (found != midpoints.end()) return found->second;
    const std::uint32_t v = static_cast<std::uint32_t>(positions.size() / 3);
    double p[3];
    for (std::size_t k = 0; k < 3; ++k) p[k] = 0.5 * (positions[3 * i + k] + positions[3 * j + k]);
    positions.insert(positions.end(), p, p + 3);
    midpoints.emplace(key, v);
    return v;
  };
  std::vector<std::uint32_t> out;
  out.reserve(4 * indices.size());
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
    const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    out.insert(out.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
  }
  indices = std::move(out);
}

void read_source(const MeshSource& source, const std::string& path, std::vector<double>& positions,
                 std::vector<std::uint32_t>& indices) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".obj") {
    io::ObjData obj;
    const Status s = io::read_obj(path, obj);
    if (!s)
      throw UserError(s.message() + (source.generated
                                         ? " (scripts/decimate.py writes it; see docs/benchmarks.md)"
                                         : " (the shared assets: ../shared/assets beside the repository, or "
                                           "-DPROX_SHARED_ASSETS_DIR)"));
    positions = std::move(obj.positions);
    indices = std::move(obj.indices);
    return;
  }
#if PROX_WITH_GLTF
  std::vector<io::GltfMesh> meshes;
  io::GltfLoadOptions options;
  options.mode = source.part < 0 ? io::GltfSceneMode::Merged : io::GltfSceneMode::PerNode;
  const Status s = io::load_gltf(path, options, meshes);
  if (!s)
    throw UserError(
        s.message() +
        " (the shared assets: ../shared/assets beside the repository, or -DPROX_SHARED_ASSETS_DIR)");
  const std::size_t i = source.part < 0 ? 0 : static_cast<std::size_t>(source.part);
  if (i >= meshes.size())
    throw UserError(path + ": no node " + std::to_string(source.part) + " with triangles (" +
                    std::to_string(meshes.size()) + " in PerNode order)");
  positions = std::move(meshes[i].positions);
  indices = std::move(meshes[i].indices);
#else
  throw UserError(path + ": built without glTF support (PROX_WITH_GLTF=OFF)");
#endif
}

}  // namespace

std::shared_ptr<Model> load_model(const MeshSource& source, const std::string& meshes_dir, int builds,
                                  CoalPeer* coal) {
  auto model = std::make_shared<Model>();
  model->name = source.label;
  model->file = source.generated ? meshes_dir + "/" + source.file : asset_path(source.file);
  std::vector<double> positions;
  std::vector<std::uint32_t> indices;
  read_source(source, model->file, positions, indices);
  for (double& x : positions) x *= source.scale;
  for (int i = 0; i < source.subdivisions; ++i) subdivide(positions, indices);
  const MeshInput input{positions.data(), static_cast<std::uint32_t>(positions.size() / 3), indices.data(),
                        static_cast<std::uint32_t>(indices.size() / 3)};
  Status status;
  model->mesh = Mesh::build(input, status);
  if (!status) throw UserError(model->file + ": " + status.message());
  const Mesh& m = model->mesh;
  model->size = glm::length(m.bounds().max - m.bounds().min);
  model->box_centre = 0.5 * (m.bounds().max + m.bounds().min);
  double area = 0.0;
  Vec3 sum(0.0);
  std::vector<double> areas;
  for (std::uint32_t t = 0; t < m.triangle_count(); ++t) {
    const Triangle tri = m.triangle(t);
    const double a = 0.5 * glm::length(glm::cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0]));
    area += a;
    sum += a * (tri.v[0] + tri.v[1] + tri.v[2]) / 3.0;
    areas.push_back(a);
  }
  model->centroid = area > 0.0 ? sum / area : model->box_centre;
  model->max_over_median_area = ratio(maximum(areas), median(areas));
  for (int i = 0; i < builds; ++i) {
    model->snch = std::make_unique<Snch>(m);
    model->snch_build_seconds.push_back(model->snch->stats().build_seconds);
  }
#ifdef PROX_BENCH_WITH_FCL
  FclBuild fcl = fcl_build(m, builds);
  model->fcl = fcl.mesh;
  model->fcl_build_seconds = fcl.seconds;
  model->fcl_memory_bytes = fcl.memory_bytes;
#endif
#ifdef PROX_BENCH_WITH_COAL
  const CoalBuild built = coal->build(m, builds);
  model->coal = built.mesh;
  model->coal_build_seconds = built.seconds;
#else
  (void)coal;
#endif
  std::printf(
      "%s: %u triangles, size %.3f m, largest / median triangle area %.0f; SNCH %u nodes, built in %.1f ms "
      "(median of %d), %.2f MiB",
      model->name.c_str(), m.triangle_count(), model->size, model->max_over_median_area,
      model->snch->stats().nodes, median(model->snch_build_seconds) * 1e3, builds,
      double(model->snch->stats().memory_bytes) / (1 << 20));
#ifdef PROX_BENCH_WITH_FCL
  std::printf("; FCL OBBRSS BVH %.1f ms, %.2f MiB\n", median(model->fcl_build_seconds) * 1e3,
              double(model->fcl_memory_bytes) / (1 << 20));
#else
  std::printf("\n");
#endif
  return model;
}

std::string asset_path(const std::string& name) {
  if (const char* dir = std::getenv("PROXIMA_ASSETS")) return std::string(dir) + "/" + name;
  return std::string(PROX_SHARED_ASSETS_DIR) + "/" + name;
}

}  // namespace prox::bench
