// proxima: the command-line face of the engine.
//
//   proxima info FILE
//   proxima lmd A B [--pose-a tx ty tz qw qx qy qz] [--pose-b ...] [--cutoff D]
//                   [--method precise|original|reference] [--force hard|soft] [--json FILE]
//   proxima polylines A B [--pose-a ...] [--pose-b ...] [--json FILE]
//   proxima path [A B] [--poses FILE | --steps N] [--method precise|original|both] [--force hard|soft]
//                [--csv FILE]
//
// Poses are world poses of the meshes as loaded (quaternion w first); lengths
// are in the meshes' units (metres for the shared assets). docs/cli.md has
// the details and the JSON layout.
#include "contact/force.h"
#include "contact/polylines.h"
#include "contact/proximity.h"
#include "io/obj.h"
#if PROX_WITH_GLTF
#include "io/gltf.h"
#endif
#include "common/json_writer.h"

#include <proxima/version.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace prox::cli {
namespace {

using Json = JsonWriter;

const char* kUsage =
    "usage:\n"
    "  proxima info FILE\n"
    "  proxima lmd A B [--pose-a tx ty tz qw qx qy qz] [--pose-b tx ty tz qw qx qy qz]\n"
    "                  [--cutoff D] [--method precise|original|reference] [--force hard|soft] [--json FILE]\n"
    "  proxima polylines A B [--pose-a tx ty tz qw qx qy qz] [--pose-b ...] [--json FILE]\n"
    "  proxima path [A B] [--poses FILE | --steps N] [--method precise|original|both] [--force hard|soft]\n"
    "               [--csv FILE]\n"
    "  proxima --version\n";

// Thrown for anything the user got wrong; main prints it and exits 1.
struct UserError {
  std::string message;
};

[[noreturn]] void fail(const std::string& message) { throw UserError{message}; }

double parse_number(const std::string& text, const char* what) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') fail(std::string(what) + ": '" + text + "' is not a number");
  if (!std::isfinite(v)) fail(std::string(what) + ": '" + text + "' is not finite");
  return v;
}

struct Model {
  std::string path;
  Mesh mesh;
  std::unique_ptr<Snch> snch;
  double load_seconds = 0.0;
};

std::string extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::shared_ptr<Model> load(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  auto model = std::make_shared<Model>();
  model->path = path;
  const std::string ext = extension(path);
  std::vector<double> positions;
  std::vector<std::uint32_t> indices;
  if (ext == "obj") {
    io::ObjData obj;
    const Status s = io::read_obj(path, obj);
    if (!s) fail(s.message());
    positions = std::move(obj.positions);
    indices = std::move(obj.indices);
  }
#if PROX_WITH_GLTF
  else if (ext == "gltf" || ext == "glb") {
    // The whole default scene as one mesh, node transforms applied.
    std::vector<io::GltfMesh> scene;
    const Status s = io::load_gltf(path, io::GltfLoadOptions{}, scene);
    if (!s) fail(s.message());
    positions = std::move(scene.front().positions);
    indices = std::move(scene.front().indices);
  }
#endif
  else {
    fail(path + ": unsupported file type '." + ext + "' (.obj, .gltf and .glb are read)");
  }
  Status s;
  const MeshInput input{positions.data(), static_cast<std::uint32_t>(positions.size() / 3), indices.data(),
                        static_cast<std::uint32_t>(indices.size() / 3)};
  model->mesh = Mesh::build(input, s);
  if (!s) fail(path + ": " + s.message());
  model->load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  model->snch = std::make_unique<Snch>(model->mesh);
  return model;
}

std::string default_asset(const char* name) {
  if (const char* dir = std::getenv("PROXIMA_ASSETS")) return std::string(dir) + "/" + name;
  return std::string(PROX_SHARED_ASSETS_DIR) + "/" + name;
}

