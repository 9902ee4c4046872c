"""WPILib 2027 3-D geometry unit tests (Quaternion, Rotation3d, Translation3d, Pose3d,
Transform3d, Twist3d, CoordinateSystem), restated for drivekin, plus the digest's edge cases
(/work/shared/reference/geometry-3d.md, sections 1.2-1.7).

Source of the ported cases: wpilibsuite/allwpilib main @ caf0fb2d,
wpimath/src/test/java/org/wpilib/math/geometry/{Quaternion,Rotation3d,Translation3d,Pose3d,
Transform3d,Twist3d,CoordinateSystem}Test.java: every test method, with its numbers and
tolerances (86 methods: 14 + 21 + 20 + 13 + 3 + 10 + 5). Java's shapes become Python's: a
``Vector<N3>`` is a length-3 float sequence (an ndarray here), a ``Matrix<N3, N3>`` /
``Matrix<N4, N4>`` an ndarray, ``IllegalArgumentException`` a ``ValueError``,
``Units.degreesToRadians`` ``math.radians``, and the units-library constructor of
``testNewWithMeasures`` takes metres from ``Units.inchesToMeters``.

JUnit's ``assertEquals(expected, actual)`` on a geometry value is Java's ``equals``; here it
is drivekin's ``==`` *and* the Java criterion recomputed from the components
(:func:`assert_equals`), so that a lenient ``__eq__`` cannot pass a case by itself.
``assertEquals(double, double)`` without a delta is exact equality, kept exact.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from drivekin import (
    CoordinateAxis,
    CoordinateSystem,
    Pose2d,
    Pose3d,
    Quaternion,
    Rotation2d,
    Rotation3d,
    Transform3d,
    Translation2d,
    Translation3d,
    Twist3d,
    Units,
)
from tests._support.wpilib_port import EPS, assert_close

X_AXIS = np.array([1.0, 0.0, 0.0])
Y_AXIS = np.array([0.0, 1.0, 0.0])
Z_AXIS = np.array([0.0, 0.0, 1.0])
rad = math.radians


# ---- Java's equals(), recomputed from the components ------------------------------------
def _q(value):
    q = value.getQuaternion() if isinstance(value, Rotation3d) else value
    return (q.getW(), q.getX(), q.getY(), q.getZ())


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]


def _norm(a):
    return math.sqrt(_dot(a, a))


def _java_equals(a, b):
    """Java's equals() of two values of the same 3-D class, from their components."""
    if isinstance(a, Quaternion):
        qa, qb = _q(a), _q(b)
        return (abs(_dot(qa, qb) - _norm(qa) * _norm(qb)) < 1e-9
                and abs(_norm(qa) - _norm(qb)) < 1e-9)
    if isinstance(a, Rotation3d):
        qa, qb = _q(a), _q(b)
        return abs(abs(_dot(qa, qb)) - _norm(qa) * _norm(qb)) < 1e-9
    if isinstance(a, Translation3d):
        return all(abs(u - v) < 1e-9 for u, v in
                   zip((a.getX(), a.getY(), a.getZ()), (b.getX(), b.getY(), b.getZ())))
    if isinstance(a, (Pose3d, Transform3d)):
        return (_java_equals(a.getTranslation(), b.getTranslation())
                and _java_equals(a.getRotation(), b.getRotation()))
    if isinstance(a, Twist3d):
        return all(abs(getattr(a, f) - getattr(b, f)) < 1e-9
                   for f in ("dx", "dy", "dz", "rx", "ry", "rz"))
    if isinstance(a, (Pose2d, Rotation2d)):
        return a == b      # the 2-D classes have their own reference tests
    raise TypeError(type(a))


def assert_equals(expected, actual):
    """JUnit assertEquals(expected, actual) on geometry values."""
    assert type(actual) is type(expected), (type(expected), type(actual))
    assert _java_equals(expected, actual), f"expected {expected!r}, got {actual!r}"
    assert expected == actual and actual == expected, (
        f"Java's equals holds but drivekin's == does not: {expected!r} vs {actual!r}")
    assert not (expected != actual)


def assert_not_equals(unexpected, actual):
    assert not _java_equals(unexpected, actual), f"{unexpected!r} equals {actual!r}"
    assert unexpected != actual and not (unexpected == actual), (
        f"Java's equals fails but drivekin's == holds: {unexpected!r} vs {actual!r}")


def assert_components(expected, q):
    """assertAll of exact assertEquals(double, double) on w, x, y, z."""
    assert (q.getW(), q.getX(), q.getY(), q.getZ()) == tuple(expected), _q(q)


