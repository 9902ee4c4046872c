"""Property tests for drivekin's dead-wheel classes (DeadWheelKinematics, DeadWheelOdometry,
TwoDeadWheelOdometry), checked against independent numpy / plain-Python models.

Model (reference §1): a wheel at (x, y) rolling along φ reads
d = cos φ·(dx − y·dθ) + sin φ·(dy + x·dθ), i.e. d = M·t with M's rows
(cos φ, sin φ, x·sin φ − y·cos φ) = [A | c]. The models below build M from the layout's raw
numbers with ``math.cos``/``math.sin`` and solve with ``numpy.linalg.lstsq``; drivekin builds
its pseudo-inverses once at construction, so the two agree to rounding, not bit for bit.

Layouts and tolerances
----------------------
Random layouts have 2..8 wheels anywhere within ±1 m, rolling in any direction (with the
common 0°, ±90°, 180°, 45° mixed in), sometimes clustered far from the centre. A layout is
kept only if the matrix the test solves with (A for a gyro solve, M without) has a 2-norm
condition number κ < ``MAX_COND`` = 1e6. Why that bound:

* beyond it the layout itself turns encoder noise into pose errors a million times larger,
  which no real robot has (FTC/FRC layouts are κ ≈ 1..30);
* it keeps every tolerance below ~1.5e-8 relative, still 10⁷ times smaller than the O(1)
  error of any formula mistake (a wrong sign, a dropped lever arm, (v1 + v2)/2);
* drivekin refuses layouts only when a singular value of the column-scaled M falls below
  1e-8 of the largest; column scaling to unit length worsens κ by at most √3 (van der
  Sluis), so every layout kept here is one drivekin must accept (asserted).

Every solution is compared within a first-order rounding bound of a pseudo-inverse solve
(Higham, *Accuracy and Stability of Numerical Algorithms*, §20.1), with ε = 2⁻⁵² and
K = 64 covering the constants and n ≤ 8 terms per dot product:

* consistent readings (forward∘inverse, zero residual):
  K·ε·(κ·‖t‖ + ‖d‖/σ_min), i.e. the error of (M + E)⁺ for ‖E‖ ≤ ε‖M‖ applied to M·t, plus
  the rounding of d and of the product;
* least squares (residual r = d − M·t ≠ 0): that plus K·ε·κ²·‖r‖/σ_max (the κ² term of
  the least-squares perturbation bound);
* with a gyro the same with A in place of M, t = (dx, dy) and d replaced by d − c·dθ, plus
  K·ε·‖c‖·|dθ|/σ_min(A) for the lever-arm product drivekin folds into A⁺c.

Norms mix metres and radians on purpose: the bound is in the 2-norm of t = (dx, dy, dθ),
which is the norm κ(M) refers to.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st
from hypothesis.stateful import initialize

from tests._support import strategies as S
from tests.properties import test_odometry_state_machine as base
from drivekin import (
    ChassisAccelerations,
    ChassisVelocities,
    DeadWheelKinematics,
    DeadWheelOdometry,
    Pose2d,
    Rotation2d,
    TwoDeadWheelOdometry,
)

EPS = S.EPS
K = 64.0
# Absolute rounding of an operation whose result is subnormal (the relative bounds alone
# would demand exactness there).
ETA = K * 5e-324
TAU = 2.0 * math.pi
IN_TO_M = 0.0254
MAX_COND = 1e6

# ---------------------------------------------------------------------------------------
# The independent model


def model_matrix(layout) -> np.ndarray:
    """M (N × 3) for a layout given as (x, y, φ) triples."""
    return np.array([[math.cos(p), math.sin(p), x * math.sin(p) - y * math.cos(p)]
                     for x, y, p in layout])


def readings_of(layout, t) -> list[float]:
    """The wheel readings for the chassis vector t = (x, y, θ-component), wheel by wheel,
    written out from the model (not via M, so it is independent of model_matrix too)."""
    vx, vy, w = t
    return [math.cos(p) * (vx - y * w) + math.sin(p) * (vy + x * w) for x, y, p in layout]


def svals(m) -> np.ndarray:
    return np.linalg.svd(m, compute_uv=False)


def cond(m) -> float:
    """κ₂ of a tall matrix; a wide one (fewer wheels than unknowns) is rank deficient."""
    if m.shape[0] < m.shape[1]:
        return math.inf
    s = svals(m)
    # Python floats: a huge ratio is inf, not a numpy overflow warning.
    return math.inf if s[-1] == 0.0 else float(s[0]) / float(s[-1])


def norm(v) -> float:
    return float(np.linalg.norm(np.asarray(v, dtype=float)))


def solve_tol(m, t, d, residual=0.0) -> float:
    """The K·ε bound described in the module docstring, for ``m`` (M or A)."""
    s = svals(m)
    kappa = s[0] / s[-1]
    return (K * EPS * (kappa * norm(t) + norm(d) / s[-1] + kappa * kappa * residual / s[0])
            + ETA / s[-1])


def gyro_tol(layout, t2, d, w, residual=0.0) -> float:
    m = model_matrix(layout)
    a, c = m[:, :2], m[:, 2]
    return (solve_tol(a, t2, np.asarray(d) - c * w, residual)
            + K * EPS * norm(c) * abs(w) / svals(a)[-1])


def model_solve(layout, d, w=None):
    """Least squares (dx, dy, dθ) from numpy: all three from the wheels, or with dθ = w
    fixed and (dx, dy) fitted to d − c·w. Also returns the residual vector."""
    m = model_matrix(layout)
    d = np.asarray(d, dtype=float)
    if w is None:
        t = np.linalg.lstsq(m, d, rcond=None)[0]
        return (float(t[0]), float(t[1]), float(t[2])), d - m @ t
    rhs = d - m[:, 2] * w
    t2 = np.linalg.lstsq(m[:, :2], rhs, rcond=None)[0]
    return (float(t2[0]), float(t2[1]), float(w)), rhs - m[:, :2] @ t2


def make_kin(layout) -> DeadWheelKinematics:
    return DeadWheelKinematics([Pose2d(x, y, Rotation2d(p)) for x, y, p in layout])


def chassis(v) -> tuple[float, float, float]:
    if isinstance(v, ChassisAccelerations):
        return (v.ax, v.ay, v.alpha)
    if isinstance(v, ChassisVelocities):
        return (v.vx, v.vy, v.omega)
    return (v.dx, v.dy, v.dtheta)                          # Twist2d


def assert_vec_close(got, exp, bound, what):
    err = norm(np.subtract(got, exp))
    assert err <= bound, f"{what}: {got!r} vs {exp!r} (‖err‖ {err:.3g} > {bound:.3g})"


# ---------------------------------------------------------------------------------------
# Strategies

COMMON_ANGLES = (0.0, math.pi / 2, -math.pi / 2, math.pi, math.pi / 4)
COMMON_POINTS = ((0.0, 0.18), (0.0, -0.18), (-0.1, 0.0), (0.15, 0.15), (-0.2, -0.05))
# Known layouts (x, y, φ): Road Runner's standard three wheels (inches → m), Pinpoint's
# two pods, and the §3.2 asymmetric counter-example to the draft's (v1 + v2)/2.
NAMED_LAYOUTS = (
    ((2.6 * IN_TO_M, 7.1 * IN_TO_M, 0.0), (2.6 * IN_TO_M, -7.1 * IN_TO_M, 0.0),
     (-3.75 * IN_TO_M, -0.15 * IN_TO_M, math.pi / 2)),
    ((0.0, 0.3, 0.0), (0.0, -0.1, 0.0), (0.2, 0.0, math.pi / 2)),
    ((0.0, 0.2, 0.0), (0.0, -0.2, 0.0), (0.1, 0.0, math.pi / 2), (-0.1, 0.0, math.pi / 2)),
    ((0.0, 0.1, 0.0), (-0.15, 0.0, math.pi / 2)),
)


@st.composite
def layouts(draw, gyro: bool, min_wheels: int = 2, max_wheels: int = 8,
            bound: float = 1.0, max_cond: float = MAX_COND):
    """An observable layout: a tuple of (x m, y m, φ rad) per wheel.

    ``gyro=True``: (dx, dy) observable (κ(A) < max_cond); ``gyro=False``: (dx, dy, dθ)
    observable (κ(M) < max_cond, hence N ≥ 3)."""
    min_wheels = max(min_wheels, 2 if gyro else 3)
    named = [lay for lay in NAMED_LAYOUTS if min_wheels <= len(lay) <= max_wheels]
    if named and draw(st.integers(0, 5)) == 0:
        layout = draw(st.sampled_from(named))
    else:
        n = draw(st.integers(min_wheels, max_wheels))
        coord = st.floats(-bound, bound, allow_nan=False, allow_subnormal=False)
        point = st.one_of(st.sampled_from(COMMON_POINTS), st.tuples(coord, coord))
        angle = st.one_of(st.sampled_from(COMMON_ANGLES),
                          st.floats(-math.pi, math.pi, allow_nan=False))
        layout = [(*draw(point), draw(angle)) for _ in range(n)]
        if draw(st.integers(0, 4)) == 0:
            # Clustered far from the centre: long, nearly equal lever arms (poorly
            # conditioned but observable).
            k = draw(st.sampled_from([0.1, 0.03]))
            cx, cy = draw(coord), draw(coord)
            layout = [(cx + k * x, cy + k * y, p) for x, y, p in layout]
        layout = tuple(layout)
    m = model_matrix(layout)
    assume(cond(m[:, :2] if gyro else m) < max_cond)
    return layout


def readings(n, bound=10.0):
    return st.lists(S.finite_floats(bound, allow_subnormal=False), min_size=n, max_size=n)


CHASSIS = S.chassis_tuples(1e2)
GYRO_VALUES = st.one_of(st.just(0.0), S.finite_floats(1e2, allow_subnormal=False))

# ---------------------------------------------------------------------------------------
# Construction accepts every layout the strategy produces


@given(layouts(gyro=True))
def test_observable_layouts_are_accepted(layout):
    kin = make_kin(layout)
    m = model_matrix(layout)
    # The wheels observe rotation iff M has rank 3. Compare only where the answer is
    # clear-cut: κ(M) < MAX_COND (drivekin's column-scaled test then passes, see the
    # module docstring), or a column-scaled κ beyond 1e12 (far past drivekin's 1e8), or
    # no lever arm at all.
    cols = np.linalg.norm(m, axis=0)
    if len(layout) < 3 or cols[2] == 0.0:
        assert kin.requiresGyro() is True
    elif cond(m) < MAX_COND:
        assert kin.requiresGyro() is False
    elif cond(m / cols) > 1e12:
        assert kin.requiresGyro() is True
    assert [(p.getX(), p.getY()) for p in kin.getWheelPoses()] == [(x, y) for x, y, _ in layout]


@st.composite
def concurrent_layouts(draw, point):
    """3..8 wheels whose lines (through the contact point, along the rolling direction)
    all pass through ``point``: a spin about it moves no wheel (reference §1.2). Each
    wheel rolls towards or away from the point, written the way a user would: degrees
    through Rotation2d.fromDegrees."""
    n = draw(st.integers(3, 8))
    px, py = point
    wheels = []
    for _ in range(n):
        r = draw(st.floats(0.05, 0.5))
        deg = draw(st.one_of(st.sampled_from([0.0, 90.0, 180.0, -90.0, 45.0, 135.0]),
                             st.floats(-180.0, 180.0)))
        x = px + r * math.cos(math.radians(deg))
        y = py + r * math.sin(math.radians(deg))
        wheels.append((x, y, deg + draw(st.sampled_from([0.0, 180.0]))))
    # Two non-parallel wheels, or even a gyro cannot help (that case has its own error).
    a = np.array([[math.cos(math.radians(d)), math.sin(math.radians(d))] for _, _, d in wheels])
    assume(cond(a) < MAX_COND)
    return wheels


def kin_from_degrees(wheels):
    return DeadWheelKinematics([Pose2d(x, y, Rotation2d.fromDegrees(d)) for x, y, d in wheels])


def assert_needs_gyro(wheels):
    kin = kin_from_degrees(wheels)
    assert kin.requiresGyro() is True, f"{wheels}: rotation reported observable"
    with pytest.raises(ValueError, match="needs a gyro"):
        kin.toChassisVelocities([0.0] * len(wheels))
    with pytest.raises(ValueError, match="needs a gyro"):
        DeadWheelOdometry(kin, [0.0] * len(wheels))


@given(st.data(), st.tuples(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0))
       .filter(lambda p: math.hypot(*p) >= 1e-3))
def test_concurrent_wheel_lines_need_a_gyro(data, point):
    assert_needs_gyro(data.draw(concurrent_layouts(point)))


def test_radial_wheels_need_a_gyro():
    # Reference §1.2's example of a singular layout: three wheels rolling radially.
    wheels = [(0.0, 0.2, 90.0), (0.2, 0.0, 0.0), (-0.2, 0.0, 180.0)]
    kin = kin_from_degrees(wheels)
    spin = kin.toWheelVelocities(ChassisVelocities(0.0, 0.0, 1.0))
    assert max(map(abs, spin)) < 1e-15          # the wheels cannot see a spin
    assert_needs_gyro(wheels)


@given(st.data())
def test_wheel_lines_through_the_centre_need_a_gyro(data):
    assert_needs_gyro(data.draw(concurrent_layouts((0.0, 0.0))))


# ---------------------------------------------------------------------------------------
# Inverse maps against the formula, and forward∘inverse = identity


@given(layouts(gyro=True), CHASSIS)
def test_inverse_matches_model(layout, v):
    kin = make_kin(layout)
    got = kin.toWheelVelocities(ChassisVelocities(*v))
    assert type(got) is tuple and len(got) == len(layout)
    assert all(type(g) is float for g in got)
    exp = readings_of(layout, v)
    for i, ((x, y, _), g, e) in enumerate(zip(layout, got, exp)):
        # A few roundings of each term; cos/sin of Rotation2d(φ) may differ by an ulp.
        scale = abs(v[0]) + abs(v[1]) + abs(v[2]) * (abs(x) + abs(y))
        assert abs(g - e) <= 8 * EPS * scale + ETA, f"wheel {i}: {g!r} vs {e!r}"
    acc = kin.toWheelAccelerations(ChassisAccelerations(*v))
    assert acc == got                          # the same matrix, the same arithmetic
    out = np.full(len(layout), np.nan)
    assert kin.toWheelVelocitiesInto(ChassisVelocities(*v), out) is None
    assert tuple(out.tolist()) == got


@given(layouts(gyro=False), CHASSIS)
@example(NAMED_LAYOUTS[1], (1.0, 0.0, 1.0))        # §3.2: the draft's (v1 + v2)/2 gives 0.9
def test_forward_inverse_identity_without_gyro(layout, v):
    kin = make_kin(layout)
    m = model_matrix(layout)
    wheels = kin.toWheelVelocities(ChassisVelocities(*v))
    bound = solve_tol(m, v, wheels)
    back = kin.toChassisVelocities(wheels)
    assert type(back) is ChassisVelocities
    assert_vec_close(chassis(back), v, bound, "velocities")
    acc = kin.toChassisAccelerations(kin.toWheelAccelerations(ChassisAccelerations(*v)))
    assert type(acc) is ChassisAccelerations
    assert chassis(acc) == chassis(back)       # the same map on the same numbers
    twist = kin.toTwist2d(wheels)
    assert chassis(twist) == chassis(back)
    out = ChassisVelocities(7.0, 8.0, 9.0)
    assert kin.toChassisVelocitiesInto(wheels, out) is None
    assert chassis(out) == chassis(back)


@given(layouts(gyro=True), CHASSIS)
@example(NAMED_LAYOUTS[3], (1.0, -1.0, 5.0))
def test_forward_inverse_identity_with_gyro(layout, v):
    kin = make_kin(layout)
    wheels = kin.toWheelVelocities(ChassisVelocities(*v))
    bound = gyro_tol(layout, v[:2], wheels, v[2])
    back = kin.toChassisVelocities(wheels, v[2])
    assert back.omega == v[2]                  # the gyro's value, untouched
    assert_vec_close(chassis(back), v, bound, "velocities")
    acc = kin.toChassisAccelerations(kin.toWheelAccelerations(ChassisAccelerations(*v)),
                                     angular_acceleration=v[2])
    assert chassis(acc) == chassis(back)
    twist = kin.toTwist2d(wheels, gyro_delta=v[2])
    assert chassis(twist) == chassis(back)
    out = ChassisVelocities(7.0, 8.0, 9.0)
    kin.toChassisVelocitiesInto(wheels, out, v[2])
    assert chassis(out) == chassis(back)


@given(layouts(gyro=True), CHASSIS)
def test_layouts_needing_a_gyro_refuse_gyro_less_calls(layout, v):
    kin = make_kin(layout)
    assume(kin.requiresGyro())
    wheels = kin.toWheelVelocities(ChassisVelocities(*v))
    for call in (kin.toChassisVelocities, kin.toTwist2d, kin.toChassisAccelerations):
        with pytest.raises(ValueError, match="needs a gyro"):
            call(wheels)
    with pytest.raises(ValueError, match="needs a gyro"):
        DeadWheelOdometry(kin, wheels)


# ---------------------------------------------------------------------------------------
# Least squares against numpy


@given(layouts(gyro=False, min_wheels=4), st.data())
def test_least_squares_without_gyro_matches_lstsq(layout, data):
    kin = make_kin(layout)
    d = data.draw(readings(len(layout)))
    exp, r = model_solve(layout, d)
    m = model_matrix(layout)
    bound = 2 * solve_tol(m, exp, d, norm(r))         # both solves carry the bound
    got = chassis(kin.toChassisVelocities(d))
    assert_vec_close(got, exp, bound, "least squares")
    # The residual of drivekin's solution is orthogonal to M's columns.
    s = svals(m)
    res = np.asarray(d) - m @ np.asarray(got)
    ortho = m.T @ res
    obound = s[0] ** 2 * bound + K * EPS * s[0] * (norm(d) + s[0] * norm(got))
    assert norm(ortho) <= obound, f"Mᵀr = {ortho!r} (bound {obound:.3g})"


@given(layouts(gyro=True, min_wheels=3), st.data(), GYRO_VALUES)
@example(((0.0, 0.3, 0.0), (0.2, 0.0, math.pi / 2), (0.0, -0.1, 0.0)),
         None, 0.1)                                      # §1.1: dx = 1.11, dy = 0.48
def test_least_squares_with_gyro_matches_lstsq(layout, data, w):
    kin = make_kin(layout)
    if data is None:
        d = [1.0, 0.5, 1.2]
    else:
        d = data.draw(readings(len(layout)))
    exp, r = model_solve(layout, d, w)
    bound = 2 * gyro_tol(layout, exp[:2], d, w, norm(r))
    got = chassis(kin.toTwist2d(d, gyro_delta=w))
    assert got[2] == w
    assert_vec_close(got, exp, bound, "least squares with gyro")
    if data is None:
        assert_vec_close(got, (1.11, 0.48, 0.1), 16 * EPS, "reference §1.1 example")
    m = model_matrix(layout)
    a, c = m[:, :2], m[:, 2]
    rhs = np.asarray(d) - c * w
    ortho = a.T @ (rhs - a @ np.asarray(got[:2]))
    s = svals(a)
    obound = s[0] ** 2 * bound + K * EPS * s[0] * (norm(rhs) + s[0] * norm(got[:2]))
    assert norm(ortho) <= obound, f"Aᵀr = {ortho!r} (bound {obound:.3g})"


def test_least_squares_worked_example_without_gyro():
    # Reference §1.1: orthogonal columns, so each component is a plain projection.
    kin = make_kin(NAMED_LAYOUTS[2])
    got = chassis(kin.toChassisVelocities([1.0, 1.2, 0.3, 0.1]))
    assert_vec_close(got, (1.1, 0.2, 0.6), 4 * EPS, "§1.1 four wheels")
    got = chassis(kin.toChassisVelocities([1.0, 1.2, 0.3, 0.1], 0.5))
    assert_vec_close(got, (1.1, 0.2, 0.5), 4 * EPS, "§1.1 four wheels, gyro")


# ---------------------------------------------------------------------------------------
# Invariances


@given(layouts(gyro=True), st.data(), st.one_of(st.none(), GYRO_VALUES))
def test_reordering_wheels_changes_nothing(layout, data, w):
    kin = make_kin(layout)
    assume(w is not None or cond(model_matrix(layout)) < MAX_COND)
    d = data.draw(readings(len(layout)))
    perm = data.draw(st.permutations(range(len(layout))))
    kin_p = make_kin([layout[i] for i in perm])
    d_p = [d[i] for i in perm]
    exp, r = model_solve(layout, d, w)
    if w is None:
        bound = 2 * solve_tol(model_matrix(layout), exp, d, norm(r))
    else:
        bound = 2 * gyro_tol(layout, exp[:2], d, w, norm(r))
    a = chassis(kin.toChassisVelocities(d, w))
    b = chassis(kin_p.toChassisVelocities(d_p, w))
    assert_vec_close(b, a, bound, "permuted layout")
    assert kin_p.toWheelVelocities(ChassisVelocities(*a)) == tuple(
        kin.toWheelVelocities(ChassisVelocities(*a))[i] for i in perm)


@given(layouts(gyro=True, max_wheels=7), st.data(), st.one_of(st.none(), GYRO_VALUES))
def test_a_consistent_extra_wheel_changes_nothing(layout, data, w):
    """A wheel whose reading agrees with the fitted motion adds a zero-residual row: the
    least-squares solution stays where it was."""
    kin = make_kin(layout)
    assume(w is not None or cond(model_matrix(layout)) < MAX_COND)
    d = data.draw(readings(len(layout)))
    extra = data.draw(st.tuples(S.finite_floats(1.0), S.finite_floats(1.0),
                                st.floats(-math.pi, math.pi, allow_nan=False)))
    t = chassis(kin.toChassisVelocities(d, w))
    grown = layout + (extra,)
    d_grown = d + readings_of([extra], t)
    t_grown = chassis(make_kin(grown).toChassisVelocities(d_grown, w))
    exp, r = model_solve(layout, d, w)
    if w is None:
        bound = (solve_tol(model_matrix(layout), exp, d, norm(r))
                 + solve_tol(model_matrix(grown), exp, d_grown, norm(r)))
    else:
        bound = (gyro_tol(layout, exp[:2], d, w, norm(r))
                 + gyro_tol(grown, exp[:2], d_grown, w, norm(r)))
    assert_vec_close(t_grown, t, 2 * bound, "with a consistent extra wheel")


@given(layouts(gyro=True), st.data(), st.one_of(st.none(), GYRO_VALUES),
       S.finite_floats(1.0), S.finite_floats(1.0), st.floats(-math.pi, math.pi))
def test_moving_the_robot_frame(layout, data, w, ox, oy, alpha):
    """Describing the same wheels from a frame at (ox, oy) rotated by α: every reading is
    unchanged, so the solution must be the old one seen from the new frame,
    v' = R(−α)·(v + ω × o), ω' = ω. Exact for the least-squares fit too: M' = M·T⁻¹ for the
    invertible T of that map, with or without the gyro (T keeps dθ)."""
    kin = make_kin(layout)
    assume(w is not None or cond(model_matrix(layout)) < MAX_COND)
    d = data.draw(readings(len(layout)))
    ca, sa = math.cos(alpha), math.sin(alpha)

    def to_new(x, y):
        return ca * x + sa * y, -sa * x + ca * y

    moved = tuple((*to_new(x - ox, y - oy), p - alpha) for x, y, p in layout)
    m2 = model_matrix(moved)
    assume(cond(m2[:, :2] if w is not None else m2) < MAX_COND)
    vx, vy, om = chassis(kin.toChassisVelocities(d, w))
    exp = (*to_new(vx - om * oy, vy + om * ox), om)
    got = chassis(make_kin(moved).toChassisVelocities(d, w))
    e_old, r = model_solve(layout, d, w)
    e_new, _ = model_solve(moved, d, w)
    if w is None:
        bound = ((1 + math.hypot(ox, oy)) * solve_tol(model_matrix(layout), e_old, d, norm(r))
                 + solve_tol(m2, e_new, d, norm(r)))
    else:
        bound = ((1 + math.hypot(ox, oy)) * gyro_tol(layout, e_old[:2], d, w, norm(r))
                 + gyro_tol(moved, e_new[:2], d, w, norm(r)))
    # The change of frame itself rounds a few times per component.
    bound = 2 * bound + 8 * EPS * (norm((vx, vy)) + abs(om) * math.hypot(ox, oy)) + ETA
    assert_vec_close(got, exp, bound, "moved frame")


# ---------------------------------------------------------------------------------------
# Road Runner 1.0 factories against Road Runner's own formulas


def rr_three_wheel(a0, a1, b, dpar0, dpar1, dperp):
    """Road Runner 1.0's ThreeDeadWheelLocalizer solve, in ticks (reference §1.3)."""
    dth = (dpar0 - dpar1) / (a0 - a1)
    return (a0 * dpar1 - a1 * dpar0) / (a0 - a1), dperp - b * dth, dth


