"""WPILib 2027 ChassisVelocities / ChassisAccelerations unit tests, restated for drivekin, plus
the digest's edge cases for these classes (/work/shared/reference/wpilib-kinematics.md,
sections 2, 4, 5 and 13).

Source of the ported cases: wpilibsuite/allwpilib main @ caf0fb2d,
wpimath/src/test/java/org/wpilib/math/kinematics/{ChassisVelocities,ChassisAccelerations}Test.java.
Where JUnit uses assertEquals without a delta the comparison here is exact as well.

Not ported: ``testMeasureConstructor`` (units-library constructors, not in drivekin's API).
"""
import math

from drivekin import (
    ChassisAccelerations,
    ChassisVelocities,
    Pose2d,
    Rotation2d,
    Twist2d,
)
from tests._support.wpilib_port import EPS, assert_close


def assert_same(expected, actual):
    """JUnit assertEquals(double, double) without a delta: bit-identical (0.0 != -0.0)."""
    assert actual == expected and math.copysign(1.0, actual) == math.copysign(1.0, expected), (
        f"expected exactly {expected!r}, got {actual!r}")


def assert_cv(cv, vx, vy, omega, tol=EPS):
    assert_close(vx, cv.vx, tol)
    assert_close(vy, cv.vy, tol)
    assert_close(omega, cv.omega, tol)


def assert_ca(ca, ax, ay, alpha, tol=EPS):
    assert_close(ax, ca.ax, tol)
    assert_close(ay, ca.ay, tol)
    assert_close(alpha, ca.alpha, tol)


# =========================================================================================
# Ported: ChassisVelocitiesTest
# =========================================================================================
class TestChassisVelocities:
    def test_discretize(self):
        target = ChassisVelocities(1.0, 0.0, 0.5)
        duration = 1.0
        dt = 0.01

        velocities = target.discretize(duration)
        twist = Twist2d(velocities.vx * dt, velocities.vy * dt, velocities.omega * dt)

        pose = Pose2d.kZero
        time = 0.0
        while time < duration:  # same floating-point loop as the Java test
            pose = pose.plus(twist.exp())
            time += dt

        assert_close(target.vx * duration, pose.getX())
        assert_close(target.vy * duration, pose.getY())
        assert_close(target.omega * duration, pose.getRotation().getRadians())

    def test_to_robot_relative(self):
        cv = ChassisVelocities(1.0, 0.0, 0.5).toRobotRelative(Rotation2d.kCW_Pi_2)
        assert_cv(cv, 0.0, 1.0, 0.5)

    def test_to_field_relative(self):
        cv = ChassisVelocities(1.0, 0.0, 0.5).toFieldRelative(Rotation2d.fromDegrees(45.0))
        assert_cv(cv, 1.0 / math.sqrt(2.0), 1.0 / math.sqrt(2.0), 0.5)

    def test_plus(self):
        cv = ChassisVelocities(1.0, 0.5, 0.75).plus(ChassisVelocities(2.0, 1.5, 0.25))
        assert_same(3.0, cv.vx)
        assert_same(2.0, cv.vy)
        assert_same(1.0, cv.omega)

    def test_minus(self):
        cv = ChassisVelocities(1.0, 0.5, 0.75).minus(ChassisVelocities(2.0, 0.5, 0.25))
        assert_same(-1.0, cv.vx)
        assert_same(0.0, cv.vy)
        assert_same(0.5, cv.omega)

    def test_unary_minus(self):
        cv = ChassisVelocities(1.0, 0.5, 0.75).unaryMinus()
        assert_same(-1.0, cv.vx)
        assert_same(-0.5, cv.vy)
        assert_same(-0.75, cv.omega)

    def test_multiplication(self):
        cv = ChassisVelocities(1.0, 0.5, 0.75).times(2.0)
        assert_same(2.0, cv.vx)
        assert_same(1.0, cv.vy)
        assert_same(1.5, cv.omega)

    def test_division(self):
        cv = ChassisVelocities(1.0, 0.5, 0.75).div(2.0)
        assert_same(0.5, cv.vx)
        assert_same(0.25, cv.vy)
        assert_same(0.375, cv.omega)

    def test_interpolation(self):
        result = ChassisVelocities(0.0, 0.0, 0.0).interpolate(ChassisVelocities(10.0, 20.0, 30.0),
                                                              0.5)
        assert_cv(result, 5.0, 10.0, 15.0)

    def test_interpolation_at_bounds(self):
        start = ChassisVelocities(1.0, 2.0, 3.0)
        end = ChassisVelocities(4.0, 5.0, 6.0)
        assert_cv(start.interpolate(end, 0.0), 1.0, 2.0, 3.0)
        assert_cv(start.interpolate(end, 1.0), 4.0, 5.0, 6.0)


