"""Differential swerve pods (drivekin.diffswerve): pinned examples, value semantics,
desaturation rules and bad input.

The model: R_A·ω_pod = ω_m1 + ω_m2, R_L·ω_wheel = ω_m1 − ω_m2, ω_wheel = v / r, with R the
motor turns per output turn; a reversed motor 2 reads and takes −ω_m2. Hypothesis
properties (round trips, integration consistency, desaturation invariants) are in
tests/properties/test_diffswerve_properties.py.
"""
from __future__ import annotations

import copy
import math
import pickle

import numpy as np
import pytest

from drivekin import (
    ChassisVelocities,
    DifferentialSwerveModuleKinematics as K,
    DifferentialSwerveModuleVelocities as ModV,
    DifferentialSwerveMotorVelocities as MotV,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Translation2d,
)

# ---------------------------------------------------------------------------------------
# The two pinned examples


def test_quail_docs_example():
    # quail_docs guides/math.md: R_A = 3, R_L = 5, V_A = 2 rad/s, V_L = 10 rad/s -> 28, -22.
    # A 0.5 m wheel makes V_L = 10 rad/s a 5 m/s ground speed (exact in binary).
    k = K(3.0, 5.0, 0.5)
    m = k.toMotorVelocities(5.0, 2.0)
    assert (m.motor1, m.motor2) == (28.0, -22.0)
    back = k.toModuleVelocities(28.0, -22.0)
    assert (back.wheelVelocity, back.azimuthVelocity) == (5.0, 2.0)


def test_quail_docs_example_with_a_real_wheel():
    r = 0.0508                          # a 4 in wheel
    k = K(3.0, 5.0, r)
    m = k.toMotorVelocities(10.0 * r, 2.0)
    assert m.motor1 == pytest.approx(28.0, rel=1e-15)
    assert m.motor2 == pytest.approx(-22.0, rel=1e-15)


def quail_module_angle(p1, p2, r_s):
    """quail's DifferentialSwerveModuleBase.calculateModuleAngle as peers.md §2.1 documents
    it: (p1 + p2) / (2·R_s), R_s = pod turns per motor turn."""
    return (p1 + p2) / (2.0 * r_s)


def test_quail_measured_case_gives_one_radian():
    # peers.md §2.1: R_s = 2, R_d = 3 (output per motor turn) = R_A 0.5, R_L 1/3 here;
    # command ω = 1 rad/s for 1 s, integrate the motor angles, convert back.
    k = K(0.5, 1.0 / 3.0, 0.05)
    p1 = p2 = 0.0
    for _ in range(50):
        m = k.toMotorVelocities(0.0, 1.0)
        p1 += m.motor1 * 0.02
        p2 += m.motor2 * 0.02
    pos = k.toModulePosition(p1, p2)
    assert pos.angle.getRadians() == pytest.approx(1.0, abs=1e-14)
    assert pos.distance == pytest.approx(0.0, abs=1e-15)
    # quail's own formula on the same motor angles: off by 2·R_s² = 8.
    assert quail_module_angle(p1, p2, 2.0) == pytest.approx(0.125, abs=1e-14)


# ---------------------------------------------------------------------------------------
# Model, inverted motor, positions


def test_sum_turns_the_pod_and_difference_spins_the_wheel():
    k = K(4.0, 6.0, 0.05)
    m = k.toMotorVelocities(0.0, 1.5)          # steering only: both motors alike
    assert m.motor1 == m.motor2 == 3.0
    m = k.toMotorVelocities(0.5, 0.0)          # wheel only: opposite motors
    assert m.motor1 == -m.motor2 == pytest.approx(30.0, rel=1e-15)


def test_motor2_inverted_negates_motor2_everywhere():
    a, b = K(3.0, 5.0, 0.05), K(3.0, 5.0, 0.05, motor2_inverted=True)
    ma, mb = a.toMotorVelocities(0.7, -1.3), b.toMotorVelocities(0.7, -1.3)
    assert (mb.motor1, mb.motor2) == (ma.motor1, -ma.motor2)
    va, vb = a.toModuleVelocities(10.0, 4.0), b.toModuleVelocities(10.0, -4.0)
    assert (va.wheelVelocity, va.azimuthVelocity) == (vb.wheelVelocity, vb.azimuthVelocity)
    pa, pb = a.toModulePosition(3.0, 1.0), b.toModulePosition(3.0, -1.0)
    assert pa == pb
    assert b.motor2Inverted and not a.motor2Inverted


