"""One entry of a log as named columns (:meth:`drivekin.datalog.LogData.table`): the
decoding of every entry type into numpy arrays, structs by their typed schema plan.

Columns have one row per record, sorted by timestamp (stable). Numbers come from the
record bytes without per-record Python objects wherever the records agree in size;
per-record objects are built only for text, raw bytes and arrays that change length,
and those are bounded by the record count (and, for struct arrays, refused beyond
_MAX_CELLS before any is built)."""
from __future__ import annotations

import struct
from typing import Any

import numpy as np

from drivekin import datalog
from drivekin._core import structschema
from drivekin._core import wpilog as _wpilog
from drivekin._core.errors import clip

# numpy dtype of one stored scalar, and of its column.
_SCALARS: dict[str, tuple[str, Any]] = {
    "double": ("<f8", np.float64), "float64": ("<f8", np.float64),
    "float": ("<f4", np.float64), "float32": ("<f4", np.float64),
    "int8": ("i1", np.int8), "int16": ("<i2", np.int16), "int32": ("<i4", np.int32),
    "int64": ("<i8", np.int64), "uint8": ("u1", np.uint8), "uint16": ("<u2", np.uint16),
    "uint32": ("<u4", np.uint32), "uint64": ("<u8", np.uint64),
    "bool": ("u1", np.bool_), "boolean": ("u1", np.bool_),
}
_TEXT = frozenset(("string", "json", "structschema"))
# Per-record arrays (cells) an array entry that changes length may give: records times
# columns. A struct of 65,536 columns in a million records would be 6.5e10 objects.
_MAX_CELLS = 1 << 22


def table(entry: Any, typed_plan: Any, what: str) -> dict[str, np.ndarray]:
    """The columns of one entry (a datalog._Entry of one type): ``typed_plan(type)``
    gives the typed plan of a struct type; ``what`` names the entry in errors."""
    type_string = entry.types[0]
    ts = entry.ts
    order = (np.argsort(ts, kind="stable") if len(ts) > 1 and (np.diff(ts) < 0).any()
             else None)
    out: dict[str, np.ndarray] = {"timestamp": ts.copy() if order is None else ts[order]}
    is_array = type_string.endswith("[]")
    base = type_string[:-2] if is_array else type_string
    if base in ("double", "float", "int64", "boolean"):
        fields = [structschema.Field("value", base, 0, None)]
        elem = int(np.dtype(_SCALARS[base][0]).itemsize)
        out.update(_numeric(entry, order, fields, elem, is_array, what))
    elif base.startswith("struct:") and len(base) > 7:
        plan = typed_plan(base)
        fields = structschema.plan_fields(plan)
        elem = plan.nbytes[plan.root]
        if elem == 0:
            raise datalog.DataLogError(f"{what}: struct:{clip(plan.root)} holds no bytes")
        out.update(_numeric(entry, order, fields, elem, is_array, what))
    elif type_string in _TEXT:
        out["value"] = _objects([d.decode("utf-8", "replace") for d in _data(entry, order)])
    elif type_string == "string[]":
        out["value"] = _objects([_strings(d, i, what) for i, d in enumerate(_data(entry, order))])
    else:
        out["value"] = _objects(_data(entry, order))
    return out


def _data(entry: Any, order: np.ndarray | None) -> list[bytes]:
    data = entry.data
    return data if order is None else [data[i] for i in order.tolist()]


def _objects(items: list[Any]) -> np.ndarray:
    col = np.empty(len(items), dtype=object)
    col[:] = items
    return col


def _strings(payload: bytes, i: int, what: str) -> tuple[str, ...]:
    """A ``string[]`` record: a uint32 count, then each string as a uint32 length and
    its UTF-8 bytes."""
    def bad() -> datalog.DataLogError:
        return datalog.DataLogError(f"{what}: record {i} is not a string array "
                                    f"({len(payload)} bytes)")

    if len(payload) < 4:
        raise bad()
    (count,) = struct.unpack_from("<I", payload)
    if count > (len(payload) - 4) // 4:
        raise bad()
    out, pos = [], 4
    for _ in range(count):
        if pos + 4 > len(payload):
            raise bad()
        (n,) = struct.unpack_from("<I", payload, pos)
        pos += 4
        if n > len(payload) - pos:
            raise bad()
        out.append(payload[pos:pos + n].decode("utf-8", "replace"))
        pos += n
    return tuple(out)


def _numeric(entry: Any, order: np.ndarray | None, fields: list[structschema.Field],
             elem: int, is_array: bool, what: str) -> dict[str, np.ndarray]:
    """Columns of fixed-size elements: (N,) per field for single values, (N, M) for
    arrays whose records all hold M elements, else (N,) object columns of 1-D arrays."""
    sizes = entry.sizes.astype(np.int64)
    if order is not None:
        sizes = sizes[order]
    bad = sizes % elem != 0 if is_array else sizes != elem
    if bad.any():
        i = int(np.argmax(bad))
        want = f"a multiple of {elem}" if is_array else f"{elem}"
        raise datalog.DataLogError(f"{what}: record {i} (by time) has {sizes[i]} bytes, "
                                   f"not {want}")
    n = len(sizes)
    if not n or (sizes == sizes[0]).all():
        size = int(sizes[0]) if n else (0 if is_array else elem)
        raw = np.empty(n * size, dtype=np.uint8)
        _wpilog.gather(entry._index.buf, entry.offsets, order, size, raw)
        shape = (n, size // elem, elem) if is_array else (n, elem)
        return _columns(raw.reshape(shape), fields)
    cells = n * len(fields)
    if cells > _MAX_CELLS:
        raise datalog.DataLogError(
            f"{what}: its arrays change length between records and {len(fields)} columns "
            f"of {n} records would be {cells} arrays (at most {_MAX_CELLS}); "
            f"LogData.values(name, ragged='drop') or LogData.concatenated(name) read it")
    raw = np.frombuffer(b"".join(_data(entry, order)), dtype=np.uint8)
    flat = _columns(raw.reshape(-1, elem), fields)
    cuts = np.cumsum(sizes // elem)[:-1]
    out = {}
    for name, col in flat.items():
        parts = np.split(col, cuts)
        for p in parts:
            p.flags.writeable = False
        out[name] = _objects(parts)
    return out


def _columns(raw: np.ndarray, fields: list[structschema.Field]) -> dict[str, np.ndarray]:
    """Each field of the elements in ``raw`` (uint8, last axis one element's bytes)."""
    out: dict[str, np.ndarray] = {}
    for f in fields:
        if f.type == "char":
            width = 1 if f.chars is None else f.chars
            cell = np.ascontiguousarray(raw[..., f.offset:f.offset + width])
            text = cell.view(f"S{width}")[..., 0] if width else np.zeros(cell.shape[:-1], "S1")
            col = np.empty(text.shape, dtype=object)
            flat = col.reshape(-1)
            flat[:] = [b.decode("utf-8", "replace") for b in text.reshape(-1).tolist()]
            out[f.path] = col
            continue
        stored, kind = _SCALARS[f.type]
        width = np.dtype(stored).itemsize
        cell = np.ascontiguousarray(raw[..., f.offset:f.offset + width])
        values = cell.view(stored)[..., 0]
        out[f.path] = values != 0 if kind is np.bool_ else values.astype(kind, copy=False)
    return out
