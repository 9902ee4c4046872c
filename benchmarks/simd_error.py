"""How far the DRIVEKIN_SIMD=1 build's batch results are from the default build's.

Run once per build (each with its own PYTHONPATH), saving every SIMD-affected batch
function's output on the same random data, then compare the two files:

    PYTHONPATH=<default build>/src python benchmarks/simd_error.py --save default.npz
    PYTHONPATH=<SIMD build>/src python benchmarks/simd_error.py --save simd.npz
    python benchmarks/simd_error.py --compare default.npz simd.npz

The comparison prints, per function, the largest absolute difference and the largest
difference relative to max(|default|, 1) (angles on the circle: π and -π are the same),
and whether NaN and infinities sit in the same places.
"""
from __future__ import annotations

import argparse
import math

import numpy as np


def outputs(n: int, seed: int) -> dict[str, np.ndarray]:
    from drivekin import (DeadWheelKinematics, DeadWheelOdometry, DifferentialDriveOdometry,
                          MecanumDriveKinematics, MecanumDriveOdometry,
                          MecanumDriveWheelPositions, Pose2d, Rotation2d,
                          SwerveDriveKinematics, SwerveDriveOdometry, SwerveModulePosition,
                          Translation2d, TwoDeadWheelOdometry, batch)
    R, T = Rotation2d, Translation2d
    rng = np.random.default_rng(seed)
    corners = [T(0.3, 0.3), T(0.3, -0.3), T(-0.3, 0.3), T(-0.3, -0.3)]
    cv = rng.uniform(-4.0, 4.0, (n, 3))
    cv[rng.random(n) < 0.05] = 0.0
    modules = np.stack([rng.uniform(-5.0, 5.0, (n, 4)), rng.uniform(-10.0, 10.0, (n, 4))],
                       axis=-1)
    twists = rng.uniform(-2.0, 2.0, (n, 3))
    twists[::7, 2] = rng.uniform(-1e-6, 1e-6, len(twists[::7]))
    transforms = rng.uniform(-5.0, 5.0, (n, 3))
    transforms[:, 2] = rng.uniform(-10.0, 10.0, n)
    angles = rng.uniform(-10.0, 10.0, n)
    gyro = np.cumsum(rng.uniform(-0.05, 0.06, n))

    def path(width):
        return np.cumsum(rng.uniform(-0.02, 0.06, (n, width)), axis=0)

    r = {}
    r["swerve IK"] = batch.toSwerveModuleVelocities(SwerveDriveKinematics(corners), cv)
    r["swerve accel IK"] = batch.toSwerveModuleAccelerations(
        SwerveDriveKinematics(corners), cv, rng.uniform(-4.0, 4.0, n))
    r["swerve FK"] = batch.toChassisVelocities(SwerveDriveKinematics(corners), modules)
    r["swerve accel FK"] = batch.toChassisAccelerations(SwerveDriveKinematics(corners), modules)
    r["discretize"] = batch.discretize(cv, rng.uniform(0.001, 0.1, n))
    r["toRobotRelative"] = batch.toRobotRelative(cv, angles)
    r["toFieldRelative"] = batch.toFieldRelative(cv, angles)
    r["exp"] = batch.exp(twists)
    r["log"] = batch.log(transforms)
    start = Pose2d(1.0, -2.0, R(0.3))
    swerve_pos = np.stack([path(4), rng.uniform(-4.0, 4.0, (n, 4))], axis=-1)
    r["swerve replay"] = batch.replay(SwerveDriveOdometry(
        SwerveDriveKinematics(corners), R(0.0), [SwerveModulePosition()] * 4, start),
        gyro, swerve_pos)
    r["mecanum replay"] = batch.replay(MecanumDriveOdometry(
        MecanumDriveKinematics(*corners), R(0.0), MecanumDriveWheelPositions(), start),
        gyro, path(4))
    r["differential replay"] = batch.replay(
        DifferentialDriveOdometry(R(0.0), 0.0, 0.0, start), gyro, path(2))
    r["two-dead-wheel replay"] = batch.replay(
        TwoDeadWheelOdometry(0.1, -0.05, 0.0, 0.0, R(0.0), start), gyro, path(2))
    wheels = DeadWheelKinematics([Pose2d(0.0, 0.18, R()), Pose2d(0.0, -0.18, R()),
                                  Pose2d(-0.1, 0.0, R(math.pi / 2))])
    r["dead-wheel replay, gyro"] = batch.replay(
        DeadWheelOdometry(wheels, [0.0] * 3, R(0.0), start), gyro, path(3))
    r["dead-wheel replay, no gyro"] = batch.replay(
        DeadWheelOdometry(wheels, [0.0] * 3, None, start), None, path(3))
    return r


# Which trailing-axis columns are angles (rad, wrapped to (-π, π]).
ANGLE_COLUMNS = {"swerve IK": 1, "swerve accel IK": 1, "exp": 2}


def differences(name: str, a: np.ndarray, b: np.ndarray) -> tuple[float, float, bool]:
    """(max abs, max relative to max(|a|, 1), non-finite pattern equal) of b against a."""
    same_pattern = bool(np.array_equal(np.isnan(a), np.isnan(b)) and
                        np.array_equal(np.where(np.isinf(a), a, 0), np.where(np.isinf(b), b, 0)))
    finite = np.isfinite(a) & np.isfinite(b)
    d = np.where(finite, b - a, 0.0)
    col = ANGLE_COLUMNS.get(name, 2 if "replay" in name else None)
    if col is not None:
        da = d[..., col]
        d[..., col] = np.where(np.abs(da) > math.pi, da - np.copysign(2 * math.pi, da), da)
    rel = np.abs(d) / np.maximum(np.abs(np.where(finite, a, 0.0)), 1.0)
    return float(np.abs(d).max(initial=0.0)), float(rel.max(initial=0.0)), same_pattern


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--save", metavar="FILE.npz")
    ap.add_argument("--compare", nargs=2, metavar=("DEFAULT.npz", "SIMD.npz"))
    ap.add_argument("-n", type=int, default=1_000_000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    if args.save:
        from drivekin import batch
        print(f"drivekin.batch from {batch.__file__}, SIMD={batch.SIMD}")
        np.savez(args.save, **outputs(args.n, args.seed))
    if args.compare:
        a, b = np.load(args.compare[0]), np.load(args.compare[1])
        print("| function | max abs difference | max relative (to max(|x|, 1)) | NaN/inf same |")
        print("|---|---:|---:|:---:|")
        for name in a.files:
            ab, rel, pattern = differences(name, a[name], b[name])
            print(f"| {name} | {ab:.3g} | {rel:.3g} | {'yes' if pattern else '**NO**'} |")


if __name__ == "__main__":
    main()
