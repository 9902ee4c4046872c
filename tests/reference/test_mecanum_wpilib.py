"""WPILib 2027 mecanum unit tests (MecanumDriveKinematics including the acceleration tests,
MecanumDriveWheelVelocities, MecanumDriveWheelAccelerations), restated for drivekin, plus the
digest's mecanum edge cases (/work/shared/reference/wpilib-kinematics.md, sections 2, 7 and 13).

Source of the ported cases: wpilibsuite/allwpilib main @ caf0fb2d,
wpimath/src/test/java/org/wpilib/math/kinematics/{MecanumDriveKinematics,
MecanumDriveWheelVelocities,MecanumDriveWheelAccelerations}Test.java. There is no
MecanumDriveWheelPositionsTest on the 2027 branch (neither Java nor C++); positions are covered
by the edge-case section below. The C++ tests under wpimath/src/test/native/cpp/kinematics/
hold the same cases. Tolerances are WPILib's own: kEpsilon = 1e-9, 0.1 where the WPILib test
uses 0.1, and exact equality where JUnit's assertEquals(double, double) has no delta.

Not ported: ``MecanumDriveWheelAccelerationsTest.testMeasureConstructor`` (units-library
constructor, not in drivekin's API).

Closed forms used by the edge cases. For a wheel at (x, y) relative to the centre of rotation
the inverse rows are FL/RR [1, -1, -(x + y)] and FR/RL [1, 1, x - y]. For the (+-12, +-12)
layout the three columns of that matrix (built at CoR (0, 0)) are orthogonal, so its
pseudo-inverse is exact: vx = (fl + fr + rl + rr) / 4, vy = (-fl + fr + rl - rr) / 4,
omega = (-fl + fr - rl + rr) / 96.
"""
import math

import pytest

from drivekin import (
    ChassisAccelerations,
    ChassisVelocities,
    DifferentialDriveWheelPositions,
    MecanumDriveKinematics,
    MecanumDriveWheelAccelerations,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
    Translation2d,
)
from tests._support.wpilib_port import BL, BR, EPS, FL, FR, WHEELS, assert_close


def assert_wheels(expected, wheels, tol=EPS):
    assert_close(expected[0], wheels.frontLeft, tol)
    assert_close(expected[1], wheels.frontRight, tol)
    assert_close(expected[2], wheels.rearLeft, tol)
    assert_close(expected[3], wheels.rearRight, tol)


def wheel_values(w):
    return (w.frontLeft, w.frontRight, w.rearLeft, w.rearRight)


def inverse_closed_form(vx, vy, omega, cor=(0.0, 0.0), wheels=WHEELS):
    """Wheel velocities from the inverse rows, with (x, y) = wheel - CoR."""
    out = []
    for i, w in enumerate(wheels):
        x = w.getX() - cor[0]
        y = w.getY() - cor[1]
        if i in (0, 3):  # front left, rear right
            out.append(vx - vy - omega * (x + y))
        else:            # front right, rear left
            out.append(vx + vy + omega * (x - y))
    return out


def forward_closed_form(fl, fr, rl, rr):
    """Exact pseudo-inverse of the CoR-(0, 0) matrix for the (+-12, +-12) layout."""
    return ((fl + fr + rl + rr) / 4.0, (-fl + fr + rl - rr) / 4.0, (-fl + fr - rl + rr) / 96.0)


@pytest.fixture
def kinematics():
    # JUnit builds a fresh test-class instance (and so a fresh kinematics) per test.
    return MecanumDriveKinematics(FL, FR, BL, BR)


