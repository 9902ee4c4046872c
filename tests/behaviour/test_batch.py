"""drivekin.batch against the per-call API called in a loop: bit for bit (the bytes of
every float64 result, so -0.0 and NaN payloads count), state included (swerve heading
memory, the odometry after a replay), on random data with exact zeros, NaN and angles
beyond ±π mixed in. Then the argument rules: shapes, dtypes, out=, and that a refused
call changes nothing."""
from __future__ import annotations

import copy
import math

import numpy as np
import pytest

from drivekin import (
    ChassisVelocities,
    DeadWheelKinematics,
    DeadWheelOdometry,
    DifferentialDriveKinematics,
    DifferentialDriveOdometry,
    DifferentialDriveWheelVelocities,
    MecanumDriveKinematics,
    MecanumDriveOdometry,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDriveOdometry,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Transform2d,
    Translation2d,
    Twist2d,
    TwoDeadWheelOdometry,
    batch,
)

R, T = Rotation2d, Translation2d
SEEDS = range(4)
N = 300


def same(a, b):
    """Bit for bit, except a NaN's sign and payload: IEEE 754 does not interpret the sign
    of a NaN and compilers do not keep it (gcc may compute (-h) * x as -(h * x), which
    flips a NaN x's sign on every target; aarch64's generated NaN is +NaN, x86's -NaN),
    so NaN must appear exactly where it does in the per-call result, any NaN."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    assert a.shape == b.shape
    assert (np.isnan(a) == np.isnan(b)).all(), np.argwhere(np.isnan(a) != np.isnan(b))[:5]
    a, b = np.where(np.isnan(a), np.nan, a), np.where(np.isnan(b), np.nan, b)
    assert a.tobytes() == b.tobytes(), np.argwhere(a.view(np.uint64) != b.view(np.uint64))[:5]


def rows(rng, n, width, scale=2.0):
    """Random rows with exact zeros (whole rows and single entries), a NaN and big values."""
    x = rng.uniform(-scale, scale, (n, width))
    x[rng.random(n) < 0.15] = 0.0
    x[rng.random((n, width)) < 0.05] = 0.0
    x[n // 2, 0] = math.nan
    x[n // 3] *= 50.0
    return x


def swerve(n=4):
    return SwerveDriveKinematics([T(0.3 * math.cos(a), 0.3 * math.sin(a))
                                  for a in np.linspace(0.4, 0.4 + 2 * math.pi, n, endpoint=False)])


def dead_wheels():
    return DeadWheelKinematics([Pose2d(0.0, 0.18, R()), Pose2d(0.0, -0.18, R()),
                                Pose2d(-0.1, 0.0, R(math.pi / 2))])


def modules(states):
    magnitude = next(n for n in ("velocity", "distance", "acceleration") if hasattr(states[0], n))
    return [(getattr(s, magnitude), s.angle.getRadians()) for s in states]


# -- inverse kinematics ---------------------------------------------------------------------

@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("m", [2, 4, 7])
def test_swerve_inverse_kinematics_and_heading_memory(seed, m):
    rng = np.random.default_rng(seed)
    cv = rows(rng, N, 3)
    cor = T(0.1, -0.2) if seed % 2 else None
    k_loop, k_batch = swerve(m), swerve(m)
    k_loop.resetHeadings([R(0.1 * i) for i in range(m)])
    k_batch.resetHeadings([R(0.1 * i) for i in range(m)])
    expected = [modules(k_loop.toSwerveModuleVelocities(ChassisVelocities(*r), cor or T()))
                for r in cv]
    same(batch.toSwerveModuleVelocities(k_batch, cv, cor), expected)
    # The heading memory ends where the loop's did: a zero velocity reports it.
    same(modules(k_batch.toSwerveModuleVelocities(ChassisVelocities())),
         modules(k_loop.toSwerveModuleVelocities(ChassisVelocities())))
    # The single form.
    same(batch.toSwerveModuleVelocities(k_batch, cv[5], cor),
         modules(k_loop.toSwerveModuleVelocities(ChassisVelocities(*cv[5]), cor or T())))


@pytest.mark.parametrize("seed", SEEDS)
def test_wheel_inverse_kinematics(seed):
    rng = np.random.default_rng(seed)
    cv = rows(rng, N, 3)
    mk = MecanumDriveKinematics(T(0.3, 0.3), T(0.3, -0.3), T(-0.3, 0.3), T(-0.3, -0.3))
    cor = T(0.2, 0.1)
    same(batch.toWheelVelocities(mk, cv, cor),
         [list(mk.toWheelVelocities(ChassisVelocities(*r), cor)) for r in cv])
    same(batch.toWheelVelocities(mk, cv),
         [list(mk.toWheelVelocities(ChassisVelocities(*r))) for r in cv])
    dk = DifferentialDriveKinematics(0.63)
    same(batch.toWheelVelocities(dk, cv),
         [[w.left, w.right] for w in (dk.toWheelVelocities(ChassisVelocities(*r)) for r in cv)])
    wk = dead_wheels()
    same(batch.toWheelVelocities(wk, cv),
         [list(wk.toWheelVelocities(ChassisVelocities(*r))) for r in cv])


# -- forward kinematics ---------------------------------------------------------------------

@pytest.mark.parametrize("seed", SEEDS)
def test_forward_kinematics(seed):
    rng = np.random.default_rng(seed)
    sk = swerve(5)
    mv = rows(rng, N, 10, scale=5.0).reshape(N, 5, 2)
    same(batch.toChassisVelocities(sk, mv),
         [chassis(sk.toChassisVelocities([SwerveModuleVelocity(v, R(a)) for v, a in r]))
          for r in mv])
    mk = MecanumDriveKinematics(T(0.3, 0.3), T(0.3, -0.3), T(-0.3, 0.3), T(-0.3, -0.3))
    w4 = rows(rng, N, 4)
    same(batch.toChassisVelocities(mk, w4),
         [chassis(mk.toChassisVelocities(MecanumDriveWheelVelocities(*r))) for r in w4])
    dk = DifferentialDriveKinematics(0.63)
    w2 = rows(rng, N, 2)
    same(batch.toChassisVelocities(dk, w2),
         [chassis(dk.toChassisVelocities(DifferentialDriveWheelVelocities(*r))) for r in w2])
    wk = dead_wheels()
    w3 = rows(rng, N, 3)
    same(batch.toChassisVelocities(wk, w3), [chassis(wk.toChassisVelocities(list(r))) for r in w3])
    rates = rng.uniform(-3, 3, N)
    same(batch.toChassisVelocities(wk, w3, rates),
         [chassis(wk.toChassisVelocities(list(r), g)) for r, g in zip(w3, rates)])
    same(batch.toChassisVelocities(wk, w3, 0.5),
         [chassis(wk.toChassisVelocities(list(r), 0.5)) for r in w3])


# -- chassis vectors and geometry -------------------------------------------------------------

@pytest.mark.parametrize("seed", SEEDS)
def test_discretize_relative_exp_log(seed):
    rng = np.random.default_rng(seed)
    cv = rows(rng, N, 3, scale=8.0)
    dts = rng.uniform(0.001, 0.5, N)
    dts[7] = 0.0
    same(batch.discretize(cv, dts), [chassis(ChassisVelocities(*r).discretize(t))
                                     for r, t in zip(cv, dts)])
    same(batch.discretize(cv, 0.02), [chassis(ChassisVelocities(*r).discretize(0.02)) for r in cv])
    angles = rng.uniform(-10, 10, N)
    same(batch.toRobotRelative(cv, angles),
         [chassis(ChassisVelocities(*r).toRobotRelative(R(a))) for r, a in zip(cv, angles)])
    same(batch.toFieldRelative(cv, angles),
         [chassis(ChassisVelocities(*r).toFieldRelative(R(a))) for r, a in zip(cv, angles)])
    same(batch.toFieldRelative(cv, 1.25),
         [chassis(ChassisVelocities(*r).toFieldRelative(R(1.25))) for r in cv])
    tw = rows(rng, N, 3, scale=5.0)
    tw[::9, 2] = rng.uniform(-1e-9, 1e-9, len(tw[::9]))
    same(batch.exp(tw), [pose(Twist2d(*r).exp()) for r in tw])
    same(batch.log(tw), [list(twist(Transform2d(r[0], r[1], R(r[2])).log())) for r in tw])
    same(batch.exp(tw[3]), pose(Twist2d(*tw[3]).exp()))


def chassis(c):
    return [c.vx, c.vy, c.omega]


def pose(p):
    return [p.x, p.y, p.getRotation().getRadians()]


def twist(t):
    return [t.dx, t.dy, t.dtheta]


# -- odometry replay ---------------------------------------------------------------------------

def _replay_both(make, gyro, positions, update):
    loop, fast = make(), make()
    expected = [pose(update(loop, g, p)) for g, p in zip(gyro if gyro is not None
                                                          else [None] * len(positions),
                                                          positions)]
    same(batch.replay(fast, gyro, positions), expected)
    same(pose(fast.getPose()), pose(loop.getPose()))
    # The objects continue identically.
    last_g = None if gyro is None else gyro[-1] + 0.1
    same(pose(update(fast, last_g, positions[-1] + 0.05)),
         pose(update(loop, last_g, positions[-1] + 0.05)))


def _path(rng, n, width):
    steps = rng.uniform(-0.02, 0.06, (n, width))
    steps[rng.random(n) < 0.1] = 0.0
    return np.cumsum(steps, axis=0)


@pytest.mark.parametrize("seed", SEEDS)
def test_replay_every_odometry(seed):
    rng = np.random.default_rng(seed)
    gyro = np.cumsum(rng.uniform(-0.2, 0.25, N))            # winds past ±π
    start = Pose2d(1.0, -2.0, R(0.3))

    sk = swerve(4)
    dist = _path(rng, N, 4)
    ang = rng.uniform(-4, 4, (N, 4))
    sp = np.stack([dist, ang], axis=-1)
    _replay_both(lambda: SwerveDriveOdometry(sk, R(0.0), [SwerveModulePosition()] * 4, start),
                 gyro, sp, lambda o, g, p: o.update(R(g), [SwerveModulePosition(d, R(a))
                                                           for d, a in p]))
    mk = MecanumDriveKinematics(T(0.3, 0.3), T(0.3, -0.3), T(-0.3, 0.3), T(-0.3, -0.3))
    _replay_both(lambda: MecanumDriveOdometry(mk, R(0.0), MecanumDriveWheelPositions(), start),
                 gyro, _path(rng, N, 4),
                 lambda o, g, p: o.update(R(g), MecanumDriveWheelPositions(*p)))
    _replay_both(lambda: DifferentialDriveOdometry(R(0.0), 0.0, 0.0, start), gyro,
                 _path(rng, N, 2), lambda o, g, p: o.update(R(g), p[0], p[1]))
    _replay_both(lambda: TwoDeadWheelOdometry(0.1, -0.05, 0.0, 0.0, R(0.0), start), gyro,
                 _path(rng, N, 2), lambda o, g, p: o.update(p[0], p[1], R(g)))
    wk = dead_wheels()
    _replay_both(lambda: DeadWheelOdometry(wk, [0.0] * 3, R(0.0), start), gyro,
                 _path(rng, N, 3), lambda o, g, p: o.update(list(p), R(g)))
    _replay_both(lambda: DeadWheelOdometry(wk, [0.0] * 3, None, start), None,
                 _path(rng, N, 3), lambda o, g, p: o.update(list(p)))


# -- argument rules -----------------------------------------------------------------------------

def test_bad_arguments_are_clear_and_change_nothing():
    k = swerve(4)
    k.resetHeadings([R(0.5)] * 4)
    cv = np.ones((5, 3))
    bad = [
        (lambda: batch.toSwerveModuleVelocities(k, cv.astype(np.float32)), TypeError, "float64"),
        (lambda: batch.toSwerveModuleVelocities(k, cv.tolist()), TypeError, "numpy array"),
        (lambda: batch.toSwerveModuleVelocities(k, np.ones((5, 4))), ValueError, "(N, 3)"),
        (lambda: batch.toSwerveModuleVelocities(k, np.ones((6, 3))[::2]), ValueError,
         "C-contiguous"),
        (lambda: batch.toSwerveModuleVelocities(k, cv, out=np.empty((5, 4, 3))), ValueError,
         "shape"),
        (lambda: batch.toSwerveModuleVelocities(k, cv, out=np.empty((5, 4, 2), np.float32)),
         TypeError, "float64"),
        (lambda: batch.toSwerveModuleVelocities(k, cv, T(1, 1), out=cv), ValueError, "shape"),
        (lambda: batch.toSwerveModuleVelocities(k, cv, centerOfRotation=(0, 0)), TypeError,
         "Translation2d"),
        (lambda: batch.toChassisVelocities(k, np.ones((5, 3, 2))), ValueError, "(4, 2)"),
        (lambda: batch.toChassisVelocities(DifferentialDriveKinematics(1.0), np.ones((5, 2)),
                                           np.ones(5)), TypeError, "gyroRates"),
        (lambda: batch.toWheelVelocities(R(), cv), TypeError, "MecanumDriveKinematics"),
        (lambda: batch.toSwerveModuleVelocities(MecanumDriveKinematics(T(1, 1), T(1, -1), T(-1, 1),
                                                                       T(-1, -1)), cv),
         TypeError, "SwerveDriveKinematics"),
        (lambda: batch.desaturateWheelVelocities(np.ones((5, 4, 2)), np.ones((4, 3)), 1.0, 1.0,
                                                 1.0), ValueError, "one row per sample"),
        (lambda: batch.desaturateWheelVelocities(np.ones((5, 4, 2)), np.ones((5, 3)), 1.0),
         TypeError, "all three limits"),
        (lambda: batch.desaturateWheelVelocities(np.ones(4), 1.0), ValueError, "(M, 2)"),
        (lambda: batch.desaturate(np.ones((2, 3, 4)), 1.0), ValueError, "(W,) or (N, W)"),
        (lambda: batch.toSwerveModuleAccelerations(k, cv, np.ones(3)), ValueError, "(5,)"),
        (lambda: batch.discretize(cv, np.ones(4)), ValueError, "(5,)"),
        (lambda: batch.discretize(cv, "0.02"), TypeError, "float"),
        (lambda: batch.exp(np.ones((5, 3), dtype=object)), TypeError, "float64"),
        (lambda: batch.replay(k, np.zeros(5), np.zeros((5, 4, 2))), TypeError, "Odometry"),
    ]
    for call, exc, needle in bad:
        with pytest.raises(exc, match=None) as info:
            call()
        assert needle in str(info.value), (needle, str(info.value))
    same(modules(k.toSwerveModuleVelocities(ChassisVelocities())), [(0.0, 0.5)] * 4)


def test_out_is_filled_and_must_not_overlap():
    x = np.random.default_rng(1).uniform(-1, 1, (10, 3))
    out = np.empty((10, 3))
    assert batch.exp(x, out=out) is out
    same(out, batch.exp(x))
    with pytest.raises(ValueError, match="overlap"):
        batch.exp(x, out=x)
    buf = np.zeros(40)
    with pytest.raises(ValueError, match="overlap"):
        batch.log(buf[:30].reshape(10, 3), out=buf[10:40].reshape(10, 3))
    frozen = np.empty((10, 3))
    frozen.flags.writeable = False
    with pytest.raises(ValueError, match="writeable"):
        batch.exp(x, out=frozen)


def test_in_place_desaturation_refuses_chassis_rows_sharing_its_memory():
    # The reproducer of the porting issue: with out=moduleVelocities and chassis rows in
    # the same buffer, writing sample 0 changed the rows sample 1 then read.
    buf = np.array([1., 2, 4, 3, 5, 3, 2, 2, 5, 4, 6, 2, 3, 4, 5, 1])
    mv, cv = buf.reshape(2, 4, 2), buf[:6].reshape(2, 3)
    before = buf.copy()
    with pytest.raises(ValueError, match="desiredChassisVelocities shares its memory"):
        batch.desaturateWheelVelocities(mv, cv, 4.0, 3.0, 5.0, out=mv)
    same(buf, before)                                     # nothing written
    # On copies the same call gives what a copy of the inputs gives, in place too.
    mv2, cv2 = mv.copy(), cv.copy()
    want = batch.desaturateWheelVelocities(mv.copy(), cv.copy(), 4.0, 3.0, 5.0)
    assert batch.desaturateWheelVelocities(mv2, cv2, 4.0, 3.0, 5.0, out=mv2) is mv2
    same(mv2, want)
    np.testing.assert_allclose(mv2[1, :, 0], [5.0, 6.0, 3.0, 5.0], rtol=0, atol=1e-12)


def test_replay_refusals_leave_the_odometry_alone():
    o = DifferentialDriveOdometry(R(0.0), 0.0, 0.0, Pose2d(1, 2, R(0.5)))
    before = pose(o.getPose())
    for gyro, pos, exc, needle in [
        (np.zeros(4), np.zeros((5, 2)), ValueError, "4 samples"),
        (None, np.zeros((5, 2)), TypeError, "None"),
        (np.zeros(5), np.zeros((5, 3)), ValueError, "(N, 2)"),
        (np.zeros(5), np.zeros(2), ValueError, "(N, 2)"),
        (np.zeros((5, 1)), np.zeros((5, 2)), ValueError, "(N,)"),
    ]:
        with pytest.raises(exc) as info:
            batch.replay(o, gyro, pos)
        assert needle in str(info.value), str(info.value)
    with pytest.raises(ValueError, match="overlap"):
        buf = np.zeros(15)
        batch.replay(o, np.zeros(5), buf[:10].reshape(5, 2), out=buf.reshape(5, 3))
    same(pose(o.getPose()), before)
    w = DeadWheelOdometry(dead_wheels(), [0.0] * 3)
    with pytest.raises(ValueError, match="without a gyro"):
        batch.replay(w, np.zeros(3), np.zeros((3, 3)))
    uninitialised = DifferentialDriveOdometry.__new__(DifferentialDriveOdometry)
    with pytest.raises(RuntimeError, match="has not completed"):
        batch.replay(uninitialised, np.zeros(3), np.zeros((3, 2)))


def test_empty_stacks():
    assert batch.exp(np.empty((0, 3))).shape == (0, 3)
    o = DifferentialDriveOdometry(R(0.0), 0.0, 0.0)
    assert batch.replay(o, np.empty(0), np.empty((0, 2))).shape == (0, 3)
    assert batch.toSwerveModuleVelocities(swerve(3), np.empty((0, 3))).shape == (0, 3, 2)


# -- accelerations and desaturation --------------------------------------------------------------

@pytest.mark.parametrize("seed", SEEDS)
def test_accelerations(seed):
    from drivekin import (ChassisAccelerations, DifferentialDriveWheelAccelerations,
                          MecanumDriveWheelAccelerations, SwerveModuleAcceleration)
    rng = np.random.default_rng(seed)
    ca = rows(rng, N, 3)
    omega = rng.uniform(-4, 4, N)
    omega[::7] = 0.0
    cor = T(0.1, 0.2)
    sk = swerve(4)
    same(batch.toSwerveModuleAccelerations(sk, ca, omega, cor),
         [modules(sk.toSwerveModuleAccelerations(ChassisAccelerations(*r), w, cor))
          for r, w in zip(ca, omega)])
    same(batch.toSwerveModuleAccelerations(sk, ca, 1.5),
         [modules(sk.toSwerveModuleAccelerations(ChassisAccelerations(*r), 1.5)) for r in ca])
    same(batch.toWheelAccelerations(sk, ca),
         [modules(sk.toWheelAccelerations(ChassisAccelerations(*r))) for r in ca])
    ma = rows(rng, N, 8, scale=4.0).reshape(N, 4, 2)
    same(batch.toChassisAccelerations(sk, ma),
         [accel(sk.toChassisAccelerations([SwerveModuleAcceleration(a, R(t)) for a, t in r]))
          for r in ma])
    mk = MecanumDriveKinematics(T(0.3, 0.3), T(0.3, -0.3), T(-0.3, 0.3), T(-0.3, -0.3))
    same(batch.toWheelAccelerations(mk, ca, cor),
         [list(mk.toWheelAccelerations(ChassisAccelerations(*r), cor)) for r in ca])
    w4 = rows(rng, N, 4)
    same(batch.toChassisAccelerations(mk, w4),
         [accel(mk.toChassisAccelerations(MecanumDriveWheelAccelerations(*r))) for r in w4])
    dk = DifferentialDriveKinematics(0.7)
    same(batch.toWheelAccelerations(dk, ca),
         [[a.left, a.right] for a in (dk.toWheelAccelerations(ChassisAccelerations(*r))
                                      for r in ca)])
    w2 = rows(rng, N, 2)
    same(batch.toChassisAccelerations(dk, w2),
         [accel(dk.toChassisAccelerations(DifferentialDriveWheelAccelerations(*r))) for r in w2])
    wk = dead_wheels()
    same(batch.toWheelAccelerations(wk, ca),
         [list(wk.toWheelAccelerations(ChassisAccelerations(*r))) for r in ca])
    w3 = rows(rng, N, 3)
    alpha = rng.uniform(-2, 2, N)
    same(batch.toChassisAccelerations(wk, w3, alpha),
         [accel(wk.toChassisAccelerations(list(r), a)) for r, a in zip(w3, alpha)])
    same(batch.toChassisAccelerations(wk, w3),
         [accel(wk.toChassisAccelerations(list(r))) for r in w3])


def accel(a):
    return [a.ax, a.ay, a.alpha]


@pytest.mark.parametrize("seed", SEEDS)
def test_desaturation_both_forms_and_in_place(seed):
    rng = np.random.default_rng(seed)
    mv = rows(rng, N, 8, scale=6.0).reshape(N, 4, 2)
    mv[4] = 0.0
    desired = rows(rng, N, 3, scale=5.0)

    def per_call(sample, *args):
        arr = sample.copy()
        SwerveDriveKinematics.desaturateWheelVelocitiesInPlace(arr, *args)
        objects = [SwerveModuleVelocity(v, R(a)) for v, a in sample]
        new = SwerveDriveKinematics.desaturateWheelVelocities(objects, *args)
        assert [s.velocity for s in new] == [v for v, _ in arr] or np.isnan(arr).any()
        return arr

    same(batch.desaturateWheelVelocities(mv, 3.0), [per_call(r, 3.0) for r in mv])
    limits = (4.0, 3.0, 6.0)
    expected = [per_call(r, ChassisVelocities(*d), *limits) for r, d in zip(mv, desired)]
    same(batch.desaturateWheelVelocities(mv, desired, *limits), expected)
    same(batch.desaturateWheelVelocities(mv[3], desired[3], *limits), expected[3])
    inplace = mv.copy()
    assert batch.desaturateWheelVelocities(inplace, desired, *limits, out=inplace) is inplace
    same(inplace, expected)

    w4 = rows(rng, N, 4, scale=6.0)
    expected = []
    for r in w4:
        v = MecanumDriveWheelVelocities(*r).desaturate(2.5)
        expected.append([v.frontLeft, v.frontRight, v.rearLeft, v.rearRight])
    same(batch.desaturate(w4, 2.5), expected)
    w2 = rows(rng, N, 2, scale=6.0)
    expected = [[v.left, v.right] for v in (DifferentialDriveWheelVelocities(*r).desaturate(2.5)
                                            for r in w2)]
    same(batch.desaturate(w2, 2.5), expected)
    batch.desaturate(w2, 2.5, out=w2)
    same(w2, expected)
