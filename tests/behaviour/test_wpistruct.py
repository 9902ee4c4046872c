"""drivekin.wpistruct: WPILib packed-struct serialization (2027 type names).

Reference: /work/shared/reference/wpilib-kinematics.md §11 (layout, type names, sizes,
schemas, Rotation2d packed as the wrapped getRadians()). The expected layouts below are
written out independently of the module (field extractors + ``struct.pack('<…d')``).

The robotpy cross-checks use robotpy-wpimath 2026.2.2, which has struct support for the
geometry types, ChassisSpeeds, SwerveModuleState, SwerveModulePosition,
MecanumDriveWheelSpeeds, DifferentialDriveWheelSpeeds, DifferentialDriveKinematics and
MecanumDriveKinematics (2026 names; no wheel positions, accelerations or
SwerveDriveKinematics). 2026 packs a Rotation2d's *constructor* value, unwrapped, while
2027 (and drivekin) packs the wrapped atan2 value; so the robotpy side is always built
from drivekin's wrapped angle (``Rotation2d(θ).getRadians()``, in [−π, π], where both
versions store the same double). ``test_rotation_outside_pi_differs_from_2026`` pins
the one real difference.
"""
from __future__ import annotations

import doctest
import math
import struct
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import drivekin
from drivekin import wpistruct
from drivekin._core.pynames import RobotpyClass
from drivekin.differential import (
    DifferentialDriveKinematics,
    DifferentialDriveWheelAccelerations,
    DifferentialDriveWheelPositions,
    DifferentialDriveWheelVelocities,
)
from drivekin.geometry import Pose2d, Rotation2d, Transform2d, Translation2d, Twist2d
from drivekin.kinematics import (
    ChassisAccelerations,
    ChassisVelocities,
    SwerveDriveKinematics,
    SwerveModuleAcceleration,
    SwerveModulePosition,
    SwerveModuleVelocity,
)
from drivekin.mecanum import (
    MecanumDriveKinematics,
    MecanumDriveWheelAccelerations,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
)

PI = math.pi
MECANUM_WHEELS = "double front_left;double front_right;double rear_left;double rear_right"


def rad(r: Rotation2d) -> float:
    return r.getRadians()


def wire(values) -> bytes:
    """Little-endian doubles, no padding: the whole layout of every type here."""
    return struct.pack("<%dd" % len(values), *values)


# ---------------------------------------------------------------------------------------
# The §11 table, with independent constructors and field extractors


@dataclass(frozen=True)
class Case:
    cls: type
    name: str
    schema: str
    size: int
    make: Callable[..., Any]                       # raw floats -> drivekin object
    fields: Callable[[Any], tuple[float, ...]]     # object -> wire values (rotations wrapped)
    rot: tuple[int, ...] = ()                      # raw/wire indices holding a Rotation2d
    nested: tuple[type, ...] = ()
    finite: bool = False                           # constructor needs finite values
    positive: tuple[int, ...] = ()                 # indices that must be > 0
    extra: dict = field(default_factory=dict)

    @property
    def nraw(self) -> int:
        return self.size // 8


def _mk_diffkin(tw):
    return DifferentialDriveKinematics(tw)


def _mk_meckin(*v):
    return MecanumDriveKinematics(*(Translation2d(v[i], v[i + 1]) for i in range(0, 8, 2)))


def _meckin_fields(k):
    out = []
    for t in (k.getFrontLeft(), k.getFrontRight(), k.getRearLeft(), k.getRearRight()):
        out += [t.getX(), t.getY()]
    return tuple(out)


