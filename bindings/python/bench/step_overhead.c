/* The C side of step_overhead.py: the same loop on the C API, timed here.
 *
 *   step_overhead MESH ITERATIONS still|moving
 *
 * A static bunny and a tool bunny 3.3 mm from it; per iteration (moving
 * only) the tool's pose is set, alternating 10 um apart so every step
 * searches, then proxWorld_Step and proxBody_GetContacts (still: no pose is
 * set, so the step skips the search). Prints the median microseconds per iteration
 * over 5 repeats. */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include <proxima/proxima.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static void check(proxResult r, const char* what) {
  if (r != PROX_SUCCESS && r != PROX_ERROR_CAPACITY) {
    fprintf(stderr, "%s: %s\n", what, proxGetLastError());
    exit(1);
  }
}

static int compare(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

int main(int argc, char** argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: step_overhead MESH ITERATIONS still|moving\n");
    return 2;
  }
  const int iterations = atoi(argv[2]);
  const int moving = strcmp(argv[3], "moving") == 0;
  proxWorldDef def = proxDefaultWorldDef();
  proxWorldId world;
  check(proxCreateWorld(&def, &world), "proxCreateWorld");
  proxMeshId mesh;
  check(proxWorld_LoadMesh(world, argv[1], &mesh), "proxWorld_LoadMesh");
  proxBodyDef body = proxDefaultBodyDef();
  body.mesh = mesh;
  proxBodyId rock, tool;
  check(proxWorld_CreateBody(world, &body, &rock), "proxWorld_CreateBody");
  body.type = PROX_BODY_TOOL;
  check(proxWorld_CreateBody(world, &body, &tool), "proxWorld_CreateBody");
  /* step_overhead.py's POSE: keep the two in step. */
  proxPose poses[2] = {{{0.135, 0.01, 0.0}, {0.98, 0.05, 0.1, 0.03}}, {{0.13501, 0.01, 0.0}, {0.98, 0.05, 0.1, 0.03}}};
  check(proxBody_SetPose(tool, &poses[0]), "proxBody_SetPose");
  proxContact contacts[256];
  int32_t count = 0;
  double medians[5];
  for (int repeat = 0; repeat < 5; ++repeat) {
    const double start = now();
    for (int i = 0; i < iterations; ++i) {
      if (moving) check(proxBody_SetPose(tool, &poses[i & 1]), "proxBody_SetPose");
      check(proxWorld_Step(world), "proxWorld_Step");
      check(proxBody_GetContacts(tool, contacts, 256, &count), "proxBody_GetContacts");
    }
    medians[repeat] = (now() - start) / iterations * 1e6;
  }
  qsort(medians, 5, sizeof medians[0], compare);
  printf("%.3f %d\n", medians[2], (int)count);
  proxWorld_Destroy(world);
  return 0;
}
