// A flat square sheet as a C API mesh: the flat-field scenes of the patch
// tests (docs/patches.md).
#pragma once

#include "mesh_arrays.h"

#include <proxima/proxima.h>

#include <cstdint>
#include <vector>

namespace capi_test {

// A flat square sheet of n x n cells (two triangles each), side `side`, in
// z = 0, facing +z or -z.
struct Sheet {
  std::vector<double> positions;
  std::vector<uint32_t> indices;
  Sheet(int n, double side, bool facing_down) {
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) positions.insert(positions.end(), {side * i / n, side * j / n, 0.0});
    const auto row = static_cast<uint32_t>(n + 1);
    for (uint32_t j = 0; j < static_cast<uint32_t>(n); ++j)
      for (uint32_t i = 0; i < static_cast<uint32_t>(n); ++i) {
        const uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
        if (facing_down)
          indices.insert(indices.end(), {a, d, b, a, c, d});
        else
          indices.insert(indices.end(), {a, b, d, a, d, c});
      }
  }
  proxMeshDef def() const { return mesh_def(positions, indices); }
};

}  // namespace capi_test
