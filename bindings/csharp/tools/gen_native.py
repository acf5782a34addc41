#!/usr/bin/env python3
"""Generates the C# binding's P/Invoke declarations and blittable types from
Proxima's public headers (docs/csharp.md, "Generated code").

    gen_native.py [--check] [--layout-c FILE] [REPOSITORY_ROOT]

Writes com.proxima.sdk/Runtime/Generated/<Header>.g.cs, one per header: its
enums and structs (partial, so that hand-written files add constructors,
operators and properties, never fields) and its functions as `Native`'s
DllImports, with a .meta file each (Unity ignores an asset without one; the
GUID is derived from the path, so it never changes). The files are committed,
because Unity takes the package folder as it is, with no build step.

--check writes nothing: it fails (exit 1, with a diff) when the committed
files are not what the headers give now (ctest csharp.generated).
--layout-c writes a C program printing every struct's and enum's size and
every field's offset as the C compiler lays them out, each with its C# name
(the NUnit StructLayoutTests compare them with Marshal's). Standard library only.
"""

import argparse
import difflib
import hashlib
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cheader  # noqa: E402

# The headers bound, each into Generated/<name>.g.cs. The functions of the
# optional parts (HID, OpenXR) are declared like the others: a DllImport is
# looked up on its first call, so the package loads whatever the library has.
HEADERS = [
    ("base.h", "Base"),
    ("types.h", "Types"),
    ("proxima.h", "Proxima"),
    ("devices.h", "Devices"),
    ("threads.h", "Threads"),
    ("inspect.h", "Inspect"),
    ("proxima_hid.h", "Hid"),
    ("proxima_openxr.h", "OpenXr"),
]
OPENXR = "proxima_openxr.h"  # its layout needs openxr.h (struct_layout.c checks it when present)

# ---- the name map: where the C# names are not the C names minus "prox" ----
# The C# names are the binding's public contract, older than this generator.
TYPE_NAMES = {
    "proxBool": "Bool32",                        # hand-written (Types.cs): converts to and from bool
    "proxStreamDeviceDef": "StreamDeviceSettings",  # public defs are "Settings", filled by users
    "proxThreadsDef": "ThreadSettings",
    "proxHidDeviceDef": "HidDeviceSettings",
    "proxXrDeviceDef": "XrDeviceSettings",
    "proxThread": "ThreadRole",                  # "Thread" would hide System.Threading.Thread
    "proxHapticFlag": "HapticFlags",
}
# C fields whose C# type says more than the C one (an int that is an enum,
# an id that is a public handle).
FIELD_TYPES = {
    ("proxContact", "other"): "Body",
    ("proxContact", "featureTool"): "Feature",
    ("proxContact", "featureOther"): "Feature",
    ("proxHapticSample", "flags"): "HapticFlags",
}
# Prefixes cut from enum members (tried in order) where the members' common
# prefix is not the right cut, and words spelt otherwise than capitalised.
ENUM_PREFIXES = {
    "proxResult": ["PROX_ERROR_", "PROX_"],
    "proxHidProfile": ["PROX_HID_PROFILE_", "PROX_HID_"],
}
WORDS = {"SPACEMOUSE": "SpaceMouse", "DUALSHOCK4": "DualShock4", "DUALSENSE": "DualSense"}
FLAG_ENUMS = {"proxHapticFlag"}  # [Flags], uint, with None = 0
# Struct-array parameters the binding passes as managed arrays (the others as
# pointers its helpers pin: a pinned array is never copied by the marshaller).
ARRAY_PARAMS = {
    ("proxBody_GetHapticTrace", "samples"): "[Out] HapticSample[]",
    ("proxEnumerateHidDevices", "infos"): "[Out] HidDeviceInfo[]",
}
# Pointer parameters that may be NULL: a second import taking IntPtr.
NULLABLE = {("proxBody_SetDevice", "def"): "proxBody_SetDeviceNull"}
NOT_GENERATED = {"proxBool"}  # hand-written

