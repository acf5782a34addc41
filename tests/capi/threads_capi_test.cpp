// The C API's threads and devices, as a customer uses them: misuse of every
// function, and a run end to end with real threads and C callbacks.
#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "expect.h"
#include "sheets.h"
#include "two_cubes.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace {

using capi_test::at;
using capi_test::length;
using capi_test::wait_until;

// Two 10 cm cubes, the tool 3 cm from the wall: beyond the cutoff.
class Threads : public capi_test::TwoCubes {
 protected:
  void SetUp() override { ASSERT_NO_FATAL_FAILURE(create_scene(0.13)); }
};

TEST_F(Threads, ScriptedDevicesAreValidated) {
  proxScriptedDeviceId id{};
  proxScriptedDeviceDef def = proxDefaultScriptedDeviceDef();
  const proxPose poses[2] = {at(0.13), at(0.105)};
  EXPECT_FAILS(proxWorld_CreateScriptedDevice(world, nullptr, &id), PROX_ERROR_INVALID_ARGUMENT, "def");
  EXPECT_FAILS(proxWorld_CreateScriptedDevice(world, &def, nullptr), PROX_ERROR_INVALID_ARGUMENT, "device");
  proxScriptedDeviceDef raw{};
  EXPECT_FAILS(proxWorld_CreateScriptedDevice(world, &raw, &id), PROX_ERROR_INVALID_ARGUMENT,
               "proxDefaultScriptedDeviceDef");
  EXPECT_FAILS(proxWorld_CreateScriptedDevice(world, &def, &id), PROX_ERROR_INVALID_ARGUMENT, "poseCount");
  def.poseCount = 2;
  EXPECT_FAILS(proxWorld_CreateScriptedDevice(world, &def, &id), PROX_ERROR_INVALID_ARGUMENT, "def->poses");
  def.poses = poses;
  def.secondsPerPose = 0.0;
  EXPECT_FAILS(proxWorld_CreateScriptedDevice(world, &def, &id), PROX_ERROR_INVALID_ARGUMENT,
               "secondsPerPose");
  def.secondsPerPose = 0.1;
  proxPose bad[2] = {at(0.13), at(NAN)};
  def.poses = bad;
  EXPECT_FAILS(proxWorld_CreateScriptedDevice(world, &def, &id), PROX_ERROR_INVALID_ARGUMENT,
               "def->poses[1]");
  bad[1] = {{0, 0, 0}, {0, 0, 0, 0}};
  EXPECT_FAILS(proxWorld_CreateScriptedDevice(world, &def, &id), PROX_ERROR_INVALID_ARGUMENT,
               "zero quaternion");
  def.poses = poses;
  EXPECT_OK(proxWorld_CreateScriptedDevice(world, &def, &id));

  proxDeviceDef device{};
  EXPECT_OK(proxScriptedDevice_GetDeviceDef(id, &device));
  EXPECT_NE(device.readPose, nullptr);
  EXPECT_FAILS(proxScriptedDevice_GetDeviceDef(id, nullptr), PROX_ERROR_INVALID_ARGUMENT, "def");
  proxScriptedDeviceId missing = id;
  missing.index1 = 99;
  EXPECT_FAILS(proxScriptedDevice_GetDeviceDef(missing, &device), PROX_ERROR_INVALID_HANDLE,
               "scripted device");
  EXPECT_FAILS(proxScriptedDevice_GetDeviceDef(proxScriptedDeviceId{}, &device), PROX_ERROR_INVALID_HANDLE,
               "world");
  proxScriptedDeviceRecord record{};
  EXPECT_OK(proxScriptedDevice_GetRecord(id, &record));
  EXPECT_EQ(record.reads, 0u);
  EXPECT_TRUE(record.allFinite);
  EXPECT_FAILS(proxScriptedDevice_GetRecord(id, nullptr), PROX_ERROR_INVALID_ARGUMENT, "record");

  // From a file, with its problems named.
  EXPECT_FAILS(proxWorld_LoadScriptedDevice(world, "no/such/poses.txt", 0.1, 0, &id), PROX_ERROR_FILE,
               "no/such/poses.txt");
  const std::string path = ::testing::TempDir() + "proxima_poses.txt";
  {
    std::ofstream f(path);
    f << "# a path\n0.13 0 0 1 0 0 0\n0.105 0 0 1 0 0\n";
  }
  EXPECT_FAILS(proxWorld_LoadScriptedDevice(world, path.c_str(), 0.1, 0, &id), PROX_ERROR_PARSE, ":3");
  {
    std::ofstream f(path);
    f << "# a path\n0.13 0 0 1 0 0 0\n0.105 0 0 1 0 0 0\n";
  }
  EXPECT_FAILS(proxWorld_LoadScriptedDevice(world, path.c_str(), -1.0, 0, &id), PROX_ERROR_INVALID_ARGUMENT,
               "secondsPerPose");
  EXPECT_FAILS(proxWorld_LoadScriptedDevice(world, nullptr, 0.1, 0, &id), PROX_ERROR_INVALID_ARGUMENT,
               "path");
  EXPECT_OK(proxWorld_LoadScriptedDevice(world, path.c_str(), 0.1, 0, &id));
  std::remove(path.c_str());
}

