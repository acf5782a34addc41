"""A reader of Proxima's public C headers, for gen_native.py: the enums,
structs and functions, in header order, with their comments.

It reads the subset of C the headers are written in (docs/c-api.md's rules:
`typedef enum X {...} X;`, `typedef struct X {...} X;`, `PROX_API` function
declarations, fixed-width types) and stops with an error on anything else
inside those, so that a header change it does not understand is never
silently dropped from the bindings. Standard library only.
"""

import re
from dataclasses import dataclass, field


class HeaderError(Exception):
    pass


@dataclass
class EnumMember:
    name: str
    value: str
    comment: str


@dataclass
class Enum:
    name: str
    members: list
    comment: str


@dataclass
class Field:
    name: str
    ctype: str          # the base type: int32_t, proxVec3, char, ...
    pointer: bool       # a pointer (any), or a function pointer
    const: bool
    array: int          # element count of a fixed array, else 0
    function: bool      # a function pointer
    comment: str


@dataclass
class Struct:
    name: str
    fields: list
    comment: str


@dataclass
class Param:
    name: str
    ctype: str
    pointer: bool
    const: bool


@dataclass
class Function:
    name: str
    ret: Param
    params: list
    comment: str


@dataclass
class Header:
    path: str
    enums: list = field(default_factory=list)
    structs: list = field(default_factory=list)
    functions: list = field(default_factory=list)
    typedefs: dict = field(default_factory=dict)  # scalar typedefs: proxBool -> int32_t
    order: list = field(default_factory=list)     # (kind, name) in header order


_COMMENT = re.compile(r"/\*.*?\*/", re.S)


def _clean_comment(text):
    """A C comment's words, without the /* */ and the leading stars."""
    body = text.strip()[2:-2]
    lines = [re.sub(r"^\s*\*+ ?", "", line) for line in body.split("\n")]
    text = " ".join(" ".join(lines).split())
    # A section rule ("---- devices ----") titles what follows, it says nothing of it.
    return re.sub(r"^-{2,}[^-]*-{2,}\s*", "", text)


def _strip(text):
    return _COMMENT.sub(" ", text)


