"""Kinematically limited swerve setpoints: PathPlannerLib's ``SwerveSetpointGenerator``
(after Team 254's), for any number of modules.

Units: m, m/s, rad, rad/s, s, kg, kg·m², N, N·m, A, V. Robot frame: x forward, y left,
CCW positive.

Each call moves the previous setpoint towards the desired robot-relative velocities as
far as the robot can in one loop period: module steering rate, drive torque (motor
curve, current limit, battery voltage, wheel friction) and the optional
:class:`PathConstraints`. Two behaviours:

- the default enforces every limit between consecutive setpoints. The desired velocities
  are desaturated and discretized first, without skew
  (:meth:`SwerveDriveKinematics.desaturatedDiscretize`), and the step is then limited in
  that space; the drive limit's root is scaled by the steering limit's, as in Team 254's
  original;
- ``compatibility="pathplanner"`` reproduces PathPlannerLib Java/C++ 2026: it drops
  254's factor (so a module's drive limit is under-enforced once the step has been
  shortened, by steering or by another module's drive limit) and discretizes after
  limiting (so consecutive outputs can differ by more than the limits allow while the
  robot turns).

docs/setpoints.md gives the rules, the PathPlanner → drivekin names and the measured
differences."""
cimport cython
from cpython.long cimport PyLong_CheckExact
from cpython.mem cimport PyMem_Free, PyMem_Malloc
from cpython.ref cimport Py_INCREF, PyObject
from cpython.tuple cimport PyTuple_New, PyTuple_SET_ITEM
from libc.math cimport M_PI, fabs, hypot, isfinite, isnan, sqrt
from drivekin._core.dkmath cimport atan2, sincos
from libc.string cimport memcpy

from drivekin._core.args cimport (check_type, is_array, positive_finite, read_floats,
                                  read_number, snapshot)
from drivekin._core.kernels cimport (chassis_discretize, desaturated_discretize_scale,
                                     forward_solve, jmax, jmin, rot_cs, rot_minus, rot_neg,
                                     rot_plus, rot_rad, rot_radians, rot_xy, swerve_ik,
                                     wheels_desaturate)
from drivekin._core.types cimport rot2_t, vec3_t
from drivekin.chassis cimport ChassisVelocities, new_chassis_velocities
from drivekin.geometry cimport Translation2d
from drivekin.motor cimport DCMotor, motor_current
from drivekin.swerve cimport SwerveDriveKinematics
from drivekin.swervemodule cimport SwerveModuleVelocity, _ModuleVector, new_module_velocity
from drivekin._core.errors import refuse_delete, type_name
cimport numpy as cnp

cnp.import_array()

__all__ = ["DriveFeedforwards", "ModuleConfig", "PathConstraints", "RobotConfig",
           "SwerveSetpoint", "SwerveSetpointGenerator"]

# PathPlannerLib's tolerance for "zero" speeds and velocities (issue #957 raised it from 1e-8).
cdef double EPS = 1e-6
# Java's int, as for DCMotor's numMotors.
cdef long long MAX_MOTORS = 2147483647
cdef enum:
    SCRATCH = 20                 # arrays of n in generator_t.scratch
    CONSTANTS = 5                # pd, lc, ls, kx, ky
cdef double NAN = float("nan")
cdef tuple COMPATIBILITY = (None, "pathplanner")
cdef tuple LIMIT_NAMES = ("maxVelocityMps", "maxAccelerationMpsSq", "maxAngularVelocityRps",
                          "maxAngularAccelerationRpsSq")
cdef tuple FEEDFORWARD_NAMES = ("accelerationsMPSSq", "linearForcesNewtons",
                                "torqueCurrentsAmps", "robotRelativeForcesXNewtons",
                                "robotRelativeForcesYNewtons")


cdef long long count_arg(object x, str name, long long low) except -1:
    if not PyLong_CheckExact(x):
        raise TypeError(f"{name} must be an int, got {type_name(x)}")
    if not low <= x <= MAX_MOTORS:
        raise ValueError(f"{name} must be an int from {low} to {MAX_MOTORS}, got {x!r}")
    return <long long>x


# ---------------------------------------------------------------------------------------
# The robot

cdef class ModuleConfig:
    """ModuleConfig(wheelRadiusMeters, maxDriveVelocityMPS, wheelCOF, driveMotor, driveCurrentLimit, numMotors=1)

    One swerve module's drive: wheel radius (m), the top speed it reaches while driving
    the robot at full output (m/s), the coefficient of friction between wheel and carpet
    (1.0 if unsure), the drive gearbox as a :class:`DCMotor` with its reduction
    (``DCMotor.getKrakenX60(1).withReduction(6.75)``), the current limit per motor (A)
    and the number of drive motors per module.

    As in PathPlannerLib, ``driveCurrentLimit`` reads back multiplied by ``numMotors``,
    and ``torqueLoss`` is the torque the motor still makes at top speed on 12 V (limited
    by the current limit), which models the module's friction. Every number must be
    positive and finite (ValueError), ``driveMotor`` a drivekin DCMotor (TypeError).
    Immutable; ``==`` compares every field.
    """

    def __init__(self, double wheelRadiusMeters, double maxDriveVelocityMPS,
                 double wheelCOF, driveMotor: DCMotor, double driveCurrentLimit,
                 numMotors=1):
        if self.frozen:
            raise TypeError("ModuleConfig is immutable: __init__ cannot be called on an "
                            "existing instance")
        positive_finite(wheelRadiusMeters, "wheelRadiusMeters", "wheel radius in m")
        positive_finite(maxDriveVelocityMPS, "maxDriveVelocityMPS", "speed in m/s")
        positive_finite(wheelCOF, "wheelCOF", "coefficient of friction")
        check_type(driveMotor, DCMotor, "driveMotor")
        positive_finite(driveCurrentLimit, "driveCurrentLimit", "current in A")
        cdef long long k = count_arg(numMotors, "numMotors", 1)
        cdef DCMotor m = <DCMotor>driveMotor
        if not m.frozen:
            raise ValueError("driveMotor has not been initialised")
        cdef double limit = driveCurrentLimit * <double>k
        positive_finite(limit, "driveCurrentLimit × numMotors", "current in A")
        # PathPlannerLib's torque loss: the current at top speed on 12 V, clamped to the
        # limit, as torque (never negative).
        cdef double w = maxDriveVelocityMPS / wheelRadiusMeters
        cdef double at_top = motor_current(m.kv, m.r, w, 12.0)
        self.radius = wheelRadiusMeters
        self.vmax = maxDriveVelocityMPS
        self.cof = wheelCOF
        self.motor = m
        self.current_limit = limit
        self.num_motors = k
        self.torque_loss = jmax(jmin(at_top, limit) * m.kt, 0.0)
        self.frozen = True

    @property
    def wheelRadiusMeters(self):
        """Drive wheel radius, m."""
        return self.radius

    @property
    def maxDriveVelocityMPS(self):
        """Top drive speed at full output, m/s."""
        return self.vmax

    @property
    def maxDriveVelocityRadPerSec(self):
        """Top wheel speed, rad/s: ``maxDriveVelocityMPS / wheelRadiusMeters``."""
        return self.vmax / self.radius

    @property
    def wheelCOF(self):
        """Coefficient of friction between wheel and carpet."""
        return self.cof

    @property
    def driveMotor(self):
        """The drive gearbox (DCMotor, reduction included)."""
        return self.motor

    @property
    def driveCurrentLimit(self):
        """Current limit of the module's drive motors together, A (per motor × numMotors)."""
        return self.current_limit

    @property
    def numMotors(self):
        """Drive motors per module."""
        return self.num_motors

    @property
    def torqueLoss(self):
        """Torque lost to friction in the module, N·m."""
        return self.torque_loss

    def __eq__(self, other):
        if type(other) is not ModuleConfig:
            return NotImplemented
        cdef ModuleConfig o = <ModuleConfig>other
        return (self.radius == o.radius and self.vmax == o.vmax and self.cof == o.cof
                and self.motor == o.motor and self.current_limit == o.current_limit
                and self.num_motors == o.num_motors)

    __hash__ = None

    def __reduce__(self):
        return (ModuleConfig, (self.radius, self.vmax, self.cof, self.motor,
                               self.current_limit / <double>self.num_motors,
                               self.num_motors))

    def __repr__(self):
        return (f"ModuleConfig(wheelRadiusMeters={self.radius!r}, "
                f"maxDriveVelocityMPS={self.vmax!r}, wheelCOF={self.cof!r}, "
                f"driveMotor={self.motor!r}, "
                f"driveCurrentLimit={self.current_limit / <double>self.num_motors!r}, "
                f"numMotors={self.num_motors!r})")

    def __delattr__(self, name):
        refuse_delete(self, name)