TEST_F(Threads, DevicesAttachOnlyToToolsAndChangeWhileTheThreadsRun) {
  proxDeviceDef def = proxDefaultDeviceDef();
  EXPECT_FAILS(proxBody_SetDevice(tool, &def), PROX_ERROR_INVALID_ARGUMENT, "readPose");
  def.readPose = [](void*, proxPose* pose) -> proxBool {
    *pose = at(0.13);
    return 1;
  };
  EXPECT_FAILS(proxBody_SetDevice(wall, &def), PROX_ERROR_INVALID_ARGUMENT, "PROX_BODY_TOOL");
  proxDeviceDef raw{};
  raw.readPose = def.readPose;
  EXPECT_FAILS(proxBody_SetDevice(tool, &raw), PROX_ERROR_INVALID_ARGUMENT, "proxDefaultDeviceDef");
  EXPECT_FAILS(proxBody_SetDevice(proxBodyId{}, &def), PROX_ERROR_INVALID_HANDLE, "world");
  EXPECT_OK(proxBody_SetDevice(tool, &def));
  EXPECT_OK(proxBody_SetDevice(tool, nullptr));  // detached
  EXPECT_OK(proxBody_SetDevice(tool, &def));

  const proxThreadsDef threads = proxDefaultThreadsDef();
  ASSERT_OK(proxWorld_StartThreads(world, &threads));
  proxPose pose = at(0.2);
  EXPECT_FAILS(proxBody_SetPose(tool, &pose), PROX_ERROR_BUSY, "device");
  // Detached while the threads run: the game thread moves the tool then.
  EXPECT_OK(proxBody_SetDevice(tool, nullptr));
  EXPECT_OK(proxBody_SetPose(tool, &pose));
  EXPECT_OK(proxBody_SetDevice(tool, &def));
  EXPECT_FAILS(proxBody_SetPose(tool, &pose), PROX_ERROR_BUSY, "device");
  EXPECT_OK(proxWorld_StopThreads(world));
  EXPECT_OK(proxBody_SetDevice(tool, nullptr));
  EXPECT_OK(proxBody_SetPose(tool, &pose));
}

