// The haptic loop's timing through the C API, functionally (the figures are
// the benchmark's): each timing mode keeps the rate within a loose bound, the
// settings are checked by name, the default pinning follows the core count,
// and a real-time priority or a memory lock the system refuses is reported,
// never fatal. Refusals are made certain by taking the privilege away from
// the calling thread first (the runtime's threads inherit it).
#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "expect.h"
#include "lone_tool.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include <linux/capability.h>
#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#include <cerrno>

namespace {

// Takes CAP_SYS_NICE and CAP_IPC_LOCK out of the calling thread's effective
// set and lowers its soft RLIMIT_RTPRIO and RLIMIT_MEMLOCK, so that neither a
// real-time priority nor mlockall can be granted to threads it starts; puts
// everything back when it goes.
class WithoutPrivileges {
 public:
  WithoutPrivileges() {
    header_.version = _LINUX_CAPABILITY_VERSION_3;
    header_.pid = 0;
    have_caps_ = syscall(SYS_capget, &header_, saved_) == 0;
    if (have_caps_) {
      __user_cap_data_struct reduced[2] = {saved_[0], saved_[1]};
      for (int cap : {CAP_SYS_NICE, CAP_IPC_LOCK}) reduced[CAP_TO_INDEX(cap)].effective &= ~CAP_TO_MASK(cap);
      EXPECT_EQ(syscall(SYS_capset, &header_, reduced), 0) << "capset: " << errno;
    }
    getrlimit(RLIMIT_RTPRIO, &rtprio_);
    getrlimit(RLIMIT_MEMLOCK, &memlock_);
    rlimit none = rtprio_;
    none.rlim_cur = 0;
    EXPECT_EQ(setrlimit(RLIMIT_RTPRIO, &none), 0);
    none = memlock_;
    none.rlim_cur = 0;
    EXPECT_EQ(setrlimit(RLIMIT_MEMLOCK, &none), 0);
  }
  ~WithoutPrivileges() {
    setrlimit(RLIMIT_RTPRIO, &rtprio_);
    setrlimit(RLIMIT_MEMLOCK, &memlock_);
    if (have_caps_) syscall(SYS_capset, &header_, saved_);
  }

 private:
  __user_cap_header_struct header_{};
  __user_cap_data_struct saved_[2]{};
  bool have_caps_ = false;
  rlimit rtprio_{}, memlock_{};
};

// Whether a thread started now may run SCHED_FIFO at `priority`: asked of
// the system directly, on a thread of the test's own.
int probe_realtime(int priority) {
  int error = 0;
  std::thread([&] {
    sched_param p{};
    p.sched_priority = priority;
    error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &p);
  }).join();
  return error;
}

class Timing : public capi_test::LoneTool {
 protected:
  // Runs the threads for `seconds` and returns the haptic thread's stats.
  proxThreadStats run(const proxThreadsDef& def, double seconds, proxThreadStats* local = nullptr) {
    proxThreadStats s{};
    EXPECT_OK(proxWorld_StartThreads(world, &def));
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    EXPECT_OK(proxWorld_GetThreadStats(world, PROX_THREAD_HAPTIC, &s));
    if (local) EXPECT_OK(proxWorld_GetThreadStats(world, PROX_THREAD_LOCAL, local));
    EXPECT_EQ(s.running, 1) << "a refused request must not stop the threads";
    EXPECT_OK(proxWorld_StopThreads(world));
    return s;
  }
};

TEST_F(Timing, SettingsAreValidatedByName) {
  const proxThreadsDef good = proxDefaultThreadsDef();
  EXPECT_EQ(good.hapticTiming, PROX_TIMING_AUTO);
  EXPECT_EQ(good.spinMargin, 0.0002);
  EXPECT_EQ(good.hapticPriority, 0);
  EXPECT_EQ(good.localPriority, 0);
  EXPECT_EQ(good.lockMemory, 0);
  struct Case {
    void (*spoil)(proxThreadsDef&);
    const char* word;
  };
  const Case cases[] = {
      {[](proxThreadsDef& d) { d.hapticTiming = static_cast<proxHapticTiming>(9); }, "hapticTiming"},
      {[](proxThreadsDef& d) { d.spinMargin = -1e-4; }, "spin margin"},
      {[](proxThreadsDef& d) { d.spinMargin = NAN; }, "spin margin"},
      {[](proxThreadsDef& d) { d.spinMargin = 0.0011; }, "haptic period"},
      {[](proxThreadsDef& d) { d.hapticPriority = 100; }, "haptic thread's real-time priority"},
      {[](proxThreadsDef& d) { d.hapticPriority = -1; }, "haptic thread's real-time priority"},
      {[](proxThreadsDef& d) { d.localPriority = 200; }, "local thread's real-time priority"},
  };
  for (const Case& c : cases) {
    proxThreadsDef d = good;
    c.spoil(d);
    EXPECT_FAILS(proxWorld_StartThreads(world, &d), PROX_ERROR_INVALID_ARGUMENT, c.word);
  }
  proxThreadStats s{};
  EXPECT_OK(proxWorld_GetThreadStats(world, PROX_THREAD_HAPTIC, &s));
  EXPECT_EQ(s.running, 0);
}

