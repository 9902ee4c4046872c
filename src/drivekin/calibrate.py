"""Find a robot's true geometry from its logs (``python -m drivekin calibrate``; command
line in ``app/calibrate_cli.py``).

Each log is replayed first (:func:`drivekin.replay.replayLog`: the same entry detection,
units and geometry options), with no corrections. Then:

1. **Windows.** The replayed motion is cut into manoeuvres, from the gyro's rate and the
   replayed translation speed (both averaged over ``SMOOTH`` s): *spin* (turning at least
   ``SPIN_RATE`` rad/s while moving less than ``STILL_SPEED`` m/s), *straight* (turning
   less than ``STRAIGHT_RATE`` rad/s while moving at least ``MOVING_SPEED`` m/s) and
   *turn* (turning and moving). ``TRIM`` s is cut from both ends of each (the modules
   are still turning there); a window shorter than ``MIN_WINDOW`` s, or a spin or turn
   that turns less than ``MIN_TURN`` rad, is rejected, and the result says why.
2. **Estimates**, each from the windows where it is observable, by least squares with an
   intercept per window (scipy.linalg), and a 95 % interval from the fit's residuals
   (Student's t):

   - ``wheelRadiusScale`` (swerve, mecanum; true radius / the radius the robot used, per
     module): spinning in place, module i rolls k_i·ψ, k_i its distance per radian of
     robot rotation in the configured geometry (the distance from the centre, for a
     swerve module), so its logged distance is k_i·ψ / scale_i (Team 6328's wheel-radius
     characterization, per module). Without a usable spin, every turning window gives
     the wheels' common scale: the rotation the wheels imply through the configured
     geometry (forward kinematics) is 1 / scale of the gyro's, one slope through the
     origin over disjoint intervals of at least ``INTERVAL`` s (independent noise), its
     interval from their residuals (heteroskedasticity-robust). Both assume the gyro and
     the module positions (and, turning while driving, a swerve's steer angles) are
     right.
   - ``trackwidth`` (differential, effective, m): (right − left) = W·ψ over every window
     that turns (WPILib SysId's trackwidth analysis, as a regression). It assumes the
     logged wheel distances are right: from the gyro alone, a differential drive's wheel
     scale and trackwidth are not separable, so its ``wheelRadiusScale`` needs a
     reference pose.
   - ``deadWheelLevers`` (m) and ``deadWheelPoses``: spinning in place, wheel i reads
     m_i·ψ with m_i = x sin φ − y cos φ (Road Runner's angular regression: a parallel
     wheel's y, a perpendicular wheel's x). The poses are then only known as the
     configured ones moved perpendicular to their rolling direction (not determined:
     the directions need a reference). With a reference pose, each wheel's readings are
     regressed on the robot's motion over the reference intervals (the twist: x, y and
     heading, robot frame): direction, distance scale and lever arm of every wheel (a
     joint least-squares fit for any number of wheels).
   - ``steerOffsets`` (swerve, rad, added to the logged angles): driving straight, every
     module points the same way, so each module's offset from the modules' mean direction
     is the circular mean of its deviation (angles mod π: a module may drive backwards).
     Their common part needs a reference pose, which gives the direction of travel.
   - ``gyroScale`` (true / the gyro's heading change): the reference pose's heading
     against the gyro's; needs a reference pose.

3. **With a reference pose** (``truth=``, e.g. vision or a simulation's true pose), a joint
   fit of the parameters minimises the drift against it (scipy.optimize.least_squares).
   Its rows are reference intervals of ``INTERVAL`` s that share no sample: the drift of
   the replayed translation over the interval (robot frame at its start) and the heading
   error at each of its samples, with one heading offset per log as a nuisance
   parameter. The drift from one end of a log to the other is not used directly: its
   errors accumulate and so correlate, which would overstate what the fit knows; over
   disjoint intervals they are independent, and the 95 % interval comes from the
   cluster-robust (sandwich) covariance of the rows. A swerve or mecanum drive's drift
   hardly tells its modules' wheel scales apart (forward kinematics averages them;
   mecanum's has a null space), so there the fit varies the common factor of the spin's
   per-module scales (and, for swerve, the common offset of the straight windows' steer
   offsets) with the gyro scale; a differential drive's wheel scales are fitted per
   side, and its trackwidth then follows from the turning windows. Dead wheels are
   regressed on the reference's motion directly.
4. **Drift before and after**: the replay as configured and with the fitted values
   (the replay's own samples corrected, :func:`drivekin.replay.replayAgain`: each log is
   read and replayed once) against the reference (without one, drift is not measured: the logged pose is the
   robot's own odometry, made with the geometry being corrected), and the ``replay``
   command line that applies the fitted values.

Intervals: ``uncertainty`` is the half-width of the 95 % interval. The tests measure how
often it holds the true value over 40 noisy simulated logs per case (94–96 % for the
window estimates and the joint fits; a differential trackwidth fitted with its wheel
scales is conservative, its terms added in quadrature).

Each drivetrain's parameters, window estimates, joint-fit parameters and corrections
are its calibration model (``drivekin._core.calibrationmodels``, found by
``model_for``); calibrate never compares drivetrain names.

A parameter the logs cannot determine is reported ``determined=False`` with the
manoeuvre or reference that would determine it. scipy is an optional extra
(``pip install "drivekin[calibrate]"``), imported only here.
"""
from __future__ import annotations

