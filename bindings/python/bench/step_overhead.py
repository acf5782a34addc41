"""The binding's overhead: step() + contacts() from Python against the same
loop in C (step_overhead.c, compiled here against the package's own
libproxima.so), on the bunny.

    python step_overhead.py [MESH] [--iterations N]

Two cases: "moving" (the pose is set each time, alternating 10 um apart, so
every step runs the global search: what a user pays in practice) and "still"
(no pose is set, the step skips the search: almost nothing but the calls, so
the binding's own cost shows). Needs a C
compiler (cc). Prints microseconds per iteration, the median of 5 repeats.
"""

import argparse
import os
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import proxima
from proxima import _core

HERE = pathlib.Path(__file__).resolve().parent
INCLUDE = HERE.parents[2] / "sdk" / "include"
POSES = [((0.135, 0.01, 0.0), (0.98, 0.05, 0.1, 0.03)), ((0.13501, 0.01, 0.0), (0.98, 0.05, 0.1, 0.03))]


def build_c(out_dir):
    compiler = os.environ.get("CC") or shutil.which("cc")
    if not compiler:
        sys.exit("step_overhead: a C compiler (cc) is needed for the C side")
    lib_dir = os.path.dirname(_core.LIBRARY_PATH)
    exe = os.path.join(out_dir, "step_overhead")
    subprocess.run([compiler, "-O2", "-std=c11", "-I", str(INCLUDE), str(HERE / "step_overhead.c"), "-o", exe,
                    _core.LIBRARY_PATH, f"-Wl,-rpath,{lib_dir}"], check=True)
    return exe


def python_loop(mesh_path, iterations, moving):
    with proxima.World() as w:
        m = w.load_mesh(mesh_path)
        w.create_body(m, "static")
        tool = w.create_body(m, "tool", pose=POSES[0])
        times = []
        for _ in range(5):
            start = time.perf_counter()
            for i in range(iterations):
                if moving:
                    tool.pose = POSES[i & 1]
                w.step()
                c = tool.contacts()
            times.append((time.perf_counter() - start) / iterations * 1e6)
        return statistics.median(times), len(c)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", default=os.path.join(os.environ.get("PROXIMA_ASSETS", "."), "bunny.obj"))
    parser.add_argument("--iterations", type=int, default=2000)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        exe = build_c(tmp)
        print(f"proxima {proxima.__version__}, {args.mesh}, {args.iterations} iterations x 5 repeats (median)")
        print(f"{'case':8s} {'C us':>10s} {'Python us':>10s} {'overhead us':>12s} {'contacts':>9s}")
        for case in ("moving", "still"):
            iterations = args.iterations if case == "still" else max(args.iterations // 10, 10)
            c_us, c_n = subprocess.run([exe, args.mesh, str(iterations), case], check=True, capture_output=True,
                                       text=True).stdout.split()
            py_us, py_n = python_loop(args.mesh, iterations, case == "moving")
            assert int(c_n) == py_n, "the C and Python loops disagree on the contacts"
            print(f"{case:8s} {float(c_us):10.2f} {py_us:10.2f} {py_us - float(c_us):12.2f} {py_n:9d}")


if __name__ == "__main__":
    main()
