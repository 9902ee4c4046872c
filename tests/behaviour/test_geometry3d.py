"""The 3-D value classes as Python values: constructors told apart by argument type,
pickling bit for bit, constructor-like repr, WPILib's toString, WPILib's equality
(q and −q the same Rotation3d) and unhashability, immutability, operators, and bad input
refused with a TypeError/ValueError that changes nothing.

Expected numbers come from closed forms written here (quaternions of axis-angle
rotations, numpy's rotation matrices), not from drivekin. WPILib's own test vectors,
the robotpy-wpimath oracle and the exactness against mpmath are in tests/reference/.
"""
from __future__ import annotations

import copy
import math
import pickle
import re
import struct

import numpy as np
import pytest

import drivekin
from drivekin import (
    CoordinateAxis,
    CoordinateSystem,
    Pose2d,
    Pose3d,
    Quaternion,
    Rotation2d,
    Rotation3d,
    Transform2d,
    Transform3d,
    Translation2d,
    Translation3d,
    Twist3d,
)

NAMESPACE = {name: getattr(drivekin, name) for name in drivekin.__all__}
A = 0.1 + 0.2          # 0.30000000000000004: a lossy round trip would show
B = -1.0 / 3.0


def quat(q: Quaternion) -> tuple[float, float, float, float]:
    return (q.w, q.x, q.y, q.z)


def rot(r: Rotation3d) -> tuple[float, float, float, float]:
    return quat(r.getQuaternion())


def fields(o) -> tuple[float, ...]:
    """Every stored double of a value, exactly."""
    if type(o) is Quaternion:
        return quat(o)
    if type(o) is Rotation3d:
        return rot(o)
    if type(o) is Translation3d:
        return (o.x, o.y, o.z)
    if type(o) in (Pose3d, Transform3d):
        return fields(o.getTranslation()) + rot(o.getRotation())
    if type(o) is Twist3d:
        return (o.dx, o.dy, o.dz, o.rx, o.ry, o.rz)
    raise AssertionError(type(o))


def bits(values) -> bytes:
    return struct.pack(f"<{len(values)}d", *values)


def axis_angle(axis, angle) -> tuple[float, float, float, float]:
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    s = math.sin(angle / 2)
    return (math.cos(angle / 2), a[0] * s, a[1] * s, a[2] * s)


def same_rotation(r: Rotation3d, q) -> bool:
    """r's quaternion is ±q to 1e-15."""
    got = np.array(rot(r))
    q = np.array(q)
    return min(np.abs(got - q).max(), np.abs(got + q).max()) < 1e-15


