// Lock-free handoffs between the runtime's threads (docs/threading.md).
//
// TripleBuffer: one writer, one reader, both wait-free. The writer fills its
// own buffer and swaps it with the "middle" one; the reader swaps the middle
// one with its own when something new is there. No copy, no lock, no wait:
// used for the contact snapshots the haptic loop reads and for the global
// search's results.
//
// SeqLock: one writer, any number of readers, for small trivially copyable
// values (a pose, a wrench). The writer never waits; a reader retries while a
// write is in progress. Its words are atomics, so it is also free of data
// races in the C++ memory model (and clean under ThreadSanitizer).
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace prox::runtime {

template <typename T>
class TripleBuffer {
 public:
  // The writer's buffer: fill it, then publish().
  T& back() { return buffers_[back_]; }

  // Makes the writer's buffer the newest; the writer gets the middle buffer
  // back (the one the reader did not take), to overwrite next time.
  void publish() {
    const std::uint32_t old = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel);
    back_ = old & kIndex;
  }

  // Takes the newest published buffer if there is one the reader has not
  // seen; true when front() changed.
  bool update() {
    if (!(middle_.load(std::memory_order_relaxed) & kFresh)) return false;
    const std::uint32_t old = middle_.exchange(front_, std::memory_order_acq_rel);
    front_ = old & kIndex;
    return true;
  }

  // Whether update() would take a newer buffer (the reader's question).
  bool fresh() const { return (middle_.load(std::memory_order_relaxed) & kFresh) != 0; }

  // The reader's buffer: the newest as of the last update().
  const T& front() const { return buffers_[front_]; }
  T& front_mutable() { return buffers_[front_]; }

  // For set-up before any thread runs: every buffer, e.g. to reserve memory.
  T& buffer(int i) { return buffers_[i]; }

 private:
  static constexpr std::uint32_t kFresh = 4, kIndex = 3;
  T buffers_[3]{};
  std::uint32_t back_ = 0;                // writer's own
  std::atomic<std::uint32_t> middle_{1};  // shared; kFresh when unread
  std::uint32_t front_ = 2;               // reader's own
};

template <typename T>
class SeqLock {
  static_assert(std::is_trivially_copyable_v<T>, "SeqLock holds plain values");
  static constexpr std::size_t kWords = (sizeof(T) + 7) / 8;

 public:
  SeqLock() { store(T{}); }
  explicit SeqLock(const T& value) { store(value); }

  // Single writer; never waits. The words are stored with release order, so
  // none can be seen before the odd sequence number that announces them.
  void store(const T& value) {
    std::uint64_t words[kWords] = {};
    std::memcpy(words, &value, sizeof(T));
    const std::uint64_t s = sequence_.load(std::memory_order_relaxed);
    sequence_.store(s + 1, std::memory_order_relaxed);  // odd: writing
    for (std::size_t i = 0; i < kWords; ++i) words_[i].store(words[i], std::memory_order_release);
    sequence_.store(s + 2, std::memory_order_release);  // even: done
  }

  // Any reader; retries while a write is under way (a handful of
  // nanoseconds). The words are loaded with acquire order, so reading any
  // word of a newer write makes the second sequence load see it too (no
  // standalone fences: ThreadSanitizer understands this form). Returns the
  // value and, in *version, how many stores made it.
  T load(std::uint64_t* version = nullptr) const {
    std::uint64_t words[kWords];
    for (;;) {
      const std::uint64_t s = sequence_.load(std::memory_order_acquire);
      if (s & 1) continue;
      for (std::size_t i = 0; i < kWords; ++i) words[i] = words_[i].load(std::memory_order_acquire);
      if (sequence_.load(std::memory_order_relaxed) != s) continue;
      if (version) *version = s / 2;
      T value;
      std::memcpy(&value, words, sizeof(T));
      return value;
    }
  }

 private:
  std::atomic<std::uint64_t> sequence_{0};
  std::atomic<std::uint64_t> words_[kWords]{};
};

}  // namespace prox::runtime
