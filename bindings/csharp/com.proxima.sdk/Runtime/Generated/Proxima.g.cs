// Generated from sdk/include/proxima/proxima.h by bindings/csharp/tools/gen_native.py:
// do not edit. Regenerate with `python3 bindings/csharp/tools/gen_native.py`
// (docs/csharp.md); ctest csharp.generated fails while this file is stale.
using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxCreateWorld(ref WorldDef def, out WorldId world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_Destroy(WorldId world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxDestroyWorld(WorldId world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Bool32 proxWorld_IsValid(WorldId world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_CreateMesh(WorldId world, ref MeshDef def, out MeshId mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_LoadMesh(WorldId world, byte[] utf8Path, out MeshId mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_LoadMeshFromMemory(WorldId world, byte[] data, ulong size, byte[] utf8Name, out MeshId mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_Destroy(MeshId mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Bool32 proxMesh_IsValid(MeshId mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetInfo(MeshId mesh, out MeshInfo info);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetTriangles(MeshId mesh, double[] positions, uint vertexCapacity, out uint vertexCount, uint[] indices, uint triangleCapacity, out uint triangleCount);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_SetVertices(MeshId mesh, double[] positions, uint vertexCount);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetWarnings(MeshId mesh, byte[] buffer, int capacity, out int length);
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
        internal static extern Result proxBody_GetContacts(BodyId tool, IntPtr contacts, int capacity, out int count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetContactPatches(BodyId tool, IntPtr contacts, IntPtr patches, int capacity, out int count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetWrench(BodyId tool, out Wrench wrench);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetIntersections(BodyId tool, IntPtr points, int pointCapacity, out int pointCount, IntPtr lines, int lineCapacity, out int lineCount);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetStats(WorldId world, out WorldStats stats);
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
    }
}
