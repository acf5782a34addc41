// A first look at a triangle pair in single precision, four candidates at a
// time: which of the exact kernel's candidates can be the closest, or that
// the pair is past a limit, decided with an error bound (docs/precision.md,
// "The single-precision screen"). The exact kernel then computes only what
// the screen could not rule out, in double precision, with the same
// arithmetic as before, so its answers stay what they were bit for bit.
#pragma once

#include "geometry/types.h"

#include <cstdint>

namespace prox::geometry::detail {

// The exact kernel's fifteen candidates, numbered as the screen's bits:
// 0..2   vertex i of a against b's face,
// 3..5   vertex i of b against a's face,
// 6 + 3 i + j   edge i of a against edge j of b.

// The screen's error bound, as a fraction of the pair's span (the largest
// distance of a vertex from the pair's local origin): every candidate's
// single-precision distance is within this of its double-precision value
// (2^-12, about 4,000 times float's rounding) for triangles whose angles
// all have a sine of at least 1/16, and this times 1 / (16 sine) for
// thinner ones down to a sine of 2^-10. docs/precision.md derives it and
// the stress suite measures it.
inline constexpr double kScreenError = 1.0 / 4096.0;

struct Screen {
  enum class Verdict : std::uint8_t {
    Unsure,   // a sliver, or a span out of range: the exact kernel decides
    Farther,  // if the triangles do not meet, they are farther apart than the limit
    Near,     // if the triangles do not meet, only the candidates in `near` can tie with the closest
  };
  Verdict verdict = Verdict::Unsure;
  // The triangles are separated along a normal by more than the error: they
  // do not meet. Otherwise the verdict holds once an exact test says so.
  bool apart = false;
  std::uint16_t near = 0;  // bit k: candidate k (numbered as above) may be within the tie tolerance
  double error = 0.0;      // the bound this pair's verdict used, in the input's units
};

// `a`, `b`: the pair in local coordinates (triangle_distance's, the middle
// of their bounding box at the origin), neither degenerate; `span`: the
// largest distance of their vertices from that origin; `limit`: a distance
// past which the caller only needs to know that the pair is past it
// (infinity for every pair).
Screen screen_pair(const Triangle& a, const Triangle& b, double span, double limit);

// A pair as triangle_distance hands it to the screen, for tests and
// benchmarks that call screen_pair themselves: translated by the middle of
// the pair's bounding box, with its span (triangle_distance.cpp's arithmetic).
struct LocalPair {
  Triangle a, b;
  double span = 0.0;
};
LocalPair local_pair(const Triangle& a, const Triangle& b);

}  // namespace prox::geometry::detail