# =========================================================================================
# Ported: ChassisAccelerationsTest
# =========================================================================================
class TestChassisAccelerations:
    def test_default_constructor(self):
        assert_ca(ChassisAccelerations(), 0.0, 0.0, 0.0)

    def test_parameterized_constructor(self):
        assert_ca(ChassisAccelerations(1.0, 2.0, 3.0), 1.0, 2.0, 3.0)

    def test_to_robot_relative(self):
        ca = ChassisAccelerations(1.0, 0.0, 0.5).toRobotRelative(Rotation2d.kCW_Pi_2)
        assert_ca(ca, 0.0, 1.0, 0.5)

    def test_to_field_relative(self):
        ca = ChassisAccelerations(1.0, 0.0, 0.5).toFieldRelative(Rotation2d.fromDegrees(45.0))
        assert_ca(ca, 1.0 / math.sqrt(2.0), 1.0 / math.sqrt(2.0), 0.5)

    def test_plus(self):
        ca = ChassisAccelerations(1.0, 0.5, 0.75).plus(ChassisAccelerations(2.0, 1.5, 0.25))
        assert_same(3.0, ca.ax)
        assert_same(2.0, ca.ay)
        assert_same(1.0, ca.alpha)

    def test_minus(self):
        ca = ChassisAccelerations(1.0, 0.5, 0.75).minus(ChassisAccelerations(2.0, 0.5, 0.25))
        assert_same(-1.0, ca.ax)
        assert_same(0.0, ca.ay)
        assert_same(0.5, ca.alpha)

    def test_unary_minus(self):
        ca = ChassisAccelerations(1.0, 0.5, 0.75).unaryMinus()
        assert_same(-1.0, ca.ax)
        assert_same(-0.5, ca.ay)
        assert_same(-0.75, ca.alpha)

    def test_multiplication(self):
        ca = ChassisAccelerations(1.0, 0.5, 0.75).times(2.0)
        assert_same(2.0, ca.ax)
        assert_same(1.0, ca.ay)
        assert_same(1.5, ca.alpha)

    def test_division(self):
        ca = ChassisAccelerations(2.0, 1.0, 1.5).div(2.0)
        assert_same(1.0, ca.ax)
        assert_same(0.5, ca.ay)
        assert_same(0.75, ca.alpha)

    def test_interpolation(self):
        result = ChassisAccelerations(0.0, 0.0, 0.0).interpolate(
            ChassisAccelerations(10.0, 20.0, 30.0), 0.5)
        assert_ca(result, 5.0, 10.0, 15.0)

    def test_interpolation_at_bounds(self):
        start = ChassisAccelerations(1.0, 2.0, 3.0)
        end = ChassisAccelerations(4.0, 5.0, 6.0)
        assert_ca(start.interpolate(end, 0.0), 1.0, 2.0, 3.0)
        assert_ca(start.interpolate(end, 1.0), 4.0, 5.0, 6.0)


