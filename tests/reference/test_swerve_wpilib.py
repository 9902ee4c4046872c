"""WPILib 2027 swerve unit tests (SwerveDriveKinematics including the acceleration tests,
SwerveModuleVelocity, SwerveModulePosition, SwerveModuleAcceleration), restated for drivekin,
plus the digest's swerve edge cases (/work/shared/reference/wpilib-kinematics.md, sections 2, 6
and 13).

Source of the ported cases: wpilibsuite/allwpilib main @ caf0fb2d,
wpimath/src/test/java/org/wpilib/math/kinematics/{SwerveDriveKinematics,SwerveModuleVelocity,
SwerveModuleAcceleration}Test.java and (no Java SwerveModulePositionTest exists on the 2027
branch) wpimath/src/test/native/cpp/kinematics/SwerveModulePositionTest.cpp.
Tolerances are WPILib's own: kEpsilon = 1e-9, and 0.1 where the WPILib test uses 0.1.

Not ported: ``SwerveModuleAccelerationTest.testMeasureConstructor`` (units-library
constructor, not in drivekin's API).
"""
import math

import pytest

from drivekin import (
    ChassisAccelerations,
    ChassisVelocities,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveModuleAcceleration,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Translation2d,
)
from tests._support.wpilib_port import BL, BR, FL, FR, assert_close


@pytest.fixture
def kinematics():
    # JUnit builds a fresh test-class instance (and so a fresh kinematics) per test.
    return SwerveDriveKinematics(FL, FR, BL, BR)


def module_velocity(rx, ry, vx, vy, omega):
    """Closed form of one module's velocity vector v + omega x r, r relative to the CoR."""
    return vx - omega * ry, vy + omega * rx


