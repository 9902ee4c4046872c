"""Property tests for drivekin.kinematics (swerve + chassis values): identities that hold
for any layout and input, checked against independent numpy/Python formulas rather than
against drivekin itself.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, example, given
from hypothesis import strategies as st

from tests._support import strategies as S
from drivekin.geometry import Rotation2d, Transform2d, Translation2d, Twist2d
from drivekin.kinematics import (
    ChassisVelocities,
    SwerveDriveKinematics,
    SwerveModulePosition,
    SwerveModuleVelocity,
)

EPS = S.EPS
desat = SwerveDriveKinematics.desaturateWheelVelocities
desat_in_place = SwerveDriveKinematics.desaturateWheelVelocitiesInPlace


def make_kin(layout):
    return SwerveDriveKinematics(*[Translation2d(x, y) for x, y in layout])


def module_vectors(layout, vx, vy, omega, cor=(0.0, 0.0)):
    """Independent IK: v_i = v + ω × (r_i − cor), as an (N, 2) array of (x, y)."""
    m = S.swerve_inverse_matrix(layout, cor)
    return (m @ np.array([vx, vy, omega])).reshape(-1, 2)


def states_as_xy(states):
    return np.array([[s.velocity * s.angle.getCos(), s.velocity * s.angle.getSin()]
                     for s in states])


def fk_rel(layout):
    """Relative error allowance for a least-squares solve on this layout: a generous
    multiple of ε·cond(M) (cond ≤ 1e6 by construction of the strategy)."""
    return max(1e-13, 64 * EPS * np.linalg.cond(S.swerve_inverse_matrix(layout)))


velocity_tuples = S.chassis_tuples(1e2)


# ---------------------------------------------------------------------------------------
# Inverse kinematics against the rigid-body formula


@given(S.swerve_layouts(), velocity_tuples, S.translation_tuples(3.0))
def test_inverse_matches_rigid_body_formula(layout, v, cor):
    kin = make_kin(layout)
    cv = ChassisVelocities(*v)
    states = kin.toSwerveModuleVelocities(cv, Translation2d(*cor))
    assert isinstance(states, tuple) and len(states) == len(layout)
    assert all(type(s) is SwerveModuleVelocity for s in states)
    expected = module_vectors(layout, *v, cor=S.effective_cor(cor))
    scale = float(np.abs(expected).max(initial=1.0))
    got = states_as_xy(states)
    for i, s in enumerate(states):
        assert s.velocity >= 0.0
        S.assert_close(s.velocity, math.hypot(*expected[i]), scale, rel=1e-14,
                       what=f"speed[{i}]")
        speed = math.hypot(*expected[i])
        if speed > 1e-6 * (1 + 1e-9):
            S.assert_close(got[i, 0], expected[i, 0], scale, rel=1e-14, what=f"x[{i}]")
            S.assert_close(got[i, 1], expected[i, 1], scale, rel=1e-14, what=f"y[{i}]")
        elif speed < 1e-6 * (1 - 1e-9):
            # Too slow to define a direction: the (fresh) remembered heading, 0.
            assert S.rot_tuple(s.angle) == (1.0, 0.0)


@given(S.swerve_layouts(), velocity_tuples)
@example([(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)], (1.0, 0.0, 0.0))
@example([(0.3, 0.3), (-0.3, -0.3)], (0.0, 0.0, 2.0))
def test_forward_inverse_identity(layout, v):
    kin = make_kin(layout)
    cv = ChassisVelocities(*v)
    speeds = np.hypot(*module_vectors(layout, *v).T)
    # Modules at ≤ 1e-6 m/s keep a remembered heading (WPILib rule), which breaks the
    # identity by up to 1e-6·|F|; keep every module clearly moving.
    assume(v == (0.0, 0.0, 0.0) or speeds.min() > 1e-5)
    states = kin.toSwerveModuleVelocities(cv)
    back = kin.toChassisVelocities(states)
    assert type(back) is ChassisVelocities
    scale = max(1.0, float(speeds.max(initial=0.0)))
    rel = fk_rel(layout)
    S.assert_close(back.vx, cv.vx, scale, rel=rel, what="vx")
    S.assert_close(back.vy, cv.vy, scale, rel=rel, what="vy")
    S.assert_close(back.omega, cv.omega, scale, rel=rel, what="omega")
    # Varargs form and list form agree exactly with the tuple form.
    assert kin.toChassisVelocities(*states) == back
    assert kin.toChassisVelocities(list(states)) == back


@given(S.swerve_layouts(), velocity_tuples, S.translation_tuples(2.0))
def test_forward_inverse_with_center_of_rotation(layout, v, cor):
    """Spinning about c is the same motion as v' = v + ω × (0 − c) about the origin, and
    forward kinematics is always solved about the origin."""
    kin = make_kin(layout)
    vx, vy, w = v
    cor = S.effective_cor(cor)
    speeds = np.hypot(*module_vectors(layout, vx, vy, w, cor).T)
    assume(v == (0.0, 0.0, 0.0) or speeds.min() > 1e-5)
    back = kin.toChassisVelocities(kin.toSwerveModuleVelocities(ChassisVelocities(*v),
                                                                Translation2d(*cor)))
    scale = max(1.0, float(speeds.max(initial=0.0)))
    rel = fk_rel(layout)
    if v != (0.0, 0.0, 0.0):
        S.assert_close(back.vx, vx + w * cor[1], scale, rel=rel, what="vx")
        S.assert_close(back.vy, vy - w * cor[0], scale, rel=rel, what="vy")
    S.assert_close(back.omega, w, scale, rel=rel, what="omega")


@given(S.swerve_layouts(), velocity_tuples, st.floats(1e-3, 10.0))
def test_twist_forward_matches_velocity_forward(layout, v, dt):
    """Position deltas d_i = v_i·dt give toTwist2d == toChassisVelocities·dt (same
    least-squares matrix), and toTwist2d(start, end) uses end − start at the end angle."""
    kin = make_kin(layout)
    states = kin.toSwerveModuleVelocities(ChassisVelocities(*v))
    deltas = [SwerveModulePosition(s.velocity * dt, s.angle) for s in states]
    tw = kin.toTwist2d(deltas)
    assert type(tw) is Twist2d
    cv = kin.toChassisVelocities(states)
    scale = max(1.0, max(abs(d.distance) for d in deltas))
    for got, exp in ((tw.dx, cv.vx * dt), (tw.dy, cv.vy * dt), (tw.dtheta, cv.omega * dt)):
        S.assert_close(got, exp, scale, rel=1e-13)
    start = [SwerveModulePosition(1.5 * i - 2.0, Rotation2d(0.3 * i)) for i in range(len(layout))]
    end = [SwerveModulePosition(s.distance + d.distance, d.angle) for s, d in zip(start, deltas)]
    tw2 = kin.toTwist2d(start, end)
    exact = kin.toTwist2d([SwerveModulePosition(e.distance - s.distance, e.angle)
                           for s, e in zip(start, end)])
    assert (tw2.dx, tw2.dy, tw2.dtheta) == (exact.dx, exact.dy, exact.dtheta)
    assert kin.toTwist2d(*deltas) == tw


# ---------------------------------------------------------------------------------------
# Heading memory


@given(S.swerve_layouts(), velocity_tuples)
def test_zero_velocity_returns_previous_headings(layout, v):
    kin = make_kin(layout)
    first = kin.toSwerveModuleVelocities(ChassisVelocities(*v))
    zero = kin.toSwerveModuleVelocities(ChassisVelocities(0.0, 0.0, 0.0))
    for a, b in zip(first, zero):
        assert b.velocity == 0.0
        assert S.rot_tuple(b.angle) == S.rot_tuple(a.angle)
    # Even with a different centre of rotation (exact-zero shortcut ignores it).
    again = kin.toSwerveModuleVelocities(ChassisVelocities(), Translation2d(5.0, -5.0))
    assert [S.rot_tuple(s.angle) for s in again] == [S.rot_tuple(s.angle) for s in first]


@given(S.swerve_layouts())
def test_fresh_kinematics_reports_zero_headings(layout):
    kin = make_kin(layout)
    for s in kin.toSwerveModuleVelocities(ChassisVelocities()):
        assert (s.velocity, *S.rot_tuple(s.angle)) == (0.0, 1.0, 0.0)


@given(S.swerve_layouts(), st.data())
def test_reset_headings_are_reported_at_zero_velocity(layout, data):
    kin = make_kin(layout)
    kin.toSwerveModuleVelocities(ChassisVelocities(1.0, 2.0, 3.0))
    hs = [Rotation2d(a) for a in data.draw(st.lists(S.angles(), min_size=len(layout),
                                                    max_size=len(layout)))]
    kin.resetHeadings(hs)
    out = kin.toSwerveModuleVelocities(ChassisVelocities())
    assert [S.rot_tuple(s.angle) for s in out] == [S.rot_tuple(h) for h in hs]
    kin.resetHeadings(*reversed(hs))  # varargs form
    out = kin.toSwerveModuleVelocities(ChassisVelocities())
    assert [S.rot_tuple(s.angle) for s in out] == [S.rot_tuple(h) for h in reversed(hs)]


@given(S.swerve_layouts(), st.data(), S.wrapped_angles(), st.floats(0.1, 10.0),
       st.floats(0.1, 10.0).flatmap(lambda w: st.sampled_from([w, -w])))
def test_module_on_center_of_rotation_keeps_heading(layout, data, heading, speed, omega):
    j = data.draw(st.integers(0, len(layout) - 1), label="module on CoR")
    kin = make_kin(layout)
    # Strafe: every module points along `heading`.
    strafe = ChassisVelocities(speed * math.cos(heading), speed * math.sin(heading), 0.0)
    before = kin.toSwerveModuleVelocities(strafe)
    # Spin about module j: it does not move, so it keeps the strafe heading.
    after = kin.toSwerveModuleVelocities(ChassisVelocities(0.0, 0.0, omega),
                                         Translation2d(*layout[j]))
    # Exactly 0 unless module j is within 1e-9 m of the previous CoR (the origin): then the
    # CoR is "unchanged" under Translation2d equality and the rows are not rebuilt.
    assert after[j].velocity <= abs(omega) * 2e-9
    assert S.rot_tuple(after[j].angle) == S.rot_tuple(before[j].angle)
    S.assert_rot_close(after[j].angle, Rotation2d(heading), rel=1e-14)
    # The others move on circles about module j (about the effective CoR, which is the
    # origin when module j is within 1e-9 m of it): perpendicular to r_i − CoR.
    c = S.effective_cor(layout[j])
    for i, s in enumerate(after):
        if i == j:
            continue
        rx, ry = layout[i][0] - c[0], layout[i][1] - c[1]
        r = math.hypot(rx, ry)
        S.assert_close(s.velocity, abs(omega) * r, omega * r, rel=1e-14, what="speed")
        dot = s.angle.getCos() * rx + s.angle.getSin() * ry
        assert abs(dot) <= 1e-12 * max(1.0, r)


@given(S.swerve_layouts(), velocity_tuples, st.floats(-9e-10, 9e-10), st.floats(-9e-10, 9e-10))
def test_center_of_rotation_compared_within_1e9(layout, v, dx, dy):
    """A CoR within 1e-9 m of the previous one does not rebuild the rows (WPILib's
    Translation2d equality), so the result is bit-identical to the previous CoR's."""
    a, b = make_kin(layout), make_kin(layout)
    cv = ChassisVelocities(*v)
    for k in (a, b):  # same CoR and heading memory in both
        k.toSwerveModuleVelocities(ChassisVelocities(1.0, 1.0, 1.0), Translation2d(1.0, -2.0))
    ra = a.toSwerveModuleVelocities(cv, Translation2d(1.0, -2.0))
    rb = b.toSwerveModuleVelocities(cv, Translation2d(1.0 + dx, -2.0 + dy))
    assert snapshot(rb) == snapshot(ra)


