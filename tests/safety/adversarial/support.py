"""Shared pieces of the adversarial cases: how to call a registered member, how to
snapshot objects (to prove a failed call changed nothing), and the hostile helpers."""
from __future__ import annotations

import gc
import types
import math

import numpy as np

import drivekin
from tests.safety.adversarial import registry as reg
from tests.safety.adversarial.registry import ODOMETRY, ODOMETRY3D, Const, Prop

CLEAN = (TypeError, ValueError)


class Boom(Exception):
    """Raised by hostile __float__/__index__/__iter__: may propagate unchanged."""


class BadNumber:
    def __float__(self):
        raise Boom("__float__")

    def __index__(self):
        raise Boom("__index__")


class Fail(AssertionError):
    pass


def describe(e: BaseException) -> str:
    return f"{type(e).__module__}.{type(e).__qualname__}: {e}"


def expect_clean(call, extra=(), needle=None):
    """Run ``call``; it must raise TypeError/ValueError (or one of ``extra``), whose
    message names ``needle`` when given. Returns the exception."""
    try:
        result = call()
    except CLEAN + tuple(extra) as e:
        if needle and needle not in str(e):
            raise Fail(f"message does not name {needle!r}: {describe(e)}") from None
        return e
    except Exception as e:
        raise Fail(f"wrong exception {describe(e)}") from None
    raise Fail(f"accepted silently, returned {short(result)}")


def short(x, n=160):
    try:
        r = repr(x)
    except Exception as e:
        r = f"<repr raised {describe(e)}>"
    return r if len(r) <= n else r[:n] + "..."


# ---- calling -----------------------------------------------------------------------

def is_module(cls):
    """``cls`` stands for a module's functions (wpistruct, protobuf), not a class."""
    return isinstance(cls, types.ModuleType)


def receiver(cls):
    """A fresh receiver for a member of ``cls`` (None for module-level functions)."""
    return None if is_module(cls) else reg.VALID[cls]()


def bound(cls, recv, name):
    """The callable for ``name``; for __init__ of an init-once class, the constructor
    (re-init is a lifecycle case), else the method (mutables: a re-init)."""
    if is_module(cls):
        return getattr(cls, name)
    if name in reg.OPERATORS:
        op = reg.OPERATORS[name]
        return lambda *a: op(recv, *a)
    if name == "__init__" and cls in reg.INIT_ONCE:
        return cls
    return getattr(recv, name)


# ---- snapshots ---------------------------------------------------------------------

def _rot(r):
    return (r.getCos(), r.getSin())


def _swerve_probe(k):
    # Zero-velocity inverse kinematics returns the heading memory and leaves it as is.
    return tuple((s.velocity, *_rot(s.angle))
                 for s in k.toSwerveModuleVelocities(drivekin.ChassisVelocities()))


def _odometry_probe(o):
    # An update with the readings the odometry was built with is a no-op unless a
    # failed call moved its baselines.
    g = drivekin.Rotation2d(reg.GYRO0)
    if isinstance(o, drivekin.SwerveDriveOdometry):
        pose = o.update(g, [drivekin.SwerveModulePosition(0.0, drivekin.Rotation2d(0.0))
                            for _ in range(reg.N)])
    elif isinstance(o, drivekin.MecanumDriveOdometry):
        pose = o.update(g, drivekin.MecanumDriveWheelPositions(0.0, 0.0, 0.0, 0.0))
    elif isinstance(o, drivekin.DeadWheelOdometry):
        pose = o.update([0.0] * reg.DEAD_WHEELS, g)
    elif isinstance(o, drivekin.TwoDeadWheelOdometry):
        pose = o.update(0.0, 0.0, g)
    else:
        pose = o.update(g, 0.0, 0.0)
    return (o.getPose().x, o.getPose().y, *_rot(o.getPose().getRotation()), pose.x)


def _odometry3d_probe(o):
    # As _odometry_probe: the readings the 3-D odometry was built with (a level gyro).
    g = drivekin.Rotation3d()
    if isinstance(o, drivekin.SwerveDriveOdometry3d):
        pose = o.update(g, [drivekin.SwerveModulePosition(0.0, drivekin.Rotation2d(0.0))
                            for _ in range(reg.N)])
    elif isinstance(o, drivekin.MecanumDriveOdometry3d):
        pose = o.update(g, drivekin.MecanumDriveWheelPositions(0.0, 0.0, 0.0, 0.0))
    elif isinstance(o, drivekin.DeadWheelOdometry3d):
        pose = o.update([0.0] * reg.DEAD_WHEELS, g)
    elif isinstance(o, drivekin.TwoDeadWheelOdometry3d):
        pose = o.update(0.0, 0.0, g)
    else:
        pose = o.update(g, 0.0, 0.0)
    p, q = o.getPose(), o.getPose().getRotation().getQuaternion()
    return (p.getX(), p.getY(), p.getZ(), q.getW(), q.getX(), q.getY(), q.getZ(), pose.getX())


