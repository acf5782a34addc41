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
//
// A customer of the SDK like any other: it sees only the C API
// (<proxima/proxima.h>, libproxima.so) and the samples' own utilities.
#include <proxima/proxima.h>

#include "common/json_writer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace proxcli {
namespace {

using Json = prox::JsonWriter;

const char* kUsage =
    "usage:\n"
    "  proxima info FILE\n"
    "  proxima lmd A B [--pose-a tx ty tz qw qx qy qz] [--pose-b tx ty tz qw qx qy qz]\n"
    "                  [--cutoff D] [--method precise|original|reference] [--force hard|soft] [--json FILE]\n"
    "  proxima polylines A B [--pose-a tx ty tz qw qx qy qz] [--pose-b ...] [--json FILE]\n"
    "  proxima path [A B] [--poses FILE | --steps N] [--method precise|original|both] [--force hard|soft]\n"
    "               [--csv FILE]\n"
    "  proxima run [A B] [--poses FILE] [--seconds S] [--hold S] [--method precise|original] [--force "
    "hard|soft]\n"
    "              [--json FILE]\n"
    "  proxima --version\n";

// Thrown for anything the user got wrong; main prints it and exits 1.
struct UserError {
  std::string message;
};

[[noreturn]] void fail(const std::string& message) { throw UserError{message}; }

// The library's message for the last failed call, without the function name
// it starts with ("proxWorld_LoadMesh: x.obj: cannot read" -> "x.obj: cannot
// read"): the user asked for a file, not a function.
void check(proxResult r) {
  if (r == PROX_SUCCESS) return;
  std::string message = proxGetLastError();
  const auto colon = message.find(": ");
  if (message.rfind("prox", 0) == 0 && colon != std::string::npos && message.find(' ') == colon + 1)
    message = message.substr(colon + 2);
  if (message.empty()) message = proxResultString(r);
  fail(message);
}

double parse_number(const std::string& text, const char* what) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') fail(std::string(what) + ": '" + text + "' is not a number");
  if (!std::isfinite(v)) fail(std::string(what) + ": '" + text + "' is not finite");
  return v;
}

// ---- small vector helpers on the C API's types ---------------------------------

proxVec3 sub(const proxVec3& a, const proxVec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double length(const proxVec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }
proxVec3 centre(const proxMeshInfo& info) {
  return {0.5 * (info.boundsMin.x + info.boundsMax.x), 0.5 * (info.boundsMin.y + info.boundsMax.y),
          0.5 * (info.boundsMin.z + info.boundsMax.z)};
}
proxPose identity() { return {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}}; }
proxPose translation(double x) { return {{x, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}}; }

const char* method_name(proxMethod m) {
  switch (m) {
    case PROX_METHOD_PRECISE:
      return "precise";
    case PROX_METHOD_ORIGINAL:
      return "original";
    case PROX_METHOD_REFERENCE:
      return "reference";
    default:
      return "unknown";
  }
}

const char* feature_name(int32_t kind) {
  switch (kind) {
    case 0:
      return "vertex";
    case 1:
      return "edge";
    case 2:
      return "face";
    default:
      return "unknown";
  }
}

// ---- a world of two meshes: A fixed, B held --------------------------------------

// The settings a command runs with: the method, the cutoff and the force.
struct Settings {
  proxMethod method = PROX_METHOD_PRECISE;
  double cutoff = 0.0;
  proxForceSettings force{};
};

Settings preset(proxForcePreset p) {
  Settings s;
  check(proxGetForcePreset(p, &s.force, &s.cutoff));
  return s;
}

