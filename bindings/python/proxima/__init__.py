"""Proxima: multi-contact proximity haptics, from Python.

    import proxima
    with proxima.World(method="precise", cutoff=0.005, force="hard") as w:
        bunny = w.load_mesh("bunny.obj")
        w.create_body(bunny, "static")
        tool = w.create_body(bunny, "tool", pose=((0.14, 0, 0), (1, 0, 0, 0)))
        w.step()
        print(tool.contacts()["distance"].min(), tool.wrench())

A thin layer over the C API (proxima.h, loaded with cffi); docs/python.md.
"""

from ._core import (Busy, CapacityError, Error, FileError, InternalError, InvalidArgument, InvalidHandle,
                    InvalidMesh, ParseError, Unsupported, VersionMismatch, WrongThread, c_dtype,
                    version_string)
from ._devices import HidDevice, ScriptedDevice, StreamDevice, enumerate_hid_devices, get_time
from ._xr import XrDevice, xr_create_actions, xr_suggested_bindings
from ._types import (Animation, ForceSettings, HidDeviceInfo, HidDeviceStats, IntersectionStats, MeshInfo, MeshStats, PatchSettings, PatchStats,
                     RigInfo, SafetyStats, ScriptedDeviceRecord, Skin, SearchStats, StreamDeviceStats, ThreadStats,
                     TrackStats, WorldStats, XrDeviceStats, contact_dtype)
from ._trace import FLAGS as HAPTIC_FLAGS, has_flag, trace_dtype
from ._world import Body, Mesh, World, distance, force_preset

#: "major.minor.patch": the library's proxGetVersion(), checked at import
#: against the header the package was built from.
__version__ = version_string()

__all__ = [
    "__version__", "World", "Mesh", "Body", "ScriptedDevice", "StreamDevice", "HidDevice", "get_time", "distance",
    "enumerate_hid_devices", "HidDeviceInfo", "HidDeviceStats",
    "XrDevice", "XrDeviceStats", "xr_create_actions", "xr_suggested_bindings",
    "force_preset", "c_dtype", "StreamDeviceStats", "trace_dtype", "has_flag", "HAPTIC_FLAGS",
    "contact_dtype", "ForceSettings", "MeshInfo", "MeshStats", "RigInfo", "Animation", "Skin", "WorldStats", "SearchStats",
    "TrackStats",
    "IntersectionStats", "ThreadStats", "SafetyStats", "ScriptedDeviceRecord", "PatchSettings", "PatchStats",
    "Error", "InvalidArgument", "InvalidHandle", "InvalidMesh", "FileError", "ParseError", "Unsupported",
    "VersionMismatch", "WrongThread", "CapacityError", "InternalError", "Busy",
]
