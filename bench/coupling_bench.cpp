// The constrained tool's local update (docs/coupling.md): the proxy's
// constrained solve and its exact check, per haptic tick of a scripted
// path straight through the obstacle and back at 1 m/s, replayed through
// the deterministic step. Prints p50/p99/max over the ticks in contact.
//
//   proxima_coupling_bench [--scene bunny|cad|saw]... [--speed M_PER_S]
#include "coupling_scenes.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace prox;
using namespace prox::coupling_scenes;

namespace {

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5))];
}

struct Axis {
  const char* scene;
  Vec3 out;
};

int run(const std::string& name, double speed) {
  const Axis axes[] = {{"bunny", Vec3(1, 0, 0)}, {"cad", Vec3(1, 0, 0)}, {"saw", Vec3(0, 1, 0)}};
  Vec3 out(1, 0, 0);
  for (const Axis& a : axes)
    if (name == a.scene) out = a.out;
  std::string error;
  const Scene scene = make_scene(name, error);
  if (!error.empty()) {
    std::fprintf(stderr, "coupling_bench: %s\n", error.c_str());
    return 1;
  }
  const Vec3 near = clear_offset(scene, out, 0.005), far = clear_offset(scene, -out, 0.005);
  const std::vector<Pose> path = line_path({near, far, near}, speed * runtime::kStepSeconds, 300);
  Built b = build(scene, path.front(), true, error);
  if (!error.empty()) {
    std::fprintf(stderr, "coupling_bench: %s\n", error.c_str());
    return 1;
  }
  runtime::World& w = *b.world;
  std::vector<double> update, solve, step, constraints;
  int halvings = 0, checks = 0;
  for (const Pose& device : path) {
    w.set_pose(b.tool, device);
    const auto start = std::chrono::steady_clock::now();
    w.step();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const coupling::ProxyStats& s = w.proxy_stats(b.tool);
    if (s.constraints == 0) continue;  // in contact only
    update.push_back(s.seconds);
    solve.push_back(s.solve_seconds);
    step.push_back(seconds);
    constraints.push_back(s.constraints);
    halvings += s.halvings;
    checks += s.distance_checks;
  }
  auto us = [](double s) { return s * 1e6; };
  std::printf("%-6s %6zu %7.0f %7.0f | %8.1f %8.1f %8.1f | %8.1f %8.1f | %8.1f %8.1f | %6d %6d\n",
              name.c_str(), update.size(), percentile(constraints, 0.5), percentile(constraints, 0.99),
              us(percentile(update, 0.5)), us(percentile(update, 0.99)), us(percentile(update, 1.0)),
              us(percentile(solve, 0.5)), us(percentile(solve, 0.99)), us(percentile(step, 0.5)),
              us(percentile(step, 0.99)), checks, halvings);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> scenes;
  double speed = 1.0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--scene" && i + 1 < argc) {
      scenes.push_back(argv[++i]);
    } else if (a == "--speed" && i + 1 < argc) {
      speed = std::atof(argv[++i]);
      if (!(speed > 0.0 && speed <= 10.0)) {
        std::fprintf(stderr, "coupling_bench: --speed must be in (0, 10] m/s\n");
        return 2;
      }
    } else {
      std::fprintf(stderr, "usage: proxima_coupling_bench [--scene bunny|cad|saw]... [--speed M_PER_S]\n");
      return 2;
    }
  }
  if (scenes.empty()) scenes = {"bunny", "cad"};
  std::printf("constrained tool, device through and back at %.3g m/s, one step a tick; ticks in contact\n",
              speed);
  std::printf("%-6s %6s %7s %7s | %8s %8s %8s | %8s %8s | %8s %8s | %6s %6s\n", "scene", "ticks", "c p50",
              "c p99", "upd p50", "upd p99", "upd max", "slv p50", "slv p99", "step p50", "step p99",
              "checks", "halved");
  std::printf("%-6s %6s %7s %7s | %26s | %17s | %17s |\n", "", "", "", "", "proxy update (us)", "solve (us)",
              "whole step (us)");
  for (const std::string& s : scenes)
    if (int rc = run(s, speed)) return rc;
  return 0;
}
