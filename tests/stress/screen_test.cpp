// The single-precision screen (geometry/triangle_screen.h) against the exact
// kernel without it: on every stress family, at limits below, at and above
// each pair's distance, the screened answers must be the unscreened ones bit
// for bit, and the screen's verdicts must hold against the quad-precision
// reference.
#include "stress/families.h"
#include "stress/quad_reference.h"

#include "geometry/triangle_distance.h"
#include "geometry/triangle_screen.h"

#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include <ostream>

namespace prox::stress {

void PrintTo(const Family& family, std::ostream* os);

namespace {

constexpr int kScreenCases = 2000;
constexpr std::uint64_t kScreenSeed = 20261206;

using geometry::TriangleDistance;
using Verdict = geometry::detail::Screen::Verdict;

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }
bool same_bits(const Vec3& x, const Vec3& y) {
  return same_bits(x.x, y.x) && same_bits(x.y, y.y) && same_bits(x.z, y.z);
}

// What differs between two answers, or "" when they are the same bits.
std::string difference(const TriangleDistance& x, const TriangleDistance& y) {
  if (x.intersects != y.intersects) return "verdict";
  if (!same_bits(x.distance, y.distance)) return "distance";
  if (!same_bits(x.point_a, y.point_a) || !same_bits(x.point_b, y.point_b)) return "points";
  if (x.feature_a != y.feature_a || x.feature_b != y.feature_b) return "features";
  return "";
}

// The screen's verdict on a pair, as triangle_distance asks for it.
geometry::detail::Screen screen_of(const Triangle& a, const Triangle& b, double limit) {
  const geometry::detail::LocalPair p = geometry::detail::local_pair(a, b);
  return geometry::detail::screen_pair(p.a, p.b, p.span, limit);
}

Verdict verdict_of(const Triangle& a, const Triangle& b, double limit) { return screen_of(a, b, limit).verdict; }

struct Tally {
  int pairs = 0, mismatches = 0, unsure = 0, near = 0, farther = 0, wrong_farther = 0, wrong_apart = 0;
  std::string first;

