#include "coal_peer.h"

#include <coal/BVH/BVH_model.h>
#include <coal/collision.h>
#include <coal/config.hh>

#include <chrono>
#include <limits>
#include <vector>

namespace prox::bench {

struct CoalMesh {
  std::shared_ptr<coal::BVHModel<coal::OBBRSS>> bvh;
};

namespace {

coal::Transform3s to_coal(const Pose& p) {
  coal::Matrix3s r;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) r(row, col) = p.rotation[col][row];  // glm is column-major
  return coal::Transform3s(r, coal::Vec3s(p.translation.x, p.translation.y, p.translation.z));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

CoalBuild coal_build(const Mesh& mesh) {
  std::vector<coal::Vec3s> points(mesh.vertex_count());
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v)
    points[v] = coal::Vec3s(mesh.vertex(v).x, mesh.vertex(v).y, mesh.vertex(v).z);
  std::vector<coal::Triangle> triangles(mesh.triangle_count());
  for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t)
    triangles[t] = coal::Triangle(mesh.indices(t)[0], mesh.indices(t)[1], mesh.indices(t)[2]);
  const auto start = std::chrono::steady_clock::now();
  auto out = std::make_shared<CoalMesh>();
  out->bvh = std::make_shared<coal::BVHModel<coal::OBBRSS>>();
  out->bvh->beginModel(static_cast<unsigned>(triangles.size()), static_cast<unsigned>(points.size()));
  out->bvh->addSubModel(points, triangles);
  out->bvh->endModel();
  return {out, seconds_since(start)};
}

CoalMargin coal_margin_collide(const CoalMesh& a, const CoalMesh& b, const Pose& pose_b, double margin) {
  // No contact details (points, normals, depths) are asked for: only the
  // pairs, which is the least Coal can be asked to do for this answer.
  coal::CollisionRequest request(coal::NO_REQUEST, std::numeric_limits<std::size_t>::max());
  request.security_margin = margin;
  coal::CollisionResult result;
  const coal::Transform3s ta = coal::Transform3s::Identity(), tb = to_coal(pose_b);
  const auto start = std::chrono::steady_clock::now();
  coal::collide(a.bvh.get(), ta, b.bvh.get(), tb, request, result);
  CoalMargin out;
  out.seconds = seconds_since(start);
  out.pairs = result.numContacts();
  out.min_distance = result.distance_lower_bound;
  return out;
}

std::string coal_version() { return COAL_VERSION; }

}  // namespace prox::bench
