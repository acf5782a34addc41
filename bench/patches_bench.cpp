// Flat distance fields (docs/patches.md, docs/benchmarks.md "Flat fields"):
// two parallel sheets 1 mm apart (10,082 and 80,000 triangles each), the
// finer two crossing at 2 degrees, and Suzanne against itself moved 1 cm, the
// precise query with patches off and on, and on with the leaf budget of the
// bounded search, side by side in one run. Reports the median global search,
// reduction and merge times and the contacts handed on.
// Usage: proxima_patches_bench [--runs N]
#include "contact/proximity.h"
#include "io/gltf.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

using namespace prox;

namespace {

struct Body {
  Mesh mesh;
  std::unique_ptr<Snch> snch;
};

std::unique_ptr<Body> build(const std::vector<double>& positions, const std::vector<std::uint32_t>& indices) {
  MeshInput input{positions.data(), static_cast<std::uint32_t>(positions.size() / 3), indices.data(),
                  static_cast<std::uint32_t>(indices.size() / 3)};
  Status status;
  auto b = std::make_unique<Body>();
  b->mesh = Mesh::build(input, status);
  if (!status.is_ok()) {
    std::fprintf(stderr, "proxima_patches_bench: %s\n", status.message().c_str());
    std::exit(1);
  }
  b->snch = std::make_unique<Snch>(b->mesh);
  return b;
}

std::unique_ptr<Body> sheet(int n, double side, bool facing_down) {
  std::vector<double> p;
  std::vector<std::uint32_t> t;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) p.insert(p.end(), {side * i / n, side * j / n, 0.0});
  const auto row = static_cast<std::uint32_t>(n + 1);
  for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(n); ++j)
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
      const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      if (facing_down)
        t.insert(t.end(), {a, d, b, a, c, d});
      else
        t.insert(t.end(), {a, b, d, a, d, c});
    }
  return build(p, t);
}

std::unique_ptr<Body> suzanne() {
  const char* env = std::getenv("PROXIMA_ASSETS");
  const std::string path = std::string(env ? env : PROX_SHARED_ASSETS_DIR) + "/gltf/Suzanne/Suzanne.gltf";
  std::vector<io::GltfMesh> meshes;
  io::GltfLoadOptions options;
  options.mode = io::GltfSceneMode::Merged;
  const Status status = io::load_gltf(path, options, meshes);
  if (!status.is_ok() || meshes.empty()) {
    std::fprintf(stderr, "proxima_patches_bench: %s: %s\n", path.c_str(), status.message().c_str());
    std::exit(1);
  }
  return build(meshes[0].positions, meshes[0].indices);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// Patches off and on, without a leaf budget, then on with the default
// budget and with a tenth of it: the bounded search.
struct Variant {
  const char* name;
  bool patches;
  std::uint64_t leaf_budget;
};

void run(const char* name, const Body& a, const Body& b, const Pose& pose_b, double cutoff, int runs) {
  const std::uint64_t budget = PatchSettings::kDefaultLeafBudget;
  for (const Variant v : {Variant{"off", false, 0}, Variant{"on", true, 0}, Variant{"budget", true, budget},
                          Variant{"budget/10", true, budget / 10}}) {
    PairQuery q{&a.mesh, a.snch.get(), Pose{}, &b.mesh, b.snch.get(), pose_b, cutoff};
    if (!v.patches) q.patches.radius_over_cutoff = 0.0;
    q.patches.leaf_budget = v.leaf_budget;
    PairState state;
    std::vector<double> global, reduction, merge;
    ProximityResult r;
    for (int i = 0; i < runs; ++i) {
      const auto start = std::chrono::steady_clock::now();
      find_lmds(q, Method::Precise, state, r);
      const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double red = r.reduction[0].seconds + r.reduction[1].seconds;
      global.push_back(r.global.seconds);
      reduction.push_back(red);
      merge.push_back(total - r.global.seconds - red);
    }
    std::printf(
        "%-14s %-9s  leaf pairs %7llu  cut %5llu  candidates %7u  LMDs %6u  contacts %6zu  largest %5u  "
        "crossing pairs %5llu  min distance %.9g  global %8.2f ms  reduction %8.2f ms  merge %6.2f ms\n",
        name, v.name, static_cast<unsigned long long>(r.global.leaf_pairs),
        static_cast<unsigned long long>(r.global.cut_node_pairs), r.candidates, r.patches.lmds_in,
        r.lmds.size(), r.patches.largest, static_cast<unsigned long long>(r.global.intersecting_pairs),
        r.min_distance, 1e3 * median(global), 1e3 * median(reduction), 1e3 * median(merge));
  }
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--runs" && i + 1 < argc)
      runs = std::max(1, std::atoi(argv[++i]));
    else {
      std::fprintf(stderr, "usage: proxima_patches_bench [--runs N]\n");
      return 2;
    }
  }
  std::printf("median of %d runs each, the precise method (search, two reduction passes, patches)\n", runs);
  const auto floor = sheet(71, 0.1, false), tool = sheet(71, 0.1, true);
  run("two sheets", *floor, *tool, Pose{glm::dmat3(1.0), Vec3(0.0, 0.0, 0.001)}, 0.005, runs);
  const auto fine_floor = sheet(200, 0.1, false), fine_tool = sheet(200, 0.1, true);
  run("fine sheets", *fine_floor, *fine_tool, Pose{glm::dmat3(1.0), Vec3(0.0, 0.0, 0.001)}, 0.005, runs);
  // The fine tool tilted by 2 degrees about y through the floor's middle:
  // the two cross along a line, near each other over a wide band.
  const glm::dmat3 tilt = glm::mat3_cast(glm::angleAxis(2.0 * 3.14159265358979323846 / 180.0, Vec3(0, 1, 0)));
  run("fine crossing", *fine_floor, *fine_tool, Pose{tilt, tilt * Vec3(-0.05, 0.0, 0.0) + Vec3(0.05, 0.0, 0.0)},
      0.005, runs);
  const auto s = suzanne();
  run("Suzanne +1 cm", *s, *s, Pose{glm::dmat3(1.0), Vec3(0.0, 0.0, 0.01)}, 0.02, runs);
  return 0;
}
