// proxima lmd A B: the LMD set of two meshes at given poses.
#include "cli.h"

namespace proxcli {
namespace {

// "INDEX:SECONDS": a glTF animation of the mesh and a time in it.
AnimateAt parse_animate(const std::string& s, const char* option) {
  const std::size_t colon = s.find(':');
  if (colon == std::string::npos)
    fail(std::string(option) + ": '" + s +
         "' is not INDEX:SECONDS (an animation index and a time, e.g. 0:1.5)");
  const double index = parse_number(s.substr(0, colon), option);
  if (index < 0 || index > 2147483647.0 || index != std::floor(index))
    fail(std::string(option) + ": the animation index '" + s.substr(0, colon) +
         "' is not a whole number >= 0");
  return {static_cast<int32_t>(index), parse_number(s.substr(colon + 1), option)};
}

}  // namespace

int lmd(Args& args) {
  const std::string path_a = args.next("mesh A"), path_b = args.next("mesh B");
  proxPose pose_a = identity(), pose_b = identity();
  double cutoff = 0.0;  // 0: the preset's own
  proxMethod method = PROX_METHOD_PRECISE;
  Settings settings = preset(PROX_FORCE_PRESET_HARD);
  std::string json_path;
  proxPatchSettings patches{0.0, 0.0, 0.0};
  bool radius_given = false, angle_given = false, spread_given = false;  // else the world's default
  double leaf_budget = -1.0;                                             // -1: the world's default
  AnimateAt animate_a, animate_b;
  while (!args.empty()) {
    const std::string opt = args.next("option");
    if (opt == "--pose-a")
      pose_a = args.pose("--pose-a");
    else if (opt == "--pose-b")
      pose_b = args.pose("--pose-b");
    else if (opt == "--cutoff")
      cutoff = parse_positive(args.next("--cutoff value"), "--cutoff");
    else if (opt == "--method")
      method = parse_method(args.next("--method value"));
    else if (opt == "--force")
      settings = parse_force(args.next("--force value"));
    else if (opt == "--patch-radius")
      patches.radiusOverCutoff = parse_number(args.next("--patch-radius value"), "--patch-radius"),
      radius_given = true;
    else if (opt == "--patch-angle")
      patches.maxAngleDegrees = parse_number(args.next("--patch-angle value"), "--patch-angle"),
      angle_given = true;
    else if (opt == "--patch-spread")
      patches.maxSpreadOverCutoff = parse_number(args.next("--patch-spread value"), "--patch-spread"),
      spread_given = true;
    else if (opt == "--leaf-budget") {
      leaf_budget = parse_number(args.next("--leaf-budget value"), "--leaf-budget");
      if (leaf_budget < 0 || leaf_budget > 1e15 || leaf_budget != std::floor(leaf_budget))
        fail("--leaf-budget must be a whole number from 0 (no bound) to 1e15");
    } else if (opt == "--animate-a")
      animate_a = parse_animate(args.next("--animate-a INDEX:SECONDS"), "--animate-a");
    else if (opt == "--animate-b")
      animate_b = parse_animate(args.next("--animate-b INDEX:SECONDS"), "--animate-b");
    else if (opt == "--json")
      json_path = args.next("--json file");
    else
      fail("lmd: unknown option '" + opt + "'");
  }
  // A preset is a shape relative to its cutoff: at another cutoff its
  // safety distance and decay length scale with it, as the benchmark's CAD
  // scenes scale them, so any positive cutoff works at any scale.
  if (cutoff > 0.0) settings = scaled_to(settings, cutoff);
  cutoff = settings.cutoff;
  settings.method = method;
  const Scene scene(settings, path_a, path_b, pose_a, pose_b, PROX_TOOL_FREE, animate_a, animate_b);
  proxPatchSettings rule;
  check(proxWorld_GetPatchSettings(scene.world(), &rule));
  if (radius_given) rule.radiusOverCutoff = patches.radiusOverCutoff;
  if (angle_given) rule.maxAngleDegrees = patches.maxAngleDegrees;
  if (spread_given) rule.maxSpreadOverCutoff = patches.maxSpreadOverCutoff;
  check(proxWorld_SetPatchSettings(scene.world(), &rule));
  if (leaf_budget >= 0) check(proxWorld_SetLeafBudget(scene.world(), static_cast<uint64_t>(leaf_budget)));
  uint64_t budget = 0;
  check(proxWorld_GetLeafBudget(scene.world(), &budget));
  check(proxWorld_Step(scene.world()));
  std::vector<proxContact> contacts;
  std::vector<proxContactPatch> patch_of;
  scene.contacts(contacts, patch_of);
  const proxWrench w = scene.wrench();
  proxSearchStats r;
  check(proxWorld_GetSearchStats(scene.world(), &r));
  proxPatchStats ps;
  check(proxWorld_GetPatchStats(scene.world(), &ps));
  const double min_d = min_distance(contacts);

  // One contact per patch of LMDs (docs/patches.md): as many as the LMDs
  // when nothing merged.
  std::printf("%s contacts between %s and %s within %g: %zu (patches of %d LMDs, from %llu candidates)\n",
              method_name(method), path_a.c_str(), path_b.c_str(), cutoff, contacts.size(), ps.lmds,
              static_cast<unsigned long long>(r.candidates));
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const proxContact& c = contacts[i];
    std::printf("  tri %u - tri %u  d=%.9g  %s-%s  a=(%.6g, %.6g, %.6g) b=(%.6g, %.6g, %.6g)",
                c.triangleOther, c.triangleTool, c.distance, feature_name(c.featureOther),
                feature_name(c.featureTool), c.pointOther.x, c.pointOther.y, c.pointOther.z, c.pointTool.x,
                c.pointTool.y, c.pointTool.z);
    if (patch_of[i].count > 1)
      std::printf("  patch of %d (within %.3g, %.3g farther)", patch_of[i].count, patch_of[i].extent,
                  patch_of[i].spread);
    std::printf("\n");
  }
  if (contacts.empty())
    std::printf("  minimum distance: none within the cutoff\n");
  else
    std::printf("  minimum distance: %.9g\n", min_d);
  std::printf("  force on B:  (%.6g, %.6g, %.6g) N%s\n", w.force.x, w.force.y, w.force.z,
              w.clipped ? " (clipped)" : "");
  std::printf("  torque on B: (%.6g, %.6g, %.6g) N m about its box centre\n", w.torque.x, w.torque.y,
              w.torque.z);
  std::printf(
      "  search: %llu node pairs, %llu leaf pairs, %llu culled by visibility, %.3f ms; reduction %.3f ms\n",
      static_cast<unsigned long long>(r.nodePairs), static_cast<unsigned long long>(r.leafPairs),
      static_cast<unsigned long long>(r.visibilityRejections), r.globalSeconds * 1e3,
      r.reductionSeconds * 1e3);
  std::printf(
      "  patches: %d LMDs merged into %d (%d merged, the largest of %d) within %g x the cutoff, %g deg and "
      "%g x the cutoff farther\n",
      ps.lmds, ps.patches, ps.merged, ps.largestPatch, rule.radiusOverCutoff, rule.maxAngleDegrees,
      rule.maxSpreadOverCutoff);
  if (ps.cutNodePairs > 0)
    std::printf(
        "  bounded search: past %llu leaf pairs, %d node pairs of patch size cut to one contact each "
        "(their LMDs are not counted)\n",
        static_cast<unsigned long long>(budget), ps.cutNodePairs);
  if (ps.intersectingPairs > 0)
    std::printf("  intersection: the surfaces cross (%llu triangle pairs; not contacts)\n",
                static_cast<unsigned long long>(ps.intersectingPairs));
  else
    std::printf("  intersection: none found\n");

