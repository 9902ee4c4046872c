"""The same bits on every platform: a fixed corpus of drivekin results, hashed.

The corpus is drivekin's own sin/cos/atan2 on a fixed set of arguments (seeded numpy
draws and exact operations on them, the same doubles on every platform, plus the special
values), then the batch functions built on them (swerve inverse kinematics, discretize,
exp, log, a differential odometry replay), per-call results (Rotation2d from an angle,
Pose2d.exp, SwerveDriveKinematics), drivekin's hypot with Rotation2d(x, y), discretize
at magnitudes where v·dt and ω·dt overflow, drivekin's pseudo-inverse and the forward
kinematics of every drivetrain built on it (per call and batch), and odometry runs of
every odometry class (update and batch replay) and a pose estimator with vision. CI runs
this file natively (x86_64, every CPython and every instruction set the CPU has) and on
the aarch64 CPython 3.14 wheel under qemu-user (scripts/wheel_tests.sh); every run must
produce EXPECTED, one digest per part, so a mismatch names the parts that moved. A
change that moves any bit changes a digest: if it is intended, run this file with
DRIVEKIN_PRINT_CORPUS=1 and put the printed digests here, saying why in the commit.
"""
from __future__ import annotations

import hashlib
import math
import os

import numpy as np

from drivekin import (ChassisVelocities, DeadWheelKinematics, DeadWheelOdometry,
                      DifferentialDriveKinematics, DifferentialDriveOdometry,
                      DifferentialDriveWheelVelocities, DifferentialSwerveModuleKinematics,
                      MecanumDriveKinematics, MecanumDriveOdometry, MecanumDriveWheelPositions,
                      MecanumDriveWheelVelocities, Pose2d, Rotation2d, SwerveDriveKinematics,
                      SwerveDriveOdometry, SwerveDrivePoseEstimator, SwerveModulePosition,
                      SwerveModuleVelocity, Translation2d, Twist2d, TwoDeadWheelOdometry)
import drivekin.batch as batch
from drivekin._core.drivetrain import pseudo_inverse
from tests._support.mp_oracle import magnitudes

EXPECTED = {"sin, cos": "8d96b95691a11fac",
            "atan2": "6e7ac9aed8a030ad",
            "batch: swerve inverse kinematics, discretize, exp, log": "81c374b020c49f68",
            "batch: differential replay": "a1d421204ed0fff0",
            "per call: Rotation2d, Pose2d.exp, swerve inverse kinematics": "68ad50db19f175d8",
            "hypot, Rotation2d(x, y)": "5a3422bf45a46e5c",
            "discretize beyond overflow": "ab930c7cd4cee4bd",
            "pseudo-inverse": "f706b32acdc60828",
            "forward kinematics": "ed4c4392ca1d7dd7",
            "odometry": "84ec5b508e24f5b2"}


def corpus() -> dict[str, bytes]:
    """The corpus's parts by name, each the bytes of its float64 results."""
    parts = {}
    trig_and_geometry(parts)
    forward_kinematics(parts)
    odometry(parts)
    return {name: b"".join(np.ascontiguousarray(p, dtype="<f8").tobytes() for p in arrays)
            for name, arrays in parts.items()}


