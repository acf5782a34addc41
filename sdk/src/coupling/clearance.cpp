#include "coupling/clearance.h"

#include "contact/global_search.h"
#include "geometry/triangle_distance.h"

#include <glm/geometric.hpp>

namespace prox::coupling {

bool closer_than(const PairQuery& q, double distance, NodeStack& stack) {
  const Snch& ta = *q.snch_a;
  const Snch& tb = *q.snch_b;
  if (ta.nodes().empty() || tb.nodes().empty() || !(distance > 0.0)) return false;
  const Pose b_to_a = q.pose_a.inverse() * q.pose_b;
  // Spheres whose gap is at least `distance` hold no closer pair (compared
  // squared: no square root per node pair).
  auto near = [&](const SnchNode& a, const SnchNode& b) {
    const Vec3 d = b_to_a.apply(b.center) - a.center;
    const double reach = a.radius + b.radius + distance;
    return glm::dot(d, d) < reach * reach;
  };
  stack.clear();
  if (near(ta.root(), tb.root())) stack.emplace_back(0u, 0u);
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
      if (geometry::triangle_distance(a, b).distance < distance) return true;
      continue;
    }
    // Split the larger node; both children that come close enough go on
    // the stack.
    if (nb.is_leaf() || (!na.is_leaf() && na.radius >= nb.radius)) {
      if (near(ta.node(na.second), nb)) stack.emplace_back(na.second, ib);
      if (near(ta.node(na.first), nb)) stack.emplace_back(na.first, ib);
    } else {
      if (near(na, tb.node(nb.second))) stack.emplace_back(ia, nb.second);
      if (near(na, tb.node(nb.first))) stack.emplace_back(ia, nb.first);
    }
  }
  return false;
}

}  // namespace prox::coupling