# =========================================================================================
# Ported: MecanumDriveKinematicsTest
# =========================================================================================
class TestMecanumDriveKinematics:
    def test_straight_line_inverse_kinematics(self, kinematics):
        wheels = kinematics.toWheelVelocities(ChassisVelocities(5, 0, 0))
        assert_wheels((5.0, 5.0, 5.0, 5.0), wheels, 0.1)

    def test_straight_line_forward_kinematics_kinematics(self, kinematics):
        cv = kinematics.toChassisVelocities(
            MecanumDriveWheelVelocities(3.536, 3.536, 3.536, 3.536))
        assert_close(3.536, cv.vx, 0.1)
        assert_close(0.0, cv.vy, 0.1)
        assert_close(0.0, cv.omega, 0.1)

    def test_straight_line_forward_kinematics_kinematics_with_deltas(self, kinematics):
        twist = kinematics.toTwist2d(MecanumDriveWheelPositions(3.536, 3.536, 3.536, 3.536))
        assert_close(3.536, twist.dx, 0.1)
        assert_close(0.0, twist.dy, 0.1)
        assert_close(0.0, twist.dtheta, 0.1)

    def test_strafe_inverse_kinematics(self, kinematics):
        wheels = kinematics.toWheelVelocities(ChassisVelocities(0, 4, 0))
        assert_wheels((-4.0, 4.0, 4.0, -4.0), wheels, 0.1)

    def test_strafe_forward_kinematics_kinematics(self, kinematics):
        cv = kinematics.toChassisVelocities(
            MecanumDriveWheelVelocities(-2.828427, 2.828427, 2.828427, -2.828427))
        assert_close(0.0, cv.vx, 0.1)
        assert_close(2.8284, cv.vy, 0.1)
        assert_close(0.0, cv.omega, 0.1)

    def test_strafe_forward_kinematics_kinematics_with_deltas(self, kinematics):
        twist = kinematics.toTwist2d(
            MecanumDriveWheelPositions(-2.828427, 2.828427, 2.828427, -2.828427))
        assert_close(0.0, twist.dx, 0.1)
        assert_close(2.8284, twist.dy, 0.1)
        assert_close(0.0, twist.dtheta, 0.1)

    def test_rotation_inverse_kinematics(self, kinematics):
        wheels = kinematics.toWheelVelocities(ChassisVelocities(0, 0, 2 * math.pi))
        assert_wheels((-150.79645, 150.79645, -150.79645, 150.79645), wheels, 0.1)

    def test_rotation_forward_kinematics_kinematics(self, kinematics):
        cv = kinematics.toChassisVelocities(
            MecanumDriveWheelVelocities(-150.79645, 150.79645, -150.79645, 150.79645))
        assert_close(0.0, cv.vx, 0.1)
        assert_close(0.0, cv.vy, 0.1)
        assert_close(2 * math.pi, cv.omega, 0.1)

    def test_rotation_forward_kinematics_kinematics_with_deltas(self, kinematics):
        twist = kinematics.toTwist2d(
            MecanumDriveWheelPositions(-150.79645, 150.79645, -150.79645, 150.79645))
        assert_close(0.0, twist.dx, 0.1)
        assert_close(0.0, twist.dy, 0.1)
        assert_close(2 * math.pi, twist.dtheta, 0.1)

    def test_mixed_translation_rotation_inverse_kinematics(self, kinematics):
        wheels = kinematics.toWheelVelocities(ChassisVelocities(2, 3, 1))
        assert_wheels((-25.0, 29.0, -19.0, 23.0), wheels, 0.1)

    def test_mixed_translation_rotation_forward_kinematics_kinematics(self, kinematics):
        cv = kinematics.toChassisVelocities(
            MecanumDriveWheelVelocities(-17.677670, 20.51, -13.44, 16.26))
        assert_close(1.413, cv.vx, 0.1)
        assert_close(2.122, cv.vy, 0.1)
        assert_close(0.707, cv.omega, 0.1)

    def test_mixed_translation_rotation_forward_kinematics_kinematics_with_deltas(
            self, kinematics):
        twist = kinematics.toTwist2d(
            MecanumDriveWheelPositions(-17.677670, 20.51, -13.44, 16.26))
        assert_close(1.413, twist.dx, 0.1)
        assert_close(2.122, twist.dy, 0.1)
        assert_close(0.707, twist.dtheta, 0.1)

    def test_off_center_rotation_inverse_kinematics(self, kinematics):
        wheels = kinematics.toWheelVelocities(ChassisVelocities(0, 0, 1), FL)
        assert_wheels((0.0, 24.0, -24.0, 48.0), wheels, 0.1)

    def test_straight_line_inverse_accelerations(self, kinematics):
        wheels = kinematics.toWheelAccelerations(ChassisAccelerations(5, 0, 0))
        assert_wheels((5.0, 5.0, 5.0, 5.0), wheels, 0.1)

    def test_straight_line_forward_accelerations(self, kinematics):
        ca = kinematics.toChassisAccelerations(
            MecanumDriveWheelAccelerations(3.536, 3.536, 3.536, 3.536))
        assert_close(3.536, ca.ax, 0.1)
        assert_close(0.0, ca.ay, 0.1)
        assert_close(0.0, ca.alpha, 0.1)

    def test_strafe_inverse_accelerations(self, kinematics):
        wheels = kinematics.toWheelAccelerations(ChassisAccelerations(0, 4, 0))
        assert_wheels((-4.0, 4.0, 4.0, -4.0), wheels, 0.1)

    def test_strafe_forward_accelerations(self, kinematics):
        ca = kinematics.toChassisAccelerations(
            MecanumDriveWheelAccelerations(-2.828427, 2.828427, 2.828427, -2.828427))
        assert_close(0.0, ca.ax, 0.1)
        assert_close(2.8284, ca.ay, 0.1)
        assert_close(0.0, ca.alpha, 0.1)

    def test_rotation_inverse_accelerations(self, kinematics):
        wheels = kinematics.toWheelAccelerations(ChassisAccelerations(0, 0, 2 * math.pi))
        assert_wheels((-150.79645, 150.79645, -150.79645, 150.79645), wheels, 0.1)

    def test_rotation_forward_accelerations(self, kinematics):
        ca = kinematics.toChassisAccelerations(
            MecanumDriveWheelAccelerations(-150.79645, 150.79645, -150.79645, 150.79645))
        assert_close(0.0, ca.ax, 0.1)
        assert_close(0.0, ca.ay, 0.1)
        assert_close(2 * math.pi, ca.alpha, 0.1)

    def test_mixed_translation_rotation_inverse_accelerations(self, kinematics):
        wheels = kinematics.toWheelAccelerations(ChassisAccelerations(2, 3, 1))
        assert_wheels((-25.0, 29.0, -19.0, 23.0), wheels, 0.1)

    def test_mixed_translation_rotation_forward_accelerations(self, kinematics):
        ca = kinematics.toChassisAccelerations(
            MecanumDriveWheelAccelerations(-17.677670, 20.51, -13.44, 16.26))
        assert_close(1.413, ca.ax, 0.1)
        assert_close(2.122, ca.ay, 0.1)
        assert_close(0.707, ca.alpha, 0.1)

    def test_off_center_rotation_inverse_accelerations(self, kinematics):
        wheels = kinematics.toWheelAccelerations(ChassisAccelerations(0, 0, 1), FL)
        assert_wheels((0.0, 24.0, -24.0, 48.0), wheels, 0.1)

    def test_off_center_rotation_forward_kinematics_kinematics(self, kinematics):
        cv = kinematics.toChassisVelocities(
            MecanumDriveWheelVelocities(0, 16.971, -16.971, 33.941))
        assert_close(8.48525, cv.vx, 0.1)
        assert_close(-8.48525, cv.vy, 0.1)
        assert_close(0.707, cv.omega, 0.1)

    def test_off_center_rotation_forward_kinematics_kinematics_with_deltas(self, kinematics):
        twist = kinematics.toTwist2d(MecanumDriveWheelPositions(0, 16.971, -16.971, 33.941))
        assert_close(8.48525, twist.dx, 0.1)
        assert_close(-8.48525, twist.dy, 0.1)
        assert_close(0.707, twist.dtheta, 0.1)

    def test_off_center_translation_rotation_inverse_kinematics(self, kinematics):
        wheels = kinematics.toWheelVelocities(ChassisVelocities(5, 2, 1), FL)
        assert_wheels((3.0, 31.0, -17.0, 51.0), wheels, 0.1)

    def test_off_center_rotation_translation_forward_kinematics_kinematics(self, kinematics):
        cv = kinematics.toChassisVelocities(
            MecanumDriveWheelVelocities(2.12, 21.92, -12.02, 36.06))
        assert_close(12.02, cv.vx, 0.1)
        assert_close(-7.07, cv.vy, 0.1)
        assert_close(0.707, cv.omega, 0.1)

    def test_off_center_rotation_translation_forward_kinematics_kinematics_with_deltas(
            self, kinematics):
        twist = kinematics.toTwist2d(MecanumDriveWheelPositions(2.12, 21.92, -12.02, 36.06))
        assert_close(12.02, twist.dx, 0.1)
        assert_close(-7.07, twist.dy, 0.1)
        assert_close(0.707, twist.dtheta, 0.1)

    def test_desaturate(self):
        wheels = MecanumDriveWheelVelocities(5, 6, 4, 7).desaturate(5.5)
        factor = 5.5 / 7.0
        assert_wheels((5.0 * factor, 6.0 * factor, 4.0 * factor, 7.0 * factor), wheels)

    def test_desaturate_negative_velocities(self):
        wheels = MecanumDriveWheelVelocities(-5, 6, 4, -7).desaturate(5.5)
        k_factor = 5.5 / 7.0
        assert_wheels((-5.0 * k_factor, 6.0 * k_factor, 4.0 * k_factor, -7.0 * k_factor),
                      wheels)


