"""WPILib 2027 differential-drive unit tests (DifferentialDriveKinematics including the
acceleration tests, DifferentialDriveWheelVelocities, DifferentialDriveWheelAccelerations),
restated for drivekin, plus the digest's differential edge cases
(/work/shared/reference/wpilib-kinematics.md, sections 2, 8 and 13).

Source of the ported cases: wpilibsuite/allwpilib main @ caf0fb2d,
wpimath/src/test/java/org/wpilib/math/kinematics/{DifferentialDriveKinematics,
DifferentialDriveWheelVelocities,DifferentialDriveWheelAccelerations}Test.java (the C++ tests
under wpimath/src/test/native/cpp/kinematics/ hold the same cases). There is no
DifferentialDriveWheelPositionsTest on the 2027 branch; positions are covered by the edge-case
section. Tolerances are WPILib's own: kEpsilon = 1e-9, exact equality where JUnit's
assertEquals(double, double) has no delta.

Not ported: ``DifferentialDriveWheelAccelerationsTest.testMeasureConstructor`` (units-library
constructor, not in drivekin's API).

Closed forms (digest section 8), trackwidth W: toChassisVelocities = ((l + r) / 2, 0,
(r - l) / W); toWheelVelocities = (vx - W/2 * omega, vx + W/2 * omega) with vy ignored;
toTwist2d the same as toChassisVelocities on distance changes.
"""
import math

import pytest

from drivekin import (
    ChassisAccelerations,
    ChassisVelocities,
    DifferentialDriveKinematics,
    DifferentialDriveWheelAccelerations,
    DifferentialDriveWheelPositions,
    DifferentialDriveWheelVelocities,
    MecanumDriveWheelPositions,
)
from tests._support.wpilib_port import assert_close

TRACKWIDTH = 0.381 * 2


def lr(w):
    return (w.left, w.right)


@pytest.fixture
def kinematics():
    return DifferentialDriveKinematics(TRACKWIDTH)


# =========================================================================================
# Ported: DifferentialDriveKinematicsTest
# =========================================================================================
class TestDifferentialDriveKinematics:
    def test_inverse_kinematics_for_zeros(self, kinematics):
        w = kinematics.toWheelVelocities(ChassisVelocities())
        assert_close(0.0, w.left)
        assert_close(0.0, w.right)

    def test_forward_kinematics_for_zeros(self, kinematics):
        cv = kinematics.toChassisVelocities(DifferentialDriveWheelVelocities())
        assert_close(0.0, cv.vx)
        assert_close(0.0, cv.vy)
        assert_close(0.0, cv.omega)

    def test_inverse_kinematics_for_straight_line(self, kinematics):
        w = kinematics.toWheelVelocities(ChassisVelocities(3, 0, 0))
        assert_close(3.0, w.left)
        assert_close(3.0, w.right)

    def test_forward_kinematics_for_straight_line(self, kinematics):
        cv = kinematics.toChassisVelocities(DifferentialDriveWheelVelocities(3, 3))
        assert_close(3.0, cv.vx)
        assert_close(0.0, cv.vy)
        assert_close(0.0, cv.omega)

    def test_inverse_kinematics_for_rotate_in_place(self, kinematics):
        w = kinematics.toWheelVelocities(ChassisVelocities(0, 0, math.pi))
        assert_close(-0.381 * math.pi, w.left)
        assert_close(+0.381 * math.pi, w.right)

    def test_forward_kinematics_for_rotate_in_place(self, kinematics):
        cv = kinematics.toChassisVelocities(
            DifferentialDriveWheelVelocities(+0.381 * math.pi, -0.381 * math.pi))
        assert_close(0.0, cv.vx)
        assert_close(0.0, cv.vy)
        assert_close(-math.pi, cv.omega)

    def test_inverse_accelerations_for_zeros(self, kinematics):
        w = kinematics.toWheelAccelerations(ChassisAccelerations())
        assert_close(0.0, w.left)
        assert_close(0.0, w.right)

    def test_forward_accelerations_for_zeros(self, kinematics):
        ca = kinematics.toChassisAccelerations(DifferentialDriveWheelAccelerations())
        assert_close(0.0, ca.ax)
        assert_close(0.0, ca.ay)
        assert_close(0.0, ca.alpha)

    def test_inverse_accelerations_for_straight_line(self, kinematics):
        w = kinematics.toWheelAccelerations(ChassisAccelerations(3, 0, 0))
        assert_close(3.0, w.left)
        assert_close(3.0, w.right)

    def test_forward_accelerations_for_straight_line(self, kinematics):
        ca = kinematics.toChassisAccelerations(DifferentialDriveWheelAccelerations(3, 3))
        assert_close(3.0, ca.ax)
        assert_close(0.0, ca.ay)
        assert_close(0.0, ca.alpha)

    def test_inverse_accelerations_for_rotate_in_place(self, kinematics):
        w = kinematics.toWheelAccelerations(ChassisAccelerations(0, 0, math.pi))
        assert_close(-0.381 * math.pi, w.left)
        assert_close(+0.381 * math.pi, w.right)

    def test_forward_accelerations_for_rotate_in_place(self, kinematics):
        ca = kinematics.toChassisAccelerations(
            DifferentialDriveWheelAccelerations(+0.381 * math.pi, -0.381 * math.pi))
        assert_close(0.0, ca.ax)
        assert_close(0.0, ca.ay)
        assert_close(-math.pi, ca.alpha)


