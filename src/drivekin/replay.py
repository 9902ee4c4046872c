"""Log replay: recompute a robot's odometry from a WPILib DataLog and compare it with the
pose the robot logged (``python -m drivekin replay``; command line in ``app/replay_cli.py``).

Steps, for one ``.wpilog`` file (read with :mod:`drivekin.datalog`):

1. **Find the entries** through the layouts table of :mod:`drivekin._core.loglayouts`
   (WPILib structs, CTRE's DriveState, AdvantageKit / robotpy-pykit per-module entries
   and their high-rate odometry arrays, left/right doubles, ``double[]`` wheel arrays,
   Field2d poses), unless named (``positions=``, ``gyro=``, ``pose=``; names match
   regardless of case, underscores and the ``NT:`` prefix). Where one layout finds
   several candidates, the best-ranked is taken and the result says why
   (:attr:`ReplayResult.why`); a tie stops the replay and lists them. High-rate odometry
   samples are preferred to cycle values (``odometryRate="cycle"`` inverts that).
   Impossible units (wheels faster than ``MAX_WHEEL_SPEED``, a gyro turning faster than
   ``MAX_TURN_RATE``) are refused. Entries under ``/drivekin/`` (an earlier replay's
   output) are never picked.
2. **Geometry.** Module (or mecanum wheel) offsets from the options, else from a
   ``struct:SwerveDriveKinematics__M`` / ``struct:MecanumDriveKinematics`` entry in the
   log, or ``trackwidth`` with ``wheelbase`` for a rectangle. Dead wheels: their poses
   (x, y, rolling direction). ``wheelScale`` multiplies every wheel distance (a corrected
   wheel radius: true radius / the radius the robot used).
3. **Alignment** (the rule a robot's odometry loop follows): the odometry is updated once
   per wheel-position sample, with the **latest gyro sample at or before** that sample's
   timestamp (``gyroAlign="latest"``); ``"interpolate"`` instead interpolates the
   (unwrapped) gyro linearly between its samples, holding the last one after the end.
   Wheel samples before the first gyro sample are skipped. Gaps need no special
   handling: the update after a gap integrates the whole distance change at the module
   angles of that sample, as the robot would.
4. **Replay**: :func:`replayPoses`, one ``update`` per sample. The start pose is the
   logged pose at the first replayed sample (interpolated; the origin without a logged
   pose, or with ``start="origin"``).
5. **Compare** at the timestamps of the logged poses inside the replayed time span. The
   replayed pose there is, by default (``compare="hold"``), the one after the latest
   wheel sample at or before it: what the robot's own ``getPose()`` returned when it
   logged, so across a gap in the wheel samples the pose stays put, as the robot's did.
   ``compare="interpolate"`` interpolates the replayed path instead (x, y linear; heading
   unwrapped, linear), better for a reference sampled off the wheel-sample clock. The
   position error (m) and the wrapped heading error (rad) give final, max and RMS values.
   Reference poses that fall inside a gap in the wheel samples (an interval longer than
   ``GAP_PERIODS`` = 3 median sample periods) are not compared — there is no replayed
   pose for that time — and are counted instead; the drift a gap causes shows in every
   pose after it.

:func:`replayLog` does 1–5 and returns a :class:`ReplayResult`; :func:`writeReplayLog`
writes the original entries plus ``/drivekin/ReplayPose`` (``struct:Pose2d``) and, with a
logged pose, ``/drivekin/ReplayError`` (``double``, m) into a new ``.wpilog``;
:func:`plotReplay` draws both paths into a PNG (matplotlib, ``pip install
"drivekin[plot]"``, imported only there, with the headless Agg backend).
"""
from __future__ import annotations

import dataclasses
import json
import math
import os
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from drivekin import batch, datalog
from drivekin._core import catalog
from drivekin._core import fieldchecks as check
from drivekin._core import loglayouts as layouts
from drivekin._core.display import escape
from drivekin._core.loglayouts import REPLAY_PREFIX, Signal
from drivekin._core.listing import listing
from drivekin._core.modulelayouts import BATCH_US, batch_ends
from drivekin._core.plotting import pyplot
from drivekin._core.replayspec import ReplaySpec
from drivekin._core.replayinputs import _gyro, _named_pose, _pose, _positions
from drivekin.datalog import DataLogError, LogData
from drivekin.geometry import Pose2d, Rotation2d

__all__ = ["DriftStats", "ReplayConfig", "ReplayResult", "listing", "plotReplay",
           "replayAgain", "replayLog", "replayPoses", "report", "writeReplayLog"]

