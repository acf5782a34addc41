// The triangles the viewer draws: exactly what the world was given, as the
// C API hands it back (proxMesh_GetTriangles), whatever file it came from.
#pragma once

#include <cstdint>
#include <vector>

namespace viewer {

struct RenderMesh {
  std::vector<float> positions;   // x, y, z per vertex, in the mesh's frame
  std::vector<uint32_t> indices;  // three per triangle
};

}  // namespace viewer
