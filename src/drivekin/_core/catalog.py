"""The catalog: one registration per public class, holding everything the integrations
need to know about it, so that adding a type touches its own module and its entry here.

Each :class:`Entry` gives the class's kind and drivetrain, and, where they exist:

* its **wire form**: the doubles of a value in WPILib's member order (``flatten``) and
  the constructor from them (``build``), which both serializations use;
* its **struct** type (name, schema, nested types; :mod:`drivekin.wpistruct`);
* its **protobuf** message (name, file, fields; :mod:`drivekin.protobuf`);
* its **robotpy-wpimath peer** (its class names in robotpy 2026 and 2027 and the two
  converters, exact but for robotpy's renormalising Rotation3d constructor;
  :mod:`drivekin.interop`), or why there is none;
* for an odometry class, the **log entry type** of its position samples, by which
  :mod:`drivekin.replay` recognises a drivetrain in a log.
* an **example**: a factory of one typical valid instance (the tests' and tools' fixture).

``tests/api/test_catalog.py`` fails, naming the class, when a public class of drivekin
has no entry. The test registries (adversarial suite, allocation tests, leak check,
benchmarks) take their lists of drivetrains from here.
"""
from __future__ import annotations

import math
import operator
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Optional, Union

import numpy as np

import drivekin as _dk
from drivekin._core import replayspec
from drivekin.chassis import ChassisAccelerations, ChassisVelocities
from drivekin.deadwheel import DeadWheelKinematics
from drivekin.differential import (
    DifferentialDriveKinematics,
    DifferentialDriveWheelAccelerations,
    DifferentialDriveWheelPositions,
    DifferentialDriveWheelVelocities,
)
from drivekin.geometry import Pose2d, Rotation2d, Transform2d, Translation2d, Twist2d
from drivekin.geometry import _rotation_from_cos_sin  # type: ignore[attr-defined]
from drivekin.geometry3d import (
    CoordinateAxis,
    CoordinateSystem,
    Pose3d,
    Quaternion,
    Rotation3d,
    Transform3d,
    Translation3d,
    Twist3d,
)
from drivekin.geometry3d import _rotation3d_from_quaternion  # type: ignore[attr-defined]
from drivekin.motor import DCMotor
from drivekin.mecanum import (
    MecanumDriveKinematics,
    MecanumDriveWheelAccelerations,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
)
from drivekin.swerve import SwerveDriveKinematics
from drivekin.swervemodule import (
    SwerveModuleAcceleration,
    SwerveModulePosition,
    SwerveModuleVelocity,
)

#: Every value a serialization packs (the classes with a struct and a protobuf message);
#: written out for type checkers, and checked against the entries by the tests.
SerializableValue = Union[
    Translation2d, Rotation2d, Pose2d, Transform2d, Twist2d,
    Translation3d, Quaternion, Rotation3d, Pose3d, Transform3d, Twist3d,
    ChassisVelocities, ChassisAccelerations,
    SwerveModuleVelocity, SwerveModulePosition, SwerveModuleAcceleration,
    MecanumDriveWheelVelocities, MecanumDriveWheelPositions, MecanumDriveWheelAccelerations,
    DifferentialDriveWheelVelocities, DifferentialDriveWheelPositions,
    DifferentialDriveWheelAccelerations,
    DifferentialDriveKinematics, MecanumDriveKinematics, SwerveDriveKinematics,
]

GEOMETRY2D_FILE = "wpimath/protobuf/geometry2d.proto"
GEOMETRY3D_FILE = "wpimath/protobuf/geometry3d.proto"
KINEMATICS_FILE = "wpimath/protobuf/kinematics.proto"

#: A protobuf field: (name, number, message type or None for a double, repeated).
Field = tuple[str, int, Optional[str], bool]


@dataclass(frozen=True)
class Struct:
    """A WPILib struct type: ``count`` doubles per value. A repeated struct has one type
    per count N >= ``least`` of its member, named ``name__N`` with the schema
    ``"<schema>[N]"`` (SwerveDriveKinematics); ``repeats(obj)`` is an instance's N and
    ``count`` is per member."""
    name: str
    schema: str
    count: int
    nested: tuple[type, ...] = ()
    repeats: Callable[[Any], int] | None = None
    least: int = 0


@dataclass(frozen=True)
class Proto:
    """A WPILib protobuf message: its file, its place in that file (WPILib's declaration
    order, which the descriptors keep) and its fields."""
    message: str
    file: str
    index: int
    fields: tuple[Field, ...]


@dataclass(frozen=True)
class Peer:
    """The robotpy-wpimath class(es) of the same meaning. ``names`` are robotpy 2026's, in
    ``wpimath.<module>``; robotpy 2027 has every class in ``wpimath`` itself, under
    ``renamed`` (one per name) where WPILib 2027 renamed it (ChassisSpeeds:
    ChassisVelocities), else under the same name. ``to(obj, wpimath)`` builds the
    installed generation's object (``wpimath.cls(name)`` takes the 2027 name) and
    ``frm(obj)`` reads either generation's (:func:`robotpy_attr` where their spellings
    differ); both copy every float exactly, except that robotpy's Rotation3d constructor
    renormalises what ``to`` gives it."""
    module: str
    names: tuple[str, ...]
    to: Callable[[Any, Any], Any]
    frm: Callable[[Any], Any]
    renamed: tuple[str, ...] = ()

    @property
    def names2027(self) -> tuple[str, ...]:
        """robotpy 2027's class names (WPILib 2027's; ``SwerveDrive{N}Kinematics`` kept)."""
        return self.renamed or self.names


