#include "geometry/triangle_screen.h"

#include "geometry/fast_math.h"

#include <algorithm>
#include <cmath>

namespace prox::geometry::detail {
namespace {

// Four lanes of single precision. GCC's and Clang's vector extension
// compiles to SSE on x86-64 and NEON on ARM; other compilers get the same
// arithmetic a lane at a time.
#if defined(__GNUC__)
using f4 = float __attribute__((vector_size(16)));
using m4 = decltype(f4{} < f4{});  // a lane mask: all bits set where true
inline f4 splat(float x) { return f4{x, x, x, x}; }
inline f4 pick(m4 mask, f4 yes, f4 no) { return mask ? yes : no; }
inline m4 both(m4 a, m4 b) { return a & b; }
inline m4 either(m4 a, m4 b) { return a | b; }
inline m4 flip(m4 a) { return ~a; }
#else
struct f4 {
  float l[4];
  float operator[](int i) const { return l[i]; }
};
struct m4 {
  bool l[4];
  bool operator[](int i) const { return l[i]; }
};
#define PROX_LANES(op)                                                     \
  inline f4 operator op(f4 a, f4 b) {                                      \
    return {{a.l[0] op b.l[0], a.l[1] op b.l[1], a.l[2] op b.l[2], a.l[3] op b.l[3]}}; \
  }
PROX_LANES(+)
PROX_LANES(-)
PROX_LANES(*)
PROX_LANES(/)
#undef PROX_LANES
#define PROX_COMPARE(op)                                                   \
  inline m4 operator op(f4 a, f4 b) {                                      \
    return {{a.l[0] op b.l[0], a.l[1] op b.l[1], a.l[2] op b.l[2], a.l[3] op b.l[3]}}; \
  }
PROX_COMPARE(<)
PROX_COMPARE(<=)
PROX_COMPARE(>=)
#undef PROX_COMPARE
inline f4 splat(float x) { return {{x, x, x, x}}; }
inline f4 pick(m4 m, f4 yes, f4 no) {
  return {{m.l[0] ? yes.l[0] : no.l[0], m.l[1] ? yes.l[1] : no.l[1], m.l[2] ? yes.l[2] : no.l[2],
           m.l[3] ? yes.l[3] : no.l[3]}};
}
inline m4 both(m4 a, m4 b) {
  return {{a.l[0] && b.l[0], a.l[1] && b.l[1], a.l[2] && b.l[2], a.l[3] && b.l[3]}};
}
inline m4 either(m4 a, m4 b) {
  return {{a.l[0] || b.l[0], a.l[1] || b.l[1], a.l[2] || b.l[2], a.l[3] || b.l[3]}};
}
inline m4 flip(m4 a) { return {{!a.l[0], !a.l[1], !a.l[2], !a.l[3]}}; }
#endif

inline f4 lane_min(f4 a, f4 b) { return pick(a < b, a, b); }
inline float lane_low(f4 a) { return std::min(std::min(a[0], a[1]), a[2]); }
inline float lane_high(f4 a) { return std::max(std::max(a[0], a[1]), a[2]); }
inline f4 clamp01(f4 t) { return pick(t < splat(0.0f), splat(0.0f), pick(splat(1.0f) < t, splat(1.0f), t)); }

// Three coordinates of four points (or one point in every lane).
struct P4 {
  f4 x, y, z;
};
inline P4 operator-(const P4& a, const P4& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline P4 operator+(const P4& a, const P4& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline P4 operator*(f4 s, const P4& a) { return {s * a.x, s * a.y, s * a.z}; }
inline f4 dot(const P4& a, const P4& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

struct F3 {
  float x, y, z;
};
inline F3 operator-(F3 a, F3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline float dot(F3 a, F3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline F3 cross(F3 a, F3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline P4 all(F3 p) { return {splat(p.x), splat(p.y), splat(p.z)}; }
// Three points as lanes, the fourth lane repeating the first.
inline P4 lanes(const F3 (&p)[3]) {
  return {f4{p[0].x, p[1].x, p[2].x, p[0].x}, f4{p[0].y, p[1].y, p[2].y, p[0].y},
          f4{p[0].z, p[1].z, p[2].z, p[0].z}};
}

// Sines of a triangle's angles below 2^-10, squared: slivers, left to the
// exact kernel. Above it the error bound grows as 1 / sine
// (docs/precision.md).
constexpr double kSliverSin2 = 1.0 / 1048576.0;

// Edges shorter than 2^-30 of the pair's span (squared, in the scaled
// units) are left to the exact kernel: its coordinates are rounded to
// 2^-53 of the span, no longer far below such an edge, so which of its
// candidates fall off an edge's end, and which tie, is its rounding's to
// decide, not something the screen's bound can foresee (a triangle 1e13
// across beside one 3.5e30 long, from the kernel fuzzer).
constexpr float kShortEdge2 = 0x1p-60f;

inline F3 to_float(const Vec3& v, double scale) {
  return {static_cast<float>(v.x * scale), static_cast<float>(v.y * scale), static_cast<float>(v.z * scale)};
}

// A triangle in single precision, scaled by the pair's power-of-two scale:
// what the screen's queries against it reuse (as the exact kernel's
// Prepared). The edges are taken in double and then rounded, so their
// directions are exact to float's rounding however small the triangle is
// against the pair's span.
struct Thin {
  F3 v[3], e[3], m[3], n;
  float ee[3], inv_ee[3], nn = 0.0f;
  double sin2 = 0.0;  // the least squared sine of its angles (of the two at the longest edge)

  Thin(const Triangle& t, double scale) {
    int longest = 0;
    for (int k = 0; k < 3; ++k) {
      v[k] = to_float(t.v[k], scale);
      e[k] = to_float(t.v[(k + 1) % 3] - t.v[k], scale);
      ee[k] = dot(e[k], e[k]);
      inv_ee[k] = ee[k] > 0.0f ? 1.0f / ee[k] : 0.0f;
      if (ee[k] > ee[longest]) longest = k;
    }
    const int next = (longest + 1) % 3, last = (longest + 2) % 3;
    n = cross(e[longest], e[next]);
    nn = dot(n, n);
    // |n|^2 = |e_l|^2 |e_k|^2 sin^2 for either edge k beside the longest;
    // the angle opposite the longest is the largest, its sine then at
    // least twice the smaller of these.
    const double l2 = static_cast<double>(ee[longest]);
    if (nn > 0.0f && std::isfinite(nn))
      sin2 = static_cast<double>(nn) / (l2 * static_cast<double>(std::max(ee[next], ee[last])));
    for (int k = 0; k < 3; ++k) m[k] = cross(n, e[k]);
  }
};

// Squared distances of the points p (lanes) to triangle t.
f4 point_triangle_d2(const P4& p, const Thin& t) {
  P4 d[3];
  for (int k = 0; k < 3; ++k) d[k] = p - all(t.v[k]);
  // Inside the prism over the face: on the inner side of all three edges.
  const m4 inside = both(both(dot(d[0], all(t.m[0])) >= splat(0.0f), dot(d[1], all(t.m[1])) >= splat(0.0f)),
                         dot(d[2], all(t.m[2])) >= splat(0.0f));
  const f4 h = dot(d[0], all(t.n));
  const f4 plane = h * h * splat(1.0f / t.nn);
  f4 edge = splat(INFINITY);
  for (int k = 0; k < 3; ++k) {
    const P4 e = all(t.e[k]);
    const f4 s = clamp01(dot(d[k], e) * splat(t.inv_ee[k]));
    const P4 w = d[k] - s * e;
    edge = lane_min(edge, dot(w, w));
  }
  return pick(inside, plane, edge);
}

// Edges closer to parallel than this (sin^2 of their angle) are solved as
// parallel, and their value not trusted (see `parallel` below).
constexpr float kParallelSin2 = 1.0f / 256.0f;

// The lines' critical point is off by at most this times |d| |e|^2 / denom
// (for s; |e| |d|^2 / denom for t) in the scaled units: the parameter's
// rounding, about eps |r| / (|d| sin^2), with |r| <= 4 and a margin.
constexpr float kParamError = 1.0f / 4096.0f;

struct EdgeLanes {
  f4 d2;         // the clamped segments' squared distance
  m4 parallel;   // too close to parallel for the bound: d2 is a pair of points on the
                 // segments (an upper bound) that may miss the closest
  m4 end;        // the lines' critical point is outside either segment by more than its
                 // rounding: the exact kernel adds no candidate for the pair
};

// a's edges (lanes: edge i from vertex i) against one edge of b, q0 + t e:
// the clamped closest points of two segments, by the normal equations.
EdgeLanes segment_segment(const P4& p0, const P4& d, f4 dd, f4 inv_dd, F3 q0, F3 e_, float ee) {
  EdgeLanes out;
  const P4 e = all(e_);
  const P4 r = p0 - all(q0);
  const f4 b = dot(d, e), c = dot(d, r), f = dot(e, r);
  const f4 big_e = splat(ee);
  const f4 denom = dd * big_e - b * b;
  out.parallel = denom <= splat(kParallelSin2) * dd * big_e;
  const f4 safe = pick(out.parallel, splat(1.0f), denom);
  // The critical point is s = ns / denom, t = nt / denom.
  const f4 ns = b * f - c * big_e, nt = dd * f - b * c;
  // Outside by more than the rounding: ns < -err_s or ns > denom + err_s,
  // err_s = kParamError |d| |e|^2 (squared: no root); the same for t.
  const f4 err_s2 = splat(kParamError * kParamError) * dd * big_e * big_e;
  const f4 err_t2 = splat(kParamError * kParamError) * big_e * dd * dd;
  const f4 below_s = splat(0.0f) - ns, above_s = ns - denom, below_t = splat(0.0f) - nt, above_t = nt - denom;
  auto beyond = [](f4 x, f4 err2) { return both(splat(0.0f) < x, err2 < x * x); };
  const m4 off_s = either(beyond(below_s, err_s2), beyond(above_s, err_s2));
  const m4 off_t = either(beyond(below_t, err_t2), beyond(above_t, err_t2));
  out.end = both(flip(out.parallel), either(off_s, off_t));
  f4 s = pick(out.parallel, splat(0.0f), clamp01(ns * (splat(1.0f) / safe)));
  const f4 t = clamp01((b * s + f) * splat(1.0f / ee));
  s = clamp01((b * t - c) * inv_dd);
  const P4 w = r + s * d - t * e;
  out.d2 = dot(w, w);
  return out;
}

// How near segment q0 + t e, t in [0, 1], comes to the line p0 + s d: no
// nearer than that to the segment on it. For parallel edges side by side,
// their distance; well conditioned however small the angle.
float segment_line_gap(F3 p0, F3 d, float dd, F3 q0, F3 e) {
  auto across = [&](F3 w) {  // w less its part along d
    const float k = dot(w, d) / dd;
    return F3{w.x - k * d.x, w.y - k * d.y, w.z - k * d.z};
  };
  const F3 u = across(q0 - p0), v = across(e);
  const float vv = dot(v, v);
  const float t = vv > 0.0f ? std::clamp(-dot(u, v) / vv, 0.0f, 1.0f) : 0.0f;
  const F3 w = {u.x + t * v.x, u.y + t * v.y, u.z + t * v.z};
  return std::sqrt(dot(w, w));
}

}  // namespace

Screen screen_pair(const Triangle& a, const Triangle& b, double span, double limit) {
  Screen out;
  // Scaled by 2^-e for span = m 2^e, m in [1, 2) (exactly), float's range
  // holds every product the screen forms, wherever the pair is. Spans
  // outside [2^-256, 2^256] are left to the exact kernel: there its own
  // predicates' products (cubes of coordinates) leave double's normal range,
  // and only it can give its own answer.
  if (!(span >= 0x1p-256 && span < 0x1p257)) return out;
  const double scale = power_of_two_below(span);
  const Thin ta(a, scale), tb(b, scale);
  const double sin2 = std::min(ta.sin2, tb.sin2);
  if (!(sin2 >= kSliverSin2)) return out;
  for (int k = 0; k < 3; ++k)
    if (!(ta.ee[k] >= kShortEdge2 && tb.ee[k] >= kShortEdge2)) return out;
  // The error bound in the scaled units (span is in [1, 2) of them):
  // kScreenError of the span, growing as 1 / sine below a sine of 1/16.
  const double error = 2.0 * kScreenError * std::max(1.0, 1.0 / (16.0 * std::sqrt(sin2)));
  out.error = error / scale;

  const P4 va = lanes(ta.v), vb = lanes(tb.v);

  // Separated along either normal by more than the error: the triangles do
  // not meet. (gap > error |n|, squared: no root.)
  for (int k = 0; k < 2 && !out.apart; ++k) {
    const Thin& t = k == 0 ? ta : tb;
    const f4 own = dot(k == 0 ? va : vb, all(t.n)), their = dot(k == 0 ? vb : va, all(t.n));
    const float gap = std::max(lane_low(their) - lane_high(own), lane_low(own) - lane_high(their));
    const auto g = static_cast<double>(gap);
    out.apart = gap > 0.0f && g * g > error * error * static_cast<double>(t.nn);
  }

  // The fifteen candidates, four lanes at a time.
  const f4 face_b = point_triangle_d2(va, tb), face_a = point_triangle_d2(vb, ta);
  const P4 ea = lanes(ta.e);
  const f4 ee_a = {ta.ee[0], ta.ee[1], ta.ee[2], ta.ee[0]};
  const f4 inv_ee_a = {ta.inv_ee[0], ta.inv_ee[1], ta.inv_ee[2], ta.inv_ee[0]};
  EdgeLanes edges[3];  // against b's edge j
  for (int j = 0; j < 3; ++j) edges[j] = segment_segment(va, ea, ee_a, inv_ee_a, tb.v[j], tb.e[j], tb.ee[j]);

  // If the triangles do not meet, their distance is the least candidate's.
  // Each candidate's distance lies within `error` of its value here, except
  // for nearly parallel edges, whose value may be too large: for those the
  // lower end is how near either edge comes to the other's line.
  f4 least4 = lane_min(face_a, face_b);
  for (const EdgeLanes& l : edges) least4 = lane_min(least4, l.d2);
  const double least = std::sqrt(static_cast<double>(lane_low(least4)));  // the fourth lane repeats the first
  double lower = least - error;  // no candidate is below this...
  float line_gap[9];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      if (!edges[j].parallel[i]) continue;
      line_gap[3 * i + j] = std::max(segment_line_gap(ta.v[i], ta.e[i], ta.ee[i], tb.v[j], tb.e[j]),
                                     segment_line_gap(tb.v[j], tb.e[j], tb.ee[j], ta.v[i], ta.e[i]));
      lower = std::min(lower, static_cast<double>(line_gap[3 * i + j]) - error);  // ...nor below this
    }
  if (lower > limit * scale) {
    out.verdict = Screen::Verdict::Farther;
    return out;
  }
  // The closest is at most least + error; a candidate can tie with it
  // only if its lower end is within the tie tolerance (far below `error`)
  // of that. An edge pair whose critical point is outside either edge adds
  // no candidate.
  const double reach = least + 3.0 * error;
  const auto reach2 = static_cast<float>(reach * reach);
  std::uint16_t near = 0;
  for (int l = 0; l < 3; ++l) {
    if (face_b[l] <= reach2) near |= static_cast<std::uint16_t>(1u << l);
    if (face_a[l] <= reach2) near |= static_cast<std::uint16_t>(1u << (3 + l));
  }
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const EdgeLanes& l = edges[j];
      const bool may_tie = l.parallel[i] ? static_cast<double>(line_gap[3 * i + j]) <= reach
                                         : !l.end[i] && l.d2[i] <= reach2;
      if (may_tie) near |= static_cast<std::uint16_t>(1u << (6 + 3 * i + j));
    }
  out.verdict = Screen::Verdict::Near;
  out.near = near;
  return out;
}

}  // namespace prox::geometry::detail
