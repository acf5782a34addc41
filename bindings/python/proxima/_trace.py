"""The haptic loop's flight recorder (proxBody_GetHapticTrace) as numpy.

A trace is a structured array with one row per haptic tick, oldest first,
viewed straight over the C samples (no copy): ``trace["force"]`` is (N, 3),
``trace["device_position"]`` (N, 3), ``trace["device_rotation"]`` (N, 4,
w x y z). The offsets come from the parsed header, as every other dtype of
the package."""

import numpy as np

from ._core import check, ffi, lib

# The proxHapticFlag bits, by their Python names.
FLAGS = {
    "clipped": lib.PROX_HAPTIC_CLIPPED,
    "stale": lib.PROX_HAPTIC_STALE,
    "untrusted": lib.PROX_HAPTIC_UNTRUSTED,
    "faded": lib.PROX_HAPTIC_FADED,
    "no_pose": lib.PROX_HAPTIC_NO_POSE,
    "stopping": lib.PROX_HAPTIC_STOPPING,
}

_DTYPE = None


def trace_dtype():
    """The dtype of a trace row: proxHapticSample with its poses and vectors
    as arrays (time, device_position, device_rotation, proxy_position,
    proxy_rotation, force, torque, contact_count, flags, closest_distance,
    tick)."""
    global _DTYPE
    if _DTYPE is None:
        off = lambda struct, field: ffi.offsetof(struct, field)
        position, rotation = off("proxPose", "position"), off("proxPose", "rotation")
        fields = [("time", "<f8", off("proxHapticSample", "time"))]
        for pose in ("device", "proxy"):
            base = off("proxHapticSample", pose + "Pose")
            fields += [(pose + "_position", ("<f8", 3), base + position),
                       (pose + "_rotation", ("<f8", 4), base + rotation)]
        fields += [("force", ("<f8", 3), off("proxHapticSample", "force")),
                   ("torque", ("<f8", 3), off("proxHapticSample", "torque")),
                   ("contact_count", "<i4", off("proxHapticSample", "contactCount")),
                   ("flags", "<u4", off("proxHapticSample", "flags")),
                   ("closest_distance", "<f8", off("proxHapticSample", "closestDistance")),
                   ("tick", "<u8", off("proxHapticSample", "tick"))]
        _DTYPE = np.dtype({"names": [f[0] for f in fields], "formats": [f[1] for f in fields],
                           "offsets": [f[2] for f in fields], "itemsize": ffi.sizeof("proxHapticSample")})
    return _DTYPE


def haptic_trace(body_id, max_samples):
    """The newest recorded ticks of a tool, at most max_samples, oldest first."""
    if int(max_samples) < 0:
        raise ValueError("max_samples must be >= 0")
    samples = ffi.new("proxHapticSample[]", max(int(max_samples), 1))
    count = ffi.new("int32_t*")
    check(lib.proxBody_GetHapticTrace(body_id, samples, int(max_samples), count))
    rows = np.frombuffer(ffi.buffer(samples), dtype=trace_dtype())
    return rows[:count[0]].copy()


def has_flag(trace, name):
    """A boolean array: which rows of a trace carry the flag (FLAGS' names)."""
    return (trace["flags"] & FLAGS[name]) != 0