def test_position_before_any_reset_is_measured_from_zero():
    k = K(3.0, 5.0, 0.05)
    p = k.toModulePosition(0.0, 0.0)
    assert (p.distance, p.angle.getCos(), p.angle.getSin()) == (0.0, 1.0, 0.0)
    p = k.toModulePosition(1.5, 1.5)           # both motors +1.5 rad: pod +1 rad
    assert p.angle.getRadians() == pytest.approx(1.0, abs=1e-15)
    assert p.distance == 0.0


def test_reset_fixes_the_offset():
    k = K(3.0, 5.0, 0.05)
    k.resetModulePosition(Rotation2d(2.0), 10.0, -4.0)
    p = k.toModulePosition(10.0, -4.0)
    assert p.distance == 0.0 and p == SwerveModulePosition(0.0, Rotation2d(2.0))
    # Wheel only (difference): distance = r·Δ(m1 − m2)/R_L, angle unchanged.
    p = k.toModulePosition(10.0 + 50.0, -4.0 - 50.0)
    assert p.distance == pytest.approx(0.05 * 100.0 / 5.0, rel=1e-15)
    assert p.angle == Rotation2d(2.0)
    # Steering only (sum): 3 motor rad each = 6/3 = 2 rad of pod rotation, no distance.
    p = k.toModulePosition(13.0, -1.0)
    assert p.distance == 0.0
    assert p.angle == Rotation2d(4.0)


def test_reset_again_restarts_the_distance():
    k = K(2.0, 4.0, 0.1)
    k.resetModulePosition(Rotation2d(), 0.0, 0.0)
    assert k.toModulePosition(40.0, -40.0).distance == pytest.approx(2.0, rel=1e-15)
    k.resetModulePosition(Rotation2d(0.5), 40.0, -40.0)
    assert k.toModulePosition(40.0, -40.0) == SwerveModulePosition(0.0, Rotation2d(0.5))


def test_into_forms_match_the_facades():
    k = K(3.5, 6.2, 0.048, motor2_inverted=True)
    k.resetModulePosition(Rotation2d(-1.0), 3.0, 7.0)
    m, v, p = MotV(), ModV(), SwerveModulePosition()
    assert k.toMotorVelocitiesInto(1.2, -0.4, m) is None
    assert m == k.toMotorVelocities(1.2, -0.4)
    assert (m.motor1, m.motor2) == tuple(k.toMotorVelocities(1.2, -0.4))
    k.toModuleVelocitiesInto(80.0, -20.0, v)
    assert tuple(v) == tuple(k.toModuleVelocities(80.0, -20.0))
    k.toModulePositionInto(12.0, -30.0, p)
    q = k.toModulePosition(12.0, -30.0)
    assert (p.distance, p.angle.getCos(), p.angle.getSin()) == \
        (q.distance, q.angle.getCos(), q.angle.getSin())


def test_module_positions_feed_swerve_odometry():
    # Four identical pods driving straight ahead for 1 s at 1 m/s: odometry moves 1 m.
    from drivekin import SwerveDriveOdometry
    k = K(3.0, 5.0, 0.05)
    kin = SwerveDriveKinematics(Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
                                Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))
    odo = SwerveDriveOdometry(kin, Rotation2d(), [k.toModulePosition(0.0, 0.0)] * 4)
    m = k.toMotorVelocities(1.0, 0.0)
    pose = odo.update(Rotation2d(), [k.toModulePosition(m.motor1, m.motor2)] * 4)
    assert pose.getX() == pytest.approx(1.0, abs=1e-12) and abs(pose.getY()) < 1e-12


# ---------------------------------------------------------------------------------------
# Value classes


