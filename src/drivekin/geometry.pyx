"""2-D geometry with WPILib 2027 semantics: Translation2d, Rotation2d, Pose2d,
Transform2d and Twist2d.

Units: metres and radians. Frame: x forward, y left, angles counter-clockwise positive.
All classes except :class:`Twist2d` are immutable. Equality uses WPILib's tolerances
(1e-9), so the immutable classes are deliberately unhashable.
"""
cimport cython
from libc.math cimport M_PI, fabs
from drivekin._core.dkmath cimport hypot

import numpy as np

from drivekin._core.types cimport pose2_t, rot2_t, twist2_t, vec2_t
from drivekin._core.args cimport check_float64, check_type, is_number, refuse_reinit
from drivekin._core.kernels cimport (
    feet_to_meters, pose, pose_interpolate, pose_relative_to, pose_times, pose_transform_by, rot_eq, rot_interp, rot_minus,
    rot_neg, rot_plus, rot_rad, rot_radians, rot_times, rot_xy, transform_inverse,
    transform_log, twist_exp, vec, vec_eq, vec_rotate,
)
from drivekin._core.errors import refuse_delete, type_name
from drivekin._core.format import f2
from drivekin._core.typedict cimport drivekin_set_type_attr


cdef double DEG = 180.0 / M_PI

# Marks an argument that was not passed (None is a value callers may pass by mistake).
cdef object MISSING = object()


cdef vec2_t vector2(object a) except *:
    # Translation2d(vector): a float64 numpy array of shape (2,), read by value.
    check_float64(a, "Translation2d(vector)")
    if a.shape != (2,):
        raise ValueError(f"Translation2d(vector) needs shape (2,), got {a.shape}")
    return vec(a[0], a[1])


cdef rot2_t feet_angle(object angle, str where) except *:
    # The angle of Pose2d/Transform2d.fromFeet: a Rotation2d, or radians as a float
    # (robotpy has both overloads).
    cdef double rad
    if isinstance(angle, Rotation2d):
        return (<Rotation2d>angle).r
    try:
        rad = angle
    except TypeError:
        raise TypeError(f"{where} takes the angle as a drivekin Rotation2d or in rad "
                        f"(float), got {type_name(angle)}") from None
    return rot_rad(rad)


