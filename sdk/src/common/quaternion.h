// Normalising a quaternion given by a user (poses in files and in the C API).
#pragma once

#include <algorithm>
#include <cmath>

namespace prox {

// Scales q (w, x, y, z) to unit length in place; false (q unchanged) when a
// component is not finite or the length is at most 1e-12 (a zero
// quaternion). Divides by the largest component first, so components as
// large as 1e300 do not overflow the sum of squares (which would make every
// component 0 after the division).
inline bool normalize_quaternion(double q[4]) {
  double largest = 0.0;
  for (int i = 0; i < 4; ++i) {
    if (!std::isfinite(q[i])) return false;
    largest = std::max(largest, std::abs(q[i]));
  }
  if (!(largest > 0.0)) return false;
  double scaled[4];
  double sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    scaled[i] = q[i] / largest;
    sum += scaled[i] * scaled[i];
  }
  const double root = std::sqrt(sum);  // in [1, 2]
  if (!(largest * root > 1e-12)) return false;
  for (int i = 0; i < 4; ++i) q[i] = scaled[i] / root;
  return true;
}

}  // namespace prox
