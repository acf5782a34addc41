#include "snch/snch.h"

#include "common/worker_pool.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numeric>

namespace prox {
namespace {

struct Sphere {
  Vec3 center{0.0};
  double radius = 0.0;
};

// A sphere holding a triangle of any finite size: about the middle of its
// box, to its farthest vertex, each length by hypot (which neither under-
// nor overflows), grown by their rounding. Not the smallest.
[[gnu::noinline]] Sphere box_sphere(const Triangle& t) {
  const Vec3 lo = glm::min(glm::min(t.v[0], t.v[1]), t.v[2]), hi = glm::max(glm::max(t.v[0], t.v[1]), t.v[2]);
  const Vec3 center = 0.5 * lo + 0.5 * hi;
  double r = 0.0;
  for (const Vec3& v : t.v) {
    const Vec3 d = v - center;
    r = std::max(r, std::hypot(d.x, d.y, d.z));
  }
  return {center, r * (1.0 + 0x1p-49) + 0x1p-1070};
}

// Whether a sphere from the products below can be trusted: they reach the
// fifth power of the edges, and under- or overflow for spheres outside
// about 1e-60..1e+60 across (never a mesh in physical units). The centre's
// sum is finite exactly when its coordinates are: they are within the 1e50
// the API accepts, and a NaN stays a NaN.
bool in_range(const Vec3& center, double radius) {
  return radius >= 1e-60 && radius <= 1e60 && std::isfinite(center.x + center.y + center.z);
}

// The smallest sphere holding a triangle: around the longest edge when the
// triangle is obtuse (or degenerate), else its circumsphere; box_sphere()
// where that is out of range.
Sphere triangle_sphere(const Triangle& t) {
  for (int k = 0; k < 3; ++k) {
    const Vec3 &a = t.v[k], &b = t.v[(k + 1) % 3], &c = t.v[(k + 2) % 3];
    // Angle at c is >= 90 degrees: the sphere on edge ab holds c.
    if (glm::dot(a - c, b - c) <= 0.0) {
      const Vec3 m = 0.5 * (a + b);
      const double r = 0.5 * glm::length(b - a);
      if (!in_range(m, r)) return box_sphere(t);
      return {m, r};
    }
  }
  const Vec3 a = t.v[1] - t.v[0], b = t.v[2] - t.v[0];
  const Vec3 n = glm::cross(a, b);
  const double nn = glm::dot(n, n);
  const Vec3 offset = (glm::dot(a, a) * glm::cross(b, n) + glm::dot(b, b) * glm::cross(n, a)) / (2.0 * nn);
  const Vec3 center = t.v[0] + offset;
  // Rounding may leave a vertex a hair outside: take the farthest (one
  // square root, of the largest square: the same as the largest root).
  double r2 = 0.0;
  for (const Vec3& v : t.v) r2 = std::max(r2, glm::dot(v - center, v - center));
  const double r = std::sqrt(r2);
  if (!in_range(center, r)) return box_sphere(t);
  return {center, r};
}

// The box from lo to hi, its half extents rounded up so that it holds both.
SnchBox box_between(const Vec3& lo, const Vec3& hi) {
  SnchBox b;
  b.center = 0.5 * (lo + hi);
  const Vec3 half = glm::max(hi - b.center, b.center - lo);
  b.half = half + 1e-12 * (half + glm::abs(b.center));
  return b;
}

// A slab holding [lo, hi], widened for the rounding of the products that
// gave them (`scale`: the size of the terms they were summed from).
SnchSlab slab_between(double lo, double hi, double scale) {
  const double slack = 1e-12 * (scale + std::abs(lo) + std::abs(hi));
  return {lo - slack, hi + slack};
}

Sphere merge(const Sphere& a, const Sphere& b) {
  const Vec3 d = b.center - a.center;
  const double dist = glm::length(d);
  if (dist + b.radius <= a.radius) return a;
  if (dist + a.radius <= b.radius) return b;
  const double r = 0.5 * (dist + a.radius + b.radius);
  const Vec3 c = a.center + ((r - a.radius) / dist) * d;
  return {c, r};
}

// True where the surface around vertex v is not a closed, consistently wound
// sheet: a boundary or non-manifold edge, or two triangles that traverse a
// shared edge the same way. There the directions in which a closest pair can
// leave the surface are not bounded by the face normals.
bool vertex_is_open(const Mesh& mesh, std::uint32_t v) {
  for (const std::uint32_t* t = mesh.vertex_triangles_begin(v); t != mesh.vertex_triangles_end(v); ++t) {
    const auto& idx = mesh.indices(*t);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = idx[k], b = idx[(k + 1) % 3];
      if (a != v && b != v) continue;
      const std::uint32_t* begin = mesh.edge_triangles_begin(*t, k);
      const std::uint32_t* end = mesh.edge_triangles_end(*t, k);
      if (end - begin != 2) return true;
      const std::uint32_t other = begin[0] == *t ? begin[1] : begin[0];
      const auto& o = mesh.indices(other);
      for (int j = 0; j < 3; ++j)
        if (o[j] == a && o[(j + 1) % 3] == b) return true;  // same direction: folded
    }
  }
  return false;
}

}  // namespace

