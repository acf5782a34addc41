using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>How a world finds contacts and turns them into forces.</summary>
    public sealed class WorldSettings
    {
        public Method Method = Method.Precise;
        /// <summary>The force curve's preset; its cutoff is used unless Cutoff is set, and then its
        /// safety distance and decay length scale with the cutoff.</summary>
        public ForcePreset Force = ForcePreset.Hard;
        /// <summary>m: contacts farther apart are not wanted (> 0). NaN: the preset's.</summary>
        public double Cutoff = double.NaN;
        /// <summary>Replaces the preset's force settings when set.</summary>
        public ForceSettings? CustomForce;
        /// <summary>Threads the game thread's own heavy work (deforming meshes, Step's
        /// searches) is split over, itself included, in [1, 256]; the results are the same
        /// whatever the count.</summary>
        public int WorkerCount = 1;
    }

    /// <summary>A world of meshes and bodies (proxWorldId). The thread that creates
    /// it is its game thread: every call on it, its meshes and bodies must come
    /// from there (else ProximaException with Result.WrongThread). Dispose it on
    /// that thread too: a finalizer cannot, so an undisposed world is never freed.</summary>
    public sealed class World : IDisposable
    {
        internal WorldId id;

        public World() : this(new WorldSettings()) { }

        public World(WorldSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            Version.Check();
            WorldDef def = Native.proxDefaultWorldDef();
            def.Method = settings.Method;
            Native.Check(Native.proxGetForcePreset(settings.Force, out def.Force, out def.Cutoff));
            if (!double.IsNaN(settings.Cutoff))
            {
                // A preset is a shape relative to its cutoff: the library scales it to
                // another (as the CLI's --cutoff does). A cutoff that is none is left for
                // proxCreateWorld to name.
                if (settings.Cutoff > 0.0 && !double.IsInfinity(settings.Cutoff))
                    Native.Check(Native.proxGetForcePresetAt(settings.Force, settings.Cutoff, out def.Force));
                def.Cutoff = settings.Cutoff;
            }
            if (settings.CustomForce.HasValue) def.Force = settings.CustomForce.Value;
            def.WorkerCount = settings.WorkerCount;
            Native.Check(Native.proxCreateWorld(ref def, out id));
        }

        /// <summary>Whether the world is alive (not disposed). Any thread.</summary>
        public bool IsValid => Native.proxWorld_IsValid(id);

        /// <summary>Destroys the world and everything in it, stopping its threads first
        /// (the devices fade out). Game thread. A second call does nothing.</summary>
        public void Dispose()
        {
            if (!Native.proxWorld_IsValid(id)) return;
            Native.Check(Native.proxWorld_Destroy(id));
            Device.ReleaseAll(id);
        }

        /// <summary>A mesh from arrays (copied): x, y, z per vertex, three indices per
        /// triangle, counter-clockwise seen from outside.</summary>
        public Mesh CreateMesh(double[] positions, uint[] indices)
        {
            if (positions == null) throw new ArgumentNullException(nameof(positions));
            if (indices == null) throw new ArgumentNullException(nameof(indices));
            if (positions.Length % 3 != 0)
                throw new ArgumentException("positions has " + positions.Length +
                                            " values, not three per vertex", nameof(positions));
            if (indices.Length % 3 != 0)
                throw new ArgumentException("indices has " + indices.Length +
                                            " values, not three per triangle", nameof(indices));
            GCHandle p = GCHandle.Alloc(positions, GCHandleType.Pinned);
            GCHandle i = GCHandle.Alloc(indices, GCHandleType.Pinned);
            try
            {
                MeshDef def = Native.proxDefaultMeshDef();
                def.Positions = p.AddrOfPinnedObject();
                def.VertexCount = (uint)(positions.Length / 3);
                def.Indices = i.AddrOfPinnedObject();
                def.TriangleCount = (uint)(indices.Length / 3);
                Native.Check(Native.proxWorld_CreateMesh(id, ref def, out MeshId mesh));
                return new Mesh(mesh);
            }
            finally
            {
                p.Free();
                i.Free();
            }
        }

        /// <summary>A mesh from an OBJ, glTF (.gltf) or binary glTF (.glb) file.</summary>
        public Mesh LoadMesh(string path)
        {
            Native.Check(Native.proxWorld_LoadMesh(id, Native.Utf8(path, nameof(path)), out MeshId mesh));
            return new Mesh(mesh);
        }

        /// <summary>A mesh from a file's bytes already in memory (a TextAsset's bytes, an
        /// asset bundle, a download): name is the file's name, whose extension says the
        /// format (.obj, .gltf, .glb) and which errors name. A .gltf must embed its
        /// buffers; nothing is read from disk.</summary>
        public Mesh LoadMesh(byte[] data, string name)
        {
            if (data == null) throw new ArgumentNullException(nameof(data));
            Native.Check(Native.proxWorld_LoadMeshFromMemory(id, data, (ulong)data.LongLength,
                                                             Native.Utf8(name, nameof(name)), out MeshId mesh));
            return new Mesh(mesh);
        }

        /// <summary>A body: the mesh at a pose. Tools get contacts and forces, with
        /// torques about referencePoint (in the body's frame).</summary>
        public Body CreateBody(Mesh mesh, BodyType type, Pose pose, Vec3 referencePoint = default(Vec3))
        {
            BodyDef def = Native.proxDefaultBodyDef();
            def.Mesh = mesh.id;
            def.Type = type;
            def.Pose = pose;
            def.ReferencePoint = referencePoint;
            Native.Check(Native.proxWorld_CreateBody(id, ref def, out BodyId body));
            return new Body(body);
        }

        /// <summary>A constrained tool (docs/coupling.md): its proxy follows the device pose
        /// but never comes closer to another body than the safety distance, and its force is
        /// the virtual coupling between the two (default coupling when null).</summary>
        public Body CreateConstrainedTool(Mesh mesh, Pose pose, Vec3 referencePoint = default(Vec3),
                                          Coupling? coupling = null)
        {
            BodyDef def = Native.proxDefaultBodyDef();
            def.Mesh = mesh.id;
            def.Type = BodyType.Tool;
            def.Pose = pose;
            def.ReferencePoint = referencePoint;
            def.ToolMode = ToolMode.Constrained;
            if (coupling.HasValue)
            {
                def.CouplingStiffness = coupling.Value.Stiffness;
                def.CouplingDamping = coupling.Value.Damping;
                def.CouplingAngularStiffness = coupling.Value.AngularStiffness;
                def.CouplingAngularDamping = coupling.Value.AngularDamping;
            }
            Native.Check(Native.proxWorld_CreateBody(id, ref def, out BodyId body));
            return new Body(body);
        }

        /// <summary>The deterministic step on this thread: broadphase, global search and
        /// reduction per pair in range, forces. Refused (Busy) while the threads run.</summary>
        public void Step() => Native.Check(Native.proxWorld_Step(id));

        /// <summary>Local tracking alone: the last step's contacts carried to the current
        /// poses; finds no new contact.</summary>
        public void Track() => Native.Check(Native.proxWorld_Track(id));

        public WorldStats Stats
        {
            get { Native.Check(Native.proxWorld_GetStats(id, out WorldStats s)); return s; }
        }

        /// <summary>The global searches of the last Step.</summary>
        public SearchStats SearchStats
        {
            get { Native.Check(Native.proxWorld_GetSearchStats(id, out SearchStats s)); return s; }
        }

        /// <summary>How LMDs merge into patches; set it between steps, not while
        /// the threads run (Busy).</summary>
        public PatchSettings PatchSettings
        {
            get { Native.Check(Native.proxWorld_GetPatchSettings(id, out PatchSettings s)); return s; }
            set { Native.Check(Native.proxWorld_SetPatchSettings(id, ref value)); }
        }

        /// <summary>The bounded search's budget (docs/patches.md): after this many triangle
        /// pairs one pair's search gives one representative per patch-sized node pair;
        /// 0: no bound. Changed from the next Step on.</summary>
        public ulong LeafBudget
        {
            get { Native.Check(Native.proxWorld_GetLeafBudget(id, out ulong b)); return b; }
            set { Native.Check(Native.proxWorld_SetLeafBudget(id, value)); }
        }

        /// <summary>What the last Step merged into patches, cut and found crossing.</summary>
        public PatchStats PatchStats
        {
            get { Native.Check(Native.proxWorld_GetPatchStats(id, out PatchStats s)); return s; }
        }

        /// <summary>The last Track.</summary>
        public TrackStats TrackStats
        {
            get { Native.Check(Native.proxWorld_GetTrackStats(id, out TrackStats s)); return s; }
        }

        /// <summary>Starts the haptic (1 kHz), local tracking and global search threads.
        /// While they run the scene's shape is frozen (Busy).</summary>
        public void StartThreads(ThreadSettings settings) =>
            Native.Check(Native.proxWorld_StartThreads(id, ref settings));

        /// <summary>Fades every device out, then stops and joins the threads.</summary>
        public void StopThreads() => Native.Check(Native.proxWorld_StopThreads(id));

        public ThreadStats GetThreadStats(ThreadRole thread)
        {
            Native.Check(Native.proxWorld_GetThreadStats(id, thread, out ThreadStats s));
            return s;
        }

        public SafetyStats SafetyStats
        {
            get { Native.Check(Native.proxWorld_GetSafetyStats(id, out SafetyStats s)); return s; }
        }

        /// <summary>The built-in scripted device: a path of poses at secondsPerPose each,
        /// interpolated; attach it with Body.SetDevice. It lives as long as the world.</summary>
        public ScriptedDevice CreateScriptedDevice(Pose[] poses, double secondsPerPose, bool loop)
        {
            if (poses == null) throw new ArgumentNullException(nameof(poses));
            GCHandle h = GCHandle.Alloc(poses, GCHandleType.Pinned);
            try
            {
                ScriptedDeviceDef def = Native.proxDefaultScriptedDeviceDef();
                def.Poses = h.AddrOfPinnedObject();
                def.PoseCount = poses.Length;
                def.Loop = loop;
                def.SecondsPerPose = secondsPerPose;
                Native.Check(Native.proxWorld_CreateScriptedDevice(id, ref def, out ScriptedDeviceId device));
                return new ScriptedDevice(device);
            }
            finally
            {
                h.Free();
            }
        }

        /// <summary>A streamed device (see StreamDevice): attach it with Body.SetDevice, then
        /// push the tool's pose once a frame. At most 1024 exist at once in a process.</summary>
        public StreamDevice CreateStreamDevice(StreamDeviceSettings settings)
        {
            Native.Check(Native.proxWorld_CreateStreamDevice(id, ref settings, out StreamDeviceId device));
            return new StreamDevice(device);
        }

        /// <summary>A streamed device with StreamDeviceSettings.Default.</summary>
        public StreamDevice CreateStreamDevice() => CreateStreamDevice(StreamDeviceSettings.Default);

        /// <summary>Opens a HID device (see HidDevice) and starts its thread: the first
        /// supported one present, with HidDeviceSettings.Default. ProximaException (File)
        /// when none is. Attach it with Body.SetDevice. Game thread.</summary>
        public HidDevice OpenHidDevice() => HidDevice.Open(id, HidDeviceSettings.Default, null);

        /// <summary>Opens the HID device HidDevice.Enumerate listed.</summary>
        public HidDevice OpenHidDevice(HidDeviceInfo device) =>
            HidDevice.Open(id, HidDeviceSettings.Default, device.Path);

        /// <summary>Opens a HID device with these settings: the one at `path` (a
        /// HidDeviceInfo.Path), or when it is null the first supported one matching the
        /// settings' VendorId and ProductId (0: any).</summary>
        public HidDevice OpenHidDevice(HidDeviceSettings settings, string path = null) =>
            HidDevice.Open(id, settings, path);

        /// <summary>OpenHidDevice under the name the other devices have
        /// (CreateStreamDevice, CreateXrDevice) and the C API gives it
        /// (proxWorld_CreateHidDevice).</summary>
        public HidDevice CreateHidDevice() => OpenHidDevice();

        /// <summary>OpenHidDevice(HidDeviceInfo) by the C API's name.</summary>
        public HidDevice CreateHidDevice(HidDeviceInfo device) => OpenHidDevice(device);

        /// <summary>OpenHidDevice(HidDeviceSettings, string) by the C API's name.</summary>
        public HidDevice CreateHidDevice(HidDeviceSettings settings, string path = null) =>
            OpenHidDevice(settings, path);

        /// <summary>Hands Proxima an XR controller (see XrDevice) and starts its thread: the
        /// app's OpenXR objects and the device's settings, from XrDeviceSettings.Default.
        /// Call it after the app attached its action sets; attach the device with
        /// Body.SetDevice. ProximaException (InvalidArgument) names what is wrong with the
        /// settings, including what the runtime refused. Game thread.</summary>
        public XrDevice CreateXrDevice(XrDeviceSettings settings) => XrDevice.Create(id, settings);

        /// <summary>A scripted device whose path is a file: "tx ty tz qw qx qy qz" per line.</summary>
        public ScriptedDevice LoadScriptedDevice(string path, double secondsPerPose, bool loop)
        {
            Native.Check(Native.proxWorld_LoadScriptedDevice(id, Native.Utf8(path, nameof(path)), secondsPerPose,
                                                             loop, out ScriptedDeviceId device));
            return new ScriptedDevice(device);
        }
    }
}
