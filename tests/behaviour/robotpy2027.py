"""Stand-ins for robotpy-wpimath 2027's classes, for drivekin.interop's tests (robotpy 2027
wheels cannot be installed here).

robotpy 2027 (robotpy/mostrobotpy e51721a, the commit tests/data/robotpy2027-names.json was
made from) has every class in the package ``wpimath`` itself (mostrobotpy 9caf4fe5,
"Flatten wpimath namespaces"), defined in its extension module ``wpimath._wpimath``:
``package()`` builds such a package. The classes carry only names from the table, each as
robotpy has it (method, static method, read-only or writable property; constructor
keywords); ``test_interop_robotpy2027`` checks them against the table, and every public
attribute read on them is recorded in ``READS`` so that the test can check what interop
reads too.

Behaviour follows robotpy 2027's C++ (allwpilib 92efd74d9) where interop depends on it:
``Rotation2d(x, y)`` divides by ``hypot(x, y)`` (giving (1, 0) at or below 1e-6 and for
NaN), ``from_matrix`` copies R(0,0) and R(1,0) after its orthogonality checks (which NaN
passes), ``DCMotor`` multiplies by the motor count and derives r, kv and kt as the C++
constructor does, ``Rotation3d(q)`` normalises ``q`` as ``Quaternion::Normalize`` does
(n = sqrt(((w² + x²) + y²) + z²), each component divided by n; the identity for n = 0),
``Rotation3d(roll, pitch, yaw)`` builds its quaternion with the C++ formula, and its x, y, z
and ``to_rotation2d`` read the angles back with the C++ formulas (Python's libm, so the
last bits may differ from robotpy's gcem; nothing here compares them with drivekin's).
"""
from __future__ import annotations

import inspect
import math
import types
from typing import Any

import numpy as np

MODULE = "wpimath._wpimath"

#: (class name, attribute) of every public attribute read on a stand-in or its class.
READS: set[tuple[str, str]] = set()


class _Recorded(type):
    def __getattribute__(cls, name: str) -> Any:
        if not name.startswith("_"):
            READS.add((type.__getattribute__(cls, "__name__"), name))
        return type.__getattribute__(cls, name)


class _Value(metaclass=_Recorded):
    def __getattribute__(self, name: str) -> Any:
        if not name.startswith("_"):
            READS.add((type(self).__name__, name))
        return object.__getattribute__(self, name)


def _ro(name: str) -> property:
    """A read-only property (robotpy's ``def_property_readonly`` or a const C++ field)."""
    return property(lambda self: getattr(self, "_" + name))


def _rw(name: str) -> property:
    """A writable property (a public C++ field)."""
    return property(lambda self: getattr(self, "_" + name),
                    lambda self, v: setattr(self, "_" + name, float(v)))


def _set(obj: object, **fields: Any) -> None:
    for k, v in fields.items():
        object.__setattr__(obj, "_" + k, v)


def _plain(name: str, fields: tuple[str, ...], *, readonly: bool = False,
           **methods: Any) -> Any:
    """A robotpy class of float fields (properties), constructed from them: positional or
    by keyword, each defaulting to 0 (robotpy's ``py::arg("vx") = 0``)."""
    signature = inspect.Signature(
        [inspect.Parameter("self", inspect.Parameter.POSITIONAL_OR_KEYWORD)]
        + [inspect.Parameter(f, inspect.Parameter.POSITIONAL_OR_KEYWORD, default=0.0)
           for f in fields])

    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
        given = signature.bind(self, *args, **kwargs)
        given.apply_defaults()
        _set(self, **{f: float(given.arguments[f]) for f in fields})

    __init__.__signature__ = signature  # type: ignore[attr-defined]
    field = _ro if readonly else _rw
    return _Recorded(name, (_Value,), {"__init__": __init__, "__module__": MODULE,
                                       "__qualname__": name, **methods,
                                       **{f: field(f) for f in fields}})


# ---- geometry ------------------------------------------------------------------------------

class Rotation2d(_Value):
    def __init__(self, *args: float) -> None:
        if len(args) == 1:
            # C++'s cos and sin of ±inf are NaN (Python's raise).
            a = float(args[0])
            c, s = (math.cos(a), math.sin(a)) if not math.isinf(a) else (math.nan, math.nan)
        elif len(args) == 2:
            x, y = map(float, args)
            magnitude = math.hypot(x, y)
            c, s = (x / magnitude, y / magnitude) if magnitude > 1e-6 else (1.0, 0.0)
        else:
            assert not args
            c, s = 1.0, 0.0
        _set(self, c=c, s=s)

    @staticmethod
    def from_matrix(rotation_matrix: Any) -> Rotation2d:
        (a, b), (c, d) = np.asarray(rotation_matrix, dtype=np.float64).tolist()
        # ||R Rᵀ - I|| (Frobenius) and det R, as the C++ constructor checks them.
        off = a * c + b * d
        if math.sqrt((a * a + b * b - 1) ** 2 + 2 * off * off + (c * c + d * d - 1) ** 2) > 1e-9:
            raise ValueError("Rotation matrix isn't orthogonal")
        if abs(a * d - b * c - 1.0) > 1e-9:
            raise ValueError("Rotation matrix is orthogonal but not special orthogonal")
        r = Rotation2d()
        _set(r, c=a, s=c)
        return r

    def cos(self) -> float:
        return self._c

    def sin(self) -> float:
        return self._s

    def radians(self) -> float:
        return math.atan2(self._s, self._c)


