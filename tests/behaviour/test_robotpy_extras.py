"""robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).

The names are those of the table tests/data/robotpy2027-names.json (robotpy/mostrobotpy
e51721a's wrapper YAML); their semantics are the YAML's ``inline_code`` and ``rename``:
feet are 0.3048 m exactly and degrees π/180 rad with the double π (the units library
robotpy converts with), so every conversion is checked against exact rational arithmetic
(two correctly rounded operations: within 2⁻⁵² relative) and, where robotpy-wpimath 2026
already has the name (``x_feet``, ``vx_fps``, ``fromFeet``, ``fromMatrix``...), against
its bits. ``from_matrix`` is checked against drivekin's matrix constructors and
robotpy-wpimath 2026's ``fromMatrix``, acceptance and messages included.
"""
from __future__ import annotations

import inspect
import json
import math
import struct
import types
from fractions import Fraction
from pathlib import Path
from typing import NamedTuple

import numpy as np
import pytest
from hypothesis import example, given, strategies as st

import drivekin
from drivekin._core import pynames
from drivekin import Pose2d, Rotation2d, Transform2d, Translation2d
from drivekin._core.robotpyextras import EXTRAS, install_extras

TABLE = json.loads((Path(__file__).parents[1] / "data" / "robotpy2027-names.json")
                   .read_text(encoding="utf-8"))["classes"]
# The classes of the table that drivekin has, by drivekin's name.
CLASSES = {c["drivekinName"]: c for c in TABLE.values()
           if c["drivekinName"] and hasattr(drivekin, c["drivekinName"])}

FT = Fraction(3048, 10000)           # m per ft, exactly
DEG = Fraction(math.pi) / 180        # rad per degree, with the double π of the units library
DBL_MAX = Fraction(1.7976931348623157e308)
finite = st.floats(allow_nan=False, allow_infinity=False)
# No overflow or subnormal on the way: for round trips.
normal = st.one_of(st.just(0.0), st.floats(1e-300, 1e300), st.floats(-1e300, -1e-300))


def bits(*xs: float) -> bytes:
    return struct.pack(f"<{len(xs)}d", *xs)


def close(got: float, exact: Fraction, roundings: int) -> bool:
    """``got`` is within what ``roundings`` correctly rounded operations allow of
    ``exact``: (1 + 2⁻⁵³)ⁿ − 1 relative, plus 2⁻¹⁰⁷⁵ each in the subnormal range."""
    u = Fraction(1, 2 ** 53)
    bound = ((1 + u) ** roundings - 1) * abs(exact) + roundings * u ** 2 * Fraction(1, 2 ** 969)
    return math.isfinite(got) and abs(Fraction(got) - exact) <= bound


def converts(call, exact: Fraction, roundings: int = 2) -> float | None:
    """Call ``call``: a finite result close to ``exact``, or ValueError where ``exact`` is
    beyond the largest double (never inf); either at the very edge. The result or None."""
    if abs(exact) > DBL_MAX * (1 + Fraction(1, 2 ** 50)):
        with pytest.raises(ValueError, match="largest double"):
            call()
        return None
    if abs(exact) < DBL_MAX * (1 - Fraction(1, 2 ** 50)):
        got = call()
        assert close(got, exact, roundings), (got, float(exact))
        return got
    return None


# ---------------------------------------------------------------------------------------
# The names

def test_every_robotpy_only_name_is_an_extra():
    expected = {}
    for name, c in CLASSES.items():
        names = set(c["robotpyOnly"])
        names |= {m for m, java in c["methods"].items() if java is None}
        names |= set(c["properties"]) - set(c["propertyJava"])
        # from_feet: drivekin's fromFeet (robotpy 2026's name), spelled by the rule.
        names -= set(pynames.spellings(getattr(drivekin, name)))
        if names:
            expected[name] = names
    assert set(expected) >= {"Rotation2d", "Translation2d", "ChassisVelocities",
                             "SwerveModulePosition", "DifferentialDriveWheelAccelerations",
                             "Rotation3d", "Translation3d", "Pose3d", "Transform3d", "Twist3d"}
    missing = sorted(f"{c}.{n}" for c, names in expected.items()
                     for n in names - set(EXTRAS.get(c, ())))
    assert not missing, f"robotpy 2027 names missing from EXTRAS: {missing}"
    unknown = sorted(f"{c}.{n}" for c, members in EXTRAS.items()
                     for n in set(members) - expected.get(c, set()))
    assert not unknown, f"EXTRAS names robotpy 2027 does not have: {unknown}"


