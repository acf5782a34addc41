#include "contact/global_search.h"

#include "contact/descent.h"

#include "common/worker_pool.h"

#include "geometry/sampled_distance.h"
#include "geometry/triangle_distance.h"
#include "geometry/visibility.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <tuple>
#include <unordered_map>

namespace prox {

MeshFeature mesh_feature(const Mesh& mesh, std::uint32_t triangle, Feature f) {
  switch (f.kind) {
    case FeatureKind::Vertex:
      return {FeatureKind::Vertex, mesh.indices(triangle)[f.index]};
    case FeatureKind::Edge:
      return {FeatureKind::Edge, mesh.edge_id(triangle, f.index)};
    case FeatureKind::Face:
      break;
  }
  return {FeatureKind::Face, triangle};
}

namespace {

using detail::descend;
using detail::Frames;
using detail::moved;

LmdPair make_pair(const PairQuery& q, std::uint32_t ta, std::uint32_t tb, const Vec3& pa_local_a,
                  const Vec3& pb_local_a, double distance, Feature fa, Feature fb) {
  LmdPair r;
  r.tri_a = ta;
  r.tri_b = tb;
  r.point_a = q.pose_a.apply(pa_local_a);
  r.point_b = q.pose_a.apply(pb_local_a);
  r.distance = distance;
  r.feature_a = fa;
  r.feature_b = fb;
  r.mesh_feature_a = mesh_feature(*q.mesh_a, ta, fa);
  r.mesh_feature_b = mesh_feature(*q.mesh_b, tb, fb);
  return r;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

bool beyond_plane(const Triangle& t, const Vec3& n, const Triangle& other, double limit) {
  if (!(glm::dot(n, n) > 0.0)) return false;
  const double d0 = glm::dot(other.v[0] - t.v[0], n);
  const double d1 = glm::dot(other.v[1] - t.v[0], n);
  const double d2 = glm::dot(other.v[2] - t.v[0], n);
  return (d0 > limit && d1 > limit && d2 > limit) || (d0 < -limit && d1 < -limit && d2 < -limit);
}

namespace {

// The precise search's leaf test: whether the pair is a candidate (then
// appended to `out`), counted in `stats`.
struct PreciseLeaf {
  const PairQuery& q;
  const Frames& frames;
  GlobalSearchStats& stats;
  std::vector<LmdPair>& out;

  bool operator()(std::uint32_t ta, std::uint32_t tb) const {
    const Mesh& ma = *q.mesh_a;
    const Mesh& mb = *q.mesh_b;
    const Triangle a = ma.triangle(ta);
    const Triangle b = moved(mb.triangle(tb), frames.b_to_a);
    // A cheap lower bound first (about 10 ns, the visibility test 140): when
    // one triangle lies wholly on one side of the other's plane, farther
    // than the cutoff, so does the pair.
    if (beyond_plane(a, ma.face_normal(ta), b, q.cutoff) ||
        beyond_plane(b, frames.b_to_a.rotate(mb.face_normal(tb)), a, q.cutoff)) {
      ++stats.plane_rejections;
      return false;
    }
    Vec3 na[3], nb[3];
    geometry::Spread sa[3], sb[3];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t va = ma.indices(ta)[k], vb = mb.indices(tb)[k];
      na[k] = ma.vertex_normal(va);
      nb[k] = frames.b_to_a.rotate(mb.vertex_normal(vb));
      sa[k] = q.snch_a->vertex_spread(va);
      sb[k] = q.snch_b->vertex_spread(vb);
    }
    const bool visible = q.visibility == PairQuery::Visibility::Off ? true
                         : q.visibility == PairQuery::Visibility::Paper
                             ? geometry::visibility_pretest(a, na, b, nb)
                             : geometry::visibility_pretest(a, na, sa, b, nb, sb);
    if (!visible) {
      ++stats.visibility_rejections;
      return false;
    }
    ++stats.distance_evaluations;
    // A pair past the cutoff is dropped as soon as that is certain, without
    // its closest points.
    geometry::TriangleDistance d;
    if (!geometry::triangle_distance_within(a, b, q.cutoff, d)) return false;
    if (d.intersects) {
      ++stats.intersecting_pairs;
      return false;
    }
    ++stats.candidates;
    out.push_back(make_pair(q, ta, tb, d.point_a, d.point_b, d.distance, d.feature_a, d.feature_b));
    return true;
  }
};

// The precise descent split over q.pool's threads, with the serial
// descent's answer bit for bit: the node pairs near the roots are visited in
// the serial order until there are 64 per thread (contact lies under few of
// them: many small pieces, handed out one at a time, even the load), and the
// descents below them, each with its own candidates and counts, are joined
// in that order, which is the serial depth-first order. No leaf budget here
// (its count runs across the whole descent, in order).
void precise_split(const PairQuery& q, const Frames& frames, std::vector<LmdPair>& out, GlobalSearchStats& stats) {
  struct Item {
    std::uint32_t a, b;
    bool leaves;  // a leaf pair the split already visited: only its leaf test is left
  };
  const Snch& ta = *q.snch_a;
  const Snch& tb = *q.snch_b;
  const std::size_t want = 64 * std::size_t{q.pool->size()};
  std::vector<Item> items{{0u, 0u, false}}, next;
  // Rounds of visiting every unvisited item and putting its children in its
  // place, in order, until there are enough (or nothing is left to split).
  for (int round = 0; round < 24 && items.size() < want; ++round) {
    next.clear();
    bool split = false;
    for (const Item& it : items) {
      if (it.leaves) {
        next.push_back(it);
        continue;
      }
      switch (detail::visit_node_pair(q, frames, q.use_cones, true, stats, it.a, it.b)) {
        case detail::Visited::Rejected:
          break;
        case detail::Visited::Leaves:
          next.push_back({it.a, it.b, true});
          break;
        case detail::Visited::Inner: {
          const SnchNode &na = ta.node(it.a), &nb = tb.node(it.b);
          if (detail::split_a(na, nb)) {
            next.push_back({na.first, it.b, false});
            next.push_back({na.second, it.b, false});
          } else {
            next.push_back({it.a, nb.first, false});
            next.push_back({it.a, nb.second, false});
          }
          split = true;
          break;
        }
      }
    }
    items.swap(next);
    if (!split) break;
  }
  std::vector<std::vector<LmdPair>> found(items.size());
  std::vector<GlobalSearchStats> counted(items.size());
  q.pool->run(items.size(), [&](std::size_t i) {
    const Item& it = items[i];
    const PreciseLeaf leaf{q, frames, counted[i], found[i]};
    if (it.leaves)
      leaf(ta.node(it.a).first, tb.node(it.b).first);
    else
      descend(q, frames, q.use_cones, true, counted[i], leaf, [](std::uint32_t, std::uint32_t) { return false; },
              it.a, it.b);
  });
  for (std::size_t i = 0; i < items.size(); ++i) {
    out.insert(out.end(), found[i].begin(), found[i].end());
    const double seconds = stats.seconds;
    stats += counted[i];
    stats.seconds = seconds;
  }
}

}  // namespace

void global_search_precise(const PairQuery& q, std::vector<LmdPair>& out, GlobalSearchStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  const Frames frames(q);
  const std::uint64_t budget = q.patches.leaf_budget;
  if (q.pool != nullptr && q.pool->size() > 1 && !q.snch_a->nodes().empty() && !q.snch_b->nodes().empty()) {
    // Split, the budget aside: a search that stays within it never cut in
    // the serial order either, so its answer stands; one that did not is
    // searched again in order, where the budget can cut (rare: a budget is a
    // bound for scenes of huge contact areas).
    std::vector<LmdPair> split;
    GlobalSearchStats split_stats;
    precise_split(q, frames, split, split_stats);
    if (budget == 0 || split_stats.leaf_pairs < budget) {
      out.insert(out.end(), split.begin(), split.end());
      stats += split_stats;
      stats.seconds += seconds_since(start);
      return;
    }
  }
  const PreciseLeaf leaf{q, frames, stats, out};
  // Over the leaf budget, a node pair of patch size (both spheres within the
  // cut radius) gives one candidate, the first of its leaf pairs best first
  // (at most kCutLeaves tried), instead of all of them: the reduction then
  // walks it to a local minimum and the patches merge it. Bigger node pairs
  // are descended as before, so what is cut is bounded by the area within
  // the cutoff over the cut radius squared, whatever the triangles' size.
  constexpr int kCutLeaves = 8;
  const std::uint64_t leaves_before = stats.leaf_pairs;
  const double cut_radius = q.patches.cut_radius(q.cutoff);
  std::vector<detail::RankedNodePair> heap;
  auto cut = [&](std::uint32_t ia, std::uint32_t ib) {
    if (budget == 0 || stats.leaf_pairs - leaves_before < budget) return false;
    if (q.snch_a->node(ia).radius > cut_radius || q.snch_b->node(ib).radius > cut_radius) return false;
    ++stats.cut_node_pairs;
    detail::first_leaf_pair(q, frames, ia, ib, kCutLeaves, heap, [&](std::uint32_t ta, std::uint32_t tb) {
      ++stats.leaf_pairs;
      return leaf(ta, tb);
    });
    return true;
  };
  descend(q, frames, q.use_cones, true, stats, leaf, cut);
  stats.seconds += seconds_since(start);
}

namespace {

// The normal of a feature, for G5: vertex normal, edge normal or face normal.
Vec3 feature_normal(const Mesh& mesh, std::uint32_t t, Feature f) {
  switch (f.kind) {
    case FeatureKind::Vertex:
      return mesh.vertex_normal(mesh.indices(t)[f.index]);
    case FeatureKind::Edge:
      return mesh.edge_normal(t, f.index);
    case FeatureKind::Face:
      break;
  }
  return mesh.face_normal(t);
}

}  // namespace

void global_search_original(const PairQuery& q, std::vector<LmdPair>& out, GlobalSearchStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  const Frames frames(q);
  const Mesh& ma = *q.mesh_a;
  const Mesh& mb = *q.mesh_b;
  descend(q, frames, true, stats, [&](std::uint32_t ta, std::uint32_t tb) {
    ++stats.distance_evaluations;
    const geometry::TriangleDistance d =
        geometry::sampled_triangle_distance(ma.triangle(ta), moved(mb.triangle(tb), frames.b_to_a));
    if (d.distance > q.cutoff) return;
    // G5: the direction must leave A along A's feature normal and arrive at
    // B against B's.
    const Vec3 dir = d.point_b - d.point_a;
    const Vec3 n_a = feature_normal(ma, ta, d.feature_a);
    const Vec3 n_b = frames.b_to_a.rotate(feature_normal(mb, tb, d.feature_b));
    if (!(glm::dot(dir, n_a) > 0.0 && glm::dot(dir, n_b) < 0.0)) {
      ++stats.normal_rejections;
      return;
    }
    ++stats.candidates;
    out.push_back(make_pair(q, ta, tb, d.point_a, d.point_b, d.distance, d.feature_a, d.feature_b));
  });
  stats.seconds += seconds_since(start);
}

namespace {

// Branch and bound for the closest pair below `bound`. Node pairs are ranked
// by the lower bound their spheres and boxes give (node_pair_distance_bound;
// no pair of triangles below them is closer), and a pair whose bound is past
// the best found is dropped. Best first (a heap) until the first pair of
// leaves, which is then near the answer, so the bound is tight from the
// start; then depth first, the nearer child pair first, and the heap's
// pairs, nearest first, whenever a dive has run out. Best first all the way
// visits about a tenth fewer node pairs, but far from contact, where
// thousands of them are below the answer, its heap's sifts were a third of
// its time; depth first from the roots, with no bound yet, dives into the
// wrong half where the boxes are loose (a turned mesh: path R near contact
// took 2.5 times as long). The measurements are in
// docs/benchmarks-changes.md. At leaves the plane bound of the precise
// search skips most exact distances, and the rest are cut short past the
// best so far. With `first_below` it returns as soon as any pair is closer
// than the bound.
double closest_pair(const PairQuery& q, double bound, bool first_below, std::uint32_t* tri_a,
                    std::uint32_t* tri_b) {
  using detail::RankedNodePair;
  const Frames frames(q);
  const Snch& ta = *q.snch_a;
  const Snch& tb = *q.snch_b;
  double best = INFINITY;
  if (ta.nodes().empty() || tb.nodes().empty()) return best;
  double limit = bound;
  // Best first until the first leaf pair: `heap`, nearest on top. Then
  // depth first: `stack`, the farther child pairs put aside; the heap's
  // pairs are taken once the stack is empty, nearest first, until the
  // nearest is past the best found.
  std::vector<RankedNodePair> heap, stack;
  heap.reserve(128);
  stack.reserve(128);
  bool depth_first = false;
  RankedNodePair item{detail::node_pair_distance_bound(q, frames, 0u, 0u, limit), 0u, 0u};
  // `item` is the next pair (the roots, then the nearer child of the last
  // split), taken only within the limit.
  bool held = item.key <= limit;
  while (true) {
    if (!held) {
      if (!stack.empty()) {
        item = stack.back();
        stack.pop_back();
        if (item.key > limit) continue;  // the best found since it was put aside is closer
      } else {
        if (heap.empty()) break;
        std::pop_heap(heap.begin(), heap.end());
        item = heap.back();
        heap.pop_back();
        if (item.key > limit) break;  // so is everything left in the heap
      }
    }
    held = false;
    const SnchNode& na = ta.node(item.a);
    const SnchNode& nb = tb.node(item.b);
    if (na.is_leaf() && nb.is_leaf()) {
      depth_first = true;
      const Triangle a = q.mesh_a->triangle(na.first);
      const Triangle b = moved(q.mesh_b->triangle(nb.first), frames.b_to_a);
      if (beyond_plane(a, q.mesh_a->face_normal(na.first), b, limit) ||
          beyond_plane(b, frames.b_to_a.rotate(q.mesh_b->face_normal(nb.first)), a, limit))
        continue;
      // The distance alone, and only if within the limit (+infinity past it).
      const double d = geometry::triangle_distance_value(a, b, limit);
      if (d < best) {
        best = d;
        limit = std::min(limit, d);
        if (tri_a) *tri_a = na.first;
        if (tri_b) *tri_b = nb.first;
        if (d == 0.0 || (first_below && d < bound)) break;
      }
      continue;
    }
    RankedNodePair child[2];
    int n = 0;
    detail::for_child_pairs(ta, tb, item.a, item.b, [&](std::uint32_t ia, std::uint32_t ib) {
      child[n++] = {detail::node_pair_distance_bound(q, frames, ia, ib, limit), ia, ib};
    });
    if (child[1].key < child[0].key) std::swap(child[0], child[1]);
    if (depth_first) {
      if (child[1].key <= limit) stack.push_back(child[1]);
      if (child[0].key <= limit) item = child[0], held = true;
    } else {
      for (const RankedNodePair& c : child) {
        if (c.key > limit) continue;
        heap.push_back(c);
        std::push_heap(heap.begin(), heap.end());
      }
    }
  }
  return best;
}

}  // namespace

double minimum_distance(const PairQuery& q, double bound, std::uint32_t* tri_a, std::uint32_t* tri_b) {
  return closest_pair(q, bound, false, tri_a, tri_b);
}

bool any_closer_than(const PairQuery& q, double distance) {
  return closest_pair(q, distance, true, nullptr, nullptr) < distance;
}

void feature_neighbourhood(const Mesh& mesh, std::uint32_t t, Feature f, std::vector<std::uint32_t>& out) {
  out.clear();
  switch (f.kind) {
    case FeatureKind::Vertex: {
      const std::uint32_t v = mesh.indices(t)[f.index];
      out.insert(out.end(), mesh.vertex_triangles_begin(v), mesh.vertex_triangles_end(v));
      return;
    }
    case FeatureKind::Edge:
      out.insert(out.end(), mesh.edge_triangles_begin(t, f.index), mesh.edge_triangles_end(t, f.index));
      return;
    case FeatureKind::Face:
      out.push_back(t);
      return;
  }
}

void reference_lmds(const PairQuery& q, std::vector<LmdPair>& out) {
  const Frames frames(q);
  const Mesh& ma = *q.mesh_a;
  const Mesh& mb = *q.mesh_b;
  // Every pair whose bounding spheres are within the cutoff (G1 only: a
  // provable bound, so no pair within the cutoff is missed).
  std::unordered_map<std::uint64_t, geometry::TriangleDistance> near;
  std::vector<std::uint64_t> order;
  GlobalSearchStats unused;
  descend(q, frames, false, unused, [&](std::uint32_t ta, std::uint32_t tb) {
    near.emplace(pair_key(ta, tb),
                 geometry::triangle_distance(ma.triangle(ta), moved(mb.triangle(tb), frames.b_to_a)));
    order.push_back(pair_key(ta, tb));
  });
  std::sort(order.begin(), order.end());

  // Strictly closer means closer by more than rounding, relative to the models.
  const double size = std::max(glm::length(ma.bounds().max - ma.bounds().min),
                               glm::length(mb.bounds().max - mb.bounds().min));
  const double tolerance = 1e-12 * size;
  std::vector<std::uint32_t> around_a, around_b;
  std::set<std::tuple<int, std::uint32_t, int, std::uint32_t>> seen;  // feature pairs already output
  for (const std::uint64_t key : order) {
    const geometry::TriangleDistance& d = near.at(key);
    if (d.intersects || d.distance > q.cutoff) continue;
    const auto ta = static_cast<std::uint32_t>(key >> 32), tb = static_cast<std::uint32_t>(key & 0xFFFFFFFFu);
    feature_neighbourhood(ma, ta, d.feature_a, around_a);
    feature_neighbourhood(mb, tb, d.feature_b, around_b);
    bool local_minimum = true;
    for (std::uint32_t na : around_a) {
      for (std::uint32_t nb : around_b) {
        // A neighbour pair missing from `near` has spheres beyond the
        // cutoff, so it is no closer than this pair.
        const auto it = near.find(pair_key(na, nb));
        if (it != near.end() && (it->second.intersects || it->second.distance < d.distance - tolerance)) {
          local_minimum = false;
          break;
        }
      }
      if (!local_minimum) break;
    }
    if (!local_minimum) continue;
    const MeshFeature fa = mesh_feature(ma, ta, d.feature_a), fb = mesh_feature(mb, tb, d.feature_b);
    if (!seen.emplace(static_cast<int>(fa.kind), fa.id, static_cast<int>(fb.kind), fb.id).second) continue;
    out.push_back(make_pair(q, ta, tb, d.point_a, d.point_b, d.distance, d.feature_a, d.feature_b));
  }
}

}  // namespace prox
