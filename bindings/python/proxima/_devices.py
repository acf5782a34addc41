"""The built-in devices: the haptic loop calls them in C, never Python."""

from ._core import check, ffi, from_c, lib
from ._types import ScriptedDeviceRecord


class ScriptedDevice:
    """A tool moved along a path of poses (proxScriptedDeviceId); attach it
    with Body.set_device. It lives as long as its world."""

    def __init__(self, world, idp):
        self.world = world
        self._idp = idp

    @property
    def record(self):
        """What the device has been handed so far (ScriptedDeviceRecord)."""
        out = ffi.new("proxScriptedDeviceRecord*")
        check(lib.proxScriptedDevice_GetRecord(self._idp[0], out))
        return from_c(ScriptedDeviceRecord, out[0])

    def _device_def(self):
        out = ffi.new("proxDeviceDef*")
        check(lib.proxScriptedDevice_GetDeviceDef(self._idp[0], out))
        return out

    def __repr__(self):
        return f"<proxima.ScriptedDevice {self._idp[0].index1 - 1}>"