CASES = [
    Case(Translation2d, "Translation2d", "double x;double y", 16,
         Translation2d, lambda t: (t.getX(), t.getY())),
    Case(Rotation2d, "Rotation2d", "double value", 8,
         Rotation2d, lambda r: (r.getRadians(),), rot=(0,)),
    Case(Pose2d, "Pose2d", "Translation2d translation;Rotation2d rotation", 24,
         lambda x, y, t: Pose2d(Translation2d(x, y), Rotation2d(t)),
         lambda p: (p.getTranslation().getX(), p.getTranslation().getY(),
                    rad(p.getRotation())),
         rot=(2,), nested=(Translation2d, Rotation2d)),
    Case(Transform2d, "Transform2d", "Translation2d translation;Rotation2d rotation", 24,
         lambda x, y, t: Transform2d(Translation2d(x, y), Rotation2d(t)),
         lambda p: (p.getTranslation().getX(), p.getTranslation().getY(),
                    rad(p.getRotation())),
         rot=(2,), nested=(Translation2d, Rotation2d)),
    Case(Twist2d, "Twist2d", "double dx;double dy;double dtheta", 24,
         Twist2d, lambda t: (t.dx, t.dy, t.dtheta)),
    Case(ChassisVelocities, "ChassisVelocities", "double vx;double vy;double omega", 24,
         ChassisVelocities, lambda c: (c.vx, c.vy, c.omega)),
    Case(ChassisAccelerations, "ChassisAccelerations", "double ax;double ay;double alpha",
         24, ChassisAccelerations, lambda c: (c.ax, c.ay, c.alpha)),
    Case(SwerveModuleVelocity, "SwerveModuleVelocity", "double velocity;Rotation2d angle", 16,
         lambda v, a: SwerveModuleVelocity(v, Rotation2d(a)),
         lambda s: (s.velocity, rad(s.angle)), rot=(1,), nested=(Rotation2d,)),
    Case(SwerveModulePosition, "SwerveModulePosition", "double distance;Rotation2d angle", 16,
         lambda v, a: SwerveModulePosition(v, Rotation2d(a)),
         lambda s: (s.distance, rad(s.angle)), rot=(1,), nested=(Rotation2d,)),
    Case(SwerveModuleAcceleration, "SwerveModuleAccelerations",   # plural, sic (§11)
         "double acceleration;Rotation2d angle", 16,
         lambda v, a: SwerveModuleAcceleration(v, Rotation2d(a)),
         lambda s: (s.acceleration, rad(s.angle)), rot=(1,), nested=(Rotation2d,)),
    *(Case(c, c.__name__, MECANUM_WHEELS, 32, c,
           lambda w: (w.frontLeft, w.frontRight, w.rearLeft, w.rearRight))
      for c in (MecanumDriveWheelVelocities, MecanumDriveWheelPositions,
                MecanumDriveWheelAccelerations)),
    *(Case(c, c.__name__, "double left;double right", 16, c, lambda w: (w.left, w.right))
      for c in (DifferentialDriveWheelVelocities, DifferentialDriveWheelPositions,
                DifferentialDriveWheelAccelerations)),
    Case(DifferentialDriveKinematics, "DifferentialDriveKinematics", "double trackwidth", 8,
         _mk_diffkin, lambda k: (k.trackwidth,), finite=True, positive=(0,)),
    Case(MecanumDriveKinematics, "MecanumDriveKinematics",
         "Translation2d front_left;Translation2d front_right;"
         "Translation2d rear_left;Translation2d rear_right", 64,
         _mk_meckin, _meckin_fields, nested=(Translation2d,), finite=True),
]
CASE_IDS = [c.cls.__name__ for c in CASES]


def raw_values(case: Case) -> st.SearchStrategy[tuple[float, ...]]:
    """Raw constructor inputs: any double (NaN, ±inf, −0.0, subnormals) for value types,
    finite bounded values for the kinematics classes; angles of any winding."""
    parts = []
    for i in range(case.nraw):
        if i in case.positive:
            parts.append(st.floats(1e-3, 1e3))
        elif case.finite:
            parts.append(st.floats(-1e3, 1e3))
        elif i in case.rot:
            parts.append(st.one_of(st.floats(-1e6, 1e6),
                                   st.sampled_from([0.0, -0.0, PI, -PI, 4.0, -4.0,
                                                    3 * PI, 1.5 * PI])))
        else:
            parts.append(st.floats())
    return st.tuples(*parts)


def swerve(*xy: float) -> SwerveDriveKinematics:
    return SwerveDriveKinematics([Translation2d(xy[i], xy[i + 1])
                                  for i in range(0, len(xy), 2)])


def swerve_fields(k: SwerveDriveKinematics) -> tuple[float, ...]:
    return tuple(v for t in k.getModules() for v in (t.getX(), t.getY()))


swerve_raw = st.integers(2, 8).flatmap(
    lambda n: st.tuples(*[st.floats(-1e3, 1e3)] * (2 * n)))


# ---------------------------------------------------------------------------------------
# Descriptors: the §11 table


@pytest.mark.parametrize("case", CASES, ids=CASE_IDS)
def test_descriptors_match_table(case):
    obj = case.make(*([1.0] * case.nraw))
    for x in (case.cls, obj):
        assert wpistruct.getTypeName(x) == case.name
        assert wpistruct.getTypeString(x) == "struct:" + case.name
        assert wpistruct.getSchema(x) == case.schema
        assert wpistruct.getSize(x) == case.size
        assert wpistruct.getNested(x) == case.nested
    assert len(wpistruct.pack(obj)) == case.size