def trig_and_geometry(parts):
    # Only operations that are exact or correctly rounded everywhere make the inputs.
    rng = np.random.default_rng(27)
    x = np.concatenate([rng.uniform(-10, 10, 20000), rng.uniform(-2.0 ** 21, 2.0 ** 21, 5000),
                        magnitudes(rng, 5000, 0, 1023), magnitudes(rng, 2000, -1074, 0),
                        np.arange(-200, 200) * (np.pi / 2),
                        [0.0, -0.0, math.inf, -math.inf, math.nan, 1.7976931348623157e308]])
    x = np.concatenate([x, -x])
    parts["sin, cos"] = list(batch._trig("sincos", x))
    y = rng.uniform(-1, 1, 20000) * magnitudes(rng, 20000, -30, 30)
    z = rng.uniform(-1, 1, 20000) * magnitudes(rng, 20000, -30, 30)
    special = np.array([0.0, -0.0, math.inf, -math.inf, 1.0, -1.0, 1e-310])
    parts["atan2"] = [batch._trig("atan2", y, z),
                      batch._trig("atan2", np.repeat(special, len(special)),
                                  np.tile(special, len(special)))]

    k = SwerveDriveKinematics(Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
                              Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))
    v = np.column_stack([rng.uniform(-3, 3, 5000), rng.uniform(-3, 3, 5000),
                         rng.uniform(-4, 4, 5000)])
    parts["batch: swerve inverse kinematics, discretize, exp, log"] = [
        batch.toSwerveModuleVelocities(k, v), batch.discretize(v, 0.02),
        batch.log(batch.exp(v * 0.7))]
    n = 5000
    wheels = np.cumsum(rng.uniform(-0.02, 0.06, (n, 2)), axis=0)
    gyro = np.cumsum(rng.uniform(-0.2, 0.25, n))
    odo = DifferentialDriveOdometry(Rotation2d(0.0), 0.0, 0.0,
                                    Pose2d(1.0, -2.0, Rotation2d(0.3)))
    parts["batch: differential replay"] = [batch.replay(odo, gyro, wheels)]

    per_call = []
    for t in rng.uniform(-50, 50, 2000):
        r = Rotation2d(float(t))
        p = Pose2d(1.0, 2.0, r).exp(Twist2d(0.1, -0.2, float(t) / 10))
        per_call += [r.getCos(), r.getSin(), r.getRadians(), p.x, p.y,
                     p.getRotation().getRadians()]
    for vx, vy, w in v[:500]:
        for m in k.toSwerveModuleVelocities(ChassisVelocities(vx, vy, w)):
            per_call += [m.velocity, m.angle.getRadians()]
    parts["per call: Rotation2d, Pose2d.exp, swerve inverse kinematics"] = [np.array(per_call)]

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
    parts["hypot, Rotation2d(x, y)"] = [np.array(norms), np.array(turns)]
    # discretize where v·dt and ω·dt overflow (ω·dt reduced from its 53 bits, dkmath's
    # dk_sincos_product) or underflow.
    big = np.column_stack([a[:2000] * 1e-8, b[:2000] * 1e-8, b[2000:4000] * 1e-8])
    dts = magnitudes(rng, 2000, -1000, 1000)
    parts["discretize beyond overflow"] = [batch.discretize(big, dts)]


R, T = Rotation2d, Translation2d
SWERVE_LAYOUTS = [[(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)],
                  [(0.31, 0.27), (0.29, -0.22), (-0.35, 0.2)],
                  [(0.35, 0.0), (0.175, 0.3), (-0.175, 0.3), (-0.35, 0.0), (-0.175, -0.3),
                   (0.175, -0.3)]]
MECANUM_LAYOUTS = [SWERVE_LAYOUTS[0], [(0.31, 0.27), (0.29, -0.22), (-0.35, 0.2), (-0.1, -0.3)]]
# Three wheels that observe rotation, and two that need the gyro.
DEAD_WHEEL_LAYOUTS = [[Pose2d(0.0, 0.15, R(0.0)), Pose2d(0.0, -0.15, R(0.0)),
                       Pose2d(-0.1, 0.0, R(0.0, 1.0))],
                      [Pose2d(0.05, 0.12, R(0.1)), Pose2d(-0.08, 0.02, R(1.4))]]


def pose_values(p):
    return [p.x, p.y, p.getRotation().getCos(), p.getRotation().getSin()]


