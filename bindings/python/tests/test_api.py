"""The API on the shared bunny: meshes, bodies, poses, the step and its results."""

import importlib.metadata
import math
import pathlib
import re

import numpy as np
import pytest

import proxima
from proxima._core import ffi, lib

from conftest import ASSETS, BUNNY, NEAR_POSE, REPO, box_centre, cube


def test_version_agrees_with_library_header_and_metadata():
    v = lib.proxGetVersion()
    assert proxima.__version__ == f"{v.major}.{v.minor}.{v.patch}"
    header = (REPO / "sdk/include/proxima/version.h").read_text()
    assert f'#define PROX_VERSION_STRING "{proxima.__version__}"' in header
    assert importlib.metadata.version("proxima") == proxima.__version__


def test_load_mesh_info_and_stats(world):
    mesh = world.load_mesh(BUNNY)
    info = mesh.info
    assert (info.triangle_count, info.vertex_count) == (27864, 13934)
    assert (info.dropped_triangles, info.boundary_edges, info.non_manifold_edges) == (0, 0, 0)
    assert info.bounds_min.shape == (3,) and np.all(info.bounds_min < info.bounds_max)
    stats = mesh.stats
    assert stats.input_triangles == 27864 and stats.hierarchy_nodes > stats.hierarchy_leaves > 0
    assert stats.hierarchy_bytes > 0 and stats.hierarchy_seconds > 0


def _triples(vertices, triangles):
    """Each triangle as its three positions from its smallest vertex on
    (the winding kept), sorted: comparable across vertex numberings."""
    out = []
    for tri in np.asarray(vertices)[np.asarray(triangles)]:
        k = min(range(3), key=lambda i: tuple(tri[i]))
        out.append(tuple(map(tuple, np.roll(tri, -k, axis=0))))
    return sorted(out)


def test_mesh_triangles_give_back_the_welded_mesh(world):
    v, t = cube()
    # Each triangle with vertices of its own, as glTF seams split them.
    split_v = v[t.reshape(-1)]
    split_t = np.arange(len(split_v)).reshape(-1, 3)
    mesh = world.create_mesh(split_v, split_t)
    vertices, triangles = mesh.triangles()
    assert vertices.shape == (8, 3) and vertices.dtype == np.float64
    assert triangles.shape == (12, 3) and triangles.dtype == np.uint32
    assert _triples(vertices, triangles) == _triples(v, t)


def test_mesh_triangles_of_the_bunny_file(world):
    rows = [line.split() for line in BUNNY.read_text().splitlines()]
    v = np.array([[float(x) for x in r[1:4]] for r in rows if r and r[0] == "v"])
    t = np.array([[int(x.split("/")[0]) - 1 for x in r[1:4]] for r in rows if r and r[0] == "f"])
    vertices, triangles = world.load_mesh(BUNNY).triangles()
    assert len(triangles) == world.load_mesh(BUNNY).info.triangle_count
    assert _triples(vertices, triangles) == _triples(v, t)


def test_load_mesh_bytes_is_the_files_mesh(world):
    data = BUNNY.read_bytes()
    expected = world.load_mesh(BUNNY).triangles()
    for given in (data, bytearray(data), memoryview(data)):
        vertices, triangles = world.load_mesh_bytes(given, "bunny.obj").triangles()
        np.testing.assert_array_equal(vertices, expected[0])
        np.testing.assert_array_equal(triangles, expected[1])
    box = ASSETS / "gltf" / "Box.glb"
    for a, b in zip(world.load_mesh_bytes(box.read_bytes(), "Box.glb").triangles(), world.load_mesh(box).triangles()):
        np.testing.assert_array_equal(a, b)
    with pytest.raises(proxima.InvalidArgument, match="data must be bytes-like"):
        world.load_mesh_bytes("v 0 0 0", "a.obj")
    with pytest.raises(proxima.InvalidArgument, match="name must be a str"):
        world.load_mesh_bytes(data, None)
    with pytest.raises(proxima.InvalidArgument, match="a.obj: size is 0"):
        world.load_mesh_bytes(b"", "a.obj")
    with pytest.raises(proxima.Unsupported, match="a.stl"):
        world.load_mesh_bytes(data, "a.stl")
    with pytest.raises(proxima.ParseError, match="broken.obj:1"):
        world.load_mesh_bytes(b"f 1 2 3\n", "broken.obj")
    gltf = ASSETS / "gltf" / "TriangleWithoutIndices" / "TriangleWithoutIndices.gltf"
    with pytest.raises(proxima.FileError, match="embed its buffers"):
        world.load_mesh_bytes(gltf.read_bytes(), gltf.name)


