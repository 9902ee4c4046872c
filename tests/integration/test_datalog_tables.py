"""LogData.table / LogData.dataframe: every entry as named columns, against
robotpy-wpiutil's own reader and robotpy's wpistruct unpacking (with the robotpy-wpimath
classes, or robotpy dataclass structs) on logs robotpy-wpiutil's DataLogWriter wrote,
and on real robot logs."""
from __future__ import annotations

import dataclasses
import struct
import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("wpiutil")

import wpiutil.log as wlog                                     # noqa: E402
import wpiutil.wpistruct as ws                                 # noqa: E402
import wpimath.geometry as wg                                  # noqa: E402
import wpimath.kinematics as wk                                # noqa: E402

from drivekin import datalog                                   # noqa: E402
from drivekin.datalog import DataLogError                      # noqa: E402
from tests._support.wpilog_logs import robotpy_log             # noqa: E402

REAL_LOGS = Path(__file__).resolve().parents[2] / ".." / "shared" / "reallogs" / "logs"


@ws.make_wpistruct(name="Pose2d")
@dataclasses.dataclass
class FlatPose2d:
    """A Pose2d whose schema lists plain doubles (as custom C++ structs and WPILib's
    2023 betas wrote), published under WPILib's own name."""
    x: ws.double
    y: ws.double
    theta: ws.double


@ws.make_wpistruct(name="TagSeen")
@dataclasses.dataclass
class TagSeen:
    """A team struct of mixed member types, a nested WPILib struct among them."""
    id: ws.uint32
    ok: bool
    area: float             # robotpy writes a Python float as a 4-byte "float"
    k: ws.int16
    big: ws.int64
    pose: wg.Pose2d


_GETTERS = {"double": "getDouble", "double[]": "getDoubleArray", "int64[]": "getIntegerArray",
            "boolean": "getBoolean", "string": "getString", "string[]": "getStringArray"}


class _Rec:
    """One record as robotpy-wpiutil's reader gives it (its record object is reused
    while iterating, so the parts are copied out)."""

    def __init__(self, rec, type_string: str) -> None:
        self.ts = rec.getTimestamp()
        self.raw = bytes(rec.getRaw())
        getter = _GETTERS.get(type_string)
        self.value = getattr(rec, getter)() if getter else None
        if isinstance(self.value, list):
            self.value = list(self.value)


def _oracle(path) -> dict:
    """{name: (type, [_Rec])} through robotpy-wpiutil's reader."""
    entries: dict = {}
    active: dict = {}
    for rec in wlog.DataLogReader(str(path)):
        if rec.getEntry() == 0:
            if rec.isStart():
                s = rec.getStartData()
                active[s.entry] = entries.setdefault(s.name, (s.type, []))
            continue
        if rec.getEntry() in active:
            type_string, recs = active[rec.getEntry()]
            recs.append(_Rec(rec, type_string))
    return entries


