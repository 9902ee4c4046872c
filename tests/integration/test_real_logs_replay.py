"""``python -m drivekin replay`` on logs written by real, independent writers
(tests/_support/real_logs.py: robotpy-pykit's Logger, ntcore's DataLog mirroring,
robotpy-wpiutil's DataLogWriter), checked against robotpy-wpimath's own odometry at the
robot's rate. Each case runs the command line docs/logs-and-replay.md shows for that
layout (the last tests check the guide shows these same commands, and the layouts
table as the code has it)."""
from __future__ import annotations

import dataclasses

import json
import pathlib
import shlex

import numpy as np
import pytest

pytest.importorskip("ntcore")
pytest.importorskip("wpiutil")

from drivekin import datalog, replay                                 # noqa: E402
from drivekin.app.cli import main                                    # noqa: E402
from tests._support import real_logs                                 # noqa: E402

# The options a user gives for what each log cannot say (the guide's commands).
COMMANDS = {
    "pykit_swerve": "--wheel-radius 0.0508 --trackwidth 0.5842 --wheelbase 0.5842",
    "ntcore_differential": "--gyro-units deg",
    "writer_mecanum": "--trackwidth 0.6 --wheelbase 0.5",
    "writer_swerve_per_module_doubles": ("--drive-units rot --wheel-radius 0.05 "
                                         "--turn-units deg --gyro-units deg "
                                         "--trackwidth 0.5 --wheelbase 0.6"),
    "ctre_drivestate": "--trackwidth 0.5842 --wheelbase 0.5842",
}


@pytest.fixture(scope="module")
def logs(tmp_path_factory):
    if "pykit_swerve" in real_logs.ALL:
        pytest.importorskip("pykit")
    folder = tmp_path_factory.mktemp("real")
    return {name: make(folder) for name, make in real_logs.ALL.items()}


def _run(path, options, capsys, *extra):
    code = main(["replay", str(path), "--no-write", "--json", *shlex.split(options), *extra])
    out, err = capsys.readouterr()
    assert code == 0, err
    return json.loads(out)[0]


def _replayed(rl, options):
    """The replay the command line runs, as a ReplayResult (the same configuration)."""
    from drivekin.app.replay_cli import build_parser
    args = build_parser().parse_args([str(rl.path), *shlex.split(options)])
    cfg = replay.ReplayConfig(
        driveUnits=args.drive_units, turnUnits=args.turn_units, gyroUnits=args.gyro_units,
        wheelRadius=args.wheel_radius, trackwidth=args.trackwidth, wheelbase=args.wheelbase,
        odometryRate=args.odometry_rate)
    return replay.replayLog(rl.path, cfg)


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_replay_reproduces_robotpy_wpimath_odometry(logs, capsys, name):
    rl = logs[name]
    d = _run(rl.path, COMMANDS[name], capsys)
    assert d["drivetrain"] == rl.drivetrain
    r = _replayed(rl, COMMANDS[name])
    if name == "ctre_drivestate":
        # NetworkTables stamps each record 800 µs after CTRE's own sample time; the
        # samples are the same, one for one.
        assert len(r.t) == len(rl.t_us)
        poses = r.poses
    else:
        # Writers that log only changes (robotpy-pykit, NetworkTables) leave no sample
        # while the robot rests: the replayed pose then is the latest one, as on the robot.
        # The replay starts at the wheel sample the robot's first logged pose follows.
        assert r.t[0] in rl.t_us and r.t[0] - rl.t_us[0] < 50_000
        keep = rl.t_us >= r.t[0]
        k = np.searchsorted(r.t, rl.t_us[keep], side="right") - 1
        poses = r.poses[k]
        rl = dataclasses.replace(rl, truth=rl.truth[keep])
    err = np.hypot(*(poses[:, :2] - rl.truth[:, :2]).T)
    assert err.max() < 1e-9, err.max()
    head = np.abs(np.angle(np.exp(1j * (poses[:, 2] - rl.truth[:, 2]))))
    assert head.max() < 1e-9


def test_pykit_high_rate_samples_are_replayed_at_their_rate(logs, capsys):
    rl = logs["pykit_swerve"]
    d = _run(rl.path, COMMANDS["pykit_swerve"], capsys)
    assert round(d["rates_hz"]["positions"]) == 250
    assert any("250 Hz samples, not the 50 Hz cycle values" in n for n in d["notes"])
    assert d["entries"]["pose"] == "/RealOutputs/Odometry/Robot"
    assert "not /RealOutputs/Odometry/TrajectorySetpoint (its name says 'setpoint')" in \
        d["why"]["pose"]
    # The logged pose was produced at 250 Hz: replayed so, it agrees to rounding.
    assert d["vs_logged"]["max_position_m"] < 1e-9
    assert d["warnings"] == []