import dataclasses
import math
import os
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from drivekin import datalog, replay
from drivekin._core.calibrationfit import (  # noqa: F401 (CONFIDENCE: calibrate's, as before)
    CONFIDENCE, INTERVAL, _joint_fit, _origin_slope, _pairs, _relative, _scipy, _slope, _t95,
    _twist)
from drivekin._core.calibrationmodels import CalibrationModel, model_for
from drivekin._core.plotting import pyplot
from drivekin.datalog import DataLogError, LogData
from drivekin.replay import DriftStats, ReplayConfig, ReplayResult

__all__ = ["CalibrationError", "CalibrationResult", "Parameter", "Window", "calibrate",
           "plotCalibration", "report"]

SMOOTH = 0.25          # s, moving average of the rates that classify the motion
SPIN_RATE = 0.5        # rad/s
STRAIGHT_RATE = 0.05   # rad/s
STILL_SPEED = 0.15     # m/s
MOVING_SPEED = 0.3     # m/s
TURN_RATE = 0.3        # rad/s, a turning window's least rate
TRIM = 0.25            # s cut from both ends of a window
MIN_WINDOW = 1.0       # s
MIN_TURN = 1.0         # rad a spin or turn window must turn

_KINDS = ("spin", "straight", "turn")


class CalibrationError(DataLogError):
    """A log that cannot be calibrated (too short, never turns, a gyro that never moves,
    entries that contradict the geometry); the message names what is missing."""


@dataclass
class Window:
    """One manoeuvre found in a log: ``kind`` (spin, straight, turn), its time span (µs),
    whether it was used, and why (not)."""

    log: str
    kind: str
    start: int
    end: int
    used: bool
    why: str

    @property
    def duration(self) -> float:
        return (self.end - self.start) / 1e6


@dataclass
class Parameter:
    """One estimate: ``value`` (a number or a list), ``uncertainty`` (the half-width of
    its 95 % interval, same shape; None when not determined), whether the logs determine
    it, and why (what it came from, or what would determine it)."""

    name: str
    value: Any
    uncertainty: Any
    determined: bool
    why: str
    unit: str = ""

    def asdict(self) -> dict[str, Any]:
        return {"value": _plain(self.value), "uncertainty": _plain(self.uncertainty),
                "determined": self.determined, "why": self.why, "unit": self.unit}


@dataclass
class CalibrationResult:
    """Everything :func:`calibrate` found: the parameters by name, the windows, the drift
    before and after (against ``against``: the reference pose, or the logged pose), and
    the ``replay`` options that apply the fitted values."""

    sources: list[str]
    drivetrain: str
    parameters: dict[str, Parameter]
    windows: list[Window]
    against: str | None
    before: list[DriftStats | None]
    after: list[DriftStats | None]
    replayOptions: dict[str, Any]
    replays: list[ReplayResult] = field(default_factory=list, repr=False)
    fitted: list[ReplayResult] = field(default_factory=list, repr=False)

    def replayCommand(self, logs: list[str] | None = None) -> str:
        """The ``python -m drivekin replay`` command line with the fitted options."""
        return "python -m drivekin replay " + " ".join(
            [_quote(p) for p in (logs or self.sources)] + _options_text(self.replayOptions))

    def asdict(self) -> dict[str, Any]:
        return {"sources": list(self.sources), "drivetrain": self.drivetrain,
                "parameters": {k: p.asdict() for k, p in self.parameters.items()},
                "windows": [{"log": w.log, "kind": w.kind, "start_s": w.start / 1e6,
                             "end_s": w.end / 1e6, "used": w.used, "why": w.why}
                            for w in self.windows],
                "drift_against": self.against,
                "drift_before": [d.asdict() if d else None for d in self.before],
                "drift_after": [d.asdict() if d else None for d in self.after],
                "replay_command": self.replayCommand()}


def _plain(v: Any) -> Any:
    if isinstance(v, np.ndarray):
        return [_plain(x) for x in v.tolist()]
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if isinstance(v, (np.floating, np.integer)):
        return v.item()
    return v


def _quote(text: str) -> str:
    return text if text and all(c.isalnum() or c in "/._-+:=," for c in text) else repr(text)