def forward_kinematics(parts):
    # drivekin's pseudo-inverse (the forward maps are built with it at construction), then
    # every drivetrain's forward kinematics on it, per call and batch.
    rng = np.random.default_rng(29)
    inverses = [pseudo_inverse(rng.uniform(-2.0, 2.0, shape))
                for shape in [(4, 3), (6, 3), (8, 4), (5, 2), (12, 3), (3, 5)]]
    # Coincident swerve modules: the rank-deficient matrix's minimum-norm inverse.
    inverses.append(pseudo_inverse([[1.0, 0.0, 0.0], [0.0, 1.0, 0.4]] * 3))
    parts["pseudo-inverse"] = inverses

    n = 300
    out = []
    for layout in SWERVE_LAYOUTS:
        k = SwerveDriveKinematics(*[T(x, y) for x, y in layout])
        m = np.stack([rng.uniform(-4.0, 4.0, (n, len(layout))),
                      rng.uniform(-4.0, 4.0, (n, len(layout)))], axis=2)
        out += [batch.toChassisVelocities(k, m), batch.toChassisAccelerations(k, m)]
        for row in m[:100]:
            c = k.toChassisVelocities([SwerveModuleVelocity(v, R(a)) for v, a in row])
            out += [c.vx, c.vy, c.omega]
    for layout in MECANUM_LAYOUTS:
        k = MecanumDriveKinematics(*[T(x, y) for x, y in layout])
        w = rng.uniform(-4.0, 4.0, (n, 4))
        out += [batch.toChassisVelocities(k, w), batch.toChassisAccelerations(k, w)]
        for row in w[:100]:
            c = k.toChassisVelocities(MecanumDriveWheelVelocities(*row))
            out += [c.vx, c.vy, c.omega]
    k = DifferentialDriveKinematics(0.6)
    w = rng.uniform(-4.0, 4.0, (n, 2))
    out.append(batch.toChassisVelocities(k, w))
    for row in w[:100]:
        c = k.toChassisVelocities(DifferentialDriveWheelVelocities(*row))
        out += [c.vx, c.vy, c.omega]
    for layout in DEAD_WHEEL_LAYOUTS:
        k = DeadWheelKinematics(layout)
        w = rng.uniform(-4.0, 4.0, (n, len(layout)))
        gyro = rng.uniform(-4.0, 4.0, n)
        out.append(batch.toChassisVelocities(k, w, gyro))
        if not k.requiresGyro():
            out.append(batch.toChassisVelocities(k, w))
        for row, g in zip(w[:100], gyro):
            c = k.toChassisVelocities(list(row), float(g))
            out += [c.vx, c.vy, c.omega]
    pod = DifferentialSwerveModuleKinematics(3.0, 5.0, 0.05)
    pod.resetModulePosition(R(0.5), 10.0, -4.0)
    for m1, m2 in rng.uniform(-200.0, 200.0, (100, 2)):
        v = pod.toModuleVelocities(m1, m2)
        p = pod.toModulePosition(m1, m2)
        out += [v.wheelVelocity, v.azimuthVelocity, p.distance, p.angle.getCos(),
                p.angle.getSin()]
    parts["forward kinematics"] = [np.array(x, dtype=np.float64).ravel() for x in out]


