"""What robotpy-wpimath code relies on when it is ported to drivekin (issue 15's porting
friction), checked against robotpy-wpimath 2026 itself where it has the behaviour."""
from __future__ import annotations

import pytest

from drivekin import (Pose2d, Rotation2d, SwerveModuleAcceleration, SwerveModulePosition,
                      SwerveModuleVelocity, Transform2d, Translation2d)

wg = pytest.importorskip("wpimath.geometry")

ANGLES = [0.5, -2.0, 3.5, 0, 7]


def same_rotation(r, wr):
    # The (cos, sin) robotpy computes for Rotation2d(radians), bit for bit.
    assert (r.getCos(), r.getSin()) == (wr.cos(), wr.sin())


@pytest.mark.parametrize("angle", ANGLES)
def test_a_number_where_a_rotation_is_expected_means_radians(angle):
    for cls, wcls in ((Pose2d, wg.Pose2d), (Transform2d, wg.Transform2d)):
        d, w = cls(1.5, -2.0, angle), wcls(1.5, -2.0, angle)
        assert (d.x, d.y) == (w.x, w.y)
        same_rotation(d.getRotation(), w.rotation())
        assert d == cls(1.5, -2.0, Rotation2d(angle))
        t = cls(Translation2d(1.5, -2.0), angle)
        assert t == d
    # robotpy-wpimath 2026's module states take only a Rotation2d; the float means what it
    # means in its geometry constructors.
    for cls in (SwerveModuleVelocity, SwerveModulePosition, SwerveModuleAcceleration):
        d = cls(2.0, angle)
        assert d.angle == Rotation2d(angle)
        same_rotation(d.angle, wg.Rotation2d(angle))


def test_what_is_not_a_number_is_still_refused():
    for bad in ("0.5", True, None, object()):
        with pytest.raises(TypeError, match="Rotation2d"):
            Pose2d(1.0, 2.0, bad)
        with pytest.raises(TypeError, match="Rotation2d"):
            Transform2d(Translation2d(), bad)
    for bad in ("0.5", True, object()):
        with pytest.raises(TypeError, match="Rotation2d"):
            SwerveModuleVelocity(1.0, bad)


def test_a_missing_rotation_is_named():
    with pytest.raises(TypeError, match=r"Pose2d\(\) is missing its rotation.*radians"):
        Pose2d(1.0, 2.0)
    with pytest.raises(TypeError, match=r"Transform2d\(\) is missing its rotation"):
        Transform2d(1.0, 2.0)


def _renames():
    from drivekin._core.renames import RENAMES
    return [(cls, old, new) for cls, names in RENAMES.items() for old, new in names.items()]


@pytest.mark.parametrize("cls, old, new", _renames())
def test_a_2026_name_raises_an_attribute_error_naming_the_2027_one(cls, old, new):
    import drivekin
    from drivekin._core import catalog
    klass = getattr(drivekin, cls)
    entry = catalog.BY_CLASS[klass]
    # The old name really is robotpy-wpimath 2026's, on the peer class.
    peer = getattr(pytest.importorskip(f"wpimath.{entry.peer.module}"), entry.peer.names[-1])
    assert hasattr(peer, old), f"{entry.peer.names[-1]}.{old} is not a robotpy 2026 name"
    # The replacement exists on drivekin's class (its first identifier, where it names one).
    first = new.split("(")[0].split(" ")[0].lstrip(".")
    assert first == cls or hasattr(klass, first), (cls, new)
    instance = entry.example()
    for where in (klass, instance):
        with pytest.raises(AttributeError) as info:
            getattr(where, old)
        assert new in str(info.value) and old in str(info.value)
    assert not hasattr(instance, old)
