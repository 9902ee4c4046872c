"""drivekin.batch's 3-D forms (and the 2-D transformBy / relativeTo) against the per-call
classes called in a loop: bit for bit (tests.behaviour.test_batch.same: every float64's
bytes, any NaN where the per-call result has one), the odometry's state included, on random
rows with unnormalised and zero quaternions, exact zeros, a NaN, tiny and large angles.
A row [x, y, z, qw, qx, qy, qz] is Pose3d(Translation3d(x, y, z),
Rotation3d(Quaternion(qw, qx, qy, qz))). Then the argument rules: shapes, dtypes, out=,
and that a refused call changes nothing."""
from __future__ import annotations

import math

import numpy as np
import pytest

from drivekin import (
    DeadWheelKinematics,
    DeadWheelOdometry3d,
    DifferentialDriveOdometry3d,
    MecanumDriveKinematics,
    MecanumDriveOdometry3d,
    MecanumDriveWheelPositions,
    Pose2d,
    Pose3d,
    Quaternion,
    Rotation2d,
    Rotation3d,
    SwerveDriveKinematics,
    SwerveDriveOdometry3d,
    SwerveModulePosition,
    Transform2d,
    Transform3d,
    Translation2d,
    Translation3d,
    Twist3d,
    TwoDeadWheelOdometry3d,
    batch,
)
from tests.behaviour.test_batch import dead_wheels, pose, rows, same, swerve

SEEDS = range(3)
N = 200


def frame(cls, r):
    return cls(Translation3d(r[0], r[1], r[2]), Rotation3d(Quaternion(r[3], r[4], r[5], r[6])))


def flat(p):
    q = p.getRotation().getQuaternion()
    return [p.getX(), p.getY(), p.getZ(), q.getW(), q.getX(), q.getY(), q.getZ()]


def twist(t):
    return [t.dx, t.dy, t.dz, t.rx, t.ry, t.rz]


def frames(rng, n):
    """Random rows: translations with zeros, a NaN and large values (test_batch.rows),
    quaternions of any length, some zero (the identity), some one axis only."""
    x = np.empty((n, 7))
    x[:, :3] = rows(rng, n, 3, scale=3.0)
    x[:, 3:] = rng.normal(size=(n, 4)) * rng.uniform(0.2, 3.0, (n, 1))
    x[::17, 3:] = 0.0
    x[5::13, 4:] = 0.0
    x[7::11, 3] = 0.0
    return x


def twists(rng, n):
    """Random twists: angles from 1e-12 rad to beyond π, some zero."""
    t = rows(rng, n, 6, scale=2.0)
    axis = rng.normal(size=(n, 3))
    axis /= np.linalg.norm(axis, axis=1, keepdims=True)
    t[:, 3:] = axis * 10.0 ** rng.uniform(-12, 0.8, (n, 1))
    t[::9, 3:] = 0.0
    return t


@pytest.mark.parametrize("seed", SEEDS)
def test_exp_log_and_compositions(seed):
    rng = np.random.default_rng(seed)
    tw = twists(rng, N)
    same(batch.exp(tw), [flat(Twist3d(*r).exp()) for r in tw])
    same(batch.exp(tw[4]), flat(Twist3d(*tw[4]).exp()))
    a, b = frames(rng, N), frames(rng, N)
    same(batch.log(a), [twist(frame(Transform3d, r).log()) for r in a])
    same(batch.log(a[3]), twist(frame(Transform3d, a[3]).log()))
    same(batch.transformBy(a, b),
         [flat(frame(Pose3d, p).transformBy(frame(Transform3d, t))) for p, t in zip(a, b)])
    same(batch.relativeTo(a, b),
         [flat(frame(Pose3d, p).relativeTo(frame(Pose3d, o))) for p, o in zip(a, b)])
    # One value with every sample of the other, either side.
    same(batch.transformBy(a[2], b),
         [flat(frame(Pose3d, a[2]).transformBy(frame(Transform3d, t))) for t in b])
    same(batch.relativeTo(a, b[2]),
         [flat(frame(Pose3d, p).relativeTo(frame(Pose3d, b[2]))) for p in a])
    same(batch.transformBy(a[1], b[1]),
         flat(frame(Pose3d, a[1]).transformBy(frame(Transform3d, b[1]))))


