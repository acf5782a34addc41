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
        // Hz, (0, 250]: the most output reports a second (default 250)
        public double OutputRate;
        readonly int internalValue;
        readonly int reserved;
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
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxEnumerateHidDevices([Out] HidDeviceInfo[] infos, int capacity, out int count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern HidDeviceSettings proxDefaultHidDeviceDef();
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
