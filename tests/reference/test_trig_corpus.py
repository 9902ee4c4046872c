"""The same bits on every platform: a fixed corpus of drivekin results, hashed.

The corpus is drivekin's own sin/cos/atan2 on a fixed set of arguments (seeded numpy
draws and exact operations on them, the same doubles on every platform, plus the special
values), then the batch functions built on them (swerve inverse kinematics, discretize,
exp, log, a differential odometry replay), per-call results (Rotation2d from an angle,
Pose2d.exp, SwerveDriveKinematics), drivekin's hypot with Rotation2d(x, y), and discretize
at magnitudes where v·dt and ω·dt overflow. CI runs this file natively (x86_64, every
CPython and every instruction set the CPU has) and on the aarch64 CPython 3.14 wheel under
qemu-user
(scripts/wheel_tests.sh); every run must produce EXPECTED. A change that moves any bit
changes the hash: if it is intended, run this file with DRIVEKIN_PRINT_CORPUS=1 and put
the printed hash here, saying why in the commit.
"""
from __future__ import annotations

import hashlib
import math
import os

import numpy as np

from drivekin import (ChassisVelocities, DifferentialDriveOdometry, Pose2d, Rotation2d,
                      SwerveDriveKinematics, Translation2d, Twist2d)
import drivekin.batch as batch
from tests._support.mp_oracle import magnitudes

EXPECTED = "0e7d6bb472b5d4f1cc913be6499b341f3f58c6c985b469f9d4cf4d1063ecaa00"


def corpus() -> bytes:
    # Only operations that are exact or correctly rounded everywhere make the inputs.
    rng = np.random.default_rng(27)
    parts = []
    x = np.concatenate([rng.uniform(-10, 10, 20000), rng.uniform(-2.0 ** 21, 2.0 ** 21, 5000),
                        magnitudes(rng, 5000, 0, 1023), magnitudes(rng, 2000, -1074, 0),
                        np.arange(-200, 200) * (np.pi / 2),
                        [0.0, -0.0, math.inf, -math.inf, math.nan, 1.7976931348623157e308]])
    x = np.concatenate([x, -x])
    parts += list(batch._trig("sincos", x))
    y = rng.uniform(-1, 1, 20000) * magnitudes(rng, 20000, -30, 30)
    z = rng.uniform(-1, 1, 20000) * magnitudes(rng, 20000, -30, 30)
    parts.append(batch._trig("atan2", y, z))
    special = np.array([0.0, -0.0, math.inf, -math.inf, 1.0, -1.0, 1e-310])
    parts.append(batch._trig("atan2", np.repeat(special, len(special)),
                             np.tile(special, len(special))))

    k = SwerveDriveKinematics(Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
                              Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))
    v = np.column_stack([rng.uniform(-3, 3, 5000), rng.uniform(-3, 3, 5000),
                         rng.uniform(-4, 4, 5000)])
    # Swerve forward kinematics and odometry are left out: their pseudo-inverse comes from
    # numpy's LAPACK at construction, whose last bits depend on the numpy build (seen:
    # numpy 2.4.6 and 2.5.5 differ), not on drivekin. A differential replay has the same
    # gyro turns, pose changes and compositions without one.
    parts += [batch.toSwerveModuleVelocities(k, v), batch.discretize(v, 0.02)]
    parts.append(batch.log(batch.exp(v * 0.7)))
    n = 5000
    wheels = np.cumsum(rng.uniform(-0.02, 0.06, (n, 2)), axis=0)
    gyro = np.cumsum(rng.uniform(-0.2, 0.25, n))
    odo = DifferentialDriveOdometry(Rotation2d(0.0), 0.0, 0.0,
                                    Pose2d(1.0, -2.0, Rotation2d(0.3)))
    parts.append(batch.replay(odo, gyro, wheels))

    per_call = []
    for t in rng.uniform(-50, 50, 2000):
        r = Rotation2d(float(t))
        p = Pose2d(1.0, 2.0, r).exp(Twist2d(0.1, -0.2, float(t) / 10))
        per_call += [r.getCos(), r.getSin(), r.getRadians(), p.x, p.y,
                     p.getRotation().getRadians()]
    for vx, vy, w in v[:500]:
        for m in k.toSwerveModuleVelocities(ChassisVelocities(vx, vy, w)):
            per_call += [m.velocity, m.angle.getRadians()]
    parts.append(np.array(per_call))

    # hypot (Translation2d.getNorm is dkmath's, called once) and Rotation2d(x, y) over every
    # magnitude, the subnormals and the overflowing norms; the special values for hypot
    # only (+inf, or a NaN argument as it came: no arithmetic makes them), since x/inf in
    # Rotation2d(inf, y) makes the hardware's NaN.
    a = rng.choice([-1.0, 1.0], 6000) * np.concatenate(
        [magnitudes(rng, 4000, -1074, 1024), magnitudes(rng, 2000, 1020, 1024)])
    b = rng.choice([-1.0, 1.0], 6000) * np.concatenate(
        [magnitudes(rng, 2000, -1074, 1024), np.ldexp(a[2000:4000], -rng.integers(0, 60, 2000)),
         magnitudes(rng, 2000, 1020, 1024)])
    norms, turns = [], []
    for x, y in zip(a, b):
        norms.append(Translation2d(float(x), float(y)).getNorm())
        r = Rotation2d(float(x), float(y))
        turns += [r.getCos(), r.getSin()]
    special = [0.0, -0.0, math.inf, -math.inf, math.nan, 5e-324, 1.7976931348623157e308]
    norms += [Translation2d(x, y).getNorm() for x in special for y in special]
    parts += [np.array(norms), np.array(turns)]
    # discretize where v·dt and ω·dt overflow (ω·dt reduced from its 53 bits, dkmath's
    # dk_sincos_product) or underflow.
    big = np.column_stack([a[:2000] * 1e-8, b[:2000] * 1e-8, b[2000:4000] * 1e-8])
    dts = magnitudes(rng, 2000, -1000, 1000)
    parts.append(batch.discretize(big, dts))
    return b"".join(np.ascontiguousarray(p, dtype="<f8").tobytes() for p in parts)


def test_corpus_hash_is_the_same_everywhere():
    digest = hashlib.sha256(corpus()).hexdigest()
    if os.environ.get("DRIVEKIN_PRINT_CORPUS") == "1":
        print(f"\ncorpus sha256 on {batch.SIMD}: {digest}")
    assert digest == EXPECTED, (f"the corpus hashes to {digest} on {batch.SIMD}, not "
                                "EXPECTED: some result's bits differ from every other build's")


def test_corpus_hash_does_not_depend_on_the_instruction_set():
    before = batch.SIMD
    digests = {}
    try:
        for isa in batch._isas():
            batch._use_isa(isa)
            digests[isa] = hashlib.sha256(corpus()).hexdigest()
    finally:
        batch._use_isa(before)
    assert digests and len(set(digests.values())) == 1, digests