  void check(const Triangle& a, const Triangle& b) {
    ++pairs;
    const TriangleDistance exact = geometry::triangle_distance_unscreened(a, b);
    auto note = [&](const std::string& what) {
      ++mismatches;
      if (first.empty()) first = what;
    };
    if (const std::string d = difference(geometry::triangle_distance(a, b), exact); !d.empty())
      note("triangle_distance: " + d);
    // Limits just below, at and just above the distance, and well away.
    const double d = exact.distance;
    for (const double limit : {0.0, 0.5 * d, std::nextafter(d, 0.0), d, std::nextafter(d, INFINITY),
                               d * (1.0 + 1e-6), 2.0 * d + 1e-3, double{INFINITY}}) {
      TriangleDistance screened, unscreened;
      const bool in = geometry::triangle_distance_within(a, b, limit, screened);
      const bool in_exact = geometry::triangle_distance_within_unscreened(a, b, limit, unscreened);
      if (in != in_exact) {
        note("within: verdict at limit " + std::to_string(limit / d) + " d");
      } else if (in) {
        if (const std::string w = difference(screened, unscreened); !w.empty()) note("within: " + w);
      }
      if (!same_bits(geometry::triangle_distance_value(a, b, limit),
                     geometry::triangle_distance_value_unscreened(a, b, limit)))
        note("value at limit " + std::to_string(limit / d) + " d");
      const geometry::detail::Screen screen = screen_of(a, b, limit);
      if (screen.apart || screen.verdict == Verdict::Farther) {
        // Apart: they do not meet. Farther: if they do not meet, they are
        // past the limit. By the higher-precision reference.
        const ReferenceDistance ref = reference_distance(a, b);
        if (screen.apart && ref.intersects) ++wrong_apart;
        if (screen.verdict == Verdict::Farther && !ref.intersects && !(ref.distance > Quad(limit))) ++wrong_farther;
      }
      unsure += screen.verdict == Verdict::Unsure;
      near += screen.verdict == Verdict::Near;
      farther += screen.verdict == Verdict::Farther;
    }
  }
};

class ScreenFamily : public ::testing::TestWithParam<Family> {};

TEST_P(ScreenFamily, AnswersAreTheUnscreenedBitForBit) {
  const Family& family = GetParam();
  Tally tally;
  for (const Case& c : family.generate(kScreenSeed, kScreenCases)) {
    tally.check(c.a, c.b);
    tally.check(c.b, c.a);
  }
  EXPECT_EQ(tally.mismatches, 0) << "first: " << tally.first;
  EXPECT_EQ(tally.wrong_farther, 0);
  EXPECT_EQ(tally.wrong_apart, 0);
  RecordProperty("unsure", tally.unsure);
  RecordProperty("near", tally.near);
  RecordProperty("farther", tally.farther);
}

INSTANTIATE_TEST_SUITE_P(Families, ScreenFamily, ::testing::ValuesIn(families()),
                         [](const ::testing::TestParamInfo<Family>& p) { return std::string(p.param.name); });

// Random well-shaped pairs from touching to far apart, near the origin and
// far from it: here the screen must settle most pairs itself (else the
// comparison above says little), and still agree bit for bit.
TEST(Screen, SettlesMostRandomPairsAndAgreesBitForBit) {
  std::mt19937_64 rng(kScreenSeed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto point = [&] { return Vec3(unit(rng), unit(rng), unit(rng)); };
  Tally tally;
  for (int i = 0; i < 4000; ++i) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 40) - 20);
    const Vec3 where = (i % 4 == 0 ? 1e6 : 0.0) * point();
    const Vec3 apart = std::ldexp(1.0, static_cast<int>(rng() % 12) - 10) * point();
    Triangle a, b;
    for (int k = 0; k < 3; ++k) {
      a.v[k] = where + scale * point();
      b.v[k] = where + scale * (point() + Vec3(2.0, 0.0, 0.0) + apart);
    }
    tally.check(a, b);
  }
  EXPECT_EQ(tally.mismatches, 0) << "first: " << tally.first;
  EXPECT_EQ(tally.wrong_farther, 0);
  EXPECT_EQ(tally.wrong_apart, 0);
  const int verdicts = tally.unsure + tally.near + tally.farther;
  EXPECT_GT(tally.near, verdicts / 4) << "unsure " << tally.unsure << ", farther " << tally.farther;
  EXPECT_GT(tally.farther, verdicts / 10) << "unsure " << tally.unsure << ", near " << tally.near;
  EXPECT_LT(tally.unsure, verdicts / 2) << "near " << tally.near << ", farther " << tally.farther;
}

// Slivers are left to the exact kernel: their normals round too badly for
// the bound (an angle of 2e-4 here; a thin triangle of 2e-3 is screened
// with a larger bound).
TEST(Screen, LeavesSliversToTheExactKernel) {
  const Triangle sliver{{Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.5, 1e-4, 0.0)}};
  const Triangle other{{Vec3(0.0, 0.0, 1.0), Vec3(1.0, 0.0, 1.0), Vec3(0.0, 1.0, 1.0)}};
  EXPECT_EQ(verdict_of(sliver, other, INFINITY), Verdict::Unsure);
  EXPECT_EQ(verdict_of(other, sliver, INFINITY), Verdict::Unsure);
  const Triangle fat{{Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.5, 0.8, 0.0)}};
  EXPECT_EQ(verdict_of(fat, other, INFINITY), Verdict::Near);
  EXPECT_EQ(verdict_of(fat, other, 0.5), Verdict::Farther);
  const Triangle thin{{Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.5, 1e-3, 0.0)}};
  const geometry::detail::Screen screened = screen_of(thin, other, 0.5);
  EXPECT_EQ(screened.verdict, Verdict::Farther);
  EXPECT_GT(screened.error, screen_of(fat, other, 0.5).error * 10.0);
}

}  // namespace
}  // namespace prox::stress
