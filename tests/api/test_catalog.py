"""The catalog (``drivekin._core.catalog``) registers every public class once, and the
integrations built on it agree with it.

* Every public class of drivekin (``drivekin.__all__`` and the public submodules) has an
  entry; a missing one fails here by name. No class has two.
* Kinds match the contracts: the kinematics classes that implement the drivetrain
  contract subclass ``_core.drivetrain.Drivetrain``, the odometry classes
  ``odometry._Odometry``, the estimators ``estimator._PoseEstimator``, the 3-D ones
  ``odometry3d._Odometry3d`` and ``estimator3d._PoseEstimator3d``, and no other entry
  does; every subclass of those bases is catalogued.
* wpistruct, protobuf, interop and ``SerializableValue`` cover exactly the entries with a
  struct, a protobuf message, a robotpy-wpimath peer.
* Every ``example`` builds a fresh instance of exactly its class, and ``flatten``/``build``
  round-trip it bit for bit.

The test registries (``tests/safety/adversarial/registry.py``, ``tests/allocation``,
``scripts/leakcheck.py``, ``benchmarks/``) take their classes and instances from here.
"""
from __future__ import annotations

import importlib
import inspect
import math
import pkgutil
import struct
import typing

import pytest

import drivekin
from drivekin._core.pynames import RobotpyClass
from drivekin import interop, protobuf, wpistruct
from drivekin._core import catalog
from drivekin._core.drivetrain import Drivetrain
from drivekin.estimator import _PoseEstimator
from drivekin.estimator3d import _PoseEstimator3d
from drivekin.geometry3d import Pose3d, Rotation3d, Transform3d
from drivekin.odometry import _Odometry
from drivekin.odometry3d import _Odometry3d

KINDS = {"value", "kinematics", "odometry", "estimator", "odometry3d", "estimator3d", "helper",
         "warning"}

# Public submodules whose classes are not the catalog's kinds: the .wpilog reader/writer
# and its records (drivekin.datalog), replay's configuration and results (drivekin.replay),
# the calibration's results (drivekin.calibrate), Choreo trajectories and their samples
# (drivekin.choreo, its sample classes compiled in drivekin._core.choreokernel, its
# feasibility report in drivekin._core.choreocheck). Their re-exports of catalogued
# classes are still checked.
LOG_TOOLS = {"drivekin.datalog", "drivekin.replay", "drivekin.calibrate", "drivekin.choreo",
             "drivekin._core.choreokernel", "drivekin._core.choreocheck"}
# The modules the issue names: discovery must find every one of them.
EXPECTED_MODULES = {"chassis", "swervemodule", "swerve", "geometry", "mecanum", "differential",
                    "deadwheel", "diffswerve", "odometry", "estimator", "odometry3d",
                    "estimator3d", "interpolation",
                    "units", "kinematics", "batch", "wpistruct", "protobuf", "interop"}
# Kinematics entries that do not implement the drivetrain contract, and why.
NOT_A_DRIVETRAIN = {
    drivekin.DifferentialSwerveModuleKinematics:
        "one differential swerve pod's motor <-> module conversion, not a drivetrain",
}
# Entries without an example, and why.
NO_EXAMPLE = {drivekin.Units: "static methods only: it refuses to be instantiated"}


def _public_modules() -> list[str]:
    return sorted(m.name for m in pkgutil.iter_modules(drivekin.__path__)
                  if not m.name.startswith("_") and m.name != "app")


def _public_classes() -> dict[type, str]:
    """Every public class reachable from drivekin.__all__ and the public submodules, with
    the first place it was found."""
    found: dict[type, str] = {}
    for name in drivekin.__all__:
        obj = getattr(drivekin, name)
        # robotpy's class names (SwerveDrive4Kinematics) build catalog classes; they
        # have no instances of their own.
        if inspect.isclass(obj) and not isinstance(obj, RobotpyClass):
            found.setdefault(obj, f"drivekin.{name}")
    for m in _public_modules():
        module = importlib.import_module(f"drivekin.{m}")
        names = getattr(module, "__all__", None) or [n for n in vars(module)
                                                     if not n.startswith("_")]
        for name in names:
            obj = getattr(module, name)
            if not inspect.isclass(obj) or not obj.__module__.startswith("drivekin"):
                continue                  # numpy, typing, ... imported by the module
            if obj.__module__ in LOG_TOOLS:
                continue
            found.setdefault(obj, f"drivekin.{m}.{name}")
    return found


