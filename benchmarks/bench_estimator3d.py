"""3-D odometry and pose estimation (issue 29): SwerveDriveOdometry3d.update and
SwerveDrivePoseEstimator3d's updateWithTime and addVisionMeasurement against robotpy-wpimath
2026.2.2's SwerveDrive4Odometry3d / SwerveDrive4PoseEstimator3d; cases in registry3d.py,
ratios in ``ratio_table.py``.

Run: `pytest benchmarks --benchmark-only` (from the repository root); see
``_bench.bench_tests`` for what is collected.
"""
from _bench import bench_tests

test_bench, test_values_agree = bench_tests("estimator3d")
