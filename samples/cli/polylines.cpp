// proxima polylines A B: where two meshes' surfaces cross.
#include "cli.h"

namespace proxcli {

int polylines(Args& args) {
  const std::string path_a = args.next("mesh A"), path_b = args.next("mesh B");
  proxPose pose_a = identity(), pose_b = identity();
  std::string json_path;
  while (!args.empty()) {
    const std::string opt = args.next("option");
    if (opt == "--pose-a")
      pose_a = args.pose("--pose-a");
    else if (opt == "--pose-b")
      pose_b = args.pose("--pose-b");
    else if (opt == "--json")
      json_path = args.next("--json file");
    else
      fail("polylines: unknown option '" + opt + "'");
  }
  const Scene scene(preset(PROX_FORCE_PRESET_HARD), path_a, path_b, pose_a, pose_b);
  // Ask the sizes, then fetch (the polylines are computed on each call).
  int32_t point_count = 0, line_count = 0;
  const proxResult sizes =
      proxBody_GetIntersections(scene.b(), nullptr, 0, &point_count, nullptr, 0, &line_count);
  if (sizes != PROX_ERROR_CAPACITY) check(sizes);
  std::vector<proxVec3> points(static_cast<std::size_t>(point_count));
  std::vector<proxPolylineInfo> lines(static_cast<std::size_t>(line_count));
  check(proxBody_GetIntersections(scene.b(), points.data(), point_count, &point_count, lines.data(),
                                  line_count, &line_count));
  proxIntersectionStats stats;
  check(proxBody_GetIntersectionStats(scene.b(), &stats));
  double total = 0.0;
  for (const proxPolylineInfo& line : lines) {
    const proxVec3* p = points.data() + line.firstPoint;
    double len = 0.0;
    for (int32_t k = 0; k + 1 < line.pointCount; ++k) len += length(sub(p[k + 1], p[k]));
    if (line.closed && line.pointCount > 0) len += length(sub(p[0], p[line.pointCount - 1]));
    total += len;
    std::printf("  %s polyline: %d points, length %.9g\n", line.closed ? "closed" : "open", line.pointCount,
                len);
  }
  std::printf(
      "%zu polylines, total length %.9g; %llu intersecting triangle pairs (%llu coplanar, not traced), "
      "%.3f ms\n",
      lines.size(), total, static_cast<unsigned long long>(stats.intersectingPairs),
      static_cast<unsigned long long>(stats.coplanarPairs), stats.seconds * 1e3);
  if (!json_path.empty()) {
    Json j;
    j.begin_object();
    j.key("polylines").begin_array();
    for (const proxPolylineInfo& line : lines) {
      j.begin_object().key("closed").value(line.closed != 0).key("points").begin_array();
      for (int32_t k = 0; k < line.pointCount; ++k)
        j.vec3(points[static_cast<std::size_t>(line.firstPoint + k)]);
      j.end_array().end_object();
    }
    j.end_array();
    j.key("total_length").value(total);
    j.key("stats").begin_object();
    j.key("intersecting_pairs").value(static_cast<long long>(stats.intersectingPairs));
    j.key("coplanar_pairs").value(static_cast<long long>(stats.coplanarPairs));
    j.key("segments").value(static_cast<long long>(stats.segments));
    j.key("ms").value(stats.seconds * 1e3);
    j.end_object();
    j.end_object();
    write_file(json_path, j.str() + "\n");
  }
  return 0;
}

}  // namespace proxcli
