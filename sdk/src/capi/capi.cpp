// The C API over the runtime: validation, ids, errors. No C++ exception
// crosses this file's functions: each body runs inside guard().
#include <proxima/proxima.h>

#include "io/obj.h"
#include "io/poses.h"
#include "runtime/threads.h"
#include "runtime/world.h"
#if PROX_WITH_GLTF
#include "io/gltf.h"
#endif

#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <thread>
#include <vector>

// The public structs' sizes are part of the ABI; the bindings check the same
// numbers.
static_assert(sizeof(proxWorldId) == 8, "ABI");
static_assert(sizeof(proxMeshId) == 16, "ABI");
static_assert(sizeof(proxBodyId) == 16, "ABI");
static_assert(sizeof(proxVec3) == 24, "ABI");
static_assert(sizeof(proxQuat) == 32, "ABI");
static_assert(sizeof(proxPose) == 56, "ABI");
static_assert(sizeof(proxForceSettings) == 40, "ABI");
static_assert(sizeof(proxWorldDef) == 64, "ABI");
static_assert(sizeof(proxMeshDef) == 32, "ABI");
static_assert(sizeof(proxBodyDef) == 112, "ABI");
static_assert(sizeof(proxContact) == 112, "ABI");
static_assert(sizeof(proxWrench) == 56, "ABI");
static_assert(sizeof(proxWorldStats) == 32, "ABI");
static_assert(sizeof(proxPolylineInfo) == 32, "ABI");
static_assert(sizeof(proxMeshInfo) == 68 + 4, "ABI");
static_assert(sizeof(proxDeviceDef) == 32, "ABI");
static_assert(sizeof(proxScriptedDeviceId) == 16, "ABI");
static_assert(sizeof(proxScriptedDeviceDef) == 32, "ABI");
static_assert(sizeof(proxScriptedDeviceRecord) == 104, "ABI");
static_assert(sizeof(proxThreadsDef) == 80, "ABI");
static_assert(sizeof(proxThreadStats) == 88, "ABI");
static_assert(sizeof(proxSafetyStats) == 48, "ABI");
static_assert(sizeof(proxResult) == 4 && sizeof(proxMethod) == 4 && sizeof(proxBodyType) == 4 &&
                  sizeof(proxThread) == 4,
              "ABI");
static_assert(sizeof(proxForcePreset) == 4, "ABI");
static_assert(sizeof(proxMeshStats) == 48, "ABI");
static_assert(sizeof(proxSearchStats) == 88, "ABI");
static_assert(sizeof(proxTrackStats) == 48, "ABI");
static_assert(sizeof(proxIntersectionStats) == 40, "ABI");

namespace {

using namespace prox;

// Marks defs made by the proxDefault*Def functions.
constexpr int32_t kDefCookie = 0x50524F58;  // "PROX"

thread_local std::string g_last_error;

struct Failure {
  proxResult code;
  std::string message;
};

[[noreturn]] void fail(proxResult code, std::string message) { throw Failure{code, std::move(message)}; }

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

// ---- the world registry ---------------------------------------------------------

struct WorldEntry {
  uint32_t generation = 0;
  std::unique_ptr<runtime::World> world;
  std::thread::id owner;
};

std::mutex g_worlds_mutex;  // guards the registry's shape, not the worlds
std::vector<WorldEntry> g_worlds;

runtime::World& world_of(proxWorldId id, const char* what = "world") {
  if (id.index1 == 0) fail(PROX_ERROR_INVALID_HANDLE, std::string(what) + " is a null id");
  std::lock_guard<std::mutex> lock(g_worlds_mutex);
  const uint32_t i = id.index1 - 1;
  if (i >= g_worlds.size() || g_worlds[i].generation != id.generation || !g_worlds[i].world)
    fail(PROX_ERROR_INVALID_HANDLE,
         std::string(what) + " does not name a live world (destroyed, or never created)");
  if (g_worlds[i].owner != std::this_thread::get_id())
    fail(PROX_ERROR_WRONG_THREAD,
         "called from a thread other than the world's game thread (the one that created it)");
  return *g_worlds[i].world;
}

runtime::Handle mesh_of(proxMeshId id, runtime::World*& world) {
  world = &world_of(id.world, "mesh's world");
  if (id.index1 == 0) fail(PROX_ERROR_INVALID_HANDLE, "mesh is a null id");
  const runtime::Handle h{id.index1 - 1, id.generation};
  if (!world->mesh_alive(h)) fail(PROX_ERROR_INVALID_HANDLE, "mesh does not name a live mesh of its world");
  return h;
}

runtime::Handle body_of(proxBodyId id, runtime::World*& world, const char* what = "body") {
  world = &world_of(id.world, "body's world");
  if (id.index1 == 0) fail(PROX_ERROR_INVALID_HANDLE, std::string(what) + " is a null id");
  const runtime::Handle h{id.index1 - 1, id.generation};
  if (!world->body_alive(h))
    fail(PROX_ERROR_INVALID_HANDLE, std::string(what) + " does not name a live body of its world");
  return h;
}

runtime::Handle tool_of(proxBodyId id, runtime::World*& world) {
  const runtime::Handle h = body_of(id, world, "tool");
  if (world->type(h) != runtime::BodyType::Tool)
    fail(PROX_ERROR_INVALID_ARGUMENT, "tool is not a PROX_BODY_TOOL body");
  return h;
}

// Calls that change the scene's shape wait for the threads to stop.
void need_stopped(const runtime::World& w) {
  if (w.running()) fail(PROX_ERROR_BUSY, "the world's threads are running; call proxWorld_StopThreads first");
}

// ---- conversions and checks -------------------------------------------------------

// Every def carries the cookie its proxDefault*Def() set; one that does not
// was filled by hand (and its unset fields would be taken for choices).
template <typename Def>
void need_def(const Def& def, const char* maker) {
  if (def.internalValue != kDefCookie)
    fail(PROX_ERROR_INVALID_ARGUMENT, std::string("def was not initialised with ") + maker + "()");
}

template <typename T>
void need(const T* p, const char* name) {
  if (!p) fail(PROX_ERROR_INVALID_ARGUMENT, std::string(name) + " is NULL");
}

void need_finite(double v, const std::string& name) {
  if (!std::isfinite(v))
    fail(PROX_ERROR_INVALID_ARGUMENT, name + " is not finite (" + std::to_string(v) + ")");
}

void need_positive(double v, const std::string& name) {
  need_finite(v, name);
  if (!(v > 0.0)) fail(PROX_ERROR_INVALID_ARGUMENT, name + " must be > 0 (it is " + std::to_string(v) + ")");
}

Vec3 to_vec(const proxVec3& v, const std::string& name) {
  need_finite(v.x, name + ".x");
  need_finite(v.y, name + ".y");
  need_finite(v.z, name + ".z");
  return {v.x, v.y, v.z};
}

proxVec3 to_c(const Vec3& v) { return {v.x, v.y, v.z}; }

Pose to_pose(const proxPose& p, const std::string& name) {
  const Vec3 t = to_vec(p.position, name + ".position");
  const double q[4] = {p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z};
  for (int i = 0; i < 4; ++i) need_finite(q[i], name + ".rotation");
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(n > 1e-12)) fail(PROX_ERROR_INVALID_ARGUMENT, name + ".rotation is a zero quaternion");
  return Pose::from_quaternion(t, q[0] / n, q[1] / n, q[2] / n, q[3] / n);
}

