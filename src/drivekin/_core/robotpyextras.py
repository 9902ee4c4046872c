"""robotpy 2027's names that have no WPILib Java counterpart, on drivekin's 2-D and 3-D classes.

robotpy-wpimath 2027 (robotpy/mostrobotpy, ``subprojects/robotpy-wpimath/semiwrap/*.yml``)
adds them by hand to the generated bindings: ``rename: from_matrix`` turns the Eigen-matrix
constructors into static factories, and ``inline_code`` adds the unit variants (factories
taking feet, ft/s or ft/s², and properties reading the SI fields in ft, ft/s, ft/s², deg,
deg/s, deg/s²). :data:`EXTRAS` holds them as plain Python objects ready for a class
dictionary (class name -> {robotpy name: staticmethod, property or function});
:func:`install_extras` puts them there.

Each one goes through drivekin's public constructors and properties; only the unit
conversion is computed here, in the order of operations of the C++ units library that
robotpy converts with (``value * num / den``: 1 ft = 381/1250 m = 0.3048 m exactly,
1° = π/180 rad), so the results are robotpy's bits. Where that order overflows although
the result is a finite double, it divides first; a result beyond the largest double is a
ValueError, never inf from finite input. Arguments are checked before anything is built
or assigned, so a failed call changes nothing.

``from_feet`` is not here: drivekin has robotpy 2026's ``fromFeet`` (2-D and 3-D), which
the names rule spells ``from_feet`` (_core/pynames). robotpy's argument forms are kept;
``from_matrix`` takes a float64 numpy array only, as drivekin's matrix constructors do
(robotpy also converts nested lists and integer arrays).
"""
from __future__ import annotations

import inspect
import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from drivekin._core.errors import type_name
from drivekin._core.numbers import as_double
from drivekin.chassis import ChassisAccelerations
from drivekin.differential import DifferentialDriveWheelAccelerations
from drivekin.geometry import Pose2d, Rotation2d, Transform2d, Translation2d
from drivekin.geometry3d import Pose3d, Transform3d
from drivekin.mecanum import MecanumDriveWheelAccelerations
from drivekin.swervemodule import SwerveModuleAcceleration

__all__ = ["EXTRAS", "install_extras"]

# A unit as (numerator, denominator) of its size in the SI unit: SI = value * num / den.
_FOOT = (381.0, 1250.0)
_DEGREE = (math.pi, 180.0)


def _convert(value: float, num: float, den: float, where: str) -> float:
    """``value * num / den`` as the units library computes it; divided first where the
    product alone overflows, ValueError where the result itself is beyond a double."""
    result = value * num / den
    if math.isinf(result) and math.isfinite(value):
        result = value / den * num
        if math.isinf(result):
            raise ValueError(f"{where}: {value!r} converts to more than the largest double")
    return result


def _real(value: object, where: str, what: str) -> float:
    return as_double(value, f"{where} takes {what} as a float")


def _si(value: object, unit: tuple[float, float], where: str, what: str) -> float:
    """The argument ``value``, given in ``unit``, in the SI unit."""
    return _convert(_real(value, where, what), unit[0], unit[1], where)


def _signed(cls: str, name: str, signature: str, func: Callable[..., Any]) -> Callable[..., Any]:
    """Name ``func`` as the member ``cls.name`` and put its signature line first in its
    docstring, as Cython's embedsignature does for the compiled members (the stubs'
    docstrings are the rest: scripts/stub_docstrings.py)."""
    func.__name__ = name
    func.__qualname__ = f"{cls}.{name}"
    func.__doc__ = f"{cls}.{name}{signature}\n\n{inspect.cleandoc(func.__doc__ or '')}"
    return func


def _parameters(func: Callable[..., Any]) -> str:
    """``func``'s parameters as robotpy's signature line shows them: names and defaults."""
    sig = inspect.signature(func)
    return str(sig.replace(parameters=[p.replace(annotation=p.empty)
                                       for p in sig.parameters.values()],
                           return_annotation=sig.empty))


def _static(cls: str, name: str, func: Callable[..., Any], signature: str | None = None
            ) -> staticmethod[..., Any]:
    return staticmethod(_signed(cls, name, signature or _parameters(func), func))


def _method(cls: str, name: str, func: Callable[..., Any]) -> Callable[..., Any]:
    return _signed(cls, name, _parameters(func), func)


def _unit_property(cls: str, name: str, field: str, unit: tuple[float, float],
                   writable: bool, doc: str, unit_name: str) -> property:
    """The SI property ``field`` read (and, if ``writable``, assigned) in ``unit``."""
    where = f"{cls}.{name}"
    num, den = unit

    def get(self: Any) -> float:
        return _convert(getattr(self, field), den, num, where)

    def set_(self: Any, value: object) -> None:
        setattr(self, field, _si(value, unit, where, unit_name))

    return property(get, set_ if writable else None, doc=doc)