# PathPlanner GUI's driveMotorType values and the DCMotor factories they name.
_GUI_MOTORS = {
    "krakenX60": "getKrakenX60", "krakenX60FOC": "getKrakenX60Foc",
    "falcon500": "getFalcon500", "falcon500FOC": "getFalcon500Foc",
    "vortex": "getNeoVortex", "NEO": "getNEO", "CIM": "getCIM", "miniCIM": "getMiniCIM",
}
_GUI_NUMBERS = ("robotMass", "robotMOI", "driveWheelRadius", "driveGearing", "maxDriveSpeed",
               "wheelCOF", "driveCurrentLimit", "flModuleX", "flModuleY", "frModuleX",
               "frModuleY", "blModuleX", "blModuleY", "brModuleX", "brModuleY")


cdef class RobotConfig:
    """RobotConfig(massKG, MOI, moduleConfig, moduleOffsets)

    The robot as the setpoint generator sees it: mass including bumpers and battery (kg),
    moment of inertia about its centre (kg·m²), the :class:`ModuleConfig` shared by its
    modules, and the N ≥ 2 module positions (Translation2d, m, robot frame, none at the
    centre) in the order the setpoints use. PathPlannerLib's derived values are
    attributes: ``wheelFrictionForce = wheelCOF · (massKG / N) · 9.8`` (N) and
    ``maxTorqueFriction = wheelFrictionForce · wheelRadiusMeters`` (N·m).
    Immutable; ``==`` compares every field.
    """

    def __init__(self, double massKG, double MOI, moduleConfig: ModuleConfig,
                 moduleOffsets):
        if self.frozen:
            raise TypeError("RobotConfig is immutable: __init__ cannot be called on an "
                            "existing instance")
        positive_finite(massKG, "massKG", "mass in kg")
        positive_finite(MOI, "MOI", "moment of inertia in kg·m²")
        check_type(moduleConfig, ModuleConfig, "moduleConfig")
        if not (<ModuleConfig>moduleConfig).frozen:
            raise ValueError("moduleConfig has not been initialised")
        cdef tuple mods = snapshot(moduleOffsets, "moduleOffsets")
        cdef Py_ssize_t i, n = len(mods)
        if n < 2:
            raise ValueError(f"moduleOffsets must hold at least 2 module positions, got {n}")
        pivots = []
        for i in range(n):
            t = mods[i]
            if type(t) is not Translation2d:
                raise TypeError(f"moduleOffsets[{i}] must be a Translation2d, "
                                f"got {type_name(t)}")
            x, y = (<Translation2d>t).v.x, (<Translation2d>t).v.y
            if not (isfinite(x) and isfinite(y)):
                raise ValueError(f"moduleOffsets[{i}] must be finite (m), got {t!r}")
            # The force model divides by the module's distance from the centre.
            d = hypot(x, y)
            if not d > 1e-9:
                raise ValueError(f"moduleOffsets[{i}] is at the robot's centre ({t!r}); a "
                                 f"swerve module needs a lever arm")
            pivots.append(d)
        self.mass = massKG
        self.moi = MOI
        self.module = <ModuleConfig>moduleConfig
        self.locations = mods
        self.pivots = tuple(pivots)
        self.frozen = True

    @staticmethod
    def fromGUISettings(path):
        """Read PathPlanner's ``settings.json`` (``deploy/pathplanner/settings.json`` in a
        robot project) at ``path`` into a RobotConfig: mass, MOI, wheel radius, gearing,
        top speed, wheel COF, drive motor type and current limit, and the four module
        positions. A file that is not a swerve (holonomic) robot's settings, lacks a key
        or holds a value of the wrong kind raises ValueError naming it."""
        import json
        from drivekin.motor import DCMotor as Motor
        try:
            with open(path, "rb") as f:
                settings = json.loads(f.read())
        except (OSError, UnicodeDecodeError, ValueError) as e:
            raise ValueError(f"cannot read PathPlanner settings {str(path)!r}: {e}") from None
        if type(settings) is not dict:
            raise ValueError(f"{str(path)!r} is not PathPlanner settings (a JSON object)")

        def get(key, kinds):
            if key not in settings:
                raise ValueError(f"{str(path)!r} has no {key!r}; is it PathPlanner's "
                                 f"settings.json?")
            v = settings[key]
            if type(v) not in kinds:
                raise ValueError(f"{key!r} in {str(path)!r} must be a "
                                 f"{' or '.join(k.__name__ for k in kinds)}, got {v!r}")
            return v

        if not get("holonomicMode", (bool,)):
            raise ValueError(f"{str(path)!r} describes a differential drive "
                             f"(holonomicMode false); the swerve setpoint generator needs "
                             f"a swerve robot's settings")
        num = {k: float(get(k, (int, float))) for k in _GUI_NUMBERS}
        motor_type = get("driveMotorType", (str,))
        if motor_type not in _GUI_MOTORS:
            raise ValueError(f"driveMotorType {motor_type!r} in {str(path)!r} is not one of "
                             f"{', '.join(_GUI_MOTORS)}")
        gearbox = getattr(Motor, _GUI_MOTORS[motor_type])(1).withReduction(num["driveGearing"])
        module = ModuleConfig(num["driveWheelRadius"], num["maxDriveSpeed"], num["wheelCOF"],
                              gearbox, num["driveCurrentLimit"], 1)
        return RobotConfig(num["robotMass"], num["robotMOI"], module, [
            Translation2d(num[f"{c}ModuleX"], num[f"{c}ModuleY"])
            for c in ("fl", "fr", "bl", "br")])

    @property
    def massKG(self):
        """Robot mass, kg."""
        return self.mass

    @property
    def MOI(self):
        """Moment of inertia about the robot's centre, kg·m²."""
        return self.moi

    @property
    def moduleConfig(self):
        """The ModuleConfig of every module."""
        return self.module

    @property
    def moduleLocations(self):
        """Module positions (tuple of Translation2d, m, robot frame)."""
        return self.locations

    @property
    def numModules(self):
        """Number of modules."""
        return len(self.locations)

    @property
    def modulePivotDistance(self):
        """Each module's distance from the robot's centre (tuple of floats, m)."""
        return self.pivots

    @property
    def wheelFrictionForce(self):
        """Friction force one wheel can transmit, N: ``wheelCOF · (massKG / N) · 9.8``."""
        return self.module.cof * ((self.mass / len(self.locations)) * 9.8)

    @property
    def maxTorqueFriction(self):
        """Largest wheel torque before it slips, N·m."""
        return self.wheelFrictionForce * self.module.radius

    def __eq__(self, other):
        if type(other) is not RobotConfig:
            return NotImplemented
        cdef RobotConfig o = <RobotConfig>other
        return (self.mass == o.mass and self.moi == o.moi and self.module == o.module
                and self.locations == o.locations)

    __hash__ = None

    def __reduce__(self):
        return (RobotConfig, (self.mass, self.moi, self.module, self.locations))

    def __repr__(self):
        return (f"RobotConfig(massKG={self.mass!r}, MOI={self.moi!r}, "
                f"moduleConfig={self.module!r}, moduleOffsets={list(self.locations)!r})")

    def __delattr__(self, name):
        refuse_delete(self, name)


