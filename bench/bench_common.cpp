#include "bench_common.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace prox::bench {

double percentile(std::vector<double> v, double p) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * double(v.size() - 1) + 0.5))];
}
double median(std::vector<double> v) { return percentile(std::move(v), 0.5); }
double maximum(const std::vector<double>& v) {
  double m = kNaN;
  for (double x : v)
    if (std::isfinite(x) && !(x <= m)) m = x;
  return m;
}
double ratio(double a, double b) { return std::isfinite(a) && std::isfinite(b) && b > 0.0 ? a / b : kNaN; }

void write_file(const std::string& path, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw UserError(path + ": cannot write");
  std::fputs(text.c_str(), f);
  if (std::fclose(f) != 0) throw UserError(path + ": cannot write");
}

std::string fmt(double v, const char* format) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace prox::bench