proxPose to_c(const Pose& p) {
  const glm::dquat q = glm::quat_cast(p.rotation);
  return {to_c(p.translation), {q.w, q.x, q.y, q.z}};
}

proxResult status_code(const Status& s) {
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

void check(const Status& s) {
  if (!s) fail(status_code(s), s.message());
}

ForceSettings to_force(const proxForceSettings& f, double cutoff) {
  if (f.curve != PROX_FORCE_EXPONENTIAL && f.curve != PROX_FORCE_LINEAR)
    fail(PROX_ERROR_INVALID_ARGUMENT, "def->force.curve is not a proxForceCurve");
  need_positive(f.maxForce, "def->force.maxForce");
  need_positive(f.maxTorque, "def->force.maxTorque");
  need_positive(f.decayLength, "def->force.decayLength");
  need_finite(f.safetyDistance, "def->force.safetyDistance");
  if (f.safetyDistance < 0.0 || !(f.safetyDistance < cutoff))
    fail(PROX_ERROR_INVALID_ARGUMENT, "def->force.safetyDistance must be in [0, cutoff)");
  ForceSettings s;
  s.curve = f.curve == PROX_FORCE_LINEAR ? ForceCurve::Linear : ForceCurve::Exponential;
  s.max_force = f.maxForce;
  s.max_torque = f.maxTorque;
  s.safety_distance = f.safetyDistance;
  s.decay_length = f.decayLength;
  s.cutoff = cutoff;
  return s;
}

proxMeshId make_mesh_id(proxWorldId world, runtime::Handle h) { return {h.index + 1, h.generation, world}; }

// `source`: the file the data came from, named in the error when it is not
// a valid mesh.
proxMeshId add_mesh(proxWorldId world_id, runtime::World& world, const MeshInput& input,
                    const std::string& source = "") {
  Status status;
  const runtime::Handle h = world.create_mesh(input, status);
  if (!status && !source.empty()) fail(status_code(status), source + ": " + status.message());
  check(status);
  return make_mesh_id(world_id, h);
}

// A C device behind the runtime's device: converts on the haptic thread
// (no allocation, no lock).
struct DeviceAdapter {
  explicit DeviceAdapter(const proxDeviceDef& d) : def(d) {}
  static bool read(void* user, runtime::DevicePose* out) {
    const auto* self = static_cast<const DeviceAdapter*>(user);
    proxPose p{};
    if (!self->def.readPose(self->def.userData, &p)) return false;
    out->position[0] = p.position.x, out->position[1] = p.position.y, out->position[2] = p.position.z;
    out->rotation[0] = p.rotation.w, out->rotation[1] = p.rotation.x, out->rotation[2] = p.rotation.y,
    out->rotation[3] = p.rotation.z;
    return true;
  }
  static void write(void* user, const runtime::DeviceWrench* w) {
    const auto* self = static_cast<const DeviceAdapter*>(user);
    const proxWrench out{{w->force[0], w->force[1], w->force[2]},
                         {w->torque[0], w->torque[1], w->torque[2]},
                         w->limited ? 1 : 0};
    self->def.writeWrench(self->def.userData, &out);
  }
  proxDeviceDef def;
};

// The scripted device seen through the C device callbacks.
struct ScriptedTrampoline {
  static proxBool read(void* user, proxPose* pose) {
    runtime::DevicePose p{};
    if (!static_cast<runtime::ScriptedDevice*>(user)->read_pose(&p)) return 0;
    *pose = {{p.position[0], p.position[1], p.position[2]},
             {p.rotation[0], p.rotation[1], p.rotation[2], p.rotation[3]}};
    return 1;
  }
  static void write(void* user, const proxWrench* w) {
    static_cast<runtime::ScriptedDevice*>(user)->write_wrench(
        {{w->force.x, w->force.y, w->force.z}, {w->torque.x, w->torque.y, w->torque.z}, w->clipped != 0});
  }
};

proxScriptedDeviceId add_scripted(proxWorldId world, runtime::World& w,
                                  std::vector<runtime::ScriptedPose> poses, double seconds_per_pose,
                                  bool loop) {
  const std::uint32_t i = w.add_scripted_device(
      std::make_unique<runtime::ScriptedDevice>(std::move(poses), seconds_per_pose, loop));
  return {i + 1, 0, world};
}

runtime::ScriptedDevice& scripted_of(proxScriptedDeviceId id) {
  const runtime::World& w = world_of(id.world, "device's world");
  if (id.index1 == 0) fail(PROX_ERROR_INVALID_HANDLE, "device is a null id");
  runtime::ScriptedDevice* d = w.scripted_device(id.index1 - 1);
  if (!d) fail(PROX_ERROR_INVALID_HANDLE, "device does not name a scripted device of its world");
  return *d;
}

}  // namespace