@dataclass(frozen=True)
class Entry:
    cls: type
    kind: str                      # "value", "kinematics", "odometry", "estimator",
                                   # "odometry3d", "estimator3d", "helper", "warning"
    drivetrain: str | None = None  # "swerve", "mecanum", "differential", "deadwheel", ...
    flatten: Callable[[Any], tuple[float, ...]] | None = None
    build: Callable[..., Any] | None = None
    struct: Struct | None = None
    proto: Proto | None = None
    peer: Peer | None = None
    no_peer: str | None = None     # why interop has no robotpy-wpimath peer ({}: the name)
    positions: str | None = None   # odometry: the log type of one positions sample
    # odometry: start one from its kinematics (or None), the gyro, the first row of a
    # positions stack as drivekin.batch.replay reads it, and the start pose (log replay)
    start: Callable[[Any, Rotation2d, Any, Pose2d], Any] | None = None
    steered: bool = False          # kinematics: its wheels are steered modules
    # odometry: what log replay and calibration know of the drivetrain (_core/replayspec)
    replay: Any = None
    # One typical valid instance (None: the class has no instances); the test registries
    # (adversarial suite, allocation tests, leak check, benchmarks) and tools use it.
    example: Callable[[], Any] | None = None
    # The class has robotpy 2027's snake_case names (_core/pynames): every class but
    # PathPlannerLib's, whose Python port keeps the Java spelling.
    robotpy_names: bool = True


# ---------------------------------------------------------------------------------------
# robotpy-wpimath peers. robotpy 2027 spells members in snake_case, made from the C++ name
# (tests/data/robotpy2027-names.json: get_modules, front_left, nominal_voltage, from_matrix),
# robotpy 2026 in camelCase (getModules, frontLeft, nominalVoltage, fromMatrix); single
# words (x, cos, rotation, angle, vx, left) are the same in both.

_MISSING = object()


def robotpy_attr(obj: Any, new: str, old: str) -> Any:
    """``obj.<new>`` (robotpy 2027's spelling), or ``obj.<old>`` (robotpy 2026's) when
    ``obj`` has no ``new``."""
    value = getattr(obj, new, _MISSING)
    return getattr(obj, old) if value is _MISSING else value


def qualified(obj: object) -> str:
    # Both libraries have a Pose2d, a Rotation2d, ...: always say whose (builtins aside).
    t = type(obj)
    module = getattr(t, "__module__", None) or "?"
    return t.__qualname__ if module == "builtins" else f"{module}.{t.__qualname__}"


# Rotations are carried as the stored (cos, sin) pair, never through the angle, so
# conversions are bit-exact both ways.

def _check_unit(c: float, s: float, r: object, where: str) -> None:
    # A rotation is a unit (cos, sin) pair, or the NaN pair of a non-finite angle.
    # robotpy-wpimath stores (0, 0) for Rotation2d(x, y) when hypot(x, y) overflows
    # (x/inf; drivekin scales the vector first): that is no rotation, and neither side
    # can rebuild it from its pair.
    if not (c != c and s != s) and not abs((c * c + s * s) - 1.0) <= 1e-9:
        raise ValueError(f"{where}: this {qualified(r)} stores (cos, sin) = ({c!r}, {s!r}), "
                         "which is not a unit vector")


def _rotation_to(r: Rotation2d, w: Any) -> Any:
    c, s = r.getCos(), r.getSin()
    _check_unit(c, s, r, "toWpimath()")
    cls = w.cls("Rotation2d")
    if c == c and s == s:
        # robotpy's Rotation2d(x, y) divides by hypot(x, y) (2026 and 2027 alike): exact
        # whenever that is 1.0 (division by a positive number keeps the sign of zero, so
        # == suffices here).
        out = cls(c, s)
        if out.cos() == c and out.sin() == s:
            return out
    # Otherwise (and for the NaN pair of a non-finite angle) fromMatrix (2027: from_matrix)
    # copies R(0,0) and R(1,0) as they are; NaN passes its orthogonality check.
    return robotpy_attr(cls, "from_matrix", "fromMatrix")(((c, -s), (s, c)))


def _rotation_from(r: Any) -> Rotation2d:
    c, s = r.cos(), r.sin()
    # The stored pair is copied as is (a unit vector, or NaN for a non-finite angle).
    # Rotation2d(x, y) would renormalise it, and Rotation2d(angle) would recompute it.
    _check_unit(c, s, r, "fromWpimath()")
    return _rotation_from_cos_sin(c, s)  # type: ignore[no-any-return]


def _translation_to(t: Translation2d, w: Any) -> Any:
    return w.cls("Translation2d")(t.x, t.y)


def _translation_from(t: Any) -> Translation2d:
    return Translation2d(t.x, t.y)


# 3-D rotations are carried as the stored quaternion. robotpy builds a Rotation3d only
# through constructors that renormalise (Rotation3d(Quaternion) divides by the norm it
# computes, which for a unit quaternion may be one ulp off 1), so toWpimath may move
# each component by a few ulps; fromWpimath copies robotpy's stored quaternion as is.

def _quaternion_parts(q: Any) -> tuple[float, float, float, float]:
    # robotpy 2027's Quaternion has the properties w, x, y, z; 2026's the methods W() ...
    w: Any = getattr(q, "w", _MISSING)
    if w is _MISSING:
        return (q.W(), q.X(), q.Y(), q.Z())
    return (w, q.x, q.y, q.z)


def _flat_quaternion(q: Quaternion) -> tuple[float, float, float, float]:
    return (q.getW(), q.getX(), q.getY(), q.getZ())


def _rotation3d_to(r: Rotation3d, w: Any) -> Any:
    q = _flat_quaternion(r.getQuaternion())
    return w.cls("Rotation3d")(w.cls("Quaternion")(*q))