def test_heading_memory_is_per_instance():
    layout = [(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)]
    a, b = make_kin(layout), make_kin(layout)
    a.toSwerveModuleVelocities(ChassisVelocities(0.0, 1.0, 0.0))  # all modules to +90°
    za = a.toSwerveModuleVelocities(ChassisVelocities())
    zb = b.toSwerveModuleVelocities(ChassisVelocities())
    assert all(s.angle.getDegrees() == pytest.approx(90.0) for s in za)
    assert all(s.angle.getDegrees() == 0.0 for s in zb)


# ---------------------------------------------------------------------------------------
# Desaturation


def velocity_lists(min_size=0, max_size=8, bound=1e2):
    return st.lists(st.tuples(S.finite_floats(bound), S.angles()), min_size=min_size,
                    max_size=max_size).map(
        lambda xs: [SwerveModuleVelocity(v, Rotation2d(a)) for v, a in xs])


def snapshot(states):
    return [(s.velocity, *S.rot_tuple(s.angle)) for s in states]


@given(velocity_lists(), st.floats(0.0, 1e2))
def test_desaturate_one_limit(states, limit):
    before = snapshot(states)
    out = desat(states, limit)
    assert isinstance(out, tuple) and len(out) == len(states)
    assert snapshot(states) == before, "input must not be mutated (2027)"
    assert all(o is not s for o, s in zip(out, states)), "results must be new objects"
    real_max = max([abs(v) for v, _, _ in before], default=0.0)
    for (v, c, s), o in zip(before, out):
        assert S.rot_tuple(o.angle) == (c, s), "angles are kept"
        if real_max <= limit:
            assert o.velocity == v, "unchanged when under the limit"
        else:
            assert abs(o.velocity) <= limit * (1 + 4 * EPS)
            # Ratios preserved: every wheel gets the same factor limit / realMax.
            S.assert_close(o.velocity, v * (limit / real_max), limit, rel=4 * EPS)
            assert math.copysign(1.0, o.velocity) == math.copysign(1.0, v) or o.velocity == 0.0
    if real_max > limit:
        assert max(abs(o.velocity) for o in out) == pytest.approx(limit, rel=4 * EPS)


