"""Property tests for drivekin.mecanum and drivekin.differential: identities that hold for
any layout and input, checked against independent numpy / plain-Python formulas rather
than against drivekin itself.

* Mecanum inverse rows (digest §7.1): for a wheel at r = wheel − CoR,
  FL/RR ``[1, −1, −(rx + ry)]`` and FR/RL ``[1, 1, rx − ry]``. Forward kinematics is the
  least-squares solve of those rows at CoR = 0 (fixed for the life of the object).
* Differential: Road Runner's ``TankKinematics`` (peers.md §1.2), written out below:
  v_L = vx − ω·W/2, v_R = vx + ω·W/2; vx = (v_L + v_R)/2, ω = (v_R − v_L)/W.
"""
from __future__ import annotations

import math

import numpy as np
from hypothesis import assume, example, given
from hypothesis import strategies as st

from tests._support import strategies as S
from drivekin import (
    ChassisVelocities,
    DifferentialDriveKinematics,
    DifferentialDriveWheelPositions,
    DifferentialDriveWheelVelocities,
    MecanumDriveKinematics,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
    Translation2d,
)

EPS = S.EPS

# ---------------------------------------------------------------------------------------
# Mecanum layouts and the independent model


MAX_MECANUM_COND = 1e4


@st.composite
def rectangle_layouts(draw):
    """The usual robot: wheels at (±a, ±b)."""
    dim = st.floats(0.05, 2.0, allow_nan=False)
    a, b = draw(dim), draw(dim)
    return [(a, b), (a, -b), (-a, b), (-a, -b)]


@st.composite
def random_layouts(draw, bound: float = 3.0):
    """Any four wheel positions whose inverse matrix has full column rank (cond ≤ 1e4)."""
    coord = st.floats(-bound, bound, allow_nan=False, allow_subnormal=False)
    pts = draw(st.lists(st.tuples(coord, coord), min_size=4, max_size=4))
    assume(np.linalg.cond(S.mecanum_inverse_matrix(pts)) < MAX_MECANUM_COND)
    return pts


mecanum_layouts = st.one_of(rectangle_layouts(), random_layouts())


def make_mecanum(layout):
    return MecanumDriveKinematics(*[Translation2d(x, y) for x, y in layout])


def wheels_of(w):
    return (w.frontLeft, w.frontRight, w.rearLeft, w.rearRight)


def fk_rel(layout):
    """Relative error allowance of a least-squares solve on this layout."""
    return max(1e-13, 64 * EPS * np.linalg.cond(S.mecanum_inverse_matrix(layout)))


velocity_tuples = S.chassis_tuples(1e2)


# ---------------------------------------------------------------------------------------
# Mecanum


@given(mecanum_layouts, velocity_tuples)
@example([(0.3, 0.25), (0.3, -0.25), (-0.3, 0.25), (-0.3, -0.25)], (0.0, 0.0, 1.0))
@example([(12.0, 12.0), (12.0, -12.0), (-12.0, 12.0), (-12.0, -12.0)], (2.0, 3.0, 1.0))
def test_mecanum_inverse_matches_rows_and_forward_inverse_identity(layout, v):
    kin = make_mecanum(layout)
    w = kin.toWheelVelocities(ChassisVelocities(*v))
    assert type(w) is MecanumDriveWheelVelocities
    expected = S.mecanum_inverse_matrix(layout) @ np.array(v)
    scale = float(np.abs(expected).max(initial=1.0))
    for got, e, name in zip(wheels_of(w), expected, ("fl", "fr", "rl", "rr")):
        S.assert_close(got, float(e), scale, rel=1e-14, what=name)
    back = kin.toChassisVelocities(w)
    assert type(back) is ChassisVelocities
    rel = fk_rel(layout)
    S.assert_close(back.vx, v[0], scale, rel=rel, what="vx")
    S.assert_close(back.vy, v[1], scale, rel=rel, what="vy")
    S.assert_close(back.omega, v[2], scale, rel=rel, what="omega")


