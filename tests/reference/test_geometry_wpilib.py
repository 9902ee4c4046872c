"""WPILib 2027 geometry unit tests (Translation2d, Rotation2d, Pose2d, Transform2d, Twist2d),
restated for drivekin, plus the 2027 edge cases from the behaviour digest
(/work/shared/reference/wpilib-kinematics.md, sections 2, 3 and 13).

Source of the ported cases: wpilibsuite/allwpilib main @ caf0fb2d,
wpimath/src/test/java/org/wpilib/math/geometry/{Translation2d,Rotation2d,Pose2d,Transform2d,
Twist2d}Test.java. Expected numbers come from those tests or from closed forms written here;
the tolerance is WPILib's kEpsilon = 1e-9 unless a case needs to be tighter to tell two
branches apart.

Not ported (no counterpart in drivekin's documented API): the units-library constructors
(``testNewWithMeasures``) and the matrix / vector constructors used by ``testToMatrix`` and
``testToVector`` (``new Rotation2d(Matrix)``, ``new Pose2d(Matrix)``, ``new Transform2d(Matrix)``,
``new Translation2d(Vector)``); ``toMatrix()`` / ``toVector()`` are checked against closed forms
instead.
"""
import math

import numpy as np

from drivekin import Pose2d, Rotation2d, Transform2d, Translation2d, Twist2d
from tests._support.wpilib_port import assert_close


# =========================================================================================
# Ported: Translation2dTest
# =========================================================================================
class TestTranslation2d:
    def test_sum(self):
        total = Translation2d(1.0, 3.0).plus(Translation2d(2.0, 5.0))
        assert_close(3.0, total.getX())
        assert_close(8.0, total.getY())

    def test_difference(self):
        diff = Translation2d(1.0, 3.0).minus(Translation2d(2.0, 5.0))
        assert_close(-1.0, diff.getX())
        assert_close(-2.0, diff.getY())

    def test_rotate_by(self):
        rotated = Translation2d(3.0, 0.0).rotateBy(Rotation2d.kCCW_Pi_2)
        assert_close(0.0, rotated.getX())
        assert_close(3.0, rotated.getY())

    def test_rotate_around(self):
        rotated = Translation2d(2.0, 1.0).rotateAround(
            Translation2d(3.0, 2.0), Rotation2d.fromDegrees(180.0))
        assert_close(4.0, rotated.getX())
        assert_close(3.0, rotated.getY())

    def test_multiplication(self):
        product = Translation2d(3.0, 5.0).times(3)
        assert_close(9.0, product.getX())
        assert_close(15.0, product.getY())

    def test_division(self):
        quotient = Translation2d(3.0, 5.0).div(2)
        assert_close(1.5, quotient.getX())
        assert_close(2.5, quotient.getY())

    def test_norm(self):
        assert_close(math.hypot(3.0, 5.0), Translation2d(3.0, 5.0).getNorm())

    def test_squared_norm(self):
        assert_close(34.0, Translation2d(3.0, 5.0).getSquaredNorm())

    def test_distance(self):
        assert_close(5.0 * math.sqrt(2.0), Translation2d(1, 1).getDistance(Translation2d(6, 6)))

    def test_squared_distance(self):
        assert_close(50.0, Translation2d(1, 1).getSquaredDistance(Translation2d(6, 6)))

    def test_unary_minus(self):
        inverted = Translation2d(-4.5, 7).unaryMinus()
        assert_close(4.5, inverted.getX())
        assert_close(-7.0, inverted.getY())

    def test_equality(self):
        assert Translation2d(9, 5.5) == Translation2d(9, 5.5)

    def test_inequality(self):
        assert Translation2d(9, 5.5) != Translation2d(9, 5.7)

    def test_polar_constructor(self):
        one = Translation2d(math.sqrt(2), Rotation2d.fromDegrees(45.0))
        two = Translation2d(2, Rotation2d.fromDegrees(60.0))
        assert_close(1.0, one.getX())
        assert_close(1.0, one.getY())
        assert_close(1.0, two.getX())
        assert_close(math.sqrt(3.0), two.getY())

    def test_nearest(self):
        origin = Translation2d.kZero
        t1 = Translation2d(1, Rotation2d.fromDegrees(45))
        t2 = Translation2d(2, Rotation2d.kCCW_Pi_2)
        t3 = Translation2d(3, Rotation2d.fromDegrees(135))
        t4 = Translation2d(4, Rotation2d.kPi)
        t5 = Translation2d(5, Rotation2d.kCW_Pi_2)
        assert origin.nearest([t5, t3, t4]) == t3
        assert origin.nearest([t1, t2, t3]) == t1
        assert origin.nearest([t4, t2, t3]) == t2

    def test_to_vector(self):
        # WPILib builds the translation from a vector; drivekin has no vector constructor,
        # so only the getters and toVector() are checked.
        translation = Translation2d(1.0, 2.0)
        assert translation.getX() == 1.0
        assert translation.getY() == 2.0
        vector = translation.toVector()
        assert vector.shape == (2,)
        assert np.array_equal(vector, np.array([1.0, 2.0]))

    def test_dot(self):
        assert_close(18.0, Translation2d(2.0, 3.0).dot(Translation2d(3.0, 4.0)))

    def test_cross(self):
        assert_close(-1.0, Translation2d(2.0, 3.0).cross(Translation2d(3.0, 4.0)))