def _rotation3d_from(r: Any) -> Rotation3d:
    q = _quaternion_parts(robotpy_attr(r, "get_quaternion", "getQuaternion")())
    try:
        return _rotation3d_from_quaternion(*q)  # type: ignore[no-any-return]
    except ValueError:
        raise ValueError(f"fromWpimath(): this {qualified(r)} stores the quaternion {q!r}, "
                         "which is not a unit quaternion") from None


def _translation3d_to(t: Translation3d, w: Any) -> Any:
    return w.cls("Translation3d")(t.x, t.y, t.z)


def _translation3d_from(t: Any) -> Translation3d:
    return Translation3d(t.x, t.y, t.z)


def _frame3d_peer(cls: type) -> Peer:
    # Pose3d and Transform3d: (translation, rotation) on both sides.
    name = cls.__name__
    return Peer("geometry", (name,),
                lambda p, w: w.cls(name)(_translation3d_to(p.getTranslation(), w),
                                         _rotation3d_to(p.getRotation(), w)),
                lambda p: cls(_translation3d_from(p.translation()),
                              _rotation3d_from(p.rotation())))


#: robotpy-wpimath's SwerveDriveNKinematics (2026 and 2027).
SWERVE_MODULE_COUNTS = (2, 3, 4, 6)


def _swerve_to(k: SwerveDriveKinematics, w: Any) -> Any:
    n = k.getNumModules()
    if n not in SWERVE_MODULE_COUNTS:
        raise ValueError(
            f"toWpimath(): robotpy-wpimath has SwerveDrive2Kinematics, "
            f"SwerveDrive3Kinematics, SwerveDrive4Kinematics and SwerveDrive6Kinematics "
            f"only; this SwerveDriveKinematics has {n} modules")
    cls = w.cls(f"SwerveDrive{n}Kinematics")
    return cls(*(_translation_to(t, w) for t in k.getModules()))


def _swerve_from(k: Any) -> SwerveDriveKinematics:
    return SwerveDriveKinematics([_translation_from(t)
                                  for t in robotpy_attr(k, "get_modules", "getModules")()])


def _wheels_from(cls: type, fields: tuple[tuple[str, str], ...]) -> Callable[[Any], Any]:
    # fields: (robotpy 2027's name, robotpy 2026's = drivekin's) per wheel, in order.
    return lambda v: cls(*(robotpy_attr(v, new, old) for new, old in fields))


def _wheel_positions_to(name: str,
                        fields: tuple[tuple[str, str], ...]) -> Callable[[Any, Any], Any]:
    def to(p: Any, w: Any) -> Any:
        # Set on a default instance: robotpy 2026's takes no arguments.
        out = w.cls(name)()
        for new, old in fields:
            setattr(out, new if hasattr(out, new) else old, getattr(p, old))
        return out
    return to


# ---------------------------------------------------------------------------------------
# Wire forms and schemas shared by several entries

def _doubles(*names: str) -> tuple[Field, ...]:
    return tuple((n, i, None, False) for i, n in enumerate(names, 1))


def _value_and_angle(name: str) -> tuple[Field, ...]:
    return ((name, 1, None, False), ("angle", 2, "ProtobufRotation2d", False))


_POSE_FIELDS: tuple[Field, ...] = (("translation", 1, "ProtobufTranslation2d", False),
                                   ("rotation", 2, "ProtobufRotation2d", False))
_POSE_SCHEMA = "Translation2d translation;Rotation2d rotation"
_MECANUM = ("front_left", "front_right", "rear_left", "rear_right")
_MECANUM_ATTRS = ("frontLeft", "frontRight", "rearLeft", "rearRight")
# robotpy 2027's mecanum wheel fields are spelled as the wire form's, 2026's as drivekin's.
_MECANUM_PEER = tuple(zip(_MECANUM, _MECANUM_ATTRS))
_MECANUM_GETTERS = (("get_front_left", "getFrontLeft"), ("get_front_right", "getFrontRight"),
                    ("get_rear_left", "getRearLeft"), ("get_rear_right", "getRearRight"))
_DIFFERENTIAL_PEER = (("left", "left"), ("right", "right"))
_R = Rotation2d
_T = Translation2d


def _flat_pose(p: Any) -> tuple[float, ...]:
    return (p.getX(), p.getY(), p.getRotation().getRadians())


_POSE3D_FIELDS: tuple[Field, ...] = (("translation", 1, "ProtobufTranslation3d", False),
                                     ("rotation", 2, "ProtobufRotation3d", False))
_POSE3D_SCHEMA = "Translation3d translation;Rotation3d rotation"


def _flat_pose3d(p: Any) -> tuple[float, ...]:
    return (p.getX(), p.getY(), p.getZ(), *_flat_quaternion(p.getRotation().getQuaternion()))


def _rotation3d(w: float, x: float, y: float, z: float) -> Rotation3d:
    # As WPILib unpacks one: through Rotation3d(Quaternion), which normalises.
    return Rotation3d(Quaternion(w, x, y, z))


def _frame3d(cls: type, index: int, example: Callable[[], Any]) -> Entry:
    return Entry(cls, "value", flatten=_flat_pose3d,
                 build=lambda x, y, z, w, i, j, k: cls(Translation3d(x, y, z),
                                                       _rotation3d(w, i, j, k)),
                 struct=Struct(cls.__name__, _POSE3D_SCHEMA, 7, (Translation3d, Rotation3d)),
                 proto=Proto(f"Protobuf{cls.__name__}", GEOMETRY3D_FILE, index,
                             _POSE3D_FIELDS),
                 peer=_frame3d_peer(cls), example=example)


def _flat_translations(ts: tuple[Translation2d, ...]) -> tuple[float, ...]:
    out: list[float] = []
    for t in ts:
        out += (t.getX(), t.getY())
    return tuple(out)


def _translations(v: tuple[float, ...]) -> list[Translation2d]:
    return [_T(v[j], v[j + 1]) for j in range(0, len(v), 2)]