# ---------------------------------------------------------------------------------------
@cython.freelist(64)
cdef class Translation2d:
    """Translation2d(x=0.0, y=0.0) or Translation2d(distance, angle) or Translation2d(vector)

    A point or vector in the plane, in metres.

    ``Translation2d(x, y)`` takes the components in m; ``Translation2d(distance, angle)``
    takes a length in m and a :class:`Rotation2d` direction; ``Translation2d(vector)``
    takes a float64 numpy array of shape (2,). Immutable; ``==`` compares each component
    within 1e-9 m.
    """

    def __init__(self, x=0.0, y=MISSING):
        cdef Rotation2d a
        cdef vec2_t v
        refuse_reinit(self.frozen, self)
        if isinstance(x, np.ndarray):
            if y is not MISSING:
                raise TypeError("Translation2d(vector) takes one argument, got a second: "
                                f"{type_name(y)}")
            v = vector2(x)
        elif isinstance(y, Rotation2d):
            a = <Rotation2d>y
            v = vec(x * a.r.c, x * a.r.s)
        else:
            v = vec(x, 0.0 if y is MISSING else y)
        self.v = v
        self.frozen = True

    @property
    def x(self):
        """X component, m."""
        return self.v.x

    @property
    def y(self):
        """Y component, m."""
        return self.v.y

    def getX(self):
        """Return the x component, m."""
        return self.v.x

    def getY(self):
        """Return the y component, m."""
        return self.v.y

    def getNorm(self):
        """Return the distance from the origin, m."""
        return hypot(self.v.x, self.v.y)

    def getSquaredNorm(self):
        """Return the squared distance from the origin, m²."""
        return self.v.x * self.v.x + self.v.y * self.v.y

    def getDistance(self, other: Translation2d):
        """Return the distance to ``other``, m."""
        check_type(other, Translation2d, "other")
        cdef vec2_t o = (<Translation2d>other).v
        return hypot(o.x - self.v.x, o.y - self.v.y)

    def getSquaredDistance(self, other: Translation2d):
        """Return the squared distance to ``other``, m²."""
        check_type(other, Translation2d, "other")
        cdef vec2_t o = (<Translation2d>other).v
        cdef double dx = o.x - self.v.x, dy = o.y - self.v.y
        return dx * dx + dy * dy

    def getAngle(self):
        """Return the direction of this vector as a Rotation2d, or ``None`` when its
        length is 1e-6 m or less (WPILib 2027 returns an empty Optional)."""
        if hypot(self.v.x, self.v.y) > 1e-6:
            return new_rotation(rot_xy(self.v.x, self.v.y))
        return None

    def rotateBy(self, other: Rotation2d):
        """Return this vector rotated counter-clockwise by ``other`` about the origin."""
        check_type(other, Rotation2d, "other")
        return new_translation(vec_rotate(self.v, (<Rotation2d>other).r))

    def rotateAround(self, other: Translation2d, rot: Rotation2d):
        """Return this point rotated by ``rot`` about the point ``other``."""
        check_type(other, Translation2d, "other")
        check_type(rot, Rotation2d, "rot")
        cdef vec2_t o = (<Translation2d>other).v
        cdef vec2_t d = vec_rotate(vec(self.v.x - o.x, self.v.y - o.y), (<Rotation2d>rot).r)
        return new_translation(vec(d.x + o.x, d.y + o.y))

    def plus(self, other: Translation2d):
        """Return the component-wise sum, m."""
        check_type(other, Translation2d, "other")
        cdef vec2_t o = (<Translation2d>other).v
        return new_translation(vec(self.v.x + o.x, self.v.y + o.y))

    def minus(self, other: Translation2d):
        """Return the component-wise difference, m."""
        check_type(other, Translation2d, "other")
        cdef vec2_t o = (<Translation2d>other).v
        return new_translation(vec(self.v.x - o.x, self.v.y - o.y))

    def unaryMinus(self):
        """Return the vector pointing the other way."""
        return new_translation(vec(-self.v.x, -self.v.y))

    def times(self, double scalar):
        """Return the vector scaled by ``scalar``."""
        return new_translation(vec(self.v.x * scalar, self.v.y * scalar))

    def div(self, double scalar):
        """Return the vector divided by ``scalar`` (no zero guard, as in WPILib)."""
        return new_translation(vec(self.v.x / scalar, self.v.y / scalar))

    def dot(self, other: Translation2d):
        """Return the dot product, m²."""
        check_type(other, Translation2d, "other")
        cdef vec2_t o = (<Translation2d>other).v
        return self.v.x * o.x + self.v.y * o.y

    def cross(self, other: Translation2d):
        """Return the z component of the cross product, m² (x·other.y − y·other.x)."""
        check_type(other, Translation2d, "other")
        cdef vec2_t o = (<Translation2d>other).v
        return self.v.x * o.y - self.v.y * o.x

    def nearest(self, translations):
        """Return the element of ``translations`` closest to this point (first on ties)."""
        return min(translations, key=self.getDistance)

    def interpolate(self, end_value: Translation2d, double t):
        """Return the linear interpolation towards ``end_value``; ``t`` is not clamped."""
        check_type(end_value, Translation2d, "end_value")
        cdef vec2_t e = (<Translation2d>end_value).v
        return new_translation(vec(self.v.x + (e.x - self.v.x) * t,
                                   self.v.y + (e.y - self.v.y) * t))

    def toVector(self):
        """Return ``numpy.array([x, y])``."""
        return np.array([self.v.x, self.v.y])

    def __add__(self, other):
        if isinstance(other, Translation2d):
            return self.plus(other)
        return NotImplemented

    def __sub__(self, other):
        if isinstance(other, Translation2d):
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

    def __eq__(self, other):
        if isinstance(other, Translation2d):
            return vec_eq(self.v, (<Translation2d>other).v)
        return NotImplemented

    __hash__ = None

    def __iter__(self):
        yield self.v.x
        yield self.v.y

    def __reduce__(self):
        return (Translation2d, (self.v.x, self.v.y))

    def __repr__(self):
        return f"Translation2d(x={self.v.x!r}, y={self.v.y!r})"

    def __str__(self):
        return f"Translation2d(X: {f2(self.v.x)}, Y: {f2(self.v.y)})"

    @staticmethod
    def fromFeet(double x, y):
        """Translation2d.fromFeet(x, y) or Translation2d.fromFeet(distance, angle)

        Return the translation (``x``, ``y``) given in feet, or the one of length
        ``distance`` ft in the direction ``angle`` (a :class:`Rotation2d`), in metres
        (1 ft = 0.3048 m; the same bits as robotpy-wpimath's ``Translation2d.fromFeet``)."""
        cdef double d = feet_to_meters(x), fy
        cdef Rotation2d a
        if isinstance(y, Rotation2d):
            a = <Rotation2d>y
            return new_translation(vec(d * a.r.c, d * a.r.s))
        try:
            fy = y
        except TypeError:
            raise TypeError("Translation2d.fromFeet(x, y) takes y in ft (float), or "
                            "(distance, angle) a drivekin Rotation2d; got "
                            f"{type_name(y)}") from None
        return new_translation(vec(d, feet_to_meters(fy)))


