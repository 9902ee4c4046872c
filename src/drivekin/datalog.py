"""WPILib DataLog (``.wpilog``) files in and out, as numpy arrays with their timestamps.

Reading and writing go through robotpy-wpiutil (``wpiutil.log.DataLogReader`` and
``wpiutil.DataLogWriter``), an optional dependency: ``pip install "drivekin[log]"``.
It is imported on first use, so ``import drivekin`` never imports it.

A round trip (writing, then reading)::

    import numpy as np
    from drivekin import Pose2d, Rotation2d, SwerveModulePosition, datalog
    pose = Pose2d(1.0, 2.0, Rotation2d(0.5))
    positions = [SwerveModulePosition(0.1 * i, Rotation2d(0.2 * i)) for i in range(4)]
    t_us = np.arange(1, 51) * 20_000                       # 50 records, 20 ms apart
    truth = np.column_stack([np.linspace(0.0, 1.0, 50), np.zeros(50), np.zeros(50)])
    with datalog.Writer("run.wpilog") as w:
        w.append("/Drive/Pose", pose, 20_000)                  # struct:Pose2d
        w.append("/Drive/ModulePositions", positions, 20_000)  # struct:SwerveModulePosition[]
        w.append("/Drive/GyroRate", 0.25, 20_000)              # double
        w.appendSeries("/Sim/TruePose", "struct:Pose2d", t_us, truth)   # (N,) and (N, 3)

    log = datalog.read("run.wpilog")
    for info in log.entries.values():      # name, type, metadata, record count
        print(info.name, info.type, info.records)
    t, poses = log.values("/Sim/TruePose")   # struct:Pose2d
    # t: int64 (N,) microseconds; poses: float64 (N, 3) [x m, y m, θ rad]

:meth:`LogData.values` shapes (N records, M array elements, k doubles per struct):

=================================  ======================================================
entry type                         values
=================================  ======================================================
``double``, ``float``              float64 (N,)
``int64``                          int64 (N,)
``boolean``                        bool (N,)
``double[]``, ``float[]``          float64 (N, M)
``int64[]``, ``boolean[]``         int64 (N, M), bool (N, M)
``struct:T`` (k doubles)           float64 (N, k); (N,) when k = 1 (``Rotation2d``)
``struct:T[]`` (k doubles)         float64 (N, M, k); (N, M) when k = 1
=================================  ======================================================

Struct columns are the struct's doubles in schema order, nested structs inlined:
``Pose2d`` → ``[x, y, θ]``, ``SwerveModulePosition`` → ``[distance m, angle rad]``,
``SwerveModuleVelocity`` (2026: ``SwerveModuleState``) → ``[velocity m/s, angle rad]``,
``MecanumDriveWheelPositions`` → ``[fl, fr, rl, rr]``; :attr:`EntryInfo.columns` names
them. Angles come back exactly as stored (robotpy 2026 stores a Rotation2d's constructor
value, WPILib 2027 the wrapped one). A struct is decoded with the schema the log
publishes for it (``/.schema/struct:<Name>``); any struct whose members are all
``double`` (``float64``) is readable, nested and fixed-size array members included.
Without a published schema the WPILib types drivekin knows are still read (2027 and 2026
names: ``ChassisSpeeds``, ``SwerveModuleState``, ``MecanumDriveWheelSpeeds``,
``DifferentialDriveWheelSpeeds``). Other member types (integers, enums, bit fields) are
refused with :class:`DataLogError`; :meth:`LogData.records` still gives the raw bytes.

Record order and damage:

* **Out-of-order timestamps** (DataLog guarantees no order: several threads write, and
  producers may set timestamps) are sorted by timestamp with a *stable* sort, so records
  with equal timestamps keep their order in the file.
* **Gaps** are not filled: the arrays hold exactly the records present.
* **Arrays that change length** between records (e.g. an empty array logged at startup)
  raise :class:`DataLogError` naming the lengths seen; ``ragged="drop"`` keeps only the
  records of the most common length (the earliest such length on a tie) and drops the
  rest. Single structs of the wrong byte size follow the same rule.
* **Truncated files** (a robot that lost power mid-write) raise :class:`DataLogError`
  saying where the file ends; ``read(path, allowTruncated=True)`` keeps every complete
  record and sets :attr:`LogData.truncated`. The record framing is checked by drivekin
  (robotpy's reader decodes a cut record as if it were whole).
* Entries finished and restarted keep their records under one name; a name restarted
  with a different type is refused when read.

Writing (:class:`Writer`, above): drivekin values go in as WPILib struct entries
(``struct:<Name>`` and ``struct:<Name>[]``, packed by :mod:`drivekin.wpistruct`) and every
struct schema they need, nested ones included, is published once as a ``structschema`` entry, so
AdvantageScope shows them as poses and module states. Timestamps are integers in
microseconds and must be >= 1: DataLog reads a timestamp of 0 as "now".

All errors about a file's contents or a missing entry raise :class:`DataLogError`
(a ValueError); wrong argument types raise TypeError.
"""
from __future__ import annotations

