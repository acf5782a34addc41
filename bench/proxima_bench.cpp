// proxima_bench: run time against error on named scenes, every method side by
// side on the same poses in one run (docs/benchmarks.md).
//
//   proxima_bench [--scene NAME|GROUP|all] [--poses N] [--out DIR] [--reference-every K]
//                 [--local-reps R] [--force-reps R] [--meshes DIR] [--scaling-poses N]
//                 [--scaling-reference-every K] [--cad-poses N] [--max-triangles N] [--builds N]
//                 [--workers N] [--list]
//
// Scenes come in groups: bunny (bunny against bunny on paths T and R, the
// paper's hard and soft settings, many bodies), cad (2CylinderEngine and
// ReciprocatingSaw parts against each other and the bunny) and scaling (path T
// on the bunny from 2k to 446k triangles; the decimated levels are read from
// --meshes, where bench/decimate.py writes them).
//
// At every pose of a scene's path, in this order: the precise method (a local
// update of the previous step's set to the new pose, as the local thread does,
// then the global search with its reduction, then the haptic loop's force
// evaluation over the result), the original Johnson-Cohen baseline (the same),
// Proxima's exact minimum distance (minimum_distance, the query FCL answers),
// FCL's distance query when built with it, and the brute-force reference every
// K-th pose. Errors are measured against the reference. Per-step figures go to
// DIR/<scene>.csv, a summary to DIR/<scene>.json, and a readable summary to
// standard output.
#include "bench_common.h"
#include "models.h"
#include "report.h"
#include "runtime_scenes.h"
#include "scene_run.h"
#include "scenes.h"
#ifdef PROX_BENCH_WITH_COAL
#include "coal_peer.h"
#endif
#ifdef PROX_BENCH_WITH_FCL
#include "fcl_peer.h"
#endif

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace prox::bench {

namespace {

const char* kUsage =
    "usage: proxima_bench [--scene NAME|GROUP|all] [--poses N] [--out DIR] [--reference-every K]\n"
    "                     [--local-reps R] [--force-reps R] [--meshes DIR] [--scaling-poses N]\n"
    "                     [--scaling-reference-every K] [--cad-poses N] [--max-triangles N] [--builds N]\n"
    "                     [--workers N (threads the precise global search splits over; 1)] [--list]";

[[noreturn]] void usage_error(const std::string& message) { throw UserError(message + "\n" + kUsage); }

int parse_int(const std::string& text, const char* what, int lo) {
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v < lo || v > 10000000)
    usage_error(std::string(what) + ": '" + text + "' is not a whole number >= " + std::to_string(lo));
  return static_cast<int>(v);
}

int run(int argc, char** argv) {
  Options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) usage_error("missing value after " + a);
      return argv[++i];
    };
    if (a == "--scene")
      opt.scene = next();
    else if (a == "--poses")
      opt.poses = parse_int(next(), "--poses", 2);
    else if (a == "--out")
      opt.out = next();
    else if (a == "--reference-every")
      opt.reference_every = parse_int(next(), "--reference-every", 0);
    else if (a == "--local-reps")
      opt.local_reps = parse_int(next(), "--local-reps", 1);
    else if (a == "--force-reps")
      opt.force_reps = parse_int(next(), "--force-reps", 1);
    else if (a == "--meshes")
      opt.meshes = next();
    else if (a == "--scaling-poses")
      opt.scaling_poses = parse_int(next(), "--scaling-poses", 2);
    else if (a == "--scaling-reference-every")
      opt.scaling_reference_every = parse_int(next(), "--scaling-reference-every", 0);
    else if (a == "--workers")
      opt.workers = parse_int(next(), "--workers", 1);
    else if (a == "--builds")
      opt.builds = parse_int(next(), "--builds", 1);
    else if (a == "--cad-poses")
      opt.cad_poses = parse_int(next(), "--cad-poses", 2);
    else if (a == "--max-triangles")
      opt.max_triangles = parse_int(next(), "--max-triangles", 0);
    else if (a == "--list") {
      for (const Scene& s : scenes())
        std::printf("%-16s [%s] %s\n", s.name.c_str(), s.group.c_str(), s.description.c_str());
      std::printf("%-16s [bunny] %s\n", "many-bodies",
                  "one tool on path T among 121, 1,201 and 12,001 static bunnies, all but one out of range");
      std::printf("%-16s [bunny] %s\n", "threads", "path T in real time on the runtime's threads");
      return 0;
    } else if (a == "--help" || a == "-h") {
      std::printf("%s\nsee docs/benchmarks.md\n", kUsage);
      return 0;
    } else
      usage_error("unknown option '" + a + "'");
  }
  // `all` runs each distinct scene once (paper-hard is path-t); a group name
  // (bunny, cad, scaling) runs the group.
  std::vector<const Scene*> chosen;
  for (const Scene& s : scenes()) {
    if (opt.scene == s.name || opt.scene == s.group || (opt.scene == "all" && s.name != "paper-hard"))
      chosen.push_back(&s);
  }
  const bool many_bodies = opt.scene == "many-bodies" || opt.scene == "bunny" || opt.scene == "all";
  const bool threads = opt.scene == "threads" || opt.scene == "bunny" || opt.scene == "all";
  if (chosen.empty() && !many_bodies && !threads)
    usage_error("--scene: no scene '" + opt.scene + "' (try --list)");
  std::filesystem::create_directories(opt.out);
  std::printf("%s\n", kPeerNote);
