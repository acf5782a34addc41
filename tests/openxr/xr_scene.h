// The tests' scene: a static bunny and a tool bunny held by the mock's right
// controller, with the poses between OpenXR's world and Proxima's worked out
// here, independently of sdk/src/xr (glm, not the device's code).
#pragma once

#include <proxima/proxima_openxr.h>

#include "openxr/mock_control.h"
#include "openxr/xr_app.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace prox::test {

// The vibrations the mock received from the `first`-th on, and how many so far.
inline std::vector<ProxMockXrVibration> vibrations_since(int32_t first) {
  const int32_t total = mock_control().vibrations(nullptr, 0, 0);
  std::vector<ProxMockXrVibration> v(std::size_t(std::max(0, total - first)));
  if (!v.empty()) mock_control().vibrations(v.data(), first, int32_t(v.size()));
  return v;
}
inline int32_t vibration_count() { return mock_control().vibrations(nullptr, 0, 0); }

struct Rigid {
  glm::dquat q{1, 0, 0, 0};
  glm::dvec3 p{0, 0, 0};
  Rigid operator*(const Rigid& b) const { return {q * b.q, p + q * b.p}; }
  Rigid inverse() const {
    const glm::dquat c = glm::conjugate(q);
    return {c, -(c * p)};
  }
};

inline Rigid of(const proxPose& x) {
  return {glm::dquat(x.rotation.w, x.rotation.x, x.rotation.y, x.rotation.z),
          {x.position.x, x.position.y, x.position.z}};
}
inline proxPose to_prox(const Rigid& r) { return {{r.p.x, r.p.y, r.p.z}, {r.q.w, r.q.x, r.q.y, r.q.z}}; }
inline XrPosef to_xr(const Rigid& r) {
  XrPosef x;
  x.orientation = {float(r.q.x), float(r.q.y), float(r.q.z), float(r.q.w)};
  x.position = {float(r.p.x), float(r.p.y), float(r.p.z)};
  return x;
}
inline Rigid of(const XrPosef& x) {  // floats: a unit quaternion only to about 1e-7
  return {glm::normalize(glm::dquat(x.orientation.w, x.orientation.x, x.orientation.y, x.orientation.z)),
          {x.position.x, x.position.y, x.position.z}};
}

inline void prox_check(proxResult r, const char* what) {
  if (r != PROX_SUCCESS) throw std::runtime_error(std::string(what) + ": " + proxGetLastError());
}

