"""Choreo trajectories (``.traj``, schema version 3): loaded, checked and sampled.

:func:`load` reads a file Choreo wrote into a :class:`ChoreoTrajectory`: its samples as a
read-only float64 array holding exactly the file's values, its events, splits and the
robot config Choreo planned it with (as a drivekin :class:`~drivekin.RobotConfig`).
:meth:`ChoreoTrajectory.sampleAt` gives the state at any time with choreolib's rules
(constant-acceleration swerve interpolation, the same adaptive Dormand–Prince integrator
for differential drives, 2026's rotate-around flip for the red alliance)::

    import json
    from drivekin import choreo
    # Choreo writes these files; here a 1 s swerve line from rest at 2 m/s², by hand.
    row = {"t": 0.0, "x": 1.0, "y": 1.0, "heading": 0.0, "vx": 0.0, "vy": 0.0,
           "omega": 0.0, "ax": 2.0, "ay": 0.0, "alpha": 0.0, "fx": [30.0] * 4,
           "fy": [0.0] * 4}
    with open("Line.traj", "w") as f:
        json.dump({"name": "Line", "version": 3, "events": [], "trajectory": {
            "sampleType": "Swerve", "config": None, "splits": [0],
            "samples": [row, dict(row, t=1.0, x=2.0, vx=2.0)]}}, f)

    traj = choreo.load("Line.traj")
    start = traj.getInitialPose()              # Pose2d(1, 1, 0)
    s = traj.sampleAt(0.5)                     # s.x == 1.25, s.vx == 1.0, s.getPose()
    red = traj.sampleAt(0.5, mirrorForRedAlliance=True)
    out = traj.newSample()
    traj.sampleInto(0.52, out)                 # the 20 ms loop's form: no allocation
    rows = traj.sampleAtMany([0.0, 0.5, 1.0])  # (3, len(traj.columns)), traj.columns order
    assert s.x == 1.25 and rows[1, 1] == 1.25

The samples :meth:`~ChoreoTrajectory.sampleAt` returns are ``SwerveSample`` or
``DifferentialSample`` (``drivekin.choreo.SwerveSample``, ...): choreolib's fields, with
``t`` for its ``timestamp`` (swerve ``t x y heading vx vy omega ax ay alpha fx fy``, ``fx``
and ``fy`` 4-tuples in Choreo's module order; differential ``t x y heading vl vr omega al
ar alpha fl fr``), ``getPose()`` (a drivekin Pose2d) and ``getChassisVelocities()``, which
returns what choreolib's ``get_chassis_speeds`` does: the field-frame ``(vx, vy, omega)``
for swerve, ``((vl + vr) / 2, 0, omega)`` for differential (along the robot's heading,
though choreolib calls it field-relative). In a robot loop, ``traj.sampleInto(t, out)``
writes into a sample from ``traj.newSample()`` without allocating. Times exactly on a
sample and the last sample's time are integrated from the previous sample, as choreolib
does, so they differ from the stored values by the file's rounding (about 1e-5).

Only version 3 loads: Choreo's own upgrader discards the samples of older files when it
upgrades them, and choreolib 2026 refuses them too, so an older file raises
:class:`ChoreoError` asking to regenerate it in Choreo 2026. A file without samples (a
path Choreo has not generated) raises too.

Bad files raise :class:`ChoreoError` (a ValueError) naming the file and what is wrong, in
time and memory bounded by :data:`MAX_BYTES`: the size is checked before reading, and the
nesting depth is measured by a linear scan before ``json.loads`` (which recurses once per
level) sees the text.
"""
from __future__ import annotations

import json
import math
import os
from typing import Any

import numpy as np

from drivekin._core import choreocheck as _choreocheck
from drivekin._core.choreocheck import FeasibilityRecord, FeasibilityReport
from drivekin._core.choreokernel import (FIELD_SIZE, ChoreoSampler, DifferentialSample,
                                         SwerveSample)
