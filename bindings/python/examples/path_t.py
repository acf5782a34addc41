"""Path T from Python: the paper's Figure 7.

One bunny held and moved along +x towards another, from 50 mm to 0.5 mm
apart, one deterministic step per pose, with the precise method and the
original Johnson-Cohen baseline side by side, exactly as `proxima path` does
(docs/cli.md). Plots the force, the LMD count and the timings against the
distance, and writes the PNG:

    python path_t.py [MESH] [--steps 1000] [--out path_t.png]

MESH defaults to bunny.obj in $PROXIMA_ASSETS. Needs matplotlib.
"""

import argparse
import os
import sys

import numpy as np

import proxima

FAR, NEAR = 0.05, 0.0005  # m: the ends of path T


def x_at_gap(world, a, b, gap):
    """Where b's x puts it `gap` from a: bisection on the exact minimum
    distance (the CLI's x_at_gap); leaves b where it was."""
    before = b.pose
    lo, hi = 0.0, _diagonal(a.mesh) + _diagonal(b.mesh) + gap
    for _ in range(100):
        if hi - lo <= 1e-12 * hi:
            break
        mid = 0.5 * (lo + hi)
        b.pose = ((mid, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))
        d = proxima.distance(a, b, max_distance=gap)
        if d < gap:
            lo = mid
        else:
            hi = mid
    b.pose = before
    return hi


def _diagonal(mesh):
    info = mesh.info
    return float(np.linalg.norm(info.bounds_max - info.bounds_min))


def run_path(mesh_path, steps=1000, methods=("precise", "original"), force="hard"):
    """Per method, one row per pose: x, min_distance (of the LMDs; -1 for
    none), candidates, lmds, force (3,), global_ms, reduction_ms, local_ms, as
    the CLI's --csv."""
    results = {}
    xs = None
    for method in methods:
        with proxima.World(method=method, force=force) as w:
            mesh = w.load_mesh(mesh_path)
            info = mesh.info
            a = w.create_body(mesh, "static")
            b = w.create_body(mesh, "tool", reference_point=(info.bounds_min + info.bounds_max) / 2)
            if xs is None:
                x0, x1 = x_at_gap(w, a, b, FAR), x_at_gap(w, a, b, NEAR)
                xs = [x0 + (x1 - x0) * i / (steps - 1) for i in range(steps)]
            rows = []
            for x in xs:
                b.pose = ((x, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))
                w.track()  # what the local thread does between global searches
                local_ms = w.track_stats.seconds * 1e3
                w.step()  # the global search and its reduction
                search = w.search_stats
                contacts = b.contacts()
                f, _, _ = b.wrench()
                rows.append({
                    "x": x,
                    "min_distance": float(contacts["distance"].min()) if len(contacts) else -1.0,
                    "candidates": search.candidates,
                    "lmds": len(contacts),
                    "force": f,
                    "global_ms": search.global_seconds * 1e3,
                    "reduction_ms": search.reduction_seconds * 1e3,
                    "local_ms": local_ms,
                })
            results[method] = rows
    return results


def plot(results, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(3, 1, figsize=(8, 10), sharex=True)
    for i, (method, rows) in enumerate(results.items()):
        step, color = np.arange(len(rows)), f"C{i}"
        axes[0].plot(step, [np.linalg.norm(r["force"]) for r in rows], color=color, label=method)
        axes[1].plot(step, [r["lmds"] for r in rows], color=color, label=method)
        axes[2].plot(step, [r["global_ms"] + r["reduction_ms"] for r in rows], color=color,
                     label=f"{method}: global search + reduction")
        axes[2].plot(step, [r["local_ms"] for r in rows], color=color, linestyle="--",
                     label=f"{method}: local tracking")
    axes[0].set_ylabel("|force| (N)")
    axes[1].set_ylabel("LMD count")
    axes[2].set_ylabel("time per step (ms)")
    axes[2].set_xlabel(f"step along path T (linear in x, {FAR * 1e3:g} mm to {NEAR * 1e3:g} mm apart)")
    axes[2].set_yscale("symlog", linthresh=0.01)
    for ax in axes:
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.suptitle("Path T: a bunny held and moved towards another")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default_mesh = os.path.join(os.environ.get("PROXIMA_ASSETS", "."), "bunny.obj")
    parser.add_argument("mesh", nargs="?", default=default_mesh)
    parser.add_argument("--steps", type=int, default=1000)
    parser.add_argument("--force", choices=("hard", "soft"), default="hard")
    parser.add_argument("--out", default="path_t.png")
    args = parser.parse_args(argv)
    if args.steps < 2:
        parser.error("--steps must be at least 2")
    if not os.path.isfile(args.mesh):
        parser.error(f"{args.mesh}: no such mesh (give one, or set PROXIMA_ASSETS)")
    results = run_path(args.mesh, args.steps, force=args.force)
    for method, rows in results.items():
        forces = np.array([r["force"] for r in rows])
        jumps = np.linalg.norm(np.diff(forces, axis=0), axis=1)
        print(f"{method:9s} steps {len(rows)}  in contact {sum(r['lmds'] > 0 for r in rows)}  "
              f"max LMDs {max(r['lmds'] for r in rows)}  max |F| {np.linalg.norm(forces, axis=1).max():.4f} N  "
              f"max jump {max(jumps):.4f} N")
    plot(results, args.out)
    print(f"plot written to {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