# Public classes that WPILib defines no struct for (no layout exists upstream in any
# version, so drivekin does not invent one).
NO_UPSTREAM_STRUCT = {"CoordinateAxis", "CoordinateSystem",
                      "DeadWheelKinematics", "DifferentialSwerveModuleKinematics",
                      "DifferentialSwerveModuleVelocities",
                      "DifferentialSwerveMotorVelocities",
                      # PathPlannerLib's setpoint generator and its values (not WPILib's)
                      "DriveFeedforwards", "ModuleConfig", "PathConstraints", "RobotConfig",
                      "SwerveSetpoint", "SwerveSetpointGenerator"}


# Public classes that are not values: stateful trackers, static-method namespaces and
# the warning category.
NOT_VALUES = {"ClockMismatchWarning", "MathSharedStore", "TimeInterpolatableBuffer", "Units"}
# Values with a WPILib 2027 struct that drivekin does not serialize yet (DCMotor: WPILib
# has a DCMotorStruct and a protobuf message; robotpy-wpimath 2026 has no protobuf to
# test the message against, and every drivekin struct type has a protobuf message too).
NOT_YET_SERIALIZED = {"DCMotor"}


def test_struct_types_cover_every_value_and_kinematics_class():
    # Every public drivekin class except odometry and pose estimators (stateful, no WPILib
    # struct) and the classes above; the 3-D geometry is test_wpistruct3d.py's.
    from tests.behaviour.test_wpistruct3d import CASES as CASES_3D
    public = [getattr(drivekin, n) for n in drivekin.__all__]
    expected = {c for c in public if isinstance(c, type)
                and not isinstance(c, RobotpyClass)   # SwerveDrive4Kinematics: builds one
                and "Odometry" not in c.__name__ and "PoseEstimator" not in c.__name__
                and c.__name__ not in NO_UPSTREAM_STRUCT | NOT_VALUES | NOT_YET_SERIALIZED}
    expected |= {c.cls for c in CASES_3D}
    assert set(wpistruct.STRUCT_TYPES) == expected
    assert len(wpistruct.STRUCT_TYPES) == len(expected)
    assert {c.cls for c in CASES + CASES_3D} | {SwerveDriveKinematics} == expected


@pytest.mark.parametrize("n", [2, 3, 4, 6, 8, 20])
def test_swerve_kinematics_descriptors(n):
    k = swerve(*[float(i) for i in range(2 * n)])
    assert wpistruct.getTypeName(k) == f"SwerveDriveKinematics__{n}"
    assert wpistruct.getTypeString(k) == f"struct:SwerveDriveKinematics__{n}"
    assert wpistruct.getSchema(k) == f"Translation2d modules[{n}]"
    assert wpistruct.getSize(k) == 16 * n
    assert wpistruct.getNested(k) == (Translation2d,)
    assert wpistruct.getNested(SwerveDriveKinematics) == (Translation2d,)
    for f in (wpistruct.getTypeName, wpistruct.getTypeString, wpistruct.getSchema,
              wpistruct.getSize):
        assert f(SwerveDriveKinematics, numModules=n) == f(k)
        assert f(k, numModules=n) == f(k)


def test_for_each_nested_order():
    def collect(x, **kw):
        out = []
        wpistruct.forEachNested(x, lambda t, s: out.append((t, s)), **kw)
        return out

    assert collect(Pose2d) == [
        ("struct:Translation2d", "double x;double y"),
        ("struct:Rotation2d", "double value"),
        ("struct:Pose2d", "Translation2d translation;Rotation2d rotation")]
    assert collect(SwerveModuleAcceleration) == [
        ("struct:Rotation2d", "double value"),
        ("struct:SwerveModuleAccelerations", "double acceleration;Rotation2d angle")]
    assert collect(ChassisVelocities) == [
        ("struct:ChassisVelocities", "double vx;double vy;double omega")]
    assert collect(SwerveDriveKinematics, numModules=4) == [
        ("struct:Translation2d", "double x;double y"),
        ("struct:SwerveDriveKinematics__4", "Translation2d modules[4]")]
    assert collect(swerve(1, 1, -1, -1)) == collect(SwerveDriveKinematics, numModules=2)


# ---------------------------------------------------------------------------------------
# Exact bytes


def test_digest_example_chassis_velocities():
    data = wpistruct.pack(ChassisVelocities(1.0, 2.0, 3.0))
    assert data == bytes.fromhex("000000000000f03f" "0000000000000040" "0000000000000840")
    assert data == wire([1.0, 2.0, 3.0])


