"""drivekin.replay and ``python -m drivekin replay`` on logs written by robotpy-wpiutil
(tests/_support/wpilog_logs.py: a known simulated path, the robot's own odometry computed by
robotpy-wpimath) and by the demo's ``--log``; bad files and options."""
from __future__ import annotations

import json
import os
import struct
import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("wpiutil")
pytest.importorskip("matplotlib")

import drivekin                                                # noqa: E402
from drivekin import Pose2d, Rotation2d, SwerveDriveKinematics, Translation2d  # noqa: E402
from drivekin import SwerveDriveOdometry, datalog, replay     # noqa: E402
from drivekin.app.cli import main                              # noqa: E402
from drivekin.app.demo.drivetrains import DeadWheelDrive       # noqa: E402
from tests._support import wpilog_logs as W                    # noqa: E402

_PACKAGE_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(drivekin.__file__)))
MODULES = [f"{x},{y}" for x, y in W.MODULES]


def run_cli(*args: str, timeout: float = 300) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (_PACKAGE_ROOT, env.get("PYTHONPATH", ""))
                                        if p)
    return subprocess.run([sys.executable, "-m", "drivekin", *args], env=env,
                          capture_output=True, text=True, encoding="utf-8", timeout=timeout)


@pytest.fixture(scope="module")
def match(tmp_path_factory):
    """The realistic log: 30 s, 250 Hz module positions, 50 Hz gyro and pose, gaps and
    out-of-order records (see wpilog_logs.write_match_log)."""
    folder = tmp_path_factory.mktemp("match")
    sim = W.simulate_match(30.0)
    path = folder / "match.wpilog"
    info = W.write_match_log(path, sim)
    return path, sim, info


def _module_args():
    out = []
    for m in MODULES:
        out += ["--module", m]
    return out


def _is_png(path) -> tuple[int, int]:
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG signature"
    assert data[12:16] == b"IHDR" and data[-8:-4] == b"IEND"
    return struct.unpack(">II", data[16:24])


# ---------------------------------------------------------------------------------------
# The realistic log

def test_replay_reproduces_the_robots_own_odometry(match):
    path, sim, info = match
    r = replay.replayLog(path, replay.ReplayConfig(modules=list(W.MODULES)))
    assert r.drivetrain == "swerve" and r.odometry == "SwerveDriveOdometry"
    # Found by type among three Pose2d entries: the one named "Odometry".
    assert r.entries == {"positions": "/Drive/ModulePositions",
                         "gyro": "/Drive/Gyro/YawPosition",
                         "pose": "/RealOutputs/Odometry/Robot"}
    assert r.skipped == info["skipped"] == 10
    assert len(r.t) == len(info["module_t"]) - 10
    assert r.rates["positions"] == pytest.approx(250.0) and r.rates["gyro"] == pytest.approx(50.0)
    assert r.maxWheelGap == pytest.approx(0.504) and r.maxGyroAge == pytest.approx(0.316)
    # Same inputs, same algorithm (robotpy-wpimath's SwerveDrive4Odometry logged it):
    # only rounding differs.
    s = r.vsLogged
    assert s.count + s.inGaps == len(info["pose_t"])
    assert s.inGaps == 25                 # poses logged during the 0.5 s module dropout
    assert s.maxPosition < 1e-9 and s.maxHeading < 1e-9


def test_corrected_wheel_radius_recovers_the_truth(match):
    path, sim, info = match
    truth_t, truth = info["pose_t"], info["truth_at_pose"]

    def against_truth(**kw):
        r = replay.replayLog(path, replay.ReplayConfig(modules=list(W.MODULES),
                                                       truth="/Sim/TruePose", **kw))
        # The logged /Sim/TruePose is the simulation's truth, bit for bit.
        assert np.array_equal(r.truth[1], truth) and np.array_equal(r.truth[0], truth_t)
        return r

    raw = against_truth()
    fixed = against_truth(wheelScale=1 / W.ENCODER_SCALE)
    interp = against_truth(wheelScale=1 / W.ENCODER_SCALE, gyroAlign="interpolate")
    # The encoders under-read by 3 %: over ~46 m of path the robot's odometry (and a
    # replay with its geometry) ends tens of cm off.
    assert raw.vsTruth.finalPosition > 0.3
    # With the wheel radius corrected only the sampling errors remain: the gyro held up
    # to 20 ms (316 ms in its gap) and the 0.5 s module dropout.
    assert fixed.vsTruth.maxPosition < 0.04
    assert interp.vsTruth.maxPosition < 0.005
    assert interp.vsTruth.maxPosition < fixed.vsTruth.maxPosition / 4
    # The gyro is trusted for heading: every replay's heading is the true one.
    for r in (raw, fixed, interp):
        assert r.vsTruth.maxHeading < 1e-9