def test_mesh_warnings_name_what_loading_skipped(world, tmp_path):
    # One triangle whose unused NORMAL accessor runs past its buffer view:
    # it loads, and the warning says which attribute was skipped.
    import base64
    import json
    import struct
    data = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    gltf = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteLength": len(data)}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 0, "componentType": 5126, "count": 30, "type": "VEC3"},
        ],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}}]}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
        "scene": 0,
    }
    path = tmp_path / "bad-normal.gltf"
    path.write_text(json.dumps(gltf))
    mesh = world.load_mesh(path)
    assert mesh.info.triangle_count == 1
    assert len(mesh.warnings) == 1 and "NORMAL" in mesh.warnings[0], mesh.warnings
    assert world.load_mesh(BUNNY).warnings == []


def test_load_mesh_gltf_and_glb_agree_with_obj(world):
    obj = world.load_mesh(BUNNY).info
    glb = world.load_mesh(ASSETS / "bunny.glb").info
    assert glb.triangle_count == obj.triangle_count
    np.testing.assert_allclose(glb.bounds_min, obj.bounds_min, atol=1e-7)
    suzanne = world.load_mesh(str(ASSETS / "gltf/Suzanne/Suzanne.gltf")).info
    assert suzanne.triangle_count == 3936 and suzanne.boundary_edges == 84


def test_create_mesh_from_arrays(world):
    v, t = cube()
    info = world.create_mesh(v, t).info
    assert (info.triangle_count, info.vertex_count, info.boundary_edges) == (12, 8, 0)
    np.testing.assert_array_equal(info.bounds_min, [0, 0, 0])
    np.testing.assert_array_equal(info.bounds_max, [1, 1, 1])


@pytest.mark.parametrize("dtype", [np.int8, np.uint8, np.int16, np.uint16, np.int32, np.uint32, np.int64, np.uint64])
def test_create_mesh_takes_any_integer_dtype(world, dtype):
    v, t = cube()
    assert world.create_mesh(v, t.astype(dtype)).info.triangle_count == 12


def test_create_mesh_takes_non_contiguous_arrays(world):
    v, t = cube()
    wide = np.zeros((8, 6))
    wide[:, ::2] = v
    strided_v = wide[:, ::2]
    fortran_t = np.asfortranarray(t)
    reversed_t = t[::-1][::-1]
    assert not strided_v.flags.c_contiguous and not fortran_t.flags.c_contiguous
    a = world.create_mesh(strided_v, fortran_t).info
    b = world.create_mesh(v.astype(np.float32), reversed_t).info
    assert (a.triangle_count, a.vertex_count, a.boundary_edges) == (12, 8, 0)
    assert (b.triangle_count, b.vertex_count) == (12, 8)
    np.testing.assert_array_equal(a.bounds_max, [1, 1, 1])


def test_create_mesh_drops_triangles_that_repeat_a_vertex(world):
    v, t = cube()
    t = np.vstack([t, [[0, 0, 1]]])
    info = world.create_mesh(v, t).info
    assert info.triangle_count == 12 and info.dropped_triangles == 1


def test_bodies_poses_and_types(world, bunny):
    rock = world.create_body(bunny, "static")
    mover = world.create_body(bunny, "movable", pose=((1, 2, 3), (0, 0, 0, 2)))
    tool = world.create_body(bunny, "tool")
    assert (rock.type, mover.type, tool.type) == ("static", "movable", "tool")
    assert rock.mesh is bunny and tool.world is world
    p, q = mover.pose
    np.testing.assert_array_equal(p, [1, 2, 3])
    np.testing.assert_array_equal(q, [0, 0, 0, 1])  # normalised on input
    tool.pose = (np.array([0.5, 0, 0]), [1, 0, 0, 0])
    p, q = tool.pose
    assert isinstance(p, np.ndarray) and p.shape == (3,) and q.shape == (4,)
    np.testing.assert_array_equal(p, [0.5, 0, 0])
    assert world.stats.bodies == 3 and world.stats.tools == 1


