"""``python -m drivekin replay LOG --list``: a log's drivetrain-relevant entries first,
ranked as the replay ranks them, each with why (:func:`drivekin.replay.listing`).

Each entry line begins with the entry's name (``repr``-escaped when it holds a control or
other unprintable character), then its type, record count and median rate, then what
the replay makes of it. Candidates say ``position candidate``, ``velocity candidate``,
``gyro candidate`` or ``pose candidate`` with their rank, and ``(used)`` on the one the
replay would take; entries named like one but refused say why without those words.
Without ``showAll`` at most ``MAX_LINES`` lines are printed and the rest counted;
``showAll`` lists every entry. Nothing is replayed: the candidates are found (their
values decoded) once and ranked.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable

import numpy as np

from drivekin._core import loglayouts as layouts
from drivekin._core.candidates import (CONTINUOUS_RECORDS, CONTINUOUS_SPAN_US, gyro_rank,
                                       gyro_rejected, pose_rank, pose_score)
from drivekin._core.display import escape
from drivekin._core.loglayouts import Signal
from drivekin._core.replayinputs import _POSITION_RANK, _gyro, _pose, _positions
from drivekin.datalog import DataLogError, EntryInfo, LogData

if TYPE_CHECKING:
    from drivekin.replay import ReplayConfig

MAX_LINES = 60
MAX_RATE_HZ = 1000.0
_ANGLES = ("double", "float", "struct:Rotation2d")      # what a refused heading could be


def listed_rate(t: np.ndarray) -> float | None:
    """The median-interval rate (Hz) of timestamps ``t`` (µs), or None for fewer than
    ``CONTINUOUS_RECORDS`` records, a span under ``CONTINUOUS_SPAN_US`` or above
    ``MAX_RATE_HZ`` (records written in one burst, not a rate)."""
    if len(t) < CONTINUOUS_RECORDS:
        return None
    t = np.sort(t)
    if int(t[-1]) - int(t[0]) < CONTINUOUS_SPAN_US:
        return None
    rate = layouts.rate(t)
    return rate if 0 < rate <= MAX_RATE_HZ else None


def _word(role: str, s: Signal) -> str:
    if role == "positions":
        return "velocity" if s.integrated else "position"
    return role


def _rank(role: str, wheels: Signal | None) -> Callable[[Signal], Any]:
    if role == "gyro":
        return lambda s: gyro_rank(s, wheels)
    if role == "pose":
        return pose_rank
    return lambda s: _POSITION_RANK.get(s.layout, 0)


def _refused(role: str, s: Signal, wheels: Signal | None) -> str | None:
    """Why a found signal is not a candidate (words without pose or gyro), else None."""
    if role == "pose" and pose_score(s.entries[0])[0] <= -10:
        return pose_score(s.entries[0])[1].split(":")[0]
    if role == "gyro" and not gyro_rank(s, wheels)[0]:
        span = (int(s.t.max()) - int(s.t.min())) / 1e6 if len(s.t) else 0.0
        return f"{len(s.t)} records over {span:.2g} s (not continuous)"
    return None


def listing(log: LogData, config: ReplayConfig | None = None, showAll: bool = False) -> str:
    """A log's entries as ``python -m drivekin replay LOG --list`` prints them: the
    drivetrain candidates first, ranked, each with why, the one the replay would use
    marked ``(used)``; at most ``MAX_LINES`` lines unless ``showAll``. Nothing is
    replayed."""
    from drivekin.replay import ReplayConfig
    cfg = config or ReplayConfig()
    opts = layouts.Options(cfg.driveUnits, cfg.turnUnits, cfg.gyroUnits, cfg.wheelRadius,
                           cfg.ragged)
    notes: list[str] = []
    found: dict[str, list[Signal]] = {}
    for role in dict.fromkeys(lay.role for lay in layouts.LAYOUTS):
        problems: list[DataLogError] = []
        found[role] = layouts.candidates(log, role, opts, problems)
        notes += [f"{role}: {e}" for e in problems]
    used: dict[str, Signal] = {}
    wheels = None
    try:
        wheels = used["positions"] = _positions(log, cfg, opts)[0]
    except DataLogError as e:
        notes.append(f"the replay would stop: {e}")
    try:
        pose = _pose(log, cfg, opts, set(), found.get("pose", []))[0]
        if pose is not None:
            used["pose"] = pose
        if cfg.heading != "wheels":
            used["gyro"] = _gyro(log, cfg, opts, wheels, pose, found.get("gyro", []))[0]
    except DataLogError as e:
        notes.append(str(e))
    stand_in = used.get("gyro") is not None and used["gyro"].layout == "pose heading"

    infos = {e.name: e for e in log.entries.values() if not layouts.is_schema(e.name)}
    width = min(max((len(escape(n)) for n in infos), default=5), 60)
    tw = max((len(e.type) for e in infos.values()), default=4)
    tw = min(tw, 30)

    def row(e: EntryInfo, text: str) -> str:
        rate = listed_rate(log._entries[e.name].ts)
        hz = f"{rate:.0f} Hz" if rate is not None else "-"
        return (f"{escape(e.name):<{width}}  {e.type[:30]:<{tw}}  {e.records:>7} rec  "
                f"{hz:>7}  {text}").rstrip()

    cand_rows: list[str] = []
    refused_rows: list[str] = []
    listed: set[str] = set()
    for role, signals in found.items():
        # The choice may be its own reading of the same entries (positions are found
        # again by the choice): the candidate holding the same entries stands for it.
        chosen = next((s for s in signals if role in used and
                       s.entries == used[role].entries), None)
        good = [s for s in signals if _refused(role, s, wheels) is None]
        good.sort(key=_rank(role, wheels), reverse=True)
        if chosen is not None and chosen in good:
            good.remove(chosen)
            good.insert(0, chosen)
        for k, s in enumerate(good, 1):
            mark = " (used)" if s is chosen else ""
            kind = f"{s.layout}, {s.drivetrain}" if s.drivetrain else s.layout
            text = f"{_word(role, s)} candidate {k}{mark}: {kind}"
            text += "".join(f"; {x}" for x in (s.why, s.units) if x)
            if role == "pose" and stand_in and s is chosen:
                text += "; its heading stands in for the gyro (the log has none)"
            for n in s.entries:
                if n not in listed and n in infos:
                    listed.add(n)
                    cand_rows.append(row(infos[n], text))
        for s in signals:
            why = _refused(role, s, wheels)
            if why is not None and s.entries[0] not in listed:
                listed.add(s.entries[0])
                refused_rows.append(row(infos[s.entries[0]], f"not used: {why}"))
    for n, e in infos.items():
        why = gyro_rejected(n)
        if (why is not None and n not in listed and e.records > 0 and e.type in _ANGLES
                and not n.rpartition("/")[2].startswith(".")):
            listed.add(n)
            refused_rows.append(row(e, f"not used: {why}"))
    rest = [e for n, e in infos.items() if n not in listed]
    head = (f"{escape(log.source)}: {len(infos)} entries (schemas not counted); drivetrain "
            f"candidates first, best first")
    notes_rows = [f"note: {x}" for x in notes]
    if showAll:
        return "\n".join([head, *cand_rows, *refused_rows, *(row(e, "") for e in rest),
                          *notes_rows])
    room = MAX_LINES - 2 - len(notes_rows)
    shown_rows = (cand_rows + refused_rows)[:max(room, 0)]
    hidden = len(cand_rows) + len(refused_rows) - len(shown_rows) + len(rest)
    tail = [f"... and {hidden} more entries (--all lists every entry)"] if hidden else []
    return "\n".join([head, *shown_rows, *tail, *notes_rows][:MAX_LINES])
