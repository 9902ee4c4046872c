"""The feasibility check and the module feedforward of :mod:`drivekin.choreo`, on the
sample array (``ChoreoTrajectory.samples``, in ``columns`` order) and a RobotConfig.

Choreo plans against a constant-torque box (module speed ≤ radius·vmax/gearing, force ≤
min(tmax·gearing/radius, cof·m·g/N)); this checks the samples against the limits of the
robot as drivekin models it: the drive motor's torque–speed curve at a battery voltage,
its current limit, wheel friction and a steering rate. Every sample value was rounded to 5
decimals by Choreo, so each comparison allows the error that rounding can cause
(:data:`ROUNDING` per value, propagated through the formula): over the limit by less than
that is a warning, by more a violation.
"""
from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np

from drivekin._core import fieldchecks

QUANTITIES = ("moduleSpeed", "driveTorque", "current", "friction", "steerRate",
              "moduleOrder")
ROUNDING = 5e-6          # half a unit in the 5th decimal, Choreo's rounding of every value
# Beyond the rounding, the torque balance allows this fraction of the moments in it and
# this many N·m (real files balance to 3.2e-4 N·m; a file whose values were scaled after
# rounding carries scaled rounding errors); forces on the wrong modules miss by a large
# part of J·α, tens of N·m.
BALANCE = 1e-4
BALANCE_FLOOR = 1e-3
STOPPED = 0.01           # m/s: a module this slow has no steering direction worth checking

# Choreo's swerve force columns, FL, BL, BR, FR, by the signs of the module's (x, y).
_CHOREO_QUADRANTS = ((1, 1), (-1, 1), (-1, -1), (1, -1))


class FeasibilityRecord(NamedTuple):
    """One comparison: at sample time ``time`` (s), ``module`` (index in the config's
    module order, −1 for the whole robot), ``quantity`` (one of :data:`QUANTITIES`, or
    ``columnShift`` among warnings) had ``value`` against ``limit`` (SI units: m/s, N·m,
    A, N, rad/s; ``moduleOrder``: the torque-balance residual ``|Σ rᵢ×Fᵢ − J·α|`` in
    N·m against what rounding explains plus 1e-4 of ``Σ|rᵢ||Fᵢ| + J·|α|`` and 1e-3 N·m)."""
    time: float
    module: int
    quantity: str
    value: float
    limit: float


class FeasibilityReport:
    """What :meth:`drivekin.choreo.ChoreoTrajectory.check` found.

    ``ok``: no violation. ``violations`` and ``warnings``: lists of
    :class:`FeasibilityRecord` in time order (a warning is over its limit by no more than
    the file's 5-decimal rounding explains; a differential file written with Choreo's
    shifted ``alpha``/``fl``/``fr`` gets one ``columnShift`` warning and is checked with
    the forces read from where Choreo put them). ``worst``: the comparison with the largest
    value/limit over every sample, module and quantity checked (violated or not).
    ``margins``: per quantity checked, the least ``1 − value/limit`` (negative when over).
    """

    __slots__ = ("ok", "violations", "warnings", "worst", "margins", "_series")

    def __init__(self, violations: list[FeasibilityRecord], warnings: list[FeasibilityRecord],
                 worst: FeasibilityRecord | None, margins: dict[str, float],
                 series: dict[str, tuple[np.ndarray, np.ndarray]] | None = None):
        self._series = {} if series is None else series   # quantity -> (t, least margin)
        self.ok = not violations
        self.violations = violations
        self.warnings = warnings
        self.worst = worst
        self.margins = margins

    def __repr__(self) -> str:
        return (f"FeasibilityReport(ok={self.ok}, {len(self.violations)} violations, "
                f"{len(self.warnings)} warnings, worst={self.worst})")

    def asdict(self) -> dict[str, Any]:
        """The report as plain JSON-ready data (a margin of −inf, a value against a limit
        of 0, becomes None)."""
        return {"ok": self.ok, "violations": [r._asdict() for r in self.violations],
                "warnings": [r._asdict() for r in self.warnings],
                "worst": None if self.worst is None else self.worst._asdict(),
                "margins": {q: m if math.isfinite(m) else None
                            for q, m in self.margins.items()}}


# (quantity, time, module, value, limit, tolerance), arrays of one shape
_Check = tuple[str, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]


