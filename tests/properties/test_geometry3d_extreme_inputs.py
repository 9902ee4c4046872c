"""3-D geometry at the ends of the double range (issue 29): finite input gives a finite
result, a stored Rotation3d quaternion unit to a few ulps, or a documented ValueError.

WPILib's normalisation n = sqrt(((w² + x²) + y²) + z²) loses precision where the squared
norm is subnormal (Quaternion(0, 0, 0, 4.2e-160) became z = 1.0000018) and gives 0 where
it overflows; its Rotation3d(axis, angle) multiplies by 1/‖axis‖, inf for a subnormal
axis. drivekin scales by an exact power of two there, and only there: wherever the squared
norm is a normal double the bits are WPILib C++'s (checked here against the formula in
Python floats; the robotpy oracle tests check the same on ordinary inputs).

Exact answers come from mpmath; hypothesis draws from the whole finite float range.
"""
from __future__ import annotations

import math
import pickle
import sys

import pytest
from hypothesis import given, strategies as st

from drivekin import Pose3d, Quaternion, Rotation3d, Transform3d, Translation3d, Twist3d

mp = pytest.importorskip("mpmath")

F = st.floats(allow_nan=False, allow_infinity=False)
VEC = st.lists(F, min_size=3, max_size=3)
HUGE = sys.float_info.max
ULP = sys.float_info.epsilon


def comps(q):
    return (q.w, q.x, q.y, q.z)


def assert_unit(r):
    # Finite, unit to a few ulps, and rebuilt exactly by pickle (which refuses anything
    # more than 1e-9 off unit).
    q = comps(r.getQuaternion())
    assert all(math.isfinite(c) for c in q), q
    assert abs(math.fsum(c * c for c in q) - 1.0) <= 4 * ULP, q
    assert comps(pickle.loads(pickle.dumps(r)).getQuaternion()) == q


def exact_unit(q):
    with mp.workdps(60):
        m = [mp.mpf(c) for c in q]
        n = mp.sqrt(sum(c * c for c in m))
        return [float(c / n) for c in m]


EXTREME_QUATERNIONS = [
    (0.0, 0.0, 0.0, 4.2e-160),          # the issue's: z = 1.0000018 in WPILib
    (1e300, 1e300, 0.0, 0.0),           # squared norm overflows: (0, 0, 0, 0) in WPILib
    (0.0, 0.0, 0.0, 1e-170),            # squares underflow to 0: the identity in WPILib
    (5e-324, 0.0, 0.0, 0.0),            # the smallest subnormal
    (1e308, -1e308, 1e308, 1e308),      # the norm itself overflows
    (3e-200, 4e-200, 0.0, 1e-310),
    (1.7e308, 1e-300, 0.0, 0.0),
]


@pytest.mark.parametrize("q", EXTREME_QUATERNIONS)
def test_normalisation_outside_the_normal_range_is_exact(q):
    want = exact_unit(q)
    for got in (comps(Rotation3d(Quaternion(*q)).getQuaternion()),
                comps(Quaternion(*q).normalize())):
        assert all(abs(g - w) <= ULP for g, w in zip(got, want)), (got, want)
    assert_unit(Rotation3d(Quaternion(*q)))


@given(st.lists(st.floats(-1e150, 1e150), min_size=4, max_size=4))
def test_ordinary_quaternions_keep_wpilib_bits(q):
    w, x, y, z = q
    s = ((w * w + x * x) + y * y) + z * z
    if not sys.float_info.min <= s <= HUGE:
        return
    n = math.sqrt(s)
    want = (w / n, x / n, y / n, z / n)
    assert comps(Rotation3d(Quaternion(*q)).getQuaternion()) == want
    assert comps(Quaternion(*q).normalize()) == want
    assert Quaternion(*q).norm() == n


@pytest.mark.parametrize("q", EXTREME_QUATERNIONS[:4] + [(3e-200, 4e-200, 0.0, 1e-310)])
def test_norm_inverse_and_log_of_extreme_quaternions(q):
    with mp.workdps(60):
        m = [mp.mpf(c) for c in q]
        n2 = sum(c * c for c in m)
        n = mp.sqrt(n2)
        inv = [m[0] / n2] + [-c / n2 for c in m[1:]]
        vn = mp.sqrt(sum(c * c for c in m[1:]))
        k = mp.atan2(vn, m[0]) / vn if vn else 0
        log = [mp.log(n)] + [k * c for c in m[1:]]
    qq = Quaternion(*q)
    assert qq.norm() == pytest.approx(float(n), rel=2 * ULP)
    if float(abs(inv[0]) + sum(abs(c) for c in inv[1:])) < HUGE:
        assert comps(qq.inverse()) == pytest.approx([float(c) for c in inv], rel=4 * ULP)
    else:
        with pytest.raises(ValueError, match="overflows"):
            qq.inverse()
    assert comps(qq.log()) == pytest.approx([float(c) for c in log], rel=4 * ULP, abs=1e-300)


