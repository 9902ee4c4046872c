"""drivekin's own sin/cos and atan2 (issue 20): ns per value on each instruction set this
CPU offers, beside numpy's float64 ufuncs and the per-call (scalar) form, in one process.

    python benchmarks/trig.py            # about 10 s
    python benchmarks/trig.py --quick    # CI smoke run

Arrays of --n values (default 4,096, in cache) through ``drivekin.batch``'s private test
hooks ``_trig`` (the array loops every batch function uses) and ``_use_isa``; each figure
is the minimum over --repeats runs of a loop of calls, divided by the values computed.
"""
from __future__ import annotations

import argparse
import sys
import timeit

import numpy as np

import drivekin.batch as batch


def ns_per_value(fn, n, number, repeats):
    return min(timeit.repeat(fn, number=number, repeat=repeats)) / number / n * 1e9


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=4096)
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    n, repeats = (256, 2) if args.quick else (args.n, args.repeats)
    number = max(1, 2_000_000 // n) if not args.quick else 5
    rng = np.random.default_rng(3)
    x = rng.uniform(-10, 10, n)
    y = rng.uniform(-4, 4, n)
    rows = []
    before = batch.SIMD
    try:
        for isa in batch._isas():
            batch._use_isa(isa)
            rows.append((f"drivekin array, {isa}",
                         ns_per_value(lambda: batch._trig("sincos", x), n, number, repeats),
                         ns_per_value(lambda: batch._trig("atan2", y, x), n, number, repeats)))
    finally:
        batch._use_isa(before)
    rows.append(("drivekin per-call form (one value at a time)",
                 ns_per_value(lambda: batch._trig("sincos", x, scalar=True), n, number, repeats),
                 ns_per_value(lambda: batch._trig("atan2", y, x, scalar=True), n, number,
                              repeats)))
    rows.append((f"numpy {np.__version__} (sin + cos; arctan2)",
                 ns_per_value(lambda: (np.sin(x), np.cos(x)), n, number, repeats),
                 ns_per_value(lambda: np.arctan2(y, x), n, number, repeats)))
    print(f"## drivekin trig, ns per value (n = {n:,}, in use: {before})"
          + (" (--quick smoke run)" if args.quick else ""))
    print()
    print("| form | sincos | atan2 |")
    print("|---|---:|---:|")
    for name, a, b in rows:
        print(f"| {name} | {a:.2f} | {b:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