PUBLIC = _public_classes()


def _id(e: catalog.Entry) -> str:
    return e.cls.__name__


# ---------------------------------------------------------------------------------------
# (a) coverage, (b) uniqueness

@pytest.mark.parametrize("cls", list(PUBLIC), ids=lambda c: c.__name__)
def test_every_public_class_has_an_entry(cls):
    assert cls in catalog.BY_CLASS, (
        f"{PUBLIC[cls]} ({cls.__module__}.{cls.__qualname__}) has no entry in "
        "drivekin._core.catalog.ENTRIES: add one (kind, drivetrain, example, ...)")


def test_discovery_sees_the_whole_public_api():
    # The parametrisation above is only as good as the discovery behind it.
    assert EXPECTED_MODULES <= set(_public_modules()), \
        sorted(EXPECTED_MODULES - set(_public_modules()))
    top = {getattr(drivekin, n) for n in drivekin.__all__ if inspect.isclass(getattr(drivekin, n))
           and not isinstance(getattr(drivekin, n), RobotpyClass)}
    assert top <= set(PUBLIC)
    assert len(top) >= 30


def test_every_entry_is_public():
    stale = [e.cls.__qualname__ for e in catalog.ENTRIES if e.cls not in PUBLIC]
    assert not stale, f"catalog entries for classes outside the public API: {stale}"


def test_no_class_is_registered_twice():
    seen: dict[type, int] = {}
    for e in catalog.ENTRIES:
        seen[e.cls] = seen.get(e.cls, 0) + 1
    twice = sorted(c.__name__ for c, n in seen.items() if n > 1)
    assert not twice, f"registered more than once: {twice}"
    assert all(catalog.BY_CLASS[e.cls] is e for e in catalog.ENTRIES)
    assert len(catalog.BY_CLASS) == len(catalog.ENTRIES)


@pytest.mark.parametrize("e", catalog.ENTRIES, ids=_id)
def test_entry_kind_and_drivetrain(e):
    assert e.kind in KINDS, f"{e.cls.__name__}: unknown kind {e.kind!r}"
    if e.kind in ("kinematics", "odometry", "estimator", "odometry3d", "estimator3d"):
        assert e.drivetrain, f"{e.cls.__name__}: a {e.kind} entry names its drivetrain"
    if e.kind in ("helper", "warning"):
        assert e.drivetrain is None
    assert (e.kind == "warning") == issubclass(e.cls, Warning)
    assert e.positions is None or e.kind == "odometry"
    assert not e.steered or (e.kind == "kinematics" and issubclass(e.cls, Drivetrain))
    assert (e.peer is None) != (e.no_peer is None) or e.kind not in ("value", "kinematics"), \
        f"{e.cls.__name__}: a value or kinematics entry has a peer or says why not"


def test_entries_selects_by_kind_and_drivetrain():
    assert catalog.entries() == catalog.ENTRIES
    for kind in KINDS:
        assert all(e.kind == kind for e in catalog.entries(kind))
    swerve = catalog.entries(drivetrain="swerve")
    assert {e.kind for e in swerve} == {"value", "kinematics", "odometry", "estimator",
                                        "odometry3d", "estimator3d"}
    assert [e.cls for e in catalog.entries("odometry", drivetrain="swerve")] == [
        drivekin.SwerveDriveOdometry]


# ---------------------------------------------------------------------------------------
# (c) the contracts

def _all_subclasses(base: type) -> set[type]:
    out: set[type] = set()
    todo = [base]
    while todo:
        for sub in todo.pop().__subclasses__():
            if sub not in out:
                out.add(sub)
                todo.append(sub)
    return out


CONTRACTS = {"kinematics": Drivetrain, "odometry": _Odometry, "estimator": _PoseEstimator,
             "odometry3d": _Odometry3d, "estimator3d": _PoseEstimator3d}


@pytest.mark.parametrize("e", catalog.ENTRIES, ids=_id)
def test_contract_membership_matches_kind(e):
    for kind, base in CONTRACTS.items():
        member = issubclass(e.cls, base)
        if kind == "kinematics" and e.cls in NOT_A_DRIVETRAIN:
            assert not member and e.kind == "kinematics", NOT_A_DRIVETRAIN[e.cls]
            continue
        assert member == (e.kind == kind), (
            f"{e.cls.__name__} (kind {e.kind!r}) "
            f"{'subclasses' if member else 'does not subclass'} {base.__qualname__}")


