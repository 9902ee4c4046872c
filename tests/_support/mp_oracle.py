"""mpmath's exact values of drivekin's own math functions (sin, cos, atan2, hypot),
errors in ulps of them, and arguments spread over the binades, for the accuracy and corpus
tests in tests/reference/.

Under emulation (DRIVEKIN_EMULATED=1) and ASan (DRIVEKIN_ASAN=1) the tests use a
two-hundredth of their points (``SCALE``): ASan's allocator makes mpmath about twenty
times slower, and what ASan checks is the loops' memory, which any size exercises.
DRIVEKIN_TRIG_FRACTION=N takes a 1/N-th anywhere (scripts/wheel_tests.sh, on the
cp310-cp313 wheels, whose C the whole run has already measured; .ci/run's main suite, a
quarter, the cp314 x86_64 wheel's whole suite measuring all of them).
"""
from __future__ import annotations

import os
from concurrent.futures import ProcessPoolExecutor

import numpy as np

SLOW = os.environ.get("DRIVEKIN_EMULATED") == "1" or os.environ.get("DRIVEKIN_ASAN") == "1"
SCALE = int(os.environ.get("DRIVEKIN_TRIG_FRACTION", 200 if SLOW else 1))
PREC = 160


def _exact(job):
    """Each value of fn at the arguments as (double, rest) pairs of the exact result."""
    import mpmath as mp    # here: the corpus test uses magnitudes() where mpmath may be absent
    name, args = job
    mp.mp.prec = PREC
    fn = {"sin": mp.sin, "cos": mp.cos, "atan2": mp.atan2, "hypot": mp.hypot}[name]
    hi = np.empty(len(args[0]))
    lo = np.empty(len(args[0]))
    for i, a in enumerate(zip(*args)):
        v = fn(*(mp.mpf(float(t)) for t in a))
        h = float(v)
        hi[i] = h
        lo[i] = float(v - h)
    return hi, lo


def exact(name, *args):
    """mpmath's values of name at args, computed on every core."""
    n = len(args[0])
    if SLOW:  # few points, and no process pool inside a root filesystem
        return _exact((name, list(args)))
    workers = max(1, min(os.cpu_count() or 1, 8))
    step = -(-n // (4 * workers)) or 1
    jobs = [(name, [a[i:i + step] for a in args]) for i in range(0, n, step)]
    with ProcessPoolExecutor(workers) as pool:
        parts = list(pool.map(_exact, jobs))
    return np.concatenate([p[0] for p in parts]), np.concatenate([p[1] for p in parts])


def ulp_errors(ours, hi, lo):
    """|ours - exact| in ulps of the exact value (hi + lo)."""
    spacing = np.spacing(np.abs(hi))
    # Just below a power of two the ulp is half the spacing above it.
    below = (np.frexp(np.abs(hi))[0] == 0.5) & (np.sign(lo) == -np.sign(hi))
    spacing = np.where(below, spacing / 2, spacing)
    spacing = np.maximum(spacing, 2.0 ** -1074)
    return np.abs((ours - hi) - lo) / spacing


def magnitudes(rng, n, lo, hi):
    """n doubles spread over the binades 2^lo .. 2^hi, built exactly (ldexp of uniform
    draws): numpy's exp could round differently on another platform."""
    return np.ldexp(rng.uniform(1.0, 2.0, n), rng.integers(lo, hi, n))