# =========================================================================================
# Ported: Rotation2dTest
# =========================================================================================
class TestRotation2d:
    def test_radians_to_degrees(self):
        assert_close(60.0, Rotation2d.fromRadians(math.pi / 3).getDegrees())
        assert_close(45.0, Rotation2d.fromRadians(math.pi / 4).getDegrees())

    def test_radians_and_degrees(self):
        assert_close(math.pi / 4.0, Rotation2d.fromDegrees(45.0).getRadians())
        assert_close(math.pi / 6.0, Rotation2d.fromDegrees(30.0).getRadians())

    def test_rotate_by_from_zero(self):
        rotated = Rotation2d.kZero.rotateBy(Rotation2d.kCCW_Pi_2)
        assert_close(math.pi / 2.0, rotated.getRadians())
        assert_close(90.0, rotated.getDegrees())

    def test_rotate_by_non_zero(self):
        rot = Rotation2d.kCCW_Pi_2.plus(Rotation2d.fromDegrees(30.0))
        assert_close(120.0, rot.getDegrees())

    def test_relative_to(self):
        result = Rotation2d.kCCW_Pi_2.relativeTo(Rotation2d.fromDegrees(30.0))
        assert_close(60.0, result.getDegrees())

    def test_minus(self):
        assert_close(40.0, Rotation2d.fromDegrees(70.0).minus(Rotation2d.fromDegrees(30.0))
                     .getDegrees())

    def test_unary_minus(self):
        assert_close(-20.0, Rotation2d.fromDegrees(20.0).unaryMinus().getDegrees())

    def test_multiply(self):
        rot = Rotation2d.fromDegrees(10.0)
        assert_close(30.0, rot.times(3.0).getDegrees())
        # 410 deg wraps to 50 deg.
        assert_close(50.0, rot.times(41.0).getDegrees())

    def test_equality(self):
        assert Rotation2d.fromDegrees(43.0) == Rotation2d.fromDegrees(43.0)
        assert Rotation2d.fromDegrees(-180.0) == Rotation2d.fromDegrees(180.0)

    def test_inequality(self):
        assert Rotation2d.fromDegrees(43.0) != Rotation2d.fromDegrees(43.5)

    def test_to_matrix(self):
        # WPILib round-trips through new Rotation2d(Matrix); drivekin has no matrix
        # constructor, so the matrix is checked against [[cos, -sin], [sin, cos]].
        theta = math.radians(20.0)
        m = Rotation2d.fromDegrees(20.0).toMatrix()
        assert m.shape == (2, 2)
        expected = [[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]]
        for i in range(2):
            for j in range(2):
                assert_close(expected[i][j], m[i, j])

    def test_interpolate(self):
        interpolated = Rotation2d.fromDegrees(50).interpolate(Rotation2d.fromDegrees(70), 0.5)
        assert_close(60.0, interpolated.getDegrees())
        # Shortest way round across +-180: 170 -> -160 is +30 deg, half of it lands on -175.
        interpolated = Rotation2d.fromDegrees(170).interpolate(Rotation2d.fromDegrees(-160), 0.5)
        assert_close(-175.0, interpolated.getDegrees())


