"""The fromFeet factories of the geometry classes: the same bits as robotpy-wpimath 2026's
(whose C++ units library converts feet as ``ft * 381 / 1250``), except where robotpy's
product overflows (|ft| above about 4.7e305): the length in metres fits a double, and
drivekin gives it (dividing first) where robotpy gives inf. Rotations from an angle
are drivekin's own sin and cos, at most 1 ulp from the exact value where libm's are within
half an ulp, so those parts are compared to a neighbouring double."""
from __future__ import annotations

import math
import struct
from fractions import Fraction

import pytest
from hypothesis import example, given, strategies as st

from drivekin import Pose2d, Rotation2d, Transform2d, Translation2d, Twist2d, Units

anything = st.floats()
angles = st.one_of(st.sampled_from([0.0, math.pi, -math.pi, 3 * math.pi / 2]), anything)


def bits(*xs: float) -> tuple[bytes, ...]:
    return tuple(struct.pack("<d", x) for x in xs)


def cos_sin(p) -> tuple[float, float]:
    # The stored (cos, sin) of a drivekin or robotpy Pose2d/Transform2d.
    r = p.getRotation() if hasattr(p, "getRotation") else p.rotation()
    return (r.getCos(), r.getSin()) if hasattr(r, "getCos") else (r.cos(), r.sin())


def meters(theirs: float, feet: float) -> float:
    """robotpy's conversion of ``feet``, or, where it overflowed from finite feet, the
    value drivekin gives instead (division first)."""
    if math.isinf(theirs) and math.isfinite(feet):
        return feet / 1250.0 * 381.0
    return theirs


def frame_bits(p) -> tuple[bytes, ...]:
    return bits(p.x, p.y, *cos_sin(p))


def neighbours(a: float, b: float) -> bool:
    """a and b are the same double or adjacent ones (NaN matches NaN)."""
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return a == b or math.nextafter(a, b) == b


def same_frame(ours, theirs, x, y) -> bool:
    """Translations bit for bit (given in feet as x, y), rotations (cos, sin) to a
    neighbouring double."""
    return bits(ours.x, ours.y) == bits(meters(theirs.x, x), meters(theirs.y, y)) and all(
        neighbours(a, b) for a, b in zip(cos_sin(ours), cos_sin(theirs)))


@pytest.fixture(scope="module")
def g():
    return pytest.importorskip("wpimath.geometry")


def test_one_foot():
    assert Translation2d.fromFeet(1.0, -2.0) == Translation2d(0.3048, -0.6096)
    assert bits(*Translation2d.fromFeet(1.0, -2.0)) == bits(0.3048, -0.6096)
    # Units.feetToMeters follows Java (through inches) and lands one ulp lower.
    assert Units.feetToMeters(1.0) == 0.30479999999999996 != Translation2d.fromFeet(1.0, 0.0).x
    assert Twist2d.fromFeet() == Twist2d() and Twist2d.fromFeet(dtheta=2.0).dtheta == 2.0


@given(x=anything, y=anything)
@example(x=1.0, y=-0.0)
@example(x=1.7976931348623157e308, y=5e-324)
def test_translation(g, x, y):
    theirs = g.Translation2d.fromFeet(x, y)
    assert bits(*Translation2d.fromFeet(x, y)) == bits(meters(theirs.x, x), meters(theirs.y, y))


@pytest.mark.parametrize("feet", [1.7976931348623157e308, -1e306, 4.8e305])
def test_feet_beyond_robotpys_overflow_convert_exactly(feet):
    # robotpy's ft * 381 overflows; the length in metres is a double, within an ulp.
    exact = Fraction(feet) * Fraction(381, 1250)
    for got in (Translation2d.fromFeet(feet, 0.0).x, Twist2d.fromFeet(feet).dx,
                Pose2d.fromFeet(0.0, feet, 0.0).y):
        assert math.isfinite(got) and abs(Fraction(got) - exact) <= abs(exact) * 2 ** -52


@given(d=anything, a=angles)
def test_translation_from_distance_and_angle(g, d, a):
    # The distance converts as robotpy's does, then scales drivekin's own rotation.
    r = Rotation2d(a)
    m = meters(g.Translation2d.fromFeet(d, 0.0).x, d)
    assert bits(*Translation2d.fromFeet(d, r)) == bits(m * r.getCos(), m * r.getSin())
    theirs = g.Rotation2d(a)
    assert neighbours(r.getCos(), theirs.cos()) and neighbours(r.getSin(), theirs.sin())


