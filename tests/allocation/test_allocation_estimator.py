"""Allocation tests for the pose estimators' loop: ``updateWithTime`` at 50 Hz with a vision
measurement every third step, ``sampleAt``, and every estimator's ``updateWithTime``.

The harness is ``tests/_support/alloc.py`` (see ``test_allocation_drivetrains.py``): after a
warm-up, the measured iterations must make no allocator calls at all (traced peak,
traced size and ``gc.get_count()[0]`` unchanged, and zero calls counted by
``drivekin._core.alloccount``). Time advances through every warm-up and measured run (a
closure variable, so the 1.5 s pose history fills, then slides, and the ring buffer's
compaction and the vision records' clean-up run many times over); each float made per
step comes from CPython's float freelist.
"""
from __future__ import annotations

import numpy as np
import pytest

from tests._support.alloc import CALLS, assert_no_allocations
from drivekin import (
    DeadWheelKinematics,
    DeadWheelPoseEstimator,
    DifferentialDrivePoseEstimator,
    MecanumDriveKinematics,
    MecanumDrivePoseEstimator,
    MecanumDriveWheelPositions,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDrivePoseEstimator,
    SwerveModulePosition,
    Translation2d,
    TwoDeadWheelPoseEstimator,
)

DT = 0.02          # 50 Hz
LATENCY = 0.05     # s between a vision frame and its measurement reaching the estimator
LAYOUT = [Translation2d(0.3, 0.3), Translation2d(0.3, -0.3), Translation2d(-0.3, 0.3),
          Translation2d(-0.3, -0.3)]


def swerve_estimator():
    return SwerveDrivePoseEstimator(
        SwerveDriveKinematics(*LAYOUT), Rotation2d(0.0),
        [SwerveModulePosition(0.0, Rotation2d(0.0)) for _ in range(4)],
        Pose2d(1.0, 2.0, Rotation2d(0.5)))


def readings():
    # Two alternating readings, so every step integrates a non-zero twist.
    pa = [SwerveModulePosition(0.01 * i, Rotation2d(0.1 * i)) for i in range(4)]
    pb = [SwerveModulePosition(0.02 * i + 0.01, Rotation2d(-0.1 * i)) for i in range(4)]
    return Rotation2d(0.01), pa, Rotation2d(-0.02), pb


STD_DEVS = {
    "two-argument": None,
    "std-devs-tuple": (0.5, 0.6, 0.7),
    "std-devs-array": np.array([0.5, 0.6, 0.7], dtype=np.float64),
}


@pytest.mark.parametrize("form", sorted(STD_DEVS))
def test_swerve_update_with_vision_every_third_step(form):
    est = swerve_estimator()
    ga, pa, gb, pb = readings()
    vision = Pose2d(1.05, 2.02, Rotation2d(0.48))
    std = STD_DEVS[form]
    t = 0.0

    if std is None:
        def loop(it):
            nonlocal t
            for _ in it:                       # three 50 Hz steps per iteration
                t += DT
                est.updateWithTime(t, ga, pa)
                t += DT
                est.updateWithTime(t, gb, pb)
                t += DT
                pose = est.updateWithTime(t, ga, pa)
                est.addVisionMeasurement(vision, t - LATENCY)
            return pose
    else:
        def loop(it):
            nonlocal t
            for _ in it:
                t += DT
                est.updateWithTime(t, ga, pa)
                t += DT
                est.updateWithTime(t, gb, pb)
                t += DT
                pose = est.updateWithTime(t, ga, pa)
                est.addVisionMeasurement(vision, t - LATENCY, std)
            return pose

    assert_no_allocations(loop, f"SwerveDrivePoseEstimator.updateWithTime + "
                                f"addVisionMeasurement ({form})")
    # 3 steps per iteration over two warm-ups of 1000, two measured runs and the
    # counter's warm-ups: the history (76 samples) wrapped hundreds of times.
    assert t > 3 * DT * 2 * CALLS
    # The measurements were used: the estimate is nearer the vision pose than the same
    # drive's odometry alone.
    odo_only = swerve_estimator()
    for i in range(round(t / (3 * DT))):
        odo_only.updateWithTime(3 * i * DT, ga, pa)
        odo_only.updateWithTime((3 * i + 1) * DT, gb, pb)
        odo_only.updateWithTime((3 * i + 2) * DT, ga, pa)
    est_err = est.getEstimatedPosition().getTranslation().getDistance(vision.getTranslation())
    odo_err = odo_only.getEstimatedPosition().getTranslation().getDistance(
        vision.getTranslation())
    assert est_err < 0.5 * odo_err, (est_err, odo_err)


