"""The WPILib DataLog (``.wpilog``) record index: one C pass over a file's buffer.

:func:`scan` walks the record framing, decodes the control records (Start, Finish,
SetMetadata) and files every data record of a started entry into per-entry index arrays:
int64 timestamps, payload offsets into the buffer (uint32 below 4 GiB, else int64) and
uint32 payload sizes, in file order. :func:`gather` copies payloads of equal size from the buffer into one output
array, :func:`payloads` makes bytes objects of them. drivekin.datalog is the API; the
format is described there.

Every size read from the file is checked against the buffer before it is used, and every
allocation is bounded by the buffer's size: the index holds at most one row per record,
and a record is at least 4 bytes.
"""
cimport cython
from cpython.bytes cimport PyBytes_FromStringAndSize
from cpython.unicode cimport PyUnicode_DecodeUTF8
from libc.stdint cimport int32_t, int64_t, uint8_t, uint32_t, uint64_t
from libc.stdlib cimport free, malloc, realloc
from libc.string cimport memcpy

import numpy as np


class Damaged(ValueError):
    """The buffer is not a DataLog, or a complete record in it is malformed; the
    message says what and where (drivekin.datalog adds the file name)."""


# Entry ids below this are looked up in a C table; larger ones (legal, but no producer
# writes them) in a dict, so a hostile id cannot make the table large.
cdef enum:
    _DIRECT = 65536


# Payload offsets: uint32 for buffers under 4 GiB (4 bytes a record less), else int64.
ctypedef fused offset_t:
    uint32_t
    int64_t


cdef inline uint64_t _le(const uint8_t* p, Py_ssize_t n) noexcept nogil:
    """Little-endian unsigned integer of ``n`` (1 to 8) bytes."""
    cdef uint64_t v = 0
    cdef Py_ssize_t i
    for i in range(n):
        v |= (<uint64_t>p[i]) << (8 * i)
    return v


cdef struct _Header:
    uint32_t entry
    uint32_t size
    int64_t ts
    Py_ssize_t payload          # offset of the payload


cdef inline int _header(const uint8_t* b, Py_ssize_t n, Py_ssize_t pos,
                        _Header* h) noexcept nogil:
    """Decode the record header at ``pos``: 0, 1 if the header runs past ``n``, 2 if
    the payload does (the record is incomplete)."""
    cdef unsigned int bits = b[pos]
    cdef Py_ssize_t le = (bits & 0x3) + 1
    cdef Py_ssize_t ls = ((bits >> 2) & 0x3) + 1
    cdef Py_ssize_t lt = ((bits >> 4) & 0x7) + 1
    cdef Py_ssize_t head = 1 + le + ls + lt
    if head > n - pos:
        return 1
    h.entry = <uint32_t>_le(b + pos + 1, le)
    h.size = <uint32_t>_le(b + pos + 1 + le, ls)
    h.ts = <int64_t>_le(b + pos + 1 + le + ls, lt)
    h.payload = pos + head
    if <Py_ssize_t>h.size > n - h.payload:
        return 2
    return 0


cdef class _Growable:
    """An int32 array in C memory that doubles when full (freed with the object)."""
    cdef int32_t* p
    cdef Py_ssize_t n, cap

    def __dealloc__(self):
        free(self.p)

    cdef int push(self, int32_t v) except -1:
        cdef Py_ssize_t cap
        cdef int32_t* q
        if self.n == self.cap:
            cap = self.cap * 2 if self.cap else 1024
            q = <int32_t*>realloc(self.p, cap * sizeof(int32_t))
            if q == NULL:
                raise MemoryError()
            self.p, self.cap = q, cap
        self.p[self.n] = v
        self.n += 1
        return 0


