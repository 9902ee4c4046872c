"""Mecanum drive kinematics, WPILib 2027.

Units: m, m/s, m/s², rad, rad/s, rad/s². Wheel order everywhere: front left, front right,
rear left, rear right. For a wheel at (x, y) relative to the centre of rotation the
inverse rows are FL/RR ``[1, −1, −(x + y)]`` and FR/RL ``[1, 1, x − y]``.
"""
cimport cython
from drivekin._core.drivetrain cimport Drivetrain
from libc.math cimport isfinite

import numpy as np

from drivekin._core.types cimport vec2_t
from drivekin._core.args cimport check_type
from drivekin._core.wheels cimport _WheelValues, install_bare_new
from drivekin._core.kernels cimport (clamp01, feet_to_meters, mat_vec, mat_vec_step, vec, vec_eq,
                                     wheels_desaturate)
from drivekin.geometry cimport Translation2d, new_twist
from drivekin.chassis cimport ChassisAccelerations, ChassisVelocities, new_chassis_velocities
from drivekin._core.drivetrain import pseudo_inverse
from drivekin._core.errors import type_name

cdef Translation2d ORIGIN = Translation2d()
cdef tuple LABELS = ("Front Left", "Front Right", "Rear Left", "Rear Right")


cdef class _Wheel4(_WheelValues):
    """Front-left, front-right, rear-left and rear-right wheel values."""

    def __init__(self, double front_left=0.0, double front_right=0.0, double rear_left=0.0,
                 double rear_right=0.0):
        self.k = 4
        self.w[0] = front_left
        self.w[1] = front_right
        self.w[2] = rear_left
        self.w[3] = rear_right

    @property
    def frontLeft(self):
        """Front-left wheel value (m/s, m or m/s² depending on the class)."""
        return self.w[0]

    @frontLeft.setter
    def frontLeft(self, double value):
        self.w[0] = value

    @property
    def frontRight(self):
        """Front-right wheel value."""
        return self.w[1]

    @frontRight.setter
    def frontRight(self, double value):
        self.w[1] = value

    @property
    def rearLeft(self):
        """Rear-left wheel value."""
        return self.w[2]

    @rearLeft.setter
    def rearLeft(self, double value):
        self.w[2] = value

    @property
    def rearRight(self):
        """Rear-right wheel value."""
        return self.w[3]

    @rearRight.setter
    def rearRight(self, double value):
        self.w[3] = value

    def __repr__(self):
        return (f"{type(self).__name__}(front_left={self.w[0]!r}, front_right={self.w[1]!r}, "
                f"rear_left={self.w[2]!r}, rear_right={self.w[3]!r})")


cdef inline _Wheel4 blank4(_Wheel4 o):
    o.k = 4
    return o


cdef class MecanumDriveWheelVelocities(_Wheel4):
    """MecanumDriveWheelVelocities(front_left=0.0, front_right=0.0, rear_left=0.0, rear_right=0.0)

    Wheel velocities of a mecanum drive, m/s. Mutable. As in WPILib Java there is no value
    equality: ``==`` is identity.
    """

    cdef _WheelValues _new(self):
        return blank4(MecanumDriveWheelVelocities.__new__(MecanumDriveWheelVelocities))

    @staticmethod
    def fromFeet(double front_left, double front_right, double rear_left, double rear_right):
        """Return the wheel velocities given in ft/s, in m/s (the same bits as
        robotpy-wpimath's ``MecanumDriveWheelSpeeds.fromFeet``)."""
        cdef _WheelValues out = blank4(MecanumDriveWheelVelocities.__new__(MecanumDriveWheelVelocities))
        out.w[0] = feet_to_meters(front_left)
        out.w[1] = feet_to_meters(front_right)
        out.w[2] = feet_to_meters(rear_left)
        out.w[3] = feet_to_meters(rear_right)
        return out

    @cython.always_allow_keywords(False)   # METH_O: the 1-argument fast call (~3 ns)
    def desaturate(self, double attainable_max_velocity):
        """Return new velocities scaled so no wheel exceeds ``attainable_max_velocity`` (m/s),
        keeping their ratios; an unchanged copy if already within it (2027)."""
        cdef _WheelValues out = blank4(MecanumDriveWheelVelocities.__new__(MecanumDriveWheelVelocities))
        wheels_desaturate(4, self.w, attainable_max_velocity, out.w)
        return out

    @cython.always_allow_keywords(False)
    def desaturateInPlace(self, double attainable_max_velocity):
        """Allocation-free :meth:`desaturate`: rescale this object. Returns None."""
        wheels_desaturate(4, self.w, attainable_max_velocity, self.w)

    def interpolate(self, end_value: MecanumDriveWheelVelocities, double t):
        """Linear interpolation with ``t`` clamped to [0, 1]."""
        check_type(end_value, MecanumDriveWheelVelocities, "end_value")
        return self._lerp(<_WheelValues>end_value, clamp01(t))

    def __str__(self):
        return self._fmt(LABELS, "m/s")


