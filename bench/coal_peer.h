// Coal (the PyPI wheel's C++ library) as a peer in proxima_bench: its
// collision query with a security margin, which reports every triangle pair
// closer than the margin, the only peer output comparable to an LMD set. Its
// own translation unit, so Coal's headers (and their Eigen and Boost) stay
// out of the benchmark's other code. Built when PROX_BENCH_WITH_COAL is on.
#pragma once

#include "contact/pose.h"
#include "mesh/mesh.h"

#include <cstddef>
#include <memory>
#include <string>

namespace prox::bench {

struct CoalMesh;  // Coal's OBBRSS BVH of one mesh

struct CoalBuild {
  std::shared_ptr<const CoalMesh> mesh;
  double seconds = 0.0;
};
// The same welded geometry as the engine's.
CoalBuild coal_build(const Mesh& mesh);

struct CoalMargin {
  double seconds = 0.0;
  std::size_t pairs = 0;      // triangle pairs within the margin
  double min_distance = 0.0;  // Coal's lower bound on the distance (its own figure)
};
// collide(A at the identity, B at `pose_b`) with security_margin = `margin`
// and room for every pair.
CoalMargin coal_margin_collide(const CoalMesh& a, const CoalMesh& b, const Pose& pose_b, double margin);

std::string coal_version();

}  // namespace prox::bench
