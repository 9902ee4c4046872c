"""Differential swerve modules: two motors drive each pod through a differential.

Model (R = motor turns per output turn, so a ratio of 3 means the motor turns three times
per pod turn)::

    R_A · ω_pod   = ω_m1 + ω_m2          (the sum of the motors turns the pod)
    R_L · ω_wheel = ω_m1 − ω_m2          (their difference spins the wheel)
    ω_wheel       = v / r                (v: wheel ground speed, r: wheel radius)

With ``motor2_inverted=True`` motor 2 is mounted reversed: what it reads and what it is
commanded is −ω_m2. Units: m, m/s, rad, rad/s. The same linear map converts motor
position changes (rad) into the pod's rotation (rad) and the wheel's travel (m), so
integrating the velocity map and converting the integrated motor positions agree to
rounding (quail's ``calculateModuleAngle`` does not: it is off by a factor 2·R_s²).
"""
cimport cython
cimport numpy as cnp
from cpython.float cimport PyFloat_AsDouble
from cpython.mem cimport PyMem_Free, PyMem_Malloc
from cpython.ref cimport PyObject
from cpython.sequence cimport PySequence_Fast_GET_SIZE, PySequence_Fast_ITEMS
from libc.math cimport isfinite
from drivekin._core.dkmath cimport atan2

from drivekin._core.types cimport rot2_t
from drivekin._core.wheels cimport _WheelValues, install_bare_new
from drivekin._core.args cimport (as_fast, check_type, float64_data, is_array,
                                   positive_finite)
from drivekin._core.kernels cimport (clamp01, dswerve_desaturate, dswerve_drive_factor,
                                     dswerve_module, dswerve_motors, rot_rad)
from drivekin.geometry cimport Rotation2d, new_rotation
from drivekin.swervemodule cimport (SwerveModulePosition, SwerveModuleVelocity, _ModuleVector,
                                    new_module_position)
from drivekin._core.errors import type_name
from drivekin._core.format import f2

cnp.import_array()

# Module counts up to this are read into stack memory by the drive-level desaturation.
cdef enum:
    STACK_MODULES = 16


# ---------------------------------------------------------------------------------------
# Values

cdef inline DifferentialSwerveMotorVelocities new_motors(double m1, double m2):
    cdef DifferentialSwerveMotorVelocities o = \
        DifferentialSwerveMotorVelocities.__new__(DifferentialSwerveMotorVelocities)
    o.k = 2
    o.w[0] = m1
    o.w[1] = m2
    return o


cdef inline DifferentialSwerveModuleVelocities new_module_velocities(double v, double w):
    cdef DifferentialSwerveModuleVelocities o = \
        DifferentialSwerveModuleVelocities.__new__(DifferentialSwerveModuleVelocities)
    o.k = 2
    o.w[0] = v
    o.w[1] = w
    return o


cdef class DifferentialSwerveMotorVelocities(_WheelValues):
    """DifferentialSwerveMotorVelocities(motor1=0.0, motor2=0.0)

    The angular velocities of a differential swerve pod's two motors, rad/s, as each
    motor reads them (a reversed motor 2, ``motor2_inverted=True``, reads −ω_m2).
    Mutable; ``==`` compares each motor within 1e-9 rad/s (so instances are unhashable);
    unpacks as ``motor1, motor2 = velocities``.
    """

    def __init__(self, double motor1=0.0, double motor2=0.0):
        self.k = 2
        self.w[0] = motor1
        self.w[1] = motor2

    cdef _WheelValues _new(self):
        return new_motors(0.0, 0.0)

    @property
    def motor1(self):
        """Motor 1 angular velocity, rad/s."""
        return self.w[0]

    @motor1.setter
    def motor1(self, double value):
        self.w[0] = value

    @property
    def motor2(self):
        """Motor 2 angular velocity, rad/s (as motor 2 reads it)."""
        return self.w[1]

    @motor2.setter
    def motor2(self, double value):
        self.w[1] = value

    def interpolate(self, end_value: DifferentialSwerveMotorVelocities, double t):
        """Linear interpolation with ``t`` clamped to [0, 1]."""
        check_type(end_value, DifferentialSwerveMotorVelocities, "end_value")
        return self._lerp(<_WheelValues>end_value, clamp01(t))

    def __eq__(self, other):
        if type(other) is DifferentialSwerveMotorVelocities:
            return self._close(<_WheelValues>other)
        return NotImplemented

    __hash__ = None

    def __repr__(self):
        return f"DifferentialSwerveMotorVelocities(motor1={self.w[0]!r}, motor2={self.w[1]!r})"

    def __str__(self):
        return self._fmt(("Motor 1", "Motor 2"), "rad/s")


