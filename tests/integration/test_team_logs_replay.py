"""``python -m drivekin replay`` on logs laid out as teams' robots write them
(tests/_support/team_logs.py: YAGSL's telemetry, a WPILib SysId drive routine, a team's
own per-module names, module velocity states only), written by ntcore and
robotpy-wpiutil, each replayed by the command a user types and checked, cycle by cycle,
against robotpy-wpimath's odometry of the same robot. The replayed path is read back
from the written replay log with robotpy-wpiutil's reader."""
from __future__ import annotations

import json
import math
import os
import shlex
import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("ntcore")
pytest.importorskip("wpiutil")

from wpimath.geometry import Rotation2d, Translation2d                # noqa: E402
from wpimath.kinematics import (                                      # noqa: E402
    SwerveDrive4Kinematics,
    SwerveDrive4Odometry,
    SwerveModulePosition,
)

import drivekin                                                      # noqa: E402
from drivekin.app.cli import main                                    # noqa: E402
from tests._support import team_logs                                 # noqa: E402
from tests._support.real_logs import _pose_row, _start_pose          # noqa: E402

# What a user types for each layout (LOG.wpilog is the log's path).
COMMANDS = {
    "yagsl_swerve": "",
    "sysid_swerve": "",
    "team_named_swerve": ('--module-entries "NT:/{module} Swerve Encoders/{module} Drive,'
                          'NT:/{module} Swerve Encoders/{module} Turn" '
                          "--drive-units m --turn-units deg --gyro-units deg "
                          "--trackwidth 0.54 --wheelbase 0.6"),
    "module_states_per_module": "--gyro-units deg --trackwidth 0.4699 --wheelbase 0.4699",
    "module_states_struct": "--trackwidth 0.4699 --wheelbase 0.4699",
}
POSITIONS = ("yagsl_swerve", "sysid_swerve", "team_named_swerve")
STATES = ("module_states_per_module", "module_states_struct")


@pytest.fixture(scope="module")
def logs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("team")
    out = {name: getattr(team_logs, name)(folder) for name in POSITIONS}
    for variant in ("per_module", "struct"):
        out["module_states_" + variant] = team_logs.module_states_only(folder, variant)
    return out


def _replay(rl, tmp_path, capsys):
    """The user's command (with --json and an output folder); the report and the
    replayed path (t µs, x, y, θ) read from /drivekin/ReplayPose."""
    args = ["replay", str(rl.path), *shlex.split(COMMANDS[_name(rl)]), "--json",
            "--out-dir", str(tmp_path)]
    code = main(args)
    out, err = capsys.readouterr()
    assert code == 0, err
    report = json.loads(out)[0]
    recs = team_logs.records(tmp_path / (rl.path.stem + "-replay.wpilog"))
    _, _, t, poses = recs["/drivekin/ReplayPose"]
    return report, np.array(t, dtype=np.int64), np.array([_pose_row(p) for p in poses])


def _name(rl) -> str:
    stem = rl.path.stem
    return stem if stem in COMMANDS else "module_states_" + stem.split("module_states_")[1]


def _per_cycle(rl, t, poses):
    """The replayed pose once each robot cycle's records are in (the latest replayed
    sample before the next cycle starts), for the cycles from the replay's first one."""
    period = rl.notes["period_us"]
    first = int(np.searchsorted(rl.t_us + period, t[0], side="right"))
    cycles = rl.t_us[first:]
    k = np.searchsorted(t, cycles + period - 1, side="right") - 1
    assert (k >= 0).all()
    return first, poses[k]


def _errors(a, b):
    pos = np.hypot(*(a[:, :2] - b[:, :2]).T)
    head = np.abs(np.angle(np.exp(1j * (a[:, 2] - b[:, 2]))))
    return pos, head


