// A headless OpenXR app for XrDeviceTests.cs, as a C# integrator without
// Unity writes one: P/Invoke into the real OpenXR loader
// (libopenxr_loader.so.1), which XR_RUNTIME_JSON (set by ctest) points at
// the mock runtime of tests/openxr, with the core validation layer on. It
// owns the instance, the session, the LOCAL space and an action set into
// which Proxima's actions are merged (XrDevice.CreateActions,
// GetSuggestedBindings); it polls events, forwarding session states to the
// device it was handed, and runs the frame loop: tests/openxr/xr_app.cpp in
// C#. MockXr is the mock's control panel (mock_control.h) through its
// proxMockXr_* exports.
using System;
using System.Diagnostics;
using System.IO;
using System.Runtime.InteropServices;
using System.Text.RegularExpressions;
using System.Threading;

namespace Proxima.XrTests
{
    static class Xr
    {
        const string Loader = "libopenxr_loader.so.1";
        // OpenXR 1.0's values (openxr.h).
        internal const int TypeInstance = 3, TypeSystem = 4, TypeSession = 8, TypeBegin = 10, TypeFrameEnd = 12,
                           TypeEventBuffer = 16, TypeStateChanged = 18, TypeActionSet = 28, TypeReferenceSpace = 37,
                           TypeFrameState = 44, TypeSuggested = 51, TypeAttach = 60, TypeSync = 61;
        internal const int EventUnavailable = 4;
        internal const int Ready = 2, Visible = 4, Focused = 5, Stopping = 6;

