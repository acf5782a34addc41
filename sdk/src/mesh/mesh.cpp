#include "mesh/mesh.h"

#include "common/worker_pool.h"
#include "geometry/fast_math.h"
#include "geometry/predicates.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

namespace prox {
namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

// A sum of unit normals shorter than this fraction of the weight that went
// into it has (nearly) cancelled: its direction would be rounding noise.
constexpr double kCancelTolerance = 1e-9;

// Half-edges are numbered 3 t + k in 32 bits.
constexpr std::uint32_t kMaxTriangles = 0xFFFFFFFFu / 3;

Status invalid(std::string message) { return {StatusCode::InvalidArgument, std::move(message)}; }

const char* non_finite_name(double x) { return std::isnan(x) ? "nan" : x > 0.0 ? "inf" : "-inf"; }

Status validate(const MeshInput& in) {
  if (in.triangle_count == 0) return invalid("mesh has no triangles");
  if (in.triangle_count > kMaxTriangles)
    return invalid("mesh has " + std::to_string(in.triangle_count) + " triangles; at most " +
                   std::to_string(kMaxTriangles) + " are supported");
  if (in.indices == nullptr)
    return invalid("indices is NULL but triangle_count is " + std::to_string(in.triangle_count));
  if (in.positions == nullptr && in.vertex_count > 0)
    return invalid("positions is NULL but vertex_count is " + std::to_string(in.vertex_count));
  static const char* const kAxis[3] = {"x", "y", "z"};
  for (std::uint32_t v = 0; v < in.vertex_count; ++v) {
    for (int c = 0; c < 3; ++c) {
      const double x = in.positions[std::size_t{3} * v + c];
      if (!std::isfinite(x))
        return invalid("vertex " + std::to_string(v) + " has a non-finite " + kAxis[c] + " coordinate (" +
                       non_finite_name(x) + ")");
    }
  }
  for (std::uint32_t t = 0; t < in.triangle_count; ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = in.indices[std::size_t{3} * t + k];
      if (i >= in.vertex_count)
        return invalid("triangle " + std::to_string(t) + " has vertex index " + std::to_string(i) +
                       ", out of range for " + std::to_string(in.vertex_count) + " vertices");
    }
  }
  return Status::ok();
}

// -0.0 and 0.0 are the same point, so they must weld.
double fold_zero(double x) { return x == 0.0 ? 0.0 : x; }

