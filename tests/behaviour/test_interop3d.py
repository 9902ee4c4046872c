"""drivekin.interop for the 3-D geometry (Translation3d, Quaternion, Rotation3d, Pose3d,
Transform3d, Twist3d), with robotpy-wpimath 2026 (installed) and 2027 (the stand-ins of
``robotpy2027.py``): every float copied exactly both ways, except that robotpy builds a
Rotation3d only through ``Rotation3d(Quaternion)``, which renormalises (each component
within 4 ulps of drivekin's); fromWpimath copies robotpy's stored quaternion bit for bit;
non-rotations refused; fromWpimath3d still flattens; the hints name the right call."""
from __future__ import annotations

import math
import struct

import numpy as np
import pytest
from hypothesis import given, strategies as st

from drivekin import Pose2d, Pose3d, Quaternion, Rotation3d, Transform3d, Translation3d, Twist3d
from drivekin._core.errors import type_name
from drivekin.interop import fromWpimath, fromWpimath3d, toWpimath
from tests.behaviour.test_interop_robotpy2027 import over_examples, robotpy_2027

NAMES = ("Translation3d", "Quaternion", "Rotation3d", "Pose3d", "Transform3d", "Twist3d")
ROTATING = ("Rotation3d", "Pose3d", "Transform3d")     # hold a robotpy Rotation3d


@pytest.fixture(scope="module")
def g():
    return pytest.importorskip("wpimath.geometry")


@pytest.fixture(params=["2026", "2027"])
def wp(request):
    """Where robotpy-wpimath keeps the geometry classes: robotpy 2026's
    ``wpimath.geometry``, or robotpy 2027's flat ``wpimath`` (the stand-ins, installed for
    the test)."""
    if request.param == "2026":
        yield pytest.importorskip("wpimath.geometry")
    else:
        with robotpy_2027() as package:
            yield package


def bits(x: float) -> bytes:
    return struct.pack("<d", x)


def ulps(a: float, b: float) -> float:
    """|a − b| in ulps of the larger (0 for equal bits; NaN only matches NaN)."""
    if math.isnan(a) or math.isnan(b):
        return 0.0 if math.isnan(a) and math.isnan(b) else math.inf
    return 0.0 if a == b else abs(a - b) / math.ulp(max(abs(a), abs(b)))


# ---- field pictures: (plain floats, quaternion) of either side, read independently -------

def dk_parts(o) -> tuple[tuple[float, ...], tuple[float, ...]]:
    def quat(q):
        return (q.getW(), q.getX(), q.getY(), q.getZ())
    t = type(o)
    if t is Translation3d:
        return (o.getX(), o.getY(), o.getZ()), ()
    if t is Quaternion:
        return quat(o), ()
    if t is Rotation3d:
        return (), quat(o.getQuaternion())
    if t in (Pose3d, Transform3d):
        tr = o.getTranslation()
        return (tr.getX(), tr.getY(), tr.getZ()), quat(o.getRotation().getQuaternion())
    if t is Twist3d:
        return (o.dx, o.dy, o.dz, o.rx, o.ry, o.rz), ()
    raise AssertionError(f"no picture for {t}")


def rp_parts(o) -> tuple[tuple[float, ...], tuple[float, ...]]:
    # robotpy 2027 (module wpimath._wpimath): properties w, x, y, z and get_quaternion();
    # robotpy 2026: methods W() ... and getQuaternion().
    new = type(o).__module__ == "wpimath._wpimath"

    def quat(q):
        return (q.w, q.x, q.y, q.z) if new else (q.W(), q.X(), q.Y(), q.Z())

    def rot(r):
        return quat(r.get_quaternion() if new else r.getQuaternion())
    n = type(o).__name__
    if n == "Translation3d":
        return (o.x, o.y, o.z), ()
    if n == "Quaternion":
        return quat(o), ()
    if n == "Rotation3d":
        return (), rot(o)
    if n in ("Pose3d", "Transform3d"):
        tr = o.translation()
        return (tr.x, tr.y, tr.z), rot(o.rotation())
    if n == "Twist3d":
        return (o.dx, o.dy, o.dz, o.rx, o.ry, o.rz), ()
    raise AssertionError(f"no picture for {type(o)}")


