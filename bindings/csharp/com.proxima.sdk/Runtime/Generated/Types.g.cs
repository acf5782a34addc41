// Generated from sdk/include/proxima/types.h by bindings/csharp/tools/gen_native.py:
// do not edit. Regenerate with `python3 bindings/csharp/tools/gen_native.py`
// (docs/csharp.md); ctest csharp.generated fails while this file is stale.
using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>
    /// proxWorldId: Ids are values: copy them freely. Zero-initialised ids are null. A destroyed object's id
    /// stays invalid forever (the generation moves on).
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct WorldId
    {
        // index + 1; 0 is null
        public uint Index1;
        public uint Generation;
    }

    /// <summary>proxMeshId</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct MeshId
    {
        public uint Index1;
        public uint Generation;
        public WorldId World;
    }

    /// <summary>proxBodyId</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct BodyId
    {
        public uint Index1;
        public uint Generation;
        public WorldId World;
    }

    /// <summary>proxVec3</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct Vec3
    {
        public double X;
        public double Y;
        public double Z;
    }

    /// <summary>proxQuat: A unit quaternion; (1, 0, 0, 0) is the identity.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct Quat
    {
        public double W;
        public double X;
        public double Y;
        public double Z;
    }

    /// <summary>proxPose</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct Pose
    {
        public Vec3 Position;
        // normalised on input; a zero quaternion is an error
        public Quat Rotation;
    }

    /// <summary>proxMethod</summary>
    public enum Method
    {
        /// <summary>the improved method: exact distances, visibility pre-test, reduction</summary>
        Precise = 0,
        /// <summary>the Johnson-Cohen baseline: 7 x 7 feature points</summary>
        Original = 1,
        /// <summary>the brute-force truth: every triangle pair; slow, for tests</summary>
        Reference = 2,
    }

    /// <summary>proxForceCurve</summary>
    public enum ForceCurve
    {
        /// <summary>max at the safety distance, falls by e per decay length, 0 at the cutoff</summary>
        Exponential = 0,
        /// <summary>max at the safety distance, linear to 0 at the cutoff</summary>
        Linear = 1,
    }

    /// <summary>proxForceSettings</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct ForceSettings
    {
        public ForceCurve Curve;
        // N: per contact at the safety distance, and the clip of the sum (> 0)
        public double MaxForce;
        // N m: clip of the summed torque (> 0)
        public double MaxTorque;
        // m: full force at and inside this distance (>= 0, < cutoff)
        public double SafetyDistance;
        // m: exponential curve's length scale (> 0)
        public double DecayLength;
    }

    /// <summary>proxWorldDef</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct WorldDef
    {
        // PROX_API_VERSION, set by proxDefaultWorldDef()
        public int ApiVersion;
        public Method Method;
        // m: contacts farther apart are not wanted (> 0)
        public double Cutoff;
        // the default: the "hard" settings of docs/cli.md
        public ForceSettings Force;
        // do not touch: lets proxCreateWorld detect a def not from proxDefaultWorldDef
        public int InternalValue;
        // Threads the game thread's own heavy work is split over, itself included, in [1, 256] (default 1: no
        // thread started): a deforming mesh's normals and hierarchy (proxMesh_SetVertices,
        // proxMesh_Animate...) and proxWorld_Step's searches. The results are the same bits whatever the
        // count. Leave the haptic and tracking threads their cores (docs/threading.md).
        public int WorkerCount;
    }

    /// <summary>proxMeshDef</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct MeshDef
    {
        // PROX_API_VERSION, set by proxDefaultMeshDef()
        public int ApiVersion;
        // x, y, z per vertex
        public IntPtr Positions;
        public uint VertexCount;
        // three per triangle, counter-clockwise seen from outside
        public IntPtr Indices;
        public uint TriangleCount;
        public int InternalValue;
    }

    /// <summary>proxMeshInfo</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct MeshInfo
    {
        // after dropping triangles that repeat a vertex
        public uint TriangleCount;
        // after welding
        public uint VertexCount;
        public uint DroppedTriangles;
        public uint BoundaryEdges;
        public uint NonManifoldEdges;
        // in the mesh's own frame
        public Vec3 BoundsMin;
        // in the mesh's own frame
        public Vec3 BoundsMax;
    }

    /// <summary>proxRigInfo</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct RigInfo
    {
        public int SkinCount;
        // over every skin
        public int JointCount;
        // what proxMesh_SetMorphWeights takes
        public int MorphWeightCount;
        public int AnimationCount;
    }

    /// <summary>proxSkinInfo</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct SkinInfo
    {
        // NUL-terminated, cut to 63 bytes; "" when the file names none
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 64)] internal byte[] name;
        public int JointCount;
        readonly int reserved;
    }

    /// <summary>proxAnimationInfo</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct AnimationInfo
    {
        // NUL-terminated, cut to 63 bytes; "animation N" when the file names none
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 64)] internal byte[] name;
        // seconds: the last keyframe's time (glTF time starts at 0)
        public double Duration;
        // seconds: the first keyframe's time
        public double Start;
        public int ChannelCount;
        readonly int reserved;
    }

    /// <summary>proxBodyType</summary>
    public enum BodyType
    {
        /// <summary>never moves; static-static pairs are never tested</summary>
        Static = 0,
        /// <summary>moved by the application</summary>
        Movable = 1,
        /// <summary>held by the user: contacts and forces are computed for tools</summary>
        Tool = 2,
    }

    /// <summary>proxToolMode: How a tool follows what moves it (docs/coupling.md).</summary>
    public enum ToolMode
    {
        /// <summary>
        /// The tool is where its device (or SetPose) puts it; the force comes from its LMDs (the paper's
        /// distance-to-force curve). The default.
        /// </summary>
        Free = 0,
        /// <summary>
        /// A proxy follows the device but never comes closer to another body than the safety distance;
        /// contacts are the proxy's, and the force is the virtual coupling, a spring-damper between device
        /// pose and proxy.
        /// </summary>
        Constrained = 1,
    }

    /// <summary>proxBodyDef</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct BodyDef
    {
        // PROX_API_VERSION, set by proxDefaultBodyDef()
        public int ApiVersion;
        public MeshId Mesh;
        public BodyType Type;
        public Pose Pose;
        // Tools: the point (in the body's frame) torques are taken about.
        public Vec3 ReferencePoint;
        // Tools: PROX_TOOL_FREE (default) or PROX_TOOL_CONSTRAINED.
        public ToolMode ToolMode;
        // PROX_TOOL_CONSTRAINED: the coupling between device pose and proxy, at the tool's reference point:
        // N/m, N s/m, N m/rad, N m s/rad (> 0, the dampings >= 0; defaults 1000, 2, 1, 0.002).
        public double CouplingStiffness;
        public double CouplingDamping;
        public double CouplingAngularStiffness;
        public double CouplingAngularDamping;
        public int InternalValue;
    }

    /// <summary>proxContact</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct Contact
    {
        // the body the tool is near
        public Body Other;
        // closest point on the tool, world
        public Vec3 PointTool;
        // closest point on the other body, world
        public Vec3 PointOther;
        // unit, from the other body to the tool
        public Vec3 Normal;
        // m, > 0
        public double Distance;
        public uint TriangleTool;
        public uint TriangleOther;
        // 0 vertex, 1 edge, 2 face
        public Feature FeatureTool;
        // 0 vertex, 1 edge, 2 face
        public Feature FeatureOther;
    }

    /// <summary>
    /// proxContactPatch: The patch a contact stands for (docs/patches.md): where the distance field is flat,
    /// LMDs merge into the closest of them, which weighs their count in the force.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct ContactPatch
    {
        // LMDs the contact stands for, itself included: 1 when nothing merged into it
        public int Count;
        readonly int reserved;
        // m: how far the farthest member's point on the tool is from the contact's
        public double Extent;
        // m: how much farther from the other body the farthest member is
        public double Spread;
        // radians: the largest angle between a member's direction and the contact's
        public double Angle;
    }

    /// <summary>proxWrench</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct Wrench
    {
        // N, on the tool, world frame
        public Vec3 Force;
        // N m, on the tool about its reference point, world frame
        public Vec3 Torque;
        public Bool32 Clipped;
    }

    /// <summary>proxPolylineInfo</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal partial struct PolylineInfo
    {
        // the body the tool's surface crosses
        public BodyId Other;
        // index of its first point in the points array
        public int FirstPoint;
        public int PointCount;
        // the last point joins the first
        public Bool32 Closed;
        public int Reserved;
    }

    /// <summary>proxWorldStats</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct WorldStats
    {
        public int Bodies;
        public int Tools;
        // tool-body pairs the broadphase kept in the last step
        public int PairsInRange;
        // ... of which ran a global search (the others had not moved)
        public int PairsSearched;
        // over all tools
        public int Contacts;
        // before reduction, over the pairs searched
        public int Candidates;
        public double StepSeconds;
    }

    /// <summary>
    /// proxPatchSettings: Patches (docs/patches.md): after the reduction, LMDs whose closest points on the
    /// tool lie within a radius of the closest one's and whose directions agree within an angle merge into
    /// one contact, the closest, which weighs the patch's count in the force.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct PatchSettings
    {
        // the radius as a share of the world's cutoff, finite, >= 0; 0: no merging
        public double RadiusOverCutoff;
        // in [0, 180]
        public double MaxAngleDegrees;
        // members at most this share of the cutoff farther than the closest, finite, >= 0
        public double MaxSpreadOverCutoff;
    }

    /// <summary>proxPatchStats</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct PatchStats
    {
        // Over the pairs searched in the last step (while the threads run: the global thread's last search):
        // LMDs after the reduction, before merging
        public int Lmds;
        // contacts kept: one per patch
        public int Patches;
        // lmds - patches: LMDs folded into a closer one's patch
        public int Merged;
        // LMDs in the largest patch
        public int LargestPatch;
        // Triangle pairs the global searches found crossing: an intersection of the two bodies, reported here
        // and never as contacts (proxBody_GetIntersections traces it).
        public ulong IntersectingPairs;
        // pairs searched with any
        public int IntersectingBodies;
        // Node pairs the bounded search cut (proxWorld_SetLeafBudget): each gave one representative instead
        // of all its LMDs, which are then not counted in lmds (the force errs low there). 0 when every search
        // stayed within its budget.
        public int CutNodePairs;
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern WorldDef proxDefaultWorldDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern MeshDef proxDefaultMeshDef();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern BodyDef proxDefaultBodyDef();
    }
}