@given(mecanum_layouts, st.lists(S.finite_floats(1e2), min_size=4, max_size=4))
def test_mecanum_forward_is_least_squares(layout, wheels):
    """Any four wheel velocities (not necessarily consistent) map to the least-squares
    chassis velocity, and toTwist2d is the same solve on distances."""
    kin = make_mecanum(layout)
    cv = kin.toChassisVelocities(MecanumDriveWheelVelocities(*wheels))
    ref = np.linalg.lstsq(S.mecanum_inverse_matrix(layout), np.array(wheels), rcond=None)[0]
    scale = max(1.0, max(abs(x) for x in wheels))
    for got, e in zip((cv.vx, cv.vy, cv.omega), ref):
        S.assert_close(got, float(e), scale, rel=fk_rel(layout))
    tw = kin.toTwist2d(MecanumDriveWheelPositions(*wheels))
    assert (tw.dx, tw.dy, tw.dtheta) == (cv.vx, cv.vy, cv.omega)
    start = MecanumDriveWheelPositions(1.0, -2.0, 3.0, -4.0)
    end = MecanumDriveWheelPositions(*[s + d for s, d in zip(wheels_of(start), wheels)])
    deltas = MecanumDriveWheelPositions(*[e - s for s, e in zip(wheels_of(start),
                                                                wheels_of(end))])
    tw2 = kin.toTwist2d(start, end)
    tw3 = kin.toTwist2d(deltas)
    assert (tw2.dx, tw2.dy, tw2.dtheta) == (tw3.dx, tw3.dy, tw3.dtheta)


@given(mecanum_layouts, velocity_tuples, S.translation_tuples(2.0))
def test_mecanum_center_of_rotation_only_affects_inverse(layout, v, cor):
    kin, fresh = make_mecanum(layout), make_mecanum(layout)
    vx, vy, w = v
    eff = S.effective_cor(cor)
    wheels = kin.toWheelVelocities(ChassisVelocities(*v), Translation2d(*cor))
    # Inverse: the rows built about the CoR.
    expected = S.mecanum_inverse_matrix(layout, eff) @ np.array(v)
    scale = float(np.abs(expected).max(initial=1.0))
    for got, e in zip(wheels_of(wheels), expected):
        S.assert_close(got, float(e), scale, rel=1e-14)
    # Forward: still solved about the origin, so spinning about c reads back as the
    # origin's velocity v + ω × (0 − c) = (vx + ω·cy, vy − ω·cx, ω).
    back = kin.toChassisVelocities(wheels)
    rel = fk_rel(layout)
    S.assert_close(back.vx, vx + w * eff[1], scale, rel=rel, what="vx")
    S.assert_close(back.vy, vy - w * eff[0], scale, rel=rel, what="vy")
    S.assert_close(back.omega, w, scale, rel=rel, what="omega")
    # The forward matrix is untouched by the CoR: bit-identical to a fresh instance.
    probe = MecanumDriveWheelVelocities(1.5, -0.25, 3.0, 0.125)
    a, b = kin.toChassisVelocities(probe), fresh.toChassisVelocities(probe)
    assert (a.vx, a.vy, a.omega) == (b.vx, b.vy, b.omega)
    pa = kin.toTwist2d(MecanumDriveWheelPositions(*wheels_of(probe)))
    pb = fresh.toTwist2d(MecanumDriveWheelPositions(*wheels_of(probe)))
    assert (pa.dx, pa.dy, pa.dtheta) == (pb.dx, pb.dy, pb.dtheta)


@given(mecanum_layouts, velocity_tuples, S.translation_tuples(2.0))
def test_mecanum_center_of_rotation_is_sticky_until_changed(layout, v, cor):
    """After a call with a CoR, the default-argument call passes the origin again, which
    rebuilds the rows about the origin (unless the CoR was within 1e-9 of it)."""
    kin, fresh = make_mecanum(layout), make_mecanum(layout)
    cv = ChassisVelocities(*v)
    kin.toWheelVelocities(cv, Translation2d(*cor))
    assert wheels_of(kin.toWheelVelocities(cv)) == wheels_of(fresh.toWheelVelocities(cv))
    # Same CoR twice gives the same numbers.
    c = Translation2d(*cor)
    assert (wheels_of(kin.toWheelVelocities(cv, c))
            == wheels_of(kin.toWheelVelocities(cv, Translation2d(*cor))))


