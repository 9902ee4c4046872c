"""drivekin.datalog: .wpilog files read from robotpy-wpiutil's writer, drivekin's writer
read back by robotpy-wpiutil's reader, and damaged or unexpected files."""
from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

pytest.importorskip("wpiutil")

import wpiutil.log as wlog                                     # noqa: E402
import wpiutil.wpistruct as ws                                 # noqa: E402
import wpimath.geometry as wg                                  # noqa: E402
import wpimath.kinematics as wk                                # noqa: E402

import drivekin                                                # noqa: E402
from drivekin import (                                         # noqa: E402
    ChassisVelocities,
    DifferentialDriveWheelPositions,
    MecanumDriveKinematics,
    MecanumDriveWheelPositions,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Translation2d,
    datalog,
)
from drivekin.datalog import DataLogError                      # noqa: E402
from tests._support.wpilog_logs import robotpy_log             # noqa: E402

_PACKAGE_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(drivekin.__file__)))


def _python(code: str) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (_PACKAGE_ROOT, env.get("PYTHONPATH", ""))
                                        if p)
    return subprocess.run([sys.executable, "-c", textwrap.dedent(code)], env=env,
                          capture_output=True, text=True, timeout=120)


@pytest.fixture
def robotpy_file(tmp_path):
    """A log written by robotpy-wpiutil with robotpy-wpimath values."""
    path = tmp_path / "robotpy.wpilog"
    with robotpy_log(path) as log:
        e_pose = log.start("/Pose", "struct:Pose2d", 1, wg.Pose2d)
        e_mods = log.start("/Modules", "struct:SwerveModulePosition[]", 1,
                           wk.SwerveModulePosition)
        e_states = log.start("/States", "struct:SwerveModuleState[]", 1, wk.SwerveModuleState)
        e_gyro = log.start("/Gyro", "struct:Rotation2d", 1, wg.Rotation2d)
        e_d = log.start("/Volts", "double", 1)
        e_da = log.start("/Currents", "double[]", 1)
        e_i = log.start("/Count", "int64", 1)
        e_b = log.start("/Enabled", "boolean", 1)
        e_s = log.start("/Msg", "string", 1)
        for k in range(1, 6):
            ts = 1000 * k
            log.raw(e_pose, ws.pack(wg.Pose2d(k, -k, wg.Rotation2d(0.1 * k))), ts)
            log.raw(e_mods, ws.packArray([wk.SwerveModulePosition(k + j, wg.Rotation2d(4.0))
                                          for j in range(3)]), ts)
            log.raw(e_states, ws.packArray([wk.SwerveModuleState(0.5 * k, wg.Rotation2d(-1.0))
                                            for _ in range(2)]), ts)
            log.raw(e_gyro, ws.pack(wg.Rotation2d(7.0 + k)), ts)
            log.double(e_d, 12.0 - k / 10, ts)
            log.log.appendDoubleArray(e_da, [k, 2.0 * k], ts)
            log.log.appendInteger(e_i, 10 * k, ts)
            log.log.appendBoolean(e_b, k % 2 == 0, ts)
            log.log.appendString(e_s, f"m{k}", ts)
    return path


# ---------------------------------------------------------------------------------------
# Reading what robotpy-wpiutil wrote

def test_reads_robotpy_struct_entries_as_arrays(robotpy_file):
    log = datalog.read(robotpy_file)
    t, poses = log.values("/Pose")
    assert t.dtype == np.int64 and t.tolist() == [1000, 2000, 3000, 4000, 5000]
    assert poses.dtype == np.float64 and poses.shape == (5, 3)
    np.testing.assert_array_equal(poses, [[k, -k, 0.1 * k] for k in range(1, 6)])
    t, mods = log.values("/Modules")
    assert mods.shape == (5, 3, 2)
    np.testing.assert_array_equal(mods[:, :, 0], [[k + j for j in range(3)] for k in range(1, 6)])
    # robotpy 2026 packs the constructor value unwrapped; it comes back as stored.
    assert (mods[:, :, 1] == 4.0).all()
    t, gyro = log.values("/Gyro")
    assert gyro.shape == (5,) and gyro.tolist() == [7.0 + k for k in range(1, 6)]


