"""3-D geometry (issue 29): Rotation3d, Pose3d, Transform3d and Twist3d against robotpy-wpimath
2026.2.2's; cases in registry3d.py, ratios in ``ratio_table.py``.

Run: `pytest benchmarks --benchmark-only` (from the repository root); see
``_bench.bench_tests`` for what is collected.
"""
from _bench import bench_tests

test_bench, test_values_agree = bench_tests("geometry3d")
