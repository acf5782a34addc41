// A small pool of worker threads for the searches that split their work
// (docs/benchmarks.md, "On every core"): run(n, f) calls f(i) for every i in
// [0, n), on the workers and on the calling thread, and returns once all are
// done. One run at a time (the caller waits); never from the haptic thread
// (it locks and waits).
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace prox {

class WorkerPool {
 public:
  // `threads` working in all, the caller included: threads - 1 workers are
  // started (none for 0 or 1).
  explicit WorkerPool(unsigned threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // The threads that work on a run, the caller included.
  unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1; }
  void run(std::size_t n, const std::function<void(std::size_t)>& f);

 private:
  void work();
  // Takes indices of run `run` until none is left, calling f on each.
  void drain(const std::function<void(std::size_t)>* f, std::size_t n, std::uint64_t run);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(std::size_t)>* job_ = nullptr;
  std::size_t count_ = 0, next_ = 0, finished_ = 0;
  std::uint64_t run_id_ = 0;
  bool stop_ = false;
};

}  // namespace prox
