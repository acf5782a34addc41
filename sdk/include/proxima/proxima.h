/* Proxima: multi-contact proximity haptics. The C API.
 *
 * This header (with proxima/threads.h and proxima/inspect.h, which it
 * includes) is the one public, stable interface of the SDK. It is plain
 * C11: opaque value ids, plain structs, fixed-width types, 32-bit booleans
 * and enums, no C++ type, no exception. Every function returns a
 * proxResult (0 on success, negative on error); on error,
 * proxGetLastError() names what was wrong, on the calling thread.
 *
 * Units and conventions: lengths in metres (or the units of the meshes you
 * give, consistently), forces in newtons, torques in newton-metres, times in
 * seconds. Poses are rigid: world = rotation * local + position, the rotation
 * a unit quaternion (w, x, y, z). A contact's normal points from the other
 * body to the tool; distances are never negative (intersecting surfaces are
 * not contacts: ask for the intersection polylines).
 *
 * Threads: each function says from which thread it may be called.
 *   "game"  - the thread that created the world (scene updates, rendering);
 *   "any"   - any thread, concurrently with anything.
 * Calls from the wrong thread fail with PROX_ERROR_WRONG_THREAD. A world
 * either steps on the game thread (proxWorld_Step) or runs its own haptic,
 * local tracking and global search threads (proxWorld_StartThreads); while
 * they run, the scene's shape is frozen (PROX_ERROR_BUSY). Who owns what is
 * in docs/threading.md.
 *
 * A newcomer's walkthrough is samples/hello/hello.c.
 */
#ifndef PROXIMA_PROXIMA_H
#define PROXIMA_PROXIMA_H

#include <stddef.h>
#include <stdint.h>

#include "proxima/version.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Overridable, so that tools that parse the header (the Python binding's
 * cffi build) can define it away. On Windows proxima.dll exports the API
 * (PROX_BUILDING_SHARED, set by its build) and every other program imports
 * it from there. */
#ifndef PROX_API
#if defined(_WIN32) && defined(PROX_BUILDING_SHARED)
#define PROX_API __declspec(dllexport)
#elif defined(_WIN32)
#define PROX_API __declspec(dllimport)
#elif defined(__GNUC__)
#define PROX_API __attribute__((visibility("default")))
#else
#define PROX_API
#endif
#endif /* PROX_API */

/* The API version this header describes. proxDefaultWorldDef() stores it in
 * the def; proxCreateWorld() takes a def of the library's major version and
 * a minor one not newer than the library's, and refuses any other. */
#define PROX_API_VERSION ((PROX_VERSION_MAJOR << 16) | PROX_VERSION_MINOR)

/* A 32-bit boolean: 0 is false, anything else true. */
typedef int32_t proxBool;

/* ---- results ----------------------------------------------------------- */

typedef enum proxResult {
  PROX_SUCCESS = 0,
  PROX_ERROR_INVALID_ARGUMENT = -1, /* NULL, NaN, out of range, malformed def */
  PROX_ERROR_INVALID_HANDLE = -2,   /* null, destroyed or foreign id */
  PROX_ERROR_INVALID_MESH = -3,     /* empty, non-finite or degenerate mesh data */
  PROX_ERROR_FILE = -4,             /* a file cannot be read */
  PROX_ERROR_PARSE = -5,            /* a file's content is malformed */
  PROX_ERROR_UNSUPPORTED = -6,      /* valid input using an unsupported feature */
  PROX_ERROR_VERSION_MISMATCH = -7, /* header and library disagree */
  PROX_ERROR_WRONG_THREAD = -8,     /* called from a thread the function does not allow */
  PROX_ERROR_CAPACITY = -9,         /* an output buffer is too small (the count says how big) */
  PROX_ERROR_INTERNAL = -10,        /* a bug in Proxima: please report it with the message */
  PROX_ERROR_BUSY = -11,            /* the world's threads are running: stop them first */
  PROX_RESULT_FORCE32 = 0x7FFFFFFF
} proxResult;

