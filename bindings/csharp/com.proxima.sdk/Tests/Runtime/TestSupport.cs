using System;
using System.IO;
using NUnit.Framework;

namespace Proxima.Tests
{
    /// <summary>The scenes and checks the fixtures share.</summary>
    internal static class Support
    {
        /// <summary>The shared assets (bunny.obj): $PROXIMA_ASSETS. A test that needs
        /// them fails, not skips, when they are missing.</summary>
        public static string Asset(string name)
        {
            string dir = Environment.GetEnvironmentVariable("PROXIMA_ASSETS");
            if (string.IsNullOrEmpty(dir)) Assert.Fail("PROXIMA_ASSETS is not set: it names the shared assets' directory");
            string path = Path.Combine(dir, name);
            if (!File.Exists(path)) Assert.Fail(path + " does not exist");
            return path;
        }

        /// <summary>A program the build made, named by an environment variable.</summary>
        public static string Program(string variable)
        {
            string path = Environment.GetEnvironmentVariable(variable);
            if (string.IsNullOrEmpty(path) || !File.Exists(path))
                Assert.Fail(variable + " must name the program built for this test (it is '" + path + "')");
            return path;
        }

        // An axis-aligned box from lo to hi: 8 vertices, 12 triangles, counter-clockwise outside.
        public static double[] BoxPositions(Vec3 lo, Vec3 hi) => new[]
        {
            lo.X, lo.Y, lo.Z, hi.X, lo.Y, lo.Z, hi.X, hi.Y, lo.Z, lo.X, hi.Y, lo.Z,
            lo.X, lo.Y, hi.Z, hi.X, lo.Y, hi.Z, hi.X, hi.Y, hi.Z, lo.X, hi.Y, hi.Z,
        };

        public static readonly uint[] BoxIndices =
        {
            0, 2, 1, 0, 3, 2, // -z
            4, 5, 6, 4, 6, 7, // +z
            0, 1, 5, 0, 5, 4, // -y
            3, 6, 2, 3, 7, 6, // +y
            0, 4, 7, 0, 7, 3, // -x
            1, 2, 6, 1, 6, 5, // +x
        };

        /// <summary>A 10 cm cube centred at the origin.</summary>
        public static Mesh Cube(World world) =>
            world.CreateMesh(BoxPositions(new Vec3(-0.05, -0.05, -0.05), new Vec3(0.05, 0.05, 0.05)), BoxIndices);

        /// <summary>Runs the call, which must fail with `result` and a message containing `text`.</summary>
        public static ProximaException Throws(Result result, string text, TestDelegate call)
        {
            var e = Assert.Throws<ProximaException>(call);
            Assert.AreEqual(result, e.Result, e.Message);
            StringAssert.Contains(text, e.Message);
            StringAssert.StartsWith(ProximaException.ResultName(result), e.Message);
            return e;
        }
    }
}