def test_reads_2026_names_with_the_logs_schema(robotpy_file):
    log = datalog.read(robotpy_file)
    assert log.schemas["SwerveModuleState"] == "double speed;Rotation2d angle"
    info = log.entries["/States"]
    assert info.type == "struct:SwerveModuleState[]" and info.records == 5
    assert info.columns == ("speed", "angle.value")
    _, states = log.values("/States")
    assert states.shape == (5, 2, 2)
    np.testing.assert_array_equal(states[:, 0, 0], [0.5 * k for k in range(1, 6)])
    assert (states[:, :, 1] == -1.0).all()
    assert log.entries["/Pose"].columns == ("translation.x", "translation.y", "rotation.value")


def test_reads_plain_entries(robotpy_file):
    log = datalog.read(robotpy_file)
    _, volts = log.values("/Volts")
    assert volts.dtype == np.float64 and volts.tolist() == [12.0 - k / 10 for k in range(1, 6)]
    _, cur = log.values("/Currents")
    assert cur.shape == (5, 2) and cur[:, 1].tolist() == [2.0 * k for k in range(1, 6)]
    _, count = log.values("/Count")
    assert count.dtype == np.int64 and count.tolist() == [10, 20, 30, 40, 50]
    _, en = log.values("/Enabled")
    assert en.dtype == np.bool_ and en.tolist() == [False, True, False, True, False]
    t, raw = log.records("/Msg")
    assert [bytes(r) for r in raw] == [b"m1", b"m2", b"m3", b"m4", b"m5"]


def test_entries_list_names_types_and_counts(robotpy_file):
    infos = {e.name: e for e in datalog.listEntries(robotpy_file)}
    assert infos["/Modules"].type == "struct:SwerveModulePosition[]"
    assert infos["/Msg"].type == "string" and infos["/Msg"].records == 5
    assert infos["/.schema/struct:Pose2d"].type == "structschema"
    assert all(infos[n].records == 5 for n in ("/Pose", "/Gyro", "/Volts", "/Enabled"))


def test_non_numeric_and_missing_entries_are_clear_errors(robotpy_file):
    log = datalog.read(robotpy_file)
    with pytest.raises(DataLogError, match=r"'/Msg'.*'string' is not numeric"):
        log.values("/Msg")
    with pytest.raises(DataLogError, match=r"no entry named '/Nope'"):
        log.values("/Nope")
    with pytest.raises(TypeError, match="entry name must be a str"):
        log.values(3)


# ---------------------------------------------------------------------------------------
# Order, gaps, length changes

def test_out_of_order_records_are_sorted_stably(tmp_path):
    path = tmp_path / "order.wpilog"
    with robotpy_log(path) as log:
        e = log.start("/x", "double", 1)
        for ts, v in ((3000, 3.0), (1000, 1.0), (2000, 2.0), (2000, 2.5), (5000, 5.0),
                      (4000, 4.0), (2000, 2.75)):
            log.double(e, v, ts)
    t, v = datalog.read(path).values("/x")
    assert t.tolist() == [1000, 2000, 2000, 2000, 3000, 4000, 5000]
    assert v.tolist() == [1.0, 2.0, 2.5, 2.75, 3.0, 4.0, 5.0]   # equal times: file order
    t_raw, _ = datalog.read(path).records("/x")
    assert t_raw.tolist()[:3] == [3000, 1000, 2000]             # records() keeps file order


