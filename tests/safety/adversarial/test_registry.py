"""The registry covers the whole public API: a public callable that is not registered
fails here by name, so new classes and methods join the adversarial suite by
construction (see registry.py for how to add one)."""
from __future__ import annotations

import drivekin
import drivekin.batch as batch
import drivekin.protobuf as protobuf
import drivekin.wpistruct as wpistruct
import pytest

from tests.safety.adversarial import registry as reg


def _public_members(cls):
    names = {n for n in dir(cls) if not n.startswith("_")}
    # Protocol dunders count when drivekin defines them (on the class or a private base).
    names |= {n for n in reg.DUNDERS
              if any(n in k.__dict__ and k.__dict__[n] is not None for k in cls.__mro__[:-1])}
    return names


@pytest.mark.parametrize("cls", reg.public_classes(), ids=lambda c: c.__name__)
def test_every_public_member_is_registered(cls):
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
    assert set(reg.API) == set(reg.public_classes())
