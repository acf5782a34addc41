#!/usr/bin/env python3
"""Checks the Unity package's layout, which no compiler sees: package.json,
the assembly definitions, a .meta with a unique GUID for every file and
folder (Unity ignores an immutable package's assets that lack one), the
native plugin's platform settings, that the package, the C# binding and
the C library carry one version, and that the binding declares every
function of proxima.h, proxima_hid.h and proxima_openxr.h. Prints "N passed, N failed".

    check_package.py REPOSITORY_ROOT
"""
import json
import os
import re
import sys

failures = []
passed = 0


def check(ok, what):
    global passed
    if ok:
        passed += 1
    else:
        failures.append(what)
        print("FAILED " + what)


def main():
    root = sys.argv[1]
    pkg = os.path.join(root, "bindings", "csharp", "com.proxima.sdk")

    manifest = json.load(open(os.path.join(pkg, "package.json")))
    check(manifest.get("name") == "com.proxima.sdk", "package.json: name is com.proxima.sdk")
    check(re.fullmatch(r"\d{4}\.\d", manifest.get("unity", "")) is not None, "package.json: unity is YEAR.N")
    for sample in manifest.get("samples", []):
        check(os.path.isdir(os.path.join(pkg, sample["path"])), "package.json: sample path " + sample["path"] + " exists")

    header = open(os.path.join(root, "sdk", "include", "proxima", "version.h")).read()
    c_version = ".".join(re.search(r"PROX_VERSION_%s (\d+)" % p, header).group(1) for p in ("MAJOR", "MINOR", "PATCH"))
    types = open(os.path.join(pkg, "Runtime", "Types.cs")).read()
    binding = re.search(r"Binding => new Version\((\d+), (\d+), (\d+)\)", types)
    check(binding is not None and ".".join(binding.groups()) == c_version,
          "Version.Binding in Types.cs is the C library's " + c_version)
    check(manifest.get("version") == c_version, "package.json: version is the C library's " + c_version)

    # Every public C function has its P/Invoke declaration (generated into
    # Runtime/Generated/ by gen_native.py; this check reads the headers and
    # the C# on its own): proxima.h, the parts it includes, proxima_hid.h and
    # proxima_openxr.h.
    api = "".join(open(os.path.join(root, "sdk", "include", "proxima", h)).read()
                  for h in ("base.h", "types.h", "proxima.h", "devices.h", "threads.h", "inspect.h", "proxima_hid.h",
                            "proxima_openxr.h"))
    c_functions = set(re.findall(r"^PROX_API\s[^;]*?\b(prox\w+)\s*\(", api, re.M | re.S))
    generated = os.path.join(pkg, "Runtime", "Generated")
    native = "".join(open(os.path.join(generated, n)).read() for n in sorted(os.listdir(generated))
                     if n.endswith(".cs"))
    native += open(os.path.join(pkg, "Runtime", "Native.cs")).read()
    declared = set(re.findall(r"static extern [\w\[\]]+ (prox\w+)\(", native))
    declared |= set(re.findall(r'EntryPoint = "(prox\w+)"', native))
    check(len(c_functions) > 90, "the headers' functions were found (%d)" % len(c_functions))
    for f in sorted(c_functions):
        check(f in declared, "Native.cs declares " + f)

    runtime = json.load(open(os.path.join(pkg, "Runtime", "Proxima.asmdef")))
    check(runtime["name"] == "Proxima", "Runtime asmdef: the assembly is Proxima (InternalsVisibleTo names Proxima.Tests)")
    check(runtime.get("noEngineReferences") is True, "Runtime asmdef: noEngineReferences")
    unity = json.load(open(os.path.join(pkg, "Runtime", "Unity", "Proxima.Unity.asmdef")))
    check("Proxima" in unity["references"] and not unity.get("noEngineReferences"),
          "Unity asmdef: references Proxima and UnityEngine")
    tests = json.load(open(os.path.join(pkg, "Tests", "Runtime", "Proxima.Tests.asmdef")))
    check(tests["name"] == "Proxima.Tests" and "UNITY_INCLUDE_TESTS" in tests["defineConstraints"],
          "Tests asmdef: Proxima.Tests, only with UNITY_INCLUDE_TESTS")

    guids = {}
    plugin_meta = os.path.join("Runtime", "Plugins", "x86_64", "libproxima.so.meta")
    for d, dirs, files in os.walk(pkg):
        dirs[:] = [x for x in dirs if not x.startswith(".")]
        for name in dirs + files:
            rel = os.path.relpath(os.path.join(d, name), pkg)
            if name.startswith(".") or rel == "Samples~" or name.startswith(("libproxima.so", "proxima.dll")):
                continue
            if name.endswith(".meta"):
                check(os.path.exists(os.path.join(d, name[:-5])), rel + " has its asset")
                continue
            meta = os.path.join(d, name) + ".meta"
            if not os.path.exists(meta):
                check(False, rel + " has a .meta")
                continue
            text = open(meta).read()
            m = re.search(r"^guid: ([0-9a-f]{32})$", text, re.M)
            check(m is not None, rel + ".meta has a 32-digit guid")
            if m:
                check(m.group(1) not in guids, rel + ".meta's guid is unique (also in %s)" % guids.get(m.group(1)))
                guids[m.group(1)] = rel
            check(("folderAsset: yes" in text) == os.path.isdir(os.path.join(d, name)), rel + ".meta: folder or file")

    text = open(os.path.join(pkg, plugin_meta)).read()
    check("PluginImporter:" in text, "the plugin's .meta is a PluginImporter")
    editor = re.search(r"Editor: Editor\n    second:\n      enabled: (\d)\n      settings:\n        CPU: (\w+)\n"
                       r"        DefaultValueInitialized: true\n        OS: (\w+)", text)
    check(editor is not None and editor.groups() == ("1", "x86_64", "Linux"), "the plugin loads in the Linux x86_64 editor")
    player = re.search(r"Standalone: Linux64\n    second:\n      enabled: (\d)\n      settings:\n        CPU: (\w+)", text)
    check(player is not None and player.groups() == ("1", "x86_64"), "the plugin ships in Linux x86_64 players")
    check(re.search(r"Standalone: Win64\n    second:\n      enabled: 1", text) is None,
          "libproxima.so is not enabled for Windows players")

    # proxima.dll (scripts/windows.sh; fill_plugins.sh copies it in): the
    # Windows x86_64 editor and players, nothing else.
    dll_meta = os.path.join(pkg, "Runtime", "Plugins", "x86_64", "proxima.dll.meta")
    check(os.path.exists(dll_meta), "the Windows plugin has a .meta")
    text = open(dll_meta).read() if os.path.exists(dll_meta) else ""
    check("PluginImporter:" in text, "proxima.dll's .meta is a PluginImporter")
    editor = re.search(r"Editor: Editor\n    second:\n      enabled: (\d)\n      settings:\n        CPU: (\w+)\n"
                       r"        DefaultValueInitialized: true\n        OS: (\w+)", text)
    check(editor is not None and editor.groups() == ("1", "x86_64", "Windows"),
          "proxima.dll loads in the Windows x86_64 editor")
    enabled = re.findall(r"Standalone: (\w+)\n    second:\n      enabled: 1\n      settings:\n        CPU: (\w+)", text)
    check(enabled == [("Win64", "x86_64")], "proxima.dll ships in Windows x86_64 players only (%s)" % enabled)

    print(f"{passed} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
