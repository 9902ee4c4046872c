"""WPILib DataLog (``.wpilog``) files in and out, as numpy arrays with their timestamps.

Reading is drivekin's own (:mod:`drivekin._core.wpilog`): the file is memory-mapped
read-only and indexed in one C pass (timestamps, payload offsets and sizes per entry), and
:meth:`LogData.values` copies the payloads straight from the file into the arrays; it
needs no robotpy-wpiutil. Every size in the file is checked before it is used; damaged
control records and struct schemas too large to decode raise :class:`DataLogError`.
The mapping lives as long as the :class:`LogData`: a file that another program shortens
meanwhile can crash the process (SIGBUS), so read a copy of a log still being written.

Writing (:class:`Writer`) goes through robotpy-wpiutil's ``DataLogWriter``, an optional
dependency: ``pip install "drivekin[log]"``. It is imported on first use, so neither
``import drivekin`` nor :func:`read` imports it.

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
``Pose2d`` → ``[x, y, θ]``, ``Pose3d`` → ``[x, y, z, qw, qx, qy, qz]`` (the quaternion
as stored: ``wpistruct.unpack`` or the class's constructor normalises it as WPILib does),
``SwerveModulePosition`` → ``[distance m, angle rad]``,
``SwerveModuleVelocity`` (2026: ``SwerveModuleState``) → ``[velocity m/s, angle rad]``,
``MecanumDriveWheelPositions`` → ``[fl, fr, rl, rr]``; :attr:`EntryInfo.columns` names
them. Angles come back exactly as stored (robotpy 2026 stores a Rotation2d's constructor
value, WPILib 2027 the wrapped one). A struct is decoded with the schema the log
publishes for it (``/.schema/struct:<Name>``, or ``NT:/.schema/struct:<Name>`` as ntcore
mirrors it from NetworkTables); any struct whose members are all
``double`` (``float64``) is readable, nested and fixed-size array members included.
Without a published schema the WPILib types drivekin knows are still read (2027 and 2026
names: ``ChassisSpeeds``, ``SwerveModuleState``, ``MecanumDriveWheelSpeeds``,
``DifferentialDriveWheelSpeeds``). Other member types (integers, enums, bit fields) are
refused with :class:`DataLogError`; :meth:`LogData.records` still gives the raw bytes.

Tables for analysis: :meth:`LogData.table` gives any entry as named columns, one row
per record sorted by timestamp (stable): ``"timestamp"`` (int64 µs), then

* ``double``, ``float``, ``int64``, ``boolean``: ``"value"`` float64, int64, bool (N,);
  their arrays ``"value"`` (N, M) when every record holds M elements;
* ``struct:T``: one column per field, named by its path in the log's schema with nested
  structs flattened (``"translation.x"``, ``"rotation.value"`` for WPILib's Pose2d; a
  schema listing plain members gives its own names); members of any scalar type
  (integers in their width, ``float`` as float64, ``bool``, enums as integers, a ``char``
  array as one str column), bit fields refused;
* ``struct:T[]``: one (N, M) column per field;
* an array entry whose records differ in length: object columns, one 1-D array per
  record (refused beyond 4,194,304 such arrays, records times fields);
* ``string``, ``json``, ``structschema``: str objects; ``string[]``: tuples of str;
  other types: the record bytes.

:meth:`LogData.dataframe` is the same as a pandas DataFrame (``pip install
"drivekin[pandas]"``), (N, M) columns split into ``"[i].<field>"`` (struct arrays) or
``"[i]"`` (plain arrays) columns. A LogData builds its entry table once and decodes each
entry once (it keeps the latest 256 results): what :meth:`LogData.values`,
:meth:`LogData.concatenated` and :meth:`LogData.table` return is read-only and shared
between calls; copy an array to change it.

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
  record and sets :attr:`LogData.truncated`.
* **Damaged records**: a complete control record that is malformed (a Start record too
  short for its strings, a Finish record that is not 5 bytes, an unknown control type)
  raises :class:`DataLogError` with its byte offset. Records of an entry never started
  (or finished) are ignored. Names, types and metadata that are not UTF-8 are decoded
  with replacement characters.
* **Struct schemas** are parsed in one linear pass and nested structs resolved without
  recursion (a cycle is an error); a struct of more than 65,536 doubles per element is
  refused before any column is built.
* Entries finished and restarted keep their records under one name; a name restarted
  with a different type is refused when read.

Writing (:class:`Writer`, above): drivekin values go in as WPILib struct entries
(``struct:<Name>`` and ``struct:<Name>[]``, packed by :mod:`drivekin.wpistruct`) and every
struct schema they need, nested ones included, is published once as a ``structschema`` entry, so
AdvantageScope shows them as poses and module states. Timestamps are integers in
microseconds and must be >= 1: DataLog reads a timestamp of 0 as "now".

All errors about a file's contents or a missing entry raise :class:`DataLogError`
(a ValueError; a missing entry's message names close names); wrong argument types raise
TypeError. Only regular files are read: a directory, a FIFO, a device (``/dev/zero``) or
a socket is refused with :class:`DataLogError` before anything is read from it.
"""
from __future__ import annotations

