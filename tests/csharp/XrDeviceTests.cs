// The C# XrDevice end to end: an app (XrApp.cs, P/Invoke) makes its
// instance, session and actions through the real OpenXR loader, with the core
// validation layer, on the mock runtime of tests/openxr, and hands them to
// the binding; the device's thread locates the mock's scripted grip (the tool
// follows) and sends the contact force back as vibration (the mock logs it).
// Outside the Unity package, because it needs the loader and the mock: ctest
// csharp.openxr runs this assembly with XR_RUNTIME_JSON set.
using System;
using System.IO;
using System.Runtime.InteropServices;
using NUnit.Framework;

namespace Proxima.XrTests
{
    [TestFixture]
    public class XrDeviceTests
    {
        // OpenXR's world turned and moved in Proxima's, the tool offset in the grip:
        // a frame mixed up anywhere puts the tool elsewhere.
        static readonly Pose BaseToWorld = new Pose(new Vec3(0.3, -1.2, 0.1), Rigid.Axis(0, 1, 0, 90));
        static readonly Pose ToolInGrip = new Pose(new Vec3(0.02, 0, -0.05), Rigid.Axis(1, 0, 0, 30));

        sealed class Scene : IDisposable
        {
            public readonly World World = new World();
            public readonly Body Tool;
            public readonly double Width;

            public Scene()
            {
                string assets = Environment.GetEnvironmentVariable("PROXIMA_ASSETS");
                if (string.IsNullOrEmpty(assets)) Assert.Fail("PROXIMA_ASSETS is not set: it names the shared assets' directory");
                Mesh bunny = World.LoadMesh(Path.Combine(assets, "bunny.obj"));
                MeshInfo info = bunny.Info;
                Width = info.BoundsMax.X - info.BoundsMin.X;
                World.CreateBody(bunny, BodyType.Static, Pose.Identity);
                Tool = World.CreateBody(bunny, BodyType.Tool, Far);
            }

            public Pose Far => new Pose(new Vec3(1.6 * Width, 0, 0), Quat.Identity);
            public Pose Near => new Pose(new Vec3(0.9 * Width, 0, 0), Quat.Identity);  // a few mm off: contact

            public static Pose GripFor(Pose tool) =>
                Rigid.Compose(Rigid.Compose(Rigid.Inverse(BaseToWorld), tool), Rigid.Inverse(ToolInGrip));

            public double Force
            {
                get { Vec3 f = Tool.GetWrench().Force; return Math.Sqrt(f.X * f.X + f.Y * f.Y + f.Z * f.Z); }
            }

            public XrDevice Start(XrApp app, XrDeviceSettings settings)
            {
                settings.BaseToWorld = BaseToWorld;
                settings.ToolInGrip = ToolInGrip;
                settings.ForceForFullAmplitude = 1.0;
                XrDevice device = World.CreateXrDevice(settings);
                app.Device = device;
                Tool.SetDevice(device);
                World.StartThreads(ThreadSettings.Default);
                return device;
            }

            public void Dispose() => World.Dispose();
        }

        static XrApp FocusedApp()
        {
            var app = new XrApp();
            Assert.IsTrue(app.PumpUntil(() => app.State == Xr.Focused), "the session never became FOCUSED");
            return app;
        }

        static string ValidationErrors(long from)
        {
            string log = Environment.GetEnvironmentVariable("XR_CORE_VALIDATION_FILE_NAME");
            if (string.IsNullOrEmpty(log)) Assert.Fail("XR_CORE_VALIDATION_FILE_NAME is not set (ctest sets it)");
            if (!File.Exists(log)) return "";
            string text = File.ReadAllText(log);
            text = from < text.Length ? text.Substring((int)from) : "";
            return text.Contains("VALID_ERROR") ? text : "";
        }

        static long ValidationLogLength()
        {
            string log = Environment.GetEnvironmentVariable("XR_CORE_VALIDATION_FILE_NAME");
            return log != null && File.Exists(log) ? File.ReadAllText(log).Length : 0;
        }

