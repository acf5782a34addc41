#include "scene.h"

#include "hid_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/quaternion.hpp>

namespace viewer {

namespace {

// The library's message without the function it starts with
// ("proxWorld_LoadMesh: cannot open 'x.obj'" -> "cannot open 'x.obj'"):
// the user named a file, not a function.
void check(proxResult r) {
  if (r == PROX_SUCCESS) return;
  std::string message = proxGetLastError();
  const auto colon = message.find(": ");
  if (message.rfind("prox", 0) == 0 && colon != std::string::npos) message.erase(0, colon + 2);
  throw SceneError(message.empty() ? proxResultString(r) : message);
}

proxPose translation(double x) { return {{x, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}}; }

glm::dmat4 matrix(const proxPose& p) {
  const glm::dquat q(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z);
  glm::dmat4 m = glm::mat4_cast(glm::normalize(q));
  m[3] = glm::dvec4(p.position.x, p.position.y, p.position.z, 1.0);
  return m;
}

// The poses of a path file, for the pace and the camera's frame; the
// library's loader reads the file again and names anything wrong in it.
std::vector<proxPose> read_path(const std::string& path) {
  std::vector<proxPose> poses;
  FILE* f = std::fopen(path.c_str(), "r");
  if (!f) throw SceneError(path + ": cannot read");
  char line[1024];
  while (std::fgets(line, sizeof line, f)) {
    double v[7];
    if (std::sscanf(line, "%lf %lf %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6]) ==
        7)
      poses.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5], v[6]}});
  }
  std::fclose(f);
  return poses;
}

}  // namespace

Scene::Scene(const Options& options, const std::string& path_a, const std::string& path_b) {
  check(proxGetForcePreset(options.force, &force_, &cutoff_));
  if (options.cutoff > 0.0) cutoff_ = options.cutoff;
  proxWorldDef def = proxDefaultWorldDef();
  def.method = options.method;
  def.cutoff = cutoff_;
  def.force = force_;
  check(proxCreateWorld(&def, &world_));
  try {
    build(options, path_a, path_b);
  } catch (...) {
    proxWorld_Destroy(world_);  // a constructor that throws runs no destructor
    throw;
  }
}

Scene::~Scene() {
  if (proxWorld_IsValid(world_)) proxWorld_Destroy(world_);
}

