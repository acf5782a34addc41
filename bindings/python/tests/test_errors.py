"""Misuse: every bad input raises a proxima.Error naming what is wrong, and
nothing crashes on a destroyed object."""

import gc
import math
import threading
import warnings
import weakref

import numpy as np
import pytest

import proxima
from proxima._core import ffi, lib

from conftest import ASSETS, BUNNY, cube


def raises(cls, match):
    return pytest.raises(cls, match=match)


def test_errors_carry_result_and_library_message(world):
    with raises(proxima.InvalidMesh, "^proxWorld_CreateMesh: mesh has no triangles$") as e:
        world.create_mesh(np.zeros((0, 3)), np.zeros((0, 3), dtype=int))
    assert e.value.result == -3 and e.value.result_name == "PROX_ERROR_INVALID_MESH"
    assert isinstance(e.value, proxima.Error) and isinstance(e.value, ValueError)
    with raises(proxima.FileError, "cannot open") as e:
        world.load_mesh("no-such-file.obj")
    assert isinstance(e.value, OSError) and e.value.result == -4


@pytest.mark.parametrize("kwargs, cls, match", [
    ({"method": "fast"}, proxima.InvalidArgument, "method must be one of 'precise', 'original', 'reference'"),
    ({"force": "medium"}, proxima.InvalidArgument, "force must be one of 'hard', 'soft'"),
    ({"force": 3}, proxima.InvalidArgument, "force must be 'hard', 'soft' or a proxima.ForceSettings"),
    ({"cutoff": "far"}, proxima.InvalidArgument, "cutoff must be a number"),
    ({"cutoff": -1}, proxima.InvalidArgument, r"proxCreateWorld: def->cutoff must be > 0"),
    ({"cutoff": math.nan}, proxima.InvalidArgument, r"def->cutoff is not finite"),
    ({"force": proxima.ForceSettings(max_force=-1)}, proxima.InvalidArgument, "maxForce must be > 0"),
    ({"force": proxima.ForceSettings(curve="cubic")}, proxima.InvalidArgument,
     "force.curve must be one of 'exponential', 'linear'"),
])
def test_bad_world_settings(kwargs, cls, match):
    with raises(cls, match):
        proxima.World(**kwargs)


def test_bad_files(world, tmp_path):
    with raises(proxima.Unsupported, "KHR_draco_mesh_compression"):
        world.load_mesh(ASSETS / "gltf/Duck-Draco/Duck.gltf")
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nf 1 2 zz\n")
    with raises(proxima.ParseError, "bad.obj:2"):
        world.load_mesh(bad)
    with raises(proxima.Unsupported, "unsupported file type '.txt'"):
        world.load_mesh(tmp_path / "mesh.txt")
    with raises(proxima.InvalidArgument, "load_mesh: path must be a path"):
        world.load_mesh(42)


def _nan_vertex():
    v, t = cube()
    v[2, 1] = np.nan
    return v, t


@pytest.mark.parametrize("make, cls, match", [
    (_nan_vertex, proxima.InvalidMesh, r"vertex 2 has a non-finite y coordinate \(nan\)"),
    (lambda: (cube()[0], [[0, 1, 8]]), proxima.InvalidMesh, "triangle 0 has vertex index 8, out of range for 8"),
    (lambda: (cube()[0], [[0, 1, -1]]), proxima.InvalidArgument, r"triangles\[0, 2\] = -1 is not a valid uint32"),
    (lambda: (cube()[0], [[0, 1, 2 ** 32]]), proxima.InvalidArgument, r"triangles\[0, 2\] = 4294967296"),
    (lambda: (cube()[0], np.array([[0, 1, 2.0]])), proxima.InvalidArgument, "integers, got dtype float64"),
    (lambda: (cube()[0], cube()[1].astype(bool)), proxima.InvalidArgument, "integers, got dtype bool"),
    (lambda: (cube()[0], cube()[1].ravel()), proxima.InvalidArgument, r"triangles must .* got shape \(36,\)"),
    (lambda: (cube()[0][:, :2], cube()[1]), proxima.InvalidArgument, r"vertices must .* got shape \(8, 2\)"),
    (lambda: (cube()[0].astype(complex), cube()[1]), proxima.InvalidArgument, "got dtype complex128"),
    (lambda: (cube()[0].astype(str), cube()[1]), proxima.InvalidArgument, "vertices must be an .* of numbers"),
    (lambda: ([[0, 0], [1, 2, 3]], cube()[1]), proxima.InvalidArgument, "vertices must be an"),
    (lambda: (None, cube()[1]), proxima.InvalidArgument, "vertices must be an"),
    (lambda: (np.zeros((0, 3)), np.zeros((0, 3), int)), proxima.InvalidMesh, "mesh has no triangles"),
    (lambda: (cube()[0], [[0, 0, 1]]), proxima.InvalidMesh, "no non-degenerate triangles"),
])
def test_bad_mesh_arrays(world, make, cls, match):
    vertices, triangles = make()
    with raises(cls, match):
        world.create_mesh(vertices, triangles)


