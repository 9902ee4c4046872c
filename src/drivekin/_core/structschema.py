"""WPILib struct schemas as :mod:`drivekin.datalog` decodes them: the schemas drivekin
knows without a log publishing them, the parse of a schema's members, the plan of a
struct's doubles (nested structs resolved without recursion, sizes refused before
anything is built) and the numeric layout of an entry type.

Its errors are :class:`drivekin.datalog.DataLogError`. datalog imports this module and
this module datalog, each as a module object used only inside functions, so either can
be imported first."""
from __future__ import annotations

import re
from typing import Any, NamedTuple

import numpy as np

from drivekin import datalog
from drivekin._core import catalog
from drivekin._core.errors import clip, cut

# Schemas drivekin knows even when a log does not publish them: drivekin's own types
# (WPILib 2027 names) and the 2026 names of the same layouts.
_KNOWN_SCHEMAS: dict[str, str] = {}
# Repeated structs (one type per member count, SwerveDriveKinematics__N): name -> entry.
REPEATED: dict[str, catalog.Entry] = {}
for _e in catalog.ENTRIES:
    if _e.struct is not None:
        if _e.struct.repeats is None:
            _KNOWN_SCHEMAS[_e.struct.name] = _e.struct.schema
        else:
            REPEATED[_e.struct.name] = _e
_KNOWN_SCHEMAS.update({
    "ChassisSpeeds": "double vx;double vy;double omega",
    "SwerveModuleState": "double speed;Rotation2d angle",
    "MecanumDriveWheelSpeeds": _KNOWN_SCHEMAS["MecanumDriveWheelVelocities"],
    "DifferentialDriveWheelSpeeds": _KNOWN_SCHEMAS["DifferentialDriveWheelVelocities"],
})
del _e

REPEATED_NAME = re.compile("(" + "|".join(REPEATED) + r")__(\d+)")

# Limits on what one struct element may decode to (WPILib's structs have a few dozen
# doubles at most): column count and the total length of the column names. A schema is
# measured before anything is built from it, so a hostile one ("double d[200000000]", or
# structs nested a thousand times a thousand) is refused without allocating its columns.
_MAX_COLUMNS = 1 << 16                  # 512 KiB of doubles per element
_MAX_COLUMN_CHARS = 1 << 23
_MAX_COUNT_DIGITS = 9                   # an array count of more is beyond _MAX_COLUMNS
_DOUBLE = ("double", "float64")
_OTHER_SCALARS = frozenset(("bool", "char", "int8", "int16", "int32", "int64", "uint8",
                            "uint16", "uint32", "uint64", "float", "float32"))
# Bytes of each scalar type (WPILib packs struct members without padding, little-endian).
SCALAR_BYTES = {"double": 8, "float64": 8, "bool": 1, "char": 1, "int8": 1, "uint8": 1,
                "int16": 2, "uint16": 2, "int32": 4, "uint32": 4, "int64": 8, "uint64": 8,
                "float": 4, "float32": 4}


class _Member(NamedTuple):
    name: str
    type: str
    count: int | None  # type: ignore[assignment]  # (shadows tuple.count) None: not an array
    special: str | None = None          # "enum" or "bit field": what only tables decode


def _tokens(decl: str) -> list[str] | None:
    """Split one schema declaration into words (runs of word characters), enum bodies
    (``{...}``, one token) and the punctuation ``[ ] :``; None if another character
    occurs. One pass, no backtracking."""
    out: list[str] = []
    i, n = 0, len(decl)
    while i < n:
        c = decl[i]
        if c.isspace():
            i += 1
        elif c.isalnum() or c == "_":
            j = i + 1
            while j < n and (decl[j].isalnum() or decl[j] == "_"):
                j += 1
            out.append(decl[i:j])
            i = j
        elif c == "{":
            j = decl.find("}", i)
            if j < 0:
                return None
            out.append(decl[i:j + 1])
            i = j + 1
        elif c in "[]:":
            out.append(c)
            i += 1
        else:
            return None
    return out


def _word(t: str) -> bool:
    return t[0].isalnum() or t[0] == "_"


def _parse_member(struct: str, decl: str) -> _Member:
    """One member of a schema: ``[enum {...}] type name [[count]] [: bits]``."""
    toks = _tokens(decl)

    def bad() -> datalog.DataLogError:
        return datalog.DataLogError(f"struct:{cut(struct)}: cannot parse schema member "
                                    f"{clip(decl.strip())}")

    if toks is None:
        raise bad()
    enum = len(toks) >= 2 and toks[0] == "enum" and toks[1][0] == "{"
    i = 2 if enum else 0
    if len(toks) < i + 2 or not (_word(toks[i]) and _word(toks[i + 1])):
        raise bad()
    mtype, mname = toks[i], toks[i + 1]
    i += 2
    count = None
    if i < len(toks) and toks[i] == "[":
        if i + 2 >= len(toks) or toks[i + 2] != "]" or not (toks[i + 1].isascii()
                                                            and toks[i + 1].isdigit()):
            raise bad()
        digits = toks[i + 1].lstrip("0") or "0"
        if len(digits) > _MAX_COUNT_DIGITS:
            raise datalog.DataLogError(f"struct:{cut(struct)}: member {clip(mname)} has an "
                                       f"array count of {len(digits)} digits, more than any "
                                       f"log holds")
        count = int(digits)
        i += 3
    bits = i < len(toks) and toks[i] == ":"
    if bits:
        if i + 1 >= len(toks) or not (toks[i + 1].isascii() and toks[i + 1].isdigit()):
            raise bad()
        i += 2
    if i != len(toks):
        raise bad()
    return _Member(mname, mtype, count, "bit field" if bits else "enum" if enum else None)


