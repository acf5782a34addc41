// What every part of proxima_bench shares: constants, the user's errors,
// timing, the statistics over poses and writing files.
#pragma once

#include "common/json_writer.h"

#include <chrono>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace prox::bench {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kPiValue = 3.14159265358979323846;

// A mistake in the command line or a missing input: printed without a trace.
struct UserError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Nearest-rank percentile of the finite values (NaN when there are none).
double percentile(std::vector<double> v, double p);
double median(std::vector<double> v);
double maximum(const std::vector<double>& v);  // of the finite values
double ratio(double a, double b);              // NaN unless both are finite and b > 0

using Json = JsonWriter;
void write_file(const std::string& path, const std::string& text);

// `v` formatted, "-" when it is not finite.
std::string fmt(double v, const char* format = "%.3f");

}  // namespace prox::bench
