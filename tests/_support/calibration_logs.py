"""``.wpilog`` files of simulated robots whose true geometry is known, for the calibration
tests (issue 19): the robot believes wrong parameters (worn wheels, a scrubbing
trackwidth, a mis-scaled gyro, steer offsets, mis-measured dead wheels), its sensors read
what the *true* robot does, and the log says what the robot believed.

Written by robotpy-wpiutil's ``DataLogWriter`` (values packed by ``wpistruct`` where
robotpy has the struct, by ``struct.pack`` with a hand-registered WPILib schema where
robotpy 2026 has none), in layouts drivekin's replay detects. Nothing here uses drivekin
to make a log; :func:`replay_drift` (a checking helper) and :func:`demo_log` (the demo's
own log) do.

API
---

``write_calibration_log(path, kind, *, seed=0, ...) -> SimulatedLog`` writes one log;
``kind`` is ``"swerve"`` (4 modules on a rectangle), ``"differential"``, ``"mecanum"`` or
``"deadwheel"`` (three dead wheels and a gyro on a holonomic chassis). Every keyword is
documented on the function; the wrong parameters default to a plausible worn robot
(:data:`DEFAULTS`). ``swerve_log``, ``differential_log``, ``mecanum_log`` and
``deadwheel_log`` are the same with ``kind`` filled in. :func:`demo_log` writes the log of
``python -m drivekin --vision --log`` (the demo's worn wheels) and returns its truth.

Conventions (``SimulatedLog.truth`` and ``SimulatedLog.believed`` have the same keys;
``truth`` is the real robot, ``believed`` what its configuration says, the values the
logged readings were converted with; all plain floats / lists, JSON-ready):

* ``wheelRadiusScale``: list, one per module (swerve FL FR BL BR, mecanum FL FR RL RR),
  per side (differential ``[left, right]``) or per dead wheel: true radius / the radius
  the robot uses. **logged distance × scale = true wheel travel** (so ``replay
  --wheel-scale S`` with all scales equal to S corrects the log). Believed: all 1.0.
* ``gyroScale``: **gyroScale × (change of the logged yaw) = change of the true heading**
  (the logged yaw is ``GYRO0 + (θ − θ₀) / gyroScale``). Believed 1.0.
* ``steerOffsets`` (swerve): list of 4, rad. **true module angle = logged angle +
  offset** (the logged angle is ``wrap(true − offset)``). Believed zeros.
* ``trackwidth`` (differential): the effective trackwidth, m (what
  ``(Δright − Δleft) / Δθ`` of the *true* wheel travel gives); believed: the robot's
  configured one, also in the log (``/Drive/Kinematics``) and in ``logged``.
* ``deadWheelPoses`` (deadwheel): ``[(x m, y m, direction rad), ...]`` in the order of
  the positions array; a wheel at (x, y) rolling along φ reads
  ``cos φ·(dx − y·dθ) + sin φ·(dy + x·dθ)`` (drivekin's DeadWheelKinematics).
  ``logged["deadWheels"]`` has the believed poses with the direction in **degrees**
  (ReplayConfig's unit).
* ``modules`` (swerve, mecanum): ``[(x, y), ...]`` m, the rectangle; true = believed
  (geometry errors there are not simulated), also in ``/Drive/Kinematics``.

``SimulatedLog.logged`` holds the :class:`drivekin.replay.ReplayConfig` fields the replay
needs for this log (``ReplayConfig(**sim.logged)`` replays it): ``drivetrain`` always;
``trackwidth`` (differential, the configured one); ``positions`` and ``deadWheels``
(deadwheel). ``sim.config(**more)`` builds that ReplayConfig with extra fields (e.g.
``truth=sim.entries["reference"]``).

Entries: ``/Drive/Gyro`` struct:Rotation2d (unwrapped rad), ``/Odometry/Robot``
struct:Pose2d (the robot's own odometry from the logged readings and the believed
geometry, started at the true start pose: robotpy-wpimath's odometry classes, numpy
for dead wheels), ``/Drive/Kinematics`` (the believed geometry, once), and

* swerve: ``/Drive/ModulePositions`` struct:SwerveModulePosition[] (m, rad),
  ``/Drive/Kinematics`` struct:SwerveDriveKinematics__4;
* differential: ``/Drive/WheelPositions`` struct:DifferentialDriveWheelPositions (m),
  ``/Drive/Kinematics`` struct:DifferentialDriveKinematics (robotpy's schema
  ``double track_width``);
* mecanum: ``/Drive/WheelPositions`` struct:MecanumDriveWheelPositions (m),
  ``/Drive/Kinematics`` struct:MecanumDriveKinematics;
* deadwheel: ``/Drive/DeadWheelPositions`` double[3] (m, metadata ``{"unit":"m"}``),
  no kinematics struct (the poses are in ``logged["deadWheels"]``);
* ``reference="pose"``: ``/Vision/Pose`` struct:Pose2d, the true pose plus noise at
  ``reference_rate_hz`` (replay never takes it for the robot's pose: "vision").

All entries share one clock: samples every ``1e6 / rate_hz`` µs from ``T0_US``; the gyro
is sampled with the wheels (same timestamps).

The motion
----------

The true motion is a chain of manoeuvres, each made of *moves* that ramp a constant
robot-relative velocity (vx, vy, ω) up from rest with a smoothstep (``RAMP_S``), hold it,
and ramp it back to rest, with ``REST_S`` of rest between moves (``LEAD_S`` before the
first, ``TAIL_S`` after the last). Within a move the velocity keeps its direction, so
module angles stay constant and a correct odometry reproduces the truth exactly at the
samples (up to the 4 kHz integration of the truth: 1e-8 m over a default log); only
``"drive_spin"`` (a field-relative line while spinning) turns the modules while driving.
Manoeuvres (:data:`MANOEUVRES`):

* ``"spin"`` / ``"spin_cw"``: in place, ``spin_turns`` (3) turns at ``spin_rate``
  (1.5 rad/s), CCW / CW;
* ``"straight"``: forward at ``speed`` (2 m/s) for ``straight_s`` (1.5 s) of hold, then
  back the same;
* ``"turn"``: an arc left (``speed`` × 0.75, ω = 1 rad/s) for one full turn, then one
  right;
* ``"arcs"``: an arc left (``speed`` × 0.75) turning ``ARC_TURN`` (3.5) rad in
  ``ARC_S`` (3) s, ramps included, then one right (ordinary driving: no spin);
* ``"strafe"`` (swerve, mecanum, deadwheel): left at 1.5 m/s, then right;
* ``"drive_spin"`` (holonomic): 1.5 m/s along the heading at its start while spinning at
  1.5 rad/s for 2 turns;
* ``"rest"``: 2 s still;
* or a tuple ``(hold_s, vx, vy, omega)``: one robot-relative move.

Default manoeuvres: ``("spin", "straight", "turn")`` for differential (36.6 s) and
``("spin", "straight", "turn", "strafe")`` for the others (43.1 s). Every default
manoeuvre returns to where it started, so the believed-parameter drift is largest in the
middle of the log, not at its end (use max / RMS drift).

``"drive_spin"`` is not in the defaults: turning the modules while driving, it makes the
odometry itself err (WPILib's odometry takes each step's distance along the module angle
at the step's end: ≈ ω·Δt/2 of the distance driven, 17 cm at 50 Hz and 3.4 cm at 250 Hz
over its 2 turns with every parameter correct), an error no parameter fit removes.
The swerve modules point along their velocity, keeping the angle while still and driving
backwards rather than turning more than 90° (WPILib's ``optimize``).
``SimulatedLog.windows`` lists each manoeuvre's time span on the log clock.

Noise (``noise=``): white Gaussian, seeded (``numpy.random.default_rng(seed)``), on each
logged wheel distance (``"position"``, m), module angle (``"angle"``, rad), gyro sample
(``"gyro"``, rad), and the reference pose (``"reference_xy"`` m, ``"reference_theta"``
rad). The noise arrays are drawn in a fixed order at unit scale and multiplied by the
std-devs, so one seed gives the same pattern at every noise level. The robot's logged
pose is computed from the noisy readings.
"""
from __future__ import annotations