def rr_two_wheel(a, b, dpar, dperp, dth):
    """Road Runner 1.0's TwoDeadWheelLocalizer with the IMU's heading change."""
    return dpar - a * dth, dperp - b * dth


IN_PER_TICK = st.one_of(st.sampled_from([1.0, 0.000528, 0.001978, 1 / 2000]),
                        st.floats(1e-4, 1.0))
OFFSET_IN = st.floats(-12.0, 12.0, allow_nan=False, allow_subnormal=False)  # inches
TICKS = st.one_of(st.just(0.0), st.floats(-1e5, 1e5, allow_nan=False, allow_subnormal=False))


@given(OFFSET_IN, OFFSET_IN, OFFSET_IN, IN_PER_TICK, TICKS, TICKS, TICKS)
@example(-7.1, 7.1, -3.75, 1.0, 0.5, 0.7, 0.1)          # peers.md §1.7 worked example
def test_road_runner_three_wheels(y0_in, y1_in, x_in, in_per_tick, t0, t1, t2):
    a0, a1, b = y0_in / in_per_tick, y1_in / in_per_tick, x_in / in_per_tick
    kin = DeadWheelKinematics.fromRoadRunner(a0, a1, b, in_per_tick)
    k = in_per_tick * IN_TO_M
    layout = [(p.getX(), p.getY(), p.getRotation().getRadians()) for p in kin.getWheelPoses()]
    m = model_matrix(layout)
    assume(cond(m) < MAX_COND)
    # The sign trap: parYTicks is minus the wheel's y.
    assert layout[0][:2] == (0.0, -a0 * k) and layout[1][:2] == (0.0, -a1 * k)
    assert layout[2][:2] == (b * k, 0.0)
    d = [t0 * k, t1 * k, t2 * k]
    dx, dy, dth = rr_three_wheel(a0, a1, b, t0, t1, t2)
    exp = (dx * in_per_tick * IN_TO_M, dy * in_per_tick * IN_TO_M, dth)
    got = chassis(kin.toTwist2d(d))
    # Road Runner's closed form rounds too (its dθ cancels like drivekin's): allow the
    # solve bound for each, plus the unit conversions' few roundings.
    bound = 2 * solve_tol(m, exp, d) + 8 * EPS * norm(exp)
    assert_vec_close(got, exp, bound, "Road Runner three-wheel twist")
    if (y0_in, y1_in, x_in, in_per_tick, t0, t1, t2) == (-7.1, 7.1, -3.75, 1.0, 0.5, 0.7, 0.1):
        assert_vec_close(got, (0.6 * IN_TO_M, (0.1 + 3.75 / 71) * IN_TO_M, 1 / 71), 1e-15,
                         "peers.md §1.7")


