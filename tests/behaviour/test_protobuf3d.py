"""drivekin.protobuf for the 3-D geometry: Translation3d, Quaternion, Rotation3d, Pose3d,
Transform3d, Twist3d (``wpimath/protobuf/geometry3d.proto``).

Reference: /work/shared/reference/geometry-3d.md §1.10 and WPILib's geometry3d.proto
(written out in ``tests/data/protobuf/wpimath/protobuf/geometry3d.proto``). The oracle is
protoc's compilation of that text, turned into message classes in a fresh descriptor
pool, as in ``test_protobuf.py`` (whose helpers this file uses); protoc runs in a child
process for the reason given there. robotpy-wpimath 2026.2.2 has no protobuf support, so
there is no robotpy byte cross-check; the doubles are the struct's
(``test_wpistruct3d.py`` checks those against robotpy).
"""
from __future__ import annotations

import importlib.util
import math
import struct
import subprocess
import sys

import pytest
from hypothesis import given, strategies as st

pytest.importorskip("google.protobuf")
if importlib.util.find_spec("grpc_tools") is None:
    pytest.skip("grpcio-tools is not installed", allow_module_level=True)

from google.protobuf import descriptor_pb2, descriptor_pool, message_factory  # noqa: E402

from drivekin import (  # noqa: E402
    Pose3d, Quaternion, Rotation3d, Transform3d, Translation3d, Twist3d, protobuf, wpistruct,
)
from tests.behaviour.test_protobuf import PROTO_ROOT, as_fields, fill, same  # noqa: E402
from tests.behaviour.test_wpistruct3d import CASES, IDS, raw_values  # noqa: E402

GEOMETRY3D = "wpimath/protobuf/geometry3d.proto"
MESSAGES = {Translation3d: "ProtobufTranslation3d", Quaternion: "ProtobufQuaternion",
            Rotation3d: "ProtobufRotation3d", Pose3d: "ProtobufPose3d",
            Transform3d: "ProtobufTransform3d", Twist3d: "ProtobufTwist3d"}


