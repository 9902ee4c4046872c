"""The registry of drivekin's public callables, for the adversarial suite.

Every public class in ``drivekin.__all__`` has an entry in :data:`API`: for each public
method, property, constant and protocol dunder, one or more :class:`Sig` that say what
each positional argument is (a value object, a sequence of them, a float, a numpy
buffer, an ``out`` target). From a ``Sig`` the suite builds a valid call
(:meth:`Sig.build`) and then breaks one argument at a time (``cases.py``).

The classes come from the catalog (``drivekin._core.catalog``; ``tests/api/test_catalog.py``
checks that it holds every public class): ``test_registry.py`` enumerates its entries,
introspects each class's members and fails, naming the member, when something is missing
here — so a new class or method joins the suite by construction. Each class's valid
instance (:data:`VALID`) is its catalog ``example``, except the few listed in
:data:`SPECIAL` with the state the suite needs; :data:`KINEMATICS`, :data:`ODOMETRY`,
:data:`ESTIMATORS` (their 3-D counterparts too) and :data:`INIT_ONCE` follow from the
entries' kinds. To add a class:
its catalog entry (with an ``example``), a second instance in :data:`ALT` if it is a value,
whether it is immutable (:data:`IMMUTABLE`), and a ``Sig`` for every member.
"""
from __future__ import annotations

import operator
import threading

import numpy as np

import drivekin
import drivekin.batch as batch
import drivekin.protobuf as protobuf
import drivekin.wpistruct as wpistruct
from drivekin._core import catalog
from drivekin import (
    ChassisAccelerations as CA,
    ChassisVelocities as CV,
    DeadWheelKinematics,
    DeadWheelOdometry,
    DeadWheelPoseEstimator,
    DifferentialDrivePoseEstimator,
    MathSharedStore,
    MecanumDrivePoseEstimator,
    SwerveDrivePoseEstimator,
    TwoDeadWheelPoseEstimator,
    DifferentialDriveKinematics,
    DifferentialDriveOdometry,
    DifferentialDriveOdometry3d,
    DifferentialDriveWheelAccelerations as DWA,
    DifferentialDriveWheelPositions as DWP,
    DifferentialDriveWheelVelocities as DWV,
    DifferentialSwerveModuleKinematics as DSK,
    DifferentialSwerveModuleVelocities as DSModV,
    DifferentialSwerveMotorVelocities as DSMV,
    MecanumDriveKinematics,
    MecanumDriveOdometry,
    MecanumDriveWheelAccelerations as MWA,
    MecanumDriveWheelPositions as MWP,
    MecanumDriveWheelVelocities as MWV,
    Pose2d,
    Rotation2d as R,
    SwerveDriveKinematics,
    SwerveDriveOdometry,
    SwerveModuleAcceleration as SMA,
    SwerveModulePosition as SMP,
    SwerveModuleVelocity as SMV,
    TimeInterpolatableBuffer as TIB,
    Transform2d,
    Translation2d as T,
    Twist2d,
    TwoDeadWheelOdometry,
    Units,
)
from drivekin import (DCMotor, DriveFeedforwards, ModuleConfig, PathConstraints, RobotConfig,
                      SwerveSetpoint, SwerveSetpointGenerator)
from drivekin import (CoordinateAxis, CoordinateSystem, Pose3d, Quaternion, Rotation3d as R3,
                      Transform3d, Translation3d as T3, Twist3d)
from drivekin import (
    DeadWheelOdometry3d,
    DeadWheelPoseEstimator3d,
    DifferentialDriveOdometry3d,
    DifferentialDrivePoseEstimator3d,
    MecanumDriveOdometry3d,
    MecanumDrivePoseEstimator3d,
    SwerveDriveOdometry3d,
    SwerveDrivePoseEstimator3d,
    TwoDeadWheelOdometry3d,
    TwoDeadWheelPoseEstimator3d,
)

N = 4  # modules of the registry's swerve drive

# Odometry receivers start from these, so a probe update with them must be a no-op.
GYRO0 = 0.0


def example(cls):
    """A fresh instance of ``cls``: its catalog entry's ``example``."""
    return catalog.BY_CLASS[cls].example()


def _swerve() -> SwerveDriveKinematics:
    k = SwerveDriveKinematics(T(0.3, 0.3), T(0.3, -0.3), T(-0.3, 0.3), T(-0.3, -0.25))
    # Distinct remembered headings, so a call that wrongly touches them is visible.
    k.resetHeadings([R(1.0), R(2.0), R(-1.0), R(3.0)])
    return k


def _diffswerve() -> DSK:
    # Small ratios so that the registry's small limits give drive-level factors in (0, 1);
    # a reset offset, so that a call that wrongly touches it is visible.
    k = DSK(0.5, 0.25, 2.0)
    k.resetModulePosition(R(0.5), 1.0, -2.0)
    return k


def _dead_wheels() -> DeadWheelKinematics:
    # The catalog's three wheels: asymmetric, observable without a gyro.
    return example(DeadWheelKinematics)


DEAD_WHEELS = 3

# A fresh, valid, non-trivial instance of each class: the catalog's example. The odometry
# and estimator examples start at gyro GYRO0 with zero readings, as the probe needs.
VALID = {e.cls: e.example for e in catalog.ENTRIES
         if e.example is not None and e.kind != "warning"}
# The classes whose instance here is not the catalog's example, and why (the factories
# are set below: the estimators' in "pose estimators", Units' in "Units").
SPECIAL = {
    SwerveDriveKinematics: "remembered headings (and an asymmetric layout), so that a call "
                           "that wrongly touches the heading memory is visible",
    DSK: "small ratios for drive-level factors in (0, 1), and a reset offset",
    **{e.cls: "one odometry sample at t = 0, so sampleAt and vision measurements have "
              "history" for kind in ("estimator", "estimator3d")
       for e in catalog.entries(kind)},
    Units: "no instances: the receiver of its static methods is the class itself",
    SwerveSetpointGenerator: "compatibility='pathplanner', whose compatibility property "
                             "reads a value (the default mode's is None, which reads as a "
                             "failed property here)",
}
VALID[SwerveDriveKinematics] = _swerve
VALID[DSK] = _diffswerve
VALID[SwerveSetpointGenerator] = lambda: SwerveSetpointGenerator(
    example(RobotConfig), 10.0, compatibility="pathplanner")

ALT = {  # a second valid instance, different from VALID's
    T: lambda: T(-2.0, 0.5),
    R: lambda: R(-2.0),
    Pose2d: lambda: Pose2d(-1.0, 0.5, R(2.5)),
    Transform2d: lambda: Transform2d(2.0, 1.0, R(-1.0)),
    Twist2d: lambda: Twist2d(-1.0, 2.0, -0.5),
    CV: lambda: CV(-3.0, 2.0, 1.0),
    CA: lambda: CA(-3.0, 2.0, 1.0),
    SMV: lambda: SMV(-2.0, R(-1.5)),
    SMP: lambda: SMP(3.0, R(2.0)),
    SMA: lambda: SMA(-2.0, R(-1.5)),
    MWV: lambda: MWV(-1.0, 0.5, 2.5, -4.0),
    MWP: lambda: MWP(-1.0, 0.5, 2.5, -4.0),
    MWA: lambda: MWA(-1.0, 0.5, 2.5, -4.0),
    DWV: lambda: DWV(-1.0, 3.0),
    DWP: lambda: DWP(-1.0, 3.0),
    DWA: lambda: DWA(-1.0, 3.0),
    DSMV: lambda: DSMV(-3.0, 0.5),
    DSModV: lambda: DSModV(-2.0, 1.0),
    DCMotor: lambda: DCMotor.getKrakenX60(1),
    ModuleConfig: lambda: ModuleConfig(0.05, 4.0, 1.0, DCMotor.getNEO(1), 40.0, 2),
    RobotConfig: lambda: RobotConfig(45.0, 4.0, example(ModuleConfig),
                                     [T(0.2, 0.3), T(0.2, -0.3), T(-0.2, 0.3), T(-0.2, -0.3)]),
    PathConstraints: lambda: PathConstraints(1.0, 2.0, 3.0, 4.0, 11.0),
    DriveFeedforwards: lambda: DriveFeedforwards(*([-0.25 * i - k for i in range(N)]
                                                   for k in range(5))),
    SwerveSetpoint: lambda: SwerveSetpoint(CV(-1.0, 0.5, -0.5),
                                           [SMV(-1.0, R(0.3 * i)) for i in range(N)],
                                           DriveFeedforwards.zeros(N)),
    Quaternion: lambda: Quaternion(-0.25, 1.5, 0.5, -2.0),
    R3: lambda: R3(-1.0, 0.5, 2.5),
    T3: lambda: T3(-2.0, 0.5, 3.0),
    Pose3d: lambda: Pose3d(-1.0, 0.5, 2.0, R3(2.5, -0.25, 1.0)),
    Transform3d: lambda: Transform3d(2.0, 1.0, -0.5, R3(-1.0, 0.75, 0.25)),
    Twist3d: lambda: Twist3d(-1.0, 2.0, -0.5, 0.25, -0.75, 1.5),
    CoordinateAxis: lambda: CoordinateAxis(-0.5, 1.0, 2.0),
    CoordinateSystem: lambda: CoordinateSystem(CoordinateAxis.N(), CoordinateAxis.E(),
                                               CoordinateAxis.D()),
}
_ALT = threading.local()  # per thread: the thread cases build both kinds at once