# ---------------------------------------------------------------------------------------
# Matrices (rename: from_matrix of the Eigen constructors)

def _array(value: object, where: str, shape: str) -> np.ndarray:
    # Only an array goes on to the constructor: Rotation2d(0.5) is an angle, not a matrix.
    if not isinstance(value, np.ndarray):
        raise TypeError(f"{where} takes a {shape} float64 numpy array, got "
                        f"{type_name(value)} (numpy.asarray(m, dtype=float) converts one)")
    return value


def _rotation_from_matrix(rotation_matrix: np.ndarray) -> Rotation2d:
    """Return the rotation of a 2×2 rotation matrix ``[[cos, −sin], [sin, cos]]`` (a
    float64 numpy array): ``Rotation2d(rotation_matrix)``. ValueError unless it is special
    orthogonal (Frobenius norm of RRᵀ − I and abs(det R − 1) at most 1e-9)."""
    return Rotation2d(_array(rotation_matrix, "Rotation2d.from_matrix(rotation_matrix)",
                             "2×2"))


def _pose_from_matrix(matrix: np.ndarray) -> Pose2d:
    """Return the pose of a 3×3 homogeneous matrix ``[[cos, −sin, x], [sin, cos, y],
    [0, 0, 1]]`` in m (a float64 numpy array): ``Pose2d(matrix)``. ValueError unless the
    last row is exactly [0, 0, 1] and the rotation block is special orthogonal."""
    return Pose2d(_array(matrix, "Pose2d.from_matrix(matrix)", "3×3"))


def _pose3d_from_matrix(matrix: np.ndarray) -> Pose3d:
    """Return the pose of a 4×4 homogeneous matrix ``[[R, t], [0, 0, 0, 1]]`` in m (a
    float64 numpy array): ``Pose3d(matrix)``. ValueError unless the last row is exactly
    [0, 0, 0, 1] and R is special orthogonal."""
    return Pose3d(_array(matrix, "Pose3d.from_matrix(matrix)", "4×4"))


def _transform3d_from_matrix(matrix: np.ndarray) -> Transform3d:
    """Return the transform of a 4×4 homogeneous matrix ``[[R, t], [0, 0, 0, 1]]`` in m (a
    float64 numpy array): ``Transform3d(matrix)``. ValueError unless the last row is
    exactly [0, 0, 0, 1] and R is special orthogonal."""
    return Transform3d(_array(matrix, "Transform3d.from_matrix(matrix)", "4×4"))


def _transform_from_matrix(matrix: np.ndarray) -> Transform2d:
    """Return the transform of a 3×3 homogeneous matrix ``[[cos, −sin, x], [sin, cos, y],
    [0, 0, 1]]`` in m (a float64 numpy array): ``Transform2d(matrix)``. ValueError unless
    the last row is exactly [0, 0, 1] and the rotation block is special orthogonal."""
    return Transform2d(_array(matrix, "Transform2d.from_matrix(matrix)", "3×3"))


# ---------------------------------------------------------------------------------------
# Factories in feet (inline_code def_static)

def _feet(where: str, unit: str, values: Mapping[str, object]) -> list[float]:
    """``values`` (robotpy's argument names -> values in ``unit``: ft, ft/s or ft/s²), in
    order, in the SI unit. A factory passes its ``locals()`` before binding anything else:
    its parameters."""
    return [_si(v, _FOOT, where, f"{name} in {unit}") for name, v in values.items()]


def _chassis_accelerations_from_fps(ax: float = 0.0, ay: float = 0.0, alpha: float = 0.0
                                    ) -> ChassisAccelerations:
    """Return the acceleration ``ax`` forward and ``ay`` left given in ft/s² (in m/s²)
    and ``alpha`` in rad/s²."""
    where = "ChassisAccelerations.from_fps()"
    forward, left = _feet(where, "ft/s²", {"ax": ax, "ay": ay})
    return ChassisAccelerations(forward, left, _real(alpha, where, "alpha in rad/s²"))


def _swerve_module_acceleration_from_fps(acceleration: float = 0.0,
                                         angle: Rotation2d | float | None = None
                                         ) -> SwerveModuleAcceleration:
    """Return the module acceleration ``acceleration`` given in ft/s² (in m/s²) at
    ``angle`` (a Rotation2d, rad as a float, or None for Rotation2d())."""
    where = "SwerveModuleAcceleration.from_fps()"
    (magnitude,) = _feet(where, "ft/s²", {"acceleration": acceleration})
    return SwerveModuleAcceleration(magnitude, angle)