# ---------------------------------------------------------------------------------------
@cython.freelist(128)
cdef class Rotation2d:
    """Rotation2d(value=0.0) or Rotation2d(x, y) or Rotation2d(matrix)

    A rotation in the plane, stored as its unit vector (cos, sin) as in WPILib 2027.

    ``Rotation2d(value)`` takes an angle in radians. ``Rotation2d(x, y)`` takes any
    vector and normalises it; a vector of length 1e-6 or less gives the identity
    (WPILib reports an error there; drivekin returns the identity silently).
    ``Rotation2d(matrix)`` takes a 2×2 special orthogonal float64 numpy array (ValueError
    if the Frobenius norm of RRᵀ − I, or abs(det R − 1), exceeds 1e-9).
    The constructor angle is not remembered: ``Rotation2d(3π/2).getDegrees()`` is −90.
    """

    def __cinit__(self):
        # A bare Rotation2d.__new__ is the identity, never the invalid (0, 0).
        self.r.c = 1.0

    def __init__(self, value=0.0, y=MISSING):
        cdef rot2_t r
        refuse_reinit(self.frozen, self)
        if y is not MISSING:
            r = rot_xy(value, y)
        elif isinstance(value, np.ndarray):
            r = _rot_matrix(value)
        else:
            r = rot_rad(value)
        self.r = r
        self.frozen = True

    @staticmethod
    def fromRadians(double radians):
        """Return the rotation of ``radians`` rad."""
        return new_rotation(rot_rad(radians))

    @staticmethod
    def fromDegrees(double degrees):
        """Return the rotation of ``degrees`` degrees."""
        return new_rotation(rot_rad(degrees / DEG))

    @staticmethod
    def fromRotations(double rotations):
        """Return the rotation of ``rotations`` full turns."""
        return new_rotation(rot_rad(rotations * 2.0 * M_PI))

    def getRadians(self):
        """Return the angle in rad, in [−π, π] (atan2 of the stored unit vector)."""
        return rot_radians(self.r)

    def getDegrees(self):
        """Return the angle in degrees, in [−180, 180]."""
        return rot_radians(self.r) * DEG

    def getRotations(self):
        """Return the angle in turns, in [−0.5, 0.5]."""
        return rot_radians(self.r) / (2.0 * M_PI)

    def getCos(self):
        """Return the cosine of the angle."""
        return self.r.c

    def getSin(self):
        """Return the sine of the angle."""
        return self.r.s

    def getTan(self):
        """Return the tangent of the angle (sin / cos; ±inf or NaN at ±90°)."""
        return self.r.s / self.r.c

    def rotateBy(self, other: Rotation2d):
        """Return this rotation followed by ``other`` (angles add)."""
        check_type(other, Rotation2d, "other")
        return new_rotation(rot_plus(self.r, (<Rotation2d>other).r))

    def plus(self, other: Rotation2d):
        """Same as :meth:`rotateBy`."""
        check_type(other, Rotation2d, "other")
        return new_rotation(rot_plus(self.r, (<Rotation2d>other).r))

    def minus(self, other: Rotation2d):
        """Return the rotation whose angle is this angle minus ``other``'s (wrapped)."""
        check_type(other, Rotation2d, "other")
        return new_rotation(rot_minus(self.r, (<Rotation2d>other).r))

    def relativeTo(self, other: Rotation2d):
        """Return this rotation seen from ``other`` (same as :meth:`minus`)."""
        check_type(other, Rotation2d, "other")
        return new_rotation(rot_minus(self.r, (<Rotation2d>other).r))

    def unaryMinus(self):
        """Return the inverse rotation."""
        return new_rotation(rot_neg(self.r))

    def times(self, double scalar):
        """Return the rotation by ``getRadians() * scalar``; the *wrapped* angle is scaled
        (270° × 0.5 = −45° in WPILib 2027)."""
        return new_rotation(rot_times(self.r, scalar))

    def div(self, double scalar):
        """Return ``times(1 / scalar)``."""
        return new_rotation(rot_times(self.r, 1.0 / scalar))

    def interpolate(self, end_value: Rotation2d, double t):
        """Return ``self + (end_value − self) · t``, the short way round; ``t`` is not
        clamped (2027)."""
        check_type(end_value, Rotation2d, "end_value")
        return new_rotation(rot_interp(self.r, (<Rotation2d>end_value).r, t))

    def toMatrix(self):
        """Return the 2×2 rotation matrix ``[[cos, −sin], [sin, cos]]``."""
        return np.array([[self.r.c, -self.r.s], [self.r.s, self.r.c]])

    def __add__(self, other):
        if isinstance(other, Rotation2d):
            return self.plus(other)
        return NotImplemented

    def __sub__(self, other):
        if isinstance(other, Rotation2d):
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

    def __eq__(self, other):
        if isinstance(other, Rotation2d):
            return rot_eq(self.r, (<Rotation2d>other).r)
        return NotImplemented

    __hash__ = None

    def __reduce__(self):
        return (_rotation_from_cos_sin, (self.r.c, self.r.s))

    def __repr__(self):
        return f"Rotation2d({rot_radians(self.r)!r})"

    def __str__(self):
        cdef double rad = rot_radians(self.r)
        return f"Rotation2d(Rads: {f2(rad)}, Deg: {f2(rad * DEG)})"