@given(OFFSET_IN, OFFSET_IN, IN_PER_TICK, TICKS, TICKS, S.wrapped_angles())
@example(-7.1, -3.75, 1.0, 0.5, 0.1, 0.014)             # reference §1.3, IMU example
def test_road_runner_two_wheels_with_imu(y_in, x_in, in_per_tick, tpar, tperp, dth):
    a, b = y_in / in_per_tick, x_in / in_per_tick
    kin = DeadWheelKinematics.fromRoadRunnerTwoWheel(a, b, in_per_tick)
    assert kin.requiresGyro()
    k = in_per_tick * IN_TO_M
    dx, dy = rr_two_wheel(a, b, tpar, tperp, dth)
    got = chassis(kin.toTwist2d([tpar * k, tperp * k], dth))
    assert got[2] == dth
    exp = (dx * in_per_tick * IN_TO_M, dy * in_per_tick * IN_TO_M)
    for g, e, dpar, lever in ((got[0], exp[0], tpar, a), (got[1], exp[1], tperp, b)):
        # Two products and a difference, each side; A is (nearly) the identity.
        bound = 16 * EPS * (abs(dpar) + abs(lever * dth)) * k + ETA
        assert abs(g - e) <= bound, f"{g!r} vs {e!r} (bound {bound:.3g})"
    if (y_in, x_in, in_per_tick, tpar, tperp, dth) == (-7.1, -3.75, 1.0, 0.5, 0.1, 0.014):
        assert_vec_close(got[:2], (0.5994 * IN_TO_M, 0.1525 * IN_TO_M), 1e-16, "§1.3 IMU")