def _check_member(struct: str, m: _Member, typed: bool) -> None:
    """Refuse what the decoder at hand cannot decode: anything but doubles for
    :meth:`LogData.values` (``typed=False``), bit fields for tables."""
    if typed:
        if m.special == "bit field":
            raise datalog.DataLogError(f"struct:{cut(struct)}: member {clip(m.name)} is a bit "
                                       f"field, which drivekin does not decode; "
                                       f"LogData.records gives the raw bytes")
        return
    if m.special is not None:
        raise datalog.DataLogError(f"struct:{cut(struct)}: member {clip(m.name)} is an enum or "
                                   f"bit field; only structs of doubles are decoded")
    if m.type in _OTHER_SCALARS:
        raise datalog.DataLogError(f"struct:{cut(struct)}: member {clip(m.name)} is {m.type}; "
                                   f"only structs of doubles are decoded")


def _members(name: str, schemas: dict[str, str]) -> list[_Member]:
    """The parsed members of struct ``name``: the log's schema first, then drivekin's."""
    schema = schemas.get(name)
    if schema is None:
        schema = _KNOWN_SCHEMAS.get(name)
        m = REPEATED_NAME.fullmatch(name)
        if schema is None and m:
            schema = f"{REPEATED[m.group(1)].struct.schema}[{m.group(2)}]"  # type: ignore[union-attr]
    if schema is None:
        raise datalog.DataLogError(f"no schema for struct:{cut(name)} in the log, and it is not "
                                   f"a WPILib type drivekin knows")
    return [_parse_member(name, d) for d in schema.split(";") if d.strip()]


def _digits_below(n: int) -> int:
    """Total decimal digits of 0, 1, ..., n - 1 (the indices in ``name[i]``)."""
    total, width, low = 0, 1, 0
    while low < n:
        high = min(n, 10 ** width)
        total += (high - low) * width
        low, width = high, width + 1
    return total


class _Plan(NamedTuple):
    root: str
    members: dict[str, list[_Member]]   # every struct reachable from root
    columns: int                        # columns per element of root (doubles, untyped)
    nbytes: dict[str, int]              # bytes per element of each struct


def _struct_plan(root: str, schemas: dict[str, str], typed: bool = False) -> _Plan:
    """Parse struct ``root`` and every struct it nests (an explicit stack, so any depth
    works; a cycle is an error), then count its columns bottom-up, refusing a struct
    beyond _MAX_COLUMNS / _MAX_COLUMN_CHARS before any column is built. Untyped, every
    member must be a double (one column each); typed, any scalar but bit fields (a char
    array is one text column)."""
    def parsed(name: str) -> list[_Member]:
        got = _members(name, schemas)
        for m in got:
            _check_member(name, m, typed)
        return got

    members = {root: parsed(root)}
    state = {root: 1}                   # 1: on the path, 2: done
    path, todo, order = [root], [iter(members[root])], []
    while todo:
        for m in todo[-1]:
            if m.type in SCALAR_BYTES or state.get(m.type) == 2:
                continue
            if state.get(m.type) == 1:
                cycle = path[path.index(m.type):] + [m.type]
                shown = (" -> ".join(cycle) if len(cycle) <= 8 else
                         " -> ".join(cycle[:3]) + f" -> ... ({len(cycle) - 6} more) -> "
                         + " -> ".join(cycle[-3:]))
                raise datalog.DataLogError(f"struct:{cut(m.type)} contains itself (schema cycle "
                                           f"{cut(shown, 300)})")
            members[m.type] = parsed(m.type)
            state[m.type] = 1
            path.append(m.type)
            todo.append(iter(members[m.type]))
            break
        else:
            todo.pop()
            done = path.pop()
            state[done] = 2
            order.append(done)
    ncols: dict[str, int] = {}
    chars: dict[str, int] = {}
    nbytes: dict[str, int] = {}
    for s in order:                     # nested structs before the structs holding them
        n = c = b = 0
        for m in members[s]:
            reps = 1 if m.count is None else m.count
            text = m.type == "char"
            elem = (len(m.name) if m.count is None or text
                    else reps * (len(m.name) + 2) + _digits_below(reps))
            if m.type in SCALAR_BYTES:
                n += 1 if text else reps
                c += elem
                b += reps * SCALAR_BYTES[m.type]
            else:
                sn = ncols[m.type]
                n += reps * sn
                c += elem * sn + reps * (sn + chars[m.type])
                b += reps * nbytes[m.type]
            if n > _MAX_COLUMNS or c > _MAX_COLUMN_CHARS:
                raise datalog.DataLogError(
                    f"struct:{cut(root)} has more than {_MAX_COLUMNS} doubles per element "
                    f"(at member {clip(m.name)} of struct:{cut(s)}) or column names of "
                    f"more than {_MAX_COLUMN_CHARS} characters; drivekin decodes smaller "
                    f"structs")
        if n == 0:
            raise datalog.DataLogError(f"struct:{cut(s)} has no members")
        ncols[s], chars[s], nbytes[s] = n, c, b
    return _Plan(root, members, ncols[root], nbytes)


