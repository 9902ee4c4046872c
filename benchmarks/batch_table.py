"""drivekin.batch throughput: drivekin's batch functions, numpy-vectorised code doing the
same math, and per-call loops (robotpy-wpimath and drivekin) over the same samples.

Issue 9 section 1 targets: every batch function >= 1.5x the numpy-vectorised version, and
odometry replay >= 20 M samples/s, on one core, N = 100,000, a 4-module swerve at
(+-0.3, +-0.3) m (the robot of ``_common.INPUTS``); issue 20's: swerve inverse kinematics
>= 5x numpy and swerve odometry replay >= 8x (TRIG_TARGETS).

Each numpy implementation is written here, in plain vectorised numpy, and is checked
against drivekin's output (to 1e-9) before anything is timed, so both columns compute the
same thing. The loops call the per-call API once per sample on argument objects prebuilt
in a list, keeping the results in a list (what a user replaying a log needs). Times are
the minimum over ``--repeats`` runs; the cases of one row are interleaved.

    python benchmarks/batch_table.py            # the table, about a minute
    python benchmarks/batch_table.py --quick    # CI smoke run (tiny N), a few seconds

Not part of the registry (``registry.py``): that times one-sample statements in ns/call,
while these are whole-array calls timed as samples per second.
"""
from __future__ import annotations

import os

# numpy's matmul goes to OpenBLAS, which would otherwise spread a (N, 8) @ (8, 3) product
# over every core; the comparison is one core against one core.
for _v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import argparse  # noqa: E402
import gc  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from dataclasses import dataclass, field  # noqa: E402
from typing import Callable, Optional  # noqa: E402

import numpy as np  # noqa: E402

from _common import INPUTS, catalog_kinematics, machine_description  # noqa: E402

RATIO_TARGET = 1.5          # drivekin batch / numpy-vectorised throughput
REPLAY_TARGET = 20.0        # M samples/s, swerve odometry replay
# Issue 20 (drivekin's own vectorised trig): rows whose ratio to numpy must be higher.
TRIG_TARGETS = {"swerve IK toSwerveModuleVelocities": 5.0, "swerve odometry replay": 8.0}
ATOL = 1e-9                 # agreement of every numpy implementation with drivekin

# Dead wheels for the dead-wheel rows: two forward-reading pods at y = +-0.15 m and one
# strafe pod at x = -0.1 m, as (x m, y m, reading direction rad).
DEAD_WHEELS = ((0.0, 0.15, 0.0), (0.0, -0.15, 0.0), (-0.1, 0.0, np.pi / 2))


# ---------------------------------------------------------------------------------------
# Samples

def make_data(n: int, seed: int = 9) -> dict:
    """Random but realistic stacks of n samples (float64, C-contiguous)."""
    rng = np.random.default_rng(seed)
    v = np.column_stack([rng.uniform(-3, 3, n), rng.uniform(-3, 3, n), rng.uniform(-4, 4, n)])
    # 5 % of the commands are an exact stop, so the swerve heading memory has work to do.
    v[rng.random(n) < 0.05] = 0.0
    modules = np.empty((n, 4, 2))
    modules[..., 0] = rng.uniform(-4, 4, (n, 4))
    modules[..., 1] = rng.uniform(-np.pi, np.pi, (n, 4))
    twists = np.column_stack([rng.uniform(-1, 1, n), rng.uniform(-1, 1, n),
                              rng.uniform(-4, 4, n)])
    twists[rng.random(n) < 0.01, 2] = 0.0          # straight-line twists (series branch)
    transforms = np.column_stack([rng.uniform(-5, 5, n), rng.uniform(-5, 5, n),
                                  rng.uniform(-np.pi, np.pi, n)])
    # A drive for the replay rows: per-step chassis velocities, the gyro integrating omega
    # (unwrapped, as a continuous gyro reports it) plus noise, and wheel/module distances
    # accumulating from a starting reading.
    dt = INPUTS.dt
    vel = np.column_stack([rng.uniform(-2, 2, n), rng.uniform(-2, 2, n),
                           rng.uniform(-3, 3, n)])
    gyro0 = INPUTS.robot_angle
    gyro = gyro0 + np.cumsum(vel[:, 2] * dt) + rng.normal(0, 1e-3, n)
    swerve_pos = np.empty((n, 4, 2))
    swerve_pos[..., 0] = 1.0 + np.cumsum(rng.uniform(-4, 4, (n, 4)) * dt, axis=0)
    swerve_pos[..., 1] = rng.uniform(-np.pi, np.pi, (n, 4))
    return dict(
        v=np.ascontiguousarray(v), modules=modules, twists=np.ascontiguousarray(twists),
        transforms=np.ascontiguousarray(transforms),
        angles=rng.uniform(-10, 10, n),
        mecanum=rng.uniform(-4, 4, (n, 4)), differential=rng.uniform(-4, 4, (n, 2)),
        deadwheel=rng.uniform(-4, 4, (n, 3)),
        gyro=gyro, gyro0=gyro0, swerve_pos=swerve_pos, swerve_pos0=np.ones(4),
        mecanum_pos=0.5 + np.cumsum(rng.uniform(-4, 4, (n, 4)) * dt, axis=0),
        mecanum_pos0=np.full(4, 0.5),
        diff_pos=np.cumsum(rng.uniform(-4, 4, (n, 2)) * dt, axis=0), diff_pos0=np.zeros(2),
        pose0=np.array(INPUTS.pose), dt=dt)