def test_set_vertices_deforms_the_mesh_for_every_body_using_it(world):
    v, t = cube()
    wall_mesh, tool_mesh = world.create_mesh(v * 0.1, t), world.create_mesh(v * 0.1, t)
    world.create_body(wall_mesh, "static")
    tool = world.create_body(tool_mesh, "tool", pose=([0.104, 0, 0], [1, 0, 0, 0]), reference_point=[0.05] * 3)
    world.step()
    assert tool.contacts()["distance"].min() == pytest.approx(0.004, rel=1e-9)
    # The wall's +x face moves 1.5 mm towards the tool: 2.5 mm to go.
    moved, _ = wall_mesh.triangles()
    moved[moved[:, 0] > 0.05, 0] += 0.0015
    wall_mesh.set_vertices(moved)
    np.testing.assert_array_equal(wall_mesh.triangles()[0], moved)
    assert wall_mesh.info.bounds_max[0] == pytest.approx(0.1015)
    world.step()
    assert tool.contacts()["distance"].min() == pytest.approx(0.0025, rel=1e-9)
    with pytest.raises(proxima.InvalidArgument, match="vertexCount is 7 but the mesh has 8"):
        wall_mesh.set_vertices(moved[:7])
    bad = moved.copy()
    bad[5, 1] = np.nan
    with pytest.raises(proxima.InvalidArgument, match="vertex 5 has a non-finite y"):
        wall_mesh.set_vertices(bad)
    with pytest.raises(proxima.InvalidArgument, match="shape"):
        wall_mesh.set_vertices(moved.ravel())


def _sheet(n, side):
    """An n x n sheet of side `side` in z = 0 facing +z: (vertices, triangles)."""
    g = np.linspace(0.0, side, n + 1)
    xs, ys = np.meshgrid(g, g)
    vertices = np.column_stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)])
    a = (np.arange(n)[None, :] + (n + 1) * np.arange(n)[:, None]).ravel()
    triangles = np.concatenate([np.column_stack([a, a + 1, a + n + 2]), np.column_stack([a, a + n + 2, a + n + 1])])
    return vertices, triangles


def test_workers_split_a_deformation_and_give_the_same_contacts():
    # A sheet of 16,200 triangles (enough to be split) under a wave, a small
    # tilted sheet above it: the same contacts, to the bit, on 1 and 3 threads.
    flat, tris = _sheet(90, 0.2)
    small, small_tris = _sheet(6, 0.02)
    moved = flat.copy()
    moved[:, 2] = 0.002 * np.sin(2 * np.pi * moved[:, 0] / 0.05)
    found = []
    for workers in (1, 3):
        with proxima.World(workers=workers) as w:
            floor = w.create_mesh(flat, tris)
            w.create_body(floor, "static")
            half = 0.015
            tool = w.create_body(w.create_mesh(small, small_tris), "tool",
                                 pose=([0.09, 0.09, 0.003], [np.cos(half), np.sin(half), 0, 0]))
            floor.set_vertices(moved)
            w.step()
            found.append(tool.contacts())
    assert len(found[0]) > 0
    for field in ("point_tool", "point_other", "normal", "distance"):
        np.testing.assert_array_equal(found[0][field], found[1][field])
    for bad in (0, 257):
        with pytest.raises(proxima.InvalidArgument, match="workerCount"):
            proxima.World(workers=bad)


def _near_scene(world, mesh):
    rock = world.create_body(mesh, "static")
    tool = world.create_body(mesh, "tool", pose=NEAR_POSE, reference_point=box_centre(mesh))
    return rock, tool


def test_step_contacts_wrench_and_stats(world, bunny):
    rock, tool = _near_scene(world, bunny)
    world.step()
    c = tool.contacts()
    assert c.dtype == proxima.contact_dtype
    # Six LMDs; two pairs of them (3.310 and 3.311 mm, 3.732 and 3.741 mm, a
    # few mm apart, one direction each) lie on flat stretches of the distance
    # field and are one patch each (docs/patches.md).
    assert world.patch_stats.lmds == 6 and world.patch_stats.merged == 2
    assert len(c) == 4
    assert set(c.dtype.names) == {"point_tool", "point_other", "normal", "distance", "triangle_tool",
                                  "triangle_other", "feature_tool", "feature_other", "patch_count",
                                  "patch_extent", "patch_spread", "patch_angle", "other"}
    # Each of those two contacts stands for its pair; the other two alone.
    assert sorted(c["patch_count"].tolist()) == [1, 1, 2, 2]
    assert c["patch_extent"][c["patch_count"] == 1].tolist() == [0.0, 0.0]
    assert all(o is rock for o in c["other"])
    # Each contact: the distance is the gap between its points, along the unit normal (other -> tool).
    gap = c["point_tool"] - c["point_other"]
    np.testing.assert_allclose(np.linalg.norm(gap, axis=1), c["distance"], rtol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(c["normal"], axis=1), 1, rtol=1e-12)
    assert np.all(np.einsum("ij,ij->i", gap, c["normal"]) > 0)
    assert np.all((c["feature_tool"] >= 0) & (c["feature_tool"] <= 2))
    assert np.all(c["triangle_tool"] < bunny.info.triangle_count)
    assert c["distance"].min() == pytest.approx(proxima.distance(rock, tool), rel=1e-12)

    force, torque, clipped = tool.wrench()
    assert force.shape == (3,) and torque.shape == (3,) and isinstance(clipped, bool)
    assert np.linalg.norm(force) > 0
    # Pushes the tool away from the rock: along the contacts' normals.
    assert force @ c["normal"].sum(axis=0) > 0

    s = world.stats
    assert (s.pairs_in_range, s.pairs_searched, s.contacts) == (1, 1, 4)
    assert s.candidates >= 6 and s.step_seconds > 0
    search = world.search_stats
    assert search.pairs_searched == 1 and search.candidates == s.candidates
    assert search.node_pairs > search.leaf_pairs > 0 and search.global_seconds > 0
    world.step()  # no pose changed: the search is skipped
    assert world.stats.pairs_searched == 0 and len(tool.contacts()) == 4