@pytest.mark.parametrize("kind", sorted(CONTRACTS))
def test_every_contract_class_is_catalogued(kind):
    base = CONTRACTS[kind]
    subclasses = {c for c in _all_subclasses(base) if not c.__name__.startswith("_")}
    missing = sorted(c.__name__ for c in subclasses if c not in catalog.BY_CLASS)
    assert not missing, f"{base.__qualname__} subclasses without a catalog entry: {missing}"
    assert subclasses == {e.cls for e in catalog.entries(kind)} - set(NOT_A_DRIVETRAIN)


def test_every_drivetrain_has_its_odometry_and_estimator():
    for e in catalog.entries("kinematics"):
        if e.cls in NOT_A_DRIVETRAIN:
            continue
        for kind in ("odometry", "estimator", "odometry3d", "estimator3d"):
            found = catalog.entries(kind, drivetrain=e.drivetrain)
            assert len(found) == 1, f"{e.drivetrain}: {kind} entries {found}"


def test_names_lists_the_contract_classes():
    drivetrains = [e.cls.__name__ for e in catalog.entries("kinematics")
                   if e.cls not in NOT_A_DRIVETRAIN]
    assert catalog.names("drivetrain") == ", ".join(drivetrains)
    assert catalog.names("odometry") == ", ".join(e.cls.__name__
                                                 for e in catalog.entries("odometry"))
    # Steered: the drivetrains whose wheels are swerve modules.
    steered = [e.cls for e in catalog.entries("kinematics")
               if e.cls not in NOT_A_DRIVETRAIN and hasattr(e.cls, "toSwerveModuleVelocities")]
    assert steered and [e.cls for e in catalog.entries("kinematics") if e.steered] == steered
    assert catalog.names("steered") == ", ".join(c.__name__ for c in steered)


# ---------------------------------------------------------------------------------------
# (d) wpistruct, protobuf, interop; (e) SerializableValue

def _with(field: str) -> set[type]:
    return {e.cls for e in catalog.ENTRIES if getattr(e, field) is not None}


def test_struct_types_are_the_struct_entries():
    assert wpistruct.STRUCT_TYPES == tuple(e.cls for e in catalog.ENTRIES if e.struct)
    assert set(wpistruct.STRUCT_TYPES) == _with("struct")


def test_protobuf_types_are_the_protobuf_entries():
    assert set(protobuf.PROTOBUF_TYPES) == _with("proto")
    assert len(protobuf.PROTOBUF_TYPES) == len(set(protobuf.PROTOBUF_TYPES))


def test_serializable_value_is_the_struct_and_protobuf_entries():
    members = set(typing.get_args(catalog.SerializableValue))
    assert members == _with("struct"), sorted(c.__name__ for c in members ^ _with("struct"))
    assert members == _with("proto"), sorted(c.__name__ for c in members ^ _with("proto"))


def _examples():
    return [pytest.param(e, id=_id(e)) for e in catalog.ENTRIES if e.example is not None]


def _accepts(fn, obj) -> bool:
    try:
        fn(obj)
    except TypeError:
        return False
    return True


@pytest.mark.parametrize("e", _examples())
def test_serializations_take_exactly_the_catalogued_values(e):
    x = e.example()
    assert _accepts(wpistruct.pack, x) == (e.struct is not None), e.cls.__name__
    assert _accepts(protobuf.pack, x) == (e.proto is not None), e.cls.__name__
    if e.struct is not None:
        n = e.struct.repeats(x) if e.struct.repeats else 1
        assert wpistruct.getSize(e.cls, **({"numModules": n} if e.struct.repeats else {})) \
            == 8 * e.struct.count * n
        assert len(wpistruct.pack(x)) == 8 * e.struct.count * n


@pytest.mark.parametrize("e", _examples())
def test_interop_converts_exactly_the_entries_with_a_peer(e):
    pytest.importorskip("wpimath")
    x = e.example()
    assert _accepts(interop.toWpimath, x) == (e.peer is not None), e.cls.__name__
    if e.peer is not None:
        w = interop.toWpimath(x)
        assert type(w).__name__ in e.peer.names
        assert type(interop.fromWpimath(w)) is e.cls
    else:
        with pytest.raises(TypeError) as info:
            interop.toWpimath(x)
        if e.no_peer is not None:
            assert e.no_peer.format(e.cls.__name__) in str(info.value)