def odometry(parts):
    # Every odometry class, update by update and in one batch replay, and a pose estimator
    # with vision measurements.
    rng = np.random.default_rng(31)
    n = 300
    gyro = np.cumsum(rng.uniform(-0.2, 0.25, n))
    start = Pose2d(1.0, -2.0, R(0.3))
    per_call, replays = [], []

    def run(make, update, positions, gyro_angles):
        odo = make()
        for i in range(n):
            per_call.extend(pose_values(update(odo, i)))
        replays.append(batch.replay(make(), gyro_angles, positions))

    k = SwerveDriveKinematics(*[T(x, y) for x, y in SWERVE_LAYOUTS[0]])
    m = np.stack([np.cumsum(rng.uniform(-0.02, 0.06, (n, 4)), axis=0),
                  rng.uniform(-4.0, 4.0, (n, 4))], axis=2)
    run(lambda: SwerveDriveOdometry(k, R(0.0), m[0], start),
        lambda o, i: o.update(R(gyro[i]), [SwerveModulePosition(d, R(a)) for d, a in m[i]]),
        m, gyro)
    k = MecanumDriveKinematics(*[T(x, y) for x, y in MECANUM_LAYOUTS[1]])
    w = np.cumsum(rng.uniform(-0.02, 0.06, (n, 4)), axis=0)
    run(lambda: MecanumDriveOdometry(k, R(0.0), MecanumDriveWheelPositions(*w[0]), start),
        lambda o, i: o.update(R(gyro[i]), MecanumDriveWheelPositions(*w[i])), w, gyro)
    w = np.cumsum(rng.uniform(-0.02, 0.06, (n, 2)), axis=0)
    run(lambda: DifferentialDriveOdometry(R(0.0), w[0, 0], w[0, 1], start),
        lambda o, i: o.update(R(gyro[i]), w[i, 0], w[i, 1]), w, gyro)
    run(lambda: TwoDeadWheelOdometry(0.1, -0.15, w[0, 0], w[0, 1], R(0.0), start),
        lambda o, i: o.update(w[i, 0], w[i, 1], R(gyro[i])), w, gyro)
    for layout in DEAD_WHEEL_LAYOUTS:
        k = DeadWheelKinematics(layout)
        w = np.cumsum(rng.uniform(-0.02, 0.06, (n, len(layout))), axis=0)
        run(lambda: DeadWheelOdometry(k, w[0], R(0.0), start),
            lambda o, i: o.update(w[i], R(gyro[i])), w, gyro)
        if not k.requiresGyro():
            run(lambda: DeadWheelOdometry(k, w[0], None, start),
                lambda o, i: o.update(w[i]), w, None)

    k = SwerveDriveKinematics(*[T(x, y) for x, y in SWERVE_LAYOUTS[1]])
    m = np.stack([np.cumsum(rng.uniform(-0.02, 0.06, (n, 3)), axis=0),
                  rng.uniform(-4.0, 4.0, (n, 3))], axis=2)
    est = SwerveDrivePoseEstimator(k, R(0.0), m[0], start, (0.1, 0.1, 0.1), (0.5, 0.5, 0.9))
    estimates = []
    for i in range(n):
        estimates += pose_values(est.updateWithTime(0.02 * i, R(gyro[i]), m[i]))
        if i % 10 == 9:
            est.addVisionMeasurement(Pose2d(1.0 + 0.01 * i, -2.0, R(0.3 + 0.001 * i)),
                                     0.02 * i - 0.05)
            estimates += pose_values(est.getEstimatedPosition())
    parts["odometry"] = [np.array(per_call)] + replays + [np.array(estimates)]


def digests(c):
    """Each part's digest: the first 16 hexadecimal digits of its SHA-256."""
    return {name: hashlib.sha256(data).hexdigest()[:16] for name, data in c.items()}


def test_corpus_hash_is_the_same_everywhere():
    got = digests(corpus())
    if os.environ.get("DRIVEKIN_PRINT_CORPUS") == "1":
        print(f"\ncorpus digests on {batch.SIMD}:")
        print("EXPECTED = {" + ",\n            ".join(f"{k!r}: {v!r}" for k, v in got.items())
              + "}")
    moved = sorted(name for name in got.keys() | EXPECTED.keys()
                   if got.get(name) != EXPECTED.get(name))
    assert not moved, (f"on {batch.SIMD} these parts of the corpus differ from EXPECTED "
                       f"(every other build's bits): {moved}")


def test_corpus_hash_does_not_depend_on_the_instruction_set():
    before = batch.SIMD
    results = {}
    try:
        for isa in batch._isas():
            batch._use_isa(isa)
            results[isa] = digests(corpus())
    finally:
        batch._use_isa(before)
    first = next(iter(results.values()))
    assert results and all(r == first for r in results.values()), results
