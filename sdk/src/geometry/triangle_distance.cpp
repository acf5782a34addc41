#include "geometry/triangle_distance.h"

#include "geometry/closest_points.h"
#include "geometry/predicates.h"
#include "geometry/triangle_intersection.h"
#include "geometry/triangle_screen.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace prox::geometry {
namespace {

using detail::closest_point_with_normal;
using detail::edge_outside;
using detail::interior_params_segment_segment;
using detail::length2;
using detail::polished;
using detail::robust_normal;

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

double longest_edge(const Triangle& t) {
  return std::sqrt(std::max({length2(t.v[1] - t.v[0]), length2(t.v[2] - t.v[1]), length2(t.v[0] - t.v[2])}));
}

// A candidate closest pair. Non-intersecting triangles reach their minimum
// distance at a vertex of one against the other triangle, or between the
// interiors of two edges; every extreme point of the (convex) set of closest
// pairs is one of these candidates, which is what lets ties name features.
struct Candidate {
  Vec3 pa, pb;
  double d2;
};

struct CandidateList {
  Candidate c[15];
  int n = 0;
  void add(const Vec3& pa, const Vec3& pb) { c[n++] = {pa, pb, length2(pb - pa)}; }
};

// Whether every point of pts is within tol2 (squared) of segment [a, b].
[[gnu::always_inline]] inline bool segment_holds(const Vec3* pts, int n, const Vec3& a, const Vec3& b, double tol2) {
  const Vec3 d = b - a;
  const double dd = length2(d);
  const double inv = dd > 0.0 ? 1.0 / dd : 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec3 x = a + std::clamp(glm::dot(pts[i] - a, d) * inv, 0.0, 1.0) * d;
    if (length2(pts[i] - x) > tol2) return false;
  }
  return true;
}

// The lowest-dimensional feature of t that holds every point of pts within
// `tol`. Several vertices or edges qualify only on (near-)degenerate
// triangles; the choice must not depend on vertex order, so it is the nearest
// vertex (coincident vertices are the same place) and the longest edge (on a
// collinear triangle it spans the others).
[[gnu::always_inline]] inline Feature feature_holding(const Triangle& t, const Vec3* pts, int n, double tol) {
  int best_vertex = -1;
  double best2 = tol * tol;
  for (int k = 0; k < 3; ++k) {
    double worst2 = 0.0;  // the farthest point from vertex k
    for (int i = 0; i < n && worst2 <= best2; ++i) worst2 = std::max(worst2, length2(pts[i] - t.v[k]));
    if (worst2 <= best2) best_vertex = k, best2 = worst2;
  }
  if (best_vertex >= 0) return {FeatureKind::Vertex, static_cast<std::uint8_t>(best_vertex)};
  int best_edge = -1;
  double best_length2 = -1.0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 &a = t.v[k], &b = t.v[(k + 1) % 3];
    const double len2 = length2(b - a);
    if (len2 > best_length2 && segment_holds(pts, n, a, b, tol * tol)) best_edge = k, best_length2 = len2;
  }
  if (best_edge >= 0) return {FeatureKind::Edge, static_cast<std::uint8_t>(best_edge)};
  return {FeatureKind::Face, 0};
}

Triangle translated(const Triangle& t, const Vec3& origin) {
  return {{t.v[0] - origin, t.v[1] - origin, t.v[2] - origin}};
}

// Middle of the bounding box of both triangles. It does not depend on vertex
// or argument order, so the translated coordinates are bit-identical under
// every permutation, and subtracting it is exact for coordinates far from the
// world origin (Sterbenz), which keeps full precision relative to the
// triangles' size wherever they are.
Vec3 local_origin(const Triangle& a, const Triangle& b) {
  Vec3 lo = a.v[0], hi = a.v[0];
  for (const Triangle* t : {&a, &b})
    for (const Vec3& v : t->v) lo = glm::min(lo, v), hi = glm::max(hi, v);
  return 0.5 * lo + 0.5 * hi;
}

