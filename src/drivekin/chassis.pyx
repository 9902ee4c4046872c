"""Chassis velocities and accelerations (WPILib 2027).

Units: m/s, m/s², rad/s, rad/s², s. Robot frame: x forward, y left, CCW positive. Each
conversion has an object-returning form and an allocation-free ``...Into`` form.
"""
cimport cython
from libc.math cimport isfinite

from drivekin._core.types cimport rot2_t, vec2_t, vec3_t
from drivekin._core.kernels cimport chassis_discretize, feet_to_meters, java_equals, rot_neg, vec, vec_rotate
from drivekin._core.args cimport check_type
from drivekin.geometry cimport Rotation2d, new_twist
from drivekin._core.errors import refuse_delete
from drivekin._core.format import f2

__all__ = ["ChassisAccelerations", "ChassisVelocities"]


# Freelists live on the two base classes: Cython only lets the base manage them, and the
# subclasses add no fields, so they share it.
@cython.freelist(64)
cdef class _ChassisVector:
    """Shared arithmetic of ChassisVelocities and ChassisAccelerations (x, y, angular)."""

    cdef _ChassisVector _new(self, double x, double y, double z):
        raise TypeError("_ChassisVector is an abstract base; use ChassisVelocities or "
                        "ChassisAccelerations")

    cdef _rotated_into(self, rot2_t r, _ChassisVector out):
        cdef vec2_t t = vec_rotate(vec(self.v.x, self.v.y), r)
        out.v.x = t.x
        out.v.y = t.y
        out.v.z = self.v.z

    def toRobotRelative(self, robot_angle: Rotation2d):
        """Convert field-relative values to robot-relative ones.

        ``robot_angle`` is the robot heading on the field; x and y are rotated by
        −robot_angle, the angular component is unchanged."""
        check_type(robot_angle, Rotation2d, "robot_angle")
        out = self._new(0.0, 0.0, 0.0)
        self._rotated_into(rot_neg((<Rotation2d>robot_angle).r), out)
        return out

    def toFieldRelative(self, robot_angle: Rotation2d):
        """Convert robot-relative values to field-relative ones (rotate by robot_angle)."""
        check_type(robot_angle, Rotation2d, "robot_angle")
        out = self._new(0.0, 0.0, 0.0)
        self._rotated_into((<Rotation2d>robot_angle).r, out)
        return out

    # A parameter annotated with the shared base (out, other, end_value) must be of this
    # object's own class: check_type against type(self).

    def toRobotRelativeInto(self, robot_angle: Rotation2d, out: _ChassisVector):
        """Allocation-free :meth:`toRobotRelative`: write the result into ``out`` (of the
        same class; may be ``self``)."""
        check_type(robot_angle, Rotation2d, "robot_angle")
        check_type(out, type(self), "out")
        self._rotated_into(rot_neg((<Rotation2d>robot_angle).r), <_ChassisVector>out)

    def toFieldRelativeInto(self, robot_angle: Rotation2d, out: _ChassisVector):
        """Allocation-free :meth:`toFieldRelative`: write the result into ``out`` (of the
        same class; may be ``self``)."""
        check_type(robot_angle, Rotation2d, "robot_angle")
        check_type(out, type(self), "out")
        self._rotated_into((<Rotation2d>robot_angle).r, <_ChassisVector>out)

    def plus(self, other: _ChassisVector):
        """Return the component-wise sum."""
        check_type(other, type(self), "other")
        cdef vec3_t o = (<_ChassisVector>other).v
        return self._new(self.v.x + o.x, self.v.y + o.y, self.v.z + o.z)

    def minus(self, other: _ChassisVector):
        """Return the component-wise difference."""
        check_type(other, type(self), "other")
        cdef vec3_t o = (<_ChassisVector>other).v
        return self._new(self.v.x - o.x, self.v.y - o.y, self.v.z - o.z)

    def unaryMinus(self):
        """Return the negation of every component."""
        return self._new(-self.v.x, -self.v.y, -self.v.z)

    def times(self, double scalar):
        """Return every component multiplied by ``scalar``."""
        return self._new(self.v.x * scalar, self.v.y * scalar, self.v.z * scalar)

    def div(self, double scalar):
        """Return every component divided by ``scalar`` (no zero guard, as in WPILib)."""
        return self._new(self.v.x / scalar, self.v.y / scalar, self.v.z / scalar)

    def interpolate(self, end_value: _ChassisVector, double t):
        """Linear interpolation; ``t <= 0`` returns ``self`` and ``t >= 1`` returns
        ``end_value`` (the objects themselves, as WPILib does)."""
        check_type(end_value, type(self), "end_value")
        if t <= 0.0:
            return self
        if t >= 1.0:
            return end_value
        cdef vec3_t e = (<_ChassisVector>end_value).v
        return self._new(self.v.x + t * (e.x - self.v.x),
                         self.v.y + t * (e.y - self.v.y),
                         self.v.z + t * (e.z - self.v.z))

    def __add__(self, other):
        if type(other) is type(self):
            return self.plus(other)
        return NotImplemented

    def __sub__(self, other):
        if type(other) is type(self):
            return self.minus(other)
        return NotImplemented

    def __neg__(self):
        return self.unaryMinus()

    def __mul__(self, other):
        try:
            return self.times(other)
        except TypeError:
            return NotImplemented

    def __rmul__(self, other):
        return self.__mul__(other)

    def __truediv__(self, other):
        try:
            return self.div(other)
        except TypeError:
            return NotImplemented

    __hash__ = None  # mutable

    def __reduce__(self):
        return (type(self), (self.v.x, self.v.y, self.v.z))

    def __delattr__(self, name):
        refuse_delete(self, name)


