"""``.wpilog`` images built byte by byte (no robotpy needed): any field widths, damaged
records, and the hostile files drivekin.datalog must refuse cleanly (:data:`HOSTILE`,
used by tests/safety/test_wpilog_hostile.py and the adversarial suite's datalog group).

:func:`exercise` reads an image the way a user would (read, entries, values and records
of every entry) and returns the DataLogError messages it met; any other exception
propagates.
"""
from __future__ import annotations

import struct


def u32(v: int) -> bytes:
    return struct.pack("<I", v)


def text(s: str | bytes) -> bytes:
    b = s.encode() if isinstance(s, str) else s
    return u32(len(b)) + b


def header(extra: bytes = b"", version: int = 0x0100) -> bytes:
    return b"WPILOG" + struct.pack("<H", version) + u32(len(extra)) + extra


def _width(v: int, most: int) -> int:
    n = 1
    while n < most and v >= 1 << (8 * n):
        n += 1
    return n


def record(entry: int, ts: int, payload: bytes, widths: tuple[int, int, int] | None = None
           ) -> bytes:
    """One record; ``widths`` (entry id 1-4, size 1-4, timestamp 1-8 bytes) default to
    the smallest that hold the values. ``ts`` is stored as its unsigned 64-bit pattern."""
    ts &= (1 << 64) - 1
    le, ls, lt = widths or (_width(entry, 4), _width(len(payload), 4), _width(ts, 8))
    bits = (le - 1) | ((ls - 1) << 2) | ((lt - 1) << 4)
    return (bytes([bits]) + entry.to_bytes(le, "little") + len(payload).to_bytes(ls, "little")
            + ts.to_bytes(lt, "little") + payload)


def start(entry: int, name: str, type_string: str, metadata: str = "", ts: int = 1) -> bytes:
    return record(0, ts, b"\0" + u32(entry) + text(name) + text(type_string) + text(metadata))


def finish(entry: int, ts: int = 1) -> bytes:
    return record(0, ts, b"\1" + u32(entry))


def set_metadata(entry: int, metadata: str, ts: int = 1) -> bytes:
    return record(0, ts, b"\2" + u32(entry) + text(metadata))


def struct_log(schemas: dict[str, str], type_string: str, payloads: list[bytes] = ()) -> bytes:
    """A log publishing ``schemas`` (name -> schema) and entry ``/x`` of ``type_string``
    with one record per payload."""
    out = [header()]
    for i, (name, schema) in enumerate(schemas.items(), start=2):
        out += [start(i, f"/.schema/struct:{name}", "structschema"), record(i, 1, schema.encode())]
    out.append(start(1, "/x", type_string))
    out += [record(1, 10 + k, p) for k, p in enumerate(payloads)]
    return b"".join(out)


def small_log() -> bytes:
    """A few entries of several types, finished and restarted, with metadata changes."""
    out = [header(b'{"producer":"test"}'),
           start(1, "/.schema/struct:Translation2d", "structschema"),
           record(1, 1, b"double x;double y"),
           start(2, "/t", "struct:Translation2d", '{"a":1}'),
           start(3, "/d", "double"), start(4, "/s", "string")]
    for k in range(1, 6):
        out += [record(2, 1000 * k, struct.pack("<2d", k, -k)),
                record(3, 1000 * k, struct.pack("<d", k / 2)), record(4, 1000 * k, b"m%d" % k)]
    out += [set_metadata(2, '{"a":2}'), finish(3, 6000), start(7, "/d", "double", ts=7000),
            record(7, 7000, struct.pack("<d", 9.0)), record(3, 7000, b"ignored: finished"),
            record(99, 7000, b"ignored: never started")]
    return b"".join(out)


def _chain(n: int, cycle: bool = False) -> bytes:
    schemas = {f"S{i}": f"S{i + 1} a" for i in range(n - 1)}
    schemas[f"S{n - 1}"] = "S0 a" if cycle else "double x"
    return struct_log(schemas, "struct:S0", [bytes(8)])


def _damaged(payload: bytes) -> bytes:
    return header() + start(1, "/d", "double") + record(0, 5, payload) + record(1, 6, bytes(8))


