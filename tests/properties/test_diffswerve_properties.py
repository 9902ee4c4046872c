"""Hypothesis properties of the differential swerve pod (drivekin.diffswerve).

The oracle is the model itself, solved independently in each test: numpy's 2×2 solve of
``[[1, 1], [1, −1]]·[ω_m1, ω_m2] = [R_A·ω_pod, R_L·v/r]`` for the motors, plain Euler
integration of the commanded wheel speed and steering rate for positions. Tolerances are
rounding bounds derived from the magnitudes involved (EPS = 2⁻⁵² per operation, a few
operations per step), not fixed allowances.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from drivekin import (
    ChassisVelocities,
    DifferentialSwerveModuleKinematics as K,
    DifferentialSwerveMotorVelocities as MotV,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveModuleVelocity,
    Translation2d,
)

EPS = 2.0 ** -52
TINY = 5e-324          # below the normal range rounding is absolute: one subnormal step


def bound(scale, ops=4):
    """Rounding bound of ``ops`` operations on numbers of magnitude ``scale``."""
    return ops * (EPS * abs(scale) + TINY)


# No subnormal inputs: halving one (0.5·x) is itself inexact, which would make the exact
# checks below compare rounding artefacts; no drivetrain turns at 1e-310 rad/s.
ratios = st.floats(0.05, 100.0)
radii = st.floats(0.01, 0.2)
geometry = st.tuples(ratios, ratios, radii, st.booleans())
wheel_speeds = st.floats(-10.0, 10.0, allow_subnormal=False)
steer_rates = st.floats(-50.0, 50.0, allow_subnormal=False)
motors = st.floats(-2000.0, 2000.0, allow_subnormal=False)


def kin(g):
    ra, rl, r, inv = g
    return K(ra, rl, r, motor2_inverted=inv)


def model_motors(g, v, w):
    ra, rl, r, inv = g
    m1, m2 = np.linalg.solve([[1.0, 1.0], [1.0, -1.0]], [ra * w, rl / r * v])
    return m1, (-m2 if inv else m2)


# ---------------------------------------------------------------------------------------
# Forward / inverse


@given(geometry, wheel_speeds, steer_rates)
@example((3.0, 5.0, 0.5, False), 5.0, 2.0)        # quail's docs: motors 28, -22
def test_motor_velocities_match_the_model(g, v, w):
    m = kin(g).toMotorVelocities(v, w)
    want = model_motors(g, v, w)
    scale = abs(g[0] * w) + abs(g[1] / g[2] * v)
    assert abs(m.motor1 - want[0]) <= bound(scale)
    assert abs(m.motor2 - want[1]) <= bound(scale)


@given(geometry, wheel_speeds, steer_rates)
def test_module_velocities_invert_motor_velocities(g, v, w):
    k = kin(g)
    m = k.toMotorVelocities(v, w)
    back = k.toModuleVelocities(m.motor1, m.motor2)
    scale = abs(m.motor1) + abs(m.motor2)
    assert abs(back.wheelVelocity - v) <= bound(scale) / (g[1] / g[2]) + bound(v)
    assert abs(back.azimuthVelocity - w) <= bound(scale) / g[0] + bound(w)


@given(geometry, motors, motors)
def test_motor_velocities_invert_module_velocities(g, m1, m2):
    k = kin(g)
    mod = k.toModuleVelocities(m1, m2)
    again = k.toMotorVelocities(mod.wheelVelocity, mod.azimuthVelocity)
    scale = abs(m1) + abs(m2)
    assert abs(again.motor1 - m1) <= bound(scale)
    assert abs(again.motor2 - m2) <= bound(scale)


@given(geometry, wheel_speeds, steer_rates)
def test_inverting_motor2_only_flips_its_sign(g, v, w):
    ra, rl, r, _ = g
    a, b = K(ra, rl, r), K(ra, rl, r, motor2_inverted=True)
    ma, mb = a.toMotorVelocities(v, w), b.toMotorVelocities(v, w)
    assert (mb.motor1, mb.motor2) == (ma.motor1, -ma.motor2)


# ---------------------------------------------------------------------------------------
# Integrating the velocity map agrees with converting motor positions


commands = st.lists(st.tuples(wheel_speeds, steer_rates, st.floats(0.001, 0.1)),
                    min_size=1, max_size=20)


@given(geometry, commands, st.floats(-math.pi, math.pi), st.floats(-1e3, 1e3),
       st.floats(-1e3, 1e3))
@example((0.5, 1.0 / 3.0, 0.05, False), [(0.0, 1.0, 1.0)], 0.0, 0.0, 0.0)  # peers.md §2.1
def test_integrated_velocities_and_positions_agree(g, steps, angle0, p1, p2):
    k = kin(g)
    k.resetModulePosition(Rotation2d(angle0), p1, p2)
    distance = theta = 0.0
    travel = 0.0                       # Σ(|m1| + |m2|)·dt: what the position sums carry
    for v, w, dt in steps:
        m = k.toMotorVelocities(v, w)
        p1 += m.motor1 * dt
        p2 += m.motor2 * dt
        travel += (abs(m.motor1) + abs(m.motor2)) * dt
        distance += v * dt
        theta += w * dt
    pos = k.toModulePosition(p1, p2)
    # The motor positions carry rounding of their own magnitude (offsets up to 1e3 rad)
    # on every step; the conversion divides by R_L/r and by R_A.
    pos_err = 8 * EPS * (len(steps) + 2) * (abs(p1) + abs(p2) + travel + 1.0)
    assert abs(pos.distance - distance) <= pos_err / (g[1] / g[2]) + 4 * EPS * abs(distance)
    err = math.remainder(pos.angle.getRadians() - (angle0 + theta), 2 * math.pi)
    assert abs(err) <= pos_err / g[0] + 8 * EPS * (abs(angle0) + abs(theta) + 1.0)


def test_quail_position_formula_is_inconsistent_and_drivekins_is_not():
    # peers.md §2.1 in the drivekin convention: R_A = 1/R_s. quail's angle (p1 + p2)/(2 R_s)
    # differs from the integrated steering by 2·R_s² unless R_s² = 1/2.
    for r_s in (0.25, 2.0, 3.0):
        k = K(1.0 / r_s, 1.0, 0.05)
        m = k.toMotorVelocities(0.0, 1.0)               # 1 rad/s for 1 s
        quail = (m.motor1 + m.motor2) / (2.0 * r_s)
        assert quail == pytest.approx(1.0 / (2.0 * r_s ** 2), rel=1e-15)
        assert k.toModulePosition(m.motor1, m.motor2).angle.getRadians() == \
            pytest.approx(1.0, abs=1e-15)


# ---------------------------------------------------------------------------------------
# Per-module desaturation

limits = st.floats(0.0, 3000.0, allow_subnormal=False)


def split(g, m1, m2):
    """(steering part a, wheel part b) in motor rad/s: ω1 = a + b, ω2 = a − b."""
    w2 = -m2 if g[3] else m2
    return 0.5 * m1 + 0.5 * w2, 0.5 * m1 - 0.5 * w2


@given(geometry, motors, motors, limits)
@example((3.0, 5.0, 0.5, False), 28.0, -22.0, 20.0)
def test_steering_first_desaturation(g, m1, m2, limit):
    k = kin(g)
    d = k.desaturateMotorVelocities(MotV(m1, m2), limit)
    assert abs(d.motor1) <= limit and abs(d.motor2) <= limit          # exactly
    if max(abs(m1), abs(m2)) <= limit:
        assert (d.motor1, d.motor2) == (m1, m2)
        return
    a, b = split(g, m1, m2)
    a2, b2 = split(g, d.motor1, d.motor2)
    tol = bound(abs(m1) + abs(m2))
    # The fastest motor ends on the limit: the wheel is slowed no more than needed.
    assert max(abs(d.motor1), abs(d.motor2)) >= limit - tol
    if abs(a) < limit:
        assert abs(a2 - a) <= tol                         # steering rate kept
        assert abs(b2) <= abs(b) + tol and b2 * b >= 0.0  # wheel slowed, same direction
    else:
        assert a2 == math.copysign(limit, a) and b2 == 0.0


@given(geometry, motors, motors, limits)
def test_proportional_desaturation(g, m1, m2, limit):
    d = kin(g).desaturateMotorVelocities(MotV(m1, m2), limit, proportional=True)
    assert abs(d.motor1) <= limit and abs(d.motor2) <= limit
    peak = max(abs(m1), abs(m2))
    if peak <= limit:
        assert (d.motor1, d.motor2) == (m1, m2)
        return
    assert max(abs(d.motor1), abs(d.motor2)) == limit
    # The ratio is kept: m1'·m2 = m2'·m1 up to rounding.
    assert abs(d.motor1 * m2 - d.motor2 * m1) <= bound(limit * peak) + bound(peak)


@given(geometry, motors, motors, limits, st.booleans())
def test_desaturation_is_idempotent_and_in_place_agrees(g, m1, m2, limit, proportional):
    k = kin(g)
    once = k.desaturateMotorVelocities(MotV(m1, m2), limit, proportional=proportional)
    twice = k.desaturateMotorVelocities(once, limit, proportional=proportional)
    assert tuple(twice) == tuple(once)
    m = MotV(m1, m2)
    k.desaturateMotorVelocitiesInPlace(m, limit, proportional=proportional)
    assert tuple(m) == tuple(once)


# ---------------------------------------------------------------------------------------
# Drive level

@st.composite
def drives(draw):
    n = draw(st.integers(2, 8))
    layout = [Translation2d(draw(st.floats(-0.5, 0.5)), draw(st.floats(-0.5, 0.5)))
              for _ in range(n)]
    cv = ChassisVelocities(draw(st.floats(-5, 5)), draw(st.floats(-5, 5)),
                           draw(st.floats(-10, 10)))
    rates = [draw(st.floats(-20.0, 20.0)) for _ in range(n)]
    return layout, cv, rates


@given(geometry, drives(), st.floats(1.0, 2000.0))
def test_drive_level_common_factor(g, drive, limit):
    layout, cv, rates = drive
    k = kin(g)
    try:
        kin_drive = SwerveDriveKinematics(layout)
    except ValueError:          # coincident modules
        return
    states = list(kin_drive.toSwerveModuleVelocities(cv))
    before = [(s.velocity, s.angle) for s in states]
    factor = k.desaturateModuleVelocitiesInPlace(states, rates, limit)
    assert 0.0 <= factor <= 1.0
    for s, (v, a) in zip(states, before):
        assert s.velocity == v * factor and s.angle == a  # one factor, angles untouched
    steer = [0.5 * g[0] * abs(w) for w in rates]
    wheel = [0.5 * g[1] / g[2] * abs(s.velocity) for s in states]
    tol = bound(limit + max(steer), 8)
    peaks = [a + b for a, b in zip(steer, wheel)]
    if factor == 0.0 and any(v != 0.0 for v, _ in before):
        assert max(steer) >= limit                         # only steering forces a stop
    elif factor < 1.0:
        assert max(peaks) >= limit - tol                   # the tightest pod is at the limit
    if max(steer) < limit:
        assert max(peaks) <= limit + tol                   # and none exceeds it
        for s, w in zip(states, rates):
            m = k.toMotorVelocities(s.velocity, w)
            assert abs(m.motor1) <= limit + tol and abs(m.motor2) <= limit + tol
    # The chassis keeps its direction of travel: forward kinematics scales by the factor.
    if factor > 0.0:
        fk = kin_drive.toChassisVelocities(states)
        ref = kin_drive.toChassisVelocities([SwerveModuleVelocity(v, a) for v, a in before])
        for x, y in ((fk.vx, ref.vx), (fk.vy, ref.vy), (fk.omega, ref.omega)):
            assert abs(x - factor * y) <= 1e-12 * (abs(ref.vx) + abs(ref.vy)
                                                   + abs(ref.omega) + 1.0)


@given(geometry, drives(), st.floats(1.0, 2000.0))
def test_drive_level_array_form_agrees(g, drive, limit):
    layout, cv, rates = drive
    k = kin(g)
    try:
        states = list(SwerveDriveKinematics(layout).toSwerveModuleVelocities(cv))
    except ValueError:
        return
    arr = np.array([[s.velocity, s.angle.getRadians()] for s in states])
    f_arr = k.desaturateModuleVelocitiesInPlace(arr, np.array(rates), limit)
    f_obj = k.desaturateModuleVelocitiesInPlace(states, rates, limit)
    assert f_arr == f_obj
    assert list(arr[:, 0]) == [s.velocity for s in states]