cdef class _Active:
    """Entry id -> slot (index of the entry by name) of the entries started and not
    finished; -1 for none."""
    cdef int32_t* table             # ids < _DIRECT
    cdef Py_ssize_t size
    cdef dict big                   # ids >= _DIRECT

    def __cinit__(self):
        self.big = {}

    def __dealloc__(self):
        free(self.table)

    cdef inline int32_t get(self, uint32_t entry):
        if entry < <uint32_t>self.size:
            return self.table[entry]
        if entry < _DIRECT or not self.big:
            return -1
        return self.big.get(entry, -1)

    cdef int set(self, uint32_t entry, int32_t slot) except -1:
        cdef Py_ssize_t size, i
        cdef int32_t* q
        if entry >= _DIRECT:
            if slot < 0:
                self.big.pop(entry, None)
            else:
                self.big[entry] = slot
            return 0
        if entry >= <uint32_t>self.size:
            if slot < 0:
                return 0
            size = max(2 * self.size, entry + 1, 64)
            if size > _DIRECT:
                size = _DIRECT
            q = <int32_t*>realloc(self.table, size * sizeof(int32_t))
            if q == NULL:
                raise MemoryError()
            for i in range(self.size, size):
                q[i] = -1
            self.table, self.size = q, size
        self.table[entry] = slot
        return 0


cdef inline str _text(const uint8_t* p, Py_ssize_t n):
    return PyUnicode_DecodeUTF8(<const char*>p, n, "replace")


cdef Py_ssize_t _string(const uint8_t* b, Py_ssize_t at, Py_ssize_t end, str what,
                        Py_ssize_t rec) except -1:
    """Check the u32-length-prefixed string at ``at`` fits before ``end``; return its
    length."""
    cdef uint64_t length
    if end - at < 4:
        raise Damaged(f"the control record at byte {rec} is too short for its {what}")
    length = _le(b + at, 4)
    if length > <uint64_t>(end - at - 4):
        raise Damaged(f"the control record at byte {rec} gives its {what} {length} "
                      f"bytes, only {end - at - 4} follow")
    return <Py_ssize_t>length


@cython.final
cdef class _Scan:
    cdef const uint8_t* b
    cdef Py_ssize_t n
    cdef _Active active
    cdef _Growable slots            # slot of each data record in file order (-1: ignored)
    cdef _Growable counts           # records per slot
    cdef list entries               # per slot: [name, [types], metadata]
    cdef dict by_name               # name -> slot
    cdef set types                  # (slot, type) pairs seen: a name restarted many
                                    # times costs no scan of its types

    def __cinit__(self):
        self.active = _Active()
        self.slots = _Growable()
        self.counts = _Growable()
        self.entries = []
        self.by_name = {}
        self.types = set()

    cdef int control(self, Py_ssize_t rec, Py_ssize_t at, Py_ssize_t size) except -1:
        cdef const uint8_t* b = self.b
        cdef Py_ssize_t end = at + size, p, ln
        cdef uint32_t entry
        cdef int32_t slot
        cdef str name, type_string, metadata
        cdef int kind
        if size == 0:
            raise Damaged(f"the control record at byte {rec} is empty")
        kind = b[at]
        if kind == 0:                                   # Start
            if size < 17:
                raise Damaged(f"the Start record at byte {rec} has {size} bytes, at least "
                              f"17 are needed")
            entry = <uint32_t>_le(b + at + 1, 4)
            p = at + 5
            ln = _string(b, p, end, "name", rec)
            name = _text(b + p + 4, ln)
            p += 4 + ln
            ln = _string(b, p, end, "type", rec)
            type_string = _text(b + p + 4, ln)
            p += 4 + ln
            ln = _string(b, p, end, "metadata", rec)
            metadata = _text(b + p + 4, ln)
            known = self.by_name.get(name)
            if known is None:
                slot = len(self.entries)
                self.entries.append([name, [type_string], metadata])
                self.by_name[name] = slot
                self.types.add((slot, type_string))
                self.counts.push(0)
            else:
                slot = known
                if (slot, type_string) not in self.types:
                    self.types.add((slot, type_string))
                    self.entries[slot][1].append(type_string)
            self.active.set(entry, slot)
        elif kind == 1:                                 # Finish
            if size != 5:
                raise Damaged(f"the Finish record at byte {rec} has {size} bytes, not 5")
            self.active.set(<uint32_t>_le(b + at + 1, 4), -1)
        elif kind == 2:                                 # SetMetadata
            if size < 9:
                raise Damaged(f"the SetMetadata record at byte {rec} has {size} bytes, at "
                              f"least 9 are needed")
            ln = _string(b, at + 5, end, "metadata", rec)
            slot = self.active.get(<uint32_t>_le(b + at + 1, 4))
            if slot >= 0:
                self.entries[slot][2] = _text(b + at + 9, ln)
        else:
            raise Damaged(f"the control record at byte {rec} has the unknown type {kind}")
        return 0


