// The simultaneous descent of two SNCHs shared by the searches. Private to
// the contact layer.
#pragma once

#include "contact/global_search.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace prox::detail {

// The searches run in A's local frame; B's nodes and triangles are moved
// into it on the fly.
struct Frames {
  Pose b_to_a;
  explicit Frames(const PairQuery& q) : b_to_a(q.pose_a.inverse() * q.pose_b) {}
};

inline Triangle moved(const Triangle& t, const Pose& pose) {
  return {{pose.apply(t.v[0]), pose.apply(t.v[1]), pose.apply(t.v[2])}};
}

struct NodePair {
  const SnchNode& a;
  Vec3 center_b;  // in A's frame
  double radius_b;
  Vec3 axis_b;  // in A's frame
  double half_b;
  bool cone_b_unbounded;
  bool two_sided_a, two_sided_b;  // open surfaces: each cone counts with its reverse
};

inline bool g1_rejects(const NodePair& p, double cutoff) {
  return glm::length(p.center_b - p.a.center) - p.a.radius - p.radius_b > cutoff;
}

// G2: a local minimum needs a normal of A and a normal of B pointing at each
// other; no such pair exists when the angle between A's axis and the reverse
// of B's exceeds both half-angles together.
inline bool g2_rejects(const NodePair& p) {
  if (p.a.cone.unbounded() || p.cone_b_unbounded) return false;
  const double theta = angle_between(p.a.cone.axis, p.axis_b);
  // Two-sided cones: the axes may point either way; the most favourable
  // orientation decides.
  const double opposite = (p.two_sided_a || p.two_sided_b) ? std::min(theta, kPi - theta) : kPi - theta;
  return opposite > p.a.cone.half_angle + p.half_b;
}

// G3.a / G3.b: every line from sphere A to sphere B lies within sigma of the
// line between the centres; A's cone must reach that cone of lines, and B's
// must reach its reverse.
inline bool g3_rejects(const NodePair& p) {
  const Vec3 between = p.center_b - p.a.center;
  const double dist = glm::length(between);
  const double reach = p.a.radius + p.radius_b;
  if (!(dist > reach)) return false;  // overlapping spheres: lines go everywhere
  const double sigma = std::asin(reach / dist);
  const Vec3 dir = between / dist;
  auto misses = [sigma](const Vec3& d, const Vec3& axis, double half, bool two_sided) {
    const double angle = angle_between(d, axis);
    return (two_sided ? std::min(angle, kPi - angle) : angle) > sigma + half;
  };
  if (!p.a.cone.unbounded() && misses(dir, p.a.cone.axis, p.a.cone.half_angle, p.two_sided_a)) return true;
  if (!p.cone_b_unbounded && misses(-dir, p.axis_b, p.half_b, p.two_sided_b)) return true;
  return false;
}

// Simultaneous descent of both trees; `use_cones` switches G2/G3 on; `leaf`
// is called for every leaf pair that passes.
template <typename Leaf>
void descend(const PairQuery& q, const Frames& frames, bool use_cones, GlobalSearchStats& stats, Leaf leaf) {
  const Snch& ta = *q.snch_a;
  const Snch& tb = *q.snch_b;
  if (ta.nodes().empty() || tb.nodes().empty()) return;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack;
  stack.reserve(256);
  stack.emplace_back(0u, 0u);
  while (!stack.empty()) {
    const auto [ia, ib] = stack.back();
    stack.pop_back();
    ++stats.node_pairs;
    const SnchNode& na = ta.node(ia);
    const SnchNode& nb = tb.node(ib);
    const NodePair p{na,
                     frames.b_to_a.apply(nb.center),
                     nb.radius,
                     frames.b_to_a.rotate(nb.cone.axis),
                     nb.cone.half_angle,
                     nb.cone.unbounded(),
                     ta.two_sided(),
                     tb.two_sided()};
    if (g1_rejects(p, q.cutoff)) {
      ++stats.rejected_g1;
      continue;
    }
    if (use_cones && g2_rejects(p)) {
      ++stats.rejected_g2;
      continue;
    }
    if (use_cones && g3_rejects(p)) {
      ++stats.rejected_g3;
      continue;
    }
    if (na.is_leaf() && nb.is_leaf()) {
      ++stats.leaf_pairs;
      leaf(na.first, nb.first);
    } else if (nb.is_leaf() || (!na.is_leaf() && na.radius >= nb.radius)) {
      stack.emplace_back(na.second, ib);
      stack.emplace_back(na.first, ib);
    } else {
      stack.emplace_back(ia, nb.second);
      stack.emplace_back(ia, nb.first);
    }
  }
}

}  // namespace prox::detail
