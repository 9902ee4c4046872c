"""Where a replay's inputs live in the logs teams write: the layouts table that
:mod:`drivekin.replay` walks (documented in docs/logs-and-replay.md, "Log layouts").

A layout turns entries of a log into one *signal*, a quantity in drivekin's own stacking
and SI units with its timestamps:

* ``positions``: swerve (N, M, 2) ``[distance m, angle rad]``, mecanum (N, 4) m,
  differential (N, 2) ``[left, right]`` m;
* ``gyro``: (N,) rad;
* ``pose``: (N, 3) ``[x m, y m, θ rad]`` (a logged Pose3d in the plane: its toPose2d).

Names are compared after :func:`fold` (case and underscores ignored), so AdvantageKit's
``DrivePositionRad`` and robotpy-pykit's ``drive_position_rad`` are the same key, and a
name given by the user is found with or without NetworkTables' ``NT:`` prefix.

Units come, in this order, from what the user gave (``--drive-units`` and friends), the
name's suffix (``...Rad``, ``...Rotations``, ``...Meters``, ``...Deg``), the entry's
``{"unit": ...}`` metadata, and the layout's own convention; where none says, the
replay stops and names the option.
"""
from __future__ import annotations

import difflib
import importlib
import math
import weakref
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from drivekin._core import catalog
from drivekin._core.metadata import parse as parse_metadata
from drivekin.datalog import DataLogError, EntryInfo, LogData

REPLAY_PREFIX = "/drivekin/"

# --------------------------------------------------------------------------------------
# Names


def fold(name: str) -> str:
    """A name as the layouts compare it: lower case, without ``_``, spaces or ``-``."""
    return name.replace("_", "").replace(" ", "").replace("-", "").lower()


def is_schema(name: str) -> bool:
    """A struct schema entry, the log's own or mirrored from NetworkTables."""
    return name.startswith(("/.schema/", "NT:/.schema/"))


def bare(name: str) -> str:
    """A name without the ``NT:`` prefix NetworkTables mirroring adds."""
    return name[3:] if name.startswith("NT:") else name


def resolve(log: LogData, name: str, option: str) -> EntryInfo:
    """The entry a user named: exactly, else the one entry equal to it after
    :func:`fold`, with or without the ``NT:`` prefix; DataLogError with the closest
    names otherwise."""
    entries = log.entries
    if name in entries:
        return entries[name]
    want = fold(bare(name))
    hits = [e for n, e in entries.items() if fold(bare(n)) == want]
    if not hits:
        # a unique tail of whole path components: Field/Robot for NT:/SmartDashboard/Field/Robot
        tail = "/" + want.lstrip("/")
        hits = [e for n, e in entries.items() if fold(bare(n)).endswith(tail)]
    if len(hits) == 1:
        return hits[0]
    if len(hits) > 1:
        raise DataLogError(f"{option} {name!r} matches several entries: "
                           f"{', '.join(e.name for e in hits)}; give one exactly")
    names = [n for n in entries if not is_schema(n)]
    folded = {fold(bare(n)): n for n in names}
    close = difflib.get_close_matches(want, list(folded), n=3, cutoff=0.6)
    hint = f"; did you mean {' or '.join(repr(folded[c]) for c in close)}?" if close else ""
    raise DataLogError(f"{option} {name!r}: no such entry{hint} "
                       f"(python -m drivekin replay LOG --list shows them all)")


# --------------------------------------------------------------------------------------
# Units

DRIVE_UNITS = ("m", "ft", "rad", "rot")
# Drive units of a wheel *velocity* (a module state): integrated into distances.
SPEED_UNITS = ("m/s", "ft/s", "rad/s", "rot/s")
TURN_UNITS = ("rad", "deg", "rot")
GYRO_UNITS = ("rad", "deg", "rot")
_UNIT_WORDS = {
    "m": "m", "meters": "m", "metres": "m", "meter": "m",
    "rad": "rad", "rads": "rad", "radians": "rad",
    "rot": "rot", "rots": "rot", "rotations": "rot", "revs": "rot", "revolutions": "rot",
    "deg": "deg", "degrees": "deg",
    "ft": "ft", "feet": "ft", "foot": "ft",
}
# Speed suffixes and metadata units ("per second" spelled the ways names spell it).
_SPEED_WORDS = {
    "m/s": "m", "meterspersecond": "m", "meterspersec": "m", "mps": "m", "meterpersecond": "m",
    "ft/s": "ft", "feetpersecond": "ft", "feetpersec": "ft", "fps": "ft",
    "rad/s": "rad", "radpersec": "rad", "radianspersecond": "rad", "radpersecond": "rad",
    "rot/s": "rot", "rotationspersecond": "rot", "rps": "rot", "rotpersec": "rot",
}
_TO_RAD = {"rad": 1.0, "deg": math.pi / 180.0, "rot": 2.0 * math.pi}
_FOOT = 0.3048
_SUFFIXES = sorted(_UNIT_WORDS, key=len, reverse=True)     # longest first: "degrees", "deg"