cdef rot2_t _rot_matrix(object m) except *:
    check_float64(m, "a rotation matrix")
    if m.shape != (2, 2):
        raise ValueError(f"a rotation matrix must have shape (2, 2), got {m.shape}")
    if np.linalg.norm(m @ m.T - np.eye(2)) > 1e-9:
        raise ValueError(f"Rotation matrix isn't orthogonal\n\nR =\n{m}")
    if abs(np.linalg.det(m) - 1.0) > 1e-9:
        raise ValueError(f"Rotation matrix is orthogonal but not special orthogonal\n\nR =\n{m}")
    cdef rot2_t r
    r.c = m[0, 0]
    r.s = m[1, 0]
    return r


cdef pose2_t _pose_matrix(object m) except *:
    check_float64(m, "an affine transformation matrix")
    if m.shape != (3, 3):
        raise ValueError(f"an affine transformation matrix must have shape (3, 3), got {m.shape}")
    if m[2, 0] != 0.0 or m[2, 1] != 0.0 or m[2, 2] != 1.0:
        raise ValueError("Affine transformation matrix is invalid: the last row must be [0, 0, 1]")
    return pose(vec(m[0, 2], m[1, 2]), _rot_matrix(m[:2, :2]))


def _rotation_from_cos_sin(double c, double s):
    """Rebuild a Rotation2d from its stored (cos, sin) exactly (used by pickle).

    Only pairs a constructor can produce are accepted: a unit vector (within 1e-9) or the
    NaN pair of a non-finite angle; anything else is a corrupted or crafted payload."""
    cdef rot2_t r
    if not (c != c and s != s) and not fabs(hypot(c, s) - 1.0) <= 1e-9:
        raise ValueError(f"a Rotation2d needs a unit (cos, sin) pair, got ({c!r}, {s!r})")
    r.c = c
    r.s = s
    return new_rotation(r)