SCALARS = {
    "int8_t": "sbyte", "uint8_t": "byte", "int16_t": "short", "uint16_t": "ushort", "int32_t": "int",
    "uint32_t": "uint", "int64_t": "long", "uint64_t": "ulong", "double": "double", "float": "float",
    "char": "byte", "void": "void", "size_t": "UIntPtr",
    # OpenXR's types (openxr.h), as Unity's OpenXR plugin passes them: handles
    # and paths are 64 bits on every platform, the function pointer an IntPtr.
    "XrInstance": "ulong", "XrSession": "ulong", "XrSpace": "ulong", "XrAction": "ulong", "XrActionSet": "ulong",
    "XrPath": "ulong", "XrTime": "long", "XrDuration": "long", "XrSessionState": "int",
    "PFN_xrGetInstanceProcAddr": "IntPtr",
}
KEYWORDS = {"object", "string", "params", "out", "ref", "base", "lock", "event", "operator", "fixed", "checked",
            "decimal", "internal", "namespace", "override", "readonly", "sizeof", "typeof", "value"}
HIDDEN = {"reserved", "internalValue", "apiVersion"}


def cs_type(ctype):
    if ctype in SCALARS:
        return SCALARS[ctype]
    if ctype in TYPE_NAMES:
        return TYPE_NAMES[ctype]
    if ctype.startswith("prox"):
        return ctype[4:]
    raise cheader.HeaderError(f"no C# type for {ctype}")


def pascal(name):
    return name[0].upper() + name[1:]


def is_internal(cs_name):
    # Ids and the defs only the binding fills are internal: users hold Body,
    # Mesh and the devices, and pass settings structs.
    return cs_name.endswith(("Id", "Def")) or cs_name == "PolylineInfo"


def xml(text):
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def wrap(text, indent, prefix, width=110):
    words, lines, line = text.split(), [], ""
    for w in words:
        if line and len(indent) + len(prefix) + len(line) + 1 + len(w) > width:
            lines.append(line)
            line = w
        else:
            line = (line + " " + w) if line else w
    if line:
        lines.append(line)
    return [indent + prefix + l for l in lines]


def summary(text, indent):
    if not text:
        return []
    lines = wrap(xml(text), indent, "/// ")
    if len(lines) == 1:
        return [f"{indent}/// <summary>{lines[0][len(indent) + 4:]}</summary>"]
    return [f"{indent}/// <summary>"] + lines + [f"{indent}/// </summary>"]


def member_name(enum, member):
    prefixes = ENUM_PREFIXES.get(enum.name)
    if prefixes is None:
        names = [m.name for m in enum.members if not m.name.endswith("FORCE32")]
        common = os.path.commonprefix(names)
        prefixes = [common[:common.rfind("_") + 1]]
    rest = member.name
    for p in prefixes:
        if rest.startswith(p):
            rest = rest[len(p):]
            break
    return "".join(WORDS.get(w, w.capitalize()) for w in rest.split("_"))


def emit_enum(enum, out):
    name = cs_type(enum.name)
    out += summary(f"{enum.name}: {enum.comment}" if enum.comment else enum.name, "    ")
    flags = enum.name in FLAG_ENUMS
    if flags:
        out.append("    [Flags]")
    out.append(f"    public enum {name}{' : uint' if flags else ''}")
    out.append("    {")
    if flags:
        out.append("        None = 0,")
    for m in enum.members:
        if m.name.endswith("FORCE32"):
            continue
        out += summary(m.comment, "        ")
        out.append(f"        {member_name(enum, m)} = {m.value},")
    out.append("    }")
    out.append("")


def field_lines(struct, f, internal):
    """The C# declaration of one C field."""
    where = (struct.name, f.name)
    if f.function:
        return [f"public IntPtr {pascal(f.name)};"] if internal else [f"internal IntPtr {f.name};"]
    if f.array:
        if f.ctype != "char":
            raise cheader.HeaderError(f"{struct.name}.{f.name}: only char arrays are bound")
        return [f"[MarshalAs(UnmanagedType.ByValArray, SizeConst = {f.array})] internal byte[] {f.name};"]
    if f.pointer:
        return [f"public IntPtr {pascal(f.name)};"] if internal else [f"internal IntPtr {f.name};"]
    t = FIELD_TYPES.get(where) or cs_type(f.ctype)
    if f.name in HIDDEN and not internal:
        return [f"readonly {t} {f.name};"]
    return [f"public {t} {pascal(f.name)};"]