import functools
import json
import math
import os
import pathlib
import struct
from dataclasses import dataclass, field
from typing import Any, Sequence

import numpy as np

__all__ = ["DEFAULTS", "KINDS", "MANOEUVRES", "NOISE", "SimulatedLog", "deadwheel_log",
           "demo_log", "differential_log", "mecanum_log", "replay_drift", "swerve_log",
           "write_calibration_log"]

KINDS = ("swerve", "differential", "mecanum", "deadwheel")
FINE_US = 250                       # the truth's integration grid: 4 kHz
T0_US = 1_000_000                   # log clock (µs) of motion time 0
START = (1.5, 2.0, 0.3)             # true start pose (x m, y m, θ rad)
GYRO0 = -1.2                        # the gyro's reading at motion time 0, rad
LEAD_S, REST_S, TAIL_S, RAMP_S = 1.0, 0.75, 1.0, 0.5
ARC_TURN, ARC_S = 3.5, 3.0          # an "arcs" move turns 3.5 rad in 3 s

MANOEUVRES = ("spin", "spin_cw", "straight", "turn", "arcs", "strafe", "drive_spin", "rest")
WRITERS = ("wpiutil", "ntcore")
_HOLONOMIC_ONLY = ("strafe", "drive_spin")

#: Std-devs of the default noise (``noise=None``); ``noise=k`` multiplies them by k.
NOISE = {"position": 2e-4, "angle": 2e-3, "gyro": 1e-3, "reference_xy": 5e-3,
         "reference_theta": 5e-3}

#: Per kind: the true parameters the keywords default to (the robot believes 1.0 scales,
#: zero offsets and ``believed_*``).
DEFAULTS: dict[str, dict[str, Any]] = {
    "swerve": {"wheel_scale": (0.97, 0.975, 0.965, 0.98), "trackwidth": 0.55,
               "wheelbase": 0.60},
    "differential": {"wheel_scale": (0.97, 0.985), "trackwidth": 0.62,
                     "believed_trackwidth": 0.56},
    "mecanum": {"wheel_scale": (0.97, 0.98, 0.975, 0.965), "trackwidth": 0.50,
                "wheelbase": 0.45},
    # Road Runner's usual three-wheel layout: two parallel wheels left and right, one
    # perpendicular wheel behind the centre; the robot's measurements are off by 1-2 cm
    # and a degree or two.
    "deadwheel": {"wheel_scale": (1.0, 1.0, 1.0),
                  "dead_wheels": ((-0.02, 0.17, 0.0), (-0.02, -0.165, 0.0),
                                  (-0.11, 0.01, math.pi / 2)),
                  "believed_dead_wheels": ((0.0, 0.155, 0.0), (0.0, -0.18, 0.02),
                                           (-0.09, 0.0, math.pi / 2 - 0.03)),
                  "trackwidth": 0.40, "wheelbase": 0.40},
}

ENTRY_GYRO = "/Drive/Gyro"
ENTRY_POSE = "/Odometry/Robot"
ENTRY_KINEMATICS = "/Drive/Kinematics"
ENTRY_REFERENCE = "/Vision/Pose"
ENTRY_POSITIONS = {"swerve": "/Drive/ModulePositions", "differential": "/Drive/WheelPositions",
                   "mecanum": "/Drive/WheelPositions", "deadwheel": "/Drive/DeadWheelPositions"}

# WPILib struct schemas robotpy-wpimath 2026 cannot publish itself (its classes have no
# WPIStruct): registered by hand, packed with struct.pack.
_SCHEMA_DIFF_POSITIONS = ("DifferentialDriveWheelPositions", "double left;double right")
_SCHEMA_MECANUM_POSITIONS = ("MecanumDriveWheelPositions",
                             "double front_left;double front_right;double rear_left;"
                             "double rear_right")


@dataclass
class SimulatedLog:
    """One written log and what is true about it (see the module docstring)."""

    path: pathlib.Path
    truth: dict
    logged: dict                         # ReplayConfig fields the replay needs
    kind: str
    believed: dict = field(default_factory=dict)    # truth's keys: the robot's config
    entries: dict = field(default_factory=dict)     # role -> entry name
    t_us: np.ndarray = field(default=None, repr=False)     # (N,) sample times, µs
    poses: np.ndarray = field(default=None, repr=False)    # (N, 3) true poses at t_us
    windows: list = field(default_factory=list)     # [(manoeuvre, start µs, end µs)]
    noise: dict = field(default_factory=dict)       # the std-devs used
    notes: dict = field(default_factory=dict)       # seed, rates, start pose, ...

    def config(self, **overrides):
        """``ReplayConfig(**self.logged, **overrides)``."""
        from drivekin.replay import ReplayConfig

        return ReplayConfig(**{**self.logged, **overrides})


# ---------------------------------------------------------------------------------------
# The motion


@dataclass(frozen=True)
class _Move:
    manoeuvre: str
    target: tuple[float, float, float]      # (vx, vy, ω) at full speed
    hold: float                             # s at full speed
    field_relative: bool = False            # (vx, vy) fixed relative to the start heading


