/* Proxima's inspection surface: what the proxima command-line tool and the
 * benchmarks report beside the core API (proxima/proxima.h, which includes
 * this header): the force presets, mesh and hierarchy figures, the search
 * and tracking statistics of the deterministic step, local tracking on its
 * own, intersection statistics and the exact minimum distance between two
 * bodies. The same conventions as proxima.h; stable like it. */
#ifndef PROXIMA_INSPECT_H
#define PROXIMA_INSPECT_H

#include "proxima/proxima.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- inspection ------------------------------------------------------------
 * What the proxima command-line tool and the benchmarks report: the force
 * presets, mesh and hierarchy figures, the search and tracking statistics of
 * the deterministic step, local tracking on its own, intersection statistics
 * and the exact minimum distance between two bodies. */

typedef enum proxForcePreset {
  PROX_FORCE_PRESET_HARD = 0, /* exponential; safety 0.3 mm, decay 0.3 mm, cutoff 5 mm: the default */
  PROX_FORCE_PRESET_SOFT = 1, /* linear; safety 2 mm, cutoff 10 mm */
  PROX_FORCE_PRESET_FORCE32 = 0x7FFFFFFF
} proxForcePreset;

/* The force settings and cutoff of a preset (docs/cli.md, "Force
 * settings"), for a proxWorldDef's `force` and `cutoff`. Any thread. */
PROX_API proxResult proxGetForcePreset(proxForcePreset preset, proxForceSettings* force, double* cutoff);
/* The preset at another cutoff (> 0, finite): a preset is a shape relative
 * to its cutoff, so its safety distance and decay length scale with it (the
 * maximum force and torque stay). The one place a preset is scaled: the
 * CLI's --cutoff and the bindings' worlds call it. Any thread. */
PROX_API proxResult proxGetForcePresetAt(proxForcePreset preset, double cutoff, proxForceSettings* force);

typedef struct proxMeshStats {
  uint32_t inputVertices;     /* as given, before welding */
  uint32_t inputTriangles;    /* as given, before dropping those that repeat a vertex */
  uint32_t zeroAreaTriangles; /* distinct vertices but collinear: kept */
  uint32_t hierarchyNodes;    /* the spatialized normal cone hierarchy (SNCH) */
  uint32_t hierarchyLeaves;
  uint32_t hierarchyDepth;     /* edges on the longest root-to-leaf path */
  uint32_t unboundedLeafCones; /* leaves whose normal cone holds every direction */
  uint32_t reserved;
  uint64_t hierarchyBytes; /* memory of the hierarchy */
  double hierarchySeconds; /* time it took to build */
} proxMeshStats;

/* More about a mesh than proxMesh_GetInfo: the input counts and the
 * hierarchy. Game thread. */
PROX_API proxResult proxMesh_GetStats(proxMeshId mesh, proxMeshStats* stats);

typedef struct proxSearchStats {
  int32_t pairsSearched; /* tool-body pairs whose global search ran in the last step */
  int32_t reserved;
  /* Summed over those pairs: */
  uint64_t nodePairs;            /* node pairs visited */
  uint64_t leafPairs;            /* triangle pairs reaching the leaf tests */
  uint64_t planeRejections;      /* precise: a triangle beyond the other's plane by more than the cutoff */
  uint64_t visibilityRejections; /* precise: culled by the visibility pre-test */
  uint64_t normalRejections;     /* original: culled by the G5 normal check */
  uint64_t distanceEvaluations;  /* exact distances (precise) or 7 x 7 samplings (original) */
  uint64_t candidates;           /* pairs the global searches output, before reduction */
  uint64_t reductionCacheHits;   /* tracking-cache hits of the reduction passes */
  double globalSeconds;          /* in the global searches */
  double reductionSeconds;       /* in the reduction passes that follow them */
} proxSearchStats;

/* The global searches of the last proxWorld_Step. Game thread. */
PROX_API proxResult proxWorld_GetSearchStats(proxWorldId world, proxSearchStats* stats);

/* Local tracking once, on the calling thread: the contacts of every pair the
 * last step kept are carried to the current poses (each walks to the closest
 * neighbouring triangle pair; those that leave the cutoff are dropped), and
 * each tool's force and torque recomputed. No new contact is found: that is
 * the global search's job (proxWorld_Step). What the local tracking thread
 * does between global searches, deterministically. Game thread. */