class _Modules:
    """Per sample × module (config order), field frame: the contact point's velocity and
    acceleration, the force, the wheel direction, and the rounding error of the speed."""

    def __init__(self, samples: np.ndarray, kind: str, config: Any):
        s = samples
        self.t = s[:, 0]
        loc = np.array([(p.x, p.y) for p in config.moduleLocations])
        self.radius_arm = np.hypot(loc[:, 0], loc[:, 1])
        if kind == "swerve":
            order = _swerve_columns(loc)
            heading, vx, vy, w, ax, ay, alpha = (s[:, j, None] for j in range(3, 10))
            c, sn = np.cos(heading), np.sin(heading)
            rx = c * loc[:, 0] - sn * loc[:, 1]
            ry = sn * loc[:, 0] + c * loc[:, 1]
            self.vx, self.vy = vx - w * ry, vy + w * rx
            self.ax = ax - alpha * ry - w * w * rx
            self.ay = ay + alpha * rx - w * w * ry
            self.fx, self.fy = s[:, 10:14][:, order], s[:, 14:18][:, order]
            self.heading = heading
            self.speed_tol = ROUNDING * (math.sqrt(2) + self.radius_arm * (1 + np.abs(w)))
        else:
            left = _differential_columns(loc)
            heading = s[:, 3, None]
            v = s[:, [4, 5]][:, left]
            a = s[:, [7, 8]][:, left]
            f = _differential_forces(s, loc)[:, left]
            c, sn = np.cos(heading), np.sin(heading)
            self.vx, self.vy = v * c, v * sn
            self.ax, self.ay = a * c, a * sn
            self.fx, self.fy = f * c, f * sn
            self.heading = heading
            self.speed_tol = np.full(v.shape, ROUNDING)
        self.speed = np.hypot(self.vx, self.vy)
        self.force = np.hypot(self.fx, self.fy)
        moving = self.speed >= STOPPED
        # The wheel rolls along the velocity; a stopped wheel turns to the force.
        ux = np.where(moving, self.vx / np.where(moving, self.speed, 1.0),
                      self.fx / np.where(self.force > 0, self.force, 1.0))
        uy = np.where(moving, self.vy / np.where(moving, self.speed, 1.0),
                      self.fy / np.where(self.force > 0, self.force, 1.0))
        self.ux, self.uy, self.moving = ux, uy, moving


def _swerve_columns(loc: np.ndarray) -> np.ndarray:
    """For each config module, the force column (Choreo's FL, BL, BR, FR) on its corner."""
    if len(loc) != 4:
        raise ValueError(f"a swerve trajectory has 4 modules; the config has {len(loc)}")
    order = []
    for x, y in loc:
        q = (int(np.sign(x)), int(np.sign(y)))
        if q not in _CHOREO_QUADRANTS:
            raise ValueError(f"a module at ({x:g}, {y:g}) m is on no corner: Choreo's forces "
                             f"belong to modules front-left, back-left, back-right and "
                             f"front-right of the centre")
        order.append(_CHOREO_QUADRANTS.index(q))
    if len(set(order)) != 4:
        raise ValueError("the config needs one module on each corner (front-left, "
                         "back-left, back-right, front-right) to match Choreo's forces")
    return np.array(order)


def _differential_columns(loc: np.ndarray) -> np.ndarray:
    """For each config wheel, 0 (left, y > 0) or 1 (right, y < 0)."""
    if len(loc) != 2 or not loc[0, 1] * loc[1, 1] < 0:
        raise ValueError("a differential trajectory needs a config with 2 wheels, one left "
                         "(y > 0) and one right (y < 0)")
    return np.array([0 if y > 0 else 1 for y in loc[:, 1]])


def _differential_forces(s: np.ndarray, loc: np.ndarray) -> np.ndarray:
    """(fl, fr) per sample: the file's, or, for Choreo's shifted files (``alpha`` holds
    the left force, ``fl`` the right one, ``fr`` 0), the shifted columns."""
    return s[:, [8, 9]] if _shifted(s, loc) else s[:, [10, 11]]


def _track(loc: np.ndarray) -> float:
    return float(abs(loc[0, 1] - loc[1, 1]))


def _shifted(s: np.ndarray, loc: np.ndarray) -> bool:
    """A differential file from Choreo's rust_ffi.cpp bug: ``fr`` ≡ 0 and ``alpha`` the
    left force, recognised by ``alpha`` ≠ (ar − al)/track while the forces read shifted
    balance m·a (they sum to m·(al + ar)/2 within rounding)."""
    return bool(np.all(s[:, 11] == 0.0) and np.any(s[:, 9] != 0.0)
                and not np.allclose(s[:, 9], (s[:, 8] - s[:, 7]) / _track(loc),
                                    atol=1e-3, rtol=1e-3))


