using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Runtime.InteropServices;
using NUnit.Framework;

namespace Proxima.Tests
{
    /// <summary>Every struct crossing P/Invoke has the size and field offsets a C
    /// compiler gives its twin in the headers: the C side is printed by the
    /// program tools/gen_native.py --layout-c generates (struct_layout.c in the
    /// build), built against the headers, which names each struct's and field's
    /// C# twin too.</summary>
    [TestFixture]
    public class StructLayoutTests
    {
        // Read once, on first use: NUnit 2.6's [TestFixtureSetUp] is obsolete in
        // the NUnit 3 of Unity's Test Runner, and [OneTimeSetUp] is not in 2.6.
        static Dictionary<string, int> layout;
        static List<string[]> twins;

        static Dictionary<string, int> C
        {
            get
            {
                if (layout != null) return layout;
                var start = new ProcessStartInfo(Support.Program("PROXIMA_STRUCT_LAYOUT"))
                {
                    UseShellExecute = false,
                    RedirectStandardOutput = true,
                };
                var read = new Dictionary<string, int>();
                var named = new List<string[]>();
                using (Process p = Process.Start(start))
                {
                    string line;
                    while ((line = p.StandardOutput.ReadLine()) != null)
                    {
                        string[] parts = line.Split(' ');
                        read[parts[0]] = int.Parse(parts[1]);
                        if (parts.Length == 3) named.Add(parts);
                    }
                    p.WaitForExit();
                    Assert.AreEqual(0, p.ExitCode, "struct_layout failed");
                }
                twins = named;
                return layout = read;
            }
        }

        public static readonly object[] Twins =
        {
            new object[] { "proxBool", typeof(Bool32) },
            new object[] { "proxVersion", typeof(Version) },
            new object[] { "proxWorldId", typeof(WorldId) },
            new object[] { "proxMeshId", typeof(MeshId) },
            new object[] { "proxMeshId", typeof(Mesh) },
            new object[] { "proxBodyId", typeof(BodyId) },
            new object[] { "proxBodyId", typeof(Body) },
            new object[] { "proxVec3", typeof(Vec3) },
            new object[] { "proxQuat", typeof(Quat) },
            new object[] { "proxPose", typeof(Pose) },
            new object[] { "proxForceSettings", typeof(ForceSettings) },
            new object[] { "proxWorldDef", typeof(WorldDef) },
            new object[] { "proxMeshDef", typeof(MeshDef) },
            new object[] { "proxMeshInfo", typeof(MeshInfo) },
            new object[] { "proxRigInfo", typeof(RigInfo) },
            new object[] { "proxSkinInfo", typeof(SkinInfo) },
            new object[] { "proxAnimationInfo", typeof(AnimationInfo) },
            new object[] { "proxBodyDef", typeof(BodyDef) },
            new object[] { "proxContact", typeof(Contact) },
            new object[] { "proxContactPatch", typeof(ContactPatch) },
            new object[] { "proxWrench", typeof(Wrench) },
            new object[] { "proxPolylineInfo", typeof(PolylineInfo) },
            new object[] { "proxWorldStats", typeof(WorldStats) },
            new object[] { "proxDeviceDef", typeof(DeviceDef) },
            new object[] { "proxScriptedDeviceId", typeof(ScriptedDeviceId) },
            new object[] { "proxScriptedDeviceId", typeof(ScriptedDevice) },
            new object[] { "proxScriptedDeviceDef", typeof(ScriptedDeviceDef) },
            new object[] { "proxScriptedDeviceRecord", typeof(ScriptedDeviceRecord) },
            new object[] { "proxStreamDeviceId", typeof(StreamDeviceId) },
            new object[] { "proxStreamDeviceId", typeof(StreamDevice) },
            new object[] { "proxStreamDeviceDef", typeof(StreamDeviceSettings) },
            new object[] { "proxStreamDeviceStats", typeof(StreamDeviceStats) },
            new object[] { "proxThreadsDef", typeof(ThreadSettings) },
            new object[] { "proxThreadStats", typeof(ThreadStats) },
            new object[] { "proxSafetyStats", typeof(SafetyStats) },
            new object[] { "proxHapticSample", typeof(HapticSample) },
            new object[] { "proxMeshStats", typeof(MeshStats) },
            new object[] { "proxSearchStats", typeof(SearchStats) },
            new object[] { "proxTrackStats", typeof(TrackStats) },
            new object[] { "proxIntersectionStats", typeof(IntersectionStats) },
            new object[] { "proxPatchSettings", typeof(PatchSettings) },
            new object[] { "proxPatchStats", typeof(PatchStats) },
        };

