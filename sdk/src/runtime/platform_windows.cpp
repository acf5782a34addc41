// The platform layer on Windows (platform.h; Linux and other systems:
// platform.cpp). Windows 8 or later (WaitOnAddress); the high-resolution
// waitable timer needs Windows 10 1803, older systems get timeBeginPeriod(1).
#include "runtime/platform.h"

#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>
// After windows.h, which they need.
#include <avrt.h>
#include <mmsystem.h>

#if defined(__MINGW32__)
#include <pthread.h>  // pthread_gethandle: MinGW's std::thread is a winpthreads thread
#endif

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <vector>

#ifndef CREATE_WAITABLE_TIMER_HIGH_RESOLUTION
#define CREATE_WAITABLE_TIMER_HIGH_RESOLUTION 0x00000002
#endif

namespace prox::runtime::platform {
namespace {

// A Windows error as the errno the statistics report (proxThreadStats).
int errno_of(DWORD error) {
  switch (error) {
    case ERROR_ACCESS_DENIED:
    case ERROR_PRIVILEGE_NOT_HELD:
      return EPERM;
    case ERROR_NOT_ENOUGH_MEMORY:
    case ERROR_OUTOFMEMORY:
    case ERROR_WORKING_SET_QUOTA:
    case ERROR_NO_SYSTEM_RESOURCES:
      return ENOMEM;
    default:
      return EINVAL;
  }
}

// What a thread holds for its waits and its priority, released when it ends.
struct ThreadState {
  bool prepared = false;
  SleepTimer kind = SleepTimer::System;
  HANDLE timer = nullptr;
  bool period_begun = false;  // timeBeginPeriod(1), to end
  HANDLE mmcss = nullptr;     // AvSetMmThreadCharacteristics, to revert

