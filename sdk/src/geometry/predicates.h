// Exact orientation predicates on double-precision input.
//
// Each returns the exact sign (-1, 0, +1) of a determinant of differences of
// its arguments, for every finite double input, with no rounding error: a fast
// floating-point evaluation with a forward error bound, and an exact expansion
// arithmetic fallback when the bound cannot certify the sign (the approach of
// Shewchuk's "Adaptive Precision Floating-Point Arithmetic and Fast Robust
// Geometric Predicates", 1997). These are the only places where the kernel
// makes a yes/no geometric decision that must be consistent.
#pragma once

#include "geometry/types.h"

namespace prox::geometry {

// sign( dot( cross(b - a, c - a), d - a ) ): +1 when d lies on the side of the
// plane through a, b, c that the normal (b - a) x (c - a) points to, -1 on the
// other side, 0 when the four points are coplanar (or a, b, c are collinear).
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// sign( cross(b - a, c - a) ) in the plane: +1 when a, b, c turn
// counter-clockwise, -1 clockwise, 0 when collinear.
int orient2d(const Vec2& a, const Vec2& b, const Vec2& c);

// Drops coordinate `axis` (0 = x, 1 = y, 2 = z) and keeps the other two in
// cyclic order, (y, z), (z, x) or (x, y), so that a counter-clockwise triangle
// seen from +axis stays counter-clockwise. Exact.
inline Vec2 drop_axis(const Vec3& p, int axis) {
  return axis == 0 ? Vec2(p.y, p.z) : axis == 1 ? Vec2(p.z, p.x) : Vec2(p.x, p.y);
}

// True when a, b, c are exactly collinear (including coincident points): the
// cross product (b - a) x (c - a) is exactly zero.
bool collinear3d(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace prox::geometry