# The attributes, and the constructor keywords (robotpy 2027's snake_case spelling).
@pytest.mark.parametrize("cls, names, keywords", [
    (MotV, ("motor1", "motor2"), ("motor1", "motor2")),
    (ModV, ("wheelVelocity", "azimuthVelocity"), ("wheel_velocity", "azimuth_velocity"))])
def test_value_class_semantics(cls, names, keywords):
    a = cls(0.1 + 0.2, -1.0 / 3.0)
    assert tuple(a) == (0.30000000000000004, -1.0 / 3.0)
    assert (getattr(a, names[0]), getattr(a, names[1])) == tuple(a)
    assert eval(repr(a), {cls.__name__: cls}) == a
    assert repr(a) == (f"{cls.__name__}({keywords[0]}=0.30000000000000004, "
                       f"{keywords[1]}=-0.3333333333333333)")
    for proto in range(pickle.HIGHEST_PROTOCOL + 1):
        b = pickle.loads(pickle.dumps(a, proto))
        assert type(b) is cls and tuple(b) == tuple(a)
    assert tuple(copy.copy(a)) == tuple(a) and copy.deepcopy(a) is not a
    assert cls() == cls(0.0, 0.0) and cls(**{keywords[0]: 1.0, keywords[1]: 2.0}) == cls(1.0, 2.0)
    assert a == cls(tuple(a)[0] + 5e-10, tuple(a)[1]) and a != cls(tuple(a)[0] + 2e-9, 0.0)
    assert (a == object()) is False and a != (0.3, -1.0 / 3.0)
    with pytest.raises(TypeError):
        hash(a)
    setattr(a, names[0], 4.0)
    setattr(a, names[1], -8.0)
    assert tuple(a) == (4.0, -8.0)
    assert tuple(a + cls(1.0, 1.0)) == (5.0, -7.0) and tuple(a - cls(1.0, 1.0)) == (3.0, -9.0)
    assert tuple(-a) == (-4.0, 8.0) and tuple(a * 0.5) == (2.0, -4.0)
    assert tuple(0.5 * a) == (2.0, -4.0) and tuple(a / 4.0) == (1.0, -2.0)
    assert tuple(a.interpolate(cls(0.0, 0.0), 0.25)) == (3.0, -6.0)
    assert tuple(a.interpolate(cls(0.0, 0.0), 7.0)) == (0.0, 0.0)       # clamped
    with pytest.raises(TypeError, match=cls.__name__):
        a.plus(MotV() if cls is ModV else ModV())
    with pytest.raises(AttributeError):
        delattr(a, names[0])


def test_value_class_str_has_units():
    assert str(MotV(28.0, -22.0)) == \
        "DifferentialSwerveMotorVelocities(Motor 1: 28.00 rad/s, Motor 2: -22.00 rad/s)"
    assert str(ModV(0.125, 2.0)) == \
        "DifferentialSwerveModuleVelocities(Wheel: 0.13 m/s, Azimuth: 2.00 rad/s)"


def test_kinematics_getters_repr_and_pickle_keep_the_offset():
    k = K(3.0, 5.0, 0.0508, motor2_inverted=True)
    assert (k.azimuthGearRatio, k.wheelGearRatio, k.wheelRadius, k.motor2Inverted) == \
        (3.0, 5.0, 0.0508, True)
    assert repr(k) == ("DifferentialSwerveModuleKinematics(azimuth_gear_ratio=3.0, "
                       "wheel_gear_ratio=5.0, wheel_radius=0.0508, motor2_inverted=True)")
    assert eval(repr(k), {"DifferentialSwerveModuleKinematics": K}).motor2Inverted
    k.resetModulePosition(Rotation2d(0.7), 12.5, -3.25)
    for dup in (pickle.loads(pickle.dumps(k, 0)), pickle.loads(pickle.dumps(k, 5)),
                copy.copy(k), copy.deepcopy(k)):
        assert dup is not k and repr(dup) == repr(k)
        for p1, p2 in ((0.0, 0.0), (12.5, -3.25), (100.0, 7.0)):
            a, b = dup.toModulePosition(p1, p2), k.toModulePosition(p1, p2)
            assert (a.distance, a.angle.getCos(), a.angle.getSin()) == \
                (b.distance, b.angle.getCos(), b.angle.getSin())
    for name in ("azimuthGearRatio", "wheelGearRatio", "wheelRadius", "motor2Inverted"):
        with pytest.raises(AttributeError):
            setattr(k, name, 1.0)


