// The operating system beneath the runtime's threads: pinning, real-time
// priority, memory locking, a thread's CPU clock, and the absolute-deadline
// sleep that a stop request can cut short. Everything here is per platform
// (Linux now; other systems fall back to the standard library where it can
// and report ENOSYS where it cannot), so threads.cpp holds no system call.
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

// Asks SCHED_FIFO at `priority` (1-99) for the calling thread: 0 when
// granted, else the errno that refused it (ENOSYS where there is none).
int set_current_thread_realtime(int priority);

// mlockall(MCL_CURRENT): 0 when locked, else the errno that refused it.
int lock_process_memory();

// CPU seconds `thread` has used so far; -1 when the system cannot tell.
double thread_cpu_seconds(std::thread& thread);

// Sleeps until `deadline` on Clock, or until wake_all(word) is called while
// `word` is non-zero; returns at once if it already is. A late wake-up or a
// signal does not make the caller drift: the deadline is absolute.
void sleep_until(const std::atomic<int>& word, Clock::time_point deadline);

// Wakes every thread in sleep_until(word, ...); set `word` first.
void wake_all(std::atomic<int>& word);

// A hint to the core that this is a spin-wait (it saves power and frees the
// sibling hyper-thread).
void cpu_relax();

}  // namespace prox::runtime::platform