@pytest.mark.parametrize("name", ["Pose2d", "Transform2d"])
@given(x=anything, y=anything, a=angles)
def test_pose_and_transform_with_radians(g, name, x, y, a):
    ours = {"Pose2d": Pose2d, "Transform2d": Transform2d}[name].fromFeet(x, y, a)
    assert same_frame(ours, getattr(g, name).fromFeet(x, y, a), x, y)


@given(x=anything, y=anything, a=angles)
def test_pose_with_a_rotation(g, x, y, a):
    # robotpy's Transform2d.fromFeet takes radians only; drivekin's takes either.
    assert same_frame(Pose2d.fromFeet(x, y, Rotation2d(a)),
                      g.Pose2d.fromFeet(x, y, g.Rotation2d(a)), x, y)
    assert frame_bits(Transform2d.fromFeet(x, y, Rotation2d(a))) == \
        frame_bits(Transform2d.fromFeet(x, y, a))


@given(dx=anything, dy=anything, dtheta=anything)
def test_twist(g, dx, dy, dtheta):
    ours, theirs = Twist2d.fromFeet(dx, dy, dtheta), g.Twist2d.fromFeet(dx, dy, dtheta)
    assert bits(ours.dx, ours.dy, ours.dtheta) == \
        bits(meters(theirs.dx, dx), meters(theirs.dy, dy), theirs.dtheta)


@pytest.mark.parametrize("call", [
    lambda g: Translation2d.fromFeet(1.0, g.Rotation2d(0.5)),
    lambda g: Pose2d.fromFeet(1.0, 2.0, g.Rotation2d(0.5)),
    lambda g: Transform2d.fromFeet(1.0, 2.0, g.Rotation2d(0.5)),
])
def test_a_robotpy_rotation_is_named(g, call):
    with pytest.raises(TypeError, match=r"drivekin Rotation2d.*got wpimath\.geometry"):
        call(g)


@pytest.mark.parametrize("call", [
    lambda: Translation2d.fromFeet(1.0, "2"), lambda: Translation2d.fromFeet(None, 2.0),
    lambda: Pose2d.fromFeet(1.0, 2.0, None), lambda: Pose2d.fromFeet(1.0, 2.0),
    lambda: Transform2d.fromFeet(1.0, 2.0, Translation2d()),
    lambda: Twist2d.fromFeet(1.0, 2.0, 3.0, 4.0), lambda: Twist2d.fromFeet(dz=1.0),
])
def test_bad_arguments(call):
    with pytest.raises(TypeError):
        call()


@given(anything, anything, anything)
def test_chassis_velocities_from_feet_matches_robotpy_bits(vx, vy, omega):
    k = pytest.importorskip("wpimath.kinematics")
    from drivekin import ChassisVelocities

    ours = ChassisVelocities.fromFeet(vx, vy, omega)
    theirs = k.ChassisSpeeds.fromFeet(vx, vy, omega)
    assert bits(ours.vx, ours.vy, ours.omega) == \
        bits(meters(theirs.vx, vx), meters(theirs.vy, vy), theirs.omega)
    assert ChassisVelocities.fromFeet() == ChassisVelocities()


@given(anything, anything, anything, anything)
def test_wheel_velocities_from_feet_match_robotpy_bits(a, b, c, d):
    k = pytest.importorskip("wpimath.kinematics")
    from drivekin import DifferentialDriveWheelVelocities, MecanumDriveWheelVelocities

    ours = MecanumDriveWheelVelocities.fromFeet(a, b, c, d)
    theirs = k.MecanumDriveWheelSpeeds.fromFeet(a, b, c, d)
    assert bits(ours.frontLeft, ours.frontRight, ours.rearLeft, ours.rearRight) == bits(
        meters(theirs.frontLeft, a), meters(theirs.frontRight, b),
        meters(theirs.rearLeft, c), meters(theirs.rearRight, d))
    two = DifferentialDriveWheelVelocities.fromFeet(a, b)
    rp = k.DifferentialDriveWheelSpeeds.fromFeet(a, b)
    assert bits(two.left, two.right) == bits(meters(rp.left, a), meters(rp.right, b))
    assert type(ours) is MecanumDriveWheelVelocities and type(two) is DifferentialDriveWheelVelocities
