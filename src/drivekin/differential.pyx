"""Differential (tank) drive kinematics, WPILib 2027.

Units: m, m/s, m/s², rad, rad/s, rad/s². The model is the same as Road Runner's
``TankKinematics``: v_left = vx − ω·W/2, v_right = vx + ω·W/2, with W the trackwidth.
"""
cimport cython
from drivekin._core.drivetrain cimport Drivetrain
from libc.math cimport isfinite

from drivekin._core.args cimport check_type
from drivekin._core.wheels cimport _WheelValues, install_bare_new
from drivekin._core.kernels cimport clamp01, feet_to_meters, wheels_desaturate
from drivekin.geometry cimport new_twist
from drivekin.chassis cimport ChassisAccelerations, ChassisVelocities, new_chassis_velocities
from drivekin._core.errors import type_name


cdef class _Wheel2(_WheelValues):
    """Left and right wheel values."""

    def __init__(self, double left=0.0, double right=0.0):
        self.k = 2
        self.w[0] = left
        self.w[1] = right

    @property
    def left(self):
        """Left wheel value (m/s, m or m/s² depending on the class)."""
        return self.w[0]

    @left.setter
    def left(self, double value):
        self.w[0] = value

    @property
    def right(self):
        """Right wheel value (m/s, m or m/s² depending on the class)."""
        return self.w[1]

    @right.setter
    def right(self, double value):
        self.w[1] = value

    def __repr__(self):
        return f"{type(self).__name__}(left={self.w[0]!r}, right={self.w[1]!r})"


cdef inline _Wheel2 init2(_Wheel2 o, double l, double r):
    o.k = 2
    o.w[0] = l
    o.w[1] = r
    return o


cdef class DifferentialDriveWheelVelocities(_Wheel2):
    """DifferentialDriveWheelVelocities(left=0.0, right=0.0)

    Wheel velocities of a differential drive, m/s. Mutable. As in WPILib Java there is no
    value equality: ``==`` is identity (compare ``left``/``right`` yourself).
    """

    cdef _WheelValues _new(self):
        return init2(DifferentialDriveWheelVelocities.__new__(DifferentialDriveWheelVelocities), 0.0, 0.0)

    @staticmethod
    def fromFeet(double left, double right):
        """Return the wheel velocities given in ft/s, in m/s (the same bits as
        robotpy-wpimath's ``DifferentialDriveWheelSpeeds.fromFeet``)."""
        return init2(DifferentialDriveWheelVelocities.__new__(DifferentialDriveWheelVelocities),
                     feet_to_meters(left), feet_to_meters(right))

    @cython.always_allow_keywords(False)   # METH_O: the 1-argument fast call (~3 ns)
    def desaturate(self, double attainable_max_velocity):
        """Return new velocities scaled so neither wheel exceeds ``attainable_max_velocity``
        (m/s), keeping their ratio; unchanged copy if already within it (2027)."""
        cdef _WheelValues out = init2(DifferentialDriveWheelVelocities.__new__(DifferentialDriveWheelVelocities), 0.0, 0.0)
        wheels_desaturate(2, self.w, attainable_max_velocity, out.w)
        return out

    @cython.always_allow_keywords(False)
    def desaturateInPlace(self, double attainable_max_velocity):
        """Allocation-free :meth:`desaturate`: rescale this object. Returns None."""
        wheels_desaturate(2, self.w, attainable_max_velocity, self.w)

    def interpolate(self, end_value: DifferentialDriveWheelVelocities, double t):
        """Linear interpolation with ``t`` clamped to [0, 1]."""
        check_type(end_value, DifferentialDriveWheelVelocities, "end_value")
        return self._lerp(<_WheelValues>end_value, clamp01(t))

    def __str__(self):
        return self._fmt(("Left", "Right"), "m/s")


