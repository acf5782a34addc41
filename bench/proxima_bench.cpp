// proxima_bench: run time against error on named scenes, every method side by
// side on the same poses in one run (issue 5, docs/benchmarks.md).
//
//   proxima_bench [--scene NAME|GROUP|all] [--poses N] [--out DIR] [--reference-every K]
//                 [--local-reps R] [--force-reps R] [--meshes DIR] [--scaling-poses N]
//                 [--scaling-reference-every K] [--cad-poses N] [--max-triangles N] [--list]
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
#include "common/json_writer.h"
#include "contact/force.h"
#include "contact/global_search.h"
#include "contact/proximity.h"
#include "io/obj.h"
#if PROX_WITH_GLTF
#include "io/gltf.h"
#endif
#include "runtime/haptic.h"
#include "runtime/scripted_device.h"
#include "runtime/threads.h"
#include "runtime/world.h"

#ifdef PROX_BENCH_WITH_COAL
#include "coal_peer.h"
#else
namespace prox::bench {
class CoalPeer;
}
#endif

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#ifdef PROX_BENCH_WITH_FCL
#include <fcl/config.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/distance.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

namespace prox::bench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPiValue = 3.14159265358979323846;

struct UserError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// ---- statistics ----------------------------------------------------------------

// Nearest-rank percentile of the finite values (NaN when there are none).
double percentile(std::vector<double> v, double p) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * double(v.size() - 1) + 0.5))];
}
double median(std::vector<double> v) { return percentile(std::move(v), 0.5); }
double maximum(const std::vector<double>& v) {
  double m = kNaN;
  for (double x : v)
    if (std::isfinite(x) && !(x <= m)) m = x;
  return m;
}
double ratio(double a, double b) { return std::isfinite(a) && std::isfinite(b) && b > 0.0 ? a / b : kNaN; }

// ---- JSON ------------------------------------------------------------------------

using Json = JsonWriter;

void write_file(const std::string& path, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw UserError(path + ": cannot write");
  std::fputs(text.c_str(), f);
  if (std::fclose(f) != 0) throw UserError(path + ": cannot write");
}

// ---- models ----------------------------------------------------------------------

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
  std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fcl;
  std::vector<double> fcl_build_seconds;
  std::size_t fcl_memory_bytes = 0;
#endif
#ifdef PROX_BENCH_WITH_COAL
  std::uint32_t coal = 0;  // the peer's id for this mesh
  std::vector<double> coal_build_seconds;
#endif
};

std::string asset_path(const std::string& name) {
  if (const char* dir = std::getenv("PROXIMA_ASSETS")) return std::string(dir) + "/" + name;
  return std::string(PROX_SHARED_ASSETS_DIR) + "/" + name;
}

constexpr int kBuildRepetitions = 3;  // hierarchy builds per mesh; the median is reported

// Splits every triangle into four at its edge midpoints (shared between the
// two triangles of an edge, so the mesh stays welded). The surface is the
// same, so distances stay comparable across levels.
void subdivide(std::vector<double>& positions, std::vector<std::uint32_t>& indices) {
  std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
  auto midpoint = [&](std::uint32_t i, std::uint32_t j) {
    const std::uint64_t key = (std::uint64_t{std::min(i, j)} << 32) | std::max(i, j);
    const auto found = midpoints.find(key);
    if (found != midpoints.end()) return found->second;
    const std::uint32_t v = static_cast<std::uint32_t>(positions.size() / 3);
    double p[3];
    for (std::size_t k = 0; k < 3; ++k) p[k] = 0.5 * (positions[3 * i + k] + positions[3 * j + k]);
    positions.insert(positions.end(), p, p + 3);
    midpoints.emplace(key, v);
    return v;
  };
  std::vector<std::uint32_t> out;
  out.reserve(4 * indices.size());
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
    const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    out.insert(out.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
  }
  indices = std::move(out);
}

void read_source(const MeshSource& source, const std::string& path, std::vector<double>& positions,
                 std::vector<std::uint32_t>& indices) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".obj") {
    io::ObjData obj;
    const Status s = io::read_obj(path, obj);
    if (!s)
      throw UserError(s.message() + (source.generated
                                         ? " (scripts/decimate.py writes it; see docs/benchmarks.md)"
                                         : " (the shared assets: ../shared/assets beside the repository, or "
                                           "-DPROX_SHARED_ASSETS_DIR)"));
    positions = std::move(obj.positions);
    indices = std::move(obj.indices);
    return;
  }
#if PROX_WITH_GLTF
  std::vector<io::GltfMesh> meshes;
  io::GltfLoadOptions options;
  options.mode = source.part < 0 ? io::GltfSceneMode::Merged : io::GltfSceneMode::PerNode;
  const Status s = io::load_gltf(path, options, meshes);
  if (!s)
    throw UserError(
        s.message() +
        " (the shared assets: ../shared/assets beside the repository, or -DPROX_SHARED_ASSETS_DIR)");
  const std::size_t i = source.part < 0 ? 0 : static_cast<std::size_t>(source.part);
  if (i >= meshes.size())
    throw UserError(path + ": no node " + std::to_string(source.part) + " with triangles (" +
                    std::to_string(meshes.size()) + " in PerNode order)");
  positions = std::move(meshes[i].positions);
  indices = std::move(meshes[i].indices);
#else
  throw UserError(path + ": built without glTF support (PROX_WITH_GLTF=OFF)");
#endif
}

std::shared_ptr<Model> load_model(const MeshSource& source, const std::string& meshes_dir, CoalPeer* coal) {
  auto model = std::make_shared<Model>();
  model->name = source.label;
  model->file = source.generated ? meshes_dir + "/" + source.file : asset_path(source.file);
  std::vector<double> positions;
  std::vector<std::uint32_t> indices;
  read_source(source, model->file, positions, indices);
  for (double& x : positions) x *= source.scale;
  for (int i = 0; i < source.subdivisions; ++i) subdivide(positions, indices);
  const MeshInput input{positions.data(), static_cast<std::uint32_t>(positions.size() / 3), indices.data(),
                        static_cast<std::uint32_t>(indices.size() / 3)};
  Status status;
  model->mesh = Mesh::build(input, status);
  if (!status) throw UserError(model->file + ": " + status.message());
  const Mesh& m = model->mesh;
  model->size = glm::length(m.bounds().max - m.bounds().min);
  model->box_centre = 0.5 * (m.bounds().max + m.bounds().min);
  double area = 0.0;
  Vec3 sum(0.0);
  std::vector<double> areas;
  for (std::uint32_t t = 0; t < m.triangle_count(); ++t) {
    const Triangle tri = m.triangle(t);
    const double a = 0.5 * glm::length(glm::cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0]));
    area += a;
    sum += a * (tri.v[0] + tri.v[1] + tri.v[2]) / 3.0;
    areas.push_back(a);
  }
  model->centroid = area > 0.0 ? sum / area : model->box_centre;
  model->max_over_median_area = ratio(maximum(areas), median(areas));
  for (int i = 0; i < kBuildRepetitions; ++i) {
    model->snch = std::make_unique<Snch>(m);
    model->snch_build_seconds.push_back(model->snch->stats().build_seconds);
  }
#ifdef PROX_BENCH_WITH_FCL
  // The same welded geometry as the engine's, so both answer for one mesh.
  std::vector<fcl::Vector3d> points(m.vertex_count());
  for (std::uint32_t v = 0; v < m.vertex_count(); ++v)
    points[v] = fcl::Vector3d(m.vertex(v).x, m.vertex(v).y, m.vertex(v).z);
  std::vector<fcl::Triangle> triangles(m.triangle_count());
  for (std::uint32_t t = 0; t < m.triangle_count(); ++t)
    triangles[t] = fcl::Triangle(m.indices(t)[0], m.indices(t)[1], m.indices(t)[2]);
  for (int i = 0; i < kBuildRepetitions; ++i) {
    const auto start = Clock::now();
    auto bvh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    bvh->beginModel(static_cast<int>(triangles.size()), static_cast<int>(points.size()));
    bvh->addSubModel(points, triangles);
    bvh->endModel();
    model->fcl_build_seconds.push_back(seconds_since(start));
    model->fcl = bvh;
  }
  // What BVHModel::memUsage prints (it returns a status, not the size).
  const auto& bvh = *model->fcl;
  model->fcl_memory_bytes = sizeof(fcl::BVNode<fcl::OBBRSSd>) * static_cast<std::size_t>(bvh.getNumBVs()) +
                            sizeof(fcl::Triangle) * static_cast<std::size_t>(bvh.num_tris) +
                            sizeof(fcl::Vector3d) * static_cast<std::size_t>(bvh.num_vertices) + sizeof(bvh);
#endif
#ifdef PROX_BENCH_WITH_COAL
  const CoalBuild built = coal->build(m, kBuildRepetitions);
  model->coal = built.mesh;
  model->coal_build_seconds = built.seconds;
#else
  (void)coal;
#endif
  std::printf(
      "%s: %u triangles, size %.3f m, largest / median triangle area %.0f; SNCH %u nodes, built in %.1f ms "
      "(median of %d), %.2f MiB",
      model->name.c_str(), m.triangle_count(), model->size, model->max_over_median_area,
      model->snch->stats().nodes, median(model->snch_build_seconds) * 1e3, kBuildRepetitions,
      double(model->snch->stats().memory_bytes) / (1 << 20));
