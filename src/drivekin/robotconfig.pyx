"""The robot as PathPlannerLib's swerve setpoint generator sees it: :class:`ModuleConfig`
(one module's drive) and :class:`RobotConfig` (mass, moment of inertia, module positions),
from code or from the PathPlanner GUI's ``settings.json`` (:meth:`RobotConfig.fromGUISettings`).

Units: m, m/s, kg, kg·m², N, N·m, A. Robot frame: x forward, y left. docs/setpoints.md
gives the PathPlanner → drivekin names; :mod:`drivekin.setpoint` exports these classes
too."""
from libc.math cimport isfinite
from drivekin._core.dkmath cimport hypot

from drivekin._core.args cimport check_type, count_arg, positive_finite, snapshot
from drivekin._core.kernels cimport jmax, jmin
from drivekin.geometry cimport Translation2d
from drivekin.motor cimport DCMotor, motor_current
from drivekin._core.errors import refuse_delete, type_name

__all__ = ["ModuleConfig", "RobotConfig"]


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


# settings.json as the GUI writes it is a few KB, one object of numbers and strings: larger
# files and deeper nesting are refused before json sees them (its parser recurses).
cdef Py_ssize_t GUI_MAX_BYTES = 1 << 20
cdef Py_ssize_t GUI_MAX_DEPTH = 64


cdef str settings_path(object path):
    """The path as text for messages; only str and os.PathLike are paths (an int would be
    taken by open() as a file descriptor, read and closed)."""
    import os
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be a str or os.PathLike naming PathPlanner's "
                        f"settings.json, got {type_name(path)}")
    return os.fsdecode(os.fspath(path))


cdef bytes read_settings(object path, str name):
    """The file's bytes: a regular file (checked before opening, and again on the open
    descriptor), opened without blocking, at most GUI_MAX_BYTES, nested at most
    GUI_MAX_DEPTH deep."""
    import os
    import stat
    cdef bytes data
    cdef int fd = -1
    try:
        if not stat.S_ISREG(os.stat(path).st_mode):
            raise ValueError(f"PathPlanner settings {name!r} is not a regular file")
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0)
                     | getattr(os, "O_BINARY", 0) | getattr(os, "O_CLOEXEC", 0))
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise ValueError(f"PathPlanner settings {name!r} is not a regular file")
        if st.st_size > GUI_MAX_BYTES:
            raise ValueError(f"PathPlanner settings {name!r} is {st.st_size} bytes, more "
                             f"than the {GUI_MAX_BYTES} this reader accepts")
        chunks = []
        size = 0
        while size <= GUI_MAX_BYTES:
            chunk = os.read(fd, GUI_MAX_BYTES + 1 - size)
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
    except OSError as e:
        raise ValueError(f"cannot read PathPlanner settings {name!r}: {e}") from None
    finally:
        if fd >= 0:
            os.close(fd)
    if size > GUI_MAX_BYTES:            # it grew after the fstat
        raise ValueError(f"PathPlanner settings {name!r} is more than {GUI_MAX_BYTES} "
                         f"bytes, the most this reader accepts")
    data = b"".join(chunks)
    if json_depth(data) > GUI_MAX_DEPTH:
        raise ValueError(f"PathPlanner settings {name!r} nests arrays or objects more than "
                         f"{GUI_MAX_DEPTH} deep; it is not the GUI's settings.json")
    return data


cdef Py_ssize_t json_depth(bytes data):
    """The deepest nesting of [ and { outside strings (one pass, no recursion); stops
    counting past GUI_MAX_DEPTH."""
    cdef const unsigned char* p = data
    cdef Py_ssize_t i, n = len(data), depth = 0, deepest = 0
    cdef bint in_string = False, escaped = False
    cdef unsigned char c
    for i in range(n):
        c = p[i]
        if in_string:
            if escaped:
                escaped = False
            elif c == 92:               # backslash
                escaped = True
            elif c == 34:               # closing quote
                in_string = False
        elif c == 34:
            in_string = True
        elif c == 91 or c == 123:       # [ {
            depth += 1
            if depth > deepest:
                deepest = depth
                if deepest > GUI_MAX_DEPTH:
                    break
        elif c == 93 or c == 125:       # ] }
            depth -= 1
    return deepest


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
        # The setpoint generator's feedforwards are mass and MOI times accelerations: 1e308
        # made them infinite.
        if not (massKG <= 1e100 and MOI <= 1e100):
            raise ValueError(f"{'massKG' if massKG > 1e100 else 'MOI'} must be at most 1e100 "
                             f"(kg, kg·m²), got {massKG if massKG > 1e100 else MOI!r}")
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
        robot project) at ``path`` (a str or os.PathLike; TypeError otherwise) into a
        RobotConfig: mass, MOI, wheel radius, gearing, top speed, wheel COF, drive motor
        type and current limit, and the four module positions. A file that is not a
        swerve (holonomic) robot's settings, lacks a key or holds a value of the wrong
        kind (a number must be finite as a float) raises ValueError naming it. So does a
        path that is not a regular file (a FIFO or a device is not opened), a file larger
        than 1 MiB (the GUI writes a few KB) or JSON nested deeper than 64 levels."""
        import json
        from drivekin.motor import DCMotor as Motor
        cdef str name = settings_path(path)
        cdef bytes data = read_settings(path, name)
        try:
            settings = json.loads(data)
        except (UnicodeDecodeError, ValueError) as e:
            raise ValueError(f"cannot read PathPlanner settings {name!r}: {e}") from None
        if type(settings) is not dict:
            raise ValueError(f"{name!r} is not PathPlanner settings (a JSON object)")

        def get(key, kinds):
            if key not in settings:
                raise ValueError(f"{name!r} has no {key!r}; is it PathPlanner's "
                                 f"settings.json?")
            v = settings[key]
            if type(v) not in kinds:
                raise ValueError(f"{key!r} in {name!r} must be a "
                                 f"{' or '.join(k.__name__ for k in kinds)}, got {v!r}")
            return v

        def number(key):
            v = get(key, (int, float))
            try:
                x = float(v)
            except OverflowError:           # an int beyond the largest float
                raise ValueError(f"{key!r} in {name!r} must be a finite number, got an "
                                 f"integer of {len(str(v))} digits") from None
            if not isfinite(x):             # 1e400 and JSON's Infinity and NaN
                raise ValueError(f"{key!r} in {name!r} must be a finite number, got {v!r}")
            return x

        if not get("holonomicMode", (bool,)):
            raise ValueError(f"{name!r} describes a differential drive "
                             f"(holonomicMode false); the swerve setpoint generator needs "
                             f"a swerve robot's settings")
        num = {k: number(k) for k in _GUI_NUMBERS}
        motor_type = get("driveMotorType", (str,))
        if motor_type not in _GUI_MOTORS:
            raise ValueError(f"driveMotorType {motor_type!r} in {name!r} is not one of "
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