def test_arrays_that_change_length_error_or_drop(tmp_path):
    path = tmp_path / "ragged.wpilog"
    with robotpy_log(path) as log:
        e = log.start("/m", "struct:SwerveModulePosition[]", 1, wk.SwerveModulePosition)
        log.raw(e, b"", 500)                                   # empty array at startup
        for k in range(1, 5):
            log.raw(e, ws.packArray([wk.SwerveModulePosition(k, wg.Rotation2d(0.0))] * 4),
                    1000 * k)
        log.raw(e, ws.packArray([wk.SwerveModulePosition(9, wg.Rotation2d(0.0))] * 3), 6000)
    log = datalog.read(path)
    with pytest.raises(DataLogError, match=r"changes size.*0 \(1 records\), 3 \(1 records\), "
                                           r"4 \(4 records\).*ragged='drop'"):
        log.values("/m")
    t, v = log.values("/m", ragged="drop")
    assert t.tolist() == [1000, 2000, 3000, 4000] and v.shape == (4, 4, 2)
    with pytest.raises(ValueError, match="ragged must be"):
        log.values("/m", ragged="pad")


def test_gaps_are_kept_as_they_are(tmp_path):
    path = tmp_path / "gap.wpilog"
    with robotpy_log(path) as log:
        e = log.start("/x", "double", 1)
        for ts in (1000, 2000, 900000, 901000):
            log.double(e, ts / 1e6, ts)
    t, v = datalog.read(path).values("/x")
    assert t.tolist() == [1000, 2000, 900000, 901000] and len(v) == 4


# ---------------------------------------------------------------------------------------
# Damaged and unexpected files

def test_truncated_file_is_refused_unless_allowed(robotpy_file, tmp_path):
    data = robotpy_file.read_bytes()
    cut = tmp_path / "cut.wpilog"
    cut.write_bytes(data[:-5])
    with pytest.raises(DataLogError, match=r"cut\.wpilog: truncated at byte \d+ of "
                                           rf"{len(data) - 5}.*allowTruncated=True"):
        datalog.read(cut)
    log = datalog.read(cut, allowTruncated=True)
    assert log.truncated and "truncated" in log.truncated
    full = datalog.read(robotpy_file)
    # Exactly the last record (a string "m5") is lost.
    assert log.entries["/Msg"].records == full.entries["/Msg"].records - 1
    assert log.values("/Pose")[1].tolist() == full.values("/Pose")[1].tolist()


@pytest.mark.parametrize("content, message", [
    (b"", "not a WPILib DataLog"),
    (b"WPIL", "not a WPILib DataLog"),
    (b"hello, this is not a log at all\n" * 4, "does not start with the 'WPILOG' header"),
    (b"WPILOG\x00\x02\x00\x00\x00\x00", "unsupported DataLog version 2.0"),
    (b"WPILOG\x00\x01\xff\x00\x00\x00abc", "extra header"),
])
def test_not_a_log_is_a_clear_error(tmp_path, content, message):
    path = tmp_path / "bad.wpilog"
    path.write_bytes(content)
    with pytest.raises(DataLogError, match=message):
        datalog.read(path)


def test_header_only_log_has_no_entries(tmp_path):
    path = tmp_path / "empty.wpilog"
    with robotpy_log(path):
        pass
    log = datalog.read(path)
    assert log.entries == {}
    with pytest.raises(DataLogError, match="no entry named"):
        log.values("/Pose")


def test_read_accepts_bytes_and_refuses_other_types(robotpy_file):
    log = datalog.read(robotpy_file.read_bytes())
    assert log.source == "<buffer>" and "/Pose" in log.entries
    with pytest.raises(TypeError, match="path or bytes"):
        datalog.read(3.5)
    with pytest.raises(FileNotFoundError):
        datalog.read(robotpy_file.parent / "missing.wpilog")


def test_struct_with_integer_members_is_refused_clearly(tmp_path):
    path = tmp_path / "int.wpilog"
    with robotpy_log(path) as log:
        log.log.addSchema("struct:Odd", "structschema", "int32 a;double b", 1)
        e = log.start("/odd", "struct:Odd", 1)
        log.raw(e, bytes(12), 1000)
        e2 = log.start("/unknown", "struct:Mystery", 1)
        log.raw(e2, bytes(8), 1000)
    log = datalog.read(path)
    with pytest.raises(DataLogError, match=r"member 'a' is int32; only structs of doubles"):
        log.values("/odd")
    with pytest.raises(DataLogError, match=r"no schema for struct:Mystery"):
        log.values("/unknown")


