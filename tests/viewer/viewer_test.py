"""Headless tests of proxima-viewer on the CPU Vulkan driver (lavapipe),
with the validation layers on in every run; run by ctest:

    python3 viewer_test.py PATH_TO_PROXIMA_VIEWER PATH_TO_SHARED_ASSETS

The pictures are checked against the frames' own sidecars: a string, a
polyline or a mesh vertex is projected with the view and projection matrices
the frame wrote, and the pixels that changed between two renders of the same
scene (with and without one kind of thing) must be exactly those.
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gltf_pose  # noqa: E402
import png  # noqa: E402
import sanitizers  # noqa: E402

VIEWER = None
VALIDATION = r"validation (error|warning|message)"  # what the viewer prints for one
ASSETS = None
SIZE = (480, 270)
# Scenes of the bunny against itself (A at the identity, B the tool):
NEAR = ("0", "0", "0.097", "1", "0", "0", "0")  # 0.45 mm apart: 8 LMDs (7 patches) within a 10 mm cutoff, no crossing
CROSSING = ("0.1", "0", "0", "1", "0", "0", "0")  # the surfaces cross: polylines
FAR = ("0.5", "0", "0", "1", "0", "0", "0")  # 0.3 m apart: nothing within the cutoff
SIDE = ("-0.14", "0", "0", "1", "0", "0", "0")  # 1 mm apart along x: 2 LMDs, a few of their pixels in view
STRING_RADIUS = (2.0 + 6.0) / 2  # the widest string: 8 px (docs/viewer.md)
POLYLINE_RADIUS = 3.0 / 2
MAGENTA = (255, 0, 255)


def run(*args, env=None, timeout=300):
    return subprocess.run([VIEWER, *args], capture_output=True, text=True, timeout=timeout,
                          env=sanitizers.environment(VIEWER, env))


def render(directory, name, pose, show, *extra):
    out = os.path.join(directory, name)
    bunny = os.path.join(ASSETS, "bunny.obj")
    r = run(bunny, bunny, "--pose-b", *pose, "--headless", "--validation", "--size", f"{SIZE[0]}x{SIZE[1]}",
            "--show", show, "--out", out, *extra)
    if r.returncode != 0 or re.search(VALIDATION, r.stderr):
        raise AssertionError(f"proxima-viewer failed ({r.returncode}) for {name}:\n{r.stdout}{r.stderr}")
    with open(os.path.join(out, "frame-0000.json")) as f:
        sidecar = json.load(f)
    return png.read(os.path.join(out, "frame-0000.png")), sidecar


def project(sidecar, p):
    """World point -> pixel coordinates (x right, y down) with the frame's matrices."""
    v, pr = sidecar["view"], sidecar["proj"]

    def mul(m, x):  # column-major 4x4 times a 4-vector
        return [sum(m[c * 4 + r] * x[c] for c in range(4)) for r in range(4)]

    clip = mul(pr, mul(v, [p[0], p[1], p[2], 1.0]))
    w, h = sidecar["viewport"]
    return ((clip[0] / clip[3] * 0.5 + 0.5) * w, (clip[1] / clip[3] * 0.5 + 0.5) * h, clip[2] / clip[3])


def changed(a, b):
    """Pixels (x, y) whose colour differs between two images."""
    out = set()
    for y in range(a.height):
        for x in range(a.width):
            i = 3 * (y * a.width + x)
            if a.rgb[i:i + 3] != b.rgb[i:i + 3]:
                out.add((x, y))
    return out


def distance_to_segment(px, py, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((px - a[0]) * dx + (py - a[1]) * dy) / length2))
    return math.hypot(px - a[0] - t * dx, py - a[1] - t * dy)


def samples(a, b):
    """Pixels along a projected segment, one per pixel of length, ends included."""
    n = max(1, int(math.hypot(b[0] - a[0], b[1] - a[1])))
    return {(int(a[0] + (b[0] - a[0]) * k / n), int(a[1] + (b[1] - a[1]) * k / n)) for k in range(n + 1)}


