using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>A body of a world (proxBodyId): a mesh at a pose. A value, copy it
    /// freely; Contact.Other is one. A destroyed body's value stays invalid forever.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct Body : IEquatable<Body>
    {
        internal readonly BodyId id;

        internal Body(BodyId id) { this.id = id; }

        public bool IsNull => id.Index1 == 0;

        /// <summary>Whether the body is alive in a live world. Game thread: false from any other.</summary>
        public bool IsValid => Native.proxBody_IsValid(id);

        /// <summary>Static bodies do not move. While the threads run: a tool's pose is the
        /// one the haptic loop last read, and setting a held tool's pose is refused (Busy).</summary>
        public Pose Pose
        {
            get { Native.Check(Native.proxBody_GetPose(id, out Pose p)); return p; }
            set { Native.Check(Native.proxBody_SetPose(id, ref value)); }
        }

        /// <summary>Where the tool is rendered and its contacts are computed: a constrained
        /// tool's proxy (Pose is its device pose), a free tool's pose.</summary>
        public Pose ProxyPose
        {
            get { Native.Check(Native.proxBody_GetProxyPose(id, out Pose p)); return p; }
        }

        public void Destroy()
        {
            Native.Check(Native.proxBody_Destroy(id));
            Device.Release(id);
        }

        /// <summary>The flight recorder's newest ticks (ThreadSettings.TraceCapacity), at most
        /// buffer.Length, oldest first, into the caller's buffer; returns how many. Game thread.</summary>
        public int GetHapticTrace(HapticSample[] buffer)
        {
            if (buffer == null) throw new ArgumentNullException(nameof(buffer));
            Native.Check(Native.proxBody_GetHapticTrace(id, buffer, buffer.Length, out int count));
            return count;
        }

        /// <summary>The flight recorder's newest ticks, at most maxSamples, in a new array.</summary>
        public HapticSample[] GetHapticTrace(int maxSamples)
        {
            var buffer = new HapticSample[maxSamples];
            int n = GetHapticTrace(buffer);
            if (n < buffer.Length) Array.Resize(ref buffer, n);
            return buffer;
        }

        /// <summary>The tool's contacts after the last step (while the threads run: local
        /// tracking's latest), in a new array.</summary>
        public Contact[] GetContacts() => GetContacts(out ContactPatch[] _);

        /// <summary>Fills the caller's array without allocating and returns how many
        /// contacts there are. When that is more than buffer.Length, the buffer holds
        /// the first buffer.Length of them (no exception: compare the count).</summary>
        public int GetContacts(Contact[] buffer)
        {
            if (buffer == null) throw new ArgumentNullException(nameof(buffer));
            Result r = Native.GetContacts(id, buffer, out int count);
            if (r != Result.Success && r != Result.Capacity) throw ProximaException.FromLastError(r);
            return count;
        }

        /// <summary>The tool's contacts with each one's patch beside it (patches[i] is
        /// contacts[i]'s), from one snapshot, in new arrays.</summary>
        public Contact[] GetContacts(out ContactPatch[] patches)
        {
            for (;;)
            {
                Result r = Native.GetContactPatches(id, null, null, out int count);
                if (r != Result.Success && r != Result.Capacity) throw ProximaException.FromLastError(r);
                var contacts = new Contact[count];
                patches = new ContactPatch[count];
                if (count == 0) return contacts;
                r = Native.GetContactPatches(id, contacts, patches, out int filled);
                // Only the threads can change the count between the two calls.
                if (r == Result.Capacity) continue;
                Native.Check(r);
                if (filled == count) return contacts;
                Array.Resize(ref contacts, filled);
                Array.Resize(ref patches, filled);
                return contacts;
            }
        }

        /// <summary>Fills the caller's arrays (either may be null) without allocating and
        /// returns how many contacts there are; as GetContacts(buffer), up to the shorter
        /// array's length.</summary>
        public int GetContacts(Contact[] buffer, ContactPatch[] patches)
        {
            if (buffer == null && patches == null) throw new ArgumentNullException(nameof(patches));
            Result r = Native.GetContactPatches(id, buffer, patches, out int count);
            if (r != Result.Success && r != Result.Capacity) throw ProximaException.FromLastError(r);
            return count;
        }

        /// <summary>Force and torque on the tool after the last step (while the threads
        /// run: what the haptic loop last handed the device).</summary>
        public Wrench GetWrench()
        {
            Native.Check(Native.proxBody_GetWrench(id, out Wrench w));
            return w;
        }

        /// <summary>Where the tool's surface crosses other bodies', at the current poses:
        /// computed on this call.</summary>
        public Polyline[] GetIntersections()
        {
            for (;;)
            {
                Result r = Native.proxBody_GetIntersections(id, IntPtr.Zero, 0, out int pointCount, IntPtr.Zero, 0,
                                                            out int lineCount);
                if (r != Result.Success && r != Result.Capacity) throw ProximaException.FromLastError(r);
                if (lineCount == 0) return new Polyline[0];
                var points = new Vec3[pointCount];
                var lines = new PolylineInfo[lineCount];
                r = Native.GetIntersections(id, points, out int pointsOut, lines, out int linesOut);
                if (r == Result.Capacity) continue;
                Native.Check(r);
                var result = new Polyline[linesOut];
                for (int i = 0; i < linesOut; ++i)
                {
                    var line = new Vec3[lines[i].PointCount];
                    Array.Copy(points, lines[i].FirstPoint, line, 0, line.Length);
                    result[i] = new Polyline(new Body(lines[i].Other), line, lines[i].Closed);
                }
                return result;
            }
        }

        /// <summary>The figures of the last GetIntersections on this tool.</summary>
        public IntersectionStats IntersectionStats
        {
            get { Native.Check(Native.proxBody_GetIntersectionStats(id, out IntersectionStats s)); return s; }
        }

        /// <summary>The exact minimum distance to another body of the world at the current
        /// poses: 0 when they touch or cross, -1 when farther than maxDistance.</summary>
        public double DistanceTo(Body other, double maxDistance = double.PositiveInfinity)
        {
            Native.Check(Native.proxBody_GetDistance(id, other.id, maxDistance, out double d));
            return d;
        }

        /// <summary>Lets a managed device hold this tool while the threads run. Its
        /// callbacks run on the haptic thread (see Device). Refused (Busy) while they run.</summary>
        public void SetDevice(Device device)
        {
            if (device == null) throw new ArgumentNullException(nameof(device), "use ClearDevice() to detach");
            Device.Attach(id, device);
        }

        /// <summary>Lets the built-in scripted device hold this tool.</summary>
        public void SetDevice(ScriptedDevice device)
        {
            Native.Check(Native.proxScriptedDevice_GetDeviceDef(device.id, out DeviceDef def));
            Native.Check(Native.proxBody_SetDevice(id, ref def));
            Device.Release(id);
        }

        /// <summary>Lets a streamed device hold this tool: the poses pushed to it move the tool.</summary>
        public void SetDevice(StreamDevice device)
        {
            Native.Check(Native.proxStreamDevice_GetDeviceDef(device.id, out DeviceDef def));
            Native.Check(Native.proxBody_SetDevice(id, ref def));
            Device.Release(id);
        }

        /// <summary>Lets a HID device hold this tool: its sticks or puck move the tool.</summary>
        public void SetDevice(HidDevice device)
        {
            DeviceDef def = device.GetDeviceDef();
            Native.Check(Native.proxBody_SetDevice(id, ref def));
            Device.Release(id);
        }

        /// <summary>Lets an XR controller hold this tool: its grip moves the tool, the force
        /// comes back as its vibration.</summary>
        public void SetDevice(XrDevice device)
        {
            DeviceDef def = device.GetDeviceDef();
            Native.Check(Native.proxBody_SetDevice(id, ref def));
            Device.Release(id);
        }

        /// <summary>No device holds the tool: Pose moves it.</summary>
        public void ClearDevice()
        {
            Native.Check(Native.proxBody_SetDeviceNull(id, IntPtr.Zero));
            Device.Release(id);
        }

        public bool Equals(Body o) =>
            id.Index1 == o.id.Index1 && id.Generation == o.id.Generation &&
            id.World.Index1 == o.id.World.Index1 && id.World.Generation == o.id.World.Generation;
        public override bool Equals(object obj) => obj is Body b && Equals(b);
        public override int GetHashCode() => (int)(id.Index1 * 31 + id.Generation) ^ (int)(id.World.Index1 << 20);
        public static bool operator ==(Body a, Body b) => a.Equals(b);
        public static bool operator !=(Body a, Body b) => !a.Equals(b);
        public override string ToString() => "Body(" + id.Index1 + "/" + id.Generation + ")";
    }
}