/* A short, static name for a result ("PROX_ERROR_INVALID_HANDLE"). Any thread. */
PROX_API const char* proxResultString(proxResult result);

/* The message of the last error on the calling thread, naming the offending
 * argument; "" when the last call succeeded. Valid until the next call on
 * this thread. Any thread. */
PROX_API const char* proxGetLastError(void);

/* The library's version (compare with PROX_VERSION_* of this header). Any thread. */
typedef struct proxVersion {
  int32_t major, minor, patch;
} proxVersion;
PROX_API proxVersion proxGetVersion(void);

/* ---- ids ----------------------------------------------------------------- */

/* Ids are values: copy them freely. Zero-initialised ids are null. A
 * destroyed object's id stays invalid forever (the generation moves on). */
typedef struct proxWorldId {
  uint32_t index1; /* index + 1; 0 is null */
  uint32_t generation;
} proxWorldId;

typedef struct proxMeshId {
  uint32_t index1;
  uint32_t generation;
  proxWorldId world;
} proxMeshId;

typedef struct proxBodyId {
  uint32_t index1;
  uint32_t generation;
  proxWorldId world;
} proxBodyId;

/* ---- geometry ------------------------------------------------------------ */

typedef struct proxVec3 {
  double x, y, z;
} proxVec3;

/* A unit quaternion; (1, 0, 0, 0) is the identity. */
typedef struct proxQuat {
  double w, x, y, z;
} proxQuat;

typedef struct proxPose {
  proxVec3 position;
  proxQuat rotation; /* normalised on input; a zero quaternion is an error */
} proxPose;

/* ---- world ----------------------------------------------------------------- */

typedef enum proxMethod {
  PROX_METHOD_PRECISE = 0,   /* the improved method: exact distances, visibility pre-test, reduction */
  PROX_METHOD_ORIGINAL = 1,  /* the Johnson-Cohen baseline: 7 x 7 feature points */
  PROX_METHOD_REFERENCE = 2, /* the brute-force truth: every triangle pair; slow, for tests */
  PROX_METHOD_FORCE32 = 0x7FFFFFFF
} proxMethod;

typedef enum proxForceCurve {
  PROX_FORCE_EXPONENTIAL = 0, /* max at the safety distance, falls by e per decay length, 0 at the cutoff */
  PROX_FORCE_LINEAR = 1,      /* max at the safety distance, linear to 0 at the cutoff */
  PROX_FORCE_CURVE_FORCE32 = 0x7FFFFFFF
} proxForceCurve;

typedef struct proxForceSettings {
  proxForceCurve curve;
  double maxForce;       /* N: per contact at the safety distance, and the clip of the sum (> 0) */
  double maxTorque;      /* N m: clip of the summed torque (> 0) */
  double safetyDistance; /* m: full force at and inside this distance (>= 0, < cutoff) */
  double decayLength;    /* m: exponential curve's length scale (> 0) */
} proxForceSettings;

typedef struct proxWorldDef {
  int32_t apiVersion; /* set by proxDefaultWorldDef to PROX_API_VERSION */
  proxMethod method;
  double cutoff;           /* m: contacts farther apart are not wanted (> 0) */
  proxForceSettings force; /* the default: the "hard" settings of docs/cli.md */
  int32_t internalValue;   /* do not touch: lets proxCreateWorld detect a def not from proxDefaultWorldDef */
  /* Threads the game thread's own heavy work is split over, itself
   * included, in [1, 256] (default 1: no thread started): a deforming mesh's
   * normals and hierarchy (proxMesh_SetVertices, proxMesh_Animate...) and
   * proxWorld_Step's searches. The results are the same bits whatever the
   * count. Leave the haptic and tracking threads their cores (docs/threading.md). */
  int32_t workerCount;
} proxWorldDef;

/* A def with every field at its default. Any thread. */
PROX_API proxWorldDef proxDefaultWorldDef(void);

/* Creates a world; the calling thread becomes its game thread. */
PROX_API proxResult proxCreateWorld(const proxWorldDef* def, proxWorldId* world);
/* Destroys a world and everything in it, stopping its threads first (the
 * devices fade out). Game thread. */