@cython.boundscheck(False)
@cython.wraparound(False)
cdef void _fill(const uint8_t* b, Py_ssize_t pos, Py_ssize_t end, const int32_t* slots,
                int64_t* fill, int64_t[::1] ts, offset_t[::1] off,
                uint32_t[::1] sz) noexcept:
    """Pass 2 of scan: file each data record into its entry's rows (``fill[slot]`` is
    the next free row); the records up to ``end`` are complete (pass 1 checked)."""
    cdef _Header h
    cdef Py_ssize_t k = 0
    cdef int32_t slot
    cdef int64_t m
    h.entry, h.size, h.ts, h.payload = 0, 0, 0, 0
    while pos < end:
        if _header(b, end, pos, &h):
            break                                   # not reached: pass 1 checked it
        if h.entry != 0:
            slot = slots[k]
            k += 1
            if slot >= 0:
                m = fill[slot]
                fill[slot] = m + 1
                ts[m] = h.ts
                off[m] = <offset_t>h.payload
                sz[m] = h.size
        pos = h.payload + h.size


@cython.boundscheck(False)
@cython.wraparound(False)
def scan(const uint8_t[::1] buf not None):
    """Index a DataLog image. Return ``(extra_header, entries, starts, ts, offsets,
    sizes, end, why)``: ``entries`` a list of ``[name, [types], metadata]`` in order of
    first appearance; the records of entry ``i`` are rows ``starts[i]:starts[i + 1]`` of
    ``ts`` (int64), ``offsets`` (int64, into ``buf``) and ``sizes`` (uint32), in file
    order; ``end`` the end of the last complete record and ``why`` None, or why the bytes
    after ``end`` are not a complete record. Damaged for anything else that is wrong."""
    cdef const uint8_t* b = &buf[0] if buf.shape[0] else NULL
    cdef Py_ssize_t n = buf.shape[0], pos, extra, k, m, i, nslots
    cdef uint32_t version
    cdef _Header h
    cdef _Scan s = _Scan()
    cdef int32_t slot
    cdef int64_t[::1] starts, fill
    cdef int64_t at
    cdef int got
    h.entry, h.size, h.ts, h.payload = 0, 0, 0, 0
    why = None
    if n < 12 or b[0] != b'W' or b[1] != b'P' or b[2] != b'I' or b[3] != b'L' \
            or b[4] != b'O' or b[5] != b'G':
        if n >= 6 or n == 0:
            raise Damaged("not a WPILib DataLog (.wpilog) file: it does not start with "
                          "the 'WPILOG' header")
        raise Damaged("not a WPILib DataLog (.wpilog) file: shorter than its header")
    version = <uint32_t>_le(b + 6, 2)
    if version != 0x0100:
        raise Damaged(f"unsupported DataLog version {version >> 8}.{version & 0xFF} "
                      f"(drivekin reads 1.0)")
    extra = <Py_ssize_t>_le(b + 8, 4)
    if extra > n - 12:
        return ("", [], np.zeros(1, np.int64), np.zeros(0, np.int64),
                np.zeros(0, np.int64), np.zeros(0, np.uint32), 12,
                f"the header says {extra} bytes of extra header, the file has {n - 12}")
    header = _text(b + 12, extra)
    s.b, s.n = b, n
    # Pass 1: framing, control records, the slot of every data record.
    pos = 12 + extra
    while pos < n:
        got = _header(b, n, pos, &h)
        if got:
            if got == 1:
                why = f"the record at byte {pos} has an incomplete header"
            else:
                why = (f"the record at byte {pos} needs {h.payload - pos + h.size} bytes, "
                       f"the file ends {n - pos} bytes after its start")
            break
        if h.entry == 0:
            s.control(pos, h.payload, h.size)
        else:
            slot = s.active.get(h.entry)
            s.slots.push(slot)
            if slot >= 0:
                s.counts.p[slot] += 1
        pos = h.payload + h.size
    end = pos
    # Per-entry row ranges, then pass 2 files each record into its entry's range.
    nslots = len(s.entries)
    starts_a = np.empty(nslots + 1, np.int64)
    starts = starts_a
    fill = np.empty(nslots + 1, np.int64)
    at = 0
    for i in range(nslots):
        starts[i] = at
        fill[i] = at
        at += s.counts.p[i]
    starts[nslots] = at
    wide = n > 0xFFFFFFFF
    ts_a, sz_a = np.empty(at, np.int64), np.empty(at, np.uint32)
    off_a = np.empty(at, np.int64 if wide else np.uint32)
    if wide:
        _fill[int64_t](b, 12 + extra, end, s.slots.p, &fill[0], ts_a, off_a, sz_a)
    else:
        _fill[uint32_t](b, 12 + extra, end, s.slots.p, &fill[0], ts_a, off_a, sz_a)
    return header, s.entries, starts_a, ts_a, off_a, sz_a, end, why


