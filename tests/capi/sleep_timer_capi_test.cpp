// What the haptic loop's sleeps wait on, and what the system granted it,
// through the C API on every system (Linux's refusals are timing_capi_test's).
// Behaviour, not figures: under Wine the timing is not Windows', so the loop
// is only required to tick and to say what it got.
#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "expect.h"
#include "lone_tool.h"

#include <cerrno>
#include <cstdio>

namespace {

using capi_test::wait_until;

const char* timer_name(proxSleepTimer timer) {
  switch (timer) {
    case PROX_SLEEP_TIMER_SYSTEM:
      return "the system's own";
    case PROX_SLEEP_TIMER_HIGH_RESOLUTION:
      return "a high-resolution waitable timer";
    case PROX_SLEEP_TIMER_PERIOD_1MS:
      return "a waitable timer with timeBeginPeriod(1)";
    default:
      return "not a proxSleepTimer";
  }
}

class SleepTimer : public capi_test::LoneTool {
 protected:
  // Runs the threads until the haptic loop has ticked `ticks` times; its stats.
  proxThreadStats run(const proxThreadsDef& def, uint64_t ticks) {
    proxThreadStats s{};
    EXPECT_OK(proxWorld_StartThreads(world, &def));
    EXPECT_TRUE(wait_until([&] {
      EXPECT_OK(proxWorld_GetThreadStats(world, PROX_THREAD_HAPTIC, &s));
      return s.updates >= ticks;
    })) << "the haptic loop ticked " << s.updates << " times";
    EXPECT_OK(proxWorld_GetThreadStats(world, PROX_THREAD_HAPTIC, &s));
    EXPECT_EQ(s.running, 1);
    EXPECT_OK(proxWorld_StopThreads(world));
    return s;
  }
};

TEST_F(SleepTimer, TheHapticLoopSaysWhatItsSleepsWaitOn) {
  for (proxHapticTiming mode : {PROX_TIMING_SLEEP, PROX_TIMING_SPIN}) {
    proxThreadsDef d = proxDefaultThreadsDef();
    d.hapticTiming = mode;
    const proxThreadStats s = run(d, 200);
    EXPECT_EQ(s.timing, mode);
    std::printf("haptic loop, %s: %.0f Hz, its sleeps wait on %s\n", mode == PROX_TIMING_SPIN ? "spin" : "sleep",
                s.achievedRate, timer_name(s.sleepTimer));
#if defined(_WIN32)
    // Windows 10 1803+ (and Wine) have the high-resolution timer; older
    // systems the 1 ms tick. Never the default 15.6 ms one.
    EXPECT_TRUE(s.sleepTimer == PROX_SLEEP_TIMER_HIGH_RESOLUTION || s.sleepTimer == PROX_SLEEP_TIMER_PERIOD_1MS)
        << s.sleepTimer;
#else
    EXPECT_EQ(s.sleepTimer, PROX_SLEEP_TIMER_SYSTEM);
#endif
    // Still reported once the threads are stopped.
    proxThreadStats after{};
    ASSERT_OK(proxWorld_GetThreadStats(world, PROX_THREAD_HAPTIC, &after));
    EXPECT_EQ(after.running, 0);
    EXPECT_EQ(after.sleepTimer, s.sleepTimer);
  }
}

#if defined(_WIN32)
// Windows: TIME_CRITICAL and VirtualLock (Linux's SCHED_FIFO and mlockall,
// granted and refused: timing_capi_test).
TEST_F(SleepTimer, PriorityAndMemoryLockAreGrantedOrReported) {
  proxThreadsDef d = proxDefaultThreadsDef();
  d.hapticTiming = PROX_TIMING_SLEEP;  // no spinning at TIME_CRITICAL on a shared machine
  d.hapticPriority = 80;
  d.lockMemory = 1;
  const proxThreadStats s = run(d, 100);
  std::printf("priority 80: %s (error %d); memory lock: %s (error %d)\n",
              s.realtimePriority ? "granted" : "refused", s.realtimeError, s.memoryLocked ? "granted" : "refused",
              s.memoryLockError);
  // Granted as asked, or refused with the reason; never half of each.
  if (s.realtimeError == 0) {
    EXPECT_EQ(s.realtimePriority, 80);
  } else {
    EXPECT_EQ(s.realtimePriority, 0);
    EXPECT_TRUE(s.realtimeError == EPERM || s.realtimeError == EINVAL) << s.realtimeError;
  }
  if (s.memoryLockError == 0) {
    EXPECT_EQ(s.memoryLocked, 1);
  } else {
    EXPECT_EQ(s.memoryLocked, 0);
    EXPECT_TRUE(s.memoryLockError == ENOMEM || s.memoryLockError == EPERM || s.memoryLockError == EINVAL)
        << s.memoryLockError;
  }
  // What was asked of the system did not stop the loop: it ticked.
  EXPECT_GE(s.updates, 100u);
}
#endif

}  // namespace
