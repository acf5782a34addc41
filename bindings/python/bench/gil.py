"""Why the binding refuses Python device callbacks: the haptic loop's timing
with the built-in scripted device, with the streamed device fed from a
Python thread at 90 Hz, and with a device whose two callbacks are Python
functions (cffi callbacks; only this benchmark makes one), while the Python
main thread sleeps or runs pure-Python work.

    python gil.py [MESH] [--seconds 2]

A Python callback needs the GIL on the haptic thread; while another thread
holds it, the callback waits up to sys.getswitchinterval() (5 ms by default)
per tick. The scripted device runs in C and never waits for Python.
"""

import argparse
import os
import sys
import threading
import time

import numpy as np

import proxima
from proxima._core import check, ffi, lib

PATH = np.array([[x, 0, 0, 1, 0, 0, 0] for x in np.linspace(0.1592, 0.1392, 50)])


def busy(seconds):
    end = time.perf_counter() + seconds
    n = 0
    while time.perf_counter() < end:
        n += sum(i * i for i in range(1000))
    return n


def run(mesh_path, device_kind, main_thread, seconds):
    with proxima.World() as w:
        m = w.load_mesh(mesh_path)
        w.create_body(m, "static")
        tool = w.create_body(m, "tool", pose=((0.16, 0, 0), (1, 0, 0, 0)))
        keep = []
        stop = threading.Event()
        pusher = None
        if device_kind == "scripted":
            tool.set_device(w.create_scripted_device(PATH, seconds / 2 / len(PATH)))
        elif device_kind == "stream":
            hand = w.create_stream_device()
            tool.set_device(hand)

            def push():
                while not stop.is_set():
                    hand.push_pose((0.1392, 0, 0), (1, 0, 0, 0))
                    time.sleep(1 / 90)

            pusher = threading.Thread(target=push)
        else:
            @ffi.callback("proxBool(void*, proxPose*)")
            def read_pose(user, pose):
                pose.position.x, pose.position.y, pose.position.z = 0.1392, 0.0, 0.0
                pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z = 1.0, 0.0, 0.0, 0.0
                return 1

            @ffi.callback("void(void*, const proxWrench*)")
            def write_wrench(user, wrench):
                pass

            d = ffi.new("proxDeviceDef*", lib.proxDefaultDeviceDef())
            d.readPose, d.writeWrench = read_pose, write_wrench
            keep += [read_pose, write_wrench]
            check(lib.proxBody_SetDevice(tool._idp[0], d))
        w.start_threads(haptic_rate=1000)
        if pusher:
            pusher.start()
        if main_thread == "busy":
            busy(seconds)
        else:
            time.sleep(seconds)
        stop.set()
        if pusher:
            pusher.join()
        w.stop_threads()
        samples = hand.stats.max_sample_interval * 1e3 if pusher else float("nan")
        return w.thread_stats("haptic"), samples


def released_during_calls(mesh_path, seconds):
    """A pure-Python counter's rate on a second thread while the main thread
    runs brute-force steps (the C API on the bunny), against its rate alone:
    near 1 (or the machine's share of a core) when the calls release the GIL."""
    def count(sec):
        n, end = 0, time.perf_counter() + sec
        while time.perf_counter() < end:
            n += 1
        return n

    alone = count(seconds)
    with proxima.World(method="reference") as w:
        m = w.load_mesh(mesh_path)
        w.create_body(m, "static")
        tool = w.create_body(m, "tool", pose=((0.1392, 0, 0), (1, 0, 0, 0)))
        result = {}
        counter = threading.Thread(target=lambda: result.setdefault("n", count(seconds)))
        counter.start()
        start, in_c, k = time.perf_counter(), 0.0, 0
        while time.perf_counter() - start < seconds:
            tool.pose = ((0.1392 + 1e-6 * (k & 1), 0, 0), (1, 0, 0, 0))
            t = time.perf_counter()
            w.step()
            in_c += time.perf_counter() - t
            k += 1
        counter.join()
    return result["n"] / alone, in_c / (time.perf_counter() - start)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", default=os.path.join(os.environ.get("PROXIMA_ASSETS", "."), "bunny.obj"))
    parser.add_argument("--seconds", type=float, default=2.0)
    args = parser.parse_args()
    ratio, busy_share = released_during_calls(args.mesh, args.seconds)
    print(f"a Python counter thread ran at {ratio:.0%} of its rate alone while the main thread spent "
          f"{busy_share:.0%} of the time in step()")
    print(f"haptic loop at 1 kHz for {args.seconds:g} s; switch interval {sys.getswitchinterval() * 1e3:g} ms")
    print(f"{'device':9s} {'main thread':12s} {'achieved Hz':>11s} {'period p50':>11s} {'p99 ms':>8s} "
          f"{'max ms':>8s} {'overruns':>9s} {'max push gap ms':>16s}")
    for device in ("scripted", "stream", "python"):
        for main_thread in ("sleeping", "busy"):
            s, gap = run(args.mesh, device, main_thread, args.seconds)
            print(f"{device:9s} {main_thread:12s} {s.achieved_rate:11.1f} {s.period_p50 * 1e3:11.3f} "
                  f"{s.period_p99 * 1e3:8.3f} {s.period_max * 1e3:8.3f} {s.overruns:9d} {gap:16.1f}")


if __name__ == "__main__":
    main()