def _options_text(opts: dict[str, Any]) -> list[str]:
    out = []
    for k, v in opts.items():
        if k == "dead-wheel":                       # repeated: X,Y,DEG per wheel
            for w in v:
                out += [f"--{k}={','.join(f'{x:.6g}' for x in w)}"]
        else:
            # Attached with '=': a value starting with '-' would read as an option.
            out += [f"--{k}=" + ",".join(f"{x:.6g}" for x in np.atleast_1d(v))]
    return out


# ---------------------------------------------------------------------------------------
# Windows

def _moving_average(x: np.ndarray, n: int) -> np.ndarray:
    if n <= 1 or len(x) < n:
        return x
    c = np.cumsum(np.concatenate([[0.0], x]))
    out = (c[n:] - c[:-n]) / n
    pad = n // 2
    return np.concatenate([np.full(pad, out[0]), out, np.full(len(x) - len(out) - pad, out[-1])])


def _windows(r: ReplayResult, name: str) -> list[tuple[str, slice, Window]]:
    t = r.t.astype(np.float64) / 1e6
    if len(t) < 3 or t[-1] - t[0] < MIN_WINDOW:
        raise CalibrationError(f"{name}: the log is too short to calibrate from "
                               f"({t[-1] - t[0] if len(t) else 0:.2f} s of wheel samples; "
                               f"at least {MIN_WINDOW:g} s of each manoeuvre is needed)")
    psi = r.gyroAngles
    dt = np.gradient(t)
    dt[dt <= 0] = np.median(dt[dt > 0]) if (dt > 0).any() else 1.0
    rate = 1.0 / float(np.median(dt))
    n = max(1, int(round(SMOOTH * rate)))
    w = _moving_average(np.gradient(psi) / dt, n)
    v = _moving_average(np.hypot(np.gradient(r.poses[:, 0]), np.gradient(r.poses[:, 1])) / dt,
                        n)
    label = np.full(len(t), "", dtype=object)
    label[(np.abs(w) >= SPIN_RATE) & (v < STILL_SPEED)] = "spin"
    label[(np.abs(w) <= STRAIGHT_RATE) & (v >= MOVING_SPEED)] = "straight"
    label[(np.abs(w) >= TURN_RATE) & (v >= MOVING_SPEED)] = "turn"
    out = []
    i = 0
    while i < len(t):
        j = i
        while j + 1 < len(t) and label[j + 1] == label[i]:
            j += 1
        kind = label[i]
        if kind:
            lo = int(np.searchsorted(t, t[i] + TRIM))
            hi = int(np.searchsorted(t, t[j] - TRIM, side="right"))
            win = Window(name, kind, int(r.t[i]), int(r.t[j]), False, "")
            if hi - lo < 3 or t[hi - 1] - t[lo] < MIN_WINDOW:
                win.why = (f"{t[j] - t[i]:.2f} s long; at least {MIN_WINDOW + 2 * TRIM:g} s "
                           f"are needed ({TRIM:g} s is trimmed at each end)")
            elif kind != "straight" and abs(psi[hi - 1] - psi[lo]) < MIN_TURN:
                win.why = (f"turned {abs(psi[hi - 1] - psi[lo]):.2f} rad; at least "
                           f"{MIN_TURN:g} rad are needed")
            else:
                win.used = True
                win.why = (f"{t[hi - 1] - t[lo]:.1f} s" + (
                    f", {abs(psi[hi - 1] - psi[lo]):.1f} rad" if kind != "straight" else
                    f", {float(np.mean(v[lo:hi])):.2f} m/s"))
            out.append((kind, slice(lo, hi), win))
        i = j + 1
    return out


# ---------------------------------------------------------------------------------------
# The estimators. Each takes the replays and their windows and returns Parameters.

@dataclass
class _Log:
    name: str
    r: ReplayResult
    windows: list[tuple[str, slice, Window]]
    ref: tuple[np.ndarray, np.ndarray] | None     # reference (t µs, poses) in the replay span

    def used(self, *kinds: str) -> list[slice]:
        return [s for k, s, w in self.windows if w.used and k in kinds]


def _gyro_scale(logs: list[_Log]) -> Parameter:
    if not any(lg.ref is not None for lg in logs):
        return Parameter("gyroScale", None, None, False,
                         "needs a reference pose (--truth ENTRY, e.g. vision or a "
                         "simulation's true pose): the wheels alone cannot tell a wrong "
                         "gyro scale from wrong wheel geometry")
    xs, ys = [], []
    for lg in logs:
        if lg.ref is None:
            continue
        tr, P = lg.ref
        g = np.interp(tr.astype(np.float64), lg.r.t.astype(np.float64), lg.r.gyroAngles)
        xs.append(g)
        ys.append(np.unwrap(P[:, 2]))
    turned = max(float(np.ptp(x)) for x in xs)
    if turned < MIN_TURN:
        return Parameter("gyroScale", None, None, False,
                         f"the robot turned {turned:.2f} rad while the reference was logged: "
                         f"turn it (spin in place for 3 turns)")
    b, se, dof = _slope(xs, ys)
    return Parameter("gyroScale", b, _t95(dof) * se, True,
                     f"reference heading against the gyro over {turned:.1f} rad")