from drivekin._core.metadata import depth
from drivekin.geometry import Pose2d, Rotation2d, Translation2d
from drivekin.motor import DCMotor
from drivekin.robotconfig import ModuleConfig, RobotConfig

__all__ = ["ChoreoError", "ChoreoTrajectory", "DifferentialSample", "FeasibilityRecord",
           "FeasibilityReport", "MAX_BYTES", "SwerveSample", "load"]

# The largest real trajectory is 0.4 MB (1,619 samples, 23 s). The cap bounds memory: the
# densest JSON, "[0.5,0.5,...]", becomes one 32-byte float object per 4 bytes (64 MB).
MAX_BYTES = 8 * 1024 * 1024
MAX_DEPTH = 64                 # events hold PathPlanner command trees; samples need 3

SCHEMA_VERSION = 3
GRAVITY = 9.8                  # m/s², Choreo's (trajoptlib) and PathPlannerLib's

SWERVE_COLUMNS = ("t", "x", "y", "heading", "vx", "vy", "omega", "ax", "ay", "alpha",
                  "fx0", "fx1", "fx2", "fx3", "fy0", "fy1", "fy2", "fy3")
DIFFERENTIAL_COLUMNS = ("t", "x", "y", "heading", "vl", "vr", "omega", "al", "ar", "alpha",
                        "fl", "fr")
_SCALAR_KEYS = {"swerve": SWERVE_COLUMNS[:10], "differential": DIFFERENTIAL_COLUMNS}
_MODULE_ORDER = {"swerve": ("FL", "BL", "BR", "FR"), "differential": ("left", "right")}


class ChoreoError(ValueError):
    """A ``.traj`` file drivekin cannot read: the message names the file and the fault."""


def _finite(value: Any) -> bool:
    """A JSON number that is a finite double (an int too large for one is not)."""
    if type(value) is float:
        return math.isfinite(value)
    return type(value) is int and abs(value) <= 1e308


class _Reader:
    """Validation helpers that name the file in every error."""

    __slots__ = ("path",)

    def __init__(self, path: str):
        self.path = path

    def error(self, what: str) -> ChoreoError:
        return ChoreoError(f"{self.path}: {what}")

    def get(self, obj: Any, key: str, where: str) -> Any:
        if not isinstance(obj, dict):
            raise self.error(f"{where} must be a JSON object, got {_kind(obj)}")
        if key not in obj:
            raise self.error(f"{where} has no {key!r}")
        return obj[key]

    def finite(self, obj: Any, key: str, where: str) -> float:
        value = self.get(obj, key, where)
        if not _finite(value):
            raise self.error(f"{where}.{key} must be a finite number, got {value!r:.40}")
        return float(value)

    def positive(self, obj: Any, key: str, where: str) -> float:
        value = self.finite(obj, key, where)
        if not value > 0.0:
            raise self.error(f"{where}.{key} must be positive, got {value!r}")
        return value


def _kind(value: Any) -> str:
    return {dict: "an object", list: "an array", str: "a string", bool: "a boolean",
            type(None): "null"}.get(type(value), "a number")


def _read_text(path: str) -> str:
    try:
        with open(path, "rb") as f:
            data = f.read(MAX_BYTES + 1)
    except OSError as e:
        raise ChoreoError(f"{path}: cannot be read ({e.strerror or e})") from None
    if len(data) > MAX_BYTES:
        raise ChoreoError(f"{path}: larger than {MAX_BYTES} bytes; a Choreo trajectory is "
                          f"a few MB at most")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise ChoreoError(f"{path}: not UTF-8 text (byte {e.start}); is it a .traj "
                          f"file?") from None


def _reject_constant(name: str) -> float:
    raise ValueError(f"{name} is not a JSON number")


def _parse(path: str) -> dict[str, Any]:
    text = _read_text(path)
    if depth(text) > MAX_DEPTH:
        raise ChoreoError(f"{path}: JSON nested deeper than {MAX_DEPTH} levels; not a "
                          f"Choreo trajectory")
    try:
        data = json.loads(text, parse_constant=_reject_constant)
    except ValueError as e:
        raise ChoreoError(f"{path}: not valid JSON ({e})") from None
    if not isinstance(data, dict):
        raise ChoreoError(f"{path}: the top level must be a JSON object, got {_kind(data)}")
    return data


