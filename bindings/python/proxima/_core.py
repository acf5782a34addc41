"""The library, its errors, and the Python and numpy types derived from proxima.h.

Everything about the C types here is read from the cffi module generated from
the header at build time (``_ffi.py``, ``_header.py``): field names, offsets,
sizes and enum values are never written out by hand.
"""

import dataclasses
import os
import re

import numpy as np

from . import _header
from ._ffi import ffi

LIBRARY_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), _header.LIBRARY)
lib = ffi.dlopen(LIBRARY_PATH)

# ---- errors -----------------------------------------------------------------


class Error(Exception):
    """A Proxima call failed. ``result`` is the C ``proxResult`` (negative),
    ``result_name`` its name; the text is the library's message."""

    def __init__(self, message, result=None):
        super().__init__(message)
        self.result = _RESULTS[type(self)] if result is None else result
        self.result_name = ffi.string(lib.proxResultString(self.result)).decode()


class InvalidArgument(Error, ValueError):
    """An argument is NULL, NaN, out of range, of the wrong shape or type."""


class InvalidHandle(Error):
    """A destroyed or foreign object (a body of a closed world, say)."""


class InvalidMesh(Error, ValueError):
    """Mesh data that is empty, non-finite or degenerate."""


class FileError(Error, OSError):
    """A file cannot be read."""


class ParseError(Error):
    """A file's content is malformed."""


class Unsupported(Error):
    """Valid input using a feature Proxima does not support (Draco, say)."""


class VersionMismatch(Error):
    """The header the package was built from and the library disagree."""


class WrongThread(Error):
    """A world was used from a thread other than the one that created it."""


class CapacityError(Error):
    """An output buffer was too small (the package sizes them: never expected)."""


class InternalError(Error):
    """A bug in Proxima: please report it with the message."""


class Busy(Error):
    """The world's threads are running: stop them first."""


# The C results, each to its exception, by the names in proxResult.
_BY_NAME = {
    "PROX_ERROR_INVALID_ARGUMENT": InvalidArgument,
    "PROX_ERROR_INVALID_HANDLE": InvalidHandle,
    "PROX_ERROR_INVALID_MESH": InvalidMesh,
    "PROX_ERROR_FILE": FileError,
    "PROX_ERROR_PARSE": ParseError,
    "PROX_ERROR_UNSUPPORTED": Unsupported,
    "PROX_ERROR_VERSION_MISMATCH": VersionMismatch,
    "PROX_ERROR_WRONG_THREAD": WrongThread,
    "PROX_ERROR_CAPACITY": CapacityError,
    "PROX_ERROR_INTERNAL": InternalError,
    "PROX_ERROR_BUSY": Busy,
}
RESULT_VALUES = {name: value for value, name in ffi.typeof("proxResult").elements.items()}
_RESULTS = {cls: RESULT_VALUES[name] for name, cls in _BY_NAME.items()}
_BY_VALUE = {RESULT_VALUES[name]: cls for name, cls in _BY_NAME.items()}
CAPACITY = RESULT_VALUES["PROX_ERROR_CAPACITY"]
for _cls in [Error, *_BY_NAME.values()]:
    _cls.__module__ = "proxima"


def error_for(result):
    """The exception class of a C result (Error for one this package does not know)."""
    return _BY_VALUE.get(result, Error)


def check(result):
    """Raises the exception of a failed call, with proxGetLastError's message."""
    if result >= 0:
        return result
    message = ffi.string(lib.proxGetLastError()).decode(errors="replace")
    if not message:
        message = ffi.string(lib.proxResultString(result)).decode()
    raise error_for(result)(message, result)


def optional_function(name, lacking):
    """A function of an optional part of the library (proxima_hid.h,
    proxima_openxr.h), or Unsupported saying what the library lacks when it
    was built without that part (cffi looks each function up on first use)."""
    try:
        return getattr(lib, name)
    except AttributeError:
        raise Unsupported(f"{name}: this libproxima has {lacking}") from None


def invalid(message):
    return InvalidArgument(message, _RESULTS[InvalidArgument])


# ---- enums: the header's names, short and lower case -----------------------


def _enum_choices(ctype_name):
    """{"precise": 0, ...} from PROX_METHOD_PRECISE = 0, ...; the FORCE32 members left out."""
    elements = {name: value for value, name in sorted(ffi.typeof(ctype_name).elements.items())
                if not name.endswith("FORCE32")}
    prefix = os.path.commonprefix(list(elements))
    prefix = prefix[: prefix.rfind("_") + 1]
    return {name[len(prefix):].lower(): value for name, value in elements.items()}