# =========================================================================================
# Ported: SwerveDriveKinematicsTest
# =========================================================================================
class TestSwerveDriveKinematics:
    def test_straight_line_inverse_kinematics(self, kinematics):
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities(5, 0, 0))
        for s in states:
            assert_close(5.0, s.velocity)
        for s in states:
            assert_close(0.0, s.angle.getRadians())

    def test_straight_line_forward_kinematics(self, kinematics):
        state = SwerveModuleVelocity(5.0, Rotation2d.kZero)
        cv = kinematics.toChassisVelocities(state, state, state, state)
        assert_close(5.0, cv.vx)
        assert_close(0.0, cv.vy)
        assert_close(0.0, cv.omega)

    def test_straight_line_forward_kinematics_with_deltas(self, kinematics):
        delta = SwerveModulePosition(5.0, Rotation2d.kZero)
        twist = kinematics.toTwist2d(delta, delta, delta, delta)
        assert_close(5.0, twist.dx)
        assert_close(0.0, twist.dy)
        assert_close(0.0, twist.dtheta)

    def test_straight_strafe_inverse_kinematics(self, kinematics):
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 5, 0))
        for s in states:
            assert_close(5.0, s.velocity)
        for s in states:
            assert_close(90.0, s.angle.getDegrees())

    def test_straight_strafe_forward_kinematics(self, kinematics):
        state = SwerveModuleVelocity(5.0, Rotation2d.kCCW_Pi_2)
        cv = kinematics.toChassisVelocities(state, state, state, state)
        assert_close(0.0, cv.vx)
        assert_close(5.0, cv.vy)
        assert_close(0.0, cv.omega)

    def test_straight_strafe_forward_kinematics_with_deltas(self, kinematics):
        delta = SwerveModulePosition(5.0, Rotation2d.kCCW_Pi_2)
        twist = kinematics.toTwist2d(delta, delta, delta, delta)
        assert_close(0.0, twist.dx)
        assert_close(5.0, twist.dy)
        assert_close(0.0, twist.dtheta)

    def test_conserve_wheel_angle(self, kinematics):
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 0, 2 * math.pi))
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities())
        for s in states:
            assert_close(0.0, s.velocity)
        assert_close(135.0, states[0].angle.getDegrees())
        assert_close(45.0, states[1].angle.getDegrees())
        assert_close(-135.0, states[2].angle.getDegrees())
        assert_close(-45.0, states[3].angle.getDegrees())

    def test_reset_wheel_angle(self, kinematics):
        kinematics.resetHeadings(Rotation2d.kZero, Rotation2d.kCCW_Pi_2, Rotation2d.kPi,
                                 Rotation2d(3 * math.pi / 2))
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities())
        for s in states:
            assert_close(0.0, s.velocity)
        assert_close(0.0, states[0].angle.getDegrees())
        assert_close(90.0, states[1].angle.getDegrees())
        assert_close(180.0, states[2].angle.getDegrees())
        assert_close(-90.0, states[3].angle.getDegrees())

    def test_turn_in_place_inverse_kinematics(self, kinematics):
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 0, 2 * math.pi))
        for s in states:
            assert_close(106.63, s.velocity, 0.1)
        assert_close(135.0, states[0].angle.getDegrees())
        assert_close(45.0, states[1].angle.getDegrees())
        assert_close(-135.0, states[2].angle.getDegrees())
        assert_close(-45.0, states[3].angle.getDegrees())

    def test_turn_in_place_forward_kinematics(self, kinematics):
        cv = kinematics.toChassisVelocities(
            SwerveModuleVelocity(106.629, Rotation2d.fromDegrees(135)),
            SwerveModuleVelocity(106.629, Rotation2d.fromDegrees(45)),
            SwerveModuleVelocity(106.629, Rotation2d.fromDegrees(-135)),
            SwerveModuleVelocity(106.629, Rotation2d.fromDegrees(-45)))
        assert_close(0.0, cv.vx)
        assert_close(0.0, cv.vy)
        assert_close(2 * math.pi, cv.omega, 0.1)

    def test_turn_in_place_forward_kinematics_with_deltas(self, kinematics):
        twist = kinematics.toTwist2d(
            SwerveModulePosition(106.629, Rotation2d.fromDegrees(135)),
            SwerveModulePosition(106.629, Rotation2d.fromDegrees(45)),
            SwerveModulePosition(106.629, Rotation2d.fromDegrees(-135)),
            SwerveModulePosition(106.629, Rotation2d.fromDegrees(-45)))
        assert_close(0.0, twist.dx)
        assert_close(0.0, twist.dy)
        assert_close(2 * math.pi, twist.dtheta, 0.1)

    def test_off_center_cor_rotation_inverse_kinematics(self, kinematics):
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 0, 2 * math.pi), FL)
        assert_close(0.0, states[0].velocity, 0.1)
        assert_close(150.796, states[1].velocity, 0.1)
        assert_close(150.796, states[2].velocity, 0.1)
        assert_close(213.258, states[3].velocity, 0.1)
        assert_close(0.0, states[0].angle.getDegrees())
        assert_close(0.0, states[1].angle.getDegrees())
        assert_close(-90.0, states[2].angle.getDegrees())
        assert_close(-45.0, states[3].angle.getDegrees())

    def test_off_center_cor_rotation_forward_kinematics(self, kinematics):
        cv = kinematics.toChassisVelocities(
            SwerveModuleVelocity(0.0, Rotation2d.kZero),
            SwerveModuleVelocity(150.796, Rotation2d.kZero),
            SwerveModuleVelocity(150.796, Rotation2d.kCW_Pi_2),
            SwerveModuleVelocity(213.258, Rotation2d.fromDegrees(-45)))
        assert_close(75.398, cv.vx, 0.1)
        assert_close(-75.398, cv.vy, 0.1)
        assert_close(2 * math.pi, cv.omega, 0.1)

    def test_off_center_cor_rotation_forward_kinematics_with_deltas(self, kinematics):
        twist = kinematics.toTwist2d(
            SwerveModulePosition(0.0, Rotation2d.kZero),
            SwerveModulePosition(150.796, Rotation2d.kZero),
            SwerveModulePosition(150.796, Rotation2d.fromDegrees(-90)),
            SwerveModulePosition(213.258, Rotation2d.fromDegrees(-45)))
        assert_close(75.398, twist.dx, 0.1)
        assert_close(-75.398, twist.dy, 0.1)
        assert_close(2 * math.pi, twist.dtheta, 0.1)

    def test_off_center_cor_rotation_and_translation_inverse_kinematics(self, kinematics):
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities(0.0, 3.0, 1.5),
                                                     Translation2d(24, 0))
        expected = [(23.43, -140.19), (23.43, -39.81), (54.08, -109.44), (54.08, -70.56)]
        vel_tol, deg_tol = 0.1, Rotation2d.fromDegrees(0.1).getDegrees()
        for (velocity, degrees), state in zip(expected, states):
            assert_close(velocity, state.velocity, vel_tol)
            assert_close(Rotation2d.fromDegrees(degrees).getDegrees(), state.angle.getDegrees(),
                         deg_tol)

    def test_off_center_cor_rotation_and_translation_forward_kinematics(self, kinematics):
        cv = kinematics.toChassisVelocities(
            SwerveModuleVelocity(23.43, Rotation2d.fromDegrees(-140.19)),
            SwerveModuleVelocity(23.43, Rotation2d.fromDegrees(-39.81)),
            SwerveModuleVelocity(54.08, Rotation2d.fromDegrees(-109.44)),
            SwerveModuleVelocity(54.08, Rotation2d.fromDegrees(-70.56)))
        assert_close(0.0, cv.vx, 0.1)
        assert_close(-33.0, cv.vy, 0.1)
        assert_close(1.5, cv.omega, 0.1)

    def test_off_center_cor_rotation_and_translation_forward_kinematics_with_deltas(
            self, kinematics):
        twist = kinematics.toTwist2d(
            SwerveModulePosition(23.43, Rotation2d.fromDegrees(-140.19)),
            SwerveModulePosition(23.43, Rotation2d.fromDegrees(-39.81)),
            SwerveModulePosition(54.08, Rotation2d.fromDegrees(-109.44)),
            SwerveModulePosition(54.08, Rotation2d.fromDegrees(-70.56)))
        assert_close(0.0, twist.dx, 0.1)
        assert_close(-33.0, twist.dy, 0.1)
        assert_close(1.5, twist.dtheta, 0.1)

    def test_desaturate(self):
        arr = [SwerveModuleVelocity(v, Rotation2d.kZero) for v in (5, 6, 4, 7)]
        out = SwerveDriveKinematics.desaturateWheelVelocities(arr, 5.5)
        factor = 5.5 / 7.0
        for v, s in zip((5.0, 6.0, 4.0, 7.0), out):
            assert_close(v * factor, s.velocity)

    def test_desaturate_smooth(self, kinematics):
        arr = [SwerveModuleVelocity(v, Rotation2d.kZero) for v in (5, 6, 4, 7)]
        out = SwerveDriveKinematics.desaturateWheelVelocities(
            arr, kinematics.toChassisVelocities(arr), 5.5, 5.5, 3.5)
        factor = 5.5 / 7.0
        for v, s in zip((5.0, 6.0, 4.0, 7.0), out):
            assert_close(v * factor, s.velocity)

    def test_desaturate_negative_velocity(self):
        arr = [SwerveModuleVelocity(v, Rotation2d.kZero) for v in (1, 1, -2, -2)]
        out = SwerveDriveKinematics.desaturateWheelVelocities(arr, 1)
        for v, s in zip((0.5, 0.5, -1.0, -1.0), out):
            assert_close(v, s.velocity)

    def test_turn_in_place_inverse_accelerations(self, kinematics):
        accelerations = ChassisAccelerations(0, 0, 2 * math.pi)
        angular_velocity = 2 * math.pi
        out = kinematics.toSwerveModuleAccelerations(accelerations, angular_velocity)

        center_radius = kinematics.getModules()[0].getNorm()
        tangential = center_radius * accelerations.alpha
        centripetal = center_radius * angular_velocity * angular_velocity
        total = math.hypot(tangential, centripetal)

        expected_angles = []
        for m in kinematics.getModules():
            radius_angle = m.getAngle()
            if radius_angle is None:
                radius_angle = Rotation2d.kZero
            tangential_dir = radius_angle.rotateBy(Rotation2d.kCCW_Pi_2)
            centripetal_dir = radius_angle.rotateBy(Rotation2d.kPi)
            x = tangential * tangential_dir.getCos() + centripetal * centripetal_dir.getCos()
            y = tangential * tangential_dir.getSin() + centripetal * centripetal_dir.getSin()
            expected_angles.append(Rotation2d(x, y))

        for a in out:
            assert_close(total, a.acceleration)
        for expected, a in zip(expected_angles, out):
            assert_close(expected.getDegrees(), a.angle.getDegrees())

    def test_turn_in_place_forward_accelerations(self, kinematics):
        ca = kinematics.toChassisAccelerations(
            SwerveModuleAcceleration(106.629, Rotation2d.fromDegrees(135)),
            SwerveModuleAcceleration(106.629, Rotation2d.fromDegrees(45)),
            SwerveModuleAcceleration(106.629, Rotation2d.fromDegrees(-135)),
            SwerveModuleAcceleration(106.629, Rotation2d.fromDegrees(-45)))
        assert_close(0.0, ca.ax)
        assert_close(0.0, ca.ay)
        assert_close(2 * math.pi, ca.alpha, 0.1)

    def test_off_center_rotation_inverse_accelerations(self, kinematics):
        accelerations = ChassisAccelerations(0, 0, 1)
        angular_velocity = 1.0
        out = kinematics.toSwerveModuleAccelerations(accelerations, angular_velocity, FL)

        expected_magnitudes = []
        expected_angles = []
        for m in kinematics.getModules():
            rel = m.minus(FL)
            r = rel.getNorm()
            if r < 1e-9:
                expected_magnitudes.append(0.0)
                expected_angles.append(Rotation2d.kZero)
                continue
            expected_magnitudes.append(math.hypot(r * accelerations.alpha,
                                                  r * angular_velocity * angular_velocity))
            radius_angle = Rotation2d(rel.getX(), rel.getY())
            tangential_dir = radius_angle.rotateBy(Rotation2d.kCCW_Pi_2)
            centripetal_dir = radius_angle.rotateBy(Rotation2d.kPi)
            x = tangential_dir.getCos() * r + centripetal_dir.getCos() * r
            y = tangential_dir.getSin() * r + centripetal_dir.getSin() * r
            expected_angles.append(Rotation2d(x, y))

        for expected, a in zip(expected_magnitudes, out):
            assert_close(expected, a.acceleration)
        for expected, a in zip(expected_angles, out):
            assert_close(expected.getDegrees(), a.angle.getDegrees())


