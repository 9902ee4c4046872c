"""Which entries of a log :func:`drivekin.replay.replayLog` reads: the positions, gyro
and pose signals, each chosen among the candidates of the layouts table
(``_core/loglayouts.py``) by rank, or named by the user (``--positions``, ``--gyro``,
``--pose``, ``--truth``), with why it was chosen."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from drivekin._core import catalog
from drivekin._core import loglayouts as layouts
from drivekin._core import modulelayouts
from drivekin._core.candidates import gyro_rank, gyro_rejected, pose_rank, pose_score
from drivekin._core.loglayouts import Signal
from drivekin.datalog import DataLogError, LogData

if TYPE_CHECKING:
    from drivekin.replay import ReplayConfig



def _choose(cands: list[Signal], role: str, option: str, rank: Any) -> tuple[Signal, str]:
    """The best-ranked candidate and why; DataLogError when the best are tied."""
    ordered = sorted(cands, key=rank, reverse=True)          # stable: table order on ties
    # One entry read by two layouts (CTRE's Pose as a Pose2d and on DriveState's clock)
    # is one candidate: the better-ranked reading.
    seen: set[str] = set()
    unique = []
    for s in ordered:
        if s.entries[0] not in seen:
            seen.add(s.entries[0])
            unique.append(s)
    best = [s for s in unique if rank(s) == rank(unique[0])]
    if len(best) > 1:
        raise DataLogError(f"several {role} entries: "
                           f"{'; '.join(f'{s.source} ({s.layout})' for s in best)}; "
                           f"name one with {option}")
    chosen = best[0]
    others = [s.source for s in unique[1:]]
    why = chosen.why or chosen.layout
    if others:
        why += f"; over {', '.join(others[:3])}" + (f" and {len(others) - 3} more"
                                                    if len(others) > 3 else "")
    return chosen, why


def _named_signal(log: LogData, cands: list[Signal], name: str, option: str) -> Signal | None:
    """The candidate holding the entry a user named, or whose entries all lie under the
    named prefix (``--positions /Drive`` for AdvantageKit's per-module entries)."""
    try:
        want = {layouts.resolve(log, name, option).name}
        under = None
    except DataLogError:
        want = set()
        under = layouts.fold(layouts.bare(name)).rstrip("/") + "/"
        if not any(all(layouts.fold(layouts.bare(n)).startswith(under) for n in s.entries)
                   for s in cands):
            inside = [n for n in log.entries
                      if layouts.fold(layouts.bare(n)).startswith(under)]
            if inside:
                raise DataLogError(
                    f"{option} {name!r} is a folder of {len(inside)} entries, but none of "
                    f"the layouts recognises modules in it (e.g. {inside[0]!r}); map each "
                    f"module's drive and angle entries with --module-entries") from None
            raise
    hits = [s for s in cands if (want & set(s.entries)) or (
        under is not None and all(layouts.fold(layouts.bare(n)).startswith(under)
                                  for n in s.entries))]
    high = [s for s in hits if s.highRate]
    return (high or hits or [None])[0]


# Distances over velocities (integrating adds error), a library's own layout over a
# guess from names, YAGSL's whole-log encoders over a SysId session's.
_POSITION_RANK = {"CTRE DriveState": 5, "AdvantageKit high-rate odometry": 4,
                  "WPILib struct": 3, "YAGSL telemetry": 3,
                  "per-module entries": 2, "SysId routine": 1.5, "left/right doubles": 1,
                  "double[] wheels": 0, "module velocity states": -1}


def _positions(log: LogData, cfg: ReplayConfig, units: layouts.Options
               ) -> tuple[Signal, Signal | None, str]:
    """The positions signal, the cycle-rate one beside high-rate samples (or None), why."""
    want = cfg.drivetrain
    problems: list[DataLogError] = []
    cands = [s for s in layouts.candidates(log, "positions", units, problems)
             if want in ("auto", s.drivetrain)]
    if cfg.odometryRate == "cycle":
        cands = [s for s in cands if not s.highRate] or cands
    if cfg.moduleEntries:
        if cfg.positions is not None:
            raise DataLogError("give --positions or --module-entries, not both")
        chosen = modulelayouts.named_modules(log, cfg.moduleEntries, units)
        why = chosen.why
    elif cfg.positions is not None:
        chosen = _named_signal(log, cands, cfg.positions, "--positions")
        if chosen is None:
            chosen = _named_array(log, cfg.positions, want, cfg.ragged)
        why = "named with --positions"
    else:
        if want != "auto" and not catalog.replay_spec(want).found_by_type:
            raise DataLogError(f"{want} positions are a double[] entry: name it with "
                               f"--positions")
        if not cands:
            found = ", ".join(dict.fromkeys(lay.name for lay in layouts.LAYOUTS
                                            if lay.role == "positions"))
            lacks = "".join(f"; {p}" for p in problems)
            raise DataLogError(f"no wheel or module positions found (layouts tried: "
                               f"{found}){lacks}; name an entry with --positions, or map "
                               f"per-module entries with --module-entries (--list shows "
                               f"the entries)")
        chosen, why = _choose(cands, "positions", "--positions",
                              lambda s: _POSITION_RANK.get(s.layout, 0))
    cycle = None
    if chosen.highRate:
        group = layouts.fold(chosen.source.split("/...")[0])
        cycle = next((s for s in cands if s.layout == "per-module entries" and
                      layouts.fold(s.source.split("/...")[0]) == group), None)
    return chosen, cycle, why


def _named_array(log: LogData, name: str, want: str, ragged: str) -> Signal:
    """A named double[] entry: dead wheels, or differential [left, right]."""
    info = layouts.resolve(log, name, "--positions")
    if info.type != "double[]":
        raise DataLogError(f"--positions {info.name!r} has type {info.type}; expected one "
                           f"of {', '.join(layouts.POSITION_STRUCTS)}, double[], or a folder of "
                           f"per-module entries")
    arrays = [s for s in catalog.replay_specs() if s.double_array]
    # a bare double[] is the drivetrain nothing else finds by type, unless one is named
    kind = (next(s.name for s in arrays if not s.found_by_type) if want == "auto"
            else want)
    if not catalog.replay_spec(kind).double_array:
        raise DataLogError(f"--positions {info.name!r} is double[]: that is read as "
                           f"{', '.join(s.name for s in arrays)} positions, not {kind}")
    t, v = log.values(info.name, ragged=ragged)
    return Signal("positions", t, v, (info.name,), "double[]", kind, "m")


def _gyro(log: LogData, cfg: ReplayConfig, units: layouts.Options, positions: Signal | None,
          pose: Signal | None, cands: list[Signal] | None = None) -> tuple[Signal, str]:
    """The gyro signal and why (``cands``: the log's gyro candidates, when known;
    ``positions`` None: the choice ``--list`` shows for a log without positions)."""
    problems: list[DataLogError] = []
    if cands is None:
        cands = layouts.candidates(log, "gyro", units, problems)
    if cfg.gyro is not None:
        info = layouts.resolve(log, cfg.gyro, "--gyro")
        hits = [s for s in cands if info.name in s.entries]
        if not hits and info.type in ("double", "float"):
            if units.gyro is None:
                raise DataLogError(f"gyro entry {info.name!r} is a plain {info.type}: give "
                                   f"its units with --gyro-units deg, rad or rot")
            t, v = log.values(info.name)
            hits = [Signal("gyro", t, v * layouts.angle_scale(units.gyro), (info.name,),
                           "double", units=f"{units.gyro} (--gyro-units)")]
        if not hits:
            raise DataLogError(f"--gyro {info.name!r} has type {info.type}; expected "
                               f"struct:Rotation2d, Rotation2d[] with its timestamps, or a "
                               f"double (with --gyro-units)")
        chosen, why = hits[0], "named with --gyro"
    else:
        if positions is not None and positions.highRate:
            high = [s for s in cands if s.highRate]
            if high:
                cands = high
        else:
            cands = [s for s in cands if not s.highRate]
        brief = [s for s in cands if not gyro_rank(s, positions)[0]]
        cands = [s for s in cands if gyro_rank(s, positions)[0]]
        named = [s for s in cands if s.why]
        if not cands and problems:
            raise problems[0]
        if not cands and pose is not None:
            # CTRE's generated Telemetry publishes the drive state without the gyro; the
            # pose's heading is the gyro's plus a constant there, which is all odometry
            # takes from a gyro (its changes).
            return (Signal("gyro", pose.t, pose.values[:, 2].copy(), pose.entries,
                           "pose heading", units="rad"),
                    "no gyro in the log: the logged pose's heading stands in for it, so "
                    "only the translation is replayed independently")
        if not cands:
            raise DataLogError(_no_gyro(log, brief))
        chosen, why = _choose(named or cands, "gyro", "--gyro",
                              lambda s: gyro_rank(s, positions))
    if not chosen.units:
        raise DataLogError(f"gyro entry {chosen.source!r} is a plain number with no units "
                           f"in its name or metadata: give --gyro-units deg, rad or rot")
    return chosen, why


def _no_gyro(log: LogData, brief: list[Signal]) -> str:
    """What the log lacks when no gyro candidate is continuous."""
    said = [n for n in log.entries if gyro_rejected(n) is not None
            and log.entries[n].records > 0]
    parts = []
    if brief:
        parts.append(f"{len(brief)} with fewer than 10 records or spanning under 1 s "
                     f"({', '.join(s.source for s in brief[:3])}"
                     f"{', ...' if len(brief) > 3 else ''})")
    if said:
        parts.append(f"{len(said)} named as something else ({', '.join(said[:3])}"
                     f"{', ...' if len(said) > 3 else ''})")
    return (f"no continuous gyro{': ' + '; '.join(parts) if parts else ''} "
            f"(struct:Rotation2d, or a double named gyro, imu, yaw, heading or robot "
            f"angle); name one with --gyro")


_POSE_TYPES = ("struct:Pose2d, struct:Pose3d, a Field2d double[3], one of three pose doubles "
               "(X, Y, Angle) or a Pose2d string")


def _pose(log: LogData, cfg: ReplayConfig, units: layouts.Options, exclude: set[str],
          cands: list[Signal] | None = None) -> tuple[Signal | None, str]:
    """The logged pose and why (``cands``: the log's pose candidates, when known)."""
    if cands is None:
        cands = layouts.candidates(log, "pose", units)
    cands = [s for s in cands if not exclude & set(s.entries)]
    if cfg.pose is not None:
        info = layouts.resolve(log, cfg.pose, "--pose")
        hits = [s for s in cands if info.name in s.entries]
        if not hits:
            raise DataLogError(f"--pose {info.name!r} has type {info.type}, expected "
                               f"{_POSE_TYPES}")
        return hits[0], "named with --pose"
    usable = [s for s in cands if pose_score(s.entries[0])[0] > -10]
    if not usable:
        return None, ("no pose entry" if not cands else
                      f"none of {', '.join(s.source for s in cands)} is the robot's pose "
                      f"(name one with --pose)")
    chosen, why = _choose(usable, "pose", "--pose", pose_rank)
    rejected = [f"{s.source} ({pose_score(s.entries[0])[1].split(':')[0]})"
                for s in cands if pose_score(s.entries[0])[0] <= -10]
    if rejected:
        why += "; not " + ", ".join(rejected[:3])
    return chosen, why


def _named_pose(log: LogData, name: str, option: str, opts: layouts.Options) -> Signal:
    info = layouts.resolve(log, name, option)
    for s in layouts.candidates(log, "pose", opts):
        if info.name in s.entries:
            return s
    raise DataLogError(f"{option} {info.name!r} has type {info.type}, expected "
                       f"{_POSE_TYPES}")
