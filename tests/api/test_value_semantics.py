"""Value semantics of the public classes: pickling, repr/str, equality and hashing,
(im)mutability, operators and unpacking.

Expected strings and equality rules come from WPILib 2027 (digest §2), not from drivekin.
"""
from __future__ import annotations

import copy
import math
import pickle

import pytest

import drivekin
from drivekin import (
    ChassisAccelerations,
    ChassisVelocities,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveModuleAcceleration,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Transform2d,
    Translation2d,
    Twist2d,
)

NAMESPACE = {name: getattr(drivekin, name) for name in drivekin.__all__}

# Non-round numbers so that a lossy round trip would show.
A = 0.1 + 0.2          # 0.30000000000000004
B = -1.0 / 3.0
TH = 2.0 * math.pi / 3.0 + 1e-12


def fields(o):
    """Every stored number of a value, exactly (angles as their (cos, sin))."""
    t = type(o)
    if t is Translation2d:
        return (o.getX(), o.getY())
    if t is Rotation2d:
        return (o.getCos(), o.getSin())
    if t in (Pose2d, Transform2d):
        return fields(o.getTranslation()) + fields(o.getRotation())
    if t is Twist2d:
        return (o.dx, o.dy, o.dtheta)
    if t is ChassisVelocities:
        return (o.vx, o.vy, o.omega)
    if t is ChassisAccelerations:
        return (o.ax, o.ay, o.alpha)
    if t is SwerveModuleVelocity:
        return (o.velocity,) + fields(o.angle)
    if t is SwerveModulePosition:
        return (o.distance,) + fields(o.angle)
    if t is SwerveModuleAcceleration:
        return (o.acceleration,) + fields(o.angle)
    raise AssertionError(t)


VALUES = [
    Translation2d(A, B),
    Rotation2d(TH),
    Rotation2d(3.0, -4.0),
    Pose2d(A, B, Rotation2d(TH)),
    Transform2d(A, B, Rotation2d(-TH)),
    Twist2d(A, B, 7.5),
    ChassisVelocities(A, B, -0.0),
    ChassisAccelerations(A, B, 12.25),
    SwerveModuleVelocity(A, Rotation2d(TH)),
    SwerveModulePosition(B, Rotation2d(-TH)),
    SwerveModuleAcceleration(A, Rotation2d(1.0)),
]
IDS = [type(v).__name__ for v in VALUES]


# ---------------------------------------------------------------------------------------
# Pickle / copy


@pytest.mark.parametrize("value", VALUES, ids=IDS)
@pytest.mark.parametrize("protocol", [0, 2, pickle.HIGHEST_PROTOCOL])
def test_pickle_round_trip_is_exact(value, protocol):
    back = pickle.loads(pickle.dumps(value, protocol=protocol))
    assert type(back) is type(value)
    assert back is not value
    assert fields(back) == fields(value)
    assert back == value


@pytest.mark.parametrize("value", VALUES, ids=IDS)
def test_copy_and_deepcopy(value):
    for c in (copy.copy(value), copy.deepcopy(value)):
        assert type(c) is type(value)
        assert fields(c) == fields(value)


def test_pickled_copy_of_mutable_value_is_independent():
    cv = ChassisVelocities(1.0, 2.0, 3.0)
    back = pickle.loads(pickle.dumps(cv))
    back.vx = 10.0
    assert cv.vx == 1.0


def test_rotation_pickle_keeps_cos_sin_bits():
    # A Rotation2d built from (x, y) is not exactly Rotation2d(atan2(y, x)); pickling must
    # keep the stored unit vector, not re-derive it from the angle.
    r = Rotation2d(1.0, 3.0)
    back = pickle.loads(pickle.dumps(r))
    assert (back.getCos(), back.getSin()) == (r.getCos(), r.getSin())