# =========================================================================================
# Ported: SwerveModuleVelocityTest
# =========================================================================================
class TestSwerveModuleVelocity:
    def test_optimize(self):
        optimized_a = SwerveModuleVelocity(-2.0, Rotation2d.kPi).optimize(
            Rotation2d.fromDegrees(45))
        assert_close(2.0, optimized_a.velocity)
        assert_close(0.0, optimized_a.angle.getDegrees())

        optimized_b = SwerveModuleVelocity(4.7, Rotation2d.fromDegrees(41)).optimize(
            Rotation2d.fromDegrees(-50))
        assert_close(-4.7, optimized_b.velocity)
        assert_close(-139.0, optimized_b.angle.getDegrees())

    def test_no_optimize(self):
        optimized_a = SwerveModuleVelocity(2.0, Rotation2d.fromDegrees(89)).optimize(
            Rotation2d.kZero)
        assert_close(2.0, optimized_a.velocity)
        assert_close(89.0, optimized_a.angle.getDegrees())

        optimized_b = SwerveModuleVelocity(-2.0, Rotation2d.fromDegrees(-2)).optimize(
            Rotation2d.kZero)
        assert_close(-2.0, optimized_b.velocity)
        assert_close(-2.0, optimized_b.angle.getDegrees())

    @pytest.mark.parametrize(
        ("velocity", "current_deg", "expected_velocity"),
        [
            (2.0, 0.0, math.sqrt(2.0)),
            (2.0, 45.0, 2.0),
            (2.0, -45.0, 0.0),
            (2.0, 135.0, 0.0),
            (2.0, -135.0, -2.0),
            (2.0, 180.0, -math.sqrt(2.0)),
            (-2.0, 0.0, -math.sqrt(2.0)),
            (-2.0, 45.0, -2.0),
            (-2.0, -45.0, 0.0),
            (-2.0, 135.0, 0.0),
            (-2.0, -135.0, 2.0),
            (-2.0, 180.0, math.sqrt(2.0)),
        ],
    )
    def test_cosine_scale(self, velocity, current_deg, expected_velocity):
        ref = SwerveModuleVelocity(velocity, Rotation2d.fromDegrees(45.0))
        scaled = ref.cosineScale(Rotation2d.fromDegrees(current_deg))
        assert_close(expected_velocity, scaled.velocity)
        assert_close(45.0, scaled.angle.getDegrees())

    def test_interpolate(self):
        start = SwerveModuleVelocity(1.0, Rotation2d.fromDegrees(0.0))
        end = SwerveModuleVelocity(5.0, Rotation2d.fromDegrees(90.0))
        for t, velocity, degrees in ((0.0, 1.0, 0.0), (1.0, 5.0, 90.0), (0.5, 3.0, 45.0),
                                     (0.25, 2.0, 22.5),
                                     (-0.5, 1.0, 0.0),   # clamped to t = 0
                                     (1.5, 5.0, 90.0)):  # clamped to t = 1
            result = start.interpolate(end, t)
            assert_close(velocity, result.velocity)
            assert_close(degrees, result.angle.getDegrees())

        start_wrap = SwerveModuleVelocity(2.0, Rotation2d.fromDegrees(170.0))
        end_wrap = SwerveModuleVelocity(4.0, Rotation2d.fromDegrees(-170.0))
        mid = start_wrap.interpolate(end_wrap, 0.5)
        assert_close(3.0, mid.velocity)
        assert_close(180.0, abs(mid.angle.getDegrees()))