# ---------------------------------------------------------------------------------------
# The same math in numpy (what a numpy user would write). Geometry matrices are built here
# from the module positions, not read from drivekin.

def swerve_ik_matrix():
    rows = []
    for x, y in INPUTS.modules:
        rows += [[1.0, 0.0, -y], [0.0, 1.0, x]]
    return np.array(rows)                            # (2M, 3)


def mecanum_ik_matrix():
    (flx, fly), (frx, fry), (rlx, rly), (rrx, rry) = INPUTS.modules
    return np.array([[1.0, -1.0, -(flx + fly)], [1.0, 1.0, frx - fry],
                     [1.0, 1.0, rlx - rly], [1.0, -1.0, -(rrx + rry)]])


def deadwheel_matrix():
    return np.array([[np.cos(p), np.sin(p), x * np.sin(p) - y * np.cos(p)]
                     for x, y, p in DEAD_WHEELS])


def np_swerve_ik(v, heading0):
    """(N, 3) -> (N, M, 2); a module slower than 1e-6 m/s keeps its last heading
    (forward-filled with a running maximum of the index of its last real heading)."""
    mods = np.array(INPUTS.modules)
    x = v[:, 0:1] - mods[:, 1] * v[:, 2:3]
    y = v[:, 1:2] + mods[:, 0] * v[:, 2:3]
    speed = np.hypot(x, y)
    angle = np.arctan2(y, x)
    moving = speed > 1e-6
    if not moving.all():
        last = np.where(moving, np.arange(len(v))[:, None], -1)
        np.maximum.accumulate(last, axis=0, out=last)
        angle = np.where(last >= 0, np.take_along_axis(angle, np.maximum(last, 0), axis=0),
                         heading0)
    out = np.empty(x.shape + (2,))
    out[..., 0] = speed
    out[..., 1] = angle
    return out


def np_swerve_fk(states, f):
    """(N, M, 2) -> (N, 3) with f = pinv(IK matrix), (3, 2M)."""
    n, m = states.shape[:2]
    w = np.empty((n, m, 2))
    np.multiply(states[..., 0], np.cos(states[..., 1]), out=w[..., 0])
    np.multiply(states[..., 0], np.sin(states[..., 1]), out=w[..., 1])
    return w.reshape(n, 2 * m) @ f.T


def np_desaturate(speeds, limit):
    """Scale each row so its largest |speed| is at most limit (v / max * limit, WPILib's
    order of operations); speeds (N, W) -> (N, W)."""
    top = np.abs(speeds).max(axis=1, keepdims=True)
    return np.where(top > limit, speeds / np.where(top > limit, top, 1.0) * limit, speeds)


def np_swerve_desaturate(states, limit):
    out = states.copy()
    out[..., 0] = np_desaturate(states[..., 0], limit)
    return out


def np_swerve_ik_accel(a, omega):
    """(N, 3) [ax, ay, alpha] and (N,) omega -> (N, M, 2) [m/s², rad]: a + α × r − ω² r;
    an exactly zero chassis acceleration gives zeros, a module under 1e-6 m/s² angle 0."""
    mods = np.array(INPUTS.modules)
    w2 = (omega * omega)[:, None]
    x = a[:, 0:1] - mods[:, 0] * w2 - mods[:, 1] * a[:, 2:3]
    y = a[:, 1:2] - mods[:, 1] * w2 + mods[:, 0] * a[:, 2:3]
    mag = np.hypot(x, y)
    out = np.empty(x.shape + (2,))
    out[..., 0] = mag
    out[..., 1] = np.where(mag > 1e-6, np.arctan2(y, x), 0.0)
    out[(a == 0.0).all(axis=1)] = 0.0
    return out


def np_differential_ik(v, trackwidth):
    half = trackwidth / 2.0
    return np.column_stack([v[:, 0] - half * v[:, 2], v[:, 0] + half * v[:, 2]])


def np_differential_fk(w, trackwidth):
    return np.column_stack([(w[:, 0] + w[:, 1]) / 2.0, np.zeros(len(w)),
                            (w[:, 1] - w[:, 0]) / trackwidth])