def _module_value(cls: type, field: str, message: str, struct_name: str, index: int,
                  peer: Peer | None, no_peer: str | None) -> Entry:
    value = operator.attrgetter(field)
    return Entry(cls, "value", "swerve",
                 flatten=lambda s: (value(s), s.angle.getRadians()),
                 build=lambda m, a: cls(m, _R(a)),
                 struct=Struct(struct_name, f"double {field};Rotation2d angle", 2,
                               (Rotation2d,)),
                 proto=Proto(message, KINEMATICS_FILE, index, _value_and_angle(field)),
                 peer=peer, no_peer=no_peer, example=lambda: cls(1.0, _R(0.5)))


def _plain(cls: type, file: str, index: int, attrs: tuple[str, ...],
           fields: tuple[str, ...] | None = None, *, drivetrain: str | None = None,
           peer: Peer | None = None, no_peer: str | None = None,
           example: Callable[[], Any] | None = None) -> Entry:
    """A value of two or more plain doubles, read from the attributes ``attrs``, with the
    struct members and protobuf fields ``fields`` (default ``attrs``), built by its
    constructor; the example defaults to ``cls(1.0, 2.0, ...)``."""
    names = fields or attrs
    return Entry(cls, "value", drivetrain, flatten=operator.attrgetter(*attrs), build=cls,
                 struct=Struct(cls.__name__, ";".join(f"double {f}" for f in names),
                               len(names)),
                 proto=Proto(f"Protobuf{cls.__name__}", file, index, _doubles(*names)),
                 peer=peer, no_peer=no_peer,
                 example=example or (lambda: cls(*map(float, range(1, len(attrs) + 1)))))


# ---------------------------------------------------------------------------------------
# The examples' robot: a 4-module swerve at (±0.3, ±0.3) m, a mecanum drive with its wheels
# at the same points, a differential drive of trackwidth 0.6 m, three dead wheels that
# observe the heading; odometry and estimators start at gyro 0 rad with zero readings, at
# (1 m, 2 m, 0.5 rad). Value examples are small distinct numbers (wheel values 1, 2, ...;
# module values 1 at 0.5 rad).

_CORNERS = ((0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3))


def _swerve() -> SwerveDriveKinematics:
    return SwerveDriveKinematics([_T(x, y) for x, y in _CORNERS])


def _mecanum() -> MecanumDriveKinematics:
    return MecanumDriveKinematics(*(_T(x, y) for x, y in _CORNERS))


def _dead_wheels() -> DeadWheelKinematics:
    # Asymmetric, and observable without a gyro (a perpendicular third wheel).
    return DeadWheelKinematics([Pose2d(0.0, 0.3, _R(0.0)), Pose2d(0.1, -0.2, _R(0.1)),
                                Pose2d(-0.2, 0.05, _R(math.pi / 2))])


def _swerve_zeros() -> list[SwerveModulePosition]:
    return [SwerveModulePosition(0.0, _R(0.0)) for _ in _CORNERS]


def _start() -> Pose2d:
    return Pose2d(1.0, 2.0, _R(0.5))


def _start3d() -> Pose3d:
    # Off the plane: the 3-D odometry and estimators start pitched and rolled, gyro level.
    return Pose3d(1.0, 2.0, 0.25, Rotation3d(0.1, -0.2, 0.5))


def _double_buffer() -> Any:
    # A 1.5 s double buffer holding three samples.
    b = _dk.TimeInterpolatableBuffer.createDoubleBuffer(1.5)
    for t, v in ((0.0, 1.0), (0.25, -2.0), (1.0, 4.0)):
        b.addSample(t, v)
    return b


def _motor_to(m: DCMotor, w: Any) -> Any:
    # The gearbox's constants as one motor; robotpy derives R, Kv and Kt with the same
    # operations, so they come out the same bits.
    return w.cls("DCMotor")(m.nominalVoltage, m.stallTorque, m.stallCurrent, m.freeCurrent,
                            m.freeSpeed, 1)


_MOTOR_PEER = (("nominal_voltage", "nominalVoltage"), ("stall_torque", "stallTorque"),
               ("stall_current", "stallCurrent"), ("free_current", "freeCurrent"),
               ("free_speed", "freeSpeed"))


def _motor_from(m: Any) -> DCMotor:
    return DCMotor(*(robotpy_attr(m, new, old) for new, old in _MOTOR_PEER))


def _robot_config() -> Any:
    module = _dk.ModuleConfig(0.0508, 4.5, 1.2, DCMotor.getKrakenX60(1).withReduction(6.75),
                              60.0, 1)
    return _dk.RobotConfig(60.0, 6.0, module, [_T(0.27, 0.27), _T(0.27, -0.27),
                                               _T(-0.27, 0.27), _T(-0.27, -0.27)])


def _setpoint() -> Any:
    return _dk.SwerveSetpoint(ChassisVelocities(1.0, 0.5, 0.25),
                              [SwerveModuleVelocity(1.0, _R(0.5 * i)) for i in range(4)],
                              _dk.DriveFeedforwards(*([0.5 * i + k for i in range(4)]
                                                      for k in range(5))))


_NEW_2027 = ("robotpy-wpimath 2026 has no {} (it is new in WPILib 2027; drivekin.interop "
             "converts the classes both robotpy generations have)")
_PATHPLANNER = "robotpy-wpimath has no {} (it is PathPlannerLib's)"
_DRIVEKIN_ONLY = "robotpy-wpimath has no counterpart of {}"
_OPAQUE = ("drivekin.interop does not convert {} (robotpy-wpimath's has no accessor to read "
           "it from; build drivekin's from the same axes)")

# ---------------------------------------------------------------------------------------
# The entries. Order within a drivetrain follows WPILib; nothing depends on it except
# where noted (the protobuf index).

