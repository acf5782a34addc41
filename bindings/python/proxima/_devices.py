"""The built-in devices: the haptic loop calls them in C, never Python."""

import numpy as np

from ._core import check, enum_name, ffi, from_c, lib, optional_function, pose_from_c, pose_to_c, real
from ._types import HidDeviceInfo, HidDeviceStats, ScriptedDeviceRecord, StreamDeviceStats


def get_time():
    """Seconds on the steady, monotonic clock StreamDevice.push_pose's times are
    on (proxGetTime). Any thread."""
    return lib.proxGetTime()


class ScriptedDevice:
    """A tool moved along a path of poses (proxScriptedDeviceId); attach it
    with Body.set_device. It lives until destroy() or its world's end."""

    def __init__(self, world, idp):
        self.world = world
        self._idp = idp

    @property
    def record(self):
        """What the device has been handed so far (ScriptedDeviceRecord)."""
        out = ffi.new("proxScriptedDeviceRecord*")
        check(lib.proxScriptedDevice_GetRecord(self._idp[0], out))
        return from_c(ScriptedDeviceRecord, out[0])

    def destroy(self):
        """Lets the device go: a tool it holds has no pose from then on (its
        force fades out)."""
        check(lib.proxScriptedDevice_Destroy(self._idp[0]))

    @property
    def valid(self):
        """Whether the device is alive (not destroyed, nor its world)."""
        return bool(lib.proxScriptedDevice_IsValid(self._idp[0]))

    def _device_def(self):
        out = ffi.new("proxDeviceDef*")
        check(lib.proxScriptedDevice_GetDeviceDef(self._idp[0], out))
        return out

    def __repr__(self):
        return f"<proxima.ScriptedDevice {self._idp[0].index1 - 1}>"


class StreamDevice:
    """The device for a tool your code moves (proxStreamDeviceId): push
    timestamped poses from one thread at your own rate, the haptic loop
    renders the pose at its 1 kHz from the latest samples (in C: no Python
    runs on the haptic thread). Attach it with Body.set_device; it lives
    until destroy() or its world's end."""

    def __init__(self, world, idp):
        self.world = world
        self._idp = idp

    def push_pose(self, position, quaternion, t=None):
        """Hands the device the tool's world pose at time `t` (get_time()'s
        clock; default now). From any one thread at a time; never waits. A
        sample no newer than the newest is dropped (counted in stats)."""
        # A pose of its own per call: a second thread pushing at once must be
        # refused by the library (PROX_ERROR_WRONG_THREAD), not overwrite this one.
        pose = ffi.new("proxPose*")
        pose_to_c((position, quaternion), pose[0], "push_pose")
        when = get_time() if t is None else real(t, "push_pose: t")
        check(lib.proxStreamDevice_PushPose(self._idp[0], pose, when))

    def wrench(self):
        """(force (3,) N, torque (3,) N m, clipped): what the haptic loop last
        handed the device. Any thread."""
        w = ffi.new("proxWrench*")
        check(lib.proxStreamDevice_GetWrench(self._idp[0], w))
        f, t = w.force, w.torque
        return np.array([f.x, f.y, f.z]), np.array([t.x, t.y, t.z]), bool(w.clipped)

    @property
    def stats(self):
        """What the device saw (StreamDeviceStats)."""
        out = ffi.new("proxStreamDeviceStats*")
        check(lib.proxStreamDevice_GetStats(self._idp[0], out))
        return from_c(StreamDeviceStats, out[0])

    def destroy(self):
        """Lets the device go: a tool it holds has no pose from then on (its
        force fades out); push_pose raises from then on."""
        check(lib.proxStreamDevice_Destroy(self._idp[0]))

    @property
    def valid(self):
        """Whether the device is alive (not destroyed, nor its world). Any
        thread."""
        return bool(lib.proxStreamDevice_IsValid(self._idp[0]))

    def _device_def(self):
        out = ffi.new("proxDeviceDef*")
        check(lib.proxStreamDevice_GetDeviceDef(self._idp[0], out))
        return out

    def __repr__(self):
        return f"<proxima.StreamDevice {self._idp[0].index1 - 1}>"


# ---- HID devices (proxima_hid.h) ----------------------------------------------


def hid_function(name):
    """A function of proxima_hid.h, or Unsupported when the library was built
    without it."""
    return optional_function(name, "no HID devices: it was built without PROX_WITH_HIDAPI (it needs hidapi's "
                                   "hidraw backend, Debian's libhidapi-dev, when the package is built)")


def _string(chars):
    return ffi.string(chars).decode("utf-8", errors="replace")


def enumerate_hid_devices():
    """The supported HID devices present now (SpaceMouse family, DualShock 4,
    DualSense): a list of HidDeviceInfo, whose `path` World.open_hid_device
    takes. Any thread."""
    enumerate_ = hid_function("proxEnumerateHidDevices")
    count = ffi.new("int32_t*")
    while True:
        result = enumerate_(ffi.NULL, 0, count)
        if result != lib.PROX_ERROR_CAPACITY:
            check(result)
        infos = ffi.new("proxHidDeviceInfo[]", max(count[0], 1))
        result = enumerate_(infos, count[0], count)
        if result == lib.PROX_ERROR_CAPACITY:
            continue  # one was plugged in meanwhile: ask again
        check(result)
        return [HidDeviceInfo(path=_string(i.path), name=_string(i.name), serial=_string(i.serial),
                              vendor_id=i.vendorId, product_id=i.productId,
                              profile=enum_name("proxHidProfile", i.profile), interface_number=i.interfaceNumber,
                              usage_page=i.usagePage, usage=i.usage)
                for i in (infos[k] for k in range(count[0]))]


class HidDevice:
    """A real HID device driving a tool (proxHidDeviceId, docs/devices.md):
    its own thread reads the reports, integrates the axes into the tool's
    pose and writes rumble back, in C. Open it with World.open_hid_device,
    attach it with Body.set_device; it lives until destroy() or its world's
    end."""

    def __init__(self, world, idp):
        self.world = world
        self._idp = idp

    @property
    def stats(self):
        """What the device did since it was opened (HidDeviceStats)."""
        out = ffi.new("proxHidDeviceStats*")
        check(lib.proxHidDevice_GetStats(self._idp[0], out))
        return from_c(HidDeviceStats, out[0])

    @property
    def pose(self):
        """The tool's pose as the device last integrated it: (position (3,),
        quaternion_wxyz (4,))."""
        out = ffi.new("proxPose*")
        check(lib.proxHidDevice_GetPose(self._idp[0], out))
        return pose_from_c(out[0])

    def destroy(self):
        """Stops its thread and closes it: a tool it holds has no pose from
        then on (its force fades out)."""
        check(lib.proxHidDevice_Destroy(self._idp[0]))

    @property
    def valid(self):
        """Whether the device is open (not destroyed, nor its world). Any thread."""
        return bool(lib.proxHidDevice_IsValid(self._idp[0]))

    def _device_def(self):
        out = ffi.new("proxDeviceDef*")
        check(lib.proxHidDevice_GetDeviceDef(self._idp[0], out))
        return out

    def __repr__(self):
        return f"<proxima.HidDevice {self._idp[0].index1 - 1}>"