std::uint64_t bits_of(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

// The splitmix64 finaliser: every input bit reaches every output bit.
std::uint64_t mix(std::uint64_t h) {
  h ^= h >> 30;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 27;
  h *= 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

// Welds positions by exact (bitwise) equality in an open-addressing hash
// table: linear time, and ids are handed out in order of first insertion.
class Welder {
 public:
  explicit Welder(std::size_t expected) {
    std::size_t size = 16;
    while (size < 2 * expected) size *= 2;
    slots_.assign(size, kNone);
    positions_.reserve(expected);
  }

  std::uint32_t insert(const Vec3& p) {
    const Vec3 q(fold_zero(p.x), fold_zero(p.y), fold_zero(p.z));
    const std::uint64_t h = mix(bits_of(q.x) + mix(bits_of(q.y) + mix(bits_of(q.z))));
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = static_cast<std::size_t>(h) & mask;; i = (i + 1) & mask) {
      if (slots_[i] == kNone) {
        slots_[i] = static_cast<std::uint32_t>(positions_.size());
        positions_.push_back(q);
        return slots_[i];
      }
      const Vec3& r = positions_[slots_[i]];
      if (bits_of(r.x) == bits_of(q.x) && bits_of(r.y) == bits_of(q.y) && bits_of(r.z) == bits_of(q.z))
        return slots_[i];
    }
  }

  const std::vector<Vec3>& positions() const { return positions_; }

 private:
  std::vector<std::uint32_t> slots_;
  std::vector<Vec3> positions_;
};

// Out of line: the rare path, so that length_of's common one inlines.
[[gnu::noinline]] double length_by_hypot(const Vec3& d) { return std::hypot(d.x, d.y, d.z); }

// |d|. Its square under- or overflows only for lengths beyond about 1e+-145,
// where hypot's scaling takes over.
inline double length_of(const Vec3& d) {
  const double l2 = glm::dot(d, d);
  if (l2 > 1e-290 && l2 < 1e290) return std::sqrt(l2);
  return length_by_hypot(d);
}

struct FaceGeometry {
  Vec3 normal{0.0};
  double angle[3] = {0.0, 0.0, 0.0};  // interior angle at each vertex
};

// Unit normal and angles of a triangle whose exact cross product is non-zero.
FaceGeometry face_geometry(const Vec3& a, const Vec3& b, const Vec3& c) {
  FaceGeometry g;
  // Scaling by a power of two is exact and keeps the products below from
  // overflowing or underflowing at any scale; normals and angles do not
  // depend on it. The clamp keeps the factor itself finite for subnormal input.
  const Vec3 m = glm::max(glm::abs(a), glm::max(glm::abs(b), glm::abs(c)));
  const double s = geometry::power_of_two_below(std::max({m.x, m.y, m.z}));
  const Vec3 e[3] = {s * b - s * a, s * c - s * b, s * a - s * c};
  // As in the distance kernel: on a sliver the rounding of the cross product
  // along the longest edge would tilt the plane, so that part is projected out.
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (glm::dot(e[i], e[i]) > glm::dot(e[k], e[k])) k = i;
  Vec3 n = glm::cross(e[k], e[(k + 1) % 3]);
  n -= (glm::dot(n, e[k]) / glm::dot(e[k], e[k])) * e[k];
  // Rounding can cancel the cross product of a sliver thinner than about
  // 1e-16 of its length: its plane is not determined in doubles, so it gets
  // no normal, like a zero-area triangle.
  const double len = length_of(n);
  if (!(len > 0.0)) return g;
  g.normal = n / len;
  // |cross| is twice the area at every corner; an angle from it and the
  // dot product (as atan2 has it, not acos) stays accurate near 0 and pi.
  // The angle opposite the longest edge, the largest (pi / 3 or more), is
  // what the other two leave of pi: one angle fewer, and a rounding of its
  // size.
  const int i = k, j = (k + 1) % 3;
  g.angle[i] = geometry::angle_from(len, -glm::dot(e[i], e[(i + 2) % 3]));
  g.angle[j] = geometry::angle_from(len, -glm::dot(e[j], e[(j + 2) % 3]));
  g.angle[(k + 2) % 3] = std::max(0.0, kPi - g.angle[i] - g.angle[j]);
  return g;
}

// v / |v|, or zero when |v| is at most kCancelTolerance times `weight`, the
// total weight of the unit vectors summed into v.
Vec3 normalized_unless_cancelled(const Vec3& v, double weight) {
  const double len = length_of(v);
  return len > 0.0 && len > kCancelTolerance * weight ? v / len : Vec3(0.0);
}

// Offsets of a CSR array from per-row counts stored at offsets[row + 1].
void prefix_sum(std::vector<std::uint32_t>& offsets) {
  for (std::size_t i = 1; i < offsets.size(); ++i) offsets[i] += offsets[i - 1];
}

}  // namespace

std::shared_ptr<const Mesh::Topology> Mesh::empty_topology() {
  static const std::shared_ptr<const Topology> empty = std::make_shared<Topology>();
  return empty;
}

