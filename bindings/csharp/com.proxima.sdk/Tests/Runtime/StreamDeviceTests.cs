using System;
using System.Threading;
using NUnit.Framework;

namespace Proxima.Tests
{
    /// <summary>The streamed device: poses pushed from a thread of the game's, the wrench
    /// read back from another, misuse.</summary>
    [TestFixture]
    public class StreamDeviceTests
    {
        World world;
        Mesh cube;
        Body rock, tool;

        [SetUp]
        public void CreateScene()
        {
            world = new World();
            cube = Support.Cube(world);
            rock = world.CreateBody(cube, BodyType.Static, Pose.Identity);
            tool = world.CreateBody(cube, BodyType.Tool, new Pose(new Vec3(0.2, 0, 0), Quat.Identity));
        }

        [TearDown]
        public void DisposeWorld() { world.Dispose(); }

        static Pose At(double x) => new Pose(new Vec3(x, 0, 0), Quat.Identity);

        [Test]
        public void DefaultsAreTheLibrarys()
        {
            StreamDeviceSettings s = StreamDeviceSettings.Default;
            Assert.AreEqual(StreamMode.Interpolate, s.Mode);
            Assert.AreEqual(1.0 / 90, s.Delay, 1e-12);
            Assert.AreEqual(0.02, s.MaxExtrapolation, 1e-12);
            Assert.AreEqual(0.05, s.StaleAfter, 1e-12);
            double t0 = StreamDevice.Now;
            Thread.Sleep(20);
            double t1 = StreamDevice.Now;
            Assert.Greater(t1 - t0, 0.015, "seconds, steady");
            Assert.Less(t1 - t0, 1.0);
        }

        [Test]
        public void PosesPushedFromAGameThreadMoveTheTool()
        {
            StreamDevice hand = world.CreateStreamDevice();
            tool.SetDevice(hand);
            world.StartThreads(ThreadSettings.Default);
            // A thread of the game's pushes the approach at 100 Hz for 0.6 s, from
            // 2 cm away to 1.5 mm away; another reads the wrench meanwhile.
            int pushes = 0;
            double felt = 0;
            Exception failed = null;
            var pusher = new Thread(() =>
            {
                try
                {
                    for (int i = 0; i <= 60; ++i)
                    {
                        hand.PushPose(At(0.12 - (0.12 - 0.1015) * i / 60.0));
                        ++pushes;
                        Thread.Sleep(10);
                    }
                }
                catch (Exception e) { failed = e; }
            });
            var reader = new Thread(() =>
            {
                try
                {
                    while (pusher.IsAlive)
                    {
                        felt = Math.Max(felt, hand.GetWrench().Force.X);
                        Thread.Sleep(1);
                    }
                }
                catch (Exception e) { failed = e; }
            });
            pusher.Start();
            reader.Start();
            pusher.Join();
            reader.Join();
            Thread.Sleep(50);
            Pose held = tool.Pose;
            world.StopThreads();

            Assert.IsNull(failed, failed?.ToString());
            Assert.Greater(felt, 0.0, "the wrench read from another thread pushed the tool away (+x)");
            Assert.AreEqual(0.1015, held.Position.X, 1e-6, "the tool is where the last sample put it");
            StreamDeviceStats s = hand.Stats;
            Assert.AreEqual((ulong)pushes, s.SamplesPushed);
            Assert.AreEqual(0UL, s.SamplesRefused);
            Assert.Greater(s.Reads, 50UL, "the haptic loop read it");
            Assert.Greater(s.MeanSampleInterval, 0.009, "pushed at 100 Hz");
            Assert.Less(s.MeanSampleInterval, 0.1);
        }

        [Test]
        public void BadSamplesAreRefusedAndLateOnesDropped()
        {
            StreamDevice hand = world.CreateStreamDevice();
            double now = StreamDevice.Now;
            hand.PushPose(At(0.15), now);
            hand.PushPose(At(0.14), now - 0.01);
            hand.PushPose(At(0.14), now);
            Support.Throws(Result.InvalidArgument, "pose->position is not finite",
                           () => hand.PushPose(At(double.NaN), now + 1));
            Support.Throws(Result.InvalidArgument, "zero quaternion",
                           () => hand.PushPose(new Pose(Vec3.Zero, default(Quat)), now + 1));
            Support.Throws(Result.InvalidArgument, "timeSeconds", () => hand.PushPose(At(0.15), -1));
            Support.Throws(Result.InvalidArgument, "timeSeconds", () => hand.PushPose(At(0.15), double.PositiveInfinity));
            StreamDeviceStats s = hand.Stats;
            Assert.AreEqual(1UL, s.SamplesPushed);
            Assert.AreEqual(2UL, s.SamplesDropped, "the late one and the duplicate");
            Assert.AreEqual(4UL, s.SamplesRefused);
        }

        [Test]
        public void PushingAllocatesNothing()
        {
            StreamDevice hand = world.CreateStreamDevice();
            double t = StreamDevice.Now;
            hand.PushPose(At(0.15), t);
            long before = GC.GetTotalMemory(false);
            for (int i = 1; i <= 10000; ++i)
            {
                hand.PushPose(At(0.15), t + i * 1e-3);
                hand.GetWrench();
            }
            Assert.Less(GC.GetTotalMemory(false) - before, 64 * 1024, "bytes allocated by 10000 pushes and reads");
            Assert.AreEqual(10001UL, hand.Stats.SamplesPushed);
        }

        [Test]
        public void MisuseIsNamed()
        {
            StreamDeviceSettings s = StreamDeviceSettings.Default;
            s.Delay = -1;
            Support.Throws(Result.InvalidArgument, "def->delay", () => world.CreateStreamDevice(s));
            s = StreamDeviceSettings.Default;
            s.Mode = (StreamMode)7;
            Support.Throws(Result.InvalidArgument, "def->mode", () => world.CreateStreamDevice(s));
            Support.Throws(Result.InvalidArgument, "proxDefaultStreamDeviceDef",
                           () => world.CreateStreamDevice(new StreamDeviceSettings()));
            Support.Throws(Result.InvalidHandle, "null id", () => default(StreamDevice).PushPose(At(0.1)));
            Support.Throws(Result.InvalidHandle, "null id", () => default(StreamDevice).GetWrench());
            StreamDevice hand = world.CreateStreamDevice();
            Support.Throws(Result.InvalidArgument, "PROX_BODY_TOOL", () => rock.SetDevice(hand));
            var e = OnAnotherThread(() => { StreamDeviceStats _ = hand.Stats; }) as ProximaException;
            Assert.AreEqual(Result.WrongThread, e?.Result, "Stats: game thread");
            Assert.IsNull(OnAnotherThread(() => hand.PushPose(At(0.15))), "PushPose: any thread");
            Assert.IsNull(OnAnotherThread(() => hand.GetWrench()), "GetWrench: any thread");
            world.Dispose();
            Support.Throws(Result.InvalidHandle, "", () => hand.PushPose(At(0.15)));
            Support.Throws(Result.InvalidHandle, "", () => hand.GetWrench());
        }

        static Exception OnAnotherThread(Action call)
        {
            Exception caught = null;
            var t = new Thread(() =>
            {
                try { call(); }
                catch (Exception e) { caught = e; }
            });
            t.Start();
            t.Join();
            return caught;
        }
    }
}
