// A C API call sequence on fuzzed ids and arguments: worlds, meshes, bodies
// and tools created and destroyed, poses set, steps and tracking, contacts,
// wrenches and statistics read, the threads started and stopped, a streamed
// device attached, pushed to and read. Ids are taken from what was created
// (live or destroyed) or made from raw bytes. Nothing may crash or leak, and
// every failure must be named.
#include "check.h"
#include "fuzz_input.h"

#include <proxima/proxima.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace {

using prox::fuzz::Input;
using prox::fuzz::set_enum;

void named(proxResult r, const char* call) {
  PROX_FUZZ_CHECK(r <= 0, "%s returned %d", call, r);
  if (r != PROX_SUCCESS)
    PROX_FUZZ_CHECK(proxGetLastError()[0] != '\0', "%s failed (%s) without a message", call,
                    proxResultString(r));
}
#define CALL(expr) named((expr), #expr)

// An id from the list (live or stale), or from raw bytes.
template <typename Id>
Id pick(Input& in, const std::vector<Id>& ids) {
  const std::uint8_t how = in.u8();
  if (how % 8 == 0 || ids.empty()) {
    Id id;
    std::uint8_t raw[sizeof(Id)];
    for (auto& b : raw) b = in.u8() % 4 == 0 ? in.u8() : 0;
    std::memcpy(&id, raw, sizeof id);
    return id;
  }
  return ids[how % ids.size()];
}

proxPose pose(Input& in) {
  proxPose p{};
  const std::uint8_t how = in.u8();
  if (how % 4 == 0) {  // anything, NaN and zero quaternions included
    p.position = {in.number(), in.number(), in.number()};
    p.rotation = {in.number(), in.number(), in.number(), in.number()};
  } else {  // near the origin, a valid rotation
    p.position = {in.i32() % 200 * 1e-3, in.i32() % 200 * 1e-3, in.i32() % 200 * 1e-3};
    p.rotation = {1.0 + in.u8() / 64.0, in.u8() / 128.0, 0.0, in.u8() / 256.0};
  }
  return p;
}

