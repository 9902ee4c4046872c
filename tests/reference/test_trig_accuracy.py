"""drivekin's own sin, cos and atan2 (src/drivekin/_core/dkmath.h) against mpmath.

The bound is at most 1 ulp of the exact value (docs/DESIGN.md, "One trig"), checked on
about two million arguments: uniform and log-uniform ranges, the Cody-Waite range's edge
(2^20) and the Payne-Hanek range beyond it up to the largest double, the doubles nearest
multiples of pi/2 (where the reduction cancels), tiny and subnormal arguments, the known
hardest case for the reduction, and for atan2 every quadrant, the octant boundaries, the
tan(pi/8) switch, signed zeros and infinities. The exact value is mpmath's at 160 bits,
split into a double and its rest, so an error is measured in ulps of the exact value.

The same functions run through drivekin.batch's vectorised loops and through the per-call
scalar path; both are measured here and must agree bit for bit (on every instruction set
this machine offers), and scripts/trig_coefficients.py must reproduce the header's
constants. Under emulation (DRIVEKIN_EMULATED=1) and ASan (DRIVEKIN_ASAN=1) the point
counts are a two-hundredth (tests/_support/mp_oracle.py, DRIVEKIN_TRIG_FRACTION).
"""
from __future__ import annotations

import math
import pathlib
import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("mpmath")
batch = pytest.importorskip("drivekin.batch")

from tests._support.mp_oracle import SCALE, SLOW, exact, ulp_errors   # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
BOUND = 1.0                 # ulps: the documented bound