Cone Snch::leaf_cone(const Mesh& mesh, std::uint32_t t, const std::vector<std::uint8_t>& open) {
  // A local minimum can sit on the face, an edge or a vertex of t. The
  // directions it can leave by are the face normal for the face, and lie in
  // the cone spanned by the adjacent face normals for an edge or a convex
  // vertex (the polar of the surface's tangent cone). So the leaf cone bounds
  // the normals of every triangle sharing a vertex with t. When those
  // normals spread past a hemisphere their cone is no longer convex and may
  // miss directions in their span: then it holds everything.
  const auto& idx = mesh.indices(t);
  Vec3 sum(0.0);
  for (std::uint32_t v : idx) {
    if (open[v]) return Cone::everything();
    for (const std::uint32_t* n = mesh.vertex_triangles_begin(v); n != mesh.vertex_triangles_end(v); ++n)
      sum += mesh.face_normal(*n);
  }
  const double len = glm::length(sum);
  if (!(len > 1e-12)) return Cone::everything();
  const Vec3 axis = sum / len;
  double half = 0.0;
  for (std::uint32_t v : idx)
    for (const std::uint32_t* n = mesh.vertex_triangles_begin(v); n != mesh.vertex_triangles_end(v); ++n) {
      const Vec3& normal = mesh.face_normal(*n);
      if (glm::dot(normal, normal) > 0.0) half = std::max(half, angle_between(axis, normal));
    }
  if (half >= 0.5 * kPi) return Cone::everything();
  return {axis, half};
}

