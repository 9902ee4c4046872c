"""Hypothesis strategies and tolerance helpers shared by the drivekin tests.

Imported by the test modules as ``from tests._support import strategies as S``.

Raw-number strategies (``*_tuples``, :func:`swerve_layouts`) exist so that the same
inputs can be fed to drivekin and to the robotpy oracle; the object strategies build
drivekin values from them.
"""
from __future__ import annotations

import math

import numpy as np
from hypothesis import assume
from hypothesis import strategies as st

from drivekin.geometry import Pose2d, Rotation2d, Transform2d, Translation2d, Twist2d

PI = math.pi
TAU = 2.0 * math.pi

# ---------------------------------------------------------------------------------------
# Scalars


def finite_floats(bound: float = 1e3, *, min_value: float | None = None,
                  allow_subnormal: bool = True) -> st.SearchStrategy[float]:
    """Finite floats in [-bound, bound] (or [min_value, bound])."""
    lo = -bound if min_value is None else min_value
    return st.floats(lo, bound, allow_nan=False, allow_infinity=False,
                     allow_subnormal=allow_subnormal)


def positive_floats(lo: float = 1e-3, hi: float = 1e3) -> st.SearchStrategy[float]:
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)


# Angles that exercise branch points: the series branches of exp (|θ| < 1e-9) and log
# (|cos θ − 1| < 1e-9, i.e. |θ| up to ~4.5e-5), the ±π wrap and quarter turns.
SPECIAL_ANGLES = (0.0, -0.0, 1e-12, -1e-10, 1e-9, 4e-5, -4.6e-5, 1e-3,
                  PI / 4, PI / 2, -PI / 2, 3 * PI / 4, PI, -PI, math.nextafter(PI, 0.0),
                  1.5 * PI, TAU, -3 * PI)


def angles(bound: float = 4 * PI) -> st.SearchStrategy[float]:
    """Angles in rad, any winding within ±bound, with the special values mixed in."""
    return st.one_of(st.sampled_from([a for a in SPECIAL_ANGLES if abs(a) <= bound]),
                     finite_floats(bound))


def wrapped_angles(margin: float = 0.0) -> st.SearchStrategy[float]:
    """Angles strictly inside (−π + margin, π − margin)."""
    hi = PI - margin
    specials = [a for a in SPECIAL_ANGLES if -hi < a < hi]
    return st.one_of(st.sampled_from(specials),
                     st.floats(-hi, hi, exclude_min=True, exclude_max=True,
                               allow_nan=False))


# ---------------------------------------------------------------------------------------
# Geometry (raw tuples + drivekin objects)


def translation_tuples(bound: float = 1e3):
    return st.tuples(finite_floats(bound), finite_floats(bound))


def pose_tuples(bound: float = 1e3, angle_bound: float = 4 * PI):
    """(x, y, theta)."""
    return st.tuples(finite_floats(bound), finite_floats(bound), angles(angle_bound))


def twist_tuples(bound: float = 1e3, dtheta=None):
    """(dx, dy, dtheta)."""
    return st.tuples(finite_floats(bound), finite_floats(bound),
                     angles() if dtheta is None else dtheta)


def translations(bound: float = 1e3) -> st.SearchStrategy[Translation2d]:
    return translation_tuples(bound).map(lambda t: Translation2d(*t))


def rotations(bound: float = 4 * PI) -> st.SearchStrategy[Rotation2d]:
    return angles(bound).map(Rotation2d)


def poses(bound: float = 1e3) -> st.SearchStrategy[Pose2d]:
    return pose_tuples(bound).map(lambda t: Pose2d(t[0], t[1], Rotation2d(t[2])))


def transforms(bound: float = 1e3) -> st.SearchStrategy[Transform2d]:
    return pose_tuples(bound).map(lambda t: Transform2d(t[0], t[1], Rotation2d(t[2])))


def twists(bound: float = 1e3, dtheta=None) -> st.SearchStrategy[Twist2d]:
    return twist_tuples(bound, dtheta).map(lambda t: Twist2d(*t))


# ---------------------------------------------------------------------------------------
# Swerve layouts


def swerve_inverse_matrix(points, cor=(0.0, 0.0)) -> np.ndarray:
    """The 2N×3 first-order inverse-kinematics matrix for module points ``points``
    (rows [1, 0, −ry] and [0, 1, rx] with r = point − cor)."""
    rows = []
    for x, y in points:
        rx, ry = x - cor[0], y - cor[1]
        rows.append([1.0, 0.0, -ry])
        rows.append([0.0, 1.0, rx])
    return np.array(rows, dtype=float)


