"""The least squares of :mod:`drivekin.calibrate`: scipy (an optional extra, imported on
first use), one slope shared by several windows, the t quantile of the ``CONFIDENCE``
intervals, and the joint fit of the geometry against a reference pose over disjoint
``INTERVAL`` s reference intervals (the model it varies replays each log again)."""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from drivekin import replay

if TYPE_CHECKING:
    from drivekin._core.calibrationmodels import CalibrationModel
    from drivekin.calibrate import _Log

CONFIDENCE = 0.95



def _scipy() -> Any:
    try:
        import scipy.linalg
        import scipy.optimize
        import scipy.stats
    except ImportError:
        raise ImportError('calibration needs scipy: pip install "drivekin[calibrate]"') \
            from None
    return scipy


def _slope(x: list[np.ndarray], y: list[np.ndarray]) -> tuple[float, float, int]:
    """One slope shared by several windows, each with its own intercept: (slope, its
    standard error, degrees of freedom)."""
    sp = _scipy()
    n = sum(len(a) for a in x)
    k = len(x)
    A = np.zeros((n, 1 + k))
    b = np.empty(n)
    row = 0
    for j, (xs, ys) in enumerate(zip(x, y)):
        A[row:row + len(xs), 0] = xs - xs.mean()
        A[row:row + len(xs), 1 + j] = 1.0
        b[row:row + len(xs)] = ys
        row += len(xs)
    coef, _, rank, _ = sp.linalg.lstsq(A, b)
    dof = n - (1 + k)
    if rank < 1 + k or dof < 1:
        return float("nan"), float("inf"), max(dof, 0)
    res = b - A @ coef
    sigma2 = float(res @ res) / dof
    sxx = float(A[:, 0] @ A[:, 0])
    return float(coef[0]), math.sqrt(sigma2 / sxx) if sxx > 0 else float("inf"), dof


def _origin_slope(x: np.ndarray, y: np.ndarray) -> tuple[float, float, int]:
    """The slope of y = b·x through the origin over independent pairs: (slope, its
    standard error from the residuals, heteroskedasticity-robust with the small-sample
    factor n/(n − 1), degrees of freedom)."""
    sxx = float(x @ x)
    n = len(x)
    if n < 2 or sxx <= 0:
        return float("nan"), float("inf"), max(n - 1, 0)
    b = float(x @ y) / sxx
    res = y - b * x
    var = float((x * x) @ (res * res)) / sxx ** 2 * n / (n - 1)
    return b, math.sqrt(var), n - 1


def _t95(dof: int) -> float:
    return float(_scipy().stats.t.ppf(0.5 + CONFIDENCE / 2, max(dof, 1)))



INTERVAL = 1.0  # s, the least span of one reference interval of the joint fit


