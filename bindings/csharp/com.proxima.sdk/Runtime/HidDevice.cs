using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>proxHidDeviceDef without its path: start from HidDeviceSettings.Default.
    /// World.OpenHidDevice takes the path (or a HidDeviceInfo) beside it.</summary>
    public partial struct HidDeviceSettings
    {
        /// <summary>Every field at its default (proxDefaultHidDeviceDef). Any thread.</summary>
        public static HidDeviceSettings Default => HidDevice.Call(() => Native.proxDefaultHidDeviceDef());
    }

    /// <summary>proxHidDeviceInfo: a supported HID device present now (HidDevice.Enumerate).</summary>
    public partial struct HidDeviceInfo
    {
        /// <summary>Manufacturer and product.</summary>
        public string Name => Native.CString(name);
        /// <summary>May be empty.</summary>
        public string Serial => Native.CString(serial);
        /// <summary>What World.OpenHidDevice opens.</summary>
        public string Path => Native.CString(path);
        public override string ToString() => Name + " (" + VendorId.ToString("x4") + ":" + ProductId.ToString("x4") + ", " + Profile + ")";
    }

    /// <summary>A real HID device driving a tool (proxHidDeviceId, docs/devices.md): a
    /// SpaceMouse, a DualShock 4 or a DualSense. Its own native thread reads its
    /// reports, integrates the axes into the tool's pose and writes rumble back,
    /// with no managed code on the way. Open it with World.OpenHidDevice, attach it
    /// with Body.SetDevice; it lives until Destroy or its world's end. Present when
    /// the native library was built with PROX_WITH_HIDAPI (else Unsupported).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct HidDevice
    {
        internal readonly HidDeviceId id;

        internal HidDevice(HidDeviceId id) { this.id = id; }

        /// <summary>The supported devices present now. Any thread.</summary>
        public static HidDeviceInfo[] Enumerate()
        {
            for (;;)
            {
                int count = 0;
                Result r = Call(() => Native.proxEnumerateHidDevices(null, 0, out count));
                if (r != Result.Capacity) Native.Check(r);
                var infos = new HidDeviceInfo[count];
                if (count == 0) return infos;
                r = Native.proxEnumerateHidDevices(infos, count, out int found);
                if (r == Result.Capacity) continue;  // one was plugged in meanwhile: ask again
                Native.Check(r);
                if (found == count) return infos;
                var fewer = new HidDeviceInfo[found];
                Array.Copy(infos, fewer, found);
                return fewer;
            }
        }

        /// <summary>What the device did since it was opened. Game thread.</summary>
        public HidDeviceStats Stats
        {
            get { Native.Check(Native.proxHidDevice_GetStats(id, out HidDeviceStats s)); return s; }
        }

        /// <summary>The tool's pose as the device last integrated it. Game thread.</summary>
        public Pose Pose
        {
            get { Native.Check(Native.proxHidDevice_GetPose(id, out Pose p)); return p; }
        }

        /// <summary>Whether the device is open (not destroyed, nor its world). Any thread.</summary>
        public bool IsValid
        {
            get
            {
                HidDeviceId device = id;
                return Call(() => (bool)Native.proxHidDevice_IsValid(device));
            }
        }

        /// <summary>Stops its thread and closes it: a tool it holds has no pose from then on
        /// (its force fades out). Game thread.</summary>
        public void Destroy() => Native.Check(Native.proxHidDevice_Destroy(id));

        internal DeviceDef GetDeviceDef()
        {
            Native.Check(Native.proxHidDevice_GetDeviceDef(id, out DeviceDef def));
            return def;
        }

        internal static HidDevice Open(WorldId world, HidDeviceSettings settings, string path)
        {
            byte[] utf8 = path != null ? Native.Utf8(path, nameof(path)) : null;
            GCHandle pin = utf8 != null ? GCHandle.Alloc(utf8, GCHandleType.Pinned) : default(GCHandle);
            try
            {
                settings.path = utf8 != null ? pin.AddrOfPinnedObject() : IntPtr.Zero;
                HidDeviceId device = default(HidDeviceId);
                Native.Check(Call(() => Native.proxWorld_CreateHidDevice(world, ref settings, out device)));
                return new HidDevice(device);
            }
            finally
            {
                if (utf8 != null) pin.Free();
            }
        }

        // The HID functions are missing from a library built without hidapi:
        // the first call of one says so, instead of an EntryPointNotFoundException.
        internal static T Call<T>(Func<T> call)
        {
            try
            {
                return call();
            }
            catch (EntryPointNotFoundException e)
            {
                throw new ProximaException(Result.Unsupported,
                    "this native library has no HID devices: it was built without PROX_WITH_HIDAPI (" + e.Message + ")");
            }
        }

        public override string ToString() => "HidDevice(" + id.Index1 + "/" + id.Reserved + ")";
    }
}