cdef class MecanumDriveWheelPositions(_Wheel4):
    """MecanumDriveWheelPositions(front_left=0.0, front_right=0.0, rear_left=0.0, rear_right=0.0)

    Distances driven by each wheel, m. Mutable; ``==`` compares each wheel within 1e-9 m
    (so instances are unhashable).
    """

    cdef _WheelValues _new(self):
        return blank4(MecanumDriveWheelPositions.__new__(MecanumDriveWheelPositions))

    def copy(self):
        """Return an independent copy."""
        cdef _WheelValues o = self._new()
        o.w = self.w
        return o

    def interpolate(self, end_value: MecanumDriveWheelPositions, double t):
        """Linear interpolation; ``t`` is not clamped."""
        check_type(end_value, MecanumDriveWheelPositions, "end_value")
        return self._lerp(<_WheelValues>end_value, t)

    def __eq__(self, other):
        if type(other) is MecanumDriveWheelPositions:
            return self._close(<_WheelValues>other)
        return NotImplemented

    __hash__ = None

    def __str__(self):
        return self._fmt(LABELS, "m")


cdef class MecanumDriveWheelAccelerations(_Wheel4):
    """MecanumDriveWheelAccelerations(front_left=0.0, front_right=0.0, rear_left=0.0, rear_right=0.0)

    Wheel accelerations of a mecanum drive, m/s². Mutable; ``==`` compares every wheel
    exactly (WPILib C++'s and robotpy's ``==``; Java has no ``equals``), so instances are
    unhashable.
    """

    cdef _WheelValues _new(self):
        return blank4(MecanumDriveWheelAccelerations.__new__(MecanumDriveWheelAccelerations))

    def interpolate(self, end_value: MecanumDriveWheelAccelerations, double t):
        """Linear interpolation with ``t`` clamped to [0, 1]."""
        check_type(end_value, MecanumDriveWheelAccelerations, "end_value")
        return self._lerp(<_WheelValues>end_value, clamp01(t))

    def __eq__(self, other):
        if type(other) is MecanumDriveWheelAccelerations:
            return self._equal(<_WheelValues>other)
        return NotImplemented

    __hash__ = None

    def __str__(self):
        return self._fmt(LABELS, "m/s²")


# ---------------------------------------------------------------------------------------
cdef inline void inverse_rows(const double* wx, const double* wy, vec2_t cor,
                              double* m) noexcept:                 # OUT m (4 x 3)
    cdef Py_ssize_t i
    cdef double x, y
    for i in range(4):
        x = wx[i] - cor.x
        y = wy[i] - cor.y
        m[3 * i] = 1.0
        if i == 0 or i == 3:        # front left, rear right
            m[3 * i + 1] = -1.0
            m[3 * i + 2] = -(x + y)
        else:                       # front right, rear left
            m[3 * i + 1] = 1.0
            m[3 * i + 2] = x - y


cdef inline void twists(const double* f, Py_ssize_t k, const double* d, const double* dth,
                        double* out) noexcept nogil:
    # The drivetrain contract's _twists with the forward matrix f (the dθ row only when
    # no heading change is given).
    cdef Py_ssize_t i
    cdef double r[3]
    for i in range(k):
        if dth != NULL:
            mat_vec_step(2, 4, f, d + i, k, r)
        else:
            mat_vec_step(3, 4, f, d + i, k, r)
            out[2 * k + i] = r[2]
        out[i] = r[0]
        out[k + i] = r[1]