def same_bits(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
    return [bits(x) for x in a] == [bits(x) for x in b]


# ---- strategies ------------------------------------------------------------------------------

anything = st.floats()
# Quaternion components whose norm neither overflows nor has a subnormal square (WPILib's
# normalisation then gives no rotation, or one off unit length: tested apart); a norm
# whose square underflows to 0 gives the identity.
component = st.one_of(st.floats(-1e6, 1e6).filter(lambda v: v == 0.0 or abs(v) >= 1e-150),
                      st.sampled_from([0.0, -0.0, 1.0, -1.0, 1e-300]))
angle = st.one_of(st.floats(-10.0, 10.0), st.sampled_from([0.0, math.pi, -math.pi,
                                                           math.pi / 2, -math.pi / 2]))
# Rotation vectors whose norm is a normal double (WPILib Java and drivekin divide by it).
rvec_component = st.floats(-10.0, 10.0).filter(lambda v: v == 0.0 or abs(v) >= 1e-150)


def dk_rotations():
    return st.one_of(
        st.tuples(component, component, component, component).map(
            lambda q: Rotation3d(Quaternion(*q))),
        st.tuples(angle, angle, angle).map(lambda a: Rotation3d(*a)),
        st.lists(rvec_component, min_size=3, max_size=3).map(Rotation3d))


def rp_rotations(g):
    return st.one_of(
        st.tuples(component, component, component, component).map(
            lambda q: g.Rotation3d(g.Quaternion(*q))),
        st.tuples(angle, angle, angle).map(lambda a: g.Rotation3d(*a)))


def dk_strategy(name):
    r = dk_rotations()
    return {
        "Translation3d": st.builds(Translation3d, anything, anything, anything),
        "Quaternion": st.builds(Quaternion, anything, anything, anything, anything),
        "Rotation3d": r,
        "Pose3d": st.builds(lambda x, y, z, q: Pose3d(Translation3d(x, y, z), q),
                            anything, anything, anything, r),
        "Transform3d": st.builds(lambda x, y, z, q: Transform3d(Translation3d(x, y, z), q),
                                 anything, anything, anything, r),
        "Twist3d": st.builds(Twist3d, *[anything] * 6),
    }[name]


def rp_strategy(name, g):
    r = rp_rotations(g)
    return {
        "Translation3d": st.builds(g.Translation3d, anything, anything, anything),
        "Quaternion": st.builds(g.Quaternion, anything, anything, anything, anything),
        "Rotation3d": r,
        "Pose3d": st.builds(lambda x, y, z, q: g.Pose3d(g.Translation3d(x, y, z), q),
                            anything, anything, anything, r),
        "Transform3d": st.builds(
            lambda x, y, z, q: g.Transform3d(g.Translation3d(x, y, z), q),
            anything, anything, anything, r),
        "Twist3d": st.builds(g.Twist3d, *[anything] * 6),
    }[name]


def check_renormalised(ours: tuple[float, ...], theirs: tuple[float, ...]) -> None:
    """robotpy's quaternion is drivekin's renormalised: each component within 4 ulps."""
    assert len(ours) == len(theirs)
    assert all(ulps(a, b) <= 4 for a, b in zip(ours, theirs)), (ours, theirs)


# ---- round trips, robotpy 2026 and 2027 ----------------------------------------------------

@pytest.mark.parametrize("name", NAMES)
@over_examples
@given(data=st.data())
def test_drivekin_to_wpimath_and_back(wp, name, data):
    obj = data.draw(dk_strategy(name))
    w = toWpimath(obj)
    assert type(w) is getattr(wp, name)
    plain, q = dk_parts(obj)
    w_plain, w_q = rp_parts(w)
    assert same_bits(w_plain, plain)
    check_renormalised(q, w_q)
    if name in ROTATING:
        # robotpy's constructor is the one that renormalised: the same bits as calling it.
        assert same_bits(w_q, rp_parts(wp.Rotation3d(wp.Quaternion(*q)))[1])
    back = fromWpimath(w)
    assert type(back) is type(obj)
    # Back in drivekin: robotpy's stored quaternion, bit for bit.
    assert same_bits(dk_parts(back)[0], plain) and same_bits(dk_parts(back)[1], w_q)


@pytest.mark.parametrize("name", NAMES)
@over_examples
@given(data=st.data())
def test_wpimath_to_drivekin_is_bit_exact(wp, name, data):
    obj = data.draw(rp_strategy(name, wp))
    d = fromWpimath(obj)
    assert type(d).__name__ == name and type(d).__module__ == "drivekin.geometry3d"
    assert same_bits(dk_parts(d)[0], rp_parts(obj)[0])
    assert same_bits(dk_parts(d)[1], rp_parts(obj)[1])
    back = toWpimath(d)
    assert type(back) is type(obj)
    assert same_bits(rp_parts(back)[0], rp_parts(obj)[0])
    check_renormalised(rp_parts(obj)[1], rp_parts(back)[1])


# ---- robotpy 2026: renormalising, refusals, sequences, hints ---------------------------------

def test_the_renormalising_moves_at_most_4_ulps_and_does_move(g):
    # drivekin's Rotation3d(Quaternion) normalises as WPILib's C++ does, so a quaternion
    # built by either side's constructor has the same bits; robotpy's constructor applied
    # to an already normalised quaternion moves its components by up to 4 ulps.
    rng = np.random.default_rng(29)
    moved = worst = 0
    for q in rng.uniform(-3.0, 3.0, (3000, 4)).tolist():
        ours = Rotation3d(Quaternion(*q))
        theirs = g.Rotation3d(g.Quaternion(*q))
        assert same_bits(dk_parts(ours)[1], rp_parts(theirs)[1])
        w = toWpimath(ours)
        d = [ulps(a, b) for a, b in zip(dk_parts(ours)[1], rp_parts(w)[1])]
        worst = max(worst, *d)
        moved += any(d)
        assert fromWpimath(w) == ours                    # WPILib's equality
    assert 0 < worst <= 4 and moved > 0


def test_quaternions_are_not_normalised(g):
    for q in ((2.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0), (1.0, 2.0, 3.0, 4.0),
              (math.nan, math.inf, -0.0, 1e-310)):
        w = toWpimath(Quaternion(*q))
        assert same_bits(rp_parts(w)[0], q)
        assert same_bits(dk_parts(fromWpimath(g.Quaternion(*q)))[0], q)


def test_rotations_that_are_no_rotation_are_refused(g):
    # A norm that overflows leaves (0, 0, 0, 0) in robotpy (WPILib divides by inf), which
    # robotpy would take for the identity: drivekin refuses it. drivekin's own constructor
    # scales first and keeps the rotation, which converts as any other.
    huge = (1e300, 1e300, 0.0, 0.0)
    theirs = g.Rotation3d(g.Quaternion(*huge))
    assert rp_parts(theirs)[1] == (0.0, 0.0, 0.0, 0.0)
    with pytest.raises(ValueError, match=r"fromWpimath\(\): .*Rotation3d.*not a unit "
                                         r"quaternion"):
        fromWpimath(g.Pose3d(g.Translation3d(), theirs))
    ours = Rotation3d(Quaternion(*huge))
    # Scaled by an exact power of two, then WPILib's normalisation: robotpy's (1, 1, 0, 0).
    assert dk_parts(ours)[1] == rp_parts(g.Rotation3d(g.Quaternion(1.0, 1.0, 0.0, 0.0)))[1]
    back = rp_parts(toWpimath(Transform3d(Translation3d(), ours)))[1]
    assert all(abs(a - b) <= 4 * math.ulp(0.7) for a, b in zip(back, dk_parts(ours)[1]))


def test_non_finite_rotations_stay_nan(g):
    for r in (Rotation3d(math.nan, 0.0, 0.0), Rotation3d(math.inf, 1.0, 2.0)):
        assert all(math.isnan(v) for v in rp_parts(toWpimath(r))[1])
    assert all(math.isnan(v) for v in dk_parts(fromWpimath(g.Rotation3d(math.nan, 0, 0)))[1])


def test_sequences_and_flattening(g):
    items = [Pose3d(Translation3d(1.0, 2.0, 3.0), Rotation3d(0.1, 0.2, 0.3)),
             Twist3d(1.0, 2.0, 3.0, 0.1, 0.2, 0.3)]
    out = toWpimath(tuple(items))
    assert type(out) is tuple and [type(o) for o in out] == [g.Pose3d, g.Twist3d]
    back = fromWpimath(list(out))
    assert type(back) is list and back == items
    # fromWpimath keeps the third dimension; fromWpimath3d still takes the 2-D part.
    p3 = g.Pose3d(1.5, -2.0, 0.7, g.Rotation3d(0.1, 0.2, 2.5))
    assert type(fromWpimath(p3)) is Pose3d and fromWpimath(p3).getZ() == 0.7
    flat, want = fromWpimath3d(p3), p3.toPose2d()
    assert type(flat) is Pose2d and (flat.x, flat.y) == (want.x, want.y)
    assert (flat.getRotation().getCos(), flat.getRotation().getSin()) == \
        (want.rotation().cos(), want.rotation().sin())


@pytest.mark.parametrize("name, expected, hint", [
    ("Pose3d", Pose3d, "fromWpimath(value)"),
    ("Pose3d", None, "fromWpimath(value)"),
    ("Pose3d", Pose2d, "fromWpimath3d(value)"),
    ("Rotation3d", Rotation3d, "fromWpimath(value)"),
    ("Twist3d", Twist3d, "fromWpimath(value)"),
    ("Quaternion", Quaternion, "fromWpimath(value)"),
    ("Twist3d", Pose3d, None),
    ("Pose3d", Rotation3d, None),
])
def test_hints_name_the_call_that_gives_what_is_expected(g, name, expected, hint):
    value = getattr(g, name)()
    text = type_name(value, expected)
    full = f"{type(value).__module__}.{type(value).__qualname__}"
    assert text == full if hint is None else text.startswith(full) and text.endswith(
        f"drivekin.interop.{hint})")


def test_a_robotpy_3d_object_passed_to_drivekin_gets_the_conversion(g):
    with pytest.raises(TypeError, match=r"other must be a Pose3d, got wpimath\.geometry\."
                                        r"_geometry\.Pose3d \(a robotpy-wpimath object: "
                                        r"convert it with drivekin\.interop\.fromWpimath"):
        Pose3d().relativeTo(g.Pose3d())
