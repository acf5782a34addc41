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
  // A glTF scene's rig (docs/dynamic-scenes.md): its skins, morph weights
  // and animations; nothing for a mesh without one.
  proxRigInfo rig;
  check(proxMesh_GetRigInfo(scene.mesh_a(), &rig));
  if (rig.skinCount > 0) std::printf("  skins            %d (%d joints)\n", rig.skinCount, rig.jointCount);
  constexpr int32_t kListed = 8;  // RecursiveSkeletons has 84 skins
  for (int32_t s = 0; s < std::min(rig.skinCount, kListed); ++s) {
    proxSkinInfo skin;
    check(proxMesh_GetSkinInfo(scene.mesh_a(), s, &skin));
    std::printf("    skin %-11d %d joints%s\n", s, skin.jointCount,
                skin.name[0] ? (" '" + std::string(skin.name) + "'").c_str() : "");
  }
  if (rig.skinCount > kListed) std::printf("    ...              %d more skins\n", rig.skinCount - kListed);
  if (rig.morphWeightCount > 0)
    std::printf("  morph targets    %d weights (over the morphed mesh instances)\n", rig.morphWeightCount);
  if (rig.animationCount > 0) std::printf("  animations       %d\n", rig.animationCount);
  for (int32_t a = 0; a < rig.animationCount; ++a) {
    proxAnimationInfo anim;
    check(proxMesh_GetAnimationInfo(scene.mesh_a(), a, &anim));
    std::printf("    animation %-6d %.6g s (keyframes from %.6g s), %d channels '%s'\n", a, anim.duration,
                anim.start, anim.channelCount, anim.name);
  }
  // What loading skipped without failing (invalid attributes Proxima does
  // not read): one line each; the mesh is loaded all the same.
  int32_t length = 0;
  const proxResult r = proxMesh_GetWarnings(scene.mesh_a(), nullptr, 0, &length);
  if (r != PROX_SUCCESS && r != PROX_ERROR_CAPACITY) check(r);
  if (length > 0) {
    std::string text(static_cast<std::size_t>(length) + 1, '\0');
    check(proxMesh_GetWarnings(scene.mesh_a(), text.data(), length + 1, &length));
    text.resize(static_cast<std::size_t>(length));
    for (std::size_t begin = 0, end; (end = text.find('\n', begin)) != std::string::npos; begin = end + 1)
      std::printf("  warning          %s\n", text.substr(begin, end - begin).c_str());
  }
  return 0;
}

}  // namespace proxcli