// Every candidate: each vertex against the other face, and each edge pair's
// closest points. A degenerate triangle's "face" is its edges, which the
// edge-edge candidates cover.
void add_every_candidate(const Triangle& a, const Triangle& b, bool a_flat, bool b_flat,
                         CandidateList& cand) {
  const Vec3 normal_a = a_flat ? Vec3(0.0) : robust_normal(a);
  const Vec3 normal_b = b_flat ? Vec3(0.0) : robust_normal(b);
  for (int i = 0; i < 3; ++i) {
    if (!b_flat) cand.add(a.v[i], closest_point_with_normal(a.v[i], b, normal_b));
    if (!a_flat) cand.add(closest_point_with_normal(b.v[i], a, normal_a), b.v[i]);
  }
  for (int i = 0; i < 3; ++i) {
    const Vec3 &p0 = a.v[i], &p1 = a.v[(i + 1) % 3];
    for (int j = 0; j < 3; ++j) {
      const Vec3 &q0 = b.v[j], &q1 = b.v[(j + 1) % 3];
      const Vec2 st = closest_params_segment_segment(p0, p1, q0, q1);
      cand.add(p0 + st.x * (p1 - p0), q0 + st.y * (q1 - q0));
    }
  }
}

// A non-degenerate triangle with what every query against it reuses: its
// edges (edge k from vertex k to k + 1), their squared lengths and inverses, the
// robust normal (robust_normal's arithmetic on these edges) and, for each
// edge, the in-plane normal n x e_k: a point is on the triangle's side of
// edge k when its dot product with that, taken from the edge's nearer end,
// is >= 0, whatever the winding (edge_outside).
struct Prepared {
  const Triangle* t;
  Vec3 e[3];
  double ee[3], inv_ee[3];
  Vec3 n;
  double inv_nn = 0.0;
  Vec3 m[3];

  explicit Prepared(const Triangle& tri) : t(&tri) {
    int longest = 0;
    for (int k = 0; k < 3; ++k) {
      e[k] = tri.v[(k + 1) % 3] - tri.v[k];
      ee[k] = length2(e[k]);
      inv_ee[k] = ee[k] > 0.0 ? 1.0 / ee[k] : 0.0;
      if (ee[k] > ee[longest]) longest = k;
    }
    n = glm::cross(e[longest], e[(longest + 1) % 3]);
    if (ee[longest] > 0.0) n -= (glm::dot(n, e[longest]) / ee[longest]) * e[longest];
    const double nn = length2(n);
    if (nn > 0.0 && std::isfinite(nn)) inv_nn = 1.0 / nn;
    for (int k = 0; k < 3; ++k) m[k] = glm::cross(n, e[k]);
  }
  // A plane to project on: not so thin, small or large that its normal
  // rounds to zero or overflows.
  bool usable() const { return inv_nn > 0.0 && std::isfinite(inv_nn); }

  // closest_point_with_normal, from the prepared parts.
  Vec3 closest_point(const Vec3& p) const {
    const Vec3 q = p - (glm::dot(p - t->v[0], n) * inv_nn) * n;
    const Vec3 d[3] = {q - t->v[0], q - t->v[1], q - t->v[2]};
    const double dd[3] = {length2(d[0]), length2(d[1]), length2(d[2])};
    bool outside[3];
    for (int k = 0; k < 3; ++k) outside[k] = edge_outside(m, d, dd, k);
    if (!outside[0] && !outside[1] && !outside[2]) return q;
    // Outside: the closest point is on an edge whose line q is beyond.
    Vec3 best(0.0);
    double best_d2 = INFINITY;
    for (int k = 0; k < 3; ++k) {
      if (!outside[k]) continue;
      const Vec3 x = t->v[k] + std::clamp(glm::dot(p - t->v[k], e[k]) * inv_ee[k], 0.0, 1.0) * e[k];
      const double d2 = length2(p - x);
      if (d2 < best_d2) best = x, best_d2 = d2;
    }
    return best;
  }
};

// The largest distance of a vertex of a or b (local coordinates) from the
// local origin. 16 eps times it is a margin for the rounding of a
// candidate's distance (see Bounds).
double pair_span(const Triangle& a, const Triangle& b) {
  double span2 = 0.0;
  for (const Triangle* t : {&a, &b})
    for (const Vec3& v : t->v) span2 = std::max(span2, length2(v));
  return std::sqrt(span2);
}