# =========================================================================================
# Ported: Pose2dTest
# =========================================================================================
class TestPose2d:
    def test_rotate_by(self):
        x, y = 1.0, 2.0
        initial = Pose2d(Translation2d(x, y), Rotation2d.fromDegrees(45.0))
        rotation = Rotation2d.fromDegrees(5.0)
        rotated = initial.rotateBy(rotation)
        c, s = rotation.getCos(), rotation.getSin()
        assert_close(c * x - s * y, rotated.getX())
        assert_close(s * x + c * y, rotated.getY())
        assert_close(initial.getRotation().getDegrees() + rotation.getDegrees(),
                     rotated.getRotation().getDegrees())

    def test_transform_by(self):
        initial = Pose2d(Translation2d(1.0, 2.0), Rotation2d.fromDegrees(45.0))
        transformation = Transform2d(Translation2d(5.0, 0.0), Rotation2d.fromDegrees(5.0))
        transformed = initial.plus(transformation)
        assert_close(1.0 + 5.0 / math.sqrt(2.0), transformed.getX())
        assert_close(2.0 + 5.0 / math.sqrt(2.0), transformed.getY())
        assert_close(50.0, transformed.getRotation().getDegrees())

    def test_relative_to(self):
        initial = Pose2d(0.0, 0.0, Rotation2d.fromDegrees(45.0))
        last = Pose2d(5.0, 5.0, Rotation2d.fromDegrees(45.0))
        relative = last.relativeTo(initial)
        assert_close(5.0 * math.sqrt(2.0), relative.getX())
        assert_close(0.0, relative.getY())
        assert_close(0.0, relative.getRotation().getDegrees())

    def test_rotate_around(self):
        rotated = Pose2d(5, 0, Rotation2d.kZero).rotateAround(Translation2d.kZero, Rotation2d.kPi)
        assert_close(-5.0, rotated.getX())
        assert_close(0.0, rotated.getY())
        assert_close(180.0, rotated.getRotation().getDegrees())

    def test_equality(self):
        assert (Pose2d(0.0, 5.0, Rotation2d.fromDegrees(43.0))
                == Pose2d(0.0, 5.0, Rotation2d.fromDegrees(43.0)))

    def test_inequality(self):
        assert (Pose2d(0.0, 5.0, Rotation2d.fromDegrees(43.0))
                != Pose2d(0.0, 1.524, Rotation2d.fromDegrees(43.0)))

    def test_to_matrix(self):
        # WPILib round-trips through new Pose2d(Matrix); checked against the closed form.
        theta = math.radians(20.0)
        c, s = math.cos(theta), math.sin(theta)
        m = Pose2d(1.0, 2.0, Rotation2d.fromDegrees(20.0)).toMatrix()
        assert m.shape == (3, 3)
        expected = [[c, -s, 1.0], [s, c, 2.0], [0.0, 0.0, 1.0]]
        for i in range(3):
            for j in range(3):
                assert_close(expected[i][j], m[i, j])

    def test_minus(self):
        initial = Pose2d(0.0, 0.0, Rotation2d.fromDegrees(45.0))
        last = Pose2d(5.0, 5.0, Rotation2d.fromDegrees(45.0))
        transform = last.minus(initial)
        assert isinstance(transform, Transform2d)
        assert_close(5.0 * math.sqrt(2.0), transform.getX())
        assert_close(0.0, transform.getY())
        assert_close(0.0, transform.getRotation().getDegrees())

    def test_nearest(self):
        origin = Pose2d.kZero
        pose1 = Pose2d(Translation2d(1, Rotation2d.fromDegrees(45)), Rotation2d.kZero)
        pose2 = Pose2d(Translation2d(2, Rotation2d.kCCW_Pi_2), Rotation2d.kZero)
        pose3 = Pose2d(Translation2d(3, Rotation2d.fromDegrees(135)), Rotation2d.kZero)
        pose4 = Pose2d(Translation2d(4, Rotation2d.kPi), Rotation2d.kZero)
        pose5 = Pose2d(Translation2d(5, Rotation2d.kCW_Pi_2), Rotation2d.kZero)
        assert origin.nearest([pose5, pose3, pose4]) == pose3
        assert origin.nearest([pose1, pose2, pose3]) == pose1
        assert origin.nearest([pose4, pose2, pose3]) == pose2

        # Same distance everywhere: the smallest heading difference wins.
        translation = Translation2d(1, Rotation2d.kZero)
        pose_a = Pose2d(translation, Rotation2d.kZero)
        pose_b = Pose2d(translation, Rotation2d.fromDegrees(30))
        pose_c = Pose2d(translation, Rotation2d.fromDegrees(120))
        pose_d = Pose2d(translation, Rotation2d.kCCW_Pi_2)
        pose_e = Pose2d(translation, Rotation2d.fromDegrees(-180))
        assert Pose2d(0, 0, Rotation2d.fromDegrees(360)).nearest([pose_a, pose_b, pose_d]) == pose_a
        assert Pose2d(0, 0, Rotation2d.fromDegrees(-335)).nearest([pose_b, pose_c, pose_d]) == pose_b
        assert Pose2d(0, 0, Rotation2d.fromDegrees(-120)).nearest([pose_b, pose_c, pose_d]) == pose_c
        assert Pose2d(0, 0, Rotation2d.fromDegrees(85)).nearest([pose_a, pose_c, pose_d]) == pose_d
        assert Pose2d(0, 0, Rotation2d.fromDegrees(170)).nearest([pose_a, pose_d, pose_e]) == pose_e