def _moves(m, kind: str, spin_rate: float, spin_turns: float, speed: float,
           straight_s: float) -> list[_Move]:
    if not isinstance(m, str):
        hold, vx, vy, w = (float(v) for v in m)
        if kind == "differential" and vy != 0.0:
            raise ValueError("a differential drive cannot strafe (vy must be 0)")
        return [_Move("custom", (vx, vy, w), hold)]
    if m not in MANOEUVRES:
        raise ValueError(f"unknown manoeuvre {m!r}; one of {MANOEUVRES} or (hold_s, vx, vy, ω)")
    if kind == "differential" and m in _HOLONOMIC_ONLY:
        raise ValueError(f"manoeuvre {m!r} needs a holonomic drivetrain, not differential")
    # a smoothstep ramp covers half of its time at full speed: 2 ramps = 1 RAMP_S
    if m in ("spin", "spin_cw"):
        hold = max(spin_turns * 2 * math.pi / spin_rate - RAMP_S, 0.0)
        return [_Move(m, (0.0, 0.0, spin_rate if m == "spin" else -spin_rate), hold)]
    if m == "straight":
        return [_Move(m, (speed, 0.0, 0.0), straight_s), _Move(m, (-speed, 0.0, 0.0), straight_s)]
    if m == "turn":
        hold = 2 * math.pi / 1.0 - RAMP_S
        return [_Move(m, (0.75 * speed, 0.0, 1.0), hold), _Move(m, (0.75 * speed, 0.0, -1.0), hold)]
    if m == "arcs":
        # 3 s each (ramps included), turning ARC_TURN rad: a smoothstep ramp pair covers
        # RAMP_S at full speed.
        w = ARC_TURN / (ARC_S - RAMP_S)
        return [_Move(m, (0.75 * speed, 0.0, w), ARC_S - 2 * RAMP_S),
                _Move(m, (0.75 * speed, 0.0, -w), ARC_S - 2 * RAMP_S)]
    if m == "strafe":
        return [_Move(m, (0.0, 1.5, 0.0), straight_s), _Move(m, (0.0, -1.5, 0.0), straight_s)]
    if m == "drive_spin":
        return [_Move(m, (1.5, 0.0, 1.5), 2 * 2 * math.pi / 1.5 - RAMP_S,
                      field_relative=True)]
    return [_Move(m, (0.0, 0.0, 0.0), 2.0 - 2 * RAMP_S)]                # rest: 2 s still


def _smooth(u: np.ndarray) -> np.ndarray:
    u = np.clip(u, 0.0, 1.0)
    return u * u * (3.0 - 2.0 * u)


def _cumtrapz(v: np.ndarray, dt: float) -> np.ndarray:
    out = np.zeros_like(v)
    out[1:] = np.cumsum(0.5 * (v[1:] + v[:-1]) * dt, axis=0)
    return out


def _wrap(a):
    return np.arctan2(np.sin(a), np.cos(a))


class _Motion:
    """The true motion on the 4 kHz grid: robot-relative speeds, pose."""

    def __init__(self, moves: list[_Move], duration: float | None) -> None:
        spans = []
        t = LEAD_S
        for mv in moves:
            length = 2 * RAMP_S + mv.hold
            spans.append((t, t + length))
            t += length + REST_S
        total = t - REST_S + TAIL_S if moves else LEAD_S + TAIL_S
        if duration is not None:
            total = float(duration)
        n = int(round(total * 1e6 / FINE_US)) + 1
        self.t = np.arange(n, dtype=np.int64) * FINE_US           # µs from motion start
        ts = self.t * 1e-6
        dt = FINE_US * 1e-6
        prof = []
        for (a, b), mv in zip(spans, moves):
            s = _smooth((ts - a) / RAMP_S) * _smooth((b - ts) / RAMP_S)
            s[(ts < a) | (ts > b)] = 0.0
            prof.append(s)
        self.omega = np.zeros(n)
        for s, mv in zip(prof, moves):
            self.omega += s * mv.target[2]
        self.theta = START[2] + _cumtrapz(self.omega, dt)          # true heading, unwrapped
        self.vx = np.zeros(n)
        self.vy = np.zeros(n)
        for (a, _), s, mv in zip(spans, prof, moves):
            vx, vy = mv.target[0] * s, mv.target[1] * s
            if mv.field_relative:        # fixed in the field: rotate into the robot frame
                i0 = min(int(round(a * 1e6 / FINE_US)), n - 1)
                rel = self.theta - self.theta[i0]
                c, sn = np.cos(rel), np.sin(rel)
                vx, vy = c * vx + sn * vy, -sn * vx + c * vy
            self.vx += vx
            self.vy += vy
        c, sn = np.cos(self.theta), np.sin(self.theta)
        self.x = START[0] + _cumtrapz(c * self.vx - sn * self.vy, dt)
        self.y = START[1] + _cumtrapz(sn * self.vx + c * self.vy, dt)
        self.windows = [(mv.manoeuvre, a, b) for (a, b), mv in zip(spans, moves)]
        self.duration = total

    def pose(self) -> np.ndarray:
        return np.stack([self.x, self.y, self.theta], axis=1)


@functools.lru_cache(maxsize=4)
def _motion(moves: tuple[_Move, ...], duration: float | None) -> _Motion:
    """The true motion of ``moves`` (shared by the logs of one test, which differ in
    noise and parameters only: read, never written)."""
    mo = _Motion(list(moves), duration)
    for a in (mo.t, mo.omega, mo.theta, mo.vx, mo.vy, mo.x, mo.y):
        a.setflags(write=False)
    return mo


@functools.lru_cache(maxsize=4)
def _true_wheels(moves: tuple[_Move, ...], duration: float | None, kind: str,
                 geometry) -> tuple[np.ndarray, np.ndarray | None]:
    """The true wheel travel (and swerve module angles) of ``moves`` on the fine grid."""
    mo = _motion(moves, duration)
    angle = None
    if kind == "swerve":
        travel, angle = _swerve_modules(mo, geometry)
        angle.setflags(write=False)
    elif kind == "mecanum":
        travel = _linear_travel(mo, _mecanum_matrix(geometry))
    elif kind == "differential":
        travel = _linear_travel(mo, [[1.0, 0.0, -geometry / 2], [1.0, 0.0, geometry / 2]])
    else:
        travel = _linear_travel(mo, _deadwheel_matrix(geometry))
    travel.setflags(write=False)
    return travel, angle