# ---------------------------------------------------------------------------------------
# Per-module desaturation

K35 = K(3.0, 5.0, 0.5)          # kv = R_L / r = 10 motor rad per m


def parts(k, m):
    v = k.toModuleVelocities(m.motor1, m.motor2)
    return v.wheelVelocity, v.azimuthVelocity


def test_desaturation_keeps_steering_and_slows_the_wheel():
    m = K35.toMotorVelocities(5.0, 2.0)          # 28, -22
    d = K35.desaturateMotorVelocities(m, 20.0)
    assert (d.motor1, d.motor2) == (20.0, -14.0)
    wheel, steer = parts(K35, d)
    assert steer == 2.0 and wheel == pytest.approx(3.4, rel=1e-15)
    assert (m.motor1, m.motor2) == (28.0, -22.0)          # input untouched


def test_desaturation_cuts_steering_only_when_it_alone_is_too_much():
    m = K35.toMotorVelocities(1.0, 10.0)         # steering part 15 rad/s per motor
    d = K35.desaturateMotorVelocities(m, 12.0)
    assert (d.motor1, d.motor2) == (12.0, 12.0)   # wheel stopped, steering at the limit
    assert parts(K35, d) == (0.0, 8.0)
    d = K35.desaturateMotorVelocities(K35.toMotorVelocities(1.0, -10.0), 12.0)
    assert (d.motor1, d.motor2) == (-12.0, -12.0)


def test_desaturation_with_inverted_motor2_keeps_steering():
    k = K(3.0, 5.0, 0.5, motor2_inverted=True)
    m = k.toMotorVelocities(5.0, 2.0)            # 28, +22 as the reversed motor reads it
    assert (m.motor1, m.motor2) == (28.0, 22.0)
    d = k.desaturateMotorVelocities(m, 20.0)
    assert (d.motor1, d.motor2) == (20.0, 14.0)
    assert parts(k, d)[1] == 2.0


def test_proportional_desaturation_keeps_the_ratio():
    m = MotV(28.0, -22.0)
    d = K35.desaturateMotorVelocities(m, 20.0, proportional=True)
    assert d.motor1 == 20.0 and d.motor2 == pytest.approx(-22.0 * 20.0 / 28.0, rel=1e-15)
    wheel, steer = parts(K35, d)
    assert wheel == pytest.approx(5.0 * 20 / 28, rel=1e-15)
    assert steer == pytest.approx(2.0 * 20 / 28, rel=1e-15)


@pytest.mark.parametrize("proportional", [False, True])
def test_desaturation_edge_limits(proportional):
    kw = {"proportional": proportional}
    m = MotV(28.0, -22.0)
    assert tuple(K35.desaturateMotorVelocities(m, 28.0, **kw)) == (28.0, -22.0)
    assert tuple(K35.desaturateMotorVelocities(m, math.inf, **kw)) == (28.0, -22.0)
    assert tuple(K35.desaturateMotorVelocities(m, 0.0, **kw)) in ((0.0, 0.0), (0.0, -0.0))
    nan = K35.desaturateMotorVelocities(MotV(math.nan, 50.0), 1.0, **kw)
    assert math.isnan(nan.motor1) and nan.motor2 == 50.0           # NaN: unchanged
    for bad in (-1.0, math.nan, -math.inf):
        with pytest.raises(ValueError, match="max_motor_velocity"):
            K35.desaturateMotorVelocities(m, bad, **kw)
        with pytest.raises(ValueError, match="max_motor_velocity"):
            K35.desaturateMotorVelocitiesInPlace(m, bad, **kw)
    assert tuple(m) == (28.0, -22.0)


