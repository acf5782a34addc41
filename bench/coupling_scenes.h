// Scenes and scripted device paths for the constrained tool's benchmark
// and tests: an obstacle, a tool, and a path of device poses, one per
// haptic tick, replayed through the deterministic step.
#pragma once

#include "runtime/world.h"

#include <string>
#include <vector>

namespace prox::coupling_scenes {

struct Soup {
  std::vector<double> positions;
  std::vector<std::uint32_t> indices;
};

// From the shared assets (PROX_SHARED_ASSETS_DIR); empty (and `error` set)
// when they cannot be read.
Soup obj_soup(const std::string& relative, std::string& error);
// Node `node` of a glTF scene, in PerNode order, coordinates times `scale`.
Soup gltf_soup(const std::string& relative, int node, double scale, std::string& error);
// A square of 2 n^2 triangles in the plane z = `z`, `size` wide, centred
// on the origin, its normal +z.
Soup square(int n, double size, double z);

struct Scene {
  std::string name;
  runtime::WorldSettings settings;
  Soup obstacle, tool;
};
// "bunny": bunny against bunny (hard settings); "cad": the 2CylinderEngine
// cylinder block (node 9) against the crankcase (node 8); "saw": the
// ReciprocatingSaw housing half body_5 (node 2) against the other, thin
// walled, half body_1 (node 0). CAD parts in metres, hard settings.
Scene make_scene(const std::string& name, std::string& error);

// A world holding the scene: the obstacle static at the identity, the tool
// constrained (or free) at `start`.
struct Built {
  std::unique_ptr<runtime::World> world;
  runtime::Handle obstacle, tool;
  runtime::Handle obstacle_mesh, tool_mesh;
};
Built build(const Scene& scene, const Pose& start, bool constrained, std::string& error);

// The tool's translation along `direction` (unit) at which its boxes are
// `gap` clear of the obstacle's, on the side `direction` points to.
Vec3 clear_offset(const Scene& scene, const Vec3& direction, double gap);

// Straight lines through `points`, `step` apart (metres per tick), the last
// point repeated `hold` times.
std::vector<Pose> line_path(const std::vector<Vec3>& points, double step, int hold);

}  // namespace prox::coupling_scenes