def _swerve_modules(mo: _Motion, modules) -> tuple[np.ndarray, np.ndarray]:
    """True travel (m, signed) and angle (rad) of each module on the fine grid."""
    dt = FINE_US * 1e-6
    travel, angle = [], []
    n = len(mo.t)
    for mx, my in modules:
        ux, uy = mo.vx - mo.omega * my, mo.vy + mo.omega * mx
        speed = np.hypot(ux, uy)
        raw = np.arctan2(uy, ux)
        moving = speed > 1e-9
        idx = np.where(moving, np.arange(n), 0)
        np.maximum.accumulate(idx, out=idx)
        held = np.where(moving[idx], raw[idx], 0.0)     # still: keep the last angle
        # optimize: the module line's direction, continuous; drive backwards rather than
        # turn more than 90°
        a = np.unwrap(2.0 * held) / 2.0
        signed = ux * np.cos(a) + uy * np.sin(a)
        travel.append(_cumtrapz(signed, dt))
        angle.append(a)
    return np.stack(travel, axis=1), np.stack(angle, axis=1)


def _linear_travel(mo: _Motion, matrix: np.ndarray) -> np.ndarray:
    v = np.asarray(matrix, dtype=float) @ np.vstack([mo.vx, mo.vy, mo.omega])
    return _cumtrapz(v.T, FINE_US * 1e-6)


def _mecanum_matrix(modules) -> np.ndarray:
    """Wheel speeds = M @ (vx, vy, ω): read off robotpy-wpimath's MecanumDriveKinematics."""
    from wpimath.geometry import Translation2d
    from wpimath.kinematics import ChassisSpeeds, MecanumDriveKinematics

    kin = MecanumDriveKinematics(*[Translation2d(float(x), float(y)) for x, y in modules])
    cols = []
    for basis in ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)):
        s = kin.toWheelSpeeds(ChassisSpeeds(*basis))
        cols.append((s.frontLeft, s.frontRight, s.rearLeft, s.rearRight))
    return np.array(cols).T


def _deadwheel_matrix(poses) -> np.ndarray:
    """Reading rates = M @ (vx, vy, ω): cos φ·(vx − y ω) + sin φ·(vy + x ω)."""
    return np.array([[math.cos(p), math.sin(p), x * math.sin(p) - y * math.cos(p)]
                     for x, y, p in poses])


def _rectangle(wheelbase: float, trackwidth: float) -> list[tuple[float, float]]:
    hl, hw = wheelbase / 2.0, trackwidth / 2.0
    return [(hl, hw), (hl, -hw), (-hl, hw), (-hl, -hw)]        # FL FR BL(RL) BR(RR)


# ---------------------------------------------------------------------------------------
# The robot's own odometry (robotpy-wpimath; numpy for dead wheels)


def _robot_odometry(kind: str, gyro: np.ndarray, P: np.ndarray, believed: dict) -> np.ndarray:
    from wpimath.geometry import Pose2d, Rotation2d, Translation2d

    start = Pose2d(START[0], START[1], Rotation2d(START[2]))
    out = np.empty((len(gyro), 3))
    if kind == "deadwheel":
        M = _deadwheel_matrix(believed["deadWheelPoses"])
        pinv = np.linalg.pinv(M[:, :2])
        x, y, th = START
        out[0] = START
        d_g = _wrap(np.diff(gyro))
        d_w = np.diff(P, axis=0)
        for k in range(1, len(gyro)):
            dth = float(d_g[k - 1])
            dx, dy = pinv @ (d_w[k - 1] - M[:, 2] * dth)
            if abs(dth) > 1e-9:
                s, c = math.sin(dth) / dth, (1 - math.cos(dth)) / dth
            else:
                s, c = 1.0 - dth * dth / 6.0, dth / 2.0
            ddx, ddy = dx * s - dy * c, dx * c + dy * s
            x += ddx * math.cos(th) - ddy * math.sin(th)
            y += ddx * math.sin(th) + ddy * math.cos(th)
            th += dth
            out[k] = (x, y, th)
        out[:, 2] = _wrap(out[:, 2])
        return out

    def row(p):
        return (p.X(), p.Y(), p.rotation().radians())

    if kind == "swerve":
        from wpimath.kinematics import (SwerveDrive4Kinematics, SwerveDrive4Odometry,
                                        SwerveModulePosition)
        kin = SwerveDrive4Kinematics(*[Translation2d(x, y) for x, y in believed["modules"]])

        def mods(i):
            return tuple(SwerveModulePosition(float(P[i, j, 0]), Rotation2d(float(P[i, j, 1])))
                         for j in range(4))
        odo = SwerveDrive4Odometry(kin, Rotation2d(float(gyro[0])), mods(0), start)
        out[0] = row(odo.getPose())
        for i in range(1, len(gyro)):
            out[i] = row(odo.update(Rotation2d(float(gyro[i])), mods(i)))
    elif kind == "mecanum":
        from wpimath.kinematics import (MecanumDriveKinematics, MecanumDriveOdometry,
                                        MecanumDriveWheelPositions)
        kin = MecanumDriveKinematics(*[Translation2d(x, y) for x, y in believed["modules"]])

        def wheels(i):
            w = MecanumDriveWheelPositions()
            w.frontLeft, w.frontRight, w.rearLeft, w.rearRight = (float(v) for v in P[i])
            return w
        odo = MecanumDriveOdometry(kin, Rotation2d(float(gyro[0])), wheels(0), start)
        out[0] = row(odo.getPose())
        for i in range(1, len(gyro)):
            out[i] = row(odo.update(Rotation2d(float(gyro[i])), wheels(i)))
    else:
        from wpimath.kinematics import DifferentialDriveOdometry
        odo = DifferentialDriveOdometry(Rotation2d(float(gyro[0])), float(P[0, 0]),
                                        float(P[0, 1]), start)
        out[0] = row(odo.getPose())
        for i in range(1, len(gyro)):
            out[i] = row(odo.update(Rotation2d(float(gyro[i])), float(P[i, 0]), float(P[i, 1])))
    return out


# ---------------------------------------------------------------------------------------
# Writing


class _Writer:
    """robotpy-wpiutil's DataLogWriter, flushed every ``FLUSH`` records (2026.2.2 blocks
    forever once about 1 MiB is buffered)."""

    FLUSH = 200

    def __init__(self, path: pathlib.Path) -> None:
        import wpiutil
        import wpiutil.wpistruct as ws

        self.ws = ws
        self.log = wpiutil.DataLogWriter(str(path))
        self.n = 0

    def struct_entry(self, name: str, cls, ts: int, array: bool = False) -> int:
        self.log.addStructSchema(cls, ts)
        type_string = "struct:" + self.ws.getTypeName(cls) + ("[]" if array else "")
        return self.log.start(name, type_string, "", ts)

    def raw_struct_entry(self, name: str, schema: tuple[str, str], ts: int) -> int:
        type_name, text = schema
        self.log.addSchema("struct:" + type_name, "structschema", text, ts)
        return self.log.start(name, "struct:" + type_name, "", ts)

    def raw(self, entry: int, data: bytes, ts: int) -> None:
        self.log.appendRaw(entry, data, ts)
        self._tick()

    def _tick(self) -> None:
        self.n += 1
        if self.n % self.FLUSH == 0:
            self.log.flush()

    def close(self) -> None:
        self.log.flush()
        self.log.stop()


