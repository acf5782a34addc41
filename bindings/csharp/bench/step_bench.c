/* The C twin of StepBench.cs: the same scene, loop and CSV rows, so that the
 * difference is the binding's overhead (docs/csharp.md).
 *
 *   proxima_c_step_bench BUNNY.obj [iterations] */
#include <proxima/proxima.h>

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void check(proxResult r, const char* what) {
  if (r != PROX_SUCCESS && r != PROX_ERROR_CAPACITY) {
    fprintf(stderr, "%s: %s: %s\n", what, proxResultString(r), proxGetLastError());
    exit(1);
  }
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: proxima_c_step_bench MESH [iterations]\n");
    return 2;
  }
  const int iterations = argc > 2 ? atoi(argv[2]) : 20000;
  proxWorldDef wdef = proxDefaultWorldDef();
  proxWorldId world;
  check(proxCreateWorld(&wdef, &world), "proxCreateWorld");
  proxMeshId bunny;
  check(proxWorld_LoadMesh(world, argv[1], &bunny), "proxWorld_LoadMesh");
  proxBodyDef bdef = proxDefaultBodyDef();
  bdef.mesh = bunny;
  proxBodyId rock, tool;
  check(proxWorld_CreateBody(world, &bdef, &rock), "proxWorld_CreateBody");
  const proxPose near = {{0.135, 0.002, 0}, {0.999, 0, 0.04, 0}};
  bdef.type = PROX_BODY_TOOL;
  bdef.pose = near;
  check(proxWorld_CreateBody(world, &bdef, &tool), "proxWorld_CreateBody");
  proxContact buffer[64];
  int32_t contacts = 0;
  check(proxWorld_Step(world), "proxWorld_Step");
  check(proxBody_GetContacts(tool, buffer, 64, &contacts), "proxBody_GetContacts");

  printf("language,case,iterations,contacts,ns_per_iteration\n");
  int32_t count = 0;
  for (int i = 0; i < 1000; ++i) {
    check(proxWorld_Step(world), "proxWorld_Step");
    check(proxBody_GetContacts(tool, buffer, 64, &count), "proxBody_GetContacts");
  }
  double t0 = now();
  for (int i = 0; i < iterations; ++i) {
    check(proxWorld_Step(world), "proxWorld_Step");
    check(proxBody_GetContacts(tool, buffer, 64, &count), "proxBody_GetContacts");
  }
  printf("c,unchanged,%d,%d,%.1f\n", iterations, contacts, (now() - t0) * 1e9 / iterations);

  const int moving = iterations / 100 > 1 ? iterations / 100 : 1;
  t0 = now();
  for (int i = 0; i < moving; ++i) {
    proxPose p = near;
    p.position.x += 1e-6 * (i % 2);
    check(proxBody_SetPose(tool, &p), "proxBody_SetPose");
    check(proxWorld_Step(world), "proxWorld_Step");
    check(proxBody_GetContacts(tool, buffer, 64, &count), "proxBody_GetContacts");
  }
  printf("c,moving,%d,%d,%.1f\n", moving, contacts, (now() - t0) * 1e9 / moving);
  proxWorld_Destroy(world);
  return 0;
}