cdef class PathConstraints:
    """PathConstraints(maxVelocityMps, maxAccelerationMpsSq, maxAngularVelocityRps, maxAngularAccelerationRpsSq, nominalVoltage=12.0, unlimited=False)

    PathPlannerLib's limits on top of the robot's own: linear velocity (m/s) and
    acceleration (m/s²), angular velocity (rad/s) and angular acceleration (rad/s²).
    The maxima must be ≥ 0 (+inf for none); ``nominalVoltage`` (V) and ``unlimited`` are
    carried for PathPlanner's path follower and do not change the setpoint generator,
    as in PathPlannerLib. The generator also takes any object with these four attribute
    names (pathplannerlib's own PathConstraints). Immutable.
    """

    def __init__(self, double maxVelocityMps, double maxAccelerationMpsSq,
                 double maxAngularVelocityRps, double maxAngularAccelerationRpsSq,
                 double nominalVoltage=12.0, unlimited=False):
        if self.frozen:
            raise TypeError("PathConstraints is immutable: __init__ cannot be called on "
                            "an existing instance")
        for v, name in ((maxVelocityMps, "maxVelocityMps"),
                        (maxAccelerationMpsSq, "maxAccelerationMpsSq"),
                        (maxAngularVelocityRps, "maxAngularVelocityRps"),
                        (maxAngularAccelerationRpsSq, "maxAngularAccelerationRpsSq")):
            if not v >= 0.0:
                raise ValueError(f"{name} must be ≥ 0 (+inf for no limit), got {v!r}")
        positive_finite(nominalVoltage, "nominalVoltage", "voltage in V")
        if type(unlimited) is not bool:
            raise TypeError(f"unlimited must be a bool, got {type_name(unlimited)}")
        self.max_v = maxVelocityMps
        self.max_a = maxAccelerationMpsSq
        self.max_w = maxAngularVelocityRps
        self.max_alpha = maxAngularAccelerationRpsSq
        self.nominal = nominalVoltage
        self.is_unlimited = unlimited
        self.frozen = True

    @staticmethod
    def unlimitedConstraints(double nominalVoltage=12.0):
        """Constraints that limit nothing (every maximum +inf, ``unlimited`` True)."""
        inf = float("inf")
        return PathConstraints(inf, inf, inf, inf, nominalVoltage, True)

    @property
    def maxVelocityMps(self):
        """Largest linear speed, m/s."""
        return self.max_v

    @property
    def maxAccelerationMpsSq(self):
        """Largest linear acceleration, m/s²."""
        return self.max_a

    @property
    def maxAngularVelocityRps(self):
        """Largest angular speed, rad/s."""
        return self.max_w

    @property
    def maxAngularAccelerationRpsSq(self):
        """Largest angular acceleration, rad/s²."""
        return self.max_alpha

    @property
    def nominalVoltage(self):
        """Nominal battery voltage, V (unused by the setpoint generator)."""
        return self.nominal

    @property
    def unlimited(self):
        """Whether these are the unlimited constraints."""
        return self.is_unlimited

    def __eq__(self, other):
        if type(other) is not PathConstraints:
            return NotImplemented
        cdef PathConstraints o = <PathConstraints>other
        return (self.max_v == o.max_v and self.max_a == o.max_a and self.max_w == o.max_w
                and self.max_alpha == o.max_alpha and self.nominal == o.nominal
                and self.is_unlimited == o.is_unlimited)

    __hash__ = None

    def __reduce__(self):
        return (PathConstraints, (self.max_v, self.max_a, self.max_w, self.max_alpha,
                                  self.nominal, bool(self.is_unlimited)))

    def __repr__(self):
        return (f"PathConstraints(maxVelocityMps={self.max_v!r}, "
                f"maxAccelerationMpsSq={self.max_a!r}, maxAngularVelocityRps={self.max_w!r}, "
                f"maxAngularAccelerationRpsSq={self.max_alpha!r}, "
                f"nominalVoltage={self.nominal!r}, unlimited={bool(self.is_unlimited)!r})")

    def __delattr__(self, name):
        refuse_delete(self, name)


# ---------------------------------------------------------------------------------------
# The setpoint

cdef int read_row(object seq, str name, Py_ssize_t n, double* out) except -1:
    # n finite numbers from a list, tuple or 1-D float64 array.
    cdef Py_ssize_t i
    read_floats(seq, n, out, name, "values (one per module)")
    for i in range(n):
        if not isfinite(out[i]):
            raise ValueError(f"{name}[{i}] must be finite, got {out[i]!r}")
    return 0


cdef DriveFeedforwards new_feedforwards(Py_ssize_t n):
    cdef DriveFeedforwards f = DriveFeedforwards.__new__(DriveFeedforwards)
    f.d = <double*>PyMem_Malloc(sizeof(double) * 5 * n)
    if f.d == NULL:
        raise MemoryError()
    f.n = n
    return f