def _wheel_scales(logs: list[_Log], model: CalibrationModel, gyro: float) -> list[Parameter]:
    """wheelRadiusScale: each wheel's from the spin windows; without one, the wheels'
    common factor from the turning windows."""
    if any(lg.used("spin") for lg in logs):
        return [_spin_scales(logs, model, gyro)]
    return [_turn_scale(logs, model, gyro)]


def _spin_scales(logs: list[_Log], model: CalibrationModel, gyro: float) -> Parameter:
    """Each wheel's distance against the gyro's heading while spinning in place: it rolls
    k·ψ / scale, k its distance per radian of robot rotation in the configured geometry."""
    r0 = logs[0].r
    width = r0.positions.shape[1]
    k = model.per_rad(r0.kinematics)
    values, errs, notes = [], [], []
    spins = sum(len(lg.used("spin")) for lg in logs)
    for i in range(width):
        xs, ys = [], []
        skipped = 0
        for lg in logs:
            for s in lg.used("spin"):
                d = model.spin_distances(lg.r, s, i)
                if d is None:
                    skipped += 1
                    continue
                xs.append(lg.r.gyroAngles[s] * gyro)
                ys.append(d)
        if not xs:
            values.append(float("nan"))
            errs.append(float("nan"))
            notes.append(f"{model.wheel} {i}: never tangent while spinning")
            continue
        b, se, dof = _slope(xs, ys)
        if not (abs(b) > 0 and math.isfinite(b)):
            values.append(float("nan"))
            errs.append(float("nan"))
            notes.append(f"{model.wheel} {i} did not roll while spinning")
            continue
        values.append(abs(k[i] / b))
        errs.append(abs(k[i]) * _t95(dof) * se / b ** 2)
        if skipped:
            notes.append(f"{model.wheel} {i}: {skipped} window(s) skipped (not tangent)")
    ok = all(math.isfinite(v) for v in values)
    why = (f"spinning in place ({spins} window(s)): each {model.wheel}'s distance against "
           f"the gyro's heading"
           + (", the gyro corrected by gyroScale" if gyro != 1.0 else
              ", assuming the gyro and the geometry are right"))
    if notes:
        why += "; " + "; ".join(notes)
    return Parameter("wheelRadiusScale", values if ok else None, errs if ok else None, ok, why)


def _turn_scale(logs: list[_Log], model: CalibrationModel, gyro: float) -> Parameter:
    """The wheels' common scale from every window that turns: the rotation the wheels
    imply through the configured geometry (forward kinematics) against the gyro's, over
    disjoint intervals of at least INTERVAL s (so their noise is independent), one slope
    through the origin; the interval from the intervals' residuals (sandwich)."""
    x, y = [], []
    windows = 0
    for lg in logs:
        steps = model.step_rotations(lg.r)
        if steps is None:
            break
        implied = np.concatenate([[0.0], np.cumsum(steps)])
        for s in lg.used("turn"):
            a, b = _pairs(lg.r.t[s])
            windows += 1
            x.append(implied[s][b] - implied[s][a])
            y.append((lg.r.gyroAngles[s][b] - lg.r.gyroAngles[s][a]) * gyro)
    count = sum(len(v) for v in x)
    if count < 3:
        return Parameter("wheelRadiusScale", None, None, False,
                         "no usable spin-in-place or turning window: spin in place for 3 "
                         "turns, or drive while turning")
    f, se, dof = _origin_slope(np.concatenate(x), np.concatenate(y))
    if not (f > 0 and math.isfinite(f)):
        return Parameter("wheelRadiusScale", None, None, False,
                         "the wheels imply no rotation while the gyro turns: check the "
                         "geometry; or spin in place for 3 turns")
    width = logs[0].r.positions.shape[1]
    half = _t95(dof) * se
    why = (f"turning ({windows} window(s), {count} independent {INTERVAL:g} s intervals): "
           f"the rotation the {model.wheel}s imply through the configured geometry against "
           f"the gyro's" + (", the gyro corrected by gyroScale" if gyro != 1.0 else
                            ", assuming the gyro and the geometry are right")
           + f"; one factor for every {model.wheel} (each {model.wheel}'s own needs a spin "
             f"in place)")
    return Parameter("wheelRadiusScale", [f] * width, [half] * width, True, why)


