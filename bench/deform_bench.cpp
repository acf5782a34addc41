// Deforming meshes and a scene that changes while the threads run
// (docs/dynamic-scenes.md):
//
//   refit   per frame of a smooth deformation (a sheet under a travelling
//           wave, 10^3 to 10^5 triangles; the bunny bent by the same wave):
//           moving the vertices, refitting the hierarchy, building it anew,
//           and the whole World::set_vertices (a copy beside the published
//           shape, refit, publish); then the search's node pairs on the
//           refitted tree after every frame against a tree built afresh for
//           the same shape;
//   skin    a skinned glTF posed by its animation every frame: the rig
//           evaluated (linear blend), the vertices moved and the hierarchy
//           refitted, as proxMesh_Animate does;
//   track   local tracking across a deformation: a sheet under the wave, a
//           probe above it; each frame the last frame's LMDs are tracked onto
//           the new shape and compared with the brute-force reference there
//           (kept, lost, spurious);
//   churn   a static body made and destroyed at 100 Hz beside a held tool
//           while the threads run: the haptic loop's period p99 and max.
//
// With --workers N (> 1) the moves, refits and skinning are also run split
// over N threads (proxWorldDef.workerCount), frame by frame beside the
// serial ones, and checked to give the same tree.
//
// Prints a table and writes build/deform-bench.json with --json FILE.
//   proxima_deform_bench [--frames N] [--workers N] [--churn-seconds S] [--json FILE]
#include "common/json_writer.h"
#include "common/worker_pool.h"
#include "contact/proximity.h"
#include "io/gltf.h"
#include "io/obj.h"
#include "runtime/scripted_device.h"
#include "runtime/threads.h"
#include "runtime/world.h"
#include "waved_sheet.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace prox;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

using bench::Shape;
using bench::sheet;
using bench::wave;

// A UV sphere of radius r about the origin, `n` rings and 2n segments,
// counter-clockwise seen from outside (closed: its poles are shared vertices).
Shape sphere(double r, int n) {
  Shape s{"sphere", {}, {}};
  s.positions.insert(s.positions.end(), {0.0, 0.0, r});
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double th = kPi * i / n, ph = kPi * j / n;
      s.positions.insert(s.positions.end(), {r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph),
                                             r * std::cos(th)});
    }
  s.positions.insert(s.positions.end(), {0.0, 0.0, -r});
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(1 + (i - 1) * 2 * n + (j % (2 * n))); };
  const auto south = static_cast<std::uint32_t>(s.positions.size() / 3 - 1);
  for (int j = 0; j < 2 * n; ++j) {
    s.indices.insert(s.indices.end(), {0, at(1, j), at(1, j + 1)});
    for (int i = 1; i + 1 < n; ++i)
      s.indices.insert(s.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1),
                                         at(i, j + 1)});
    s.indices.insert(s.indices.end(), {at(n - 1, j), south, at(n - 1, j + 1)});
  }
  return s;
}

struct RefitRow {
  std::string mesh;
  std::uint32_t triangles = 0;
  double move_ms = 0, refit_ms = 0, rebuild_ms = 0, world_ms = 0;
  double pooled_move_ms = 0, pooled_refit_ms = 0;  // the same on --workers threads
  int rebuilds = 0;  // World::set_vertices that rebuilt rather than refitted
  double degradation = 1.0;
  double node_pairs_ratio = 1.0;  // the search's node pairs, refitted tree over fresh tree, median
};

