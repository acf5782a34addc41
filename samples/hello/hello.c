/* Hello, Proxima: the shortest useful program.
 *
 * Loads the Stanford bunny twice, holds one as a tool a few millimetres from
 * the other, runs one deterministic step and prints the contacts (the local
 * minimum distance pairs) and the force and torque the user would feel.
 *
 *   hello [path/to/mesh.obj|.gltf|.glb]
 */
#include <proxima/proxima.h>

#include <stdio.h>

/* The build in this repository points it at the shared assets. */
#ifndef PROX_HELLO_DEFAULT_MESH
#define PROX_HELLO_DEFAULT_MESH "bunny.obj"
#endif

/* Every call returns a proxResult; on failure proxGetLastError() says what
 * was wrong, naming the argument. */
static int ok(proxResult r, const char* what) {
  if (r == PROX_SUCCESS) return 1;
  fprintf(stderr, "%s failed: %s: %s\n", what, proxResultString(r), proxGetLastError());
  return 0;
}

int main(int argc, char** argv) {
  const char* path = argc > 1 ? argv[1] : PROX_HELLO_DEFAULT_MESH;

  /* 1. A world, with its defaults: the precise method, a 5 mm cutoff and the
   *    "hard" force settings. The calling thread becomes its game thread. */
  proxWorldDef world_def = proxDefaultWorldDef();
  proxWorldId world;
  if (!ok(proxCreateWorld(&world_def, &world), "proxCreateWorld")) return 1;

  /* 2. A mesh: loaded once, its hierarchy built once, shared by every body
   *    that uses it. */
  proxMeshId bunny;
  if (!ok(proxWorld_LoadMesh(world, path, &bunny), "proxWorld_LoadMesh")) return 1;
  proxMeshInfo info;
  if (!ok(proxMesh_GetInfo(bunny, &info), "proxMesh_GetInfo")) return 1;
  printf("%s: %u triangles, %u vertices\n", path, info.triangleCount, info.vertexCount);

  /* 3. Two bodies: a static bunny at the origin, and a tool (the bunny the
   *    user holds) moved along +x until it is a few millimetres away. */
  proxBodyDef body_def = proxDefaultBodyDef();
  body_def.mesh = bunny;
  body_def.type = PROX_BODY_STATIC;
  proxBodyId rock;
  if (!ok(proxWorld_CreateBody(world, &body_def, &rock), "proxWorld_CreateBody")) return 1;

  const double width = info.boundsMax.x - info.boundsMin.x;
  body_def.type = PROX_BODY_TOOL;
  body_def.pose.position.x = 0.9 * width; /* most of a bunny's width to the side: close, not touching */
  body_def.referencePoint.x = 0.5 * (info.boundsMin.x + info.boundsMax.x);
  body_def.referencePoint.y = 0.5 * (info.boundsMin.y + info.boundsMax.y);
  body_def.referencePoint.z = 0.5 * (info.boundsMin.z + info.boundsMax.z);
  proxBodyId tool;
  if (!ok(proxWorld_CreateBody(world, &body_def, &tool), "proxWorld_CreateBody")) return 1;

  /* 4. One deterministic step: broadphase, global search, reduction, force.
   *    (The threaded runtime runs the same work at 1 kHz.) */
  if (!ok(proxWorld_Step(world), "proxWorld_Step")) return 1;

  /* 5. The results. Ask how many contacts there are, then fetch them. */
  int32_t count = 0;
  proxResult r = proxBody_GetContacts(tool, NULL, 0, &count);
  if (r != PROX_SUCCESS && r != PROX_ERROR_CAPACITY) return !ok(r, "proxBody_GetContacts");
  proxContact contacts[64];
  const int32_t capacity = count < 64 ? count : 64;
  r = proxBody_GetContacts(tool, contacts, capacity, &count);
  if (r != PROX_SUCCESS && r != PROX_ERROR_CAPACITY) return !ok(r, "proxBody_GetContacts");
  printf("%d contacts within %.1f mm:\n", count, world_def.cutoff * 1e3);
  static const char* feature[] = {"vertex", "edge", "face"};
  for (int32_t i = 0; i < capacity; ++i) {
    const proxContact* c = &contacts[i];
    printf("  %.3f mm  tool %s %u - %s %u  normal (%.3f, %.3f, %.3f)\n", c->distance * 1e3,
           feature[c->featureTool], c->triangleTool, feature[c->featureOther], c->triangleOther, c->normal.x,
           c->normal.y, c->normal.z);
  }

  proxWrench wrench;
  if (!ok(proxBody_GetWrench(tool, &wrench), "proxBody_GetWrench")) return 1;
  printf("force on the tool:  (%.4f, %.4f, %.4f) N\n", wrench.force.x, wrench.force.y, wrench.force.z);
  printf("torque on the tool: (%.5f, %.5f, %.5f) N m\n", wrench.torque.x, wrench.torque.y, wrench.torque.z);

  /* 6. Destroying the world destroys everything in it. */
  if (!ok(proxWorld_Destroy(world), "proxWorld_Destroy")) return 1;
  return count > 0 ? 0 : 2; /* the scene is built to be in contact */
}