# =========================================================================================
# Ported: MecanumDriveWheelVelocitiesTest
# =========================================================================================
class TestMecanumDriveWheelVelocities:
    def test_plus(self):
        left = MecanumDriveWheelVelocities(1.0, 0.5, 2.0, 1.5)
        right = MecanumDriveWheelVelocities(2.0, 1.5, 0.5, 1.0)
        assert wheel_values(left.plus(right)) == (3.0, 2.0, 2.5, 2.5)

    def test_minus(self):
        left = MecanumDriveWheelVelocities(1.0, 0.5, 2.0, 1.5)
        right = MecanumDriveWheelVelocities(2.0, 0.5, 0.5, 1.0)
        assert wheel_values(left.minus(right)) == (-1.0, 0.0, 1.5, 0.5)

    def test_unary_minus(self):
        wheels = MecanumDriveWheelVelocities(1.0, 0.5, 2.0, 1.5).unaryMinus()
        assert wheel_values(wheels) == (-1.0, -0.5, -2.0, -1.5)

    def test_multiplication(self):
        wheels = MecanumDriveWheelVelocities(1.0, 0.5, 2.0, 1.5).times(2.0)
        assert wheel_values(wheels) == (2.0, 1.0, 4.0, 3.0)

    def test_division(self):
        wheels = MecanumDriveWheelVelocities(1.0, 0.5, 2.0, 1.5).div(2.0)
        assert wheel_values(wheels) == (0.5, 0.25, 1.0, 0.75)

    def test_interpolate(self):
        start = MecanumDriveWheelVelocities(1.0, 2.0, 3.0, 4.0)
        end = MecanumDriveWheelVelocities(5.0, 6.0, 7.0, 8.0)
        assert_wheels((1.0, 2.0, 3.0, 4.0), start.interpolate(end, 0.0))
        assert_wheels((5.0, 6.0, 7.0, 8.0), start.interpolate(end, 1.0))
        assert_wheels((3.0, 4.0, 5.0, 6.0), start.interpolate(end, 0.5))
        assert_wheels((2.0, 3.0, 4.0, 5.0), start.interpolate(end, 0.25))
        # Clamping: t < 0 -> 0, t > 1 -> 1.
        assert_wheels((1.0, 2.0, 3.0, 4.0), start.interpolate(end, -0.5))
        assert_wheels((5.0, 6.0, 7.0, 8.0), start.interpolate(end, 1.5))