# ---------------------------------------------------------------------------------------
# Differential: Road Runner's tank formulas, written out


def rr_tank_inverse(vx, omega, w):
    return vx - omega * w / 2.0, vx + omega * w / 2.0


def rr_tank_forward(vl, vr, w):
    return (vl + vr) / 2.0, 0.0, (vr - vl) / w


trackwidths = st.floats(0.05, 5.0, allow_nan=False)


@given(trackwidths, S.finite_floats(1e2), S.finite_floats(1e2))
@example(0.7, 1.0, 0.0)
@example(0.7, 0.0, 2.0)
def test_differential_forward_inverse_identity(tw, vx, omega):
    kin = DifferentialDriveKinematics(tw)
    w = kin.toWheelVelocities(ChassisVelocities(vx, 0.0, omega))
    assert type(w) is DifferentialDriveWheelVelocities
    back = kin.toChassisVelocities(w)
    assert type(back) is ChassisVelocities
    scale = max(abs(vx), abs(omega) * tw)
    S.assert_close(back.vx, vx, scale, rel=4 * EPS, what="vx")
    assert back.vy == 0.0
    S.assert_close(back.omega, omega, scale / tw, rel=8 * EPS, what="omega")


@given(trackwidths, velocity_tuples)
def test_differential_ignores_vy(tw, v):
    kin = DifferentialDriveKinematics(tw)
    with_vy = kin.toWheelVelocities(ChassisVelocities(*v))
    without = kin.toWheelVelocities(ChassisVelocities(v[0], 0.0, v[2]))
    assert (with_vy.left, with_vy.right) == (without.left, without.right)


@given(trackwidths, velocity_tuples)
def test_differential_inverse_matches_road_runner(tw, v):
    vx, _, omega = v
    w = DifferentialDriveKinematics(tw).toWheelVelocities(ChassisVelocities(*v))
    el, er = rr_tank_inverse(vx, omega, tw)
    scale = max(abs(vx), abs(omega) * tw)
    S.assert_close(w.left, el, scale, rel=2 * EPS, what="left")
    S.assert_close(w.right, er, scale, rel=2 * EPS, what="right")


@given(trackwidths, S.finite_floats(1e2), S.finite_floats(1e2), S.finite_floats(1e2),
       S.finite_floats(1e2))
def test_differential_forward_matches_road_runner(tw, vl, vr, l0, r0):
    kin = DifferentialDriveKinematics(tw)
    evx, evy, ew = rr_tank_forward(vl, vr, tw)
    scale = max(abs(vl), abs(vr))
    cv = kin.toChassisVelocities(DifferentialDriveWheelVelocities(vl, vr))
    S.assert_close(cv.vx, evx, scale, rel=2 * EPS, what="vx")
    assert cv.vy == evy
    S.assert_close(cv.omega, ew, scale / tw, rel=4 * EPS, what="omega")
    # The same formulas on distance increments (both toTwist2d forms).
    tw1 = kin.toTwist2d(vl, vr)
    assert (tw1.dx, tw1.dy, tw1.dtheta) == (cv.vx, cv.vy, cv.omega)
    start = DifferentialDriveWheelPositions(l0, r0)
    end = DifferentialDriveWheelPositions(l0 + vl, r0 + vr)
    tw2 = kin.toTwist2d(start, end)
    ex, _, eth = rr_tank_forward(end.left - start.left, end.right - start.right, tw)
    assert (tw2.dx, tw2.dy, tw2.dtheta) == (ex, 0.0, eth)


# ---------------------------------------------------------------------------------------
# Desaturation (both wheel-velocity classes)

MECANUM_W = st.lists(S.finite_floats(1e2), min_size=4, max_size=4)
DIFF_W = st.lists(S.finite_floats(1e2), min_size=2, max_size=2)
LIMITS = st.one_of(st.just(0.0), st.floats(0.0, 2e2, allow_nan=False))
WHEEL_CASES = st.one_of(
    st.tuples(st.just(MecanumDriveWheelVelocities), MECANUM_W),
    st.tuples(st.just(DifferentialDriveWheelVelocities), DIFF_W),
)


