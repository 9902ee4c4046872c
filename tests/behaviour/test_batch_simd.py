"""The DRIVEKIN_SIMD=1 build of drivekin.batch (libmvec sin, cos and atan2) against the
per-call API: tests/behaviour/test_batch.py's random-data tests run again with its bit-for-bit
comparison replaced by the bound drivekin.batch documents, plus a larger sample with
non-finite values. Skipped on the default build, where test_batch.py proves bit-identity
(scripts/simd_tests.sh builds a SIMD copy and runs this file)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from tests.behaviour import test_batch as exact
from drivekin import (ChassisVelocities, Pose2d, Rotation2d, SwerveDriveKinematics,
                      SwerveDriveOdometry, SwerveModulePosition, SwerveModuleVelocity,
                      Transform2d, Translation2d, Twist2d, batch)

pytestmark = pytest.mark.skipif(
    not batch.SIMD, reason="default build: drivekin.batch is bit-identical to the per-call "
    "API (tests/behaviour/test_batch.py); run scripts/simd_tests.sh for the DRIVEKIN_SIMD=1 build")

# The documented bound (drivekin.batch's docstring): a per-sample result differs from the
# per-call API's by at most RTOL * max(|value|, 1); a replay's poses by at most that per
# sample replayed (heading differences are composed along the path).
RTOL = 1e-14


class Bound:
    """Stands in for test_batch.same: equal shapes, NaN and infinities in the same places,
    finite values within ``factor * RTOL * max(|expected|, 1)``; an angle of π may come
    back as -π (the same rotation, one rounding either side of the cut)."""

    def __init__(self):
        self.factor = 1.0
        self.worst = 0.0

    def __call__(self, a, b):
        a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
        assert a.shape == b.shape
        assert np.array_equal(np.isnan(a), np.isnan(b)), np.argwhere(np.isnan(a) != np.isnan(b))[:5]
        inf = np.isinf(a) | np.isinf(b)
        assert np.array_equal(a[inf], b[inf])
        fin = ~np.isnan(a) & ~inf
        d = np.abs(a[fin] - b[fin])
        wrap = (np.abs(np.abs(a[fin]) - math.pi) < 1e-12) & (np.abs(a[fin] + b[fin]) < 1e-12)
        err = np.where(wrap, 0.0, d / np.maximum(np.abs(b[fin]), 1.0))
        tol = self.factor * RTOL
        self.worst = max(self.worst, float(err.max(initial=0.0)) / self.factor)
        assert (err <= tol).all(), (np.argwhere(err > tol)[:5], err.max(), tol)


@pytest.fixture
def bound(monkeypatch):
    b = Bound()
    monkeypatch.setattr(exact, "same", b)
    return b


@pytest.mark.parametrize("seed", exact.SEEDS)
@pytest.mark.parametrize("m", [2, 4, 7])
def test_swerve_inverse_kinematics_simd(bound, seed, m):
    exact.test_swerve_inverse_kinematics_and_heading_memory(seed, m)


@pytest.mark.parametrize("seed", exact.SEEDS)
def test_forward_kinematics_simd(bound, seed):
    exact.test_forward_kinematics(seed)


@pytest.mark.parametrize("seed", exact.SEEDS)
def test_discretize_relative_exp_log_simd(bound, seed):
    exact.test_discretize_relative_exp_log(seed)


@pytest.mark.parametrize("seed", exact.SEEDS)
def test_accelerations_simd(bound, seed):
    exact.test_accelerations(seed)


@pytest.mark.parametrize("seed", exact.SEEDS)
def test_replay_every_odometry_simd(bound, seed):
    bound.factor = exact.N + 1          # N samples, then one more update
    exact.test_replay_every_odometry(seed)


def test_results_actually_differ_from_libm(bound):
    # Guards against a "SIMD" build that silently runs libm: some last bits must differ.
    x = np.random.default_rng(5).uniform(-10, 10, (4000, 3))
    expected = [exact.pose(Twist2d(*r).exp()) for r in x]
    got = batch.exp(x)
    assert np.asarray(expected).tobytes() != got.tobytes()
    bound(got, expected)


def test_non_finite_and_large_angles(bound):
    rng = np.random.default_rng(11)
    n = 1000
    x = rng.uniform(-4, 4, (n, 3))
    x[::10, 2] = rng.uniform(-1e6, 1e6, len(x[::10]))        # far outside ±π
    x[5, 2], x[6, 2], x[7, 2] = math.nan, math.inf, -math.inf
    x[8, 0], x[9, 1] = math.inf, math.nan
    bound(batch.exp(x), [exact.pose(Twist2d(*r).exp()) for r in x])
    bound(batch.log(x), [exact.twist(Transform2d(r[0], r[1], Rotation2d(r[2])).log())
                         for r in x])
    bound(batch.toFieldRelative(x, np.ascontiguousarray(x[:, 2])),
          [exact.chassis(ChassisVelocities(*r).toFieldRelative(Rotation2d(r[2]))) for r in x])
    bound(batch.discretize(x, 0.02), [exact.chassis(ChassisVelocities(*r).discretize(0.02))
                                      for r in x])
    k = exact.swerve(4)
    mv = np.stack([x[:, :1].repeat(4, 1), x[:, 2:].repeat(4, 1)], axis=-1)
    bound(batch.toChassisVelocities(k, mv),
          [exact.chassis(k.toChassisVelocities([SwerveModuleVelocity(v, Rotation2d(a))
                                                for v, a in r])) for r in mv])
    loop = exact.swerve(4)
    fast = exact.swerve(4)
    bound(batch.toSwerveModuleVelocities(fast, x),
          [exact.modules(loop.toSwerveModuleVelocities(ChassisVelocities(*r))) for r in x])


def test_long_replay_within_bound_per_sample(bound):
    # A whole match at 250 Hz (37,500 samples): the replay bound grows with the length.
    rng = np.random.default_rng(3)
    n = 37_500
    gyro = np.cumsum(rng.uniform(-0.05, 0.06, n))
    pos = np.stack([np.cumsum(rng.uniform(-0.02, 0.06, (n, 4)), axis=0),
                    rng.uniform(-4, 4, (n, 4))], axis=-1)
    k = SwerveDriveKinematics([Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
                               Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3)])
    loop = SwerveDriveOdometry(k, Rotation2d(), [SwerveModulePosition()] * 4, Pose2d())
    fast = SwerveDriveOdometry(k, Rotation2d(), [SwerveModulePosition()] * 4, Pose2d())
    expected = [exact.pose(loop.update(Rotation2d(g), [SwerveModulePosition(d, Rotation2d(a))
                                                       for d, a in p]))
                for g, p in zip(gyro, pos)]
    bound.factor = n
    bound(batch.replay(fast, gyro, pos), expected)