# =========================================================================================
# Ported: DifferentialDriveWheelVelocitiesTest
# =========================================================================================
class TestDifferentialDriveWheelVelocities:
    def test_plus(self):
        left = DifferentialDriveWheelVelocities(1.0, 0.5)
        right = DifferentialDriveWheelVelocities(2.0, 1.5)
        assert lr(left.plus(right)) == (3.0, 2.0)

    def test_minus(self):
        left = DifferentialDriveWheelVelocities(1.0, 0.5)
        right = DifferentialDriveWheelVelocities(2.0, 0.5)
        assert lr(left.minus(right)) == (-1.0, 0.0)

    def test_unary_minus(self):
        assert lr(DifferentialDriveWheelVelocities(1.0, 0.5).unaryMinus()) == (-1.0, -0.5)

    def test_multiplication(self):
        assert lr(DifferentialDriveWheelVelocities(1.0, 0.5).times(2.0)) == (2.0, 1.0)

    def test_division(self):
        assert lr(DifferentialDriveWheelVelocities(1.0, 0.5).div(2.0)) == (0.5, 0.25)

    def test_interpolate(self):
        start = DifferentialDriveWheelVelocities(1.0, 2.0)
        end = DifferentialDriveWheelVelocities(5.0, 6.0)
        for t, (el, er) in [(0.0, (1.0, 2.0)), (1.0, (5.0, 6.0)), (0.5, (3.0, 4.0)),
                            (0.25, (2.0, 3.0)),
                            # clamping: t < 0 -> 0, t > 1 -> 1
                            (-0.5, (1.0, 2.0)), (1.5, (5.0, 6.0))]:
            w = start.interpolate(end, t)
            assert_close(el, w.left)
            assert_close(er, w.right)


# =========================================================================================
# Ported: DifferentialDriveWheelAccelerationsTest
# =========================================================================================
class TestDifferentialDriveWheelAccelerations:
    def test_default_constructor(self):
        w = DifferentialDriveWheelAccelerations()
        assert_close(0.0, w.left)
        assert_close(0.0, w.right)

    def test_parameterized_constructor(self):
        w = DifferentialDriveWheelAccelerations(1.5, 2.5)
        assert_close(1.5, w.left)
        assert_close(2.5, w.right)

    def test_plus(self):
        left = DifferentialDriveWheelAccelerations(1.0, 0.5)
        right = DifferentialDriveWheelAccelerations(2.0, 1.5)
        assert lr(left.plus(right)) == (3.0, 2.0)

    def test_minus(self):
        left = DifferentialDriveWheelAccelerations(1.0, 0.5)
        right = DifferentialDriveWheelAccelerations(2.0, 0.5)
        assert lr(left.minus(right)) == (-1.0, 0.0)

    def test_unary_minus(self):
        assert lr(DifferentialDriveWheelAccelerations(1.0, 0.5).unaryMinus()) == (-1.0, -0.5)

    def test_multiplication(self):
        assert lr(DifferentialDriveWheelAccelerations(1.0, 0.5).times(2.0)) == (2.0, 1.0)

    def test_division(self):
        assert lr(DifferentialDriveWheelAccelerations(1.0, 0.5).div(2.0)) == (0.5, 0.25)

    def test_interpolate(self):
        start = DifferentialDriveWheelAccelerations(1.0, 2.0)
        end = DifferentialDriveWheelAccelerations(5.0, 6.0)
        for t, (el, er) in [(0.0, (1.0, 2.0)), (1.0, (5.0, 6.0)), (0.5, (3.0, 4.0)),
                            (0.25, (2.0, 3.0)), (-0.5, (1.0, 2.0)), (1.5, (5.0, 6.0))]:
            w = start.interpolate(end, t)
            assert_close(el, w.left)
            assert_close(er, w.right)