// Command-line arguments after the command, consumed front to back.
class Args {
 public:
  Args(int argc, char** argv, int first) : args_(argv + first, argv + argc) {}
  bool empty() const { return i_ >= args_.size(); }
  const std::string& peek() const { return args_[i_]; }
  std::string next(const char* what) {
    if (empty()) fail(std::string("missing ") + what);
    return args_[i_++];
  }
  Pose pose(const char* option) {
    double v[7];
    for (double& x : v) x = parse_number(next(option), option);
    if (v[3] == 0.0 && v[4] == 0.0 && v[5] == 0.0 && v[6] == 0.0)
      fail(std::string(option) + ": the quaternion (qw qx qy qz) is zero");
    return Pose::from_quaternion(Vec3(v[0], v[1], v[2]), v[3], v[4], v[5], v[6]);
  }

 private:
  std::vector<std::string> args_;
  std::size_t i_ = 0;
};

Method parse_method(const std::string& s) {
  if (s == "precise") return Method::Precise;
  if (s == "original") return Method::Original;
  if (s == "reference") return Method::Reference;
  fail("--method: '" + s + "' is not precise, original or reference");
}

ForceSettings parse_force(const std::string& s) {
  if (s == "hard") return hard_force_settings();
  if (s == "soft") return soft_force_settings();
  fail("--force: '" + s + "' is not hard or soft");
}

void write_file(const std::string& path, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) fail(path + ": cannot write");
  std::fputs(text.c_str(), f);
  if (std::fclose(f) != 0) fail(path + ": cannot write");
}

// ---- info ---------------------------------------------------------------------

int info(Args& args) {
  const std::string path = args.next("FILE");
  if (!args.empty()) fail("info: unexpected argument '" + args.peek() + "'");
  const auto model = load(path);
  const MeshStats& s = model->mesh.stats();
  const Aabb& box = model->mesh.bounds();
  const SnchStats& t = model->snch->stats();
  std::printf("%s\n", path.c_str());
  std::printf("  triangles        %u (of %u in the file; %u dropped: they repeat a vertex)\n", s.triangles,
              s.input_triangles, s.dropped_triangles);
  std::printf("  vertices         %u welded (of %u in the file)\n", s.vertices, s.input_vertices);
  std::printf("  zero-area        %u triangles (kept)\n", s.zero_area_triangles);
  std::printf("  boundary edges   %u\n", s.boundary_edges);
  std::printf("  non-manifold     %u edges\n", s.nonmanifold_edges);
  std::printf("  bounding box     [%.6g, %.6g, %.6g] .. [%.6g, %.6g, %.6g] (size %.6g x %.6g x %.6g)\n",
              box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z, box.max.x - box.min.x,
              box.max.y - box.min.y, box.max.z - box.min.z);
  std::printf("  load             %.1f ms\n", model->load_seconds * 1e3);
  std::printf("  SNCH             %u nodes, depth %u, %u unbounded leaf cones, built in %.1f ms, %.1f MiB\n",
              t.nodes, t.depth, t.unbounded_leaves, t.build_seconds * 1e3,
              double(t.memory_bytes) / (1 << 20));
  return 0;
}

// ---- lmd -----------------------------------------------------------------------