def _metadata_unit(metadata: str) -> str | None:
    """The folded unit an entry's metadata names: ``{"unit": ...}`` JSON, or the bare unit
    word WPILib's SysId log writes (``Meter``, ``Meter per Second``)."""
    if metadata.lstrip().startswith("{"):
        meta = parse_metadata(metadata)
        unit = meta.get("unit") if meta is not None else None
        return fold(unit) if isinstance(unit, str) else None
    word = fold(metadata)
    return word if 0 < len(word) < 40 else None


def unit_of(suffix: str, metadata: str) -> str | None:
    """The unit a name's suffix (after the quantity's own word) or the entry's metadata
    names (singular or plural), or None."""
    u = _UNIT_WORDS.get(suffix)
    if u is not None:
        return u
    unit = _metadata_unit(metadata)
    if unit is None:
        return None
    return _UNIT_WORDS.get(unit) or _UNIT_WORDS.get(unit + "s")


def speed_unit_of(suffix: str, metadata: str) -> str | None:
    """The distance unit of a speed named by a name's suffix or the metadata (``m`` for
    ``Meter per Second``), or None. A suffix that names a distance (``...Feet``) is read
    as that distance per second: the entry is known to be a velocity."""
    u = _SPEED_WORDS.get(suffix) or _UNIT_WORDS.get(suffix)
    if u is not None:
        return u
    unit = _metadata_unit(metadata)
    if unit is None:
        return None
    return _SPEED_WORDS.get(unit) or _SPEED_WORDS.get(unit.replace("meter", "meters"))


def is_speed_metadata(metadata: str) -> bool:
    unit = _metadata_unit(metadata)
    return unit is not None and ("persec" in unit or unit in _SPEED_WORDS)


def unit_suffix(leaf: str) -> str:
    """The unit word a folded leaf name ends with (``headingdegrees`` -> ``degrees``), or
    ``""``."""
    for u in _SUFFIXES:
        if leaf.endswith(u) and len(leaf) > len(u):
            return u
    return ""


def angle_scale(unit: str) -> float:
    return _TO_RAD[unit]


# --------------------------------------------------------------------------------------
# Signals


@dataclass(eq=False)
class Signal:
    """One quantity assembled from a log (see the module docstring)."""

    role: str
    t: np.ndarray                       # int64 µs
    values: np.ndarray
    entries: tuple[str, ...]            # the log entries it came from
    layout: str                         # the layout's name
    drivetrain: str | None = None       # positions only
    units: str = ""                     # the units assumed, and from where
    why: str = ""                       # why this one was chosen
    highRate: bool = False              # AdvantageKit odometry-thread samples
    integrated: bool = False            # distances integrated from velocity states
    batched: bool = False               # samples are batches of records (NetworkTables)
    # Module offsets (m) the log itself gives with these positions, and where from.
    offsets: tuple[tuple[float, float], ...] | None = None
    offsetsFrom: str = ""

    @property
    def source(self) -> str:
        return self.entries[0] if len(self.entries) == 1 else _common(self.entries)


def _common(names: tuple[str, ...]) -> str:
    parts = [n.split("/") for n in names]
    head = []
    for level in zip(*parts):
        if len(set(level)) != 1:
            break
        head.append(level[0])
    prefix = "/".join(head)
    return f"{prefix}/... ({len(names)} entries)"


@dataclass
class Options:
    """What the user said that a log cannot say: units, the wheel radius, and what to do
    with arrays that change length."""

    drive: str | None = None            # DRIVE_UNITS
    turn: str | None = None             # TURN_UNITS
    gyro: str | None = None             # GYRO_UNITS
    wheelRadius: float | None = None    # m, for drive positions in rad or rot
    ragged: str = "error"               # or "drop" (LogData.values)