        [TestCase(XrPoseMode.LocateEachTick)]
        [TestCase(XrPoseMode.ExtrapolateFrame)]
        public void TheGripMovesTheToolAndContactVibrates(XrPoseMode mode)
        {
            long logStart = ValidationLogLength();
            using (XrApp app = FocusedApp())
            using (var scene = new Scene())
            {
                MockXr.Hold(Scene.GripFor(scene.Far));
                XrDeviceSettings settings = app.Settings();
                settings.PoseMode = mode;
                XrDevice device = scene.Start(app, settings);
                Assert.IsTrue(device.IsValid);

                // The tool follows the grip to a turned, moved pose (the grip's floats: 1e-5).
                Pose target = Rigid.Compose(scene.Far, new Pose(new Vec3(0.05, -0.02, 0.03), Rigid.Axis(1, 1, 0, -40)));
                MockXr.Hold(Scene.GripFor(target));
                Assert.IsTrue(app.PumpUntil(() => Rigid.Error(scene.Tool.Pose, target) < 1e-5, 10),
                              Rigid.Error(scene.Tool.Pose, target) + " m from the script");
                app.PumpFor(0.1);
                Assert.Less(Rigid.Error(scene.Tool.Pose, target), 1e-5, "and stays there");
                XrDeviceStats far = device.Stats;
                Assert.Greater(far.PosesPushed, 0UL);
                Assert.Greater(far.Locates, 0UL);
                Assert.AreEqual(Xr.Focused, far.SessionState);
                Assert.AreEqual(XrTimeSource.Timespec, far.TimeSource);
                Assert.AreEqual(0UL, far.VibrationsSent, "vibrations while far from anything");

                // Into contact: the force comes back as vibration.
                int before = MockXr.VibrationCount();
                MockXr.Hold(Scene.GripFor(scene.Near));
                Assert.IsTrue(app.PumpUntil(() => scene.Force > 0 && MockXr.VibrationCount() > before + 5),
                              "no vibration in contact: force " + scene.Force + " N");
                MockXr.Vibration[] sent = MockXr.VibrationsSince(before);
                foreach (MockXr.Vibration v in sent)
                {
                    Assert.AreEqual(0, v.Stop, "a stop while in contact");
                    Assert.AreEqual(0, v.Result);
                    Assert.That(v.Amplitude > 0 && v.Amplitude <= 1, "amplitude " + v.Amplitude);
                    Assert.AreEqual(20000000L, v.Duration, "the default PulseDuration, 0.02 s");
                }
                XrDeviceStats stats = device.Stats;
                Assert.GreaterOrEqual(stats.VibrationsSent, (ulong)sent.Length);
                Assert.That(stats.LastAmplitude > 0 && stats.LastAmplitude <= 1);

                // Out of contact again: the vibration is stopped.
                MockXr.Hold(Scene.GripFor(scene.Far));
                Assert.IsTrue(app.PumpUntil(() => {
                    MockXr.Vibration[] v = MockXr.VibrationsSince(before);
                    return v.Length > 0 && v[v.Length - 1].Stop != 0;
                }), "no xrStopHapticFeedback after contact ended");
                scene.World.StopThreads();
                device.Destroy();
                Assert.IsFalse(device.IsValid);
            }
            Assert.AreEqual("", ValidationErrors(logStart));
        }

        [DllImport("libopenxr_loader.so.1")]
        static extern int xrLocateSpace(ulong space, ulong baseSpace, long time, byte[] location);

        [Test]
        public void TheValidationLayerIsOn()
        {
            // Else the other tests' "no validation error" would hold vacuously.
            long logStart = ValidationLogLength();
            using (XrApp app = FocusedApp())
            {
                var location = new byte[64];  // an XrSpaceLocation whose type is 0: wrong on purpose
                Assert.AreEqual(-1, xrLocateSpace(app.Local, app.Local, 1000, location), "XR_ERROR_VALIDATION_FAILURE");
            }
            StringAssert.Contains("VUID-XrSpaceLocation-type-type", ValidationErrors(logStart));
        }

        [Test]
        public void FocusLossIsForwarded()
        {
            using (XrApp app = FocusedApp())
            using (var scene = new Scene())
            {
                MockXr.Hold(Scene.GripFor(scene.Far));
                XrDevice device = scene.Start(app, app.Settings());
                app.PumpFor(0.2);
                MockXr.SetFocused(false);
                try
                {
                    Assert.IsTrue(app.PumpUntil(() => app.State == Xr.Visible));  // polled, forwarded
                    ulong ticks = device.Stats.NotFocusedTicks;
                    app.PumpFor(0.1);
                    Assert.AreEqual(Xr.Visible, device.Stats.SessionState);
                    Assert.Greater(device.Stats.NotFocusedTicks, ticks);
                }
                finally
                {
                    MockXr.SetFocused(true);  // the mock outlives the test
                }
                Assert.IsTrue(app.PumpUntil(() => device.Stats.SessionState == Xr.Focused));
                device.Destroy();
            }
        }