def test_rotation_packs_wrapped_radians_2027():
    data = wpistruct.pack(Rotation2d(4.0))
    (value,) = struct.unpack("<d", data)
    # 2027 packs getRadians() = atan2(sin 4, cos 4) = 4 − 2π (up to the last ulp of the
    # atan2 round trip), not the constructor value 4.0 that 2026 packed.
    assert value == Rotation2d(4.0).getRadians()
    assert value == pytest.approx(4.0 - 2.0 * PI, abs=1e-15)
    assert value != 4.0
    assert wpistruct.pack(Pose2d(1.0, 2.0, Rotation2d(-4.0))) == wire(
        [1.0, 2.0, Rotation2d(-4.0).getRadians()])
    assert struct.unpack("<d", wpistruct.pack(Rotation2d(-4.0)))[0] == pytest.approx(
        2.0 * PI - 4.0, abs=1e-15)


def test_exact_bytes_nested_layouts():
    r = Rotation2d(0.5).getRadians()
    assert wpistruct.pack(SwerveModuleVelocity(3.5, Rotation2d(0.5))) == wire([3.5, r])
    assert wpistruct.pack(Transform2d(Translation2d(-1.0, 2.0), Rotation2d(0.5))) == wire(
        [-1.0, 2.0, r])
    m = MecanumDriveKinematics(Translation2d(1, 2), Translation2d(3, 4),
                               Translation2d(5, 6), Translation2d(7, 8))
    assert wpistruct.pack(m) == wire([1, 2, 3, 4, 5, 6, 7, 8])
    assert wpistruct.pack(swerve(1, 2, 3, 4, 5, 6)) == wire([1, 2, 3, 4, 5, 6])
    assert wpistruct.pack(MecanumDriveWheelAccelerations(1, 2, 3, 4)) == wire([1, 2, 3, 4])
    assert wpistruct.pack(DifferentialDriveKinematics(0.6)) == wire([0.6])
    # little-endian, bit-exact specials
    assert wpistruct.pack(Translation2d(-0.0, math.inf)) == (
        bytes.fromhex("0000000000000080") + bytes.fromhex("000000000000f07f"))


# ---------------------------------------------------------------------------------------
# Round trips


@pytest.mark.parametrize("case", CASES, ids=CASE_IDS)
@given(data=st.data())
def test_round_trip(case, data):
    raw = data.draw(raw_values(case))
    obj = case.make(*raw)
    expected = case.fields(obj)
    packed = wpistruct.pack(obj)
    assert packed == wire(expected)                  # layout, rotations as getRadians()
    back = wpistruct.unpack(case.cls, packed)
    assert type(back) is case.cls and back is not obj
    # Rotation2d comes back as Rotation2d(value): its getRadians() is atan2 of the unit
    # vector, which may differ from the packed value in the last ulp.
    again = tuple(Rotation2d(v).getRadians() if i in case.rot else v
                  for i, v in enumerate(expected))
    assert wire(case.fields(back)) == wire(again)
    # A second round trip is a fixed point for every non-rotation field and stays within
    # an ulp-level distance for the rotations.
    twice = case.fields(wpistruct.unpack(case.cls, wpistruct.pack(back)))
    for i, (a, b) in enumerate(zip(twice, again)):
        if i in case.rot and math.isfinite(a):
            assert abs(a - b) <= 4e-16 * max(1.0, abs(b))
        else:
            assert wire([a]) == wire([b])


@pytest.mark.parametrize("case", [c for c in CASES if c.cls not in {
    MecanumDriveWheelVelocities, MecanumDriveWheelAccelerations,
    DifferentialDriveWheelVelocities, DifferentialDriveWheelAccelerations,
    DifferentialDriveKinematics, MecanumDriveKinematics}], ids=lambda c: c.cls.__name__)
def test_round_trip_value_equality(case):
    # Types with WPILib value equality compare equal to their unpacked copy.
    raw = [0.25 * (i + 1) * (-1) ** i for i in range(case.nraw)]
    for i in case.rot:
        raw[i] = 5.0                                 # outside [−π, π]: equal after wrapping
    obj = case.make(*raw)
    assert wpistruct.unpack(case.cls, wpistruct.pack(obj)) == obj


@given(raw=swerve_raw)
def test_swerve_kinematics_round_trip(raw):
    k = swerve(*raw)
    n = len(raw) // 2
    data = wpistruct.pack(k)
    assert data == wire(raw)
    back = wpistruct.unpack(SwerveDriveKinematics, data)       # N inferred from length
    assert back.getNumModules() == n
    assert swerve_fields(back) == tuple(raw)
    back2 = wpistruct.unpack(SwerveDriveKinematics, data, numModules=n)
    assert swerve_fields(back2) == tuple(raw)