def _by_time(recs):
    return sorted(recs, key=lambda r: r.ts)                    # sorted() is stable


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """Every kind of entry, records out of time order, written by robotpy-wpiutil."""
    path = tmp_path_factory.mktemp("tables") / "tables.wpilog"
    rng = np.random.default_rng(30)
    stamps = [5000, 1000, 3000, 3000, 9000, 7000]               # out of order, a tie
    with robotpy_log(path) as log:
        e = {
            "pose": log.start("/Pose", "struct:Pose2d", 1, wg.Pose2d),
            "states": log.start("/States", "struct:SwerveModuleState[]", 1, wk.SwerveModuleState),
            "speeds": log.start("/Speeds", "struct:ChassisSpeeds", 1, wk.ChassisSpeeds),
            "tag": log.start("/Tags", "struct:TagSeen[]", 1, TagSeen),
            "d": log.start("/Volts", "double", 1),
            "da": log.start("/Currents", "double[]", 1),
            "ragged": log.start("/Samples", "double[]", 1),
            "ia": log.start("/Counts", "int64[]", 1),
            "b": log.start("/Enabled", "boolean", 1),
            "s": log.start("/Msg", "string", 1),
            "sa": log.start("/Names", "string[]", 1),
            "raw": log.start("/Blob", "raw", 1),
        }
        w = log.log
        for i, ts in enumerate(stamps):
            x = rng.normal(size=12)
            w.appendRaw(e["pose"], ws.pack(wg.Pose2d(x[0], x[1], wg.Rotation2d(x[2]))), ts)
            w.appendRaw(e["states"], ws.packArray([wk.SwerveModuleState(x[j], wg.Rotation2d(x[j + 4]))
                                                   for j in range(4)]), ts)
            w.appendRaw(e["speeds"], ws.pack(wk.ChassisSpeeds(x[3], x[4], x[5])), ts)
            w.appendRaw(e["tag"], ws.packArray(
                [TagSeen(7 + i + j, bool(j % 2), float(x[j]), -3 * i + j, -(2 ** 40) * i,
                         wg.Pose2d(x[j + 1], x[j + 2], wg.Rotation2d(x[j + 3])))
                 for j in range(i % 3)]), ts)
            w.appendDouble(e["d"], x[6], ts)
            w.appendDoubleArray(e["da"], list(x[7:10]), ts)
            w.appendDoubleArray(e["ragged"], list(x[:i]), ts)
            w.appendIntegerArray(e["ia"], [i, -i, 2 ** 50 + i], ts)
            w.appendBoolean(e["b"], i % 2 == 0, ts)
            w.appendString(e["s"], f"step {i} é", ts)
            w.appendStringArray(e["sa"], [f"m{j}" for j in range(i)], ts)
            w.appendRaw(e["raw"], bytes([i]) * i, ts)
            log._tick()
    return path, _oracle(path)


def test_struct_columns_match_robotpys_unpacking(written):
    path, ref = written
    log = datalog.read(path)
    pose = log.table("/Pose")
    recs = _by_time(ref["/Pose"][1])
    assert list(pose) == ["timestamp", "translation.x", "translation.y", "rotation.value"]
    assert pose["timestamp"].dtype == np.int64
    assert pose["timestamp"].tolist() == [r.ts for r in recs]
    want = [ws.unpack(wg.Pose2d, r.raw) for r in recs]
    assert pose["translation.x"].tolist() == [p.X() for p in want]
    assert pose["translation.y"].tolist() == [p.Y() for p in want]
    assert pose["rotation.value"].tolist() == [p.rotation().radians() for p in want]
    speeds = log.table("/Speeds")
    want_s = [ws.unpack(wk.ChassisSpeeds, r.raw) for r in _by_time(ref["/Speeds"][1])]
    assert [speeds["vx"].tolist(), speeds["vy"].tolist(), speeds["omega"].tolist()] == [
        [s.vx for s in want_s], [s.vy for s in want_s], [s.omega for s in want_s]]


def test_struct_arrays_give_one_2d_column_per_field(written):
    path, ref = written
    t = datalog.read(path).table("/States")
    want = [ws.unpackArray(wk.SwerveModuleState, r.raw)
            for r in _by_time(ref["/States"][1])]
    assert list(t) == ["timestamp", "speed", "angle.value"]
    assert t["speed"].shape == (6, 4)
    assert t["speed"].tolist() == [[m.speed for m in row] for row in want]
    assert t["angle.value"].tolist() == [[m.angle.radians() for m in row] for row in want]


def test_mixed_member_types_and_arrays_that_change_length(written):
    """A robotpy dataclass struct (uint32, bool, 4-byte float, int16, int64, a nested
    Pose2d) in arrays of 0, 1 or 2 elements: one object column per field, each cell the
    record's elements."""
    path, ref = written
    t = datalog.read(path).table("/Tags")
    want = [ws.unpackArray(TagSeen, r.raw) for r in _by_time(ref["/Tags"][1])]
    assert list(t) == ["timestamp", "id", "ok", "area", "k", "big", "pose.translation.x",
                       "pose.translation.y", "pose.rotation.value"]
    assert [len(c) for c in t["id"]] == [len(w) for w in want]
    assert t["id"][0].dtype == np.uint32 and t["ok"][0].dtype == np.bool_
    assert t["k"][0].dtype == np.int16 and t["big"][0].dtype == np.int64
    for row, w in enumerate(want):
        assert t["id"][row].tolist() == [m.id for m in w]
        assert t["ok"][row].tolist() == [m.ok for m in w]
        assert t["area"][row].tolist() == [m.area for m in w]       # float32 exact in float64
        assert t["k"][row].tolist() == [m.k for m in w]
        assert t["big"][row].tolist() == [m.big for m in w]
        assert t["pose.rotation.value"][row].tolist() == [m.pose.rotation().radians() for m in w]