def test_zero_quaternion_is_the_identity_and_has_no_inverse():
    zero = Quaternion(0.0, 0.0, 0.0, 0.0)
    assert comps(Rotation3d(zero).getQuaternion()) == (1.0, 0.0, 0.0, 0.0)
    assert comps(zero.normalize()) == (1.0, 0.0, 0.0, 0.0)
    assert list(zero.toRotationVector()) == [0.0, 0.0, 0.0]
    with pytest.raises(ValueError, match="zero quaternion"):
        zero.inverse()


@pytest.mark.parametrize("i", range(4))
@pytest.mark.parametrize("other", [0.0, 1.0, 4.2e-160, 1e300])
def test_a_nan_component_gives_a_nan_rotation_as_wpilib(i, other):
    # WPILib divides every component by the NaN norm; the scaled paths must not skip the
    # NaN (a maximum that ignores it once turned (0, 0, 0, NaN) into the identity).
    q = [other] * 4
    q[i] = math.nan
    r = Rotation3d(Quaternion(*q)).getQuaternion()
    assert all(math.isnan(c) for c in (r.getW(), r.getX(), r.getY(), r.getZ()))
    assert all(math.isnan(c) for c in Quaternion(*q).toRotationVector())
    assert all(math.isnan(c) for c in Rotation3d(Quaternion(*q)).toVector())


def test_subnormal_rotation_vector_is_the_tiny_rotation():
    # Java: axis·(1/‖axis‖) = 0·inf, a NaN quaternion; C++ and robotpy: the identity.
    q = comps(Rotation3d([0.0, 0.0, 2.2e-313]).getQuaternion())
    assert q[:3] == (1.0, 0.0, 0.0) and abs(q[3] - 1.1e-313) <= 5e-324
    q = comps(Quaternion.fromRotationVector([0.0, 0.0, 2e-313]))
    assert q[:3] == (1.0, 0.0, 0.0) and abs(q[3] - 1e-313) <= 5e-324
    assert_unit(Rotation3d([2.2e-313, -5e-324, 0.0]))


@pytest.mark.parametrize("axis", [[0.0, 0.0, 2.2e-313], [3e-320, 4e-320, 0.0],
                                  [1e308, 1e308, 0.0], [HUGE, HUGE, HUGE]])
def test_axis_angle_with_an_extreme_axis(axis):
    with mp.workdps(60):
        a = [mp.mpf(c) for c in axis]
        n = mp.sqrt(sum(c * c for c in a))
        want = [float(mp.cos(mp.mpf(0.5)))] + [float(c / n * mp.sin(mp.mpf(0.5))) for c in a]
    r = Rotation3d(axis, 1.0)
    assert all(abs(g - w) <= 2 * ULP for g, w in zip(comps(r.getQuaternion()), want))
    assert_unit(r)


@pytest.mark.parametrize("rvec", [[0.0, 1.27e308, 1.27e308], [HUGE, HUGE, HUGE],
                                  [-HUGE, 0.0, HUGE]])
def test_rotation_vector_whose_norm_overflows_keeps_its_axis(rvec):
    # The angle (up to √3 times the largest double) is known only to its rounding, so
    # what is pinned is a unit quaternion about the vector's direction.
    r = Rotation3d(rvec)
    assert_unit(r)
    d = [c / HUGE for c in rvec]
    want = [c / math.sqrt(sum(e * e for e in d)) for c in d]
    for got in (comps(r.getQuaternion()), comps(Quaternion.fromRotationVector(rvec))):
        v = got[1:]
        s = math.copysign(math.sqrt(sum(c * c for c in v)), sum(a * b for a, b in zip(v, d)))
        assert all(abs(a - s * b) <= 4 * ULP for a, b in zip(v, want)), (got, rvec)
        assert abs(math.fsum(c * c for c in got) - 1.0) <= 4 * ULP


def exact_rotation_vector(q):
    with mp.workdps(60):
        m = [mp.mpf(c) for c in q]
        if m[0] < 0:
            m = [-c for c in m]
        vn = mp.sqrt(sum(c * c for c in m[1:]))
        if vn == 0:
            return [0.0, 0.0, 0.0]
        k = 2 * mp.atan2(vn, m[0]) / vn
        return [float(k * c) for c in m[1:]]


@pytest.mark.parametrize("q, want", [
    ((1e-12, 1e-12, 0.0, 0.0), [math.pi / 2, 0.0, 0.0]),    # WPILib's series: 2 rad
    ((1e-170, 1e-170, 0.0, 0.0), [math.pi / 2, 0.0, 0.0]),
    ((1e300, 0.0, 0.0, 1e300), [0.0, 0.0, math.pi / 2]),
    ((-2e-300, 0.0, 2e-300, 0.0), [0.0, -math.pi / 2, 0.0]),
])
def test_to_rotation_vector_does_not_depend_on_the_norm(q, want):
    assert list(Quaternion(*q).toRotationVector()) == pytest.approx(want, abs=2 * ULP)


@given(st.lists(F, min_size=4, max_size=4))
def test_to_rotation_vector_is_exact_over_the_whole_range(q):
    got = Quaternion(*q).toRotationVector()
    want = exact_rotation_vector(q)
    if abs(math.hypot(*want) - math.pi) <= 8 * ULP and got @ want < 0:
        want = [-w for w in want]     # a half turn: θ = π and −π are the same rotation
    assert all(abs(g - w) <= 8 * ULP for g, w in zip(got, want)), (list(got), want)