import collections
import operator
import os
import re
from collections.abc import Iterable
from typing import Any, NamedTuple

import numpy as np

from drivekin import wpistruct
from drivekin._core.errors import type_name
from drivekin._core import catalog

__all__ = ["DataLogError", "EntryInfo", "LogData", "Writer", "listEntries", "read"]

_INSTALL_HINT = 'robotpy-wpiutil is needed to read and write .wpilog files: pip install "drivekin[log]"'


def _wpiutil() -> Any:
    """Import robotpy-wpiutil on first use (an optional dependency)."""
    try:
        import wpiutil
        import wpiutil.log
    except ImportError as e:
        raise ImportError(_INSTALL_HINT) from e
    return wpiutil


class DataLogError(ValueError):
    """A ``.wpilog`` file that cannot be read as asked: not a DataLog, truncated, an
    entry missing or of a type that cannot be decoded."""


class EntryInfo(NamedTuple):
    """One entry of a log: its ``name``, ``type`` string (``"double"``,
    ``"struct:Pose2d"``, ...), ``metadata``, the number of data records ``records``, and
    for decodable numeric entries the ``columns`` of one element (``("x", "y", "value")``
    style paths for structs, ``()`` for plain numbers and other types)."""

    name: str
    type: str
    metadata: str
    records: int
    columns: tuple[str, ...]


# ---------------------------------------------------------------------------------------
# Struct layouts

# Schemas drivekin knows even when a log does not publish them: drivekin's own types
# (WPILib 2027 names) and the 2026 names of the same layouts.
_KNOWN_SCHEMAS: dict[str, str] = {}
# Repeated structs (one type per member count, SwerveDriveKinematics__N): name -> entry.
_REPEATED: dict[str, catalog.Entry] = {}
for _e in catalog.ENTRIES:
    if _e.struct is not None:
        if _e.struct.repeats is None:
            _KNOWN_SCHEMAS[_e.struct.name] = _e.struct.schema
        else:
            _REPEATED[_e.struct.name] = _e
_KNOWN_SCHEMAS.update({
    "ChassisSpeeds": "double vx;double vy;double omega",
    "SwerveModuleState": "double speed;Rotation2d angle",
    "MecanumDriveWheelSpeeds": _KNOWN_SCHEMAS["MecanumDriveWheelVelocities"],
    "DifferentialDriveWheelSpeeds": _KNOWN_SCHEMAS["DifferentialDriveWheelVelocities"],
})
del _e

_DECL = re.compile(r"\s*(?P<enum>enum\s*\{[^}]*\}\s*)?(?P<type>\w+)\s+(?P<name>\w+)\s*"
                   r"(?:\[\s*(?P<count>\d+)\s*\])?\s*(?P<bits>:\s*\d+)?\s*")
_REPEATED_NAME = re.compile("(" + "|".join(_REPEATED) + r")__(\d+)")


