"""The proxima tool with HID devices emulated from the real descriptors, run by ctest:

    python3 hid_cli_test.py PATH_TO_PROXIMA PATH_TO_PROXIMA_HID_EMULATE PATH_TO_SHARED_ASSETS

proxima_hid_emulate (tests/hid/hid_emulate.cpp) plugs the devices in, feeds
the reports given, runs proxima and records what each device was written.
The reports are built here from the layouts in the shared devices folder.
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

PROXIMA = EMULATE = None

DEVICES = {  # name: (vid:pid, profile, usage, interface)
    "spacenavigator": ("046d:c626", "spacemouse-split", 0x08, 0),
    "spacemouse_wireless": ("256f:c62e", "spacemouse", 0x08, 0),
    "ds4v2": ("054c:09cc", "dualshock4", 0x05, 3),
    "dualsense": ("054c:0ce6", "dualsense", 0x05, 3),
}


def le16(v):
    return (v & 0xFFFF).to_bytes(2, "little")


def pad(name, lx=128, ly=128, rx=128, ry=128):
    """A pad's input report 0x01 (64 bytes), nothing pressed."""
    b = bytearray(64)
    b[0], b[1], b[2], b[3], b[4] = 1, lx, ly, rx, ry
    b[5 if name == "ds4v2" else 8] = 0x08  # hat released
    return b.hex()


def puck(name, x=0, y=0, z=0):
    """Translation: report 1 of the split layout (7 bytes) or of the combined one (13)."""
    if name == "spacenavigator":
        return (b"\x01" + le16(x) + le16(y) + le16(z)).hex()
    return (b"\x01" + le16(x) + le16(y) + le16(z) + bytes(6)).hex()


# The force-feedback sticks: (vid:pid, the stick's report size and where
# its X is, PROTOCOL.md's reset, stop-all and enable bytes, Block Load's id).
PID = {
    "openffboard": ("1209:ffb0", 25, 9, ["0c08", "0c08", "0c04", "0c01"], 0x12),
    "arduino_ffb": ("2341:8036", 10, 2, ["0c04", "0c04", "0c03", "0c01"], 0x06),
}


def stick(name, x):
    """The stick's input report 0x01 with X at x in [-1, 1] of its travel."""
    _, size, at, _, _ = PID[name]
    b = bytearray(size)
    b[0] = 1
    b[at:at + 2] = le16(round(x * 32767))
    return b.hex()


def left(name):
    """Full deflection towards -x (the default scene's A)."""
    return pad(name, lx=0) if name in ("ds4v2", "dualsense") else puck(name, x=-350)


def rest(name):
    return pad(name) if name in ("ds4v2", "dualsense") else puck(name)


class HidCliTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def emulate(self, devices, sends, *command, after_output=()):
        record = os.path.join(self.dir.name, "record.json")
        args = [EMULATE]
        for d in devices:
            args += ["--device", d]
        for device, seconds, report in sends:
            args += ["--send", str(device), str(seconds), report]
        for device, report in after_output:
            args += ["--send-after-output", str(device), report]
        r = subprocess.run(args + ["--record", record, "--", PROXIMA, *command], capture_output=True, text=True,
                           timeout=240)
        with open(record) as f:
            return r, json.load(f)["devices"]

    def test_devices_lists_every_profile(self):
        out = os.path.join(self.dir.name, "devices.json")
        names = list(DEVICES)
        r, _ = self.emulate(names, [], "devices", "--json", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(out) as f:
            listed = json.load(f)["devices"]
        self.assertEqual(len(listed), 4, "one entry a device: the SpaceNavigator's vendor collections are left out")
        for i, (name, d) in enumerate(zip(names, listed)):
            ids, profile, usage, interface = DEVICES[name]
            self.assertEqual(f"{d['vendor_id']}:{d['product_id']}", ids)
            self.assertEqual(d["profile"], profile)
            self.assertEqual(d["path"], f"/dev/hidraw{i}")
            self.assertEqual((d["usage_page"], d["usage"], d["interface"]), (1, usage, interface))
            self.assertIn(f"{ids}  {profile}", r.stdout)
            self.assertIn(f"/dev/hidraw{i}", r.stdout)

    def test_devices_lists_the_force_feedback_sticks(self):
        out = os.path.join(self.dir.name, "devices.json")
        r, _ = self.emulate(list(PID) + ["openffboard_1axis"], [], "devices", "--json", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(out) as f:
            listed = json.load(f)["devices"]
        self.assertEqual([d["profile"] for d in listed], ["pid-joystick", "pid-joystick", "pid-wheel"])
        self.assertEqual([f"{d['vendor_id']}:{d['product_id']}" for d in listed],
                         [PID["openffboard"][0], PID["arduino_ffb"][0], "1209:ffb0"])
        self.assertIn("pid-wheel", r.stdout)

    def test_devices_with_none_present(self):
        r, _ = self.emulate([], [], "devices")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("no supported HID devices found", r.stdout)

    def test_run_drives_the_tool_and_feels_the_contact(self):
        # Path T's start is 5 cm from A; full deflection is 0.1 m/s towards
        # it: about 0.5 s reaches contact. The stick is let go once the
        # device is written its first output (the contact felt), not after a
        # fixed time, which a busy machine's device thread integrates short
        # of contact; then the tool is held there.
        for name in DEVICES:
            with self.subTest(name):
                ids = DEVICES[name][0]
                out = os.path.join(self.dir.name, name + ".json")
                r, record = self.emulate([name], [(0, 0, left(name))], "run", "--device", "hid:" + ids,
                                         "--seconds", "2", "--hold", "0.5", "--json", out,
                                         after_output=[(0, rest(name))])
                self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
                self.assertNotIn("before every report was sent", r.stderr, "no output: the contact never came")
                self.assertIn("device: HID " + DEVICES[name][1], r.stdout)
                with open(out) as f:
                    report = json.load(f)
                hid = report["hid"]
                self.assertEqual(hid["profile"], DEVICES[name][1])
                self.assertGreaterEqual(hid["reports_read"], 2)
                self.assertEqual(hid["malformed"], 0)
                self.assertEqual(hid["failed_writes"], 0)
                first, last = hid["first_pose"], hid["last_pose"]
                self.assertLess(last[0], first[0] - 0.01, "the tool moved towards A")
                self.assertEqual(last[1:3], [0, 0])
                self.assertGreater(report["device"]["max_force"], 0.0, "the contact was felt")
                writes = record[0]["writes"]
                # The stats are read before the device is closed: it may write once more.
                self.assertIn(len(writes) - hid["outputs_written"], (0, 1))
                self.assertGreaterEqual(len(writes), 1)
                if name == "dualsense":
                    self.assertGreater(max(int(w[6:8], 16) for w in writes), 0, "rumble")
                    self.assertTrue(any(w[22:24] == "01" for w in writes), "trigger resistance")
                    self.assertEqual(record[0]["feature_requests"], [5])
                elif name == "ds4v2":
                    self.assertGreater(max(int(w[10:12], 16) for w in writes), 0, "rumble")
                    self.assertEqual(record[0]["feature_requests"], [2])
                else:
                    self.assertIn("0401", writes, "the LED lit in contact")

    def test_run_drives_a_force_feedback_stick_into_contact(self):
        # Position control: the stick at -0.55 of its travel (0.1 m at full
        # deflection) puts the tool 5.5 cm towards A, within the 5 mm cutoff
        # of it (the bunnies' closest points are not along x alone).
        for name, (ids, _, _, opening, block_load) in PID.items():
            with self.subTest(name):
                out = os.path.join(self.dir.name, name + ".json")
                r, record = self.emulate([name], [(0, 0, stick(name, -0.55))], "run", "--device", "hid:" + ids,
                                         "--seconds", "1.0", "--hold", "0.5", "--json", out)
                self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
                self.assertIn("device: HID pid-joystick", r.stdout)
                self.assertIn("force feedback: 1 effects created", r.stdout)
                with open(out) as f:
                    report = json.load(f)
                hid = report["hid"]
                self.assertEqual(hid["profile"], "pid-joystick")
                self.assertGreaterEqual(hid["reports_read"], 1)
                self.assertEqual((hid["malformed"], hid["failed_writes"]), (0, 0))
                self.assertEqual(hid["effects_created"], 1)
                self.assertEqual(hid["force_effect"], "playing")
                self.assertGreater(hid["force_updates"], 0)
                self.assertGreater(hid["max_force_magnitude"], 0.0, "the contact was pushed back")
                self.assertLessEqual(hid["max_force_magnitude"], 1.0)
                first, last = hid["first_pose"], hid["last_pose"]
                self.assertAlmostEqual(last[0], first[0] - 0.055, delta=1e-4)
                self.assertGreater(report["device"]["max_force"], 0.0)
                writes = record[0]["writes"]
                self.assertEqual(writes[:4], opening)
                self.assertIn(block_load, record[0]["feature_requests"])
                forces = [w for w in writes if w.startswith("0501") and len(w) == 8]
                self.assertTrue(any(w != "05010000" for w in forces), "a constant force was sent")
                # Closed at the end: the effect stopped and freed, everything stopped.
                self.assertEqual(writes[-4:-1], ["0a010301", "0b01", opening[2]])

    def test_run_refuses_what_is_not_there(self):
        r, _ = self.emulate(["ds4v2"], [], "run", "--device", "hid:256f:c62e", "--seconds", "0.1")
        self.assertEqual(r.returncode, 1)
        self.assertIn("256f:c62e", r.stderr)
        r, _ = self.emulate([], [], "run", "--device", "hid:zz:12", "--seconds", "0.1")
        self.assertEqual(r.returncode, 1)
        self.assertIn("hid:VVVV:PPPP", r.stderr)


if __name__ == "__main__":
    PROXIMA, EMULATE = sys.argv[1], sys.argv[2]
    os.environ.setdefault("PROXIMA_ASSETS", sys.argv[3])
    unittest.main(argv=sys.argv[:1])