# =========================================================================================
# Ported: Transform2dTest
# =========================================================================================
class TestTransform2d:
    def test_to_matrix(self):
        # WPILib round-trips through new Transform2d(Matrix); checked against the closed form.
        theta = math.radians(20.0)
        c, s = math.cos(theta), math.sin(theta)
        m = Transform2d(1.0, 2.0, Rotation2d.fromDegrees(20.0)).toMatrix()
        assert m.shape == (3, 3)
        expected = [[c, -s, 1.0], [s, c, 2.0], [0.0, 0.0, 1.0]]
        for i in range(3):
            for j in range(3):
                assert_close(expected[i][j], m[i, j])

    def test_inverse(self):
        initial = Pose2d(Translation2d(1.0, 2.0), Rotation2d.fromDegrees(45.0))
        transform = Transform2d(Translation2d(5.0, 0.0), Rotation2d.fromDegrees(5.0))
        untransformed = initial.plus(transform).plus(transform.inverse())
        assert untransformed == initial

    def test_composition(self):
        initial = Pose2d(Translation2d(1.0, 2.0), Rotation2d.fromDegrees(45.0))
        transform1 = Transform2d(Translation2d(5.0, 0.0), Rotation2d.fromDegrees(5.0))
        transform2 = Transform2d(Translation2d(0.0, 2.0), Rotation2d.fromDegrees(5.0))
        separate = initial.plus(transform1).plus(transform2)
        combined = initial.plus(transform1.plus(transform2))
        assert separate == combined


