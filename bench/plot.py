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
                                      method and scene (bunny and CAD scenes)
  scaling.png                         time against triangle count, log-log,
                                      with the peers (the scaling-* scenes)
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
           "fcl": "tab:green", "min-distance": "tab:purple", "coal": "tab:orange"}
MARKERS = {"path-t": "o", "paper-hard": "o", "path-r": "s", "paper-soft": "^", "cad-engine": "D",
           "cad-saw": "v", "cad-bunny-engine": "P", "cad-saw-engine": "X"}
ORDER = ["path-t", "paper-hard", "path-r", "paper-soft", "cad-engine", "cad-saw", "cad-bunny-engine",
         "cad-saw-engine", "scaling-2k", "scaling-7k", "scaling-28k", "scaling-111k", "scaling-446k"]


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
    fig, axes = plt.subplots(1, 3, figsize=(18, 5.5))
    floor = 1e-19
    for scene, s in summaries.items():
        marker = MARKERS.get(scene, "D")
        methods = s["methods"]
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
                                label=label + (" (0.4-cutoff match)" if m == "original" else ""))
            elif m in ("fcl", "min-distance"):
                err = data["min_distance_error_max_over_size"]
                axes[0].scatter(t, max(err, floor) if finite(err) else floor, c=c, marker=marker, label=label)
            elif m == "coal":
                continue  # pairs within the cutoff, no distances or forces to score
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
    if axes[2].get_legend_handles_labels()[0]:
        axes[2].legend(fontsize=5, loc="center left", bbox_to_anchor=(1.0, 0.5))
    fig.suptitle("Run time against error: lower left is better (FCL and min-distance return one pair, "
                 "not an LMD set)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def scaling(summaries, path):
    """Time against triangle count, log-log: medians over the poses in contact."""
    levels = sorted(summaries.values(), key=lambda s: s["meshes"][0]["triangles"])
    tris = [s["meshes"][0]["triangles"] for s in levels]
    fig, axes = plt.subplots(1, 2, figsize=(14, 5.5))
    ax = axes[0]

    def series(method, key, scale=1.0, stat="median"):
        out = []
        for s in levels:
            d = s["methods"].get(method, {}).get(key)
            v = d["contact"][stat] if d else math.nan
            out.append(v * scale if finite(v) else math.nan)
        return out
    ax.plot(tris, series("precise", "query_ms"), "o-", c=COLOURS["precise"], label="precise: global + reduction")
    ax.plot(tris, series("precise", "global_ms"), "o--", c=COLOURS["precise"], alpha=0.7,
            label="precise: global search")
    ax.plot(tris, series("precise", "reduction_ms"), "o:", c=COLOURS["precise"], alpha=0.7,
            label="precise: reduction")
    ax.plot(tris, series("precise", "local_ms"), "s-", c="tab:cyan", label="precise: local update (median)")
    ax.plot(tris, series("precise", "local_ms", stat="p99"), "s:", c="tab:cyan", label="precise: local update (p99)")
    ax.plot(tris, series("original", "query_ms"), "o-", c=COLOURS["original"], label="original: global + reduction")
    ax.plot(tris, series("fcl", "query_ms"), "^-", c=COLOURS["fcl"], label="FCL distance (one pair)")
    ax.plot(tris, series("min-distance", "query_ms"), "^--", c=COLOURS["min-distance"],
            label="Proxima min-distance (one pair)")
    if any(finite(v) for v in series("coal", "query_ms")):
        ax.plot(tris, series("coal", "query_ms"), "v-", c=COLOURS["coal"], label="Coal margin collide (all pairs)")
    lo, hi = min(tris), max(tris)
    ref = series("precise", "global_ms")[0]
    if finite(ref):
        ax.plot([lo, hi], [ref, ref * hi / lo], c="grey", lw=0.6, ls="--", label="linear in triangles (from 2k)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("triangles per bunny (A and B the same)")
    ax.set_ylabel("ms, median over the poses in contact (path T)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    ax.set_title("query times against mesh size", fontsize=9)
    ax = axes[1]
    ax.plot(tris, [s["meshes"][0]["snch_build_ms"] for s in levels], "o-", c=COLOURS["precise"], label="SNCH build (ms)")
    ax.plot(tris, [s["meshes"][0].get("fcl_build_ms", math.nan) for s in levels], "^-", c=COLOURS["fcl"],
            label="FCL OBBRSS build (ms)")
    if any("coal_build_ms" in s["meshes"][0] for s in levels):
        ax.plot(tris, [s["meshes"][0].get("coal_build_ms", math.nan) for s in levels], "v-", c=COLOURS["coal"],
                label="Coal OBBRSS build (ms)")
    ax.plot(tris, [s["meshes"][0]["snch_memory_bytes"] / 2**20 for s in levels], "o--", c="tab:brown",
            label="SNCH memory (MiB)")
    ax.plot(tris, [s["meshes"][0].get("fcl_memory_bytes", math.nan) / 2**20 for s in levels], "^--", c="tab:olive",
            label="FCL memory (MiB)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("triangles")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    ax.set_title("hierarchy build time and memory per mesh", fontsize=9)
    fig.suptitle("Scaling: the bunny from 2k (decimated) to 446k (subdivided) triangles, path T, cutoff 5 mm",
                 fontsize=10)
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
        out.append(f"{s['description']} {s['path']['poses']} poses, {s['contact_poses']} within the cutoff "
                   f"({s['cutoff'] * 1e3:.2f} mm); reference at {s['reference_poses']} poses.\n")
        out.append("Times over the poses in contact, median / p99:\n")
        out.append("| method | global + reduction (ms) | global (ms) | reduction (ms) | local update (µs) "
                   "| force evaluation (ns) |")
        out.append("|---|---|---|---|---|---|")
        for name in ("precise", "original", "min-distance", "fcl", "coal", "reference"):
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
                   "| recall / precision within 0.4 cutoffs | max min-distance error / size | max force error (N) "
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
        if "coal" in m:
            pc = r["contact"]["precise_over_coal"]
            pairs = m["coal"]["pairs_within_cutoff"]["contact"]
            out.append(f"Per-pose ratio precise / Coal's margin collide (every triangle pair within the cutoff), in "
                       f"contact: median {fmt(pc['per_pose_median'], '.3f')} (p99 {fmt(pc['per_pose_p99'], '.3f')}); "
                       f"Coal's pairs in contact: median {fmt(pairs['median'], '.0f')}, max "
                       f"{fmt(pairs['max'], '.0f')}.")
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
    levels = sorted((s for n, s in summaries.items() if n.startswith("scaling-")),
                    key=lambda s: s["meshes"][0]["triangles"])
    if levels:
        out.append("### Scaling\n")
        out.append("Path T on the bunny at each resolution; medians over the poses in contact (ms; local update in "
                   "µs, median / p99).\n")
        out.append("| triangles | precise global | precise reduction | precise global + reduction | precise local "
                   "update (µs) | original global + reduction | FCL distance | Proxima min-distance "
                   "| Coal margin collide | poses in contact |")
        out.append("|---|---|---|---|---|---|---|---|---|---|")
        for s in levels:
            m = s["methods"]

            def med(method, key, scale=1.0, stat="median"):
                d = m.get(method, {}).get(key)
                v = d["contact"][stat] if d else None
                return fmt(v * scale if finite(v) else None, ".3f" if scale == 1.0 else ".1f")
            out.append(f"| {s['meshes'][0]['triangles']} | {med('precise', 'global_ms')} "
                       f"| {med('precise', 'reduction_ms')} | {med('precise', 'query_ms')} "
                       f"| {med('precise', 'local_ms', 1e3)} / {med('precise', 'local_ms', 1e3, 'p99')} "
                       f"| {med('original', 'query_ms')} | {med('fcl', 'query_ms')} | {med('min-distance', 'query_ms')} "
                       f"| {med('coal', 'query_ms')} | {s['contact_poses']} |")
        out.append("")
    meshes = {}
    for s in summaries.values():
        for mesh in s["meshes"]:
            meshes.setdefault(mesh["name"], mesh)
    out.append("### Hierarchies\n")
    out.append("Median of 3 builds per mesh.\n")
    out.append("| mesh | triangles | largest / median triangle area | SNCH nodes | depth | SNCH build (ms) "
               "| SNCH memory (MiB) | FCL OBBRSS build (ms) | FCL memory (MiB) | Coal OBBRSS build (ms) |")
    out.append("|---|---|---|---|---|---|---|---|---|---|")
    for mesh in sorted(meshes.values(), key=lambda m: m["triangles"]):
        out.append(f"| {mesh['name']} | {mesh['triangles']} | {fmt(mesh.get('max_over_median_triangle_area'), '.0f')} "
                   f"| {mesh['snch_nodes']} | {mesh['snch_depth']} "
                   f"| {fmt(mesh['snch_build_ms'], '.1f')} | {fmt(mesh['snch_memory_bytes'] / 2**20, '.2f')} "
                   f"| {fmt(mesh.get('fcl_build_ms'), '.1f')} "
                   f"| {fmt(mesh['fcl_memory_bytes'] / 2**20 if 'fcl_memory_bytes' in mesh else None, '.2f')} "
                   f"| {fmt(mesh.get('coal_build_ms'), '.1f')} |")
    out.append("")
    with open(path, "w") as f:
        f.write("\n".join(out))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    results, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    names = [n for n in ORDER if os.path.exists(os.path.join(results, n + ".json"))]
    if not names:
        sys.exit(f"plot.py: no scene results in {results}")
    summaries = {}
    for n in names:
        with open(os.path.join(results, n + ".json")) as f:
            summaries[n] = json.load(f)
    rows = {n: read_rows(os.path.join(results, n + ".csv")) for n in names if not n.startswith("scaling-")}
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
    if "cad-saw-engine" in names:
        figure7(rows["cad-saw-engine"], summaries["cad-saw-engine"], os.path.join(out, "figure7-cad-saw-engine.png"),
                "CAD: saw housing half approaching the engine's cylinder block (hard force scaled, cutoff 2% of size)")
    pareto({n: summaries[n] for n in names
            if not n.startswith("scaling-") and (n != "paper-hard" or "path-t" not in names)},
           os.path.join(out, "pareto.png"))
    levels = {n: summaries[n] for n in names if n.startswith("scaling-")}
    if len(levels) >= 2:
        scaling(levels, os.path.join(out, "scaling.png"))
    machine_path = os.path.join(results, "machine.txt")
    machine = open(machine_path).read() if os.path.exists(machine_path) else None
    tables(summaries, os.path.join(out, "tables.md"), machine)
    print(f"plots and tables written to {out}/")


if __name__ == "__main__":
    main()
