"""Swerve modules logged one entry per module under a team's or a library's own names:
YAGSL's telemetry, WPILib SysId routine logs, module entries named on the command line
(``--module-entries``) and module *velocity* states, which a replay integrates where a
log holds no distances (rule in :func:`integral_at`).

Builds on the primitives of :mod:`drivekin._core.loglayouts`, whose ``LAYOUTS`` table
lists the finders here.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from drivekin._core import loglayouts as L
from drivekin._core.loglayouts import Options, Signal, fold
from drivekin.datalog import DataLogError, EntryInfo, LogData

#: An interval between velocity records this many median intervals long is a writer
#: publishing on change only (NetworkTables): the earlier value held, see integral_at.
HELD_GAP = 3.0
_INCH = 0.0254


# --------------------------------------------------------------------------------------
# Velocity states → distances

def integral_at(t: np.ndarray, v: np.ndarray, at: np.ndarray) -> np.ndarray:
    """The distance (0 at the first record) at times ``at`` (µs, none before ``t[0]``)
    of a velocity logged as records ``(t µs, v per s)``.

    The rule: the velocity is linear between consecutive records (trapezoidal
    integration), and held after the last one. Across an interval longer than
    ``HELD_GAP`` median intervals (a writer that publishes a value only when it changes)
    the earlier value is held until one median interval before the later record, then
    linear. The error of a trapezoid over one interval h is h³·|a'|/12 for a jerk a' of the
    wheel speed, so the distance error grows linearly with time at h²·|a'|/12 per second
    (2e-5 m/s for 50 Hz records and 6 m/s³), plus whatever the writer's sampling hides.
    ``v`` may be (N, k): k velocities on the same records, integrated column by column.
    """
    ts = t.astype(np.float64) / 1e6
    vs = np.asarray(v, dtype=np.float64)
    dt = np.diff(ts)
    if len(dt):
        pos = dt[dt > 0]
        period = float(np.median(pos)) if len(pos) else 0.0
        gap = np.flatnonzero(dt > HELD_GAP * period) if period > 0 else np.array([], int)
        if len(gap):
            ts = np.insert(ts, gap + 1, ts[gap + 1] - period)
            vs = np.insert(vs, gap + 1, vs[gap], axis=0)
    h = np.diff(ts)
    if vs.ndim == 2:
        h = h[:, None]
    cum = np.concatenate([np.zeros((1,) + vs.shape[1:]),
                          np.cumsum(0.5 * (vs[1:] + vs[:-1]) * h, axis=0)])
    q = at.astype(np.float64) / 1e6
    j = np.clip(np.searchsorted(ts, q, side="right") - 1, 0, len(ts) - 1)
    nxt = np.minimum(j + 1, len(ts) - 1)
    dq, span = q - ts[j], ts[nxt] - ts[j]
    if vs.ndim == 2:
        dq, span = dq[:, None], span[:, None]
    slope = np.divide(vs[nxt] - vs[j], span, out=np.zeros(vs[j].shape), where=span > 0)
    return cum[j] + vs[j] * dq + 0.5 * slope * dq * dq


# --------------------------------------------------------------------------------------
# One entry per module


@dataclass
class ModuleInput:
    """One module's drive and angle entries, with the factors to m (m/s) and rad."""

    label: str
    drive: EntryInfo
    angle: EntryInfo
    driveScale: float
    velocity: bool
    angleScale: float
    units: str


def module_input(label: str, drive: EntryInfo, angle: EntryInfo, units: Options,
                 drive_suffix: str = "", angle_suffix: str = "", *,
                 velocity: bool | None = None, drive_unit: str | None = None,
                 angle_unit: str | None = None) -> ModuleInput:
    """A module's inputs, their units from (in order) the options, the names' suffixes,
    the metadata, then ``drive_unit``/``angle_unit`` (a layout's own convention). A
    drive entry is a velocity when ``velocity`` says so, its name says velocity or speed,
    its metadata unit is a speed, or ``--drive-units`` is one."""
    leaf = fold(drive.name.rpartition("/")[2])
    if velocity is None:
        velocity = bool((units.drive or "").endswith("/s")
                        or L.split_velocity(leaf) is not None
                        or any(w in leaf for w in ("velocity", "speed"))
                        or L.is_speed_metadata(drive.metadata))
    if not drive_suffix:
        drive_suffix = L.unit_suffix(leaf)
    unit = (L.speed_unit_of(drive_suffix, drive.metadata) if velocity
            else L.unit_of(drive_suffix, drive.metadata)) or drive_unit
    dscale, dunits = L._drive_scale(unit, drive.name, units)
    if velocity:
        dunits = dunits.replace("drive ", "drive velocity ", 1).replace(" (", "/s (", 1)
    aleaf = fold(angle.name.rpartition("/")[2])
    if not angle_suffix:
        angle_suffix = next((u for u in ("degrees", "deg", "radians", "rad", "rotations")
                             if aleaf.endswith(u) and len(aleaf) > len(u)), "")
    aunit = L.unit_of(angle_suffix, angle.metadata) or angle_unit
    tscale, tunits = L._turn_scale(aunit, angle.name, units,
                                   angle.type == "struct:Rotation2d")
    return ModuleInput(label, drive, angle, dscale, velocity, tscale, f"{dunits}; {tunits}")


