using System;
using NUnit.Framework;

namespace Proxima.Tests
{
    /// <summary>proxima_openxr.h's declarations (generated; no wrapper yet) against the
    /// library: the def's defaults by value, and a refusal with its message through
    /// a ref def. PROXIMA_WITH_OPENXR says whether the library has the OpenXR device
    /// (ctest sets it from PROX_WITH_OPENXR); without it the calls must be missing.</summary>
    [TestFixture]
    public class OpenXrTests
    {
        static bool LibraryHasOpenXr()
        {
            string v = Environment.GetEnvironmentVariable("PROXIMA_WITH_OPENXR");
            if (v != "1" && v != "0")
                Assert.Fail("PROXIMA_WITH_OPENXR must be 1 or 0: whether libproxima was built with PROX_WITH_OPENXR");
            return v == "1";
        }

        [Test]
        public void TheDefaultDefIsTheHeaders()
        {
            if (!LibraryHasOpenXr())
            {
                Assert.Throws<EntryPointNotFoundException>(() => Native.proxDefaultXrDeviceDef());
                return;
            }
            XrDeviceDef d = Native.proxDefaultXrDeviceDef();
            Assert.AreEqual(IntPtr.Zero, d.GetInstanceProcAddr);
            Assert.AreEqual(0UL, d.Instance);
            Assert.AreEqual(XrPoseMode.LocateEachTick, d.PoseMode);
            Assert.AreEqual(100.0, d.VibrationRate);
            Assert.AreEqual(5.0, d.ForceForFullAmplitude);
            Assert.AreEqual(5, d.SessionState, "XR_SESSION_STATE_FOCUSED");
            Assert.AreEqual(1000.0, d.TickRate);
            Assert.AreEqual(0.02, d.PulseDuration);
            Assert.AreEqual(0.05, d.MaxExtrapolation);
            Assert.AreEqual(Pose.Identity, d.ToolInGrip);
            Assert.AreEqual(0L, d.RuntimeTime);
        }

        [Test]
        public void ADefWithoutASessionIsRefused()
        {
            if (!LibraryHasOpenXr()) return;  // TheDefaultDefIsTheHeaders checked the calls are missing
            using (var world = new World())
            {
                XrDeviceDef d = Native.proxDefaultXrDeviceDef();
                Result r = Native.proxWorld_CreateXrDevice(world.id, ref d, out XrDeviceId device);
                Assert.AreEqual(Result.InvalidArgument, r);
                StringAssert.Contains("getInstanceProcAddr is NULL", ProximaException.FromLastError(r).Message);
                Assert.IsFalse((bool)Native.proxXrDevice_IsValid(device));
            }
        }
    }
}