int lmd(Args& args) {
  const std::string path_a = args.next("mesh A"), path_b = args.next("mesh B");
  Pose pose_a, pose_b;
  double cutoff = 0.005;
  Method method = Method::Precise;
  ForceSettings force = hard_force_settings();
  std::string json_path;
  while (!args.empty()) {
    const std::string opt = args.next("option");
    if (opt == "--pose-a")
      pose_a = args.pose("--pose-a");
    else if (opt == "--pose-b")
      pose_b = args.pose("--pose-b");
    else if (opt == "--cutoff")
      cutoff = parse_number(args.next("--cutoff value"), "--cutoff");
    else if (opt == "--method")
      method = parse_method(args.next("--method value"));
    else if (opt == "--force")
      force = parse_force(args.next("--force value"));
    else if (opt == "--json")
      json_path = args.next("--json file");
    else
      fail("lmd: unknown option '" + opt + "'");
  }
  if (!(cutoff >= 0.0)) fail("--cutoff must be zero or positive");
  force.cutoff = std::max(cutoff, force.safety_distance);
  const auto a = load(path_a);
  const auto b = path_b == path_a ? a : load(path_b);
  const PairQuery q{&a->mesh, a->snch.get(), pose_a, &b->mesh, b->snch.get(), pose_b, cutoff};
  PairState state;
  ProximityResult r;
  find_lmds(q, method, state, r);
  // The tool is B; its reference point is its bounding-box centre.
  const Vec3 reference = pose_b.apply(0.5 * (b->mesh.bounds().min + b->mesh.bounds().max));
  const Wrench w = tool_wrench(force, r.lmds, reference);

  std::printf("%s LMDs between %s and %s within %g: %zu (from %u candidates)\n", method_name(method),
              path_a.c_str(), path_b.c_str(), cutoff, r.lmds.size(), r.candidates);
  for (const LmdPair& p : r.lmds)
    std::printf("  tri %u - tri %u  d=%.9g  %s-%s  a=(%.6g, %.6g, %.6g) b=(%.6g, %.6g, %.6g)\n", p.tri_a,
                p.tri_b, p.distance, feature_kind_name(p.feature_a.kind), feature_kind_name(p.feature_b.kind),
                p.point_a.x, p.point_a.y, p.point_a.z, p.point_b.x, p.point_b.y, p.point_b.z);
  if (r.lmds.empty())
    std::printf("  minimum distance: none within the cutoff\n");
  else
    std::printf("  minimum distance: %.9g\n", r.min_distance);
  std::printf("  force on B:  (%.6g, %.6g, %.6g) N%s\n", w.force.x, w.force.y, w.force.z,
              w.clipped ? " (clipped)" : "");
  std::printf("  torque on B: (%.6g, %.6g, %.6g) N m about its box centre\n", w.torque.x, w.torque.y,
              w.torque.z);
  std::printf(
      "  search: %llu node pairs, %llu leaf pairs, %llu culled by visibility, %.3f ms; reduction %.3f ms\n",
      static_cast<unsigned long long>(r.global.node_pairs),
      static_cast<unsigned long long>(r.global.leaf_pairs),
      static_cast<unsigned long long>(r.global.visibility_rejections), r.global.seconds * 1e3,
      (r.reduction[0].seconds + r.reduction[1].seconds) * 1e3);

  if (!json_path.empty()) {
    Json j;
    j.begin_object();
    // -1 when no pair is within the cutoff (the minimum is then unknown).
    j.key("min_distance").value(r.min_distance);
    j.key("method").value(method_name(method));
    j.key("cutoff").value(cutoff);
    j.key("lmds").begin_array();
    for (const LmdPair& p : r.lmds) {
      j.begin_object();
      j.key("tri_a").value(static_cast<long long>(p.tri_a));
      j.key("tri_b").value(static_cast<long long>(p.tri_b));
      j.key("point_a").vec3(p.point_a);
      j.key("point_b").vec3(p.point_b);
      j.key("distance").value(p.distance);
      j.key("feature_a").value(feature_kind_name(p.feature_a.kind));
      j.key("feature_b").value(feature_kind_name(p.feature_b.kind));
      j.end_object();
    }
    j.end_array();
    j.key("force").vec3(w.force);
    j.key("torque").vec3(w.torque);
    j.key("stats").begin_object();
    j.key("candidates").value(static_cast<long long>(r.candidates));
    j.key("node_pairs").value(static_cast<long long>(r.global.node_pairs));
    j.key("leaf_pairs").value(static_cast<long long>(r.global.leaf_pairs));
    j.key("plane_rejections").value(static_cast<long long>(r.global.plane_rejections));
    j.key("visibility_rejections").value(static_cast<long long>(r.global.visibility_rejections));
    j.key("normal_rejections").value(static_cast<long long>(r.global.normal_rejections));
    j.key("distance_evaluations").value(static_cast<long long>(r.global.distance_evaluations));
    j.key("global_ms").value(r.global.seconds * 1e3);
    j.key("reduction_ms").value((r.reduction[0].seconds + r.reduction[1].seconds) * 1e3);
    j.key("tracking_cache_hits")
        .value(static_cast<long long>(r.reduction[0].cache_hits + r.reduction[1].cache_hits));
    j.end_object();
    j.end_object();
    write_file(json_path, j.str() + "\n");
  }
  return 0;
}

