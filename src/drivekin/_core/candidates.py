"""Pose and gyro candidates: the finders the layouts table (:mod:`loglayouts`) lists for
the roles ``pose`` and ``gyro`` (beside its AdvantageKit and CTRE ones), and how
:mod:`replayinputs` ranks what they find.

**Poses.** The robot's own pose, never what it was told to do or what a camera saw:

* tier 3, a ``struct:Pose2d`` / ``struct:Pose3d`` entry (the robot's own log);
* tier 2, the same pose in the robot's own words: three doubles beside each other
  (``/Pose/RobotPoseX``, ``RobotPoseY``, ``RobotPoseAngle``; ``Drive/X``, ``Y``,
  ``Heading``) or a string entry holding WPILib's ``Pose2d.toString()``
  (``Pose2d(Translation2d(X: 1.00, Y: 2.00), Rotation2d(Rads: 0.50, Deg: 28.65))``,
  Java; robotpy's ``Pose2d(Translation2d(x=1.000000, y=2.000000), Rotation2d(0.500000))``)
  or ``x,y,θ``; tier 1 when NetworkTables mirrored them (a dashboard copy);
* tier 0, a Field2d ``double[3]`` (SmartDashboard's copy, in degrees).

Within a tier the name decides (:func:`pose_score`); a name saying vision, camera,
target, setpoint, turret, limelight (its ``botpose``), a simulation's truth, ... is never
taken. An entry with fewer than ``CONTINUOUS_RECORDS`` records or spanning less than
``CONTINUOUS_SPAN_US`` ranks below every one that does (PathPlanner's one-record
``currentPose``). The angle of three doubles or a ``x,y,θ`` string takes its unit from
its name or metadata; without one it is read as degrees when a value lies beyond ±π
(no Pose2d's radians do), else as radians (Pose2d's ``getRotation().getRadians()``), and
the units text says which.

**Gyros.** Continuous readings of the robot's heading: ``CONTINUOUS_RECORDS`` records or
more spanning ``CONTINUOUS_SPAN_US`` or more (a short log's gyro counts when it spans the
wheel samples), never a one-record value, a setpoint, a stored, reset or offset value,
a rate, a distance, a module's or turret's angle. Names rank: YAGSL's
``swerve/imu/raw`` (degrees: its odometry's gyro) first, then device words (gyro, imu,
pigeon, navX, ahrs, yaw; a SmartDashboard ``Gyro`` widget's ``Value``, degrees), then
the robot's heading (``Heading``, ``Robot Angle``; one higher under a drivetrain path:
drive, chassis, swerve, so ``DriveTrain/Robot Angle`` passes a dashboard's ``Heading``). Units come from the name (``Degrees``, ``Deg``, ``Rad``),
the metadata or the convention just named; otherwise ``--gyro-units`` must say.
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

from drivekin._core import catalog
from drivekin._core.loglayouts import (_TO_RAD, Options, Signal, _join, _live,
                                       _module_index, fold, unit_of, unit_suffix)
from drivekin.datalog import DataLogError, EntryInfo, LogData
from drivekin.geometry3d import Pose3d

CONTINUOUS_RECORDS = 10
CONTINUOUS_SPAN_US = 1_000_000


def continuous(t: np.ndarray) -> bool:
    """At least ``CONTINUOUS_RECORDS`` records spanning ``CONTINUOUS_SPAN_US`` or more."""
    return len(t) >= CONTINUOUS_RECORDS and int(t.max()) - int(t.min()) >= CONTINUOUS_SPAN_US


# --------------------------------------------------------------------------------------
# Gyros

_YAGSL_IMU = "swerve/imu/raw"
_YAGSL_DEGREES = (_YAGSL_IMU, "swerve/imu/adjusted")
_GYRO_DEVICE = ("gyro", "imu", "pigeon", "navx", "ahrs", "yaw")
_GYRO_HEADING = ("heading", "robotangle")
_DRIVE_PATH = ("drive", "chassis", "swerve")
_NOT_GYRO = ("velocity", "rate", "persec", "omega", "turn", "steer", "module", "absolute",
             "connected", "pitch", "roll", "setpoint", "target", "desired", "goal",
             "stored", "reset", "offset", "turret", "distance", "vision", "camera",
             "limelight", "photon", "option", "accel", "error", "tolerance")


def gyro_score(name: str) -> tuple[int, str] | None:
    """How much a name says the robot's heading (higher first) and why; None for a name
    that is not a gyro's (no gyro word, or a word saying it is something else)."""
    f = fold(name)
    if any(w in f for w in _NOT_GYRO):
        return None
    if f.endswith(_YAGSL_IMU):
        return 5, "YAGSL's IMU reading (its odometry's heading)"
    device = next((w for w in _GYRO_DEVICE if w in f), None)
    heading = next((w for w in _GYRO_HEADING if w in f), None)
    if device is None and heading is None:
        return None
    score, why = (3, f"its name says {device}") if device else (
        2, f"its name says {'robot angle' if heading == 'robotangle' else heading}")
    path = f.rpartition("/")[0]
    if device is None and any(w in path for w in _DRIVE_PATH):
        score, why = score + 1, why + " under the drivetrain"
    return score, why


