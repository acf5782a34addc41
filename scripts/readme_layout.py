#!/usr/bin/env python3
"""The README's layout section, made from the tree.

    scripts/readme_layout.py [ROOT]            check: exit 1, naming what differs
    scripts/readme_layout.py --write [ROOT]    rewrite the README's block

Every folder git tracks files in, down to the depth listed in LEVELS, has a
line below; a folder with no line, or a line for a folder that is gone,
fails the check (the ctest test readme.layout), and so does a README whose
block is not what this script makes of the tree.
"""
import os
import subprocess
import sys

# Which folders are listed: these and, under each, its folders this many
# levels down (0: the folder alone).
LEVELS = {
    "sdk/include/proxima": 0,
    "sdk/src": 1,
    "sdk/src/devices": 1,
    "tests": 1,
    "samples": 1,
    "bindings": 1,
    "bench": 0,
    "shaders": 0,
    "cmake": 0,
    "docs": 0,
    "scripts": 0,
}

DESCRIPTIONS = {
    "sdk/include/proxima": "the public C API: proxima.h (the whole API) and its parts base.h, types.h, devices.h, "
                           "threads.h, inspect.h; proxima_hid.h, proxima_openxr.h",
    "sdk/src/common": "status, quaternions, a worker pool",
    "sdk/src/geometry": "exact predicates, triangle distance/intersection, visibility",
    "sdk/src/mesh": "indexed meshes with adjacency and normals; glTF rigs (skins, morphs, animation)",
    "sdk/src/io": "OBJ and glTF reading",
    "sdk/src/snch": "the hierarchy: bounding spheres, boxes and normal cones, built and refitted",
    "sdk/src/contact": "global search, local tracking, the brute-force reference, forces, patches, polylines",
    "sdk/src/coupling": "the constrained tool: proxy, clearance, virtual coupling",
    "sdk/src/runtime": "worlds, scene versions, the pipeline's stages (global pass, local tracking); the threads, "
                       "handoffs, haptic rendering and safety gate, the device model",
    "sdk/src/devices": "HID devices: profiles, their threads and outputs; report descriptors, HID PID force feedback",
    "sdk/src/devices/xr": "the OpenXR device, built on the runtime's streamed device",
    "sdk/src/capi": "the C API over the runtime: ids, the one device table, validation, errors",
    "tests/support": "what the tests share: scenes, the brute-force matchers, marked threads",
    "tests/geometry": "the kernel against exact and quad-precision references",
    "tests/mesh": "meshes, adjacency, normals",
    "tests/io": "the OBJ and glTF readers and rigs, on the shared assets",
    "tests/contact": "the engine against the brute-force reference; forces, patches, refits",
    "tests/coupling": "the constrained tool, deterministic and on the threads",
    "tests/runtime": "handoffs, the haptic tick and safety gate, the threads with fault injection, living scenes",
    "tests/stress": "the numerical stress suite: generators, quad reference, report",
    "tests/capi": "the C API: misuse of every function; the header's parts as C11",
    "tests/cli": "the command-line tool end to end",
    "tests/hid": "HID devices on umockdev-emulated hidraw nodes from real descriptors; HID PID firmware models",
    "tests/openxr": "the OpenXR device on the real loader and validation layer over a mock runtime",
    "tests/viewer": "the viewer headless on lavapipe and windowed under Xvfb",
    "tests/csharp": "the C# suite's runner, the C struct layout, the package check, the UnityEngine stub",
    "tests/install": "the installed package consumed by find_package, pkg-config and a subdirectory build",
    "tests/fuzz": "libFuzzer targets, their seeds, dictionaries and regressions",
    "samples/hello": "the C API walkthrough to read first",
    "samples/haptic": "the threaded walkthrough: a device, the threads, their statistics",
    "samples/stream": "a device thread of the application's own, streaming poses",
    "samples/openxr": "handing an OpenXR session to the OpenXR device",
    "samples/cli": "the proxima command-line tool (a C API customer)",
    "samples/common": "what the samples share (the JSON writer)",
    "samples/viewer": "proxima-viewer, the Vulkan viewer",
    "bindings/python": "the Python package (cffi over the headers): proxima/, tests/, examples/, bench/",
    "bindings/csharp": "the C# binding and Unity package (com.proxima.sdk), generated from the headers",
    "bench": "the scene, kernel, deformation, fidelity and coupling benchmarks; the FCL and Coal peers",
    "shaders": "the viewer's GLSL shaders",
    "cmake": "packaging: install rules, the config files, toolchains",
    "docs": "decisions and measurements",
    "scripts": "the two commands of the README, the benchmark run, the Windows build, the layering checks",
}

BEGIN = "```\n"  # the block right after the "## Layout" heading's paragraph


def tracked_dirs(root):
    files = subprocess.run(["git", "-C", root, "ls-files"], check=True, capture_output=True,
                           text=True).stdout.split("\n")
    dirs = set()
    for f in files:
        parts = f.split("/")[:-1]
        for i in range(1, len(parts) + 1):
            dirs.add("/".join(parts[:i]))
    return dirs


def listed(root):
    """The folders that must have a line, by LEVELS, in DESCRIPTIONS' order
    (the layers bottom up), any without a line last."""
    dirs = tracked_dirs(root)
    wanted = set()
    for top, depth in LEVELS.items():
        if top not in dirs:
            continue
        if depth == 0 or top in DESCRIPTIONS:
            wanted.add(top)
        if depth >= 1:
            wanted.update(d for d in dirs
                          if d.startswith(top + "/") and d.count("/") == top.count("/") + 1 and d not in LEVELS)
    order = list(DESCRIPTIONS)
    return sorted(wanted, key=lambda d: (order.index(d) if d in order else len(order), d))


def block(root):
    missing = [d for d in listed(root) if d not in DESCRIPTIONS]
    gone = [d for d in DESCRIPTIONS if d not in tracked_dirs(root)]
    lines = []
    for d in listed(root):
        if d in DESCRIPTIONS:
            lines.append(f"{d + '/':<24}{DESCRIPTIONS[d]}")
    return "\n".join(lines) + "\n", missing, gone


def readme_parts(text):
    head = text.index("## Layout")
    start = text.index(BEGIN, head) + len(BEGIN)
    end = text.index("```", start)
    return start, end


def main(argv):
    write = "--write" in argv
    args = [a for a in argv if a != "--write"]
    root = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    made, missing, gone = block(root)
    problems = [f"{d}/ has no line in scripts/readme_layout.py" for d in missing]
    problems += [f"{d}/ has a line in scripts/readme_layout.py but is not in the tree" for d in gone]
    path = os.path.join(root, "README.md")
    text = open(path, encoding="utf-8").read()
    start, end = readme_parts(text)
    if write and not problems:
        open(path, "w", encoding="utf-8").write(text[:start] + made + text[end:])
        return 0
    if text[start:end] != made:
        problems.append("README.md's layout block is not the tree's (scripts/readme_layout.py --write)")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
