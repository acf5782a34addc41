"""Writes a binary glTF's triangles as an OBJ file, node transforms applied,
for proxima-viewer's frame-time measurement on CAD parts (docs/viewer.md):
the viewer draws OBJ only. Python's standard library only.

    python3 bench/gltf_to_obj.py IN.glb OUT.obj [--mesh NAME] [--scale S]

--mesh keeps only the instances of the mesh of that name; --scale
multiplies every coordinate (0.001: the CAD samples' millimetres to metres).
Reads float positions and unsigned byte/short/int indices of TRIANGLES
primitives; anything else is refused by name.
"""
import argparse
import json
import math
import struct
import sys

COMPONENTS = {5121: ("B", 1), 5123: ("H", 2), 5125: ("I", 4), 5126: ("f", 4)}
WIDTH = {"SCALAR": 1, "VEC3": 3}


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def local_matrix(node):
    if "matrix" in node:
        m = node["matrix"]  # column-major
        return [[m[c * 4 + r] for c in range(4)] for r in range(4)]
    tx, ty, tz = node.get("translation", [0, 0, 0])
    x, y, z, w = node.get("rotation", [0, 0, 0, 1])
    n = math.sqrt(x * x + y * y + z * z + w * w) or 1.0
    x, y, z, w = x / n, y / n, z / n, w / n
    sx, sy, sz = node.get("scale", [1, 1, 1])
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[r[0][0] * sx, r[0][1] * sy, r[0][2] * sz, tx], [r[1][0] * sx, r[1][1] * sy, r[1][2] * sz, ty],
            [r[2][0] * sx, r[2][1] * sy, r[2][2] * sz, tz], [0, 0, 0, 1]]


def accessor(gltf, binary, index):
    a = gltf["accessors"][index]
    if "sparse" in a or a["componentType"] not in COMPONENTS or a["type"] not in WIDTH:
        sys.exit(f"accessor {index}: {a['type']} of component type {a['componentType']} (or sparse) is not read here")
    view = gltf["bufferViews"][a["bufferView"]]
    fmt, size = COMPONENTS[a["componentType"]]
    width = WIDTH[a["type"]]
    stride = view.get("byteStride", size * width)
    base = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    return [struct.unpack_from("<" + fmt * width, binary, base + i * stride) for i in range(a["count"])]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("input")
    p.add_argument("output")
    p.add_argument("--mesh")
    p.add_argument("--scale", type=float, default=1.0)
    args = p.parse_args()
    with open(args.input, "rb") as f:
        data = f.read()
    magic, version, _ = struct.unpack_from("<4sII", data, 0)
    if magic != b"glTF" or version != 2:
        sys.exit(f"{args.input}: not a binary glTF 2.0 file")
    json_length = struct.unpack_from("<I", data, 12)[0]
    gltf = json.loads(data[20:20 + json_length])
    binary = data[20 + json_length + 8:]
    nodes = gltf["nodes"]
    scene = gltf["scenes"][gltf.get("scene", 0)]
    identity = [[float(i == j) for j in range(4)] for i in range(4)]
    positions, triangles = [], []

    def emit(index, parent):
        node = nodes[index]
        world = matmul(parent, local_matrix(node))
        if "mesh" in node and args.mesh in (None, gltf["meshes"][node["mesh"]].get("name")):
            for prim in gltf["meshes"][node["mesh"]]["primitives"]:
                if prim.get("mode", 4) != 4:
                    continue
                first = len(positions)
                for v in accessor(gltf, binary, prim["attributes"]["POSITION"]):
                    positions.append([args.scale * sum(world[r][c] * (list(v) + [1.0])[c] for c in range(4))
                                      for r in range(3)])
                count = len(positions) - first
                idx = [i[0] for i in accessor(gltf, binary, prim["indices"])] if "indices" in prim else list(range(count))
                triangles.extend([(first + idx[k], first + idx[k + 1], first + idx[k + 2]) for k in range(0, len(idx) - 2, 3)])
        for child in node.get("children", []):
            emit(child, world)

    for root in scene["nodes"]:
        emit(root, identity)
    if not triangles:
        sys.exit(f"{args.input}: no triangles" + (f" in a mesh named {args.mesh}" if args.mesh else ""))
    with open(args.output, "w") as f:
        for v in positions:
            f.write("v %.9g %.9g %.9g\n" % tuple(v))
        for t in triangles:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))
    print(f"{args.output}: {len(positions)} vertices, {len(triangles)} triangles")


if __name__ == "__main__":
    main()