def gyro_rejected(name: str) -> str | None:
    """Why an entry named like a gyro is not one (the word that says so), else None."""
    f = fold(name)
    if not any(w in f for w in _GYRO_DEVICE + _GYRO_HEADING):
        return None
    word = next((w for w in _NOT_GYRO if w in f), None)
    return None if word is None else f"its name says {word!r}"


def _gyro_widget(log: LogData, e: EntryInfo) -> bool:
    """A SmartDashboard Gyro widget's ``Value`` (its ``.type`` entry reads ``Gyro``):
    WPILib's Gyro sendable publishes the angle in degrees."""
    head, _, leaf = e.name.rpartition("/")
    kind = log.entries.get(head + "/.type")
    if leaf != "Value" or kind is None or kind.type != "string" or kind.records == 0:
        return False
    return bytes(log.records(kind.name)[1][-1]) == b"Gyro"


def _module_entry(name: str) -> bool:
    return any(_module_index(p) is not None for p in name.split("/")[:-1])


def find_struct_gyro(log: LogData, units: Options) -> list[Signal]:
    out = []
    for e in _live(log):
        if e.type != "struct:Rotation2d" or e.records < 2 or _module_entry(e.name):
            continue
        named = gyro_score(e.name)
        if named is None and gyro_rejected(e.name) is not None:
            continue
        t, v = log.values(e.name)
        out.append(Signal("gyro", t, v.astype(np.float64), (e.name,), "Rotation2d",
                          units="rad", why=named[1] if named else ""))
    return out


def find_double_gyro(log: LogData, units: Options) -> list[Signal]:
    out = []
    pose_parts = {g[3].name for g in _double_pose_groups(log)}   # the pose's own heading
    for e in _live(log):
        if e.type not in ("double", "float") or e.records < 2 or e.name in pose_parts:
            continue
        widget = _gyro_widget(log, e)
        named = (3, "a SmartDashboard Gyro widget's value") if widget else gyro_score(e.name)
        if named is None:
            continue
        suffix = unit_suffix(fold(e.name.rpartition("/")[2]))
        u, said = units.gyro, "--gyro-units"
        if u is None:
            u, said = unit_of(suffix, e.metadata), "the entry's name or metadata"
        if u is None and (widget or fold(e.name).endswith(_YAGSL_DEGREES)):
            u, said = "deg", "YAGSL's convention" if not widget else "WPILib's Gyro widget"
        t, v = log.values(e.name)
        if u is None:
            out.append(Signal("gyro", t, v, (e.name,), "double", units="",
                              why=named[1] + "; needs --gyro-units"))
            continue
        out.append(Signal("gyro", t, v * _TO_RAD[u], (e.name,), "double",
                          units=f"{u} ({said})", why=named[1]))
    return out


def gyro_rank(s: Signal, wheels: Signal | None = None) -> tuple[bool, int, bool, bool]:
    """A gyro candidate's rank (higher first): continuous (or spanning the wheel samples
    ``wheels``), the name's score, a struct over a plain number, known units."""
    named = gyro_score(s.entries[0])
    cont = continuous(s.t) or (wheels is not None and len(s.t) >= 2 and len(wheels.t) > 0
                               and s.t[0] <= wheels.t[0] and s.t[-1] >= wheels.t[-1])
    return cont, named[0] if named else 0, s.layout != "double", bool(s.units)


# --------------------------------------------------------------------------------------
# Poses

# Words that make a pose the robot's own, and words that make it something else (what
# the robot was told to do, or saw, or a simulation's truth).
_POSE_GOOD = (("odometry/robot", 6, "AdvantageKit's odometry output"),
              ("drivestate/pose", 5, "CTRE's swerve drive state"),
              ("estimat", 4, "an estimate of the robot's pose"),
              ("odometry", 3, "odometry"),
              ("currentpose", 3, "the current pose"),
              ("field/robot", 2, "Field2d's robot pose"),
              ("robot", 1, "the robot"),
              ("pose", 1, "a pose"))