@pytest.mark.parametrize("cls_name", sorted(EXTRAS))
def test_kinds_are_robotpys(cls_name):
    """Static factories, read-only or assignable properties, methods: as the table says."""
    cls, entry = getattr(drivekin, cls_name), CLASSES[cls_name]
    for name in EXTRAS[cls_name]:
        raw = vars(cls)[name]
        assert raw is EXTRAS[cls_name][name], name
        if name in entry["static"]:
            assert isinstance(raw, staticmethod), name
        elif name in entry["properties"]:
            assert isinstance(raw, property), name
            assert (raw.fset is None) == (name in entry["readonlyProperties"]), name
            assert raw.__doc__ and raw.fdel is None
        else:
            assert inspect.isfunction(raw), name
        assert getattr(cls, name).__doc__, name


def test_install_is_idempotent():
    before = {c: dict(vars(getattr(drivekin, c))) for c in EXTRAS}
    install_extras(vars(drivekin))
    assert {c: dict(vars(getattr(drivekin, c))) for c in EXTRAS} == before


@pytest.mark.parametrize("taken", ["own", "inherited"])
def test_install_refuses_a_taken_name_and_installs_nothing(taken):
    fake = {c: type(c, (), {}) for c in EXTRAS}
    if taken == "own":
        fake["Twist2d"] = type("Twist2d", (), {"dx_feet": 1.0})
    else:
        fake["Pose2d"] = type("Pose2d", (type("Base", (), {"x_feet": 1.0}),), {})
    with pytest.raises(RuntimeError, match="dx_feet|x_feet"):
        install_extras(fake)
    assert not [(c, n) for c, k in fake.items() for n, v in EXTRAS[c].items()
                if vars(k).get(n) is v]
    assert (fake["Twist2d"].dx_feet if taken == "own" else fake["Pose2d"].x_feet) == 1.0


# robotpy 2027's parameters (the YAML's py::arg, with their defaults) of the factories and
# methods that have one form; REQUIRED: no default.
REQUIRED = object()
SIGNATURES = {
    ("Rotation2d", "from_matrix"): [("rotation_matrix", REQUIRED)],
    ("Pose2d", "from_matrix"): [("matrix", REQUIRED)],
    ("Transform2d", "from_matrix"): [("matrix", REQUIRED)],
    ("ChassisAccelerations", "from_fps"): [("ax", 0), ("ay", 0), ("alpha", 0)],
    # angle=Rotation2d() in robotpy; drivekin's constructors spell that default None.
    ("SwerveModuleAcceleration", "from_fps"): [("acceleration", 0), ("angle", None)],
    ("MecanumDriveWheelAccelerations", "from_fps"): [
        ("front_left", 0), ("front_right", 0), ("rear_left", 0), ("rear_right", 0)],
    ("DifferentialDriveWheelAccelerations", "from_fps"): [("left", REQUIRED),
                                                           ("right", REQUIRED)],
    # A lambda without py::arg: robotpy names no parameter.
    ("Translation2d", "distance_feet"): [("self", REQUIRED), ("other", REQUIRED)],
    ("Translation2d", "norm_feet"): [("self", REQUIRED)],
    ("Pose3d", "from_matrix"): [("matrix", REQUIRED)],
    ("Transform3d", "from_matrix"): [("matrix", REQUIRED)],
    ("Translation3d", "distance_feet"): [("self", REQUIRED), ("other", REQUIRED)],
    ("Translation3d", "norm_feet"): [("self", REQUIRED)],
}


def test_every_callable_extra_has_robotpys_signature_here():
    callables = {(c, n) for c, members in EXTRAS.items() for n, v in members.items()
                 if not isinstance(v, property)}
    assert callables == set(SIGNATURES)


@pytest.mark.parametrize("where", sorted(SIGNATURES), ids="{0[0]}.{0[1]}".format)
def test_parameters_are_robotpys(where):
    params = inspect.signature(getattr(getattr(drivekin, where[0]), where[1])).parameters
    got = [(p.name, REQUIRED if p.default is p.empty else p.default) for p in params.values()]
    assert got == SIGNATURES[where]
    if where[1] == "distance_feet":
        assert params["other"].kind is inspect.Parameter.POSITIONAL_ONLY


# ---------------------------------------------------------------------------------------
# The properties