  ThreadState() = default;
  ThreadState(const ThreadState&) = delete;
  ThreadState& operator=(const ThreadState&) = delete;
  ~ThreadState() {
    if (mmcss) AvRevertMmThreadCharacteristics(mmcss);
    if (timer) CloseHandle(timer);
    if (period_begun) timeEndPeriod(1);
  }
};

ThreadState& this_thread_state() {
  thread_local ThreadState state;
  return state;
}

HANDLE handle_of(std::thread& thread) {
#if defined(__MINGW32__)
  return pthread_gethandle(thread.native_handle());
#else
  return static_cast<HANDLE>(thread.native_handle());
#endif
}

// Waits `wait` (at most a few milliseconds) on the thread's timer.
void timer_wait(ThreadState& state, Clock::duration wait) {
  const auto ticks = std::chrono::duration_cast<std::chrono::duration<std::int64_t, std::ratio<1, 10000000>>>(wait);
  LARGE_INTEGER due;
  due.QuadPart = -std::max<std::int64_t>(1, ticks.count());  // negative: relative, in 100 ns
  if (state.timer && SetWaitableTimer(state.timer, &due, 0, nullptr, nullptr, FALSE)) {
    WaitForSingleObject(state.timer, INFINITE);
    return;
  }
  Sleep(wait >= std::chrono::milliseconds(1) ? 1 : 0);  // no timer at all: the scheduler's tick
}

}  // namespace

void default_cores(int cores[3]) {
  cores[0] = cores[1] = cores[2] = -1;
  DWORD_PTR process = 0, system = 0;
  if (!GetProcessAffinityMask(GetCurrentProcess(), &process, &system)) return;
  constexpr int kBits = int(sizeof(DWORD_PTR) * 8);
  int allowed = 0;
  for (int c = 0; c < kBits; ++c) allowed += int((process >> c) & 1u);
  if (allowed < 4) return;
  int found = 0;
  for (int c = kBits - 1; c >= 0 && found < 2; --c)
    if ((process >> c) & 1u) cores[found++] = c;  // haptic on the last allowed core, local on the one before
}

bool pin_current_thread(int core) {
  // One processor group: the first 64 logical processors.
  if (core < 0 || core >= int(sizeof(DWORD_PTR) * 8)) return false;
  return SetThreadAffinityMask(GetCurrentThread(), DWORD_PTR(1) << core) != 0;
}

int set_current_thread_realtime(int priority) {
  // Windows has no priority levels to ask for within a class: any 1-99 is
  // the highest of the normal classes, TIME_CRITICAL.
  if (priority < 1 || priority > 99) return EINVAL;
  if (!SetThreadPriority(GetCurrentThread(), THREAD_PRIORITY_TIME_CRITICAL)) return errno_of(GetLastError());
  // MMCSS's "Pro Audio" task where the service runs: the scheduler then
  // also keeps the thread's share of the CPU. A refusal leaves the priority.
  ThreadState& state = this_thread_state();
  if (!state.mmcss) {
    DWORD task = 0;
    state.mmcss = AvSetMmThreadCharacteristicsW(L"Pro Audio", &task);
    if (state.mmcss) AvSetMmThreadPriority(state.mmcss, AVRT_PRIORITY_CRITICAL);
  }
  return 0;
}

int lock_process_memory() {
  // Windows has no mlockall: lock each committed region now mapped. A
  // locked page counts against the working set's minimum, so that grows by
  // what is locked first.
  SYSTEM_INFO info;
  GetSystemInfo(&info);
  std::vector<MEMORY_BASIC_INFORMATION> regions;
  SIZE_T total = 0;
  try {
    char* p = static_cast<char*>(info.lpMinimumApplicationAddress);
    while (p < static_cast<char*>(info.lpMaximumApplicationAddress)) {
      MEMORY_BASIC_INFORMATION m;
      if (VirtualQuery(p, &m, sizeof m) == 0) break;
      const DWORD denied = PAGE_NOACCESS | PAGE_GUARD;
      if (m.State == MEM_COMMIT && m.Protect != 0 && (m.Protect & denied) == 0) {
        regions.push_back(m);
        total += m.RegionSize;
      }
      p = static_cast<char*>(m.BaseAddress) + m.RegionSize;
    }
  } catch (const std::bad_alloc&) {
    return ENOMEM;
  }
  const HANDLE process = GetCurrentProcess();
  SIZE_T minimum = 0, maximum = 0;
  if (!GetProcessWorkingSetSize(process, &minimum, &maximum)) return errno_of(GetLastError());
  const SIZE_T slack = SIZE_T(16) << 20;  // the pages the threads touch after this
  if (!SetProcessWorkingSetSize(process, minimum + total + slack, std::max(maximum, minimum + total + 2 * slack)))
    return errno_of(GetLastError());
  for (const MEMORY_BASIC_INFORMATION& m : regions)
    if (!VirtualLock(m.BaseAddress, m.RegionSize)) return errno_of(GetLastError());
  return 0;
}

double thread_cpu_seconds(std::thread& thread) {
  if (!thread.joinable()) return -1.0;
  FILETIME created, exited, kernel, user;
  if (!GetThreadTimes(handle_of(thread), &created, &exited, &kernel, &user)) return -1.0;
  const auto ticks = [](const FILETIME& t) {
    return double((std::uint64_t(t.dwHighDateTime) << 32) | t.dwLowDateTime);
  };
  return (ticks(kernel) + ticks(user)) * 1e-7;  // 100 ns units
}

SleepTimer prepare_precise_waits() {
  ThreadState& state = this_thread_state();
  if (state.prepared) return state.kind;
  state.prepared = true;
  state.timer = CreateWaitableTimerExW(nullptr, nullptr, CREATE_WAITABLE_TIMER_HIGH_RESOLUTION, TIMER_ALL_ACCESS);
  if (state.timer) {
    state.kind = SleepTimer::HighResolution;
    return state.kind;
  }
  // Before Windows 10 1803: an ordinary timer, on a 1 ms system tick.
  state.timer = CreateWaitableTimerExW(nullptr, nullptr, 0, TIMER_ALL_ACCESS);
  state.period_begun = timeBeginPeriod(1) == TIMERR_NOERROR;
  state.kind = state.period_begun ? SleepTimer::Period1ms : SleepTimer::System;
  return state.kind;
}

void sleep_until(const std::atomic<int>& word, Clock::time_point deadline) {
  static_assert(sizeof(std::atomic<int>) == sizeof(int) && std::atomic<int>::is_always_lock_free);
  ThreadState& state = this_thread_state();
  prepare_precise_waits();
  volatile void* address = const_cast<std::atomic<int>*>(&word);
  int zero = 0;
  while (word.load(std::memory_order_relaxed) == 0) {
    const auto now = Clock::now();
    if (now >= deadline) break;
    const auto left = deadline - now;
    // Far from the deadline: on the word, which wake_all wakes at once,
    // until the system's coarsest tick (15.6 ms) before the deadline.
    if (left > std::chrono::milliseconds(20)) {
      const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(left).count() - 16;
      WaitOnAddress(address, &zero, sizeof zero, DWORD(std::min<long long>(ms, 0x7FFFFFFF)));
      continue;
    }
    // The last stretch on the timer, in slices of a millisecond at most so
    // that a stop is seen within one.
    timer_wait(state, std::min<Clock::duration>(left, std::chrono::milliseconds(1)));
  }
}

void wake_all(std::atomic<int>& word) { WakeByAddressAll(&word); }

void cpu_relax() { YieldProcessor(); }

}  // namespace prox::runtime::platform