PROX_API proxResult proxDestroyWorld(proxWorldId world);
/* Whether an id names a live world. Any thread. */
PROX_API proxBool proxWorld_IsValid(proxWorldId world);

/* ---- meshes ---------------------------------------------------------------- */

typedef struct proxMeshDef {
  const double* positions; /* x, y, z per vertex */
  uint32_t vertexCount;
  const uint32_t* indices; /* three per triangle, counter-clockwise seen from outside */
  uint32_t triangleCount;
  int32_t internalValue;
} proxMeshDef;

PROX_API proxMeshDef proxDefaultMeshDef(void);

/* Validates the data (finite coordinates, indices in range, at least one
 * non-degenerate triangle), welds vertices by position, builds the topology
 * and the hierarchy, on the calling thread. The data is copied. Game thread;
 * also while the threads run (docs/dynamic-scenes.md). */
PROX_API proxResult proxWorld_CreateMesh(proxWorldId world, const proxMeshDef* def, proxMeshId* mesh);

/* Reads a mesh from an OBJ, glTF (.gltf) or binary glTF (.glb) file; a glTF
 * scene is merged into one mesh with its node transforms applied. Game thread. */
PROX_API proxResult proxWorld_LoadMesh(proxWorldId world, const char* path, proxMeshId* mesh);

/* proxWorld_LoadMesh from a file's bytes already in memory (an engine's asset
 * package, a download): `name` is the file's name, whose extension says the
 * format (.obj, .gltf, .glb; bytes starting with the GLB magic are read as
 * GLB whatever the name) and which errors name. Nothing is read from disk: a
 * .gltf must embed its buffers (data: URIs). The bytes are the caller's and
 * are not kept. Game thread. */
PROX_API proxResult proxWorld_LoadMeshFromMemory(proxWorldId world, const void* data, uint64_t size,
                                                 const char* name, proxMeshId* mesh);

/* Destroys a mesh; fails while bodies use it. Game thread; also while the
 * threads run. */
PROX_API proxResult proxMesh_Destroy(proxMeshId mesh);
/* Whether an id names a live mesh of a live world. Game thread: from any
 * other it is false, and proxGetLastError says why (as it does for a dead
 * or null id). */
PROX_API proxBool proxMesh_IsValid(proxMeshId mesh);

typedef struct proxMeshInfo {
  uint32_t triangleCount; /* after dropping triangles that repeat a vertex */
  uint32_t vertexCount;   /* after welding */
  uint32_t droppedTriangles;
  uint32_t boundaryEdges;
  uint32_t nonManifoldEdges;
  proxVec3 boundsMin, boundsMax; /* in the mesh's own frame */
} proxMeshInfo;

/* Game thread. */
PROX_API proxResult proxMesh_GetInfo(proxMeshId mesh, proxMeshInfo* info);

/* The mesh as Proxima uses it, in its own frame: the welded vertices (x, y, z
 * each) and the kept triangles (three vertex indices each, counter-clockwise
 * seen from outside), the counts proxMesh_GetInfo reports. For drawing a mesh
 * loaded from a file, or exporting it. Sets *vertexCount and *triangleCount
 * to the mesh's counts; copies the data when both arrays have room
 * (positions: 3 * vertexCapacity doubles, indices: 3 * triangleCapacity), else
 * copies nothing and returns PROX_ERROR_CAPACITY. Pass NULL arrays with
 * capacities 0 to learn the counts first. Game thread. */
PROX_API proxResult proxMesh_GetTriangles(proxMeshId mesh, double* positions, uint32_t vertexCapacity,
                                          uint32_t* vertexCount, uint32_t* indices, uint32_t triangleCapacity,
                                          uint32_t* triangleCount);