cdef class DriveFeedforwards:
    """DriveFeedforwards(accelerationsMPSSq, linearForcesNewtons, torqueCurrentsAmps, robotRelativeForcesXNewtons, robotRelativeForcesYNewtons)

    Per-module feedforwards of a setpoint, each a sequence of N floats in module order:
    drive acceleration (m/s²), linear force at the wheel along the module (N), the drive
    current that makes that force (A), and the wheel's force vector in the robot frame
    (x and y, N). The attributes return tuples. ``==`` compares every value.
    """

    def __cinit__(self, *args, **kwargs):
        self.d = NULL
        self.n = 0

    def __init__(self, accelerationsMPSSq, linearForcesNewtons, torqueCurrentsAmps,
                 robotRelativeForcesXNewtons, robotRelativeForcesYNewtons):
        if self.d != NULL:
            raise TypeError("DriveFeedforwards is immutable: __init__ cannot be called on "
                            "an existing instance")
        rows = (accelerationsMPSSq, linearForcesNewtons, torqueCurrentsAmps,
                robotRelativeForcesXNewtons, robotRelativeForcesYNewtons)
        cdef Py_ssize_t n = 0
        if is_array(accelerationsMPSSq) or type(accelerationsMPSSq) in (list, tuple):
            n = len(accelerationsMPSSq)
        else:
            read_row(accelerationsMPSSq, FEEDFORWARD_NAMES[0], 0, NULL)    # the TypeError
        if n < 1:
            raise ValueError("accelerationsMPSSq must hold one value per module, got none")
        cdef double* d = <double*>PyMem_Malloc(sizeof(double) * 5 * n)
        if d == NULL:
            raise MemoryError()
        cdef int k
        try:
            for k in range(5):
                read_row(rows[k], FEEDFORWARD_NAMES[k], n, d + k * n)
        except BaseException:
            PyMem_Free(d)
            raise
        if self.d != NULL:              # reading the sequences ran Python code
            PyMem_Free(d)
            raise TypeError("DriveFeedforwards is immutable: __init__ cannot be called on "
                            "an existing instance")
        self.n = n
        self.d = d

    def __dealloc__(self):
        PyMem_Free(self.d)

    @staticmethod
    def zeros(numModules):
        """Feedforwards of zeros for ``numModules`` modules."""
        cdef long long n = count_arg(numModules, "numModules", 1)
        cdef DriveFeedforwards f = new_feedforwards(<Py_ssize_t>n)
        cdef Py_ssize_t i
        for i in range(5 * f.n):
            f.d[i] = 0.0
        return f

    cdef tuple _row(self, int k):
        if self.d == NULL:
            raise RuntimeError("DriveFeedforwards.__init__ has not completed")
        cdef tuple t = PyTuple_New(self.n)
        cdef Py_ssize_t i
        cdef object x
        for i in range(self.n):
            x = self.d[k * self.n + i]
            Py_INCREF(x)
            PyTuple_SET_ITEM(t, i, x)
        return t

    @property
    def accelerationsMPSSq(self):
        """Drive accelerations, m/s² (tuple, one per module)."""
        return self._row(0)

    @property
    def linearForcesNewtons(self):
        """Linear forces at the wheels along the modules, N."""
        return self._row(1)

    @property
    def torqueCurrentsAmps(self):
        """Drive currents that produce those forces, A."""
        return self._row(2)

    @property
    def robotRelativeForcesXNewtons(self):
        """x components of the wheel force vectors, robot frame, N."""
        return self._row(3)

    @property
    def robotRelativeForcesYNewtons(self):
        """y components of the wheel force vectors, robot frame, N."""
        return self._row(4)

    def __len__(self):
        if self.d == NULL:
            raise RuntimeError("DriveFeedforwards.__init__ has not completed")
        return self.n

    def __eq__(self, other):
        if type(other) is not DriveFeedforwards:
            return NotImplemented
        cdef DriveFeedforwards o = <DriveFeedforwards>other
        cdef Py_ssize_t i
        if o.n != self.n or self.d == NULL or o.d == NULL:
            return self.d == o.d
        for i in range(5 * self.n):
            if self.d[i] != o.d[i]:
                return False
        return True

    __hash__ = None

    def __reduce__(self):
        return (DriveFeedforwards, tuple(self._row(k) for k in range(5)))

    def __repr__(self):
        return ("DriveFeedforwards(" + ", ".join(
            f"{FEEDFORWARD_NAMES[k]}={list(self._row(k))!r}" for k in range(5)) + ")")


cdef tuple copy_modules(object moduleVelocities, str name):
    cdef tuple mods = snapshot(moduleVelocities, name)
    cdef Py_ssize_t i, n = len(mods)
    cdef tuple t = PyTuple_New(n)
    cdef SwerveModuleVelocity o
    for i in range(n):
        if type(mods[i]) is not SwerveModuleVelocity:
            raise TypeError(f"{name}[{i}] must be a SwerveModuleVelocity, "
                            f"got {type_name(mods[i])}")
        o = new_module_velocity((<_ModuleVector>mods[i]).m, (<_ModuleVector>mods[i]).a)
        Py_INCREF(o)
        PyTuple_SET_ITEM(t, i, o)
    return t


cdef SwerveSetpoint new_setpoint(Py_ssize_t n):
    cdef SwerveSetpoint s = SwerveSetpoint.__new__(SwerveSetpoint)
    cdef tuple t = PyTuple_New(n)
    cdef Py_ssize_t i
    cdef SwerveModuleVelocity o
    for i in range(n):
        o = SwerveModuleVelocity.__new__(SwerveModuleVelocity)
        Py_INCREF(o)
        PyTuple_SET_ITEM(t, i, o)
    s.v = ChassisVelocities.__new__(ChassisVelocities)
    s.modules = t
    s.ff = new_feedforwards(n)
    return s


cdef class SwerveSetpoint:
    """SwerveSetpoint(robotRelativeVelocities, moduleVelocities, feedforwards)

    A setpoint of the generator: robot-relative ChassisVelocities (m/s, rad/s), one
    SwerveModuleVelocity per module and their :class:`DriveFeedforwards`. The setpoint
    owns copies of what it is given; its attributes return those objects, which
    :meth:`SwerveSetpointGenerator.generateSetpointInto` updates in place when the
    setpoint is its ``out``. ``==`` compares every value.
    """

    def __init__(self, robotRelativeVelocities: ChassisVelocities, moduleVelocities,
                 feedforwards: DriveFeedforwards):
        if self.modules is not None:
            raise TypeError("SwerveSetpoint is immutable: __init__ cannot be called on an "
                            "existing instance")
        check_type(robotRelativeVelocities, ChassisVelocities, "robotRelativeVelocities")
        check_type(feedforwards, DriveFeedforwards, "feedforwards")
        cdef tuple mods = copy_modules(moduleVelocities, "moduleVelocities")
        cdef DriveFeedforwards f = <DriveFeedforwards>feedforwards
        if f.d == NULL:
            raise ValueError("feedforwards has not been initialised")
        if len(mods) < 1 or f.n != len(mods):
            raise ValueError(f"moduleVelocities and feedforwards must describe the same "
                             f"modules, got {len(mods)} velocities and feedforwards for "
                             f"{f.n}")
        cdef DriveFeedforwards own = new_feedforwards(f.n)
        memcpy(own.d, f.d, sizeof(double) * 5 * f.n)
        if self.modules is not None:
            raise TypeError("SwerveSetpoint is immutable: __init__ cannot be called on an "
                            "existing instance")
        cdef vec3_t v = (<ChassisVelocities>robotRelativeVelocities).v
        self.v = new_chassis_velocities(v.x, v.y, v.z)
        self.modules = mods
        self.ff = own

    cdef int _ready(self) except -1:
        if self.modules is None:
            raise RuntimeError("SwerveSetpoint.__init__ has not completed")
        return 0

    @property
    def robotRelativeVelocities(self):
        """Robot-relative chassis velocities (ChassisVelocities, m/s and rad/s)."""
        self._ready()
        return self.v

    @property
    def moduleVelocities(self):
        """Module velocities (tuple of SwerveModuleVelocity, m/s and angle)."""
        self._ready()
        return self.modules

    @property
    def feedforwards(self):
        """The modules' DriveFeedforwards."""
        self._ready()
        return self.ff

    def __eq__(self, other):
        if type(other) is not SwerveSetpoint:
            return NotImplemented
        cdef SwerveSetpoint o = <SwerveSetpoint>other
        return self.v == o.v and self.modules == o.modules and self.ff == o.ff

    __hash__ = None

    def __reduce__(self):
        self._ready()
        return (SwerveSetpoint, (self.v, list(self.modules), self.ff))

    def __repr__(self):
        if self.modules is None:
            return "SwerveSetpoint(<uninitialised>)"
        return (f"SwerveSetpoint(robotRelativeVelocities={self.v!r}, "
                f"moduleVelocities={list(self.modules)!r}, feedforwards={self.ff!r})")

    def __delattr__(self, name):
        refuse_delete(self, name)


# ---------------------------------------------------------------------------------------
# The kernel: PathPlannerLib's algorithm in its order of operations, on C doubles. Angles
# go through drivekin's Rotation2d arithmetic (WPILib's), so the branches PathPlannerLib
# takes on angle comparisons come out the same.

# Rotation2d(π), as PathPlannerLib adds it (cos π, sin π: not exactly (−1, 0)).
cdef rot2_t HALF_TURN = rot_rad(M_PI)


cdef inline bint eps_eq(double a, double b) noexcept nogil:
    return a - EPS <= b and a + EPS >= b