# ---------------------------------------------------------------------------------------
# Reading forms: list, tuple, arrays of every stride, numpy.float64 items, ints


def reading_forms(d):
    n = len(d)
    arr = np.array(d, dtype=np.float64)
    wide = np.zeros(3 * n)
    wide[::3] = d
    rev = np.array(d[::-1], dtype=np.float64)[::-1]
    col = np.zeros((n, 2))
    col[:, 1] = d
    ro = arr.copy()
    ro.setflags(write=False)
    return {
        "list": list(d), "tuple": tuple(d), "array": arr, "strided": wide[::3],
        "reversed": rev, "column": col[:, 1], "read-only": ro,
        "Fortran column": np.asfortranarray(col)[:, 1],
        "numpy.float64 items": [np.float64(x) for x in d],
        "mixed": [np.float64(x) if i % 2 else x for i, x in enumerate(d)],
    }


@given(layouts(gyro=True), st.data(), st.one_of(st.none(), GYRO_VALUES))
def test_reading_forms_give_identical_results(layout, data, w):
    kin = make_kin(layout)
    assume(w is not None or cond(model_matrix(layout)) < MAX_COND)
    d = data.draw(readings(len(layout)))
    ref_v = chassis(kin.toChassisVelocities(d, w))
    ref_t = chassis(kin.toTwist2d(d, w))
    ref_a = chassis(kin.toChassisAccelerations(d, w))
    start = [0.5 * x for x in d]
    gyro = None if w is None else Rotation2d(0.25)
    gyro2 = None if w is None else Rotation2d(0.25 + (w % 3.0))
    odo_ref = DeadWheelOdometry(kin, start, gyro)
    ref_p = odo_ref.update(d, gyro2)
    forms = reading_forms(d)
    for name, form in forms.items():
        assert chassis(kin.toChassisVelocities(form, w)) == ref_v, name
        assert chassis(kin.toTwist2d(form, w)) == ref_t, name
        assert chassis(kin.toChassisAccelerations(form, w)) == ref_a, name
        out = ChassisVelocities()
        kin.toChassisVelocitiesInto(form, out, w)
        assert chassis(out) == ref_v, name
        odo = DeadWheelOdometry(kin, reading_forms(start)[name], gyro)
        p = odo.update(form, gyro2)
        assert (p.getX(), p.getY(), p.getRotation().getCos(), p.getRotation().getSin()) == (
            ref_p.getX(), ref_p.getY(), ref_p.getRotation().getCos(),
            ref_p.getRotation().getSin()), name
    for name, form in forms.items():           # the inputs were only read
        assert [float(x) for x in form] == d, name