class Prop(NamedTuple):
    cls: str
    name: str
    field: str                         # the SI field it reads and assigns
    unit: Fraction                     # its unit in the SI unit
    peer: tuple[str, str] | None       # robotpy-wpimath 2026: (name, SI field)


ROT = "<rotation>"
# Constructor fields in order, the same in drivekin and robotpy-wpimath 2026.
FIELDS = {
    "Translation2d": ("x", "y"), "Pose2d": ("x", "y", ROT), "Transform2d": ("x", "y", ROT),
    "Twist2d": ("dx", "dy", "dtheta"), "ChassisVelocities": ("vx", "vy", "omega"),
    "ChassisAccelerations": ("ax", "ay", "alpha"),
    "SwerveModuleVelocity": ("velocity", ROT), "SwerveModulePosition": ("distance", ROT),
    "SwerveModuleAcceleration": ("acceleration", ROT),
    "MecanumDriveWheelVelocities": ("frontLeft", "frontRight", "rearLeft", "rearRight"),
    "MecanumDriveWheelAccelerations": ("frontLeft", "frontRight", "rearLeft", "rearRight"),
    "DifferentialDriveWheelVelocities": ("left", "right"),
    "DifferentialDriveWheelAccelerations": ("left", "right"),
    "Translation3d": ("x", "y", "z"), "Pose3d": ("x", "y", "z", ROT),
    "Transform3d": ("x", "y", "z", ROT), "Twist3d": ("dx", "dy", "dz", "rx", "ry", "rz"),
}
PEER_CLASS = {"ChassisVelocities": "ChassisSpeeds", "SwerveModuleVelocity": "SwerveModuleState",
              "MecanumDriveWheelVelocities": "MecanumDriveWheelSpeeds",
              "DifferentialDriveWheelVelocities": "DifferentialDriveWheelSpeeds"}
_WHEELS = [("front_left", "frontLeft"), ("front_right", "frontRight"),
           ("rear_left", "rearLeft"), ("rear_right", "rearRight")]
# From the YAML: what each property reads, in which unit.
PROPERTIES = [
    *(Prop(c, f"{a}_feet", a, FT, (f"{a}_feet", a))
      for c in ("Translation2d", "Pose2d", "Transform2d") for a in ("x", "y")),
    *(Prop(c, f"{a}_feet", a, FT, (f"{a}_feet", a))
      for c in ("Translation3d", "Pose3d", "Transform3d") for a in ("x", "y", "z")),
    *(Prop("Twist3d", f"{a}_feet", a, FT, (f"{a}_feet", a)) for a in ("dx", "dy", "dz")),
    *(Prop("Twist3d", f"{a}_degrees", a, DEG, (f"{a}_degrees", a)) for a in ("rx", "ry", "rz")),
    Prop("Twist2d", "dx_feet", "dx", FT, ("dx_feet", "dx")),
    Prop("Twist2d", "dy_feet", "dy", FT, ("dy_feet", "dy")),
    Prop("Twist2d", "dtheta_degrees", "dtheta", DEG, ("dtheta_degrees", "dtheta")),
    Prop("ChassisVelocities", "vx_fps", "vx", FT, ("vx_fps", "vx")),
    Prop("ChassisVelocities", "vy_fps", "vy", FT, ("vy_fps", "vy")),
    Prop("ChassisVelocities", "omega_dps", "omega", DEG, ("omega_dps", "omega")),
    Prop("ChassisAccelerations", "ax_fpss", "ax", FT, None),
    Prop("ChassisAccelerations", "ay_fpss", "ay", FT, None),
    Prop("ChassisAccelerations", "alpha_dpss", "alpha", DEG, None),
    Prop("SwerveModuleVelocity", "velocity_fps", "velocity", FT, ("speed_fps", "speed")),
    Prop("SwerveModulePosition", "distance_ft", "distance", FT, ("distance_ft", "distance")),
    Prop("SwerveModuleAcceleration", "acceleration_fpss", "acceleration", FT, None),
    *(Prop("MecanumDriveWheelVelocities", f"{w}_fps", f, FT, (f"{f}_fps", f))
      for w, f in _WHEELS),
    *(Prop("MecanumDriveWheelAccelerations", f"{w}_fpss", f, FT, None) for w, f in _WHEELS),
    *(Prop("DifferentialDriveWheelVelocities", f"{s}_fps", s, FT, (f"{s}_fps", s))
      for s in ("left", "right")),
    *(Prop("DifferentialDriveWheelAccelerations", f"{s}_fpss", s, FT, None)
      for s in ("left", "right")),
]
WRITABLE = [p for p in PROPERTIES if p.name not in CLASSES[p.cls]["readonlyProperties"]]
READONLY = [p for p in PROPERTIES if p not in WRITABLE]
prop_id = "{0.cls}.{0.name}".format