MAX_LAYOUT_COND = 1e6
MIN_MODULE_SEPARATION = 1e-2


@st.composite
def swerve_layouts(draw, min_modules: int = 2, max_modules: int = 8, sizes=None,
                   bound: float = 3.0):
    """A full-rank swerve layout: a list of N distinct (x, y) module positions in m.

    ``sizes`` (e.g. (2, 3, 4, 6)) restricts N. Layouts whose inverse-kinematics matrix
    has condition number above ``MAX_LAYOUT_COND`` are rejected.
    """
    n = draw(st.sampled_from(tuple(sizes)) if sizes else st.integers(min_modules, max_modules))
    coord = st.floats(-bound, bound, allow_nan=False, allow_infinity=False,
                      allow_subnormal=False)
    common = [(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3), (0.5, 0.0), (-0.5, 0.0),
              (0.0, 0.5), (0.0, -0.5)]
    pts = draw(st.lists(st.one_of(st.sampled_from(common), st.tuples(coord, coord)),
                        min_size=n, max_size=n, unique=True))
    if draw(st.booleans()):
        # Clustered far from the origin: a poorly conditioned (but full-rank) layout.
        k = draw(st.sampled_from([0.1, 0.03]))
        cx, cy = draw(coord), draw(coord)
        pts = [(cx + k * x, cy + k * y) for x, y in pts]
    for i in range(n):
        for j in range(i):
            assume(math.hypot(pts[i][0] - pts[j][0], pts[i][1] - pts[j][1])
                   > MIN_MODULE_SEPARATION)
    assume(np.linalg.cond(swerve_inverse_matrix(pts)) < MAX_LAYOUT_COND)
    return pts


def effective_cor(cor, prev=(0.0, 0.0)):
    """The centre of rotation the inverse rows are built for. WPILib rebuilds them only
    when the CoR differs from the previous one under Translation2d equality (both
    components within 1e-9 m means "the same"), so a nearby CoR keeps ``prev``."""
    if abs(cor[0] - prev[0]) < 1e-9 and abs(cor[1] - prev[1]) < 1e-9:
        return prev
    return cor


# ---------------------------------------------------------------------------------------
# Mecanum layouts


def mecanum_inverse_matrix(points, cor=(0.0, 0.0)) -> np.ndarray:
    """4×3 inverse-kinematics matrix for wheels FL, FR, RL, RR at ``points``
    (rows FL/RR [1, −1, −(rx + ry)] and FR/RL [1, 1, rx − ry] with r = point − cor)."""
    rows = []
    for i, (x, y) in enumerate(points):
        rx, ry = x - cor[0], y - cor[1]
        if i in (0, 3):                  # front left, rear right
            rows.append([1.0, -1.0, -(rx + ry)])
        else:                            # front right, rear left
            rows.append([1.0, 1.0, rx - ry])
    return np.array(rows, dtype=float)


# ---------------------------------------------------------------------------------------
# Chassis velocities


def chassis_tuples(bound: float = 1e3):
    """(vx, vy, omega); sometimes with exact zeros in some components."""
    comp = st.one_of(st.just(0.0), finite_floats(bound))
    return st.tuples(comp, comp, comp)


# ---------------------------------------------------------------------------------------
# Tolerances. A test compares against an absolute error bound rel·max(1, scale), where
# ``scale`` is the magnitude of the quantities the result was computed from. rel = 1e-9
# is the project's accuracy contract; round trips inside drivekin use tighter values.


def tol(*scales: float, rel: float = 1e-9) -> float:
    m = 1.0
    for s in scales:
        m = max(m, abs(s))
    return rel * m


def assert_close(actual: float, expected: float, *scales: float, rel: float = 1e-9,
                 what: str = "value") -> None:
    bound = tol(expected, *scales, rel=rel)
    err = abs(actual - expected)
    assert err <= bound, f"{what}: {actual!r} != {expected!r} (|err| {err:.3g} > {bound:.3g})"


EPS = 2.220446049250313e-16