Snch::Snch(const Mesh& mesh) {
  static std::atomic<std::uint64_t> builds{0};
  build_id_ = ++builds;
  const auto start = std::chrono::steady_clock::now();
  const std::uint32_t n = mesh.triangle_count();
  std::vector<Vec3> centroid(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    const Triangle tri = mesh.triangle(t);
    centroid[t] = (tri.v[0] + tri.v[1] + tri.v[2]) / 3.0;
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  nodes_.reserve(n > 0 ? 2 * static_cast<std::size_t>(n) - 1 : 0);
  boxes_.resize(n > 0 ? 2 * static_cast<std::size_t>(n) - 1 : 0);
  slabs_.resize(boxes_.size());

  struct Task {
    std::uint32_t node, begin, end, depth;
  };
  // Each node's range in `order`, for fitting inner spheres to their vertices.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> range(n > 0 ? 2 * static_cast<std::size_t>(n) - 1 : 0);
  std::vector<Task> stack;
  // The build merges cones as angles (exactly the smallest cone holding
  // both); the nodes keep their cosines and sines.
  std::vector<Cone> cones(nodes_.capacity());
  // Each vertex's openness, once: every triangle around it asks.
  open_.resize(mesh.vertex_count());
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) open_[v] = vertex_is_open(mesh, v);
  const std::vector<std::uint8_t>& open = open_;
  if (n > 0) {
    nodes_.emplace_back();
    stack.push_back({0, 0, n, 0});
  }
  // Pre-order: children are created when a node is split, and their
  // geometry is filled in once both are built (post-order pass below).
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    stats_.depth = std::max(stats_.depth, task.depth);
    range[task.node] = {task.begin, task.end};
    if (task.end - task.begin == 1) {
      const std::uint32_t t = order[task.begin];
      SnchNode& leaf = nodes_[task.node];
      const Sphere s = triangle_sphere(mesh.triangle(t));
      leaf.center = s.center;
      leaf.radius = s.radius;
      cones[task.node] = leaf_cone(mesh, t, open);
      leaf.first = t;
      leaf.second = SnchNode::kLeaf;
      const Triangle tri = mesh.triangle(t);
      boxes_[task.node] = box_between(glm::min(glm::min(tri.v[0], tri.v[1]), tri.v[2]),
                                      glm::max(glm::max(tri.v[0], tri.v[1]), tri.v[2]));
      ++stats_.leaves;
      if (cones[task.node].unbounded()) ++stats_.unbounded_leaves;
      continue;
    }
    Vec3 lo = centroid[order[task.begin]], hi = lo;
    for (std::uint32_t i = task.begin; i < task.end; ++i)
      lo = glm::min(lo, centroid[order[i]]), hi = glm::max(hi, centroid[order[i]]);
    const Vec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t mid = task.begin + (task.end - task.begin) / 2;
    // Ties broken by triangle index, so the split does not depend on how
    // nth_element orders equal keys.
    std::nth_element(order.begin() + task.begin, order.begin() + mid, order.begin() + task.end,
                     [&](std::uint32_t a, std::uint32_t b) {
                       return centroid[a][axis] < centroid[b][axis] ||
                              (centroid[a][axis] == centroid[b][axis] && a < b);
                     });
    const auto first = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    nodes_.emplace_back();
    nodes_[task.node].first = first;
    nodes_[task.node].second = first + 1;
    stack.push_back({first + 1, mid, task.end, task.depth + 1});
    stack.push_back({first, task.begin, mid, task.depth + 1});
  }
  // Children always come after their parent: fill inner nodes bottom-up.
  // The sphere is the smaller of the one holding both children's spheres and
  // the one around the middle of the node's own vertices' box: merged
  // spheres grow with every level, fitted ones do not.
  for (std::size_t i = nodes_.size(); i-- > 0;) {
    SnchNode& node = nodes_[i];
    if (node.is_leaf()) continue;
    const SnchNode &a = nodes_[node.first], &b = nodes_[node.second];
    Sphere s = merge(Sphere{a.center, a.radius}, Sphere{b.center, b.radius});
    Vec3 lo(INFINITY), hi(-INFINITY);
    for (std::uint32_t k = range[i].first; k < range[i].second; ++k)
      for (std::uint32_t v : mesh.indices(order[k]))
        lo = glm::min(lo, mesh.vertex(v)), hi = glm::max(hi, mesh.vertex(v));
    boxes_[i] = box_between(lo, hi);
    const Vec3 centre = 0.5 * (lo + hi);
    double r2 = 0.0;
    for (std::uint32_t k = range[i].first; k < range[i].second; ++k)
      for (std::uint32_t v : mesh.indices(order[k]))
        r2 = std::max(r2, glm::dot(mesh.vertex(v) - centre, mesh.vertex(v) - centre));
    if (std::sqrt(r2) < s.radius) s = {centre, std::sqrt(r2)};
    node.center = s.center;
    node.radius = s.radius;
    cones[i] = merge(cones[node.first], cones[node.second]);
  }
  for (std::size_t i = 0; i < nodes_.size(); ++i) nodes_[i].cone = CosCone::of(cones[i]);
  // Each node's slab along its cone's axis, measured on its vertices.
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const SnchNode& node = nodes_[i];
    double lo = INFINITY, hi = -INFINITY;
    for (std::uint32_t k = range[i].first; k < range[i].second; ++k)
      for (std::uint32_t v : mesh.indices(order[k])) {
        const double d = glm::dot(mesh.vertex(v) - node.center, node.cone.axis);
        lo = std::min(lo, d), hi = std::max(hi, d);
      }
    slabs_[i] = slab_between(lo, hi, node.radius);
  }
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) two_sided_ = two_sided_ || open_[v];
  compute_vertex_spread(mesh);
  stats_.nodes = static_cast<std::uint32_t>(nodes_.size());
  stats_.memory_bytes = nodes_.capacity() * sizeof(SnchNode) + boxes_.capacity() * sizeof(SnchBox) +
                        slabs_.capacity() * sizeof(SnchSlab) +
                        vertex_spread_.capacity() * sizeof(geometry::Spread) + open_.capacity();
  plan_refit();
  // The ratio a refit of the unmoved mesh would measure, so that
  // degradation starts at exactly 1.
  {
    Snch copy;
    copy.nodes_ = nodes_;
    copy.boxes_ = boxes_;
    copy.refit_tasks_ = refit_tasks_;
    copy.refit_top_ = refit_top_;
    built_ratio_ = copy.sweep(
        [&copy](std::uint32_t i) {
          if (!copy.nodes_[i].is_leaf()) copy.refit_inner(i);
        },
        nullptr);
  }
  stats_.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void Snch::compute_vertex_spread(const Mesh& mesh) {
  vertex_spread_.assign(mesh.vertex_count(), geometry::Spread{});
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3& normal = mesh.vertex_normal(v);
    if (open_[v] || !(glm::dot(normal, normal) > 0.0)) continue;
    double spread = 0.0;
    for (const std::uint32_t* t = mesh.vertex_triangles_begin(v); t != mesh.vertex_triangles_end(v); ++t) {
      const Vec3& f = mesh.face_normal(*t);
      if (glm::dot(f, f) > 0.0) spread = std::max(spread, angle_between(normal, f));
    }
    vertex_spread_[v] = geometry::Spread::of_angle(spread);
  }
}