def test_kinematics_pickle_round_trip():
    mods = [Translation2d(0.3, 0.25), Translation2d(0.3, -0.25), Translation2d(-0.31, 0.2),
            Translation2d(-0.3, -0.2), Translation2d(0.0, 0.4)]
    kin = SwerveDriveKinematics(*mods)
    back = pickle.loads(pickle.dumps(kin))
    assert type(back) is SwerveDriveKinematics
    assert [fields(m) for m in back.getModules()] == [fields(m) for m in mods]
    cv = ChassisVelocities(1.5, -0.5, 2.0)
    s1 = kin.toSwerveModuleVelocities(cv)
    s2 = back.toSwerveModuleVelocities(cv)
    assert [fields(s) for s in s1] == [fields(s) for s in s2]
    assert kin.toChassisVelocities(s1) == back.toChassisVelocities(s1)
    # The copy has its own heading memory.
    back.toSwerveModuleVelocities(ChassisVelocities(0.0, 1.0, 0.0))
    assert [fields(s) for s in kin.toSwerveModuleVelocities(ChassisVelocities())] == [
        (0.0,) + fields(s.angle) for s in s1]


# ---------------------------------------------------------------------------------------
# repr / str


@pytest.mark.parametrize("value", VALUES, ids=IDS)
def test_repr_is_constructor_like(value):
    """repr() is constructor-like (docs/porting.md): evaluating it rebuilds the value."""
    r = repr(value)
    assert r.startswith(type(value).__name__ + "(")
    back = eval(r, dict(NAMESPACE))  # noqa: S307 - our own repr
    assert type(back) is type(value)
    assert back == value


def test_kinematics_repr_names_modules():
    kin = SwerveDriveKinematics(Translation2d(1.0, 2.0), Translation2d(-1.0, 0.5))
    r = repr(kin)
    assert r.startswith("SwerveDriveKinematics(")
    back = eval(r, dict(NAMESPACE))  # noqa: S307
    assert [fields(m) for m in back.getModules()] == [(1.0, 2.0), (-1.0, 0.5)]


# Strings: WPILib 2027 toString, Java %.2f rounding HALF_UP on the shortest decimal
# (0.125 → 0.13, 2.675 → 2.68, 1.005 → 1.01), digest §2.
@pytest.mark.parametrize("value, expected", [
    (Translation2d(0.125, 2.675), "Translation2d(X: 0.13, Y: 2.68)"),
    (Translation2d(-1.005, 0.0), "Translation2d(X: -1.01, Y: 0.00)"),
    (Rotation2d(math.pi / 2), "Rotation2d(Rads: 1.57, Deg: 90.00)"),
    (Rotation2d.fromDegrees(-45.0), "Rotation2d(Rads: -0.79, Deg: -45.00)"),
    (Pose2d(1.0, 2.0, Rotation2d.fromDegrees(180.0)),
     "Pose2d(Translation2d(X: 1.00, Y: 2.00), Rotation2d(Rads: 3.14, Deg: 180.00))"),
    (Transform2d(0.125, -3.0, Rotation2d()),
     "Transform2d(Translation2d(X: 0.13, Y: -3.00), Rotation2d(Rads: 0.00, Deg: 0.00))"),
    (Twist2d(1.0, 0.125, -2.675), "Twist2d(dX: 1.00, dY: 0.13, dTheta: -2.68)"),
    (ChassisVelocities(1.0, 2.675, -0.5),
     "ChassisVelocities(Vx: 1.00 m/s, Vy: 2.68 m/s, Omega: -0.50 rad/s)"),
    (ChassisAccelerations(0.125, 0.0, 3.0),
     "ChassisAccelerations(Ax: 0.13 m/s², Ay: 0.00 m/s², Alpha: 3.00 rad/s²)"),
    (SwerveModuleVelocity(2.5, Rotation2d.fromDegrees(90.0)),
     "SwerveModuleVelocity(Velocity: 2.50 m/s, Angle: Rotation2d(Rads: 1.57, Deg: 90.00))"),
    (SwerveModulePosition(1.005, Rotation2d()),
     "SwerveModulePosition(Distance: 1.01 m, Angle: Rotation2d(Rads: 0.00, Deg: 0.00))"),
    (SwerveModuleAcceleration(3.0, Rotation2d()),
     "SwerveModuleAccelerations(Acceleration: 3.00 m/s², "
     "Angle: Rotation2d(Rads: 0.00, Deg: 0.00))"),
])
def test_str_matches_wpilib_to_string(value, expected):
    assert str(value) == expected