Translation2d = _plain("Translation2d", ("x", "y"), readonly=True)


class _Frame2d(_Value):
    x = _ro("x")
    y = _ro("y")

    def __init__(self, *args: Any) -> None:
        if len(args) == 2:
            (t, r), (x, y) = args, (args[0].x, args[0].y)
        elif len(args) == 3:
            x, y, r = args
        else:
            assert not args
            x, y, r = 0.0, 0.0, Rotation2d()
        assert type(r) is Rotation2d
        _set(self, x=float(x), y=float(y), r=r)

    def translation(self) -> Any:
        return Translation2d(self._x, self._y)

    def rotation(self) -> Rotation2d:
        return self._r


class Pose2d(_Frame2d):
    pass


class Transform2d(_Frame2d):
    pass


Twist2d = _plain("Twist2d", ("dx", "dy", "dtheta"))
Translation3d = _plain("Translation3d", ("x", "y", "z"), readonly=True,
                       to_translation2d=lambda self: Translation2d(self._x, self._y))


class Quaternion(_Value):
    w = _ro("w")
    x = _ro("x")
    y = _ro("y")
    z = _ro("z")

    def __init__(self, w: float = 1.0, x: float = 0.0, y: float = 0.0, z: float = 0.0) -> None:
        _set(self, w=float(w), x=float(x), y=float(y), z=float(z))

    def normalize(self) -> Quaternion:
        w, x, y, z = self._w, self._x, self._y, self._z
        n = math.sqrt(w * w + x * x + y * y + z * z)
        return Quaternion() if n == 0.0 else Quaternion(w / n, x / n, y / n, z / n)


def _euler(q: Quaternion) -> tuple[float, float, float]:
    """Rotation3d::X(), Y(), Z() of the C++ header (gimbal lock included)."""
    w, x, y, z = q._w, q._x, q._y, q._z
    cxcy, sxcy = 1.0 - 2.0 * (x * x + y * y), 2.0 * (w * x + y * z)
    roll = math.atan2(sxcy, cxcy) if cxcy * cxcy + sxcy * sxcy > 1e-20 else 0.0
    ratio = 2.0 * (w * y - z * x)
    pitch = math.copysign(math.pi / 2, ratio) if abs(ratio) >= 1.0 else math.asin(ratio)
    cycz, cysz = 1.0 - 2.0 * (y * y + z * z), 2.0 * (w * z + x * y)
    yaw = (math.atan2(cysz, cycz) if cycz * cycz + cysz * cysz > 1e-20
           else math.atan2(2.0 * w * z, w * w - z * z))
    return roll, pitch, yaw


class Rotation3d(_Value):
    x = property(lambda self: _euler(self._q)[0])
    y = property(lambda self: _euler(self._q)[1])
    z = property(lambda self: _euler(self._q)[2])

    def __init__(self, *args: Any) -> None:
        if len(args) == 1:
            assert type(args[0]) is Quaternion
            q = args[0].normalize()
        elif len(args) == 3:
            hr, hp, hy = (0.5 * float(a) for a in args)
            cr, sr, cp, sp = math.cos(hr), math.sin(hr), math.cos(hp), math.sin(hp)
            cy, sy = math.cos(hy), math.sin(hy)
            q = Quaternion(cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
                           cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy)
        else:
            assert not args
            q = Quaternion()
        _set(self, q=q)

    def get_quaternion(self) -> Quaternion:
        return self._q

    def to_rotation2d(self) -> Rotation2d:
        return Rotation2d(self.z)


class _Frame3d(_Value):
    x = _ro("x")
    y = _ro("y")
    z = _ro("z")

    def __init__(self, *args: Any) -> None:
        t = args[0] if len(args) == 2 else Translation3d(*args[:3])    # or (x, y, z, rotation)
        _set(self, x=t.x, y=t.y, z=t.z, t=t, r=args[-1])

    def translation(self) -> Any:
        return self._t

    def rotation(self) -> Any:
        return self._r


class Pose3d(_Frame3d):
    def to_pose2d(self) -> Pose2d:
        return Pose2d(self._x, self._y, self._r.to_rotation2d())


class Transform3d(_Frame3d):
    pass


Twist3d = _plain("Twist3d", ("dx", "dy", "dz", "rx", "ry", "rz"))


# ---- kinematics values -------------------------------------------------------------------

