// The triangles the viewer draws. The C API hands out contacts, not mesh
// data, so the viewer reads the file itself (OBJ only: positions and faces)
// to draw exactly what the world was given.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace viewer {

struct RenderMesh {
  std::vector<float> positions;   // x, y, z per vertex, in the mesh's frame
  std::vector<uint32_t> indices;  // three per triangle
};

// Reads the v and f records of an OBJ file (polygons fanned into
// triangles, negative indices counted from the end). Throws
// std::runtime_error naming the file and line on malformed input, and for
// any file that is not .obj.
RenderMesh read_render_mesh(const std::string& path);

}  // namespace viewer