# ---------------------------------------------------------------------------------------
# Equality and hashing


@pytest.mark.parametrize("value", VALUES, ids=IDS)
def test_values_are_unhashable(value):
    # Tolerant equality (geometry, modules) or mutability (chassis, twist) rules out a
    # hash consistent with ==.
    with pytest.raises(TypeError):
        hash(value)
    with pytest.raises(TypeError):
        {value}  # noqa: B018


def test_kinematics_is_identity_hashable_or_unhashable_consistently():
    kin = SwerveDriveKinematics(Translation2d(1.0, 0.0), Translation2d(-1.0, 0.0))
    assert kin == kin
    try:
        h = hash(kin)
    except TypeError:
        return
    assert h == hash(kin)


def test_translation_equality_tolerance():
    t = Translation2d(1.0, 2.0)
    assert t == Translation2d(1.0 + 5e-10, 2.0 - 5e-10)
    assert t != Translation2d(1.0 + 2e-9, 2.0)
    assert t != Translation2d(1.0, 2.0 + 2e-9)
    assert not (t == (1.0, 2.0))
    assert t != (1.0, 2.0)


def test_rotation_equality_is_on_unit_vector():
    assert Rotation2d(math.pi) == Rotation2d(-math.pi)
    assert Rotation2d(0.0) == Rotation2d(2 * math.pi)
    assert Rotation2d(1.0) == Rotation2d(1.0 + 5e-10)
    assert Rotation2d(1.0) != Rotation2d(1.0 + 2e-9)
    assert Rotation2d(1.0) != 1.0


def test_pose_and_transform_equality():
    p = Pose2d(1.0, 2.0, Rotation2d(math.pi))
    assert p == Pose2d(1.0 + 5e-10, 2.0, Rotation2d(-math.pi))
    assert p != Pose2d(1.0, 2.0, Rotation2d(math.pi - 2e-9))
    # Same numbers, different meaning: a pose is not a transform.
    assert p != Transform2d(1.0, 2.0, Rotation2d(math.pi))
    assert Transform2d(1.0, 2.0, Rotation2d(0.5)) == Transform2d(1.0, 2.0 + 5e-10,
                                                                 Rotation2d(0.5))


def test_twist_equality_tolerance():
    assert Twist2d(1.0, 2.0, 3.0) == Twist2d(1.0 + 5e-10, 2.0, 3.0 - 5e-10)
    assert Twist2d(1.0, 2.0, 3.0) != Twist2d(1.0, 2.0, 3.0 + 2e-9)
    # dtheta is a plain number, not an angle: 2π apart is different.
    assert Twist2d(0.0, 0.0, 0.0) != Twist2d(0.0, 0.0, 2 * math.pi)


def test_chassis_velocities_equality_is_exact():
    assert ChassisVelocities(1.0, 2.0, 3.0) == ChassisVelocities(1.0, 2.0, 3.0)
    assert ChassisVelocities(1.0, 2.0, 3.0) != ChassisVelocities(1.0, 2.0, 3.0 + 1e-15)
    assert ChassisVelocities(0.0, 0.0, 0.0) == ChassisVelocities(-0.0, -0.0, -0.0)
    nan = float("nan")
    assert ChassisVelocities(nan, 0.0, 0.0) != ChassisVelocities(nan, 0.0, 0.0)
    assert ChassisVelocities() != ChassisAccelerations()


def test_chassis_accelerations_equality_is_double_compare():
    assert ChassisAccelerations(1.0, 2.0, 3.0) == ChassisAccelerations(1.0, 2.0, 3.0)
    assert ChassisAccelerations(1.0, 2.0, 3.0) != ChassisAccelerations(1.0, 2.0, 3.0 + 1e-15)
    nan = float("nan")
    assert ChassisAccelerations(nan, 0.0, 0.0) == ChassisAccelerations(nan, 0.0, 0.0)
    assert ChassisAccelerations(0.0, 0.0, 0.0) != ChassisAccelerations(-0.0, 0.0, 0.0)