def _pose2d(p):
    from wpimath.geometry import Pose2d, Rotation2d

    return Pose2d(float(p[0]), float(p[1]), Rotation2d(float(p[2])))


def _write(path: pathlib.Path, kind: str, t_us: np.ndarray, gyro: np.ndarray, P: np.ndarray,
           robot_pose: np.ndarray | None, reference: tuple[np.ndarray, np.ndarray] | None,
           believed: dict) -> dict:
    from wpimath.geometry import Pose2d, Rotation2d, Translation2d
    from wpimath.kinematics import (DifferentialDriveKinematics, MecanumDriveKinematics,
                                    SwerveModulePosition)

    w = _Writer(path)
    ts0 = int(t_us[0]) - 1000
    entries = {"positions": ENTRY_POSITIONS[kind], "gyro": ENTRY_GYRO}
    try:
        # geometry, once
        if kind == "swerve":
            w.log.addStructSchema(Translation2d, ts0)
            e = w.raw_struct_entry(ENTRY_KINEMATICS, ("SwerveDriveKinematics__4",
                                                      "Translation2d modules[4]"), ts0)
            w.raw(e, b"".join(w.ws.pack(Translation2d(x, y)) for x, y in believed["modules"]),
                  ts0)
            entries["geometry"] = ENTRY_KINEMATICS
        elif kind == "mecanum":
            e = w.struct_entry(ENTRY_KINEMATICS, MecanumDriveKinematics, ts0)
            w.raw(e, w.ws.pack(MecanumDriveKinematics(*[Translation2d(x, y)
                                                        for x, y in believed["modules"]])), ts0)
            entries["geometry"] = ENTRY_KINEMATICS
        elif kind == "differential":
            e = w.struct_entry(ENTRY_KINEMATICS, DifferentialDriveKinematics, ts0)
            w.raw(e, w.ws.pack(DifferentialDriveKinematics(believed["trackwidth"])), ts0)
            entries["geometry"] = ENTRY_KINEMATICS
        # positions
        if kind == "swerve":
            e_pos = w.struct_entry(ENTRY_POSITIONS[kind], SwerveModulePosition, ts0, array=True)

            def pack(i):
                return w.ws.packArray([SwerveModulePosition(float(P[i, j, 0]),
                                                            Rotation2d(float(P[i, j, 1])))
                                       for j in range(P.shape[1])])
        elif kind == "deadwheel":
            e_pos = w.log.start(ENTRY_POSITIONS[kind], "double[]", '{"unit":"m"}', ts0)
            pack = None
        else:
            schema = _SCHEMA_DIFF_POSITIONS if kind == "differential" else _SCHEMA_MECANUM_POSITIONS
            e_pos = w.raw_struct_entry(ENTRY_POSITIONS[kind], schema, ts0)
            fmt = "<%dd" % P.shape[1]

            def pack(i):
                return struct.pack(fmt, *P[i])
        e_gyro = w.struct_entry(ENTRY_GYRO, Rotation2d, ts0)
        e_pose = e_ref = None
        if robot_pose is not None:
            e_pose = w.struct_entry(ENTRY_POSE, Pose2d, ts0)
            entries["pose"] = ENTRY_POSE
        if reference is not None:
            e_ref = w.struct_entry(ENTRY_REFERENCE, Pose2d, ts0)
            entries["reference"] = ENTRY_REFERENCE
        ref_at = {} if reference is None else {int(t): k for k, t in enumerate(reference[0])}
        for i in range(len(t_us)):
            ts = int(t_us[i])
            if pack is None:
                w.log.appendDoubleArray(e_pos, [float(v) for v in P[i]], ts)
                w._tick()
            else:
                w.raw(e_pos, pack(i), ts)
            w.raw(e_gyro, w.ws.pack(Rotation2d(float(gyro[i]))), ts)
            if e_pose is not None:
                p = robot_pose[i]
                w.raw(e_pose, w.ws.pack(_pose2d(p)), ts)
            k = ref_at.get(ts)
            if k is not None:
                p = reference[1][k]
                w.raw(e_ref, w.ws.pack(_pose2d(p)), ts)
    finally:
        w.close()
    return entries


def _write_nt(path: pathlib.Path, kind: str, t_us: np.ndarray, gyro: np.ndarray,
              P: np.ndarray, robot_pose: np.ndarray | None,
              reference: tuple[np.ndarray, np.ndarray] | None, believed: dict) -> dict:
    """The same samples published on NetworkTables and mirrored into the log by ntcore
    (``startEntryDataLog(log, "", "NT:")``, as WPILib's DataLogManager does; NT drops a
    value equal to the last): swerve ``/Drive/ModulePositions``
    struct:SwerveModulePosition[], mecanum ``/Drive/WheelPositions`` double[4] (FL FR RL
    RR) with ``/Drive/Kinematics`` struct:MecanumDriveKinematics, differential
    ``/Drive/LeftPosition`` and ``/Drive/RightPosition`` doubles; ``/Drive/Gyro``
    struct:Rotation2d, ``/Odometry/Robot`` and ``/Vision/Pose`` struct:Pose2d. No
    dead-wheel layout. Entry names carry the ``NT:`` prefix."""
    import ntcore
    import wpiutil
    from wpimath.geometry import Pose2d, Rotation2d, Translation2d
    from wpimath.kinematics import MecanumDriveKinematics, SwerveModulePosition

    if kind == "deadwheel":
        raise ValueError("the ntcore writer has no dead-wheel layout")
    log = wpiutil.DataLogWriter(str(path))
    inst = ntcore.NetworkTableInstance.create()
    handle = inst.startEntryDataLog(log, "", "NT:")
    drive = inst.getTable("Drive")
    entries = {"gyro": "NT:" + ENTRY_GYRO}
    ts0 = int(t_us[0]) - 1000
    try:
        if kind == "swerve":
            pub = drive.getStructArrayTopic("ModulePositions", SwerveModulePosition).publish()
            entries["positions"] = "NT:/Drive/ModulePositions"

            def send(i, ts):
                pub.set([SwerveModulePosition(float(P[i, j, 0]), Rotation2d(float(P[i, j, 1])))
                         for j in range(P.shape[1])], ts)
        elif kind == "mecanum":
            kin = drive.getStructTopic("Kinematics", MecanumDriveKinematics).publish()
            kin.set(MecanumDriveKinematics(*[Translation2d(x, y)
                                             for x, y in believed["modules"]]), ts0)
            entries["geometry"] = "NT:" + ENTRY_KINEMATICS
            pub = drive.getDoubleArrayTopic("WheelPositions").publish()
            entries["positions"] = "NT:/Drive/WheelPositions"

            def send(i, ts):
                pub.set([float(v) for v in P[i]], ts)
        else:
            pub_l = drive.getDoubleTopic("LeftPosition").publish()
            pub_r = drive.getDoubleTopic("RightPosition").publish()
            entries["positions"] = "NT:/Drive/LeftPosition"

            def send(i, ts):
                pub_l.set(float(P[i, 0]), ts)
                pub_r.set(float(P[i, 1]), ts)
        pub_gyro = drive.getStructTopic("Gyro", Rotation2d).publish()
        pub_pose = pub_ref = None
        if robot_pose is not None:
            pub_pose = inst.getStructTopic(ENTRY_POSE, Pose2d).publish()
            entries["pose"] = "NT:" + ENTRY_POSE
        if reference is not None:
            pub_ref = inst.getStructTopic(ENTRY_REFERENCE, Pose2d).publish()
            entries["reference"] = "NT:" + ENTRY_REFERENCE
        ref_at = {} if reference is None else {int(t): k for k, t in enumerate(reference[0])}
        for i in range(len(t_us)):
            ts = int(t_us[i])
            send(i, ts)
            pub_gyro.set(Rotation2d(float(gyro[i])), ts)
            if pub_pose is not None:
                pub_pose.set(_pose2d(robot_pose[i]), ts)
            k = ref_at.get(ts)
            if k is not None:
                pub_ref.set(_pose2d(reference[1][k]), ts)
            if i % 100 == 99:
                log.flush()
    finally:
        inst.stopEntryDataLog(handle)
        ntcore.NetworkTableInstance.destroy(inst)
        log.flush()
        log.stop()
    return entries