// One world: mesh A as a static body, mesh B (the same mesh when the paths
// are equal) as the tool, torques about B's bounding-box centre.
class Scene {
 public:
  Scene(const Settings& settings, const std::string& path_a, const std::string& path_b,
        const proxPose& pose_a, const proxPose& pose_b) {
    proxWorldDef def = proxDefaultWorldDef();
    def.method = settings.method;
    def.cutoff = settings.cutoff;
    def.force = settings.force;
    check(proxCreateWorld(&def, &world_));
    destroy_on_failure([&] {
      mesh_a_ = load(path_a, nullptr);
      mesh_b_ = path_b == path_a ? mesh_a_ : load(path_b, nullptr);
      proxBodyDef body = proxDefaultBodyDef();
      body.mesh = mesh_a_;
      body.pose = pose_a;
      check(proxWorld_CreateBody(world_, &body, &a_));
      proxMeshInfo info;
      check(proxMesh_GetInfo(mesh_b_, &info));
      body.mesh = mesh_b_;
      body.type = PROX_BODY_TOOL;
      body.pose = pose_b;
      body.referencePoint = centre(info);
      check(proxWorld_CreateBody(world_, &body, &b_));
    });
  }
  // A world holding only one mesh, for `info`.
  explicit Scene(const std::string& path, double* load_seconds) {
    const proxWorldDef def = proxDefaultWorldDef();
    check(proxCreateWorld(&def, &world_));
    destroy_on_failure([&] { mesh_a_ = load(path, load_seconds); });
  }
  ~Scene() {
    if (proxWorld_IsValid(world_)) proxDestroyWorld(world_);
  }
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  proxWorldId world() const { return world_; }
  proxMeshId mesh_a() const { return mesh_a_; }
  proxMeshId mesh_b() const { return mesh_b_; }
  proxBodyId a() const { return a_; }
  proxBodyId b() const { return b_; }

  std::vector<proxContact> contacts() const {
    int32_t count = 0;
    const proxResult r = proxBody_GetContacts(b_, nullptr, 0, &count);
    if (r != PROX_ERROR_CAPACITY) check(r);
    std::vector<proxContact> out(static_cast<std::size_t>(count));
    if (count > 0) check(proxBody_GetContacts(b_, out.data(), count, &count));
    return out;
  }
  proxWrench wrench() const {
    proxWrench w;
    check(proxBody_GetWrench(b_, &w));
    return w;
  }

 private:
  // A constructor that throws runs no destructor: the world goes first.
  template <typename F>
  void destroy_on_failure(F&& build) {
    try {
      build();
    } catch (...) {
      proxDestroyWorld(world_);
      throw;
    }
  }
  proxMeshId load(const std::string& path, double* seconds) {
    const auto start = std::chrono::steady_clock::now();
    proxMeshId mesh{};
    check(proxWorld_LoadMesh(world_, path.c_str(), &mesh));
    if (seconds) *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return mesh;
  }
  proxWorldId world_{};
  proxMeshId mesh_a_{}, mesh_b_{};
  proxBodyId a_{}, b_{};
};

double min_distance(const std::vector<proxContact>& contacts) {
  double d = -1.0;  // none within the cutoff
  for (const proxContact& c : contacts) d = d < 0.0 ? c.distance : std::min(d, c.distance);
  return d;
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
  proxPose pose(const char* option) {
    double v[7];
    for (double& x : v) x = parse_number(next(option), option);
    if (v[3] == 0.0 && v[4] == 0.0 && v[5] == 0.0 && v[6] == 0.0)
      fail(std::string(option) + ": the quaternion (qw qx qy qz) is zero");
    return {{v[0], v[1], v[2]}, {v[3], v[4], v[5], v[6]}};  // the library normalises it
  }

 private:
  std::vector<std::string> args_;
  std::size_t i_ = 0;
};

proxMethod parse_method(const std::string& s) {
  if (s == "precise") return PROX_METHOD_PRECISE;
  if (s == "original") return PROX_METHOD_ORIGINAL;
  if (s == "reference") return PROX_METHOD_REFERENCE;
  fail("--method: '" + s + "' is not precise, original or reference");
}

