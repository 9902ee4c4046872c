"""drivekin.wpistruct for the 3-D geometry: Translation3d, Quaternion, Rotation3d, Pose3d,
Transform3d, Twist3d.

Reference: /work/shared/reference/geometry-3d.md §1.10 (names and schemas, the same in
WPILib 2026 and 2027; a Rotation3d packs its quaternion and unpacks through
``Rotation3d(Quaternion)``, which normalises). The oracle is robotpy-wpimath 2026.2.2's
packer (``wpiutil.wpistruct``), whose C++ structs are WPILib's: the same descriptors, the
same bytes for values built the same way on both sides, and the same bits after
unpacking any payload (the normalisation included). The expected layouts are also written
out independently (field getters + ``struct.pack('<…d')``).
"""
from __future__ import annotations

import math
import struct
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import pytest
from hypothesis import given, strategies as st

from drivekin import wpistruct
from drivekin import Pose3d, Quaternion, Rotation3d, Transform3d, Translation3d, Twist3d

POSE_SCHEMA = "Translation3d translation;Rotation3d rotation"


def wire(values) -> bytes:
    return struct.pack("<%dd" % len(values), *values)


def quat(q: Quaternion) -> tuple[float, ...]:
    return (q.getW(), q.getX(), q.getY(), q.getZ())


def frame(p) -> tuple[float, ...]:
    t = p.getTranslation()
    return (t.getX(), t.getY(), t.getZ(), *quat(p.getRotation().getQuaternion()))


@dataclass(frozen=True)
class Case:
    cls: type
    schema: str
    size: int
    nested: tuple[type, ...]
    fields: Callable[[Any], tuple[float, ...]]     # object -> wire values
    rp: Callable[[Any, tuple[float, ...]], Any]    # robotpy geometry, raw values -> object
    ours: Callable[..., Any]                       # raw values -> drivekin object, the same way
    quaternion: int | None = None                  # raw index of a quaternion (normalised)

    @property
    def n(self) -> int:
        return self.size // 8


def _normal_norm(w, x, y, z) -> bool:
    """WPILib's squared norm ((w² + x²) + y²) + z² is a normal double, or NaN, or the
    quaternion is zero."""
    s = ((w * w + x * x) + y * y) + z * z
    return s != s or w == x == y == z == 0.0 or 2.2250738585072014e-308 <= s < math.inf


def _rp_rotation(g, w, x, y, z):
    # WPILib's normalisation where the squared norm is a normal double; outside that range
    # drivekin scales by an exact power of two first (the largest component's binade), so
    # the result stays unit: robotpy's normalisation of the scaled quaternion.
    if not _normal_norm(w, x, y, z):
        e = math.frexp(max(abs(w), abs(x), abs(y), abs(z)))[1]
        w, x, y, z = (math.ldexp(v, -e) for v in (w, x, y, z))
    return g.Rotation3d(g.Quaternion(w, x, y, z))


CASES = [
    Case(Translation3d, "double x;double y;double z", 24, (),
         lambda t: (t.getX(), t.getY(), t.getZ()),
         lambda g, v: g.Translation3d(*v), Translation3d),
    Case(Quaternion, "double w;double x;double y;double z", 32, (), quat,
         lambda g, v: g.Quaternion(*v), Quaternion),
    Case(Rotation3d, "Quaternion q", 32, (Quaternion,), lambda r: quat(r.getQuaternion()),
         lambda g, v: _rp_rotation(g, *v), lambda *v: Rotation3d(Quaternion(*v)),
         quaternion=0),
    *(Case(cls, POSE_SCHEMA, 56, (Translation3d, Rotation3d), frame,
           lambda g, v, n=cls.__name__: getattr(g, n)(g.Translation3d(*v[:3]),
                                                      _rp_rotation(g, *v[3:])),
           lambda *v, c=cls: c(Translation3d(*v[:3]), Rotation3d(Quaternion(*v[3:]))),
           quaternion=3)
      for cls in (Pose3d, Transform3d)),
    Case(Twist3d, "double dx;double dy;double dz;double rx;double ry;double rz", 48, (),
         lambda t: (t.dx, t.dy, t.dz, t.rx, t.ry, t.rz),
         lambda g, v: g.Twist3d(*v), Twist3d),
]
IDS = [c.cls.__name__ for c in CASES]