def _trackwidth(logs: list[_Log], gyro: float, scales: Any = None,
                halves: tuple[list[float], float] | None = None) -> Parameter:
    """(right − left) = W·ψ over the windows that turn; with fitted wheel scales and gyro
    scale (and their 95 % half-widths), W's interval includes theirs."""
    xs, left, right = [], [], []
    sl, sr = (scales if scales is not None else (1.0, 1.0))
    for lg in logs:
        for s in lg.used("spin", "turn"):
            P = lg.r.positions[s]
            xs.append(lg.r.gyroAngles[s] * gyro)
            left.append(P[:, 0])
            right.append(P[:, 1])
    if not xs:
        return Parameter("trackwidth", None, None, False,
                         "no usable window that turns: spin in place for 3 turns", "m")
    b, se, dof = _slope(xs, [r * sr - lft * sl for r, lft in zip(right, left)])
    half = _t95(dof) * se
    if halves is not None:
        # W = sr·Wr − sl·Wl with Wr, Wl the slopes of each side alone: the scales' and
        # the gyro's intervals add in quadrature (linearised).
        (hl, hr), hg = halves
        wr = _slope(xs, right)[0]
        wl = _slope(xs, left)[0]
        half = math.sqrt(half ** 2 + (wr * hr) ** 2 + (wl * hl) ** 2 + (b * hg / gyro) ** 2)
    return Parameter("trackwidth", b, half, math.isfinite(b) and b > 0,
                     f"(right − left) against the gyro's heading over {len(xs)} turning "
                     f"window(s)" + (", with the fitted wheel and gyro scales"
                                     if scales is not None else
                                     ", assuming the logged wheel distances are right"),
                     "m")


def _steer_offsets(logs: list[_Log]) -> Parameter:
    diffs: list[np.ndarray] = []
    for lg in logs:
        for s in lg.used("straight"):
            a = lg.r.positions[s][:, :, 1]
            z = np.exp(2j * a)                       # mod π: a module may drive backwards
            common = np.angle(z.mean(axis=1))
            diffs.append(np.angle(z * np.exp(-1j * common)[:, None]) / 2)
    if not diffs:
        return Parameter("steerOffsets", None, None, False,
                         "no usable straight-driving window: drive straight for a few "
                         "seconds", "rad")
    d = np.concatenate(diffs)
    n = d.shape[0]
    mean = np.angle(np.exp(1j * d).mean(axis=0))
    sd = d.std(axis=0, ddof=1)
    off = -mean
    off -= off.mean()
    return Parameter("steerOffsets", off.tolist(), (_t95(n - 1) * sd / math.sqrt(n)).tolist(),
                     True, f"driving straight ({len(diffs)} window(s), {n} samples): each "
                           f"module's angle against the modules' mean; their common offset "
                           f"needs a reference pose", "rad")


def _dead_wheel_levers(logs: list[_Log], gyro: float) -> list[Parameter]:
    r0 = logs[0].r
    poses = list(r0.kinematics.getWheelPoses())
    spins = sum(len(lg.used("spin")) for lg in logs)
    if spins == 0:
        why = "no usable spin-in-place window: spin in place for 3 turns"
        return [Parameter("deadWheelLevers", None, None, False, why, "m"),
                Parameter("deadWheelPoses", None, None, False, why, "m, m, deg")]
    out, err, levers, lever_err = [], [], [], []
    for i, p in enumerate(poses):
        xs, ys = [], []
        for lg in logs:
            for s in lg.used("spin"):
                xs.append(lg.r.gyroAngles[s] * gyro)
                ys.append(lg.r.positions[s][:, i])
        m, se, dof = _slope(xs, ys)
        phi = p.getRotation().getRadians()
        m0 = p.getX() * math.sin(phi) - p.getY() * math.cos(phi)
        x = p.getX() + (m - m0) * math.sin(phi)
        y = p.getY() - (m - m0) * math.cos(phi)
        h = _t95(dof) * se
        out.append([x, y, math.degrees(phi)])
        err.append([h * abs(math.sin(phi)), h * abs(math.cos(phi)), 0.0])
        levers.append(m)
        lever_err.append(h)
    why = (f"spinning in place ({spins} window(s)): each wheel's reading against the gyro "
           f"gives its lever arm m = x sin φ − y cos φ (Road Runner's angular regression)")
    return [Parameter("deadWheelLevers", levers, lever_err, True, why, "m"),
            Parameter("deadWheelPoses", out, None, False,
                      "the rolling directions need a reference pose (--truth ENTRY); the "
                      "values are the configured poses moved perpendicular to their "
                      "rolling direction to the fitted levers (deadWheelLevers)",
                      "m, m, deg")]


