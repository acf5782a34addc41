using System;
using NUnit.Framework;

namespace Proxima.Tests
{
    [TestFixture]
    public class VersionTests
    {
        [Test]
        public void LibraryIsTheBindingsVersion()
        {
            Version lib = Version.Library, bound = Version.Binding;
            Assert.AreEqual(bound.Major, lib.Major);
            Assert.AreEqual(bound.Minor, lib.Minor);
            Assert.DoesNotThrow(Version.Check);
            StringAssert.IsMatch(@"^\d+\.\d+\.\d+$", lib.ToString());
        }

        [Test]
        public void ResultNamesAreTheCNames()
        {
            Assert.AreEqual("PROX_SUCCESS", ProximaException.ResultName(Result.Success));
            Assert.AreEqual("PROX_ERROR_INVALID_HANDLE", ProximaException.ResultName(Result.InvalidHandle));
            Assert.AreEqual("PROX_ERROR_BUSY", ProximaException.ResultName(Result.Busy));
        }

        [Test]
        public void PresetsAreTheLibrarys()
        {
            ForceSettings hard = ForceSettings.FromPreset(ForcePreset.Hard, out double hardCutoff);
            ForceSettings soft = ForceSettings.FromPreset(ForcePreset.Soft, out double softCutoff);
            Assert.AreEqual(ForceCurve.Exponential, hard.Curve);
            Assert.AreEqual(0.005, hardCutoff, 1e-12);
            Assert.AreEqual(0.0003, hard.SafetyDistance, 1e-12);
            Assert.AreEqual(ForceCurve.Linear, soft.Curve);
            Assert.AreEqual(0.010, softCutoff, 1e-12);
            Support.Throws(Result.InvalidArgument, "preset",
                           () => ForceSettings.FromPreset((ForcePreset)7, out double _));
        }

        [Test]
        public void WorkerCountReachesTheLibrary()
        {
            Assert.AreEqual(1, new WorldSettings().WorkerCount);
            using (var world = new World(new WorldSettings { WorkerCount = 3 })) Assert.IsTrue(world.IsValid);
            Support.Throws(Result.InvalidArgument, "workerCount",
                           () => new World(new WorldSettings { WorkerCount = 0 }));
        }

        [Test]
        public void ThreadSettingsDefaultIsTheLibrarys()
        {
            ThreadSettings s = ThreadSettings.Default;
            Assert.AreEqual(1000.0, s.HapticRate);
            Assert.AreEqual(-1, s.GlobalCore, "the global search is never pinned by default");
            Assert.That(s.HapticCore == -1 || (s.HapticCore >= 0 && s.HapticCore != s.LocalCore),
                        "not pinned, or haptic and local on cores of their own: " + s.HapticCore + ", " + s.LocalCore);
            Assert.AreEqual(1024, s.MaxContacts);
            Assert.AreEqual(0.05, s.StaleAfter, 1e-12);
            Assert.AreEqual(HapticTiming.Auto, s.HapticTiming);
            Assert.AreEqual(0.0002, s.SpinMargin, 1e-12);
            Assert.AreEqual(0, s.HapticPriority);
            Assert.AreEqual(0, s.LocalPriority);
            Assert.IsFalse(s.LockMemory);
        }
    }

    [TestFixture]
    public class WorldTests
    {
        [Test]
        public void CreatesAndDisposes()
        {
            var world = new World(new WorldSettings { Method = Method.Precise, Cutoff = 0.005, Force = ForcePreset.Hard });
            Assert.IsTrue(world.IsValid);
            world.Dispose();
            Assert.IsFalse(world.IsValid);
            Assert.DoesNotThrow(world.Dispose, "a second Dispose does nothing");
        }

        [Test]
        public void DisposedWorldIsRefused()
        {
            var world = new World();
            Mesh cube = Support.Cube(world);
            Body body = world.CreateBody(cube, BodyType.Static, Pose.Identity);
            world.Dispose();
            Support.Throws(Result.InvalidHandle, "does not name a live world", world.Step);
            Support.Throws(Result.InvalidHandle, "does not name a live world", () => Support.Cube(world));
            Support.Throws(Result.InvalidHandle, "live world", () => { MeshInfo _ = cube.Info; });
            Support.Throws(Result.InvalidHandle, "live world", () => { Pose _ = body.Pose; });
        }

