"""The windowed path of proxima-viewer under Xvfb: a swapchain on the CPU
Vulkan driver, frames presented with the validation layers on, and a
screenshot of the X screen (`xwd -root`) compared with the headless frame
of the same scene. Run by ctest:

    python3 window_test.py PATH_TO_PROXIMA_VIEWER PATH_TO_SHARED_ASSETS

Then a left-drag in the window (xdotool) must orbit the camera: a second
screenshot shows the scene from elsewhere, and after a resize the window
is drawn whole at its new size. And with --device mouse, a
right-drag moves the tool through the streamed device, along the view's
right axis, and the M key switches the method. Under umockdev an emulated
Xbox 360 pad (gamepad.py) with its left stick held right is found by
--device auto and moves the tool the same way; without one, --device
gamepad is refused.

Needs xvfb-run, xauth, xwd and xdotool (Debian: xvfb, xauth, x11-apps,
xdotool).
"""
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gamepad  # noqa: E402
import png  # noqa: E402
import sanitizers  # noqa: E402
import xwd  # noqa: E402

VIEWER = None
VALIDATION = r"validation (error|warning|message)"  # what the viewer prints for one
ASSETS = None
SIZE = (480, 270)
SCREEN = "640x480x24"
RESIZED = (600, 400)


def scene_args():
    bunny = os.path.join(ASSETS, "bunny.obj")
    # The surfaces cross (polylines) and touch nearby (strings); the HUD is
    # left out, as its frame-time bar differs from run to run.
    return [bunny, bunny, "--pose-b", "0.1", "0", "0", "1", "0", "0", "0", "--size", f"{SIZE[0]}x{SIZE[1]}",
            "--show", "meshes,strings,polylines,force,grid", "--validation"]