def _log_k(theta, c, s):
    """(θ/2)·cot(θ/2) from θ and its cos/sin, without cancellation (drivekin's form)."""
    h = 0.5 * theta
    with np.errstate(divide="ignore", invalid="ignore"):
        k = np.where(c > 0.0, h * (1.0 + c) / s, -(h * s) / (c - 1.0))
    small = np.abs(theta) < 1e-9
    if small.any():
        k[small] = 1.0 - theta[small] ** 2 / 12.0
    return h, k


def np_discretize(v, dt):
    theta = v[:, 2] * dt
    x, y = v[:, 0] * dt, v[:, 1] * dt
    c, s = np.cos(theta), np.sin(theta)
    # The angle goes through a Rotation2d (wrapped); only |θ| >= 3 can change under the wrap.
    wide = np.abs(theta) >= 3.0
    if wide.any():
        theta = theta.copy()
        theta[wide] = np.arctan2(s[wide], c[wide])
    h, k = _log_k(theta, c, s)
    return np.column_stack([(k * x + h * y) / dt, (-h * x + k * y) / dt, theta / dt])


def np_rotate(v, angles, to_robot):
    c, s = np.cos(angles), np.sin(angles)
    if to_robot:
        s = -s
    return np.column_stack([v[:, 0] * c - v[:, 1] * s, v[:, 0] * s + v[:, 1] * c, v[:, 2]])


