"""Converters between drivekin and robotpy-wpimath 2026 (``wpimath``) objects.

``toWpimath(obj)`` turns a drivekin object into the robotpy-wpimath object of the same
meaning, ``fromWpimath(obj)`` goes the other way, mapping WPILib 2026 names to 2027 ones:

==========================================  ==========================================
drivekin (WPILib 2027)                       robotpy-wpimath 2026
==========================================  ==========================================
Translation2d, Rotation2d, Pose2d,           the same names in ``wpimath.geometry``
Transform2d, Twist2d
ChassisVelocities (vx, vy, omega)            ChassisSpeeds (vx, vy, omega)
SwerveModuleVelocity (velocity, angle)       SwerveModuleState (speed, angle)
SwerveModulePosition (distance, angle)       SwerveModulePosition (distance, angle)
MecanumDriveWheelVelocities                  MecanumDriveWheelSpeeds
MecanumDriveWheelPositions                   MecanumDriveWheelPositions
DifferentialDriveWheelVelocities             DifferentialDriveWheelSpeeds
DifferentialDriveWheelPositions              DifferentialDriveWheelPositions
SwerveDriveKinematics (N modules)            SwerveDrive2/3/4/6Kinematics (N = 2, 3, 4, 6)
MecanumDriveKinematics                       MecanumDriveKinematics
DifferentialDriveKinematics (trackwidth)     DifferentialDriveKinematics (trackWidth)
==========================================  ==========================================

Units are the same on both sides (m, m/s, rad, rad/s). Every conversion is exact: each
float is copied, never recomputed. A rotation is carried as its stored (cos, sin) pair —
not through its angle, whose cos/sin would differ in the last bit — so a drivekin →
wpimath → drivekin round trip returns bit-identical objects. A robotpy ``Rotation2d``
remembers the angle it was built with (``Rotation2d(3π/2).radians()`` is 4.71); drivekin,
like WPILib 2027, keeps only (cos, sin), so its angle comes back wrapped to (−π, π]
(−π/2 here: ``atan2(sin, cos)``). Kinematics objects carry their module geometry only:
the module heading memory starts empty on the new object (robotpy has no getter for it;
call ``resetHeadings`` to set it).

Sequences: a list or tuple is converted element by element into a container of the same
kind (robotpy's ``toSwerveModuleStates`` returns a tuple: ``fromWpimath`` of it is a
tuple of SwerveModuleVelocity). Only one level: a nested list is a TypeError, as is any
other iterable (generator, numpy array).

Not converted (TypeError saying so): drivekin's 2027 additions that robotpy-wpimath 2026
lacks (ChassisAccelerations, SwerveModuleAcceleration, the wheel accelerations, dead-wheel
and differential swerve kinematics), odometry objects (stateful: build the other library's
odometry from converted kinematics and poses), and wpimath types drivekin has no
counterpart for (3-D geometry, estimators, trajectories, ...).

robotpy-wpimath is optional: importing drivekin or this module never imports it. The first
conversion that needs it does, and if it is missing raises ImportError (a
ModuleNotFoundError when the package is absent) saying to ``pip install robotpy-wpimath``,
or ``pip install "drivekin[wpimath]"``.
"""
from __future__ import annotations

import importlib
from collections.abc import Callable
from types import ModuleType
from typing import TYPE_CHECKING, Any, NamedTuple, overload

from drivekin.differential import (
    DifferentialDriveKinematics,
    DifferentialDriveWheelPositions,
    DifferentialDriveWheelVelocities,
)
from drivekin.geometry import Pose2d, Rotation2d, Transform2d, Translation2d, Twist2d
# The exact (cos, sin) constructor pickle uses; private, so the stub does not declare it.
from drivekin.geometry import _rotation_from_cos_sin  # type: ignore[attr-defined]
from drivekin.kinematics import (
    ChassisVelocities,
    SwerveDriveKinematics,
    SwerveModulePosition,
    SwerveModuleVelocity,
)
from drivekin.mecanum import (
    MecanumDriveKinematics,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
)

if TYPE_CHECKING:
    import wpimath.geometry as wpg
    import wpimath.kinematics as wpk