def test_flat_schema_names_its_own_fields(tmp_path):
    """A log whose struct:Pose2d schema lists plain doubles gives that schema's names."""
    path = tmp_path / "flat.wpilog"
    with robotpy_log(path) as log:
        e = log.start("/Pose", "struct:Pose2d", 1, FlatPose2d)
        for k in range(1, 4):
            log.raw(e, ws.pack(FlatPose2d(0.5 * k, -k, 0.1 * k)), 100 * k)
    recs = _by_time(_oracle(path)["/Pose"][1])
    t = datalog.read(path).table("/Pose")
    want = [ws.unpack(FlatPose2d, r.raw) for r in recs]
    assert list(t) == ["timestamp", "x", "y", "theta"]
    assert t["theta"].tolist() == [p.theta for p in want]
    assert t["x"].tolist() == [p.x for p in want]


def test_plain_entries(written):
    path, ref = written
    log = datalog.read(path)
    got = {n: log.table(n) for n in ("/Volts", "/Currents", "/Counts", "/Enabled", "/Msg",
                                     "/Names", "/Blob", "/Samples")}
    r = {n: _by_time(ref[n][1]) for n in got}
    assert got["/Volts"]["value"].tolist() == [x.value for x in r["/Volts"]]
    assert got["/Currents"]["value"].shape == (6, 3)
    assert got["/Currents"]["value"].tolist() == [x.value for x in r["/Currents"]]
    assert got["/Counts"]["value"].dtype == np.int64
    assert got["/Counts"]["value"].tolist() == [x.value for x in r["/Counts"]]
    assert got["/Enabled"]["value"].dtype == np.bool_
    assert got["/Enabled"]["value"].tolist() == [x.value for x in r["/Enabled"]]
    assert got["/Msg"]["value"].tolist() == [x.value for x in r["/Msg"]]
    assert got["/Names"]["value"].tolist() == [tuple(x.value) for x in r["/Names"]]
    assert got["/Blob"]["value"].tolist() == [x.raw for x in r["/Blob"]]
    ragged = got["/Samples"]["value"]
    assert ragged.dtype == object
    assert [c.tolist() for c in ragged] == [x.value for x in r["/Samples"]]


def test_tables_are_read_only_and_decoded_once(written):
    log = datalog.read(written[0])
    t = log.table("/States")
    assert log.table("/States") is t
    with pytest.raises(ValueError, match="read-only"):
        t["speed"][0, 0] = 1.0
    assert log._stats["table", "/States"] == 1


def test_bad_names_name_close_ones(written):
    log = datalog.read(written[0])
    with pytest.raises(DataLogError, match=r"no entry named '/state'; similar: .*'/States'"):
        log.table("/state")
    with pytest.raises(TypeError, match="must be a str"):
        log.table(5)


def test_a_struct_without_a_schema_is_refused_by_name(tmp_path):
    path = tmp_path / "noschema.wpilog"
    with robotpy_log(path) as log:
        log.raw(log.start("/Mystery", "struct:Mystery", 1), b"\0" * 8, 5)
    with pytest.raises(DataLogError, match=r"'/Mystery' \(struct:Mystery\): no schema for struct:Mystery"):
        datalog.read(path).table("/Mystery")