cdef int check_discretize_fits(vec3_t v, double dt) except -1:
    # ValueError where finite input's discretize exceeds the doubles (every form).
    cdef vec3_t d
    if not discretize_is_large(v.x, v.y, v.z):
        return 0
    if not (isfinite(v.x) and isfinite(v.y) and isfinite(v.z) and isfinite(dt)) or dt == 0.0:
        return 0
    d = chassis_discretize(v.x, v.y, v.z, dt)
    if isfinite(d.x) and isfinite(d.y) and isfinite(d.z):
        return 0
    raise ValueError(f"the chassis velocities ({v.x!r}, {v.y!r}, {v.z!r}) discretized over "
                     f"dt = {dt!r} s exceed the largest double ({d.x!r}, {d.y!r}, {d.z!r}); "
                     "scale them down")


cdef class ChassisVelocities(_ChassisVector):
    """ChassisVelocities(vx=0.0, vy=0.0, omega=0.0)

    Robot velocity: ``vx`` forward and ``vy`` left in m/s, ``omega`` counter-clockwise in
    rad/s. Robot-relative unless stated otherwise. Fields are mutable; ``==`` compares
    each field exactly (0.0 == −0.0, NaN != NaN), as WPILib does.
    """

    def __init__(self, double vx=0.0, double vy=0.0, double omega=0.0):
        self.v.x = vx
        self.v.y = vy
        self.v.z = omega

    cdef _ChassisVector _new(self, double x, double y, double z):
        return new_chassis_velocities(x, y, z)

    @staticmethod
    def fromFeet(double vx=0.0, double vy=0.0, double omega=0.0):
        """Return the velocity ``vx`` forward and ``vy`` left given in ft/s, ``omega`` in
        rad/s, in m/s (the same bits as robotpy-wpimath's ``ChassisSpeeds.fromFeet``)."""
        return new_chassis_velocities(feet_to_meters(vx), feet_to_meters(vy), omega)

    @property
    def vx(self):
        """Forward velocity, m/s."""
        return self.v.x

    @vx.setter
    def vx(self, double value):
        self.v.x = value

    @property
    def vy(self):
        """Leftward velocity, m/s."""
        return self.v.y

    @vy.setter
    def vy(self, double value):
        self.v.y = value

    @property
    def omega(self):
        """Angular velocity, rad/s, counter-clockwise positive."""
        return self.v.z

    @omega.setter
    def omega(self, double value):
        self.v.z = value

    def toTwist2d(self, double dt):
        """Return the Twist2d ``(vx·dt, vy·dt, omega·dt)`` travelled in ``dt`` seconds."""
        return new_twist(self.v.x * dt, self.v.y * dt, self.v.z * dt)

    def discretize(self, double dt):
        """Return the velocities that, held constant for ``dt`` s along a straight line in
        the rotating frame, end at the pose this constant twist would reach.

        This removes the drift of swerve/mecanum drives that translate while turning.
        ``omega·dt`` passes through a Rotation2d, so it is wrapped to [−π, π]
        (omega = 4, dt = 1 gives omega' = 4 − 2π); ``dt = 0`` divides by zero (NaN),
        as in WPILib. Finite input gives a finite result at any magnitude (ValueError if
        that result is beyond the largest double)."""
        check_discretize_fits(self.v, dt)
        cdef vec3_t d = chassis_discretize(self.v.x, self.v.y, self.v.z, dt)
        return new_chassis_velocities(d.x, d.y, d.z)

    def discretizeInto(self, double dt, out: ChassisVelocities):
        """Allocation-free :meth:`discretize`: write the result into ``out`` (may be self)."""
        check_type(out, ChassisVelocities, "out")
        check_discretize_fits(self.v, dt)
        (<ChassisVelocities>out).v = chassis_discretize(self.v.x, self.v.y, self.v.z, dt)

    def __eq__(self, other):
        cdef ChassisVelocities o
        if isinstance(other, ChassisVelocities):
            o = <ChassisVelocities>other
            return self.v.x == o.v.x and self.v.y == o.v.y and self.v.z == o.v.z
        return NotImplemented

    def __repr__(self):
        return f"ChassisVelocities(vx={self.v.x!r}, vy={self.v.y!r}, omega={self.v.z!r})"

    def __str__(self):
        return (f"ChassisVelocities(Vx: {f2(self.v.x)} m/s, Vy: {f2(self.v.y)} m/s, "
                f"Omega: {f2(self.v.z)} rad/s)")