ChassisVelocities = _plain("ChassisVelocities", ("vx", "vy", "omega"))
ChassisAccelerations = _plain("ChassisAccelerations", ("ax", "ay", "alpha"))
_MECANUM = ("front_left", "front_right", "rear_left", "rear_right")
MecanumDriveWheelVelocities = _plain("MecanumDriveWheelVelocities", _MECANUM)
MecanumDriveWheelPositions = _plain("MecanumDriveWheelPositions", _MECANUM)
DifferentialDriveWheelVelocities = _plain("DifferentialDriveWheelVelocities", ("left", "right"))


class DifferentialDriveWheelPositions(_Value):
    left = _rw("left")
    right = _rw("right")

    def __init__(self) -> None:    # robotpy 2027 binds only the default constructor
        _set(self, left=0.0, right=0.0)


class SwerveModuleVelocity(_Value):
    velocity = _rw("velocity")
    angle = property(lambda self: self._angle,
                     lambda self, v: object.__setattr__(self, "_angle", v))

    def __init__(self, velocity: float = 0.0, angle: Rotation2d | None = None) -> None:
        _set(self, velocity=float(velocity), angle=Rotation2d() if angle is None else angle)


class SwerveModulePosition(_Value):
    distance = _rw("distance")
    angle = SwerveModuleVelocity.angle

    def __init__(self, distance: float = 0.0, angle: Rotation2d | None = None) -> None:
        _set(self, distance=float(distance), angle=Rotation2d() if angle is None else angle)


# ---- kinematics, odometry, motors ----------------------------------------------------------

def _swerve(n: int) -> type:
    def __init__(self: Any, *modules: Any) -> None:
        assert len(modules) == n and all(type(m) is Translation2d for m in modules)
        _set(self, modules=modules)

    def get_modules(self: Any) -> tuple[Any, ...]:
        return self._modules

    name = f"SwerveDrive{n}Kinematics"
    return _Recorded(name, (_Value,), {"__init__": __init__, "get_modules": get_modules,
                                       "__module__": MODULE, "__qualname__": name})


class MecanumDriveKinematics(_Value):
    def __init__(self, front_left_wheel: Any, front_right_wheel: Any, rear_left_wheel: Any,
                 rear_right_wheel: Any) -> None:
        _set(self, fl=front_left_wheel, fr=front_right_wheel, rl=rear_left_wheel,
             rr=rear_right_wheel)

    def get_front_left(self) -> Any:
        return self._fl

    def get_front_right(self) -> Any:
        return self._fr

    def get_rear_left(self) -> Any:
        return self._rl

    def get_rear_right(self) -> Any:
        return self._rr


class DifferentialDriveKinematics(_Value):
    trackwidth = _ro("trackwidth")

    def __init__(self, trackwidth: float) -> None:
        _set(self, trackwidth=float(trackwidth))


class DifferentialDriveOdometry(_Value):
    """Stateful: interop refuses it (no members needed)."""


class DCMotor(_Value):
    nominal_voltage = _ro("nominal_voltage")
    stall_torque = _ro("stall_torque")
    stall_current = _ro("stall_current")
    free_current = _ro("free_current")
    free_speed = _ro("free_speed")
    r = _ro("r")
    kv = _ro("kv")
    kt = _ro("kt")

    def __init__(self, nominal_voltage: float, stall_torque: float, stall_current: float,
                 free_current: float, free_speed: float, num_motors: int = 1) -> None:
        stall_torque *= num_motors
        stall_current *= num_motors
        free_current *= num_motors
        r = nominal_voltage / stall_current
        _set(self, nominal_voltage=nominal_voltage, stall_torque=stall_torque,
             stall_current=stall_current, free_current=free_current, free_speed=free_speed,
             r=r, kv=free_speed / (nominal_voltage - r * free_current),
             kt=stall_torque / stall_current)


CLASSES: tuple[type, ...] = (
    Rotation2d, Translation2d, Pose2d, Transform2d, Twist2d,
    Quaternion, Rotation3d, Translation3d, Pose3d, Transform3d, Twist3d,
    ChassisVelocities, ChassisAccelerations, SwerveModuleVelocity, SwerveModulePosition,
    MecanumDriveWheelVelocities, MecanumDriveWheelPositions,
    DifferentialDriveWheelVelocities, DifferentialDriveWheelPositions,
    *(_swerve(n) for n in (2, 3, 4, 6)),
    MecanumDriveKinematics, DifferentialDriveKinematics, DifferentialDriveOdometry, DCMotor,
)
for _cls in CLASSES:
    _cls.__module__ = MODULE


def package() -> types.ModuleType:
    """A ``wpimath`` package laid out as robotpy 2027's: every class at the top level."""
    p = types.ModuleType("wpimath", "robotpy-wpimath 2027 stand-in (drivekin tests)")
    for cls in CLASSES:
        setattr(p, cls.__name__, cls)
    return p