def module_signal(log: LogData, mods: list[ModuleInput], layout: str, why: str,
                  offsets: tuple[tuple[float, float], ...] | None = None,
                  offsets_from: str = "") -> Signal:
    """Swerve positions (N, M, 2) from one drive and one angle entry per module, on one
    timeline: the cycle clock (/Timestamp) when the log has one, else every time any
    of them was logged, from when all have a value. Angles and logged distances are
    held (latest record at or before); velocities are integrated (:func:`integral_at`)."""
    where = ", ".join(m.label for m in mods)
    series = []
    for m in mods:
        for info in (m.drive, m.angle):
            if info.type not in ("double", "float") and not (
                    info is m.angle and info.type == "struct:Rotation2d"):
                raise DataLogError(f"module {m.label}: {info.name!r} has type {info.type}; "
                                   f"expected a double")
            if info.records == 0:
                raise DataLogError(f"module {m.label}: {info.name!r} has no records")
        series.append((log.values(m.drive.name), log.values(m.angle.name)))
    clock = L._cycle_clock(log)
    if clock is None:
        clock = batches(np.concatenate([ts for pair in series for ts, _ in pair]))
    start = max(int(ts[0]) for pair in series for ts, _ in pair)
    t = clock[clock >= start]
    if len(t) == 0:
        raise DataLogError(f"modules {where}: their entries never all have a value")
    dist, ang = [], []
    for m, ((td, vd), (ta, va)) in zip(mods, series):
        if m.velocity:
            dist.append(integral_at(td, vd * m.driveScale, t))
        else:
            dist.append(vd[np.searchsorted(td, t, side="right") - 1] * m.driveScale)
        ang.append(va[np.searchsorted(ta, t, side="right") - 1] * m.angleScale)
    P = np.stack([np.stack(dist, axis=1), np.stack(ang, axis=1)], axis=2)
    names = tuple(n for m in mods for n in (m.drive.name, m.angle.name))
    integrated = any(m.velocity for m in mods)
    return Signal("positions", t, P, names, layout, "swerve", mods[0].units, why=why,
                  integrated=integrated, offsets=offsets, offsetsFrom=offsets_from,
                  batched=L._cycle_clock(log) is None)


#: Records of different entries closer than this are one batch (µs): a robot cycle's
#: values as NetworkTables' mirror (or a program writing SysId records, then publishing)
#: stamps them, well under the shortest robot loop (10 ms).
BATCH_US = 5000


def batches(t: np.ndarray) -> np.ndarray:
    """The sample times of records that come in batches: each run of records under
    ``BATCH_US`` apart is one sample, at its last record, when every value of the batch
    is known."""
    u = np.unique(t)
    if len(u) < 2:
        return u
    return u[np.concatenate([np.diff(u) >= BATCH_US, [True]])]


def batch_ends(t: np.ndarray):  # type: ignore[no-untyped-def]
    """A function taking record times to the end of their batch among the times ``t``."""
    ends = batches(t)

    def snap(x: np.ndarray) -> np.ndarray:
        k = np.minimum(np.searchsorted(ends, x, side="left"), len(ends) - 1)
        return ends[k]
    return snap


def corner_order(labels: list[str]) -> list[int] | None:
    """Indices putting module labels in the order FL, FR, BL, BR (numbered labels: by
    number), or None when they are neither four distinct corners nor numbered."""
    keys = [(0, int(lb)) if lb.strip().isdigit() and len(lb) < 4 else L._module_index(lb)
            for lb in labels]
    if any(k is None for k in keys) or len({k for k in keys}) != len(keys):
        return None
    if len({k[0] for k in keys if k}) != 1:
        return None
    return sorted(range(len(labels)), key=lambda i: keys[i][1])  # type: ignore[index]