// A built-in device is one hand: it drives one tool at a time, before and
// while the threads run; handed to another tool, it is refused by name.
TEST_F(Threads, ABuiltInDeviceHoldsOneToolAtATime) {
  proxScriptedDeviceDef sd = proxDefaultScriptedDeviceDef();
  const proxPose poses[1] = {at(0.13)};
  sd.poses = poses;
  sd.poseCount = 1;
  sd.secondsPerPose = 0.1;
  proxScriptedDeviceId scripted{};
  ASSERT_OK(proxWorld_CreateScriptedDevice(world, &sd, &scripted));
  proxDeviceDef def{};
  ASSERT_OK(proxScriptedDevice_GetDeviceDef(scripted, &def));
  proxBodyDef bd = proxDefaultBodyDef();
  bd.mesh = mesh;
  bd.type = PROX_BODY_TOOL;
  bd.pose = at(0.0, 0.5);
  proxBodyId second{};
  ASSERT_OK(proxWorld_CreateBody(world, &bd, &second));
  EXPECT_OK(proxBody_SetDevice(tool, &def));
  EXPECT_OK(proxBody_SetDevice(tool, &def));  // again on the same tool: no change
  EXPECT_FAILS(proxBody_SetDevice(second, &def), PROX_ERROR_INVALID_ARGUMENT, "already holds another tool");
  const proxThreadsDef threads = proxDefaultThreadsDef();
  ASSERT_OK(proxWorld_StartThreads(world, &threads));
  EXPECT_FAILS(proxBody_SetDevice(second, &def), PROX_ERROR_INVALID_ARGUMENT, "already holds another tool");
  EXPECT_OK(proxBody_SetDevice(tool, nullptr));
  EXPECT_OK(proxBody_SetDevice(second, &def));  // let go of, it may hold another
  EXPECT_OK(proxWorld_StopThreads(world));
}