def log_rel(theta: float, rel: float = 1e-12) -> float:
    """Relative error allowance for comparing with robotpy-wpimath a result that went
    through Transform2d.log and/or Twist2d.exp with rotation angle ``theta`` (use the sum
    of both allowances for a round trip).

    drivekin evaluates both without cancellation (tests/properties/test_exp_log_exactness.py
    holds it to 1e-13 of 50-digit math); robotpy uses WPILib's formulas, whose errors are:

    * log, outside its series branch (|cos θ − 1| ≥ 1e-9), computes
      k = −(θ/2)·sin θ / (cos θ − 1); cos θ − 1 cancels (relative error ≈ ε / |cos θ − 1|,
      about 1e-7 at θ = 4.6e-5 just outside the branch).
    * exp, outside its series branch (|θ| ≥ 1e-9), computes c = (1 − cos θ)/θ whose
      absolute error is about min(|θ|/2, ε/|θ|) (at θ = 1e-9, cos θ rounds to 1 and
      c = 0 instead of 5e-10).
    """
    return rel + _log_part(theta) + exp_rounding(theta)


def _log_part(theta: float) -> float:
    cm1 = abs(math.cos(theta) - 1.0)
    return 0.0 if cm1 < 1e-9 else 8 * EPS / cm1


def exp_rounding(theta: float) -> float:
    """Absolute error (per metre of twist) of WPILib's c = (1 − cos θ)/θ in Twist2d.exp
    outside its series branch: about min(|θ|, ε/|θ|), at most ~1e-8 near |θ| = 1.5e-8.
    Two implementations of that formula can differ by this much when their θ differ in
    the last bits."""
    a = abs(theta)
    return 0.0 if a < 1e-9 else min(a, 4 * EPS / a)


def compose_exp(x, y, th, dx, dy, dth):
    """pose ∘ exp(twist) in plain math: the pose (x, y, th) moved by the twist
    (dx, dy, dth). (1 − cos θ)/θ is written as 2·sin²(θ/2)/θ, which has no cancellation,
    so the only special case is θ = 0 exactly."""
    if dth == 0.0:
        s, c = 1.0, 0.0
    else:
        s = math.sin(dth) / dth
        c = 2.0 * math.sin(0.5 * dth) ** 2 / dth
    tx, ty = s * dx - c * dy, c * dx + s * dy
    ct, st_ = math.cos(th), math.sin(th)
    return x + ct * tx - st_ * ty, y + st_ * tx + ct * ty, th + dth


def angle_diff(a: float, b: float) -> float:
    """Smallest signed difference a − b modulo 2π."""
    return math.remainder(a - b, TAU)


def assert_angle_close(actual: float, expected: float, *scales: float, rel: float = 1e-9,
                       what: str = "angle") -> None:
    bound = tol(*scales, rel=rel)
    err = abs(angle_diff(actual, expected))
    assert err <= bound, f"{what}: {actual!r} !~ {expected!r} mod 2π (|err| {err:.3g} > {bound:.3g})"


def assert_unit_close(c1: float, s1: float, c2: float, s2: float, *scales: float,
                      rel: float = 1e-9, what: str = "rotation") -> None:
    """Compare two rotations as unit vectors (immune to the ±π wrap)."""
    bound = tol(*scales, rel=rel)
    err = math.hypot(c1 - c2, s1 - s2)
    assert err <= bound, (f"{what}: (cos, sin) ({c1!r}, {s1!r}) vs ({c2!r}, {s2!r}) "
                          f"(|err| {err:.3g} > {bound:.3g})")


def rot_tuple(r) -> tuple[float, float]:
    return (r.getCos(), r.getSin())


def assert_rot_close(r1, r2, *scales, rel=1e-9, what="rotation"):
    assert_unit_close(r1.getCos(), r1.getSin(), r2.getCos(), r2.getSin(), *scales,
                      rel=rel, what=what)


def assert_translation_close(t1, t2, *scales, rel=1e-9, what="translation"):
    assert_close(t1.getX(), t2.getX(), *scales, rel=rel, what=what + ".x")
    assert_close(t1.getY(), t2.getY(), *scales, rel=rel, what=what + ".y")


def assert_pose_close(p1, p2, *scales, rel=1e-9, what="pose"):
    """Pose2d/Transform2d comparison: translation within rel·scale, rotation as unit
    vectors within rel·max(1, ...) (rotations are O(1) quantities)."""
    assert_translation_close(p1.getTranslation(), p2.getTranslation(), *scales, rel=rel,
                             what=what)
    assert_rot_close(p1.getRotation(), p2.getRotation(), rel=rel, what=what + ".rotation")
