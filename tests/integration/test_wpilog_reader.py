"""drivekin's native .wpilog reader against robotpy-wpiutil's DataLogReader, bit for bit:
the same entries, types, metadata, extra header, timestamps and payload bytes in file
order, on every kind of log the tests write and on random logs (hypothesis)."""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

pytest.importorskip("wpiutil")

import wpiutil                                                 # noqa: E402
import wpiutil.log as wlog                                     # noqa: E402

from drivekin import Pose2d, Rotation2d, SwerveModulePosition, datalog  # noqa: E402
from tests._support import wpilog_bytes as W                  # noqa: E402
from tests._support.wpilog_logs import simulate_match, write_match_log  # noqa: E402
from tests.integration.test_datalog import robotpy_file        # noqa: E402,F401


def robotpy_view(data: bytes):
    """(extra header, {name: (types, metadata, [(timestamp, payload)])}) through
    robotpy-wpiutil's reader, with drivekin's rules: one entry per name, records of
    entries not started (or finished) ignored, metadata as last set."""
    reader = wlog.DataLogReader(data, "x")
    assert reader.isValid()
    entries: dict = {}
    active: dict = {}
    for rec in reader:
        if rec.getEntry() == 0:
            if rec.isStart():
                s = rec.getStartData()
                e = entries.setdefault(s.name, ([], [s.metadata], []))
                if s.type not in e[0]:
                    e[0].append(s.type)
                active[s.entry] = e
            elif rec.isFinish():
                active.pop(rec.getFinishEntry(), None)
            elif rec.isSetMetadata():
                md = rec.getSetMetadataData()
                if md.entry in active:
                    active[md.entry][1][0] = md.metadata
            continue
        e = active.get(rec.getEntry())
        if e is not None:
            e[2].append((rec.getTimestamp(), bytes(rec.getRaw())))
    return reader.getExtraHeader(), {n: (t, m[0], r) for n, (t, m, r) in entries.items()}


def drivekin_view(data: bytes):
    log = datalog.read(data)
    out = {}
    for name, e in log._entries.items():
        out[name] = (list(e.types), e.metadata, list(zip(e.ts.tolist(), e.data)))
    return log.extraHeader, out


def assert_same(data: bytes) -> None:
    ours, theirs = drivekin_view(data), robotpy_view(data)
    assert ours[0] == theirs[0]
    assert list(ours[1]) == list(theirs[1])          # names, in order of first Start
    for name in theirs[1]:
        assert ours[1][name] == theirs[1][name], name


def test_robotpy_written_log(robotpy_file):                    # noqa: F811
    assert_same(robotpy_file.read_bytes())


def test_match_log(tmp_path):
    path = tmp_path / "match.wpilog"
    write_match_log(path, simulate_match(seconds=3.0))
    data = path.read_bytes()
    assert_same(data)
    log = datalog.read(path)
    assert log.entries["/Drive/ModulePositions"].records > 500


def test_drivekin_written_log(tmp_path):
    path = tmp_path / "ours.wpilog"
    with datalog.Writer(path, extraHeader="drivekin test ✓") as w:
        for k in range(1, 30):
            w.append("/Pose", Pose2d(k, 2.0, Rotation2d(0.5)), 1000 * k)
            w.append("/Mods", [SwerveModulePosition(k, Rotation2d(0.1))] * 4, 1000 * k)
            w.append("/Volts", 12.0 - k / 10, 1000 * k)
            w.append("/Msg", f"m{k}", 1000 * k)
        w.appendSeries("/S", "double[]", np.arange(1, 11), np.ones((10, 3)), metadata="md")
    assert_same(path.read_bytes())


def test_hand_built_logs():
    assert_same(W.small_log())
    assert_same(W.HOSTILE["4-byte entry ids and 8-byte timestamps"][0]())
    assert_same(W.flood(2000))


_names = st.sampled_from(["/a", "/b", "/c/d", "/ünï", "messages"])
_types = st.sampled_from(["double", "int64", "string", "struct:Pose2d", "raw", "double[]"])
_op = st.one_of(
    st.tuples(st.just("start"), _names, _types, st.text(max_size=8)),
    st.tuples(st.just("append"), st.integers(0, 5), st.integers(1, 2**40),
              st.binary(max_size=40)),
    st.tuples(st.just("finish"), st.integers(0, 5), st.integers(1, 2**40)),
    st.tuples(st.just("meta"), st.integers(0, 5), st.text(max_size=8)),
)


@settings(max_examples=60, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(st.text(max_size=10), st.lists(_op, max_size=40))
def test_random_logs_from_robotpys_writer(tmp_path, extra, ops):
    path = tmp_path / "random.wpilog"
    log = wpiutil.DataLogWriter(str(path), extra)
    ids: list[int] = []
    for op in ops:
        if op[0] == "start":
            ids.append(log.start(op[1], op[2], op[3], 1))
        elif ids and op[0] == "append":
            log.appendRaw(ids[op[1] % len(ids)], op[3], op[2])
        elif ids and op[0] == "finish":
            log.finish(ids[op[1] % len(ids)], op[2])
        elif ids and op[0] == "meta":
            log.setMetadata(ids[op[1] % len(ids)], op[2], 1)
    log.flush()
    log.stop()
    assert_same(path.read_bytes())


_widths = st.tuples(st.integers(1, 4), st.integers(1, 4), st.integers(1, 8))


@settings(max_examples=150, deadline=None)
@given(st.lists(st.one_of(
    st.tuples(st.just("start"), st.integers(1, 2**32 - 1), _names, _types, st.text(max_size=5)),
    st.tuples(st.just("data"), st.integers(0, 6), st.integers(0, 2**64 - 1),
              st.binary(max_size=30), _widths),
    st.tuples(st.just("finish"), st.integers(0, 6)),
    st.tuples(st.just("meta"), st.integers(0, 6), st.text(max_size=5)),
), max_size=40))
def test_random_hand_built_logs(ops):
    # Any field widths, entry ids up to 2**32 - 1, 8-byte timestamps (negative ones too).
    image, ids = [W.header(b"x")], [7]
    for op in ops:
        if op[0] == "start":
            ids.append(op[1])
            image.append(W.start(op[1], op[2], op[3], op[4]))
        elif op[0] == "data":
            le, ls, lt = op[4]
            entry = ids[op[1] % len(ids)] & ((1 << (8 * le)) - 1)
            if entry == 0:
                continue
            image.append(W.record(entry, op[2] & ((1 << (8 * lt)) - 1), op[3], (le, ls, lt)))
        elif op[0] == "finish":
            image.append(W.finish(ids[op[1] % len(ids)]))
        else:
            image.append(W.set_metadata(ids[op[1] % len(ids)], op[2]))
    assert_same(b"".join(image))