# =========================================================================================
# Ported: MecanumDriveWheelAccelerationsTest
# =========================================================================================
class TestMecanumDriveWheelAccelerations:
    def test_default_constructor(self):
        assert_wheels((0.0, 0.0, 0.0, 0.0), MecanumDriveWheelAccelerations())

    def test_parameterized_constructor(self):
        assert_wheels((1.0, 2.0, 3.0, 4.0), MecanumDriveWheelAccelerations(1.0, 2.0, 3.0, 4.0))

    def test_plus(self):
        left = MecanumDriveWheelAccelerations(1.0, 0.5, 2.0, 1.5)
        right = MecanumDriveWheelAccelerations(2.0, 1.5, 0.5, 1.0)
        assert wheel_values(left.plus(right)) == (3.0, 2.0, 2.5, 2.5)

    def test_minus(self):
        left = MecanumDriveWheelAccelerations(5.0, 4.0, 6.0, 2.5)
        right = MecanumDriveWheelAccelerations(1.0, 2.0, 3.0, 0.5)
        assert wheel_values(left.minus(right)) == (4.0, 2.0, 3.0, 2.0)

    def test_unary_minus(self):
        wheels = MecanumDriveWheelAccelerations(1.0, -2.0, 3.0, -4.0).unaryMinus()
        assert wheel_values(wheels) == (-1.0, 2.0, -3.0, 4.0)

    def test_multiplication(self):
        wheels = MecanumDriveWheelAccelerations(2.0, 2.5, 3.0, 3.5).times(2.0)
        assert wheel_values(wheels) == (4.0, 5.0, 6.0, 7.0)

    def test_division(self):
        wheels = MecanumDriveWheelAccelerations(2.0, 2.5, 1.5, 1.0).div(2.0)
        assert wheel_values(wheels) == (1.0, 1.25, 0.75, 0.5)

    def test_interpolate(self):
        start = MecanumDriveWheelAccelerations(1.0, 2.0, 3.0, 4.0)
        end = MecanumDriveWheelAccelerations(5.0, 6.0, 7.0, 8.0)
        assert_wheels((1.0, 2.0, 3.0, 4.0), start.interpolate(end, 0.0))
        assert_wheels((5.0, 6.0, 7.0, 8.0), start.interpolate(end, 1.0))
        assert_wheels((3.0, 4.0, 5.0, 6.0), start.interpolate(end, 0.5))
        assert_wheels((2.0, 3.0, 4.0, 5.0), start.interpolate(end, 0.25))
        assert_wheels((1.0, 2.0, 3.0, 4.0), start.interpolate(end, -0.5))
        assert_wheels((5.0, 6.0, 7.0, 8.0), start.interpolate(end, 1.5))


