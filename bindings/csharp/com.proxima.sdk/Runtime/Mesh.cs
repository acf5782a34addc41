using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>A mesh of a world (proxMeshId): a value, copy it freely. Its hierarchy
    /// is built once and shared by every body using it. A destroyed mesh's value
    /// stays invalid forever: using it throws (InvalidHandle).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct Mesh : IEquatable<Mesh>
    {
        internal readonly MeshId id;

        internal Mesh(MeshId id) { this.id = id; }

        /// <summary>Zero-initialised: names no mesh.</summary>
        public bool IsNull => id.Index1 == 0;

        /// <summary>Whether the mesh is alive in a live world. Game thread: false from any other.</summary>
        public bool IsValid => Native.proxMesh_IsValid(id);

        public MeshInfo Info
        {
            get { Native.Check(Native.proxMesh_GetInfo(id, out MeshInfo info)); return info; }
        }

        public MeshStats Stats
        {
            get { Native.Check(Native.proxMesh_GetStats(id, out MeshStats s)); return s; }
        }

        /// <summary>What loading the mesh's file skipped without failing (invalid attributes
        /// Proxima does not read), one string per warning; empty for none.</summary>
        public string[] Warnings
        {
            get
            {
                Result r = Native.proxMesh_GetWarnings(id, null, 0, out int length);
                if (r != Result.Success && r != Result.Capacity) throw ProximaException.FromLastError(r);
                if (length == 0) return new string[0];
                var buffer = new byte[length + 1];
                Native.Check(Native.proxMesh_GetWarnings(id, buffer, buffer.Length, out length));
                string text = System.Text.Encoding.UTF8.GetString(buffer, 0, length);
                return text.Split(new[] { '\n' }, StringSplitOptions.RemoveEmptyEntries);
            }
        }

        /// <summary>The mesh as Proxima uses it, in its own frame, after welding and dropping
        /// the triangles that repeat a vertex (the counts of Info): x, y, z per vertex
        /// and three vertex indices per triangle, counter-clockwise seen from outside.
        /// For drawing a mesh loaded from a file (a Unity Mesh's vertices and triangles).</summary>
        public void GetTriangles(out double[] positions, out uint[] indices)
        {
            Result r = Native.proxMesh_GetTriangles(id, null, 0, out uint vertices, null, 0, out uint triangles);
            if (r != Result.Success && r != Result.Capacity) throw ProximaException.FromLastError(r);
            positions = new double[3 * (long)vertices];
            indices = new uint[3 * (long)triangles];
            Native.Check(Native.proxMesh_GetTriangles(id, positions, vertices, out vertices, indices, triangles,
                                                      out triangles));
        }

        /// <summary>Deforms the mesh: x, y, z per vertex in the order GetTriangles hands them out, as
        /// many vertices as the mesh has (Info.VertexCount). The bodies using it take the new shape;
        /// also while the threads run, at frame rate (docs/dynamic-scenes.md). Game thread.</summary>
        public void SetVertices(double[] positions)
        {
            if (positions == null) throw new ArgumentNullException(nameof(positions));
            if (positions.Length % 3 != 0)
                throw new ArgumentException("positions holds x, y, z per vertex: its length " + positions.Length +
                                            " is not a multiple of 3", nameof(positions));
            Native.Check(Native.proxMesh_SetVertices(id, positions, (uint)(positions.Length / 3)));
        }

        // ---- glTF skins, morph targets and animation (docs/dynamic-scenes.md) ----

        /// <summary>What the mesh's glTF rig holds; zeros for a mesh without one.</summary>
        public RigInfo Rig
        {
            get { Native.Check(Native.proxMesh_GetRigInfo(id, out RigInfo info)); return info; }
        }

        /// <summary>The rig's skins, in the file's order (their joint counts are what
        /// SetJointMatrices takes); empty for none.</summary>
        public SkinInfo[] Skins
        {
            get
            {
                var skins = new SkinInfo[Rig.SkinCount];
                for (int s = 0; s < skins.Length; ++s) Native.Check(Native.proxMesh_GetSkinInfo(id, s, out skins[s]));
                return skins;
            }
        }

        /// <summary>The glTF scene's animations, in the file's order; empty for none.</summary>
        public AnimationInfo[] Animations
        {
            get
            {
                Native.Check(Native.proxMesh_GetAnimationCount(id, out int count));
                var animations = new AnimationInfo[count];
                for (int a = 0; a < count; ++a) Native.Check(Native.proxMesh_GetAnimationInfo(id, a, out animations[a]));
                return animations;
            }
        }

        /// <summary>Poses the mesh at animation `animation` (an index of Animations) at `seconds`:
        /// nodes, skins and morph weights; its vertices are replaced, as SetVertices does.
        /// Drops joint matrices and morph weights set before. Game thread.</summary>
        public void Animate(int animation, double seconds) =>
            Native.Check(Native.proxMesh_Animate(id, animation, seconds));

        /// <summary>Your animation system drives skin `skin`: its joints' WORLD matrices, 16 doubles
        /// each, column-major (element 4 * column + row; translation in 12, 13, 14), affine, in the
        /// mesh's frame, one per joint in the skin's order; Proxima applies the file's inverse bind
        /// matrices. Until the next Animate. Game thread.</summary>
        public void SetJointMatrices(int skin, double[] matrices)
        {
            if (matrices == null) throw new ArgumentNullException(nameof(matrices));
            if (matrices.Length % 16 != 0)
                throw new ArgumentException("matrices holds 16 doubles per joint: its length " + matrices.Length +
                                            " is not a multiple of 16", nameof(matrices));
            Native.Check(Native.proxMesh_SetJointMatrices(id, skin, matrices, matrices.Length / 16));
        }

        /// <summary>Every morphed mesh instance's weights, one after the other in scene order
        /// (Rig.MorphWeightCount of them). Until the next Animate. Game thread.</summary>
        public void SetMorphWeights(double[] weights)
        {
            if (weights == null) throw new ArgumentNullException(nameof(weights));
            Native.Check(Native.proxMesh_SetMorphWeights(id, weights, weights.Length));
        }

        /// <summary>Fails while bodies use the mesh.</summary>
        public void Destroy() => Native.Check(Native.proxMesh_Destroy(id));

        public bool Equals(Mesh o) =>
            id.Index1 == o.id.Index1 && id.Generation == o.id.Generation &&
            id.World.Index1 == o.id.World.Index1 && id.World.Generation == o.id.World.Generation;
        public override bool Equals(object obj) => obj is Mesh m && Equals(m);
        public override int GetHashCode() => (int)(id.Index1 * 31 + id.Generation) ^ (int)(id.World.Index1 << 20);
        public static bool operator ==(Mesh a, Mesh b) => a.Equals(b);
        public static bool operator !=(Mesh a, Mesh b) => !a.Equals(b);
        public override string ToString() => "Mesh(" + id.Index1 + "/" + id.Generation + ")";
    }
}
