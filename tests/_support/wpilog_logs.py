"""Test logs written by robotpy-wpiutil's own DataLogWriter (a real producer, not
drivekin's writer), with values packed by robotpy's wpistruct from robotpy-wpimath objects.

:func:`simulate_match` drives a 4-module swerve robot along a known smooth path (the
truth, integrated at 1 kHz) and samples what its sensors report; :func:`write_match_log`
writes it the way a robot program with a 250 Hz odometry thread would log it, with
realistic entry names, gaps and out-of-order records; the robot's own odometry there is
robotpy-wpimath's SwerveDrive4Odometry.
"""
from __future__ import annotations

import contextlib
import math

import numpy as np
import wpiutil
import wpiutil.wpistruct as ws
from wpimath.geometry import (
    Pose2d,
    Pose3d,
    Rotation2d,
    Rotation3d,
    Translation2d,
    Translation3d,
)
from wpimath.kinematics import (
    ChassisSpeeds,
    SwerveDrive4Kinematics,
    SwerveDrive4Odometry,
    SwerveModulePosition,
    SwerveModuleState,
)

MODULES = ((0.28, 0.28), (0.28, -0.28), (-0.28, 0.28), (-0.28, -0.28))
START = (1.0, 2.0, 0.5)          # true start pose (x m, y m, θ rad)
GYRO_OFFSET = 1.0                # the gyro reads true heading + this, rad
ENCODER_SCALE = 0.97             # encoders report 97 % of the true wheel travel
T0_US = 3_000_000                # first module sample (FPGA clock, µs)
GYRO_DELAY = 10                  # module samples (4 ms) before the first gyro sample


class RobotpyLog:
    """robotpy-wpiutil's DataLogWriter. It must be flushed regularly: 2026.2.2 blocks
    forever once about 1 MiB is buffered."""

    def __init__(self, path: str) -> None:
        self.log = wpiutil.DataLogWriter(str(path))
        self.n = 0

    def start(self, name: str, type_string: str, ts: int, schema_of=None) -> int:
        if schema_of is not None:
            self.log.addStructSchema(schema_of, ts)
        return self.log.start(name, type_string, "", ts)

    def raw(self, entry: int, data: bytes, ts: int) -> None:
        self.log.appendRaw(entry, data, ts)
        self._tick()

    def double(self, entry: int, value: float, ts: int) -> None:
        self.log.appendDouble(entry, value, ts)
        self._tick()

    def _tick(self) -> None:
        self.n += 1
        if self.n % 1000 == 0:
            self.log.flush()

    def close(self) -> None:
        self.log.flush()
        self.log.stop()


@contextlib.contextmanager
def robotpy_log(path):
    log = RobotpyLog(path)
    try:
        yield log
    finally:
        log.close()


def _velocity(t: float) -> tuple[float, float, float]:
    """Robot-relative (vx m/s, vy m/s, ω rad/s): smooth, and every module keeps moving."""
    return (1.5 + 0.5 * math.sin(0.4 * t), 0.8 * math.sin(0.25 * t),
            0.2 + 0.6 * math.sin(0.3 * t))


def simulate_match(seconds: float = 30.0) -> dict:
    """The truth at 250 Hz sample times and the module positions the encoders report."""
    fine = 1e-3
    n_fine = round(seconds / fine)
    per_sample = 4                       # 1 kHz steps per 250 Hz sample
    x, y, th = START
    dist = np.zeros(4)
    truth, modules = [], []
    for k in range(n_fine + 1):
        if k % per_sample == 0:
            vx, vy, w = _velocity(k * fine)
            angles = [math.atan2(vy + w * mx, vx - w * my) for mx, my in MODULES]
            truth.append((x, y, th))
            modules.append([(d * ENCODER_SCALE, a) for d, a in zip(dist, angles)])
        vx, vy, w = _velocity((k + 0.5) * fine)      # midpoint rule
        for j, (mx, my) in enumerate(MODULES):
            dist[j] += math.hypot(vx - w * my, vy + w * mx) * fine
        # Exact pose exponential for constant velocities over one fine step.
        dth = w * fine
        if abs(dth) > 1e-12:
            s, c = math.sin(dth) / dth, (1 - math.cos(dth)) / dth
        else:
            s, c = 1.0, 0.0
        dx, dy = (vx * s - vy * c) * fine, (vx * c + vy * s) * fine
        x += dx * math.cos(th) - dy * math.sin(th)
        y += dx * math.sin(th) + dy * math.cos(th)
        th += dth
    n = len(truth)
    t = T0_US + 4000 * np.arange(n, dtype=np.int64)
    return {"t": t, "truth": np.array(truth), "modules": np.array(modules)}