# =========================================================================================
# Ported: SwerveModulePositionTest (C++; no Java test on the 2027 branch)
# =========================================================================================
class TestSwerveModulePosition:
    def test_equality(self):
        assert (SwerveModulePosition(2.0, Rotation2d.fromDegrees(90))
                == SwerveModulePosition(2.0, Rotation2d.fromDegrees(90)))

    def test_inequality(self):
        position1 = SwerveModulePosition(1.0, Rotation2d.fromDegrees(90))
        position2 = SwerveModulePosition(2.0, Rotation2d.fromDegrees(90))
        position3 = SwerveModulePosition(1.0, Rotation2d.fromDegrees(89))
        assert position1 != position2
        assert position1 != position3


# =========================================================================================
# Ported: SwerveModuleAccelerationTest
# =========================================================================================
class TestSwerveModuleAcceleration:
    def test_default_constructor(self):
        a = SwerveModuleAcceleration()
        assert_close(0.0, a.acceleration)
        assert_close(0.0, a.angle.getRadians())

    def test_parameterized_constructor(self):
        a = SwerveModuleAcceleration(2.5, Rotation2d(1.5))
        assert_close(2.5, a.acceleration)
        assert_close(1.5, a.angle.getRadians())

    def test_equals(self):
        a1 = SwerveModuleAcceleration(2.0, Rotation2d(1.5))
        a2 = SwerveModuleAcceleration(2.0, Rotation2d(1.5))
        a3 = SwerveModuleAcceleration(2.1, Rotation2d(1.5))
        assert a1 == a2
        assert a1 != a3

    def test_compare_to(self):
        slower = SwerveModuleAcceleration(1.0, Rotation2d(2.0))
        faster = SwerveModuleAcceleration(2.0, Rotation2d(1.0))
        assert slower.compareTo(faster) < 0
        assert faster.compareTo(slower) > 0
        assert slower.compareTo(SwerveModuleAcceleration(1.0, Rotation2d(2.0))) == 0

    def test_interpolate(self):
        start = SwerveModuleAcceleration(1.0, Rotation2d(0.0))
        end = SwerveModuleAcceleration(5.0, Rotation2d(math.pi / 2))
        for t, acceleration, radians in ((0.0, 1.0, 0.0), (1.0, 5.0, math.pi / 2),
                                         (0.5, 3.0, math.pi / 4), (0.25, 2.0, math.pi / 8),
                                         (-0.5, 1.0, 0.0),           # clamped to t = 0
                                         (1.5, 5.0, math.pi / 2)):   # clamped to t = 1
            result = start.interpolate(end, t)
            assert_close(acceleration, result.acceleration)
            assert_close(radians, result.angle.getRadians())


