// The glTF/GLB reader straight into io, on the file's bytes in memory, in
// both scene modes: an error names the file, a success gives finite
// positions and indices in range, and its warnings name the file. External buffers resolve beside a path
// that does not exist, so they fail as I/O errors.
#include "check.h"
#include "io/gltf.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using namespace prox;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool binary = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
  const std::string path =
      binary ? "/nonexistent-proxima-fuzz/fuzz.glb" : "/nonexistent-proxima-fuzz/fuzz.gltf";
  for (const io::GltfSceneMode mode : {io::GltfSceneMode::Merged, io::GltfSceneMode::PerNode}) {
    std::vector<io::GltfMesh> meshes;
    std::vector<std::string> warnings;
    const Status status = io::load_gltf_bytes(std::vector<unsigned char>(data, data + size), path,
                                              io::GltfLoadOptions{mode}, meshes, &warnings);
    if (!status) {
      PROX_FUZZ_CHECK(status.message().find("fuzz.gl") != std::string::npos, "error without the file: %s",
                      status.message().c_str());
      PROX_FUZZ_CHECK(meshes.empty() && warnings.empty(), "meshes or warnings left after an error");
      return 0;  // the other mode fails the same way
    }
    PROX_FUZZ_CHECK(!meshes.empty(), "success without a mesh");
    for (const std::string& warning : warnings)
      PROX_FUZZ_CHECK(warning.find("fuzz.gl") != std::string::npos, "warning without the file: %s",
                      warning.c_str());
    for (const io::GltfMesh& mesh : meshes) {
      PROX_FUZZ_CHECK(mesh.positions.size() % 3 == 0 && mesh.indices.size() % 3 == 0, "ragged arrays");
      for (const double x : mesh.positions) PROX_FUZZ_CHECK(std::isfinite(x), "non-finite coordinate %g", x);
      for (const std::uint32_t i : mesh.indices)
        PROX_FUZZ_CHECK(i < mesh.positions.size() / 3, "index %u past %zu vertices", i,
                        mesh.positions.size() / 3);
    }
  }
  return 0;
}