void Snch::plan_refit() {
  refit_tasks_.clear();
  refit_top_.clear();
  if (nodes_.empty()) return;
  // Each subtree's last node: a leaf is its own, an inner node's is its
  // second child's (made after the first's whole subtree).
  std::vector<std::uint32_t> last(nodes_.size());
  for (std::size_t i = nodes_.size(); i-- > 0;)
    last[i] = nodes_[i].is_leaf() ? static_cast<std::uint32_t>(i)
                                  : std::max(last[nodes_[i].first], last[nodes_[i].second]);
  // Split the largest subtree until there are enough to share out.
  const auto size = [&](std::uint32_t r) { return nodes_[r].is_leaf() ? 1u : last[r] - nodes_[r].first + 2; };
  std::vector<std::uint32_t> roots{0};
  while (roots.size() < kRefitTasks) {
    const auto largest = std::max_element(roots.begin(), roots.end(),
                                          [&](std::uint32_t a, std::uint32_t b) { return size(a) < size(b); });
    if (nodes_[*largest].is_leaf()) break;
    const SnchNode& n = nodes_[*largest];
    refit_top_.push_back(*largest);
    *largest = n.first;
    roots.push_back(n.second);
  }
  std::sort(roots.begin(), roots.end());
  std::sort(refit_top_.begin(), refit_top_.end());
  for (std::uint32_t r : roots) {
    const std::uint32_t begin = nodes_[r].is_leaf() ? r + 1 : nodes_[r].first;
    refit_tasks_.push_back({r, begin, nodes_[r].is_leaf() ? r + 1 : last[r] + 1});
  }
}