#ifdef PROX_BENCH_WITH_FCL
  std::printf("; FCL OBBRSS BVH %.1f ms, %.2f MiB\n", median(model->fcl_build_seconds) * 1e3,
              double(model->fcl_memory_bytes) / (1 << 20));
#else
  std::printf("\n");
#endif
  return model;
}

#ifdef PROX_BENCH_WITH_FCL
fcl::Transform3d to_fcl(const Pose& p) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  fcl::Matrix3d r;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) r(row, col) = p.rotation[col][row];  // glm is column-major
  tf.linear() = r;
  tf.translation() = fcl::Vector3d(p.translation.x, p.translation.y, p.translation.z);
  return tf;
}
#endif

// ---- scenes --------------------------------------------------------------------

enum class PathKind {
  Translate,  // B along `direction`, linear in the offset between the offsets of two gaps
  Rotate,     // path R: B turned about its centroid, x set per pose for a gap
};

MeshSource bunny_source() { return {"bunny", "bunny.obj", -1, 1.0, 0, false}; }
// The CAD parts, by node in PerNode order (sizes in mm, the file's units):
// 2CylinderEngine node 8 "body_1" (the crankcase, 190 x 271 x 233), node 9
// "body_2" (a cylinder block, 161 x 160 x 190; the part the accuracy tests
// use); ReciprocatingSaw node 0 "body_1" and node 2 "body_5", the two halves
// of the housing (152 x 42 x 147 each, split at y = 0).
MeshSource engine_part(int node, const char* name) {
  return {std::string("engine ") + name, "gltf/2CylinderEngine.glb", node, 0.001, 0, false};
}
MeshSource saw_part(int node, const char* name) {
  return {std::string("saw ") + name, "gltf/ReciprocatingSaw.glb", node, 0.001, 0, false};
}

struct Scene {
  std::string name;
  std::string description;
  std::string group;  // "bunny", "cad" or "scaling"
  MeshSource a, b;    // A fixed at the identity, B held and moved
  PathKind kind = PathKind::Translate;
  double far = 0.05, near = 0.0005;  // minimum distance at the first and the last pose
  bool soft = false;                 // force settings: soft, else hard
  std::string same_as;               // another name for the same scene
  Vec3 direction{1.0, 0.0, 0.0};     // Translate: B moves along this (unit)
  bool centre_b_on_a = false;  // offset 0 puts B's box centre on A's; else B stays where its file has it
  // > 0: the hard settings scaled so that the cutoff is this times the larger
  // bounding-box diagonal (the bunny pair's 5 mm on 0.249 m is 0.020), and
  // the path runs from 3 to 0.1 cutoffs: the bunny's 10 would spend two
  // thirds of the CAD scenes' run far from contact, where the exact
  // minimum distance and the reference still cost 0.1 s a pose.
  double cutoff_over_size = 0.0;
};

constexpr double kCadCutoffOverSize = 0.02;
constexpr double kCadFarOverCutoff = 3.0;

std::vector<Scene> make_scenes() {
  std::vector<Scene> all;
  auto bunny_scene = [&](const char* name, const char* description, PathKind kind, double near, bool soft,
                         const char* same_as) {
    Scene s;
    s.name = name, s.description = description, s.group = "bunny";
    s.a = s.b = bunny_source();
    s.kind = kind, s.near = near, s.soft = soft, s.same_as = same_as;
    all.push_back(s);
  };
  bunny_scene("path-t",
              "Path T (issue 5): bunny B translated along +x from 50 mm to 0.5 mm from bunny A, linear in x; "
              "hard force settings, cutoff 5 mm. The paper's hard scene (6.1) is this path.",
              PathKind::Translate, 0.0005, false, "paper-hard");
  bunny_scene(
      "path-r",
      "Path R (issue 5): bunny B turned by 90 deg * s about normalize(0.3, 1, 0.2) through its centroid "
      "and moved along +x so that the minimum distance is 50 mm * 0.01^s (bisection on x); hard force "
      "settings, cutoff 5 mm.",
      PathKind::Rotate, 0.0005, false, "");
  bunny_scene(
      "paper-hard",
      "The paper's 6.1 benchmark with the hard force settings: path T (50 mm to 0.5 mm), cutoff 5 mm.",
      PathKind::Translate, 0.0005, false, "path-t");
  bunny_scene(
      "paper-soft",
      "The paper's 6.1 benchmark with the soft force settings: bunny B translated along +x from 50 mm to "
      "2 mm from bunny A, linear in x; linear force, cutoff 10 mm.",
      PathKind::Translate, 0.002, true, "");

  // Large and uneven triangles (the paper's case where the original method
  // fails). CAD parts in metres; cutoff 2% of the larger diagonal, the
  // bunny pair's ratio; B moves along a file axis, linear in the offset.
  auto cad_scene = [&](const char* name, const char* description, MeshSource a, MeshSource b, Vec3 direction,
                       bool centre) {
    Scene s;
    s.name = name, s.description = description, s.group = "cad";
    s.a = std::move(a), s.b = std::move(b);
    s.direction = direction, s.centre_b_on_a = centre;
    s.cutoff_over_size = kCadCutoffOverSize;
    all.push_back(s);
  };
  cad_scene(
      "cad-engine",
      "2CylinderEngine parts: the cylinder block (node 9, body_2) pulled out of the crankcase (node 8, "
      "body_1) along +x from where the two are assembled in the file, linear in the offset from 3 to 0.1 "
      "cutoffs; hard force settings scaled to a cutoff of 2% of the larger diagonal.",
      engine_part(8, "body_1"), engine_part(9, "body_2"), Vec3(1.0, 0.0, 0.0), false);
  cad_scene(
      "cad-saw",
      "ReciprocatingSaw housing halves: node 2 (body_5) pulled off node 0 (body_1) along +y from where they "
      "are assembled in the file, linear in the offset from 3 to 0.1 cutoffs; hard force settings scaled "
      "to a cutoff of 2% of the larger diagonal.",
      saw_part(0, "body_1"), saw_part(2, "body_5"), Vec3(0.0, 1.0, 0.0), false);
  cad_scene(
      "cad-bunny-engine",
      "The bunny (B, 27,864 small triangles) against the 2CylinderEngine cylinder block (A, node 9, large "
      "and thin triangles): B's box centre on A's, then along +x, linear in the offset from 3 to 0.1 "
      "cutoffs; hard force settings scaled to a cutoff of 2% of the larger diagonal.",
      engine_part(9, "body_2"), bunny_source(), Vec3(1.0, 0.0, 0.0), true);
  cad_scene(
      "cad-saw-engine",
      "ReciprocatingSaw housing half (B, node 0, body_1) against the 2CylinderEngine cylinder block (A, node "
      "9): B's box centre on A's, then along +z, linear in the offset from 3 to 0.1 cutoffs; hard force "
      "settings scaled to a cutoff of 2% of the larger diagonal.",
      engine_part(9, "body_2"), saw_part(0, "body_1"), Vec3(0.0, 0.0, 1.0), true);

  // Scaling: path T on the bunny at five resolutions, A and B the same mesh.
  // Decimated by scripts/decimate.py (quadric simplification, so the shape
  // and the path move a little); subdivided by 1 -> 4 midpoint splits (the
  // same surface, so the same path and distances).
  struct Level {
    const char* name;
    MeshSource source;
  };
  const Level levels[] = {
      {"scaling-2k", {"bunny 2k (decimated)", "bunny-2k.obj", -1, 1.0, 0, true}},
      {"scaling-7k", {"bunny 7k (decimated)", "bunny-7k.obj", -1, 1.0, 0, true}},
      {"scaling-28k", bunny_source()},
      {"scaling-111k", {"bunny 111k (subdivided once)", "bunny.obj", -1, 1.0, 1, false}},
      {"scaling-446k", {"bunny 446k (subdivided twice)", "bunny.obj", -1, 1.0, 2, false}},
  };
  for (const Level& level : levels) {
    Scene s;
    s.name = level.name, s.group = "scaling";
    s.a = s.b = level.source;
    s.description =
        "Scaling: path T (B along +x from 50 mm to 0.5 mm, hard force settings, cutoff 5 mm) with A and "
        "B both " +
        level.source.label + ".";
    all.push_back(s);
  }
  return all;
}

const std::vector<Scene>& scenes() {
  static const std::vector<Scene> all = make_scenes();
  return all;
}

struct PosePoint {
  Pose pose;
  double s = 0.0, x = 0.0, target_gap = 0.0;
};

PairQuery make_query(const Model& a, const Model& b, const Pose& pose_b, double cutoff) {
  return {&a.mesh, a.snch.get(), Pose{}, &b.mesh, b.snch.get(), pose_b, cutoff};
}