@given(layouts(gyro=True), st.data(), st.one_of(st.none(), GYRO_VALUES))
def test_int_readings_are_their_float_values(layout, data, w):
    kin = make_kin(layout)
    assume(w is not None or cond(model_matrix(layout)) < MAX_COND)
    ints = data.draw(st.lists(st.one_of(st.integers(-10, 10), st.integers(-2 ** 62, 2 ** 62)),
                              min_size=len(layout), max_size=len(layout)))
    as_floats = [float(i) for i in ints]       # the correctly rounded double of each int
    assert (chassis(kin.toChassisVelocities(ints, w))
            == chassis(kin.toChassisVelocities(as_floats, w)))
    assert chassis(kin.toTwist2d(tuple(ints), w)) == chassis(kin.toTwist2d(as_floats, w))


def test_gyro_argument_forms():
    kin = make_kin(NAMED_LAYOUTS[1])
    d = [0.3, -0.2, 0.7]
    ref = chassis(kin.toChassisVelocities(d, 0.5))
    for w in (np.float64(0.5), np.float32(0.5), 0.5, 1 / 2):
        assert chassis(kin.toChassisVelocities(d, w)) == ref, type(w)
    assert chassis(kin.toChassisVelocities(d, 2)) == chassis(kin.toChassisVelocities(d, 2.0))