# =========================================================================================
# Digest edge cases
# =========================================================================================
class TestChassisVelocitiesEdgeCases:
    def test_default_constructor_and_mutable_fields(self):
        cv = ChassisVelocities()
        assert (cv.vx, cv.vy, cv.omega) == (0.0, 0.0, 0.0)
        cv.vx = 1.5
        cv.vy = -2.0
        cv.omega = 0.25
        assert (cv.vx, cv.vy, cv.omega) == (1.5, -2.0, 0.25)

    def test_to_twist2d(self):
        twist = ChassisVelocities(1.0, 2.0, 3.0).toTwist2d(0.5)
        assert_close(0.5, twist.dx)
        assert_close(1.0, twist.dy)
        assert_close(1.5, twist.dtheta)

    def test_discretize_closed_form(self):
        # log of Transform2d(1, 0, Rotation2d(0.5)): dx = h*cot(h) with h = 0.25, dy = -h.
        cv = ChassisVelocities(1.0, 0.0, 0.5).discretize(1.0)
        assert_cv(cv, 0.25 / math.tan(0.25), -0.25, 0.5)
        assert_close(0.9790793411614854, cv.vx)

    def test_discretize_scales_with_dt(self):
        vx, vy, omega, dt = 2.0, -1.0, 1.2, 0.02
        h = omega * dt / 2.0
        k = h / math.tan(h)
        x, y = vx * dt, vy * dt
        cv = ChassisVelocities(vx, vy, omega).discretize(dt)
        assert_cv(cv, (k * x + h * y) / dt, (-h * x + k * y) / dt, omega)

    def test_discretize_wraps_omega_dt(self):
        # omega*dt passes through a Rotation2d: 4 rad becomes 4 - 2*pi.
        cv = ChassisVelocities(0.0, 0.0, 4.0).discretize(1.0)
        assert_close(4.0 - 2.0 * math.pi, cv.omega)
        assert_close(0.0, cv.vx)
        assert_close(0.0, cv.vy)

    def test_discretize_zero_dt_has_no_guard(self):
        # WPILib divides by dt unguarded: 0/0 gives NaN in every field.
        cv = ChassisVelocities(1.0, 2.0, 3.0).discretize(0.0)
        assert math.isnan(cv.vx)
        assert math.isnan(cv.vy)
        assert math.isnan(cv.omega)

    def test_discretize_returns_new_object(self):
        cv = ChassisVelocities(1.0, 0.0, 0.5)
        out = cv.discretize(1.0)
        assert out is not cv
        assert (cv.vx, cv.vy, cv.omega) == (1.0, 0.0, 0.5)

    def test_relative_conversions_round_trip(self):
        angle = Rotation2d.fromDegrees(37.0)
        cv = ChassisVelocities(1.5, -0.5, 2.0)
        back = cv.toRobotRelative(angle).toFieldRelative(angle)
        assert_cv(back, 1.5, -0.5, 2.0)
        # toRobotRelative rotates by -angle.
        r = cv.toRobotRelative(angle)
        c, s = math.cos(math.radians(37.0)), math.sin(math.radians(37.0))
        assert_cv(r, 1.5 * c + (-0.5) * s, -1.5 * s + (-0.5) * c, 2.0)

    def test_operators(self):
        a = ChassisVelocities(1.0, 0.5, 0.75)
        b = ChassisVelocities(2.0, 1.5, 0.25)
        assert (a + b) == ChassisVelocities(3.0, 2.0, 1.0)
        assert (a - b) == ChassisVelocities(-1.0, -1.0, 0.5)
        assert (-a) == ChassisVelocities(-1.0, -0.5, -0.75)
        assert (a * 2.0) == ChassisVelocities(2.0, 1.0, 1.5)
        assert (a / 2.0) == ChassisVelocities(0.5, 0.25, 0.375)

    def test_interpolation_clamping(self):
        # t <= 0 -> start, t >= 1 -> end (no extrapolation).
        start = ChassisVelocities(1.0, 2.0, 3.0)
        end = ChassisVelocities(4.0, 5.0, 6.0)
        assert_cv(start.interpolate(end, -0.5), 1.0, 2.0, 3.0)
        assert_cv(start.interpolate(end, 1.5), 4.0, 5.0, 6.0)
        assert_cv(start.interpolate(end, 0.25), 1.75, 2.75, 3.75)

    def test_equality_is_exact(self):
        assert ChassisVelocities(1.0, 2.0, 3.0) == ChassisVelocities(1.0, 2.0, 3.0)
        assert ChassisVelocities(1.0, 2.0, 3.0) != ChassisVelocities(1.0, 2.0, 3.0 + 1e-12)
        assert ChassisVelocities(1.0 + 1e-15, 2.0, 3.0) != ChassisVelocities(1.0, 2.0, 3.0)
        # Primitive double ==: 0.0 == -0.0 and NaN != NaN.
        assert ChassisVelocities(0.0, 0.0, 0.0) == ChassisVelocities(-0.0, -0.0, -0.0)
        nan = float("nan")
        assert ChassisVelocities(nan, 0.0, 0.0) != ChassisVelocities(nan, 0.0, 0.0)

    def test_str(self):
        assert (str(ChassisVelocities(0.125, -2.675, 1.005))
                == "ChassisVelocities(Vx: 0.13 m/s, Vy: -2.68 m/s, Omega: 1.01 rad/s)")
        assert (str(ChassisVelocities())
                == "ChassisVelocities(Vx: 0.00 m/s, Vy: 0.00 m/s, Omega: 0.00 rad/s)")


