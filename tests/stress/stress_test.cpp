// The numerical stress suite: every family, thousands of seeded cases, against
// the quad-precision reference, with the bounds of families.cpp asserted.
#include "stress/evaluate.h"

#include <gtest/gtest.h>

#include <ostream>

namespace prox::stress {

// gtest prints a failing parameter with this.
void PrintTo(const Family& family, std::ostream* os) { *os << family.name; }

namespace {

constexpr int kCasesPerFamily = 2000;
constexpr std::uint64_t kSeed = 20261123;

class StressFamily : public ::testing::TestWithParam<Family> {};

TEST_P(StressFamily, MeetsItsBounds) {
  const Family& family = GetParam();
  const FamilyStats s = evaluate_family(family, kSeed, kCasesPerFamily);
  std::string examples;
  for (const std::string& e : s.examples) examples += "\n  " + e;
  SCOPED_TRACE("first failures:" + examples);

  EXPECT_EQ(s.cases, kCasesPerFamily);
  EXPECT_EQ(s.nan_count, 0);
  EXPECT_EQ(s.bound_violations, 0) << "max error / bound = " << s.max_bound_ratio;
  EXPECT_EQ(s.verdict_mismatches, 0);
  EXPECT_EQ(s.feature_errors, 0);
  EXPECT_EQ(s.invariance_violations, 0) << "max spread / L = " << s.max_invariance_spread;
  EXPECT_EQ(s.intersection_invariance_violations, 0);
  // Random families may graze touching within the reference's rounding; that
  // must stay rare, or the family is not testing the verdict at all.
  EXPECT_LE(s.ambiguous_verdicts, s.cases / 100);

  // Reported points sit on their triangles and are the distance apart (bounds
  // per case, families.cpp).
  EXPECT_EQ(s.point_violations, 0) << "max off / L = " << s.max_point_error
                                   << ", max gap error / L = " << s.max_gap_error;
}

INSTANTIATE_TEST_SUITE_P(Families, StressFamily, ::testing::ValuesIn(families()),
                         [](const ::testing::TestParamInfo<Family>& param) {
                           return std::string(param.param.name);
                         });

}  // namespace
}  // namespace prox::stress