Mesh Mesh::build(const MeshInput& in, Status& status) {
  status = validate(in);
  if (!status) return {};
  const std::size_t index_count = std::size_t{3} * in.triangle_count;

  // Weld the referenced vertices in input order, so the welded order is the
  // order of first appearance.
  std::vector<std::uint8_t> referenced(in.vertex_count, 0);
  for (std::size_t i = 0; i < index_count; ++i) referenced[in.indices[i]] = 1;
  std::vector<std::uint32_t> welded_of(in.vertex_count, kNone);
  Welder welder(static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), 1)));
  for (std::uint32_t v = 0; v < in.vertex_count; ++v) {
    if (!referenced[v]) continue;
    const double* p = in.positions + std::size_t{3} * v;
    welded_of[v] = welder.insert(Vec3(p[0], p[1], p[2]));
  }

  Mesh mesh;
  auto topology = std::make_shared<Topology>();
  Topology& topo = *topology;
  mesh.topology_ = topology;
  MeshStats& stats = mesh.stats_;
  stats.input_vertices = in.vertex_count;
  stats.input_triangles = in.triangle_count;
  for (std::uint32_t t = 0; t < in.triangle_count; ++t) {
    const std::uint32_t* i = in.indices + std::size_t{3} * t;
    const std::array<std::uint32_t, 3> w = {welded_of[i[0]], welded_of[i[1]], welded_of[i[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[2] == w[0]) {
      ++stats.dropped_triangles;
      continue;
    }
    topo.triangles.push_back(w);
    topo.input_triangle.push_back(t);
  }
  if (topo.triangles.empty()) {
    status = invalid("mesh has no non-degenerate triangles: all " + std::to_string(in.triangle_count) +
                     " repeat a vertex after welding");
    return {};
  }

  // Keep only vertices of kept triangles, in welded order.
  const std::vector<Vec3>& welded = welder.positions();
  std::vector<std::uint32_t> final_of(welded.size(), kNone);
  for (const auto& tri : topo.triangles)
    for (std::uint32_t w : tri) final_of[w] = 0;
  for (std::uint32_t w = 0; w < welded.size(); ++w) {
    if (final_of[w] == kNone) continue;
    final_of[w] = static_cast<std::uint32_t>(mesh.vertices_.size());
    mesh.vertices_.push_back(welded[w]);
  }
  for (auto& tri : topo.triangles)
    for (std::uint32_t& w : tri) w = final_of[w];
  topo.input_vertex.resize(in.vertex_count);
  for (std::uint32_t v = 0; v < in.vertex_count; ++v)
    topo.input_vertex[v] = welded_of[v] == kNone ? kNoVertex : final_of[welded_of[v]];

  const std::uint32_t vertex_count = mesh.vertex_count();
  const std::uint32_t triangle_count = mesh.triangle_count();
  stats.vertices = vertex_count;
  stats.triangles = triangle_count;

  // Vertex -> triangles, by counting sort: ascending because triangles are
  // visited in order.
  topo.vertex_tri_offsets.assign(std::size_t{vertex_count} + 1, 0);
  for (const auto& tri : topo.triangles)
    for (std::uint32_t v : tri) ++topo.vertex_tri_offsets[v + 1];
  prefix_sum(topo.vertex_tri_offsets);
  topo.vertex_tri.resize(topo.vertex_tri_offsets.back());
  {
    std::vector<std::uint32_t> cursor(topo.vertex_tri_offsets.begin(), topo.vertex_tri_offsets.end() - 1);
    for (std::uint32_t t = 0; t < triangle_count; ++t)
      for (std::uint32_t v : topo.triangles[t]) topo.vertex_tri[cursor[v]++] = t;
  }

  // Edges. Half-edge h = 3 t + k runs from vertex k to vertex k + 1 of t.
  // Bucketing half-edges by their lower vertex (a stable counting sort) and
  // then sorting each bucket, as small as the vertex's degree, by the upper
  // vertex groups equal edges without a global sort; edge ids follow
  // (lower, upper) vertex order.
  const std::uint32_t half_edges = 3 * triangle_count;
  const auto end_vertex = [&](std::uint32_t h, std::uint32_t step) {
    return topo.triangles[h / 3][(h % 3 + step) % 3];
  };
  const auto lower = [&](std::uint32_t h) { return std::min(end_vertex(h, 0), end_vertex(h, 1)); };
  const auto upper = [&](std::uint32_t h) { return std::max(end_vertex(h, 0), end_vertex(h, 1)); };
  std::vector<std::uint32_t> bucket_offsets(std::size_t{vertex_count} + 1, 0);
  for (std::uint32_t h = 0; h < half_edges; ++h) ++bucket_offsets[lower(h) + 1];
  prefix_sum(bucket_offsets);
  std::vector<std::uint32_t> bucket(half_edges);
  {
    std::vector<std::uint32_t> cursor(bucket_offsets.begin(), bucket_offsets.end() - 1);
    for (std::uint32_t h = 0; h < half_edges; ++h) bucket[cursor[lower(h)]++] = h;
  }
  topo.triangle_edge.assign(half_edges, kNone);
  topo.edge_tri.reserve(half_edges);
  topo.edge_tri_offsets.reserve(half_edges / 2 + 2);
  topo.edge_tri_offsets.push_back(0);
  for (std::uint32_t v = 0; v < vertex_count; ++v) {
    const auto first = bucket.begin() + bucket_offsets[v], last = bucket.begin() + bucket_offsets[v + 1];
    std::sort(first, last, [&](std::uint32_t g, std::uint32_t h) {
      const std::uint32_t ug = upper(g), uh = upper(h);
      return ug < uh || (ug == uh && g < h);
    });
    for (auto run = first; run != last;) {
      const std::uint32_t u = upper(*run);
      const auto id = static_cast<std::uint32_t>(topo.edge_tri_offsets.size() - 1);
      auto it = run;
      // Half-edges ascend within the run, so do their (distinct) triangles.
      for (; it != last && upper(*it) == u; ++it) {
        topo.triangle_edge[*it] = id;
        topo.edge_tri.push_back(*it / 3);
      }
      const auto sharing = it - run;
      if (sharing == 1) ++stats.boundary_edges;
      if (sharing >= 3) ++stats.nonmanifold_edges;
      topo.edge_tri_offsets.push_back(static_cast<std::uint32_t>(topo.edge_tri.size()));
      run = it;
    }
  }
  mesh.compute_geometry();
  return mesh;
}

void Mesh::compute_geometry(WorkerPool* pool) {
  const std::uint32_t vertex_count = this->vertex_count();
  const std::uint32_t triangle_count = this->triangle_count();
  bounds_.min = bounds_.max = vertices_[0];
  for (const Vec3& p : vertices_) {
    bounds_.min = glm::min(bounds_.min, p);
    bounds_.max = glm::max(bounds_.max, p);
  }
  // In chunks, on the pool's threads where there is one: first each
  // triangle's normal and angles, then each vertex's normal from its
  // triangles' in ascending order, the order a sweep over the triangles
  // would add them in, so the sums are the same however many threads ran.
  constexpr std::size_t kChunk = 4096;
  const auto in_chunks = [pool](std::size_t n, const auto& f) {
    const std::size_t chunks = (n + kChunk - 1) / kChunk;
    const auto run = [&](std::size_t k) { f(k * kChunk, std::min(n, (k + 1) * kChunk)); };
    if (pool != nullptr && pool->size() > 1 && chunks > 1) {
      pool->run(chunks, run);
    } else {
      for (std::size_t k = 0; k < chunks; ++k) run(k);
    }
  };
  // Scratch kept by the thread between calls: a deforming mesh's every
  // frame would otherwise allocate it anew.
  struct ChunkResult {
    std::uint32_t zero_area = 0;
    double longest = 0.0, longest2 = 0.0;  // the longest edge and its square
  };
  static thread_local std::vector<std::array<double, 3>> corner_angle;
  static thread_local std::vector<ChunkResult> chunk_result;
  face_normals_.resize(triangle_count);
  corner_angle.resize(triangle_count);
  chunk_result.assign((triangle_count + kChunk - 1) / kChunk, ChunkResult{});
  std::array<double, 3>* angles = corner_angle.data();
  ChunkResult* results = chunk_result.data();
  in_chunks(triangle_count, [&](std::size_t begin, std::size_t end) {
    ChunkResult r;
    for (std::size_t t = begin; t < end; ++t) {
      const auto& tri = topology_->triangles[t];
      const Vec3 &a = vertices_[tri[0]], &b = vertices_[tri[1]], &c = vertices_[tri[2]];
      // One square root a triangle where the squares neither over- nor
      // underflow (length_of's range), three elsewhere.
      const Vec3 e0 = b - a, e1 = c - b, e2 = a - c;
      const double l0 = glm::dot(e0, e0), l1 = glm::dot(e1, e1), l2 = glm::dot(e2, e2);
      const double longest2 = std::max({l0, l1, l2});
      if (longest2 > 1e-290 && longest2 < 1e290) {
        if (longest2 > r.longest2) r.longest2 = longest2, r.longest = std::sqrt(longest2);
      } else {
        r.longest = std::max({r.longest, length_of(e0), length_of(e1), length_of(e2)});
        r.longest2 = r.longest * r.longest;
      }
      // Weighted by the angle at the vertex: a face split into more
      // triangles does not weigh more.
      FaceGeometry g;
      if (geometry::collinear3d(a, b, c)) {
        ++r.zero_area;
      } else {
        g = face_geometry(a, b, c);
      }
      face_normals_[t] = g.normal;
      angles[t] = {g.angle[0], g.angle[1], g.angle[2]};
    }
    results[begin / kChunk] = r;
  });
  stats_.zero_area_triangles = 0;
  longest_edge_ = 0.0;
  for (const ChunkResult& r : chunk_result) {
    stats_.zero_area_triangles += r.zero_area;
    longest_edge_ = std::max(longest_edge_, r.longest);
  }
  vertex_normals_.resize(vertex_count);
  in_chunks(vertex_count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      Vec3 sum(0.0);
      double weight = 0.0;
      for (const std::uint32_t* t = vertex_triangles_begin(static_cast<std::uint32_t>(v));
           t != vertex_triangles_end(static_cast<std::uint32_t>(v)); ++t) {
        const Vec3& normal = face_normals_[*t];
        if (normal == Vec3(0.0)) continue;
        const auto& tri = topology_->triangles[*t];
        const double angle = angles[*t][tri[0] == v ? 0 : (tri[1] == v ? 1 : 2)];
        sum += angle * normal;
        weight += angle;
      }
      vertex_normals_[v] = normalized_unless_cancelled(sum, weight);
    }
  });
}