def _drive_scale(unit: str | None, where: str, units: Options) -> tuple[float, str]:
    """Metres per logged drive unit, and how that was decided."""
    if units.drive is not None:
        unit, said = units.drive.removesuffix("/s"), "--drive-units"
    elif unit is not None:
        said = "the entry's name or metadata"
    else:
        raise DataLogError(f"{where}: the drive positions' units are not in the log; give "
                           f"--drive-units m|rad|rot (rad and rot: of the wheel, with "
                           f"--wheel-radius)")
    if unit == "m":
        return 1.0, f"drive m ({said})"
    if unit == "ft":
        return _FOOT, f"drive ft ({said})"
    if units.wheelRadius is None:
        raise DataLogError(f"{where}: drive positions are wheel {unit} ({said}); give "
                           f"--wheel-radius M to turn them into metres")
    return (_TO_RAD[unit] * units.wheelRadius,
            f"drive wheel {unit} ({said}) × radius {units.wheelRadius:g} m")


def _turn_scale(unit: str | None, where: str, units: Options, is_rotation: bool) -> tuple[float, str]:
    if is_rotation:
        return 1.0, "turn Rotation2d"
    if units.turn is not None:
        return _TO_RAD[units.turn], f"turn {units.turn} (--turn-units)"
    if unit is not None and unit in _TO_RAD:
        return _TO_RAD[unit], f"turn {unit} (the entry's name or metadata)"
    raise DataLogError(f"{where}: the turn angles' units are not in the log; give "
                       f"--turn-units rad|deg|rot")


# --------------------------------------------------------------------------------------
# Module and side groups: per-module entries such as /Drive/Module0/DrivePositionRad

_CORNERS = {  # folded corner names -> module order FL, FR, BL, BR (RL, RR are BL, BR)
    "fl": 0, "frontleft": 0, "fr": 1, "frontright": 1, "bl": 2, "backleft": 2,
    "rl": 2, "rearleft": 2, "br": 3, "backright": 3, "rr": 3, "rearright": 3,
    "lf": 0, "leftfront": 0, "rf": 1, "rightfront": 1, "lb": 2, "leftback": 2,
    "leftrear": 2, "rb": 3, "rightback": 3, "rightrear": 3,
}
CORNER_NAMES = ("front-left", "front-right", "back-left", "back-right")
_MODULE_WORDS = ("swervemodule", "module", "mod")


def _module_index(part: str) -> tuple[int, int] | None:
    """(kind, index) for a path component naming a module: kind 0 numbered, 1 corner."""
    f = fold(part)
    if f in _CORNERS:
        return 1, _CORNERS[f]
    for w in _MODULE_WORDS:
        if f.startswith(w) and f[len(w):].isdigit() and len(f) - len(w) <= 2:
            return 0, int(f[len(w):])
    return None


# Leaf keys (folded) of a module's entries, each with the word a unit suffix follows.
_HIGH_DRIVE = "odometrydrivepositions"
_HIGH_TURN = "odometryturnpositions"
_HIGH_TIME = "odometrytimestamps"
_DRIVE_WORDS = ("driveposition", "drivedistance", "distance")
_TURN_WORDS = ("turnposition", "turnangle", "steerposition", "steerangle", "angle",
               "azimuth", "steer")
_VELOCITY_WORDS = ("drivevelocity", "drivespeed", "velocity", "speed")


def _split_word(leaf: str, words: tuple[str, ...], units: Any = _UNIT_WORDS) -> str | None:
    """The unit suffix after the first of ``words`` that ``leaf`` starts with (``""``
    for none), or None if it starts with none of them or the rest is not a unit."""
    for w in words:
        if leaf.startswith(w):
            rest = leaf[len(w):]
            if rest == "" or rest in units:
                return rest
    return None


def split_velocity(leaf: str) -> str | None:
    """A folded leaf naming a drive velocity (``DriveVelocityFeet``,
    ``DriveVelocityMetersPerSec``): its unit suffix, else None."""
    return _split_word(leaf, _VELOCITY_WORDS, {**_UNIT_WORDS, **_SPEED_WORDS})


@dataclass
class _Module:
    entries: dict[str, tuple[EntryInfo, str]] = field(default_factory=dict)  # role -> (info, suffix)


