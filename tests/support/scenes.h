// Test and benchmark scenes built from the shared assets.
#pragma once

#include "contact/proximity.h"
#include "mesh/mesh.h"
#include "snch/snch.h"

#include <memory>
#include <random>
#include <string>

namespace prox::testing {

// The shared assets folder as configured at build time (PROX_SHARED_ASSETS_DIR:
// ../shared/assets beside the repository unless configured otherwise).
std::string asset_path(const std::string& relative);

// How many of `n` random poses a test against the brute-force reference
// runs: all of them, or a quarter (the same first quarter) in a sanitizer
// build, where the reference runs about ten times slower. The release suite
// checks the full count; a sanitizer build is there for memory errors and
// undefined behaviour, which the first poses already exercise.
constexpr int sampled_poses(int n) {
#ifdef PROX_TESTS_SANITIZED
  return n / 4 > 0 ? n / 4 : 1;
#else
  return n;
#endif
}

// A mesh and its hierarchy.
struct Model {
  Mesh mesh;
  std::unique_ptr<Snch> snch;
  double size = 0.0;  // bounding-box diagonal
  Vec3 centre{0.0};   // bounding-box centre
};

// Loads an OBJ from the shared assets; fails the calling test (and returns
// nullptr) when it cannot.
std::shared_ptr<const Model> load_obj_model(const std::string& relative);
// Loads a glTF scene from the shared assets: merged into one mesh, or only
// node `part` of it (scene order). Fails the calling test when it cannot.
std::shared_ptr<const Model> load_gltf_model(const std::string& relative, int part = -1);
std::shared_ptr<const Model> model_from_arrays(const std::vector<double>& positions,
                                               const std::vector<std::uint32_t>& indices);

// A random relative pose of b near a: b rotated about its centre by a random
// rotation and moved along a random direction until the exact minimum
// distance between the meshes is `gap` (bisection on the distance; the
// result never penetrates).
Pose pose_at_gap(const Model& a, const Model& b, double gap, std::mt19937_64& rng);

PairQuery make_query(const Model& a, const Pose& pose_a, const Model& b, const Pose& pose_b, double cutoff);

// Matches found LMDs to reference LMDs by their closest points (both within
// `tolerance`); counts reference LMDs found and found LMDs that are real.
struct Match {
  int reference = 0, found = 0;
  int recalled = 0;   // reference LMDs with a matching found LMD
  int confirmed = 0;  // found LMDs with a matching reference LMD
};
Match match_lmds(const std::vector<LmdPair>& reference, const std::vector<LmdPair>& found, double tolerance);

}  // namespace prox::testing