TEST_F(Threads, StartAndStopAreValidatedAndTheSceneLivesWhileTheyRun) {
  proxThreadsDef def = proxDefaultThreadsDef();
  EXPECT_FAILS(proxWorld_StartThreads(world, nullptr), PROX_ERROR_INVALID_ARGUMENT, "def");
  proxThreadsDef raw{};
  EXPECT_FAILS(proxWorld_StartThreads(world, &raw), PROX_ERROR_INVALID_ARGUMENT, "proxDefaultThreadsDef");
  def.hapticRate = NAN;
  EXPECT_FAILS(proxWorld_StartThreads(world, &def), PROX_ERROR_INVALID_ARGUMENT, "haptic rate");
  def = proxDefaultThreadsDef();
  def.staleAfter = -1.0;
  EXPECT_FAILS(proxWorld_StartThreads(world, &def), PROX_ERROR_INVALID_ARGUMENT, "staleness");
  def = proxDefaultThreadsDef();
  def.globalCore = 1 << 20;
  EXPECT_FAILS(proxWorld_StartThreads(world, &def), PROX_ERROR_INVALID_ARGUMENT, "global thread's core");
  def = proxDefaultThreadsDef();
  EXPECT_OK(proxWorld_StopThreads(world));  // not running: nothing to do

  proxThreadStats stats{};
  EXPECT_OK(proxWorld_GetThreadStats(world, PROX_THREAD_HAPTIC, &stats));
  EXPECT_EQ(stats.updates, 0u) << "never started";
  EXPECT_EQ(stats.running, 0);

  ASSERT_OK(proxWorld_StartThreads(world, &def));
  EXPECT_FAILS(proxWorld_StartThreads(world, &def), PROX_ERROR_BUSY, "already running");
  EXPECT_FAILS(proxWorld_Step(world), PROX_ERROR_BUSY, "proxWorld_StopThreads");
  proxMeshDef md = proxDefaultMeshDef();
  md.positions = positions.data();
  md.vertexCount = 8;
  md.indices = indices.data();
  md.triangleCount = 12;
  // The scene lives (docs/dynamic-scenes.md): meshes and static or movable
  // bodies come and go while the threads run; tools, and the meshes they
  // hold, stay as they are until the threads stop.
  proxMeshId other{};
  EXPECT_OK(proxWorld_CreateMesh(world, &md, &other));
  proxMeshId missing{};
  EXPECT_FAILS(proxWorld_LoadMesh(world, "no/such/mesh.obj", &missing), PROX_ERROR_FILE, "no/such/mesh.obj");
  proxBodyDef bd = proxDefaultBodyDef();
  bd.mesh = other;
  bd.pose = at(0.0, 0.5);
  proxBodyId body{};
  EXPECT_OK(proxWorld_CreateBody(world, &bd, &body));
  EXPECT_FAILS(proxMesh_Destroy(other), PROX_ERROR_INVALID_ARGUMENT, "destroy them first");
  EXPECT_OK(proxBody_Destroy(body));
  EXPECT_OK(proxMesh_Destroy(other));
  bd.type = PROX_BODY_TOOL;
  bd.mesh = mesh;
  bd.pose = at(0.0, -0.5);
  proxBodyId second{};
  EXPECT_OK(proxWorld_CreateBody(world, &bd, &second));
  EXPECT_OK(proxBody_Destroy(second));
  proxWrench gone{};
  EXPECT_FAILS(proxBody_GetWrench(second, &gone), PROX_ERROR_INVALID_HANDLE, "live body");
  // A held tool's mesh deforms while the threads run too.
  EXPECT_OK(proxMesh_SetVertices(mesh, positions.data(), 8));

  // Another thread may not drive the world.
  std::thread([&] {
    EXPECT_EQ(proxWorld_StopThreads(world), PROX_ERROR_WRONG_THREAD);
    proxThreadStats s{};
    EXPECT_EQ(proxWorld_GetThreadStats(world, PROX_THREAD_LOCAL, &s), PROX_ERROR_WRONG_THREAD);
  }).join();

  EXPECT_TRUE(wait_until([&] {
    proxThreadStats s{};
    return proxWorld_GetThreadStats(world, PROX_THREAD_HAPTIC, &s) == PROX_SUCCESS && s.updates > 20;
  }));
  EXPECT_OK(proxWorld_GetThreadStats(world, PROX_THREAD_HAPTIC, &stats));
  EXPECT_EQ(stats.running, 1);
  EXPECT_EQ(stats.targetRate, 1000.0);
  EXPECT_GT(stats.achievedRate, 0.0);
  EXPECT_GT(stats.periodMax, 0.0);
  EXPECT_LE(stats.periodP50, stats.periodP99);
  EXPECT_LE(stats.periodP99, stats.periodMax);
  EXPECT_EQ(stats.pinnedCore, def.hapticCore);
  EXPECT_FAILS(proxWorld_GetThreadStats(world, static_cast<proxThread>(7), &stats),
               PROX_ERROR_INVALID_ARGUMENT, "proxThread");
  EXPECT_FAILS(proxWorld_GetThreadStats(world, PROX_THREAD_GLOBAL, nullptr), PROX_ERROR_INVALID_ARGUMENT,
               "stats");
  proxSafetyStats safety{};
  EXPECT_OK(proxWorld_GetSafetyStats(world, &safety));
  EXPECT_EQ(safety.tornSnapshots, 0u);
  EXPECT_FAILS(proxWorld_GetSafetyStats(world, nullptr), PROX_ERROR_INVALID_ARGUMENT, "stats");

  EXPECT_OK(proxWorld_StopThreads(world));
  EXPECT_OK(proxWorld_GetThreadStats(world, PROX_THREAD_HAPTIC, &stats));
  EXPECT_EQ(stats.running, 0);
  EXPECT_GT(stats.updates, 20u) << "the last run's statistics stay readable";
  EXPECT_OK(proxWorld_Step(world));
}

// A device written in C style: a fixed pose, and a count of what it got.
struct FixedDevice {
  proxPose pose;
  std::atomic<int> writes{0};
  std::atomic<bool> finite{true};
  std::atomic<double> last_x{0.0};
  static proxBool read(void* user, proxPose* pose) {
    *pose = static_cast<FixedDevice*>(user)->pose;
    return 1;
  }
  static void write(void* user, const proxWrench* w) {
    auto* self = static_cast<FixedDevice*>(user);
    if (!std::isfinite(w->force.x + w->force.y + w->force.z + w->torque.x + w->torque.y + w->torque.z))
      self->finite.store(false);
    self->last_x.store(w->force.x);
    self->writes.fetch_add(1);
  }
};

