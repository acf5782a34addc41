#!/usr/bin/env python3
"""The decimated bunnies of the scaling scenes (docs/benchmarks.md).

    decimate.py BUNNY_OBJ OUTPUT_DIR

Reads the shared assets' bunny.obj (27,864 triangles) and writes
OUTPUT_DIR/bunny-2k.obj and OUTPUT_DIR/bunny-7k.obj, quadric edge-collapse
simplifications to about 2,000 and 7,000 triangles by the PyPI package
fast-simplification (the version pinned in docs/dependencies.md;
scripts/bench.sh and scripts/test.sh install it into build/bench-venv). The
output is generated, never committed: run this again to reproduce it.
"""
import os
import sys

import numpy as np
import fast_simplification

TARGETS = {"bunny-2k.obj": 2000, "bunny-7k.obj": 7000}


def read_obj(path):
    """Vertices and triangles of an OBJ (v and f lines; f as i, i/t, i//n or i/t/n)."""
    points, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                points.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                ids = [int(p.split("/")[0]) for p in parts[1:]]
                ids = [i - 1 if i > 0 else len(points) + i for i in ids]
                for k in range(1, len(ids) - 1):  # fan a polygon into triangles
                    faces.append([ids[0], ids[k], ids[k + 1]])
    return np.asarray(points, dtype=np.float64), np.asarray(faces, dtype=np.int32)


def write_obj(path, points, faces, note):
    with open(path, "w") as f:
        f.write(f"# {note}\n")
        for p in points:
            f.write(f"v {p[0]:.17g} {p[1]:.17g} {p[2]:.17g}\n")
        for t in faces:
            f.write(f"f {t[0] + 1} {t[1] + 1} {t[2] + 1}\n")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    source, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    points, faces = read_obj(source)
    version = getattr(fast_simplification, "__version__", "unknown")
    for name, count in TARGETS.items():
        p, t = fast_simplification.simplify(points, faces, target_count=count)
        note = (f"{os.path.basename(source)} ({len(faces)} triangles) simplified to {len(t)} triangles by "
                f"fast-simplification {version}, target_count={count}; written by bench/decimate.py")
        write_obj(os.path.join(out, name), p, t, note)
        print(f"{name}: {len(t)} triangles, {len(p)} vertices")


if __name__ == "__main__":
    main()
