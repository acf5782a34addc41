using System;
using NUnit.Framework;

namespace Proxima.Tests
{
    /// <summary>The left-handed (Unity) frame's conversion: rotations, cross products and
    /// winding come out as a right-handed engine needs them.</summary>
    [TestFixture]
    public class LeftHandedTests
    {
        // q v q*, with q = (w, x, y, z): Unity's Quaternion * Vector3 and Proxima's
        // pose rotation are both this formula on their own components.
        static Vec3 Rotate(Quat q, Vec3 v)
        {
            var u = new Vec3(q.X, q.Y, q.Z);
            Vec3 t = 2.0 * Cross(u, v);
            return v + q.W * t + Cross(u, t);
        }

        static Vec3 Cross(Vec3 a, Vec3 b) =>
            new Vec3(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

        static void AreClose(Vec3 expected, Vec3 actual, string what)
        {
            Assert.AreEqual(0.0, (expected - actual).Length, 1e-12, what + ": " + expected + " against " + actual);
        }

        [Test]
        public void RotationsAndTorquesMirrorConsistently()
        {
            var random = new Random(11);
            for (int i = 0; i < 200; ++i)
            {
                Func<double> r = () => 2 * random.NextDouble() - 1;
                Quat unity = Quat.FromAxisAngle(new Vec3(r(), r(), r()), 3 * r());
                var v = new Vec3(r(), r(), r());
                var f = new Vec3(r(), r(), r());

                Vec3 rotatedInUnity = Rotate(unity, v);
                Quat proxima = LeftHanded.Rotation(unity.X, unity.Y, unity.Z, unity.W);
                Vec3 p = LeftHanded.Point(v.X, v.Y, v.Z);
                AreClose(LeftHanded.Point(rotatedInUnity.X, rotatedInUnity.Y, rotatedInUnity.Z), Rotate(proxima, p),
                         "rotating, then converting");

                Vec3 torqueInUnity = Cross(v, f);
                Vec3 torque = Cross(p, LeftHanded.Point(f.X, f.Y, f.Z));
                LeftHanded.FromTorque(torque, out double tx, out double ty, out double tz);
                AreClose(torqueInUnity, new Vec3(tx, ty, tz), "a cross product, back");

                LeftHanded.FromRotation(proxima, out double qx, out double qy, out double qz, out double qw);
                Assert.AreEqual(unity, new Quat(qw, qx, qy, qz), "a rotation, back");
                LeftHanded.FromPoint(p, out double x, out double y, out double z);
                Assert.AreEqual(v, new Vec3(x, y, z), "a point, back");
            }
        }

        static void FacesOut(double[] positions, uint[] indices, string frame)
        {
            for (int t = 0; t < indices.Length; t += 3)
            {
                Vec3 a = At(positions, indices[t]), b = At(positions, indices[t + 1]), c = At(positions, indices[t + 2]);
                Vec3 n = Cross(b - a, c - a);
                Vec3 centre = (1.0 / 3) * (a + b + c);
                Assert.Greater(n.X * centre.X + n.Y * centre.Y + n.Z * centre.Z, 0.0, frame + ": triangle " + t / 3 + " faces out");
            }
        }

        [Test]
        public void UnityMeshesBecomeOutwardFacing()
        {
            // The 10 cm cube as Unity holds it: the right-handed box's vertices with
            // z mirrored, and triangles whose standard cross product points out of the
            // cube, as Unity's RecalculateNormals would have it for front faces.
            double[] box = Support.BoxPositions(new Vec3(-0.05, -0.05, -0.05), new Vec3(0.05, 0.05, 0.05));
            var unityPositions = (double[])box.Clone();
            for (int v = 2; v < box.Length; v += 3) unityPositions[v] = -box[v];
            var unityTriangles = new int[Support.BoxIndices.Length];
            for (int t = 0; t < unityTriangles.Length; t += 3)
            {
                unityTriangles[t] = (int)Support.BoxIndices[t];
                unityTriangles[t + 1] = (int)Support.BoxIndices[t + 2];
                unityTriangles[t + 2] = (int)Support.BoxIndices[t + 1];
            }
            var asUint = Array.ConvertAll(unityTriangles, i => (uint)i);
            FacesOut(unityPositions, asUint, "Unity's frame");

            var converted = new double[box.Length];
            for (int v = 0; v < box.Length; v += 3)
            {
                Vec3 p = LeftHanded.Point(unityPositions[v], unityPositions[v + 1], unityPositions[v + 2]);
                converted[v] = p.X;
                converted[v + 1] = p.Y;
                converted[v + 2] = p.Z;
            }
            uint[] triangles = LeftHanded.Triangles(unityTriangles);
            FacesOut(converted, triangles, "Proxima's frame");

            // The engine agrees: the converted cube gives the contacts of the cube
            // built right-handed.
            using (var world = new World())
            {
                Mesh fromUnity = world.CreateMesh(converted, triangles);
                Mesh native = Support.Cube(world);
                world.CreateBody(fromUnity, BodyType.Static, Pose.Identity);
                Body tool = world.CreateBody(native, BodyType.Tool, new Pose(new Vec3(0.102, 0.01, -0.02), Quat.Identity));
                world.Step();
                Contact[] contacts = tool.GetContacts();
                Assert.Greater(contacts.Length, 0);
                foreach (Contact c in contacts)
                {
                    Assert.AreEqual(0.002, c.Distance, 1e-12);
                    AreClose(new Vec3(1, 0, 0), c.Normal, "from the cube to the tool");
                }
            }
        }

        [Test]
        public void BadTrianglesAreNamed()
        {
            Assert.Throws<ArgumentNullException>(() => LeftHanded.Triangles(null));
            StringAssert.Contains("4 values", Assert.Throws<ArgumentException>(() => LeftHanded.Triangles(new int[4])).Message);
            StringAssert.Contains("triangle 1", Assert.Throws<ArgumentException>(
                () => LeftHanded.Triangles(new[] { 0, 1, 2, 0, -1, 2 })).Message);
        }

        static Vec3 At(double[] p, uint i) => new Vec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    }
}