# ---------------------------------------------------------------------------------------
cdef pose2_t _pose_args(object a, object b, object c, object translation, object rotation,
                        object x_, object y_, str cls) except *:
    """Parse (), (Translation2d, Rotation2d), (x, y, Rotation2d) or (3×3 matrix), where
    the documented keywords translation/rotation/x/y may stand for the positional ones."""
    cdef double x, y
    if translation is not MISSING or x_ is not MISSING or y_ is not MISSING \
            or rotation is not MISSING:
        if (translation is not MISSING and (a is not None or x_ is not MISSING)) \
                or (x_ is not MISSING and a is not None) \
                or (y_ is not MISSING and b is not None):
            raise TypeError(f"{cls}() got an argument both by position and by keyword")
        if translation is not MISSING:
            a = translation
        if x_ is not MISSING:
            a = x_
        if y_ is not MISSING:
            b = y_
        if rotation is not MISSING:
            if b is None and c is None:
                b = rotation
            elif c is None:
                c = rotation
            else:
                raise TypeError(f"{cls}() takes rotation= with translation= or with x and y")
    if a is None and b is None and c is None:
        return pose(vec(0.0, 0.0), rot_xy(1.0, 0.0))
    if b is None and c is None and isinstance(a, np.ndarray):
        return _pose_matrix(a)
    if c is None and isinstance(a, Translation2d) and isinstance(b, Rotation2d):
        return pose((<Translation2d>a).v, (<Rotation2d>b).r)
    if isinstance(c, Rotation2d) and a is not None and b is not None:
        x = a
        y = b
        return pose(vec(x, y), (<Rotation2d>c).r)
    # robotpy converts a number where a Rotation2d is expected: Rotation2d(radians).
    if c is None and isinstance(a, Translation2d) and is_number(b):
        return pose((<Translation2d>a).v, rot_rad(b))
    if is_number(c) and a is not None and b is not None:
        x = a
        y = b
        return pose(vec(x, y), rot_rad(c))
    if c is None and a is not None and b is not None and not isinstance(a, Translation2d):
        raise TypeError(f"{cls}() is missing its rotation: pass {cls}(x, y, Rotation2d) or "
                        f"{cls}(x, y, radians); got ({type_name(a)}, {type_name(b)})")
    raise TypeError(
        f"{cls}() takes (), (Translation2d, Rotation2d or radians), (x: float, y: float, "
        f"Rotation2d or radians) or (3x3 float64 numpy matrix); "
        f"got ({type_name(a)}, {type_name(b)}, {type_name(c)})")


# Pose2d and Transform2d share their layout (pose2_t) and every accessor; the freelist
# lives on the base because Cython lets only a base class manage one.
@cython.freelist(64)
cdef class _Frame2d:
    """Shared accessors of Pose2d and Transform2d (a translation in m and a rotation)."""

    def __cinit__(self):
        # A bare __new__ is the identity pose, never an invalid (0, 0) rotation.
        self.p.r.c = 1.0

    cdef _Frame2d _new(self, pose2_t p):
        raise TypeError("_Frame2d is an abstract base; use Pose2d or Transform2d")

    @property
    def x(self):
        """X component of the translation, m."""
        return self.p.t.x

    @property
    def y(self):
        """Y component of the translation, m."""
        return self.p.t.y

    def getX(self):
        """Return the x component of the translation, m."""
        return self.p.t.x

    def getY(self):
        """Return the y component of the translation, m."""
        return self.p.t.y

    def getTranslation(self):
        """Return the translation part (Translation2d, m)."""
        return new_translation(self.p.t)

    def getRotation(self):
        """Return the rotation part (Rotation2d)."""
        return new_rotation(self.p.r)

    def times(self, double scalar):
        """Return (translation · scalar, rotation.times(scalar))."""
        return self._new(pose_times(self.p, scalar))

    def div(self, double scalar):
        """Return ``times(1 / scalar)``."""
        return self._new(pose_times(self.p, 1.0 / scalar))

    def toMatrix(self):
        """Return the 3×3 homogeneous matrix ``[[cos, −sin, x], [sin, cos, y], [0, 0, 1]]``."""
        return np.array([[self.p.r.c, -self.p.r.s, self.p.t.x],
                         [self.p.r.s, self.p.r.c, self.p.t.y],
                         [0.0, 0.0, 1.0]])

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

    def __eq__(self, other):
        if type(other) is type(self):
            return vec_eq(self.p.t, (<_Frame2d>other).p.t) and rot_eq(self.p.r, (<_Frame2d>other).p.r)
        return NotImplemented

    __hash__ = None

    def __reduce__(self):
        return (type(self), (new_translation(self.p.t), new_rotation(self.p.r)))

    def __repr__(self):
        return (f"{type(self).__name__}({self.p.t.x!r}, {self.p.t.y!r}, "
                f"Rotation2d({rot_radians(self.p.r)!r}))")

    def __str__(self):
        return f"{type(self).__name__}({new_translation(self.p.t)}, {new_rotation(self.p.r)})"