ENTRIES: tuple[Entry, ...] = (
    # Geometry
    Entry(Translation2d, "value",
          flatten=lambda t: (t.getX(), t.getY()), build=lambda x, y: _T(x, y),
          struct=Struct("Translation2d", "double x;double y", 2),
          proto=Proto("ProtobufTranslation2d", GEOMETRY2D_FILE, 0, _doubles("x", "y")),
          peer=Peer("geometry", ("Translation2d",), _translation_to, _translation_from),
          example=lambda: _T(1.0, 2.0)),
    Entry(Rotation2d, "value",
          flatten=lambda r: (r.getRadians(),), build=_R,
          struct=Struct("Rotation2d", "double value", 1),
          proto=Proto("ProtobufRotation2d", GEOMETRY2D_FILE, 1, _doubles("value")),
          peer=Peer("geometry", ("Rotation2d",), _rotation_to, _rotation_from),
          example=lambda: _R(0.5)),
    Entry(Pose2d, "value",
          flatten=_flat_pose, build=lambda x, y, r: Pose2d(x, y, _R(r)),
          struct=Struct("Pose2d", _POSE_SCHEMA, 3, (Translation2d, Rotation2d)),
          proto=Proto("ProtobufPose2d", GEOMETRY2D_FILE, 2, _POSE_FIELDS),
          peer=Peer("geometry", ("Pose2d",),
                    lambda p, w: w.cls("Pose2d")(p.x, p.y, _rotation_to(p.getRotation(), w)),
                    lambda p: Pose2d(p.x, p.y, _rotation_from(p.rotation()))),
          example=_start),
    Entry(Transform2d, "value",
          flatten=_flat_pose, build=lambda x, y, r: Transform2d(x, y, _R(r)),
          struct=Struct("Transform2d", _POSE_SCHEMA, 3, (Translation2d, Rotation2d)),
          proto=Proto("ProtobufTransform2d", GEOMETRY2D_FILE, 3, _POSE_FIELDS),
          peer=Peer("geometry", ("Transform2d",),
                    lambda t, w: w.cls("Transform2d")(t.x, t.y,
                                                      _rotation_to(t.getRotation(), w)),
                    lambda t: Transform2d(t.x, t.y, _rotation_from(t.rotation()))),
          example=lambda: Transform2d(0.5, -1.0, _R(0.25))),
    _plain(Twist2d, GEOMETRY2D_FILE, 4, ("dx", "dy", "dtheta"),
           peer=Peer("geometry", ("Twist2d",),
                     lambda t, w: w.cls("Twist2d")(t.dx, t.dy, t.dtheta),
                     lambda t: Twist2d(t.dx, t.dy, t.dtheta)),
           example=lambda: Twist2d(0.5, 0.25, 0.125)),
    # Geometry in 3-D (drivekin.geometry3d; protobuf indices: WPILib's geometry3d.proto)
    Entry(Quaternion, "value", flatten=_flat_quaternion, build=Quaternion,
          struct=Struct("Quaternion", "double w;double x;double y;double z", 4),
          proto=Proto("ProtobufQuaternion", GEOMETRY3D_FILE, 1, _doubles("w", "x", "y", "z")),
          peer=Peer("geometry", ("Quaternion",),
                    lambda q, w: w.cls("Quaternion")(*_flat_quaternion(q)),
                    lambda q: Quaternion(*_quaternion_parts(q))),
          example=lambda: Quaternion(0.5, -0.25, 0.75, 0.125)),
    Entry(Rotation3d, "value",
          flatten=lambda r: _flat_quaternion(r.getQuaternion()), build=_rotation3d,
          struct=Struct("Rotation3d", "Quaternion q", 4, (Quaternion,)),
          proto=Proto("ProtobufRotation3d", GEOMETRY3D_FILE, 2,
                      (("q", 1, "ProtobufQuaternion", False),)),
          peer=Peer("geometry", ("Rotation3d",), _rotation3d_to, _rotation3d_from),
          example=lambda: Rotation3d(0.25, -0.5, 0.75)),
    _plain(Translation3d, GEOMETRY3D_FILE, 0, ("x", "y", "z"),
           peer=Peer("geometry", ("Translation3d",), _translation3d_to, _translation3d_from),
           example=lambda: Translation3d(1.0, 2.0, 0.5)),
    _frame3d(Pose3d, 3, lambda: Pose3d(1.0, 2.0, 0.5, Rotation3d(0.25, -0.5, 0.75))),
    _frame3d(Transform3d, 4, lambda: Transform3d(0.5, -1.0, 0.25,
                                                 Rotation3d(-0.125, 0.25, 0.5))),
    _plain(Twist3d, GEOMETRY3D_FILE, 5, ("dx", "dy", "dz", "rx", "ry", "rz"),
           peer=Peer("geometry", ("Twist3d",),
                     lambda t, w: w.cls("Twist3d")(t.dx, t.dy, t.dz, t.rx, t.ry, t.rz),
                     lambda t: Twist3d(t.dx, t.dy, t.dz, t.rx, t.ry, t.rz)),
           example=lambda: Twist3d(0.5, 0.25, 0.125, 0.0625, -0.125, 0.25)),
    Entry(CoordinateAxis, "value", no_peer=_OPAQUE,
          example=lambda: CoordinateAxis(1.0, 2.0, -0.5)),
    Entry(CoordinateSystem, "value", no_peer=_OPAQUE,
          example=lambda: CoordinateSystem(CoordinateAxis.E(), CoordinateAxis.D(),
                                           CoordinateAxis.N())),
    # Chassis
    _plain(ChassisVelocities, KINEMATICS_FILE, 0, ("vx", "vy", "omega"),
           peer=Peer("kinematics", ("ChassisSpeeds",),
                     lambda v, w: w.cls("ChassisVelocities")(v.vx, v.vy, v.omega),
                     lambda v: ChassisVelocities(v.vx, v.vy, v.omega),
                     ("ChassisVelocities",)),
           example=lambda: ChassisVelocities(1.0, 0.5, 0.25)),
    _plain(ChassisAccelerations, KINEMATICS_FILE, 1, ("ax", "ay", "alpha"),
           no_peer=_NEW_2027, example=lambda: ChassisAccelerations(1.0, 0.5, 0.25)),
    # Swerve
    _module_value(SwerveModuleVelocity, "velocity", "ProtobufSwerveModuleVelocity",
                  "SwerveModuleVelocity", 12,
                  Peer("kinematics", ("SwerveModuleState",),
                       lambda m, w: w.cls("SwerveModuleVelocity")(
                           m.velocity, _rotation_to(m.angle, w)),
                       lambda m: SwerveModuleVelocity(robotpy_attr(m, "velocity", "speed"),
                                                      _rotation_from(m.angle)),
                       ("SwerveModuleVelocity",)),
                  None),
    _module_value(SwerveModulePosition, "distance", "ProtobufSwerveModulePosition",
                  "SwerveModulePosition", 11,
                  Peer("kinematics", ("SwerveModulePosition",),
                       lambda m, w: w.cls("SwerveModulePosition")(
                           m.distance, _rotation_to(m.angle, w)),
                       lambda m: SwerveModulePosition(m.distance, _rotation_from(m.angle))),
                  None),
    # WPILib 2027 publishes SwerveModuleAcceleration under the plural struct name (sic).
    _module_value(SwerveModuleAcceleration, "acceleration",
                  "ProtobufSwerveModuleAcceleration", "SwerveModuleAccelerations", 13,
                  None, _NEW_2027),
    Entry(SwerveDriveKinematics, "kinematics", "swerve",
          flatten=lambda k: _flat_translations(k.getModules()),
          build=lambda *v: SwerveDriveKinematics(_translations(v)),
          struct=Struct("SwerveDriveKinematics", "Translation2d modules", 2,
                        (Translation2d,), repeats=lambda k: k.getNumModules(), least=2),
          steered=True,
          proto=Proto("ProtobufSwerveDriveKinematics", KINEMATICS_FILE, 10,
                      (("modules", 1, "ProtobufTranslation2d", True),)),
          peer=Peer("kinematics", tuple(f"SwerveDrive{n}Kinematics"
                                        for n in SWERVE_MODULE_COUNTS),
                    _swerve_to, _swerve_from),
          example=_swerve),
    Entry(_dk.SwerveDriveOdometry, "odometry", "swerve",
          replay=replayspec.SWERVE,
          positions="struct:SwerveModulePosition[]",
          start=lambda k, g, row, p: _dk.SwerveDriveOdometry(k, g, np.ascontiguousarray(row),
                                                             p),
          example=lambda: _dk.SwerveDriveOdometry(_swerve(), _R(0.0), _swerve_zeros(),
                                                  _start())),
    Entry(_dk.SwerveDrivePoseEstimator, "estimator", "swerve",
          example=lambda: _dk.SwerveDrivePoseEstimator(_swerve(), _R(0.0), _swerve_zeros(),
                                                       _start())),
    Entry(_dk.SwerveDriveOdometry3d, "odometry3d", "swerve",
          example=lambda: _dk.SwerveDriveOdometry3d(_swerve(), Rotation3d(), _swerve_zeros(),
                                                    _start3d())),
    Entry(_dk.SwerveDrivePoseEstimator3d, "estimator3d", "swerve",
          example=lambda: _dk.SwerveDrivePoseEstimator3d(_swerve(), Rotation3d(),
                                                         _swerve_zeros(), _start3d())),
    # Mecanum
    _plain(MecanumDriveWheelVelocities, KINEMATICS_FILE, 8, _MECANUM_ATTRS, _MECANUM,
           drivetrain="mecanum",
           peer=Peer("kinematics", ("MecanumDriveWheelSpeeds",),
                     lambda m, w: w.cls("MecanumDriveWheelVelocities")(
                         m.frontLeft, m.frontRight, m.rearLeft, m.rearRight),
                     _wheels_from(MecanumDriveWheelVelocities, _MECANUM_PEER),
                     ("MecanumDriveWheelVelocities",))),
    _plain(MecanumDriveWheelPositions, KINEMATICS_FILE, 7, _MECANUM_ATTRS, _MECANUM,
           drivetrain="mecanum",
           peer=Peer("kinematics", ("MecanumDriveWheelPositions",),
                     _wheel_positions_to("MecanumDriveWheelPositions", _MECANUM_PEER),
                     _wheels_from(MecanumDriveWheelPositions, _MECANUM_PEER))),
    _plain(MecanumDriveWheelAccelerations, KINEMATICS_FILE, 9, _MECANUM_ATTRS, _MECANUM,
           drivetrain="mecanum", no_peer=_NEW_2027),
    Entry(MecanumDriveKinematics, "kinematics", "mecanum",
          flatten=lambda k: _flat_translations((k.getFrontLeft(), k.getFrontRight(),
                                                k.getRearLeft(), k.getRearRight())),
          build=lambda *v: MecanumDriveKinematics(*_translations(v)),
          struct=Struct("MecanumDriveKinematics",
                        ";".join(f"Translation2d {f}" for f in _MECANUM), 8,
                        (Translation2d,)),
          proto=Proto("ProtobufMecanumDriveKinematics", KINEMATICS_FILE, 6,
                      tuple((n, i, "ProtobufTranslation2d", False)
                            for i, n in enumerate(_MECANUM, 1))),
          peer=Peer("kinematics", ("MecanumDriveKinematics",),
                    lambda k, w: w.cls("MecanumDriveKinematics")(
                        _translation_to(k.getFrontLeft(), w),
                        _translation_to(k.getFrontRight(), w),
                        _translation_to(k.getRearLeft(), w),
                        _translation_to(k.getRearRight(), w)),
                    lambda k: MecanumDriveKinematics(*(
                        _translation_from(robotpy_attr(k, new, old)())
                        for new, old in _MECANUM_GETTERS))),
          example=_mecanum),
    Entry(_dk.MecanumDriveOdometry, "odometry", "mecanum",
          replay=replayspec.MECANUM,
          positions="struct:MecanumDriveWheelPositions",
          start=lambda k, g, row, p: _dk.MecanumDriveOdometry(
              k, g, MecanumDriveWheelPositions(*row.tolist()), p),
          example=lambda: _dk.MecanumDriveOdometry(_mecanum(), _R(0.0),
                                                   MecanumDriveWheelPositions(), _start())),
    Entry(_dk.MecanumDrivePoseEstimator, "estimator", "mecanum",
          example=lambda: _dk.MecanumDrivePoseEstimator(_mecanum(), _R(0.0),
                                                        MecanumDriveWheelPositions(),
                                                        _start())),
    Entry(_dk.MecanumDriveOdometry3d, "odometry3d", "mecanum",
          example=lambda: _dk.MecanumDriveOdometry3d(_mecanum(), Rotation3d(),
                                                     MecanumDriveWheelPositions(), _start3d())),
    Entry(_dk.MecanumDrivePoseEstimator3d, "estimator3d", "mecanum",
          example=lambda: _dk.MecanumDrivePoseEstimator3d(_mecanum(), Rotation3d(),
                                                          MecanumDriveWheelPositions(),
                                                          _start3d())),
    # Differential
    _plain(DifferentialDriveWheelVelocities, KINEMATICS_FILE, 3, ("left", "right"),
           drivetrain="differential",
           peer=Peer("kinematics", ("DifferentialDriveWheelSpeeds",),
                     lambda d, w: w.cls("DifferentialDriveWheelVelocities")(d.left, d.right),
                     lambda d: DifferentialDriveWheelVelocities(d.left, d.right),
                     ("DifferentialDriveWheelVelocities",))),
    _plain(DifferentialDriveWheelPositions, KINEMATICS_FILE, 5, ("left", "right"),
           drivetrain="differential",
           peer=Peer("kinematics", ("DifferentialDriveWheelPositions",),
                     _wheel_positions_to("DifferentialDriveWheelPositions",
                                         _DIFFERENTIAL_PEER),
                     lambda d: DifferentialDriveWheelPositions(d.left, d.right))),
    _plain(DifferentialDriveWheelAccelerations, KINEMATICS_FILE, 4, ("left", "right"),
           drivetrain="differential", no_peer=_NEW_2027),
    Entry(DifferentialDriveKinematics, "kinematics", "differential",
          flatten=lambda k: (k.trackwidth,), build=DifferentialDriveKinematics,
          struct=Struct("DifferentialDriveKinematics", "double trackwidth", 1),
          proto=Proto("ProtobufDifferentialDriveKinematics", KINEMATICS_FILE, 2,
                      _doubles("trackwidth")),
          peer=Peer("kinematics", ("DifferentialDriveKinematics",),
                    lambda k, w: w.cls("DifferentialDriveKinematics")(k.trackwidth),
                    lambda k: DifferentialDriveKinematics(
                        robotpy_attr(k, "trackwidth", "trackWidth"))),
          example=lambda: DifferentialDriveKinematics(0.6)),
    Entry(_dk.DifferentialDriveOdometry, "odometry", "differential",
          replay=replayspec.DIFFERENTIAL,
          positions="struct:DifferentialDriveWheelPositions",
          start=lambda k, g, row, p: _dk.DifferentialDriveOdometry(g, float(row[0]),
                                                                   float(row[1]), p),
          example=lambda: _dk.DifferentialDriveOdometry(_R(0.0), 0.0, 0.0, _start())),
    Entry(_dk.DifferentialDrivePoseEstimator, "estimator", "differential",
          example=lambda: _dk.DifferentialDrivePoseEstimator(_R(0.0), 0.0, 0.0, _start())),
    Entry(_dk.DifferentialDriveOdometry3d, "odometry3d", "differential",
          example=lambda: _dk.DifferentialDriveOdometry3d(Rotation3d(), 0.0, 0.0, _start3d())),
    Entry(_dk.DifferentialDrivePoseEstimator3d, "estimator3d", "differential",
          example=lambda: _dk.DifferentialDrivePoseEstimator3d(Rotation3d(), 0.0, 0.0,
                                                               _start3d())),
    # Dead wheels
    Entry(DeadWheelKinematics, "kinematics", "deadwheel", no_peer=_DRIVEKIN_ONLY,
          example=_dead_wheels),
    Entry(_dk.DeadWheelOdometry, "odometry", "deadwheel",
          replay=replayspec.DEADWHEEL,
          start=lambda k, g, row, p: _dk.DeadWheelOdometry(k, np.ascontiguousarray(row), g, p),
          example=lambda: _dk.DeadWheelOdometry(_dead_wheels(), [0.0, 0.0, 0.0], _R(0.0),
                                                _start())),
    Entry(_dk.DeadWheelPoseEstimator, "estimator", "deadwheel",
          example=lambda: _dk.DeadWheelPoseEstimator(_dead_wheels(), [0.0, 0.0, 0.0],
                                                     _R(0.0), _start())),
    Entry(_dk.DeadWheelOdometry3d, "odometry3d", "deadwheel",
          example=lambda: _dk.DeadWheelOdometry3d(_dead_wheels(), [0.0, 0.0, 0.0],
                                                  Rotation3d(), _start3d())),
    Entry(_dk.DeadWheelPoseEstimator3d, "estimator3d", "deadwheel",
          example=lambda: _dk.DeadWheelPoseEstimator3d(_dead_wheels(), [0.0, 0.0, 0.0],
                                                       Rotation3d(), _start3d())),
    # Two dead wheels 0.1 m ahead and 0.2 m to the right of the centre, and a gyro.
    Entry(_dk.TwoDeadWheelOdometry, "odometry", "twodeadwheel",
          example=lambda: _dk.TwoDeadWheelOdometry(0.1, -0.2, 0.0, 0.0, _R(0.0), _start())),
    Entry(_dk.TwoDeadWheelPoseEstimator, "estimator", "twodeadwheel",
          example=lambda: _dk.TwoDeadWheelPoseEstimator(0.1, -0.2, 0.0, 0.0, _R(0.0),
                                                        _start())),
    Entry(_dk.TwoDeadWheelOdometry3d, "odometry3d", "twodeadwheel",
          example=lambda: _dk.TwoDeadWheelOdometry3d(0.1, -0.2, 0.0, 0.0, Rotation3d(),
                                                     _start3d())),
    Entry(_dk.TwoDeadWheelPoseEstimator3d, "estimator3d", "twodeadwheel",
          example=lambda: _dk.TwoDeadWheelPoseEstimator3d(0.1, -0.2, 0.0, 0.0, Rotation3d(),
                                                          _start3d())),
    # Differential swerve pods (per pod: not a drivetrain of their own); the example pod
    # has azimuth ratio 3, wheel ratio 5 and a 0.05 m wheel.
    Entry(_dk.DifferentialSwerveModuleKinematics, "kinematics", "diffswerve",
          no_peer=_DRIVEKIN_ONLY,
          example=lambda: _dk.DifferentialSwerveModuleKinematics(3.0, 5.0, 0.05)),
    Entry(_dk.DifferentialSwerveModuleVelocities, "value", "diffswerve",
          no_peer=_DRIVEKIN_ONLY,
          example=lambda: _dk.DifferentialSwerveModuleVelocities(1.5, -0.5)),
    Entry(_dk.DifferentialSwerveMotorVelocities, "value", "diffswerve",
          no_peer=_DRIVEKIN_ONLY,
          example=lambda: _dk.DifferentialSwerveMotorVelocities(1.0, -2.0)),
    # Motors (WPILib 2027 has a DCMotor struct and protobuf message; drivekin serializes
    # neither yet, so the entry has no wire form)
    Entry(DCMotor, "value",
          peer=Peer("system.plant", ("DCMotor",), _motor_to, _motor_from),
          example=lambda: DCMotor.getNEO(2)),
    # PathPlannerLib's setpoint generator and what it takes and gives (drivekin.setpoint,
    # the robot description from drivekin.robotconfig)
    Entry(_dk.ModuleConfig, "value", robotpy_names=False, no_peer=_PATHPLANNER,
          example=lambda: _robot_config().moduleConfig),
    Entry(_dk.RobotConfig, "value", robotpy_names=False, no_peer=_PATHPLANNER,
          example=_robot_config),
    Entry(_dk.PathConstraints, "value", robotpy_names=False, no_peer=_PATHPLANNER,
          example=lambda: _dk.PathConstraints(3.0, 4.0, 5.0, 6.0)),
    Entry(_dk.DriveFeedforwards, "value", robotpy_names=False, no_peer=_PATHPLANNER,
          example=lambda: _setpoint().feedforwards),
    Entry(_dk.SwerveSetpoint, "value", robotpy_names=False, no_peer=_PATHPLANNER,
          example=_setpoint),
    Entry(_dk.SwerveSetpointGenerator, "helper", robotpy_names=False,
          example=lambda: _dk.SwerveSetpointGenerator(_robot_config(), 10.0)),
    # Helpers (Units has static methods only and refuses instances: no example)
    Entry(_dk.MathSharedStore, "helper", example=_dk.MathSharedStore),
    Entry(_dk.TimeInterpolatableBuffer, "helper", example=_double_buffer),
    Entry(_dk.Units, "helper"),
    Entry(_dk.ClockMismatchWarning, "warning", robotpy_names=False,
          example=lambda: _dk.ClockMismatchWarning("vision timestamp off the clock")),
)