// The x at which `at(x) = at(0) + x * dir` puts B exactly `gap` from A. The
// minimum distance d(x) changes no faster than x, so from an x where the
// bounding boxes are `gap` apart along dir, steps of x -= d(x) - gap never
// bring B closer than `gap`; head-on they arrive in two or three steps.
// Where they crawl (a grazing approach), a bisection between a closer x and
// the last step finishes. Either way no pair is closer than `gap`, and the
// result is within 1e-12 of the model sizes of the exact x.
template <typename PoseAt>
double x_at_gap(const Model& a, const Model& b, double gap, const Vec3& dir, PoseAt at) {
  const Pose start = at(0.0);
  double reach_a = -kInf, reach_b = kInf;  // A's box forward along dir, B's box backward
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 pa((corner & 1 ? a.mesh.bounds().max : a.mesh.bounds().min).x,
                  (corner & 2 ? a.mesh.bounds().max : a.mesh.bounds().min).y,
                  (corner & 4 ? a.mesh.bounds().max : a.mesh.bounds().min).z);
    const Vec3 pb((corner & 1 ? b.mesh.bounds().max : b.mesh.bounds().min).x,
                  (corner & 2 ? b.mesh.bounds().max : b.mesh.bounds().min).y,
                  (corner & 4 ? b.mesh.bounds().max : b.mesh.bounds().min).z);
    reach_a = std::max(reach_a, glm::dot(pa, dir));
    reach_b = std::min(reach_b, glm::dot(start.apply(pb), dir));
  }
  double lo = 0.0, hi = std::max(0.0, reach_a - reach_b) + gap;
  const double tolerance = 1e-12 * (a.size + b.size);
  double excess = 0.0;
  for (int i = 0; i < 8; ++i) {
    const double d = minimum_distance(make_query(a, b, at(hi), 0.0), kInf) - gap;
    if (!(d > 0.0)) {  // only rounding can do this: back to the last x known to be far enough
      hi += excess;
      break;
    }
    excess = d;
    if (excess <= tolerance) return hi;
    hi -= excess;
  }
  if (!any_closer_than(make_query(a, b, at(lo), 0.0), gap))
    throw UserError(a.name + " / " + b.name + ": the path's offset 0 is not within " + std::to_string(gap) +
                    " m, so the bisection has no bracket");
  // A closer x for the bisection's bracket, in growing steps back from hi
  // (every x that is not closer than `gap` is a better hi).
  for (double step = std::max(excess, tolerance);; step *= 4.0) {
    const double x = std::max(lo, hi - step);
    if (x == lo || any_closer_than(make_query(a, b, at(x), 0.0), gap)) {
      lo = x;
      break;
    }
    hi = x;
  }
  for (int i = 0; i < 100 && hi - lo > tolerance; ++i) {
    const double mid = 0.5 * (lo + hi);
    (any_closer_than(make_query(a, b, at(mid), 0.0), gap) ? lo : hi) = mid;
  }
  return hi;
}

std::vector<PosePoint> make_path(const Scene& scene, double far, double near, const Model& a, const Model& b,
                                 int n) {
  std::vector<PosePoint> path;
  if (scene.kind == PathKind::Translate) {
    const Vec3 base = scene.centre_b_on_a ? a.box_centre - b.box_centre : Vec3(0.0);
    const Vec3 dir = scene.direction;
    auto at = [&](double x) { return Pose{glm::dmat3(1.0), base + x * dir}; };
    const double x0 = x_at_gap(a, b, far, dir, at), x1 = x_at_gap(a, b, near, dir, at);
    for (int i = 0; i < n; ++i) {
      const double s = n > 1 ? double(i) / double(n - 1) : 1.0;
      PosePoint p;
      p.s = s;
      p.x = x0 + (x1 - x0) * s;
      p.pose = at(p.x);
      p.target_gap = kNaN;  // linear in x, not in the gap
      path.push_back(p);
    }
  } else {
    const Vec3 axis = glm::normalize(Vec3(0.3, 1.0, 0.2));
    const Vec3 c = b.centroid;
    for (int i = 0; i < n; ++i) {
      const double s = n > 1 ? double(i) / double(n - 1) : 1.0;
      const glm::dmat3 r = glm::mat3_cast(glm::angleAxis(0.5 * kPiValue * s, axis));
      const Vec3 base = c - r * c;  // turn about the centroid
      auto at = [&](double x) { return Pose{r, base + Vec3(x, 0.0, 0.0)}; };
      PosePoint p;
      p.s = s;
      p.target_gap = far * std::pow(near / far, s);
      p.x = x_at_gap(a, b, p.target_gap, Vec3(1.0, 0.0, 0.0), at);
      p.pose = at(p.x);
      path.push_back(p);
    }
  }
  return path;
}

// ---- one step ------------------------------------------------------------------

// One row of the per-step CSV: one method at one pose. NaN: not applicable.
struct Row {
  int step = 0;
  double s = 0.0, x = 0.0, target_gap = kNaN, exact_min = kNaN;
  std::string method;
  double query_ms = kNaN;  // precise/original: global search + reduction; others: the one query
  double global_ms = kNaN, reduction_ms = kNaN;
  double local_ms = kNaN, local_in = kNaN, local_out = kNaN, local_cache_hits = kNaN;
  double local_distance_evaluations = kNaN;
  double force_eval_ns = kNaN;
  double candidates = kNaN, lmds = kNaN;
  double node_pairs = kNaN, leaf_pairs = kNaN, visibility_rejections = kNaN, normal_rejections = kNaN;
  double distance_evaluations = kNaN, reduction_cache_hits = kNaN;
  double min_distance = kNaN;
  Vec3 force{kNaN}, torque{kNaN};
  // Against the reference at this pose (when it was computed).
  double ref_lmds = kNaN, recalled = kNaN, confirmed = kNaN, recalled_loose = kNaN, confirmed_loose = kNaN;
  double min_distance_error = kNaN, force_error = kNaN, torque_error = kNaN;
  double local_recalled = kNaN, local_confirmed = kNaN;  // the locally updated set at this pose
};

using Column = std::pair<const char*, std::function<double(const Row&)>>;
const std::vector<Column>& columns() {
  static const std::vector<Column> c = {
      {"s", [](const Row& r) { return r.s; }},
      {"x", [](const Row& r) { return r.x; }},
      {"target_gap", [](const Row& r) { return r.target_gap; }},
      {"exact_min_distance", [](const Row& r) { return r.exact_min; }},
      {"query_ms", [](const Row& r) { return r.query_ms; }},
      {"global_ms", [](const Row& r) { return r.global_ms; }},
      {"reduction_ms", [](const Row& r) { return r.reduction_ms; }},
      {"local_ms", [](const Row& r) { return r.local_ms; }},
      {"local_in", [](const Row& r) { return r.local_in; }},
      {"local_out", [](const Row& r) { return r.local_out; }},
      {"local_cache_hits", [](const Row& r) { return r.local_cache_hits; }},
      {"local_distance_evaluations", [](const Row& r) { return r.local_distance_evaluations; }},
      {"force_eval_ns", [](const Row& r) { return r.force_eval_ns; }},
      {"candidates", [](const Row& r) { return r.candidates; }},
      {"lmds", [](const Row& r) { return r.lmds; }},
      {"node_pairs", [](const Row& r) { return r.node_pairs; }},
      {"leaf_pairs", [](const Row& r) { return r.leaf_pairs; }},
      {"visibility_rejections", [](const Row& r) { return r.visibility_rejections; }},
      {"normal_rejections", [](const Row& r) { return r.normal_rejections; }},
      {"distance_evaluations", [](const Row& r) { return r.distance_evaluations; }},
      {"reduction_cache_hits", [](const Row& r) { return r.reduction_cache_hits; }},
      {"min_distance", [](const Row& r) { return r.min_distance; }},
      {"force_x", [](const Row& r) { return r.force.x; }},
      {"force_y", [](const Row& r) { return r.force.y; }},
      {"force_z", [](const Row& r) { return r.force.z; }},
      {"force", [](const Row& r) { return glm::length(r.force); }},
      {"torque_x", [](const Row& r) { return r.torque.x; }},
      {"torque_y", [](const Row& r) { return r.torque.y; }},
      {"torque_z", [](const Row& r) { return r.torque.z; }},
      {"torque", [](const Row& r) { return glm::length(r.torque); }},
      {"ref_lmds", [](const Row& r) { return r.ref_lmds; }},
      {"recalled", [](const Row& r) { return r.recalled; }},
      {"confirmed", [](const Row& r) { return r.confirmed; }},
      {"recalled_2mm", [](const Row& r) { return r.recalled_loose; }},
      {"confirmed_2mm", [](const Row& r) { return r.confirmed_loose; }},
      {"min_distance_error", [](const Row& r) { return r.min_distance_error; }},
      {"force_error", [](const Row& r) { return r.force_error; }},
      {"torque_error", [](const Row& r) { return r.torque_error; }},
      {"local_recalled", [](const Row& r) { return r.local_recalled; }},
      {"local_confirmed", [](const Row& r) { return r.local_confirmed; }},
  };
  return c;
}

struct Options {
  std::string scene = "all";
  int poses = 1000;
  std::string out = "bench-results";
  int reference_every = 1;              // 0: never
  int local_reps = 5;                   // local updates per step and method; the median time is kept
  int force_reps = 7;                   // batches of kForceBatch force evaluations; the median is kept
  std::string meshes = "bench-meshes";  // where scripts/decimate.py wrote the decimated bunnies
  int scaling_poses = 200;              // poses per scaling scene (at most --poses)
  int scaling_reference_every = 20;     // the reference on the scaling scenes (0: never)
  int max_triangles = 0;                // skip the scaling levels above this (0: none)
  int cad_poses = 300;                  // poses per CAD scene (at most --poses)
  std::string coal_version;             // the peer's, when it runs
};