extern "C" {

const char* proxResultString(proxResult result) {
  switch (result) {
    case PROX_SUCCESS:
      return "PROX_SUCCESS";
    case PROX_ERROR_INVALID_ARGUMENT:
      return "PROX_ERROR_INVALID_ARGUMENT";
    case PROX_ERROR_INVALID_HANDLE:
      return "PROX_ERROR_INVALID_HANDLE";
    case PROX_ERROR_INVALID_MESH:
      return "PROX_ERROR_INVALID_MESH";
    case PROX_ERROR_FILE:
      return "PROX_ERROR_FILE";
    case PROX_ERROR_PARSE:
      return "PROX_ERROR_PARSE";
    case PROX_ERROR_UNSUPPORTED:
      return "PROX_ERROR_UNSUPPORTED";
    case PROX_ERROR_VERSION_MISMATCH:
      return "PROX_ERROR_VERSION_MISMATCH";
    case PROX_ERROR_WRONG_THREAD:
      return "PROX_ERROR_WRONG_THREAD";
    case PROX_ERROR_CAPACITY:
      return "PROX_ERROR_CAPACITY";
    case PROX_ERROR_INTERNAL:
      return "PROX_ERROR_INTERNAL";
    case PROX_ERROR_BUSY:
      return "PROX_ERROR_BUSY";
    case PROX_RESULT_FORCE32:
      break;
  }
  return "unknown proxResult";
}

const char* proxGetLastError(void) { return g_last_error.c_str(); }

proxVersion proxGetVersion(void) { return {PROX_VERSION_MAJOR, PROX_VERSION_MINOR, PROX_VERSION_PATCH}; }

proxWorldDef proxDefaultWorldDef(void) {
  const ForceSettings f = hard_force_settings();
  proxWorldDef d{};
  d.apiVersion = PROX_API_VERSION;
  d.method = PROX_METHOD_PRECISE;
  d.cutoff = f.cutoff;
  d.force = {PROX_FORCE_EXPONENTIAL, f.max_force, f.max_torque, f.safety_distance, f.decay_length};
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxCreateWorld(const proxWorldDef* def, proxWorldId* world) {
  return guard("proxCreateWorld", [&] {
    need(def, "def");
    need(world, "world");
    *world = proxWorldId{};
    need_def(*def, "proxDefaultWorldDef");
    if (def->apiVersion != PROX_API_VERSION)
      fail(PROX_ERROR_VERSION_MISMATCH, "def comes from API version " + std::to_string(def->apiVersion) +
                                            ", the library is " + std::to_string(PROX_API_VERSION));
    if (def->method != PROX_METHOD_PRECISE && def->method != PROX_METHOD_ORIGINAL &&
        def->method != PROX_METHOD_REFERENCE)
      fail(PROX_ERROR_INVALID_ARGUMENT, "def->method is not a proxMethod");
    need_positive(def->cutoff, "def->cutoff");
    runtime::WorldSettings s;
    s.method = def->method == PROX_METHOD_ORIGINAL    ? Method::Original
               : def->method == PROX_METHOD_REFERENCE ? Method::Reference
                                                      : Method::Precise;
    s.cutoff = def->cutoff;
    s.force = to_force(def->force, def->cutoff);
    auto w = std::make_unique<runtime::World>(s);
    std::lock_guard<std::mutex> lock(g_worlds_mutex);
    uint32_t i = 0;
    while (i < g_worlds.size() && g_worlds[i].world) ++i;
    if (i == g_worlds.size()) g_worlds.emplace_back();
    g_worlds[i].generation += 1;
    g_worlds[i].world = std::move(w);
    g_worlds[i].owner = std::this_thread::get_id();
    *world = {i + 1, g_worlds[i].generation};
  });
}

proxResult proxDestroyWorld(proxWorldId world) {
  return guard("proxDestroyWorld", [&] {
    world_of(world);  // validates id and thread
    std::unique_ptr<runtime::World> doomed;
    {
      std::lock_guard<std::mutex> lock(g_worlds_mutex);
      doomed = std::move(g_worlds[world.index1 - 1].world);
    }
  });
}

proxBool proxWorld_IsValid(proxWorldId world) {
  if (world.index1 == 0) return 0;
  std::lock_guard<std::mutex> lock(g_worlds_mutex);
  const uint32_t i = world.index1 - 1;
  return i < g_worlds.size() && g_worlds[i].generation == world.generation && g_worlds[i].world ? 1 : 0;
}

proxMeshDef proxDefaultMeshDef(void) {
  proxMeshDef d{};
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateMesh(proxWorldId world, const proxMeshDef* def, proxMeshId* mesh) {
  return guard("proxWorld_CreateMesh", [&] {
    need(mesh, "mesh");
    *mesh = proxMeshId{};
    runtime::World& w = world_of(world);
    need_stopped(w);
    need(def, "def");
    need_def(*def, "proxDefaultMeshDef");
    *mesh = add_mesh(world, w, {def->positions, def->vertexCount, def->indices, def->triangleCount});
  });
}

proxResult proxWorld_LoadMesh(proxWorldId world, const char* path, proxMeshId* mesh) {
  return guard("proxWorld_LoadMesh", [&] {
    need(mesh, "mesh");
    *mesh = proxMeshId{};
    runtime::World& w = world_of(world);
    need_stopped(w);
    need(path, "path");
    std::string p(path);
    std::string ext = p.substr(p.find_last_of('.') == std::string::npos ? p.size() : p.find_last_of('.') + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == "obj") {
      io::ObjData obj;
      check(io::read_obj(p, obj));
      *mesh = add_mesh(world, w,
                       {obj.positions.data(), static_cast<uint32_t>(obj.positions.size() / 3),
                        obj.indices.data(), static_cast<uint32_t>(obj.indices.size() / 3)},
                       p);
      return;
    }
#if PROX_WITH_GLTF
    if (ext == "gltf" || ext == "glb") {
      std::vector<io::GltfMesh> parts;
      check(io::load_gltf(p, io::GltfLoadOptions{}, parts));
      if (parts.empty()) fail(PROX_ERROR_INVALID_MESH, p + ": the scene has no triangles");
      const io::GltfMesh& m = parts.front();
      *mesh = add_mesh(world, w,
                       {m.positions.data(), static_cast<uint32_t>(m.positions.size() / 3), m.indices.data(),
                        static_cast<uint32_t>(m.indices.size() / 3)},
                       p);
      return;
    }
#endif
    fail(PROX_ERROR_UNSUPPORTED,
         p + ": unsupported file type '." + ext + "' (.obj, .gltf and .glb are read)");
  });
}

proxResult proxMesh_Destroy(proxMeshId mesh) {
  return guard("proxMesh_Destroy", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    need_stopped(*w);
    Status s;
    if (!w->destroy_mesh(h, s)) fail(PROX_ERROR_INVALID_ARGUMENT, s.message());
  });
}

proxResult proxMesh_GetInfo(proxMeshId mesh, proxMeshInfo* info) {
  return guard("proxMesh_GetInfo", [&] {
    need(info, "info");
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    const Mesh& m = w->mesh(h);
    const MeshStats& s = m.stats();
    *info = proxMeshInfo{s.triangles,         s.vertices,           s.dropped_triangles, s.boundary_edges,
                         s.nonmanifold_edges, to_c(m.bounds().min), to_c(m.bounds().max)};
  });
}

proxBodyDef proxDefaultBodyDef(void) {
  proxBodyDef d{};
  d.type = PROX_BODY_STATIC;
  d.pose.rotation.w = 1.0;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateBody(proxWorldId world, const proxBodyDef* def, proxBodyId* body) {
  return guard("proxWorld_CreateBody", [&] {
    need(body, "body");
    *body = proxBodyId{};
    runtime::World& w = world_of(world);
    need_stopped(w);
    need(def, "def");
    need_def(*def, "proxDefaultBodyDef");
    runtime::World* mesh_world = nullptr;
    const runtime::Handle mesh = mesh_of(def->mesh, mesh_world);
    if (mesh_world != &w) fail(PROX_ERROR_INVALID_HANDLE, "def->mesh belongs to another world");
    runtime::BodyType type;
    switch (def->type) {
      case PROX_BODY_STATIC:
        type = runtime::BodyType::Static;
        break;
      case PROX_BODY_MOVABLE:
        type = runtime::BodyType::Movable;
        break;
      case PROX_BODY_TOOL:
        type = runtime::BodyType::Tool;
        break;
      default:
        fail(PROX_ERROR_INVALID_ARGUMENT, "def->type is not a proxBodyType");
    }
    const Pose pose = to_pose(def->pose, "def->pose");
    const Vec3 reference = to_vec(def->referencePoint, "def->referencePoint");
    const runtime::Handle h = w.create_body(mesh, type, pose, reference);
    *body = {h.index + 1, h.generation, world};
  });
}

proxResult proxBody_Destroy(proxBodyId body) {
  return guard("proxBody_Destroy", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = body_of(body, w);
    need_stopped(*w);
    w->destroy_body(h);
  });
}

proxResult proxBody_SetPose(proxBodyId body, const proxPose* pose) {
  return guard("proxBody_SetPose", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = body_of(body, w);
    need(pose, "pose");
    const Pose p = to_pose(*pose, "pose");
    if (w->type(h) == runtime::BodyType::Static)
      fail(PROX_ERROR_INVALID_ARGUMENT, "body is static; create it PROX_BODY_MOVABLE to move it");
    if (w->running() && w->device(h).attached())
      fail(PROX_ERROR_BUSY, "body is a tool held by a device while the threads run; the device moves it");
    w->set_pose(h, p);
  });
}

proxResult proxBody_GetPose(proxBodyId body, proxPose* pose) {
  return guard("proxBody_GetPose", [&] {
    need(pose, "pose");
    runtime::World* w = nullptr;
    const runtime::Handle h = body_of(body, w);
    *pose = to_c(w->current_pose(h));
  });
}

proxResult proxWorld_Step(proxWorldId world) {
  return guard("proxWorld_Step", [&] {
    runtime::World& w = world_of(world);
    need_stopped(w);
    w.step();
  });
}

proxResult proxBody_GetContacts(proxBodyId tool, proxContact* contacts, int32_t capacity, int32_t* count) {
  return guard("proxBody_GetContacts", [&] {
    need(count, "count");
    *count = 0;
    if (capacity < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "capacity is negative");
    if (capacity > 0) need(contacts, "contacts");
    runtime::World* w = nullptr;
    const runtime::Handle h = tool_of(tool, w);
    std::vector<runtime::Contact> list;
    w->contacts(h, list);
    *count = static_cast<int32_t>(list.size());
    const std::size_t n = std::min<std::size_t>(list.size(), static_cast<std::size_t>(capacity));
    for (std::size_t i = 0; i < n; ++i) {
      const runtime::Contact& c = list[i];
      const LmdPair& p = c.lmd;
      proxContact& out = contacts[i];
      out.other = {c.other + 1, w->body_generation(c.other), tool.world};
      out.pointTool = to_c(p.point_b);
      out.pointOther = to_c(p.point_a);
      const Vec3 d = p.point_b - p.point_a;
      const double len = glm::length(d);
      out.normal = to_c(len > 0.0 ? d / len : Vec3(0.0));
      out.distance = p.distance;
      out.triangleTool = p.tri_b;
      out.triangleOther = p.tri_a;
      out.featureTool = static_cast<int32_t>(p.feature_b.kind);
      out.featureOther = static_cast<int32_t>(p.feature_a.kind);
    }
    if (n < list.size())
      fail(PROX_ERROR_CAPACITY, "capacity " + std::to_string(capacity) + " is less than the " +
                                    std::to_string(list.size()) + " contacts (*count says how many)");
  });
}

proxResult proxBody_GetWrench(proxBodyId tool, proxWrench* wrench) {
  return guard("proxBody_GetWrench", [&] {
    need(wrench, "wrench");
    runtime::World* w = nullptr;
    const runtime::Handle h = tool_of(tool, w);
    const Wrench x = w->wrench(h);
    *wrench = {to_c(x.force), to_c(x.torque), x.clipped ? 1 : 0};
  });
}

proxResult proxBody_GetIntersections(proxBodyId tool, proxVec3* points, int32_t pointCapacity,
                                     int32_t* pointCount, proxPolylineInfo* lines, int32_t lineCapacity,
                                     int32_t* lineCount) {
  return guard("proxBody_GetIntersections", [&] {
    need(pointCount, "pointCount");
    need(lineCount, "lineCount");
    *pointCount = 0;
    *lineCount = 0;
    if (pointCapacity < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "pointCapacity is negative");
    if (lineCapacity < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "lineCapacity is negative");
    if (pointCapacity > 0) need(points, "points");
    if (lineCapacity > 0) need(lines, "lines");
    runtime::World* w = nullptr;
    const runtime::Handle h = tool_of(tool, w);
    std::vector<std::pair<std::uint32_t, Polyline>> found;
    w->intersections(h, found);
    int32_t point_total = 0;
    for (const auto& entry : found) point_total += static_cast<int32_t>(entry.second.points.size());
    *pointCount = point_total;
    *lineCount = static_cast<int32_t>(found.size());
    int32_t next = 0;
    bool fits = true;
    for (std::size_t i = 0; i < found.size(); ++i) {
      const Polyline& line = found[i].second;
      const auto n = static_cast<int32_t>(line.points.size());
      if (static_cast<int32_t>(i) < lineCapacity)
        lines[i] = {{found[i].first + 1, w->body_generation(found[i].first), tool.world},
                    next,
                    n,
                    line.closed ? 1 : 0,
                    0};
      else
        fits = false;
      for (int32_t k = 0; k < n; ++k) {
        if (next + k < pointCapacity)
          points[next + k] = to_c(line.points[static_cast<std::size_t>(k)]);
        else
          fits = false;
      }
      next += n;
    }
    if (!fits)
      fail(PROX_ERROR_CAPACITY, "the " + std::to_string(*lineCount) + " polylines with " +
                                    std::to_string(*pointCount) + " points do not fit in capacities " +
                                    std::to_string(lineCapacity) + " and " + std::to_string(pointCapacity));
  });
}

proxResult proxWorld_GetStats(proxWorldId world, proxWorldStats* stats) {
  return guard("proxWorld_GetStats", [&] {
    need(stats, "stats");
    const runtime::World& w = world_of(world);
    const runtime::StepStats s = w.stats();
    *stats = {w.body_count(),   w.tool_count(), s.pairs_in_range,
              s.pairs_searched, s.contacts,     static_cast<int32_t>(s.candidates),
              s.seconds};
  });
}

// ---- devices ---------------------------------------------------------------------

proxDeviceDef proxDefaultDeviceDef(void) {
  proxDeviceDef d{};
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxBody_SetDevice(proxBodyId tool, const proxDeviceDef* def) {
  return guard("proxBody_SetDevice", [&] {
    runtime::World* w = nullptr;
    const runtime::Handle h = tool_of(tool, w);
    need_stopped(*w);
    if (!def) {
      w->set_device(h, runtime::Device{});
      return;
    }
    need_def(*def, "proxDefaultDeviceDef");
    if (!def->readPose) fail(PROX_ERROR_INVALID_ARGUMENT, "def->readPose is NULL");
    auto adapter = std::make_shared<DeviceAdapter>(*def);
    runtime::Device d;
    d.read_pose = &DeviceAdapter::read;
    d.write_wrench = def->writeWrench ? &DeviceAdapter::write : nullptr;
    d.user = adapter.get();
    d.owner = adapter;
    w->set_device(h, d);
  });
}

proxScriptedDeviceDef proxDefaultScriptedDeviceDef(void) {
  proxScriptedDeviceDef d{};
  d.secondsPerPose = 0.001;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_CreateScriptedDevice(proxWorldId world, const proxScriptedDeviceDef* def,
                                          proxScriptedDeviceId* device) {
  return guard("proxWorld_CreateScriptedDevice", [&] {
    need(device, "device");
    *device = proxScriptedDeviceId{};
    runtime::World& w = world_of(world);
    need(def, "def");
    need_def(*def, "proxDefaultScriptedDeviceDef");
    if (def->poseCount < 1) fail(PROX_ERROR_INVALID_ARGUMENT, "def->poseCount must be >= 1");
    need(def->poses, "def->poses");
    need_positive(def->secondsPerPose, "def->secondsPerPose");
    std::vector<runtime::ScriptedPose> path(static_cast<std::size_t>(def->poseCount));
    for (int32_t i = 0; i < def->poseCount; ++i)
      path[std::size_t(i)] =
          runtime::ScriptedPose::of(to_pose(def->poses[i], "def->poses[" + std::to_string(i) + "]"));
    *device = add_scripted(world, w, std::move(path), def->secondsPerPose, def->loop != 0);
  });
}

proxResult proxWorld_LoadScriptedDevice(proxWorldId world, const char* path, double secondsPerPose,
                                        proxBool loop, proxScriptedDeviceId* device) {
  return guard("proxWorld_LoadScriptedDevice", [&] {
    need(device, "device");
    *device = proxScriptedDeviceId{};
    runtime::World& w = world_of(world);
    need(path, "path");
    need_positive(secondsPerPose, "secondsPerPose");
    std::vector<io::PoseRecord> records;
    check(io::read_poses(path, records));
    std::vector<runtime::ScriptedPose> poses;
    for (const io::PoseRecord& r : records) {
      runtime::ScriptedPose p;
      p.position = Vec3(r.position[0], r.position[1], r.position[2]);
      for (int k = 0; k < 4; ++k) p.rotation[k] = r.rotation[k];
      poses.push_back(p);
    }
    *device = add_scripted(world, w, std::move(poses), secondsPerPose, loop != 0);
  });
}

proxResult proxScriptedDevice_GetDeviceDef(proxScriptedDeviceId device, proxDeviceDef* def) {
  return guard("proxScriptedDevice_GetDeviceDef", [&] {
    need(def, "def");
    runtime::ScriptedDevice& d = scripted_of(device);
    *def = proxDefaultDeviceDef();
    def->readPose = &ScriptedTrampoline::read;
    def->writeWrench = &ScriptedTrampoline::write;
    def->userData = &d;
  });
}

proxResult proxScriptedDevice_GetRecord(proxScriptedDeviceId device, proxScriptedDeviceRecord* record) {
  return guard("proxScriptedDevice_GetRecord", [&] {
    need(record, "record");
    const runtime::ScriptedRecord r = scripted_of(device).record();
    *record = proxScriptedDeviceRecord{};
    record->reads = r.reads;
    record->writes = r.writes;
    record->progress = r.progress;
    record->maxForce = r.max_force;
    record->maxTorque = r.max_torque;
    record->maxForceStep = r.max_force_step;
    record->lastForce = to_c(r.last_force);
    record->lastTorque = to_c(r.last_torque);
    record->allFinite = r.finite ? 1 : 0;
  });
}

// ---- threads -------------------------------------------------------------------------

proxThreadsDef proxDefaultThreadsDef(void) {
  const runtime::ThreadSettings s;
  proxThreadsDef d{};
  d.hapticRate = s.haptic_rate;
  d.localRate = s.local_rate;
  d.globalRate = s.global_rate;
  d.hapticCore = s.cores[0];
  d.localCore = s.cores[1];
  d.globalCore = s.cores[2];
  d.maxContacts = s.max_contacts;
  d.staleAfter = s.stale_after;
  d.maxForceRate = s.max_force_rate;
  d.maxTorqueRate = s.max_torque_rate;
  d.trustDistance = s.trust_distance;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_StartThreads(proxWorldId world, const proxThreadsDef* def) {
  return guard("proxWorld_StartThreads", [&] {
    runtime::World& w = world_of(world);
    need(def, "def");
    need_def(*def, "proxDefaultThreadsDef");
    if (w.running()) fail(PROX_ERROR_BUSY, "the world's threads are already running");
    runtime::ThreadSettings s;
    s.haptic_rate = def->hapticRate;
    s.local_rate = def->localRate;
    s.global_rate = def->globalRate;
    s.cores[0] = def->hapticCore;
    s.cores[1] = def->localCore;
    s.cores[2] = def->globalCore;
    s.max_contacts = def->maxContacts;
    s.stale_after = def->staleAfter;
    s.max_force_rate = def->maxForceRate;
    s.max_torque_rate = def->maxTorqueRate;
    s.trust_distance = def->trustDistance;
    Status status;
    if (!w.start_threads(s, status)) {
      if (status.code() == StatusCode::InvalidArgument)
        fail(PROX_ERROR_INVALID_ARGUMENT, "def: " + status.message());
      fail(PROX_ERROR_INTERNAL, status.message());
    }
  });
}

proxResult proxWorld_StopThreads(proxWorldId world) {
  return guard("proxWorld_StopThreads", [&] { world_of(world).stop_threads(); });
}

proxResult proxWorld_GetThreadStats(proxWorldId world, proxThread thread, proxThreadStats* stats) {
  return guard("proxWorld_GetThreadStats", [&] {
    need(stats, "stats");
    *stats = proxThreadStats{};
    stats->pinnedCore = -1;
    const runtime::World& w = world_of(world);
    if (thread != PROX_THREAD_HAPTIC && thread != PROX_THREAD_LOCAL && thread != PROX_THREAD_GLOBAL)
      fail(PROX_ERROR_INVALID_ARGUMENT, "thread is not a proxThread");
    const runtime::Threads* t = w.threads();
    if (!t) return;  // never started: all zero
    const auto role = static_cast<runtime::Role>(thread);
    const runtime::LoopSummary s = t->loop_summary(role);
    stats->running = w.running() ? 1 : 0;
    stats->pinnedCore = t->pinned_core(role);
    stats->targetRate = s.target_rate;
    stats->achievedRate = s.achieved_rate;
    stats->periodP50 = s.period_p50;
    stats->periodP99 = s.period_p99;
    stats->periodMax = s.period_max;
    stats->updateP50 = s.update_p50;
    stats->updateP99 = s.update_p99;
    stats->updateMax = s.update_max;
    stats->updates = s.updates;
    stats->overruns = s.overruns;
  });
}

proxResult proxWorld_GetSafetyStats(proxWorldId world, proxSafetyStats* stats) {
  return guard("proxWorld_GetSafetyStats", [&] {
    need(stats, "stats");
    *stats = proxSafetyStats{};
    const runtime::World& w = world_of(world);
    if (!w.threads()) return;
    const runtime::HapticCounters c = w.threads()->haptic_counters();
    *stats = {c.invalid_poses, c.stale_ticks,    c.untrusted_ticks,
              c.limited_ticks, c.torn_snapshots, c.dropped_contacts};
  });
}

// ---- inspection --------------------------------------------------------------------

proxResult proxGetForcePreset(proxForcePreset preset, proxForceSettings* force, double* cutoff) {
  return guard("proxGetForcePreset", [&] {
    need(force, "force");
    need(cutoff, "cutoff");
    ForceSettings f;
    switch (preset) {
      case PROX_FORCE_PRESET_HARD:
        f = hard_force_settings();
        break;
      case PROX_FORCE_PRESET_SOFT:
        f = soft_force_settings();
        break;
      default:
        fail(PROX_ERROR_INVALID_ARGUMENT, "preset is not a proxForcePreset");
    }
    *force = {f.curve == ForceCurve::Linear ? PROX_FORCE_LINEAR : PROX_FORCE_EXPONENTIAL, f.max_force,
              f.max_torque, f.safety_distance, f.decay_length};
    *cutoff = f.cutoff;
  });
}

proxResult proxMesh_GetStats(proxMeshId mesh, proxMeshStats* stats) {
  return guard("proxMesh_GetStats", [&] {
    need(stats, "stats");
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    const MeshStats& m = w->mesh(h).stats();
    const SnchStats& t = w->snch(h).stats();
    *stats = proxMeshStats{};
    stats->inputVertices = m.input_vertices;
    stats->inputTriangles = m.input_triangles;
    stats->zeroAreaTriangles = m.zero_area_triangles;
    stats->hierarchyNodes = t.nodes;
    stats->hierarchyLeaves = t.leaves;
    stats->hierarchyDepth = t.depth;
    stats->unboundedLeafCones = t.unbounded_leaves;
    stats->hierarchyBytes = t.memory_bytes;
    stats->hierarchySeconds = t.build_seconds;
  });
}

proxResult proxWorld_GetSearchStats(proxWorldId world, proxSearchStats* stats) {
  return guard("proxWorld_GetSearchStats", [&] {
    need(stats, "stats");
    const runtime::StepStats s = world_of(world).stats();
    *stats = proxSearchStats{};
    stats->pairsSearched = s.pairs_searched;
    stats->nodePairs = s.search.node_pairs;
    stats->leafPairs = s.search.leaf_pairs;
    stats->planeRejections = s.search.plane_rejections;
    stats->visibilityRejections = s.search.visibility_rejections;
    stats->normalRejections = s.search.normal_rejections;
    stats->distanceEvaluations = s.search.distance_evaluations;
    stats->candidates = static_cast<uint64_t>(s.candidates);
    stats->reductionCacheHits = s.reduction_cache_hits;
    stats->globalSeconds = s.search.seconds;
    stats->reductionSeconds = s.reduction_seconds;
  });
}

proxResult proxWorld_Track(proxWorldId world) {
  return guard("proxWorld_Track", [&] {
    runtime::World& w = world_of(world);
    need_stopped(w);
    w.track();
  });
}

proxResult proxWorld_GetTrackStats(proxWorldId world, proxTrackStats* stats) {
  return guard("proxWorld_GetTrackStats", [&] {
    need(stats, "stats");
    const runtime::TrackStats& s = world_of(world).track_stats();
    *stats = proxTrackStats{};
    stats->pairsTracked = s.pairs;
    stats->contactsIn = static_cast<int32_t>(s.local.pairs_in);
    stats->contactsOut = static_cast<int32_t>(s.local.pairs_out);
    stats->distanceEvaluations = s.local.distance_evaluations;
    stats->cacheHits = s.local.cache_hits;
    stats->moves = s.local.steps;
    stats->seconds = s.seconds;
  });
}

proxResult proxBody_GetIntersectionStats(proxBodyId tool, proxIntersectionStats* stats) {
  return guard("proxBody_GetIntersectionStats", [&] {
    need(stats, "stats");
    runtime::World* w = nullptr;
    const runtime::Handle h = tool_of(tool, w);
    const PolylineStats& s = w->intersection_stats(h);
    *stats = {s.triangle_pairs, s.intersecting_pairs, s.coplanar_pairs, s.segments, s.seconds};
  });
}

proxResult proxBody_GetDistance(proxBodyId a, proxBodyId b, double maxDistance, double* distance) {
  return guard("proxBody_GetDistance", [&] {
    need(distance, "distance");
    *distance = -1.0;
    runtime::World* wa = nullptr;
    runtime::World* wb = nullptr;
    const runtime::Handle ha = body_of(a, wa, "a");
    const runtime::Handle hb = body_of(b, wb, "b");
    if (wa != wb) fail(PROX_ERROR_INVALID_HANDLE, "a and b belong to different worlds");
    if (ha.index == hb.index) fail(PROX_ERROR_INVALID_ARGUMENT, "a and b are the same body");
    if (std::isnan(maxDistance) || maxDistance < 0.0)
      fail(PROX_ERROR_INVALID_ARGUMENT,
           "maxDistance must be >= 0 (INFINITY for no bound; it is " + std::to_string(maxDistance) + ")");
    const double d = wa->distance(ha, hb, maxDistance);
    // The search may end on a pair beyond the bound: that is "farther" too.
    *distance = d <= maxDistance ? d : -1.0;
  });
}

}  // extern "C"
