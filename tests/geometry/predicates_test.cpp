// Tests of the exact orientation predicates against exact integer references.
//
// Every input here has integer coordinates (possibly scaled by a power of two,
// which changes no sign and, without underflow or overflow, no rounding), so
// the exact determinant can be computed with integers: __int128 where it fits,
// and a small 256-bit integer for coordinates up to 2^61, where differences of
// doubles are no longer exact. The near-degenerate cases are built so that the
// plain double evaluation often gets the sign wrong, and the tests count those
// cases to prove that the exact path was needed and exercised.
#include "geometry/predicates.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

namespace prox::geometry {
namespace {

__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 UInt128;

int sign_of(Int128 v) { return (v > 0) - (v < 0); }
int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

// ---------------------------------------------------------------------------
// Exact references.

// A coordinate as an integer; the tests only pass integer-valued doubles
// below 2^62 in magnitude.
std::int64_t to_int(double x) {
  const auto i = static_cast<std::int64_t>(x);
  EXPECT_EQ(static_cast<double>(i), x) << "reference needs integer coordinates";
  return i;
}

Int128 exact_diff(double p, double q) { return Int128{to_int(p)} - to_int(q); }

// orient3d for integer coordinates with |x| < 2^40: the differences are below
// 2^41, so the determinant is below 3 * 2^124 and fits in __int128.
int reference_orient3d_i128(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Int128 ux = exact_diff(b.x, a.x), uy = exact_diff(b.y, a.y), uz = exact_diff(b.z, a.z);
  const Int128 vx = exact_diff(c.x, a.x), vy = exact_diff(c.y, a.y), vz = exact_diff(c.z, a.z);
  const Int128 wx = exact_diff(d.x, a.x), wy = exact_diff(d.y, a.y), wz = exact_diff(d.z, a.z);
  const Int128 nx = uy * vz - uz * vy;
  const Int128 ny = uz * vx - ux * vz;
  const Int128 nz = ux * vy - uy * vx;
  return sign_of(nx * wx + ny * wy + nz * wz);
}

// orient2d for integer coordinates with |x| < 2^61: differences below 2^62,
// products below 2^124, so the determinant fits in __int128.
int reference_orient2d_i128(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Int128 ux = exact_diff(b.x, a.x), uy = exact_diff(b.y, a.y);
  const Int128 vx = exact_diff(c.x, a.x), vy = exact_diff(c.y, a.y);
  return sign_of(ux * vy - uy * vx);
}

// Exactly zero cross product, for integer coordinates with |x| < 2^61.
bool reference_collinear3d_i128(const Vec3& a, const Vec3& b, const Vec3& c) {
  for (int axis = 0; axis < 3; ++axis) {
    if (reference_orient2d_i128(drop_axis(a, axis), drop_axis(b, axis), drop_axis(c, axis)) != 0)
      return false;
  }
  return true;
}

// A 256-bit two's complement integer: just enough for the orient3d
// determinant of integer coordinates below 2^61 (below 6 * 2^186).
struct Wide {
  std::array<std::uint32_t, 8> limb{};  // least significant first
};

Wide to_wide(Int128 v) {
  Wide w;
  const auto bits = static_cast<UInt128>(v);
  for (int i = 0; i < 4; ++i) w.limb[i] = static_cast<std::uint32_t>(bits >> (32 * i));
  for (int i = 4; i < 8; ++i) w.limb[i] = v < 0 ? 0xffffffffu : 0u;
  return w;
}

Wide operator+(const Wide& a, const Wide& b) {
  Wide r;
  std::uint64_t carry = 0;
  for (int i = 0; i < 8; ++i) {
    const std::uint64_t t = std::uint64_t{a.limb[i]} + b.limb[i] + carry;
    r.limb[i] = static_cast<std::uint32_t>(t);
    carry = t >> 32;
  }
  return r;
}

Wide operator-(const Wide& a) {
  Wide r;
  for (int i = 0; i < 8; ++i) r.limb[i] = ~a.limb[i];
  return r + to_wide(1);
}

Wide operator-(const Wide& a, const Wide& b) { return a + (-b); }

// Schoolbook product modulo 2^256, which is the exact signed product as long
// as that fits in 256 bits.
Wide operator*(const Wide& a, const Wide& b) {
  Wide r;
  for (int i = 0; i < 8; ++i) {
    std::uint64_t carry = 0;
    for (int j = 0; i + j < 8; ++j) {
      const std::uint64_t t = std::uint64_t{r.limb[i + j]} + std::uint64_t{a.limb[i]} * b.limb[j] + carry;
      r.limb[i + j] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
  }
  return r;
}

int sign_of(const Wide& w) {
  if (w.limb[7] >> 31) return -1;
  for (std::uint32_t limb : w.limb) {
    if (limb != 0) return 1;
  }
  return 0;
}

// orient3d for integer coordinates with |x| < 2^61.
int reference_orient3d_wide(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const auto diff = [](double p, double q) { return to_wide(exact_diff(p, q)); };
  const Wide ux = diff(b.x, a.x), uy = diff(b.y, a.y), uz = diff(b.z, a.z);
  const Wide vx = diff(c.x, a.x), vy = diff(c.y, a.y), vz = diff(c.z, a.z);
  const Wide wx = diff(d.x, a.x), wy = diff(d.y, a.y), wz = diff(d.z, a.z);
  const Wide nx = uy * vz - uz * vy;
  const Wide ny = uz * vx - ux * vz;
  const Wide nz = ux * vy - uy * vx;
  return sign_of(nx * wx + ny * wy + nz * wz);
}

// The plain double evaluation, written the way one naturally would. Only used
// to count how often it is wrong.
int naive_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  return sign_of(w.x * (u.y * v.z - u.z * v.y) + w.y * (u.z * v.x - u.x * v.z) +
                 w.z * (u.x * v.y - u.y * v.x));
}

int naive_orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 u = b - a, v = c - a;
  return sign_of(u.x * v.y - u.y * v.x);
}

// ---------------------------------------------------------------------------
// Generators.

struct Lattice3 {
  std::int64_t x, y, z;
};

Lattice3 operator+(const Lattice3& p, const Lattice3& q) { return {p.x + q.x, p.y + q.y, p.z + q.z}; }
Lattice3 operator*(std::int64_t k, const Lattice3& p) { return {k * p.x, k * p.y, k * p.z}; }

Vec3 to_vec3(const Lattice3& p) {
  return Vec3(static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z));
}

