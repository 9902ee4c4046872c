"""Differential tests of drivekin's 3-D odometry and pose estimators against robotpy-wpimath
2026.2.2's (``SwerveDrive4Odometry3d``/``MecanumDriveOdometry3d``/``DifferentialDriveOdometry3d``
and their ``*PoseEstimator3d``; skipped without robotpy-wpimath).

One seeded drive per drivetrain over rough ground: the gyro rolls, pitches and turns all the
time (steps of 3 to 30 mrad about every axis), the wheels move unevenly, vision measurements
(rotated and moved off the estimate about every axis, some with their own standard
deviations) arrive late, between samples, at a sample or ahead of the newest, and
``sampleAt``, ``setVisionMeasurementStdDevs`` and the four resets are mixed in. Poses must
agree to 1e-9 (translations relative to 10 m; quaternions up to sign).

robotpy 2026.2.2 composes the gyro as an offset (pose₀·gyro₀⁻¹·gyro) where WPILib 2027 and
drivekin compose the gyro's changes onto the pose (mathematically the same), and its
estimators take the kinematics first (the differential one a kinematics it does not use).
Its C++ estimator differs from Java's (drivekin's) where
``/work/shared/reference/followers-and-estimators.md`` §8 says; the drive stays clear of
those places: vision timestamps are never older than the newest sample − 1.5 s, no update
time is exactly 1.5 s after a buffered one, and times never repeat. Rotation steps between
samples are at least 3 mrad, clear of the range where robotpy's Pose3d log cancels (the
buffer interpolates through it).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from drivekin import (
    DifferentialDriveOdometry3d,
    DifferentialDrivePoseEstimator3d,
    MecanumDriveKinematics,
    MecanumDriveOdometry3d,
    MecanumDrivePoseEstimator3d,
    MecanumDriveWheelPositions,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDriveOdometry3d,
    SwerveDrivePoseEstimator3d,
    SwerveModulePosition,
    Translation2d,
)
from drivekin.geometry3d import Pose3d, Quaternion, Rotation3d, Translation3d

pytest.importorskip("wpimath")
WG = pytest.importorskip("wpimath.geometry")
WK = pytest.importorskip("wpimath.kinematics")
WE = pytest.importorskip("wpimath.estimator")

TOL = 1e-9
SCALE = 10.0   # m: translations are compared relative to the field's size
HISTORY = 1.5
LAYOUT = [(0.3, 0.25), (0.3, -0.25), (-0.3, 0.25), (-0.3, -0.25)]


def ours_pose(x, y, z, q):
    return Pose3d(x, y, z, Rotation3d(Quaternion(*q)))


def theirs_pose(x, y, z, q):
    return WG.Pose3d(x, y, z, WG.Rotation3d(WG.Quaternion(*q)))


def ours_rotation(q):
    return Rotation3d(Quaternion(*q))


def theirs_rotation(q):
    return WG.Rotation3d(WG.Quaternion(*q))


def flat(p):
    """(x, y, z, w, qx, qy, qz) of either library's Pose3d, w >= 0."""
    if isinstance(p, Pose3d):
        q = p.getRotation().getQuaternion()
        v = [p.getX(), p.getY(), p.getZ(), q.getW(), q.getX(), q.getY(), q.getZ()]
    else:
        q = p.rotation().getQuaternion()
        v = [p.X(), p.Y(), p.Z(), q.W(), q.X(), q.Y(), q.Z()]
    if v[3] < 0:
        v[3:] = [-c for c in v[3:]]
    return np.array(v)


def assert_same(ours, theirs, what):
    if ours is None or theirs is None:
        assert ours is None and theirs is None, f"{what}: drivekin {ours} vs robotpy {theirs}"
        return
    a, b = flat(ours), flat(theirs)
    err = np.abs(a - b) / np.array([SCALE] * 3 + [1.0] * 4)
    assert err.max() <= TOL, f"{what}: drivekin {a} vs robotpy {b} (max err {err.max():.3g})"


# ---- the three drivetrains: readings in both libraries' forms ------------------------------

class Swerve:
    name = "swerve"
    kin = SwerveDriveKinematics(*[Translation2d(x, y) for x, y in LAYOUT])

    @staticmethod
    def wkin():
        return WK.SwerveDrive4Kinematics(*[WG.Translation2d(x, y) for x, y in LAYOUT])

    @staticmethod
    def readings(rng, prev):
        d = prev[0] + rng.uniform(-0.01, 0.05, 4) if prev else rng.uniform(-5, 5, 4)
        return (d, rng.uniform(-math.pi, math.pi, 4))

    @staticmethod
    def ours(r):
        return ([SwerveModulePosition(d, Rotation2d(a)) for d, a in zip(*r)],)

    @staticmethod
    def theirs(r):
        return (tuple(WK.SwerveModulePosition(d, WG.Rotation2d(a)) for d, a in zip(*r)),)

    @classmethod
    def make(cls, gyro, r, pose, std=None):
        if std is None:
            return (SwerveDriveOdometry3d(cls.kin, ours_rotation(gyro), *cls.ours(r),
                                          ours_pose(*pose)),
                    WK.SwerveDrive4Odometry3d(cls.wkin(), theirs_rotation(gyro),
                                              *cls.theirs(r), theirs_pose(*pose)))
        return (SwerveDrivePoseEstimator3d(cls.kin, ours_rotation(gyro), *cls.ours(r),
                                           ours_pose(*pose), *std),
                WE.SwerveDrive4PoseEstimator3d(cls.wkin(), theirs_rotation(gyro),
                                               *cls.theirs(r), theirs_pose(*pose), *std))