def test_unpacked_kinematics_work():
    k = swerve(0.3, 0.3, 0.3, -0.3, -0.3, 0.3, -0.3, -0.3)
    k2 = wpistruct.unpack(SwerveDriveKinematics, wpistruct.pack(k))
    cv = ChassisVelocities(1.0, 0.5, 0.2)
    a = k.toSwerveModuleVelocities(cv)
    b = k2.toSwerveModuleVelocities(cv)
    assert a == b
    d = wpistruct.unpack(DifferentialDriveKinematics, wpistruct.pack(
        DifferentialDriveKinematics(0.7)))
    assert d.trackwidth == 0.7
    w = d.toWheelVelocities(cv)
    assert (w.left, w.right) == (1.0 - 0.2 * 0.35, 1.0 + 0.2 * 0.35)


# ---------------------------------------------------------------------------------------
# Arrays, offsets, buffers


@pytest.mark.parametrize("case", CASES, ids=CASE_IDS)
@given(data=st.data())
def test_array_round_trip(case, data):
    raws = data.draw(st.lists(raw_values(case), max_size=5))
    objs = [case.make(*r) for r in raws]
    packed = wpistruct.packArray(objs)
    assert packed == b"".join(wpistruct.pack(o) for o in objs)
    assert packed == wire([v for o in objs for v in case.fields(o)])
    back = wpistruct.unpackArray(case.cls, packed)
    assert len(back) == len(objs)
    assert all(type(b) is case.cls for b in back)
    assert [wpistruct.pack(b) for b in back] == [
        wpistruct.pack(wpistruct.unpack(case.cls, wpistruct.pack(o))) for o in objs]


def test_array_generators_and_empty():
    assert wpistruct.packArray([]) == b""
    assert wpistruct.packArray(iter(())) == b""
    assert wpistruct.unpackArray(Pose2d, b"") == []
    data = wpistruct.packArray(Translation2d(i, -i) for i in range(3))
    assert data == wire([0, -0, 1, -1, 2, -2])
    assert [tuple(t) for t in wpistruct.unpackArray(Translation2d, data)] == [
        (0.0, 0.0), (1.0, -1.0), (2.0, -2.0)]


def test_swerve_kinematics_array():
    ks = [swerve(1, 2, 3, 4, 5, 6, 7, 8), swerve(-1, -2, -3, -4, -5, -6, -7, -8)]
    data = wpistruct.packArray(ks)
    assert data == wire([1, 2, 3, 4, 5, 6, 7, 8, -1, -2, -3, -4, -5, -6, -7, -8])
    back = wpistruct.unpackArray(SwerveDriveKinematics, data, numModules=4)
    assert [swerve_fields(k) for k in back] == [swerve_fields(k) for k in ks]
    back2 = wpistruct.unpackArray(SwerveDriveKinematics, data, numModules=2)
    assert len(back2) == 4          # the bytes alone cannot tell N; the caller decides
    with pytest.raises(TypeError, match="numModules"):
        wpistruct.unpackArray(SwerveDriveKinematics, data)
    with pytest.raises(TypeError, match="one struct type"):
        wpistruct.packArray([swerve(1, 2, 3, 4), swerve(1, 2, 3, 4, 5, 6)])


def test_buffer_kinds_and_offsets():
    p = Pose2d(1.0, -2.0, Rotation2d(0.75))
    data = wpistruct.pack(p)
    for buf in (data, bytearray(data), memoryview(data), np.frombuffer(data, np.uint8),
                np.frombuffer(data, np.float64)):
        assert wpistruct.unpack(Pose2d, buf) == p
    assert wpistruct.unpack(Pose2d, b"\xff" * 5 + data, 5) == p
    assert wpistruct.unpack(Pose2d, b"\xff" * 5 + data, offset=5) == p
    assert wpistruct.unpackFrom(Pose2d, b"\xff" * 5 + data + b"\xee" * 3, 5) == p
    assert wpistruct.unpackFrom(Pose2d, data) == p
    k = swerve(1, 2, 3, 4, 5, 6)
    kd = b"\0" * 8 + wpistruct.pack(k)
    assert swerve_fields(wpistruct.unpack(SwerveDriveKinematics, kd, 8)) == swerve_fields(k)
    assert swerve_fields(wpistruct.unpackFrom(SwerveDriveKinematics, kd + b"\0" * 16, 8,
                                              numModules=3)) == swerve_fields(k)
    # A bytearray is not left locked by an exported buffer.
    ba = bytearray(data)
    wpistruct.unpack(Pose2d, ba)
    wpistruct.unpackArray(Pose2d, ba)
    ba.extend(b"\0")


