"""Property tests for drivekin.geometry: algebraic identities that must hold for any
input, independent of any reference implementation.

Tolerances are absolute bounds rel·max(1, magnitude of the inputs). Round trips inside
drivekin lose only a few ulps per operation, so most use rel = 1e-12 (about 4500 ulps of
the largest input), far below the 1e-9 accuracy contract but still well above rounding.
"""
from __future__ import annotations

import math

import pytest
from hypothesis import assume, example, given
from hypothesis import strategies as st

from tests._support import strategies as S
from drivekin.geometry import Pose2d, Rotation2d, Transform2d, Translation2d, Twist2d

RT = 1e-12  # relative tolerance for round trips

# ---------------------------------------------------------------------------------------
# Rotation2d


@given(S.angles(1e3))
def test_rotation_stores_unit_vector_and_wraps(theta):
    r = Rotation2d(theta)
    assert math.hypot(r.getCos(), r.getSin()) == pytest.approx(1.0, abs=1e-15)
    rad = r.getRadians()
    assert -math.pi <= rad <= math.pi
    # The wrapped angle equals theta modulo 2π (cos/sin of a large theta are exact to an
    # ulp of theta, so the bound scales with |theta|).
    S.assert_angle_close(rad, theta, theta, rel=1e-15 * 8)
    assert r.getDegrees() == pytest.approx(math.degrees(rad), rel=1e-15, abs=1e-300)
    assert r.getRotations() == pytest.approx(rad / S.TAU, rel=1e-15, abs=1e-300)


@given(S.angles(), S.angles())
def test_rotation_plus_minus_match_angle_arithmetic(a, b):
    ra, rb = Rotation2d(a), Rotation2d(b)
    S.assert_rot_close(ra.plus(rb), Rotation2d(a + b), a, b, rel=1e-14, what="plus")
    S.assert_rot_close(ra.rotateBy(rb), Rotation2d(a + b), a, b, rel=1e-14, what="rotateBy")
    S.assert_rot_close(ra + rb, Rotation2d(a + b), a, b, rel=1e-14, what="+")
    S.assert_rot_close(ra.minus(rb), Rotation2d(a - b), a, b, rel=1e-14, what="minus")
    S.assert_rot_close(ra - rb, Rotation2d(a - b), a, b, rel=1e-14, what="-")
    S.assert_rot_close(ra.relativeTo(rb), Rotation2d(a - b), a, b, rel=1e-14,
                       what="relativeTo")
    S.assert_rot_close(ra.unaryMinus(), Rotation2d(-a), a, rel=1e-14, what="unaryMinus")
    S.assert_rot_close(-ra, Rotation2d(-a), a, rel=1e-14, what="neg")
    # Composition is a group: (a + b) − b == a, and a + (−a) is the identity.
    S.assert_rot_close(ra.plus(rb).minus(rb), ra, rel=1e-14, what="(a+b)-b")
    S.assert_rot_close(ra.plus(ra.unaryMinus()), Rotation2d(), rel=1e-14, what="a+(-a)")
    # Results stay normalised.
    for r in (ra.plus(rb), ra.minus(rb), ra.unaryMinus()):
        assert math.hypot(r.getCos(), r.getSin()) == pytest.approx(1.0, abs=1e-15)


@given(S.angles(), st.floats(-10, 10, allow_nan=False))
def test_rotation_times_scales_wrapped_angle(theta, k):
    r = Rotation2d(theta)
    wrapped = r.getRadians()
    S.assert_rot_close(r.times(k), Rotation2d(wrapped * k), rel=1e-14, what="times")
    S.assert_rot_close(r * k, Rotation2d(wrapped * k), rel=1e-14, what="*")
    S.assert_rot_close(k * r, Rotation2d(wrapped * k), rel=1e-14, what="rmul")
    assume(abs(k) > 1e-3)
    S.assert_rot_close(r.div(k), Rotation2d(wrapped / k), wrapped / k, rel=1e-14, what="div")
    S.assert_rot_close(r / k, Rotation2d(wrapped / k), wrapped / k, rel=1e-14, what="/")


def test_rotation_times_uses_wrapped_angle_example():
    # 270° is stored as −90°, so ×0.5 gives −45° (2027), not 135°.
    assert Rotation2d.fromDegrees(270).times(0.5).getDegrees() == pytest.approx(-45.0)


