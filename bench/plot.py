#!/usr/bin/env python3
"""Plots and tables from proxima_bench's output (docs/benchmarks.md).

    plot.py RESULTS_DIR OUTPUT_DIR

RESULTS_DIR holds <scene>.csv and <scene>.json as proxima_bench --out wrote
them. Writes into OUTPUT_DIR:
  figure7-hard.png, figure7-soft.png  the paper's Figure 7 for both methods:
                                      force, LMD count (and count before
                                      reduction), global time, local time
  figure7-path-r.png                  the same along path R
  pareto.png                          run time against error, one point per
                                      method and scene
  tables.md                           the summary tables, in Markdown (with
                                      RESULTS_DIR/machine.txt when present)
Needs matplotlib (scripts/bench.sh installs it from PyPI into a venv).
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"precise": "tab:blue", "original": "tab:red", "reference": "black",
           "fcl": "tab:green", "min-distance": "tab:purple"}
MARKERS = {"path-t": "o", "paper-hard": "o", "path-r": "s", "paper-soft": "^"}


def number(text):
    return float(text) if text not in ("", None) else math.nan


def read_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            if k != "method":
                r[k] = number(v)
    return rows


def by_method(rows, method):
    return [r for r in rows if r["method"] == method]


def finite(v):
    return v is not None and not (isinstance(v, float) and math.isnan(v))


def figure7(rows, summary, path, title):
    """Force, LMD counts, global and local time along the path, both methods."""
    cutoff = summary["cutoff"]
    precise = by_method(rows, "precise")
    # Only the part of the path near contact: from a little before the first
    # pose within the cutoff to the end.
    first = next((r["step"] for r in precise if r["exact_min_distance"] <= cutoff), 0)
    start = max(0, int(first - 0.25 * (len(precise) - first)))
    fig, axes = plt.subplots(4, 1, figsize=(8, 11), sharex=True)
    before = axes[1].twinx()  # counts before reduction, log scale
    for method in ("original", "precise", "reference"):
        rs = [r for r in by_method(rows, method) if r["step"] >= start]
        if not rs:
            continue
        steps = [r["step"] for r in rs]
        if method == "reference":
            style = dict(color=COLOURS[method], lw=0.8, ls="--")
            name = "reference (under precise where hidden)"
        else:
            style = dict(color=COLOURS[method], lw=1.2)
            name = method
        axes[0].plot(steps, [r["force"] for r in rs], label=name, **style)
        axes[1].plot(steps, [r["lmds"] for r in rs], label=f"{name}: LMDs", **style)
        if method == "reference":
            continue
        before.plot(steps, [r["candidates"] for r in rs], color=COLOURS[method], lw=0.7, ls=":",
                    label=f"{method}: before reduction (right)")
        axes[2].plot(steps, [r["query_ms"] for r in rs], label=f"{method}: global + reduction", **style)
        axes[2].plot(steps, [r["global_ms"] for r in rs], color=COLOURS[method], lw=0.7, alpha=0.6,
                     ls=":", label=f"{method}: global search alone")
        axes[3].plot(steps, [1e3 * r["local_ms"] for r in rs], label=method, **style)
    before.set_yscale("symlog", linthresh=1)
    before.set_ylabel("candidates before reduction (dotted)")
    before.legend(fontsize=7, loc="center left")
    fcl = [r for r in by_method(rows, "fcl") if r["step"] >= start]
    if fcl:
        axes[2].plot([r["step"] for r in fcl], [r["query_ms"] for r in fcl], color=COLOURS["fcl"], lw=0.8,
                     label="FCL distance (one pair)")
    axes[0].set_ylabel("|force| on B (N)")
    axes[1].set_ylabel("LMD pairs after reduction")
    axes[2].set_ylabel("global thread (ms)")
    axes[3].set_ylabel("local update (µs)")
    axes[3].set_xlabel("step along the path")
    # The minimum distance on a second axis of the force panel.
    twin = axes[0].twinx()
    twin.plot([r["step"] for r in precise if r["step"] >= start],
              [1e3 * r["exact_min_distance"] for r in precise if r["step"] >= start],
              color="grey", lw=0.6, alpha=0.7)
    twin.set_ylabel("minimum distance (mm, grey)")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def pareto(summaries, path):
    """Run time against error: one point per method and scene."""
    fig, axes = plt.subplots(1, 3, figsize=(15, 5))
    floor = 1e-19
    for scene, s in summaries.items():
        marker = MARKERS.get(scene, "D")
        methods = s["methods"]
        size = s["meshes"][0]["size"]
        for m, data in methods.items():
            t = data["query_ms"]["contact"]["median"]
            if not finite(t):
                continue
            c = COLOURS.get(m, "grey")
            label = f"{m}, {scene}"
            if m in ("precise", "original"):
                acc = data["accuracy"]
                err = acc["min_distance_error_max_over_size"]
                axes[0].scatter(t, max(err, floor) if finite(err) else floor, c=c, marker=marker, label=label)
                ferr = acc["force_error_max"]
                if finite(ferr):
                    axes[1].scatter(t, max(ferr, 1e-6), c=c, marker=marker, label=label)
                recall = acc["recall"] if m == "precise" else acc["recall_2mm"]
                axes[2].scatter(t, max(1.0 - recall, 1e-4) if finite(recall) else 1.0, c=c, marker=marker,
                                label=label + (" (2 mm match)" if m == "original" else ""))
            elif m in ("fcl", "min-distance"):
                err = data["min_distance_error_max_over_size"]
                axes[0].scatter(t, max(err, floor) if finite(err) else floor, c=c, marker=marker, label=label)
            elif m == "reference":
                axes[0].scatter(t, floor, c=c, marker=marker, label=label)
                axes[1].scatter(t, 1e-6, c=c, marker=marker, label=label)
                axes[2].scatter(t, 1e-4, c=c, marker=marker, label=label)
    axes[0].set_ylabel("largest minimum-distance error / model size (floor 1e-19 = exact)")
    axes[1].set_ylabel("largest force error vs reference (N, floor 1e-6)")
    axes[2].set_ylabel("LMDs missed: 1 - recall (floor 1e-4)")
    for ax in axes:
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("median query time in contact (ms)")
        ax.grid(alpha=0.3, which="both")
    axes[0].set_title("minimum distance (every method, FCL too)", fontsize=9)
    axes[1].set_title("force on the tool (LMD-set methods)", fontsize=9)
    axes[2].set_title("LMD recall (LMD-set methods)", fontsize=9)
    axes[2].legend(fontsize=6, loc="center right")
    axes[0].legend(fontsize=6, loc="center right")
    fig.suptitle("Run time against error: lower left is better (FCL and min-distance return one pair, "
                 "not an LMD set)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def fmt(v, spec):
    return format(v, spec) if finite(v) else "-"


def tables(summaries, path, machine=None):
    out = ["# Benchmark tables\n",
           "Written by `bench/plot.py` from `proxima_bench`'s JSON (`./scripts/bench.sh`); "
           "see [../benchmarks.md](../benchmarks.md) for how to read them.\n"]
    if machine:
        out.append("```\n" + machine.strip() + "\n```\n")
    for scene, s in summaries.items():
        m = s["methods"]
        out.append(f"### {scene}\n")
        out.append(f"{s['description']} {s['path']['poses']} poses, {s['contact_poses']} within the cutoff; "
                   f"reference at {s['reference_poses']} poses.\n")
        out.append("Times over the poses in contact, median / p99:\n")
        out.append("| method | global + reduction (ms) | global (ms) | reduction (ms) | local update (µs) "
                   "| force evaluation (ns) |")
        out.append("|---|---|---|---|---|---|")
        for name in ("precise", "original", "min-distance", "fcl", "reference"):
            if name not in m:
                continue
            d = m[name]

            def pair(key, scale=1.0, spec=".3f"):
                if key not in d:
                    return "—"
                c = d[key]["contact"]
                return f"{fmt(c['median'] * scale if finite(c['median']) else None, spec)} / " \
                       f"{fmt(c['p99'] * scale if finite(c['p99']) else None, spec)}"
            out.append(f"| {name} | {pair('query_ms')} | {pair('global_ms')} | {pair('reduction_ms')} | "
                       f"{pair('local_ms', 1e3, '.1f')} | {pair('force_eval_ns', 1.0, '.0f')} |")
        out.append("")
        out.append("| method | max LMDs | max before reduction | reduction (overall / max) | node pairs (median) "
                   "| leaf pairs (median) | reduction cache hits (median) | recall | precision "
                   "| recall / precision within 2 mm | max min-distance error / size | max force error (N) "
                   "| max force jump (N) | total variation (N) |")
        out.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for name in ("precise", "original"):
            d = m[name]
            a = d["accuracy"]
            sm = d["smoothness"]
            out.append(
                f"| {name} | {fmt(d['lmds']['all']['max'], '.0f')} | {fmt(d['candidates']['all']['max'], '.0f')} "
                f"| {fmt(d['reduction_ratio']['overall'], '.0f')}× / {fmt(d['reduction_ratio']['max'], '.0f')}× "
                f"| {fmt(d['node_pairs']['contact']['median'], '.0f')} "
                f"| {fmt(d['leaf_pairs']['contact']['median'], '.0f')} "
                f"| {fmt(d['reduction_cache_hits']['contact']['median'], '.0f')} "
                f"| {fmt(a['recall'], '.4f')} | {fmt(a['precision'], '.4f')} "
                f"| {fmt(a['recall_2mm'], '.4f')} / {fmt(a['precision_2mm'], '.4f')} "
                f"| {fmt(a['min_distance_error_max_over_size'], '.1e')} | {fmt(a['force_error_max'], '.4f')} "
                f"| {fmt(sm['max_force_jump'], '.4f')} | {fmt(sm['total_variation'], '.3f')} |")
        if "reference" in m and "smoothness" in m["reference"]:
            sm = m["reference"]["smoothness"]
            out.append(f"| reference | | | | | | | | | | | | {fmt(sm['max_force_jump'], '.4f')} "
                       f"| {fmt(sm['total_variation'], '.3f')} |")
        out.append("")
        r = s["ratios"]
        line = (f"Ratios of medians in contact, precise / original: global + reduction "
                f"{fmt(r['contact']['precise_over_original']['query_ms'], '.2f')}, global "
                f"{fmt(r['contact']['precise_over_original']['global_ms'], '.2f')}, reduction "
                f"{fmt(r['contact']['precise_over_original']['reduction_ms'], '.2f')}, local update "
                f"{fmt(r['contact']['precise_over_original']['local_ms'], '.2f')}.")
        out.append(line)
        if "precise_over_fcl" in r["all"]:
            pf, pc = r["all"]["precise_over_fcl"], r["contact"]["precise_over_fcl"]
            mf = r["all"]["min-distance_over_fcl"]
            out.append(f"Per-pose ratio precise (global + reduction, the whole LMD set) / FCL distance (one pair): "
                       f"median {fmt(pf['per_pose_median'], '.2f')} over all poses, "
                       f"{fmt(pc['per_pose_median'], '.2f')} in contact (p99 {fmt(pc['per_pose_p99'], '.2f')}). "
                       f"Proxima's own single-pair minimum_distance / FCL: median "
                       f"{fmt(mf['per_pose_median'], '.2f')}. FCL agrees with Proxima's exact minimum distance "
                       f"to {fmt(m['fcl']['min_distance_error_max'], '.1e')} m.")
        out.append("")
    meshes = next(iter(summaries.values()))["meshes"]
    out.append("### Hierarchies\n")
    out.append("| mesh | triangles | SNCH nodes | depth | SNCH build (ms) | SNCH memory (MiB) | FCL OBBRSS build (ms) "
               "| FCL memory (MiB) |")
    out.append("|---|---|---|---|---|---|---|---|")
    for mesh in meshes:
        out.append(f"| {mesh['name']} | {mesh['triangles']} | {mesh['snch_nodes']} | {mesh['snch_depth']} "
                   f"| {fmt(mesh['snch_build_ms'], '.1f')} | {fmt(mesh['snch_memory_bytes'] / 2**20, '.2f')} "
                   f"| {fmt(mesh.get('fcl_build_ms'), '.1f')} "
                   f"| {fmt(mesh['fcl_memory_bytes'] / 2**20 if 'fcl_memory_bytes' in mesh else None, '.2f')} |")
    out.append("")
    with open(path, "w") as f:
        f.write("\n".join(out))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    results, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    order = ["path-t", "paper-hard", "path-r", "paper-soft"]
    names = [n for n in order if os.path.exists(os.path.join(results, n + ".json"))]
    if not names:
        sys.exit(f"plot.py: no scene results in {results}")
    summaries = {}
    for n in names:
        with open(os.path.join(results, n + ".json")) as f:
            summaries[n] = json.load(f)
    rows = {n: read_rows(os.path.join(results, n + ".csv")) for n in names}
    hard = "paper-hard" if "paper-hard" in names else ("path-t" if "path-t" in names else None)
    if hard:
        figure7(rows[hard], summaries[hard], os.path.join(out, "figure7-hard.png"),
                "Figure 7, hard force (exponential, cutoff 5 mm): bunny vs bunny along path T, 50 mm to 0.5 mm")
    if "paper-soft" in names:
        figure7(rows["paper-soft"], summaries["paper-soft"], os.path.join(out, "figure7-soft.png"),
                "Figure 7, soft force (linear, cutoff 10 mm): bunny vs bunny along +x, 50 mm to 2 mm")
    if "path-r" in names:
        figure7(rows["path-r"], summaries["path-r"], os.path.join(out, "figure7-path-r.png"),
                "Path R (hard force, cutoff 5 mm): bunny B turning 90° while approaching, 50 mm to 0.5 mm")
    pareto({n: summaries[n] for n in names if n != "paper-hard" or "path-t" not in names},
           os.path.join(out, "pareto.png"))
    machine_path = os.path.join(results, "machine.txt")
    machine = open(machine_path).read() if os.path.exists(machine_path) else None
    tables(summaries, os.path.join(out, "tables.md"), machine)
    print(f"plots and tables written to {out}/")


if __name__ == "__main__":
    main()