def _struct_columns(name: str, schemas: dict[str, str],
                    stack: tuple[str, ...] = ()) -> tuple[str, ...]:
    """Column paths of struct ``name`` (one per double), resolving nested structs with
    the log's schemas first, then drivekin's; DataLogError for anything but doubles."""
    if name in stack:
        raise DataLogError(f"struct:{name} contains itself (schema cycle "
                           f"{' -> '.join(stack + (name,))})")
    schema = schemas.get(name)
    if schema is None:
        schema = _KNOWN_SCHEMAS.get(name)
        m = _REPEATED_NAME.fullmatch(name)
        if schema is None and m:
            schema = f"{_REPEATED[m.group(1)].struct.schema}[{m.group(2)}]"  # type: ignore[union-attr]
    if schema is None:
        raise DataLogError(f"no schema for struct:{name} in the log, and it is not a "
                           f"WPILib type drivekin knows")
    columns: list[str] = []
    for decl in schema.split(";"):
        if not decl.strip():
            continue
        m = _DECL.fullmatch(decl)
        if m is None:
            raise DataLogError(f"struct:{name}: cannot parse schema member {decl.strip()!r}")
        if m.group("enum") or m.group("bits"):
            raise DataLogError(f"struct:{name}: member {m.group('name')!r} is an enum or "
                               f"bit field; only structs of doubles are decoded")
        mtype, mname = m.group("type"), m.group("name")
        count = m.group("count")
        names = [mname] if count is None else [f"{mname}[{i}]" for i in range(int(count))]
        if mtype in ("double", "float64"):
            sub: tuple[str, ...] = ("",)
        elif mtype in ("bool", "char", "int8", "int16", "int32", "int64", "uint8",
                       "uint16", "uint32", "uint64", "float", "float32"):
            raise DataLogError(f"struct:{name}: member {mname!r} is {mtype}; only structs "
                               f"of doubles are decoded")
        else:
            sub = tuple("." + c for c in _struct_columns(mtype, schemas, stack + (name,)))
        columns += [n + s for n in names for s in sub]
    if not columns:
        raise DataLogError(f"struct:{name} has no members")
    return tuple(columns)


_PLAIN = {  # type -> (numpy dtype of one element, output dtype)
    "double": ("<f8", np.float64), "float": ("<f4", np.float64),
    "int64": ("<i8", np.int64), "boolean": ("u1", np.bool_),
}


def _layout(type_string: str, schemas: dict[str, str]) -> tuple[str, tuple[str, ...], bool]:
    """(numpy dtype of one scalar, struct columns or (), is an array) for a type string,
    or DataLogError if the type is not decodable as numbers."""
    is_array = type_string.endswith("[]")
    base = type_string[:-2] if is_array else type_string
    if base in _PLAIN:
        return _PLAIN[base][0], (), is_array
    if base.startswith("struct:") and len(base) > 7:
        return "<f8", _struct_columns(base[7:], schemas), is_array
    raise DataLogError(f"entry type {type_string!r} is not numeric; readable types: "
                       f"double, float, int64, boolean, their arrays, and struct:<T> or "
                       f"struct:<T>[] of doubles")


# ---------------------------------------------------------------------------------------
# Record framing (checked here: robotpy's reader accepts a cut record as whole)

def _frame_end(data: memoryview) -> tuple[int, int, str | None]:
    """Walk the record headers of a DataLog image. Return (end of the last complete
    record, number of complete records, why the rest is not a record or None)."""
    n = len(data)
    if n < 12 or bytes(data[:6]) != b"WPILOG":
        raise DataLogError("not a WPILib DataLog (.wpilog) file: it does not start with "
                           "the 'WPILOG' header" if n >= 6 or n == 0 else
                           "not a WPILib DataLog (.wpilog) file: shorter than its header")
    version = int.from_bytes(data[6:8], "little")
    if version != 0x0100:
        raise DataLogError(f"unsupported DataLog version {version >> 8}.{version & 0xFF} "
                           f"(robotpy-wpiutil reads 1.0)")
    extra = int.from_bytes(data[8:12], "little")
    pos = 12 + extra
    if pos > n:
        return 12, 0, f"the header says {extra} bytes of extra header, the file has {n - 12}"
    records = 0
    b = bytes(data)           # int indexing on bytes is the fastest way to walk
    frm = int.from_bytes
    while pos < n:
        bits = b[pos]
        le = (bits & 0x3) + 1
        ls = ((bits >> 2) & 0x3) + 1
        lt = ((bits >> 4) & 0x7) + 1
        head = 1 + le + ls + lt
        if pos + head > n:
            return pos, records, f"the record at byte {pos} has an incomplete header"
        size = frm(b[pos + 1 + le:pos + 1 + le + ls], "little")
        end = pos + head + size
        if end > n:
            return pos, records, (f"the record at byte {pos} needs {head + size} bytes, "
                                  f"the file ends {n - pos} bytes after its start")
        pos = end
        records += 1
    return pos, records, None


