// The triangle kernel's single-precision screen on arbitrary pairs: every
// answer of the screened kernel (triangle_distance, _within, _value) must be
// the unscreened one's, bit for bit, at limits below, at and above the
// distance. The first byte picks how the rest becomes two triangles:
// 0, raw doubles (NaN, infinities, denormals, huge); otherwise small
// integers on a grid (ties, parallel and coplanar pairs, shared vertices),
// scaled by a power of two and moved away from the origin.
#include "check.h"
#include "geometry/triangle_distance.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace {

using prox::Triangle;
using prox::geometry::TriangleDistance;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Equal bits, or both NaN (whose payloads may differ).
bool same(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0 || (std::isnan(x) && std::isnan(y)); }

bool same(const TriangleDistance& x, const TriangleDistance& y) {
  return x.intersects == y.intersects && same(x.distance, y.distance) && same(x.point_a.x, y.point_a.x) &&
         same(x.point_a.y, y.point_a.y) && same(x.point_a.z, y.point_a.z) && same(x.point_b.x, y.point_b.x) &&
         same(x.point_b.y, y.point_b.y) && same(x.point_b.z, y.point_b.z) && x.feature_a == y.feature_a &&
         x.feature_b == y.feature_b;
}

// The pair from the bytes after the first; missing bytes read as zero.
void read_pair(const std::uint8_t* data, std::size_t size, Triangle& a, Triangle& b) {
  double* out[18];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) out[3 * k + c] = &a.v[k][c], out[9 + 3 * k + c] = &b.v[k][c];
  const std::uint8_t mode = size > 0 ? data[0] : 0;
  ++data, size = size > 0 ? size - 1 : 0;
  auto byte = [&](std::size_t i) { return i < size ? data[i] : std::uint8_t{0}; };
  if (mode == 0) {
    for (int i = 0; i < 18; ++i) {
      std::uint8_t raw[8];
      for (int j = 0; j < 8; ++j) raw[j] = byte(8 * static_cast<std::size_t>(i) + static_cast<std::size_t>(j));
      std::memcpy(out[i], raw, 8);
    }
    return;
  }
  // A grid of 256 steps a side, a power of two from 2^-40 to 2^23 a step,
  // and an offset of up to 2^30 steps from the origin.
  const double step = std::ldexp(1.0, (mode % 64) - 40);
  const double offset = static_cast<double>(byte(18)) * std::ldexp(1.0, 22) * step;
  for (int i = 0; i < 18; ++i) *out[i] = offset + static_cast<double>(static_cast<std::int8_t>(byte(i))) * step;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Triangle a{}, b{};
  read_pair(data, size, a, b);
  const TriangleDistance exact = prox::geometry::triangle_distance_unscreened(a, b);
  PROX_FUZZ_CHECK(same(prox::geometry::triangle_distance(a, b), exact), "triangle_distance differs (%.17g)",
                  exact.distance);
  const double d = exact.distance;
  for (const double limit : {0.0, 0.5 * d, std::nextafter(d, 0.0), d, std::nextafter(d, kInf), 2.0 * d, kInf}) {
    TriangleDistance screened, unscreened;
    const bool in = prox::geometry::triangle_distance_within(a, b, limit, screened);
    const bool in_exact = prox::geometry::triangle_distance_within_unscreened(a, b, limit, unscreened);
    PROX_FUZZ_CHECK(in == in_exact, "within: %d against %d at limit %.17g", in, in_exact, limit);
    PROX_FUZZ_CHECK(!in || same(screened, unscreened), "within differs at limit %.17g", limit);
    const double value = prox::geometry::triangle_distance_value(a, b, limit);
    const double value_exact = prox::geometry::triangle_distance_value_unscreened(a, b, limit);
    PROX_FUZZ_CHECK(same(value, value_exact), "value %.17g against %.17g at limit %.17g", value, value_exact,
                    limit);
  }
  return 0;
}
