// A higher-precision reference for the triangle kernel, for tests only.
//
// Quadruple precision (113-bit significand: __float128 on x86, long double
// where that is already IEEE quad), so every double input converts exactly and
// differences of doubles up to 2^60 apart stay exact. It deliberately uses
// other formulations than the kernel (Gram-matrix barycentrics, the normal
// equations, Cramer's rule for piercing), so a shared mistake is unlikely.
#pragma once

#include "geometry/types.h"

namespace prox::stress {

#if defined(__x86_64__) || defined(__i386__)
using Quad = __float128;
#else
using Quad = long double;
#endif

struct QVec3 {
  Quad x, y, z;
};

QVec3 to_quad(const Vec3& v);
Vec3 to_double(const QVec3& v);
Quad qsqrt(Quad x);
double to_double(Quad x);

struct ReferenceDistance {
  Quad distance;  // exact up to ~1e-33 relative
  QVec3 point_a;  // one closest pair (not canonical when it is not unique)
  QVec3 point_b;
  bool intersects;  // the closed triangles share a point (to ~1e-30 relative)
};

ReferenceDistance reference_distance(const Triangle& a, const Triangle& b);

// Distance from a point (given in quad) to a triangle, in quad.
Quad reference_point_triangle_distance(const QVec3& p, const Triangle& t);

}  // namespace prox::stress
