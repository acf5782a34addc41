#include "geometry/sampled_distance.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace prox::geometry {
namespace {

struct FeaturePoints {
  Vec3 p[7];
  Feature f[7];
};

FeaturePoints feature_points(const Triangle& t) {
  FeaturePoints r;
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::uint8_t>(k);
    r.p[k] = t.v[k];
    r.f[k] = {FeatureKind::Vertex, i};
    r.p[3 + k] = 0.5 * (t.v[k] + t.v[(k + 1) % 3]);
    r.f[3 + k] = {FeatureKind::Edge, i};
  }
  r.p[6] = (t.v[0] + t.v[1] + t.v[2]) / 3.0;
  r.f[6] = {FeatureKind::Face, 0};
  return r;
}

}  // namespace

TriangleDistance sampled_triangle_distance(const Triangle& ta, const Triangle& tb) {
  const FeaturePoints a = feature_points(ta), b = feature_points(tb);
  int bi = 0, bj = 0;
  double best = INFINITY;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) {
      const Vec3 d = b.p[j] - a.p[i];
      const double dd = glm::dot(d, d);
      if (dd < best) best = dd, bi = i, bj = j;
    }
  TriangleDistance r;
  r.distance = std::sqrt(best);
  r.point_a = a.p[bi];
  r.point_b = b.p[bj];
  r.feature_a = a.f[bi];
  r.feature_b = b.f[bj];
  return r;
}

}  // namespace prox::geometry