def _mecanum_accelerations_from_fps(front_left: float = 0.0, front_right: float = 0.0,
                                    rear_left: float = 0.0, rear_right: float = 0.0
                                    ) -> MecanumDriveWheelAccelerations:
    """Return the wheel accelerations given in ft/s², in m/s²."""
    return MecanumDriveWheelAccelerations(
        *_feet("MecanumDriveWheelAccelerations.from_fps()", "ft/s²", locals()))


def _differential_accelerations_from_fps(left: float, right: float
                                         ) -> DifferentialDriveWheelAccelerations:
    """Return the wheel accelerations given in ft/s², in m/s²."""
    return DifferentialDriveWheelAccelerations(
        *_feet("DifferentialDriveWheelAccelerations.from_fps()", "ft/s²", locals()))


# ---------------------------------------------------------------------------------------
# Translation2d's and Translation3d's methods in feet (inline_code def; robotpy names no
# parameter)

def _translation_feet(cls: str) -> dict[str, object]:
    """distance_feet and norm_feet of the translation class ``cls``."""

    def distance_feet(self: Any, other: Any, /) -> float:
        """Return the distance to ``other``, ft (``getDistance(other)`` in m)."""
        return _convert(self.getDistance(other), _FOOT[1], _FOOT[0],
                        f"{cls}.distance_feet()")

    def norm_feet(self: Any) -> float:
        """Return the distance from the origin, ft (``getNorm()`` in m)."""
        return _convert(self.getNorm(), _FOOT[1], _FOOT[0], f"{cls}.norm_feet()")

    return {"distance_feet": _method(cls, "distance_feet", distance_feet),
            "norm_feet": _method(cls, "norm_feet", norm_feet)}


# ---------------------------------------------------------------------------------------
# The table

_FT = (_FOOT, "ft", "m")
_FPS = (_FOOT, "ft/s", "m/s")
_FPSS = (_FOOT, "ft/s²", "m/s²")


def _properties(cls: str, writable: bool,
                rows: tuple[tuple[str, str, tuple[tuple[float, float], str, str], str], ...]
                ) -> dict[str, object]:
    """{name: property} from rows (name, SI field, (unit, its name, the SI unit's name),
    what it is)."""
    return {name: _unit_property(
        cls, name, field, unit, writable,
        f"{what}, {unit_name} (``{field}`` in {si_name}){'; assignable' if writable else ''}.",
        unit_name) for name, field, (unit, unit_name, si_name), what in rows}


def _frame(cls: str, what: str, axes: str = "xy") -> dict[str, object]:
    """x_feet, y_feet (and z_feet), read-only (def_property_readonly) as x, y, z are."""
    return _properties(cls, False, tuple(
        (f"{a}_feet", a, _FT, f"{a.upper()} component of the {what}") for a in axes))


def _wheels(cls: str, suffix: str, unit: tuple[tuple[float, float], str, str]
            ) -> dict[str, object]:
    """The per-wheel properties of a wheel values class (front_left_fps, left_fpss ...)."""
    fields = (("front_left", "frontLeft"), ("front_right", "frontRight"),
              ("rear_left", "rearLeft"), ("rear_right", "rearRight")) \
        if cls.startswith("Mecanum") else (("left", "left"), ("right", "right"))
    return _properties(cls, True, tuple(
        (f"{name}_{suffix}", field, unit, f"{name.replace('_', '-').capitalize()} wheel")
        for name, field in fields))