# =========================================================================================
# Digest edge cases: SwerveDriveKinematics
# =========================================================================================
class TestHeadingMemory:
    def test_initial_headings_are_zero(self, kinematics):
        for s in kinematics.toSwerveModuleVelocities(ChassisVelocities()):
            assert s.velocity == 0.0
            assert_close(0.0, s.angle.getRadians())

    def test_module_on_cor_keeps_previous_heading(self, kinematics):
        # Strafe left (all modules to 90 deg), then spin about the front-left module: that
        # module has zero velocity and keeps 90 deg; the others point along omega x r.
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 5, 0))
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 0, 1), FL)
        assert_close(0.0, states[0].velocity)
        assert_close(90.0, states[0].angle.getDegrees())
        for i, m in enumerate((FR, BL, BR), start=1):
            x, y = module_velocity(m.getX() - 12, m.getY() - 12, 0.0, 0.0, 1.0)
            assert_close(math.hypot(x, y), states[i].velocity)
            assert_close(math.degrees(math.atan2(y, x)), states[i].angle.getDegrees())

    def test_speed_threshold_is_strictly_above_1e_6(self, kinematics):
        # speed <= 1e-6 keeps the stored heading (and still reports the tiny speed).
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 5, 0))
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities(1e-6, 0, 0))
        for s in states:
            assert_close(1e-6, s.velocity)
            assert_close(90.0, s.angle.getDegrees())
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities(2e-6, 0, 0))
        for s in states:
            assert_close(2e-6, s.velocity)
            assert_close(0.0, s.angle.getDegrees())

    def test_headings_written_on_every_nonzero_call(self, kinematics):
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 0, 1))
        kinematics.toSwerveModuleVelocities(ChassisVelocities(-3, 0, 0))
        for s in kinematics.toSwerveModuleVelocities(ChassisVelocities()):
            assert s.velocity == 0.0
            assert_close(180.0, abs(s.angle.getDegrees()))

    def test_zero_call_leaves_headings_alone(self, kinematics):
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0, -2, 0))
        kinematics.toSwerveModuleVelocities(ChassisVelocities())
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0.0, -0.0, 0.0))
        for s in kinematics.toSwerveModuleVelocities(ChassisVelocities()):
            assert_close(-90.0, s.angle.getDegrees())

    def test_heading_memory_is_per_instance(self, kinematics):
        other = SwerveDriveKinematics(FL, FR, BL, BR)
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 5, 0))
        for s in other.toSwerveModuleVelocities(ChassisVelocities()):
            assert_close(0.0, s.angle.getDegrees())
        for s in kinematics.toSwerveModuleVelocities(ChassisVelocities()):
            assert_close(90.0, s.angle.getDegrees())

    def test_reset_headings_overwrites(self, kinematics):
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 5, 0))
        headings = [Rotation2d.fromDegrees(d) for d in (10.0, -20.0, 30.0, -40.0)]
        kinematics.resetHeadings(*headings)
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities())
        for expected, s in zip((10.0, -20.0, 30.0, -40.0), states):
            assert_close(expected, s.angle.getDegrees())

    def test_reset_headings_wrong_count(self, kinematics):
        with pytest.raises(ValueError):
            kinematics.resetHeadings(Rotation2d.kZero, Rotation2d.kZero, Rotation2d.kZero)

    def test_to_wheel_velocities_is_the_same_path(self, kinematics):
        states = kinematics.toWheelVelocities(ChassisVelocities(1.0, 2.0, 0.5))
        for s, m in zip(states, (FL, FR, BL, BR)):
            x, y = module_velocity(m.getX(), m.getY(), 1.0, 2.0, 0.5)
            assert_close(math.hypot(x, y), s.velocity)
            assert_close(math.atan2(y, x), s.angle.getRadians())
        # ... and it writes the shared heading memory.
        for s, m in zip(kinematics.toSwerveModuleVelocities(ChassisVelocities()),
                        (FL, FR, BL, BR)):
            x, y = module_velocity(m.getX(), m.getY(), 1.0, 2.0, 0.5)
            assert_close(math.atan2(y, x), s.angle.getRadians())


class TestCenterOfRotation:
    def test_forward_matrix_fixed_at_origin(self, kinematics):
        # Inverse kinematics about FL, forward kinematics of the result: the forward matrix
        # was built for CoR (0, 0), so it reports the robot-centre motion. Spinning at 1 rad/s
        # about (12, 12), the centre (offset (-12, -12) from the CoR) moves at (12, -12).
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 0, 1), FL)
        cv = kinematics.toChassisVelocities(states)
        assert_close(12.0, cv.vx)
        assert_close(-12.0, cv.vy)
        assert_close(1.0, cv.omega)

    def test_forward_acceleration_matrix_fixed_at_origin(self, kinematics):
        # About FL with alpha = 1, omega = 1: the centre at r = (-12, -12) from the CoR has
        # alpha x r - omega^2 r = (12, -12) + (12, 12) = (24, 0); the omega^2 estimate is
        # dropped and alpha is returned.
        accels = kinematics.toSwerveModuleAccelerations(ChassisAccelerations(0, 0, 1), 1.0, FL)
        ca = kinematics.toChassisAccelerations(*accels)
        assert_close(24.0, ca.ax)
        assert_close(0.0, ca.ay)
        assert_close(1.0, ca.alpha)

    def test_cor_switches_back(self, kinematics):
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 0, 1), FL)
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 0, 1))
        for s, m in zip(states, (FL, FR, BL, BR)):
            x, y = module_velocity(m.getX(), m.getY(), 0.0, 0.0, 1.0)
            assert_close(math.hypot(x, y), s.velocity)
            assert_close(math.atan2(y, x), s.angle.getRadians())

    def test_cor_change_within_1e_9_does_not_rebuild(self, kinematics):
        # The requested CoR is compared with the previous one using Translation2d equality
        # (|dx|, |dy| < 1e-9), so a 9e-10 shift keeps the matrix built for (1, 1).
        omega = 1000.0
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 0, omega), Translation2d(1, 1))
        states = kinematics.toSwerveModuleVelocities(
            ChassisVelocities(0, 0, omega), Translation2d(1 + 9e-10, 1 + 9e-10))
        for s, m in zip(states, (FL, FR, BL, BR)):
            x, y = module_velocity(m.getX() - 1.0, m.getY() - 1.0, 0.0, 0.0, omega)
            assert_close(math.hypot(x, y), s.velocity)
        # A 2e-9 shift is a different CoR: rebuilt.
        cor = Translation2d(1 + 2e-9, 1 + 2e-9)
        states = kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 0, omega), cor)
        for s, m in zip(states, (FL, FR, BL, BR)):
            x, y = module_velocity(m.getX() - cor.getX(), m.getY() - cor.getY(), 0.0, 0.0, omega)
            assert_close(math.hypot(x, y), s.velocity)

    def test_cor_within_1e_9_of_origin_uses_origin(self, kinematics):
        omega = 1000.0
        states = kinematics.toSwerveModuleVelocities(
            ChassisVelocities(0, 0, omega), Translation2d(9e-10, -9e-10))
        for s, m in zip(states, (FL, FR, BL, BR)):
            x, y = module_velocity(m.getX(), m.getY(), 0.0, 0.0, omega)
            assert_close(math.hypot(x, y), s.velocity)