void Scene::build(const Options& options, const std::string& path_a, const std::string& path_b) {
  check(proxWorld_LoadMesh(world_, path_a.c_str(), &mesh_a_));
  mesh_b_ = mesh_a_;
  // One file animated otherwise for A than for the tool is two meshes.
  if (path_b != path_a || options.animate_b != options.animate_a)
    check(proxWorld_LoadMesh(world_, path_b.c_str(), &mesh_b_));
  proxMeshInfo info_a, info_b;
  check(proxMesh_GetInfo(mesh_a_, &info_a));
  check(proxMesh_GetInfo(mesh_b_, &info_b));
  if (options.animate_a >= 0)
    animations_[0] = animation(mesh_a_, options.animate_a, options.animate_a_option, path_a);
  if (options.animate_b >= 0 && !shares_mesh())
    animations_[1] = animation(mesh_b_, options.animate_b, "--animate-b", path_b);
  glm::dvec3 lo_a(info_a.boundsMin.x, info_a.boundsMin.y, info_a.boundsMin.z);
  glm::dvec3 hi_a(info_a.boundsMax.x, info_a.boundsMax.y, info_a.boundsMax.z);
  glm::dvec3 lo_b(info_b.boundsMin.x, info_b.boundsMin.y, info_b.boundsMin.z);
  glm::dvec3 hi_b(info_b.boundsMax.x, info_b.boundsMax.y, info_b.boundsMax.z);
  animated_bounds(animations_[0], &lo_a, &hi_a);
  animated_bounds(animations_[1], &lo_b, &hi_b);
  if (shares_mesh()) lo_b = lo_a, hi_b = hi_a;

  proxBodyDef body = proxDefaultBodyDef();
  body.mesh = mesh_a_;
  check(proxWorld_CreateBody(world_, &body, &a_));
  body.mesh = mesh_b_;
  body.type = PROX_BODY_TOOL;
  body.pose = options.pose_b;
  constrained_ = options.tool_mode == PROX_TOOL_CONSTRAINED;
  const glm::dvec3 lo(info_b.boundsMin.x, info_b.boundsMin.y, info_b.boundsMin.z);
  const glm::dvec3 hi(info_b.boundsMax.x, info_b.boundsMax.y, info_b.boundsMax.z);
  reference_local_ = 0.5 * (lo + hi);
  body.referencePoint = {reference_local_.x, reference_local_.y, reference_local_.z};
  check(proxWorld_CreateBody(world_, &body, &tool_));
  // Puts the tool where its device starts. A constrained tool must start
  // clear of A (its proxy never moves through it), so it is made there: the
  // free tool above only serves to find that pose (x_at_gap).
  auto place = [&](const proxPose& start) {
    if (!constrained_) {
      check(proxBody_SetPose(tool_, &start));
      return;
    }
    check(proxBody_Destroy(tool_));
    body.pose = start;
    body.toolMode = PROX_TOOL_CONSTRAINED;
    check(proxWorld_CreateBody(world_, &body, &tool_));
  };

  // The poses the tool visits, for the camera's frame.
  std::vector<proxPose> visited{options.pose_b};
  proxScriptedDeviceId device{};
  if (options.device_kind == DeviceKind::scripted) {
    if (!options.poses_file.empty()) {
      visited = read_path(options.poses_file);
      const double pace = options.seconds / static_cast<double>(std::max<std::size_t>(2, visited.size()) - 1);
      check(proxWorld_LoadScriptedDevice(world_, options.poses_file.c_str(), pace, 1, &device));
      place(visited.front());
    } else {
      // Path T (docs/cli.md) there and back, from 50 mm apart to 0.5 mm,
      // holding the near end as long as each way takes.
      const proxPose far = translation(x_at_gap(0.05)), near = translation(x_at_gap(0.0005));
      const proxPose ends[4] = {far, near, near, far};
      proxScriptedDeviceDef d = proxDefaultScriptedDeviceDef();
      d.poses = ends;
      d.poseCount = 4;
      d.loop = 1;
      d.secondsPerPose = options.seconds;
      check(proxWorld_CreateScriptedDevice(world_, &d, &device));
      visited = {ends[0], ends[1]};
      place(ends[0]);
    }
    proxDeviceDef device_def;
    check(proxScriptedDevice_GetDeviceDef(device, &device_def));
    check(proxBody_SetDevice(tool_, &device_def));
  } else if (options.device_kind == DeviceKind::mouse || options.device_kind == DeviceKind::gamepad) {
    // The streamed device (docs/devices.md), fed once a frame. A software
    // renderer's frames can take 50 ms or more: one frame of interpolation
    // delay at 30 Hz, and silence only after half a second.
    proxStreamDeviceDef d = proxDefaultStreamDeviceDef();
    d.mode = PROX_STREAM_INTERPOLATE;
    d.delay = 1.0 / 30.0;
    d.staleAfter = 0.5;
    place(options.pose_b);
    check(proxWorld_CreateStreamDevice(world_, &d, &stream_));
    check(proxStreamDevice_PushPose(stream_, &options.pose_b, proxGetTime()));
    proxDeviceDef device_def;
    check(proxStreamDevice_GetDeviceDef(stream_, &device_def));
    check(proxBody_SetDevice(tool_, &device_def));
  } else if (options.device_kind == DeviceKind::hid) {
    // The built-in scene starts where path T does, 50 mm from A. The
    // device's own thread moves the tool from there.
    const proxPose start = options.mesh_a.empty() ? translation(x_at_gap(0.05)) : options.pose_b;
    if (options.mesh_a.empty()) visited = {start, translation(x_at_gap(0.0005))};
    place(start);
    hid_ = attach_hid(world_, tool_, start, body.referencePoint);
  }

  // The camera's box: A, and the tool at every pose it visits, each over its
  // whole animation.
  bounds_min_ = lo_a;
  bounds_max_ = hi_a;
  for (const proxPose& pose : visited) {
    const glm::dmat4 m = matrix(pose);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::dvec3 c((corner & 1) ? hi_b.x : lo_b.x, (corner & 2) ? hi_b.y : lo_b.y,
                         (corner & 4) ? hi_b.z : lo_b.z);
      const glm::dvec3 w = glm::dvec3(m * glm::dvec4(c, 1.0));
      bounds_min_ = glm::min(bounds_min_, w);
      bounds_max_ = glm::max(bounds_max_, w);
    }
  }

  if (options.device_kind == DeviceKind::none) {
    place(options.pose_b);
    check(proxWorld_Step(world_));  // the tool stays: one deterministic step is the whole answer
  } else {
    const proxThreadsDef threads = proxDefaultThreadsDef();
    check(proxWorld_StartThreads(world_, &threads));
    threads_ = true;
  }
}

