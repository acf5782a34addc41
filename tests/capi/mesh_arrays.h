// A C API mesh def over a test's own position and index arrays, which must
// outlive the def.
#pragma once

#include <proxima/proxima.h>

#include <cstdint>
#include <vector>

namespace capi_test {

inline proxMeshDef mesh_def(const std::vector<double>& positions, const std::vector<uint32_t>& indices) {
  proxMeshDef d = proxDefaultMeshDef();
  d.positions = positions.data();
  d.vertexCount = static_cast<uint32_t>(positions.size() / 3);
  d.indices = indices.data();
  d.triangleCount = static_cast<uint32_t>(indices.size() / 3);
  return d;
}

}  // namespace capi_test