#: The drivetrains a log can be replayed for: the catalog's odometry classes that can be
#: started from a positions stack (in catalog order).
DRIVETRAINS = tuple(s.name for s in catalog.replay_specs())
GAP_PERIODS = 3.0       # a wheel-sample interval this many median periods long is a gap
POSE_ENTRY = "/drivekin/ReplayPose"
ERROR_ENTRY = "/drivekin/ReplayError"


@dataclass
class ReplayConfig:
    """What to replay and how (every field optional; see the module docstring)."""

    drivetrain: str = "auto"                      # or one of DRIVETRAINS
    positions: str | None = None                  # entry names; None: found by type
    moduleEntries: list[str] | None = None        # "NAME=DRIVE,ANGLE" per module, or one
                                                  # "DRIVE,ANGLE" with {module}
    gyro: str | None = None
    pose: str | None = None
    truth: str | None = None                      # a second pose to compare with
    gyroUnits: str | None = None                  # "rad", "deg" or "rot", for a double gyro
    driveUnits: str | None = None                 # "m", "rad" or "rot" (of the wheel)
    turnUnits: str | None = None                  # "rad", "deg" or "rot"
    wheelRadius: float | None = None              # m, for drive positions in rad or rot
    modules: list[tuple[float, float]] | None = None      # swerve / mecanum offsets, m
    wheelbase: float | None = None                # with trackwidth: modules at (±L/2, ±W/2)
    deadWheels: list[tuple[float, float, float]] | None = None  # x m, y m, direction deg
    trackwidth: float | None = None               # m: differential heading="wheels", or
                                                  # with wheelbase, a rectangle of modules
    odometryRate: str = "auto"                    # or "cycle": ignore high-rate samples
    heading: str = "gyro"                         # or "wheels" (differential only)
    wheelScale: float | list[float] = 1.0         # or one per module / wheel / side
    gyroScale: float = 1.0                        # true heading change / the gyro's
    steerOffsets: list[float] | None = None       # rad added to each swerve module angle
    gyroAlign: str = "latest"                     # or "interpolate"
    start: str = "logged"                         # or "origin"
    compare: str = "hold"                         # or "interpolate"
    ragged: str = "error"                         # or "drop"
    allowTruncated: bool = False

    def __setattr__(self, name: str, value: Any) -> None:
        # Every assignment is checked (the constructor's included): a bad value fails
        # where it is given, never as a silent default later.
        check = _CONFIG_CHECKS.get(name)
        if check is None:
            raise AttributeError(f"ReplayConfig has no option {name!r}")
        check(f"ReplayConfig.{name}", value)
        object.__setattr__(self, name, value)


# One check per ReplayConfig field (a new field needs its line here).
_CONFIG_CHECKS: dict[str, check.Check] = {
    "drivetrain": check.choice("auto", *DRIVETRAINS),
    "positions": check.entry_name,
    "moduleEntries": check.texts,
    "gyro": check.entry_name,
    "pose": check.entry_name,
    "truth": check.entry_name,
    "gyroUnits": check.choice(None, *layouts.GYRO_UNITS),
    "driveUnits": check.choice(None, *layouts.DRIVE_UNITS, *layouts.SPEED_UNITS),
    "turnUnits": check.choice(None, *layouts.TURN_UNITS),
    "wheelRadius": check.positive(optional=True),
    "modules": check.points(2),
    "wheelbase": check.positive(optional=True),
    "deadWheels": check.points(3),
    "trackwidth": check.positive(optional=True),
    "odometryRate": check.choice("auto", "cycle"),
    "heading": check.choice("gyro", "wheels"),
    "wheelScale": check.scales,
    "gyroScale": check.positive(optional=False),
    "steerOffsets": check.finite_list,
    "gyroAlign": check.choice("latest", "interpolate"),
    "start": check.choice("logged", "origin"),
    "compare": check.choice("hold", "interpolate"),
    "ragged": check.choice("error", "drop"),
    "allowTruncated": check.flag,
}


@dataclass
class DriftStats:
    """Replayed pose minus a reference pose, at ``count`` reference timestamps: position
    error (m) and heading error (rad, wrapped to [-π, π]) at the end, worst and RMS."""

    count: int
    finalPosition: float
    maxPosition: float
    rmsPosition: float
    finalHeading: float
    maxHeading: float
    rmsHeading: float
    t: np.ndarray = field(repr=False)             # reference timestamps used, µs
    error: np.ndarray = field(repr=False)         # position error at each, m
    inGaps: int = 0                               # reference poses inside wheel gaps

    def asdict(self) -> dict[str, float]:
        return {"count": self.count, "final_position_m": self.finalPosition,
                "max_position_m": self.maxPosition, "rms_position_m": self.rmsPosition,
                "final_heading_deg": math.degrees(self.finalHeading),
                "max_heading_deg": math.degrees(self.maxHeading),
                "rms_heading_deg": math.degrees(self.rmsHeading),
                "skipped_in_gaps": self.inGaps}