// Lower bounds from the two normals: along each triangle's unit normal u,
// the other's vertices and edges are at least the gap between their
// projections and the interval the triangle's own vertices project to
// (any direction gives such a bound; the normals give tight ones). Holding
// for any u, the bounds need u only to be a unit vector, not the exact
// normal, so slivers are no exception. `error`, 16 eps times the largest
// distance of a vertex from the local origin, covers the rounding of the
// projections, of u's length, of the local coordinates and of the
// candidates themselves: a margin, not a derived bound (on adversarial
// inputs the bounds exceeded a computed candidate distance by at most about
// 6 eps of that scale, and touching triangles' gap reached 1 eps).
struct Bounds {
  double vertex[2][3];  // vertex i of triangle k from the other triangle
  double edge[2][3];    // edge i of triangle k from the other triangle
  double error = 0.0;
  double apart = 0.0;      // the triangles' gap along the wider-apart normal: at most their distance
  bool separated = false;  // by more than `error` along a normal: the triangles do not meet

  // `rounding`: 16 eps times pair_span.
  Bounds(const Prepared& pa, const Prepared& pb, double rounding) : error(rounding) {
    const Prepared* p[2] = {&pa, &pb};
    for (int k = 0; k < 2; ++k) {
      const Prepared& self = *p[k];
      const Prepared& other = *p[1 - k];
      const Vec3 u = other.n * std::sqrt(other.inv_nn);
      double proj[3], lo = INFINITY, hi = -INFINITY;
      for (int i = 0; i < 3; ++i) {
        const double x = glm::dot(other.t->v[i], u);
        lo = std::min(lo, x), hi = std::max(hi, x);
        proj[i] = glm::dot(self.t->v[i], u);
      }
      auto gap = [&](double from, double to) { return std::max({from - hi, lo - to, 0.0}); };
      for (int i = 0; i < 3; ++i) {
        const double x0 = proj[i], x1 = proj[(i + 1) % 3];
        vertex[k][i] = gap(x0, x0);
        edge[k][i] = gap(std::min(x0, x1), std::max(x0, x1));
      }
      const double self_lo = std::min({proj[0], proj[1], proj[2]});
      const double self_hi = std::max({proj[0], proj[1], proj[2]});
      apart = std::max(apart, gap(self_lo, self_hi));
    }
    separated = apart > error;
  }
};

// Vertex i of a (o = i) or of b (o = 3 + i) against the other's face.
[[gnu::always_inline]] inline void add_vertex_face(const Prepared& pa, const Prepared& pb, int o,
                                                   CandidateList& cand) {
  if (o < 3) {
    const Vec3& v = pa.t->v[o];
    cand.add(v, pb.closest_point(v));
  } else {
    const Vec3& v = pb.t->v[o - 3];
    cand.add(pa.closest_point(v), v);
  }
}

// Two non-degenerate triangles: the same closest set from fewer candidates.
// - An edge pair whose closest points include an end of an edge adds
//   nothing: that end against the other triangle (a vertex-face candidate)
//   is at least as close, and is the same pair when the two tie exactly. So
//   an edge pair adds a candidate only when its closest points lie inside
//   both edges (or, for parallel edges, at the middle of their overlap).
//   (Within the tie tolerance such an edge point can lie up to
//   sqrt(2 d tolerance) from the vertex-face one; the full enumeration
//   averaged it in, which under a sliver's vertex could name the face where
//   the quad-precision reference names the vertex.)
// - A candidate whose lower bound (Bounds) is beyond the tie tolerance of
//   the best one found so far cannot tie with the minimum, so it is not
//   computed: it would not have tied in the full enumeration either.
// - With a `limit` (finite where only a distance up to it matters), a
//   candidate farther than it cannot be the minimum the caller wants, so
//   the best so far is taken as no more than the limit.
// `tie_slack` 0 keeps only what may be the minimum (the distance alone).
void add_near_candidates(const Prepared& pa, const Prepared& pb, const Bounds& bounds, double limit,
                         double tie_slack, CandidateList& cand) {
  double best2 = INFINITY;
  // A candidate may tie with the minimum while its bound, less the rounding,
  // is within the tie slack of the best so far (or of the limit): bound <= reach.
  double reach = limit + tie_slack;
  auto may_tie = [&](double bound) { return bound - bounds.error <= reach; };
  auto found = [&](double d2) {
    if (d2 < best2) best2 = d2, reach = std::min(std::sqrt(best2), limit) + tie_slack;
  };
  const double* vertex_bound = &bounds.vertex[0][0];
  auto vertex_face = [&](int o) {
    add_vertex_face(pa, pb, o, cand);
    found(cand.c[cand.n - 1].d2);
  };
  // Vertices against faces: the nearest by its bound first (a small best
  // early prunes the rest), then the others that may still tie.
  int first = 0;
  for (int o = 1; o < 6; ++o)
    if (vertex_bound[o] < vertex_bound[first]) first = o;
  vertex_face(first);
  for (int o = 0; o < 6; ++o)
    if (o != first && may_tie(vertex_bound[o])) vertex_face(o);
  // Edges against edges.
  const Triangle &a = *pa.t, &b = *pb.t;
  struct Rough {
    int index, i, j;
    Vec2 st;
  } rough[9];
  int roughs = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (!may_tie(std::max(bounds.edge[0][i], bounds.edge[1][j]))) continue;
      Vec2 st;
      bool near_parallel = false;
      if (interior_params_segment_segment(a.v[i], pa.e[i], pa.ee[i], b.v[j], pb.e[j], pb.ee[j], st,
                                          near_parallel)) {
        if (near_parallel) rough[roughs++] = {cand.n, i, j, st};
        cand.add(a.v[i] + st.x * pa.e[i], b.v[j] + st.y * pb.e[j]);
        found(cand.c[cand.n - 1].d2);
      }
    }
  // Nearly parallel edges' points polished after the loop (rare; a call in
  // the loop costs every pair more than the polish): each only comes closer,
  // so what was pruned against the rough ones stays pruned.
  for (int k = 0; k < roughs; ++k) {
    const Rough& r = rough[k];
    const Vec2 st = polished(a.v[r.i], pa.e[r.i], pa.ee[r.i], b.v[r.j], pb.e[r.j], pb.ee[r.j], r.st);
    const Vec3 p = a.v[r.i] + st.x * pa.e[r.i], q = b.v[r.j] + st.y * pb.e[r.j];
    if (length2(q - p) < cand.c[r.index].d2) cand.c[r.index] = {p, q, length2(q - p)};
  }
}

