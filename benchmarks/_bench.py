"""The pytest-benchmark test functions of a ``bench_<suite>.py`` file, generated from the
registry (``registry.py``).

A module of its own so that the imports run one way: ``registry`` imports ``_common`` (the
inputs and prebuilt objects), and this module imports ``registry``; ``_common`` imports
neither, and ``ratio_table.py`` needs neither pytest nor this module.
"""
from __future__ import annotations

import pytest

import registry


def bench_tests(*suites: str):
    """Return ``(test_bench, test_values_agree)`` for the registry suites ``suites``.

    A bench file is then ``test_bench, test_values_agree = bench_tests("chassis")``.
    ``test_bench`` has three benchmarks per operation in one pytest-benchmark group
    (robotpy, drivekin façade, drivekin allocation-free path, plus any extra variants; the
    cases live in registry.py), run by ``pytest benchmarks --benchmark-only`` from the
    repository root. ``test_values_agree`` is not a benchmark: it is skipped under
    --benchmark-only and run by a plain ``pytest benchmarks``. The fixtures ``bench_op`` and
    ``check_op`` come from conftest.py. Each call makes new function objects, so the
    parametrize marks of one file never leak into another.
    """
    ops = [op for s in suites for op in registry.suite(s)]

    @pytest.mark.parametrize(
        "op, variant",
        [pytest.param(op, v, id=f"{op.key}-{v}") for op in ops for v in op.variants()])
    def test_bench(bench_op, op, variant):
        bench_op(op, variant)

    @pytest.mark.parametrize("op", [pytest.param(op, id=op.key) for op in ops])
    def test_values_agree(check_op, op):
        check_op(op)

    return test_bench, test_values_agree
