// Generated from sdk/include/proxima/proxima_hid.h by bindings/csharp/tools/gen_native.py:
// do not edit. Regenerate with `python3 bindings/csharp/tools/gen_native.py`
// (docs/csharp.md); ctest csharp.generated fails while this file is stale.
using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>proxHidProfile: How a device's reports are read (the table of known ids: docs/devices.md).</summary>
    public enum HidProfile
    {
        None = 0,
        /// <summary>SpaceNavigator and siblings: report 1 translation, 2 rotation, 3 buttons</summary>
        SpaceMouseSplit = 1,
        /// <summary>SpaceMouse Wireless and newer: report 1 with all six axes</summary>
        SpaceMouseCombined = 2,
        /// <summary>Sony DualShock 4 (USB)</summary>
        DualShock4 = 3,
        /// <summary>Sony DualSense (USB)</summary>
        DualSense = 4,
        /// <summary>HID PID force feedback, recognised from the report descriptor: two force axes (a stick)</summary>
        PidJoystick = 5,
        /// <summary>one force axis (a wheel base)</summary>
        PidWheel = 6,
    }

    /// <summary>proxHidDeviceInfo: A supported device present now. Strings are UTF-8 and NUL-terminated (cut to fit).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct HidDeviceInfo
    {
        public ushort VendorId;
        public ushort ProductId;
        public HidProfile Profile;
        public int InterfaceNumber;
        public ushort UsagePage;
        public ushort Usage;
        // manufacturer and product
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 128)] internal byte[] name;
        // may be empty
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 64)] internal byte[] serial;
        // for proxHidDeviceDef.path
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 256)] internal byte[] path;
    }

    /// <summary>proxHidDeviceId</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct HidDeviceId
    {
        // index + 1; 0 is null
        public uint Index1;
        // the slot's generation
        public uint Reserved;
        public WorldId World;
    }

    /// <summary>proxHidDeviceDef</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct HidDeviceSettings
    {
        // PROX_API_VERSION, set by proxDefaultHidDeviceDef()
        readonly int apiVersion;
        // a proxHidDeviceInfo.path, or NULL: the first supported device matching ...
        internal IntPtr path;
        // ... these ids (0: any)
        public ushort VendorId;
        // ... these ids (0: any)
        public ushort ProductId;
        // the tool's pose at open, and where the re-centre button puts it
        public Pose InitialPose;
        // in the tool's frame: the point rotations turn about
        public Vec3 ReferencePoint;
        // m/s at full deflection, >= 0 (default 0.1)
        public double LinearSpeed;
        // rad/s at full deflection, >= 0 (default 1.0)
        public double AngularSpeed;
        // [0, 0.9]: the fraction of each axis's travel ignored about rest (default 0.1)
        public double DeadZone;
        // [1, 5]: past the dead zone, the rescaled deflection to this power (default 2)
        public double ResponseExponent;
        // rotates the device's frame (x right, y up, z towards the user) into the world's
        public Quat DeviceToWorld;
        // N, > 0: the force at which rumble is full (default 3)
        public double RumbleForce;
        // N, > 0: the force at which the DualSense trigger's resistance is full (default 3)
        public double TriggerForce;
        // Hz, (0, 250]: the most output reports a second (default 250; a PID device sends at most one report
        // a millisecond, whatever this says)
        public double OutputRate;
        // Force-feedback (PID) devices. Position control: the tool's travel at full deflection about
        // initialPose along the device frame's x (the stick's X, right) and z (its Y, towards the user), in
        // m; for a wheel, its turn about the device frame's z, in rad. 0 (default): 0.1 m, or 1 rad.
        public double Workspace;
        // N (N m for a wheel) at full magnitude, > 0 (default 5): the magnitude a PID device takes is a
        // fraction of what the device is set to.
        public double MaxForce;
        // The sign of the force on each device axis, the stick's X and Y: 1 as DirectInput pushes, -1 the
        // other way, 0 (default) the firmware's known convention (the Arduino library's is -1, every other
        // +1).
        public int ForceSignX;
        // The sign of the force on each device axis, the stick's X and Y: 1 as DirectInput pushes, -1 the
        // other way, 0 (default) the firmware's known convention (the Arduino library's is -1, every other
        // +1).
        public int ForceSignY;
        // What the device renders stably, as proxDeviceDef.maxStiffness and damping say (N/m and N s/m; 0,
        // the default: no limit, no damping). A force-feedback stick's firmware and motor decide it: measure
        // it.
        public double MaxStiffness;
        public double Damping;
        readonly int internalValue;
        readonly int reserved;
    }

    /// <summary>proxHidForceEffect: Where a PID device's constant-force effect is.</summary>
    public enum HidForceEffect
    {
        /// <summary>not a PID device, or not created yet</summary>
        None = 0,
        /// <summary>created, started and renewed</summary>
        Playing = 1,
        /// <summary>the device had no free effect block: input only</summary>
        Full = 2,
        /// <summary>the device could not create it: input only</summary>
        Error = 3,
        /// <summary>Block Load never answered: input only</summary>
        NoAnswer = 4,
        /// <summary>stopped and freed (closed, or unplugged)</summary>
        Stopped = 5,
    }

    /// <summary>proxHidDeviceStats: What a HID device did. Counts since it was opened.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct HidDeviceStats
    {
        public HidProfile Profile;
        // open and answering now
        public Bool32 Connected;
        // input reports decoded
        public ulong ReportsRead;
        // input reports ignored: unknown id, too short or too long
        public ulong Malformed;
        // output reports written
        public ulong OutputsWritten;
        // output reports the device refused
        public ulong FailedWrites;
        // times it stopped answering (unplugged)
        public ulong Disconnects;
        // times it was found again and reopened
        public ulong Reconnects;
        // haptic ticks that asked for the pose
        public ulong PoseReads;
        // ... and got none (disconnected or closed)
        public ulong NoPoseTicks;
        // s since the last input report (-1 before the first)
        public double LastReportAge;
        // PID devices: Set Constant Force reports written
        public ulong ForceUpdates;
        // constant-force effects created (one more at each reconnection)
        public ulong EffectsCreated;
        // the last magnitude sent, a fraction of maxForce in [-1, 1]
        public double LastForceMagnitude;
        // the largest |magnitude| sent, in [0, 1]
        public double MaxForceMagnitude;
        public HidForceEffect ForceEffect;
        readonly int reserved;
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxEnumerateHidDevices([Out] HidDeviceInfo[] infos, int capacity, out int count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern HidDeviceSettings proxDefaultHidDeviceDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_CreateHidDevice(WorldId world, ref HidDeviceSettings def, out HidDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_OpenHidDevice(WorldId world, ref HidDeviceSettings def, out HidDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxHidDevice_GetDeviceDef(HidDeviceId device, out DeviceDef def);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxHidDevice_GetStats(HidDeviceId device, out HidDeviceStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxHidDevice_GetPose(HidDeviceId device, out Pose pose);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxHidDevice_Destroy(HidDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxHidDevice_Close(HidDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Bool32 proxHidDevice_IsValid(HidDeviceId device);
    }
}
