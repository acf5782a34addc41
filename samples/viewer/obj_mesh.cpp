#include "obj_mesh.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace viewer {

namespace {

bool ends_with(const std::string& s, const char* suffix) {
  const std::string t(suffix);
  if (s.size() < t.size()) return false;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - t.size() + i])) != t[i]) return false;
  return true;
}

}  // namespace

RenderMesh read_render_mesh(const std::string& path) {
  if (!ends_with(path, ".obj"))
    throw std::runtime_error(path +
                             ": the viewer draws OBJ files only in this version (the SDK itself reads glTF)");
  FILE* f = std::fopen(path.c_str(), "r");
  if (!f) throw std::runtime_error(path + ": cannot read");
  RenderMesh mesh;
  char line[4096];
  int number = 0;
  std::string error;
  std::vector<long> face;
  while (error.empty() && std::fgets(line, sizeof line, f)) {
    ++number;
    const char* p = line;
    while (*p == ' ' || *p == '\t') ++p;
    if (p[0] == 'v' && (p[1] == ' ' || p[1] == '\t')) {
      char* end = nullptr;
      const char* at = p + 1;
      for (int k = 0; k < 3; ++k) {
        const double v = std::strtod(at, &end);
        if (end == at || !std::isfinite(v)) {
          error = "expected three finite coordinates";
          break;
        }
        mesh.positions.push_back(static_cast<float>(v));
        at = end;
      }
    } else if (p[0] == 'f' && (p[1] == ' ' || p[1] == '\t')) {
      face.clear();
      const char* at = p + 1;
      const long vertices = static_cast<long>(mesh.positions.size() / 3);
      for (;;) {
        while (*at == ' ' || *at == '\t') ++at;
        if (*at == '\0' || *at == '\n' || *at == '\r') break;
        char* end = nullptr;
        long index = std::strtol(at, &end, 10);
        if (end == at) {
          error = "a face index is not a number";
          break;
        }
        index = index < 0 ? vertices + index : index - 1;
        if (index < 0 || index >= vertices) {
          error = "a face index is out of range";
          break;
        }
        face.push_back(index);
        at = end;
        while (*at != '\0' && *at != ' ' && *at != '\t' && *at != '\n' && *at != '\r') ++at;  // v/vt/vn
      }
      if (error.empty() && face.size() < 3) error = "a face has fewer than three vertices";
      for (std::size_t k = 2; error.empty() && k < face.size(); ++k) {
        mesh.indices.push_back(static_cast<uint32_t>(face[0]));
        mesh.indices.push_back(static_cast<uint32_t>(face[k - 1]));
        mesh.indices.push_back(static_cast<uint32_t>(face[k]));
      }
    }
  }
  std::fclose(f);
  if (!error.empty()) throw std::runtime_error(path + ":" + std::to_string(number) + ": " + error);
  if (mesh.indices.empty()) throw std::runtime_error(path + ": no triangles");
  return mesh;
}

}  // namespace viewer