# Rotation3d's angles in degrees read computed values (Euler angles, the rotation angle):
# checked on their own below.
ROTATION3D = ("x_degrees", "y_degrees", "z_degrees", "angle_degrees")


def test_every_property_is_described_here():
    assert {(p.cls, p.name) for p in PROPERTIES} | {("Rotation3d", n) for n in ROTATION3D} \
        == {(c, n) for c, members in EXTRAS.items() for n, v in members.items()
            if isinstance(v, property)}
    assert {(p.cls, p.name) for p in READONLY} == {
        (c, n) for c in ("Translation2d", "Pose2d", "Transform2d") for n in ("x_feet", "y_feet")
    } | {(c, f"{a}_feet") for c in ("Translation3d", "Pose3d", "Transform3d") for a in "xyz"}


def build(ns, rotation, cls: str, field: str, value: float):
    """An instance of ``cls`` from ``ns`` (drivekin, or robotpy-wpimath 2026 with its own
    class name) with ``field`` = ``value`` and distinct values elsewhere."""
    rot = ns.Rotation3d(0.1, 0.2, 0.3) if cls.endswith("3d") else rotation(0.1)
    args = [rot if f == ROT else value if f == field else 0.25 * (i + 1)
            for i, f in enumerate(FIELDS[cls])]
    return getattr(ns, PEER_CLASS.get(cls, cls) if ns is not drivekin else cls)(*args)


def si_fields(obj, cls: str) -> tuple[float, ...]:
    return tuple(getattr(obj, f) for f in FIELDS[cls] if f != ROT)


def state(obj, cls: str) -> bytes:
    """The bits of every field of ``obj``, its rotation's cos and sin included."""
    rot = rotation_of(obj) if ROT in FIELDS[cls] else None
    if cls.endswith("3d") and rot is not None:
        q = rot.getQuaternion()
        return bits(*si_fields(obj, cls), q.getW(), q.getX(), q.getY(), q.getZ())
    return bits(*si_fields(obj, cls), *((rot.getCos(), rot.getSin()) if rot else ()))


def rotation_of(obj):
    return obj.getRotation() if hasattr(obj, "getRotation") else obj.angle


@pytest.fixture(scope="module")
def robotpy():
    """robotpy-wpimath 2026's geometry and kinematics classes in one namespace."""
    g = pytest.importorskip("wpimath.geometry")
    k = pytest.importorskip("wpimath.kinematics")
    return _Robotpy(**{n: v for m in (g, k) for n, v in vars(m).items()
                       if not n.startswith("_")})


class _Robotpy(types.SimpleNamespace):
    def __repr__(self):                 # hypothesis prints the fixture with a failure
        return "<robotpy-wpimath 2026>"


# Where the units library's order of operations overflows although the result is finite
# (1e306 m in ft, 1.5e308 ft in m), where the result is beyond a double (1.79e308 m in
# ft), subnormals, signed zeros and ordinary values.
VALUES = [0.0, -0.0, 1.0, -2.5, 0.1, 123.456, -1e-310, 5e-324, 1e306, -1.5e308,
          1.7976931348623157e308, 1e300]


def check_read(robotpy, p: Prop, value: float) -> None:
    obj = build(drivekin, Rotation2d, p.cls, p.field, value)
    got = converts(lambda: getattr(obj, p.name), Fraction(value) / p.unit)
    if p.peer is not None and got is not None:
        theirs = getattr(build(robotpy, robotpy.Rotation2d, p.cls, p.field, value), p.peer[0])
        if math.isfinite(theirs):       # robotpy's value * 1250 may overflow first
            assert bits(got) == bits(theirs)


