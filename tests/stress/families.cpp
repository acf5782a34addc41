#include "stress/families.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <cmath>
#include <random>

namespace prox::stress {
namespace {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  double log_uniform(double lo_exp10, double hi_exp10) { return std::pow(10.0, uniform(lo_exp10, hi_exp10)); }
  Vec3 vec(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
  Vec3 unit() {
    for (;;) {
      const Vec3 v = vec(-1.0, 1.0);
      const double n = glm::dot(v, v);
      if (n > 1e-4 && n <= 1.0) return v / std::sqrt(n);
    }
  }
  // A dyadic number k / 2^bits, |k| < 2^bits: exact, and sums and midpoints of
  // a few of them stay exact.
  double dyadic(double lo, double hi, int bits = 20) {
    return std::ldexp(std::floor(std::ldexp(uniform(lo, hi), bits)), -bits);
  }
  Vec3 dyadic_vec(double lo, double hi) { return {dyadic(lo, hi), dyadic(lo, hi), dyadic(lo, hi)}; }
  glm::dmat3 rotation() {
    const glm::dquat q =
        glm::normalize(glm::dquat(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
    return glm::mat3_cast(q);
  }
  bool coin() { return integer(0, 1) == 1; }

 private:
  std::mt19937_64 engine_;
};

Triangle random_triangle(Rng& rng, const Vec3& center, double size) {
  return {{center + size * rng.vec(-0.5, 0.5), center + size * rng.vec(-0.5, 0.5),
           center + size * rng.vec(-0.5, 0.5)}};
}

// Applies x -> R x + t to both triangles (inexact: for families where the
// configuration only needs to be near-special).
void move(Case& c, const glm::dmat3& r, const Vec3& t) {
  for (Triangle* tri : {&c.a, &c.b})
    for (Vec3& v : tri->v) v = r * v + t;
}

// An exact rigid map: a permutation of the axes with sign flips. Keeps exact
// coplanarity, parallelism and incidence.
void exact_axis_map(Case& c, Rng& rng) {
  int perm[3] = {0, 1, 2};
  for (int i = 2; i > 0; --i) std::swap(perm[i], perm[rng.integer(0, i)]);
  const double sign[3] = {rng.coin() ? 1.0 : -1.0, rng.coin() ? 1.0 : -1.0, rng.coin() ? 1.0 : -1.0};
  for (Triangle* tri : {&c.a, &c.b})
    for (Vec3& v : tri->v) {
      const Vec3 old = v;
      for (int k = 0; k < 3; ++k) v[k] = sign[k] * old[perm[k]];
    }
}

template <typename Make>
std::vector<Case> make_cases(std::uint64_t seed, int count, Make make) {
  Rng rng(seed);
  std::vector<Case> out;
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) out.push_back(make(rng));
  return out;
}

// ---- families ----------------------------------------------------------------

std::vector<Case> general(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    c.a = random_triangle(rng, Vec3(0.0), 1.0);
    c.b = random_triangle(rng, rng.unit() * rng.uniform(0.0, 2.0), 1.0);
    return c;
  });
}

std::vector<Case> near_parallel_edges(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    const double angle = rng.log_uniform(-12.0, -3.0);
    const double gap = rng.log_uniform(-6.0, -1.0);
    c.a = {{Vec3(-0.5, 0, 0), Vec3(0.5, 0, 0),
            Vec3(rng.uniform(-0.5, 0.5), -rng.uniform(0.2, 1.0), rng.uniform(-0.5, 0.5))}};
    const Vec3 dir = glm::normalize(Vec3(1.0, angle * rng.uniform(-1, 1), angle * rng.uniform(-1, 1)));
    const Vec3 start(rng.uniform(-1.0, 0.5), gap, rng.uniform(-0.1, 0.1) * gap);
    c.b = {{start, start + rng.uniform(0.3, 1.0) * dir,
            start + Vec3(rng.uniform(-0.5, 0.5), rng.uniform(0.2, 1.0), rng.uniform(-0.5, 0.5))}};
    move(c, rng.rotation(), rng.vec(-1, 1));
    return c;
  });
}

std::vector<Case> parallel_edges(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    const double y = rng.dyadic(0.001, 0.5), z = rng.dyadic(-0.1, 0.1);
    c.a = {{Vec3(rng.dyadic(-1, 0), 0, 0), Vec3(rng.dyadic(0, 1), 0, 0),
            Vec3(rng.dyadic(-1, 1), -rng.dyadic(0.1, 1), rng.dyadic(-1, 1))}};
    c.b = {{Vec3(rng.dyadic(-1.5, 0.5), y, z), Vec3(rng.dyadic(0.5, 1.5), y, z),
            Vec3(rng.dyadic(-1, 1), y + rng.dyadic(0.1, 1), z + rng.dyadic(-1, 1))}};
    exact_axis_map(c, rng);
    return c;
  });
}