  if (!json_path.empty()) {
    auto count = [](uint64_t n) { return static_cast<long long>(n); };
    Json j;
    j.begin_object();
    // -1 when no pair is within the cutoff (the minimum is then unknown).
    j.key("min_distance").value(min_d);
    j.key("method").value(method_name(method));
    j.key("cutoff").value(cutoff);
    j.key("lmds").begin_array();
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      const proxContact& c = contacts[i];
      j.begin_object();
      j.key("tri_a").value(static_cast<long long>(c.triangleOther));
      j.key("tri_b").value(static_cast<long long>(c.triangleTool));
      j.key("point_a").vec3(c.pointOther);
      j.key("point_b").vec3(c.pointTool);
      j.key("distance").value(c.distance);
      j.key("feature_a").value(feature_name(c.featureOther));
      j.key("feature_b").value(feature_name(c.featureTool));
      j.key("patch_count").value(static_cast<long long>(patch_of[i].count));
      j.key("patch_extent").value(patch_of[i].extent);
      j.key("patch_spread").value(patch_of[i].spread);
      j.key("patch_angle").value(patch_of[i].angle);
      j.end_object();
    }
    j.end_array();
    j.key("force").vec3(w.force);
    j.key("torque").vec3(w.torque);
    j.key("stats").begin_object();
    j.key("candidates").value(count(r.candidates));
    j.key("node_pairs").value(count(r.nodePairs));
    j.key("leaf_pairs").value(count(r.leafPairs));
    j.key("plane_rejections").value(count(r.planeRejections));
    j.key("visibility_rejections").value(count(r.visibilityRejections));
    j.key("normal_rejections").value(count(r.normalRejections));
    j.key("distance_evaluations").value(count(r.distanceEvaluations));
    j.key("global_ms").value(r.globalSeconds * 1e3);
    j.key("reduction_ms").value(r.reductionSeconds * 1e3);
    j.key("tracking_cache_hits").value(count(r.reductionCacheHits));
    j.end_object();
    j.key("patches").begin_object();
    j.key("lmds").value(static_cast<long long>(ps.lmds));
    j.key("patches").value(static_cast<long long>(ps.patches));
    j.key("merged").value(static_cast<long long>(ps.merged));
    j.key("largest").value(static_cast<long long>(ps.largestPatch));
    j.key("radius_over_cutoff").value(rule.radiusOverCutoff);
    j.key("max_angle_degrees").value(rule.maxAngleDegrees);
    j.key("max_spread_over_cutoff").value(rule.maxSpreadOverCutoff);
    j.key("leaf_budget").value(static_cast<long long>(budget));
    j.key("cut_node_pairs").value(static_cast<long long>(ps.cutNodePairs));
    j.end_object();
    j.key("intersection").begin_object();
    j.key("crossing").value(ps.intersectingPairs > 0);
    j.key("intersecting_pairs").value(count(ps.intersectingPairs));
    j.end_object();
    j.end_object();
    write_file(json_path, j.str() + "\n");
  }
  return 0;
}

}  // namespace proxcli