// Where the tool's x puts it `gap` from A: bisection on the exact minimum
// distance, as `proxima path` does; leaves the tool where it was.
double Scene::x_at_gap(double gap) const {
  proxPose before;
  check(proxBody_GetPose(tool_, &before));
  proxMeshInfo a, b;
  check(proxMesh_GetInfo(mesh_a_, &a));
  check(proxMesh_GetInfo(mesh_b_, &b));
  auto diagonal = [](const proxMeshInfo& i) {
    return std::hypot(i.boundsMax.x - i.boundsMin.x, i.boundsMax.y - i.boundsMin.y,
                      i.boundsMax.z - i.boundsMin.z);
  };
  double lo = 0.0, hi = diagonal(a) + diagonal(b) + gap;
  for (int i = 0; i < 100 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    const proxPose p = translation(mid);
    check(proxBody_SetPose(tool_, &p));
    double d = -1.0;
    check(proxBody_GetDistance(a_, tool_, gap, &d));
    (d >= 0.0 && d < gap ? lo : hi) = mid;
  }
  check(proxBody_SetPose(tool_, &before));
  return hi;
}

void Scene::update(FrameData& frame, bool polylines) const {
  // The tool is drawn, and its contacts were found, at its proxy; a
  // constrained tool's device pose (GetPose) may be elsewhere.
  proxPose pa, pt, device;
  check(proxBody_GetPose(a_, &pa));
  check(proxBody_GetProxyPose(tool_, &pt));
  check(proxBody_GetPose(tool_, &device));
  frame.model_a = matrix(pa);
  frame.model_tool = matrix(pt);
  frame.tool_pose = pt;
  frame.device_pose = device;
  frame.model_ghost = matrix(device);
  frame.reference_point = glm::dvec3(frame.model_tool * glm::dvec4(reference_local_, 1.0));

  int32_t count = 0;
  proxResult r = proxBody_GetContactPatches(tool_, nullptr, nullptr, 0, &count);
  if (r != PROX_ERROR_CAPACITY) check(r);
  frame.contacts.resize(static_cast<std::size_t>(count));
  frame.patches.resize(static_cast<std::size_t>(count));
  if (count > 0) {
    // Local tracking may have found more since the size was asked: take what fits.
    r = proxBody_GetContactPatches(tool_, frame.contacts.data(), frame.patches.data(), count, &count);
    if (r != PROX_ERROR_CAPACITY) check(r);
    const auto kept =
        static_cast<std::size_t>(std::min<int32_t>(count, static_cast<int32_t>(frame.contacts.size())));
    frame.contacts.resize(kept);
    frame.patches.resize(kept);
  }
  check(proxBody_GetWrench(tool_, &frame.wrench));

  auto same = [](const proxPose& a, const proxPose& b) {
    return a.position.x == b.position.x && a.position.y == b.position.y && a.position.z == b.position.z &&
           a.rotation.w == b.rotation.w && a.rotation.x == b.rotation.x && a.rotation.y == b.rotation.y &&
           a.rotation.z == b.rotation.z;
  };
  frame.ghost = constrained_ && !same(pt, device);

  if (!polylines) {
    frame.polylines.clear();
    frame.polylines_valid = false;
  } else if (!frame.polylines_valid || !same(frame.polylines_pose, pt)) {
    frame.polylines.clear();
    frame.polylines_valid = true;
    frame.polylines_pose = pt;
    // The polylines are computed on each call: ask once into last frame's
    // buffers, and again only when they were too small.
    std::vector<proxVec3>& p = frame.polyline_points;
    std::vector<proxPolylineInfo>& l = frame.polyline_infos;
    int32_t points = 0, lines = 0;
    r = proxBody_GetIntersections(tool_, p.data(), static_cast<int32_t>(p.size()), &points, l.data(),
                                  static_cast<int32_t>(l.size()), &lines);
    if (r == PROX_ERROR_CAPACITY) {
      p.resize(static_cast<std::size_t>(points) * 2);
      l.resize(static_cast<std::size_t>(lines) * 2);
      r = proxBody_GetIntersections(tool_, p.data(), static_cast<int32_t>(p.size()), &points, l.data(),
                                    static_cast<int32_t>(l.size()), &lines);
    }
    check(r);
    for (int32_t i = 0; i < lines; ++i) {
      const proxPolylineInfo& info = l[static_cast<std::size_t>(i)];
      Polyline line;
      line.closed = info.closed != 0;
      for (int32_t k = 0; k < info.pointCount; ++k) {
        const proxVec3& v = p[static_cast<std::size_t>(info.firstPoint + k)];
        line.points.emplace_back(v.x, v.y, v.z);
      }
      frame.polylines.push_back(std::move(line));
    }
  }

  frame.threads = threads_;
  for (int t = 0; t < 3; ++t)
    check(proxWorld_GetThreadStats(world_, static_cast<proxThread>(t), &frame.thread_stats[t]));
}

void Scene::push_tool_pose(const proxPose& pose) {
  check(proxStreamDevice_PushPose(stream_, &pose, proxGetTime()));
}

std::string Scene::hid_summary() const { return viewer::hid_summary(world_, hid_); }

