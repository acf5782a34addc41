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
  d.apiVersion = PROX_API_VERSION;
  d.internalValue = kDefCookie;
  d.traceCapacity = s.trace_capacity;
  d.globalWorkerCount = s.global_workers;
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
    switch (enum_value(def->hapticTiming)) {
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
    s.trace_capacity = def->traceCapacity;
    s.global_workers = def->globalWorkerCount;
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
    if (enum_value(thread) != PROX_THREAD_HAPTIC && enum_value(thread) != PROX_THREAD_LOCAL &&
        enum_value(thread) != PROX_THREAD_GLOBAL)
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
      stats->sleepTimer = static_cast<proxSleepTimer>(t->sleep_timer());
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

proxResult proxBody_GetHapticTrace(proxBodyId tool, proxHapticSample* samples, int32_t capacity,
                                   int32_t* count) {
  return guard("proxBody_GetHapticTrace", [&] {
    need(count, "count");
    *count = 0;
    if (capacity < 0) fail(PROX_ERROR_INVALID_ARGUMENT, "capacity is negative");
    if (capacity > 0) need(samples, "samples");
    runtime::World* w = nullptr;
    const runtime::Handle h = tool_of(tool, w);
    const runtime::Threads* t = w->threads();
    if (!t || capacity == 0) return;
    // The ring's samples hold the C struct's contents in another layout.
    static_assert(sizeof(runtime::TraceSample) == sizeof(proxHapticSample));
    std::vector<runtime::TraceSample> buffer(static_cast<std::size_t>(capacity));
    const std::size_t n = t->trace(h.index, buffer.data(), buffer.size());
    auto pose = [](const double* p) { return proxPose{{p[0], p[1], p[2]}, {p[3], p[4], p[5], p[6]}}; };
    for (std::size_t i = 0; i < n; ++i) {
      const runtime::TraceSample& s = buffer[i];
      proxHapticSample& out = samples[i];
      out.time = s.time;
      out.devicePose = pose(s.device);
      out.proxyPose = pose(s.proxy);
      out.force = {s.force[0], s.force[1], s.force[2]};
      out.torque = {s.torque[0], s.torque[1], s.torque[2]};
      out.contactCount = static_cast<int32_t>(s.contacts);
      out.flags = s.flags;
      out.closestDistance = s.closest;
      out.tick = s.tick;
    }
    *count = static_cast<int32_t>(n);
  });
}

}  // extern "C"