constexpr int kForceBatch = 100;
// The original's points are feature points: they are also matched within
// 0.4 cutoffs (2 mm on the bunny pair).
constexpr double kLooseMatchOverCutoff = 0.4;

// How many of `reference` have a match in `found` and how many of `found` have
// one in `reference`: closest points on both sides within `tolerance`.
std::pair<int, int> match(const std::vector<LmdPair>& reference, const std::vector<LmdPair>& found,
                          double tolerance) {
  auto same = [tolerance](const LmdPair& x, const LmdPair& y) {
    return glm::length(x.point_a - y.point_a) <= tolerance && glm::length(x.point_b - y.point_b) <= tolerance;
  };
  int recalled = 0, confirmed = 0;
  for (const LmdPair& r : reference)
    recalled += std::any_of(found.begin(), found.end(), [&](const LmdPair& f) { return same(r, f); });
  for (const LmdPair& f : found)
    confirmed +=
        std::any_of(reference.begin(), reference.end(), [&](const LmdPair& r) { return same(r, f); });
  return {recalled, confirmed};
}

// Median time, in nanoseconds, of what the haptic loop computes each tick
// from a snapshot of `lmds` tracked at `pose`: the contacts re-evaluated at
// the current pose (runtime::evaluate_contacts, here the same pose) and the
// safety gate.
double time_force(const ForceSettings& force, const std::vector<LmdPair>& lmds, const Pose& pose,
                  const Vec3& reference_local, int batches) {
  runtime::ContactSnapshot snapshot;
  const Pose to_local = pose.inverse();
  runtime::HapticContact c;
  for (const LmdPair& p : lmds)
    if (runtime::to_haptic_contact(p, to_local, c)) snapshot.contacts.push_back(c);
  snapshot.tool_pose = pose;
  runtime::SafetyFilter gate;
  std::vector<double> ns;
  volatile double sink = 0.0;
  for (int b = 0; b < batches; ++b) {
    const auto start = Clock::now();
    for (int i = 0; i < kForceBatch; ++i)
      sink =
          sink +
          gate.step(runtime::evaluate_contacts(force, snapshot, pose, reference_local), true, 1e-3).force.x;
    ns.push_back(seconds_since(start) * 1e9 / kForceBatch);
  }
  return median(ns);
}

struct MethodState {
  Method method;
  std::vector<LmdPair> tracked;  // the previous step's set
  std::vector<LmdPair> current;  // this step's
  std::vector<LmdPair> local;    // the previous set updated to this pose
};

// ---- summaries -----------------------------------------------------------------

struct SceneRun {
  const Scene* scene = nullptr;
  const Model* a = nullptr;
  const Model* b = nullptr;
  double far = 0.0, near = 0.0;  // the path's first and last minimum distance
  ForceSettings force;
  std::vector<PosePoint> path;
  std::vector<Row> rows;
  double seconds = 0.0;
  double path_seconds = 0.0;
  int reference_every = 1;
};

std::vector<const Row*> rows_of(const SceneRun& run, const std::string& method, bool contact_only) {
  std::vector<const Row*> out;
  for (const Row& r : run.rows)
    if (r.method == method && (!contact_only || r.exact_min <= run.force.cutoff)) out.push_back(&r);
  return out;
}

std::vector<double> values(const std::vector<const Row*>& rows, double Row::*field) {
  std::vector<double> v;
  for (const Row* r : rows) v.push_back(r->*field);
  return v;
}

void distribution(Json& j, const std::string& name, const std::vector<double>& v) {
  j.key(name).begin_object();
  j.field("median", median(v)).field("p99", percentile(v, 0.99)).field("max", maximum(v));
  j.end_object();
}

// Median, p99 and max of a field over all poses and over the poses in contact
// (exact minimum distance within the cutoff).
void both(Json& j, const SceneRun& run, const std::string& method, const std::string& name,
          double Row::*field) {
  j.key(name).begin_object();
  distribution(j, "all", values(rows_of(run, method, false), field));
  distribution(j, "contact", values(rows_of(run, method, true), field));
  j.end_object();
}

struct Accuracy {
  long long reference = 0, found = 0, recalled = 0, confirmed = 0, recalled_loose = 0, confirmed_loose = 0;
  long long local_found = 0, local_recalled = 0, local_confirmed = 0, poses = 0, missed_minimum = 0;
  double min_error = kNaN, force_error = kNaN, torque_error = kNaN, force_error_median = kNaN;
};

Accuracy accuracy(const SceneRun& run, const std::string& method) {
  Accuracy a;
  std::vector<double> force_errors;
  for (const Row* r : rows_of(run, method, false)) {
    if (!std::isfinite(r->ref_lmds)) continue;
    ++a.poses;
    a.reference += static_cast<long long>(r->ref_lmds);
    a.found += static_cast<long long>(r->lmds);
    a.recalled += static_cast<long long>(r->recalled);
    a.confirmed += static_cast<long long>(r->confirmed);
    a.recalled_loose += static_cast<long long>(r->recalled_loose);
    a.confirmed_loose += static_cast<long long>(r->confirmed_loose);
    if (std::isfinite(r->local_recalled)) {
      a.local_found += static_cast<long long>(r->local_out);
      a.local_recalled += static_cast<long long>(r->local_recalled);
      a.local_confirmed += static_cast<long long>(r->local_confirmed);
    }
    if (r->ref_lmds > 0 && !(r->lmds > 0)) ++a.missed_minimum;
    if (std::isfinite(r->min_distance_error) && !(r->min_distance_error <= a.min_error))
      a.min_error = r->min_distance_error;
    if (std::isfinite(r->force_error) && !(r->force_error <= a.force_error)) a.force_error = r->force_error;
    if (std::isfinite(r->torque_error) && !(r->torque_error <= a.torque_error))
      a.torque_error = r->torque_error;
    force_errors.push_back(r->force_error);
  }
  a.force_error_median = median(force_errors);
  return a;
}

double fraction(long long part, long long whole) { return whole > 0 ? double(part) / double(whole) : kNaN; }

struct Smoothness {
  double max_jump = kNaN, total_variation = kNaN, max_torque_jump = kNaN;
};

Smoothness smoothness(const std::vector<const Row*>& rows) {
  Smoothness s;
  const Row* previous = nullptr;
  for (const Row* r : rows) {
    if (!std::isfinite(r->force.x)) continue;
    if (previous) {
      const double jump = glm::length(r->force - previous->force);
      const double tjump = glm::length(r->torque - previous->torque);
      s.max_jump = std::isfinite(s.max_jump) ? std::max(s.max_jump, jump) : jump;
      s.total_variation = (std::isfinite(s.total_variation) ? s.total_variation : 0.0) + jump;
      s.max_torque_jump = std::isfinite(s.max_torque_jump) ? std::max(s.max_torque_jump, tjump) : tjump;
    }
    previous = r;
  }
  return s;
}

// Per-pose ratio of one method's query time to another's.
std::vector<double> pose_ratios(const SceneRun& run, const std::string& num, const std::string& den,
                                bool contact_only) {
  const auto a = rows_of(run, num, contact_only), b = rows_of(run, den, contact_only);
  std::vector<double> r;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    r.push_back(ratio(a[i]->query_ms, b[i]->query_ms));
  return r;
}

double reduction_ratio(const std::vector<const Row*>& rows, bool maximum_only) {
  double total_c = 0.0, total_l = 0.0, best = kNaN;
  for (const Row* r : rows) {
    if (!(r->lmds > 0)) continue;
    total_c += r->candidates, total_l += r->lmds;
    const double q = r->candidates / r->lmds;
    if (!(q <= best)) best = q;
  }
  return maximum_only ? best : ratio(total_c, total_l);
}

const char* kPeerNote =
    "FCL's distance query returns one closest pair per pose; Proxima returns the whole LMD set (every local "
    "minimum within the cutoff). min-distance is Proxima's own single-pair query (minimum_distance), the "
    "like-for-like peer of FCL's.";

void mesh_json(Json& j, const Model& model, const char* used_as) {
  j.begin_object();
  j.field("name", model.name).field("used_as", used_as);
  j.field("triangles", static_cast<long long>(model.mesh.triangle_count()));
  j.field("vertices", static_cast<long long>(model.mesh.vertex_count()));
  j.field("size", model.size);
  j.field("max_over_median_triangle_area", model.max_over_median_area);
  const SnchStats& st = model.snch->stats();
  j.field("snch_nodes", static_cast<long long>(st.nodes))
      .field("snch_depth", static_cast<long long>(st.depth));
  j.field("snch_unbounded_leaves", static_cast<long long>(st.unbounded_leaves));
  j.field("snch_build_ms", median(model.snch_build_seconds) * 1e3);
  j.field("snch_memory_bytes", st.memory_bytes);
#ifdef PROX_BENCH_WITH_FCL
  j.field("fcl_build_ms", median(model.fcl_build_seconds) * 1e3);
  j.field("fcl_memory_bytes", model.fcl_memory_bytes);
#endif
#ifdef PROX_BENCH_WITH_COAL
  j.field("coal_build_ms", median(model.coal_build_seconds) * 1e3);
#endif
  j.end_object();
}

