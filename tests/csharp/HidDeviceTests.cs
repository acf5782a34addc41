// The C# HidDevice on an emulated DualSense: real hidapi in libproxima on
// hidraw nodes umockdev makes from the device's real report descriptor
// (tests/hid/emulated_hid.h). Outside the Unity package, because it needs the
// emulator: ctest csharp.hid runs this assembly under proxima_hid_emulate,
// which plugs in one DualSense and queues one report, the left stick held
// fully left.
using System;
using System.Diagnostics;
using System.Threading;
using NUnit.Framework;

namespace Proxima.HidTests
{
    [TestFixture]
    public class HidDeviceTests
    {
        static readonly Pose Start = new Pose(new Vec3(0.3, 0, 0), Quat.Identity);

        static Mesh Cube(World world)
        {
            const double h = 0.05;
            var positions = new[] { -h, -h, -h, h, -h, -h, h, h, -h, -h, h, -h, -h, -h, h, h, -h, h, h, h, h, -h, h, h };
            var indices = new uint[] { 0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                       3, 6, 2, 3, 7, 6, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5 };
            return world.CreateMesh(positions, indices);
        }

        [Test]
        public void EnumerateFindsTheDualSense()
        {
            HidDeviceInfo[] found = HidDevice.Enumerate();
            Assert.AreEqual(1, found.Length, "the emulator plugs in one device");
            Assert.AreEqual(HidProfile.DualSense, found[0].Profile);
            Assert.AreEqual(0x054c, found[0].VendorId);
            Assert.AreEqual(0x0ce6, found[0].ProductId);
            StringAssert.StartsWith("/dev/hidraw", found[0].Path);
            Assert.IsNotEmpty(found[0].Name);
        }

        [Test]
        public void TheStickMovesAToolItHolds()
        {
            using (var world = new World())
            {
                Mesh cube = Cube(world);
                world.CreateBody(cube, BodyType.Static, Pose.Identity);
                Body tool = world.CreateBody(cube, BodyType.Tool, Start);
                HidDeviceSettings settings = HidDeviceSettings.Default;
                Assert.AreEqual(0.1, settings.LinearSpeed, 1e-12, "the header's default");
                settings.InitialPose = Start;
                HidDevice pad = world.CreateHidDevice(settings, HidDevice.Enumerate()[0].Path);
                Assert.IsTrue(pad.IsValid);
                tool.SetDevice(pad);
                world.StartThreads(ThreadSettings.Default);
                // The queued report is read once the device is open; from then on the
                // held stick moves the tool at 0.1 m/s. Wait on what happened, with a
                // bound only against a hang.
                var clock = Stopwatch.StartNew();
                HidDeviceStats stats = pad.Stats;
                while ((stats.ReportsRead < 1 || tool.Pose.Position.X > Start.Position.X - 0.005) &&
                       clock.Elapsed.TotalSeconds < 120)
                {
                    Thread.Sleep(5);
                    stats = pad.Stats;
                }
                Pose moved = tool.Pose;
                world.StopThreads();
                Assert.AreEqual(1, stats.ReportsRead);
                Assert.AreEqual(0, stats.Malformed);
                Assert.IsTrue(stats.Connected);
                Assert.AreEqual(HidProfile.DualSense, stats.Profile);
                Assert.Greater(stats.PoseReads, 0);
                Assert.Less(moved.Position.X, Start.Position.X - 0.005, "the tool moved left");
                Assert.AreEqual(0.0, moved.Position.Y);
                Assert.AreEqual(0.0, moved.Position.Z);
                Assert.Less(pad.Pose.Position.X, Start.Position.X - 0.005, "the device's own pose too");
                pad.Destroy();
                Assert.IsFalse(pad.IsValid);
                var e = Assert.Throws<ProximaException>(() => { var s = pad.Stats; });
                Assert.AreEqual(Result.InvalidHandle, e.Result);
            }
        }

        [Test]
        public void ANodeThatIsNotThereIsAFileError()
        {
            using (var world = new World())
            {
                var e = Assert.Throws<ProximaException>(() => world.OpenHidDevice(HidDeviceSettings.Default, "/dev/hidraw9"));
                Assert.AreEqual(Result.File, e.Result, e.Message);
                e = Assert.Throws<ProximaException>(() => world.CreateHidDevice(HidDeviceSettings.Default, "/dev/hidraw9"));
                Assert.AreEqual(Result.File, e.Result, e.Message);
            }
        }
    }
}
