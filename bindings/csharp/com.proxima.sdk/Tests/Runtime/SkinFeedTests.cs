using System;
using System.Reflection;
using NUnit.Framework;

namespace Proxima.Tests
{
    /// <summary>SkinFeed, what ProximaBody on a SkinnedMeshRenderer runs every frame,
    /// with a real world: a cube as Unity holds one (24 vertices, four per face, so
    /// each corner is three seam copies; left-handed, Unity's winding).</summary>
    [TestFixture]
    public class SkinFeedTests
    {
        const float H = 0.05f;
        World world;

        [SetUp]
        public void CreateWorld() { world = new World(); }

        [TearDown]
        public void DisposeWorld() { world.Dispose(); }

        // Face by face (axis a, side s): corners s*H on a, then +-H on the next two axes,
        // counter-clockwise about s*a, so that (b - a) x (c - a) points out in Unity's
        // numbers (its front faces), as a Unity mesh's do.
        static void UnityCube(out float[] vertices, out int[] triangles)
        {
            vertices = new float[24 * 3];
            triangles = new int[36];
            int[,] corners = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
            int n = 0, t = 0;
            for (int s = -1; s <= 1; s += 2)  // -x, -y, -z, +x, +y, +z: the welded order is not Unity's
                for (int a = 0; a < 3; ++a)
                {
                    int first = n;
                    for (int k = 0; k < 4; ++k, ++n)
                    {
                        vertices[3 * n + a] = s * H;
                        vertices[3 * n + (a + 1) % 3] = corners[k, 0] * H;
                        vertices[3 * n + (a + 2) % 3] = corners[k, 1] * H;
                    }
                    int[] quad = s > 0 ? new[] { 0, 1, 2, 0, 2, 3 } : new[] { 0, 2, 1, 0, 3, 2 };
                    foreach (int q in quad) triangles[t++] = first + q;
                }
        }

        static Vec3 Converted(float[] v, int i) => LeftHanded.Point(v[3 * i], v[3 * i + 1], v[3 * i + 2]);

        [Test]
        public void SeamCopiesMapToOneProximaVertex()
        {
            UnityCube(out float[] vertices, out int[] triangles);
            SkinFeed feed = SkinFeed.Create(world, vertices, triangles);
            Assert.AreEqual(24, feed.SourceVertexCount);
            Assert.AreEqual(8, feed.VertexCount);
            Assert.AreEqual(8u, feed.Mesh.Info.VertexCount);
            Assert.AreEqual(12u, feed.Mesh.Info.TriangleCount);
            Assert.AreEqual(0u, feed.Mesh.Info.BoundaryEdges, "the seams are welded shut");
            feed.Mesh.GetTriangles(out double[] p, out uint[] indices);
            for (int i = 0; i < 24; ++i)
            {
                int v = feed.ProximaVertex(i);
                Assert.AreEqual(Converted(vertices, i), new Vec3(p[3 * v], p[3 * v + 1], p[3 * v + 2]), "vertex " + i);
                int copies = 0;
                for (int j = 0; j < 24; ++j)
                {
                    bool samePlace = Converted(vertices, i).Equals(Converted(vertices, j));
                    Assert.AreEqual(samePlace, feed.ProximaVertex(j) == v, i + " and " + j);
                    if (samePlace) ++copies;
                }
                Assert.AreEqual(3, copies, "a cube's corner has three faces");
                Assert.LessOrEqual(feed.PlacingVertex(v), i, "the first copy places the vertex");
                Assert.AreEqual(v, feed.ProximaVertex(feed.PlacingVertex(v)));
            }
            // Converted, every triangle faces out of the cube (centred at the origin).
            for (int t = 0; t < indices.Length; t += 3)
            {
                Vec3 a = Corner(p, indices[t]), b = Corner(p, indices[t + 1]), c = Corner(p, indices[t + 2]);
                Vec3 u = b - a, w = c - a;
                var normal = new Vec3(u.Y * w.Z - u.Z * w.Y, u.Z * w.X - u.X * w.Z, u.X * w.Y - u.Y * w.X);
                Vec3 centre = (1.0 / 3) * (a + b + c);
                Assert.Greater(normal.X * centre.X + normal.Y * centre.Y + normal.Z * centre.Z, 0.0, "triangle " + t / 3);
            }
        }

        static Vec3 Corner(double[] p, uint v) => new Vec3(p[3 * v], p[3 * v + 1], p[3 * v + 2]);

        [Test]
        public void AFaceFed1Point5MmNearerIs1Point5MmNearer()
        {
            UnityCube(out float[] vertices, out int[] triangles);
            SkinFeed feed = SkinFeed.Create(world, vertices, triangles);
            Body skin = world.CreateBody(feed.Mesh, BodyType.Static, Pose.Identity);
            // Unity's +z face is Proxima's -z face; the other cube lies 1 cm beyond it.
            Body other = world.CreateBody(
                world.CreateMesh(Support.BoxPositions(new Vec3(-0.05, -0.05, -0.16), new Vec3(0.05, 0.05, -0.06)),
                                 Support.BoxIndices),
                BodyType.Movable, Pose.Identity);
            double before = skin.DistanceTo(other);
            Assert.AreEqual(0.06 - (double)H, before, 1e-15);

            // The +z face 1.5 mm nearer: all 12 Unity vertices at z = H, every seam copy.
            var posed = (float[])vertices.Clone();
            const float Moved = H + 0.0015f;
            int moved = 0;
            for (int i = 2; i < posed.Length; i += 3)
                if (posed[i] == H)
                {
                    posed[i] = Moved;
                    ++moved;
                }
            Assert.AreEqual(12, moved);
            feed.Feed(posed, 24);
            double after = skin.DistanceTo(other);
            Assert.AreEqual(0.06 - (double)Moved, after, 1e-15, "the deformed cube's distance");
            Assert.AreEqual(0.0015, before - after, 1e-8, "1.5 mm, to the floats' rounding");
            Assert.AreEqual(-(double)Moved, feed.Mesh.Info.BoundsMin.Z, 1e-15);
            feed.Mesh.GetTriangles(out double[] p, out uint[] _);
            for (int i = 0; i < 24; ++i)
                Assert.AreEqual(Converted(posed, i), Corner(p, (uint)feed.ProximaVertex(i)), "Unity vertex " + i);

            feed.Feed(vertices, 24);
            Assert.AreEqual(before, skin.DistanceTo(other), 1e-15, "back at rest");
        }