def _samples(r: _Reader, raw: Any, kind: str) -> np.ndarray:
    if not isinstance(raw, list):
        raise r.error(f"trajectory.samples must be an array, got {_kind(raw)}")
    if not raw:
        raise r.error("trajectory.samples is empty: generate the trajectory in Choreo")
    keys = _SCALAR_KEYS[kind]
    width = 18 if kind == "swerve" else 12
    out = np.empty((len(raw), width))
    row = [0.0] * width
    for k, s in enumerate(raw):
        if not isinstance(s, dict):
            raise r.error(f"trajectory.samples[{k}] must be an object, got {_kind(s)}")
        for j, key in enumerate(keys):
            if key not in s:
                raise r.error(f"trajectory.samples[{k}] has no {key!r}")
            v = s[key]
            if not _finite(v):
                raise r.error(f"trajectory.samples[{k}].{key} must be a finite number, "
                              f"got {v!r:.40}")
            row[j] = v
        if kind == "swerve":
            for j, key in ((10, "fx"), (14, "fy")):
                f = s.get(key)
                if not isinstance(f, list) or len(f) != 4:
                    raise r.error(f"trajectory.samples[{k}].{key} must be an array of 4 "
                                  f"module forces, got {f!r:.60}")
                for i, v in enumerate(f):
                    if not _finite(v):
                        raise r.error(f"trajectory.samples[{k}].{key}[{i}] must be a "
                                      f"finite number, got {v!r:.40}")
                    row[j + i] = v
        out[k] = row
    problem = _rows_problem(out)
    if problem:
        raise r.error(problem)
    out.flags.writeable = False
    return out


def _rows_problem(rows: np.ndarray) -> str | None:
    """What makes a float64 sample array (n, w) no trajectory: a value that is not finite,
    or sample times that do not increase (sampling's binary search needs them sorted)."""
    bad = np.flatnonzero(~np.isfinite(rows).all(axis=1))
    if bad.size:
        return f"samples[{int(bad[0])}] holds a value that is not finite"
    t = rows[:, 0]
    bad = np.flatnonzero(np.diff(t) <= 0.0)
    if bad.size:
        k = int(bad[0]) + 1
        return (f"sample times must increase: samples[{k}].t = {float(t[k])!r} after "
                f"{float(t[k - 1])!r}")
    return None


def _splits(r: _Reader, raw: Any, n: int) -> tuple[int, ...]:
    if not isinstance(raw, list):
        raise r.error(f"trajectory.splits must be an array, got {_kind(raw)}")
    splits = []
    for i, v in enumerate(raw):
        if type(v) is not int or not 0 <= v < n:
            raise r.error(f"trajectory.splits[{i}] must be a sample index from 0 to {n - 1}, "
                          f"got {v!r:.40}")
        splits.append(v)
    if not splits or splits[0] != 0:     # choreolib: 0 is always the first split
        splits.insert(0, 0)
    return tuple(splits)


def _events(r: _Reader, raw: Any) -> list[tuple[float, str]]:
    """choreolib's rules: time = targetTimestamp + offset.val; dropped when either is null,
    the name is not a string (choreolib's len() raises TypeError, which it catches), the
    time is negative or the name empty; a missing key is an error."""
    if not isinstance(raw, list):
        raise r.error(f"events must be an array, got {_kind(raw)}")
    events = []
    for i, e in enumerate(raw):
        where = f"events[{i}]"
        source = r.get(e, "from", where)
        offset = r.get(r.get(source, "offset", where + ".from"), "val", where + ".from.offset")
        target = r.get(source, "targetTimestamp", where + ".from")
        name = r.get(e, "name", where)
        if offset is None or target is None or not isinstance(name, str):
            continue
        for key, v in (("from.offset.val", offset), ("from.targetTimestamp", target)):
            if not _finite(v):
                raise r.error(f"{where}.{key} must be a finite number or null, got {v!r:.40}")
        time = float(target) + float(offset)
        if time < 0.0 or not name:
            continue
        events.append((time, name))
    return events