# ---------------------------------------------------------------------------------------
# Reading

class _Entry:
    __slots__ = ("name", "types", "metadata", "ts", "data")

    def __init__(self, name: str, type_string: str, metadata: str) -> None:
        self.name = name
        self.types = [type_string]
        self.metadata = metadata
        self.ts: list[int] = []
        self.data: list[bytes] = []


class LogData:
    """The contents of one ``.wpilog`` file (see :func:`read`)."""

    def __init__(self, source: str, entries: dict[str, _Entry], schemas: dict[str, str],
                 truncated: str | None, extraHeader: str) -> None:
        self.source = source
        """The file name (or ``"<buffer>"``)."""
        self._entries = entries
        self._schemas = schemas
        self.truncated = truncated
        """None, or why the file ended early (only with ``allowTruncated=True``)."""
        self.extraHeader = extraHeader
        """The file header's extra string (often JSON from the producer)."""

    @property
    def entries(self) -> dict[str, EntryInfo]:
        """Every entry by name, in order of first appearance (schema entries
        ``/.schema/...`` included)."""
        out = {}
        for e in self._entries.values():
            try:
                columns = _layout(e.types[0], self._schemas)[1] if len(e.types) == 1 else ()
            except DataLogError:
                columns = ()
            out[e.name] = EntryInfo(e.name, "|".join(e.types), e.metadata, len(e.ts),
                                    columns)
        return out

    @property
    def schemas(self) -> dict[str, str]:
        """Struct schemas published in the log: type name (``"Pose2d"``) → schema."""
        return dict(self._schemas)

    def _entry(self, name: str) -> _Entry:
        if not isinstance(name, str):
            raise TypeError(f"entry name must be a str, got {type_name(name)}")
        e = self._entries.get(name)
        if e is None:
            close = [n for n in self._entries if n.lower().endswith(name.lower().rsplit("/", 1)[-1])]
            hint = f"; similar: {', '.join(close[:5])}" if close else ""
            raise DataLogError(f"{self.source}: no entry named {name!r}{hint}")
        if len(e.types) > 1:
            raise DataLogError(f"{self.source}: entry {name!r} was started with several "
                               f"types ({', '.join(e.types)})")
        return e

    def records(self, name: str) -> tuple[np.ndarray, list[bytes]]:
        """Timestamps (int64 µs) and raw payloads of an entry, in file order (unsorted)."""
        e = self._entry(name)
        return np.array(e.ts, dtype=np.int64), list(e.data)

    def values(self, name: str, *, ragged: str = "error") -> tuple[np.ndarray, np.ndarray]:
        """Return ``(timestamps, values)`` of a numeric entry, sorted by timestamp
        (stable): timestamps int64 (N,) in µs, values as in the module's table.

        ``ragged``: ``"error"`` (default) raises DataLogError if records differ in size
        (arrays that change length); ``"drop"`` keeps the records of the most common
        size. An entry without records gives empty arrays of the right shape when the
        size of an element is known (structs, plain numbers)."""
        if ragged not in ("error", "drop"):
            raise ValueError(f"ragged must be 'error' or 'drop', got {ragged!r}")
        e = self._entry(name)
        type_string = e.types[0]
        try:
            scalar, columns, is_array = _layout(type_string, self._schemas)
        except DataLogError as err:
            raise DataLogError(f"{self.source}: entry {name!r}: {err}") from None
        k = max(len(columns), 1)
        item = np.dtype(scalar).itemsize
        elem = item * k
        ts = np.array(e.ts, dtype=np.int64)
        data = e.data
        sizes = np.fromiter((len(d) for d in data), dtype=np.int64, count=len(data))
        if is_array:
            bad = sizes % elem != 0
            if bad.any():
                i = int(np.argmax(bad))
                raise DataLogError(f"{self.source}: entry {name!r} ({type_string}): record "
                                   f"{i} has {sizes[i]} bytes, not a multiple of {elem}")
        if len(data) and (sizes != sizes[0]).any():
            counts = collections.Counter(sizes.tolist())
            if ragged == "error":
                seen = ", ".join(f"{(s // elem) if is_array else s} ({c} records)"
                                 for s, c in sorted(counts.items()))
                what = "array lengths" if is_array else "record sizes in bytes"
                raise DataLogError(
                    f"{self.source}: entry {name!r} ({type_string}) changes size between "
                    f"records: {what} {seen}; pass ragged='drop' (replay: --ragged drop) "
                    f"to keep only the most common")
            best = max(counts.values())
            keep_size = next(s for s in sizes.tolist() if counts[s] == best)
            keep = sizes == keep_size
            ts = ts[keep]
            data = [d for d, k_ in zip(data, keep.tolist()) if k_]
            sizes = sizes[keep]
        n = len(data)
        if not is_array and n and sizes[0] != elem:
            raise DataLogError(f"{self.source}: entry {name!r} ({type_string}) has "
                               f"{sizes[0]}-byte records, expected {elem}")
        m = int(sizes[0]) // elem if n and is_array else 0
        flat = np.frombuffer(b"".join(data), dtype=scalar)
        base = type_string[:-2] if is_array else type_string
        out_dtype = _PLAIN[base][1] if base in _PLAIN else np.float64
        shape: tuple[int, ...] = (n, m) if is_array else (n,)
        if columns and len(columns) > 1:
            shape += (k,)
        values: np.ndarray = flat.astype(out_dtype).reshape(shape)
        if n > 1 and (np.diff(ts) < 0).any():
            order = np.argsort(ts, kind="stable")
            ts, values = ts[order], values[order]
        return ts, values

    def __repr__(self) -> str:
        return (f"<drivekin.datalog.LogData {self.source!r}: {len(self._entries)} entries"
                f"{', truncated' if self.truncated else ''}>")