Status Mesh::set_vertices(const double* positions, std::uint32_t count, WorkerPool* pool) {
  if (count != vertex_count())
    return invalid("vertexCount is " + std::to_string(count) + " but the mesh has " +
                   std::to_string(vertex_count()) + " vertices (after welding)");
  if (positions == nullptr) return invalid("positions is NULL");
  static const char* const kAxis[3] = {"x", "y", "z"};
  for (std::uint32_t v = 0; v < count; ++v)
    for (int c = 0; c < 3; ++c) {
      const double x = positions[std::size_t{3} * v + c];
      if (!std::isfinite(x))
        return invalid("vertex " + std::to_string(v) + " has a non-finite " + kAxis[c] + " coordinate (" +
                       non_finite_name(x) + ")");
    }
  for (std::uint32_t v = 0; v < count; ++v) {
    const double* p = positions + std::size_t{3} * v;
    vertices_[v] = Vec3(p[0], p[1], p[2]);
  }
  compute_geometry(pool);
  return Status::ok();
}

Vec3 Mesh::edge_normal(std::uint32_t t, int k) const {
  Vec3 sum(0.0);
  double weight = 0.0;
  for (const std::uint32_t* s = edge_triangles_begin(t, k); s != edge_triangles_end(t, k); ++s) {
    sum += face_normals_[*s];
    if (face_normals_[*s] != Vec3(0.0)) weight += 1.0;
  }
  return normalized_unless_cancelled(sum, weight);
}

const std::uint32_t* Mesh::vertex_triangles_begin(std::uint32_t v) const {
  return topology_->vertex_tri.data() + topology_->vertex_tri_offsets[v];
}

const std::uint32_t* Mesh::vertex_triangles_end(std::uint32_t v) const {
  return topology_->vertex_tri.data() + topology_->vertex_tri_offsets[std::size_t{v} + 1];
}

const std::uint32_t* Mesh::edge_triangles_begin(std::uint32_t t, int k) const {
  return topology_->edge_tri.data() + topology_->edge_tri_offsets[topology_->triangle_edge[std::size_t{3} * t + k]];
}

const std::uint32_t* Mesh::edge_triangles_end(std::uint32_t t, int k) const {
  return topology_->edge_tri.data() + topology_->edge_tri_offsets[std::size_t{topology_->triangle_edge[std::size_t{3} * t + k]} + 1];
}

}  // namespace prox