template <class RefitNode>
double Snch::sweep(const RefitNode& refit_node, WorkerPool* pool) {
  if (nodes_.empty()) return 1.0;
  // Each task sums its own inner radii; the sums are added in task order,
  // so the ratio is the same however many threads ran them.
  static thread_local std::vector<double> task_sum;
  task_sum.assign(refit_tasks_.size(), 0.0);
  double* sums = task_sum.data();
  const auto run_task = [&](std::size_t k) {
    const RefitTask& task = refit_tasks_[k];
    double sum = 0.0;
    // Children come after their parent: a reverse sweep meets both first.
    for (std::uint32_t i = task.end; i-- > task.begin;) {
      refit_node(i);
      if (!nodes_[i].is_leaf()) sum += nodes_[i].radius;
    }
    refit_node(task.root);
    if (!nodes_[task.root].is_leaf()) sum += nodes_[task.root].radius;
    sums[k] = sum;
  };
  // Below a few thousand nodes waking the pool costs more than it saves.
  constexpr std::size_t kSplitFrom = 8192;
  if (pool != nullptr && pool->size() > 1 && nodes_.size() >= kSplitFrom) {
    pool->run(refit_tasks_.size(), run_task);
  } else {
    for (std::size_t k = 0; k < refit_tasks_.size(); ++k) run_task(k);
  }
  double inner = 0.0;
  for (std::size_t k = 0; k < refit_tasks_.size(); ++k) inner += sums[k];
  for (auto i = refit_top_.size(); i-- > 0;) {
    refit_node(refit_top_[i]);
    inner += nodes_[refit_top_[i]].radius;
  }
  return nodes_[0].radius > 0.0 && inner > 0.0 ? inner / nodes_[0].radius : 1.0;
}

void Snch::refit_inner(std::uint32_t i) {
  SnchNode& node = nodes_[i];
  const SnchNode &a = nodes_[node.first], &b = nodes_[node.second];
  const SnchBox &ba = boxes_[node.first], &bb = boxes_[node.second];
  SnchBox& box = boxes_[i];
  box = box_between(glm::min(ba.center - ba.half, bb.center - bb.half),
                    glm::max(ba.center + ba.half, bb.center + bb.half));
  // The smallest of three spheres that each hold both children: the
  // merged one, and two about the box's centre (around the box, and
  // around the children's spheres).
  Sphere s = merge(Sphere{a.center, a.radius}, Sphere{b.center, b.radius});
  const double around_box = glm::length(box.half);
  const double around_children = std::max(glm::length(a.center - box.center) + a.radius,
                                          glm::length(b.center - box.center) + b.radius);
  const double r = std::min(around_box, around_children);
  if (r < s.radius) s = {box.center, r};
  node.center = s.center;
  node.radius = s.radius;
  node.cone = merge(a.cone, b.cone);
}