def _preprocess(text):
    """Drops #ifdef __cplusplus blocks and preprocessor lines, keeping line count."""
    text = re.sub(r"#ifdef __cplusplus.*?#endif", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    out = []
    continued = False
    for line in text.split("\n"):
        if continued or line.lstrip().startswith("#"):
            continued = line.rstrip().endswith("\\")
            out.append("")
        else:
            out.append(line)
    return "\n".join(out)


def _chunks(body, separator):
    """(declaration, leading comment, trailing comment) for each `separator`-ended
    declaration of a struct or enum body; a comment on the declaration's own
    line (after it) is its trailing one, the others lead the next."""
    items = []
    pending = []
    pos = 0
    token = re.compile(r"/\*.*?\*/|[^/%s]+%s|[^/%s]+" % (separator, separator, separator), re.S)
    for m in token.finditer(body):
        text = m.group(0)
        if text.startswith("/*"):
            before = body[pos:m.start()] if items else "\n"
            if items and "\n" not in before and items[-1][2] == "" and not pending:
                items[-1] = (items[-1][0], items[-1][1], _clean_comment(text))
            else:
                pending.append(_clean_comment(text))
        elif text.strip().strip(separator).strip():
            items.append((text.strip().rstrip(separator).strip(), " ".join(pending), ""))
            pending = []
        else:
            continue
        pos = m.end()
    if "".join(m.group(0) for m in token.finditer(body)) != body:
        raise HeaderError("a stray '/' in %r" % body[:60])
    return items


def _type_and_name(decl, where):
    """(base type, pointer, const, name) of "const proxPose* poses"."""
    m = re.fullmatch(r"(const\s+)?(\w+)\s*(\*?)\s*(\w+)", decl.strip())
    if not m:
        raise HeaderError(f"{where}: cannot read declaration {decl.strip()!r}")
    return m.group(2), bool(m.group(3)), bool(m.group(1)), m.group(4)


def _fields(struct_name, body):
    fields = []
    for decl, lead, trail in _chunks(body, ";"):
        comment = " ".join(c for c in (lead, trail) if c)
        where = f"struct {struct_name}"
        fp = re.fullmatch(r"(\w+)\s*\(\s*\*\s*(\w+)\s*\)\s*\((.*)\)", decl, re.S)
        if fp:
            fields.append(Field(fp.group(2), fp.group(1), True, False, 0, True, comment))
            continue
        m = re.fullmatch(r"(const\s+)?(\w+)(\s*\*)?\s+(.+)", " ".join(decl.split()))
        if not m:
            raise HeaderError(f"{where}: cannot read field {decl!r}")
        const, ctype, star, names = bool(m.group(1)), m.group(2), bool(m.group(3)), m.group(4)
        for part in names.split(","):
            n = re.fullmatch(r"\s*(\*?)\s*(\w+)\s*(?:\[\s*(\d+)\s*\])?\s*", part)
            if not n:
                raise HeaderError(f"{where}: cannot read field {part!r} of {decl!r}")
            fields.append(Field(n.group(2), ctype, star or bool(n.group(1)), const,
                                int(n.group(3) or 0), False, comment))
    return fields


def _members(enum_name, body):
    members = []
    for decl, lead, trail in _chunks(body, ","):
        m = re.fullmatch(r"(\w+)\s*=\s*([-\w]+)", " ".join(decl.split()))
        if not m:
            raise HeaderError(f"enum {enum_name}: cannot read member {decl!r} (members need explicit values)")
        members.append(EnumMember(m.group(1), m.group(2), " ".join(c for c in (lead, trail) if c)))
    return members


def _params(function_name, text):
    text = " ".join(text.split())
    if text in ("void", ""):
        return []
    params = []
    for part in text.split(","):
        ctype, pointer, const, name = _type_and_name(part, "function " + function_name)
        params.append(Param(name, ctype, pointer, const))
    return params


_DECL = re.compile(
    r"(?P<comment>/\*(?:(?!\*/).)*\*/\s*)?"
    r"(?:typedef\s+enum\s+(?P<enum>\w+)\s*\{(?P<enum_body>.*?)\}\s*(?P=enum)\s*;"
    r"|typedef\s+struct\s+(?P<struct>\w+)\s*\{(?P<struct_body>.*?)\}\s*(?P=struct)\s*;"
    r"|typedef\s+(?P<alias_type>\w+)\s+(?P<alias>\w+)\s*;"
    r"|PROX_API\s+(?P<function>[^;]*?\))\s*;)",
    re.S,
)


def read(path):
    """The declarations of one header (not those of the headers it includes)."""
    with open(path, encoding="utf-8") as f:
        text = _preprocess(f.read())
    header = Header(path)
    for m in _DECL.finditer(text):
        comment = _clean_comment(m.group("comment")) if m.group("comment") else ""
        if m.group("enum"):
            header.enums.append(Enum(m.group("enum"), _members(m.group("enum"), m.group("enum_body")), comment))
            header.order.append(("enum", m.group("enum")))
        elif m.group("struct"):
            header.structs.append(Struct(m.group("struct"), _fields(m.group("struct"), m.group("struct_body")),
                                         comment))
            header.order.append(("struct", m.group("struct")))
        elif m.group("alias"):
            header.typedefs[m.group("alias")] = m.group("alias_type")
        else:
            decl = _strip(m.group("function"))
            f = re.fullmatch(r"\s*(const\s+)?(\w+)\s*(\*?)\s*(\w+)\s*\((.*)\)\s*", decl, re.S)
            if not f:
                raise HeaderError(f"{path}: cannot read function {decl.strip()!r}")
            ret = Param("", f.group(2), bool(f.group(3)), bool(f.group(1)))
            header.functions.append(Function(f.group(4), ret, _params(f.group(4), f.group(5)), comment))
            header.order.append(("function", f.group(4)))
    # Whatever names a prox function or type and was not read is a construct
    # this reader does not know: refuse rather than drop it.
    declared = len(re.findall(r"^\s*PROX_API\b", _strip(text), re.M))
    if declared != len(header.functions):
        raise HeaderError(f"{path}: {declared} PROX_API declarations but {len(header.functions)} read")
    typedefs = len(re.findall(r"\btypedef\b", _strip(text)))
    if typedefs != len(header.enums) + len(header.structs) + len(header.typedefs):
        raise HeaderError(f"{path}: {typedefs} typedefs but only "
                          f"{len(header.enums) + len(header.structs) + len(header.typedefs)} read")
    return header