#: The embedded robot's motor turns freely at vmax / FREE_SPEED_FRACTION (Choreo's docs:
#: "Motor Max Speed" is about 80 % of the free speed).
FREE_SPEED_FRACTION = 0.8


def _config(r: _Reader, raw: Any, kind: str) -> RobotConfig | None:
    if raw is None:
        return None
    w = "trajectory.config"
    mass = r.positive(raw, "mass", w)
    inertia = r.positive(raw, "inertia", w)
    gearing = r.positive(raw, "gearing", w)
    radius = r.positive(raw, "radius", w)
    vmax = r.positive(raw, "vmax", w)
    tmax = r.positive(raw, "tmax", w)
    cof = r.positive(raw, "cof", w)
    if kind == "swerve":
        fl = r.get(raw, "frontLeft", w)
        bl = r.get(raw, "backLeft", w)
        flx, fly = r.finite(fl, "x", w + ".frontLeft"), r.finite(fl, "y", w + ".frontLeft")
        blx, bly = r.finite(bl, "x", w + ".backLeft"), r.finite(bl, "y", w + ".backLeft")
        # Choreo's module_translations(): the force columns' order.
        offsets = [Translation2d(flx, fly), Translation2d(blx, bly),
                   Translation2d(blx, -bly), Translation2d(flx, -fly)]
    else:
        half = 0.5 * r.positive(raw, "differentialTrackWidth", w)
        offsets = [Translation2d(0.0, half), Translation2d(0.0, -half)]
    # Choreo names no motor: Kraken X60s (enough of them for tmax) behind the file's
    # gearing, current-limited so that their low-speed torque is exactly Choreo's tmax,
    # turning freely at vmax / 0.8: Choreo's guidance is that "Motor Max Speed" is about
    # 80 % of the free speed, and a free speed of vmax itself leaves no torque at the top
    # speed Choreo plans to (its own default robot would be infeasible).
    try:
        kraken = DCMotor.getKrakenX60()
        motor = DCMotor(kraken.nominalVoltage, kraken.stallTorque, kraken.stallCurrent,
                        kraken.freeCurrent, vmax / FREE_SPEED_FRACTION,
                        math.floor(tmax / kraken.stallTorque) + 1)
        limit = tmax / motor.Kt
        module = ModuleConfig(radius, radius * vmax / gearing, cof,
                              motor.withReduction(gearing), limit)
        return RobotConfig(mass, inertia, module, offsets)
    except ValueError as e:
        raise r.error(f"{w} is not a usable robot: {e}") from None