#: The window estimators, by the parameter they estimate (a model's windowEstimates):
#: (logs, model, gyro scale) -> the Parameters found.
_ESTIMATORS = {
    "wheelRadiusScale": _wheel_scales,
    "steerOffsets": lambda logs, model, gyro: [_steer_offsets(logs)],
    "trackwidth": lambda logs, model, gyro: [_trackwidth(logs, gyro)],
    "deadWheelLevers": lambda logs, model, gyro: _dead_wheel_levers(logs, gyro),
}


# ---------------------------------------------------------------------------------------
# calibrate()

def calibrate(logs: Any, config: ReplayConfig | None = None,
              truth: str | None = None) -> CalibrationResult:
    """Estimate a robot's geometry from one log or several (paths or LogData) of the same
    robot; see the module docstring. ``config`` carries replay's options (entry names,
    units, geometry: the geometry the robot used); its corrections (wheelScale,
    gyroScale, steerOffsets) must be left at their defaults. ``truth`` names a reference
    pose entry (struct:Pose2d) present in every log. CalibrationError (a DataLogError)
    for logs that cannot be calibrated."""
    if isinstance(logs, (str, os.PathLike, LogData)):
        logs = [logs]
    logs = list(logs)
    if not logs:
        raise CalibrationError("no log to calibrate from")
    cfg = config or ReplayConfig()
    if (np.atleast_1d(np.asarray(cfg.wheelScale)) != 1.0).any() or cfg.gyroScale != 1.0 \
            or cfg.steerOffsets is not None:
        raise ValueError("calibrate finds wheelScale, gyroScale and steerOffsets itself: "
                         "leave them out of the configuration")
    if truth is not None:
        cfg = dataclasses.replace(cfg, truth=truth)
    _scipy()
    runs: list[_Log] = []
    windows: list[Window] = []
    for item in logs:
        name = str(item.source if isinstance(item, LogData) else os.fspath(item))
        try:
            log = item if isinstance(item, LogData) else datalog.read(
                item, allowTruncated=cfg.allowTruncated)
            r = replay.replayLog(log, cfg)
        except DataLogError as e:
            # Several logs: the message names the one it is about.
            text = str(e)
            raise CalibrationError(text if text.startswith(name) else f"{name}: {text}") \
                from None
        if runs and r.drivetrain != runs[0].r.drivetrain:
            raise CalibrationError(f"{name} is a {r.drivetrain} drive's log, "
                                   f"{runs[0].name} a {runs[0].r.drivetrain}'s: calibrate "
                                   f"one robot at a time")
        if runs and r.positions.shape[1:] != runs[0].r.positions.shape[1:]:
            raise CalibrationError(f"{name} has {r.positions.shape[1]} wheels per sample, "
                                   f"{runs[0].name} {runs[0].r.positions.shape[1]}")
        wins = _windows(r, name)            # refuses a log too short first
        turned = float(np.ptp(r.gyroAngles))
        if turned < MIN_TURN:
            raise CalibrationError(
                f"{name}: the gyro ({r.entries.get('gyro')}) turned {turned:.3f} rad in "
                f"all: the robot never turned, or the gyro never moved; a calibration needs "
                f"the robot to turn (spin in place for 3 turns) and a gyro that reads it")
        if model_for(r).needsGyro and r.entries.get("gyro") in (None, "(wheels)"):
            raise CalibrationError(f"{name}: calibrating {model_for(r).wheel}s of a "
                                   f"{r.drivetrain} drive needs a gyro")
        ref = None
        if r.truth is not None:
            tr, P = r.truth
            keep = (tr >= r.t[0]) & (tr <= r.t[-1])
            ref = (tr[keep], P[keep])
        runs.append(_Log(name, r, wins, ref))
        windows += [w for _, _, w in wins]
    model = model_for(runs[0].r)
    if not any(w.used and w.kind != "straight" for w in windows):
        raise CalibrationError(
            "no usable window that turns in " + ", ".join(lg.name for lg in runs) +
            f": spin in place (at least {SPIN_RATE:g} rad/s for {MIN_WINDOW + 2 * TRIM:g} s "
            f"and {MIN_TURN:g} rad) or drive while turning")

    gyro_p = _gyro_scale(runs)
    g = gyro_p.value if gyro_p.determined else 1.0
    found: dict[str, Parameter] = {n: Parameter(n, None, None, False, why)
                                   for n, why in model.undetermined.items()}
    for name in model.windowEstimates:
        for p in _ESTIMATORS[name](runs, model, g):
            found[p.name] = p
    found["gyroScale"] = gyro_p
    params = {n: found[n] for n in model.parameters}

    # The joint fit against the reference.
    if model.joint:
        start = {k: p.value for k, p in params.items() if p.determined}
        base = {k: (p.value, p.uncertainty) for k, p in params.items()
                if k in model.jointCommon and p.determined}
        joint = _joint_fit(runs, model, start, base)
        if joint is not None:
            values, half, count = joint
            for name, v in values.items():
                params[name] = Parameter(
                    name, v, half[name], True,
                    f"joint fit of {', '.join(values)} minimising the drift against the "
                    f"reference pose over {count} independent {INTERVAL:g} s intervals",
                    params[name].unit)
            if "trackwidth" in params:
                params["trackwidth"] = _trackwidth(
                    runs, values["gyroScale"], values["wheelRadiusScale"],
                    (half["wheelRadiusScale"], half["gyroScale"]))
    elif model.regressesOnReference:
        for p in _dead_wheel_joint(runs) or ():
            params[p.name] = p

    # The fitted replay of each log: its samples corrected, not the log read again.
    fields = model.config_fields(params)
    values = {n: p.value for n, p in params.items() if p.determined}
    fitted = []
    for lg in runs:
        P = model.correct(lg.r.positions, values)
        gy = lg.r.gyroAngles
        gy = gy[0] + (gy - gy[0]) * float(values.get("gyroScale", 1.0))
        fitted.append(replay.replayAgain(lg.r, P, gy, cfg.compare,
                                         model.kinematics(lg.r, params)))
    # Only a reference measures drift: the logged pose is the robot's own odometry, made
    # with the very geometry being corrected.
    before: list[DriftStats | None] = [lg.r.vsTruth for lg in runs]
    after: list[DriftStats | None] = [fr.vsTruth for fr in fitted]
    against = "reference" if any(b is not None for b in before) else None
    return CalibrationResult([lg.name for lg in runs], runs[0].r.drivetrain, params, windows,
                             against, before, after, _replay_options(fields),
                             [lg.r for lg in runs], fitted)


