#include "coupling_scenes.h"

#include "io/obj.h"
#if PROX_WITH_GLTF
#include "io/gltf.h"
#endif

#include <glm/geometric.hpp>

#include <cmath>

namespace prox::coupling_scenes {
namespace {

std::string asset(const std::string& relative) {
  return std::string(PROX_SHARED_ASSETS_DIR) + "/" + relative;
}

Aabb bounds(const Soup& s) {
  Aabb box{Vec3(INFINITY), Vec3(-INFINITY)};
  for (std::size_t i = 0; i + 2 < s.positions.size(); i += 3) {
    const Vec3 p(s.positions[i], s.positions[i + 1], s.positions[i + 2]);
    box.min = glm::min(box.min, p);
    box.max = glm::max(box.max, p);
  }
  return box;
}

}  // namespace

Soup obj_soup(const std::string& relative, std::string& error) {
  io::ObjData data;
  const Status status = io::read_obj(asset(relative), data);
  if (!status) {
    error = status.message();
    return {};
  }
  return {std::move(data.positions), std::move(data.indices)};
}

Soup gltf_soup(const std::string& relative, int node, double scale, std::string& error) {
#if PROX_WITH_GLTF
  std::vector<io::GltfMesh> meshes;
  io::GltfLoadOptions options;
  options.mode = io::GltfSceneMode::PerNode;
  const Status status = io::load_gltf(asset(relative), options, meshes);
  if (!status) {
    error = status.message();
    return {};
  }
  if (node < 0 || static_cast<std::size_t>(node) >= meshes.size()) {
    error = relative + " has no node " + std::to_string(node);
    return {};
  }
  Soup s{std::move(meshes[std::size_t(node)].positions), std::move(meshes[std::size_t(node)].indices)};
  for (double& v : s.positions) v *= scale;
  return s;
#else
  (void)node, (void)scale;
  error = "built without glTF support: cannot read " + relative;
  return {};
#endif
}

Soup square(int n, double size, double z) {
  Soup s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      s.positions.insert(s.positions.end(), {size * (double(i) / n - 0.5), size * (double(j) / n - 0.5), z});
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      s.indices.insert(s.indices.end(),
                       {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
  return s;
}

Scene make_scene(const std::string& name, std::string& error) {
  Scene s;
  s.name = name;
  s.settings.force = hard_force_settings();
  if (name == "bunny") {
    s.obstacle = obj_soup("bunny.obj", error);
    s.tool = s.obstacle;
  } else if (name == "cad") {
    s.obstacle = gltf_soup("gltf/2CylinderEngine.glb", 8, 0.001, error);
    s.tool = gltf_soup("gltf/2CylinderEngine.glb", 9, 0.001, error);
  } else if (name == "saw") {
    s.obstacle = gltf_soup("gltf/ReciprocatingSaw.glb", 0, 0.001, error);
    s.tool = gltf_soup("gltf/ReciprocatingSaw.glb", 2, 0.001, error);
  } else {
    error = "no scene " + name;
  }
  return s;
}

Built build(const Scene& scene, const Pose& start, bool constrained, std::string& error) {
  Built b;
  b.world = std::make_unique<runtime::World>(scene.settings);
  Status status;
  auto mesh = [&](const Soup& soup) {
    const MeshInput in{soup.positions.data(), static_cast<std::uint32_t>(soup.positions.size() / 3),
                       soup.indices.data(), static_cast<std::uint32_t>(soup.indices.size() / 3)};
    return b.world->create_mesh(in, status);
  };
  const runtime::Handle ma = mesh(scene.obstacle);
  if (!status) error = status.message();
  const runtime::Handle mb = mesh(scene.tool);
  if (!status) error = status.message();
  if (!error.empty()) return b;
  b.obstacle_mesh = ma;
  b.tool_mesh = mb;
  b.obstacle = b.world->create_body(ma, runtime::BodyType::Static, Pose{}, Vec3(0.0));
  runtime::ToolSettings tool;
  if (constrained) tool.mode = coupling::ToolMode::Constrained;
  const Aabb box = bounds(scene.tool);
  b.tool = b.world->create_body(mb, runtime::BodyType::Tool, start, 0.5 * (box.min + box.max), tool);
  return b;
}

Vec3 clear_offset(const Scene& scene, const Vec3& direction, double gap) {
  const Aabb a = bounds(scene.obstacle), t = bounds(scene.tool);
  // The smallest shift along `direction` after which the boxes are
  // separated by `gap` along it.
  double shift = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (direction[k] > 0.0) shift = std::max(shift, (a.max[k] - t.min[k] + gap) / direction[k]);
    if (direction[k] < 0.0) shift = std::max(shift, (a.min[k] - t.max[k] - gap) / direction[k]);
  }
  return shift * direction;
}

std::vector<Pose> line_path(const std::vector<Vec3>& points, double step, int hold) {
  std::vector<Pose> path;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double length = glm::length(points[i + 1] - points[i]);
    const int n = std::max(1, static_cast<int>(std::ceil(length / step)));
    for (int k = 0; k < n; ++k) {
      Pose p;
      p.translation = points[i] + (double(k) / n) * (points[i + 1] - points[i]);
      path.push_back(p);
    }
  }
  Pose last;
  last.translation = points.back();
  for (int k = 0; k <= hold; ++k) path.push_back(last);
  return path;
}

}  // namespace prox::coupling_scenes