@pytest.mark.parametrize("cls", [SwerveModuleVelocity, SwerveModulePosition,
                                 SwerveModuleAcceleration])
def test_module_value_equality_tolerance(cls):
    assert cls(1.0, Rotation2d(math.pi)) == cls(1.0 + 5e-10, Rotation2d(-math.pi))
    assert cls(1.0, Rotation2d(0.5)) != cls(1.0 + 2e-9, Rotation2d(0.5))
    assert cls(1.0, Rotation2d(0.5)) != cls(1.0, Rotation2d(0.5 + 2e-9))
    others = {SwerveModuleVelocity, SwerveModulePosition, SwerveModuleAcceleration} - {cls}
    for other in others:
        assert cls(1.0, Rotation2d(0.5)) != other(1.0, Rotation2d(0.5))


def test_compare_to_uses_java_double_compare():
    a, b = SwerveModuleVelocity(1.0), SwerveModuleVelocity(2.0, Rotation2d(3.0))
    assert (a.compareTo(b), b.compareTo(a), a.compareTo(SwerveModuleVelocity(1.0, Rotation2d(1.0)))
            ) == (-1, 1, 0)
    assert SwerveModulePosition(-0.0).compareTo(SwerveModulePosition(0.0)) == -1
    assert SwerveModuleAcceleration(float("nan")).compareTo(SwerveModuleAcceleration(1e300)) == 1
    nan = SwerveModuleVelocity(float("nan"))
    assert nan.compareTo(SwerveModuleVelocity(float("nan"))) == 0


# ---------------------------------------------------------------------------------------
# Immutability of geometry, mutability of the rest


@pytest.mark.parametrize("value, attrs", [
    (Translation2d(1.0, 2.0), ["x", "y", "v", "foo"]),
    (Rotation2d(1.0), ["value", "radians", "r", "foo"]),
    (Pose2d(1.0, 2.0, Rotation2d(1.0)), ["x", "y", "translation", "rotation", "p", "foo"]),
    (Transform2d(1.0, 2.0, Rotation2d(1.0)), ["x", "y", "translation", "rotation", "p", "foo"]),
], ids=["Translation2d", "Rotation2d", "Pose2d", "Transform2d"])
def test_geometry_is_immutable(value, attrs):
    before = fields(value)
    for name in attrs:
        with pytest.raises(AttributeError):
            setattr(value, name, 5.0)
    with pytest.raises(AttributeError):
        delattr(value, "x" if hasattr(value, "x") else "foo")
    assert fields(value) == before


def test_geometry_constants_cannot_be_replaced():
    before = fields(Rotation2d.kZero)
    with pytest.raises((TypeError, AttributeError)):
        Rotation2d.kZero = Rotation2d(1.0)
    assert fields(Rotation2d.kZero) == before == (1.0, 0.0)
    assert fields(Translation2d.kZero) == (0.0, 0.0)
    assert fields(Rotation2d.kPi)[0] == -1.0
    assert fields(Pose2d.kZero) == (0.0, 0.0, 1.0, 0.0)
    assert fields(Transform2d.kZero) == (0.0, 0.0, 1.0, 0.0)


@pytest.mark.parametrize("cls, names", [
    (Twist2d, ("dx", "dy", "dtheta")),
    (ChassisVelocities, ("vx", "vy", "omega")),
    (ChassisAccelerations, ("ax", "ay", "alpha")),
])
def test_mutable_fields(cls, names):
    o = cls()
    assert fields(o) == (0.0, 0.0, 0.0)
    for i, name in enumerate(names):
        setattr(o, name, A * (i + 1))
    assert fields(o) == (A, 2 * A, 3 * A)
    o2 = cls(**{n: v for n, v in zip(names, (1.0, 2.0, 3.0))})
    assert fields(o2) == (1.0, 2.0, 3.0)
    setattr(o2, names[0], 7)  # ints are accepted as floats
    assert getattr(o2, names[0]) == 7.0 and type(getattr(o2, names[0])) is float
    with pytest.raises(TypeError):
        setattr(o2, names[1], "fast")
    with pytest.raises(AttributeError):
        o2.not_a_field = 1.0  # a typo must not silently create an attribute