# ---------------------------------------------------------------------------------------
# Odometry against an independent model: state machines on the shared odometry machine
# (tests/properties/test_odometry_state_machine.py), whose rules drive, turn the gyro
# (also by whole turns, so the raw reading wraps past ±180°), stand still and exercise all
# four resets, and whose invariant compares getPose() with a hand-integrated model within
# 1e-9·(1 + steps)·magnitude. The layouts here are kept to κ < 1e3, so one step's solve
# error (≤ K·ε·κ·‖Δd‖ ≈ 1.4e-11·‖Δd‖) stays well inside that per-step allowance.

MACHINE_COND = 1e3


def draw_form(data, values):
    """The readings in a random accepted form."""
    form = data.draw(st.sampled_from(["list", "tuple", "array", "strided", "numpy.float64 items"]),
                     label="reading form")
    return reading_forms(list(values))[form]


class DeadWheelMachineBase(base.OdometryMachine):
    """Dead-wheel odometry: the model twist needs the gyro change (with a gyro, the
    lever arms move dx, dy), so the step computes all three components itself."""

    def _model_twist3(self, old, new, gyro_change):
        raise NotImplementedError

    def _step(self, new_wheels, new_gyro, data):
        dx, dy, dth = self._model_twist3(self.wheels, new_wheels,
                                         base.wrapped(new_gyro - self.gyro))
        returned = self._update(Rotation2d(new_gyro), new_wheels, data)
        self.x, self.y, self.th = S.compose_exp(self.x, self.y, self.th, dx, dy, dth)
        self.wheels, self.gyro = new_wheels, new_gyro
        self.steps += 1
        self.path += math.hypot(dx, dy)
        self._seen()
        got = self.odo.getPose()
        assert type(returned) is Pose2d
        assert ((returned.getX(), returned.getY(), S.rot_tuple(returned.getRotation()))
                == (got.getX(), got.getY(), S.rot_tuple(got.getRotation())))

    def _draw_absolute(self, data):
        return tuple(data.draw(st.lists(base.ABS_WHEEL, min_size=self.n, max_size=self.n)))

    def _draw_move(self, data):
        steps = data.draw(st.lists(base.STEP, min_size=self.n, max_size=self.n))
        return tuple(d + s for d, s in zip(self.wheels, steps))


