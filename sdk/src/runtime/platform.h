// The operating system beneath the runtime's threads: pinning, real-time
// priority, memory locking, a thread's CPU clock, and the absolute-deadline
// sleep that a stop request can cut short. Everything here is per platform
// (platform.cpp: Linux, and the standard library where it can on other POSIX
// systems, ENOSYS where it cannot; platform_windows.cpp: Windows), so
// threads.cpp holds no system call.
#pragma once

#include <atomic>
#include <chrono>
#include <thread>

namespace prox::runtime::platform {

using Clock = std::chrono::steady_clock;

// Cores for the haptic and local threads on a machine with at least four
// the process may use: the last two, one each, and -1 (not pinned) for the
// third; -1 for all three below that.
void default_cores(int cores[3]);

// Pins the calling thread to `core`; false when refused.
bool pin_current_thread(int core);

// Asks SCHED_FIFO at `priority` (1-99) for the calling thread (Windows:
// THREAD_PRIORITY_TIME_CRITICAL, and MMCSS's "Pro Audio" task where the
// service runs): 0 when granted, else the errno that refused it (ENOSYS
// where there is none).
int set_current_thread_realtime(int priority);

// mlockall(MCL_CURRENT) (Windows: VirtualLock on every committed region,
// the working set grown to hold them): 0 when locked, else the errno that
// refused it.
int lock_process_memory();

// CPU seconds `thread` has used so far; -1 when the system cannot tell.
double thread_cpu_seconds(std::thread& thread);

// Sleeps until `deadline` on Clock, or until wake_all(word) is called while
// `word` is non-zero; returns at once if it already is. A late wake-up or a
// signal does not make the caller drift: the deadline is absolute.
void sleep_until(const std::atomic<int>& word, Clock::time_point deadline);

// How sleep_until waits on this system (proxSleepTimer's values).
enum class SleepTimer {
  System = 0,          // the system's own (Linux: a futex wait on the monotonic clock's hrtimers)
  HighResolution = 1,  // Windows 10 1803+: a high-resolution waitable timer
  Period1ms = 2,       // older Windows: a waitable timer, with timeBeginPeriod(1) while the thread lives
};

// Makes the calling thread's precise wait ready (Windows: its waitable
// timer, or timeBeginPeriod(1) until the thread ends where there is no
// high-resolution timer) and says which it is. sleep_until does it on its
// first wait; a thread calls it up front to know.
SleepTimer prepare_precise_waits();

// Wakes every thread in sleep_until(word, ...); set `word` first.
void wake_all(std::atomic<int>& word);

// A hint to the core that this is a spin-wait (it saves power and frees the
// sibling hyper-thread).
void cpu_relax();

}  // namespace prox::runtime::platform
