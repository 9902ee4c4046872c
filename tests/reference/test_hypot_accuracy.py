"""drivekin's own hypot (src/drivekin/_core/dkmath.h) against mpmath, through
Translation2d.getNorm (which is that function, called once).

The bound is under 1 ulp of the exact value (docs/DESIGN.md, "One trig"), checked on a
seeded set: robot-sized vectors, every magnitude from the subnormals to the largest
double, pairs of nearly equal and of very different magnitudes, both components
subnormal, and results near overflow. Special values follow C99 Annex F
(hypot(inf, NaN) = inf).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

mp = pytest.importorskip("mpmath")

from drivekin import Rotation2d, Translation2d                        # noqa: E402
from tests._support.mp_oracle import SCALE, exact, magnitudes, ulp_errors   # noqa: E402

BOUND = 1.0                 # ulps: the documented bound (strictly below)


def arguments():
    rng = np.random.default_rng(20261204)
    n = 25_000 // SCALE
    sign = lambda k: rng.choice([-1.0, 1.0], k)  # noqa: E731
    xs, ys = [], []
    xs.append(rng.uniform(-6, 6, 2 * n))                                 # robot sizes
    ys.append(rng.uniform(-6, 6, 2 * n))
    xs.append(sign(2 * n) * magnitudes(rng, 2 * n, -1074, 1024))         # every binade
    ys.append(sign(2 * n) * magnitudes(rng, 2 * n, -1074, 1024))
    x = sign(2 * n) * magnitudes(rng, 2 * n, -1074, 1024)                # near equal
    xs.append(x)
    ys.append(x * (1 + rng.uniform(-1e-3, 1e-3, 2 * n)))
    x = magnitudes(rng, n, -1074, 1024)                                  # ratio 2^-70..1
    xs.append(x)
    ys.append(np.ldexp(x, -rng.integers(0, 70, n)) * rng.uniform(0.5, 1, n))
    xs.append(magnitudes(rng, n, -1074, -1022))                          # both subnormal
    ys.append(magnitudes(rng, n, -1074, -1022))
    xs.append(magnitudes(rng, n, 1020, 1024))                            # near overflow
    ys.append(magnitudes(rng, n, 1018, 1022))
    x, y = np.concatenate(xs), np.concatenate(ys)
    keep = np.hypot(x / 4, y / 4) < np.finfo(float).max / 4     # a finite result
    return x[keep], y[keep]


def norms(x, y):
    return np.array([Translation2d(float(a), float(b)).getNorm() for a, b in zip(x, y)])


def test_hypot_within_one_ulp():
    x, y = arguments()
    assert len(x) >= 200_000 // SCALE
    ours = norms(x, y)
    hi, lo = exact("hypot", x, y)
    err = ulp_errors(ours, hi, lo)
    # A subnormal result's rest is below the smallest double (lo would round): measured
    # in mpmath instead, in units of 2^-1074.
    sub = np.flatnonzero(hi < 2.0 ** -1022)
    assert len(sub) >= 1000 // SCALE
    with mp.workprec(200):
        err[sub] = [float(abs(mp.mpf(float(ours[i])) - mp.hypot(float(x[i]), float(y[i])))
                          * mp.mpf(2) ** 1074) for i in sub]
    worst = int(np.argmax(err))
    print(f"hypot: max {err[worst]:.4f} ulp at ({x[worst]!r}, {y[worst]!r}) over {len(x)}; "
          f"normal results: max {np.delete(err, sub).max():.4f}")
    assert err[worst] < BOUND, f"hypot({x[worst]!r}, {y[worst]!r}) is {err[worst]:.4f} ulp off"
    # A normal result is rounded once, from a value good to far better than an ulp.
    assert np.delete(err, sub).max() < 0.51


def test_hypot_special_values_follow_c99():
    inf, nan = math.inf, math.nan
    for a, b, want in [
            (inf, nan, inf), (nan, -inf, inf), (-inf, 1.0, inf), (3.0, inf, inf),
            (0.0, -0.0, 0.0), (-0.0, -0.0, 0.0), (-3.0, 0.0, 3.0), (5e-324, 0.0, 5e-324),
            (5e-324, 5e-324, 5e-324), (1.7976931348623157e308, 1e300, 1.7976931348623157e308),
            (1.7976931348623157e308, 1.7976931348623157e308, inf)]:
        got = Translation2d(a, b).getNorm()
        assert math.copysign(1.0, got) == 1.0 and got == want, (a, b, got)
    for a, b in [(nan, 1.0), (1.0, nan), (nan, nan), (nan, 0.0)]:
        assert math.isnan(Translation2d(a, b).getNorm()), (a, b)


@pytest.mark.parametrize("x, y", [(1.3e308, 1.3e308), (-1.7e308, 1e308), (1e308, -1.5e308),
                                  (1.7976931348623157e308, 5e-324)])
def test_rotation_of_a_vector_whose_norm_overflows(x, y):
    """Rotation2d(x, y) is the direction of (x, y) even where |(x, y)| exceeds the doubles
    (robotpy-wpimath's divides by an infinite hypot and stores (0, 0))."""
    r = Rotation2d(x, y)
    mp = mp = pytest.importorskip("mpmath")
    with mp.workprec(160):
        m = mp.hypot(x, y)
        c, s = float(mp.mpf(x) / m), float(mp.mpf(y) / m)
    # Two roundings (the norm's and the quotient's): within 2 ulps of 1.
    assert abs(r.getCos() - c) <= 2 * 2.0 ** -53 and abs(r.getSin() - s) <= 2 * 2.0 ** -53
    assert r.getRadians() == pytest.approx(math.atan2(y, x), rel=1e-15, abs=1e-300)
