#include "scene_run.h"
#include "common/worker_pool.h"

#include "contact/global_search.h"
#include "contact/proximity.h"
#include "runtime/haptic.h"
#ifdef PROX_BENCH_WITH_COAL
#include "coal_peer.h"
#endif
#ifdef PROX_BENCH_WITH_FCL
#include "fcl_peer.h"
#endif

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace prox::bench {

namespace {

// How many of `reference` have a match in `found` and how many of `found` have
// one in `reference`: closest points on both sides within `tolerance`.
std::pair<int, int> match(const std::vector<LmdPair>& reference, const std::vector<LmdPair>& found,
                          double tolerance) {
  auto same = [tolerance](const LmdPair& x, const LmdPair& y) {
    return glm::length(x.point_a - y.point_a) <= tolerance && glm::length(x.point_b - y.point_b) <= tolerance;
  };
  int recalled = 0, confirmed = 0;
  for (const LmdPair& r : reference)
    recalled += std::any_of(found.begin(), found.end(), [&](const LmdPair& f) { return same(r, f); });
  for (const LmdPair& f : found)
    confirmed +=
        std::any_of(reference.begin(), reference.end(), [&](const LmdPair& r) { return same(r, f); });
  return {recalled, confirmed};
}

// Median time, in nanoseconds, of what the haptic loop computes each tick
// from a snapshot of `lmds` tracked at `pose`: the contacts re-evaluated at
// the current pose (runtime::evaluate_contacts, here the same pose) and the
// safety gate.
double time_force(const ForceSettings& force, const std::vector<LmdPair>& lmds, const Pose& pose,
                  const Vec3& reference_local, int batches) {
  runtime::ContactSnapshot snapshot;
  const Pose to_local = pose.inverse();
  runtime::HapticContact c;
  for (const LmdPair& p : lmds)
    if (runtime::to_haptic_contact(p, to_local, c)) snapshot.contacts.push_back(c);
  snapshot.tool_pose = pose;
  runtime::SafetyFilter gate;
  std::vector<double> ns;
  volatile double sink = 0.0;
  for (int b = 0; b < batches; ++b) {
    const auto start = Clock::now();
    for (int i = 0; i < kForceBatch; ++i)
      sink =
          sink +
          gate.step(runtime::evaluate_contacts(force, snapshot, pose, reference_local), true, 1e-3).force.x;
    ns.push_back(seconds_since(start) * 1e9 / kForceBatch);
  }
  return median(ns);
}

struct MethodState {
  Method method;
  std::vector<LmdPair> tracked;  // the previous step's set
  std::vector<LmdPair> current;  // this step's
  std::vector<LmdPair> local;    // the previous set updated to this pose
};

}  // namespace

ForceSettings scene_force(const Scene& scene, const Model& a, const Model& b) {
  ForceSettings f = scene.soft ? soft_force_settings() : hard_force_settings();
  if (scene.cutoff_over_size > 0.0) {
    const double k = scene.cutoff_over_size * std::max(a.size, b.size) / f.cutoff;
    f.cutoff *= k, f.safety_distance *= k, f.decay_length *= k;
  }
  return f;
}

SceneRun run_scene(const Scene& scene, const Model& a, const Model& b, int poses, int reference_every,
                   const Options& opt, CoalPeer* coal) {
  SceneRun run;
  run.scene = &scene;
  run.a = &a, run.b = &b;
  run.force = scene_force(scene, a, b);
  const double cutoff = run.force.cutoff;
  run.far = scene.cutoff_over_size > 0.0 ? kCadFarOverCutoff * cutoff : scene.far;
  run.near = scene.cutoff_over_size > 0.0 ? 0.1 * cutoff : scene.near;
  const auto start = Clock::now();
  run.path = make_path(scene, run.far, run.near, a, b, poses);
  run.path_seconds = seconds_since(start);
  run.reference_every = reference_every;
  const double tolerance = 1e-9 * std::max(a.size, b.size);
  const double loose_tolerance = kLooseMatchOverCutoff * cutoff;

  PairState state;
  MethodState methods[2] = {{Method::Precise, {}, {}, {}}, {Method::Original, {}, {}, {}}};
  std::vector<LmdPair> scratch;
  WorkerPool pool(static_cast<unsigned>(std::max(1, opt.workers)));
#ifndef PROX_BENCH_WITH_COAL
  (void)coal;
#endif
  for (std::size_t i = 0; i < run.path.size(); ++i) {
    const PosePoint& p = run.path[i];
    PairQuery q = make_query(a, b, p.pose, cutoff);
    q.pool = &pool;
    const Vec3 reference_point = p.pose.apply(b.box_centre);
    Row base;
    base.step = static_cast<int>(i);
    base.s = p.s, base.x = p.x, base.target_gap = p.target_gap;
    const std::size_t first_row = run.rows.size();
    // With --workers N, the precise global search on one thread too, at the
    // same pose, before the split one on even poses and after it on odd
    // ones (neither always finds the caches warm): the split's speed-up
    // measured side by side, pose by pose.
    const auto serial_search = [&] {
      if (opt.workers <= 1) return;
      Row sr = base;
      sr.method = "precise-1";
      PairQuery serial = q;
      serial.pool = nullptr;
      std::vector<LmdPair> found;
      GlobalSearchStats stats;
      global_search_precise(serial, found, stats);
      sr.global_ms = sr.query_ms = stats.seconds * 1e3;
      sr.node_pairs = double(stats.node_pairs), sr.leaf_pairs = double(stats.leaf_pairs);
      run.rows.push_back(sr);
    };
    if (i % 2 == 0) serial_search();

    for (MethodState& ms : methods) {
      Row r = base;
      r.method = method_name(ms.method);
      LocalTracker& tracker = ms.method == Method::Precise ? state.precise : state.original;
      // The local thread: the previous step's set carried to this pose.
      std::vector<double> local_times;
      LocalTrackingStats local;
      for (int k = 0; k < std::max(1, opt.local_reps); ++k) {
        ms.local = ms.tracked;
        local = LocalTrackingStats{};
        tracker.update(q, ms.local, local);
        local_times.push_back(local.seconds);
      }
      r.local_ms = median(local_times) * 1e3;
      r.local_in = local.pairs_in, r.local_out = local.pairs_out;
      r.local_cache_hits = double(local.cache_hits);
      r.local_distance_evaluations = double(local.distance_evaluations);
      // The global thread: search and reduction.
      ProximityResult res;
      find_lmds(q, ms.method, state, res);
      r.global_ms = res.global.seconds * 1e3;
      r.reduction_ms = (res.reduction[0].seconds + res.reduction[1].seconds) * 1e3;
      r.query_ms = r.global_ms + r.reduction_ms;
      r.candidates = res.candidates;
      r.lmds = double(res.lmds.size());
      r.node_pairs = double(res.global.node_pairs), r.leaf_pairs = double(res.global.leaf_pairs);
      r.visibility_rejections = double(res.global.visibility_rejections);
      r.normal_rejections = double(res.global.normal_rejections);
      r.distance_evaluations = double(res.global.distance_evaluations);
      r.reduction_cache_hits = double(res.reduction[0].cache_hits + res.reduction[1].cache_hits);
      r.min_distance = res.min_distance >= 0.0 ? res.min_distance : kNaN;
      // The haptic loop: the force from the current set.
      const Wrench w = tool_wrench(run.force, res.lmds, reference_point);
      r.force = w.force, r.torque = w.torque;
      r.force_eval_ns = time_force(run.force, res.lmds, p.pose, b.box_centre, opt.force_reps);
      ms.current = std::move(res.lmds);
      run.rows.push_back(r);
    }

    if (i % 2 == 1) serial_search();

    // Proxima's exact minimum distance: the single-pair query FCL answers.
    Row md = base;
    md.method = "min-distance";
    auto t0 = Clock::now();
    const double exact = minimum_distance(q, kInf);
    md.query_ms = seconds_since(t0) * 1e3;
    md.min_distance = exact;
    run.rows.push_back(md);

#ifdef PROX_BENCH_WITH_FCL
    {
      Row fr = base;
      fr.method = "fcl";
      const FclDistance f = fcl_distance(*a.fcl, *b.fcl, p.pose);
      const double d = f.distance;
      fr.query_ms = f.seconds * 1e3;
      fr.min_distance = d;
      fr.min_distance_error = std::abs(d - exact);  // agreement with Proxima's exact minimum
      run.rows.push_back(fr);
    }
#endif
#ifdef PROX_BENCH_WITH_COAL
    {
      // Every triangle pair within the cutoff: the pairs go in `candidates`.
      Row cr = base;
      cr.method = "coal";
      const CoalMargin c = coal->margin_collide(a.coal, b.coal, p.pose, cutoff);
      cr.query_ms = c.seconds * 1e3;
      cr.candidates = double(c.pairs);
      run.rows.push_back(cr);
    }
#endif

    const bool with_reference = reference_every > 0 && (i % static_cast<std::size_t>(reference_every) == 0 ||
                                                        i + 1 == run.path.size());
    if (with_reference) {
      Row rr = base;
      rr.method = "reference";
      ProximityResult ref;
      t0 = Clock::now();
      find_lmds(q, Method::Reference, state, ref);
      rr.query_ms = seconds_since(t0) * 1e3;
      rr.lmds = double(ref.lmds.size());
      rr.min_distance = ref.min_distance >= 0.0 ? ref.min_distance : kNaN;
      const Wrench w = tool_wrench(run.force, ref.lmds, reference_point);
      rr.force = w.force, rr.torque = w.torque;
      run.rows.push_back(rr);
      // Errors of this step's rows against the reference.
      for (std::size_t k = first_row; k < run.rows.size(); ++k) {
        Row& r = run.rows[k];
        if (r.method != "precise" && r.method != "original" && r.method != "min-distance") continue;
        if (r.method == "min-distance") {
          if (!ref.lmds.empty()) r.min_distance_error = std::abs(r.min_distance - ref.min_distance);
          continue;
        }
        const MethodState& ms = methods[r.method == "precise" ? 0 : 1];
        r.ref_lmds = double(ref.lmds.size());
        const auto strict = match(ref.lmds, ms.current, tolerance);
        const auto loose = match(ref.lmds, ms.current, loose_tolerance);
        r.recalled = strict.first, r.confirmed = strict.second;
        r.recalled_loose = loose.first, r.confirmed_loose = loose.second;
        if (!ref.lmds.empty() && !ms.current.empty())
          r.min_distance_error = std::abs(r.min_distance - ref.min_distance);
        r.force_error = glm::length(r.force - w.force);
        r.torque_error = glm::length(r.torque - w.torque);
        const auto local = match(ref.lmds, ms.local, tolerance);
        r.local_recalled = local.first, r.local_confirmed = local.second;
      }
    }
    for (std::size_t k = first_row; k < run.rows.size(); ++k) run.rows[k].exact_min = exact;
    for (MethodState& ms : methods) ms.tracked = ms.current;
  }
  run.seconds = seconds_since(start);
  return run;
}

}  // namespace prox::bench
