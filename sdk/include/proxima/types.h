/* Proxima's C API, its types: ids, geometry, the defs of worlds, meshes and
 * bodies with the functions that give their defaults, and what the calls
 * hand back (contacts, wrenches, statistics). Plain C11 on its own (it
 * includes proxima/base.h); the functions that use them are in
 * proxima/proxima.h, the devices' and threads' own types in
 * proxima/devices.h and proxima/threads.h. */
#ifndef PROXIMA_TYPES_H
#define PROXIMA_TYPES_H

#include "proxima/base.h"

#ifdef __cplusplus
extern "C" {
#endif

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
  int32_t apiVersion; /* PROX_API_VERSION, set by proxDefaultWorldDef() */
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

/* ---- meshes ---------------------------------------------------------------- */

typedef struct proxMeshDef {
  int32_t apiVersion; /* PROX_API_VERSION, set by proxDefaultMeshDef() */
  const double* positions; /* x, y, z per vertex */
  uint32_t vertexCount;
  const uint32_t* indices; /* three per triangle, counter-clockwise seen from outside */
  uint32_t triangleCount;
  int32_t internalValue;
} proxMeshDef;

PROX_API proxMeshDef proxDefaultMeshDef(void);

typedef struct proxMeshInfo {
  uint32_t triangleCount; /* after dropping triangles that repeat a vertex */
  uint32_t vertexCount;   /* after welding */
  uint32_t droppedTriangles;
  uint32_t boundaryEdges;
  uint32_t nonManifoldEdges;
  proxVec3 boundsMin, boundsMax; /* in the mesh's own frame */
} proxMeshInfo;

/* ---- glTF skins, morph targets and animation ------------------------------ */

typedef struct proxRigInfo {
  int32_t skinCount;
  int32_t jointCount;       /* over every skin */
  int32_t morphWeightCount; /* what proxMesh_SetMorphWeights takes */
  int32_t animationCount;
} proxRigInfo;

typedef struct proxSkinInfo {
  char name[64]; /* NUL-terminated, cut to 63 bytes; "" when the file names none */
  int32_t jointCount;
  int32_t reserved;
} proxSkinInfo;

typedef struct proxAnimationInfo {
  char name[64];   /* NUL-terminated, cut to 63 bytes; "animation N" when the file names none */
  double duration; /* seconds: the last keyframe's time (glTF time starts at 0) */
  double start;    /* seconds: the first keyframe's time */
  int32_t channelCount;
  int32_t reserved;
} proxAnimationInfo;

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
  int32_t apiVersion; /* PROX_API_VERSION, set by proxDefaultBodyDef() */
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

/* ---- stepping and results ---------------------------------------------------- */

typedef struct proxContact {
  proxBodyId other;    /* the body the tool is near */
  proxVec3 pointTool;  /* closest point on the tool, world */
  proxVec3 pointOther; /* closest point on the other body, world */
  proxVec3 normal;     /* unit, from the other body to the tool */
  double distance;     /* m, > 0 */
  uint32_t triangleTool, triangleOther;
  int32_t featureTool, featureOther; /* 0 vertex, 1 edge, 2 face */
} proxContact;

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

typedef struct proxWrench {
  proxVec3 force;  /* N, on the tool, world frame */
  proxVec3 torque; /* N m, on the tool about its reference point, world frame */
  proxBool clipped;
} proxWrench;

typedef struct proxPolylineInfo {
  proxBodyId other;   /* the body the tool's surface crosses */
  int32_t firstPoint; /* index of its first point in the points array */
  int32_t pointCount;
  proxBool closed; /* the last point joins the first */
  int32_t reserved;
} proxPolylineInfo;

typedef struct proxWorldStats {
  int32_t bodies, tools;
  int32_t pairsInRange;  /* tool-body pairs the broadphase kept in the last step */
  int32_t pairsSearched; /* ... of which ran a global search (the others had not moved) */
  int32_t contacts;      /* over all tools */
  int32_t candidates;    /* before reduction, over the pairs searched */
  double stepSeconds;
} proxWorldStats;

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

#ifdef __cplusplus
}
#endif

#endif /* PROXIMA_TYPES_H */