std::vector<Case> near_parallel_faces(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    const double h = rng.log_uniform(-6.0, -1.0);
    c.a = {{Vec3(rng.uniform(-1, 0), rng.uniform(-1, 0), 0), Vec3(rng.uniform(0, 1), rng.uniform(-1, 0), 0),
            Vec3(rng.uniform(-0.5, 0.5), rng.uniform(0.2, 1), 0)}};
    // b: a in-plane copy lifted by h and tilted by a tiny angle about its centroid.
    const glm::dmat3 tilt = glm::mat3_cast(
        glm::angleAxis(rng.log_uniform(-12.0, -3.0), glm::normalize(Vec3(rng.unit().x, rng.unit().y, 0.0))));
    const Vec3 centre(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), 0.0);
    for (int i = 0; i < 3; ++i)
      c.b.v[i] = centre + tilt * (c.a.v[(i + 1) % 3] * rng.uniform(0.5, 1.2)) + Vec3(0, 0, h);
    move(c, rng.rotation(), rng.vec(-1, 1));
    return c;
  });
}

// A triangle in z = 0 with dyadic corners that holds the disc of radius 0.12
// around the origin.
Triangle around_origin_z0(Rng& rng) {
  return {{Vec3(rng.dyadic(-1, -0.5), rng.dyadic(-1, -0.5), 0),
           Vec3(rng.dyadic(0.5, 1), rng.dyadic(-1, -0.5), 0),
           Vec3(rng.dyadic(-0.2, 0.2), rng.dyadic(0.5, 1), 0)}};
}

std::vector<Case> parallel_faces(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    const double h = rng.dyadic(0.0001, 0.5);
    c.a = around_origin_z0(rng);
    // b is a small triangle around the origin, which a holds with room to
    // spare: the projections overlap with positive area.
    const double s = rng.dyadic(0.01, 0.08);
    c.b = {{Vec3(-s, -s, h), Vec3(s, -s, h), Vec3(0, s, h)}};
    c.known = Case::Known::Disjoint;
    c.known_features = true;  // face against face: the closest set is a 2D region
    exact_axis_map(c, rng);
    return c;
  });
}

// Points of the plane z = 3x - 2y with integer x, y: exactly coplanar, tilted.
Vec3 lattice_point(Rng& rng, int x_lo, int x_hi) {
  const double x = rng.integer(x_lo, x_hi), y = rng.integer(-1000, 1000);
  return {x, y, 3.0 * x - 2.0 * y};
}

std::vector<Case> coplanar_overlapping(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    if (rng.coin()) {
      // z = 0, b around a point inside a.
      c.a = around_origin_z0(rng);
      const double s = rng.dyadic(0.05, 2.0);
      const Vec3 o(rng.dyadic(-0.05, 0.05), rng.dyadic(-0.05, 0.05), 0);
      c.b = {{o + Vec3(-s, -s, 0), o + Vec3(s, rng.dyadic(-1, 1) * s, 0),
              o + Vec3(rng.dyadic(-1, 1) * s, s, 0)}};
    } else {
      // Tilted lattice plane; both triangles contain the lattice origin.
      auto around_origin = [&rng]() {
        const double k = rng.integer(1, 300);
        return Triangle{{Vec3(-k, -k, 3 * -k - 2 * -k), Vec3(k, -k + rng.integer(-2, 2), 0),
                         Vec3(rng.integer(-5, 5), k, 0)}};
      };
      c.a = around_origin();
      c.b = around_origin();
      for (Triangle* t : {&c.a, &c.b})
        for (Vec3& v : t->v) v.z = 3.0 * v.x - 2.0 * v.y;
    }
    c.known = Case::Known::Intersecting;
    exact_axis_map(c, rng);
    return c;
  });
}

std::vector<Case> coplanar_disjoint(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    if (rng.coin()) {
      const double gap = std::ldexp(1.0, -rng.integer(1, 40));
      for (int i = 0; i < 3; ++i) {
        c.a.v[i] = Vec3(rng.dyadic(-1, 0), rng.dyadic(-1, 1), 0);
        c.b.v[i] = Vec3(gap + rng.dyadic(0, 1), rng.dyadic(-1, 1), 0);
      }
    } else {
      for (int i = 0; i < 3; ++i) {
        c.a.v[i] = lattice_point(rng, -1000, 0);
        c.b.v[i] = lattice_point(rng, 1, 1000);
      }
    }
    c.known = Case::Known::Disjoint;
    exact_axis_map(c, rng);
    return c;
  });
}