        [Test]
        public void WhenAPosePartsSeamCopiesTheFirstPlacesTheVertex()
        {
            UnityCube(out float[] vertices, out int[] triangles);
            SkinFeed feed = SkinFeed.Create(world, vertices, triangles);
            int v = feed.ProximaVertex(23);
            int first = feed.PlacingVertex(v);
            Assert.Less(first, 23);
            var posed = (float[])vertices.Clone();
            posed[3 * 23] += 0.01f;  // a later copy alone moves: not seen
            feed.Feed(posed, 24);
            feed.Mesh.GetTriangles(out double[] p, out uint[] indices);
            Assert.AreEqual(Converted(vertices, first), Corner(p, (uint)v));
            posed[3 * first] += 0.02f;  // the first copy moves: the vertex follows it
            feed.Feed(posed, 24);
            feed.Mesh.GetTriangles(out p, out indices);
            Assert.AreEqual(Converted(posed, first), Corner(p, (uint)v));
            Assert.AreNotEqual(Converted(vertices, first), Corner(p, (uint)v));
        }

        [Test]
        public void MisuseIsRefusedByName()
        {
            UnityCube(out float[] vertices, out int[] triangles);
            SkinFeed feed = SkinFeed.Create(world, vertices, triangles);
            Body skin = world.CreateBody(feed.Mesh, BodyType.Static, Pose.Identity);

            var e = Assert.Throws<ArgumentException>(() => feed.Feed(new float[23 * 3], 23));
            Assert.AreEqual("vertexCount", e.ParamName);
            StringAssert.Contains("vertexCount is 23 but the mesh was made from 24 vertices", e.Message);
            e = Assert.Throws<ArgumentException>(() => feed.Feed(new float[23 * 3], 24));
            Assert.AreEqual("vertices", e.ParamName);
            StringAssert.Contains("69 floats", e.Message);
            Assert.AreEqual("vertices", Assert.Throws<ArgumentNullException>(() => feed.Feed(null, 24)).ParamName);

            // A non-finite coordinate: Proxima names its own vertex, and the mesh keeps its shape.
            var posed = (float[])vertices.Clone();
            posed[3 * feed.PlacingVertex(3) + 1] = float.NaN;
            Support.Throws(Result.InvalidArgument, "vertex 3 has a non-finite y", () => feed.Feed(posed, 24));
            Assert.AreEqual(new Vec3(-0.05, -0.05, -0.05), Round(feed.Mesh.Info.BoundsMin));

            e = Assert.Throws<ArgumentException>(() => SkinFeed.Create(world, new float[7], triangles));
            Assert.AreEqual("vertices", e.ParamName);
            // A feed for a mesh made from other vertices.
            var shifted = (float[])vertices.Clone();
            for (int i = 0; i < shifted.Length; i += 3) shifted[i] += 0.001f;
            e = Assert.Throws<ArgumentException>(() => new SkinFeed(feed.Mesh, shifted, triangles));
            Assert.AreEqual("mesh", e.ParamName);
            StringAssert.Contains("the mesh was not made from them", e.Message);
            e = Assert.Throws<ArgumentException>(() => new SkinFeed(feed.Mesh, vertices, new[] { 0, 1, 24 }));
            Assert.AreEqual("triangles", e.ParamName);
            skin.Destroy();
        }

        static Vec3 Round(Vec3 v) => new Vec3(Math.Round(v.X, 6), Math.Round(v.Y, 6), Math.Round(v.Z, 6));

        [Test]
        public void RepeatedFeedsAllocateNothing()
        {
            UnityCube(out float[] vertices, out int[] triangles);
            SkinFeed feed = SkinFeed.Create(world, vertices, triangles);
            world.CreateBody(feed.Mesh, BodyType.Static, Pose.Identity);
            var posed = (float[])vertices.Clone();
            feed.Feed(posed, 24);  // the first call's JIT and the marshaller's stubs

            // GC.GetAllocatedBytesForCurrentThread counts every managed allocation of this
            // thread (Mono 6.8 has it, as .NET Core 3 and later do); looked up by name so the
            // suite also compiles where the API profile lacks it.
            MethodInfo counter = typeof(GC).GetMethod("GetAllocatedBytesForCurrentThread", Type.EmptyTypes);
            if (counter == null)
                Assert.Ignore("this runtime has no GC.GetAllocatedBytesForCurrentThread: allocations not measured");
            var allocated = (Func<long>)Delegate.CreateDelegate(typeof(Func<long>), counter);
            long before = allocated();
            for (int frame = 0; frame < 1000; ++frame)
            {
                posed[2] = -H - 0.00001f * (frame % 7);  // a shape that changes each frame
                feed.Feed(posed, 24);
            }
            long bytes = allocated() - before;
            Assert.AreEqual(0, bytes, "bytes allocated by 1000 feeds");
        }
    }
}
