#include "common/worker_pool.h"

namespace prox {

WorkerPool::WorkerPool(unsigned threads) {
  for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this] { work(); });
}

WorkerPool::~WorkerPool() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void WorkerPool::drain(const std::function<void(std::size_t)>* f, std::size_t n, std::uint64_t run) {
  for (;;) {
    std::size_t i;
    {
      // An index of this run only: once it is taken the run cannot end (nor
      // `f`, the caller's, go) before f(i) returns.
      const std::lock_guard<std::mutex> lock(mutex_);
      if (run_id_ != run || next_ >= n) return;
      i = next_++;
    }
    (*f)(i);
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (++finished_ == n) done_.notify_all();
    }
  }
}

void WorkerPool::run(std::size_t n, const std::function<void(std::size_t)>& f) {
  if (n == 0) return;
  if (workers_.empty()) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    job_ = &f;
    count_ = n;
    next_ = 0;
    finished_ = 0;
    ++run_id_;
  }
  std::uint64_t run;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    run = run_id_;
  }
  wake_.notify_all();
  drain(&f, n, run);
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [&] { return finished_ == n; });
  job_ = nullptr;
}

void WorkerPool::work() {
  std::uint64_t seen = 0;
  for (;;) {
    const std::function<void(std::size_t)>* job;
    std::size_t n;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || (job_ != nullptr && run_id_ != seen && next_ < count_); });
      if (stop_) return;
      seen = run_id_;
      job = job_;
      n = count_;
    }
    drain(job, n, seen);
  }
}

}  // namespace prox
