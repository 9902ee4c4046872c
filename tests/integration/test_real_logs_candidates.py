"""Pose and gyro candidates and ``replay --list`` on the real robots' logs of
../shared/reallogs/logs (SOURCES.md there says where each comes from). The chosen entry
of each log was determined by reading the log's entries, not by running drivekin."""
from __future__ import annotations

import pathlib
import re

import numpy as np
import pytest

from drivekin import datalog, replay
from drivekin._core import loglayouts as layouts
from drivekin._core.display import escape
from drivekin._core.replayinputs import _pose

LOGS = pathlib.Path(__file__).resolve().parents[2] / ".." / "shared" / "reallogs" / "logs"
NAMES = ["mcm001_FRC_20241008_044638", "mcm001_FRC_20241012_171633",
         "mcm001_FRC_20241013_023615",
         "team100_all24_armCartesianSpaceSquare_FRC_20231121_173813",
         "team302_FRC_20240814_235409.3", "team302_FRC_20240910_002841",
         "team4201_FRC_20220523_024716", "yagsl_1672_FRC_20250214_212636"]

# log -> (pose entries, gyro entry or None): what each robot logged as its own.
CHOSEN = {
    # PhotonVision's sim: the robot's estimate as three dashboard doubles (degrees); the
    # Sim Field copies are the vision simulation's; no gyro entry at all.
    "mcm001": (("NT:/SmartDashboard/Drive/X", "NT:/SmartDashboard/Drive/Y",
                "NT:/SmartDashboard/Drive/Heading"), None),
    "team100": ((), None),                                   # an arm study: no drivetrain
    "team302_FRC_20240814": (("/Pose/RobotPoseX", "/Pose/RobotPoseY",
                              "/Pose/RobotPoseAngle"), None),
    # The robot's own 51 Hz struct:Pose2d, not the 25 Hz Field2d copy; no gyro stream.
    "team302_FRC_20240910": (("/Chassis/Pose",), None),
    # The robot's own 50 Hz "x,y,θ" string over the 25 Hz Field2d copy; DriveTrain's Robot
    # Angle over the dashboard's Heading Degrees and the turret's copy.
    "team4201": (("/pose",), "NT:/DriveTrain/Robot Angle"),
    # YAGSL: its odometry's IMU reading; Field/Robot, not PathPlanner's one-record pose.
    "yagsl": (("NT:/SmartDashboard/Field/Robot",), "NT:/SmartDashboard/swerve/imu/raw"),
}


def _facts(name):
    return next(v for k, v in CHOSEN.items() if name.startswith(k))


@pytest.fixture(scope="module")
def real():
    if not LOGS.is_dir():
        pytest.skip("../shared/reallogs/logs is not beside the repository")
    out = {}
    for n in NAMES:
        log = datalog.read(LOGS / f"{n}.wpilog")
        out[n] = (log, replay.listing(log), replay.listing(log, showAll=True))
    return out


def _lines(text, log, entry):
    """The lines of ``entry``: its (printed) name, at least two spaces, its type."""
    shown = escape(entry)
    kind = log.entries[entry].type[:30]
    return [x for x in text.splitlines() if x.startswith(shown + "  ")
            and x[len(shown):].lstrip(" ").startswith(kind + " ")]


def _line(text, log, entry):
    (line,) = _lines(text, log, entry)
    return line


def _description(line):
    """What a listing line says after its name, type, record count and rate."""
    return re.split(r" rec +(?:\d+ Hz|-)(?:  |$)", line, maxsplit=1)[1]


@pytest.mark.parametrize("name", NAMES)
def test_list_fits_in_60_lines_and_all_lists_every_entry(real, name):
    log, short, full = real[name]
    assert len(short.splitlines()) <= 60
    for entry in log.entries:
        if not layouts.is_schema(entry):
            assert len(_lines(full, log, entry)) == 1, entry


@pytest.mark.parametrize("name", NAMES)
def test_the_used_entries_are_the_robots_own(real, name):
    log, short, _ = real[name]
    pose, gyro = _facts(name)
    used = [x for x in short.splitlines() if "(used)" in x]
    assert sorted(x.split("  ")[0] for x in used if "pose candidate" in x) == sorted(pose)
    s, _ = _pose(log, replay.ReplayConfig(), layouts.Options(), set())
    assert (s.entries if s is not None else ()) == pose
    if gyro is not None:
        assert "gyro candidate 1" in _line(short, log, gyro)
    assert not any("gyro candidate" in x for x in used if gyro is None)