def desat5_formula(speeds, desired, max_module, max_trans, max_rot):
    """The 2027 joystick-normalisation factor, written out independently."""
    real_max = max([abs(v) for v in speeds], default=0.0)
    if max_trans == 0.0 or max_rot == 0.0 or real_max == 0.0:
        return 1.0
    k = max(math.hypot(desired[0], desired[1]) / max_trans, abs(desired[2]) / max_rot)
    return min(k * max_module / real_max, 1.0)


limits = st.one_of(st.just(0.0), st.floats(1e-3, 1e2))


@given(velocity_lists(), velocity_tuples, limits, limits, limits)
@example([SwerveModuleVelocity(v) for v in (5.0, 6.0, 4.0, 7.0)], (1.0, 0.0, 0.0), 5.5, 5.5,
         3.5)
def test_desaturate_five_arg(states, desired, max_module, max_trans, max_rot):
    before = snapshot(states)
    out = desat(states, ChassisVelocities(*desired), max_module, max_trans, max_rot)
    assert isinstance(out, tuple) and len(out) == len(states)
    assert snapshot(states) == before
    factor = desat5_formula([v for v, _, _ in before], desired, max_module, max_trans, max_rot)
    assert 0.0 <= factor <= 1.0
    for (v, c, s), o in zip(before, out):
        assert S.rot_tuple(o.angle) == (c, s)
        assert abs(o.velocity) <= abs(v), "never scales up"
        S.assert_close(o.velocity, v * factor, v, rel=4 * EPS, what="scaled velocity")
        if factor == 1.0:
            assert o.velocity == v