__all__ = ["fromWpimath", "toWpimath"]

INSTALL_HINT = ('install it with `pip install robotpy-wpimath` '
                '(or `pip install "drivekin[wpimath]"`)')


class _Wpimath(NamedTuple):
    geometry: ModuleType
    kinematics: ModuleType


_wpimath: _Wpimath | None = None


def _load() -> _Wpimath:
    """Import robotpy-wpimath on first use (it is optional)."""
    global _wpimath
    if _wpimath is None:
        try:
            geometry = importlib.import_module("wpimath.geometry")
            kinematics = importlib.import_module("wpimath.kinematics")
        except ModuleNotFoundError as e:
            raise ModuleNotFoundError(
                f"drivekin.interop needs robotpy-wpimath, which is not installed ({e}): "
                f"{INSTALL_HINT}", name=e.name or "wpimath") from e
        except ImportError as e:
            raise ImportError(
                f"drivekin.interop needs robotpy-wpimath, which failed to import ({e}): "
                f"reinstall it, or {INSTALL_HINT}", name="wpimath") from e
        _wpimath = _Wpimath(geometry, kinematics)
    return _wpimath


# ---- drivekin -> wpimath ---------------------------------------------------------------

def _check_unit(c: float, s: float, r: object, where: str) -> None:
    # A rotation is a unit (cos, sin) pair, or the NaN pair of a non-finite angle. Both
    # libraries store (0, 0) for Rotation2d(x, y) when hypot(x, y) overflows (x/inf);
    # that is no rotation, and neither side can rebuild it from its pair.
    if not (c != c and s != s) and not abs((c * c + s * s) - 1.0) <= 1e-9:
        raise ValueError(f"{where}: this {_qualified(r)} stores (cos, sin) = ({c!r}, {s!r}), "
                         "which is not a unit vector")


def _rotation_to(r: Rotation2d, w: _Wpimath) -> Any:
    c, s = r.getCos(), r.getSin()
    _check_unit(c, s, r, "toWpimath()")
    if c == c and s == s:
        # robotpy's Rotation2d(x, y) divides by hypot(x, y): exact whenever that is 1.0
        # (division by a positive number keeps the sign of zero, so == suffices here).
        out = w.geometry.Rotation2d(c, s)
        if out.cos() == c and out.sin() == s:
            return out
    # Otherwise (and for the NaN pair of a non-finite angle) fromMatrix copies R(0,0) and
    # R(1,0) as they are; NaN passes its orthogonality check.
    return w.geometry.Rotation2d.fromMatrix(((c, -s), (s, c)))


def _translation_to(t: Translation2d, w: _Wpimath) -> Any:
    return w.geometry.Translation2d(t.x, t.y)


def _pose_to(p: Pose2d, w: _Wpimath) -> Any:
    return w.geometry.Pose2d(p.x, p.y, _rotation_to(p.getRotation(), w))


def _transform_to(t: Transform2d, w: _Wpimath) -> Any:
    return w.geometry.Transform2d(t.x, t.y, _rotation_to(t.getRotation(), w))


def _twist_to(t: Twist2d, w: _Wpimath) -> Any:
    return w.geometry.Twist2d(t.dx, t.dy, t.dtheta)


def _chassis_to(v: ChassisVelocities, w: _Wpimath) -> Any:
    return w.kinematics.ChassisSpeeds(v.vx, v.vy, v.omega)


def _module_velocity_to(m: SwerveModuleVelocity, w: _Wpimath) -> Any:
    return w.kinematics.SwerveModuleState(m.velocity, _rotation_to(m.angle, w))


def _module_position_to(m: SwerveModulePosition, w: _Wpimath) -> Any:
    return w.kinematics.SwerveModulePosition(m.distance, _rotation_to(m.angle, w))


def _mecanum_velocities_to(m: MecanumDriveWheelVelocities, w: _Wpimath) -> Any:
    return w.kinematics.MecanumDriveWheelSpeeds(m.frontLeft, m.frontRight, m.rearLeft,
                                                m.rearRight)


