// Patches and intersections: the patch rule, the bounded search's leaf
// budget, and what the last step merged, cut and found crossing
// (docs/patches.md).
#include "capi/common.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <string>

using namespace prox;
using namespace prox::capi;

extern "C" {

proxResult proxWorld_GetPatchSettings(proxWorldId world, proxPatchSettings* settings) {
  return guard("proxWorld_GetPatchSettings", [&] {
    need(settings, "settings");
    const PatchSettings& p = world_of(world).settings().patches;
    *settings = {p.radius_over_cutoff, p.max_angle_degrees, p.max_spread_over_cutoff};
  });
}

proxResult proxWorld_SetPatchSettings(proxWorldId world, const proxPatchSettings* settings) {
  return guard("proxWorld_SetPatchSettings", [&] {
    need(settings, "settings");
    runtime::World& w = world_of(world);
    need_finite(settings->radiusOverCutoff, "settings->radiusOverCutoff");
    need_finite(settings->maxAngleDegrees, "settings->maxAngleDegrees");
    if (settings->radiusOverCutoff < 0.0)
      fail(PROX_ERROR_INVALID_ARGUMENT, "settings->radiusOverCutoff must be >= 0 (0: no merging; it is " +
                                            std::to_string(settings->radiusOverCutoff) + ")");
    if (settings->maxAngleDegrees < 0.0 || settings->maxAngleDegrees > 180.0)
      fail(PROX_ERROR_INVALID_ARGUMENT, "settings->maxAngleDegrees must be in [0, 180] (it is " +
                                            std::to_string(settings->maxAngleDegrees) + ")");
    need_finite(settings->maxSpreadOverCutoff, "settings->maxSpreadOverCutoff");
    if (settings->maxSpreadOverCutoff < 0.0)
      fail(PROX_ERROR_INVALID_ARGUMENT, "settings->maxSpreadOverCutoff must be >= 0 (it is " +
                                            std::to_string(settings->maxSpreadOverCutoff) + ")");
    need_stopped(w);
    PatchSettings p = w.settings().patches;  // keeps the leaf budget
    p.radius_over_cutoff = settings->radiusOverCutoff;
    p.max_angle_degrees = settings->maxAngleDegrees;
    p.max_spread_over_cutoff = settings->maxSpreadOverCutoff;
    w.set_patches(p);
  });
}

proxResult proxWorld_SetLeafBudget(proxWorldId world, uint64_t leafPairs) {
  return guard("proxWorld_SetLeafBudget", [&] {
    runtime::World& w = world_of(world);
    need_stopped(w);
    PatchSettings p = w.settings().patches;
    p.leaf_budget = leafPairs;
    w.set_patches(p);
  });
}

proxResult proxWorld_GetLeafBudget(proxWorldId world, uint64_t* leafPairs) {
  return guard("proxWorld_GetLeafBudget", [&] {
    need(leafPairs, "leafPairs");
    *leafPairs = world_of(world).settings().patches.leaf_budget;
  });
}

proxResult proxWorld_GetPatchStats(proxWorldId world, proxPatchStats* stats) {
  return guard("proxWorld_GetPatchStats", [&] {
    need(stats, "stats");
    const runtime::StepStats s = world_of(world).stats();
    *stats = proxPatchStats{};
    stats->lmds = static_cast<int32_t>(s.patches.lmds_in);
    stats->patches = static_cast<int32_t>(s.patches.patches);
    stats->merged = static_cast<int32_t>(s.patches.merged);
    stats->largestPatch = static_cast<int32_t>(s.patches.largest);
    stats->intersectingPairs = s.search.intersecting_pairs;
    stats->intersectingBodies = s.intersecting_bodies;
    stats->cutNodePairs = static_cast<int32_t>(std::min<std::uint64_t>(s.search.cut_node_pairs, INT32_MAX));
  });
}

}  // extern "C"