def _module_groups(log: LogData) -> dict[tuple[str, int], dict[int, _Module]]:
    """Per-module entries grouped by (path before the module component, naming kind)."""
    groups: dict[tuple[str, int], dict[int, _Module]] = {}
    for info in log.entries.values():
        if info.records == 0 or info.name.startswith(REPLAY_PREFIX):
            continue
        parts = info.name.split("/")
        for j in range(len(parts) - 1):
            mi = _module_index(parts[j])
            if mi is None:
                continue
            leaf = fold("".join(parts[j + 1:]))
            role = suffix = None
            if leaf.startswith(_HIGH_DRIVE):
                role, suffix = "hdrive", leaf[len(_HIGH_DRIVE):]
            elif leaf.startswith(_HIGH_TURN):
                role, suffix = "hturn", leaf[len(_HIGH_TURN):]
            elif leaf == _HIGH_TIME:
                role, suffix = "htime", ""
            elif _split_word(leaf, _DRIVE_WORDS) is not None:
                role, suffix = "drive", _split_word(leaf, _DRIVE_WORDS)
            elif _split_word(leaf, _TURN_WORDS) is not None:
                role, suffix = "turn", _split_word(leaf, _TURN_WORDS)
            elif split_velocity(leaf) is not None:
                role, suffix = "velocity", split_velocity(leaf)
            if role is not None:
                key = ("/".join(parts[:j]), mi[0])
                mod = groups.setdefault(key, {}).setdefault(mi[1], _Module())
                mod.entries.setdefault(role, (info, suffix or ""))
            break
    return groups


def _module_positions(log: LogData, prefix: str, mods: dict[int, _Module], units: Options,
                      high: bool) -> Signal | None:
    """Swerve positions from per-module entries (cycle values or high-rate arrays)."""
    order = sorted(mods)
    if len(order) < 2 or order != list(range(order[0], order[0] + len(order))):
        return None
    where = prefix or "/"
    if high:
        need = ("hdrive", "hturn", "htime")
        if not all(all(r in mods[i].entries for r in need) for i in order):
            return None
        dist: list[np.ndarray] = []
        ang: list[np.ndarray] = []
        times: list[np.ndarray] = []
        for i in order:
            e = mods[i].entries
            di, dsuf = e["hdrive"]
            ti, tsuf = e["hturn"]
            clock = e["htime"][0].name
            vs = log.concatenated(clock)[2]
            if times and len(vs) != len(times[0]):
                raise DataLogError(f"{where}: the modules' OdometryTimestamps hold "
                                   f"different numbers of samples")
            dscale, dunits = _drive_scale(unit_of(dsuf, di.metadata), f"{di.name}", units)
            tscale, tunits = _turn_scale(unit_of(tsuf, ti.metadata), f"{ti.name}", units,
                                         ti.type == "struct:Rotation2d[]")
            dist.append(_held(log, clock, di.name, where) * dscale)
            ang.append(_held(log, clock, ti.name, where) * tscale)
            times.append(vs)
        stamps = times[0]
        t = np.round(stamps * 1e6).astype(np.int64)
        P = np.stack([np.stack(dist, axis=1), np.stack(ang, axis=1)], axis=2)
        names = tuple(n for i in order for n in (mods[i].entries["hdrive"][0].name,
                                                  mods[i].entries["hturn"][0].name,
                                                  mods[i].entries["htime"][0].name))
        return Signal("positions", t, P, names, "AdvantageKit high-rate odometry",
                      "swerve", f"{dunits}; {tunits}; timestamps s", highRate=True)
    if not all("drive" in mods[i].entries and "turn" in mods[i].entries for i in order):
        return None
    names_d = [mods[i].entries["drive"][0].name for i in order]
    names_t = [mods[i].entries["turn"][0].name for i in order]
    dists, angs = [], []
    dunits = tunits = ""
    for i in order:
        di, dsuf = mods[i].entries["drive"]
        ti, tsuf = mods[i].entries["turn"]
        if di.type not in ("double", "float") or ti.type not in ("double", "float",
                                                                 "struct:Rotation2d"):
            return None
        dscale, dunits = _drive_scale(unit_of(dsuf, di.metadata), di.name, units)
        tscale, tunits = _turn_scale(unit_of(tsuf, ti.metadata), ti.name, units,
                                     ti.type == "struct:Rotation2d")
        td, vd = log.values(di.name)
        tt, vt = log.values(ti.name)
        dists.append((td, vd * dscale))
        angs.append((tt, vt * tscale))
    t, P = _join([*dists, *angs], where, _cycle_clock(log))
    m = len(order)
    P = np.stack([P[:, :m], P[:, m:]], axis=2)
    return Signal("positions", t, P, tuple(names_d + names_t), "per-module entries",
                  "swerve", f"{dunits}; {tunits}")