class TestForwardKinematicsForms:
    def test_to_twist2d_start_end_uses_end_angle(self, kinematics):
        start = [SwerveModulePosition(1.0, Rotation2d.kZero) for _ in range(4)]
        end = [SwerveModulePosition(6.0, Rotation2d.kCCW_Pi_2) for _ in range(4)]
        twist = kinematics.toTwist2d(start, end)
        assert_close(0.0, twist.dx)
        assert_close(5.0, twist.dy)
        assert_close(0.0, twist.dtheta)

    def test_to_twist2d_start_end_mismatched_lengths(self, kinematics):
        start = [SwerveModulePosition() for _ in range(4)]
        end = [SwerveModulePosition() for _ in range(3)]
        with pytest.raises(ValueError):
            kinematics.toTwist2d(start, end)

    def test_sequence_and_varargs_forms_agree(self, kinematics):
        states = [SwerveModuleVelocity(v, Rotation2d.fromDegrees(d))
                  for v, d in ((1.0, 10.0), (2.0, -30.0), (0.5, 100.0), (3.0, 45.0))]
        a = kinematics.toChassisVelocities(*states)
        b = kinematics.toChassisVelocities(states)
        assert (a.vx, a.vy, a.omega) == (b.vx, b.vy, b.omega)
        deltas = [SwerveModulePosition(s.velocity, s.angle) for s in states]
        ta = kinematics.toTwist2d(*deltas)
        tb = kinematics.toTwist2d(deltas)
        assert (ta.dx, ta.dy, ta.dtheta) == (tb.dx, tb.dy, tb.dtheta)
        assert (ta.dx, ta.dy, ta.dtheta) == (a.vx, a.vy, a.omega)

    def test_wrong_module_count(self, kinematics):
        three = [SwerveModuleVelocity() for _ in range(3)]
        with pytest.raises(ValueError):
            kinematics.toChassisVelocities(*three)
        with pytest.raises(ValueError):
            kinematics.toTwist2d(*[SwerveModulePosition() for _ in range(5)])
        with pytest.raises(ValueError):
            kinematics.toChassisAccelerations(*[SwerveModuleAcceleration() for _ in range(2)])

    def test_at_least_two_modules(self):
        with pytest.raises(ValueError):
            SwerveDriveKinematics(FL)
        with pytest.raises(ValueError):
            SwerveDriveKinematics([FL])
        with pytest.raises(ValueError):
            SwerveDriveKinematics()
        two = SwerveDriveKinematics(Translation2d(0, 1), Translation2d(0, -1))
        states = two.toSwerveModuleVelocities(ChassisVelocities(1, 0, 0))
        assert len(states) == 2

    def test_get_modules(self, kinematics):
        modules = kinematics.getModules()
        assert len(modules) == 4
        for expected, m in zip((FL, FR, BL, BR), modules):
            assert m == expected

    def test_interpolate_copy_copy_into(self, kinematics):
        start = [SwerveModulePosition(0.0, Rotation2d.fromDegrees(0.0)) for _ in range(4)]
        end = [SwerveModulePosition(10.0, Rotation2d.fromDegrees(90.0)) for _ in range(4)]
        # Per-module SwerveModulePosition.interpolate: not clamped.
        for p in kinematics.interpolate(start, end, 1.5):
            assert_close(15.0, p.distance)
            assert_close(135.0, p.angle.getDegrees())
        with pytest.raises(ValueError):
            kinematics.interpolate(start, end[:3], 0.5)

        copies = kinematics.copy(end)
        assert len(copies) == 4
        for c, e in zip(copies, end):
            assert c is not e
            assert c == e
        output = [SwerveModulePosition() for _ in range(4)]
        kinematics.copyInto(end, output)
        for o, e in zip(output, end):
            assert_close(e.distance, o.distance)
            assert o.angle == e.angle
        with pytest.raises(ValueError):
            kinematics.copyInto(end, output[:2])


class TestDesaturate:
    def test_two_arg_unsaturated_is_unchanged_copy(self):
        arr = [SwerveModuleVelocity(v, Rotation2d.fromDegrees(d))
               for v, d in ((1.0, 10.0), (-2.0, 20.0), (0.5, 30.0), (3.0, 40.0))]
        out = SwerveDriveKinematics.desaturateWheelVelocities(arr, 3.0)
        assert len(out) == 4
        for a, o in zip(arr, out):
            assert o is not a
            assert o.velocity == a.velocity
            assert o.angle == a.angle

    def test_two_arg_keeps_angles_and_inputs(self):
        arr = [SwerveModuleVelocity(v, Rotation2d.fromDegrees(d))
               for v, d in ((5.0, 10.0), (6.0, -20.0), (-4.0, 30.0), (7.0, 170.0))]
        out = SwerveDriveKinematics.desaturateWheelVelocities(arr, 5.5)
        for (v, d), a, o in zip(((5.0, 10.0), (6.0, -20.0), (-4.0, 30.0), (7.0, 170.0)),
                                arr, out):
            assert_close(v / 7.0 * 5.5, o.velocity)
            assert_close(d, o.angle.getDegrees())
            # 2027: a new array; the input is left alone.
            assert a.velocity == v
            assert o is not a

    def test_five_arg_scales_down_unsaturated_states(self):
        # k = max(|(1, 0)| / 5.5, 0 / 3.5) = 1/5.5; scale = min(k * 5.5 / 7, 1) = 1/7.
        arr = [SwerveModuleVelocity(v, Rotation2d.kZero) for v in (5, 6, 4, 7)]
        out = SwerveDriveKinematics.desaturateWheelVelocities(
            arr, ChassisVelocities(1, 0, 0), 5.5, 5.5, 3.5)
        for v, o in zip((5.0, 6.0, 4.0, 7.0), out):
            assert_close(v / 7.0, o.velocity)
        for v, a in zip((5.0, 6.0, 4.0, 7.0), arr):
            assert a.velocity == v

    def test_five_arg_rotational_term(self):
        # k = max(hypot(0.3, 0.4) / 4, |-2| / 4) = 0.5; scale = min(0.5 * 4 / 8, 1) = 0.25.
        arr = [SwerveModuleVelocity(v, Rotation2d.kZero) for v in (2, -8, 4, 1)]
        out = SwerveDriveKinematics.desaturateWheelVelocities(
            arr, ChassisVelocities(0.3, 0.4, -2.0), 4.0, 4.0, 4.0)
        for v, o in zip((2.0, -8.0, 4.0, 1.0), out):
            assert_close(v * 0.25, o.velocity)

    def test_five_arg_scale_clamped_to_one(self):
        # k * maxModule / realMax = (100 / 5.5) * 5.5 / 7 > 1 -> scale 1, states unchanged
        # even though 7 > 5.5.
        arr = [SwerveModuleVelocity(v, Rotation2d.kZero) for v in (5, 6, 4, 7)]
        out = SwerveDriveKinematics.desaturateWheelVelocities(
            arr, ChassisVelocities(100, 0, 0), 5.5, 5.5, 3.5)
        for v, o in zip((5.0, 6.0, 4.0, 7.0), out):
            assert_close(v, o.velocity)

    @pytest.mark.parametrize(
        ("speeds", "max_trans", "max_rot"),
        [
            ((5, 6, 4, 7), 0.0, 3.5),   # attainable translational velocity 0
            ((5, 6, 4, 7), 5.5, 0.0),   # attainable rotational velocity 0
            ((0, 0, 0, 0), 5.5, 3.5),   # every module at rest
        ],
    )
    def test_five_arg_guards_return_unchanged_copies(self, speeds, max_trans, max_rot):
        arr = [SwerveModuleVelocity(v, Rotation2d.fromDegrees(15.0 * i))
               for i, v in enumerate(speeds)]
        out = SwerveDriveKinematics.desaturateWheelVelocities(
            arr, ChassisVelocities(1, 0, 0), 5.5, max_trans, max_rot)
        assert len(out) == 4
        for a, o in zip(arr, out):
            assert o is not a
            assert o.velocity == a.velocity
            assert o.angle == a.angle


