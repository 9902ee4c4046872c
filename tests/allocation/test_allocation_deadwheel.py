"""Allocation tests for the dead-wheel hot paths (DeadWheelKinematics, DeadWheelOdometry,
TwoDeadWheelOdometry), in the style of ``test_allocation_drivetrains.py``.

After a warm-up, 10 000 iterations of each loop body must make no allocator calls at all:
tracemalloc's peak and traced size and ``gc.get_count()[0]`` unchanged, and zero
malloc/calloc/realloc calls counted by ``drivekin._core.alloccount.AllocationCounter`` (harness:
``tests/_support/alloc.py``). Readings are passed as the list of floats a robot loop would build
once and refill, or as a float64 array (contiguous and strided); ``pose = odo.update(...)``
and ``toTwist2d`` return objects from drivekin's freelists, which are not allocator calls.
Each loop alternates two readings so every call integrates (or solves) something new.
The loop that only reads the pose runs on every catalogued odometry class, these two
included, in ``test_allocation_drivetrains.py``.
"""
from __future__ import annotations

import numpy as np
import pytest

from tests._support.alloc import assert_no_allocations
from drivekin import (
    ChassisVelocities,
    DeadWheelKinematics,
    DeadWheelOdometry,
    Pose2d,
    Rotation2d,
    TwoDeadWheelOdometry,
)

# Three wheels that observe rotation (asymmetric, so no term vanishes), and Road Runner's
# two-wheel layout for the gyro-only path.
THREE = [Pose2d(0.0, 0.18, Rotation2d(0.0)), Pose2d(0.02, -0.16, Rotation2d(0.0)),
         Pose2d(-0.1, 0.01, Rotation2d.fromDegrees(90.0))]
FOUR = THREE + [Pose2d(0.12, 0.05, Rotation2d(2.0))]
START = Pose2d(1.0, 2.0, Rotation2d(0.5))


# A gyro value goes through the same path as None plus one float conversion; an earlier
# version built its error-message prefix on every call (one str allocation per call).
GYRO_RATE = pytest.param(0.3, id="gyro")


def three():
    return DeadWheelKinematics(THREE)


def readings(n, scale):
    return [scale * (i + 1) - 0.01 * i * i for i in range(n)]


FORMS = {
    "list": lambda v: list(v),
    "tuple": lambda v: tuple(v),
    "array": lambda v: np.array(v, dtype=np.float64),
    "strided array": lambda v: np.repeat(np.array(v, dtype=np.float64), 2)[::2],
}


# ---------------------------------------------------------------------------------------
# DeadWheelOdometry.update


@pytest.mark.parametrize("form", sorted(FORMS))
@pytest.mark.parametrize("layout", [THREE, FOUR], ids=["3 wheels", "4 wheels"])
def test_dead_wheel_odometry_update_without_gyro(form, layout):
    n = len(layout)
    odo = DeadWheelOdometry(DeadWheelKinematics(layout), [0.0] * n, None, START)
    pa, pb = FORMS[form](readings(n, 0.01)), FORMS[form](readings(n, -0.02))

    def loop(it):
        for _ in it:
            pose = odo.update(pa)
            pose = odo.update(pb)               # noqa: F841 - the pattern under test

    assert_no_allocations(loop, f"DeadWheelOdometry.update({form}, no gyro)")


@pytest.mark.parametrize("form", sorted(FORMS))
@pytest.mark.parametrize("layout", [THREE[::2], THREE], ids=["2 wheels", "3 wheels"])
def test_dead_wheel_odometry_update_with_gyro(form, layout):
    n = len(layout)
    odo = DeadWheelOdometry(DeadWheelKinematics(layout), [0.0] * n, Rotation2d(0.0), START)
    pa, pb = FORMS[form](readings(n, 0.01)), FORMS[form](readings(n, -0.02))
    ga, gb = Rotation2d(0.01), Rotation2d(-0.02)

    def loop(it):
        for _ in it:
            pose = odo.update(pa, ga)
            pose = odo.update(pb, gb)           # noqa: F841

    assert_no_allocations(loop, f"DeadWheelOdometry.update({form}, gyro)")


