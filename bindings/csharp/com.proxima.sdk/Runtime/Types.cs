// The value types of the C API (sdk/include/proxima/proxima.h), field for
// field: blittable and sequential, so arrays of them cross P/Invoke without
// copying or conversion. Every size is checked against C's in the tests.
using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>proxBool: a 32-bit boolean (0 false, anything else true).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct Bool32 : IEquatable<Bool32>
    {
        readonly int value;
        public Bool32(bool b) { value = b ? 1 : 0; }
        public static implicit operator bool(Bool32 b) => b.value != 0;
        public static implicit operator Bool32(bool b) => new Bool32(b);
        public bool Equals(Bool32 other) => (value != 0) == (other.value != 0);
        public override bool Equals(object obj) => obj is Bool32 b && Equals(b);
        public override int GetHashCode() => value != 0 ? 1 : 0;
        public override string ToString() => value != 0 ? "true" : "false";
    }

    /// <summary>proxResult: 0 on success, negative on error.</summary>
    public enum Result
    {
        Success = 0,
        InvalidArgument = -1,
        InvalidHandle = -2,
        InvalidMesh = -3,
        File = -4,
        Parse = -5,
        Unsupported = -6,
        VersionMismatch = -7,
        WrongThread = -8,
        Capacity = -9,
        Internal = -10,
        Busy = -11,
    }

    /// <summary>The library's version (proxVersion).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Version
    {
        public int Major, Minor, Patch;

        public Version(int major, int minor, int patch) { Major = major; Minor = minor; Patch = patch; }

        /// <summary>The C API version this binding was written against.</summary>
        public static Version Binding => new Version(0, 4, 0);

        /// <summary>The version of the native library actually loaded.</summary>
        public static Version Library
        {
            get
            {
                try
                {
                    return Native.proxGetVersion();
                }
                catch (DllNotFoundException e)
                {
                    throw new DllNotFoundException(
                        "Proxima's native library (libproxima) could not be loaded. In Unity it belongs in the " +
                        "package's Runtime/Plugins/<platform>/ (bindings/csharp/fill_plugins.sh copies it from a " +
                        "build); elsewhere put it beside Proxima.dll or on the library path. (" + e.Message + ")", e);
                }
            }
        }

        /// <summary>Throws ProximaException (VersionMismatch) unless the loaded library's
        /// major version is the binding's (and, before 1.0, its minor too).</summary>
        public static void Check()
        {
            Version lib = Library, bound = Binding;
            if (lib.Major != bound.Major || (bound.Major == 0 && lib.Minor != bound.Minor))
                throw new ProximaException(Result.VersionMismatch,
                    "the native library is Proxima " + lib + " but this binding was written for " + bound +
                    ": use the libproxima built with these bindings");
        }

        public override string ToString() => Major + "." + Minor + "." + Patch;
    }

    /// <summary>A vector: metres for points, newtons for forces, newton-metres for torques.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Vec3 : IEquatable<Vec3>
    {
        public double X, Y, Z;

        public Vec3(double x, double y, double z) { X = x; Y = y; Z = z; }

        public static readonly Vec3 Zero = new Vec3(0, 0, 0);
        public double Length => Math.Sqrt(X * X + Y * Y + Z * Z);
        public static Vec3 operator +(Vec3 a, Vec3 b) => new Vec3(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        public static Vec3 operator -(Vec3 a, Vec3 b) => new Vec3(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        public static Vec3 operator *(double s, Vec3 a) => new Vec3(s * a.X, s * a.Y, s * a.Z);
        public bool Equals(Vec3 o) => X == o.X && Y == o.Y && Z == o.Z;
        public override bool Equals(object obj) => obj is Vec3 v && Equals(v);
        public override int GetHashCode() => X.GetHashCode() ^ (Y.GetHashCode() * 397) ^ (Z.GetHashCode() * 7919);
        public override string ToString() => "(" + X.ToString("R") + ", " + Y.ToString("R") + ", " + Z.ToString("R") + ")";
    }

    /// <summary>A rotation as a unit quaternion (w, x, y, z); normalised by Proxima on input.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Quat : IEquatable<Quat>
    {
        public double W, X, Y, Z;

        public Quat(double w, double x, double y, double z) { W = w; X = x; Y = y; Z = z; }

        public static readonly Quat Identity = new Quat(1, 0, 0, 0);

        /// <summary>A rotation of `radians` about `axis` (any length but zero).</summary>
        public static Quat FromAxisAngle(Vec3 axis, double radians)
        {
            double n = axis.Length, s = Math.Sin(0.5 * radians) / n;
            return new Quat(Math.Cos(0.5 * radians), axis.X * s, axis.Y * s, axis.Z * s);
        }

        public bool Equals(Quat o) => W == o.W && X == o.X && Y == o.Y && Z == o.Z;
        public override bool Equals(object obj) => obj is Quat q && Equals(q);
        public override int GetHashCode() => W.GetHashCode() ^ (X.GetHashCode() * 397) ^ (Y.GetHashCode() * 7919) ^ (Z.GetHashCode() * 104729);
        public override string ToString() => "(" + W.ToString("R") + ", " + X.ToString("R") + ", " + Y.ToString("R") + ", " + Z.ToString("R") + ")";
    }

    /// <summary>A rigid pose: world = Rotation * local + Position.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Pose : IEquatable<Pose>
    {
        public Vec3 Position;
        public Quat Rotation;

        public Pose(Vec3 position, Quat rotation) { Position = position; Rotation = rotation; }

        public static readonly Pose Identity = new Pose(Vec3.Zero, Quat.Identity);
        public bool Equals(Pose o) => Position.Equals(o.Position) && Rotation.Equals(o.Rotation);
        public override bool Equals(object obj) => obj is Pose p && Equals(p);
        public override int GetHashCode() => Position.GetHashCode() ^ (Rotation.GetHashCode() * 31);
        public override string ToString() => "{" + Position + ", " + Rotation + "}";
    }

    public enum Method { Precise = 0, Original = 1, Reference = 2 }

    public enum ForceCurve { Exponential = 0, Linear = 1 }

    public enum ForcePreset { Hard = 0, Soft = 1 }

    public enum BodyType { Static = 0, Movable = 1, Tool = 2 }

    /// <summary>How a tool follows what moves it (proxToolMode): Free, where its device puts
    /// it, with the LMDs' force; Constrained, a proxy that stays outside the other bodies,
    /// with the virtual coupling's force.</summary>
    public enum ToolMode { Free = 0, Constrained = 1 }

    /// <summary>The virtual coupling of a constrained tool: N/m, N s/m, N m/rad, N m s/rad.</summary>
    public struct Coupling
    {
        public double Stiffness, Damping, AngularStiffness, AngularDamping;
    }

    /// <summary>A closest feature of a triangle.</summary>
    public enum Feature { Vertex = 0, Edge = 1, Face = 2 }

    /// <summary>How the haptic loop waits for its next period (proxHapticTiming).</summary>
    public enum HapticTiming
    {
        /// <summary>Spin when the haptic thread runs real-time or on a core of its own, else Sleep.</summary>
        Auto = 0,
        /// <summary>Sleep to SpinMargin before the deadline, then spin: on time, costs CPU.</summary>
        Spin = 1,
        /// <summary>Sleep to the deadline: no CPU between ticks, late by the OS's wake-up.</summary>
        Sleep = 2,
    }

    /// <summary>What the haptic loop's sleeps wait on (proxSleepTimer).</summary>
    public enum SleepTimer
    {
        /// <summary>The system's own: Linux's futex wait on high-resolution timers.</summary>
        System = 0,
        /// <summary>Windows 10 1803+: a high-resolution waitable timer.</summary>
        HighResolution = 1,
        /// <summary>Older Windows: a waitable timer, timeBeginPeriod(1) while the loop runs.</summary>
        Period1ms = 2,
    }

    /// <summary>One of the world's own threads (proxThread).</summary>
    public enum ThreadRole { Haptic = 0, Local = 1, Global = 2 }

    /// <summary>proxForceSettings: the force curve of every contact.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct ForceSettings
    {
        public ForceCurve Curve;
        public double MaxForce;       // N: per contact at the safety distance, and the clip of the sum
        public double MaxTorque;      // N m: clip of the summed torque
        public double SafetyDistance; // m: full force at and inside this distance
        public double DecayLength;    // m: the exponential curve's length scale

        /// <summary>A preset's force settings and cutoff (metres). Any thread.</summary>
        public static ForceSettings FromPreset(ForcePreset preset, out double cutoff)
        {
            Native.Check(Native.proxGetForcePreset(preset, out ForceSettings force, out cutoff));
            return force;
        }
    }

    /// <summary>proxMeshInfo: counts and bounds of a mesh.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct MeshInfo
    {
        public uint TriangleCount;   // after dropping triangles that repeat a vertex
        public uint VertexCount;     // after welding
        public uint DroppedTriangles;
        public uint BoundaryEdges;
        public uint NonManifoldEdges;
        public Vec3 BoundsMin, BoundsMax; // in the mesh's own frame
    }

    /// <summary>proxRigInfo: what a glTF mesh's rig holds (docs/dynamic-scenes.md); zeros for a mesh
    /// without one.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct RigInfo
    {
        public int SkinCount;
        public int JointCount;       // over every skin
        public int MorphWeightCount; // what Mesh.SetMorphWeights takes
        public int AnimationCount;
    }

    /// <summary>proxSkinInfo: one skin of a glTF mesh.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SkinInfo
    {
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 64)] internal byte[] name;
        public int JointCount;
        int reserved;
        /// <summary>The skin's name in the file; "" when it has none.</summary>
        public string Name => Native.CString(name);
    }

    /// <summary>proxAnimationInfo: one animation of a glTF mesh, times in seconds.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct AnimationInfo
    {
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 64)] internal byte[] name;
        public double Duration;  // the last keyframe's time (glTF time starts at 0)
        public double Start;     // the first keyframe's time
        public int ChannelCount;
        int reserved;
        /// <summary>The animation's name in the file, else "animation N".</summary>
        public string Name => Native.CString(name);
    }

    /// <summary>proxContact: one local minimum distance pair of a tool.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Contact
    {
        public Body Other;        // the body the tool is near
        public Vec3 PointTool;    // closest point on the tool, world
        public Vec3 PointOther;   // closest point on the other body, world
        public Vec3 Normal;       // unit, from the other body to the tool
        public double Distance;   // m, > 0
        public uint TriangleTool, TriangleOther;
        public Feature FeatureTool, FeatureOther;
    }

    /// <summary>proxContactPatch: the LMDs a contact stands for where the distance field
    /// is flat (docs/patches.md); beside the contact it belongs to.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct ContactPatch
    {
        public int Count;        // LMDs the contact stands for, itself included (1: none merged into it)
        readonly int reserved;
        public double Extent;    // m: the farthest member's point on the tool from the contact's
        public double Spread;    // m: how much farther from the other body the farthest member is
        public double Angle;     // radians: the largest angle between a member's direction and the contact's
    }

    /// <summary>proxWrench: force and torque on a tool, world frame.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Wrench
    {
        public Vec3 Force;   // N, on the tool
        public Vec3 Torque;  // N m, on the tool about its reference point
        public Bool32 Clipped;
    }

    /// <summary>proxHapticFlag: why a recorded tick rendered what it did.</summary>
    [Flags]
    public enum HapticFlags : uint
    {
        None = 0,
        Clipped = 1,    // the safety gate changed the wrench (clip or rate limit)
        Stale = 2,      // the contacts were older than StaleAfter
        Untrusted = 4,  // the tool was farther than TrustDistance from where they were tracked
        Faded = 8,      // no contacts rendered: the gate faded the force towards zero
        NoPose = 16,    // the device gave no valid pose
        Stopping = 32,  // the fade-out after StopThreads
    }

    /// <summary>proxHapticSample: one tick of the flight recorder (ThreadSettings.TraceCapacity).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct HapticSample
    {
        public double Time;       // s since the threads started
        public Pose DevicePose;   // the device's (or the game's) pose this tick
        public Pose ProxyPose;    // a constrained tool's proxy this tick, else DevicePose
        public Vec3 Force;        // N, what the device was handed
        public Vec3 Torque;       // N m
        public int ContactCount;  // contacts rendered this tick
        public HapticFlags Flags;
        public double ClosestDistance;  // m
        public ulong Tick;        // consecutive samples differ by 1
    }

    /// <summary>An intersection polyline: where the tool's surface crosses another body's.</summary>
    public sealed class Polyline
    {
        public Body Other { get; }
        public Vec3[] Points { get; }  // world frame
        public bool Closed { get; }    // the last point joins the first

        public Polyline(Body other, Vec3[] points, bool closed) { Other = other; Points = points; Closed = closed; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct WorldStats
    {
        public int Bodies, Tools;
        public int PairsInRange;   // tool-body pairs the broadphase kept in the last step
        public int PairsSearched;  // ... of which ran a global search
        public int Contacts;       // over all tools
        public int Candidates;     // before reduction
        public double StepSeconds;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct MeshStats
    {
        public uint InputVertices, InputTriangles, ZeroAreaTriangles;
        public uint HierarchyNodes, HierarchyLeaves, HierarchyDepth, UnboundedLeafCones;
        readonly uint reserved;
        public ulong HierarchyBytes;
        public double HierarchySeconds;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct SearchStats
    {
        public int PairsSearched;
        readonly int reserved;
        public ulong NodePairs, LeafPairs, PlaneRejections, VisibilityRejections, NormalRejections;
        public ulong DistanceEvaluations, Candidates, ReductionCacheHits;
        public double GlobalSeconds, ReductionSeconds;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct TrackStats
    {
        public int PairsTracked, ContactsIn, ContactsOut;
        readonly int reserved;
        public ulong DistanceEvaluations, CacheHits, Moves;
        public double Seconds;
    }

    /// <summary>How LMDs merge into patches (proxPatchSettings, docs/patches.md):
    /// the radius as a share of the cutoff (0: no merging) and the largest
    /// angle between directions, and how much farther than the closest a
    /// member may be (a share of the cutoff).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct PatchSettings
    {
        public double RadiusOverCutoff, MaxAngleDegrees, MaxSpreadOverCutoff;
    }

    /// <summary>What the last step merged into patches, cut and found crossing (proxPatchStats).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct PatchStats
    {
        public int Lmds, Patches, Merged, LargestPatch;
        public ulong IntersectingPairs;
        public int IntersectingBodies;
        public int CutNodePairs;   // node pairs the bounded search cut (World.LeafBudget)
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct IntersectionStats
    {
        public ulong TrianglePairs, IntersectingPairs, CoplanarPairs, Segments;
        public double Seconds;
    }

    /// <summary>proxThreadsDef: start from ThreadSettings.Default and change what you need.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct ThreadSettings
    {
        public double HapticRate;  // Hz (default 1000)
        public double LocalRate;   // Hz (default 1000; 0: back to back)
        public double GlobalRate;  // Hz (default 0: back to back, idle while nothing moves)
        // -1: not pinned. The default, on at least four cores: haptic and local
        // on the last two, global unpinned; else none.
        public int HapticCore, LocalCore, GlobalCore;
        public int MaxContacts;    // per tool handed to the haptic loop (default 1024)
        public double StaleAfter;     // s (default 0.05)
        public double MaxForceRate;   // N/s (default 300)
        public double MaxTorqueRate;  // N m/s (default 30)
        public double TrustDistance;  // m; 0: the world's cutoff
        public HapticTiming HapticTiming; // default Auto
        public int HapticPriority;    // SCHED_FIFO priority (1-99) asked for the haptic thread; 0: none
        public double SpinMargin;     // s, in [0, the haptic period]: Spin's spin (default 0.0002)
        public int LocalPriority;     // the same for the local tracking thread
        public Bool32 LockMemory;     // mlockall once the threads run (process-wide, never undone)
        readonly int internalValue;
        public int TraceCapacity;     // the flight recorder: each tool's last this many ticks (0: off)

        /// <summary>Every field at its default (proxDefaultThreadsDef). Any thread.</summary>
        public static ThreadSettings Default => Native.proxDefaultThreadsDef();
    }

    /// <summary>proxThreadStats: one thread's timing.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct ThreadStats
    {
        public Bool32 Running;
        public int PinnedCore;     // -1: not pinned
        public double TargetRate;  // Hz; 0: back to back
        public double AchievedRate;
        public double PeriodP50, PeriodP99, PeriodMax; // s, iteration start to start
        public double UpdateP50, UpdateP99, UpdateMax; // s of work per iteration
        public ulong Updates;
        public ulong Overruns;
        public double PeriodP999;      // s
        public int RealtimePriority;   // the SCHED_FIFO priority granted (Windows: as TIME_CRITICAL); 0: none asked, or refused
        public int RealtimeError;      // the errno that refused it; 0
        public Bool32 MemoryLocked;    // haptic thread: LockMemory was granted
        public int MemoryLockError;    // ... or the errno that refused it; 0
        public HapticTiming Timing;    // haptic thread: Spin or Sleep, as Auto resolved
        public SleepTimer SleepTimer;  // haptic thread: what its sleeps wait on
    }

    /// <summary>proxSafetyStats: the haptic loop's safety decisions, in ticks over all tools.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SafetyStats
    {
        public ulong InvalidPoses, StaleTicks, UntrustedTicks, LimitedTicks, TornSnapshots, DroppedContacts;
    }

    /// <summary>proxScriptedDeviceRecord: what a scripted device was handed.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct ScriptedDeviceRecord
    {
        public ulong Reads, Writes;
        public double Progress;      // poses into the path (fractional)
        public double MaxForce;      // N
        public double MaxTorque;     // N m
        public double MaxForceStep;  // N, between consecutive writes
        public Vec3 LastForce, LastTorque;
        public Bool32 AllFinite;
        readonly int reserved;
    }
}