# =========================================================================================
# Edge cases from the digest (not in the WPILib tests)
# =========================================================================================
class TestKinematicsClosedForms:
    @pytest.mark.parametrize("vx, vy, omega", [
        (1.5, 0.0, 0.0), (0.0, 0.0, -2.0), (2.0, 0.0, 0.75), (-1.25, 3.0, 4.5),
    ])
    def test_inverse_ignores_vy(self, kinematics, vx, vy, omega):
        w = kinematics.toWheelVelocities(ChassisVelocities(vx, vy, omega))
        assert_close(vx - TRACKWIDTH / 2 * omega, w.left)
        assert_close(vx + TRACKWIDTH / 2 * omega, w.right)
        a = kinematics.toWheelAccelerations(ChassisAccelerations(vx, vy, omega))
        assert_close(vx - TRACKWIDTH / 2 * omega, a.left)
        assert_close(vx + TRACKWIDTH / 2 * omega, a.right)

    @pytest.mark.parametrize("left, right", [(1.0, 2.0), (-3.0, 0.5), (0.0, 0.0), (4.0, 4.0)])
    def test_forward(self, kinematics, left, right):
        cv = kinematics.toChassisVelocities(DifferentialDriveWheelVelocities(left, right))
        assert_close((left + right) / 2, cv.vx)
        assert cv.vy == 0.0
        assert_close((right - left) / TRACKWIDTH, cv.omega)
        ca = kinematics.toChassisAccelerations(DifferentialDriveWheelAccelerations(left, right))
        assert_close((left + right) / 2, ca.ax)
        assert ca.ay == 0.0
        assert_close((right - left) / TRACKWIDTH, ca.alpha)

    def test_to_twist2d_distances(self, kinematics):
        twist = kinematics.toTwist2d(1.0, 3.0)
        assert_close(2.0, twist.dx)
        assert twist.dy == 0.0
        assert_close(2.0 / TRACKWIDTH, twist.dtheta)

    def test_to_twist2d_positions_uses_end_minus_start(self, kinematics):
        start = DifferentialDriveWheelPositions(10.0, -4.0)
        end = DifferentialDriveWheelPositions(11.0, -1.0)
        twist = kinematics.toTwist2d(start, end)
        assert_close(2.0, twist.dx)
        assert twist.dy == 0.0
        assert_close(2.0 / TRACKWIDTH, twist.dtheta)

    def test_trackwidth_field(self, kinematics):
        assert kinematics.trackwidth == TRACKWIDTH

    def test_round_trip(self, kinematics):
        cv = ChassisVelocities(1.25, 0.0, -0.8)
        back = kinematics.toChassisVelocities(kinematics.toWheelVelocities(cv))
        assert_close(cv.vx, back.vx)
        assert_close(cv.omega, back.omega)

    def test_into_forms_match(self, kinematics):
        cv = ChassisVelocities(1.0, 0.0, 2.0)
        out = DifferentialDriveWheelVelocities()
        assert kinematics.toWheelVelocitiesInto(cv, out) is None
        assert lr(out) == lr(kinematics.toWheelVelocities(cv))
        back = ChassisVelocities(9.0, 9.0, 9.0)
        assert kinematics.toChassisVelocitiesInto(out, back) is None
        expected = kinematics.toChassisVelocities(out)
        assert (back.vx, back.vy, back.omega) == (expected.vx, expected.vy, expected.omega)

    def test_interpolate_copy_copy_into(self, kinematics):
        start = DifferentialDriveWheelPositions(1.0, 2.0)
        end = DifferentialDriveWheelPositions(5.0, 6.0)
        assert lr(kinematics.interpolate(start, end, 0.5)) == (3.0, 4.0)
        assert lr(kinematics.interpolate(start, end, 1.5)) == (7.0, 8.0)  # unclamped
        c = kinematics.copy(start)
        assert c is not start and c == start
        start.left = 100.0
        assert c.left == 1.0
        out = DifferentialDriveWheelPositions(0.0, 0.0)
        assert kinematics.copyInto(end, out) is None
        assert lr(out) == (5.0, 6.0)