def pose3d(x: float, y: float, th: float, t: float) -> Pose3d:
    """The planar pose (x, y, θ) at time ``t`` s as a Pose3d of a robot rocking on uneven
    ground: a few cm of height, a few degrees of roll and pitch; its toPose2d() is
    (x, y, θ) up to rounding."""
    return Pose3d(Translation3d(x, y, 0.03 * (1.0 + math.sin(0.9 * t))),
                  Rotation3d(0.05 * math.sin(0.7 * t), -0.08 * math.sin(0.5 * t + 1.0), th))


def write_match_log(path, sim: dict, *, module_gaps=((2000, 2125),), gyro_gaps=((1000, 1015),),
                    shuffle: bool = True, poses: tuple[str, ...] = ("Pose2d",)) -> dict:
    """Write ``sim`` as a robot would log it and return what the robot computed.

    * ``/Drive/ModulePositions`` struct:SwerveModulePosition[] at 250 Hz (the odometry
      thread), minus the samples in ``module_gaps`` (index ranges: a CAN dropout);
    * ``/Drive/Gyro/YawPosition`` struct:Rotation2d at 50 Hz, starting ``GYRO_DELAY``
      module samples late, minus ``gyro_gaps`` (index ranges in gyro samples);
    * ``/RealOutputs/Odometry/Robot`` struct:Pose2d at 50 Hz: the robot's odometry
      (robotpy-wpimath SwerveDrive4Odometry updated at every module sample from the first
      gyro sample on, with the latest gyro sample), sampled at each gyro timestamp; with
      ``"Pose3d"`` in ``poses``, the same in ``/RealOutputs/Odometry/Robot3d``
      (struct:Pose3d, as a robot on uneven ground logs it: :func:`pose3d`), and without
      ``"Pose2d"`` only that;
    * distractors: measured module states (struct:SwerveModuleState[], 2026 name),
      chassis speeds, a camera pose (a second struct:Pose2d), battery voltage, enabled
      flag, console messages, and ``/Sim/TruePose``;
    * with ``shuffle``, records are written out of timestamp order: module samples in
      swapped pairs, and the second half of the gyro written before the first.
    """
    t, truth, modules = sim["t"], sim["truth"], sim["modules"]
    n = len(t)
    keep = np.ones(n, dtype=bool)
    for a, b in module_gaps:
        keep[a:b] = False
    g_idx = np.arange(GYRO_DELAY, n, 5)                  # 50 Hz, on module sample times
    g_keep = np.ones(len(g_idx), dtype=bool)
    for a, b in gyro_gaps:
        g_keep[a:b] = False
    g_idx = g_idx[g_keep]
    gyro = truth[:, 2] + GYRO_OFFSET

    # The robot's own odometry (robotpy-wpimath), as its odometry thread ran it.
    kin = SwerveDrive4Kinematics(*[Translation2d(mx, my) for mx, my in MODULES])

    def positions(i):
        return tuple(SwerveModulePosition(float(d), Rotation2d(float(a))) for d, a in modules[i])

    robot_pose = np.full((n, 3), np.nan)
    gi = 0
    odo = None
    latest_gyro = None
    for i in range(n):
        while gi < len(g_idx) and g_idx[gi] <= i:
            latest_gyro = gyro[g_idx[gi]]
            gi += 1
        if latest_gyro is None or not keep[i]:
            continue
        if odo is None:
            odo = SwerveDrive4Odometry(kin, Rotation2d(float(latest_gyro)), positions(i),
                                       Pose2d(*truth[i, :2], Rotation2d(float(truth[i, 2]))))
            p = odo.getPose()
        else:
            p = odo.update(Rotation2d(float(latest_gyro)), positions(i))
        robot_pose[i] = (p.X(), p.Y(), p.rotation().radians())
    # the logged pose at a gyro time: the odometry's latest pose at that time
    last = np.maximum.accumulate(np.where(~np.isnan(robot_pose[:, 0]), np.arange(n), -1))
    pose_idx = g_idx[last[g_idx] >= 0]
    logged = robot_pose[last[pose_idx]]

    with robotpy_log(path) as log:
        ts0 = int(t[0]) - 1000
        e_mod = log.start("/Drive/ModulePositions", "struct:SwerveModulePosition[]", ts0,
                          SwerveModulePosition)
        e_gyro = log.start("/Drive/Gyro/YawPosition", "struct:Rotation2d", ts0, Rotation2d)
        e_pose = (log.start("/RealOutputs/Odometry/Robot", "struct:Pose2d", ts0, Pose2d)
                  if "Pose2d" in poses else None)
        e_pose3 = (log.start("/RealOutputs/Odometry/Robot3d", "struct:Pose3d", ts0, Pose3d)
                   if "Pose3d" in poses else None)
        e_cam = log.start("/RealOutputs/Vision/Camera0/EstimatedPose", "struct:Pose2d", ts0)
        e_true = log.start("/Sim/TruePose", "struct:Pose2d", ts0)
        e_states = log.start("/RealOutputs/SwerveStates/Measured",
                             "struct:SwerveModuleState[]", ts0, SwerveModuleState)
        e_speeds = log.start("/RealOutputs/SwerveChassisSpeeds/Measured",
                             "struct:ChassisSpeeds", ts0, ChassisSpeeds)
        e_batt = log.start("/SystemStats/BatteryVoltage", "double", ts0)
        e_en = log.start("/DriverStation/Enabled", "boolean", ts0)
        e_msg = log.start("messages", "string", ts0)
        log.log.appendString(e_msg, "Robot program starting", ts0)
        log.log.appendBoolean(e_en, True, ts0)

        order = np.flatnonzero(keep)
        if shuffle:                       # swap neighbours: records out of order
            order = order.copy()
            for k in range(0, len(order) - 1, 40):
                order[k], order[k + 1] = order[k + 1], order[k]
        for i in order:
            log.raw(e_mod, ws.packArray(list(positions(i))), int(t[i]))
        g_order = np.arange(len(g_idx))
        if shuffle:
            half = len(g_order) // 2
            g_order = np.concatenate([g_order[half:], g_order[:half]])
        for k in g_order:
            i = g_idx[k]
            log.raw(e_gyro, ws.pack(Rotation2d(float(gyro[i]))), int(t[i]))
        for k, i in enumerate(pose_idx):
            ts = int(t[i])
            x, y, th = logged[k]
            if e_pose is not None:
                log.raw(e_pose, ws.pack(Pose2d(x, y, Rotation2d(th))), ts)
            if e_pose3 is not None:
                log.raw(e_pose3, ws.pack(pose3d(x, y, th, (ts - T0_US) / 1e6)), ts)
            tx, ty, tth = truth[i]
            log.raw(e_true, ws.pack(Pose2d(tx, ty, Rotation2d(tth))), ts)
            log.raw(e_cam, ws.pack(Pose2d(tx + 0.05, ty - 0.03, Rotation2d(tth))), ts)
            vx, vy, w = _velocity((ts - T0_US) / 1e6)
            log.raw(e_speeds, ws.pack(ChassisSpeeds(vx, vy, w)), ts)
            log.raw(e_states, ws.packArray(kin.toSwerveModuleStates(ChassisSpeeds(vx, vy, w))),
                    ts)
            log.double(e_batt, 12.3 - 0.1 * math.sin(ts / 1e6), ts)
    return {"pose_t": t[pose_idx], "logged": logged, "truth_at_pose": truth[pose_idx],
            "gyro_t": t[g_idx], "module_t": t[keep], "skipped": int(keep[:GYRO_DELAY].sum())}