cdef class DifferentialSwerveModuleVelocities(_WheelValues):
    """DifferentialSwerveModuleVelocities(wheel_velocity=0.0, azimuth_velocity=0.0)

    The motion of one differential swerve pod: the wheel's ground speed ``wheel_velocity``
    in m/s and the pod's steering rate ``azimuth_velocity`` in rad/s (counter-clockwise
    positive). Mutable; ``==`` compares each field within 1e-9 (so instances are
    unhashable); unpacks as ``wheel_velocity, azimuth_velocity = velocities``.
    """

    def __init__(self, double wheel_velocity=0.0, double azimuth_velocity=0.0):
        self.k = 2
        self.w[0] = wheel_velocity
        self.w[1] = azimuth_velocity

    cdef _WheelValues _new(self):
        return new_module_velocities(0.0, 0.0)

    @property
    def wheelVelocity(self):
        """Wheel ground speed, m/s."""
        return self.w[0]

    @wheelVelocity.setter
    def wheelVelocity(self, double value):
        self.w[0] = value

    @property
    def azimuthVelocity(self):
        """Pod steering rate, rad/s (counter-clockwise positive)."""
        return self.w[1]

    @azimuthVelocity.setter
    def azimuthVelocity(self, double value):
        self.w[1] = value

    def interpolate(self, end_value: DifferentialSwerveModuleVelocities, double t):
        """Linear interpolation with ``t`` clamped to [0, 1]."""
        check_type(end_value, DifferentialSwerveModuleVelocities, "end_value")
        return self._lerp(<_WheelValues>end_value, clamp01(t))

    def __eq__(self, other):
        if type(other) is DifferentialSwerveModuleVelocities:
            return self._close(<_WheelValues>other)
        return NotImplemented

    __hash__ = None

    def __repr__(self):
        return (f"DifferentialSwerveModuleVelocities(wheel_velocity={self.w[0]!r}, "
                f"azimuth_velocity={self.w[1]!r})")

    def __str__(self):
        return (f"DifferentialSwerveModuleVelocities(Wheel: {f2(self.w[0])} m/s, "
                f"Azimuth: {f2(self.w[1])} rad/s)")


# ---------------------------------------------------------------------------------------
# Argument helpers

cdef int check_limit(double limit) except -1:
    if not limit >= 0.0:       # NaN fails too
        raise ValueError("max_motor_velocity must be a non-negative motor velocity in rad/s "
                         f"(inf: no limit), got {limit!r}")
    return 0


cdef bint flag(object x, str name) except -1:
    if x is True:
        return True
    if x is False:
        return False
    raise TypeError(f"{name} must be a bool, got {type_name(x)}")


cdef int uninitialised() except -1:
    raise RuntimeError("DifferentialSwerveModuleKinematics.__init__ has not completed")


cdef Py_ssize_t read_rates(object rates, double* stack, double** buf) except -1:
    """Read the pods' steering rates (a sequence of numbers or a float64 (N,) array) into
    C memory: ``buf[0]`` becomes ``stack`` (room for STACK_MODULES) or a PyMem block of
    2·N doubles (the caller frees it when it is not ``stack``); the upper half is scratch
    for the wheel speeds. Returns N.

    Reading a number may run Python code (``__float__``) that mutates the sequence, so
    each item is held by a strong reference while it is converted and the size is
    checked on every step: nothing borrowed survives a conversion."""
    cdef Py_ssize_t i, n
    cdef const double* d = NULL
    cdef object fast, x
    if is_array(rates):
        d = float64_data(rates, -1, 0, False, "azimuth_velocities")
        n = cnp.PyArray_DIM(<cnp.ndarray>rates, 0)
        fast = None
    else:
        fast = as_fast(rates, "azimuth_velocities", "a sequence or a float64 numpy array", "",
                       True)
        n = PySequence_Fast_GET_SIZE(fast)
    if n > STACK_MODULES:
        buf[0] = <double*>PyMem_Malloc(sizeof(double) * 2 * n)
        if buf[0] == NULL:
            raise MemoryError()
    if fast is None:
        for i in range(n):
            buf[0][i] = d[i]
        return n
    for i in range(n):
        if PySequence_Fast_GET_SIZE(fast) != n:
            raise ValueError("azimuth_velocities changed size while it was being read")
        x = <object>PySequence_Fast_ITEMS(fast)[i]
        if type(x) is float:
            buf[0][i] = <double>x
            continue
        try:
            buf[0][i] = PyFloat_AsDouble(x)
        except TypeError:
            raise TypeError(f"azimuth_velocities[{i}] must be a number (rad/s), "
                            f"got {type_name(x)}") from None
    if PySequence_Fast_GET_SIZE(fast) != n:
        raise ValueError("azimuth_velocities changed size while it was being read")
    return n