def test_track_carries_contacts_to_a_new_pose(world, bunny):
    rock, tool = _near_scene(world, bunny)
    assert world.track_stats.pairs_tracked == 0
    world.step()
    before = tool.contacts()
    p, q = tool.pose
    tool.pose = (p + [1e-5, 0, 0], q)
    world.track()
    t = world.track_stats
    assert t.pairs_tracked == 1 and t.contacts_in == len(before) and t.contacts_out > 0
    assert t.distance_evaluations + t.cache_hits > 0 and t.seconds > 0
    after = tool.contacts()
    assert after["distance"].min() > before["distance"].min()


def test_methods(bunny):
    for method in ("precise", "original", "reference"):
        with proxima.World(method=method) as w:
            m = w.load_mesh(BUNNY) if method != "reference" else w.create_mesh(*cube())
            rock = w.create_body(m, "static")
            tool = w.create_body(m, "tool", pose=((1.002, 0, 0), (1, 0, 0, 0)) if method == "reference"
                                 else NEAR_POSE)
            w.step()
            d = tool.contacts()["distance"]
            assert len(d) > 0 and d.min() == pytest.approx(proxima.distance(rock, tool), rel=1e-9 if
                                                           method != "original" else 0.5)


def test_force_presets_and_settings():
    hard, hard_cutoff = proxima.force_preset("hard")
    soft, soft_cutoff = proxima.force_preset("soft")
    assert (hard.curve, soft.curve) == ("exponential", "linear")
    assert (hard_cutoff, soft_cutoff) == (0.005, 0.01)
    assert proxima.ForceSettings() == hard
    with proxima.World(force="soft") as w:
        assert w._cutoff == soft_cutoff
    settings = proxima.ForceSettings(max_force=1e-4)

    def force_at(force):
        with proxima.World(force=force, cutoff=0.005) as w:
            m = w.load_mesh(BUNNY)
            w.create_body(m, "static")
            tool = w.create_body(m, "tool", pose=NEAR_POSE)
            w.step()
            return np.linalg.norm(tool.wrench()[0])

    assert 0 < force_at(settings) <= 1e-4 < force_at("hard")


def test_distance(world, bunny):
    rock = world.create_body(bunny, "static")
    tool = world.create_body(bunny, "tool", pose=((0.3, 0, 0), (1, 0, 0, 0)))
    d = proxima.distance(rock, tool)
    assert 0.1 < d < 0.3
    assert proxima.distance(rock, tool, max_distance=0.01) == math.inf
    assert proxima.distance(rock, tool, max_distance=1.0) == d
    tool.pose = ((0, 0, 0), (1, 0, 0, 0))
    assert proxima.distance(rock, tool) == 0


def test_intersections(world, bunny):
    rock = world.create_body(bunny, "static")
    tool = world.create_body(bunny, "tool", pose=((0.12, 0, 0), (1, 0, 0, 0)))
    assert world.create_body(bunny, "movable", pose=((5, 0, 0), (1, 0, 0, 0)))
    lines = tool.intersections()
    assert len(lines) >= 1
    stats = tool.intersection_stats
    assert stats.intersecting_pairs > 0 and stats.segments >= sum(len(p) - 1 for p, _, _ in lines)
    for points, closed, other in lines:
        assert points.shape[1] == 3 and len(points) >= 2 and isinstance(closed, bool) and other is rock
    tool.pose = ((0.3, 0, 0), (1, 0, 0, 0))
    assert tool.intersections() == []