_POSE_BAD = ("setpoint", "target", "trajectory", "desired", "goal", "reference",
             "commanded", "vision", "camera", "tag", "replayoutputs", "truth", "sim",
             "ghost", "start", "initial", "reset", "turret", "limelight",
             "photon", "cargo", "note", "intake")


def pose_score(name: str) -> tuple[int, str]:
    """How much a pose entry's name says it is the robot's own pose, and why (-10 with
    the word that says it is not)."""
    f = fold(name)
    for w in _POSE_BAD:
        if w in f:
            return -10, f"its name says {w!r}: not the robot's measured pose"
    for w, s, why in _POSE_GOOD:
        if w in f:
            return s, why
    return 0, "no hint in the name"


_POSE_TIER = {"Pose2d": 3, "Pose3d": 3, "CTRE DriveState": 3, "three doubles": 2,
              "Pose2d string": 2, "Field2d double[3]": 0}


def pose_rank(s: Signal) -> tuple[bool, int, int, bool, bool]:
    """A pose candidate's rank (higher first): continuous, the robot's own log over a
    NetworkTables copy (see the module docstring), the name's score, CTRE's clock over
    its Pose2d read plainly, a 2-D pose over a 3-D one (the replay is planar)."""
    tier = _POSE_TIER.get(s.layout, 0)
    if tier == 2 and s.entries[0].startswith("NT:"):
        tier = 1
    return (continuous(s.t), tier, pose_score(s.entries[0])[0],
            s.layout == "CTRE DriveState", s.layout != "Pose3d")


def _planar(rows: np.ndarray) -> np.ndarray:
    """Pose3d struct rows (N, 7) ``[x, y, z, qw, qx, qy, qz]`` in the plane, (N, 3)
    ``[x, y, θ]``: each unpacked as WPILib unpacks it (the quaternion normalised), then
    its ``toPose2d()`` (x, y and the rotation about z)."""
    build = catalog.BY_CLASS[Pose3d].build
    assert build is not None
    out = np.empty((len(rows), 3))
    for i, row in enumerate(rows.tolist()):
        p = build(*row).toPose2d()
        out[i] = (p.getX(), p.getY(), p.getRotation().getRadians())
    return out


def _find_struct_pose(type_string: str, layout: str, units_text: str,
                      planar: Callable[[np.ndarray], np.ndarray] | None
                      ) -> Callable[[LogData, Options], list[Signal]]:
    def find(log: LogData, units: Options) -> list[Signal]:
        out = []
        for e in _live(log):
            if e.type == type_string:
                t, v = log.values(e.name)
                why = pose_score(e.name)[1]
                out.append(Signal("pose", t, v if planar is None else planar(v), (e.name,),
                                  layout, units=units_text, why=why))
        return out
    return find


find_pose2d = _find_struct_pose("struct:Pose2d", "Pose2d", "m; rad", None)
find_pose3d = _find_struct_pose("struct:Pose3d", "Pose3d", "m; rad (toPose2d)", _planar)


def find_field2d_pose(log: LogData, units: Options) -> list[Signal]:
    out = []
    for e in _live(log):
        if e.type != "double[]":
            continue
        f = fold(e.name)
        if not any(w in f for w in ("field", "pose", "robot")):
            continue
        try:
            t, v = log.values(e.name)
        except DataLogError:
            continue
        if v.ndim != 2 or v.shape[1] != 3:
            continue
        why = pose_score(e.name)[1]
        P = v.copy()
        P[:, 2] = np.radians(P[:, 2])
        out.append(Signal("pose", t, P, (e.name,), "Field2d double[3]",
                          units="m; deg (Field2d)", why=why))
    return out


def _angle(values: np.ndarray, unit: str | None, where: str) -> tuple[np.ndarray, str]:
    """A pose's logged angles in rad and the units text (see the module docstring)."""
    if unit is not None:
        return values * _TO_RAD[unit], f"θ {unit} ({where})"
    if values.size and np.abs(values).max() > math.pi + 0.01:
        return np.radians(values), "θ deg (no unit named; values beyond ±π)"
    return values.copy(), "θ rad (no unit named; assumed, as all values lie within ±π)"


_ANGLE_WORDS = ("angle", "heading", "rotation", "theta", "yaw")