// A unit tetrahedron scaled by s, and a quad: small, so each step is quick.
proxResult make_mesh(Input& in, proxWorldId world, proxMeshId* mesh) {
  const double s = in.u8() % 8 == 0 ? in.number() : 0.05 * (1 + in.u8() % 8);
  const double positions[] = {0, 0, 0, s, 0, 0, 0, s, 0, 0, 0, s};
  const std::uint32_t tetra[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  proxMeshDef def = proxDefaultMeshDef();
  def.positions = positions;
  def.vertexCount = 4;
  def.indices = tetra;
  def.triangleCount = 4;
  const std::uint8_t bad = in.u8();
  if (bad % 16 == 1) def.triangleCount = in.below(5);  // at most what the array holds
  if (bad % 16 == 2) def.internalValue = in.i32();
  return proxWorld_CreateMesh(world, bad % 16 == 3 ? nullptr : &def, mesh);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  std::vector<proxWorldId> worlds;
  std::vector<proxMeshId> meshes;
  std::vector<proxBodyId> bodies;
  std::vector<proxStreamDeviceId> streams;
  int thread_starts = 0;  // starting threads costs milliseconds: a few per input

  for (int op = 0; op < 64 && !in.empty(); ++op) {
    switch (in.u8() % 20) {
      case 0: {
        if (worlds.size() >= 3) break;
        proxWorldDef def = proxDefaultWorldDef();
        const std::uint8_t how = in.u8();
        if (how & 1) def.cutoff = in.number();
        if (how & 2) set_enum(def.method, in.i32());
        if (how & 4) def.force.safetyDistance = in.number();
        if (how & 8) def.force.maxForce = in.number();
        if (how & 16) def.apiVersion = in.i32();
        if (how & 32) set_enum(def.force.curve, in.i32());
        proxWorldId world;
        const proxResult r = proxCreateWorld((how & 64) ? nullptr : &def, &world);
        named(r, "proxCreateWorld");
        if (r == PROX_SUCCESS) worlds.push_back(world);
        break;
      }
      case 1:
        CALL(proxWorld_Destroy(pick(in, worlds)));
        break;
      case 2: {
        proxMeshId mesh;
        const proxResult r = make_mesh(in, pick(in, worlds), &mesh);
        named(r, "proxWorld_CreateMesh");
        if (r == PROX_SUCCESS) meshes.push_back(mesh);
        break;
      }
      case 3:
        CALL(proxMesh_Destroy(pick(in, meshes)));
        break;
      case 4: {
        proxBodyDef def = proxDefaultBodyDef();
        def.mesh = pick(in, meshes);
        set_enum(def.type, in.u8() % 4);
        def.pose = pose(in);
        proxBodyId body;
        const proxWorldId world = in.u8() % 4 == 0 ? pick(in, worlds) : def.mesh.world;
        const proxResult r = proxWorld_CreateBody(world, &def, &body);
        named(r, "proxWorld_CreateBody");
        if (r == PROX_SUCCESS) bodies.push_back(body);
        break;
      }
      case 5:
        CALL(proxBody_Destroy(pick(in, bodies)));
        break;
      case 6: {
        const proxPose p = pose(in);
        CALL(proxBody_SetPose(pick(in, bodies), &p));
        break;
      }
      case 7:
        CALL(proxWorld_Step(pick(in, worlds)));
        break;
      case 8:
        CALL(proxWorld_Track(pick(in, worlds)));
        break;
      case 9: {
        proxContact contacts[8];
        proxContactPatch patches[8];
        int32_t count = -1;
        const int32_t capacity = in.u8() % 4 == 0 ? in.i32() : in.u8() % 9;
        const bool fits = capacity >= 0 && capacity <= 8;
        // The contacts alone, or with their patches (either array may be left out).
        const std::uint8_t how = in.u8() % 4;
        proxContact* c = fits && how != 2 ? contacts : nullptr;
        proxContactPatch* p = fits && how >= 2 ? patches : nullptr;
        const proxResult r = how == 0 ? proxBody_GetContacts(pick(in, bodies), c, capacity, &count)
                                      : proxBody_GetContactPatches(pick(in, bodies), c, p, capacity, &count);
        named(r, how == 0 ? "proxBody_GetContacts" : "proxBody_GetContactPatches");
        if (r == PROX_SUCCESS || r == PROX_ERROR_CAPACITY)
          for (int32_t i = 0; i < (count < capacity ? count : capacity); ++i) {
            if (c) PROX_FUZZ_CHECK(std::isfinite(c[i].distance), "contact distance %g", c[i].distance);
            if (p)
              PROX_FUZZ_CHECK(p[i].count >= 1 && std::isfinite(p[i].extent) && std::isfinite(p[i].angle),
                              "patch of %d, extent %g", p[i].count, p[i].extent);
          }
        break;
      }
      case 10: {
        proxWrench w;
        const proxResult r = proxBody_GetWrench(pick(in, bodies), &w);
        named(r, "proxBody_GetWrench");
        if (r == PROX_SUCCESS)
          PROX_FUZZ_CHECK(std::isfinite(w.force.x) && std::isfinite(w.torque.z), "non-finite wrench");
        break;
      }
      case 11: {
        double distance;
        const double max = in.u8() % 2 ? HUGE_VAL : in.number();
        CALL(proxBody_GetDistance(pick(in, bodies), pick(in, bodies), max, &distance));
        break;
      }
      case 12: {
        if (thread_starts >= 2) break;
        proxThreadsDef def = proxDefaultThreadsDef();
        def.hapticCore = def.localCore = def.globalCore = -1;
        def.hapticTiming = PROX_TIMING_SLEEP;  // no spinning, no real-time priority, no mlockall
        const std::uint8_t how = in.u8();
        if (how & 1) def.maxContacts = in.i32();
        if (how & 2) def.staleAfter = in.number();
        if (how & 4) def.hapticRate = in.number();
        if (how & 8) def.trustDistance = in.number();
        if (how & 16) def.maxForceRate = in.number();
        const proxResult r = proxWorld_StartThreads(pick(in, worlds), &def);
        named(r, "proxWorld_StartThreads");
        if (r == PROX_SUCCESS) ++thread_starts;
        break;
      }
      case 13:
        CALL(proxWorld_StopThreads(pick(in, worlds)));
        break;
      case 14: {
        proxStreamDeviceDef def = proxDefaultStreamDeviceDef();
        const std::uint8_t how = in.u8();
        if (how & 1) set_enum(def.mode, in.i32());
        if (how & 2) def.delay = in.number();
        if (how & 4) def.staleAfter = in.number();
        if (how & 8) def.maxExtrapolation = in.number();
        proxStreamDeviceId device;
        const proxResult r = proxWorld_CreateStreamDevice(pick(in, worlds), &def, &device);
        named(r, "proxWorld_CreateStreamDevice");
        if (r == PROX_SUCCESS) streams.push_back(device);
        break;
      }
      case 15: {
        proxDeviceDef def;
        const proxResult r = proxStreamDevice_GetDeviceDef(pick(in, streams), &def);
        named(r, "proxStreamDevice_GetDeviceDef");
        const bool detach = in.u8() % 4 == 0;
        if (r == PROX_SUCCESS || detach) CALL(proxBody_SetDevice(pick(in, bodies), detach ? nullptr : &def));
        break;
      }
      case 16: {
        const proxPose p = pose(in);
        const double t = in.u8() % 4 == 0 ? in.number() : proxGetTime() + in.u8() * 1e-3;
        CALL(proxStreamDevice_PushPose(pick(in, streams), &p, t));
        break;
      }
      case 17: {
        proxWrench w;
        proxStreamDeviceStats stats;
        const proxStreamDeviceId device = pick(in, streams);
        CALL(proxStreamDevice_GetWrench(device, &w));
        CALL(proxStreamDevice_GetStats(device, &stats));
        break;
      }
      case 18: {
        const proxWorldId world = pick(in, worlds);
        proxWorldStats stats;
        proxSearchStats search;
        proxTrackStats track;
        proxSafetyStats safety;
        proxThreadStats thread;
        CALL(proxWorld_GetStats(world, &stats));
        CALL(proxWorld_GetSearchStats(world, &search));
        CALL(proxWorld_GetTrackStats(world, &track));
        CALL(proxWorld_GetSafetyStats(world, &safety));
        CALL(proxWorld_GetThreadStats(world, static_cast<proxThread>(in.u8() % 5), &thread));
        proxPatchStats patch_stats;
        CALL(proxWorld_GetPatchStats(world, &patch_stats));
        // Any patch rule, in or out of range: refused by name or taken.
        proxPatchSettings rule{in.number(), in.number(), in.number()};
        CALL(proxWorld_SetPatchSettings(world, &rule));
        CALL(proxWorld_GetPatchSettings(world, &rule));
        // Any leaf budget: a small one makes the steps that follow cut.
        uint64_t budget = in.u8() % 2 ? in.u8() : static_cast<uint64_t>(in.u32()) << 16;
        CALL(proxWorld_SetLeafBudget(world, budget));
        CALL(proxWorld_GetLeafBudget(world, &budget));
        break;
      }
      default: {
        const proxMeshId mesh = pick(in, meshes);
        proxMeshInfo info;
        proxMeshStats stats;
        CALL(proxMesh_GetInfo(mesh, &info));
        CALL(proxMesh_GetStats(mesh, &stats));
        proxPose p;
        CALL(proxBody_GetPose(pick(in, bodies), &p));
        break;
      }
    }
  }
  // Destroying a world stops its threads and frees everything in it.
  for (const proxWorldId world : worlds)
    if (proxWorld_IsValid(world))
      PROX_FUZZ_CHECK(proxWorld_Destroy(world) == PROX_SUCCESS, "%s", proxGetLastError());
  return 0;
}