# =========================================================================================
# Ported: QuaternionTest (14)
# =========================================================================================
class TestQuaternion:
    def test_init(self):
        assert_components((1.0, 0.0, 0.0, 0.0), Quaternion())
        assert_components((0.5, 0.5, 0.5, 0.5), Quaternion(0.5, 0.5, 0.5, 0.5))
        q3 = Quaternion(0.75, 0.3, 0.4, 0.5)
        assert_components((0.75, 0.3, 0.4, 0.5), q3)
        q3_norm = q3.normalize()
        norm = math.sqrt(0.75 * 0.75 + 0.3 * 0.3 + 0.4 * 0.4 + 0.5 * 0.5)
        assert_components((0.75 / norm, 0.3 / norm, 0.4 / norm, 0.5 / norm), q3_norm)
        assert q3_norm.dot(q3_norm) == 1.0

    def test_addition(self):
        q = Quaternion(0.1, 0.2, 0.3, 0.4)
        p = Quaternion(0.5, 0.6, 0.7, 0.8)
        assert_components([a + b for a, b in zip(_q(q), _q(p))], q.plus(p))

    def test_subtraction(self):
        q = Quaternion(0.1, 0.2, 0.3, 0.4)
        p = Quaternion(0.5, 0.6, 0.7, 0.8)
        assert_components([a - b for a, b in zip(_q(q), _q(p))], q.minus(p))

    def test_scalar_multiplication(self):
        q = Quaternion(0.1, 0.2, 0.3, 0.4)
        assert_components([a * 2 for a in _q(q)], q.times(2))

    def test_scalar_division(self):
        q = Quaternion(0.1, 0.2, 0.3, 0.4)
        assert_components([a / 2 for a in _q(q)], q.divide(2))

    def test_times(self):
        # 90° CCW about X, then Y, then Z (zRot·yRot·xRot) is a 90° CCW rotation about Y.
        c = math.cos(rad(90.0) / 2.0)
        s = math.sin(rad(90.0) / 2.0)
        x_rot = Quaternion(c, s, 0.0, 0.0)
        y_rot = Quaternion(c, 0.0, s, 0.0)
        z_rot = Quaternion(c, 0.0, 0.0, s)
        actual = z_rot.times(y_rot).times(x_rot)
        for e, a in zip(_q(y_rot), _q(actual)):
            assert_close(e, a, 1e-9)

        # Identity, exactly.
        q = Quaternion(0.7276068751089989, 0.29104275004359953, 0.38805700005813276,
                       0.48507125007266594)
        assert_components((1.0, 0.0, 0.0, 0.0), q.times(q.inverse()))

    def test_conjugate(self):
        q = Quaternion(0.75, 0.3, 0.4, 0.5)
        assert_components((0.75, -0.3, -0.4, -0.5), q.conjugate())

    def test_inverse(self):
        q = Quaternion(0.75, 0.3, 0.4, 0.5)
        inv = q.inverse()
        norm = q.norm()
        for e, a in zip((0.75, -0.3, -0.4, -0.5), _q(inv)):
            assert_close(e / (norm * norm), a, 1e-10)

    def test_norm(self):
        # Pythagorean triples (3, 4, 5), (5, 12, 13), (13, 84, 85).
        assert_close(85, Quaternion(3, 4, 12, 84).norm(), 1e-10)

    def test_exponential(self):
        q = Quaternion(1.1, 2.2, 3.3, 4.4)
        q_exp = Quaternion(2.81211398529184, -0.392521193481878, -0.588781790222817,
                           -0.785042386963756)
        assert_equals(q_exp, q.exp())

    def test_logarithm(self):
        q = Quaternion(1.1, 2.2, 3.3, 4.4)
        q_log = Quaternion(1.7959088706354, 0.515190292664085, 0.772785438996128,
                           1.03038058532817)
        assert_equals(q_log, q.log())

        zero = Quaternion(0, 0, 0, 0)
        one = Quaternion()
        assert_equals(zero, zero.log())
        assert_equals(zero, one.log())

        i = Quaternion(0, 1, 0, 0)
        assert_equals(i.times(math.pi / 2), i.log())
        j = Quaternion(0, 0, 1, 0)
        assert_equals(j.times(math.pi / 2), j.log())
        k = Quaternion(0, 0, 0, 1)
        assert_equals(k.times(math.pi / 2), k.log())
        assert_equals(i.times(-math.pi), one.times(-1).log())

        ln_half = math.log(0.5)
        assert_equals(Quaternion(ln_half, -math.pi, 0, 0), one.times(-0.5).log())

    def test_logarithm_is_inverse_of_exponential(self):
        q = Quaternion(1.1, 2.2, 3.3, 4.4)
        # ln(exp(q)) is congruent to, not necessarily equal to, exp(ln(q)).
        assert_equals(q, q.log().exp())

        start = Quaternion(1, 2, 3, 4)
        expect = Quaternion(5, 6, 7, 8)
        twist = expect.times(start.inverse()).log()
        assert_equals(expect, twist.exp().times(start))

    def test_dot_product(self):
        q = Quaternion(1.1, 2.2, 3.3, 4.4)
        p = Quaternion(5.5, 6.6, 7.7, 8.8)
        assert q.dot(p) == 1.1 * 5.5 + 2.2 * 6.6 + 3.3 * 7.7 + 4.4 * 8.8

    def test_dot_product_as_equality(self):
        q = Quaternion(1.1, 2.2, 3.3, 4.4)
        assert_equals(q, q)
        assert_not_equals(q, q.conjugate())


