"""The OpenXR device (proxima_openxr.h, docs/openxr.md): the app owns OpenXR
and hands Proxima its handles; the device's own thread, in C, locates the
controller's grip and sends vibrations.

OpenXR handles, paths and times are Python ints here, as the app got them:
from pyopenxr (whose handles are ctypes pointers, accepted too), from its own
ctypes calls into the loader, or from an engine. xrGetInstanceProcAddr is
its address as an int, a ctypes function pointer or a cffi one."""

import ctypes

import numpy as np

from ._core import check, enum_choices, ffi, from_c, integer, invalid, lib, optional_function, pose_to_c

_PFN = "PFN_xrGetInstanceProcAddr"


def xr_function(name):
    """A function of proxima_openxr.h, or Unsupported when the library was
    built without it."""
    return optional_function(name, "no OpenXR device: it was built without PROX_WITH_OPENXR (it needs the "
                                   "OpenXR headers, Debian's libopenxr-dev, when the package is built)")


def _address(value):
    """An int address from a ctypes pointer or function pointer, or None."""
    if isinstance(value, (ctypes._Pointer, ctypes._CFuncPtr, ctypes.c_void_p)):
        return ctypes.cast(value, ctypes.c_void_p).value or 0
    return None


def handle(value, what, null_ok=True):
    """An OpenXR handle or path (a uint64): an int, a numpy integer, a
    ctypes pointer (pyopenxr's handles) or a ctypes integer."""
    address = _address(value)
    if address is not None:
        value = address
    elif isinstance(value, (ctypes.c_uint64, ctypes.c_int64, ctypes.c_uint32)):
        value = value.value
    elif value is None and null_ok:
        value = 0
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise invalid(f"{what} must be an OpenXR handle (an int, or a ctypes pointer or integer), not {value!r}")
    value = int(value)
    if not 0 <= value < 1 << 64:
        raise invalid(f"{what} must be a 64-bit OpenXR handle, not {value}")
    return value


def proc_addr(value, what="get_instance_proc_addr"):
    """xrGetInstanceProcAddr as proxima_openxr.h's PFN_xrGetInstanceProcAddr."""
    if isinstance(value, ffi.CData):
        return ffi.cast(_PFN, value)
    address = _address(value)
    if address is None:
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
            raise invalid(f"{what} must be xrGetInstanceProcAddr: its address as an int, a ctypes "
                          f"function pointer or a cffi one, not {value!r}")
        address = int(value)
    if not 0 <= address < 1 << (8 * ffi.sizeof("void*")):
        raise invalid(f"{what} must be an address, not {address}")
    return ffi.cast(_PFN, address)


def session_state(value, what):
    """An XrSessionState: its int (pyopenxr's SessionState is an IntEnum) or
    its short name ("focused", "visible", ...)."""
    if isinstance(value, str):
        choices = enum_choices("XrSessionState")
        if value in choices:
            return choices[value]
        raise invalid(f"{what} must be an XrSessionState: one of {', '.join(map(repr, choices))} or its int, "
                      f"not {value!r}")
    return integer(value, what)


def _bytes(value, what):
    if not isinstance(value, str):
        raise invalid(f"{what} must be a str, not {value!r}")
    return value.encode("utf-8")


class XrDevice:
    """An XR controller holding a tool (proxXrDeviceId, docs/openxr.md): the
    grip pose moves the tool, the force comes back as the controller's
    vibration, from the device's own thread in C. Create it with
    World.create_xr_device after the app attached its action sets, attach it
    with Body.set_device. The app keeps polling events (forward each session
    state to on_session_state), syncing actions and running frames (on_frame).
    It lives until destroy() or its world's end: destroy it before the app
    destroys its session, spaces or actions."""

    def __init__(self, world, idp):
        self.world = world
        self._idp = idp

    def on_session_state(self, state):
        """Forward every session state change the app polls: an
        XrSessionState int or its short name ("focused"). Game thread."""
        check(xr_function("proxXrDevice_OnSessionState")(self._idp[0],
                                                          session_state(state, "on_session_state: state")))

    def on_frame(self, predicted_display_time, predicted_display_period):
        """Once a frame, after xrWaitFrame and xrSyncActions: the frame
        state's XrTime and XrDuration (ns, ints; a headless runtime's 0 has no
        frame to report: skip the call). Game thread."""
        check(xr_function("proxXrDevice_OnFrame")(
            self._idp[0], integer(predicted_display_time, "on_frame: predicted_display_time"),
            integer(predicted_display_period, "on_frame: predicted_display_period")))

    def on_runtime_time(self, time):
        """Optional: an XrTime the runtime gave the app, about now (an event's
        time > 0): the device's clock when the runtime offers no other.
        Game thread."""
        check(xr_function("proxXrDevice_OnRuntimeTime")(self._idp[0], integer(time, "on_runtime_time: time")))

    @property
    def stats(self):
        """What the device did since it was created (XrDeviceStats). Any thread."""
        out = ffi.new("proxXrDeviceStats*")
        check(xr_function("proxXrDevice_GetStats")(self._idp[0], out))
        from ._types import XrDeviceStats
        return from_c(XrDeviceStats, out[0])

    def destroy(self):
        """Stops its thread (a vibration playing is stopped) and destroys its
        action space: a tool it holds has no pose from then on (its force
        fades out). Game thread."""
        check(xr_function("proxXrDevice_Destroy")(self._idp[0]))

    @property
    def valid(self):
        """Whether the device is alive (not destroyed, nor its world). Any thread."""
        return bool(xr_function("proxXrDevice_IsValid")(self._idp[0]))

    def _device_def(self):
        out = ffi.new("proxDeviceDef*")
        check(xr_function("proxXrDevice_GetDeviceDef")(self._idp[0], out))
        return out

    def __repr__(self):
        return f"<proxima.XrDevice {self._idp[0].index1 - 1}>"