std::int64_t uniform_int(std::mt19937_64& rng, std::int64_t lo, std::int64_t hi) {
  return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
}

// Uniform integer point with |coordinate| < bound.
Lattice3 random_lattice(std::mt19937_64& rng, std::int64_t bound) {
  return {uniform_int(rng, -bound + 1, bound - 1), uniform_int(rng, -bound + 1, bound - 1),
          uniform_int(rng, -bound + 1, bound - 1)};
}

// An integer-valued double below 2^max_bits in magnitude with a random number
// of bits, so that coordinates of very different sizes meet and differences
// of doubles are often inexact.
double random_mixed_integer(std::mt19937_64& rng, int max_bits) {
  const int bits = static_cast<int>(uniform_int(rng, 0, max_bits));
  const std::uint64_t mantissa = rng() >> 11;  // 53 random bits
  const std::uint64_t magnitude = bits <= 53 ? mantissa >> (53 - bits) : mantissa << (bits - 53);
  const double value = static_cast<double>(magnitude);  // exact: at most 53 significant bits
  return (rng() & 1) != 0 ? -value : value;
}

Vec3 random_mixed_point(std::mt19937_64& rng, int max_bits) {
  return Vec3(random_mixed_integer(rng, max_bits), random_mixed_integer(rng, max_bits),
              random_mixed_integer(rng, max_bits));
}

// The double nearest to p + i * (q - p) + j * (r - p), computed exactly in
// integers first, so the only error is the final rounding.
double rounded_combination(double p, double q, double r, std::int64_t i, std::int64_t j) {
  const Int128 exact = Int128{to_int(p)} + i * exact_diff(q, p) + j * exact_diff(r, p);
  return static_cast<double>(exact);  // round to nearest
}