std::string summary_json(const SceneRun& run, const Options& opt) {
  const Scene& sc = *run.scene;
  const Model& model = *run.b;
  const double size = std::max(run.a->size, run.b->size);
  Json j;
  j.begin_object();
  j.field("scene", sc.name).field("description", sc.description).field("group", sc.group);
  if (!sc.same_as.empty()) j.field("same_as", sc.same_as);
  j.key("path").begin_object();
  j.field("kind", sc.kind == PathKind::Translate ? "translate" : "rotate");
  if (sc.kind == PathKind::Translate) {
    j.key("direction").vec3(sc.direction);
    j.field("b_box_centre_on_a", sc.centre_b_on_a);
  }
  j.field("far_gap", run.far).field("near_gap", run.near).field("poses", static_cast<int>(run.path.size()));
  if (sc.kind == PathKind::Rotate) {
    j.key("axis").vec3(glm::normalize(Vec3(0.3, 1.0, 0.2)));
    j.field("angle_deg", 90.0);
    j.key("centroid").vec3(model.centroid);
  }
  j.field("x_first", run.path.front().x).field("x_last", run.path.back().x);
  j.field("seconds_to_build", run.path_seconds);
  j.end_object();
  j.key("force_settings").begin_object();
  j.field("curve", run.force.curve == ForceCurve::Exponential ? "exponential" : "linear");
  j.field("max_force", run.force.max_force).field("max_torque", run.force.max_torque);
  j.field("safety_distance", run.force.safety_distance).field("cutoff", run.force.cutoff);
  j.field("decay_length", run.force.decay_length);
  j.end_object();
  j.field("cutoff", run.force.cutoff);
  j.field("reference_every", run.reference_every).field("local_reps", opt.local_reps);
  j.field("force_batches", opt.force_reps).field("force_batch_calls", kForceBatch);
  j.field("contact_poses", static_cast<int>(rows_of(run, "precise", true).size()));
  j.field("reference_poses", static_cast<int>(accuracy(run, "precise").poses));
  j.field("seconds", run.seconds);
#ifdef PROX_BENCH_WITH_FCL
  j.field("fcl", true).field("fcl_version", FCL_VERSION);
#else
  j.field("fcl", false);
#endif
#ifdef PROX_BENCH_WITH_COAL
  j.field("coal", true).field("coal_version", opt.coal_version);
#else
  j.field("coal", false);
#endif
  j.field("peer_note", kPeerNote);

  j.key("meshes").begin_array();
  if (run.a == run.b) {
    mesh_json(j, *run.a, "A and B");
  } else {
    mesh_json(j, *run.a, "A");
    mesh_json(j, *run.b, "B");
  }
  j.end_array();

  const double tolerance = 1e-9 * size;
  j.field("size", size).field("loose_match_tolerance", kLooseMatchOverCutoff * run.force.cutoff);
  j.key("methods").begin_object();
  for (const char* m : {"precise", "original"}) {
    j.key(m).begin_object();
    both(j, run, m, "query_ms", &Row::query_ms);
    both(j, run, m, "global_ms", &Row::global_ms);
    both(j, run, m, "reduction_ms", &Row::reduction_ms);
    both(j, run, m, "local_ms", &Row::local_ms);
    both(j, run, m, "force_eval_ns", &Row::force_eval_ns);
    both(j, run, m, "candidates", &Row::candidates);
    both(j, run, m, "lmds", &Row::lmds);
    both(j, run, m, "node_pairs", &Row::node_pairs);
    both(j, run, m, "leaf_pairs", &Row::leaf_pairs);
    both(j, run, m, "reduction_cache_hits", &Row::reduction_cache_hits);
    both(j, run, m, "local_in", &Row::local_in);
    both(j, run, m, "local_cache_hits", &Row::local_cache_hits);
    const auto contact = rows_of(run, m, true);
    j.key("reduction_ratio").begin_object();
    j.field("overall", reduction_ratio(contact, false)).field("max", reduction_ratio(contact, true));
    j.end_object();
    const Accuracy a = accuracy(run, m);
    j.key("accuracy").begin_object();
    j.field("poses", a.poses).field("reference_lmds", a.reference).field("found", a.found);
    j.field("match_tolerance", tolerance);
    j.field("recall", fraction(a.recalled, a.reference)).field("precision", fraction(a.confirmed, a.found));
    j.field("recall_2mm", fraction(a.recalled_loose, a.reference));
    j.field("precision_2mm", fraction(a.confirmed_loose, a.found));
    j.field("poses_missing_every_lmd", a.missed_minimum);
    j.field("min_distance_error_max", a.min_error);
    j.field("min_distance_error_max_over_size", a.min_error / size);
    j.field("force_error_max", a.force_error).field("force_error_median", a.force_error_median);
    j.field("torque_error_max", a.torque_error);
    j.field("local_recall", fraction(a.local_recalled, a.reference));
    j.field("local_precision", fraction(a.local_confirmed, a.local_found));
    j.end_object();
    const Smoothness s = smoothness(rows_of(run, m, false));
    j.key("smoothness").begin_object();
    j.field("max_force_jump", s.max_jump).field("total_variation", s.total_variation);
    j.field("max_torque_jump", s.max_torque_jump);
    j.end_object();
    j.end_object();
  }
  for (const char* m : {"min-distance", "fcl", "coal", "reference"}) {
    if (rows_of(run, m, false).empty()) continue;
    j.key(m).begin_object();
    both(j, run, m, "query_ms", &Row::query_ms);
    if (std::string(m) == "coal") {
      both(j, run, m, "pairs_within_cutoff", &Row::candidates);
    } else if (std::string(m) != "reference") {
      const auto rows = rows_of(run, m, false);
      j.field("min_distance_error_max", maximum(values(rows, &Row::min_distance_error)));
      j.field("min_distance_error_max_over_size", maximum(values(rows, &Row::min_distance_error)) / size);
    } else {
      const Smoothness s = smoothness(rows_of(run, m, false));
      j.key("smoothness").begin_object();
      j.field("max_force_jump", s.max_jump).field("total_variation", s.total_variation);
      j.field("max_torque_jump", s.max_torque_jump);
      j.end_object();
    }
    j.end_object();
  }
  j.end_object();

  j.key("ratios").begin_object();
  auto ratio_of_medians = [&](const char* num, const char* den, double Row::*field, bool contact) {
    return ratio(median(values(rows_of(run, num, contact), field)),
                 median(values(rows_of(run, den, contact), field)));
  };
  for (const bool contact : {false, true}) {
    j.key(contact ? "contact" : "all").begin_object();
    j.key("precise_over_original").begin_object();
    j.field("query_ms", ratio_of_medians("precise", "original", &Row::query_ms, contact));
    j.field("global_ms", ratio_of_medians("precise", "original", &Row::global_ms, contact));
    j.field("reduction_ms", ratio_of_medians("precise", "original", &Row::reduction_ms, contact));
    j.field("local_ms", ratio_of_medians("precise", "original", &Row::local_ms, contact));
    j.field("force_eval_ns", ratio_of_medians("precise", "original", &Row::force_eval_ns, contact));
    j.end_object();
    for (const char* num : {"precise", "original", "min-distance"}) {
      if (rows_of(run, "fcl", false).empty()) break;
      const auto r = pose_ratios(run, num, "fcl", contact);
      j.key(std::string(num) + "_over_fcl").begin_object();
      j.field("per_pose_median", median(r)).field("per_pose_p99", percentile(r, 0.99));
      j.field("of_medians", ratio_of_medians(num, "fcl", &Row::query_ms, contact));
      j.end_object();
    }
    if (!rows_of(run, "coal", false).empty()) {
      const auto r = pose_ratios(run, "precise", "coal", contact);
      j.key("precise_over_coal").begin_object();
      j.field("per_pose_median", median(r)).field("per_pose_p99", percentile(r, 0.99));
      j.field("of_medians", ratio_of_medians("precise", "coal", &Row::query_ms, contact));
      j.end_object();
    }
    j.end_object();
  }
  j.end_object();

  // The targets of issue 5 this scene can measure.
  const Accuracy pa = accuracy(run, "precise");
  j.key("targets").begin_object();
  if (!rows_of(run, "fcl", false).empty()) {
    j.field("precise_query_over_fcl_per_pose_median", median(pose_ratios(run, "precise", "fcl", false)));
    j.field("precise_query_over_fcl_per_pose_median_contact",
            median(pose_ratios(run, "precise", "fcl", true)));
  }
  if (!rows_of(run, "coal", false).empty()) {
    j.field("precise_query_over_coal_per_pose_median", median(pose_ratios(run, "precise", "coal", false)));
    j.field("precise_query_over_coal_per_pose_median_contact",
            median(pose_ratios(run, "precise", "coal", true)));
  }
  j.field("precise_local_p99_us",
          percentile(values(rows_of(run, "precise", true), &Row::local_ms), 0.99) * 1e3);
  j.field("precise_recall", fraction(pa.recalled, pa.reference));
  j.field("precise_precision", fraction(pa.confirmed, pa.found));
  j.field("precise_min_distance_error_over_size", pa.min_error / size);
  j.end_object();
  j.end_object();
  return j.str() + "\n";
}

std::string csv(const SceneRun& run) {
  std::string out = "step,method";
  for (const Column& c : columns()) out += std::string(",") + c.first;
  out += '\n';
  char buf[64];
  for (const Row& r : run.rows) {
    out += std::to_string(r.step) + "," + r.method;
    for (const Column& c : columns()) {
      const double v = c.second(r);
      out += ',';
      if (std::isfinite(v)) {
        std::snprintf(buf, sizeof buf, "%.9g", v);
        out += buf;
      }
    }
    out += '\n';
  }
  return out;
}