def test_desaturate_five_arg_known_example():
    states = [SwerveModuleVelocity(v) for v in (5.0, 6.0, 4.0, 7.0)]
    out = desat(states, ChassisVelocities(1.0, 0.0, 0.0), 5.5, 5.5, 3.5)
    assert [o.velocity for o in out] == pytest.approx([5 / 7, 6 / 7, 4 / 7, 1.0], rel=1e-15)


@given(velocity_lists(min_size=1), st.floats(0.0, 1e2), velocity_tuples, limits, limits,
       limits)
def test_desaturate_in_place_agrees_with_returning_form(states, limit, desired, mm, mt, mr):
    for args in ((limit,), (ChassisVelocities(*desired), mm, mt, mr)):
        expected = snapshot(desat(states, *args))
        objs = [SwerveModuleVelocity(s.velocity, s.angle) for s in states]
        keep = list(objs)
        assert desat_in_place(objs, *args) is None
        assert all(a is b for a, b in zip(objs, keep)), "same objects, updated in place"
        assert snapshot(objs) == expected
        arr = np.array([[s.velocity, s.angle.getRadians()] for s in states])
        angles = arr[:, 1].copy()
        assert desat_in_place(arr, *args) is None
        assert arr[:, 0].tolist() == [e[0] for e in expected]
        assert arr[:, 1].tolist() == angles.tolist(), "angle column untouched"


