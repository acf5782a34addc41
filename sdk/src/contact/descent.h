// The simultaneous descent of two SNCHs shared by the searches. Private to
// the contact layer, and the constrained proxy's exact check
// (coupling/clearance.cpp), which culls with the same box test.
#pragma once

#include "contact/global_search.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace prox::detail {

// The 15 separating axes of A's boxes against B's (SnchBox: every box of a
// mesh has its mesh's axes), in A's frame: A's three axes, B's three, and
// their nine cross products. They depend only on the rotation between the
// meshes, so they are set up once per search.
struct BoxAxes {
  struct Axis {
    Vec3 l;          // the axis, not normalised
    Vec3 wa, wb;     // |l . A_k| and |l . B_k|: a box's reach along l is dot(half, w)
    double inv_len;  // 1 / |l|
  };
  Axis axis[15];
  int count = 0;

  explicit BoxAxes(const glm::dmat3& rotation_b_to_a) {
    const Vec3 e[3] = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    const Vec3 b[3] = {rotation_b_to_a[0], rotation_b_to_a[1], rotation_b_to_a[2]};  // glm: columns
    auto add = [&](const Vec3& l) {
      const double len = glm::length(l);
      // Nearly parallel edges give an axis whose projections are all
      // rounding; the face axes cover that case.
      if (!(len > 1e-6)) return;
      Axis& x = axis[count++];
      x.l = l;
      for (int k = 0; k < 3; ++k)
        x.wa[k] = std::abs(glm::dot(l, e[k])), x.wb[k] = std::abs(glm::dot(l, b[k]));
      x.inv_len = 1.0 / len;
    };
    for (const Vec3& a : e) add(a);
    for (const Vec3& v : b) add(v);
    for (const Vec3& a : e)
      for (const Vec3& v : b) add(glm::cross(a, v));
  }
};

// The searches run in A's local frame; B's nodes and triangles are moved
// into it on the fly.
struct Frames {
  Pose b_to_a;
  BoxAxes axes;
  bool slabs;  // both trees have their slabs (a refitted one has none)
  explicit Frames(const PairQuery& q)
      : b_to_a(q.pose_a.inverse() * q.pose_b),
        axes(b_to_a.rotation),
        slabs(q.snch_a->has_slabs() && q.snch_b->has_slabs()) {}
};

// Rounding in the projections, bounded generously: a box test never rejects
// a pair closer than its limit by less than this.
inline double box_slack(const SnchBox& a, const SnchBox& b, const Vec3& t) {
  const Vec3 s = glm::abs(t) + a.half + b.half;
  return 1e-9 * (s.x + s.y + s.z);
}

// Whether boxes `a` and `b` (B's box centre moved into A's frame is
// a.center + t) are more than `limit` apart: along some separating axis the
// gap between their projections exceeds it, a lower bound on the distance.
// Only the six face axes: on cad-engine the nine edge axes rejected no node
// pair the face axes let through, and cost more than the face axes.
inline bool boxes_farther_than(const BoxAxes& axes, const SnchBox& a, const SnchBox& b, const Vec3& t,
                               double limit) {
  const double slack = box_slack(a, b, t);
  for (int i = 0; i < 6; ++i) {  // the face axes come first and are never skipped
    const BoxAxes::Axis& x = axes.axis[i];
    const double gap = std::abs(glm::dot(t, x.l)) - glm::dot(a.half, x.wa) - glm::dot(b.half, x.wb);
    if (gap * x.inv_len > limit + slack) return true;
  }
  return false;
}

// The largest of those gaps (a lower bound on the distance between the
// boxes, less the rounding slack; may be negative).
inline double box_lower_bound(const BoxAxes& axes, const SnchBox& a, const SnchBox& b, const Vec3& t) {
  double best = -INFINITY;
  for (int i = 0; i < axes.count; ++i) {
    const BoxAxes::Axis& x = axes.axis[i];
    const double gap = std::abs(glm::dot(t, x.l)) - glm::dot(a.half, x.wa) - glm::dot(b.half, x.wb);
    best = std::max(best, gap * x.inv_len);
  }
  return best - box_slack(a, b, t);
}