cdef class Pose2d(_Frame2d):
    """Pose2d() or Pose2d(translation, rotation) or Pose2d(x, y, rotation) or Pose2d(matrix)

    A robot pose on the field: position in m and heading as a :class:`Rotation2d`.
    ``Pose2d(matrix)`` takes a 3×3 homogeneous float64 numpy array (see :meth:`toMatrix`).
    Immutable; ``==`` compares translation within 1e-9 m and rotation within 1e-9.
    """

    def __init__(self, a=None, b=None, c=None, /, *, translation=MISSING, rotation=MISSING,
                 x=MISSING, y=MISSING):
        refuse_reinit(self.frozen, self)
        self.p = _pose_args(a, b, c, translation, rotation, x, y, "Pose2d")
        self.frozen = True

    cdef _Frame2d _new(self, pose2_t p):
        return new_pose(p)

    def transformBy(self, other: Transform2d):
        """Return this pose moved by ``other``, expressed in this pose's frame."""
        check_type(other, Transform2d, "other")
        return new_pose(pose_transform_by(self.p, (<Transform2d>other).p))

    def plus(self, other: Transform2d):
        """Same as :meth:`transformBy`."""
        check_type(other, Transform2d, "other")
        return new_pose(pose_transform_by(self.p, (<Transform2d>other).p))

    def minus(self, other: Pose2d):
        """Return the Transform2d that maps ``other`` onto this pose."""
        check_type(other, Pose2d, "other")
        return new_transform(pose_relative_to(self.p, (<Pose2d>other).p))

    def relativeTo(self, other: Pose2d):
        """Return this pose expressed in the frame of ``other``."""
        check_type(other, Pose2d, "other")
        return new_pose(pose_relative_to(self.p, (<Pose2d>other).p))

    def rotateBy(self, other: Rotation2d):
        """Return the pose rotated about the field origin (position and heading)."""
        check_type(other, Rotation2d, "other")
        cdef rot2_t r = (<Rotation2d>other).r
        return new_pose(pose(vec_rotate(self.p.t, r), rot_plus(self.p.r, r)))

    def rotateAround(self, point: Translation2d, rot: Rotation2d):
        """Return the pose rotated by ``rot`` about ``point``; the heading turns by ``rot``."""
        check_type(point, Translation2d, "point")
        check_type(rot, Rotation2d, "rot")
        cdef vec2_t c = (<Translation2d>point).v
        cdef rot2_t r = (<Rotation2d>rot).r
        cdef vec2_t d = vec_rotate(vec(self.p.t.x - c.x, self.p.t.y - c.y), r)
        return new_pose(pose(vec(d.x + c.x, d.y + c.y), rot_plus(self.p.r, r)))

    def exp(self, twist: Twist2d):
        """Return ``self.plus(twist.exp())`` in one call (the WPILib 2026 ``Pose2d.exp``;
        2027 spells it ``pose.plus(twist.exp())`` and both give the same numbers)."""
        check_type(twist, Twist2d, "twist")
        cdef twist2_t tw = (<Twist2d>twist).t
        return new_pose(pose_transform_by(self.p, twist_exp(tw.dx, tw.dy, tw.dtheta)))

    def log(self, end: Pose2d):
        """Return ``end.minus(self).log()`` (the WPILib 2026 ``Pose2d.log``)."""
        check_type(end, Pose2d, "end")
        cdef twist2_t tw = transform_log(pose_relative_to((<Pose2d>end).p, self.p))
        return new_twist(tw.dx, tw.dy, tw.dtheta)

    def nearest(self, poses):
        """Return the pose in ``poses`` closest to this one: smallest translation distance,
        ties broken by the smallest heading difference."""
        cdef Pose2d best = None, q
        cdef double bd = 0.0, ba = 0.0, d, a
        for o in poses:
            # Exact type test: a typed loop variable would let None through.
            if type(o) is not Pose2d:
                raise TypeError(f"nearest() takes Pose2d objects, got {type_name(o)}")
            q = <Pose2d>o
            d = hypot(q.p.t.x - self.p.t.x, q.p.t.y - self.p.t.y)
            a = fabs(rot_radians(rot_minus(self.p.r, q.p.r)))
            if best is None or d < bd or (d == bd and a < ba):
                best, bd, ba = q, d, a
        if best is None:
            raise ValueError("nearest() of an empty sequence")
        return best

    def interpolate(self, end_value: Pose2d, double t):
        """Interpolate along the constant-curvature arc to ``end_value``.

        ``t < 0`` returns this pose and ``t ≥ 1`` returns ``end_value`` (WPILib's clamp)."""
        check_type(end_value, Pose2d, "end_value")
        if t < 0.0:
            return self
        if t >= 1.0:
            return end_value
        return new_pose(pose_interpolate(self.p, (<Pose2d>end_value).p, t))

    def __add__(self, other):
        if isinstance(other, Transform2d):
            return self.plus(other)
        return NotImplemented

    def __sub__(self, other):
        if isinstance(other, Pose2d):
            return self.minus(other)
        return NotImplemented

    @staticmethod
    def fromFeet(double x, double y, angle):
        """Return the pose at (``x``, ``y``) given in feet, in metres, with heading
        ``angle`` (a :class:`Rotation2d`, or rad as a float); robotpy-wpimath's
        ``Pose2d.fromFeet`` (1 ft = 0.3048 m, same bits)."""
        return new_pose(pose(vec(feet_to_meters(x), feet_to_meters(y)),
                             feet_angle(angle, "Pose2d.fromFeet(x, y, angle)")))