Vec3 scaled(const Vec3& p, int exponent) { return p * std::ldexp(1.0, exponent); }
Vec2 scaled(const Vec2& p, int exponent) { return p * std::ldexp(1.0, exponent); }

struct Case3 {
  Vec3 a, b, c, d;
};

// A sliver triangle a, b, c on integers below 2^40, d on the lattice plane
// through it, then moved by -1, 0 or +1 along one axis. With c - a = k (b - a)
// + e for a short e, the normal (b - a) x (c - a) is tiny compared with the
// products it is computed from, so the naive determinant has rounding errors
// far larger than the exact one (which is a component of the normal, or 0).
Case3 near_coplanar_lattice_case(std::mt19937_64& rng) {
  const Lattice3 a = random_lattice(rng, std::int64_t{1} << 36);
  const Lattice3 u = random_lattice(rng, std::int64_t{1} << 36);
  const std::int64_t k = std::array<std::int64_t, 4>{-2, -1, 1, 2}[uniform_int(rng, 0, 3)];
  const Lattice3 e = random_lattice(rng, std::int64_t{1} << uniform_int(rng, 0, 16));
  const Lattice3 v = k * u + e;
  Lattice3 d = a + uniform_int(rng, -2, 2) * u + uniform_int(rng, -2, 2) * v;
  const std::int64_t nudge = uniform_int(rng, -1, 1);
  switch (uniform_int(rng, 0, 2)) {
    case 0:
      d.x += nudge;
      break;
    case 1:
      d.y += nudge;
      break;
    default:
      d.z += nudge;
      break;
  }
  return {to_vec3(a), to_vec3(a + u), to_vec3(a + v), to_vec3(d)};
}

// Integer coordinates below 2^61 of mixed sizes; d (and sometimes c) is the
// rounded image of an exact lattice combination of the others, so it lies on
// or within a rounding error of the plane (line), and differences are inexact.
Case3 near_coplanar_mixed_case(std::mt19937_64& rng) {
  Case3 t;
  t.a = random_mixed_point(rng, 58);
  t.b = random_mixed_point(rng, 58);
  t.c = random_mixed_point(rng, 58);
  if (uniform_int(rng, 0, 1) == 0) {  // make a, b, c a sliver too
    const std::int64_t k = uniform_int(rng, -2, 2);
    t.c = Vec3(rounded_combination(t.a.x, t.b.x, t.b.x, k, 0), rounded_combination(t.a.y, t.b.y, t.b.y, k, 0),
               rounded_combination(t.a.z, t.b.z, t.b.z, k, 0));
    // |c| <= 5 * 2^58 < 2^61, so the next combination stays below 2^61 * 7.
    t.c = t.c * 0.125;
    t.c = Vec3(std::round(t.c.x), std::round(t.c.y), std::round(t.c.z));
  }
  const std::int64_t i = uniform_int(rng, -1, 2), j = uniform_int(rng, -1, 2);
  t.d = Vec3(rounded_combination(t.a.x, t.b.x, t.c.x, i, j), rounded_combination(t.a.y, t.b.y, t.c.y, i, j),
             rounded_combination(t.a.z, t.b.z, t.c.z, i, j));
  return t;
}

void report(const char* what, int naive_wrong, int total) {
  std::printf("[          ] %s: naive double sign wrong in %d of %d cases\n", what, naive_wrong, total);
}

// ---------------------------------------------------------------------------
// orient3d

TEST(Orient3dTest, SignConventionMatchesHeader) {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  EXPECT_EQ(orient3d(o, x, y, z), 1);  // (x - o) x (y - o) = +z points to d
  EXPECT_EQ(orient3d(o, x, y, -z), -1);
  EXPECT_EQ(orient3d(o, y, x, z), -1);
  EXPECT_EQ(orient3d(o, x, y, Vec3(5, -7, 0)), 0);
}

