// proxWorld_LoadMesh on a fuzzed .glb/.gltf (written to a temporary file),
// and proxWorld_LoadMeshFromMemory on the same bytes: every failure is named,
// a success gives a mesh whose information is sane, and the two agree (but
// where the file names an external buffer, which from memory is never read).
#include "check.h"
#include "temp_file.h"

#include <proxima/proxima.h>

#include <cmath>
#include <cstdint>
#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static prox::fuzz::TempFile glb(".glb");
  static prox::fuzz::TempFile gltf(".gltf");
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const std::string& path = (binary ? glb : gltf).write(data, size);

  const proxWorldDef def = proxDefaultWorldDef();
  proxWorldId world;
  PROX_FUZZ_CHECK(proxCreateWorld(&def, &world) == PROX_SUCCESS, "%s", proxGetLastError());
  proxMeshId mesh;
  const proxResult r = proxWorld_LoadMesh(world, path.c_str(), &mesh);
  if (r != PROX_SUCCESS) {
    PROX_FUZZ_CHECK(r < 0 && std::strstr(proxGetLastError(), path.c_str()) != nullptr,
                    "%s: the error does not name the file: %s", proxResultString(r), proxGetLastError());
    PROX_FUZZ_CHECK(mesh.index1 == 0, "an id was returned with an error");
  } else {
    proxMeshInfo info;
    PROX_FUZZ_CHECK(proxMesh_GetInfo(mesh, &info) == PROX_SUCCESS, "%s", proxGetLastError());
    PROX_FUZZ_CHECK(info.triangleCount > 0 && info.vertexCount >= 3, "a mesh of %u triangles, %u vertices",
                    info.triangleCount, info.vertexCount);
    PROX_FUZZ_CHECK(std::isfinite(info.boundsMin.x) && std::isfinite(info.boundsMax.z) &&
                        info.boundsMin.x <= info.boundsMax.x,
                    "bounds");
  }
  const char* name = binary ? "fuzzed.glb" : "fuzzed.gltf";
  proxMeshId from_memory;
  const proxResult m =
      proxWorld_LoadMeshFromMemory(world, size > 0 ? data : nullptr, size, name, &from_memory);
  if (m != PROX_SUCCESS) {
    PROX_FUZZ_CHECK(m < 0 && std::strstr(proxGetLastError(), name) != nullptr,
                    "%s: the error does not name the bytes: %s", proxResultString(m), proxGetLastError());
    PROX_FUZZ_CHECK(from_memory.index1 == 0, "an id was returned with an error");
  }
  if (m != PROX_ERROR_FILE && size > 0) {
    PROX_FUZZ_CHECK(m == r, "from memory %s, from the file %s", proxResultString(m), proxResultString(r));
    if (m == PROX_SUCCESS && r == PROX_SUCCESS) {
      proxMeshInfo a, b;
      PROX_FUZZ_CHECK(
          proxMesh_GetInfo(mesh, &a) == PROX_SUCCESS && proxMesh_GetInfo(from_memory, &b) == PROX_SUCCESS,
          "%s", proxGetLastError());
      PROX_FUZZ_CHECK(a.triangleCount == b.triangleCount && a.vertexCount == b.vertexCount,
                      "%u triangles from the file, %u from memory", a.triangleCount, b.triangleCount);
    }
  }
  PROX_FUZZ_CHECK(proxWorld_Destroy(world) == PROX_SUCCESS, "%s", proxGetLastError());
  return 0;
}