Settings parse_force(const std::string& s) {
  if (s == "hard") return preset(PROX_FORCE_PRESET_HARD);
  if (s == "soft") return preset(PROX_FORCE_PRESET_SOFT);
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
  double seconds = 0.0;
  const Scene scene(path, &seconds);
  proxMeshInfo m;
  proxMeshStats t;
  check(proxMesh_GetInfo(scene.mesh_a(), &m));
  check(proxMesh_GetStats(scene.mesh_a(), &t));
  const proxVec3 &lo = m.boundsMin, &hi = m.boundsMax;
  std::printf("%s\n", path.c_str());
  std::printf("  triangles        %u (of %u in the file; %u dropped: they repeat a vertex)\n",
              m.triangleCount, t.inputTriangles, m.droppedTriangles);
  std::printf("  vertices         %u welded (of %u in the file)\n", m.vertexCount, t.inputVertices);
  std::printf("  zero-area        %u triangles (kept)\n", t.zeroAreaTriangles);
  std::printf("  boundary edges   %u\n", m.boundaryEdges);
  std::printf("  non-manifold     %u edges\n", m.nonManifoldEdges);
  std::printf("  bounding box     [%.6g, %.6g, %.6g] .. [%.6g, %.6g, %.6g] (size %.6g x %.6g x %.6g)\n", lo.x,
              lo.y, lo.z, hi.x, hi.y, hi.z, hi.x - lo.x, hi.y - lo.y, hi.z - lo.z);
  // Reading, welding and topology: the load call less the hierarchy's build.
  std::printf("  load             %.1f ms\n", std::max(0.0, seconds - t.hierarchySeconds) * 1e3);
  std::printf("  SNCH             %u nodes, depth %u, %u unbounded leaf cones, built in %.1f ms, %.1f MiB\n",
              t.hierarchyNodes, t.hierarchyDepth, t.unboundedLeafCones, t.hierarchySeconds * 1e3,
              static_cast<double>(t.hierarchyBytes) / (1 << 20));
  return 0;
}

// ---- lmd -----------------------------------------------------------------------

int lmd(Args& args) {
  const std::string path_a = args.next("mesh A"), path_b = args.next("mesh B");
  proxPose pose_a = identity(), pose_b = identity();
  double cutoff = 0.005;
  proxMethod method = PROX_METHOD_PRECISE;
  Settings settings = preset(PROX_FORCE_PRESET_HARD);
  std::string force_name = "hard";
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
      settings = parse_force(force_name = args.next("--force value"));
    else if (opt == "--json")
      json_path = args.next("--json file");
    else
      fail("lmd: unknown option '" + opt + "'");
  }
  // The force falls from its maximum at the safety distance to zero at the
  // cutoff, so the cutoff must lie beyond the safety distance.
  if (!(cutoff > settings.force.safetyDistance)) {
    char text[160];
    std::snprintf(text, sizeof text, "--cutoff must be larger than the safety distance of --force %s (%g)",
                  force_name.c_str(), settings.force.safetyDistance);
    fail(text);
  }
  settings.method = method;
  settings.cutoff = cutoff;
  const Scene scene(settings, path_a, path_b, pose_a, pose_b);
  check(proxWorld_Step(scene.world()));
  const std::vector<proxContact> contacts = scene.contacts();
  const proxWrench w = scene.wrench();
  proxSearchStats r;
  check(proxWorld_GetSearchStats(scene.world(), &r));
  const double min_d = min_distance(contacts);

  std::printf("%s LMDs between %s and %s within %g: %zu (from %llu candidates)\n", method_name(method),
              path_a.c_str(), path_b.c_str(), cutoff, contacts.size(),
              static_cast<unsigned long long>(r.candidates));
  for (const proxContact& c : contacts)
    std::printf("  tri %u - tri %u  d=%.9g  %s-%s  a=(%.6g, %.6g, %.6g) b=(%.6g, %.6g, %.6g)\n",
                c.triangleOther, c.triangleTool, c.distance, feature_name(c.featureOther),
                feature_name(c.featureTool), c.pointOther.x, c.pointOther.y, c.pointOther.z, c.pointTool.x,
                c.pointTool.y, c.pointTool.z);
  if (contacts.empty())
    std::printf("  minimum distance: none within the cutoff\n");
  else
    std::printf("  minimum distance: %.9g\n", min_d);
  std::printf("  force on B:  (%.6g, %.6g, %.6g) N%s\n", w.force.x, w.force.y, w.force.z,
              w.clipped ? " (clipped)" : "");
  std::printf("  torque on B: (%.6g, %.6g, %.6g) N m about its box centre\n", w.torque.x, w.torque.y,
              w.torque.z);
  std::printf(
      "  search: %llu node pairs, %llu leaf pairs, %llu culled by visibility, %.3f ms; reduction %.3f ms\n",
      static_cast<unsigned long long>(r.nodePairs), static_cast<unsigned long long>(r.leafPairs),
      static_cast<unsigned long long>(r.visibilityRejections), r.globalSeconds * 1e3,
      r.reductionSeconds * 1e3);

  if (!json_path.empty()) {
    auto count = [](uint64_t n) { return static_cast<long long>(n); };
    Json j;
    j.begin_object();
    // -1 when no pair is within the cutoff (the minimum is then unknown).
    j.key("min_distance").value(min_d);
    j.key("method").value(method_name(method));
    j.key("cutoff").value(cutoff);
    j.key("lmds").begin_array();
    for (const proxContact& c : contacts) {
      j.begin_object();
      j.key("tri_a").value(static_cast<long long>(c.triangleOther));
      j.key("tri_b").value(static_cast<long long>(c.triangleTool));
      j.key("point_a").vec3(c.pointOther);
      j.key("point_b").vec3(c.pointTool);
      j.key("distance").value(c.distance);
      j.key("feature_a").value(feature_name(c.featureOther));
      j.key("feature_b").value(feature_name(c.featureTool));
      j.end_object();
    }
    j.end_array();
    j.key("force").vec3(w.force);
    j.key("torque").vec3(w.torque);
    j.key("stats").begin_object();
    j.key("candidates").value(count(r.candidates));
    j.key("node_pairs").value(count(r.nodePairs));
    j.key("leaf_pairs").value(count(r.leafPairs));
    j.key("plane_rejections").value(count(r.planeRejections));
    j.key("visibility_rejections").value(count(r.visibilityRejections));
    j.key("normal_rejections").value(count(r.normalRejections));
    j.key("distance_evaluations").value(count(r.distanceEvaluations));
    j.key("global_ms").value(r.globalSeconds * 1e3);
    j.key("reduction_ms").value(r.reductionSeconds * 1e3);
    j.key("tracking_cache_hits").value(count(r.reductionCacheHits));
    j.end_object();
    j.end_object();
    write_file(json_path, j.str() + "\n");
  }
  return 0;
}