def _overload_names(fn, key: str) -> set[str]:
    names = {o.__annotations__[key] for o in typing.get_overloads(fn)}
    names -= {"list[Any]", "tuple[Any, ...]", "object"}    # containers, and the fallback
    return {n.rpartition(".")[2] for n in names}          # wpk.ChassisSpeeds -> ChassisSpeeds


def test_interop_overloads_name_the_peers():
    peers = [e for e in catalog.ENTRIES if e.peer is not None]
    # fromWpimath: one overload per robotpy-wpimath class.
    assert _overload_names(interop.fromWpimath, "obj") == {n for e in peers
                                                          for n in e.peer.names}
    # toWpimath: one per drivekin class, except a class whose peer depends on the value
    # (swerve kinematics -> SwerveDrive<N>Kinematics), which takes `object -> Any`.
    assert _overload_names(interop.toWpimath, "obj") == {
        e.cls.__name__ for e in peers if len(e.peer.names) == 1}


# ---------------------------------------------------------------------------------------
# (f) examples, (g) wire forms

def test_every_entry_has_an_example_or_a_reason():
    for e in catalog.ENTRIES:
        assert (e.example is None) == (e.cls in NO_EXAMPLE), (
            f"{e.cls.__name__}: give its entry an example= (a typical valid instance)")
    for cls in NO_EXAMPLE:
        with pytest.raises(TypeError):
            cls()


@pytest.mark.parametrize("e", _examples())
def test_example_builds_a_fresh_instance_of_its_class(e):
    a, b = e.example(), e.example()
    assert type(a) is e.cls, f"{e.cls.__name__}.example() built a {type(a).__name__}"
    assert a is not b, f"{e.cls.__name__}.example() returns a shared instance"


def _bits(values) -> bytes:
    return struct.pack(f"<{len(values)}d", *values)


# Wire forms holding a Rotation3d's quaternion (its slice of the doubles), which ``build``
# renormalises through Rotation3d(Quaternion), as WPILib's unpack does: a component may
# move by a few ulps.
RENORMALISED = {Rotation3d: slice(0, 4), Pose3d: slice(3, 7), Transform3d: slice(3, 7)}


@pytest.mark.parametrize("e", [pytest.param(e, id=_id(e)) for e in catalog.ENTRIES
                               if e.flatten and e.build and e.example])
def test_wire_form_round_trips_the_example_bit_for_bit(e):
    x = e.example()
    flat = e.flatten(x)
    assert all(type(v) is float for v in flat), flat
    if e.struct is not None:
        n = e.struct.repeats(x) if e.struct.repeats else 1
        assert len(flat) == e.struct.count * n
    y = e.build(*flat)
    assert type(y) is e.cls
    again = e.flatten(y)
    q = RENORMALISED.get(e.cls, slice(0, 0))
    if q.stop:
        assert y == x
        assert all(abs(a - b) <= 4 * math.ulp(1.0) for a, b in zip(flat[q], again[q]))
    assert _bits(again[:q.start] + again[q.stop:]) == _bits(flat[:q.start] + flat[q.stop:]), \
        (flat, again)
    # Through the wire, too: wpistruct packs exactly these doubles.
    if e.struct is not None:
        assert wpistruct.pack(x) == _bits(flat)


def test_every_wire_form_has_both_halves():
    for e in catalog.ENTRIES:
        assert (e.flatten is None) == (e.build is None), e.cls.__name__
        assert (e.flatten is None) == (e.struct is None), e.cls.__name__


# ---------------------------------------------------------------------------------------
# The demo's simulated drivetrains (python -m drivekin): each is a hand-written wheel model
# of one catalogued drivetrain, localized by a catalogued odometry or estimator class.

def test_demo_drivetrains_are_catalogued():
    from drivekin.app.demo import DRIVETRAINS, VISION_DRIVETRAINS

    keys = {e.drivetrain for e in catalog.ENTRIES if e.drivetrain}
    for name, sim in [*DRIVETRAINS.items(), *VISION_DRIVETRAINS.items()]:
        assert sim.name == name and name in keys, f"demo drivetrain {name!r}: no catalog key"
        entry = catalog.BY_CLASS.get(sim.ODOMETRY)
        assert entry is not None and entry.kind in ("odometry", "estimator"), \
            f"demo drivetrain {name!r}: {sim.ODOMETRY!r} is not a catalogued odometry"