def test_cycle_rate_replay_of_a_250_hz_robot_is_flagged(logs, capsys):
    # Replaying only the 50 Hz values reports drift that is not there (the issue's
    # 2.6 cm / 5.9 cm); the run says it ignored the high-rate samples.
    rl = logs["pykit_swerve"]
    d = _run(rl.path, COMMANDS["pykit_swerve"], capsys, "--odometry-rate", "cycle")
    assert round(d["rates_hz"]["positions"]) == 50
    assert any("holds high-rate odometry samples" in n for n in d["notes"])
    assert d["vs_logged"]["max_position_m"] > 1e-3
    assert abs(d["vs_logged"]["max_position_m"] - rl.notes["max_error_50hz_m"]) < 2e-3


def test_names_match_whatever_the_case_underscores_or_nt_prefix(logs, capsys):
    rl = logs["ntcore_differential"]
    d = _run(rl.path, COMMANDS["ntcore_differential"], capsys,
             "--pose", "/smartdashboard/FIELD/robot", "--gyro", "/Drive/gyro_angle")
    assert d["entries"]["pose"] == "NT:/SmartDashboard/Field/Robot"
    assert d["entries"]["gyro"] == "NT:/Drive/GyroAngle"


def test_a_misspelt_name_gets_a_did_you_mean(logs, capsys):
    rl = logs["ntcore_differential"]
    code = main(["replay", str(rl.path), "--no-write", "--gyro-units", "deg",
                 "--pose", "/SmartDashboard/Feild/Robot"])
    err = capsys.readouterr().err
    assert code == 1
    assert "did you mean 'NT:/SmartDashboard/Field/Robot'" in err


def test_a_degrees_gyro_read_as_radians_is_refused(logs, capsys):
    rl = logs["ntcore_differential"]
    code = main(["replay", str(rl.path), "--no-write", "--gyro-units", "rad"])
    err = capsys.readouterr().err
    assert code == 1
    assert "probably in degrees (--gyro-units deg)" in err


def test_wheel_radians_read_as_metres_are_refused(logs, capsys):
    # AdvantageKit's DrivePositionRad taken for metres: 1 / 0.0508 times too far.
    rl = logs["pykit_swerve"]
    code = main(["replay", str(rl.path), "--no-write", "--drive-units", "m",
                 "--trackwidth", "0.5842", "--wheelbase", "0.5842"])
    err = capsys.readouterr().err
    assert code == 1
    assert "faster than any robot: check the units" in err


def test_list_all_shows_every_entry_and_its_use(logs, capsys):
    rl = logs["pykit_swerve"]
    assert main(["replay", str(rl.path), "--list", "--all", "--wheel-radius", "0.0508"]) == 0
    out = capsys.readouterr().out
    log = datalog.read(rl.path)
    lines = out.splitlines()
    for name in log.entries:
        if not name.startswith(("/.schema/", "NT:/.schema/")):
            assert sum(x.startswith(name + " ") for x in lines) == 1, name
    line = next(x for x in lines if x.startswith("/RealOutputs/Odometry/Robot "))
    assert "pose candidate 1 (used)" in line
    line = next(x for x in lines if x.startswith("/Drive/Module0/odometryTimestamps "))
    # the records' rate: each array record holds five 250 Hz samples
    assert "position candidate 1 (used)" in line and " 50 Hz " in line


def test_an_existing_output_is_not_overwritten_without_force(logs, capsys, tmp_path):
    rl = logs["writer_mecanum"]
    args = ["replay", str(rl.path), "--out-dir", str(tmp_path),
            *shlex.split(COMMANDS["writer_mecanum"])]
    assert main(args) == 0
    out = tmp_path / (rl.path.stem + "-replay.wpilog")
    before = out.stat().st_mtime_ns
    capsys.readouterr()
    assert main(args) == 1
    assert "already exists: pass --force" in capsys.readouterr().err
    assert out.stat().st_mtime_ns == before
    assert main(args + ["--force"]) == 0


GUIDE = pathlib.Path(__file__).resolve().parents[2] / "docs" / "logs-and-replay.md"


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_the_guide_shows_each_layouts_command(name):
    assert f"`python -m drivekin replay LOG.wpilog {COMMANDS[name]}`" in GUIDE.read_text()