@pytest.mark.parametrize("name", NAMES)
def test_non_candidates_do_not_say_pose_or_gyro(real, name):
    _, _, full = real[name]
    for line in full.splitlines()[1:]:
        if " rec " in line and "candidate" not in line:
            assert not re.search(r"\b(pose|gyro)\b", _description(line), re.I), line


@pytest.mark.parametrize("name", NAMES)
def test_rates_only_for_ten_records_over_a_second_up_to_1_khz(real, name):
    log, _, full = real[name]
    for entry, info in log.entries.items():
        if layouts.is_schema(entry):
            continue
        line = _line(full, log, entry)
        hz = re.search(r" rec +(\d+) Hz  ", line)
        t = np.sort(log.records(entry)[0]) if info.records else np.array([], np.int64)
        ok = len(t) >= 10 and t[-1] - t[0] >= 1_000_000
        if not ok:
            assert hz is None, line
        elif hz is not None:
            d = np.diff(t)
            assert abs(int(hz.group(1)) - 1e6 / np.median(d[d > 0])) <= 0.5
            assert int(hz.group(1)) <= 1000


def test_team100s_two_records_a_microsecond_apart_print_no_rate(real):
    log, _, full = real["team100_all24_armCartesianSpaceSquare_FRC_20231121_173813"]
    entry = "NT:$pub$/Shuffleboard/.metadata/Selected"
    t = log.records(entry)[0]
    assert len(t) == 2 and t[1] - t[0] == 1
    assert re.search(r" rec +-(  |$)", _line(full, log, entry))


def test_team302s_pose_is_its_51_hz_struct_not_the_field2d_copy(real):
    log, short, _ = real["team302_FRC_20240910_002841"]
    line = _line(short, log, "/Chassis/Pose")
    assert "struct:Pose2d" in line and " 51 Hz " in line and "pose candidate 1 (used)" in line
    assert "pose candidate 2:" in _line(short, log, "NT:/SmartDashboard/Field/Robot")
    for refused in ("/Chassis/StoredHeadingDegrees",
                    "NT:/SwerveChassisLogging/ResetPosePigeonYaw"):
        assert _description(_line(short, log, refused)).startswith("not used:")


def test_team4201s_vision_and_turret_are_refused_and_its_text_pose_is_in_radians(real):
    log, short, _ = real["team4201_FRC_20220523_024716"]
    for refused in ("NT:/SmartDashboard/Field2d/Vision", "NT:/SmartDashboard/Field2d/Turret",
                    "NT:/Turret/Robot Angle"):
        assert _description(_line(short, log, refused)).startswith("not used:")
    assert "gyro candidate 2:" in _line(short, log, "NT:/SmartDashboard/Heading Degrees")
    # The Field2d copy is in degrees by Field2d's definition: the text's angle, read as
    # radians, follows it.
    s, _ = _pose(log, replay.ReplayConfig(), layouts.Options(), set())
    tf, field = log.values("NT:/SmartDashboard/Field2d/Robot")
    k = np.searchsorted(tf, s.t, side="right") - 1
    late = (k >= 0) & (s.t > tf[0] + 60_000_000)
    diff = np.angle(np.exp(1j * (s.values[late, 2] - np.radians(field[k[late], 2]))))
    assert np.median(np.abs(diff)) < 0.01


def test_mcm001s_three_doubles_match_the_estimate_in_degrees(real):
    log, _, _ = real["mcm001_FRC_20241013_023615"]
    s, _ = _pose(log, replay.ReplayConfig(), layouts.Options(), set())
    assert "θ deg" in s.units
    te, est = log.values("NT:/SmartDashboard/VisionSystemSim-main/Sim Field/EstimatedRobot")
    k = np.searchsorted(te, s.t, side="right") - 1
    ok = k >= 0
    assert np.median(np.hypot(*(s.values[ok, :2] - est[k[ok], :2]).T)) < 0.01
    diff = np.angle(np.exp(1j * (s.values[ok, 2] - np.radians(est[k[ok], 2]))))
    assert np.median(np.abs(diff)) < 0.01