@pytest.fixture(scope="module")
def compiled(tmp_path_factory):
    out = tmp_path_factory.mktemp("proto3d") / "set.pb"
    r = subprocess.run([sys.executable, "-m", "grpc_tools.protoc", f"-I{PROTO_ROOT}",
                        f"--descriptor_set_out={out}", GEOMETRY3D],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    (f,) = descriptor_pb2.FileDescriptorSet.FromString(out.read_bytes()).file
    pool = descriptor_pool.DescriptorPool()
    pool.Add(f)
    classes = {m.name: message_factory.GetMessageClass(
        pool.FindMessageTypeByName(f"wpi.proto.{m.name}")) for m in f.message_type}
    return {"file": f, "classes": classes}


# The expected message of a drivekin object, as nested dicts (read with its getters).

def tr(t: Translation3d) -> dict:
    return {"x": t.getX(), "y": t.getY(), "z": t.getZ()}


def quat(q: Quaternion) -> dict:
    return {"w": q.getW(), "x": q.getX(), "y": q.getY(), "z": q.getZ()}


def message_fields(obj) -> dict:
    t = type(obj)
    if t is Translation3d:
        return tr(obj)
    if t is Quaternion:
        return quat(obj)
    if t is Rotation3d:
        return {"q": quat(obj.getQuaternion())}
    if t in (Pose3d, Transform3d):
        return {"translation": tr(obj.getTranslation()),
                "rotation": {"q": quat(obj.getRotation().getQuaternion())}}
    if t is Twist3d:
        return {n: getattr(obj, n) for n in ("dx", "dy", "dz", "rx", "ry", "rz")}
    raise AssertionError(t)


# ---------------------------------------------------------------------------------------
# Names and descriptors

@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_type_names_and_descriptor_order(case):
    message = MESSAGES[case.cls]
    for x in (case.cls, case.ours(*[0.5] * case.n)):
        assert protobuf.getTypeName(x) == "wpi.proto." + message
        assert protobuf.getTypeString(x) == "proto:wpi.proto." + message
        assert protobuf.getMessageClass(x).DESCRIPTOR.full_name == "wpi.proto." + message
    out = []
    protobuf.forEachDescriptor(case.cls, lambda name, data: out.append(name))
    assert out == ["proto:" + GEOMETRY3D]       # no dependencies


def test_descriptor_file_is_protocs(compiled):
    assert protobuf.GEOMETRY3D_FILE == GEOMETRY3D
    got = {}
    protobuf.forEachDescriptor(Pose3d, lambda name, data: got.setdefault(name, data))
    data = got["proto:" + GEOMETRY3D]
    mine = descriptor_pb2.FileDescriptorProto.FromString(data)
    assert [m.name for m in mine.message_type] == [
        "ProtobufTranslation3d", "ProtobufQuaternion", "ProtobufRotation3d", "ProtobufPose3d",
        "ProtobufTransform3d", "ProtobufTwist3d"]
    assert mine == compiled["file"]
    assert data == compiled["file"].SerializeToString()
    assert protobuf.forEachDescriptor(Twist3d, lambda n, d: pytest.fail(n),
                                      exists=lambda n: True) is None


# ---------------------------------------------------------------------------------------
# The oracle decodes drivekin's bytes; drivekin decodes the oracle's

@pytest.mark.parametrize("case", CASES, ids=IDS)
@given(data=st.data())
def test_oracle_decodes_every_field(compiled, case, data):
    obj = case.ours(*data.draw(raw_values(case)))
    msg = compiled["classes"][MESSAGES[case.cls]]()
    msg.ParseFromString(protobuf.pack(obj))
    assert same(as_fields(msg), message_fields(obj))


@pytest.mark.parametrize("case", CASES, ids=IDS)
@given(data=st.data())
def test_oracle_bytes_unpack_as_the_struct_does(compiled, case, data):
    # Any doubles, the quaternion included (unpacking normalises it through
    # Rotation3d(Quaternion), as the struct does), decode to the struct's object.
    raw = data.draw(raw_values(case))
    via_struct = wpistruct.unpack(case.cls, struct.pack(f"<{case.n}d", *raw))
    msg = compiled["classes"][MESSAGES[case.cls]]()
    fill(msg, _nested(case, raw))
    back = protobuf.unpack(case.cls, msg.SerializeToString())
    assert type(back) is case.cls
    assert wpistruct.pack(back) == wpistruct.pack(via_struct)
    assert wpistruct.pack(protobuf.unpack(case.cls, protobuf.pack(back))) == \
        wpistruct.pack(wpistruct.unpack(case.cls, wpistruct.pack(back)))


def _nested(case, raw) -> dict:
    """The message of raw wire doubles (the struct's order) as nested dicts."""
    names = {Translation3d: ("x", "y", "z"), Quaternion: ("w", "x", "y", "z"),
             Twist3d: ("dx", "dy", "dz", "rx", "ry", "rz")}
    if case.cls in names:
        return dict(zip(names[case.cls], raw))
    q = dict(zip(("w", "x", "y", "z"), raw[-4:]))
    if case.cls is Rotation3d:
        return {"q": q}
    return {"translation": dict(zip(("x", "y", "z"), raw[:3])), "rotation": {"q": q}}


def test_exact_bytes():
    def d(field, x):
        return bytes([field << 3 | 1]) + struct.pack("<d", x)

    def sub(field, payload):
        return bytes([field << 3 | 2, len(payload)]) + payload

    # proto3: +0.0 fields are left out, nested messages always written.
    assert protobuf.pack(Rotation3d()) == sub(1, d(1, 1.0))
    assert protobuf.pack(Pose3d()) == sub(1, b"") + sub(2, sub(1, d(1, 1.0)))
    half = Rotation3d(Quaternion(0.0, 0.0, -3.0, 4.0))
    assert protobuf.pack(Transform3d(Translation3d(1.0, -0.0, 2.0), half)) == \
        sub(1, d(1, 1.0) + d(2, -0.0) + d(3, 2.0)) + sub(2, sub(1, d(3, -0.6) + d(4, 0.8)))
    assert protobuf.pack(Quaternion(0.0, 0.0, 0.0, 0.0)) == b""
    assert protobuf.pack(Twist3d(0, 0, 0, 0, 0, 2.5)) == d(6, 2.5)


def test_missing_fields_read_as_zero():
    # A missing q is the zero quaternion, which Rotation3d(Quaternion) makes the identity.
    assert protobuf.unpack(Rotation3d, b"") == Rotation3d()
    assert protobuf.unpack(Pose3d, b"") == Pose3d()
    assert protobuf.unpack(Quaternion, b"").getW() == 0.0
    only_z = bytes([0x21]) + struct.pack("<d", -2.0)            # field 4, fixed64
    assert protobuf.unpack(Quaternion, only_z).getZ() == -2.0
    r = protobuf.unpack(Rotation3d, bytes([0x0A, 9]) + only_z)
    assert (r.getQuaternion().getW(), r.getQuaternion().getZ()) == (0.0, -1.0)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_round_trip_equal(case):
    obj = case.ours(*[0.25 * (i + 1) * (-1) ** i for i in range(case.n)])
    back = protobuf.unpack(case.cls, protobuf.pack(obj))
    assert type(back) is case.cls and back == obj


# ---------------------------------------------------------------------------------------
# Bad bytes

@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_truncated_bytes(case):
    obj = case.ours(*[0.25 * (i + 1) for i in range(case.n)])
    data = protobuf.pack(obj)
    for cut in (1, 2, len(data) - 1):
        with pytest.raises(ValueError, match=f"cannot unpack wpi.proto.{MESSAGES[case.cls]}"):
            protobuf.unpack(case.cls, data[:cut])


@pytest.mark.parametrize("garbage", [b"\xff", b"\x0a\x05\x09", b"\x12\x03\x0a\x09\x00",
                                     b"\x0b", b"\x09\x00"])
def test_garbage_bytes(garbage):
    with pytest.raises(ValueError, match="cannot unpack wpi.proto.ProtobufPose3d"):
        protobuf.unpack(Pose3d, garbage)


def test_nan_passes_through():
    msg = protobuf.pack(Translation3d(math.nan, math.inf, -math.inf))
    t = protobuf.unpack(Translation3d, msg)
    assert math.isnan(t.getX()) and (t.getY(), t.getZ()) == (math.inf, -math.inf)
    nan_w = bytes([0x09]) + struct.pack("<d", math.nan)          # field 1, fixed64
    q = protobuf.unpack(Rotation3d, bytes([0x0A, 9]) + nan_w).getQuaternion()
    assert all(math.isnan(v) for v in (q.getW(), q.getX(), q.getY(), q.getZ()))
