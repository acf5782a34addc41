#include "fcl_peer.h"

#include "bench_common.h"

#include <fcl/config.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/distance.h>

namespace prox::bench {

struct FclMesh {
  std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> bvh;
};

namespace {

fcl::Transform3d to_fcl(const Pose& p) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  fcl::Matrix3d r;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) r(row, col) = p.rotation[col][row];  // glm is column-major
  tf.linear() = r;
  tf.translation() = fcl::Vector3d(p.translation.x, p.translation.y, p.translation.z);
  return tf;
}

}  // namespace

FclBuild fcl_build(const Mesh& m, int reps) {
  std::vector<fcl::Vector3d> points(m.vertex_count());
  for (std::uint32_t v = 0; v < m.vertex_count(); ++v)
    points[v] = fcl::Vector3d(m.vertex(v).x, m.vertex(v).y, m.vertex(v).z);
  std::vector<fcl::Triangle> triangles(m.triangle_count());
  for (std::uint32_t t = 0; t < m.triangle_count(); ++t)
    triangles[t] = fcl::Triangle(m.indices(t)[0], m.indices(t)[1], m.indices(t)[2]);
  FclBuild out;
  auto mesh = std::make_shared<FclMesh>();
  for (int i = 0; i < reps; ++i) {
    const auto start = Clock::now();
    auto bvh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    bvh->beginModel(static_cast<int>(triangles.size()), static_cast<int>(points.size()));
    bvh->addSubModel(points, triangles);
    bvh->endModel();
    out.seconds.push_back(seconds_since(start));
    mesh->bvh = bvh;
  }
  // What BVHModel::memUsage prints (it returns a status, not the size).
  const auto& bvh = *mesh->bvh;
  out.memory_bytes = sizeof(fcl::BVNode<fcl::OBBRSSd>) * static_cast<std::size_t>(bvh.getNumBVs()) +
                     sizeof(fcl::Triangle) * static_cast<std::size_t>(bvh.num_tris) +
                     sizeof(fcl::Vector3d) * static_cast<std::size_t>(bvh.num_vertices) + sizeof(bvh);
  out.mesh = mesh;
  return out;
}

FclDistance fcl_distance(const FclMesh& a, const FclMesh& b, const Pose& pose_b) {
  static const fcl::Transform3d identity = to_fcl(Pose{});
  const fcl::Transform3d tb = to_fcl(pose_b);
  fcl::DistanceRequestd request;
  fcl::DistanceResultd result;
  const auto start = Clock::now();
  const double d = fcl::distance(a.bvh.get(), identity, b.bvh.get(), tb, request, result);
  return {seconds_since(start), d};
}

const char* fcl_version() { return FCL_VERSION; }

}  // namespace prox::bench
