"""The WPILib DataLog (``.wpilog``) record index: one C pass over a file's buffer.

:func:`scan` walks the record framing, decodes the control records (Start, Finish,
SetMetadata) and files every data record of a started entry into per-entry index arrays:
int64 timestamps, payload offsets into the buffer (uint32 below 4 GiB, else int64) and
uint32 payload sizes, in file order. :func:`gather` copies payloads of equal size from the buffer into one output
array, :func:`payloads` makes bytes objects of them. drivekin.datalog is the API; the
format is described there.

Every size read from the file is checked against the buffer before it is used, and every
allocation is bounded by the buffer's size: the index holds at most one row per record,
and a record is at least 4 bytes."""
from typing import Any

import numpy as np

class Damaged(ValueError):
    """The buffer is not a DataLog, or a complete record in it is malformed; the
    message says what and where (drivekin.datalog adds the file name).
    """

_Index = tuple[str, list[list[Any]], np.ndarray, np.ndarray, np.ndarray, np.ndarray, int,
               str | None]

def scan(buf: Any) -> _Index:
    """Index a DataLog image. Return ``(extra_header, entries, starts, ts, offsets,
    sizes, end, why)``: ``entries`` a list of ``[name, [types], metadata]`` in order of
    first appearance; the records of entry ``i`` are rows ``starts[i]:starts[i + 1]`` of
    ``ts`` (int64), ``offsets`` (int64, into ``buf``) and ``sizes`` (uint32), in file
    order; ``end`` the end of the last complete record and ``why`` None, or why the bytes
    after ``end`` are not a complete record. Damaged for anything else that is wrong."""
def gather(buf: Any, offsets: np.ndarray, rows: np.ndarray | None, size: int, out: Any) -> None:
    """Copy the ``size``-byte payloads at ``offsets[rows[i]]`` (``rows`` an int64 array,
    or None for every row in order) to ``out[i * size:]``. The caller has checked that
    those records hold exactly ``size`` bytes; the bounds are checked here again."""
def payloads(buf: Any, offsets: np.ndarray, sizes: np.ndarray) -> list[bytes]:
    """The payloads as a list of bytes objects."""
