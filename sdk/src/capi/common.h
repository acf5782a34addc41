// What every file of the C API shares: errors (guard() turns any C++
// failure into a proxResult and the thread's last error), the world
// registry and the id lookups, and the checks and conversions of C values.
// Private to sdk/src/capi.
#pragma once

#include <proxima/proxima.h>

#include "common/quaternion.h"
#include "runtime/world.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <utility>
#include <thread>
#include <vector>

namespace prox::capi {

// Marks defs made by the proxDefault*Def functions.
inline constexpr int32_t kDefCookie = 0x50524F58;  // "PROX"

// The calling thread's last error message (proxGetLastError).
extern thread_local std::string g_last_error;

struct Failure {
  proxResult code;
  std::string message;
};

[[noreturn]] inline void fail(proxResult code, std::string message) {
  throw Failure{code, std::move(message)};
}

template <typename F>
proxResult guard(const char* function, F&& body) {
  try {
    body();
    g_last_error.clear();
    return PROX_SUCCESS;
  } catch (const Failure& f) {
    g_last_error = std::string(function) + ": " + f.message;
    return f.code;
  } catch (const std::bad_alloc&) {
    g_last_error = std::string(function) + ": out of memory";
    return PROX_ERROR_INTERNAL;
  } catch (const std::exception& e) {
    g_last_error = std::string(function) + ": internal error: " + e.what();
    return PROX_ERROR_INTERNAL;
  } catch (...) {
    g_last_error = std::string(function) + ": internal error";
    return PROX_ERROR_INTERNAL;
  }
}

struct WorldEntry {
  uint32_t generation = 0;
  std::unique_ptr<runtime::World> world;
  std::thread::id owner;
};

extern std::mutex g_worlds_mutex;  // guards the registry's shape, not the worlds
extern std::vector<WorldEntry> g_worlds;

// The live world an id names, called from its game thread (else fails).
runtime::World& world_of(proxWorldId id, const char* what = "world");

inline runtime::Handle mesh_of(proxMeshId id, runtime::World*& world) {
  world = &world_of(id.world, "mesh's world");
  if (id.index1 == 0) fail(PROX_ERROR_INVALID_HANDLE, "mesh is a null id");
  const runtime::Handle h{id.index1 - 1, id.generation};
  if (!world->mesh_alive(h)) fail(PROX_ERROR_INVALID_HANDLE, "mesh does not name a live mesh of its world");
  return h;
}

inline runtime::Handle body_of(proxBodyId id, runtime::World*& world, const char* what = "body") {
  world = &world_of(id.world, "body's world");
  if (id.index1 == 0) fail(PROX_ERROR_INVALID_HANDLE, std::string(what) + " is a null id");
  const runtime::Handle h{id.index1 - 1, id.generation};
  if (!world->body_alive(h))
    fail(PROX_ERROR_INVALID_HANDLE, std::string(what) + " does not name a live body of its world");
  return h;
}

inline runtime::Handle tool_of(proxBodyId id, runtime::World*& world) {
  const runtime::Handle h = body_of(id, world, "tool");
  if (world->type(h) != runtime::BodyType::Tool)
    fail(PROX_ERROR_INVALID_ARGUMENT, "tool is not a PROX_BODY_TOOL body");
  return h;
}

// An IsValid function: whether `check` (which fails for an id that is not
// valid) passes. It sets the last error as any call does, so that a false
// answer says why.
template <typename F>
proxBool valid(const char* function, F&& check) {
  return guard(function, std::forward<F>(check)) == PROX_SUCCESS ? 1 : 0;
}

// Calls that change the scene's shape wait for the threads to stop.
inline void need_stopped(const runtime::World& w) {
  if (w.running()) fail(PROX_ERROR_BUSY, "the world's threads are running; call proxWorld_StopThreads first");
}

// The oldest minor version of this major one whose defs are laid out as
// this library's (0.4 grew the device and thread defs and gave every def
// its apiVersion).
constexpr int32_t kOldestCompatibleMinor = 4;
// Fails with PROX_ERROR_VERSION_MISMATCH unless apiVersion is one this
// library takes; the message names the def's maker.
void need_api_version(int32_t apiVersion, const char* maker);

// Every def carries the cookie its proxDefault*Def() set; one that does not
// was filled by hand (and its unset fields would be taken for choices). And
// the API version it was made for (Steam Audio's rule): a program built
// against an older minor version of the same major one runs on this library
// (what it knows is still here, in its place), back to the oldest whose defs
// are laid out as this one's; a newer minor or another major does not.
template <typename Def>
inline void need_def(const Def& def, const char* maker) {
  if (def.internalValue != kDefCookie)
    fail(PROX_ERROR_INVALID_ARGUMENT, std::string("def was not initialised with ") + maker + "()");
  need_api_version(def.apiVersion, maker);
}

template <typename T>
inline void need(const T* p, const char* name) {
  if (!p) fail(PROX_ERROR_INVALID_ARGUMENT, std::string(name) + " is NULL");
}

// The largest coordinate magnitude a mesh vertex or a pose translation may
// have at the C API. The mesh layer builds normals at any scale, but
// distances and the exact predicates multiply several coordinate differences
// together, and past about 1e77 those products overflow to infinity. 1e50
// leaves room for poses on top and is far beyond any real scene.
constexpr double kMaxCoordinate = 1e50;

// An enum field or argument as the int32 the caller stored. A C caller or a
// binding may store any value; reading one outside the C++ enum's range
// through the enum type is undefined behaviour, so validation reads the bits.
template <typename E>
inline int32_t enum_value(const E& e) {
  static_assert(sizeof(E) == sizeof(int32_t), "public enums are 32 bits");
  int32_t v;
  std::memcpy(&v, &e, sizeof v);
  return v;
}

inline void need_finite(double v, const std::string& name) {
  if (!std::isfinite(v))
    fail(PROX_ERROR_INVALID_ARGUMENT, name + " is not finite (" + std::to_string(v) + ")");
}

inline void need_positive(double v, const std::string& name) {
  need_finite(v, name);
  if (!(v > 0.0)) fail(PROX_ERROR_INVALID_ARGUMENT, name + " must be > 0 (it is " + std::to_string(v) + ")");
}

inline void need_non_negative(double v, const std::string& name) {
  need_finite(v, name);
  if (!(v >= 0.0))
    fail(PROX_ERROR_INVALID_ARGUMENT, name + " must be >= 0 (it is " + std::to_string(v) + ")");
}

inline Vec3 to_vec(const proxVec3& v, const std::string& name) {
  need_finite(v.x, name + ".x");
  need_finite(v.y, name + ".y");
  need_finite(v.z, name + ".z");
  return {v.x, v.y, v.z};
}

inline proxVec3 to_c(const Vec3& v) { return {v.x, v.y, v.z}; }

// A wrench that came through the C callbacks: no distance is known.
inline runtime::DeviceWrench device_wrench_of(const proxWrench& w) {
  return {{w.force.x, w.force.y, w.force.z},
          {w.torque.x, w.torque.y, w.torque.z},
          w.clipped != 0,
          runtime::kUnknownDistance,
          0.0,
          0.0};
}

inline Pose to_pose(const proxPose& p, const std::string& name) {
  const Vec3 t = to_vec(p.position, name + ".position");
  for (const double x : {t.x, t.y, t.z})
    if (std::abs(x) > kMaxCoordinate) {
      char value[32];
      std::snprintf(value, sizeof value, "%g", x);
      fail(PROX_ERROR_INVALID_ARGUMENT,
           name + ".position has a coordinate of " + value + ", beyond the +-1e50 Proxima supports");
    }
  double q[4] = {p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z};
  for (int i = 0; i < 4; ++i) need_finite(q[i], name + ".rotation");
  if (!normalize_quaternion(q)) fail(PROX_ERROR_INVALID_ARGUMENT, name + ".rotation is a zero quaternion");
  return Pose::from_quaternion(t, q[0], q[1], q[2], q[3]);
}

inline proxPose to_c(const Pose& p) {
  const glm::dquat q = glm::quat_cast(p.rotation);
  return {to_c(p.translation), {q.w, q.x, q.y, q.z}};
}

inline proxResult status_code(const Status& s) {
  switch (s.code()) {
    case StatusCode::Ok:
      return PROX_SUCCESS;
    case StatusCode::InvalidArgument:
      return PROX_ERROR_INVALID_MESH;
    case StatusCode::ParseError:
      return PROX_ERROR_PARSE;
    case StatusCode::IoError:
      return PROX_ERROR_FILE;
    case StatusCode::Unsupported:
      return PROX_ERROR_UNSUPPORTED;
  }
  return PROX_ERROR_INTERNAL;
}

inline void check(const Status& s) {
  if (!s) fail(status_code(s), s.message());
}

inline ForceSettings to_force(const proxForceSettings& f, double cutoff) {
  if (enum_value(f.curve) != PROX_FORCE_EXPONENTIAL && enum_value(f.curve) != PROX_FORCE_LINEAR)
    fail(PROX_ERROR_INVALID_ARGUMENT, "def->force.curve is not a proxForceCurve");
  need_positive(f.maxForce, "def->force.maxForce");
  need_positive(f.maxTorque, "def->force.maxTorque");
  need_positive(f.decayLength, "def->force.decayLength");
  need_finite(f.safetyDistance, "def->force.safetyDistance");
  if (f.safetyDistance < 0.0 || !(f.safetyDistance < cutoff))
    fail(PROX_ERROR_INVALID_ARGUMENT, "def->force.safetyDistance must be in [0, cutoff)");
  ForceSettings s;
  s.curve = enum_value(f.curve) == PROX_FORCE_LINEAR ? ForceCurve::Linear : ForceCurve::Exponential;
  s.max_force = f.maxForce;
  s.max_torque = f.maxTorque;
  s.safety_distance = f.safetyDistance;
  s.decay_length = f.decayLength;
  s.cutoff = cutoff;
  return s;
}

}  // namespace prox::capi