def _mecanum_positions_to(m: MecanumDriveWheelPositions, w: _Wpimath) -> Any:
    out = w.kinematics.MecanumDriveWheelPositions()  # robotpy's takes no arguments
    out.frontLeft, out.frontRight = m.frontLeft, m.frontRight
    out.rearLeft, out.rearRight = m.rearLeft, m.rearRight
    return out


def _differential_velocities_to(d: DifferentialDriveWheelVelocities, w: _Wpimath) -> Any:
    return w.kinematics.DifferentialDriveWheelSpeeds(d.left, d.right)


def _differential_positions_to(d: DifferentialDriveWheelPositions, w: _Wpimath) -> Any:
    out = w.kinematics.DifferentialDriveWheelPositions()  # robotpy's takes no arguments
    out.left, out.right = d.left, d.right
    return out


SWERVE_MODULE_COUNTS = (2, 3, 4, 6)  # robotpy-wpimath 2026's SwerveDriveNKinematics


def _swerve_to(k: SwerveDriveKinematics, w: _Wpimath) -> Any:
    n = k.getNumModules()
    if n not in SWERVE_MODULE_COUNTS:
        raise ValueError(
            f"toWpimath(): robotpy-wpimath 2026 has SwerveDrive2Kinematics, "
            f"SwerveDrive3Kinematics, SwerveDrive4Kinematics and SwerveDrive6Kinematics "
            f"only; this SwerveDriveKinematics has {n} modules")
    cls = getattr(w.kinematics, f"SwerveDrive{n}Kinematics")
    return cls(*(_translation_to(t, w) for t in k.getModules()))


def _mecanum_to(k: MecanumDriveKinematics, w: _Wpimath) -> Any:
    return w.kinematics.MecanumDriveKinematics(
        _translation_to(k.getFrontLeft(), w), _translation_to(k.getFrontRight(), w),
        _translation_to(k.getRearLeft(), w), _translation_to(k.getRearRight(), w))


def _differential_to(k: DifferentialDriveKinematics, w: _Wpimath) -> Any:
    return w.kinematics.DifferentialDriveKinematics(k.trackwidth)


_TO: dict[type, Callable[[Any, _Wpimath], Any]] = {
    Translation2d: _translation_to,
    Rotation2d: _rotation_to,
    Pose2d: _pose_to,
    Transform2d: _transform_to,
    Twist2d: _twist_to,
    ChassisVelocities: _chassis_to,
    SwerveModuleVelocity: _module_velocity_to,
    SwerveModulePosition: _module_position_to,
    MecanumDriveWheelVelocities: _mecanum_velocities_to,
    MecanumDriveWheelPositions: _mecanum_positions_to,
    DifferentialDriveWheelVelocities: _differential_velocities_to,
    DifferentialDriveWheelPositions: _differential_positions_to,
    SwerveDriveKinematics: _swerve_to,
    MecanumDriveKinematics: _mecanum_to,
    DifferentialDriveKinematics: _differential_to,
}

# drivekin classes that robotpy-wpimath 2026 has no counterpart for, and why.
_NO_PEER_2027 = ("ChassisAccelerations", "SwerveModuleAcceleration",
                 "MecanumDriveWheelAccelerations", "DifferentialDriveWheelAccelerations")
_NO_PEER_DRIVEKIN = ("DeadWheelKinematics", "DifferentialSwerveModuleKinematics",
                     "DifferentialSwerveModuleVelocities", "DifferentialSwerveMotorVelocities")


# ---- wpimath -> drivekin ---------------------------------------------------------------

def _rotation_from(r: Any) -> Rotation2d:
    c, s = r.cos(), r.sin()
    # The stored pair is copied as is (a unit vector, or NaN for a non-finite angle).
    # Rotation2d(x, y) would renormalise it, and Rotation2d(angle) would recompute it.
    _check_unit(c, s, r, "fromWpimath()")
    return _rotation_from_cos_sin(c, s)  # type: ignore[no-any-return]


def _translation_from(t: Any) -> Translation2d:
    return Translation2d(t.x, t.y)


def _pose_from(p: Any) -> Pose2d:
    return Pose2d(p.x, p.y, _rotation_from(p.rotation()))


