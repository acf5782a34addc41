using System;
using System.Text;
using NUnit.Framework;

namespace Proxima.Tests
{
    /// <summary>glTF skins, morph targets and animation (docs/dynamic-scenes.md): a morphed
    /// triangle written here, its expected vertices worked out by hand.</summary>
    [TestFixture]
    public class RigTests
    {
        World world;

        [SetUp]
        public void CreateWorld() { world = new World(); }

        [TearDown]
        public void DisposeWorld() { world.Dispose(); }

        /// The unit right triangle in z = 0, one morph target lifting vertex 2 by 1 in z, and an
        /// animation "lift" of its weight, LINEAR from 0 at t = 0 to 1 at t = 2 s.
        static byte[] MorphedTriangle()
        {
            var floats = new float[] { 0, 0, 0, 1, 0, 0, 0, 1, 0,  0, 0, 0, 0, 0, 0, 0, 0, 1,  0, 2,  0, 1 };
            var data = new byte[4 * floats.Length];
            Buffer.BlockCopy(floats, 0, data, 0, data.Length);
            string json =
                "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}]," +
                "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"targets\":[{\"POSITION\":1}]}]}]," +
                "\"animations\":[{\"name\":\"lift\",\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"weights\"}}]," +
                "\"samplers\":[{\"input\":2,\"output\":3}]}]," +
                "\"buffers\":[{\"byteLength\":88,\"uri\":\"data:application/octet-stream;base64," +
                Convert.ToBase64String(data) + "\"}]," +
                "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36,\"byteLength\":36}," +
                "{\"buffer\":0,\"byteOffset\":72,\"byteLength\":8},{\"buffer\":0,\"byteOffset\":80,\"byteLength\":8}]," +
                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}," +
                "{\"bufferView\":1,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}," +
                "{\"bufferView\":2,\"componentType\":5126,\"count\":2,\"type\":\"SCALAR\"}," +
                "{\"bufferView\":3,\"componentType\":5126,\"count\":2,\"type\":\"SCALAR\"}]}";
            return Encoding.UTF8.GetBytes(json);
        }

        /// The z of the vertex at (0, 1).
        static double LiftedZ(Mesh mesh)
        {
            mesh.GetTriangles(out double[] p, out uint[] unused);
            for (int v = 0; v < p.Length / 3; ++v)
                if (p[3 * v] == 0 && p[3 * v + 1] == 1) return p[3 * v + 2];
            throw new InvalidOperationException("no vertex at (0, 1)");
        }

        [Test]
        public void AnimationsAndAnimate()
        {
            Mesh mesh = world.LoadMesh(MorphedTriangle(), "morph.gltf");
            AnimationInfo[] animations = mesh.Animations;
            Assert.AreEqual(1, animations.Length);
            Assert.AreEqual("lift", animations[0].Name);
            Assert.AreEqual(2.0, animations[0].Duration);
            Assert.AreEqual(0.0, animations[0].Start);
            Assert.AreEqual(1, animations[0].ChannelCount);
            Assert.AreEqual(1, mesh.Rig.MorphWeightCount);
            Assert.AreEqual(0, mesh.Skins.Length);
            Assert.AreEqual(0.0, LiftedZ(mesh));
            mesh.Animate(0, 1.5);  // weight 0.75
            Assert.AreEqual(0.75, LiftedZ(mesh), 1e-15);
            mesh.SetMorphWeights(new[] { 0.25 });
            Assert.AreEqual(0.25, LiftedZ(mesh));
        }

        [Test]
        public void MisuseIsRefusedByName()
        {
            Mesh mesh = world.LoadMesh(MorphedTriangle(), "morph.gltf");
            var e = Assert.Throws<ProximaException>(() => mesh.Animate(1, 0.0));
            StringAssert.Contains("animation 1 does not exist", e.Message);
            e = Assert.Throws<ProximaException>(() => mesh.SetMorphWeights(new[] { 0.1, 0.2 }));
            StringAssert.Contains("count is 2 but the mesh has 1 morph weights", e.Message);
            e = Assert.Throws<ProximaException>(() => mesh.SetJointMatrices(0, new double[16]));
            StringAssert.Contains("skin 0 does not exist", e.Message);
            Assert.Throws<ArgumentException>(() => mesh.SetJointMatrices(0, new double[15]));
        }
    }
}