        /// <summary>Every struct, enum and field of the bound headers, against the C# type
        /// and field the generator bound it to: nothing generated escapes the check.</summary>
        [Test]
        public void EveryGeneratedTypeIsC()
        {
            Assert.IsNotNull(C);
            var failures = new List<string>();
            int structs = 0, fields = 0;
            Type type = null;
            foreach (string[] t in twins)
            {
                if (!t[0].Contains("."))
                {
                    type = typeof(World).Assembly.GetType("Proxima." + t[2]);
                    if (type == null) { failures.Add(t[0] + ": no type Proxima." + t[2]); continue; }
                    int size = type.IsEnum ? Marshal.SizeOf(Enum.GetUnderlyingType(type)) : Marshal.SizeOf(type);
                    if (size != int.Parse(t[1])) failures.Add(t[0] + " is " + t[1] + " bytes, " + t[2] + " " + size);
                    ++structs;
                    continue;
                }
                if (type == null) continue;
                int offset;
                try { offset = Marshal.OffsetOf(type, t[2]).ToInt32(); }
                catch (ArgumentException) { failures.Add(t[0] + ": no field " + type.Name + "." + t[2]); continue; }
                if (offset != int.Parse(t[1])) failures.Add(t[0] + " at " + t[1] + ", " + type.Name + "." + t[2] + " at " + offset);
                ++fields;
            }
            Assert.IsEmpty(failures, string.Join("\n", failures));
            // The headers have about 50 types and 300 fields: an empty listing is a failure too.
            Assert.Greater(structs, 40);
            Assert.Greater(fields, 250);
        }

        [TestCaseSource("Twins")]
        public void SizeIsC(string cName, Type type)
        {
            Assert.IsTrue(C.ContainsKey(cName), cName + " is not printed by struct_layout.c");
            Assert.AreEqual(C[cName], Marshal.SizeOf(type), type.Name + " against " + cName);
        }

