"""A headless OpenXR app for test_openxr.py, written as a Python integrator
would with ctypes: the real OpenXR loader (libopenxr_loader.so.1), told by
XR_RUNTIME_JSON to load the mock runtime of tests/openxr (whose control
panel, mock_control.h, the tests reach through its proxMockXr_* exports),
with the core validation layer on. It owns the instance, the session, the
LOCAL space and an action set into which Proxima's actions are merged
(proxima.xr_create_actions, proxima.xr_suggested_bindings); it polls events,
forwarding session states to the device it was handed, and runs the frame
loop: the C++ tests' tests/openxr/xr_app.cpp, in Python."""

import ctypes
import json
import os
import time

import proxima

# OpenXR 1.0's values (openxr.h).
XR_SUCCESS, XR_EVENT_UNAVAILABLE = 0, 4
TYPE = {"instance": 3, "system": 4, "session": 8, "begin": 10, "frame_end": 12, "event_buffer": 16,
        "state_changed": 18, "action_set": 28, "reference_space": 37, "frame_state": 44,
        "suggested": 51, "attach": 60, "sync": 61}
STATES = {1: "idle", 2: "ready", 3: "synchronized", 4: "visible", 5: "focused", 6: "stopping", 8: "exiting"}
handle_t = ctypes.c_uint64


def _s(fields):
    return [("type", ctypes.c_int32), ("next", ctypes.c_void_p)] + fields


class ApplicationInfo(ctypes.Structure):
    _fields_ = [("applicationName", ctypes.c_char * 128), ("applicationVersion", ctypes.c_uint32),
                ("engineName", ctypes.c_char * 128), ("engineVersion", ctypes.c_uint32),
                ("apiVersion", ctypes.c_uint64)]


class InstanceCreateInfo(ctypes.Structure):
    _fields_ = _s([("createFlags", ctypes.c_uint64), ("applicationInfo", ApplicationInfo),
                   ("enabledApiLayerCount", ctypes.c_uint32), ("enabledApiLayerNames", ctypes.c_void_p),
                   ("enabledExtensionCount", ctypes.c_uint32),
                   ("enabledExtensionNames", ctypes.POINTER(ctypes.c_char_p))])


class SystemGetInfo(ctypes.Structure):
    _fields_ = _s([("formFactor", ctypes.c_int32)])


class ActionSetCreateInfo(ctypes.Structure):
    _fields_ = _s([("actionSetName", ctypes.c_char * 64), ("localizedActionSetName", ctypes.c_char * 128),
                   ("priority", ctypes.c_uint32)])


class SuggestedBinding(ctypes.Structure):
    _fields_ = [("action", handle_t), ("binding", handle_t)]


class ProfileSuggestedBinding(ctypes.Structure):
    _fields_ = _s([("interactionProfile", handle_t), ("countSuggestedBindings", ctypes.c_uint32),
                   ("suggestedBindings", ctypes.POINTER(SuggestedBinding))])


class SessionCreateInfo(ctypes.Structure):
    _fields_ = _s([("createFlags", ctypes.c_uint64), ("systemId", ctypes.c_uint64)])


class Posef(ctypes.Structure):  # orientation x y z w, then position x y z: floats
    _fields_ = [("qx", ctypes.c_float), ("qy", ctypes.c_float), ("qz", ctypes.c_float), ("qw", ctypes.c_float),
                ("px", ctypes.c_float), ("py", ctypes.c_float), ("pz", ctypes.c_float)]


class ReferenceSpaceCreateInfo(ctypes.Structure):
    _fields_ = _s([("referenceSpaceType", ctypes.c_int32), ("poseInReferenceSpace", Posef)])


class AttachInfo(ctypes.Structure):
    _fields_ = _s([("countActionSets", ctypes.c_uint32), ("actionSets", ctypes.POINTER(handle_t))])


class EventBuffer(ctypes.Structure):
    _fields_ = _s([("varying", ctypes.c_uint8 * 4000)])


class SessionStateChanged(ctypes.Structure):
    _fields_ = _s([("session", handle_t), ("state", ctypes.c_int32), ("time", ctypes.c_int64)])


class SessionBeginInfo(ctypes.Structure):
    _fields_ = _s([("primaryViewConfigurationType", ctypes.c_int32)])


class FrameState(ctypes.Structure):
    _fields_ = _s([("predictedDisplayTime", ctypes.c_int64), ("predictedDisplayPeriod", ctypes.c_int64),
                   ("shouldRender", ctypes.c_uint32)])


class ActiveActionSet(ctypes.Structure):
    _fields_ = [("actionSet", handle_t), ("subactionPath", handle_t)]


class SyncInfo(ctypes.Structure):
    _fields_ = _s([("countActiveActionSets", ctypes.c_uint32), ("activeActionSets", ctypes.POINTER(ActiveActionSet))])


