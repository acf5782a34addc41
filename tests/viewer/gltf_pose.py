"""A morphed glTF scene posed at an animation's time, read and evaluated here
from the file with the standard library alone: the oracle the viewer's
animation test holds the images to, independent of the SDK's rig code.

It reads what a morph-target animation needs (a GLB's float accessors and
integer indices, node TRS or matrices, mesh weights, a LINEAR `weights`
channel) and refuses anything else (skins, other interpolations or paths)
rather than evaluate it wrongly.
"""
import bisect
import json
import struct

_COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
_FORMATS = {5121: "B", 5123: "H", 5125: "I", 5126: "f"}


def _mul(a, b):  # 4x4 row-major
    return [[sum(a[r][k] * b[k][c] for k in range(4)) for c in range(4)] for r in range(4)]


def _local(node):
    if "matrix" in node:
        m = node["matrix"]  # column-major
        return [[m[c * 4 + r] for c in range(4)] for r in range(4)]
    x, y, z, w = node.get("rotation", [0.0, 0.0, 0.0, 1.0])
    sx, sy, sz = node.get("scale", [1.0, 1.0, 1.0])
    tx, ty, tz = node.get("translation", [0.0, 0.0, 0.0])
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
    return [[r[0][0] * sx, r[0][1] * sy, r[0][2] * sz, tx],
            [r[1][0] * sx, r[1][1] * sy, r[1][2] * sz, ty],
            [r[2][0] * sx, r[2][1] * sy, r[2][2] * sz, tz],
            [0.0, 0.0, 0.0, 1.0]]


class Gltf:
    def __init__(self, path):
        with open(path, "rb") as f:
            data = f.read()
        magic, version, _ = struct.unpack_from("<4sII", data, 0)
        assert magic == b"glTF" and version == 2, f"{path}: not a GLB 2"
        length, kind = struct.unpack_from("<I4s", data, 12)
        assert kind == b"JSON"
        self.json = json.loads(data[20:20 + length])
        self.bin = data[20 + length + 8:]
        assert not self.json.get("skins"), "skins are not evaluated here"

    def accessor(self, index):
        a = self.json["accessors"][index]
        assert "sparse" not in a, "sparse accessors are not read here"
        view = self.json["bufferViews"][a["bufferView"]]
        n, fmt = _COMPONENTS[a["type"]], _FORMATS[a["componentType"]]
        size = struct.calcsize("<" + fmt)
        stride = view.get("byteStride", n * size)
        base = view.get("byteOffset", 0) + a.get("byteOffset", 0)
        return [struct.unpack_from(f"<{n}{fmt}", self.bin, base + i * stride) for i in range(a["count"])]

    def weights(self, node_index, animation, seconds):
        """The node's morph weights at `seconds` of `animation` (None: at rest)."""
        node = self.json["nodes"][node_index]
        weights = list(node.get("weights", self.json["meshes"][node["mesh"]].get("weights", [])))
        if animation is None:
            return weights
        anim = self.json["animations"][animation]
        for channel in anim["channels"]:
            target = channel["target"]
            if target["node"] != node_index:
                continue
            assert target["path"] == "weights", "only weights channels are evaluated here"
            sampler = anim["samplers"][channel["sampler"]]
            assert sampler.get("interpolation", "LINEAR") == "LINEAR"
            times = [t[0] for t in self.accessor(sampler["input"])]
            values = [v[0] for v in self.accessor(sampler["output"])]
            n = len(weights)
            t = min(max(seconds, times[0]), times[-1])
            k = max(0, min(len(times) - 2, bisect.bisect_right(times, t) - 1))
            u = 0.0 if times[k + 1] == times[k] else (t - times[k]) / (times[k + 1] - times[k])
            weights = [(1 - u) * values[k * n + j] + u * values[(k + 1) * n + j] for j in range(n)]
        return weights

    def triangles(self, animation=None, seconds=0.0):
        """World triangles [(p0, p1, p2)] of the default scene at `seconds` of `animation`."""
        out = []
        scene = self.json["scenes"][self.json.get("scene", 0)]
        stack = [(n, [[float(r == c) for c in range(4)] for r in range(4)]) for n in scene["nodes"]]
        while stack:
            index, parent = stack.pop()
            node = self.json["nodes"][index]
            world = _mul(parent, _local(node))
            stack += [(c, world) for c in node.get("children", [])]
            if "mesh" not in node:
                continue
            weights = self.weights(index, animation, seconds)
            for prim in self.json["meshes"][node["mesh"]]["primitives"]:
                assert prim.get("mode", 4) == 4
                points = [list(p) for p in self.accessor(prim["attributes"]["POSITION"])]
                for w, target in zip(weights, prim.get("targets", [])):
                    for p, d in zip(points, self.accessor(target["POSITION"])):
                        for c in range(3):
                            p[c] += w * d[c]
                points = [tuple(sum(world[r][c] * (p[c] if c < 3 else 1.0) for c in range(4)) for r in range(3))
                          for p in points]
                indices = [i[0] for i in self.accessor(prim["indices"])] if "indices" in prim else \
                    list(range(len(points)))
                out += [tuple(points[i] for i in indices[k:k + 3]) for k in range(0, len(indices), 3)]
        return out