_ENUMS = {}


def enum_choices(ctype_name):
    if ctype_name not in _ENUMS:
        _ENUMS[ctype_name] = _enum_choices(ctype_name)
    return _ENUMS[ctype_name]


def enum_value(ctype_name, name, what):
    """The C value of a short name, or InvalidArgument listing the choices."""
    choices = enum_choices(ctype_name)
    if isinstance(name, str) and name in choices:
        return choices[name]
    listed = ", ".join(repr(c) for c in choices)
    raise invalid(f"{what} must be one of {listed}, not {name!r}")


def enum_name(ctype_name, value):
    for name, v in enum_choices(ctype_name).items():
        if v == value:
            return name
    return int(value)


# ---- numpy dtypes of the C structs -------------------------------------------

_PRIMITIVES = {
    "double": "<f8", "float": "<f4", "int8_t": "<i1", "uint8_t": "<u1", "int16_t": "<i2",
    "uint16_t": "<u2", "int32_t": "<i4", "uint32_t": "<u4", "int64_t": "<i8", "uint64_t": "<u8",
    "char": "<i1", "size_t": "<u8",
}
_DTYPES = {}


def _dtype_of(ctype):
    if ctype.kind == "struct":
        names, formats, offsets = [], [], []
        for name, field in ctype.fields:
            names.append(name)
            formats.append(_dtype_of(field.type))
            offsets.append(field.offset)
        return np.dtype({"names": names, "formats": formats, "offsets": offsets,
                         "itemsize": ffi.sizeof(ctype)})
    if ctype.kind == "enum":
        return np.dtype("<i%d" % ffi.sizeof(ctype))
    if ctype.kind == "primitive":
        return np.dtype(_PRIMITIVES[ctype.cname])
    if ctype.kind in ("pointer", "function"):
        return np.dtype("<u%d" % ffi.sizeof("void*"))
    if ctype.kind == "array":
        return np.dtype((_dtype_of(ctype.item), ctype.length))
    raise TypeError(f"no numpy dtype for {ctype.cname}")


def c_dtype(name):
    """The numpy structured dtype of a C struct of proxima.h, from the parsed
    header: the same field names, offsets and itemsize as the C compiler's."""
    if name not in _DTYPES:
        _DTYPES[name] = _dtype_of(ffi.typeof(name))
    return _DTYPES[name]


def struct_array(cdata, name):
    """A numpy view of a cffi array of C structs (no copy)."""
    return np.frombuffer(ffi.buffer(cdata), dtype=c_dtype(name))


# ---- dataclasses of the C structs ----------------------------------------------

# The fields a def carries for the library, never a setting.
HIDDEN_FIELDS = ("reserved", "internalValue", "apiVersion")


def snake(name):
    """pointTool -> point_tool, periodP50 -> period_p50, index1 -> index1."""
    return re.sub(r"(?<=[a-z0-9])([A-Z])", r"_\1", name).lower()


def _struct_name(ctype):
    return ctype.cname.replace("struct ", "")


def _field_kind(struct_name, field_name, ctype):
    if field_name in _header.BOOL_FIELDS.get(struct_name, ()):
        return "bool"
    if ctype.kind == "struct" and _struct_name(ctype) == "proxVec3":
        return "vec3"
    if ctype.kind == "enum":
        return "enum"
    if ctype.kind == "primitive":
        return "float" if ctype.cname in ("double", "float") else "int"
    raise TypeError(f"{struct_name}.{field_name}: no Python form for {ctype.cname}")


_PY_TYPES = {"bool": bool, "vec3": np.ndarray, "enum": str, "float": float, "int": int}


def make_dataclass(struct_name, class_name, doc, defaults=None):
    """A dataclass with the struct's fields in snake_case (reserved and
    internal fields left out). ``defaults``, a C struct value, gives every
    field a default."""
    ctype = ffi.typeof(struct_name)
    fields, kinds = [], {}
    for name, field in ctype.fields:
        if name in HIDDEN_FIELDS:
            continue
        kind = _field_kind(struct_name, name, field.type)
        kinds[snake(name)] = (name, kind, field.type)
        spec = (snake(name), _PY_TYPES[kind])
        if defaults is not None:
            spec += (dataclasses.field(default=_to_python(getattr(defaults, name), kind, field.type)),)
        fields.append(spec)
    cls = dataclasses.make_dataclass(class_name, fields, eq=not any(k == "vec3" for _, k, _ in kinds.values()))
    cls.__module__ = "proxima"
    cls.__doc__ = doc
    cls._c_struct = struct_name
    cls._c_fields = kinds
    return cls


