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
import math
import os
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from drivekin import batch, datalog
from drivekin._core import catalog
from drivekin._core import loglayouts as layouts
from drivekin._core.loglayouts import REPLAY_PREFIX, Signal
from drivekin._core.plotting import pyplot
from drivekin._core.replayinputs import _gyro, _named_pose, _pose, _positions
from drivekin.datalog import DataLogError, LogData
from drivekin.deadwheel import DeadWheelKinematics
from drivekin.geometry import Pose2d, Rotation2d

__all__ = ["DriftStats", "ReplayConfig", "ReplayResult", "listing", "plotReplay",
           "replayLog", "replayPoses", "report", "writeReplayLog"]

#: The drivetrains a log can be replayed for: the catalog's odometry classes that can be
#: started from a positions stack (in catalog order).
DRIVETRAINS = tuple(e.drivetrain for e in catalog.entries("odometry") if e.start is not None)
GAP_PERIODS = 3.0       # a wheel-sample interval this many median periods long is a gap
POSE_ENTRY = "/drivekin/ReplayPose"
ERROR_ENTRY = "/drivekin/ReplayError"

# Each drivetrain's odometry: the catalog's.
_ODOMETRY = {e.drivetrain: e.cls.__name__ for e in catalog.entries("odometry")
             if e.drivetrain in DRIVETRAINS}


@dataclass
class ReplayConfig:
    """What to replay and how (every field optional; see the module docstring)."""

    drivetrain: str = "auto"                      # or one of DRIVETRAINS
    positions: str | None = None                  # entry names; None: found by type
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

def _kinematics_entry(kind: str) -> catalog.Entry:
    return catalog.entries("kinematics", drivetrain=kind)[0]


def _odometry_entry(kind: str) -> catalog.Entry:
    return catalog.entries("odometry", drivetrain=kind)[0]


