using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Threading;
using NUnit.Framework;

namespace Proxima.Tests
{
    /// <summary>The world's threads, devices written in C#, and the game-thread rule.</summary>
    [TestFixture]
    public class ThreadTests
    {
        World world;
        Mesh cube;
        Body rock, tool;

        // The tool cube 2 mm from the rock cube along +x: within the cutoff.
        static readonly Pose Near = new Pose(new Vec3(0.102, 0, 0), Quat.Identity);

        [SetUp]
        public void CreateScene()
        {
            world = new World();
            cube = Support.Cube(world);
            rock = world.CreateBody(cube, BodyType.Static, Pose.Identity);
            tool = world.CreateBody(cube, BodyType.Tool, Near);
        }

        [TearDown]
        public void DisposeWorld()
        {
            world.Dispose();
            Assert.AreEqual(0, Device.AttachedCount, "the world's devices were released");
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

        [Test]
        public void OtherThreadsAreRefused()
        {
            var calls = new Dictionary<string, Action>
            {
                { "Step", world.Step },
                { "CreateMesh", () => Support.Cube(world) },
                { "Pose", () => tool.Pose = Near },
                { "GetContacts", () => tool.GetContacts() },
                { "GetWrench", () => tool.GetWrench() },
                { "Info", () => { MeshInfo _ = cube.Info; } },
                { "StartThreads", () => world.StartThreads(ThreadSettings.Default) },
                { "Dispose", world.Dispose },
            };
            foreach (var call in calls)
            {
                var e = OnAnotherThread(call.Value) as ProximaException;
                Assert.IsNotNull(e, call.Key + " must throw ProximaException on another thread");
                Assert.AreEqual(Result.WrongThread, e.Result, call.Key);
                StringAssert.Contains("game thread", e.Message, call.Key);
            }
            Assert.IsTrue(world.IsValid, "nothing changed");
            Assert.IsNull(OnAnotherThread(() => Assert.IsTrue(world.IsValid)), "IsValid: any thread");
            Assert.IsNull(OnAnotherThread(() => { ThreadSettings _ = ThreadSettings.Default; }), "defaults: any thread");
            world.Step();
        }

        [Test]
        public void ThreadsRunAndToolsStayWhileTheyRun()
        {
            ThreadSettings settings = ThreadSettings.Default;
            settings.HapticTiming = HapticTiming.Sleep;
            world.StartThreads(settings);
            try
            {
                Support.Throws(Result.Busy, "already running", () => world.StartThreads(ThreadSettings.Default));
                Support.Throws(Result.Busy, "StopThreads", world.Step);
                // Meshes, bodies and tools come and go while the threads run, and a tool's mesh deforms.
                Mesh more = Support.Cube(world);
                Body block = world.CreateBody(more, BodyType.Static, new Pose(new Vec3(0, 1, 0), Quat.Identity));
                block.Destroy();
                Body second = world.CreateBody(more, BodyType.Tool, new Pose(new Vec3(0, -1, 0), Quat.Identity));
                more.GetTriangles(out double[] corners, out uint[] _);
                more.SetVertices(corners);
                second.Destroy();
                more.Destroy();
                tool.Pose = new Pose(new Vec3(0.1015, 0, 0), Quat.Identity);
                Thread.Sleep(200);
                Assert.IsTrue(world.GetThreadStats(ThreadRole.Haptic).Running);
                Assert.Greater(tool.GetContacts().Length, 0);
                Assert.Greater(tool.GetWrench().Force.X, 0.0);
            }
            finally
            {
                world.StopThreads();
            }
            foreach (ThreadRole role in new[] { ThreadRole.Haptic, ThreadRole.Local, ThreadRole.Global })
            {
                ThreadStats s = world.GetThreadStats(role);
                Assert.IsFalse(s.Running, role.ToString());
                Assert.Greater(s.Updates, 0UL, role.ToString());
            }
            ThreadSettings asked = ThreadSettings.Default;
            ThreadStats haptic = world.GetThreadStats(ThreadRole.Haptic);
            Assert.That(haptic.PinnedCore == -1 || haptic.PinnedCore == asked.HapticCore, "pinned where asked, or not at all");
            Assert.AreEqual(-1, world.GetThreadStats(ThreadRole.Global).PinnedCore);
            Assert.AreEqual(HapticTiming.Sleep, haptic.Timing, "as asked");
            Assert.AreEqual(0, haptic.RealtimePriority, "none asked");
            Assert.IsFalse(haptic.MemoryLocked, "not asked");
            Assert.GreaterOrEqual(haptic.PeriodP999, haptic.PeriodP99);
            Assert.AreEqual(1000.0, world.GetThreadStats(ThreadRole.Haptic).TargetRate);
            Support.Throws(Result.InvalidArgument, "thread", () => world.GetThreadStats((ThreadRole)3));
            Assert.DoesNotThrow(world.StopThreads, "no effect when stopped");
            world.Step();
        }

        [Test]
        public void BadThreadSettingsAreNamed()
        {
            ThreadSettings s = ThreadSettings.Default;
            s.HapticRate = -5;
            Support.Throws(Result.InvalidArgument, "haptic rate", () => world.StartThreads(s));
            s = ThreadSettings.Default;
            s.SpinMargin = -1;
            Support.Throws(Result.InvalidArgument, "spin margin", () => world.StartThreads(s));
            s = ThreadSettings.Default;
            s.HapticTiming = (HapticTiming)5;
            Support.Throws(Result.InvalidArgument, "hapticTiming", () => world.StartThreads(s));
            Support.Throws(Result.InvalidArgument, "proxDefaultThreadsDef", () => world.StartThreads(new ThreadSettings()));
        }

        [Test]
        public void ScriptedDeviceHoldsTheTool()
        {
            var path = new[] { new Pose(new Vec3(0.12, 0, 0), Quat.Identity), Near };
            ScriptedDevice device = world.CreateScriptedDevice(path, 0.2, false);
            tool.SetDevice(device);
            world.StartThreads(ThreadSettings.Default);
            Thread.Sleep(400);
            Support.Throws(Result.Busy, "device", () => tool.Pose = Near);
            // Devices change while the threads run: the old one is faded out first.
            tool.ClearDevice();
            tool.SetDevice(device);
            world.StopThreads();
            ScriptedDeviceRecord r = device.Record;
            Assert.Greater(r.Reads, 20UL, "the haptic loop read the device");
            Assert.Greater(r.Writes, 20UL);
            Assert.AreEqual(1.0, r.Progress, 1e-9, "held at the last pose");
            Assert.IsTrue(r.AllFinite);
            Assert.Greater(r.MaxForce, 0.0, "the tool reached the rock's field");
            Assert.AreEqual(Near.Position.X, tool.Pose.Position.X, 1e-9);
            tool.ClearDevice();
            tool.Pose = new Pose(new Vec3(0.2, 0, 0), Quat.Identity);

            Support.Throws(Result.InvalidArgument, "poseCount", () => world.CreateScriptedDevice(new Pose[0], 0.1, false));
            Support.Throws(Result.InvalidArgument, "secondsPerPose", () => world.CreateScriptedDevice(path, 0, false));
            Assert.Throws<ArgumentNullException>(() => world.CreateScriptedDevice(null, 0.1, false));
            Support.Throws(Result.File, "no-such-path.txt", () => world.LoadScriptedDevice("no-such-path.txt", 0.1, true));
            Support.Throws(Result.InvalidHandle, "device", () => { ScriptedDeviceRecord _ = default(ScriptedDevice).Record; });
        }

        [Test]
        public void TheFlightRecorderKeepsEveryTick()
        {
            var path = new[] { new Pose(new Vec3(0.12, 0, 0), Quat.Identity), Near };
            ScriptedDevice device = world.CreateScriptedDevice(path, 0.2, false);
            tool.SetDevice(device);
            Assert.AreEqual(0, tool.GetHapticTrace(16).Length, "never started: nothing recorded");
            ThreadSettings settings = ThreadSettings.Default;
            settings.TraceCapacity = 8192;
            world.StartThreads(settings);
            // Closed on the count, not on time: the path done and 300 ticks more.
            var clock = Stopwatch.StartNew();
            while ((device.Record.Progress < 1.0 || device.Record.Writes < 500) && clock.Elapsed.TotalSeconds < 60)
                Thread.Sleep(5);
            world.StopThreads();
            ScriptedDeviceRecord r = device.Record;
            HapticSample[] trace = tool.GetHapticTrace(8192);
            Assert.AreEqual((long)r.Writes, trace.Length, "every tick of the run, the fade-out included");
            double maxForce = 0;
            for (int i = 0; i < trace.Length; i++)
            {
                Assert.AreEqual((ulong)i, trace[i].Tick);
                if (i > 0) Assert.Greater(trace[i].Time, trace[i - 1].Time);
                Vec3 f = trace[i].Force;
                maxForce = Math.Max(maxForce, Math.Sqrt(f.X * f.X + f.Y * f.Y + f.Z * f.Z));
                Assert.LessOrEqual(trace[i].DevicePose.Position.X, 0.12 + 1e-12);
            }
            Assert.AreEqual(r.MaxForce, maxForce, 1e-12, "the device's largest force is the trace's");
            HapticSample last = trace[trace.Length - 1];
            Assert.AreEqual(0.0, last.Force.X);
            Assert.IsTrue((last.Flags & HapticFlags.Stopping) != 0);
            Assert.AreEqual(Near.Position.X, last.DevicePose.Position.X, 1e-12);
            var few = new HapticSample[4];
            Assert.AreEqual(4, tool.GetHapticTrace(few));
            Assert.AreEqual(last.Tick, few[3].Tick, "the newest, oldest first");
            Assert.Throws<ArgumentNullException>(() => tool.GetHapticTrace(null));
            settings.TraceCapacity = -1;
            Support.Throws(Result.InvalidArgument, "trace capacity", () => world.StartThreads(settings));
        }

        [Test]
        public void ScriptedDeviceFromAFile()
        {
            string file = System.IO.Path.GetTempFileName();
            System.IO.File.WriteAllText(file, "# x y z w x y z\n0.12 0 0 1 0 0 0\n0.102 0 0 1 0 0 0\n");
            try
            {
                ScriptedDevice device = world.LoadScriptedDevice(file, 0.1, true);
                tool.SetDevice(device);
                world.StartThreads(ThreadSettings.Default);
                Thread.Sleep(100);
                world.StopThreads();
                Assert.Greater(device.Record.Reads, 0UL);
            }
            finally
            {
                System.IO.File.Delete(file);
            }
        }

        /// <summary>A device that holds the tool still and notes when each tick came.</summary>
        sealed class StillDevice : Device
        {
            public readonly long[] ticks = new long[4000];
            public int reads, writes;
            public Wrench last;
            public Pose pose = Near;

            public override bool ReadPose(out Pose p)
            {
                int i = reads++;
                if (i < ticks.Length) ticks[i] = Stopwatch.GetTimestamp();
                p = pose;
                return true;
            }

            public override void WriteWrench(ref Wrench wrench)
            {
                ++writes;
                last = wrench;
            }
        }

        /// <summary>Runs the threads for a second with the device holding the tool, while
        /// `beside` runs on this thread; prints how the ticks came (recorded, not asserted:
        /// timing depends on the machine, docs/csharp.md).</summary>
        StillDevice RunForASecond(string label, Action<Stopwatch> beside)
        {
            var device = new StillDevice();
            tool.SetDevice(device);
            world.StartThreads(ThreadSettings.Default);
            var clock = Stopwatch.StartNew();
            beside(clock);
            world.StopThreads();

            int n = Math.Min(device.reads, device.ticks.Length);
            int late = 0;
            double worst = 0;
            for (int i = 1; i < n; ++i)
            {
                double ms = (device.ticks[i] - device.ticks[i - 1]) * 1000.0 / Stopwatch.Frequency;
                if (ms > 2.0) ++late;
                worst = Math.Max(worst, ms);
            }
            ThreadStats haptic = world.GetThreadStats(ThreadRole.Haptic);
            Console.WriteLine("managed device at 1 kHz for 1 s, {0}: {1} ticks, {2} late (> 2 ms), longest gap {3:F2} ms; " +
                              "haptic work per tick p50 {4:F1} us, p99 {5:F1} us",
                              label, device.reads, late, worst, haptic.UpdateP50 * 1e6, haptic.UpdateP99 * 1e6);
            Assert.Greater(device.reads, 100, "the haptic thread called the device");
            Assert.Greater(device.writes, 100);
            Assert.AreEqual(0L, device.Exceptions);
            Assert.IsFalse(double.IsNaN(device.last.Force.X) || double.IsInfinity(device.last.Force.X));
            Assert.AreEqual(world.GetThreadStats(ThreadRole.Haptic).Updates, (ulong)device.reads, 2.0,
                            "one read per haptic tick");
            return device;
        }

        /// <summary>Makes garbage and forces a full collection every 50 ms for a second;
        /// calls `each` between; returns the number of collections.</summary>
        static int CollectForASecond(Stopwatch clock, Action each)
        {
            int collections = 0;
            var keep = new List<byte[]>();
            while (clock.ElapsedMilliseconds < 1000)
            {
                for (int i = 0; i < 100; ++i) keep.Add(new byte[1024]);
                if (keep.Count > 5000) keep.Clear();
                if (clock.ElapsedMilliseconds / 50 > collections)
                {
                    GC.Collect();
                    ++collections;
                }
                each();
            }
            return collections;
        }

        [Test]
        public void ManagedDeviceAt1kHzBesideTheGarbageCollector()
        {
            // The same second three times, side by side: a managed device with this
            // thread asleep, then with it making garbage and collecting, then the
            // streamed device (no managed code on the haptic thread) beside the same.
            RunForASecond("this thread asleep", clock => Thread.Sleep(1000));
            int collections = 0;
            RunForASecond("beside 20 full collections", clock => collections = CollectForASecond(clock, () => { }));
            Assert.GreaterOrEqual(collections, 19);

            StreamDevice hand = world.CreateStreamDevice();
            tool.SetDevice(hand);
            world.StartThreads(ThreadSettings.Default);
            var watch = Stopwatch.StartNew();
            long lastPush = -1;
            CollectForASecond(watch, () =>
            {
                long ms = watch.ElapsedMilliseconds;
                if (ms / 10 == lastPush) return;
                lastPush = ms / 10;
                hand.PushPose(Near);
            });
            world.StopThreads();
            StreamDeviceStats stream = hand.Stats;
            ThreadStats haptic = world.GetThreadStats(ThreadRole.Haptic);
            Console.WriteLine("streamed device pushed at 100 Hz for 1 s beside full collections: {0} haptic ticks read it, " +
                              "{1} found it stale, haptic period max {2:F2} ms, {3} overruns; " +
                              "haptic work per tick p50 {4:F1} us, p99 {5:F1} us",
                              stream.Reads, stream.StaleTicks, haptic.PeriodMax * 1e3, haptic.Overruns,
                              haptic.UpdateP50 * 1e6, haptic.UpdateP99 * 1e6);
            Assert.Greater(stream.Reads, 100UL);
            Assert.Greater(stream.SamplesPushed, 10UL);
        }

        sealed class ThrowingDevice : Device
        {
            public int reads;
            public bool throwOnWrite;

            public override bool ReadPose(out Pose p)
            {
                p = Near;
                if (++reads % 2 == 0 && !throwOnWrite) throw new InvalidOperationException("device unplugged");
                return true;
            }

            public override void WriteWrench(ref Wrench wrench)
            {
                if (throwOnWrite) throw new InvalidOperationException("motor fault");
            }
        }

        [Test]
        public void ExceptionsInCallbacksAreCaught()
        {
            var device = new ThrowingDevice();
            tool.SetDevice(device);
            world.StartThreads(ThreadSettings.Default);
            Thread.Sleep(200);
            world.StopThreads();
            Assert.Greater(device.Exceptions, 10L);
            Assert.IsInstanceOf<InvalidOperationException>(device.LastException);
            Assert.AreEqual("device unplugged", device.LastException.Message);
            Assert.Greater(world.SafetyStats.InvalidPoses, 10UL, "a throwing ReadPose is no pose");

            var writer = new ThrowingDevice { throwOnWrite = true };
            tool.SetDevice(writer);
            Assert.AreEqual(1, Device.AttachedCount, "the first device was released");
            world.StartThreads(ThreadSettings.Default);
            Thread.Sleep(200);
            world.StopThreads();
            Assert.Greater(writer.Exceptions, 10L);
            Assert.AreEqual("motor fault", writer.LastException.Message);
        }

        [Test]
        public void DevicesAreReleased()
        {
            tool.SetDevice(new StillDevice());
            Assert.AreEqual(1, Device.AttachedCount);
            tool.ClearDevice();
            Assert.AreEqual(0, Device.AttachedCount);
            tool.SetDevice(new StillDevice());
            tool.Destroy();
            Assert.AreEqual(0, Device.AttachedCount, "destroying the tool releases its device");
            tool = world.CreateBody(cube, BodyType.Tool, Near);
            tool.SetDevice(new StillDevice());
            Support.Throws(Result.InvalidArgument, "PROX_BODY_TOOL", () => rock.SetDevice(new StillDevice()));
            Assert.AreEqual(1, Device.AttachedCount, "a refused device is not kept");
            Assert.Throws<ArgumentNullException>(() => tool.SetDevice((Device)null));
            // TearDown: disposing the world releases the last one.
        }

        [Test]
        public void SafetyStatsCountFaults()
        {
            var device = new StillDevice();
            device.pose = new Pose(new Vec3(double.NaN, 0, 0), Quat.Identity);
            tool.SetDevice(device);
            world.StartThreads(ThreadSettings.Default);
            Thread.Sleep(200);
            world.StopThreads();
            SafetyStats s = world.SafetyStats;
            Assert.Greater(s.InvalidPoses, 10UL);
            Assert.AreEqual(0UL, s.TornSnapshots);
            Assert.AreEqual(0.0, tool.GetWrench().Force.Length, "faded out");
        }
    }
}
