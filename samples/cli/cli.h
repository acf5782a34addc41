// What the proxima tool's commands share: errors for the user, argument
// parsing, the force presets, a world of two meshes (A fixed, B held), the
// built-in path and pose files. Each command has a file of its own.
#pragma once

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

using Json = prox::JsonWriter;

// Thrown for anything the user got wrong; main prints it and exits 1.
struct UserError {
  std::string message;
};

[[noreturn]] inline void fail(const std::string& message) { throw UserError{message}; }

// The library's message for the last failed call, without the function name
// it starts with ("proxWorld_LoadMesh: x.obj: cannot read" -> "x.obj: cannot
// read"): the user asked for a file, not a function.
inline void check(proxResult r) {
  if (r == PROX_SUCCESS) return;
  std::string message = proxGetLastError();
  const auto colon = message.find(": ");
  if (message.rfind("prox", 0) == 0 && colon != std::string::npos && message.find(' ') == colon + 1)
    message = message.substr(colon + 2);
  if (message.empty()) message = proxResultString(r);
  fail(message);
}

inline double parse_number(const std::string& text, const char* what) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') fail(std::string(what) + ": '" + text + "' is not a number");
  if (!std::isfinite(v)) fail(std::string(what) + ": '" + text + "' is not finite");
  return v;
}

inline double parse_positive(const std::string& text, const char* what) {
  const double v = parse_number(text, what);
  if (!(v > 0.0)) fail(std::string(what) + ": '" + text + "' must be > 0");
  return v;
}

// small vector helpers on the C API's types

inline proxVec3 sub(const proxVec3& a, const proxVec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline double length(const proxVec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }
inline proxVec3 centre(const proxMeshInfo& info) {
  return {0.5 * (info.boundsMin.x + info.boundsMax.x), 0.5 * (info.boundsMin.y + info.boundsMax.y),
          0.5 * (info.boundsMin.z + info.boundsMax.z)};
}
inline proxPose identity() { return {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}}; }
inline proxPose translation(double x) { return {{x, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}}; }

