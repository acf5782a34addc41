#!/usr/bin/env python3
"""Seed corpora for the fuzz targets, made from the shared assets (never
committed): small glTF/GLB samples as they are, the .gltf samples with their
external buffers embedded as data URIs (a fuzzed file has nothing beside it),
a cut-down bunny OBJ, and the real HID report descriptors of the shared
devices folder beside the assets. The hand-written seeds in tests/fuzz/seeds are
added too.

    make_corpus.py ASSETS_DIR OUT_DIR
"""
import base64
import json
import os
import shutil
import sys

MAX_SEED = 48 * 1024  # larger seeds slow every execution down


def embed_buffers(path):
    with open(path, encoding="utf-8") as f:
        gltf = json.load(f)
    for buffer in gltf.get("buffers", []):
        uri = buffer.get("uri", "")
        if uri and not uri.startswith("data:"):
            with open(os.path.join(os.path.dirname(path), uri), "rb") as f:
                data = f.read()
            buffer["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    gltf.pop("images", None)  # textures are never read; their external files would only fail
    for texture in gltf.get("textures", []):
        texture.pop("source", None)
    return json.dumps(gltf, separators=(",", ":")).encode()


def bunny_cut(path, vertices):
    """The first `vertices` vertices of the bunny and the faces among them."""
    out = ["# cut-down Stanford bunny"]
    count = 0
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("v "):
                count += 1
                if count <= vertices:
                    out.append(line.rstrip())
            elif line.startswith("f "):
                idx = [int(p.split("/")[0]) for p in line.split()[1:]]
                if max(idx) <= vertices:
                    out.append(line.rstrip())
    return ("\n".join(out) + "\n").encode()


def main():
    assets, out = sys.argv[1], sys.argv[2]
    here = os.path.dirname(os.path.abspath(__file__))
    corpora = {name: os.path.join(out, name) for name in
               ("obj", "poses", "gltf", "gltf_capi", "create_mesh", "capi", "hid_descriptor", "kernel")}
    for d in corpora.values():
        os.makedirs(d, exist_ok=True)

    def put(target, name, data):
        if len(data) <= MAX_SEED:
            with open(os.path.join(corpora[target], name), "wb") as f:
                f.write(data)

    for name in ("Box.glb", "RiggedSimple.glb", "OrientationTest.glb"):
        with open(os.path.join(assets, "gltf", name), "rb") as f:
            data = f.read()
        put("gltf", name, data)
        put("gltf_capi", name, data)
    for rel in ("TriangleWithoutIndices/TriangleWithoutIndices.gltf",
                "SimpleSparseAccessor/SimpleSparseAccessor.gltf", "Duck-Draco/Duck.gltf"):
        data = embed_buffers(os.path.join(assets, "gltf", rel))
        put("gltf", os.path.basename(os.path.dirname(rel)) + ".gltf", data)
        put("gltf_capi", os.path.basename(os.path.dirname(rel)) + ".gltf", data)
    put("obj", "bunny-400.obj", bunny_cut(os.path.join(assets, "bunny.obj"), 400))
    devices = os.path.join(os.path.dirname(os.path.normpath(assets)), "devices")
    for sub in ("", "pid"):
        folder = os.path.join(devices, sub)
        if os.path.isdir(folder):
            for name in sorted(os.listdir(folder)):
                if name.endswith(".rdesc.bin"):
                    with open(os.path.join(folder, name), "rb") as f:
                        put("hid_descriptor", name, f.read())

    for target, d in corpora.items():
        seeds = os.path.join(here, "seeds", target)
        if os.path.isdir(seeds):
            for name in os.listdir(seeds):
                shutil.copy(os.path.join(seeds, name), os.path.join(d, "seed-" + name))
        count = len(os.listdir(d))
        print(f"{target}: {count} seeds")


if __name__ == "__main__":
    main()