RefitRow refit_row(const Shape& shape, int frames, int axis, double amplitude, double wavelength, unsigned workers) {
  RefitRow row;
  row.mesh = shape.name;
  Status status;
  const MeshInput input = shape.input();
  const Mesh rest = Mesh::build(input, status);
  if (!status) throw std::runtime_error(shape.name + ": " + status.message());
  row.triangles = rest.triangle_count();
  Mesh mesh = rest, pooled_mesh = rest;
  Snch snch(rest), pooled_snch(rest);
  WorkerPool pool(workers);
  // A probe to search against: a small sheet 1 mm above the rest shape's
  // middle, facing down and tilted by 0.02 rad, so that the search has
  // contacts to find but no exactly parallel flat field (where which of the
  // tied LMDs a reduction keeps depends on the order the tree hands them out).
  const Shape probe_shape = sheet(8);
  Mesh probe = Mesh::build(probe_shape.input(), status);
  const Snch probe_snch(probe);
  const Aabb box = rest.bounds();
  const Vec3 middle = 0.5 * (box.min + box.max);
  Pose probe_pose{glm::dmat3(1.0), Vec3(middle.x - 0.1, middle.y - 0.1, box.max.z + amplitude + 0.001)};
  const double c = std::cos(0.02), s = std::sin(0.02);
  probe_pose.rotation = glm::dmat3(1, 0, 0, 0, -1, 0, 0, 0, -1) * glm::dmat3(c, 0, s, 0, 1, 0, -s, 0, c);
  probe_pose.translation.y += 0.2;

  runtime::World world{runtime::WorldSettings{}};
  const runtime::Handle handle = world.create_mesh(input, status);
  std::vector<double> move, refit, rebuild, in_world, ratio, pooled_move, pooled_refit;
  std::vector<double> xyz;
  for (int f = 1; f <= frames; ++f) {
    wave(rest, f, axis, amplitude, wavelength, xyz);
    auto t0 = Clock::now();
    if (!mesh.set_vertices(xyz.data(), mesh.vertex_count())) throw std::runtime_error("set_vertices");
    move.push_back(seconds_since(t0));
    t0 = Clock::now();
    snch.refit(mesh);
    refit.push_back(seconds_since(t0));
    if (workers > 1) {
      t0 = Clock::now();
      if (!pooled_mesh.set_vertices(xyz.data(), mesh.vertex_count(), &pool)) throw std::runtime_error("set_vertices");
      pooled_move.push_back(seconds_since(t0));
      t0 = Clock::now();
      pooled_snch.refit(pooled_mesh, &pool);
      pooled_refit.push_back(seconds_since(t0));
      if (pooled_snch.root().radius != snch.root().radius || pooled_mesh.vertex_normal(0) != mesh.vertex_normal(0))
        throw std::runtime_error(shape.name + ": the refit on workers differs from the serial one");
    }
    t0 = Clock::now();
    const Snch fresh(mesh);
    rebuild.push_back(seconds_since(t0));
    t0 = Clock::now();
    const std::uint64_t before = world.snch(handle).stats().refits;
    if (!world.set_vertices(handle, xyz.data(), mesh.vertex_count(), status))
      throw std::runtime_error(status.message());
    in_world.push_back(seconds_since(t0));
    if (world.snch(handle).stats().refits <= before) ++row.rebuilds;
    // The search on both trees: what refitting costs in node pairs. Patches
    // off: which LMDs of a flat field merge depends on the order the
    // candidates come in, which the trees' shapes decide.
    PairState s1, s2;
    ProximityResult on_refit, on_fresh;
    PairQuery q1{&probe, &probe_snch, probe_pose, &mesh, &snch, Pose{}, 0.005};
    PairQuery q2{&probe, &probe_snch, probe_pose, &mesh, &fresh, Pose{}, 0.005};
    q1.patches.radius_over_cutoff = q2.patches.radius_over_cutoff = 0.0;
    find_lmds(q1, Method::Precise, s1, on_refit);
    find_lmds(q2, Method::Precise, s2, on_fresh);
    if (on_fresh.global.node_pairs > 0)
      ratio.push_back(double(on_refit.global.node_pairs) / double(on_fresh.global.node_pairs));
    if (on_refit.lmds.size() != on_fresh.lmds.size())
      throw std::runtime_error(shape.name + ": the refitted tree found other LMDs than a fresh one");
  }
  row.move_ms = 1e3 * median(move);
  row.refit_ms = 1e3 * median(refit);
  row.rebuild_ms = 1e3 * median(rebuild);
  row.world_ms = 1e3 * median(in_world);
  row.pooled_move_ms = 1e3 * median(pooled_move);
  row.pooled_refit_ms = 1e3 * median(pooled_refit);
  row.degradation = snch.stats().degradation;
  row.node_pairs_ratio = median(ratio);
  return row;
}