# =========================================================================================
# Ported: Twist2dTest
# =========================================================================================
class TestTwist2d:
    def test_straight(self):
        assert Twist2d(5.0, 0.0, 0.0).exp() == Transform2d(5.0, 0.0, Rotation2d.kZero)

    def test_quarter_circle(self):
        quarter = Twist2d(5.0 / 2.0 * math.pi, 0, math.pi / 2.0)
        assert quarter.exp() == Transform2d(5.0, 5.0, Rotation2d.kCCW_Pi_2)

    def test_diagonal_no_dtheta(self):
        assert Twist2d(2.0, 2.0, 0.0).exp() == Transform2d(2.0, 2.0, Rotation2d.kZero)

    def test_equality(self):
        assert Twist2d(5, 1, 3) == Twist2d(5, 1, 3)

    def test_inequality(self):
        assert Twist2d(5, 1, 3) != Twist2d(5, 1.2, 3)

    def test_pose2d_log(self):
        start = Pose2d.kZero
        end = Pose2d(5.0, 5.0, Rotation2d.kCCW_Pi_2)
        twist = end.minus(start).log()
        assert twist == Twist2d(5.0 / 2.0 * math.pi, 0.0, math.pi / 2.0)
        assert start.plus(twist.exp()) == end


# =========================================================================================
# Digest edge cases (2027 semantics) not covered by the WPILib tests above
# =========================================================================================
class TestRotation2dEdgeCases2027:
    def test_get_degrees_wraps(self):
        # 2027 stores only (cos, sin): the constructor angle is not remembered.
        assert_close(-90.0, Rotation2d(3 * math.pi / 2).getDegrees())
        assert_close(-math.pi / 2, Rotation2d(3 * math.pi / 2).getRadians())
        assert_close(-0.25, Rotation2d.fromRotations(0.75).getRotations())
        assert_close(20.0, Rotation2d.fromDegrees(380.0).getDegrees())

    def test_get_radians_range(self):
        for deg in (-720.0, -540.0, -190.0, -180.0, 0.0, 179.0, 181.0, 359.0, 900.0):
            rad = Rotation2d.fromDegrees(deg).getRadians()
            assert -math.pi <= rad <= math.pi

    def test_minus_three_pi_is_minus_pi(self):
        # sin(-3*pi) is a tiny negative number, so atan2 lands on exactly -pi.
        rad = Rotation2d(-3 * math.pi).getRadians()
        assert_close(-math.pi, rad)
        assert rad < 0.0

    def test_times_scales_wrapped_angle(self):
        # 270 deg is stored as -90 deg; half of it is -45 deg (2026 gave 135 deg).
        assert_close(-45.0, Rotation2d.fromDegrees(270.0).times(0.5).getDegrees())
        assert_close(-45.0, Rotation2d.fromDegrees(270.0).div(2.0).getDegrees())

    def test_interpolate_not_clamped(self):
        start = Rotation2d.fromDegrees(0.0)
        end = Rotation2d.fromDegrees(90.0)
        assert_close(135.0, start.interpolate(end, 1.5).getDegrees())
        assert_close(-45.0, start.interpolate(end, -0.5).getDegrees())
        assert_close(0.0, start.interpolate(end, 0.0).getDegrees())
        assert_close(90.0, start.interpolate(end, 1.0).getDegrees())

    def test_xy_constructor_normalises(self):
        rot = Rotation2d(3.0, 4.0)
        assert_close(0.6, rot.getCos())
        assert_close(0.8, rot.getSin())
        assert_close(0.8 / 0.6, rot.getTan())

    def test_xy_constructor_near_zero_gives_identity(self):
        # Magnitude <= 1e-6 -> identity, reported but not raised.
        for x, y in ((0.0, 0.0), (1e-7, 1e-7), (7e-7, 7e-7), (-1e-6, 0.0)):
            rot = Rotation2d(x, y)
            assert rot.getCos() == 1.0
            assert rot.getSin() == 0.0
        # hypot(1e-6, 1e-6) > 1e-6: a real direction.
        assert_close(45.0, Rotation2d(1e-6, 1e-6).getDegrees())

    def test_constants(self):
        assert_close(0.0, Rotation2d.kZero.getRadians())
        assert_close(-math.pi / 2, Rotation2d.kCW_Pi_2.getRadians())
        assert_close(-math.pi / 2, Rotation2d.kCW_90deg.getRadians())
        assert_close(math.pi / 2, Rotation2d.kCCW_Pi_2.getRadians())
        assert_close(math.pi / 2, Rotation2d.kCCW_90deg.getRadians())
        assert_close(math.pi, abs(Rotation2d.kPi.getRadians()))
        assert_close(180.0, abs(Rotation2d.k180deg.getDegrees()))

    def test_equality_tolerance(self):
        # hypot(dcos, dsin) < 1e-9, i.e. an angle difference below 1e-9 rad.
        assert Rotation2d(0.0) == Rotation2d(5e-10)
        assert Rotation2d(0.0) != Rotation2d(2e-9)
        assert Rotation2d(math.pi) == Rotation2d(-math.pi)
        assert Rotation2d.fromDegrees(10.0) == Rotation2d.fromDegrees(370.0)

    def test_equality_with_other_types_is_false(self):
        assert not (Rotation2d() == Translation2d())
        assert Rotation2d() != 0.0