@pytest.mark.parametrize("seed", SEEDS)
def test_planar_compositions(seed):
    rng = np.random.default_rng(seed)
    a, b = rows(rng, N, 3, scale=8.0), rows(rng, N, 3, scale=8.0)

    def p2(r):
        return Pose2d(r[0], r[1], Rotation2d(r[2]))

    def t2(r):
        return Transform2d(r[0], r[1], Rotation2d(r[2]))

    same(batch.transformBy(a, b), [pose(p2(p).transformBy(t2(t))) for p, t in zip(a, b)])
    same(batch.relativeTo(a, b), [pose(p2(p).relativeTo(p2(o))) for p, o in zip(a, b)])
    same(batch.transformBy(a, b[6]), [pose(p2(p).transformBy(t2(b[6]))) for p in a])
    same(batch.relativeTo(a[6], b), [pose(p2(a[6]).relativeTo(p2(o))) for o in b])


# -- 3-D odometry replay -----------------------------------------------------------------------

def gyro_path(rng, n):
    """Quaternions [w, x, y, z] of a robot turning about every axis (winding past ±π in
    yaw), at lengths other than 1 and with a sign flip now and then (the same rotation)."""
    angles = np.cumsum(rng.uniform(-0.05, 0.08, (n, 3)) * [0.3, 0.3, 3.0], axis=0)
    q = np.array([[r.getQuaternion().getW(), r.getQuaternion().getX(),
                   r.getQuaternion().getY(), r.getQuaternion().getZ()]
                  for r in (Rotation3d(*a) for a in angles)])
    q *= rng.uniform(0.5, 2.0, (n, 1))
    q[::7] *= -1.0
    return q


def _path(rng, n, width):
    steps = rng.uniform(-0.02, 0.06, (n, width))
    steps[rng.random(n) < 0.1] = 0.0
    return np.cumsum(steps, axis=0)


def _replay_both(make, gyro, positions, update):
    loop, fast = make(), make()
    expected = [flat(update(loop, Rotation3d(Quaternion(*g)), p))
                for g, p in zip(gyro, positions)]
    same(batch.replay(fast, gyro, positions), expected)
    same(flat(fast.getPose()), flat(loop.getPose()))
    # The objects continue identically (gyro and wheel baselines, pose).
    g = Rotation3d(0.1, -0.2, 0.3)
    same(flat(update(fast, g, positions[-1] + 0.05)), flat(update(loop, g, positions[-1] + 0.05)))


@pytest.mark.parametrize("seed", SEEDS)
def test_replay_every_3d_odometry(seed):
    rng = np.random.default_rng(seed)
    gyro = gyro_path(rng, N)
    start = Pose3d(Translation3d(1.0, -2.0, 0.5), Rotation3d(0.1, -0.05, 0.3))
    g0 = Rotation3d(Quaternion(*gyro[0]))

    sk = swerve(4)
    sp = np.stack([_path(rng, N, 4), rng.uniform(-4, 4, (N, 4))], axis=-1)
    _replay_both(lambda: SwerveDriveOdometry3d(sk, g0, [SwerveModulePosition()] * 4, start),
                 gyro, sp, lambda o, g, p: o.update(g, [SwerveModulePosition(d, Rotation2d(a))
                                                        for d, a in p]))
    mk = MecanumDriveKinematics(Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
                                Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))
    _replay_both(lambda: MecanumDriveOdometry3d(mk, g0, MecanumDriveWheelPositions(), start),
                 gyro, _path(rng, N, 4),
                 lambda o, g, p: o.update(g, MecanumDriveWheelPositions(*p)))
    _replay_both(lambda: DifferentialDriveOdometry3d(g0, 0.0, 0.0, start), gyro,
                 _path(rng, N, 2), lambda o, g, p: o.update(g, p[0], p[1]))
    _replay_both(lambda: TwoDeadWheelOdometry3d(0.1, -0.05, 0.0, 0.0, g0, start), gyro,
                 _path(rng, N, 2), lambda o, g, p: o.update(p[0], p[1], g))
    wk = dead_wheels()
    _replay_both(lambda: DeadWheelOdometry3d(wk, [0.0] * 3, g0, start), gyro,
                 _path(rng, N, 3), lambda o, g, p: o.update(list(p), g))


# -- argument rules -----------------------------------------------------------------------------

def test_bad_arguments_are_clear():
    p7, t6 = np.ones((5, 7)), np.ones((5, 6))
    bad = [
        (lambda: batch.exp(np.ones((5, 4))), ValueError, "(N, 6) (3-D)"),
        (lambda: batch.log(np.ones(5)), ValueError, "(7,) or (N, 7)"),
        (lambda: batch.exp(t6.astype(np.float32)), TypeError, "float64"),
        (lambda: batch.log(np.ones((10, 7))[::2]), ValueError, "C-contiguous"),
        (lambda: batch.exp(t6, out=np.empty((5, 6))), ValueError, "(5, 7)"),
        (lambda: batch.log(p7, out=np.empty((5, 7))), ValueError, "(5, 6)"),
        (lambda: batch.transformBy(p7, np.ones((4, 7))), ValueError, "5 samples"),
        (lambda: batch.transformBy(p7, np.ones((5, 3))), ValueError, "transforms must have shape"),
        (lambda: batch.relativeTo(np.ones((5, 3)), p7), ValueError, "others must have shape"),
        (lambda: batch.relativeTo(p7, p7.tolist()), TypeError, "numpy array"),
        (lambda: batch.transformBy(p7, None), TypeError, "numpy array"),
    ]
    for call, exc, needle in bad:
        with pytest.raises(exc) as info:
            call()
        assert needle in str(info.value), (needle, str(info.value))