struct SkinRow {
  std::string mesh;
  std::uint32_t triangles = 0;
  double animate_ms = 0;  // evaluate the rig, move the vertices, refit: one frame
  double pooled_animate_ms = 0;  // the same in a world of --workers threads
};

// `file`'s animation 0 at 60 Hz over `frames` frames, in a world of one
// thread and, frame by frame beside it, in one of `workers`.
SkinRow skin_row(const std::string& assets, const std::string& file, int frames, unsigned workers) {
  std::vector<io::GltfMesh> parts;
  Status status = io::load_gltf(assets + "/" + file, io::GltfLoadOptions{}, parts);
  if (!status || parts.empty() || !parts[0].rig) throw std::runtime_error(file + ": no rig (" + status.message() + ")");
  const io::GltfMesh& m = parts[0];
  SkinRow row{file, 0, 0.0, 0.0};
  runtime::WorldSettings pooled;
  pooled.workers = workers;
  runtime::World world{runtime::WorldSettings{}}, pooled_world{pooled};
  std::vector<double> times[2];
  runtime::Handle handles[2];
  for (int pass = 0; pass < (workers > 1 ? 2 : 1); ++pass) {
    runtime::World& w = pass == 0 ? world : pooled_world;
    const runtime::Handle h = handles[pass] =
        w.create_mesh({m.positions.data(), static_cast<std::uint32_t>(m.positions.size() / 3), m.indices.data(),
                       static_cast<std::uint32_t>(m.indices.size() / 3)},
                      status);
    if (!status || !w.set_rig(h, m.rig, status)) throw std::runtime_error(file + ": " + status.message());
    row.triangles = w.mesh(h).triangle_count();
  }
  std::vector<Vec3> positions;
  for (int f = 0; f < frames; ++f)
    for (int pass = 0; pass < (workers > 1 ? 2 : 1); ++pass) {
      runtime::World& w = pass == 0 ? world : pooled_world;
      const runtime::Handle h = handles[pass];
      const auto t0 = Clock::now();
      runtime::MeshRig& rig = *w.rig(h);
      if (!rig.animate(0, f / 60.0, status)) throw std::runtime_error(status.message());
      rig.welded_positions(w.mesh(h), positions);
      if (!w.set_vertices(h, positions, status)) throw std::runtime_error(status.message());
      times[pass].push_back(seconds_since(t0));
    }
  row.animate_ms = 1e3 * median(times[0]);
  row.pooled_animate_ms = 1e3 * median(times[1]);
  return row;
}

struct TrackRow {
  int frames = 0;
  long reference = 0, kept = 0, lost = 0, spurious = 0;
};

// Whether an LMD of `found` has the same closest points as `p` (to `tolerance`).
bool matched(const LmdPair& p, const std::vector<LmdPair>& found, double tolerance) {
  for (const LmdPair& q : found)
    if (glm::length(q.point_a - p.point_a) <= tolerance && glm::length(q.point_b - p.point_b) <= tolerance)
      return true;
  return false;
}