/* Deforms a mesh: new positions for its vertices, the same topology. x, y, z
 * per vertex (3 * vertexCount doubles, in the mesh's own frame), in the
 * order proxMesh_GetTriangles hands the vertices out; vertexCount must be
 * the mesh's (proxMeshInfo.vertexCount). The hierarchy is refitted on the
 * calling thread, or rebuilt there when refitting has loosened it too far
 * (docs/dynamic-scenes.md); every body using the mesh takes the new shape:
 * at the next proxWorld_Step, or at the threads' next iteration while they
 * run, where local tracking carries the contacts onto it. A count that
 * differs or a non-finite coordinate (named by vertex) is refused and
 * changes nothing. Game thread, at frame rate, also while the threads run
 * (a held tool's mesh too: its contacts are tracked on its new shape). */
PROX_API proxResult proxMesh_SetVertices(proxMeshId mesh, const double* positions, uint32_t vertexCount);

/* What loading the mesh's file skipped without failing: attributes Proxima
 * does not read (NORMAL, TEXCOORD_0, ...) that are invalid, say a NORMAL
 * accessor running past its buffer view. One warning per line, each ending
 * in '\n', naming the file, mesh, primitive and accessor; "" for a mesh
 * without warnings (every mesh made by proxWorld_CreateMesh). Copies at most
 * capacity - 1 bytes and a terminating NUL into `buffer` (may be NULL when
 * capacity is 0) and sets *length to the whole text's length without the
 * NUL; PROX_ERROR_CAPACITY when it did not all fit. Game thread. */
PROX_API proxResult proxMesh_GetWarnings(proxMeshId mesh, char* buffer, int32_t capacity, int32_t* length);

/* ---- glTF skins, morph targets and animation ------------------------------
 * A mesh loaded from a glTF scene with skins, morph targets or animations
 * keeps its rig (docs/dynamic-scenes.md): loaded, it is posed at rest. The
 * calls that pose it (Animate, SetJointMatrices, SetMorphWeights) replace
 * its vertices as proxMesh_SetVertices does (same topology, the hierarchy
 * refitted); where glTF vertices welded at rest move apart, the first in
 * scene order places the vertex. All: game thread, also while the threads
 * run. A mesh without a
 * rig has zero of everything; posing it is PROX_ERROR_INVALID_ARGUMENT. */
typedef struct proxRigInfo {
  int32_t skinCount;
  int32_t jointCount;       /* over every skin */
  int32_t morphWeightCount; /* what proxMesh_SetMorphWeights takes */
  int32_t animationCount;
} proxRigInfo;
/* Game thread. */
PROX_API proxResult proxMesh_GetRigInfo(proxMeshId mesh, proxRigInfo* info);

typedef struct proxSkinInfo {
  char name[64]; /* NUL-terminated, cut to 63 bytes; "" when the file names none */
  int32_t jointCount;
  int32_t reserved;
} proxSkinInfo;
/* Skin `skin` in [0, skinCount). Game thread. */
PROX_API proxResult proxMesh_GetSkinInfo(proxMeshId mesh, int32_t skin, proxSkinInfo* info);

/* The animations, in the file's order (0 for a mesh without a rig). Game thread. */
PROX_API proxResult proxMesh_GetAnimationCount(proxMeshId mesh, int32_t* count);

typedef struct proxAnimationInfo {
  char name[64];   /* NUL-terminated, cut to 63 bytes; "animation N" when the file names none */
  double duration; /* seconds: the last keyframe's time (glTF time starts at 0) */
  double start;    /* seconds: the first keyframe's time */
  int32_t channelCount;
  int32_t reserved;
} proxAnimationInfo;
/* Animation `index` in [0, count). Game thread. */
PROX_API proxResult proxMesh_GetAnimationInfo(proxMeshId mesh, int32_t index, proxAnimationInfo* info);

/* The scene at `seconds` of animation `animation` (clamped to its keyframes:
 * STEP, LINEAR with slerp for rotations, CUBICSPLINE): its nodes, skins
 * (linear blend) and morph weights; joint matrices and morph weights set
 * before are dropped. Game thread, also while the threads run. */
PROX_API proxResult proxMesh_Animate(proxMeshId mesh, int32_t animation, double seconds);