def wpi_mecanum(values):
    p = WK.MecanumDriveWheelPositions()
    p.frontLeft, p.frontRight, p.rearLeft, p.rearRight = values
    return p


class Mecanum:
    name = "mecanum"
    kin = MecanumDriveKinematics(*[Translation2d(x, y) for x, y in LAYOUT])

    @staticmethod
    def wkin():
        return WK.MecanumDriveKinematics(*[WG.Translation2d(x, y) for x, y in LAYOUT])

    @staticmethod
    def readings(rng, prev):
        return prev + rng.uniform(-0.02, 0.05, 4) if prev is not None else rng.uniform(-5, 5, 4)

    @staticmethod
    def ours(r):
        return (MecanumDriveWheelPositions(*r),)

    @staticmethod
    def theirs(r):
        return (wpi_mecanum(r),)

    @classmethod
    def make(cls, gyro, r, pose, std=None):
        if std is None:
            return (MecanumDriveOdometry3d(cls.kin, ours_rotation(gyro), *cls.ours(r),
                                           ours_pose(*pose)),
                    WK.MecanumDriveOdometry3d(cls.wkin(), theirs_rotation(gyro),
                                              *cls.theirs(r), theirs_pose(*pose)))
        return (MecanumDrivePoseEstimator3d(cls.kin, ours_rotation(gyro), *cls.ours(r),
                                            ours_pose(*pose), *std),
                WE.MecanumDrivePoseEstimator3d(cls.wkin(), theirs_rotation(gyro),
                                               *cls.theirs(r), theirs_pose(*pose), *std))


class Differential:
    name = "differential"

    @staticmethod
    def readings(rng, prev):
        return prev + rng.uniform(-0.01, 0.05, 2) if prev is not None else rng.uniform(-5, 5, 2)

    @staticmethod
    def ours(r):
        return (float(r[0]), float(r[1]))

    theirs = ours

    @classmethod
    def make(cls, gyro, r, pose, std=None):
        if std is None:
            return (DifferentialDriveOdometry3d(ours_rotation(gyro), *cls.ours(r),
                                                ours_pose(*pose)),
                    WK.DifferentialDriveOdometry3d(theirs_rotation(gyro), *cls.theirs(r),
                                                   theirs_pose(*pose)))
        # robotpy 2026 still takes a kinematics, which its odometry does not use.
        return (DifferentialDrivePoseEstimator3d(ours_rotation(gyro), *cls.ours(r),
                                                 ours_pose(*pose), *std),
                WE.DifferentialDrivePoseEstimator3d(WK.DifferentialDriveKinematics(0.6),
                                                    theirs_rotation(gyro), *cls.theirs(r),
                                                    theirs_pose(*pose), *std))


DRIVES = [Swerve, Mecanum, Differential]


class Ground:
    """The robot's attitude: every step turns it about all three axes by 3-30 mrad."""

    def __init__(self, rng):
        self.rng = rng
        self.rot = (1.0, 0.0, 0.0, 0.0)

    def step(self):
        rv = self.rng.uniform(0.003, 0.03, 3) * self.rng.choice([-1.0, 1.0], 3)
        turned = Rotation3d(rv.tolist()).rotateBy(ours_rotation(self.rot))
        q = turned.getQuaternion()
        self.rot = (q.getW(), q.getX(), q.getY(), q.getZ())
        return self.rot


def random_pose(rng, near=None):
    if near is None:
        x, y, z = rng.uniform(-5, 5, 3)
        rot = ours_rotation(rng.normal(size=4).tolist())
    else:
        x, y, z = flat(near)[:3] + rng.uniform(-0.5, 0.5, 3)
        rot = Rotation3d(*rng.uniform(-0.4, 0.4, 3)).rotateBy(near.getRotation())
    q = rot.getQuaternion()
    return (x, y, z, (q.getW(), q.getX(), q.getY(), q.getZ()))