inline Triangle moved(const Triangle& t, const Pose& pose) {
  return {{pose.apply(t.v[0]), pose.apply(t.v[1]), pose.apply(t.v[2])}};
}

struct NodePair {
  const SnchNode& a;
  const SnchNode& b;
  Vec3 center_b;                  // in A's frame
  Vec3 axis_b;                    // in A's frame
  bool two_sided_a, two_sided_b;  // open surfaces: each cone counts with its reverse
};

inline bool g1_rejects(const NodePair& p, double cutoff) {
  const double reach = p.a.radius + p.b.radius + cutoff;
  const Vec3 d = p.center_b - p.a.center;
  return glm::dot(d, d) > reach * reach;
}

// cos(x + y) from the cosines and sines of x and y, for x, y in [0, pi]; -1
// when x + y >= pi (then every angle is within x + y).
inline double cos_sum(double cx, double sx, double cy, double sy) {
  if (cx * cy - sx * sy <= -1.0) return -1.0;
  // x + y >= pi exactly when cos(x) <= cos(pi - y) = -cos(y).
  if (cx <= -cy) return -1.0;
  return cx * cy - sx * sy;
}

// G2: a local minimum needs a normal of A and a normal of B pointing at each
// other; no such pair exists when the angle between A's axis and the reverse
// of B's exceeds both half-angles together. In cosines: reject when
// cos(angle(a, -b)) < cos(phi_a + phi_b).
inline bool g2_rejects(const NodePair& p) {
  if (p.a.cone.unbounded() || p.b.cone.unbounded()) return false;
  const double limit = cos_sum(p.a.cone.cos, p.a.cone.sin, p.b.cone.cos, p.b.cone.sin);
  if (limit <= -1.0) return false;
  const double c = -glm::dot(p.a.cone.axis, p.axis_b);
  // Two-sided cones: the axes may point either way; the most favourable
  // orientation decides.
  return ((p.two_sided_a || p.two_sided_b) ? std::abs(c) : c) < limit;
}

// G3.a / G3.b: every line from sphere A to sphere B lies within sigma of the
// line between the centres (sin sigma = (rho_a + rho_b) / distance); A's cone
// must reach that cone of lines, and B's must reach its reverse.
inline bool g3_rejects(const NodePair& p) {
  const Vec3 between = p.center_b - p.a.center;
  const double dist2 = glm::dot(between, between);
  const double reach = p.a.radius + p.b.radius;
  if (!(dist2 > reach * reach)) return false;  // overlapping spheres: lines go everywhere
  const double dist = std::sqrt(dist2);
  const double sin_sigma = reach / dist, cos_sigma = std::sqrt(1.0 - sin_sigma * sin_sigma);
  const Vec3 dir = between / dist;
  auto misses = [&](const SnchNode& n, const Vec3& d, const Vec3& axis, bool two_sided) {
    if (n.cone.unbounded()) return false;
    const double limit = cos_sum(cos_sigma, sin_sigma, n.cone.cos, n.cone.sin);
    if (limit <= -1.0) return false;
    const double c = glm::dot(d, axis);
    return (two_sided ? std::abs(c) : c) < limit;
  };
  return misses(p.a, dir, p.a.cone.axis, p.two_sided_a) || misses(p.b, -dir, p.axis_b, p.two_sided_b);
}