class FrameEndInfo(ctypes.Structure):
    _fields_ = _s([("displayTime", ctypes.c_int64), ("environmentBlendMode", ctypes.c_int32),
                   ("layerCount", ctypes.c_uint32), ("layers", ctypes.c_void_p)])


# mock_control.h's ProxMockXrKey and ProxMockXrVibration.
class MockKey(ctypes.Structure):
    _fields_ = [("time", ctypes.c_int64), ("pose", Posef)]


class MockVibration(ctypes.Structure):
    _fields_ = [("time", ctypes.c_int64), ("stop", ctypes.c_int32), ("amplitude", ctypes.c_float),
                ("duration", ctypes.c_int64), ("frequency", ctypes.c_float), ("result", ctypes.c_int32)]


class Mock:
    """The mock runtime's control panel: the library the loader loads (the
    manifest's library_path), loaded here too: one copy in the process."""

    def __init__(self, manifest):
        with open(manifest, encoding="utf-8") as f:
            self.path = json.load(f)["runtime"]["library_path"]
        self.lib = ctypes.CDLL(self.path)
        self.lib.proxMockXr_Now.restype = ctypes.c_int64
        self.lib.proxMockXr_Vibrations.restype = ctypes.c_int32
        self.lib.proxMockXr_Vibrations.argtypes = [ctypes.POINTER(MockVibration), ctypes.c_int32, ctypes.c_int32]
        self.lib.proxMockXr_SetScript.argtypes = [ctypes.POINTER(MockKey), ctypes.c_int32]
        self.lib.proxMockXr_LocateCalls.restype = ctypes.c_uint64

    def now(self):
        return self.lib.proxMockXr_Now()

    def hold(self, grip):
        """The grip at `grip` ((x, y, z), (w, x, y, z)) from now on."""
        (px, py, pz), (qw, qx, qy, qz) = grip
        key = MockKey(self.now(), Posef(qx, qy, qz, qw, px, py, pz))
        self.lib.proxMockXr_SetScript(ctypes.byref(key), 1)

    def vibrations(self, first=0):
        total = self.lib.proxMockXr_Vibrations(None, 0, 0)
        out = (MockVibration * max(total - first, 1))()
        self.lib.proxMockXr_Vibrations(out, first, total - first)
        return list(out)[: max(total - first, 0)]

    def vibration_count(self):
        return self.lib.proxMockXr_Vibrations(None, 0, 0)


class Loader:
    """libopenxr_loader.so.1 through ctypes: every xr* call the app makes."""

    def __init__(self):
        self.lib = ctypes.CDLL("libopenxr_loader.so.1")
        # What an integrator hands Proxima: the loader's xrGetInstanceProcAddr.
        self.get_instance_proc_addr = ctypes.cast(self.lib.xrGetInstanceProcAddr, ctypes.c_void_p).value

    def __call__(self, name, *args):
        function = getattr(self.lib, name)
        function.restype = ctypes.c_int32
        result = function(*args)
        if result < 0:
            raise RuntimeError(f"{name} failed: XrResult {result}")
        return result