def _transform_from(t: Any) -> Transform2d:
    return Transform2d(t.x, t.y, _rotation_from(t.rotation()))


def _twist_from(t: Any) -> Twist2d:
    return Twist2d(t.dx, t.dy, t.dtheta)


def _chassis_from(v: Any) -> ChassisVelocities:
    return ChassisVelocities(v.vx, v.vy, v.omega)


def _module_state_from(m: Any) -> SwerveModuleVelocity:
    return SwerveModuleVelocity(m.speed, _rotation_from(m.angle))


def _module_position_from(m: Any) -> SwerveModulePosition:
    return SwerveModulePosition(m.distance, _rotation_from(m.angle))


def _mecanum_speeds_from(m: Any) -> MecanumDriveWheelVelocities:
    return MecanumDriveWheelVelocities(m.frontLeft, m.frontRight, m.rearLeft, m.rearRight)


def _mecanum_positions_from(m: Any) -> MecanumDriveWheelPositions:
    return MecanumDriveWheelPositions(m.frontLeft, m.frontRight, m.rearLeft, m.rearRight)


def _differential_speeds_from(d: Any) -> DifferentialDriveWheelVelocities:
    return DifferentialDriveWheelVelocities(d.left, d.right)


def _differential_positions_from(d: Any) -> DifferentialDriveWheelPositions:
    return DifferentialDriveWheelPositions(d.left, d.right)


def _swerve_from(k: Any) -> SwerveDriveKinematics:
    return SwerveDriveKinematics([_translation_from(t) for t in k.getModules()])


def _mecanum_from(k: Any) -> MecanumDriveKinematics:
    return MecanumDriveKinematics(
        _translation_from(k.getFrontLeft()), _translation_from(k.getFrontRight()),
        _translation_from(k.getRearLeft()), _translation_from(k.getRearRight()))


def _differential_from(k: Any) -> DifferentialDriveKinematics:
    return DifferentialDriveKinematics(k.trackWidth)


_FROM_NAMES: tuple[tuple[str, str, Callable[[Any], Any]], ...] = (
    ("geometry", "Translation2d", _translation_from),
    ("geometry", "Rotation2d", _rotation_from),
    ("geometry", "Pose2d", _pose_from),
    ("geometry", "Transform2d", _transform_from),
    ("geometry", "Twist2d", _twist_from),
    ("kinematics", "ChassisSpeeds", _chassis_from),
    ("kinematics", "SwerveModuleState", _module_state_from),
    ("kinematics", "SwerveModulePosition", _module_position_from),
    ("kinematics", "MecanumDriveWheelSpeeds", _mecanum_speeds_from),
    ("kinematics", "MecanumDriveWheelPositions", _mecanum_positions_from),
    ("kinematics", "DifferentialDriveWheelSpeeds", _differential_speeds_from),
    ("kinematics", "DifferentialDriveWheelPositions", _differential_positions_from),
    *(("kinematics", f"SwerveDrive{n}Kinematics", _swerve_from) for n in SWERVE_MODULE_COUNTS),
    ("kinematics", "MecanumDriveKinematics", _mecanum_from),
    ("kinematics", "DifferentialDriveKinematics", _differential_from),
)
_from: dict[type, Callable[[Any], Any]] | None = None


def _from_table() -> dict[type, Callable[[Any], Any]]:
    global _from
    if _from is None:
        w = _load()
        _from = {getattr(getattr(w, mod), name): fn for mod, name, fn in _FROM_NAMES}
    return _from


# ---- dispatch ----------------------------------------------------------------------------

def _qualified(obj: object) -> str:
    # Both libraries have a Pose2d, a Rotation2d, ...: always say whose (builtins aside).
    t = type(obj)
    module = getattr(t, "__module__", None) or "?"
    return t.__qualname__ if module == "builtins" else f"{module}.{t.__qualname__}"


def _lookup(table: dict[type, Callable[..., Any]], obj: object) -> Callable[..., Any] | None:
    # The exact class first, then its bases (a user's subclass of a robotpy class).
    for klass in type(obj).__mro__:
        fn = table.get(klass)
        if fn is not None:
            return fn
    return None