def test_bad_bodies(world):
    mesh = world.create_mesh(*cube())
    with raises(proxima.InvalidArgument, "mesh must be a proxima.Mesh"):
        world.create_body("cube", "static")
    with raises(proxima.InvalidArgument, "type must be one of 'static', 'movable', 'tool', not 'rock'"):
        world.create_body(mesh, "rock")
    with raises(proxima.InvalidArgument, "rotation is a zero quaternion"):
        world.create_body(mesh, "tool", pose=((0, 0, 0), (0, 0, 0, 0)))
    with raises(proxima.InvalidArgument, r"pose.position.x is not finite \(nan\)"):
        world.create_body(mesh, "tool", pose=((math.nan, 0, 0), (1, 0, 0, 0)))
    with raises(proxima.InvalidArgument, "pose position must be 3 numbers, got shape"):
        world.create_body(mesh, "tool", pose=((0, 0), (1, 0, 0, 0)))
    with raises(proxima.InvalidArgument, r"quaternion \(w, x, y, z\) must be 4 numbers"):
        world.create_body(mesh, "tool", pose=((0, 0, 0), (1, 0, 0)))
    with raises(proxima.InvalidArgument, "pose must be"):
        world.create_body(mesh, "tool", pose=(0, 0, 0, 1, 0, 0, 0))
    with raises(proxima.InvalidArgument, r"referencePoint.x is not finite \(inf\)"):
        world.create_body(mesh, "tool", reference_point=(math.inf, 0, 0))
    rock = world.create_body(mesh, "static")
    with raises(proxima.InvalidArgument, "body is static"):
        rock.pose = ((1, 0, 0), (1, 0, 0, 0))
    with raises(proxima.InvalidArgument, "tool is not a PROX_BODY_TOOL body"):
        rock.contacts()
    with raises(proxima.InvalidArgument, "not a PROX_BODY_TOOL"):
        rock.wrench()
    with raises(proxima.InvalidArgument, "mesh is used by 1 bodies"):
        mesh.destroy()
    with raises(proxima.InvalidArgument, "set_device: expected a device of proxima"):
        world.create_body(mesh, "tool").set_device(lambda: None)


def test_objects_of_other_worlds(world):
    mesh = world.create_mesh(*cube())
    with proxima.World() as other:
        foreign = other.create_mesh(*cube())
        with raises(proxima.InvalidHandle, "belongs to another world"):
            world.create_body(foreign, "static")
        a = world.create_body(mesh, "static")
        b = other.create_body(foreign, "tool")
        with raises(proxima.InvalidHandle, "different worlds"):
            proxima.distance(a, b)
    with raises(proxima.InvalidArgument, "same body"):
        proxima.distance(a, a)
    with raises(proxima.InvalidArgument, "expected two proxima.Body"):
        proxima.distance(a, "b")
    with raises(proxima.InvalidArgument, "max_distance must be a number"):
        proxima.distance(a, world.create_body(mesh, "tool"), max_distance=None)


def test_destroyed_objects_raise_invalid_handle():
    w = proxima.World()
    mesh = w.create_mesh(*cube())
    body = w.create_body(mesh, "tool")
    device = w.create_scripted_device([((0, 0, 0), (1, 0, 0, 0))], 0.1)
    assert body.valid and mesh.valid
    body.destroy()
    assert not body.valid and mesh.valid
    with raises(proxima.InvalidHandle, "does not name a live body"):
        body.pose
    with raises(proxima.InvalidHandle, "proxBody_Destroy"):
        body.destroy()
    mesh.destroy()
    assert not mesh.valid
    with raises(proxima.InvalidHandle, "proxMesh_GetInfo"):
        mesh.info
    tool = w.create_body(w.create_mesh(*cube()), "tool")
    w.close()
    w.close()  # twice is fine
    assert w.closed
    for call in (w.step, w.track, lambda: w.stats, lambda: w.load_mesh(BUNNY), lambda: tool.pose,
                 tool.contacts, tool.wrench, tool.intersections, lambda: device.record,
                 lambda: tool.set_device(device), lambda: w.thread_stats("haptic"), w.stop_threads,
                 lambda: w.create_mesh(*cube())):
        with raises(proxima.InvalidHandle, "does not name a live"):
            call()


def test_context_manager_destroys_the_world():
    with proxima.World() as w:
        tool = w.create_body(w.create_mesh(*cube()), "tool")
        world_id = ffi.new("proxWorldId*", w._idp[0])
        assert lib.proxWorld_IsValid(world_id[0])
    assert not lib.proxWorld_IsValid(world_id[0]) and w.closed
    with raises(proxima.InvalidHandle, "world does not name a live world"):
        tool.pose = ((0, 0, 0), (1, 0, 0, 0))