def _to_python(value, kind, ctype):
    if kind == "bool":
        return bool(value)
    if kind == "vec3":
        return np.array([value.x, value.y, value.z])
    if kind == "enum":
        return enum_name(ctype.cname, value)
    return value


def from_c(cls, value):
    """A dataclass instance from a C struct value."""
    return cls(**{py: _to_python(getattr(value, c), kind, ctype)
                  for py, (c, kind, ctype) in cls._c_fields.items()})


def fill_c(obj, out, what):
    """Writes a dataclass instance into a C struct (a cdata pointer's target)."""
    for py, (c, kind, ctype) in obj._c_fields.items():
        value = getattr(obj, py)
        where = f"{what}.{py}"
        if kind == "enum":
            value = enum_value(ctype.cname, value, where)
        elif kind == "vec3":
            x, y, z = vec3(value, where)
            value = {"x": x, "y": y, "z": z}
        elif kind == "bool":
            value = bool(value)
        elif kind == "float":
            value = real(value, where)
        else:
            value = integer(value, where)
        setattr(out, c, value)


# ---- argument checks ---------------------------------------------------------------


def real(value, what):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise invalid(f"{what} must be a number, not {value!r}")
    return float(value)


def integer(value, what):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise invalid(f"{what} must be an integer, not {value!r}")
    return int(value)


def numbers(value, count, what):
    """A float64 array of exactly `count` numbers (finiteness is the library's check)."""
    try:
        array = np.asarray(value)
    except (ValueError, TypeError):
        raise invalid(f"{what} must be {count} numbers, not {value!r}") from None
    if array.dtype.kind not in "fiu" or array.shape != (count,):
        raise invalid(f"{what} must be {count} numbers, got {_describe(array)}")
    return array.astype(np.float64)


def vec3(value, what):
    return numbers(value, 3, what)


def _describe(array):
    return f"shape {array.shape} of {array.dtype}"


def pose_to_c(pose, out, what="pose"):
    """Writes (position, quaternion_wxyz) into a proxPose."""
    if not isinstance(pose, (tuple, list)) or len(pose) != 2:
        raise invalid(f"{what} must be (position, quaternion_wxyz), not {pose!r}")
    p = vec3(pose[0], f"{what} position")
    q = numbers(pose[1], 4, f"{what} quaternion (w, x, y, z)")
    out.position = {"x": p[0], "y": p[1], "z": p[2]}
    out.rotation = {"w": q[0], "x": q[1], "y": q[2], "z": q[3]}


def pose_from_c(pose):
    p, q = pose.position, pose.rotation
    return np.array([p.x, p.y, p.z]), np.array([q.w, q.x, q.y, q.z])


def poses_array(poses, what):
    """A sequence of poses as a (K, 7) float64 array: tx ty tz qw qx qy qz per row.
    Takes a (K, 7) array or a sequence of (position, quaternion) pairs."""
    try:
        array = np.asarray(poses)
    except (ValueError, TypeError):
        array = None
    if array is not None and array.dtype.kind in "fiu" and array.ndim == 2 and array.shape[1] == 7:
        return np.ascontiguousarray(array, dtype=np.float64)
    if isinstance(poses, (list, tuple)):
        rows = []
        for i, pose in enumerate(poses):
            if not isinstance(pose, (tuple, list)) or len(pose) != 2:
                break
            rows.append(np.concatenate([vec3(pose[0], f"{what}[{i}] position"),
                                        numbers(pose[1], 4, f"{what}[{i}] quaternion")]))
        else:
            return np.array(rows, dtype=np.float64).reshape(-1, 7)
    raise invalid(f"{what} must be a (K, 7) array of tx ty tz qw qx qy qz rows "
                  "or a sequence of (position, quaternion) pairs")


def version_string():
    v = lib.proxGetVersion()
    return f"{v.major}.{v.minor}.{v.patch}"


HEADER_VERSION = _header.VERSION
if version_string() != HEADER_VERSION:
    raise VersionMismatch(f"proxima {HEADER_VERSION} was built for its own header but loaded "
                          f"{LIBRARY_PATH}, version {version_string()}")
