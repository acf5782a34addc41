// Generated from sdk/include/proxima/threads.h by bindings/csharp/tools/gen_native.py:
// do not edit. Regenerate with `python3 bindings/csharp/tools/gen_native.py`
// (docs/csharp.md); ctest csharp.generated fails while this file is stale.
using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>
    /// proxHapticTiming: How the haptic loop waits for its next period (docs/threading.md, "Keeping the
    /// beat"). Both wait for an absolute deadline, so they never drift.
    /// </summary>
    public enum HapticTiming
    {
        /// <summary>SPIN when the haptic thread runs real-time or on a core of its own, else SLEEP</summary>
        Auto = 0,
        /// <summary>sleep to spinMargin before the deadline, then spin to it: on time, costs CPU</summary>
        Spin = 1,
        /// <summary>sleep to the deadline: no CPU between ticks, late by the OS's wake-up</summary>
        Sleep = 2,
    }

    /// <summary>
    /// proxSleepTimer: What the haptic loop's sleeps wait on (proxThreadStats.sleepTimer), as the system
    /// allowed (docs/threading.md, "Keeping the beat").
    /// </summary>
    public enum SleepTimer
    {
        /// <summary>the system's own: Linux's futex wait on high-resolution timers</summary>
        System = 0,
        /// <summary>Windows 10 1803+: a high-resolution waitable timer</summary>
        HighResolution = 1,
        /// <summary>older Windows: a waitable timer, timeBeginPeriod(1) while the loop runs</summary>
        Period1ms = 2,
    }

    /// <summary>proxThreadsDef</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct ThreadSettings
    {
        // PROX_API_VERSION, set by proxDefaultThreadsDef()
        readonly int apiVersion;
        // Hz, in [1, 100000]: the haptic loop (default 1000)
        public double HapticRate;
        // Hz, 0 or >= 1: local tracking (default 1000; 0: back to back)
        public double LocalRate;
        // Hz, 0 or >= 1: global search (default 0: back to back, idle while nothing moves)
        public double GlobalRate;
        // The core each thread is pinned to; -1: not pinned. The default, where the process may use at least
        // four cores: the haptic and local threads on the last two, one each, the global search unpinned;
        // else none.
        public int HapticCore;
        // The core each thread is pinned to; -1: not pinned. The default, where the process may use at least
        // four cores: the haptic and local threads on the last two, one each, the global search unpinned;
        // else none.
        public int LocalCore;
        // The core each thread is pinned to; -1: not pinned. The default, where the process may use at least
        // four cores: the haptic and local threads on the last two, one each, the global search unpinned;
        // else none.
        public int GlobalCore;
        // per tool handed to the haptic loop, the closest first (default 1024)
        public int MaxContacts;
        // s: contacts older than this fade the force out (default 0.05)
        public double StaleAfter;
        // N/s: how fast the force may change (default 300)
        public double MaxForceRate;
        // N m/s (default 30)
        public double MaxTorqueRate;
        // m: contacts tracked at a tool pose farther than this from the current one are not rendered (a
        // teleport; the force fades out until tracking catches up). 0 (the default): the world's cutoff.
        public double TrustDistance;
        // default PROX_TIMING_AUTO
        public HapticTiming HapticTiming;
        // SCHED_FIFO priority (1-99) asked for the haptic thread; 0 (the default): none. Needs root,
        // CAP_SYS_NICE or an RLIMIT_RTPRIO of at least it; a refusal is reported in proxThreadStats, never an
        // error. On Windows any priority asks for THREAD_PRIORITY_TIME_CRITICAL (and MMCSS's "Pro Audio" task
        // where that service runs).
        public int HapticPriority;
        // s, in [0, the haptic period]: PROX_TIMING_SPIN's spin (default 0.0002)
        public double SpinMargin;
        // the same for the local tracking thread (default 0)
        public int LocalPriority;
        // Lock the process's memory (mlockall(MCL_CURRENT); Windows: VirtualLock on every committed region)
        // once the threads run, so no page the haptic loop touches is paged out. Process-wide and never
        // undone by Proxima; reported in proxThreadStats. Default 0.
        public Bool32 LockMemory;
        readonly int internalValue;
        // The flight recorder: keep each tool's last this many haptic ticks for proxBody_GetHapticTrace, in
        // [0, 1048576] (192 bytes a tick, reserved when the threads start). 0 (the default): off.
        public int TraceCapacity;
        // Threads the global search splits each pair's search over, itself included, in [1, 256] (default 1).
        // Its helpers are plain threads, neither pinned nor prioritised: leave the haptic and local threads
        // their cores (on two cores, keep 1). The contacts are the same whatever the count
        // (docs/benchmarks.md, "On every core").
        public int GlobalWorkerCount;
    }

    /// <summary>proxThread</summary>
    public enum ThreadRole
    {
        Haptic = 0,
        Local = 1,
        Global = 2,
    }

    /// <summary>
    /// proxThreadStats: One thread's timing over its last 4096 iterations (maxima and counts over the whole
    /// run), from the running threads or the last ones stopped.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct ThreadStats
    {
        public Bool32 Running;
        // -1: not pinned
        public int PinnedCore;
        // Hz; 0: back to back
        public double TargetRate;
        // Hz
        public double AchievedRate;
        // s, iteration start to start
        public double PeriodP50;
        // s, iteration start to start
        public double PeriodP99;
        // s, iteration start to start
        public double PeriodMax;
        // s of work per iteration
        public double UpdateP50;
        // s of work per iteration
        public double UpdateP99;
        // s of work per iteration
        public double UpdateMax;
        public ulong Updates;
        // iterations that missed the next period's start
        public ulong Overruns;
        // s: the 99.9th percentile of the period
        public double PeriodP999;
        // the SCHED_FIFO priority granted (Windows: the one asked, granted as TIME_CRITICAL); 0: none asked,
        // or refused
        public int RealtimePriority;
        // the errno that refused it (1, EPERM: no privilege); 0
        public int RealtimeError;
        // haptic thread's stats: lockMemory was granted
        public Bool32 MemoryLocked;
        // ... or the errno that refused it (ENOMEM, EPERM: RLIMIT_MEMLOCK); 0
        public int MemoryLockError;
        // haptic thread's stats: SPIN or SLEEP, as AUTO resolved
        public HapticTiming Timing;
        // haptic thread's stats: what its sleeps wait on
        public SleepTimer SleepTimer;
    }

    /// <summary>proxSafetyStats: The haptic loop's safety decisions, counted in ticks over all tools.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct SafetyStats
    {
        // the device gave no pose, or an invalid one
        public ulong InvalidPoses;
        // contacts older than staleAfter: faded out
        public ulong StaleTicks;
        // tool farther than trustDistance from where contacts were tracked
        public ulong UntrustedTicks;
        // the gate changed the wrench (clip or rate)
        public ulong LimitedTicks;
        // a contact snapshot failed its checksum (never expected)
        public ulong TornSnapshots;
        // contacts beyond maxContacts, summed over snapshots
        public ulong DroppedContacts;
    }

    /// <summary>
    /// proxHapticFlag: What the haptic loop rendered, tick by tick (docs/haptic-fidelity.md): what "it
    /// buzzes" is debugged with. Recorded on the haptic thread without a lock, an allocation or a system
    /// call, when proxThreadsDef.traceCapacity &gt; 0.
    /// </summary>
    [Flags]
    public enum HapticFlags : uint
    {
        None = 0,
        /// <summary>the safety gate changed the wrench (the clip or the rate limit)</summary>
        Clipped = 1,
        /// <summary>the contacts were older than staleAfter</summary>
        Stale = 2,
        /// <summary>the tool was farther than trustDistance from where they were tracked</summary>
        Untrusted = 4,
        /// <summary>no contacts rendered this tick: the gate faded the force towards zero</summary>
        Faded = 8,
        /// <summary>the device gave no valid pose (devicePose: the last valid one)</summary>
        NoPose = 16,
        /// <summary>a tick of the fade-out after proxWorld_StopThreads</summary>
        Stopping = 32,
    }

    /// <summary>proxHapticSample</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct HapticSample
    {
        // s since the threads started
        public double Time;
        // the device's pose this tick (the game's, for a tool no device holds)
        public Pose DevicePose;
        // a constrained tool's proxy this tick (never closer than the safety distance), else devicePose
        public Pose ProxyPose;
        // N, what the device was handed (after the safety gate)
        public Vec3 Force;
        // N m
        public Vec3 Torque;
        // contacts rendered this tick (0 when faded)
        public int ContactCount;
        // proxHapticFlag bits
        public HapticFlags Flags;
        // m: the closest contact's distance told to the device; +infinity: none
        public double ClosestDistance;
        // the tool's haptic ticks before this one: consecutive samples differ by 1
        public ulong Tick;
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ThreadSettings proxDefaultThreadsDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_StartThreads(WorldId world, ref ThreadSettings def);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_StopThreads(WorldId world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetThreadStats(WorldId world, ThreadRole thread, out ThreadStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetSafetyStats(WorldId world, out SafetyStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetHapticTrace(BodyId tool, [Out] HapticSample[] samples, int capacity, out int count);
    }
}
