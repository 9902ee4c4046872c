"""ChassisVelocities: discretize, field -> robot relative (cases in registry.py).

Run: `pytest benchmarks --benchmark-only` (from the repository root); see
``_common.bench_tests`` for what is collected.
"""
from _common import bench_tests

test_bench, test_values_agree = bench_tests("chassis")