def sin_cos_arguments():
    rng = np.random.default_rng(20261202)
    n = 1_200_000 // SCALE
    parts = [
        rng.uniform(-4.0, 4.0, 3 * n // 10),                        # angles robots use
        rng.uniform(-100.0, 100.0, n // 10),
        rng.uniform(-2.0 ** 20, 2.0 ** 20, n // 10),                 # the Cody-Waite range
        np.exp(rng.uniform(np.log(2.0 ** 20), np.log(1.7e308), n // 10))
        * rng.choice([-1.0, 1.0], n // 10),                          # Payne-Hanek
        np.exp(rng.uniform(np.log(1e-320), np.log(1e-4), n // 20)),  # tiny, subnormal
    ]
    # The doubles nearest multiples of pi/2 (and a few ulps around them), up to 2^20 and
    # beyond: the reduced argument cancels to a few bits of x there.
    k = np.unique(np.concatenate([np.arange(1, 2000), rng.integers(1, 2 ** 21, n // 20)]))
    near = k * (np.pi / 2)
    parts += [near, -near, np.nextafter(near, 0), np.nextafter(near, np.inf)]
    edge = np.array([2.0 ** 20, -(2.0 ** 20)])
    parts += [edge, np.nextafter(edge, 0), np.nextafter(np.nextafter(edge, 0), 0)]
    # Around pi/4, where the polynomials' error peaks, and the quadrant switches.
    parts += [np.pi / 4 + rng.uniform(-1e-3, 1e-3, n // 20) * rng.choice([-1, 1], n // 20)]
    # The double closest to a multiple of pi/2 (6381956970095103 * 2^797, Muller's
    # Elementary Functions), and other edges.
    parts += [np.array([6381956970095103.0 * 2.0 ** 797, 1.7976931348623157e308,
                        np.nextafter(0.0, 1.0), 2.0 ** -1022, 1e-300, 1.0, 2.0, 3.0])]
    x = np.concatenate(parts)
    return np.concatenate([x, -x])


@pytest.fixture(scope="module")
def sin_cos():
    x = sin_cos_arguments()
    s, c = batch._trig("sincos", x)
    return x, s, c


def test_sin_cos_within_one_ulp(sin_cos):
    x, s, c = sin_cos
    assert len(x) >= 2_000_000 // SCALE
    for name, ours in (("sin", s), ("cos", c)):
        hi, lo = exact(name, x)
        err = ulp_errors(ours, hi, lo)
        worst = int(np.argmax(err))
        print(f"{name}: max {err[worst]:.4f} ulp at x = {x[worst]!r} over {len(x)} points")
        assert err[worst] <= BOUND, f"{name}({x[worst]!r}) is {err[worst]:.4f} ulp off"


def atan2_arguments():
    rng = np.random.default_rng(20261203)
    n = 1_100_000 // SCALE
    mag = lambda k: np.exp(rng.uniform(-30, 30, k))  # noqa: E731
    sign = lambda k: rng.choice([-1.0, 1.0], k)  # noqa: E731
    ys, xs = [], []
    k = 4 * n // 10
    ys.append(rng.standard_normal(k) * mag(k))                       # every quadrant
    xs.append(rng.standard_normal(k) * mag(k))
    for ratio in (np.tan(np.pi / 8), 1.0, np.tan(3 * np.pi / 8)):     # the switches
        k = n // 10
        x = sign(k) * mag(k)
        ys.append(sign(k) * np.abs(x) * ratio * (1 + rng.uniform(-1e-6, 1e-6, k)))
        xs.append(x)
    k = n // 10
    x = sign(k) * mag(k)
    ys.append(x * np.exp(rng.uniform(-745, -20, k)))                 # near the x axis
    xs.append(x)
    ys.append(x)
    xs.append(x * np.exp(rng.uniform(-745, -20, k)))                 # near the y axis
    k = n // 20
    ys.append(sign(k) * np.exp(rng.uniform(-740, 709, k)))           # extreme magnitudes
    xs.append(sign(k) * np.exp(rng.uniform(-740, 709, k)))
    return np.concatenate(ys), np.concatenate(xs)


@pytest.fixture(scope="module")
def atan2():
    y, x = atan2_arguments()
    return y, x, batch._trig("atan2", y, x)


def test_atan2_within_one_ulp(atan2):
    y, x, r = atan2
    assert len(x) >= 1_000_000 // SCALE
    # mpmath has no signed zero: where an argument underflowed to +-0, C99's answer is
    # CPython's math.atan2 (an exact 0, +-pi or +-pi/2, so its bits).
    zero = (y == 0) | (x == 0)
    assert zero.sum() >= 10
    want = np.array([math.atan2(a, b) for a, b in zip(y[zero], x[zero])])
    assert np.array_equal(bits(r[zero]), bits(want))
    y, x, r = y[~zero], x[~zero], r[~zero]
    hi, lo = exact("atan2", y, x)
    err = ulp_errors(r, hi, lo)
    worst = int(np.argmax(err))
    print(f"atan2: max {err[worst]:.4f} ulp at ({y[worst]!r}, {x[worst]!r}) over {len(x)}")
    assert err[worst] <= BOUND, f"atan2({y[worst]!r}, {x[worst]!r}) is {err[worst]:.4f} ulp off"


def bits(a):
    return np.asarray(a, dtype=np.float64).view(np.int64)


SPECIAL = [0.0, -0.0, math.inf, -math.inf, math.nan, 1.0, -1.0, 5e-324, -5e-324,
           1.7976931348623157e308, -1.7976931348623157e308, 1e-310]


def test_sin_cos_special_values():
    x = np.array([0.0, -0.0, math.inf, -math.inf, math.nan, 5e-324, -5e-324, 1e-310])
    s, c = batch._trig("sincos", x)
    assert list(bits(s[:2])) == list(bits([0.0, -0.0]))      # the sign of zero is kept
    assert list(c[:2]) == [1.0, 1.0]
    assert np.isnan(s[2:5]).all() and np.isnan(c[2:5]).all()
    assert list(bits(s[5:])) == list(bits(x[5:]))             # sin x = x for tiny x
    assert list(c[5:]) == [1.0] * 3


def test_atan2_special_values_follow_c99():
    """Annex F: signed zeros, infinities and NaN, as CPython's math.atan2 gives them."""
    pairs = [(a, b) for a in SPECIAL for b in SPECIAL]
    y = np.array([p[0] for p in pairs])
    x = np.array([p[1] for p in pairs])
    r = batch._trig("atan2", y, x)
    for (a, b), got in zip(pairs, r):
        want = math.atan2(a, b)
        if math.isnan(want):
            assert math.isnan(got), (a, b, got)
        elif want in (0.0, math.pi, -math.pi, math.pi / 2, -math.pi / 2, math.pi / 4,
                      -math.pi / 4, 3 * math.pi / 4, -3 * math.pi / 4):
            assert bits([got]) == bits([want]), (a, b, got, want)
        else:
            assert abs(got - want) <= 2 * math.ulp(want), (a, b, got, want)


def test_vector_and_scalar_paths_give_the_same_bits(sin_cos, atan2):
    x, s, c = sin_cos
    y, ax, r = atan2
    extra = np.array(SPECIAL)
    before = batch.SIMD
    isas = batch._isas()
    assert before in isas
    try:
        for isa in isas:
            batch._use_isa(isa)
            s2, c2 = batch._trig("sincos", x)
            assert np.array_equal(bits(s2), bits(s)) and np.array_equal(bits(c2), bits(c)), isa
            assert np.array_equal(bits(batch._trig("atan2", y, ax)), bits(r)), isa
            # Odd lengths and offsets: a value's bits do not depend on its place.
            for lo, hi in ((1, 8), (3, 1000), (5, 1003)):
                s3, c3 = batch._trig("sincos", x[lo:hi].copy())
                assert np.array_equal(bits(s3), bits(s[lo:hi])), (isa, lo, hi)
                assert np.array_equal(bits(c3), bits(c[lo:hi])), (isa, lo, hi)
            e1, e2 = batch._trig("sincos", extra)
            es1, es2 = batch._trig("sincos", extra, scalar=True)
            assert np.array_equal(bits(e1), bits(es1)) and np.array_equal(bits(e2), bits(es2))
    finally:
        batch._use_isa(before)
    m = slice(0, 200_000 // SCALE)
    s4, c4 = batch._trig("sincos", x[m].copy(), scalar=True)
    assert np.array_equal(bits(s4), bits(s[m])) and np.array_equal(bits(c4), bits(c[m]))
    assert np.array_equal(bits(batch._trig("atan2", y[m].copy(), ax[m].copy(), scalar=True)),
                          bits(r[m]))


def test_isa_names_what_runs():
    assert batch.SIMD in ("AVX-512", "AVX2", "SSE2", "NEON", "scalar")
    with pytest.raises(ValueError, match="not available"):
        batch._use_isa("AVX-1024")


@pytest.mark.skipif(SLOW, reason="the Remez exchange is slow under emulation and ASan")
def test_header_constants_are_the_scripts():
    script = ROOT / "scripts" / "trig_coefficients.py"
    if not script.exists() or not (ROOT / "src" / "drivekin" / "_core" / "dkmath.h").exists():
        pytest.skip("needs the source tree")
    run = subprocess.run([sys.executable, str(script), "--check"], capture_output=True,
                         text=True)
    assert run.returncode == 0, run.stderr
