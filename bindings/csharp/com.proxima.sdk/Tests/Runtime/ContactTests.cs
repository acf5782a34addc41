using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Runtime.Serialization;
using System.Runtime.Serialization.Json;
using NUnit.Framework;

namespace Proxima.Tests
{
    /// <summary>Contacts, wrench and intersections, against the C API's own answer.</summary>
    [TestFixture]
    public class ContactTests
    {
        // The proxima tool's `lmd --json` output (docs/cli.md), the keys this test reads.
        [DataContract]
        class LmdReport
        {
            [DataMember(Name = "lmds")] public Lmd[] Lmds = null;
            [DataMember(Name = "force")] public double[] Force = null;
            [DataMember(Name = "torque")] public double[] Torque = null;
        }

        [DataContract]
        class Lmd
        {
            [DataMember(Name = "tri_a")] public uint TriA = 0;
            [DataMember(Name = "tri_b")] public uint TriB = 0;
            [DataMember(Name = "point_a")] public double[] PointA = null;
            [DataMember(Name = "point_b")] public double[] PointB = null;
            [DataMember(Name = "distance")] public double Distance = 0;
            [DataMember(Name = "feature_a")] public string FeatureA = null;
            [DataMember(Name = "feature_b")] public string FeatureB = null;
        }

        // A pose of the held bunny with three LMDs against the one at the identity.
        static readonly Pose Near = new Pose(new Vec3(0.135, 0.002, 0), new Quat(0.999, 0, 0.04, 0));

        static LmdReport RunCli(string bunny, Pose b, Method method, ForcePreset force, double cutoff)
        {
            string json = Path.Combine(Path.GetTempPath(), "proxima-csharp-lmd-" + Process.GetCurrentProcess().Id + ".json");
            var args = string.Format(CultureInfo.InvariantCulture,
                                     "lmd \"{0}\" \"{0}\" --pose-b {1:R} {2:R} {3:R} {4:R} {5:R} {6:R} {7:R} --json \"{8}\" " +
                                     "--method {9} --force {10} --cutoff {11:R}",
                                     bunny, b.Position.X, b.Position.Y, b.Position.Z, b.Rotation.W, b.Rotation.X,
                                     b.Rotation.Y, b.Rotation.Z, json, method.ToString().ToLowerInvariant(),
                                     force.ToString().ToLowerInvariant(), cutoff);
            var start = new ProcessStartInfo(Support.Program("PROXIMA_CLI"), args)
            {
                UseShellExecute = false,
                RedirectStandardOutput = true,
            };
            using (Process p = Process.Start(start))
            {
                p.StandardOutput.ReadToEnd();
                p.WaitForExit();
                Assert.AreEqual(0, p.ExitCode, "proxima " + args);
            }
            try
            {
                using (FileStream f = File.OpenRead(json))
                    return (LmdReport)new DataContractJsonSerializer(typeof(LmdReport)).ReadObject(f);
            }
            finally
            {
                File.Delete(json);
            }
        }

        static void AreEqual(double[] expected, Vec3 actual, string what)
        {
            Assert.AreEqual(expected[0], actual.X, 1e-12, what + ".X");
            Assert.AreEqual(expected[1], actual.Y, 1e-12, what + ".Y");
            Assert.AreEqual(expected[2], actual.Z, 1e-12, what + ".Z");
        }