def check_assign(robotpy, p: Prop, value: float) -> None:
    obj = build(drivekin, Rotation2d, p.cls, p.field, 0.5)
    others = [(f, v) for f, v in zip(FIELDS[p.cls], si_fields(obj, p.cls)) if f != p.field]
    setattr(obj, p.name, value)
    got = getattr(obj, p.field)
    assert close(got, Fraction(value) * p.unit, 2), (got, value)
    assert [(f, getattr(obj, f)) for f, _ in others] == others
    if p.peer is not None:
        theirs = build(robotpy, robotpy.Rotation2d, p.cls, p.field, 0.5)
        setattr(theirs, p.peer[0], value)
        if math.isfinite(getattr(theirs, p.peer[1])):
            assert bits(got) == bits(getattr(theirs, p.peer[1]))
    if value == 0.0 or 1e-300 <= abs(value) <= 1e300:   # no overflow nor subnormal between
        assert close(getattr(obj, p.name), Fraction(value), 4)


@pytest.mark.parametrize("p", PROPERTIES, ids=prop_id)
def test_a_property_reads_and_assigns_its_field_in_its_unit(robotpy, p):
    for value in VALUES:
        check_read(robotpy, p, value)
        if p in WRITABLE:
            check_assign(robotpy, p, value)


# The conversions are one code path for every property: generated values go through one
# property per unit.
@pytest.mark.parametrize("p", [p for p in PROPERTIES if p.cls == "Twist2d" and p.name != "dy_feet"],
                         ids=prop_id)
@given(value=finite)
def test_conversions_on_generated_values(robotpy, p, value):
    check_read(robotpy, p, value)
    check_assign(robotpy, p, value)


@pytest.mark.parametrize("p", READONLY, ids=prop_id)
def test_positions_in_feet_are_read_only(p):
    obj = build(drivekin, Rotation2d, p.cls, p.field, 0.5)
    with pytest.raises(AttributeError, match=p.name):
        setattr(obj, p.name, 1.0)
    assert getattr(obj, p.field) == 0.5


@pytest.mark.parametrize("p", WRITABLE, ids=prop_id)
@pytest.mark.parametrize("bad, error", [("1.0", TypeError), (None, TypeError), (1j, TypeError),
                                        (Translation2d(), TypeError), (10 ** 400, ValueError)])
def test_a_bad_assignment_changes_nothing(p, bad, error):
    obj = build(drivekin, Rotation2d, p.cls, p.field, 0.5)
    before = state(obj, p.cls)
    with pytest.raises(error, match=rf"{p.cls}\.{p.name}"):
        setattr(obj, p.name, bad)
    assert state(obj, p.cls) == before


def test_examples():
    assert Translation2d(0.3048, -0.6096).x_feet == 1.0
    assert Translation2d(0.3048, -0.6096).y_feet == -2.0
    v = drivekin.ChassisVelocities(omega=math.radians(90.0))
    assert v.omega_dps == 90.0
    v.omega_dps = 180.0
    assert v.omega == math.pi
    tw = drivekin.Twist2d()
    tw.dtheta_degrees = -90.0
    assert tw.dtheta == -math.pi / 2
    m = drivekin.MecanumDriveWheelVelocities(0.3048, 0.6096, 0.9144, 1.2192)
    assert (m.front_left_fps, m.front_right_fps, m.rear_left_fps, m.rear_right_fps) == \
        (1.0, 2.0, 3.0, 4.0)
    p = drivekin.SwerveModulePosition(1.0, Rotation2d(0.5))
    p.distance_ft = 10.0
    assert p.distance == 3.048 and p.angle == Rotation2d(0.5)


def test_non_finite_values_stay_non_finite():
    t = Translation2d(math.inf, math.nan)
    assert t.x_feet == math.inf and math.isnan(t.y_feet)
    v = drivekin.ChassisVelocities.from_feet(-math.inf, math.nan, math.inf)
    assert v.vx == -math.inf and math.isnan(v.vy) and v.omega == math.inf


# ---------------------------------------------------------------------------------------
# Translation2d's methods

@given(x=finite, y=finite)
@example(x=1e306, y=0.0)
def test_norm_and_distance_in_feet(robotpy, x, y):
    t = Translation2d(x, y)
    origin = Translation2d(0.0, 0.0)
    if math.isinf(t.getNorm()):         # beyond a double in metres already
        assert t.norm_feet() == t.distance_feet(origin) == math.inf
        return
    # Each is the method in metres, converted: two more roundings.
    norm = converts(t.norm_feet, Fraction(t.getNorm()) / FT)
    assert converts(lambda: t.distance_feet(origin), Fraction(t.getDistance(origin)) / FT) \
        == norm
    theirs = robotpy.Translation2d(x, y)
    if norm is not None and bits(theirs.norm()) == bits(t.getNorm()) \
            and math.isfinite(theirs.normFeet()):
        assert bits(norm) == bits(theirs.normFeet())
    with pytest.raises(TypeError, match="other must be a Translation2d"):
        t.distance_feet(robotpy.Translation2d(x, y))
    with pytest.raises(TypeError):
        t.distance_feet(other=origin)   # robotpy names no parameter


