// Exact orientation predicates: a floating-point filter with a static forward
// error bound, backed by exact expansion arithmetic (Shewchuk 1997).
//
// Numerical assumptions:
//  * IEEE 754 binary64 with round-to-nearest, evaluated in double (no x87
//    excess precision), and no contraction of a*b+c into an fma: checked
//    below, and this file is compiled with -ffp-contract=off -fno-fast-math.
//    The error bounds below count exactly one rounding per written operation.
//  * Finite inputs, and no overflow or underflow below the smallest normal
//    double in the intermediate products. A sufficient condition for both
//    predicates: every coordinate has |x| <= 2^339 (products of three
//    differences then stay below 2^1020) and is an integer multiple of 2^-300
//    (true of 0 and of every double with |x| >= 2^-248; every intermediate
//    value is then a multiple of 2^-900, so either 0 or a normal number).
//    Inputs whose products underflow below the smallest normal double (tiny
//    coordinates, around 2^-300 and below) may lose exactness; that is
//    accepted. Overflow or NaN gives an unspecified sign.
#include "geometry/predicates.h"

#include <cassert>
#include <cfloat>
#include <cmath>
#include <limits>

static_assert(std::numeric_limits<double>::is_iec559, "the predicates need IEEE 754 doubles");
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD != 0
#error "the predicates need double expressions evaluated in double precision (FLT_EVAL_METHOD == 0)"
#endif

namespace prox::geometry {
namespace {

// Unit roundoff of double: |fl(x) - x| <= kEps * |fl(x)| and <= kEps * |x|
// for round-to-nearest in the normal range.
constexpr double kEps = 0x1p-53;

// ---------------------------------------------------------------------------
// Error-free transformations. Each returns a rounded result and the exact
// rounding error, so that value + error equals the real result exactly.

// a + b == sum + err exactly, for any finite a, b (Knuth's branch-free TwoSum:
// it recovers which parts of a and b the rounded sum actually absorbed).
inline void two_sum(double a, double b, double& sum, double& err) {
  sum = a + b;
  const double b_absorbed = sum - a;
  const double a_absorbed = sum - b_absorbed;
  err = (a - a_absorbed) + (b - b_absorbed);
}

// a * b == product + err exactly, unless err underflows. The fma computes
// a * b - product with a single rounding, and that difference is representable.
inline void two_product(double a, double b, double& product, double& err) {
  product = a * b;
  err = std::fma(a, b, -product);
}

// ---------------------------------------------------------------------------
// Expansions: a real number represented exactly as an unevaluated sum of
// doubles. Invariant: the terms are nonzero, ordered by increasing magnitude
// and nonoverlapping (the lowest set bit of each term is above the highest set
// bit of the previous one). Then the largest term alone carries the sign,
// because the others add up to less than its lowest set bit.
//
// The capacity N is a compile-time upper bound on the number of terms, so all
// storage is on the stack; the functions below return types whose capacity
// covers their worst case.
template <int N>
struct Expansion {
  double term[N] = {};
  int size = 0;

  // Adds one double exactly (Shewchuk's Grow-Expansion, Theorem 10): carry b
  // upwards through the terms, leaving each two_sum's rounding error behind.
  // The result keeps the invariant and grows by at most one term. Writing in
  // place is safe because at most one term is written per term read.
  void add(double b) {
    if (b == 0.0) return;
    assert(size < N);
    double carry = b;
    int kept = 0;
    for (int i = 0; i < size; ++i) {
      double sum = 0.0;
      double err = 0.0;
      two_sum(carry, term[i], sum, err);
      if (err != 0.0) term[kept++] = err;
      carry = sum;
    }
    if (carry != 0.0) term[kept++] = carry;
    size = kept;
  }

  // Adds every term of another expansion. Since only add() ever stores a term,
  // every expansion satisfies the invariant by construction.
  template <int M>
  void add_all(const Expansion<M>& e) {
    for (int i = 0; i < e.size; ++i) add(e.term[i]);
  }