// ---- polylines -------------------------------------------------------------

int polylines(Args& args) {
  const std::string path_a = args.next("mesh A"), path_b = args.next("mesh B");
  Pose pose_a, pose_b;
  std::string json_path;
  while (!args.empty()) {
    const std::string opt = args.next("option");
    if (opt == "--pose-a")
      pose_a = args.pose("--pose-a");
    else if (opt == "--pose-b")
      pose_b = args.pose("--pose-b");
    else if (opt == "--json")
      json_path = args.next("--json file");
    else
      fail("polylines: unknown option '" + opt + "'");
  }
  const auto a = load(path_a);
  const auto b = path_b == path_a ? a : load(path_b);
  const PairQuery q{&a->mesh, a->snch.get(), pose_a, &b->mesh, b->snch.get(), pose_b, 0.0};
  std::vector<Polyline> lines;
  PolylineStats stats;
  intersection_polylines(q, lines, stats);
  double total = 0.0;
  for (const Polyline& line : lines) {
    double len = 0.0;
    for (std::size_t k = 0; k + 1 < line.points.size(); ++k)
      len += glm::length(line.points[k + 1] - line.points[k]);
    if (line.closed) len += glm::length(line.points.front() - line.points.back());
    total += len;
    std::printf("  %s polyline: %zu points, length %.9g\n", line.closed ? "closed" : "open",
                line.points.size(), len);
  }
  std::printf(
      "%zu polylines, total length %.9g; %llu intersecting triangle pairs (%llu coplanar, not traced), "
      "%.3f ms\n",
      lines.size(), total, static_cast<unsigned long long>(stats.intersecting_pairs),
      static_cast<unsigned long long>(stats.coplanar_pairs), stats.seconds * 1e3);
  if (!json_path.empty()) {
    Json j;
    j.begin_object();
    j.key("polylines").begin_array();
    for (const Polyline& line : lines) {
      j.begin_object().key("closed").value(line.closed).key("points").begin_array();
      for (const Vec3& p : line.points) j.vec3(p);
      j.end_array().end_object();
    }
    j.end_array();
    j.key("total_length").value(total);
    j.key("stats").begin_object();
    j.key("intersecting_pairs").value(static_cast<long long>(stats.intersecting_pairs));
    j.key("coplanar_pairs").value(static_cast<long long>(stats.coplanar_pairs));
    j.key("segments").value(static_cast<long long>(stats.segments));
    j.key("ms").value(stats.seconds * 1e3);
    j.end_object();
    j.end_object();
    write_file(json_path, j.str() + "\n");
  }
  return 0;
}

// ---- path ----------------------------------------------------------------------

struct Step {
  int index = 0;
  double x = 0.0;
  Method method = Method::Precise;
  std::size_t candidates = 0, lmds = 0;
  double min_distance = -1.0;
  Wrench wrench;
  double global_ms = 0.0, reduction_ms = 0.0, local_ms = 0.0;
};

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * double(v.size() - 1) + 0.5))];
}

// Path T of docs/cli.md: B translated along +x from where the minimum
// distance to A is `far` to where it is `near`, linear in x.
double x_at_gap(const Model& a, const Model& b, double gap) {
  double lo = 0.0, hi = glm::length(a.mesh.bounds().max - a.mesh.bounds().min) +
                        glm::length(b.mesh.bounds().max - b.mesh.bounds().min) + gap;
  for (int i = 0; i < 100 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    const Pose pb{glm::dmat3(1.0), Vec3(mid, 0.0, 0.0)};
    const PairQuery q{&a.mesh, a.snch.get(), Pose{}, &b.mesh, b.snch.get(), pb, 0.0};
    (any_closer_than(q, gap) ? lo : hi) = mid;
  }
  return hi;
}