class DeadWheelGyroMachine(DeadWheelMachineBase):
    @initialize(layout=layouts(gyro=True, max_cond=MACHINE_COND), data=st.data(),
                gyro=base.GYROS, x=base.COORDS, y=base.COORDS, th=base.HEADINGS)
    def setup(self, layout, data, gyro, x, y, th):
        self.layout, self.n = layout, len(layout)
        kin = make_kin(layout)
        wheels = self._draw_absolute(data)
        self.odo = DeadWheelOdometry(kin, draw_form(data, wheels), Rotation2d(gyro),
                                     base.make_pose(x, y, th))
        self._start(gyro, wheels, (x, y, th))

    def _model_twist3(self, old, new, gyro_change):
        deltas = [b - a for a, b in zip(old, new)]
        return model_solve(self.layout, deltas, gyro_change)[0]

    def _update(self, gyro, wheels, data):
        return self.odo.update(draw_form(data, wheels), gyro)

    def _reset_position(self, gyro, wheels, pose):
        self.odo.resetPosition(list(wheels), gyro, pose)


class DeadWheelNoGyroMachine(DeadWheelMachineBase):
    """Heading from the wheels alone; the machine's gyro rules still run, and the odometry
    must ignore them (it is never given the gyro)."""

    @initialize(layout=layouts(gyro=False, max_cond=MACHINE_COND), data=st.data(),
                x=base.COORDS, y=base.COORDS, th=base.HEADINGS)
    def setup(self, layout, data, x, y, th):
        self.layout, self.n = layout, len(layout)
        kin = make_kin(layout)
        wheels = self._draw_absolute(data)
        self.odo = DeadWheelOdometry(kin, draw_form(data, wheels), None,
                                     base.make_pose(x, y, th))
        self._start(0.0, wheels, (x, y, th))

    def _model_twist3(self, old, new, gyro_change):
        deltas = [b - a for a, b in zip(old, new)]
        return model_solve(self.layout, deltas)[0]

    def _update(self, gyro, wheels, data):
        if data.draw(st.booleans(), label="gyro keyword"):
            return self.odo.update(draw_form(data, wheels), gyro_angle=None)
        return self.odo.update(draw_form(data, wheels))

    def _reset_position(self, gyro, wheels, pose):
        self.odo.resetPosition(tuple(wheels), None, pose)


class TwoDeadWheelMachine(DeadWheelMachineBase):
    """TwoDeadWheelOdometry against the upstream closed form dx = Δx + dθ·xWheelYPos,
    dy = Δy − dθ·yWheelXPos (reference §6), written out here."""

    n = 2

    @initialize(a=st.floats(-0.5, 0.5), b=st.floats(-0.5, 0.5), data=st.data(),
                gyro=base.GYROS, x=base.COORDS, y=base.COORDS, th=base.HEADINGS)
    def setup(self, a, b, data, gyro, x, y, th):
        self.a, self.b = a, b
        wheels = self._draw_absolute(data)
        self.odo = TwoDeadWheelOdometry(a, b, wheels[0], wheels[1], Rotation2d(gyro),
                                        base.make_pose(x, y, th))
        self._start(gyro, wheels, (x, y, th))

    def _model_twist3(self, old, new, gyro_change):
        return (new[0] - old[0] + gyro_change * self.a,
                new[1] - old[1] - gyro_change * self.b, gyro_change)

    def _update(self, gyro, wheels, data):
        return self.odo.update(wheels[0], wheels[1], gyro)

    def _reset_position(self, gyro, wheels, pose):
        self.odo.resetPosition(wheels[0], wheels[1], gyro, pose)


TestDeadWheelGyroOdometryStateMachine = DeadWheelGyroMachine.TestCase
TestDeadWheelGyroOdometryStateMachine.settings = base.MACHINE_SETTINGS
TestDeadWheelNoGyroOdometryStateMachine = DeadWheelNoGyroMachine.TestCase
TestDeadWheelNoGyroOdometryStateMachine.settings = base.MACHINE_SETTINGS
TestTwoDeadWheelOdometryStateMachine = TwoDeadWheelMachine.TestCase
TestTwoDeadWheelOdometryStateMachine.settings = base.MACHINE_SETTINGS


# ---------------------------------------------------------------------------------------
# TwoDeadWheelOdometry = DeadWheelOdometry on its two wheel poses with a gyro


STEPS = st.lists(st.tuples(base.STEP, base.STEP, st.one_of(base.TURNS, base.GYROS)),
                 min_size=1, max_size=30)


@given(st.floats(-0.5, 0.5), st.floats(-0.5, 0.5), base.ABS_WHEEL, base.ABS_WHEEL,
       base.GYROS, base.COORDS, base.COORDS, base.HEADINGS, STEPS)
def test_two_dead_wheel_equals_general_layout(a, b, x0, y0, g0, px, py, pth, steps):
    start = base.make_pose(px, py, pth)
    two = TwoDeadWheelOdometry(a, b, x0, y0, Rotation2d(g0), start)
    kin = DeadWheelKinematics([Pose2d(0.0, a, Rotation2d(0.0)),
                               Pose2d(b, 0.0, Rotation2d(math.pi / 2))])
    general = DeadWheelOdometry(kin, [x0, y0], Rotation2d(g0), start)
    xw, yw, g = x0, y0, g0
    mag = max(1.0, abs(px), abs(py))
    for i, (sx, sy, turn) in enumerate(steps, 1):
        xw, yw, g = xw + sx, yw + sy, g + turn
        p1 = two.update(xw, yw, Rotation2d(g))
        p2 = general.update([xw, yw], Rotation2d(g))
        mag = max(mag, abs(p1.getX()), abs(p1.getY()))
        # Rotation2d(π/2) has cos = 6.1e-17, not 0, so the general solve is the closed
        # form up to a few ε per step, not bit for bit.
        S.assert_pose_close(p2, p1, mag * i, rel=16 * EPS, what=f"step {i}")
    assert two.toChassisVelocities(0.3, -0.2, 0.7) is not None
    tv = chassis(two.toChassisVelocities(0.3, -0.2, 0.7))
    gv = chassis(kin.toChassisVelocities([0.3, -0.2], 0.7))
    assert_vec_close(gv, tv, 16 * EPS * (1 + 0.7), "toChassisVelocities")
    assert tv == (0.3 + 0.7 * a, -0.2 - 0.7 * b, 0.7)