# drivekin class name -> {robotpy 2027 name: staticmethod / property / function}
EXTRAS: dict[str, dict[str, object]] = {
    "Rotation2d": {
        "from_matrix": _static("Rotation2d", "from_matrix", _rotation_from_matrix),
    },
    "Translation2d": {
        **_frame("Translation2d", "translation"),
        **_translation_feet("Translation2d"),
    },
    "Pose2d": {
        "from_matrix": _static("Pose2d", "from_matrix", _pose_from_matrix),
        **_frame("Pose2d", "position"),
    },
    "Transform2d": {
        "from_matrix": _static("Transform2d", "from_matrix", _transform_from_matrix),
        **_frame("Transform2d", "translation"),
    },
    "Twist2d": {
        **_properties("Twist2d", True, (
            ("dx_feet", "dx", _FT, "Change along the start frame's x axis"),
            ("dy_feet", "dy", _FT, "Change along the start frame's y axis"),
            ("dtheta_degrees", "dtheta", (_DEGREE, "degrees", "rad"), "Change in heading"),
        )),
    },
    "Rotation3d": _properties("Rotation3d", False, (
        ("x_degrees", "x", (_DEGREE, "degrees", "rad"),
         "Counter-clockwise rotation about the X axis (roll)"),
        ("y_degrees", "y", (_DEGREE, "degrees", "rad"),
         "Counter-clockwise rotation about the Y axis (pitch)"),
        ("z_degrees", "z", (_DEGREE, "degrees", "rad"),
         "Counter-clockwise rotation about the Z axis (yaw)"),
        ("angle_degrees", "angle", (_DEGREE, "degrees", "rad"),
         "Angle of the rotation about its axis"),
    )),
    "Translation3d": {
        **_frame("Translation3d", "translation", "xyz"),
        **_translation_feet("Translation3d"),
    },
    "Pose3d": {
        "from_matrix": _static("Pose3d", "from_matrix", _pose3d_from_matrix),
        **_frame("Pose3d", "position", "xyz"),
    },
    "Transform3d": {
        "from_matrix": _static("Transform3d", "from_matrix", _transform3d_from_matrix),
        **_frame("Transform3d", "translation", "xyz"),
    },
    "Twist3d": {
        **_properties("Twist3d", True, (
            ("dx_feet", "dx", _FT, "Change along the start frame's x axis"),
            ("dy_feet", "dy", _FT, "Change along the start frame's y axis"),
            ("dz_feet", "dz", _FT, "Change along the start frame's z axis"),
            ("rx_degrees", "rx", (_DEGREE, "degrees", "rad"),
             "Rotation vector's x component"),
            ("ry_degrees", "ry", (_DEGREE, "degrees", "rad"),
             "Rotation vector's y component"),
            ("rz_degrees", "rz", (_DEGREE, "degrees", "rad"),
             "Rotation vector's z component"),
        )),
    },
    "ChassisVelocities": {
        **_properties("ChassisVelocities", True, (
            ("vx_fps", "vx", _FPS, "Forward velocity"),
            ("vy_fps", "vy", _FPS, "Leftward velocity"),
            ("omega_dps", "omega", (_DEGREE, "deg/s", "rad/s"),
             "Angular velocity, counter-clockwise positive"),
        )),
    },
    "ChassisAccelerations": {
        "from_fps": _static("ChassisAccelerations", "from_fps",
                            _chassis_accelerations_from_fps),
        **_properties("ChassisAccelerations", True, (
            ("ax_fpss", "ax", _FPSS, "Forward acceleration"),
            ("ay_fpss", "ay", _FPSS, "Leftward acceleration"),
            ("alpha_dpss", "alpha", (_DEGREE, "deg/s²", "rad/s²"),
             "Angular acceleration, counter-clockwise positive"),
        )),
    },
    "SwerveModuleVelocity": _properties("SwerveModuleVelocity", True, (
        ("velocity_fps", "velocity", _FPS, "Wheel velocity"),)),
    "SwerveModulePosition": _properties("SwerveModulePosition", True, (
        ("distance_ft", "distance", _FT, "Distance driven by the wheel"),)),
    "SwerveModuleAcceleration": {
        "from_fps": _static("SwerveModuleAcceleration", "from_fps",
                            _swerve_module_acceleration_from_fps),
        **_properties("SwerveModuleAcceleration", True, (
            ("acceleration_fpss", "acceleration", _FPSS, "Acceleration magnitude"),)),
    },
    "MecanumDriveWheelVelocities": {
        **_wheels("MecanumDriveWheelVelocities", "fps", _FPS),
    },
    "MecanumDriveWheelAccelerations": {
        "from_fps": _static("MecanumDriveWheelAccelerations", "from_fps",
                            _mecanum_accelerations_from_fps),
        **_wheels("MecanumDriveWheelAccelerations", "fpss", _FPSS),
    },
    "DifferentialDriveWheelVelocities": {
        **_wheels("DifferentialDriveWheelVelocities", "fps", _FPS),
    },
    "DifferentialDriveWheelAccelerations": {
        "from_fps": _static("DifferentialDriveWheelAccelerations", "from_fps",
                            _differential_accelerations_from_fps),
        **_wheels("DifferentialDriveWheelAccelerations", "fpss", _FPSS),
    },
}


def install_extras(namespace: Mapping[str, Any]) -> None:
    """Put every name of :data:`EXTRAS` into its class's dictionary (classes by name from
    ``namespace``, the package's). A name the class (or a base) already has is an error,
    unless it is this very extra, installed before; nothing is installed then."""
    from drivekin._core.wheels import set_type_attr
    todo = []
    for cls_name, members in EXTRAS.items():
        cls = namespace[cls_name]
        for name, value in members.items():
            owner = next((k for k in cls.__mro__ if name in vars(k)), None)
            if owner is None:
                todo.append((cls, name, value))
            elif vars(owner)[name] is not value:
                raise RuntimeError(f"{cls_name}.{name} exists ({owner.__qualname__} defines "
                                   "it); it cannot be a robotpy 2027 extra")
    for cls, name, value in todo:
        set_type_attr(cls, name, value)
        # What a class statement does for its descriptors (a property learns its name,
        # for its error messages).
        set_name = getattr(type(value), "__set_name__", None)
        if set_name is not None:
            set_name(value, cls, name)
