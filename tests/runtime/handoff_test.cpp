// The lock-free handoffs and the loop statistics, with real threads: a reader
// must never see a value half written, nor an older value after a newer one.
#include "runtime/handoff.h"
#include "runtime/loop_stats.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <thread>
#include <vector>

namespace prox::runtime {
namespace {

// Every word equal to the sequence number: a torn read shows as a mismatch.
struct Block {
  std::uint64_t sequence = 0;
  std::array<std::uint64_t, 61> words{};
};

bool consistent(const Block& b) {
  return std::all_of(b.words.begin(), b.words.end(), [&](std::uint64_t w) { return w == b.sequence; });
}

TEST(TripleBuffer, ReaderSeesWholeValuesInOrder) {
  TripleBuffer<Block> buffer;
  // The writer keeps going until the reader has taken many values while it
  // writes, so that the two really overlap.
  constexpr std::uint64_t kWrites = 200000, kReads = 2000;
  std::atomic<bool> done{false};
  std::atomic<std::uint64_t> reads{0};
  std::uint64_t written = 0;
  std::thread writer([&] {
    for (std::uint64_t s = 1; s <= kWrites || reads.load() < kReads; ++s) {
      Block& b = buffer.back();
      b.sequence = s;
      b.words.fill(s);
      buffer.publish();
      written = s;
    }
    done.store(true);
  });
  std::uint64_t last = 0, torn = 0, backwards = 0;
  for (;;) {
    const bool finished = done.load();  // then one last update sees the last publish
    if (buffer.update()) {
      const Block& b = buffer.front();
      torn += !consistent(b);
      backwards += b.sequence <= last;
      last = b.sequence;
      reads.fetch_add(1);
    }
    if (finished) break;
  }
  writer.join();
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(backwards, 0u);
  EXPECT_EQ(buffer.front().sequence, written) << "the reader ends on the newest value";
  EXPECT_GE(reads.load(), kReads);
}

TEST(TripleBuffer, UpdateIsFalseWithoutAPublish) {
  TripleBuffer<int> buffer;
  EXPECT_FALSE(buffer.update());
  buffer.back() = 7;
  buffer.publish();
  EXPECT_TRUE(buffer.update());
  EXPECT_EQ(buffer.front(), 7);
  EXPECT_FALSE(buffer.update());
  EXPECT_EQ(buffer.front(), 7);
  // Two publishes before a read: the reader gets the newer.
  buffer.back() = 8;
  buffer.publish();
  buffer.back() = 9;
  buffer.publish();
  EXPECT_TRUE(buffer.update());
  EXPECT_EQ(buffer.front(), 9);
}

struct Triple {
  double a, b, c;  // b == 2a, c == 3a
};

TEST(SeqLock, ReadersSeeWholeValuesInOrder) {
  SeqLock<Triple> lock(Triple{0.0, 0.0, 0.0});
  constexpr int kWrites = 200000;
  constexpr std::uint64_t kReads = 2000;
  std::atomic<bool> done{false};
  std::atomic<std::uint64_t> torn{0}, backwards{0}, reads{0};
  auto reader = [&] {
    double last = -1.0;
    std::uint64_t last_version = 0;
    while (!done.load()) {
      reads.fetch_add(1);
      std::uint64_t version = 0;
      const Triple t = lock.load(&version);
      if (t.b != 2.0 * t.a || t.c != 3.0 * t.a) torn.fetch_add(1);
      if (t.a < last || version < last_version) backwards.fetch_add(1);
      last = t.a, last_version = version;
    }
  };
  std::thread r1(reader), r2(reader);
  int i = 1;
  for (; i <= kWrites || reads.load() < 2 * kReads; ++i) lock.store({double(i), 2.0 * i, 3.0 * i});
  done.store(true);
  r1.join();
  r2.join();
  EXPECT_EQ(torn.load(), 0u);
  EXPECT_EQ(backwards.load(), 0u);
  std::uint64_t version = 0;
  EXPECT_EQ(lock.load(&version).a, double(i - 1));
  EXPECT_EQ(version, std::uint64_t(i - 1) + 1) << "one store per write, plus the constructor's";
}

TEST(LoopStats, PercentilesOfKnownPeriods) {
  LoopStats stats;
  stats.reset(1000.0);
  // Periods 1..100 ms (in a shuffled order), work a tenth of each; the
  // first iteration has no period.
  std::vector<double> periods;
  for (int i = 1; i <= 100; ++i) periods.push_back(i * 1e-3);
  std::reverse(periods.begin(), periods.end());
  stats.record(0.0, 0.5e-3, false);
  for (double p : periods) stats.record(p, p / 10.0, p > 0.095);
  const LoopSummary s = stats.summary();
  EXPECT_EQ(s.updates, 101u);
  EXPECT_EQ(s.overruns, 5u);
  EXPECT_DOUBLE_EQ(s.period_max, 0.1);
  EXPECT_NEAR(s.period_p50, 0.050, 0.0011);
  EXPECT_NEAR(s.period_p99, 0.099, 0.0011);
  EXPECT_DOUBLE_EQ(s.update_max, 0.01);
  EXPECT_NEAR(s.achieved_rate, 100.0 / 5.05, 1e-9);  // 100 periods summing to 5.05 s
  EXPECT_EQ(s.target_rate, 1000.0);
}

TEST(LoopStats, WindowKeepsTheLatest) {
  LoopStats stats;
  stats.reset(0.0);
  for (int i = 0; i < LoopStats::kWindow; ++i) stats.record(1.0, 1.0, false);
  for (int i = 0; i < LoopStats::kWindow; ++i) stats.record(0.001, 0.0005, false);
  const LoopSummary s = stats.summary();
  EXPECT_DOUBLE_EQ(s.period_p99, 0.001);
  EXPECT_DOUBLE_EQ(s.period_max, 1.0) << "the maximum is over the whole run";
}

}  // namespace
}  // namespace prox::runtime