# Quaternion components whose norm neither overflows nor underflows (both sides then
# store the same degenerate values, tested apart); plain members take any double.
component = st.one_of(st.floats(-1e150, 1e150),
                      st.sampled_from([0.0, -0.0, 1.0, -1.0, 1e-150, math.nan]))


def raw_values(case: Case) -> st.SearchStrategy[tuple[float, ...]]:
    q = case.quaternion
    return st.tuples(*[component if q is not None and q <= i < q + 4 else st.floats()
                       for i in range(case.n)])


@pytest.fixture(scope="module")
def rp():
    g = pytest.importorskip("wpimath.geometry")
    ws = pytest.importorskip("wpiutil.wpistruct")
    return g, ws


# ---------------------------------------------------------------------------------------
# Descriptors

@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_descriptors_match_the_table_and_robotpy(rp, case):
    g, ws = rp
    rpcls = getattr(g, case.cls.__name__)
    for x in (case.cls, case.ours(*[0.5] * case.n)):
        assert wpistruct.getTypeName(x) == case.cls.__name__ == ws.getTypeName(rpcls)
        assert wpistruct.getTypeString(x) == "struct:" + case.cls.__name__
        assert wpistruct.getSchema(x) == case.schema == ws.getSchema(rpcls)
        assert wpistruct.getSize(x) == case.size == ws.getSize(rpcls)
        assert wpistruct.getNested(x) == case.nested
    ours, theirs = [], []
    wpistruct.forEachNested(case.cls, lambda t, s: ours.append((t, s)))
    ws.forEachNested(rpcls, lambda t, s: theirs.append((t, s)))
    assert ours == theirs


def test_nested_order():
    out = []
    wpistruct.forEachNested(Transform3d, lambda t, s: out.append(t))
    assert out == ["struct:Translation3d", "struct:Quaternion", "struct:Rotation3d",
                   "struct:Transform3d"]


# ---------------------------------------------------------------------------------------
# Bytes

@pytest.mark.parametrize("case", CASES, ids=IDS)
@given(data=st.data())
def test_same_bytes_as_robotpy(rp, case, data):
    g, ws = rp
    raw = data.draw(raw_values(case))
    obj, theirs = case.ours(*raw), case.rp(g, raw)
    packed = wpistruct.pack(obj)
    # drivekin's Rotation3d(Quaternion) normalises with WPILib's C++ operations: the
    # same stored bits, so the same bytes.
    assert packed == ws.pack(theirs) == wire(case.fields(obj))
    assert wpistruct.packArray([obj, obj]) == ws.packArray([theirs, theirs])


@pytest.mark.parametrize("case", CASES, ids=IDS)
@given(data=st.data())
def test_unpacking_any_payload_gives_robotpys_bits(rp, case, data):
    g, ws = rp
    raw = data.draw(raw_values(case))
    payload = wire(raw)
    rpcls = getattr(g, case.cls.__name__)
    obj = wpistruct.unpack(case.cls, payload)
    assert type(obj) is case.cls
    # Unpacking normalises a Rotation3d's quaternion (and leaves a bare Quaternion as
    # it is) exactly as WPILib does, where its squared norm is a normal double.
    q = case.quaternion
    if q is None or case.cls is Quaternion or _normal_norm(*raw[q:q + 4]):
        assert wpistruct.pack(obj) == ws.pack(ws.unpack(rpcls, payload))
    else:
        assert wpistruct.pack(obj) == ws.pack(case.rp(g, raw))
    two = wpistruct.unpackArray(case.cls, payload * 2)
    assert [wpistruct.pack(o) for o in two] == [wpistruct.pack(obj)] * 2


@pytest.mark.parametrize("payload, expected", [
    ((0.0, 0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0)),      # zero: the identity (WPILib's rule)
    ((-2.0, 0.0, 0.0, 0.0), (-1.0, 0.0, 0.0, 0.0)),    # −q: kept, not canonicalised
    ((0.0, 0.0, 3.0, 4.0), (0.0, 0.0, 0.6, 0.8)),
    ((1e-200, 0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0)),   # norm² underflows to 0
])
def test_unpacked_rotations_are_normalised(rp, payload, expected):
    g, ws = rp
    r = wpistruct.unpack(Rotation3d, wire(payload))
    assert quat(r.getQuaternion()) == expected
    assert wpistruct.pack(r) == ws.pack(ws.unpack(g.Rotation3d, wire(payload)))
    assert quat(wpistruct.unpack(Quaternion, wire(payload))) == payload   # not normalised