/* Your engine's animation system drives the skin: `count` (the skin's joint
 * count) JOINT WORLD matrices, 16 doubles each, column-major (element
 * 4 * column + row, translation in 12, 13, 14), affine, in the mesh's own
 * frame (the glTF scene root), in the skin's joint order. Proxima multiplies
 * each by the joint's inverse bind matrix from the file. They stand for the
 * joints' nodes until the next proxMesh_Animate. Game thread; as
 * proxMesh_Animate while the threads run. */
PROX_API proxResult proxMesh_SetJointMatrices(proxMeshId mesh, int32_t skin, const double* matrices,
                                              int32_t count);

/* Every morphed mesh instance's weights, one after the other in scene order
 * (count: proxRigInfo.morphWeightCount), until the next proxMesh_Animate.
 * Game thread; as proxMesh_Animate while the threads run. */
PROX_API proxResult proxMesh_SetMorphWeights(proxMeshId mesh, const double* weights, int32_t count);

/* ---- bodies ---------------------------------------------------------------- */

typedef enum proxBodyType {
  PROX_BODY_STATIC = 0,  /* never moves; static-static pairs are never tested */
  PROX_BODY_MOVABLE = 1, /* moved by the application */
  PROX_BODY_TOOL = 2,    /* held by the user: contacts and forces are computed for tools */
  PROX_BODY_TYPE_FORCE32 = 0x7FFFFFFF
} proxBodyType;

/* How a tool follows what moves it (docs/coupling.md). */
typedef enum proxToolMode {
  /* The tool is where its device (or SetPose) puts it; the force comes from
   * its LMDs (the paper's distance-to-force curve). The default. */
  PROX_TOOL_FREE = 0,
  /* A proxy follows the device but never comes closer to another body than
   * the safety distance; contacts are the proxy's, and the force is the
   * virtual coupling, a spring-damper between device pose and proxy. */
  PROX_TOOL_CONSTRAINED = 1,
  PROX_TOOL_MODE_FORCE32 = 0x7FFFFFFF
} proxToolMode;

typedef struct proxBodyDef {
  proxMeshId mesh;
  proxBodyType type;
  proxPose pose;
  /* Tools: the point (in the body's frame) torques are taken about. */
  proxVec3 referencePoint;
  /* Tools: PROX_TOOL_FREE (default) or PROX_TOOL_CONSTRAINED. */
  proxToolMode toolMode;
  /* PROX_TOOL_CONSTRAINED: the coupling between device pose and proxy, at
   * the tool's reference point: N/m, N s/m, N m/rad, N m s/rad (> 0, the
   * dampings >= 0; defaults 1000, 2, 1, 0.002). */
  double couplingStiffness;
  double couplingDamping;
  double couplingAngularStiffness;
  double couplingAngularDamping;
  int32_t internalValue;
} proxBodyDef;

PROX_API proxBodyDef proxDefaultBodyDef(void);
/* Game thread. Create and destroy: also while the threads run
 * (docs/dynamic-scenes.md): a destroyed body's contacts fade from the force as
 * any lost contact does, and a new one is found by the next global search; a
 * tool destroyed while they run has its device's wrench faded to zero before
 * the call returns, and its device is called no more.
 * SetPose while they run: taken at the threads' next iteration; refused for
 * a tool a device holds. GetPose of a tool while they run: the pose the
 * haptic loop last read. */
PROX_API proxResult proxWorld_CreateBody(proxWorldId world, const proxBodyDef* def, proxBodyId* body);
PROX_API proxResult proxBody_Destroy(proxBodyId body);
/* Whether an id names a live body of a live world; as proxMesh_IsValid. */
PROX_API proxBool proxBody_IsValid(proxBodyId body);
PROX_API proxResult proxBody_SetPose(proxBodyId body, const proxPose* pose);
PROX_API proxResult proxBody_GetPose(proxBodyId body, proxPose* pose);
/* A tool's proxy: where it is rendered and where its contacts, distances and
 * intersections are computed. A constrained tool's proxy stays outside the
 * other bodies while proxBody_GetPose gives its device pose; a free tool's
 * proxy is its pose. Game thread; while the threads run, the haptic loop's
 * latest (its contacts are local tracking's, at the proxy that thread
 * verified, up to about a safety distance behind: docs/coupling.md). */