# ---------------------------------------------------------------------------------------
# drivekin's writer, read back by robotpy-wpiutil's reader

def _robotpy_read(path):
    """{name: (type, [(timestamp, bytes)])} and the schema entries, via wpiutil only."""
    names, out = {}, {}
    for rec in wlog.DataLogReader(str(path)):
        if rec.isStart():
            s = rec.getStartData()
            names[s.entry] = s.name
            out[s.name] = (s.type, s.metadata, [])
        elif not rec.isControl():
            out[names[rec.getEntry()]][2].append((rec.getTimestamp(), rec.getRaw()))
    return out


def test_writer_round_trip_through_robotpy_reader(tmp_path):
    path = tmp_path / "ours.wpilog"
    kin = SwerveDriveKinematics(Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
                                Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))
    mods = [SwerveModulePosition(1.5 + j, Rotation2d(0.25 * j)) for j in range(4)]
    with datalog.Writer(path, extraHeader="drivekin test") as w:
        w.append("/Pose", Pose2d(1.0, 2.0, Rotation2d(0.5)), 1000)
        w.append("/Pose", Pose2d(1.5, 2.5, Rotation2d(-0.5)), 2000)
        w.append("/Modules", mods, 1000)
        w.append("/States", [SwerveModuleVelocity(2.0, Rotation2d(1.0))] * 4, 1000)
        w.append("/Speeds", ChassisVelocities(1.0, 2.0, 3.0), 1000)
        w.append("/Kin", kin, 1000)
        w.append("/Mecanum", MecanumDriveWheelPositions(1.0, 2.0, 3.0, 4.0), 1000)
        w.append("/Diff", DifferentialDriveWheelPositions(0.5, 0.75), 1000)
        w.append("/Gyro", Rotation2d(4.0), 1000)
        w.append("/Volts", 12.5, 1000)
        w.append("/Arr", [1.0, 2.0, 3.0], 1000)
        w.append("/On", True, 1000)
        w.append("/Msg", "hello", 1000)
    got = _robotpy_read(path)
    assert wlog.DataLogReader(str(path)).getExtraHeader() == "drivekin test"
    assert got["/Pose"][0] == "struct:Pose2d"
    p = [ws.unpack(wg.Pose2d, d) for _, d in got["/Pose"][2]]
    assert [(q.X(), q.Y(), q.rotation().radians()) for q in p] == [(1.0, 2.0, 0.5),
                                                                    (1.5, 2.5, -0.5)]
    assert [t for t, _ in got["/Pose"][2]] == [1000, 2000]
    assert got["/Modules"][0] == "struct:SwerveModulePosition[]"
    m = ws.unpackArray(wk.SwerveModulePosition, got["/Modules"][2][0][1])
    assert [(x.distance, x.angle.radians()) for x in m] == [(1.5 + j, 0.25 * j) for j in range(4)]
    assert got["/States"][0] == "struct:SwerveModuleVelocity[]"
    assert got["/Speeds"][0] == "struct:ChassisVelocities"
    assert got["/Kin"][0] == "struct:SwerveDriveKinematics__4"
    assert got["/Mecanum"][0] == "struct:MecanumDriveWheelPositions"
    assert got["/Diff"][0] == "struct:DifferentialDriveWheelPositions"
    g = ws.unpack(wg.Rotation2d, got["/Gyro"][2][0][1])
    assert g.radians() == pytest.approx(4.0 - 2 * np.pi, abs=1e-15)   # 2027: wrapped
    assert got["/Volts"][0] == "double"
    assert got["/Arr"][0] == "double[]" and got["/On"][0] == "boolean"
    assert got["/Msg"][0] == "string" and bytes(got["/Msg"][2][0][1]) == b"hello"
    # Every schema, nested ones included, published once, under its 2027 name.
    schemas = {n[len("/.schema/"):]: bytes(v[2][0][1]).decode() for n, v in got.items()
               if n.startswith("/.schema/")}
    assert schemas == {
        "struct:Translation2d": "double x;double y",
        "struct:Rotation2d": "double value",
        "struct:Pose2d": "Translation2d translation;Rotation2d rotation",
        "struct:SwerveModulePosition": "double distance;Rotation2d angle",
        "struct:SwerveModuleVelocity": "double velocity;Rotation2d angle",
        "struct:ChassisVelocities": "double vx;double vy;double omega",
        "struct:SwerveDriveKinematics__4": "Translation2d modules[4]",
        "struct:MecanumDriveWheelPositions":
            "double front_left;double front_right;double rear_left;double rear_right",
        "struct:DifferentialDriveWheelPositions": "double left;double right",
    }
    assert all(len(got[f"/.schema/{k}"][2]) == 1 for k in schemas)
    assert all(v[0] == "structschema" for n, v in got.items() if n.startswith("/.schema/"))