# =========================================================================================
# Ported: Rotation3dTest (21)
# =========================================================================================
class TestRotation3d:
    def test_gimbal_lock_accuracy(self):
        rot1 = Rotation3d(0, 0, math.pi / 2)
        rot2 = Rotation3d(math.pi, 0, 0)
        rot3 = Rotation3d(-math.pi / 2, 0, 0)
        result1 = rot1.rotateBy(rot2).rotateBy(rot3)
        assert_equals(Rotation3d(0, -math.pi / 2, math.pi / 2), result1)
        assert_close(math.pi / 2, result1.getX() + result1.getZ())
        assert_close(-math.pi / 2, result1.getY())

        rot1 = Rotation3d(0, 0, math.pi / 2)
        rot2 = Rotation3d(-math.pi, 0, 0)
        rot3 = Rotation3d(math.pi / 2, 0, 0)
        result2 = rot1.rotateBy(rot2).rotateBy(rot3)
        assert_equals(Rotation3d(0, math.pi / 2, math.pi / 2), result2)
        assert_close(math.pi / 2, result2.getZ() - result2.getX())
        assert_close(math.pi / 2, result2.getY())

        rot1 = Rotation3d(0, 0, math.pi / 2)
        rot2 = Rotation3d(0, math.pi / 3, 0)
        rot3 = Rotation3d(-math.pi / 2, 0, 0)
        result3 = rot1.rotateBy(rot2).rotateBy(rot3)
        assert_equals(Rotation3d(0, math.pi / 2, math.pi / 6), result3)
        assert_close(math.pi / 6, result3.getZ() - result3.getX())
        assert_close(math.pi / 2, result3.getY())

    def test_init_axis_angle_and_roll_pitch_yaw(self):
        for axis, rpy in ((X_AXIS, (math.pi / 3, 0.0, 0.0)), (Y_AXIS, (0.0, math.pi / 3, 0.0)),
                          (Z_AXIS, (0.0, 0.0, math.pi / 3))):
            rot = Rotation3d(axis, math.pi / 3)
            assert_equals(rot, Rotation3d(*rpy))
            assert_equals(rot, Rotation3d(axis * (math.pi / 3)))

    def test_init_rotation_matrix(self):
        # No rotation
        assert_equals(Rotation3d.kZero, Rotation3d(np.eye(3)))

        # 90 degree CCW rotation around z-axis (columns (0, 1, 0), (-1, 0, 0), (0, 0, 1))
        r2 = np.column_stack([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
        assert_equals(Rotation3d(0.0, 0.0, rad(90.0)), Rotation3d(r2))

        # Matrix that isn't orthogonal
        r3 = np.array([[1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
        with pytest.raises(ValueError):
            Rotation3d(r3)

        # Matrix that's orthogonal but not special orthogonal
        with pytest.raises(ValueError):
            Rotation3d(np.eye(3) * 2.0)

    def test_init_two_vector(self):
        # 90 degree CW rotation around y-axis
        assert_equals(Rotation3d(Y_AXIS, -math.pi / 2.0), Rotation3d(X_AXIS, Z_AXIS))
        # 45 degree CCW rotation around z-axis
        assert_equals(Rotation3d(Z_AXIS, math.pi / 4.0),
                      Rotation3d(X_AXIS, np.array([1.0, 1.0, 0.0])))
        # 0 degree rotations of the x, y and z axes
        for axis in (X_AXIS, Y_AXIS, Z_AXIS):
            assert_equals(Rotation3d.kZero, Rotation3d(axis, axis))

        # 180 degree rotations: any quaternion with an axis orthogonal to the initial vector
        # is acceptable, so only w = 0 and axis · initial = 0 are checked (exactly).
        for axis in (X_AXIS, Y_AXIS, Z_AXIS):
            q = Rotation3d(axis, axis * -1.0).getQuaternion()
            assert q.getW() == 0.0
            assert q.getX() * axis[0] + q.getY() * axis[1] + q.getZ() * axis[2] == 0.0

    def test_radians_to_degrees(self):
        rot1 = Rotation3d(Z_AXIS, math.pi / 3)
        assert_close(rad(0.0), rot1.getX())
        assert_close(rad(0.0), rot1.getY())
        assert_close(rad(60.0), rot1.getZ())

        rot2 = Rotation3d(Z_AXIS, math.pi / 4)
        assert_close(rad(0.0), rot2.getX())
        assert_close(rad(0.0), rot2.getY())
        assert_close(rad(45.0), rot2.getZ())

    def test_radians_and_degrees(self):
        rot1 = Rotation3d(Z_AXIS, rad(45.0))
        assert_close(0.0, rot1.getX())
        assert_close(0.0, rot1.getY())
        assert_close(math.pi / 4.0, rot1.getZ())

        rot2 = Rotation3d(Z_AXIS, rad(30.0))
        assert_close(0.0, rot2.getX())
        assert_close(0.0, rot2.getY())
        assert_close(math.pi / 6.0, rot2.getZ())

    def test_rotation_loop(self):
        rot = Rotation3d.kZero
        rot = rot.rotateBy(Rotation3d(rad(90.0), 0.0, 0.0))
        assert_equals(Rotation3d(rad(90.0), 0.0, 0.0), rot)

        rot = rot.rotateBy(Rotation3d(0.0, rad(90.0), 0.0))
        r3 = 1.0 / math.sqrt(3)
        assert_equals(Rotation3d(np.array([r3, r3, -r3]), rad(120.0)), rot)

        rot = rot.rotateBy(Rotation3d(0.0, 0.0, rad(90.0)))
        assert_equals(Rotation3d(0.0, rad(90.0), 0.0), rot)

        rot = rot.rotateBy(Rotation3d(0.0, rad(-90.0), 0.0))
        assert_equals(Rotation3d.kZero, rot)

    @pytest.mark.parametrize("axis", [X_AXIS, Y_AXIS, Z_AXIS], ids=["X", "Y", "Z"])
    def test_rotate_by_from_zero(self, axis):      # testRotateByFromZero{X,Y,Z}
        rotated = Rotation3d.kZero.rotateBy(Rotation3d(axis, rad(90.0)))
        assert_equals(Rotation3d(axis, rad(90.0)), rotated)

    @pytest.mark.parametrize("axis", [X_AXIS, Y_AXIS, Z_AXIS], ids=["X", "Y", "Z"])
    def test_rotate_by_non_zero(self, axis):       # testRotateByNonZero{X,Y,Z}
        rot = Rotation3d(axis, rad(90.0)).rotateBy(Rotation3d(axis, rad(30.0)))
        assert_equals(Rotation3d(axis, rad(120.0)), rot)

    def test_relative_to(self):
        start = Rotation3d(Y_AXIS, rad(-90.0))
        end = Rotation3d(Z_AXIS, rad(90.0))
        expected = Rotation3d(np.array([1.0, 1.0, 1.0]), rad(120.0))
        assert_equals(expected, end.relativeTo(start))

    def test_integrate(self):
        rot = Rotation3d(0.0, 0.0, rad(90.0))
        assert_equals(Rotation3d(0.0, 0.0, rad(110.0)), rot.integrate(0.0, 0.0, rad(20.0), 1.0))
        assert_equals(Rotation3d(0.0, rad(20.0), rad(90.0)),
                      rot.integrate(0.0, rad(20.0), 0.0, 1.0))
        expected3 = Rotation3d(Quaternion(0.5635121137168105, -0.12216409746525868,
                                          0.1221640974652587, 0.8078403086473278))
        assert_equals(expected3, rot.integrate(0.0, rad(20.0), rad(20.0), 1.0))

    def test_equality(self):
        assert_equals(Rotation3d(Z_AXIS, rad(43.0)), Rotation3d(Z_AXIS, rad(43.0)))
        assert_equals(Rotation3d(Z_AXIS, rad(-180.0)), Rotation3d(Z_AXIS, rad(180.0)))

    def test_axis_angle(self):
        for axis, degrees in ((X_AXIS, 90.0), (Y_AXIS, 45.0), (Z_AXIS, 60.0)):
            rot = Rotation3d(axis, rad(degrees))
            got = rot.getAxis()
            assert isinstance(got, np.ndarray) and got.shape == (3,) and got.dtype == np.float64
            assert np.array_equal(axis, got)   # Java's Matrix.equals is exact
            assert_close(rad(degrees), rot.getAngle(), 1e-9)

    def test_to_rotation2d(self):
        rotation = Rotation3d(rad(20.0), rad(30.0), rad(40.0))
        assert_equals(Rotation2d(rad(40.0)), rotation.toRotation2d())

    def test_inequality(self):
        assert_not_equals(Rotation3d(Z_AXIS, rad(43.0)), Rotation3d(Z_AXIS, rad(43.5)))

    def test_to_matrix(self):
        before = Rotation3d(rad(10.0), rad(20.0), rad(30.0))
        matrix = before.toMatrix()
        assert isinstance(matrix, np.ndarray) and matrix.shape == (3, 3)
        assert_equals(before, Rotation3d(matrix))

    def test_interpolate(self):
        def check(rot1, rot2, t, expected_xyz):
            interpolated = rot1.interpolate(rot2, t)
            for e, a in zip(expected_xyz,
                            (interpolated.getX(), interpolated.getY(), interpolated.getZ())):
                assert_close(e, a)

        # 50 + (70 - 50) * 0.5 = 60
        check(Rotation3d(X_AXIS, rad(50)), Rotation3d(X_AXIS, rad(70)), 0.5,
              (rad(60.0), rad(0.0), rad(0.0)))
        # -160 minus half distance between 170 and -160 (15) = -175
        check(Rotation3d(X_AXIS, rad(170)), Rotation3d(X_AXIS, rad(-160)), 0.5,
              (rad(-175.0), rad(0.0), rad(0.0)))
        check(Rotation3d(Y_AXIS, rad(50)), Rotation3d(Y_AXIS, rad(70)), 0.5,
              (rad(0.0), rad(60.0), rad(0.0)))
        # -160 minus half distance between 170 and -160 (165) = 5
        check(Rotation3d(Y_AXIS, rad(170)), Rotation3d(Y_AXIS, rad(-160)), 0.5,
              (rad(180.0), rad(-5.0), rad(180.0)))
        check(Rotation3d(Z_AXIS, rad(50)), Rotation3d(Z_AXIS, rad(70)), 0.5,
              (rad(0.0), rad(0.0), rad(60.0)))
        check(Rotation3d(Z_AXIS, rad(170)), Rotation3d(Z_AXIS, rad(-160)), 0.5,
              (rad(0.0), rad(0.0), rad(-175.0)))

        # t = 0 gives the start
        rot1 = Rotation3d(Y_AXIS, -rad(90))
        rot2 = Rotation3d(Z_AXIS, rad(90))
        check(rot1, rot2, 0.0, (rot1.getX(), rot1.getY(), rot1.getZ()))

        # The whole way from rot1 to rot2 is 120° about the extrinsic axis (-1, 1, 1).
        extrinsic_axis = np.array([-1.0, 1.0, 1.0])
        assert_equals(rot2, rot1.rotateBy(Rotation3d(extrinsic_axis, rad(120))))
        expected = rot1.rotateBy(Rotation3d(extrinsic_axis, rad(60)))
        check(rot1, rot2, 0.5, (expected.getX(), expected.getY(), expected.getZ()))

        # t = 1 gives the end
        check(rot1, rot2, 1.0, (rot2.getX(), rot2.getY(), rot2.getZ()))


# =========================================================================================
# Ported: Translation3dTest (20)
# =========================================================================================
class TestTranslation3d:
    def test_new_with_measures(self):
        # Java: new Translation3d(Inches.of(6), Inches.of(8), Inches.of(16)).
        translation = Translation3d(Units.inchesToMeters(6), Units.inchesToMeters(8),
                                    Units.inchesToMeters(16))
        assert_close(0.1524, translation.getX())
        assert_close(0.2032, translation.getY())
        assert_close(0.4064, translation.getZ())

    def test_sum(self):
        total = Translation3d(1.0, 3.0, 5.0).plus(Translation3d(2.0, 5.0, 8.0))
        assert_close(3.0, total.getX())
        assert_close(8.0, total.getY())
        assert_close(13.0, total.getZ())

    def test_difference(self):
        diff = Translation3d(1.0, 3.0, 5.0).minus(Translation3d(2.0, 5.0, 8.0))
        assert_close(-1.0, diff.getX())
        assert_close(-2.0, diff.getY())
        assert_close(-3.0, diff.getZ())

    def test_rotate_by(self):
        translation = Translation3d(1.0, 2.0, 3.0)
        for axis, expected in ((X_AXIS, (1.0, -3.0, 2.0)), (Y_AXIS, (3.0, 2.0, -1.0)),
                               (Z_AXIS, (-2.0, 1.0, 3.0))):
            rotated = translation.rotateBy(Rotation3d(axis, rad(90.0)))
            for e, a in zip(expected, (rotated.getX(), rotated.getY(), rotated.getZ())):
                assert_close(e, a)

    def test_rotate_around(self):
        translation = Translation3d(1.0, 2.0, 3.0)
        around = Translation3d(3.0, 2.0, 1.0)
        for axis, expected in ((X_AXIS, (1.0, 0.0, 1.0)), (Y_AXIS, (5.0, 2.0, 3.0)),
                               (Z_AXIS, (3.0, 0.0, 3.0))):
            rotated = translation.rotateAround(around, Rotation3d(axis, rad(90.0)))
            for e, a in zip(expected, (rotated.getX(), rotated.getY(), rotated.getZ())):
                assert_close(e, a)

    def test_to_translation2d(self):
        assert Translation3d(1.0, 2.0, 3.0).toTranslation2d() == Translation2d(1.0, 2.0)

    def test_multiplication(self):
        mult = Translation3d(3.0, 5.0, 7.0).times(3)
        assert_close(9.0, mult.getX())
        assert_close(15.0, mult.getY())
        assert_close(21.0, mult.getZ())

    def test_division(self):
        div = Translation3d(3.0, 5.0, 7.0).div(2)
        assert_close(1.5, div.getX())
        assert_close(2.5, div.getY())
        assert_close(3.5, div.getZ())

    def test_norm(self):
        assert_close(math.sqrt(83.0), Translation3d(3.0, 5.0, 7.0).getNorm())

    def test_squared_norm(self):
        assert_close(83.0, Translation3d(3.0, 5.0, 7.0).getSquaredNorm())

    def test_distance(self):
        one = Translation3d(1.0, 1.0, 1.0)
        assert_close(5.0 * math.sqrt(3.0), one.getDistance(Translation3d(6.0, 6.0, 6.0)))

    def test_squared_distance(self):
        one = Translation3d(1.0, 1.0, 1.0)
        assert_close(75.0, one.getSquaredDistance(Translation3d(6.0, 6.0, 6.0)))

    def test_unary_minus(self):
        inverted = Translation3d(-4.5, 7.0, 9.0).unaryMinus()
        assert_close(4.5, inverted.getX())
        assert_close(-7.0, inverted.getY())
        assert_close(-9.0, inverted.getZ())

    def test_equality(self):
        assert_equals(Translation3d(9, 5.5, 3.5), Translation3d(9, 5.5, 3.5))

    def test_inequality(self):
        assert_not_equals(Translation3d(9, 5.5, 3.5), Translation3d(9, 5.7, 3.5))

    def test_polar_constructor(self):
        one = Translation3d(math.sqrt(2), Rotation3d(Z_AXIS, rad(45.0)))
        two = Translation3d(2, Rotation3d(Z_AXIS, rad(60.0)))
        assert_close(1.0, one.getX())
        assert_close(1.0, one.getY())
        assert_close(0.0, one.getZ())
        assert_close(1.0, two.getX())
        assert_close(math.sqrt(3.0), two.getY())
        assert_close(0.0, two.getZ())

    def test_to_vector(self):
        vec = np.array([1.0, 2.0, 3.0])
        translation = Translation3d(vec)
        assert translation.getX() == vec[0]
        assert translation.getY() == vec[1]
        assert translation.getZ() == vec[2]
        got = translation.toVector()
        assert isinstance(got, np.ndarray) and got.shape == (3,) and got.dtype == np.float64
        assert np.array_equal(vec, got)

    def test_nearest(self):
        origin = Translation3d.kZero
        t1 = Translation3d(1, 0, 0)
        t2 = Translation3d(0, 2, 0)
        t3 = Translation3d(0, 0, 3)
        t4 = Translation3d(2, 2, 2)
        t5 = Translation3d(3, 3, 3)
        assert_equals(t3, origin.nearest([t5, t3, t4]))
        assert_equals(t1, origin.nearest([t1, t2, t3]))
        assert_equals(t2, origin.nearest([t4, t2, t3]))

    def test_dot(self):
        assert Translation3d(1.0, 2.0, 3.0).dot(Translation3d(4.0, 5.0, 6.0)) == 32.0

    def test_cross(self):
        cross = Translation3d(1.0, 2.0, 3.0).cross(Translation3d(4.0, 5.0, 6.0))
        assert isinstance(cross, np.ndarray) and cross.shape == (3,)
        assert_close(-3.0, cross[0])
        assert_close(6.0, cross[1])
        assert_close(-3.0, cross[2])


# =========================================================================================
# Ported: Pose3dTest (13)
# =========================================================================================
COMPLEX_INITIAL = [
    ((0.698303, -0.959096, 0.271076), (0.86403, -0.076866, 0.147234, 0.475254)),
    ((0.634892, -0.765209, 0.117543), (0.84987, -0.070829, 0.162097, 0.496415)),
    ((0.584827, -0.590303, -0.02557), (0.832743, -0.041991, 0.202188, 0.513708)),
    ((0.505038, -0.451479, -0.112835), (0.816515, -0.002673, 0.226182, 0.531166)),
    ((0.428178, -0.329692, -0.189707), (0.807886, 0.029298, 0.257788, 0.529157)),
]
COMPLEX_FINAL = [
    ((-0.230448, -0.511957, 0.198406), (0.753984, 0.347016, 0.409105, 0.379106)),
    ((-0.088932, -0.343253, 0.095018), (0.638738, 0.413016, 0.536281, 0.365833)),
    ((-0.107908, -0.317552, 0.133946), (0.653444, 0.417069, 0.465505, 0.427046)),
    ((-0.123383, -0.156411, -0.047435), (0.652983, 0.40644, 0.431566, 0.47135)),
    ((-0.084654, -0.019305, -0.030022), (0.620243, 0.429104, 0.479384, 0.44873)),
]
NAN_INITIAL = [
    ((6.32, 4.12, 0.00), (-0.9999999999999999, 0.0, 0.0, 1.9208309264993548E-8)),
    ((3.75, 2.95, 0.00), (0.9999999999999793, 0.0, 0.0, 2.0352360299846772E-7)),
]
NAN_FINAL = [
    ((6.33, 4.15, 0.00), (-0.9999999999999999, 0.0, 0.0, 2.416890209039172E-8)),
    ((3.66, 2.93, 0.00), (0.9999999999999782, 0.0, 0.0, 2.0859477994905617E-7)),
]


def _pose(t, q):
    return Pose3d(Translation3d(*t), Rotation3d(Quaternion(*q)))


class TestPose3d:
    def test_rotate_by(self):
        x, y = 1.0, 2.0
        initial = Pose3d(Translation3d(x, y, 0.0), Rotation3d(rad(0.0), rad(0.0), rad(45.0)))
        yaw = rad(5.0)
        rotation = Rotation3d(rad(0.0), rad(0.0), yaw)
        rotated = initial.rotateBy(rotation)
        c, s = math.cos(yaw), math.sin(yaw)
        assert_close(c * x - s * y, rotated.getX())
        assert_close(s * x + c * y, rotated.getY())
        assert_close(0.0, rotated.getZ())
        assert_close(0.0, rotated.getRotation().getX())
        assert_close(0.0, rotated.getRotation().getY())
        assert_close(initial.getRotation().getZ() + rotation.getZ(), rotated.getRotation().getZ())

    def test_transform_by_rotations(self):
        initial = Pose3d.kZero
        t1 = Transform3d(Translation3d.kZero, Rotation3d(rad(90.0), rad(45.0), rad(0.0)))
        t2 = Transform3d(Translation3d.kZero, Rotation3d(rad(-90.0), rad(0.0), rad(0.0)))
        t3 = Transform3d(Translation3d.kZero, Rotation3d(rad(0.0), rad(-45.0), rad(0.0)))
        # Applied intrinsically, these rotations leave the origin and come back to it.
        final = initial.transformBy(t1).transformBy(t2).transformBy(t3)
        assert_close(final.getRotation().getX(), initial.getRotation().getX())
        assert_close(final.getRotation().getY(), initial.getRotation().getY())
        assert_close(final.getRotation().getZ(), initial.getRotation().getZ())

    def test_transform_by(self):
        initial = Pose3d(Translation3d(1.0, 2.0, 0.0), Rotation3d(Z_AXIS, rad(45.0)))
        transformation = Transform3d(Translation3d(5.0, 0.0, 0.0), Rotation3d(Z_AXIS, rad(5.0)))
        transformed = initial.plus(transformation)
        assert_close(1.0 + 5.0 / math.sqrt(2.0), transformed.getX())
        assert_close(2.0 + 5.0 / math.sqrt(2.0), transformed.getY())
        assert_close(rad(50.0), transformed.getRotation().getZ())

    def test_relative_to(self):
        initial = Pose3d(0.0, 0.0, 0.0, Rotation3d(Z_AXIS, rad(45.0)))
        last = Pose3d(5.0, 5.0, 0.0, Rotation3d(Z_AXIS, rad(45.0)))
        relative = last.relativeTo(initial)
        assert isinstance(relative, Pose3d)
        assert_close(5.0 * math.sqrt(2.0), relative.getX())
        assert_close(0.0, relative.getY())
        assert_close(0.0, relative.getRotation().getZ())

    def test_rotate_around(self):
        initial = Pose3d(Translation3d(5, 0, 0), Rotation3d.kZero)
        rotated = initial.rotateAround(Translation3d.kZero, Rotation3d(0, 0, math.pi))
        assert_close(-5.0, rotated.getX())
        assert_close(0.0, rotated.getY())
        assert_close(math.pi, rotated.getRotation().getZ())

    def test_equality(self):
        assert_equals(Pose3d(0.0, 5.0, 0.0, Rotation3d(Z_AXIS, rad(43.0))),
                      Pose3d(0.0, 5.0, 0.0, Rotation3d(Z_AXIS, rad(43.0))))

    def test_inequality(self):
        assert_not_equals(Pose3d(0.0, 5.0, 0.0, Rotation3d(Z_AXIS, rad(43.0))),
                          Pose3d(0.0, 1.524, 0.0, Rotation3d(Z_AXIS, rad(43.0))))

    def test_minus(self):
        initial = Pose3d(0.0, 0.0, 0.0, Rotation3d(Z_AXIS, rad(45.0)))
        last = Pose3d(5.0, 5.0, 0.0, Rotation3d(Z_AXIS, rad(45.0)))
        transform = last.minus(initial)
        assert isinstance(transform, Transform3d)
        assert_close(5.0 * math.sqrt(2.0), transform.getX())
        assert_close(0.0, transform.getY())
        assert_close(0.0, transform.getRotation().getZ())

    def test_to_matrix(self):
        before = Pose3d(1.0, 2.0, 3.0, Rotation3d(rad(20.0), rad(30.0), rad(40.0)))
        matrix = before.toMatrix()
        assert isinstance(matrix, np.ndarray) and matrix.shape == (4, 4)
        assert_equals(before, Pose3d(matrix))

    def test_to_pose2d(self):
        pose = Pose3d(1.0, 2.0, 3.0, Rotation3d(rad(20.0), rad(30.0), rad(40.0)))
        assert_equals(Pose2d(1.0, 2.0, Rotation2d(rad(40.0))), pose.toPose2d())

    def test_complex_twists(self):
        eps = 1e-5
        for (ti, qi), (tf, qf) in zip(COMPLEX_INITIAL, COMPLEX_FINAL):
            start, end = _pose(ti, qi), _pose(tf, qf)
            twist = end.minus(start).log()
            start_exp = start.plus(twist.exp())
            assert_close(start_exp.getX(), end.getX(), eps)
            assert_close(start_exp.getY(), end.getY(), eps)
            assert_close(start_exp.getZ(), end.getZ(), eps)
            for a, b in zip(_q(start_exp.getRotation()), _q(end.getRotation())):
                assert_close(a, b, eps)

    def test_twist_nan(self):
        for (ti, qi), (tf, qf) in zip(NAN_INITIAL, NAN_FINAL):
            twist = _pose(tf, qf).minus(_pose(ti, qi)).log()
            for field in ("dx", "dy", "dz", "rx", "ry", "rz"):
                assert not math.isnan(getattr(twist, field)), field

    def test_nearest(self):
        origin = Pose3d.kZero
        # Distance sort
        pose1 = Pose3d(1, 0, 0, Rotation3d.kZero)
        pose2 = Pose3d(0, 2, 0, Rotation3d.kZero)
        pose3 = Pose3d(0, 0, 3, Rotation3d.kZero)
        pose4 = Pose3d(2, 2, 2, Rotation3d.kZero)
        pose5 = Pose3d(3, 3, 3, Rotation3d.kZero)
        assert_equals(pose3, origin.nearest([pose5, pose3, pose4]))
        assert_equals(pose1, origin.nearest([pose1, pose2, pose3]))
        assert_equals(pose2, origin.nearest([pose4, pose2, pose3]))

        # Rotation sort (same distance)
        translation = Translation3d(1, 0, 0)
        pose_a = Pose3d(translation, Rotation3d.kZero)
        pose_b = Pose3d(translation, Rotation3d(rad(30), 0, 0))
        pose_c = Pose3d(translation, Rotation3d(0, rad(45), 0))
        pose_d = Pose3d(translation, Rotation3d(0, 0, rad(90)))
        pose_e = Pose3d(translation, Rotation3d(rad(180), 0, 0))
        assert_equals(pose_a, Pose3d(0, 0, 0, Rotation3d.kZero).nearest([pose_a, pose_b, pose_d]))
        assert_equals(pose_b, Pose3d(0, 0, 0, Rotation3d(rad(25), 0, 0))
                      .nearest([pose_b, pose_c, pose_d]))
        assert_equals(pose_c, Pose3d(0, 0, 0, Rotation3d(0, rad(50), 0))
                      .nearest([pose_b, pose_c, pose_d]))
        assert_equals(pose_d, Pose3d(0, 0, 0, Rotation3d(0, 0, rad(85)))
                      .nearest([pose_a, pose_c, pose_d]))
        assert_equals(pose_e, Pose3d(0, 0, 0, Rotation3d(rad(170), 0, 0))
                      .nearest([pose_a, pose_d, pose_e]))

        # Combined roll, pitch and yaw
        complex1 = Pose3d(translation, Rotation3d(rad(45), rad(30), rad(60)))
        complex2 = Pose3d(translation, Rotation3d(rad(90), rad(45), rad(90)))
        complex3 = Pose3d(translation, Rotation3d(rad(10), rad(15), rad(20)))
        assert_equals(complex3, Pose3d(0, 0, 0, Rotation3d(rad(5), rad(10), rad(15)))
                      .nearest([complex1, complex2, complex3]))


# =========================================================================================
# Ported: Transform3dTest (3)
# =========================================================================================
class TestTransform3d:
    def test_to_matrix(self):
        before = Transform3d(1.0, 2.0, 3.0, Rotation3d(rad(20.0), rad(30.0), rad(40.0)))
        matrix = before.toMatrix()
        assert isinstance(matrix, np.ndarray) and matrix.shape == (4, 4)
        assert_equals(before, Transform3d(matrix))

    def test_inverse(self):
        initial = Pose3d(Translation3d(1.0, 2.0, 3.0), Rotation3d(Z_AXIS, rad(45.0)))
        transform = Transform3d(Translation3d(5.0, 4.0, 3.0), Rotation3d(Z_AXIS, rad(5.0)))
        untransformed = initial.plus(transform).plus(transform.inverse())
        assert_equals(initial, untransformed)

    def test_composition(self):
        initial = Pose3d(Translation3d(1.0, 2.0, 3.0), Rotation3d(Z_AXIS, rad(45.0)))
        t1 = Transform3d(Translation3d(5.0, 0.0, 0.0), Rotation3d(Z_AXIS, rad(5.0)))
        t2 = Transform3d(Translation3d(0.0, 2.0, 0.0), Rotation3d(Z_AXIS, rad(5.0)))
        assert_equals(initial.plus(t1).plus(t2), initial.plus(t1.plus(t2)))


# =========================================================================================
# Ported: Twist3dTest (10)
# =========================================================================================
class TestTwist3d:
    @pytest.mark.parametrize("xyz", [(5.0, 0.0, 0.0), (0.0, 5.0, 0.0), (0.0, 0.0, 5.0)],
                             ids=["X", "Y", "Z"])
    def test_straight(self, xyz):                 # testStraight{X,Y,Z}
        transform = Twist3d(*xyz, 0.0, 0.0, 0.0).exp()
        assert_equals(Transform3d(*xyz, Rotation3d.kZero), transform)

    def test_quarter_circle(self):
        transform = Twist3d(5.0 / 2.0 * math.pi, 0.0, 0.0, 0.0, 0.0, math.pi / 2.0).exp()
        assert_equals(Transform3d(5.0, 5.0, 0.0, Rotation3d(Z_AXIS, rad(90.0))), transform)

    def test_diagonal_no_dtheta(self):
        transform = Twist3d(2.0, 2.0, 0.0, 0.0, 0.0, 0.0).exp()
        assert_equals(Transform3d(2.0, 2.0, 0.0, Rotation3d.kZero), transform)

    def test_equality(self):
        assert_equals(Twist3d(5, 1, 0, 0.0, 0.0, 3.0), Twist3d(5, 1, 0, 0.0, 0.0, 3.0))

    def test_inequality(self):
        assert_not_equals(Twist3d(5, 1, 0, 0.0, 0.0, 3.0), Twist3d(5, 1.2, 0, 0.0, 0.0, 3.0))

    @pytest.mark.parametrize("end, expected", [
        ((0.0, 5.0, 5.0, (rad(90.0), 0.0, 0.0)),
         (0.0, 5.0 / 2.0 * math.pi, 0.0, rad(90.0), 0.0, 0.0)),
        ((5.0, 0.0, 5.0, (0.0, rad(90.0), 0.0)),
         (0.0, 0.0, 5.0 / 2.0 * math.pi, 0.0, math.pi / 2.0, 0.0)),
        ((5.0, 5.0, 0.0, (0.0, 0.0, rad(90.0))),
         (5.0 / 2.0 * math.pi, 0.0, 0.0, 0.0, 0.0, math.pi / 2.0)),
    ], ids=["X", "Y", "Z"])
    def test_pose3d_log(self, end, expected):     # testPose3dLog{X,Y,Z}
        start = Pose3d.kZero
        end = Pose3d(*end[:3], Rotation3d(*end[3]))
        twist = end.minus(start).log()
        assert_equals(Twist3d(*expected), twist)
        # The twist gives back the end pose.
        assert_equals(end, start.plus(twist.exp()))


# =========================================================================================
# Ported: CoordinateSystemTest (5)
# =========================================================================================
def _check_pose3d_convert(pose_from, pose_to, coord_from, coord_to):
    convert = CoordinateSystem.convert
    assert_equals(pose_to.getTranslation(),
                  convert(pose_from.getTranslation(), coord_from, coord_to))
    assert_equals(pose_to.getRotation(), convert(pose_from.getRotation(), coord_from, coord_to))
    assert_equals(pose_to, convert(pose_from, coord_from, coord_to))

    assert_equals(pose_from.getTranslation(),
                  convert(pose_to.getTranslation(), coord_to, coord_from))
    assert_equals(pose_from.getRotation(), convert(pose_to.getRotation(), coord_to, coord_from))
    assert_equals(pose_from, convert(pose_to, coord_to, coord_from))


def _check_transform3d_convert(transform_from, transform_to, coord_from, coord_to):
    convert = CoordinateSystem.convert
    assert_equals(transform_to.getTranslation(),
                  convert(transform_from.getTranslation(), coord_from, coord_to))
    assert_equals(transform_to, convert(transform_from, coord_from, coord_to))

    assert_equals(transform_from.getTranslation(),
                  convert(transform_to.getTranslation(), coord_to, coord_from))
    assert_equals(transform_from, convert(transform_to, coord_to, coord_from))


def _rpy(r, p, y):
    return Rotation3d(rad(r), rad(p), rad(y))


class TestCoordinateSystem:
    # (rotation in the "from" frame as roll, pitch, yaw in degrees) -> the same in "to"
    @pytest.mark.parametrize("to, xyz, cases", [
        ("NWU", (3.0, -1.0, -2.0), [((0, 0, 0), (-90, 0, -90)), ((45, 0, 0), (-45, 0, -90)),
                                    ((0, 45, 0), (-90, 0, -135)),
                                    ((0, 0, 45), (-90, 45, -90))]),
        ("NED", (3.0, 1.0, 2.0), [((0, 0, 0), (90, 0, 90)), ((45, 0, 0), (135, 0, 90)),
                                  ((0, 45, 0), (90, 0, 135)), ((0, 0, 45), (90, -45, 90))]),
    ], ids=["testPose3dEDNtoNWU", "testPose3dEDNtoNED"])
    def test_pose3d_edn_to(self, to, xyz, cases):
        for rpy_from, rpy_to in cases:
            _check_pose3d_convert(Pose3d(1.0, 2.0, 3.0, _rpy(*rpy_from)),
                                  Pose3d(*xyz, _rpy(*rpy_to)),
                                  CoordinateSystem.EDN(), getattr(CoordinateSystem, to)())

    @pytest.mark.parametrize("to, xyz, cases", [
        ("NWU", (3.0, -1.0, -2.0), [((0, 0, 0), (0, 0, 0)), ((45, 0, 0), (0, -45, 0)),
                                    ((0, 45, 0), (0, 0, -45)), ((0, 0, 45), (45, 0, 0))]),
        ("NED", (3.0, 1.0, 2.0), [((0, 0, 0), (0, 0, 0)), ((45, 0, 0), (0, 45, 0)),
                                  ((0, 45, 0), (0, 0, 45)), ((0, 0, 45), (45, 0, 0))]),
    ], ids=["testTransform3dEDNtoNWU", "testTransform3dEDNtoNED"])
    def test_transform3d_edn_to(self, to, xyz, cases):
        for rpy_from, rpy_to in cases:
            _check_transform3d_convert(
                Transform3d(Translation3d(1.0, 2.0, 3.0), _rpy(*rpy_from)),
                Transform3d(Translation3d(*xyz), _rpy(*rpy_to)),
                CoordinateSystem.EDN(), getattr(CoordinateSystem, to)())

    def test_left_handed_system_throws_exception(self):
        A = CoordinateAxis
        for axes in ((A.N(), A.E(), A.U()), (A.E(), A.U(), A.N()), (A.N(), A.W(), A.D())):
            with pytest.raises(ValueError):
                CoordinateSystem(*axes)


# =========================================================================================
# The digest's edge cases (geometry-3d.md §1.2-1.7), against closed forms written here
# =========================================================================================
class TestDigestEdgeCases:
    @pytest.mark.parametrize("a", [(1.0, 2.0, 3.0), (3.0, 2.0, 1.0), (2.0, 1.0, 3.0),
                                   (2.0, 3.0, 1.0), (1.0, 1.0, 1.0), (0.0, 0.0, 2.0),
                                   (-1.0, 0.5, 0.25), (0.3, -0.3, 0.9)])
    def test_antiparallel_axis_choice(self, a):
        # 180° about a × e, e the basis axis WPILib picks from |a| (issue 29, deliverable 1).
        ax, ay, az = (abs(v) for v in a)
        if ax < ay:
            e = (1.0, 0.0, 0.0) if ax < az else (0.0, 0.0, 1.0)
        else:
            e = (0.0, 1.0, 0.0) if ay < az else (0.0, 0.0, 1.0)
        axis = np.cross(a, e)
        axis = axis / math.sqrt(axis @ axis)
        rot = Rotation3d(np.array(a), -2.5 * np.array(a))
        assert rot.getQuaternion().getW() == 0.0
        assert_equals(Rotation3d(Quaternion(0.0, *axis)), rot)

    def test_two_vector_degenerate_inputs_give_identity(self):
        # A zero vector makes the cosine NaN: the last branch, normalised to the identity.
        assert_equals(Rotation3d.kZero, Rotation3d(np.zeros(3), X_AXIS))
        assert_equals(Rotation3d.kZero, Rotation3d(np.zeros(3), np.zeros(3)))

    def test_zero_axis_gives_identity(self):
        rot = Rotation3d(np.zeros(3), 1.0)
        assert_components((1.0, 0.0, 0.0, 0.0), rot.getQuaternion())
        assert_components((1.0, 0.0, 0.0, 0.0), Rotation3d(np.zeros(3)).getQuaternion())

    def test_quaternion_log_edges(self):
        # Norm 0 gives 0 (no division by zero, #9051); w/|q| = -1 picks the x axis; the
        # identity's log is exactly 0 (the series branch).
        assert_components((0.0, 0.0, 0.0, 0.0), Quaternion(0.0, 0.0, 0.0, 0.0).log())
        assert_components((math.log(2.0), -math.pi, 0.0, 0.0),
                          Quaternion(-2.0, 0.0, 0.0, 0.0).log())
        assert_components((0.0, 0.0, 0.0, 0.0), Quaternion(1.0, 0.0, 0.0, 0.0).log())

    def test_quaternion_normalize_zero_is_identity(self):
        assert_components((1.0, 0.0, 0.0, 0.0), Quaternion(0.0, 0.0, 0.0, 0.0).normalize())

    def test_rotation3d_normalises_like_wpilib_cpp(self):
        # n = sqrt(((w² + x²) + y²) + z²), each component divided by n, no FMA.
        w, x, y, z = 0.75, 0.3, 0.4, 0.5
        n = math.sqrt(((w * w + x * x) + y * y) + z * z)
        assert_components((w / n, x / n, y / n, z / n),
                          Rotation3d(Quaternion(w, x, y, z)).getQuaternion())

    def test_gimbal_lock_readout(self):
        # Pitch ±90°: roll reads 0 and yaw carries the sum (getX/getZ's gimbal rules).
        for pitch in (math.pi / 2, -math.pi / 2):
            rot = Rotation3d(0.3, pitch, 0.2)
            assert rot.getX() == 0.0
            q = _q(rot)
            assert_close(math.atan2(2.0 * q[0] * q[3], q[0] * q[0] - q[3] * q[3]), rot.getZ(),
                         1e-12)

    def test_matrix4_bottom_row_checked(self):
        m = Pose3d(1.0, 2.0, 3.0, Rotation3d(0.1, 0.2, 0.3)).toMatrix()
        for cls in (Pose3d, Transform3d):
            for i, bad in ((0, 1e-300), (3, 1.0 + 2.0 ** -52)):
                wrong = m.copy()
                wrong[3, i] = bad
                with pytest.raises(ValueError):
                    cls(wrong)

    def test_coordinate_axis_is_normalised(self):
        # A 45° turn about Z as a coordinate system with unnormalised axes.
        system = CoordinateSystem(CoordinateAxis(2.0, 2.0, 0.0), CoordinateAxis(-3.0, 3.0, 0.0),
                                  CoordinateAxis(0.0, 0.0, 5.0))
        converted = CoordinateSystem.convert(Translation3d(1.0, 0.0, 0.0), system,
                                             CoordinateSystem.NWU())
        assert_equals(Translation3d(math.sqrt(0.5), math.sqrt(0.5), 0.0), converted)

    def test_pose_interpolate_clamps_t(self):
        start = Pose3d(1.0, 2.0, 3.0, Rotation3d(0.1, 0.2, 0.3))
        end = Pose3d(-1.0, 0.5, 2.0, Rotation3d(-0.4, 0.1, 1.2))
        assert_equals(start, start.interpolate(end, -0.5))
        assert_equals(end, start.interpolate(end, 1.0))
        assert_equals(end, start.interpolate(end, 1.5))

    def test_rotation_interpolate_does_not_clamp_t(self):
        start = Rotation3d(Z_AXIS, 0.2)
        end = Rotation3d(Z_AXIS, 0.5)
        assert_equals(Rotation3d(Z_AXIS, 0.8), start.interpolate(end, 2.0))
        assert_equals(Rotation3d(Z_AXIS, -0.1), start.interpolate(end, -1.0))