@pytest.mark.parametrize("proportional", [False, True])
def test_in_place_desaturation_matches(proportional):
    for m in (MotV(28.0, -22.0), MotV(-3.0, 40.0), MotV(1.0, 2.0), MotV(90.0, 80.0)):
        want = K35.desaturateMotorVelocities(m, 20.0, proportional=proportional)
        assert K35.desaturateMotorVelocitiesInPlace(m, 20.0, proportional=proportional) is None
        assert tuple(m) == tuple(want)


def test_proportional_must_be_a_bool():
    for bad in (1, "yes", None, np.bool_(True)):
        with pytest.raises(TypeError, match="proportional must be a bool"):
            K35.desaturateMotorVelocities(MotV(), 1.0, proportional=bad)
    with pytest.raises(TypeError):
        K35.desaturateMotorVelocities(MotV(), 1.0, True)            # keyword-only


# ---------------------------------------------------------------------------------------
# Drive-level desaturation

LAYOUT = [Translation2d(0.3, 0.3), Translation2d(0.3, -0.3), Translation2d(-0.3, 0.3),
          Translation2d(-0.3, -0.3)]


def targets(cv=ChassisVelocities(3.0, 1.0, 2.0)):
    return list(SwerveDriveKinematics(*LAYOUT).toSwerveModuleVelocities(cv))


def max_motor(k, states, rates):
    return max(abs(x) for s, w in zip(states, rates)
               for x in k.toMotorVelocities(s.velocity, w))


def test_drive_level_scales_every_wheel_alike():
    k = K(3.0, 5.0, 0.05)                        # 100 motor rad/s per m/s of wheel speed
    states = targets()
    before = [(s.velocity, s.angle) for s in states]
    rates = [1.0, -2.0, 4.0, 0.5]
    factor = k.desaturateModuleVelocitiesInPlace(states, rates, 150.0)
    assert 0.5 < factor < 1.0
    for s, (v, a) in zip(states, before):
        assert s.velocity == v * factor and s.angle == a
    assert max_motor(k, states, rates) == pytest.approx(150.0, rel=1e-15)
    # The chassis keeps its direction of travel and its centre of rotation.
    fk = SwerveDriveKinematics(*LAYOUT).toChassisVelocities(states)
    assert (fk.vx, fk.vy, fk.omega) == pytest.approx((3.0 * factor, 1.0 * factor,
                                                      2.0 * factor), rel=1e-12)


def test_drive_level_array_forms_agree_with_objects():
    k = K(3.0, 5.0, 0.05, motor2_inverted=True)
    rates = [1.0, -2.0, 4.0, 0.5]
    states = targets()
    arr = np.array([[s.velocity, s.angle.getRadians()] for s in states])
    want = k.desaturateModuleVelocitiesInPlace(states, rates, 150.0)
    assert want < 1.0
    for r in (rates, tuple(rates), np.array(rates), (x for x in rates)):
        a = arr.copy()
        assert k.desaturateModuleVelocitiesInPlace(a, r, 150.0) == want
        assert list(a[:, 0]) == [s.velocity for s in states]
        assert list(a[:, 1]) == list(arr[:, 1])
    objs = targets()
    assert k.desaturateModuleVelocitiesInPlace(tuple(objs), np.array(rates), 150.0) == want
    assert [s.velocity for s in objs] == [s.velocity for s in states]


def test_drive_level_within_limit_is_untouched():
    k = K(3.0, 5.0, 0.05)
    states = targets()
    v = [s.velocity for s in states]
    assert k.desaturateModuleVelocitiesInPlace(states, [0.0] * 4, 1000.0) == 1.0
    assert [s.velocity for s in states] == v


def test_drive_level_steering_beyond_the_limit_stops_the_wheels():
    k = K(3.0, 5.0, 0.05)
    states = targets()
    assert k.desaturateModuleVelocitiesInPlace(states, [0.0, 0.0, 100.0, 0.0], 120.0) == 0.0
    assert [s.velocity for s in states] == [0.0] * 4


