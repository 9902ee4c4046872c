"""Swerve drive (4 modules): IK, FK, both desaturate forms.

Three benchmarks per operation in one pytest-benchmark group: robotpy, drivekin façade,
drivekin allocation-free path (plus any extra variants); the cases live in registry.py.
Run: `pytest benchmarks --benchmark-only` (from the repository root).
"""
import pytest

import registry

SUITE = "swerve"
OPS = registry.suite(SUITE)


@pytest.mark.parametrize(
    "op, variant",
    [pytest.param(op, v, id=f"{op.key}-{v}") for op in OPS for v in op.variants()])
def test_bench(bench_op, op, variant):
    bench_op(op, variant)


@pytest.mark.parametrize("op", [pytest.param(op, id=op.key) for op in OPS])
def test_values_agree(check_op, op):
    # Not a benchmark: skipped under --benchmark-only, run by a plain `pytest benchmarks`.
    check_op(op)