def read(source: str | os.PathLike[str] | bytes | bytearray | memoryview, *,
         allowTruncated: bool = False) -> LogData:
    """Read a ``.wpilog`` file (a path, or the file's bytes) with robotpy-wpiutil's
    DataLogReader and return its entries (see :class:`LogData`).

    DataLogError: not a DataLog, or truncated (unless ``allowTruncated``).
    OSError: the file cannot be opened. ImportError: robotpy-wpiutil is missing."""
    if isinstance(source, (str, os.PathLike)):
        name = os.fspath(source)
        with open(name, "rb") as f:
            raw = f.read()
    elif isinstance(source, (bytes, bytearray, memoryview)):
        name = "<buffer>"
        raw = bytes(source)
    else:
        raise TypeError(f"read() takes a path or bytes, got {type_name(source)}")
    wpiutil = _wpiutil()
    try:
        end, _, why = _frame_end(memoryview(raw))
    except DataLogError as err:
        raise DataLogError(f"{name}: {err}") from None
    truncated = None
    if why is not None:
        truncated = f"truncated at byte {end} of {len(raw)}: {why}"
        if not allowTruncated:
            raise DataLogError(f"{name}: {truncated} (pass allowTruncated=True, replay: "
                               f"--allow-truncated, to use the complete records)")
        raw = raw[:end]
    reader = wpiutil.log.DataLogReader(raw, name)
    if not reader.isValid():
        raise DataLogError(f"{name}: robotpy-wpiutil does not accept it as a DataLog")
    entries: dict[str, _Entry] = {}
    active: dict[int, _Entry] = {}
    for rec in reader:
        entry_id = rec.getEntry()
        if entry_id == 0:               # control record
            if rec.isStart():
                s = rec.getStartData()
                e = entries.get(s.name)
                if e is None:
                    e = entries[s.name] = _Entry(s.name, s.type, s.metadata)
                elif s.type not in e.types:
                    e.types.append(s.type)
                active[s.entry] = e
            elif rec.isFinish():
                active.pop(rec.getFinishEntry(), None)
            elif rec.isSetMetadata():
                md = rec.getSetMetadataData()
                e = active.get(md.entry)
                if e is not None:
                    e.metadata = md.metadata
            continue
        e = active.get(entry_id)
        if e is None:
            continue                    # a record for an entry never started: ignored
        e.ts.append(rec.getTimestamp())
        e.data.append(rec.getRaw())
    schemas = {}
    for e in entries.values():
        if (e.name.startswith("/.schema/struct:") and e.types == ["structschema"]
                and e.data):
            schemas[e.name[len("/.schema/struct:"):]] = bytes(e.data[-1]).decode(
                "utf-8", "replace")
    return LogData(name, entries, schemas, truncated, reader.getExtraHeader())


