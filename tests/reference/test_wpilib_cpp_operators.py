"""WPILib C++'s operators that robotpy 2027 binds and Java lacks (Twist2d ``*``,
SwerveModuleAcceleration ``+ - * /`` and unary ``-``, the wheel accelerations' defaulted
``==``), against the C++ definitions
(allwpilib wpimath/src/main/native/include/wpi/math/kinematics/SwerveModuleAcceleration.hpp
and geometry/Twist2d.hpp) written out here with math's functions."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, strategies as st

from drivekin import (DifferentialDriveWheelAccelerations, MecanumDriveWheelAccelerations,
                      Rotation2d, SwerveModuleAcceleration, Twist2d)

finite = st.floats(-1e3, 1e3, allow_nan=False)
angles = st.floats(-10.0, 10.0, allow_nan=False)


def _cpp_sum(a_m, a_t, b_m, b_c, b_s):
    x = a_m * math.cos(a_t) + b_m * b_c
    y = a_m * math.sin(a_t) + b_m * b_s
    n = math.hypot(x, y)
    return n, (x / n, y / n) if n > 1e-6 else (1.0, 0.0)


def _close(got, m, cs):
    assert got.acceleration == pytest.approx(m, rel=1e-12, abs=1e-12)
    assert got.angle.getCos() == pytest.approx(cs[0], abs=1e-12)
    assert got.angle.getSin() == pytest.approx(cs[1], abs=1e-12)


@given(finite, angles, finite, angles)
def test_sum_and_difference_are_cartesian(am, at, bm, bt):
    a, b = SwerveModuleAcceleration(am, Rotation2d(at)), SwerveModuleAcceleration(bm, Rotation2d(bt))
    m, cs = _cpp_sum(am, at, bm, math.cos(bt), math.sin(bt))
    _close(a + b, m, cs)
    # a - b = a + (-b), and -b turns b's angle by 180°.
    m, cs = _cpp_sum(am, at, bm, math.cos(bt + math.pi), math.sin(bt + math.pi))
    _close(a - b, m, cs)
    assert (a.acceleration, a.angle) == (am, Rotation2d(at))      # operands unchanged


@given(finite, angles, st.floats(-1e3, 1e3, allow_nan=False))
def test_scaling_turns_the_angle_for_a_negative_factor(am, at, k):
    a = SwerveModuleAcceleration(am, Rotation2d(at))
    turn = math.pi if k < 0 else 0.0
    _close(a * k, abs(k) * am if k < 0 else k * am,
           (math.cos(at + turn), math.sin(at + turn)))
    if k != 0:
        q = 1.0 / k
        _close(a / k, -q * am if q < 0 else q * am,
               (math.cos(at + (math.pi if q < 0 else 0.0)),
                math.sin(at + (math.pi if q < 0 else 0.0))))
    n = -a
    _close(n, am, (math.cos(at + math.pi), math.sin(at + math.pi)))


def test_opposite_accelerations_cancel_to_zero_at_the_identity_angle():
    a = SwerveModuleAcceleration(2.0, Rotation2d(0.3))
    z = a - a
    assert z.acceleration == pytest.approx(0.0, abs=1e-15)
    assert (z.angle.getCos(), z.angle.getSin()) == (1.0, 0.0)


@given(finite, finite, finite, st.floats(-1e3, 1e3, allow_nan=False))
def test_twist_times_a_factor_scales_each_component(dx, dy, dtheta, k):
    for t in (Twist2d(dx, dy, dtheta) * k, k * Twist2d(dx, dy, dtheta)):
        assert (t.dx, t.dy, t.dtheta) == (dx * k, dy * k, dtheta * k)


def test_operands_of_other_types_are_refused():
    a = SwerveModuleAcceleration(1.0, Rotation2d())
    for bad in ("2", None, Rotation2d()):
        with pytest.raises(TypeError):
            a * bad
        with pytest.raises(TypeError):
            a + bad
        with pytest.raises(TypeError):
            Twist2d() * bad


@pytest.mark.parametrize("cls, n", [(MecanumDriveWheelAccelerations, 4),
                                    (DifferentialDriveWheelAccelerations, 2)])
def test_wheel_accelerations_compare_every_wheel_exactly(cls, n):
    # C++ ``operator==(...) const = default``: field by field, IEEE equality.
    values = [1.5, -2.0, 0.25, 3.0][:n]
    assert cls(*values) == cls(*values)
    assert cls(*values) is not cls(*values)
    assert cls(*([0.0] * n)) == cls(*([-0.0] * n))
    for i in range(n):
        other = list(values)
        other[i] = math.nextafter(other[i], math.inf)
        assert cls(*values) != cls(*other)
    nan = [math.nan] * n
    assert cls(*nan) != cls(*nan)
    with pytest.raises(TypeError):
        hash(cls(*values))