@pytest.mark.parametrize("name", POSITIONS)
def test_the_generators_truth_follows_from_the_records(logs, name):
    # Independent of drivekin: the records read back with robotpy-wpiutil, held to the end
    # of each robot cycle, fed to robotpy-wpimath's odometry, give the truth.
    rl = logs[name]
    recs = team_logs.records(rl.path)
    end = rl.t_us + rl.notes["period_us"] - 1
    e = rl.entries
    if "wheel_location" in e:                      # YAGSL: inches, x y per module
        wl = recs[e["wheel_location"]][3][0]
        mods = [(wl[2 * j] * 0.0254, wl[2 * j + 1] * 0.0254) for j in range(4)]
    else:
        mods = rl.geometry["modules"]
    kin = SwerveDrive4Kinematics(*[Translation2d(x, y) for x, y in mods])
    dist = [team_logs.held(recs, n, end) for n in e["drive_positions"]]
    ang = [team_logs.held(recs, n, end) for n in e["turn_angles"]]
    gyro = team_logs.held(recs, e["gyro_deg"], end)
    odo, out = None, []
    for k in range(len(end)):
        # SysId positions start with the first test; the robot rests at 0 m before it.
        m = [SwerveModulePosition(0.0 if isinstance(d[k], float) and math.isnan(d[k]) else d[k],
                                  Rotation2d.fromDegrees(a[k])) for d, a in zip(dist, ang)]
        g = Rotation2d.fromDegrees(gyro[k])
        if odo is None:
            odo = SwerveDrive4Odometry(kin, g, m, _start_pose())
            out.append(_pose_row(odo.getPose()))
        else:
            out.append(_pose_row(odo.update(g, m)))
    pos, head = _errors(np.array(out), rl.truth)
    assert pos.max() < 1e-12 and head.max() < 1e-12
    if name == "sysid_swerve":
        units = {recs[n][1] for n in e["drive_positions"]}
        assert units == {"Meter"}
        assert {recs[n][1] for n in e["decoys"]} == {"Volt", "Meter per Second"}


@pytest.mark.parametrize("name", STATES)
def test_the_velocity_oracle_follows_from_the_records(logs, name):
    # The rule's oracle from exactly the logged records (robotpy-wpiutil's reader):
    # distances integrated trapezoidally between consecutive records.
    rl = logs[name]
    recs = team_logs.records(rl.path)
    e = rl.entries
    if "module_states" in e:
        _, _, t, states = recs[e["module_states"]]
        v = np.array([[s.speed for s in row] for row in states])
        ang = [[s.angle for s in row] for row in states]
        _, _, tg, g = recs[e["gyro"]]
    else:
        t = recs[e["velocities_ftps"][0]][2]
        v = np.column_stack([recs[n][3] for n in e["velocities_ftps"]]) * team_logs.FEET
        a = np.column_stack([team_logs.held(recs, n, t) for n in e["turn_angles"]])
        ang = [[Rotation2d.fromDegrees(x) for x in row] for row in a]
        tg, g = recs[e["gyro_deg"]][2:]
        g = [Rotation2d.fromDegrees(x) for x in g]
    assert len(t) == len(rl.t_us)                  # every cycle logged: jitter, no repeats
    gk = np.searchsorted(tg, t, side="right") - 1
    d = np.zeros_like(v)
    d[1:] = np.cumsum(0.5 * (v[1:] + v[:-1]) * (np.diff(t) * 1e-6)[:, None], axis=0)
    kin = SwerveDrive4Kinematics(*[Translation2d(x, y) for x, y in rl.geometry["modules"]])
    odo, out = None, []
    for k in range(len(t)):
        m = [SwerveModulePosition(float(d[k, j]), ang[k][j]) for j in range(4)]
        if odo is None:
            odo = SwerveDrive4Odometry(kin, g[gk[k]], m, _start_pose())
            out.append(_pose_row(odo.getPose()))
        else:
            out.append(_pose_row(odo.update(g[gk[k]], m)))
    pos, head = _errors(np.array(out), rl.notes["truth_from_velocities"])
    assert pos.max() < 1e-12 and head.max() < 1e-12
    # The robot's own odometry integrated its distances: within the stated bound, which
    # is itself small (the motion's v'' at 50 Hz and the 1e-6 m/s jitter).
    pos, head = _errors(rl.notes["truth_from_velocities"], rl.truth)
    assert pos.max() <= rl.notes["bound_m"] < 2e-3
    assert head.max() < 1e-12                      # the heading is the logged gyro's