def test_dead_wheel_odometry_update_refilled_list():
    """The robot-loop pattern: one list, refilled in place from the encoders."""
    odo = DeadWheelOdometry(three(), [0.0, 0.0, 0.0], Rotation2d(0.0), START)
    wheels = [0.0, 0.0, 0.0]
    ga, gb = Rotation2d(0.01), Rotation2d(-0.02)
    a, b = 0.015, -0.0125                       # module-level constants: no new floats

    def loop(it):
        for _ in it:
            wheels[0] = a
            wheels[2] = b
            pose = odo.update(wheels, ga)
            wheels[0] = b
            wheels[2] = a
            pose = odo.update(wheels, gb)       # noqa: F841

    assert_no_allocations(loop, "DeadWheelOdometry.update(refilled list)")


def test_dead_wheel_odometry_reset_position():
    odo = DeadWheelOdometry(three(), [0.0, 0.0, 0.0], Rotation2d(0.0), START)
    pa = np.array(readings(3, 0.01))
    ga = Rotation2d(0.01)

    def loop(it):
        for _ in it:
            odo.resetPosition(pa, ga, START)

    assert_no_allocations(loop, "DeadWheelOdometry.resetPosition")


# ---------------------------------------------------------------------------------------
# TwoDeadWheelOdometry.update


def test_two_dead_wheel_odometry_update():
    odo = TwoDeadWheelOdometry(0.1, -0.15, 0.0, 0.0, Rotation2d(0.0), START)
    ga, gb = Rotation2d(0.01), Rotation2d(-0.02)

    def loop(it):
        for _ in it:
            pose = odo.update(0.01, 0.02, ga)
            pose = odo.update(-0.01, 0.03, gb)  # noqa: F841

    assert_no_allocations(loop, "TwoDeadWheelOdometry.update")


# ---------------------------------------------------------------------------------------
# DeadWheelKinematics


@pytest.mark.parametrize("form", sorted(FORMS))
@pytest.mark.parametrize("gyro", [pytest.param(None, id="no gyro"), GYRO_RATE])
def test_to_chassis_velocities_into(form, gyro):
    kin = three()
    va, vb = FORMS[form](readings(3, 0.5)), FORMS[form](readings(3, -1.5))
    out = ChassisVelocities()

    def loop(it):
        for _ in it:
            kin.toChassisVelocitiesInto(va, out, gyro)
            kin.toChassisVelocitiesInto(vb, out, gyro)

    assert_no_allocations(loop, f"DeadWheelKinematics.toChassisVelocitiesInto({form}, {gyro})")


def test_to_chassis_velocities_into_two_wheels_with_gyro():
    kin = DeadWheelKinematics.fromRoadRunnerTwoWheel(-2000.0, -1500.0, 0.002)
    va, vb = [0.5, -0.25], [1.0, 0.75]
    out = ChassisVelocities()

    def loop(it):
        for _ in it:
            kin.toChassisVelocitiesInto(va, out, 0.3)
            kin.toChassisVelocitiesInto(vb, out, -0.2)

    assert_no_allocations(loop, "DeadWheelKinematics.toChassisVelocitiesInto(2 wheels, gyro)")


@pytest.mark.parametrize("n", [3, 4])
def test_to_wheel_velocities_into(n):
    kin = DeadWheelKinematics(FOUR[:n])
    ca, cb = ChassisVelocities(1.0, -0.5, 2.0), ChassisVelocities(-0.3, 0.2, -1.0)
    out = np.zeros(n)

    def loop(it):
        for _ in it:
            kin.toWheelVelocitiesInto(ca, out)
            kin.toWheelVelocitiesInto(cb, out)

    assert_no_allocations(loop, "DeadWheelKinematics.toWheelVelocitiesInto")


@pytest.mark.parametrize("form", sorted(FORMS))
@pytest.mark.parametrize("gyro", [pytest.param(None, id="no gyro"), GYRO_RATE])
def test_to_twist2d(form, gyro):
    kin = three()
    da, db = FORMS[form](readings(3, 0.01)), FORMS[form](readings(3, -0.02))

    def loop(it):
        for _ in it:
            t = kin.toTwist2d(da, gyro)
            t = kin.toTwist2d(db, gyro)         # noqa: F841

    assert_no_allocations(loop, f"DeadWheelKinematics.toTwist2d({form}, {gyro})")