def _alt():
    return getattr(_ALT, "on", False)


class _alternate:
    def __init__(self, on):
        self.on = on

    def __enter__(self):
        self.saved, _ALT.on = _alt(), self.on

    def __exit__(self, *exc):
        _ALT.on = self.saved


def make(cls):
    """A fresh valid instance (the alternate one inside ``build(alt=True)``)."""
    return (ALT if _alt() and cls in ALT else VALID)[cls]()


# Objects whose __init__ must refuse to run twice (and every object whose __init__ did
# not run must refuse to compute): immutable values, kinematics, odometry, estimators and
# the interpolation buffer. Immutability is a property of the class that the catalog does
# not record, so IMMUTABLE is listed here; the rest follows from the catalog's kinds.
IMMUTABLE = {T, R, Pose2d, Transform2d, Quaternion, R3, T3, Pose3d, Transform3d}
KINEMATICS = {e.cls for e in catalog.entries("kinematics")}
ODOMETRY = {e.cls for e in catalog.entries("odometry")}
ESTIMATORS = {e.cls for e in catalog.entries("estimator")}
ODOMETRY3D = {e.cls for e in catalog.entries("odometry3d")}
ESTIMATORS3D = {e.cls for e in catalog.entries("estimator3d")}
# DCMotor is immutable too, but has no default value for __new__ to match: a __new__'d
# one refuses to compute, as the kinematics do.
INIT_ONCE = (IMMUTABLE | KINEMATICS | ODOMETRY | ESTIMATORS | ODOMETRY3D | ESTIMATORS3D
             | {TIB, DCMotor})
# The coordinate axes and systems are immutable without a default value, as DCMotor.
INIT_ONCE |= {CoordinateAxis, CoordinateSystem}
# The setpoint generator's values are immutable and refuse a second __init__ the same way.
INIT_ONCE |= {ModuleConfig, RobotConfig, PathConstraints, DriveFeedforwards, SwerveSetpoint,
              SwerveSetpointGenerator}
# No value semantics: not copyable, no str of values.
STATEFUL = ODOMETRY | ESTIMATORS | ODOMETRY3D | ESTIMATORS3D | {TIB}
NAMESPACES = {MathSharedStore, Units}      # static methods only; the clock is not deterministic


# ---- argument kinds ---------------------------------------------------------------

class Kind:
    """What one argument position takes. ``valid()`` makes a fresh good value."""

    out = False  # the call writes into this argument


class Obj(Kind):
    """A value object of ``cls``. ``none_ok``/``float_ok``: an overload or default
    accepts None / a float at this position, so those are not hostile here."""

    def __init__(self, cls, none_ok=False, float_ok=False):
        self.cls, self.none_ok, self.float_ok = cls, none_ok, float_ok

    def valid(self):
        return make(self.cls)


class Out(Obj):
    out = True


class StructObj(Obj):
    """Any wpistruct value (so another drivekin value class is not hostile)."""


class Seq(Kind):
    """A list of ``n`` value objects of ``cls`` (``n=None``: any length of at least
    ``least``)."""

    def __init__(self, cls, n=N, least=0):
        self.cls, self.n, self.least = cls, n, least

    def valid(self):
        return [make(self.cls) for _ in range(self.n or N)]


class WheelPoses(Seq):
    """The registry's dead-wheel layout as a list of Pose2d (a list of equal poses would
    be an unobservable layout, not a valid one)."""

    def __init__(self):
        super().__init__(Pose2d, n=None, least=2)

    def valid(self):
        poses = list(_dead_wheels().getWheelPoses())
        return poses[::-1] if _alt() else poses


class OutSeq(Seq):
    out = True


class NumSeq(Seq):
    """A list of ``n`` floats (hostile items: None, objects, another value class)."""

    def __init__(self, n=N):
        super().__init__(float, n)

    def valid(self):
        v = [0.1, -0.2, 0.3, 0.05][:self.n] + [0.0] * max(0, self.n - 4)
        return [-1.5 * x + 0.25 for x in v] if _alt() else v


class Num(Kind):
    """A float (``value`` is the valid one). ``none_ok``: None is accepted here."""

    def __init__(self, value=0.5, none_ok=False):
        self.value, self.none_ok = value, none_ok

    def valid(self):
        return -1.5 * self.value + 0.25 if _alt() else self.value


class Floats(Kind):
    """A list of ``n`` plain floats (one value per dead wheel). Only lists, tuples and
    float64 arrays are accepted there, never other iterables."""

    def __init__(self, n, none_ok=False, float_ok=False):
        # float_ok: an overload takes a float at this position (Rotation3d(axis, angle)
        # beside Rotation3d(initial, final)), so a float is not hostile here.
        self.n, self.none_ok, self.float_ok = n, none_ok, float_ok

    def valid(self):
        v = [0.25 * (i + 1) for i in range(self.n)]
        return [-x for x in v] if _alt() else v


class Axis(Obj):
    """A CoordinateAxis with the given direction (the three of a CoordinateSystem must
    be perpendicular, so the catalog's example cannot stand for each)."""

    def __init__(self, direction, alt):
        super().__init__(CoordinateAxis)
        self.direction, self.alt = direction, alt

    def valid(self):
        return CoordinateAxis(*(self.alt if _alt() else self.direction))


class Int(Kind):
    def __init__(self, value):
        self.value = value

    def valid(self):
        return self.value


class Arr(Kind):
    """A float64 C-contiguous numpy array of ``shape`` (``fill`` gives its values;
    ``rows_free``: any number of rows is valid; ``list_ok``: a list of numbers is also
    valid here, so the array's ``tolist()`` is not hostile)."""

    def __init__(self, shape, fill=None, rows_free=False, list_ok=False):
        self.shape, self.fill, self.rows_free = shape, fill, rows_free
        self.list_ok = list_ok   # a plain list of the values is accepted here too

    def valid(self):
        if self.fill is not None:
            return np.array(self.fill, dtype=np.float64).reshape(self.shape)
        a = np.arange(1.0, 1.0 + np.prod(self.shape)).reshape(self.shape) / 4.0
        return -a if _alt() else a


class OutArr(Arr):
    out = True

    def valid(self):
        return np.full(self.shape, 7.0)


class RawArr(Arr):
    """A numpy array used as raw bytes (wpistruct): any dtype's bytes are bytes, but
    never an object array's pointers."""


class OutRawArr(RawArr):
    out = True

    def valid(self):
        return np.full(self.shape, 7.0)


class Bytes(Kind):
    """A bytes-like input (wpistruct)."""

    def __init__(self, make):
        self.make = make

    def valid(self):
        return self.make()


class OutBytes(Bytes):
    out = True


class Type(Kind):
    """A class argument (wpistruct): hostile values are other classes/objects."""

    def __init__(self, cls):
        self.cls = cls

    def valid(self):
        return self.cls


class State(Kind):
    """A ``__setstate__`` payload (``make`` builds a valid one); hostile values are
    wrong shapes and wrong item types."""

    def __init__(self, make):
        self.make = make

    def valid(self):
        return self.make()


class Callback(Kind):
    def valid(self):
        return lambda name, schema: None


class Sig:
    """One way to call a member: the kinds of its positional arguments, plus optional
    keywords (name -> factory). ``build(alt=True)`` gives a second, different valid call
    (for re-entrancy and thread cases, where two calls must not share results)."""

    def __init__(self, *kinds, kw=None):
        self.kinds, self.kw = kinds, kw or {}

    def build(self, alt=False):
        with _alternate(alt):
            return [k.valid() for k in self.kinds], {k: v() for k, v in self.kw.items()}


class Prop:
    """A property: ``kind`` is None for read-only, else what the setter takes."""

    def __init__(self, kind=None):
        self.kind = kind


class Const:
    """A class constant (``kZero``); ``value`` is what it must equal."""

    def __init__(self, value):
        self.value = value


S = Sig
NUM = Num()
# Protocol dunders are exercised through the operator, not the bound method.
OPERATORS = {
    "__add__": operator.add, "__sub__": operator.sub, "__mul__": operator.mul,
    "__rmul__": lambda a, b: b * a, "__truediv__": operator.truediv,
    "__neg__": operator.neg, "__eq__": operator.eq, "__iter__": lambda a: list(iter(a)),
}
# Operators a class defines only to refuse, whatever the operands (a TypeError naming the
# 2027 replacement, before any argument is read): Rotation3d's + - and unary −, which
# WPILib 2027 removed (tests/behaviour/test_geometry3d.py pins the messages). Not attacked.
REFUSED_OPERATORS = {R3: ("__add__", "__sub__", "__neg__")}
# The dunders the completeness check looks for (beyond plain public names).
DUNDERS = ("__init__", "__reduce__", "__reduce_ex__", "__setstate__", "__copy__",
           "__deepcopy__", "__call__", "__len__", "__getitem__", "__setitem__",
           *OPERATORS)