@pytest.mark.parametrize("drive", DRIVES, ids=[d.name for d in DRIVES])
def test_odometry3d_matches_robotpy(drive):
    rng = np.random.default_rng(29)
    ground = Ground(rng)
    r = drive.readings(rng, None)
    o, wo = drive.make(ground.rot, r, random_pose(rng))
    for i in range(300):
        r = drive.readings(rng, r)
        gyro = ground.step()
        got = o.update(ours_rotation(gyro), *drive.ours(r))
        exp = wo.update(theirs_rotation(gyro), *drive.theirs(r))
        assert_same(got, exp, f"update {i}")
        if i % 60 == 59:     # resets, each in the middle of the drive
            which = (i // 60) % 4
            if which == 0:
                pose = random_pose(rng)
                o.resetPose(ours_pose(*pose))
                wo.resetPose(theirs_pose(*pose))
            elif which == 1:
                t = rng.uniform(-5, 5, 3)
                o.resetTranslation(Translation3d(*t))
                wo.resetTranslation(WG.Translation3d(*t))
            elif which == 2:
                rot = random_pose(rng)[3]
                o.resetRotation(ours_rotation(rot))
                wo.resetRotation(theirs_rotation(rot))
            else:
                r, pose = drive.readings(rng, None), random_pose(rng)
                o.resetPosition(ours_rotation(gyro), *drive.ours(r), ours_pose(*pose))
                wo.resetPosition(theirs_rotation(gyro), *drive.theirs(r), theirs_pose(*pose))
            assert_same(o.getPose(), wo.getPose(), f"reset {which} at {i}")


@pytest.mark.parametrize("drive", DRIVES, ids=[d.name for d in DRIVES])
def test_estimator3d_matches_robotpy(drive):
    rng = np.random.default_rng(2029)
    ground = Ground(rng)
    r = drive.readings(rng, None)
    std = ((0.1, 0.2, 0.15, 0.1), (0.5, 0.4, 0.6, 0.3))
    e, we = drive.make(ground.rot, r, random_pose(rng), std)
    assert_same(e.getEstimatedPosition(), we.getEstimatedPosition(), "initial")
    assert e.sampleAt(0.0) is None and we.sampleAt(0.0) is None
    times = []
    t = 0.0
    for i in range(400):
        t = t + 0.02 + rng.uniform(-0.005, 0.005)
        # Steer off C++'s buffer boundary (§8.2): no sample exactly 1.5 s old.
        while any(t - s == HISTORY for s in times):
            t += 1e-6
        times = [s for s in times if t - s < HISTORY] + [t]
        r = drive.readings(rng, r)
        gyro = ground.step()
        got = e.updateWithTime(t, ours_rotation(gyro), *drive.ours(r))
        exp = we.updateWithTime(t, theirs_rotation(gyro), *drive.theirs(r))
        assert_same(got, exp, f"updateWithTime({t})")
        if i % 3 == 0:
            kind = rng.integers(0, 4)
            ts = (rng.uniform(t - HISTORY + 0.01, t) if kind == 0 else     # late
                  rng.choice(times) if kind == 1 else                       # at a sample
                  rng.uniform(t, t + 0.5) if kind == 2 else                 # ahead
                  rng.uniform(times[0], t))                                 # in the buffer
            vision = random_pose(rng, near=e.getEstimatedPosition())
            if rng.integers(0, 3) == 0:
                own = tuple(rng.uniform(0.05, 2.0, 4))
                e.addVisionMeasurement(ours_pose(*vision), ts, own)
                we.addVisionMeasurement(theirs_pose(*vision), ts, own)
            else:
                e.addVisionMeasurement(ours_pose(*vision), ts)
                we.addVisionMeasurement(theirs_pose(*vision), ts)
            assert_same(e.getEstimatedPosition(), we.getEstimatedPosition(),
                        f"addVisionMeasurement at {ts}")
        for ts in (rng.uniform(t - 2.0, t + 0.5), rng.choice(times)):
            assert_same(e.sampleAt(ts), we.sampleAt(ts), f"sampleAt({ts})")
        if i % 50 == 49:
            which = (i // 50) % 5
            if which == 0:
                vstd = tuple(rng.uniform(0.05, 2.0, 4))
                e.setVisionMeasurementStdDevs(vstd)
                we.setVisionMeasurementStdDevs(vstd)
            elif which == 1:
                tr = flat(e.getEstimatedPosition())[:3] + rng.uniform(-0.2, 0.2, 3)
                e.resetTranslation(Translation3d(*tr))
                we.resetTranslation(WG.Translation3d(*tr))
                times = []
            elif which == 2:
                rot = random_pose(rng)[3]
                e.resetRotation(ours_rotation(rot))
                we.resetRotation(theirs_rotation(rot))
                times = []
            elif which == 3:
                pose = random_pose(rng)
                e.resetPose(ours_pose(*pose))
                we.resetPose(theirs_pose(*pose))
                times = []
            else:
                r, pose = drive.readings(rng, None), random_pose(rng)
                e.resetPosition(ours_rotation(gyro), *drive.ours(r), ours_pose(*pose))
                we.resetPosition(theirs_rotation(gyro), *drive.theirs(r), theirs_pose(*pose))
                times = []
            assert_same(e.getEstimatedPosition(), we.getEstimatedPosition(),
                        f"reset {which} at {t}")
