"""The registry covers the whole public API: every class of the catalog
(``drivekin._core.catalog``, which ``tests/api/test_catalog.py`` holds to every public
class) with every member found by introspection; a public callable that is not registered
fails here by name, so new classes and methods join the adversarial suite by construction
(see registry.py for how to add one)."""
from __future__ import annotations

import inspect

import drivekin
import drivekin.batch as batch
import drivekin.protobuf as protobuf
import drivekin.wpistruct as wpistruct
import pytest

from drivekin._core.renames import Renamed
from drivekin._core import catalog, pynames

from tests.safety.adversarial import registry as reg
from tests.safety.adversarial import support


# Every catalogued class but the warning categories (see registry.public_classes).
ATTACKED = [e for e in catalog.ENTRIES if e.kind != "warning"]

def _public_members(cls):
    # robotpy-wpimath 2026 names only raise (drivekin._core.renames), and robotpy 2027's
    # spellings are the Java members themselves (drivekin._core.pynames): not members.
    aliases = pynames.spellings(cls)
    names = {n for n in dir(cls) if not n.startswith("_") and n not in aliases
             and not isinstance(inspect.getattr_static(cls, n), Renamed)}
    # Protocol dunders count when drivekin defines them (on the class or a private base).
    names |= {n for n in reg.DUNDERS
              if any(n in k.__dict__ and k.__dict__[n] is not None for k in cls.__mro__[:-1])}
    return names - set(reg.REFUSED_OPERATORS.get(cls, ()))


@pytest.mark.parametrize("entry", ATTACKED, ids=lambda e: e.cls.__name__)
def test_every_public_member_is_registered(entry):
    cls = entry.cls
    assert cls in reg.API, f"{cls.__name__} has no entry in registry.API"
    assert cls in reg.VALID, f"{cls.__name__} has no factory in registry.VALID"
    missing = _public_members(cls) - set(reg.API[cls])
    assert not missing, f"{cls.__name__}: not in registry.API: {sorted(missing)}"
    stale = set(reg.API[cls]) - _public_members(cls)
    assert not stale, f"{cls.__name__}: registry names members it lacks: {sorted(stale)}"


def test_every_wpistruct_function_is_registered():
    public = set(wpistruct.__all__) - reg.WPISTRUCT_NONCALLABLE
    assert public == set(reg.WPISTRUCT), sorted(public ^ set(reg.WPISTRUCT))


def test_every_batch_function_is_registered():
    assert set(batch.__all__) == set(reg.BATCH), sorted(set(batch.__all__) ^ set(reg.BATCH))


def test_every_protobuf_function_is_registered():
    public = set(protobuf.__all__) - reg.PROTOBUF_NONCALLABLE
    assert public == set(reg.PROTOBUF), sorted(public ^ set(reg.PROTOBUF))


def test_registry_has_no_unknown_classes():
    catalogued = {e.cls for e in ATTACKED}
    assert set(reg.public_classes()) == catalogued
    assert set(reg.API) == catalogued, sorted(c.__name__ for c in set(reg.API) ^ catalogued)
    assert set(reg.VALID) == catalogued, sorted(c.__name__ for c in set(reg.VALID) ^ catalogued)


@pytest.mark.parametrize("entry", ATTACKED, ids=lambda e: e.cls.__name__)
def test_valid_instances_are_the_catalog_examples(entry):
    # A factory of the registry's own is a SPECIAL case, with its reason.
    cls = entry.cls
    if cls in reg.SPECIAL:
        assert reg.VALID[cls] is not entry.example, f"{cls.__name__} is not special"
    else:
        assert reg.VALID[cls] is entry.example, (
            f"{cls.__name__}: registry.VALID has its own factory; use the catalog's "
            "example, or say why in registry.SPECIAL")
    obj = reg.VALID[cls]()
    if entry.example is None:           # Units: its static methods' receiver is the class
        assert obj is cls
    else:
        assert type(obj) is cls


def test_kinds_follow_the_catalog():
    assert reg.KINEMATICS == {e.cls for e in catalog.entries("kinematics")}
    assert reg.ODOMETRY == {e.cls for e in catalog.entries("odometry")}
    assert reg.ESTIMATORS == {e.cls for e in catalog.entries("estimator")}
    assert reg.ODOMETRY3D == {e.cls for e in catalog.entries("odometry3d")}
    assert reg.ESTIMATORS3D == {e.cls for e in catalog.entries("estimator3d")}
    assert reg.IMMUTABLE <= {e.cls for e in catalog.entries("value")}
    assert reg.INIT_ONCE >= (reg.KINEMATICS | reg.ODOMETRY | reg.ESTIMATORS | reg.ODOMETRY3D
                             | reg.ESTIMATORS3D | reg.IMMUTABLE)


@pytest.mark.parametrize("cls", sorted(reg.ODOMETRY, key=lambda c: c.__name__),
                         ids=lambda c: c.__name__)
def test_odometry_starts_at_the_probe_readings(cls):
    # support's snapshot of an odometry object updates it with the probe's readings
    # (gyro GYRO0, zero distances): a no-op only if the factory starts there.
    obj = reg.VALID[cls]()
    pose = (obj.getPose().x, obj.getPose().y, obj.getPose().getRotation().getRadians())
    assert support.snap(obj) == support.snap(obj)
    assert (obj.getPose().x, obj.getPose().y,
            obj.getPose().getRotation().getRadians()) == pose


@pytest.mark.parametrize("cls", sorted(reg.ODOMETRY3D, key=lambda c: c.__name__),
                         ids=lambda c: c.__name__)
def test_odometry3d_starts_at_the_probe_readings(cls):
    obj = reg.VALID[cls]()
    before = support.snap(obj)
    assert support.snap(obj) == before   # each snap updates with the probe's readings