def test_writer_round_trip_through_our_reader(tmp_path):
    path = tmp_path / "series.wpilog"
    t = np.array([20_000, 40_000, 60_000], dtype=np.int64)
    poses = np.array([[0.0, 0.0, 0.0], [1.0, 0.5, 0.25], [2.0, 1.0, 4.0]])
    mods = np.arange(3 * 4 * 2, dtype=np.float64).reshape(3, 4, 2)
    gyro = np.array([0.0, 0.5, 7.0])
    with datalog.Writer(path) as w:
        w.appendSeries("/P", "struct:Pose2d", t, poses, metadata='{"a":1}')
        w.appendSeries("/M", "struct:SwerveModulePosition[]", t, mods)
        w.appendSeries("/G", "struct:Rotation2d", t, gyro)
        w.appendSeries("/D", "double", t, gyro)
        w.appendSeries("/A", "double[]", t, poses)
        w.append("/K", MecanumDriveKinematics(Translation2d(1, 1), Translation2d(1, -1),
                                              Translation2d(-1, 1), Translation2d(-1, -1)),
                 1000)
    log = datalog.read(path)
    assert log.entries["/P"].metadata == '{"a":1}'
    for name, want in (("/P", poses), ("/M", mods), ("/G", gyro), ("/D", gyro), ("/A", poses)):
        ts, v = log.values(name)
        assert ts.tolist() == t.tolist()
        np.testing.assert_array_equal(v, want)       # stored as given (angles unwrapped)
    _, k = log.values("/K")
    assert k.tolist() == [[1.0, 1.0, 1.0, -1.0, -1.0, 1.0, -1.0, -1.0]]


def test_writer_refuses_bad_input(tmp_path):
    with datalog.Writer(tmp_path / "w.wpilog") as w:
        with pytest.raises(ValueError, match="0 means 'now'"):
            w.append("/x", 1.0, 0)
        with pytest.raises(TypeError, match="timestamp must be an int"):
            w.append("/x", 1.0, 1.5)
        w.append("/x", 1.0, 10)
        with pytest.raises(TypeError, match=r"'/x' holds double, got a struct:Pose2d"):
            w.append("/x", Pose2d(), 20)
        with pytest.raises(TypeError, match="empty sequence"):
            w.append("/y", [], 20)
        with pytest.raises(TypeError, match="must all be Pose2d"):
            w.append("/y", [Pose2d(), Rotation2d()], 20)
        with pytest.raises(TypeError, match="cannot serialize"):
            w.append("/y", object(), 20)
        with pytest.raises(ValueError, match=r"shape \(2, 3\), got \(2, 2\)"):
            w.appendSeries("/s", "struct:Pose2d", [1, 2], np.zeros((2, 2)))
        with pytest.raises(ValueError, match=r"shape \(2, M, 2\)"):
            w.appendSeries("/s", "struct:SwerveModulePosition[]", [1, 2], np.zeros((2, 2)))
        with pytest.raises(TypeError, match="float64 array"):
            w.appendSeries("/s", "double", [1, 2], np.array([1.0, 2.0], dtype=object))
        with pytest.raises(TypeError, match="integer array"):
            w.appendSeries("/s", "double", [1.0, 2.0], np.zeros(2))
        with pytest.raises(ValueError, match="0 means 'now'"):
            w.appendSeries("/s", "double", [0, 1], np.zeros(2))
        with pytest.raises(ValueError, match="appendSeries\\(\\) writes"):
            w.appendSeries("/s", "string", [1], np.zeros(1))
    with pytest.raises(ValueError, match="closed"):
        w.append("/x", 1.0, 30)
    with pytest.raises(OSError, match="cannot write"):
        datalog.Writer(tmp_path / "no" / "such" / "dir.wpilog")
    # The failed calls wrote nothing: the file holds exactly the one good record.
    log = datalog.read(tmp_path / "w.wpilog")
    assert [n for n in log.entries if not n.startswith("/.schema/")] == ["/x"]
    assert log.values("/x")[1].tolist() == [1.0]