def _exp_parts(theta, s, c):
    """sin θ/θ and (1 − cos θ)/θ (stable form; series below 1e-9)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        a = s / theta
        b = np.where(c > 0.0, s * s / (1.0 + c), 1.0 - c) / theta
    small = np.abs(theta) < 1e-9
    if small.any():
        a[small] = 1.0 - theta[small] ** 2 / 6.0
        b[small] = 0.5 * theta[small]
    return a, b


def np_exp(t):
    dx, dy, theta = t[:, 0], t[:, 1], t[:, 2]
    s, c = np.sin(theta), np.cos(theta)
    a, b = _exp_parts(theta, s, c)
    return np.column_stack([dx * a - dy * b, dx * b + dy * a, np.arctan2(s, c)])


def np_log(tr):
    x, y = tr[:, 0], tr[:, 1]
    c, s = np.cos(tr[:, 2]), np.sin(tr[:, 2])
    theta = np.arctan2(s, c)
    h, k = _log_k(theta, c, s)
    return np.column_stack([k * x + h * y, -h * x + k * y, theta])


def np_integrate(dx, dy, gyro, gyro0, pose0):
    """Odometry from per-step robot-relative (dx, dy) and the gyro: each step's heading
    change is the wrapped gyro change, the heading is the initial one plus the gyro's
    change since the start, and each step's arc (Twist2d.exp) is rotated by the heading
    before it and summed. (N, 3) poses."""
    g = np.concatenate(([gyro0], gyro))
    cg, sg = np.cos(g), np.sin(g)
    # gyro_i - gyro_{i-1} as a rotation: its cos/sin are the exp's, its atan2 the dθ
    c = cg[1:] * cg[:-1] + sg[1:] * sg[:-1]
    s = sg[1:] * cg[:-1] - cg[1:] * sg[:-1]
    dtheta = np.arctan2(s, c)
    a, b = _exp_parts(dtheta, s, c)
    tx, ty = dx * a - dy * b, dx * b + dy * a
    # heading φ = θ0 + (g − g_start): rotate the gyro's (cos, sin) by θ0 − g_start
    off = pose0[2] - gyro0
    co, so = np.cos(off), np.sin(off)
    cp, sp = cg * co - sg * so, sg * co + cg * so
    out = np.empty((len(dx), 3))
    np.cumsum(tx * cp[:-1] - ty * sp[:-1], out=out[:, 0])
    np.cumsum(tx * sp[:-1] + ty * cp[:-1], out=out[:, 1])
    out[:, 0] += pose0[0]
    out[:, 1] += pose0[1]
    out[:, 2] = np.arctan2(sp[1:], cp[1:])
    return out


def np_swerve_replay(pos, pos0, gyro, gyro0, pose0, f):
    d = np.diff(pos[..., 0], axis=0, prepend=pos0[None, :])
    n, m = d.shape
    w = np.empty((n, m, 2))
    np.multiply(d, np.cos(pos[..., 1]), out=w[..., 0])
    np.multiply(d, np.sin(pos[..., 1]), out=w[..., 1])
    t = w.reshape(n, 2 * m) @ f[:2].T          # the heading row is the gyro's job
    return np_integrate(t[:, 0], t[:, 1], gyro, gyro0, pose0)


def np_mecanum_replay(pos, pos0, gyro, gyro0, pose0, f):
    t = np.diff(pos, axis=0, prepend=pos0[None, :]) @ f[:2].T
    return np_integrate(t[:, 0], t[:, 1], gyro, gyro0, pose0)


def np_differential_replay(pos, pos0, gyro, gyro0, pose0):
    d = np.diff(pos, axis=0, prepend=pos0[None, :])
    dx = (d[:, 0] + d[:, 1]) / 2.0
    return np_integrate(dx, np.zeros_like(dx), gyro, gyro0, pose0)


# ---------------------------------------------------------------------------------------
# Rows

@dataclass
class Row:
    title: str
    batch: Callable[[], object]              # drivekin.batch on the N samples
    numpy: Callable[[], object]              # the numpy implementation on the same
    batch_setup: Optional[Callable[[], None]] = None   # state reset before each batch run
    robotpy: Optional[Callable[[], object]] = None     # loop over n_loop prebuilt samples
    robotpy_setup: Optional[Callable[[], None]] = None
    loop: Optional[Callable[[], object]] = None        # drivekin per-call loop, n_loop
    loop_setup: Optional[Callable[[], None]] = None
    replay: bool = False
    # The checks: ``reference`` gives drivekin's result for the numpy comparison (default:
    # ``batch`` after ``batch_setup``); ``angles`` says which values are angles, compared
    # on the circle ("last": the last column; "modules": [..., 1]); ``rp_values`` turns the
    # robotpy loop's results into an array to compare with the first n_loop samples.
    reference: Optional[Callable[[], np.ndarray]] = None
    angles: str = ""
    rp_values: Optional[Callable[[list], np.ndarray]] = None
    times: dict = field(default_factory=dict)


def speeds3(res):
    return np.array([[c.vx, c.vy, c.omega] for c in res])


def poses(res):
    return np.array([[p.X(), p.Y(), p.rotation().radians()] for p in res])


class Objects:
    """drivekin and robotpy objects for the fixed robot (drivekin's swerve, mecanum and
    differential kinematics: the catalog's examples, checked to be INPUTS' robot)."""

    def __init__(self):
        from drivekin import deadwheel, differential, geometry, kinematics, mecanum, odometry
        from wpimath import geometry as rg, kinematics as rk
        self.dg, self.dk, self.dm, self.dd, self.dw, self.do = (
            geometry, kinematics, mecanum, differential, deadwheel, odometry)
        self.rg, self.rk = rg, rk
        self.kin = catalog_kinematics("swerve")
        self.mkin = catalog_kinematics("mecanum")
        self.dkin = catalog_kinematics("differential")
        self.wkin = deadwheel.DeadWheelKinematics(
            [geometry.Pose2d(x, y, geometry.Rotation2d(p)) for x, y, p in DEAD_WHEELS])
        rt = [rg.Translation2d(x, y) for x, y in INPUTS.modules]
        self.rkin = rk.SwerveDrive4Kinematics(*rt)
        self.rmkin = rk.MecanumDriveKinematics(*rt)
        self.rdkin = rk.DifferentialDriveKinematics(INPUTS.trackwidth)

    def fresh_swerve(self):
        return catalog_kinematics("swerve")


def build_rows(o: Objects, d: dict, n_loop: int) -> list:
    import drivekin.batch as B

    dg, dk, rg, rk = o.dg, o.dk, o.rg, o.rk
    v, modules, dt = d["v"], d["modules"], d["dt"]
    L = slice(0, n_loop)
    # Prebuilt per-call arguments for the loops (first n_loop samples).
    cvs = [dk.ChassisVelocities(*r) for r in v[L].tolist()]
    css = [rk.ChassisSpeeds(*r) for r in v[L].tolist()]
    dstates = [tuple(dk.SwerveModuleVelocity(s, dg.Rotation2d(a)) for s, a in m)
               for m in modules[L].tolist()]
    rstates = [tuple(rk.SwerveModuleState(s, rg.Rotation2d(a)) for s, a in m)
               for m in modules[L].tolist()]
    drot = [dg.Rotation2d(a) for a in d["angles"][L].tolist()]
    rrot = [rg.Rotation2d(a) for a in d["angles"][L].tolist()]
    f_swerve = np.linalg.pinv(swerve_ik_matrix())
    m_mec = mecanum_ik_matrix()
    f_mec = np.linalg.pinv(m_mec)
    m_dead = deadwheel_matrix()
    f_dead = np.linalg.pinv(m_dead)
    tw = INPUTS.trackwidth
    rows = []

    def add(*args, **kw):
        rows.append(Row(*args, **kw))

    kin = o.kin
    add("swerve IK toSwerveModuleVelocities",
        lambda: B.toSwerveModuleVelocities(kin, v), lambda: np_swerve_ik(v, 0.0),
        robotpy=lambda f=o.rkin.toSwerveModuleStates: [f(c) for c in css],
        loop=lambda f=kin.toSwerveModuleVelocities: [f(c) for c in cvs],
        # from a fresh heading memory (every module at 0 rad), as np_swerve_ik assumes
        reference=lambda: B.toSwerveModuleVelocities(o.fresh_swerve(), v), angles="modules",
        rp_values=lambda res: np.array([[[m.speed, m.angle.radians()] for m in r]
                                        for r in res]))
    add("swerve FK toChassisVelocities",
        lambda: B.toChassisVelocities(kin, modules), lambda: np_swerve_fk(modules, f_swerve),
        robotpy=lambda f=o.rkin.toChassisSpeeds: [f(s) for s in rstates],
        loop=lambda f=kin.toChassisVelocities: [f(s) for s in dstates], rp_values=speeds3)

    mw = d["mecanum"]
    mwd = [o.dm.MecanumDriveWheelVelocities(*r) for r in mw[L].tolist()]
    mwr = [rk.MecanumDriveWheelSpeeds(*r) for r in mw[L].tolist()]
    add("mecanum IK toWheelVelocities",
        lambda: B.toWheelVelocities(o.mkin, v), lambda: v @ m_mec.T,
        robotpy=lambda f=o.rmkin.toWheelSpeeds: [f(c) for c in css],
        loop=lambda f=o.mkin.toWheelVelocities: [f(c) for c in cvs],
        rp_values=lambda res: np.array([[w.frontLeft, w.frontRight, w.rearLeft, w.rearRight]
                                        for w in res]))
    add("mecanum FK toChassisVelocities",
        lambda: B.toChassisVelocities(o.mkin, mw), lambda: mw @ f_mec.T,
        robotpy=lambda f=o.rmkin.toChassisSpeeds: [f(w) for w in mwr],
        loop=lambda f=o.mkin.toChassisVelocities: [f(w) for w in mwd], rp_values=speeds3)

    dw = d["differential"]
    dwd = [o.dd.DifferentialDriveWheelVelocities(*r) for r in dw[L].tolist()]
    dwr = [rk.DifferentialDriveWheelSpeeds(*r) for r in dw[L].tolist()]
    add("differential IK toWheelVelocities",
        lambda: B.toWheelVelocities(o.dkin, v), lambda: np_differential_ik(v, tw),
        robotpy=lambda f=o.rdkin.toWheelSpeeds: [f(c) for c in css],
        loop=lambda f=o.dkin.toWheelVelocities: [f(c) for c in cvs],
        rp_values=lambda res: np.array([[w.left, w.right] for w in res]))
    add("differential FK toChassisVelocities",
        lambda: B.toChassisVelocities(o.dkin, dw), lambda: np_differential_fk(dw, tw),
        robotpy=lambda f=o.rdkin.toChassisSpeeds: [f(w) for w in dwr],
        loop=lambda f=o.dkin.toChassisVelocities: [f(w) for w in dwd], rp_values=speeds3)

    ww = d["deadwheel"]
    wwd = [tuple(r) for r in ww[L].tolist()]
    add("dead-wheel (3) IK toWheelVelocities",
        lambda: B.toWheelVelocities(o.wkin, v), lambda: v @ m_dead.T,
        loop=lambda f=o.wkin.toWheelVelocities: [f(c) for c in cvs])
    add("dead-wheel (3) FK toChassisVelocities",
        lambda: B.toChassisVelocities(o.wkin, ww), lambda: ww @ f_dead.T,
        loop=lambda f=o.wkin.toChassisVelocities: [f(w) for w in wwd])

    limit = 2.5
    add("swerve desaturateWheelVelocities(states, max)",
        lambda: B.desaturateWheelVelocities(modules, limit),
        lambda: np_swerve_desaturate(modules, limit),
        robotpy=lambda f=rk.SwerveDrive4Kinematics.desaturateWheelSpeeds: [
            f(s, limit) for s in rstates],
        loop=lambda f=dk.SwerveDriveKinematics.desaturateWheelVelocities: [
            f(s, limit) for s in dstates],
        rp_values=lambda res: np.array([[[m.speed, m.angle.radians()] for m in r]
                                        for r in res]), angles="modules")
    add("mecanum desaturate(max)",
        lambda: B.desaturate(mw, limit), lambda: np_desaturate(mw, limit),
        loop=lambda: [w.desaturate(limit) for w in mwd])
    omega = d["angles"] * 0.3
    cas = [dk.ChassisAccelerations(*r) for r in v[L].tolist()]
    add("swerve IK toSwerveModuleAccelerations(a, omega)",
        lambda: B.toSwerveModuleAccelerations(kin, v, omega),
        lambda: np_swerve_ik_accel(v, omega),
        loop=lambda f=kin.toSwerveModuleAccelerations: [
            f(c, w) for c, w in zip(cas, omega[L].tolist())], angles="modules")

    add("discretize",
        lambda: B.discretize(v, dt), lambda: np_discretize(v, dt),
        robotpy=lambda f=rk.ChassisSpeeds.discretize: [f(c, dt) for c in css],
        loop=lambda: [c.discretize(dt) for c in cvs], rp_values=speeds3)
    a = d["angles"]
    pairs_r, pairs_d = list(zip(css, rrot)), list(zip(cvs, drot))
    add("toRobotRelative",
        lambda: B.toRobotRelative(v, a), lambda: np_rotate(v, a, True),
        robotpy=lambda f=rk.ChassisSpeeds.fromFieldRelativeSpeeds: [f(c, r)
                                                                      for c, r in pairs_r],
        loop=lambda: [c.toRobotRelative(r) for c, r in pairs_d], rp_values=speeds3)
    add("toFieldRelative",
        lambda: B.toFieldRelative(v, a), lambda: np_rotate(v, a, False),
        robotpy=lambda f=rk.ChassisSpeeds.fromRobotRelativeSpeeds: [f(c, r)
                                                                      for c, r in pairs_r],
        loop=lambda: [c.toFieldRelative(r) for c, r in pairs_d], rp_values=speeds3)

    t, x = d["twists"], d["transforms"]
    tws_r = [rg.Twist2d(*r) for r in t[L].tolist()]
    tws_d = [dg.Twist2d(*r) for r in t[L].tolist()]
    poses_r = [rg.Pose2d(p, q, rg.Rotation2d(r)) for p, q, r in x[L].tolist()]
    trs_d = [dg.Transform2d(p, q, dg.Rotation2d(r)) for p, q, r in x[L].tolist()]
    origin = rg.Pose2d()
    add("Twist2d.exp", lambda: B.exp(t), lambda: np_exp(t),
        robotpy=lambda f=origin.exp: [f(w) for w in tws_r],
        loop=lambda: [w.exp() for w in tws_d], angles="last", rp_values=poses)
    add("Transform2d.log", lambda: B.log(x), lambda: np_log(x),
        robotpy=lambda f=origin.log: [f(p) for p in poses_r],
        loop=lambda: [p.log() for p in trs_d],
        rp_values=lambda res: np.array([[w.dx, w.dy, w.dtheta] for w in res]))

    rows += replay_rows(o, d, n_loop, f_swerve, f_mec)
    return rows


def replay_rows(o: Objects, d: dict, n_loop: int, f_swerve, f_mec) -> list:
    import drivekin.batch as B

    dg, dk, rg, rk, do = o.dg, o.dk, o.rg, o.rk, o.do
    g, g0, pose0 = d["gyro"], d["gyro0"], d["pose0"]
    L = slice(0, n_loop)
    dgyro = [dg.Rotation2d(a) for a in g[L].tolist()]
    rgyro = [rg.Rotation2d(a) for a in g[L].tolist()]
    dpose0 = dg.Pose2d(pose0[0], pose0[1], dg.Rotation2d(pose0[2]))
    rpose0 = rg.Pose2d(pose0[0], pose0[1], rg.Rotation2d(pose0[2]))
    rows = []
    state = {}

    # swerve
    sp, sp0 = d["swerve_pos"], d["swerve_pos0"]
    a0 = sp[0, :, 1].tolist()
    dpos = [tuple(dk.SwerveModulePosition(s, dg.Rotation2d(a)) for s, a in m)
            for m in sp[L].tolist()]
    rpos = [tuple(rk.SwerveModulePosition(s, rg.Rotation2d(a)) for s, a in m)
            for m in sp[L].tolist()]

    def swerve_odo():
        return do.SwerveDriveOdometry(
            o.kin, dg.Rotation2d(g0),
            [dk.SwerveModulePosition(s, dg.Rotation2d(a)) for s, a in zip(sp0, a0)], dpose0)

    def rp_swerve_odo():
        return rk.SwerveDrive4Odometry(
            o.rkin, rg.Rotation2d(g0),
            tuple(rk.SwerveModulePosition(s, rg.Rotation2d(a)) for s, a in zip(sp0, a0)),
            rpose0)

    def setter(key, make):
        return lambda: state.__setitem__(key, make())

    rows.append(Row(
        "swerve odometry replay", lambda: B.replay(state["s"], g, sp),
        lambda: np_swerve_replay(sp, sp0, g, g0, pose0, f_swerve),
        batch_setup=setter("s", swerve_odo),
        robotpy=lambda: [state["rs"].update(a, p) for a, p in zip(rgyro, rpos)],
        robotpy_setup=setter("rs", rp_swerve_odo),
        loop=lambda: [state["ds"].update(a, p) for a, p in zip(dgyro, dpos)],
        loop_setup=setter("ds", swerve_odo), replay=True, angles="last",
        rp_values=poses))

    # mecanum
    mp, mp0 = d["mecanum_pos"], d["mecanum_pos0"]
    dmp = [o.dm.MecanumDriveWheelPositions(*r) for r in mp[L].tolist()]
    rmp = []
    for r in mp[L].tolist():
        p = rk.MecanumDriveWheelPositions()
        p.frontLeft, p.frontRight, p.rearLeft, p.rearRight = r
        rmp.append(p)

    def mec_odo():
        return do.MecanumDriveOdometry(o.mkin, dg.Rotation2d(g0),
                                       o.dm.MecanumDriveWheelPositions(*mp0), dpose0)

    def rp_mec_odo():
        p = rk.MecanumDriveWheelPositions()
        p.frontLeft, p.frontRight, p.rearLeft, p.rearRight = mp0.tolist()
        return rk.MecanumDriveOdometry(o.rmkin, rg.Rotation2d(g0), p, rpose0)

    rows.append(Row(
        "mecanum odometry replay", lambda: B.replay(state["m"], g, mp),
        lambda: np_mecanum_replay(mp, mp0, g, g0, pose0, f_mec),
        batch_setup=setter("m", mec_odo),
        robotpy=lambda: [state["rm"].update(a, p) for a, p in zip(rgyro, rmp)],
        robotpy_setup=setter("rm", rp_mec_odo),
        loop=lambda: [state["dm"].update(a, p) for a, p in zip(dgyro, dmp)],
        loop_setup=setter("dm", mec_odo), replay=True, angles="last",
        rp_values=poses))

    # differential
    dp, dp0 = d["diff_pos"], d["diff_pos0"]
    lr = [tuple(r) for r in dp[L].tolist()]

    def diff_odo():
        return do.DifferentialDriveOdometry(dg.Rotation2d(g0), *dp0.tolist(), dpose0)

    def rp_diff_odo():
        return rk.DifferentialDriveOdometry(rg.Rotation2d(g0), *dp0.tolist(), rpose0)

    rows.append(Row(
        "differential odometry replay", lambda: B.replay(state["d"], g, dp),
        lambda: np_differential_replay(dp, dp0, g, g0, pose0),
        batch_setup=setter("d", diff_odo),
        robotpy=lambda: [state["rd"].update(a, x, y) for a, (x, y) in zip(rgyro, lr)],
        robotpy_setup=setter("rd", rp_diff_odo),
        loop=lambda: [state["dd"].update(a, x, y) for a, (x, y) in zip(dgyro, lr)],
        loop_setup=setter("dd", diff_odo), replay=True, angles="last",
        rp_values=poses))
    return rows



# ---------------------------------------------------------------------------------------
# Agreement checks (before timing)

def max_error(got: np.ndarray, want: np.ndarray, angles: str) -> float:
    """Largest absolute difference; angles are compared on the circle (π and −π agree)."""
    if got.shape != want.shape:
        raise AssertionError(f"shapes differ: {got.shape} vs {want.shape}")
    diff = np.abs(got - want)
    if angles:
        idx = (..., 1) if angles == "modules" else (..., -1)
        d = got[idx] - want[idx]
        diff[idx] = np.abs(np.arctan2(np.sin(d), np.cos(d)))
    return float(np.max(diff)) if diff.size else 0.0


def check(row: Row) -> list:
    """Assert that the numpy implementation gives drivekin's numbers; compare the robotpy
    loop's first n_loop results too. Returns notes for the table."""
    if row.batch_setup:
        row.batch_setup()
    ref = row.reference() if row.reference else row.batch()
    err = max_error(ref, row.numpy(), row.angles)
    assert err <= ATOL, f"{row.title}: numpy differs from drivekin by {err:.3g} > {ATOL:g}"
    notes = []
    if row.robotpy and row.rp_values:
        if row.robotpy_setup:
            row.robotpy_setup()
        rp = row.rp_values(row.robotpy())
        e = max_error(ref[:len(rp)], rp, row.angles)
        if not e <= ATOL:
            notes.append(f"{row.title}: robotpy differs from drivekin by {e:.3g}")
    return notes


