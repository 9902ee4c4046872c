"""Swerve module values (WPILib 2027): the velocity, position and acceleration of one
swerve module, each a scalar and the module angle.

Units: m, m/s, m/s², rad. Robot frame: x forward, y left, CCW positive.

The values hold C doubles (the angle as a cos/sin pair), so :mod:`drivekin.swerve`'s
kinematics reads and writes them without creating Python objects; they are importable
from :mod:`drivekin.swerve` too."""
cimport cython
from cpython.ref cimport Py_INCREF
from cpython.tuple cimport PyTuple_New, PyTuple_SET_ITEM
from libc.math cimport M_PI, fabs, signbit

from drivekin._core.types cimport rot2_t
from drivekin._core.args cimport check_type, is_number
from drivekin._core.dkmath cimport hypot
from drivekin._core.kernels cimport (clamp01, java_equals, rot_eq, rot_interp, rot_minus,
                                     rot_plus, rot_rad, rot_radians, rot_xy)
from drivekin.geometry cimport Rotation2d, new_rotation
from drivekin._core.errors import refuse_delete, type_name
from drivekin._core.format import f2

__all__ = ["SwerveModuleAcceleration", "SwerveModulePosition", "SwerveModuleVelocity"]

cdef rot2_t IDENTITY
IDENTITY.c = 1.0
IDENTITY.s = 0.0


cdef rot2_t _angle_arg(object angle) except *:
    if angle is None:
        return IDENTITY
    if isinstance(angle, Rotation2d):
        return (<Rotation2d>angle).r
    if is_number(angle):                   # robotpy's implicit Rotation2d(radians)
        return rot_rad(angle)
    raise TypeError(f"angle must be a Rotation2d or a float (rad), got {type_name(angle)}")


cdef inline void optimize_into(_ModuleVector v, rot2_t current, _ModuleVector out) noexcept:
    # Turn at most 90°: beyond that, drive backwards at the angle + 180°.
    if fabs(rot_radians(rot_minus(v.a, current)) * (180.0 / M_PI)) > 90.0:
        out.m = -v.m
        out.a = rot_plus(v.a, rot_rad(M_PI))
    else:
        out.m = v.m
        out.a = v.a


@cython.freelist(128)
cdef class _ModuleVector:
    """Shared behaviour of the swerve module values: a scalar and an angle."""

    cdef _ModuleVector _new(self, double m, rot2_t a):
        raise TypeError("_ModuleVector is an abstract base; use a SwerveModule... class")

    @property
    def angle(self):
        """Module angle (Rotation2d). Stored by value: assigning copies the rotation."""
        return new_rotation(self.a)

    @angle.setter
    def angle(self, value: Rotation2d):
        check_type(value, Rotation2d, "angle")
        self.a = (<Rotation2d>value).r

    def compareTo(self, other: _ModuleVector):
        """Compare the scalar only, like Java ``Double.compare``: −1, 0 or 1. ``other``
        must be of the same class."""
        check_type(other, type(self), "other")
        cdef double a = self.m, b = (<_ModuleVector>other).m
        if a < b:
            return -1
        if a > b:
            return 1
        if java_equals(a, b):
            return 0
        # Double.compare orders -0.0 before 0.0 and NaN after everything.
        if a != a:
            return 1
        if b != b:
            return -1
        return -1 if signbit(a) else 1

    cdef _ModuleVector _lerp(self, _ModuleVector end, double t):
        if type(end) is not type(self):
            raise TypeError(f"expected a {type(self).__name__}, got {type_name(end)}")
        return self._new(self.m + (end.m - self.m) * t, rot_interp(self.a, end.a, t))

    def __eq__(self, other):
        cdef _ModuleVector o
        if type(other) is type(self):
            o = <_ModuleVector>other
            return fabs(self.m - o.m) < 1e-9 and rot_eq(self.a, o.a)
        return NotImplemented

    __hash__ = None  # mutable, tolerant equality

    def __reduce__(self):
        return (type(self), (self.m, new_rotation(self.a)))

    def __delattr__(self, name):
        refuse_delete(self, name)

    def __iter__(self):
        yield self.m
        yield new_rotation(self.a)