cdef inline bint eps_zero(vec3_t v) noexcept nogil:
    return eps_eq(v.x, 0.0) and eps_eq(v.y, 0.0) and eps_eq(v.z, 0.0)


cdef inline bint flips(rot2_t r) noexcept nogil:
    # Reaching the rotation is faster by turning the other way and driving backwards.
    return fabs(rot_radians(r)) > M_PI / 2.0


cdef inline double signum(double x) noexcept nogil:
    return 1.0 if x > 0.0 else (-1.0 if x < 0.0 else 0.0)


cdef inline double steering_max_s(double x0, double y0, double t0, double x1, double y1,
                                  double t1, double max_step) noexcept nogil:
    # The s in [0, 1] at which the velocity interpolated from (x0, y0) to (x1, y1) has
    # turned max_step from heading t0: rotate both so that the target heading is +x; the
    # y components are proportional to the distances to the crossing.
    cdef double diff, target, sn, cs, h0, h1
    if t1 - t0 > M_PI:
        t1 -= 2.0 * M_PI
    elif t1 - t0 < -M_PI:
        t1 += 2.0 * M_PI
    diff = t1 - t0
    if fabs(diff) <= max_step:
        return 1.0
    target = t0 + (max_step if diff >= 0.0 else -max_step)
    cdef rot2_t r = rot_rad(-target)
    sn = r.s
    cs = r.c
    h0 = sn * x0 + cs * y0
    h1 = sn * x1 + cs * y1
    return h0 / (h0 - h1)


cdef inline bint valid_s(double s) noexcept nogil:
    return isfinite(s) and s >= 0.0 and s <= 1.0


cdef inline double drive_max_s(double x0, double y0, double x1, double y1,
                               double max_step) noexcept nogil:
    # The first s in [0, 1] at which |p0 + s (p1 − p0)| = |p0| ± max_step (a quadratic in
    # s); 1 when the whole segment is within the step.
    cdef double l0 = x0 * x0 + y0 * y0, l1 = x1 * x1 + y1 * y1
    cdef double r0 = sqrt(l0), diff = sqrt(l1) - r0, target, p, a, b, c, root, s
    if fabs(diff) <= max_step:
        return 1.0
    target = r0 + (max_step if diff >= 0.0 else -max_step)
    p = x0 * x1 + y0 * y1
    a = l0 + l1 - 2.0 * p
    b = 2.0 * (p - l0)
    c = l0 - target * target
    root = sqrt(b * b - 4.0 * a * c)
    if a != 0.0:
        s = (-b + root) / (2.0 * a)
        if valid_s(s):
            return s
        s = (-b - root) / (2.0 * a)
        if valid_s(s):
            return s
    return 1.0


cdef inline double band_exit(double x0, double y0, double x1, double y1,
                             double step) noexcept nogil:
    # The first s in [0, 1] at which |p0 + s (p1 − p0)| leaves [|p0| − step, |p0| + step]
    # (1 if it never does). PathPlannerLib's root (drive_max_s) only looks for the bound on
    # the side of |p1|, so a speed that dips through |p0| − step on the way to a faster
    # end goes unseen, and another module's limit can stop the step inside the dip; and
    # its l0 + l1 − 2p cancels for a short step at speed (a 1e-8 m/s step near 4.3 m/s
    # came out 0: no limit). Here a = |Δ|² and b = 2 p0·Δ come from the difference, the
    # constant terms from |p0| and the step, and the roots from the cancellation-free
    # form of the quadratic formula.
    cdef double dx = x1 - x0, dy = y1 - y0
    cdef double a = dx * dx + dy * dy, b = 2.0 * (x0 * dx + y0 * dy)
    cdef double r0 = sqrt(x0 * x0 + y0 * y0), s = 1.0, c, disc, q, lo, hi
    if not a > 0.0:
        return 1.0
    # Leaving above: a s² + b s − step (2|p0| + step) = 0 has one positive root.
    c = -step * (2.0 * r0 + step)
    disc = b * b - 4.0 * a * c
    q = -0.5 * (b + (sqrt(disc) if b >= 0.0 else -sqrt(disc)))
    hi = jmax(q / a, c / q) if q != 0.0 else sqrt(-c / a)
    if hi < s:
        s = hi
    # Leaving below (only where |p0| > step): c > 0, real roots only when heading inwards.
    if r0 > step:
        c = step * (2.0 * r0 - step)
        disc = b * b - 4.0 * a * c
        if disc >= 0.0 and b < 0.0:
            q = -0.5 * (b - sqrt(disc))
            lo = jmin(q / a, c / q)
            if 0.0 <= lo < s:
                s = lo
    return jmax(s, 0.0)


cdef inline vec3_t wpilib_discretize(double vx, double vy, double omega,
                                    double dt) noexcept nogil:
    # ChassisSpeeds.discretize in WPILib 2026's own arithmetic (Pose2d.log's cos θ − 1,
    # which cancels for small θ): drivekin's discretize is exact where this is not (up to
    # ~1e-10 m/s apart here), and the compatibility mode reproduces PathPlannerLib's
    # arithmetic (its bits, but for drivekin's own sin and cos, an ulp from libm's at most).
    cdef double c, s, m, theta, h, k, cmo, rc, rs, x, y
    cdef vec3_t out
    sincos(omega * dt, &s, &c)
    m = hypot(c, s)
    if m > 1e-6:
        c = c / m
        s = s / m
    else:
        c = 1.0
        s = 0.0
    theta = atan2(s, c)
    h = theta / 2.0
    cmo = c - 1.0
    if fabs(cmo) < 1e-9:
        k = 1.0 - 1.0 / 12.0 * theta * theta
    else:
        k = -(h * s) / cmo
    m = hypot(k, -h)
    rc = k / m
    rs = -h / m
    x = vx * dt
    y = vy * dt
    m = hypot(k, h)
    out.x = (x * rc - y * rs) * m / dt
    out.y = (x * rs + y * rc) * m / dt
    out.z = theta / dt
    return out


