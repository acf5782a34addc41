#include "coupling/clearance.h"

#include "contact/descent.h"
#include "geometry/triangle_distance.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace prox::coupling {
namespace {

// Whether boxes `a` and `b` (B's centre moved into A's frame is a.center +
// t) are farther apart than `limit` along one of the six face axes: the
// searches' test (detail::boxes_farther_than), with the axes taken for what
// they are, A's the unit vectors and B's the rotation's columns, so a pair
// takes fewer products. B's axes are unit and orthogonal to rounding
// (1e-16), far inside the test's slack (1e-9 of the extents).
bool boxes_apart(const detail::BoxAxes& axes, const SnchBox& a, const SnchBox& b, const Vec3& t, double limit) {
  const double bound = limit + detail::box_slack(a, b, t);
  for (int k = 0; k < 3; ++k)  // A's axis k: t's k-th component, A's half extent k
    if (std::abs(t[k]) - a.half[k] - glm::dot(b.half, axes.axis[k].wb) > bound) return true;
  for (int k = 0; k < 3; ++k) {  // B's axis k: B's half extent k
    const detail::BoxAxes::Axis& x = axes.axis[3 + k];
    if ((std::abs(glm::dot(t, x.l)) - glm::dot(a.half, x.wa)) * x.inv_len - b.half[k] > bound) return true;
  }
  return false;
}

}  // namespace

bool closer_than(const PairQuery& q, double distance, NodeStack& stack) {
  const Snch& ta = *q.snch_a;
  const Snch& tb = *q.snch_b;
  if (ta.nodes().empty() || tb.nodes().empty() || !(distance > 0.0)) return false;
  const detail::Frames frames(q);
  const Pose& b_to_a = frames.b_to_a;
  // Node pairs whose spheres are `distance` or more apart hold no closer
  // pair (compared squared: no square root per node pair), nor those whose
  // boxes are farther apart than it. The spheres alone let almost every
  // pair of long thin or flat triangles through (CAD: two merged
  // 2CylinderEngines a few mm apart, 1.7 million node pairs a check); the
  // boxes cull those as the searches do (contact/descent.h).
  auto near = [&](std::uint32_t ia, std::uint32_t ib) {
    const SnchNode& a = ta.node(ia);
    const SnchNode& b = tb.node(ib);
    const Vec3 d = b_to_a.apply(b.center) - a.center;
    const double reach = a.radius + b.radius + distance;
    if (!(glm::dot(d, d) < reach * reach)) return false;
    const SnchBox& ba = ta.box(ia);
    const SnchBox& bb = tb.box(ib);
    return !boxes_apart(frames.axes, ba, bb, b_to_a.apply(bb.center) - ba.center, distance);
  };
  stack.clear();
  if (near(0u, 0u)) stack.emplace_back(0u, 0u);
  while (!stack.empty()) {
    const auto [ia, ib] = stack.back();
    stack.pop_back();
    const SnchNode& na = ta.node(ia);
    const SnchNode& nb = tb.node(ib);
    if (na.is_leaf() && nb.is_leaf()) {
      const Triangle a = q.mesh_a->triangle(na.first);
      const Triangle tri_b = q.mesh_b->triangle(nb.first);
      const Triangle b{{b_to_a.apply(tri_b.v[0]), b_to_a.apply(tri_b.v[1]), b_to_a.apply(tri_b.v[2])}};
      if (beyond_plane(a, q.mesh_a->face_normal(na.first), b, distance) ||
          beyond_plane(b, b_to_a.rotate(q.mesh_b->face_normal(nb.first)), a, distance))
        continue;
      if (geometry::triangle_distance_value(a, b, distance) < distance) return true;
      continue;
    }
    // Split the larger node; both children that come close enough go on
    // the stack.
    if (nb.is_leaf() || (!na.is_leaf() && na.radius >= nb.radius)) {
      if (near(na.second, ib)) stack.emplace_back(na.second, ib);
      if (near(na.first, ib)) stack.emplace_back(na.first, ib);
    } else {
      if (near(ia, nb.second)) stack.emplace_back(ia, nb.second);
      if (near(ia, nb.first)) stack.emplace_back(ia, nb.first);
    }
  }
  return false;
}

}  // namespace prox::coupling