        [Test]
        public void ADestroyedDeviceRefusesCalls()
        {
            using (XrApp app = FocusedApp())
            {
                XrDevice device;
                using (var scene = new Scene())
                {
                    device = scene.Start(app, app.Settings());
                    device.Destroy();
                    Assert.IsFalse(device.IsValid);
                    XrDevice d = device;
                    Body tool = scene.Tool;
                    foreach (TestDelegate call in new TestDelegate[] {
                                 () => { var s = d.Stats; }, () => d.OnFrame(1, 1), () => d.OnRuntimeTime(1),
                                 () => d.OnSessionState(Xr.Focused), d.Destroy, () => tool.SetDevice(d) })
                    {
                        var e = Assert.Throws<ProximaException>(call);
                        Assert.AreEqual(Result.InvalidHandle, e.Result);
                        StringAssert.Contains("live XR device", e.Message);
                    }
                }
                Assert.IsFalse(device.IsValid, "gone with its world");
            }
        }

        [Test]
        public void BadHandlesAndSettingsAreRefused()
        {
            using (XrApp app = FocusedApp())
            using (var world = new World())
            {
                XrDeviceSettings good = app.Settings();
                Action<Func<XrDeviceSettings, XrDeviceSettings>, Result, string> Refused = (change, result, words) =>
                {
                    var e = Assert.Throws<ProximaException>(() => world.CreateXrDevice(change(good)));
                    Assert.AreEqual(result, e.Result, e.Message);
                    StringAssert.Contains(words, e.Message);
                };
                Refused(s => { s.Session = 0; return s; }, Result.InvalidArgument, "def->session");
                Refused(s => { s.GetInstanceProcAddr = IntPtr.Zero; return s; }, Result.InvalidArgument, "getInstanceProcAddr");
                // A vibration action where the pose action belongs: the runtime refuses its space.
                Refused(s => { s.PoseAction = app.HapticAction; return s; }, Result.InvalidArgument, "xrCreateActionSpace");
                Refused(s => { s.VibrationRate = 0; return s; }, Result.InvalidArgument, "vibrationRate");
                Refused(s => { s.PoseMode = (XrPoseMode)7; return s; }, Result.InvalidArgument, "poseMode");

                XrDevice device = world.CreateXrDevice(good);
                var bad = Assert.Throws<ProximaException>(() => device.OnSessionState(99));
                Assert.AreEqual(Result.InvalidArgument, bad.Result);
                StringAssert.Contains("XrSessionState", bad.Message);
                bad = Assert.Throws<ProximaException>(() => device.OnFrame(0, 1));
                StringAssert.Contains("predictedDisplayTime", bad.Message);
                device.Destroy();
            }
        }

        [Test]
        public void ActionHelpers()
        {
            using (XrApp app = FocusedApp())
            {
                IntPtr gipa = Xr.GetInstanceProcAddr;
                const string simple = "/interaction_profiles/khr/simple_controller";
                XrActionSuggestedBinding[] b = XrDevice.GetSuggestedBindings(gipa, app.Instance, simple, "/user/hand/right",
                                                                             app.PoseAction, app.HapticAction);
                Assert.AreEqual(2, b.Length);
                Assert.AreEqual(app.PoseAction, b[0].Action);
                Assert.AreEqual(app.Path("/user/hand/right/input/grip/pose"), b[0].Binding);
                Assert.AreEqual(app.HapticAction, b[1].Action);
                Assert.AreEqual(app.Path("/user/hand/right/output/haptic"), b[1].Binding);
                Assert.AreEqual(1, XrDevice.GetSuggestedBindings(gipa, app.Instance, simple, "left", app.PoseAction, 0).Length);

                var e = Assert.Throws<ProximaException>(() => XrDevice.GetSuggestedBindings(
                    gipa, app.Instance, "/interaction_profiles/acme/glove", "right", app.PoseAction, 0));
                Assert.AreEqual(Result.Unsupported, e.Result);
                StringAssert.Contains("/interaction_profiles/acme/glove", e.Message);
                // The app's set is attached already: the runtime refuses new actions.
                e = Assert.Throws<ProximaException>(() => XrDevice.CreateActions(
                    gipa, app.Instance, app.ActionSet, "late", out ulong pose, out ulong haptic));
                Assert.AreEqual(Result.InvalidArgument, e.Result);
                StringAssert.Contains("xrCreateAction", e.Message);
                Assert.Throws<ArgumentNullException>(() => XrDevice.CreateActions(
                    gipa, app.Instance, app.ActionSet, null, out ulong pose, out ulong haptic));
            }
        }
    }
}