cdef class DifferentialDriveWheelPositions(_Wheel2):
    """DifferentialDriveWheelPositions(left, right)

    Distances driven by the left and right wheels, m. Mutable; ``==`` compares each
    wheel within 1e-9 m (so instances are unhashable).
    """

    def __init__(self, double left, double right):
        init2(self, left, right)

    cdef _WheelValues _new(self):
        return init2(DifferentialDriveWheelPositions.__new__(DifferentialDriveWheelPositions), 0.0, 0.0)

    def copy(self):
        """Return an independent copy."""
        return init2(self._new(), self.w[0], self.w[1])

    def interpolate(self, end_value: DifferentialDriveWheelPositions, double t):
        """Linear interpolation; ``t`` is not clamped."""
        check_type(end_value, DifferentialDriveWheelPositions, "end_value")
        return self._lerp(<_WheelValues>end_value, t)

    def __eq__(self, other):
        if type(other) is DifferentialDriveWheelPositions:
            return self._close(<_WheelValues>other)
        return NotImplemented

    __hash__ = None

    def __str__(self):
        # WPILib's toString lacks the closing parenthesis; drivekin closes it.
        return self._fmt(("Left", "Right"), "m")


cdef class DifferentialDriveWheelAccelerations(_Wheel2):
    """DifferentialDriveWheelAccelerations(left=0.0, right=0.0)

    Wheel accelerations of a differential drive, m/s². Mutable; ``==`` compares every wheel
    exactly (WPILib C++'s and robotpy's ``==``; Java has no ``equals``), so instances are
    unhashable.
    """

    cdef _WheelValues _new(self):
        return init2(DifferentialDriveWheelAccelerations.__new__(DifferentialDriveWheelAccelerations), 0.0, 0.0)

    def interpolate(self, end_value: DifferentialDriveWheelAccelerations, double t):
        """Linear interpolation with ``t`` clamped to [0, 1]."""
        check_type(end_value, DifferentialDriveWheelAccelerations, "end_value")
        return self._lerp(<_WheelValues>end_value, clamp01(t))

    def __eq__(self, other):
        if type(other) is DifferentialDriveWheelAccelerations:
            return self._equal(<_WheelValues>other)
        return NotImplemented

    __hash__ = None

    def __str__(self):
        return self._fmt(("Left", "Right"), "m/s²")


cdef inline DifferentialDriveWheelVelocities new_wheel_velocities(double l, double r):
    return <DifferentialDriveWheelVelocities>init2(
        DifferentialDriveWheelVelocities.__new__(DifferentialDriveWheelVelocities), l, r)


# ---------------------------------------------------------------------------------------
cdef inline void twists(double trackwidth, Py_ssize_t k, const double* d, const double* dth,
                        double* out) noexcept nogil:
    # The drivetrain contract's _twists: d[i] left, d[k + i] right.
    cdef Py_ssize_t i
    for i in range(k):
        out[i] = (d[i] + d[k + i]) / 2.0
        out[k + i] = 0.0
        if dth == NULL:
            out[2 * k + i] = (d[k + i] - d[i]) / trackwidth


