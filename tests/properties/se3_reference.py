"""Quaternion and SE(3) maths in mpmath, written from the formulas of the 3-D digest
(/work/shared/reference/geometry-3d.md §1.2-1.6), for the 3-D oracle and exactness tests of
this folder: the independent reference where WPILib 2027 changed from robotpy-wpimath 2026
(slerp, ``times``, ``integrate``, ``inverse``, the ``from*`` factories) and the exact value
against which ``Twist3d.exp`` / ``Transform3d.log`` / ``Pose3d.interpolate`` are measured.

Inputs are doubles, taken exactly (``mp.mpf(float)``); results are mpf. Quaternions are
(w, x, y, z) tuples, vectors (x, y, z) tuples, rigid motions (translation, quaternion)
pairs. The exp/log closed forms cancel for small angles (``1 − cos θ`` and ``1 − A``,
``1 − A/2B`` lose about 2·|log₁₀ θ| digits each), so they run with
:func:`digits_for` extra digits, never through a truncated series.
"""
from __future__ import annotations

import functools
import math

import mpmath as mp

DPS = 50        # digits of every result; the closed forms get more (digits_for)


def _at_least_dps(fn):
    """Run fn with at least DPS digits, whatever mpmath's global precision is."""
    @functools.wraps(fn)
    def wrapper(*args):
        with mp.workdps(max(mp.mp.dps, DPS)):
            return fn(*args)
    return wrapper


def digits_for(theta: float) -> int:
    """Working digits for the closed forms at angle theta: DPS plus what they cancel."""
    if 0.0 < theta < 1.0:
        return DPS + 4 * math.ceil(-math.log10(theta)) + 4
    return DPS + 4


def vec(v):
    return tuple(mp.mpf(c) for c in v)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def norm(a):
    return mp.sqrt(dot(a, a))


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def scale(k, a):
    return tuple(k * x for x in a)


# ---- quaternions ------------------------------------------------------------------------
@_at_least_dps
def qmul(a, b):
    """Hamilton product a·b."""
    aw, av = a[0], a[1:]
    bw, bv = b[0], b[1:]
    w = aw * bw - dot(av, bv)
    v = add(add(scale(aw, bv), scale(bw, av)), cross(av, bv))
    return (w,) + v


def qconj(q):
    return (q[0], -q[1], -q[2], -q[3])


@_at_least_dps
def qinv(q):
    n2 = dot(q, q)
    return tuple(c / n2 for c in qconj(q))


@_at_least_dps
def qnormalize(q):
    n = norm(q)
    return tuple(c / n for c in q) if n != 0 else (mp.mpf(1), mp.mpf(0), mp.mpf(0), mp.mpf(0))


@_at_least_dps
def q_from_rvec(r):
    """The unit quaternion of rotation vector r (axis r/|r|, angle |r|)."""
    theta = norm(r)
    if theta == 0:
        return (mp.mpf(1), mp.mpf(0), mp.mpf(0), mp.mpf(0))
    s = mp.sin(theta / 2) / theta
    return (mp.cos(theta / 2),) + scale(s, r)


@_at_least_dps
def q_to_rvec(q):
    """The rotation vector of q (any norm, either sign), the short way round: |r| ≤ π."""
    q = qnormalize(q)
    if q[0] < 0:
        q = tuple(-c for c in q)
    n = norm(q[1:])
    if n == 0:
        return (mp.mpf(0),) * 3
    return scale(2 * mp.atan2(n, q[0]) / n, q[1:])


@_at_least_dps
def q_from_rpy(roll, pitch, yaw):
    """Extrinsic roll about X, then pitch about Y, then yaw about Z: q_z·q_y·q_x."""
    half = [mp.mpf(a) / 2 for a in (roll, pitch, yaw)]
    qx = (mp.cos(half[0]), mp.sin(half[0]), mp.mpf(0), mp.mpf(0))
    qy = (mp.cos(half[1]), mp.mpf(0), mp.sin(half[1]), mp.mpf(0))
    qz = (mp.cos(half[2]), mp.mpf(0), mp.mpf(0), mp.sin(half[2]))
    return qmul(qz, qmul(qy, qx))


@_at_least_dps
def q_pow(q, t):
    """Unit q to the power t, exp(t·log q): (cos tφ, axis·sin tφ) with φ = atan2(|v|, w)."""
    n = norm(q[1:])
    if n == 0:
        return (mp.mpf(1), mp.mpf(0), mp.mpf(0), mp.mpf(0))
    phi = mp.atan2(n, q[0]) * t
    return (mp.cos(phi),) + scale(mp.sin(phi) / n, q[1:])


