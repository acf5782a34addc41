"""Tests of the proxima command-line tool, run by ctest:

    python3 cli_test.py PATH_TO_PROXIMA PATH_TO_SHARED_ASSETS

Every expected value is worked out by hand from the scene written here.
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

PROXIMA = None


def run(*args, cwd=None):
    return subprocess.run([PROXIMA, *args], capture_output=True, text=True, cwd=cwd, timeout=300)


def write(directory, name, text):
    path = os.path.join(directory, name)
    with open(path, "w") as f:
        f.write(text)
    return path


class CliTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        d = self.dir.name
        # A: the unit right triangle in z = 0 (normal +z).
        self.tri = write(d, "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
        # A unit square of two triangles, for the info counts.
        self.square = write(d, "square.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n")

    def tearDown(self):
        self.dir.cleanup()

    def test_every_command_has_help_listing_every_option(self):
        # The options each command's source parses, read from it: the usage
        # text must name every one.
        sources = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "samples", "cli")
        for command in ("info", "lmd", "polylines", "path", "run", "devices"):
            with self.subTest(command=command):
                r = run(command, "--help")
                self.assertEqual(r.returncode, 0, r.stderr)
                self.assertTrue(r.stdout.startswith("usage:\n  proxima " + command), r.stdout)
                self.assertNotIn("proxima " + ("lmd" if command != "lmd" else "info"), r.stdout,
                                 "only this command's usage")
                with open(os.path.join(sources, command + ".cpp")) as f:
                    options = set(re.findall(r'opt == "(--[a-z0-9-]+)"', f.read()))
                for option in options:
                    self.assertIn(option, r.stdout, "%s --help omits %s" % (command, option))
        self.assertEqual(run("--help").returncode, 0)

    def test_info_counts_a_square(self):
        r = run("info", self.square)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(r.stdout, r"triangles\s+2 ")
        self.assertRegex(r.stdout, r"vertices\s+4 welded")
        self.assertRegex(r.stdout, r"boundary edges\s+4\b")

    def test_info_reads_gltf(self):
        # The MANIFEST's numbers for the Duck: 4,212 triangles, 1.655 x 1.54 x 1.153.
        assets = os.environ.get("PROXIMA_ASSETS")
        r = run("info", os.path.join(assets, "gltf", "Duck.glb"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(r.stdout, r"triangles\s+4212 ")
        self.assertRegex(r.stdout, r"size 1\.65\d* x 1\.5[34]\d* x 1\.15\d*")
        r = run("info", os.path.join(assets, "gltf", "Duck-Draco", "Duck.gltf"))
        self.assertEqual(r.returncode, 1)
        self.assertIn("KHR_draco_mesh_compression", r.stderr)

    def test_info_reports_skipped_attributes(self):
        # One triangle whose NORMAL accessor (30 VEC3 floats, 360 bytes) runs
        # past its 36-byte buffer view: loaded, with a warning naming it.
        gltf = write(self.dir.name, "bad-normal.gltf", json.dumps({
            "asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 2}, "indices": 1}]}],
            "buffers": [{"byteLength": 42, "uri": "data:application/octet-stream;base64,"
                         "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA"}],
            "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                          {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
                          {"bufferView": 0, "componentType": 5126, "count": 30, "type": "VEC3"}]}))
        r = run("info", gltf)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(r.stdout, r"triangles\s+1 ")
        warnings = [line for line in r.stdout.splitlines() if line.strip().startswith("warning")]
        self.assertEqual(len(warnings), 1, r.stdout)
        self.assertIn("mesh 0 primitive 0: NORMAL accessor 2", warnings[0])
        self.assertIn("run past the end of the bufferView (36 bytes)", warnings[0])
        # A clean file has no warning line.
        r = run("info", self.square)
        self.assertNotIn("warning", r.stdout)

    def morphed_triangle(self):
        # The unit right triangle in z = 0 with one morph target lifting
        # vertex 2 by 1 in z, and an animation of its weight, LINEAR from 0
        # at t = 0 to 1 at t = 2 s.
        import base64
        import struct
        data = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<9f", 0, 0, 0, 0, 0, 0, 0, 0, 1) + \
            struct.pack("<2f", 0, 2) + struct.pack("<2f", 0, 1)
        return write(self.dir.name, "morph.gltf", json.dumps({
            "asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "targets": [{"POSITION": 1}]}]}],
            "animations": [{"name": "lift", "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}],
                            "samplers": [{"input": 2, "output": 3}]}],
            "buffers": [{"byteLength": len(data),
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
            "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36},
                            {"buffer": 0, "byteOffset": 72, "byteLength": 8},
                            {"buffer": 0, "byteOffset": 80, "byteLength": 8}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                          {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
                          {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR",
                           "min": [0], "max": [2]},
                          {"bufferView": 3, "componentType": 5126, "count": 2, "type": "SCALAR"}]}))

    def test_info_lists_the_rig(self):
        r = run("info", self.morphed_triangle())
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertRegex(r.stdout, r"morph targets\s+1 weights")
        self.assertRegex(r.stdout, r"animation 0\s+2 s \(keyframes from 0 s\), 1 channels 'lift'")
        self.assertNotIn("skins", r.stdout)

    def test_lmd_animates_a_gltf_before_the_query(self):
        # At 1.5 s the weight is 0.75: vertex 2 at (0, 1, 0.75). B, the unit
        # triangle lifted to z = 2, is then 1.25 from it (2 unanimated).
        morph = self.morphed_triangle()
        for extra, want in (((), 2.0), (("--animate-a", "0:1.5"), 1.25), (("--animate-a", "0:9"), 1.0)):
            json_path = os.path.join(self.dir.name, "animated.json")
            r = run("lmd", morph, self.tri, "--pose-b", "0", "0", "2", "1", "0", "0", "0", "--cutoff", "3",
                    "--json", json_path, *extra)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(json_path) as f:
                self.assertAlmostEqual(json.load(f)["min_distance"], want, delta=1e-12, msg=str(extra))
        # B animated alone (the same file as A, so loaded twice): at 0.5 s
        # its weight is 0.25, vertex 2 at (0, 1, 0.25); turned over about x
        # and moved by (0, 1, 2) it is at (0, 0, 1.75), above A's flat vertex
        # 0: 1.75 apart (2 unanimated, B's other vertices at z = 2).
        for extra, want in (((), 2.0), (("--animate-b", "0:0.5"), 1.75)):
            json_path = os.path.join(self.dir.name, "animated_b.json")
            r = run("lmd", morph, morph, "--pose-b", "0", "1", "2", "0", "1", "0", "0", "--cutoff", "3",
                    "--json", json_path, *extra)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(json_path) as f:
                self.assertAlmostEqual(json.load(f)["min_distance"], want, delta=1e-12, msg=str(extra))
        r = run("lmd", morph, morph, "--animate-b", "1:0.5")
        self.assertEqual(r.returncode, 1)
        self.assertIn("--animate-b: proxMesh_Animate: animation 1 does not exist (the mesh has 1)", r.stderr)
        r = run("lmd", morph, morph, "--animate-a", "0")
        self.assertEqual(r.returncode, 1)
        self.assertIn("is not INDEX:SECONDS", r.stderr)

    def test_run_plays_animations_while_the_threads_run(self):
        # RiggedSimple's cylinder bends under its two joints: A (static) and
        # B (the held tool) both posed at 60 Hz while the threads run.
        rigged = os.path.join(os.environ.get("PROXIMA_ASSETS"), "gltf", "RiggedSimple.glb")
        json_path = os.path.join(self.dir.name, "animated_run.json")
        r = run("run", rigged, rigged, "--animate-a", "0", "--animate-b", "0", "--seconds", "0.4", "--hold", "0.2",
                "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("animation: B's", r.stdout)
        with open(json_path) as f:
            report = json.load(f)
        # Two meshes posed at 60 Hz for 0.6 s (a frame late now and then on a busy machine).
        self.assertGreater(report["animation_frames"], 20)
        self.assertTrue(report["device"]["all_finite"])
        self.assertEqual(report["safety"]["torn_snapshots"], 0)
        r = run("run", rigged, rigged, "--animate-b", "3")
        self.assertEqual(r.returncode, 1)
        self.assertIn("animation 3 does not exist", r.stderr)

    def test_lmd_between_single_triangles(self):
        # B is A turned over (180 degrees about x: normal -z, facing A),
        # shifted by (0.1, 0.1) and lifted 1 mm: two parallel faces that
        # overlap, 1 mm apart.
        json_path = os.path.join(self.dir.name, "out.json")
        r = run("lmd", self.tri, self.tri, "--pose-b", "0.1", "0.1", "0.001", "0", "1", "0", "0",
                "--cutoff", "0.005", "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(json_path) as f:
            out = json.load(f)
        self.assertAlmostEqual(out["min_distance"], 0.001, delta=1e-12)
        self.assertEqual(len(out["lmds"]), 1)
        lmd = out["lmds"][0]
        self.assertAlmostEqual(lmd["distance"], 0.001, delta=1e-12)
        self.assertAlmostEqual(lmd["point_b"][2] - lmd["point_a"][2], 0.001, delta=1e-12)
        self.assertEqual((lmd["feature_a"], lmd["feature_b"]), ("face", "face"))
        # B is above A, so the force pushes B up (+z) and is within the clip.
        fx, fy, fz = out["force"]
        self.assertGreater(fz, 0.0)
        self.assertAlmostEqual(fx, 0.0, delta=1e-12)
        self.assertLessEqual(math.sqrt(fx * fx + fy * fy + fz * fz), 3.0 + 1e-12)
        for key in ("candidates", "node_pairs", "leaf_pairs", "global_ms"):
            self.assertIn(key, out["stats"])

    def test_lmd_reports_nothing_beyond_the_cutoff(self):
        json_path = os.path.join(self.dir.name, "far.json")
        r = run("lmd", self.tri, self.tri, "--pose-b", "0", "0", "0.01", "1", "0", "0", "0",
                "--cutoff", "0.005", "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(json_path) as f:
            out = json.load(f)
        self.assertEqual(out["lmds"], [])
        self.assertEqual(out["min_distance"], -1)
        self.assertEqual(out["force"], [0, 0, 0])

    def test_all_methods_agree_on_a_vertex_over_a_face(self):
        # B's vertex 0 sits 2 mm above A's interior point (0.25, 0.25) and B
        # rises from there, wound to face A: the only LMD is B's vertex over
        # A's face at 2 mm. The original's 7 x 7 sampling can only pair that
        # vertex with A's centroid or corners, so it reports more than 2 mm.
        b = write(self.dir.name, "b.obj", "v 0.25 0.25 0.002\nv 1 0.5 1\nv 0.5 1 1\nf 1 3 2\n")
        results = {}
        for method in ("precise", "reference", "original"):
            json_path = os.path.join(self.dir.name, method + ".json")
            r = run("lmd", self.tri, b, "--method", method, "--cutoff", "0.5", "--json", json_path)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(json_path) as f:
                results[method] = json.load(f)
        self.assertAlmostEqual(results["precise"]["min_distance"], 0.002, delta=1e-12)
        self.assertAlmostEqual(results["reference"]["min_distance"], 0.002, delta=1e-12)
        self.assertEqual(results["precise"]["lmds"][0]["feature_b"], "vertex")
        self.assertEqual(results["precise"]["lmds"][0]["feature_a"], "face")
        # The sampled distance can only be larger than the exact one.
        self.assertGreater(results["original"]["min_distance"], 0.002)

    def test_lmd_reports_a_crossing_as_an_intersection_not_a_contact(self):
        # The wall of the polylines test crosses A's face: one crossing
        # triangle pair, and nothing at distance zero among the contacts.
        b = write(self.dir.name, "wall.obj", "v 0.25 -1 -1\nv 0.25 -1 1\nv 0.25 3 0\nf 1 2 3\n")
        json_path = os.path.join(self.dir.name, "cross.json")
        r = run("lmd", self.tri, b, "--cutoff", "0.005", "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("intersection: the surfaces cross (1 triangle pairs", r.stdout)
        with open(json_path) as f:
            out = json.load(f)
        self.assertEqual(out["intersection"], {"crossing": True, "intersecting_pairs": 1})
        self.assertEqual(out["lmds"], [])
        self.assertEqual((out["patches"]["lmds"], out["patches"]["patches"]), (0, 0))
        # The patch rule is taken from the options, and refused by name.
        r = run("lmd", self.tri, self.tri, "--pose-b", "0.1", "0.1", "0.001", "0", "1", "0", "0",
                "--patch-radius", "0.5", "--patch-angle", "2", "--patch-spread", "0.01", "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(json_path) as f:
            out = json.load(f)
        self.assertEqual(out["patches"]["radius_over_cutoff"], 0.5)
        self.assertEqual(out["patches"]["max_angle_degrees"], 2.0)
        self.assertEqual(out["patches"]["max_spread_over_cutoff"], 0.01)
        self.assertEqual((out["patches"]["lmds"], out["patches"]["patches"]), (1, 1))
        self.assertFalse(out["intersection"]["crossing"])
        r = run("lmd", self.tri, self.tri, "--patch-angle", "200")
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("maxAngleDegrees", r.stderr)

    def test_lmd_leaf_budget_cuts_parallel_sheets(self):
        # Two 1 cm squares of 10 x 10 cells, the second 1 mm above the
        # first and facing it; the default cutoff is 5 mm.
        def sheet(name, z, facing_down):
            lines = [f"v {i / 1000} {j / 1000} {z}" for j in range(11) for i in range(11)]
            for j in range(10):
                for i in range(10):
                    a = j * 11 + i + 1
                    b, c, d = a + 1, a + 11, a + 12
                    lines += [f"f {a} {d} {b}", f"f {a} {c} {d}"] if facing_down else \
                        [f"f {a} {b} {d}", f"f {a} {d} {c}"]
            return write(self.dir.name, name, "\n".join(lines) + "\n")
        floor, tool = sheet("floor.obj", 0, False), sheet("tool.obj", 0.001, True)
        json_path = os.path.join(self.dir.name, "sheets.json")
        r = run("lmd", floor, tool, "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertNotIn("bounded search", r.stdout)
        with open(json_path) as f:
            whole = json.load(f)
        self.assertEqual((whole["patches"]["leaf_budget"], whole["patches"]["cut_node_pairs"]), (50000, 0))
        r = run("lmd", floor, tool, "--leaf-budget", "1", "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("bounded search: past 1 leaf pairs,", r.stdout)
        with open(json_path) as f:
            cut = json.load(f)
        self.assertEqual(cut["patches"]["leaf_budget"], 1)
        n = cut["patches"]["cut_node_pairs"]
        self.assertGreater(n, 0)
        # At most 8 triangle pairs tried per cut node pair past the budget.
        self.assertLessEqual(cut["stats"]["leaf_pairs"], 1 + 8 * n)
        self.assertLess(cut["stats"]["leaf_pairs"], whole["stats"]["leaf_pairs"])
        self.assertLess(cut["patches"]["lmds"], whole["patches"]["lmds"])
        self.assertAlmostEqual(cut["min_distance"], 0.001, delta=1e-12)
        self.assertGreaterEqual(len(cut["lmds"]), 1)
        for bad in ("-1", "2.5", "x"):
            r = run("lmd", floor, tool, "--leaf-budget", bad)
            self.assertNotEqual(r.returncode, 0)
            self.assertIn("--leaf-budget", r.stderr)

    def test_polylines_of_two_crossing_triangles(self):
        # B: a triangle in the plane x = 0.25 crossing A's face along
        # x = 0.25, y in [0, 0.75]: one open polyline of length 0.75.
        b = write(self.dir.name, "wall.obj", "v 0.25 -1 -1\nv 0.25 -1 1\nv 0.25 3 0\nf 1 2 3\n")
        json_path = os.path.join(self.dir.name, "lines.json")
        r = run("polylines", self.tri, b, "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(json_path) as f:
            out = json.load(f)
        self.assertEqual(len(out["polylines"]), 1)
        line = out["polylines"][0]
        self.assertFalse(line["closed"])
        self.assertAlmostEqual(out["total_length"], 0.75, delta=1e-12)
        for x, y, z in line["points"]:
            self.assertAlmostEqual(x, 0.25, delta=1e-15)
            self.assertAlmostEqual(z, 0.0, delta=1e-15)

    def test_path_writes_a_csv_per_step(self):
        csv = os.path.join(self.dir.name, "path.csv")
        r = run("path", "--steps", "20", "--csv", csv)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(csv) as f:
            lines = f.read().splitlines()
        self.assertTrue(lines[0].startswith("step,method,x,min_distance"))
        self.assertEqual(len(lines), 1 + 2 * 20)  # both methods
        last_precise = [l for l in lines if ",precise," in l][-1].split(",")
        # The last pose is 0.5 mm from contact.
        self.assertAlmostEqual(float(last_precise[3]), 0.0005, delta=1e-9)
        self.assertIn("precise", r.stdout)
        self.assertIn("original", r.stdout)

    def test_path_from_a_poses_file(self):
        # B (the triangle turned to face A) descends onto A: 3, 2 then 1 mm.
        poses = write(self.dir.name, "poses.txt",
                      "# tx ty tz qw qx qy qz\n0.1 0.1 0.003 0 1 0 0\n\n0.1 0.1 0.002 0 1 0 0\n0.1 0.1 0.001 0 1 0 0\n")
        csv = os.path.join(self.dir.name, "p.csv")
        r = run("path", self.tri, self.tri, "--poses", poses, "--method", "precise", "--csv", csv)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(csv) as f:
            rows = [l.split(",") for l in f.read().splitlines()[1:]]
        self.assertEqual([round(float(row[3]), 12) for row in rows], [0.003, 0.002, 0.001])
        forces = [float(row[9]) for row in rows]
        self.assertLess(forces[0], forces[1])
        self.assertLess(forces[1], forces[2])

    def test_run_drives_the_threads_with_the_scripted_device(self):
        # B (the triangle turned to face A) descends onto A from 3 to 1 mm in
        # 0.3 s, held there 0.3 s, on Proxima's threads.
        poses = write(self.dir.name, "descent.txt", "0.1 0.1 0.003 0 1 0 0\n0.1 0.1 0.001 0 1 0 0\n")
        json_path = os.path.join(self.dir.name, "run.json")
        r = run("run", self.tri, self.tri, "--poses", poses, "--seconds", "0.3", "--hold", "0.3",
                "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        with open(json_path) as f:
            report = json.load(f)
        for thread in ("haptic", "local", "global"):
            self.assertGreater(report["threads"][thread]["updates"], 0, thread)
        self.assertGreater(report["threads"]["haptic"]["updates"], 100)
        device = report["device"]
        self.assertTrue(device["all_finite"])
        self.assertGreater(device["max_force"], 0.0, "a millimetre from A, the tool is pushed back")
        self.assertLessEqual(device["max_force"], 3.0 + 1e-12)
        self.assertEqual(report["safety"]["torn_snapshots"], 0)
        # The last sample, held 1 mm over A, feels a force.
        last = [l.split() for l in r.stdout.splitlines() if l.strip() and l.split()[0].replace(".", "").isdigit()][-1]
        self.assertGreater(float(last[3]), 0.0)

    def test_run_drives_the_threads_with_the_streamed_device(self):
        # The same descent, fed to a streamed device at 90 Hz by a second
        # thread of the tool, as an engine's frame loop would feed it.
        poses = write(self.dir.name, "descent.txt", "0.1 0.1 0.003 0 1 0 0\n0.1 0.1 0.001 0 1 0 0\n")
        json_path = os.path.join(self.dir.name, "run.json")
        r = run("run", self.tri, self.tri, "--device", "stream", "--poses", poses, "--seconds", "0.3",
                "--hold", "0.3", "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("stream:", r.stdout)
        with open(json_path) as f:
            report = json.load(f)
        self.assertEqual(report["device"]["kind"], "stream")
        stream = report["stream"]
        self.assertEqual(stream["mode"], "interpolate")
        # 0.6 s at 90 Hz, give or take the scheduler of a busy machine.
        self.assertGreater(stream["samples_pushed"], 20)
        self.assertLessEqual(stream["samples_pushed"], 60)
        self.assertEqual(stream["samples_refused"], 0)
        self.assertGreater(stream["reads"], 100, "the haptic loop reads at 1 kHz, many times per sample")
        self.assertGreater(stream["mean_sample_interval_ms"], 9.0)
        device = report["device"]
        self.assertTrue(device["all_finite"])
        self.assertGreater(device["max_force"], 0.0, "a millimetre from A, the tool is pushed back")
        self.assertLessEqual(device["max_force"], 3.0 + 1e-12)
        last = [l.split() for l in r.stdout.splitlines() if l.strip() and l.split()[0].replace(".", "").isdigit()][-1]
        self.assertGreater(float(last[3]), 0.0)

    def test_run_constrained_tool_stays_outside(self):
        # A 1 cm cube pushed straight through a 2 cm cube and back by the
        # scripted device: the constrained tool's proxy stays outside (its
        # exact distance never below the hard settings' 0.3 mm safety
        # distance) while the device pose goes in.
        def cube(name, h):
            v = "".join(f"v {x} {y} {z}\n" for x in (-h, h) for y in (-h, h) for z in (-h, h))
            f = ("f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n")
            return write(self.dir.name, name, v + f)
        a, b = cube("a.obj", 0.01), cube("b.obj", 0.005)
        poses = write(self.dir.name, "through.txt",
                      "0.02 0.001 0.002 1 0 0 0\n-0.02 0.001 0.002 1 0 0 0\n0.02 0.001 0.002 1 0 0 0\n")
        json_path = os.path.join(self.dir.name, "run.json")
        r = run("run", a, b, "--tool-mode", "constrained", "--poses", poses, "--seconds", "0.6",
                "--hold", "0.3", "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("proxy: closest", r.stdout)
        with open(json_path) as f:
            out = json.load(f)
        self.assertEqual(out["tool_mode"], "constrained")
        self.assertGreater(out["proxy_samples"], 50)
        self.assertGreaterEqual(out["min_proxy_distance"], 0.0003 * (1 - 1e-6))
        self.assertGreater(out["max_device_penetration"], 0.005)
        self.assertTrue(out["device"]["all_finite"])
        self.assertLessEqual(out["device"]["max_force"], 3.0 + 1e-9)
        self.assertGreater(out["device"]["max_force"], 1.0)  # the coupling pulled the hand back
        for name in ("haptic", "local", "global"):
            self.assertGreater(out["threads"][name]["updates"], 0)

    def test_run_takes_the_timing_and_real_time_options(self):
        json_path = os.path.join(self.dir.name, "run.json")
        r = run("run", self.tri, self.tri, "--seconds", "0.2", "--hold", "0", "--haptic-timing", "spin",
                "--realtime", "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("haptic timing: spin", r.stdout)
        with open(json_path) as f:
            report = json.load(f)
        self.assertEqual(report["haptic_timing"], "spin")
        haptic = report["threads"]["haptic"]
        # Granted (80) where the system allows it; else refused with a reason, and the run goes on.
        if haptic["realtime_priority"] == 0:
            self.assertNotEqual(haptic["realtime_error"], 0)
            self.assertIn("refused", r.stdout)
        else:
            self.assertEqual(haptic["realtime_priority"], 80)
            self.assertEqual(report["threads"]["local"]["realtime_priority"], 70)
        self.assertGreater(haptic["updates"], 50)
        self.assertLessEqual(haptic["period_p99_ms"], haptic["period_p999_ms"])
        r = run("run", self.tri, self.tri, "--seconds", "0.1", "--hold", "0", "--haptic-timing", "sleep",
                "--json", json_path)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        with open(json_path) as f:
            self.assertEqual(json.load(f)["haptic_timing"], "sleep")

    def test_lmd_at_micro_scale_scales_the_force_preset(self):
        # Triangles 2e-6 across, B turned over 1e-5 above A: the cutoff 2e-5
        # is far inside the presets' own safety distances (0.3 mm, 2 mm), so
        # the presets scale to it. Hard at cutoff 2e-5 (k = 2e-5 / 5e-3):
        # safety 1.2e-6, decay 1.2e-6; the force at 1e-5 is
        # 3 N * (exp(-(1e-5 - 1.2e-6) / 1.2e-6) - exp(-(2e-5 - 1.2e-6) / 1.2e-6))
        # / (1 - exp(-(2e-5 - 1.2e-6) / 1.2e-6)), along +z. Soft (linear,
        # safety 2 mm of 10 mm, so 4e-6 of 2e-5): 3 N * (2e-5 - 1e-5) / (2e-5 - 4e-6).
        tiny = write(self.dir.name, "tiny.obj", "v 0 0 0\nv 2e-6 0 0\nv 0 2e-6 0\nf 1 2 3\n")
        pose_b = ("--pose-b", "0", "0", "1e-5", "0", "1", "0", "0")
        e = math.exp
        expected = {
            "hard": 3.0 * (e(-(1e-5 - 1.2e-6) / 1.2e-6) - e(-(2e-5 - 1.2e-6) / 1.2e-6))
            / (1 - e(-(2e-5 - 1.2e-6) / 1.2e-6)),
            "soft": 3.0 * (2e-5 - 1e-5) / (2e-5 - 4e-6),
        }
        for force, fz in expected.items():
            with self.subTest(force=force):
                json_path = os.path.join(self.dir.name, force + ".json")
                r = run("lmd", tiny, tiny, *pose_b, "--cutoff", "2e-5", "--force", force, "--json", json_path)
                self.assertEqual(r.returncode, 0, r.stderr)
                with open(json_path) as f:
                    out = json.load(f)
                self.assertEqual(out["cutoff"], 2e-5)
                self.assertEqual(len(out["lmds"]), 1)
                self.assertAlmostEqual(out["lmds"][0]["distance"], 1e-5, delta=1e-17)
                self.assertAlmostEqual(out["force"][2], fz, delta=1e-9 * fz)
        # Any positive cutoff: far below and far above the presets' own.
        for cutoff in ("1e-12", "1e3"):
            with self.subTest(cutoff=cutoff):
                r = run("lmd", tiny, tiny, *pose_b, "--cutoff", cutoff)
                self.assertEqual(r.returncode, 0, r.stderr)
                self.assertIn("within " + ("1e-12: 0" if cutoff == "1e-12" else "1000: 1"), r.stdout)

    def test_errors_are_clear_and_exit_non_zero(self):
        cases = [
            (("info", os.path.join(self.dir.name, "missing.obj")), "missing.obj"),
            (("info", write(self.dir.name, "nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")), "nan.obj"),
            (("info", write(self.dir.name, "bad.obj", "v 0 0 0\nf 1 2 3\n")), "bad.obj:2"),
            (("info", write(self.dir.name, "x.stl", "solid")), "unsupported file type"),
            (("lmd", self.tri, self.tri, "--pose-b", "0", "0", "x", "1", "0", "0", "0"), "--pose-b"),
            (("lmd", self.tri, self.tri, "--pose-b", "0", "0", "0", "0", "0", "0", "0"), "quaternion"),
            (("lmd", self.tri, self.tri, "--pose-b", "0", "0", "inf", "1", "0", "0", "0"), "not finite"),
            (("lmd", self.tri, self.tri, "--pose-a", "1", "2"), "missing"),
            (("lmd", self.tri, self.tri, "--cutoff", "-1"), "--cutoff"),
            (("lmd", self.tri, self.tri, "--cutoff", "0"), "must be > 0"),
            (("lmd", self.tri, self.tri, "--method", "magic"), "--method"),
            (("lmd", self.tri), "missing mesh B"),
            (("path", "--steps", "1"), "--steps"),
            (("path", self.tri, self.tri, "--poses", write(self.dir.name, "bad.txt", "0 0 0 1 0 0\n")), "bad.txt:1"),
            (("path", self.tri, self.tri, "--poses", write(self.dir.name, "one.txt", "0 0 0 1 0 0 0\n")),
             "at least 2 poses"),
            (("run", "--seconds", "0"), "--seconds"),
            (("run", "--hold", "-1"), "--hold"),
            (("run", "--method", "reference"), "real time"),
            (("run", "--wobble"), "unknown option"),
            (("run", "--device", "joystick"), "--device"),
            (("run", "--haptic-timing", "fast"), "--haptic-timing"),
            (("run", "--tool-mode", "sticky"), "--tool-mode"),
            (("run", "--spin-margin", "0.5"), "spin margin"),
            (("run", "--device", "stream", "--stream-rate", "0"), "--stream-rate"),
            (("run", "--device", "stream", "--stream-mode", "guess"), "--stream-mode"),
        ]
        for args, expected in cases:
            with self.subTest(args=args):
                r = run(*args)
                self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
                self.assertIn(expected, r.stderr)
                self.assertTrue(r.stderr.startswith("proxima: "), r.stderr)
        r = run("frobnicate")
        self.assertEqual(r.returncode, 2)
        self.assertIn("usage", r.stderr)


if __name__ == "__main__":
    PROXIMA = os.path.abspath(sys.argv.pop(1))
    os.environ.setdefault("PROXIMA_ASSETS", os.path.abspath(sys.argv.pop(1)))
    unittest.main()
