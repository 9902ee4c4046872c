"""Converters between drivekin and robotpy-wpimath (``wpimath``) objects, 2026 or 2027.

``toWpimath(obj)`` turns a drivekin object into the robotpy-wpimath object of the same
meaning, ``fromWpimath(obj)`` goes the other way, mapping WPILib 2026 names to 2027 ones:

==========================================  ==========================================
drivekin (WPILib 2027)                       robotpy-wpimath 2026
==========================================  ==========================================
Translation2d, Rotation2d, Pose2d,           the same names in ``wpimath.geometry``
Transform2d, Twist2d
Translation3d, Quaternion, Rotation3d,       the same names in ``wpimath.geometry``
Pose3d, Transform3d, Twist3d
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
DCMotor                                      ``wpimath.system.plant.DCMotor``
==========================================  ==========================================

robotpy-wpimath 2027 works the same way: it has each of these classes in ``wpimath``
itself under drivekin's name (``wpimath.ChassisVelocities``; swerve kinematics stay
``SwerveDrive{2,3,4,6}Kinematics``) and spells members in snake_case (``get_modules()``,
``front_left``, ``trackwidth``, ``nominal_voltage``, ``from_matrix``). ``toWpimath``
builds the installed generation's objects and ``fromWpimath`` takes them: the classes are
found by name in the installed package (the 2027 name first, in ``wpimath`` or in its
2026 modules), and attributes are read in either spelling (``get_quaternion()``,
``Quaternion.w``; 2026: ``getQuaternion()``, ``W()``), so no version is consulted.

Units are the same on both sides (m, m/s, rad, rad/s). Every conversion is exact: each
float is copied, never recomputed. A rotation is carried as its stored (cos, sin) pair —
not through its angle, whose cos/sin would differ in the last bit — so a drivekin →
wpimath → drivekin round trip returns bit-identical objects. The one exception is a
``Rotation3d`` going to robotpy (alone or in a Pose3d or Transform3d): robotpy can build
one only through a constructor that renormalises, ``Rotation3d(Quaternion)``, which
divides each component by the norm it computes, and for a unit quaternion that norm may
be an ulp off 1, so each component may move by up to 4 ulps (about 9e-16; the rotation
itself equal by WPILib's equality; renormalising is not idempotent, so this holds for
robotpy's own quaternions too). ``fromWpimath`` copies robotpy's stored quaternion
exactly, and a drivekin Rotation3d unpacked from WPILib bytes (:mod:`drivekin.wpistruct`)
has the bits robotpy's unpack gives. Quaternion is copied as it is, both ways.

A robotpy 2026 ``Rotation2d`` remembers the angle it was built with
(``Rotation2d(3π/2).radians()`` is 4.71); drivekin, like WPILib 2027, keeps only (cos,
sin), so its angle comes back wrapped to (−π, π] (−π/2 here: ``atan2(sin, cos)``).
Kinematics objects carry their module geometry only: the module heading memory starts
empty on the new object (robotpy has no getter for it; call ``resetHeadings`` to set it).

Sequences: a list or tuple is converted element by element into a container of the same
kind (robotpy's ``toSwerveModuleStates`` returns a tuple: ``fromWpimath`` of it is a
tuple of SwerveModuleVelocity). Only one level: a nested list is a TypeError, as is any
other iterable (generator, numpy array).

Not converted (TypeError saying so): drivekin's 2027 additions that robotpy-wpimath 2026
lacks (ChassisAccelerations, SwerveModuleAcceleration, the wheel accelerations: robotpy
2027 has them, but interop converts only what both generations share), dead-wheel and
differential swerve kinematics, odometry objects (stateful: build the other library's
odometry from converted kinematics and poses), CoordinateAxis and CoordinateSystem, and
wpimath types drivekin has no counterpart for (estimators, trajectories, ...).

``fromWpimath3d`` flattens robotpy's 3-D values to drivekin's 2-D ones (as ``toPose2d``
does); ``fromWpimath`` keeps the third dimension (a robotpy Pose3d gives a drivekin
Pose3d).

robotpy-wpimath is optional: importing drivekin or this module never imports it. The first
conversion that needs it does, and if it is missing raises ImportError (a
ModuleNotFoundError when the package is absent) saying to ``pip install robotpy-wpimath``,
or ``pip install "drivekin[wpimath]"``.
"""
from __future__ import annotations

import importlib
from collections.abc import Callable
from types import ModuleType
from typing import TYPE_CHECKING, Any, TypeVar, overload

