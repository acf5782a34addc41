using System;
using System.Collections.Generic;

namespace Proxima
{
    /// <summary>A deforming mesh of a left-handed engine (Unity's frame, converted by
    /// LeftHanded as everywhere in the package) fed to a Proxima mesh every frame: a
    /// skinned character baked to vertex positions, blend shapes included.
    ///
    /// The engine's vertex array keeps its own order and its duplicated seam vertices
    /// (one per UV or normal side); Proxima welds identical positions, so its mesh has
    /// fewer vertices in another order. The map between them is built once, when the
    /// feed is made, from the mesh Proxima built (GetTriangles): each vertex that a
    /// triangle uses is looked up by its converted position among Proxima's welded
    /// vertices (welding is by exact position, -0 and 0 alike, so the lookup finds
    /// exactly the vertex it was welded into). When a pose parts the copies of a seam
    /// vertex, the first of them in the engine's order places Proxima's vertex (the
    /// rule the SDK's glTF rigs follow too). Feed allocates nothing: the positions it
    /// hands to Mesh.SetVertices live in an array made once. Game thread, as every
    /// mesh call; also while the threads run.</summary>
    public sealed class SkinFeed
    {
        readonly int[] welded;        // engine vertex -> Proxima vertex; -1: no kept triangle uses it
        readonly int[] placer;        // Proxima vertex -> the first engine vertex welded into it
        readonly double[] positions;  // what Feed hands to Mesh.SetVertices, made once

        /// <summary>The Proxima mesh the feed deforms.</summary>
        public Mesh Mesh { get; }

        /// <summary>How many vertices the engine's mesh has (what Feed takes).</summary>
        public int SourceVertexCount => welded.Length;

        /// <summary>How many vertices Proxima's mesh has after welding (Mesh.Info.VertexCount).</summary>
        public int VertexCount => placer.Length;

        /// <summary>Makes the Proxima mesh from the engine's vertices (x, y, z per vertex,
        /// left-handed) and triangles (three indices each, the engine's winding), converted
        /// by LeftHanded, and the feed that deforms it.</summary>
        public static SkinFeed Create(World world, float[] vertices, int[] triangles)
        {
            if (world == null) throw new ArgumentNullException(nameof(world));
            CheckVertices(vertices);
            var converted = new double[vertices.Length];
            for (int i = 0; i < vertices.Length; i += 3)
            {
                Vec3 p = LeftHanded.Point(vertices[i], vertices[i + 1], vertices[i + 2]);
                converted[i] = p.X;
                converted[i + 1] = p.Y;
                converted[i + 2] = p.Z;
            }
            Mesh mesh = world.CreateMesh(converted, LeftHanded.Triangles(triangles));
            try
            {
                return new SkinFeed(mesh, vertices, triangles);
            }
            catch
            {
                mesh.Destroy();
                throw;
            }
        }

        /// <summary>A feed for a mesh made from these vertices and triangles, converted by
        /// LeftHanded (as Create makes it). Refused when a vertex of Proxima's mesh is none
        /// of them.</summary>
        public SkinFeed(Mesh mesh, float[] vertices, int[] triangles)
        {
            CheckVertices(vertices);
            if (triangles == null) throw new ArgumentNullException(nameof(triangles));
            int count = vertices.Length / 3;
            mesh.GetTriangles(out double[] proxima, out uint[] _);
            var index = new Dictionary<Key, int>(proxima.Length / 3);
            for (int v = 0; v < proxima.Length / 3; ++v)
                index[new Key(proxima[3 * v], proxima[3 * v + 1], proxima[3 * v + 2])] = v;

            var used = new bool[count];
            foreach (int i in triangles)
            {
                if (i < 0 || i >= count)
                    throw new ArgumentException("triangles has vertex index " + i + ", out of range for " + count +
                                                " vertices", nameof(triangles));
                used[i] = true;
            }
            welded = new int[count];
            placer = new int[proxima.Length / 3];
            for (int v = 0; v < placer.Length; ++v) placer[v] = -1;
            for (int i = 0; i < count; ++i)
            {
                welded[i] = -1;
                if (!used[i]) continue;
                Vec3 p = LeftHanded.Point(vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]);
                if (!index.TryGetValue(new Key(p.X, p.Y, p.Z), out int v)) continue;  // only in dropped triangles
                welded[i] = v;
                if (placer[v] < 0) placer[v] = i;
            }
            for (int v = 0; v < placer.Length; ++v)
                if (placer[v] < 0)
                    throw new ArgumentException("the mesh's vertex " + v + " (" + proxima[3 * v] + ", " +
                                                proxima[3 * v + 1] + ", " + proxima[3 * v + 2] +
                                                ") is none of the given vertices, converted: the mesh was not made from them",
                                                nameof(mesh));
            Mesh = mesh;
            positions = new double[proxima.Length];
        }