@given(S.finite_floats(1e3), S.finite_floats(1e3))
def test_rotation_from_xy_normalises(x, y):
    r = Rotation2d(x, y)
    m = math.hypot(x, y)
    if m > 1e-6:
        S.assert_unit_close(r.getCos(), r.getSin(), x / m, y / m, rel=1e-15 * 4)
    else:
        assert (r.getCos(), r.getSin()) == (1.0, 0.0)


@given(st.floats(1e-5, 1e3), S.angles())
def test_rotation_xy_equals_polar(m, theta):
    S.assert_rot_close(Rotation2d(m * math.cos(theta), m * math.sin(theta)), Rotation2d(theta),
                       rel=1e-14)


@given(S.angles(), S.angles())
def test_rotation_interpolate_endpoints_and_short_way(a, b):
    ra, rb = Rotation2d(a), Rotation2d(b)
    S.assert_rot_close(ra.interpolate(rb, 0.0), ra, rel=1e-14, what="t=0")
    S.assert_rot_close(ra.interpolate(rb, 1.0), rb, rel=1e-14, what="t=1")
    # The midpoint is half the wrapped difference away from a, i.e. within 90° of a.
    d = S.angle_diff(rb.getRadians(), ra.getRadians())
    assume(abs(abs(d) - math.pi) > 1e-9)  # exactly opposite: direction ambiguous
    mid = ra.interpolate(rb, 0.5)
    S.assert_rot_close(mid, Rotation2d(ra.getRadians() + d / 2), rel=1e-13, what="mid")
    # Not clamped in 2027: t = 2 goes a full difference past b.
    S.assert_rot_close(ra.interpolate(rb, 2.0), Rotation2d(ra.getRadians() + 2 * d),
                       rel=1e-13, what="t=2")


@given(S.angles())
def test_rotation_matrix_is_orthonormal(theta):
    m = Rotation2d(theta).toMatrix()
    r = Rotation2d(theta)
    assert m.tolist() == [[r.getCos(), -r.getSin()], [r.getSin(), r.getCos()]]


# ---------------------------------------------------------------------------------------
# Translation2d


@given(S.translations(), S.translations(), S.finite_floats(1e2))
def test_translation_vector_space(a, b, k):
    s = a.plus(b)
    assert (s.getX(), s.getY()) == (a.getX() + b.getX(), a.getY() + b.getY())
    d = a.minus(b)
    assert (d.getX(), d.getY()) == (a.getX() - b.getX(), a.getY() - b.getY())
    assert (a + b) == s and (a - b) == d
    n = -a
    assert (n.getX(), n.getY()) == (-a.getX(), -a.getY())
    t = a.times(k)
    assert (t.getX(), t.getY()) == (a.getX() * k, a.getY() * k)
    assert (a * k) == t and (k * a) == t
    S.assert_translation_close(a.plus(b).minus(b), a, a.getNorm(), b.getNorm(), rel=1e-15 * 4)
    assert a.getNorm() == pytest.approx(math.hypot(a.getX(), a.getY()), rel=1e-15)
    assert a.getSquaredNorm() == pytest.approx(a.getX() ** 2 + a.getY() ** 2, rel=1e-15,
                                               abs=1e-300)
    assert a.getDistance(b) == pytest.approx(math.hypot(b.getX() - a.getX(), b.getY() - a.getY()),
                                             rel=1e-15, abs=1e-300)
    assert a.dot(b) == pytest.approx(a.getX() * b.getX() + a.getY() * b.getY(), rel=1e-12,
                                     abs=1e-300)
    assert a.cross(b) == pytest.approx(a.getX() * b.getY() - a.getY() * b.getX(), rel=1e-12,
                                       abs=1e-300)


@given(S.translations(), S.angles(), S.angles())
def test_translation_rotate_preserves_norm_and_composes(t, a, b):
    ra, rb = Rotation2d(a), Rotation2d(b)
    u = t.rotateBy(ra)
    S.assert_close(u.getNorm(), t.getNorm(), t.getNorm(), rel=1e-15 * 8, what="norm")
    S.assert_translation_close(u.rotateBy(rb), t.rotateBy(ra.plus(rb)), t.getNorm(),
                               rel=1e-14, what="compose")
    S.assert_translation_close(u.rotateBy(ra.unaryMinus()), t, t.getNorm(), rel=1e-14,
                               what="inverse")


