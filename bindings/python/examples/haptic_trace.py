"""What the hand felt: the haptic loop's flight recorder, plotted.

Runs one bunny moved towards another on Proxima's threads with the built-in
scripted device (from 20 mm to 0.5 mm apart in a second, then held), keeps
every haptic tick with the flight recorder (start_threads(trace_capacity=N),
Body.haptic_trace()), and plots the force, its change from one tick to the
next, and the force's spectrum: where a buzz shows as a peak. Or plots a
trace written by `proxima run --trace FILE.csv` (docs/haptic-fidelity.md):

    python haptic_trace.py [MESH] [--seconds 1] [--out trace.png]
    python haptic_trace.py --csv run-trace.csv [--out trace.png]

MESH defaults to bunny.obj in $PROXIMA_ASSETS. Needs matplotlib.
"""

import argparse
import os
import sys
import time

import numpy as np

import proxima


def record(mesh_path, seconds=1.0, hold=0.3, force="hard"):
    """The trace of an approach along +x, as a structured array
    (proxima.trace_dtype())."""
    with proxima.World(method="precise", force=force) as world:
        mesh = world.load_mesh(mesh_path)
        static = world.create_body(mesh, "static")
        info = mesh.info
        centre = 0.5 * (info.bounds_min + info.bounds_max)
        width = float(info.bounds_max[0] - info.bounds_min[0])
        # The tool's x where it starts (20 mm out) and ends (0.5 mm out),
        # measured with the exact distance.
        tool = world.create_body(mesh, "tool", pose=((width + 0.05, 0, 0), (1, 0, 0, 0)),
                                 reference_point=centre)
        xs = [_x_at_gap(static, tool, gap) for gap in (0.02, 0.0005)]
        steps = 100
        path = np.zeros((steps, 7))
        path[:, 0] = np.linspace(xs[0], xs[1], steps)
        path[:, 3] = 1.0
        tool.pose = (path[0, :3], path[0, 3:])
        device = world.create_scripted_device(path, seconds_per_pose=seconds / (steps - 1), loop=False)
        tool.set_device(device)
        rate = 1000.0
        world.start_threads(haptic_rate=rate, trace_capacity=int((seconds + hold + 1.0) * rate))
        try:
            # Closed on what is measured: the path's end reached, then `hold`
            # seconds of ticks more.
            while device.record.progress < steps - 1:
                time.sleep(0.01)
            end = device.record.writes + int(hold * rate)
            while device.record.writes < end:
                time.sleep(0.01)
        finally:
            world.stop_threads()
        return tool.haptic_trace()


def _x_at_gap(static, tool, gap):
    """Where the tool's x puts it `gap` from the static body (bisection on
    the exact distance)."""
    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        tool.pose = ((mid, 0, 0), (1, 0, 0, 0))
        lo, hi = (mid, hi) if proxima.distance(static, tool, max_distance=gap) < gap else (lo, mid)
    return hi


def read_csv(path):
    """A `proxima run --trace` CSV as the same structured array."""
    rows = np.genfromtxt(path, delimiter=",", names=True)
    trace = np.zeros(len(rows), dtype=proxima.trace_dtype())
    trace["tick"], trace["time"] = rows["tick"], rows["time"]
    for pose in ("device", "proxy"):
        trace[pose + "_position"] = np.column_stack([rows[pose + "_" + a] for a in "xyz"])
        trace[pose + "_rotation"] = np.column_stack([rows[pose + "_q" + a] for a in "wxyz"])
    trace["force"] = np.column_stack([rows["force_" + a] for a in "xyz"])
    trace["torque"] = np.column_stack([rows["torque_" + a] for a in "xyz"])
    trace["contact_count"], trace["closest_distance"] = rows["contacts"], rows["closest"]
    for name, bit in proxima.HAPTIC_FLAGS.items():
        trace["flags"] |= np.where(rows[name] > 0, bit, 0).astype(np.uint32)
    return trace


def figures(trace):
    """|F| per tick, its change per tick, and the spectrum of |F| (Hz, N)."""
    magnitude = np.linalg.norm(trace["force"], axis=1)
    step = np.abs(np.diff(magnitude, prepend=magnitude[:1]))
    dt = float(np.median(np.diff(trace["time"]))) if len(trace) > 1 else 1e-3
    detrended = magnitude - np.convolve(magnitude, np.ones(25) / 25, mode="same")
    spectrum = np.abs(np.fft.rfft(detrended)) / max(len(trace), 1)
    frequency = np.fft.rfftfreq(len(trace), d=dt)
    return magnitude, step, frequency, spectrum


def plot(trace, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    magnitude, step, frequency, spectrum = figures(trace)
    t = trace["time"] - trace["time"][0]
    fig, axes = plt.subplots(3, 1, figsize=(9, 9))
    axes[0].plot(t, magnitude, lw=0.8)
    faded = proxima.has_flag(trace, "faded")
    axes[0].fill_between(t, 0, magnitude.max(initial=0) * 1.05, where=faded, color="0.85", label="faded")
    axes[0].set(xlabel="time (s)", ylabel="|force| (N)", title="the force the device was handed")
    axes[0].legend(loc="upper left")
    axes[1].semilogy(t, np.maximum(step, 1e-9), lw=0.6)
    axes[1].axhline(0.05, color="r", lw=0.8, ls="--", label="0.05 N")
    axes[1].set(xlabel="time (s)", ylabel="|force| change per tick (N)")
    axes[1].legend(loc="upper left")
    axes[2].semilogy(frequency[1:], np.maximum(spectrum[1:], 1e-12), lw=0.6)
    axes[2].set(xlabel="frequency (Hz)", ylabel="|F| spectrum (N)", title="a buzz shows as a peak")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", default=os.path.join(os.environ.get("PROXIMA_ASSETS", "."), "bunny.obj"))
    parser.add_argument("--csv", help="plot this `proxima run --trace` file instead of running")
    parser.add_argument("--seconds", type=float, default=1.0)
    parser.add_argument("--out", default="haptic_trace.png")
    args = parser.parse_args(argv)
    trace = read_csv(args.csv) if args.csv else record(args.mesh, args.seconds)
    magnitude, step, _, _ = figures(trace)
    print("%d ticks; largest |F| %.4f N; largest change per tick %.4f N; %d ticks over 0.05 N"
          % (len(trace), magnitude.max(initial=0), step.max(initial=0), int((step > 0.05).sum())))
    plot(trace, args.out)
    print("wrote", args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