// The candidates the screen (triangle_screen.h) could not rule out, each
// computed as add_near_candidates computes it: the same arithmetic, so the
// same bits. An edge pair adds a candidate only when its closest points
// are inside both edges, as there.
void add_screened_candidates(const Prepared& pa, const Prepared& pb, std::uint16_t near, CandidateList& cand) {
  for (int o = 0; o < 6; ++o)
    if (near >> o & 1u) add_vertex_face(pa, pb, o, cand);
  const Triangle &a = *pa.t, &b = *pb.t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (!(near >> (6 + 3 * i + j) & 1u)) continue;
      Vec2 st;
      bool near_parallel = false;
      if (!interior_params_segment_segment(a.v[i], pa.e[i], pa.ee[i], b.v[j], pb.e[j], pb.ee[j], st,
                                           near_parallel))
        continue;
      Vec3 p = a.v[i] + st.x * pa.e[i], q = b.v[j] + st.y * pb.e[j];
      if (near_parallel) {
        const Vec2 sp = polished(a.v[i], pa.e[i], pa.ee[i], b.v[j], pb.e[j], pb.ee[j], st);
        const Vec3 pp = a.v[i] + sp.x * pa.e[i], qp = b.v[j] + sp.y * pb.e[j];
        if (length2(qp - pp) < length2(q - p)) p = pp, q = qp;
      }
      cand.add(p, q);
    }
}

// How many candidates closest_result would average: those within the tie
// slack of the least.
int tie_count(const CandidateList& cand, double tie_slack) {
  double min_d2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < cand.n; ++i) min_d2 = std::min(min_d2, cand.c[i].d2);
  const double tie = std::sqrt(min_d2) + tie_slack;
  const double tie2 = std::max(tie * tie, min_d2);
  int ties = 0;
  for (int i = 0; i < cand.n; ++i) ties += cand.c[i].d2 <= tie2 ? 1 : 0;
  return ties;
}

// The result of intersecting triangles: the middle of their intersection
// set and the features holding it.
TriangleDistance intersection_result(const TriangleIntersection& hit, const Triangle& a, const Triangle& b,
                                     double size_a, double size_b) {
  TriangleDistance r;
  Vec3 middle(0.0);
  for (int i = 0; i < hit.count; ++i) middle += hit.points[i];
  middle /= static_cast<double>(hit.count);
  r.intersects = true;
  r.distance = 0.0;
  r.point_a = r.point_b = middle;
  r.feature_a = feature_holding(a, hit.points, hit.count, kFeatureTolerance * size_a);
  r.feature_b = feature_holding(b, hit.points, hit.count, kFeatureTolerance * size_b);
  return r;
}