// ---- the run -------------------------------------------------------------------

// The scene's force settings; CAD scenes scale the hard ones to their size.
ForceSettings scene_force(const Scene& scene, const Model& a, const Model& b) {
  ForceSettings f = scene.soft ? soft_force_settings() : hard_force_settings();
  if (scene.cutoff_over_size > 0.0) {
    const double k = scene.cutoff_over_size * std::max(a.size, b.size) / f.cutoff;
    f.cutoff *= k, f.safety_distance *= k, f.decay_length *= k;
  }
  return f;
}

SceneRun run_scene(const Scene& scene, const Model& a, const Model& b, int poses, int reference_every,
                   const Options& opt, CoalPeer* coal) {
  SceneRun run;
  run.scene = &scene;
  run.a = &a, run.b = &b;
  run.force = scene_force(scene, a, b);
  const double cutoff = run.force.cutoff;
  run.far = scene.cutoff_over_size > 0.0 ? kCadFarOverCutoff * cutoff : scene.far;
  run.near = scene.cutoff_over_size > 0.0 ? 0.1 * cutoff : scene.near;
  const auto start = Clock::now();
  run.path = make_path(scene, run.far, run.near, a, b, poses);
  run.path_seconds = seconds_since(start);
  run.reference_every = reference_every;
  const double tolerance = 1e-9 * std::max(a.size, b.size);
  const double loose_tolerance = kLooseMatchOverCutoff * cutoff;

  PairState state;
  MethodState methods[2] = {{Method::Precise, {}, {}, {}}, {Method::Original, {}, {}, {}}};
  std::vector<LmdPair> scratch;
#ifndef PROX_BENCH_WITH_COAL
  (void)coal;
#endif
#ifdef PROX_BENCH_WITH_FCL
  const fcl::Transform3d fcl_a = to_fcl(Pose{});
  fcl::DistanceRequestd request;
#endif
  for (std::size_t i = 0; i < run.path.size(); ++i) {
    const PosePoint& p = run.path[i];
    const PairQuery q = make_query(a, b, p.pose, cutoff);
    const Vec3 reference_point = p.pose.apply(b.box_centre);
    Row base;
    base.step = static_cast<int>(i);
    base.s = p.s, base.x = p.x, base.target_gap = p.target_gap;
    const std::size_t first_row = run.rows.size();

    for (MethodState& ms : methods) {
      Row r = base;
      r.method = method_name(ms.method);
      LocalTracker& tracker = ms.method == Method::Precise ? state.precise : state.original;
      // The local thread: the previous step's set carried to this pose.
      std::vector<double> local_times;
      LocalTrackingStats local;
      for (int k = 0; k < std::max(1, opt.local_reps); ++k) {
        ms.local = ms.tracked;
        local = LocalTrackingStats{};
        tracker.update(q, ms.local, local);
        local_times.push_back(local.seconds);
      }
      r.local_ms = median(local_times) * 1e3;
      r.local_in = local.pairs_in, r.local_out = local.pairs_out;
      r.local_cache_hits = double(local.cache_hits);
      r.local_distance_evaluations = double(local.distance_evaluations);
      // The global thread: search and reduction.
      ProximityResult res;
      find_lmds(q, ms.method, state, res);
      r.global_ms = res.global.seconds * 1e3;
      r.reduction_ms = (res.reduction[0].seconds + res.reduction[1].seconds) * 1e3;
      r.query_ms = r.global_ms + r.reduction_ms;
      r.candidates = res.candidates;
      r.lmds = double(res.lmds.size());
      r.node_pairs = double(res.global.node_pairs), r.leaf_pairs = double(res.global.leaf_pairs);
      r.visibility_rejections = double(res.global.visibility_rejections);
      r.normal_rejections = double(res.global.normal_rejections);
      r.distance_evaluations = double(res.global.distance_evaluations);
      r.reduction_cache_hits = double(res.reduction[0].cache_hits + res.reduction[1].cache_hits);
      r.min_distance = res.min_distance >= 0.0 ? res.min_distance : kNaN;
      // The haptic loop: the force from the current set.
      const Wrench w = tool_wrench(run.force, res.lmds, reference_point);
      r.force = w.force, r.torque = w.torque;
      r.force_eval_ns = time_force(run.force, res.lmds, p.pose, b.box_centre, opt.force_reps);
      ms.current = std::move(res.lmds);
      run.rows.push_back(r);
    }

    // Proxima's exact minimum distance: the single-pair query FCL answers.
    Row md = base;
    md.method = "min-distance";
    auto t0 = Clock::now();
    const double exact = minimum_distance(q, kInf);
    md.query_ms = seconds_since(t0) * 1e3;
    md.min_distance = exact;
    run.rows.push_back(md);

#ifdef PROX_BENCH_WITH_FCL
    {
      Row fr = base;
      fr.method = "fcl";
      fcl::DistanceResultd result;
      t0 = Clock::now();
      const double d = fcl::distance(a.fcl.get(), fcl_a, b.fcl.get(), to_fcl(p.pose), request, result);
      fr.query_ms = seconds_since(t0) * 1e3;
      fr.min_distance = d;
      fr.min_distance_error = std::abs(d - exact);  // agreement with Proxima's exact minimum
      run.rows.push_back(fr);
    }
#endif
#ifdef PROX_BENCH_WITH_COAL
    {
      // Every triangle pair within the cutoff: the pairs go in `candidates`.
      Row cr = base;
      cr.method = "coal";
      const CoalMargin c = coal->margin_collide(a.coal, b.coal, p.pose, cutoff);
      cr.query_ms = c.seconds * 1e3;
      cr.candidates = double(c.pairs);
      run.rows.push_back(cr);
    }
#endif

    const bool with_reference = reference_every > 0 && (i % static_cast<std::size_t>(reference_every) == 0 ||
                                                        i + 1 == run.path.size());
    if (with_reference) {
      Row rr = base;
      rr.method = "reference";
      ProximityResult ref;
      t0 = Clock::now();
      find_lmds(q, Method::Reference, state, ref);
      rr.query_ms = seconds_since(t0) * 1e3;
      rr.lmds = double(ref.lmds.size());
      rr.min_distance = ref.min_distance >= 0.0 ? ref.min_distance : kNaN;
      const Wrench w = tool_wrench(run.force, ref.lmds, reference_point);
      rr.force = w.force, rr.torque = w.torque;
      run.rows.push_back(rr);
      // Errors of this step's rows against the reference.
      for (std::size_t k = first_row; k < run.rows.size(); ++k) {
        Row& r = run.rows[k];
        if (r.method != "precise" && r.method != "original" && r.method != "min-distance") continue;
        if (r.method == "min-distance") {
          if (!ref.lmds.empty()) r.min_distance_error = std::abs(r.min_distance - ref.min_distance);
          continue;
        }
        const MethodState& ms = methods[r.method == "precise" ? 0 : 1];
        r.ref_lmds = double(ref.lmds.size());
        const auto strict = match(ref.lmds, ms.current, tolerance);
        const auto loose = match(ref.lmds, ms.current, loose_tolerance);
        r.recalled = strict.first, r.confirmed = strict.second;
        r.recalled_loose = loose.first, r.confirmed_loose = loose.second;
        if (!ref.lmds.empty() && !ms.current.empty())
          r.min_distance_error = std::abs(r.min_distance - ref.min_distance);
        r.force_error = glm::length(r.force - w.force);
        r.torque_error = glm::length(r.torque - w.torque);
        const auto local = match(ref.lmds, ms.local, tolerance);
        r.local_recalled = local.first, r.local_confirmed = local.second;
      }
    }
    for (std::size_t k = first_row; k < run.rows.size(); ++k) run.rows[k].exact_min = exact;
    for (MethodState& ms : methods) ms.tracked = ms.current;
  }
  run.seconds = seconds_since(start);
  return run;
}

// ---- printing ------------------------------------------------------------------