def plan_columns(plan: _Plan) -> tuple[str, ...]:
    """Column paths of a planned struct (one per double, nested structs inlined), built
    top-down with an explicit stack."""
    out: list[str] = []
    stack: list[tuple[str, str | None]] = [("", plan.root)]
    while stack:
        prefix, s = stack.pop()
        if s is None:
            out.append(prefix)
            continue
        items: list[tuple[str, str | None]] = []
        for m in plan.members[s]:
            elems = [m.name] if m.count is None else [f"{m.name}[{i}]" for i in range(m.count)]
            if m.type in _DOUBLE:
                items += [(prefix + e, None) for e in elems]
            else:
                items += [(prefix + e + ".", m.type) for e in elems]
        stack += reversed(items)
    return tuple(out)


class Field(NamedTuple):
    path: str                           # "translation.x", "modules[2].angle.value"
    type: str                           # a SCALAR_BYTES type
    offset: int                         # bytes into one element
    chars: int | None                   # a char array's length (one text column)


def plan_fields(plan: _Plan) -> list[Field]:
    """The scalar fields of a typed plan in schema order, each with its byte offset in
    one element (nested structs and scalar arrays inlined, a char array one field),
    built top-down with an explicit stack."""
    out: list[Field] = []
    stack: list[Field | tuple[str, str, int]] = [("", plan.root, 0)]
    while stack:
        top = stack.pop()
        if isinstance(top, Field):
            out.append(top)
            continue
        prefix, s, offset = top
        items: list[Field | tuple[str, str, int]] = []
        for m in plan.members[s]:
            if m.type == "char" and m.count is not None:
                items.append(Field(prefix + m.name, "char", offset, m.count))
                offset += m.count
                continue
            size = SCALAR_BYTES.get(m.type) or plan.nbytes[m.type]
            elems = [m.name] if m.count is None else [f"{m.name}[{i}]" for i in range(m.count)]
            for e in elems:
                items.append(Field(prefix + e, m.type, offset, None) if m.type in SCALAR_BYTES
                             else (prefix + e + ".", m.type, offset))
                offset += size
        stack += reversed(items)
    return out


def typed_plan(name: str, schemas: dict[str, str]) -> _Plan:
    """The plan of struct ``name`` with members of any scalar type but bit fields (for
    tables), resolving nested structs with the log's schemas first, then drivekin's."""
    return _struct_plan(name, schemas, typed=True)


def struct_columns(name: str, schemas: dict[str, str]) -> tuple[str, ...]:
    """Column paths of struct ``name`` (one per double), resolving nested structs with
    the log's schemas first, then drivekin's; DataLogError for anything but doubles."""
    return plan_columns(_struct_plan(name, schemas))


_PLAIN = {  # type -> (numpy dtype of one element, output dtype)
    "double": ("<f8", np.float64), "float": ("<f4", np.float64),
    "int64": ("<i8", np.int64), "boolean": ("u1", np.bool_),
}


class Layout(NamedTuple):
    scalar: str                         # numpy dtype of one stored scalar
    out: Any                            # numpy dtype of the values
    k: int                              # scalars per element (struct doubles, or 1)
    is_array: bool
    plan: _Plan | None                  # structs


def layout(type_string: str, schemas: dict[str, str]) -> Layout:
    """How a type string decodes as numbers, or DataLogError if it does not."""
    is_array = type_string.endswith("[]")
    base = type_string[:-2] if is_array else type_string
    if base in _PLAIN:
        return Layout(_PLAIN[base][0], _PLAIN[base][1], 1, is_array, None)
    if base.startswith("struct:") and len(base) > 7:
        plan = _struct_plan(base[7:], schemas)
        return Layout("<f8", np.float64, plan.columns, is_array, plan)
    raise datalog.DataLogError(f"entry type {clip(type_string)} is not numeric; readable types: "
                               f"double, float, int64, boolean, their arrays, and struct:<T> or "
                               f"struct:<T>[] of doubles")