# ---------------------------------------------------------------------------------------
# The generator


def _per_wheel(value, n: int, what: str) -> list[float]:
    if np.ndim(value) == 0:
        return [float(value)] * n
    v = [float(x) for x in value]
    if len(v) != n:
        raise ValueError(f"{what}: {len(v)} values for {n} wheels")
    return v


def _noise_levels(noise) -> dict[str, float]:
    if noise is None:
        return dict(NOISE)
    if isinstance(noise, dict):
        bad = set(noise) - set(NOISE)
        if bad:
            raise ValueError(f"unknown noise keys {sorted(bad)}; known: {sorted(NOISE)}")
        return {k: float(noise.get(k, v)) for k, v in NOISE.items()}
    return {k: float(noise) * v for k, v in NOISE.items()}


def write_calibration_log(
        path, kind: str, *, seed: int = 0, manoeuvres: Sequence | None = None,
        wheel_scale=None, gyro_scale: float = 1.0, steer_offsets=None,
        trackwidth: float | None = None, wheelbase: float | None = None,
        believed_trackwidth: float | None = None, dead_wheels=None, believed_dead_wheels=None,
        noise=None, reference: str = "none", reference_rate_hz: float = 20.0,
        rate_hz: int = 100, duration: float | None = None, log_pose: bool = True,
        gyro_stuck: bool = False, spin_rate: float = 1.5, spin_turns: float = 3.0,
        speed: float = 2.0, straight_s: float = 1.5, writer: str = "wpiutil") -> SimulatedLog:
    """Simulate one robot and write its log to ``path``; return a :class:`SimulatedLog`.

    * ``kind``: ``"swerve" | "differential" | "mecanum" | "deadwheel"``.
    * ``manoeuvres``: names from :data:`MANOEUVRES` or ``(hold_s, vx, vy, ω)`` tuples, in
      order (default: see the module docstring); ``spin_rate`` (rad/s), ``spin_turns``,
      ``speed`` (m/s, straight; arcs at 0.75 × it), ``straight_s`` (hold of straight and
      strafe moves) tune them. ``duration`` (s): cut the log there (or pad it with rest).
    * ``wheel_scale``: true scale(s), one number or one per module / side / dead wheel
      (default :data:`DEFAULTS`); ``gyro_scale``: the true gyro scale; ``steer_offsets``
      (swerve): 4 offsets in rad (default zeros).
    * ``trackwidth``, ``wheelbase``: swerve / mecanum rectangle (m); for differential,
      ``trackwidth`` is the true effective one and ``believed_trackwidth`` the robot's.
    * ``dead_wheels`` / ``believed_dead_wheels``: true / believed ``[(x, y, φ rad)] × 3``
      (any number ≥ 2 works; default :data:`DEFAULTS`).
    * ``noise``: None (the :data:`NOISE` std-devs), a factor on them (0: noise-free), or a
      dict overriding some of them. ``seed``: the numpy Generator's seed.
    * ``reference``: ``"none"`` or ``"pose"`` (``/Vision/Pose``: true pose + noise every
      ``1 / reference_rate_hz`` s, on sample times).
    * ``rate_hz``: the sample rate, a divisor of 4000 (50, 100, 200, 250, 500).
    * ``log_pose``: also log the robot's own (believed-parameter) odometry pose.
    * ``gyro_stuck``: the gyro logs ``GYRO0`` (plus noise) throughout (bad input).
    * ``writer``: ``"wpiutil"`` (robotpy-wpiutil's DataLogWriter, the layouts above) or
      ``"ntcore"`` (published on NetworkTables and mirrored by ntcore: see
      :func:`_write_nt`; swerve, mecanum and differential).
    """
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, not {kind!r}")
    if reference not in ("none", "pose"):
        raise ValueError("reference must be 'none' or 'pose'")
    if 4000 % rate_hz:
        raise ValueError("rate_hz must divide 4000 (50, 100, 200, 250, 500)")
    path = pathlib.Path(path)
    d = DEFAULTS[kind]
    levels = _noise_levels(noise)
    if manoeuvres is None:
        manoeuvres = (("spin", "straight", "turn") if kind == "differential"
                      else ("spin", "straight", "turn", "strafe"))
    moves = [mv for m in manoeuvres
             for mv in _moves(m, kind, spin_rate, spin_turns, speed, straight_s)]
    mo = _motion(tuple(moves), duration)

    # geometry and parameters
    truth: dict[str, Any] = {}
    believed: dict[str, Any] = {}
    if kind in ("swerve", "mecanum"):
        tw = float(trackwidth if trackwidth is not None else d["trackwidth"])
        wb = float(wheelbase if wheelbase is not None else d["wheelbase"])
        modules = _rectangle(wb, tw)
        truth["modules"] = believed["modules"] = [list(m) for m in modules]
        n_wheels = 4
    elif kind == "differential":
        tw = float(trackwidth if trackwidth is not None else d["trackwidth"])
        btw = float(believed_trackwidth if believed_trackwidth is not None
                    else d["believed_trackwidth"])
        truth["trackwidth"], believed["trackwidth"] = tw, btw
        n_wheels = 2
    else:
        true_dw = [tuple(float(v) for v in p) for p in (dead_wheels or d["dead_wheels"])]
        bel_dw = [tuple(float(v) for v in p) for p in (believed_dead_wheels
                                                        or d["believed_dead_wheels"])]
        if len(true_dw) != len(bel_dw) or len(true_dw) < 2:
            raise ValueError("dead_wheels and believed_dead_wheels: the same number (>= 2)")
        truth["deadWheelPoses"] = [list(p) for p in true_dw]
        believed["deadWheelPoses"] = [list(p) for p in bel_dw]
        n_wheels = len(true_dw)
    scales = _per_wheel(d["wheel_scale"] if wheel_scale is None else wheel_scale, n_wheels,
                        "wheel_scale")
    truth["wheelRadiusScale"], believed["wheelRadiusScale"] = scales, [1.0] * n_wheels
    truth["gyroScale"], believed["gyroScale"] = float(gyro_scale), 1.0
    if kind == "swerve":
        offs = _per_wheel(0.0 if steer_offsets is None else steer_offsets, 4, "steer_offsets")
        truth["steerOffsets"], believed["steerOffsets"] = offs, [0.0] * 4
    elif steer_offsets is not None:
        raise ValueError("steer_offsets apply to swerve only")

    # true sensor values on the fine grid
    geometry = (tuple(map(tuple, modules)) if kind in ("swerve", "mecanum") else
                tw if kind == "differential" else tuple(true_dw))
    travel, angle = _true_wheels(tuple(moves), duration, kind, geometry)

    # samples
    step = 4000 // rate_hz
    idx = np.arange(0, len(mo.t), step)
    t_us = T0_US + mo.t[idx]
    n = len(idx)
    rng = np.random.default_rng(seed)
    z_pos = rng.standard_normal((n, n_wheels))
    z_ang = rng.standard_normal((n, n_wheels))
    z_gyro = rng.standard_normal(n)
    dist = travel[idx] / np.array(scales) + levels["position"] * z_pos
    if gyro_stuck:
        gyro = GYRO0 + levels["gyro"] * z_gyro
    else:
        gyro = GYRO0 + (mo.theta[idx] - START[2]) / gyro_scale + levels["gyro"] * z_gyro
    if kind == "swerve":
        ang = _wrap(angle[idx] - np.array(offs) + levels["angle"] * z_ang)
        P = np.stack([dist, ang], axis=2)                       # (N, 4, 2)
    else:
        P = dist
    poses = mo.pose()[idx]
    ref = None
    if reference == "pose":
        every = max(int(round(rate_hz / reference_rate_hz)), 1)
        k = np.arange(0, n, every)
        z_ref = rng.standard_normal((len(k), 3))
        rp = poses[k].copy()
        rp[:, :2] += levels["reference_xy"] * z_ref[:, :2]
        rp[:, 2] = _wrap(rp[:, 2] + levels["reference_theta"] * z_ref[:, 2])
        ref = (t_us[k], rp)
    robot_pose = _robot_odometry(kind, gyro, P, believed) if log_pose else None
    if writer not in WRITERS:
        raise ValueError(f"writer must be one of {WRITERS}")
    entries = (_write if writer == "wpiutil" else _write_nt)(path, kind, t_us, gyro, P,
                                                             robot_pose, ref, believed)

    logged: dict[str, Any] = {"drivetrain": kind}
    if kind == "differential":
        logged["trackwidth"] = believed["trackwidth"]
    if writer == "ntcore" and kind == "swerve":
        logged["modules"] = [tuple(m) for m in believed["modules"]]   # no geometry entry
    if writer == "ntcore" and kind == "mecanum":
        logged["positions"] = entries["positions"]      # a double[]: named
    if kind == "deadwheel":
        logged["positions"] = ENTRY_POSITIONS[kind]
        logged["deadWheels"] = [(x, y, math.degrees(p)) for x, y, p in bel_dw]
    windows = [(name, T0_US + int(round(a * 1e6)), T0_US + int(round(b * 1e6)))
               for name, a, b in mo.windows if a * 1e6 <= mo.t[-1]]
    notes = {"seed": seed, "rate_hz": rate_hz, "start_pose": START, "gyro0": GYRO0,
             "duration_s": float(mo.t[-1]) * 1e-6, "manoeuvres": list(manoeuvres),
             "gyro_stuck": gyro_stuck,
             "reference_rate_hz": reference_rate_hz if ref is not None else None,
             "robot_pose": robot_pose, "reference": ref}
    return SimulatedLog(path, truth, logged, kind, believed, entries, t_us, poses, windows,
                        levels, notes)