@given(S.translations(), S.translations(), S.angles())
def test_translation_rotate_around(t, p, a):
    r = Rotation2d(a)
    got = t.rotateAround(p, r)
    exp = p.plus(t.minus(p).rotateBy(r))
    S.assert_translation_close(got, exp, t.getNorm(), p.getNorm(), rel=1e-15 * 8)
    # The distance to the pivot is preserved.
    S.assert_close(got.getDistance(p), t.getDistance(p), t.getNorm(), p.getNorm(), rel=1e-14)


@given(S.finite_floats(), S.angles())
def test_translation_polar_constructor_and_angle(d, theta):
    r = Rotation2d(theta)
    t = Translation2d(d, r)
    S.assert_close(t.getX(), d * r.getCos(), d, rel=1e-15 * 4)
    S.assert_close(t.getY(), d * r.getSin(), d, rel=1e-15 * 4)
    if t.getNorm() > 1e-6:
        ang = t.getAngle()
        assert ang is not None
        expected = r if d > 0 else r.plus(Rotation2d(math.pi))
        S.assert_rot_close(ang, expected, rel=1e-14)
    else:
        assert t.getAngle() is None


@given(S.translations(), S.translations(), st.floats(-2, 3, allow_nan=False))
def test_translation_interpolate(a, b, t):
    assert a.interpolate(b, 0.0) == a
    S.assert_translation_close(a.interpolate(b, 1.0), b, a.getNorm(), b.getNorm(), rel=1e-15 * 4)
    got = a.interpolate(b, t)
    S.assert_close(got.getX(), a.getX() + (b.getX() - a.getX()) * t, a.getNorm(), b.getNorm(),
                   rel=1e-14)
    S.assert_close(got.getY(), a.getY() + (b.getY() - a.getY()) * t, a.getNorm(), b.getNorm(),
                   rel=1e-14)


# ---------------------------------------------------------------------------------------
# Transform2d.log / Twist2d.exp


def _tr_scale(tr):
    return max(1.0, tr.getTranslation().getNorm())


@given(S.transforms())
@example(Transform2d(5.0, 5.0, Rotation2d(math.pi / 2)))
@example(Transform2d(0.0, 2.0, Rotation2d(math.pi)))
@example(Transform2d(1e3, -1e3, Rotation2d(-math.pi)))
@example(Transform2d(3.0, 0.0, Rotation2d(4.4e-5)))  # where WPILib's log used to cancel
@example(Transform2d(3.0, 0.0, Rotation2d(4.6e-5)))
def test_transform_log_exp_round_trip(tr):
    tw = tr.log()
    assert isinstance(tw, Twist2d)
    assert -math.pi <= tw.dtheta <= math.pi
    S.assert_pose_close(tw.exp(), tr, _tr_scale(tr), rel=RT,
                        what="log().exp()")


@given(S.twists(dtheta=S.wrapped_angles()))
@example(Twist2d(1.0, 0.5, 1e-10))  # exp's series branch
@example(Twist2d(1e3, 1e3, 3.14159))
@example(Twist2d(-2.0, 0.0, 0.0))
def test_twist_exp_log_round_trip(tw):
    back = tw.exp().log()
    scale = max(1.0, math.hypot(tw.dx, tw.dy))
    rel = RT
    S.assert_close(back.dx, tw.dx, scale, rel=rel, what="dx")
    S.assert_close(back.dy, tw.dy, scale, rel=rel, what="dy")
    S.assert_angle_close(back.dtheta, tw.dtheta, rel=1e-14, what="dtheta")


@given(S.twists(dtheta=S.angles()))
def test_twist_exp_matches_closed_form(tw):
    """exp against the closed-form arc, computed independently in Python (1 − cos θ as
    2·sin²(θ/2), which does not cancel; mpmath checks the absolute accuracy elsewhere)."""
    dx, dy, th = tw.dx, tw.dy, tw.dtheta
    tr = tw.exp()
    if th == 0.0:
        s, c = 1.0, 0.0
    else:
        s, c = math.sin(th) / th, 2.0 * math.sin(th / 2.0) ** 2 / th
    scale = max(1.0, math.hypot(dx, dy))
    S.assert_close(tr.getX(), dx * s - dy * c, scale, rel=1e-14, what="x")
    S.assert_close(tr.getY(), dx * c + dy * s, scale, rel=1e-14, what="y")
    S.assert_rot_close(tr.getRotation(), Rotation2d(th), rel=1e-14)


