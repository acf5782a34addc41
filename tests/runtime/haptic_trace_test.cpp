// The flight recorder's ring (runtime/haptic_trace.h): what a reader copies
// is always a run of whole, consecutive samples, the newest ones, while the
// writer goes on; under ThreadSanitizer too (label threads).
#include "runtime/haptic_trace.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <thread>
#include <vector>

namespace prox::runtime {
namespace {

// Every word of sample n is a function of n, so a torn copy shows.
TraceSample sample(std::uint64_t n) {
  TraceSample s;
  s.tick = n;
  s.time = double(n) * 1e-3;
  for (int i = 0; i < 7; ++i) s.device[i] = double(n) + i, s.proxy[i] = -double(n) - i;
  for (int i = 0; i < 3; ++i) s.force[i] = double(n) * (i + 1), s.torque[i] = double(n) / (i + 1);
  s.closest = double(n) * 2.0;
  s.contacts = static_cast<std::uint32_t>(n * 3);
  s.flags = static_cast<std::uint32_t>(n & 63);
  return s;
}

bool whole(const TraceSample& s) {
  const TraceSample want = sample(s.tick);
  return std::memcmp(&s, &want, sizeof s) == 0;
}

TEST(HapticTrace, KeepsTheNewestSamplesOldestFirst) {
  TraceRing<TraceSample> ring(8, 0);
  std::vector<TraceSample> out(16);
  EXPECT_EQ(ring.copy_newest(out.data(), out.size()), 0u) << "nothing written yet";
  for (std::uint64_t n = 0; n < 5; ++n) ring.push(sample(n));
  ASSERT_EQ(ring.copy_newest(out.data(), out.size()), 5u);
  for (std::uint64_t i = 0; i < 5; ++i) EXPECT_TRUE(whole(out[i]) && out[i].tick == i) << i;
  for (std::uint64_t n = 5; n < 21; ++n) ring.push(sample(n));
  // 21 written into 8 slots: ticks 13 to 20.
  ASSERT_EQ(ring.copy_newest(out.data(), out.size()), 8u);
  for (std::uint64_t i = 0; i < 8; ++i) EXPECT_TRUE(whole(out[i]) && out[i].tick == 13 + i) << i;
  // Fewer asked for: the newest of them.
  ASSERT_EQ(ring.copy_newest(out.data(), 3), 3u);
  EXPECT_EQ(out[0].tick, 18u);
  EXPECT_EQ(out[2].tick, 20u);
  EXPECT_EQ(ring.written(), 21u);
}

// A writer that laps a small ring as fast as it can: the reader's copies may
// come up short, never torn, never out of order, never older than the ring.
// Without the margin (0), so that the writer does overwrite what is copied.
TEST(HapticTrace, AReaderBesideAFastWriterSeesOnlyWholeConsecutiveSamples) {
  for (const std::size_t capacity : {std::size_t{4}, std::size_t{64}, std::size_t{4096}}) {
    SCOPED_TRACE(capacity);
    TraceRing<TraceSample> ring(capacity, 0);
    std::atomic<bool> done{false};
    constexpr std::uint64_t kSamples = 200000;
    std::thread writer([&] {
      for (std::uint64_t n = 0; n < kSamples; ++n) ring.push(sample(n));
      done.store(true);
    });
    std::vector<TraceSample> out(capacity);
    std::uint64_t copies = 0, last_newest = 0;
    while (!done.load() || copies == 0) {
      const std::size_t k = ring.copy_newest(out.data(), out.size());
      ++copies;
      for (std::size_t i = 0; i < k; ++i) {
        ASSERT_TRUE(whole(out[i])) << "a torn sample at tick " << out[i].tick;
        if (i > 0) {
          ASSERT_EQ(out[i].tick, out[i - 1].tick + 1);
        }
      }
      if (k > 0) {
        ASSERT_GE(out[k - 1].tick, last_newest) << "the newest sample went back in time";
        last_newest = out[k - 1].tick;
      }
    }
    writer.join();
    // Once the writer is done every copy is full and ends at the last sample.
    ASSERT_EQ(ring.copy_newest(out.data(), out.size()), capacity);
    EXPECT_EQ(out[capacity - 1].tick, kSamples - 1);
    EXPECT_GT(copies, 0u);
  }
}

}  // namespace
}  // namespace prox::runtime
