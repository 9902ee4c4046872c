"""drivekin.protobuf: WPILib protobuf serialization (2027 message names).

Reference: /work/shared/reference/wpilib-kinematics.md §12. The oracle is independent of
drivekin's descriptor code: ``tests/data/protobuf/wpimath/protobuf/*.proto`` are the two
files written out as ``.proto`` text, compiled here by protoc (grpc_tools) into a
FileDescriptorSet, and turned into message classes in a fresh descriptor pool. (protoc's
``--python_out`` modules cannot be imported in this process: their import path
``wpimath.protobuf`` belongs to robotpy-wpimath's ``wpimath`` package, which the suite
imports as an oracle.) protoc runs in a child process: loading grpc_tools' compiler
extension into this process makes a later ``import wpimath`` abort (glibc assertion in
``__pthread_tpp_change_priority`` while libwpiutil loads; grpcio-tools 1.85.1,
robotpy-wpimath 2026.2.2).

robotpy-wpimath 2026.2.2 has no protobuf support (only ``WPIStruct``), so there is no
robotpy byte cross-check here.
"""
from __future__ import annotations

import doctest
import importlib.util
import math
import os
import struct
import subprocess
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

pytest.importorskip("google.protobuf")
if importlib.util.find_spec("grpc_tools") is None:
    pytest.skip("grpcio-tools is not installed", allow_module_level=True)

from google.protobuf import descriptor_pb2, descriptor_pool, message_factory  # noqa: E402

import drivekin  # noqa: E402
from drivekin import protobuf, wpistruct  # noqa: E402
from drivekin.differential import (  # noqa: E402
    DifferentialDriveKinematics,
    DifferentialDriveWheelAccelerations,
    DifferentialDriveWheelPositions,
    DifferentialDriveWheelVelocities,
)
from drivekin.geometry import (  # noqa: E402
    Pose2d, Rotation2d, Transform2d, Translation2d, Twist2d,
)
from drivekin.kinematics import (  # noqa: E402
    ChassisAccelerations,
    ChassisVelocities,
    SwerveDriveKinematics,
    SwerveModuleAcceleration,
    SwerveModulePosition,
    SwerveModuleVelocity,
)
from drivekin.mecanum import (  # noqa: E402
    MecanumDriveKinematics,
    MecanumDriveWheelAccelerations,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
)

PI = math.pi
PROTO_ROOT = Path(__file__).resolve().parents[1] / "data" / "protobuf"
GEOMETRY = "wpimath/protobuf/geometry2d.proto"
KINEMATICS = "wpimath/protobuf/kinematics.proto"


def bits(x: float) -> bytes:
    """Compare doubles by their bits (NaN == NaN, −0.0 != 0.0)."""
    return struct.pack("<d", x)


# ---------------------------------------------------------------------------------------
# The oracle: protoc's compilation of the .proto text