# ---------------------------------------------------------------------------------------
# The factories

class Factory(NamedTuple):
    cls: str
    name: str
    args: tuple[str, ...]              # "ft" (to SI), "rad" (as given), ROT (a Rotation2d)
    peer: str | None                   # robotpy-wpimath 2026's fromFeet of the same class


FACTORIES = [
    Factory("ChassisAccelerations", "from_fps", ("ft", "ft", "rad"), None),
    Factory("SwerveModuleAcceleration", "from_fps", ("ft", ROT), None),
    Factory("MecanumDriveWheelAccelerations", "from_fps", ("ft",) * 4, None),
    Factory("DifferentialDriveWheelAccelerations", "from_fps", ("ft", "ft"), None),
]
factory_id = "{0.cls}.{0.name}".format


def test_every_factory_is_described_here():
    assert {(f.cls, f.name) for f in FACTORIES} == {
        (c, n) for c, members in EXTRAS.items() for n in members if n.startswith("from_f")}


def check_factory(robotpy, f: Factory, values: list[float]) -> None:
    args = [Rotation2d(v) if kind == ROT else v for kind, v in zip(f.args, values)]
    obj = getattr(getattr(drivekin, f.cls), f.name)(*args)
    assert type(obj) is getattr(drivekin, f.cls)
    for field, kind, arg in zip(FIELDS[f.cls], f.args, args):
        if kind == "ft":
            assert close(getattr(obj, field), Fraction(arg) * FT, 2), (field, arg)
        elif field == ROT:   # radians, or a Rotation2d, through drivekin's Rotation2d
            want = arg if kind == ROT else Rotation2d(arg)
            assert bits(rotation_of(obj).getCos(), rotation_of(obj).getSin()) == \
                bits(want.getCos(), want.getSin())
        else:
            assert bits(getattr(obj, field)) == bits(arg)
    if f.peer is not None:
        theirs = getattr(getattr(robotpy, PEER_CLASS.get(f.cls, f.cls)), f.peer)(*args)
        fields = [fd for fd, kind in zip(FIELDS[f.cls], f.args) if kind == "ft"]
        ours, want = [getattr(obj, fd) for fd in fields], [getattr(theirs, fd) for fd in fields]
        if all(math.isfinite(w) for w in want):   # robotpy's ft * 381 may overflow first
            assert bits(*ours) == bits(*want)


@pytest.mark.parametrize("f", FACTORIES, ids=factory_id)
def test_a_factory_converts_its_arguments(robotpy, f):
    for i in range(len(VALUES)):
        check_factory(robotpy, f, (VALUES[i:] + VALUES[:i])[:4])


# One code path converts every factory's arguments: generated values go through the
# factories with a rotation argument (radians or a Rotation2d) and one without.
@pytest.mark.parametrize("f", [f for f in FACTORIES if f.cls in (
    "Pose2d", "SwerveModuleAcceleration", "ChassisVelocities")], ids=factory_id)
@given(values=st.lists(finite, min_size=4, max_size=4))
def test_factories_on_generated_values(robotpy, f, values):
    check_factory(robotpy, f, values)


@pytest.mark.parametrize("f", FACTORIES, ids=factory_id)
def test_keywords_are_robotpys(f):
    """All arguments by keyword give the same object as by position."""
    factory = getattr(getattr(drivekin, f.cls), f.name)
    names = [n for n, _ in SIGNATURES[(f.cls, f.name)]]
    args = [Rotation2d(0.75) if kind == ROT else 1.5 + i for i, kind in enumerate(f.args)]
    by_name = factory(**dict(zip(names, args)))
    assert state(by_name, f.cls) == state(factory(*args), f.cls)


def test_defaults():
    a = drivekin.SwerveModuleAcceleration.from_fps(10.0)
    assert a.angle == Rotation2d() and a.acceleration == 3.048
    z = drivekin.ChassisAccelerations.from_fps()
    assert state(z, "ChassisAccelerations") == bits(0.0, 0.0, 0.0)


