using System;
using System.IO;
using NUnit.Framework;

namespace Proxima.Tests
{
    [TestFixture]
    public class MeshTests
    {
        World world;

        [SetUp]
        public void CreateWorld() { world = new World(); }

        [TearDown]
        public void DisposeWorld() { world.Dispose(); }

        [Test]
        public void CreateMeshFromArrays()
        {
            Mesh cube = Support.Cube(world);
            MeshInfo info = cube.Info;
            Assert.AreEqual(12u, info.TriangleCount);
            Assert.AreEqual(8u, info.VertexCount);
            Assert.AreEqual(0u, info.BoundaryEdges);
            Assert.AreEqual(new Vec3(-0.05, -0.05, -0.05), info.BoundsMin);
            Assert.AreEqual(new Vec3(0.05, 0.05, 0.05), info.BoundsMax);
            MeshStats stats = cube.Stats;
            Assert.AreEqual(8u, stats.InputVertices);
            Assert.AreEqual(12u, stats.InputTriangles);
            Assert.Greater(stats.HierarchyNodes, 0u);
            Assert.Greater(stats.HierarchyBytes, 0UL);
        }

        [Test]
        public void LoadMeshReadsTheBunny()
        {
            Mesh bunny = world.LoadMesh(Support.Asset("bunny.obj"));
            MeshInfo info = bunny.Info;
            Assert.AreEqual(27864u, info.TriangleCount, "MANIFEST.md");
            Assert.Less(info.BoundsMax.X - info.BoundsMin.X, 0.2, "metres");
        }

        [Test]
        public void LoadMeshFromBytesIsTheFilesMesh()
        {
            string path = Support.Asset("bunny.obj");
            Mesh fromFile = world.LoadMesh(path);
            Mesh fromBytes = world.LoadMesh(File.ReadAllBytes(path), "bunny.obj");
            fromFile.GetTriangles(out double[] p1, out uint[] i1);
            fromBytes.GetTriangles(out double[] p2, out uint[] i2);
            Assert.AreEqual(p1, p2);
            Assert.AreEqual(i1, i2);
            Support.Throws(Result.Unsupported, "a.stl", () => world.LoadMesh(File.ReadAllBytes(path), "a.stl"));
            Support.Throws(Result.InvalidArgument, "size is 0", () => world.LoadMesh(new byte[0], "a.obj"));
            Assert.Throws<ArgumentNullException>(() => world.LoadMesh((byte[])null, "a.obj"));
            Assert.Throws<ArgumentNullException>(() => world.LoadMesh(new byte[] { 1 }, null));
        }

