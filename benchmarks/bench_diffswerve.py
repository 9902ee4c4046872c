"""Differential swerve pods (drivekin-only: no robotpy peer): conversions, per-pod and
drive-level desaturation; cases in registry.py, absolute times and ratios to drivekin
baselines in ``ratio_table.py``.

Run: `pytest benchmarks --benchmark-only` (from the repository root); see
``_bench.bench_tests`` for what is collected.
"""
from _bench import bench_tests

test_bench, test_values_agree = bench_tests("diffswerve")
