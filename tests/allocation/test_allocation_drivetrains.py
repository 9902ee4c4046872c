"""Allocation tests for the mecanum / differential hot paths and the odometry loops.

After a warm-up, 10 000 iterations of each loop body must make no allocator calls at all
(traced peak, traced size and ``gc.get_count()[0]`` unchanged). The harness is
``tests/_support/alloc.py`` (shared with ``test_allocation.py``, which also holds its
self-tests): it warms up again after ``gc.collect()``, so bodies that return floats (``pose.getX()``) from
CPython's float freelist measure as the zero they are. Objects drawn from a freelist
(drivekin's Cython freelists, CPython's float freelist) are not allocator calls; that is how
``pose = odo.update(...)`` and ``pose.getX()`` stay free.

The pose-reading loops run on every odometry class and every estimator of the catalog
(``drivekin._core.catalog``: each entry's ``example``), so a new drivetrain's are covered
without an edit here.
"""
from __future__ import annotations

import numpy as np
import pytest

from tests._support.alloc import assert_no_allocations
from drivekin._core import catalog
from drivekin import (
    ChassisVelocities,
    DifferentialDriveKinematics,
    DifferentialDriveOdometry,
    DifferentialDriveWheelVelocities,
    MecanumDriveKinematics,
    MecanumDriveOdometry,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDriveOdometry,
    SwerveModulePosition,
    Translation2d,
)

# ---------------------------------------------------------------------------------------
# Mecanum kinematics

MECANUM_LAYOUT = [Translation2d(0.3, 0.25), Translation2d(0.3, -0.25),
                  Translation2d(-0.3, 0.25), Translation2d(-0.3, -0.25)]


def test_mecanum_to_wheel_velocities_into():
    kin = MecanumDriveKinematics(*MECANUM_LAYOUT)
    cv = ChassisVelocities(1.0, -0.5, 2.0)
    out = MecanumDriveWheelVelocities()

    def loop(it):
        for _ in it:
            kin.toWheelVelocitiesInto(cv, out)

    assert_no_allocations(loop, "MecanumDriveKinematics.toWheelVelocitiesInto")


def test_mecanum_to_wheel_velocities_into_with_center_of_rotation():
    kin = MecanumDriveKinematics(*MECANUM_LAYOUT)
    cv = ChassisVelocities(1.0, -0.5, 2.0)
    out = MecanumDriveWheelVelocities()
    a, b = Translation2d(0.3, 0.25), Translation2d(-0.1, 0.2)

    def loop(it):
        for _ in it:                                # alternate: the rows are rebuilt
            kin.toWheelVelocitiesInto(cv, out, a)
            kin.toWheelVelocitiesInto(cv, out, b)

    assert_no_allocations(loop, "MecanumDriveKinematics.toWheelVelocitiesInto(cor)")


def test_mecanum_to_chassis_velocities_into():
    kin = MecanumDriveKinematics(*MECANUM_LAYOUT)
    wheels = MecanumDriveWheelVelocities(1.0, 2.0, -3.0, 0.5)
    out = ChassisVelocities()

    def loop(it):
        for _ in it:
            kin.toChassisVelocitiesInto(wheels, out)

    assert_no_allocations(loop, "MecanumDriveKinematics.toChassisVelocitiesInto")


def test_mecanum_desaturate_in_place():
    w = MecanumDriveWheelVelocities()

    def loop(it):
        for _ in it:
            w.frontLeft = 5.0                       # over the limit every time
            w.frontRight = -7.0
            w.rearLeft = 1.0
            w.rearRight = 2.0
            w.desaturateInPlace(4.0)

    assert_no_allocations(loop, "MecanumDriveWheelVelocities.desaturateInPlace")
    assert w.frontRight == -4.0


# ---------------------------------------------------------------------------------------
# Differential kinematics


def test_differential_to_wheel_velocities_into():
    kin = DifferentialDriveKinematics(0.6)
    cv = ChassisVelocities(1.0, 0.0, 2.0)
    out = DifferentialDriveWheelVelocities()

    def loop(it):
        for _ in it:
            kin.toWheelVelocitiesInto(cv, out)

    assert_no_allocations(loop, "DifferentialDriveKinematics.toWheelVelocitiesInto")


def test_differential_to_chassis_velocities_into():
    kin = DifferentialDriveKinematics(0.6)
    wheels = DifferentialDriveWheelVelocities(1.0, 2.5)
    out = ChassisVelocities()

    def loop(it):
        for _ in it:
            kin.toChassisVelocitiesInto(wheels, out)

    assert_no_allocations(loop, "DifferentialDriveKinematics.toChassisVelocitiesInto")


def test_differential_desaturate_in_place():
    w = DifferentialDriveWheelVelocities()

    def loop(it):
        for _ in it:
            w.left = -6.0
            w.right = 3.0
            w.desaturateInPlace(4.0)

    assert_no_allocations(loop, "DifferentialDriveWheelVelocities.desaturateInPlace")
    assert (w.left, w.right) == (-4.0, 2.0)