cdef class DifferentialDriveKinematics(Drivetrain):
    """DifferentialDriveKinematics(trackwidth)

    Kinematics of a differential drive whose left and right wheels are ``trackwidth`` m
    apart (use the effective, empirically tuned value if the wheels scrub). The
    trackwidth must be positive and finite (ValueError otherwise).
    """

    def __init__(self, double trackwidth):
        if self._trackwidth != 0.0:
            raise TypeError("DifferentialDriveKinematics is already initialised (its "
                            "trackwidth is read-only): __init__ cannot be called again")
        if not (isfinite(trackwidth) and trackwidth > 0.0):
            raise ValueError(f"trackwidth must be a positive finite distance in m, got {trackwidth!r}")
        self.nwheels = 2
        self._trackwidth = trackwidth

    cdef int _ready(self) except -1:
        # 0 is what a bare __new__ leaves; __init__ admits only positive finite values.
        if self._trackwidth == 0.0:
            raise RuntimeError("DifferentialDriveKinematics.__init__ has not completed")
        return 0

    # -----------------------------------------------------------------------------------
    # The drivetrain contract (drivekin._core.drivetrain): [left, right] wheels

    cdef Py_ssize_t _params(self, double* params, bint forward, bint accel) noexcept:
        if params != NULL:
            params[0] = self._trackwidth
        return 1

    cdef void _inverse_many(self, Py_ssize_t k, const double* chassis, const double* omega,
                            bint accel, double* params,
                            double* m, double* c, double* s) noexcept nogil:
        cdef Py_ssize_t i
        cdef double half = params[0] / 2.0
        cdef const double* x
        for i in range(k):
            x = chassis + 3 * i
            m[2 * i] = x[0] - half * x[2]
            m[2 * i + 1] = x[0] + half * x[2]

    cdef void _forward_many(self, Py_ssize_t k, const double* m, const double* c,
                            const double* s, const double* gyro, bint accel,
                            const double* params, double* out) noexcept nogil:
        cdef Py_ssize_t i
        cdef double tw = params[0]
        cdef const double* x
        for i in range(k):
            x = m + 2 * i
            out[3 * i] = (x[0] + x[1]) / 2.0
            out[3 * i + 1] = 0.0
            out[3 * i + 2] = (x[1] - x[0]) / tw

    cdef void _twists(self, Py_ssize_t k, const double* d, const double* c, const double* s,
                      const double* dth, double* out) noexcept nogil:
        twists(self._trackwidth, k, d, dth, out)

    cdef void _twist(self, const double* d, const double* c, const double* s,
                     const double* dth, double* out) noexcept nogil:
        twists(self._trackwidth, 1, d, dth, out)

    @property
    def trackwidth(self):
        """Distance between the left and right wheels, m (read-only)."""
        return self._trackwidth

    def __reduce__(self):
        self._ready()
        return (DifferentialDriveKinematics, (self._trackwidth,))

    def __repr__(self):
        return f"DifferentialDriveKinematics(trackwidth={self._trackwidth!r})"

    def toChassisVelocities(self, wheel_velocities: DifferentialDriveWheelVelocities):
        """Return the robot velocity: vx = (left + right) / 2, vy = 0,
        omega = (right − left) / trackwidth."""
        check_type(wheel_velocities, DifferentialDriveWheelVelocities, "wheel_velocities")
        self._ready()
        cdef _WheelValues w = <_WheelValues>wheel_velocities
        return new_chassis_velocities((w.w[0] + w.w[1]) / 2.0, 0.0,
                                      (w.w[1] - w.w[0]) / self._trackwidth)

    def toChassisVelocitiesInto(self, wheel_velocities: DifferentialDriveWheelVelocities,
                                out: ChassisVelocities):
        """Allocation-free :meth:`toChassisVelocities`: write into ``out``. Returns None."""
        check_type(wheel_velocities, DifferentialDriveWheelVelocities, "wheel_velocities")
        check_type(out, ChassisVelocities, "out")
        self._ready()
        cdef _WheelValues w = <_WheelValues>wheel_velocities
        (<ChassisVelocities>out).v.x = (w.w[0] + w.w[1]) / 2.0
        (<ChassisVelocities>out).v.y = 0.0
        (<ChassisVelocities>out).v.z = (w.w[1] - w.w[0]) / self._trackwidth

    def toWheelVelocities(self, chassis_velocities: ChassisVelocities):
        """Return the wheel velocities for a robot velocity; ``vy`` is ignored (a
        differential drive cannot strafe)."""
        check_type(chassis_velocities, ChassisVelocities, "chassis_velocities")
        self._ready()
        cdef ChassisVelocities c = <ChassisVelocities>chassis_velocities
        return new_wheel_velocities(c.v.x - self._trackwidth / 2.0 * c.v.z,
                                    c.v.x + self._trackwidth / 2.0 * c.v.z)

    def toWheelVelocitiesInto(self, chassis_velocities: ChassisVelocities,
                              out: DifferentialDriveWheelVelocities):
        """Allocation-free :meth:`toWheelVelocities`: write into ``out``. Returns None."""
        check_type(chassis_velocities, ChassisVelocities, "chassis_velocities")
        check_type(out, DifferentialDriveWheelVelocities, "out")
        self._ready()
        cdef ChassisVelocities c = <ChassisVelocities>chassis_velocities
        cdef _WheelValues o = <_WheelValues>out
        o.w[0] = c.v.x - self._trackwidth / 2.0 * c.v.z
        o.w[1] = c.v.x + self._trackwidth / 2.0 * c.v.z

    def toTwist2d(self, start, end):
        """toTwist2d(left_distance, right_distance) or toTwist2d(start, end)

        Return the Twist2d (m, rad) for wheel distance changes: dx = (l + r) / 2, dy = 0,
        dtheta = (r − l) / trackwidth. With two DifferentialDriveWheelPositions the
        changes are end − start."""
        self._ready()
        cdef double l, r
        if type(start) is DifferentialDriveWheelPositions or type(end) is DifferentialDriveWheelPositions:
            if type(start) is not type(end):
                raise TypeError("toTwist2d takes two DifferentialDriveWheelPositions or two "
                                f"distances, got {type_name(start)} and {type_name(end)}")
            l = (<_WheelValues>end).w[0] - (<_WheelValues>start).w[0]
            r = (<_WheelValues>end).w[1] - (<_WheelValues>start).w[1]
        else:
            try:
                l = start
                r = end
            except TypeError:
                raise TypeError("toTwist2d takes two DifferentialDriveWheelPositions or two "
                                f"distances in m, got {type_name(start)} and "
                                f"{type_name(end)}") from None
        return new_twist((l + r) / 2.0, 0.0, (r - l) / self._trackwidth)

    def toChassisAccelerations(self, wheel_accelerations: DifferentialDriveWheelAccelerations):
        """Return (ax = (l + r) / 2, ay = 0, alpha = (r − l) / trackwidth), m/s² and rad/s²."""
        check_type(wheel_accelerations, DifferentialDriveWheelAccelerations,
                   "wheel_accelerations")
        self._ready()
        cdef _WheelValues w = <_WheelValues>wheel_accelerations
        return ChassisAccelerations((w.w[0] + w.w[1]) / 2.0, 0.0,
                                    (w.w[1] - w.w[0]) / self._trackwidth)

    def toWheelAccelerations(self, chassis_accelerations: ChassisAccelerations):
        """Return the wheel accelerations (ax ∓ trackwidth/2 · alpha); ``ay`` is ignored."""
        check_type(chassis_accelerations, ChassisAccelerations, "chassis_accelerations")
        self._ready()
        cdef ChassisAccelerations c = <ChassisAccelerations>chassis_accelerations
        return DifferentialDriveWheelAccelerations(c.v.x - self._trackwidth / 2.0 * c.v.z,
                                                   c.v.x + self._trackwidth / 2.0 * c.v.z)

    def interpolate(self, start: DifferentialDriveWheelPositions,
                    end: DifferentialDriveWheelPositions, double t):
        """Return ``start.interpolate(end, t)`` (not clamped)."""
        check_type(start, DifferentialDriveWheelPositions, "start")
        check_type(end, DifferentialDriveWheelPositions, "end")
        self._ready()
        return start.interpolate(end, t)

    def copy(self, positions: DifferentialDriveWheelPositions):
        """Return an independent copy of ``positions``."""
        check_type(positions, DifferentialDriveWheelPositions, "positions")
        self._ready()
        return positions.copy()

    def copyInto(self, positions: DifferentialDriveWheelPositions,
                 output: DifferentialDriveWheelPositions):
        """Copy ``positions`` into ``output``."""
        check_type(positions, DifferentialDriveWheelPositions, "positions")
        check_type(output, DifferentialDriveWheelPositions, "output")
        self._ready()
        (<_WheelValues>output).w[0] = (<_WheelValues>positions).w[0]
        (<_WheelValues>output).w[1] = (<_WheelValues>positions).w[1]


install_bare_new((DifferentialDriveWheelVelocities, DifferentialDriveWheelPositions,
                  DifferentialDriveWheelAccelerations), 2)