def test_cli_prints_drift_and_writes_log_and_plot(match, tmp_path, capsys):
    path, sim, info = match
    code = main(["replay", str(path), *_module_args(), "--out-dir", str(tmp_path), "--plot"])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert "[1/1]" in err and "done in" in err                      # progress on stderr
    assert "Traceback" not in err
    lines = out.splitlines()
    assert lines[0] == f"{path}: swerve (SwerveDriveOdometry)"
    vs = next(line for line in lines if line.startswith("  vs logged"))
    assert "(1459 poses; 25 inside wheel-sample gaps not compared)" in vs
    assert "10 wheel samples before the first gyro sample skipped" in out
    replayed = tmp_path / "match-replay.wpilog"
    png = tmp_path / "match-replay.png"
    assert f"wrote      {replayed}, {png}" in out
    w, h = _is_png(png)
    assert w >= 600 and h >= 300
    # Every original entry is copied through, record for record; the replay is added.
    orig, new = datalog.read(path), datalog.read(replayed)
    for name, e in orig.entries.items():
        assert new.entries[name].type == e.type and new.entries[name].records == e.records
        t0, r0 = orig.records(name)
        t1, r1 = new.records(name)
        assert t0.tolist() == t1.tolist() and [bytes(b) for b in r0] == [bytes(b) for b in r1]
    t, poses = new.values(replay.POSE_ENTRY)
    assert new.entries[replay.POSE_ENTRY].type == "struct:Pose2d"
    assert len(t) == len(info["module_t"]) - 10 and poses.shape == (len(t), 3)
    te, err_m = new.values(replay.ERROR_ENTRY)
    assert len(te) == 1459 and err_m.max() < 1e-9
    # Replaying the replay's own output ignores /drivekin/ entries and gives the same.
    again = replay.replayLog(replayed, replay.ReplayConfig(modules=list(W.MODULES)))
    assert np.array_equal(again.poses, poses)


def test_json_output_and_several_logs_with_one_bad(match, tmp_path, capsys):
    path, sim, info = match
    bad = tmp_path / "bad.wpilog"
    bad.write_bytes(b"not a log")
    code = main(["replay", str(path), str(bad), str(path), *_module_args(), "--no-write",
                 "--json", "--gyro-align", "interpolate"])
    out, err = capsys.readouterr()
    assert code == 1
    results = json.loads(out)
    assert len(results) == 2 and results[0] == results[1]
    assert results[0]["vs_logged"]["skipped_in_gaps"] == 25
    assert results[0]["samples"] == len(info["module_t"]) - 10
    assert results[0]["outputs"] == []
    assert "[1/3]" in err and "[2/3]" in err and "[3/3]" in err
    assert "replayed 2 of 3 logs" in err
    errors = [line for line in err.splitlines() if "error:" in line]
    assert errors == [f"python -m drivekin replay: error: {bad}: not a WPILib DataLog "
                      f"(.wpilog) file: it does not start with the 'WPILOG' header"]
    assert not (tmp_path / "match-replay.wpilog").exists()


def test_replay_poses_leaves_the_odometry_at_the_last_sample():
    kin = SwerveDriveKinematics(Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
                                Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))
    n = 50
    gyro = np.linspace(0.0, 1.0, n)
    pos = np.zeros((n, 4, 2))
    pos[:, :, 0] = np.linspace(0.0, 2.0, n)[:, None]
    pos[:, :, 1] = 0.3
    odo = SwerveDriveOdometry(kin, Rotation2d(0.0), pos[0], Pose2d())
    poses = replay.replayPoses(odo, gyro, pos)
    ref = SwerveDriveOdometry(kin, Rotation2d(0.0), pos[0], Pose2d())
    for i in range(n):
        p = ref.update(Rotation2d(float(gyro[i])), pos[i])
        assert poses[i].tolist() == [p.x, p.y, p.getRotation().getRadians()]
    last = odo.getPose()
    assert poses[-1].tolist() == [last.x, last.y, last.getRotation().getRadians()]
    with pytest.raises(TypeError, match="takes a drivekin"):
        replay.replayPoses(object(), gyro, pos)