@pytest.mark.parametrize("name", POSITIONS)
def test_replay_reproduces_the_robots_odometry(logs, tmp_path, capsys, name):
    rl = logs[name]
    d, t, poses = _replay(rl, tmp_path, capsys)
    assert d["drivetrain"] == "swerve"
    assert d["entries"]["pose"] == rl.entries["pose"]
    first, replayed = _per_cycle(rl, t, poses)
    if name == "sysid_swerve":                     # no distances before the first test
        assert first <= int(np.argmax(rl.notes["test_cycles"] >= 0))
    else:
        assert first == 0
    pos, head = _errors(replayed, rl.truth[first:])
    assert pos.max() < 1e-9, pos.max()
    assert head.max() < 1e-9, head.max()
    assert d["vs_logged"]["max_position_m"] < 1e-9


def test_yagsl_module_locations_come_from_its_wheel_location_entry(logs, tmp_path, capsys):
    # YAGSL rounds the JSON's locations to whole inches and publishes what it used: a
    # replay with the JSON's unrounded locations would not reproduce its odometry.
    rl = logs["yagsl_swerve"]
    d, _, _ = _replay(rl, tmp_path, capsys)
    assert d["entries"]["gyro"] == rl.entries["gyro_deg"]
    assert rl.geometry["wheel_location_inches"][:2] == pytest.approx([12.0, 12.0], abs=1e-12)
    assert rl.geometry["json_inches"][2][0] == -11.5       # Java's Math.round: -11, not -12
    assert rl.geometry["modules"][2][0] == pytest.approx(-11 * 0.0254, abs=0)


@pytest.mark.parametrize("name", STATES)
def test_replay_integrates_module_velocity_states(logs, tmp_path, capsys, name):
    rl = logs[name]
    d, t, poses = _replay(rl, tmp_path, capsys)
    assert d["drivetrain"] == "swerve"
    assert d["entries"]["pose"] == rl.entries["pose"]
    assert any("integrated from velocity states" in n for n in d["notes"])
    first, replayed = _per_cycle(rl, t, poses)
    assert first == 0
    pos, head = _errors(replayed, rl.notes["truth_from_velocities"])
    assert pos.max() < 1e-9, pos.max()                   # the documented rule, exactly
    assert head.max() < 1e-9
    pos, _ = _errors(replayed, rl.truth)
    assert pos.max() <= rl.notes["bound_m"]               # the robot's own odometry
    assert d["vs_logged"]["max_position_m"] <= rl.notes["bound_m"]


def test_the_yagsl_command_as_typed(logs, tmp_path):
    # `python -m drivekin replay LOG.wpilog`, no options, in a fresh interpreter.
    rl = logs["yagsl_swerve"]
    env = dict(os.environ)                     # the imported (in-place built) package first
    root = os.path.dirname(os.path.dirname(os.path.abspath(drivekin.__file__)))
    env["PYTHONPATH"] = os.pathsep.join(p for p in (root, env.get("PYTHONPATH", "")) if p)
    r = subprocess.run([sys.executable, "-m", "drivekin", "replay", str(rl.path), "--json",
                        "--no-write"], capture_output=True, text=True, timeout=60, env=env)
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)[0]
    assert d["vs_logged"]["max_position_m"] < 1e-9
    final = d["final_pose"]
    assert np.hypot(final["x_m"] - rl.truth[-1, 0], final["y_m"] - rl.truth[-1, 1]) < 1e-9
