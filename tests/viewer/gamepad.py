"""An emulated gamepad for the viewer's tests: the files umockdev-run needs
to show an Xbox 360 pad on /dev/input/event7 (a device description, the
evdev ioctls GLFW asks at start, and the events it then reads), written
from the description below. GLFW 3.3 reads gamepads from evdev, and its
built-in mappings know this pad by its bus, vendor, product and version.

Only the sticks' first positions are sent, without a SYN_REPORT: on one,
GLFW re-reads every axis with EVIOCGABS, whose answers here are fixed."""

import os
import struct

DEVICE = "/dev/input/event7"
BUTTONS = (0x130, 0x131, 0x133, 0x134, 0x136, 0x137, 0x13A, 0x13B, 0x13C, 0x13D, 0x13E)  # BTN_A ... BTN_THUMBR
STICKS = (0x00, 0x01, 0x03, 0x04)  # ABS_X, ABS_Y (left), ABS_RX, ABS_RY (right): -32768 .. 32767
TRIGGERS = (0x02, 0x05)  # ABS_Z, ABS_RZ: 0 .. 255
HAT = (0x10, 0x11)  # ABS_HAT0X, ABS_HAT0Y: -1 .. 1

DESCRIPTION = """P: /devices/virtual/input/input7/event7
N: input/event7
E: DEVNAME=/dev/input/event7
E: ID_INPUT=1
E: ID_INPUT_JOYSTICK=1
E: MAJOR=13
E: MINOR=71
E: SUBSYSTEM=input
A: dev=13:71

P: /devices/virtual/input/input7
E: ID_INPUT=1
E: ID_INPUT_JOYSTICK=1
E: NAME="Microsoft X-Box 360 pad"
E: PRODUCT=3/45e/28e/110
E: SUBSYSTEM=input
A: name=Microsoft X-Box 360 pad
"""


def bits(codes, size):
    out = bytearray(size)
    for c in codes:
        out[c // 8] |= 1 << (c % 8)
    return bytes(out)


def ioctls():
    name = b"Microsoft X-Box 360 pad\0"
    lines = [f"@DEV {DEVICE}",
             # GLFW asks for 4 bytes of event types (EV_CNT bits): EV_SYN, EV_KEY, EV_ABS.
             "EVIOCGBIT(0) 4 " + bits((0, 1, 3), 4).hex().upper(),
             "EVIOCGBIT(1) 96 " + bits(BUTTONS, 96).hex().upper(),
             "EVIOCGBIT(3) 8 " + bits(STICKS + TRIGGERS + HAT, 8).hex().upper(),
             "EVIOCGID 0 " + struct.pack("<4H", 3, 0x045E, 0x028E, 0x0110).hex().upper(),  # USB, Microsoft, 360 pad
             f"EVIOCGNAME(0) {len(name)} " + (name + bytes(256 - len(name))).hex().upper()]
    for code in STICKS + TRIGGERS + HAT:
        lo, hi, fuzz, flat = (-32768, 32767, 16, 128) if code in STICKS else ((0, 255, 0, 0) if code in TRIGGERS
                                                                            else (-1, 1, 0, 0))
        info = struct.pack("<6i", 0, lo, hi, fuzz, flat, 0)  # struct input_absinfo, at rest
        lines.append(("EVIOCGABS" if code == 0 else f"EVIOCGABS({code})") + " 0 " + info.hex().upper())
    return "\n".join(lines) + "\n"


def write(directory, left_x=32767, right_x=32767):
    """Writes the three files; from the first read the left stick sits at left_x and the right one at right_x.
    Returns umockdev-run's options."""
    paths = {k: os.path.join(directory, "pad." + k) for k in ("umockdev", "ioctl", "events")}
    with open(paths["umockdev"], "w") as f:
        f.write(DESCRIPTION)
    with open(paths["ioctl"], "w") as f:
        f.write(ioctls())
    with open(paths["events"], "w") as f:
        f.write(f"E: 0.000000 0003 0000 {left_x}\n")  # EV_ABS ABS_X
        f.write(f"E: 0.000000 0003 0003 {right_x}\n")  # EV_ABS ABS_RX
    return ["-d", paths["umockdev"], "-i", f"{DEVICE}={paths['ioctl']}", "-e", f"{DEVICE}={paths['events']}"]
