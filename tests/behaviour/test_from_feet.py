"""The fromFeet factories of the geometry classes: the same bits as robotpy-wpimath 2026's
(whose C++ units library converts feet as ``ft * 381 / 1250``). Rotations from an angle
are drivekin's own sin and cos, at most 1 ulp from the exact value where libm's are within
half an ulp, so those parts are compared to a neighbouring double."""
from __future__ import annotations

import math
import struct

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


def frame_bits(p) -> tuple[bytes, ...]:
    return bits(p.x, p.y, *cos_sin(p))


def neighbours(a: float, b: float) -> bool:
    """a and b are the same double or adjacent ones (NaN matches NaN)."""
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return a == b or math.nextafter(a, b) == b


def same_frame(ours, theirs) -> bool:
    """Translations bit for bit, rotations (cos, sin) to a neighbouring double."""
    return bits(ours.x, ours.y) == bits(theirs.x, theirs.y) and all(
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
    assert bits(*Translation2d.fromFeet(x, y)) == bits(*g.Translation2d.fromFeet(x, y))


@given(d=anything, a=angles)
def test_translation_from_distance_and_angle(g, d, a):
    # The distance converts as robotpy's does, then scales drivekin's own rotation.
    r = Rotation2d(a)
    meters = g.Translation2d.fromFeet(d, 0.0).x
    assert bits(*Translation2d.fromFeet(d, r)) == bits(meters * r.getCos(), meters * r.getSin())
    theirs = g.Rotation2d(a)
    assert neighbours(r.getCos(), theirs.cos()) and neighbours(r.getSin(), theirs.sin())


@pytest.mark.parametrize("name", ["Pose2d", "Transform2d"])
@given(x=anything, y=anything, a=angles)
def test_pose_and_transform_with_radians(g, name, x, y, a):
    ours = {"Pose2d": Pose2d, "Transform2d": Transform2d}[name].fromFeet(x, y, a)
    assert same_frame(ours, getattr(g, name).fromFeet(x, y, a))


@given(x=anything, y=anything, a=angles)
def test_pose_with_a_rotation(g, x, y, a):
    # robotpy's Transform2d.fromFeet takes radians only; drivekin's takes either.
    assert same_frame(Pose2d.fromFeet(x, y, Rotation2d(a)),
                      g.Pose2d.fromFeet(x, y, g.Rotation2d(a)))
    assert frame_bits(Transform2d.fromFeet(x, y, Rotation2d(a))) == \
        frame_bits(Transform2d.fromFeet(x, y, a))


@given(dx=anything, dy=anything, dtheta=anything)
def test_twist(g, dx, dy, dtheta):
    ours, theirs = Twist2d.fromFeet(dx, dy, dtheta), g.Twist2d.fromFeet(dx, dy, dtheta)
    assert bits(ours.dx, ours.dy, ours.dtheta) == bits(theirs.dx, theirs.dy, theirs.dtheta)


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
    assert bits(ours.vx, ours.vy, ours.omega) == bits(theirs.vx, theirs.vy, theirs.omega)
    assert ChassisVelocities.fromFeet() == ChassisVelocities()


@given(anything, anything, anything, anything)
def test_wheel_velocities_from_feet_match_robotpy_bits(a, b, c, d):
    k = pytest.importorskip("wpimath.kinematics")
    from drivekin import DifferentialDriveWheelVelocities, MecanumDriveWheelVelocities

    ours = MecanumDriveWheelVelocities.fromFeet(a, b, c, d)
    theirs = k.MecanumDriveWheelSpeeds.fromFeet(a, b, c, d)
    assert bits(ours.frontLeft, ours.frontRight, ours.rearLeft, ours.rearRight) == \
        bits(theirs.frontLeft, theirs.frontRight, theirs.rearLeft, theirs.rearRight)
    two = DifferentialDriveWheelVelocities.fromFeet(a, b)
    rp = k.DifferentialDriveWheelSpeeds.fromFeet(a, b)
    assert bits(two.left, two.right) == bits(rp.left, rp.right)
    assert type(ours) is MecanumDriveWheelVelocities and type(two) is DifferentialDriveWheelVelocities