# ---------------------------------------------------------------------------------------
# Odometry: `pose = odo.update(...)` in a loop (two alternating readings, so every call
# integrates a non-zero twist)

SWERVE_LAYOUTS = {
    2: [(0.3, 0.0), (-0.3, 0.0)],
    4: [(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)],
    6: [(0.4, 0.3), (0.4, -0.3), (0.0, 0.35), (0.0, -0.35), (-0.4, 0.3), (-0.4, -0.3)],
}


def swerve_odometry(n):
    kin = SwerveDriveKinematics(*[Translation2d(x, y) for x, y in SWERVE_LAYOUTS[n]])
    start = [SwerveModulePosition(0.0, Rotation2d(0.0)) for _ in range(n)]
    return SwerveDriveOdometry(kin, Rotation2d(0.0), start, Pose2d(1.0, 2.0, Rotation2d(0.5)))


@pytest.mark.parametrize("n", sorted(SWERVE_LAYOUTS))
def test_swerve_odometry_update_objects(n):
    odo = swerve_odometry(n)
    pa = [SwerveModulePosition(0.01 * i, Rotation2d(0.1 * i)) for i in range(n)]
    pb = [SwerveModulePosition(0.02 * i + 0.01, Rotation2d(-0.1 * i)) for i in range(n)]
    ga, gb = Rotation2d(0.01), Rotation2d(-0.02)

    def loop(it):
        for _ in it:
            pose = odo.update(ga, pa)
            pose = odo.update(gb, pb)           # noqa: F841 - the pattern under test

    assert_no_allocations(loop, f"SwerveDriveOdometry.update({n} objects)")


@pytest.mark.parametrize("n", sorted(SWERVE_LAYOUTS))
def test_swerve_odometry_update_array(n):
    odo = swerve_odometry(n)
    aa = np.array([[0.01 * i, 0.1 * i] for i in range(n)], dtype=np.float64)
    ab = np.array([[0.02 * i + 0.01, -0.1 * i] for i in range(n)], dtype=np.float64)
    ga, gb = Rotation2d(0.01), Rotation2d(-0.02)

    def loop(it):
        for _ in it:
            pose = odo.update(ga, aa)
            pose = odo.update(gb, ab)           # noqa: F841

    assert_no_allocations(loop, f"SwerveDriveOdometry.update(({n}, 2) array)")


def mecanum_odometry():
    return MecanumDriveOdometry(MecanumDriveKinematics(*MECANUM_LAYOUT), Rotation2d(0.0),
                                MecanumDriveWheelPositions(), Pose2d(1.0, 2.0, Rotation2d(0.5)))


def test_mecanum_odometry_update():
    odo = mecanum_odometry()
    pa = MecanumDriveWheelPositions(0.01, 0.02, 0.03, 0.04)
    pb = MecanumDriveWheelPositions(-0.01, 0.05, 0.0, 0.02)
    ga, gb = Rotation2d(0.01), Rotation2d(-0.02)

    def loop(it):
        for _ in it:
            pose = odo.update(ga, pa)
            pose = odo.update(gb, pb)           # noqa: F841

    assert_no_allocations(loop, "MecanumDriveOdometry.update")


def differential_odometry():
    return DifferentialDriveOdometry(Rotation2d(0.0), 0.0, 0.0, Pose2d(1.0, 2.0, Rotation2d(0.5)))


def test_differential_odometry_update():
    odo = differential_odometry()
    ga, gb = Rotation2d(0.01), Rotation2d(-0.02)

    def loop(it):
        for _ in it:
            pose = odo.update(ga, 0.01, 0.02)
            pose = odo.update(gb, -0.01, 0.03)  # noqa: F841

    assert_no_allocations(loop, "DifferentialDriveOdometry.update")


# ---------------------------------------------------------------------------------------
# A 50 Hz loop that only reads the pose: every odometry class and estimator of the catalog


def _catalogued():
    # (factory, the method that returns its pose) for every odometry and estimator class.
    return [pytest.param(e.example, getter, id=f"{e.kind}-{e.drivetrain}")
            for kind, getter in (("odometry", "getPose"), ("estimator", "getEstimatedPosition"))
            for e in catalog.entries(kind)]


@pytest.mark.parametrize("make, getter", _catalogued())
def test_reading_the_pose(make, getter):
    read = getattr(make(), getter)

    def loop(it):
        for _ in it:
            pose = read()
            x = pose.getX()
            y = pose.getY()
            heading = pose.getRotation().getRadians()
            c = pose.getRotation().getCos()
            t = pose.getTranslation().getNorm()   # noqa: F841
            del x, y, heading, c

    assert_no_allocations(loop, f"reading {getter}()")
