"""Pieces shared by the WPILib JUnit tests restated for drivekin (``tests/reference/``) and
by the API tests that use WPILib's test robot.

Importable from any test module as ``from wpilib_port import ...`` (``tests/conftest.py``
puts ``tests/`` on ``sys.path``).
"""
from __future__ import annotations

import math

from drivekin import Translation2d

EPS = 1e-9  # WPILib kEpsilon

# WPILib's test robot (SwerveDriveKinematicsTest, MecanumDriveKinematicsTest and the
# odometry tests): modules / wheels at (±12, ±12), front left, front right, back (rear)
# left, back (rear) right. Translation2d is immutable, so modules can share these.
FL = Translation2d(12, 12)
FR = Translation2d(12, -12)
BL = Translation2d(-12, 12)
BR = Translation2d(-12, -12)
WHEELS = (FL, FR, BL, BR)


def assert_close(expected, actual, tol=EPS):
    """JUnit assertEquals(expected, actual, delta): |expected - actual| <= delta."""
    assert math.isclose(actual, expected, rel_tol=0.0, abs_tol=tol), (
        f"expected {expected!r}, got {actual!r} (|diff| = {abs(actual - expected)!r} > {tol!r})")


def assert_pose(expected, pose, tol=EPS):
    """expected = (x m, y m, heading rad); heading compared on the unit circle."""
    x, y, theta = expected
    assert_close(x, pose.getX(), tol)
    assert_close(y, pose.getY(), tol)
    r = pose.getRotation()
    assert math.hypot(r.getCos() - math.cos(theta), r.getSin() - math.sin(theta)) <= tol, (
        f"expected heading {math.degrees(theta)!r} deg, got {r.getDegrees()!r} deg")
