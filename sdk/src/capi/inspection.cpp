// What the CLI and the benchmarks inspect: presets, mesh and search statistics, tracking alone, distances.
#include "capi/common.h"

#include "runtime/threads.h"

using namespace prox;
using namespace prox::capi;

extern "C" {

namespace {

ForceSettings preset_of(proxForcePreset preset) {
  switch (enum_value(preset)) {
    case PROX_FORCE_PRESET_HARD:
      return hard_force_settings();
    case PROX_FORCE_PRESET_SOFT:
      return soft_force_settings();
    default:
      fail(PROX_ERROR_INVALID_ARGUMENT, "preset is not a proxForcePreset");
  }
}

proxForceSettings to_c(const ForceSettings& f) {
  return {f.curve == ForceCurve::Linear ? PROX_FORCE_LINEAR : PROX_FORCE_EXPONENTIAL, f.max_force, f.max_torque,
          f.safety_distance, f.decay_length};
}

}  // namespace

proxResult proxGetForcePreset(proxForcePreset preset, proxForceSettings* force, double* cutoff) {
  return guard("proxGetForcePreset", [&] {
    need(force, "force");
    need(cutoff, "cutoff");
    const ForceSettings f = preset_of(preset);
    *force = to_c(f);
    *cutoff = f.cutoff;
  });
}

proxResult proxGetForcePresetAt(proxForcePreset preset, double cutoff, proxForceSettings* force) {
  return guard("proxGetForcePresetAt", [&] {
    need(force, "force");
    need_positive(cutoff, "cutoff");
    ForceSettings f = preset_of(preset);
    const double k = cutoff / f.cutoff;
    f.safety_distance *= k;
    f.decay_length *= k;
    *force = to_c(f);
  });
}

proxResult proxMesh_GetStats(proxMeshId mesh, proxMeshStats* stats) {
  return guard("proxMesh_GetStats", [&] {
    need(stats, "stats");
    runtime::World* w = nullptr;
    const runtime::Handle h = mesh_of(mesh, w);
    const MeshStats& m = w->mesh(h).stats();
    const SnchStats& t = w->snch(h).stats();
    *stats = proxMeshStats{};
    stats->inputVertices = m.input_vertices;
    stats->inputTriangles = m.input_triangles;
    stats->zeroAreaTriangles = m.zero_area_triangles;
    stats->hierarchyNodes = t.nodes;
    stats->hierarchyLeaves = t.leaves;
    stats->hierarchyDepth = t.depth;
    stats->unboundedLeafCones = t.unbounded_leaves;
    stats->hierarchyBytes = t.memory_bytes;
    stats->hierarchySeconds = t.build_seconds;
  });
}

proxResult proxWorld_GetSearchStats(proxWorldId world, proxSearchStats* stats) {
  return guard("proxWorld_GetSearchStats", [&] {
    need(stats, "stats");
    const runtime::StepStats s = world_of(world).stats();
    *stats = proxSearchStats{};
    stats->pairsSearched = s.pairs_searched;
    stats->nodePairs = s.search.node_pairs;
    stats->leafPairs = s.search.leaf_pairs;
    stats->planeRejections = s.search.plane_rejections;
    stats->visibilityRejections = s.search.visibility_rejections;
    stats->normalRejections = s.search.normal_rejections;
    stats->distanceEvaluations = s.search.distance_evaluations;
    stats->candidates = static_cast<uint64_t>(s.candidates);
    stats->reductionCacheHits = s.reduction_cache_hits;
    stats->globalSeconds = s.search.seconds;
    stats->reductionSeconds = s.reduction_seconds;
  });
}

proxResult proxWorld_Track(proxWorldId world) {
  return guard("proxWorld_Track", [&] {
    runtime::World& w = world_of(world);
    need_stopped(w);
    w.track();
  });
}

proxResult proxWorld_GetTrackStats(proxWorldId world, proxTrackStats* stats) {
  return guard("proxWorld_GetTrackStats", [&] {
    need(stats, "stats");
    const runtime::TrackStats& s = world_of(world).track_stats();
    *stats = proxTrackStats{};
    stats->pairsTracked = s.pairs;
    stats->contactsIn = static_cast<int32_t>(s.local.pairs_in);
    stats->contactsOut = static_cast<int32_t>(s.local.pairs_out);
    stats->distanceEvaluations = s.local.distance_evaluations;
    stats->cacheHits = s.local.cache_hits;
    stats->moves = s.local.steps;
    stats->seconds = s.seconds;
  });
}

proxResult proxBody_GetIntersectionStats(proxBodyId tool, proxIntersectionStats* stats) {
  return guard("proxBody_GetIntersectionStats", [&] {
    need(stats, "stats");
    runtime::World* w = nullptr;
    const runtime::Handle h = tool_of(tool, w);
    const PolylineStats& s = w->intersection_stats(h);
    *stats = {s.triangle_pairs, s.intersecting_pairs, s.coplanar_pairs, s.segments, s.seconds};
  });
}

proxResult proxBody_GetDistance(proxBodyId a, proxBodyId b, double maxDistance, double* distance) {
  return guard("proxBody_GetDistance", [&] {
    need(distance, "distance");
    *distance = -1.0;
    runtime::World* wa = nullptr;
    runtime::World* wb = nullptr;
    const runtime::Handle ha = body_of(a, wa, "a");
    const runtime::Handle hb = body_of(b, wb, "b");
    if (wa != wb) fail(PROX_ERROR_INVALID_HANDLE, "a and b belong to different worlds");
    if (ha.index == hb.index) fail(PROX_ERROR_INVALID_ARGUMENT, "a and b are the same body");
    if (std::isnan(maxDistance) || maxDistance < 0.0)
      fail(PROX_ERROR_INVALID_ARGUMENT,
           "maxDistance must be >= 0 (INFINITY for no bound; it is " + std::to_string(maxDistance) + ")");
    const double d = wa->distance(ha, hb, maxDistance);
    // The search may end on a pair beyond the bound: that is "farther" too.
    *distance = d <= maxDistance ? d : -1.0;
  });
}

}  // extern "C"