        [TestCase(Method.Precise, ForcePreset.Hard)]
        [TestCase(Method.Original, ForcePreset.Soft)]
        public void ContactsAreTheCApisOnTheBunny(Method method, ForcePreset force)
        {
            string path = Support.Asset("bunny.obj");
            ForceSettings.FromPreset(force, out double cutoff);
            LmdReport expected = RunCli(path, Near, method, force, cutoff);
            Assert.GreaterOrEqual(expected.Lmds.Length, 3, "the scene this test was written for");

            using (var world = new World(new WorldSettings { Method = method, Force = force }))
            {
                Mesh bunny = world.LoadMesh(path);
                MeshInfo info = bunny.Info;
                Vec3 centre = 0.5 * (info.BoundsMin + info.BoundsMax);
                Body rock = world.CreateBody(bunny, BodyType.Static, Pose.Identity);
                Body tool = world.CreateBody(bunny, BodyType.Tool, Near, centre);
                world.Step();
                Contact[] contacts = tool.GetContacts();
                Assert.AreEqual(expected.Lmds.Length, contacts.Length);
                foreach (Lmd lmd in expected.Lmds)
                {
                    Contact c = Array.Find(contacts, x => x.TriangleOther == lmd.TriA && x.TriangleTool == lmd.TriB);
                    string what = "LMD " + lmd.TriA + "-" + lmd.TriB;
                    Assert.AreEqual(rock, c.Other, what + " (missing?)");
                    AreEqual(lmd.PointA, c.PointOther, what + " PointOther");
                    AreEqual(lmd.PointB, c.PointTool, what + " PointTool");
                    Assert.AreEqual(lmd.Distance, c.Distance, 1e-15, what);
                    Assert.AreEqual(lmd.FeatureA, c.FeatureOther.ToString().ToLowerInvariant(), what);
                    Assert.AreEqual(lmd.FeatureB, c.FeatureTool.ToString().ToLowerInvariant(), what);
                    Vec3 d = c.PointTool - c.PointOther;
                    Assert.AreEqual(c.Distance, d.Length, 1e-12);
                    Assert.AreEqual(1.0, c.Normal.Length, 1e-12);
                    Assert.AreEqual(d.X / d.Length, c.Normal.X, 1e-12, "from the other body to the tool");
                }
                Wrench w = tool.GetWrench();
                AreEqual(expected.Force, w.Force, "force");
                AreEqual(expected.Torque, w.Torque, "torque");
            }
        }

        [Test]
        public void ContactsIntoTheCallersArray()
        {
            using (var world = new World())
            {
                Mesh bunny = world.LoadMesh(Support.Asset("bunny.obj"));
                world.CreateBody(bunny, BodyType.Static, Pose.Identity);
                Body tool = world.CreateBody(bunny, BodyType.Tool, Near);
                var buffer = new Contact[8];
                Assert.AreEqual(0, tool.GetContacts(buffer), "before the first step");
                world.Step();
                Contact[] all = tool.GetContacts();
                Assert.AreEqual(3, all.Length);
                Assert.AreEqual(3, tool.GetContacts(buffer));
                for (int i = 0; i < all.Length; ++i)
                    Assert.AreEqual(all[i].PointTool, buffer[i].PointTool);
                Assert.AreEqual(default(Contact).Distance, buffer[3].Distance, "untouched past the count");
                var small = new Contact[1];
                Assert.AreEqual(3, tool.GetContacts(small), "the count, though only one fits");
                Assert.AreEqual(all[0].TriangleTool, small[0].TriangleTool);
                Assert.AreEqual(3, tool.GetContacts(new Contact[0]));
                Assert.Throws<ArgumentNullException>(() => tool.GetContacts(null));

                // The overload allocates nothing: the loop a game runs every frame.
                long before = GC.GetTotalMemory(false);
                for (int i = 0; i < 10000; ++i) tool.GetContacts(buffer);
                long grown = GC.GetTotalMemory(false) - before;
                Assert.Less(grown, 64 * 1024, "bytes allocated by 10000 calls");
            }
        }

        [Test]
        public void IntersectionsOfTwoCubes()
        {
            using (var world = new World())
            {
                Mesh cube = Support.Cube(world);
                Body rock = world.CreateBody(cube, BodyType.Static, Pose.Identity);
                var offset = new Vec3(0.06, 0.01, 0.02);
                Body tool = world.CreateBody(cube, BodyType.Tool, new Pose(offset, Quat.Identity));
                Assert.AreEqual(default(IntersectionStats).Segments, tool.IntersectionStats.Segments);
                Polyline[] lines = tool.GetIntersections();
                Assert.AreEqual(1, lines.Length);
                Assert.AreEqual(rock, lines[0].Other);
                Assert.IsTrue(lines[0].Closed);
                Assert.GreaterOrEqual(lines[0].Points.Length, 4);
                foreach (Vec3 p in lines[0].Points)
                {
                    Vec3 q = p - offset;
                    Assert.AreEqual(0.05, Math.Max(Math.Abs(p.X), Math.Max(Math.Abs(p.Y), Math.Abs(p.Z))), 1e-12, "on the rock");
                    Assert.AreEqual(0.05, Math.Max(Math.Abs(q.X), Math.Max(Math.Abs(q.Y), Math.Abs(q.Z))), 1e-12, "on the tool");
                }
                IntersectionStats s = tool.IntersectionStats;
                Assert.Greater(s.IntersectingPairs, 0UL);
                Assert.Greater(s.Segments, 0UL);

                tool.Pose = new Pose(new Vec3(0.5, 0, 0), Quat.Identity);
                Assert.AreEqual(0, tool.GetIntersections().Length, "apart");
            }
        }
    }
}