def _dead_wheel_joint(logs: list[_Log]) -> list[Parameter] | None:
    """Each dead wheel's readings against the reference motion: (cos φ, sin φ, m) / k."""
    sp = _scipy()
    refs = [lg for lg in logs if lg.ref is not None and len(_pairs(lg.ref[0])[0]) >= 4]
    if not refs:
        return None
    width = refs[0].r.positions.shape[1]
    A, B = [], []
    for lg in refs:
        tr, ref = lg.ref
        a, b = _pairs(tr)
        W = np.column_stack([np.interp(tr.astype(np.float64), lg.r.t.astype(np.float64),
                                       lg.r.positions[:, j]) for j in range(width)])
        B.append(W[b] - W[a])
        A.append(_twist(_relative(ref, a, b)))
    A, B = np.concatenate(A), np.concatenate(B)
    if len(A) < 8:
        return None
    out, err, levers, lever_err = [], [], [], []
    dof = len(A) - 3
    t = _t95(dof)
    for i in range(width):
        coef, _, rank, _ = sp.linalg.lstsq(A, B[:, i])
        if rank < 3:
            return None
        res = B[:, i] - A @ coef
        cov = np.linalg.inv(A.T @ A) * float(res @ res) / dof
        c, s, m = coef
        k = math.hypot(c, s)
        phi = math.atan2(s, c)
        # The contact point on the line x sin φ − y cos φ = m/k nearest the configured one.
        p = refs[0].r.kinematics.getWheelPoses()[i]
        lever = m / k
        m0 = p.getX() * math.sin(phi) - p.getY() * math.cos(phi)
        x = p.getX() + (lever - m0) * math.sin(phi)
        y = p.getY() - (lever - m0) * math.cos(phi)
        hm = t * math.sqrt(cov[2, 2]) / k
        hphi = t * math.sqrt(max(0.0, (s * s * cov[0, 0] + c * c * cov[1, 1]
                                       - 2 * s * c * cov[0, 1]))) / k ** 2
        out.append([x, y, math.degrees(phi)])
        err.append([hm * abs(math.sin(phi)), hm * abs(math.cos(phi)), math.degrees(hphi)])
        levers.append(lever)
        lever_err.append(hm)
    why = ("each wheel's readings regressed on the reference pose's motion "
           f"({len(A)} independent intervals): rolling direction and lever arm (a joint "
           "least-squares fit)")
    return [Parameter("deadWheelLevers", levers, lever_err, True, why, "m"),
            Parameter("deadWheelPoses", out, err, True,
                      why + "; the coordinate along the rolling direction as configured",
                      "m, m, deg")]


def _replay_options(fields: dict[str, Any]) -> dict[str, Any]:
    """The ``replay`` command-line options of the replay configuration fields."""
    out: dict[str, Any] = {}
    if "wheelScale" in fields:
        out["wheel-scale"] = fields["wheelScale"]
    if "gyroScale" in fields:
        out["gyro-scale"] = fields["gyroScale"]
    if "steerOffsets" in fields:
        out["steer-offsets"] = [math.degrees(a) for a in fields["steerOffsets"]]
    if "deadWheels" in fields:
        out["dead-wheel"] = fields["deadWheels"]
    return out


