#include "stress/evaluate.h"

#include "geometry/triangle_distance.h"
#include "geometry/triangle_intersection.h"
#include "stress/quad_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace prox::stress {
namespace {

using geometry::triangle_distance;
using geometry::TriangleDistance;

constexpr double kEps = std::numeric_limits<double>::epsilon();

double longest_edge(const Triangle& t) {
  double m = 0.0;
  for (int k = 0; k < 3; ++k) m = std::max(m, glm::length(t.v[(k + 1) % 3] - t.v[k]));
  return m;
}

double max_coordinate(const Triangle& a, const Triangle& b) {
  double m = 0.0;
  for (const Triangle* t : {&a, &b})
    for (const Vec3& v : t->v) m = std::max({m, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  return m;
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

Triangle rotate(const Triangle& t, int r) { return {{t.v[r % 3], t.v[(r + 1) % 3], t.v[(r + 2) % 3]}}; }

// A feature as the set of its vertices' coordinates, sorted, so features can
// be compared across vertex orders (and on degenerate triangles, where two
// indices may name the same place).
std::vector<std::array<double, 3>> feature_points(const Triangle& t, Feature f) {
  std::vector<std::array<double, 3>> pts;
  auto add = [&](int k) { pts.push_back({t.v[k].x, t.v[k].y, t.v[k].z}); };
  switch (f.kind) {
    case FeatureKind::Vertex:
      add(f.index);
      break;
    case FeatureKind::Edge:
      add(f.index), add((f.index + 1) % 3);
      break;
    case FeatureKind::Face:
      add(0), add(1), add(2);
      break;
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  return pts;
}

// Distance from p to the feature f of t.
double distance_to_feature(const Vec3& p, const Triangle& t, Feature f) {
  switch (f.kind) {
    case FeatureKind::Vertex:
      return glm::length(p - t.v[f.index]);
    case FeatureKind::Edge: {
      const Triangle seg{{t.v[f.index], t.v[(f.index + 1) % 3], t.v[(f.index + 1) % 3]}};
      return to_double(reference_point_triangle_distance(to_quad(p), seg));
    }
    case FeatureKind::Face:
      return to_double(reference_point_triangle_distance(to_quad(p), t));
  }
  return INFINITY;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

std::string describe(const Case& c) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "a={(%.17g,%.17g,%.17g),(%.17g,%.17g,%.17g),(%.17g,%.17g,%.17g)} "
                "b={(%.17g,%.17g,%.17g),(%.17g,%.17g,%.17g),(%.17g,%.17g,%.17g)}",
                c.a.v[0].x, c.a.v[0].y, c.a.v[0].z, c.a.v[1].x, c.a.v[1].y, c.a.v[1].z, c.a.v[2].x,
                c.a.v[2].y, c.a.v[2].z, c.b.v[0].x, c.b.v[0].y, c.b.v[0].z, c.b.v[1].x, c.b.v[1].y,
                c.b.v[1].z, c.b.v[2].x, c.b.v[2].y, c.b.v[2].z);
  return buf;
}

// The 36 permutations of each triangle's vertices, both argument orders.
bool intersection_verdict_invariant(const Case& c, bool expected) {
  static const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (const auto& pa : perms)
    for (const auto& pb : perms) {
      const Triangle a{{c.a.v[pa[0]], c.a.v[pa[1]], c.a.v[pa[2]]}};
      const Triangle b{{c.b.v[pb[0]], c.b.v[pb[1]], c.b.v[pb[2]]}};
      if (geometry::triangles_intersect(a, b) != expected || geometry::triangles_intersect(b, a) != expected)
        return false;
    }
  return true;
}

}  // namespace

FamilyStats evaluate_family(const Family& family, std::uint64_t seed, int count) {
  FamilyStats s;
  s.name = family.name;
  const std::vector<Case> cases = family.generate(seed, count);
  std::vector<double> size_errors, rel_errors;
  auto note = [&s](const char* what, const Case& c) {
    if (s.examples.size() < 4) s.examples.push_back(std::string(what) + ": " + describe(c));
  };

  for (const Case& c : cases) {
    ++s.cases;
    const TriangleDistance r = triangle_distance(c.a, c.b);
    if (!std::isfinite(r.distance) || !finite(r.point_a) || !finite(r.point_b)) {
      ++s.nan_count;
      note("non-finite", c);
      continue;
    }
    const ReferenceDistance ref = reference_distance(c.a, c.b);
    const double ref_d = to_double(ref.distance);
    // L: the scale of the local geometry, the longest edge or (for point
    // triangles) the distance itself.
    const double size = std::max({longest_edge(c.a), longest_edge(c.b), ref_d});
    const double scale = size > 0.0 ? size : std::max(1.0, max_coordinate(c.a, c.b)) * kEps;

    // Verdict: the construction decides when it can; otherwise the reference,
    // except inside its rounding band around touching.
    bool judged = true;
    bool expected = ref.intersects;
    if (c.known != Case::Known::Unknown) {
      expected = c.known == Case::Known::Intersecting;
    } else if (!ref.intersects && ref_d <= 1e-20 * scale) {
      judged = false;
    }
    if (!judged) {
      ++s.ambiguous_verdicts;
    } else if (r.intersects != expected) {
      ++s.verdict_mismatches;
      note("verdict", c);
    }

    // Distance error against the reference and the family's bound.
    const double err = std::abs(r.distance - ref_d);
    const double allowed =
        family.bound.size_ulps * kEps * scale + family.bound.coord_ulps * kEps * max_coordinate(c.a, c.b);
    size_errors.push_back(err / scale);
    if (ref_d > 0.0) rel_errors.push_back(err / ref_d);
    s.max_bound_ratio = std::max(s.max_bound_ratio, err / allowed);
    if (err > allowed) {
      ++s.bound_violations;
      note("distance", c);
    }

    // The closest points lie on their triangles and their gap is the distance.
    const double allowed_off =
        family.bound.point_rel * scale + family.bound.coord_ulps * kEps * max_coordinate(c.a, c.b);
    const double off_a = to_double(reference_point_triangle_distance(to_quad(r.point_a), c.a));
    const double off_b = to_double(reference_point_triangle_distance(to_quad(r.point_b), c.b));
    s.max_point_error = std::max(s.max_point_error, std::max(off_a, off_b) / scale);
    if (std::max(off_a, off_b) > allowed_off) {
      ++s.point_violations;
      note("closest point off its triangle", c);
    }
    const double gap = std::abs(glm::length(r.point_b - r.point_a) - r.distance);
    s.max_gap_error = std::max(s.max_gap_error, gap / scale);
    if (gap > 2.0 * allowed_off) {
      ++s.point_violations;
      note("closest points not the distance apart", c);
    }

    // The points lie on the features named, and known features are named.
    const double feature_tol = 1e-6 * scale;
    bool feature_ok = distance_to_feature(r.point_a, c.a, r.feature_a) <= feature_tol &&
                      distance_to_feature(r.point_b, c.b, r.feature_b) <= feature_tol;
    if (c.known_features)
      feature_ok = feature_ok && r.feature_a.kind == c.kind_a && r.feature_b.kind == c.kind_b;
    if (!feature_ok) {
      ++s.feature_errors;
      note("feature", c);
    }

    // Invariance: both argument orders, all 3 x 3 vertex rotations.
    bool invariant = true;
    double lo = r.distance, hi = r.distance;
    const auto fa = feature_points(c.a, r.feature_a), fb = feature_points(c.b, r.feature_b);
    for (int ra = 0; ra < 3; ++ra)
      for (int rb = 0; rb < 3; ++rb) {
        const Triangle a = rotate(c.a, ra), b = rotate(c.b, rb);
        const TriangleDistance x = triangle_distance(a, b);
        const TriangleDistance y = triangle_distance(b, a);
        lo = std::min({lo, x.distance, y.distance});
        hi = std::max({hi, x.distance, y.distance});
        invariant = invariant && x.intersects == r.intersects && y.intersects == r.intersects &&
                    feature_points(a, x.feature_a) == fa && feature_points(b, x.feature_b) == fb &&
                    feature_points(a, y.feature_b) == fa && feature_points(b, y.feature_a) == fb;
      }
    s.max_invariance_spread = std::max(s.max_invariance_spread, (hi - lo) / scale);
    if (!invariant || hi - lo > allowed) {
      ++s.invariance_violations;
      note("invariance", c);
    }
    if (!intersection_verdict_invariant(c, r.intersects)) {
      ++s.intersection_invariance_violations;
      note("intersection invariance", c);
    }

    // Intersection points lie on both triangles.
    if (r.intersects) {
      const geometry::TriangleIntersection hit = geometry::intersect_triangles(c.a, c.b);
      for (int i = 0; i < hit.count; ++i) {
        const QVec3 p = to_quad(hit.points[i]);
        const double off = std::max(to_double(reference_point_triangle_distance(p, c.a)),
                                    to_double(reference_point_triangle_distance(p, c.b)));
        s.max_intersection_point_error = std::max(s.max_intersection_point_error, off / scale);
        if (off > allowed_off) {
          ++s.point_violations;
          note("intersection point off a triangle", c);
        }
      }
    }
  }
  s.max_size_error = size_errors.empty() ? 0.0 : *std::max_element(size_errors.begin(), size_errors.end());
  s.median_size_error = median(size_errors);
  s.max_rel_error = rel_errors.empty() ? 0.0 : *std::max_element(rel_errors.begin(), rel_errors.end());
  s.median_rel_error = median(rel_errors);
  return s;
}

}  // namespace prox::stress
