using Proxima;
using UnityEngine;

namespace Proxima.Unity
{
    /// <summary>Unity's frame to Proxima's, in one place: Unity is left-handed
    /// (x right, y up, z forward), Proxima right-handed; the conversion mirrors z
    /// and reverses each triangle's winding (see LeftHanded, which the tests check
    /// against the engine). Units: Unity's, read as metres.</summary>
    public static class UnityFrame
    {
        public static Vec3 ToProxima(Vector3 p) => LeftHanded.Point(p.x, p.y, p.z);

        public static Quat ToProxima(Quaternion q) => LeftHanded.Rotation(q.x, q.y, q.z, q.w);

        public static Pose ToProxima(Transform t) => new Pose(ToProxima(t.position), ToProxima(t.rotation));

        public static Vector3 ToUnity(Vec3 p)
        {
            LeftHanded.FromPoint(p, out double x, out double y, out double z);
            return new Vector3((float)x, (float)y, (float)z);
        }

        public static Quaternion ToUnity(Quat q)
        {
            LeftHanded.FromRotation(q, out double x, out double y, out double z, out double w);
            return new Quaternion((float)x, (float)y, (float)z, (float)w);
        }

        /// <summary>A torque (or any cross product) from Proxima's frame to Unity's.</summary>
        public static Vector3 TorqueToUnity(Vec3 t)
        {
            LeftHanded.FromTorque(t, out double x, out double y, out double z);
            return new Vector3((float)x, (float)y, (float)z);
        }

        /// <summary>A MeshFilter's mesh as a Proxima mesh: its vertices scaled by the
        /// transform's lossyScale (Proxima poses are rigid) and mirrored into Proxima's
        /// frame, its triangles' winding reversed with them.</summary>
        public static Mesh CreateMesh(World world, MeshFilter filter)
        {
            UnityEngine.Mesh source = filter.sharedMesh;
            if (source == null)
                throw new System.ArgumentException(filter.name + " has no mesh", nameof(filter));
            Vector3 scale = filter.transform.lossyScale;
            Vector3[] vertices = source.vertices;
            var positions = new double[vertices.Length * 3];
            for (int i = 0; i < vertices.Length; ++i)
            {
                Vec3 p = ToProxima(Vector3.Scale(vertices[i], scale));
                positions[3 * i] = p.X;
                positions[3 * i + 1] = p.Y;
                positions[3 * i + 2] = p.Z;
            }
            return world.CreateMesh(positions, LeftHanded.Triangles(source.triangles));
        }
    }
}
