"""Allocation tests for the differential swerve hot paths (drivekin.diffswerve).

After a warm-up, 10 000 iterations of each loop body must make no allocator calls at all:
traced peak, traced size and ``gc.get_count()[0]`` unchanged, and zero
malloc/calloc/realloc calls counted by ``drivekin._core.alloccount`` (harness: tests/_support/alloc.py).
The object-returning façades are included: their results come from drivekin's freelists
(and the drive-level factor from CPython's float freelist), so they are allocation-free too.
"""
from __future__ import annotations

import numpy as np
import pytest

from tests._support.alloc import assert_no_allocations
from drivekin import (
    DifferentialSwerveModuleKinematics,
    DifferentialSwerveModuleVelocities,
    DifferentialSwerveMotorVelocities,
    Rotation2d,
    SwerveModulePosition,
    SwerveModuleVelocity,
)


@pytest.fixture(params=[False, True], ids=["motor2-normal", "motor2-inverted"])
def kin(request):
    k = DifferentialSwerveModuleKinematics(3.0, 5.0, 0.05, motor2_inverted=request.param)
    k.resetModulePosition(Rotation2d(0.4), 12.0, -7.0)
    return k


def test_to_motor_velocities_into(kin):
    out = DifferentialSwerveMotorVelocities()

    def loop(it):
        for _ in it:
            kin.toMotorVelocitiesInto(1.5, -2.0, out)

    assert_no_allocations(loop, "toMotorVelocitiesInto")
    assert tuple(out) == tuple(kin.toMotorVelocities(1.5, -2.0))


def test_to_module_velocities_into(kin):
    out = DifferentialSwerveModuleVelocities()

    def loop(it):
        for _ in it:
            kin.toModuleVelocitiesInto(120.0, -80.0, out)

    assert_no_allocations(loop, "toModuleVelocitiesInto")


def test_to_module_position_into(kin):
    out = SwerveModulePosition()

    def loop(it):
        for _ in it:
            kin.toModulePositionInto(30.0, -25.0, out)

    assert_no_allocations(loop, "toModulePositionInto")
    assert out == kin.toModulePosition(30.0, -25.0)


def test_facades_draw_from_freelists(kin):
    def loop(it):
        for _ in it:
            m = kin.toMotorVelocities(1.5, -2.0)
            v = kin.toModuleVelocities(m.motor1, m.motor2)
            p = kin.toModulePosition(30.0, -25.0)
            d = kin.desaturateMotorVelocities(m, 100.0)
            del v, p, d

    assert_no_allocations(loop, "diffswerve façades")


@pytest.mark.parametrize("proportional", [False, True])
def test_desaturate_motor_velocities_in_place(kin, proportional):
    m = DifferentialSwerveMotorVelocities()

    def loop(it):
        for _ in it:
            m.motor1 = 280.0                     # over the limit every time
            m.motor2 = -220.0
            kin.desaturateMotorVelocitiesInPlace(m, 200.0, proportional=proportional)

    assert_no_allocations(loop, f"desaturateMotorVelocitiesInPlace(proportional={proportional})")
    assert max(abs(m.motor1), abs(m.motor2)) == 200.0


def _states():
    return [SwerveModuleVelocity(3.0 + 0.1 * i, Rotation2d(0.3 * i)) for i in range(4)]


RATES = [1.0, -2.0, 4.0, 0.5]


@pytest.mark.parametrize("modules, rates", [("objects", "list"), ("objects", "array"),
                                            ("array", "array"), ("array", "tuple")])
def test_drive_level_desaturation(kin, modules, rates):
    objs = _states()
    arr = np.array([[s.velocity, s.angle.getRadians()] for s in objs])
    target = objs if modules == "objects" else arr
    r = {"list": list(RATES), "tuple": tuple(RATES), "array": np.array(RATES)}[rates]

    def loop(it):
        for _ in it:
            # Reset the speeds so that every call finds them saturated and rescales.
            if modules == "objects":
                objs[0].velocity = 3.0
                objs[1].velocity = 3.1
                objs[2].velocity = 3.2
                objs[3].velocity = 3.3
            else:
                arr[0, 0] = 3.0
                arr[1, 0] = 3.1
                arr[2, 0] = 3.2
                arr[3, 0] = 3.3
            kin.desaturateModuleVelocitiesInPlace(target, r, 150.0)

    assert_no_allocations(loop, f"desaturateModuleVelocitiesInPlace({modules}, {rates})")
    first = objs[0].velocity if modules == "objects" else arr[0, 0]
    assert first < 3.0                                     # it did rescale