@dataclass
class ReplayResult:
    """Everything one replay found and computed (times in µs, poses (N, 3) [x, y, θ])."""

    source: str
    drivetrain: str
    odometry: str
    entries: dict[str, str]                       # role -> entry name
    geometry: str
    t: np.ndarray                                 # replayed sample timestamps
    poses: np.ndarray                             # replayed poses
    skipped: int                                  # wheel samples before the first gyro
    maxWheelGap: float                            # s
    maxGyroAge: float                             # s (latest rule; 0 when interpolating)
    rates: dict[str, float]                       # role -> median sample rate, Hz
    alignment: str                                # how gyro and wheel samples were paired
    logged: tuple[np.ndarray, np.ndarray] | None = None
    truth: tuple[np.ndarray, np.ndarray] | None = None
    vsLogged: DriftStats | None = None
    vsTruth: DriftStats | None = None
    truncated: str | None = None
    log: LogData | None = field(default=None, repr=False)
    why: dict[str, str] = field(default_factory=dict)      # role -> why that entry
    notes: list[str] = field(default_factory=list)         # what the replay decided
    warnings: list[str] = field(default_factory=list)      # what looks wrong
    # What the replay ran on (drivekin.calibrate replays it again with other parameters):
    positions: np.ndarray | None = field(default=None, repr=False)   # aligned wheel samples
    gyroAngles: np.ndarray | None = field(default=None, repr=False)  # rad, unwrapped, aligned
    kinematics: Any = field(default=None, repr=False)
    start: Pose2d | None = field(default=None, repr=False)

    @property
    def pathLength(self) -> float:
        d = np.diff(self.poses[:, :2], axis=0)
        return float(np.hypot(d[:, 0], d[:, 1]).sum())

    @property
    def duration(self) -> float:
        return float(self.t[-1] - self.t[0]) / 1e6 if len(self.t) else 0.0

    def asdict(self) -> dict[str, Any]:
        last = self.poses[-1]
        return {
            "source": self.source, "drivetrain": self.drivetrain, "odometry": self.odometry,
            "entries": dict(self.entries), "geometry": self.geometry,
            "samples": len(self.t), "skipped_before_gyro": self.skipped,
            "duration_s": self.duration, "path_length_m": self.pathLength,
            "max_wheel_gap_s": self.maxWheelGap, "max_gyro_age_s": self.maxGyroAge,
            "rates_hz": dict(self.rates), "alignment": self.alignment,
            "final_pose": {"x_m": float(last[0]), "y_m": float(last[1]),
                           "heading_deg": math.degrees(float(last[2]))},
            "vs_logged": self.vsLogged.asdict() if self.vsLogged else None,
            "vs_truth": self.vsTruth.asdict() if self.vsTruth else None,
            "truncated": self.truncated, "why": dict(self.why), "notes": list(self.notes),
            "warnings": list(self.warnings),
        }


# ---------------------------------------------------------------------------------------
# The per-sample odometry replay (the batch kernel of issue 9 §1 replaces this loop)

def replayPoses(odometry: Any, gyro: np.ndarray, positions: np.ndarray) -> np.ndarray:
    """Run ``odometry.update`` once per sample through :func:`drivekin.batch.replay` (the
    same bits as a loop of ``update`` calls) and return the (N, 3) poses
    ``[x m, y m, θ rad]`` (θ wrapped), leaving ``odometry`` at the last sample.

    ``gyro``: (N,) gyro angles in rad. ``positions``: (N, M, 2) ``[distance m, angle rad]``
    for SwerveDriveOdometry, (N, 4) ``[fl, fr, rl, rr]`` for MecanumDriveOdometry, (N, 2)
    ``[left, right]`` for DifferentialDriveOdometry, (N, k) wheel distances for
    DeadWheelOdometry (with a gyro)."""
    return batch.replay(odometry, np.ascontiguousarray(gyro, dtype=np.float64),
                        np.ascontiguousarray(positions, dtype=np.float64))


# ---------------------------------------------------------------------------------------
# Drift against a reference pose

def _unwrap(theta: np.ndarray) -> np.ndarray:
    return np.unwrap(theta) if len(theta) else theta