def test_garbage_collection_of_a_world_with_live_bodies():
    def make():
        w = proxima.World()
        m = w.load_mesh(BUNNY)
        w.create_body(m, "static")
        tool = w.create_body(m, "tool", pose=((0.14, 0, 0), (1, 0, 0, 0)))
        return tool, weakref.ref(w), ffi.new("proxWorldId*", w._idp[0])

    tool, world_ref, world_id = make()
    # Only the body holds the world now: it stays alive and usable.
    gc.collect()
    assert world_ref() is not None and lib.proxWorld_IsValid(world_id[0])
    tool.world.step()
    assert len(tool.contacts()) == 1
    contacts = tool.contacts()
    del tool
    gc.collect()
    # The contacts' other body keeps it too.
    assert world_ref() is not None
    del contacts
    gc.collect()
    assert world_ref() is None and not lib.proxWorld_IsValid(world_id[0])


def test_a_dropped_world_is_freed_at_once():
    # No reference cycle: the world goes when its last object does, without
    # waiting for the cyclic garbage collector.
    gc.disable()
    try:
        w = proxima.World()
        m = w.load_mesh(BUNNY)
        rock = w.create_body(m, "static")
        tool = w.create_body(m, "tool", pose=((0.14, 0, 0), (1, 0, 0, 0)))
        w.step()
        contacts = tool.contacts()
        device = w.create_scripted_device([((0, 0, 0), (1, 0, 0, 0))], 0.1)
        world_ref, world_id = weakref.ref(w), ffi.new("proxWorldId*", w._idp[0])
        del w, m, rock, tool, contacts, device
        assert world_ref() is None and not lib.proxWorld_IsValid(world_id[0])
    finally:
        gc.enable()


def test_world_dropped_on_another_thread_warns_and_is_kept():
    holder = [proxima.World()]
    world_id = ffi.new("proxWorldId*", holder[0]._idp[0])
    caught = []

    def drop():
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter("always")
            holder.pop()
            gc.collect()
            caught.extend(w)

    t = threading.Thread(target=drop)
    t.start()
    t.join()
    assert any(issubclass(w.category, ResourceWarning) and "other than the one that created it" in str(w.message)
               for w in caught)
    assert lib.proxWorld_IsValid(world_id[0])
    assert lib.proxWorld_Destroy(world_id[0]) == 0


def test_wrong_thread(world):
    mesh = world.create_mesh(*cube())
    tool = world.create_body(mesh, "tool")
    errors = []

    def use():
        for call in (world.step, lambda: tool.pose, lambda: world.create_mesh(*cube())):
            try:
                call()
            except proxima.Error as e:
                errors.append(e)

    t = threading.Thread(target=use)
    t.start()
    t.join()
    assert len(errors) == 3 and all(isinstance(e, proxima.WrongThread) for e in errors)
    assert "thread" in str(errors[0])
    world.step()  # the world is unharmed


def test_bad_thread_and_device_arguments(world):
    with raises(proxima.InvalidArgument, "thread_stats: thread must be one of 'haptic', 'local', 'global'"):
        world.thread_stats("render")
    with raises(proxima.InvalidArgument, "start_threads: unknown setting 'rate'; the settings are haptic_rate"):
        world.start_threads(rate=1000)
    with raises(proxima.InvalidArgument, "haptic rate must be in"):
        world.start_threads(haptic_rate=-5)
    with raises(proxima.InvalidArgument, "start_threads: haptic_core must be an integer"):
        world.start_threads(haptic_core=0.5)
    with raises(proxima.InvalidArgument, "start_threads: haptic_timing must be one of 'auto', 'spin', 'sleep'"):
        world.start_threads(haptic_timing="busy")
    with raises(proxima.InvalidArgument, "start_threads: lock_memory must be True or False, not 1"):
        world.start_threads(lock_memory=1)
    with raises(proxima.InvalidArgument, "global workers must be in"):
        world.start_threads(global_worker_count=0)
    with raises(proxima.InvalidArgument, "poseCount must be >= 1"):
        world.create_scripted_device([], 0.1)
    with raises(proxima.InvalidArgument, "must be a \\(K, 7\\) array"):
        world.create_scripted_device(np.zeros((3, 6)), 0.1)
    with raises(proxima.InvalidArgument, r"poses\[0\].rotation is a zero quaternion"):
        world.create_scripted_device(np.zeros((2, 7)), 0.1)
    with raises(proxima.InvalidArgument, "secondsPerPose must be > 0"):
        world.create_scripted_device([((0, 0, 0), (1, 0, 0, 0))], 0)
    with raises(proxima.FileError, "cannot open"):
        world.load_scripted_device("no-such-path.txt", 0.1)