// Pinned by default only where the process may use four cores or more: the
// haptic and local threads on two different ones, the global search free.
TEST_F(Timing, DefaultPinningFollowsTheCoresAllowed) {
  cpu_set_t set;
  CPU_ZERO(&set);
  ASSERT_EQ(sched_getaffinity(0, sizeof set, &set), 0);
  const proxThreadsDef d = proxDefaultThreadsDef();
  EXPECT_EQ(d.globalCore, -1);
  if (CPU_COUNT(&set) >= 4) {
    ASSERT_GE(d.hapticCore, 0);
    ASSERT_GE(d.localCore, 0);
    EXPECT_NE(d.hapticCore, d.localCore);
    EXPECT_TRUE(CPU_ISSET(d.hapticCore, &set) && CPU_ISSET(d.localCore, &set));
  } else {
    EXPECT_EQ(d.hapticCore, -1);
    EXPECT_EQ(d.localCore, -1);
  }
  const proxThreadStats s = run(d, 0.05);
  EXPECT_EQ(s.pinnedCore, d.hapticCore);
}

// Every mode keeps the rate within a loose bound (a busy machine's
// scheduler decides the rest), and says which mode it ran.
TEST_F(Timing, EachModeKeepsTheRate) {
  for (proxHapticTiming mode : {PROX_TIMING_AUTO, PROX_TIMING_SPIN, PROX_TIMING_SLEEP}) {
    proxThreadsDef d = proxDefaultThreadsDef();
    d.hapticTiming = mode;
    const proxThreadStats s = run(d, 0.4);
    EXPECT_GT(s.achievedRate, 500.0) << mode;
    EXPECT_LT(s.achievedRate, 1100.0) << mode;
    EXPECT_GT(s.updates, 150u) << mode;
    EXPECT_LE(s.periodP99, s.periodP999) << mode;
    EXPECT_LE(s.periodP999, s.periodMax) << mode;
    const bool own_core = s.pinnedCore >= 0 && d.localCore != s.pinnedCore && d.globalCore != s.pinnedCore;
    const proxHapticTiming expected =
        mode != PROX_TIMING_AUTO ? mode : (own_core ? PROX_TIMING_SPIN : PROX_TIMING_SLEEP);
    EXPECT_EQ(s.timing, expected) << mode;
  }
}

TEST_F(Timing, ARefusedPriorityOrMemoryLockIsReportedNotFatal) {
  const WithoutPrivileges unprivileged;
  ASSERT_NE(probe_realtime(80), 0) << "the test could not take the privilege away";
  proxThreadsDef d = proxDefaultThreadsDef();
  d.hapticPriority = 80;
  d.localPriority = 70;
  d.lockMemory = 1;
  proxThreadStats local{};
  const proxThreadStats s = run(d, 0.2, &local);
  EXPECT_EQ(s.realtimePriority, 0);
  EXPECT_EQ(s.realtimeError, EPERM);
  EXPECT_EQ(local.realtimePriority, 0);
  EXPECT_EQ(local.realtimeError, EPERM);
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  // The sanitizers replace mlockall with a no-op that succeeds (locking
  // their shadow memory would take the machine's): nothing to refuse here.
  EXPECT_EQ(s.memoryLocked, 1);
#else
  EXPECT_EQ(s.memoryLocked, 0);
  EXPECT_TRUE(s.memoryLockError == ENOMEM || s.memoryLockError == EPERM) << s.memoryLockError;
#endif
  EXPECT_GT(s.achievedRate, 500.0) << "the threads run on at normal priority";
}

// Granted exactly when the system grants it to any thread of this process.
TEST_F(Timing, APriorityTheSystemAllowsIsGranted) {
  const int allowed = probe_realtime(10);
  proxThreadsDef d = proxDefaultThreadsDef();
  d.hapticPriority = 10;
  const proxThreadStats s = run(d, 0.2);
  EXPECT_EQ(s.realtimeError, allowed);
  EXPECT_EQ(s.realtimePriority, allowed == 0 ? 10 : 0);
  if (allowed == 0) {
    EXPECT_EQ(s.timing, PROX_TIMING_SPIN) << "auto spins when real-time";
  }
}

}  // namespace
