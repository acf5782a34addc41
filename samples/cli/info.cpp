// proxima info FILE: a mesh as Proxima sees it.
#include "cli.h"

namespace proxcli {

int info(Args& args) {
  const std::string path = args.next("FILE");
  if (!args.empty()) fail("info: unexpected argument '" + args.peek() + "'");
  double seconds = 0.0;
  const Scene scene(path, &seconds);
  proxMeshInfo m;
  proxMeshStats t;
  check(proxMesh_GetInfo(scene.mesh_a(), &m));
  check(proxMesh_GetStats(scene.mesh_a(), &t));
  const proxVec3 &lo = m.boundsMin, &hi = m.boundsMax;
  std::printf("%s\n", path.c_str());
  std::printf("  triangles        %u (of %u in the file; %u dropped: they repeat a vertex)\n",
              m.triangleCount, t.inputTriangles, m.droppedTriangles);
  std::printf("  vertices         %u welded (of %u in the file)\n", m.vertexCount, t.inputVertices);
  std::printf("  zero-area        %u triangles (kept)\n", t.zeroAreaTriangles);
  std::printf("  boundary edges   %u\n", m.boundaryEdges);
  std::printf("  non-manifold     %u edges\n", m.nonManifoldEdges);
  std::printf("  bounding box     [%.6g, %.6g, %.6g] .. [%.6g, %.6g, %.6g] (size %.6g x %.6g x %.6g)\n", lo.x,
              lo.y, lo.z, hi.x, hi.y, hi.z, hi.x - lo.x, hi.y - lo.y, hi.z - lo.z);
  // Reading, welding and topology: the load call less the hierarchy's build.
  std::printf("  load             %.1f ms\n", std::max(0.0, seconds - t.hierarchySeconds) * 1e3);
  std::printf("  SNCH             %u nodes, depth %u, %u unbounded leaf cones, built in %.1f ms, %.1f MiB\n",
              t.hierarchyNodes, t.hierarchyDepth, t.unboundedLeafCones, t.hierarchySeconds * 1e3,
              static_cast<double>(t.hierarchyBytes) / (1 << 20));
  return 0;
}

}  // namespace proxcli
