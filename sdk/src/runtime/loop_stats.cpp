#include "runtime/loop_stats.h"

#include <algorithm>
#include <vector>

namespace prox::runtime {
namespace {

void raise_to(std::atomic<double>& max, double v) {
  double m = max.load(std::memory_order_relaxed);
  while (v > m && !max.compare_exchange_weak(m, v, std::memory_order_relaxed)) {
  }
}

double at(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0.0;
  return sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(p * double(sorted.size() - 1) + 0.5))];
}

}  // namespace

void LoopStats::reset(double target_rate) {
  target_rate_.store(target_rate, std::memory_order_relaxed);
  count_.store(0, std::memory_order_relaxed);
  overruns_.store(0, std::memory_order_relaxed);
  period_max_.store(0.0, std::memory_order_relaxed);
  update_max_.store(0.0, std::memory_order_relaxed);
  for (int i = 0; i < kWindow; ++i) {
    periods_[i].store(0.0, std::memory_order_relaxed);
    updates_[i].store(0.0, std::memory_order_relaxed);
  }
}

void LoopStats::record(double period, double update, bool overrun) {
  const std::uint64_t n = count_.load(std::memory_order_relaxed);
  const std::size_t slot = static_cast<std::size_t>(n % kWindow);
  // A period of 0 means "none yet" (the first iteration) and is left out.
  periods_[slot].store(period > 0.0 ? period : 0.0, std::memory_order_relaxed);
  updates_[slot].store(update, std::memory_order_relaxed);
  if (period > 0.0) raise_to(period_max_, period);
  raise_to(update_max_, update);
  if (overrun) overruns_.fetch_add(1, std::memory_order_relaxed);
  count_.store(n + 1, std::memory_order_release);
}

LoopSummary LoopStats::summary() const {
  LoopSummary s;
  s.target_rate = target_rate_.load(std::memory_order_relaxed);
  s.updates = count_.load(std::memory_order_acquire);
  s.overruns = overruns_.load(std::memory_order_relaxed);
  s.period_max = period_max_.load(std::memory_order_relaxed);
  s.update_max = update_max_.load(std::memory_order_relaxed);
  const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(s.updates, kWindow));
  std::vector<double> periods, updates;
  periods.reserve(n), updates.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double p = periods_[i].load(std::memory_order_relaxed);
    if (p > 0.0) periods.push_back(p);
    updates.push_back(updates_[i].load(std::memory_order_relaxed));
  }
  std::sort(periods.begin(), periods.end());
  std::sort(updates.begin(), updates.end());
  s.period_p50 = at(periods, 0.5), s.period_p99 = at(periods, 0.99), s.period_p999 = at(periods, 0.999);
  s.update_p50 = at(updates, 0.5), s.update_p99 = at(updates, 0.99);
  double total = 0.0;
  for (double p : periods) total += p;
  s.achieved_rate = total > 0.0 ? double(periods.size()) / total : 0.0;
  return s;
}

std::vector<double> LoopStats::periods() const {
  const std::uint64_t count = count_.load(std::memory_order_acquire);
  const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(count, kWindow));
  std::vector<double> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double p = periods_[i].load(std::memory_order_relaxed);
    if (p > 0.0) out.push_back(p);
  }
  return out;
}

}  // namespace prox::runtime