# ---------------------------------------------------------------------------------------
cdef class Transform2d(_Frame2d):
    """Transform2d() or Transform2d(translation, rotation) or Transform2d(x, y, rotation)
    or Transform2d(initial, final) or Transform2d(matrix)

    A rigid motion: a translation in m followed by a rotation, expressed in the frame it
    is applied to. ``Transform2d(initial, final)`` with two :class:`Pose2d` gives the
    transform that maps ``initial`` onto ``final``. Immutable; ``==`` as for Pose2d.
    """

    def __init__(self, a=None, b=None, c=None, /, *, translation=MISSING, rotation=MISSING,
                 x=MISSING, y=MISSING, initial=MISSING, final=MISSING):
        refuse_reinit(self.frozen, self)
        if initial is not MISSING or final is not MISSING:
            if a is not None or b is not None:
                raise TypeError("Transform2d() got an argument both by position and by keyword")
            a = None if initial is MISSING else initial
            b = None if final is MISSING else final
            if not (isinstance(a, Pose2d) and isinstance(b, Pose2d)):
                raise TypeError("Transform2d(initial, final) takes two Pose2d, got "
                                f"{type_name(a)} and {type_name(b)}")
        if c is None and isinstance(a, Pose2d) and isinstance(b, Pose2d):
            self.p = pose_relative_to((<Pose2d>b).p, (<Pose2d>a).p)
        else:
            self.p = _pose_args(a, b, c, translation, rotation, x, y, "Transform2d")
        self.frozen = True

    cdef _Frame2d _new(self, pose2_t p):
        return new_transform(p)

    def inverse(self):
        """Return the transform that undoes this one."""
        return new_transform(transform_inverse(self.p))

    def plus(self, other: Transform2d):
        """Return this transform followed by ``other``."""
        check_type(other, Transform2d, "other")
        return new_transform(pose_transform_by(self.p, (<Transform2d>other).p))

    def log(self):
        """Return the Twist2d whose :meth:`Twist2d.exp` is this transform (the
        constant-curvature arc; the inverse of exp)."""
        cdef twist2_t tw = transform_log(self.p)
        return new_twist(tw.dx, tw.dy, tw.dtheta)

    def __add__(self, other):
        if isinstance(other, Transform2d):
            return self.plus(other)
        return NotImplemented

    @staticmethod
    def fromFeet(double x, double y, angle):
        """Return the transform with translation (``x``, ``y``) given in feet, in metres,
        and rotation ``angle`` (a :class:`Rotation2d`, or rad as a float);
        robotpy-wpimath's ``Transform2d.fromFeet`` (1 ft = 0.3048 m, same bits)."""
        return new_transform(pose(vec(feet_to_meters(x), feet_to_meters(y)),
                                  feet_angle(angle, "Transform2d.fromFeet(x, y, angle)")))