std::vector<Case> touching_vertex(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    c.a = around_origin_z0(rng);
    // The touching point: a vertex, an edge midpoint or an interior point of a
    // (midpoints of dyadics are exact).
    const int where = rng.integer(0, 2);
    const int k = rng.integer(0, 2);
    const Vec3 m = 0.5 * (c.a.v[k] + c.a.v[(k + 1) % 3]);
    const Vec3 touch = where == 0 ? c.a.v[k] : where == 1 ? m : 0.5 * (m + c.a.v[(k + 2) % 3]);
    c.b = {{touch, touch + Vec3(rng.dyadic(-1, 1), rng.dyadic(-1, 1), rng.dyadic(0.1, 1)),
            touch + Vec3(rng.dyadic(-1, 1), rng.dyadic(-1, 1), rng.dyadic(0.1, 1))}};
    c.known = Case::Known::Intersecting;
    c.known_features = true;
    c.kind_a = where == 0 ? FeatureKind::Vertex : where == 1 ? FeatureKind::Edge : FeatureKind::Face;
    c.kind_b = FeatureKind::Vertex;
    exact_axis_map(c, rng);
    return c;
  });
}

std::vector<Case> touching_edge(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    c.a = around_origin_z0(rng);
    if (rng.coin()) {
      // b's edge lies on a's edge k, inside it (quarter points are exact).
      const int k = rng.integer(0, 2);
      const Vec3 p = c.a.v[k], q = c.a.v[(k + 1) % 3];
      c.b = {{0.75 * p + 0.25 * q, 0.25 * p + 0.75 * q,
              0.5 * (p + q) + Vec3(rng.dyadic(-1, 1), rng.dyadic(-1, 1), rng.dyadic(0.1, 1))}};
      c.known_features = true;
      c.kind_a = FeatureKind::Edge;
      c.kind_b = FeatureKind::Edge;
    } else {
      // b's edge lies in a's plane across a's interior, b stands above it.
      const Vec3 m0 = 0.5 * (c.a.v[0] + c.a.v[1]), m1 = 0.5 * (c.a.v[1] + c.a.v[2]);
      const Vec3 p = 0.5 * (m0 + c.a.v[2]), q = 0.5 * (m1 + c.a.v[0]);
      c.b = {{p, q, 0.5 * (p + q) + Vec3(rng.dyadic(-1, 1), rng.dyadic(-1, 1), rng.dyadic(0.1, 1))}};
      c.known_features = true;
      c.kind_a = FeatureKind::Face;
      c.kind_b = FeatureKind::Edge;
    }
    c.known = Case::Known::Intersecting;
    exact_axis_map(c, rng);
    return c;
  });
}

// Both triangles have the origin strictly inside; they are not coplanar.
std::vector<Case> crossing(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    auto around_origin = [&rng](const Vec3& n) {
      // q2 = -(w0 q0 + w1 q1) / w2 puts the origin inside with weights w.
      const Vec3 u = glm::normalize(glm::cross(n, rng.unit())), w = glm::cross(n, u);
      const double w0 = rng.uniform(0.2, 1), w1 = rng.uniform(0.2, 1), w2 = rng.uniform(0.2, 1);
      const Vec3 q0 = rng.uniform(0.3, 1) * (u * rng.uniform(0.5, 1.0) + w * rng.uniform(-0.5, 0.5));
      const Vec3 q1 = rng.uniform(0.3, 1) * (-u * rng.uniform(0.0, 0.5) + w * rng.uniform(0.5, 1.0));
      return Triangle{{q0, q1, -(w0 * q0 + w1 * q1) / w2}};
    };
    const Vec3 na = rng.unit();
    Vec3 nb = rng.unit();
    while (std::abs(glm::dot(na, nb)) > 0.95) nb = rng.unit();
    c.a = around_origin(na);
    c.b = around_origin(nb);
    c.known = Case::Known::Intersecting;
    move(c, glm::dmat3(1.0), rng.vec(-1, 1));
    return c;
  });
}

// An edge of a small b passes through the interior of a large a.
std::vector<Case> piercing(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    c.a = {{Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(0, 1, 0)}};
    const double s = rng.log_uniform(-4.0, -1.3);
    const Vec3 at(rng.uniform(-0.2, 0.2), rng.uniform(-0.4, 0.1), 0.0);
    c.b = {{at + s * Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), -rng.uniform(0.2, 1)),
            at + s * Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.2, 1)),
            at + s * Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.2, 1))}};
    // The first vertex is below, the others above: the crossing points of
    // edges 0 and 2 lie within s of `at`, well inside a.
    c.known = Case::Known::Intersecting;
    move(c, rng.rotation(), rng.vec(-1, 1));
    return c;
  });
}

