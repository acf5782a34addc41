// proxima path: the deterministic approach, both methods side by side, a CSV per step.
#include "cli.h"

namespace proxcli {

namespace {

struct Step {
  int index = 0;
  double x = 0.0;
  proxMethod method = PROX_METHOD_PRECISE;
  std::size_t candidates = 0, lmds = 0;
  double min_distance = -1.0;
  proxWrench wrench{};
  double global_ms = 0.0, reduction_ms = 0.0, local_ms = 0.0;
};

}  // namespace

int path(Args& args) {
  std::string path_a = default_asset("bunny.obj"), path_b;
  int steps = 1000;
  std::string poses_path;
  std::vector<proxMethod> methods = {PROX_METHOD_PRECISE, PROX_METHOD_ORIGINAL};
  Settings settings = preset(PROX_FORCE_PRESET_HARD);
  std::string csv_path = "proxima-path.csv";
  if (!args.empty() && args.peek().rfind("--", 0) != 0) {
    path_a = args.next("mesh A");
    path_b = args.next("mesh B");
  }
  while (!args.empty()) {
    const std::string opt = args.next("option");
    if (opt == "--steps") {
      const double s = parse_number(args.next("--steps value"), "--steps");
      if (s < 2 || s > 1e7 || s != std::floor(s)) fail("--steps must be a whole number from 2 to 10000000");
      steps = static_cast<int>(s);
    } else if (opt == "--method") {
      const std::string m = args.next("--method value");
      methods = m == "both" ? std::vector<proxMethod>{PROX_METHOD_PRECISE, PROX_METHOD_ORIGINAL}
                            : std::vector<proxMethod>{parse_method(m)};
    } else if (opt == "--force") {
      settings = parse_force(args.next("--force value"));
    } else if (opt == "--csv") {
      csv_path = args.next("--csv file");
    } else if (opt == "--poses") {
      poses_path = args.next("--poses file");
    } else {
      fail("path: unknown option '" + opt + "'");
    }
  }
  if (path_b.empty()) path_b = path_a;
  const double cutoff = settings.cutoff;
  // A world per method, each pair's memory starting afresh; the first also
  // finds the ends of path T.
  auto scene_for = [&](proxMethod method) {
    Settings with_method = settings;
    with_method.method = method;
    return std::make_unique<Scene>(with_method, path_a, path_b, identity(), identity());
  };
  std::unique_ptr<Scene> scene = scene_for(methods.front());
  std::vector<proxPose> poses;
  if (!poses_path.empty()) {
    poses = read_poses(poses_path);
    std::printf("path from %s: %zu poses of %s against %s, cutoff %.3g m\n", poses_path.c_str(), poses.size(),
                path_b.c_str(), path_a.c_str(), cutoff);
  } else {
    const double far = kPathFar, near = kPathNear;
    const double x0 = x_at_gap(*scene, far), x1 = x_at_gap(*scene, near);
    for (int i = 0; i < steps; ++i) poses.push_back(translation(x0 + (x1 - x0) * i / (steps - 1)));
    std::printf(
        "path T: %s held and moved along +x against %s, %d poses from %.3g m to %.3g m apart "
        "(x %.6g .. %.6g), cutoff %.3g m\n",
        path_b.c_str(), path_a.c_str(), steps, far, near, x0, x1, cutoff);
  }

  std::vector<Step> rows;
  for (const proxMethod method : methods) {
    if (!scene) scene = scene_for(method);
    for (std::size_t i = 0; i < poses.size(); ++i) {
      Step s;
      s.index = static_cast<int>(i);
      s.method = method;
      s.x = poses[i].position.x;
      check(proxBody_SetPose(scene->b(), &poses[i]));
      // What the local thread does between global searches: carry the last
      // set to the new pose.
      check(proxWorld_Track(scene->world()));
      proxTrackStats local;
      check(proxWorld_GetTrackStats(scene->world(), &local));
      s.local_ms = local.seconds * 1e3;
      // The global search and its reduction.
      check(proxWorld_Step(scene->world()));
      proxSearchStats search;
      check(proxWorld_GetSearchStats(scene->world(), &search));
      const std::vector<proxContact> contacts = scene->contacts();
      s.candidates = static_cast<std::size_t>(search.candidates);
      s.lmds = contacts.size();
      s.min_distance = min_distance(contacts);
      s.global_ms = search.globalSeconds * 1e3;
      s.reduction_ms = search.reductionSeconds * 1e3;
      s.wrench = scene->wrench();
      rows.push_back(s);
    }
    scene.reset();
  }

  std::string csv =
      "step,method,x,min_distance,candidates,lmds,force_x,force_y,force_z,force,torque_x,torque_y,torque_z,"
      "global_ms,reduction_ms,local_ms\n";
  for (const Step& s : rows) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "%d,%s,%.9g,%.9g,%zu,%zu,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.6f,%.6f,%.6f\n", s.index,
                  method_name(s.method), s.x, s.min_distance, s.candidates, s.lmds, s.wrench.force.x,
                  s.wrench.force.y, s.wrench.force.z, length(s.wrench.force), s.wrench.torque.x,
                  s.wrench.torque.y, s.wrench.torque.z, s.global_ms, s.reduction_ms, s.local_ms);
    csv += line;
  }
  write_file(csv_path, csv);

  std::printf("%-9s %6s %9s %9s %10s %10s %12s %12s %12s %12s\n", "method", "steps", "contact", "max LMDs",
              "max |F| N", "max jump N", "global p50", "global p99", "local p50", "reduction");
  for (const proxMethod method : methods) {
    std::vector<double> global, local;
    int contact = 0;
    std::size_t max_lmds = 0, candidates = 0, lmds = 0;
    double max_force = 0.0, max_jump = 0.0;
    const Step* previous = nullptr;
    for (const Step& s : rows) {
      if (s.method != method) continue;
      global.push_back(s.global_ms + s.reduction_ms);
      local.push_back(s.local_ms);
      contact += s.lmds > 0;
      max_lmds = std::max(max_lmds, s.lmds);
      candidates += s.candidates, lmds += s.lmds;
      max_force = std::max(max_force, length(s.wrench.force));
      if (previous) max_jump = std::max(max_jump, length(sub(s.wrench.force, previous->wrench.force)));
      previous = &s;
    }
    char reduction[32];
    std::snprintf(reduction, sizeof reduction, "%.1fx",
                  lmds ? static_cast<double>(candidates) / static_cast<double>(lmds) : 0.0);
    std::printf("%-9s %6zu %9d %9zu %10.4f %10.4f %9.3f ms %9.3f ms %9.3f ms %12s\n", method_name(method),
                global.size(), contact, max_lmds, max_force, max_jump, percentile(global, 0.5),
                percentile(global, 0.99), percentile(local, 0.5), reduction);
  }
  std::printf("per-step figures written to %s\n", csv_path.c_str());
  return 0;
}

}  // namespace proxcli
