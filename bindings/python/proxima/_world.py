"""Worlds over the C API; their meshes and bodies are in _bodies.py."""

import atexit
import os
import threading
import warnings
import weakref

import numpy as np

from . import _header
from ._core import (check, enum_value, ffi, fill_c, from_c, integer, invalid, lib, numbers, pose_to_c, poses_array,
                    real, snake, vec3, HIDDEN_FIELDS)
from ._bodies import Body, Mesh, _key, distance
from ._types import (ForceSettings, PatchSettings, PatchStats, SafetyStats, SearchStats, ThreadStats, TrackStats,
                     WorldStats)

_UINT32_MAX = 0xFFFFFFFF
_live_worlds = weakref.WeakSet()


def force_preset(name):
    """(ForceSettings, cutoff) of a preset: "hard" or "soft" (docs/cli.md)."""
    force, cutoff = ffi.new("proxForceSettings*"), ffi.new("double*")
    check(lib.proxGetForcePreset(enum_value("proxForcePreset", name, "force"), force, cutoff))
    return from_c(ForceSettings, force[0]), cutoff[0]


def _path(path, what):
    if not isinstance(path, (str, bytes, os.PathLike)):
        raise invalid(f"{what} must be a path, not {path!r}")
    return os.fsencode(path)


class World:
    """A world of meshes and bodies (proxWorldId). Destroyed by close(), at
    the end of a ``with`` block, or when it is garbage collected; its meshes
    and bodies keep it alive."""

    def __init__(self, method="precise", cutoff=None, force="hard", workers=1):
        """workers: threads the calling thread's heavy work (deforming
        meshes, step()'s searches) is split over, itself included, in
        [1, 256]; the results are the same whatever the count."""
        self._idp = None
        d = ffi.new("proxWorldDef*", lib.proxDefaultWorldDef())
        d.workerCount = integer(workers, "workers")
        d.method = enum_value("proxMethod", method, "method")
        if isinstance(force, str):
            settings, default_cutoff = force_preset(force)
            if cutoff is not None:
                # A preset is a shape relative to its cutoff: the library
                # scales it to another (as the CLI's --cutoff does), so any
                # positive cutoff works.
                # A cutoff that is none is left for proxCreateWorld to name.
                wanted = real(cutoff, "cutoff")
                if 0.0 < wanted < float("inf"):
                    at = ffi.new("proxForceSettings*")
                    check(lib.proxGetForcePresetAt(enum_value("proxForcePreset", force, "force"), wanted, at))
                    settings = from_c(ForceSettings, at[0])
        elif isinstance(force, ForceSettings):
            settings, default_cutoff = force, d.cutoff
        else:
            raise invalid(f"force must be 'hard', 'soft' or a proxima.ForceSettings, not {force!r}")
        fill_c(settings, d.force, "force")
        d.cutoff = default_cutoff if cutoff is None else real(cutoff, "cutoff")
        idp = ffi.new("proxWorldId*")
        check(lib.proxCreateWorld(d, idp))
        self._idp = idp
        self._thread = threading.get_ident()
        self._method = method
        self._cutoff = d.cutoff
        self._bodies = weakref.WeakValueDictionary()
        self._body_info = {}
        self._meshes = weakref.WeakValueDictionary()
        _live_worlds.add(self)

    # ---- lifetime ----

    def close(self):
        """Destroys the world and everything in it (stopping its threads
        first). Its meshes, bodies and devices then raise InvalidHandle."""
        if self._idp is not None and lib.proxWorld_IsValid(self._idp[0]):
            check(lib.proxWorld_Destroy(self._idp[0]))

    @property
    def closed(self):
        return self._idp is None or not lib.proxWorld_IsValid(self._idp[0])

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        if getattr(self, "_idp", None) is None or lib is None:
            return
        if not lib.proxWorld_IsValid(self._idp[0]):
            return
        if threading.get_ident() != self._thread:
            # Only the creating thread may destroy a world; it is left alive.
            warnings.warn("a proxima.World was garbage collected on a thread other than the one that "
                          "created it and could not be destroyed: close it on its own thread",
                          ResourceWarning, stacklevel=2)
            return
        lib.proxWorld_Destroy(self._idp[0])

    def __repr__(self):
        state = "closed" if self.closed else f"method={self._method!r}, cutoff={self._cutoff!r}"
        return f"<proxima.World {state}>"

    # ---- meshes ----

    def load_mesh(self, path):
        """A mesh from an OBJ, glTF (.gltf) or binary glTF (.glb) file."""
        idp = ffi.new("proxMeshId*")
        check(lib.proxWorld_LoadMesh(self._idp[0], _path(path, "load_mesh: path"), idp))
        return self._mesh(idp)

    def load_mesh_bytes(self, data, name):
        """A mesh from a file's bytes already in memory (bytes, bytearray,
        memoryview or anything with the buffer protocol): ``name`` is the
        file's name, whose extension says the format (.obj, .gltf, .glb) and
        which errors name. A .gltf must embed its buffers; nothing is read
        from disk."""
        try:
            view = memoryview(data)
        except TypeError:
            raise invalid(f"load_mesh_bytes: data must be bytes-like, not {type(data).__name__}") from None
        if not isinstance(name, str):
            raise invalid(f"load_mesh_bytes: name must be a str, not {name!r}")
        buffer = ffi.from_buffer(view.cast("B") if view.contiguous else view.tobytes())
        idp = ffi.new("proxMeshId*")
        check(lib.proxWorld_LoadMeshFromMemory(self._idp[0], buffer, len(buffer), name.encode(), idp))
        return self._mesh(idp)

    def create_mesh(self, vertices, triangles):
        """A mesh from an (N, 3) array of vertex positions and an (M, 3)
        integer array of vertex indices per triangle, counter-clockwise seen
        from outside. Any real dtype for the vertices, any integer dtype
        whose values fit uint32 for the triangles; copied."""
        v = _array(vertices, "create_mesh: vertices", "fiu", "numbers")
        t = _array(triangles, "create_mesh: triangles", "iu", "integers")
        if t.size:
            bad = np.argwhere((t < 0) | (t > _UINT32_MAX))
            if bad.size:
                i, j = bad[0]
                raise invalid(f"create_mesh: triangles[{i}, {j}] = {t[i, j]} is not a valid uint32 vertex index")
        if len(v) > _UINT32_MAX or len(t) > _UINT32_MAX:
            raise invalid("create_mesh: more than 2**32 - 1 vertices or triangles")
        v = np.ascontiguousarray(v, dtype=np.float64)
        t = np.ascontiguousarray(t, dtype=np.uint32)
        d = ffi.new("proxMeshDef*", lib.proxDefaultMeshDef())
        d.positions = ffi.from_buffer("double[]", v) if v.size else ffi.NULL
        d.vertexCount = len(v)
        d.indices = ffi.from_buffer("uint32_t[]", t) if t.size else ffi.NULL
        d.triangleCount = len(t)
        idp = ffi.new("proxMeshId*")
        check(lib.proxWorld_CreateMesh(self._idp[0], d, idp))
        return self._mesh(idp)

    def create_mesh_from_trimesh(self, mesh):
        """A mesh from a trimesh.Trimesh (its vertices and faces); trimesh
        is optional and only needed to make the object."""
        if not (hasattr(mesh, "vertices") and hasattr(mesh, "faces")):
            raise invalid(f"create_mesh_from_trimesh: expected a trimesh.Trimesh, not {type(mesh).__name__}")
        return self.create_mesh(mesh.vertices, mesh.faces)

    def _mesh(self, idp):
        key = _key(idp[0])
        mesh = self._meshes.get(key)
        if mesh is None:
            mesh = Mesh(self, idp)
            self._meshes[key] = mesh
        return mesh

    # ---- bodies ----

    def create_body(self, mesh, type="static", pose=None, reference_point=None, tool_mode="free",
                    coupling=None):
        """A body: `mesh` at `pose` ((position, quaternion_wxyz); default the
        identity). `type` is "static", "movable" or "tool"; a tool's torques
        are taken about `reference_point` (its own frame; default the origin).
        A tool's `tool_mode` is "free" or "constrained" (a proxy that stays
        outside the other bodies, with the virtual coupling's force;
        docs/coupling.md); `coupling`, for a constrained tool, is
        (stiffness N/m, damping N s/m, angular stiffness N m/rad, angular
        damping N m s/rad), default the library's."""
        if not isinstance(mesh, Mesh):
            raise invalid(f"create_body: mesh must be a proxima.Mesh, not {mesh!r}")
        d = ffi.new("proxBodyDef*", lib.proxDefaultBodyDef())
        d.mesh = mesh._idp[0]
        d.type = enum_value("proxBodyType", type, "create_body: type")
        if pose is not None:
            pose_to_c(pose, d.pose, "create_body: pose")
        if reference_point is not None:
            x, y, z = vec3(reference_point, "create_body: reference_point")
            d.referencePoint = {"x": x, "y": y, "z": z}
        d.toolMode = enum_value("proxToolMode", tool_mode, "create_body: tool_mode")
        if coupling is not None:
            try:
                values = [float(v) for v in coupling]
            except (TypeError, ValueError):
                values = []
            if len(values) != 4:
                raise invalid("create_body: coupling must be four numbers (stiffness, damping, "
                              f"angular stiffness, angular damping), not {coupling!r}")
            (d.couplingStiffness, d.couplingDamping, d.couplingAngularStiffness,
             d.couplingAngularDamping) = values
        idp = ffi.new("proxBodyId*")
        check(lib.proxWorld_CreateBody(self._idp[0], d, idp))
        key = _key(idp[0])
        # The mesh's id, not the Mesh: a Mesh holds its world, and the world
        # must not hold itself (it is freed as soon as the script drops it).
        self._body_info[key] = (type, ffi.new("proxMeshId*", mesh._idp[0]))
        body = Body(self, idp, type, mesh)
        self._bodies[key] = body
        return body

    def _body(self, id_value):
        """The Body of an id this world reported (the same object while it lives)."""
        key = _key(id_value)
        body = self._bodies.get(key)
        if body is None:
            idp = ffi.new("proxBodyId*", id_value)
            type_name, mesh_idp = self._body_info.get(key, (None, None))
            body = Body(self, idp, type_name, self._mesh(mesh_idp) if mesh_idp is not None else None)
            self._bodies[key] = body
        return body

    # ---- stepping ----

    def step(self):
        """The whole method once, on this thread: broadphase, global search
        and reduction per pair in range (skipped when no pose changed), forces."""
        check(lib.proxWorld_Step(self._idp[0]))

    def track(self):
        """Local tracking alone: the last step's contacts carried to the
        current poses; finds no new contact."""
        check(lib.proxWorld_Track(self._idp[0]))

    def _stats(self, cls, function, ctype):
        out = ffi.new(ctype + "*")
        check(function(self._idp[0], out))
        return from_c(cls, out[0])

    @property
    def stats(self):
        return self._stats(WorldStats, lib.proxWorld_GetStats, "proxWorldStats")

    @property
    def search_stats(self):
        return self._stats(SearchStats, lib.proxWorld_GetSearchStats, "proxSearchStats")

    @property
    def track_stats(self):
        return self._stats(TrackStats, lib.proxWorld_GetTrackStats, "proxTrackStats")

    @property
    def patch_stats(self):
        return self._stats(PatchStats, lib.proxWorld_GetPatchStats, "proxPatchStats")

    @property
    def patch_settings(self):
        """How LMDs merge into patches (docs/patches.md): a PatchSettings;
        assign one, or a (radius_over_cutoff, max_angle_degrees,
        max_spread_over_cutoff) triple, to change it from the next step on
        (radius 0: no merging)."""
        return self._stats(PatchSettings, lib.proxWorld_GetPatchSettings, "proxPatchSettings")

    @patch_settings.setter
    def patch_settings(self, value):
        if not isinstance(value, PatchSettings):
            radius, angle, spread = value
            value = PatchSettings(radius_over_cutoff=real(radius, "radius_over_cutoff"),
                                  max_angle_degrees=real(angle, "max_angle_degrees"),
                                  max_spread_over_cutoff=real(spread, "max_spread_over_cutoff"))
        out = ffi.new("proxPatchSettings*")
        fill_c(value, out[0], "patch_settings")
        check(lib.proxWorld_SetPatchSettings(self._idp[0], out))

    @property
    def leaf_budget(self):
        """The bounded search's budget (docs/patches.md): after this many
        triangle pairs one pair's search gives one representative per
        patch-sized node pair; 0: no bound. Assign an int >= 0 to change it
        from the next step on."""
        out = ffi.new("uint64_t*")
        check(lib.proxWorld_GetLeafBudget(self._idp[0], out))
        return int(out[0])

    @leaf_budget.setter
    def leaf_budget(self, value):
        value = integer(value, "leaf_budget")
        if not 0 <= value < 2 ** 64:
            raise invalid(f"leaf_budget must be in [0, 2**64), not {value}")
        check(lib.proxWorld_SetLeafBudget(self._idp[0], value))

    @property
    def safety_stats(self):
        return self._stats(SafetyStats, lib.proxWorld_GetSafetyStats, "proxSafetyStats")

    # ---- threads and devices ----

    def start_threads(self, **settings):
        """Starts the haptic, local tracking and global search threads.
        Settings are proxThreadsDef's fields in snake_case (haptic_rate=1000,
        local_rate, global_rate, haptic_core, ..., max_contacts, stale_after,
        haptic_timing="spin", lock_memory=True, ...); the rest keep their
        defaults."""
        d = ffi.new("proxThreadsDef*", lib.proxDefaultThreadsDef())
        _fill_settings(d, "proxThreadsDef", settings, "start_threads")
        check(lib.proxWorld_StartThreads(self._idp[0], d))
        self._trace_capacity = d.traceCapacity  # Body.haptic_trace's default length

    def stop_threads(self):
        """Fades every device's force out, then stops the threads."""
        check(lib.proxWorld_StopThreads(self._idp[0]))

    def thread_stats(self, thread):
        """ThreadStats of "haptic", "local" or "global"."""
        out = ffi.new("proxThreadStats*")
        check(lib.proxWorld_GetThreadStats(self._idp[0], enum_value("proxThread", thread, "thread_stats: thread"),
                                           out))
        return from_c(ThreadStats, out[0])

    def create_scripted_device(self, poses, seconds_per_pose, loop=False):
        """The built-in scripted device: moves a tool through `poses` (a
        (K, 7) array of tx ty tz qw qx qy qz, or (position, quaternion)
        pairs), `seconds_per_pose` apart, interpolating. Attach it with
        Body.set_device; it lives as long as the world."""
        from ._devices import ScriptedDevice
        array = poses_array(poses, "create_scripted_device: poses")
        c_poses = ffi.new("proxPose[]", max(len(array), 1))
        for i, row in enumerate(array):
            pose_to_c((row[:3], row[3:]), c_poses[i], f"create_scripted_device: poses[{i}]")
        d = ffi.new("proxScriptedDeviceDef*", lib.proxDefaultScriptedDeviceDef())
        d.poses = c_poses
        d.poseCount = len(array)
        d.loop = bool(loop)
        d.secondsPerPose = real(seconds_per_pose, "create_scripted_device: seconds_per_pose")
        idp = ffi.new("proxScriptedDeviceId*")
        check(lib.proxWorld_CreateScriptedDevice(self._idp[0], d, idp))
        return ScriptedDevice(self, idp)

    def create_stream_device(self, mode="interpolate", **settings):
        """A streamed device: your thread pushes timestamped poses
        (StreamDevice.push_pose), the haptic loop renders them at its rate.
        `mode` is "hold", "interpolate" or "extrapolate"; the settings are
        proxStreamDeviceDef's other fields in snake_case (delay,
        max_extrapolation, stale_after; seconds)."""
        from ._devices import StreamDevice
        d = ffi.new("proxStreamDeviceDef*", lib.proxDefaultStreamDeviceDef())
        d.mode = enum_value("proxStreamMode", mode, "create_stream_device: mode")
        _fill_settings(d, "proxStreamDeviceDef", settings, "create_stream_device", skip=("mode",))
        idp = ffi.new("proxStreamDeviceId*")
        check(lib.proxWorld_CreateStreamDevice(self._idp[0], d, idp))
        return StreamDevice(self, idp)

    def open_hid_device(self, device=None, *, initial_pose=None, reference_point=None, device_to_world=None,
                        **settings):
        """Opens a HID device (HidDevice) and starts its thread: `device` is a
        HidDeviceInfo of enumerate_hid_devices(), its path, or None for the
        first supported one present (matching vendor_id and product_id when
        given). initial_pose is where the tool starts (position, quaternion);
        reference_point the point rotations turn about (tool frame);
        device_to_world a quaternion (w, x, y, z) from the device's frame to
        the world's. The settings are proxHidDeviceDef's other fields in
        snake_case (vendor_id, product_id, linear_speed, angular_speed,
        dead_zone, response_exponent, rumble_force, trigger_force,
        output_rate). FileError when no supported device matches. Raises
        Unsupported when the library was built without PROX_WITH_HIDAPI."""
        from ._devices import HidDevice, HidDeviceInfo, hid_function
        d = ffi.new("proxHidDeviceDef*", hid_function("proxDefaultHidDeviceDef")())
        _fill_settings(d, "proxHidDeviceDef", settings, "open_hid_device",
                       skip=("path", "initial_pose", "reference_point", "device_to_world"))
        if initial_pose is not None:
            pose_to_c(initial_pose, d.initialPose, "open_hid_device: initial_pose")
        if reference_point is not None:
            x, y, z = vec3(reference_point, "open_hid_device: reference_point")
            d.referencePoint = {"x": x, "y": y, "z": z}
        if device_to_world is not None:
            w, x, y, z = numbers(device_to_world, 4, "open_hid_device: device_to_world")
            d.deviceToWorld = {"w": w, "x": x, "y": y, "z": z}
        if isinstance(device, HidDeviceInfo):
            device = device.path
        path = None  # the C string, alive until the call returns
        if device is not None:
            path = ffi.new("char[]", _path(device, "open_hid_device: device"))
            d.path = path
        idp = ffi.new("proxHidDeviceId*")
        check(hid_function("proxWorld_CreateHidDevice")(self._idp[0], d, idp))
        return HidDevice(self, idp)

    def create_hid_device(self, device=None, **settings):
        """open_hid_device under the name the other devices have
        (create_stream_device, create_xr_device) and the C API gives it
        (proxWorld_CreateHidDevice); the same arguments."""
        return self.open_hid_device(device, **settings)

    def create_xr_device(self, *, get_instance_proc_addr, instance, session, base_space, pose_action,
                         haptic_action=0, subaction_path=0, tool_in_grip=None, base_to_world=None,
                         session_state=None, **settings):
        """Hands Proxima an XR controller (XrDevice, docs/openxr.md) and starts
        its thread; call it after the app attached its action sets. The app's
        OpenXR objects are ints (or ctypes pointers): get_instance_proc_addr
        (xrGetInstanceProcAddr's address, or a ctypes or cffi function
        pointer), instance, session, base_space (its LOCAL or STAGE space),
        pose_action (POSE_INPUT), haptic_action (VIBRATION_OUTPUT, or 0: no
        vibration), subaction_path (/user/hand/right's XrPath, or 0).
        tool_in_grip and base_to_world are poses (position, quaternion);
        session_state the session's state now (an XrSessionState int or
        "focused", the default). The settings are proxXrDeviceDef's other
        fields in snake_case, defaults from proxDefaultXrDeviceDef: pose_mode
        ("locate_each_tick" or "extrapolate_frame"), vibration_rate,
        force_for_full_amplitude, timespec_time, tick_rate, pulse_duration,
        max_extrapolation, win32_performance_counter_time, runtime_time.
        Raises Unsupported when the library was built without PROX_WITH_OPENXR."""
        from ._xr import create_xr_device
        handles = {"instance": instance, "session": session, "base_space": base_space, "pose_action": pose_action,
                   "haptic_action": haptic_action, "subaction_path": subaction_path}
        return create_xr_device(self, get_instance_proc_addr, handles, tool_in_grip, base_to_world, session_state,
                                settings, _fill_settings)

    def load_scripted_device(self, path, seconds_per_pose, loop=False):
        """A scripted device whose path is read from a file: one pose per
        line, "tx ty tz qw qx qy qz", '#' comments."""
        from ._devices import ScriptedDevice
        idp = ffi.new("proxScriptedDeviceId*")
        check(lib.proxWorld_LoadScriptedDevice(self._idp[0], _path(path, "load_scripted_device: path"),
                                               real(seconds_per_pose, "load_scripted_device: seconds_per_pose"),
                                               bool(loop), idp))
        return ScriptedDevice(self, idp)