class TestTranslation2dEdgeCases2027:
    def test_get_angle_optional(self):
        # 2027 returns an empty Optional (None here) when the norm is <= 1e-6.
        assert Translation2d(0.0, 0.0).getAngle() is None
        assert Translation2d(1e-6, 0.0).getAngle() is None
        assert Translation2d(0.0, -7e-7).getAngle() is None
        angle = Translation2d(0.0, 2e-6).getAngle()
        assert angle is not None
        assert_close(90.0, angle.getDegrees())
        assert_close(math.atan2(4.0, 3.0), Translation2d(3.0, 4.0).getAngle().getRadians())

    def test_equality_tolerance(self):
        # Each component within 1e-9 (strict).
        assert Translation2d(1.0, 2.0) == Translation2d(1.0 + 5e-10, 2.0 - 5e-10)
        assert Translation2d(1.0, 2.0) != Translation2d(1.0 + 2e-9, 2.0)
        assert Translation2d(1.0, 2.0) != Translation2d(1.0, 2.0 - 2e-9)
        assert not (Translation2d() == Rotation2d())

    def test_interpolate_not_clamped(self):
        start = Translation2d(0.0, 0.0)
        end = Translation2d(10.0, 20.0)
        mid = start.interpolate(end, 0.5)
        assert_close(5.0, mid.getX())
        assert_close(10.0, mid.getY())
        beyond = start.interpolate(end, 1.5)
        assert_close(15.0, beyond.getX())
        assert_close(30.0, beyond.getY())
        before = start.interpolate(end, -0.5)
        assert_close(-5.0, before.getX())
        assert_close(-10.0, before.getY())