cdef class MecanumDriveKinematics(Drivetrain):
    """MecanumDriveKinematics(front_left_wheel, front_right_wheel, rear_left_wheel, rear_right_wheel)

    Kinematics of a mecanum drive with the four wheel positions (Translation2d, m, robot
    frame). The forward (pseudo-inverse) matrix is computed once for the robot origin and
    never changes; a ``center_of_rotation`` passed to inverse kinematics moves only the
    inverse rows and stays in effect until a different one is passed (within 1e-9 m).
    """

    def __init__(self, front_left_wheel: Translation2d, front_right_wheel: Translation2d,
                 rear_left_wheel: Translation2d, rear_right_wheel: Translation2d):
        check_type(front_left_wheel, Translation2d, "front_left_wheel")
        check_type(front_right_wheel, Translation2d, "front_right_wheel")
        check_type(rear_left_wheel, Translation2d, "rear_left_wheel")
        check_type(rear_right_wheel, Translation2d, "rear_right_wheel")
        cdef Py_ssize_t i
        cdef Translation2d t
        cdef double wx[4]
        cdef double wy[4]
        cdef double m[12]
        cdef tuple wheels = (front_left_wheel, front_right_wheel, rear_left_wheel,
                             rear_right_wheel)
        if self.wheels is not None:
            raise TypeError("MecanumDriveKinematics is already initialised: __init__ cannot "
                            "be called again")
        for i in range(4):
            t = <Translation2d>wheels[i]
            if not (isfinite(t.v.x) and isfinite(t.v.y)):
                raise ValueError(f"wheel {i} position must be finite (m), got {t!r}")
            wx[i] = t.v.x
            wy[i] = t.v.y
        # The pseudo-inverse of the CoR = 0 matrix (as WPILib Java's EJML pinv; drivekin's
        # own, the same bits everywhere), before the object is touched.
        inverse_rows(wx, wy, vec(0.0, 0.0), m)
        cdef double[:, ::1] f = pseudo_inverse(
            np.array([m[i] for i in range(12)]).reshape(4, 3))
        self.wx = wx
        self.wy = wy
        self.m = m
        self.cor = vec(0.0, 0.0)
        for i in range(12):
            self.f[i] = f[i // 4, i % 4]
        self.nwheels = 4
        self.centered = True
        self.wheels = wheels                    # last: what every method checks

    cdef int _ready(self) except -1:
        if self.wheels is None:
            raise RuntimeError("MecanumDriveKinematics.__init__ has not completed")
        return 0

    def __reduce__(self):
        self._ready()
        return (MecanumDriveKinematics, self.wheels)

    def __repr__(self):
        if self.wheels is None:
            return "<uninitialised MecanumDriveKinematics>"
        return f"MecanumDriveKinematics({', '.join(repr(w) for w in self.wheels)})"

    cdef void _set_cor(self, vec2_t cor) noexcept:
        if not vec_eq(cor, self.cor):
            inverse_rows(self.wx, self.wy, cor, self.m)
            self.cor = cor

    cdef void _inverse(self, const double* x, object cor, double* out) except *:
        self._ready()
        if not isinstance(cor, Translation2d):
            raise TypeError(f"center_of_rotation must be a Translation2d, got {type_name(cor)}")
        self._set_cor((<Translation2d>cor).v)
        mat_vec(4, 3, self.m, x, out)

    # -----------------------------------------------------------------------------------
    # The drivetrain contract (drivekin._core.drivetrain): four wheels, one 4 x 3 map

    cdef Py_ssize_t _params(self, double* params, bint forward, bint accel) noexcept:
        # The same matrices serve velocities and accelerations (no centripetal term).
        cdef Py_ssize_t j
        if params != NULL:
            for j in range(12):
                params[j] = self.f[j] if forward else self.m[j]
        return 12

    cdef void _inverse_many(self, Py_ssize_t k, const double* chassis, const double* omega,
                            bint accel, double* params,
                            double* m, double* c, double* s) noexcept nogil:
        cdef Py_ssize_t i
        for i in range(k):
            mat_vec(4, 3, params, chassis + 3 * i, m + 4 * i)

    cdef void _forward_many(self, Py_ssize_t k, const double* m, const double* c,
                            const double* s, const double* gyro, bint accel,
                            const double* params, double* out) noexcept nogil:
        cdef Py_ssize_t i
        for i in range(k):
            mat_vec(3, 4, params, m + 4 * i, out + 3 * i)

    cdef void _twists(self, Py_ssize_t k, const double* d, const double* c, const double* s,
                      const double* dth, double* out) noexcept nogil:
        twists(self.f, k, d, dth, out)

    cdef void _twist(self, const double* d, const double* c, const double* s,
                     const double* dth, double* out) noexcept nogil:
        twists(self.f, 1, d, dth, out)

    def getFrontLeft(self):
        """Return the front-left wheel position (Translation2d, m)."""
        self._ready()
        return self.wheels[0]

    def getFrontRight(self):
        """Return the front-right wheel position (Translation2d, m)."""
        self._ready()
        return self.wheels[1]

    def getRearLeft(self):
        """Return the rear-left wheel position (Translation2d, m)."""
        self._ready()
        return self.wheels[2]

    def getRearRight(self):
        """Return the rear-right wheel position (Translation2d, m)."""
        self._ready()
        return self.wheels[3]

    def toWheelVelocities(self, chassis_velocities: ChassisVelocities,
                          center_of_rotation=ORIGIN):
        """Return the wheel velocities (m/s) for a robot-relative chassis velocity,
        rotating about ``center_of_rotation`` (robot frame, m). Not desaturated."""
        check_type(chassis_velocities, ChassisVelocities, "chassis_velocities")
        cdef _WheelValues out = blank4(MecanumDriveWheelVelocities.__new__(MecanumDriveWheelVelocities))
        self._inverse(&(<ChassisVelocities>chassis_velocities).v.x, center_of_rotation, out.w)
        return out

    def toWheelVelocitiesInto(self, chassis_velocities: ChassisVelocities,
                              out: MecanumDriveWheelVelocities, center_of_rotation=ORIGIN):
        """Allocation-free :meth:`toWheelVelocities`: write into ``out``. Returns None."""
        check_type(chassis_velocities, ChassisVelocities, "chassis_velocities")
        check_type(out, MecanumDriveWheelVelocities, "out")
        self._inverse(&(<ChassisVelocities>chassis_velocities).v.x, center_of_rotation,
                      (<_WheelValues>out).w)

    def toChassisVelocities(self, wheel_velocities: MecanumDriveWheelVelocities):
        """Return the least-squares robot velocity for measured wheel velocities."""
        check_type(wheel_velocities, MecanumDriveWheelVelocities, "wheel_velocities")
        self._ready()
        cdef ChassisVelocities out = new_chassis_velocities(0.0, 0.0, 0.0)
        mat_vec(3, 4, self.f, (<_WheelValues>wheel_velocities).w, &out.v.x)
        return out

    def toChassisVelocitiesInto(self, wheel_velocities: MecanumDriveWheelVelocities,
                                out: ChassisVelocities):
        """Allocation-free :meth:`toChassisVelocities`: write into ``out``. Returns None."""
        check_type(wheel_velocities, MecanumDriveWheelVelocities, "wheel_velocities")
        check_type(out, ChassisVelocities, "out")
        self._ready()
        mat_vec(3, 4, self.f, (<_WheelValues>wheel_velocities).w, &(<ChassisVelocities>out).v.x)

    def toTwist2d(self, start: MecanumDriveWheelPositions, end=None):
        """toTwist2d(wheel_deltas) or toTwist2d(start, end)

        Return the Twist2d (m, rad) for wheel distance changes, either given directly or
        as ``end − start`` of two MecanumDriveWheelPositions."""
        cdef double d[4]
        cdef double r[3]
        cdef Py_ssize_t i
        check_type(start, MecanumDriveWheelPositions, "start")
        self._ready()
        if end is None:
            d = (<_WheelValues>start).w
        elif type(end) is MecanumDriveWheelPositions:
            for i in range(4):
                d[i] = (<_WheelValues>end).w[i] - (<_WheelValues>start).w[i]
        else:
            raise TypeError(f"end must be a MecanumDriveWheelPositions, got {type_name(end)}")
        mat_vec(3, 4, self.f, d, r)
        return new_twist(r[0], r[1], r[2])

    def toWheelAccelerations(self, chassis_accelerations: ChassisAccelerations,
                             center_of_rotation=ORIGIN):
        """Return the wheel accelerations (m/s²) for a chassis acceleration; the same
        matrix as for velocities (no centripetal term, as in WPILib)."""
        check_type(chassis_accelerations, ChassisAccelerations, "chassis_accelerations")
        cdef _WheelValues out = blank4(MecanumDriveWheelAccelerations.__new__(MecanumDriveWheelAccelerations))
        self._inverse(&(<ChassisAccelerations>chassis_accelerations).v.x, center_of_rotation,
                      out.w)
        return out

    def toChassisAccelerations(self, wheel_accelerations: MecanumDriveWheelAccelerations):
        """Return the least-squares chassis acceleration for wheel accelerations."""
        cdef double r[3]
        check_type(wheel_accelerations, MecanumDriveWheelAccelerations, "wheel_accelerations")
        self._ready()
        mat_vec(3, 4, self.f, (<_WheelValues>wheel_accelerations).w, r)
        return ChassisAccelerations(r[0], r[1], r[2])

    def interpolate(self, start: MecanumDriveWheelPositions,
                    end: MecanumDriveWheelPositions, double t):
        """Return ``start.interpolate(end, t)`` (not clamped)."""
        check_type(start, MecanumDriveWheelPositions, "start")
        check_type(end, MecanumDriveWheelPositions, "end")
        self._ready()
        return start.interpolate(end, t)

    def copy(self, positions: MecanumDriveWheelPositions):
        """Return an independent copy of ``positions``."""
        check_type(positions, MecanumDriveWheelPositions, "positions")
        self._ready()
        return positions.copy()

    def copyInto(self, positions: MecanumDriveWheelPositions,
                 output: MecanumDriveWheelPositions):
        """Copy ``positions`` into ``output``."""
        check_type(positions, MecanumDriveWheelPositions, "positions")
        check_type(output, MecanumDriveWheelPositions, "output")
        self._ready()
        (<_WheelValues>output).w = (<_WheelValues>positions).w


install_bare_new((MecanumDriveWheelVelocities, MecanumDriveWheelPositions,
                  MecanumDriveWheelAccelerations), 4)