FIELDS = {
    drivekin.Translation2d: lambda v: (v.x, v.y),
    drivekin.Rotation2d: _rot,
    drivekin.Pose2d: lambda v: (v.x, v.y, *_rot(v.getRotation())),
    drivekin.Transform2d: lambda v: (v.x, v.y, *_rot(v.getRotation())),
    drivekin.Twist2d: lambda v: (v.dx, v.dy, v.dtheta),
    drivekin.ChassisVelocities: lambda v: (v.vx, v.vy, v.omega),
    drivekin.ChassisAccelerations: lambda v: (v.ax, v.ay, v.alpha),
    drivekin.SwerveModuleVelocity: lambda v: (v.velocity, *_rot(v.angle)),
    drivekin.SwerveModulePosition: lambda v: (v.distance, *_rot(v.angle)),
    drivekin.SwerveModuleAcceleration: lambda v: (v.acceleration, *_rot(v.angle)),
    drivekin.SwerveDriveKinematics: lambda k: (
        tuple((m.x, m.y) for m in k.getModules()), _swerve_probe(k)),
    drivekin.MecanumDriveKinematics: lambda k: tuple(
        (t.x, t.y) for t in (k.getFrontLeft(), k.getFrontRight(), k.getRearLeft(),
                             k.getRearRight())),
    drivekin.DifferentialDriveKinematics: lambda k: k.trackwidth,
    drivekin.DeadWheelKinematics: lambda k: (
        tuple((p.x, p.y, *_rot(p.getRotation())) for p in k.getWheelPoses()),
        k.requiresGyro()),
    **{c: _odometry_probe for c in ODOMETRY},
    **{c: _odometry3d_probe for c in ODOMETRY3D},
}


def _diffswerve(k):
    # Geometry, plus the reset offset seen through a probe at motor positions 0.
    p = k.toModulePosition(0.0, 0.0)
    return (k.azimuthGearRatio, k.wheelGearRatio, k.wheelRadius, k.motor2Inverted,
            p.distance, *_rot(p.angle))


FIELDS[drivekin.DifferentialSwerveModuleKinematics] = _diffswerve


def _quat(q):
    return (q.w, q.x, q.y, q.z)


FIELDS.update({
    drivekin.Quaternion: _quat,
    drivekin.Rotation3d: lambda r: _quat(r.getQuaternion()),
    drivekin.Translation3d: tuple,
    drivekin.Pose3d: lambda p: (p.x, p.y, p.z, *_quat(p.getRotation().getQuaternion())),
    drivekin.Transform3d: lambda p: (p.x, p.y, p.z, *_quat(p.getRotation().getQuaternion())),
    drivekin.Twist3d: lambda t: (t.dx, t.dy, t.dz, t.rx, t.ry, t.rz),
    drivekin.CoordinateAxis: repr,
    drivekin.CoordinateSystem: repr,
})
for _c in (drivekin.DifferentialSwerveMotorVelocities,
           drivekin.DifferentialSwerveModuleVelocities,
           drivekin.MecanumDriveWheelVelocities, drivekin.MecanumDriveWheelPositions,
           drivekin.MecanumDriveWheelAccelerations, drivekin.DifferentialDriveWheelVelocities,
           drivekin.DifferentialDriveWheelPositions,
           drivekin.DifferentialDriveWheelAccelerations):
    FIELDS[_c] = tuple


def snap(x, ids=True):
    """A comparable picture of ``x`` (exact floats: repr keeps -0.0 and NaN). With
    ``ids``, containers also record which objects they hold."""
    try:
        if type(x) in FIELDS:
            return (type(x).__name__, repr(FIELDS[type(x)](x)))
        if isinstance(x, np.ndarray):
            return ("ndarray", x.dtype.str, x.shape, x.tobytes())
        if isinstance(x, (bytearray, bytes, memoryview)):
            return (type(x).__name__, bytes(x) if not isinstance(x, memoryview)
                    else x.tobytes())
        if isinstance(x, (list, tuple)):
            return (type(x).__name__, tuple((id(i) if ids else None, snap(i, ids)) for i in x))
        if isinstance(x, dict):
            return tuple((k, snap(v, ids)) for k, v in x.items())
        if isinstance(x, float):
            return repr(x)
        if x is None or isinstance(x, (int, str, type)):
            return repr(x)
        return ("object", type(x).__name__, id(x) if ids else None)
    except Exception as e:  # an uninitialised object may refuse to be read
        return ("unreadable", type(e).__name__)


def outcome(call):
    """('ok', result) or ('raised', exception)."""
    try:
        return ("ok", call())
    except Exception as e:
        return ("raised", e)


def finite(x) -> bool:
    s = snap(x, ids=False)
    return "nan" not in repr(s) and "inf" not in repr(s)


class armed_gc:
    """Run the body with gen-0 collections on every allocation of a tracked object,
    and a chain of garbage cycles whose finalizer runs ``action`` at the ``fuse``-th
    collection. ``fired`` says whether it ran during the body."""

    def __init__(self, action, fuse):
        self.action, self.fuse, self.fired, self.armed = action, fuse, False, True

    def _bomb(self, fuse):
        outer = self

        class Bomb:
            def __init__(self):
                self.cycle = self

            def __del__(self):
                if not outer.armed:
                    return
                if fuse <= 1:
                    outer.fired = True
                    outer.action()
                else:
                    outer._bomb(fuse - 1)
        Bomb()

    def __enter__(self):
        gc.collect()  # an empty young generation: the fuse counts only the call's collections
        self.saved = gc.get_threshold()
        gc.disable()
        self._bomb(self.fuse)
        gc.set_threshold(1)
        gc.enable()
        return self

    def __exit__(self, *exc):
        gc.set_threshold(*self.saved)
        self.armed = False
        gc.collect()


def math_ok(x):
    return isinstance(x, float) and math.isfinite(x)


def member_specs(classes=None):
    """(cls, name, spec) for every registered member; for the module-level functions
    (reg.MODULE_FUNCTIONS) cls is the module."""
    for cls in classes or reg.public_classes():
        for name, spec in reg.members(cls):
            yield cls, name, spec
    if classes is None:
        for module, functions in reg.MODULE_FUNCTIONS.items():
            for name, sig in functions.items():
                yield module, name, sig if isinstance(sig, list) else [sig]


def label(cls, name, si=None):
    base = f"{cls.__name__.rpartition('.')[2]}.{name}"
    return base if si is None else f"{base}#{si}"


__all__ = ["Const", "Prop"]