@pytest.fixture(scope="module")
def compiled(tmp_path_factory):
    out = tmp_path_factory.mktemp("proto") / "set.pb"
    r = subprocess.run([sys.executable, "-m", "grpc_tools.protoc", f"-I{PROTO_ROOT}",
                        "--include_imports", f"--descriptor_set_out={out}", KINEMATICS],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    fds = descriptor_pb2.FileDescriptorSet.FromString(out.read_bytes())
    pool = descriptor_pool.DescriptorPool()
    for f in fds.file:
        pool.Add(f)
    classes = {}
    for f in fds.file:
        for m in f.message_type:
            classes[m.name] = message_factory.GetMessageClass(
                pool.FindMessageTypeByName(f"wpi.proto.{m.name}"))
    return {"files": {f.name: f for f in fds.file}, "classes": classes}


# ---------------------------------------------------------------------------------------
# The §12 table, with independent constructors and field extractors. ``fields(obj)``
# gives the expected message as nested dicts/lists (Rotation2d: its getRadians()).


@dataclass(frozen=True)
class Case:
    cls: type
    message: str
    nraw: int                                     # raw constructor doubles
    make: Callable[..., Any]                      # raw doubles -> drivekin object
    fields: Callable[[Any], dict]                 # object -> expected message fields
    rot: tuple[int, ...] = ()                     # raw indices holding a Rotation2d
    finite: bool = False                          # constructor needs finite values
    positive: tuple[int, ...] = ()                # raw indices that must be > 0


def tr(t: Translation2d) -> dict:
    return {"x": t.getX(), "y": t.getY()}


def rot(r: Rotation2d) -> dict:
    return {"value": r.getRadians()}


def _meckin(*v):
    return MecanumDriveKinematics(*(Translation2d(v[i], v[i + 1]) for i in range(0, 8, 2)))


MECANUM = ("front_left", "front_right", "rear_left", "rear_right")

CASES = [
    Case(Translation2d, "ProtobufTranslation2d", 2, Translation2d, tr),
    Case(Rotation2d, "ProtobufRotation2d", 1, Rotation2d, rot, rot=(0,)),
    Case(Pose2d, "ProtobufPose2d", 3, lambda x, y, t: Pose2d(x, y, Rotation2d(t)),
         lambda p: {"translation": tr(p.getTranslation()), "rotation": rot(p.getRotation())},
         rot=(2,)),
    Case(Transform2d, "ProtobufTransform2d", 3,
         lambda x, y, t: Transform2d(x, y, Rotation2d(t)),
         lambda p: {"translation": tr(p.getTranslation()), "rotation": rot(p.getRotation())},
         rot=(2,)),
    Case(Twist2d, "ProtobufTwist2d", 3, Twist2d,
         lambda t: {"dx": t.dx, "dy": t.dy, "dtheta": t.dtheta}),
    Case(ChassisVelocities, "ProtobufChassisVelocities", 3, ChassisVelocities,
         lambda c: {"vx": c.vx, "vy": c.vy, "omega": c.omega}),
    Case(ChassisAccelerations, "ProtobufChassisAccelerations", 3, ChassisAccelerations,
         lambda c: {"ax": c.ax, "ay": c.ay, "alpha": c.alpha}),
    Case(SwerveModuleVelocity, "ProtobufSwerveModuleVelocity", 2,
         lambda v, a: SwerveModuleVelocity(v, Rotation2d(a)),
         lambda s: {"velocity": s.velocity, "angle": rot(s.angle)}, rot=(1,)),
    Case(SwerveModulePosition, "ProtobufSwerveModulePosition", 2,
         lambda v, a: SwerveModulePosition(v, Rotation2d(a)),
         lambda s: {"distance": s.distance, "angle": rot(s.angle)}, rot=(1,)),
    Case(SwerveModuleAcceleration, "ProtobufSwerveModuleAcceleration", 2,  # singular here
         lambda v, a: SwerveModuleAcceleration(v, Rotation2d(a)),
         lambda s: {"acceleration": s.acceleration, "angle": rot(s.angle)}, rot=(1,)),
    *(Case(c, "Protobuf" + c.__name__, 4, c,
           lambda w: dict(zip(MECANUM, (w.frontLeft, w.frontRight, w.rearLeft, w.rearRight))))
      for c in (MecanumDriveWheelVelocities, MecanumDriveWheelPositions,
                MecanumDriveWheelAccelerations)),
    *(Case(c, "Protobuf" + c.__name__, 2, c, lambda w: {"left": w.left, "right": w.right})
      for c in (DifferentialDriveWheelVelocities, DifferentialDriveWheelPositions,
                DifferentialDriveWheelAccelerations)),
    Case(DifferentialDriveKinematics, "ProtobufDifferentialDriveKinematics", 1,
         DifferentialDriveKinematics, lambda k: {"trackwidth": k.trackwidth},
         finite=True, positive=(0,)),
    Case(MecanumDriveKinematics, "ProtobufMecanumDriveKinematics", 8, _meckin,
         lambda k: dict(zip(MECANUM, (tr(k.getFrontLeft()), tr(k.getFrontRight()),
                                      tr(k.getRearLeft()), tr(k.getRearRight())))),
         finite=True),
]
CASE_IDS = [c.cls.__name__ for c in CASES]
SWERVE_MESSAGE = "ProtobufSwerveDriveKinematics"


def swerve(*xy: float) -> SwerveDriveKinematics:
    return SwerveDriveKinematics([Translation2d(xy[i], xy[i + 1])
                                  for i in range(0, len(xy), 2)])


def swerve_fields(k: SwerveDriveKinematics) -> dict:
    return {"modules": [tr(t) for t in k.getModules()]}


swerve_raw = st.integers(2, 8).flatmap(
    lambda n: st.tuples(*[st.floats(-1e3, 1e3)] * (2 * n)))

ANGLES = st.one_of(st.floats(-1e6, 1e6),
                   st.sampled_from([0.0, -0.0, PI, -PI, 4.0, -4.0, 3 * PI, 1.5 * PI]))


def raw_values(case: Case) -> st.SearchStrategy[tuple[float, ...]]:
    """Any double (NaN, ±inf, −0.0, subnormals) for value types, finite bounded values
    for the kinematics classes; angles of any winding for the rotation-only types."""
    parts = []
    for i in range(case.nraw):
        if i in case.positive:
            parts.append(st.floats(1e-3, 1e3))
        elif case.finite:
            parts.append(st.floats(-1e3, 1e3))
        elif i in case.rot:
            parts.append(st.one_of(ANGLES, st.floats()))
        else:
            parts.append(st.floats())
    return st.tuples(*parts)


def as_fields(msg, descriptor=None) -> dict:
    """A decoded message as nested dicts: every field the schema has (absent = default)."""
    out = {}
    for f in msg.DESCRIPTOR.fields:
        v = getattr(msg, f.name)
        if f.message_type is not None:
            is_repeated = getattr(f, "is_repeated", None)
            repeated = is_repeated if is_repeated is not None else f.label == f.LABEL_REPEATED
            out[f.name] = [as_fields(x) for x in v] if repeated else as_fields(v)
        else:
            out[f.name] = v
    return out


def same(a, b) -> bool:
    """Equal nested dicts, doubles compared by bits."""
    if isinstance(a, dict):
        return isinstance(b, dict) and a.keys() == b.keys() and all(
            same(a[k], b[k]) for k in a)
    if isinstance(a, list):
        return isinstance(b, list) and len(a) == len(b) and all(map(same, a, b))
    return type(a) is float and type(b) is float and bits(a) == bits(b)


def fill(msg, values: dict) -> None:
    """Set a message from nested dicts (the oracle's own encoder)."""
    for name, v in values.items():
        if isinstance(v, dict):
            sub = getattr(msg, name)
            sub.SetInParent()
            fill(sub, v)
        elif isinstance(v, list):
            for item in v:
                fill(getattr(msg, name).add(), item)
        else:
            setattr(msg, name, v)


# ---------------------------------------------------------------------------------------
# Names and type strings


def test_cases_cover_every_protobuf_type():
    # The 3-D geometry is test_protobuf3d.py's.
    from tests.behaviour.test_protobuf3d import MESSAGES as MESSAGES_3D
    assert set(protobuf.PROTOBUF_TYPES) == {c.cls for c in CASES} | {SwerveDriveKinematics} \
        | set(MESSAGES_3D)
    # Everything wpistruct serializes has a protobuf message too (WPILib 2027 has
    # messages for exactly these drivekin types).
    assert set(protobuf.PROTOBUF_TYPES) == set(wpistruct.STRUCT_TYPES)


@pytest.mark.parametrize("case", CASES, ids=CASE_IDS)
def test_type_names(case):
    obj = case.make(*([1.0] * case.nraw))
    for x in (case.cls, obj):
        assert protobuf.getTypeName(x) == "wpi.proto." + case.message
        assert protobuf.getTypeString(x) == "proto:wpi.proto." + case.message


def test_type_names_2027_renames():
    # The §1 rename table: the four messages WPILib renamed in 2027.
    assert protobuf.getTypeString(ChassisVelocities) == \
        "proto:wpi.proto.ProtobufChassisVelocities"
    assert protobuf.getTypeName(SwerveModuleVelocity) == \
        "wpi.proto.ProtobufSwerveModuleVelocity"
    assert protobuf.getTypeName(MecanumDriveWheelVelocities) == \
        "wpi.proto.ProtobufMecanumDriveWheelVelocities"
    assert protobuf.getTypeName(DifferentialDriveWheelVelocities) == \
        "wpi.proto.ProtobufDifferentialDriveWheelVelocities"
    k = swerve(1, 1, -1, -1)
    assert protobuf.getTypeString(k) == protobuf.getTypeString(SwerveDriveKinematics) == \
        "proto:wpi.proto.ProtobufSwerveDriveKinematics"     # one message for any N


def test_message_classes(compiled):
    for cls in protobuf.PROTOBUF_TYPES:
        mc = protobuf.getMessageClass(cls)
        assert mc is protobuf.getMessageClass(cls)           # one class per message
        assert mc.DESCRIPTOR.full_name == protobuf.getTypeName(cls)
    p = Pose2d(1.0, 2.0, Rotation2d(0.5))
    msg = protobuf.getMessageClass(p).FromString(protobuf.pack(p))
    assert (msg.translation.x, msg.translation.y, msg.rotation.value) == (1.0, 2.0, 0.5)


# ---------------------------------------------------------------------------------------
# Descriptors


def descriptors(x, **kw) -> list[tuple[str, bytes]]:
    out: list[tuple[str, bytes]] = []
    protobuf.forEachDescriptor(x, lambda name, data: out.append((name, data)), **kw)
    return out


def test_descriptor_files_match_protoc(compiled):
    got = dict(descriptors(SwerveDriveKinematics))
    assert set(got) == {"proto:" + GEOMETRY, "proto:" + KINEMATICS}
    for fname, want in compiled["files"].items():
        data = got["proto:" + fname]
        mine = descriptor_pb2.FileDescriptorProto.FromString(data)
        assert mine.name == fname and mine.package == "wpi.proto"
        assert mine.syntax == "proto3"
        assert list(mine.dependency) == list(want.dependency)
        assert [m.name for m in mine.message_type] == [m.name for m in want.message_type]
        for m, w in zip(mine.message_type, want.message_type):
            assert [(f.name, f.number, f.type, f.label, f.type_name, f.json_name)
                    for f in m.field] == \
                   [(f.name, f.number, f.type, f.label, f.type_name, f.json_name)
                    for f in w.field], m.name
        # Beyond the names, numbers and types: the whole descriptor is protoc's, byte
        # for byte (protoc's output for the .proto text without java options).
        assert mine == want
        assert data == want.SerializeToString()


def test_descriptor_message_types():
    f = descriptor_pb2.FileDescriptorProto.FromString(
        dict(descriptors(SwerveDriveKinematics))["proto:" + KINEMATICS])
    fields = {m.name: m.field for m in f.message_type}
    (modules,) = fields["ProtobufSwerveDriveKinematics"]
    assert modules.label == descriptor_pb2.FieldDescriptorProto.LABEL_REPEATED
    assert modules.type_name == ".wpi.proto.ProtobufTranslation2d"
    vel = fields["ProtobufSwerveModuleVelocity"]
    assert [(x.name, x.number) for x in vel] == [("velocity", 1), ("angle", 2)]
    assert vel[0].type == descriptor_pb2.FieldDescriptorProto.TYPE_DOUBLE
    assert vel[1].type_name == ".wpi.proto.ProtobufRotation2d"


@pytest.mark.parametrize("case", CASES, ids=CASE_IDS)
def test_for_each_descriptor_order(case):
    names = [n for n, _ in descriptors(case.cls)]
    if case.message in ("ProtobufTranslation2d", "ProtobufRotation2d", "ProtobufPose2d",
                        "ProtobufTransform2d", "ProtobufTwist2d"):
        assert names == ["proto:" + GEOMETRY]
    else:
        assert names == ["proto:" + GEOMETRY, "proto:" + KINEMATICS]   # dependency first


def test_for_each_descriptor_exists():
    have = {"proto:" + GEOMETRY}
    asked = []

    def exists(name):
        asked.append(name)
        return name in have

    assert [n for n, _ in descriptors(ChassisVelocities, exists=exists)] == \
        ["proto:" + KINEMATICS]
    assert asked == ["proto:" + KINEMATICS, "proto:" + GEOMETRY]
    # A published file hides its dependencies too (WPILib's rule).
    assert descriptors(ChassisVelocities, exists=lambda n: n.endswith("kinematics.proto")) \
        == []
    assert descriptors(Pose2d, exists=lambda n: True) == []


def test_schema_constants():
    assert protobuf.SCHEMA_TYPE == "proto:FileDescriptorProto"
    assert protobuf.PACKAGE == "wpi.proto"
    assert (protobuf.GEOMETRY2D_FILE, protobuf.KINEMATICS_FILE) == (GEOMETRY, KINEMATICS)


# ---------------------------------------------------------------------------------------
# drivekin's bytes decoded by the oracle, the oracle's bytes decoded by drivekin


def oracle_decode(compiled, message: str, data: bytes) -> dict:
    msg = compiled["classes"][message]()
    msg.ParseFromString(data)
    return as_fields(msg)


@pytest.mark.parametrize("case", CASES, ids=CASE_IDS)
@given(data=st.data())
def test_oracle_decodes_every_field(compiled, case, data):
    obj = case.make(*data.draw(raw_values(case)))
    packed = protobuf.pack(obj)
    assert type(packed) is bytes
    got = oracle_decode(compiled, case.message, packed)
    assert same(got, case.fields(obj)), (got, case.fields(obj))


@pytest.mark.parametrize("case", CASES, ids=CASE_IDS)
@given(data=st.data())
def test_oracle_bytes_unpack(compiled, case, data):
    obj = case.make(*data.draw(raw_values(case)))
    msg = compiled["classes"][case.message]()
    fill(msg, case.fields(obj))
    back = protobuf.unpack(case.cls, msg.SerializeToString())
    assert type(back) is case.cls
    # Rotation2d comes back as Rotation2d(value): compare with the same construction.
    assert same(case.fields(back), case.fields(case.make(*_refeed(case, obj))))


def _refeed(case, obj) -> list[float]:
    """Raw constructor arguments reproducing what unpack builds from obj's fields."""
    def flat(v):
        if isinstance(v, dict):
            return [x for item in v.values() for x in flat(item)]
        return [v]
    return flat(case.fields(obj))


@given(raw=swerve_raw)
def test_swerve_kinematics_oracle(compiled, raw):
    k = swerve(*raw)
    data = protobuf.pack(k)
    assert same(oracle_decode(compiled, SWERVE_MESSAGE, data), swerve_fields(k))
    back = protobuf.unpack(SwerveDriveKinematics, data)
    assert back.getNumModules() == len(raw) // 2
    assert same(swerve_fields(back), swerve_fields(k))
    msg = compiled["classes"][SWERVE_MESSAGE]()
    fill(msg, swerve_fields(k))
    assert same(swerve_fields(protobuf.unpack(SwerveDriveKinematics,
                                              msg.SerializeToString())), swerve_fields(k))


def test_exact_bytes():
    # Hand-encoded wire format: tag = (field << 3) | wire type (1: 64-bit, 2: length).
    def d(field, x):
        return bytes([field << 3 | 1]) + struct.pack("<d", x)

    def sub(field, payload):
        return bytes([field << 3 | 2, len(payload)]) + payload

    assert protobuf.pack(ChassisVelocities(1.0, 2.0, 3.0)) == d(1, 1.0) + d(2, 2.0) + d(3, 3.0)
    assert protobuf.pack(Pose2d(1.0, -2.0, Rotation2d(0.5))) == \
        sub(1, d(1, 1.0) + d(2, -2.0)) + sub(2, d(1, 0.5))
    # proto3: +0.0 fields are left out, −0.0 is not; nested messages are always present.
    assert protobuf.pack(Pose2d()) == sub(1, b"") + sub(2, b"")
    assert protobuf.pack(Translation2d(-0.0, 0.0)) == d(1, -0.0)
    assert protobuf.pack(Rotation2d()) == b""
    wrapped = Rotation2d(4.0).getRadians()                     # wrapped, as in §11
    assert abs(wrapped - (4.0 - 2 * PI)) < 1e-15
    assert protobuf.pack(SwerveModuleVelocity(2.0, Rotation2d(4.0))) == \
        d(1, 2.0) + sub(2, d(1, wrapped))
    assert protobuf.pack(swerve(1, 2, 3, 4)) == \
        sub(1, d(1, 1.0) + d(2, 2.0)) + sub(1, d(1, 3.0) + d(2, 4.0))


def test_rotation_packs_wrapped_radians():
    for theta in (4.0, -4.0, 3 * PI, 7.5):
        r = Rotation2d(theta)
        assert protobuf.pack(r) == protobuf.pack(Rotation2d(r.getRadians()))
        assert struct.unpack("<d", protobuf.pack(r)[1:])[0] == r.getRadians()
        assert -PI <= r.getRadians() <= PI


# ---------------------------------------------------------------------------------------
# Round trips and agreement with wpistruct


@pytest.mark.parametrize("case", CASES, ids=CASE_IDS)
@given(data=st.data())
def test_round_trip_matches_wpistruct(case, data):
    # Both formats carry the same doubles: unpacking either gives the same object, field
    # for field, at every step. (A Rotation2d round trip is not a fixed point: the
    # unpacked Rotation2d(value) may report a value one ulp away.)
    obj = case.make(*data.draw(raw_values(case)))
    back = protobuf.unpack(case.cls, protobuf.pack(obj))
    via_struct = wpistruct.unpack(case.cls, wpistruct.pack(obj))
    assert type(back) is case.cls and back is not obj
    assert same(case.fields(back), case.fields(via_struct))
    assert wpistruct.pack(back) == wpistruct.pack(via_struct)
    again = protobuf.unpack(case.cls, protobuf.pack(back))
    again_struct = wpistruct.unpack(case.cls, wpistruct.pack(via_struct))
    assert same(case.fields(again), case.fields(again_struct))


def test_round_trip_value_equality():
    for obj in (Translation2d(1.0, -2.0), Rotation2d(5.0), Pose2d(1, 2, Rotation2d(5.0)),
                Transform2d(1, 2, Rotation2d(-5.0)), Twist2d(1, 2, 3),
                ChassisVelocities(1, 2, 3), ChassisAccelerations(1, 2, 3),
                SwerveModuleVelocity(1, Rotation2d(2)), SwerveModulePosition(1, Rotation2d(2)),
                SwerveModuleAcceleration(1, Rotation2d(2)), MecanumDriveWheelPositions(1, 2, 3, 4),
                DifferentialDriveWheelPositions(1, 2)):
        assert protobuf.unpack(type(obj), protobuf.pack(obj)) == obj


def test_unpacked_kinematics_work():
    cv = ChassisVelocities(1.0, 0.5, 0.2)
    k = swerve(0.3, 0.3, 0.3, -0.3, -0.3, 0.3, -0.3, -0.3)
    k2 = protobuf.unpack(SwerveDriveKinematics, protobuf.pack(k))
    assert list(k2.toSwerveModuleVelocities(cv)) == list(k.toSwerveModuleVelocities(cv))
    m = _meckin(0.3, 0.3, 0.3, -0.3, -0.3, 0.3, -0.3, -0.3)
    m2 = protobuf.unpack(MecanumDriveKinematics, protobuf.pack(m))
    assert list(m2.toWheelVelocities(cv)) == list(m.toWheelVelocities(cv))
    dk = protobuf.unpack(DifferentialDriveKinematics,
                         protobuf.pack(DifferentialDriveKinematics(0.7)))
    assert dk.trackwidth == 0.7


def test_missing_and_unknown_fields():
    assert protobuf.unpack(Pose2d, b"") == Pose2d()
    assert protobuf.unpack(ChassisVelocities, bytes([0x11]) + struct.pack("<d", 2.5)) == \
        ChassisVelocities(0.0, 2.5, 0.0)
    # An unknown field (number 9, varint) is skipped.
    assert protobuf.unpack(Translation2d, bytes([0x48, 0x05]) + protobuf.pack(
        Translation2d(1, 2))) == Translation2d(1, 2)


def test_buffer_kinds():
    p = Pose2d(1.0, 2.0, Rotation2d(0.25))
    data = protobuf.pack(p)
    for buf in (bytearray(data), memoryview(data), np.frombuffer(data, dtype=np.uint8)):
        assert protobuf.unpack(Pose2d, buf) == p
    ba = bytearray(data)
    protobuf.unpack(Pose2d, ba)
    ba.extend(b"\0")                                  # no buffer export left behind


def test_module_doctest():
    result = doctest.testmod(protobuf, verbose=False)
    assert result.attempted > 0 and result.failed == 0


# ---------------------------------------------------------------------------------------
# Errors


@pytest.mark.parametrize("case", CASES, ids=CASE_IDS)
def test_truncated_bytes(case):
    obj = case.make(*[0.25 * (i + 1) for i in range(case.nraw)])
    data = protobuf.pack(obj)
    # Every field is present (no zeros), so each cut ends inside a field: after the first
    # tag, inside the first value or length, or one byte short of the last value.
    for cut in (1, 2, len(data) - 1):
        with pytest.raises(ValueError, match=f"cannot unpack wpi.proto.{case.message}"):
            protobuf.unpack(case.cls, data[:cut])


@pytest.mark.parametrize("garbage", [b"\xff", b"\xff\xff\xff", b"\x0a\x05\x09",
                                     b"\x07", b"\x0b", b"\x0c", b"\x09\x00"])
def test_garbage_bytes(garbage):
    with pytest.raises(ValueError, match="cannot unpack wpi.proto.ProtobufPose2d"):
        protobuf.unpack(Pose2d, garbage)


def test_swerve_needs_two_modules():
    one = protobuf.pack(swerve(1, 2, 3, 4))[:20]      # the first module only
    assert len(one) == 20
    for data in (b"", one):
        with pytest.raises(ValueError, match="ProtobufSwerveDriveKinematics.*at least 2"):
            protobuf.unpack(SwerveDriveKinematics, data)


def test_values_rejected_by_constructors():
    # The same values wpistruct.unpack rejects (drivekin's constructors decide).
    tw = protobuf.getMessageClass(DifferentialDriveKinematics)
    for x in (0.0, -1.0, math.nan, math.inf):
        with pytest.raises(ValueError,
                           match="cannot unpack wpi.proto.ProtobufDifferentialDriveKinematics"):
            protobuf.unpack(DifferentialDriveKinematics, tw(trackwidth=x).SerializeToString())
        with pytest.raises(ValueError):
            wpistruct.unpack(DifferentialDriveKinematics, struct.pack("<d", x))
    mk = protobuf.getMessageClass(MecanumDriveKinematics)
    T = protobuf.getMessageClass(Translation2d)
    bad = mk(front_left=T(x=math.nan, y=1.0), front_right=T(x=1.0, y=-1.0),
             rear_left=T(x=-1.0, y=1.0), rear_right=T(x=-1.0, y=-1.0)).SerializeToString()
    with pytest.raises(ValueError, match="cannot unpack wpi.proto.ProtobufMecanumDriveKinematics"):
        protobuf.unpack(MecanumDriveKinematics, bad)
    sk = protobuf.getMessageClass(SwerveDriveKinematics)
    bad = sk(modules=[T(x=math.inf, y=0.0), T(x=1.0, y=0.0)]).SerializeToString()
    with pytest.raises(ValueError, match="cannot unpack wpi.proto.ProtobufSwerveDriveKinematics"):
        protobuf.unpack(SwerveDriveKinematics, bad)
    with pytest.raises(ValueError):
        wpistruct.unpack(SwerveDriveKinematics, struct.pack("<4d", math.inf, 0.0, 1.0, 0.0))


def test_unsupported_objects():
    for bad in (None, 1.0, "x", object(), [Pose2d()], drivekin.Units,
                drivekin.DifferentialDriveOdometry(Rotation2d(), 0.0, 0.0)):
        with pytest.raises(TypeError, match="cannot serialize"):
            protobuf.pack(bad)
    with pytest.raises(TypeError, match="pass an instance"):
        protobuf.pack(Pose2d)
    for fn in (protobuf.getTypeName, protobuf.getTypeString, protobuf.getMessageClass,
               lambda c: protobuf.forEachDescriptor(c, print)):
        with pytest.raises(TypeError, match="no WPILib protobuf"):
            fn(drivekin.DifferentialDriveOdometry)
        with pytest.raises(TypeError, match="cannot serialize"):
            fn(3)
    with pytest.raises(TypeError, match="takes a class"):
        protobuf.unpack(Pose2d(), b"")
    with pytest.raises(TypeError, match="no WPILib protobuf"):
        protobuf.unpack(int, b"")


def test_foreign_classes_named_with_module():
    wpimath_geometry = pytest.importorskip("wpimath.geometry")
    rp = wpimath_geometry.Pose2d()
    with pytest.raises(TypeError, match=r"wpimath\.geometry.*Pose2d"):
        protobuf.pack(rp)
    with pytest.raises(TypeError, match=r"wpimath\.geometry.*Pose2d"):
        protobuf.unpack(type(rp), b"")
    with pytest.raises(TypeError, match=r"wpimath\.geometry.*Pose2d"):
        protobuf.getTypeString(rp)


def test_bad_buffers():
    with pytest.raises(TypeError, match="bytes-like"):
        protobuf.unpack(Pose2d, "0a00")
    with pytest.raises(TypeError, match="bytes-like"):
        protobuf.unpack(Pose2d, None)
    with pytest.raises(TypeError, match="dtype=object"):
        protobuf.unpack(Pose2d, np.zeros(3, dtype=object))
    with pytest.raises(TypeError, match="C-contiguous"):
        protobuf.unpack(Pose2d, np.zeros(8, dtype=np.uint8)[::2])


# ---------------------------------------------------------------------------------------
# The optional dependency


def _run(code: str) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(Path(drivekin.__file__).parents[1]), env.get("PYTHONPATH", "")])
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=env, timeout=120)