@pytest.mark.parametrize("cls, name", [
    (SwerveModuleVelocity, "velocity"),
    (SwerveModulePosition, "distance"),
    (SwerveModuleAcceleration, "acceleration"),
])
def test_module_values_are_mutable(cls, name):
    o = cls()
    assert fields(o) == (0.0, 1.0, 0.0)
    setattr(o, name, B)
    r = Rotation2d(TH)
    o.angle = r
    assert fields(o) == (B,) + fields(r)
    assert o.angle == r
    o2 = cls(**{name: 2.0, "angle": Rotation2d(1.0)})
    assert fields(o2) == (2.0,) + fields(Rotation2d(1.0))
    with pytest.raises(TypeError):
        o.angle = 1.0
    with pytest.raises(TypeError):
        setattr(o, name, None)
    assert fields(o) == (B,) + fields(r)


def test_position_copy_is_independent():
    p = SwerveModulePosition(1.0, Rotation2d(0.5))
    c = p.copy()
    assert c is not p and fields(c) == fields(p)
    c.distance = 9.0
    c.angle = Rotation2d(2.0)
    assert fields(p) == fields(SwerveModulePosition(1.0, Rotation2d(0.5)))


# ---------------------------------------------------------------------------------------
# Operators


def test_translation_operators():
    a, b = Translation2d(1.0, 2.0), Translation2d(0.5, -4.0)
    assert fields(a + b) == (1.5, -2.0)
    assert fields(a - b) == (0.5, 6.0)
    assert fields(-a) == (-1.0, -2.0)
    assert fields(a * 2.0) == fields(2.0 * a) == (2.0, 4.0)
    assert fields(a / 4.0) == (0.25, 0.5)
    with pytest.raises(TypeError):
        a + 1.0  # noqa: B018
    with pytest.raises(TypeError):
        a * "x"  # noqa: B018
    with pytest.raises(TypeError):
        a * b  # noqa: B018


def test_rotation_operators():
    a, b = Rotation2d.fromDegrees(30.0), Rotation2d.fromDegrees(45.0)
    assert (a + b).getDegrees() == pytest.approx(75.0, abs=1e-12)
    assert (a - b).getDegrees() == pytest.approx(-15.0, abs=1e-12)
    assert (-a).getDegrees() == pytest.approx(-30.0, abs=1e-12)
    assert (a * 3.0).getDegrees() == pytest.approx(90.0, abs=1e-12)
    assert (3.0 * a).getDegrees() == pytest.approx(90.0, abs=1e-12)
    assert (b / 3.0).getDegrees() == pytest.approx(15.0, abs=1e-12)
    with pytest.raises(TypeError):
        a + 1.0  # noqa: B018


def test_pose_and_transform_operators():
    p = Pose2d(1.0, 0.0, Rotation2d.fromDegrees(90.0))
    t = Transform2d(2.0, 0.0, Rotation2d.fromDegrees(90.0))
    q = p + t
    assert type(q) is Pose2d
    assert (q.getX(), q.getY()) == pytest.approx((1.0, 2.0), abs=1e-15)
    assert q.getRotation().getDegrees() == pytest.approx(180.0)
    d = q - p
    assert type(d) is Transform2d and d == t
    assert type(t + t) is Transform2d
    assert fields(p * 2.0)[:2] == (2.0, 0.0)
    assert (p / 2.0).getRotation().getDegrees() == pytest.approx(45.0)
    assert type(t * 0.5) is Transform2d and type(t / 2.0) is Transform2d
    with pytest.raises(TypeError):
        p + p  # noqa: B018
    with pytest.raises(TypeError):
        p - t  # noqa: B018
    with pytest.raises(TypeError):
        t - t  # noqa: B018  (WPILib has no Transform2d.minus)


