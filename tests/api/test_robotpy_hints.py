"""``drivekin._core.errors.type_name`` names a robotpy-wpimath object with the
``drivekin.interop`` call that converts it (``fromWpimath``, or ``fromWpimath3d`` for a
3-D one), only where interop converts it to what is expected, and never fails.
"""
from __future__ import annotations

import pytest

import drivekin
from drivekin._core import catalog
from drivekin._core.errors import type_name

HINT = "(a robotpy-wpimath object: convert it with drivekin.interop.fromWpimath(value))"
HINT_3D = ("(a robotpy-wpimath 3-D object: convert its 2-D part with "
           "drivekin.interop.fromWpimath3d(value))")


# ---- the hint: drivekin._core.errors.type_name ---------------------------------------------

PEERS = [pytest.param(e, id=e.cls.__name__) for e in catalog.ENTRIES if e.peer is not None]


@pytest.mark.parametrize("entry", PEERS)
def test_every_catalogued_peer_gets_the_hint(entry, wpimath_geo):
    from drivekin.interop import toWpimath

    value = toWpimath(entry.example())
    name = f"{type(value).__module__}.{type(value).__qualname__}"
    assert type_name(value) == f"{name} {HINT}"
    assert type_name(value, entry.cls) == f"{name} {HINT}"
    # Only where the conversion gives what is expected: a Twist2d's peer is no Pose2d.
    other = drivekin.Twist2d if entry.cls is not drivekin.Twist2d else drivekin.Pose2d
    assert type_name(value, other) == name


def test_a_subclass_of_a_robotpy_class_gets_the_hint(wpimath_geo):
    # interop converts subclasses of robotpy classes (their bases are looked up too).
    class MyPose(wpimath_geo.Pose2d):
        pass

    assert type_name(MyPose()) == f"{__name__}.{MyPose.__qualname__} {HINT}"


@pytest.mark.parametrize("name, expected, hint", [
    ("Pose3d", drivekin.Pose2d, True),
    ("Transform3d", drivekin.Transform2d, True),
    ("Translation3d", drivekin.Translation2d, True),
    ("Rotation3d", drivekin.Rotation2d, True),
    ("Pose3d", drivekin.Rotation2d, False),
    ("Rotation3d", drivekin.Pose2d, False),
])
def test_3d_objects_point_to_fromwpimath3d(name, expected, hint, wpimath_geo):
    value = getattr(wpimath_geo, name)()
    full = f"{type(value).__module__}.{type(value).__qualname__}"
    assert type_name(value) == f"{full} {HINT_3D}"
    assert type_name(value, expected) == (f"{full} {HINT_3D}" if hint else full)


def test_no_false_hint_for_robotpy_types_interop_does_not_convert(wpimath_geo, wpimath_kin):
    # 3-D values fromWpimath3d does not flatten, and robotpy's stateful classes.
    odometry = wpimath_kin.DifferentialDriveOdometry(wpimath_geo.Rotation2d(), 0.0, 0.0)
    for value in (wpimath_geo.Twist3d(), wpimath_geo.Quaternion(), odometry):
        assert type_name(value) == f"{type(value).__module__}.{type(value).__qualname__}"
    # Containers are named as such (interop converts only their items).
    assert type_name([wpimath_geo.Pose2d()]) == "list"


def test_no_hint_for_other_objects_and_no_failure_without_robotpy(monkeypatch):
    # Not robotpy's (a look-alike module name), and robotpy failing to load: the plain
    # name, and the error message itself never fails.
    from drivekin import interop

    fake = type("Pose2d", (), {"__module__": "wpimath.geometry._geometry"})()
    assert type_name(fake) == "wpimath.geometry._geometry.Pose2d"
    assert type_name(type("Pose2d", (), {"__module__": "wpimathx"})()) == "wpimathx.Pose2d"
    assert type_name(drivekin.Pose2d()) == "Pose2d"
    assert type_name(None) == "NoneType"

    def missing():
        raise ModuleNotFoundError("No module named 'wpimath'", name="wpimath")

    monkeypatch.setattr(interop, "_load", missing)
    assert type_name(fake) == "wpimath.geometry._geometry.Pose2d"
