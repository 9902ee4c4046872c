"""Mecanum and differential drives (IK, FK, desaturate) and odometry update for all three
drivetrains (swerve, mecanum, differential); cases in registry.py.

For odometry, drivekin has one form, so the façade and allocation-free cases time the
same statement. Run: `pytest benchmarks --benchmark-only` (from the repository root); see
``_bench.bench_tests`` for what is collected.
"""
from _bench import bench_tests

test_bench, test_values_agree = bench_tests("mecanum", "differential", "odometry")