def _pose_part(leaf: str) -> tuple[str, str, str] | None:
    """(stem, part, unit suffix) of a folded leaf naming a pose's x, y or angle."""
    suffix = unit_suffix(leaf)
    core = leaf[:len(leaf) - len(suffix)] if suffix else leaf
    for w in _ANGLE_WORDS:
        if core.endswith(w):
            return core[:-len(w)], "angle", suffix
    if core.endswith(("x", "y")) and suffix in ("", "m", "meters", "metres", "meter"):
        return core[:-1], core[-1], suffix
    return None


def _double_pose_groups(log: LogData) -> list[tuple[str, EntryInfo, EntryInfo, EntryInfo, str]]:
    """(folder, x, y, angle entries, the angle's unit suffix) of three doubles beside each
    other holding a pose: ``...X``, ``...Y``, ``...Angle`` (or Heading, Rotation, Theta,
    Yaw) with the same stem, not named as something other than the robot's pose."""
    groups: dict[tuple[str, str], dict[str, tuple[EntryInfo, str]]] = {}
    for e in _live(log):
        if e.type not in ("double", "float") or e.records < 2:
            continue
        head, _, leaf = e.name.rpartition("/")
        part = _pose_part(fold(leaf))
        if part is not None:
            groups.setdefault((head, part[0]), {}).setdefault(part[1], (e, part[2]))
    return [(head, parts["x"][0], parts["y"][0], parts["angle"][0], parts["angle"][1])
            for (head, stem), parts in groups.items()
            if len(parts) == 3 and pose_score(f"{head}/{stem}")[0] >= 0]


def find_double_pose(log: LogData, units: Options) -> list[Signal]:
    out = []
    for head, xe, ye, ae, asuf in _double_pose_groups(log):
        series = [log.values(n.name) for n in (xe, ye, ae)]
        # A robot writes the three one after another in its loop (microseconds apart):
        # one pose per burst, at its last record.
        u = np.unique(np.concatenate([ts for ts, _ in series]))
        clock = u[np.append(np.diff(u) > 1000, True)]
        t, P = _join(series, head or "/", clock)
        P[:, 2], text = _angle(P[:, 2], unit_of(asuf, ae.metadata),
                               "the angle's name or metadata")
        why = f"x, y and {ae.name.rpartition('/')[2]} logged together"
        out.append(Signal("pose", t, P, (xe.name, ye.name, ae.name), "three doubles",
                          units=f"x, y m (assumed); {text}", why=why))
    return out


_POSE_WORDS = ("pose", "odometry", "robot", "position")


def _parse_pose(text: str) -> tuple[float, float, float, bool] | None:
    """(x, y, θ, θ named as radians) from WPILib's Java ``Pose2d.toString()``, robotpy's
    repr or ``x,y,θ``; None for anything else."""
    if len(text) > 200:
        return None
    named = text.startswith("Pose2d(")
    if named:
        text = text.replace("Pose2d", " ").replace("Translation2d", " ").replace(
            "Rotation2d", " ")
    elif text.count(",") != 2:
        return None
    numbers = []
    for token in text.replace(",", " ").replace("(", " ").replace(")", " ").replace(
            ":", " ").replace("=", " ").split():
        try:
            numbers.append(float(token))
        except ValueError:
            if not named:
                return None
    # Java: X, Y, Rads, Deg (two decimals); robotpy: x, y, radians.
    if len(numbers) not in ((3, 4) if named else (3,)):
        return None
    if not all(math.isfinite(v) for v in numbers):
        return None
    return numbers[0], numbers[1], numbers[2], named


def find_string_pose(log: LogData, units: Options) -> list[Signal]:
    """A string entry holding WPILib's ``Pose2d(...)`` text or ``x,y,θ``."""
    out = []
    for e in _live(log):
        if e.type != "string" or e.records < 2 or not any(w in fold(e.name)
                                                          for w in _POSE_WORDS):
            continue
        t, raw = log.records(e.name)
        rows = []
        for b in raw:
            try:
                p = _parse_pose(bytes(b).decode("utf-8"))
            except UnicodeDecodeError:
                p = None
            if p is None:
                break
            rows.append(p)
        if len(rows) != len(raw):
            continue
        P = np.array([r[:3] for r in rows], dtype=np.float64)
        named = all(r[3] for r in rows)
        if named:
            text = "x, y m; θ rad (WPILib's Pose2d text, to its printed digits)"
        else:
            P[:, 2], text = _angle(P[:, 2], None, "")
            text = "x, y m (assumed); " + text
        out.append(Signal("pose", np.asarray(t, dtype=np.int64), P, (e.name,),
                          "Pose2d string", units=text,
                          why="WPILib's Pose2d text" if named else "x,y,θ text"))
    return out