def test_writer_does_not_hang_past_robotpys_buffer(tmp_path):
    # robotpy-wpiutil 2026.2.2's DataLogWriter blocks forever after ~1 MiB unflushed; a
    # subprocess with a timeout turns a regression into a failure instead of a hang.
    path = tmp_path / "big.wpilog"
    r = _python(f"""
        import numpy as np
        from drivekin import datalog
        n = 40000
        with datalog.Writer({str(path)!r}) as w:
            w.appendSeries("/m", "struct:SwerveModulePosition[]",
                           np.arange(1, n + 1) * 4000, np.ones((n, 4, 2)))
        print(datalog.read({str(path)!r}).entries["/m"].records)
    """)
    assert r.returncode == 0, r.stderr[-1000:]
    assert r.stdout.strip() == "40000"
    assert path.stat().st_size > 2 * 1024 * 1024


# ---------------------------------------------------------------------------------------
# Optional dependencies stay optional

def test_import_drivekin_imports_neither_wpiutil_nor_matplotlib():
    r = _python("""
        import sys
        import drivekin, drivekin.wpistruct
        import drivekin.datalog, drivekin.replay     # the modules themselves are lazy too
        print(sorted(m for m in ("wpiutil", "matplotlib", "wpimath") if m in sys.modules))
    """)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]"


def test_missing_wpiutil_is_an_import_error_naming_the_extra(tmp_path):
    # Reading needs no robotpy-wpiutil (and does not import it); writing does.
    path = tmp_path / "w.wpilog"
    r = _python(f"""
        import sys
        sys.modules["wpiutil"] = None        # as if robotpy-wpiutil were not installed
        from drivekin import datalog
        print(datalog.read(b"WPILOG\\x00\\x01\\x00\\x00\\x00\\x00").entries)
        try:
            datalog.Writer({str(path)!r})
        except ImportError as e:
            print("ImportError:", e)
    """)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines()[0] == "{}"
    assert 'ImportError: robotpy-wpiutil is needed to write' in r.stdout
    assert 'pip install "drivekin[log]"' in r.stdout


def test_read_imports_no_wpiutil(robotpy_file):
    r = _python(f"""
        import sys
        from drivekin import datalog
        log = datalog.read({str(robotpy_file)!r})
        log.values("/Pose"), log.records("/Msg"), log.entries
        print("wpiutil" in sys.modules)
    """)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "False"


def test_entry_restarted_with_another_type_is_refused(tmp_path):
    path = tmp_path / "restart.wpilog"
    with robotpy_log(path) as log:
        e = log.start("/x", "double", 1)
        log.double(e, 1.0, 1000)
        log.log.finish(e, 1500)
        e2 = log.start("/x", "string", 2000)
        log.log.appendString(e2, "now a string", 2500)
        e3 = log.start("/y", "double", 1)
        log.double(e3, 2.0, 1000)
        log.log.finish(e3, 1500)
        e4 = log.start("/y", "double", 2000)
        log.double(e4, 3.0, 3000)
    log = datalog.read(path)
    assert log.entries["/x"].type == "double|string"
    with pytest.raises(DataLogError, match=r"'/x' was started with several types "
                                           r"\(double, string\)"):
        log.values("/x")
    # Finished and restarted with the same type: one entry, both records.
    assert log.values("/y")[1].tolist() == [2.0, 3.0]