# ---------------------------------------------------------------------------------------
# Gyro wrap and failed calls


@given(layouts(gyro=True, max_cond=MACHINE_COND), st.data(),
       st.floats(math.pi - 0.2, math.pi, allow_nan=False), st.floats(0.0, 0.2),
       st.sampled_from([-1, 1]), st.integers(-2, 2))
def test_gyro_wrap_across_180_degrees(layout, data, before, step, sign, winds):
    """A gyro going from ±(π − δ1) to ∓(π − δ2) (or reporting the same angle plus whole
    turns) turns the robot by the short way, not by ~2π."""
    kin = make_kin(layout)
    d0 = data.draw(readings(len(layout)))
    d1 = data.draw(readings(len(layout)))
    g0 = sign * before
    g1 = g0 + sign * step + winds * TAU
    odo = DeadWheelOdometry(kin, d0, Rotation2d(g0))
    p = odo.update(d1, Rotation2d(g1))
    dth = math.remainder(g1 - g0, TAU)
    assert abs(dth - sign * step) <= 1e-14 * (1 + abs(winds) * TAU)
    deltas = [b - a for a, b in zip(d0, d1)]
    twist, r = model_solve(layout, deltas, dth)
    x, y, th = S.compose_exp(0.0, 0.0, 0.0, *twist)
    # drivekin takes the change from the two Rotation2d values (cos/sin of each raw angle,
    # rounded relative to |g|), the model from the raw angles: dθ may differ by δw.
    dw = 4 * EPS * (1.0 + abs(g0) + abs(g1))
    m = model_matrix(layout)
    lever = norm(np.linalg.pinv(m[:, :2]) @ m[:, 2])     # how dθ moves the fitted (dx, dy)
    # The solve's bound (for both solves), exp's few roundings per component, and δw
    # moving (dx, dy) through the lever arms and turning the translation.
    bound = (2 * gyro_tol(layout, twist[:2], deltas, dth, norm(r)) + 8 * EPS * norm(twist)
             + dw * (lever + norm(twist)) + ETA)
    assert_vec_close((p.getX(), p.getY()), (x, y), bound, "position after the wrap")
    err = abs(math.remainder(p.getRotation().getRadians() - th, TAU))
    assert err <= dw + 4 * EPS, f"heading {p.getRotation().getRadians()!r} vs {th!r}"


@given(layouts(gyro=True), st.data())
def test_failed_update_changes_nothing(layout, data):
    """A call refused half-way through the readings leaves pose and baselines as they
    were: the next good update integrates from the last good one."""
    kin = make_kin(layout)
    n = len(layout)
    d0, d1 = data.draw(readings(n)), data.draw(readings(n))
    bad = list(d1)
    bad[data.draw(st.integers(0, n - 1))] = data.draw(st.sampled_from([None, "1.0", 1j]))
    ref = DeadWheelOdometry(kin, d0, Rotation2d(0.1))
    odo = DeadWheelOdometry(kin, d0, Rotation2d(0.1))
    for args, exc in (((bad, Rotation2d(0.4)), TypeError),
                      ((d1 + [0.0], Rotation2d(0.4)), ValueError),
                      ((np.array(d1, dtype=np.float32), Rotation2d(0.4)), TypeError),
                      ((d1,), TypeError),                      # gyro odometry, no gyro
                      ((d1, 0.4), TypeError)):                 # a float is not a Rotation2d
        with pytest.raises(exc):
            odo.update(*args)
        with pytest.raises(exc):
            odo.resetPosition(args[0], args[1] if len(args) > 1 else None,
                              base.make_pose(5.0, 5.0, 1.0))
    p_ref = ref.update(d1, Rotation2d(0.4))
    p = odo.update(d1, Rotation2d(0.4))
    assert (p.getX(), p.getY(), S.rot_tuple(p.getRotation())) == (
        p_ref.getX(), p_ref.getY(), S.rot_tuple(p_ref.getRotation()))


def test_gyro_use_is_fixed_at_construction():
    kin = make_kin(NAMED_LAYOUTS[1])
    no_gyro = DeadWheelOdometry(kin, [0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="without a gyro"):
        no_gyro.update([0.1, 0.1, 0.1], Rotation2d(0.1))
    with pytest.raises(ValueError, match="without a gyro"):
        no_gyro.resetPosition([0.1, 0.1, 0.1], Rotation2d(0.1), Pose2d())
    assert chassis_pose(no_gyro.getPose()) == (0.0, 0.0, 1.0, 0.0)
    p = no_gyro.update([0.1, 0.1, 0.1])
    assert p.getX() != 0.0


def chassis_pose(p):
    return (p.getX(), p.getY(), *S.rot_tuple(p.getRotation()))


@settings(max_examples=30)
@given(layouts(gyro=True), st.data())
def test_independent_odometries_share_a_kinematics(layout, data):
    """Odometries built on one DeadWheelKinematics (which holds the scratch buffer) do
    not disturb each other, interleaved or not."""
    kin = make_kin(layout)
    n = len(layout)
    seq = data.draw(st.lists(st.tuples(readings(n), readings(n)), min_size=1, max_size=8))
    shared_a = DeadWheelOdometry(kin, [0.0] * n, Rotation2d(0.0))
    shared_b = DeadWheelOdometry(kin, [1.0] * n, Rotation2d(1.0))
    own_a = DeadWheelOdometry(make_kin(layout), [0.0] * n, Rotation2d(0.0))
    own_b = DeadWheelOdometry(make_kin(layout), [1.0] * n, Rotation2d(1.0))
    for i, (ra, rb) in enumerate(seq):
        g = Rotation2d(0.1 * i)
        assert chassis_pose(shared_a.update(ra, g)) == chassis_pose(own_a.update(ra, g))
        kin.toChassisVelocities(rb, 0.3)                  # also uses the scratch
        assert chassis_pose(shared_b.update(rb, g)) == chassis_pose(own_b.update(rb, g))
