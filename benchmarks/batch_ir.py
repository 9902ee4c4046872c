"""drivekin.batch instructions per sample under callgrind: deterministic, so two builds
can be compared on a busy machine (wall-clock batch throughput is in batch_table.py).

    PYTHONPATH=src python benchmarks/batch_ir.py                       # this build
    PYTHONPATH=src python benchmarks/batch_ir.py --against OTHER/src   # side by side

Each operation runs on N samples once to warm up, then K more times; instructions per
sample = (count with K runs − count with none) / (K·N), so start-up and set-up cancel.
OpenBLAS threads and hash randomisation are turned off so that the counts repeat. Needs
valgrind. Inputs: the 4-module swerve and mecanum at (±0.3, ±0.3) m, differential 0.6 m,
three dead wheels; random commands, readings, 3-D poses and gyro quaternions (seed 1).
"""
from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys

N = 20000
OPERATIONS = {
    "swerve IK toSwerveModuleVelocities": "batch.toSwerveModuleVelocities(sw, ch)",
    "swerve FK toChassisVelocities": "batch.toChassisVelocities(sw, mods)",
    "mecanum IK toWheelVelocities": "batch.toWheelVelocities(me, ch)",
    "mecanum FK toChassisVelocities": "batch.toChassisVelocities(me, w4)",
    "differential IK toWheelVelocities": "batch.toWheelVelocities(di, ch)",
    "dead-wheel (3) FK toChassisVelocities": "batch.toChassisVelocities(dw, w3)",
    "swerve odometry replay": "batch.replay(dk.SwerveDriveOdometry(sw, R(0), "
                              "[dk.SwerveModulePosition()] * 4), gy, pos)",
    "mecanum odometry replay": "batch.replay(dk.MecanumDriveOdometry(me, R(0), "
                               "dk.MecanumDriveWheelPositions()), gy, w4c)",
    "differential odometry replay": "batch.replay(dk.DifferentialDriveOdometry(R(0), 0.0, "
                                    "0.0), gy, w2c)",
    "dead-wheel (3) odometry replay": "batch.replay(dk.DeadWheelOdometry(dw, [0.0] * 3, "
                                      "R(0)), gy, w3c)",
    "Pose2d.transformBy": "batch.transformBy(ch, ch2)",
    "Twist3d.exp": "batch.exp(tw6)",
    "Transform3d.log": "batch.log(fr7)",
    "Pose3d.transformBy": "batch.transformBy(fr7, fr7b)",
    "Pose3d.relativeTo": "batch.relativeTo(fr7, fr7b)",
    "swerve odometry3d replay": "batch.replay(dk.SwerveDriveOdometry3d(sw, dk.Rotation3d(), "
                                "[dk.SwerveModulePosition()] * 4), gq, pos)",
}
SETUP = f"""
import numpy as np
import drivekin as dk
from drivekin import batch, Pose2d, Rotation2d as R, Translation2d as T
N = {N}
rng = np.random.default_rng(1)
sw = dk.SwerveDriveKinematics(T(.3, .3), T(.3, -.3), T(-.3, .3), T(-.3, -.3))
me = dk.MecanumDriveKinematics(T(.3, .3), T(.3, -.3), T(-.3, .3), T(-.3, -.3))
di = dk.DifferentialDriveKinematics(0.6)
dw = dk.DeadWheelKinematics([Pose2d(0, .15, R(0)), Pose2d(0, -.15, R(0)),
                             Pose2d(-.1, 0, R(1.5707963267948966))])
ch = rng.normal(size=(N, 3))
gy = np.cumsum(rng.normal(size=N)) * 0.01
mods = np.stack([rng.normal(size=(N, 4)), rng.uniform(-3, 3, size=(N, 4))], axis=-1)
pos = np.stack([np.cumsum(rng.normal(size=(N, 4)), 0) * 0.01,
                rng.uniform(-3, 3, size=(N, 4))], axis=-1)
w4 = rng.normal(size=(N, 4)); w3 = rng.normal(size=(N, 3))
w4c = np.cumsum(w4, 0) * 0.01; w3c = np.cumsum(w3, 0) * 0.01
w2c = np.cumsum(rng.normal(size=(N, 2)), 0) * 0.01
ch2 = rng.normal(size=(N, 3))
tw6 = rng.normal(size=(N, 6)) * 0.3
fr7 = batch.exp(tw6); fr7b = batch.exp(rng.normal(size=(N, 6)))
gq = batch.exp(np.concatenate([np.zeros((N, 3)), np.cumsum(rng.normal(size=(N, 3)), 0) * 0.01],
                              axis=1))[:, 3:].copy()
"""


def count(src: str | None, statement: str, runs: int) -> int:
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", PYTHONHASHSEED="0")
    if src is not None:
        env["PYTHONPATH"] = src
    code = SETUP + f"{statement}\nfor _ in range({runs}):\n    {statement}\n"
    out = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
                          sys.executable, "-c", code], env=env, capture_output=True,
                         text=True, check=True).stderr
    m = re.search(r"Collected : (\d+)", out)
    if m is None:
        raise RuntimeError(f"callgrind printed no count:\n{out}")
    return int(m.group(1))


def per_sample(src: str | None, statement: str, runs: int) -> float:
    return (count(src, statement, runs) - count(src, statement, 0)) / (runs * N)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--against", help="another build's src folder, measured beside this one")
    ap.add_argument("--runs", type=int, default=2, help="measured runs of N samples (2)")
    ap.add_argument("--only", default="", help="comma-separated substrings of row titles")
    args = ap.parse_args(argv)
    if shutil.which("valgrind") is None:
        print("batch_ir.py needs valgrind", file=sys.stderr)
        return 2
    only = [s for s in args.only.split(",") if s]
    print("| operation | instructions / sample |" + (" other build | change |" if args.against else ""))
    print("|---|---:|" + ("---:|---:|" if args.against else ""))
    for title, statement in OPERATIONS.items():
        if only and not any(s in title for s in only):
            continue
        mine = per_sample(os.environ.get("PYTHONPATH"), statement, args.runs)
        row = f"| {title} | {mine:.0f} |"
        if args.against:
            other = per_sample(args.against, statement, args.runs)
            row += f" {other:.0f} | {100 * (mine - other) / other:+.1f} % |"
        print(row, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
