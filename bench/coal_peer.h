// Coal as a peer in proxima_bench, driven in its own process
// (proxima_coal_peer, coal_peer/main.cpp): Coal's wheel brings an octomap that
// cannot share a process with Debian's FCL, so nothing of Coal is linked into
// the bench. Its collision query with a security margin reports every
// triangle pair closer than the margin, the only peer output comparable to an
// LMD set. Used when PROX_BENCH_WITH_COAL is on.
#pragma once

#include "contact/pose.h"
#include "mesh/mesh.h"

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace prox::bench {

struct CoalBuild {
  std::uint32_t mesh = 0;       // the peer's id for the mesh
  std::vector<double> seconds;  // one per build
};

struct CoalMargin {
  double seconds = 0.0;       // Coal's call alone, timed in the peer
  std::size_t pairs = 0;      // triangle pairs within the margin
  double min_distance = 0.0;  // Coal's lower bound on the distance (its own figure)
};

class CoalPeer {
 public:
  // Starts `executable`; throws std::runtime_error when it cannot.
  explicit CoalPeer(const std::string& executable);
  ~CoalPeer();
  CoalPeer(const CoalPeer&) = delete;
  CoalPeer& operator=(const CoalPeer&) = delete;

  std::string version();
  // The same welded geometry as the engine's, built `reps` times.
  CoalBuild build(const Mesh& mesh, int reps);
  // collide(A at the identity, B at `pose_b`) with security_margin = `margin`
  // and room for every pair.
  CoalMargin margin_collide(std::uint32_t a, std::uint32_t b, const Pose& pose_b, double margin);

 private:
  [[noreturn]] void fail(const char* what);
  pid_t pid_ = -1;
  int to_ = -1, from_ = -1;
};

// proxima_coal_peer beside the running executable.
std::string coal_peer_beside_self();

}  // namespace prox::bench