// The gap between the slabs of node `ia` of A and node `ib` of B (SnchSlab),
// each along its own axis: along A's axis A spans its slab and B at most its
// slab turned onto that axis plus its sphere's reach across its own (and
// likewise along B's). A lower bound on their triangles' distance, less
// the rounding; may be negative. `d` is B's sphere centre less A's, in A's
// frame, `mb` B's cone axis turned into A's frame. Two nearly flat patches
// facing each other, however turned, bound almost exactly.
inline double slab_gap(const PairQuery& q, std::uint32_t ia, std::uint32_t ib, const Vec3& d, const Vec3& mb) {
  const SnchNode &na = q.snch_a->node(ia), &nb = q.snch_b->node(ib);
  const SnchSlab &sa = q.snch_a->slab(ia), &sb = q.snch_b->slab(ib);
  const Vec3& ma = na.cone.axis;
  const double k = glm::dot(ma, mb);
  const double sin = glm::length(glm::cross(ma, mb)) + 1e-15;
  const double along_a = glm::dot(d, ma), along_b = -glm::dot(d, mb);
  const double b_lo = along_a + std::min(sb.lo * k, sb.hi * k) - nb.radius * sin;
  const double b_hi = along_a + std::max(sb.lo * k, sb.hi * k) + nb.radius * sin;
  const double a_lo = along_b + std::min(sa.lo * k, sa.hi * k) - na.radius * sin;
  const double a_hi = along_b + std::max(sa.lo * k, sa.hi * k) + na.radius * sin;
  const double gap = std::max(std::max(b_lo - sa.hi, sa.lo - b_hi), std::max(a_lo - sb.hi, sb.lo - a_hi));
  return gap - 1e-12 * (std::abs(along_a) + std::abs(along_b) + na.radius + nb.radius);
}

// Which node of a pair the descents split: A's unless B's is the larger
// (or A's is a leaf and B's is not).
inline bool split_a(const SnchNode& na, const SnchNode& nb) {
  return nb.is_leaf() || (!na.is_leaf() && na.radius >= nb.radius);
}

// Calls f(ia', ib') for the two child pairs of the inner node pair (ia, ib).
template <typename F>
void for_child_pairs(const Snch& ta, const Snch& tb, std::uint32_t ia, std::uint32_t ib, F f) {
  const SnchNode &na = ta.node(ia), &nb = tb.node(ib);
  if (split_a(na, nb)) {
    f(na.first, ib);
    f(na.second, ib);
  } else {
    f(ia, nb.first);
    f(ia, nb.second);
  }
}

// What descend() makes of one node pair, counted in `stats`: rejected by
// G1 (and the box and slab tests with `use_boxes`), G2 or G3 (with `use_cones`), or
// passed, as a pair of leaves or with inner nodes to split.
enum class Visited { Rejected, Leaves, Inner };
inline Visited visit_node_pair(const PairQuery& q, const Frames& frames, bool use_cones, bool use_boxes,
                               GlobalSearchStats& stats, std::uint32_t ia, std::uint32_t ib) {
  const Snch& ta = *q.snch_a;
  const Snch& tb = *q.snch_b;
  ++stats.node_pairs;
  const SnchNode& na = ta.node(ia);
  const SnchNode& nb = tb.node(ib);
  const NodePair p{na,
                   nb,
                   frames.b_to_a.apply(nb.center),
                   frames.b_to_a.rotate(nb.cone.axis),
                   ta.two_sided(),
                   tb.two_sided()};
  if (g1_rejects(p, q.cutoff) ||
      (use_boxes && boxes_farther_than(frames.axes, ta.box(ia), tb.box(ib),
                                       frames.b_to_a.apply(tb.box(ib).center) - ta.box(ia).center, q.cutoff))) {
    ++stats.rejected_g1;
    return Visited::Rejected;
  }
  if (use_boxes && frames.slabs && slab_gap(q, ia, ib, p.center_b - na.center, p.axis_b) > q.cutoff) {
    ++stats.rejected_g1;
    return Visited::Rejected;
  }
  if (use_cones && g2_rejects(p)) {
    ++stats.rejected_g2;
    return Visited::Rejected;
  }
  if (use_cones && g3_rejects(p)) {
    ++stats.rejected_g3;
    return Visited::Rejected;
  }
  if (na.is_leaf() && nb.is_leaf()) {
    ++stats.leaf_pairs;
    return Visited::Leaves;
  }
  return Visited::Inner;
}