TEST_F(Threads, AScriptedApproachFeelsTheWallAsTheStepDoes) {
  // The scripted device brings the tool from 3 cm to 3 mm from the wall in
  // a fifth of a second, then holds it.
  proxScriptedDeviceDef sd = proxDefaultScriptedDeviceDef();
  const proxPose poses[2] = {at(0.13), at(0.103)};
  sd.poses = poses;
  sd.poseCount = 2;
  sd.secondsPerPose = 0.2;
  proxScriptedDeviceId scripted{};
  ASSERT_OK(proxWorld_CreateScriptedDevice(world, &sd, &scripted));
  proxDeviceDef device{};
  ASSERT_OK(proxScriptedDevice_GetDeviceDef(scripted, &device));
  ASSERT_OK(proxBody_SetDevice(tool, &device));

  // What the deterministic step says at the resting pose.
  ASSERT_OK(proxBody_SetPose(tool, &poses[1]));
  ASSERT_OK(proxWorld_Step(world));
  proxWrench expected{};
  ASSERT_OK(proxBody_GetWrench(tool, &expected));
  ASSERT_GT(length(expected.force), 0.0);
  int32_t expected_contacts = 0;
  EXPECT_EQ(proxBody_GetContacts(tool, nullptr, 0, &expected_contacts), PROX_ERROR_CAPACITY);
  ASSERT_OK(proxBody_SetPose(tool, &poses[0]));

  const proxThreadsDef def = proxDefaultThreadsDef();
  ASSERT_OK(proxWorld_StartThreads(world, &def));
  auto settled = [&] {
    proxScriptedDeviceRecord r{};
    proxWrench w{};
    return proxScriptedDevice_GetRecord(scripted, &r) == PROX_SUCCESS && r.progress >= 1.0 &&
           proxBody_GetWrench(tool, &w) == PROX_SUCCESS && std::abs(w.force.x - expected.force.x) < 1e-9;
  };
  ASSERT_TRUE(wait_until(settled)) << "the threads never felt what the step feels";
  proxPose pose{};
  EXPECT_OK(proxBody_GetPose(tool, &pose));
  EXPECT_NEAR(pose.position.x, 0.103, 1e-12) << "the tool is where the device holds it";
  int32_t count = 0;
  EXPECT_EQ(proxBody_GetContacts(tool, nullptr, 0, &count), PROX_ERROR_CAPACITY);
  EXPECT_EQ(count, expected_contacts);
  EXPECT_OK(proxWorld_StopThreads(world));

  proxScriptedDeviceRecord record{};
  EXPECT_OK(proxScriptedDevice_GetRecord(scripted, &record));
  EXPECT_TRUE(record.allFinite);
  EXPECT_GT(record.writes, 100u);
  EXPECT_LE(record.maxForce, proxDefaultWorldDef().force.maxForce + 1e-12);
  EXPECT_LE(record.maxForceStep, def.maxForceRate * 0.005 + 1e-9);
  EXPECT_EQ(length(record.lastForce), 0.0) << "stopping fades the force out";

  // The same world, now held by a device written against the C callbacks;
  // destroying the world while its threads run stops them cleanly.
  FixedDevice fixed;
  fixed.pose = poses[1];
  proxDeviceDef c = proxDefaultDeviceDef();
  c.readPose = &FixedDevice::read;
  c.writeWrench = &FixedDevice::write;
  c.userData = &fixed;
  ASSERT_OK(proxBody_SetDevice(tool, &c));
  ASSERT_OK(proxWorld_StartThreads(world, &def));
  EXPECT_TRUE(wait_until([&] { return std::abs(fixed.last_x.load() - expected.force.x) < 1e-9; }));
  EXPECT_OK(proxWorld_Destroy(world));
  EXPECT_TRUE(fixed.finite.load());
  EXPECT_EQ(fixed.last_x.load(), 0.0);
  const int writes = fixed.writes.load();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(fixed.writes.load(), writes) << "no callback after the world is gone";
}