# =========================================================================================
# Edge cases from the digest (not in the WPILib tests)
# =========================================================================================
class TestClosedForms:
    """The WPILib tests use 0.1; the same cases at 1e-9 against the closed forms."""

    def test_digest_example_mixed(self, kinematics):
        # Digest section 7.1: (2, 3, 1) -> (-25, 29, -19, 23).
        wheels = kinematics.toWheelVelocities(ChassisVelocities(2, 3, 1))
        assert_wheels((-25.0, 29.0, -19.0, 23.0), wheels)

    def test_digest_example_about_front_left(self, kinematics):
        # Digest section 7.1: (0, 0, 1) about FL -> (0, 24, -24, 48).
        wheels = kinematics.toWheelVelocities(ChassisVelocities(0, 0, 1), FL)
        assert_wheels((0.0, 24.0, -24.0, 48.0), wheels)

    @pytest.mark.parametrize("vx, vy, omega, cor", [
        (5, 0, 0, (0, 0)),
        (0, 4, 0, (0, 0)),
        (0, 0, 2 * math.pi, (0, 0)),
        (5, 2, 1, (12, 12)),
        (-1.5, 0.25, -3.0, (-3.0, 7.5)),
    ])
    def test_inverse_closed_form(self, kinematics, vx, vy, omega, cor):
        wheels = kinematics.toWheelVelocities(ChassisVelocities(vx, vy, omega),
                                              Translation2d(*cor))
        assert_wheels(inverse_closed_form(vx, vy, omega, cor), wheels)
        accels = kinematics.toWheelAccelerations(ChassisAccelerations(vx, vy, omega),
                                                 Translation2d(*cor))
        assert_wheels(inverse_closed_form(vx, vy, omega, cor), accels)

    @pytest.mark.parametrize("w", [
        (3.536, 3.536, 3.536, 3.536),
        (-2.828427, 2.828427, 2.828427, -2.828427),
        (-150.79645, 150.79645, -150.79645, 150.79645),
        (-17.677670, 20.51, -13.44, 16.26),
        (0, 16.971, -16.971, 33.941),
        (2.12, 21.92, -12.02, 36.06),
    ])
    def test_forward_closed_form(self, kinematics, w):
        vx, vy, omega = forward_closed_form(*w)
        cv = kinematics.toChassisVelocities(MecanumDriveWheelVelocities(*w))
        twist = kinematics.toTwist2d(MecanumDriveWheelPositions(*w))
        ca = kinematics.toChassisAccelerations(MecanumDriveWheelAccelerations(*w))
        for got in ((cv.vx, cv.vy, cv.omega), (twist.dx, twist.dy, twist.dtheta),
                    (ca.ax, ca.ay, ca.alpha)):
            assert_close(vx, got[0])
            assert_close(vy, got[1])
            assert_close(omega, got[2])

    def test_to_twist2d_start_end(self, kinematics):
        start = MecanumDriveWheelPositions(1.0, -2.0, 3.0, 0.5)
        end = MecanumDriveWheelPositions(1.0 + 2.12, -2.0 + 21.92, 3.0 - 12.02, 0.5 + 36.06)
        dx, dy, dtheta = forward_closed_form(2.12, 21.92, -12.02, 36.06)
        twist = kinematics.toTwist2d(start, end)
        assert_close(dx, twist.dx)
        assert_close(dy, twist.dy)
        assert_close(dtheta, twist.dtheta)

    def test_no_zero_special_case(self, kinematics):
        # Unlike swerve, mecanum has no heading memory: zero in, zeros out.
        assert_wheels((0.0, 0.0, 0.0, 0.0), kinematics.toWheelVelocities(ChassisVelocities()))