PROX_API proxResult proxBody_GetProxyPose(proxBodyId tool, proxPose* pose);

/* ---- stepping and results ---------------------------------------------------- */

/* Runs the whole method once, on the calling thread, deterministically
 * (PROX_ERROR_BUSY while the world's threads run): for
 * every tool, the bodies within the cutoff (a broadphase skips the rest), a
 * global search with its reduction per pair (skipped when no pose changed),
 * and the force and torque. For tests, benchmarks and engines that own their
 * threads. Game thread. */
PROX_API proxResult proxWorld_Step(proxWorldId world);

typedef struct proxContact {
  proxBodyId other;    /* the body the tool is near */
  proxVec3 pointTool;  /* closest point on the tool, world */
  proxVec3 pointOther; /* closest point on the other body, world */
  proxVec3 normal;     /* unit, from the other body to the tool */
  double distance;     /* m, > 0 */
  uint32_t triangleTool, triangleOther;
  int32_t featureTool, featureOther; /* 0 vertex, 1 edge, 2 face */
} proxContact;

/* The tool's contacts after the last step (while the threads run: local
 * tracking's latest): copies up to `capacity` into
 * `contacts` (may be NULL when capacity is 0) and sets *count to how many
 * there are; PROX_ERROR_CAPACITY when they did not all fit. Game thread. */
PROX_API proxResult proxBody_GetContacts(proxBodyId tool, proxContact* contacts, int32_t capacity,
                                         int32_t* count);

/* The patch a contact stands for (docs/patches.md): where the distance
 * field is flat, LMDs merge into the closest of them, which weighs their
 * count in the force. */
typedef struct proxContactPatch {
  int32_t count; /* LMDs the contact stands for, itself included: 1 when nothing merged into it */
  int32_t reserved;
  double extent; /* m: how far the farthest member's point on the tool is from the contact's */
  double spread; /* m: how much farther from the other body the farthest member is */
  double angle;  /* radians: the largest angle between a member's direction and the contact's */
} proxContactPatch;

/* proxBody_GetContacts with each contact's patch beside it, both from one
 * snapshot (so they agree while the threads run): patches[i] is the patch
 * of contacts[i]. Either array may be NULL when not wanted; capacity and
 * *count as in proxBody_GetContacts. Game thread. */
PROX_API proxResult proxBody_GetContactPatches(proxBodyId tool, proxContact* contacts,
                                               proxContactPatch* patches, int32_t capacity, int32_t* count);

typedef struct proxWrench {
  proxVec3 force;  /* N, on the tool, world frame */
  proxVec3 torque; /* N m, on the tool about its reference point, world frame */
  proxBool clipped;
} proxWrench;

/* The force and torque on a tool after the last step (while the threads
 * run: what the haptic loop last handed the device). Game thread. */
PROX_API proxResult proxBody_GetWrench(proxBodyId tool, proxWrench* wrench);

typedef struct proxPolylineInfo {
  proxBodyId other;   /* the body the tool's surface crosses */
  int32_t firstPoint; /* index of its first point in the points array */
  int32_t pointCount;
  proxBool closed; /* the last point joins the first */
  int32_t reserved;
} proxPolylineInfo;

/* Where the tool's surface crosses other bodies' surfaces, at their current
 * poses: computed on this call (intersections cost nothing unless asked
 * for). The points of every polyline go to `points` (world frame), one
 * proxPolylineInfo per polyline to `lines`; both counts are always set, and
 * when either array is too small what fits is copied and the result is
 * PROX_ERROR_CAPACITY. Pass capacities of 0 (and NULL arrays) to ask the
 * sizes. Coplanar overlaps are regions, not curves, and are not listed.
 * Game thread. */
PROX_API proxResult proxBody_GetIntersections(proxBodyId tool, proxVec3* points, int32_t pointCapacity,
                                              int32_t* pointCount, proxPolylineInfo* lines,
                                              int32_t lineCapacity, int32_t* lineCount);