@pytest.mark.parametrize("call, error, match", [
    (lambda: drivekin.ChassisAccelerations.from_fps(10 ** 400), ValueError, "largest double"),
    (lambda: drivekin.SwerveModuleAcceleration.from_fps(1.0, "x"), TypeError, "angle"),
    (lambda: drivekin.DifferentialDriveWheelAccelerations.from_fps(1.0, b"2"), TypeError,
     "right in ft/s²"),

])
def test_bad_arguments(call, error, match):
    with pytest.raises(error, match=match):
        call()


# ---------------------------------------------------------------------------------------
# from_matrix

@given(angle=finite, x=finite, y=finite)
@example(angle=math.pi, x=-0.0, y=5e-324)
def test_from_matrix_is_the_matrix_constructor(robotpy, angle, x, y):
    r = Rotation2d(angle)
    m = r.toMatrix()
    java = Rotation2d(m)                # the Java-named matrix constructor
    assert bits(java.getCos(), java.getSin()) == bits(m[0, 0], m[1, 0])
    for ours in (Rotation2d.from_matrix(m), Rotation2d.from_matrix(rotation_matrix=m)):
        assert bits(ours.getCos(), ours.getSin()) == bits(m[0, 0], m[1, 0])
        assert bits(ours.getCos(), ours.getSin()) == bits(r.getCos(), r.getSin())
    theirs = robotpy.Rotation2d.fromMatrix(m)
    assert bits(theirs.cos(), theirs.sin()) == bits(m[0, 0], m[1, 0])
    for cls, peer in ((Pose2d, robotpy.Pose2d), (Transform2d, robotpy.Transform2d)):
        frame = cls(x, y, r)
        h = frame.toMatrix()
        for ours in (cls.from_matrix(h), cls.from_matrix(matrix=h)):
            assert type(ours) is cls
            assert bits(ours.x, ours.y, ours.getRotation().getCos(), ours.getRotation().getSin()) \
                == bits(frame.x, frame.y, r.getCos(), r.getSin())
        theirs = peer.fromMatrix(h)
        assert bits(theirs.x, theirs.y, theirs.rotation().cos(), theirs.rotation().sin()) == \
            bits(frame.x, frame.y, r.getCos(), r.getSin())


def _rot(a, scale=1.0):
    c, s = math.cos(a) * scale, math.sin(a) * scale
    return [[c, -s], [s, c]]


def _affine(block, last=(0.0, 0.0, 1.0)):
    return [block[0] + [1.5], block[1] + [-2.5], list(last)]


ROTATION_MATRICES = {
    "rotation": _rot(0.3), "within 1e-9": _rot(0.3, 1 + 2e-10),
    "not orthogonal": _rot(0.3, 1 + 1e-8), "shear": [[1.0, 1.0], [0.0, 1.0]],
    "reflection": [[1.0, 0.0], [0.0, -1.0]], "zero": [[0.0, 0.0], [0.0, 0.0]],
}
AFFINE_MATRICES = {
    "affine": _affine(_rot(2.0)), "last row 2": _affine(_rot(2.0), (0.0, 0.0, 2.0)),
    "last row tiny": _affine(_rot(2.0), (5e-324, 0.0, 1.0)),
    "last row -0": _affine(_rot(2.0), (-0.0, 0.0, 1.0)),
    "bad block": _affine([[1.0, 1.0], [0.0, 1.0]]),
    "reflection": _affine([[1.0, 0.0], [0.0, -1.0]]),
}


def _agree(ours_call, theirs_call, read_ours, read_theirs):
    """Both give the same values, or both raise ValueError and ours starts with
    robotpy's message."""
    try:
        theirs = read_theirs(theirs_call())
    except ValueError as e:
        with pytest.raises(ValueError) as ours_error:
            ours_call()
        assert str(ours_error.value).startswith(str(e)), (str(ours_error.value), str(e))
        return
    assert bits(*read_ours(ours_call())) == bits(*theirs)


@pytest.mark.parametrize("name", sorted(ROTATION_MATRICES))
def test_rotation_from_matrix_accepts_what_robotpy_accepts(robotpy, name):
    m = np.array(ROTATION_MATRICES[name])
    _agree(lambda: Rotation2d.from_matrix(m), lambda: robotpy.Rotation2d.fromMatrix(m),
           lambda r: (r.getCos(), r.getSin()), lambda r: (r.cos(), r.sin()))