@given(WHEEL_CASES, LIMITS)
@example((MecanumDriveWheelVelocities, [5.0, 6.0, 4.0, 7.0]), 5.5)
@example((DifferentialDriveWheelVelocities, [5.0, 6.0]), 6.0)
@example((DifferentialDriveWheelVelocities, [-8.0, 2.0]), 4.0)
def test_desaturate_invariants(case, limit):
    cls, values = case
    wv = cls(*values)
    before = list(wv)
    out = wv.desaturate(limit)
    assert type(out) is cls
    assert out is not wv
    assert list(wv) == before, "desaturate must not touch its receiver (2027)"
    got = list(out)
    real_max = max(abs(x) for x in values)
    # Never above the limit (exactly: |w| / max ≤ 1 and rounding is monotonic).
    assert max(abs(x) for x in got) <= limit
    if real_max <= limit:
        assert got == values, "within the limit the values are unchanged"
    else:
        # Ratios kept: every wheel scaled by the same limit / max, signs preserved.
        k = limit / real_max
        for g, x in zip(got, values):
            S.assert_close(g, x * k, limit, rel=4 * EPS)
            assert g == 0.0 or math.copysign(1.0, g) == math.copysign(1.0, x)
        # The fastest wheel lands exactly on the limit.
        i = max(range(len(values)), key=lambda j: abs(values[j]))
        assert abs(got[i]) == limit


@given(WHEEL_CASES, LIMITS)
def test_desaturate_in_place_equals_desaturate(case, limit):
    cls, values = case
    expected = list(cls(*values).desaturate(limit))
    wv = cls(*values)
    assert wv.desaturateInPlace(limit) is None
    assert list(wv) == expected


# ---------------------------------------------------------------------------------------
# `...Into` forms are bit-identical to the façade forms


@given(mecanum_layouts, velocity_tuples, st.one_of(st.none(), S.translation_tuples(2.0)))
def test_mecanum_into_forms_equal_facade(layout, v, cor):
    ref, into = make_mecanum(layout), make_mecanum(layout)
    cv = ChassisVelocities(*v)
    # Two calls with the same history so the CoR memory is exercised identically.
    for cvi in (cv, ChassisVelocities(v[2], v[0], v[1])):
        if cor is None:
            expected = ref.toWheelVelocities(cvi)
            out = MecanumDriveWheelVelocities(9.0, 9.0, 9.0, 9.0)
            assert into.toWheelVelocitiesInto(cvi, out) is None
        else:
            expected = ref.toWheelVelocities(cvi, Translation2d(*cor))
            out = MecanumDriveWheelVelocities(9.0, 9.0, 9.0, 9.0)
            assert into.toWheelVelocitiesInto(cvi, out, Translation2d(*cor)) is None
        assert wheels_of(out) == wheels_of(expected)
        fk = ref.toChassisVelocities(expected)
        fk_out = ChassisVelocities(7.0, 8.0, 9.0)
        assert into.toChassisVelocitiesInto(expected, fk_out) is None
        assert (fk_out.vx, fk_out.vy, fk_out.omega) == (fk.vx, fk.vy, fk.omega)


@given(trackwidths, velocity_tuples, DIFF_W)
def test_differential_into_forms_equal_facade(tw, v, wheels):
    kin = DifferentialDriveKinematics(tw)
    cv = ChassisVelocities(*v)
    expected = kin.toWheelVelocities(cv)
    out = DifferentialDriveWheelVelocities(9.0, 9.0)
    assert kin.toWheelVelocitiesInto(cv, out) is None
    assert (out.left, out.right) == (expected.left, expected.right)
    wv = DifferentialDriveWheelVelocities(*wheels)
    fk = kin.toChassisVelocities(wv)
    fk_out = ChassisVelocities(7.0, 8.0, 9.0)
    assert kin.toChassisVelocitiesInto(wv, fk_out) is None
    assert (fk_out.vx, fk_out.vy, fk_out.omega) == (fk.vx, fk.vy, fk.omega)
