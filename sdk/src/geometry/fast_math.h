// Plain-arithmetic stand-ins for C library calls on the paths a deforming
// mesh runs every frame (Mesh::set_vertices: two angles and a scale a
// triangle): faster than the calls, and the same on every platform.
#pragma once

#include "geometry/types.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace prox::geometry {

// 2^-e for e the exponent of m (m = f 2^e, 1 <= f < 2), e at least -1020:
// ldexp(1, -max(ilogb(m), -1020)) exactly, from m's bits. m finite, >= 0.
inline double power_of_two_below(double m) {
  std::uint64_t bits;
  std::memcpy(&bits, &m, sizeof bits);
  const int e = std::max(static_cast<int>(bits >> 52) - 1023, -1020);  // a subnormal's field is 0
  if (e >= 1023) return 0x1p-1023;  // 2^-1023 is below the normal range: no exponent field for it
  const std::uint64_t out = static_cast<std::uint64_t>(1023 - e) << 52;
  double s;
  std::memcpy(&s, &out, sizeof s);
  return s;
}

// The angle whose sine and cosine are proportional to y and x, for y >= 0:
// atan2(y, x) in [0, pi], to about 1e-12 of itself.
inline double angle_from(double y, double x) {
  const double ax = std::abs(x);
  // Into [0, 1] (z = y / |x|, or |x| / y where y is the larger), then into
  // [-tan(pi/8), tan(pi/8)] by atan(z) = pi/4 + atan((z - 1) / (z + 1)):
  // one division either way, and selects of values rather than branches
  // (a mesh's corners fall either way at random).
  const bool steep = y > ax;
  const double big = std::max(y, ax), small = std::min(y, ax);
  const bool upper = small > 0.41421356237309503 * big;
  const double z = (upper ? small - big : small) / (upper ? small + big : big);
  // atan(z) / z as a polynomial in z^2, fitted on that interval (relative
  // error below 8e-13).
  const double t = z * z;
  const double p =
      0.99999999999925149 +
      t * (-0.33333333277288202 +
           t * (0.19999993087308823 +
                t * (-0.1428538772470061 +
                     t * (0.11103476284644917 +
                          t * (-0.089927176807782214 + t * (0.069748931464061595 + t * -0.037666645363594875))))));
  double a = (upper ? 0.25 * kPi : 0.0) + z * p;
  a = steep ? 0.5 * kPi - a : a;
  return x < 0.0 ? kPi - a : a;
}

}  // namespace prox::geometry