def test_the_guide_shows_the_layouts_table():
    from drivekin._core.loglayouts import layouts_table
    assert layouts_table() in GUIDE.read_text()


def test_a_pose_produced_at_the_cycle_rate_is_flagged(logs, capsys, tmp_path):
    # The same 250 Hz inputs, but the logged Odometry/Robot is what a robot integrating
    # only its 50 Hz cycle values computed: the replay at 250 Hz warns that the logged
    # pose follows the cycle values.
    rl = logs["pykit_swerve"]
    path = tmp_path / "pose_at_50hz.wpilog"
    with datalog.Writer(path) as w:
        w.copyFrom(datalog.read(rl.path), exclude=["/RealOutputs/Odometry/Robot"])
        w.appendSeries("/RealOutputs/Odometry/Robot", "struct:Pose2d",
                       rl.notes["t_us_50hz"], rl.notes["truth_50hz"])
    d = _run(path, COMMANDS["pykit_swerve"], capsys)
    assert round(d["rates_hz"]["positions"]) == 250
    assert any("the logged pose follows the 50 Hz cycle values" in x for x in d["warnings"])


@pytest.mark.parametrize("names, chosen", [
    (["/RealOutputs/Odometry/TrajectorySetpoint", "/RealOutputs/Odometry/Robot"],
     "/RealOutputs/Odometry/Robot"),
    (["/PathPlanner/targetPose", "/PathPlanner/currentPose"], "/PathPlanner/currentPose"),
    (["NT:/Vision/RobotPose", "NT:/Drive/EstimatedPose"], "NT:/Drive/EstimatedPose"),
])
def test_the_robots_own_pose_is_chosen_over_targets(tmp_path, names, chosen):
    from drivekin import Pose2d, Rotation2d, SwerveModulePosition
    path = tmp_path / "poses.wpilog"
    with datalog.Writer(path) as w:
        for k in range(1, 4):
            t = 20_000 * k
            w.append("/Drive/Modules", [SwerveModulePosition(0.01 * k, Rotation2d(0.0))] * 4, t)
            w.append("/Drive/Gyro", Rotation2d(0.0), t)
            for i, n in enumerate(names):
                w.append(n, Pose2d(float(i), 0.0, Rotation2d(0.0)), t)
    r = replay.replayLog(path, replay.ReplayConfig(trackwidth=0.5, wheelbase=0.5))
    assert r.entries["pose"] == chosen
    other = next(n for n in names if n != chosen)
    assert other in r.why["pose"]


def test_positions_can_name_the_folder_of_per_module_entries(logs, capsys):
    rl = logs["pykit_swerve"]
    d = _run(rl.path, COMMANDS["pykit_swerve"], capsys, "--positions", "/drive")
    assert d["entries"]["positions"] == "/Drive/... (12 entries)"       # the 250 Hz arrays
    assert d["why"]["positions"] == "named with --positions"
    d = _run(rl.path, COMMANDS["pykit_swerve"], capsys, "--positions", "/Drive",
             "--odometry-rate", "cycle")
    assert d["entries"]["positions"] == "/Drive/... (8 entries)"        # the cycle values
    assert round(d["rates_hz"]["positions"]) == 50


def test_a_log_that_begins_in_motion_agrees_as_one_that_begins_at_rest(tmp_path, capsys):
    # The robot program (and its pykit log) starts 5 s into the motion, at 1.5 m/s on an
    # arc: its first logged pose already follows five odometry samples. The replay starts
    # from that pose at the last of them, not at the first sample (4.75 cm and 0.29° off).
    rl = real_logs.pykit_swerve(tmp_path, moving_from_s=5.0)
    capsys.readouterr()                 # pykit's own messages
    d = _run(rl.path, COMMANDS["pykit_swerve"], capsys)
    assert d["vs_logged"]["max_position_m"] < 1e-9
    assert d["vs_logged"]["max_heading_deg"] < 1e-7
    assert any("started at the first logged pose" in n for n in d["notes"])
    r = _replayed(rl, COMMANDS["pykit_swerve"])
    keep = rl.t_us >= r.t[0]
    assert r.t[0] in rl.t_us and not keep.all()
    k = np.searchsorted(r.t, rl.t_us[keep], side="right") - 1
    err = np.hypot(*(r.poses[k, :2] - rl.truth[keep, :2]).T)
    assert err.max() < 1e-9