// A flat field on the threads (docs/patches.md): two 2 cm sheets 1 mm
// apart, held there by a device. The haptic loop gets the step's patches,
// not the LMDs, and what reaches the device stays finite and clipped; the
// rule cannot change while the threads run.
TEST(ThreadsPatches, ParallelSheetsReachTheHapticLoopAsPatches) {
  proxWorldId world{};
  const proxWorldDef wd = proxDefaultWorldDef();
  ASSERT_OK(proxCreateWorld(&wd, &world));
  const capi_test::Sheet up(20, 0.02, false), down(20, 0.02, true);
  const proxMeshDef du = up.def(), dd = down.def();
  proxMeshId mu{}, md{};
  ASSERT_OK(proxWorld_CreateMesh(world, &du, &mu));
  ASSERT_OK(proxWorld_CreateMesh(world, &dd, &md));
  proxBodyDef b = proxDefaultBodyDef();
  b.mesh = mu;
  b.type = PROX_BODY_STATIC;
  proxBodyId floor{}, tool{};
  ASSERT_OK(proxWorld_CreateBody(world, &b, &floor));
  b.mesh = md;
  b.type = PROX_BODY_TOOL;
  b.pose = {{0.0, 0.0, 0.001}, {1, 0, 0, 0}};
  ASSERT_OK(proxWorld_CreateBody(world, &b, &tool));
  ASSERT_OK(proxWorld_Step(world));
  proxPatchStats step{};
  ASSERT_OK(proxWorld_GetPatchStats(world, &step));
  ASSERT_GT(step.lmds, 10 * step.patches);

  FixedDevice fixed;
  fixed.pose = b.pose;
  proxDeviceDef c = proxDefaultDeviceDef();
  c.readPose = &FixedDevice::read;
  c.writeWrench = &FixedDevice::write;
  c.userData = &fixed;
  ASSERT_OK(proxBody_SetDevice(tool, &c));
  const proxThreadsDef def = proxDefaultThreadsDef();
  ASSERT_OK(proxWorld_StartThreads(world, &def));
  const proxPatchSettings off{0.0, 5.0, 0.002};
  EXPECT_FAILS(proxWorld_SetPatchSettings(world, &off), PROX_ERROR_BUSY, "proxWorld_StopThreads");
  EXPECT_FAILS(proxWorld_SetLeafBudget(world, 10), PROX_ERROR_BUSY, "proxWorld_StopThreads");
  // The global thread's search merged its LMDs as the step did, the local
  // thread tracks those patches, and the haptic loop has run on them.
  auto contacts = [&] {
    int32_t n = 0;
    const proxResult r = proxBody_GetContacts(tool, nullptr, 0, &n);
    return r == PROX_SUCCESS || r == PROX_ERROR_CAPACITY ? n : -1;
  };
  // The force ramps up behind the safety gate's rate limit: it pushes the
  // tool up, never past the clip.
  proxWrench w{};
  EXPECT_TRUE(wait_until([&] {
    return contacts() == step.patches && proxBody_GetWrench(tool, &w) == PROX_SUCCESS && w.force.z > 0.0;
  })) << contacts()
      << " contacts, " << step.patches << " patches in the step";
  EXPECT_LE(length(w.force), wd.force.maxForce + 1e-12);
  EXPECT_EQ(contacts(), step.patches);
  // Local tracking's contacts carry their patches: each seed still stands
  // for its members, and together for every LMD of the step.
  std::vector<proxContactPatch> patches(static_cast<size_t>(step.patches));
  int32_t n = 0;
  ASSERT_OK(proxBody_GetContactPatches(tool, nullptr, patches.data(), step.patches, &n));
  ASSERT_EQ(n, step.patches);
  int32_t members = 0;
  for (const proxContactPatch& p : patches) members += p.count;
  EXPECT_EQ(members, step.lmds);
  proxSafetyStats safety{};
  EXPECT_OK(proxWorld_GetSafetyStats(world, &safety));
  EXPECT_EQ(safety.tornSnapshots, 0u);
  EXPECT_OK(proxWorld_StopThreads(world));
  EXPECT_TRUE(fixed.finite.load());
  EXPECT_OK(proxWorld_Destroy(world));
}

}  // namespace