def test_drive_level_nan_disables_scaling():
    k = K(3.0, 5.0, 0.05)
    states = targets()
    v = [s.velocity for s in states]
    assert k.desaturateModuleVelocitiesInPlace(states, [1.0, math.nan, 0.0, 0.0], 1.0) == 1.0
    assert [s.velocity for s in states] == v


def test_drive_level_many_modules_use_the_heap_path():
    k = K(3.0, 5.0, 0.05)
    n = 40
    states = [SwerveModuleVelocity(1.0 + i / n, Rotation2d(0.1 * i)) for i in range(n)]
    rates = [0.5 * math.sin(i) for i in range(n)]
    f = k.desaturateModuleVelocitiesInPlace(states, rates, 80.0)
    assert 0.5 < f < 1.0
    assert max_motor(k, states, rates) == pytest.approx(80.0, rel=1e-15)
    arr = np.array([[1.0 + i / n, 0.1 * i] for i in range(n)])
    assert k.desaturateModuleVelocitiesInPlace(arr, np.array(rates), 80.0) == f


def test_drive_level_bad_input_changes_nothing():
    k = K(3.0, 5.0, 0.05)
    states = targets()
    snapshot = [(s.velocity, s.angle) for s in states]
    arr = np.array([[4.0, 0.0]] * 4)
    cases = [
        ((states, [1.0] * 3, 100.0), ValueError, "one per module"),
        ((states[:3], [1.0] * 4, 100.0), ValueError, "one per module"),
        ((states, [1.0, None, 1.0, 1.0], 100.0), TypeError, r"azimuth_velocities\[1\]"),
        ((states, [1.0, "2", 1.0, 1.0], 100.0), TypeError, r"azimuth_velocities\[1\]"),
        ((states, "abcd", 100.0), TypeError, "azimuth_velocities"),
        ((states, 1.0, 100.0), TypeError, "azimuth_velocities"),
        ((states, np.ones(4, np.float32), 100.0), TypeError, "float64"),
        ((states, np.ones((4, 1)), 100.0), ValueError, "shape"),
        ((states, memoryview(np.ones(4)), 100.0), TypeError, "azimuth_velocities"),
        ((states[:3] + [None], [1.0] * 4, 100.0), TypeError, r"module_velocities\[3\]"),
        ((states[:3] + [SwerveModulePosition()], [1.0] * 4, 100.0), TypeError,
         "SwerveModuleVelocity"),
        ((None, [1.0] * 4, 100.0), TypeError, "module_velocities"),
        ((arr.astype(np.float32), [1.0] * 4, 100.0), TypeError, "float64"),
        ((arr[:3], [1.0] * 4, 100.0), ValueError, "one per module"),
        ((np.asfortranarray(np.ones((4, 2))), [1.0] * 4, 100.0), ValueError, "contiguous"),
        ((states, [1.0] * 4, -1.0), ValueError, "max_motor_velocity"),
        ((states, [1.0] * 4, math.nan), ValueError, "max_motor_velocity"),
    ]
    ro = np.ones((4, 2))
    ro.flags.writeable = False
    cases.append(((ro, [1.0] * 4, 0.5), ValueError, "writeable"))
    for args, exc, match in cases:
        with pytest.raises(exc, match=match):
            k.desaturateModuleVelocitiesInPlace(*args)
        assert [(s.velocity, s.angle) for s in states] == snapshot
    assert (arr == 4.0).sum() == 4 and (ro == 1.0).all()


def test_drive_level_reading_a_rate_may_not_corrupt_the_modules():
    # __float__ of a steering rate empties the module list: the call either raises
    # cleanly or works on what it read; it never writes half a result.
    k = K(3.0, 5.0, 0.05)
    states = targets()

    class Evil:
        def __float__(self):
            states.clear()
            return 1.0

    with pytest.raises(ValueError, match="one per module"):
        k.desaturateModuleVelocitiesInPlace(states, [1.0, Evil(), 1.0, 1.0], 100.0)

    rates = [1.0, 2.0, 3.0, 4.0]

    class Shrink:
        def __float__(self):
            rates.clear()
            return 1.0

    rates[1] = Shrink()
    with pytest.raises(ValueError, match="changed size"):
        k.desaturateModuleVelocitiesInPlace(targets(), rates, 100.0)