// ---- polylines -------------------------------------------------------------

int polylines(Args& args) {
  const std::string path_a = args.next("mesh A"), path_b = args.next("mesh B");
  proxPose pose_a = identity(), pose_b = identity();
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
  const Scene scene(preset(PROX_FORCE_PRESET_HARD), path_a, path_b, pose_a, pose_b);
  // Ask the sizes, then fetch (the polylines are computed on each call).
  int32_t point_count = 0, line_count = 0;
  const proxResult sizes =
      proxBody_GetIntersections(scene.b(), nullptr, 0, &point_count, nullptr, 0, &line_count);
  if (sizes != PROX_ERROR_CAPACITY) check(sizes);
  std::vector<proxVec3> points(static_cast<std::size_t>(point_count));
  std::vector<proxPolylineInfo> lines(static_cast<std::size_t>(line_count));
  check(proxBody_GetIntersections(scene.b(), points.data(), point_count, &point_count, lines.data(),
                                  line_count, &line_count));
  proxIntersectionStats stats;
  check(proxBody_GetIntersectionStats(scene.b(), &stats));
  double total = 0.0;
  for (const proxPolylineInfo& line : lines) {
    const proxVec3* p = points.data() + line.firstPoint;
    double len = 0.0;
    for (int32_t k = 0; k + 1 < line.pointCount; ++k) len += length(sub(p[k + 1], p[k]));
    if (line.closed && line.pointCount > 0) len += length(sub(p[0], p[line.pointCount - 1]));
    total += len;
    std::printf("  %s polyline: %d points, length %.9g\n", line.closed ? "closed" : "open", line.pointCount,
                len);
  }
  std::printf(
      "%zu polylines, total length %.9g; %llu intersecting triangle pairs (%llu coplanar, not traced), "
      "%.3f ms\n",
      lines.size(), total, static_cast<unsigned long long>(stats.intersectingPairs),
      static_cast<unsigned long long>(stats.coplanarPairs), stats.seconds * 1e3);
  if (!json_path.empty()) {
    Json j;
    j.begin_object();
    j.key("polylines").begin_array();
    for (const proxPolylineInfo& line : lines) {
      j.begin_object().key("closed").value(line.closed != 0).key("points").begin_array();
      for (int32_t k = 0; k < line.pointCount; ++k)
        j.vec3(points[static_cast<std::size_t>(line.firstPoint + k)]);
      j.end_array().end_object();
    }
    j.end_array();
    j.key("total_length").value(total);
    j.key("stats").begin_object();
    j.key("intersecting_pairs").value(static_cast<long long>(stats.intersectingPairs));
    j.key("coplanar_pairs").value(static_cast<long long>(stats.coplanarPairs));
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
  proxMethod method = PROX_METHOD_PRECISE;
  std::size_t candidates = 0, lmds = 0;
  double min_distance = -1.0;
  proxWrench wrench{};
  double global_ms = 0.0, reduction_ms = 0.0, local_ms = 0.0;
};

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5))];
}

