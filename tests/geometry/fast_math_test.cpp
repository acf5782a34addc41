// geometry/fast_math.h against the C library calls it stands in for.
#include "geometry/fast_math.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace prox::geometry {
namespace {

// Within 1e-12 of the angle (and a rounding of pi), over ratios y / x from
// 1e-12 to 1e12 of either sign, x = 0, and every scale.
TEST(AngleFrom, IsAtan2ToAPartInATrillion) {
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> exponent(-12.0, 12.0), scale(-200.0, 200.0), unit(0.0, 1.0);
  for (int i = 0; i < 200000; ++i) {
    const double s = std::pow(10.0, scale(rng));
    const double y = s * (0.5 + unit(rng));
    double x = s * std::pow(10.0, exponent(rng)) * (unit(rng) < 0.5 ? -1.0 : 1.0);
    if (i % 1000 == 0) x = 0.0;
    const double want = std::atan2(y, x), got = angle_from(y, x);
    ASSERT_LE(std::abs(got - want), 1e-12 * want + 4.5e-16) << "y " << y << " x " << x;
  }
  EXPECT_EQ(angle_from(1.0, 0.0), 0.5 * kPi);
  EXPECT_EQ(angle_from(1.0, 1.0), 0.25 * kPi);
}

// Every exponent, subnormals and zero included, with random mantissas.
TEST(PowerOfTwoBelow, IsLdexpOfTheNegatedExponent) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  const auto expected = [](double m) { return std::ldexp(1.0, -std::max(std::ilogb(m), -1020)); };
  for (int e = -1074; e <= 1023; ++e)
    for (int k = 0; k < 8; ++k) {
      const double m = std::ldexp(k == 0 ? 1.0 : mantissa(rng), e);
      ASSERT_EQ(power_of_two_below(m), expected(m)) << "m " << m << " (exponent " << e << ")";
    }
  EXPECT_EQ(power_of_two_below(0.0), expected(0.0));
  EXPECT_EQ(power_of_two_below(std::numeric_limits<double>::max()), expected(std::numeric_limits<double>::max()));
  EXPECT_EQ(power_of_two_below(std::numeric_limits<double>::denorm_min()), 0x1p1020);
}

}  // namespace
}  // namespace prox::geometry