// Simultaneous descent of both trees from node pair (root_a, root_b);
// `use_cones` switches G2/G3 on; `use_boxes` adds the box test to G1's
// sphere test (the same pairs within the cutoff reach the leaves, far fewer
// beyond it); `leaf` is called for every leaf pair that passes, depth first,
// first children first. `cut(ia, ib)` is asked about every inner node pair
// that passes: when it returns true, the pair is taken as handled and not
// descended.
template <typename Leaf, typename Cut>
void descend(const PairQuery& q, const Frames& frames, bool use_cones, bool use_boxes,
             GlobalSearchStats& stats, Leaf leaf, Cut cut, std::uint32_t root_a = 0, std::uint32_t root_b = 0) {
  const Snch& ta = *q.snch_a;
  const Snch& tb = *q.snch_b;
  if (ta.nodes().empty() || tb.nodes().empty()) return;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack;
  stack.reserve(256);
  stack.emplace_back(root_a, root_b);
  while (!stack.empty()) {
    const auto [ia, ib] = stack.back();
    stack.pop_back();
    switch (visit_node_pair(q, frames, use_cones, use_boxes, stats, ia, ib)) {
      case Visited::Rejected:
        break;
      case Visited::Leaves:
        leaf(ta.node(ia).first, tb.node(ib).first);
        break;
      case Visited::Inner: {
        if (cut(ia, ib)) break;
        const SnchNode &na = ta.node(ia), &nb = tb.node(ib);
        if (split_a(na, nb)) {
          stack.emplace_back(na.second, ib);
          stack.emplace_back(na.first, ib);
        } else {
          stack.emplace_back(ia, nb.second);
          stack.emplace_back(ia, nb.first);
        }
        break;
      }
    }
  }
}

// Every node pair that passes is descended.
template <typename Leaf>
void descend(const PairQuery& q, const Frames& frames, bool use_cones, bool use_boxes,
             GlobalSearchStats& stats, Leaf leaf) {
  descend(q, frames, use_cones, use_boxes, stats, leaf, [](std::uint32_t, std::uint32_t) { return false; });
}

// Spheres only (the baseline, the reference and the polylines).
template <typename Leaf>
void descend(const PairQuery& q, const Frames& frames, bool use_cones, GlobalSearchStats& stats, Leaf leaf) {
  descend(q, frames, use_cones, false, stats, leaf);
}

// The gap between the bounding spheres of nodes `na` of A and `nb` of B,
// `d` apart in A's frame (negative where they overlap): a lower bound on
// their triangles' distance.
inline double sphere_gap(const SnchNode& na, const SnchNode& nb, const Vec3& d) {
  return glm::length(d) - na.radius - nb.radius;
}
inline double sphere_gap(const PairQuery& q, const Frames& frames, std::uint32_t ia, std::uint32_t ib) {
  const SnchNode &na = q.snch_a->node(ia), &nb = q.snch_b->node(ib);
  return sphere_gap(na, nb, frames.b_to_a.apply(nb.center) - na.center);
}

// A lower bound on the distance between the triangles below node `ia` of A
// and node `ib` of B: the better of the spheres' and the boxes' bounds. The
// patches rank a cut's leaf pairs by it (first_leaf_pair).
inline double node_pair_lower_bound(const PairQuery& q, const Frames& frames, std::uint32_t ia,
                                    std::uint32_t ib) {
  const SnchBox &ba = q.snch_a->box(ia), &bb = q.snch_b->box(ib);
  return std::max(sphere_gap(q, frames, ia, ib),
                  box_lower_bound(frames.axes, ba, bb, frames.b_to_a.apply(bb.center) - ba.center));
}