typedef struct proxWorldStats {
  int32_t bodies, tools;
  int32_t pairsInRange;  /* tool-body pairs the broadphase kept in the last step */
  int32_t pairsSearched; /* ... of which ran a global search (the others had not moved) */
  int32_t contacts;      /* over all tools */
  int32_t candidates;    /* before reduction, over the pairs searched */
  double stepSeconds;
} proxWorldStats;

/* Game thread. */
PROX_API proxResult proxWorld_GetStats(proxWorldId world, proxWorldStats* stats);

/* Patches (docs/patches.md): after the reduction, LMDs whose closest points
 * on the tool lie within a radius of the closest one's and whose directions
 * agree within an angle merge into one contact, the closest, which weighs
 * the patch's count in the force. */
typedef struct proxPatchSettings {
  double radiusOverCutoff; /* the radius as a share of the world's cutoff, finite, >= 0; 0: no merging */
  double maxAngleDegrees;  /* in [0, 180] */
  /* members at most this share of the cutoff farther than the closest, finite, >= 0 */
  double maxSpreadOverCutoff;
} proxPatchSettings;

/* The world's patch rule (the default: radius = the cutoff, 5 degrees, a
 * spread of 0.2% of the cutoff). Game thread. */
PROX_API proxResult proxWorld_GetPatchSettings(proxWorldId world, proxPatchSettings* settings);
/* Changes it from the next proxWorld_Step on (PROX_ERROR_BUSY while the
 * threads run). Game thread. */
PROX_API proxResult proxWorld_SetPatchSettings(proxWorldId world, const proxPatchSettings* settings);

typedef struct proxPatchStats {
  /* Over the pairs searched in the last step (while the threads run: the
   * global thread's last search): */
  int32_t lmds;         /* LMDs after the reduction, before merging */
  int32_t patches;      /* contacts kept: one per patch */
  int32_t merged;       /* lmds - patches: LMDs folded into a closer one's patch */
  int32_t largestPatch; /* LMDs in the largest patch */
  /* Triangle pairs the global searches found crossing: an intersection of
   * the two bodies, reported here and never as contacts
   * (proxBody_GetIntersections traces it). */
  uint64_t intersectingPairs;
  int32_t intersectingBodies; /* pairs searched with any */
  /* Node pairs the bounded search cut (proxWorld_SetLeafBudget): each gave
   * one representative instead of all its LMDs, which are then not counted
   * in lmds (the force errs low there). 0 when every search stayed within
   * its budget. */
  int32_t cutNodePairs;
} proxPatchStats;

/* Game thread. */
PROX_API proxResult proxWorld_GetPatchStats(proxWorldId world, proxPatchStats* stats);

/* The bounded search (docs/patches.md): once one pair's precise global
 * search has tested this many triangle pairs, each node pair it meets whose
 * two bounding spheres are within half the patch radius (half the cutoff
 * with merging off) gives one representative, the first candidate of at
 * most 8 of its triangle pairs tried closest first, instead of every
 * triangle pair below it. Where surfaces run parallel or cross over a large
 * area, the work is then bounded by that area over the patch radius
 * squared, not by the triangle count. 0: no bound; the default is 50000.
 * Changes it from the next proxWorld_Step on (the pairs' cached results are
 * dropped); PROX_ERROR_BUSY while the threads run. Game thread. */
PROX_API proxResult proxWorld_SetLeafBudget(proxWorldId world, uint64_t leafPairs);
PROX_API proxResult proxWorld_GetLeafBudget(proxWorldId world, uint64_t* leafPairs);

#ifdef __cplusplus
}
#endif

/* Devices: the application's callbacks, the scripted and the streamed
 * device: declared here too, so this header stays the whole API. */
#include "proxima/devices.h"

/* The runtime's threads and their statistics, and the haptic loop's flight
 * recorder: declared here too, so this header stays the whole API. */
#include "proxima/threads.h"

/* What the proxima command-line tool and the benchmarks read beside the
 * core API: declared here too, so this header stays the whole API. */
#include "proxima/inspect.h"

#endif /* PROXIMA_PROXIMA_H */