def _pairs(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Indices (a, b) of reference intervals at least INTERVAL long that share no sample
    (so their noise is independent): the motion over each is the fit's residual, and a
    longer interval carries more of the drift than it adds of the reference's noise."""
    if len(t) < 2:
        return np.zeros(0, dtype=np.intp), np.zeros(0, dtype=np.intp)
    period = float(np.median(np.diff(t))) / 1e6
    k = max(1, int(math.ceil(INTERVAL / max(period, 1e-9))))
    a = np.arange(0, len(t) - k, k + 1)
    return a, a + k


def _relative(P: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Relative poses from row a to row b (robot frame at a): (k, 3)."""
    pa, pb = P[a], P[b]
    c, s = np.cos(pa[:, 2]), np.sin(pa[:, 2])
    dx, dy = pb[:, 0] - pa[:, 0], pb[:, 1] - pa[:, 1]
    dth = np.angle(np.exp(1j * (pb[:, 2] - pa[:, 2])))
    return np.column_stack([c * dx + s * dy, -s * dx + c * dy, dth])


def _twist(rel: np.ndarray) -> np.ndarray:
    """The twists (dx, dy, dθ, robot frame) whose exponentials are the relative poses: the
    integral of the robot-frame velocity over an interval of constant curvature, which is
    what a dead wheel integrates."""
    th = rel[:, 2]
    h = th / 2.0
    small = np.abs(th) < 1e-9
    k = np.where(small, 1.0 - th * th / 12.0, h / np.tan(np.where(small, 1.0, h)))
    return np.column_stack([k * rel[:, 0] + h * rel[:, 1], -h * rel[:, 0] + k * rel[:, 1], th])


def _at(t_src: np.ndarray, poses: np.ndarray, t: np.ndarray) -> np.ndarray:
    """The replayed path interpolated at the reference timestamps (x, y linear, heading
    unwrapped)."""
    ts, tt = t_src.astype(np.float64), t.astype(np.float64)
    return np.column_stack([np.interp(tt, ts, poses[:, 0]), np.interp(tt, ts, poses[:, 1]),
                            np.interp(tt, ts, np.unwrap(poses[:, 2]))])


_ADDITIVE = ("steerOffsets",)     # joint parameters that add (rad); the rest multiply


class _Model:
    """The parameters a drivetrain's joint fit varies (its calibration model's ``joint``),
    as one vector, and the replay they give. The drift of a swerve or mecanum drive
    barely tells one module's wheel scale or steer offset from another's (forward
    kinematics averages the modules; a mecanum drive's has a null space), so where the
    windows gave them (``base``, of the model's ``jointCommon``) the fit varies only
    their common factor and common offset, keeping the windows' differences between
    modules; everything else is fitted per wheel."""

    def __init__(self, model: CalibrationModel, width: int, start: dict[str, Any],
                 base: dict[str, tuple[list[float], list[float]]]) -> None:
        self.model, self.width, self.base = model, width, base
        self.names: list[tuple[str, int | None]] = []
        for name in model.joint:
            if name == "gyroScale" or name in base:
                self.names.append((name, None))
            else:
                self.names += [(name, i) for i in range(width)]
        x = []
        for name, i in self.names:
            v = start.get(name)
            neutral = 0.0 if name in _ADDITIVE else 1.0
            if name in base or v is None:
                x.append(neutral)
            else:
                x.append(v[i] if i is not None else v)
        self.x0 = np.array(x, dtype=np.float64)

    def config(self, x: np.ndarray, half: np.ndarray | None = None) -> dict[str, Any]:
        """The parameters of ``x`` by name; with ``half`` (the 95 % half-widths of x), the
        half-widths of those parameters instead (a common factor's combined in quadrature
        with the windows' own)."""
        out: dict[str, Any] = {}
        for j, ((name, i), v) in enumerate(zip(self.names, x)):
            h = None if half is None else float(half[j])
            if name in self.base:
                values, halves = self.base[name]
                if name in _ADDITIVE:
                    out[name] = ([float(b + v) for b in values] if h is None else
                                 [math.hypot(h, hb) for hb in halves])
                else:
                    out[name] = ([float(b * v) for b in values] if h is None else
                                 [math.hypot(b * h, v * hb) for b, hb in zip(values, halves)])
            elif i is None:
                out[name] = float(v) if h is None else h
            else:
                out.setdefault(name, [0.0] * self.width)[i] = float(v) if h is None else h
        return out

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        lo = [-math.pi / 2 if n in _ADDITIVE else 0.5 for n, _ in self.names]
        hi = [math.pi / 2 if n in _ADDITIVE else 2.0 for n, _ in self.names]
        return np.array(lo), np.array(hi)

    def replay(self, lg: _Log, x: np.ndarray) -> np.ndarray:
        c = self.config(x)
        P = self.model.correct(lg.r.positions, c)
        g = lg.r.gyroAngles[0] + (lg.r.gyroAngles - lg.r.gyroAngles[0]) * c["gyroScale"]
        return replay.replayAgain(lg.r, P, g, None).poses


def _joint_fit(logs: list[_Log], model: CalibrationModel, start: dict[str, Any],
               base: dict[str, tuple[list[float], list[float]]]
               ) -> tuple[dict[str, Any], dict[str, Any], int] | None:
    sp = _scipy()
    refs = [lg for lg in logs if lg.ref is not None and len(_pairs(lg.ref[0])[0]) >= 4]
    if not refs:
        return None
    width = refs[0].r.positions.shape[1]
    fit_model = _Model(model, width, start, base)

    pairs = [_pairs(lg.ref[0]) for lg in refs]
    targets = [_relative(lg.ref[1], a, b)[:, :2] for lg, (a, b) in zip(refs, pairs)]

    npar = len(fit_model.x0)

    def blocks(x: np.ndarray) -> list[np.ndarray]:
        # One row per reference interval (from one sample to one INTERVAL later, sharing
        # no sample with the next): the drift of its translation (the replayed motion
        # minus the reference's, robot frame at its start), and the heading error at
        # each of its samples. Its noise is the reference's and the sensors' within the
        # interval, independent of the other rows'; the translation drift from one end of
        # the log to the other accumulates errors (which then correlate) and would
        # overstate what the fit knows, while the heading (the gyro's, turned by
        # gyroScale) accumulates none.
        # Each log's headings carry one more unknown, a constant offset (the noise of the
        # gyro's and the reference's first samples): the last parameters.
        out = []
        for j, (lg, (a, b), want) in enumerate(zip(refs, pairs, targets)):
            rep = _at(lg.r.t, fit_model.replay(lg, x[:npar]), lg.ref[0])
            dh = np.angle(np.exp(1j * (rep[:, 2] + x[npar + j] - lg.ref[1][:, 2])))
            span = a[:, None] + np.arange(b[0] - a[0] + 1)[None, :]
            out.append(np.column_stack([_relative(rep, a, b)[:, :2] - want, dh[span]]))
        return out

    def weights(x: np.ndarray) -> list[np.ndarray]:
        # Metres and radians weighed by their spread: a residual in units of its noise.
        bl = blocks(x)
        trans = np.concatenate([b_[:, :2].ravel() for b_ in bl]).std(ddof=1)
        head = np.concatenate([b_[:, 2:].ravel() for b_ in bl]).std(ddof=1)
        return [np.concatenate([np.full(2, 1.0 / max(trans, 1e-9)),
                                np.full(b_.shape[1] - 2, 1.0 / max(head, 1e-12))])
                for b_ in bl]

    lo, hi = fit_model.bounds()
    lo = np.concatenate([lo, np.full(len(refs), -math.pi)])
    hi = np.concatenate([hi, np.full(len(refs), math.pi)])
    x0 = np.clip(np.concatenate([fit_model.x0, np.zeros(len(refs))]), lo, hi)
    w = weights(x0)

    def residuals(x: np.ndarray) -> np.ndarray:
        return np.concatenate([(b_ * wb).ravel() for b_, wb in zip(blocks(x), w)])

    fit = sp.optimize.least_squares(residuals, x0, bounds=(lo, hi), x_scale="jac")
    w = weights(fit.x)                  # once more with the fitted residuals' spread
    fit = sp.optimize.least_squares(residuals, fit.x, bounds=(lo, hi), x_scale="jac")
    if not fit.success:
        return None
    # The covariance from the sandwich of each interval's scores (cluster-robust, with
    # the small-sample factor k/(k − p)): an interval's noise grows with how far it moves
    # (the heading's noise turns its translation), so the plain (JᵀJ)⁻¹σ² would credit the
    # long intervals, which carry most of what the fit learns, with the short ones' noise.
    p = len(fit.x)
    scores, bread, row = [], np.zeros((p, p)), 0
    for b_ in blocks(fit.x):
        n_rows, width_b = b_.shape
        J = fit.jac[row:row + n_rows * width_b].reshape(n_rows, width_b, p)
        r = fit.fun[row:row + n_rows * width_b].reshape(n_rows, width_b)
        scores.append(np.einsum("kcp,kc->kp", J, r))
        bread += np.einsum("kcp,kcq->pq", J, J)
        row += n_rows * width_b
    sc = np.concatenate(scores)
    k = len(sc)
    if k <= p:
        return None
    try:
        inv = np.linalg.inv(bread)
    except np.linalg.LinAlgError:
        return None
    cov = inv @ (sc.T @ sc) @ inv * (k / (k - p))
    dof = k - p
    values = fit_model.config(fit.x[:npar])
    half = fit_model.config(fit.x[:npar],
                        _t95(dof) * np.sqrt(np.maximum(np.diag(cov)[:npar], 0.0)))
    return values, half, k