def _interp_poses(t_src: np.ndarray, poses: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Poses at times ``t``: x, y and the unwrapped heading interpolated linearly
    (clamped to the first/last pose outside ``t_src``)."""
    ts = t_src.astype(np.float64)
    tq = t.astype(np.float64)
    th = _unwrap(poses[:, 2])
    return np.stack([np.interp(tq, ts, poses[:, 0]), np.interp(tq, ts, poses[:, 1]),
                     np.interp(tq, ts, th)], axis=1)


def _wrap(a: np.ndarray) -> np.ndarray:
    return np.arctan2(np.sin(a), np.cos(a))


def _drift(t_rep: np.ndarray, rep: np.ndarray, t_ref: np.ndarray, ref: np.ndarray,
           compare: str) -> DriftStats | None:
    inside = (t_ref >= t_rep[0]) & (t_ref <= t_rep[-1])
    k = np.searchsorted(t_rep, t_ref, side="right") - 1
    dt = np.diff(t_rep)
    if len(dt):
        period = float(np.median(dt))
        kk = np.clip(k, 0, len(dt) - 1)
        in_gap = inside & (k < len(dt)) & (dt[kk] > GAP_PERIODS * period) & (t_ref > t_rep[kk])
    else:
        in_gap = np.zeros(len(t_ref), dtype=bool)
    use = inside & ~in_gap
    if not use.any():
        return None
    tr, pr = t_ref[use], ref[use]
    if compare == "interpolate":
        at = _interp_poses(t_rep, rep, tr)
    else:
        at = rep[k[use]]
    pos = np.hypot(at[:, 0] - pr[:, 0], at[:, 1] - pr[:, 1])
    head = np.abs(_wrap(at[:, 2] - pr[:, 2]))
    return DriftStats(len(tr), float(pos[-1]), float(pos.max()),
                      float(np.sqrt(np.mean(pos ** 2))), float(head[-1]),
                      float(head.max()), float(np.sqrt(np.mean(head ** 2))), tr, pos,
                      int(in_gap.sum()))


# ---------------------------------------------------------------------------------------
# Replay

def replayLog(log: LogData | str | os.PathLike[str],
              config: ReplayConfig | None = None) -> ReplayResult:
    """Replay the odometry of one log (a path or a :class:`~drivekin.datalog.LogData`);
    see the module docstring. DataLogError for logs that cannot be replayed."""
    cfg = config or ReplayConfig()
    if not isinstance(log, LogData):
        log = datalog.read(log, allowTruncated=cfg.allowTruncated)
    opts = layouts.Options(cfg.driveUnits, cfg.turnUnits, cfg.gyroUnits, cfg.wheelRadius,
                           cfg.ragged)
    entries: dict[str, str] = {}
    why: dict[str, str] = {}
    notes: list[str] = []

    # 1. positions and drivetrain
    pos, cycle, why["positions"] = _positions(log, cfg, opts)
    assert pos.drivetrain is not None
    spec = catalog.replay_spec(pos.drivetrain)
    entries["positions"] = pos.source
    tw, P = pos.t, pos.values
    if len(tw) == 0:
        raise DataLogError(f"entry {pos.source!r} has no samples")
    width = spec.width(P, pos.source)
    _check_positions(pos, spec)
    P = spec.correct(P.copy(), cfg)
    if cycle is not None:
        notes.append(f"replaying the odometry thread's {layouts.rate(tw):.0f} Hz samples, "
                     f"not the {layouts.rate(cycle.t):.0f} Hz cycle values")
    elif cfg.odometryRate == "cycle" and any(
            s.highRate for s in layouts.candidates(log, "positions", opts)):
        notes.append("the log holds high-rate odometry samples; replaying the cycle values "
                     "(--odometry-rate cycle)")

    # 2. the logged pose (and truth), which the gyro may stand in for
    logged = truth = None
    if cfg.truth is not None:
        tsig = _named_pose(log, cfg.truth, "--truth", opts)
        truth = _finite_poses(tsig, "--truth", notes)
        entries["truth"] = tsig.source
    pose_sig, why["pose"] = _pose(log, cfg, opts,
                                  {entries["truth"]} if "truth" in entries else set())
    if pose_sig is not None and len(pose_sig.t):
        logged = _finite_poses(pose_sig, "pose", notes)
        entries["pose"] = pose_sig.source

    # 3. gyro
    if cfg.heading == "wheels":
        tg = tw
        G = spec.wheel_heading(P, cfg)
        entries["gyro"] = "(wheels)"
    else:
        gyro_sig, why["gyro"] = _gyro(log, cfg, opts, pos, pose_sig)
        entries["gyro"] = gyro_sig.source
        tg, G = gyro_sig.t, gyro_sig.values
        if len(tg) == 0:
            raise DataLogError(f"gyro entry {gyro_sig.source!r} has no samples")
        if not np.isfinite(G).all():
            raise DataLogError(f"gyro entry {gyro_sig.source!r} holds a NaN or infinite "
                               f"value")
        if len(tg) > 1 and (np.diff(tg) < 0).any():
            order = np.argsort(tg, kind="stable")
            tg, G = tg[order], G[order]
        _check_gyro(gyro_sig.source, tg, G, gyro_sig.units)
        G = _unwrap(G) * cfg.gyroScale
    if pos.batched:
        # NetworkTables' mirror: one robot cycle's values arrive as one batch of records
        # a few µs to ms apart, in any order; each is taken at its batch's end
        snap = batch_ends(np.concatenate([tw, tg] + [r[0] for r in (logged, truth) if r]))
        tw, tg = snap(tw), snap(tg)
        logged = (snap(logged[0]), logged[1]) if logged else None
        truth = (snap(truth[0]), truth[1]) if truth else None
        notes.append(f"records under {BATCH_US / 1e3:g} ms apart (one NetworkTables "
                     f"update) are taken as one sample")

    # alignment
    tw, P, gyro, skipped, max_age, alignment = _align(tw, P, tg, G, cfg, pos.source)
    max_gap = float(np.diff(tw).max()) / 1e6 if len(tw) > 1 else 0.0

    # 4. replay
    kin, geometry = spec.geometry(log, width, cfg, pos)
    geometry += corrections_text(cfg)
    start = Pose2d()
    if cfg.start == "logged" and logged is not None:
        tw, P, gyro, start, before = _start_at_logged(tw, P, gyro, logged)
        if before:
            notes.append(f"started at the first logged pose ({logged[0][0] / 1e6:.3f} s), "
                         f"from the wheel sample at or before it; {before} earlier wheel "
                         f"samples not replayed")
    if pos.integrated:
        notes.append("wheel distances integrated from velocity states (trapezoidal "
                     "between records, held across gaps): the error grows with time")
    poses = _run(spec, kin, gyro, P, start)

    rates = {"positions": layouts.rate(tw)}
    if entries["gyro"] != "(wheels)":
        rates["gyro"] = layouts.rate(tg)
    result = ReplayResult(log.source, spec.name, spec.odometry, entries, geometry, tw, poses,
                          skipped, max_gap, max_age, rates, alignment, logged, truth,
                          truncated=log.truncated, log=log, why=why, notes=notes,
                          positions=P, gyroAngles=gyro, kinematics=kin, start=start)
    # 5. compare
    if logged is not None:
        rates["pose"] = layouts.rate(logged[0])
        result.vsLogged = _drift(tw, poses, logged[0], logged[1], cfg.compare)
    if truth is not None and len(truth[0]):
        result.vsTruth = _drift(tw, poses, truth[0], truth[1], cfg.compare)
    if cycle is not None and result.vsLogged is not None:
        result.warnings += _rate_check(log, cfg, result)
    return result


def _finite_poses(sig: Signal, role: str, notes: list[str]) -> tuple[np.ndarray, np.ndarray]:
    """A reference pose's samples without the non-finite ones (a robot may log NaN
    before its estimator has a fix), counted in a note; DataLogError when none is
    finite. The start pose and every comparison then use finite poses only."""
    finite = np.isfinite(sig.values).all(axis=1)
    bad = int((~finite).sum())
    if not bad:
        return sig.t, sig.values
    if bad == len(finite):
        raise DataLogError(f"{role} entry {sig.source!r} holds no finite pose: all {bad} "
                           f"are NaN or infinite")
    notes.append(f"{bad} of the {len(finite)} poses of {role} entry {sig.source!r} are "
                 f"NaN or infinite: skipped")
    return sig.t[finite], sig.values[finite]


def corrections_text(cfg: ReplayConfig) -> str:
    """The geometry description's note of the corrections applied ('' for none)."""
    text = ""
    scale = np.atleast_1d(np.asarray(cfg.wheelScale, dtype=np.float64))
    if (scale != 1.0).any():
        text += "; wheel distances × " + ", ".join(f"{k:g}" for k in scale)
    if cfg.gyroScale != 1.0:
        text += f"; gyro × {cfg.gyroScale:g}"
    if cfg.steerOffsets is not None:
        text += "; steer offsets " + ", ".join(f"{math.degrees(a):+.2f}°"
                                               for a in cfg.steerOffsets)
    return text