def flood(n: int = 40_000) -> bytes:
    """``n`` entries, one record each."""
    return header() + b"".join(start(i, f"/e{i}", "double") + record(i, i, struct.pack("<d", i))
                               for i in range(1, n + 1))


def restarts(n: int = 40_000) -> bytes:
    """One name started ``n`` times, each time with another type."""
    return header() + b"".join(start(1, "/r", f"t{i}") for i in range(n)) + record(1, 1, b"x")


# name -> (image builder, text one of exercise()'s messages must contain, or None if the
# file must read without any error)
HOSTILE = {
    "struct double d[200000000]": (
        lambda: struct_log({"Big": "double d[200000000]"}, "struct:Big", [bytes(8)]),
        "more than 65536 doubles per element"),
    "nested structs 1000 x 1000 x 1000": (
        lambda: struct_log({"A": "B b[1000]", "B": "C c[1000]", "C": "double d[1000]"},
                           "struct:A[]", [b""]),
        "more than 65536 doubles per element"),
    "schema regex backtracking": (
        lambda: struct_log({"Bt": "double a" + " " * 2000 + "!"}, "struct:Bt", [bytes(8)]),
        "cannot parse schema member"),
    "chain of 3000 nested structs": (lambda: _chain(3000), None),
    "cycle of 3000 nested structs": (lambda: _chain(3000, cycle=True), "contains itself"),
    "array count of 5000 digits": (
        lambda: struct_log({"D": "double d[" + "9" * 5000 + "]"}, "struct:D", [bytes(8)]),
        "array count of 5000 digits"),
    "Start record too short": (lambda: _damaged(b"\0" + u32(1) + b"abc"),
                               "the Start record at byte 41 has 8 bytes"),
    "Start record name too long": (
        lambda: _damaged(b"\0" + u32(2) + u32(1 << 31) + bytes(12)), "gives its name"),
    "Start record type cut": (
        lambda: _damaged(b"\0" + u32(2) + text("/n") + u32(50) + bytes(8)), "gives its type"),
    "Start record metadata missing": (
        lambda: _damaged(b"\0" + u32(2) + text("/n") + text("double") + b"\0"),
        "too short for its metadata"),
    "Finish record of 6 bytes": (lambda: _damaged(b"\1" + u32(1) + b"\0"), "not 5"),
    "SetMetadata record too short": (lambda: _damaged(b"\2" + u32(1)), "at least 9"),
    "SetMetadata length past the record": (
        lambda: _damaged(b"\2" + u32(1) + u32(100) + b"x"), "gives its metadata"),
    "unknown control record type": (lambda: _damaged(b"\x07" + u32(1)), "unknown type 7"),
    "empty control record": (lambda: _damaged(b""), "is empty"),
    "extra header past the end": (lambda: header()[:8] + u32(1000) + b"x", "extra header"),
    "4-byte entry ids and 8-byte timestamps": (
        lambda: header() + start(0xFFFFFFFF, "/w", "int64")
        + record(0xFFFFFFFF, -5, bytes(8), (4, 4, 8)) + record(0xFFFFFFFE, 1, b"", (4, 1, 1)),
        None),
    "40000-entry flood": (flood, None),
    "one name restarted with 40000 types": (restarts, "started with several types "
                                                      "(t0, t1, t2, t3, t4, ... (40000 types))"),
}


_NUMERIC = ("double", "float", "int64", "boolean")


def exercise(data: bytes, allowTruncated: bool = False) -> list[str]:
    """Read ``data`` and decode every entry (as a table and as values); the DataLogError
    messages met, in order."""
    from drivekin import datalog
    try:
        log = datalog.read(data, allowTruncated=allowTruncated)
    except datalog.DataLogError as e:
        return [str(e)]
    errors = []
    for name, info in log.entries.items():
        assert info.records >= 0 and isinstance(info.columns, tuple)
        try:
            log.records(name)
            if len(info.type.split("|")) == 1:
                log.table(name)
        except datalog.DataLogError as e:
            errors.append(str(e))
        try:
            if info.type.startswith("struct:") or info.type.rstrip("[]") in _NUMERIC:
                log.values(name, ragged="drop")
                if info.type.endswith("[]"):
                    log.concatenated(name)
        except datalog.DataLogError as e:
            errors.append(str(e))
    return errors