PROX_API proxResult proxWorld_Track(proxWorldId world);

typedef struct proxTrackStats {
  int32_t pairsTracked; /* tool-body pairs tracked by the last proxWorld_Track */
  int32_t contactsIn;   /* contacts before */
  int32_t contactsOut;  /* ... and after */
  int32_t reserved;
  uint64_t distanceEvaluations; /* exact triangle distances computed */
  uint64_t cacheHits;           /* ... and answered from the tracking cache instead */
  uint64_t moves;               /* walks to a closer neighbouring pair */
  double seconds;               /* the whole call */
} proxTrackStats;

/* The figures of the last proxWorld_Track (zeros before the first). Game thread. */
PROX_API proxResult proxWorld_GetTrackStats(proxWorldId world, proxTrackStats* stats);

typedef struct proxIntersectionStats {
  uint64_t trianglePairs;     /* tested: their bounding spheres overlap */
  uint64_t intersectingPairs; /* share a point (exact) */
  uint64_t coplanarPairs;     /* overlap in one plane: regions, not in the polylines */
  uint64_t segments;          /* of the polylines, before joining */
  double seconds;
} proxIntersectionStats;

/* The figures of the last proxBody_GetIntersections call on this tool,
 * summed over the bodies it crossed (zeros before the first). Game thread. */
PROX_API proxResult proxBody_GetIntersectionStats(proxBodyId tool, proxIntersectionStats* stats);

/* The exact minimum distance between two bodies' surfaces at their current
 * poses (any types, same world): *distance is set to it, 0 when they touch
 * or cross, or to -1 when they are farther apart than maxDistance (>= 0;
 * INFINITY for no bound; a tight bound makes the search faster). Computed
 * on this call. Game thread. */
PROX_API proxResult proxBody_GetDistance(proxBodyId a, proxBodyId b, double maxDistance, double* distance);

#ifdef __cplusplus
}
#endif

/* proxGetForcePreset(kind, cutoff): the preset at that cutoff, by value, as
 * proxGetForcePresetAt makes it; a zeroed proxForceSettings (which every def
 * refuses) when it fails, proxGetLastError saying why. And
 * proxGetForcePreset(kind, cutoff, &force), proxGetForcePresetAt by the same
 * name. In C++ two overloads; in C11 a macro choosing by the arguments, so
 * the three-argument form of 0.3, (preset, &force, &cutoff), still calls the
 * exported function (as (proxGetForcePreset)(...) always does). The
 * bindings' generators define PROX_NO_OVERLOADS. */
#ifndef PROX_NO_OVERLOADS
#ifdef __cplusplus
inline proxResult proxGetForcePreset(proxForcePreset kind, double cutoff, proxForceSettings* force) {
  return proxGetForcePresetAt(kind, cutoff, force);
}
inline proxForceSettings proxGetForcePreset(proxForcePreset kind, double cutoff) {
  proxForceSettings force = {};
  if (proxGetForcePresetAt(kind, cutoff, &force) != PROX_SUCCESS) force = proxForceSettings{};
  return force;
}
#elif defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L
static inline proxForceSettings proxGetForcePresetAtCutoff_(proxForcePreset kind, double cutoff) {
  proxForceSettings force = {0};
  if (proxGetForcePresetAt(kind, cutoff, &force) != PROX_SUCCESS) {
    proxForceSettings none = {0};
    force = none;
  }
  return force;
}
#define PROX_PICK_THIRD_(a, b, c, name, ...) name
#define PROX_FORCE_PRESET3_(kind, second, third) \
  _Generic((second), proxForceSettings*: (proxGetForcePreset), default: proxGetForcePresetAt)(kind, second, third)
#define proxGetForcePreset(...) \
  PROX_PICK_THIRD_(__VA_ARGS__, PROX_FORCE_PRESET3_, proxGetForcePresetAtCutoff_, ~)(__VA_ARGS__)
#endif
#endif /* PROX_NO_OVERLOADS */

#endif /* PROXIMA_INSPECT_H */