# ---------------------------------------------------------------------------------------
@cython.freelist(64)
cdef class Twist2d:
    """Twist2d(dx=0.0, dy=0.0, dtheta=0.0)

    A motion along a constant-curvature arc: ``dx``, ``dy`` in m (in the start frame) and
    ``dtheta`` in rad. Mutable, like WPILib's public fields; ``==`` compares each field
    within 1e-9, so instances are unhashable.
    """

    def __init__(self, double dx=0.0, double dy=0.0, double dtheta=0.0):
        self.t.dx = dx
        self.t.dy = dy
        self.t.dtheta = dtheta

    @property
    def dx(self):
        """Change along the start frame's x axis, m."""
        return self.t.dx

    @dx.setter
    def dx(self, double value):
        self.t.dx = value

    @property
    def dy(self):
        """Change along the start frame's y axis, m."""
        return self.t.dy

    @dy.setter
    def dy(self, double value):
        self.t.dy = value

    @property
    def dtheta(self):
        """Change in heading, rad."""
        return self.t.dtheta

    @dtheta.setter
    def dtheta(self, double value):
        self.t.dtheta = value

    def exp(self):
        """Return the Transform2d reached by following this arc from the origin.

        Uses the series form when ``|dtheta| < 1e-9``."""
        return new_transform(twist_exp(self.t.dx, self.t.dy, self.t.dtheta))

    def __eq__(self, other):
        cdef Twist2d o
        if isinstance(other, Twist2d):
            o = <Twist2d>other
            return (fabs(self.t.dx - o.t.dx) < 1e-9 and fabs(self.t.dy - o.t.dy) < 1e-9
                    and fabs(self.t.dtheta - o.t.dtheta) < 1e-9)
        return NotImplemented

    __hash__ = None

    def __mul__(self, factor):
        """Return the twist with each component times ``factor`` (WPILib C++'s
        ``operator*``, robotpy's ``*``; Java has none)."""
        if not is_number(factor):
            return NotImplemented
        cdef double k = factor
        return new_twist(self.t.dx * k, self.t.dy * k, self.t.dtheta * k)

    def __rmul__(self, factor):
        return self.__mul__(factor)

    def __reduce__(self):
        return (Twist2d, (self.t.dx, self.t.dy, self.t.dtheta))

    def __delattr__(self, name):
        refuse_delete(self, name)

    def __repr__(self):
        return f"Twist2d(dx={self.t.dx!r}, dy={self.t.dy!r}, dtheta={self.t.dtheta!r})"

    def __str__(self):
        return f"Twist2d(dX: {f2(self.t.dx)}, dY: {f2(self.t.dy)}, dTheta: {f2(self.t.dtheta)})"

    @staticmethod
    def fromFeet(double dx=0.0, double dy=0.0, double dtheta=0.0):
        """Return the twist with ``dx``, ``dy`` given in feet (converted to m) and
        ``dtheta`` in rad; robotpy-wpimath's ``Twist2d.fromFeet`` (1 ft = 0.3048 m, same
        bits)."""
        return new_twist(feet_to_meters(dx), feet_to_meters(dy), dtheta)


# WPILib's named constants.
for _name, _value in (("kZero", Translation2d()),):
    drivekin_set_type_attr(Translation2d, _name, _value)
for _name, _value in (
    ("kZero", Rotation2d()),
    ("kCW_Pi_2", Rotation2d(-M_PI / 2)), ("kCW_90deg", Rotation2d(-M_PI / 2)),
    ("kCCW_Pi_2", Rotation2d(M_PI / 2)), ("kCCW_90deg", Rotation2d(M_PI / 2)),
    ("kPi", Rotation2d(M_PI)), ("k180deg", Rotation2d(M_PI)),
):
    drivekin_set_type_attr(Rotation2d, _name, _value)
drivekin_set_type_attr(Pose2d, "kZero", Pose2d())
drivekin_set_type_attr(Transform2d, "kZero", Transform2d())
del _name, _value