#ifdef PROX_BENCH_WITH_COAL
  // Coal answers from a process of its own (coal_peer.h).
  CoalPeer coal_peer(coal_peer_beside_self());
  CoalPeer* coal = &coal_peer;
  opt.coal_version = coal->version();
  std::printf(
      "Coal %s (proxima_coal_peer): collide with security_margin = the cutoff, every triangle pair within "
      "it.\n",
      opt.coal_version.c_str());
#else
  CoalPeer* coal = nullptr;
  std::printf("Coal: not built in (PROX_BENCH_WITH_COAL=OFF).\n");
#endif
#ifdef PROX_BENCH_WITH_FCL
  std::printf("FCL %s: OBBRSS BVH per mesh, built once.\n", fcl_version());
#else
  std::printf("FCL: not built in (PROX_BENCH_WITH_FCL=OFF).\n");
#endif

  // Meshes are loaded (with their hierarchies) once and shared by the scenes.
  std::map<std::string, std::shared_ptr<Model>> models;
  auto model_of = [&](const MeshSource& source) {
    const std::string key = source.file + "#" + std::to_string(source.part) + "#" +
                            std::to_string(source.subdivisions) + "#" + std::to_string(source.scale);
    auto& m = models[key];
    if (!m) m = load_model(source, opt.meshes, opt.builds, coal);
    return m;
  };
  if (many_bodies) run_many_bodies(*model_of(bunny_source()), opt);
  if (threads) run_threads(*model_of(bunny_source()), opt);
  for (const Scene* s : chosen) {
    if (s->group == "scaling") {
      if (s->a.generated && !std::filesystem::exists(opt.meshes + "/" + s->a.file)) {
        std::printf(
            "\n== %s: skipped: %s/%s is missing; scripts/decimate.py writes it (see docs/benchmarks.md)\n",
            s->name.c_str(), opt.meshes.c_str(), s->a.file.c_str());
        continue;
      }
      // 27,864 triangles, times 4 per subdivision.
      const long long estimate = 27864LL << (2 * s->a.subdivisions);
      if (opt.max_triangles > 0 && !s->a.generated && estimate > opt.max_triangles) {
        std::printf("\n== %s: skipped: about %lld triangles, above --max-triangles %d\n", s->name.c_str(),
                    estimate, opt.max_triangles);
        continue;
      }
    }
    const auto a = model_of(s->a), b = model_of(s->b);
    const bool scaling = s->group == "scaling";
    const int poses = scaling             ? std::min(opt.poses, opt.scaling_poses)
                      : s->group == "cad" ? std::min(opt.poses, opt.cad_poses)
                                          : opt.poses;
    const int reference_every =
        scaling ? (opt.reference_every > 0 ? opt.scaling_reference_every : 0) : opt.reference_every;
    const SceneRun r = run_scene(*s, *a, *b, poses, reference_every, opt, coal);
    write_file(opt.out + "/" + s->name + ".csv", csv(r));
    write_file(opt.out + "/" + s->name + ".json", summary_json(r, opt));
    print_summary(r);
  }
  std::printf("\nper-step CSV and summary JSON per scene written to %s/\n", opt.out.c_str());
  return 0;
}

}  // namespace
}  // namespace prox::bench

int main(int argc, char** argv) {
  try {
    return prox::bench::run(argc, argv);
  } catch (const prox::bench::UserError& e) {
    std::fprintf(stderr, "proxima_bench: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "proxima_bench: %s\n", e.what());
    return 1;
  }
}