class TestSecondOrderSwerve:
    def test_zero_acceleration_ignores_angular_velocity(self, kinematics):
        # Early return on ax == ay == alpha == 0: the centripetal term is skipped.
        for a in kinematics.toSwerveModuleAccelerations(ChassisAccelerations(), 5.0):
            assert a.acceleration == 0.0
            assert_close(0.0, a.angle.getRadians())

    def test_zero_acceleration_ignores_heading_memory(self, kinematics):
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 5, 0))
        for a in kinematics.toSwerveModuleAccelerations(ChassisAccelerations(), 0.0):
            assert_close(0.0, a.angle.getDegrees())

    def test_zero_magnitude_module_gets_angle_zero(self, kinematics):
        # About FL with alpha = 1, omega = 0 the FL module's acceleration is zero: its angle
        # is Rotation2d 0, not a remembered heading.
        kinematics.toSwerveModuleVelocities(ChassisVelocities(0, 5, 0))
        out = kinematics.toSwerveModuleAccelerations(ChassisAccelerations(0, 0, 1), 0.0, FL)
        assert_close(0.0, out[0].acceleration)
        assert_close(0.0, out[0].angle.getDegrees())
        # FR at r = (0, -24): alpha x r = (24, 0).
        assert_close(24.0, out[1].acceleration)
        assert_close(0.0, out[1].angle.getDegrees())

    def test_magnitude_threshold_1e_6(self, kinematics):
        # |a| <= 1e-6 -> angle 0; just above -> the real direction.
        out = kinematics.toSwerveModuleAccelerations(ChassisAccelerations(0, 1e-6, 0), 0.0)
        for a in out:
            assert_close(1e-6, a.acceleration)
            assert_close(0.0, a.angle.getDegrees())
        out = kinematics.toSwerveModuleAccelerations(ChassisAccelerations(0, 2e-6, 0), 0.0)
        for a in out:
            assert_close(2e-6, a.acceleration)
            assert_close(90.0, a.angle.getDegrees())

    def test_turn_in_place_numbers(self, kinematics):
        out = kinematics.toSwerveModuleAccelerations(
            ChassisAccelerations(0, 0, 2 * math.pi), 2 * math.pi)
        for a in out:
            assert_close(678.403180825929, a.acceleration)
        assert_close(-144.0430610790377, out[0].angle.getDegrees())

    def test_closed_form_with_translation(self, kinematics):
        ax, ay, alpha, omega = 1.5, -0.5, 0.75, 2.0
        out = kinematics.toSwerveModuleAccelerations(ChassisAccelerations(ax, ay, alpha), omega)
        for a, m in zip(out, (FL, FR, BL, BR)):
            rx, ry = m.getX(), m.getY()
            x = ax - omega * omega * rx - alpha * ry
            y = ay - omega * omega * ry + alpha * rx
            assert_close(math.hypot(x, y), a.acceleration)
            assert_close(math.atan2(y, x), a.angle.getRadians())

    def test_forward_returns_alpha_and_drops_omega_squared(self, kinematics):
        out = kinematics.toSwerveModuleAccelerations(
            ChassisAccelerations(0.5, -1.0, 2 * math.pi), 2 * math.pi)
        ca = kinematics.toChassisAccelerations(*out)
        assert_close(0.5, ca.ax)
        assert_close(-1.0, ca.ay)
        assert_close(2 * math.pi, ca.alpha)

    def test_to_wheel_accelerations_uses_zero_angular_velocity(self, kinematics):
        out = kinematics.toWheelAccelerations(ChassisAccelerations(0, 0, 1))
        for a, m in zip(out, (FL, FR, BL, BR)):
            x, y = -m.getY(), m.getX()
            assert_close(math.hypot(x, y), a.acceleration)
            assert_close(math.atan2(y, x), a.angle.getRadians())