def _arith(cls, add=True, neg=True, eq=True, iterable=False):
    """The operator/algebra members shared by the vector-like values."""
    d = {"plus": S(Obj(cls)), "minus": S(Obj(cls)), "times": S(NUM), "div": S(NUM),
         "__mul__": S(NUM), "__rmul__": S(NUM), "__truediv__": S(NUM)}
    if add:
        d.update(__add__=S(Obj(cls)), __sub__=S(Obj(cls)))
    if neg:
        d.update(unaryMinus=S(), __neg__=S())
    if eq:
        d["__eq__"] = S(Obj(cls))
    if iterable:
        d["__iter__"] = S()
    return d


def _chassis(cls, fields):
    d = _arith(cls)
    d.update({f: Prop(NUM) for f in fields})
    d.update(
        __init__=S(NUM, NUM, NUM),
        __reduce__=S(),
        toRobotRelative=S(Obj(R)), toFieldRelative=S(Obj(R)),
        toRobotRelativeInto=S(Obj(R), Out(cls)), toFieldRelativeInto=S(Obj(R), Out(cls)),
        interpolate=S(Obj(cls), NUM),
    )
    return d


def _module(cls, field):
    return {
        # A float angle is robotpy's implicit Rotation2d(radians) (porting issue, item 2).
        "__init__": S(NUM, Obj(R, none_ok=True, float_ok=True)), "__reduce__": S(),
        "__eq__": S(Obj(cls)),
        "__iter__": S(), field: Prop(NUM), "angle": Prop(Obj(R)),
        "interpolate": S(Obj(cls), NUM), "compareTo": S(Obj(cls)),
    }


def _wheels(cls, names, desat=False, copy=False, eq=False):
    d = _arith(cls, eq=eq, iterable=True)
    d.update({f: Prop(NUM) for f in names})
    d.update(__init__=S(*[NUM] * len(names)), __reduce__=S(),
             interpolate=S(Obj(cls), NUM))
    if desat:
        d.update(desaturate=S(NUM), desaturateInPlace=S(NUM))
    if copy:
        d["copy"] = S()
    return d


def _odometry(kin, positions, gyro=Obj(R)):
    """Odometry members; ``positions`` are the kinds after the gyro angle."""
    return {
        "__init__": S(*((Obj(kin),) if kin else ()), gyro, *positions,
                      Obj(Pose2d, none_ok=True)),
        "resetPosition": S(gyro, *positions, Obj(Pose2d)),
        "update": S(gyro, *positions),
        "getPose": S(), "resetPose": S(Obj(Pose2d)),
        "resetTranslation": S(Obj(T)), "resetRotation": S(Obj(R)),
    }


_FRAME = {"x": Prop(), "y": Prop(), "getX": S(), "getY": S(), "getTranslation": S(),
          "getRotation": S(), "times": S(NUM), "div": S(NUM), "toMatrix": S(),
          "__reduce__": S(), "__eq__": S(Obj(Pose2d)), "__mul__": S(NUM),
          "__rmul__": S(NUM), "__truediv__": S(NUM)}
_MOD_ARR = Arr((N, 2))

