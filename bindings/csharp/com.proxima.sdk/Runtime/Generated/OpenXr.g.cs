// Generated from sdk/include/proxima/proxima_openxr.h by bindings/csharp/tools/gen_native.py:
// do not edit. Regenerate with `python3 bindings/csharp/tools/gen_native.py`
// (docs/csharp.md); ctest csharp.generated fails while this file is stale.
using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>
    /// proxXrDeviceId: Proxima's OpenXR device: an XR controller's grip pose holds the tool, the rendered
    /// force comes back as the controller's vibration. The application owns OpenXR; Proxima borrows it. The
    /// app hands over its XrInstance, XrSession, world space, actions and its xrGetInstanceProcAddr, and
    /// Proxima makes every OpenXR call through that pointer (libproxima links no OpenXR loader). The app
    /// keeps polling events (forwarding session state changes), syncing actions (with the set that holds
    /// Proxima's actions) and running its frame loop; Proxima's own thread only locates the pose space and
    /// sends vibrations, which OpenXR allows concurrently. The integrator's checklist and the engine hooks
    /// are in docs/openxr.md; the walkthrough is samples/openxr/openxr_sample.c. Built when libproxima was
    /// configured with PROX_WITH_OPENXR; needs the OpenXR headers (Debian: libopenxr-dev), not its loader.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct XrDeviceId
    {
        // 0: the null id
        public uint Index1;
        public uint Generation;
    }

    /// <summary>proxXrPoseMode</summary>
    public enum XrPoseMode
    {
        /// <summary>
        /// Locate the pose space at "now" on every tick of the device's 1 kHz thread (the freshest pose; one
        /// xrLocateSpace per millisecond).
        /// </summary>
        LocateEachTick = 0,
        /// <summary>
        /// Locate it once a frame, at the frame's predicted display time, with its velocity
        /// (XrSpaceVelocity), and extrapolate to "now" on every tick.
        /// </summary>
        ExtrapolateFrame = 1,
    }

    /// <summary>
    /// proxXrTimeSource: Where the device's "now" (an XrTime) comes from, first that has one: the app's time
    /// conversion extension, the frames the app reports, else the device's own monotonic clock
    /// (docs/openxr.md, "Threads and time").
    /// </summary>
    public enum XrTimeSource
    {
        /// <summary>No time yet: no locate, the tick counts as untracked.</summary>
        None = 0,
        /// <summary>XR_KHR_convert_timespec_time (def.timespecTime).</summary>
        Timespec = 1,
        /// <summary>XR_KHR_win32_convert_performance_counter_time (def.win32PerformanceCounterTime).</summary>
        Win32PerformanceCounter = 2,
        /// <summary>The last predicted display time (proxXrDevice_OnFrame), advanced by the monotonic clock.</summary>
        Frames = 3,
        /// <summary>
        /// The device's monotonic clock from the newest time the runtime accepted (a locate that succeeded,
        /// def.runtimeTime, proxXrDevice_OnRuntimeTime).
        /// </summary>
        OwnClock = 4,
    }

    /// <summary>proxXrDeviceDef</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct XrDeviceSettings
    {
        // PROX_API_VERSION, set by proxDefaultXrDeviceDef()
        readonly int apiVersion;
        // the app's: every call goes through it
        public IntPtr GetInstanceProcAddr;
        public ulong Instance;
        public ulong Session;
        // the app's world space (LOCAL or STAGE)
        public ulong BaseSpace;
        // XR_ACTION_TYPE_POSE_INPUT, in a set the app attached and syncs
        public ulong PoseAction;
        // XR_ACTION_TYPE_VIBRATION_OUTPUT, or XR_NULL_HANDLE: no vibration
        public ulong HapticAction;
        // e.g. /user/hand/right, or XR_NULL_PATH
        public ulong SubactionPath;
        // the tool's pose in the grip space (default identity)
        public Pose ToolInGrip;
        // baseSpace's pose in Proxima's world (default identity)
        public Pose BaseToWorld;
        // default PROX_XR_LOCATE_EACH_TICK
        public XrPoseMode PoseMode;
        // Hz, in (0, 1000]: vibrations sent at most this often (default 100)
        public double VibrationRate;
        // N: the force rendered as amplitude 1 (default 5; above it, 1)
        public double ForceForFullAmplitude;
        // the app enabled XR_KHR_convert_timespec_time: "now" comes from it (default 0)
        public Bool32 TimespecTime;
        // The state the session is in when the device is created (default XR_SESSION_STATE_FOCUSED); forward
        // every later change.
        public int SessionState;
        // Hz, in [10, 10000]: the device thread (default 1000)
        public double TickRate;
        // s: each vibration's length, longer than 1/vibrationRate so pulses overlap (default 0.02)
        public double PulseDuration;
        // s: PROX_XR_EXTRAPOLATE_FRAME predicts at most this far (default 0.05)
        public double MaxExtrapolation;
        // do not touch
        readonly int internalValue;
        // Windows: the app enabled XR_KHR_win32_convert_performance_counter_time, "now" comes from it
        // (default 0; refused elsewhere).
        public Bool32 Win32PerformanceCounterTime;
        // An XrTime the runtime gave the app or accepted from it, about now (as for
        // proxXrDevice_OnRuntimeTime), or 0 (default): a device with no other source of "now" has a clock
        // from its first tick.
        public long RuntimeTime;
    }

    /// <summary>proxXrDeviceStats</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct XrDeviceStats
    {
        // the device thread's ticks
        public ulong Ticks;
        // xrLocateSpace calls
        public ulong Locates;
        // focused ticks without a valid pose (no valid bit, no time yet, a failed locate)
        public ulong UntrackedTicks;
        // ticks while the session was not FOCUSED (no pose, no vibration)
        public ulong NotFocusedTicks;
        // xrApplyHapticFeedback calls that succeeded
        public ulong VibrationsSent;
        // ... that failed (XR_SESSION_NOT_FOCUSED and the like): counted, never fatal
        public ulong VibrationsRefused;
        // xrStopHapticFeedback calls (contact ended, focus lost, destroyed)
        public ulong StopsSent;
        // poses handed to the haptic loop
        public ulong PosesPushed;
        // "now" is anchored on the last predicted display time (timeSource is PROX_XR_TIME_FRAMES)
        public Bool32 TimeFromFrames;
        // the last failing OpenXR result, or XR_SUCCESS
        public int LastXrResult;
        // the last amplitude sent
        public float LastAmplitude;
        // as last forwarded
        public int SessionState;
        // where the last tick's "now" came from
        public XrTimeSource TimeSource;
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern XrDeviceSettings proxDefaultXrDeviceDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_CreateXrDevice(WorldId world, ref XrDeviceSettings def, out XrDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxXrDevice_OnSessionState(XrDeviceId device, int state);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxXrDevice_OnFrame(XrDeviceId device, long predictedDisplayTime, long predictedDisplayPeriod);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxXrDevice_OnRuntimeTime(XrDeviceId device, long time);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxXrDevice_GetDeviceDef(XrDeviceId device, out DeviceDef def);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxXrDevice_GetStats(XrDeviceId device, out XrDeviceStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxXrDevice_Destroy(XrDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Bool32 proxXrDevice_IsValid(XrDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxXrCreateActions(IntPtr gipa, ulong instance, ulong set, byte[] utf8NamePrefix, out ulong poseAction, out ulong hapticAction);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxXrGetSuggestedBindings(IntPtr gipa, ulong instance, byte[] utf8InteractionProfile, byte[] utf8Hand, ulong poseAction, ulong hapticAction, IntPtr bindings, int capacity, out int count);
    }
}