def swerve_log(path, **kw) -> SimulatedLog:
    return write_calibration_log(path, "swerve", **kw)


def differential_log(path, **kw) -> SimulatedLog:
    return write_calibration_log(path, "differential", **kw)


def mecanum_log(path, **kw) -> SimulatedLog:
    return write_calibration_log(path, "mecanum", **kw)


def deadwheel_log(path, **kw) -> SimulatedLog:
    return write_calibration_log(path, "deadwheel", **kw)


# ---------------------------------------------------------------------------------------
# Checking: replay a log with corrected parameters (drivekin's odometry)


def replay_drift(sim: SimulatedLog, params: dict | str | None = None, *,
                 heading: str = "gyro") -> dict:
    """Replay ``sim``'s log with drivekin's odometry, its readings corrected by ``params``
    (keys of ``sim.truth``; ``"truth"`` for ``sim.truth``; a missing key keeps the believed
    value, so ``None`` replays what the robot believed), and compare with the true poses
    at every sample: ``{"final", "max", "rms"}`` position error (m), ``"heading_max"``
    (rad), and ``"poses"`` (N, 3). ``heading="wheels"`` (differential): heading from
    ``(right − left) / trackwidth`` instead of the gyro.

    The readings are read back from the file with :mod:`drivekin.datalog` and corrected
    with the conventions of the module docstring (distance × wheelRadiusScale, angle +
    steerOffset, gyro change × gyroScale)."""
    from drivekin import datalog
    from drivekin import (DeadWheelKinematics, DeadWheelOdometry, DifferentialDriveOdometry,
                          MecanumDriveKinematics, MecanumDriveOdometry,
                          MecanumDriveWheelPositions, Pose2d, Rotation2d,
                          SwerveDriveKinematics, SwerveDriveOdometry, Translation2d)
    from drivekin.replay import replayPoses

    p = dict(sim.believed)
    if params == "truth":
        p.update(sim.truth)
    elif params:
        unknown = set(params) - set(sim.truth)
        if unknown:
            raise KeyError(f"not parameters of a {sim.kind} log: {sorted(unknown)}")
        p.update(params)
    log = datalog.read(os.fspath(sim.path))
    t, P = log.values(sim.entries["positions"])
    tg, G = log.values(sim.entries["gyro"])
    assert np.array_equal(t, tg) and np.array_equal(t, sim.t_us)
    P = np.array(P, dtype=np.float64)
    G = np.unwrap(np.asarray(G, dtype=np.float64))
    scale = np.asarray(p["wheelRadiusScale"]) / np.asarray(sim.believed["wheelRadiusScale"])
    G = G[0] + (G - G[0]) * (p["gyroScale"] / sim.believed["gyroScale"])
    start = Pose2d(*sim.poses[0, :2], Rotation2d.fromRadians(float(sim.poses[0, 2])))
    if sim.kind == "swerve":
        P[:, :, 0] *= scale
        P[:, :, 1] += np.asarray(p["steerOffsets"]) - np.asarray(sim.believed["steerOffsets"])
        kin = SwerveDriveKinematics(*[Translation2d(x, y) for x, y in p["modules"]])
        odo = SwerveDriveOdometry(kin, Rotation2d.fromRadians(float(G[0])),
                                  np.ascontiguousarray(P[0]), start)
    elif sim.kind == "mecanum":
        P *= scale
        kin = MecanumDriveKinematics(*[Translation2d(x, y) for x, y in p["modules"]])
        odo = MecanumDriveOdometry(kin, Rotation2d.fromRadians(float(G[0])),
                                   MecanumDriveWheelPositions(*P[0].tolist()), start)
    elif sim.kind == "differential":
        P *= scale
        if heading == "wheels":
            G = (P[:, 1] - P[:, 0]) / p["trackwidth"]
        odo = DifferentialDriveOdometry(Rotation2d.fromRadians(float(G[0])), float(P[0, 0]),
                                        float(P[0, 1]), start)
    else:
        P *= scale
        kin = DeadWheelKinematics([Pose2d(x, y, Rotation2d.fromRadians(d))
                                   for x, y, d in p["deadWheelPoses"]])
        odo = DeadWheelOdometry(kin, np.ascontiguousarray(P[0]),
                                Rotation2d.fromRadians(float(G[0])), start)
    if heading != "gyro" and sim.kind != "differential":
        raise ValueError("heading='wheels' is for differential logs")
    poses = replayPoses(odo, G, P)
    err = np.hypot(poses[:, 0] - sim.poses[:, 0], poses[:, 1] - sim.poses[:, 1])
    head = np.abs(_wrap(poses[:, 2] - sim.poses[:, 2]))
    return {"final": float(err[-1]), "max": float(err.max()),
            "rms": float(np.sqrt(np.mean(err ** 2))), "heading_max": float(head.max()),
            "poses": poses}


