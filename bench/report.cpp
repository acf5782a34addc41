#include "report.h"

#ifdef PROX_BENCH_WITH_FCL
#include "fcl_peer.h"
#endif

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>

namespace prox::bench {

const char* const kPeerNote =
    "FCL's distance query returns one closest pair per pose; Proxima returns the whole LMD set (every local "
    "minimum within the cutoff). min-distance is Proxima's own single-pair query (minimum_distance), the "
    "like-for-like peer of FCL's.";

namespace {

using Column = std::pair<const char*, std::function<double(const Row&)>>;
const std::vector<Column>& columns() {
  static const std::vector<Column> c = {
      {"s", [](const Row& r) { return r.s; }},
      {"x", [](const Row& r) { return r.x; }},
      {"target_gap", [](const Row& r) { return r.target_gap; }},
      {"exact_min_distance", [](const Row& r) { return r.exact_min; }},
      {"query_ms", [](const Row& r) { return r.query_ms; }},
      {"global_ms", [](const Row& r) { return r.global_ms; }},
      {"reduction_ms", [](const Row& r) { return r.reduction_ms; }},
      {"local_ms", [](const Row& r) { return r.local_ms; }},
      {"local_in", [](const Row& r) { return r.local_in; }},
      {"local_out", [](const Row& r) { return r.local_out; }},
      {"local_cache_hits", [](const Row& r) { return r.local_cache_hits; }},
      {"local_distance_evaluations", [](const Row& r) { return r.local_distance_evaluations; }},
      {"force_eval_ns", [](const Row& r) { return r.force_eval_ns; }},
      {"candidates", [](const Row& r) { return r.candidates; }},
      {"lmds", [](const Row& r) { return r.lmds; }},
      {"node_pairs", [](const Row& r) { return r.node_pairs; }},
      {"leaf_pairs", [](const Row& r) { return r.leaf_pairs; }},
      {"visibility_rejections", [](const Row& r) { return r.visibility_rejections; }},
      {"normal_rejections", [](const Row& r) { return r.normal_rejections; }},
      {"distance_evaluations", [](const Row& r) { return r.distance_evaluations; }},
      {"reduction_cache_hits", [](const Row& r) { return r.reduction_cache_hits; }},
      {"min_distance", [](const Row& r) { return r.min_distance; }},
      {"force_x", [](const Row& r) { return r.force.x; }},
      {"force_y", [](const Row& r) { return r.force.y; }},
      {"force_z", [](const Row& r) { return r.force.z; }},
      {"force", [](const Row& r) { return glm::length(r.force); }},
      {"torque_x", [](const Row& r) { return r.torque.x; }},
      {"torque_y", [](const Row& r) { return r.torque.y; }},
      {"torque_z", [](const Row& r) { return r.torque.z; }},
      {"torque", [](const Row& r) { return glm::length(r.torque); }},
      {"ref_lmds", [](const Row& r) { return r.ref_lmds; }},
      {"recalled", [](const Row& r) { return r.recalled; }},
      {"confirmed", [](const Row& r) { return r.confirmed; }},
      {"recalled_2mm", [](const Row& r) { return r.recalled_loose; }},
      {"confirmed_2mm", [](const Row& r) { return r.confirmed_loose; }},
      {"min_distance_error", [](const Row& r) { return r.min_distance_error; }},
      {"force_error", [](const Row& r) { return r.force_error; }},
      {"torque_error", [](const Row& r) { return r.torque_error; }},
      {"local_recalled", [](const Row& r) { return r.local_recalled; }},
      {"local_confirmed", [](const Row& r) { return r.local_confirmed; }},
  };
  return c;
}

std::vector<const Row*> rows_of(const SceneRun& run, const std::string& method, bool contact_only) {
  std::vector<const Row*> out;
  for (const Row& r : run.rows)
    if (r.method == method && (!contact_only || r.exact_min <= run.force.cutoff)) out.push_back(&r);
  return out;
}

std::vector<double> values(const std::vector<const Row*>& rows, double Row::*field) {
  std::vector<double> v;
  for (const Row* r : rows) v.push_back(r->*field);
  return v;
}

void distribution(Json& j, const std::string& name, const std::vector<double>& v) {
  j.key(name).begin_object();
  j.field("median", median(v)).field("p99", percentile(v, 0.99)).field("max", maximum(v));
  j.end_object();
}

// Median, p99 and max of a field over all poses and over the poses in contact
// (exact minimum distance within the cutoff).
void both(Json& j, const SceneRun& run, const std::string& method, const std::string& name,
          double Row::*field) {
  j.key(name).begin_object();
  distribution(j, "all", values(rows_of(run, method, false), field));
  distribution(j, "contact", values(rows_of(run, method, true), field));
  j.end_object();
}

struct Accuracy {
  long long reference = 0, found = 0, recalled = 0, confirmed = 0, recalled_loose = 0, confirmed_loose = 0;
  long long local_found = 0, local_recalled = 0, local_confirmed = 0, poses = 0, missed_minimum = 0;
  double min_error = kNaN, force_error = kNaN, torque_error = kNaN, force_error_median = kNaN;
};

Accuracy accuracy(const SceneRun& run, const std::string& method) {
  Accuracy a;
  std::vector<double> force_errors;
  for (const Row* r : rows_of(run, method, false)) {
    if (!std::isfinite(r->ref_lmds)) continue;
    ++a.poses;
    a.reference += static_cast<long long>(r->ref_lmds);
    a.found += static_cast<long long>(r->lmds);
    a.recalled += static_cast<long long>(r->recalled);
    a.confirmed += static_cast<long long>(r->confirmed);
    a.recalled_loose += static_cast<long long>(r->recalled_loose);
    a.confirmed_loose += static_cast<long long>(r->confirmed_loose);
    if (std::isfinite(r->local_recalled)) {
      a.local_found += static_cast<long long>(r->local_out);
      a.local_recalled += static_cast<long long>(r->local_recalled);
      a.local_confirmed += static_cast<long long>(r->local_confirmed);
    }
    if (r->ref_lmds > 0 && !(r->lmds > 0)) ++a.missed_minimum;
    if (std::isfinite(r->min_distance_error) && !(r->min_distance_error <= a.min_error))
      a.min_error = r->min_distance_error;
    if (std::isfinite(r->force_error) && !(r->force_error <= a.force_error)) a.force_error = r->force_error;
    if (std::isfinite(r->torque_error) && !(r->torque_error <= a.torque_error))
      a.torque_error = r->torque_error;
    force_errors.push_back(r->force_error);
  }
  a.force_error_median = median(force_errors);
  return a;
}

double fraction(long long part, long long whole) { return whole > 0 ? double(part) / double(whole) : kNaN; }

struct Smoothness {
  double max_jump = kNaN, total_variation = kNaN, max_torque_jump = kNaN;
};

Smoothness smoothness(const std::vector<const Row*>& rows) {
  Smoothness s;
  const Row* previous = nullptr;
  for (const Row* r : rows) {
    if (!std::isfinite(r->force.x)) continue;
    if (previous) {
      const double jump = glm::length(r->force - previous->force);
      const double tjump = glm::length(r->torque - previous->torque);
      s.max_jump = std::isfinite(s.max_jump) ? std::max(s.max_jump, jump) : jump;
      s.total_variation = (std::isfinite(s.total_variation) ? s.total_variation : 0.0) + jump;
      s.max_torque_jump = std::isfinite(s.max_torque_jump) ? std::max(s.max_torque_jump, tjump) : tjump;
    }
    previous = r;
  }
  return s;
}

// Per-pose ratio of one method's query time to another's.
std::vector<double> pose_ratios(const SceneRun& run, const std::string& num, const std::string& den,
                                bool contact_only) {
  const auto a = rows_of(run, num, contact_only), b = rows_of(run, den, contact_only);
  std::vector<double> r;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    r.push_back(ratio(a[i]->query_ms, b[i]->query_ms));
  return r;
}

double reduction_ratio(const std::vector<const Row*>& rows, bool maximum_only) {
  double total_c = 0.0, total_l = 0.0, best = kNaN;
  for (const Row* r : rows) {
    if (!(r->lmds > 0)) continue;
    total_c += r->candidates, total_l += r->lmds;
    const double q = r->candidates / r->lmds;
    if (!(q <= best)) best = q;
  }
  return maximum_only ? best : ratio(total_c, total_l);
}

void mesh_json(Json& j, const Model& model, const char* used_as) {
  j.begin_object();
  j.field("name", model.name).field("used_as", used_as);
  j.field("triangles", static_cast<long long>(model.mesh.triangle_count()));
  j.field("vertices", static_cast<long long>(model.mesh.vertex_count()));
  j.field("size", model.size);
  j.field("max_over_median_triangle_area", model.max_over_median_area);
  const SnchStats& st = model.snch->stats();
  j.field("snch_nodes", static_cast<long long>(st.nodes))
      .field("snch_depth", static_cast<long long>(st.depth));
  j.field("snch_unbounded_leaves", static_cast<long long>(st.unbounded_leaves));
  j.field("snch_build_ms", median(model.snch_build_seconds) * 1e3);
  j.field("snch_memory_bytes", st.memory_bytes);
#ifdef PROX_BENCH_WITH_FCL
  j.field("fcl_build_ms", median(model.fcl_build_seconds) * 1e3);
  j.field("fcl_memory_bytes", model.fcl_memory_bytes);
#endif
#ifdef PROX_BENCH_WITH_COAL
  j.field("coal_build_ms", median(model.coal_build_seconds) * 1e3);
#endif
  j.end_object();
}

}  // namespace

std::string summary_json(const SceneRun& run, const Options& opt) {
  const Scene& sc = *run.scene;
  const Model& model = *run.b;
  const double size = std::max(run.a->size, run.b->size);
  Json j;
  j.begin_object();
  j.field("scene", sc.name).field("description", sc.description).field("group", sc.group);
  if (!sc.same_as.empty()) j.field("same_as", sc.same_as);
  j.key("path").begin_object();
  j.field("kind", sc.kind == PathKind::Translate ? "translate" : "rotate");
  if (sc.kind == PathKind::Translate) {
    j.key("direction").vec3(sc.direction);
    j.field("b_box_centre_on_a", sc.centre_b_on_a);
  }
  j.field("far_gap", run.far).field("near_gap", run.near).field("poses", static_cast<int>(run.path.size()));
  if (sc.kind == PathKind::Rotate) {
    j.key("axis").vec3(glm::normalize(Vec3(0.3, 1.0, 0.2)));
    j.field("angle_deg", 90.0);
    j.key("centroid").vec3(model.centroid);
  }
  j.field("x_first", run.path.front().x).field("x_last", run.path.back().x);
  j.field("seconds_to_build", run.path_seconds);
  j.end_object();
  j.key("force_settings").begin_object();
  j.field("curve", run.force.curve == ForceCurve::Exponential ? "exponential" : "linear");
  j.field("max_force", run.force.max_force).field("max_torque", run.force.max_torque);
  j.field("safety_distance", run.force.safety_distance).field("cutoff", run.force.cutoff);
  j.field("decay_length", run.force.decay_length);
  j.end_object();
  j.field("cutoff", run.force.cutoff);
  j.field("reference_every", run.reference_every).field("local_reps", opt.local_reps);
  j.field("force_batches", opt.force_reps).field("force_batch_calls", kForceBatch);
  j.field("contact_poses", static_cast<int>(rows_of(run, "precise", true).size()));
  j.field("reference_poses", static_cast<int>(accuracy(run, "precise").poses));
  j.field("seconds", run.seconds);
#ifdef PROX_BENCH_WITH_FCL
  j.field("fcl", true).field("fcl_version", fcl_version());
#else
  j.field("fcl", false);
#endif
#ifdef PROX_BENCH_WITH_COAL
  j.field("coal", true).field("coal_version", opt.coal_version);
#else
  j.field("coal", false);
#endif
  j.field("peer_note", kPeerNote);

  j.key("meshes").begin_array();
  if (run.a == run.b) {
    mesh_json(j, *run.a, "A and B");
  } else {
    mesh_json(j, *run.a, "A");
    mesh_json(j, *run.b, "B");
  }
  j.end_array();

  const double tolerance = 1e-9 * size;
  j.field("size", size).field("loose_match_tolerance", kLooseMatchOverCutoff * run.force.cutoff);
  j.key("methods").begin_object();
  for (const char* m : {"precise", "original"}) {
    j.key(m).begin_object();
    both(j, run, m, "query_ms", &Row::query_ms);
    both(j, run, m, "global_ms", &Row::global_ms);
    both(j, run, m, "reduction_ms", &Row::reduction_ms);
    both(j, run, m, "local_ms", &Row::local_ms);
    both(j, run, m, "force_eval_ns", &Row::force_eval_ns);
    both(j, run, m, "candidates", &Row::candidates);
    both(j, run, m, "lmds", &Row::lmds);
    both(j, run, m, "node_pairs", &Row::node_pairs);
    both(j, run, m, "leaf_pairs", &Row::leaf_pairs);
    both(j, run, m, "reduction_cache_hits", &Row::reduction_cache_hits);
    both(j, run, m, "local_in", &Row::local_in);
    both(j, run, m, "local_cache_hits", &Row::local_cache_hits);
    const auto contact = rows_of(run, m, true);
    j.key("reduction_ratio").begin_object();
    j.field("overall", reduction_ratio(contact, false)).field("max", reduction_ratio(contact, true));
    j.end_object();
    const Accuracy a = accuracy(run, m);
    j.key("accuracy").begin_object();
    j.field("poses", a.poses).field("reference_lmds", a.reference).field("found", a.found);
    j.field("match_tolerance", tolerance);
    j.field("recall", fraction(a.recalled, a.reference)).field("precision", fraction(a.confirmed, a.found));
    j.field("recall_2mm", fraction(a.recalled_loose, a.reference));
    j.field("precision_2mm", fraction(a.confirmed_loose, a.found));
    j.field("poses_missing_every_lmd", a.missed_minimum);
    j.field("min_distance_error_max", a.min_error);
    j.field("min_distance_error_max_over_size", a.min_error / size);
    j.field("force_error_max", a.force_error).field("force_error_median", a.force_error_median);
    j.field("torque_error_max", a.torque_error);
    j.field("local_recall", fraction(a.local_recalled, a.reference));
    j.field("local_precision", fraction(a.local_confirmed, a.local_found));
    j.end_object();
    const Smoothness s = smoothness(rows_of(run, m, false));
    j.key("smoothness").begin_object();
    j.field("max_force_jump", s.max_jump).field("total_variation", s.total_variation);
    j.field("max_torque_jump", s.max_torque_jump);
    j.end_object();
    j.end_object();
  }
  for (const char* m : {"min-distance", "fcl", "coal", "reference"}) {
    if (rows_of(run, m, false).empty()) continue;
    j.key(m).begin_object();
    both(j, run, m, "query_ms", &Row::query_ms);
    if (std::string(m) == "coal") {
      both(j, run, m, "pairs_within_cutoff", &Row::candidates);
    } else if (std::string(m) != "reference") {
      const auto rows = rows_of(run, m, false);
      j.field("min_distance_error_max", maximum(values(rows, &Row::min_distance_error)));
      j.field("min_distance_error_max_over_size", maximum(values(rows, &Row::min_distance_error)) / size);
    } else {
      const Smoothness s = smoothness(rows_of(run, m, false));
      j.key("smoothness").begin_object();
      j.field("max_force_jump", s.max_jump).field("total_variation", s.total_variation);
      j.field("max_torque_jump", s.max_torque_jump);
      j.end_object();
    }
    j.end_object();
  }
  j.end_object();

  j.key("ratios").begin_object();
  auto ratio_of_medians = [&](const char* num, const char* den, double Row::*field, bool contact) {
    return ratio(median(values(rows_of(run, num, contact), field)),
                 median(values(rows_of(run, den, contact), field)));
  };
  for (const bool contact : {false, true}) {
    j.key(contact ? "contact" : "all").begin_object();
    j.key("precise_over_original").begin_object();
    j.field("query_ms", ratio_of_medians("precise", "original", &Row::query_ms, contact));
    j.field("global_ms", ratio_of_medians("precise", "original", &Row::global_ms, contact));
    if (!rows_of(run, "precise-1", false).empty())
      j.field("global_one_thread_over_split", ratio_of_medians("precise-1", "precise", &Row::global_ms, contact));
    j.field("reduction_ms", ratio_of_medians("precise", "original", &Row::reduction_ms, contact));
    j.field("local_ms", ratio_of_medians("precise", "original", &Row::local_ms, contact));
    j.field("force_eval_ns", ratio_of_medians("precise", "original", &Row::force_eval_ns, contact));
    j.end_object();
    for (const char* num : {"precise", "original", "min-distance"}) {
      if (rows_of(run, "fcl", false).empty()) break;
      const auto r = pose_ratios(run, num, "fcl", contact);
      j.key(std::string(num) + "_over_fcl").begin_object();
      j.field("per_pose_median", median(r)).field("per_pose_p99", percentile(r, 0.99));
      j.field("of_medians", ratio_of_medians(num, "fcl", &Row::query_ms, contact));
      j.end_object();
    }
    if (!rows_of(run, "coal", false).empty()) {
      const auto r = pose_ratios(run, "precise", "coal", contact);
      j.key("precise_over_coal").begin_object();
      j.field("per_pose_median", median(r)).field("per_pose_p99", percentile(r, 0.99));
      j.field("of_medians", ratio_of_medians("precise", "coal", &Row::query_ms, contact));
      j.end_object();
    }
    j.end_object();
  }
  j.end_object();

  // The performance targets this scene can measure (docs/benchmarks.md,
  // the latest "The run of ... against the speed targets").
  const Accuracy pa = accuracy(run, "precise");
  j.key("targets").begin_object();
  if (!rows_of(run, "fcl", false).empty()) {
    j.field("precise_query_over_fcl_per_pose_median", median(pose_ratios(run, "precise", "fcl", false)));
    j.field("precise_query_over_fcl_per_pose_median_contact",
            median(pose_ratios(run, "precise", "fcl", true)));
  }
  if (!rows_of(run, "coal", false).empty()) {
    j.field("precise_query_over_coal_per_pose_median", median(pose_ratios(run, "precise", "coal", false)));
    j.field("precise_query_over_coal_per_pose_median_contact",
            median(pose_ratios(run, "precise", "coal", true)));
  }
  j.field("precise_local_p99_us",
          percentile(values(rows_of(run, "precise", true), &Row::local_ms), 0.99) * 1e3);
  j.field("precise_recall", fraction(pa.recalled, pa.reference));
  j.field("precise_precision", fraction(pa.confirmed, pa.found));
  j.field("precise_min_distance_error_over_size", pa.min_error / size);
  j.end_object();
  j.end_object();
  return j.str() + "\n";
}

std::string csv(const SceneRun& run) {
  std::string out = "step,method";
  for (const Column& c : columns()) out += std::string(",") + c.first;
  out += '\n';
  char buf[64];
  for (const Row& r : run.rows) {
    out += std::to_string(r.step) + "," + r.method;
    for (const Column& c : columns()) {
      const double v = c.second(r);
      out += ',';
      if (std::isfinite(v)) {
        std::snprintf(buf, sizeof buf, "%.9g", v);
        out += buf;
      }
    }
    out += '\n';
  }
  return out;
}

void print_summary(const SceneRun& run) {
  const Scene& sc = *run.scene;
  const auto contact_rows = rows_of(run, "precise", true);
  std::printf("\n== %s: %zu poses (%zu within the %.2f mm cutoff), %.1f s (path %.1f s)\n", sc.name.c_str(),
              run.path.size(), contact_rows.size(), run.force.cutoff * 1e3, run.seconds, run.path_seconds);
  std::printf("   %s\n", sc.description.c_str());
  std::printf("   times over the poses in contact: median / p99\n");
  std::printf("   %-13s %19s %17s %17s %19s %15s\n", "method", "global+reduction ms", "global ms",
              "reduction ms", "local update us", "force eval ns");
  for (const char* m : {"precise", "original", "min-distance", "fcl", "coal", "reference"}) {
    const auto rows = rows_of(run, m, true);
    if (rows.empty()) continue;
    auto pair = [&](double Row::*f, double scale, const char* format) {
      const auto v = values(rows, f);
      return fmt(median(v) * scale, format) + " / " + fmt(percentile(v, 0.99) * scale, format);
    };
    std::printf("   %-13s %19s %17s %17s %19s %15s\n", m, pair(&Row::query_ms, 1.0, "%.3f").c_str(),
                pair(&Row::global_ms, 1.0, "%.3f").c_str(), pair(&Row::reduction_ms, 1.0, "%.3f").c_str(),
                pair(&Row::local_ms, 1e3, "%.1f").c_str(), pair(&Row::force_eval_ns, 1.0, "%.0f").c_str());
  }
  std::printf("   %-9s %9s %9s %9s %8s %9s %9s %11s %10s %10s %9s\n", "method", "max LMDs", "max cand",
              "reduction", "recall", "precision", "recall-lo", "max dmin err", "max |dF| N", "max jump N",
              "TV N");
  for (const char* m : {"precise", "original"}) {
    const Accuracy a = accuracy(run, m);
    const Smoothness s = smoothness(rows_of(run, m, false));
    const auto all = rows_of(run, m, false);
    std::printf("   %-9s %9s %9s %9s %8s %9s %9s %11s %10s %10s %9s\n", m,
                fmt(maximum(values(all, &Row::lmds)), "%.0f").c_str(),
                fmt(maximum(values(all, &Row::candidates)), "%.0f").c_str(),
                (fmt(reduction_ratio(rows_of(run, m, true), false), "%.1f") + "x").c_str(),
                fmt(fraction(a.recalled, a.reference), "%.4f").c_str(),
                fmt(fraction(a.confirmed, a.found), "%.4f").c_str(),
                fmt(fraction(a.recalled_loose, a.reference), "%.4f").c_str(),
                fmt(a.min_error, "%.2e").c_str(), fmt(a.force_error, "%.4f").c_str(),
                fmt(s.max_jump, "%.4f").c_str(), fmt(s.total_variation, "%.3f").c_str());
  }
  const Smoothness rs = smoothness(rows_of(run, "reference", false));
  if (std::isfinite(rs.max_jump))
    std::printf("   %-9s %87s %10s %9s\n", "reference", "", fmt(rs.max_jump, "%.4f").c_str(),
                fmt(rs.total_variation, "%.3f").c_str());
  auto med_ratio = [&](const char* num, const char* den, double Row::*f) {
    return fmt(ratio(median(values(rows_of(run, num, true), f)), median(values(rows_of(run, den, true), f))),
               "%.2f");
  };
  std::printf(
      "   precise / original (medians in contact): global+reduction %s, global %s, reduction %s, local %s\n",
      med_ratio("precise", "original", &Row::query_ms).c_str(),
      med_ratio("precise", "original", &Row::global_ms).c_str(),
      med_ratio("precise", "original", &Row::reduction_ms).c_str(),
      med_ratio("precise", "original", &Row::local_ms).c_str());
  if (!rows_of(run, "precise-1", false).empty()) {
    const auto split = values(rows_of(run, "precise", true), &Row::global_ms);
    const auto one = values(rows_of(run, "precise-1", true), &Row::global_ms);
    std::printf("   precise global search on one thread / split (medians in contact, side by side): %s / %s ms = %s\n",
                fmt(median(one), "%.3f").c_str(), fmt(median(split), "%.3f").c_str(),
                fmt(ratio(median(one), median(split)), "%.2f").c_str());
  }
  if (!rows_of(run, "fcl", false).empty()) {
    const auto all = pose_ratios(run, "precise", "fcl", false), in = pose_ratios(run, "precise", "fcl", true);
    const auto md = pose_ratios(run, "min-distance", "fcl", false);
    std::printf(
        "   precise (whole LMD set) / FCL distance (one pair), per pose: median %s (in contact %s), p99 %s\n",
        fmt(median(all), "%.2f").c_str(), fmt(median(in), "%.2f").c_str(),
        fmt(percentile(all, 0.99), "%.2f").c_str());
    std::printf(
        "   Proxima min-distance / FCL distance (both one pair), per pose: median %s; FCL agrees with "
        "Proxima's exact minimum to %s m\n",
        fmt(median(md), "%.2f").c_str(),
        fmt(maximum(values(rows_of(run, "fcl", false), &Row::min_distance_error)), "%.1e").c_str());
  }
  if (!rows_of(run, "coal", false).empty()) {
    const auto in = pose_ratios(run, "precise", "coal", true);
    const auto pairs = values(rows_of(run, "coal", true), &Row::candidates);
    std::printf(
        "   precise / Coal margin collide (every triangle pair within the cutoff), per pose in contact: "
        "median "
        "%s, p99 %s; Coal's pairs in contact: median %s, max %s\n",
        fmt(median(in), "%.3f").c_str(), fmt(percentile(in, 0.99), "%.3f").c_str(),
        fmt(median(pairs), "%.0f").c_str(), fmt(maximum(pairs), "%.0f").c_str());
  }
}

}  // namespace prox::bench