@given(S.finite_floats(), S.finite_floats(),
       st.floats(-1e-9, 1e-9, exclude_min=True, exclude_max=True))
def test_twist_exp_series_branch_is_continuous(dx, dy, th):
    """Inside the series branch the result matches the straight line plus a first-order
    correction; it must never collapse to c = 0 (the cos-rounds-to-1 trap)."""
    tr = Twist2d(dx, dy, th).exp()
    scale = max(1.0, math.hypot(dx, dy))
    S.assert_close(tr.getX(), dx - dy * th / 2, scale, rel=1e-15 * 4)
    S.assert_close(tr.getY(), dy + dx * th / 2, scale, rel=1e-15 * 4)


def test_twist_exp_tiny_angle_example():
    tr = Twist2d(1.0, 0.5, 1e-10).exp()
    assert tr.getX() == pytest.approx(0.999999999975, abs=1e-15)
    assert tr.getY() == pytest.approx(0.50000000005, abs=1e-15)


@given(S.transforms(), st.floats(0.0, 1.0))
def test_transform_log_scaled_exp_stays_on_arc(tr, t):
    """exp(t·log T) then exp((1−t)·log T) composes back to T (one-parameter subgroup)."""
    tw = tr.log()
    a = Twist2d(tw.dx * t, tw.dy * t, tw.dtheta * t).exp()
    b = Twist2d(tw.dx * (1 - t), tw.dy * (1 - t), tw.dtheta * (1 - t)).exp()
    S.assert_pose_close(a.plus(b), tr, _tr_scale(tr), rel=RT)


# ---------------------------------------------------------------------------------------
# Pose2d / Transform2d algebra


def _scale(*ps):
    return max([1.0] + [p.getTranslation().getNorm() for p in ps])


@given(S.poses(), S.poses())
def test_pose_minus_plus_identity(a, b):
    t = b.minus(a)
    assert isinstance(t, Transform2d)
    S.assert_pose_close(a.plus(t), b, _scale(a, b), rel=RT, what="a + (b − a)")
    S.assert_pose_close(a + (b - a), b, _scale(a, b), rel=RT, what="operators")
    S.assert_pose_close(a.transformBy(t), b, _scale(a, b), rel=RT, what="transformBy")
    S.assert_pose_close(Transform2d(a, b), t, _scale(a, b), rel=0.0, what="Transform2d(a, b)")


@given(S.poses(), S.transforms())
def test_pose_plus_minus_identity(a, t):
    b = a.plus(t)
    S.assert_pose_close(b.minus(a), t, _scale(a, b), rel=RT, what="(a + t) − a")


@given(S.poses(), S.poses())
def test_relative_to_inverse(a, b):
    rel = b.relativeTo(a)
    S.assert_pose_close(a.transformBy(Transform2d(rel.getTranslation(), rel.getRotation())), b,
                        _scale(a, b), rel=RT, what="a ∘ (b rel a)")
    # relativeTo is minus expressed as a pose.
    m = b.minus(a)
    S.assert_pose_close(rel, Pose2d(m.getTranslation(), m.getRotation()), _scale(a, b), rel=0.0)
    # A pose relative to itself is the origin.
    S.assert_pose_close(a.relativeTo(a), Pose2d(), _scale(a), rel=RT, what="a rel a")
    # Distances are preserved by a change of frame.
    S.assert_close(rel.getTranslation().getNorm(),
                   b.getTranslation().getDistance(a.getTranslation()), _scale(a, b), rel=RT)


