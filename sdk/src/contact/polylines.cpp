#include "contact/polylines.h"

#include "contact/descent.h"
#include "geometry/predicates.h"
#include "geometry/triangle_intersection.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <unordered_map>

namespace prox {
namespace {

// An endpoint of an intersection segment is where an edge of one mesh
// crosses a triangle of the other. The segments of neighbouring triangle
// pairs share such crossings, which is how they chain. Crossings at the same
// place (a vertex lying exactly on the other surface) are one node.
struct CrossingKey {
  std::uint32_t side;      // 0: an edge of A crosses a triangle of B; 1: the reverse
  std::uint32_t edge;      // mesh edge id
  std::uint32_t triangle;  // the crossed triangle
  bool operator==(const CrossingKey& o) const {
    return side == o.side && edge == o.edge && triangle == o.triangle;
  }
};

struct KeyHash {
  std::size_t operator()(const CrossingKey& k) const {
    return std::hash<std::uint64_t>()((std::uint64_t{k.side} << 63) ^ (std::uint64_t{k.edge} << 32) ^
                                      k.triangle);
  }
};

struct PointHash {
  std::size_t operator()(const Vec3& p) const {
    std::uint64_t bits[3];
    std::memcpy(bits, &p, sizeof bits);
    return std::hash<std::uint64_t>()(bits[0] * 0x9E3779B97F4A7C15ULL ^ bits[1] * 0xC2B2AE3D27D4EB4FULL ^
                                      bits[2]);
  }
};

class Graph {
 public:
  // The node of a crossing, created on first sight; crossings at the same
  // point share a node.
  std::uint32_t node(const CrossingKey& key, const Vec3& point) {
    const auto k = by_key_.find(key);
    if (k != by_key_.end()) return k->second;
    const auto p = by_point_.find(point);
    const std::uint32_t n = p != by_point_.end() ? p->second : add(point);
    by_key_.emplace(key, n);
    return n;
  }
  void connect(std::uint32_t a, std::uint32_t b) {
    if (a == b) return;
    edges_.push_back({a, b});
    degree_[a]++, degree_[b]++;
  }

  // Walks the graph into polylines: open chains from their ends first, then
  // the remaining loops.
  void polylines(const Pose& to_world, std::vector<Polyline>& out) {
    std::vector<std::vector<std::uint32_t>> adjacent(points_.size());
    for (std::uint32_t e = 0; e < edges_.size(); ++e) {
      adjacent[edges_[e].first].push_back(e);
      adjacent[edges_[e].second].push_back(e);
    }
    std::vector<bool> used(edges_.size(), false);
    auto walk = [&](std::uint32_t start) {
      Polyline line;
      std::uint32_t at = start;
      line.points.push_back(to_world.apply(points_[at]));
      for (;;) {
        std::uint32_t next_edge = kNone;
        for (std::uint32_t e : adjacent[at])
          if (!used[e]) {
            next_edge = e;
            break;
          }
        if (next_edge == kNone) break;
        used[next_edge] = true;
        at = edges_[next_edge].first == at ? edges_[next_edge].second : edges_[next_edge].first;
        if (at == start) {
          line.closed = true;
          break;
        }
        line.points.push_back(to_world.apply(points_[at]));
      }
      if (line.points.size() >= 2) out.push_back(std::move(line));
    };
    for (std::uint32_t n = 0; n < points_.size(); ++n)
      if (degree_[n] % 2 == 1) walk(n);
    for (std::uint32_t n = 0; n < points_.size(); ++n)
      while (std::any_of(adjacent[n].begin(), adjacent[n].end(), [&](std::uint32_t e) { return !used[e]; }))
        walk(n);
  }

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::uint32_t add(const Vec3& point) {
    const auto n = static_cast<std::uint32_t>(points_.size());
    points_.push_back(point);
    degree_.push_back(0);
    by_point_.emplace(point, n);
    return n;
  }
  std::unordered_map<CrossingKey, std::uint32_t, KeyHash> by_key_;
  std::unordered_map<Vec3, std::uint32_t, PointHash> by_point_;
  std::vector<Vec3> points_;
  std::vector<std::uint32_t> degree_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges_;
};

}  // namespace

void intersection_polylines(const PairQuery& query, std::vector<Polyline>& out, PolylineStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  PairQuery q = query;
  q.cutoff = 0.0;  // spheres must overlap
  const detail::Frames frames(q);
  const Mesh& ma = *q.mesh_a;
  const Mesh& mb = *q.mesh_b;
  Graph graph;
  GlobalSearchStats descent;
  detail::descend(q, frames, false, descent, [&](std::uint32_t ta, std::uint32_t tb) {
    const Triangle a = ma.triangle(ta);
    const Triangle b = detail::moved(mb.triangle(tb), frames.b_to_a);
    if (!geometry::triangles_intersect(a, b)) return;
    ++stats.intersecting_pairs;
    const bool a_flat = geometry::collinear3d(a.v[0], a.v[1], a.v[2]);
    const bool b_flat = geometry::collinear3d(b.v[0], b.v[1], b.v[2]);
    if (!a_flat && !b_flat) {
      bool coplanar = true;
      for (const Vec3& v : b.v) coplanar = coplanar && geometry::orient3d(a.v[0], a.v[1], a.v[2], v) == 0;
      if (coplanar) {
        ++stats.coplanar_pairs;
        return;
      }
    }
    std::uint32_t nodes[6];
    Vec3 points[6];
    int n = 0;
    for (int k = 0; k < 3; ++k) {
      Vec3 x;
      if (geometry::segment_crosses_triangle(a.v[k], a.v[(k + 1) % 3], b, x)) {
        points[n] = x;
        nodes[n++] = graph.node({0, ma.edge_id(ta, k), tb}, x);
      }
      if (geometry::segment_crosses_triangle(b.v[k], b.v[(k + 1) % 3], a, x)) {
        points[n] = x;
        nodes[n++] = graph.node({1, mb.edge_id(tb, k), ta}, x);
      }
    }
    // Generically two crossings; more when a vertex lies on the other
    // surface (they then share nodes): the segment joins the two farthest.
    int bi = 0, bj = 0;
    double best = -1.0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const double d = glm::length(points[i] - points[j]);
        if (nodes[i] != nodes[j] && d > best) best = d, bi = i, bj = j;
      }
    if (best < 0.0) return;  // touching in a single point: no segment
    graph.connect(nodes[bi], nodes[bj]);
    ++stats.segments;
  });
  stats.node_pairs += descent.node_pairs;
  stats.triangle_pairs += descent.leaf_pairs;
  graph.polylines(q.pose_a, out);
  stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace prox