        public static readonly object[] Offsets =
        {
            new object[] { "proxForceSettings.maxForce", typeof(ForceSettings), "MaxForce" },
            new object[] { "proxWorldDef.cutoff", typeof(WorldDef), "Cutoff" },
            new object[] { "proxWorldDef.internalValue", typeof(WorldDef), "InternalValue" },
            new object[] { "proxMeshDef.indices", typeof(MeshDef), "Indices" },
            new object[] { "proxMeshDef.triangleCount", typeof(MeshDef), "TriangleCount" },
            new object[] { "proxMeshInfo.boundsMin", typeof(MeshInfo), "BoundsMin" },
            new object[] { "proxSkinInfo.jointCount", typeof(SkinInfo), "JointCount" },
            new object[] { "proxAnimationInfo.duration", typeof(AnimationInfo), "Duration" },
            new object[] { "proxAnimationInfo.channelCount", typeof(AnimationInfo), "ChannelCount" },
            new object[] { "proxBodyDef.pose", typeof(BodyDef), "Pose" },
            new object[] { "proxBodyDef.referencePoint", typeof(BodyDef), "ReferencePoint" },
            new object[] { "proxBodyDef.toolMode", typeof(BodyDef), "ToolMode" },
            new object[] { "proxBodyDef.couplingAngularDamping", typeof(BodyDef), "CouplingAngularDamping" },
            new object[] { "proxBodyDef.internalValue", typeof(BodyDef), "InternalValue" },
            new object[] { "proxContact.pointTool", typeof(Contact), "PointTool" },
            new object[] { "proxContact.distance", typeof(Contact), "Distance" },
            new object[] { "proxContact.featureOther", typeof(Contact), "FeatureOther" },
            new object[] { "proxContactPatch.extent", typeof(ContactPatch), "Extent" },
            new object[] { "proxWrench.clipped", typeof(Wrench), "Clipped" },
            new object[] { "proxPolylineInfo.closed", typeof(PolylineInfo), "Closed" },
            new object[] { "proxDeviceDef.userData", typeof(DeviceDef), "UserData" },
            new object[] { "proxScriptedDeviceDef.secondsPerPose", typeof(ScriptedDeviceDef), "SecondsPerPose" },
            new object[] { "proxScriptedDeviceRecord.allFinite", typeof(ScriptedDeviceRecord), "AllFinite" },
            new object[] { "proxStreamDeviceDef.delay", typeof(StreamDeviceSettings), "Delay" },
            new object[] { "proxStreamDeviceDef.internalValue", typeof(StreamDeviceSettings), "internalValue" },
            new object[] { "proxStreamDeviceStats.meanSampleInterval", typeof(StreamDeviceStats), "MeanSampleInterval" },
            new object[] { "proxThreadsDef.staleAfter", typeof(ThreadSettings), "StaleAfter" },
            new object[] { "proxThreadsDef.hapticTiming", typeof(ThreadSettings), "HapticTiming" },
            new object[] { "proxThreadsDef.spinMargin", typeof(ThreadSettings), "SpinMargin" },
            new object[] { "proxThreadsDef.lockMemory", typeof(ThreadSettings), "LockMemory" },
            new object[] { "proxThreadsDef.internalValue", typeof(ThreadSettings), "internalValue" },
            new object[] { "proxThreadsDef.traceCapacity", typeof(ThreadSettings), "TraceCapacity" },
            new object[] { "proxHapticSample.force", typeof(HapticSample), "Force" },
            new object[] { "proxHapticSample.flags", typeof(HapticSample), "Flags" },
            new object[] { "proxHapticSample.closestDistance", typeof(HapticSample), "ClosestDistance" },
            new object[] { "proxHapticSample.tick", typeof(HapticSample), "Tick" },
            new object[] { "proxThreadStats.targetRate", typeof(ThreadStats), "TargetRate" },
            new object[] { "proxThreadStats.periodP999", typeof(ThreadStats), "PeriodP999" },
            new object[] { "proxThreadStats.timing", typeof(ThreadStats), "Timing" },
            new object[] { "proxThreadStats.sleepTimer", typeof(ThreadStats), "SleepTimer" },
            new object[] { "proxMeshStats.hierarchyBytes", typeof(MeshStats), "HierarchyBytes" },
            new object[] { "proxSearchStats.nodePairs", typeof(SearchStats), "NodePairs" },
            new object[] { "proxTrackStats.distanceEvaluations", typeof(TrackStats), "DistanceEvaluations" },
            new object[] { "proxPatchStats.intersectingPairs", typeof(PatchStats), "IntersectingPairs" },
            new object[] { "proxPatchStats.cutNodePairs", typeof(PatchStats), "CutNodePairs" },
        };

        [TestCaseSource("Offsets")]
        public void OffsetIsC(string cField, Type type, string field)
        {
            Assert.IsTrue(C.ContainsKey(cField), cField + " is not printed by struct_layout.c");
            Assert.AreEqual(C[cField], Marshal.OffsetOf(type, field).ToInt32(), type.Name + "." + field);
        }

        [Test]
        public void EnumsAre32Bits()
        {
            foreach (Type t in new[] { typeof(Result), typeof(Method), typeof(ForceCurve), typeof(ForcePreset),
                                       typeof(BodyType), typeof(Feature), typeof(ThreadRole), typeof(StreamMode), typeof(HapticTiming) })
                Assert.AreEqual(typeof(int), Enum.GetUnderlyingType(t), t.Name);
            Assert.AreEqual(C["proxResult"], sizeof(int));
            Assert.AreEqual(C["proxStreamMode"], sizeof(int));
            Assert.AreEqual(C["proxHapticTiming"], sizeof(int));
        }

        [Test]
        public void ArraysOfResultsAreBlittable()
        {
            // A pinned GCHandle exists only for blittable types: arrays of these
            // cross P/Invoke without a copy.
            foreach (object array in new object[] { new Contact[1], new ContactPatch[1], new Vec3[1], new Pose[1], new PolylineInfo[1] })
                GCHandle.Alloc(array, GCHandleType.Pinned).Free();
        }
    }
}
