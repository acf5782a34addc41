// The meshes the scenes use: where each comes from, and what is built from
// it once for every method (the SNCH, FCL's and Coal's hierarchies).
#pragma once

#include "bench_common.h"
#include "mesh/mesh.h"
#include "snch/snch.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace prox::bench {

struct FclMesh;  // fcl_peer.h
class CoalPeer;  // coal_peer.h

// Where a mesh comes from. Lengths end up in metres: the bunny's files are in
// metres, the CAD models in millimetres (2CylinderEngine's box is about
// 743 x 273 x 268 file units, a two-cylinder engine; ReciprocatingSaw's
// 375 x 84 x 149, a hand saw), so those are scaled by 0.001.
struct MeshSource {
  std::string label;       // the name in tables and plots
  std::string file;        // relative to the shared assets, or to --meshes when `generated`
  int part = -1;           // glTF node in PerNode order (io::GltfSceneMode::PerNode); -1: the whole file
  double scale = 1.0;      // file units to metres
  int subdivisions = 0;    // 1 -> 4 midpoint splits after loading
  bool generated = false;  // written by scripts/decimate.py into the --meshes folder
};

struct Model {
  std::string name, file;
  Mesh mesh;
  std::unique_ptr<Snch> snch;
  double size = 0.0;                       // bounding-box diagonal
  Vec3 box_centre{0.0};                    // the tool's reference point for torques
  Vec3 centroid{0.0};                      // area-weighted surface centroid: path R turns about it
  std::vector<double> snch_build_seconds;  // one per build
  double max_over_median_area = kNaN;      // how uneven the triangles are
#ifdef PROX_BENCH_WITH_FCL
  std::shared_ptr<const FclMesh> fcl;
  std::vector<double> fcl_build_seconds;
  std::size_t fcl_memory_bytes = 0;
#endif
#ifdef PROX_BENCH_WITH_COAL
  std::uint32_t coal = 0;  // the peer's id for this mesh
  std::vector<double> coal_build_seconds;
#endif
};

// The mesh under the shared assets (PROXIMA_ASSETS overrides the built-in folder).
std::string asset_path(const std::string& name);

// Loads, welds and builds every hierarchy of `source` `builds` times (the
// median time is reported); `coal` (null when Coal is not built in) builds
// Coal's in its process.
std::shared_ptr<Model> load_model(const MeshSource& source, const std::string& meshes_dir, int builds,
                                  CoalPeer* coal);

}  // namespace prox::bench