API = {
    T: {
        **_arith(T, iterable=True),
        "__init__": [S(NUM, NUM), S(NUM, Obj(R, float_ok=True)), S(Arr((2,))),
                     S(kw={"x": lambda: 1.0, "y": lambda: 2.0})],
        "__reduce__": S(), "kZero": Const(T(0.0, 0.0)),
        "x": Prop(), "y": Prop(), "getX": S(), "getY": S(), "getNorm": S(),
        "getSquaredNorm": S(), "getDistance": S(Obj(T)), "getSquaredDistance": S(Obj(T)),
        "getAngle": S(), "rotateBy": S(Obj(R)), "rotateAround": S(Obj(T), Obj(R)),
        "dot": S(Obj(T)), "cross": S(Obj(T)), "nearest": S(Seq(T, n=None, least=1)),
        "interpolate": S(Obj(T), NUM), "toVector": S(),
        "fromFeet": [S(NUM, NUM), S(NUM, Obj(R, float_ok=True))],
    },
    R: {
        **_arith(R),
        "__init__": [S(NUM), S(NUM, NUM), S(Arr((2, 2), fill=[[0.0, -1.0], [1.0, 0.0]])),
                     S(kw={"value": lambda: 1.0})],
        "__reduce__": S(),
        **{k: Const(R(v)) for k, v in [("kZero", 0.0), ("kCW_Pi_2", -np.pi / 2),
                                       ("kCW_90deg", -np.pi / 2), ("kCCW_Pi_2", np.pi / 2),
                                       ("kCCW_90deg", np.pi / 2), ("kPi", np.pi),
                                       ("k180deg", np.pi)]},
        "fromRadians": S(NUM), "fromDegrees": S(NUM), "fromRotations": S(NUM),
        "getRadians": S(), "getDegrees": S(), "getRotations": S(), "getCos": S(),
        "getSin": S(), "getTan": S(), "rotateBy": S(Obj(R)), "relativeTo": S(Obj(R)),
        "interpolate": S(Obj(R), NUM), "toMatrix": S(),
    },
    Pose2d: {
        **_FRAME,
        "__init__": [S(), S(Obj(T), Obj(R, float_ok=True)), S(NUM, NUM, Obj(R, float_ok=True)),
                     S(Arr((3, 3), fill=[[1.0, 0.0, 1.0], [0.0, 1.0, 2.0], [0.0, 0.0, 1.0]])),
                     S(kw={"translation": VALID[T], "rotation": VALID[R]}),
                     S(kw={"x": lambda: 1.0, "y": lambda: 2.0, "rotation": VALID[R]})],
        "kZero": Const(Pose2d()),
        "transformBy": S(Obj(Transform2d)), "plus": S(Obj(Transform2d)),
        "__add__": S(Obj(Transform2d)), "minus": S(Obj(Pose2d)), "__sub__": S(Obj(Pose2d)),
        "relativeTo": S(Obj(Pose2d)), "rotateBy": S(Obj(R)),
        "rotateAround": S(Obj(T), Obj(R)), "exp": S(Obj(Twist2d)), "log": S(Obj(Pose2d)),
        "nearest": S(Seq(Pose2d, n=None, least=1)), "interpolate": S(Obj(Pose2d), NUM),
        "fromFeet": [S(NUM, NUM, Obj(R, float_ok=True)), S(NUM, NUM, NUM)],
    },
    Transform2d: {
        **_FRAME,
        "__eq__": S(Obj(Transform2d)),
        "__init__": [S(), S(Obj(T), Obj(R, float_ok=True)), S(NUM, NUM, Obj(R, float_ok=True)),
                     S(Arr((3, 3), fill=[[1.0, 0.0, 1.0], [0.0, 1.0, 2.0], [0.0, 0.0, 1.0]])),
                     S(Obj(Pose2d), Obj(Pose2d)),
                     S(kw={"translation": VALID[T], "rotation": VALID[R]})],
        "kZero": Const(Transform2d()),
        "inverse": S(), "plus": S(Obj(Transform2d)), "__add__": S(Obj(Transform2d)),
        "log": S(),
        "fromFeet": [S(NUM, NUM, Obj(R, float_ok=True)), S(NUM, NUM, NUM)],
    },
    Twist2d: {
        "__init__": S(NUM, NUM, NUM), "__reduce__": S(), "__eq__": S(Obj(Twist2d)),
        "dx": Prop(NUM), "dy": Prop(NUM), "dtheta": Prop(NUM), "exp": S(),
        "fromFeet": [S(), S(NUM, NUM, NUM)], "__mul__": S(NUM),
        "__rmul__": S(NUM),
    },
    CV: {**_chassis(CV, ("vx", "vy", "omega")), "fromFeet": [S(), S(NUM, NUM, NUM)],
         "toTwist2d": S(NUM), "discretize": S(NUM), "discretizeInto": S(NUM, Out(CV))},
    CA: _chassis(CA, ("ax", "ay", "alpha")),
    SMV: {**_module(SMV, "velocity"),
          "optimize": S(Obj(R)), "optimizeInPlace": S(Obj(R)),
          "cosineScale": S(Obj(R)), "cosineScaleInPlace": S(Obj(R))},
    SMP: {**_module(SMP, "distance"), "copy": S()},
    # WPILib C++'s operators (robotpy's): vector sum and difference, scaling, negation.
    SMA: {**_module(SMA, "acceleration"), "__add__": S(Obj(SMA)), "__sub__": S(Obj(SMA)),
          "__mul__": S(NUM), "__rmul__": S(NUM), "__truediv__": S(NUM), "__neg__": S()},
    MWV: {**_wheels(MWV, ("frontLeft", "frontRight", "rearLeft", "rearRight"), desat=True),
          "fromFeet": S(NUM, NUM, NUM, NUM)},
    MWP: _wheels(MWP, ("frontLeft", "frontRight", "rearLeft", "rearRight"), copy=True,
                 eq=True),
    MWA: _wheels(MWA, ("frontLeft", "frontRight", "rearLeft", "rearRight"), eq=True),
    DWV: {**_wheels(DWV, ("left", "right"), desat=True), "fromFeet": S(NUM, NUM)},
    DWP: _wheels(DWP, ("left", "right"), copy=True, eq=True),
    DWA: _wheels(DWA, ("left", "right"), eq=True),
    SwerveDriveKinematics: {
        "__init__": [S(Seq(T, n=None, least=2)), S(*[Obj(T)] * N)], "__reduce__": S(),
        "__setstate__": S(State(lambda: tuple(R(0.1 * i) for i in range(N)))),
        "getModules": S(), "getNumModules": S(),
        "resetHeadings": [S(Seq(R)), S(*[Obj(R)] * N)],
        "toSwerveModuleVelocities": [S(Obj(CV)), S(Obj(CV), Obj(T))],
        "toWheelVelocities": S(Obj(CV)),
        "toSwerveModuleVelocitiesInto": [S(Obj(CV), OutSeq(SMV)), S(Obj(CV), OutArr((N, 2))),
                                         S(Obj(CV), OutSeq(SMV), Obj(T))],
        "toChassisVelocities": [S(Seq(SMV)), S(_MOD_ARR)],
        "toChassisVelocitiesInto": [S(Seq(SMV), Out(CV)), S(_MOD_ARR, Out(CV))],
        "toTwist2d": [S(Seq(SMP)), S(Seq(SMP), Seq(SMP)), S(_MOD_ARR)],
        "toTwist2dInto": [S(Seq(SMP), Out(Twist2d)), S(_MOD_ARR, Out(Twist2d))],
        "interpolate": S(Seq(SMP), Seq(SMP), NUM),
        "copy": S(Seq(SMP, n=None)), "copyInto": S(Seq(SMP), OutSeq(SMP)),
        "toSwerveModuleAccelerations": [S(Obj(CA)), S(Obj(CA), NUM, Obj(T))],
        "toWheelAccelerations": S(Obj(CA)),
        "toChassisAccelerations": [S(Seq(SMA)), S(_MOD_ARR)],
        # The limit stays valid (>= 0) in the alternate build: 0.125 -> 0.0625.
        "desaturatedDiscretize": S(Obj(CV), Num(0.02), Num(0.125)),
        "desaturatedDiscretizeInto": S(Obj(CV), Num(0.02), Num(0.125), Out(CV)),
        # Static: any number of modules.
        "desaturateWheelVelocities": [
            S(Seq(SMV, n=None), NUM),
            S(Seq(SMV, n=None), Obj(CV), Num(2.0), Num(1.0), Num(1.0))],
        "desaturateWheelVelocitiesInPlace": [
            S(OutSeq(SMV, n=None), NUM), S(OutArr((N, 2), rows_free=True), NUM),
            S(OutSeq(SMV, n=None), Obj(CV), Num(2.0), Num(1.0), Num(1.0))],
    },
    MecanumDriveKinematics: {
        "__init__": S(*[Obj(T)] * 4), "__reduce__": S(),
        "getFrontLeft": S(), "getFrontRight": S(), "getRearLeft": S(), "getRearRight": S(),
        "toWheelVelocities": [S(Obj(CV)), S(Obj(CV), Obj(T))],
        "toWheelVelocitiesInto": [S(Obj(CV), Out(MWV)), S(Obj(CV), Out(MWV), Obj(T))],
        "toChassisVelocities": S(Obj(MWV)), "toChassisVelocitiesInto": S(Obj(MWV), Out(CV)),
        "toTwist2d": [S(Obj(MWP)), S(Obj(MWP), Obj(MWP, none_ok=True))],
        "toWheelAccelerations": [S(Obj(CA)), S(Obj(CA), Obj(T))],
        "toChassisAccelerations": S(Obj(MWA)),
        "interpolate": S(Obj(MWP), Obj(MWP), NUM),
        "copy": S(Obj(MWP)), "copyInto": S(Obj(MWP), Out(MWP)),
    },
    DifferentialDriveKinematics: {
        "__init__": S(NUM), "__reduce__": S(), "trackwidth": Prop(),
        "toChassisVelocities": S(Obj(DWV)), "toChassisVelocitiesInto": S(Obj(DWV), Out(CV)),
        "toWheelVelocities": S(Obj(CV)), "toWheelVelocitiesInto": S(Obj(CV), Out(DWV)),
        "toTwist2d": [S(NUM, NUM), S(Obj(DWP), Obj(DWP))],
        "toChassisAccelerations": S(Obj(DWA)), "toWheelAccelerations": S(Obj(CA)),
        "interpolate": S(Obj(DWP), Obj(DWP), NUM),
        "copy": S(Obj(DWP)), "copyInto": S(Obj(DWP), Out(DWP)),
    },
    SwerveDriveOdometry: _odometry(SwerveDriveKinematics, (Seq(SMP),)),
    MecanumDriveOdometry: _odometry(MecanumDriveKinematics, (Obj(MWP),)),
    DifferentialDriveOdometry: _odometry(None, (NUM, NUM)),
}
# robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras): unit
# variants in feet and degrees, every one assignable but the positions' (x_feet, y_feet).
# (from_feet is fromFeet under the names rule: attacked under its Java-side name.)
_HOMOGENEOUS = Arr((3, 3), fill=[[0.0, -1.0, 1.0], [1.0, 0.0, 2.0], [0.0, 0.0, 1.0]])
_FRAME_FT = {"from_matrix": S(_HOMOGENEOUS), "x_feet": Prop(), "y_feet": Prop()}
for _cls, _extras in {
    T: {"x_feet": Prop(), "y_feet": Prop(), "distance_feet": S(Obj(T)), "norm_feet": S()},
    R: {"from_matrix": S(Arr((2, 2), fill=[[0.0, -1.0], [1.0, 0.0]]))},
    Pose2d: _FRAME_FT,
    Transform2d: _FRAME_FT,
    Twist2d: {"dx_feet": Prop(NUM),
              "dy_feet": Prop(NUM), "dtheta_degrees": Prop(NUM)},
    CV: {"vx_fps": Prop(NUM), "vy_fps": Prop(NUM),
         "omega_dps": Prop(NUM)},
    CA: {"from_fps": [S(), S(NUM, NUM, NUM)], "ax_fpss": Prop(NUM), "ay_fpss": Prop(NUM),
         "alpha_dpss": Prop(NUM)},
    SMV: {"velocity_fps": Prop(NUM)},
    SMP: {"distance_ft": Prop(NUM)},
    SMA: {"from_fps": [S(), S(NUM, Obj(R, none_ok=True, float_ok=True))],
          "acceleration_fpss": Prop(NUM)},
    MWV: {**{f"{w}_fps": Prop(NUM) for w in ("front_left", "front_right", "rear_left",
                                              "rear_right")}},
    MWA: {"from_fps": [S(), S(NUM, NUM, NUM, NUM)],
          **{f"{w}_fpss": Prop(NUM) for w in ("front_left", "front_right", "rear_left",
                                               "rear_right")}},
    DWV: {"left_fps": Prop(NUM), "right_fps": Prop(NUM)},
    DWA: {"from_fps": S(NUM, NUM), "left_fpss": Prop(NUM), "right_fpss": Prop(NUM)},
}.items():
    API[_cls].update(_extras)