TEST(Orient3dTest, MatchesInt128ReferenceOnRandomLatticePoints) {
  std::mt19937_64 rng(0x5eed0001);
  const std::int64_t bound = std::int64_t{1} << 40;
  for (int n = 0; n < 2000; ++n) {
    const Vec3 a = to_vec3(random_lattice(rng, bound)), b = to_vec3(random_lattice(rng, bound));
    const Vec3 c = to_vec3(random_lattice(rng, bound)), d = to_vec3(random_lattice(rng, bound));
    const int expected = reference_orient3d_i128(a, b, c, d);
    // The 256-bit reference must agree wherever __int128 suffices.
    ASSERT_EQ(reference_orient3d_wide(a, b, c, d), expected);
    for (int exponent : {0, -60, 60}) {
      EXPECT_EQ(orient3d(scaled(a, exponent), scaled(b, exponent), scaled(c, exponent), scaled(d, exponent)),
                expected)
          << "case " << n << " scaled by 2^" << exponent;
    }
  }
}

TEST(Orient3dTest, MatchesInt128ReferenceOnNearCoplanarLatticePoints) {
  std::mt19937_64 rng(0x5eed0002);
  int naive_wrong = 0, zeros = 0, total = 0;
  for (int n = 0; n < 16000; ++n) {
    const Case3 t = near_coplanar_lattice_case(rng);
    const int expected = reference_orient3d_i128(t.a, t.b, t.c, t.d);
    ASSERT_EQ(reference_orient3d_wide(t.a, t.b, t.c, t.d), expected);
    zeros += expected == 0;
    for (int exponent : {0, -60, 60}) {
      const Vec3 a = scaled(t.a, exponent), b = scaled(t.b, exponent);
      const Vec3 c = scaled(t.c, exponent), d = scaled(t.d, exponent);
      EXPECT_EQ(orient3d(a, b, c, d), expected) << "case " << n << " scaled by 2^" << exponent;
      naive_wrong += naive_orient3d(a, b, c, d) != expected;
      ++total;
    }
  }
  report("orient3d near-coplanar lattice", naive_wrong, total);
  EXPECT_GT(naive_wrong, 0) << "the cases never needed the exact path";
  EXPECT_GT(zeros, 0);
}

TEST(Orient3dTest, MatchesWideReferenceWithInexactDifferences) {
  std::mt19937_64 rng(0x5eed0003);
  int naive_wrong = 0, zeros = 0, total = 0;
  for (int n = 0; n < 12000; ++n) {
    const Case3 t = near_coplanar_mixed_case(rng);
    const int expected = reference_orient3d_wide(t.a, t.b, t.c, t.d);
    zeros += expected == 0;
    // 2^-300 and 2^278 reach the documented limits of the exact range: all
    // coordinates multiples of 2^-300, and |x| < 2^339.
    for (int exponent : {0, -300, 278}) {
      const Vec3 a = scaled(t.a, exponent), b = scaled(t.b, exponent);
      const Vec3 c = scaled(t.c, exponent), d = scaled(t.d, exponent);
      EXPECT_EQ(orient3d(a, b, c, d), expected) << "case " << n << " scaled by 2^" << exponent;
      naive_wrong += naive_orient3d(a, b, c, d) != expected;
      ++total;
    }
  }
  report("orient3d mixed magnitudes", naive_wrong, total);
  EXPECT_GT(naive_wrong, 0) << "the cases never needed the exact path";
  EXPECT_GT(zeros, 0);
}

TEST(Orient3dTest, ExactZeroForCoplanarPointsFarFromOrigin) {
  std::mt19937_64 rng(0x5eed0004);
  const Lattice3 offset{std::int64_t{1} << 50, -(std::int64_t{3} << 49), std::int64_t{5} << 48};
  int naive_nonzero = 0;
  for (int n = 0; n < 2000; ++n) {
    const Lattice3 a = offset + random_lattice(rng, std::int64_t{1} << 30);
    const Lattice3 u = random_lattice(rng, std::int64_t{1} << 20);
    const Lattice3 v = random_lattice(rng, std::int64_t{1} << 20);
    const Lattice3 p = a + uniform_int(rng, -1000, 1000) * u + uniform_int(rng, -1000, 1000) * v;
    const Lattice3 q = a + uniform_int(rng, -1000, 1000) * u + uniform_int(rng, -1000, 1000) * v;
    const Lattice3 r = a + uniform_int(rng, -1000, 1000) * u + uniform_int(rng, -1000, 1000) * v;
    for (int exponent : {0, -80}) {
      const Vec3 pa = scaled(to_vec3(p), exponent), pb = scaled(to_vec3(q), exponent);
      const Vec3 pc = scaled(to_vec3(r), exponent), pd = scaled(to_vec3(a + u + v), exponent);
      EXPECT_EQ(orient3d(pa, pb, pc, pd), 0) << "case " << n;
      EXPECT_EQ(orient3d(pd, pc, pb, pa), 0) << "case " << n;
      naive_nonzero += naive_orient3d(pa, pb, pc, pd) != 0;
    }
  }
  report("orient3d coplanar far from origin", naive_nonzero, 4000);
}