cdef class SwerveModuleVelocity(_ModuleVector):
    """SwerveModuleVelocity(velocity=0.0, angle=Rotation2d())

    The velocity of one swerve module: wheel ``velocity`` in m/s (may be negative) and the
    module ``angle``. Mutable; ``==`` compares velocity within 1e-9 m/s and the angle
    within 1e-9. (WPILib 2026: ``SwerveModuleState(speed, angle)``.)
    """

    def __init__(self, double velocity=0.0, angle=None):
        self.a = _angle_arg(angle)
        self.m = velocity

    cdef _ModuleVector _new(self, double m, rot2_t a):
        return new_module_velocity(m, a)

    @property
    def velocity(self):
        """Wheel velocity, m/s."""
        return self.m

    @velocity.setter
    def velocity(self, double value):
        self.m = value

    def optimize(self, current_angle: Rotation2d):
        """Return the equivalent velocity that turns the module by at most 90°.

        If the target angle is more than 90° from ``current_angle``, the result drives the
        wheel backwards at the angle + 180°. Returns a new object (2027)."""
        check_type(current_angle, Rotation2d, "current_angle")
        cdef SwerveModuleVelocity out = new_module_velocity(self.m, self.a)
        optimize_into(self, (<Rotation2d>current_angle).r, out)
        return out

    def optimizeInPlace(self, current_angle: Rotation2d):
        """Allocation-free :meth:`optimize`: update this object (the WPILib 2026
        behaviour). Returns None."""
        check_type(current_angle, Rotation2d, "current_angle")
        optimize_into(self, (<Rotation2d>current_angle).r, self)

    def cosineScale(self, current_angle: Rotation2d):
        """Return the velocity scaled by cos(angle − current_angle), so a module that is
        still turning does not push sideways. Returns a new object (2027)."""
        check_type(current_angle, Rotation2d, "current_angle")
        return new_module_velocity(self.m * rot_minus(self.a, (<Rotation2d>current_angle).r).c,
                                   self.a)

    def cosineScaleInPlace(self, current_angle: Rotation2d):
        """Allocation-free :meth:`cosineScale`: update this object. Returns None."""
        check_type(current_angle, Rotation2d, "current_angle")
        self.m = self.m * rot_minus(self.a, (<Rotation2d>current_angle).r).c

    def interpolate(self, end_value: SwerveModuleVelocity, double t):
        """Interpolate velocity linearly and the angle the short way; ``t`` is clamped to
        [0, 1]."""
        check_type(end_value, SwerveModuleVelocity, "end_value")
        return self._lerp(<_ModuleVector>end_value, clamp01(t))

    def __repr__(self):
        return f"SwerveModuleVelocity({self.m!r}, {new_rotation(self.a)!r})"

    def __str__(self):
        return f"SwerveModuleVelocity(Velocity: {f2(self.m)} m/s, Angle: {new_rotation(self.a)})"


cdef class SwerveModulePosition(_ModuleVector):
    """SwerveModulePosition(distance=0.0, angle=Rotation2d())

    The position of one swerve module: distance driven by the wheel in m and the module
    ``angle``. Mutable; ``==`` compares distance within 1e-9 m and the angle within 1e-9.
    """

    def __init__(self, double distance=0.0, angle=None):
        self.a = _angle_arg(angle)
        self.m = distance

    cdef _ModuleVector _new(self, double m, rot2_t a):
        return new_module_position(m, a)

    @property
    def distance(self):
        """Distance driven by the wheel, m."""
        return self.m

    @distance.setter
    def distance(self, double value):
        self.m = value

    def copy(self):
        """Return an independent copy."""
        return new_module_position(self.m, self.a)

    def interpolate(self, end_value: SwerveModulePosition, double t):
        """Interpolate distance linearly and the angle the short way; ``t`` is not clamped."""
        check_type(end_value, SwerveModulePosition, "end_value")
        return self._lerp(<_ModuleVector>end_value, t)

    def __repr__(self):
        return f"SwerveModulePosition({self.m!r}, {new_rotation(self.a)!r})"

    def __str__(self):
        return f"SwerveModulePosition(Distance: {f2(self.m)} m, Angle: {new_rotation(self.a)})"