# ---------------------------------------------------------------------------------------
# Construction and bad input


@pytest.mark.parametrize("pos, name", [(0, "azimuth_gear_ratio"), (1, "wheel_gear_ratio"),
                                       (2, "wheel_radius")])
@pytest.mark.parametrize("bad", [0.0, -0.0, -1.0, math.nan, math.inf, -math.inf])
def test_bad_geometry_names_the_argument(pos, name, bad):
    args = [3.0, 5.0, 0.05]
    args[pos] = bad
    with pytest.raises(ValueError, match=name):
        K(*args)


def test_geometry_whose_ratio_per_metre_overflows_is_rejected():
    with pytest.raises(ValueError, match="wheel_gear_ratio / wheel_radius"):
        K(3.0, 1e300, 1e-300)
    with pytest.raises(ValueError, match="wheel_gear_ratio / wheel_radius"):
        K(3.0, 1e-300, 1e300)


def test_wrong_types():
    with pytest.raises(TypeError):
        K("3", 5.0, 0.05)
    with pytest.raises(TypeError):
        K(3.0, None, 0.05)
    with pytest.raises(TypeError, match="motor2_inverted must be a bool"):
        K(3.0, 5.0, 0.05, motor2_inverted=1)
    with pytest.raises(TypeError):
        K(3.0, 5.0, 0.05, True)                  # keyword-only
    k = K(3.0, 5.0, 0.05)
    for call in (lambda: k.toMotorVelocities("1", 2.0),
                 lambda: k.toMotorVelocitiesInto(1.0, 2.0, ModV()),
                 lambda: k.toModuleVelocitiesInto(1.0, 2.0, MotV()),
                 lambda: k.toModulePositionInto(1.0, 2.0, SwerveModuleVelocity()),
                 lambda: k.resetModulePosition(0.5, 1.0, 2.0),
                 lambda: k.desaturateMotorVelocities(ModV(), 1.0),
                 lambda: k.desaturateMotorVelocitiesInPlace(None, 1.0)):
        with pytest.raises(TypeError):
            call()


def test_reset_rejects_non_finite_positions_and_keeps_the_offset():
    k = K(3.0, 5.0, 0.05)
    k.resetModulePosition(Rotation2d(1.0), 2.0, 3.0)
    for bad in ((math.nan, 0.0), (0.0, math.inf)):
        with pytest.raises(ValueError, match="finite"):
            k.resetModulePosition(Rotation2d(-1.0), *bad)
    assert k.toModulePosition(2.0, 3.0) == SwerveModulePosition(0.0, Rotation2d(1.0))


def test_uninitialised_and_reinitialised():
    k = K.__new__(K)
    for call in (lambda: k.toMotorVelocities(1.0, 2.0), lambda: k.toModulePosition(0.0, 0.0),
                 lambda: k.resetModulePosition(Rotation2d(), 0.0, 0.0),
                 lambda: k.desaturateModuleVelocitiesInPlace([], [], 1.0),
                 lambda: k.toModuleVelocitiesInto(1.0, 2.0, ModV())):
        with pytest.raises(RuntimeError, match="__init__ has not completed"):
            call()
    k = K(3.0, 5.0, 0.05)
    with pytest.raises(TypeError, match="already initialised"):
        k.__init__(4.0, 5.0, 0.05)
    assert k.azimuthGearRatio == 3.0


def test_setstate_validates():
    k = K(3.0, 5.0, 0.05)
    k.resetModulePosition(Rotation2d(0.3), 1.0, 2.0)
    for bad, exc in (([Rotation2d(), 0.0, 0.0], TypeError), ((0.5, 0.0, 0.0), TypeError),
                     ((Rotation2d(), 0.0), TypeError), ((Rotation2d(), "1", 0.0), TypeError),
                     ((Rotation2d(), math.nan, 0.0), ValueError)):
        with pytest.raises(exc):
            k.__setstate__(bad)
    assert k.toModulePosition(1.0, 2.0) == SwerveModulePosition(0.0, Rotation2d(0.3))