BY_CLASS: dict[type, Entry] = {e.cls: e for e in ENTRIES}


def entries(kind: str | None = None, *, drivetrain: str | None = None) -> tuple[Entry, ...]:
    """The entries of one kind (and drivetrain), in catalog order."""
    return tuple(e for e in ENTRIES if (kind is None or e.kind == kind)
                 and (drivetrain is None or e.drivetrain == drivetrain))


def replay_specs() -> tuple[replayspec.ReplaySpec, ...]:
    """The drivetrains a log can be replayed for, in catalog order."""
    return tuple(e.replay for e in entries("odometry") if e.replay is not None)


def replay_spec(drivetrain: str) -> replayspec.ReplaySpec:
    """The replay spec of a drivetrain named by replay_specs()."""
    return next(s for s in replay_specs() if s.name == drivetrain)


def names(what: str) -> str:
    """The class names a call accepts, for its TypeError: ``"drivetrain"`` (kinematics
    classes implementing the drivetrain contract), ``"steered"`` (those whose wheels are
    swerve modules), ``"odometry"`` or ``"odometry3d"``."""
    from drivekin._core.drivetrain import Drivetrain
    if what in ("odometry", "odometry3d"):
        classes = [e.cls for e in entries(what)]
    else:
        classes = [e.cls for e in entries("kinematics") if issubclass(e.cls, Drivetrain)]
        if what == "steered":
            classes = [c for c in classes if BY_CLASS[c].steered]
    return ", ".join(c.__name__ for c in classes)