std::vector<Case> slivers(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    auto sliver = [&rng]() {
      const double aspect = rng.log_uniform(-8.0, 0.0);
      const double t = rng.uniform(-0.5, 1.5);  // apex above or beyond the base
      return Triangle{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(t, aspect, 0)}};
    };
    c.a = sliver();
    c.b = rng.coin() ? sliver() : random_triangle(rng, Vec3(0.0), 1.0);
    const glm::dmat3 rb = rng.rotation();
    for (Vec3& v : c.b.v) v = rb * v;
    const Vec3 shift = rng.unit() * rng.log_uniform(-7.0, 0.0);
    for (Vec3& v : c.b.v) v += shift + Vec3(0.5, 0.0, 0.0);
    move(c, rng.rotation(), Vec3(0.0));
    return c;
  });
}

// A vertex of b near a vertex of a sliver a (angles 1e-8..1e-2): the sharp
// tip of a needle, or the obtuse vertex of a cap, above it by 1e-10..0.1 and
// off it in the plane by 1e-16..1e-6, inside a or out. Behind a needle's tip,
// within about eps L / angle of it, the point is within rounding of both long
// edges' lines; near a cap's obtuse vertex, just inside, it is within
// rounding of both short edges' lines. Edge tests taken from the edges' far
// ends can round either way there.
std::vector<Case> sliver_apex(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    const double angle = rng.log_uniform(-8.0, -2.0);
    double phi = 0.0;
    Vec3 tip;
    if (rng.coin()) {  // a needle: tip at the origin, tip angle `angle`
      const double l = rng.uniform(0.5, 1.5);
      c.a = {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(l * std::cos(angle), l * std::sin(angle), 0)}};
      const double bisector = 0.5 * angle;
      switch (rng.integer(0, 2)) {
        case 0: phi = bisector + M_PI + rng.uniform(-1.0, 1.0) * angle; break;  // behind the tip
        case 1: phi = bisector + rng.uniform(-0.5, 0.5) * angle; break;         // inside the wedge
        default: phi = rng.uniform(-M_PI, M_PI); break;
      }
      tip = Vec3(0.0);
    } else {  // a cap: vertex c at (t, w), its angle pi - about 2 w / (t (1 - t))
      const double t = rng.uniform(0.2, 0.8), w = angle * t * (1.0 - t);
      c.a = {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(t, w, 0)}};
      switch (rng.integer(0, 2)) {
        case 0: phi = -0.5 * M_PI + rng.uniform(-1.0, 1.0) * (0.5 * M_PI); break;  // inside, below c
        case 1: phi = rng.coin() ? rng.uniform(-angle, angle) : M_PI + rng.uniform(-angle, angle); break;
        default: phi = rng.uniform(-M_PI, M_PI); break;
      }
      tip = c.a.v[2];
    }
    const double r = rng.log_uniform(-16.0, -6.0), h = rng.log_uniform(-10.0, -1.0);
    const Vec3 p = tip + Vec3(r * std::cos(phi), r * std::sin(phi), h);
    const double s = rng.log_uniform(-3.0, 0.0);
    c.b = {{p, p + s * Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.5, 1)),
            p + s * Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.5, 1))}};
    move(c, rng.rotation(), rng.vec(-1, 1));
    return c;
  });
}

std::vector<Case> degenerate(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    // Exactly collinear: p + k d with small integers k and dyadic p, d; or a
    // repeated vertex index, as in real CAD exports.
    auto flat = [&rng]() {
      const Vec3 p = rng.dyadic_vec(-1, 1), d = rng.dyadic_vec(-0.25, 0.25);
      switch (rng.integer(0, 2)) {
        case 0:
          return Triangle{{p, p + 2.0 * d, p + d}};
        case 1:
          return Triangle{{p, p + 3.0 * d, p + 3.0 * d}};
        default:
          return Triangle{{p - d, p + d, p + 4.0 * d}};
      }
    };
    c.a = flat();
    c.b = rng.coin() ? flat() : random_triangle(rng, rng.unit() * rng.uniform(0.0, 1.5), 1.0);
    if (rng.coin()) std::swap(c.a, c.b);
    return c;
  });
}

