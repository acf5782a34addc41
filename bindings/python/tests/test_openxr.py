"""The OpenXR device from Python, end to end: an app (xr_app.py, ctypes)
makes its instance, session and actions through the real OpenXR loader,
with the core validation layer, on the mock runtime of tests/openxr; it
hands them to proxima, whose device thread locates the mock's scripted grip
(the tool follows) and sends the contact force back as vibration (the mock
logs it).

The mock's manifest comes from PROXIMA_XR_RUNTIME_JSON (scripts/test.sh sets
it to the release build's tests/openxr/mock_runtime.json); without it these
tests fail, naming the variable."""

import os

import numpy as np
import pytest

import proxima
from proxima import _xr

from conftest import BUNNY
from xr_app import Loader, Mock, XrApp, validation_log_errors


@pytest.fixture(scope="module")
def xr(tmp_path_factory):
    manifest = os.environ.get("PROXIMA_XR_RUNTIME_JSON")
    assert manifest and os.path.isfile(manifest), (
        "PROXIMA_XR_RUNTIME_JSON must name the mock OpenXR runtime's manifest "
        "(build/release/tests/openxr/mock_runtime.json: cmake --build build/release "
        "--target proxima_mock_openxr_runtime)")
    # As a user's environment tells the loader: the runtime, and the core
    # validation layer, whose log the process keeps (it reads where once).
    log = str(tmp_path_factory.mktemp("xr") / "validation.txt")
    os.environ.update({"XR_RUNTIME_JSON": manifest, "XR_ENABLE_API_LAYERS": "XR_APILAYER_LUNARG_core_validation",
                       "XR_CORE_VALIDATION_EXPORT_TYPE": "text", "XR_CORE_VALIDATION_FILE_NAME": log})
    mock = Mock(manifest)  # loaded before the loader loads it: one copy
    return Loader(), mock, log


@pytest.fixture
def app(xr):
    loader, _, _ = xr
    a = XrApp(loader)
    assert a.pump_until(lambda: a.state == 5), "the session never became FOCUSED"
    yield a
    a.destroy()


def _q(axis, degrees):
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    h = np.radians(degrees) / 2
    return np.concatenate([[np.cos(h)], np.sin(h) * axis])


def _qmul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return np.array([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2])


def _rotate(q, v):
    return _qmul(_qmul(q, np.concatenate([[0.0], v])), q * [1, -1, -1, -1])[1:]


def _compose(a, b):  # pose a * pose b
    return a[0] + _rotate(a[1], b[0]), _qmul(a[1], b[1])


def _inverse(a):
    c = a[1] * [1, -1, -1, -1]
    return -_rotate(c, a[0]), c


class Scene:
    """A static bunny and a tool bunny; OpenXR's world turned and moved in
    Proxima's (base_to_world), the tool offset in the grip (tool_in_grip), so
    that a frame mixed up anywhere puts the tool elsewhere."""

    base_to_world = (np.array([0.3, -1.2, 0.1]), _q([0, 1, 0], 90))
    tool_in_grip = (np.array([0.02, 0.0, -0.05]), _q([1, 0, 0], 30))

    def __init__(self, world):
        self.world = world
        mesh = world.load_mesh(BUNNY)
        info = mesh.info
        self.width = info.bounds_max[0] - info.bounds_min[0]
        world.create_body(mesh, "static")
        self.tool = world.create_body(mesh, "tool", pose=self.far())

    def far(self):
        return np.array([1.6 * self.width, 0, 0]), np.array([1.0, 0, 0, 0])

    def near(self):  # a few mm from the rock: in contact
        return np.array([0.9 * self.width, 0, 0]), np.array([1.0, 0, 0, 0])

    def grip_for(self, tool):
        return _compose(_compose(_inverse(self.base_to_world), tool), _inverse(self.tool_in_grip))

    def error(self, expected):
        position, q = self.tool.pose
        angle = 2 * np.arccos(min(1.0, abs(float(np.dot(q, expected[1])))))
        return max(float(np.linalg.norm(position - expected[0])), angle)

    def device(self, app, **settings):
        device = self.world.create_xr_device(**{**app.device_settings(), "base_to_world": self.base_to_world,
                                                "tool_in_grip": self.tool_in_grip, "force_for_full_amplitude": 1.0,
                                                **settings})
        app.device = device
        self.tool.set_device(device)
        self.world.start_threads()
        return device