def test_many_contacts_grow_the_buffer(world):
    # Two parallel grids of triangles 1 mm apart: every pair facing is a contact.
    n = 12
    xs, ys = np.meshgrid(np.arange(n + 1) * 0.01, np.arange(n + 1) * 0.01)
    v = np.column_stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)])
    idx = np.arange((n + 1) ** 2).reshape(n + 1, n + 1)
    a, b, c, d = idx[:-1, :-1].ravel(), idx[:-1, 1:].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel()
    up = np.vstack([np.column_stack([a, b, d]), np.column_stack([a, d, c])])
    plate = world.create_mesh(v, up)
    under = world.create_mesh(v, up[:, ::-1])
    world.create_body(plate, "static")
    tool = world.create_body(under, "tool", pose=((0, 0, 0.001), (1, 0, 0, 0)))
    world.step()
    c = tool.contacts()
    assert len(c) > 64 and len(c) == world.stats.contacts
    np.testing.assert_allclose(c["distance"], 0.001, rtol=1e-9)


def test_contacts_name_each_other_body(world, bunny):
    # The tool between two bunnies, 0.14 m from each: the same gap to both.
    left = world.create_body(bunny, "static")
    right = world.create_body(bunny, "static", pose=((0.28, 0, 0), (1, 0, 0, 0)))
    tool = world.create_body(bunny, "tool", pose=((0.14, 0, 0), (1, 0, 0, 0)))
    world.step()
    c = tool.contacts()
    assert set(c["other"]) == {left, right}
    assert c[c["other"] == left]["distance"].min() == pytest.approx(proxima.distance(left, tool), rel=1e-12)
    assert c[c["other"] == right]["distance"].min() == pytest.approx(proxima.distance(right, tool), rel=1e-12)
    # A Body dropped by the script still lives in its world, and is named again.
    del left, c
    others = set(tool.contacts()["other"])
    assert len(others) == 2 and right in others
    (again,) = others - {right}
    assert again.type == "static" and again.mesh is bunny


def test_trimesh_interop(world):
    import trimesh  # optional for users, installed for this suite

    t = trimesh.load(BUNNY, force="mesh")
    mesh = world.create_mesh_from_trimesh(t)
    assert mesh.info.triangle_count == len(t.faces) == 27864
    box = world.create_mesh_from_trimesh(trimesh.creation.box(extents=(1, 1, 1)))
    assert box.info.boundary_edges == 0 and box.info.triangle_count == 12


def test_every_c_function_is_bound():
    source = "".join(p.read_text() for p in pathlib.Path(proxima.__file__).parent.glob("*.py")
                     if p.name not in ("_ffi.py", "_header.py"))
    functions = [name for name in dir(lib) if name.startswith("prox") and callable(getattr(lib, name))]
    assert len(functions) > 40
    # Python device callbacks are refused (docs/python.md), so their def is not needed;
    # Body.contacts() takes the contacts with their patches (proxBody_GetContactPatches);
    # proxHidDevice_Close, proxWorld_OpenHidDevice and proxDestroyWorld are deprecated old names. The calls of
    # proxima_hid.h and proxima_openxr.h go through hid_function and
    # xr_function, which name what a library built without them lacks.
    unbound = {"proxDefaultDeviceDef", "proxBody_GetContacts", "proxHidDevice_Close", "proxWorld_OpenHidDevice",
               "proxDestroyWorld"}
    missing = [f for f in functions
               if f not in unbound and not re.search(rf'\blib\.{f}\b|(hid|xr)_function\("{f}"\)', source)]
    assert "proxWorld_CreateHidDevice" in functions and "proxWorld_CreateXrDevice" in functions
    assert missing == []


def test_every_result_has_its_exception():
    from proxima._core import RESULT_VALUES, error_for
    for name, value in RESULT_VALUES.items():
        if name in ("PROX_SUCCESS", "PROX_RESULT_FORCE32"):
            continue
        cls = error_for(value)
        assert cls is not proxima.Error and issubclass(cls, proxima.Error), name
        assert cls("x").result == value
        assert cls("x").result_name == name


def test_trimesh_is_never_imported_by_the_package():
    import subprocess
    import sys
    code = "import sys, proxima; assert 'trimesh' not in sys.modules; print('ok')"
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True, cwd="/")
    assert out.stdout.strip() == "ok"
    with proxima.World() as w:
        with pytest.raises(proxima.InvalidArgument, match="expected a trimesh.Trimesh, not list"):
            w.create_mesh_from_trimesh([1, 2, 3])