def string_segments(sidecar):
    return [(project(sidecar, c["point_tool"]), project(sidecar, c["point_other"])) for c in sidecar["contacts"]]


def polyline_segments(sidecar):
    out = []
    for line in sidecar["polylines"]:
        pts = [project(sidecar, p) for p in line]
        out += list(zip(pts, pts[1:]))
    return out


def on_ramp(rgb):
    """The strings' colours: green through yellow to red, no blue."""
    return rgb[2] == 0 and (rgb[0] == 255 or rgb[1] == 255)


def obj_vertices(path):
    with open(path) as f:
        return [tuple(float(x) for x in line.split()[1:4]) for line in f if line.startswith("v ")]


class ViewerTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        d = cls.tmp.name
        near = ("--cutoff", "0.01", "--msaa", "1")
        cls.near_strings = render(d, "near-strings", NEAR, "strings", *near)
        cls.near_none = render(d, "near-none", NEAR, "none", *near)
        cls.near_all = render(d, "near-all", NEAR, "all", *near)
        cls.near_no_strings = render(d, "near-no-strings", NEAR, "meshes,polylines,force,hud,grid", *near)
        cls.side_all = render(d, "side-all", SIDE, "all", *near)
        cls.side_no_strings = render(d, "side-no-strings", SIDE, "meshes,polylines,force,hud,grid", *near)
        cls.near_hud = render(d, "near-hud", NEAR, "hud", *near)
        cls.near_meshes = render(d, "near-meshes", NEAR, "meshes", *near)
        cls.near_strings_4x = render(d, "near-strings-4x", NEAR, "strings", "--cutoff", "0.01", "--msaa", "4")
        cls.near_none_4x = render(d, "near-none-4x", NEAR, "none", "--cutoff", "0.01", "--msaa", "4")
        cls.crossing_polylines = render(d, "crossing-polylines", CROSSING, "polylines", "--msaa", "1")
        cls.crossing_none = render(d, "crossing-none", CROSSING, "none", "--msaa", "1")
        cls.crossing_all = render(d, "crossing-all", CROSSING, "all", "--msaa", "1")
        cls.crossing_no_polylines = render(d, "crossing-no-polylines", CROSSING, "meshes,strings,force,hud,grid",
                                           "--msaa", "1")
        cls.far_all = render(d, "far-all", FAR, "all", "--msaa", "1")
        cls.far_no_strings = render(d, "far-no-strings", FAR, "meshes,polylines,force,hud,grid", "--msaa", "1")
        cls.far_no_polylines = render(d, "far-no-polylines", FAR, "meshes,strings,force,hud,grid", "--msaa", "1")

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def assert_changes_follow(self, with_, without, segments, radius, colour_ok, what):
        image, sidecar = with_
        diff = changed(image, without[0])
        self.assertTrue(segments, f"the scene has no {what}")
        # Every changed pixel lies on a projected segment (its centre within the line's radius, plus a pixel).
        stray = [p for p in diff
                 if min(distance_to_segment(p[0] + 0.5, p[1] + 0.5, a, b) for a, b in segments) > radius + 1.0]
        self.assertEqual(stray, [], f"pixels changed away from every projected {what}")
        # ... and every pixel along every projected segment changed, to a colour of its kind.
        for a, b in segments:
            for p in samples(a, b):
                if 0 <= p[0] < image.width and 0 <= p[1] < image.height:
                    self.assertIn(p, diff, f"{what} from {a[:2]} to {b[:2]}: pixel {p} did not change")
                    self.assertTrue(colour_ok(image.pixel(*p)), f"{what}: pixel {p} is {image.pixel(*p)}")
        return diff

    def test_strings_are_exactly_where_the_contacts_project(self):
        sidecar = self.near_strings[1]
        # The near scene's 8 LMDs, two of them one patch (docs/patches.md): 7 contacts, and the
        # sidecar says which stands for two.
        self.assertEqual(len(sidecar["contacts"]), 7)
        self.assertEqual(sorted(c["patch_count"] for c in sidecar["contacts"]), [1, 1, 1, 1, 1, 1, 2])
        self.assert_changes_follow(self.near_strings, self.near_none, string_segments(sidecar), STRING_RADIUS,
                                   on_ramp, "string")

    def test_strings_are_where_the_contacts_project_with_4x_msaa(self):
        # Resolved edges blend with the background: the colour test is on the pixels' centres only.
        sidecar = self.near_strings_4x[1]
        self.assertEqual(len(sidecar["contacts"]), 7)
        self.assert_changes_follow(self.near_strings_4x, self.near_none_4x, string_segments(sidecar),
                                   STRING_RADIUS, lambda rgb: rgb[2] <= 40, "string")

    def test_string_colour_follows_the_distance_ramp(self):
        # Green at the cutoff, yellow half way, red at the safety distance (hard: 0.3 mm).
        image, sidecar = self.near_strings
        segments = string_segments(sidecar)
        checked = 0
        for i, c in enumerate(sidecar["contacts"]):
            a, b = segments[i]
            mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
            if any(j != i and distance_to_segment(mid[0], mid[1], *segments[j]) < 2 * STRING_RADIUS + 2
                   for j in range(len(segments))):
                continue  # another string crosses here
            t = max(0.0, min(1.0, (c["distance"] - 0.0003) / (0.01 - 0.0003)))
            want = (255 if t < 0.5 else round(510 * (1 - t)), round(510 * t) if t < 0.5 else 255, 0)
            got = image.pixel(int(mid[0]), int(mid[1]))
            for k in range(3):
                self.assertLessEqual(abs(got[k] - want[k]), 2, f"contact {i} at {c['distance']} m: {got}, not {want}")
            checked += 1
        self.assertGreater(checked, 0, "every string's middle is crossed by another")

    def test_in_the_whole_scene_strings_change_only_their_own_pixels(self):
        # Strings lie in the gap between two surfaces, so the meshes hide most of them.
        for (image, sidecar), without, visible in ((self.near_all, self.near_no_strings, 0),
                                                   (self.side_all, self.side_no_strings, 1)):
            diff = changed(image, without[0])
            segments = string_segments(sidecar)
            self.assertTrue(segments)
            self.assertGreaterEqual(len(diff), visible, "the strings are hidden in the whole scene")
            stray = [p for p in diff
                     if min(distance_to_segment(p[0] + 0.5, p[1] + 0.5, a, b) for a, b in segments) > STRING_RADIUS + 1]
            self.assertEqual(stray, [])
            self.assertTrue(all(on_ramp(image.pixel(*p)) for p in diff))

    def test_polylines_are_where_the_meshes_cross(self):
        sidecar = self.crossing_polylines[1]
        self.assertGreater(len(sidecar["polylines"]), 0)
        self.assert_changes_follow(self.crossing_polylines, self.crossing_none, polyline_segments(sidecar),
                                   POLYLINE_RADIUS, lambda rgb: rgb == MAGENTA, "polyline")

    def test_in_the_whole_scene_polylines_show_and_change_only_their_own_pixels(self):
        image, sidecar = self.crossing_all
        diff = changed(image, self.crossing_no_polylines[0])
        segments = polyline_segments(sidecar)
        self.assertGreater(len([p for p in diff if image.pixel(*p) == MAGENTA]), 20)
        stray = [p for p in diff
                 if min(distance_to_segment(p[0] + 0.5, p[1] + 0.5, a, b) for a, b in segments) > POLYLINE_RADIUS + 1]
        self.assertEqual(stray, [])
        # No string shares the polylines' colour.
        strings = self.near_strings[0]
        self.assertFalse(any(strings.pixel(x, y) == MAGENTA for x in range(strings.width) for y in range(strings.height)))

    def test_nothing_of_either_when_far_apart(self):
        image, sidecar = self.far_all
        self.assertEqual(sidecar["contacts"], [])
        self.assertEqual(sidecar["polylines"], [])
        self.assertEqual(sidecar["force"], [0, 0, 0])
        self.assertEqual(changed(image, self.far_no_strings[0]), set())
        self.assertEqual(changed(image, self.far_no_polylines[0]), set())
        pixels = [image.pixel(x, y) for y in range(image.height) for x in range(image.width)]
        self.assertNotIn(MAGENTA, pixels)
        self.assertFalse(any(on_ramp(p) for p in pixels), "a string-coloured pixel with no contact")

    def test_sidecar_matches_the_frame(self):
        image, sidecar = self.near_all
        self.assertEqual(sidecar["viewport"], [image.width, image.height])
        self.assertEqual(tuple(sidecar["background"]), image.pixel(image.width - 1, 0))
        self.assertEqual(len(sidecar["view"]), 16)
        self.assertEqual(len(sidecar["proj"]), 16)
        self.assertEqual(len(sidecar["force"]), 3)
        self.assertEqual(len(sidecar["torque"]), 3)
        # Near surfaces push the tool (B, at +z) away from A: +z.
        self.assertGreater(sidecar["force"][2], 0.0)
        for c in sidecar["contacts"]:
            self.assertAlmostEqual(math.dist(c["point_tool"], c["point_other"]), c["distance"], delta=1e-9)

    def test_hud_is_a_panel_in_the_top_left_corner(self):
        image, _ = self.near_hud
        diff = changed(image, self.near_none[0])
        self.assertGreater(len(diff), 2000, "no HUD")
        self.assertLess(max(x for x, _ in diff), image.width * 3 // 4)
        self.assertLess(max(y for _, y in diff), image.height * 3 // 4)
        self.assertLess(min(x for x, _ in diff), 20)
        self.assertLess(min(y for _, y in diff), 20)

    def test_meshes_cover_where_they_project(self):
        image, sidecar = self.near_meshes
        diff = changed(image, self.near_none[0])
        verts = obj_vertices(os.path.join(ASSETS, "bunny.obj"))
        offset = [float(x) for x in NEAR[:3]]
        masks, inside = [], 0
        for shift in ((0.0, 0.0, 0.0), offset):
            mask = set()
            for v in verts:
                x, y, z = project(sidecar, [v[0] + shift[0], v[1] + shift[1], v[2] + shift[2]])
                self.assertTrue(0 <= x < image.width and 0 <= y < image.height and 0 < z < 1,
                                f"vertex {v} projects outside the frame: the camera does not frame the scene")
                inside += (int(x), int(y)) in diff or any((int(x) + dx, int(y) + dy) in diff
                                                          for dx in (-1, 0, 1) for dy in (-1, 0, 1))
                mask |= {(int(x) + dx, int(y) + dy) for dx in range(-2, 3) for dy in range(-2, 3)}
            masks.append(mask)
        self.assertGreaterEqual(inside, 0.99 * 2 * len(verts), "projected vertices on unchanged pixels")
        covered = masks[0] | masks[1]
        self.assertGreaterEqual(len([p for p in diff if p in covered]), 0.995 * len(diff),
                                "pixels drawn away from every projected vertex")
        # The tool in its own colour: bluer than red where only it projects; A the other way round.
        only_tool = [image.pixel(*p) for p in diff if p in masks[1] and p not in masks[0]]
        only_a = [image.pixel(*p) for p in diff if p in masks[0] and p not in masks[1]]
        self.assertGreater(len(only_tool), 1000)
        self.assertGreater(len(only_a), 1000)
        self.assertGreaterEqual(sum(p[2] > p[0] for p in only_tool), 0.95 * len(only_tool))
        self.assertGreaterEqual(sum(p[0] > p[2] for p in only_a), 0.95 * len(only_a))


class ViewerGltfTest(unittest.TestCase):
    def test_gltf_meshes_are_drawn_where_they_project(self):
        # Khronos' Box.glb (a unit cube under a node rotation) as both bodies, B 1.5 m along x.
        box = os.path.join(ASSETS, "gltf", "Box.glb")
        pose = ("1.5", "0", "0", "1", "0", "0", "0")
        images = {}
        with tempfile.TemporaryDirectory() as d:
            for show in ("meshes", "none"):
                out = os.path.join(d, show)
                r = run(box, box, "--pose-b", *pose, "--headless", "--validation", "--size", f"{SIZE[0]}x{SIZE[1]}",
                        "--msaa", "1", "--show", show, "--out", out)
                self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
                self.assertNotRegex(r.stderr, VALIDATION)
                with open(os.path.join(out, "frame-0000.json")) as f:
                    sidecar = json.load(f)
                images[show] = png.read(os.path.join(out, "frame-0000.png"))
        diff = changed(images["meshes"], images["none"])
        boxes = []
        for shift in (0.0, 1.5):
            corners = [project(sidecar, [shift + x, y, z]) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
            for x, y, z in corners:
                self.assertTrue(0 <= x < SIZE[0] and 0 <= y < SIZE[1] and 0 < z < 1, "the camera frames both boxes")
            boxes.append((min(c[0] for c in corners), max(c[0] for c in corners),
                          min(c[1] for c in corners), max(c[1] for c in corners)))
            cx, cy, _ = project(sidecar, [shift, 0.0, 0.0])
            self.assertIn((int(cx), int(cy)), diff, "nothing drawn where a box's centre projects")

        def inside(p):
            return any(x0 - 1 <= p[0] <= x1 + 1 and y0 - 1 <= p[1] <= y1 + 1 for x0, x1, y0, y1 in boxes)

        self.assertGreater(len(diff), 2000)
        self.assertEqual([p for p in diff if not inside(p)], [], "pixels drawn outside both boxes' projections")


def coverage(sidecar, triangles, margin):
    """Pixels whose centre lies inside a projected triangle by more than `margin` px (negative: within
    -margin px outside it)."""
    w, h = sidecar["viewport"]
    out = set()
    for tri in triangles:
        p = [project(sidecar, v)[:2] for v in tri]
        area = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0])
        if area == 0:
            continue
        edges = []
        for a, b in ((p[0], p[1]), (p[1], p[2]), (p[2], p[0])):
            length = math.hypot(b[0] - a[0], b[1] - a[1])
            edges.append((a, b, length, 1.0 if area > 0 else -1.0))
        x0, x1 = int(max(0, min(q[0] for q in p) - 2)), int(min(w - 1, max(q[0] for q in p) + 2))
        y0, y1 = int(max(0, min(q[1] for q in p) - 2)), int(min(h - 1, max(q[1] for q in p) + 2))
        for y in range(y0, y1 + 1):
            for x in range(x0, x1 + 1):
                c = (x + 0.5, y + 0.5)
                if all(length > 0 and sign * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / length
                       > margin for a, b, length, sign in edges):
                    out.add((x, y))
    return out


class ViewerAnimationTest(unittest.TestCase):
    def check_played(self, tool):
        # AnimatedMorphCube (a 2 m cube; its first morph target flattens it along world z, its weight 1 at
        # 1.6 s) playing animation 0 with Box.glb, the tool 4 m along x: the cube as A (--animate) or as the
        # tool (--animate-b). Headless, frames are 1/60 s apart: frame 0 is the cube at rest, frame 96 the
        # flat one. The oracle poses the file here.
        cube, box = os.path.join(ASSETS, "gltf", "AnimatedMorphCube.glb"), os.path.join(ASSETS, "gltf", "Box.glb")
        args = (box, cube, "--animate-b", "0") if tool else (cube, box, "--animate", "0")
        shift = 4.0 if tool else 0.0
        oracle = gltf_pose.Gltf(cube)

        def triangles(*at):
            return [tuple((v[0] + shift, v[1], v[2]) for v in tri) for tri in oracle.triangles(*at)]

        frames = (0, 96)
        with tempfile.TemporaryDirectory() as d:
            r = run(*args, "--pose-b", "4", "0", "0", "1", "0", "0", "0", "--headless", "--validation", "--frames",
                    str(frames[-1] + 1), "--size", f"{SIZE[0]}x{SIZE[1]}", "--msaa", "1", "--show", "meshes", "--out", d)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertNotRegex(r.stderr, VALIDATION)
            shots = {}
            for i in frames:
                with open(os.path.join(d, f"frame-{i:04d}.json")) as f:
                    shots[i] = (png.read(os.path.join(d, f"frame-{i:04d}.png")), json.load(f))
        # The camera holds the cube over its whole animation (4.2 s): every posed vertex is in the frame.
        for k in range(0, 253, 6):
            for tri in triangles(0, k / 60):
                for v in tri:
                    x, y, z = project(shots[0][1], v)
                    self.assertTrue(0 <= x < SIZE[0] and 0 <= y < SIZE[1] and 0 < z < 1, f"{v} at {k / 60} s")
        rest = triangles()
        drawn = {}
        for i in frames:
            image, sidecar = shots[i]
            posed = triangles(0, i / 60)
            # The cube's pixels (A warm grey, the tool blue): all of the posed cube's inside, nothing outside
            # it (pixel centres within 0.75 px of an edge may go either way).
            drawn[i] = {(x, y) for y in range(image.height) for x in range(image.width)
                        if (image.pixel(x, y)[2] > image.pixel(x, y)[0]) == tool and image.pixel(x, y) !=
                        tuple(sidecar["background"])}
            inside, hull = coverage(sidecar, posed, 0.75), coverage(sidecar, posed, -0.75)
            self.assertGreater(len(inside), 3000)
            self.assertEqual(inside - drawn[i], set(), f"frame {i}: pixels of the posed mesh not drawn")
            self.assertEqual(drawn[i] - hull, set(), f"frame {i}: pixels drawn outside the posed mesh")
            if i:
                # Where the cube was at rest and no longer is: the rest pose drawn would fail above.
                self.assertGreater(len(coverage(sidecar, rest, 0.75) - hull), 3000)
        self.assertGreater(len(drawn[0] ^ drawn[96]), 3000, "the silhouette did not change")

    def test_the_animated_mesh_is_drawn_as_posed(self):
        self.check_played(tool=False)

    def test_the_animated_tool_is_drawn_as_posed(self):
        self.check_played(tool=True)


class ViewerConstrainedTest(unittest.TestCase):
    def test_the_constrained_tool_stays_out_and_its_device_pose_is_a_ghost(self):
        # The scripted device goes from 0.3 m out to x = 0.1, where the bunnies cross, and holds there;
        # the constrained tool (its proxy) stops outside A, and the device pose is drawn as a ghost.
        bunny = os.path.join(ASSETS, "bunny.obj")
        frames = 150
        with tempfile.TemporaryDirectory() as d:
            poses = os.path.join(d, "poses.txt")
            with open(poses, "w") as f:
                f.write("0.3 0 0 1 0 0 0\n" + "0.1 0 0 1 0 0 0\n" * 40)
            last = {}
            for show in ("meshes,ghost", "meshes"):
                out = os.path.join(d, show.replace(",", "-"))
                r = run(bunny, bunny, "--poses", poses, "--seconds", "30", "--tool-mode", "constrained",
                        "--headless", "--validation", "--frames", str(frames), "--size", f"{SIZE[0]}x{SIZE[1]}",
                        "--msaa", "1", "--show", show, "--out", out)
                self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
                self.assertNotRegex(r.stderr, VALIDATION)
                for i in range(frames):
                    with open(os.path.join(out, f"frame-{i:04d}.json")) as f:
                        s = json.load(f)
                    # The proxy never crosses A: no polyline, no contact closer than half the 0.3 mm
                    # safety distance of the hard settings.
                    self.assertEqual(s["polylines"], [], f"frame {i}")
                    for c in s["contacts"]:
                        self.assertGreater(c["distance"], 0.00015, f"frame {i}")
                last[show] = (png.read(os.path.join(out, f"frame-{frames - 1:04d}.png")), s)
        image, s = last["meshes,ghost"]
        self.assertEqual(s["device_pose"][0], 0.1, "the device holds inside A by the last frame")
        self.assertTrue(s["ghost"])
        self.assertGreater(s["tool_pose"][0], 0.13, "the proxy stopped outside A")
        # The ghost: the pixels that differ from the frame without it lie where the bunny projects at
        # the device pose. The two runs' proxies may have slid to slightly different places: their
        # pixels are left out.
        verts = obj_vertices(bunny)

        def footprint(pose):
            w, x, y, z = pose[3:]
            rot = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                   [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                   [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
            mask = set()
            for v in verts:
                p = [sum(rot[r][c] * v[c] for c in range(3)) + pose[r] for r in range(3)]
                px, py, _ = project(s, p)
                mask |= {(int(px) + dx, int(py) + dy) for dx in range(-2, 3) for dy in range(-2, 3)}
            return mask

        ghost = footprint(s["device_pose"])
        proxies = footprint(s["tool_pose"]) | footprint(last["meshes"][1]["tool_pose"])
        diff = [p for p in changed(image, last["meshes"][0]) if p not in proxies]
        self.assertGreater(len(diff), 150, "no ghost beside the proxy")
        self.assertGreaterEqual(len([p for p in diff if p in ghost]), 0.97 * len(diff))


class ViewerRunTest(unittest.TestCase):
    def test_the_built_in_scene_moves_the_tool_on_the_threads(self):
        with tempfile.TemporaryDirectory() as d:
            # Legs of 30 ms: the 60 frames see the path loop more than once, however fast they are.
            r = run("--headless", "--validation", "--frames", "60", "--seconds", "0.03", "--size", "320x180",
                    "--msaa", "1", "--out", d)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertNotRegex(r.stderr, VALIDATION)
            self.assertRegex(r.stdout, r"haptic thread +\d+\.\d Hz")
            counts = []
            for i in range(60):
                with open(os.path.join(d, f"frame-{i:04d}.json")) as f:
                    s = json.load(f)
                counts.append(len(s["contacts"]))
            # Path T: in and out of the cutoff, and held near with contacts.
            self.assertGreater(max(counts), 0, counts)
            self.assertIn(0, counts)

    def test_a_poses_file_drives_the_scripted_device(self):
        with tempfile.TemporaryDirectory() as d:
            poses = os.path.join(d, "poses.txt")
            with open(poses, "w") as f:
                f.write("# A against A: from 0.3 m out to 1 mm apart along x (the shared bunny's path T end)\n")
                f.write("0.3 0 0 1 0 0 0\n0.14 0 0 1 0 0 0\n0.14 0 0 1 0 0 0\n")
            bunny = os.path.join(ASSETS, "bunny.obj")
            r = run(bunny, bunny, "--poses", poses, "--seconds", "0.1", "--headless", "--validation", "--frames", "150",
                    "--size", "160x90", "--msaa", "1", "--show", "none", "--out", d)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            counts = []
            for i in range(150):
                with open(os.path.join(d, f"frame-{i:04d}.json")) as f:
                    counts.append(len(json.load(f)["contacts"]))
            # The path loops: out of range at its start, within the cutoff where it holds.
            self.assertIn(0, counts)
            self.assertGreater(max(counts), 0, counts)

    def test_method_and_force_reach_the_world(self):
        def scene(pose, method, force):
            with tempfile.TemporaryDirectory() as d:
                bunny = os.path.join(ASSETS, "bunny.obj")
                r = run(bunny, bunny, "--pose-b", *pose, "--method", method, "--force", force, "--cutoff", "0.01",
                        "--headless", "--validation", "--size", "160x90", "--show", "none", "--out", d)
                self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
                with open(os.path.join(d, "frame-0000.json")) as f:
                    s = json.load(f)
                return len(s["contacts"]), math.hypot(*s["force"])

        # The near scene's 8 LMDs within 10 mm (precise), two of them one patch (docs/patches.md): 7
        # contacts; the original method's 7 x 7 samples find others.
        precise, original = scene(NEAR, "precise", "hard"), scene(NEAR, "original", "hard")
        self.assertEqual(precise[0], 7)
        self.assertGreater(original[0], 0)
        self.assertNotEqual(original, precise)
        # 1 mm apart: soft (full force inside 2 mm) renders the 3 N maximum; hard (safety 0.3 mm, decay
        # 0.3 mm) e^-(0.7/0.3) of it per contact.
        self.assertAlmostEqual(scene(SIDE, "precise", "soft")[1], 3.0, places=6)
        self.assertLess(scene(SIDE, "precise", "hard")[1], 1.0)

    def test_bad_input_gets_a_clear_error(self):
        bunny = os.path.join(ASSETS, "bunny.obj")
        cube = os.path.join(ASSETS, "gltf", "AnimatedMorphCube.glb")
        with tempfile.TemporaryDirectory() as d:
            missing = os.path.join(d, "missing.obj")
            broken = os.path.join(d, "broken.gltf")
            with open(broken, "w") as f:
                f.write('{"asset": {"version": "2.0"}, "meshes": [')
            cases = [
                ((missing, bunny, "--headless"), 1, "missing.obj"),
                ((broken, bunny, "--headless"), 1, "broken.gltf"),
                (("--show", "strings,bogus"), 2, "bogus"),
                (("--size", "640"), 2, "WxH"),
                (("--msaa", "2"), 2, "--msaa"),
                (("--frames", "0"), 2, "--frames"),
                (("--device", "mouse", "--headless"), 2, "window"),
                (("--device", "joystick"), 2, "joystick"),
                (("--pose-b", "0", "0", "0", "0", "0", "0", "0"), 2, "quaternion"),
                ((bunny,), 2, "two meshes"),
                (("--poses", missing, "--headless"), 1, "missing.obj"),
                (("--out", d, "--frames", "2"), 2, "--headless"),
                (("--animate", "x"), 2, "--animate"),
                ((cube, bunny, "--animate", "1", "--headless"), 1, "--animate 1: " + cube + " has 1 animation"),
                ((cube, bunny, "--animate-b", "0", "--headless"), 1, "--animate-b 0: " + bunny + " has no animations"),
                (("--animate", "0", "--headless"), 1, "has no animations"),
            ]
            for args, code, text in cases:
                with self.subTest(args=args):
                    r = run(*args)
                    self.assertEqual(r.returncode, code, r.stdout + r.stderr)
                    self.assertIn(text, r.stderr)
                    self.assertTrue(r.stderr.startswith("proxima-viewer: "), r.stderr)

    def test_no_display_for_a_window(self):
        env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
        r = run("--frames", "1", env=env)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("no display", r.stderr)
        self.assertIn("--headless", r.stderr)

    def test_no_vulkan_device(self):
        env = dict(os.environ, VK_ICD_FILENAMES="/nonexistent/icd.json", VK_DRIVER_FILES="/nonexistent/icd.json")
        r = run("--headless", env=env)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("Vulkan", r.stderr)
        self.assertTrue(r.stderr.startswith("proxima-viewer: "), r.stderr)

    def test_help_lists_the_options(self):
        r = run("--help")
        self.assertEqual(r.returncode, 0)
        for option in ("--pose-b", "--cutoff", "--headless", "--frames", "--out", "--size", "--show", "--validation",
                       "--device", "--poses", "--method", "--force", "auto", "--animate", "--animate-b"):
            self.assertIn(option, r.stdout)


if __name__ == "__main__":
    VIEWER = os.path.abspath(sys.argv.pop(1))
    ASSETS = os.path.abspath(sys.argv.pop(1))
    unittest.main()