# ---------------------------------------------------------------------------------------
# Kinematics

def _restore(azimuth_gear_ratio, wheel_gear_ratio, wheel_radius, motor2_inverted):
    """Unpickling helper: the constructor with ``motor2_inverted`` passed by keyword."""
    return DifferentialSwerveModuleKinematics(azimuth_gear_ratio, wheel_gear_ratio, wheel_radius,
                                              motor2_inverted=motor2_inverted)


cdef class DifferentialSwerveModuleKinematics:
    """``DifferentialSwerveModuleKinematics(azimuth_gear_ratio, wheel_gear_ratio, wheel_radius, *, motor2_inverted=False)``

    Kinematics of one differential swerve pod (quail's model, made consistent):
    ``R_A·ω_pod = ω_m1 + ω_m2`` and ``R_L·ω_wheel = ω_m1 − ω_m2`` with ``ω_wheel = v / r``.

    ``azimuth_gear_ratio`` R_A and ``wheel_gear_ratio`` R_L are motor turns per output turn
    (pod turn, wheel turn); quail's ``R_s``/``R_d`` are output per motor turn, i.e.
    R_A = 1/R_s and R_L = 1/R_d. ``wheel_radius`` r is in m. All three must be positive and
    finite (ValueError naming the argument otherwise). ``motor2_inverted=True`` means
    motor 2 is mounted reversed: every motor-2 value this class takes or returns (velocity
    or position) is the negative of the ω_m2 in the equations.

    Motor velocities are rad/s and motor positions rad, as the motors' own encoders
    report them (convert from rotations or RPM first). The object also remembers the
    offset set by :meth:`resetModulePosition` (pod angle 0 and motor positions 0 until
    the first reset); it is not thread-safe against a concurrent reset, like WPILib's
    kinematics classes.
    """

    def __init__(self, double azimuth_gear_ratio, double wheel_gear_ratio,
                 double wheel_radius, *, motor2_inverted=False):
        cdef dswerve_t g
        if self.g.ra != 0.0:
            raise TypeError("DifferentialSwerveModuleKinematics is already initialised (its "
                            "geometry is read-only): __init__ cannot be called again")
        positive_finite(azimuth_gear_ratio, "azimuth_gear_ratio",
                        "ratio (motor turns per pod turn)")
        positive_finite(wheel_gear_ratio, "wheel_gear_ratio",
                        "ratio (motor turns per wheel turn)")
        positive_finite(wheel_radius, "wheel_radius", "radius in m")
        g.s2 = -1.0 if flag(motor2_inverted, "motor2_inverted") else 1.0
        g.kv = wheel_gear_ratio / wheel_radius
        if not (isfinite(g.kv) and g.kv > 0.0):
            raise ValueError("wheel_gear_ratio / wheel_radius (motor rad per m of wheel travel) "
                             f"must be positive and finite, got {g.kv!r}")
        g.ra = azimuth_gear_ratio
        # The inverse map multiplies by these (a division would cost ~4 ns per call).
        g.ira = 1.0 / g.ra
        g.ikv = 1.0 / g.kv
        if not (isfinite(g.ira) and isfinite(g.ikv) and g.ikv > 0.0):
            raise ValueError("azimuth_gear_ratio and wheel_gear_ratio / wheel_radius must have "
                             f"finite non-zero reciprocals, got {g.ra!r} and {g.kv!r}")
        g.rl = wheel_gear_ratio
        g.r = wheel_radius
        self.p1 = 0.0
        self.p2 = 0.0
        self.r0.c = 1.0
        self.r0.s = 0.0
        self.a0 = 0.0
        self.g = g                    # g.ra != 0 marks the object initialised

    cdef int _ready(self) except -1:
        if self.g.ra == 0.0:
            uninitialised()
        return 0

    @property
    def azimuthGearRatio(self):
        """R_A: motor turns per pod (azimuth) turn (read-only)."""
        return self.g.ra

    @property
    def wheelGearRatio(self):
        """R_L: motor turns per wheel turn (read-only)."""
        return self.g.rl

    @property
    def wheelRadius(self):
        """Wheel radius, m (read-only)."""
        return self.g.r

    @property
    def motor2Inverted(self):
        """True if motor 2 is mounted reversed (read-only)."""
        return self.g.s2 < 0.0

    def __repr__(self):
        return (f"DifferentialSwerveModuleKinematics(azimuth_gear_ratio={self.g.ra!r}, "
                f"wheel_gear_ratio={self.g.rl!r}, wheel_radius={self.g.r!r}, "
                f"motor2_inverted={self.g.s2 < 0.0!r})")

    def __reduce__(self):
        self._ready()
        return (_restore, (self.g.ra, self.g.rl, self.g.r, self.g.s2 < 0.0),
                (new_rotation(self.r0), self.p1, self.p2))

    def __setstate__(self, state):
        """Restore the offset of :meth:`resetModulePosition` from a pickle:
        ``(angle Rotation2d, motor1_position rad, motor2_position rad)``."""
        cdef double p1, p2
        self._ready()
        if type(state) is not tuple or len(state) != 3:
            raise TypeError("state must be a tuple (Rotation2d, motor1_position, "
                            f"motor2_position), got {type_name(state)}")
        angle = state[0]
        if type(angle) is not Rotation2d:
            raise TypeError(f"state[0] must be a Rotation2d, got {type_name(angle)}")
        if type(state[1]) is not float or type(state[2]) is not float:
            raise TypeError("state[1] and state[2] must be floats (motor positions in rad)")
        p1 = state[1]
        p2 = state[2]
        self._set_offset((<Rotation2d>angle).r, p1, p2)

    cdef int _set_offset(self, rot2_t r, double p1, double p2) except -1:
        if not (isfinite(p1) and isfinite(p2)):
            raise ValueError("motor positions must be finite (rad), got "
                             f"{p1!r} and {p2!r}")
        self.r0 = r
        self.a0 = atan2(r.s, r.c)
        self.p1 = p1
        self.p2 = p2
        return 0

    # -- velocities -------------------------------------------------------------------

    def toMotorVelocities(self, double wheel_velocity, double azimuth_velocity):
        """Return the motor velocities (DifferentialSwerveMotorVelocities, rad/s) that
        drive the wheel at ``wheel_velocity`` m/s while the pod turns at
        ``azimuth_velocity`` rad/s: ω_m1 = (R_A·ω_pod + R_L·v/r)/2,
        ω_m2 = (R_A·ω_pod − R_L·v/r)/2 (negated when motor 2 is inverted)."""
        cdef double m1, m2
        if self.g.ra == 0.0:
            uninitialised()
        dswerve_motors(&self.g, wheel_velocity, azimuth_velocity, &m1, &m2)
        return new_motors(m1, m2)

    def toMotorVelocitiesInto(self, double wheel_velocity, double azimuth_velocity,
                              out: DifferentialSwerveMotorVelocities):
        """Allocation-free :meth:`toMotorVelocities`: write into ``out``. Returns None."""
        check_type(out, DifferentialSwerveMotorVelocities, "out")
        if self.g.ra == 0.0:
            uninitialised()
        cdef double* w = (<_WheelValues>out).w
        dswerve_motors(&self.g, wheel_velocity, azimuth_velocity, &w[0], &w[1])

    def toModuleVelocities(self, double motor1, double motor2):
        """Return the pod's motion (DifferentialSwerveModuleVelocities: wheel m/s,
        steering rad/s) for motor velocities ``motor1``, ``motor2`` in rad/s, the exact
        inverse of :meth:`toMotorVelocities`: ω_pod = (ω_m1 + ω_m2)/R_A,
        v = r·(ω_m1 − ω_m2)/R_L."""
        cdef double v, w
        if self.g.ra == 0.0:
            uninitialised()
        dswerve_module(&self.g, motor1, motor2, &v, &w)
        return new_module_velocities(v, w)

    def toModuleVelocitiesInto(self, double motor1, double motor2,
                               out: DifferentialSwerveModuleVelocities):
        """Allocation-free :meth:`toModuleVelocities`: write into ``out``. Returns None."""
        check_type(out, DifferentialSwerveModuleVelocities, "out")
        if self.g.ra == 0.0:
            uninitialised()
        cdef double* w = (<_WheelValues>out).w
        dswerve_module(&self.g, motor1, motor2, &w[0], &w[1])

    # -- positions --------------------------------------------------------------------

    def resetModulePosition(self, angle: Rotation2d, double motor1_position,
                            double motor2_position):
        """Declare that the pod points at ``angle`` while the motors read
        ``motor1_position`` and ``motor2_position`` (rad, finite; ValueError otherwise):
        :meth:`toModulePosition` measures from here. Call it once the pod's absolute
        angle is known (e.g. from an absolute encoder at start-up). Returns None."""
        check_type(angle, Rotation2d, "angle")
        self._ready()
        self._set_offset((<Rotation2d>angle).r, motor1_position, motor2_position)

    def toModulePosition(self, double motor1_position, double motor2_position):
        """Return the SwerveModulePosition for the motors' positions (rad): the distance
        (m) the wheel has rolled since the last :meth:`resetModulePosition` and the pod
        angle = reset angle + (Δθ_m1 + Δθ_m2)/R_A. Before any reset the offset is zero
        (angle 0 and distance 0 at motor positions 0). Feed the results to
        SwerveDriveOdometry as the module positions."""
        cdef double d, dtheta
        if self.g.ra == 0.0:
            uninitialised()
        # Position changes map exactly as velocities do: the same kernel.
        dswerve_module(&self.g, motor1_position - self.p1, motor2_position - self.p2,
                       &d, &dtheta)
        return new_module_position(d, rot_rad(self.a0 + dtheta))

    def toModulePositionInto(self, double motor1_position, double motor2_position,
                             out: SwerveModulePosition):
        """Allocation-free :meth:`toModulePosition`: write into ``out``. Returns None."""
        cdef double d, dtheta
        check_type(out, SwerveModulePosition, "out")
        if self.g.ra == 0.0:
            uninitialised()
        dswerve_module(&self.g, motor1_position - self.p1, motor2_position - self.p2,
                       &d, &dtheta)
        (<_ModuleVector>out).m = d
        (<_ModuleVector>out).a = rot_rad(self.a0 + dtheta)

    # -- desaturation -----------------------------------------------------------------

    def desaturateMotorVelocities(self, motor_velocities: DifferentialSwerveMotorVelocities,
                                  double max_motor_velocity, *, proportional=False):
        """Return new motor velocities each of magnitude at most ``max_motor_velocity`` (rad/s,
        ≥ 0; ValueError if negative or NaN; inf means no limit).

        By default the pod's steering rate is kept and the wheel speed is reduced first:
        the wheel slows until the faster motor is at the limit, and only when steering
        alone needs more than the limit is the steering rate cut (to the limit, with the
        wheel stopped). The pod then still reaches its commanded angle on time, which
        keeps the robot's path. ``proportional=True`` instead scales both motors by one
        factor (the fastest lands on the limit), which slows steering and wheel alike.
        Velocities already within the limit, or with a NaN motor, are returned unchanged.
        The input is not modified."""
        cdef double o1, o2
        check_type(motor_velocities, DifferentialSwerveMotorVelocities, "motor_velocities")
        cdef bint prop = flag(proportional, "proportional")
        self._ready()
        check_limit(max_motor_velocity)
        dswerve_desaturate(self.g.s2, (<_WheelValues>motor_velocities).w[0],
                           (<_WheelValues>motor_velocities).w[1], max_motor_velocity, prop,
                           &o1, &o2)
        return new_motors(o1, o2)

    def desaturateMotorVelocitiesInPlace(self,
                                         motor_velocities: DifferentialSwerveMotorVelocities,
                                         double max_motor_velocity, *, proportional=False):
        """Allocation-free :meth:`desaturateMotorVelocities` (same rules and keyword):
        rescale ``motor_velocities`` itself. Returns None."""
        check_type(motor_velocities, DifferentialSwerveMotorVelocities, "motor_velocities")
        cdef bint prop = flag(proportional, "proportional")
        self._ready()
        check_limit(max_motor_velocity)
        cdef double* w = (<_WheelValues>motor_velocities).w
        dswerve_desaturate(self.g.s2, w[0], w[1], max_motor_velocity, prop, &w[0], &w[1])

    def desaturateModuleVelocitiesInPlace(self, module_velocities, azimuth_velocities,
                                          double max_motor_velocity):
        """Drive-level desaturation for a swerve drive whose N pods are all built like this
        one: scale every module's wheel velocity by one common factor k in [0, 1], the
        largest for which no pod's motors exceed ``max_motor_velocity`` (rad/s, ≥ 0) while
        pod i steers at ``azimuth_velocities[i]`` rad/s. Because every wheel is scaled
        alike (angles untouched), the chassis keeps its direction of travel and its
        centre of rotation. Returns k (1.0 when nothing needed scaling).

        ``module_velocities`` are the N targets from SwerveDriveKinematics: a list/tuple
        of SwerveModuleVelocity (updated in place) or a float64 (N, 2) array
        ``[velocity m/s, angle rad]`` (column 0 rescaled in place).
        ``azimuth_velocities`` is a sequence of N numbers or a float64 (N,) array.
        Allocation-free for N ≤ 16. Every input is read and checked before anything is
        written, so a failed call changes nothing.

        Steering is never reduced here: if a pod's steering rate alone needs more than the
        limit, k is 0 (all wheels stop) and that pod's motors still exceed it; cut them
        with :meth:`desaturateMotorVelocities` afterwards. A NaN velocity or steering rate
        disables the scaling (k = 1), as a NaN wheel speed does in WPILib's
        desaturation. Up to rounding (a few ulps), the motors of the scaled targets are
        within the limit."""
        cdef double stack[2 * STACK_MODULES]
        cdef double* buf = stack
        cdef double* d
        cdef double k
        cdef Py_ssize_t i, n
        cdef object fast
        cdef PyObject** items
        self._ready()
        check_limit(max_motor_velocity)
        try:
            # Everything that can run Python code (iterating, __float__) happens here,
            # before the destination is looked at.
            n = read_rates(azimuth_velocities, stack, &buf)
            if is_array(module_velocities):
                d = float64_data(module_velocities, -1, 2, True, "module_velocities")
                if cnp.PyArray_DIM(<cnp.ndarray>module_velocities, 0) != n:
                    raise ValueError(
                        "module_velocities has "
                        f"{cnp.PyArray_DIM(<cnp.ndarray>module_velocities, 0)} "
                        f"rows but azimuth_velocities has {n} values (one per module)")
                k = dswerve_drive_factor(&self.g, n, d, 2, buf, max_motor_velocity)
                if k != 1.0:
                    for i in range(n):
                        d[2 * i] = d[2 * i] * k
                return k
            fast = as_fast(module_velocities, "module_velocities",
                           "a sequence or a float64 numpy array", "", True)
            if PySequence_Fast_GET_SIZE(fast) != n:
                raise ValueError(f"module_velocities has {PySequence_Fast_GET_SIZE(fast)} "
                                 f"entries but azimuth_velocities has {n} values (one per "
                                 "module)")
            items = PySequence_Fast_ITEMS(fast)
            # Check, read, decide, write: nothing from here on allocates or runs Python.
            for i in range(n):
                if type(<object>items[i]) is not SwerveModuleVelocity:
                    raise TypeError(f"module_velocities[{i}] must be a SwerveModuleVelocity, "
                                    f"got {type_name(<object>items[i])}")
                buf[n + i] = (<_ModuleVector>items[i]).m
            k = dswerve_drive_factor(&self.g, n, buf + n, 1, buf, max_motor_velocity)
            if k != 1.0:
                for i in range(n):
                    (<_ModuleVector>items[i]).m = buf[n + i] * k
            return k
        finally:
            if buf != stack:
                PyMem_Free(buf)


install_bare_new((DifferentialSwerveMotorVelocities, DifferentialSwerveModuleVelocities), 2)
