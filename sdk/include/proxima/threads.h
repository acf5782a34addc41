/* Proxima's threads: the haptic loop, local tracking and the global search
 * (proxWorld_StartThreads), their timing and the safety gate's statistics,
 * and the haptic loop's flight recorder. Part of the core API: proxima/proxima.h
 * includes this header. The same conventions as proxima.h. */
#ifndef PROXIMA_THREADS_H
#define PROXIMA_THREADS_H

#include "proxima/proxima.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- threads --------------------------------------------------------------------- */

/* How the haptic loop waits for its next period (docs/threading.md,
 * "Keeping the beat"). Both wait for an absolute deadline, so they never drift. */
typedef enum proxHapticTiming {
  PROX_TIMING_AUTO = 0,  /* SPIN when the haptic thread runs real-time or on a core of its own, else SLEEP */
  PROX_TIMING_SPIN = 1,  /* sleep to spinMargin before the deadline, then spin to it: on time, costs CPU */
  PROX_TIMING_SLEEP = 2, /* sleep to the deadline: no CPU between ticks, late by the OS's wake-up */
  PROX_TIMING_FORCE32 = 0x7FFFFFFF
} proxHapticTiming;

/* What the haptic loop's sleeps wait on (proxThreadStats.sleepTimer), as the
 * system allowed (docs/threading.md, "Keeping the beat"). */
typedef enum proxSleepTimer {
  PROX_SLEEP_TIMER_SYSTEM = 0,          /* the system's own: Linux's futex wait on high-resolution timers */
  PROX_SLEEP_TIMER_HIGH_RESOLUTION = 1, /* Windows 10 1803+: a high-resolution waitable timer */
  PROX_SLEEP_TIMER_PERIOD_1MS = 2,      /* older Windows: a waitable timer, timeBeginPeriod(1) while the loop runs */
  PROX_SLEEP_TIMER_FORCE32 = 0x7FFFFFFF
} proxSleepTimer;

typedef struct proxThreadsDef {
  int32_t apiVersion; /* PROX_API_VERSION, set by proxDefaultThreadsDef() */
  double hapticRate; /* Hz, in [1, 100000]: the haptic loop (default 1000) */
  double localRate;  /* Hz, 0 or >= 1: local tracking (default 1000; 0: back to back) */
  double globalRate; /* Hz, 0 or >= 1: global search (default 0: back to back, idle while nothing moves) */
  /* The core each thread is pinned to; -1: not pinned. The default, where
   * the process may use at least four cores: the haptic and local threads
   * on the last two, one each, the global search unpinned; else none. */
  int32_t hapticCore, localCore, globalCore;
  int32_t maxContacts;  /* per tool handed to the haptic loop, the closest first (default 1024) */
  double staleAfter;    /* s: contacts older than this fade the force out (default 0.05) */
  double maxForceRate;  /* N/s: how fast the force may change (default 300) */
  double maxTorqueRate; /* N m/s (default 30) */
  /* m: contacts tracked at a tool pose farther than this from the current
   * one are not rendered (a teleport; the force fades out until tracking
   * catches up). 0 (the default): the world's cutoff. */
  double trustDistance;
  proxHapticTiming hapticTiming; /* default PROX_TIMING_AUTO */
  /* SCHED_FIFO priority (1-99) asked for the haptic thread; 0 (the default):
   * none. Needs root, CAP_SYS_NICE or an RLIMIT_RTPRIO of at least it; a
   * refusal is reported in proxThreadStats, never an error. On Windows any
   * priority asks for THREAD_PRIORITY_TIME_CRITICAL (and MMCSS's "Pro
   * Audio" task where that service runs). */
  int32_t hapticPriority;
  double spinMargin;     /* s, in [0, the haptic period]: PROX_TIMING_SPIN's spin (default 0.0002) */
  int32_t localPriority; /* the same for the local tracking thread (default 0) */
  /* Lock the process's memory (mlockall(MCL_CURRENT); Windows: VirtualLock
   * on every committed region) once the threads run, so no page the haptic
   * loop touches is paged out. Process-wide and never undone by Proxima;
   * reported in proxThreadStats. Default 0. */
  proxBool lockMemory;
  int32_t internalValue;
  /* The flight recorder: keep each tool's last this many haptic ticks for
   * proxBody_GetHapticTrace, in [0, 1048576] (192 bytes a tick, reserved
   * when the threads start). 0 (the default): off. */
  int32_t traceCapacity;
  /* Threads the global search splits each pair's search over, itself
   * included, in [1, 256] (default 1). Its helpers are plain threads,
   * neither pinned nor prioritised: leave the haptic and local threads
   * their cores (on two cores, keep 1). The contacts are the same
   * whatever the count (docs/benchmarks.md, "On every core"). */
  int32_t globalWorkerCount;
} proxThreadsDef;

PROX_API proxThreadsDef proxDefaultThreadsDef(void);

/* Starts the haptic, local tracking and global search threads. While they
 * run: meshes and bodies come and go, meshes deform and tools change
 * devices (docs/dynamic-scenes.md); proxWorld_Step is refused
 * (PROX_ERROR_BUSY); proxBody_SetPose moves static and movable bodies and
 * tools no device holds; contacts, wrench, pose and stats read the
 * threads' latest results. Game thread. */
