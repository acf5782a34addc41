// proxWorld_LoadMesh on a fuzzed .glb/.gltf (written to a temporary file):
// every failure is named, a success gives a mesh whose information is sane.
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
  PROX_FUZZ_CHECK(proxDestroyWorld(world) == PROX_SUCCESS, "%s", proxGetLastError());
  return 0;
}
