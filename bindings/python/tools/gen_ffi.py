"""Generates the package's cffi module from the preprocessed proxima.h.

    python gen_ffi.py proxima_cdef.h version.h LIBRARY_NAME OUT_DIR

Writes OUT_DIR/_ffi.py (cffi's out-of-line ABI mode: the parsed header as a
Python module, loaded with ffi.dlopen, no compiler needed at import) and
OUT_DIR/_header.py: what the C types lose in cffi and the package needs, read
from the same parse: the header's version string, which struct fields are
declared proxBool (cffi sees only int32_t), and the library's file name.
"""

import os
import re
import sys

import cffi
import pycparser
from pycparser import c_ast

# Only for pycparser's parse of the fields below; cffi knows these types.
_STDINT = "".join(
    f"typedef int {name};\n"
    for name in ("size_t", "int8_t", "int16_t", "int32_t", "int64_t",
                 "uint8_t", "uint16_t", "uint32_t", "uint64_t", "intptr_t", "uintptr_t")
)


def bool_fields(cdef):
    """{struct name: [field, ...]} of the fields declared proxBool."""
    ast = pycparser.CParser().parse(_STDINT + cdef, "proxima_cdef.h")
    out = {}

    class Visitor(c_ast.NodeVisitor):
        def visit_Struct(self, node):
            for decl in node.decls or []:
                type_decl = decl.type
                if isinstance(type_decl, c_ast.TypeDecl) and isinstance(type_decl.type, c_ast.IdentifierType):
                    if type_decl.type.names == ["proxBool"]:
                        out.setdefault(node.name, []).append(decl.name)
            self.generic_visit(node)

    Visitor().visit(ast)
    return out


def main(cdef_path, version_path, library_name, out_dir):
    with open(cdef_path, encoding="utf-8") as f:
        cdef = f.read()
    with open(version_path, encoding="utf-8") as f:
        match = re.search(r'#define\s+PROX_VERSION_STRING\s+"([^"]+)"', f.read())
    if not match:
        sys.exit(f"{version_path}: no PROX_VERSION_STRING")
    os.makedirs(out_dir, exist_ok=True)

    builder = cffi.FFI()
    builder.cdef(cdef)
    builder.set_source("proxima._ffi", None)
    builder.emit_python_code(os.path.join(out_dir, "_ffi.py"))

    with open(os.path.join(out_dir, "_header.py"), "w", encoding="utf-8") as f:
        f.write('"""Generated from proxima.h by tools/gen_ffi.py."""\n\n')
        f.write(f"VERSION = {match.group(1)!r}\n")
        f.write(f"BOOL_FIELDS = {bool_fields(cdef)!r}\n")
        f.write(f"LIBRARY = {library_name!r}\n")


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit("usage: gen_ffi.py proxima_cdef.h version.h LIBRARY_NAME OUT_DIR")
    main(*sys.argv[1:])
