namespace Proxima
{
    /// <summary>Conversions between a left-handed frame (Unity's: x right, y up, z
    /// forward) and Proxima's right-handed one, by mirroring z. A point or a force
    /// (x, y, z) is (x, y, -z); a rotation (x, y, z, w) is (w, -x, -y, z); a torque,
    /// or any cross product, (x, y, z) is (-x, -y, z); a triangle (a, b, c) is
    /// (a, c, b). The last because in either frame a front face's normal is the
    /// standard cross product (b - a) x (c - a) (what Unity's RecalculateNormals
    /// computes and its clockwise-on-screen rule amounts to), and a mirror turns
    /// that product around. Applying a conversion twice gives back the input.
    /// Outside Unity too, for engines with the same convention.</summary>
    public static class LeftHanded
    {
        public static Vec3 Point(double x, double y, double z) => new Vec3(x, y, -z);

        /// <summary>Triangle indices, three per triangle, with each triangle's winding
        /// reversed for the mirrored frame (new array).</summary>
        public static uint[] Triangles(int[] indices)
        {
            if (indices == null) throw new System.ArgumentNullException(nameof(indices));
            if (indices.Length % 3 != 0)
                throw new System.ArgumentException("indices has " + indices.Length + " values, not three per triangle",
                                                   nameof(indices));
            var result = new uint[indices.Length];
            for (int t = 0; t < indices.Length; t += 3)
            {
                if (indices[t] < 0 || indices[t + 1] < 0 || indices[t + 2] < 0)
                    throw new System.ArgumentException("triangle " + t / 3 + " has a negative index", nameof(indices));
                result[t] = (uint)indices[t];
                result[t + 1] = (uint)indices[t + 2];
                result[t + 2] = (uint)indices[t + 1];
            }
            return result;
        }

        /// <summary>A left-handed frame's rotation quaternion, components (x, y, z, w).</summary>
        public static Quat Rotation(double x, double y, double z, double w) => new Quat(w, -x, -y, z);

        /// <summary>A point or force of Proxima's in the left-handed frame.</summary>
        public static void FromPoint(Vec3 p, out double x, out double y, out double z)
        {
            x = p.X;
            y = p.Y;
            z = -p.Z;
        }

        /// <summary>A rotation of Proxima's as the left-handed frame's (x, y, z, w).</summary>
        public static void FromRotation(Quat q, out double x, out double y, out double z, out double w)
        {
            x = -q.X;
            y = -q.Y;
            z = q.Z;
            w = q.W;
        }

        /// <summary>A torque of Proxima's (an axial vector) in the left-handed frame.</summary>
        public static void FromTorque(Vec3 t, out double x, out double y, out double z)
        {
            x = -t.X;
            y = -t.Y;
            z = t.Z;
        }
    }
}