  int sign() const {
    if (size == 0) return 0;
    return term[size - 1] > 0.0 ? 1 : -1;
  }
};

// The exact difference a - b as a two-term expansion. The rounded difference
// of two doubles is in general not exact, so the exact path cannot start from
// the filter's b - a.
inline Expansion<2> exact_difference(double a, double b) {
  double diff = 0.0;
  double err = 0.0;
  two_sum(a, -b, diff, err);
  Expansion<2> e;
  e.add(err);
  e.add(diff);
  return e;
}

template <int N, int M>
Expansion<N + M> sum(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<N + M> result;
  result.add_all(e);
  result.add_all(f);
  return result;
}

template <int N>
Expansion<N> negated(const Expansion<N>& e) {
  Expansion<N> result = e;  // negating every term keeps the invariant
  for (int i = 0; i < result.size; ++i) result.term[i] = -result.term[i];
  return result;
}

// e * b exactly: every term contributes its rounded product and its error.
template <int N>
Expansion<2 * N> scale(const Expansion<N>& e, double b) {
  Expansion<2 * N> result;
  for (int i = 0; i < e.size; ++i) {
    double product = 0.0;
    double err = 0.0;
    two_product(e.term[i], b, product, err);
    result.add(err);
    result.add(product);
  }
  return result;
}

// e * f exactly, by distributing over the terms of f.
template <int N, int M>
Expansion<2 * N * M> product(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<2 * N * M> result;
  for (int j = 0; j < f.size; ++j) result.add_all(scale(e, f.term[j]));
  return result;
}

// The 2x2 determinant u0 * v1 - u1 * v0, exactly.
template <int N>
Expansion<4 * N * N> exact_cross2(const Expansion<N>& u0, const Expansion<N>& u1, const Expansion<N>& v0,
                                  const Expansion<N>& v1) {
  return sum(product(u0, v1), negated(product(u1, v0)));
}

// ---------------------------------------------------------------------------
// Slow paths, reached only when the filter cannot certify the sign.

int orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Expansion<2> ux = exact_difference(b.x, a.x);
  const Expansion<2> uy = exact_difference(b.y, a.y);
  const Expansion<2> vx = exact_difference(c.x, a.x);
  const Expansion<2> vy = exact_difference(c.y, a.y);
  return exact_cross2(ux, uy, vx, vy).sign();
}

int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Expansion<2> ux = exact_difference(b.x, a.x);
  const Expansion<2> uy = exact_difference(b.y, a.y);
  const Expansion<2> uz = exact_difference(b.z, a.z);
  const Expansion<2> vx = exact_difference(c.x, a.x);
  const Expansion<2> vy = exact_difference(c.y, a.y);
  const Expansion<2> vz = exact_difference(c.z, a.z);
  const Expansion<2> wx = exact_difference(d.x, a.x);
  const Expansion<2> wy = exact_difference(d.y, a.y);
  const Expansion<2> wz = exact_difference(d.z, a.z);
  // (u x v) . w, one component of the cross product at a time.
  const Expansion<16> nx = exact_cross2(uy, uz, vy, vz);
  const Expansion<16> ny = exact_cross2(uz, ux, vz, vx);
  const Expansion<16> nz = exact_cross2(ux, uy, vx, vy);
  return sum(sum(product(nx, wx), product(ny, wy)), product(nz, wz)).sign();
}

// ---------------------------------------------------------------------------
// Filter bounds. The filter evaluates the determinant in doubles exactly as
// written in orient2d()/orient3d() and accepts its sign when
// |det| > coefficient * permanent, where the permanent is the same expression
// with every difference, product and minor replaced by its absolute value,
// also evaluated in doubles.
//
// Why that is sound: let s be the computed determinant before its last
// rounding (det = fl(s)). Rounding is monotonic and the bound B is a double,
// so |det| > B implies |s| > B; if B >= |s - exact|, then exact has the sign
// of s, hence of det. So the last operation never needs to be counted.
//
// orient2d: every monomial of the exact determinant passes through 3
// roundings before the last subtraction (two differences, one product), so
// |s - exact| <= (3 eps + 3 eps^2 + eps^3) * (|p1| + |p2|) for the computed
// products p1, p2. Expressing that through the rounded permanent (one more
// rounding) and allowing for the rounding of the bound itself (one more)
// needs a coefficient of about 3 eps + 9 eps^2; 3 eps + 16 eps^2 leaves margin.
constexpr double kOrient2dBound = (3.0 + 16.0 * kEps) * kEps;

// orient3d: every monomial passes through 7 roundings before the last
// addition (three differences, the product, the minor's subtraction, the
// product with the third difference, the first of the two additions). A
// direct count, in terms of the computed differences and products, gives
// |s - exact| <= (7 eps + 15 eps^2) * permanent_exact. The permanent's own 4
// roundings and the rounding of the bound raise the needed coefficient to
// about 7 eps + 50 eps^2; 7 eps + 64 eps^2 leaves margin.
constexpr double kOrient3dBound = (7.0 + 64.0 * kEps) * kEps;

inline int sign_of(double x) { return (x > 0.0) - (x < 0.0); }

}  // namespace

int orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double ux = b.x - a.x;
  const double uy = b.y - a.y;
  const double vx = c.x - a.x;
  const double vy = c.y - a.y;
  const double left = ux * vy;
  const double right = uy * vx;
  const double det = left - right;
  const double bound = kOrient2dBound * (std::fabs(left) + std::fabs(right));
  if (det > bound || -det > bound) return sign_of(det);
  return orient2d_exact(a, b, c);
}

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const double wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
  // The six products of the cross product n = u x v.
  const double uy_vz = uy * vz, uz_vy = uz * vy;
  const double uz_vx = uz * vx, ux_vz = ux * vz;
  const double ux_vy = ux * vy, uy_vx = uy * vx;
  const double det = (wx * (uy_vz - uz_vy) + wy * (uz_vx - ux_vz)) + wz * (ux_vy - uy_vx);
  const double permanent = (std::fabs(wx) * (std::fabs(uy_vz) + std::fabs(uz_vy)) +
                            std::fabs(wy) * (std::fabs(uz_vx) + std::fabs(ux_vz))) +
                           std::fabs(wz) * (std::fabs(ux_vy) + std::fabs(uy_vx));
  const double bound = kOrient3dBound * permanent;
  if (det > bound || -det > bound) return sign_of(det);
  return orient3d_exact(a, b, c, d);
}

bool collinear3d(const Vec3& a, const Vec3& b, const Vec3& c) {
  // Component `axis` of (b - a) x (c - a) is the 2D cross product of the
  // projection that drops that axis, so the cross product is exactly zero iff
  // all three projections are exactly collinear.
  for (int axis = 0; axis < 3; ++axis) {
    if (orient2d(drop_axis(a, axis), drop_axis(b, axis), drop_axis(c, axis)) != 0) return false;
  }
  return true;
}

}  // namespace prox::geometry