cdef void generate(generator_t* g, const double* prev, vec3_t desired, double dt,
                   double voltage, const limits_t* lim, double* out) noexcept nogil:
    """One setpoint. ``prev`` holds the previous chassis velocities then n speeds, n
    cosines and n sines; ``out`` receives the chassis velocities, the module speeds,
    cosines and sines, then the five feedforward rows. ``lim`` may be NULL."""
    cdef Py_ssize_t n = g.n, m
    cdef const double* psp = prev + 3
    cdef const double* pcs = prev + 3 + n
    cdef const double* psn = prev + 3 + 2 * n
    cdef double* w = g.scratch
    cdef double* dsp = w            # desired module speeds, angles
    cdef double* dc = w + n
    cdef double* ds = w + 2 * n
    cdef double* pvx = w + 3 * n    # previous and desired module velocity vectors
    cdef double* pvy = w + 4 * n
    cdef double* dvx = w + 5 * n
    cdef double* dvy = w + 6 * n
    cdef double* pht = w + 7 * n    # their headings (direction of travel), rad
    cdef double* dht = w + 8 * n
    cdef double* ovr = w + 9 * n    # 1 where the module's angle is set by the steering rule
    cdef double* oc = w + 10 * n
    cdef double* osn = w + 11 * n
    cdef double* acc = w + 12 * n   # module speeds of the chassis acceleration
    cdef double* tc = w + 13 * n
    cdef double* ts = w + 14 * n
    cdef double* wfx = w + 15 * n   # wheel force vectors
    cdef double* wfy = w + 16 * n
    cdef double* rsp = out + 3      # the result's module speeds, angles
    cdef double* rc = out + 3 + n
    cdef double* rs = out + 3 + 2 * n
    cdef double* ff = out + 3 + 3 * n
    cdef double max_speed, k, norm, dx, dy, dth, min_s, step, s, cur, rcur, tq_f, tq_r
    cdef double fcx, fcy, torque, ax, ay, alpha, x1, y1, fx, fy, tq, wd, applied, f
    cdef double r3[3]
    cdef vec3_t d, ret
    cdef rot2_t ph, dh, a, fa
    cdef bint steer = True, all_flip, accelerating
    cdef int attempt

    if isnan(voltage):
        voltage = 12.0
    else:
        voltage = jmax(voltage, g.brownout)
    max_speed = g.vmax * jmin(1.0, voltage / 12.0)

    for attempt in range(2):
        d = desired
        if attempt == 1:
            # Every module would turn more than 90°: stop first, then flip in place.
            d.x = 0.0
            d.y = 0.0
            d.z = 0.0
        if lim != NULL:
            norm = hypot(d.x, d.y)
            if norm > lim.max_v:
                k = lim.max_v / norm
                d.x = d.x * k
                d.y = d.y * k
            d.z = jmax(-lim.max_w, jmin(d.z, lim.max_w))
        if g.compat:
            swerve_ik(n, g.mx, g.my, d.x, d.y, d.z, g.hc, g.hs, dsp, dc, ds)
            wheels_desaturate(n, dsp, max_speed, dsp)
            forward_solve(3, n, g.f1, dsp, dc, ds, r3)
            d.x = r3[0]
            d.y = r3[1]
            d.z = r3[2]
        else:
            k = desaturated_discretize_scale(n, g.mx, g.my, d.x, d.y, d.z, dt, max_speed)
            d = chassis_discretize(k * d.x, k * d.y, k * d.z, dt)
            swerve_ik(n, g.mx, g.my, d.x, d.y, d.z, g.hc, g.hs, dsp, dc, ds)

        steer = not eps_zero(d)
        if not steer:
            for m in range(n):
                dc[m] = pcs[m]
                ds[m] = psn[m]
                dsp[m] = 0.0
        all_flip = True
        for m in range(n):
            pvx[m] = pcs[m] * psp[m]
            pvy[m] = psn[m] * psp[m]
            ph = rot_cs(pcs[m], psn[m])
            if psp[m] < 0.0:
                ph = rot_plus(ph, HALF_TURN)
            dvx[m] = dc[m] * dsp[m]
            dvy[m] = ds[m] * dsp[m]
            dh = rot_cs(dc[m], ds[m])
            if dsp[m] < 0.0:
                dh = rot_plus(dh, HALF_TURN)
            pht[m] = rot_radians(ph)
            dht[m] = rot_radians(dh)
            if all_flip and fabs(rot_radians(rot_plus(rot_neg(ph), dh))) < M_PI / 2.0:
                all_flip = False
        ret.x = prev[0]
        ret.y = prev[1]
        ret.z = prev[2]
        if attempt == 1 or not (all_flip and not eps_zero(ret) and not eps_zero(d)):
            break

    dx = d.x - prev[0]
    dy = d.y - prev[1]
    dth = d.z - prev[2]
    min_s = 1.0

    # Steering: a stopped module turns in place (holding the robot still until it is
    # within a step of its goal); a moving one limits s to where its heading has turned
    # one step, which friction may shorten (the wheel must not slide sideways).
    for m in range(n):
        ovr[m] = 0.0
        if not steer:
            ovr[m] = 1.0
            oc[m] = pcs[m]
            osn[m] = psn[m]
            continue
        step = dt * g.max_steer
        if eps_eq(psp[m], 0.0):
            ovr[m] = 1.0
            if eps_eq(dsp[m], 0.0):
                oc[m] = pcs[m]
                osn[m] = psn[m]
                continue
            a = rot_plus(rot_neg(rot_cs(pcs[m], psn[m])), rot_cs(dc[m], ds[m]))
            if flips(a):
                a = rot_plus(a, HALF_TURN)
            if fabs(rot_radians(a)) / step <= 1.0:
                oc[m] = dc[m]
                osn[m] = ds[m]
            else:
                a = rot_plus(rot_cs(pcs[m], psn[m]), rot_rad(signum(rot_radians(a)) * step))
                oc[m] = a.c
                osn[m] = a.s
                min_s = 0.0
            continue
        if min_s == 0.0:
            continue
        step = jmin(step, (dt * g.friction_force) / ((g.mass / n) * fabs(psp[m])))
        s = steering_max_s(pvx[m], pvy[m], pht[m], dvx[m], dvy[m], dht[m], step)
        min_s = jmin(min_s, s)

    # Drive torque: what each motor can give at its present speed on this voltage, less
    # (accelerating) or plus (braking) the module's friction, capped by wheel slip; the
    # forces give the chassis acceleration, and that each module's largest speed step.
    fcx = 0.0
    fcy = 0.0
    torque = 0.0
    for m in range(n):
        f = fabs(psp[m] / g.radius)
        cur = jmax(jmin(motor_current(g.kv, g.r, f, voltage), g.current_limit), 0.0)
        rcur = jmax(jmin(fabs(motor_current(g.kv, g.r, f, -voltage)), g.current_limit), 0.0)
        tq_f = cur * g.kt
        tq_r = rcur * g.kt
        # The desired speed once optimised against the previous angle (turn ≤ 90°).
        s = dsp[m]
        if fabs(rot_radians(rot_minus(rot_cs(dc[m], ds[m]), rot_cs(pcs[m], psn[m])))
                * (180.0 / M_PI)) > 90.0:
            s = -s
        fa = rot_cs(pcs[m], psn[m])
        accelerating = (eps_eq(psp[m], 0.0) or (psp[m] > 0.0 and s >= psp[m])
                        or (psp[m] < 0.0 and s <= psp[m]))
        if accelerating:
            tq = tq_f - g.torque_loss
            k = 1.0
            if psp[m] < 0.0:
                fa = rot_plus(fa, HALF_TURN)
        else:
            tq = tq_r + g.torque_loss
            k = -1.0
            if psp[m] > 0.0:
                fa = rot_plus(fa, HALF_TURN)
        tq = jmin(tq, g.max_torque_friction)
        f = tq / g.radius
        fx = f * k * fa.c
        fy = f * k * fa.s
        fcx = fcx + fx
        fcy = fcy + fy
        if not eps_eq(0.0, hypot(fx, fy)):
            torque = torque + f * g.pd[m] * rot_minus(rot_xy(fx, fy), rot_cs(g.lc[m], g.ls[m])).s
    ax = fcx / g.mass
    ay = fcy / g.mass
    alpha = torque / g.moi
    if lim != NULL:
        norm = hypot(ax, ay)
        if norm > lim.max_a:
            k = lim.max_a / norm
            ax = ax * k
            ay = ay * k
        alpha = jmax(-lim.max_alpha, jmin(alpha, lim.max_alpha))
    # A velocity conversion, as in PathPlannerLib: it updates the heading memory.
    swerve_ik(n, g.mx, g.my, ax, ay, alpha, g.hc, g.hs, acc, tc, ts)

    # Drive: search the segment the limits so far left, [prev, prev + min_s·Δ]. Its root
    # is relative to that segment, so the step is min_s·s (Team 254); PathPlannerLib takes
    # s itself. The default mode also takes the first point where the module's speed leaves
    # the band of one step around its previous speed on either side (band_exit).
    for m in range(n):
        if min_s == 0.0:
            break
        step = fabs(acc[m] * dt)
        if min_s == 1.0:
            x1 = dvx[m]
            y1 = dvy[m]
        else:
            x1 = (dvx[m] - pvx[m]) * min_s + pvx[m]
            y1 = (dvy[m] - pvy[m]) * min_s + pvy[m]
        if g.compat:
            min_s = jmin(min_s, drive_max_s(pvx[m], pvy[m], x1, y1, step))
        else:
            min_s = jmin(min_s, min_s * band_exit(pvx[m], pvy[m], x1, y1, step))

    ret.x = prev[0] + min_s * dx
    ret.y = prev[1] + min_s * dy
    ret.z = prev[2] + min_s * dth
    if g.compat:
        ret = wpilib_discretize(ret.x, ret.y, ret.z, dt)
    out[0] = ret.x
    out[1] = ret.y
    out[2] = ret.z

    # Feedforwards: the force and torque that make this step's acceleration, shared out
    # over the wheels.
    fx = (ret.x - prev[0]) / dt * g.mass / n
    fy = (ret.y - prev[1]) / dt * g.mass / n
    tq = (ret.z - prev[2]) / dt * g.moi / n
    for m in range(n):
        wfx[m] = fx + g.kx[m] * tq
        wfy[m] = fy + g.ky[m] * tq
    swerve_ik(n, g.mx, g.my, ret.x, ret.y, ret.z, g.hc, g.hs, rsp, rc, rs)
    for m in range(n):
        wd = hypot(wfx[m], wfy[m])
        applied = 0.0
        if wd > 1e-6:
            applied = wd * rot_minus(rot_xy(wfx[m], wfy[m]), rot_cs(rc[m], rs[m])).c
        cur = applied * g.radius / g.kt
        if ovr[m] != 0.0:
            if flips(rot_plus(rot_neg(rot_cs(rc[m], rs[m])), rot_cs(oc[m], osn[m]))):
                rsp[m] = -rsp[m]
                applied = -applied
                cur = -cur
            rc[m] = oc[m]
            rs[m] = osn[m]
        if flips(rot_plus(rot_neg(rot_cs(pcs[m], psn[m])), rot_cs(rc[m], rs[m]))):
            a = rot_plus(rot_cs(rc[m], rs[m]), HALF_TURN)
            rc[m] = a.c
            rs[m] = a.s
            rsp[m] = -rsp[m]
            applied = -applied
            cur = -cur
        ff[m] = (rsp[m] - psp[m]) / dt
        ff[n + m] = applied
        ff[2 * n + m] = cur
        ff[3 * n + m] = wfx[m]
        ff[4 * n + m] = wfy[m]