def test_out_is_filled_and_must_not_overlap():
    rng = np.random.default_rng(4)
    a, b = frames(rng, 10), frames(rng, 10)
    out = np.empty((10, 7))
    assert batch.transformBy(a, b, out=out) is out
    same(out, batch.transformBy(a, b))
    for call in (lambda: batch.transformBy(a, b, out=a), lambda: batch.relativeTo(a, b, out=b),
                 lambda: batch.transformBy(a[0], b, out=b)):
        with pytest.raises(ValueError, match="overlap"):
            call()
    buf = np.zeros(70)
    with pytest.raises(ValueError, match="overlap"):
        batch.log(buf[:63].reshape(9, 7), out=buf[16:70].reshape(9, 6))
    before = (a.copy(), b.copy())
    frozen = np.empty((10, 7))
    frozen.flags.writeable = False
    with pytest.raises(ValueError, match="writeable"):
        batch.relativeTo(a, b, out=frozen)
    same(a, before[0])
    same(b, before[1])


def test_replay_refusals_leave_the_odometry_alone():
    start = Pose3d(Translation3d(1.0, 2.0, 0.0), Rotation3d(0.0, 0.0, 0.5))
    o = DifferentialDriveOdometry3d(Rotation3d(), 0.0, 0.0, start)
    g = np.tile([1.0, 0.0, 0.0, 0.0], (5, 1))
    for gyro, pos, exc, needle in [
        (g[:4], np.zeros((5, 2)), ValueError, "4 samples"),
        (None, np.zeros((5, 2)), TypeError, "(N, 4)"),
        (np.zeros(5), np.zeros((5, 2)), ValueError, "(N, 4)"),
        (g, np.zeros((5, 3)), ValueError, "(N, 2)"),
        (g, np.zeros((5, 2), np.float32), TypeError, "float64"),
    ]:
        with pytest.raises(exc) as info:
            batch.replay(o, gyro, pos)
        assert needle in str(info.value), str(info.value)
    buf = np.zeros(35)
    with pytest.raises(ValueError, match="overlap"):
        batch.replay(o, g, buf[:10].reshape(5, 2), out=buf.reshape(5, 7))
    with pytest.raises(ValueError, match="overlap"):
        batch.replay(o, buf[:20].reshape(5, 4), np.zeros((5, 2)), out=buf.reshape(5, 7))
    with pytest.raises(ValueError, match=r"\(5, 7\)"):
        batch.replay(o, g, np.zeros((5, 2)), out=np.empty((5, 3)))
    same(flat(o.getPose()), flat(start))
    # The baselines are untouched too: a move of 1 m straight ahead from them.
    same(flat(o.update(Rotation3d(), 1.0, 1.0)),
         flat(start.transformBy(Transform3d(Translation3d(1.0, 0.0, 0.0), Rotation3d()))))
    uninitialised = SwerveDriveOdometry3d.__new__(SwerveDriveOdometry3d)
    with pytest.raises(RuntimeError, match="has not completed"):
        batch.replay(uninitialised, g, np.zeros((5, 4, 2)))
    with pytest.raises(TypeError, match="SwerveDriveOdometry3d"):
        batch.replay(SwerveDriveKinematics(Translation2d(1, 1), Translation2d(-1, -1)), g,
                     np.zeros((5, 2, 2)))


def test_empty_stacks():
    assert batch.exp(np.empty((0, 6))).shape == (0, 7)
    assert batch.log(np.empty((0, 7))).shape == (0, 6)
    assert batch.transformBy(np.empty((0, 7)), np.ones(7)).shape == (0, 7)
    assert batch.relativeTo(np.empty((0, 3)), np.ones(3)).shape == (0, 3)
    o = DeadWheelOdometry3d(DeadWheelKinematics([Pose2d(0.0, 0.2, Rotation2d()),
                                                 Pose2d(-0.1, 0.0, Rotation2d(math.pi / 2))]),
                            [0.0, 0.0], Rotation3d())
    assert batch.replay(o, np.empty((0, 4)), np.empty((0, 2))).shape == (0, 7)
    same(flat(o.getPose()), flat(Pose3d()))