def _align(tw: np.ndarray, P: np.ndarray, tg: np.ndarray, G: np.ndarray, cfg: ReplayConfig,
           source: str) -> tuple[np.ndarray, np.ndarray, np.ndarray, int, float, str]:
    """Pair each wheel sample with a gyro angle (the module docstring's step 3)."""
    idx = np.searchsorted(tg, tw, side="right") - 1
    valid = idx >= 0
    skipped = int((~valid).sum())
    if skipped == len(tw):
        raise DataLogError(f"every wheel sample of {source!r} comes before the first "
                           f"gyro sample ({tg[0] / 1e6:.3f} s)")
    tw, P, idx = tw[valid], P[valid], idx[valid]
    if cfg.heading == "wheels":
        gyro = G[idx]
        max_age = 0.0
        alignment = "heading from the wheels: (right - left) / trackwidth"
    elif cfg.gyroAlign == "interpolate":
        gyro = np.interp(tw.astype(np.float64), tg.astype(np.float64), G)
        max_age = 0.0
        alignment = "gyro interpolated (unwrapped, linear) at each wheel sample"
    else:
        gyro = G[idx]
        max_age = float((tw - tg[idx]).max()) / 1e6
        alignment = (f"latest gyro sample at or before each wheel sample (max age "
                     f"{max_age * 1e3:.1f} ms)")
    alignment += ("; compared at the reference times: latest replayed pose" if
                  cfg.compare == "hold" else "; compared with the replay interpolated")
    return tw, P, gyro, skipped, max_age, alignment


