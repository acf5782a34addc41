// proxima_timing_bench: how well the haptic loop keeps its 1 kHz beat, for
// each way of waiting (sleep, spin), with and without a real-time priority,
// with the global search idle and busy, side by side in one run
// (docs/benchmarks-runtime.md, "Keeping the beat"; docs/threading.md).
//
//   proxima_timing_bench [--seconds S] [--out DIR] [--mesh FILE]
//
// The scene is the bunny against the bunny on the runtime's threads. Idle:
// the tool held still far away (nothing to search). Busy: the tool swept
// back and forth through contact, 5 mm to 0.5 mm, so the global search runs
// back to back and local tracking has contacts. Per configuration: the
// period error |period - 1 ms| at p50, p99, p99.9 and its maximum, the
// overruns, the haptic thread's CPU use, and a histogram of the period, to
// DIR/haptic-timing.json; a table to standard output.
#include "common/json_writer.h"
#include "io/obj.h"
#include "runtime/scripted_device.h"
#include "runtime/threads.h"
#include "runtime/world.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace prox::bench {
namespace {

using Json = prox::JsonWriter;

struct Config {
  runtime::HapticTiming timing;
  int priority;  // SCHED_FIFO for the haptic thread (local one below it); 0: none
  bool busy;
};

struct Result {
  Config config;
  double error_p50 = 0, error_p99 = 0, error_p999 = 0, error_max = 0;  // s
  std::uint64_t ticks = 0, overruns = 0;
  double cpu = -1;  // fraction of one core used by the haptic thread
  int granted = 0, refused = 0;
  std::vector<double> periods;
};

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * double(v.size() - 1) + 0.5))];
}

const char* timing_name(runtime::HapticTiming t) {
  return t == runtime::HapticTiming::Spin ? "spin" : "sleep";
}

class Bench {
 public:
  explicit Bench(const std::string& mesh_path) {
    io::ObjData obj;
    const Status read = io::read_obj(mesh_path, obj);
    if (!read) throw std::runtime_error(read.message());
    input_ = obj;
    runtime::World probe{runtime::WorldSettings{}};
    Status status;
    const runtime::Handle mesh = make_mesh(probe, status);
    const Aabb& box = probe.mesh(mesh).bounds();
    centre_ = 0.5 * (box.min + box.max);
    const runtime::Handle rock = probe.create_body(mesh, runtime::BodyType::Static, Pose{}, Vec3(0.0));
    const runtime::Handle tool = probe.create_body(mesh, runtime::BodyType::Tool, Pose{}, centre_);
    far_ = x_at_gap(probe, rock, tool, 0.05);
    near_ = x_at_gap(probe, rock, tool, 0.0005);
    contact_ = x_at_gap(probe, rock, tool, 0.005);
  }

  Result run(const Config& c, double seconds) const {
    runtime::World world{runtime::WorldSettings{}};
    Status status;
    const runtime::Handle mesh = make_mesh(world, status);
    world.create_body(mesh, runtime::BodyType::Static, Pose{}, Vec3(0.0));
    const runtime::Handle tool = world.create_body(mesh, runtime::BodyType::Tool, at(far_), centre_);
    // Busy: 5 mm to 0.5 mm and back every 0.4 s; idle: still, far away.
    std::vector<runtime::ScriptedPose> path;
    if (c.busy)
      path = {runtime::ScriptedPose::of(at(contact_)), runtime::ScriptedPose::of(at(near_))};
    else
      path = {runtime::ScriptedPose::of(at(far_))};
    runtime::ScriptedDevice device(path, 0.2, true);
    world.set_device(tool, runtime::Device::borrowed(device));
    runtime::ThreadSettings s;
    s.haptic_timing = c.timing;
    s.realtime_priority[0] = c.priority;
    s.realtime_priority[1] = c.priority > 0 ? c.priority - 10 : 0;
    if (!world.start_threads(s, status)) throw std::runtime_error(status.message());
    const runtime::Threads& threads = *world.threads();
    // Past the start (threads settling, the first searches), then measured.
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    const double cpu0 = threads.cpu_seconds(runtime::Role::Haptic);
    const std::uint64_t ticks0 = threads.loop_summary(runtime::Role::Haptic).updates;
    const std::uint64_t overruns0 = threads.loop_summary(runtime::Role::Haptic).overruns;
    const auto t0 = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu1 = threads.cpu_seconds(runtime::Role::Haptic);
    const runtime::LoopSummary summary = threads.loop_summary(runtime::Role::Haptic);
    Result r;
    r.config = c;
    r.ticks = summary.updates - ticks0;
    r.overruns = summary.overruns - overruns0;
    r.cpu = cpu0 >= 0 && cpu1 >= 0 ? (cpu1 - cpu0) / wall : -1.0;
    r.granted = threads.grant(runtime::Role::Haptic).realtime_priority;
    r.refused = threads.grant(runtime::Role::Haptic).realtime_error;
    std::vector<double> periods = threads.periods(runtime::Role::Haptic);
    world.stop_threads();
    // The window's newest periods: those of the measured stretch.
    const std::size_t keep = std::min<std::size_t>(periods.size(), static_cast<std::size_t>(r.ticks));
    r.periods.assign(periods.end() - static_cast<std::ptrdiff_t>(keep), periods.end());
    std::vector<double> error;
    for (double p : r.periods) error.push_back(std::fabs(p - 1e-3));
    r.error_p50 = percentile(error, 0.5);
    r.error_p99 = percentile(error, 0.99);
    r.error_p999 = percentile(error, 0.999);
    r.error_max = error.empty() ? 0.0 : *std::max_element(error.begin(), error.end());
    return r;
  }