        [Test]
        public void WarningsNameWhatLoadingSkipped()
        {
            // One triangle whose unused NORMAL accessor runs past its buffer view.
            var data = new byte[36];
            Buffer.BlockCopy(new float[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, 0, data, 0, 36);
            string gltf = "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":36,\"uri\":" +
                          "\"data:application/octet-stream;base64," + Convert.ToBase64String(data) + "\"}]," +
                          "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],\"accessors\":[" +
                          "{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"," +
                          "\"min\":[0,0,0],\"max\":[1,1,0]}," +
                          "{\"bufferView\":0,\"componentType\":5126,\"count\":30,\"type\":\"VEC3\"}]," +
                          "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1}}]}]," +
                          "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0}";
            string path = Path.Combine(Path.GetTempPath(), "proxima-bad-normal-" + Guid.NewGuid() + ".gltf");
            File.WriteAllText(path, gltf);
            try
            {
                Mesh mesh = world.LoadMesh(path);
                Assert.AreEqual(1u, mesh.Info.TriangleCount);
                string[] warnings = mesh.Warnings;
                Assert.AreEqual(1, warnings.Length, string.Join("|", warnings));
                StringAssert.Contains("NORMAL", warnings[0]);
                Assert.AreEqual(0, world.LoadMesh(Support.Asset("bunny.obj")).Warnings.Length);
                // The same bytes from memory: the same mesh, the same warning.
                Mesh fromBytes = world.LoadMesh(System.Text.Encoding.UTF8.GetBytes(gltf), "bad-normal.gltf");
                Assert.AreEqual(1u, fromBytes.Info.TriangleCount);
                Assert.AreEqual(1, fromBytes.Warnings.Length);
                StringAssert.Contains("bad-normal.gltf", fromBytes.Warnings[0]);
            }
            finally
            {
                File.Delete(path);
            }
        }

        [Test]
        public void TrianglesGiveBackTheWeldedMesh()
        {
            // The box with each triangle's vertices its own, as glTF seams split them.
            double[] box = Support.BoxPositions(new Vec3(0, 0, 0), new Vec3(1, 1, 1));
            uint[] boxIndices = Support.BoxIndices;
            var split = new double[boxIndices.Length * 3];
            var splitIndices = new uint[boxIndices.Length];
            for (int i = 0; i < boxIndices.Length; i++)
            {
                for (int c = 0; c < 3; c++) split[3 * i + c] = box[3 * boxIndices[i] + c];
                splitIndices[i] = (uint)i;
            }
            Mesh mesh = world.CreateMesh(split, splitIndices);
            mesh.GetTriangles(out double[] positions, out uint[] indices);
            Assert.AreEqual(3 * (int)mesh.Info.VertexCount, positions.Length);
            Assert.AreEqual(box.Length, positions.Length, "welded back to the box's corners");
            Assert.AreEqual(boxIndices.Length, indices.Length);
            // Every triangle the same three corners in the same order as the input's.
            for (int t = 0; t < indices.Length; t += 3)
                for (int k = 0; k < 3; k++)
                    for (int c = 0; c < 3; c++)
                        Assert.AreEqual(split[3 * (t + k) + c], positions[3 * indices[t + k] + c]);
        }

        [Test]
        public void SetVerticesDeformsTheMeshEveryBodyUses()
        {
            Mesh wallMesh = Support.Cube(world);
            Body wall = world.CreateBody(wallMesh, BodyType.Static, Pose.Identity);
            Body other = world.CreateBody(Support.Cube(world), BodyType.Movable,
                                          new Pose(new Vec3(0.104, 0, 0), Quat.Identity));
            Assert.AreEqual(0.004, wall.DistanceTo(other), 1e-12);
            // The wall's +x face 1.5 mm nearer.
            wallMesh.GetTriangles(out double[] positions, out uint[] _);
            for (int i = 0; i < positions.Length; i += 3)
                if (positions[i] > 0) positions[i] += 0.0015;
            wallMesh.SetVertices(positions);
            Assert.AreEqual(0.0515, wallMesh.Info.BoundsMax.X, 1e-15);
            Assert.AreEqual(0.0025, wall.DistanceTo(other), 1e-12);
            Support.Throws(Result.InvalidArgument, "vertexCount is 7",
                           () => wallMesh.SetVertices(new double[21]));
            positions[4] = double.NaN;
            Support.Throws(Result.InvalidArgument, "vertex 1 has a non-finite y", () => wallMesh.SetVertices(positions));
            Assert.Throws<ArgumentException>(() => wallMesh.SetVertices(new double[4]));
            Assert.Throws<ArgumentNullException>(() => wallMesh.SetVertices(null));
        }

        [Test]
        public void BadArraysAreNamed()
        {
            double[] p = Support.BoxPositions(new Vec3(0, 0, 0), new Vec3(1, 1, 1));
            var e = Assert.Throws<ArgumentNullException>(() => world.CreateMesh(null, Support.BoxIndices));
            Assert.AreEqual("positions", e.ParamName);
            Assert.AreEqual("indices", Assert.Throws<ArgumentNullException>(() => world.CreateMesh(p, null)).ParamName);
            var a = Assert.Throws<ArgumentException>(() => world.CreateMesh(new double[7], Support.BoxIndices));
            StringAssert.Contains("7 values", a.Message);
            a = Assert.Throws<ArgumentException>(() => world.CreateMesh(p, new uint[] { 0, 1 }));
            Assert.AreEqual("indices", a.ParamName);

            uint[] outOfRange = (uint[])Support.BoxIndices.Clone();
            outOfRange[5] = 8;
            Support.Throws(Result.InvalidMesh, "proxWorld_CreateMesh", () => world.CreateMesh(p, outOfRange));
            double[] nan = (double[])p.Clone();
            nan[7] = double.NaN;
            Support.Throws(Result.InvalidMesh, "vertex 2", () => world.CreateMesh(nan, Support.BoxIndices));
            Support.Throws(Result.InvalidMesh, "", () => world.CreateMesh(new double[0], new uint[0]));
        }

        [Test]
        public void BadFilesAreNamed()
        {
            Support.Throws(Result.File, "no-such-mesh.obj", () => world.LoadMesh("no-such-mesh.obj"));
            string broken = Path.Combine(Path.GetTempPath(), "proxima-csharp-broken.obj");
            File.WriteAllText(broken, "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
            try
            {
                Support.Throws(Result.Parse, "broken", () => world.LoadMesh(broken));
            }
            finally
            {
                File.Delete(broken);
            }
            Assert.Throws<ArgumentNullException>(() => world.LoadMesh(null));
        }

        [Test]
        public void DestroyedMeshesStayInvalid()
        {
            Mesh cube = Support.Cube(world);
            Mesh copy = cube;
            Body body = world.CreateBody(cube, BodyType.Static, Pose.Identity);
            Support.Throws(Result.InvalidArgument, "", cube.Destroy);
            Assert.IsTrue(cube.IsValid && body.IsValid);
            body.Destroy();
            Assert.IsFalse(body.IsValid);
            cube.Destroy();
            Assert.IsFalse(copy.IsValid);
            Support.Throws(Result.InvalidHandle, "does not name a live mesh", () => { MeshInfo _ = copy.Info; });
            Mesh again = Support.Cube(world);
            Assert.AreNotEqual(cube, again, "a reused slot has a new generation");
            Support.Throws(Result.InvalidHandle, "does not name a live mesh", cube.Destroy);
            Assert.IsTrue(default(Mesh).IsNull);
            Support.Throws(Result.InvalidHandle, "null id",
                           () => world.CreateBody(default(Mesh), BodyType.Static, Pose.Identity));
        }

        [Test]
        public void MeshesOfAnotherWorldAreRefused()
        {
            using (var other = new World())
            {
                Mesh foreign = Support.Cube(other);
                Support.Throws(Result.InvalidHandle, "another world",
                               () => world.CreateBody(foreign, BodyType.Static, Pose.Identity));
            }
        }
    }

    [TestFixture]
    public class BodyTests
    {
        World world;
        Mesh cube;

        [SetUp]
        public void CreateWorld()
        {
            world = new World();
            cube = Support.Cube(world);
        }

        [TearDown]
        public void DisposeWorld() { world.Dispose(); }

        [Test]
        public void PoseRoundTripsNormalised()
        {
            Body movable = world.CreateBody(cube, BodyType.Movable, Pose.Identity);
            movable.Pose = new Pose(new Vec3(1, 2, 3), new Quat(2, 0, 0, 0));
            Pose p = movable.Pose;
            Assert.AreEqual(new Vec3(1, 2, 3), p.Position);
            Assert.AreEqual(1.0, p.Rotation.W, 1e-15, "normalised on input");
            Quat q = Quat.FromAxisAngle(new Vec3(0, 0, 2), Math.PI / 2);
            movable.Pose = new Pose(Vec3.Zero, q);
            Assert.AreEqual(Math.Sqrt(0.5), movable.Pose.Rotation.Z, 1e-15);
        }

        [Test]
        public void BadPosesAreNamed()
        {
            Body movable = world.CreateBody(cube, BodyType.Movable, Pose.Identity);
            Support.Throws(Result.InvalidArgument, "zero quaternion",
                           () => movable.Pose = new Pose(Vec3.Zero, new Quat(0, 0, 0, 0)));
            Support.Throws(Result.InvalidArgument, "not finite",
                           () => movable.Pose = new Pose(new Vec3(double.NaN, 0, 0), Quat.Identity));
            Support.Throws(Result.InvalidArgument, "zero quaternion",
                           () => world.CreateBody(cube, BodyType.Tool, new Pose(Vec3.Zero, default(Quat))));
            Body rock = world.CreateBody(cube, BodyType.Static, Pose.Identity);
            Support.Throws(Result.InvalidArgument, "static", () => rock.Pose = Pose.Identity);
            Support.Throws(Result.InvalidArgument, "def->type",
                           () => world.CreateBody(cube, (BodyType)5, Pose.Identity));
        }

        [Test]
        public void ToolOnlyCallsRefuseOtherBodies()
        {
            Body rock = world.CreateBody(cube, BodyType.Static, Pose.Identity);
            Support.Throws(Result.InvalidArgument, "not a PROX_BODY_TOOL", () => rock.GetContacts());
            Support.Throws(Result.InvalidArgument, "not a PROX_BODY_TOOL", () => rock.GetContacts(new Contact[4]));
            Support.Throws(Result.InvalidArgument, "not a PROX_BODY_TOOL", () => rock.GetWrench());
            Support.Throws(Result.InvalidArgument, "not a PROX_BODY_TOOL", () => rock.GetIntersections());
        }

        [Test]
        public void DestroyedBodiesStayInvalid()
        {
            Body tool = world.CreateBody(cube, BodyType.Tool, Pose.Identity);
            Body copy = tool;
            tool.Destroy();
            Support.Throws(Result.InvalidHandle, "does not name a live body", () => { Pose _ = copy.Pose; });
            Support.Throws(Result.InvalidHandle, "does not name a live body", () => copy.GetContacts());
            Support.Throws(Result.InvalidHandle, "does not name a live body", () => copy.GetWrench());
            Support.Throws(Result.InvalidHandle, "does not name a live body", copy.Destroy);
            Body next = world.CreateBody(cube, BodyType.Tool, Pose.Identity);
            Assert.AreNotEqual(copy, next);
            Support.Throws(Result.InvalidHandle, "does not name a live body", () => copy.GetWrench());
            Support.Throws(Result.InvalidHandle, "null id", () => default(Body).GetWrench());
        }

        [Test]
        public void DistanceBetweenBodies()
        {
            Body a = world.CreateBody(cube, BodyType.Static, Pose.Identity);
            Body b = world.CreateBody(cube, BodyType.Movable, new Pose(new Vec3(0.13, 0, 0), Quat.Identity));
            Assert.AreEqual(0.03, a.DistanceTo(b), 1e-12);
            Assert.AreEqual(-1.0, a.DistanceTo(b, 0.01), "farther than the bound");
            b.Pose = new Pose(new Vec3(0.05, 0, 0), Quat.Identity);
            Assert.AreEqual(0.0, a.DistanceTo(b), "crossing");
            Support.Throws(Result.InvalidArgument, "same body", () => a.DistanceTo(a));
        }
    }
}
