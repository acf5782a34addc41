using Proxima;
using UnityEngine;

namespace Proxima.Unity
{
    /// <summary>Unity's frame to Proxima's, in one place. Unity is left-handed
    /// (x right, y up, z forward); Proxima is right-handed. The conversion
    /// mirrors z: a point (x, y, z) is (x, y, -z) in Proxima, a rotation
    /// (x, y, z, w) is (w, -x, -y, z), a force is a vector like a point, and a
    /// torque (an axial vector) is (-x, -y, z). The mirror also turns Unity's
    /// clockwise front faces into the counter-clockwise ones Proxima expects,
    /// so triangle indices are kept as they are. Units: Unity's metres.</summary>
    public static class UnityFrame
    {
        public static Vec3 ToProxima(Vector3 p) => new Vec3(p.x, p.y, -p.z);

        public static Quat ToProxima(Quaternion q) => new Quat(q.w, -q.x, -q.y, q.z);

        public static Pose ToProxima(Transform t) => new Pose(ToProxima(t.position), ToProxima(t.rotation));

        public static Vector3 ToUnity(Vec3 p) => new Vector3((float)p.X, (float)p.Y, (float)-p.Z);

        public static Quaternion ToUnity(Quat q) => new Quaternion((float)-q.X, (float)-q.Y, (float)q.Z, (float)q.W);

        /// <summary>A torque (or any cross product) from Proxima's frame to Unity's.</summary>
        public static Vector3 TorqueToUnity(Vec3 t) => new Vector3((float)-t.X, (float)-t.Y, (float)t.Z);

        /// <summary>A MeshFilter's mesh as a Proxima mesh: its vertices scaled by the
        /// transform's lossyScale (Proxima poses are rigid) and mirrored into Proxima's
        /// frame, its triangles as they are.</summary>
        public static Mesh CreateMesh(World world, MeshFilter filter)
        {
            UnityEngine.Mesh source = filter.sharedMesh;
            if (source == null)
                throw new System.ArgumentException(filter.name + " has no mesh", nameof(filter));
            Vector3 scale = filter.transform.lossyScale;
            Vector3[] vertices = source.vertices;
            int[] triangles = source.triangles;
            var positions = new double[vertices.Length * 3];
            for (int i = 0; i < vertices.Length; ++i)
            {
                Vec3 p = ToProxima(Vector3.Scale(vertices[i], scale));
                positions[3 * i] = p.X;
                positions[3 * i + 1] = p.Y;
                positions[3 * i + 2] = p.Z;
            }
            var indices = new uint[triangles.Length];
            for (int i = 0; i < triangles.Length; ++i) indices[i] = (uint)triangles[i];
            return world.CreateMesh(positions, indices);
        }
    }
}