def test_import_drivekin_does_not_import_protobuf():
    r = _run("import sys, drivekin, drivekin.wpistruct, drivekin.protobuf as p\n"
             "from drivekin import ChassisVelocities as C\n"
             "assert p.getTypeString(C) == 'proto:wpi.proto.ProtobufChassisVelocities'\n"
             "print(sorted(m for m in sys.modules if m.startswith('google')))")
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]"


def test_missing_protobuf_gives_install_hint():
    # None in sys.modules makes `import google.protobuf` raise ModuleNotFoundError, as when
    # protobuf is not installed (the import system's documented rule).
    r = _run("import sys\n"
             "sys.modules['google'] = sys.modules['google.protobuf'] = None\n"
             "import drivekin.protobuf as p\n"
             "from drivekin import Pose2d\n"
             "print(p.getTypeName(Pose2d))\n"
             "for f in (lambda: p.pack(Pose2d()), lambda: p.unpack(Pose2d, b''),\n"
             "          lambda: p.getMessageClass(Pose2d)):\n"
             "    try:\n"
             "        f()\n"
             "    except ImportError as e:\n"
             "        print(e)\n")
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert lines[0] == "wpi.proto.ProtobufPose2d"
    assert len(lines) == 4
    assert all('pip install "drivekin[protobuf]"' in line for line in lines[1:])


def test_first_use_from_threads():
    # The runtime is built once even when first used from several threads at once: every
    # thread sees the same message class and gets the same bytes.
    r = _run("import threading\n"
             "import drivekin.protobuf as p\n"
             "from drivekin import Pose2d, Rotation2d\n"
             "go = threading.Barrier(8)\n"
             "out = []\n"
             "def work():\n"
             "    go.wait()\n"
             "    out.append((p.getMessageClass(Pose2d), p.pack(Pose2d(1, 2, Rotation2d(3)))))\n"
             "ts = [threading.Thread(target=work) for _ in range(8)]\n"
             "[t.start() for t in ts]\n"
             "[t.join() for t in ts]\n"
             "print(len(out), len({id(c) for c, _ in out}), len({b for _, b in out}))\n")
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["8", "1", "1"]