from drivekin._core import catalog
from drivekin._core.catalog import SWERVE_MODULE_COUNTS  # noqa: F401  (0.1.0 name)
from drivekin._core.catalog import qualified as _qualified
from drivekin.geometry import Pose2d, Rotation2d, Transform2d, Translation2d

if TYPE_CHECKING:
    # The overloads below give each conversion its static types.
    import wpimath.geometry as wpg
    import wpimath.kinematics as wpk
    import wpimath.system.plant as wpp

    from drivekin import (
        ChassisVelocities,
        DCMotor,
        DifferentialDriveKinematics,
        DifferentialDriveWheelPositions,
        DifferentialDriveWheelVelocities,
        MecanumDriveKinematics,
        MecanumDriveWheelPositions,
        MecanumDriveWheelVelocities,
        Pose3d,
        Quaternion,
        Rotation3d,
        SwerveDriveKinematics,
        SwerveModulePosition,
        SwerveModuleVelocity,
        Transform3d,
        Translation3d,
        Twist2d,
        Twist3d,
    )

__all__ = ["fromWpimath", "fromWpimath3d", "toWpimath"]

_V = TypeVar("_V")

INSTALL_HINT = ('install it with `pip install robotpy-wpimath` '
                '(or `pip install "drivekin[wpimath]"`)')


# ---- the converters: the catalog's robotpy-wpimath peers ---------------------------------

_PEERS: tuple[tuple[type, catalog.Peer], ...] = tuple(
    (e.cls, e.peer) for e in catalog.ENTRIES if e.peer is not None)
_TO: dict[type, Callable[[Any, _Wpimath], Any]] = {cls: peer.to for cls, peer in _PEERS}
# drivekin classes that robotpy-wpimath has no counterpart for, and why.
_NO_PEER: dict[str, str] = {e.cls.__name__: e.no_peer.format(e.cls.__name__)
                            for e in catalog.ENTRIES if e.no_peer is not None}


def _project(obj: Any, new: str, old: str) -> Any:
    return catalog.robotpy_attr(obj, new, old)()


# fromWpimath3d: each robotpy 3-D class, the drivekin 2-D class it gives, and robotpy's own
# projection to its 2-D class (robotpy 2027 spells toPose2d to_pose2d, and so on).
_FLATTEN_3D: tuple[tuple[str, type, Callable[[Any, _Wpimath], Any]], ...] = (
    ("Pose3d", Pose2d, lambda p, w: _project(p, "to_pose2d", "toPose2d")),
    ("Transform3d", Transform2d, lambda t, w: w.cls("Transform2d")(
        _project(t.translation(), "to_translation2d", "toTranslation2d"),
        _project(t.rotation(), "to_rotation2d", "toRotation2d"))),
    ("Translation3d", Translation2d,
     lambda t, w: _project(t, "to_translation2d", "toTranslation2d")),
    ("Rotation3d", Rotation2d, lambda r, w: _project(r, "to_rotation2d", "toRotation2d")),
)

# robotpy 2027 class name -> the robotpy 2026 module and the names to look for, 2027's
# first (``_Wpimath.cls``).
_WHERE: dict[str, tuple[str, tuple[str, ...]]] = {
    new: (peer.module, (new,) if new == old else (new, old))
    for _, peer in _PEERS for new, old in zip(peer.names2027, peer.names)}