class ChoreoTrajectory(ChoreoSampler):
    """A Choreo trajectory as :func:`load` read it (immutable).

    ``samples`` holds one row per sample in ``columns`` order, exactly the file's values:
    swerve ``t x y heading vx vy omega ax ay alpha fx0..fx3 fy0..fy3`` (velocities,
    accelerations and forces in the field frame; the forces in ``moduleOrder``, which is
    Choreo's FL, BL, BR, FR and not the FL, FR, BL, BR choreolib documents), differential
    ``t x y heading vl vr omega al ar alpha fl fr``.

    ``config`` is the robot Choreo planned with, as a drivekin RobotConfig, or None when
    the file carries none. Choreo names no motor, so drivekin picks one: Kraken X60
    motors (one, or as many as a torque above 7.09 N·m needs; a Kraken's stall torque,
    stall and free current) behind the file's ``gearing``, with a free speed of
    ``vmax / 0.8`` (Choreo's guidance: its "Motor Max Speed" is about 80 % of the free
    speed) and a current limit ``tmax / Kt`` so that the low-speed wheel torque
    ``min(stallTorque, getTorque(limit))`` equals Choreo's ``tmax · gearing``; wheel
    radius and ``cof`` as given, ``maxDriveVelocityMPS = radius · vmax / gearing``; the
    modules in the force columns' order (FL, BL, BR, FR; differential: left at
    (0, +track/2), right at (0, −track/2)).
    """

    __slots__ = ("_name", "_kind", "_samples", "_events", "_splits", "_config", "_path")

    def __init__(self, name: str, kind: str, samples: np.ndarray,
                 events: list[tuple[float, str]], splits: tuple[int, ...],
                 config: RobotConfig | None, path: str = "<memory>"):
        if kind not in _MODULE_ORDER:
            raise ValueError(f"kind must be 'swerve' or 'differential', got {kind!r}")
        self._name = name
        self._kind = kind
        rows = self._bind(samples, kind == "swerve")
        problem = _rows_problem(rows)
        if problem:
            raise ValueError(problem)
        self._samples = rows
        self._events = events
        self._splits = splits
        self._config = config
        self._path = path

    def __repr__(self) -> str:
        return (f"ChoreoTrajectory({self._name!r}, {self._kind}, {len(self._samples)} "
                f"samples, {self.totalTime:g} s)")

    def __reduce__(self) -> tuple[Any, ...]:
        return (ChoreoTrajectory, (self._name, self._kind, self._samples,
                                   self._events, self._splits, self._config, self._path))

    @property
    def name(self) -> str:
        """The trajectory's name (the file name without ``.traj``)."""
        return self._name

    @property
    def kind(self) -> str:
        """``"swerve"`` or ``"differential"``."""
        return self._kind

    @property
    def samples(self) -> np.ndarray:
        """The samples, float64 (n, len(columns)), read-only, exactly the file's values."""
        return self._samples

    @property
    def columns(self) -> tuple[str, ...]:
        """The names of ``samples``' columns."""
        return SWERVE_COLUMNS if self._kind == "swerve" else DIFFERENTIAL_COLUMNS

    @property
    def times(self) -> np.ndarray:
        """The sample times, s (a read-only view of ``samples[:, 0]``)."""
        return self._samples[:, 0]

    @property
    def events(self) -> list[tuple[float, str]]:
        """The event markers as (time s, name), by choreolib's rules (a copy)."""
        return list(self._events)

    @property
    def splits(self) -> tuple[int, ...]:
        """Indices of the samples that start each split, 0 first (choreolib's rule)."""
        return self._splits

    @property
    def config(self) -> RobotConfig | None:
        """The embedded robot config as a drivekin RobotConfig (see the class), or None."""
        return self._config

    @property
    def moduleOrder(self) -> tuple[str, ...]:
        """The order of the force columns as Choreo writes them: ``("FL", "BL", "BR",
        "FR")`` for swerve, ``("left", "right")`` for differential."""
        return _MODULE_ORDER[self._kind]

    @property
    def totalTime(self) -> float:
        """The last sample's time, s."""
        return float(self._samples[-1, 0])

    def getInitialPose(self, mirrorForRedAlliance: bool = False) -> Pose2d:
        """The first sample's pose (flipped for the red alliance if asked)."""
        return self._pose(0, mirrorForRedAlliance)

    def getFinalPose(self, mirrorForRedAlliance: bool = False) -> Pose2d:
        """The last sample's pose (flipped for the red alliance if asked)."""
        return self._pose(len(self._samples) - 1, mirrorForRedAlliance)

    def _pose(self, k: int, flip: bool) -> Pose2d:
        x, y, heading = (float(v) for v in self._samples[k, 1:4])
        if flip:
            x, y, heading = FIELD_SIZE[0] - x, FIELD_SIZE[1] - y, math.pi + heading
        return Pose2d(x, y, Rotation2d(heading))

    # -- Feasibility and feedforward (drivekin._core.choreocheck) --------------------------

    def check(self, config: RobotConfig | None = None, *, maxSteerVelocity: float | None = None,
              voltage: float = 12.0) -> FeasibilityReport:
        """Check the samples against a robot's real limits (default: the embedded config):
        per sample and module, the module speed against ``maxDriveVelocityMPS`` and the
        motor's free speed at ``voltage``; the drive torque (the force along the wheel
        times the radius) against the motor's torque–speed curve at ``voltage`` and the
        current limit; the force against friction μ·m·g/N; with ``maxSteerVelocity``
        (rad/s), the steering rate between samples k−1 and k, reported at k (modulo π: a
        module may reverse its drive instead of turning half a turn; modules under 1 cm/s
        skipped); and, per sample, the torque balance Σ rᵢ×Fᵢ = J·α with the forces on
        the modules in ``moduleOrder`` (the embedded config's MOI and positions). The
        config's modules are matched to the force columns by position (one per corner).
        Comparisons allow the file's 5-decimal rounding. Returns a
        :class:`FeasibilityReport`; ValueError for a bad ``voltage`` or
        ``maxSteerVelocity``, a config whose modules do not sit one on each corner, or no
        config at all; TypeError for a config that is not a RobotConfig."""
        config = self._require_config(config)
        return _choreocheck.check(self._samples, self._kind, config,
                                  self._config if self._config is not None else config,
                                  maxSteerVelocity=maxSteerVelocity, voltage=voltage)

    def moduleSetpoints(self, config: RobotConfig | None = None) -> dict[str, np.ndarray]:
        """The feedforward per sample and module (arrays samples × modules, the config's
        module order, default the embedded config): ``speed`` (m/s ≥ 0), ``angle`` (rad,
        robot frame; a stopped module keeps its angle), ``acceleration`` (the contact
        point's, along the wheel, m/s²) and ``current`` (A,
        ``driveMotor.getCurrent(torque=(F·wheel direction)·radius)``)."""
        return _choreocheck.moduleSetpoints(self._samples, self._kind,
                                            self._require_config(config))

    def _require_config(self, config: RobotConfig | None) -> RobotConfig:
        if config is None:
            if self._config is None:
                raise ValueError(f"{self._path}: the trajectory carries no robot config; "
                                 f"pass config=RobotConfig(...)")
            return self._config
        if not isinstance(config, RobotConfig):
            raise TypeError(f"config must be a drivekin RobotConfig or None, got "
                            f"{type(config).__name__}")
        return config