PROX_API proxResult proxWorld_StartThreads(proxWorldId world, const proxThreadsDef* def);
/* Fades every device's force out, then stops and joins the threads; the
 * last results stay readable. No effect when they do not run. Game thread. */
PROX_API proxResult proxWorld_StopThreads(proxWorldId world);

typedef enum proxThread {
  PROX_THREAD_HAPTIC = 0,
  PROX_THREAD_LOCAL = 1,
  PROX_THREAD_GLOBAL = 2,
  PROX_THREAD_FORCE32 = 0x7FFFFFFF
} proxThread;

/* One thread's timing over its last 4096 iterations (maxima and counts over
 * the whole run), from the running threads or the last ones stopped. */
typedef struct proxThreadStats {
  proxBool running;
  int32_t pinnedCore;                     /* -1: not pinned */
  double targetRate;                      /* Hz; 0: back to back */
  double achievedRate;                    /* Hz */
  double periodP50, periodP99, periodMax; /* s, iteration start to start */
  double updateP50, updateP99, updateMax; /* s of work per iteration */
  uint64_t updates;
  uint64_t overruns;        /* iterations that missed the next period's start */
  double periodP999;        /* s: the 99.9th percentile of the period */
  int32_t realtimePriority; /* the SCHED_FIFO priority granted (Windows: the one asked, granted as
                             * TIME_CRITICAL); 0: none asked, or refused */
  int32_t realtimeError;    /* the errno that refused it (1, EPERM: no privilege); 0 */
  proxBool memoryLocked;    /* haptic thread's stats: lockMemory was granted */
  int32_t memoryLockError;  /* ... or the errno that refused it (ENOMEM, EPERM: RLIMIT_MEMLOCK); 0 */
  proxHapticTiming timing;  /* haptic thread's stats: SPIN or SLEEP, as AUTO resolved */
  proxSleepTimer sleepTimer; /* haptic thread's stats: what its sleeps wait on */
} proxThreadStats;

/* Game thread. */
PROX_API proxResult proxWorld_GetThreadStats(proxWorldId world, proxThread thread, proxThreadStats* stats);

/* The haptic loop's safety decisions, counted in ticks over all tools. */
typedef struct proxSafetyStats {
  uint64_t invalidPoses;    /* the device gave no pose, or an invalid one */
  uint64_t staleTicks;      /* contacts older than staleAfter: faded out */
  uint64_t untrustedTicks;  /* tool farther than trustDistance from where contacts were tracked */
  uint64_t limitedTicks;    /* the gate changed the wrench (clip or rate) */
  uint64_t tornSnapshots;   /* a contact snapshot failed its checksum (never expected) */
  uint64_t droppedContacts; /* contacts beyond maxContacts, summed over snapshots */
} proxSafetyStats;

/* Game thread. */
PROX_API proxResult proxWorld_GetSafetyStats(proxWorldId world, proxSafetyStats* stats);

/* ---- the flight recorder -----------------------------------------------------
 * What the haptic loop rendered, tick by tick (docs/haptic-fidelity.md): what
 * "it buzzes" is debugged with. Recorded on the haptic thread without a lock,
 * an allocation or a system call, when proxThreadsDef.traceCapacity > 0. */

typedef enum proxHapticFlag {
  PROX_HAPTIC_CLIPPED = 1,    /* the safety gate changed the wrench (the clip or the rate limit) */
  PROX_HAPTIC_STALE = 2,      /* the contacts were older than staleAfter */
  PROX_HAPTIC_UNTRUSTED = 4,  /* the tool was farther than trustDistance from where they were tracked */
  PROX_HAPTIC_FADED = 8,      /* no contacts rendered this tick: the gate faded the force towards zero */
  PROX_HAPTIC_NO_POSE = 16,   /* the device gave no valid pose (devicePose: the last valid one) */
  PROX_HAPTIC_STOPPING = 32,  /* a tick of the fade-out after proxWorld_StopThreads */
  PROX_HAPTIC_FLAG_FORCE32 = 0x7FFFFFFF
} proxHapticFlag;

typedef struct proxHapticSample {
  double time;          /* s since the threads started */
  proxPose devicePose;  /* the device's pose this tick (the game's, for a tool no device holds) */
  proxPose proxyPose;   /* a constrained tool's proxy this tick (never closer than the safety distance), else devicePose */
  proxVec3 force;       /* N, what the device was handed (after the safety gate) */
  proxVec3 torque;      /* N m */
  int32_t contactCount; /* contacts rendered this tick (0 when faded) */
  uint32_t flags;       /* proxHapticFlag bits */
  double closestDistance; /* m: the closest contact's distance told to the device; +infinity: none */
  uint64_t tick;        /* the tool's haptic ticks before this one: consecutive samples differ by 1 */
} proxHapticSample;

/* Copies the tool's newest recorded ticks, at most `capacity`, oldest first,
 * into `samples` and sets *count to how many it copied (0 when the recorder
 * is off or the threads never ran). While the threads run, from the running
 * loop; after a stop, the last run's, the fade-out included. Game thread. */
PROX_API proxResult proxBody_GetHapticTrace(proxBodyId tool, proxHapticSample* samples, int32_t capacity,
                                            int32_t* count);

#ifdef __cplusplus
}
#endif

#endif /* PROXIMA_THREADS_H */