cdef int check_step(vec3_t want, double dt, double voltage, str where) except -1:
    """The per-step arguments: finite desired velocities, dt > 0, a finite voltage or NaN
    (``where`` prefixes the message, for the batch form's samples)."""
    if not (isfinite(want.x) and isfinite(want.y) and isfinite(want.z)):
        raise ValueError(f"{where}desiredRobotRelativeVelocities must be finite, got "
                         f"({want.x!r}, {want.y!r}, {want.z!r})")
    if not (isfinite(dt) and dt > 0.0):
        raise ValueError(f"{where}dt must be a positive finite loop period in s, got {dt!r}")
    if not (isnan(voltage) or isfinite(voltage)):
        raise ValueError(f"{where}inputVoltage must be a finite voltage in V (NaN for 12 V), "
                         f"got {voltage!r}")
    return 0


cdef void store_setpoint(SwerveSetpoint s, const double* out, Py_ssize_t n) noexcept:
    """Copy the kernel's output into a setpoint of n modules (no Python code runs)."""
    cdef Py_ssize_t i
    cdef _ModuleVector mv
    s.v.v.x = out[0]
    s.v.v.y = out[1]
    s.v.v.z = out[2]
    for i in range(n):
        mv = <_ModuleVector>s.modules[i]
        mv.m = out[3 + i]
        mv.a.c = out[3 + n + i]
        mv.a.s = out[3 + 2 * n + i]
    memcpy(s.ff.d, out + 3 + 3 * n, sizeof(double) * 5 * n)


# ---------------------------------------------------------------------------------------
# The generator