TEST(Orient3dTest, ExactZeroForRepeatedAndCollinearPoints) {
  std::mt19937_64 rng(0x5eed0005);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random_point = [&] {
    // Arbitrary doubles of varied magnitude, not integers.
    const double s = std::ldexp(1.0, static_cast<int>(uniform_int(rng, -40, 60)));
    return Vec3(unit(rng) * s, unit(rng) * s, unit(rng) * s);
  };
  for (int n = 0; n < 1000; ++n) {
    const Vec3 a = random_point(), b = random_point(), c = random_point(), d = random_point();
    EXPECT_EQ(orient3d(a, a, c, d), 0);
    EXPECT_EQ(orient3d(a, b, a, d), 0);
    EXPECT_EQ(orient3d(a, b, c, a), 0);
    EXPECT_EQ(orient3d(a, b, b, d), 0);
    EXPECT_EQ(orient3d(a, b, c, b), 0);
    EXPECT_EQ(orient3d(a, b, c, c), 0);
    EXPECT_EQ(orient3d(a, a, a, a), 0);
  }
  // a, b, c exactly collinear far from the origin, d anywhere.
  const Lattice3 offset{std::int64_t{1} << 50, std::int64_t{1} << 50, -(std::int64_t{1} << 50)};
  for (int n = 0; n < 1000; ++n) {
    const Lattice3 a = offset + random_lattice(rng, std::int64_t{1} << 30);
    const Lattice3 u = random_lattice(rng, std::int64_t{1} << 24);
    const Vec3 d = random_point();
    const Vec3 pa = to_vec3(a), pb = to_vec3(a + uniform_int(rng, -50, 50) * u);
    const Vec3 pc = to_vec3(a + uniform_int(rng, -50, 50) * u);
    EXPECT_EQ(orient3d(pa, pb, pc, d), 0) << "case " << n;
    EXPECT_EQ(orient3d(d, pa, pb, pc), 0) << "case " << n;
  }
}

TEST(Orient3dTest, AntisymmetricUnderArgumentSwaps) {
  std::mt19937_64 rng(0x5eed0006);
  int nonzero = 0;
  for (int n = 0; n < 6000; ++n) {
    const Case3 t = (n % 2 == 0) ? near_coplanar_mixed_case(rng) : near_coplanar_lattice_case(rng);
    const Vec3 &a = t.a, &b = t.b, &c = t.c, &d = t.d;
    const int s = orient3d(a, b, c, d);
    nonzero += s != 0;
    // Each transposition flips the sign ...
    EXPECT_EQ(orient3d(b, a, c, d), -s) << "case " << n;
    EXPECT_EQ(orient3d(c, b, a, d), -s) << "case " << n;
    EXPECT_EQ(orient3d(d, b, c, a), -s) << "case " << n;
    EXPECT_EQ(orient3d(a, c, b, d), -s) << "case " << n;
    EXPECT_EQ(orient3d(a, d, c, b), -s) << "case " << n;
    EXPECT_EQ(orient3d(a, b, d, c), -s) << "case " << n;
    // ... and even permutations keep it.
    EXPECT_EQ(orient3d(b, c, a, d), s) << "case " << n;
    EXPECT_EQ(orient3d(b, a, d, c), s) << "case " << n;
    EXPECT_EQ(orient3d(d, c, b, a), s) << "case " << n;
  }
  EXPECT_GT(nonzero, 0);
}

