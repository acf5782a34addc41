#!/usr/bin/env python3
"""Runs the C and C# step benchmarks alternately, ROUNDS rounds, and prints
the median of each case side by side as a Markdown table, and as CSV
(--csv FILE). Alternating keeps a busy machine's drift out of the
difference (docs/csharp.md).

    compare.py BUILD_BINDINGS_DIR MESH [--rounds 5] [--iterations 200000] [--csv FILE]
"""
import argparse
import csv
import statistics
import subprocess
import sys


def run(cmd):
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return list(csv.DictReader(out.splitlines()))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("bindings_dir")
    p.add_argument("mesh")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--iterations", type=int, default=200000)
    p.add_argument("--csv")
    a = p.parse_args()
    programs = {
        "c": [a.bindings_dir + "/proxima_c_step_bench", a.mesh, str(a.iterations)],
        "csharp": ["mono", a.bindings_dir + "/step_bench.exe", a.mesh, str(a.iterations)],
    }
    ns = {}
    for _ in range(a.rounds):
        for language, cmd in programs.items():
            for row in run(cmd):
                ns.setdefault((row["case"], language), []).append(float(row["ns_per_iteration"]))
    cases = sorted({case for case, _ in ns})
    print("| case | C (ns) | C# (ns) | C# - C (ns) |")
    print("|---|---|---|---|")
    rows = []
    for case in cases:
        c, cs = statistics.median(ns[(case, "c")]), statistics.median(ns[(case, "csharp")])
        rows.append((case, c, cs))
        print(f"| {case} | {c:.0f} | {cs:.0f} | {cs - c:+.0f} |")
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["case", "c_ns_median", "csharp_ns_median", "rounds"])
            for case, c, cs in rows:
                w.writerow([case, f"{c:.1f}", f"{cs:.1f}", a.rounds])
    return 0


if __name__ == "__main__":
    sys.exit(main())