def missing_corners(labels: list[str]) -> str:
    """'no back-left module' style text for corner-named modules short of four."""
    have = {k[1] for k in (L._module_index(lb) for lb in labels) if k and k[0] == 1}
    gone = [L.CORNER_NAMES[i] for i in range(4) if i not in have]
    return ", ".join(f"no {c} module" for c in gone)


# --------------------------------------------------------------------------------------
# --module-entries

def _fill(pattern: str, value: str) -> str:
    return fold(L.bare(pattern.replace("{module}", value)))


def _placeholder_values(log: LogData, pattern: str) -> list[str]:
    """Every value of ``{module}`` that turns ``pattern`` into an entry of the log, in
    the order the entries first appear (no regular expressions: a linear scan per name)."""
    head, _, rest = pattern.partition("{module}")
    tail = rest.partition("{module}")[0]
    fhead = fold(L.bare(head))
    out: list[str] = []
    for e in log.entries.values():
        name = L.bare(e.name)
        # the value sits between the literal head and the next literal part, both folded
        # as names are, so compare on the folded name and cut the original by position
        if not fold(name).startswith(fhead):
            continue
        k = _cut(name, len(fhead))
        end = name.find(tail, k) if tail else len(name)
        while end != -1 and end > k:
            value = name[k:end]
            if _fill(pattern, value) == fold(name) and value not in out:
                out.append(value)
                break
            end = name.find(tail, end + 1) if tail else -1
    return out


def _cut(name: str, folded_len: int) -> int:
    """The index in ``name`` after its first ``folded_len`` folded characters."""
    n = 0
    for i, ch in enumerate(name):
        if n == folded_len:
            return i
        if ch not in "_ -":
            n += 1
    return len(name)


def named_modules(log: LogData, specs: list[str], units: Options) -> Signal:
    """The positions of ``--module-entries`` (see docs/logs-and-replay.md)."""
    pairs: list[tuple[str, str, str]] = []
    for spec in specs:
        label, eq, entries = spec.partition("=")
        if not eq:
            label, entries = "", spec
        drive, comma, angle = entries.rpartition(",")
        if not comma or not drive or not angle:
            raise DataLogError(f"--module-entries {spec!r}: expected NAME=DRIVE_ENTRY,"
                               f"ANGLE_ENTRY or DRIVE_ENTRY,ANGLE_ENTRY with {{module}}")
        pairs.append((label.strip(), drive.strip(), angle.strip()))
    templated = [p for p in pairs if "{module}" in p[1] or "{module}" in p[2]]
    if templated:
        if len(pairs) != 1 or not all("{module}" in x for x in pairs[0][1:]):
            raise DataLogError("--module-entries with {module} is given once, with the "
                               "placeholder in both the drive and the angle entry")
        _, dpat, apat = pairs[0]
        values = [v for v in _placeholder_values(log, dpat)
                  if v in _placeholder_values(log, apat)]
        if len(values) < 2:
            raise DataLogError(f"--module-entries {dpat!r},{apat!r}: {len(values)} module "
                               f"name(s) fill both entries in this log; a swerve has at "
                               f"least 2 (--list shows the entries)")
        order = corner_order(values)
        if order is None:
            raise DataLogError(f"--module-entries: the modules {', '.join(values)} are "
                               f"neither corners (FL, front left, ...) nor numbered; give "
                               f"them in order as NAME=DRIVE,ANGLE once per module")
        pairs = [(values[i], dpat.replace("{module}", values[i]),
                  apat.replace("{module}", values[i])) for i in order]
    mods = []
    for k, (label, drive, angle) in enumerate(pairs):
        label = label or f"module {k}"
        d = L.resolve(log, drive, f"--module-entries {label}: drive entry")
        a = L.resolve(log, angle, f"--module-entries {label}: angle entry")
        mods.append(module_input(label, d, a, units))
    labels = ", ".join(m.label for m in mods)
    return module_signal(log, mods, "--module-entries", f"named with --module-entries "
                         f"({labels})")


# --------------------------------------------------------------------------------------
# YAGSL telemetry

_YAGSL_DRIVE = "rawdriveencoder"
_YAGSL_ANGLE = "adjustedabsoluteencoder"


