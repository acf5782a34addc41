/* Haptic, the threaded walkthrough: what a game engine does with Proxima.
 *
 * Two bunnies: one static, one held by a device. Proxima's threads run the
 * haptic loop at 1 kHz (reading the device, rendering the force), local
 * tracking and the global search, while this thread (the "game" thread)
 * reads the results as a renderer would. The device here is the built-in
 * scripted one, which moves the tool along a path; a real device is two
 * callbacks of yours (proxDeviceDef). See docs/threading.md.
 *
 *   haptic [path/to/mesh.obj|.gltf|.glb]
 */
#include <proxima/proxima.h>

#include <math.h>
#include <stdio.h>
#include <time.h>

static int ok(proxResult r, const char* what) {
  if (r == PROX_SUCCESS) return 1;
  fprintf(stderr, "%s failed: %s: %s\n", what, proxResultString(r), proxGetLastError());
  return 0;
}

static void sleep_ms(long ms) {
  struct timespec t = {ms / 1000, (ms % 1000) * 1000000L};
  nanosleep(&t, NULL);
}

static double norm(proxVec3 v) { return sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

int main(int argc, char** argv) {
  const char* path = argc > 1 ? argv[1] : PROX_HAPTIC_DEFAULT_MESH;

  /* 1. The scene, as in hello.c: a static bunny and a tool bunny. */
  proxWorldDef world_def = proxDefaultWorldDef();
  proxWorldId world;
  if (!ok(proxCreateWorld(&world_def, &world), "proxCreateWorld")) return 1;
  proxMeshId bunny;
  if (!ok(proxWorld_LoadMesh(world, path, &bunny), "proxWorld_LoadMesh")) return 1;
  proxMeshInfo info;
  if (!ok(proxMesh_GetInfo(bunny, &info), "proxMesh_GetInfo")) return 1;
  const double width = info.boundsMax.x - info.boundsMin.x;

  proxBodyDef body_def = proxDefaultBodyDef();
  body_def.mesh = bunny;
  proxBodyId rock, tool;
  if (!ok(proxWorld_CreateBody(world, &body_def, &rock), "proxWorld_CreateBody")) return 1;
  body_def.type = PROX_BODY_TOOL;
  body_def.pose.position.x = 1.2 * width;
  body_def.referencePoint.x = 0.5 * (info.boundsMin.x + info.boundsMax.x);
  body_def.referencePoint.y = 0.5 * (info.boundsMin.y + info.boundsMax.y);
  body_def.referencePoint.z = 0.5 * (info.boundsMin.z + info.boundsMax.z);
  if (!ok(proxWorld_CreateBody(world, &body_def, &tool), "proxWorld_CreateBody")) return 1;

  /* 2. The device: a scripted path from well apart to a few millimetres
   *    apart in one second, then held. It lives as long as the world. */
  proxPose path_poses[2] = {{{1.2 * width, 0, 0}, {1, 0, 0, 0}}, {{0.9 * width, 0, 0}, {1, 0, 0, 0}}};
  proxScriptedDeviceDef script = proxDefaultScriptedDeviceDef();
  script.poses = path_poses;
  script.poseCount = 2;
  script.secondsPerPose = 1.0;
  proxScriptedDeviceId scripted;
  if (!ok(proxWorld_CreateScriptedDevice(world, &script, &scripted), "proxWorld_CreateScriptedDevice"))
    return 1;
  proxDeviceDef device;
  if (!ok(proxScriptedDevice_GetDeviceDef(scripted, &device), "proxScriptedDevice_GetDeviceDef")) return 1;
  if (!ok(proxBody_SetDevice(tool, &device), "proxBody_SetDevice")) return 1;

  /* 3. Start the threads. From now on the scene's shape is frozen; this
   *    thread reads results and may move non-held bodies. */
  proxThreadsDef threads = proxDefaultThreadsDef();
  if (!ok(proxWorld_StartThreads(world, &threads), "proxWorld_StartThreads")) return 1;

  /* 4. The "render loop": every 100 ms, where the tool is and what the
   *    user feels. */
  printf("  time   tool x (m)  contacts  |force| (N)\n");
  double felt = 0.0;
  for (int frame = 0; frame <= 15; ++frame) {
    proxPose pose;
    proxWrench wrench;
    int32_t contacts = 0;
    if (!ok(proxBody_GetPose(tool, &pose), "proxBody_GetPose")) return 1;
    if (!ok(proxBody_GetWrench(tool, &wrench), "proxBody_GetWrench")) return 1;
    proxResult r = proxBody_GetContacts(tool, NULL, 0, &contacts); /* just the count */
    if (r != PROX_ERROR_CAPACITY && !ok(r, "proxBody_GetContacts")) return 1;
    printf("  %.1f s  %.6f  %8d  %.4f\n", 0.1 * frame, pose.position.x, contacts, norm(wrench.force));
    if (norm(wrench.force) > felt) felt = norm(wrench.force);
    sleep_ms(100);
  }

  /* 5. Stop (the force fades out first) and look at how the threads did. */
  if (!ok(proxWorld_StopThreads(world), "proxWorld_StopThreads")) return 1;
  const char* names[3] = {"haptic", "local", "global"};
  for (int t = 0; t < 3; ++t) {
    proxThreadStats s;
    if (!ok(proxWorld_GetThreadStats(world, (proxThread)t, &s), "proxWorld_GetThreadStats")) return 1;
    printf(
        "%-6s thread: %6.0f Hz achieved (target %s), period p50 %.3f ms p99 %.3f ms, work p99 %.3f ms, "
        "%llu updates, %llu overruns\n",
        names[t], s.achievedRate, s.targetRate > 0 ? "fixed" : "back to back", s.periodP50 * 1e3,
        s.periodP99 * 1e3, s.updateP99 * 1e3, (unsigned long long)s.updates, (unsigned long long)s.overruns);
  }
  proxScriptedDeviceRecord record;
  if (!ok(proxScriptedDevice_GetRecord(scripted, &record), "proxScriptedDevice_GetRecord")) return 1;
  printf("device: %llu poses read, %llu wrenches written, largest force %.4f N, largest step %.4f N, %s\n",
         (unsigned long long)record.reads, (unsigned long long)record.writes, record.maxForce,
         record.maxForceStep, record.allFinite ? "all finite" : "NOT ALL FINITE");

  proxWorld_Destroy(world);
  /* The sample fails (for its test) if nothing was felt or anything was off. */
  return felt > 0.0 && record.allFinite && record.maxForce <= world_def.force.maxForce ? 0 : 1;
}