        [Test]
        public void BadSettingsAreNamed()
        {
            Support.Throws(Result.InvalidArgument, "def->cutoff", () => new World(new WorldSettings { Cutoff = -1 }));
            Support.Throws(Result.InvalidArgument, "def->method",
                           () => new World(new WorldSettings { Method = (Method)9 }));
            ForceSettings f = ForceSettings.FromPreset(ForcePreset.Hard, out double _);
            f.SafetyDistance = 1.0;
            Support.Throws(Result.InvalidArgument, "safetyDistance",
                           () => new World(new WorldSettings { CustomForce = f }));
            Assert.Throws<ArgumentNullException>(() => new World(null));
        }

        [Test]
        public void SettingsReachTheWorld()
        {
            // Two cubes 1 mm apart: 7 mm is within a 10 mm cutoff, not within 5 mm.
            foreach (double cutoff in new[] { 0.010, 0.005 })
                using (var world = new World(new WorldSettings { Cutoff = cutoff }))
                {
                    Mesh cube = Support.Cube(world);
                    world.CreateBody(cube, BodyType.Static, Pose.Identity);
                    Body tool = world.CreateBody(cube, BodyType.Tool, new Pose(new Vec3(0.107, 0, 0), Quat.Identity));
                    world.Step();
                    Assert.AreEqual(cutoff > 0.007, tool.GetContacts().Length > 0, "cutoff " + cutoff);
                }
            // A custom force: the clip is the given maximum.
            ForceSettings f = ForceSettings.FromPreset(ForcePreset.Hard, out double _);
            f.MaxForce = 0.25;
            using (var world = new World(new WorldSettings { CustomForce = f }))
            {
                Mesh cube = Support.Cube(world);
                world.CreateBody(cube, BodyType.Static, Pose.Identity);
                Body tool = world.CreateBody(cube, BodyType.Tool, new Pose(new Vec3(0.1001, 0, 0), Quat.Identity));
                world.Step();
                Wrench w = tool.GetWrench();
                Assert.IsTrue(w.Clipped);
                Assert.AreEqual(0.25, w.Force.Length, 1e-9);
                Assert.Greater(w.Force.X, 0.0, "pushes the tool away (+x)");
            }
        }

        [Test]
        public void StatsAfterAStep()
        {
            using (var world = new World())
            {
                Mesh cube = Support.Cube(world);
                Body rock = world.CreateBody(cube, BodyType.Static, Pose.Identity);
                world.CreateBody(cube, BodyType.Static, new Pose(new Vec3(5, 0, 0), Quat.Identity));
                Body tool = world.CreateBody(cube, BodyType.Tool, new Pose(new Vec3(0.102, 0, 0), Quat.Identity));
                world.Step();
                WorldStats s = world.Stats;
                Assert.AreEqual(3, s.Bodies);
                Assert.AreEqual(1, s.Tools);
                Assert.AreEqual(1, s.PairsInRange, "the far cube is skipped by the broadphase");
                Assert.AreEqual(1, s.PairsSearched);
                Assert.AreEqual(tool.GetContacts().Length, s.Contacts);
                Assert.Greater(s.Contacts, 0);
                SearchStats search = world.SearchStats;
                Assert.AreEqual(1, search.PairsSearched);
                Assert.Greater(search.NodePairs, 0UL);
                Assert.GreaterOrEqual(search.Candidates, (ulong)s.Contacts);
                world.Step();
                Assert.AreEqual(0, world.Stats.PairsSearched, "nothing moved: no search");
                Assert.AreEqual(rock, tool.GetContacts()[0].Other);
            }
        }

        // A flat square of n x n cells in z = 0, facing +z or -z.
        static Mesh Sheet(World world, int n, double side, bool facingDown)
        {
            var positions = new double[3 * (n + 1) * (n + 1)];
            for (int j = 0, k = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i, k += 3)
                {
                    positions[k] = side * i / n;
                    positions[k + 1] = side * j / n;
                }
            var indices = new uint[6 * n * n];
            for (uint j = 0, k = 0; j < n; ++j)
                for (uint i = 0; i < n; ++i, k += 6)
                {
                    uint a = j * (uint)(n + 1) + i, b = a + 1, c = a + (uint)(n + 1), d = c + 1;
                    uint[] t = facingDown ? new[] { a, d, b, a, c, d } : new[] { a, b, d, a, d, c };
                    Array.Copy(t, 0, indices, k, 6);
                }
            return world.CreateMesh(positions, indices);
        }