// The least squared distance among the candidates.
double least_d2(const CandidateList& cand) {
  double min_d2 = INFINITY;
  for (int i = 0; i < cand.n; ++i) min_d2 = std::min(min_d2, cand.c[i].d2);
  return min_d2;
}

// The result from the candidates of separate triangles (in local
// coordinates, `origin` added back), the least of their squared distances
// `min_d2` (least_d2) and its root `min_d` found by the caller.
TriangleDistance closest_result(const CandidateList& cand, double min_d2, double min_d, const Triangle& a,
                                const Triangle& b, const Vec3& origin, double size_a, double size_b,
                                double tie_slack) {

  // Every candidate within the tie tolerance of the minimum is a closest pair
  // (up to rounding); together they span the closest set.
  const double tie = min_d + tie_slack;
  const double tie2 = std::max(tie * tie, min_d2);  // sqrt(x)^2 may round below x
  Vec3 on_a[15], on_b[15];
  int ties = 0;
  Vec3 sum_a(0.0), sum_b(0.0);
  for (int i = 0; i < cand.n; ++i) {
    if (cand.c[i].d2 > tie2) continue;
    on_a[ties] = cand.c[i].pa;
    on_b[ties] = cand.c[i].pb;
    sum_a += cand.c[i].pa;
    sum_b += cand.c[i].pb;
    ++ties;
  }
  TriangleDistance r;
  r.distance = min_d;
  r.point_a = sum_a / static_cast<double>(ties) + origin;
  r.point_b = sum_b / static_cast<double>(ties) + origin;
  // One closest pair is the common case: a constant count, inlined, lets
  // the compiler drop the loops over the points.
  if (ties == 1) {
    r.feature_a = feature_holding(a, on_a, 1, kFeatureTolerance * size_a);
    r.feature_b = feature_holding(b, on_b, 1, kFeatureTolerance * size_b);
  } else {
    r.feature_a = feature_holding(a, on_a, ties, kFeatureTolerance * size_a);
    r.feature_b = feature_holding(b, on_b, ties, kFeatureTolerance * size_b);
  }
  return r;
}

// What a caller wants of a pair: `every`, the full enumeration even where
// the pruned one applies; `limit`, only a distance up to it (past it, only
// that it is past); kDetails, points, features and ties, else the distance
// alone; kScreen, the single-precision screen first (both template
// arguments: the exact kernel's path stays as lean as it was).
struct Want {
  bool every = false;
  double limit = INFINITY;
};