@pytest.mark.parametrize("pose_mode", ["locate_each_tick", "extrapolate_frame"])
def test_the_grip_moves_the_tool_and_contact_vibrates(xr, app, pose_mode):
    _, mock, log = xr
    log_start = os.path.getsize(log) if os.path.exists(log) else 0
    with proxima.World() as world:
        scene = Scene(world)
        mock.hold(scene.grip_for(scene.far()))
        device = scene.device(app, pose_mode=pose_mode)
        assert device.valid

        # The tool follows the grip to a turned, moved pose (floats: 1e-6).
        target = _compose(scene.far(), (np.array([0.05, -0.02, 0.03]), _q([1, 1, 0], -40)))
        mock.hold(scene.grip_for(target))
        assert app.pump_until(lambda: scene.error(target) < 1e-5, 10.0), f"{scene.error(target)} m off"
        app.pump_for(0.1)
        assert scene.error(target) < 1e-5, "and stays there"
        far = device.stats
        assert far.poses_pushed > 0 and far.locates > 0
        assert far.session_state == "focused"
        assert far.time_source == "timespec"
        assert far.vibrations_sent == 0, "vibrations while far from anything"

        # Into contact: the force comes back as vibration.
        before = mock.vibration_count()
        mock.hold(scene.grip_for(scene.near()))
        assert app.pump_until(lambda: np.linalg.norm(scene.tool.wrench()[0]) > 0
                              and mock.vibration_count() > before + 5), "no vibration in contact"
        sent = mock.vibrations(before)
        assert all(not v.stop and v.result == 0 and 0 < v.amplitude <= 1 for v in sent)
        assert all(v.duration == 20_000_000 for v in sent), "the default pulse_duration, 0.02 s"
        stats = device.stats
        assert stats.vibrations_sent >= len(sent) > 5
        assert 0 < stats.last_amplitude <= 1

        # Out of contact again: the vibration is stopped.
        mock.hold(scene.grip_for(scene.far()))
        assert app.pump_until(lambda: mock.vibrations(before)[-1].stop), "no xrStopHapticFeedback"
        world.stop_threads()
        device.destroy()
        assert not device.valid
    app.destroy()
    assert validation_log_errors(log, log_start) == ""


def test_the_validation_layer_is_on(xr, app):
    # Else the other tests' "no validation error" would hold vacuously.
    import ctypes
    loader, _, log = xr
    start = os.path.getsize(log) if os.path.exists(log) else 0
    location = (ctypes.c_uint8 * 64)()  # an XrSpaceLocation whose type is 0: wrong on purpose
    locate = loader.lib.xrLocateSpace
    locate.restype = ctypes.c_int32
    assert locate(ctypes.c_uint64(app.local), ctypes.c_uint64(app.local), ctypes.c_int64(1000), location) == -1
    app.destroy()
    assert "VUID-XrSpaceLocation-type-type" in validation_log_errors(log, start)


def test_focus_loss_is_forwarded(xr, app):
    _, mock, _ = xr
    with proxima.World() as world:
        scene = Scene(world)
        mock.hold(scene.grip_for(scene.far()))
        device = scene.device(app, session_state="focused")
        app.pump_for(0.2)
        mock.lib.proxMockXr_SetFocused(0)
        try:
            assert app.pump_until(lambda: app.state == 4)  # VISIBLE, polled and forwarded
            ticks = device.stats.not_focused_ticks
            app.pump_for(0.1)
            assert device.stats.session_state == "visible"
            assert device.stats.not_focused_ticks > ticks
        finally:
            mock.lib.proxMockXr_SetFocused(1)  # the mock outlives the test
        assert app.pump_until(lambda: device.stats.session_state == "focused")
        device.destroy()


def test_a_destroyed_device_refuses_calls(xr, app):
    with proxima.World() as world:
        scene = Scene(world)
        device = scene.device(app)
        device.destroy()
        assert not device.valid
        for call in (lambda: device.stats, lambda: device.on_frame(1, 1), lambda: device.on_runtime_time(1),
                     lambda: device.on_session_state("focused"), device.destroy,
                     lambda: scene.tool.set_device(device)):
            with pytest.raises(proxima.InvalidHandle, match="live XR device"):
                call()
    # Its world closed: the device went with it.
    assert not device.valid