 private:
  runtime::Handle make_mesh(runtime::World& world, Status& status) const {
    const runtime::Handle h =
        world.create_mesh({input_.positions.data(), static_cast<std::uint32_t>(input_.positions.size() / 3),
                           input_.indices.data(), static_cast<std::uint32_t>(input_.indices.size() / 3)},
                          status);
    if (!status) throw std::runtime_error(status.message());
    return h;
  }
  static Pose at(double x) { return Pose{glm::dmat3(1.0), Vec3(x, 0.0, 0.0)}; }
  // The tool's x that puts it `gap` from the other bunny (bisection).
  static double x_at_gap(runtime::World& w, runtime::Handle rock, runtime::Handle tool, double gap) {
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      w.set_pose(tool, at(mid));
      (w.distance(rock, tool, gap) < gap ? lo : hi) = mid;
    }
    return hi;
  }

  io::ObjData input_;
  Vec3 centre_{0.0};
  double far_ = 0, near_ = 0, contact_ = 0;
};

int run(int argc, char** argv) {
  double seconds = 4.0;  // 4,000 ticks: within the 4,096 periods the loop statistics keep
  std::string out = "bench-results", mesh = std::string(PROX_SHARED_ASSETS_DIR) + "/bunny.obj";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) throw std::runtime_error("missing value after " + a);
    if (a == "--seconds")
      seconds = std::stod(argv[++i]);
    else if (a == "--out")
      out = argv[++i];
    else if (a == "--mesh")
      mesh = argv[++i];
    else
      throw std::runtime_error("unknown option '" + a + "' (--seconds S, --out DIR, --mesh FILE)");
  }
  if (!(seconds > 0.0 && seconds <= 600.0)) throw std::runtime_error("--seconds must be in (0, 600]");
  const Bench bench(mesh);
  std::vector<Result> results;
  std::printf("haptic loop at 1 kHz, %u cores, %.1f s per configuration; period error |period - 1 ms|\n",
              std::thread::hardware_concurrency(), seconds);
  std::printf("%-6s %-6s %-9s %9s %9s %9s %9s %9s %8s %s\n", "search", "timing", "priority", "p50 us",
              "p99 us", "p99.9 us", "max us", "overruns", "CPU", "ticks");
  for (bool busy : {false, true})
    for (runtime::HapticTiming timing : {runtime::HapticTiming::Sleep, runtime::HapticTiming::Spin})
      for (int priority : {0, 80}) {
        const Result r = bench.run({timing, priority, busy}, seconds);
        const std::string prio = priority == 0 ? "normal"
                                 : r.granted   ? "FIFO " + std::to_string(r.granted)
                                               : "refused";
        std::printf("%-6s %-6s %-9s %9.1f %9.1f %9.1f %9.1f %9llu %7.1f%% %llu\n", busy ? "busy" : "idle",
                    timing_name(timing), prio.c_str(), r.error_p50 * 1e6, r.error_p99 * 1e6,
                    r.error_p999 * 1e6, r.error_max * 1e6, static_cast<unsigned long long>(r.overruns),
                    r.cpu * 100.0, static_cast<unsigned long long>(r.ticks));
        results.push_back(r);
      }

  Json j;
  j.begin_object();
  j.field("scene", "haptic-timing");
  j.field("machine_cores", static_cast<long long>(std::thread::hardware_concurrency()));
  j.field("seconds_per_configuration", seconds);
  j.key("configurations").begin_array();
  for (const Result& r : results) {
    j.begin_object();
    j.field("search", r.config.busy ? "busy" : "idle");
    j.field("timing", timing_name(r.config.timing));
    j.field("priority_asked", r.config.priority);
    j.field("priority_granted", r.granted);
    j.field("priority_error", r.refused);
    j.field("error_us_p50", r.error_p50 * 1e6).field("error_us_p99", r.error_p99 * 1e6);
    j.field("error_us_p999", r.error_p999 * 1e6).field("error_us_max", r.error_max * 1e6);
    j.field("ticks", static_cast<long long>(r.ticks)).field("overruns", static_cast<long long>(r.overruns));
    j.field("cpu_fraction", r.cpu);
    // The period's histogram in 10 us bins from 0 to 3 ms; the last bin holds everything longer.
    std::vector<long long> bins(301, 0);
    for (double p : r.periods) ++bins[std::min<std::size_t>(300, static_cast<std::size_t>(p * 1e5))];
    j.key("period_histogram_10us").begin_array();
    for (long long b : bins) j.value(b);
    j.end_array();
    j.end_object();
  }
  j.end_array();
  j.end_object();
  std::filesystem::create_directories(out);
  const std::string path = out + "/haptic-timing.json";
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error(path + ": cannot write");
  std::fputs((j.str() + "\n").c_str(), f);
  std::fclose(f);
  std::printf("written to %s\n", path.c_str());
  return 0;
}

}  // namespace
}  // namespace prox::bench

int main(int argc, char** argv) {
  try {
    return prox::bench::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "proxima_timing_bench: %s\n", e.what());
    return 1;
  }
}