        [StructLayout(LayoutKind.Sequential)]
        internal struct ApplicationInfo
        {
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 128)] public byte[] ApplicationName;
            public uint ApplicationVersion;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 128)] public byte[] EngineName;
            public uint EngineVersion;
            public ulong ApiVersion;
        }
        [StructLayout(LayoutKind.Sequential)]
        internal struct InstanceCreateInfo
        {
            public int Type; public IntPtr Next; public ulong CreateFlags; public ApplicationInfo Application;
            public uint LayerCount; public IntPtr LayerNames; public uint ExtensionCount; public IntPtr ExtensionNames;
        }
        [StructLayout(LayoutKind.Sequential)]
        internal struct SystemGetInfo { public int Type; public IntPtr Next; public int FormFactor; }
        [StructLayout(LayoutKind.Sequential)]
        internal struct ActionSetCreateInfo
        {
            public int Type; public IntPtr Next;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 64)] public byte[] Name;
            [MarshalAs(UnmanagedType.ByValArray, SizeConst = 128)] public byte[] LocalizedName;
            public uint Priority;
        }
        [StructLayout(LayoutKind.Sequential)]
        internal struct ProfileSuggestedBinding
        {
            public int Type; public IntPtr Next; public ulong Profile; public uint Count; public IntPtr Bindings;
        }
        [StructLayout(LayoutKind.Sequential)]
        internal struct SessionCreateInfo { public int Type; public IntPtr Next; public ulong Flags; public ulong System; }
        [StructLayout(LayoutKind.Sequential)]
        internal struct Posef { public float Qx, Qy, Qz, Qw, Px, Py, Pz; }
        [StructLayout(LayoutKind.Sequential)]
        internal struct ReferenceSpaceCreateInfo { public int Type; public IntPtr Next; public int SpaceType; public Posef Pose; }
        [StructLayout(LayoutKind.Sequential)]
        internal struct AttachInfo { public int Type; public IntPtr Next; public uint Count; public IntPtr Sets; }
        [StructLayout(LayoutKind.Sequential)]
        internal struct SessionBeginInfo { public int Type; public IntPtr Next; public int ViewConfiguration; }
        [StructLayout(LayoutKind.Sequential)]
        internal struct FrameState { public int Type; public IntPtr Next; public long Time; public long Period; public uint ShouldRender; }
        [StructLayout(LayoutKind.Sequential)]
        internal struct ActiveActionSet { public ulong Set; public ulong Subaction; }
        [StructLayout(LayoutKind.Sequential)]
        internal struct SyncInfo { public int Type; public IntPtr Next; public uint Count; public IntPtr Sets; }
        [StructLayout(LayoutKind.Sequential)]
        internal struct FrameEndInfo
        {
            public int Type; public IntPtr Next; public long DisplayTime; public int BlendMode; public uint LayerCount;
            public IntPtr Layers;
        }

        [DllImport(Loader)] internal static extern int xrCreateInstance(ref InstanceCreateInfo info, out ulong instance);
        [DllImport(Loader)] internal static extern int xrGetSystem(ulong instance, ref SystemGetInfo info, out ulong system);
        [DllImport(Loader)] internal static extern int xrCreateActionSet(ulong instance, ref ActionSetCreateInfo info, out ulong set);
        [DllImport(Loader)] internal static extern int xrStringToPath(ulong instance, byte[] path, out ulong xrPath);
        [DllImport(Loader)] internal static extern int xrSuggestInteractionProfileBindings(ulong instance, ref ProfileSuggestedBinding s);
        [DllImport(Loader)] internal static extern int xrCreateSession(ulong instance, ref SessionCreateInfo info, out ulong session);
        [DllImport(Loader)] internal static extern int xrCreateReferenceSpace(ulong session, ref ReferenceSpaceCreateInfo info, out ulong space);
        [DllImport(Loader)] internal static extern int xrAttachSessionActionSets(ulong session, ref AttachInfo info);
        [DllImport(Loader)] internal static extern int xrPollEvent(ulong instance, IntPtr eventBuffer);
        [DllImport(Loader)] internal static extern int xrBeginSession(ulong session, ref SessionBeginInfo info);
        [DllImport(Loader)] internal static extern int xrEndSession(ulong session);
        [DllImport(Loader)] internal static extern int xrWaitFrame(ulong session, IntPtr info, ref FrameState state);
        [DllImport(Loader)] internal static extern int xrBeginFrame(ulong session, IntPtr info);
        [DllImport(Loader)] internal static extern int xrSyncActions(ulong session, ref SyncInfo info);
        [DllImport(Loader)] internal static extern int xrEndFrame(ulong session, ref FrameEndInfo info);
        [DllImport(Loader)] internal static extern int xrDestroySpace(ulong space);
        [DllImport(Loader)] internal static extern int xrDestroySession(ulong session);
        [DllImport(Loader)] internal static extern int xrDestroyActionSet(ulong set);
        [DllImport(Loader)] internal static extern int xrDestroyInstance(ulong instance);

        [DllImport("libdl.so.2")] static extern IntPtr dlopen(string file, int mode);
        [DllImport("libdl.so.2")] static extern IntPtr dlsym(IntPtr handle, string name);

        internal static IntPtr Symbol(string library, string name)
        {
            IntPtr lib = dlopen(library, 2);  // RTLD_NOW: the copy already loaded, when it is
            if (lib == IntPtr.Zero) throw new InvalidOperationException("dlopen " + library + " failed");
            IntPtr f = dlsym(lib, name);
            if (f == IntPtr.Zero) throw new InvalidOperationException(library + " has no " + name);
            return f;
        }

        // What an integrator hands Proxima (Unity: OpenXRFeature.xrGetInstanceProcAddr).
        internal static IntPtr GetInstanceProcAddr => Symbol(Loader, "xrGetInstanceProcAddr");

        internal static void Check(int result, string what)
        {
            if (result < 0) throw new InvalidOperationException(what + " failed: XrResult " + result);
        }

        internal static byte[] Chars(string s, int size)
        {
            var b = new byte[size];
            System.Text.Encoding.UTF8.GetBytes(s, 0, s.Length, b, 0);
            return b;
        }
    }

    /// <summary>The mock runtime's control panel (mock_control.h): the library the loader
    /// loads (the manifest's library_path), whose proxMockXr_* functions it exports.</summary>
    static class MockXr
    {
        [StructLayout(LayoutKind.Sequential)]
        internal struct Key { public long Time; public Xr.Posef Pose; }
        [StructLayout(LayoutKind.Sequential)]
        internal struct Vibration
        {
            public long Time; public int Stop; public float Amplitude; public long Duration; public float Frequency;
            public int Result;
        }

        [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate void SetScriptFn(ref Key keys, int count);
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate void SetIntFn(int value);
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int VibrationsFn(IntPtr out_, int first, int capacity);
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate long NowFn();

        static string library;
        static SetScriptFn setScript;
        static SetIntFn setFocused;
        static VibrationsFn vibrations;
        static NowFn now;

        /// <summary>Loads the mock named by XR_RUNTIME_JSON's manifest (before the loader does).</summary>
        internal static void Load()
        {
            if (library != null) return;
            string manifest = Environment.GetEnvironmentVariable("XR_RUNTIME_JSON");
            if (string.IsNullOrEmpty(manifest) || !File.Exists(manifest))
                throw new InvalidOperationException("XR_RUNTIME_JSON must name the mock OpenXR runtime's manifest " +
                                                    "(tests/openxr/mock_runtime.json in the build; ctest sets it)");
            Match m = Regex.Match(File.ReadAllText(manifest), "\"library_path\"\\s*:\\s*\"([^\"]+)\"");
            if (!m.Success) throw new InvalidOperationException(manifest + " has no library_path");
            library = m.Groups[1].Value;
            setScript = Marshal.GetDelegateForFunctionPointer<SetScriptFn>(Xr.Symbol(library, "proxMockXr_SetScript"));
            setFocused = Marshal.GetDelegateForFunctionPointer<SetIntFn>(Xr.Symbol(library, "proxMockXr_SetFocused"));
            vibrations = Marshal.GetDelegateForFunctionPointer<VibrationsFn>(Xr.Symbol(library, "proxMockXr_Vibrations"));
            now = Marshal.GetDelegateForFunctionPointer<NowFn>(Xr.Symbol(library, "proxMockXr_Now"));
        }

        internal static long Now() => now();
        internal static void SetFocused(bool focused) => setFocused(focused ? 1 : 0);

        /// <summary>The grip at `grip` (in the runtime's world) from now on.</summary>
        internal static void Hold(Pose grip)
        {
            var key = new Key { Time = now(), Pose = Rigid.ToXr(grip) };
            setScript(ref key, 1);
        }

        internal static int VibrationCount() => vibrations(IntPtr.Zero, 0, 0);

        internal static Vibration[] VibrationsSince(int first)
        {
            int count = Math.Max(0, VibrationCount() - first);
            var all = new Vibration[count];
            int size = Marshal.SizeOf(typeof(Vibration));
            IntPtr buffer = Marshal.AllocHGlobal(Math.Max(1, count) * size);
            try
            {
                vibrations(buffer, first, count);
                for (int i = 0; i < count; ++i)
                    all[i] = Marshal.PtrToStructure<Vibration>(buffer + i * size);
            }
            finally
            {
                Marshal.FreeHGlobal(buffer);
            }
            return all;
        }
    }

    /// <summary>Poses composed and inverted (Proxima's Pose has no operators).</summary>
    static class Rigid
    {
        internal static Quat Mul(Quat a, Quat b) => new Quat(
            a.W * b.W - a.X * b.X - a.Y * b.Y - a.Z * b.Z, a.W * b.X + a.X * b.W + a.Y * b.Z - a.Z * b.Y,
            a.W * b.Y - a.X * b.Z + a.Y * b.W + a.Z * b.X, a.W * b.Z + a.X * b.Y - a.Y * b.X + a.Z * b.W);
        static Quat Conj(Quat q) => new Quat(q.W, -q.X, -q.Y, -q.Z);
        static Vec3 Rotate(Quat q, Vec3 v)
        {
            Quat r = Mul(Mul(q, new Quat(0, v.X, v.Y, v.Z)), Conj(q));
            return new Vec3(r.X, r.Y, r.Z);
        }
        internal static Pose Compose(Pose a, Pose b) =>
            new Pose(a.Position + Rotate(a.Rotation, b.Position), Mul(a.Rotation, b.Rotation));
        internal static Pose Inverse(Pose a)
        {
            Quat c = Conj(a.Rotation);
            return new Pose(-1.0 * Rotate(c, a.Position), c);
        }
        internal static Quat Axis(double x, double y, double z, double degrees)
        {
            double n = Math.Sqrt(x * x + y * y + z * z), h = degrees * Math.PI / 360, s = Math.Sin(h) / n;
            return new Quat(Math.Cos(h), x * s, y * s, z * s);
        }
        internal static Xr.Posef ToXr(Pose p) => new Xr.Posef {
            Qx = (float)p.Rotation.X, Qy = (float)p.Rotation.Y, Qz = (float)p.Rotation.Z, Qw = (float)p.Rotation.W,
            Px = (float)p.Position.X, Py = (float)p.Position.Y, Pz = (float)p.Position.Z };
        // How far `now` is from `expected` (m; the rotation's error as the distance it moves a point at 1 m).
        internal static double Error(Pose now, Pose expected)
        {
            Vec3 d = now.Position - expected.Position;
            Quat q = now.Rotation, e = expected.Rotation;
            double dot = Math.Min(1.0, Math.Abs(q.W * e.W + q.X * e.X + q.Y * e.Y + q.Z * e.Z));
            return Math.Max(Math.Sqrt(d.X * d.X + d.Y * d.Y + d.Z * d.Z), 2 * Math.Acos(dot));
        }
    }

    sealed class XrApp : IDisposable
    {
        public ulong Instance, Session, Local, ActionSet, Right, PoseAction, HapticAction;
        public int State;
        public XrDevice? Device;
        bool running;
        readonly IntPtr eventBuffer = Marshal.AllocHGlobal(4016);  // XrEventDataBuffer

        public XrApp()
        {
            MockXr.Load();
            string[] extensions = { "XR_MND_headless", "XR_KHR_convert_timespec_time" };
            IntPtr[] names = Array.ConvertAll(extensions, Marshal.StringToHGlobalAnsi);
            GCHandle namesPin = GCHandle.Alloc(names, GCHandleType.Pinned);
            try
            {
                var ci = new Xr.InstanceCreateInfo {
                    Type = Xr.TypeInstance,
                    Application = new Xr.ApplicationInfo { ApplicationName = Xr.Chars("proxima-csharp-tests", 128),
                                                           EngineName = new byte[128], ApiVersion = 1UL << 48 },
                    ExtensionCount = (uint)names.Length, ExtensionNames = namesPin.AddrOfPinnedObject() };
                Xr.Check(Xr.xrCreateInstance(ref ci, out Instance), "xrCreateInstance");
            }
            finally
            {
                namesPin.Free();
                foreach (IntPtr n in names) Marshal.FreeHGlobal(n);
            }
            var si = new Xr.SystemGetInfo { Type = Xr.TypeSystem, FormFactor = 1 };
            Xr.Check(Xr.xrGetSystem(Instance, ref si, out ulong system), "xrGetSystem");
            var ai = new Xr.ActionSetCreateInfo { Type = Xr.TypeActionSet, Name = Xr.Chars("gameplay", 64),
                                                  LocalizedName = Xr.Chars("Gameplay", 128) };
            Xr.Check(Xr.xrCreateActionSet(Instance, ref ai, out ActionSet), "xrCreateActionSet");
            Right = Path("/user/hand/right");
            // Proxima's actions in the app's set, their bindings merged into the app's suggestion.
            XrDevice.CreateActions(Xr.GetInstanceProcAddr, Instance, ActionSet, "proxima", out PoseAction, out HapticAction);
            const string profile = "/interaction_profiles/khr/simple_controller";
            XrActionSuggestedBinding[] ours = XrDevice.GetSuggestedBindings(Xr.GetInstanceProcAddr, Instance, profile,
                                                                            "right", PoseAction, HapticAction);
            GCHandle pin = GCHandle.Alloc(ours, GCHandleType.Pinned);
            try
            {
                var s = new Xr.ProfileSuggestedBinding { Type = Xr.TypeSuggested, Profile = Path(profile),
                                                         Count = (uint)ours.Length, Bindings = pin.AddrOfPinnedObject() };
                Xr.Check(Xr.xrSuggestInteractionProfileBindings(Instance, ref s), "xrSuggestInteractionProfileBindings");
            }
            finally
            {
                pin.Free();
            }
            var sci = new Xr.SessionCreateInfo { Type = Xr.TypeSession, System = system };  // headless: no graphics
            Xr.Check(Xr.xrCreateSession(Instance, ref sci, out Session), "xrCreateSession");
            var ri = new Xr.ReferenceSpaceCreateInfo { Type = Xr.TypeReferenceSpace, SpaceType = 2,  // LOCAL
                                                       Pose = new Xr.Posef { Qw = 1 } };
            Xr.Check(Xr.xrCreateReferenceSpace(Session, ref ri, out Local), "xrCreateReferenceSpace");
            ulong[] sets = { ActionSet };
            GCHandle setsPin = GCHandle.Alloc(sets, GCHandleType.Pinned);
            try
            {
                var attach = new Xr.AttachInfo { Type = Xr.TypeAttach, Count = 1, Sets = setsPin.AddrOfPinnedObject() };
                Xr.Check(Xr.xrAttachSessionActionSets(Session, ref attach), "xrAttachSessionActionSets");
            }
            finally
            {
                setsPin.Free();
            }
        }

        public ulong Path(string path)
        {
            Xr.Check(Xr.xrStringToPath(Instance, Xr.Chars(path, path.Length + 1), out ulong p), "xrStringToPath");
            return p;
        }

        /// <summary>XrDeviceSettings.Default with this app's objects for the right hand.</summary>
        public XrDeviceSettings Settings()
        {
            XrDeviceSettings s = XrDeviceSettings.Default;
            s.GetInstanceProcAddr = Xr.GetInstanceProcAddr;
            s.Instance = Instance;
            s.Session = Session;
            s.BaseSpace = Local;
            s.PoseAction = PoseAction;
            s.HapticAction = HapticAction;
            s.SubactionPath = Right;
            s.TimespecTime = true;
            s.SessionState = State;
            return s;
        }

        /// <summary>Polls events (forwarding states to Device), then, while the session
        /// runs, one frame: wait, begin, sync, OnFrame, end.</summary>
        public void Frame()
        {
            for (;;)
            {
                Marshal.WriteInt32(eventBuffer, Xr.TypeEventBuffer);
                Marshal.WriteIntPtr(eventBuffer, 8, IntPtr.Zero);
                int r = Xr.xrPollEvent(Instance, eventBuffer);
                Xr.Check(r, "xrPollEvent");
                if (r == Xr.EventUnavailable) break;
                if (Marshal.ReadInt32(eventBuffer) != Xr.TypeStateChanged) continue;
                State = Marshal.ReadInt32(eventBuffer, 24);  // XrEventDataSessionStateChanged.state
                long time = Marshal.ReadInt64(eventBuffer, 32);
                if (Device.HasValue)
                {
                    Device.Value.OnSessionState(State);
                    if (time > 0) Device.Value.OnRuntimeTime(time);
                }
                if (State == Xr.Ready)
                {
                    var begin = new Xr.SessionBeginInfo { Type = Xr.TypeBegin, ViewConfiguration = 2 };
                    Xr.Check(Xr.xrBeginSession(Session, ref begin), "xrBeginSession");
                    running = true;
                }
                else if (State == Xr.Stopping)
                {
                    Xr.Check(Xr.xrEndSession(Session), "xrEndSession");
                    running = false;
                }
            }
            if (!running)
            {
                Thread.Sleep(10);
                return;
            }
            var fs = new Xr.FrameState { Type = Xr.TypeFrameState };
            Xr.Check(Xr.xrWaitFrame(Session, IntPtr.Zero, ref fs), "xrWaitFrame");
            Xr.Check(Xr.xrBeginFrame(Session, IntPtr.Zero), "xrBeginFrame");
            var active = new[] { new Xr.ActiveActionSet { Set = ActionSet } };
            GCHandle pin = GCHandle.Alloc(active, GCHandleType.Pinned);
            try
            {
                var sync = new Xr.SyncInfo { Type = Xr.TypeSync, Count = 1, Sets = pin.AddrOfPinnedObject() };
                Xr.Check(Xr.xrSyncActions(Session, ref sync), "xrSyncActions");
            }
            finally
            {
                pin.Free();
            }
            if (Device.HasValue) Device.Value.OnFrame(fs.Time, fs.Period);
            var end = new Xr.FrameEndInfo { Type = Xr.TypeFrameEnd, DisplayTime = fs.Time, BlendMode = 1 };  // OPAQUE
            Xr.Check(Xr.xrEndFrame(Session, ref end), "xrEndFrame");
        }

        public bool PumpUntil(Func<bool> done, double seconds = 20)
        {
            var clock = Stopwatch.StartNew();
            while (clock.Elapsed.TotalSeconds < seconds)
            {
                Frame();
                if (done()) return true;
            }
            return false;
        }

        public void PumpFor(double seconds) => PumpUntil(() => false, seconds);

        public void Dispose()
        {
            if (Instance == 0) return;
            Xr.xrDestroySpace(Local);
            Xr.xrDestroySession(Session);
            Xr.xrDestroyActionSet(ActionSet);
            Xr.xrDestroyInstance(Instance);
            Instance = 0;
            Marshal.FreeHGlobal(eventBuffer);
        }
    }
}