// A poses file: one pose of B per line, "tx ty tz qw qx qy qz"; blank lines
// and lines starting with # are skipped.
std::vector<Pose> read_poses(const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "r");
  if (!f) fail(path + ": cannot read");
  std::vector<Pose> poses;
  char line[1024];
  int number = 0;
  while (std::fgets(line, sizeof line, f)) {
    ++number;
    std::string text(line);
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos || text[first] == '#') continue;
    double v[7];
    int read = 0;
    const char* at = text.c_str();
    for (; read < 7; ++read) {
      char* end = nullptr;
      v[read] = std::strtod(at, &end);
      if (end == at) break;
      at = end;
    }
    const std::string where = path + ":" + std::to_string(number);
    if (read != 7 || std::string(at).find_first_not_of(" \t\r\n") != std::string::npos) {
      std::fclose(f);
      fail(where + ": expected 7 numbers: tx ty tz qw qx qy qz");
    }
    for (double x : v)
      if (!std::isfinite(x)) {
        std::fclose(f);
        fail(where + ": a number is not finite");
      }
    if (v[3] == 0.0 && v[4] == 0.0 && v[5] == 0.0 && v[6] == 0.0) {
      std::fclose(f);
      fail(where + ": the quaternion is zero");
    }
    poses.push_back(Pose::from_quaternion(Vec3(v[0], v[1], v[2]), v[3], v[4], v[5], v[6]));
  }
  std::fclose(f);
  if (poses.size() < 2) fail(path + ": a path needs at least 2 poses");
  return poses;
}