# ---------------------------------------------------------------------------------------
# A robot that logs its pose in 3-D (struct:Pose3d): compared in the plane

@pytest.fixture(scope="module")
def match3d(tmp_path_factory):
    """6 s of the realistic log, the robot's pose logged as a Pose3d (rocking on uneven
    ground), alone (``only``) or beside the same pose as a Pose2d (``both``)."""
    folder = tmp_path_factory.mktemp("match3d")
    sim = W.simulate_match(6.0)
    out = {}
    for name, poses in (("only", ("Pose3d",)), ("both", ("Pose2d", "Pose3d"))):
        path = folder / f"{name}.wpilog"
        out[name] = path, W.write_match_log(path, sim, module_gaps=((600, 625),),
                                            gyro_gaps=((100, 103),), poses=poses)
    return out


def test_a_logged_pose3d_is_the_robots_pose_in_the_plane(match3d):
    path, info = match3d["only"]
    r = replay.replayLog(path, replay.ReplayConfig(modules=list(W.MODULES)))
    assert r.entries["pose"] == "/RealOutputs/Odometry/Robot3d"
    assert r.why["pose"].startswith("AdvantageKit's odometry output; not ")
    # The Pose3d's toPose2d is the robot's planar odometry (robotpy-wpimath's) up to the
    # rounding of its quaternion: height, roll and pitch play no part.
    s = r.vsLogged
    assert s.count + s.inGaps == len(info["pose_t"]) and s.inGaps == 5
    assert s.maxPosition < 1e-9 and s.maxHeading < 1e-9
    # The start pose is the logged one, in the plane.
    x, y, th = info["logged"][0]
    assert r.poses[0, :2].tolist() == pytest.approx([x, y], abs=1e-3)


def test_a_pose2d_is_preferred_to_the_same_pose_in_3d(match3d):
    path, info = match3d["both"]
    r = replay.replayLog(path, replay.ReplayConfig(modules=list(W.MODULES)))
    assert r.entries["pose"] == "/RealOutputs/Odometry/Robot"
    assert "/RealOutputs/Odometry/Robot3d" in r.why["pose"]          # "over ..."
    named = replay.replayLog(path, replay.ReplayConfig(
        modules=list(W.MODULES), pose="/RealOutputs/Odometry/Robot3d",
        truth="/RealOutputs/Odometry/Robot"))
    assert named.entries["pose"] == "/RealOutputs/Odometry/Robot3d"
    assert named.vsLogged.maxPosition < 1e-9 and named.vsLogged.maxHeading < 1e-9
    # The same poses either way (the start pose is the logged one, whose Pose3d form
    # differs from the Pose2d in the last bits of the quaternion's rounding).
    assert named.vsTruth.maxPosition < 1e-9 and named.vsTruth.maxHeading < 1e-9
    assert np.abs(named.poses - r.poses).max() < 1e-12


# ---------------------------------------------------------------------------------------
# Bad files and missing or wrong entries: one clear line, exit 1, never a traceback

def _robotpy_log_with(path, entries):
    """A log with the given entries (name, type, [(ts, bytes)]) and schemas."""
    import wpimath.geometry as wg
    import wpimath.kinematics as wk
    with W.robotpy_log(path) as log:
        for cls in (wg.Pose2d, wg.Rotation2d, wk.SwerveModulePosition):
            log.log.addStructSchema(cls, 1)
        for name, type_string, records in entries:
            e = log.start(name, type_string, 1)
            for ts, data in records:
                log.raw(e, data, ts)


def _struct_bytes(*values):
    return struct.pack(f"<{len(values)}d", *values)


GOOD_MODULES = ("/Drive/ModulePositions", "struct:SwerveModulePosition[]",
                [(20_000 * k, _struct_bytes(*(0.1 * k, 0.0) * 4)) for k in range(1, 6)])
GOOD_GYRO = ("/Gyro", "struct:Rotation2d", [(20_000 * k, _struct_bytes(0.0)) for k in range(1, 6)])


