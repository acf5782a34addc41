#!/usr/bin/env python3
"""The haptic loop's period, from proxima_timing_bench (docs/benchmarks.md).

    plot_timing.py RESULTS_DIR OUTPUT_DIR

Reads RESULTS_DIR/haptic-timing.json; writes OUTPUT_DIR/haptic-timing.png
(the period's histogram per configuration, search idle and busy) and
OUTPUT_DIR/haptic-timing.md (the table). Needs matplotlib.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {("sleep", False): ("tab:blue", "-"), ("sleep", True): ("tab:blue", "--"),
         ("spin", False): ("tab:red", "-"), ("spin", True): ("tab:red", "--")}


def label(c):
    prio = "normal" if c["priority_asked"] == 0 else (
        f"FIFO {c['priority_granted']}" if c["priority_granted"] else "FIFO refused")
    return f"{c['timing']}, {prio}"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(os.path.join(sys.argv[1], "haptic-timing.json")) as f:
        run = json.load(f)
    out = sys.argv[2]
    os.makedirs(out, exist_ok=True)
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.2), sharey=True)
    for ax, search in zip(axes, ("idle", "busy")):
        for c in run["configurations"]:
            if c["search"] != search:
                continue
            bins = c["period_histogram_10us"]
            xs = [0.01 * i for i in range(len(bins))]  # ms
            colour, dash = STYLE[(c["timing"], c["priority_asked"] > 0)]
            ax.step(xs, [max(b, 0.5) for b in bins], where="post", color=colour, linestyle=dash, label=label(c))
        ax.set_yscale("log")
        ax.set_ylim(0.7, None)
        ax.set_xlim(0.6, 3.0)
        ax.axvline(1.0, color="grey", linewidth=0.5)
        ax.set_xlabel("period (ms); the last bin holds all longer ones")
        ax.set_title(f"global search {search}")
        ax.legend(fontsize=8)
    axes[0].set_ylabel("ticks per 10 µs bin")
    fig.suptitle(f"Haptic loop at 1 kHz, {run['seconds_per_configuration']:g} s per configuration, "
                 f"{run['machine_cores']} cores")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "haptic-timing.png"), dpi=110)
    lines = ["| search | timing | priority | error p50 µs | p99 µs | p99.9 µs | max µs | overruns | CPU |",
             "|---|---|---|---|---|---|---|---|---|"]
    for c in run["configurations"]:
        prio = label(c).split(", ")[1]
        lines.append(f"| {c['search']} | {c['timing']} | {prio} | {c['error_us_p50']:.1f} | {c['error_us_p99']:.1f} | "
                     f"{c['error_us_p999']:.1f} | {c['error_us_max']:.1f} | {c['overruns']} | "
                     f"{100 * c['cpu_fraction']:.1f}% |")
    with open(os.path.join(out, "haptic-timing.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"haptic-timing.png and haptic-timing.md written to {out}/")


if __name__ == "__main__":
    main()