def matrix(axis, angle) -> np.ndarray:
    """Rodrigues' rotation matrix, for the matrix constructors."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * (k @ k)


VALUES = [
    Quaternion(A, B, 0.5, -2.0),
    Rotation3d(A, B, 2.5),
    Rotation3d(Quaternion(3.0, -4.0, 1.0, 2.0)),
    Translation3d(A, B, 7.25),
    Pose3d(A, B, -1.5, Rotation3d(0.25, B, A)),
    Transform3d(B, A, 0.125, Rotation3d(-2.0, 0.5, 3.0)),
    Twist3d(A, B, 1.5, -0.25, 0.75, -A),
]
IDS = [type(v).__name__ for v in VALUES]


# ---------------------------------------------------------------------------------------
# Constructors, told apart by argument type

def test_rotation3d_constructor_forms():
    t = 0.7
    want = axis_angle([1.0, -2.0, 0.5], t)
    vector = np.array([1.0, -2.0, 0.5])
    rvec = vector / np.linalg.norm(vector) * t
    assert same_rotation(Rotation3d(), (1.0, 0.0, 0.0, 0.0))
    assert same_rotation(Rotation3d([1.0, -2.0, 0.5], t), want)            # list
    assert same_rotation(Rotation3d((1.0, -2.0, 0.5), t), want)            # tuple
    assert same_rotation(Rotation3d(vector, t), want)                      # (3,) array
    assert same_rotation(Rotation3d(vector.reshape(3, 1), t), want)        # column vector
    assert same_rotation(Rotation3d(rvec), want)                           # rotation vector
    assert same_rotation(Rotation3d(list(rvec)), want)
    assert same_rotation(Rotation3d(matrix(vector, t)), want)              # 3x3 matrix
    assert same_rotation(Rotation3d(Quaternion(*(2.0 * np.array(want)))), want)
    assert same_rotation(Rotation3d(Rotation2d(t)), axis_angle([0, 0, 1], t))
    # Extrinsic roll, pitch, yaw: Rz(yaw)·Ry(pitch)·Rx(roll).
    roll, pitch, yaw = 0.3, -0.4, 1.1
    r = Rotation3d(roll, pitch, yaw)
    expected = matrix([0, 0, 1], yaw) @ matrix([0, 1, 0], pitch) @ matrix([1, 0, 0], roll)
    assert np.abs(r.toMatrix() - expected).max() < 1e-15
    assert Rotation3d(roll=roll, pitch=pitch, yaw=yaw) == r
    assert Rotation3d(1, 0, 0) == Rotation3d(1.0, 0.0, 0.0)                # ints are floats


def test_rotation3d_from_initial_to_final():
    a, b = np.array([1.0, 2.0, -0.5]), np.array([-0.3, 0.4, 2.0])
    r = Rotation3d(a, b)
    turned = Translation3d(a).rotateBy(r).toVector()
    assert np.abs(turned / np.linalg.norm(turned) - b / np.linalg.norm(b)).max() < 1e-15
    # Shortest: the axis is perpendicular to both.
    axis = r.getAxis()
    assert abs(axis @ a) < 1e-15 and abs(axis @ b) < 1e-15
    assert same_rotation(Rotation3d(a, 3.0 * a), (1.0, 0.0, 0.0, 0.0))     # parallel


@pytest.mark.parametrize("initial, e", [
    ([0.1, 0.5, 0.9], [1, 0, 0]),      # |x| < |y|, |x| < |z|: X
    ([0.9, 1.5, 0.2], [0, 0, 1]),      # |x| < |y|, |x| >= |z|: Z
    ([1.5, 0.2, 0.9], [0, 1, 0]),      # |x| >= |y|, |y| < |z|: Y
    ([1.5, 0.9, 0.2], [0, 0, 1]),      # |x| >= |y|, |y| >= |z|: Z
])
def test_rotation3d_antiparallel_turns_half_about_initial_cross_e(initial, e):
    a = np.array(initial)
    axis = np.cross(a, e)
    r = Rotation3d(a, -2.0 * a)
    assert same_rotation(r, axis_angle(axis, math.pi))


def test_rotation3d_degenerate_inputs_give_the_identity():
    # WPILib: a zero axis, a zero vector pair, a zero quaternion.
    for r in (Rotation3d([0.0, 0.0, 0.0], 1.0), Rotation3d([0.0, 0.0, 0.0]),
              Rotation3d([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]), Rotation3d(Quaternion(0, 0, 0, 0))):
        assert rot(r) == (1.0, 0.0, 0.0, 0.0)


def test_rotation3d_quaternion_is_normalised_as_wpilib():
    w, x, y, z = 3.0, -4.0, 1.0, 2.0
    n = math.sqrt(((w * w + x * x) + y * y) + z * z)
    assert rot(Rotation3d(Quaternion(w, x, y, z))) == (w / n, x / n, y / n, z / n)


def test_static_factories():
    r = Rotation3d(0.2, -0.3, 0.4)
    assert rot(Rotation3d.fromRadians(0.2, -0.3, 0.4)) == rot(r)
    assert Rotation3d.fromDegrees(math.degrees(0.2), math.degrees(-0.3), math.degrees(0.4)) == r
    assert Rotation3d.fromRotations(0.2 / (2 * math.pi), -0.3 / (2 * math.pi),
                                    0.4 / (2 * math.pi)) == r
    q = Quaternion.fromRotationVector([0.0, 0.0, 0.5])
    assert np.abs(np.array(quat(q)) - axis_angle([0, 0, 1], 0.5)).max() < 1e-16


def test_translation3d_constructor_forms():
    r = Rotation3d([0.0, 0.0, 1.0], math.pi / 2)
    assert fields(Translation3d()) == (0.0, 0.0, 0.0)
    assert fields(Translation3d(1.0, 2.0, 3.0)) == (1.0, 2.0, 3.0)
    assert fields(Translation3d(1, 2)) == (1.0, 2.0, 0.0)
    assert fields(Translation3d(x=1.0, y=2.0, z=3.0)) == (1.0, 2.0, 3.0)
    assert fields(Translation3d([1.0, 2.0, 3.0])) == (1.0, 2.0, 3.0)
    assert fields(Translation3d(np.array([1.0, 2.0, 3.0]))) == (1.0, 2.0, 3.0)
    assert fields(Translation3d(Translation2d(1.0, 2.0))) == (1.0, 2.0, 0.0)
    d = Translation3d(2.0, r)                          # (2, 0, 0) turned 90° about z
    assert np.abs(d.toVector() - [0.0, 2.0, 0.0]).max() < 1e-15


def test_pose_and_transform_constructor_forms():
    t, r = Translation3d(1.0, -2.0, 0.5), Rotation3d(0.1, 0.2, 0.3)
    for cls in (Pose3d, Transform3d):
        p = cls(t, r)
        assert fields(p) == fields(t) + rot(r)
        assert fields(cls(1.0, -2.0, 0.5, r)) == fields(p)
        assert fields(cls(translation=t, rotation=r)) == fields(p)
        assert fields(cls(x=1.0, y=-2.0, z=0.5, rotation=r)) == fields(p)
        assert fields(cls(1.0, -2.0, 0.5, rotation=r)) == fields(p)
        assert fields(cls()) == (0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
        m = np.eye(4)
        m[:3, :3] = matrix([1.0, 1.0, 0.0], 0.4)
        m[:3, 3] = [1.0, -2.0, 0.5]
        q = cls(m)
        assert fields(q)[:3] == (1.0, -2.0, 0.5)
        assert same_rotation(q.getRotation(), axis_angle([1.0, 1.0, 0.0], 0.4))
        assert np.abs(q.toMatrix() - m).max() < 1e-15
    flat = Pose3d(Pose2d(1.0, 2.0, Rotation2d(0.5)))
    assert fields(flat)[:3] == (1.0, 2.0, 0.0)
    assert same_rotation(flat.getRotation(), axis_angle([0, 0, 1], 0.5))
    assert Pose3d(pose=Pose2d(1.0, 2.0, Rotation2d(0.5))) == flat
    assert Transform3d(Transform2d(1.0, 2.0, Rotation2d(0.5))) == Transform3d(
        1.0, 2.0, 0.0, Rotation3d(0.0, 0.0, 0.5))
    a, b = Pose3d(1.0, 2.0, 3.0, r), Pose3d(-1.0, 0.5, 2.0, Rotation3d(-0.3, 0.2, 1.0))
    tr = Transform3d(a, b)
    assert a.transformBy(tr) == b
    assert Transform3d(initial=a, final=b) == tr


def test_coordinate_systems():
    nwu, edn = CoordinateSystem.NWU(), CoordinateSystem.EDN()
    assert CoordinateSystem.NWU() is nwu                 # presets are shared
    # NWU (x forward, y left, z up) to EDN (x right, y down, z forward).
    got = CoordinateSystem.convert(Translation3d(1.0, 2.0, 3.0), nwu, edn)
    assert fields(got) == (-2.0, -3.0, 1.0)
    assert CoordinateSystem.convert(pose=Pose3d(), from_=nwu, to=edn) == Pose3d(
        0.0, 0.0, 0.0, CoordinateSystem.convert(Rotation3d(), nwu, edn))
    axis = CoordinateAxis(3.0, 0.0, 4.0)
    assert repr(axis) == "CoordinateAxis(0.6, 0.0, 0.8)"


# ---------------------------------------------------------------------------------------
# Pickle, copy, repr, str

@pytest.mark.parametrize("value", VALUES, ids=IDS)
@pytest.mark.parametrize("protocol", [0, 2, pickle.HIGHEST_PROTOCOL])
def test_pickle_round_trip_is_exact(value, protocol):
    back = pickle.loads(pickle.dumps(value, protocol=protocol))
    assert type(back) is type(value) and back is not value
    assert bits(fields(back)) == bits(fields(value))


@pytest.mark.parametrize("value", VALUES, ids=IDS)
def test_copy_and_deepcopy(value):
    for c in (copy.copy(value), copy.deepcopy(value)):
        assert bits(fields(c)) == bits(fields(value))


def test_pickle_keeps_a_stored_quaternion_as_it_is():
    # A unit quaternion off by an ulp would move if pickling renormalised it.
    q = (0.5000000000000001, 0.5, 0.5, -0.5)
    r = pickle.loads(pickle.dumps(Rotation3d(Quaternion(*q))))
    stored = rot(r)
    assert rot(pickle.loads(pickle.dumps(r))) == stored
    from drivekin.geometry3d import _rotation3d_from_quaternion
    assert rot(_rotation3d_from_quaternion(*q)) == q
    with pytest.raises(ValueError, match="unit quaternion"):
        _rotation3d_from_quaternion(2.0, 0.0, 0.0, 0.0)     # a crafted payload


def test_coordinate_values_pickle():
    s = pickle.loads(pickle.dumps(CoordinateSystem(CoordinateAxis.E(), CoordinateAxis.D(),
                                                   CoordinateAxis.N())))
    t = Translation3d(1.0, 2.0, 3.0)
    assert CoordinateSystem.convert(t, CoordinateSystem.NWU(), s) == \
        CoordinateSystem.convert(t, CoordinateSystem.NWU(), CoordinateSystem.EDN())
    a = pickle.loads(pickle.dumps(CoordinateAxis(1.0, 2.0, 2.0)))
    assert repr(a) == repr(CoordinateAxis(1.0, 2.0, 2.0))


@pytest.mark.parametrize("value", VALUES, ids=IDS)
def test_repr_rebuilds_the_value(value):
    r = repr(value)
    assert r.startswith(type(value).__name__ + "(")
    back = eval(r, dict(NAMESPACE))  # noqa: S307 - our own repr
    assert type(back) is type(value) and back == value


@pytest.mark.parametrize("value, expected", [
    # WPILib's toString: %.2f (half up) for translations and twists, Double.toString
    # for quaternion components.
    (Translation3d(0.125, 2.675, -1.005), "Translation3d(X: 0.13, Y: 2.68, Z: -1.01)"),
    (Quaternion(1.0, 0.0, -0.0, 1e-05), "Quaternion(1.0, 0.0, -0.0, 1.0E-5)"),
    (Quaternion(0.25, 12345678.9, 1e7, 0.001), "Quaternion(0.25, 1.23456789E7, 1.0E7, 0.001)"),
    (Rotation3d(), "Rotation3d(Quaternion(1.0, 0.0, 0.0, 0.0))"),
    (Pose3d(1.0, 2.0, 3.0, Rotation3d()),
     "Pose3d(Translation3d(X: 1.00, Y: 2.00, Z: 3.00), Rotation3d(Quaternion(1.0, 0.0, 0.0, 0.0)))"),
    (Transform3d(), "Transform3d(Translation3d(X: 0.00, Y: 0.00, Z: 0.00), "
                    "Rotation3d(Quaternion(1.0, 0.0, 0.0, 0.0)))"),
    (Twist3d(1.0, 0.125, -2.675, 0.0, 0.5, 3.0),
     "Twist3d(dX: 1.00, dY: 0.13, dZ: -2.68, rX: 0.00, rY: 0.50, rZ: 3.00)"),
])
def test_str_matches_wpilib_to_string(value, expected):
    assert str(value) == expected


# ---------------------------------------------------------------------------------------
# Equality and hashing

def test_rotation3d_equality_is_wpilib_s():
    q = axis_angle([1.0, 2.0, 3.0], 0.8)
    r = Rotation3d(Quaternion(*q))
    assert r == Rotation3d(Quaternion(*(-np.array(q))))         # q and −q: one rotation
    assert r == r.rotateBy(Rotation3d([0.0, 1.0, 0.0], 8e-5))    # |1 − cos(δ/2)| < 1e-9
    assert r != r.rotateBy(Rotation3d([0.0, 1.0, 0.0], 1e-4))
    # Quaternions: −q is a different quaternion.
    assert Quaternion(*q) != Quaternion(*(-np.array(q)))
    assert Quaternion(*q) == Quaternion(*q)
    assert Quaternion(1.0, 0.0, 0.0, 0.0) != Quaternion(2.0, 0.0, 0.0, 0.0)  # norms differ


def test_tolerances_of_translations_poses_twists():
    assert Translation3d(1.0, 2.0, 3.0) == Translation3d(1.0 + 5e-10, 2.0, 3.0 - 5e-10)
    assert Translation3d(1.0, 2.0, 3.0) != Translation3d(1.0, 2.0, 3.0 + 2e-9)
    r = Rotation3d(0.1, 0.2, 0.3)
    assert Pose3d(1.0, 2.0, 3.0, r) != Transform3d(1.0, 2.0, 3.0, r)   # other class
    assert Twist3d(1.0, 0, 0, 0, 0, 0) == Twist3d(1.0 + 5e-10, 0, 0, 0, 0, 0)
    assert Twist3d(1.0, 0, 0, 0, 0, 0) != Twist3d(1.0, 0, 0, 0, 0, 2e-9)


@pytest.mark.parametrize("value", VALUES, ids=IDS)
def test_values_are_unhashable(value):
    # Tolerant equality (q and −q equal, 1e-9 everywhere) or mutability (Twist3d).
    with pytest.raises(TypeError):
        hash(value)


def test_coordinate_values_compare_by_identity():
    assert CoordinateAxis.N() == CoordinateAxis.N()
    assert CoordinateAxis(1.0, 0.0, 0.0) != CoordinateAxis.N()
    assert len({CoordinateSystem.NWU(), CoordinateSystem.NWU()}) == 1


# ---------------------------------------------------------------------------------------
# Immutability and the mutable Twist3d

@pytest.mark.parametrize("value", [v for v in VALUES if type(v) is not Twist3d] +
                         [CoordinateAxis.N(), CoordinateSystem.NWU()],
                         ids=lambda v: type(v).__name__)
def test_immutable_values_refuse_reinit_and_assignment(value):
    before = repr(value)
    args = {CoordinateAxis: (0.0, 1.0, 0.0),
            CoordinateSystem: (CoordinateAxis.E(), CoordinateAxis.D(), CoordinateAxis.N())}
    with pytest.raises(TypeError, match="immutable"):
        value.__init__(*args.get(type(value), ()))
    for name in ("x", "w", "q", "v", "p", "frozen"):
        with pytest.raises(AttributeError):
            setattr(value, name, 1.0)
    assert repr(value) == before


def test_shared_constants_stay_put():
    with pytest.raises(TypeError, match="immutable"):
        Rotation3d.kZero.__init__(1.0, 2.0, 3.0)
    assert rot(Rotation3d.kZero) == (1.0, 0.0, 0.0, 0.0)
    assert fields(Pose3d.kZero) == fields(Transform3d.kZero) == (0, 0, 0, 1, 0, 0, 0)
    assert fields(Translation3d.kZero) == (0.0, 0.0, 0.0)


def test_twist3d_fields_are_mutable_floats():
    t = Twist3d()
    t.dx, t.dy, t.dz, t.rx, t.ry, t.rz = 1, 2.0, 3.0, 4.0, 5.0, 6.0
    assert fields(t) == (1.0, 2.0, 3.0, 4.0, 5.0, 6.0)
    with pytest.raises(TypeError):
        t.dx = "1"
    with pytest.raises(AttributeError):
        del t.rz
    assert fields(t) == (1.0, 2.0, 3.0, 4.0, 5.0, 6.0)


# ---------------------------------------------------------------------------------------
# Operators (WPILib's plus/minus/times/div/unaryMinus; C++'s Twist3d * k)

def test_operators_are_the_named_methods():
    p, q = Pose3d(1.0, 2.0, 3.0, Rotation3d(0.1, 0.2, 0.3)), Pose3d(0, 1, 0, Rotation3d(1, 0, 0))
    t = Transform3d(0.5, 0.0, -0.5, Rotation3d(0.0, 0.3, 0.0))
    assert fields(p + t) == fields(p.plus(t)) == fields(p.transformBy(t))
    assert fields(p - q) == fields(p.minus(q))
    assert fields(t + t) == fields(t.plus(t))
    assert fields(2.0 * t) == fields(t * 2.0) == fields(t.times(2.0))
    assert fields(t / 4.0) == fields(t.div(4.0))
    a, b = Translation3d(1.0, 2.0, 3.0), Translation3d(-0.5, 0.25, 2.0)
    assert fields(a + b) == (0.5, 2.25, 5.0)
    assert fields(a - b) == (1.5, 1.75, 1.0)
    assert fields(-a) == (-1.0, -2.0, -3.0)
    assert fields(a * 2) == fields(2 * a) == (2.0, 4.0, 6.0)
    assert fields(a / 2) == (0.5, 1.0, 1.5)
    assert tuple(a) == (1.0, 2.0, 3.0)
    assert list(a.cross(b)) == list(np.cross([1.0, 2.0, 3.0], [-0.5, 0.25, 2.0]))
    qa, qb = Quaternion(1.0, 2.0, 3.0, 4.0), Quaternion(0.5, -1.0, 0.25, 2.0)
    assert quat(qa + qb) == (1.5, 1.0, 3.25, 6.0)
    assert quat(qa - qb) == (0.5, 3.0, 2.75, 2.0)
    assert quat(qa * 2.0) == quat(2.0 * qa) == (2.0, 4.0, 6.0, 8.0)
    assert quat(qa / 2.0) == (0.5, 1.0, 1.5, 2.0)
    # Hamilton product, written out.
    w1, x1, y1, z1 = quat(qa)
    w2, x2, y2, z2 = quat(qb)
    assert np.abs(np.array(quat(qa * qb)) - [
        w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2]).max() < 1e-15
    r = Rotation3d([0.0, 0.0, 1.0], 1.0)
    assert same_rotation(r * 0.5, axis_angle([0, 0, 1], 0.5))
    assert same_rotation(r / 4.0, axis_angle([0, 0, 1], 0.25))
    tw = Twist3d(1.0, 2.0, 3.0, 0.1, 0.2, 0.3)
    assert fields(tw * 2.0) == fields(2.0 * tw) == (2.0, 4.0, 6.0, 0.2, 0.4, 0.6)
    # 2027: Rotation3d has no + − or unary − (plus/minus/unaryMinus were removed).
    for op in (lambda: r + r, lambda: r - r, lambda: -r, lambda: p * p, lambda: p + p):
        with pytest.raises(TypeError):
            op()


# ---------------------------------------------------------------------------------------
# Bad input: TypeError / ValueError naming the problem; nothing changes

def _rotation_matrix_with(change):
    m = matrix([1.0, 2.0, 3.0], 0.5)
    change(m)
    return m


@pytest.mark.parametrize("make, error, match", [
    (lambda: Rotation3d(_rotation_matrix_with(lambda m: m.__setitem__((0, 0), m[0, 0] + 1e-6))),
     ValueError, "isn't orthogonal"),
    (lambda: Rotation3d(-np.eye(3)), ValueError, "not special orthogonal"),
    (lambda: Rotation3d(np.eye(3, dtype=np.float32)), TypeError, "float64"),
    (lambda: Rotation3d(np.eye(2)), ValueError, r"shape \(3, 3\)"),
    (lambda: Pose3d(np.eye(3)), ValueError, r"shape \(4, 4\)"),
    (lambda: Pose3d(np.diag([1.0, 1.0, 1.0, 2.0])), ValueError, "bottom row"),
    (lambda: Transform3d(np.vstack([np.eye(4)[:3], [1e-300, 0, 0, 1]])), ValueError,
     "bottom row"),
    (lambda: CoordinateSystem(CoordinateAxis.N(), CoordinateAxis.E(), CoordinateAxis.U()),
     ValueError, "left-handed"),
    (lambda: CoordinateSystem(CoordinateAxis.N(), CoordinateAxis.N(), CoordinateAxis.U()),
     ValueError, "orthogonal"),
    (lambda: CoordinateAxis(0.0, 0.0, 0.0), ValueError, "non-zero finite"),
    (lambda: CoordinateAxis(math.nan, 0.0, 1.0), ValueError, "non-zero finite"),
    (lambda: Rotation3d([1.0, 2.0], 0.5), ValueError, "3 floats"),
    (lambda: Rotation3d(["1", 2.0, 3.0]), TypeError, "float"),
    (lambda: Rotation3d("abc"), TypeError, "takes"),
    (lambda: Rotation3d(0.5), TypeError, "takes"),
    (lambda: Rotation3d(0.1, "b", 0.3), TypeError, "pitch"),
    (lambda: Rotation3d(pitch=0.1, yaw=0.2), TypeError, "together"),
    (lambda: Rotation3d(None), TypeError, "takes"),
    (lambda: Translation3d(1.0, Rotation2d()), TypeError, "y"),
    (lambda: Translation3d([1.0, 2.0, 3.0], 4.0), TypeError, "takes"),
    (lambda: Pose3d(Translation3d(), Rotation2d()), TypeError, "rotation must be a Rotation3d"),
    (lambda: Pose3d(1.0, 2.0, Rotation3d()), TypeError, "takes"),
    (lambda: Pose3d(Pose3d()), TypeError, "takes"),
    (lambda: Transform3d(Pose3d(), Pose2d()), TypeError, "final must be a Pose3d"),
    (lambda: Pose3d(translation=Translation3d()), TypeError, "takes"),
    (lambda: Pose3d(initial=Pose3d(), final=Pose3d()), TypeError, "unexpected keyword"),
    (lambda: Pose3d().transformBy(Pose3d()), TypeError, "other must be a Transform3d"),
    (lambda: Pose3d().relativeTo(None), TypeError, "other must be a Pose3d, got NoneType"),
    (lambda: Pose3d().nearest([Pose3d(), Pose2d()]), TypeError, "Pose3d objects"),
    (lambda: Pose3d().nearest([]), ValueError, "empty"),
    (lambda: Translation3d().nearest([Translation2d()]), TypeError, "Translation3d objects"),
    (lambda: Rotation3d().interpolate(Quaternion(), 0.5), TypeError, "end_value"),
    (lambda: Quaternion().times("x"), TypeError, "scalar"),
    (lambda: CoordinateSystem.convert(Pose2d(), CoordinateSystem.NWU(), CoordinateSystem.NED()),
     TypeError, "Translation3d, Rotation3d, Pose3d or Transform3d"),
    (lambda: CoordinateSystem.convert(Pose3d(), CoordinateSystem.NWU(), None), TypeError,
     "to must be a CoordinateSystem"),
])
def test_bad_input_is_refused(make, error, match):
    with pytest.raises(error, match=match):
        make()


def test_a_refused_call_changes_nothing():
    r = Rotation3d(0.1, 0.2, 0.3)
    before = rot(r)
    with pytest.raises(TypeError):
        r.__init__(-np.eye(3))
    with pytest.raises(TypeError):
        Rotation3d.kZero.__init__(-np.eye(3))
    assert rot(r) == before and rot(Rotation3d.kZero) == (1.0, 0.0, 0.0, 0.0)
    t = Twist3d(1.0, 2.0, 3.0, 4.0, 5.0, 6.0)
    with pytest.raises(TypeError):
        t.__init__(1.0, "2")
    assert fields(t) == (1.0, 2.0, 3.0, 4.0, 5.0, 6.0)


def test_finite_input_gives_finite_results():
    # Vectors whose squares overflow or underflow still have a direction and a length.
    assert same_rotation(Rotation3d([1e200, 0.0, 0.0], 1.0), axis_angle([1, 0, 0], 1.0))
    assert same_rotation(Rotation3d([0.0, 3e-200, 0.0], 1.0), axis_angle([0, 1, 0], 1.0))
    assert Translation3d(3e200, 4e200, 0.0).getNorm() == pytest.approx(5e200, rel=1e-15)
    assert Translation3d(3e-200, 4e-200, 0.0).getNorm() == pytest.approx(5e-200, rel=1e-15)
    big = Twist3d(1.0, 2.0, 3.0, 1e200, 0.0, 0.0).exp()
    assert all(math.isfinite(v) for v in fields(big))


@pytest.mark.parametrize("op, names", [
    (lambda r: -r, "inverse()"), (lambda r: r + r, "rotateBy"), (lambda r: r - r, "relativeTo"),
])
def test_rotation3d_has_no_2026_operators(op, names):
    # WPILib 2027 removed Rotation3d's unaryMinus, plus and minus (3-D rotations do not
    # commute); the TypeError names the replacement.
    with pytest.raises(TypeError, match=re.escape(names)):
        op(Rotation3d(0.1, 0.2, 0.3))


@pytest.mark.parametrize("angle", [2.2, 3.0, 3.14])
def test_twist3d_exp_quaternion_has_w_nonnegative_where_wpilib_may_negate(angle):
    # Twist3d.exp builds (cos θ/2, n̂ sin θ/2); WPILib's matrix → quaternion gives the
    # negation above 2π/3 for this axis: the same rotation, the opposite sign.
    wg = pytest.importorskip("wpimath.geometry")
    rvec = [0.0, -angle, 0.0]
    q = Twist3d(0.0, 0.0, 0.0, *rvec).exp().getRotation().getQuaternion()
    w = wg.Pose3d().exp(wg.Twist3d(0.0, 0.0, 0.0, *rvec)).rotation().getQuaternion()
    assert q.w == pytest.approx(math.cos(angle / 2), abs=1e-15) and q.w > 0.0
    assert (w.W(), w.X(), w.Y(), w.Z()) == pytest.approx((-q.w, -q.x, -q.y, -q.z), abs=1e-15)
