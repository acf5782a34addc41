// FCL (Debian's libfcl-dev) as a peer in proxima_bench: its OBBRSS BVH and
// distance query, the single closest pair per pose. Its own translation unit,
// so FCL's and Eigen's headers stay out of the benchmark's other code. Built
// when PROX_BENCH_WITH_FCL is on.
#pragma once

#include "contact/pose.h"
#include "mesh/mesh.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace prox::bench {

struct FclMesh;  // FCL's OBBRSS BVH of one mesh

struct FclBuild {
  std::shared_ptr<const FclMesh> mesh;
  std::vector<double> seconds;   // one per build
  std::size_t memory_bytes = 0;  // what BVHModel::memUsage prints
};
// The same welded geometry as the engine's, built `reps` times.
FclBuild fcl_build(const Mesh& mesh, int reps);

struct FclDistance {
  double seconds = 0.0;
  double distance = 0.0;
};
// distance(A at the identity, B at `pose_b`) with the default request.
FclDistance fcl_distance(const FclMesh& a, const FclMesh& b, const Pose& pose_b);

const char* fcl_version();

}  // namespace prox::bench