class XrApp:
    def __init__(self, loader, timespec=True):
        self.xr = loader
        self.timespec = timespec
        self.state = 0
        self.running = False
        self.device = None
        xr = self.xr
        names = [b"XR_MND_headless"] + ([b"XR_KHR_convert_timespec_time"] if timespec else [])
        ci = InstanceCreateInfo(type=TYPE["instance"])
        ci.applicationInfo.applicationName = b"proxima-python-tests"
        ci.applicationInfo.apiVersion = 1 << 48  # XR_MAKE_VERSION(1, 0, 0)
        ci.enabledExtensionCount = len(names)
        ci.enabledExtensionNames = (ctypes.c_char_p * len(names))(*names)
        self.instance = handle_t()
        xr("xrCreateInstance", ctypes.byref(ci), ctypes.byref(self.instance))
        self.instance = self.instance.value
        system = ctypes.c_uint64()
        xr("xrGetSystem", handle_t(self.instance), ctypes.byref(SystemGetInfo(TYPE["system"], None, 1)),
           ctypes.byref(system))

        si = ActionSetCreateInfo(type=TYPE["action_set"])
        si.actionSetName, si.localizedActionSetName = b"gameplay", b"Gameplay"
        action_set = handle_t()
        xr("xrCreateActionSet", handle_t(self.instance), ctypes.byref(si), ctypes.byref(action_set))
        self.action_set = action_set.value
        self.right = self.path("/user/hand/right")
        # Proxima's actions in the app's set, and their bindings merged into the app's suggestion.
        self.pose, self.haptic = proxima.xr_create_actions(xr.get_instance_proc_addr, self.instance,
                                                           self.action_set, "proxima")
        profile = "/interaction_profiles/khr/simple_controller"
        ours = proxima.xr_suggested_bindings(xr.get_instance_proc_addr, self.instance, profile, "right",
                                             self.pose, self.haptic)
        bindings = (SuggestedBinding * len(ours))(*[SuggestedBinding(a, b) for a, b in ours])
        suggested = ProfileSuggestedBinding(TYPE["suggested"], None, self.path(profile), len(ours), bindings)
        xr("xrSuggestInteractionProfileBindings", handle_t(self.instance), ctypes.byref(suggested))

        session = handle_t()  # headless (XR_MND_headless): no graphics binding
        xr("xrCreateSession", handle_t(self.instance), ctypes.byref(SessionCreateInfo(TYPE["session"], None, 0,
                                                                                      system.value)),
           ctypes.byref(session))
        self.session = session.value
        ri = ReferenceSpaceCreateInfo(TYPE["reference_space"], None, 2, Posef(qw=1.0))  # LOCAL
        space = handle_t()
        xr("xrCreateReferenceSpace", handle_t(self.session), ctypes.byref(ri), ctypes.byref(space))
        self.local = space.value
        sets = (handle_t * 1)(self.action_set)
        xr("xrAttachSessionActionSets", handle_t(self.session), ctypes.byref(AttachInfo(TYPE["attach"], None, 1,
                                                                                        sets)))

    def path(self, text):
        out = handle_t()
        self.xr("xrStringToPath", handle_t(self.instance), text.encode(), ctypes.byref(out))
        return out.value

    def device_settings(self):
        """create_xr_device's OpenXR arguments for this app's right hand."""
        return dict(get_instance_proc_addr=self.xr.get_instance_proc_addr, instance=self.instance,
                    session=self.session, base_space=self.local, pose_action=self.pose, haptic_action=self.haptic,
                    subaction_path=self.right, session_state=self.state, timespec_time=self.timespec)

    def frame(self):
        """Polls events (forwarding states to the device), then, while the
        session runs, one frame: wait, begin, sync, on_frame, end."""
        xr = self.xr
        while True:
            event = EventBuffer(TYPE["event_buffer"])
            if xr("xrPollEvent", handle_t(self.instance), ctypes.byref(event)) == XR_EVENT_UNAVAILABLE:
                break
            if event.type != TYPE["state_changed"]:
                continue
            changed = ctypes.cast(ctypes.byref(event), ctypes.POINTER(SessionStateChanged)).contents
            self.state = changed.state
            if self.device is not None:
                self.device.on_session_state(self.state)
                if changed.time > 0:
                    self.device.on_runtime_time(changed.time)
            if STATES.get(self.state) == "ready":
                xr("xrBeginSession", handle_t(self.session), ctypes.byref(SessionBeginInfo(TYPE["begin"], None, 2)))
                self.running = True
            elif STATES.get(self.state) == "stopping":
                xr("xrEndSession", handle_t(self.session))
                self.running = False
        if not self.running:
            time.sleep(0.01)
            return
        fs = FrameState(TYPE["frame_state"])
        xr("xrWaitFrame", handle_t(self.session), None, ctypes.byref(fs))
        xr("xrBeginFrame", handle_t(self.session), None)
        active = ActiveActionSet(self.action_set, 0)
        xr("xrSyncActions", handle_t(self.session), ctypes.byref(SyncInfo(TYPE["sync"], None, 1,
                                                                          ctypes.pointer(active))))
        if self.device is not None:
            self.device.on_frame(fs.predictedDisplayTime, fs.predictedDisplayPeriod)
        end = FrameEndInfo(TYPE["frame_end"], None, fs.predictedDisplayTime, 1, 0, None)  # OPAQUE, no layers
        xr("xrEndFrame", handle_t(self.session), ctypes.byref(end))

    def pump_until(self, done, seconds=20.0):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            self.frame()
            if done():
                return True
        return False

    def pump_for(self, seconds):
        self.pump_until(lambda: False, seconds)

    def destroy(self):
        if not self.instance:
            return
        self.xr("xrDestroySpace", handle_t(self.local))
        self.xr("xrDestroySession", handle_t(self.session))
        self.xr("xrDestroyActionSet", handle_t(self.action_set))
        self.xr("xrDestroyInstance", handle_t(self.instance))
        self.instance = 0


def validation_log_errors(path, start):
    """What the core validation layer wrote from byte `start` on, when it
    raised an error there; else ""."""
    if not os.path.exists(path):
        return ""
    with open(path, encoding="utf-8", errors="replace") as f:
        f.seek(start)
        text = f.read()
    return text if "VALID_ERROR" in text else ""