import collections
import difflib
import importlib
import mmap
import operator
import os
import stat
from collections.abc import Iterable
from typing import Any, NamedTuple

import numpy as np

from drivekin import wpistruct
from drivekin._core.display import escape
from drivekin._core.errors import clip, cut, type_name
from drivekin._core import catalog
from drivekin._core import wpilog as _wpilog
from drivekin._core import logtable
from drivekin._core import structschema

__all__ = ["DataLogError", "EntryInfo", "LogData", "Writer", "listEntries", "read"]

_INSTALL_HINT = 'robotpy-wpiutil is needed to write .wpilog files: pip install "drivekin[log]"'


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
    entry missing or of a type that cannot be decoded. The message is escaped
    (:func:`drivekin._core.display.escape`): an entry name it quotes cannot carry terminal
    control characters to wherever it is printed."""

    def __init__(self, message: object = "", *args: object) -> None:
        super().__init__(escape(str(message)), *args)


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
# Reading

class _Index(NamedTuple):
    """The records of every entry: rows ``starts[i]:starts[i + 1]`` belong to entry
    ``i``; timestamps (int64), payload offsets into ``buf`` (uint32, or int64 from 4 GiB)
    and payload sizes (uint32), file order; read-only arrays."""
    buf: Any
    starts: np.ndarray
    ts: np.ndarray
    offsets: np.ndarray
    sizes: np.ndarray


class _Entry:
    """One entry's name, types and metadata, and its rows of the log's index."""

    __slots__ = ("name", "types", "metadata", "_index", "_a", "_b")

    def __init__(self, name: str, types: list[str], metadata: str, index: _Index,
                 a: int, b: int) -> None:
        self.name, self.types, self.metadata = name, types, metadata
        self._index, self._a, self._b = index, a, b

    def __len__(self) -> int:
        return self._b - self._a

    @property
    def ts(self) -> np.ndarray:
        """Timestamps (int64 µs, a read-only view, file order)."""
        return self._index.ts[self._a:self._b]

    @property
    def offsets(self) -> np.ndarray:
        return self._index.offsets[self._a:self._b]

    @property
    def sizes(self) -> np.ndarray:
        return self._index.sizes[self._a:self._b]

    @property
    def data(self) -> list[bytes]:
        """The payloads, as bytes objects (file order)."""
        return _wpilog.payloads(self._index.buf, self.offsets, self.sizes)


def _shown(name: str) -> str:
    """A file name for messages: as it is when it is valid text, else its repr (a name
    that is not UTF-8 comes from os.fsdecode with surrogate escapes)."""
    try:
        name.encode("utf-8")
    except UnicodeEncodeError:
        return repr(name)
    return name


# Decoded results a LogData keeps (the latest used): a replay decodes about ten entries.
_KEEP = 256


class LogData:
    """The contents of one ``.wpilog`` file (see :func:`read`)."""

    def __init__(self, source: str, entries: dict[str, _Entry], schemas: dict[str, str],
                 truncated: str | None, extraHeader: str) -> None:
        self.source = source
        """The file name (or ``"<buffer>"``)."""
        self._entries = entries
        self._schemas = schemas
        self._layouts: dict[str, structschema.Layout | DataLogError] = {}
        self._typed_plans: dict[str, Any] = {}     # tables' struct plans, or their error
        # Read once: the entry table is built on first use and each entry's decoded
        # arrays (read-only, so no caller can change what the next one gets) are kept,
        # failures included, keyed by what changes the result: the latest _KEEP of them,
        # so that decoding every entry of a log of 40,000 entries keeps no more.
        self._infos: dict[str, EntryInfo] | None = None
        self._decoded: collections.OrderedDict[tuple[str, str, str], Any] = (
            collections.OrderedDict())
        self._stats: collections.Counter[Any] = collections.Counter()
        """Private counters for tests: ``"entry_table"`` builds and ``(kind, name)``
        decodes."""
        self.truncated = truncated
        """None, or why the file ended early (only with ``allowTruncated=True``)."""
        self.extraHeader = extraHeader
        """The file header's extra string (often JSON from the producer)."""

    def _layout(self, type_string: str) -> structschema.Layout:
        got = self._layouts.get(type_string)
        if got is None:
            try:
                got = structschema.layout(type_string, self._schemas)
            except DataLogError as err:
                got = err
            self._layouts[type_string] = got
        if isinstance(got, DataLogError):
            raise DataLogError(*got.args)
        return got

    @property
    def entries(self) -> dict[str, EntryInfo]:
        """Every entry by name, in order of first appearance (schema entries
        ``/.schema/...`` included); a new dict each time, of one table built once."""
        if self._infos is None:
            self._infos = self._entry_table()
        return dict(self._infos)

    def _entry_table(self) -> dict[str, EntryInfo]:
        self._stats["entry_table"] += 1
        out = {}
        columns: dict[str, tuple[str, ...]] = {}
        for e in self._entries.values():
            cols: tuple[str, ...] = ()
            if len(e.types) == 1:
                if e.types[0] not in columns:
                    try:
                        plan = self._layout(e.types[0]).plan
                        columns[e.types[0]] = (() if plan is None
                                               else structschema.plan_columns(plan))
                    except DataLogError:
                        columns[e.types[0]] = ()
                cols = columns[e.types[0]]
            out[e.name] = EntryInfo(e.name, "|".join(e.types), e.metadata, len(e), cols)
        return out

    @property
    def schemas(self) -> dict[str, str]:
        """Struct schemas published in the log: type name (``"Pose2d"``) → schema."""
        return dict(self._schemas)

    def _close_names(self, name: str) -> str:
        """"; similar: ..." naming up to five entries close to ``name`` (same last path
        part, or close spelling ignoring case), or ""."""
        last = name.lower().rsplit("/", 1)[-1]
        close = [n for n in self._entries if last and n.lower().endswith(last)]
        lowered = {n.lower(): n for n in self._entries}
        close += [lowered[n] for n in difflib.get_close_matches(name.lower()[:200],
                                                                 lowered, 5, 0.6)]
        close = list(dict.fromkeys(close))[:5]
        return f"; similar: {', '.join(clip(n, 200) for n in close)}" if close else ""

    def _entry(self, name: str) -> _Entry:
        if not isinstance(name, str):
            raise TypeError(f"entry name must be a str, got {type_name(name)}")
        e = self._entries.get(name)
        if e is None:
            raise DataLogError(f"{_shown(self.source)}: no entry named {clip(name, 200)}"
                               f"{self._close_names(name)}")
        if len(e.types) > 1:
            shown = ", ".join(cut(t) for t in e.types[:5])
            more = f", ... ({len(e.types)} types)" if len(e.types) > 5 else ""
            raise DataLogError(f"{_shown(self.source)}: entry {clip(name, 200)} was started "
                               f"with several types ({shown}{more})")
        return e

    def table(self, name: str) -> dict[str, np.ndarray]:
        """Any entry as named columns, one row per record, sorted by timestamp (stable):
        ``"timestamp"`` int64 µs, then the entry's fields (see "Tables for analysis" in
        the module documentation). The arrays are read-only and shared between calls:
        copy one to change it. DataLogError for an unknown name (naming close ones), a
        damaged record or a struct that cannot be decoded (no schema, bit fields)."""
        return self._once("table", name, "", self._table)  # type: ignore[no-any-return]

    def _table(self, name: str, _: str) -> dict[str, np.ndarray]:
        e = self._entry(name)
        what = f"{_shown(self.source)}: entry {clip(name, 200)} ({cut(e.types[0])})"

        def typed_plan(base: str) -> Any:
            got = self._typed_plans.get(base)
            if got is None:
                try:
                    got = structschema.typed_plan(base[7:], self._schemas)
                except DataLogError as err:
                    got = err
                self._typed_plans[base] = got
            if isinstance(got, DataLogError):
                raise DataLogError(f"{what}: {got}")
            return got

        return logtable.table(e, typed_plan, what)

    def dataframe(self, name: str) -> Any:
        """:meth:`table` as a pandas DataFrame (a writable copy): one column per
        1-D column of the table; a 2-D column (arrays whose records agree in length) is
        split into one column per element, ``"[i]"`` for a plain array and
        ``"[i].<field>"`` for a struct array, element by element. Needs pandas:
        ``pip install "drivekin[pandas]"``."""
        try:
            pandas = importlib.import_module("pandas")
        except ImportError as e:
            raise ImportError('LogData.dataframe needs pandas: pip install "drivekin[pandas]" '
                              '(LogData.table gives the same columns as numpy arrays)') from e
        columns = self.table(name)
        out: dict[str, np.ndarray] = {}
        wide = [k for k, v in columns.items() if v.ndim == 2]
        for k, v in columns.items():
            if v.ndim == 1:
                out[k] = v
        if wide:
            plain = len(columns) == 2 and wide == ["value"]
            for i in range(columns[wide[0]].shape[1]):
                for k in wide:
                    out[f"[{i}]" if plain else f"[{i}].{k}"] = columns[k][:, i]
        return pandas.DataFrame(out, copy=True)

    def records(self, name: str) -> tuple[np.ndarray, list[bytes]]:
        """Timestamps (int64 µs) and raw payloads of an entry, in file order (unsorted)."""
        e = self._entry(name)
        return e.ts.copy(), e.data

    def values(self, name: str, *, ragged: str = "error") -> tuple[np.ndarray, np.ndarray]:
        """Return ``(timestamps, values)`` of a numeric entry, sorted by timestamp
        (stable): timestamps int64 (N,) in µs, values as in the module's table.

        ``ragged``: ``"error"`` (default) raises DataLogError if records differ in size
        (arrays that change length); ``"drop"`` keeps the records of the most common
        size. An entry without records gives empty arrays of the right shape when the
        size of an element is known (structs, plain numbers)."""
        if ragged not in ("error", "drop"):
            raise ValueError(f"ragged must be 'error' or 'drop', got {ragged!r}")
        return self._once("values", name, ragged, self._values)  # type: ignore[no-any-return]

    def _once(self, kind: str, name: str, option: str, decode: Any) -> Any:
        """``decode(name, option)``, computed once per (kind, name, option): its arrays
        made read-only and kept, a DataLogError kept and raised again."""
        self._entry(name)       # TypeError / DataLogError for a bad name, not cached
        key = (kind, name, option)
        got = self._decoded.get(key)
        if got is not None:
            self._decoded.move_to_end(key)
        else:
            self._stats[kind, name] += 1
            try:
                got = decode(name, option)
            except DataLogError as err:
                got = err
            else:
                for a in got.values() if isinstance(got, dict) else got:
                    a.flags.writeable = False
            self._decoded[key] = got
            if len(self._decoded) > _KEEP:
                self._decoded.popitem(last=False)
        if isinstance(got, DataLogError):
            raise DataLogError(*got.args)
        return got

    def _values(self, name: str, ragged: str) -> tuple[np.ndarray, np.ndarray]:
        e = self._entry(name)
        type_string = e.types[0]
        what = f"{_shown(self.source)}: entry {clip(name, 200)} ({cut(type_string)})"
        try:
            lay = self._layout(type_string)
        except DataLogError as err:
            raise DataLogError(f"{_shown(self.source)}: entry {clip(name, 200)}: {err}") from None
        elem = np.dtype(lay.scalar).itemsize * lay.k
        ts, sizes = e.ts, e.sizes
        rows = None
        if lay.is_array and len(sizes):
            bad = sizes % elem != 0
            if bad.any():
                i = int(np.argmax(bad))
                raise DataLogError(f"{what}: record {i} has {sizes[i]} bytes, not a "
                                   f"multiple of {elem}")
        if len(sizes) and (sizes != sizes[0]).any():
            uniq, first, counts = np.unique(sizes, return_index=True, return_counts=True)
            if ragged == "error":
                seen = ", ".join(f"{(int(s) // elem) if lay.is_array else int(s)} ({c} records)"
                                 for s, c in zip(uniq.tolist(), counts.tolist()))
                kind = "array lengths" if lay.is_array else "record sizes in bytes"
                raise DataLogError(
                    f"{what} changes size between records: {kind} {seen}; pass "
                    f"ragged='drop' (replay: --ragged drop) to keep only the most common")
            best = counts == counts.max()
            keep_size = uniq[best][np.argmin(first[best])]   # the earliest on a tie
            rows = np.flatnonzero(sizes == keep_size)
            ts = ts[rows]
        n = len(ts)
        size = int(sizes[0] if rows is None else sizes[rows[0]]) if n else 0
        if not lay.is_array and n and size != elem:
            raise DataLogError(f"{what} has {size}-byte records, expected {elem}")
        m = size // elem if n and lay.is_array else 0
        if n > 1 and (np.diff(ts) < 0).any():
            order = np.argsort(ts, kind="stable")
            rows = order if rows is None else rows[order]
            ts = ts[order]
        else:
            ts = ts.copy()
        raw = np.empty(n * size, dtype=np.uint8)
        _wpilog.gather(e._index.buf, e.offsets, rows, size, raw)
        shape: tuple[int, ...] = (n, m) if lay.is_array else (n,)
        if lay.k > 1:
            shape += (lay.k,)
        values: np.ndarray = raw.view(lay.scalar).astype(lay.out, copy=False).reshape(shape)
        return ts, values

    def concatenated(self, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Return ``(timestamps, counts, values)`` of an array entry whose records may
        differ in length (AdvantageKit's high-rate odometry arrays hold however many
        samples arrived in a cycle): records sorted by timestamp (stable), timestamps
        int64 (N,) µs, ``counts`` int64 (N,) elements per record, and every record's
        elements concatenated in that order: float64 (sum of counts,) or
        (sum of counts, k) for structs of k doubles, as :meth:`values` shapes them."""
        return self._once("concatenated", name, "", self._concatenated)  # type: ignore[no-any-return]

    def _concatenated(self, name: str, _: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        e = self._entry(name)
        type_string = e.types[0]
        try:
            lay = self._layout(type_string)
        except DataLogError as err:
            raise DataLogError(f"{_shown(self.source)}: entry {clip(name, 200)}: {err}") from None
        if not lay.is_array:
            raise DataLogError(f"{_shown(self.source)}: entry {clip(name, 200)} "
                               f"({cut(type_string)}) is not an array")
        elem = np.dtype(lay.scalar).itemsize * lay.k
        ts, sizes = e.ts, e.sizes.astype(np.int64)
        if (sizes % elem != 0).any():
            i = int(np.argmax(sizes % elem != 0))
            raise DataLogError(f"{_shown(self.source)}: entry {clip(name, 200)}: record "
                               f"{i} has {sizes[i]} bytes, not a multiple of {elem}")
        order = np.argsort(ts, kind="stable")
        data = e.data
        raw = b"".join([data[i] for i in order.tolist()])
        values = np.frombuffer(raw, dtype=lay.scalar).astype(lay.out)
        if lay.k > 1:
            values = values.reshape(-1, lay.k)
        return ts[order], sizes[order] // elem, values

    def __repr__(self) -> str:
        return (f"<drivekin.datalog.LogData {self.source!r}: {len(self._entries)} entries"
                f"{', truncated' if self.truncated else ''}>")


def _open(path: str | bytes) -> Any:
    """The contents of a regular file: a read-only memory map, or bytes where the file
    cannot be mapped (empty files). Anything else (a directory, a FIFO, a device such as
    /dev/zero, a socket) is refused before a byte is read: it is opened without
    blocking (a FIFO with no writer would wait forever) and checked with fstat."""
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0))
    st = os.fstat(fd)
    if not stat.S_ISREG(st.st_mode):
        os.close(fd)
        raise DataLogError(f"{_shown(os.fsdecode(path))}: not a regular file "
                           f"({_file_kind(st.st_mode)}); a .wpilog is read from a file on "
                           f"disk")
    with open(fd, "rb") as f:
        try:
            if st.st_size > 0:
                return mmap.mmap(fd, 0, access=mmap.ACCESS_READ)
        except (OSError, ValueError):
            pass
        return f.read()


def _file_kind(mode: int) -> str:
    for test, kind in ((stat.S_ISDIR, "a directory"), (stat.S_ISFIFO, "a FIFO or pipe"),
                       (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                       (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return kind
    return "not a regular file"


def read(source: str | os.PathLike[str] | bytes | bytearray | memoryview, *,
         allowTruncated: bool = False) -> LogData:
    """Read a ``.wpilog`` file (a path, or the file's bytes) and return its entries (see
    :class:`LogData`). A file is memory-mapped (read-only) and indexed in one pass;
    values are decoded from it on demand. robotpy-wpiutil is not needed to read.

    DataLogError: not a DataLog, damaged, or truncated (unless ``allowTruncated``); the
    message names the file (its repr when the name is not valid text).
    OSError: the file cannot be opened."""
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        name = os.fsdecode(path)
        buf = _open(path)
    elif isinstance(source, (bytes, bytearray, memoryview)):
        name = "<buffer>"
        buf = bytes(source)
    else:
        raise TypeError(f"read() takes a path or bytes, got {type_name(source)}")
    try:
        header, found, starts, ts, offsets, sizes, end, why = _wpilog.scan(buf)
    except _wpilog.Damaged as err:
        raise DataLogError(f"{_shown(name)}: {err}") from None
    truncated = None
    if why is not None:
        truncated = f"truncated at byte {end} of {len(buf)}: {why}"
        if not allowTruncated:
            raise DataLogError(f"{_shown(name)}: {truncated} (pass allowTruncated=True, "
                               f"replay: --allow-truncated, to use the complete records)")
    for a in (ts, offsets, sizes):
        a.flags.writeable = False
    index = _Index(buf, starts, ts, offsets, sizes)
    bounds = starts.tolist()
    entries = {ename: _Entry(ename, types, metadata, index, bounds[i], bounds[i + 1])
               for i, (ename, types, metadata) in enumerate(found)}
    # The log's own schemas, and those ntcore mirrors from NetworkTables (NT:/.schema/);
    # the log's own win where both exist.
    schemas = {}
    for prefix in ("NT:/.schema/struct:", "/.schema/struct:"):
        for e in entries.values():
            if e.name.startswith(prefix) and e.types == ["structschema"] and len(e):
                o, s = int(e.offsets[-1]), int(e.sizes[-1])
                schemas[e.name[len(prefix):]] = bytes(buf[o:o + s]).decode("utf-8",
                                                                           "replace")
    return LogData(name, entries, schemas, truncated, header)


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
        m = structschema.REPEATED_NAME.fullmatch(name)
        if m:
            cls: type | None = structschema.REPEATED[m.group(1)].cls
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
        entry: int = log.start(name, type_string, metadata, timestamp)
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
                                             or structschema.REPEATED_NAME.fullmatch(base[7:])):
            k = len(structschema.struct_columns(base[7:], {}))
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