@cython.boundscheck(False)
@cython.wraparound(False)
def gather(const uint8_t[::1] buf not None, const offset_t[::1] offsets not None,
           rows, Py_ssize_t size, uint8_t[::1] out not None):
    """Copy the ``size``-byte payloads at ``offsets[rows[i]]`` (``rows`` an int64 array,
    or None for every row in order) to ``out[i * size:]``. The caller has checked that
    those records hold exactly ``size`` bytes; the bounds are checked here again."""
    cdef const int64_t[::1] r
    cdef Py_ssize_t i, j, n, nbuf = buf.shape[0], noff = offsets.shape[0]
    cdef int64_t o
    cdef bint direct = rows is None
    if not direct:
        r = rows
        n = r.shape[0]
    else:
        n = noff
    if size < 0 or out.shape[0] != n * size:
        raise ValueError("gather: the output does not hold the rows")
    for i in range(n):
        j = i if direct else r[i]
        if j < 0 or j >= noff:
            raise IndexError("gather: row out of range")
        o = offsets[j]
        if o < 0 or o > nbuf - size:
            raise IndexError("gather: payload outside the buffer")
        if size:
            memcpy(&out[i * size], &buf[o], size)


@cython.boundscheck(False)
@cython.wraparound(False)
def payloads(const uint8_t[::1] buf not None, const offset_t[::1] offsets not None,
             const uint32_t[::1] sizes not None):
    """The payloads as a list of bytes objects."""
    cdef Py_ssize_t i, n = offsets.shape[0], nbuf = buf.shape[0]
    cdef int64_t o
    cdef uint32_t s
    cdef list out = []
    if sizes.shape[0] != n:
        raise ValueError("payloads: offsets and sizes differ in length")
    for i in range(n):
        o, s = offsets[i], sizes[i]
        if o < 0 or o > nbuf or s > nbuf - o:
            raise IndexError("payloads: payload outside the buffer")
        out.append(PyBytes_FromStringAndSize(<const char*>&buf[o] if s else NULL, s))
    return out
