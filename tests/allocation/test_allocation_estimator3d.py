"""Allocation tests for the 3-D odometry and pose estimators: every odometry class's
``update``, the swerve estimator's 50 Hz loop with a vision measurement every third step
(both forms of addVisionMeasurement), ``sampleAt``, and every other estimator's
``updateWithTime``.

The harness is ``tests/_support/alloc.py`` (see ``test_allocation_estimator.py`` for the 2-D
ones): after a warm-up the measured iterations make no allocator calls at all. Time
advances through every run, so the 1.5 s history fills and slides; the returned Pose3d comes
from its freelist. Each loop spells its call out (``f(*args)`` would build a tuple).
"""
from __future__ import annotations

import numpy as np
import pytest

from tests._support.alloc import CALLS, assert_no_allocations
from drivekin import (
    DeadWheelKinematics,
    DeadWheelOdometry3d,
    DeadWheelPoseEstimator3d,
    DifferentialDriveOdometry3d,
    DifferentialDrivePoseEstimator3d,
    MecanumDriveKinematics,
    MecanumDriveOdometry3d,
    MecanumDrivePoseEstimator3d,
    MecanumDriveWheelPositions,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDriveOdometry3d,
    SwerveDrivePoseEstimator3d,
    SwerveModulePosition,
    Translation2d,
    TwoDeadWheelOdometry3d,
    TwoDeadWheelPoseEstimator3d,
)
from drivekin.geometry3d import Pose3d, Rotation3d

DT = 0.02
LATENCY = 0.05
LAYOUT = [Translation2d(0.3, 0.3), Translation2d(0.3, -0.3), Translation2d(-0.3, 0.3),
          Translation2d(-0.3, -0.3)]
START = Pose3d(1.0, 2.0, 0.25, Rotation3d(0.1, -0.2, 0.5))
# Two gyro readings that differ about every axis, so every step composes a full rotation.
GA, GB = Rotation3d(0.01, -0.02, 0.03), Rotation3d(-0.02, 0.01, -0.01)


def module_readings():
    pa = [SwerveModulePosition(0.01 * i, Rotation2d(0.1 * i)) for i in range(4)]
    pb = [SwerveModulePosition(0.02 * i + 0.01, Rotation2d(-0.1 * i)) for i in range(4)]
    return pa, pb


def dead_wheels():
    return DeadWheelKinematics([Pose2d(0.0, 0.3, Rotation2d(0.0)),
                                Pose2d(0.1, -0.2, Rotation2d(0.1)),
                                Pose2d(-0.2, 0.05, Rotation2d(np.pi / 2))])


# ---- odometry -------------------------------------------------------------------------------

def test_swerve_odometry3d_update():
    pa, pb = module_readings()
    odo = SwerveDriveOdometry3d(SwerveDriveKinematics(*LAYOUT), GA, pa, START)

    def loop(it):
        for _ in it:
            pose = odo.update(GB, pb)
            pose = odo.update(GA, pa)
        return pose

    assert_no_allocations(loop, "SwerveDriveOdometry3d.update")


def test_swerve_odometry3d_update_from_an_array():
    a = np.array([[0.01 * i, 0.1 * i] for i in range(4)], dtype=np.float64)
    b = np.array([[0.02 * i + 0.01, -0.1 * i] for i in range(4)], dtype=np.float64)
    odo = SwerveDriveOdometry3d(SwerveDriveKinematics(*LAYOUT), GA, a, START)

    def loop(it):
        for _ in it:
            pose = odo.update(GB, b)
            pose = odo.update(GA, a)
        return pose

    assert_no_allocations(loop, "SwerveDriveOdometry3d.update ((N, 2) array)")


def test_mecanum_odometry3d_update():
    wa = MecanumDriveWheelPositions(0.01, 0.02, 0.03, 0.04)
    wb = MecanumDriveWheelPositions(-0.01, 0.05, 0.0, 0.02)
    odo = MecanumDriveOdometry3d(MecanumDriveKinematics(*LAYOUT), GA, wa, START)

    def loop(it):
        for _ in it:
            pose = odo.update(GB, wb)
            pose = odo.update(GA, wa)
        return pose

    assert_no_allocations(loop, "MecanumDriveOdometry3d.update")


def test_differential_odometry3d_update():
    odo = DifferentialDriveOdometry3d(GA, 0.01, 0.02, START)

    def loop(it):
        for _ in it:
            pose = odo.update(GB, -0.01, 0.03)
            pose = odo.update(GA, 0.01, 0.02)
        return pose

    assert_no_allocations(loop, "DifferentialDriveOdometry3d.update")


def test_dead_wheel_odometry3d_update():
    wa = np.array([0.01, 0.02, 0.03], dtype=np.float64)
    wb = np.array([-0.01, 0.05, 0.0], dtype=np.float64)
    odo = DeadWheelOdometry3d(dead_wheels(), wa, GA, START)
    two = TwoDeadWheelOdometry3d(0.1, -0.2, 0.01, 0.02, GA, START)

    def loop(it):
        for _ in it:
            pose = odo.update(wb, GB)
            pose = odo.update(wa, GA)
            pose = two.update(-0.01, 0.03, GB)
            pose = two.update(0.01, 0.02, GA)
        return pose

    assert_no_allocations(loop, "DeadWheelOdometry3d.update, TwoDeadWheelOdometry3d.update")