// ---------------------------------------------------------------------------
// orient2d

// Near-collinear triples with integer coordinates below 2^61: c is the
// rounded image of an exact point of the line through a and b (or of an exact
// lattice point of a short-offset line), so it is on or next to the line.
struct Case2 {
  Vec2 a, b, c;
};

Case2 near_collinear_mixed_case(std::mt19937_64& rng) {
  Case2 t;
  t.a = Vec2(random_mixed_integer(rng, 58), random_mixed_integer(rng, 58));
  t.b = Vec2(random_mixed_integer(rng, 58), random_mixed_integer(rng, 58));
  const std::int64_t i = uniform_int(rng, -2, 3);
  t.c = Vec2(rounded_combination(t.a.x, t.b.x, t.b.x, i, 0), rounded_combination(t.a.y, t.b.y, t.b.y, i, 0));
  return t;
}

Case2 near_collinear_lattice_case(std::mt19937_64& rng) {
  const Lattice3 a = random_lattice(rng, std::int64_t{1} << 38);
  const Lattice3 u = random_lattice(rng, std::int64_t{1} << 37);
  Lattice3 c = a + uniform_int(rng, -2, 2) * u;
  c.x += uniform_int(rng, -1, 1);
  return {Vec2(to_vec3(a)), Vec2(to_vec3(a + u)), Vec2(to_vec3(c))};
}

TEST(Orient2dTest, SignConventionMatchesHeader) {
  EXPECT_EQ(orient2d(Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)), 1);  // counter-clockwise
  EXPECT_EQ(orient2d(Vec2(0, 0), Vec2(0, 1), Vec2(1, 0)), -1);
  EXPECT_EQ(orient2d(Vec2(0, 0), Vec2(1, 1), Vec2(3, 3)), 0);
}

TEST(Orient2dTest, MatchesInt128ReferenceOnRandomPoints) {
  std::mt19937_64 rng(0x5eed0101);
  for (int n = 0; n < 3000; ++n) {
    Vec2 a, b, c;
    if (n % 2 == 0) {
      const std::int64_t bound = std::int64_t{1} << 40;
      a = Vec2(to_vec3(random_lattice(rng, bound)));
      b = Vec2(to_vec3(random_lattice(rng, bound)));
      c = Vec2(to_vec3(random_lattice(rng, bound)));
    } else {
      a = Vec2(random_mixed_integer(rng, 60), random_mixed_integer(rng, 60));
      b = Vec2(random_mixed_integer(rng, 60), random_mixed_integer(rng, 60));
      c = Vec2(random_mixed_integer(rng, 60), random_mixed_integer(rng, 60));
    }
    const int expected = reference_orient2d_i128(a, b, c);
    for (int exponent : {0, -60, 60}) {
      EXPECT_EQ(orient2d(scaled(a, exponent), scaled(b, exponent), scaled(c, exponent)), expected)
          << "case " << n << " scaled by 2^" << exponent;
    }
  }
}

TEST(Orient2dTest, MatchesInt128ReferenceNearCollinear) {
  std::mt19937_64 rng(0x5eed0102);
  int naive_wrong = 0, zeros = 0, total = 0;
  for (int n = 0; n < 20000; ++n) {
    const Case2 t = (n % 2 == 0) ? near_collinear_mixed_case(rng) : near_collinear_lattice_case(rng);
    const int expected = reference_orient2d_i128(t.a, t.b, t.c);
    zeros += expected == 0;
    for (int exponent : {0, -60, 60}) {
      const Vec2 a = scaled(t.a, exponent), b = scaled(t.b, exponent), c = scaled(t.c, exponent);
      EXPECT_EQ(orient2d(a, b, c), expected) << "case " << n << " scaled by 2^" << exponent;
      naive_wrong += naive_orient2d(a, b, c) != expected;
      ++total;
    }
  }
  report("orient2d near-collinear", naive_wrong, total);
  EXPECT_GT(naive_wrong, 0) << "the cases never needed the exact path";
  EXPECT_GT(zeros, 0);
}

