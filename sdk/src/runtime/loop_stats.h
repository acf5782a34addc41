// Per-thread timing statistics, written by the thread itself without a lock
// or an allocation and readable from any thread at any time.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

namespace prox::runtime {

struct LoopSummary {
  double target_rate = 0.0;    // Hz; 0: back to back
  double achieved_rate = 0.0;  // Hz, over the recorded window
  double period_p50 = 0.0, period_p99 = 0.0, period_p999 = 0.0, period_max = 0.0;  // s, start to start
  double update_p50 = 0.0, update_p99 = 0.0, update_max = 0.0;                     // s of work per iteration
  std::uint64_t updates = 0;
  std::uint64_t overruns = 0;  // iterations whose work outlasted the period
};

class LoopStats {
 public:
  // The window the percentiles are taken over: the last kWindow iterations.
  static constexpr int kWindow = 4096;

  void reset(double target_rate);
  // One iteration: the time since the previous one started, and its work.
  void record(double period, double update, bool overrun);
  // Any thread; allocates (it sorts a copy of the window).
  LoopSummary summary() const;
  // The recorded periods of the window, oldest slot first (for benchmarks).
  std::vector<double> periods() const;

 private:
  std::atomic<double> target_rate_{0.0};
  std::atomic<std::uint64_t> count_{0}, overruns_{0};
  std::atomic<double> period_max_{0.0}, update_max_{0.0};
  std::atomic<double> periods_[kWindow]{}, updates_[kWindow]{};
};

}  // namespace prox::runtime