cdef class ChassisAccelerations(_ChassisVector):
    """ChassisAccelerations(ax=0.0, ay=0.0, alpha=0.0)

    Robot acceleration: ``ax`` forward and ``ay`` left in m/s², ``alpha`` counter-clockwise
    in rad/s². Fields are mutable; ``==`` follows Java ``Double.compare`` (NaN == NaN,
    0.0 != −0.0).
    """

    def __init__(self, double ax=0.0, double ay=0.0, double alpha=0.0):
        self.v.x = ax
        self.v.y = ay
        self.v.z = alpha

    cdef _ChassisVector _new(self, double x, double y, double z):
        cdef ChassisAccelerations o = ChassisAccelerations.__new__(ChassisAccelerations)
        o.v.x = x
        o.v.y = y
        o.v.z = z
        return o

    @property
    def ax(self):
        """Forward acceleration, m/s²."""
        return self.v.x

    @ax.setter
    def ax(self, double value):
        self.v.x = value

    @property
    def ay(self):
        """Leftward acceleration, m/s²."""
        return self.v.y

    @ay.setter
    def ay(self, double value):
        self.v.y = value

    @property
    def alpha(self):
        """Angular acceleration, rad/s², counter-clockwise positive."""
        return self.v.z

    @alpha.setter
    def alpha(self, double value):
        self.v.z = value

    def __eq__(self, other):
        cdef ChassisAccelerations o
        if isinstance(other, ChassisAccelerations):
            o = <ChassisAccelerations>other
            return (java_equals(self.v.x, o.v.x) and java_equals(self.v.y, o.v.y)
                    and java_equals(self.v.z, o.v.z))
        return NotImplemented

    def __repr__(self):
        return f"ChassisAccelerations(ax={self.v.x!r}, ay={self.v.y!r}, alpha={self.v.z!r})"

    def __str__(self):
        return (f"ChassisAccelerations(Ax: {f2(self.v.x)} m/s², Ay: {f2(self.v.y)} m/s², "
                f"Alpha: {f2(self.v.z)} rad/s²)")