_HANDLES = {"instance": "instance", "session": "session", "base_space": "baseSpace",
            "pose_action": "poseAction", "haptic_action": "hapticAction", "subaction_path": "subactionPath"}


def create_xr_device(world, get_instance_proc_addr, handles, tool_in_grip, base_to_world, session_state_, settings,
                     fill_settings):
    """World.create_xr_device's work (there, the arguments)."""
    d = ffi.new("proxXrDeviceDef*", xr_function("proxDefaultXrDeviceDef")())
    fill_settings(d, "proxXrDeviceDef", settings, "create_xr_device",
                  skip=("get_instance_proc_addr", "tool_in_grip", "base_to_world", "session_state", *_HANDLES))
    d.getInstanceProcAddr = proc_addr(get_instance_proc_addr, "create_xr_device: get_instance_proc_addr")
    for key, value in handles.items():
        setattr(d, _HANDLES[key], handle(value, f"create_xr_device: {key}"))
    if tool_in_grip is not None:
        pose_to_c(tool_in_grip, d.toolInGrip, "create_xr_device: tool_in_grip")
    if base_to_world is not None:
        pose_to_c(base_to_world, d.baseToWorld, "create_xr_device: base_to_world")
    if session_state_ is not None:
        d.sessionState = session_state(session_state_, "create_xr_device: session_state")
    idp = ffi.new("proxXrDeviceId*")
    check(xr_function("proxWorld_CreateXrDevice")(world._idp[0], d, idp))
    return XrDevice(world, idp)


def xr_create_actions(get_instance_proc_addr, instance, action_set, name_prefix="proxima"):
    """Creates Proxima's pose and vibration actions, "<name_prefix>_grip" and
    "<name_prefix>_haptic", in the app's action set for /user/hand/left and
    /user/hand/right (proxXrCreateActions), before the app attaches the set.
    Returns (pose_action, haptic_action) as ints. Any thread."""
    pose, haptic = ffi.new("XrAction*"), ffi.new("XrAction*")
    check(xr_function("proxXrCreateActions")(
        proc_addr(get_instance_proc_addr, "xr_create_actions: get_instance_proc_addr"),
        handle(instance, "xr_create_actions: instance"), handle(action_set, "xr_create_actions: action_set"),
        _bytes(name_prefix, "xr_create_actions: name_prefix"), pose, haptic))
    return int(pose[0]), int(haptic[0])


def xr_suggested_bindings(get_instance_proc_addr, instance, interaction_profile, hand, pose_action, haptic_action=0):
    """The bindings Proxima's actions need in an interaction profile
    ("/interaction_profiles/khr/simple_controller", ...) for a hand ("left",
    "right" or "/user/hand/right"), for the app to merge into its one
    xrSuggestInteractionProfileBindings call for that profile
    (proxXrGetSuggestedBindings): a list of (action, binding path) int
    pairs. haptic_action may be 0. Unsupported for a profile Proxima does not
    know. Any thread."""
    function = xr_function("proxXrGetSuggestedBindings")
    args = (proc_addr(get_instance_proc_addr, "xr_suggested_bindings: get_instance_proc_addr"),
            handle(instance, "xr_suggested_bindings: instance"),
            _bytes(interaction_profile, "xr_suggested_bindings: interaction_profile"),
            _bytes(hand, "xr_suggested_bindings: hand"),
            handle(pose_action, "xr_suggested_bindings: pose_action"),
            handle(haptic_action, "xr_suggested_bindings: haptic_action"))
    count = ffi.new("int32_t*")
    capacity = 4
    while True:
        bindings = ffi.new("XrActionSuggestedBinding[]", capacity)
        result = function(*args, bindings, capacity, count)
        if result == lib.PROX_ERROR_CAPACITY and count[0] > capacity:
            capacity = count[0]
            continue
        check(result)
        return [(int(bindings[i].action), int(bindings[i].binding)) for i in range(count[0])]