def test_dataframe_matches_the_table(written):
    pd = pytest.importorskip("pandas")
    log = datalog.read(written[0])
    df = log.dataframe("/States")
    t = log.table("/States")
    assert isinstance(df, pd.DataFrame)
    assert list(df.columns) == ["timestamp"] + [f"[{i}].{f}" for i in range(4)
                                                for f in ("speed", "angle.value")]
    assert df["[2].angle.value"].tolist() == t["angle.value"][:, 2].tolist()
    assert list(log.dataframe("/Currents").columns) == ["timestamp", "[0]", "[1]", "[2]"]
    df.loc[0, "[0].speed"] = 99.0                                # a copy: the table is intact
    assert t["speed"][0, 0] != 99.0


def test_dataframe_without_pandas_says_how_to_install(written, monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match=r'pip install "drivekin\[pandas\]"'):
        datalog.read(written[0]).dataframe("/Pose")


REAL = [("team302_FRC_20240910_002841.wpilog", "struct:SwerveModuleState", wk.SwerveModuleState),
        ("team302_FRC_20240910_002841.wpilog", "struct:Pose2d", wg.Pose2d),
        ("yagsl_1672_FRC_20250214_212636.wpilog", "struct:SwerveModuleState[]",
         wk.SwerveModuleState),
        ("yagsl_1672_FRC_20250214_212636.wpilog", "struct:ChassisSpeeds", wk.ChassisSpeeds)]


@pytest.mark.parametrize("filename, type_string, cls", REAL)
def test_real_logs_match_robotpys_unpacking(filename, type_string, cls):
    path = REAL_LOGS / filename
    if not path.is_file():
        pytest.skip(f"{REAL_LOGS} is absent")
    ref = _oracle(path)
    log = datalog.read(path)
    names = [n for n, (t, recs) in ref.items() if t == type_string and recs]
    assert names
    array = type_string.endswith("[]")
    for name in names[:4]:
        recs = _by_time(ref[name][1])
        t = log.table(name)
        assert t["timestamp"].tolist() == [r.ts for r in recs]
        for r, row in zip(recs, range(len(recs))):
            raw = r.raw
            objs = ws.unpackArray(cls, raw) if array else [ws.unpack(cls, raw)]
            got = [[t[c][row] if not array else t[c][row][i] for c in list(t)[1:]]
                   for i in range(len(objs))]
            # the oracle's fields in schema order, through the wpimath object
            assert got == [_fields(o) for o in objs]


def _fields(o) -> list[float]:
    if isinstance(o, wk.SwerveModuleState):
        return [o.speed, o.angle.radians()]
    if isinstance(o, wg.Pose2d):
        return [o.X(), o.Y(), o.rotation().radians()]
    return [o.vx, o.vy, o.omega]


def test_real_struct_schemas_are_wpilibs_nested_ones():
    """WPILib's Java and C++ publish the same nested schemas (a Pose2d holds a
    Translation2d and a Rotation2d), as both real logs show."""
    path = REAL_LOGS / "team302_FRC_20240910_002841.wpilog"
    if not path.is_file():
        pytest.skip(f"{REAL_LOGS} is absent")
    log = datalog.read(path)
    assert log.schemas["Pose2d"] == "Translation2d translation;Rotation2d rotation"
    name = next(n for n, e in log.entries.items() if e.type == "struct:Pose2d" and e.records)
    assert list(log.table(name)) == ["timestamp", "translation.x", "translation.y",
                                     "rotation.value"]


def test_struct_with_integer_members_from_a_real_log():
    """gtsam-playground's TagDetection (uint32 id, doubles, a nested Pose2d)."""
    path = REAL_LOGS / "mcm001_FRC_20241013_023615.wpilog"
    if not path.is_file():
        pytest.skip(f"{REAL_LOGS} is absent")
    ref = _oracle(path)
    log = datalog.read(path)
    name = next(n for n, (t, recs) in ref.items() if t == "struct:TagDetection[]" and recs)
    t = log.table(name)
    size = 4 + 8 * 8 + 24
    for row, r in enumerate(_by_time(ref[name][1])):
        raw = r.raw
        elems = [struct.unpack_from("<I8d3d", raw, i * size) for i in range(len(raw) // size)]
        assert t["id"][row].tolist() == [e[0] for e in elems]
        assert t["cy4"][row].tolist() == [e[8] for e in elems]
        assert t["guess.rotation.value"][row].tolist() == [e[11] for e in elems]
