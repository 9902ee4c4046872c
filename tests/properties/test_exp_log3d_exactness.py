"""Twist3d.exp, Transform3d.log and Pose3d.interpolate against exact arithmetic (mpmath,
tests/properties/se3_reference.py): every component within 1e-13 of the exact value, the
translation per metre (error / max(1 m, |translation|)), for rotation angles log-spaced
from 1e-12 to π about random axes, with extra points in the bands where WPILib's closed
forms cancel (just above its 1e-7 series threshold, 1e-6, 1e-5, 1e-3) and next to π
(issue 29, deliverable 2).

The exact value is that of the double inputs as given: for exp, of the twist's six
doubles; for log, of the transform's translation and of its stored quaternion (the rotation
vector does not depend on the quaternion's norm or sign); for interpolate, of the two
stored poses and the double t.

robotpy-wpimath 2026.2.2 (``Pose3d.exp`` / ``Pose3d.log``, the same formulas as WPILib
2027's ``Twist3d.exp`` / ``Transform3d.log``) is measured at the same points to show the gap
the issue names; only that it exceeds drivekin's bound in the cancelling bands is asserted.
Measured on x86_64 (largest error per band; translations per metre):

    angle band          Twist3d.exp              Transform3d.log
                     drivekin  robotpy 2026    drivekin  robotpy 2026
    1e-12 .. π       3.3e-16   3.3e-10         4.4e-16   6.1e-3
    1e-7 .. 3e-7     2.0e-16   3.5e-10         1.9e-16   6.6e-3
    1e-6 .. 3e-6     1.9e-16   3.1e-11         2.0e-16   5.7e-5
    1e-5 .. 3e-5     1.9e-16   2.8e-12         2.2e-16   5.8e-7
    1e-3 .. 3e-3     2.0e-16   2.8e-14         2.0e-16   5.0e-11
    3 .. π           3.1e-16   2.7e-16         4.4e-16   6.2e-16

Pose3d.interpolate: 9.9e-16 (robotpy 2026 has none); Pose3d.exp / Pose3d.log: 9.0e-16.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from drivekin import Pose3d, Quaternion, Rotation3d, Transform3d, Translation3d, Twist3d
from tests._support.mp_oracle import SCALE

mp = pytest.importorskip("mpmath")
from tests.properties import se3_reference as R  # noqa: E402  (needs mpmath)

TOL = 1e-13
RNG_SEED = 20261204
# A 1/SCALE-th of the points under emulation, ASan and DRIVEKIN_TRIG_FRACTION (mp_oracle).
N_LOG_SPACED = max(40, 1000 // SCALE)
BANDS = {                      # name: (lo, hi) of the rotation angle, rad
    "1e-7": (1e-7, 3e-7),      # just above WPILib's series threshold
    "1e-6": (1e-6, 3e-6),
    "1e-5": (1e-5, 3e-5),
    "1e-3": (1e-3, 3e-3),
    "pi": (3.0, math.pi),
}
N_PER_BAND = max(4, 100 // SCALE)


def _unit(rng):
    v = rng.normal(size=3)
    return v / math.sqrt(v @ v)


def _angles(rng):
    """(band name, angle) pairs: log-uniform over [1e-12, π] plus the bands."""
    out = [("log-spaced", float(a)) for a in
           np.exp(rng.uniform(math.log(1e-12), math.log(math.pi), N_LOG_SPACED))]
    out += [("log-spaced", a) for a in (0.0, 1e-12, 1e-9, math.nextafter(1e-7, 0.0), 1e-7,
                                        math.pi)]
    for name, (lo, hi) in BANDS.items():
        out += [(name, float(a)) for a in rng.uniform(lo, hi, N_PER_BAND)]
    return out


def _cases():
    rng = np.random.default_rng(RNG_SEED)
    cases = []
    for band, theta in _angles(rng):
        axis = _unit(rng)
        u = rng.uniform(-5.0, 5.0, 3)
        flip = bool(rng.integers(2))        # log: q or −q, the same rotation
        cases.append((band, theta, tuple(float(c) for c in u),
                      tuple(float(c) for c in axis * theta), flip))
    return cases


CASES = _cases()


def _translation_scale(t):
    return max(1.0, math.sqrt(sum(c * c for c in t)))


def _exp_error(u, got_t, got_q, want):
    want_t, want_q = want
    et = max(abs(float(mp.mpf(g) - w)) for g, w in zip(got_t, want_t)) / _translation_scale(u)
    return max(et, R.same_rotation_error(got_q, want_q))


def _log_error(t, got, want):
    want_u, want_r = want
    eu = max(abs(float(mp.mpf(g) - w)) for g, w in zip(got[:3], want_u)) / _translation_scale(t)
    er = max(abs(float(mp.mpf(g) - w)) for g, w in zip(got[3:], want_r))
    return max(eu, er)


def _quat(rot):
    q = rot.getQuaternion()
    return (q.getW(), q.getX(), q.getY(), q.getZ())


def _log_input(theta, u, r, flip):
    """The transform whose log is measured: translation u, rotation of vector r (as WPILib
    builds it from a quaternion, possibly negated)."""
    half = theta / 2.0
    s = math.sin(half) / theta if theta else 0.5
    q = (math.cos(half), r[0] * s, r[1] * s, r[2] * s)
    if flip:
        q = tuple(-c for c in q)
    return Transform3d(Translation3d(*u), Rotation3d(Quaternion(*q)))


@pytest.fixture(scope="module")
def exp_table():
    """(band, u, r, exact transform) for every case."""
    return [(band, u, r, R.se3_exp(u, r)) for band, _, u, r, _ in CASES]


@pytest.fixture(scope="module")
def log_table():
    """(band, transform, its stored quaternion, exact twist) for every case."""
    out = []
    for band, theta, u, r, flip in CASES:
        tr = _log_input(theta, u, r, flip)
        q = _quat(tr.getRotation())
        out.append((band, tr, q, R.se3_log(u, q)))
    return out


def _by_band(errors):
    worst = {}
    for band, e in errors:
        worst[band] = max(worst.get(band, 0.0), e)
    return worst


def test_twist_exp_is_exact(exp_table):
    errors = []
    for band, u, r, want in exp_table:
        tr = Twist3d(*u, *r).exp()
        assert isinstance(tr, Transform3d)
        errors.append((band, _exp_error(u, (tr.getX(), tr.getY(), tr.getZ()),
                                        _quat(tr.getRotation()), want)))
    worst = _by_band(errors)
    assert max(worst.values()) <= TOL, worst


def test_transform_log_is_exact(log_table):
    errors = []
    for band, tr, _, want in log_table:
        tw = tr.log()
        assert isinstance(tw, Twist3d)
        got = (tw.dx, tw.dy, tw.dz, tw.rx, tw.ry, tw.rz)
        errors.append((band, _log_error((tr.getX(), tr.getY(), tr.getZ()), got, want)))
    worst = _by_band(errors)
    assert max(worst.values()) <= TOL, worst


def test_pose_exp_and_log_forms_are_exact(exp_table):
    # Pose3d.exp(twist) = pose + twist.exp() and start.log(end) = (end − start).log(), the
    # robotpy 2026 forms drivekin keeps: exact for the composed / relative transform.
    rng = np.random.default_rng(RNG_SEED + 2)
    worst = 0.0
    for band, u, r, want in exp_table[::4]:
        start = Pose3d(Translation3d(*rng.uniform(-5.0, 5.0, 3)),
                       Rotation3d(_unit(rng) * rng.uniform(0.0, math.pi)))
        s = ((start.getX(), start.getY(), start.getZ()), _quat(start.getRotation()))
        end = start.exp(Twist3d(*u, *r))
        with mp.workdps(R.DPS + 10):
            want_t, want_q = R.compose((R.vec(s[0]), R.qnormalize(R.vec(s[1]))), want)
        got_t = (end.getX(), end.getY(), end.getZ())
        scale = max(1.0, math.sqrt(sum(c * c for c in s[0])) + _translation_scale(u))
        worst = max(worst, max(abs(float(mp.mpf(g) - w)) for g, w in zip(got_t, want_t)) / scale,
                    R.same_rotation_error(_quat(end.getRotation()), want_q))
        tw = start.log(end)
        e = ((end.getX(), end.getY(), end.getZ()), _quat(end.getRotation()))
        with mp.workdps(R.DPS + 10):
            rel_t, rel_q = R.relative((R.vec(e[0]), R.qnormalize(R.vec(e[1]))),
                                      (R.vec(s[0]), R.qnormalize(R.vec(s[1]))))
        want_log = R.se3_log(rel_t, rel_q)
        worst = max(worst, _log_error(rel_t, (tw.dx, tw.dy, tw.dz, tw.rx, tw.ry, tw.rz),
                                      want_log))
    assert worst <= TOL, worst


def test_pose_interpolate_is_exact():
    # start + exp(t·log(end − start)) for 0 < t < 1, the relative rotation's angle from the
    # same spread (up to 3 rad: at π the short way round is decided by one rounding).
    rng = np.random.default_rng(RNG_SEED + 1)
    worst = 0.0
    for band, theta, u, r, _ in CASES[::3]:
        if theta > 3.0:
            continue
        start = Pose3d(Translation3d(*rng.uniform(-5.0, 5.0, 3)),
                       Rotation3d(_unit(rng) * rng.uniform(0.0, math.pi)))
        end = start.transformBy(Twist3d(*u, *r).exp())
        t = float(rng.uniform(0.0, 1.0))
        got = start.interpolate(end, t)
        pose = lambda p: ((p.getX(), p.getY(), p.getZ()), _quat(p.getRotation()))  # noqa: E731
        want_t, want_q = R.pose_interpolate(pose(start), pose(end), t)
        got_t, got_q = pose(got)
        scale = max(1.0, math.sqrt(sum(c * c for c in got_t)))
        et = max(abs(float(mp.mpf(g) - w)) for g, w in zip(got_t, want_t)) / scale
        worst = max(worst, et, R.same_rotation_error(got_q, want_q))
    assert worst <= TOL, worst


def test_robotpy_2026_is_not_exact(exp_table, log_table):
    """robotpy 2026's Pose3d.exp/log at the same points: its error exceeds drivekin's bound
    where the issue says (log near 1e-7 and 1e-6 rad, exp near 1e-7 rad); nothing else about
    it is asserted."""
    rg = pytest.importorskip("wpimath.geometry")
    exp_errors = []
    for band, u, r, want in exp_table:
        p = rg.Pose3d().exp(rg.Twist3d(*u, *r))
        q = p.rotation().getQuaternion()
        exp_errors.append((band, _exp_error(u, (p.X(), p.Y(), p.Z()),
                                            (q.W(), q.X(), q.Y(), q.Z()), want)))
    log_errors = []
    for band, tr, q, want in log_table:
        end = rg.Pose3d(rg.Translation3d(tr.getX(), tr.getY(), tr.getZ()),
                        rg.Rotation3d(rg.Quaternion(*q)))
        tw = rg.Pose3d().log(end)
        log_errors.append((band, _log_error((tr.getX(), tr.getY(), tr.getZ()),
                                            (tw.dx, tw.dy, tw.dz, tw.rx, tw.ry, tw.rz), want)))
    exp_worst, log_worst = _by_band(exp_errors), _by_band(log_errors)
    table = {"exp": exp_worst, "log": log_worst}
    assert log_worst["1e-7"] > TOL and log_worst["1e-6"] > TOL, table
    assert exp_worst["1e-7"] > TOL, table