def _fill_settings(d, struct_name, settings, what, skip=()):
    """Sets a def's fields from keyword arguments named in snake_case: numbers,
    enums by their short names ("spin"), proxBool fields from bools."""
    bools = _header.BOOL_FIELDS.get(struct_name, ())
    fields = {snake(name): (name, field.type) for name, field in ffi.typeof(struct_name).fields
              if name not in HIDDEN_FIELDS and snake(name) not in skip}
    for key, value in settings.items():
        if key not in fields:
            raise invalid(f"{what}: unknown setting {key!r}; the settings are {', '.join(fields)}")
        name, ctype = fields[key]
        where = f"{what}: {key}"
        if ctype.kind == "enum":
            setattr(d, name, enum_value(ctype.cname, value, where))
        elif name in bools:
            if not isinstance(value, (bool, np.bool_)):
                raise invalid(f"{where} must be True or False, not {value!r}")
            setattr(d, name, bool(value))
        elif ctype.cname in ("double", "float"):
            setattr(d, name, real(value, where))
        else:
            setattr(d, name, integer(value, where))


def _array(value, what, kinds, noun):
    try:
        array = np.asarray(value)
    except (ValueError, TypeError) as e:
        raise invalid(f"{what} must be an (N, 3) array of {noun}: {e}") from None
    if array.dtype.kind not in kinds:
        raise invalid(f"{what} must be an (N, 3) array of {noun}, got dtype {array.dtype}")
    if array.ndim != 2 or array.shape[1] != 3:
        raise invalid(f"{what} must be an (N, 3) array of {noun}, got shape {array.shape}")
    return array


@atexit.register
def _close_worlds():
    # Before the interpreter's teardown: running threads are stopped and
    # joined while the library is still whole.
    me = threading.get_ident()
    for world in list(_live_worlds):
        if world._thread == me:
            world.close()


__all__ = ["World", "Mesh", "Body", "distance", "force_preset"]