def _start_at_logged(tw: np.ndarray, P: np.ndarray, gyro: np.ndarray,
                     logged: tuple[np.ndarray, np.ndarray]
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray, Pose2d, int]:
    """Start where the robot's own odometry was when it logged its first pose: at the
    latest wheel sample at or before that pose's timestamp, from that pose (a robot
    already moving then would otherwise start from the right pose at the wrong
    instant). Without a wheel sample before it, the first sample starts from the latest
    logged pose at or before it (held: a writer that logs changes only leaves a robot at
    rest unlogged). Also returns how many samples were dropped."""
    k = int(np.searchsorted(tw, logged[0][0], side="right")) - 1
    j = 0 if k >= 0 else int(np.searchsorted(logged[0], tw[0], side="right")) - 1
    x, y, th = logged[1][j]
    start = Pose2d(float(x), float(y), Rotation2d.fromRadians(float(th)))
    if k < 0:
        return tw, P, gyro, start, 0
    return tw[k:], P[k:], gyro[k:], start, k


def _run(spec: ReplaySpec, kin: Any, gyro: np.ndarray, P: np.ndarray, start: Pose2d
         ) -> np.ndarray:
    odo = spec.start(kin, Rotation2d.fromRadians(float(gyro[0])), P[0], start)
    return replayPoses(odo, gyro, P)


def _rate_check(log: LogData, cfg: ReplayConfig, result: ReplayResult) -> list[str]:
    """Replay the cycle values too; warn when the logged pose follows them, not the
    high-rate samples (a robot whose odometry ran at the loop rate after all)."""
    mine = result.vsLogged
    assert mine is not None
    if mine.rmsPosition <= 1e-3:
        return []
    try:
        other = replayLog(log, dataclasses.replace(cfg, odometryRate="cycle"))
    except DataLogError:
        return []
    if other.vsLogged is None or other.vsLogged.rmsPosition >= 0.2 * mine.rmsPosition:
        return []
    return [f"the logged pose follows the {other.rates['positions']:.0f} Hz cycle values "
            f"(RMS {_cm(other.vsLogged.rmsPosition)}) far better than the "
            f"{result.rates['positions']:.0f} Hz samples replayed (RMS "
            f"{_cm(mine.rmsPosition)}): it was evidently produced at the cycle rate; "
            f"--odometry-rate cycle replays that"]


# The fastest a wheel rolls or a robot turns that the sanity checks believe.
MAX_WHEEL_SPEED = 30.0      # m/s
MAX_TURN_RATE = 60.0        # rad/s (about 10 turns a second)
# A gyro step (read as rad) beyond this is no robot's turn in degrees either.
MAX_DEGREE_STEP = math.degrees(MAX_TURN_RATE * 0.1)