def check(samples: np.ndarray, kind: str, config: Any, planned: Any, *,
          maxSteerVelocity: float | None = None, voltage: float = 12.0) -> FeasibilityReport:
    """The report of ``samples`` against ``config``; the torque balance uses ``planned``
    (the config the trajectory was planned with: its MOI and module positions)."""
    fieldchecks.positive(False)("voltage (V)", voltage)
    if voltage > 1000.0:
        raise ValueError(f"voltage (V) must be at most 1000, got {voltage!r}")
    fieldchecks.positive(True)("maxSteerVelocity (rad/s)", maxSteerVelocity)
    m = _Modules(samples, kind, config)
    mc = config.moduleConfig
    motor = mc.driveMotor
    r = mc.wheelRadiusMeters
    n_t, n_m = m.speed.shape
    checks: list[_Check] = []

    def add(name: str, time: Any, module: Any, value: np.ndarray, limit: Any,
            tol: Any) -> None:
        checks.append((name, np.broadcast_to(time, value.shape),
                       np.broadcast_to(module, value.shape), value,
                       np.broadcast_to(limit, value.shape), np.broadcast_to(tol, value.shape)))

    times = m.t[:, None]
    modules = np.arange(n_m)[None, :]
    free = (voltage - motor.R * motor.freeCurrent) * motor.Kv * r
    add("moduleSpeed", times, modules, m.speed, min(mc.maxDriveVelocityMPS, free), m.speed_tol)

    torque = (m.fx * m.ux + m.fy * m.uy) * r          # signed: > 0 drives along the motion
    wheel = m.speed / r
    # The curve: the current the voltage drives against the back-EMF (motoring), or with it
    # (braking, the voltage reversed), times Kt.
    emf = np.where(torque >= 0.0, -1.0, 1.0) * wheel / motor.Kv
    curve = np.maximum(motor.Kt * (voltage + emf) / motor.R, 0.0)
    slope = motor.Kt / (motor.R * motor.Kv * r)
    direction_err = np.minimum(1.0, m.speed_tol / np.maximum(m.speed, 1e-300))
    torque_tol = r * (ROUNDING * math.sqrt(2) + m.force * np.where(m.moving, direction_err, 0))
    add("driveTorque", times, modules, np.abs(torque), curve, torque_tol + slope * m.speed_tol)
    add("current", times, modules, np.abs(torque) / motor.Kt, mc.driveCurrentLimit,
        torque_tol / motor.Kt)
    add("friction", times, modules, m.force, config.wheelFrictionForce,
        ROUNDING * math.sqrt(2))

    if maxSteerVelocity is not None and kind == "swerve" and n_t > 1:
        angle = np.arctan2(m.vy, m.vx) - m.heading
        turn = np.abs((np.diff(angle, axis=0) + math.pi / 2) % math.pi - math.pi / 2)
        dt = np.diff(m.t)[:, None]
        both = m.moving[1:] & m.moving[:-1]
        err = (m.speed_tol[1:] / np.maximum(m.speed[1:], STOPPED)
               + m.speed_tol[:-1] / np.maximum(m.speed[:-1], STOPPED) + 2 * ROUNDING)
        rate = np.where(both, turn / dt, 0.0)
        add("steerRate", m.t[1:, None], modules, rate, float(maxSteerVelocity), err / dt)

    warnings: list[FeasibilityRecord] = []
    residual, tol = _balance(samples, kind, planned, warnings)
    add("moduleOrder", m.t, -1, np.abs(residual), tol, 0.0)
    return _report(checks, warnings)


def _balance(s: np.ndarray, kind: str, planned: Any,
             warnings: list[FeasibilityRecord]) -> tuple[np.ndarray, np.ndarray]:
    """Σ rᵢ×Fᵢ − J·α per sample (the module order decides which rᵢ goes with which Fᵢ)
    and what the rounding of the values can make of it, N·m."""
    loc = np.array([(p.x, p.y) for p in planned.moduleLocations])
    J = planned.MOI
    if kind == "swerve":
        order = _swerve_columns(loc)
        heading = s[:, 3, None]
        c, sn = np.cos(heading), np.sin(heading)
        rx = c * loc[:, 0] - sn * loc[:, 1]
        ry = sn * loc[:, 0] + c * loc[:, 1]
        fx, fy = s[:, 10:14][:, order], s[:, 14:18][:, order]
        residual = np.sum(rx * fy - ry * fx, axis=1) - J * s[:, 9]
        arm = np.hypot(loc[:, 0], loc[:, 1])
        moment = np.sum(arm * np.hypot(fx, fy), axis=1) + J * np.abs(s[:, 9])
        tol = (np.sum(arm * (ROUNDING * math.sqrt(2) + ROUNDING * np.hypot(fx, fy)), axis=1)
               + J * ROUNDING)
        return residual, tol + BALANCE * moment + BALANCE_FLOOR
    _differential_columns(loc)
    half = 0.5 * _track(loc)
    shifted = _shifted(s, loc)
    fl, fr, alpha = s[:, 10], s[:, 11], s[:, 9]
    if shifted:
        fl, fr, alpha = s[:, 9], s[:, 10], (s[:, 8] - s[:, 7]) / (2 * half)
    residual = (fr - fl) * half - J * alpha
    tol = (2 * half * ROUNDING + J * ROUNDING * (1 + 1 / half) + BALANCE_FLOOR
           + BALANCE * (half * (np.abs(fl) + np.abs(fr)) + J * np.abs(alpha)))
    if shifted:
        written = (s[:, 11] - s[:, 10]) * half - J * s[:, 9]
        warnings.append(FeasibilityRecord(float(s[0, 0]), -1, "columnShift",
                                          float(np.max(np.abs(written))), tol))
    return residual, tol


