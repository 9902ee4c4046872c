"""The fromFeet factories of the geometry classes: the same bits as robotpy-wpimath 2026's
(whose C++ units library converts feet as ``ft * 381 / 1250``)."""
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


def frame_bits(p) -> tuple[bytes, ...]:
    # drivekin Pose2d/Transform2d or robotpy's: x, y and the stored (cos, sin).
    r = p.getRotation() if hasattr(p, "getRotation") else p.rotation()
    c, s = (r.getCos(), r.getSin()) if hasattr(r, "getCos") else (r.cos(), r.sin())
    return bits(p.x, p.y, c, s)


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
    ours = Translation2d.fromFeet(d, Rotation2d(a))
    assert bits(*ours) == bits(*g.Translation2d.fromFeet(d, g.Rotation2d(a)))


@pytest.mark.parametrize("name", ["Pose2d", "Transform2d"])
@given(x=anything, y=anything, a=angles)
def test_pose_and_transform_with_radians(g, name, x, y, a):
    ours = {"Pose2d": Pose2d, "Transform2d": Transform2d}[name].fromFeet(x, y, a)
    assert frame_bits(ours) == frame_bits(getattr(g, name).fromFeet(x, y, a))


@given(x=anything, y=anything, a=angles)
def test_pose_with_a_rotation(g, x, y, a):
    # robotpy's Transform2d.fromFeet takes radians only; drivekin's takes either.
    assert frame_bits(Pose2d.fromFeet(x, y, Rotation2d(a))) == \
        frame_bits(g.Pose2d.fromFeet(x, y, g.Rotation2d(a)))
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