class TestPose2dTransform2dEdgeCases2027:
    def test_pose_equality_tolerance(self):
        base = Pose2d(1.0, 2.0, Rotation2d(0.5))
        assert base == Pose2d(1.0 + 5e-10, 2.0, Rotation2d(0.5 + 5e-10))
        assert base != Pose2d(1.0 + 2e-9, 2.0, Rotation2d(0.5))
        assert base != Pose2d(1.0, 2.0, Rotation2d(0.5 + 2e-9))
        assert Pose2d(0.0, 0.0, Rotation2d(math.pi)) == Pose2d(0.0, 0.0, Rotation2d(-math.pi))

    def test_transform_equality_tolerance(self):
        base = Transform2d(1.0, 2.0, Rotation2d(0.5))
        assert base == Transform2d(1.0, 2.0 - 5e-10, Rotation2d(0.5 - 5e-10))
        assert base != Transform2d(1.0, 2.0 - 2e-9, Rotation2d(0.5))
        assert base != Transform2d(1.0, 2.0, Rotation2d(0.5 - 2e-9))

    def test_twist_equality_tolerance(self):
        assert Twist2d(1.0, 2.0, 3.0) == Twist2d(1.0 + 5e-10, 2.0 - 5e-10, 3.0 + 5e-10)
        assert Twist2d(1.0, 2.0, 3.0) != Twist2d(1.0 + 2e-9, 2.0, 3.0)
        assert Twist2d(1.0, 2.0, 3.0) != Twist2d(1.0, 2.0 - 2e-9, 3.0)
        assert Twist2d(1.0, 2.0, 3.0) != Twist2d(1.0, 2.0, 3.0 + 2e-9)

    def test_pose_interpolate_clamping(self):
        start = Pose2d.kZero
        end = Pose2d(5.0, 5.0, Rotation2d.kCCW_Pi_2)
        # t < 0 -> start, t >= 1 -> end.
        assert start.interpolate(end, -0.5) == start
        assert start.interpolate(end, 1.0) == end
        assert start.interpolate(end, 1.5) == end
        assert start.interpolate(end, 0.0) == start
        # Along the arc of radius 5 about (0, 5): half way is 45 deg round it.
        mid = start.interpolate(end, 0.5)
        assert_close(5.0 * math.sin(math.pi / 4), mid.getX())
        assert_close(5.0 * (1.0 - math.cos(math.pi / 4)), mid.getY())
        assert_close(45.0, mid.getRotation().getDegrees())

    def test_transform_constructor_from_poses(self):
        initial = Pose2d(1.0, 2.0, Rotation2d.fromDegrees(90.0))
        last = Pose2d(1.0, 5.0, Rotation2d.fromDegrees(180.0))
        t = Transform2d(initial, last)
        # (0, 3) rotated by -90 deg is (3, 0); heading change 90 deg.
        assert_close(3.0, t.getX())
        assert_close(0.0, t.getY())
        assert_close(90.0, t.getRotation().getDegrees())
        assert initial.plus(t) == last

    def test_transform_times_uses_wrapped_rotation(self):
        t = Transform2d(2.0, 4.0, Rotation2d.fromDegrees(270.0)).times(0.5)
        assert_close(1.0, t.getX())
        assert_close(2.0, t.getY())
        assert_close(-45.0, t.getRotation().getDegrees())

    def test_log_half_turn(self):
        # Pose2d(0, 2, 180 deg) from the origin: a half circle of radius 1, arc length pi.
        twist = Pose2d(0.0, 2.0, Rotation2d.kPi).minus(Pose2d.kZero).log()
        assert_close(math.pi, twist.dx)
        assert_close(0.0, twist.dy)
        assert_close(math.pi, abs(twist.dtheta))

    def test_pose_exp_log_match_2027_forms(self):
        start = Pose2d(1.0, -2.0, Rotation2d.fromDegrees(30.0))
        end = Pose2d(4.0, 1.5, Rotation2d.fromDegrees(-100.0))
        tw = Twist2d(1.0, 0.5, 0.7)
        assert start.exp(tw) == start.plus(tw.exp())
        assert start.log(end) == end.minus(start).log()


