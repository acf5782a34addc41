// Wavefront OBJ reading: positions and faces only.
#pragma once

#include "common/status.h"

#include <cstdint>
#include <string>
#include <vector>

namespace prox::io {

// Triangles of an OBJ file as flat arrays: positions (x, y, z per vertex) and
// indices (three per triangle, 0-based). Polygons are fan-triangulated;
// texture coordinates, normals, groups and materials are ignored.
struct ObjData {
  std::vector<double> positions;
  std::vector<std::uint32_t> indices;
};

// Reads `path`. Errors name the file and line: a missing file, a malformed
// number, an index out of range, a face with fewer than three vertices.
Status read_obj(const std::string& path, ObjData& out);
// The same, from text already in memory (`name` is used in messages).
Status parse_obj(const std::string& text, const std::string& name, ObjData& out);

}  // namespace prox::io