def emit_struct(struct, out):
    name = cs_type(struct.name)
    internal = is_internal(name)
    out += summary(f"{struct.name}: {struct.comment}" if struct.comment else struct.name, "    ")
    out.append("    [StructLayout(LayoutKind.Sequential)]")
    out.append(f"    {'internal' if internal else 'public'} partial struct {name}")
    out.append("    {")
    for f in struct.fields:
        if f.comment:
            out += wrap(f.comment, "        ", "// ")
        out += ["        " + line for line in field_lines(struct, f, internal)]
    out.append("    }")
    out.append("")


def param_decl(function, index):
    p = function.params[index]
    name = ("@" + p.name) if p.name in KEYWORDS else p.name
    later = [q.name for q in function.params[index + 1:]]
    if not p.pointer:
        return f"{cs_type(p.ctype)} {name}"
    if p.ctype == "char" and p.const:
        return f"byte[] utf8{pascal(p.name)}"
    if p.ctype in SCALARS:
        if p.const or (later and later[0].lower().endswith("capacity")):
            return f"{'byte' if p.ctype == 'void' else cs_type(p.ctype)}[] {name}"
        return f"out {cs_type(p.ctype)} {name}"
    if p.const:
        return f"ref {cs_type(p.ctype)} {name}"
    if any(q.lower().endswith("capacity") for q in later):
        return f"{ARRAY_PARAMS.get((function.name, p.name), 'IntPtr')} {name}"
    return f"out {cs_type(p.ctype)} {name}"


def return_type(function):
    r = function.ret
    if r.pointer:
        if r.ctype == "char" and r.const:
            return "IntPtr"  # the library's string: copied (Native.Copy), never freed by the marshaller
        raise cheader.HeaderError(f"{function.name}: returns a pointer")
    return cs_type(r.ctype)


def emit_function(function, out):
    params = [param_decl(function, i) for i in range(len(function.params))]
    ret = return_type(function)
    out.append("        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]")
    out.append(f"        internal static extern {ret} {function.name}({', '.join(params)});")
    for i, p in enumerate(function.params):
        alias = NULLABLE.get((function.name, p.name))
        if alias:
            nullable = list(params)
            nullable[i] = f"IntPtr {p.name}"
            out.append(f"        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, "
                       f"EntryPoint = \"{function.name}\")]")
            out.append(f"        internal static extern {ret} {alias}({', '.join(nullable)});")


def generate_file(header, header_name):
    out = [
        f"// Generated from sdk/include/proxima/{header_name} by bindings/csharp/tools/gen_native.py:",
        "// do not edit. Regenerate with `python3 bindings/csharp/tools/gen_native.py`",
        "// (docs/csharp.md); ctest csharp.generated fails while this file is stale.",
        "using System;",
        "using System.Runtime.InteropServices;",
        "",
        "namespace Proxima",
        "{",
    ]
    enums = {e.name: e for e in header.enums}
    structs = {s.name: s for s in header.structs}
    for kind, name in header.order:
        if name in NOT_GENERATED:
            continue
        if kind == "enum":
            emit_enum(enums[name], out)
        elif kind == "struct":
            emit_struct(structs[name], out)
    out.append("    internal static partial class Native")
    out.append("    {")
    for f in header.functions:
        emit_function(f, out)
    out.append("    }")
    out.append("}")
    return "\n".join(out) + "\n"


META = """fileFormatVersion: 2
guid: {guid}
MonoImporter:
  externalObjects: {{}}
  serializedVersion: 2
  defaultReferences: []
  executionOrder: 0
  icon: {{instanceID: 0}}
  userData: 
  assetBundleName: 
  assetBundleVariant: 
"""
FOLDER_META = """fileFormatVersion: 2
guid: {guid}
folderAsset: yes
DefaultImporter:
  externalObjects: {{}}
  userData: 
  assetBundleName: 
  assetBundleVariant: 
"""


def guid(relative):
    return hashlib.md5(("com.proxima.sdk/" + relative).encode()).hexdigest()


def read_headers(root):
    include = os.path.join(root, "sdk", "include", "proxima")
    return [(cheader.read(os.path.join(include, h)), h, stem) for h, stem in HEADERS]