# ---------------------------------------------------------------------------------------
# The demo's worn wheels


def demo_log(path, *, seconds: float = 30.0, via: str = "record") -> SimulatedLog:
    """The log of ``python -m drivekin --vision --seconds S --log PATH`` (swerve, wheels
    worn: the robot moves ``VisionSwerveDrive.EFFICIENCY`` = 0.95 of what its encoders
    claim; exact gyro; no steer offsets) and its truth.

    ``via="record"`` steps the demo's recording simulation in-process
    (``drivekin.app.demo.record``, what ``--log`` writes after its measured passes, which
    it checks end at the same pose); ``via="cli"`` runs the command itself (slower: it
    also runs the two measured passes). The log is written by drivekin's own
    ``datalog.Writer`` (the demo's), not robotpy-wpiutil. Entries: ``/Drive/ModulePositions``,
    ``/Drive/Gyro``, ``/Odometry/Robot`` (the robot's odometry), ``/Sim/TruePose`` (the
    truth, every sample: ``entries["reference"]``), ``/PoseEstimator/Robot``,
    ``/Drive/Kinematics`` (the modules) and module states; 50 Hz, samples at
    (k + 1)·20 ms, the robot starting at the origin. ``t_us`` / ``poses`` are read back from
    ``/Sim/TruePose``."""
    from drivekin import datalog
    from drivekin.app.demo.drivetrains import VisionSwerveDrive
    from drivekin.app.demo.script import DT

    path = pathlib.Path(path)
    steps = round(seconds / DT)
    if via == "record":
        import types

        from drivekin.app.cli import parse_args
        from drivekin.app.demo import record

        defaults = parse_args(["--vision"])
        args = types.SimpleNamespace(drivetrain="swerve", max_speed=defaults.max_speed,
                                     max_omega=defaults.max_omega, vision=True,
                                     setpoint_generator=False)
        record.write_log(os.fspath(path), record.record(args, steps))
    elif via == "cli":
        import subprocess
        import sys

        subprocess.run([sys.executable, "-m", "drivekin", "--vision", "--seconds",
                        repr(float(seconds)), "--log", os.fspath(path), "--quiet"],
                       check=True, capture_output=True)
    else:
        raise ValueError("via must be 'record' or 'cli'")
    log = datalog.read(os.fspath(path))
    t_us, poses = log.values("/Sim/TruePose")
    kin = log.values(ENTRY_KINEMATICS)[1][-1]
    modules = [[float(kin[2 * j]), float(kin[2 * j + 1])] for j in range(4)]
    e = float(VisionSwerveDrive.EFFICIENCY)
    truth = {"wheelRadiusScale": [e] * 4, "gyroScale": 1.0, "steerOffsets": [0.0] * 4,
             "modules": modules}
    believed = {"wheelRadiusScale": [1.0] * 4, "gyroScale": 1.0, "steerOffsets": [0.0] * 4,
                "modules": modules}
    entries = {"positions": "/Drive/ModulePositions", "gyro": "/Drive/Gyro",
               "pose": "/Odometry/Robot", "geometry": ENTRY_KINEMATICS,
               "reference": "/Sim/TruePose", "estimator": "/PoseEstimator/Robot"}
    notes = {"seconds": steps * DT, "rate_hz": round(1 / DT), "start_pose": (0.0, 0.0, 0.0),
             "via": via, "producer": json.dumps({"producer": "python -m drivekin"}),
             "model": "truth.exp(Twist2d(vx·DT·e, vy·DT·e, ω·DT)) of the measured chassis "
                      "velocities: the wheel distances are e times too long, the gyro exact"}
    return SimulatedLog(path, truth, {"drivetrain": "swerve"}, "swerve", believed, entries,
                        np.asarray(t_us), np.asarray(poses), [], {}, notes)