def test_pack_into():
    buf = bytearray(40)
    cv = ChassisVelocities(1.0, 2.0, 3.0)
    wpistruct.packInto(cv, buf, 8)
    assert bytes(buf[8:32]) == wpistruct.pack(cv) and buf[:8] == bytes(8)
    arr = np.zeros(3)
    wpistruct.packInto(Pose2d(1.0, 2.0, Rotation2d(4.0)), arr)
    assert arr.tolist() == [1.0, 2.0, Rotation2d(4.0).getRadians()]
    wpistruct.packInto(cv, memoryview(buf)[16:])
    assert bytes(buf[16:40]) == wpistruct.pack(cv)
    buf.extend(b"\0")                                # not left locked
    with pytest.raises(ValueError, match="needs 24 bytes"):
        wpistruct.packInto(cv, bytearray(23))
    with pytest.raises(ValueError, match="needs 24 bytes"):
        wpistruct.packInto(cv, bytearray(30), 7)
    with pytest.raises(TypeError, match="writable"):
        wpistruct.packInto(cv, bytes(24))
    with pytest.raises(TypeError, match="bytes-like"):
        wpistruct.packInto(cv, [0] * 24)
    with pytest.raises(TypeError, match="cannot serialize"):
        wpistruct.packInto(object(), bytearray(24))


# ---------------------------------------------------------------------------------------
# Errors


def test_unsupported_types():
    odo = drivekin.DifferentialDriveOdometry(Rotation2d(), 0.0, 0.0)
    for bad in (object(), 1.0, (1.0, 2.0), odo, None):
        with pytest.raises(TypeError, match="cannot serialize"):
            wpistruct.pack(bad)
        with pytest.raises(TypeError, match="cannot serialize"):
            wpistruct.getTypeName(bad)
        with pytest.raises(TypeError):
            wpistruct.packArray([bad])
    for bad_cls in (float, drivekin.SwerveDriveOdometry, int):
        with pytest.raises(TypeError, match="no WPILib struct"):
            wpistruct.getSchema(bad_cls)
        with pytest.raises(TypeError, match="no WPILib struct"):
            wpistruct.unpack(bad_cls, bytes(8))
        with pytest.raises(TypeError, match="no WPILib struct"):
            wpistruct.unpackArray(bad_cls, bytes(8))
    with pytest.raises(TypeError, match="cannot serialize"):
        wpistruct.pack(Pose2d)                       # a class, not an instance
    with pytest.raises(TypeError, match="takes a class"):
        wpistruct.unpack(Pose2d(), bytes(24))
    with pytest.raises(TypeError, match="takes a class"):
        wpistruct.unpackArray(Rotation2d(), bytes(8))


def test_mixed_array():
    with pytest.raises(TypeError, match="element 1 is Rotation2d"):
        wpistruct.packArray([Pose2d(), Rotation2d()])
    with pytest.raises(TypeError, match="element 1"):
        wpistruct.packArray([ChassisVelocities(), ChassisAccelerations()])


def test_wrong_lengths():
    with pytest.raises(ValueError, match="struct:Pose2d is 24 bytes, got 23"):
        wpistruct.unpack(Pose2d, bytes(23))
    with pytest.raises(ValueError, match="is 24 bytes, got 25"):
        wpistruct.unpack(Pose2d, bytes(25))       # e.g. the wrong type's bytes
    with pytest.raises(ValueError, match="is 16 bytes, got 24"):
        wpistruct.unpack(Translation2d, wpistruct.pack(Pose2d()))
    with pytest.raises(ValueError, match="got 0"):
        wpistruct.unpack(Rotation2d, bytes(8), 9)
    with pytest.raises(ValueError, match="only 7 available"):
        wpistruct.unpackFrom(Rotation2d, bytes(9), 2)
    with pytest.raises(ValueError, match="multiple of 24 bytes, got 50"):
        wpistruct.unpackArray(ChassisVelocities, bytes(50))
    with pytest.raises(ValueError, match="offset must be >= 0"):
        wpistruct.unpack(Rotation2d, bytes(8), -1)
    with pytest.raises(TypeError, match="offset must be an int"):
        wpistruct.unpack(Rotation2d, bytes(8), 0.0)
    for bad in ("x" * 8, 8, [0] * 8, None):
        with pytest.raises(TypeError, match="bytes-like"):
            wpistruct.unpack(Rotation2d, bad)
        with pytest.raises(TypeError, match="bytes-like"):
            wpistruct.unpackArray(Rotation2d, bad)