def _yagsl_groups(log: LogData) -> dict[str, dict[str, dict[str, EntryInfo]]]:
    """prefix (up to ``swerve``) -> module name -> {"drive"|"angle": entry}, modules in
    the order their entries first appear (YAGSL publishes them in its module order)."""
    groups: dict[str, dict[str, dict[str, EntryInfo]]] = {}
    for e in L._live(log):
        parts = e.name.split("/")
        if len(parts) < 4 or fold(parts[-3]) != "modules" or fold(parts[-4]) != "swerve":
            continue
        leaf = fold(parts[-1])
        role = {_YAGSL_DRIVE: "drive", _YAGSL_ANGLE: "angle"}.get(leaf)
        if role is not None:
            prefix = "/".join(parts[:-3])
            groups.setdefault(prefix, {}).setdefault(parts[-2], {})[role] = e
    return groups


def _yagsl_offsets(log: LogData, prefix: str, count: int
                   ) -> tuple[tuple[tuple[float, float], ...] | None, str]:
    for leaf in ("wheelLocations", "wheelLocation"):
        info = log.entries.get(f"{prefix}/{leaf}")
        if info is not None and info.records and info.type == "double[]":
            v = log.values(info.name, ragged="drop")[1][-1]
            if len(v) == 2 * count and np.isfinite(v).all():
                return (tuple((float(v[2 * j]) * _INCH, float(v[2 * j + 1]) * _INCH)
                              for j in range(count)),
                        f"{info.name} (inches, as YAGSL used them)")
    return None, ""


def find_yagsl_positions(log: LogData, units: Options) -> list[Signal]:
    out = []
    for prefix, modules in _yagsl_groups(log).items():
        labels = [n for n, roles in modules.items() if len(roles) == 2]
        if len(labels) < 2:
            continue
        order = corner_order(labels)
        ordered = [labels[i] for i in order] if order is not None else labels
        mods = [module_input(n, modules[n]["drive"], modules[n]["angle"], units,
                             velocity=False, drive_unit="m", angle_unit="deg")
                for n in ordered]
        offsets, src = _yagsl_offsets(log, prefix, len(mods))
        out.append(module_signal(log, mods, "YAGSL telemetry",
                                 f"YAGSL's odometry inputs ({', '.join(ordered)})",
                                 offsets, src))
    return out


# --------------------------------------------------------------------------------------
# WPILib SysId routine logs: position-<motor>, velocity-<motor>, voltage-<motor>

def _sysid_positions(log: LogData) -> dict[str, list[tuple[int, str, EntryInfo]]]:
    """Subsystem -> (corner index, label, entry) of each ``position-<motor>`` entry
    whose motor name holds a corner."""
    out: dict[str, list[tuple[int, str, EntryInfo]]] = {}
    for e in L._live(log):
        if not e.name.startswith("position-") or e.type not in ("double", "float"):
            continue
        parts = e.name[len("position-"):].split("-")
        hits = [(j, L._module_index(p)) for j, p in enumerate(parts)]
        corner = [(j, k) for j, k in hits if k is not None and k[0] == 1]
        if len(corner) != 1:
            continue
        j, (_, idx) = corner[0]
        rest = "-".join(parts[:j] + ["*"] + parts[j + 1:])
        out.setdefault(rest, []).append((idx, parts[j], e))
    return out


def _module_angles(log: LogData) -> dict[int, EntryInfo]:
    """Corner index -> the robot's module angle entry (YAGSL's, else per-module turn
    entries named by corner)."""
    angles: dict[int, EntryInfo] = {}
    for modules in _yagsl_groups(log).values():
        for name, roles in modules.items():
            k = L._module_index(name)
            if k is not None and k[0] == 1 and "angle" in roles:
                angles.setdefault(k[1], roles["angle"])
    for (_, kind), mods in L._module_groups(log).items():
        if kind == 1:
            for idx, mod in mods.items():
                if "turn" in mod.entries:
                    angles.setdefault(idx, mod.entries["turn"][0])
    return angles


def find_sysid_positions(log: LogData, units: Options) -> list[Signal]:
    out = []
    angles = None
    for motor, found in _sysid_positions(log).items():
        found.sort(key=lambda f: f[0])
        if len(found) < 2 or len({f[0] for f in found}) != len(found):
            continue
        angles = _module_angles(log) if angles is None else angles
        if not all(idx in angles for idx, _, _ in found):
            continue
        mods = [module_input(label, e, angles[idx], units, velocity=False,
                             angle_unit="deg") for idx, label, e in found]
        offsets, src = _corner_offsets(log, [idx for idx, _, _ in found])
        out.append(module_signal(log, mods, "SysId routine",
                                 f"SysId's wheel distances (position-{motor}) with the "
                                 f"module angles", offsets, src))
    return out