bool Scene::stream_stats(proxStreamDeviceStats* stats) const {
  if (stream_.index1 == 0) return false;
  check(proxStreamDevice_GetStats(stream_, stats));
  return true;
}

proxPose Scene::tool_pose() const {
  proxPose p;
  check(proxBody_GetPose(tool_, &p));
  return p;
}

std::vector<double> Scene::force_shares(const std::vector<proxContact>& contacts,
                                        const std::vector<proxContactPatch>& patches) const {
  std::vector<double> w;
  double sum = 0.0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const proxContact& c = contacts[i];
    const double d = std::max(c.distance, force_.safetyDistance);
    double f = 0.0;
    if (d < cutoff_) {
      f = force_.curve == PROX_FORCE_LINEAR ? (cutoff_ - d) / (cutoff_ - force_.safetyDistance)
                                            : std::exp(-(d - force_.safetyDistance) / force_.decayLength);
      if (i < patches.size()) f *= std::max(1, patches[i].count);  // a patch pushes as its count would
    }
    w.push_back(f);
    sum += f;
  }
  for (double& x : w) x = sum > 0.0 ? x / sum : 0.0;
  return w;
}

Scene::Animation Scene::animation(proxMeshId mesh, int index, const std::string& option,
                                  const std::string& path) const {
  int32_t count = 0;
  check(proxMesh_GetAnimationCount(mesh, &count));
  const std::string given = option + " " + std::to_string(index) + ": " + path;
  if (count == 0) throw SceneError(given + " has no animations");
  if (index >= count)
    throw SceneError(given + " has " + std::to_string(count) +
                     (count == 1 ? " animation (index 0)"
                                 : " animations (indices 0 to " + std::to_string(count - 1) + ")"));
  proxAnimationInfo info;
  check(proxMesh_GetAnimationInfo(mesh, index, &info));
  return {mesh, index, info.start, std::max(0.0, info.duration - info.start)};
}

void Scene::animated_bounds(const Animation& a, glm::dvec3* lo, glm::dvec3* hi) {
  if (a.index < 0) return;
  *lo = glm::dvec3(HUGE_VAL);
  *hi = glm::dvec3(-HUGE_VAL);
  const int steps = std::clamp(static_cast<int>(std::ceil(a.length * 60.0)), 1, 600);
  for (int s = steps; s >= 0; --s) {  // the last pose is the animation's start
    check(proxMesh_Animate(a.mesh, a.index, a.start + a.length * s / steps));
    read_positions(a.mesh);
    for (std::size_t v = 0; v + 2 < positions_.size(); v += 3) {
      const glm::dvec3 p(positions_[v], positions_[v + 1], positions_[v + 2]);
      *lo = glm::min(*lo, p);
      *hi = glm::max(*hi, p);
    }
  }
}

bool Scene::animate(double seconds) {
  bool posed = false;
  for (const Animation& a : animations_) {
    if (a.index < 0) continue;
    const double t = a.start + (a.length > 0.0 ? std::fmod(seconds, a.length) : 0.0);
    check(proxMesh_Animate(a.mesh, a.index, t));
    posed = true;
  }
  // Without threads the world answers at its steps: one on the new shape.
  if (posed && !threads_) check(proxWorld_Step(world_));
  return posed;
}

void Scene::read_positions(proxMeshId mesh) {
  proxMeshInfo info;
  check(proxMesh_GetInfo(mesh, &info));
  positions_.resize(3 * std::size_t{info.vertexCount});
  indices_.resize(3 * std::size_t{info.triangleCount});
  uint32_t vertices = 0, triangles = 0;
  check(proxMesh_GetTriangles(mesh, positions_.data(), info.vertexCount, &vertices, indices_.data(),
                              info.triangleCount, &triangles));
}

void Scene::read_vertices(bool tool, std::vector<float>& positions) {
  read_positions(tool ? mesh_b_ : mesh_a_);
  positions.resize(positions_.size());
  std::copy(positions_.begin(), positions_.end(), positions.begin());
}

RenderMesh Scene::render_mesh(bool tool) const {
  const proxMeshId mesh = tool ? mesh_b_ : mesh_a_;
  uint32_t vertices = 0, triangles = 0;
  const proxResult r = proxMesh_GetTriangles(mesh, nullptr, 0, &vertices, nullptr, 0, &triangles);
  if (r != PROX_ERROR_CAPACITY) check(r);
  std::vector<double> positions(3 * std::size_t{vertices});
  RenderMesh out;
  out.indices.resize(3 * std::size_t{triangles});
  check(proxMesh_GetTriangles(mesh, positions.data(), vertices, &vertices, out.indices.data(), triangles,
                              &triangles));
  out.positions.assign(positions.begin(), positions.end());
  return out;
}

}  // namespace viewer
