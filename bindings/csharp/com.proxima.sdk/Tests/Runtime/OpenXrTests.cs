using System;
using NUnit.Framework;

namespace Proxima.Tests
{
    /// <summary>proxima_openxr.h's declarations and XrDevice against the library: the
    /// settings' defaults by value, and a refusal with its message (the device end
    /// to end, on the real loader and the mock runtime: tests/csharp/XrDeviceTests.cs). PROXIMA_WITH_OPENXR says whether the library has the OpenXR device
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
                var e = Assert.Throws<ProximaException>(() => { var s = XrDeviceSettings.Default; });
                Assert.AreEqual(Result.Unsupported, e.Result);
                StringAssert.Contains("PROX_WITH_OPENXR", e.Message);
                return;
            }
            XrDeviceSettings d = XrDeviceSettings.Default;
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
                XrDeviceSettings d = XrDeviceSettings.Default;
                Result r = Native.proxWorld_CreateXrDevice(world.id, ref d, out XrDeviceId device);
                Assert.AreEqual(Result.InvalidArgument, r);
                StringAssert.Contains("getInstanceProcAddr is NULL", ProximaException.FromLastError(r).Message);
                Assert.IsFalse((bool)Native.proxXrDevice_IsValid(device));

                // The wrapper: the same refusal, as an exception with the library's words.
                var e = Assert.Throws<ProximaException>(() => world.CreateXrDevice(XrDeviceSettings.Default));
                Assert.AreEqual(Result.InvalidArgument, e.Result);
                StringAssert.Contains("getInstanceProcAddr is NULL", e.Message);
            }
        }

        [Test]
        public void ADeviceThatIsNoneRefusesCalls()
        {
            if (!LibraryHasOpenXr()) return;
            XrDevice none = default(XrDevice);
            Assert.IsFalse(none.IsValid);
            var e = Assert.Throws<ProximaException>(() => { var s = none.Stats; });
            Assert.AreEqual(Result.InvalidHandle, e.Result);
            StringAssert.Contains("null id", e.Message);
            e = Assert.Throws<ProximaException>(() => none.OnFrame(1, 1));
            Assert.AreEqual(Result.InvalidHandle, e.Result);
        }
    }
}
