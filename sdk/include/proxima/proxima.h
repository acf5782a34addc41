/* Proxima: multi-contact proximity haptics. The C API.
 *
 * This header is the one public, stable interface of the SDK. It includes
 * its parts: proxima/base.h (the export macro, the version, results and
 * errors), proxima/types.h (ids, defs, what the calls hand back),
 * proxima/devices.h, proxima/threads.h and proxima/inspect.h (what the CLI
 * and the benchmarks read); here are the functions of worlds, meshes and
 * bodies. It is plain
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
 * they run, meshes and bodies still come and go and meshes deform
 * (docs/dynamic-scenes.md). Who owns what is in docs/threading.md.
 *
 * A newcomer's walkthrough is samples/hello/hello.c.
 */
#ifndef PROXIMA_PROXIMA_H
#define PROXIMA_PROXIMA_H

#include "proxima/base.h"
#include "proxima/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- world ----------------------------------------------------------------- */

/* Creates a world; the calling thread becomes its game thread. */
PROX_API proxResult proxCreateWorld(const proxWorldDef* def, proxWorldId* world);
/* Destroys a world and everything in it, stopping its threads first (the
 * devices fade out). Game thread. */
PROX_API proxResult proxWorld_Destroy(proxWorldId world);
/* Deprecated: proxWorld_Destroy under its old name (kept until at least 0.5). */
PROX_API proxResult proxDestroyWorld(proxWorldId world);
/* Whether an id names a live world. Any thread. */
PROX_API proxBool proxWorld_IsValid(proxWorldId world);

/* ---- meshes ---------------------------------------------------------------- */

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

/* Game thread. */
PROX_API proxResult proxMesh_GetRigInfo(proxMeshId mesh, proxRigInfo* info);

/* Skin `skin` in [0, skinCount). Game thread. */
PROX_API proxResult proxMesh_GetSkinInfo(proxMeshId mesh, int32_t skin, proxSkinInfo* info);

/* The animations, in the file's order (0 for a mesh without a rig). Game thread. */
PROX_API proxResult proxMesh_GetAnimationCount(proxMeshId mesh, int32_t* count);

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

/* The tool's contacts after the last step (while the threads run: local
 * tracking's latest): copies up to `capacity` into
 * `contacts` (may be NULL when capacity is 0) and sets *count to how many
 * there are; PROX_ERROR_CAPACITY when they did not all fit. Game thread. */
PROX_API proxResult proxBody_GetContacts(proxBodyId tool, proxContact* contacts, int32_t capacity,
                                         int32_t* count);

/* proxBody_GetContacts with each contact's patch beside it, both from one
 * snapshot (so they agree while the threads run): patches[i] is the patch
 * of contacts[i]. Either array may be NULL when not wanted; capacity and
 * *count as in proxBody_GetContacts. Game thread. */
PROX_API proxResult proxBody_GetContactPatches(proxBodyId tool, proxContact* contacts,
                                               proxContactPatch* patches, int32_t capacity, int32_t* count);

/* The force and torque on a tool after the last step (while the threads
 * run: what the haptic loop last handed the device). Game thread. */
PROX_API proxResult proxBody_GetWrench(proxBodyId tool, proxWrench* wrench);

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

/* Game thread. */
PROX_API proxResult proxWorld_GetStats(proxWorldId world, proxWorldStats* stats);

/* The world's patch rule (the default: radius = the cutoff, 5 degrees, a
 * spread of 0.2% of the cutoff). Game thread. */
PROX_API proxResult proxWorld_GetPatchSettings(proxWorldId world, proxPatchSettings* settings);
/* Changes it from the next proxWorld_Step on (PROX_ERROR_BUSY while the
 * threads run). Game thread. */
PROX_API proxResult proxWorld_SetPatchSettings(proxWorldId world, const proxPatchSettings* settings);

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