def outputs(root):
    """{path: text} of every generated file."""
    runtime = os.path.join(root, "bindings", "csharp", "com.proxima.sdk", "Runtime")
    files = {os.path.join(runtime, "Generated.meta"): FOLDER_META.format(guid=guid("Runtime/Generated"))}
    for header, header_name, stem in read_headers(root):
        rel = f"Runtime/Generated/{stem}.g.cs"
        files[os.path.join(runtime, "Generated", stem + ".g.cs")] = generate_file(header, header_name)
        files[os.path.join(runtime, "Generated", stem + ".g.cs.meta")] = META.format(guid=guid(rel))
    return files


def layout_program(root):
    """The C program printing "cName size csName" and "cName.field offset csField"."""
    out = ["/* Generated by bindings/csharp/tools/gen_native.py --layout-c: every struct's and enum's size",
           " * and every field's offset, as the C compiler lays them out, with the C# names they are",
           " * bound to (StructLayoutTests). One \"name value [C# name]\" per line. */",
           "#include <proxima/proxima.h>", "#include <proxima/proxima_hid.h>",
           "#if defined(__has_include)", "#if __has_include(<openxr/openxr.h>)",
           "#define PROX_LAYOUT_OPENXR 1", "#include <proxima/proxima_openxr.h>", "#endif", "#endif", "",
           "#include <stddef.h>", "#include <stdio.h>", "", "int main(void) {"]
    out.append('  printf("proxBool %zu Bool32\\n", sizeof(proxBool));')
    for header, header_name, _ in read_headers(root):
        if header_name == OPENXR:
            out.append("#if PROX_LAYOUT_OPENXR")
        for e in header.enums:
            out.append(f'  printf("{e.name} %zu {cs_type(e.name)}\\n", sizeof({e.name}));')
        for s in header.structs:
            out.append(f'  printf("{s.name} %zu {cs_type(s.name)}\\n", sizeof({s.name}));')
            internal = is_internal(cs_type(s.name))
            for f in s.fields:
                hidden = f.array or ((f.pointer or f.function or f.name in HIDDEN) and not internal)
                cs_field = f.name if hidden else pascal(f.name)
                out.append(f'  printf("{s.name}.{f.name} %zu {cs_field}\\n", offsetof({s.name}, {f.name}));')
        if header_name == OPENXR:
            out.append("#endif")
    out += ["  return 0;", "}"]
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", nargs="?", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                                "..", "..", ".."))
    parser.add_argument("--check", action="store_true", help="compare with the committed files, write nothing")
    parser.add_argument("--layout-c", help="write the struct layout program here instead")
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    try:
        if args.layout_c:
            text = layout_program(root)
            if not os.path.exists(args.layout_c) or open(args.layout_c).read() != text:
                with open(args.layout_c, "w", encoding="utf-8") as f:
                    f.write(text)
            return 0
        files = outputs(root)
    except cheader.HeaderError as e:
        print("gen_native.py: " + str(e), file=sys.stderr)
        return 2
    generated_dir = os.path.join(root, "bindings", "csharp", "com.proxima.sdk", "Runtime", "Generated")
    stale = []
    for path, text in sorted(files.items()):
        old = open(path, encoding="utf-8").read() if os.path.exists(path) else None
        if old == text:
            continue
        stale.append(path)
        if args.check:
            rel = os.path.relpath(path, root)
            sys.stdout.writelines(difflib.unified_diff((old or "").splitlines(True), text.splitlines(True),
                                                       "a/" + rel, "b/" + rel))
        else:
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
    extra = [os.path.join(generated_dir, n) for n in sorted(os.listdir(generated_dir))
             if os.path.join(generated_dir, n) not in files] if os.path.isdir(generated_dir) else []
    for path in extra:
        if args.check:
            print("not generated from any header: " + os.path.relpath(path, root))
        else:
            os.remove(path)
    if args.check:
        if stale or extra:
            print(f"{len(stale) + len(extra)} generated file(s) differ from the headers: run "
                  "python3 bindings/csharp/tools/gen_native.py and commit the result")
            return 1
        print(f"{len(files)} generated files match the headers")
    return 0


if __name__ == "__main__":
    sys.exit(main())