double diagonal(proxMeshId mesh) {
  proxMeshInfo info;
  check(proxMesh_GetInfo(mesh, &info));
  return length(sub(info.boundsMax, info.boundsMin));
}

// Path T of docs/cli.md: B translated along +x from where the minimum
// distance to A is kPathFar to where it is kPathNear, linear in x.
constexpr double kPathFar = 0.05, kPathNear = 0.0005;

// Where B's x puts it `gap` from A: bisection on the exact minimum
// distance; leaves B where it was.
double x_at_gap(const Scene& scene, double gap) {
  proxPose before;
  check(proxBody_GetPose(scene.b(), &before));
  double lo = 0.0, hi = diagonal(scene.mesh_a()) + diagonal(scene.mesh_b()) + gap;
  for (int i = 0; i < 100 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    const proxPose pb = translation(mid);
    check(proxBody_SetPose(scene.b(), &pb));
    double d = -1.0;
    check(proxBody_GetDistance(scene.a(), scene.b(), gap, &d));
    (d >= 0.0 && d < gap ? lo : hi) = mid;
  }
  check(proxBody_SetPose(scene.b(), &before));
  return hi;
}

// A poses file: one pose of B per line, "tx ty tz qw qx qy qz"; blank lines
// and lines starting with # are skipped.
std::vector<proxPose> read_poses(const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "r");
  if (!f) fail(path + ": cannot read");
  std::vector<proxPose> poses;
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
    poses.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5], v[6]}});
  }
  std::fclose(f);
  if (poses.size() < 2) fail(path + ": a path needs at least 2 poses");
  return poses;
}