cdef class SwerveSetpointGenerator:
    """SwerveSetpointGenerator(config, maxSteerVelocityRadPerSec, brownoutVoltage=6.75, compatibility=None)

    Limits setpoints to what the robot in ``config`` (:class:`RobotConfig`) can do with
    modules that steer at most ``maxSteerVelocityRadPerSec`` (rad/s, > 0, +inf for no
    limit). ``brownoutVoltage`` (V, ≥ 0) is the lowest battery voltage the torque model
    assumes (SystemCore's default brownout is 6.75 V; PathPlannerLib reads the robot
    controller's). ``compatibility`` is None (every limit enforced between consecutive
    setpoints) or ``"pathplanner"`` (PathPlannerLib Java/C++ 2026's numbers, its
    under-enforced drive limit included); the module docstring says how they differ.

    Like PathPlannerLib's, whose heading memory lives in its RobotConfig's kinematics,
    the generator remembers each module's last heading (a module stopped in a moving
    robot keeps its angle). Not thread-safe; every call holds the GIL.
    """

    def __cinit__(self, *args, **kwargs):
        self.buf = NULL

    def __init__(self, config: RobotConfig, double maxSteerVelocityRadPerSec,
                 double brownoutVoltage=6.75, compatibility=None):
        if self.buf != NULL:
            raise TypeError("SwerveSetpointGenerator is already initialised: __init__ "
                            "cannot be called again")
        check_type(config, RobotConfig, "config")
        cdef RobotConfig c = <RobotConfig>config
        if not c.frozen:
            raise ValueError("config has not been initialised")
        if not maxSteerVelocityRadPerSec > 0.0:
            raise ValueError(f"maxSteerVelocityRadPerSec must be a positive steering rate "
                             f"in rad/s (+inf for no limit), got {maxSteerVelocityRadPerSec!r}")
        if not (isfinite(brownoutVoltage) and brownoutVoltage >= 0.0):
            raise ValueError(f"brownoutVoltage must be a finite voltage ≥ 0 in V, "
                             f"got {brownoutVoltage!r}")
        if not any(compatibility is x or (type(compatibility) is str and compatibility == x)
                   for x in COMPATIBILITY):
            raise ValueError(f"compatibility must be None or 'pathplanner', "
                             f"got {compatibility!r}")
        cdef SwerveDriveKinematics kin = SwerveDriveKinematics(c.locations)
        cdef Py_ssize_t n = len(c.locations), i
        cdef double* buf = <double*>PyMem_Malloc(
            sizeof(double) * ((CONSTANTS + SCRATCH) * n + (3 + 3 * n) + (3 + 8 * n)))
        if buf == NULL:
            raise MemoryError()
        if self.buf != NULL:            # constructing the kinematics ran Python code
            PyMem_Free(buf)
            raise TypeError("SwerveSetpointGenerator is already initialised: __init__ "
                            "cannot be called again")
        cdef ModuleConfig mc = c.module
        cdef rot2_t a
        cdef double d
        self.cfg = c
        self.kin = kin
        self.compat_name = compatibility
        self.g.n = n
        self.g.compat = compatibility is not None
        self.g.mass = c.mass
        self.g.moi = c.moi
        self.g.radius = mc.radius
        self.g.vmax = mc.vmax
        self.g.friction_force = mc.cof * ((c.mass / n) * 9.8)
        self.g.max_torque_friction = self.g.friction_force * mc.radius
        self.g.current_limit = mc.current_limit
        self.g.torque_loss = mc.torque_loss
        self.g.kv = mc.motor.kv
        self.g.r = mc.motor.r
        self.g.kt = mc.motor.kt
        self.g.max_steer = maxSteerVelocityRadPerSec
        self.g.brownout = brownoutVoltage
        self.g.mx = kin.mx
        self.g.my = kin.my
        self.g.f1 = kin.f1
        self.g.hc = kin.hc
        self.g.hs = kin.hs
        self.g.pd = buf
        self.g.lc = buf + n
        self.g.ls = buf + 2 * n
        self.g.kx = buf + 3 * n
        self.g.ky = buf + 4 * n
        self.g.scratch = buf + CONSTANTS * n
        self.prev = buf + (CONSTANTS + SCRATCH) * n
        self.out = self.prev + 3 + 3 * n
        for i in range(n):
            self.g.pd[i] = c.pivots[i]
            a = rot_xy(kin.mx[i], kin.my[i])
            self.g.lc[i] = a.c
            self.g.ls[i] = a.s
            # PathPlannerLib's force kinematics rows [1, 0, −y/|r|²] and [0, 1, x/|r|²],
            # through its reciprocal Translation2d(1/|r|, angle).
            d = 1.0 / self.g.pd[i]
            self.g.kx[i] = -(d * a.s)
            self.g.ky[i] = d * a.c
        self.buf = buf

    def __dealloc__(self):
        PyMem_Free(self.buf)

    cdef int _load(self, object prevSetpoint, object constraints,
                   limits_t* lim) except -1:
        """Validate the previous setpoint and the constraints and read them into C memory
        (self.prev, lim); returns 1 when there are constraints. Nothing is written
        elsewhere, and nothing after the copy of the setpoint can run Python code."""
        cdef SwerveSetpoint p
        cdef Py_ssize_t n, i
        cdef _ModuleVector mv
        cdef PathConstraints pc
        cdef double vals[4]
        cdef int has = 0
        if self.buf == NULL:
            raise RuntimeError("SwerveSetpointGenerator.__init__ has not completed")
        check_type(prevSetpoint, SwerveSetpoint, "prevSetpoint")
        p = <SwerveSetpoint>prevSetpoint
        p._ready()
        n = self.g.n
        if len(p.modules) != n:
            raise ValueError(f"prevSetpoint has {len(p.modules)} modules; this generator's "
                             f"config has {n}")
        if constraints is not None:
            if type(constraints) is PathConstraints:
                pc = <PathConstraints>constraints
                if not pc.frozen:
                    raise ValueError("constraints has not been initialised")
                vals[0], vals[1], vals[2], vals[3] = pc.max_v, pc.max_a, pc.max_w, pc.max_alpha
            else:
                for i, name in enumerate(LIMIT_NAMES):
                    try:
                        x = getattr(constraints, name)
                    except AttributeError:
                        raise TypeError(f"constraints must be a PathConstraints (or have "
                                        f"its {name} attribute), got "
                                        f"{type_name(constraints)}") from None
                    if read_number(<PyObject*>x, &vals[i]) != 0:
                        raise TypeError(f"constraints.{name} must be a float, "
                                        f"got {type_name(x)}")
                    if not vals[i] >= 0.0:
                        raise ValueError(f"constraints.{name} must be ≥ 0, got {vals[i]!r}")
            lim.max_v, lim.max_a, lim.max_w, lim.max_alpha = vals[0], vals[1], vals[2], vals[3]
            has = 1
        self.prev[0] = p.v.v.x
        self.prev[1] = p.v.v.y
        self.prev[2] = p.v.v.z
        for i in range(n):
            mv = <_ModuleVector>p.modules[i]
            self.prev[3 + i] = mv.m
            self.prev[3 + n + i] = mv.a.c
            self.prev[3 + 2 * n + i] = mv.a.s
        for i in range(3 + n):
            if not isfinite(self.prev[i]):
                raise ValueError(f"prevSetpoint must be finite, got {prevSetpoint!r}")
        return has

    @property
    def config(self):
        """The RobotConfig."""
        return self.cfg

    @property
    def maxSteerVelocityRadPerSec(self):
        """Largest module steering rate, rad/s."""
        return self.g.max_steer

    @property
    def brownoutVoltage(self):
        """Lowest voltage the torque model assumes, V."""
        return self.g.brownout

    @property
    def compatibility(self):
        """None or ``"pathplanner"``."""
        return self.compat_name

    def generateSetpoint(self, prevSetpoint: SwerveSetpoint,
                         desiredRobotRelativeVelocities: ChassisVelocities, double dt,
                         double inputVoltage=NAN, constraints=None):
        """Return the next :class:`SwerveSetpoint` from ``prevSetpoint`` (normally the
        previous call's result) towards ``desiredRobotRelativeVelocities`` (m/s, rad/s;
        not discretized: the generator does that) over ``dt`` (s, > 0).

        ``inputVoltage`` (V) is the drive motors' supply: NaN means 12 V, lower values
        are raised to ``brownoutVoltage``; the top speed scales by min(1, V/12).
        ``constraints`` (:class:`PathConstraints`, or None) adds PathPlanner's limits.
        Invalid arguments raise ValueError or TypeError and change nothing."""
        cdef limits_t lim
        check_type(desiredRobotRelativeVelocities, ChassisVelocities,
                   "desiredRobotRelativeVelocities")
        cdef vec3_t want = (<ChassisVelocities>desiredRobotRelativeVelocities).v
        check_step(want, dt, inputVoltage, "")
        cdef SwerveSetpoint r = new_setpoint(self.g.n)
        cdef int has = self._load(prevSetpoint, constraints, &lim)
        generate(&self.g, self.prev, want, dt, inputVoltage, &lim if has else NULL, self.out)
        store_setpoint(r, self.out, self.g.n)
        return r

    def generateSetpointInto(self, prevSetpoint: SwerveSetpoint,
                             desiredRobotRelativeVelocities: ChassisVelocities, double dt,
                             out: SwerveSetpoint, double inputVoltage=NAN,
                             constraints=None):
        """Allocation-free :meth:`generateSetpoint`: the result is written into ``out``
        (a SwerveSetpoint for this robot's modules, which may be ``prevSetpoint``), its
        ChassisVelocities, module velocities and feedforwards updated in place. Returns
        None."""
        cdef limits_t lim
        check_type(desiredRobotRelativeVelocities, ChassisVelocities,
                   "desiredRobotRelativeVelocities")
        cdef vec3_t want = (<ChassisVelocities>desiredRobotRelativeVelocities).v
        check_step(want, dt, inputVoltage, "")
        check_type(out, SwerveSetpoint, "out")
        (<SwerveSetpoint>out)._ready()
        if len((<SwerveSetpoint>out).modules) != self.g.n:
            raise ValueError(f"out has {len((<SwerveSetpoint>out).modules)} modules; this "
                             f"generator's config has {self.g.n}")
        cdef int has = self._load(prevSetpoint, constraints, &lim)
        generate(&self.g, self.prev, want, dt, inputVoltage, &lim if has else NULL, self.out)
        store_setpoint(<SwerveSetpoint>out, self.out, self.g.n)

    def __reduce__(self):
        return (SwerveSetpointGenerator, (self.cfg, self.g.max_steer, self.g.brownout,
                                          self.compat_name))

    def __repr__(self):
        if self.buf == NULL:
            return "SwerveSetpointGenerator(<uninitialised>)"
        return (f"SwerveSetpointGenerator({self.cfg!r}, "
                f"maxSteerVelocityRadPerSec={self.g.max_steer!r}, "
                f"brownoutVoltage={self.g.brownout!r}, "
                f"compatibility={self.compat_name!r})")

