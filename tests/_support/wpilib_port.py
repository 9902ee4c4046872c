"""Pieces shared by the WPILib JUnit tests restated for drivekin (``tests/reference/``) and
by the API tests that use WPILib's test robot.

Imported by the test modules as ``from tests._support.wpilib_port import ...``.
"""
from __future__ import annotations

import math

import pytest

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


# ---- the accuracy tests' ground truth and noise (odometry, estimator, dead wheels) -------
DT = 0.02  # s, the accuracy tests' time step


def trajectory_generator():
    """Return generate(waypoints, maxV, maxA) backed by robotpy-wpimath, or skip."""
    geometry = pytest.importorskip("wpimath.geometry")
    trajectory = pytest.importorskip("wpimath.trajectory")

    def generate(waypoints, max_velocity, max_acceleration):
        poses = [geometry.Pose2d(x, y, geometry.Rotation2d(theta)) for x, y, theta in waypoints]
        return trajectory.TrajectoryGenerator.generateTrajectory(
            poses, trajectory.TrajectoryConfig(max_velocity, max_acceleration))

    return generate


class JavaRandom:
    """java.util.Random: 48-bit LCG, nextDouble from 26 + 27 bits, polar-method Gaussian."""

    _MULT = 0x5DEECE66D
    _MASK = (1 << 48) - 1

    def __init__(self, seed):
        self._seed = (seed ^ self._MULT) & self._MASK
        self._next_next_gaussian = None

    def _next(self, bits):
        self._seed = (self._seed * self._MULT + 0xB) & self._MASK
        r = self._seed >> (48 - bits)
        return r - (1 << 32) if r >= 1 << 31 else r

    def next_double(self):
        return ((self._next(26) << 27) + self._next(27)) * 2.0 ** -53

    def next_gaussian(self):
        if self._next_next_gaussian is not None:
            g, self._next_next_gaussian = self._next_next_gaussian, None
            return g
        while True:
            v1 = 2 * self.next_double() - 1
            v2 = 2 * self.next_double() - 1
            s = v1 * v1 + v2 * v2
            if 0 < s < 1:
                break
        multiplier = math.sqrt(-2 * math.log(s) / s)
        self._next_next_gaussian = v2 * multiplier
        return v1 * multiplier