def test_bad_handles_and_settings_are_refused(xr, app):
    loader = xr[0]
    with proxima.World() as world:
        good = app.device_settings()

        def refused(error, words, **changes):
            with pytest.raises(error, match=words):
                world.create_xr_device(**{**good, **changes})

        refused(proxima.InvalidArgument, "session", session=0)
        refused(proxima.InvalidArgument, "pose_action must be an OpenXR handle", pose_action="grip")
        refused(proxima.InvalidArgument, "64-bit", instance=-1)
        refused(proxima.InvalidArgument, "get_instance_proc_addr must be xrGetInstanceProcAddr",
                get_instance_proc_addr="xrGetInstanceProcAddr")
        refused(proxima.InvalidArgument, "getInstanceProcAddr", get_instance_proc_addr=0)
        # A vibration action where the pose action belongs: the runtime refuses its space.
        refused(proxima.InvalidArgument, "xrCreateActionSpace", pose_action=app.haptic)
        refused(proxima.InvalidArgument, "pose_mode must be one of 'locate_each_tick', 'extrapolate_frame'",
                pose_mode="guess")
        refused(proxima.InvalidArgument, "unknown setting 'vibration_hz'", vibration_hz=50)
        refused(proxima.InvalidArgument, "vibrationRate", vibration_rate=0.0)
        refused(proxima.InvalidArgument, "session_state must be an XrSessionState", session_state="awake")
        with pytest.raises(TypeError):
            world.create_xr_device(instance=app.instance)  # the handles are required

        # The forms an app may hold xrGetInstanceProcAddr and handles in.
        import ctypes
        gipa = ctypes.cast(loader.lib.xrGetInstanceProcAddr, ctypes.c_void_p)
        device = world.create_xr_device(**{**good, "get_instance_proc_addr": loader.lib.xrGetInstanceProcAddr,
                                           "session": ctypes.c_void_p(app.session)})
        device.destroy()
        device = world.create_xr_device(**{**good, "get_instance_proc_addr": _xr.ffi.cast("void*", gipa.value),
                                           "instance": ctypes.c_uint64(app.instance)})
        with pytest.raises(proxima.InvalidArgument, match="XrSessionState"):
            device.on_session_state(99)
        with pytest.raises(proxima.InvalidArgument, match="predictedDisplayTime"):
            device.on_frame(0, 1)
        with pytest.raises(proxima.InvalidArgument, match="on_frame: predicted_display_time must be an integer"):
            device.on_frame(1.5, 1)
        device.destroy()

    other = proxima.World()
    try:
        # A device of another world's: set_device refuses it before the C API sees it.
        foreign = _xr.XrDevice(other, _xr.ffi.new("proxXrDeviceId*"))
        with proxima.World() as world:
            tool = world.create_body(world.load_mesh(BUNNY), "tool")
            with pytest.raises(proxima.InvalidArgument, match="another world"):
                tool.set_device(foreign)
    finally:
        other.close()


def test_action_helpers(xr, app):
    gipa = xr[0].get_instance_proc_addr
    right = app.path("/user/hand/right/input/grip/pose")
    bindings = proxima.xr_suggested_bindings(gipa, app.instance, "/interaction_profiles/khr/simple_controller",
                                             "/user/hand/right", app.pose, app.haptic)
    assert (app.pose, right) in bindings
    assert (app.haptic, app.path("/user/hand/right/output/haptic")) in bindings
    assert len(bindings) == 2
    no_haptic = proxima.xr_suggested_bindings(gipa, app.instance, "/interaction_profiles/khr/simple_controller",
                                              "right", app.pose)
    assert no_haptic == [(app.pose, right)]
    with pytest.raises(proxima.Unsupported, match="/interaction_profiles/acme/glove"):
        proxima.xr_suggested_bindings(gipa, app.instance, "/interaction_profiles/acme/glove", "right", app.pose)
    with pytest.raises(proxima.InvalidArgument, match="hand must be a str"):
        proxima.xr_suggested_bindings(gipa, app.instance, "/interaction_profiles/khr/simple_controller", 1, app.pose)
    # The app's set is attached already: the runtime refuses new actions.
    with pytest.raises(proxima.InvalidArgument, match="xrCreateAction"):
        proxima.xr_create_actions(gipa, app.instance, app.action_set, "late")


def test_a_library_without_openxr_says_which_option_is_missing():
    # cffi's ABI mode finds a function missing only when it is first used: a
    # library built without PROX_WITH_OPENXR lacks proxima_openxr.h's.
    with pytest.raises(proxima.Unsupported, match="PROX_WITH_OPENXR"):
        _xr.xr_function("proxXrDevice_NotInAnyLibrary")


def test_the_defaults_are_the_headers():
    from proxima._core import ffi
    d = _xr.xr_function("proxDefaultXrDeviceDef")()
    assert (d.vibrationRate, d.forceForFullAmplitude, d.tickRate, d.pulseDuration) == (100.0, 5.0, 1000.0, 0.02)
    assert d.sessionState == 5 and d.poseMode == 0
    assert ffi.sizeof("proxXrDeviceDef") == ffi.sizeof(d)