// triangle_distance's answer into `out` (its distance alone without
// kDetails) and true, or false when the distance is past want.limit.
template <bool kDetails, bool kScreen>
bool distance_of(const Triangle& a_world, const Triangle& b_world, const Want& want, TriangleDistance& out) {
  const bool a_flat = collinear3d(a_world.v[0], a_world.v[1], a_world.v[2]);
  const bool b_flat = collinear3d(b_world.v[0], b_world.v[1], b_world.v[2]);
  const Vec3 origin = local_origin(a_world, b_world);
  const Triangle a = translated(a_world, origin), b = translated(b_world, origin);
  const double span = pair_span(a, b);
  const double rounding = 16.0 * kEpsilon * span;
  // Sizes name features and set the tie slack; the distance alone needs
  // neither: it is the least candidate's, ties or not.
  const double size_a = kDetails ? longest_edge(a_world) : 0.0;
  const double size_b = kDetails ? longest_edge(b_world) : 0.0;
  // Candidates tie within kTieTolerance of the size, or within their own
  // rounding where that is larger: triangles more than about 600 sizes
  // apart have local coordinates that large, and exactly tied candidates
  // (parallel faces or edges) then differ by more than the size's tolerance.
  const double tie_slack = kDetails ? std::max(kTieTolerance * std::max(size_a, size_b), rounding) : 0.0;
  auto intersecting = [&](const TriangleIntersection& hit) {
    if constexpr (kDetails) {
      out = intersection_result(hit, a_world, b_world, size_a, size_b);
    } else {
      out.distance = 0.0;
      out.intersects = true;
    }
    return !(0.0 > want.limit);
  };
  CandidateList cand;
  auto closest = [&] {
    const double min_d2 = least_d2(cand);
    const double min_d = std::sqrt(min_d2);
    if (min_d > want.limit) return false;
    if constexpr (kDetails) {
      out = closest_result(cand, min_d2, min_d, a, b, origin, size_a, size_b, tie_slack);
    } else {
      out.distance = min_d;
      out.intersects = false;
    }
    return true;
  };

  if (!want.every && !a_flat && !b_flat) {
    if constexpr (kScreen) {
      // Single precision first (triangle_screen.h): most pairs are past the
      // limit or have one or two candidates that can be the closest, and
      // only those are computed, in double precision. What the screen
      // cannot settle goes on to the exact kernel below.
      const detail::Screen screen = detail::screen_pair(a, b, span, want.limit);
      if (screen.verdict != detail::Screen::Verdict::Unsure) {
        // Not proved apart: the exact test first, which the exact kernel
        // runs on such pairs too (its double-precision bounds separate no
        // pair that meets).
        if (!screen.apart) {
          const TriangleIntersection hit = intersect_triangles(a_world, b_world, a_flat, b_flat);
          if (hit.intersects) return intersecting(hit);
        }
        if (screen.verdict == detail::Screen::Verdict::Farther) return false;
        const Prepared pa(a), pb(b);
        if (pa.usable() && pb.usable()) {
          add_screened_candidates(pa, pb, screen.near, cand);
          // Two tied candidates average the same in either order; three or
          // more in the order add_near_candidates finds them, so those
          // pairs go on.
          if (cand.n > 0 && (!kDetails || tie_count(cand, tie_slack) <= 2)) return closest();
          cand.n = 0;
        }
      }
    }
    const Prepared pa(a), pb(b);
    if (pa.usable() && pb.usable()) {
      const Bounds bounds(pa, pb, rounding);
      // Farther apart along a normal than the limit: so is every pair of
      // points (the bounds' rounding margin taken off).
      if (bounds.separated && bounds.apart - bounds.error > want.limit) return false;
      // Separated along a normal, they do not meet: the exact test would
      // say so too.
      if (!bounds.separated) {
        const TriangleIntersection hit = intersect_triangles(a_world, b_world, a_flat, b_flat);
        if (hit.intersects) return intersecting(hit);
      }
      add_near_candidates(pa, pb, bounds, want.limit, tie_slack, cand);
      return closest();
    }
  }
  const TriangleIntersection hit = intersect_triangles(a_world, b_world, a_flat, b_flat);
  if (hit.intersects) return intersecting(hit);
  add_every_candidate(a, b, a_flat, b_flat, cand);
  return closest();
}

// The public entry points' three shapes, with and without the screen.
template <bool kScreen>
TriangleDistance full_answer(const Triangle& a, const Triangle& b, const Want& want = Want{}) {
  TriangleDistance out;
  distance_of<true, kScreen>(a, b, want, out);
  return out;
}

template <bool kScreen>
double value_within(const Triangle& a, const Triangle& b, double limit) {
  TriangleDistance out;
  return distance_of<false, kScreen>(a, b, Want{false, limit}, out) ? out.distance
                                                                    : std::numeric_limits<double>::infinity();
}

}  // namespace

detail::LocalPair detail::local_pair(const Triangle& a, const Triangle& b) {
  const Vec3 origin = local_origin(a, b);
  LocalPair p{translated(a, origin), translated(b, origin), 0.0};
  p.span = pair_span(p.a, p.b);
  return p;
}

TriangleDistance triangle_distance(const Triangle& a, const Triangle& b) { return full_answer<true>(a, b); }

TriangleDistance triangle_distance_every_candidate(const Triangle& a, const Triangle& b) {
  return full_answer<false>(a, b, Want{true, INFINITY});
}

bool triangle_distance_within(const Triangle& a, const Triangle& b, double limit, TriangleDistance& out) {
  return distance_of<true, true>(a, b, Want{false, limit}, out);
}

double triangle_distance_value(const Triangle& a, const Triangle& b, double limit) {
  return value_within<true>(a, b, limit);
}

TriangleDistance triangle_distance_unscreened(const Triangle& a, const Triangle& b) {
  return full_answer<false>(a, b);
}

bool triangle_distance_within_unscreened(const Triangle& a, const Triangle& b, double limit, TriangleDistance& out) {
  return distance_of<true, false>(a, b, Want{false, limit}, out);
}

double triangle_distance_value_unscreened(const Triangle& a, const Triangle& b, double limit) {
  return value_within<false>(a, b, limit);
}

}  // namespace prox::geometry