# 3-D geometry (drivekin.geometry3d). A vector is 3 floats (list, tuple or float64 array).
_V3 = Floats(3)
_ROTATION_MATRIX = Arr((3, 3), fill=[[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
_AFFINE = Arr((4, 4), fill=[[0.0, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 2.0],
                            [0.0, 0.0, 1.0, 3.0], [0.0, 0.0, 0.0, 1.0]])
_Q = Quaternion
_FRAME3D = {"x": Prop(), "y": Prop(), "z": Prop(), "getX": S(), "getY": S(), "getZ": S(),
            "getTranslation": S(), "getRotation": S(), "times": S(NUM), "div": S(NUM),
            "toMatrix": S(), "__reduce__": S(), "__mul__": S(NUM), "__rmul__": S(NUM),
            "__truediv__": S(NUM)}
_FRAME3D_INIT = [S(), S(Obj(T3), Obj(R3)), S(NUM, NUM, NUM, Obj(R3)), S(_AFFINE),
                 S(kw={"translation": VALID[T3], "rotation": VALID[R3]}),
                 S(kw={"x": lambda: 1.0, "y": lambda: 2.0, "z": lambda: 3.0,
                       "rotation": VALID[R3]})]
_SYSTEM = [Obj(CoordinateSystem), Obj(CoordinateSystem)]
API.update({
    _Q: {
        "__init__": [S(), S(NUM, NUM, NUM, NUM),
                     S(kw={"w": lambda: 0.5, "x": lambda: 0.5, "y": lambda: -0.5,
                           "z": lambda: 0.5})],
        "__reduce__": S(), "__eq__": S(Obj(_Q)),
        **{f: Prop() for f in ("w", "x", "y", "z")},
        **{f: S() for f in ("getW", "getX", "getY", "getZ", "conjugate", "inverse", "norm",
                            "normalize", "exp", "log", "toRotationVector")},
        "plus": S(Obj(_Q)), "minus": S(Obj(_Q)), "dot": S(Obj(_Q)),
        "times": [S(Obj(_Q, float_ok=True)), S(NUM)], "divide": S(NUM), "pow": S(NUM),
        "fromRotationVector": S(_V3),
        "__add__": S(Obj(_Q)), "__sub__": S(Obj(_Q)),
        "__mul__": [S(Obj(_Q, float_ok=True)), S(NUM)], "__rmul__": S(NUM),
        "__truediv__": S(NUM),
    },
    R3: {
        "__init__": [S(), S(NUM, NUM, NUM), S(Obj(_Q)), S(_V3, NUM), S(_V3),
                     S(_ROTATION_MATRIX), S(_V3, Floats(3, float_ok=True)), S(Obj(R)),
                     S(kw={"roll": lambda: 0.1, "pitch": lambda: 0.2, "yaw": lambda: 0.3})],
        "__reduce__": S(), "__eq__": S(Obj(R3)), "kZero": Const(R3()),
        **{f: Prop() for f in ("x", "y", "z", "angle")},
        **{f: S() for f in ("getX", "getY", "getZ", "getAngle", "getAxis", "getQuaternion",
                            "toMatrix", "toVector", "toRotation2d", "inverse")},
        "fromRadians": S(NUM, NUM, NUM), "fromDegrees": S(NUM, NUM, NUM),
        "fromRotations": S(NUM, NUM, NUM),
        "rotateBy": S(Obj(R3)), "relativeTo": S(Obj(R3)), "times": S(NUM), "div": S(NUM),
        "interpolate": S(Obj(R3), NUM), "integrate": S(NUM, NUM, NUM, NUM),
        "__mul__": S(NUM), "__rmul__": S(NUM), "__truediv__": S(NUM),
    },
    T3: {
        **_arith(T3, iterable=True),
        # A float where the angle or the only argument goes is the (x, y[, z]) form.
        "__init__": [S(NUM, NUM, NUM), S(NUM, Obj(R3, float_ok=True)),
                     S(Floats(3, float_ok=True)), S(Obj(T, float_ok=True)),
                     S(kw={"x": lambda: 1.0, "y": lambda: 2.0, "z": lambda: 3.0})],
        "__reduce__": S(), "kZero": Const(T3()),
        "x": Prop(), "y": Prop(), "z": Prop(), "getX": S(), "getY": S(), "getZ": S(),
        "getNorm": S(), "getSquaredNorm": S(), "getDistance": S(Obj(T3)),
        "getSquaredDistance": S(Obj(T3)), "toVector": S(), "toTranslation2d": S(),
        "rotateBy": S(Obj(R3)), "rotateAround": S(Obj(T3), Obj(R3)), "dot": S(Obj(T3)),
        "cross": S(Obj(T3)), "nearest": S(Seq(T3, n=None, least=1)),
        "interpolate": S(Obj(T3), NUM), "fromFeet": S(NUM, NUM, NUM),
    },
    Pose3d: {
        **_FRAME3D,
        "__init__": [*_FRAME3D_INIT, S(Obj(Pose2d)), S(kw={"pose": VALID[Pose2d]})],
        "__eq__": S(Obj(Pose3d)), "kZero": Const(Pose3d()),
        "transformBy": S(Obj(Transform3d)), "plus": S(Obj(Transform3d)),
        "__add__": S(Obj(Transform3d)), "minus": S(Obj(Pose3d)), "__sub__": S(Obj(Pose3d)),
        "relativeTo": S(Obj(Pose3d)), "rotateBy": S(Obj(R3)),
        "rotateAround": S(Obj(T3), Obj(R3)), "toPose2d": S(), "exp": S(Obj(Twist3d)),
        "log": S(Obj(Pose3d)), "nearest": S(Seq(Pose3d, n=None, least=1)),
        "interpolate": S(Obj(Pose3d), NUM), "fromFeet": S(NUM, NUM, NUM, Obj(R3)),
    },
    Transform3d: {
        **_FRAME3D,
        "__init__": [*_FRAME3D_INIT, S(Obj(Pose3d), Obj(Pose3d)), S(Obj(Transform2d)),
                     S(kw={"initial": VALID[Pose3d], "final": VALID[Pose3d]}),
                     S(kw={"transform": VALID[Transform2d]})],
        "__eq__": S(Obj(Transform3d)), "kZero": Const(Transform3d()),
        "inverse": S(), "plus": S(Obj(Transform3d)), "__add__": S(Obj(Transform3d)),
        "log": S(),
    },
    Twist3d: {
        "__init__": S(*[NUM] * 6), "__reduce__": S(), "__eq__": S(Obj(Twist3d)),
        **{f: Prop(NUM) for f in ("dx", "dy", "dz", "rx", "ry", "rz")},
        "exp": S(), "fromFeet": [S(), S(*[NUM] * 6)], "__mul__": S(NUM), "__rmul__": S(NUM),
    },
    CoordinateAxis: {
        "__init__": S(NUM, NUM, NUM), "__reduce__": S(),
        **{f: S() for f in ("N", "S", "E", "W", "U", "D")},
    },
    CoordinateSystem: {
        # EDN, and NED in the alternate build.
        "__init__": S(Axis((0.0, -1.0, 0.0), (1.0, 0.0, 0.0)),
                      Axis((0.0, 0.0, -1.0), (0.0, -1.0, 0.0)),
                      Axis((1.0, 0.0, 0.0), (0.0, 0.0, -1.0))),
        "__reduce__": S(),
        **{f: S() for f in ("NWU", "EDN", "NED")},
        "convert": [S(Obj(T3), *_SYSTEM), S(Obj(R3), *_SYSTEM), S(Obj(Pose3d), *_SYSTEM),
                    S(Obj(Transform3d), *_SYSTEM)],
    },
})
# robotpy 2027's 3-D names without a Java counterpart: degrees of Rotation3d (read-only),
# feet of the translations, from_matrix, the twist's assignable units.
_FRAME3D_FT = {"from_matrix": S(_AFFINE), "x_feet": Prop(), "y_feet": Prop(), "z_feet": Prop()}
for _cls, _extras in {
    R3: {f"{a}_degrees": Prop() for a in ("x", "y", "z", "angle")},
    T3: {"x_feet": Prop(), "y_feet": Prop(), "z_feet": Prop(), "distance_feet": S(Obj(T3)),
         "norm_feet": S()},
    Pose3d: _FRAME3D_FT,
    Transform3d: _FRAME3D_FT,
    Twist3d: {**{f"{a}_feet": Prop(NUM) for a in ("dx", "dy", "dz")},
              **{f"{a}_degrees": Prop(NUM) for a in ("rx", "ry", "rz")}},
}.items():
    API[_cls].update(_extras)
# Differential swerve. The limit stays valid (>= 0) in the alternate build: 0.125 -> 0.0625.
_LIMIT = Num(0.125)
_PROP = {"proportional": lambda: True}
_RATES = Arr((N,), list_ok=True)
API[DSMV] = _wheels(DSMV, ("motor1", "motor2"), eq=True)
API[DSModV] = _wheels(DSModV, ("wheelVelocity", "azimuthVelocity"), eq=True)
API[DSK] = {
    "__init__": [S(Num(3.0), Num(5.0), Num(0.05)),
                 S(Num(3.0), Num(5.0), Num(0.05), kw={"motor2_inverted": lambda: True})],
    "__reduce__": S(), "__setstate__": S(State(lambda: (R(0.25), 0.5, -1.5))),
    "azimuthGearRatio": Prop(), "wheelGearRatio": Prop(), "wheelRadius": Prop(),
    "motor2Inverted": Prop(),
    "toMotorVelocities": S(NUM, NUM), "toMotorVelocitiesInto": S(NUM, NUM, Out(DSMV)),
    "toModuleVelocities": S(NUM, NUM), "toModuleVelocitiesInto": S(NUM, NUM, Out(DSModV)),
    "resetModulePosition": S(Obj(R), NUM, NUM),
    "toModulePosition": S(NUM, NUM), "toModulePositionInto": S(NUM, NUM, Out(SMP)),
    "desaturateMotorVelocities": [S(Obj(DSMV), _LIMIT), S(Obj(DSMV), _LIMIT, kw=_PROP)],
    "desaturateMotorVelocitiesInPlace": [S(Out(DSMV), _LIMIT),
                                         S(Out(DSMV), _LIMIT, kw=_PROP)],
    "desaturateModuleVelocitiesInPlace": [
        S(OutSeq(SMV), NumSeq(), _LIMIT), S(OutArr((N, 2)), _RATES, _LIMIT),
        S(OutSeq(SMV), _RATES, _LIMIT), S(OutArr((N, 2)), NumSeq(), _LIMIT)],
}
_DW = Floats(DEAD_WHEELS)
_DW_ARR = Arr((DEAD_WHEELS,), list_ok=True)
_GYRO_NUM = Num(0.5, none_ok=True)


def _dead_wheel_forward(out=None):
    extra = (Out(out),) if out else ()
    return [S(_DW, *extra), S(_DW, *extra, _GYRO_NUM), S(_DW_ARR, *extra, _GYRO_NUM)]


_POSE_RESETS = {"getPose": S(), "resetPose": S(Obj(Pose2d)),
                "resetTranslation": S(Obj(T)), "resetRotation": S(Obj(R))}
API[DeadWheelKinematics] = {
    "__init__": S(WheelPoses()), "__reduce__": S(),
    "fromRoadRunner": S(NUM, NUM, NUM, Num(0.1)),
    "fromRoadRunnerTwoWheel": S(NUM, NUM, Num(0.1)),
    "getWheelPoses": S(), "requiresGyro": S(),
    "toChassisVelocities": _dead_wheel_forward(),
    "toChassisVelocitiesInto": _dead_wheel_forward(CV),
    "toTwist2d": _dead_wheel_forward(),
    "toChassisAccelerations": _dead_wheel_forward(),
    "toWheelVelocities": S(Obj(CV)),
    "toWheelVelocitiesInto": S(Obj(CV), OutArr((DEAD_WHEELS,))),
    "toWheelAccelerations": S(Obj(CA)),
}
API[DeadWheelOdometry] = {
    "__init__": [S(Obj(DeadWheelKinematics), _DW, Obj(R, none_ok=True),
                   Obj(Pose2d, none_ok=True)),
                 S(Obj(DeadWheelKinematics), _DW_ARR, Obj(R, none_ok=True))],
    "resetPosition": [S(_DW, Obj(R), Obj(Pose2d)), S(_DW_ARR, Obj(R), Obj(Pose2d))],
    "update": [S(_DW, Obj(R)), S(_DW_ARR, Obj(R))],
    **_POSE_RESETS,
}
API[TwoDeadWheelOdometry] = {
    "__init__": S(NUM, NUM, NUM, NUM, Obj(R), Obj(Pose2d, none_ok=True)),
    "resetPosition": S(NUM, NUM, Obj(R), Obj(Pose2d)),
    "update": S(NUM, NUM, Obj(R)),
    "toChassisVelocities": S(NUM, NUM, NUM),
    **_POSE_RESETS,
}
# ---- pose estimators ----------------------------------------------------------------
# Each VALID estimator has one odometry sample at t = 0 (so sampleAt and vision
# measurements have history to work on); its readings are the constructor's, so the
# registry's update calls are valid.

_STD = Floats(3)


def _estimator(make, *update):
    def build():
        e = make()
        e.updateWithTime(0.0, *update)
        return e
    return build


# The update's readings: the catalog examples' starting readings (per drivetrain, as the
# positions' form differs).
_UPDATE = {
    SwerveDrivePoseEstimator: (R(GYRO0), [SMP(0.0, R(0.0)) for _ in range(N)]),
    MecanumDrivePoseEstimator: (R(GYRO0), MWP(0.0, 0.0, 0.0, 0.0)),
    DifferentialDrivePoseEstimator: (R(GYRO0), 0.0, 0.0),
    TwoDeadWheelPoseEstimator: (0.0, 0.0, R(GYRO0)),
    DeadWheelPoseEstimator: ([0.0] * DEAD_WHEELS, R(GYRO0)),
}
for _cls in ESTIMATORS:
    VALID[_cls] = _estimator(catalog.BY_CLASS[_cls].example, *_UPDATE[_cls])


def _estimator_api(init, update_kinds, reset_kinds):
    return {
        "__init__": init,
        "update": S(*update_kinds), "updateWithTime": S(Num(1.0), *update_kinds),
        "resetPosition": S(*reset_kinds),
        "getEstimatedPosition": S(), "sampleAt": S(NUM),
        "setVisionMeasurementStdDevs": [S(_STD), S(Arr((3,), list_ok=True))],
        "addVisionMeasurement": [S(Obj(Pose2d), NUM),
                                 S(Obj(Pose2d), NUM, Floats(3, none_ok=True))],
        **{k: v for k, v in _POSE_RESETS.items() if k != "getPose"},
    }


API[SwerveDrivePoseEstimator] = _estimator_api(
    [S(Obj(SwerveDriveKinematics), Obj(R), Seq(SMP), Obj(Pose2d)),
     S(Obj(SwerveDriveKinematics), Obj(R), Seq(SMP), Obj(Pose2d), _STD, _STD)],
    (Obj(R), Seq(SMP)), (Obj(R), Seq(SMP), Obj(Pose2d)))
API[MecanumDrivePoseEstimator] = _estimator_api(
    [S(Obj(MecanumDriveKinematics), Obj(R), Obj(MWP), Obj(Pose2d)),
     S(Obj(MecanumDriveKinematics), Obj(R), Obj(MWP), Obj(Pose2d), _STD, _STD)],
    (Obj(R), Obj(MWP)), (Obj(R), Obj(MWP), Obj(Pose2d)))
API[DifferentialDrivePoseEstimator] = _estimator_api(
    [S(Obj(R), NUM, NUM, Obj(Pose2d)), S(Obj(R), NUM, NUM, Obj(Pose2d), _STD, _STD)],
    (Obj(R), NUM, NUM), (Obj(R), NUM, NUM, Obj(Pose2d)))
API[DifferentialDrivePoseEstimator]["update"] = [S(Obj(R), NUM, NUM), S(Obj(R), Obj(DWP))]
API[DifferentialDrivePoseEstimator]["updateWithTime"] = [S(Num(1.0), Obj(R), NUM, NUM),
                                                         S(Num(1.0), Obj(R), Obj(DWP))]
API[DifferentialDrivePoseEstimator]["resetPosition"] = [S(Obj(R), NUM, NUM, Obj(Pose2d)),
                                                        S(Obj(R), Obj(DWP), Obj(Pose2d))]
API[TwoDeadWheelPoseEstimator] = _estimator_api(
    [S(NUM, NUM, NUM, NUM, Obj(R), Obj(Pose2d)),
     S(NUM, NUM, NUM, NUM, Obj(R), Obj(Pose2d), _STD, _STD)],
    (NUM, NUM, Obj(R)), (NUM, NUM, Obj(R), Obj(Pose2d)))
API[DeadWheelPoseEstimator] = _estimator_api(
    [S(Obj(DeadWheelKinematics), _DW, Obj(R, none_ok=True), Obj(Pose2d, none_ok=True)),
     S(Obj(DeadWheelKinematics), _DW, Obj(R, none_ok=True), Obj(Pose2d, none_ok=True),
       _STD, _STD)],
    (_DW, Obj(R)), (_DW, Obj(R), Obj(Pose2d)))


# ---- 3-D odometry and pose estimators ---------------------------------------------
# As the 2-D ones, with Rotation3d gyros, Pose3d poses and four standard deviations. Each
# VALID estimator has one odometry sample at t = 0; the readings are the catalog examples'.

_POSE3D_RESETS = {"getPose": S(), "resetPose": S(Obj(Pose3d)),
                  "resetTranslation": S(Obj(T3)), "resetRotation": S(Obj(R3))}


def _odometry3d(init, readings, gyro_last=False):
    """3-D odometry members: ``init`` the constructor's arguments before the optional
    initial pose, ``readings`` the kinds of one sample (before the gyro, or after it)."""
    def call(*tail):
        return S(*readings, Obj(R3), *tail) if gyro_last else S(Obj(R3), *readings, *tail)
    return {"__init__": S(*init, Obj(Pose3d, none_ok=True)),
            "resetPosition": call(Obj(Pose3d)), "update": call(), **_POSE3D_RESETS}


API[SwerveDriveOdometry3d] = _odometry3d(
    (Obj(SwerveDriveKinematics), Obj(R3), Seq(SMP)), (Seq(SMP),))
API[MecanumDriveOdometry3d] = _odometry3d(
    (Obj(MecanumDriveKinematics), Obj(R3), Obj(MWP)), (Obj(MWP),))
API[DifferentialDriveOdometry3d] = _odometry3d((Obj(R3), NUM, NUM), (NUM, NUM))
API[DeadWheelOdometry3d] = _odometry3d(
    (Obj(DeadWheelKinematics), _DW, Obj(R3)), (_DW,), gyro_last=True)
API[TwoDeadWheelOdometry3d] = _odometry3d(
    (NUM, NUM, NUM, NUM, Obj(R3)), (NUM, NUM), gyro_last=True)
API[TwoDeadWheelOdometry3d]["toChassisVelocities"] = S(NUM, NUM, NUM)
# The swerve and dead-wheel readings also come as float64 arrays.
for _cls, _seq, _arr in ((SwerveDriveOdometry3d, Seq, _MOD_ARR),
                         (DeadWheelOdometry3d, Floats, _DW_ARR)):
    for _m in ("__init__", "resetPosition", "update"):
        _s = API[_cls][_m]
        API[_cls][_m] = [_s, Sig(*[(_arr if isinstance(k, _seq) else k) for k in _s.kinds])]

_STD4 = Floats(4)
_UPDATE3D = {
    SwerveDrivePoseEstimator3d: (R3(), [SMP(0.0, R(0.0)) for _ in range(N)]),
    MecanumDrivePoseEstimator3d: (R3(), MWP(0.0, 0.0, 0.0, 0.0)),
    DifferentialDrivePoseEstimator3d: (R3(), 0.0, 0.0),
    DeadWheelPoseEstimator3d: ([0.0] * DEAD_WHEELS, R3()),
    TwoDeadWheelPoseEstimator3d: (0.0, 0.0, R3()),
}
for _cls in ESTIMATORS3D:
    VALID[_cls] = _estimator(catalog.BY_CLASS[_cls].example, *_UPDATE3D[_cls])


def _estimator3d_api(init, update_kinds, reset_kinds):
    return {
        "__init__": [S(*init), S(*init, _STD4, _STD4)],
        "update": S(*update_kinds), "updateWithTime": S(Num(1.0), *update_kinds),
        "resetPosition": S(*reset_kinds),
        "getEstimatedPosition": S(), "sampleAt": S(NUM),
        "setVisionMeasurementStdDevs": [S(_STD4), S(Arr((4,), list_ok=True))],
        "addVisionMeasurement": [S(Obj(Pose3d), NUM),
                                 S(Obj(Pose3d), NUM, Floats(4, none_ok=True))],
        **{k: v for k, v in _POSE3D_RESETS.items() if k != "getPose"},
    }


API[SwerveDrivePoseEstimator3d] = _estimator3d_api(
    (Obj(SwerveDriveKinematics), Obj(R3), Seq(SMP), Obj(Pose3d)),
    (Obj(R3), Seq(SMP)), (Obj(R3), Seq(SMP), Obj(Pose3d)))
API[MecanumDrivePoseEstimator3d] = _estimator3d_api(
    (Obj(MecanumDriveKinematics), Obj(R3), Obj(MWP), Obj(Pose3d)),
    (Obj(R3), Obj(MWP)), (Obj(R3), Obj(MWP), Obj(Pose3d)))
API[DifferentialDrivePoseEstimator3d] = _estimator3d_api(
    (Obj(R3), NUM, NUM, Obj(Pose3d)), (Obj(R3), NUM, NUM), (Obj(R3), NUM, NUM, Obj(Pose3d)))
API[DifferentialDrivePoseEstimator3d].update(
    update=[S(Obj(R3), NUM, NUM), S(Obj(R3), Obj(DWP))],
    updateWithTime=[S(Num(1.0), Obj(R3), NUM, NUM), S(Num(1.0), Obj(R3), Obj(DWP))],
    resetPosition=[S(Obj(R3), NUM, NUM, Obj(Pose3d)), S(Obj(R3), Obj(DWP), Obj(Pose3d))])
API[DeadWheelPoseEstimator3d] = _estimator3d_api(
    (Obj(DeadWheelKinematics), _DW, Obj(R3), Obj(Pose3d, none_ok=True)),
    (_DW, Obj(R3)), (_DW, Obj(R3), Obj(Pose3d)))
API[TwoDeadWheelPoseEstimator3d] = _estimator3d_api(
    (NUM, NUM, NUM, NUM, Obj(R3), Obj(Pose3d)),
    (NUM, NUM, Obj(R3)), (NUM, NUM, Obj(R3), Obj(Pose3d)))


class ClockSource(Kind):
    """MathSharedStore's timestamp source: the valid call restores the default clock
    (None); hostile sources are not generated, as a bad clock would only break the other
    cases run in the same process (tests/behaviour/test_estimator.py covers them)."""

    def valid(self):
        return None


API[MathSharedStore] = {"getTimestamp": S(), "setTimestampSource": S(ClockSource())}

# ---- TimeInterpolatableBuffer ----------------------------------------------------
# The registry's buffer is the catalog's: a double buffer (so samples are floats, and a
# hostile sample is a hostile number) holding three samples inside its 1.5 s history.

class Interpolator(Kind):
    """An interpolation function f(start, end, t): the valid one is the double buffer's
    own lerp (module-level, so buffers built with it pickle). Hostile callables are not
    generated: any callable is accepted, and what it computes is the caller's."""

    def valid(self):
        return drivekin.interpolation._lerp


API[TIB] = {
    "__init__": S(Interpolator(), Num(1.5)),
    "createBuffer": [S(Num(1.5)), S(Interpolator(), Num(1.5))],
    "createDoubleBuffer": S(Num(1.5)),
    "addSample": S(Num(0.5), NUM), "getSample": S(Num(0.5)),
    "clear": S(), "getInternalBuffer": S(), "__reduce__": S(),
}

# The registry's dead-wheel layout must be the one the factories above describe.
assert len(_dead_wheels().getWheelPoses()) == DEAD_WHEELS

# SwerveDriveOdometry also takes the positions as an (N, 2) array.
for _m in ("__init__", "resetPosition", "update"):
    _s = API[SwerveDriveOdometry][_m]
    API[SwerveDriveOdometry][_m] = [_s, Sig(*[(_MOD_ARR if isinstance(k, Seq) else k)
                                              for k in _s.kinds])]


# Units: static methods only and no instances (like the Java class), so the receiver is the
# class itself and the instance lifecycle cases do not apply.
VALID[Units] = lambda: Units
API[Units] = {name: S(NUM) for name in (
    "metersToFeet", "feetToMeters", "metersToInches", "inchesToMeters", "degreesToRadians",
    "radiansToDegrees", "radiansToRotations", "degreesToRotations", "rotationsToDegrees",
    "rotationsToRadians", "rotationsPerMinuteToRadiansPerSecond",
    "radiansPerSecondToRotationsPerMinute", "milesPerHourToMetersPerSecond",
    "metersPerSecondToMilesPerHour", "millisecondsToSeconds", "secondsToMilliseconds",
    "kilogramsToLbs", "lbsToKilograms")}


# ---- wpistruct --------------------------------------------------------------------

def _pose_bytes():
    return wpistruct.pack(VALID[Pose2d]())


WPISTRUCT = {  # function name -> Sig (receiver-less)
    "getTypeName": S(Type(Pose2d)), "getTypeString": S(Type(Pose2d)),
    "getSchema": S(Type(Pose2d)), "getSize": S(Type(Pose2d)), "getNested": S(Type(Pose2d)),
    "forEachNested": S(Type(Pose2d), Callback()),
    "pack": S(StructObj(Pose2d)), "packArray": S(Seq(Pose2d, n=None)),
    "packInto": [S(StructObj(Pose2d), OutBytes(lambda: bytearray(24))),
                 S(StructObj(Pose2d), OutRawArr((3,)))],
    "unpack": [S(Type(Pose2d), Bytes(_pose_bytes)), S(Type(Pose2d), RawArr((3,)))],
    "unpackFrom": S(Type(Pose2d), Bytes(_pose_bytes)),
    "unpackArray": S(Type(Pose2d), Bytes(lambda: _pose_bytes() * 2)),
}
WPISTRUCT_NONCALLABLE = {"STRUCT_TYPES", "StructValue", "MAX_SWERVE_MODULES"}


# ---- protobuf ---------------------------------------------------------------------

def _pose_message():
    return protobuf.pack(VALID[Pose2d]())


PROTOBUF = {  # function name -> Sig (receiver-less)
    "getTypeName": S(Type(Pose2d)), "getTypeString": S(Type(Pose2d)),
    "getMessageClass": S(Type(Pose2d)),
    "forEachDescriptor": S(Type(Pose2d), Callback()),
    "pack": S(StructObj(Pose2d)),
    "unpack": [S(Type(Pose2d), Bytes(_pose_message)),
               S(Type(Pose2d), Bytes(lambda: bytearray(_pose_message())))],
}
PROTOBUF_NONCALLABLE = {"PROTOBUF_TYPES", "ProtobufValue", "PACKAGE", "GEOMETRY2D_FILE",
                        "GEOMETRY3D_FILE", "KINEMATICS_FILE", "SCHEMA_TYPE"}

class SettingsFile(Kind):
    """The path of a valid PathPlanner settings.json (written once per process)."""

    path = None

    def valid(self):
        if SettingsFile.path is None:
            import json
            import tempfile
            f = tempfile.NamedTemporaryFile("w", suffix=".json", delete=False)
            json.dump({"holonomicMode": True, "robotMass": 60.0, "robotMOI": 6.0,
                       "driveWheelRadius": 0.0508, "driveGearing": 6.75,
                       "maxDriveSpeed": 4.5, "wheelCOF": 1.2, "driveMotorType": "krakenX60",
                       "driveCurrentLimit": 60.0, "flModuleX": 0.27, "flModuleY": 0.27,
                       "frModuleX": 0.27, "frModuleY": -0.27, "blModuleX": -0.27,
                       "blModuleY": 0.27, "brModuleX": -0.27, "brModuleY": -0.27}, f)
            f.close()
            SettingsFile.path = f.name
        return SettingsFile.path


# The setpoint generator (drivekin.setpoint): PathPlannerLib's names.
API[ModuleConfig] = {
    "__init__": [S(Num(0.05), Num(4.5), Num(1.2), Obj(DCMotor), Num(60.0)),
                 S(Num(0.05), Num(4.5), Num(1.2), Obj(DCMotor), Num(60.0), Int(2))],
    "__reduce__": S(), "__eq__": S(Obj(ModuleConfig)),
    **{f: Prop() for f in ("wheelRadiusMeters", "maxDriveVelocityMPS",
                           "maxDriveVelocityRadPerSec", "wheelCOF", "driveMotor",
                           "driveCurrentLimit", "numMotors", "torqueLoss")},
}
API[RobotConfig] = {
    "__init__": S(Num(60.0), Num(6.0), Obj(ModuleConfig), Seq(T, n=None, least=2)),
    "__reduce__": S(), "__eq__": S(Obj(RobotConfig)),
    "fromGUISettings": S(SettingsFile()),
    **{f: Prop() for f in ("massKG", "MOI", "moduleConfig", "moduleLocations", "numModules",
                           "modulePivotDistance", "wheelFrictionForce", "maxTorqueFriction")},
}
API[PathConstraints] = {
    "__init__": [S(Num(1.0), Num(2.0), Num(3.0), Num(4.0)),
                 S(Num(1.0), Num(2.0), Num(3.0), Num(4.0), Num(12.0))],
    "__reduce__": S(), "__eq__": S(Obj(PathConstraints)),
    "unlimitedConstraints": [S(), S(Num(12.0))],
    **{f: Prop() for f in ("maxVelocityMps", "maxAccelerationMpsSq", "maxAngularVelocityRps",
                           "maxAngularAccelerationRpsSq", "nominalVoltage", "unlimited")},
}
API[DriveFeedforwards] = {
    "__init__": S(*(Floats(N) for _ in range(5))),
    "__reduce__": S(), "__eq__": S(Obj(DriveFeedforwards)), "__len__": S(),
    "zeros": S(Int(N)),
    **{f: Prop() for f in ("accelerationsMPSSq", "linearForcesNewtons", "torqueCurrentsAmps",
                           "robotRelativeForcesXNewtons", "robotRelativeForcesYNewtons")},
}
API[SwerveSetpoint] = {
    "__init__": S(Obj(CV), Seq(SMV), Obj(DriveFeedforwards)),
    "__reduce__": S(), "__eq__": S(Obj(SwerveSetpoint)),
    **{f: Prop() for f in ("robotRelativeVelocities", "moduleVelocities", "feedforwards")},
}
_CONSTRAINTS = Obj(PathConstraints, none_ok=True)
API[SwerveSetpointGenerator] = {
    "__init__": [S(Obj(RobotConfig), Num(10.0)), S(Obj(RobotConfig), Num(10.0), Num(6.75))],
    "__reduce__": S(),
    **{f: Prop() for f in ("config", "maxSteerVelocityRadPerSec", "brownoutVoltage",
                           "compatibility")},
    "generateSetpoint": [S(Obj(SwerveSetpoint), Obj(CV), Num(0.02)),
                         S(Obj(SwerveSetpoint), Obj(CV), Num(0.02), Num(11.0), _CONSTRAINTS)],
    "generateSetpointInto": [
        S(Obj(SwerveSetpoint), Obj(CV), Num(0.02), Out(SwerveSetpoint)),
        S(Obj(SwerveSetpoint), Obj(CV), Num(0.02), Out(SwerveSetpoint), Num(11.0),
          _CONSTRAINTS)],
}

_CHASSIS_STACK = Arr((6, 3), rows_free=True)
_FRAME_STACK = Arr((6, 7), rows_free=True)          # 3-D poses [x, y, z, qw, qx, qy, qz]
BATCH = {  # drivekin.batch: stacks of 6 samples
    "toSwerveModuleVelocities": S(Obj(SwerveDriveKinematics), _CHASSIS_STACK),
    "toWheelVelocities": [S(Obj(MecanumDriveKinematics), _CHASSIS_STACK),
                          S(Obj(DifferentialDriveKinematics), _CHASSIS_STACK)],
    "toChassisVelocities": [S(Obj(SwerveDriveKinematics), Arr((6, N, 2), rows_free=True)),
                            S(Obj(MecanumDriveKinematics), Arr((6, 4), rows_free=True))],
    "toSwerveModuleAccelerations": S(Obj(SwerveDriveKinematics), _CHASSIS_STACK, NUM),
    "toWheelAccelerations": [S(Obj(MecanumDriveKinematics), _CHASSIS_STACK),
                             S(Obj(SwerveDriveKinematics), _CHASSIS_STACK)],
    "toChassisAccelerations": [S(Obj(SwerveDriveKinematics), Arr((6, N, 2), rows_free=True)),
                               S(Obj(DifferentialDriveKinematics), Arr((6, 2), rows_free=True))],
    "desaturateWheelVelocities": [S(Arr((6, N, 2), rows_free=True), NUM),
                                  S(Arr((6, N, 2)), Arr((6, 3)), NUM, NUM, NUM)],
    "desaturate": S(Arr((6, 4), rows_free=True), NUM),
    "discretize": S(_CHASSIS_STACK, NUM),
    "desaturatedDiscretize": S(Obj(SwerveDriveKinematics), _CHASSIS_STACK, Num(0.02),
                               Num(0.125)),
    "toRobotRelative": S(_CHASSIS_STACK, NUM), "toFieldRelative": S(_CHASSIS_STACK, NUM),
    "exp": [S(_CHASSIS_STACK), S(Arr((6, 6), rows_free=True))],
    "log": [S(_CHASSIS_STACK), S(_FRAME_STACK)],
    # Two stacks must have one length, so neither's rows are free.
    **{f: [S(Arr((6, 3)), Arr((6, 3))), S(Arr((6, 7)), Arr((6, 7)))]
       for f in ("transformBy", "relativeTo")},
    "replay": [S(Obj(DifferentialDriveOdometry), Arr((6,)), Arr((6, 2))),
               S(Obj(DifferentialDriveOdometry3d), Arr((6, 4)), Arr((6, 2)))],
    "generateSetpoints": [
        S(Obj(SwerveSetpointGenerator), Obj(SwerveSetpoint), _CHASSIS_STACK, Num(0.02),
          Num(12.0)),
        S(Obj(SwerveSetpointGenerator), Obj(SwerveSetpoint), _CHASSIS_STACK, Arr((6,)),
          Arr((6,), fill=[12.0, 11.0, 10.0, 9.0, 8.0, 7.0]), _CONSTRAINTS)],
}

# Module-level functions (the receiver-less members): module -> its registry.
MODULE_FUNCTIONS = {wpistruct: WPISTRUCT, protobuf: PROTOBUF, batch: BATCH}


def members(cls):
    """(name, [Sig, ...] | Prop | Const) for every registered member of ``cls``."""
    for name, spec in API[cls].items():
        yield name, spec if isinstance(spec, (Prop, Const)) else (
            spec if isinstance(spec, list) else [spec])


def public_classes():
    """The classes under attack: every catalog entry's (test_catalog.py checks that the
    catalog holds every public class) but the warning categories, plain Python classes
    with no code of drivekin's."""
    return [e.cls for e in catalog.ENTRIES if e.kind != "warning"]


# DCMotor: WPILib's motor model (immutable; the factories are static methods).
_MOTORS = ("getCIM", "getVex775Pro", "getNEO", "getMiniCIM", "getBag", "getAndymarkRs775_125",
           "getBanebotsRs775", "getAndymark9015", "getBanebotsRs550", "getNeo550",
           "getFalcon500", "getFalcon500Foc", "getRomiBuiltIn", "getKrakenX60",
           "getKrakenX60Foc", "getKrakenX44", "getKrakenX44Foc", "getMinion", "getNeoVortex")
API[DCMotor] = {
    "__init__": [S(Num(12.0), Num(2.6), Num(105.0), Num(1.8), Num(594.0)),
                 S(Num(12.0), Num(2.6), Num(105.0), Num(1.8), Num(594.0), Int(2))],
    "__reduce__": S(), "__eq__": S(Obj(DCMotor)),
    **{f: Prop() for f in ("nominalVoltage", "stallTorque", "stallCurrent", "freeCurrent",
                           "freeSpeed", "R", "Kv", "Kt")},
    "getCurrent": [S(NUM, NUM), S(NUM)],
    "getTorque": S(NUM), "getVoltage": S(NUM, NUM), "getVelocity": S(NUM, NUM),
    "withReduction": S(Num(3.0)),
    **{name: [S(), S(Int(2))] for name in _MOTORS},
}