# ---------------------------------------------------------------------------------------
# Timing

def pin(cpu):
    if hasattr(os, "sched_setaffinity"):
        cpus = sorted(os.sched_getaffinity(0))
        os.sched_setaffinity(0, {cpus[-1] if cpu is None else cpu})


CASES = (("batch", "batch_setup"), ("numpy", None), ("robotpy", "robotpy_setup"),
         ("loop", "loop_setup"))


def measure(rows: list, repeats: int, log) -> None:
    """Minimum time of each case over ``repeats`` runs; the cases of a row take turns, so
    a burst of load from another process hits them alike. Set-up is not timed."""
    clock = time.perf_counter
    gc_was = gc.isenabled()
    gc.disable()
    try:
        for row in rows:
            for name, _ in CASES:
                if getattr(row, name) is not None:
                    row.times[name] = float("inf")
            for _ in range(repeats):
                for name, setup in CASES:
                    fn = getattr(row, name)
                    if fn is None:
                        continue
                    if setup and getattr(row, setup):
                        getattr(row, setup)()
                    t0 = clock()
                    res = fn()
                    t = clock() - t0
                    del res
                    gc.collect()        # the loops' result lists, outside the timing
                    row.times[name] = min(row.times[name], t)
            log(f"  {row.title} done")
    finally:
        if gc_was:
            gc.enable()


