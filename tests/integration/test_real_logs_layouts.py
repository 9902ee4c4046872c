"""The team layouts on the real robots' logs of ../shared/reallogs/logs: a YAGSL robot
replayed with no options, a module-velocity-state robot, and the refusals that say what
a log lacks. The robot's own logged pose is the reference (these are real logs: no
truth exists), so the bounds are what NetworkTables' sampling allows, as measured."""
from __future__ import annotations

import json
import subprocess
import sys

import pytest

from drivekin import replay
from tests.integration.test_real_logs_candidates import LOGS

pytestmark = pytest.mark.skipif(not LOGS.is_dir(),
                                reason="../shared/reallogs/logs is not beside the repository")


def _cli(name, *options):
    proc = subprocess.run([sys.executable, "-m", "drivekin", "replay",
                           str(LOGS / f"{name}.wpilog"), "--no-write", "--json", *options],
                          capture_output=True, text=True, timeout=60)
    return proc


def test_the_yagsl_robot_replays_with_no_options():
    proc = _cli("yagsl_1672_FRC_20250214_212636")
    assert proc.returncode == 0, proc.stderr
    d = json.loads(proc.stdout)[0]
    assert d["entries"]["gyro"] == "NT:/SmartDashboard/swerve/imu/raw"
    assert d["entries"]["pose"] == "NT:/SmartDashboard/Field/Robot"
    assert "YAGSL's odometry inputs (frontleft, frontright, backleft, backright)" in \
        d["why"]["positions"]
    # swerve/wheelLocation holds 17, 14, 17, -13, -16, 14, -16, -13 (inches)
    assert "(0.4318, 0.3556), (0.4318, -0.3302), (-0.4064, 0.3556), (-0.4064, -0.3302)" \
        in d["geometry"]
    # Field/Robot is YAGSL's own odometry, mirrored through NetworkTables at ~50 Hz
    assert d["vs_logged"]["rms_position_m"] < 0.01
    assert d["vs_logged"]["final_position_m"] < 0.005


def test_the_sysid_session_of_the_yagsl_robot_replays_its_distances():
    r = replay.replayLog(LOGS / "yagsl_1672_FRC_20250214_212636.wpilog",
                         replay.ReplayConfig(positions="position-drive-frontleft-SwerveSubsystem"))
    assert r.why["positions"].startswith("named with --positions")
    assert len(r.entries["positions"]) and "(0.4318, 0.3556)" in r.geometry
    assert r.vsLogged is not None and r.vsLogged.rmsPosition < 0.03


def test_a_velocity_state_robot_is_integrated_and_agrees_with_its_own_pose():
    proc = _cli("mcm001_FRC_20241013_023615", "--trackwidth", "0.5", "--wheelbase", "0.5")
    assert proc.returncode == 0, proc.stderr
    d = json.loads(proc.stdout)[0]
    assert any("integrated from velocity states" in n for n in d["notes"])
    assert d["duration_s"] > 90
    assert d["vs_logged"]["max_position_m"] < 0.01


@pytest.mark.parametrize("name, lacks", [
    ("team302_FRC_20240910_002841", "no back-left module"),
    ("team302_FRC_20240814_235409.3", "no wheel or module positions found"),
    ("team100_all24_armCartesianSpaceSquare_FRC_20231121_173813",
     "no wheel or module positions found"),
])
def test_a_log_without_distances_says_what_it_lacks(name, lacks):
    proc = _cli(name)
    assert proc.returncode == 1
    lines = [ln for ln in proc.stderr.splitlines() if not ln.startswith("[1/1]")]
    assert len(lines) == 1 and "Traceback" not in proc.stderr
    assert lacks in lines[0] and "--module-entries" in lines[0]