# =========================================================================================
# Digest edge cases: module value classes
# =========================================================================================
class TestModuleValueEdgeCases:
    def test_defaults(self):
        v = SwerveModuleVelocity()
        assert v.velocity == 0.0
        assert_close(0.0, v.angle.getRadians())
        p = SwerveModulePosition()
        assert p.distance == 0.0
        assert_close(0.0, p.angle.getRadians())

    def test_mutable_fields(self):
        v = SwerveModuleVelocity(1.0, Rotation2d.kZero)
        v.velocity = 2.5
        v.angle = Rotation2d.kCCW_Pi_2
        assert v.velocity == 2.5
        assert_close(90.0, v.angle.getDegrees())
        p = SwerveModulePosition(1.0, Rotation2d.kZero)
        p.distance = -3.0
        p.angle = Rotation2d.kPi
        assert p.distance == -3.0
        assert_close(180.0, abs(p.angle.getDegrees()))

    def test_optimize_returns_new_object(self):
        ref = SwerveModuleVelocity(4.7, Rotation2d.fromDegrees(41))
        optimized = ref.optimize(Rotation2d.fromDegrees(-50))
        assert optimized is not ref
        assert ref.velocity == 4.7
        assert_close(41.0, ref.angle.getDegrees())
        unchanged = ref.optimize(Rotation2d.fromDegrees(30))
        assert unchanged is not ref
        assert_close(4.7, unchanged.velocity)
        assert_close(41.0, unchanged.angle.getDegrees())

    def test_cosine_scale_returns_new_object(self):
        ref = SwerveModuleVelocity(2.0, Rotation2d.fromDegrees(45.0))
        scaled = ref.cosineScale(Rotation2d.kZero)
        assert scaled is not ref
        assert ref.velocity == 2.0

    def test_velocity_equality_tolerance(self):
        base = SwerveModuleVelocity(1.0, Rotation2d.fromDegrees(30.0))
        assert base == SwerveModuleVelocity(1.0 + 5e-10, Rotation2d.fromDegrees(30.0))
        assert base != SwerveModuleVelocity(1.0 + 2e-9, Rotation2d.fromDegrees(30.0))
        assert base != SwerveModuleVelocity(1.0, Rotation2d.fromDegrees(30.001))
        assert (SwerveModuleVelocity(1.0, Rotation2d.fromDegrees(180.0))
                == SwerveModuleVelocity(1.0, Rotation2d.fromDegrees(-180.0)))

    def test_position_and_acceleration_equality_tolerance(self):
        assert (SwerveModulePosition(2.0, Rotation2d(0.5))
                == SwerveModulePosition(2.0 - 5e-10, Rotation2d(0.5)))
        assert (SwerveModulePosition(2.0, Rotation2d(0.5))
                != SwerveModulePosition(2.0 - 2e-9, Rotation2d(0.5)))
        assert (SwerveModuleAcceleration(2.0, Rotation2d(0.5))
                == SwerveModuleAcceleration(2.0 + 5e-10, Rotation2d(0.5)))
        assert (SwerveModuleAcceleration(2.0, Rotation2d(0.5))
                != SwerveModuleAcceleration(2.0 + 2e-9, Rotation2d(0.5)))

    def test_compare_to_uses_double_compare(self):
        # Only the scalar is compared, with Double.compare (-1/0/1, 0.0 > -0.0, NaN largest).
        for cls in (SwerveModuleVelocity, SwerveModulePosition, SwerveModuleAcceleration):
            a = cls(1.0, Rotation2d(2.0))
            b = cls(2.0, Rotation2d(1.0))
            assert a.compareTo(b) == -1
            assert b.compareTo(a) == 1
            assert a.compareTo(cls(1.0, Rotation2d(-3.0))) == 0
            assert cls(0.0, Rotation2d()).compareTo(cls(-0.0, Rotation2d())) == 1
            assert cls(float("nan"), Rotation2d()).compareTo(cls(1e300, Rotation2d())) == 1

    def test_position_copy(self):
        p = SwerveModulePosition(3.0, Rotation2d.fromDegrees(-60.0))
        c = p.copy()
        assert c is not p
        assert c == p
        c.distance = 4.0
        assert p.distance == 3.0

    def test_position_interpolate_not_clamped(self):
        start = SwerveModulePosition(0.0, Rotation2d.fromDegrees(0.0))
        end = SwerveModulePosition(10.0, Rotation2d.fromDegrees(90.0))
        for t, distance, degrees in ((0.5, 5.0, 45.0), (1.5, 15.0, 135.0), (-0.5, -5.0, -45.0)):
            result = start.interpolate(end, t)
            assert_close(distance, result.distance)
            assert_close(degrees, result.angle.getDegrees())

    def test_str(self):
        assert (str(SwerveModuleVelocity(1.005, Rotation2d.kPi))
                == "SwerveModuleVelocity(Velocity: 1.01 m/s, "
                   "Angle: Rotation2d(Rads: 3.14, Deg: 180.00))")
        assert (str(SwerveModulePosition(-0.125, Rotation2d.kCCW_Pi_2))
                == "SwerveModulePosition(Distance: -0.13 m, "
                   "Angle: Rotation2d(Rads: 1.57, Deg: 90.00))")
        # The class is SwerveModuleAcceleration, the string says "Accelerations" (sic).
        assert (str(SwerveModuleAcceleration(2.675, Rotation2d.kZero))
                == "SwerveModuleAccelerations(Acceleration: 2.68 m/s², "
                   "Angle: Rotation2d(Rads: 0.00, Deg: 0.00))")