int path(Args& args) {
  std::string path_a = default_asset("bunny.obj"), path_b;
  int steps = 1000;
  std::string poses_path;
  std::vector<proxMethod> methods = {PROX_METHOD_PRECISE, PROX_METHOD_ORIGINAL};
  Settings settings = preset(PROX_FORCE_PRESET_HARD);
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
      methods = m == "both" ? std::vector<proxMethod>{PROX_METHOD_PRECISE, PROX_METHOD_ORIGINAL}
                            : std::vector<proxMethod>{parse_method(m)};
    } else if (opt == "--force") {
      settings = parse_force(args.next("--force value"));
    } else if (opt == "--csv") {
      csv_path = args.next("--csv file");
    } else if (opt == "--poses") {
      poses_path = args.next("--poses file");
    } else {
      fail("path: unknown option '" + opt + "'");
    }
  }
  if (path_b.empty()) path_b = path_a;
  const double cutoff = settings.cutoff;
  // A world per method, each pair's memory starting afresh; the first also
  // finds the ends of path T.
  auto scene_for = [&](proxMethod method) {
    Settings with_method = settings;
    with_method.method = method;
    return std::make_unique<Scene>(with_method, path_a, path_b, identity(), identity());
  };
  std::unique_ptr<Scene> scene = scene_for(methods.front());
  std::vector<proxPose> poses;
  if (!poses_path.empty()) {
    poses = read_poses(poses_path);
    std::printf("path from %s: %zu poses of %s against %s, cutoff %.3g m\n", poses_path.c_str(), poses.size(),
                path_b.c_str(), path_a.c_str(), cutoff);
  } else {
    const double far = kPathFar, near = kPathNear;
    const double x0 = x_at_gap(*scene, far), x1 = x_at_gap(*scene, near);
    for (int i = 0; i < steps; ++i) poses.push_back(translation(x0 + (x1 - x0) * i / (steps - 1)));
    std::printf(
        "path T: %s held and moved along +x against %s, %d poses from %.3g m to %.3g m apart "
        "(x %.6g .. %.6g), cutoff %.3g m\n",
        path_b.c_str(), path_a.c_str(), steps, far, near, x0, x1, cutoff);
  }

  std::vector<Step> rows;
  for (const proxMethod method : methods) {
    if (!scene) scene = scene_for(method);
    for (std::size_t i = 0; i < poses.size(); ++i) {
      Step s;
      s.index = static_cast<int>(i);
      s.method = method;
      s.x = poses[i].position.x;
      check(proxBody_SetPose(scene->b(), &poses[i]));
      // What the local thread does between global searches: carry the last
      // set to the new pose.
      check(proxWorld_Track(scene->world()));
      proxTrackStats local;
      check(proxWorld_GetTrackStats(scene->world(), &local));
      s.local_ms = local.seconds * 1e3;
      // The global search and its reduction.
      check(proxWorld_Step(scene->world()));
      proxSearchStats search;
      check(proxWorld_GetSearchStats(scene->world(), &search));
      const std::vector<proxContact> contacts = scene->contacts();
      s.candidates = static_cast<std::size_t>(search.candidates);
      s.lmds = contacts.size();
      s.min_distance = min_distance(contacts);
      s.global_ms = search.globalSeconds * 1e3;
      s.reduction_ms = search.reductionSeconds * 1e3;
      s.wrench = scene->wrench();
      rows.push_back(s);
    }
    scene.reset();
  }

  std::string csv =
      "step,method,x,min_distance,candidates,lmds,force_x,force_y,force_z,force,torque_x,torque_y,torque_z,"
      "global_ms,reduction_ms,local_ms\n";
  for (const Step& s : rows) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "%d,%s,%.9g,%.9g,%zu,%zu,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.6f,%.6f,%.6f\n", s.index,
                  method_name(s.method), s.x, s.min_distance, s.candidates, s.lmds, s.wrench.force.x,
                  s.wrench.force.y, s.wrench.force.z, length(s.wrench.force), s.wrench.torque.x,
                  s.wrench.torque.y, s.wrench.torque.z, s.global_ms, s.reduction_ms, s.local_ms);
    csv += line;
  }
  write_file(csv_path, csv);

  std::printf("%-9s %6s %9s %9s %10s %10s %12s %12s %12s %12s\n", "method", "steps", "contact", "max LMDs",
              "max |F| N", "max jump N", "global p50", "global p99", "local p50", "reduction");
  for (const proxMethod method : methods) {
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
      max_force = std::max(max_force, length(s.wrench.force));
      if (previous) max_jump = std::max(max_jump, length(sub(s.wrench.force, previous->wrench.force)));
      previous = &s;
    }
    char reduction[32];
    std::snprintf(reduction, sizeof reduction, "%.1fx",
                  lmds ? static_cast<double>(candidates) / static_cast<double>(lmds) : 0.0);
    std::printf("%-9s %6zu %9d %9zu %10.4f %10.4f %9.3f ms %9.3f ms %9.3f ms %12s\n", method_name(method),
                global.size(), contact, max_lmds, max_force, max_jump, percentile(global, 0.5),
                percentile(global, 0.99), percentile(local, 0.5), reduction);
  }
  std::printf("per-step figures written to %s\n", csv_path.c_str());
  return 0;
}