# ---- estimators ---------------------------------------------------------------------------

STD_DEVS = {
    "two-argument": None,
    "std-devs-tuple": (0.5, 0.6, 0.7, 0.4),
    "std-devs-array": np.array([0.5, 0.6, 0.7, 0.4], dtype=np.float64),
}


def swerve_estimator():
    pa, _ = module_readings()
    return SwerveDrivePoseEstimator3d(SwerveDriveKinematics(*LAYOUT), GA, pa, START)


@pytest.mark.parametrize("form", sorted(STD_DEVS))
def test_swerve_update_with_vision_every_third_step(form):
    est = swerve_estimator()
    pa, pb = module_readings()
    vision = Pose3d(1.05, 2.02, 0.3, Rotation3d(0.12, -0.18, 0.48))
    std = STD_DEVS[form]
    t = 0.0

    if std is None:
        def loop(it):
            nonlocal t
            for _ in it:                       # three 50 Hz steps per iteration
                t += DT
                est.updateWithTime(t, GB, pb)
                t += DT
                est.updateWithTime(t, GA, pa)
                t += DT
                pose = est.updateWithTime(t, GB, pb)
                est.addVisionMeasurement(vision, t - LATENCY)
            return pose
    else:
        def loop(it):
            nonlocal t
            for _ in it:
                t += DT
                est.updateWithTime(t, GB, pb)
                t += DT
                est.updateWithTime(t, GA, pa)
                t += DT
                pose = est.updateWithTime(t, GB, pb)
                est.addVisionMeasurement(vision, t - LATENCY, std)
            return pose

    assert_no_allocations(loop, f"SwerveDrivePoseEstimator3d.updateWithTime + "
                                f"addVisionMeasurement ({form})")
    # The history (76 samples) wrapped hundreds of times, and the measurements were used:
    # the estimate is nearer the vision pose than the odometry alone.
    assert t > 3 * DT * 2 * CALLS
    odometry = SwerveDriveOdometry3d(SwerveDriveKinematics(*LAYOUT), GA, pa, START)
    for _ in range(round(t / (3 * DT))):
        odometry.update(GB, pb)
        odometry.update(GA, pa)
        odometry.update(GB, pb)
    est_err = est.getEstimatedPosition().getTranslation().getDistance(vision.getTranslation())
    odo_err = odometry.getPose().getTranslation().getDistance(vision.getTranslation())
    assert est_err < 0.5 * odo_err, (est_err, odo_err)


def test_swerve_sample_at():
    est = swerve_estimator()
    pa, pb = module_readings()
    t = 0.0
    for i in range(100):
        t += DT
        est.updateWithTime(t, *((GB, pb) if i % 2 == 0 else (GA, pa)))
        if i % 3 == 2:
            est.addVisionMeasurement(Pose3d(1.05, 2.02, 0.3, Rotation3d()), t - LATENCY)
    between = t - 0.5 - 0.3 * DT                 # between two samples, after the records
    clamped = t - 10.0

    def loop(it):
        for _ in it:
            pose = est.sampleAt(between)
            pose = est.sampleAt(clamped)
        return pose

    assert_no_allocations(loop, "SwerveDrivePoseEstimator3d.sampleAt")


def test_mecanum_update_with_time():
    wa = MecanumDriveWheelPositions(0.01, 0.02, 0.03, 0.04)
    wb = MecanumDriveWheelPositions(-0.01, 0.05, 0.0, 0.02)
    est = MecanumDrivePoseEstimator3d(MecanumDriveKinematics(*LAYOUT), GA, wa, START)
    t = 0.0

    def loop(it):
        nonlocal t
        for _ in it:
            t += DT
            est.updateWithTime(t, GB, wb)
            t += DT
            pose = est.updateWithTime(t, GA, wa)
        return pose

    assert_no_allocations(loop, "MecanumDrivePoseEstimator3d.updateWithTime")


def test_differential_update_with_time():
    est = DifferentialDrivePoseEstimator3d(GA, 0.01, 0.02, START)
    t = 0.0

    def loop(it):
        nonlocal t
        for _ in it:
            t += DT
            est.updateWithTime(t, GB, -0.01, 0.03)
            t += DT
            pose = est.updateWithTime(t, GA, 0.01, 0.02)
        return pose

    assert_no_allocations(loop, "DifferentialDrivePoseEstimator3d.updateWithTime")


def test_dead_wheel_update_with_time():
    wa = np.array([0.01, 0.02, 0.03], dtype=np.float64)
    wb = np.array([-0.01, 0.05, 0.0], dtype=np.float64)
    est = DeadWheelPoseEstimator3d(dead_wheels(), wa, GA, START)
    two = TwoDeadWheelPoseEstimator3d(0.1, -0.2, 0.01, 0.02, GA, START)
    t = 0.0

    def loop(it):
        nonlocal t
        for _ in it:
            t += DT
            est.updateWithTime(t, wb, GB)
            two.updateWithTime(t, -0.01, 0.03, GB)
            t += DT
            pose = est.updateWithTime(t, wa, GA)
            pose = two.updateWithTime(t, 0.01, 0.02, GA)
        return pose

    assert_no_allocations(loop, "DeadWheelPoseEstimator3d.updateWithTime, "
                                "TwoDeadWheelPoseEstimator3d.updateWithTime")