class TestCenterOfRotation:
    def test_forward_matrix_fixed_at_origin(self, kinematics):
        # Spinning at 1 rad/s about FL = (12, 12): the robot centre, at (-12, -12) from the
        # CoR, moves at omega x r = (12, -12). The forward matrix was built for CoR (0, 0)
        # and is never rebuilt, so it reports that centre motion, not (0, 0, 1).
        wheels = kinematics.toWheelVelocities(ChassisVelocities(0, 0, 1), FL)
        cv = kinematics.toChassisVelocities(wheels)
        assert_close(12.0, cv.vx)
        assert_close(-12.0, cv.vy)
        assert_close(1.0, cv.omega)
        deltas = MecanumDriveWheelPositions(*wheel_values(wheels))
        twist = kinematics.toTwist2d(deltas)
        assert_close(12.0, twist.dx)
        assert_close(-12.0, twist.dy)
        assert_close(1.0, twist.dtheta)

    def test_forward_acceleration_matrix_fixed_at_origin(self, kinematics):
        accels = kinematics.toWheelAccelerations(ChassisAccelerations(0, 0, 1), FL)
        assert_wheels((0.0, 24.0, -24.0, 48.0), accels)
        ca = kinematics.toChassisAccelerations(accels)
        assert_close(12.0, ca.ax)
        assert_close(-12.0, ca.ay)
        assert_close(1.0, ca.alpha)

    def test_cor_is_sticky_until_a_different_one_is_passed(self, kinematics):
        kinematics.toWheelVelocities(ChassisVelocities(0, 0, 1), FL)
        # Passing the same CoR again: same matrix.
        assert_wheels((0.0, 24.0, -24.0, 48.0),
                      kinematics.toWheelVelocities(ChassisVelocities(0, 0, 1), FL))
        # The default (origin) is a different CoR: rebuilt for the origin.
        assert_wheels(inverse_closed_form(0, 0, 1),
                      kinematics.toWheelVelocities(ChassisVelocities(0, 0, 1)))

    def test_velocity_and_acceleration_share_the_cor(self, kinematics):
        kinematics.toWheelVelocities(ChassisVelocities(0, 0, 1), FL)
        assert_wheels(inverse_closed_form(0, 0, 1),
                      kinematics.toWheelAccelerations(ChassisAccelerations(0, 0, 1)))
        kinematics.toWheelAccelerations(ChassisAccelerations(0, 0, 1), BR)
        assert_wheels(inverse_closed_form(0, 0, 1, (-12, -12)),
                      kinematics.toWheelVelocities(ChassisVelocities(0, 0, 1), BR))

    def test_cor_change_within_1e_9_does_not_rebuild(self, kinematics):
        # The CoR is compared with Translation2d equality (|dx|, |dy| < 1e-9). With
        # omega = 1000 a 9e-10 shift would change the wheels by ~1.8e-6, so the 1e-9
        # check below distinguishes "kept the (1, 1) matrix" from "rebuilt".
        omega = 1000.0
        cv = ChassisVelocities(0.5, -0.25, omega)
        kinematics.toWheelVelocities(cv, Translation2d(1, 1))
        shifted = (1 + 9e-10, 1 + 9e-10)
        wheels = kinematics.toWheelVelocities(cv, Translation2d(*shifted))
        kept = inverse_closed_form(0.5, -0.25, omega, (1, 1))
        rebuilt = inverse_closed_form(0.5, -0.25, omega, shifted)
        assert_wheels(kept, wheels)
        assert any(abs(a - b) > 1e-6 for a, b in zip(kept, rebuilt))  # the check has teeth
        # A 2e-9 shift is a different CoR: rebuilt.
        cor = (1 + 2e-9, 1 + 2e-9)
        wheels = kinematics.toWheelVelocities(cv, Translation2d(*cor))
        assert_wheels(inverse_closed_form(0.5, -0.25, omega, cor), wheels)

    def test_cor_within_1e_9_of_origin_uses_origin(self, kinematics):
        omega = 1000.0
        wheels = kinematics.toWheelVelocities(ChassisVelocities(0, 0, omega),
                                              Translation2d(9e-10, -9e-10))
        # FR/RL rows use x - y, so the 9e-10/-9e-10 offset would shift them by 1.8e-6.
        assert_wheels(inverse_closed_form(0, 0, omega), wheels)

    def test_cor_per_instance(self, kinematics):
        other = MecanumDriveKinematics(FL, FR, BL, BR)
        kinematics.toWheelVelocities(ChassisVelocities(0, 0, 1), FL)
        assert_wheels(inverse_closed_form(0, 0, 1),
                      other.toWheelVelocities(ChassisVelocities(0, 0, 1), Translation2d()))