// A 10,082-triangle sheet under the wave (2 mm, 10 cm wavelength, 60 Hz
// frames), a 1 cm ball 1 mm above the wave's crest: the LMDs
// of each frame tracked onto the next shape (one local update, as the local
// thread does after a deformation), against the brute-force reference.
TrackRow track_row(int frames) {
  const Shape shape = sheet(71);
  Status status;
  const Mesh rest = Mesh::build(shape.input(), status);
  Mesh mesh = rest;
  Snch snch(rest);
  const Shape ball = sphere(0.01, 12);
  const Mesh probe = Mesh::build(ball.input(), status);
  if (!status) throw std::runtime_error("sphere: " + status.message());
  const Snch probe_snch(probe);
  const Pose probe_pose{glm::dmat3(1.0), Vec3(0.1, 0.1, 0.002 + 0.001 + 0.01)};
  const double cutoff = 0.005, tolerance = 1e-9;
  TrackRow row;
  std::vector<double> xyz;
  wave(rest, 0, 2, 0.002, 0.1, xyz);
  mesh.set_vertices(xyz.data(), mesh.vertex_count());
  snch.refit(mesh);
  PairState state;
  ProximityResult start;
  find_lmds({&probe, &probe_snch, probe_pose, &mesh, &snch, Pose{}, cutoff}, Method::Precise, state, start);
  std::vector<LmdPair> tracked = start.lmds;
  LocalTracker tracker;
  for (int f = 1; f <= frames; ++f) {
    wave(rest, f, 2, 0.002, 0.1, xyz);
    mesh.set_vertices(xyz.data(), mesh.vertex_count());
    snch.refit(mesh);
    LocalTrackingStats stats;
    tracker.update({&probe, &probe_snch, probe_pose, &mesh, &snch, Pose{}, cutoff}, tracked, stats);
    PairState s;
    ProximityResult ref;
    find_lmds({&probe, &probe_snch, probe_pose, &mesh, &snch, Pose{}, cutoff}, Method::Reference, s, ref);
    for (const LmdPair& p : ref.lmds) (matched(p, tracked, tolerance) ? row.kept : row.lost) += 1;
    for (const LmdPair& p : tracked)
      if (p.distance <= cutoff && !matched(p, ref.lmds, tolerance)) ++row.spurious;
    row.reference += static_cast<long>(ref.lmds.size());
    ++row.frames;
    // What the next frame starts from: the global search's set, as the
    // threads would have it within a frame or two (a lost LMD is a birth
    // the search finds, not one tracking can).
    ProximityResult fresh;
    find_lmds({&probe, &probe_snch, probe_pose, &mesh, &snch, Pose{}, cutoff}, Method::Precise, state, fresh);
    tracked = fresh.lmds;
  }
  return row;
}

struct ChurnRow {
  double seconds = 0;
  int made = 0;
  double haptic_p50_ms = 0, haptic_p99_ms = 0, haptic_max_ms = 0;
  double still_p99_ms = 0, still_max_ms = 0;  // the same run with nothing made or destroyed
};