@pytest.fixture(scope="module")
def bad_logs(tmp_path_factory, match):
    folder = tmp_path_factory.mktemp("bad")
    logs = {}
    data = match[0].read_bytes()
    (folder / "truncated.wpilog").write_bytes(data[:-7])       # inside the last record
    logs["truncated"] = (folder / "truncated.wpilog", "truncated at byte")
    (folder / "text.wpilog").write_text("timestamp,value\n1,2\n")
    logs["not a log"] = (folder / "text.wpilog", "not a WPILib DataLog")
    (folder / "empty.wpilog").write_bytes(b"")
    logs["empty"] = (folder / "empty.wpilog", "not a WPILib DataLog")
    logs["missing file"] = (folder / "nope.wpilog", "No such file or directory")
    p = folder / "nomodules.wpilog"
    _robotpy_log_with(p, [GOOD_GYRO])
    logs["no positions"] = (p, "no wheel or module positions found")
    p = folder / "nogyro.wpilog"
    _robotpy_log_with(p, [GOOD_MODULES])
    logs["no gyro"] = (p, "no continuous gyro (struct:Rotation2d, or a double named gyro, imu, yaw, "
                          "heading or robot angle); name one with --gyro")
    p = folder / "twogyros.wpilog"
    _robotpy_log_with(p, [GOOD_MODULES, GOOD_GYRO, ("/Drive/GyroBackup", *GOOD_GYRO[1:])])
    logs["two gyros"] = (p, "several gyro entries")
    p = folder / "nogeometry.wpilog"
    _robotpy_log_with(p, [GOOD_MODULES, GOOD_GYRO])
    logs["no geometry"] = (p, "no module offsets in the log: give --trackwidth W --wheelbase L for a rectangle, or --module X,Y for each of the 4 modules")
    p = folder / "ragged.wpilog"
    _robotpy_log_with(p, [GOOD_GYRO, (GOOD_MODULES[0], GOOD_MODULES[1],
                                      GOOD_MODULES[2] + [(9000, _struct_bytes(1.0, 0.0))])])
    logs["ragged"] = (p, "changes size between records: array lengths 1 (1 records), "
                         "4 (5 records)")
    p = folder / "nan.wpilog"
    _robotpy_log_with(p, [GOOD_GYRO, (GOOD_MODULES[0], GOOD_MODULES[1],
                                      [(1000, _struct_bytes(*(float("nan"), 0.0) * 4))])])
    logs["nan"] = (p, "holds a NaN or infinite value")
    return logs


@pytest.mark.parametrize("case", ["truncated", "not a log", "empty", "missing file",
                                  "no positions", "no gyro", "two gyros", "no geometry",
                                  "ragged", "nan"])
def test_bad_logs_get_one_clear_line(bad_logs, case):
    path, message = bad_logs[case]
    r = run_cli("replay", str(path), "--no-write")
    assert r.returncode == 1, (r.returncode, r.stderr[-800:])
    assert "Traceback" not in r.stderr
    errors = [line for line in r.stderr.splitlines() if "error:" in line]
    assert len(errors) == 1, r.stderr
    assert errors[0].startswith(f"python -m drivekin replay: error: {path}: "), errors[0]
    assert message in errors[0], errors[0]
    assert r.stdout == ""


def test_wrong_entry_types_named_on_the_command_line(match, capsys):
    path = str(match[0])
    cases = [
        (["--gyro", "messages"], "--gyro 'messages' has type string; expected "
                                 "struct:Rotation2d, Rotation2d[]"),
        (["--positions", "/RealOutputs/Odometry/Robot"], "has type struct:Pose2d; expected"),
        (["--pose", "/Drive/Gyro/YawPosition"], "--pose '/Drive/Gyro/YawPosition' has type "
                                                "struct:Rotation2d, expected struct:Pose2d"),
        (["--gyro", "/SystemStats/BatteryVoltage"], "is a plain double: give its units with "
                                                    "--gyro-units"),
        (["--gyro", "/Nope"], "--gyro '/Nope': no such entry"),
        (["--drivetrain", "mecanum"], "no wheel or module positions found "
                                      "(layouts tried: WPILib struct, "),
        (["--module", "1,1"], "1 module offsets given, the log's positions have 4 modules"),
    ]
    for extra, message in cases:
        code = main(["replay", path, "--no-write", *(_module_args() if "--module" not in extra
                                                      else []), *extra])
        out, err = capsys.readouterr()
        assert code == 1, (extra, err)
        errors = [line for line in err.splitlines() if "error:" in line]
        assert len(errors) == 1 and message in errors[0], (extra, err)