def drag(button, dx):
    """A drag of dx pixels to the right across the window's middle, in 8 steps."""
    x, y = SIZE[0] // 2, SIZE[1] // 2
    subprocess.run(["xdotool", "mousemove", str(x), str(y), "mousedown", button], check=True, timeout=60)
    for step in range(1, 9):
        time.sleep(0.05)
        subprocess.run(["xdotool", "mousemove", str(x + dx * step // 8), str(y)], check=True, timeout=60)
    subprocess.run(["xdotool", "mouseup", button], check=True, timeout=60)


def mouse_args():
    bunny = os.path.join(ASSETS, "bunny.obj")
    return [bunny, bunny, "--pose-b", "0.3", "0", "0", "1", "0", "0", "0", "--size", f"{SIZE[0]}x{SIZE[1]}",
            "--show", "meshes,grid", "--validation"]


def capture_mouse(out_dir):
    """Inside Xvfb: the mouse device; right-drag the tool, quit, keep what the viewer said."""
    viewer = subprocess.Popen([VIEWER, *mouse_args(), "--device", "mouse"], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, env=sanitizers.environment(VIEWER))
    line = viewer.stdout.readline()
    if "presenting" in line:
        time.sleep(0.5)
        drag("3", 80)
        time.sleep(0.5)
        subprocess.run(["xdotool", "key", "m"], check=True, timeout=60)  # the method: rebuilds the world
        time.sleep(1.0)
    viewer.send_signal(signal.SIGTERM)
    out, err = viewer.communicate(timeout=60)
    with open(os.path.join(out_dir, "mouse.log"), "w") as f:
        f.write(line + out + err)
    sys.exit(viewer.returncode)


def capture_gamepad(out_dir):
    """Inside Xvfb and umockdev: --device auto finds the emulated pad, whose left stick is held right."""
    viewer = subprocess.Popen([VIEWER, *mouse_args(), "--device", "auto"], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, env=sanitizers.environment(VIEWER))
    first = viewer.stdout.readline()
    line = viewer.stdout.readline()
    if "presenting" in line:
        time.sleep(1.5)
    viewer.send_signal(signal.SIGTERM)
    out, err = viewer.communicate(timeout=60)
    with open(os.path.join(out_dir, "gamepad.log"), "w") as f:
        f.write(first + line + out + err)
    sys.exit(viewer.returncode)


def capture_no_gamepad(out_dir):
    """Inside Xvfb, no gamepad: --device gamepad must refuse to start."""
    r = subprocess.run([VIEWER, *mouse_args(), "--device", "gamepad", "--frames", "1"], capture_output=True,
                       text=True, timeout=300, env=sanitizers.environment(VIEWER))
    with open(os.path.join(out_dir, "no-gamepad.log"), "w") as f:
        f.write(f"exit {r.returncode}\n" + r.stdout + r.stderr)
    sys.exit(0)


def capture(out_dir):
    """Inside Xvfb: open the window, wait for frames, dump the screen, quit."""
    viewer = subprocess.Popen([VIEWER, *scene_args()], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                              env=sanitizers.environment(VIEWER))
    line = viewer.stdout.readline()  # "presenting on ..." after the first frame is presented
    if "presenting" not in line:
        viewer.kill()
        out, err = viewer.communicate()
        sys.exit(f"the viewer did not present a frame:\n{line}{out}{err}")
    time.sleep(1.0)  # a few more frames
    with open(os.path.join(out_dir, "screen.xwd"), "wb") as f:
        subprocess.run(["xwd", "-root", "-silent"], stdout=f, check=True, timeout=60)
    drag("1", 80)
    time.sleep(1.0)
    with open(os.path.join(out_dir, "orbited.xwd"), "wb") as f:
        subprocess.run(["xwd", "-root", "-silent"], stdout=f, check=True, timeout=60)
    # A resize: the swapchain is made again at the new size.
    window = subprocess.run(["xdotool", "search", "--name", "proxima-viewer"], capture_output=True, text=True,
                            check=True, timeout=60).stdout.split()[0]
    subprocess.run(["xdotool", "windowsize", window, str(RESIZED[0]), str(RESIZED[1])], check=True, timeout=60)
    time.sleep(1.5)
    with open(os.path.join(out_dir, "resized.xwd"), "wb") as f:
        subprocess.run(["xwd", "-root", "-silent"], stdout=f, check=True, timeout=60)
    viewer.send_signal(signal.SIGTERM)
    out, err = viewer.communicate(timeout=60)
    with open(os.path.join(out_dir, "viewer.log"), "w") as f:
        f.write(line + out + err)
    sys.exit(viewer.returncode)


class WindowTest(unittest.TestCase):
    def setUp(self):
        for tool in ("xvfb-run", "xauth", "xwd", "xdotool"):
            self.assertIsNotNone(shutil.which(tool), f"{tool} is missing (Debian: xvfb, xauth, x11-apps, xdotool)")

    def test_right_drag_moves_the_tool_through_the_streamed_device(self):
        with tempfile.TemporaryDirectory() as d:
            r = subprocess.run(["xvfb-run", "-a", "-s", f"-screen 0 {SCREEN}", sys.executable, os.path.abspath(__file__),
                                "--capture-mouse", VIEWER, ASSETS, d], capture_output=True, text=True, timeout=300)
            log = ""
            if os.path.exists(os.path.join(d, "mouse.log")):
                with open(os.path.join(d, "mouse.log")) as f:
                    log = f.read()
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr + log)
            self.assertNotRegex(log, VALIDATION)
            m = re.search(r"mouse device: (\d+) poses pushed, tool at (\S+) (\S+) (\S+),", log)
            self.assertIsNotNone(m, log)
            # Counted by the streamed device of the world the M key rebuilt, which took the dragged pose.
            self.assertGreater(int(m.group(1)), 0, log)
            self.assertIn("method original, force hard", log)
            moved = [float(m.group(2)) - 0.3, float(m.group(3)), float(m.group(4))]
            # The camera of the same scene, from a headless frame's sidecar.
            headless = subprocess.run([VIEWER, *mouse_args(), "--headless", "--out", d], capture_output=True,
                                      text=True, timeout=300, env=sanitizers.environment(VIEWER))
            self.assertEqual(headless.returncode, 0, headless.stdout + headless.stderr)
            with open(os.path.join(d, "frame-0000.json")) as f:
                view = json.load(f)["view"]
        right = [view[0], view[4], view[8]]  # the view matrix's first row: the camera's right axis
        up = [view[1], view[5], view[9]]
        along = sum(a * b for a, b in zip(moved, right))
        across = abs(sum(a * b for a, b in zip(moved, up)))
        self.assertGreater(along, 0.01, f"the tool moved by {moved}, not to the right")
        self.assertLess(across, 0.1 * along, f"the tool moved by {moved}, not along the view's right axis")

    def moved_along_the_view(self, d, log, device):
        """The tool's displacement from --pose-b, in the view's right and up axes."""
        m = re.search(device + r" device: (\d+) poses pushed, tool at (\S+) (\S+) (\S+), turned (\S+) (\S+) (\S+) (\S+)",
                      log)
        self.assertIsNotNone(m, log)
        self.assertGreater(int(m.group(1)), 2, log)  # a frame or more a push, however slow the frames
        moved = [float(m.group(2)) - 0.3, float(m.group(3)), float(m.group(4))]
        self.turned = [float(m.group(k)) for k in range(5, 9)]  # w, x, y, z
        headless = subprocess.run([VIEWER, *mouse_args(), "--headless", "--out", d], capture_output=True,
                                  text=True, timeout=300, env=sanitizers.environment(VIEWER))
        self.assertEqual(headless.returncode, 0, headless.stdout + headless.stderr)
        with open(os.path.join(d, "frame-0000.json")) as f:
            view = json.load(f)["view"]
        right, up = [view[0], view[4], view[8]], [view[1], view[5], view[9]]
        self.view_up = up
        return sum(a * b for a, b in zip(moved, right)), sum(a * b for a, b in zip(moved, up)), moved

    def test_a_gamepad_stick_moves_the_tool_through_the_streamed_device(self):
        self.assertIsNotNone(shutil.which("umockdev-run"), "umockdev-run is missing (Debian: umockdev)")
        with tempfile.TemporaryDirectory() as d:
            pad = gamepad.write(d)
            r = subprocess.run(["xvfb-run", "-a", "-s", f"-screen 0 {SCREEN}", "umockdev-run", *pad, "--",
                                sys.executable, os.path.abspath(__file__), "--capture-gamepad", VIEWER, ASSETS, d],
                               capture_output=True, text=True, timeout=300)
            log = ""
            if os.path.exists(os.path.join(d, "gamepad.log")):
                with open(os.path.join(d, "gamepad.log")) as f:
                    log = f.read()
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr + log)
            self.assertNotRegex(log, VALIDATION)
            self.assertIn("proxima-viewer: gamepad X360 Controller", log)  # the name of GLFW's mapping
            along, across, moved = self.moved_along_the_view(d, log, "gamepad")
        # The left stick held right for about 1.5 s at half the scene's radius (0.2 m) a second: about
        # 0.15 m, less when frames are slower than the 0.25 s a frame may integrate.
        self.assertGreater(along, 0.02, f"the tool moved by {moved}, not to the right")
        self.assertLess(abs(across), 0.1 * along, f"the tool moved by {moved}, not along the view's right axis")
        # The right stick held right: turned by about 1.5 rad about the view's up axis.
        w, axis = self.turned[0], self.turned[1:]
        angle = 2 * math.acos(max(-1.0, min(1.0, abs(w))))
        self.assertGreater(angle, 0.2, f"the tool turned by {self.turned}")
        norm = math.sqrt(sum(a * a for a in axis))
        self.assertGreater(abs(sum(a * u for a, u in zip(axis, self.view_up))) / norm, 0.99,
                           f"the tool turned about {axis}, not the view's up axis {self.view_up}")

    def test_no_gamepad_is_a_clear_error(self):
        with tempfile.TemporaryDirectory() as d:
            r = subprocess.run(["xvfb-run", "-a", "-s", f"-screen 0 {SCREEN}", sys.executable, os.path.abspath(__file__),
                                "--capture-no-gamepad", VIEWER, ASSETS, d], capture_output=True, text=True, timeout=300)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            with open(os.path.join(d, "no-gamepad.log")) as f:
                log = f.read()
        self.assertTrue(log.startswith("exit 1\n"), log)
        self.assertIn("proxima-viewer: --device gamepad: no gamepad is connected", log)

    def test_window_shows_what_the_headless_frame_shows(self):
        with tempfile.TemporaryDirectory() as d:
            r = subprocess.run(["xvfb-run", "-a", "-s", f"-screen 0 {SCREEN}", sys.executable, os.path.abspath(__file__),
                                "--capture", VIEWER, ASSETS, d], capture_output=True, text=True, timeout=300)
            log = ""
            if os.path.exists(os.path.join(d, "viewer.log")):
                with open(os.path.join(d, "viewer.log")) as f:
                    log = f.read()
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr + log)
            self.assertNotRegex(log, VALIDATION)
            self.assertRegex(log, r"frames at 480x270")
            width, height, screen = xwd.read(os.path.join(d, "screen.xwd"))
            _, _, orbited = xwd.read(os.path.join(d, "orbited.xwd"))
            _, _, resized = xwd.read(os.path.join(d, "resized.xwd"))

            headless = subprocess.run([VIEWER, *scene_args(), "--headless", "--out", d], capture_output=True,
                                      text=True, timeout=300, env=sanitizers.environment(VIEWER))
            self.assertEqual(headless.returncode, 0, headless.stdout + headless.stderr)
            frame = png.read(os.path.join(d, "frame-0000.png"))

        # Without a window manager the window sits at the screen's top-left corner.
        differing, worst = 0, 0
        for y in range(SIZE[1]):
            for x in range(SIZE[0]):
                i, j = 3 * (y * width + x), 3 * (y * SIZE[0] + x)
                d = max(abs(screen[i + k] - frame.rgb[j + k]) for k in range(3))
                differing += d > 0
                worst = max(worst, d)
        # Measured identical on lavapipe; a few pixels are allowed to round differently.
        print(f"window against headless: {differing} pixels differ, by up to {worst}", file=sys.stderr)
        self.assertLessEqual(differing, SIZE[0] * SIZE[1] // 1000, f"{differing} pixels differ, by up to {worst}")
        # The rest of the screen is not the viewer's: X's black root window.
        self.assertEqual(screen[3 * (SIZE[1] + 10) * width:3 * (SIZE[1] + 11) * width], bytes(3 * width))

        # After the drag: the scene seen from elsewhere (a still scene changes no pixel).
        moved = sum(screen[3 * (y * width + x):3 * (y * width + x) + 3] != orbited[3 * (y * width + x):3 * (y * width + x) + 3]
                    for y in range(SIZE[1]) for x in range(SIZE[0]))
        print(f"after the drag: {moved} pixels changed", file=sys.stderr)
        self.assertGreater(moved, SIZE[0] * SIZE[1] // 20, "the drag did not orbit the camera")
        self.assertEqual(orbited[3 * (width - 1):3 * width], bytes(3))  # still only the window is drawn

        # Resized to 600x400: the viewer draws up to the window's corners (the background at the top right,
        # not X's black at the bottom right), and X's black is just beyond them.
        def at(x, y):
            return resized[3 * (y * width + x):3 * (y * width + x) + 3]

        background = tuple(frame.pixel(frame.width - 1, 0))
        self.assertEqual(tuple(at(RESIZED[0] - 1, 0)), background)
        self.assertNotEqual(at(RESIZED[0] - 1, RESIZED[1] - 1), bytes(3))
        self.assertEqual(at(RESIZED[0] + 1, 0), bytes(3))
        self.assertEqual(at(0, RESIZED[1] + 1), bytes(3))


if __name__ == "__main__":
    captures = {"--capture": capture, "--capture-mouse": capture_mouse, "--capture-gamepad": capture_gamepad,
                "--capture-no-gamepad": capture_no_gamepad}
    if len(sys.argv) == 5 and sys.argv[1] in captures:
        VIEWER, ASSETS = sys.argv[2], sys.argv[3]
        captures[sys.argv[1]](sys.argv[4])
    VIEWER = os.path.abspath(sys.argv.pop(1))
    ASSETS = os.path.abspath(sys.argv.pop(1))
    unittest.main()
