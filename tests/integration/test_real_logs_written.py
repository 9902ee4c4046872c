"""The logs of tests/_support/real_logs.py are what their real writers (robotpy-pykit,
ntcore's DataLog mirroring, robotpy-wpiutil's DataLogWriter) wrote, and their truth is
robotpy-wpimath's odometry of exactly the logged values.

Each log is read back with drivekin's reader (``drivekin.datalog.read``): the entries
have the names and types the writer gives them, the rates and record counts are the
robot's, and wpimath's odometry re-run from ``values(...)`` reproduces the truth to
1e-12 m. Nothing here needs drivekin's replay.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("wpimath")
pytest.importorskip("wpiutil")
pytest.importorskip("ntcore")

from wpimath.geometry import Pose2d, Rotation2d, Translation2d  # noqa: E402
from wpimath.kinematics import (  # noqa: E402
    DifferentialDriveOdometry,
    MecanumDriveKinematics,
    MecanumDriveOdometry,
    MecanumDriveWheelPositions,
    SwerveDrive4Kinematics,
    SwerveDrive4Odometry,
    SwerveModulePosition,
)

from drivekin import datalog  # noqa: E402
from tests._support import real_logs  # noqa: E402

TOL = 1e-12


_MAKERS = {
    "pykit": lambda d: real_logs.pykit_swerve(d),
    "pykit_100hz": lambda d: real_logs.pykit_swerve(d, rate_hz=100),
    "pykit_50hz": lambda d: real_logs.pykit_swerve(d, high_rate=False),
    "nt_diff": real_logs.ntcore_differential,
    "mecanum": real_logs.writer_mecanum,
    "per_module_rot_deg": real_logs.writer_swerve_per_module_doubles,
    "per_module_m_rad": lambda d: real_logs.writer_swerve_per_module_doubles(d, "m", "rad"),
    "ctre": real_logs.ctre_drivestate,
}


class _Logs(dict):
    """Each log written once per module, on first use (robotpy-pykit's only if installed)."""

    def __init__(self, directory) -> None:
        super().__init__()
        self.directory = directory

    def __missing__(self, key):
        if key.startswith("pykit"):
            pytest.importorskip("pykit")
        self[key] = _MAKERS[key](self.directory)
        return self[key]


@pytest.fixture(scope="module")
def logs(tmp_path_factory):
    return _Logs(tmp_path_factory.mktemp("real_logs"))


def held(log, name, at):
    """The entry's value at each time of ``at``: its last record at or before it."""
    ts, v = log.values(name)
    i = np.searchsorted(ts, at, side="right") - 1
    assert (i >= 0).all(), f"{name} has no record before {at[i < 0][0]}"
    return v[i]


def start_pose(rl):
    x, y, th = rl.notes["initial_pose"]
    return Pose2d(x, y, Rotation2d(th))


def swerve_odometry(rl, kin, gyro, dist, ang):
    """wpimath SwerveDrive4Odometry over (N,) gyro Rotation2d list, (N, 4) distances m,
    (N, 4) angle Rotation2d lists, from the log's initial pose."""
    def mods(i):
        return tuple(SwerveModulePosition(float(dist[i][j]), ang[i][j]) for j in range(4))
    odo = SwerveDrive4Odometry(kin, gyro[0], mods(0), start_pose(rl))
    out = [odo.getPose()]
    out += [odo.update(gyro[i], mods(i)) for i in range(1, len(gyro))]
    return np.array([(p.X(), p.Y(), p.rotation().radians()) for p in out])


def assert_close(a, b, tol=TOL):
    a, b = np.asarray(a), np.asarray(b)
    assert a.shape == b.shape
    err = np.abs(a - b).max()
    assert err <= tol, f"max |Δ| = {err:.3g} > {tol:g}"


def types_of(log):
    return {n: e.type for n, e in log.entries.items()}


# ---------------------------------------------------------------------------------------
# robotpy-pykit


def test_pykit_entries_and_types(logs):
    rl = logs["pykit"]
    log = datalog.read(rl.path)
    t = types_of(log)
    assert t["/Timestamp"] == "int64"
    for j in range(4):
        p = f"/Drive/Module{j}/"
        assert t[p + "drivePositionRad"] == "double"
        assert t[p + "turnPosition"] == "struct:Rotation2d"
        assert t[p + "odometryTimestamps"] == "double[]"
        assert t[p + "odometryDrivePositionsRad"] == "double[]"
        assert t[p + "odometryTurnPositions"] == "struct:Rotation2d[]"
    assert t["/Drive/Gyro/yawPosition"] == "struct:Rotation2d"
    assert t["/Drive/Gyro/odometryYawTimestamps"] == "double[]"
    assert t["/Drive/Gyro/odometryYawPositions"] == "struct:Rotation2d[]"
    assert t["/Drive/Gyro/connected"] == "boolean"
    assert t["/RealOutputs/Odometry/Robot"] == "struct:Pose2d"
    assert t["/RealOutputs/Odometry/TrajectorySetpoint"] == "struct:Pose2d"
    assert t["/RealOutputs/SwerveStates/Measured"] == "struct:SwerveModuleState[]"
    for s in ("Rotation2d", "Pose2d", "Translation2d", "SwerveModuleState"):
        assert t[f"/.schema/struct:{s}"] == "structschema"
    assert {"Rotation2d", "Pose2d", "SwerveModuleState"} <= set(log.schemas)
    # pykit's own field names (not capitalised), pykit's metadata
    assert not any("/DrivePositionRad" in n for n in t)
    assert log.entries["/Drive/Module0/drivePositionRad"].metadata == '{"source": "PyKit"}'
    # what pykit adds by itself
    assert any(n.startswith("/DriverStation/") for n in t)
    assert any(n.startswith("/SystemStats/") for n in t)
    assert "/RealOutputs/LoggedRobot/FullCycleMS" in t
    # the roles named in the RealLog are all there
    for names in rl.entries.values():
        for n in [names] if isinstance(names, str) else names:
            assert n in t, n


def test_pykit_rates_and_counts(logs):
    rl = logs["pykit"]
    log = datalog.read(rl.path)
    cycles = len(rl.notes["cycle_us"])
    assert cycles == 1300 and log.entries["/Timestamp"].records == cycles
    ts, clock = log.values("/Timestamp")
    assert (ts == clock).all() and (ts == rl.notes["cycle_us"]).all()
    assert (np.diff(ts) == 20_000).all()                       # the 50 Hz loop
    for j in range(4):
        tts, stamps = log.values(f"/Drive/Module{j}/odometryTimestamps")
        assert (tts == ts).all()                               # a new batch every cycle
        assert stamps.shape == (cycles, 5)                     # 250 Hz: 5 per cycle
        sample_us = np.round(stamps * 1e6).astype(np.int64).ravel()
        assert (sample_us == rl.t_us).all()
        assert (np.diff(sample_us) == 4_000).all()
        assert (stamps[:, -1] * 1e6 < ts).all() and (stamps[:, 0] * 1e6 > ts - 20_000).all()
    _, ystamps = log.values("/Drive/Gyro/odometryYawTimestamps")
    assert (np.round(ystamps * 1e6).astype(np.int64).ravel() == rl.t_us).all()
    # pykit writes a field only when it changes: held values at rest
    assert log.entries["/Drive/Gyro/connected"].records == 1
    assert log.entries["/Drive/Module0/drivePositionRad"].records < cycles
    assert log.entries["/RealOutputs/Odometry/Robot"].records < cycles
    assert len(rl.t_us) == len(rl.truth) == cycles * 5


def test_pykit_truth_from_logged_high_rate_samples(logs):
    rl = logs["pykit"]
    log = datalog.read(rl.path)
    clock = log.values("/Timestamp")[1]
    r = rl.geometry["wheel_radius"]
    kin = SwerveDrive4Kinematics(*[Translation2d(*m) for m in rl.geometry["modules"]])
    dist = np.stack([held(log, f"/Drive/Module{j}/odometryDrivePositionsRad", clock).ravel() * r
                     for j in range(4)], axis=1)
    ang = np.stack([held(log, f"/Drive/Module{j}/odometryTurnPositions", clock).ravel()
                    for j in range(4)], axis=1)
    yaw = held(log, "/Drive/Gyro/odometryYawPositions", clock).ravel()
    truth = swerve_odometry(rl, kin, [Rotation2d(float(v)) for v in yaw], dist,
                            [[Rotation2d(float(a)) for a in row] for row in ang])
    assert_close(truth, rl.truth)
    # Odometry/Robot is the robot's pose after each cycle's last sample
    pose = held(log, "/RealOutputs/Odometry/Robot", clock)
    assert_close(pose, rl.truth[4::5], 0.0)
    assert_close(pose, rl.notes["logged_pose"], 0.0)
    # the decoy setpoint is a different pose
    setpoint = held(log, "/RealOutputs/Odometry/TrajectorySetpoint", clock)
    assert np.hypot(*(setpoint - pose)[:, :2].T).min() > 0.05


def test_pykit_cycle_values_give_a_different_odometry(logs):
    """A replay using only the 50 Hz cycle values reproduces notes["truth_50hz"], which
    misses the high-rate truth by millimetres to centimetres."""
    rl = logs["pykit"]
    log = datalog.read(rl.path)
    clock = log.values("/Timestamp")[1]
    r = rl.geometry["wheel_radius"]
    kin = SwerveDrive4Kinematics(*[Translation2d(*m) for m in rl.geometry["modules"]])
    dist = np.stack([held(log, f"/Drive/Module{j}/drivePositionRad", clock) * r
                     for j in range(4)], axis=1)
    ang = np.stack([held(log, f"/Drive/Module{j}/turnPosition", clock) for j in range(4)], axis=1)
    yaw = held(log, "/Drive/Gyro/yawPosition", clock)
    t50 = swerve_odometry(rl, kin, [Rotation2d(float(v)) for v in yaw], dist,
                          [[Rotation2d(float(a)) for a in row] for row in ang])
    assert (rl.notes["t_us_50hz"] == clock).all()
    assert_close(t50, rl.notes["truth_50hz"])
    err = np.hypot(*(t50[:, :2] - rl.truth[4::5, :2]).T)
    assert 0.005 < err.max() == pytest.approx(rl.notes["max_error_50hz_m"])


def test_pykit_without_odometry_thread(logs):
    rl = logs["pykit_50hz"]
    log = datalog.read(rl.path)
    assert not any("odometry" in n.lower() and "/Drive/" in n for n in log.entries)
    clock = log.values("/Timestamp")[1]
    assert (clock == rl.t_us).all() and len(rl.t_us) == 1300
    r = rl.geometry["wheel_radius"]
    kin = SwerveDrive4Kinematics(*[Translation2d(*m) for m in rl.geometry["modules"]])
    dist = np.stack([held(log, f"/Drive/Module{j}/drivePositionRad", clock) * r
                     for j in range(4)], axis=1)
    ang = np.stack([held(log, f"/Drive/Module{j}/turnPosition", clock) for j in range(4)], axis=1)
    yaw = held(log, "/Drive/Gyro/yawPosition", clock)
    truth = swerve_odometry(rl, kin, [Rotation2d(float(v)) for v in yaw], dist,
                            [[Rotation2d(float(a)) for a in row] for row in ang])
    assert_close(truth, rl.truth)
    assert_close(held(log, "/RealOutputs/Odometry/Robot", clock), rl.truth, 0.0)


# ---------------------------------------------------------------------------------------
# ntcore mirroring: differential


def test_ntcore_differential_entries(logs):
    rl = logs["nt_diff"]
    log = datalog.read(rl.path)
    t = types_of(log)
    for n in ("LeftPosition", "RightPosition", "GyroAngle", "LeftVelocity", "RightVelocity"):
        assert t[f"NT:/Drive/{n}"] == "double"
    assert t["NT:/SmartDashboard/Field/Robot"] == "double[]"
    assert t["NT:/SmartDashboard/Field/.type"] == "string"
    assert log.records("NT:/SmartDashboard/Field/.type")[1] == [b"Field2d"]
    assert all(n.startswith("NT:/") for n in t)
    assert '"source":"NT"' in log.entries["NT:/Drive/LeftPosition"].metadata
    # 50 Hz, NT drops repeated values (the robot rests at both ends)
    n = len(rl.t_us)
    assert n == 1301 and (np.diff(rl.t_us) == 20_000).all()
    for name in ("NT:/Drive/LeftPosition", "NT:/Drive/GyroAngle", "NT:/SmartDashboard/Field/Robot"):
        ts, _ = log.values(name)
        assert 0.5 * n < len(ts) < n
        assert np.isin(ts, rl.t_us).all()
        assert ts[0] == rl.t_us[0]
    assert log.values("NT:/SmartDashboard/Field/Robot")[1].shape[1] == 3


def test_ntcore_differential_truth(logs):
    rl = logs["nt_diff"]
    log = datalog.read(rl.path)
    at = rl.t_us
    left = held(log, "NT:/Drive/LeftPosition", at)
    right = held(log, "NT:/Drive/RightPosition", at)
    deg = held(log, "NT:/Drive/GyroAngle", at)
    odo = DifferentialDriveOdometry(Rotation2d.fromDegrees(float(deg[0])), float(left[0]),
                                    float(right[0]), start_pose(rl))
    poses = [odo.getPose()] + [odo.update(Rotation2d.fromDegrees(float(deg[i])), float(left[i]),
                                          float(right[i])) for i in range(1, len(at))]
    truth = np.array([(p.X(), p.Y(), p.rotation().radians()) for p in poses])
    assert_close(truth, rl.truth)
    # the Field2d pose is the robot's odometry, heading in degrees
    field = held(log, "NT:/SmartDashboard/Field/Robot", at)
    assert_close(field[:, :2], rl.truth[:, :2], 0.0)
    assert_close(np.radians(field[:, 2]), rl.truth[:, 2], 1e-12)
    # the heading crosses ±180° (truth θ is Rotation2d.radians(): wrapped)
    assert np.abs(np.diff(rl.truth[:, 2])).max() > math.pi


# ---------------------------------------------------------------------------------------
# DataLogWriter: mecanum


def test_writer_mecanum(logs):
    rl = logs["mecanum"]
    log = datalog.read(rl.path)
    t = types_of(log)
    assert t["/Drive/WheelPositions"] == "double[]"
    assert t["/Drive/Gyro"] == "struct:Rotation2d"
    assert t["/Drive/Pose"] == "struct:Pose2d"
    assert t["/.schema/struct:Rotation2d"] == t["/.schema/struct:Pose2d"] == "structschema"
    ts, wheels = log.values("/Drive/WheelPositions")
    assert wheels.shape == (2601, 4) and (ts == rl.t_us).all()
    assert (np.diff(ts) == 10_000).all()                 # 100 Hz
    gts, gyro = log.values("/Drive/Gyro")
    assert (gts == ts).all() and gyro.shape == (2601,)
    kin = MecanumDriveKinematics(*[Translation2d(*w) for w in rl.geometry["wheels"]])

    def pos(i):
        p = MecanumDriveWheelPositions()
        p.frontLeft, p.frontRight, p.rearLeft, p.rearRight = map(float, wheels[i])
        return p
    odo = MecanumDriveOdometry(kin, Rotation2d(float(gyro[0])), pos(0), start_pose(rl))
    poses = [odo.getPose()] + [odo.update(Rotation2d(float(gyro[i])), pos(i))
                               for i in range(1, len(ts))]
    truth = np.array([(p.X(), p.Y(), p.rotation().radians()) for p in poses])
    assert_close(truth, rl.truth)
    assert_close(log.values("/Drive/Pose")[1], rl.truth, 0.0)
    # strafing happened: the robot moved sideways relative to its heading
    d = np.diff(rl.truth[:, :2], axis=0)
    side = -d[:, 0] * np.sin(rl.truth[:-1, 2]) + d[:, 1] * np.cos(rl.truth[:-1, 2])
    assert abs(side).sum() > 3.0


# ---------------------------------------------------------------------------------------
# DataLogWriter: swerve, one double per module signal


@pytest.mark.parametrize("key, drive, turn", [("per_module_rot_deg", "rot", "deg"),
                                              ("per_module_m_rad", "m", "rad")])
def test_writer_swerve_per_module_doubles(logs, key, drive, turn):
    rl = logs[key]
    assert (rl.geometry["drive_units"], rl.geometry["turn_units"]) == (drive, turn)
    log = datalog.read(rl.path)
    t = types_of(log)
    names = rl.geometry["module_names"]
    for n in names:
        for s in ("DrivePosition", "TurnAngle", "DriveVelocity"):
            assert t[f"/Swerve/{n}/{s}"] == "double"
            assert log.entries[f"/Swerve/{n}/{s}"].records == 1301
    assert t["/Swerve/Gyro/Yaw"] == "double" and t["/Swerve/Pose"] == "struct:Pose2d"
    ts = log.values("/Swerve/Gyro/Yaw")[0]
    assert (ts == rl.t_us).all() and (np.diff(ts) == 20_000).all()
    scale = 2 * math.pi * rl.geometry["wheel_radius"] if drive == "rot" else 1.0
    dist = np.stack([log.values(f"/Swerve/{n}/DrivePosition")[1] * scale for n in names], axis=1)
    turn_v = np.stack([log.values(f"/Swerve/{n}/TurnAngle")[1] for n in names], axis=1)
    if turn == "deg":
        assert abs(turn_v).max() <= 180 and abs(turn_v).max() > 90
        ang = [[Rotation2d.fromDegrees(float(a)) for a in row] for row in turn_v]
    else:
        assert abs(turn_v).max() <= math.pi
        ang = [[Rotation2d(float(a)) for a in row] for row in turn_v]
    yaw = [Rotation2d.fromDegrees(float(v)) for v in log.values("/Swerve/Gyro/Yaw")[1]]
    kin = SwerveDrive4Kinematics(*[Translation2d(*m) for m in rl.geometry["modules"]])
    assert_close(swerve_odometry(rl, kin, yaw, dist, ang), rl.truth)
    assert_close(log.values("/Swerve/Pose")[1], rl.truth, 0.0)


def test_per_module_units_describe_the_same_motion(logs):
    a, b = logs["per_module_rot_deg"], logs["per_module_m_rad"]
    assert (a.t_us == b.t_us).all()
    assert_close(a.truth[:, :2], b.truth[:, :2], 1e-9)


# ---------------------------------------------------------------------------------------
# CTRE DriveState via ntcore mirroring


def test_ctre_drivestate_entries(logs):
    rl = logs["ctre"]
    log = datalog.read(rl.path)
    t = types_of(log)
    p = "NT:/DriveState/"
    assert t[p + "Pose"] == "struct:Pose2d"
    assert t[p + "Speeds"] == "struct:ChassisSpeeds"
    assert t[p + "ModuleStates"] == t[p + "ModuleTargets"] == "struct:SwerveModuleState[]"
    assert t[p + "ModulePositions"] == "struct:SwerveModulePosition[]"
    assert t[p + "Timestamp"] == t[p + "OdometryFrequency"] == "double"
    assert t["NT:/Pose/robotPose"] == "double[]" and t["NT:/Pose/.type"] == "string"
    for s in ("Pose2d", "ChassisSpeeds", "SwerveModuleState", "SwerveModulePosition"):
        assert t[f"NT:/.schema/struct:{s}"] == "structschema"
    assert not any("gyro" in n.lower() or "yaw" in n.lower() or "heading" in n.lower() for n in t)
    # Timestamp: the sample times at 250 Hz; NT's record times come 0.8 ms later
    ts, stamp = log.values(p + "Timestamp")
    assert len(ts) == len(rl.t_us) == 6501
    assert (np.round(stamp * 1e6).astype(np.int64) == rl.t_us).all()
    assert (np.diff(rl.t_us) == 4_000).all()
    assert (ts - rl.t_us == rl.notes["publish_delay_us"]).all()
    fts, freq = log.values(p + "OdometryFrequency")
    assert len(fts) == 1 and freq[0] == 250.0                  # NT drops repeated values
    mts, mods = log.values(p + "ModulePositions")
    assert mods.shape[1:] == (4, 2) and len(mts) < len(ts)     # unchanged at rest


def test_ctre_drivestate_truth(logs):
    rl = logs["ctre"]
    log = datalog.read(rl.path)
    p = "NT:/DriveState/"
    at = log.values(p + "Timestamp")[0]                        # record times of each sample
    mods = held(log, p + "ModulePositions", at)
    pose = held(log, p + "Pose", at)
    assert_close(pose, rl.truth, 0.0)
    # With the pose's heading for the missing gyro, wpimath reproduces the truth.
    kin = SwerveDrive4Kinematics(*[Translation2d(*m) for m in rl.geometry["modules"]])
    truth = swerve_odometry(rl, kin, [Rotation2d(float(v)) for v in pose[:, 2]], mods[:, :, 0],
                            [[Rotation2d(float(a)) for a in row] for row in mods[:, :, 1]])
    assert_close(truth, rl.notes["truth_pose_heading"])
    assert_close(truth, rl.truth)
    # heading from module kinematics alone drifts from the gyro's
    drift = np.abs(rl.notes["truth_kinematic_heading"] - rl.truth)[:, :2].max()
    assert 1e-4 < drift < 0.5
    field = held(log, "NT:/Pose/robotPose", at)
    assert_close(np.radians(field[:, 2]), rl.truth[:, 2])


def test_pykit_100hz_odometry_thread(logs):
    rl = logs["pykit_100hz"]
    log = datalog.read(rl.path)
    ts, stamps = log.values("/Drive/Module0/odometryTimestamps")
    assert stamps.shape == (1300, 2)                           # 100 Hz: 2 per 50 Hz cycle
    assert (np.round(stamps * 1e6).astype(np.int64).ravel() == rl.t_us).all()
    assert (np.diff(rl.t_us) == 10_000).all() and rl.notes["odometry_rate_hz"] == 100
    assert_close(held(log, "/RealOutputs/Odometry/Robot", ts), rl.truth[1::2], 0.0)