def test_truncated_log_replays_with_allow_truncated(bad_logs, capsys, tmp_path):
    path, _ = bad_logs["truncated"]
    code = main(["replay", str(path), *_module_args(), "--allow-truncated",
                 "--out-dir", str(tmp_path)])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert "warning    truncated at byte" in out
    assert (tmp_path / "truncated-replay.wpilog").exists()


BAD_OPTIONS = [
    (["--module", "1"], "argument --module: expected X,Y in m, got '1'"),
    (["--module", "1,nan"], "argument --module: expected X,Y in m"),
    (["--dead-wheel", "a,b,c"], "argument --dead-wheel: expected X,Y,DEG"),
    (["--wheel-scale", "0"], "argument --wheel-scale: expected a number greater than 0"),
    (["--wheel-scale", "inf"], "argument --wheel-scale: expected a number greater than 0"),
    (["--trackwidth", "-1"], "argument --trackwidth: expected a number greater than 0"),
    (["--gyro-align", "nearest"], "argument --gyro-align: invalid choice"),
    (["--out-dir", "/no/such/folder"], "argument --out-dir: '/no/such/folder' is not a folder"),
    (["--heading", "wheels"], "--heading wheels needs --trackwidth"),
]


@pytest.mark.parametrize("extra, message", BAD_OPTIONS, ids=[" ".join(e) for e, _ in BAD_OPTIONS])
def test_bad_replay_options_are_one_argparse_line(match, extra, message):
    r = run_cli("replay", str(match[0]), *extra)
    assert r.returncode == 2, r.stderr
    errors = [line for line in r.stderr.splitlines() if "error:" in line]
    assert len(errors) == 1, r.stderr
    assert errors[0].startswith("python -m drivekin replay: error: "), errors[0]
    assert message in errors[0], errors[0]
    assert "Traceback" not in r.stderr and r.stdout == ""


def test_replay_without_logs_is_a_usage_error():
    r = run_cli("replay")
    assert r.returncode == 2
    assert "the following arguments are required: LOG.wpilog" in r.stderr


# ---------------------------------------------------------------------------------------
# The demo's --log / --plot, replayed

def test_demo_log_and_plot_replay_to_the_logged_odometry(tmp_path):
    log, png = tmp_path / "run.wpilog", tmp_path / "run.png"
    r = run_cli("--seconds", "6", "--log", str(log), "--plot", str(png), "--json")
    assert r.returncode == 0, r.stderr
    result = json.loads(r.stdout)
    assert result["recorded_run_matches"] is True
    assert result["log"] == {"path": str(log), "entries": 8}
    # Recording happens after the measured passes: they still allocate nothing.
    assert result["allocations"]["allocator_calls"] == 0
    _is_png(png)
    contents = datalog.read(log)
    types = {n: e.type for n, e in contents.entries.items() if not n.startswith("/.schema/")}
    assert types == {
        "/Drive/Kinematics": "struct:SwerveDriveKinematics__4",
        "/Odometry/Robot": "struct:Pose2d", "/Sim/TruePose": "struct:Pose2d",
        "/Drive/Gyro": "struct:Rotation2d",
        "/Drive/ChassisVelocities": "struct:ChassisVelocities",
        "/Drive/ModulePositions": "struct:SwerveModulePosition[]",
        "/Drive/ModuleStates/Commanded": "struct:SwerveModuleVelocity[]",
        "/Drive/ModuleStates/Measured": "struct:SwerveModuleVelocity[]",
    }
    t, poses = contents.values("/Odometry/Robot")
    assert t.tolist() == list(range(20_000, 300 * 20_000 + 1, 20_000))
    final = result["final_pose"]
    assert poses[-1, :2].tolist() == [final["x_m"], final["y_m"]]
    # Geometry from the log's kinematics entry; replay == the demo's own odometry.
    rep = replay.replayLog(log, replay.ReplayConfig(truth="/Sim/TruePose"))
    assert "from /Drive/Kinematics" in rep.geometry
    assert rep.vsLogged.count == 300 and rep.vsLogged.maxPosition < 1e-9
    assert rep.vsTruth.maxPosition < 1e-3