inline double norm(const proxVec3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

class XrScene {
 public:
  // The OpenXR world's place in Proxima's and the tool's in the grip: both
  // rotated, so a frame mixed up anywhere moves the tool elsewhere.
  const Rigid baseToWorld{glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 1, 0)), {0.3, -1.2, 0.1}};
  const Rigid toolInGrip{glm::angleAxis(glm::radians(30.0), glm::dvec3(1, 0, 0)), {0.02, 0.0, -0.05}};

  XrScene() {
    proxWorldDef wd = proxDefaultWorldDef();
    prox_check(proxCreateWorld(&wd, &world), "proxCreateWorld");
    prox_check(proxWorld_LoadMesh(world, PROX_SHARED_ASSETS_DIR "/bunny.obj", &mesh), "proxWorld_LoadMesh");
    proxMeshInfo info;
    prox_check(proxMesh_GetInfo(mesh, &info), "proxMesh_GetInfo");
    width = info.boundsMax.x - info.boundsMin.x;
    proxBodyDef bd = proxDefaultBodyDef();
    bd.mesh = mesh;
    prox_check(proxWorld_CreateBody(world, &bd, &rock), "proxWorld_CreateBody");
    bd.type = PROX_BODY_TOOL;
    bd.pose = to_prox(far_tool());
    prox_check(proxWorld_CreateBody(world, &bd, &tool), "proxWorld_CreateBody");
  }
  ~XrScene() {
    if (proxWorld_IsValid(world)) proxWorld_Destroy(world);
  }

  // Tool poses in Proxima's world: far from the rock, and a few mm from it
  // (in contact, as samples/stream finds).
  Rigid far_tool() const { return {{1, 0, 0, 0}, {1.6 * width, 0, 0}}; }
  Rigid near_tool() const { return {{1, 0, 0, 0}, {0.9 * width, 0, 0}}; }
  // The grip pose in the OpenXR world that puts the tool at `tool`.
  Rigid grip_for(const Rigid& held) const { return baseToWorld.inverse() * held * toolInGrip.inverse(); }
  // The tool pose a grip pose makes (the grip as the runtime reports it: floats).
  Rigid tool_for(const XrPosef& grip) const { return baseToWorld * of(grip) * toolInGrip; }

  // The script: the grip at `tool` from now on.
  void hold(const Rigid& held) const {
    const ProxMockXrKey key{mock_control().now(), to_xr(grip_for(held))};
    mock_control().setScript(&key, 1);
  }

  proxXrDeviceDef def(const XrApp& app) const {
    proxXrDeviceDef d = app.device_def();
    d.baseToWorld = to_prox(baseToWorld);
    d.toolInGrip = to_prox(toolInGrip);
    d.forceForFullAmplitude = 1.0;
    return d;
  }

  // Creates the device, attaches it to the tool and starts the threads.
  proxXrDeviceId start(XrApp& app, const proxXrDeviceDef& d) {
    proxXrDeviceId device{};
    prox_check(proxWorld_CreateXrDevice(world, &d, &device), "proxWorld_CreateXrDevice");
    app.set_device(device);
    proxDeviceDef dd;
    prox_check(proxXrDevice_GetDeviceDef(device, &dd), "proxXrDevice_GetDeviceDef");
    prox_check(proxBody_SetDevice(tool, &dd), "proxBody_SetDevice");
    proxThreadsDef td = proxDefaultThreadsDef();
    prox_check(proxWorld_StartThreads(world, &td), "proxWorld_StartThreads");
    return device;
  }

  double force() const {
    proxWrench w;
    prox_check(proxBody_GetWrench(tool, &w), "proxBody_GetWrench");
    return norm(w.force);
  }
  proxPose tool_pose() const {
    proxPose p;
    prox_check(proxBody_GetPose(tool, &p), "proxBody_GetPose");
    return p;
  }
  // How far the tool is from `expected` (m; the rotation's error as the
  // distance it moves a point at 1 m).
  double error(const Rigid& expected) const {
    const Rigid now = of(tool_pose());
    const double position = glm::length(now.p - expected.p);
    const glm::dquat d = now.q * glm::conjugate(expected.q);
    const double angle = 2.0 * std::atan2(glm::length(glm::dvec3(d.x, d.y, d.z)), std::abs(d.w));
    return std::max(position, angle);
  }

  // Scripts the grip to hold the tool at `target` and pumps the app until
  // the tool is within 1e-6 of where the script puts it (or 10 s pass);
  // returns that pose, for the caller to check error() against.
  Rigid follow_to(XrApp& app, const Rigid& target) const {
    const ProxMockXrKey key{mock_control().now(), to_xr(grip_for(target))};
    mock_control().setScript(&key, 1);
    const Rigid expected = tool_for(key.pose);
    app.pump_until([&] { return error(expected) < 1e-6; }, 10.0);
    return expected;
  }

  // While the runtime's clock runs from t0 to `until`, one app frame at a
  // time: how far the tool is from the straight motion from `start` (at t0)
  // to `end` (at t1), at the middle of each read's runtime time, once a
  // quarter of the motion is under way.
  std::vector<double> motion_errors(XrApp& app, XrTime t0, XrTime t1, XrTime until, const Rigid& start,
                                    const Rigid& end) const {
    std::vector<double> errors;
    while (mock_control().now() < until) {
      app.frame();
      const XrTime before = mock_control().now();
      const glm::dvec3 p = of(tool_pose()).p;
      const XrTime after = mock_control().now();
      const double f = (0.5 * double(before + after) - double(t0)) / double(t1 - t0);
      if (f < 0.25) continue;  // the motion under way for a while
      errors.push_back(glm::length(p - (start.p + (end.p - start.p) * f)));
    }
    return errors;
  }

  proxWorldId world{};
  proxMeshId mesh{};
  proxBodyId rock{}, tool{};
  double width = 0.0;
};

inline proxXrDeviceStats stats_of(proxXrDeviceId device) {
  proxXrDeviceStats s;
  prox_check(proxXrDevice_GetStats(device, &s), "proxXrDevice_GetStats");
  return s;
}

}  // namespace prox::test