// The classic demonstration: a point on a 64 x 64 grid of adjacent doubles
// around (0.5, 0.5) against the line through (12, 12) and (24, 24). Scaled by
// 2^53 all coordinates are integers below 2^58.
TEST(Orient2dTest, MatchesInt128ReferenceOnGridOfAdjacentDoubles) {
  const Vec2 q(12.0, 12.0), r(24.0, 24.0);
  int naive_wrong = 0;
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const Vec2 p(0.5 + std::ldexp(i, -53), 0.5 + std::ldexp(j, -53));
      const int expected = reference_orient2d_i128(scaled(p, 53), scaled(q, 53), scaled(r, 53));
      EXPECT_EQ(orient2d(p, q, r), expected) << "i = " << i << ", j = " << j;
      EXPECT_EQ(orient2d(q, r, p), expected) << "i = " << i << ", j = " << j;
      EXPECT_EQ(orient2d(r, p, q), expected) << "i = " << i << ", j = " << j;
      naive_wrong += naive_orient2d(p, q, r) != expected;
    }
  }
  report("orient2d grid near (0.5, 0.5)", naive_wrong, 64 * 64);
  EXPECT_GT(naive_wrong, 0);
}

TEST(Orient2dTest, ExactZeroForCollinearAndRepeatedPoints) {
  std::mt19937_64 rng(0x5eed0103);
  const std::int64_t offset = std::int64_t{1} << 50;
  for (int n = 0; n < 2000; ++n) {
    const std::int64_t ax = offset + uniform_int(rng, -(1 << 30), 1 << 30);
    const std::int64_t ay = -offset + uniform_int(rng, -(1 << 30), 1 << 30);
    const std::int64_t ux = uniform_int(rng, -(1 << 24), 1 << 24);
    const std::int64_t uy = uniform_int(rng, -(1 << 24), 1 << 24);
    const auto point = [&](std::int64_t k) {
      return Vec2(static_cast<double>(ax + k * ux), static_cast<double>(ay + k * uy));
    };
    const Vec2 a = point(uniform_int(rng, -60, 60)), b = point(uniform_int(rng, -60, 60));
    const Vec2 c = point(uniform_int(rng, -60, 60));
    for (int exponent : {0, -100, 100}) {
      EXPECT_EQ(orient2d(scaled(a, exponent), scaled(b, exponent), scaled(c, exponent)), 0) << "case " << n;
    }
    const Vec2 p(random_mixed_integer(rng, 60) * 0x1p-30, random_mixed_integer(rng, 60) * 0x1p-30);
    EXPECT_EQ(orient2d(a, a, p), 0);
    EXPECT_EQ(orient2d(a, p, a), 0);
    EXPECT_EQ(orient2d(p, a, a), 0);
    EXPECT_EQ(orient2d(p, p, p), 0);
  }
}

TEST(Orient2dTest, AntisymmetricUnderArgumentSwaps) {
  std::mt19937_64 rng(0x5eed0104);
  int nonzero = 0;
  for (int n = 0; n < 10000; ++n) {
    const Case2 t = (n % 2 == 0) ? near_collinear_mixed_case(rng) : near_collinear_lattice_case(rng);
    const int s = orient2d(t.a, t.b, t.c);
    nonzero += s != 0;
    EXPECT_EQ(orient2d(t.b, t.a, t.c), -s) << "case " << n;
    EXPECT_EQ(orient2d(t.c, t.b, t.a), -s) << "case " << n;
    EXPECT_EQ(orient2d(t.a, t.c, t.b), -s) << "case " << n;
    EXPECT_EQ(orient2d(t.b, t.c, t.a), s) << "case " << n;
    EXPECT_EQ(orient2d(t.c, t.a, t.b), s) << "case " << n;
  }
  EXPECT_GT(nonzero, 0);
}

// ---------------------------------------------------------------------------
// collinear3d