# ---------------------------------------------------------------------------------------
# Table

def table(rows: list, n: int, n_loop: int, repeats: int, quick: bool) -> tuple:
    def rate(row, name, count):
        t = row.times.get(name)
        return None if t is None else count / t / 1e6

    def cell(x):
        return "—" if x is None else (f"{x:.1f}" if x >= 1 else f"{x:.3f}")

    lines = ["## drivekin.batch throughput" + (" (--quick smoke run)" if quick else ""), ""]
    lines += [f"* {m}" for m in machine_description()]
    lines += [f"* N = {n:,} samples per batch / numpy call, {n_loop:,} per loop; minimum of "
              f"{repeats} runs per case, cases interleaved, GC off; one thread "
              "(OPENBLAS_NUM_THREADS=1)", "",
              "| operation | drivekin batch M samples/s | numpy-vectorised M samples/s | "
              f"ratio batch / numpy (target ≥ {RATIO_TARGET}×) | met? | robotpy loop "
              "M samples/s | drivekin per-call loop M samples/s |",
              "|---|---:|---:|---:|:---:|---:|---:|"]
    missed = []
    for row in rows:
        b, p = rate(row, "batch", n), rate(row, "numpy", n)
        ratio = b / p
        target = TRIG_TARGETS.get(row.title, RATIO_TARGET)
        ok = ratio >= target
        met = ("yes" if ok else "**NO**") + (f" (≥ {target:g}×)" if target != RATIO_TARGET
                                             else "")
        if not ok:
            missed.append(f"{row.title}: {ratio:.2f}× numpy < {target:g}×")
        if row.title.startswith("swerve odometry"):
            r_ok = b >= REPLAY_TARGET
            met += "; " + (f"≥ {REPLAY_TARGET:g} M/s yes" if r_ok
                           else f"≥ {REPLAY_TARGET:g} M/s **NO**")
            if not r_ok:
                missed.append(f"{row.title}: {b:.1f} M samples/s < {REPLAY_TARGET:g}")
        lines.append(f"| {row.title} | {cell(b)} | {cell(p)} | {ratio:.2f}× | {met} | "
                     f"{cell(rate(row, 'robotpy', n_loop))} | "
                     f"{cell(rate(row, 'loop', n_loop))} |")
    lines += ["", "Robot: 4-module swerve and mecanum at (±0.3, ±0.3) m, differential "
              f"trackwidth {INPUTS.trackwidth} m, dead wheels {DEAD_WHEELS!r} "
              "(x m, y m, direction rad). Each numpy implementation (in this file) matches "
              f"drivekin's output to {ATOL:g} on these samples. — : robotpy has no such "
              "operation. Swerve IK includes the heading memory (5 % of the commands are "
              "exact stops) in both columns."]
    if quick:
        lines += ["", "Smoke run: N too small for the numbers to mean anything; targets "
                  "not judged."]
    elif missed:
        lines += ["", "Targets missed: " + "; ".join(missed)]
    return lines, missed


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="CI smoke run: N = 2000, 2 repeats")
    ap.add_argument("-n", type=int, default=None, help="samples per batch call (100000)")
    ap.add_argument("--n-loop", type=int, default=None,
                    help="samples per per-call loop (10000)")
    ap.add_argument("--repeats", type=int, default=None, help="runs per case (7)")
    ap.add_argument("--only", default="", help="comma-separated substrings of row titles")
    ap.add_argument("--cpu", type=int, default=None, help="CPU to pin to (default: last)")
    ap.add_argument("--no-pin", action="store_true")
    ap.add_argument("--strict", action="store_true", help="exit 1 if a target is missed")
    args = ap.parse_args(argv)
    preset = (dict(n=2000, n_loop=200, repeats=2) if args.quick
              else dict(n=100_000, n_loop=10_000, repeats=7))
    for k, val in preset.items():
        if getattr(args, k) is None:
            setattr(args, k, val)
    if args.n_loop > args.n:
        ap.error("--n-loop must not exceed -n")
    log = (lambda m: print(m, file=sys.stderr, flush=True))
    if not args.no_pin:
        pin(args.cpu)

    data = make_data(args.n)
    rows = build_rows(Objects(), data, args.n_loop)
    if args.only:
        keys = [k.strip() for k in args.only.split(",") if k.strip()]
        rows = [r for r in rows if any(k in r.title for k in keys)]
    notes = [note for row in rows for note in check(row)]
    log(f"values agree; timing {len(rows)} rows x {args.repeats} runs")
    measure(rows, args.repeats, log)
    lines, missed = table(rows, args.n, args.n_loop, args.repeats, args.quick)
    if notes:
        lines += ["", "Value notes (robotpy vs drivekin):"] + [f"* {x}" for x in notes]
    print("\n".join(lines))
    return 1 if (args.strict and missed and not args.quick) else 0


if __name__ == "__main__":
    sys.exit(main())