class TestWheelValueEdgeCases:
    def test_positions_have_no_no_arg_constructor(self):
        # Java DifferentialDriveWheelPositions has only (left, right).
        with pytest.raises(TypeError):
            DifferentialDriveWheelPositions()
        assert lr(DifferentialDriveWheelPositions(1.0, 2.0)) == (1.0, 2.0)

    def test_defaults_and_mutable_fields(self):
        for cls in (DifferentialDriveWheelVelocities, DifferentialDriveWheelAccelerations):
            w = cls()
            assert lr(w) == (0.0, 0.0)
            w.left, w.right = 1.0, -2.0
            assert lr(w) == (1.0, -2.0)
        p = DifferentialDriveWheelPositions(0.0, 0.0)
        p.left, p.right = 3.0, 4.0
        assert lr(p) == (3.0, 4.0)

    def test_desaturate_returns_new_object(self):
        w = DifferentialDriveWheelVelocities(4.0, -8.0)
        d = w.desaturate(2.0)
        assert d is not w
        assert type(d) is DifferentialDriveWheelVelocities
        assert lr(w) == (4.0, -8.0)
        assert_close(1.0, d.left)
        assert_close(-2.0, d.right)

    def test_desaturate_unsaturated_is_unchanged_copy(self):
        w = DifferentialDriveWheelVelocities(1.0, -2.0)
        d = w.desaturate(2.0)  # max |v| == 2 is not > 2
        assert d is not w
        assert lr(d) == (1.0, -2.0)

    def test_desaturate_in_place_mutates(self):
        w = DifferentialDriveWheelVelocities(6.0, 3.0)
        assert w.desaturateInPlace(3.0) is None
        assert_close(3.0, w.left)
        assert_close(1.5, w.right)

    def test_accelerations_have_no_desaturate(self):
        assert not hasattr(DifferentialDriveWheelAccelerations(), "desaturate")

    def test_positions_interpolate_unclamped(self):
        start = DifferentialDriveWheelPositions(1.0, 2.0)
        end = DifferentialDriveWheelPositions(5.0, 6.0)
        assert lr(start.interpolate(end, 0.25)) == (2.0, 3.0)
        assert lr(start.interpolate(end, 1.5)) == (7.0, 8.0)
        assert lr(start.interpolate(end, -0.5)) == (-1.0, 0.0)

    @pytest.mark.parametrize("cls", [DifferentialDriveWheelVelocities,
                                     DifferentialDriveWheelAccelerations])
    def test_velocities_accelerations_interpolate_clamped(self, cls):
        start, end = cls(1.0, 2.0), cls(5.0, 6.0)
        assert lr(start.interpolate(end, 7.0)) == (5.0, 6.0)
        assert lr(start.interpolate(end, -7.0)) == (1.0, 2.0)

    def test_velocities_identity_equality(self):
        # No equals in Java, no operator== in C++ (the accelerations have C++'s defaulted
        # ==: test_wpilib_cpp_operators.py).
        cls = DifferentialDriveWheelVelocities
        a, b = cls(1.0, 2.0), cls(1.0, 2.0)
        assert a == a
        assert not (a == b)
        assert a != b
        assert hash(a) == hash(a)

    def test_positions_equality_within_1e_9(self):
        a = DifferentialDriveWheelPositions(1.0, 2.0)
        assert a == DifferentialDriveWheelPositions(1.0, 2.0)
        assert a == DifferentialDriveWheelPositions(1.0 + 9e-10, 2.0 - 9e-10)
        assert a != DifferentialDriveWheelPositions(1.0 + 2e-9, 2.0)
        assert a != DifferentialDriveWheelPositions(1.0, 2.0 - 2e-9)
        assert a != DifferentialDriveWheelVelocities(1.0, 2.0)
        assert a != MecanumDriveWheelPositions(1.0, 2.0, 0.0, 0.0)
        assert a != (1.0, 2.0)
        with pytest.raises(TypeError):
            hash(a)

    def test_operators_match_methods(self):
        a = DifferentialDriveWheelAccelerations(1.0, 0.5)
        b = DifferentialDriveWheelAccelerations(2.0, 1.5)
        assert lr(a + b) == lr(a.plus(b))
        assert lr(a - b) == lr(a.minus(b))
        assert lr(-a) == lr(a.unaryMinus())
        assert lr(a * 3.0) == lr(3.0 * a) == lr(a.times(3.0))
        assert lr(a / 4.0) == lr(a.div(4.0))
        assert type(a * 3.0) is DifferentialDriveWheelAccelerations

    def test_str(self):
        assert (str(DifferentialDriveWheelVelocities(1.005, -0.125))
                == "DifferentialDriveWheelVelocities(Left: 1.01 m/s, Right: -0.13 m/s)")
        assert (str(DifferentialDriveWheelAccelerations(2.675, 0.0))
                == "DifferentialDriveWheelAccelerations(Left: 2.68 m/s², Right: 0.00 m/s²)")

    def test_positions_str_closes_parenthesis(self):
        # WPILib's toString is "DifferentialDriveWheelPositions(Left: %.2f m, Right: %.2f m"
        # (no closing parenthesis); drivekin deliberately closes it (documented in
        # differential.pyx).
        assert (str(DifferentialDriveWheelPositions(1.0, -2.345))
                == "DifferentialDriveWheelPositions(Left: 1.00 m, Right: -2.35 m)")