def _steps(t: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per-sample changes and intervals (s) between samples under 0.1 s apart."""
    dt = np.diff(t) / 1e6
    d = np.diff(v, axis=0)
    near = (dt > 0) & (dt < 0.1)
    return d[near], dt[near]


def _check_positions(pos: Signal, spec: ReplaySpec) -> None:
    """Refuse wheel distances that move impossibly fast: wrong units."""
    P = pos.values
    if not np.isfinite(P).all():
        bad = int(np.argmax(~np.isfinite(P.reshape(len(P), -1)).all(axis=1)))
        raise DataLogError(f"{pos.source!r} holds a NaN or infinite value (sample {bad} at "
                           f"{pos.t[bad] / 1e6:.3f} s)")
    d, dt = _steps(pos.t, spec.distances(P))
    if not len(dt):
        return
    speed = np.abs(d).max(axis=1) / dt
    if (speed > MAX_WHEEL_SPEED).mean() > 0.01:
        raise DataLogError(
            f"{pos.source!r}: wheel distances ({pos.units}) change by up to "
            f"{float(np.abs(d).max()):.3g} m between samples ({float(speed.max()):.3g} m/s), "
            f"faster than any robot: check the units (--drive-units, --wheel-radius)")


def _check_gyro(source: str, t: np.ndarray, G: np.ndarray, units: str) -> None:
    """Refuse a gyro that turns impossibly fast between samples, as wheel distances are
    refused: degrees read as radians, or corrupt samples. A step of about one turn is a
    wrap (a gyro reading in [-180°, 180°)), not a turn; one of more than 1.5 turns never
    is (wrapping it would hide a jump of 1e9 rad, which wraps to 0.58)."""
    d, dt = _steps(t, G)
    if not len(dt):
        return
    step = np.abs(d)
    step = np.where(step <= 3.0 * math.pi, np.abs(_wrap(d)), step)
    if ((step / dt > MAX_TURN_RATE) & (step > math.pi / 4)).mean() > 0.01:
        worst = float(step.max())
        raise DataLogError(
            f"gyro entry {source!r} ({units}) turns by up to {worst:.3g} rad between "
            f"samples: in those units that is faster than any robot turns; " +
            ("it is probably in degrees (--gyro-units deg)" if worst < MAX_DEGREE_STEP else
             "its samples are corrupt or in the wrong units (--gyro-units)"))


# ---------------------------------------------------------------------------------------
# Outputs

def writeReplayLog(result: ReplayResult, path: str | os.PathLike[str]) -> None:
    """Write ``result``'s source log (every entry except earlier ``/drivekin/`` ones) plus
    ``/drivekin/ReplayPose`` and, with a logged pose, ``/drivekin/ReplayError`` to
    ``path``."""
    if result.log is None:
        raise ValueError("the result holds no log to copy (replayed from a LogData?)")
    if os.path.exists(result.source) and os.path.exists(path) and \
            os.path.samefile(result.source, path):
        raise ValueError(f"refusing to overwrite the input log {result.source}")
    skip = [n for n in result.log.entries if n.startswith(REPLAY_PREFIX)]
    with datalog.Writer(path) as w:
        w.copyFrom(result.log, exclude=skip)
        w.appendSeries(POSE_ENTRY, "struct:Pose2d", result.t, result.poses,
                       metadata='{"source":"drivekin replay"}')
        if result.vsLogged is not None:
            w.appendSeries(ERROR_ENTRY, "double", result.vsLogged.t, result.vsLogged.error,
                           metadata=json.dumps({"unit": "m", "against": result.entries["pose"]}))


def plotReplay(result: ReplayResult, path: str | os.PathLike[str]) -> None:
    """Draw the replayed path, the logged one (and the truth) and the position errors
    over time into a PNG at ``path`` (matplotlib, Agg backend)."""
    plt = pyplot()
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(12, 5.2),
                                  gridspec_kw={"width_ratios": [1.15, 1]})
    try:
        if result.truth is not None:
            ax.plot(result.truth[1][:, 0], result.truth[1][:, 1], color="0.55", lw=3.0,
                    alpha=0.6, label=f"truth ({result.entries['truth']})")
        if result.logged is not None:
            ax.plot(result.logged[1][:, 0], result.logged[1][:, 1], color="tab:red",
                    lw=1.4, ls="--", label=f"logged ({result.entries['pose']})")
        ax.plot(result.poses[:, 0], result.poses[:, 1], color="tab:blue", lw=1.2,
                label="replayed (drivekin)")
        ax.plot(result.poses[:1, 0], result.poses[:1, 1], "o", color="k", ms=5,
                label="start")
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
        ax.set_title(f"{os.path.basename(result.source)}: {result.drivetrain}, "
                     f"{len(result.t)} samples", fontsize=10)
        t0 = result.t[0]
        drew = False
        for stats, label, color in ((result.vsLogged, "replayed − logged", "tab:red"),
                                    (result.vsTruth, "replayed − truth", "0.4")):
            if stats is not None:
                ax2.plot((stats.t - t0) / 1e6, stats.error * 100.0, color=color,
                         label=f"{label}: final {stats.finalPosition * 100:.1f} cm, "
                               f"max {stats.maxPosition * 100:.1f} cm")
                drew = True
        ax2.set_xlabel("time since the first replayed sample (s)")
        ax2.set_ylabel("position error (cm)")
        ax2.grid(True, alpha=0.3)
        if drew:
            ax2.legend(loc="upper left", fontsize=8)
        else:
            ax2.text(0.5, 0.5, "no logged pose to compare with", ha="center",
                     transform=ax2.transAxes)
        ax2.set_title(result.geometry if len(result.geometry) < 70
                      else result.geometry[:67] + "...", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.fspath(path), dpi=100, format="png")
    finally:
        plt.close(fig)


def _cm(x: float) -> str:
    # Every position error in the report in one unit (cm), however small or large.
    cm = x * 100.0
    return f"{cm:.1e} cm" if cm < 0.01 else f"{cm:.2f} cm"


def _deg(a: float) -> str:
    d = math.degrees(a)
    return f"{d:.1e}°" if d < 1e-3 else f"{d:.3f}°"


def _drift_line(s: DriftStats) -> str:
    return (f"position final {_cm(s.finalPosition)}, max {_cm(s.maxPosition)}, RMS "
            f"{_cm(s.rmsPosition)}; heading final {_deg(s.finalHeading)}, max "
            f"{_deg(s.maxHeading)}, RMS {_deg(s.rmsHeading)} ({s.count} poses"
            + (f"; {s.inGaps} inside wheel-sample gaps not compared" if s.inGaps else "")
            + ")")


def report(result: ReplayResult, outputs: tuple[str, ...] = ()) -> str:
    """The text report of one replay (what ``python -m drivekin replay`` prints)."""
    r = result
    e = r.entries

    def entry(role: str) -> str:
        rate = r.rates.get(role)
        return f"{e[role]}" + (f" ({rate:.0f} Hz)" if rate else "")

    align = r.alignment
    last = r.poses[-1]
    def because(role: str) -> str:
        return f" [{r.why[role]}]" if r.why.get(role) else ""

    rows = [
        f"{r.source}: {r.drivetrain} ({r.odometry})",
        f"  positions  {entry('positions')}{because('positions')}",
        f"  gyro       {entry('gyro') if 'gyro' in r.rates else e['gyro']}{because('gyro')}",
        "  pose       " + (f"{entry('pose')}{because('pose')}" if 'pose' in e else
                            f"(none: nothing to compare with; {r.why.get('pose', '')})"),
        f"  geometry   {r.geometry}",
        f"  alignment  {align}; largest wheel-sample gap {r.maxWheelGap * 1e3:.1f} ms"
        + (f"; {r.skipped} wheel samples before the first gyro sample skipped"
           if r.skipped else ""),
        f"  replayed   {len(r.t)} samples over {r.duration:.2f} s, path {r.pathLength:.2f} m, "
        f"final pose x {last[0]:.3f} m, y {last[1]:.3f} m, heading "
        f"{math.degrees(last[2]):.2f}°",
    ]
    if r.vsLogged is not None:
        rows.append(f"  vs logged  {_drift_line(r.vsLogged)}")
    if r.vsTruth is not None:
        rows.append(f"  vs truth   {_drift_line(r.vsTruth)} [{e['truth']}]")
    rows += [f"  note       {n}" for n in r.notes]
    rows += [f"  warning    {w}" for w in r.warnings]
    if r.truncated:
        rows.append(f"  warning    {r.truncated}; the complete records were used")
    if outputs:
        rows.append(f"  wrote      {', '.join(outputs)}")
    # Entry names and paths are the log's and the user's bytes: escaped row by row, so
    # one with a newline or terminal controls stays on its row and prints harmlessly.
    return "\n".join(escape(row) for row in rows)


# ---------------------------------------------------------------------------------------
# Replaying a result again with corrected samples (drivekin.calibrate's one public hook)

def replayAgain(result: ReplayResult, positions: np.ndarray, gyroAngles: np.ndarray,
                compare: str | None = "hold", kinematics: Any = None) -> ReplayResult:
    """``result`` replayed again, without reading its log, from its start pose on other
    (corrected) wheel samples and gyro angles, of the shapes of ``result.positions`` and
    ``result.gyroAngles`` (rad, unwrapped), with ``kinematics`` (default: the result's
    geometry), and compared with its logged pose and truth as :func:`replayLog` compares
    (``compare``: "hold" or "interpolate"; None: not compared). A new
    :class:`ReplayResult`; ``result`` is unchanged."""
    P = np.ascontiguousarray(positions, dtype=np.float64)
    g = np.ascontiguousarray(gyroAngles, dtype=np.float64)
    if result.positions is None or P.shape != result.positions.shape or \
            g.shape != result.t.shape:
        raise ValueError("positions and gyroAngles must have the shapes of the result's")
    kin = result.kinematics if kinematics is None else kinematics
    poses = _run(catalog.replay_spec(result.drivetrain), kin, g, P,
                 result.start or Pose2d())
    out = dataclasses.replace(result, poses=poses, positions=P, gyroAngles=g,
                              kinematics=kin, vsLogged=None, vsTruth=None)
    if compare is not None and result.logged is not None:
        out.vsLogged = _drift(result.t, poses, result.logged[0], result.logged[1], compare)
    if compare is not None and result.truth is not None and len(result.truth[0]):
        out.vsTruth = _drift(result.t, poses, result.truth[0], result.truth[1], compare)
    return out