class _Wpimath:
    """The installed robotpy-wpimath, either generation, found by class names: robotpy
    2027 has every class in ``wpimath`` itself (mostrobotpy flattened the namespaces),
    robotpy 2026 in ``wpimath.geometry``, ``wpimath.kinematics`` and
    ``wpimath.system.plant``, some under WPILib 2026's names (ChassisSpeeds)."""

    def __init__(self, package: ModuleType) -> None:
        self._package = package
        self.flat = hasattr(package, "Rotation2d")
        self._classes: dict[str, type | None] = {}
        self._from: dict[type, tuple[type, Callable[[Any], Any]]] | None = None
        self._from_3d: dict[type, tuple[type, Callable[[Any, _Wpimath], Any]]] | None = None

    def _find(self, name: str) -> type | None:
        if name not in self._classes:
            module, names = _WHERE[name]
            space = (self._package if self.flat
                     else importlib.import_module(f"wpimath.{module}"))
            found = (getattr(space, n, None) for n in names)
            self._classes[name] = next((c for c in found if isinstance(c, type)), None)
        return self._classes[name]

    def cls(self, name: str) -> Any:
        """The robotpy class of the robotpy 2027 name ``name`` (on robotpy 2026 its 2026
        name: ``ChassisVelocities`` gives ``ChassisSpeeds``)."""
        found = self._find(name)
        if found is None:
            raise ImportError(
                f"the installed robotpy-wpimath ({getattr(self._package, '__file__', '?')}) "
                f"has no {' or '.join(_WHERE[name][1])}: drivekin.interop supports "
                "robotpy-wpimath 2026 and 2027", name="wpimath")
        return found

    def from_table(self) -> dict[type, tuple[type, Callable[[Any], Any]]]:
        """fromWpimath's table: robotpy class -> (drivekin class, converter)."""
        if self._from is None:
            self._from = {c: (cls, peer.frm) for cls, peer in _PEERS
                          for c in map(self._find, peer.names2027) if c is not None}
        return self._from

    def from_3d_table(self) -> dict[type, tuple[type, Callable[[Any, _Wpimath], Any]]]:
        """fromWpimath3d's table: robotpy 3-D class -> (drivekin 2-D class, projection)."""
        if self._from_3d is None:
            self._from_3d = {c: (cls, flatten) for name, cls, flatten in _FLATTEN_3D
                             if (c := self._find(name)) is not None}
        return self._from_3d


_wpimath: _Wpimath | None = None


def _load() -> _Wpimath:
    """Import robotpy-wpimath on first use (it is optional)."""
    global _wpimath
    if _wpimath is None:
        try:
            w = _Wpimath(importlib.import_module("wpimath"))
            if not w.flat:
                # robotpy 2026: import its modules now, so a broken install fails here.
                importlib.import_module("wpimath.geometry")
                importlib.import_module("wpimath.kinematics")
        except ModuleNotFoundError as e:
            raise ModuleNotFoundError(
                f"drivekin.interop needs robotpy-wpimath, which is not installed ({e}): "
                f"{INSTALL_HINT}", name=e.name or "wpimath") from e
        except ImportError as e:
            raise ImportError(
                f"drivekin.interop needs robotpy-wpimath, which failed to import ({e}): "
                f"reinstall it, or {INSTALL_HINT}", name="wpimath") from e
        _wpimath = w
    return _wpimath


# ---- dispatch ----------------------------------------------------------------------------

def _lookup(table: dict[type, _V], obj: object) -> _V | None:
    # The exact class first, then its bases (a user's subclass of a robotpy class).
    for klass in type(obj).__mro__:
        found = table.get(klass)
        if found is not None:
            return found
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


def _conversions(obj: object) -> list[tuple[str, type]]:
    """The functions that convert the robotpy-wpimath object ``obj`` (``"fromWpimath"``,
    then ``"fromWpimath3d"`` for a 3-D value it flattens) and the drivekin class each
    gives (error messages)."""
    w = _load()
    tables: tuple[tuple[str, dict[type, tuple[type, Any]]], ...] = (
        ("fromWpimath", w.from_table()), ("fromWpimath3d", w.from_3d_table()))
    out = []
    for function, table in tables:
        found = _lookup(table, obj)
        if found is not None:
            out.append((function, found[0]))
    return out


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
    elif _is_drivekin(obj) and name in _NO_PEER:
        reason = _NO_PEER[name]
    elif _is_drivekin(obj) and name.endswith(("Odometry", "PoseEstimator")):
        reason = _STATEFUL
    else:
        reason = "it is not a drivekin value or kinematics type"
    raise TypeError(f"{where} cannot convert {_qualified(obj)}: {reason}")


def _from_one(obj: object, where: str) -> Any:
    if _is_wpimath(obj):
        found = _lookup(_load().from_table(), obj)
        if found is not None:
            return found[1](obj)
        name = type(obj).__name__
        stateful = name.endswith(("Odometry", "Odometry3d", "PoseEstimator", "PoseEstimator3d"))
        # robotpy 2027's classes new in WPILib 2027 (ChassisAccelerations, ...) say why.
        reason = (_STATEFUL if stateful else _NO_PEER.get(name)
                  or "drivekin has no counterpart of it")
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
def toWpimath(obj: Translation3d) -> wpg.Translation3d: ...
@overload
def toWpimath(obj: Quaternion) -> wpg.Quaternion: ...
@overload
def toWpimath(obj: Rotation3d) -> wpg.Rotation3d: ...
@overload
def toWpimath(obj: Pose3d) -> wpg.Pose3d: ...
@overload
def toWpimath(obj: Transform3d) -> wpg.Transform3d: ...
@overload
def toWpimath(obj: Twist3d) -> wpg.Twist3d: ...
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
def toWpimath(obj: DCMotor) -> wpp.DCMotor: ...
@overload
def toWpimath(obj: list[Any]) -> list[Any]: ...
@overload
def toWpimath(obj: tuple[Any, ...]) -> tuple[Any, ...]: ...
@overload
def toWpimath(obj: object) -> Any: ...