// A lower bound on the distance between the triangles below node `ia` of A
// and node `ib` of B for a branch and bound on the distance: the better of
// the spheres' bound and the distance from A's box to the box, along A's
// axes, around B's (the norm of the gaps along A's three axes, where
// box_lower_bound takes the largest gap along fifteen). On paths T and R and
// the CAD scenes it costs less and bounds more tightly than that (the
// closest-pair search far from contact on path T: 5.1 -> 2.2 times FCL's
// time, docs/benchmarks-changes.md).
// Past `limit` it may return the boxes' bound alone (still past the limit):
// the spheres' is not computed for a pair the boxes already reject.
inline double node_pair_distance_bound(const PairQuery& q, const Frames& frames, std::uint32_t ia,
                                       std::uint32_t ib,
                                       double limit = std::numeric_limits<double>::infinity()) {
  const SnchBox &ba = q.snch_a->box(ia), &bb = q.snch_b->box(ib);
  const Vec3 t = frames.b_to_a.apply(bb.center) - ba.center;
  double gaps2 = 0.0;
  for (int k = 0; k < 3; ++k) {  // A's axis k: B's box reaches dot(half, wb) along it
    const double gap = std::abs(t[k]) - ba.half[k] - glm::dot(bb.half, frames.axes.axis[k].wb);
    if (gap > 0.0) gaps2 += gap * gap;
  }
  const double boxes = std::sqrt(gaps2) - box_slack(ba, bb, t);
  if (boxes > limit) return boxes;
  const SnchNode &na = q.snch_a->node(ia), &nb = q.snch_b->node(ib);
  const Vec3 d = frames.b_to_a.apply(nb.center) - na.center;
  const double bound = std::max(sphere_gap(na, nb, d), boxes);
  if (!frames.slabs) return bound;
  return std::max(bound, slab_gap(q, ia, ib, d, frames.b_to_a.rotate(nb.cone.axis)));
}

// A node pair in a best-first search's heap, smallest key on top.
struct RankedNodePair {
  double key;
  std::uint32_t a, b;
  bool operator<(const RankedNodePair& o) const { return key > o.key; }  // min-heap
};

// The leaf pairs below node pair (ia, ib) best first, until `leaf(ta, tb)`
// returns true or `max_leaves` leaf pairs were tried: the representative of
// a cut node pair. Best is the smaller lower bound; where lower bounds tie
// (flat, parallel boxes all bound at the gap) the pair whose spheres' centres
// are closer, by adding a thousandth of that distance. `heap` is scratch.
template <typename Leaf>
bool first_leaf_pair(const PairQuery& q, const Frames& frames, std::uint32_t ia, std::uint32_t ib,
                     int max_leaves, std::vector<RankedNodePair>& heap, Leaf leaf) {
  const Snch& ta = *q.snch_a;
  const Snch& tb = *q.snch_b;
  auto rank = [&](std::uint32_t a, std::uint32_t b) {
    const double centres = glm::length(frames.b_to_a.apply(tb.node(b).center) - ta.node(a).center);
    heap.push_back({node_pair_lower_bound(q, frames, a, b) + 1e-3 * centres, a, b});
    std::push_heap(heap.begin(), heap.end());
  };
  heap.clear();
  rank(ia, ib);
  int tried = 0;
  while (!heap.empty() && tried < max_leaves) {
    std::pop_heap(heap.begin(), heap.end());
    const RankedNodePair p = heap.back();
    heap.pop_back();
    const SnchNode& na = ta.node(p.a);
    const SnchNode& nb = tb.node(p.b);
    if (na.is_leaf() && nb.is_leaf()) {
      ++tried;
      if (leaf(na.first, nb.first)) return true;
    } else {
      for_child_pairs(ta, tb, p.a, p.b, rank);
    }
  }
  return false;
}

}  // namespace prox::detail