def test_swerve_kinematics_errors():
    with pytest.raises(TypeError, match="numModules=N or an instance"):
        wpistruct.getTypeName(SwerveDriveKinematics)
    with pytest.raises(TypeError, match="numModules=N or an instance"):
        wpistruct.getSize(SwerveDriveKinematics)
    with pytest.raises(TypeError, match="numModules=N or an instance"):
        wpistruct.forEachNested(SwerveDriveKinematics, lambda t, s: None)
    for n in (1, 0, -3):
        with pytest.raises(ValueError, match="numModules >= 2"):
            wpistruct.getSchema(SwerveDriveKinematics, numModules=n)
    for bad in (True, 2.0, "4"):
        with pytest.raises(TypeError, match="numModules must be an int"):
            wpistruct.getSchema(SwerveDriveKinematics, numModules=bad)
    with pytest.raises(TypeError, match="only to SwerveDriveKinematics"):
        wpistruct.getSchema(Pose2d, numModules=4)
    with pytest.raises(TypeError, match="only to SwerveDriveKinematics"):
        wpistruct.getSchema(Pose2d(), numModules=4)
    with pytest.raises(ValueError, match="does not match"):
        wpistruct.getTypeName(swerve(1, 2, 3, 4), numModules=3)
    # inference: a multiple of 16 bytes, at least two modules
    for nbytes in (0, 16, 40, 33):
        with pytest.raises(ValueError, match="cannot infer the module count"):
            wpistruct.unpack(SwerveDriveKinematics, bytes(nbytes))
    with pytest.raises(ValueError, match="SwerveDriveKinematics__3 is 48 bytes, got 64"):
        wpistruct.unpack(SwerveDriveKinematics, bytes(64), numModules=3)
    with pytest.raises(ValueError, match="numModules >= 2"):
        wpistruct.unpack(SwerveDriveKinematics, bytes(16), numModules=1)
    with pytest.raises(TypeError, match="numModules"):
        wpistruct.unpackFrom(SwerveDriveKinematics, bytes(64))


def test_values_rejected_by_constructors():
    # drivekin validates what WPILib Java accepts silently; unpack reports it as ValueError.
    for tw in (0.0, -1.0, math.nan, math.inf):
        with pytest.raises(ValueError, match="cannot unpack DifferentialDriveKinematics"):
            wpistruct.unpack(DifferentialDriveKinematics, wire([tw]))
    with pytest.raises(ValueError, match="cannot unpack SwerveDriveKinematics__2"):
        wpistruct.unpack(SwerveDriveKinematics, wire([math.nan, 1.0, 0.0, 0.0]))
    with pytest.raises(ValueError, match="cannot unpack MecanumDriveKinematics"):
        wpistruct.unpack(MecanumDriveKinematics, wire([math.nan, 1.0] * 4))
    ba = bytearray(wire([1.0, 0.0]))
    with pytest.raises(ValueError, match="cannot unpack DifferentialDriveKinematics"):
        wpistruct.unpackArray(DifferentialDriveKinematics, ba)
    with pytest.raises(ValueError, match="cannot unpack DifferentialDriveKinematics"):
        wpistruct.unpack(DifferentialDriveKinematics, ba, 8)
    ba.extend(b"\0")                                 # no buffer export left behind


def test_module_doctest():
    result = doctest.testmod(wpistruct, verbose=False)
    assert result.attempted > 0 and result.failed == 0


# ---------------------------------------------------------------------------------------
# Cross-check against robotpy-wpimath 2026.2.2's packer


@pytest.fixture(scope="module")
def rp():
    pytest.importorskip("wpimath")
    pytest.importorskip("wpiutil")
    import wpimath.geometry as rg
    import wpimath.kinematics as rk
    import wpiutil.wpistruct as rws
    return rg, rk, rws


def _rp_pairs(rg, rk):
    """(drivekin class, robotpy class, robotpy constructor from *wire* values)."""
    rt = rg.Translation2d
    return [
        (Translation2d, rg.Translation2d, rg.Translation2d),
        (Rotation2d, rg.Rotation2d, rg.Rotation2d),
        (Pose2d, rg.Pose2d, lambda x, y, t: rg.Pose2d(x, y, rg.Rotation2d(t))),
        (Transform2d, rg.Transform2d,
         lambda x, y, t: rg.Transform2d(rt(x, y), rg.Rotation2d(t))),
        (Twist2d, rg.Twist2d, rg.Twist2d),
        (ChassisVelocities, rk.ChassisSpeeds, rk.ChassisSpeeds),
        (SwerveModuleVelocity, rk.SwerveModuleState,
         lambda v, a: rk.SwerveModuleState(v, rg.Rotation2d(a))),
        (SwerveModulePosition, rk.SwerveModulePosition,
         lambda v, a: rk.SwerveModulePosition(v, rg.Rotation2d(a))),
        (MecanumDriveWheelVelocities, rk.MecanumDriveWheelSpeeds, rk.MecanumDriveWheelSpeeds),
        (DifferentialDriveWheelVelocities, rk.DifferentialDriveWheelSpeeds,
         rk.DifferentialDriveWheelSpeeds),
        (DifferentialDriveKinematics, rk.DifferentialDriveKinematics,
         rk.DifferentialDriveKinematics),
        (MecanumDriveKinematics, rk.MecanumDriveKinematics,
         lambda *v: rk.MecanumDriveKinematics(*(rt(v[i], v[i + 1]) for i in range(0, 8, 2)))),
    ]


