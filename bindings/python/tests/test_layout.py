"""The dtypes and the cffi types against the C compiler's layout of proxima.h."""

import os
import shutil
import subprocess

import numpy as np
import pytest

import proxima
from proxima._core import ffi

from conftest import REPO


def _structs():
    # XrActionSuggestedBinding: of tools/cffi_openxr's OpenXR types, the struct.
    return sorted(name for name in ffi.list_types()[1]
                  if name.startswith("prox") or name == "XrActionSuggestedBinding")


@pytest.fixture(scope="module")
def c_layout(tmp_path_factory):
    """{struct: sizeof} and {(struct, field): offsetof}, from a C program
    compiled against the repository's header."""
    compiler = os.environ.get("CC") or shutil.which("cc") or shutil.which("gcc")
    assert compiler, "a C compiler (cc) is needed to check the layouts"
    # proxima_openxr.h with the real <openxr/openxr.h> (libopenxr-dev), against
    # which the package's own few OpenXR types (tools/cffi_openxr) are checked.
    lines = ["#include <stddef.h>", "#include <stdio.h>", "#include <proxima/proxima.h>",
             "#include <proxima/proxima_hid.h>", "#include <proxima/proxima_openxr.h>", "int main(void) {"]
    for value, name in ffi.typeof("XrSessionState").elements.items():
        lines.append(f'  printf("{name} %d\\n", (int){name});')
    for name in ("XrInstance", "XrSession", "XrSpace", "XrAction", "XrActionSet", "XrPath", "XrTime"):
        lines.append(f'  printf("{name} %zu\\n", sizeof({name}));')
    for name in _structs():
        lines.append(f'  printf("{name} %zu\\n", sizeof(struct {name}));')
        for field, _ in ffi.typeof(f"struct {name}").fields:
            lines.append(f'  printf("{name}.{field} %zu\\n", offsetof(struct {name}, {field}));')
    lines.append("  return 0;\n}")
    tmp = tmp_path_factory.mktemp("layout")
    (tmp / "layout.c").write_text("\n".join(lines))
    built = subprocess.run([compiler, "-std=c11", "-I", str(REPO / "sdk/include"), str(tmp / "layout.c"), "-o",
                            str(tmp / "layout")], capture_output=True, text=True)
    assert built.returncode == 0, ("the layout program needs the OpenXR headers (Debian: libopenxr-dev) "
                                   "beside a C compiler:\n" + built.stderr)
    out = subprocess.run([str(tmp / "layout")], check=True, capture_output=True, text=True).stdout
    return dict((k, int(v)) for k, v in (line.split() for line in out.splitlines()))


def test_every_struct_has_the_compilers_layout(c_layout):
    structs = _structs()
    assert {"proxContact", "proxPolylineInfo", "proxWorldStats", "proxThreadStats", "proxSearchStats",
            "proxHidDeviceDef", "proxHidDeviceInfo", "proxHidDeviceStats", "proxXrDeviceDef", "proxXrDeviceStats",
            "XrActionSuggestedBinding"} <= set(structs)
    for name in structs:
        dtype = proxima.c_dtype(name)
        assert dtype.itemsize == c_layout[name] == ffi.sizeof(f"struct {name}"), name
        for field in dtype.names:
            assert dtype.fields[field][1] == c_layout[f"{name}.{field}"], f"{name}.{field}"


def test_the_openxr_types_are_openxr_h_s(c_layout):
    # tools/cffi_openxr stands in for <openxr/openxr.h>: the same enum values
    # and sizes as the real header (the structs are checked above).
    for value, name in ffi.typeof("XrSessionState").elements.items():
        assert c_layout[name] == value, name
    for name in ("XrInstance", "XrSession", "XrSpace", "XrAction", "XrActionSet", "XrPath", "XrTime"):
        assert c_layout[name] == ffi.sizeof(name) == 8, name


def test_contact_dtype_reads_what_the_library_wrote(world):
    from conftest import BUNNY, NEAR_POSE
    m = world.load_mesh(BUNNY)
    world.create_body(m, "static")
    tool = world.create_body(m, "tool", pose=NEAR_POSE)
    world.step()
    buf = ffi.new("proxContact[]", 16)
    count = ffi.new("int32_t*")
    assert proxima._core.lib.proxBody_GetContacts(tool._idp[0], buf, 16, count) == 0
    raw = np.frombuffer(ffi.buffer(buf, count[0] * ffi.sizeof("proxContact")), dtype=proxima.c_dtype("proxContact"))
    public = tool.contacts()
    for i in range(count[0]):
        assert raw["distance"][i] == buf[i].distance == public["distance"][i]
        assert raw["triangleOther"][i] == buf[i].triangleOther == public["triangle_other"][i]
        assert raw["featureTool"][i] == buf[i].featureTool == public["feature_tool"][i]
        assert raw["pointTool"]["z"][i] == buf[i].pointTool.z == public["point_tool"][i, 2]
        assert raw["other"]["index1"][i] == buf[i].other.index1