def listEntries(source: str | os.PathLike[str] | bytes, *,
                allowTruncated: bool = False) -> list[EntryInfo]:
    """The entries of a ``.wpilog`` file (see :attr:`LogData.entries`), as a list."""
    return list(read(source, allowTruncated=allowTruncated).entries.values())


# ---------------------------------------------------------------------------------------
# Writing

_STRUCT_CLASSES: dict[str, type] = {e.struct.name: e.cls for e in catalog.ENTRIES
                                    if e.struct is not None and e.struct.repeats is None}

# robotpy-wpiutil 2026.2.2's DataLogWriter blocks forever once about 1 MiB is buffered
# without a flush() (no thread empties its buffers), so the writer flushes well before.
_FLUSH_BYTES = 256 * 1024


def _timestamp(t: object) -> int:
    try:
        v = operator.index(t)  # type: ignore[arg-type]
    except TypeError:
        raise TypeError(f"timestamp must be an int (microseconds), got {type_name(t)}") from None
    if isinstance(t, bool):
        raise TypeError("timestamp must be an int (microseconds), got bool")
    if not 1 <= v < 2 ** 63:
        raise ValueError(f"timestamp must be from 1 to 2**63 - 1 µs (0 means 'now' to "
                         f"DataLog), got {v}")
    return v


