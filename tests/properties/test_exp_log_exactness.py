"""Twist2d.exp, Transform2d.log / Pose2d.log and ChassisVelocities.discretize against
50-digit arithmetic (mpmath): every component within 1e-13 of the exact value, over the
whole angle range and in the small-angle bands where WPILib's formulas cancel (its
``cos θ − 1`` in log near θ ≈ 5e-5, ``1 − cos θ`` in exp near θ ≈ 1e-9).

The exact value is that of the double inputs as given: for log, of the transform whose
rotation is the stored (cos, sin) normalised; for discretize, of the products v·dt taken
exactly and the angle ω·dt as the double WPILib turns into a Rotation2d.
"""
from __future__ import annotations

import numpy as np
import pytest

from drivekin import ChassisVelocities, Pose2d, Rotation2d, Transform2d, Twist2d

mp = pytest.importorskip("mpmath")
mp.mp.dps = 50

TOL = 1e-13
RNG_SEED = 20261126


def _angles(rng, n):
    """Angles log-uniform over [1e-13, π), both signs, plus the cancellation bands."""
    mags = np.exp(rng.uniform(np.log(1e-13), np.log(np.pi), n))
    bands = np.concatenate([rng.uniform(lo, hi, n // 8) for lo, hi in
                            ((1e-10, 1e-8), (1e-6, 1e-4), (4e-5, 6e-5), (3.0, np.pi))])
    mags = np.concatenate([mags, bands, [0.0, 5e-324, 1e-300, 1e-9, 4.5e-5, np.pi]])
    return mags * rng.choice([-1.0, 1.0], mags.size)


def _cases(n=3000):
    rng = np.random.default_rng(RNG_SEED)
    th = _angles(rng, n)
    xy = rng.uniform(-5.0, 5.0, (th.size, 2))
    return [(float(x), float(y), float(t)) for (x, y), t in zip(xy, th)]


CASES = _cases()


def exact_exp(dx, dy, th):
    dx, dy, th = mp.mpf(dx), mp.mpf(dy), mp.mpf(th)
    if th == 0:
        s, c = mp.mpf(1), mp.mpf(0)
    else:
        s, c = mp.sin(th) / th, (1 - mp.cos(th)) / th
    return dx * s - dy * c, dx * c + dy * s, mp.cos(th), mp.sin(th)


def exact_log(x, y, c, s):
    x, y, c, s = (mp.mpf(v) for v in (x, y, c, s))
    norm = mp.sqrt(c * c + s * s)
    c, s = c / norm, s / norm
    th = mp.atan2(s, c)
    h = th / 2
    # (θ/2)·sin θ / (1 − cos θ), written without the cancellation (this is mp, but 1 − c
    # can still vanish at 50 digits when sin θ is subnormal).
    k = h * (1 + c) / s if s != 0 else (mp.mpf(1) if c > 0 else mp.mpf(0))
    return k * x + h * y, -h * x + k * y, th


def _worst(pairs):
    return max(abs(float(mp.mpf(got) - want)) for got, want in pairs)


def test_twist_exp_is_exact():
    worst = 0.0
    for dx, dy, th in CASES:
        tr = Twist2d(dx, dy, th).exp()
        want = exact_exp(dx, dy, th)
        got = (tr.getX(), tr.getY(), tr.getRotation().getCos(), tr.getRotation().getSin())
        worst = max(worst, _worst(zip(got, want)))
    assert worst <= TOL, worst


def test_transform_log_is_exact():
    worst = 0.0
    for x, y, th in CASES:
        rot = Rotation2d(th)
        tw = Transform2d(x, y, rot).log()
        want = exact_log(x, y, rot.getCos(), rot.getSin())
        worst = max(worst, _worst(zip((tw.dx, tw.dy, tw.dtheta), want)))
    assert worst <= TOL, worst


def test_pose_log_is_exact():
    # Pose2d.log(end) is the log of end relative to start: exact for that transform.
    worst = 0.0
    for x, y, th in CASES[:500]:
        start = Pose2d(0.5, -1.0, Rotation2d(0.3))
        end = start.plus(Transform2d(x, y, Rotation2d(th)))
        rel = end.relativeTo(start)
        tw = start.log(end)
        want = exact_log(rel.getX(), rel.getY(), rel.getRotation().getCos(),
                         rel.getRotation().getSin())
        worst = max(worst, _worst(zip((tw.dx, tw.dy, tw.dtheta), want)))
    assert worst <= TOL, worst


@pytest.mark.parametrize("dt", [0.005, 0.02, 0.1])
def test_discretize_is_exact(dt):
    worst = 0.0
    for vx, vy, th in CASES:
        omega = th / dt
        got = ChassisVelocities(vx, vy, omega).discretize(dt)
        mdt = mp.mpf(dt)
        # The angle is the double omega·dt, as WPILib builds Rotation2d(omega·dt) from it:
        # near ±π its rounding decides which way the angle wraps.
        theta = mp.mpf(omega * dt)
        x, y = mp.mpf(vx) * mdt, mp.mpf(vy) * mdt
        if abs(theta) > mp.pi:      # the angle passes through a Rotation2d: wrapped
            theta = mp.atan2(mp.sin(theta), mp.cos(theta))
        h = theta / 2
        k = mp.mpf(1) if theta == 0 else h * mp.cos(h) / mp.sin(h)
        want = ((k * x + h * y) / mdt, (-h * x + k * y) / mdt, theta / mdt)
        worst = max(worst, _worst(zip((got.vx, got.vy, got.omega), want)))
    assert worst <= TOL, worst
