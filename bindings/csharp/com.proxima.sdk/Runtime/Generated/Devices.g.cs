// Generated from sdk/include/proxima/devices.h by bindings/csharp/tools/gen_native.py:
// do not edit. Regenerate with `python3 bindings/csharp/tools/gen_native.py`
// (docs/csharp.md); ctest csharp.generated fails while this file is stale.
using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>
    /// proxDeviceDef: A haptic device: two callbacks and your pointer, called from the haptic thread at its
    /// rate while the world's threads run. They must return quickly and must not call Proxima.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct DeviceDef
    {
        // PROX_API_VERSION, set by proxDefaultDeviceDef()
        public int ApiVersion;
        // Writes the tool's world pose and returns nonzero, or returns 0 when the device has no pose this
        // tick (the force then fades out). A non-finite pose or a quaternion far from unit length counts as
        // none. Required.
        public IntPtr ReadPose;
        // Receives the force and torque to render: always finite, within the world's maxima and rate-limited
        // (clipped is set when the safety gate changed it). May be NULL.
        public IntPtr WriteWrench;
        public IntPtr UserData;
        // What the device renders stably at the haptic rate, as CHAI3D's cHapticDeviceInfo declares it: the
        // stiffest contact in N/m (>= 0; 0, the default: no limit) and the damping in N s/m it needs (>= 0,
        // default 0). The force it is handed never grows faster than maxStiffness per metre the tool moves,
        // and a constrained tool's coupling is no stiffer (docs/devices.md, "A device's limits").
        public double MaxStiffness;
        public double Damping;
        public int InternalValue;
        public int Reserved;
    }

    /// <summary>
    /// proxScriptedDeviceId: Every device of Proxima's (scripted, streamed, HID, XR) is made by its world,
    /// lives until its Destroy or its world's destruction, and is let go of the same way: Destroy closes it
    /// (stops its thread, if it has one), so a tool that holds it has no pose from then on and its force
    /// fades out, until the tool is given another device or NULL; its id is then invalid everywhere. Its ids
    /// carry a generation (the field `reserved`): copy them whole, never make one by hand. At most 4096
    /// devices of every kind together exist at once in the process (PROX_ERROR_CAPACITY beyond). The built-in
    /// scripted device: a tool moved along a path of poses, for tests, demos and replays.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct ScriptedDeviceId
    {
        // index + 1; 0 is null
        public uint Index1;
        // the slot's generation
        public uint Reserved;
        public WorldId World;
    }

    /// <summary>proxScriptedDeviceDef</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct ScriptedDeviceDef
    {
        // PROX_API_VERSION, set by proxDefaultScriptedDeviceDef()
        public int ApiVersion;
        // the path; copied
        public IntPtr Poses;
        // >= 1
        public int PoseCount;
        // start over after the last pose, or hold it
        public Bool32 Loop;
        // > 0: the device moves through the poses at this pace, interpolating
        public double SecondsPerPose;
        public int InternalValue;
        public int Reserved;
    }

    /// <summary>proxScriptedDeviceRecord: What the scripted device has been handed so far.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct ScriptedDeviceRecord
    {
        public ulong Reads;
        public ulong Writes;
        // poses into the path (fractional)
        public double Progress;
        // N: largest |force| written
        public double MaxForce;
        // N m: largest |torque| written
        public double MaxTorque;
        // N: largest |force change| between consecutive writes
        public double MaxForceStep;
        public Vec3 LastForce;
        public Vec3 LastTorque;
        // every value written was finite
        public Bool32 AllFinite;
        readonly int reserved;
    }

    /// <summary>
    /// proxStreamDeviceId: The device for engines, bindings and XR (docs/devices.md): the application pushes
    /// timestamped tool poses from a thread of its own at its own rate (a frame's 60-120 Hz), the haptic loop
    /// renders the pose at its 1 kHz from the latest samples, and the wrench it renders is read back from any
    /// thread (for a rumble or an XR vibration the application drives itself). Pushing and reading never
    /// lock, allocate or wait, and the haptic loop never waits on the pusher. Attach it to one tool with
    /// proxBody_SetDevice.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct StreamDeviceId
    {
        // index + 1; 0 is null
        public uint Index1;
        // the slot's generation
        public uint Reserved;
        public WorldId World;
    }

    /// <summary>proxStreamMode</summary>
    public enum StreamMode
    {
        /// <summary>the newest sample's pose</summary>
        Hold = 0,
        /// <summary>the pose `delay` ago, between the samples around it; holds past the newest</summary>
        Interpolate = 1,
        /// <summary>
        /// the pose now: between samples, or predicted from the newest two (at most maxExtrapolation past the
        /// newest, then held)
        /// </summary>
        Extrapolate = 2,
    }

    /// <summary>proxStreamDeviceDef</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct StreamDeviceSettings
    {
        // PROX_API_VERSION, set by proxDefaultStreamDeviceDef()
        readonly int apiVersion;
        // default PROX_STREAM_INTERPOLATE
        public StreamMode Mode;
        // s, >= 0: INTERPOLATE's latency (default 1/90: one 90 Hz frame)
        public double Delay;
        // s, >= 0: EXTRAPOLATE's furthest prediction past the newest sample (default 0.02)
        public double MaxExtrapolation;
        // s, > 0: nothing pushed for this long: no pose, the force fades out (default 0.05)
        public double StaleAfter;
        // What the device behind the stream renders stably, as proxDeviceDef.maxStiffness and damping say (0,
        // the default: no limit).
        public double MaxStiffness;
        public double Damping;
        readonly int internalValue;
        readonly int reserved;
    }

    /// <summary>proxStreamDeviceStats: What a streamed device saw. Counts since it was created.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct StreamDeviceStats
    {
        // accepted
        public ulong SamplesPushed;
        // no newer than the newest accepted: late (out of order) or duplicate
        public ulong SamplesDropped;
        // invalid (non-finite, zero quaternion, bad time): PROX_ERROR_INVALID_ARGUMENT
        public ulong SamplesRefused;
        // haptic ticks that asked for the pose
        public ulong Reads;
        // ... and got none: nothing pushed yet, or not for staleAfter
        public ulong StaleTicks;
        // ... rendered past the newest sample (EXTRAPOLATE: predicted; else held)
        public ulong ExtrapolatedTicks;
        // s, between accepted samples' times
        public double MeanSampleInterval;
        // s
        public double MaxSampleInterval;
        // s: the furthest a rendered pose was predicted past the newest sample
        public double MaxExtrapolation;
        // s: now minus the newest sample's time, at the last read
        public double LastSampleAge;
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern DeviceDef proxDefaultDeviceDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_SetDevice(BodyId tool, ref DeviceDef def);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, EntryPoint = "proxBody_SetDevice")]
        internal static extern Result proxBody_SetDeviceNull(BodyId tool, IntPtr def);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ScriptedDeviceDef proxDefaultScriptedDeviceDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_CreateScriptedDevice(WorldId world, ref ScriptedDeviceDef def, out ScriptedDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_LoadScriptedDevice(WorldId world, byte[] utf8Path, double secondsPerPose, Bool32 loop, out ScriptedDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxScriptedDevice_GetDeviceDef(ScriptedDeviceId device, out DeviceDef def);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxScriptedDevice_GetRecord(ScriptedDeviceId device, out ScriptedDeviceRecord record);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxScriptedDevice_Destroy(ScriptedDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Bool32 proxScriptedDevice_IsValid(ScriptedDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern double proxGetTime();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern StreamDeviceSettings proxDefaultStreamDeviceDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_CreateStreamDevice(WorldId world, ref StreamDeviceSettings def, out StreamDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxStreamDevice_PushPose(StreamDeviceId device, ref Pose pose, double timeSeconds);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxStreamDevice_GetWrench(StreamDeviceId device, out Wrench wrench);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxStreamDevice_GetDeviceDef(StreamDeviceId device, out DeviceDef def);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxStreamDevice_GetStats(StreamDeviceId device, out StreamDeviceStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxStreamDevice_Destroy(StreamDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Bool32 proxStreamDevice_IsValid(StreamDeviceId device);
    }
}