@pytest.mark.parametrize("drivetrain, extra", [
    ("mecanum", []),
    ("differential", []),
    ("differential", ["--heading", "wheels", "--trackwidth", "0.6"]),
    ("deadwheel", ["--positions", "/Drive/DeadWheelPositions"]
     + sum((["--dead-wheel", f"{x!r},{y!r},{d!r}"] for x, y, d in (
         (0.0, DeadWheelDrive.PAR_Y, 0.0), (0.0, -DeadWheelDrive.PAR_Y, 0.0),
         (DeadWheelDrive.PERP_X, 0.0, 90.0))), [])),
])
def test_demo_logs_of_every_drivetrain_replay(tmp_path, drivetrain, extra):
    log = tmp_path / f"{drivetrain}.wpilog"
    r = run_cli("--drivetrain", drivetrain, "--seconds", "4", "--log", str(log), "--quiet")
    assert r.returncode == 0, r.stderr
    assert f"wrote {log}" in r.stdout
    r = run_cli("replay", str(log), "--json", "--no-write", *extra)
    assert r.returncode == 0, r.stderr
    (res,) = json.loads(r.stdout)
    assert res["drivetrain"] == ("deadwheel" if "--dead-wheel" in extra else
                                 drivetrain if drivetrain != "deadwheel" else "mecanum")
    assert res["samples"] == 200
    # Same inputs as the demo's own odometry: rounding only.
    assert res["vs_logged"]["max_position_m"] < 1e-9, res["vs_logged"]


def test_demo_log_and_plot_options_are_validated():
    for option in ("--log", "--plot"):
        r = run_cli("--seconds", "1", option, "/no/such/folder/x")
        assert r.returncode == 2, r.stderr
        errors = [line for line in r.stderr.splitlines() if "error:" in line]
        assert errors == [f"python -m drivekin: error: argument {option}: the folder of "
                          f"'/no/such/folder/x' does not exist"], r.stderr


@pytest.mark.parametrize("argv, missing, message", [
    (["--seconds", "1", "--log", "x.wpilog"], "wpiutil",
     'python -m drivekin: error: --log needs robotpy-wpiutil: pip install "drivekin[log]"'),
    (["--seconds", "1", "--plot", "x.png"], "matplotlib",
     'python -m drivekin: error: --plot needs matplotlib: pip install "drivekin[plot]"'),
    (["replay", "x.wpilog"], "wpiutil",
     "python -m drivekin replay: error: writing LOG-replay.wpilog (--no-write skips it) "
     'needs robotpy-wpiutil: pip install "drivekin[log]"'),
    (["replay", "x.wpilog", "--plot"], "matplotlib",
     'python -m drivekin replay: error: --plot needs matplotlib: pip install "drivekin[plot]"'),
])
def test_missing_extras_are_usage_errors_before_any_work(monkeypatch, capsys, argv, missing,
                                                         message):
    import importlib.util
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == missing else real(name, *a))
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 2
    errors = [line for line in capsys.readouterr().err.splitlines() if "error:" in line]
    assert errors == [message]


def test_replay_without_robotpy_wpiutil_reads_and_reports(monkeypatch, capsys, match):
    # Reading is drivekin's own: only writing LOG-replay.wpilog needs robotpy-wpiutil.
    import importlib.util
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "wpiutil" else real(name, *a))
    monkeypatch.setitem(sys.modules, "wpiutil", None)      # importing it would fail
    assert main(["replay", str(match[0]), "--no-write", *_module_args()]) == 0
    assert "vs logged" in capsys.readouterr().out


def test_replay_poses_matches_update_calls_bit_for_bit_on_a_real_log(match):
    # replayPoses runs drivekin.batch.replay; on a real log's samples it must give the bits
    # of one update call per sample.
    log = datalog.read(match[0])
    _, gyro = log.values("/Drive/Gyro/YawPosition")
    _, pos = log.values("/Drive/ModulePositions")
    n = min(len(gyro), len(pos))
    gyro, pos = np.unwrap(gyro[:n]), np.ascontiguousarray(pos[:n])
    kin = SwerveDriveKinematics(*[Translation2d(x, y) for x, y in W.MODULES])

    def fresh():
        return SwerveDriveOdometry(kin, Rotation2d(float(gyro[0])), pos[0], Pose2d())

    a, b = fresh(), fresh()
    fast = replay.replayPoses(a, gyro, pos)
    loop = np.array([[p.x, p.y, p.getRotation().getRadians()]
                     for p in (b.update(Rotation2d(float(g)), row) for g, row in zip(gyro, pos))])
    assert fast.tobytes() == loop.tobytes()
    assert a.getPose() == b.getPose()