int path(Args& args) {
  std::string path_a = default_asset("bunny.obj"), path_b;
  int steps = 1000;
  std::string poses_path;
  std::vector<Method> methods = {Method::Precise, Method::Original};
  ForceSettings force = hard_force_settings();
  std::string csv_path = "proxima-path.csv";
  if (!args.empty() && args.peek().rfind("--", 0) != 0) {
    path_a = args.next("mesh A");
    path_b = args.next("mesh B");
  }
  while (!args.empty()) {
    const std::string opt = args.next("option");
    if (opt == "--steps") {
      const double s = parse_number(args.next("--steps value"), "--steps");
      if (s < 2 || s > 1e7 || s != std::floor(s)) fail("--steps must be a whole number from 2 to 10000000");
      steps = static_cast<int>(s);
    } else if (opt == "--method") {
      const std::string m = args.next("--method value");
      methods = m == "both" ? std::vector<Method>{Method::Precise, Method::Original}
                            : std::vector<Method>{parse_method(m)};
    } else if (opt == "--force") {
      force = parse_force(args.next("--force value"));
    } else if (opt == "--csv") {
      csv_path = args.next("--csv file");
    } else if (opt == "--poses") {
      poses_path = args.next("--poses file");
    } else {
      fail("path: unknown option '" + opt + "'");
    }
  }
  const auto a = load(path_a);
  const auto b = path_b.empty() || path_b == path_a ? a : load(path_b);
  const double cutoff = force.cutoff;
  std::vector<Pose> poses;
  if (!poses_path.empty()) {
    poses = read_poses(poses_path);
    std::printf("path from %s: %zu poses of %s against %s, cutoff %.3g m\n", poses_path.c_str(), poses.size(),
                b->path.c_str(), a->path.c_str(), cutoff);
  } else {
    const double far = 0.05, near = 0.0005;
    const double x0 = x_at_gap(*a, *b, far), x1 = x_at_gap(*a, *b, near);
    for (int i = 0; i < steps; ++i)
      poses.push_back({glm::dmat3(1.0), Vec3(x0 + (x1 - x0) * i / (steps - 1), 0, 0)});
    std::printf(
        "path T: %s held and moved along +x against %s, %d poses from %.3g m to %.3g m apart "
        "(x %.6g .. %.6g), cutoff %.3g m\n",
        b->path.c_str(), a->path.c_str(), steps, far, near, x0, x1, cutoff);
  }

  std::vector<Step> rows;
  for (const Method method : methods) {
    PairState state;
    std::vector<LmdPair> tracked;
    for (std::size_t i = 0; i < poses.size(); ++i) {
      Step s;
      s.index = static_cast<int>(i);
      s.method = method;
      const Pose& pb = poses[i];
      s.x = pb.translation.x;
      const PairQuery q{&a->mesh, a->snch.get(), Pose{}, &b->mesh, b->snch.get(), pb, cutoff};
      // What the local thread does between global searches: carry the last
      // set to the new pose.
      LocalTrackingStats local;
      (method == Method::Original ? state.original : state.precise).update(q, tracked, local);
      s.local_ms = local.seconds * 1e3;
      ProximityResult r;
      find_lmds(q, method, state, r);
      s.candidates = r.candidates;
      s.lmds = r.lmds.size();
      s.min_distance = r.min_distance;
      s.global_ms = r.global.seconds * 1e3;
      s.reduction_ms = (r.reduction[0].seconds + r.reduction[1].seconds) * 1e3;
      s.wrench = tool_wrench(force, r.lmds, pb.apply(0.5 * (b->mesh.bounds().min + b->mesh.bounds().max)));
      tracked = r.lmds;
      rows.push_back(s);
    }
  }

  std::string csv =
      "step,method,x,min_distance,candidates,lmds,force_x,force_y,force_z,force,torque_x,torque_y,torque_z,"
      "global_ms,reduction_ms,local_ms\n";
  for (const Step& s : rows) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "%d,%s,%.9g,%.9g,%zu,%zu,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.6f,%.6f,%.6f\n", s.index,
                  method_name(s.method), s.x, s.min_distance, s.candidates, s.lmds, s.wrench.force.x,
                  s.wrench.force.y, s.wrench.force.z, glm::length(s.wrench.force), s.wrench.torque.x,
                  s.wrench.torque.y, s.wrench.torque.z, s.global_ms, s.reduction_ms, s.local_ms);
    csv += line;
  }
  write_file(csv_path, csv);

  std::printf("%-9s %6s %9s %9s %10s %10s %12s %12s %12s %12s\n", "method", "steps", "contact", "max LMDs",
              "max |F| N", "max jump N", "global p50", "global p99", "local p50", "reduction");
  for (const Method method : methods) {
    std::vector<double> global, local;
    int contact = 0;
    std::size_t max_lmds = 0, candidates = 0, lmds = 0;
    double max_force = 0.0, max_jump = 0.0;
    const Step* previous = nullptr;
    for (const Step& s : rows) {
      if (s.method != method) continue;
      global.push_back(s.global_ms + s.reduction_ms);
      local.push_back(s.local_ms);
      contact += s.lmds > 0;
      max_lmds = std::max(max_lmds, s.lmds);
      candidates += s.candidates, lmds += s.lmds;
      max_force = std::max(max_force, glm::length(s.wrench.force));
      if (previous) max_jump = std::max(max_jump, glm::length(s.wrench.force - previous->wrench.force));
      previous = &s;
    }
    char reduction[32];
    std::snprintf(reduction, sizeof reduction, "%.1fx", lmds ? double(candidates) / double(lmds) : 0.0);
    std::printf("%-9s %6zu %9d %9zu %10.4f %10.4f %9.3f ms %9.3f ms %9.3f ms %12s\n", method_name(method),
                global.size(), contact, max_lmds, max_force, max_jump, percentile(global, 0.5),
                percentile(global, 0.99), percentile(local, 0.5), reduction);
  }
  std::printf("per-step figures written to %s\n", csv_path.c_str());
  return 0;
}

}  // namespace
}  // namespace prox::cli

int main(int argc, char** argv) {
  using namespace prox::cli;
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const std::string command = argv[1];
  try {
    Args args(argc, argv, 2);
    if (command == "info") return info(args);
    if (command == "lmd") return lmd(args);
    if (command == "polylines") return polylines(args);
    if (command == "path") return path(args);
    if (command == "--version") {
      std::printf("proxima %s\n", PROX_VERSION_STRING);
      return 0;
    }
    if (command == "--help" || command == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    std::fprintf(stderr, "proxima: unknown command '%s'\n%s", command.c_str(), kUsage);
    return 2;
  } catch (const UserError& e) {
    std::fprintf(stderr, "proxima: %s\n", e.message.c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "proxima: %s\n", e.what());
    return 1;
  }
}
