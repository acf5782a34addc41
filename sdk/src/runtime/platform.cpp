// Linux and other POSIX systems; Windows: platform_windows.cpp.
#include "runtime/platform.h"

#include <algorithm>
#include <cerrno>
#include <climits>

#if defined(__linux__)
#include <linux/futex.h>
#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>
#endif
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace prox::runtime::platform {

void default_cores(int cores[3]) {
  cores[0] = cores[1] = cores[2] = -1;
#if defined(__linux__)
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0 || CPU_COUNT(&set) < 4) return;
  int found = 0;
  for (int c = CPU_SETSIZE - 1; c >= 0 && found < 2; --c)
    if (CPU_ISSET(c, &set)) cores[found++] = c;  // haptic on the last allowed core, local on the one before
#endif
}

bool pin_current_thread(int core) {
#if defined(__linux__)
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(core, &set);
  return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
#else
  (void)core;
  return false;
#endif
}

int set_current_thread_realtime(int priority) {
#if defined(__linux__)
  sched_param param{};
  param.sched_priority = priority;
  return pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
#else
  (void)priority;
  return ENOSYS;
#endif
}

int lock_process_memory() {
#if defined(__linux__)
  return mlockall(MCL_CURRENT) == 0 ? 0 : errno;
#else
  return ENOSYS;
#endif
}

double thread_cpu_seconds(std::thread& thread) {
#if defined(__linux__)
  clockid_t clock;
  timespec ts{};
  if (!thread.joinable() || pthread_getcpuclockid(thread.native_handle(), &clock) != 0 ||
      clock_gettime(clock, &ts) != 0)
    return -1.0;
  return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
#else
  (void)thread;
  return -1.0;
#endif
}

void sleep_until(const std::atomic<int>& word, Clock::time_point deadline) {
#if defined(__linux__)
  // An absolute wait on CLOCK_MONOTONIC (steady_clock's), on the futex of
  // `word`, which wake_all() wakes.
  static_assert(sizeof(std::atomic<int>) == sizeof(int) && std::atomic<int>::is_always_lock_free);
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(deadline.time_since_epoch()).count();
  const timespec ts{static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)};
  int* futex = reinterpret_cast<int*>(const_cast<std::atomic<int>*>(&word));
  // 0: woken, or a spurious wake-up (wait again); ETIMEDOUT: the deadline;
  // EAGAIN: the word was already set; EINTR: a signal.
  while (word.load(std::memory_order_relaxed) == 0) {
    const long r = syscall(SYS_futex, futex, FUTEX_WAIT_BITSET_PRIVATE, 0, &ts, nullptr, FUTEX_BITSET_MATCH_ANY);
    if (r != 0 && errno != EINTR) break;
  }
#else
  // Without a futex a stop waits for the end of the current sleep, in
  // slices of a millisecond at most.
  while (word.load(std::memory_order_relaxed) == 0) {
    const auto now = Clock::now();
    if (now >= deadline) break;
    std::this_thread::sleep_until(std::min(deadline, now + std::chrono::milliseconds(1)));
  }
#endif
}

SleepTimer prepare_precise_waits() { return SleepTimer::System; }

void wake_all(std::atomic<int>& word) {
#if defined(__linux__)
  syscall(SYS_futex, reinterpret_cast<int*>(&word), FUTEX_WAKE_PRIVATE, INT_MAX, nullptr, nullptr, 0);
#else
  (void)word;
#endif
}

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

}  // namespace prox::runtime::platform
