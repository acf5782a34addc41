// The haptic loop's flight recorder (docs/haptic-fidelity.md): the last N
// ticks of a tool, written by the haptic thread into storage reserved before
// the threads start and read by any other thread while it runs. The writer
// never waits, allocates or makes a system call; a reader copies the newest
// samples and drops any the writer overwrote while it copied.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>

namespace prox::runtime {

// What a tick rendered (proxHapticSample's fields; poses as x y z and a
// quaternion w x y z).
struct TraceSample {
  std::uint64_t tick = 0;  // the tool's haptic ticks before this one
  double time = 0.0;       // s since the threads started
  double device[7] = {};   // the device's (or game's) pose this tick
  double proxy[7] = {};    // the pose the force was rendered against
  double force[3] = {}, torque[3] = {};
  double closest = 0.0;
  std::uint32_t contacts = 0;
  std::uint32_t flags = 0;  // TraceFlag
};

enum TraceFlag : std::uint32_t {
  kTraceClipped = 1u << 0,    // the safety gate changed the wrench (clip or rate limit)
  kTraceStale = 1u << 1,      // the contacts were older than the staleness limit
  kTraceUntrusted = 1u << 2,  // the tool was too far from where they were tracked
  kTraceFaded = 1u << 3,      // no contacts rendered: the gate faded towards zero
  kTraceNoPose = 1u << 4,     // the device gave no valid pose
  kTraceStopping = 1u << 5,   // the fade-out after a stop request
};

// One writer, any number of readers. Every word is an atomic, stored with
// release and loaded with acquire order (as SeqLock's), so a reader that
// sees any word of a newer sample also sees the state that announces its
// write: the copy is free of data races and checked, not trusted.
template <typename T>
class TraceRing {
  static_assert(std::is_trivially_copyable_v<T>, "TraceRing holds plain values");
  static constexpr std::size_t kWords = (sizeof(T) + 7) / 8;

 public:
  // Keeps the newest `capacity` samples. The ring has a margin of slots
  // beyond them, so that the writer can go on while a reader copies a full
  // ring (a slow reader, under a sanitizer say) without overwriting any of
  // the samples it copies.
  explicit TraceRing(std::size_t capacity) : TraceRing(capacity, std::max<std::size_t>(64, capacity / 8)) {}
  // With a margin of one's own: for tests (0 makes a reader's copy of a
  // full ring race the writer).
  TraceRing(std::size_t capacity, std::size_t margin)
      : capacity_(std::max<std::size_t>(capacity, 1)),
        slots_(capacity_ + margin),
        words_(new std::atomic<std::uint64_t>[slots_ * kWords]()) {}

  std::size_t capacity() const { return capacity_; }
  // Samples pushed so far.
  std::uint64_t written() const { return state_.load(std::memory_order_acquire) / 2; }

  // The writer's: never waits.
  void push(const T& value) {
    std::uint64_t words[kWords] = {};
    std::memcpy(words, &value, sizeof(T));
    const std::uint64_t s = state_.load(std::memory_order_relaxed);
    const std::uint64_t n = s / 2;
    state_.store(s + 1, std::memory_order_relaxed);  // odd: sample n under way
    std::atomic<std::uint64_t>* slot = &words_[(n % slots_) * kWords];
    for (std::size_t i = 0; i < kWords; ++i) slot[i].store(words[i], std::memory_order_release);
    state_.store(s + 2, std::memory_order_release);  // even: n + 1 samples whole
  }

  // Copies the newest samples, at most `max`, oldest first, into `out`;
  // returns how many. Samples the writer overwrote during the copy are left
  // out (only when the writer laps the margin during a copy).
  std::size_t copy_newest(T* out, std::size_t max) const {
    const std::uint64_t before = state_.load(std::memory_order_acquire) / 2;
    const std::uint64_t k = std::min<std::uint64_t>({max, capacity_, before});
    const std::uint64_t first = before - k;
    std::uint64_t words[kWords];
    for (std::uint64_t i = 0; i < k; ++i) {
      const std::atomic<std::uint64_t>* slot = &words_[((first + i) % slots_) * kWords];
      for (std::size_t w = 0; w < kWords; ++w) words[w] = slot[w].load(std::memory_order_acquire);
      std::memcpy(&out[i], words, sizeof(T));
    }
    // Any word of a later write read above makes this load see that write
    // begun (acquire on the word, release after the odd state): every
    // sample up to the one the newest begun write overwrites may be torn.
    const std::uint64_t after = state_.load(std::memory_order_acquire);
    const std::uint64_t begun = after / 2 + (after & 1);  // writes begun: whole or under way
    const std::uint64_t oldest_whole = begun > slots_ ? begun - slots_ : 0;
    if (first >= oldest_whole) return static_cast<std::size_t>(k);
    const std::uint64_t torn = std::min(k, oldest_whole - first);
    std::memmove(static_cast<void*>(out), out + torn, static_cast<std::size_t>(k - torn) * sizeof(T));
    return static_cast<std::size_t>(k - torn);
  }

 private:
  std::size_t capacity_;  // what readers get at most
  std::size_t slots_;     // capacity_ and the margin
  std::unique_ptr<std::atomic<std::uint64_t>[]> words_;
  // 2 n: n samples written, all whole; 2 n + 1: sample n is being written.
  std::atomic<std::uint64_t> state_{0};
};

}  // namespace prox::runtime