class TestExpLogSeriesBranches:
    def test_exp_series_branch_tiny_dtheta(self):
        # |dtheta| < 1e-9: s = 1 - dtheta^2/6, c = dtheta/2. Without the series branch,
        # cos(1e-10) rounds to 1 and c would be exactly 0 (giving (1.0, 0.5)).
        theta = 1e-10
        s = 1.0 - theta * theta / 6.0
        c = 0.5 * theta
        t = Twist2d(1.0, 0.5, theta).exp()
        assert math.isclose(t.getX(), 1.0 * s - 0.5 * c, rel_tol=0.0, abs_tol=1e-15)
        assert math.isclose(t.getY(), 1.0 * c + 0.5 * s, rel_tol=0.0, abs_tol=1e-15)
        assert math.isclose(t.getX(), 0.999999999975, rel_tol=0.0, abs_tol=1e-15)
        assert math.isclose(t.getY(), 0.50000000005, rel_tol=0.0, abs_tol=1e-15)
        assert t.getX() != 1.0
        assert_close(theta, t.getRotation().getRadians())

    def test_exp_regular_branch(self):
        theta = 0.3
        t = Twist2d(2.0, -1.0, theta).exp()
        s = math.sin(theta) / theta
        c = (1.0 - math.cos(theta)) / theta
        assert_close(2.0 * s + 1.0 * c, t.getX())
        assert_close(2.0 * c - 1.0 * s, t.getY())
        assert_close(theta, t.getRotation().getRadians())

    def test_log_series_branch_keyed_on_cos_minus_one(self):
        # theta = 1e-5: |cos(theta) - 1| ~ 5e-11 < 1e-9, so WPILib uses k = 1 - theta^2/12
        # even though |theta| >> 1e-9. The non-series formula would be off by ~8e-8 here.
        theta = 1e-5
        twist = Transform2d(1.0, 0.0, Rotation2d(theta)).log()
        assert_close(1.0 - theta * theta / 12.0, twist.dx)
        assert_close(-theta / 2.0, twist.dy)
        assert_close(theta, twist.dtheta)

    def test_log_regular_branch(self):
        theta = 0.5
        h = theta / 2.0
        k = h / math.tan(h)
        twist = Transform2d(1.0, 2.0, Rotation2d(theta)).log()
        assert_close(k * 1.0 + h * 2.0, twist.dx)
        assert_close(-h * 1.0 + k * 2.0, twist.dy)
        assert_close(theta, twist.dtheta)

    def test_log_uses_wrapped_angle(self):
        # A rotation built from 3*pi/2 is -pi/2: the twist turns the short way.
        twist = Transform2d(0.0, 0.0, Rotation2d(3 * math.pi / 2)).log()
        assert_close(-math.pi / 2, twist.dtheta)
        assert_close(0.0, twist.dx)
        assert_close(0.0, twist.dy)

    def test_exp_log_round_trip(self):
        for tw in (Twist2d(1.0, 0.5, 1e-10), Twist2d(1.0, 0.5, 1e-5), Twist2d(-2.0, 3.0, 2.5),
                   Twist2d(0.0, 0.0, -1.0)):
            back = tw.exp().log()
            assert back == tw


class TestToStringFormats:
    # Java String.format("%.2f") rounds HALF_UP on the shortest decimal representation
    # (0.125 -> 0.13, 1.005 -> 1.01, 2.675 -> 2.68), unlike Python's "%.2f".
    def test_translation2d(self):
        assert str(Translation2d(0.125, 1.005)) == "Translation2d(X: 0.13, Y: 1.01)"
        assert str(Translation2d(-2.675, 0.015)) == "Translation2d(X: -2.68, Y: 0.02)"
        assert str(Translation2d(-0.0, -0.001)) == "Translation2d(X: -0.00, Y: -0.00)"

    def test_rotation2d(self):
        assert str(Rotation2d.fromDegrees(45.0)) == "Rotation2d(Rads: 0.79, Deg: 45.00)"
        assert str(Rotation2d.kPi) == "Rotation2d(Rads: 3.14, Deg: 180.00)"
        assert str(Rotation2d.kCW_Pi_2) == "Rotation2d(Rads: -1.57, Deg: -90.00)"
        assert str(Rotation2d()) == "Rotation2d(Rads: 0.00, Deg: 0.00)"

    def test_pose2d(self):
        assert (str(Pose2d(2.675, -0.125, Rotation2d.kPi))
                == "Pose2d(Translation2d(X: 2.68, Y: -0.13), Rotation2d(Rads: 3.14, Deg: 180.00))")

    def test_transform2d(self):
        assert (str(Transform2d(1.115, 12.345, Rotation2d.kCCW_Pi_2))
                == "Transform2d(Translation2d(X: 1.12, Y: 12.35), "
                   "Rotation2d(Rads: 1.57, Deg: 90.00))")

    def test_twist2d(self):
        assert (str(Twist2d(0.005, 1.115, -2.675))
                == "Twist2d(dX: 0.01, dY: 1.12, dTheta: -2.68)")