def _corner_offsets(log: LogData, corners: list[int]
                    ) -> tuple[tuple[tuple[float, float], ...] | None, str]:
    """The module offsets YAGSL published for these corners (the robot a SysId session
    ran on), or (None, "")."""
    for prefix, modules in _yagsl_groups(log).items():
        names = list(modules)
        offsets, src = _yagsl_offsets(log, prefix, len(names))
        keys = [L._module_index(n) for n in names]
        if offsets is None or any(k is None or k[0] != 1 for k in keys):
            continue
        at = {k[1]: xy for k, xy in zip(keys, offsets) if k is not None}
        if all(c in at for c in corners):
            return tuple(at[c] for c in corners), src
    return None, ""


# --------------------------------------------------------------------------------------
# Module velocity states

_NOT_MEASURED = ("desired", "target", "setpoint", "goal", "commanded", "requested")


def _measured(name: str) -> bool:
    f = fold(name)
    return not any(w in f for w in _NOT_MEASURED) and not name.startswith(L.REPLAY_PREFIX)


def find_state_velocities(log: LogData, units: Options) -> list[Signal]:
    """Velocity states: per-module velocity and angle entries (``Module 1/Drive Velocity
    Feet`` with ``Steer Degrees``) and ``struct:SwerveModuleState[]`` measured states."""
    out = []
    for (prefix, _), mods in L._module_groups(log).items():
        order = sorted(mods)
        if len(order) < 2 or order != list(range(order[0], order[0] + len(order))):
            continue
        if not all("velocity" in mods[i].entries and "turn" in mods[i].entries
                   for i in order) or any("drive" in mods[i].entries for i in order):
            continue
        inputs = []
        for i in order:
            (vi, vsuf), (ti, tsuf) = mods[i].entries["velocity"], mods[i].entries["turn"]
            inputs.append(module_input(f"module {i}", vi, ti, units, vsuf, tsuf,
                                       velocity=True))
        out.append(module_signal(log, inputs, "module velocity states",
                                 f"integrated from velocity states under {prefix or '/'}"))
    for e in L._live(log):
        if e.type == "struct:SwerveModuleState[]" and _measured(e.name):
            out.extend(_state_array(log, e, units))
    return out


def _state_array(log: LogData, e: EntryInfo, units: Options) -> list[Signal]:
    try:
        t, v = log.values(e.name)
    except DataLogError:
        return []                       # ragged: not one robot's modules
    if v.ndim != 3 or v.shape[1] < 2 or len(t) < 2:
        return []
    P = np.empty_like(v)
    P[:, :, 0] = integral_at(t, v[:, :, 0], t)
    P[:, :, 1] = v[:, :, 1]
    return [Signal("positions", t, P, (e.name,), "module velocity states", "swerve",
                   "speed m/s, angle rad (SwerveModuleState)", integrated=True,
                   why="integrated from measured module states")]


def find_corner_states(log: LogData, units: Options) -> list[Signal]:
    """One struct:SwerveModuleState entry per corner, beside each other."""
    groups: dict[str, dict[int, EntryInfo]] = {}
    for e in L._live(log):
        if e.type != "struct:SwerveModuleState" or not _measured(e.name):
            continue
        head, _, leaf = e.name.rpartition("/")
        f = fold(leaf)
        for corner, idx in L._CORNERS.items():
            if len(corner) > 2 and corner in f:
                groups.setdefault(head + "/" + f.replace(corner, "*"), {})[idx] = e
                break
    out, lacking = [], []
    for corners in groups.values():
        if len(corners) < 4:
            if len(corners) >= 2:
                names = ", ".join(e.name for _, e in sorted(corners.items()))
                labels = [L.CORNER_NAMES[i] for i in corners]
                lacking.append(f"module states {names}: {missing_corners(labels)}")
            continue
        series = [log.values(corners[i].name) for i in range(4)]
        start = max(int(ts[0]) for ts, _ in series)
        t = batches(np.concatenate([ts for ts, _ in series]))
        t = t[t >= start]
        P = np.empty((len(t), 4, 2))
        for j, (ts, v) in enumerate(series):
            P[:, j, 0] = integral_at(ts, v[:, 0], t)
            P[:, j, 1] = v[np.searchsorted(ts, t, side="right") - 1, 1]
        out.append(Signal("positions", t, P, tuple(corners[i].name for i in range(4)),
                          "module velocity states", "swerve",
                          "speed m/s, angle rad (SwerveModuleState)", integrated=True,
                          batched=True,
                          why="integrated from measured module states, one per corner"))
    if lacking and not out:
        raise DataLogError("; ".join(lacking))
    return out