def test_swerve_sample_at():
    est = swerve_estimator()
    ga, pa, gb, pb = readings()
    t = 0.0
    for i in range(100):
        t += DT
        est.updateWithTime(t, *((ga, pa) if i % 2 == 0 else (gb, pb)))
        if i % 3 == 2:
            est.addVisionMeasurement(Pose2d(1.05, 2.02, Rotation2d(0.48)), t - LATENCY)
    between = t - 0.5 - 0.3 * DT                 # between two samples, after the records
    clamped = t - 10.0

    def loop(it):
        for _ in it:
            pose = est.sampleAt(between)
            pose = est.sampleAt(clamped)
        return pose

    assert_no_allocations(loop, "SwerveDrivePoseEstimator.sampleAt")


def test_vision_from_another_clock():
    # Unix-stamped vision against monotonic odometry (porting issue, items 1 and 8): after
    # the one warning, each such measurement replaces the last one from that clock, so the
    # records stay bounded and the loop allocates nothing.
    import warnings
    est = swerve_estimator()
    ga, pa, gb, pb = readings()
    vision = Pose2d(1.05, 2.02, Rotation2d(0.48))
    t = 0.0
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        est.updateWithTime(t, ga, pa)
        est.addVisionMeasurement(vision, 1.7e9)

    def loop(it):
        nonlocal t
        for _ in it:
            t += DT
            est.updateWithTime(t, ga, pa)
            t += DT
            pose = est.updateWithTime(t, gb, pb)
            est.addVisionMeasurement(vision, 1.7e9 + t)
        return pose

    assert_no_allocations(loop, "SwerveDrivePoseEstimator.addVisionMeasurement "
                                "(another clock)")
    assert len(caught) == 1


# Each loop calls updateWithTime with its arguments spelled out: ``f(t, *args)`` would
# build a fresh argument tuple per call in the test itself.

def test_mecanum_update_with_time():
    est = MecanumDrivePoseEstimator(
        MecanumDriveKinematics(*LAYOUT), Rotation2d(0.0), MecanumDriveWheelPositions(),
        Pose2d(1.0, 2.0, Rotation2d(0.5)))
    ga, gb = Rotation2d(0.01), Rotation2d(-0.02)
    wa = MecanumDriveWheelPositions(0.01, 0.02, 0.03, 0.04)
    wb = MecanumDriveWheelPositions(-0.01, 0.05, 0.0, 0.02)
    t = 0.0

    def loop(it):
        nonlocal t
        for _ in it:
            t += DT
            est.updateWithTime(t, ga, wa)
            t += DT
            pose = est.updateWithTime(t, gb, wb)
        return pose

    assert_no_allocations(loop, "MecanumDrivePoseEstimator.updateWithTime")


def test_differential_update_with_time():
    est = DifferentialDrivePoseEstimator(Rotation2d(0.0), 0.0, 0.0,
                                         Pose2d(1.0, 2.0, Rotation2d(0.5)))
    ga, gb = Rotation2d(0.01), Rotation2d(-0.02)
    t = 0.0

    def loop(it):
        nonlocal t
        for _ in it:
            t += DT
            est.updateWithTime(t, ga, 0.01, 0.02)
            t += DT
            pose = est.updateWithTime(t, gb, -0.01, 0.03)
        return pose

    assert_no_allocations(loop, "DifferentialDrivePoseEstimator.updateWithTime")


def test_two_dead_wheel_update_with_time():
    est = TwoDeadWheelPoseEstimator(0.1, -0.2, 0.0, 0.0, Rotation2d(0.0),
                                    Pose2d(1.0, 2.0, Rotation2d(0.5)))
    ga, gb = Rotation2d(0.01), Rotation2d(-0.02)
    t = 0.0

    def loop(it):
        nonlocal t
        for _ in it:
            t += DT
            est.updateWithTime(t, 0.01, 0.02, ga)
            t += DT
            pose = est.updateWithTime(t, -0.01, 0.03, gb)
        return pose

    assert_no_allocations(loop, "TwoDeadWheelPoseEstimator.updateWithTime")


@pytest.mark.parametrize("gyro", [True, False])
def test_dead_wheel_update_with_time(gyro):
    kin = DeadWheelKinematics([Pose2d(0.0, 0.3, Rotation2d(0.0)),
                               Pose2d(0.1, -0.2, Rotation2d(0.1)),
                               Pose2d(-0.2, 0.05, Rotation2d(np.pi / 2))])
    est = DeadWheelPoseEstimator(kin, [0.0, 0.0, 0.0], Rotation2d(0.0) if gyro else None,
                                 Pose2d(1.0, 2.0, Rotation2d(0.5)))
    wa = np.array([0.01, 0.02, 0.03], dtype=np.float64)
    wb = np.array([-0.01, 0.05, 0.0], dtype=np.float64)
    ga, gb = (Rotation2d(0.01), Rotation2d(-0.02)) if gyro else (None, None)
    t = 0.0

    def loop(it):
        nonlocal t
        for _ in it:
            t += DT
            est.updateWithTime(t, wa, ga)
            t += DT
            pose = est.updateWithTime(t, wb, gb)
        return pose

    assert_no_allocations(loop, f"DeadWheelPoseEstimator.updateWithTime (gyro={gyro})")
