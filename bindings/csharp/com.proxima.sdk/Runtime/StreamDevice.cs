using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>proxStreamDeviceDef: start from StreamDeviceSettings.Default.</summary>
    public partial struct StreamDeviceSettings
    {
        /// <summary>Every field at its default (proxDefaultStreamDeviceDef). Any thread.</summary>
        public static StreamDeviceSettings Default => Native.proxDefaultStreamDeviceDef();
    }

    /// <summary>The built-in streamed device (proxStreamDeviceId): how a game drives a tool
    /// at frame rate. A thread of yours pushes timestamped poses; the haptic loop renders
    /// the pose of each 1 kHz tick from them, with no managed code on the haptic thread
    /// (so a garbage collection cannot stall it); the wrench it rendered is read back
    /// from any thread. Attach it with Body.SetDevice; it lives until Destroy or its world's end.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct StreamDevice
    {
        internal readonly StreamDeviceId id;

        internal StreamDevice(StreamDeviceId id) { this.id = id; }

        /// <summary>Seconds on the steady clock PushPose's times are on (proxGetTime). Any thread.</summary>
        public static double Now => Native.proxGetTime();

        /// <summary>The tool's world pose at timeSeconds (on Now's clock: when the pose was
        /// or will be true). Any thread, one at a time (two at once: WrongThread); allocates
        /// nothing. A sample no newer than the newest accepted is dropped and counted, not
        /// an error; a non-finite pose, a zero quaternion or a bad time throws (InvalidArgument).</summary>
        public void PushPose(Pose pose, double timeSeconds) =>
            Native.Check(Native.proxStreamDevice_PushPose(id, ref pose, timeSeconds));

        /// <summary>The pose, true now.</summary>
        public void PushPose(Pose pose) => PushPose(pose, Now);

        /// <summary>The wrench the haptic loop last handed the device (zero before the first),
        /// never torn. Any thread.</summary>
        public Wrench GetWrench()
        {
            Native.Check(Native.proxStreamDevice_GetWrench(id, out Wrench w));
            return w;
        }

        /// <summary>Game thread.</summary>
        public StreamDeviceStats Stats
        {
            get { Native.Check(Native.proxStreamDevice_GetStats(id, out StreamDeviceStats s)); return s; }
        }

        /// <summary>Whether the device is alive (not destroyed, nor its world). Any thread.</summary>
        public bool IsValid => Native.proxStreamDevice_IsValid(id);

        /// <summary>Lets the device go: a tool it holds has no pose from then on (its force
        /// fades out); pushes from then on throw InvalidHandle. Game thread.</summary>
        public void Destroy() => Native.Check(Native.proxStreamDevice_Destroy(id));
    }
}