@pytest.mark.parametrize("cls", [ChassisVelocities, ChassisAccelerations])
def test_chassis_operators(cls):
    a, b = cls(1.0, 2.0, 3.0), cls(0.5, -1.0, 0.25)
    for r, exp in ((a + b, (1.5, 1.0, 3.25)), (a - b, (0.5, 3.0, 2.75)), (-a, (-1.0, -2.0, -3.0)),
                   (a * 2.0, (2.0, 4.0, 6.0)), (2.0 * a, (2.0, 4.0, 6.0)),
                   (a / 2.0, (0.5, 1.0, 1.5)), (a.plus(b), (1.5, 1.0, 3.25)),
                   (a.minus(b), (0.5, 3.0, 2.75)), (a.unaryMinus(), (-1.0, -2.0, -3.0)),
                   (a.times(2.0), (2.0, 4.0, 6.0)), (a.div(2.0), (0.5, 1.0, 1.5))):
        assert type(r) is cls and r is not a
        assert fields(r) == exp
    assert fields(a) == (1.0, 2.0, 3.0)
    other = ChassisAccelerations if cls is ChassisVelocities else ChassisVelocities
    with pytest.raises(TypeError):
        a + other(1.0, 1.0, 1.0)  # noqa: B018
    with pytest.raises(TypeError):
        a.plus(other())


def test_chassis_interpolate_clamps_by_returning_endpoints():
    a, b = ChassisVelocities(0.0, 0.0, 0.0), ChassisVelocities(2.0, 4.0, 8.0)
    assert a.interpolate(b, -1.0) is a and a.interpolate(b, 0.0) is a
    assert a.interpolate(b, 1.0) is b and a.interpolate(b, 3.0) is b
    assert fields(a.interpolate(b, 0.25)) == (0.5, 1.0, 2.0)


def test_module_interpolate_clamping():
    v0, v1 = SwerveModuleVelocity(0.0, Rotation2d()), SwerveModuleVelocity(4.0, Rotation2d(1.0))
    assert fields(v0.interpolate(v1, 2.0)) == pytest.approx(fields(v1), abs=1e-15)
    assert fields(v0.interpolate(v1, -1.0)) == pytest.approx(fields(v0), abs=1e-15)
    p0, p1 = SwerveModulePosition(0.0, Rotation2d()), SwerveModulePosition(4.0, Rotation2d(1.0))
    p = p0.interpolate(p1, 1.5)  # not clamped
    assert p.distance == 6.0 and p.angle.getRadians() == pytest.approx(1.5)


# ---------------------------------------------------------------------------------------
# Unpacking


def test_module_tuples_unpack():
    kin = SwerveDriveKinematics(Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
                                Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))
    fl, fr, bl, br = kin.toSwerveModuleVelocities(ChassisVelocities(0.0, 0.0, 1.0))
    assert all(type(s) is SwerveModuleVelocity for s in (fl, fr, bl, br))
    assert fl.angle.getDegrees() == pytest.approx(135.0)
    assert br.angle.getDegrees() == pytest.approx(-45.0)
    velocity, angle = fl
    assert velocity == fl.velocity and type(angle) is Rotation2d and angle == fl.angle
    a, b = SwerveModulePosition(1.5, Rotation2d(0.25))
    assert (a, b.getRadians()) == (1.5, pytest.approx(0.25))
    x, y = Translation2d(3.0, 4.0)
    assert (x, y) == (3.0, 4.0)
    m1, m2, m3, m4 = kin.getModules()
    assert fields(m3) == (-0.3, 0.3)


def test_get_modules_is_constructor_order_and_accepts_one_sequence():
    mods = [Translation2d(0.1 * i, -0.2 * i + 1) for i in range(5)]
    k1 = SwerveDriveKinematics(*mods)
    k2 = SwerveDriveKinematics(mods)
    k3 = SwerveDriveKinematics(tuple(mods))
    for k in (k1, k2, k3):
        assert [fields(m) for m in k.getModules()] == [fields(m) for m in mods]
    # The kinematics keeps its own copy of the layout.
    mods.append(Translation2d(9.0, 9.0))
    assert len(k2.getModules()) == 5