class TestKinematicsHelpers:
    def test_getters(self, kinematics):
        assert kinematics.getFrontLeft() == FL
        assert kinematics.getFrontRight() == FR
        assert kinematics.getRearLeft() == BL
        assert kinematics.getRearRight() == BR

    def test_interpolate_is_unclamped(self, kinematics):
        start = MecanumDriveWheelPositions(1.0, 2.0, 3.0, 4.0)
        end = MecanumDriveWheelPositions(5.0, 6.0, 7.0, 8.0)
        assert_wheels((3.0, 4.0, 5.0, 6.0), kinematics.interpolate(start, end, 0.5))
        assert_wheels((7.0, 8.0, 9.0, 10.0), kinematics.interpolate(start, end, 1.5))
        assert_wheels((-1.0, 0.0, 1.0, 2.0), kinematics.interpolate(start, end, -0.5))

    def test_copy_and_copy_into(self, kinematics):
        p = MecanumDriveWheelPositions(1.0, 2.0, 3.0, 4.0)
        c = kinematics.copy(p)
        assert c is not p
        assert c == p
        p.frontLeft = 10.0
        assert c.frontLeft == 1.0
        out = MecanumDriveWheelPositions()
        assert kinematics.copyInto(p, out) is None
        assert wheel_values(out) == (10.0, 2.0, 3.0, 4.0)

    def test_into_forms_match(self, kinematics):
        cv = ChassisVelocities(2, 3, 1)
        out = MecanumDriveWheelVelocities()
        assert kinematics.toWheelVelocitiesInto(cv, out, FL) is None
        assert wheel_values(out) == wheel_values(kinematics.toWheelVelocities(cv, FL))
        back = ChassisVelocities()
        assert kinematics.toChassisVelocitiesInto(out, back) is None
        expected = kinematics.toChassisVelocities(out)
        assert (back.vx, back.vy, back.omega) == (expected.vx, expected.vy, expected.omega)


