"""The viewer driven by an emulated DualSense (--device hid, and auto picking
it), headless on the CPU driver, run by ctest:

    python3 viewer_hid_test.py PATH_TO_PROXIMA_VIEWER PATH_TO_PROXIMA_HID_EMULATE

The left stick held fully left for 0.3 s moves the built-in scene's tool
(path T's start, 5 cm from A) towards A at 0.1 m/s: about 3 cm.
"""
import os
import re
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "viewer"))
import sanitizers  # noqa: E402

VIEWER = EMULATE = None
START_X = 0.194895  # path T's far end in the built-in scene (proxima run prints it)


def pad(lx):
    b = bytearray(64)
    b[0], b[1], b[2], b[3], b[4], b[8] = 1, lx, 128, 128, 128, 0x08
    return b.hex()


def stick(x):
    """OpenFFBoard's input report 0x01 (25 bytes) with its X at x of its travel."""
    b = bytearray(25)
    b[0] = 1
    b[9:11] = (round(x * 32767) & 0xFFFF).to_bytes(2, "little")
    return b.hex()


def emulate(devices, sends, *viewer_args):
    args = [EMULATE]
    for d in devices:
        args += ["--device", d]
    for device, seconds, report in sends:
        args += ["--send", str(device), str(seconds), report]
    return subprocess.run(args + ["--", VIEWER, *viewer_args], capture_output=True, text=True, timeout=300,
                          env=sanitizers.environment(VIEWER))


class ViewerHidTest(unittest.TestCase):
    def test_auto_picks_the_hid_device_and_it_moves_the_tool(self):
        for device in ("auto", "hid"):
            with self.subTest(device):
                # 40 frames: the viewer is still running when the release comes
                # at 0.3 s, even where the emulator is slow to send it.
                r = emulate(["dualsense"], [(0, 0, pad(0)), (0, 0.3, pad(128))], "--headless", "--validation",
                            "--device", device, "--frames", "40", "--size", "320x180")
                self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
                m = re.search(r"hid device: (\d+) reports read, (\d+) malformed, \d+ outputs written, tool at "
                              r"(\S+) (\S+) ([^\s,]+)", r.stdout)
                self.assertIsNotNone(m, r.stdout)
                self.assertEqual(int(m.group(1)), 2)
                self.assertEqual(int(m.group(2)), 0)
                x, y, z = (float(m.group(i)) for i in (3, 4, 5))
                self.assertLess(x, START_X - 0.015)
                self.assertGreater(x, START_X - 0.05)
                self.assertEqual((y, z), (0.0, 0.0))

    def test_a_force_feedback_stick_holds_the_tool_where_it_is(self):
        # Position control: the stick at -0.3 of its 0.1 m travel puts the
        # tool 3 cm towards A, and keeps it there.
        r = emulate(["openffboard"], [(0, 0, stick(-0.3))], "--headless", "--validation", "--device", "hid",
                    "--frames", "20", "--size", "320x180")
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        m = re.search(r"hid device: (\d+) reports read, (\d+) malformed, \d+ outputs written, tool at "
                      r"(\S+) (\S+) ([^\s,]+)", r.stdout)
        self.assertIsNotNone(m, r.stdout)
        self.assertEqual((int(m.group(1)), int(m.group(2))), (1, 0))
        x, y, z = (float(m.group(i)) for i in (3, 4, 5))
        self.assertAlmostEqual(x, START_X - 0.03, delta=1e-4)
        self.assertEqual((y, z), (0.0, 0.0))

    def test_hid_with_nothing_plugged_in_is_refused(self):
        r = emulate([], [], "--headless", "--device", "hid", "--frames", "1", "--size", "320x180")
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("no supported HID device", r.stderr)


if __name__ == "__main__":
    VIEWER, EMULATE = sys.argv[1], sys.argv[2]
    unittest.main(argv=sys.argv[:1])
