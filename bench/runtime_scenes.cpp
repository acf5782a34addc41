#include "runtime_scenes.h"

#include "runtime/haptic.h"
#include "runtime/scripted_device.h"
#include "runtime/threads.h"
#include "runtime/world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

namespace prox::bench {

namespace {

// A model's mesh as arrays again, as an application hands it to a world.
struct MeshArrays {
  std::vector<double> positions;
  std::vector<std::uint32_t> indices;
};
MeshArrays arrays_of(const Model& model) {
  MeshArrays a;
  for (std::uint32_t v = 0; v < model.mesh.vertex_count(); ++v)
    a.positions.insert(a.positions.end(),
                       {model.mesh.vertex(v).x, model.mesh.vertex(v).y, model.mesh.vertex(v).z});
  for (std::uint32_t t = 0; t < model.mesh.triangle_count(); ++t)
    a.indices.insert(a.indices.end(), model.mesh.indices(t).begin(), model.mesh.indices(t).end());
  return a;
}

// One tool bunny on path T against one static bunny, in worlds side by side
// on the same poses: alone, and among crowds of more static bunnies on a
// grid out of range (120, 1,200 and 12,000 of them). The runtime's
// broadphase (a tree of the static bodies' boxes, rebuilt only when they
// move) should make the crowd cost next to nothing, whatever its size: the
// step-time ratios and the per-body overhead are the figures.
constexpr int kCrowds[] = {120, 1200, 12000};

}  // namespace

void run_many_bodies(const Model& model, const Options& opt) {
  const Scene& path_t = scenes().front();
  const std::vector<PosePoint> path = make_path(path_t, path_t.far, path_t.near, model, model, opt.poses);
  const MeshArrays arrays = arrays_of(model);
  const std::vector<double>& positions = arrays.positions;
  const std::vector<std::uint32_t>& indices = arrays.indices;
  auto world_with = [&](int far_bodies) {
    auto world = std::make_unique<runtime::World>(runtime::WorldSettings{});
    runtime::World& w = *world;
    Status status;
    const MeshInput input{positions.data(), static_cast<std::uint32_t>(positions.size() / 3), indices.data(),
                          static_cast<std::uint32_t>(indices.size() / 3)};
    const runtime::Handle mesh = w.create_mesh(input, status);
    if (!status) throw UserError(status.message());
    w.create_body(mesh, runtime::BodyType::Static, Pose{}, Vec3(0.0));
    // A grid 0.5 m apart, 12 wide, rows going up from y = 0.6 m: beyond the
    // path's reach.
    for (int i = 0; i < far_bodies; ++i)
      w.create_body(mesh, runtime::BodyType::Static,
                    Pose{glm::dmat3(1.0), Vec3(0.5 * (i % 12) - 2.75, 0.6 + 0.5 * (i / 12), 0.0)}, Vec3(0.0));
    const runtime::Handle tool =
        w.create_body(mesh, runtime::BodyType::Tool, path.front().pose, model.centroid);
    return std::make_pair(std::move(world), tool);
  };
  struct Crowd {
    int bodies = 0;
    std::unique_ptr<runtime::World> world;
    runtime::Handle tool;
    std::vector<double> ms, near_ms, overhead_far;
    int max_in_range = 0, contacts_differ = 0;
  };
  auto [alone_world, tool_alone] = world_with(0);
  runtime::World& alone = *alone_world;
  std::vector<Crowd> crowds;
  for (int n : kCrowds) {
    auto [w, t] = world_with(n);
    Crowd c;
    c.bodies = n;
    c.world = std::move(w);
    c.tool = t;
    crowds.push_back(std::move(c));
  }
  std::vector<double> alone_ms, alone_near;
  std::string rows = "step,x,alone_ms";
  for (const Crowd& c : crowds) rows += ",crowd" + std::to_string(c.bodies) + "_ms";
  rows += ",pairs_in_range,contacts\n";
  for (std::size_t i = 0; i < path.size(); ++i) {
    alone.set_pose(tool_alone, path[i].pose);
    alone.step();
    alone_ms.push_back(alone.stats().seconds * 1e3);
    const bool in_range = alone.stats().pairs_in_range > 0;
    if (in_range) alone_near.push_back(alone_ms.back());
    char line[512];
    std::snprintf(line, sizeof line, "%zu,%.9g,%.6f", i, path[i].x, alone_ms.back());
    rows += line;
    for (Crowd& c : crowds) {
      c.world->set_pose(c.tool, path[i].pose);
      c.world->step();
      const runtime::StepStats st = c.world->stats();
      c.ms.push_back(st.seconds * 1e3);
      c.max_in_range = std::max(c.max_in_range, st.pairs_in_range);
      c.contacts_differ += st.contacts != alone.stats().contacts;
      if (in_range)
        c.near_ms.push_back(c.ms.back());
      else
        c.overhead_far.push_back(c.ms.back() - alone_ms.back());
      std::snprintf(line, sizeof line, ",%.6f", c.ms.back());
      rows += line;
    }
    std::snprintf(line, sizeof line, ",%d,%d\n", crowds.back().world->stats().pairs_in_range,
                  crowds.back().world->stats().contacts);
    rows += line;
  }
  Json j;
  j.begin_object();
  j.field("scene", "many-bodies");
  j.field(
      "description",
      std::string("One tool bunny on path T among 1 + N static bunnies (all but one out of range), against "
                  "the same path with the one bunny alone, side by side; runtime::World::step, whole step "
                  "timed."));
  j.field("poses", static_cast<long long>(path.size()));
  j.field("steps_in_range", static_cast<long long>(alone_near.size()));
  j.field("alone_step_ms_median", median(alone_ms)).field("alone_step_ms_p99", percentile(alone_ms, 0.99));
  j.field("in_range_alone_step_ms_median", median(alone_near));
  j.key("crowds").begin_array();
  std::printf(
      "\n== many-bodies: %zu poses, one tool among crowds of static bunnies (all but one out of range)\n",
      path.size());
  std::printf("   %8s %22s %22s %10s %24s %10s\n", "bodies", "step median in range", "alone in range",
              "ratio", "out of range: added/body", "max pairs");
  for (const Crowd& c : crowds) {
    const double ratio = median(c.near_ms) / median(alone_near);
    const double per_body_ns = median(c.overhead_far) * 1e6 / c.bodies;
    j.begin_object();
    j.field("bodies", static_cast<long long>(c.bodies + 2));
    j.field("crowd_step_ms_median", median(c.ms)).field("crowd_step_ms_p99", percentile(c.ms, 0.99));
    j.field("in_range_crowd_step_ms_median", median(c.near_ms));
    j.field("in_range_crowd_over_alone", ratio);
    j.field("out_of_range_overhead_ns_per_far_body", per_body_ns);
    j.field("out_of_range_overhead_ns_median", median(c.overhead_far) * 1e6);
    j.field("max_pairs_in_range", static_cast<long long>(c.max_in_range));
    j.field("steps_with_different_contacts", static_cast<long long>(c.contacts_differ));
    j.end_object();
    std::printf("   %8d %19.3f ms %19.3f ms %10.3f %21.2f ns %10d%s\n", c.bodies + 2, median(c.near_ms),
                median(alone_near), ratio, per_body_ns, c.max_in_range,
                c.contacts_differ ? "  CONTACTS DIFFER" : "");
  }
  j.end_array();
  j.end_object();
  write_file(opt.out + "/many-bodies.csv", rows);
  write_file(opt.out + "/many-bodies.json", j.str() + "\n");
}

// ---- the threads in real time ------------------------------------------------------

// Path T in real time on the runtime's threads: the scripted device moves the
// tool through the path's poses at 3 ms a pose (1000 poses: 3 s), then holds
// it 0.5 s, while the haptic loop (1 kHz), local tracking (1 kHz) and the
// global search (back to back) run. What the threads achieved: rates,
// period and work percentiles, overruns; what the device was handed.
void run_threads(const Model& model, const Options& opt) {
  const Scene& path_t = scenes().front();
  const std::vector<PosePoint> path = make_path(path_t, path_t.far, path_t.near, model, model, opt.poses);
  const MeshArrays arrays = arrays_of(model);
  const std::vector<double>& positions = arrays.positions;
  const std::vector<std::uint32_t>& indices = arrays.indices;
  runtime::World world{runtime::WorldSettings{}};
  Status status;
  const runtime::Handle mesh =
      world.create_mesh({positions.data(), static_cast<std::uint32_t>(positions.size() / 3), indices.data(),
                         static_cast<std::uint32_t>(indices.size() / 3)},
                        status);
  if (!status) throw UserError(status.message());
  world.create_body(mesh, runtime::BodyType::Static, Pose{}, Vec3(0.0));
  const runtime::Handle tool =
      world.create_body(mesh, runtime::BodyType::Tool, path.front().pose, model.centroid);
  std::vector<runtime::ScriptedPose> poses;
  for (const PosePoint& p : path) poses.push_back(runtime::ScriptedPose::of(p.pose));
  constexpr double kSecondsPerPose = 0.003, kHold = 0.5;
  runtime::ScriptedDevice device(poses, kSecondsPerPose, false);
  world.set_device(tool, runtime::Device::borrowed(device));
  const runtime::ThreadSettings settings;
  if (!world.start_threads(settings, status)) throw UserError(status.message());
  std::this_thread::sleep_for(
      std::chrono::duration<double>(kSecondsPerPose * double(path.size() - 1) + kHold));
  world.stop_threads();
  const runtime::Threads& threads = *world.threads();
  const runtime::ScriptedRecord record = device.record();
  const runtime::HapticCounters safety = threads.haptic_counters();

  Json j;
  j.begin_object();
  j.field("scene", "threads");
  j.field("description",
          std::string("Path T in real time on the runtime's threads, the scripted device moving "
                      "the tool at 3 ms a pose, then holding it 0.5 s."));
  j.field("poses", static_cast<long long>(path.size()));
  j.field("machine_cores", static_cast<long long>(std::thread::hardware_concurrency()));
  const char* names[3] = {"haptic", "local", "global"};
  std::printf("\n== threads: path T in real time (%zu poses at %.0f ms each, then %.1f s still), %u cores\n",
              path.size(), kSecondsPerPose * 1e3, kHold, std::thread::hardware_concurrency());
  std::printf("   %-7s %9s %9s %11s %11s %11s %11s %11s %11s %9s %9s\n", "thread", "target", "achieved",
              "period p50", "period p99", "period max", "work p50", "work p99", "work max", "updates",
              "overruns");
  j.key("threads").begin_object();
  for (int r = 0; r < 3; ++r) {
    const runtime::LoopSummary s = threads.loop_summary(static_cast<runtime::Role>(r));
    j.key(names[r]).begin_object();
    j.field("target_hz", s.target_rate).field("achieved_hz", s.achieved_rate);
    j.field("period_ms_p50", s.period_p50 * 1e3).field("period_ms_p99", s.period_p99 * 1e3);
    j.field("period_ms_max", s.period_max * 1e3);
    j.field("update_ms_p50", s.update_p50 * 1e3).field("update_ms_p99", s.update_p99 * 1e3);
    j.field("update_ms_max", s.update_max * 1e3);
    j.field("updates", static_cast<long long>(s.updates))
        .field("overruns", static_cast<long long>(s.overruns));
    j.end_object();
    std::printf(
        "   %-7s %6.0f Hz %6.0f Hz %8.3f ms %8.3f ms %8.3f ms %8.4f ms %8.4f ms %8.3f ms %9llu %9llu\n",
        names[r], s.target_rate, s.achieved_rate, s.period_p50 * 1e3, s.period_p99 * 1e3, s.period_max * 1e3,
        s.update_p50 * 1e3, s.update_p99 * 1e3, s.update_max * 1e3,
        static_cast<unsigned long long>(s.updates), static_cast<unsigned long long>(s.overruns));
  }
  j.end_object();
  j.key("device").begin_object();
  j.field("writes", static_cast<long long>(record.writes));
  j.field("max_force", record.max_force).field("max_force_step", record.max_force_step);
  j.field("all_finite", record.finite);
  j.end_object();
  j.key("safety").begin_object();
  j.field("stale_ticks", static_cast<long long>(safety.stale_ticks));
  j.field("untrusted_ticks", static_cast<long long>(safety.untrusted_ticks));
  j.field("limited_ticks", static_cast<long long>(safety.limited_ticks));
  j.field("torn_snapshots", static_cast<long long>(safety.torn_snapshots));
  j.field("dropped_contacts", static_cast<long long>(safety.dropped_contacts));
  j.end_object();
  j.end_object();
  write_file(opt.out + "/threads.json", j.str() + "\n");
  std::printf(
      "   device: %llu wrenches, largest force %.3f N, largest change between ticks %.3f N, %s; "
      "stale ticks %llu, untrusted %llu, rate-limited %llu, torn snapshots %llu\n",
      static_cast<unsigned long long>(record.writes), record.max_force, record.max_force_step,
      record.finite ? "all finite" : "NOT ALL FINITE", static_cast<unsigned long long>(safety.stale_ticks),
      static_cast<unsigned long long>(safety.untrusted_ticks),
      static_cast<unsigned long long>(safety.limited_ticks),
      static_cast<unsigned long long>(safety.torn_snapshots));
}

}  // namespace prox::bench
