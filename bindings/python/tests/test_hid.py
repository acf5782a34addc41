"""HID devices from Python on an emulated DualSense: real hidapi in
libproxima on hidraw nodes that umockdev makes from the device's real report
descriptor (tests/hid/emulated_hid.h). The emulator, proxima_hid_emulate,
runs a child Python with the device plugged in and one report queued (the
left stick fully left); the child drives the binding and prints what it saw.

The emulator's path comes from PROXIMA_HID_EMULATE (scripts/test.sh sets it);
without it these tests fail, naming the variable."""

import json
import os
import subprocess
import sys

import pytest

import proxima
from proxima import _devices

# A DualSense USB input report: id 1, left stick x 0 (fully left), the other
# axes centred, the d-pad released (8).
STICK_LEFT = bytes([1, 0, 128, 128, 128, 0, 0, 0, 8] + [0] * 55).hex()

CHILD = r"""
import json, time
import proxima

found = proxima.enumerate_hid_devices()
start = ((0.3, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))
out = {"found": [d._asdict() for d in found]}
with proxima.World() as world:
    cube = world.create_mesh(*CUBE)
    world.create_body(cube, "static")
    tool = world.create_body(cube, "tool", pose=start)
    pad = world.create_hid_device(found[0], initial_pose=start)
    out["valid"] = pad.valid
    tool.set_device(pad)
    world.start_threads()
    # The queued report is read once the device is open; from then on the
    # held stick moves the tool at 0.1 m/s. Wait on what happened, with a
    # bound only against a hang.
    deadline = time.monotonic() + 120
    while (pad.stats.reports_read < 1 or tool.pose[0][0] > 0.295) and time.monotonic() < deadline:
        time.sleep(0.005)
    moved = tool.pose[0]
    world.stop_threads()
    stats = pad.stats
    out["stats"] = {"reports_read": stats.reports_read, "malformed": stats.malformed,
                    "connected": stats.connected, "profile": stats.profile, "pose_reads": stats.pose_reads}
    out["tool"] = moved.tolist()
    out["device_pose"] = pad.pose[0].tolist()
    pad.destroy()
    out["valid_after_destroy"] = pad.valid
    try:
        pad.stats
    except proxima.InvalidHandle:
        out["stats_after_destroy"] = "InvalidHandle"
    try:
        world.open_hid_device("/dev/hidraw9")
    except proxima.FileError as e:
        out["missing_node"] = "FileError"
print("RESULT " + json.dumps(out))
"""

CUBE = ([[x, y, z] for x in (-0.05, 0.05) for y in (-0.05, 0.05) for z in (-0.05, 0.05)],
        [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
         [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])


@pytest.fixture(scope="module")
def emulate():
    path = os.environ.get("PROXIMA_HID_EMULATE")
    assert path and os.access(path, os.X_OK), (
        "PROXIMA_HID_EMULATE must name the HID emulator (build/release/tests/hid/proxima_hid_emulate: "
        "cmake --build build/release --target proxima_hid_emulate)")
    return path


@pytest.fixture(scope="module")
def child_run(emulate):
    code = f"CUBE = {CUBE!r}\n" + CHILD
    r = subprocess.run([emulate, "--device", "dualsense", "--send", "0", "0", STICK_LEFT, "--",
                        sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    lines = [line for line in r.stdout.splitlines() if line.startswith("RESULT ")]
    assert lines, r.stdout + r.stderr
    return json.loads(lines[-1][len("RESULT "):])


def test_enumerate_finds_the_emulated_dualsense(child_run):
    (found,) = child_run["found"]
    assert found["profile"] == "dualsense"
    assert (found["vendor_id"], found["product_id"]) == (0x054C, 0x0CE6)
    assert found["path"].startswith("/dev/hidraw")
    assert found["name"]


def test_the_stick_moves_a_tool_the_device_holds(child_run):
    stats = child_run["stats"]
    assert child_run["valid"]
    assert stats["reports_read"] == 1
    assert stats["malformed"] == 0
    assert stats["connected"] is True
    assert stats["profile"] == "dualsense"
    assert stats["pose_reads"] > 0
    x, y, z = child_run["tool"]
    assert x < 0.295, "the tool moved left"
    assert (y, z) == (0.0, 0.0)
    assert child_run["device_pose"][0] < 0.295


def test_destroy_and_a_missing_node(child_run):
    assert child_run["valid_after_destroy"] is False
    assert child_run["stats_after_destroy"] == "InvalidHandle"
    assert child_run["missing_node"] == "FileError"


def test_a_library_without_hid_says_which_option_is_missing():
    # cffi's ABI mode finds a function missing only when it is first used: a
    # library built without PROX_WITH_HIDAPI lacks proxima_hid.h's.
    with pytest.raises(proxima.Unsupported, match="PROX_WITH_HIDAPI"):
        _devices.hid_function("proxHidDevice_NotInAnyLibrary")


def test_set_device_takes_a_hid_device_of_its_own_world_only(world):
    other = proxima.World()
    try:
        # A null id of the other world's: set_device must refuse it before the C API sees it.
        pad = _devices.HidDevice(other, _devices.ffi.new("proxHidDeviceId*"))
        tool = world.create_body(world.create_mesh(*CUBE), "tool")
        with pytest.raises(proxima.InvalidArgument, match="another world"):
            tool.set_device(pad)
    finally:
        other.close()


def test_no_device_plugged_in_is_a_file_error(world):
    # Outside the emulator: this machine's own HID devices are not
    # predictable, so only a path that cannot be one.
    with pytest.raises(proxima.FileError):
        world.open_hid_device("/nonexistent/hidraw")
    with pytest.raises(proxima.FileError):
        world.create_hid_device("/nonexistent/hidraw")
