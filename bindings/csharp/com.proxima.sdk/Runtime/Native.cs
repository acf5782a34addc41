// The C API's functions, declared as they are in proxima.h. Nothing here is
// public: World, Mesh, Body and the devices are the interface.
using System;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

[assembly: InternalsVisibleTo("Proxima.Tests")]

namespace Proxima
{
    [StructLayout(LayoutKind.Sequential)]
    internal struct WorldId
    {
        public uint Index1, Generation;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct MeshId
    {
        public uint Index1, Generation;
        public WorldId World;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct BodyId
    {
        public uint Index1, Generation;
        public WorldId World;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct ScriptedDeviceId
    {
        public uint Index1, Reserved;
        public WorldId World;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct StreamDeviceId
    {
        public uint Index1, Reserved;
        public WorldId World;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct WorldDef
    {
        public int ApiVersion;
        public Method Method;
        public double Cutoff;
        public ForceSettings Force;
        public int InternalValue;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct MeshDef
    {
        public IntPtr Positions;
        public uint VertexCount;
        public IntPtr Indices;
        public uint TriangleCount;
        public int InternalValue;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct BodyDef
    {
        public MeshId Mesh;
        public BodyType Type;
        public Pose Pose;
        public Vec3 ReferencePoint;
        public ToolMode ToolMode;
        public double CouplingStiffness;
        public double CouplingDamping;
        public double CouplingAngularStiffness;
        public double CouplingAngularDamping;
        public int InternalValue;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct PolylineInfo
    {
        public BodyId Other;
        public int FirstPoint;
        public int PointCount;
        public Bool32 Closed;
        public int Reserved;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct DeviceDef
    {
        public IntPtr ReadPose;
        public IntPtr WriteWrench;
        public IntPtr UserData;
        public int InternalValue;
        public int Reserved;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct ScriptedDeviceDef
    {
        public IntPtr Poses;
        public int PoseCount;
        public Bool32 Loop;
        public double SecondsPerPose;
        public int InternalValue;
        public int Reserved;
    }

    // The callbacks' C signatures; the thunks in Device.cs implement them.
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
    internal delegate int ReadPoseCallback(IntPtr userData, out Pose pose);

    [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
    internal delegate void WriteWrenchCallback(IntPtr userData, ref Wrench wrench);

    internal static class Native
    {
#if (UNITY_IOS || UNITY_WEBGL) && !UNITY_EDITOR
        // Statically linked into the player: IL2CPP resolves these at link time.
        internal const string Library = "__Internal";
#else
        internal const string Library = "proxima";
#endif

        // The library's strings belong to it: returned as IntPtr and copied,
        // because a `string` return would make the marshaller free them.
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr proxResultString(Result result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr proxGetLastError();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Version proxGetVersion();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern WorldDef proxDefaultWorldDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxCreateWorld(ref WorldDef def, out WorldId world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxDestroyWorld(WorldId world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Bool32 proxWorld_IsValid(WorldId world);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern MeshDef proxDefaultMeshDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_CreateMesh(WorldId world, ref MeshDef def, out MeshId mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_LoadMesh(WorldId world, byte[] utf8Path, out MeshId mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_LoadMeshFromMemory(WorldId world, byte[] data, ulong size, byte[] utf8Name,
                                                                   out MeshId mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_Destroy(MeshId mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Bool32 proxMesh_IsValid(MeshId mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetInfo(MeshId mesh, out MeshInfo info);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetStats(MeshId mesh, out MeshStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetWarnings(MeshId mesh, byte[] buffer, int capacity, out int length);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetTriangles(MeshId mesh, double[] positions, uint vertexCapacity,
                                                            out uint vertexCount, uint[] indices,
                                                            uint triangleCapacity, out uint triangleCount);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_SetVertices(MeshId mesh, double[] positions, uint vertexCount);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetRigInfo(MeshId mesh, out RigInfo info);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetSkinInfo(MeshId mesh, int skin, out SkinInfo info);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetAnimationCount(MeshId mesh, out int count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetAnimationInfo(MeshId mesh, int index, out AnimationInfo info);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_Animate(MeshId mesh, int animation, double seconds);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_SetJointMatrices(MeshId mesh, int skin, double[] matrices, int count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_SetMorphWeights(MeshId mesh, double[] weights, int count);

        /// <summary>A NUL-terminated UTF-8 char array of a C struct, as a string.</summary>
        internal static string CString(byte[] bytes)
        {
            if (bytes == null) return "";
            int length = Array.IndexOf(bytes, (byte)0);
            return System.Text.Encoding.UTF8.GetString(bytes, 0, length < 0 ? bytes.Length : length);
        }

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern BodyDef proxDefaultBodyDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_CreateBody(WorldId world, ref BodyDef def, out BodyId body);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_Destroy(BodyId body);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Bool32 proxBody_IsValid(BodyId body);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_SetPose(BodyId body, ref Pose pose);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetPose(BodyId body, out Pose pose);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetProxyPose(BodyId tool, out Pose pose);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_Step(WorldId world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        // Output arrays are passed as pointers the caller pinned: Mono copies a
        // managed array of structs element by element both ways (measured: 20 us
        // for 64 contacts), where pinning costs a GCHandle.
        internal static extern Result proxBody_GetContacts(BodyId tool, IntPtr contacts, int capacity, out int count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetContactPatches(BodyId tool, IntPtr contacts, IntPtr patches, int capacity,
                                                                 out int count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetWrench(BodyId tool, out Wrench wrench);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetHapticTrace(BodyId tool, [Out] HapticSample[] samples, int capacity, out int count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetIntersections(BodyId tool, IntPtr points, int pointCapacity,
                                                                out int pointCount, IntPtr lines, int lineCapacity,
                                                                out int lineCount);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetStats(WorldId world, out WorldStats stats);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern DeviceDef proxDefaultDeviceDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_SetDevice(BodyId tool, ref DeviceDef def);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, EntryPoint = "proxBody_SetDevice")]
        internal static extern Result proxBody_SetDeviceNull(BodyId tool, IntPtr def);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ScriptedDeviceDef proxDefaultScriptedDeviceDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_CreateScriptedDevice(WorldId world, ref ScriptedDeviceDef def,
                                                                     out ScriptedDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_LoadScriptedDevice(WorldId world, byte[] utf8Path, double secondsPerPose,
                                                                   Bool32 loop, out ScriptedDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxScriptedDevice_GetDeviceDef(ScriptedDeviceId device, out DeviceDef def);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxScriptedDevice_GetRecord(ScriptedDeviceId device,
                                                                   out ScriptedDeviceRecord record);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxScriptedDevice_Destroy(ScriptedDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Bool32 proxScriptedDevice_IsValid(ScriptedDeviceId device);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern double proxGetTime();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern StreamDeviceSettings proxDefaultStreamDeviceDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_CreateStreamDevice(WorldId world, ref StreamDeviceSettings def,
                                                                   out StreamDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxStreamDevice_PushPose(StreamDeviceId device, ref Pose pose, double timeSeconds);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxStreamDevice_GetWrench(StreamDeviceId device, out Wrench wrench);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxStreamDevice_GetDeviceDef(StreamDeviceId device, out DeviceDef def);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxStreamDevice_GetStats(StreamDeviceId device, out StreamDeviceStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxStreamDevice_Destroy(StreamDeviceId device);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Bool32 proxStreamDevice_IsValid(StreamDeviceId device);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern ThreadSettings proxDefaultThreadsDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_StartThreads(WorldId world, ref ThreadSettings def);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_StopThreads(WorldId world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetThreadStats(WorldId world, ThreadRole thread, out ThreadStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetSafetyStats(WorldId world, out SafetyStats stats);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxGetForcePreset(ForcePreset preset, out ForceSettings force, out double cutoff);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetSearchStats(WorldId world, out SearchStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_Track(WorldId world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetTrackStats(WorldId world, out TrackStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetIntersectionStats(BodyId tool, out IntersectionStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetPatchSettings(WorldId world, out PatchSettings settings);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_SetPatchSettings(WorldId world, ref PatchSettings settings);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetPatchStats(WorldId world, out PatchStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_SetLeafBudget(WorldId world, ulong leafPairs);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetLeafBudget(WorldId world, out ulong leafPairs);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetDistance(BodyId a, BodyId b, double maxDistance, out double distance);

        /// <summary>proxBody_GetContactPatches into managed arrays (either may be null), pinned
        /// for the call; the capacity is the shorter one's length.</summary>
        internal static Result GetContactPatches(BodyId tool, Contact[] contacts, ContactPatch[] patches, out int count)
        {
            int capacity = Math.Min(contacts?.Length ?? int.MaxValue, patches?.Length ?? int.MaxValue);
            if (capacity == int.MaxValue || capacity == 0)
                return proxBody_GetContactPatches(tool, IntPtr.Zero, IntPtr.Zero, 0, out count);
            GCHandle pinContacts = contacts != null ? GCHandle.Alloc(contacts, GCHandleType.Pinned) : default(GCHandle);
            GCHandle pinPatches = patches != null ? GCHandle.Alloc(patches, GCHandleType.Pinned) : default(GCHandle);
            try
            {
                return proxBody_GetContactPatches(tool, contacts != null ? pinContacts.AddrOfPinnedObject() : IntPtr.Zero,
                                                  patches != null ? pinPatches.AddrOfPinnedObject() : IntPtr.Zero,
                                                  capacity, out count);
            }
            finally
            {
                if (contacts != null) pinContacts.Free();
                if (patches != null) pinPatches.Free();
            }
        }

        /// <summary>proxBody_GetContacts into a managed array, pinned for the call.</summary>
        internal static Result GetContacts(BodyId tool, Contact[] contacts, out int count)
        {
            if (contacts == null || contacts.Length == 0) return proxBody_GetContacts(tool, IntPtr.Zero, 0, out count);
            GCHandle pin = GCHandle.Alloc(contacts, GCHandleType.Pinned);
            try
            {
                return proxBody_GetContacts(tool, pin.AddrOfPinnedObject(), contacts.Length, out count);
            }
            finally
            {
                pin.Free();
            }
        }

        /// <summary>proxBody_GetIntersections into managed arrays, pinned for the call.</summary>
        internal static Result GetIntersections(BodyId tool, Vec3[] points, out int pointCount, PolylineInfo[] lines,
                                                out int lineCount)
        {
            GCHandle p = GCHandle.Alloc(points, GCHandleType.Pinned);
            GCHandle l = GCHandle.Alloc(lines, GCHandleType.Pinned);
            try
            {
                return proxBody_GetIntersections(tool, p.AddrOfPinnedObject(), points.Length, out pointCount,
                                                 l.AddrOfPinnedObject(), lines.Length, out lineCount);
            }
            finally
            {
                p.Free();
                l.Free();
            }
        }

        /// <summary>A C string of the library's, copied (UTF-8).</summary>
        internal static string Copy(IntPtr s)
        {
            if (s == IntPtr.Zero) return "";
            int n = 0;
            while (Marshal.ReadByte(s, n) != 0) ++n;
            var bytes = new byte[n];
            Marshal.Copy(s, bytes, 0, n);
            return System.Text.Encoding.UTF8.GetString(bytes);
        }

        internal static byte[] Utf8(string s, string parameter)
        {
            if (s == null) throw new ArgumentNullException(parameter);
            var bytes = new byte[System.Text.Encoding.UTF8.GetByteCount(s) + 1];
            System.Text.Encoding.UTF8.GetBytes(s, 0, s.Length, bytes, 0);
            return bytes;
        }

        /// <summary>Throws the library's error, with its message, unless r is success.
        /// Must run on the thread that made the failing call (the message is per thread).</summary>
        internal static void Check(Result r)
        {
            if (r != Result.Success) throw ProximaException.FromLastError(r);
        }
    }
}