def test_exact_bytes():
    p = Pose3d(Translation3d(1.0, -2.0, 0.5), Rotation3d(Quaternion(0.0, 0.0, 0.0, 2.0)))
    assert wpistruct.pack(p) == wire([1.0, -2.0, 0.5, 0.0, 0.0, 0.0, 1.0])
    assert wpistruct.pack(Rotation3d()) == bytes.fromhex("000000000000f03f") + bytes(24)
    assert wpistruct.pack(Twist3d(1, 2, 3, 4, 5, 6)) == wire([1, 2, 3, 4, 5, 6])
    assert wpistruct.pack(Quaternion(-0.0, math.inf, 1.0, 2.0)) == wire(
        [-0.0, math.inf, 1.0, 2.0])


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_round_trip_equal(case):
    obj = case.ours(*[0.25 * (i + 1) * (-1) ** i for i in range(case.n)])
    back = wpistruct.unpack(case.cls, wpistruct.pack(obj))
    assert type(back) is case.cls and back is not obj and back == obj


def test_pose_from_euler_angles_round_trips_to_the_same_pose():
    p = Pose3d(Translation3d(4.0, -1.5, 0.25), Rotation3d(0.1, -0.3, 2.9))
    data = wpistruct.pack(p)
    back = wpistruct.unpack(Pose3d, data)
    assert back == p and back.getRotation().getZ() == pytest.approx(2.9, abs=1e-15)
    arr = np.frombuffer(data, np.float64)
    assert arr[:3].tolist() == [4.0, -1.5, 0.25]
    assert math.fsum(v * v for v in arr[3:]) == pytest.approx(1.0, abs=4e-16)


# ---------------------------------------------------------------------------------------
# Bad bytes

@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_wrong_lengths(case):
    name = case.cls.__name__
    for n in (0, case.size - 1, case.size + 1, case.size - 8):
        with pytest.raises(ValueError, match=rf"struct:{name} is {case.size} bytes, got {n}"):
            wpistruct.unpack(case.cls, bytes(n))
    with pytest.raises(ValueError, match=rf"only {case.size - 1} available at offset 1"):
        wpistruct.unpackFrom(case.cls, bytes(case.size), 1)
    with pytest.raises(ValueError, match=rf"multiple of {case.size} bytes, got "
                                         rf"{2 * case.size + 3}"):
        wpistruct.unpackArray(case.cls, bytes(2 * case.size + 3))
    with pytest.raises(TypeError, match="bytes-like"):
        wpistruct.unpack(case.cls, [0] * case.size)
    with pytest.raises(ValueError, match="needs"):
        wpistruct.packInto(case.ours(*[1.0] * case.n), bytearray(case.size - 1))


def test_offsets_and_buffers():
    p = Pose3d(Translation3d(1.0, 2.0, 3.0), Rotation3d(0.5, 0.25, -1.0))
    data = wpistruct.pack(p)
    for buf in (bytearray(b"\xee" * 3 + data), np.frombuffer(b"\xee" * 3 + data, np.uint8)):
        assert wpistruct.pack(wpistruct.unpack(Pose3d, buf, 3)) == \
            wpistruct.pack(wpistruct.unpack(Pose3d, data))
    assert wpistruct.unpackFrom(Pose3d, data + b"\xff" * 5) == p
    out = bytearray(64)
    wpistruct.packInto(p, out, 8)
    assert bytes(out[8:]) == data and out[:8] == bytes(8)


def test_non_finite_members_pass_through_and_nan_rotations_stay_nan():
    t = wpistruct.unpack(Translation3d, wire([math.nan, math.inf, -0.0]))
    assert math.isnan(t.getX()) and t.getY() == math.inf and math.copysign(1, t.getZ()) < 0
    r = wpistruct.unpack(Rotation3d, wire([math.nan, 0.0, 0.0, 1.0]))
    assert all(math.isnan(v) for v in quat(r.getQuaternion()))