// The bunny held 1 mm from a static bunny by the scripted device; a small
// cube made within the tool's cutoff and destroyed again at `rate` Hz.
ChurnRow churn(const std::string& bunny_path, double seconds, double rate) {
  io::ObjData obj;
  const Status read = io::read_obj(bunny_path, obj);
  if (!read) throw std::runtime_error(read.message());
  const double cube_corners[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  std::vector<double> cube;
  for (double c : cube_corners) cube.push_back(0.005 * c);
  const std::vector<std::uint32_t> cube_indices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                                   2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
  ChurnRow row;
  row.seconds = seconds;
  for (int pass = 0; pass < 2; ++pass) {
    const bool changing = pass == 1;
    runtime::World world{runtime::WorldSettings{}};
    Status status;
    const runtime::Handle mesh = world.create_mesh(
        {obj.positions.data(), static_cast<std::uint32_t>(obj.positions.size() / 3), obj.indices.data(),
         static_cast<std::uint32_t>(obj.indices.size() / 3)},
        status);
    const runtime::Handle cube_mesh = world.create_mesh({cube.data(), 8, cube_indices.data(), 12}, status);
    if (!status) throw std::runtime_error(status.message());
    const Aabb box = world.mesh(mesh).bounds();
    const double width = box.max.x - box.min.x;
    world.create_body(mesh, runtime::BodyType::Static, Pose{}, Vec3(0.0));
    // The tool beside the wall along +x, 1 mm past its box: some of it within the cutoff.
    const Pose held{glm::dmat3(1.0), Vec3(width + 0.001, 0.0, 0.0)};
    const runtime::Handle tool = world.create_body(mesh, runtime::BodyType::Tool, held, Vec3(0.0));
    runtime::ScriptedDevice device({runtime::ScriptedPose::of(held)}, 1.0, false);
    world.set_device(tool, runtime::Device::borrowed(device));
    runtime::ThreadSettings settings;
    if (!world.start_threads(settings, status)) throw std::runtime_error(status.message());
    const auto start = Clock::now();
    int made = 0;
    while (seconds_since(start) < seconds) {
      if (changing) {
        // Between the two bunnies' boxes, near the tool's face.
        const Pose at{glm::dmat3(1.0), Vec3(box.max.x - 0.004, 0.5 * (box.min.y + box.max.y), 0.0)};
        const runtime::Handle h = world.create_body(cube_mesh, runtime::BodyType::Static, at, Vec3(0.0));
        std::this_thread::sleep_for(std::chrono::duration<double>(0.5 / rate));
        world.destroy_body(h);
        ++made;
        std::this_thread::sleep_for(std::chrono::duration<double>(0.5 / rate));
      } else {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
    }
    const runtime::LoopSummary haptic = world.threads()->loop_summary(runtime::Role::Haptic);
    world.stop_threads();
    if (changing) {
      row.made = made;
      row.haptic_p50_ms = 1e3 * haptic.period_p50;
      row.haptic_p99_ms = 1e3 * haptic.period_p99;
      row.haptic_max_ms = 1e3 * haptic.period_max;
    } else {
      row.still_p99_ms = 1e3 * haptic.period_p99;
      row.still_max_ms = 1e3 * haptic.period_max;
    }
  }
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 60;
  int workers = 1;
  double churn_seconds = 10.0;
  std::string json_path;
  std::string assets = PROX_SHARED_ASSETS_DIR;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--frames" && has_value) {
      frames = std::atoi(argv[++i]);
    } else if (a == "--workers" && has_value) {
      workers = std::atoi(argv[++i]);
    } else if (a == "--churn-seconds" && has_value) {
      churn_seconds = std::atof(argv[++i]);
    } else if (a == "--json" && has_value) {
      json_path = argv[++i];
    } else if (a == "--help" || a == "-h") {
      std::printf("usage: proxima_deform_bench [--frames N] [--workers N] [--churn-seconds S] [--json FILE]\n");
      return 0;
    } else {
      std::fprintf(stderr, "proxima_deform_bench: unknown option '%s' (--help)\n", a.c_str());
      return 2;
    }
  }
  if (frames < 1 || workers < 1 || workers > 256 || !(churn_seconds >= 0.0)) {
    std::fprintf(stderr,
                 "proxima_deform_bench: --frames must be >= 1, --workers in [1, 256] and --churn-seconds >= 0\n");
    return 2;
  }
  try {
    std::vector<RefitRow> rows;
    // Sheets of about 1k, 10k, 60k and 100k triangles under a 5 mm wave of
    // 10 cm wavelength travelling at 6 cm/s, and the bunny bent by it.
    for (const int n : {23, 71, 173, 224}) rows.push_back(refit_row(sheet(n), frames, 2, 0.005, 0.1, workers));
    io::ObjData obj;
    const Status read = io::read_obj(assets + "/bunny.obj", obj);
    if (!read) throw std::runtime_error(read.message());
    rows.push_back(refit_row({"bunny", obj.positions, obj.indices}, frames, 1, 0.005, 0.1, workers));

    std::printf("%-13s %9s %9s %9s %10s %10s %8s %11s %13s\n", "mesh", "triangles", "move ms", "refit ms",
                "rebuild ms", "set_vert ms", "rebuilds", "degradation", "node pairs x");
    for (const RefitRow& r : rows)
      std::printf("%-13s %9u %9.3f %9.3f %10.3f %10.3f %8d %11.3f %13.3f\n", r.mesh.c_str(), r.triangles,
                  r.move_ms, r.refit_ms, r.rebuild_ms, r.world_ms, r.rebuilds, r.degradation,
                  r.node_pairs_ratio);
    if (workers > 1) {
      std::printf("on %d threads, beside the above frame by frame (the same trees):\n%-13s %9s %9s %9s\n", workers,
                  "mesh", "triangles", "move ms", "refit ms");
      for (const RefitRow& r : rows)
        std::printf("%-13s %9u %9.3f %9.3f\n", r.mesh.c_str(), r.triangles, r.pooled_move_ms, r.pooled_refit_ms);
    }
    std::vector<SkinRow> skins;
    for (const char* file : {"gltf/RiggedFigure.glb", "gltf/RecursiveSkeletons.glb"})
      skins.push_back(skin_row(assets, file, frames, static_cast<unsigned>(workers)));
    for (const SkinRow& s : skins) {
      std::printf("skin: %s, %u triangles: proxMesh_Animate's work (evaluate, move, refit) %.3f ms a frame",
                  s.mesh.c_str(), s.triangles, s.animate_ms);
      if (workers > 1) std::printf(" (on %d threads: %.3f ms)", workers, s.pooled_animate_ms);
      std::printf("\n");
    }
    const TrackRow tr = track_row(std::min(frames, 60));
    std::printf(
        "track: %d frames of a waved 10k sheet under a ball: %ld reference LMDs, %ld kept by one local update, "
        "%ld lost (births for the global search), %ld spurious\n",
        tr.frames, tr.reference, tr.kept, tr.lost, tr.spurious);
    ChurnRow c;
    if (churn_seconds > 0.0) {
      c = churn(assets + "/bunny.obj", churn_seconds, 100.0);
      std::printf(
          "churn: %d bodies made and destroyed at 100 Hz in %.0f s beside a held tool: haptic period p50 %.3f "
          "ms, p99 %.3f ms, max %.3f ms (a still scene, same run: p99 %.3f ms, max %.3f ms)\n",
          c.made, c.seconds, c.haptic_p50_ms, c.haptic_p99_ms, c.haptic_max_ms, c.still_p99_ms, c.still_max_ms);
    }
    if (!json_path.empty()) {
      JsonWriter j;
      j.begin_object();
      j.key("frames").value(frames);
      j.key("workers").value(workers);
      j.key("refit").begin_array();
      for (const RefitRow& r : rows) {
        j.begin_object();
        j.key("mesh").value(r.mesh);
        j.key("triangles").value(static_cast<long long>(r.triangles));
        j.key("move_ms").value(r.move_ms);
        j.key("refit_ms").value(r.refit_ms);
        j.key("rebuild_ms").value(r.rebuild_ms);
        j.key("set_vertices_ms").value(r.world_ms);
        j.key("rebuilds").value(r.rebuilds);
        j.key("degradation").value(r.degradation);
        j.key("node_pairs_ratio").value(r.node_pairs_ratio);
        if (workers > 1) {
          j.key("pooled_move_ms").value(r.pooled_move_ms);
          j.key("pooled_refit_ms").value(r.pooled_refit_ms);
        }
        j.end_object();
      }
      j.end_array();
      j.key("skin").begin_array();
      for (const SkinRow& s : skins) {
        j.begin_object();
        j.key("mesh").value(s.mesh);
        j.key("triangles").value(static_cast<long long>(s.triangles));
        j.key("animate_ms").value(s.animate_ms);
        if (workers > 1) j.key("pooled_animate_ms").value(s.pooled_animate_ms);
        j.end_object();
      }
      j.end_array();
      j.key("track").begin_object();
      j.key("frames").value(tr.frames);
      j.key("reference").value(static_cast<long long>(tr.reference));
      j.key("kept").value(static_cast<long long>(tr.kept));
      j.key("lost").value(static_cast<long long>(tr.lost));
      j.key("spurious").value(static_cast<long long>(tr.spurious));
      j.end_object();
      j.key("churn").begin_object();
      j.key("seconds").value(c.seconds);
      j.key("bodies").value(c.made);
      j.key("haptic_period_p50_ms").value(c.haptic_p50_ms);
      j.key("haptic_period_p99_ms").value(c.haptic_p99_ms);
      j.key("haptic_period_max_ms").value(c.haptic_max_ms);
      j.key("still_period_p99_ms").value(c.still_p99_ms);
      j.key("still_period_max_ms").value(c.still_max_ms);
      j.end_object();
      j.end_object();
      std::ofstream(json_path) << j.str() << "\n";
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "proxima_deform_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
