"""A world's meshes and bodies over the C API (the world itself: _world.py)."""

import math

import numpy as np

from ._core import (CAPACITY, c_dtype, check, ffi, from_c, integer, invalid, lib, pose_from_c, pose_to_c, real,
                    snake)
from ._trace import haptic_trace
from ._types import PATCH_FIELDS, Animation, IntersectionStats, MeshInfo, MeshStats, RigInfo, Skin, contact_dtype


def _key(id_value):
    return (id_value.index1, id_value.generation)


class Mesh:
    """A mesh of a world (proxMeshId): shared by every body that uses it."""

    def __init__(self, world, idp):
        self.world = world
        self._idp = idp

    @property
    def info(self):
        out = ffi.new("proxMeshInfo*")
        check(lib.proxMesh_GetInfo(self._idp[0], out))
        return from_c(MeshInfo, out[0])

    @property
    def stats(self):
        out = ffi.new("proxMeshStats*")
        check(lib.proxMesh_GetStats(self._idp[0], out))
        return from_c(MeshStats, out[0])

    @property
    def warnings(self):
        """What loading the mesh's file skipped without failing (invalid
        attributes Proxima does not read), one string per warning; [] for
        none."""
        length = ffi.new("int32_t*")
        result = lib.proxMesh_GetWarnings(self._idp[0], ffi.NULL, 0, length)
        if result != CAPACITY:
            check(result)
        if length[0] == 0:
            return []
        buffer = ffi.new("char[]", length[0] + 1)
        check(lib.proxMesh_GetWarnings(self._idp[0], buffer, length[0] + 1, length))
        return ffi.string(buffer).decode("utf-8", "replace").splitlines()

    def triangles(self):
        """The mesh as Proxima uses it, in its own frame: (vertices (N, 3)
        float64, triangles (M, 3) uint32), after welding and dropping the
        triangles that repeat a vertex (the counts of info)."""
        vertices = ffi.new("uint32_t*")
        triangles = ffi.new("uint32_t*")
        result = lib.proxMesh_GetTriangles(self._idp[0], ffi.NULL, 0, vertices, ffi.NULL, 0, triangles)
        if result != CAPACITY:
            check(result)
        v = np.empty((vertices[0], 3), dtype=np.float64)
        t = np.empty((triangles[0], 3), dtype=np.uint32)
        check(lib.proxMesh_GetTriangles(self._idp[0], ffi.cast("double*", ffi.from_buffer(v)), vertices[0],
                                        vertices, ffi.cast("uint32_t*", ffi.from_buffer(t)), triangles[0],
                                        triangles))
        return v, t

    def set_vertices(self, vertices):
        """Deforms the mesh: new positions (N, 3), in the order triangles()
        hands the vertices out, N the mesh's vertex count; the topology
        stays. Every body using the mesh takes the new shape, also while the
        threads run (docs/dynamic-scenes.md). Copied."""
        v = np.ascontiguousarray(vertices, dtype=np.float64)
        if v.ndim != 2 or v.shape[1] != 3:
            raise invalid(f"set_vertices: expected an (N, 3) array, got shape {v.shape}")
        check(lib.proxMesh_SetVertices(self._idp[0], ffi.from_buffer("double[]", v) if v.size else ffi.NULL,
                                       len(v)))

    # ---- glTF skins, morph targets and animation (docs/dynamic-scenes.md) ----

    @property
    def rig(self):
        """What the mesh's glTF rig holds (skins, joints, morph weights,
        animations); zeros for a mesh without one."""
        out = ffi.new("proxRigInfo*")
        check(lib.proxMesh_GetRigInfo(self._idp[0], out))
        return from_c(RigInfo, out[0])

    @property
    def skins(self):
        """The glTF rig's skins, in the file's order: a list of Skin(name,
        joints), joints the skin's joint count (what set_joint_matrices
        takes); [] for none."""
        info = ffi.new("proxSkinInfo*")
        out = []
        for s in range(self.rig.skin_count):
            check(lib.proxMesh_GetSkinInfo(self._idp[0], s, info))
            out.append(Skin(ffi.string(info.name).decode("utf-8", "replace"), info.jointCount))
        return out

    @property
    def animations(self):
        """The glTF scene's animations, in the file's order: a list of
        Animation(name, duration, start, channels), duration the last
        keyframe's time and start the first's, in seconds; [] for none."""
        count = ffi.new("int32_t*")
        check(lib.proxMesh_GetAnimationCount(self._idp[0], count))
        info = ffi.new("proxAnimationInfo*")
        out = []
        for i in range(count[0]):
            check(lib.proxMesh_GetAnimationInfo(self._idp[0], i, info))
            out.append(Animation(ffi.string(info.name).decode("utf-8", "replace"), info.duration, info.start,
                                 info.channelCount))
        return out

    def animate(self, index, seconds):
        """Poses the mesh at animation ``index`` (of animations) at
        ``seconds``: nodes, skins and morph weights; its vertices are
        replaced, as set_vertices does. Drops joint matrices and morph
        weights set before."""
        check(lib.proxMesh_Animate(self._idp[0], integer(index, "animate: index"), real(seconds, "animate: seconds")))

    def set_joint_matrices(self, skin, matrices):
        """Your animation system drives skin ``skin``: its joints' world
        matrices, (J, 4, 4) with m[row, column] (numpy's indexing; passed to
        the C API column-major), affine, in the mesh's frame, J the skin's
        joint count; Proxima applies the inverse bind matrices. Until the
        next animate."""
        m = np.asarray(matrices, dtype=np.float64)
        if m.ndim != 3 or m.shape[1:] != (4, 4):
            raise invalid(f"set_joint_matrices: expected a (J, 4, 4) array, got shape {m.shape}")
        columns = np.ascontiguousarray(np.transpose(m, (0, 2, 1)))
        check(lib.proxMesh_SetJointMatrices(self._idp[0], integer(skin, "set_joint_matrices: skin"),
                                            ffi.from_buffer("double[]", columns) if columns.size else ffi.NULL,
                                            len(columns)))

    def set_morph_weights(self, weights):
        """Every morphed mesh instance's weights, one after the other in
        scene order (rig.morph_weight_count of them). Until the next
        animate."""
        w = np.ascontiguousarray(weights, dtype=np.float64)
        if w.ndim != 1:
            raise invalid(f"set_morph_weights: expected a 1-D array, got shape {w.shape}")
        check(lib.proxMesh_SetMorphWeights(self._idp[0], ffi.from_buffer("double[]", w) if w.size else ffi.NULL,
                                           len(w)))

    def destroy(self):
        """Destroys the mesh; refused while bodies use it."""
        check(lib.proxMesh_Destroy(self._idp[0]))

    @property
    def valid(self):
        """Whether the mesh is alive in a live world (False from a thread
        other than the world's)."""
        return bool(lib.proxMesh_IsValid(self._idp[0]))

    def __eq__(self, other):
        return isinstance(other, Mesh) and other.world is self.world and _key(other._idp[0]) == _key(self._idp[0])

    def __hash__(self):
        return hash((id(self.world), _key(self._idp[0])))

    def __repr__(self):
        return f"<proxima.Mesh {self._idp[0].index1 - 1}>"