def _from_package(obj: object, package: str) -> bool:
    # The class or one of its bases (a user's subclass of a robotpy class) is the package's.
    for klass in type(obj).__mro__:
        module = getattr(klass, "__module__", None) or ""
        if module == package or module.startswith(package + "."):
            return True
    return False


def _is_wpimath(obj: object) -> bool:
    return _from_package(obj, "wpimath")


def _is_drivekin(obj: object) -> bool:
    return _from_package(obj, "drivekin")


_STATEFUL = ("odometry and estimators are stateful and are not converted: build one from "
             "converted kinematics, rotations, positions and poses")


def _to_one(obj: object, where: str) -> Any:
    fn = _lookup(_TO, obj)
    if fn is not None:
        return fn(obj, _load())
    name = type(obj).__name__
    if isinstance(obj, (list, tuple)):
        reason = "only a plain list or tuple is converted, and only one level deep"
    elif _is_wpimath(obj):
        reason = "it is already a robotpy-wpimath object (fromWpimath converts to drivekin)"
    elif _is_drivekin(obj) and name in _NO_PEER_2027:
        reason = f"robotpy-wpimath 2026 has no {name} (it is new in WPILib 2027)"
    elif _is_drivekin(obj) and name in _NO_PEER_DRIVEKIN:
        reason = f"robotpy-wpimath 2026 has no counterpart of {name}"
    elif _is_drivekin(obj) and name.endswith(("Odometry", "PoseEstimator")):
        reason = _STATEFUL
    else:
        reason = "it is not a drivekin value or kinematics type"
    raise TypeError(f"{where} cannot convert {_qualified(obj)}: {reason}")


def _from_one(obj: object, where: str) -> Any:
    if _is_wpimath(obj):
        fn = _lookup(_from_table(), obj)
        if fn is not None:
            return fn(obj)
        name = type(obj).__name__
        stateful = name.endswith(("Odometry", "Odometry3d", "PoseEstimator", "PoseEstimator3d"))
        reason = _STATEFUL if stateful else "drivekin has no counterpart of it"
    elif isinstance(obj, (list, tuple)):
        reason = "only a plain list or tuple is converted, and only one level deep"
    elif _is_drivekin(obj):
        reason = "it is already a drivekin object (toWpimath converts to robotpy-wpimath)"
    else:
        reason = "it is not a robotpy-wpimath value or kinematics type"
    raise TypeError(f"{where} cannot convert {_qualified(obj)}: {reason}")


def _convert(obj: object, one: Callable[[object, str], Any], where: str) -> Any:
    if type(obj) is list or type(obj) is tuple:
        # Read the items first: the container cannot change under the conversion.
        items = tuple(obj)
        out = [one(x, f"{where} (item {i})") for i, x in enumerate(items)]
        return out if type(obj) is list else tuple(out)
    return one(obj, where)


# ---- public API --------------------------------------------------------------------------

@overload
def toWpimath(obj: Translation2d) -> wpg.Translation2d: ...
@overload
def toWpimath(obj: Rotation2d) -> wpg.Rotation2d: ...
@overload
def toWpimath(obj: Pose2d) -> wpg.Pose2d: ...
@overload
def toWpimath(obj: Transform2d) -> wpg.Transform2d: ...
@overload
def toWpimath(obj: Twist2d) -> wpg.Twist2d: ...
@overload
def toWpimath(obj: ChassisVelocities) -> wpk.ChassisSpeeds: ...
@overload
def toWpimath(obj: SwerveModuleVelocity) -> wpk.SwerveModuleState: ...
@overload
def toWpimath(obj: SwerveModulePosition) -> wpk.SwerveModulePosition: ...
@overload
def toWpimath(obj: MecanumDriveWheelVelocities) -> wpk.MecanumDriveWheelSpeeds: ...
@overload
def toWpimath(obj: MecanumDriveWheelPositions) -> wpk.MecanumDriveWheelPositions: ...
@overload
def toWpimath(obj: DifferentialDriveWheelVelocities) -> wpk.DifferentialDriveWheelSpeeds: ...
@overload
def toWpimath(obj: DifferentialDriveWheelPositions) -> wpk.DifferentialDriveWheelPositions: ...
@overload
def toWpimath(obj: MecanumDriveKinematics) -> wpk.MecanumDriveKinematics: ...
@overload
def toWpimath(obj: DifferentialDriveKinematics) -> wpk.DifferentialDriveKinematics: ...
@overload
def toWpimath(obj: list[Any]) -> list[Any]: ...
@overload
def toWpimath(obj: tuple[Any, ...]) -> tuple[Any, ...]: ...
@overload
def toWpimath(obj: object) -> Any: ...