# ---------------------------------------------------------------------------------------
# Allocation-free forms agree exactly with the façade; numpy forms with object forms


@given(S.swerve_layouts(), velocity_tuples, S.translation_tuples(2.0))
def test_ik_into_agrees_with_facade(layout, v, cor):
    cv, c = ChassisVelocities(*v), Translation2d(*cor)
    ref_kin, obj_kin, arr_kin = make_kin(layout), make_kin(layout), make_kin(layout)
    # Two calls so that the heading memory is exercised identically in every instance.
    for cvi in (cv, ChassisVelocities()):
        expected = ref_kin.toSwerveModuleVelocities(cvi, c)
        out = [SwerveModuleVelocity() for _ in layout]
        keep = list(out)
        assert obj_kin.toSwerveModuleVelocitiesInto(cvi, out, c) is None
        assert all(a is b for a, b in zip(out, keep))
        assert snapshot(out) == snapshot(expected)
        arr = np.full((len(layout), 2), np.nan)
        assert arr_kin.toSwerveModuleVelocitiesInto(cvi, arr, c) is None
        assert arr[:, 0].tolist() == [s.velocity for s in expected]
        assert arr[:, 1].tolist() == [s.angle.getRadians() for s in expected]
    # Tuple `out` works too (its elements are mutated).
    out_t = tuple(SwerveModuleVelocity() for _ in layout)
    make_kin(layout).toSwerveModuleVelocitiesInto(cv, out_t, c)
    assert snapshot(out_t) == snapshot(make_kin(layout).toSwerveModuleVelocities(cv, c))


@given(S.swerve_layouts(), velocity_tuples)
def test_to_wheel_velocities_is_ik_about_origin(layout, v):
    a, b = make_kin(layout), make_kin(layout)
    assert snapshot(a.toWheelVelocities(ChassisVelocities(*v))) == snapshot(
        b.toSwerveModuleVelocities(ChassisVelocities(*v)))


@given(S.swerve_layouts(), st.data())
def test_fk_into_and_array_forms_agree(layout, data):
    n = len(layout)
    raw = data.draw(st.lists(st.tuples(S.finite_floats(1e2), S.angles()), min_size=n,
                             max_size=n))
    states = [SwerveModuleVelocity(v, Rotation2d(a)) for v, a in raw]
    kin = make_kin(layout)
    expected = kin.toChassisVelocities(states)
    out = ChassisVelocities(7.0, 8.0, 9.0)
    assert kin.toChassisVelocitiesInto(states, out) is None
    assert (out.vx, out.vy, out.omega) == (expected.vx, expected.vy, expected.omega)
    arr = np.array(raw, dtype=np.float64)
    out2 = ChassisVelocities()
    kin.toChassisVelocitiesInto(arr, out2)
    assert (out2.vx, out2.vy, out2.omega) == (expected.vx, expected.vy, expected.omega)
    # Independent least squares with numpy.
    w = np.array([[v * math.cos(a), v * math.sin(a)] for v, a in raw]).ravel()
    ref = np.linalg.lstsq(S.swerve_inverse_matrix(layout), w, rcond=None)[0]
    scale = max(1.0, max(abs(v) for v, _ in raw))
    for got, e in zip((expected.vx, expected.vy, expected.omega), ref):
        S.assert_close(got, float(e), scale, rel=fk_rel(layout))
    # Twist forms: positions with the same numbers.
    positions = [SwerveModulePosition(v, Rotation2d(a)) for v, a in raw]
    tw = kin.toTwist2d(positions)
    assert (tw.dx, tw.dy, tw.dtheta) == (expected.vx, expected.vy, expected.omega)
    out3 = Twist2d(1.0, 2.0, 3.0)
    assert kin.toTwist2dInto(positions, out3) is None
    assert (out3.dx, out3.dy, out3.dtheta) == (tw.dx, tw.dy, tw.dtheta)
    out4 = Twist2d()
    kin.toTwist2dInto(arr, out4)
    assert (out4.dx, out4.dy, out4.dtheta) == (tw.dx, tw.dy, tw.dtheta)