        /// <summary>The Proxima vertex the engine's vertex `source` was welded into, or -1
        /// when no triangle Proxima kept uses it.</summary>
        public int ProximaVertex(int source) => welded[source];

        /// <summary>The engine's vertex that places Proxima's vertex `vertex`: the first
        /// of those welded into it.</summary>
        public int PlacingVertex(int vertex) => placer[vertex];

        /// <summary>Deforms the mesh: the engine's vertices in their new places (x, y, z per
        /// vertex, left-handed, the first `vertexCount` of `vertices`), which must be as
        /// many as it was made from. Allocates nothing. A non-finite coordinate is refused
        /// by Proxima naming its own vertex (see PlacingVertex); on any error the mesh
        /// keeps its shape.</summary>
        public void Feed(float[] vertices, int vertexCount)
        {
            if (vertices == null) throw new ArgumentNullException(nameof(vertices));
            if (vertexCount != welded.Length)
                throw new ArgumentException("vertexCount is " + vertexCount + " but the mesh was made from " +
                                            welded.Length + " vertices", nameof(vertexCount));
            if (vertices.Length < 3 * vertexCount)
                throw new ArgumentException("vertices holds " + vertices.Length + " floats, fewer than x, y, z for " +
                                            vertexCount + " vertices", nameof(vertices));
            for (int v = 0; v < placer.Length; ++v)
            {
                int i = 3 * placer[v];
                Vec3 p = LeftHanded.Point(vertices[i], vertices[i + 1], vertices[i + 2]);
                positions[3 * v] = p.X;
                positions[3 * v + 1] = p.Y;
                positions[3 * v + 2] = p.Z;
            }
            Mesh.SetVertices(positions);
        }

        static void CheckVertices(float[] vertices)
        {
            if (vertices == null) throw new ArgumentNullException(nameof(vertices));
            if (vertices.Length % 3 != 0)
                throw new ArgumentException("vertices holds x, y, z per vertex: its length " + vertices.Length +
                                            " is not a multiple of 3", nameof(vertices));
        }

        /// <summary>A position as Proxima welds it: exact, -0 the same as 0.</summary>
        readonly struct Key : IEquatable<Key>
        {
            readonly double x, y, z;

            public Key(double x, double y, double z)
            {
                // 0.0 == -0.0, so both fold to 0.0 (as the welder does).
                this.x = x == 0 ? 0.0 : x;
                this.y = y == 0 ? 0.0 : y;
                this.z = z == 0 ? 0.0 : z;
            }

            public bool Equals(Key o) => x == o.x && y == o.y && z == o.z;
            public override bool Equals(object obj) => obj is Key k && Equals(k);
            public override int GetHashCode()
            {
                long h = BitConverter.DoubleToInt64Bits(x);
                h = h * 31 + BitConverter.DoubleToInt64Bits(y);
                h = h * 31 + BitConverter.DoubleToInt64Bits(z);
                return (int)(h ^ (h >> 32));
            }
        }
    }
}