def _geometry(log: LogData, kind: str, width: int, cfg: ReplayConfig) -> tuple[Any, str]:
    """The kinematics object (or None) and a description of the geometry used."""
    kin: Any
    if kind in ("swerve", "mecanum"):
        count = width if kind == "swerve" else 4
        what = ("module" if kind == "swerve" else "wheel")
        struct = (f"struct:SwerveDriveKinematics__{width}" if kind == "swerve"
                  else "struct:MecanumDriveKinematics")
        mods = cfg.modules
        src = "from the options"
        if mods is None and cfg.wheelbase is not None and cfg.trackwidth is not None:
            hl, hw = cfg.wheelbase / 2.0, cfg.trackwidth / 2.0
            mods = [(hl, hw), (hl, -hw), (-hl, hw), (-hl, -hw)]
            src = (f"--wheelbase {cfg.wheelbase:g} --trackwidth {cfg.trackwidth:g}: FL, FR, "
                   f"{'BL, BR' if kind == 'swerve' else 'RL, RR'}")
        if mods is None:
            names = [e.name for e in log.entries.values() if e.type == struct and e.records
                     and not e.name.startswith(REPLAY_PREFIX)]
            if len(names) > 1:
                raise DataLogError(f"several {struct} entries: {', '.join(names)}; give "
                                   f"the offsets with --module or --trackwidth/--wheelbase")
            if not names:
                raise DataLogError(
                    f"no {what} offsets in the log: give --trackwidth W --wheelbase L for a "
                    f"rectangle, or --module X,Y for each of the {count} {what}s (in the "
                    f"log's order{', FL, FR, RL, RR' if kind == 'mecanum' else ''})")
            v = log.values(names[0])[1][-1]
            mods = [(float(v[2 * j]), float(v[2 * j + 1])) for j in range(count)]
            src = f"from {names[0]}"
        if len(mods) != count:
            raise DataLogError(f"{len(mods)} {what} offsets given, the log's positions have "
                               f"{count} {what}s")
        kin = _kinematics_entry(kind).build(*[c for xy in mods for c in xy])  # type: ignore[misc]
        text = ", ".join(f"({x:g}, {y:g})" for x, y in mods)
        return kin, f"{count} {what}s at {text} m ({src})"
    if kind == "deadwheel":
        wheels = cfg.deadWheels
        if not wheels:
            raise DataLogError("dead wheels need their poses: --dead-wheel X,Y,DEG for "
                               "each wheel, in the order of the positions array")
        if len(wheels) != width:
            raise DataLogError(f"{len(wheels)} dead wheels given, the positions entry has "
                               f"{width} values per sample")
        kin = DeadWheelKinematics([Pose2d(x, y, Rotation2d.fromDegrees(d))
                                   for x, y, d in wheels])
        text = ", ".join(f"({x:g}, {y:g}, {d:g}°)" for x, y, d in wheels)
        return kin, f"{width} dead wheels at {text}"
    if cfg.heading == "wheels":
        return None, f"trackwidth {cfg.trackwidth:g} m (heading from the wheels)"
    return None, "no geometry needed (heading from the gyro)"


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
    kind = pos.drivetrain
    assert kind is not None
    entries["positions"] = pos.source
    tw, P = pos.t, pos.values
    if len(tw) == 0:
        raise DataLogError(f"entry {pos.source!r} has no samples")
    if kind == "differential" and P.ndim == 2 and P.shape[1] != 2:
        raise DataLogError(f"differential positions must be [left, right], {pos.source!r} "
                           f"has {P.shape[1]} values per sample")
    width = P.shape[1] if P.ndim >= 2 else 1
    if kind == "swerve" and width < 2:
        raise DataLogError(f"{pos.source!r} has {width} module(s) per sample; a swerve "
                           f"drive has at least 2")
    _check_positions(pos, kind)
    P = _corrected(P.copy(), kind, cfg)
    if cycle is not None:
        notes.append(f"replaying the odometry thread's {layouts.rate(tw):.0f} Hz samples, "
                     f"not the {layouts.rate(cycle.t):.0f} Hz cycle values")
    elif cfg.odometryRate == "cycle" and any(
            s.highRate for s in layouts.candidates(log, "positions", opts)):
        notes.append("the log holds high-rate odometry samples; replaying the cycle values "
                     "(--odometry-rate cycle)")

    # 2. gyro
    if cfg.heading == "wheels":
        if kind != "differential":
            raise DataLogError("heading from the wheels is supported for differential "
                               "drives only")
        if not cfg.trackwidth:
            raise DataLogError("heading from the wheels needs --trackwidth")
        tg = tw
        G = (P[:, 1] - P[:, 0]) / cfg.trackwidth
        entries["gyro"] = "(wheels)"
    else:
        gyro_sig, why["gyro"] = _gyro(log, cfg, opts, pos, _pose(log, cfg, opts, set())[0])
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

    # 3. alignment
    tw, P, gyro, skipped, max_age, alignment = _align(tw, P, tg, G, cfg, pos.source)
    max_gap = float(np.diff(tw).max()) / 1e6 if len(tw) > 1 else 0.0

    # logged pose and truth
    logged = truth = None
    if cfg.truth is not None:
        tsig = _named_pose(log, cfg.truth, "--truth", opts)
        truth = (tsig.t, tsig.values)
        entries["truth"] = tsig.source
    pose_sig, why["pose"] = _pose(log, cfg, opts,
                                  {entries["truth"]} if "truth" in entries else set())
    if pose_sig is not None and len(pose_sig.t):
        logged = (pose_sig.t, pose_sig.values)
        entries["pose"] = pose_sig.source

    # 4. replay
    kin, geometry = _geometry(log, kind, width, cfg)
    geometry += corrections_text(cfg)
    start = Pose2d()
    if cfg.start == "logged" and logged is not None:
        x, y, th = _interp_poses(logged[0], logged[1], tw[:1])[0]
        start = Pose2d(float(x), float(y), Rotation2d.fromRadians(float(th)))
    poses = _run(kind, kin, gyro, P, start)

    rates = {"positions": layouts.rate(tw)}
    if entries["gyro"] != "(wheels)":
        rates["gyro"] = layouts.rate(tg)
    result = ReplayResult(log.source, kind, _ODOMETRY[kind], entries, geometry, tw, poses,
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


def _corrected(P: np.ndarray, kind: str, cfg: ReplayConfig) -> np.ndarray:
    """Apply wheelScale (one number, or one per module, wheel or side) and steerOffsets
    (rad, swerve) to the positions, in place."""
    width = P.shape[1] if P.ndim >= 2 else 1
    scale = np.asarray(cfg.wheelScale, dtype=np.float64)
    if scale.ndim == 1 and scale.shape[0] != width:
        raise DataLogError(f"{scale.shape[0]} wheel scales given, the positions have {width} "
                           f"{'modules' if kind == 'swerve' else 'wheels'} per sample")
    if not (np.isfinite(scale).all() and (scale > 0).all()):
        raise DataLogError("wheel scales must be positive and finite")
    if kind == "swerve":
        P[:, :, 0] *= scale
        if cfg.steerOffsets is not None:
            if len(cfg.steerOffsets) != width:
                raise DataLogError(f"{len(cfg.steerOffsets)} steer offsets given, the "
                                   f"positions have {width} modules per sample")
            P[:, :, 1] += np.asarray(cfg.steerOffsets, dtype=np.float64)
    else:
        if cfg.steerOffsets is not None:
            raise DataLogError("steer offsets apply to swerve modules only")
        P *= scale
    return P


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


def _run(kind: str, kin: Any, gyro: np.ndarray, P: np.ndarray, start: Pose2d) -> np.ndarray:
    g0 = Rotation2d.fromRadians(float(gyro[0]))
    odo = _odometry_entry(kind).start(kin, g0, P[0], start)  # type: ignore[misc]
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


def _steps(t: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per-sample changes and intervals (s) between samples under 0.1 s apart."""
    dt = np.diff(t) / 1e6
    d = np.diff(v, axis=0)
    near = (dt > 0) & (dt < 0.1)
    return d[near], dt[near]


def _check_positions(pos: Signal, kind: str) -> None:
    """Refuse wheel distances that move impossibly fast: wrong units."""
    P = pos.values
    if not np.isfinite(P).all():
        bad = int(np.argmax(~np.isfinite(P.reshape(len(P), -1)).all(axis=1)))
        raise DataLogError(f"{pos.source!r} holds a NaN or infinite value (sample {bad} at "
                           f"{pos.t[bad] / 1e6:.3f} s)")
    dist = P[:, :, 0] if kind == "swerve" else P
    d, dt = _steps(pos.t, dist.reshape(len(dist), -1))
    if not len(dt):
        return
    speed = np.abs(d).max(axis=1) / dt
    if (speed > MAX_WHEEL_SPEED).mean() > 0.01:
        raise DataLogError(
            f"{pos.source!r}: wheel distances ({pos.units}) change by up to "
            f"{float(np.abs(d).max()):.3g} m between samples ({float(speed.max()):.3g} m/s), "
            f"faster than any robot: check the units (--drive-units, --wheel-radius)")


def _check_gyro(source: str, t: np.ndarray, G: np.ndarray, units: str) -> None:
    """Refuse a gyro that turns impossibly fast between samples: degrees read as
    radians (a wrap of a full turn is not a step)."""
    d, dt = _steps(t, G)
    if not len(dt):
        return
    step = np.abs(_wrap(d))
    if ((step / dt > MAX_TURN_RATE) & (step > math.pi / 4)).mean() > 0.01:
        raise DataLogError(
            f"gyro entry {source!r} ({units}) turns by up to {float(step.max()):.3g} rad "
            f"between samples: in those units that is faster than any robot turns; it is "
            f"probably in degrees (--gyro-units deg)")


# ---------------------------------------------------------------------------------------
# Listing

def listing(log: LogData, config: ReplayConfig | None = None) -> str:
    """Every entry of a log with its type, record count and median rate, and what
    :func:`replayLog` would use it for (``python -m drivekin replay LOG --list``)."""
    cfg = config or ReplayConfig()
    opts = layouts.Options(cfg.driveUnits, cfg.turnUnits, cfg.gyroUnits, cfg.wheelRadius,
                           cfg.ragged)
    use: dict[str, list[str]] = {}
    chosen: dict[str, str] = {}
    problems = []

    def mark(signals: list[Signal], role: str) -> None:
        for s in signals:
            what = f"{role} candidate: {s.layout}" + (f", {s.drivetrain}" if s.drivetrain
                                                     else "")
            for n in s.entries:
                use.setdefault(n, []).append(what)

    for role in ("positions", "gyro", "pose"):
        found: list[DataLogError] = []
        mark(layouts.candidates(log, role, opts, found), role)
        problems += [f"{role}: {e}" for e in found]
    try:
        pos, _, _ = _positions(log, cfg, opts)
        chosen.update(dict.fromkeys(pos.entries, "positions"))
        if cfg.heading != "wheels":
            g, _ = _gyro(log, cfg, opts, pos, _pose(log, cfg, opts, set())[0])
            chosen.update(dict.fromkeys(g.entries, "gyro"))
    except DataLogError as e:
        problems.append(str(e))
    try:
        p, _ = _pose(log, cfg, opts, set())
        if p is not None:
            chosen.update(dict.fromkeys(p.entries, "pose"))
    except DataLogError as e:
        problems.append(str(e))
    infos = [e for e in log.entries.values() if not layouts.is_schema(e.name)]
    width = min(max((len(e.name) for e in infos), default=4), 60)
    rows = [f"{log.source}: {len(infos)} entries (schemas not listed)",
            f"  {'entry':<{width}}  {'type':<30} {'records':>8} {'rate':>8}  replay uses it as"]
    for e in infos:
        t = log._entries[e.name].ts
        rate = layouts.rate(np.sort(t)) if len(t) > 1 else 0.0
        role = chosen.get(e.name)
        text = (f"{role} (chosen)" if role else "; ".join(dict.fromkeys(use.get(e.name, []))))
        rows.append(f"  {e.name:<{width}}  {e.type[:30]:<30} {e.records:>8} "
                    f"{(f'{rate:.0f} Hz' if rate else '-'):>8}  {text}")
    rows += [f"  note: {p}" for p in problems]
    return "\n".join(rows)


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
                           metadata='{"unit":"m","against":"' + result.entries["pose"] + '"}')


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
    return "\n".join(rows)


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
    poses = _run(result.drivetrain, kin, g, P, result.start or Pose2d())
    out = dataclasses.replace(result, poses=poses, positions=P, gyroAngles=g,
                              kinematics=kin, vsLogged=None, vsTruth=None)
    if compare is not None and result.logged is not None:
        out.vsLogged = _drift(result.t, poses, result.logged[0], result.logged[1], compare)
    if compare is not None and result.truth is not None and len(result.truth[0]):
        out.vsTruth = _drift(result.t, poses, result.truth[0], result.truth[1], compare)
    return out