class TestWheelValueEdgeCases:
    def test_defaults_and_mutable_fields(self):
        for cls in (MecanumDriveWheelVelocities, MecanumDriveWheelPositions,
                    MecanumDriveWheelAccelerations):
            w = cls()
            assert wheel_values(w) == (0.0, 0.0, 0.0, 0.0)
            w.frontLeft, w.frontRight, w.rearLeft, w.rearRight = 1.0, 2.0, 3.0, 4.0
            assert wheel_values(w) == (1.0, 2.0, 3.0, 4.0)

    def test_desaturate_returns_new_object(self):
        # 2027 (#8274): desaturate returns a new object and leaves the receiver alone.
        w = MecanumDriveWheelVelocities(5, 6, 4, 7)
        d = w.desaturate(5.5)
        assert d is not w
        assert type(d) is MecanumDriveWheelVelocities
        assert wheel_values(w) == (5.0, 6.0, 4.0, 7.0)
        factor = 5.5 / 7.0
        assert_wheels((5 * factor, 6 * factor, 4 * factor, 7 * factor), d)

    def test_desaturate_unsaturated_is_unchanged_copy(self):
        w = MecanumDriveWheelVelocities(1, -2, 3, -4)
        d = w.desaturate(4.0)  # max |v| == 4 is not > 4: unchanged
        assert d is not w
        assert wheel_values(d) == (1.0, -2.0, 3.0, -4.0)

    def test_desaturate_in_place_mutates(self):
        w = MecanumDriveWheelVelocities(-5, 6, 4, -7)
        assert w.desaturateInPlace(5.5) is None
        factor = 5.5 / 7.0
        assert_wheels((-5 * factor, 6 * factor, 4 * factor, -7 * factor), w)
        w = MecanumDriveWheelVelocities(1, 2, 3, 4)
        w.desaturateInPlace(10.0)
        assert wheel_values(w) == (1.0, 2.0, 3.0, 4.0)

    def test_accelerations_have_no_desaturate(self):
        assert not hasattr(MecanumDriveWheelAccelerations(), "desaturate")

    def test_positions_interpolate_unclamped(self):
        start = MecanumDriveWheelPositions(1.0, 2.0, 3.0, 4.0)
        end = MecanumDriveWheelPositions(5.0, 6.0, 7.0, 8.0)
        assert_wheels((3.0, 4.0, 5.0, 6.0), start.interpolate(end, 0.5))
        assert_wheels((7.0, 8.0, 9.0, 10.0), start.interpolate(end, 1.5))
        assert_wheels((-1.0, 0.0, 1.0, 2.0), start.interpolate(end, -0.5))

    @pytest.mark.parametrize("cls", [MecanumDriveWheelVelocities, MecanumDriveWheelAccelerations])
    def test_velocities_accelerations_interpolate_clamped(self, cls):
        start = cls(1.0, 2.0, 3.0, 4.0)
        end = cls(5.0, 6.0, 7.0, 8.0)
        assert_wheels((5.0, 6.0, 7.0, 8.0), start.interpolate(end, 100.0))
        assert_wheels((1.0, 2.0, 3.0, 4.0), start.interpolate(end, -100.0))

    def test_velocities_identity_equality(self):
        # No equals override in Java and no operator== in C++ (robotpy): identity only.
        # (The accelerations have C++'s defaulted ==: test_wpilib_cpp_operators.py.)
        cls = MecanumDriveWheelVelocities
        a = cls(1.0, 2.0, 3.0, 4.0)
        b = cls(1.0, 2.0, 3.0, 4.0)
        assert a == a
        assert not (a == b)
        assert a != b
        assert hash(a) == hash(a)  # identity-hashable

    def test_positions_equality_within_1e_9(self):
        a = MecanumDriveWheelPositions(1.0, 2.0, 3.0, 4.0)
        assert a == MecanumDriveWheelPositions(1.0, 2.0, 3.0, 4.0)
        assert a == MecanumDriveWheelPositions(1.0 + 5e-10, 2.0 - 5e-10, 3.0, 4.0 + 9e-10)
        assert a != MecanumDriveWheelPositions(1.0, 2.0, 3.0, 4.0 + 2e-9)
        assert a != MecanumDriveWheelPositions(1.0, 2.0 - 2e-9, 3.0, 4.0)
        assert a != MecanumDriveWheelVelocities(1.0, 2.0, 3.0, 4.0)
        assert a != DifferentialDriveWheelPositions(1.0, 2.0)
        assert a != (1.0, 2.0, 3.0, 4.0)

    def test_positions_unhashable(self):
        with pytest.raises(TypeError):
            hash(MecanumDriveWheelPositions())

    def test_operators_match_methods(self):
        a = MecanumDriveWheelVelocities(1.0, 0.5, 2.0, 1.5)
        b = MecanumDriveWheelVelocities(2.0, 1.5, 0.5, 1.0)
        assert wheel_values(a + b) == wheel_values(a.plus(b))
        assert wheel_values(a - b) == wheel_values(a.minus(b))
        assert wheel_values(-a) == wheel_values(a.unaryMinus())
        assert wheel_values(a * 2.0) == wheel_values(a.times(2.0))
        assert wheel_values(2.0 * a) == wheel_values(a.times(2.0))
        assert wheel_values(a / 2.0) == wheel_values(a.div(2.0))
        assert type(a + b) is MecanumDriveWheelVelocities

    def test_str(self):
        # Java %.2f rounds HALF_UP on the shortest decimal: 1.005 -> 1.01, -0.125 -> -0.13,
        # 2.675 -> 2.68.
        assert (str(MecanumDriveWheelVelocities(1.005, -0.125, 2.675, 0.0))
                == "MecanumDriveWheelVelocities(Front Left: 1.01 m/s, Front Right: -0.13 m/s, "
                   "Rear Left: 2.68 m/s, Rear Right: 0.00 m/s)")
        assert (str(MecanumDriveWheelPositions(1.0, 2.5, -3.0, 4.125))
                == "MecanumDriveWheelPositions(Front Left: 1.00 m, Front Right: 2.50 m, "
                   "Rear Left: -3.00 m, Rear Right: 4.13 m)")
        assert (str(MecanumDriveWheelAccelerations(0.5, 0.0, -1.0, 12.345))
                == "MecanumDriveWheelAccelerations(Front Left: 0.50 m/s², "
                   "Front Right: 0.00 m/s², Rear Left: -1.00 m/s², Rear Right: 12.35 m/s²)")
