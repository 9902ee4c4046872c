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
from cpython.mem cimport PyMem_Free, PyMem_Malloc
from cpython.ref cimport Py_INCREF, PyObject
from cpython.tuple cimport PyTuple_New, PyTuple_SET_ITEM
from libc.math cimport fabs, isfinite
from libc.string cimport memcpy

from drivekin._core.args cimport (check_type, count_arg, is_array, positive_finite,
                                  read_floats, read_number, snapshot)
from drivekin._core.kernels cimport rot_xy
from drivekin._core.setpointkernel cimport (CONSTANTS, SAVED, SCRATCH, SetpointKernel,
                                            check_output, check_step, generate,
                                            keep_headings, limits_t)
from drivekin._core.types cimport rot2_t, vec3_t
from drivekin.chassis cimport ChassisVelocities, new_chassis_velocities
from drivekin cimport robotconfig
from drivekin.swerve cimport SwerveDriveKinematics
from drivekin.swervemodule cimport SwerveModuleVelocity, _ModuleVector, new_module_velocity
from drivekin._core.errors import refuse_delete, type_name
# The robot description lives in drivekin.robotconfig; this module exports it too.
from drivekin.robotconfig import ModuleConfig, RobotConfig
cimport numpy as cnp

cnp.import_array()

__all__ = ["DriveFeedforwards", "ModuleConfig", "PathConstraints", "RobotConfig",
           "SwerveSetpoint", "SwerveSetpointGenerator"]

cdef double NAN = float("nan")
cdef tuple COMPATIBILITY = (None, "pathplanner")
cdef tuple LIMIT_NAMES = ("maxVelocityMps", "maxAccelerationMpsSq", "maxAngularVelocityRps",
                          "maxAngularAccelerationRpsSq")
cdef tuple FEEDFORWARD_NAMES = ("accelerationsMPSSq", "linearForcesNewtons",
                                "torqueCurrentsAmps", "robotRelativeForcesXNewtons",
                                "robotRelativeForcesYNewtons")


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
            raise TypeError(f"accelerationsMPSSq must be a list or tuple of floats (one per "
                            f"module) or a 1-D float64 array, got "
                            f"{type_name(accelerationsMPSSq)} (list(...) makes a list of "
                            f"another iterable)")
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

cdef class SwerveSetpointGenerator(SetpointKernel):
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

    def __init__(self, config: RobotConfig, double maxSteerVelocityRadPerSec,
                 double brownoutVoltage=6.75, compatibility=None):
        if self.buf != NULL:
            raise TypeError("SwerveSetpointGenerator is already initialised: __init__ "
                            "cannot be called again")
        check_type(config, RobotConfig, "config")
        cdef robotconfig.RobotConfig c = <robotconfig.RobotConfig>config
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
            sizeof(double) * ((CONSTANTS + SCRATCH + SAVED) * n + (3 + 3 * n) + (3 + 8 * n)))
        if buf == NULL:
            raise MemoryError()
        if self.buf != NULL:            # constructing the kinematics ran Python code
            PyMem_Free(buf)
            raise TypeError("SwerveSetpointGenerator is already initialised: __init__ "
                            "cannot be called again")
        cdef robotconfig.ModuleConfig mc = c.module
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
        self.saved = self.out + 3 + 8 * n
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
            # check_step's bound on velocities, for the same reason (check_output keeps
            # every output within it).
            if not fabs(self.prev[i]) <= 1e100:
                raise ValueError(f"prevSetpoint's velocities must be finite and at most 1e100 "
                                 f"(m/s, rad/s) in magnitude, got {prevSetpoint!r}")
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
        not discretized: the generator does that) over ``dt`` (s, from 1e-9 to 1e6).
        Velocities (desired and previous) must be at most 1e100 in magnitude, so that
        every setpoint is finite; one that still overflows (a robot whose own numbers
        are extreme) raises ValueError.

        ``inputVoltage`` (V) is the drive motors' supply: NaN means 12 V, lower values
        are raised to ``brownoutVoltage``; the top speed scales by min(1, V/12).
        ``constraints`` (:class:`PathConstraints`, or None) adds PathPlanner's limits.
        Invalid arguments raise ValueError or TypeError and change nothing."""
        cdef limits_t lim
        check_type(desiredRobotRelativeVelocities, ChassisVelocities,
                   "desiredRobotRelativeVelocities")
        cdef vec3_t want = (<ChassisVelocities>desiredRobotRelativeVelocities).v
        check_step(want, dt, inputVoltage, -1)
        cdef SwerveSetpoint r = new_setpoint(self.g.n)
        cdef int has = self._load(prevSetpoint, constraints, &lim)
        keep_headings(self)
        generate(&self.g, self.prev, want, dt, inputVoltage, &lim if has else NULL, self.out)
        check_output(self, -1)
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
        check_step(want, dt, inputVoltage, -1)
        check_type(out, SwerveSetpoint, "out")
        (<SwerveSetpoint>out)._ready()
        if len((<SwerveSetpoint>out).modules) != self.g.n:
            raise ValueError(f"out has {len((<SwerveSetpoint>out).modules)} modules; this "
                             f"generator's config has {self.g.n}")
        cdef int has = self._load(prevSetpoint, constraints, &lim)
        keep_headings(self)
        generate(&self.g, self.prev, want, dt, inputVoltage, &lim if has else NULL, self.out)
        check_output(self, -1)
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