class TestChassisAccelerationsEdgeCases:
    def test_relative_conversions(self):
        angle = Rotation2d.fromDegrees(-120.0)
        c, s = math.cos(math.radians(-120.0)), math.sin(math.radians(-120.0))
        ca = ChassisAccelerations(2.0, 1.0, -0.5)
        assert_ca(ca.toFieldRelative(angle), 2.0 * c - 1.0 * s, 2.0 * s + 1.0 * c, -0.5)
        assert_ca(ca.toRobotRelative(angle), 2.0 * c + 1.0 * s, -2.0 * s + 1.0 * c, -0.5)

    def test_operators(self):
        a = ChassisAccelerations(1.0, 0.5, 0.75)
        b = ChassisAccelerations(2.0, 1.5, 0.25)
        assert (a + b) == ChassisAccelerations(3.0, 2.0, 1.0)
        assert (a - b) == ChassisAccelerations(-1.0, -1.0, 0.5)
        assert (-a) == ChassisAccelerations(-1.0, -0.5, -0.75)
        assert (a * 2.0) == ChassisAccelerations(2.0, 1.0, 1.5)
        assert (a / 2.0) == ChassisAccelerations(0.5, 0.25, 0.375)

    def test_interpolation_clamping(self):
        start = ChassisAccelerations(1.0, 2.0, 3.0)
        end = ChassisAccelerations(4.0, 5.0, 6.0)
        assert_ca(start.interpolate(end, -0.5), 1.0, 2.0, 3.0)
        assert_ca(start.interpolate(end, 1.5), 4.0, 5.0, 6.0)
        assert_ca(start.interpolate(end, 0.75), 3.25, 4.25, 5.25)

    def test_equality_uses_double_compare(self):
        # Double.compare semantics: NaN equals NaN, 0.0 differs from -0.0.
        assert ChassisAccelerations(1.0, 2.0, 3.0) == ChassisAccelerations(1.0, 2.0, 3.0)
        assert ChassisAccelerations(1.0, 2.0, 3.0) != ChassisAccelerations(1.0, 2.0, 3.0 + 1e-12)
        nan = float("nan")
        assert ChassisAccelerations(nan, 0.0, 0.0) == ChassisAccelerations(nan, 0.0, 0.0)
        assert ChassisAccelerations(0.0, 0.0, 0.0) != ChassisAccelerations(-0.0, 0.0, 0.0)
        assert ChassisAccelerations(0.0, 0.0, 0.0) != ChassisAccelerations(0.0, 0.0, -0.0)

    def test_str(self):
        assert (str(ChassisAccelerations(0.125, 1.005, -2.675))
                == "ChassisAccelerations(Ax: 0.13 m/s², Ay: 1.01 m/s², Alpha: -2.68 rad/s²)")