RP_CLASSES = [Translation2d, Rotation2d, Pose2d, Transform2d, Twist2d, ChassisVelocities,
              SwerveModuleVelocity, SwerveModulePosition, MecanumDriveWheelVelocities,
              DifferentialDriveWheelVelocities, DifferentialDriveKinematics,
              MecanumDriveKinematics]
# Schemas that differ only by the 2027 field renames (§1 "Serialization names").
RENAMED_SCHEMA = {
    SwerveModuleVelocity: "double speed;Rotation2d angle",
    DifferentialDriveKinematics: "double track_width",
}


def _rp_pair(rp, cls):
    rg, rk, _ = rp
    (pair,) = [p for p in _rp_pairs(rg, rk) if p[0] is cls]
    return pair


@pytest.mark.parametrize("cls", RP_CLASSES, ids=lambda c: c.__name__)
def test_robotpy_descriptors(rp, cls):
    rws = rp[2]
    _, rpcls, _ = _rp_pair(rp, cls)
    assert wpistruct.getSize(cls) == rws.getSize(rpcls)
    assert RENAMED_SCHEMA.get(cls, wpistruct.getSchema(cls)) == rws.getSchema(rpcls)
    if rpcls.__name__ == cls.__name__:
        assert wpistruct.getTypeName(cls) == rws.getTypeName(rpcls)
        ours, theirs = [], []
        wpistruct.forEachNested(cls, lambda t, s: ours.append((t, s)))
        rws.forEachNested(rpcls, lambda t, s: theirs.append((t, s)))
        assert [t for t, _ in ours] == [t for t, _ in theirs]


@pytest.mark.parametrize("cls", RP_CLASSES, ids=lambda c: c.__name__)
@given(data=st.data())
def test_robotpy_same_bytes(rp, cls, data):
    rws = rp[2]
    (case,) = [c for c in CASES if c.cls is cls]
    _, rpcls, rpmake = _rp_pair(rp, cls)
    raw = data.draw(raw_values(case))
    obj = case.make(*raw)
    # Build the robotpy object from drivekin's wire values, i.e. with every angle already
    # wrapped to [−π, π]: 2026 packs the unwrapped constructor value, so raw angles outside
    # [−π, π] would (legitimately) give different bytes.
    w = case.fields(obj)
    rpobj = rpmake(*w)
    ours = wpistruct.pack(obj)
    assert ours == rws.pack(rpobj)
    # drivekin reads robotpy's bytes and robotpy reads drivekin's.
    assert wpistruct.pack(wpistruct.unpack(cls, rws.pack(rpobj))) == wpistruct.pack(
        wpistruct.unpack(cls, ours))
    assert rws.pack(rws.unpack(rpcls, ours)) == rws.pack(rpobj)
    n = data.draw(st.integers(0, 3))
    assert wpistruct.packArray([obj] * n) == rws.packArray([rpobj] * n)
    assert len(wpistruct.unpackArray(cls, rws.packArray([rpobj] * n))) == n


def test_robotpy_digest_example(rp):
    _, rk, rws = rp
    assert wpistruct.pack(ChassisVelocities(1, 2, 3)) == rws.pack(rk.ChassisSpeeds(1, 2, 3))


def test_rotation_outside_pi_differs_from_2026(rp):
    rg, _, rws = rp
    # The one intended difference: 2026 (robotpy) packs 4.0 unchanged, 2027 packs 4 − 2π.
    assert rws.pack(rg.Rotation2d(4.0)) == wire([4.0])
    assert wpistruct.pack(Rotation2d(4.0)) == wire([Rotation2d(4.0).getRadians()])
    # Both decode to the same angle.
    r = wpistruct.unpack(Rotation2d, rws.pack(rg.Rotation2d(4.0)))
    assert r == Rotation2d(4.0)