TEST(Collinear3dTest, MatchesExactCrossProductReference) {
  std::mt19937_64 rng(0x5eed0201);
  int collinear = 0, not_collinear = 0, naive_wrong = 0;
  for (int n = 0; n < 10000; ++n) {
    Vec3 a, b, c;
    if (n % 2 == 0) {
      // Rounded points of the line through a and b, integers below 2^61.
      a = random_mixed_point(rng, 58);
      b = random_mixed_point(rng, 58);
      const std::int64_t i = uniform_int(rng, -2, 3);
      c = Vec3(rounded_combination(a.x, b.x, b.x, i, 0), rounded_combination(a.y, b.y, b.y, i, 0),
               rounded_combination(a.z, b.z, b.z, i, 0));
    } else {
      // Lattice points of a line, one of them moved by -1, 0 or +1 along an
      // axis. Sometimes the line is parallel to a coordinate plane, so that
      // only one component of the cross product becomes nonzero.
      const Lattice3 p = random_lattice(rng, std::int64_t{1} << 38);
      Lattice3 u = random_lattice(rng, std::int64_t{1} << 37);
      std::int64_t* const u_flat[] = {&u.x, &u.y, &u.z, nullptr};
      if (std::int64_t* flat = u_flat[uniform_int(rng, 0, 3)]) *flat = 0;
      Lattice3 q = p + uniform_int(rng, -2, 2) * u;
      std::int64_t* const q_moved[] = {&q.x, &q.y, &q.z};
      *q_moved[uniform_int(rng, 0, 2)] += uniform_int(rng, -1, 1);
      a = to_vec3(p);
      b = to_vec3(p + u);
      c = to_vec3(q);
    }
    const bool expected = reference_collinear3d_i128(a, b, c);
    (expected ? collinear : not_collinear) += 1;
    const Vec3 cross = glm::dvec3((b - a).y * (c - a).z - (b - a).z * (c - a).y,
                                  (b - a).z * (c - a).x - (b - a).x * (c - a).z,
                                  (b - a).x * (c - a).y - (b - a).y * (c - a).x);
    naive_wrong += (cross == Vec3(0.0)) != expected;
    for (int exponent : {0, -60, 60}) {
      const Vec3 sa = scaled(a, exponent), sb = scaled(b, exponent), sc = scaled(c, exponent);
      EXPECT_EQ(collinear3d(sa, sb, sc), expected) << "case " << n << " scaled by 2^" << exponent;
      EXPECT_EQ(collinear3d(sc, sa, sb), expected) << "case " << n << " scaled by 2^" << exponent;
    }
  }
  report("collinear3d", naive_wrong, 10000);
  EXPECT_GT(collinear, 0);
  EXPECT_GT(not_collinear, 0);
}

TEST(Collinear3dTest, TrueForCollinearAndCoincidentPointsFarFromOrigin) {
  std::mt19937_64 rng(0x5eed0202);
  const Lattice3 offset{std::int64_t{1} << 50, -(std::int64_t{1} << 50), std::int64_t{3} << 48};
  for (int n = 0; n < 1000; ++n) {
    const Lattice3 a = offset + random_lattice(rng, std::int64_t{1} << 30);
    const Lattice3 u = random_lattice(rng, std::int64_t{1} << 24);
    const Vec3 p = to_vec3(a + uniform_int(rng, -50, 50) * u);
    const Vec3 q = to_vec3(a + uniform_int(rng, -50, 50) * u);
    const Vec3 r = to_vec3(a + uniform_int(rng, -50, 50) * u);
    EXPECT_TRUE(collinear3d(p, q, r)) << "case " << n;
    EXPECT_TRUE(collinear3d(p, p, r)) << "case " << n;
    EXPECT_TRUE(collinear3d(p, p, p)) << "case " << n;
    // Moving one point by one unit along x, off a line that is not parallel
    // to x, breaks collinearity (unless the other two points coincide).
    if ((u.y != 0 || u.z != 0) && p != r) {
      EXPECT_FALSE(collinear3d(p, q + Vec3(1, 0, 0), r)) << "case " << n;
    }
  }
  EXPECT_TRUE(collinear3d(Vec3(0.1, 0.2, 0.3), Vec3(0.1, 0.2, 0.3), Vec3(-7e30, 1e-30, 3.0)));
  EXPECT_FALSE(collinear3d(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0x1p-60, 0)));
}

}  // namespace
}  // namespace prox::geometry