std::vector<Case> points(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    const Vec3 p = rng.vec(-1, 1);
    c.a = {{p, p, p}};
    if (rng.coin()) {
      const Vec3 q = rng.vec(-1, 1);
      c.b = {{q, q, q}};
    } else {
      c.b = random_triangle(rng, rng.vec(-0.5, 0.5), 1.0);
    }
    if (rng.coin()) std::swap(c.a, c.b);
    return c;
  });
}

std::vector<Case> scales(std::uint64_t seed, int count) {
  std::vector<Case> out = general(seed, count);
  Rng rng(seed ^ 0x5ca1eULL);
  for (Case& c : out) move(c, glm::dmat3(rng.log_uniform(-6.0, 6.0)), Vec3(0.0));
  return out;
}

std::vector<Case> far_from_origin(std::uint64_t seed, int count) {
  std::vector<Case> out = general(seed, count);
  Rng rng(seed ^ 0xfa7ULL);
  for (Case& c : out) move(c, glm::dmat3(1.0), rng.unit() * rng.log_uniform(0.0, 6.0));
  return out;
}

// Triangles 10^2..10^6 of their size apart: half parallel faces (a's plane
// z = 0 and b's at a power of two, then rotated, so parallel to rounding:
// the closest set is a region), half general pairs moved apart. The candidates' distances carry
// the rounding of coordinates that large, which must not break their ties.
std::vector<Case> far_apart(std::uint64_t seed, int count) {
  return make_cases(seed, count, [](Rng& rng) {
    Case c;
    if (rng.coin()) {
      const double h = std::ldexp(1.0, rng.integer(7, 20));
      c.a = around_origin_z0(rng);
      const double s = rng.dyadic(0.01, 0.08);
      c.b = {{Vec3(-s, -s, h), Vec3(s, -s, h), Vec3(0, s, h)}};
      c.known = Case::Known::Disjoint;
      // Face against face, once the planes' tilt by the rotation's rounding
      // (eps L across a) is within the rounding of the distances (eps D).
      c.known_features = true;
      move(c, rng.rotation(), rng.vec(-1, 1));
    } else {
      c.a = random_triangle(rng, Vec3(0.0), 1.0);
      c.b = random_triangle(rng, rng.unit() * rng.log_uniform(2.0, 6.0), 1.0);
      c.known = Case::Known::Disjoint;
    }
    return c;
  });
}

}  // namespace

const std::vector<Family>& families() {
  static const std::vector<Family> all = {
      {"general", "random triangles, separated or crossing", general, {8, 0, 1e-12}},
      {"near_parallel_edges",
       "closest edges at 1e-12..1e-3 rad, gap 1e-6..0.1",
       near_parallel_edges,
       {8, 0, 1e-12}},
      {"parallel_edges", "exactly parallel closest edges", parallel_edges, {8, 0, 1e-12}},
      {"near_parallel_faces", "faces at 1e-12..1e-3 rad, gap 1e-6..0.1", near_parallel_faces, {8, 0, 1e-12}},
      {"parallel_faces", "exactly parallel overlapping faces", parallel_faces, {8, 0, 1e-12}},
      {"coplanar_overlapping",
       "one plane, overlapping (z=0 and a tilted lattice plane)",
       coplanar_overlapping,
       {8, 0, 1e-12}},
      {"coplanar_disjoint", "one plane, apart by 2^-40..0.5", coplanar_disjoint, {8, 0, 1e-12}},
      {"touching_vertex", "a vertex of b on a vertex, edge or face of a", touching_vertex, {8, 0, 1e-12}},
      {"touching_edge", "an edge of b along an edge of a, or across a's face", touching_edge, {8, 0, 1e-12}},
      {"crossing", "both faces cross, intersection segment inside both", crossing, {8, 0, 1e-12}},
      {"piercing", "an edge of a small b through a large a", piercing, {8, 0, 1e-12}},
      {"slivers", "aspect ratio 1e-8..1, gaps 1e-7..1", slivers, {8, 0, 1e-9}},
      {"sliver_apex", "a vertex near a needle's tip or a cap's obtuse vertex (1e-8..1e-2 rad)", sliver_apex, {8, 0, 1e-9}},
      {"degenerate", "zero-area: collinear or repeated vertices", degenerate, {8, 0, 1e-12}},
      {"points", "all three vertices equal", points, {8, 0, 1e-12}},
      {"scales", "general, scaled by 1e-6..1e6", scales, {8, 0, 1e-12}},
      {"far_from_origin", "general, translated 1..1e6 sizes away", far_from_origin, {8, 8, 1e-12}},
      {"far_apart", "1e2..1e6 sizes apart: parallel faces, or general", far_apart, {8, 0, 1e-12}},
  };
  return all;
}

}  // namespace prox::stress