@given(velocity_tuples, st.floats(1e-3, 1.0), S.angles())
def test_chassis_into_forms_agree(v, dt, theta):
    cv, r = ChassisVelocities(*v), Rotation2d(theta)
    for method, arg in (("discretize", dt), ("toRobotRelative", r), ("toFieldRelative", r)):
        expected = getattr(cv, method)(arg)
        assert type(expected) is ChassisVelocities
        out = ChassisVelocities(-1.0, -2.0, -3.0)
        assert getattr(cv, method + "Into")(arg, out) is None
        assert (out.vx, out.vy, out.omega) == (expected.vx, expected.vy, expected.omega)
        alias = ChassisVelocities(*v)  # out may be self
        getattr(alias, method + "Into")(arg, alias)
        assert (alias.vx, alias.vy, alias.omega) == (expected.vx, expected.vy, expected.omega)
    assert (cv.vx, cv.vy, cv.omega) == v, "the façade must not mutate the receiver"


# ---------------------------------------------------------------------------------------
# ChassisVelocities identities


@given(velocity_tuples, S.angles())
def test_field_robot_relative_round_trip(v, theta):
    cv, r = ChassisVelocities(*v), Rotation2d(theta)
    fr = cv.toFieldRelative(r)
    scale = max(1.0, math.hypot(v[0], v[1]))
    S.assert_close(fr.vx, v[0] * r.getCos() - v[1] * r.getSin(), scale, rel=1e-15 * 4)
    S.assert_close(fr.vy, v[0] * r.getSin() + v[1] * r.getCos(), scale, rel=1e-15 * 4)
    assert fr.omega == v[2]
    back = fr.toRobotRelative(r)
    S.assert_close(back.vx, v[0], scale, rel=1e-14)
    S.assert_close(back.vy, v[1], scale, rel=1e-14)
    assert back.omega == v[2]


@given(velocity_tuples, st.floats(1e-3, 1.0))
def test_discretize_reaches_the_constant_velocity_pose(v, dt):
    """Following the discretized twist for dt lands on (vx·dt, vy·dt, ω·dt)."""
    vx, vy, w = v
    d = ChassisVelocities(*v).discretize(dt)
    tr = Twist2d(d.vx * dt, d.vy * dt, d.omega * dt).exp()
    target = Transform2d(vx * dt, vy * dt, Rotation2d(w * dt))
    scale = max(1.0, math.hypot(vx, vy) * dt)
    rel = 1e-12
    S.assert_pose_close(tr, target, scale, rel=rel)
    # omega is wrapped through a Rotation2d.
    S.assert_angle_close(d.omega * dt, w * dt, rel=1e-13)
    assert abs(d.omega * dt) <= math.pi


@given(velocity_tuples, st.floats(0.0, 10.0))
def test_chassis_to_twist(v, dt):
    tw = ChassisVelocities(*v).toTwist2d(dt)
    assert (tw.dx, tw.dy, tw.dtheta) == (v[0] * dt, v[1] * dt, v[2] * dt)


# ---------------------------------------------------------------------------------------
# Module values


@given(S.finite_floats(1e2), S.angles(), S.angles())
def test_optimize_keeps_vector_and_turns_at_most_90(v, target, current):
    s = SwerveModuleVelocity(v, Rotation2d(target))
    o = s.optimize(Rotation2d(current))
    assert o is not s and type(o) is SwerveModuleVelocity
    assert (s.velocity, *S.rot_tuple(s.angle)) == (v, *S.rot_tuple(Rotation2d(target)))
    # Same wheel velocity vector.
    S.assert_close(o.velocity * o.angle.getCos(), v * s.angle.getCos(), v, rel=1e-14)
    S.assert_close(o.velocity * o.angle.getSin(), v * s.angle.getSin(), v, rel=1e-14)
    assert abs(o.velocity) == abs(v)
    diff = abs(o.angle.minus(Rotation2d(current)).getDegrees())
    assert diff <= 90.0 + 1e-9


@given(S.finite_floats(1e2), S.angles(), S.angles())
def test_cosine_scale(v, target, current):
    s = SwerveModuleVelocity(v, Rotation2d(target))
    o = s.cosineScale(Rotation2d(current))
    assert o is not s and s.velocity == v
    S.assert_close(o.velocity, v * math.cos(target - current), v, target, current, rel=1e-14)
    assert S.rot_tuple(o.angle) == S.rot_tuple(s.angle)