def _report(checks: list[_Check], warnings: list[FeasibilityRecord]) -> FeasibilityReport:
    violations: list[FeasibilityRecord] = []
    margins: dict[str, float] = {}
    series: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    worst = None
    worst_ratio = -math.inf
    for name, time, module, value, limit, tol in checks:
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.where(limit > 0, value / np.where(limit > 0, limit, 1.0),
                             np.where(value > 0, math.inf, 0.0))
        k = np.unravel_index(int(np.argmax(ratio)), ratio.shape)
        margins[name] = float(1.0 - ratio[k])
        rows = ratio if ratio.ndim == 1 else ratio.max(axis=1)
        series[name] = (time if time.ndim == 1 else time[:, 0], 1.0 - rows)
        if ratio[k] > worst_ratio:
            worst_ratio = float(ratio[k])
            worst = _record(name, time, module, value, limit, k)
        over = value - limit
        for idx in zip(*np.nonzero(over > tol)):
            violations.append(_record(name, time, module, value, limit, idx))
        for idx in zip(*np.nonzero((over > 0) & (over <= tol))):
            warnings.append(_record(name, time, module, value, limit, idx))
    key = (lambda rec: (rec.time, QUANTITIES.index(rec.quantity)
                        if rec.quantity in QUANTITIES else -1, rec.module))
    return FeasibilityReport(sorted(violations, key=key), sorted(warnings, key=key), worst,
                             margins, series)


def plot(report: FeasibilityReport, path: str, title: str) -> None:
    """Draw each limit's margin (1 − value/limit, the least over the modules) over time
    into the PNG ``path``; below 0 is over the limit (clipped at −1)."""
    from drivekin._core.plotting import pyplot
    plt = pyplot()
    names = [q for q in QUANTITIES if q in report._series]
    fig, axes = plt.subplots(len(names), 1, sharex=True, squeeze=False,
                             figsize=(8, 1.6 * len(names) + 0.8))
    for ax, name in zip(axes[:, 0], names):
        t, margin = report._series[name]
        ax.plot(t, np.clip(margin, -1.0, 1.0), lw=1)
        ax.axhline(0.0, color="red", lw=0.8)
        ax.set_ylim(-1.05, 1.05)
        ax.set_ylabel(name, fontsize=8)
    axes[-1, 0].set_xlabel("time (s)")
    fig.suptitle(title + ": margin 1 − value/limit (below 0: over the limit)", fontsize=9)
    fig.tight_layout()
    try:
        fig.savefig(path, dpi=100)
    finally:
        plt.close(fig)


def _record(name: str, time: np.ndarray, module: np.ndarray, value: np.ndarray,
            limit: np.ndarray, idx: Any) -> FeasibilityRecord:
    return FeasibilityRecord(float(time[idx]), int(module[idx]), name, float(value[idx]),
                             float(limit[idx]))


def moduleSetpoints(samples: np.ndarray, kind: str, config: Any) -> dict[str, np.ndarray]:
    """Per sample × module (config order): speed (m/s ≥ 0), angle (rad, robot frame, in
    (−π, π]; a stopped module keeps the angle it had, or takes the first it will have),
    the contact point's acceleration along the wheel (m/s²) and the drive current for
    the force along the wheel (A)."""
    m = _Modules(samples, kind, config)
    mc = config.moduleConfig
    heading_dir = np.arctan2(m.vy, m.vx) - m.heading
    angle = np.arctan2(np.sin(heading_dir), np.cos(heading_dir))
    # Stopped modules hold the last moving angle (backfilled at the start).
    idx = np.where(m.moving, np.arange(len(angle))[:, None], -1)
    np.maximum.accumulate(idx, axis=0, out=idx)
    first = np.where(m.moving.any(axis=0), np.argmax(m.moving, axis=0), 0)
    idx = np.where(idx < 0, first[None, :], idx)
    angle = np.take_along_axis(angle, idx, axis=0)
    angle = np.where(angle <= -math.pi, angle + 2 * math.pi, angle)
    heading = np.broadcast_to(m.heading, angle.shape)
    ux = np.cos(angle + heading)
    uy = np.sin(angle + heading)
    torque = (m.fx * ux + m.fy * uy) * mc.wheelRadiusMeters
    return {"speed": m.speed.copy(), "angle": angle,
            "acceleration": m.ax * ux + m.ay * uy,
            "current": torque / mc.driveMotor.Kt}