@given(S.transforms(), S.transforms(), S.poses())
def test_transform_inverse_and_composition(t1, t2, p):
    sc = _scale(t1, t2, p)
    S.assert_pose_close(t1.plus(t1.inverse()), Transform2d(), sc, rel=RT, what="t + t⁻¹")
    S.assert_pose_close(t1.inverse().plus(t1), Transform2d(), sc, rel=RT, what="t⁻¹ + t")
    S.assert_pose_close(p.plus(t1).plus(t1.inverse()), p, sc, rel=RT, what="p + t + t⁻¹")
    # Composition is associative with pose application.
    S.assert_pose_close(p.plus(t1).plus(t2), p.plus(t1.plus(t2)), sc, rel=RT, what="assoc")
    S.assert_pose_close(p + t1 + t2, p + (t1 + t2), sc, rel=RT, what="assoc ops")


@given(S.poses(), S.twists(dtheta=S.angles()))
def test_pose_exp_equals_plus_twist_exp(p, tw):
    a = p.exp(tw)
    b = p.plus(tw.exp())
    # Same kernels, same numbers: exact equality.
    assert (a.getX(), a.getY()) == (b.getX(), b.getY())
    assert S.rot_tuple(a.getRotation()) == S.rot_tuple(b.getRotation())


@given(S.poses(), S.poses())
def test_pose_log_equals_minus_log(a, b):
    t1 = a.log(b)
    t2 = b.minus(a).log()
    assert (t1.dx, t1.dy, t1.dtheta) == (t2.dx, t2.dy, t2.dtheta)
    S.assert_pose_close(a.exp(t1), b, _scale(a, b), rel=RT)


@given(S.poses(), S.angles(), S.translations())
def test_pose_rotate_by_and_around(p, theta, pivot):
    r = Rotation2d(theta)
    q = p.rotateBy(r)
    S.assert_translation_close(q.getTranslation(), p.getTranslation().rotateBy(r), _scale(p),
                               rel=0.0)
    S.assert_rot_close(q.getRotation(), p.getRotation().plus(r), rel=0.0)
    q2 = p.rotateAround(pivot, r)
    S.assert_translation_close(q2.getTranslation(), p.getTranslation().rotateAround(pivot, r),
                               _scale(p), pivot.getNorm(), rel=1e-15 * 4)
    S.assert_rot_close(q2.getRotation(), p.getRotation().plus(r), rel=0.0)


@given(S.poses(), S.poses())
def test_pose_interpolate_endpoints(a, b):
    assert a.interpolate(b, -0.5) is a
    assert a.interpolate(b, 1.0) is b
    assert a.interpolate(b, 7.0) is b
    S.assert_pose_close(a.interpolate(b, 0.0), a, _scale(a), rel=1e-15 * 4, what="t=0")
    # Just below 1 the arc lands next to b.
    rel = RT
    S.assert_pose_close(a.interpolate(b, math.nextafter(1.0, 0.0)), b, _scale(a, b), rel=rel,
                        what="t→1")


@given(S.poses(), S.poses(), st.floats(0.0, 1.0, exclude_max=True))
def test_pose_interpolate_follows_twist(a, b, t):
    tw = b.minus(a).log()
    got = a.interpolate(b, t)
    part = got.minus(a).log()
    sc = _scale(a, b)
    rel = 2 * RT
    S.assert_close(part.dx, tw.dx * t, sc, rel=rel, what="dx")
    S.assert_close(part.dy, tw.dy * t, sc, rel=rel, what="dy")
    S.assert_angle_close(part.dtheta, tw.dtheta * t, rel=1e-13, what="dtheta")


@given(S.translations(), S.translations(), S.angles())
def test_transform_from_poses_matches_relative(t1, t2, theta):
    a = Pose2d(t1, Rotation2d(theta))
    b = Pose2d(t2, Rotation2d(-theta))
    tr = Transform2d(a, b)
    exp_t = t2.minus(t1).rotateBy(Rotation2d(theta).unaryMinus())
    S.assert_translation_close(tr.getTranslation(), exp_t, t1.getNorm(), t2.getNorm(),
                               rel=1e-15 * 8)
    S.assert_rot_close(tr.getRotation(), Rotation2d(-2 * theta), theta, rel=1e-14)


@given(S.poses(), st.floats(-10, 10, allow_nan=False))
def test_pose_times(p, k):
    q = p.times(k)
    assert (q.getX(), q.getY()) == (p.getX() * k, p.getY() * k)
    S.assert_rot_close(q.getRotation(), p.getRotation().times(k), rel=0.0)
    S.assert_pose_close(p * k, q, rel=0.0)
