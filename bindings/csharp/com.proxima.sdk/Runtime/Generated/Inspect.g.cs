// Generated from sdk/include/proxima/inspect.h by bindings/csharp/tools/gen_native.py:
// do not edit. Regenerate with `python3 bindings/csharp/tools/gen_native.py`
// (docs/csharp.md); ctest csharp.generated fails while this file is stale.
using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>
    /// proxForcePreset: What the proxima command-line tool and the benchmarks report: the force presets, mesh
    /// and hierarchy figures, the search and tracking statistics of the deterministic step, local tracking on
    /// its own, intersection statistics and the exact minimum distance between two bodies.
    /// </summary>
    public enum ForcePreset
    {
        /// <summary>exponential; safety 0.3 mm, decay 0.3 mm, cutoff 5 mm: the default</summary>
        Hard = 0,
        /// <summary>linear; safety 2 mm, cutoff 10 mm</summary>
        Soft = 1,
    }

    /// <summary>proxMeshStats</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct MeshStats
    {
        // as given, before welding
        public uint InputVertices;
        // as given, before dropping those that repeat a vertex
        public uint InputTriangles;
        // distinct vertices but collinear: kept
        public uint ZeroAreaTriangles;
        // the spatialized normal cone hierarchy (SNCH)
        public uint HierarchyNodes;
        public uint HierarchyLeaves;
        // edges on the longest root-to-leaf path
        public uint HierarchyDepth;
        // leaves whose normal cone holds every direction
        public uint UnboundedLeafCones;
        readonly uint reserved;
        // memory of the hierarchy
        public ulong HierarchyBytes;
        // time it took to build
        public double HierarchySeconds;
    }

    /// <summary>proxSearchStats</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct SearchStats
    {
        // tool-body pairs whose global search ran in the last step
        public int PairsSearched;
        readonly int reserved;
        // Summed over those pairs: node pairs visited
        public ulong NodePairs;
        // triangle pairs reaching the leaf tests
        public ulong LeafPairs;
        // precise: a triangle beyond the other's plane by more than the cutoff
        public ulong PlaneRejections;
        // precise: culled by the visibility pre-test
        public ulong VisibilityRejections;
        // original: culled by the G5 normal check
        public ulong NormalRejections;
        // exact distances (precise) or 7 x 7 samplings (original)
        public ulong DistanceEvaluations;
        // pairs the global searches output, before reduction
        public ulong Candidates;
        // tracking-cache hits of the reduction passes
        public ulong ReductionCacheHits;
        // in the global searches
        public double GlobalSeconds;
        // in the reduction passes that follow them
        public double ReductionSeconds;
    }

    /// <summary>proxTrackStats</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct TrackStats
    {
        // tool-body pairs tracked by the last proxWorld_Track
        public int PairsTracked;
        // contacts before
        public int ContactsIn;
        // ... and after
        public int ContactsOut;
        readonly int reserved;
        // exact triangle distances computed
        public ulong DistanceEvaluations;
        // ... and answered from the tracking cache instead
        public ulong CacheHits;
        // walks to a closer neighbouring pair
        public ulong Moves;
        // the whole call
        public double Seconds;
    }

    /// <summary>proxIntersectionStats</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct IntersectionStats
    {
        // tested: their bounding spheres overlap
        public ulong TrianglePairs;
        // share a point (exact)
        public ulong IntersectingPairs;
        // overlap in one plane: regions, not in the polylines
        public ulong CoplanarPairs;
        // of the polylines, before joining
        public ulong Segments;
        public double Seconds;
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxGetForcePreset(ForcePreset preset, out ForceSettings force, out double cutoff);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxGetForcePresetAt(ForcePreset preset, double cutoff, out ForceSettings force);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxMesh_GetStats(MeshId mesh, out MeshStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetSearchStats(WorldId world, out SearchStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_Track(WorldId world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxWorld_GetTrackStats(WorldId world, out TrackStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetIntersectionStats(BodyId tool, out IntersectionStats stats);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Result proxBody_GetDistance(BodyId a, BodyId b, double maxDistance, out double distance);
    }
}