def toWpimath(obj: object) -> Any:
    """Return the robotpy-wpimath object equivalent to the drivekin object ``obj``, of the
    installed generation (robotpy 2026's ChassisSpeeds, or robotpy 2027's
    ChassisVelocities; the type hints name 2026's classes).

    Every float is copied exactly (rotations as their (cos, sin) pair), except that
    robotpy's Rotation3d constructor renormalises the quaternion (each component may move
    by up to 4 ulps; see the module's docs); units are the same on both sides (m, m/s,
    rad, rad/s). A list or tuple gives a list or tuple of converted items. A
    SwerveDriveKinematics becomes ``SwerveDrive{N}Kinematics`` and needs N in (2, 3, 4,
    6) (ValueError otherwise). TypeError for anything else, naming
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
def fromWpimath(obj: wpg.Translation3d) -> Translation3d: ...
@overload
def fromWpimath(obj: wpg.Quaternion) -> Quaternion: ...
@overload
def fromWpimath(obj: wpg.Rotation3d) -> Rotation3d: ...
@overload
def fromWpimath(obj: wpg.Pose3d) -> Pose3d: ...
@overload
def fromWpimath(obj: wpg.Transform3d) -> Transform3d: ...
@overload
def fromWpimath(obj: wpg.Twist3d) -> Twist3d: ...
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
def fromWpimath(obj: wpp.DCMotor) -> DCMotor: ...
@overload
def fromWpimath(obj: list[Any]) -> list[Any]: ...
@overload
def fromWpimath(obj: tuple[Any, ...]) -> tuple[Any, ...]: ...
@overload
def fromWpimath(obj: object) -> Any: ...


def fromWpimath(obj: object) -> Any:
    """Return the drivekin object equivalent to the robotpy-wpimath object ``obj``
    (robotpy 2026's or 2027's classes and spellings).

    Every float is copied exactly; a rotation keeps its stored (cos, sin) pair, so an
    angle robotpy kept unwrapped (``Rotation2d(3π/2)``) reads back wrapped to (−π, π]
    (−π/2), and a Rotation3d its stored quaternion (ValueError if that is not a unit
    quaternion or NaN). 3-D values stay 3-D (:func:`fromWpimath3d` flattens them). A
    list or tuple gives a list or tuple of converted items. Kinematics objects carry
    their geometry only (module heading memory starts empty). TypeError for
    anything else, naming its type."""
    return _convert(obj, _from_one, "fromWpimath()")


def _from_3d(obj: object, where: str) -> Any:
    if _is_wpimath(obj):
        w = _load()
        found = _lookup(w.from_3d_table(), obj)
        if found is not None:
            return _from_one(found[1](obj, w), where)
    raise TypeError(f"{where} cannot convert {_qualified(obj)}: it is not a robotpy-wpimath "
                    "Pose3d, Transform3d, Translation3d or Rotation3d (fromWpimath converts "
                    "the others, 3-D ones as they are)")


def fromWpimath3d(obj: object) -> Any:
    """Return the drivekin 2-D object for a robotpy-wpimath 3-D one, with robotpy's
    ``toPose2d`` semantics: a Pose3d gives a Pose2d and a Transform3d a Transform2d (x, y
    and the rotation about z), a Translation3d a Translation2d (x, y), a Rotation3d a
    Rotation2d (about z). robotpy computes the 2-D value (``toPose2d``,
    ``toTranslation2d``, ``toRotation2d``; robotpy 2027: ``to_pose2d``, ...) and it is
    then copied exactly, as by
    :func:`fromWpimath`; for a vision pose from photonlibpy, ``fromWpimath3d(pose3d)`` is
    ``fromWpimath(pose3d.toPose2d())``. A list or tuple gives a list or tuple of converted
    items. TypeError for anything else."""
    return _convert(obj, _from_3d, "fromWpimath3d()")