void Snch::refit(const Mesh& mesh, WorkerPool* pool) {
  const auto start = std::chrono::steady_clock::now();
  // Each vertex's cone of the face normals around it, about its vertex
  // normal: its half-angle is the vertex's spread, and a leaf's cone holds
  // its three vertices' (refit_leaf_cone(); leaf_cone() bounds the same
  // normals, about their sum). Kept between refits by the calling thread.
  static thread_local std::vector<CosCone> vertex_cone;
  const std::uint32_t vertices = mesh.vertex_count();
  vertex_cone.resize(vertices);
  vertex_spread_.resize(vertices);
  CosCone* cones = vertex_cone.data();
  constexpr std::uint32_t kVertexChunk = 4096;
  const auto cone_chunk = [&](std::size_t k) {
    const auto end = static_cast<std::uint32_t>(std::min<std::size_t>(vertices, (k + 1) * kVertexChunk));
    for (auto v = static_cast<std::uint32_t>(k * kVertexChunk); v < end; ++v) {
      cones[v] = refit_vertex_cone(mesh, v);
      // The cone's own pair: a cosine rounded down and a sine rounded up,
      // an angle a little wider than the spread, never narrower.
      vertex_spread_[v] = cones[v].cos > 0.0 ? geometry::Spread{cones[v].cos, cones[v].sin} : geometry::Spread{};
    }
  };
  const std::size_t chunks = (std::size_t{vertices} + kVertexChunk - 1) / kVertexChunk;
  if (pool != nullptr && pool->size() > 1 && chunks > 1) {
    pool->run(chunks, cone_chunk);
  } else {
    for (std::size_t k = 0; k < chunks; ++k) cone_chunk(k);
  }
  const double ratio = sweep(
      [&](std::uint32_t i) {
        SnchNode& node = nodes_[i];
        if (!node.is_leaf()) return refit_inner(i);
        const Triangle tri = mesh.triangle(node.first);
        const Sphere s = triangle_sphere(tri);
        node.center = s.center;
        node.radius = s.radius;
        boxes_[i] = box_between(glm::min(glm::min(tri.v[0], tri.v[1]), tri.v[2]),
                                glm::max(glm::max(tri.v[0], tri.v[1]), tri.v[2]));
        node.cone = refit_leaf_cone(mesh, node.first, cones);
      },
      pool);
  // The slabs are measured on the triangles at a build; bounding them
  // again from the children would cost a refit about a third more, so a
  // refitted tree has none until it is rebuilt (the searches then bound
  // node pairs by their spheres and boxes alone).
  slabs_valid_ = false;
  stats_.refits += 1;
  stats_.degradation = ratio / built_ratio_;
  stats_.refit_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void Snch::refit_as(const Snch& current, const Mesh& mesh, WorkerPool* pool) {
  if (build_id_ != current.build_id_) {
    *this = current;  // another tree: copied, into the storage at hand where it fits
  } else {
    // The same nodes and topology: refit() writes every bound, vertex
    // spread and statistic but these.
    stats_ = current.stats_;
  }
  refit(mesh, pool);
}

CosCone Snch::refit_leaf_cone(const Mesh& mesh, std::uint32_t t, const CosCone* vertex_cone) {
  // The cone about the face normal that holds its vertices' cones: the
  // widest of their axes' angles to it plus their half-angles, sums taken on
  // cosines and sines. Three square roots, where merging the three cones
  // would take eight and their divisions; a little wider than that merge.
  // Past a right angle, everything, as leaf_cone() has it.
  const Vec3& axis = mesh.face_normal(t);
  const auto& idx = mesh.indices(t);
  const CosCone* cones[3] = {&vertex_cone[idx[0]], &vertex_cone[idx[1]], &vertex_cone[idx[2]]};
  if (cones[0]->unbounded() || cones[1]->unbounded() || cones[2]->unbounded() || !(glm::dot(axis, axis) > 0.0))
    return CosCone::everything();
  double c = 1.0, s = 0.0;  // the widest so far
  for (const CosCone* v : cones) {
    const double ct = glm::dot(axis, v->axis), st = glm::length(glm::cross(axis, v->axis));
    const double cw = ct * v->cos - st * v->sin, sw = st * v->cos + ct * v->sin;
    if (!(cw > 0.0)) return CosCone::everything();
    if (!cone_detail::at_most(cw, sw, c, s)) c = cw, s = sw;
  }
  return cone_detail::widened(axis, c, s);
}

CosCone Snch::refit_vertex_cone(const Mesh& mesh, std::uint32_t v) const {
  // Without trigonometry: the widest angle's cosine is the least dot product
  // with the axis, its sine the largest cross product, each a bound on its
  // own (below a right angle the sine grows with the angle), so no normal is
  // left out by the other's rounding.
  const Vec3& axis = mesh.vertex_normal(v);
  if (open_[v] || !(glm::dot(axis, axis) > 0.0)) return CosCone::everything();
  double least = 1.0, widest2 = 0.0;
  for (const std::uint32_t* t = mesh.vertex_triangles_begin(v); t != mesh.vertex_triangles_end(v); ++t) {
    const Vec3& normal = mesh.face_normal(*t);
    if (!(glm::dot(normal, normal) > 0.0)) continue;
    least = std::min(least, glm::dot(axis, normal));
    const Vec3 c = glm::cross(axis, normal);
    widest2 = std::max(widest2, glm::dot(c, c));
  }
  if (!(least > 0.0)) return CosCone::everything();
  // Widened by a few roundings of the products above.
  return {axis, least - 4e-16, std::min(1.0, std::sqrt(widest2) * (1.0 + 4e-16) + 4e-16)};
}

}  // namespace prox
