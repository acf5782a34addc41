// Rigid-motion maths for the mock OpenXR runtime (double precision; the
// runtime hands out floats).
#pragma once

#include <openxr/openxr.h>

#include <cmath>

namespace prox::mock_xr {

struct Q {
  double w, x, y, z;
};
struct V {
  double x, y, z;
};
inline Q mul(const Q& a, const Q& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
inline Q conj(const Q& q) { return {q.w, -q.x, -q.y, -q.z}; }
inline V rotate(const Q& q, const V& v) {
  const Q r = mul(mul(q, {0, v.x, v.y, v.z}), conj(q));
  return {r.x, r.y, r.z};
}
struct Pose {
  Q q{1, 0, 0, 0};
  V p{0, 0, 0};
};
inline Pose of(const XrPosef& x) {
  return {{x.orientation.w, x.orientation.x, x.orientation.y, x.orientation.z},
          {x.position.x, x.position.y, x.position.z}};
}
inline XrPosef to_xr(const Pose& p) {
  XrPosef x;
  x.orientation = {float(p.q.x), float(p.q.y), float(p.q.z), float(p.q.w)};
  x.position = {float(p.p.x), float(p.p.y), float(p.p.z)};
  return x;
}
inline Pose compose(const Pose& a, const Pose& b) {  // a * b
  const V r = rotate(a.q, b.p);
  return {mul(a.q, b.q), {a.p.x + r.x, a.p.y + r.y, a.p.z + r.z}};
}
inline Pose inverse(const Pose& a) {
  const Q c = conj(a.q);
  const V r = rotate(c, a.p);
  return {c, {-r.x, -r.y, -r.z}};
}
inline Q slerp(Q a, Q b, double f) {
  double d = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
  if (d < 0) b = {-b.w, -b.x, -b.y, -b.z}, d = -d;
  if (d > 0.9999995)
    return {a.w + (b.w - a.w) * f, a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f, a.z + (b.z - a.z) * f};
  const double t = std::acos(d), s = std::sin(t), ka = std::sin((1 - f) * t) / s, kb = std::sin(f * t) / s;
  return {ka * a.w + kb * b.w, ka * a.x + kb * b.x, ka * a.y + kb * b.y, ka * a.z + kb * b.z};
}

}  // namespace prox::mock_xr