class Writer:
    """Write a ``.wpilog`` file with robotpy-wpiutil's ``DataLogWriter``.

    ``Writer(path, extraHeader="")``; use as a context manager or call :meth:`close`.
    Entries are created on their first record; a later record must have the same type.
    The file is complete only after :meth:`close`."""

    def __init__(self, path: str | os.PathLike[str], extraHeader: str = "") -> None:
        wpiutil = _wpiutil()
        self.path = os.fspath(path)
        try:
            self._log = wpiutil.DataLogWriter(self.path, str(extraHeader))
        except RuntimeError as e:       # robotpy reports open() failures this way
            raise OSError(f"cannot write {self.path}: {e}") from None
        self._entries: dict[str, tuple[int, str]] = {}
        self._schemas: set[str] = set()
        self._pending = 0

    # -- internals

    def _open(self) -> Any:
        if self._log is None:
            raise ValueError(f"the writer for {self.path} is closed")
        return self._log

    def _bytes(self, n: int) -> None:
        self._pending += n + 16
        if self._pending >= _FLUSH_BYTES:
            self._log.flush()
            self._pending = 0

    def _schema_for(self, type_string: str, timestamp: int) -> None:
        """Publish the schemas a struct type needs (nested first), once each."""
        base = type_string[:-2] if type_string.endswith("[]") else type_string
        if not base.startswith("struct:"):
            return
        name = base[7:]
        m = _REPEATED_NAME.fullmatch(name)
        if m:
            cls: type | None = _REPEATED[m.group(1)].cls
            kw: dict[str, int] = {"numModules": int(m.group(2))}
        else:
            cls, kw = _STRUCT_CLASSES.get(name), {}
        if cls is None:
            return

        def publish(type_str: str, schema: str) -> None:
            if type_str not in self._schemas:
                self._schemas.add(type_str)
                self._log.addSchema(type_str, "structschema", schema, timestamp)

        wpistruct.forEachNested(cls, publish, **kw)

    def _entry(self, name: str, type_string: str, timestamp: int, metadata: str = "") -> int:
        if not isinstance(name, str):
            raise TypeError(f"entry name must be a str, got {type_name(name)}")
        known = self._entries.get(name)
        if known is not None:
            if known[1] != type_string:
                raise TypeError(f"entry {name!r} holds {known[1]}, got a {type_string} value")
            return known[0]
        if not name:
            raise ValueError("entry name must not be empty")
        log = self._open()
        if name.startswith("/.schema/struct:") and type_string == "structschema":
            self._schemas.add(name[len("/.schema/"):])
        else:
            self._schema_for(type_string, timestamp)
        entry = log.start(name, type_string, metadata, timestamp)
        self._entries[name] = (entry, type_string)
        return entry

    # -- public

    def append(self, name: str, value: object, timestamp: int) -> None:
        """Append one record: a drivekin value (``struct:<Name>``), a non-empty list or
        tuple of one drivekin type (``struct:<Name>[]``), a float or int (``double``),
        a bool (``boolean``), a str (``string``), or a sequence or 1-D float64 array of
        floats (``double[]``)."""
        ts = _timestamp(timestamp)
        log = self._open()
        if isinstance(value, bool):
            entry = self._entry(name, "boolean", ts)
            log.appendBoolean(entry, value, ts)
            self._bytes(1)
            return
        if isinstance(value, (float, int)):
            entry = self._entry(name, "double", ts)
            log.appendDouble(entry, float(value), ts)
            self._bytes(8)
            return
        if isinstance(value, str):
            entry = self._entry(name, "string", ts)
            log.appendString(entry, value, ts)
            self._bytes(len(value))
            return
        if isinstance(value, np.ndarray):
            if value.dtype != np.float64 or value.ndim != 1:
                raise TypeError(f"an array value must be 1-D float64 (double[]), got "
                                f"{value.ndim}-D {value.dtype}")
            entry = self._entry(name, "double[]", ts)
            data = np.ascontiguousarray(value, dtype="<f8")
            log.appendRaw(entry, data.tobytes(), ts)
            self._bytes(data.nbytes)
            return
        if isinstance(value, (list, tuple)):
            if not value:
                raise TypeError(f"cannot tell the type of an empty sequence for {name!r}; "
                                f"use appendSeries with a type string")
            first = value[0]
            if type(first) in (float, int):
                if not all(type(v) in (float, int) for v in value):
                    i = next(j for j, v in enumerate(value) if type(v) not in (float, int))
                    raise TypeError(f"double[] elements must be float or int; element {i} "
                                    f"is {type_name(value[i])}")
                entry = self._entry(name, "double[]", ts)
                data = np.array(value, dtype="<f8")
                log.appendRaw(entry, data.tobytes(), ts)
                self._bytes(data.nbytes)
                return
            payload = wpistruct.packArray(value)
            type_string = wpistruct.getTypeString(first) + "[]"
        else:
            payload = wpistruct.pack(value)  # type: ignore[arg-type]
            type_string = wpistruct.getTypeString(value)
        entry = self._entry(name, type_string, ts)
        log.appendRaw(entry, payload, ts)
        self._bytes(len(payload))

    def appendSeries(self, name: str, type: str, timestamps: Any, values: Any, *,
                     metadata: str = "") -> None:
        """Append N records at once from arrays: ``timestamps`` (N,) ints in µs (each
        >= 1), ``values`` float64 in the shape :meth:`LogData.values` returns for
        ``type`` — ``"double"`` (N,), ``"double[]"`` (N, M), ``"struct:<Name>"`` (N, k)
        or (N,) when k = 1, ``"struct:<Name>[]"`` (N, M, k) or (N, M) — for drivekin's
        struct types (``struct:SwerveDriveKinematics__4`` style for swerve kinematics).
        Values are stored as given (angles are not wrapped) and records in the given
        order."""
        if not isinstance(type, str):
            raise TypeError(f"type must be a type string such as 'struct:Pose2d', got "
                            f"{type_name(type)}")
        is_array = type.endswith("[]")
        base = type[:-2] if is_array else type
        if base == "double":
            k = 1
        elif base.startswith("struct:") and (base[7:] in _STRUCT_CLASSES
                                             or _REPEATED_NAME.fullmatch(base[7:])):
            k = len(_struct_columns(base[7:], {}))
        else:
            raise ValueError(f"appendSeries() writes double, double[] and drivekin's "
                             f"struct types, got {type!r}")
        if isinstance(values, np.ndarray):
            if values.dtype != np.float64:
                raise TypeError(f"values must be a float64 array, got {values.dtype}")
            arr = values
        elif isinstance(values, (list, tuple)):
            arr = np.array(values, dtype=np.float64)
        else:
            raise TypeError(f"values must be a float64 array or a list, got "
                            f"{type_name(values)}")
        ts_in = np.asarray(timestamps)
        if ts_in.ndim != 1 or ts_in.dtype.kind not in "iu":
            raise TypeError(f"timestamps must be a 1-D integer array (µs), got "
                            f"{ts_in.ndim}-D {ts_in.dtype}")
        n = len(ts_in)
        if n and (ts_in.min() < 1 or ts_in.max() >= 2 ** 63):
            raise ValueError("timestamps must be from 1 to 2**63 - 1 µs (0 means 'now' "
                             "to DataLog)")
        want = (n,) + ((None,) if is_array else ()) + ((k,) if k > 1 else ())
        if arr.ndim != len(want) or arr.shape[0] != n or (k > 1 and arr.shape[-1] != k):
            shown = "(" + ", ".join("M" if w is None else str(w) for w in want) + ")"
            raise ValueError(f"{type} values for {n} timestamps must have shape {shown}, "
                             f"got {arr.shape}")
        if n == 0:
            return
        rows = np.ascontiguousarray(arr, dtype="<f8").reshape(n, -1)
        ts_list = [int(t) for t in ts_in.tolist()]
        entry = self._entry(name, type, ts_list[0], str(metadata))
        log = self._log
        row_bytes = rows.shape[1] * 8
        for i in range(n):
            log.appendRaw(entry, rows[i].tobytes(), ts_list[i])
            self._bytes(row_bytes)

    def appendRaw(self, name: str, type: str, data: bytes, timestamp: int, *,
                  metadata: str = "") -> None:
        """Append one record of any type as raw bytes (e.g. to copy another log's
        entries; struct schemas are still published for drivekin's struct types)."""
        ts = _timestamp(timestamp)
        if not isinstance(type, str):
            raise TypeError(f"type must be a str, got {type_name(type)}")
        payload = bytes(data)
        entry = self._entry(name, type, ts, str(metadata))
        self._log.appendRaw(entry, payload, ts)
        self._bytes(len(payload))

    def copyFrom(self, log: LogData, *, exclude: Iterable[str] = ()) -> None:
        """Copy every entry of ``log`` (names, types, metadata, records in file order),
        except the names in ``exclude``."""
        skip = set(exclude)
        for e in log._entries.values():
            if e.name in skip or len(e.types) != 1:
                continue
            for t, d in zip(e.ts, e.data):
                if t < 1:
                    t = 1
                self.appendRaw(e.name, e.types[0], d, t, metadata=e.metadata)

    def close(self) -> None:
        """Flush and close the file (again: no effect)."""
        if self._log is not None:
            log, self._log = self._log, None
            log.flush()
            log.stop()

    def __enter__(self) -> Writer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
