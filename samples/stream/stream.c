/* Stream, the engine walkthrough: how a game engine, a binding or an XR
 * integration drives the held tool.
 *
 * The engine knows the hand's pose once a frame (60-120 Hz) on its own
 * thread; the haptic loop needs one every millisecond and must never wait
 * for the engine. So the engine pushes timestamped poses into a streamed
 * device, the haptic loop interpolates between them at 1 kHz, and the engine
 * reads back the wrench the haptic loop rendered, once a frame, to drive
 * whatever it has: a rumble, a controller's vibration, a force display.
 * See docs/devices.md.
 *
 *   stream [path/to/mesh.obj|.gltf|.glb]
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

/* Sleeps until `deadline` on proxGetTime()'s clock. */
static void sleep_until(double deadline) {
  const double left = deadline - proxGetTime();
  if (left <= 0.0) return;
  struct timespec t = {(time_t)left, (long)((left - floor(left)) * 1e9)};
  nanosleep(&t, NULL);
}

static double norm(proxVec3 v) { return sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

int main(int argc, char** argv) {
  const char* path = argc > 1 ? argv[1] : PROX_STREAM_DEFAULT_MESH;

  /* 1. The scene, as in hello.c: a static bunny and a tool bunny beside it. */
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

  /* 2. The streamed device. The default interpolates one 90 Hz frame in
   *    the past, so there is nearly always a sample on either side of the
   *    pose it renders: smooth at the cost of a frame of latency. */
  proxStreamDeviceDef stream_def = proxDefaultStreamDeviceDef();
  proxStreamDeviceId hand;
  if (!ok(proxWorld_CreateStreamDevice(world, &stream_def, &hand), "proxWorld_CreateStreamDevice")) return 1;
  proxDeviceDef device;
  if (!ok(proxStreamDevice_GetDeviceDef(hand, &device), "proxStreamDevice_GetDeviceDef")) return 1;
  if (!ok(proxBody_SetDevice(tool, &device), "proxBody_SetDevice")) return 1;

  proxThreadsDef threads = proxDefaultThreadsDef();
  if (!ok(proxWorld_StartThreads(world, &threads), "proxWorld_StartThreads")) return 1;

  /* 3. The engine's frame loop at 90 Hz for 1.5 s: the hand moves the tool
   *    from well apart to a few millimetres from the rock in one second,
   *    then holds it. Each frame pushes the pose with the time it is true
   *    and reads back what the user should feel. */
  const double fps = 90.0, start = proxGetTime();
  double felt = 0.0;
  int finite = 1;
  printf("  time   tool x (m)  |force| (N)  (what the engine renders this frame)\n");
  for (int frame = 0; frame <= 135; ++frame) {
    sleep_until(start + frame / fps);
    const double now = proxGetTime();
    const double s = fmin(1.0, (now - start) / 1.0);
    proxPose hand_pose = {{(1.2 - 0.3 * s) * width, 0, 0}, {1, 0, 0, 0}};
    if (!ok(proxStreamDevice_PushPose(hand, &hand_pose, now), "proxStreamDevice_PushPose")) return 1;
    proxWrench wrench;
    if (!ok(proxStreamDevice_GetWrench(hand, &wrench), "proxStreamDevice_GetWrench")) return 1;
    const double f = norm(wrench.force);
    if (!isfinite(f)) finite = 0;
    if (f > felt) felt = f;
    if (frame % 15 == 0) printf("  %.2f s  %.6f  %.4f\n", now - start, hand_pose.position.x, f);
  }

  /* 4. Stop the threads (the force fades out first) and see what the
   *    stream looked like from the haptic loop's side. */
  if (!ok(proxWorld_StopThreads(world), "proxWorld_StopThreads")) return 1;
  proxStreamDeviceStats stats;
  if (!ok(proxStreamDevice_GetStats(hand, &stats), "proxStreamDevice_GetStats")) return 1;
  printf(
      "stream: %llu poses pushed (%llu dropped), every %.2f ms on average (at most %.2f); the haptic loop "
      "read %llu poses from them, %llu of them past the newest sample\n",
      (unsigned long long)stats.samplesPushed, (unsigned long long)stats.samplesDropped,
      stats.meanSampleInterval * 1e3, stats.maxSampleInterval * 1e3, (unsigned long long)stats.reads,
      (unsigned long long)stats.extrapolatedTicks);
  proxWorld_Destroy(world);
  /* The sample fails (for its test) if nothing was felt or anything was off. */
  return felt > 0.0 && finite && felt <= world_def.force.maxForce && stats.reads > stats.samplesPushed ? 0
                                                                                                       : 1;
}