cdef class SwerveModuleAcceleration(_ModuleVector):
    """SwerveModuleAcceleration(acceleration=0.0, angle=Rotation2d())

    The acceleration of one swerve module: magnitude in m/s² and the direction ``angle``
    of the acceleration vector. Mutable; ``==`` compares within 1e-9.
    """

    def __init__(self, double acceleration=0.0, angle=None):
        self.a = _angle_arg(angle)
        self.m = acceleration

    cdef _ModuleVector _new(self, double m, rot2_t a):
        cdef SwerveModuleAcceleration o = SwerveModuleAcceleration.__new__(SwerveModuleAcceleration)
        o.m = m
        o.a = a
        return o

    @property
    def acceleration(self):
        """Acceleration magnitude, m/s²."""
        return self.m

    @acceleration.setter
    def acceleration(self, double value):
        self.m = value

    def interpolate(self, end_value: SwerveModuleAcceleration, double t):
        """Interpolate the magnitude linearly and the angle the short way; ``t`` is
        clamped to [0, 1]."""
        check_type(end_value, SwerveModuleAcceleration, "end_value")
        return self._lerp(<_ModuleVector>end_value, clamp01(t))

    # Vector arithmetic of WPILib C++'s operators (robotpy's + - * /; Java has none): the
    # sum goes through Cartesian components, negation turns the angle by 180°.
    def __add__(self, other):
        if not isinstance(other, SwerveModuleAcceleration):
            return NotImplemented
        cdef _ModuleVector o = <_ModuleVector>other
        return _acceleration_sum(self, o.m, o.a)

    def __sub__(self, other):
        if not isinstance(other, SwerveModuleAcceleration):
            return NotImplemented
        cdef _ModuleVector o = <_ModuleVector>other
        return _acceleration_sum(self, o.m, rot_plus(o.a, rot_rad(M_PI)))

    def __neg__(self):
        return self._new(self.m, rot_plus(self.a, rot_rad(M_PI)))

    def __mul__(self, scalar):
        if not is_number(scalar):
            return NotImplemented
        return _acceleration_scaled(self, scalar)

    def __rmul__(self, scalar):
        return self.__mul__(scalar)

    def __truediv__(self, scalar):
        if not is_number(scalar):
            return NotImplemented
        return _acceleration_scaled(self, 1.0 / <double>scalar)

    def __repr__(self):
        return f"SwerveModuleAcceleration({self.m!r}, {new_rotation(self.a)!r})"

    def __str__(self):
        # WPILib's toString says "Accelerations" (plural); kept for identical logs.
        return (f"SwerveModuleAccelerations(Acceleration: {f2(self.m)} m/s², "
                f"Angle: {new_rotation(self.a)})")


cdef _ModuleVector _acceleration_sum(_ModuleVector a, double m, rot2_t angle):
    cdef double x = a.m * a.a.c + m * angle.c
    cdef double y = a.m * a.a.s + m * angle.s
    return a._new(hypot(x, y), rot_xy(x, y))


cdef _ModuleVector _acceleration_scaled(_ModuleVector a, double k):
    if k < 0:
        return a._new(-k * a.m, rot_plus(a.a, rot_rad(M_PI)))
    return a._new(k * a.m, a.a)


# Built here, where each class's allocator (and its freelist) is a direct call, not a
# call through the type object as in the modules that cimport the classes.
cdef object new_modules(Py_ssize_t n, type cls):
    """Return a tuple of n new module values (from the freelists), to be filled."""
    cdef object t = PyTuple_New(n)
    cdef _ModuleVector o
    cdef Py_ssize_t i
    for i in range(n):
        if cls is SwerveModuleVelocity:
            o = SwerveModuleVelocity.__new__(SwerveModuleVelocity)
        elif cls is SwerveModulePosition:
            o = SwerveModulePosition.__new__(SwerveModulePosition)
        else:
            o = SwerveModuleAcceleration.__new__(SwerveModuleAcceleration)
        Py_INCREF(o)
        PyTuple_SET_ITEM(t, i, o)
    return t