def _cycle_clock(log: LogData) -> np.ndarray | None:
    """AdvantageKit's and robotpy-pykit's cycle clock: /Timestamp (int64 µs per cycle)."""
    e = log.entries.get("/Timestamp")
    if e is None or e.type != "int64" or e.records == 0:
        return None
    return log.values("/Timestamp")[1]


def _join(series: list[tuple[np.ndarray, np.ndarray]], where: str,
          clock: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Scalar series logged once per cycle, as columns on one timeline: the cycle clock
    when the log has one, else every time any of them was logged. Writers that log a
    value only when it changes (robotpy-pykit, NetworkTables) leave the rest to be held,
    so each column holds its latest record at or before each time; the timeline starts
    once every series has a value."""
    if clock is None:
        clock = np.unique(np.concatenate([ts for ts, _ in series]))
    if not all(len(ts) for ts, _ in series):
        raise DataLogError(f"{where}: an entry of the group has no records")
    start = max(int(ts[0]) for ts, _ in series)
    t = clock[clock >= start]
    if len(t) == 0:
        raise DataLogError(f"{where}: the entries of the group never all have a value")
    cols = [v[np.searchsorted(ts, t, side="right") - 1] for ts, v in series]
    return t, np.stack(cols, axis=1)


def _held(log: LogData, clock: str, name: str, where: str) -> np.ndarray:
    """The elements of array entry ``name`` for each record of array entry ``clock``
    (AdvantageKit's OdometryTimestamps): each clock record takes the latest ``name``
    record at or before it, which must hold as many elements (a writer that logs only
    changes skips a record whose array repeats the last one)."""
    tc, cc, _ = log.concatenated(clock)
    tx, cx, vx = log.concatenated(name)
    k = np.searchsorted(tx, tc, side="right") - 1
    if len(tc) and (k < 0).any():
        raise DataLogError(f"{where}: {name} starts after {clock}")
    if len(tc) and (cx[k] != cc).any():
        i = int(np.argmax(cx[k] != cc))
        raise DataLogError(f"{where}: {name} holds {cx[k[i]]} samples where {clock} holds "
                           f"{cc[i]} (record at {tc[i] / 1e6:.3f} s)")
    starts = np.concatenate([[0], np.cumsum(cx)[:-1]]).astype(np.int64)
    first = np.concatenate([[0], np.cumsum(cc)[:-1]]).astype(np.int64)
    total = int(cc.sum())
    idx = np.repeat(starts[k], cc) + (np.arange(total) - np.repeat(first, cc))
    held: np.ndarray = vx[idx]
    return held


def rate(t: np.ndarray) -> float:
    """Median sample rate (Hz) of sorted timestamps in µs (0 for fewer than two)."""
    d = np.diff(t)
    d = d[d > 0]
    return float(1e6 / np.median(d)) if len(d) else 0.0


# --------------------------------------------------------------------------------------
# The layouts table


@dataclass(frozen=True)
class Layout:
    """One way a quantity is written into logs: ``find`` returns its signals."""

    name: str
    role: str
    writers: str                        # who writes it this way
    units: str                          # the units it implies
    find: Callable[[LogData, Options], list[Signal]]


# The log types that identify a drivetrain: the catalog's.
POSITION_STRUCTS = {e.positions: e.drivetrain for e in catalog.entries("odometry")
                    if e.positions is not None}


def _live(log: LogData) -> list[EntryInfo]:
    return [e for e in log.entries.values()
            if e.records > 0 and not e.name.startswith(REPLAY_PREFIX)
            and not is_schema(e.name)]


def _find_struct_positions(log: LogData, units: Options) -> list[Signal]:
    out = []
    for e in _live(log):
        kind = POSITION_STRUCTS.get(e.type)
        if kind is not None:
            t, v = log.values(e.name, ragged=units.ragged)
            out.append(Signal("positions", t, np.array(v, dtype=np.float64), (e.name,),
                              "WPILib struct", kind, "m; rad"))
    return out


def _find_module_positions(high: bool) -> Callable[[LogData, Options], list[Signal]]:
    def find(log: LogData, units: Options) -> list[Signal]:
        out = []
        for (prefix, _), mods in _module_groups(log).items():
            s = _module_positions(log, prefix, mods, units, high)
            if s is not None:
                out.append(s)
        return out
    return find


def _drivestate(log: LogData, leaf: str, type_string: str) -> list[tuple[EntryInfo, EntryInfo]]:
    """CTRE's DriveState entries named ``leaf`` with their table's Timestamp entry."""
    by_name = {fold(e.name): e for e in _live(log)}
    out = []
    for f, e in by_name.items():
        if f.endswith("drivestate/" + leaf) and e.type == type_string:
            clock = by_name.get(f[:-len(leaf)] + "timestamp")
            if clock is not None and clock.type == "double":
                out.append((e, clock))
    return out


def _on_clock(log: LogData, entry: EntryInfo, clock: EntryInfo) -> tuple[np.ndarray, np.ndarray]:
    """Values of ``entry`` at each sample of CTRE's DriveState/Timestamp (the sample time
    in seconds; NetworkTables stamps the records later and drops repeated values, so
    each sample holds the latest record at or before its own record)."""
    tc, sec = log.values(clock.name)
    tx, vx = log.values(entry.name)
    k = np.searchsorted(tx, tc, side="right") - 1
    keep = k >= 0
    return np.round(sec[keep] * 1e6).astype(np.int64), vx[k[keep]]


def _find_ctre_positions(log: LogData, units: Options) -> list[Signal]:
    out = []
    for e, clock in _drivestate(log, "modulepositions", "struct:SwerveModulePosition[]"):
        t, v = _on_clock(log, e, clock)
        out.append(Signal("positions", t, v, (e.name, clock.name), "CTRE DriveState",
                          "swerve", "m; rad; timestamps s", why="CTRE's swerve drive state, "
                          "on its own sample clock (DriveState/Timestamp)"))
    return out


def _find_ctre_pose(log: LogData, units: Options) -> list[Signal]:
    out = []
    for e, clock in _drivestate(log, "pose", "struct:Pose2d"):
        t, v = _on_clock(log, e, clock)
        out.append(Signal("pose", t, v, (e.name, clock.name), "CTRE DriveState",
                          units="m; rad", why="CTRE's swerve drive state"))
    return out


_SIDE_WORDS = ("position", "distance", "encoderposition", "encoderdistance",
               "driveposition", "drivedistance")


def _find_side_positions(log: LogData, units: Options) -> list[Signal]:
    """Differential left/right doubles beside each other: LeftPosition, RightPosition."""
    sides: dict[tuple[str, str], dict[str, tuple[EntryInfo, str]]] = {}
    for e in _live(log):
        if e.type not in ("double", "float"):
            continue
        head, _, leaf = e.name.rpartition("/")
        f = fold(leaf)
        for side in ("left", "right"):
            if f.startswith(side):
                suf = _split_word(f[len(side):], _SIDE_WORDS)
                if suf is not None:
                    sides.setdefault((head, fold(f[len(side):])), {})[side] = (e, suf)
    out = []
    for (head, _), pair in sides.items():
        if len(pair) != 2:
            continue
        (li, ls), (ri, rs) = pair["left"], pair["right"]
        unit = unit_of(ls, li.metadata) or unit_of(rs, ri.metadata)
        if unit is None and units.drive is None:
            scale, text = 1.0, ("m (left/right distances are read as metres; --drive-units "
                                "says otherwise)")
        else:
            scale, text = _drive_scale(unit, li.name, units)
        tl, vl = log.values(li.name)
        tr, vr = log.values(ri.name)
        t, P = _join([(tl, vl * scale), (tr, vr * scale)], head or "/", _cycle_clock(log))
        out.append(Signal("positions", t, P, (li.name, ri.name), "left/right doubles",
                          "differential", text))
    return out


_ARRAY_WORDS = ("position", "distance", "wheel", "encoder")
_NOT_POSITION = ("speed", "velocity", "rate", "current", "volt", "accel", "setpoint",
                 "target", "desired")


def _find_array_positions(log: LogData, units: Options) -> list[Signal]:
    """double[2] [left, right] (differential) and double[4] FL, FR, RL, RR (mecanum)."""
    out = []
    for e in _live(log):
        f = fold(e.name)
        if e.type != "double[]" or not any(w in f for w in _ARRAY_WORDS) or any(
                w in f for w in _NOT_POSITION):
            continue
        if "odometry" in fold(e.name.rpartition("/")[2]):
            continue                    # AdvantageKit's high-rate arrays
        try:
            t, v = log.values(e.name)
        except DataLogError:
            continue                    # a ragged array is not a wheel array
        kind = {2: "differential", 4: "mecanum"}.get(v.shape[1] if v.ndim == 2 else 0)
        if kind is None:
            continue
        leaf = fold(e.name.rpartition("/")[2])
        suffix = next((u for u in ("rotations", "radians", "meters", "rad", "rot")
                       if leaf.endswith(u)), "")
        unit = unit_of(suffix, e.metadata)
        if unit is None and units.drive is None:
            scale, text = 1.0, ("m (a double[] of wheel distances is read as metres; "
                                "--drive-units says otherwise)")
        else:
            scale, text = _drive_scale(unit, e.name, units)
        out.append(Signal("positions", t, v * scale, (e.name,), f"double[{v.shape[1]}]",
                          kind, text))
    return out


def _find_high_gyro(log: LogData, units: Options) -> list[Signal]:
    """AdvantageKit's OdometryYawPositions with OdometryYawTimestamps."""
    out = []
    by_name = {fold(e.name): e for e in _live(log)}
    for f, e in by_name.items():
        if "odometryyawpositions" not in f:
            continue
        head = f[:f.rfind("odometryyawpositions")]
        suffix = f[len(head) + len("odometryyawpositions"):]
        te = by_name.get(head + "odometryyawtimestamps")
        if te is None:
            continue
        if e.type == "struct:Rotation2d[]":
            scale, text = 1.0, "Rotation2d"
        else:
            u = units.gyro or unit_of(suffix, e.metadata)
            if u is None:
                continue
            scale, text = _TO_RAD[u], u
        vs = log.concatenated(te.name)[2]
        vy = _held(log, te.name, e.name, e.name)
        out.append(Signal("gyro", np.round(vs * 1e6).astype(np.int64), vy * scale,
                          (e.name, te.name), "AdvantageKit high-rate odometry",
                          units=text, highRate=True, why="odometry-thread yaw samples"))
    return out


def _later(module: str, name: str) -> Callable[[LogData, Options], list[Signal]]:
    """A finder of ``_core/candidates.py`` (poses, gyros) or ``_core/modulelayouts.py``,
    looked up when called: those modules build on this one's helpers."""
    def find(log: LogData, units: Options) -> list[Signal]:
        found: list[Signal] = getattr(importlib.import_module(f"drivekin._core.{module}"),
                                      name)(log, units)
        return found
    return find


LAYOUTS: tuple[Layout, ...] = (
    Layout("WPILib struct", "positions",
           "robotpy / Java struct entries (DataLogManager NT mirroring, CTRE DriveState "
           "ModulePositions, drivekin)", "m; rad", _find_struct_positions),
    Layout("CTRE DriveState", "positions",
           "CTRE Phoenix 6 generated swerve Telemetry (NT:/DriveState/ModulePositions with "
           "DriveState/Timestamp)", "m; rad; timestamps s", _find_ctre_positions),
    Layout("AdvantageKit high-rate odometry", "positions",
           "AdvantageKit and robotpy-pykit swerve templates: per-module "
           "OdometryDrivePositions*, OdometryTurnPositions, OdometryTimestamps",
           "drive from the suffix (Rad: wheel radians); turn Rotation2d; timestamps s",
           _find_module_positions(True)),
    Layout("per-module entries", "positions",
           "AdvantageKit cycle inputs (DrivePositionRad, TurnPosition) and robotpy teams' "
           "per-module doubles (Module0..N or FL/FR/BL/BR)",
           "from the suffix, the metadata or --drive-units / --turn-units",
           _find_module_positions(False)),
    Layout("YAGSL telemetry", "positions",
           "YAGSL's SmartDashboard telemetry (DataLogManager's NT mirror): "
           "swerve/modules/<name>/Raw Drive Encoder, Adjusted Absolute Encoder, module "
           "offsets from swerve/wheelLocation", "drive m; turn deg; offsets in",
           _later("modulelayouts", "find_yagsl_positions")),
    Layout("SysId routine", "positions",
           "WPILib SysIdRoutineLog: position-<motor> per module corner, paired with the "
           "robot's module angles", "from the entry's unit metadata (Meter, Rotation)",
           _later("modulelayouts", "find_sysid_positions")),
    Layout("module velocity states", "positions",
           "module speeds without distances: per-module Drive Velocity with Steer/Angle "
           "entries, struct:SwerveModuleState[] measured states; integrated",
           "from the suffix (Feet: ft/s), the metadata or --drive-units m/s|ft/s",
           _later("modulelayouts", "find_state_velocities")),
    Layout("module velocity states", "positions",
           "one struct:SwerveModuleState per corner (ActualFrontLeftModuleState, ...); "
           "integrated", "m/s; rad", _later("modulelayouts", "find_corner_states")),
    Layout("left/right doubles", "positions", "differential drives: LeftPosition, "
           "RightPosition", "m unless the suffix or --drive-units says otherwise",
           _find_side_positions),
    Layout("double[] wheels", "positions",
           "double[2] [left, right] (differential), double[4] FL, FR, RL, RR (mecanum): "
           "robotpy 2026 has no struct for these", "m unless --drive-units says otherwise",
           _find_array_positions),
    Layout("AdvantageKit high-rate odometry", "gyro",
           "AdvantageKit / robotpy-pykit OdometryYawPositions + OdometryYawTimestamps",
           "Rotation2d; timestamps s", _find_high_gyro),
    Layout("Rotation2d", "gyro", "struct:Rotation2d entries (AdvantageKit YawPosition)",
           "rad", _later("candidates", "find_struct_gyro")),
    Layout("double", "gyro", "double entries named gyro, imu, pigeon, navX, yaw, heading, "
           "robot angle (YAGSL swerve/imu/raw; a SmartDashboard Gyro widget's Value)",
           "from the suffix, the metadata or --gyro-units (YAGSL and Gyro widgets: deg)",
           _later("candidates", "find_double_gyro")),
    Layout("CTRE DriveState", "pose", "CTRE's NT:/DriveState/Pose with DriveState/Timestamp",
           "m; rad; timestamps s", _find_ctre_pose),
    Layout("Pose2d", "pose", "struct:Pose2d entries (AdvantageKit Odometry/Robot, CTRE "
           "DriveState/Pose, PathPlanner currentPose)", "m; rad",
           _later("candidates", "find_pose2d")),
    Layout("Pose3d", "pose", "struct:Pose3d entries (a 3-D pose estimate), compared in the "
           "plane", "m; rad (x, y and yaw: toPose2d)",
           _later("candidates", "find_pose3d")),
    Layout("three doubles", "pose", "a pose as three doubles: X, Y and Angle / Heading / "
           "Rotation (/Pose/RobotPoseX, ...; Drive/X, Drive/Y, Drive/Heading)",
           "m; the angle's unit from its name or metadata, else deg beyond ±π, else rad",
           _later("candidates", "find_double_pose")),
    Layout("Pose2d string", "pose", "a string entry holding WPILib's Pose2d.toString() "
           "(Java, robotpy) or x,y,θ", "m; rad (x,y,θ text: as three doubles)",
           _later("candidates", "find_string_pose")),
    Layout("Field2d double[3]", "pose", "SmartDashboard Field2d (legacy double[3])",
           "m; deg", _later("candidates", "find_field2d_pose")),
)


def layouts_table() -> str:
    """The layouts table as Markdown (docs/logs-and-replay.md shows it; a test keeps the
    two in step)."""
    rows = ["| quantity | layout | written by | units |", "|---|---|---|---|"]
    for lay in LAYOUTS:
        rows.append(f"| {lay.role} | {lay.name} | {lay.writers} | {lay.units} |")
    return "\n".join(rows)


def candidates(log: LogData, role: str, units: Options,
               problems: list[DataLogError] | None = None) -> list[Signal]:
    """Every signal of ``role`` the layouts find, in the table's order. A layout that
    recognises its entries but cannot read them as asked (units the log does not give)
    adds its DataLogError to ``problems`` (raised at once when that is None) and the
    other layouts still look."""
    key = (role, units.drive, units.turn, units.gyro, units.wheelRadius, units.ragged)
    cache = _FOUND.setdefault(log, {})
    if key not in cache:
        found: list[Signal] = []
        failed: list[DataLogError] = []
        for lay in LAYOUTS:
            if lay.role == role:
                try:
                    found += lay.find(log, units)
                except DataLogError as e:
                    failed.append(e)
        cache[key] = (found, failed)
    found, failed = cache[key]
    if failed and problems is None:
        raise failed[0]
    if problems is not None:
        problems += failed
    return list(found)


# What the layouts found in each log, per role and options: a replay (and --list, and
# calibrate's replays of the same LogData) plans from one reading of the log.
_FOUND: weakref.WeakKeyDictionary[LogData, dict[tuple[object, ...], tuple[list[Signal], list[DataLogError]]]] = weakref.WeakKeyDictionary()