def toWpimath(obj: object) -> Any:
    """Return the robotpy-wpimath 2026 object equivalent to the drivekin object ``obj``.

    Every float is copied exactly (rotations as their (cos, sin) pair); units are the
    same on both sides (m, m/s, rad, rad/s). A list or tuple gives a list or tuple of
    converted items. A SwerveDriveKinematics becomes ``SwerveDrive{N}Kinematics`` and
    needs N in (2, 3, 4, 6) (ValueError otherwise). TypeError for anything else, naming
    its type; ImportError (saying what to install) when robotpy-wpimath is missing."""
    return _convert(obj, _to_one, "toWpimath()")


@overload
def fromWpimath(obj: wpg.Translation2d) -> Translation2d: ...
@overload
def fromWpimath(obj: wpg.Rotation2d) -> Rotation2d: ...
@overload
def fromWpimath(obj: wpg.Pose2d) -> Pose2d: ...
@overload
def fromWpimath(obj: wpg.Transform2d) -> Transform2d: ...
@overload
def fromWpimath(obj: wpg.Twist2d) -> Twist2d: ...
@overload
def fromWpimath(obj: wpk.ChassisSpeeds) -> ChassisVelocities: ...
@overload
def fromWpimath(obj: wpk.SwerveModuleState) -> SwerveModuleVelocity: ...
@overload
def fromWpimath(obj: wpk.SwerveModulePosition) -> SwerveModulePosition: ...
@overload
def fromWpimath(obj: wpk.MecanumDriveWheelSpeeds) -> MecanumDriveWheelVelocities: ...
@overload
def fromWpimath(obj: wpk.MecanumDriveWheelPositions) -> MecanumDriveWheelPositions: ...
@overload
def fromWpimath(obj: wpk.DifferentialDriveWheelSpeeds) -> DifferentialDriveWheelVelocities: ...
@overload
def fromWpimath(obj: wpk.DifferentialDriveWheelPositions) -> DifferentialDriveWheelPositions: ...
@overload
def fromWpimath(obj: wpk.SwerveDrive2Kinematics) -> SwerveDriveKinematics: ...
@overload
def fromWpimath(obj: wpk.SwerveDrive3Kinematics) -> SwerveDriveKinematics: ...
@overload
def fromWpimath(obj: wpk.SwerveDrive4Kinematics) -> SwerveDriveKinematics: ...
@overload
def fromWpimath(obj: wpk.SwerveDrive6Kinematics) -> SwerveDriveKinematics: ...
@overload
def fromWpimath(obj: wpk.MecanumDriveKinematics) -> MecanumDriveKinematics: ...
@overload
def fromWpimath(obj: wpk.DifferentialDriveKinematics) -> DifferentialDriveKinematics: ...
@overload
def fromWpimath(obj: list[Any]) -> list[Any]: ...
@overload
def fromWpimath(obj: tuple[Any, ...]) -> tuple[Any, ...]: ...
@overload
def fromWpimath(obj: object) -> Any: ...


def fromWpimath(obj: object) -> Any:
    """Return the drivekin object equivalent to the robotpy-wpimath 2026 object ``obj``.

    Every float is copied exactly; a rotation keeps its stored (cos, sin) pair, so an
    angle robotpy kept unwrapped (``Rotation2d(3π/2)``) reads back wrapped to (−π, π]
    (−π/2). A list or tuple gives a list or tuple of converted items. Kinematics objects
    carry their geometry only (module heading memory starts empty). TypeError for
    anything else, naming its type."""
    return _convert(obj, _from_one, "fromWpimath()")