std::string fmt(double v, const char* format = "%.3f") {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

void print_summary(const SceneRun& run) {
  const Scene& sc = *run.scene;
  const auto contact_rows = rows_of(run, "precise", true);
  std::printf("\n== %s: %zu poses (%zu within the %.2f mm cutoff), %.1f s (path %.1f s)\n", sc.name.c_str(),
              run.path.size(), contact_rows.size(), run.force.cutoff * 1e3, run.seconds, run.path_seconds);
  std::printf("   %s\n", sc.description.c_str());
  std::printf("   times over the poses in contact: median / p99\n");
  std::printf("   %-13s %19s %17s %17s %19s %15s\n", "method", "global+reduction ms", "global ms",
              "reduction ms", "local update us", "force eval ns");
  for (const char* m : {"precise", "original", "min-distance", "fcl", "coal", "reference"}) {
    const auto rows = rows_of(run, m, true);
    if (rows.empty()) continue;
    auto pair = [&](double Row::*f, double scale, const char* format) {
      const auto v = values(rows, f);
      return fmt(median(v) * scale, format) + " / " + fmt(percentile(v, 0.99) * scale, format);
    };
    std::printf("   %-13s %19s %17s %17s %19s %15s\n", m, pair(&Row::query_ms, 1.0, "%.3f").c_str(),
                pair(&Row::global_ms, 1.0, "%.3f").c_str(), pair(&Row::reduction_ms, 1.0, "%.3f").c_str(),
                pair(&Row::local_ms, 1e3, "%.1f").c_str(), pair(&Row::force_eval_ns, 1.0, "%.0f").c_str());
  }
  std::printf("   %-9s %9s %9s %9s %8s %9s %9s %11s %10s %10s %9s\n", "method", "max LMDs", "max cand",
              "reduction", "recall", "precision", "recall-lo", "max dmin err", "max |dF| N", "max jump N",
              "TV N");
  for (const char* m : {"precise", "original"}) {
    const Accuracy a = accuracy(run, m);
    const Smoothness s = smoothness(rows_of(run, m, false));
    const auto all = rows_of(run, m, false);
    std::printf("   %-9s %9s %9s %9s %8s %9s %9s %11s %10s %10s %9s\n", m,
                fmt(maximum(values(all, &Row::lmds)), "%.0f").c_str(),
                fmt(maximum(values(all, &Row::candidates)), "%.0f").c_str(),
                (fmt(reduction_ratio(rows_of(run, m, true), false), "%.1f") + "x").c_str(),
                fmt(fraction(a.recalled, a.reference), "%.4f").c_str(),
                fmt(fraction(a.confirmed, a.found), "%.4f").c_str(),
                fmt(fraction(a.recalled_loose, a.reference), "%.4f").c_str(),
                fmt(a.min_error, "%.2e").c_str(), fmt(a.force_error, "%.4f").c_str(),
                fmt(s.max_jump, "%.4f").c_str(), fmt(s.total_variation, "%.3f").c_str());
  }
  const Smoothness rs = smoothness(rows_of(run, "reference", false));
  if (std::isfinite(rs.max_jump))
    std::printf("   %-9s %87s %10s %9s\n", "reference", "", fmt(rs.max_jump, "%.4f").c_str(),
                fmt(rs.total_variation, "%.3f").c_str());
  auto med_ratio = [&](const char* num, const char* den, double Row::*f) {
    return fmt(ratio(median(values(rows_of(run, num, true), f)), median(values(rows_of(run, den, true), f))),
               "%.2f");
  };
  std::printf(
      "   precise / original (medians in contact): global+reduction %s, global %s, reduction %s, local %s\n",
      med_ratio("precise", "original", &Row::query_ms).c_str(),
      med_ratio("precise", "original", &Row::global_ms).c_str(),
      med_ratio("precise", "original", &Row::reduction_ms).c_str(),
      med_ratio("precise", "original", &Row::local_ms).c_str());
  if (!rows_of(run, "fcl", false).empty()) {
    const auto all = pose_ratios(run, "precise", "fcl", false), in = pose_ratios(run, "precise", "fcl", true);
    const auto md = pose_ratios(run, "min-distance", "fcl", false);
    std::printf(
        "   precise (whole LMD set) / FCL distance (one pair), per pose: median %s (in contact %s), p99 %s\n",
        fmt(median(all), "%.2f").c_str(), fmt(median(in), "%.2f").c_str(),
        fmt(percentile(all, 0.99), "%.2f").c_str());
    std::printf(
        "   Proxima min-distance / FCL distance (both one pair), per pose: median %s; FCL agrees with "
        "Proxima's exact minimum to %s m\n",
        fmt(median(md), "%.2f").c_str(),
        fmt(maximum(values(rows_of(run, "fcl", false), &Row::min_distance_error)), "%.1e").c_str());
  }
  if (!rows_of(run, "coal", false).empty()) {
    const auto in = pose_ratios(run, "precise", "coal", true);
    const auto pairs = values(rows_of(run, "coal", true), &Row::candidates);
    std::printf(
        "   precise / Coal margin collide (every triangle pair within the cutoff), per pose in contact: "
        "median "
        "%s, p99 %s; Coal's pairs in contact: median %s, max %s\n",
        fmt(median(in), "%.3f").c_str(), fmt(percentile(in, 0.99), "%.3f").c_str(),
        fmt(median(pairs), "%.0f").c_str(), fmt(maximum(pairs), "%.0f").c_str());
  }
}

const char* kUsage =
    "usage: proxima_bench [--scene NAME|GROUP|all] [--poses N] [--out DIR] [--reference-every K]\n"
    "                     [--local-reps R] [--force-reps R] [--meshes DIR] [--scaling-poses N]\n"
    "                     [--scaling-reference-every K] [--cad-poses N] [--max-triangles N] [--list]";

[[noreturn]] void usage_error(const std::string& message) { throw UserError(message + "\n" + kUsage); }

int parse_int(const std::string& text, const char* what, int lo) {
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v < lo || v > 10000000)
    usage_error(std::string(what) + ": '" + text + "' is not a whole number >= " + std::to_string(lo));
  return static_cast<int>(v);
}

// ---- many bodies -------------------------------------------------------------

// A model's mesh as arrays again, as an application hands it to a world.
struct MeshArrays {
  std::vector<double> positions;
  std::vector<std::uint32_t> indices;
};
MeshArrays arrays_of(const Model& model) {
  MeshArrays a;
  for (std::uint32_t v = 0; v < model.mesh.vertex_count(); ++v)
    a.positions.insert(a.positions.end(),
                       {model.mesh.vertex(v).x, model.mesh.vertex(v).y, model.mesh.vertex(v).z});
  for (std::uint32_t t = 0; t < model.mesh.triangle_count(); ++t)
    a.indices.insert(a.indices.end(), model.mesh.indices(t).begin(), model.mesh.indices(t).end());
  return a;
}

// One tool bunny on path T against one static bunny, in worlds side by side
// on the same poses: alone, and among crowds of more static bunnies on a
// grid out of range (120, 1,200 and 12,000 of them). The runtime's
// broadphase (a tree of the static bodies' boxes, rebuilt only when they
// move) should make the crowd cost next to nothing, whatever its size: the
// step-time ratios and the per-body overhead are the figures.
constexpr int kCrowds[] = {120, 1200, 12000};

void run_many_bodies(const Model& model, const Options& opt) {
  const Scene& path_t = scenes().front();
  const std::vector<PosePoint> path = make_path(path_t, path_t.far, path_t.near, model, model, opt.poses);
  const MeshArrays arrays = arrays_of(model);
  const std::vector<double>& positions = arrays.positions;
  const std::vector<std::uint32_t>& indices = arrays.indices;
  auto world_with = [&](int far_bodies) {
    auto world = std::make_unique<runtime::World>(runtime::WorldSettings{});
    runtime::World& w = *world;
    Status status;
    const MeshInput input{positions.data(), static_cast<std::uint32_t>(positions.size() / 3), indices.data(),
                          static_cast<std::uint32_t>(indices.size() / 3)};
    const runtime::Handle mesh = w.create_mesh(input, status);
    if (!status) throw UserError(status.message());
    w.create_body(mesh, runtime::BodyType::Static, Pose{}, Vec3(0.0));
    // A grid 0.5 m apart, 12 wide, rows going up from y = 0.6 m: beyond the
    // path's reach.
    for (int i = 0; i < far_bodies; ++i)
      w.create_body(mesh, runtime::BodyType::Static,
                    Pose{glm::dmat3(1.0), Vec3(0.5 * (i % 12) - 2.75, 0.6 + 0.5 * (i / 12), 0.0)}, Vec3(0.0));
    const runtime::Handle tool =
        w.create_body(mesh, runtime::BodyType::Tool, path.front().pose, model.centroid);
    return std::make_pair(std::move(world), tool);
  };
  struct Crowd {
    int bodies = 0;
    std::unique_ptr<runtime::World> world;
    runtime::Handle tool;
    std::vector<double> ms, near_ms, overhead_far;
    int max_in_range = 0, contacts_differ = 0;
  };
  auto [alone_world, tool_alone] = world_with(0);
  runtime::World& alone = *alone_world;
  std::vector<Crowd> crowds;
  for (int n : kCrowds) {
    auto [w, t] = world_with(n);
    Crowd c;
    c.bodies = n;
    c.world = std::move(w);
    c.tool = t;
    crowds.push_back(std::move(c));
  }
  std::vector<double> alone_ms, alone_near;
  std::string rows = "step,x,alone_ms";
  for (const Crowd& c : crowds) rows += ",crowd" + std::to_string(c.bodies) + "_ms";
  rows += ",pairs_in_range,contacts\n";
  for (std::size_t i = 0; i < path.size(); ++i) {
    alone.set_pose(tool_alone, path[i].pose);
    alone.step();
    alone_ms.push_back(alone.stats().seconds * 1e3);
    const bool in_range = alone.stats().pairs_in_range > 0;
    if (in_range) alone_near.push_back(alone_ms.back());
    char line[512];
    std::snprintf(line, sizeof line, "%zu,%.9g,%.6f", i, path[i].x, alone_ms.back());
    rows += line;
    for (Crowd& c : crowds) {
      c.world->set_pose(c.tool, path[i].pose);
      c.world->step();
      const runtime::StepStats st = c.world->stats();
      c.ms.push_back(st.seconds * 1e3);
      c.max_in_range = std::max(c.max_in_range, st.pairs_in_range);
      c.contacts_differ += st.contacts != alone.stats().contacts;
      if (in_range)
        c.near_ms.push_back(c.ms.back());
      else
        c.overhead_far.push_back(c.ms.back() - alone_ms.back());
      std::snprintf(line, sizeof line, ",%.6f", c.ms.back());
      rows += line;
    }
    std::snprintf(line, sizeof line, ",%d,%d\n", crowds.back().world->stats().pairs_in_range,
                  crowds.back().world->stats().contacts);
    rows += line;
  }
  Json j;
  j.begin_object();
  j.field("scene", "many-bodies");
  j.field(
      "description",
      std::string("One tool bunny on path T among 1 + N static bunnies (all but one out of range), against "
                  "the same path with the one bunny alone, side by side; runtime::World::step, whole step "
                  "timed."));
  j.field("poses", static_cast<long long>(path.size()));
  j.field("steps_in_range", static_cast<long long>(alone_near.size()));
  j.field("alone_step_ms_median", median(alone_ms)).field("alone_step_ms_p99", percentile(alone_ms, 0.99));
  j.field("in_range_alone_step_ms_median", median(alone_near));
  j.key("crowds").begin_array();
  std::printf(
      "\n== many-bodies: %zu poses, one tool among crowds of static bunnies (all but one out of range)\n",
      path.size());
  std::printf("   %8s %22s %22s %10s %24s %10s\n", "bodies", "step median in range", "alone in range",
              "ratio", "out of range: added/body", "max pairs");
  for (const Crowd& c : crowds) {
    const double ratio = median(c.near_ms) / median(alone_near);
    const double per_body_ns = median(c.overhead_far) * 1e6 / c.bodies;
    j.begin_object();
    j.field("bodies", static_cast<long long>(c.bodies + 2));
    j.field("crowd_step_ms_median", median(c.ms)).field("crowd_step_ms_p99", percentile(c.ms, 0.99));
    j.field("in_range_crowd_step_ms_median", median(c.near_ms));
    j.field("in_range_crowd_over_alone", ratio);
    j.field("out_of_range_overhead_ns_per_far_body", per_body_ns);
    j.field("out_of_range_overhead_ns_median", median(c.overhead_far) * 1e6);
    j.field("max_pairs_in_range", static_cast<long long>(c.max_in_range));
    j.field("steps_with_different_contacts", static_cast<long long>(c.contacts_differ));
    j.end_object();
    std::printf("   %8d %19.3f ms %19.3f ms %10.3f %21.2f ns %10d%s\n", c.bodies + 2, median(c.near_ms),
                median(alone_near), ratio, per_body_ns, c.max_in_range,
                c.contacts_differ ? "  CONTACTS DIFFER" : "");
  }
  j.end_array();
  j.end_object();
  write_file(opt.out + "/many-bodies.csv", rows);
  write_file(opt.out + "/many-bodies.json", j.str() + "\n");
}

