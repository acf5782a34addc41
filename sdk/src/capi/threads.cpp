// The runtime's threads: start, stop, their statistics and the safety gate's.
#include "capi/common.h"

#include "runtime/threads.h"

using namespace prox;
using namespace prox::capi;

extern "C" {

proxThreadsDef proxDefaultThreadsDef(void) {
  const runtime::ThreadSettings s;
  proxThreadsDef d{};
  d.hapticRate = s.haptic_rate;
  d.localRate = s.local_rate;
  d.globalRate = s.global_rate;
  int cores[3];
  runtime::default_cores(cores);
  d.hapticCore = cores[0];
  d.localCore = cores[1];
  d.globalCore = cores[2];
  d.maxContacts = s.max_contacts;
  d.staleAfter = s.stale_after;
  d.maxForceRate = s.max_force_rate;
  d.maxTorqueRate = s.max_torque_rate;
  d.trustDistance = s.trust_distance;
  d.hapticTiming = PROX_TIMING_AUTO;
  d.spinMargin = s.spin_margin;
  d.hapticPriority = s.realtime_priority[0];
  d.localPriority = s.realtime_priority[1];
  d.lockMemory = s.lock_memory ? 1 : 0;
  d.internalValue = kDefCookie;
  return d;
}

proxResult proxWorld_StartThreads(proxWorldId world, const proxThreadsDef* def) {
  return guard("proxWorld_StartThreads", [&] {
    runtime::World& w = world_of(world);
    need(def, "def");
    need_def(*def, "proxDefaultThreadsDef");
    if (w.running()) fail(PROX_ERROR_BUSY, "the world's threads are already running");
    runtime::ThreadSettings s;
    s.haptic_rate = def->hapticRate;
    s.local_rate = def->localRate;
    s.global_rate = def->globalRate;
    s.cores[0] = def->hapticCore;
    s.cores[1] = def->localCore;
    s.cores[2] = def->globalCore;
    s.max_contacts = def->maxContacts;
    s.stale_after = def->staleAfter;
    s.max_force_rate = def->maxForceRate;
    s.max_torque_rate = def->maxTorqueRate;
    s.trust_distance = def->trustDistance;
    switch (def->hapticTiming) {
      case PROX_TIMING_AUTO:
        s.haptic_timing = runtime::HapticTiming::Auto;
        break;
      case PROX_TIMING_SPIN:
        s.haptic_timing = runtime::HapticTiming::Spin;
        break;
      case PROX_TIMING_SLEEP:
        s.haptic_timing = runtime::HapticTiming::Sleep;
        break;
      default:
        fail(PROX_ERROR_INVALID_ARGUMENT, "def->hapticTiming is not a proxHapticTiming");
    }
    s.spin_margin = def->spinMargin;
    s.realtime_priority[0] = def->hapticPriority;
    s.realtime_priority[1] = def->localPriority;
    s.lock_memory = def->lockMemory != 0;
    Status status;
    if (!w.start_threads(s, status)) {
      if (status.code() == StatusCode::InvalidArgument)
        fail(PROX_ERROR_INVALID_ARGUMENT, "def: " + status.message());
      fail(PROX_ERROR_INTERNAL, status.message());
    }
  });
}

proxResult proxWorld_StopThreads(proxWorldId world) {
  return guard("proxWorld_StopThreads", [&] { world_of(world).stop_threads(); });
}

proxResult proxWorld_GetThreadStats(proxWorldId world, proxThread thread, proxThreadStats* stats) {
  return guard("proxWorld_GetThreadStats", [&] {
    need(stats, "stats");
    *stats = proxThreadStats{};
    stats->pinnedCore = -1;
    const runtime::World& w = world_of(world);
    if (thread != PROX_THREAD_HAPTIC && thread != PROX_THREAD_LOCAL && thread != PROX_THREAD_GLOBAL)
      fail(PROX_ERROR_INVALID_ARGUMENT, "thread is not a proxThread");
    const runtime::Threads* t = w.threads();
    if (!t) return;  // never started: all zero
    const auto role = static_cast<runtime::Role>(thread);
    const runtime::LoopSummary s = t->loop_summary(role);
    stats->running = w.running() ? 1 : 0;
    stats->pinnedCore = t->pinned_core(role);
    stats->targetRate = s.target_rate;
    stats->achievedRate = s.achieved_rate;
    stats->periodP50 = s.period_p50;
    stats->periodP99 = s.period_p99;
    stats->periodMax = s.period_max;
    stats->updateP50 = s.update_p50;
    stats->updateP99 = s.update_p99;
    stats->updateMax = s.update_max;
    stats->updates = s.updates;
    stats->overruns = s.overruns;
    stats->periodP999 = s.period_p999;
    const runtime::ThreadGrant g = t->grant(role);
    stats->realtimePriority = g.realtime_priority;
    stats->realtimeError = g.realtime_error;
    if (role == runtime::Role::Haptic) {
      stats->memoryLocked = t->memory_locked() ? 1 : 0;
      stats->memoryLockError = t->memory_lock_error();
      stats->timing =
          t->haptic_timing() == runtime::HapticTiming::Spin ? PROX_TIMING_SPIN : PROX_TIMING_SLEEP;
    }
  });
}

proxResult proxWorld_GetSafetyStats(proxWorldId world, proxSafetyStats* stats) {
  return guard("proxWorld_GetSafetyStats", [&] {
    need(stats, "stats");
    *stats = proxSafetyStats{};
    const runtime::World& w = world_of(world);
    if (!w.threads()) return;
    const runtime::HapticCounters c = w.threads()->haptic_counters();
    *stats = {c.invalid_poses, c.stale_ticks,    c.untrusted_ticks,
              c.limited_ticks, c.torn_snapshots, c.dropped_contacts};
  });
}

}  // extern "C"