def load(path: str | os.PathLike[str]) -> ChoreoTrajectory:
    """Read a Choreo ``.traj`` file (schema version 3) into a :class:`ChoreoTrajectory`.

    Raises :class:`ChoreoError` (a ValueError) naming the file and the fault: unreadable,
    larger than MAX_BYTES, not JSON, another schema version, missing or mistyped keys,
    non-finite numbers, sample times that do not increase, no samples."""
    path = os.fspath(path)
    if not isinstance(path, str):
        raise TypeError(f"path must be a str or os.PathLike[str], got {type(path).__name__}")
    data = _parse(path)
    r = _Reader(path)
    version = r.get(data, "version", "the file")
    if type(version) is not int or version != SCHEMA_VERSION:
        raise r.error(f"schema version {version!r:.40}; drivekin reads version "
                      f"{SCHEMA_VERSION} (Choreo 2026): open and regenerate it in Choreo")
    name = r.get(data, "name", "the file")
    if not isinstance(name, str):
        raise r.error(f"name must be a string, got {_kind(name)}")
    traj = r.get(data, "trajectory", "the file")
    sample_type = r.get(traj, "sampleType", "trajectory")
    kinds = {"Swerve": "swerve", "Differential": "differential"}
    if not isinstance(sample_type, str) or sample_type not in kinds:
        raise r.error(f"trajectory.sampleType must be \"Swerve\" or \"Differential\", got "
                      f"{sample_type!r:.40}")
    kind = kinds[sample_type]
    samples = _samples(r, r.get(traj, "samples", "trajectory"), kind)
    splits = _splits(r, r.get(traj, "splits", "trajectory"), len(samples))
    events = _events(r, r.get(data, "events", "the file"))
    config = _config(r, traj.get("config"), kind)
    return ChoreoTrajectory(name, kind, samples, events, splits, config, path)