// ---- the threads in real time ------------------------------------------------------

// Path T in real time on the runtime's threads: the scripted device moves the
// tool through the path's poses at 3 ms a pose (1000 poses: 3 s), then holds
// it 0.5 s, while the haptic loop (1 kHz), local tracking (1 kHz) and the
// global search (back to back) run. What the threads achieved: rates,
// period and work percentiles, overruns; what the device was handed.
void run_threads(const Model& model, const Options& opt) {
  const Scene& path_t = scenes().front();
  const std::vector<PosePoint> path = make_path(path_t, path_t.far, path_t.near, model, model, opt.poses);
  const MeshArrays arrays = arrays_of(model);
  const std::vector<double>& positions = arrays.positions;
  const std::vector<std::uint32_t>& indices = arrays.indices;
  runtime::World world{runtime::WorldSettings{}};
  Status status;
  const runtime::Handle mesh =
      world.create_mesh({positions.data(), static_cast<std::uint32_t>(positions.size() / 3), indices.data(),
                         static_cast<std::uint32_t>(indices.size() / 3)},
                        status);
  if (!status) throw UserError(status.message());
  world.create_body(mesh, runtime::BodyType::Static, Pose{}, Vec3(0.0));
  const runtime::Handle tool =
      world.create_body(mesh, runtime::BodyType::Tool, path.front().pose, model.centroid);
  std::vector<runtime::ScriptedPose> poses;
  for (const PosePoint& p : path) poses.push_back(runtime::ScriptedPose::of(p.pose));
  constexpr double kSecondsPerPose = 0.003, kHold = 0.5;
  runtime::ScriptedDevice device(poses, kSecondsPerPose, false);
  world.set_device(tool, device.device());
  const runtime::ThreadSettings settings;
  if (!world.start_threads(settings, status)) throw UserError(status.message());
  std::this_thread::sleep_for(
      std::chrono::duration<double>(kSecondsPerPose * double(path.size() - 1) + kHold));
  world.stop_threads();
  const runtime::Threads& threads = *world.threads();
  const runtime::ScriptedRecord record = device.record();
  const runtime::HapticCounters safety = threads.haptic_counters();

  Json j;
  j.begin_object();
  j.field("scene", "threads");
  j.field("description",
          std::string("Path T in real time on the runtime's threads, the scripted device moving "
                      "the tool at 3 ms a pose, then holding it 0.5 s."));
  j.field("poses", static_cast<long long>(path.size()));
  j.field("machine_cores", static_cast<long long>(std::thread::hardware_concurrency()));
  const char* names[3] = {"haptic", "local", "global"};
  std::printf("\n== threads: path T in real time (%zu poses at %.0f ms each, then %.1f s still), %u cores\n",
              path.size(), kSecondsPerPose * 1e3, kHold, std::thread::hardware_concurrency());
  std::printf("   %-7s %9s %9s %11s %11s %11s %11s %11s %11s %9s %9s\n", "thread", "target", "achieved",
              "period p50", "period p99", "period max", "work p50", "work p99", "work max", "updates",
              "overruns");
  j.key("threads").begin_object();
  for (int r = 0; r < 3; ++r) {
    const runtime::LoopSummary s = threads.loop_summary(static_cast<runtime::Role>(r));
    j.key(names[r]).begin_object();
    j.field("target_hz", s.target_rate).field("achieved_hz", s.achieved_rate);
    j.field("period_ms_p50", s.period_p50 * 1e3).field("period_ms_p99", s.period_p99 * 1e3);
    j.field("period_ms_max", s.period_max * 1e3);
    j.field("update_ms_p50", s.update_p50 * 1e3).field("update_ms_p99", s.update_p99 * 1e3);
    j.field("update_ms_max", s.update_max * 1e3);
    j.field("updates", static_cast<long long>(s.updates))
        .field("overruns", static_cast<long long>(s.overruns));
    j.end_object();
    std::printf(
        "   %-7s %6.0f Hz %6.0f Hz %8.3f ms %8.3f ms %8.3f ms %8.4f ms %8.4f ms %8.3f ms %9llu %9llu\n",
        names[r], s.target_rate, s.achieved_rate, s.period_p50 * 1e3, s.period_p99 * 1e3, s.period_max * 1e3,
        s.update_p50 * 1e3, s.update_p99 * 1e3, s.update_max * 1e3,
        static_cast<unsigned long long>(s.updates), static_cast<unsigned long long>(s.overruns));
  }
  j.end_object();
  j.key("device").begin_object();
  j.field("writes", static_cast<long long>(record.writes));
  j.field("max_force", record.max_force).field("max_force_step", record.max_force_step);
  j.field("all_finite", record.finite);
  j.end_object();
  j.key("safety").begin_object();
  j.field("stale_ticks", static_cast<long long>(safety.stale_ticks));
  j.field("untrusted_ticks", static_cast<long long>(safety.untrusted_ticks));
  j.field("limited_ticks", static_cast<long long>(safety.limited_ticks));
  j.field("torn_snapshots", static_cast<long long>(safety.torn_snapshots));
  j.field("dropped_contacts", static_cast<long long>(safety.dropped_contacts));
  j.end_object();
  j.end_object();
  write_file(opt.out + "/threads.json", j.str() + "\n");
  std::printf(
      "   device: %llu wrenches, largest force %.3f N, largest change between ticks %.3f N, %s; "
      "stale ticks %llu, untrusted %llu, rate-limited %llu, torn snapshots %llu\n",
      static_cast<unsigned long long>(record.writes), record.max_force, record.max_force_step,
      record.finite ? "all finite" : "NOT ALL FINITE", static_cast<unsigned long long>(safety.stale_ticks),
      static_cast<unsigned long long>(safety.untrusted_ticks),
      static_cast<unsigned long long>(safety.limited_ticks),
      static_cast<unsigned long long>(safety.torn_snapshots));
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
  std::printf("FCL %s: OBBRSS BVH per mesh, built once.\n", FCL_VERSION);
#else
  std::printf("FCL: not built in (PROX_BENCH_WITH_FCL=OFF).\n");
#endif

  // Meshes are loaded (with their hierarchies) once and shared by the scenes.
  std::map<std::string, std::shared_ptr<Model>> models;
  auto model_of = [&](const MeshSource& source) {
    const std::string key = source.file + "#" + std::to_string(source.part) + "#" +
                            std::to_string(source.subdivisions) + "#" + std::to_string(source.scale);
    auto& m = models[key];
    if (!m) m = load_model(source, opt.meshes, coal);
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