def _flat_dtype(name):
    """The C struct's dtype with each proxVec3 as a (3,) float64 field at the
    same offset (proxVec3 is three contiguous doubles), and each proxBodyId's
    index and generation as one uint64 key."""
    raw = c_dtype(name)
    vec, body = c_dtype("proxVec3"), c_dtype("proxBodyId")
    assert vec.itemsize == 24 and [vec.fields[c][1] for c in "xyz"] == [0, 8, 16]
    assert [body.fields[c][1] for c in ("index1", "generation")] == [0, 4]
    formats = []
    for n in raw.names:
        field = raw.fields[n][0]
        formats.append((np.float64, (3,)) if field == vec else np.uint64 if field == body else field)
    return np.dtype({"names": list(raw.names), "formats": formats,
                     "offsets": [raw.fields[n][1] for n in raw.names], "itemsize": raw.itemsize})


_CONTACT_FLAT = _flat_dtype("proxContact")
_CONTACT_FIELDS = [(snake(n), n) for n in _CONTACT_FLAT.names if n != "other"]
_PATCH_DTYPE = c_dtype("proxContactPatch")
_LINE_DTYPE = c_dtype("proxPolylineInfo")


class Body:
    """A body of a world (proxBodyId): a mesh at a pose."""

    def __init__(self, world, idp, type, mesh):
        self.world = world
        self._idp = idp
        self.type = type
        self.mesh = mesh
        self._contacts = None
        self._patches = None
        self._count = ffi.new("int32_t*")
        # The bodies its contacts named (they keep their world alive, not this body).
        self._others = {}

    @property
    def pose(self):
        """(position (3,), quaternion_wxyz (4,)) as numpy arrays."""
        out = ffi.new("proxPose*")
        check(lib.proxBody_GetPose(self._idp[0], out))
        return pose_from_c(out[0])

    @pose.setter
    def pose(self, pose):
        out = ffi.new("proxPose*")
        pose_to_c(pose, out[0], "pose")
        check(lib.proxBody_SetPose(self._idp[0], out))

    @property
    def proxy_pose(self):
        """Where the tool is rendered and its contacts are computed: a
        constrained tool's proxy (`pose` is its device pose), a free tool's
        pose. (position (3,), quaternion_wxyz (4,))."""
        out = ffi.new("proxPose*")
        check(lib.proxBody_GetProxyPose(self._idp[0], out))
        return pose_from_c(out[0])

    def contacts(self):
        """The tool's contacts after the last step (while the threads run,
        local tracking's latest): a structured array of contact_dtype."""
        if self._contacts is None:
            self._contacts = ffi.new("proxContact[]", 64)
            self._patches = ffi.new("proxContactPatch[]", 64)
        while True:
            # The contacts and their patches from one snapshot.
            result = lib.proxBody_GetContactPatches(self._idp[0], self._contacts, self._patches,
                                                    len(self._contacts), self._count)
            if result != CAPACITY:
                check(result)
                break
            self._contacts = ffi.new("proxContact[]", self._count[0])
            self._patches = ffi.new("proxContactPatch[]", self._count[0])
        n = self._count[0]
        out = np.empty(n, dtype=contact_dtype)
        if n == 0:
            return out
        flat = np.frombuffer(ffi.buffer(self._contacts, n * _CONTACT_FLAT.itemsize), dtype=_CONTACT_FLAT)
        for public, c in _CONTACT_FIELDS:
            out[public] = flat[c]
        patches = np.frombuffer(ffi.buffer(self._patches, n * _PATCH_DTYPE.itemsize), dtype=_PATCH_DTYPE)
        for public, c in PATCH_FIELDS:
            out[public] = patches[c]
        keys = flat["other"]
        if (keys == keys[0]).all():
            out["other"] = self._other(int(keys[0]), 0)
        else:
            out["other"] = [self._other(k, i) for i, k in enumerate(keys.tolist())]
        return out

    def _other(self, key, i):
        body = self._others.get(key)
        if body is None:
            body = self._others[key] = self.world._body(self._contacts[i].other)
        return body

    def wrench(self):
        """(force (3,) N, torque (3,) N m about the reference point, clipped)."""
        w = ffi.new("proxWrench*")
        check(lib.proxBody_GetWrench(self._idp[0], w))
        f, t = w.force, w.torque
        return np.array([f.x, f.y, f.z]), np.array([t.x, t.y, t.z]), bool(w.clipped)

    def haptic_trace(self, max_samples=None):
        """The flight recorder's newest ticks (start_threads(trace_capacity=N)),
        oldest first: a structured array of proxima.trace_dtype(), by default
        as many as the recorder keeps. Empty when it is off."""
        if max_samples is None:
            max_samples = getattr(self.world, "_trace_capacity", 0)
        return haptic_trace(self._idp[0], max_samples)

    def intersections(self):
        """Where the tool's surface crosses other bodies at their current
        poses: a list of (points (K, 3), closed, other Body)."""
        point_count, line_count = ffi.new("int32_t*"), ffi.new("int32_t*")
        points, lines = ffi.new("proxVec3[]", 1024), ffi.new("proxPolylineInfo[]", 64)
        while True:
            result = lib.proxBody_GetIntersections(self._idp[0], points, len(points), point_count,
                                                   lines, len(lines), line_count)
            if result != CAPACITY:
                check(result)
                break
            points = ffi.new("proxVec3[]", max(point_count[0], 1))
            lines = ffi.new("proxPolylineInfo[]", max(line_count[0], 1))
        xyz = np.frombuffer(ffi.buffer(points, point_count[0] * 24), dtype=np.float64).reshape(-1, 3)
        out = []
        for i in range(line_count[0]):
            line = lines[i]
            out.append((xyz[line.firstPoint:line.firstPoint + line.pointCount].copy(), bool(line.closed),
                        self.world._body(line.other)))
        return out

    @property
    def intersection_stats(self):
        out = ffi.new("proxIntersectionStats*")
        check(lib.proxBody_GetIntersectionStats(self._idp[0], out))
        return from_c(IntersectionStats, out[0])

    def set_device(self, device):
        """Lets a device hold this tool while the threads run (None: none).
        Devices are built in (World.create_stream_device,
        World.create_scripted_device, World.open_hid_device,
        World.create_xr_device): a Python
        callback cannot keep a 1 kHz haptic loop's time (docs/python.md)."""
        if device is None:
            check(lib.proxBody_SetDevice(self._idp[0], ffi.NULL))
            return
        device_def = getattr(device, "_device_def", None)
        if device_def is None:
            raise invalid(f"set_device: expected a device of proxima (World.create_stream_device, "
                          f"World.create_scripted_device, World.open_hid_device, World.create_xr_device) "
                          f"or None, not {device!r}; "
                          "Python callbacks cannot "
                          "drive the haptic loop: push poses to a stream device (docs/python.md)")
        if getattr(device, "world", None) is not self.world:
            # The C API cannot tell, and the device would die with its own world.
            raise invalid(f"set_device: {device!r} belongs to another world than this body")
        check(lib.proxBody_SetDevice(self._idp[0], device_def()))

    def destroy(self):
        check(lib.proxBody_Destroy(self._idp[0]))
        self.world._body_info.pop(_key(self._idp[0]), None)

    @property
    def valid(self):
        """Whether the body is alive in a live world (False from a thread
        other than the world's)."""
        return bool(lib.proxBody_IsValid(self._idp[0]))

    def __eq__(self, other):
        return isinstance(other, Body) and other.world is self.world and _key(other._idp[0]) == _key(self._idp[0])

    def __hash__(self):
        return hash((id(self.world), _key(self._idp[0])))

    def __repr__(self):
        return f"<proxima.Body {self._idp[0].index1 - 1} {self.type}>"


def distance(a, b, max_distance=math.inf):
    """The exact minimum distance between two bodies of one world at their
    current poses: 0 when they touch or cross, inf when farther apart than
    max_distance."""
    if not isinstance(a, Body) or not isinstance(b, Body):
        raise invalid(f"distance: expected two proxima.Body, not {type(a).__name__} and {type(b).__name__}")
    out = ffi.new("double*")
    check(lib.proxBody_GetDistance(a._idp[0], b._idp[0], real(max_distance, "distance: max_distance"), out))
    return math.inf if out[0] < 0 else out[0]