@pytest.mark.parametrize("cls", ["Pose2d", "Transform2d"])
@pytest.mark.parametrize("name", sorted(AFFINE_MATRICES))
def test_affine_from_matrix_accepts_what_robotpy_accepts(robotpy, cls, name):
    m = np.array(AFFINE_MATRICES[name])
    _agree(lambda: getattr(drivekin, cls).from_matrix(m),
           lambda: getattr(robotpy, cls).fromMatrix(m),
           lambda p: (p.x, p.y, p.getRotation().getCos(), p.getRotation().getSin()),
           lambda p: (p.x, p.y, p.rotation().cos(), p.rotation().sin()))


@pytest.mark.parametrize("cls, shape", [("Rotation2d", (2, 2)), ("Pose2d", (3, 3)),
                                        ("Transform2d", (3, 3))])
@pytest.mark.parametrize("bad, error, match", [
    (0.5, TypeError, "numpy array, got float"),   # never the angle constructor
    (None, TypeError, "got NoneType"),
    ("eye", TypeError, "got str"),
    ("list", TypeError, r"got list \(numpy.asarray"),
    ("int64", TypeError, "float64"),
    ("shape", ValueError, "shape"),
])
def test_from_matrix_bad_input(cls, shape, bad, error, match):
    eye = np.eye(shape[0])
    bad = {"eye": "eye", "list": eye.tolist(), "int64": eye.astype(np.int64),
           "shape": np.eye(5 - shape[0])}.get(bad, bad)
    with pytest.raises(error, match=match):
        getattr(drivekin, cls).from_matrix(bad)


# ---------------------------------------------------------------------------------------
# The 3-D classes' own extras

@pytest.mark.parametrize("name", ROTATION3D)
@pytest.mark.parametrize("rpy", [(0.1, -0.2, 0.3), (-3.0, 1.2, 2.9), (0.0, math.pi / 2, 0.5),
                                 (1e-300, 0.0, -5e-324)])
def test_rotation3d_angles_in_degrees(robotpy, name, rpy):
    """x/y/z/angle in degrees: the radian readout converted (two roundings), robotpy 2026's
    bits where its readout in radians has drivekin's bits."""
    r = drivekin.Rotation3d(*rpy)
    field = name.removesuffix("_degrees")
    rad = getattr(r, field)
    assert close(getattr(r, name), Fraction(rad) / DEG, 2)
    theirs = robotpy.Rotation3d(*rpy)
    if bits(getattr(theirs, field)) == bits(rad):
        assert bits(getattr(r, name)) == bits(getattr(theirs, name))
    with pytest.raises(AttributeError, match=name):
        setattr(r, name, 1.0)


@given(x=finite, y=finite, z=finite)
@example(x=1e306, y=0.0, z=0.0)
def test_norm_and_distance_in_feet_3d(robotpy, x, y, z):
    t = drivekin.Translation3d(x, y, z)
    origin = drivekin.Translation3d()
    if math.isinf(t.getNorm()):
        assert t.norm_feet() == t.distance_feet(origin) == math.inf
        return
    norm = converts(t.norm_feet, Fraction(t.getNorm()) / FT)
    assert converts(lambda: t.distance_feet(origin), Fraction(t.getDistance(origin)) / FT) \
        == norm
    theirs = robotpy.Translation3d(x, y, z)
    if norm is not None and bits(theirs.norm()) == bits(t.getNorm()) \
            and math.isfinite(theirs.normFeet()):
        assert bits(norm) == bits(theirs.normFeet())


@pytest.mark.parametrize("cls", ["Pose3d", "Transform3d"])
def test_from_matrix_3d_is_the_matrix_constructor(robotpy, cls):
    rot = drivekin.Rotation3d(0.3, -0.4, 1.1)
    m = np.eye(4)
    m[:3, :3] = rot.toMatrix()
    m[:3, 3] = (1.5, -2.0, 0.25)
    got = getattr(drivekin, cls).from_matrix(m)
    assert type(got) is getattr(drivekin, cls) and got == getattr(drivekin, cls)(m)
    theirs = getattr(robotpy, cls).fromMatrix(m)
    assert abs(got.x - theirs.x) < 1e-15 and abs(got.z - theirs.z) < 1e-15
    with pytest.raises(TypeError, match=f"{cls}.from_matrix"):
        getattr(drivekin, cls).from_matrix(m.tolist())
    bad = m.copy()
    bad[3, 0] = 1e-3
    with pytest.raises(ValueError):
        getattr(drivekin, cls).from_matrix(bad)