@pytest.mark.parametrize("scale", [1e-200, 5e-324 * 2**20, 1e200, 1e308])
def test_initial_final_vectors_of_any_size(scale):
    r = Rotation3d([scale, 0.0, 0.0], [0.0, scale, 0.0])
    want = (math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5))
    assert comps(r.getQuaternion()) == pytest.approx(want, abs=2 * ULP)


def test_overflow_is_refused():
    with pytest.raises(ValueError, match="overflows"):
        Quaternion(1000.0, 0.0, 0.0, 0.0).exp()
    with pytest.raises(ValueError, match="overflows"):
        Quaternion(2.0, 0.0, 0.0, 0.0).pow(2000.0)
    with pytest.raises(ValueError, match="overflows"):
        Quaternion(5e-324, 0.0, 0.0, 0.0).inverse()
    r = Rotation3d(0.0, 0.0, 3.0)
    for call in (lambda: r.times(HUGE), lambda: r.div(0.0), lambda: r.div(5e-324),
                 lambda: Rotation3d().interpolate(r, HUGE),
                 lambda: r.integrate(0.0, 0.0, 3.0, 1.2e308),
                 lambda: Pose3d(Translation3d(), r).times(HUGE),
                 lambda: Transform3d(Translation3d(), r).div(1e-320)):
        with pytest.raises(ValueError, match="beyond the largest double"):
            call()
    # Above 1e300 turns every double is a whole number of turns.
    assert comps(Rotation3d.fromRotations(1e308, -1e301, 0.0).getQuaternion()) == (
        1.0, 0.0, 0.0, 0.0)


def refused_or_unit(make):
    try:
        r = make()
    except ValueError as e:
        assert "beyond the largest double" in str(e)
        return
    assert_unit(r)


@given(st.lists(F, min_size=4, max_size=4), VEC, F, st.lists(F, min_size=3, max_size=3), VEC)
def test_constructors_give_unit_rotations(q, v, angle, rpy, v2):
    for make in (lambda: Rotation3d(Quaternion(*q)), lambda: Rotation3d(v),
                 lambda: Rotation3d(v, angle), lambda: Rotation3d(*rpy),
                 lambda: Rotation3d.fromDegrees(*rpy), lambda: Rotation3d.fromRotations(*rpy),
                 lambda: Rotation3d(v, v2)):
        assert_unit(make())
    qq = Quaternion.fromRotationVector(v)
    assert all(math.isfinite(c) for c in comps(qq))
    assert abs(math.fsum(c * c for c in comps(qq)) - 1.0) <= 4 * ULP


@given(st.lists(F, min_size=4, max_size=4), F)
def test_quaternion_algebra_is_finite_or_refused(q, t):
    qq = Quaternion(*q)
    assert all(math.isfinite(c) for c in qq.toRotationVector())
    for f in (qq.normalize, qq.log, qq.exp, qq.inverse, lambda: qq.pow(t)):
        try:
            r = f()
        except ValueError as e:
            assert "overflows" in str(e) or "zero quaternion" in str(e)
            continue
        assert all(math.isfinite(c) for c in comps(r)), (q, r)


@given(VEC, VEC, F, st.lists(F, min_size=4, max_size=4))
def test_rotation_operations_are_unit_or_refused(v, v2, t, rates):
    a, b = Rotation3d(v), Rotation3d(v2)
    for make in (lambda: a.times(t), lambda: a.div(t), lambda: a.interpolate(b, t),
                 lambda: a.integrate(*rates), lambda: a.rotateBy(b), lambda: a.relativeTo(b),
                 a.inverse):
        refused_or_unit(make)
    assert all(math.isfinite(c) for c in (*a.toVector(), a.getX(), a.getY(), a.getZ(),
                                           a.getAngle(), *a.getAxis(), *a.toMatrix().ravel()))


BOUNDED = st.floats(-1e300, 1e300)   # translations whose sums cannot overflow


@given(st.lists(BOUNDED, min_size=9, max_size=9), VEC, VEC, F)
def test_twists_and_poses_are_finite(u, r1, r2, t):
    tw = Twist3d(*u[:3], *r1)
    e = tw.exp()
    assert all(math.isfinite(c) for c in (e.x, e.y, e.z)), tw
    assert_unit(e.rotation())
    lg = e.log()
    assert all(math.isfinite(c) for c in (lg.dx, lg.dy, lg.dz, lg.rx, lg.ry, lg.rz))
    a = Pose3d(Translation3d(*u[3:6]), Rotation3d(r1))
    b = Transform3d(Translation3d(*u[6:]), Rotation3d(r2))
    for p in (a + b, a.relativeTo(Pose3d(Translation3d(*u[6:]), Rotation3d(r2))),
              b.inverse(), a.interpolate(a + b, t)):
        assert all(math.isfinite(c) for c in (p.x, p.y, p.z))
        assert_unit(p.rotation())