// `run`: the threaded runtime in real time. The built-in scripted device
// moves B along path T (or the --poses path) in --seconds, then holds it for
// --hold; Proxima's haptic, local and global threads do the rest while this
// thread samples the results every 100 ms, as a renderer would.
int run(Args& args) {
  std::string path_a = default_asset("bunny.obj"), path_b;
  std::string poses_path, json_path;
  double seconds = 2.0, hold = 0.5;
  Settings settings = preset(PROX_FORCE_PRESET_HARD);
  if (!args.empty() && args.peek().rfind("--", 0) != 0) {
    path_a = args.next("mesh A");
    path_b = args.next("mesh B");
  }
  while (!args.empty()) {
    const std::string opt = args.next("option");
    if (opt == "--seconds") {
      seconds = parse_number(args.next("--seconds value"), "--seconds");
      if (!(seconds > 0.0 && seconds <= 3600.0)) fail("--seconds must be in (0, 3600]");
    } else if (opt == "--hold") {
      hold = parse_number(args.next("--hold value"), "--hold");
      if (!(hold >= 0.0 && hold <= 3600.0)) fail("--hold must be in [0, 3600]");
    } else if (opt == "--method") {
      settings.method = parse_method(args.next("--method value"));
      if (settings.method == PROX_METHOD_REFERENCE)
        fail("run: the reference method is too slow for real time");
    } else if (opt == "--force") {
      const proxMethod method = settings.method;
      settings = parse_force(args.next("--force value"));
      settings.method = method;
    } else if (opt == "--poses") {
      poses_path = args.next("--poses file");
    } else if (opt == "--json") {
      json_path = args.next("--json file");
    } else {
      fail("run: unknown option '" + opt + "'");
    }
  }
  if (path_b.empty()) path_b = path_a;
  Scene scene(settings, path_a, path_b, identity(), identity());
  proxScriptedDeviceId device{};
  if (!poses_path.empty()) {
    const std::vector<proxPose> poses = read_poses(poses_path);
    proxScriptedDeviceDef def = proxDefaultScriptedDeviceDef();
    def.poses = poses.data();
    def.poseCount = static_cast<int32_t>(poses.size());
    def.secondsPerPose = seconds / static_cast<double>(poses.size() - 1);
    check(proxWorld_CreateScriptedDevice(scene.world(), &def, &device));
    check(proxBody_SetPose(scene.b(), &poses.front()));
    std::printf("run: %s held along %s (%zu poses in %.3g s, then %.3g s still) against %s, cutoff %.3g m\n",
                path_b.c_str(), poses_path.c_str(), poses.size(), seconds, hold, path_a.c_str(),
                settings.cutoff);
  } else {
    const double far = kPathFar, near = kPathNear;
    const proxPose ends[2] = {translation(x_at_gap(scene, far)), translation(x_at_gap(scene, near))};
    proxScriptedDeviceDef def = proxDefaultScriptedDeviceDef();
    def.poses = ends;
    def.poseCount = 2;
    def.secondsPerPose = seconds;
    check(proxWorld_CreateScriptedDevice(scene.world(), &def, &device));
    check(proxBody_SetPose(scene.b(), &ends[0]));
    std::printf(
        "run: path T, %s held and moved along +x against %s from %.3g m to %.3g m apart in %.3g s, "
        "then %.3g s still, cutoff %.3g m\n",
        path_b.c_str(), path_a.c_str(), far, near, seconds, hold, settings.cutoff);
  }
  proxDeviceDef device_def;
  check(proxScriptedDevice_GetDeviceDef(device, &device_def));
  check(proxBody_SetDevice(scene.b(), &device_def));

  const proxThreadsDef threads = proxDefaultThreadsDef();
  check(proxWorld_StartThreads(scene.world(), &threads));
  std::printf("%8s %12s %9s %12s\n", "time s", "tool x m", "contacts", "|force| N");
  const auto start = std::chrono::steady_clock::now();
  for (int frame = 0;; ++frame) {
    const double t = 0.1 * frame;
    std::this_thread::sleep_until(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                              std::chrono::duration<double>(t)));
    proxPose pose;
    check(proxBody_GetPose(scene.b(), &pose));
    std::printf("%8.1f %12.6f %9zu %12.4f\n", t, pose.position.x, scene.contacts().size(),
                length(scene.wrench().force));
    if (t >= seconds + hold - 1e-9) break;
  }
  check(proxWorld_StopThreads(scene.world()));

  const char* names[3] = {"haptic", "local", "global"};
  proxThreadStats stats[3];
  std::printf("%-7s %10s %10s %11s %11s %11s %11s %9s %9s\n", "thread", "target Hz", "rate Hz", "period p50",
              "period p99", "period max", "work p99", "updates", "overruns");
  for (int i = 0; i < 3; ++i) {
    check(proxWorld_GetThreadStats(scene.world(), static_cast<proxThread>(i), &stats[i]));
    const proxThreadStats& s = stats[i];
    std::printf("%-7s %10.0f %10.0f %8.3f ms %8.3f ms %8.3f ms %8.3f ms %9llu %9llu\n", names[i],
                s.targetRate, s.achievedRate, s.periodP50 * 1e3, s.periodP99 * 1e3, s.periodMax * 1e3,
                s.updateP99 * 1e3, static_cast<unsigned long long>(s.updates),
                static_cast<unsigned long long>(s.overruns));
  }
  proxSafetyStats safety;
  check(proxWorld_GetSafetyStats(scene.world(), &safety));
  proxScriptedDeviceRecord record;
  check(proxScriptedDevice_GetRecord(device, &record));
  std::printf(
      "device: %llu poses read, %llu wrenches written; largest force %.4f N, largest change between "
      "ticks %.4f N; %s\n",
      static_cast<unsigned long long>(record.reads), static_cast<unsigned long long>(record.writes),
      record.maxForce, record.maxForceStep, record.allFinite ? "all finite" : "NOT ALL FINITE");
  std::printf(
      "safety: %llu invalid poses, %llu stale ticks, %llu untrusted ticks, %llu limited ticks, "
      "%llu torn snapshots\n",
      static_cast<unsigned long long>(safety.invalidPoses),
      static_cast<unsigned long long>(safety.staleTicks),
      static_cast<unsigned long long>(safety.untrustedTicks),
      static_cast<unsigned long long>(safety.limitedTicks),
      static_cast<unsigned long long>(safety.tornSnapshots));

  if (!json_path.empty()) {
    auto count = [](uint64_t n) { return static_cast<long long>(n); };
    Json j;
    j.begin_object();
    j.key("method").value(method_name(settings.method));
    j.key("cutoff").value(settings.cutoff);
    j.key("threads").begin_object();
    for (int i = 0; i < 3; ++i) {
      const proxThreadStats& s = stats[i];
      j.key(names[i]).begin_object();
      j.key("target_hz").value(s.targetRate);
      j.key("achieved_hz").value(s.achievedRate);
      j.key("period_p50_ms").value(s.periodP50 * 1e3);
      j.key("period_p99_ms").value(s.periodP99 * 1e3);
      j.key("period_max_ms").value(s.periodMax * 1e3);
      j.key("update_p50_ms").value(s.updateP50 * 1e3);
      j.key("update_p99_ms").value(s.updateP99 * 1e3);
      j.key("update_max_ms").value(s.updateMax * 1e3);
      j.key("updates").value(count(s.updates));
      j.key("overruns").value(count(s.overruns));
      j.end_object();
    }
    j.end_object();
    j.key("device").begin_object();
    j.key("reads").value(count(record.reads));
    j.key("writes").value(count(record.writes));
    j.key("max_force").value(record.maxForce);
    j.key("max_torque").value(record.maxTorque);
    j.key("max_force_step").value(record.maxForceStep);
    j.key("all_finite").value(record.allFinite != 0);
    j.end_object();
    j.key("safety").begin_object();
    j.key("invalid_poses").value(count(safety.invalidPoses));
    j.key("stale_ticks").value(count(safety.staleTicks));
    j.key("untrusted_ticks").value(count(safety.untrustedTicks));
    j.key("limited_ticks").value(count(safety.limitedTicks));
    j.key("torn_snapshots").value(count(safety.tornSnapshots));
    j.key("dropped_contacts").value(count(safety.droppedContacts));
    j.end_object();
    j.end_object();
    write_file(json_path, j.str() + "\n");
  }
  return record.allFinite ? 0 : 1;
}

}  // namespace
}  // namespace proxcli

int main(int argc, char** argv) {
  using namespace proxcli;
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
    if (command == "run") return run(args);
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
