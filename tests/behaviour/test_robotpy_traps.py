"""The traps of docs/porting.md ("Behaviour that changed"), checked against the installed
robotpy-wpimath 2026 and drivekin: if robotpy changes, that page must change with it."""
from __future__ import annotations

import math

import pytest

from drivekin import (
    DifferentialDriveWheelVelocities,
    MecanumDriveWheelVelocities,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveModuleVelocity,
    Units,
)

g = pytest.importorskip("wpimath.geometry")
k = pytest.importorskip("wpimath.kinematics")
units = pytest.importorskip("wpimath.units")


def test_robotpy_keeps_the_constructed_angle_drivekin_wraps():
    assert g.Rotation2d.fromDegrees(725).degrees() == 725.0
    assert (g.Rotation2d.fromDegrees(270) * 0.5).degrees() == 135.0
    assert g.Rotation2d(3 * math.pi / 2).degrees() == 270.0
    assert abs(Rotation2d.fromDegrees(725).getDegrees() - 5.0) < 1e-12
    assert abs((Rotation2d.fromDegrees(270) * 0.5).getDegrees() + 45.0) < 1e-12
    assert abs(Rotation2d(3 * math.pi / 2).getDegrees() + 90.0) < 1e-12
    # robotpy already compared by cos/sin.
    assert g.Rotation2d.fromDegrees(725) == g.Rotation2d.fromDegrees(5)


def test_robotpy_optimize_and_cosine_scale_mutate_drivekins_return_new():
    s = k.SwerveModuleState(2.0, g.Rotation2d(3.0))
    assert s.optimize(g.Rotation2d(0.0)) is None and s.speed == -2.0
    s = k.SwerveModuleState(2.0, g.Rotation2d(0.5))
    assert s.cosineScale(g.Rotation2d(0.0)) is None
    assert abs(s.speed - 2.0 * math.cos(0.5)) < 1e-12

    d = SwerveModuleVelocity(2.0, Rotation2d(3.0))
    assert d.optimize(Rotation2d(0.0)).velocity == -2.0 and d.velocity == 2.0
    assert abs(d.cosineScale(Rotation2d(0.5)).velocity - 2.0 * math.cos(2.5)) < 1e-12
    assert d.velocity == 2.0
    assert d.optimizeInPlace(Rotation2d(0.0)) is None and d.velocity == -2.0


def test_robotpy_wheel_desaturate_mutates_drivekins_returns_new():
    m, w = k.MecanumDriveWheelSpeeds(5.0, 1.0, 1.0, 1.0), k.DifferentialDriveWheelSpeeds(5.0, 1.0)
    assert m.desaturate(1.0) is None and m.frontLeft == 1.0
    assert w.desaturate(1.0) is None and w.left == 1.0
    dm, dw = MecanumDriveWheelVelocities(5.0, 1.0, 1.0, 1.0), DifferentialDriveWheelVelocities(5.0, 1.0)
    assert dm.desaturate(1.0).frontLeft == 1.0 and dm.frontLeft == 5.0
    assert dw.desaturate(1.0).left == 1.0 and dw.left == 5.0


@pytest.mark.parametrize("container", [list, tuple])
def test_robotpy_desaturate_wheel_speeds_does_not_mutate_its_argument(container):
    def states():
        return container(k.SwerveModuleState(5.0, g.Rotation2d(0.1 * i)) for i in range(4))

    for extra in ((1.0,), (k.ChassisSpeeds(1.0, 1.0, 1.0), 1.0, 1.0, 1.0)):
        arg = states()
        out = k.SwerveDrive4Kinematics.desaturateWheelSpeeds(arg, *extra)
        assert [s.speed for s in arg] == [5.0] * 4               # untouched
        assert all(s.speed < 5.0 for s in out) and type(out) is tuple
    # drivekin: the same call shape returns new objects too.
    ours = [SwerveModuleVelocity(5.0, Rotation2d(0.1 * i)) for i in range(4)]
    out = SwerveDriveKinematics.desaturateWheelVelocities(ours, 1.0)
    assert [s.velocity for s in ours] == [5.0] * 4 and [s.velocity for s in out] == [1.0] * 4


def test_rpm_conversion_differs_in_the_last_bits():
    assert units.rotationsPerMinuteToRadiansPerSecond(60.0) == 2 * math.pi
    assert Units.rotationsPerMinuteToRadiansPerSecond(60.0) == math.nextafter(2 * math.pi, 0.0)