# ---------------------------------------------------------------------------------------
# The report

def _fmt(v: Any, e: Any, unit: str) -> tuple[str, str]:
    if isinstance(v, list) and v and isinstance(v[0], list):
        return ("; ".join("(" + ", ".join(f"{x:.4f}" for x in w) + ")" for w in v),
                "; ".join("±(" + ", ".join(f"{x:.4f}" for x in w) + ")" for w in e))
    if isinstance(v, list):
        if unit == "rad":
            return (", ".join(f"{math.degrees(x):+.2f}°" for x in v),
                    ", ".join(f"±{math.degrees(x):.2f}°" for x in e))
        return ", ".join(f"{x:.5f}" for x in v), ", ".join(f"±{x:.5f}" for x in e)
    return f"{v:.5f}{' ' + unit if unit else ''}", f"±{e:.5f}"


def report(result: CalibrationResult) -> str:
    """The text report: each parameter with its 95 % interval (or why it is not
    determined), the windows, the drift before and after, the replay command."""
    lines = [f"calibration of {', '.join(result.sources)} ({result.drivetrain})", ""]
    for p in result.parameters.values():
        if p.determined:
            v, e = _fmt(p.value, p.uncertainty, p.unit)
            lines.append(f"  {p.name}: {v}  (95 %: {e})")
            lines.append(f"      from {p.why}")
        else:
            lines.append(f"  {p.name}: not determined: {p.why}")
            if p.value is not None:
                lines.append(f"      best known: {_fmt(p.value, p.value, p.unit)[0]}")
    lines += ["", "windows:"]
    for w in result.windows:
        mark = "used" if w.used else "rejected"
        lines.append(f"  {w.kind:8s} {w.start / 1e6:8.2f}–{w.end / 1e6:8.2f} s  {mark}: "
                     f"{w.why}")
    if not result.against:
        lines += ["", "drift: not measured (no reference pose; --truth ENTRY names one)"]
    else:
        lines += ["", "drift against the reference pose (final / max / RMS position):"]
        for src, b, a in zip(result.sources, result.before, result.after):
            if b is None or a is None:
                continue
            lines.append(f"  {src}: before {b.finalPosition * 100:.1f} / "
                         f"{b.maxPosition * 100:.1f} / {b.rmsPosition * 100:.1f} cm, after "
                         f"{a.finalPosition * 100:.1f} / {a.maxPosition * 100:.1f} / "
                         f"{a.rmsPosition * 100:.1f} cm")
    lines += ["", "replay with the fitted values:", "  " + result.replayCommand()]
    return "\n".join(lines)


def plotCalibration(result: CalibrationResult, path: str | os.PathLike[str]) -> None:
    """Draw each log's replayed path before and after the fit (and the reference or
    logged pose) and the position error against it over time into a PNG (matplotlib,
    imported only here)."""
    plt = pyplot()
    rows = len(result.replays)
    fig, axes = plt.subplots(rows, 2, figsize=(11, 4.5 * rows), squeeze=False)
    for row, (before, after) in enumerate(zip(result.replays, result.fitted)):
        ax, ex = axes[row]
        ref = before.truth if before.truth is not None else before.logged
        label = "reference" if before.truth is not None else "logged pose (the robot's own)"
        if ref is not None:
            ax.plot(ref[1][:, 0], ref[1][:, 1], color="black", lw=1.5, label=label)
        ax.plot(before.poses[:, 0], before.poses[:, 1], color="tab:red", lw=1,
                label="replay, as configured")
        ax.plot(after.poses[:, 0], after.poses[:, 1], color="tab:blue", lw=1,
                label="replay, fitted")
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        ax.set_title(os.path.basename(str(before.source)))
        ax.legend(loc="best", fontsize=8)
        for stats, color, name in ((result.before[row], "tab:red", "as configured"),
                                   (result.after[row], "tab:blue", "fitted")):
            if stats is not None:
                ex.plot((stats.t - before.t[0]) / 1e6, stats.error * 100, color=color,
                        label=name)
        ex.set_xlabel("time (s)")
        ex.set_ylabel(f"position error against the {label} (cm)")
        for w in result.windows:
            if w.used and w.log == result.sources[row]:
                ex.axvspan((w.start - before.t[0]) / 1e6, (w.end - before.t[0]) / 1e6,
                           alpha=0.08, color={"spin": "green", "straight": "orange",
                                              "turn": "purple"}[w.kind])
        ex.legend(loc="best", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.fspath(path), dpi=110)
    plt.close(fig)
