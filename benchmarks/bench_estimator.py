"""Pose estimators: drivekin's SwerveDrivePoseEstimator against robotpy-wpimath's
SwerveDrive4PoseEstimator (updateWithTime, addVisionMeasurement, sampleAt on a full 1.5 s
history); cases in registry.py, ratios in ``ratio_table.py``.

Run: `pytest benchmarks --benchmark-only` (from the repository root); see
``_bench.bench_tests`` for what is collected.
"""
from _bench import bench_tests

test_bench, test_values_agree = bench_tests("estimator")