inline const char* method_name(proxMethod m) {
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

inline const char* feature_name(int32_t kind) {
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

// a world of two meshes: A fixed, B held

// The settings a command runs with: the method, the cutoff and the force.
struct Settings {
  proxMethod method = PROX_METHOD_PRECISE;
  double cutoff = 0.0;
  proxForceSettings force{};
  proxForcePreset preset = PROX_FORCE_PRESET_HARD;  // the force settings' preset
};

inline Settings preset(proxForcePreset p) {
  Settings s;
  s.preset = p;
  check(proxGetForcePreset(p, &s.force, &s.cutoff));
  return s;
}

// The settings' preset at another cutoff (the library scales it:
// proxGetForcePresetAt).
inline Settings scaled_to(Settings s, double cutoff) {
  s.cutoff = cutoff;
  check(proxGetForcePresetAt(s.preset, cutoff, &s.force));
  return s;
}

// A glTF animation to pose a mesh at (proxMesh_Animate): `--animate-a
// INDEX:SECONDS`; index -1: none.
struct AnimateAt {
  int32_t index = -1;
  double seconds = 0.0;
  bool operator==(const AnimateAt& o) const { return index == o.index && seconds == o.seconds; }
};

// One world: mesh A as a static body, mesh B (the same mesh when the paths
// and animations are equal) as the tool, torques about B's bounding-box
// centre. Each mesh is first posed at its animation, if any.
class Scene {
 public:
  Scene(const Settings& settings, const std::string& path_a, const std::string& path_b,
        const proxPose& pose_a, const proxPose& pose_b, proxToolMode tool_mode = PROX_TOOL_FREE,
        const AnimateAt& animate_a = {}, const AnimateAt& animate_b = {}) {
    proxWorldDef def = proxDefaultWorldDef();
    def.method = settings.method;
    def.cutoff = settings.cutoff;
    def.force = settings.force;
    check(proxCreateWorld(&def, &world_));
    destroy_on_failure([&] {
      mesh_a_ = load(path_a, nullptr);
      mesh_b_ = path_b == path_a && animate_b == animate_a ? mesh_a_ : load(path_b, nullptr);
      animate(mesh_a_, animate_a, "--animate-a");
      if (!(mesh_b_.index1 == mesh_a_.index1)) animate(mesh_b_, animate_b, "--animate-b");
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
      body.toolMode = tool_mode;
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
    if (proxWorld_IsValid(world_)) proxWorld_Destroy(world_);
  }
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  proxWorldId world() const { return world_; }
  proxMeshId mesh_a() const { return mesh_a_; }
  proxMeshId mesh_b() const { return mesh_b_; }
  proxBodyId a() const { return a_; }
  proxBodyId b() const { return b_; }

  std::vector<proxContact> contacts() const {
    std::vector<proxContact> out;
    std::vector<proxContactPatch> unused;
    contacts(out, unused);
    return out;
  }
  // The contacts and each one's patch (docs/patches.md), from one snapshot.
  void contacts(std::vector<proxContact>& contacts, std::vector<proxContactPatch>& patches) const {
    int32_t count = 0;
    const proxResult r = proxBody_GetContactPatches(b_, nullptr, nullptr, 0, &count);
    if (r != PROX_ERROR_CAPACITY) check(r);
    contacts.resize(static_cast<std::size_t>(count));
    patches.resize(static_cast<std::size_t>(count));
    if (count > 0) check(proxBody_GetContactPatches(b_, contacts.data(), patches.data(), count, &count));
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
      proxWorld_Destroy(world_);
      throw;
    }
  }
  static void animate(proxMeshId mesh, const AnimateAt& at, const char* option) {
    if (at.index < 0) return;
    if (proxMesh_Animate(mesh, at.index, at.seconds) != PROX_SUCCESS)
      fail(std::string(option) + ": " + proxGetLastError());
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

inline double min_distance(const std::vector<proxContact>& contacts) {
  double d = -1.0;  // none within the cutoff
  for (const proxContact& c : contacts) d = d < 0.0 ? c.distance : std::min(d, c.distance);
  return d;
}

inline std::string default_asset(const char* name) {
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

inline proxMethod parse_method(const std::string& s) {
  if (s == "precise") return PROX_METHOD_PRECISE;
  if (s == "original") return PROX_METHOD_ORIGINAL;
  if (s == "reference") return PROX_METHOD_REFERENCE;
  fail("--method: '" + s + "' is not precise, original or reference");
}

inline Settings parse_force(const std::string& s) {
  if (s == "hard") return preset(PROX_FORCE_PRESET_HARD);
  if (s == "soft") return preset(PROX_FORCE_PRESET_SOFT);
  fail("--force: '" + s + "' is not hard or soft");
}

inline void write_file(const std::string& path, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) fail(path + ": cannot write");
  std::fputs(text.c_str(), f);
  if (std::fclose(f) != 0) fail(path + ": cannot write");
}

inline double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5))];
}

inline double diagonal(proxMeshId mesh) {
  proxMeshInfo info;
  check(proxMesh_GetInfo(mesh, &info));
  return length(sub(info.boundsMax, info.boundsMin));
}

// Path T of docs/cli.md: B translated along +x from where the minimum
// distance to A is kPathFar to where it is kPathNear, linear in x.
inline constexpr double kPathFar = 0.05, kPathNear = 0.0005;

// Where B's x puts it `gap` from A: bisection on the exact minimum
// distance; leaves B where it was.
inline double x_at_gap(const Scene& scene, double gap) {
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
inline std::vector<proxPose> read_poses(const std::string& path) {
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

// The commands: each parses its own arguments and returns the exit status.
int info(Args& args);
int lmd(Args& args);
int polylines(Args& args);
int path(Args& args);
int run(Args& args);
// The flight recorder for `run --trace` (trace.cpp): the capacity a run of
// `seconds` needs, and its ticks written as CSV (how many).
int trace_capacity_for(double seconds, double haptic_rate);
std::size_t write_trace_csv(proxBodyId tool, int capacity, const std::string& path);
int devices(Args& args);

// HID devices for `run --device hid[:VVVV:PPPP]` (devices.cpp; only when
// libproxima was built with them, else opening fails with a message).
struct HidRun;
bool is_hid_kind(const std::string& kind);
// Opens the device the kind names and fills *def to attach it; the tool
// starts at `start` and turns about `reference` (in its frame).
std::shared_ptr<HidRun> open_hid(const std::string& kind, proxWorldId world, const proxPose& start,
                                 const proxVec3& reference, proxDeviceDef* def);
std::string hid_description(const HidRun& hid);
void print_hid_stats(const HidRun& hid);
void hid_json(const HidRun& hid, Json& j);

}  // namespace proxcli
