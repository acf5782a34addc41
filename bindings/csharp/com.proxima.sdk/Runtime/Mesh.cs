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

        public MeshInfo Info
        {
            get { Native.Check(Native.proxMesh_GetInfo(id, out MeshInfo info)); return info; }
        }

        public MeshStats Stats
        {
            get { Native.Check(Native.proxMesh_GetStats(id, out MeshStats s)); return s; }
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