        [Test]
        public void ParallelSheetsMergeIntoPatches()
        {
            using (var world = new World())
            {
                PatchSettings d = world.PatchSettings;
                Assert.AreEqual(1.0, d.RadiusOverCutoff);
                Assert.AreEqual(5.0, d.MaxAngleDegrees);
                Assert.AreEqual(0.002, d.MaxSpreadOverCutoff);
                Support.Throws(Result.InvalidArgument, "maxAngleDegrees",
                               () => world.PatchSettings = new PatchSettings { RadiusOverCutoff = 1, MaxAngleDegrees = 200, MaxSpreadOverCutoff = 0.002 });
                world.CreateBody(Sheet(world, 20, 0.02, false), BodyType.Static, Pose.Identity);
                Body tool = world.CreateBody(Sheet(world, 20, 0.02, true), BodyType.Tool,
                                             new Pose(new Vec3(0, 0, 0.001), Quat.Identity));
                world.Step();
                PatchStats merged = world.PatchStats;
                Assert.Greater(merged.Lmds, 800);
                Assert.LessOrEqual(merged.Patches, 31);
                Assert.AreEqual(merged.Lmds - merged.Patches, merged.Merged);
                Assert.AreEqual(merged.Patches, tool.GetContacts().Length);
                Assert.AreEqual(0UL, merged.IntersectingPairs);
                // Each contact's patch: the counts add up to the LMDs before merging,
                // and each keeps the rule (radius = the 5 mm cutoff, 0.2% of it, 5 degrees).
                Contact[] contacts = tool.GetContacts(out ContactPatch[] patches);
                Assert.AreEqual(contacts.Length, patches.Length);
                int total = 0, largest = 0;
                foreach (ContactPatch p in patches)
                {
                    Assert.GreaterOrEqual(p.Count, 1);
                    Assert.LessOrEqual(p.Extent, 0.005 + 1e-12);
                    Assert.LessOrEqual(p.Spread, 1e-5 + 1e-12);
                    Assert.LessOrEqual(p.Angle, 5.0 * Math.PI / 180.0 + 1e-9);
                    total += p.Count;
                    largest = Math.Max(largest, p.Count);
                }
                Assert.AreEqual(merged.Lmds, total);
                Assert.AreEqual(merged.LargestPatch, largest);
                var few = new ContactPatch[2];
                Assert.AreEqual(contacts.Length, tool.GetContacts(null, few), "the count, beyond the buffer");
                Assert.AreEqual(patches[1].Count, few[1].Count);
                Assert.AreEqual(0, merged.CutNodePairs);
                // The bounded search: a budget of 100 triangle pairs cuts the rest.
                Assert.AreEqual(50000UL, world.LeafBudget);
                world.LeafBudget = 100;
                Assert.AreEqual(100UL, world.LeafBudget);
                world.Step();
                Assert.Greater(world.PatchStats.CutNodePairs, 0);
                Assert.Less(world.PatchStats.Lmds, merged.Lmds);
                world.LeafBudget = 0;
                world.PatchSettings = new PatchSettings { RadiusOverCutoff = 0, MaxAngleDegrees = 5, MaxSpreadOverCutoff = 0.002 };
                world.Step();
                Assert.AreEqual(0UL, world.LeafBudget, "kept when the patch rule changes");
                Assert.AreEqual(merged.Lmds, tool.GetContacts().Length, "unmerged");
                Assert.AreEqual(0, world.PatchStats.Merged);
                double h = Math.Sqrt(0.5);
                tool.Pose = new Pose(new Vec3(0, 0.01, -0.01), new Quat(h, h, 0, 0));
                world.Step();
                Assert.GreaterOrEqual(world.PatchStats.IntersectingPairs, 1UL);
                Assert.AreEqual(1, world.PatchStats.IntersectingBodies);
            }
        }

        [Test]
        public void TrackCarriesContactsToTheNewPose()
        {
            using (var world = new World())
            {
                Mesh cube = Support.Cube(world);
                world.CreateBody(cube, BodyType.Static, Pose.Identity);
                Body tool = world.CreateBody(cube, BodyType.Tool, new Pose(new Vec3(0.102, 0, 0), Quat.Identity));
                world.Step();
                Assert.AreEqual(default(TrackStats).ContactsIn, world.TrackStats.ContactsIn, "zeros before the first");
                tool.Pose = new Pose(new Vec3(0.101, 0, 0), Quat.Identity);
                world.Track();
                TrackStats t = world.TrackStats;
                Assert.AreEqual(1, t.PairsTracked);
                Assert.Greater(t.ContactsOut, 0);
                foreach (Contact c in tool.GetContacts())
                    Assert.AreEqual(0.001, c.Distance, 1e-9, "tracked to the new pose");
            }
        }
    }
}