@_at_least_dps
def slerp(q0, q1, t):
    """WPILib 2027's Rotation3d.interpolate: Δ = q1·q0⁻¹ (negated if Δw < 0), Δ^t·q0."""
    q0, q1 = qnormalize(q0), qnormalize(q1)
    delta = qmul(q1, qconj(q0))
    if delta[0] < 0:
        delta = tuple(-c for c in delta)
    return qnormalize(qmul(q_pow(delta, mp.mpf(t)), q0))


@_at_least_dps
def q_exp(q):
    """The quaternion exponential: e^w·(cos|v|, v·sin|v|/|v|)."""
    n = norm(q[1:])
    ew = mp.exp(q[0])
    s = mp.sin(n) / n if n != 0 else mp.mpf(1)
    return (ew * mp.cos(n),) + scale(ew * s, q[1:])


@_at_least_dps
def rotate(q, v):
    """v rotated by q: the vector part of q·(0, v)·q⁻¹."""
    return qmul(qmul(q, (mp.mpf(0),) + tuple(v)), qinv(q))[1:]


def same_rotation_error(got, want):
    """max |got − ±want| over the components, the sign that fits (q and −q are one rotation)."""
    e1 = max(abs(mp.mpf(g) - w) for g, w in zip(got, want))
    e2 = max(abs(mp.mpf(g) + w) for g, w in zip(got, want))
    return float(min(e1, e2))


# ---- SE(3) ------------------------------------------------------------------------------
def se3_exp(u, r):
    """Twist (u, r) → transform (V·u, q(r)); V = I + BΩ + CΩ², Ω·x = r × x."""
    theta_f = math.sqrt(sum(float(c) ** 2 for c in r))
    with mp.workdps(digits_for(theta_f)):
        u, r = vec(u), vec(r)
        theta = norm(r)
        if theta == 0:
            b, c = mp.mpf(1) / 2, mp.mpf(1) / 6
        else:
            b = 2 * mp.sin(theta / 2) ** 2 / theta ** 2           # (1 − cos θ)/θ²
            c = (theta - mp.sin(theta)) / theta ** 3                # (1 − sin θ/θ)/θ²
        ru = cross(r, u)
        t = add(add(u, scale(b, ru)), scale(c, cross(r, ru)))
        q = q_from_rvec(r)
    return tuple(+x for x in t), tuple(+x for x in q)


def se3_log(t, q):
    """Transform (t, q) → twist (V⁻¹·t, r); V⁻¹ = I − Ω/2 + CΩ², C = (1 − A/2B)/θ²."""
    with mp.workdps(DPS + 10):
        r0 = q_to_rvec(vec(q))
    theta_f = float(norm(r0))
    with mp.workdps(digits_for(theta_f)):
        t = vec(t)
        r = q_to_rvec(vec(q))
        theta = norm(r)
        if theta == 0:
            c = mp.mpf(1) / 12
        else:
            a = mp.sin(theta) / theta
            b = 2 * mp.sin(theta / 2) ** 2 / theta ** 2
            c = (1 - a / (2 * b)) / theta ** 2
        rt = cross(r, t)
        u = add(add(t, scale(-mp.mpf(1) / 2, rt)), scale(c, cross(r, rt)))
    return tuple(+x for x in u), tuple(+x for x in r)


@_at_least_dps
def compose(a, b):
    """a then b in a's frame (Pose3d.transformBy): (ta + qa·tb, qa·qb)."""
    (ta, qa), (tb, qb) = a, b
    return add(ta, rotate(qa, tb)), qmul(qa, qb)


@_at_least_dps
def relative(a, o):
    """a seen from o (a.relativeTo(o), a − o): (qo⁻¹·(ta − to), qo⁻¹·qa)."""
    (ta, qa), (to, qo) = a, o
    qo_inv = qinv(qo)
    return rotate(qo_inv, add(ta, scale(-1, to))), qmul(qo_inv, qa)


def pose_interpolate(start, end, t):
    """Pose3d.interpolate for 0 < t < 1: start + exp(t·log(end − start)), exactly."""
    with mp.workdps(DPS + 40):
        start = (vec(start[0]), qnormalize(vec(start[1])))
        end = (vec(end[0]), qnormalize(vec(end[1])))
        rel_t, rel_q = relative(end, start)
        u, r = se3_log(rel_t, rel_q)
        k = mp.mpf(t)
        step = se3_exp(scale(k, u), scale(k, r))
        return compose(start, step)
