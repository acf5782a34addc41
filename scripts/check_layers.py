#!/usr/bin/env python3
"""Checks the layering docs/architecture.md draws, from the tree's includes
and build files; exits 1 naming every file that breaks it.

- Each folder of sdk/src includes only the folders below it (LAYERS).
- Only sdk/src/capi includes the public headers (<proxima/...>) or capi/.
- bench/ and samples/ compile no file of tests/.
- samples/ use the public API only: no internal library, no sdk/src header.

A break that is known and being mended is listed in KNOWN with why; it is
reported as known, and a KNOWN entry that no longer breaks anything is an
error (so the list only shrinks).

    check_layers.py [ROOT]        check the tree at ROOT (default: here)
    check_layers.py --self-test   check that a break of each rule is caught
"""
import os
import re
import shutil
import sys
import tempfile

# What each folder of sdk/src may include besides itself (third-party and
# system headers aside).
LAYERS = {
    "common": set(),
    "geometry": {"common"},
    "mesh": {"common", "geometry"},
    "io": {"common", "geometry", "mesh"},
    "snch": {"common", "geometry", "mesh"},
    "contact": {"common", "geometry", "mesh", "snch"},
    "coupling": {"common", "geometry", "mesh", "snch", "contact"},
    "runtime": {"common", "geometry", "mesh", "io", "snch", "contact", "coupling"},
    "devices": {"common", "geometry", "runtime"},
    "capi": {"common", "geometry", "mesh", "io", "snch", "contact", "coupling", "runtime", "devices"},
}

# Known breaks being mended (issue: one shape for the SDK).
KNOWN = {
}

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')
SOURCES = (".c", ".cc", ".cpp", ".h", ".hpp")


def sources(root, top):
    for dirpath, dirnames, files in os.walk(os.path.join(root, top)):
        dirnames[:] = [d for d in dirnames if not d.startswith(".") and d != "build"]
        for f in sorted(files):
            if f.endswith(SOURCES) or f == "CMakeLists.txt":
                yield os.path.join(dirpath, f)


def includes(path):
    with open(path, errors="replace") as f:
        for line in f:
            m = INCLUDE.match(line)
            if m:
                yield m.group(1)


def check(root):
    breaks = []  # (file, what, message)
    src = os.path.join(root, "sdk", "src")
    folders = set(os.listdir(src)) if os.path.isdir(src) else set()
    for path in sources(root, os.path.join("sdk", "src")):
        rel = os.path.relpath(path, root).replace(os.sep, "/")
        folder = rel.split("/")[2]
        for inc in includes(path):
            head = inc.split("/")[0]
            if inc.startswith("proxima/") and folder != "capi":
                breaks.append((rel, inc, "includes a public header: only sdk/src/capi may"))
            elif head in folders and head != folder:
                allowed = LAYERS.get(folder)
                if allowed is None:
                    breaks.append((rel, inc, "is in sdk/src/%s, a folder the layers do not name" % folder))
                elif head not in allowed:
                    breaks.append((rel, inc, "sdk/src/%s may include only %s" % (folder, ", ".join(sorted(allowed)) or "itself")))
    for top in ("bench", "samples"):
        for path in sources(root, top):
            rel = os.path.relpath(path, root).replace(os.sep, "/")
            text = open(path, errors="replace").read()
            if path.endswith("CMakeLists.txt"):
                for m in re.finditer(r"(?:PROJECT_SOURCE_DIR|CMAKE_SOURCE_DIR)\}/(tests\b[\w/.-]*)", text):
                    breaks.append((rel, m.group(1), "compiles or includes a file of tests/"))
                if top == "samples":
                    for m in re.finditer(r"\b(proxima::core|proxima_core|sdk/src)\b", text):
                        breaks.append((rel, m.group(1), "a sample uses the internal library: the public API only"))
            elif top == "samples":
                for inc in includes(path):
                    head = inc.split("/")[0]
                    here = os.path.join(os.path.dirname(path), inc)
                    shared = os.path.join(root, "samples", inc)
                    if head in folders and not (os.path.exists(here) or os.path.exists(shared)):
                        breaks.append((rel, inc, "a sample includes an sdk/src header: the public API only"))
    return breaks


def report(root):
    breaks = check(root)
    seen = set()
    failed = False
    for rel, what, message in breaks:
        key = (rel, what)
        seen.add(key)
        if key in KNOWN:
            print("known: %s: %s (%s; %s)" % (rel, what, message, KNOWN[key]))
        else:
            print("BREAK: %s: %s: %s" % (rel, what, message))
            failed = True
    for key in sorted(set(KNOWN) - seen):
        print("MENDED: %s: %s no longer breaks the layers: take it out of KNOWN in %s" % (key[0], key[1], __file__))
        failed = True
    unknown = len([b for b in breaks if (b[0], b[1]) not in KNOWN])
    print("%d breaks of the layering (%d known, being mended)" % (unknown, len(breaks) - unknown))
    return 1 if failed else 0


def self_test():
    # One tree per rule, each breaking it once: every one must be caught.
    cases = {
        "a layer includes one above it": {"sdk/src/mesh/a.cpp": '#include "runtime/world.h"\n'},
        "a layer includes a public header": {"sdk/src/runtime/a.cpp": "#include <proxima/proxima.h>\n"},
        "a layer includes capi": {"sdk/src/devices/a.cpp": '#include "capi/common.h"\n'},
        "bench compiles a test file": {"bench/CMakeLists.txt": "add_executable(b ${PROJECT_SOURCE_DIR}/tests/x.cpp)\n"},
        "a sample links the core": {"samples/x/CMakeLists.txt": "target_link_libraries(x PRIVATE proxima::core)\n"},
        "a sample includes sdk/src": {"samples/x/a.cpp": '#include "runtime/world.h"\n'},
    }
    base = {"sdk/src/runtime/world.h": "", "sdk/src/mesh/mesh.h": "", "sdk/src/capi/common.h": "",
            "sdk/src/devices/d.h": ""}
    ok = True
    for name, files in cases.items():
        root = tempfile.mkdtemp()
        try:
            for rel, text in {**base, **files}.items():
                os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
                with open(os.path.join(root, rel), "w") as f:
                    f.write(text)
            found = check(root)
            print("%s: %s" % (name, "caught" if found else "MISSED"))
            ok = ok and bool(found)
        finally:
            shutil.rmtree(root)
    # And a tree that keeps the rules passes.
    root = tempfile.mkdtemp()
    try:
        for rel, text in {**base, "sdk/src/runtime/a.cpp": '#include "mesh/mesh.h"\n',
                          "samples/x/a.cpp": "#include <proxima/proxima.h>\n"}.items():
            os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w") as f:
                f.write(text)
        clean = not check(root)
        print("a tree that keeps the rules: %s" % ("passes" if clean else "FLAGGED"))
        ok = ok and clean
    finally:
        shutil.rmtree(root)
    return 0 if ok else 1


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(self_test())
    sys.exit(report(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")))
