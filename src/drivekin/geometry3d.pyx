"""3-D geometry with WPILib 2027 semantics: Quaternion, Rotation3d, Translation3d, Pose3d,
Transform3d, Twist3d, CoordinateAxis and CoordinateSystem.

Units: metres and radians. Frame: x forward, y left, z up (NWU), angles counter-clockwise
about their axis. A vector argument is any sequence of 3 floats (a list, a tuple, a
float64 numpy array); vectors and matrices come back as float64 numpy arrays of shape
(3,), (3, 3) and (4, 4). All classes except :class:`Twist3d` are immutable. Equality uses
WPILib's tolerances, so the values are deliberately unhashable (q and −q are the same
Rotation3d, and rotations within about 8.9e-5 rad of each other compare equal).
"""
cimport cython
from libc.math cimport INFINITY, M_PI, fabs, isfinite
cimport numpy as cnp

import numpy as np

from drivekin._core.types cimport pose2_t, pose3_t, quat_t, rot2_t, twist3_t, vec3_t
from drivekin._core.args cimport check_float64, check_type, is_number, read_floats, refuse_reinit
from drivekin._core.kernels cimport feet_to_meters, pose, rot_rad, rot_radians, vec
from drivekin._core.kernels3d cimport (
    matrix_det, matrix_orthogonality, norm3, pose3, pose3_interpolate, pose3_log, pose3_plus,
    pose3_relative_to, pose3_rotate_by, pose3_times, q_conjugate, q_div, q_dot, q_eq, q_exp,
    q_from_axis_angle, q_from_euler, q_from_matrix, q_from_rvec, q_from_rvec_static,
    q_from_vectors, q_identity, q_inverse, q_log, q_max_abs, q_mul, q_norm, q_normalize, q_pow,
    q_scale, q_to_rvec, quat, rot3_angle, rot3_apply, rot3_eq, rot3_integrate, rot3_interpolate,
    rot3_inverse, rot3_matrix, rot3_relative_to, rot3_rotate_by, rot3_times, rot3_x, rot3_y,
    rot3_yaw, rot3_z, transform3_inverse, twist3, twist3_exp, v3_add, v3_cross, v3_dot, v3_eq,
    v3_scale, v3_sub, vec3,
)
from drivekin.geometry cimport (Pose2d, Rotation2d, Transform2d, Translation2d, new_pose,
                                new_rotation, new_translation)
from drivekin._core.errors import refuse_delete, type_name
from drivekin._core.format import f2, jstr
from drivekin._core.typedict cimport drivekin_set_type_attr

cnp.import_array()

cdef double DEG = 180.0 / M_PI

# Marks an argument that was not passed (None is a value callers may pass by mistake).
cdef object MISSING = object()


# ---------------------------------------------------------------------------------------
# Argument readers

cdef double number(object x, str where) except? -1.0:
    # A double argument by Cython's rule (anything with __float__ or __index__, never text).
    if type(x) is float:
        return <double>x
    if isinstance(x, (str, bytes, bytearray)):
        raise TypeError(f"{where} must be a float, got {type_name(x)}")
    try:
        return x
    except TypeError:
        raise TypeError(f"{where} must be a float, got {type_name(x)}") from None


cdef vec3_t vector3(object a, str what) except *:
    # A Vector3: any sequence of 3 floats (list, tuple, float64 array of shape (3,) or
    # (3, 1), WPILib's column vector).
    cdef double v[3]
    if cnp.PyArray_Check(a) and a.shape == (3, 1):
        a = a[:, 0]
    read_floats(a, 3, v, what, "floats")
    return vec3(v[0], v[1], v[2])


cdef bint is_vector(object a) noexcept:
    # Whether a positional argument is meant as a Vector3 (as opposed to a number or a
    # value object); its contents are checked when it is read.
    return isinstance(a, (list, tuple)) or cnp.PyArray_Check(a)


cdef void matrix_values(object m, int n, str what, double* out) except *:
    # An n×n float64 numpy array, read row by row into out.
    cdef int i, j
    if not cnp.PyArray_Check(m):
        raise TypeError(f"{what} must be a {n}x{n} float64 numpy array, got {type_name(m)}")
    check_float64(m, what)
    if m.shape != (n, n):
        raise ValueError(f"{what} must have shape ({n}, {n}), got {m.shape}")
    rows = m.tolist()
    for i in range(n):
        for j in range(n):
            out[n * i + j] = rows[i][j]


cdef quat_t rotation_matrix(const double* R, str where) except *:
    # Rotation3d(Matrix3), with WPILib's two checks (ValueError: Java's
    # IllegalArgumentException, C++'s std::domain_error).
    if matrix_orthogonality(R) > 1e-9:
        raise ValueError(f"{where}: Rotation matrix isn't orthogonal (the Frobenius norm of "
                         "R·Rᵀ − I exceeds 1e-9)\n\nR =\n" + _matrix_text(R, 3))
    if fabs(matrix_det(R) - 1.0) > 1e-9:
        raise ValueError(f"{where}: Rotation matrix is orthogonal but not special orthogonal "
                         "(abs(det R − 1) exceeds 1e-9)\n\nR =\n" + _matrix_text(R, 3))
    return q_from_matrix(R)


cdef str _matrix_text(const double* m, int n):
    return str(np.array([[m[n * i + j] for j in range(n)] for i in range(n)]))


cdef pose3_t affine_matrix(object m, str where) except *:
    # Pose3d / Transform3d (Matrix4): the rotation block is checked first, then the bottom
    # row, which must be exactly (0, 0, 0, 1), as in WPILib.
    cdef double a[16]
    cdef double R[9]
    cdef int i, j
    matrix_values(m, 4, f"{where} (matrix)", a)
    for i in range(3):
        for j in range(3):
            R[3 * i + j] = a[4 * i + j]
    cdef quat_t q = rotation_matrix(R, where)
    if a[12] != 0.0 or a[13] != 0.0 or a[14] != 0.0 or a[15] != 1.0:
        raise ValueError(f"{where}: Affine transformation matrix is invalid: the bottom row "
                         f"must be exactly (0, 0, 0, 1), got ({a[12]!r}, {a[13]!r}, "
                         f"{a[14]!r}, {a[15]!r})")
    return pose3(vec3(a[3], a[7], a[11]), q)


cdef quat_t yaw_rotation(rot2_t r) noexcept:
    # Rotation3d(Rotation2d) = Rotation3d(0, 0, rotation.getRadians()).
    return q_from_euler(0.0, 0.0, rot_radians(r))


cdef tuple keyword_form(str cls, tuple forms, tuple given, dict kw):
    """The constructor form that the positional arguments ``given`` and the keyword
    arguments ``kw`` (names of the forms) spell: (its index, its arguments in order).
    The keywords pick the form; the positional arguments come first in it."""
    cdef Py_ssize_t k = len(given), i
    for i, form in enumerate(forms):
        if len(form) == k + len(kw) and set(form[k:]) == set(kw):
            return i, given + tuple(kw[n] for n in form[k:])
    spelled = " or ".join(f"{cls}({', '.join(f)})" for f in forms)
    raise TypeError(f"{cls}() takes {spelled}; got {k} positional argument(s) and the "
                    f"keyword(s) {', '.join(sorted(kw))}")


cdef dict given_keywords(tuple names, tuple values):
    return {n: v for n, v in zip(names, values) if v is not MISSING}


# ---------------------------------------------------------------------------------------
@cython.freelist(32)
cdef class Quaternion:
    """Quaternion(w=1.0, x=0.0, y=0.0, z=0.0)

    A quaternion w + xi + yj + zk (WPILib's Quaternion: not normalised automatically).
    Immutable; ``==`` is WPILib's: the same direction and the same norm, each within
    1e-9 (so q and −q differ as Quaternions, although they are the same rotation).
    """

    def __cinit__(self):
        # A bare Quaternion.__new__ is the default (1, 0, 0, 0).
        self.q.w = 1.0

    def __init__(self, double w=1.0, double x=0.0, double y=0.0, double z=0.0):
        refuse_reinit(self.frozen, self)
        self.q = quat(w, x, y, z)
        self.frozen = True

    @property
    def w(self):
        """W (scalar) component."""
        return self.q.w

    @property
    def x(self):
        """X component."""
        return self.q.x

    @property
    def y(self):
        """Y component."""
        return self.q.y

    @property
    def z(self):
        """Z component."""
        return self.q.z

    def getW(self):
        """Return the W (scalar) component."""
        return self.q.w

    def getX(self):
        """Return the X component."""
        return self.q.x

    def getY(self):
        """Return the Y component."""
        return self.q.y

    def getZ(self):
        """Return the Z component."""
        return self.q.z

    def plus(self, other: Quaternion):
        """Return the component-wise sum."""
        check_type(other, Quaternion, "other")
        cdef quat_t o = (<Quaternion>other).q
        return new_quaternion(quat(self.q.w + o.w, self.q.x + o.x, self.q.y + o.y,
                                   self.q.z + o.z))

    def minus(self, other: Quaternion):
        """Return the component-wise difference."""
        check_type(other, Quaternion, "other")
        cdef quat_t o = (<Quaternion>other).q
        return new_quaternion(quat(self.q.w - o.w, self.q.x - o.x, self.q.y - o.y,
                                   self.q.z - o.z))

    def times(self, other):
        """Return the Hamilton product ``self·other`` for a Quaternion ``other``, or every
        component times ``other`` for a float."""
        if type(other) is Quaternion:
            return new_quaternion(q_mul(self.q, (<Quaternion>other).q))
        return new_quaternion(q_scale(self.q, number(other, "Quaternion.times(scalar)")))

    def divide(self, double scalar):
        """Return every component divided by ``scalar`` (no zero guard, as in WPILib)."""
        return new_quaternion(q_div(self.q, scalar))

    def conjugate(self):
        """Return (w, −x, −y, −z)."""
        return new_quaternion(q_conjugate(self.q))

    def dot(self, other: Quaternion):
        """Return the sum of the component-wise products."""
        check_type(other, Quaternion, "other")
        return q_dot(self.q, (<Quaternion>other).q)

    def inverse(self):
        """Return the conjugate divided by the squared norm. ValueError for the zero
        quaternion (WPILib's 0/0 NaNs), or if the result overflows."""
        if self.q.w == 0.0 and self.q.x == 0.0 and self.q.y == 0.0 and self.q.z == 0.0:
            raise ValueError("Quaternion.inverse(): the zero quaternion has no inverse")
        return finite_quaternion(q_inverse(self.q), self.q, "inverse", 1.0)

    def norm(self):
        """Return the Euclidean norm sqrt(w² + x² + y² + z²)."""
        return q_norm(self.q)

    def normalize(self):
        """Return this quaternion divided by its norm; a zero quaternion gives the
        identity (1, 0, 0, 0). WPILib C++'s bits wherever the squared norm is a normal
        double; outside, the quaternion is first scaled by an exact power of two (so
        subnormal and huge quaternions come out unit, not off-unit or zero)."""
        return new_quaternion(q_normalize(self.q))

    def pow(self, double t):
        """Return this quaternion raised to the power ``t``: ``(log() · t).exp()``.
        ValueError if the result overflows (a norm beyond the largest double)."""
        return finite_quaternion(q_pow(self.q, t), self.q, "pow", t)

    def exp(self):
        """Return the quaternion exponential e^w (cos‖v‖, v sin‖v‖/‖v‖), v = (x, y, z).
        ValueError if e^w overflows (w > 709.78...)."""
        return finite_quaternion(q_exp(self.q), self.q, "exp", 1.0)

    def log(self):
        """Return the quaternion logarithm (ln‖q‖, v·atan2(‖v‖, w)/‖v‖); a zero
        quaternion gives (0, 0, 0, 0) and w/‖q‖ = −1 gives (ln‖q‖, −π, 0, 0)."""
        return new_quaternion(q_log(self.q))

    def toRotationVector(self):
        """Return the rotation vector (rad) of the rotation this quaternion represents,
        the short way round (angle at most π), as a float64 array of shape (3,). It does
        not depend on the norm (WPILib's small-angle series, taken for ‖v‖ < 1e-9 alone,
        does for a non-unit quaternion); the zero quaternion gives (0, 0, 0), the identity,
        as :meth:`normalize` and ``Rotation3d(q)`` make it."""
        cdef vec3_t r = q_to_rvec(self.q)
        return np.array([r.x, r.y, r.z])

    @staticmethod
    def fromRotationVector(rvec):
        """Return the quaternion (cos θ/2, rvec·sin(θ/2)/θ) of the rotation vector
        ``rvec`` (3 floats, rad), θ = ‖rvec‖."""
        return new_quaternion(q_from_rvec_static(vector3(rvec, "rvec")))

    def __add__(self, other):
        if type(other) is Quaternion:
            return self.plus(other)
        return NotImplemented

    def __sub__(self, other):
        if type(other) is Quaternion:
            return self.minus(other)
        return NotImplemented

    def __mul__(self, other):
        if type(other) is Quaternion or is_number(other):
            return self.times(other)
        return NotImplemented

    def __rmul__(self, other):
        if is_number(other):
            return self.times(other)
        return NotImplemented

    def __truediv__(self, other):
        if is_number(other):
            return self.divide(other)
        return NotImplemented

    def __eq__(self, other):
        if type(other) is Quaternion:
            return q_eq(self.q, (<Quaternion>other).q)
        return NotImplemented

    __hash__ = None

    def __reduce__(self):
        return (Quaternion, (self.q.w, self.q.x, self.q.y, self.q.z))

    def __repr__(self):
        return f"Quaternion(w={self.q.w!r}, x={self.q.x!r}, y={self.q.y!r}, z={self.q.z!r})"

    def __str__(self):
        return (f"Quaternion({jstr(self.q.w)}, {jstr(self.q.x)}, {jstr(self.q.y)}, "
                f"{jstr(self.q.z)})")


cdef inline bint q_finite(quat_t q):
    return isfinite(q.w) and isfinite(q.x) and isfinite(q.y) and isfinite(q.z)


cdef Quaternion finite_quaternion(quat_t r, quat_t q, str what, double t):
    # Quaternion.exp, pow and inverse of finite input are finite or refused: a result too
    # large for a double would otherwise come out as inf and NaN (0 · inf).
    if q_finite(r) or not (q_finite(q) and isfinite(t)):
        return new_quaternion(r)
    raise ValueError(f"Quaternion.{what}() overflows: the result's norm is beyond the largest "
                     f"double (for exp, e^w with w > 709.78); got {new_quaternion(q)!r}"
                     + (f" and t = {t!r}" if what == "pow" else ""))


cdef quat_t rotation_in_range(quat_t r, quat_t q, double a, double b, str what) except *:
    # Rotation3d.times, div, interpolate and integrate of a finite rotation and finite
    # numbers are finite or refused: an angle beyond the largest double (a huge scalar or
    # rate·dt, or div by a tiny or zero one) would come out as NaN.
    if q_finite(r) or not (q_finite(q) and isfinite(a) and isfinite(b)):
        return r
    raise ValueError(f"Rotation3d.{what}: the resulting rotation angle is beyond the "
                     "largest double (a scalar, t or rate·dt too large, or a division by "
                     "zero or a tiny number)")


cdef inline double whole_turns_away(double turns):
    # Above 1e300 turns (where turns·2π could overflow) every double is a whole number of
    # turns: no rotation.
    return turns if fabs(turns) <= 1e300 else 0.0


# ---------------------------------------------------------------------------------------
cdef quat_t rotation_form(int form, tuple a) except *:
    # One Rotation3d constructor form, its arguments checked: 0 (q), 1 (roll, pitch, yaw),
    # 2 (axis, angle), 3 (rvec), 4 (rotation_matrix), 5 (initial, final), 6 (rotation).
    cdef double R[9]
    if form == 0:
        check_type(a[0], Quaternion, "q")
        return q_normalize((<Quaternion>a[0]).q)
    if form == 1:
        return q_from_euler(number(a[0], "roll"), number(a[1], "pitch"),
                            number(a[2], "yaw"))
    if form == 2:
        return q_from_axis_angle(vector3(a[0], "axis"), number(a[1], "angle"))
    if form == 3:
        return q_from_rvec(vector3(a[0], "rvec"))
    if form == 4:
        matrix_values(a[0], 3, "rotation_matrix", R)
        return rotation_matrix(R, "Rotation3d(rotation_matrix)")
    if form == 5:
        return q_from_vectors(vector3(a[0], "initial"), vector3(a[1], "final"))
    check_type(a[0], Rotation2d, "rotation")
    return yaw_rotation((<Rotation2d>a[0]).r)


cdef quat_t rotation_positional(tuple a) except *:
    # The form of positional-only arguments, told apart by their types.
    cdef Py_ssize_t n = len(a)
    if n == 0:
        return q_identity()
    if n == 3:
        return rotation_form(1, a)
    if n == 1:
        x = a[0]
        if type(x) is Quaternion:
            return rotation_form(0, a)
        if type(x) is Rotation2d:
            return rotation_form(6, a)
        if cnp.PyArray_Check(x) and (<cnp.ndarray>x).ndim == 2 and x.shape != (3, 1):
            return rotation_form(4, a)
        if is_vector(x):
            return rotation_form(3, a)
    elif n == 2 and is_vector(a[0]):
        return rotation_form(5 if is_vector(a[1]) else 2, a)
    raise TypeError(
        "Rotation3d() takes (), (q: Quaternion), (roll, pitch, yaw: float, rad), "
        "(axis: 3 floats, angle: float, rad), (rvec: 3 floats, rad), (rotation_matrix: "
        "3x3 float64 numpy array), (initial: 3 floats, final: 3 floats) or (rotation: "
        f"Rotation2d); got ({', '.join(type_name(x) for x in a)})")


@cython.freelist(64)
cdef class Rotation3d:
    """Rotation3d() or Rotation3d(roll, pitch, yaw) or Rotation3d(q) or
    Rotation3d(axis, angle) or Rotation3d(rvec) or Rotation3d(rotation_matrix) or
    Rotation3d(initial, final) or Rotation3d(rotation)

    A rotation in space, stored as a unit quaternion (WPILib 2027's Rotation3d).

    * ``(roll, pitch, yaw)``: extrinsic rotations in rad about the fixed X, then Y, then Z
      axis.
    * ``(q)``: a :class:`Quaternion`, normalised (a zero quaternion gives the identity).
    * ``(axis, angle)``: a rotation of ``angle`` rad about ``axis`` (3 floats, any length;
      a zero axis gives the identity, as in WPILib).
    * ``(rvec)``: a rotation vector (3 floats, rad): axis times angle.
    * ``(rotation_matrix)``: a 3×3 float64 numpy array; ValueError if the Frobenius norm of
      RRᵀ − I, or abs(det R − 1), exceeds 1e-9.
    * ``(initial, final)``: the shortest rotation that turns the direction ``initial``
      onto ``final`` (3 floats each); antiparallel vectors give a half turn about an axis
      perpendicular to ``initial``, chosen as WPILib does.
    * ``(rotation)``: a :class:`Rotation2d` as a yaw.

    Immutable; ``==`` is WPILib's: q and −q are equal, and so are rotations within about
    8.9e-5 rad of each other (abs(abs(q·q') − 1) < 1e-9).
    """

    def __cinit__(self):
        # A bare Rotation3d.__new__ is the identity, never the invalid (0, 0, 0, 0).
        self.q.w = 1.0

    def __init__(self, roll=MISSING, pitch=MISSING, yaw=MISSING):
        cdef quat_t r
        refuse_reinit(self.frozen, self)
        if type(roll) is float and type(pitch) is float and type(yaw) is float:
            r = q_from_euler(<double>roll, <double>pitch, <double>yaw)
        else:
            r = rotation_positional(_given(roll, pitch, yaw, "Rotation3d", "roll, pitch, yaw"))
        self.q = r
        self.frozen = True

    @staticmethod
    def fromRadians(double roll, double pitch, double yaw):
        """Return ``Rotation3d(roll, pitch, yaw)`` (extrinsic, rad)."""
        return new_rotation3d(q_from_euler(roll, pitch, yaw))

    @staticmethod
    def fromDegrees(double roll, double pitch, double yaw):
        """Return the rotation of extrinsic ``roll``, ``pitch`` and ``yaw`` given in
        degrees."""
        return new_rotation3d(q_from_euler(roll / DEG, pitch / DEG, yaw / DEG))

    @staticmethod
    def fromRotations(double roll, double pitch, double yaw):
        """Return the rotation of extrinsic ``roll``, ``pitch`` and ``yaw`` given in turns."""
        return new_rotation3d(q_from_euler(whole_turns_away(roll) * 2.0 * M_PI,
                                           whole_turns_away(pitch) * 2.0 * M_PI,
                                           whole_turns_away(yaw) * 2.0 * M_PI))

    @property
    def x(self):
        """Roll, rad: the counter-clockwise rotation about the X axis (``getX()``)."""
        return rot3_x(self.q)

    @property
    def y(self):
        """Pitch, rad: the counter-clockwise rotation about the Y axis (``getY()``)."""
        return rot3_y(self.q)

    @property
    def z(self):
        """Yaw, rad: the counter-clockwise rotation about the Z axis (``getZ()``)."""
        return rot3_z(self.q)

    @property
    def angle(self):
        """Rotation angle about :meth:`getAxis`, rad, in [0, 2π] (``getAngle()``)."""
        return rot3_angle(self.q)

    def getX(self):
        """Return the roll, rad, in [−π, π]: the extrinsic rotation about X (0 at gimbal
        lock, where pitch is ±π/2)."""
        return rot3_x(self.q)

    def getY(self):
        """Return the pitch, rad, in [−π/2, π/2]: the extrinsic rotation about Y."""
        return rot3_y(self.q)

    def getZ(self):
        """Return the yaw, rad, in [−π, π]: the extrinsic rotation about Z (at gimbal lock
        it carries roll and yaw together)."""
        return rot3_z(self.q)

    def getAngle(self):
        """Return the rotation angle about :meth:`getAxis`, rad, 2·atan2(‖v‖, w) in
        [0, 2π]."""
        return rot3_angle(self.q)

    def getAxis(self):
        """Return the unit rotation axis as a float64 array of shape (3,); the identity
        gives (0, 0, 0)."""
        cdef double n = norm3(self.q.x, self.q.y, self.q.z)
        if n == 0.0:
            return np.zeros(3)
        return np.array([self.q.x / n, self.q.y / n, self.q.z / n])

    def getQuaternion(self):
        """Return the stored unit quaternion."""
        return new_quaternion(self.q)

    def toMatrix(self):
        """Return the 3×3 rotation matrix (float64 array)."""
        cdef double R[9]
        rot3_matrix(self.q, R)
        return np.array([[R[0], R[1], R[2]], [R[3], R[4], R[5]], [R[6], R[7], R[8]]])

    def toVector(self):
        """Return the rotation vector (axis times angle, rad) as a float64 array of shape
        (3,), the short way round (angle at most π)."""
        cdef vec3_t r = q_to_rvec(self.q)
        return np.array([r.x, r.y, r.z])

    def toRotation2d(self):
        """Return the yaw (:meth:`getZ`) as a Rotation2d (not a projection of the
        rotated x axis)."""
        return new_rotation(rot3_yaw(self.q))

    def inverse(self):
        """Return the rotation that undoes this one."""
        return new_rotation3d(rot3_inverse(self.q))

    def rotateBy(self, other: Rotation3d):
        """Return this rotation followed by ``other``, applied about the fixed (extrinsic)
        axes: the quaternion ``other·self``."""
        check_type(other, Rotation3d, "other")
        return new_rotation3d(rot3_rotate_by(self.q, (<Rotation3d>other).q))

    def relativeTo(self, other: Rotation3d):
        """Return this rotation seen from ``other``: the quaternion ``other⁻¹·self`` (so
        ``a.relativeTo(b)`` applied after ``b``, intrinsically, gives ``a``)."""
        check_type(other, Rotation3d, "other")
        return new_rotation3d(rot3_relative_to(self.q, (<Rotation3d>other).q))

    def times(self, double scalar):
        """Return the rotation scaled by ``scalar`` along the shortest path from the
        identity (``Rotation3d.kZero.interpolate(self, scalar)``, 2027)."""
        return new_rotation3d(rotation_in_range(rot3_times(self.q, scalar), self.q, scalar,
                                                0.0, "times()"))

    def div(self, double scalar):
        """Return ``times(1 / scalar)``."""
        return new_rotation3d(rotation_in_range(rot3_times(self.q, 1.0 / scalar), self.q,
                                                scalar, 0.0, "div()"))

    def interpolate(self, end_value: Rotation3d, double t):
        """Return the spherical linear interpolation towards ``end_value``, the short way:
        ``(q1·q0⁻¹)^t·q0``; ``t`` is not clamped (2027)."""
        check_type(end_value, Rotation3d, "end_value")
        cdef quat_t e = (<Rotation3d>end_value).q
        return new_rotation3d(rotation_in_range(rot3_interpolate(self.q, e, t), e, t,
                                                q_max_abs(self.q), "interpolate()"))

    def integrate(self, double roll_rate, double pitch_rate, double yaw_rate, double dt):
        """Return this rotation after turning at the body-frame rates ``roll_rate``,
        ``pitch_rate`` and ``yaw_rate`` (rad/s, about the rotated axes) for ``dt`` s:
        ``q·exp(½ (0, roll_rate, pitch_rate, yaw_rate) dt)``."""
        return new_rotation3d(rotation_in_range(
            rot3_integrate(self.q, roll_rate, pitch_rate, yaw_rate, dt), self.q, dt,
            roll_rate * 0.0 + pitch_rate * 0.0 + yaw_rate * 0.0, "integrate()"))

    def __mul__(self, other):
        if is_number(other):
            return self.times(other)
        return NotImplemented

    def __rmul__(self, other):
        if is_number(other):
            return self.times(other)
        return NotImplemented

    def __truediv__(self, other):
        if is_number(other):
            return self.div(other)
        return NotImplemented

    # WPILib 2027 has no Rotation3d + - or unary − (robotpy 2026 had them): the TypeError
    # says what to use.
    def __add__(self, other):
        raise TypeError("Rotation3d has no + (WPILib 2027 removed it: 3-D rotations do not "
                        "commute): use a.rotateBy(b) for b applied after a about the fixed "
                        "axes (the quaternion b·a), or compose Pose3d/Transform3d")

    def __sub__(self, other):
        raise TypeError("Rotation3d has no - (WPILib 2027 removed it): use a.relativeTo(b), "
                        "the quaternion b⁻¹·a")

    def __neg__(self):
        raise TypeError("Rotation3d has no unary - (WPILib 2027 removed unaryMinus): use "
                        "inverse()")

    def __eq__(self, other):
        if type(other) is Rotation3d:
            return rot3_eq(self.q, (<Rotation3d>other).q)
        return NotImplemented

    __hash__ = None

    def __reduce__(self):
        return (_rotation3d_from_quaternion, (self.q.w, self.q.x, self.q.y, self.q.z))

    def __repr__(self):
        return (f"Rotation3d(Quaternion(w={self.q.w!r}, x={self.q.x!r}, y={self.q.y!r}, "
                f"z={self.q.z!r}))")

    def __str__(self):
        return f"Rotation3d({new_quaternion(self.q)})"


cdef tuple _given(object a, object b, object c, str cls, str names):
    # The arguments passed, in order; a gap (a later one passed by keyword without an
    # earlier one) is refused.
    if c is not MISSING:
        if a is MISSING or b is MISSING:
            raise TypeError(f"{cls}() takes {names} together")
        return (a, b, c)
    if b is not MISSING:
        if a is MISSING:
            raise TypeError(f"{cls}() takes {names} together")
        return (a, b)
    return () if a is MISSING else (a,)


def _rotation3d_from_quaternion(double w, double x, double y, double z):
    """Rebuild a Rotation3d from its stored quaternion exactly (used by pickle).

    Only what a constructor can store is accepted: a unit quaternion (within 1e-9) or one
    holding NaN (a non-finite angle); anything else is a corrupted or crafted payload."""
    cdef quat_t q = quat(w, x, y, z)
    cdef double n = q_norm(q)
    if n == n and not fabs(n - 1.0) <= 1e-9:
        raise ValueError(f"a Rotation3d needs a unit quaternion, got ({w!r}, {x!r}, {y!r}, "
                         f"{z!r})")
    return new_rotation3d(q)


# ---------------------------------------------------------------------------------------
@cython.freelist(64)
cdef class Translation3d:
    """Translation3d(x=0.0, y=0.0, z=0.0) or Translation3d(distance, angle) or
    Translation3d(vector) or Translation3d(translation)

    A point or vector in space, in metres.

    ``Translation3d(x, y, z)`` takes the components in m; ``Translation3d(distance,
    angle)`` the vector (``distance`` m, 0, 0) rotated by the :class:`Rotation3d`
    ``angle``; ``Translation3d(vector)`` 3 floats (m); ``Translation3d(translation)`` a
    :class:`Translation2d` at z = 0. Immutable; ``==`` compares each component within
    1e-9 m.
    """

    def __init__(self, x=0.0, y=MISSING, z=MISSING):
        cdef vec3_t v
        refuse_reinit(self.frozen, self)
        if type(x) is float and type(y) is float and type(z) is float:
            v = vec3(<double>x, <double>y, <double>z)
        else:
            v = _translation_positional(x, y, z)
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

    @property
    def z(self):
        """Z component, m."""
        return self.v.z

    def getX(self):
        """Return the x component, m."""
        return self.v.x

    def getY(self):
        """Return the y component, m."""
        return self.v.y

    def getZ(self):
        """Return the z component, m."""
        return self.v.z

    def getNorm(self):
        """Return the distance from the origin, m."""
        return norm3(self.v.x, self.v.y, self.v.z)

    def getSquaredNorm(self):
        """Return the squared distance from the origin, m²."""
        return self.v.x * self.v.x + self.v.y * self.v.y + self.v.z * self.v.z

    def getDistance(self, other: Translation3d):
        """Return the distance to ``other``, m."""
        check_type(other, Translation3d, "other")
        cdef vec3_t d = v3_sub((<Translation3d>other).v, self.v)
        return norm3(d.x, d.y, d.z)

    def getSquaredDistance(self, other: Translation3d):
        """Return the squared distance to ``other``, m²."""
        check_type(other, Translation3d, "other")
        cdef vec3_t d = v3_sub((<Translation3d>other).v, self.v)
        return d.x * d.x + d.y * d.y + d.z * d.z

    def toVector(self):
        """Return ``numpy.array([x, y, z])``."""
        return np.array([self.v.x, self.v.y, self.v.z])

    def toTranslation2d(self):
        """Return (x, y) as a Translation2d (z dropped)."""
        return new_translation(vec(self.v.x, self.v.y))

    def rotateBy(self, other: Rotation3d):
        """Return this vector rotated by ``other`` about the origin: q·(0, v)·q⁻¹."""
        check_type(other, Rotation3d, "other")
        return new_translation3d(rot3_apply((<Rotation3d>other).q, self.v))

    def rotateAround(self, other: Translation3d, rot: Rotation3d):
        """Return this point rotated by ``rot`` about the point ``other``."""
        check_type(other, Translation3d, "other")
        check_type(rot, Rotation3d, "rot")
        cdef vec3_t o = (<Translation3d>other).v
        return new_translation3d(v3_add(rot3_apply((<Rotation3d>rot).q, v3_sub(self.v, o)),
                                        o))

    def dot(self, other: Translation3d):
        """Return the dot product, m²."""
        check_type(other, Translation3d, "other")
        return v3_dot(self.v, (<Translation3d>other).v)

    def cross(self, other: Translation3d):
        """Return the cross product ``self × other`` (m²) as a float64 array of shape (3,)
        (WPILib returns a Vector, not a Translation3d)."""
        check_type(other, Translation3d, "other")
        cdef vec3_t c = v3_cross(self.v, (<Translation3d>other).v)
        return np.array([c.x, c.y, c.z])

    def plus(self, other: Translation3d):
        """Return the component-wise sum, m."""
        check_type(other, Translation3d, "other")
        return new_translation3d(v3_add(self.v, (<Translation3d>other).v))

    def minus(self, other: Translation3d):
        """Return the component-wise difference, m."""
        check_type(other, Translation3d, "other")
        return new_translation3d(v3_sub(self.v, (<Translation3d>other).v))

    def unaryMinus(self):
        """Return the vector pointing the other way."""
        return new_translation3d(vec3(-self.v.x, -self.v.y, -self.v.z))

    def times(self, double scalar):
        """Return the vector scaled by ``scalar``."""
        return new_translation3d(v3_scale(self.v, scalar))

    def div(self, double scalar):
        """Return the vector divided by ``scalar`` (no zero guard, as in WPILib)."""
        return new_translation3d(vec3(self.v.x / scalar, self.v.y / scalar, self.v.z / scalar))

    def nearest(self, translations):
        """Return the element of ``translations`` closest to this point (first on ties)."""
        items = list(translations)          # one pass: a generator is read once
        for t in items:
            if type(t) is not Translation3d:
                raise TypeError(f"nearest() takes Translation3d objects, got {type_name(t)}")
        return min(items, key=self.getDistance)

    def interpolate(self, end_value: Translation3d, double t):
        """Return the linear interpolation towards ``end_value``; ``t`` is not clamped."""
        check_type(end_value, Translation3d, "end_value")
        cdef vec3_t e = (<Translation3d>end_value).v
        return new_translation3d(vec3(self.v.x + (e.x - self.v.x) * t,
                                      self.v.y + (e.y - self.v.y) * t,
                                      self.v.z + (e.z - self.v.z) * t))

    @staticmethod
    def fromFeet(double x, double y, double z):
        """Return the translation (``x``, ``y``, ``z``) given in feet, in metres
        (1 ft = 0.3048 m; the same bits as robotpy-wpimath's ``Translation3d.fromFeet``)."""
        return new_translation3d(vec3(feet_to_meters(x), feet_to_meters(y),
                                      feet_to_meters(z)))

    def __add__(self, other):
        if type(other) is Translation3d:
            return self.plus(other)
        return NotImplemented

    def __sub__(self, other):
        if type(other) is Translation3d:
            return self.minus(other)
        return NotImplemented

    def __neg__(self):
        return self.unaryMinus()

    def __mul__(self, other):
        if is_number(other):
            return self.times(other)
        return NotImplemented

    def __rmul__(self, other):
        if is_number(other):
            return self.times(other)
        return NotImplemented

    def __truediv__(self, other):
        if is_number(other):
            return self.div(other)
        return NotImplemented

    def __eq__(self, other):
        if type(other) is Translation3d:
            return v3_eq(self.v, (<Translation3d>other).v)
        return NotImplemented

    __hash__ = None

    def __iter__(self):
        yield self.v.x
        yield self.v.y
        yield self.v.z

    def __reduce__(self):
        return (Translation3d, (self.v.x, self.v.y, self.v.z))

    def __repr__(self):
        return f"Translation3d(x={self.v.x!r}, y={self.v.y!r}, z={self.v.z!r})"

    def __str__(self):
        return f"Translation3d(X: {f2(self.v.x)}, Y: {f2(self.v.y)}, Z: {f2(self.v.z)})"


cdef vec3_t _translation_positional(object x, object y, object z) except *:
    # The forms other than three floats, told apart by their types (as Translation2d's):
    # (distance, angle: Rotation3d), (vector), (translation: Translation2d), or numbers
    # (a missing y or z is 0 m).
    if type(y) is Rotation3d and z is MISSING:
        return rot3_apply((<Rotation3d>y).q, vec3(number(x, "distance"), 0.0, 0.0))
    if y is MISSING and z is MISSING:
        if type(x) is Translation2d:
            return vec3((<Translation2d>x).v.x, (<Translation2d>x).v.y, 0.0)
        if is_vector(x):
            return vector3(x, "vector")
    if is_vector(x) or type(x) is Translation2d or type(y) is Rotation3d:
        raise TypeError(
            "Translation3d() takes (x, y, z: float, m), (distance: float, m, angle: "
            "Rotation3d), (vector: 3 floats, m) or (translation: Translation2d); got "
            f"({', '.join(type_name(v) for v in (x, y, z) if v is not MISSING)})")
    return vec3(number(x, "x"), 0.0 if y is MISSING else number(y, "y"),
                0.0 if z is MISSING else number(z, "z"))


# ---------------------------------------------------------------------------------------
_POSE_FORMS = (("translation", "rotation"), ("x", "y", "z", "rotation"), ("pose",),
               ("initial", "final"), ("transform",))


cdef pose3_t frame_form(int form, tuple a, bint transform, str cls) except *:
    # One Pose3d/Transform3d constructor form (an index into _POSE_FORMS; the last two are
    # Transform3d's only).
    cdef rot2_t r2
    if form == 0:
        check_type(a[0], Translation3d, "translation")
        check_type(a[1], Rotation3d, "rotation")
        return pose3((<Translation3d>a[0]).v, (<Rotation3d>a[1]).q)
    if form == 1:
        check_type(a[3], Rotation3d, "rotation")
        return pose3(vec3(number(a[0], "x"), number(a[1], "y"), number(a[2], "z")),
                     (<Rotation3d>a[3]).q)
    if form == 2 and not transform:
        check_type(a[0], Pose2d, "pose")
        return _planar((<Pose2d>a[0]).p)
    if form == 3 and transform:
        check_type(a[0], Pose3d, "initial")
        check_type(a[1], Pose3d, "final")
        return pose3_relative_to((<Pose3d>a[1]).p, (<Pose3d>a[0]).p)
    if form == 4 and transform:
        check_type(a[0], Transform2d, "transform")
        return _planar((<Transform2d>a[0]).p)
    raise TypeError(f"{cls}() takes no {', '.join(_POSE_FORMS[form])} form")


cdef pose3_t _planar(pose2_t p) noexcept:
    # Pose3d(Pose2d), Transform3d(Transform2d): z = 0 and the heading as a yaw.
    return pose3(vec3(p.t.x, p.t.y, 0.0), yaw_rotation(p.r))


cdef pose3_t frame_args(str cls, bint transform, object a, object b, object c, object d,
                        dict kw) except *:
    # The constructor forms of Pose3d / Transform3d, by position (told apart by type) or
    # with keywords (kw: the keyword arguments passed).
    cdef tuple given = _given4(a, b, c, d)
    cdef Py_ssize_t n = len(given)
    if kw:
        forms = _POSE_FORMS if transform else _POSE_FORMS[:3]
        form, args = keyword_form(cls, forms, given, kw)
        return frame_form(form, args, transform, cls)
    if n == 0:
        return pose3(vec3(0.0, 0.0, 0.0), q_identity())
    if n == 1:
        if cnp.PyArray_Check(a):
            return affine_matrix(a, f"{cls}(matrix)")
        if type(a) is (Transform2d if transform else Pose2d):
            return frame_form(4 if transform else 2, given, transform, cls)
    elif n == 2:
        if type(a) is Translation3d:
            return frame_form(0, given, transform, cls)
        if transform and type(a) is Pose3d:
            return frame_form(3, given, transform, cls)
    elif n == 4:
        return frame_form(1, given, transform, cls)
    raise TypeError(
        f"{cls}() takes (), (translation: Translation3d, rotation: Rotation3d), (x, y, z: "
        f"float, m, rotation: Rotation3d), "
        + ("(initial: Pose3d, final: Pose3d), (transform: Transform2d)" if transform
           else "(pose: Pose2d)")
        + f" or (matrix: 4x4 float64 numpy array); got ({', '.join(type_name(x) for x in given)})")


cdef tuple _given4(object a, object b, object c, object d):
    if d is MISSING:
        return _given(a, b, c, "", "")
    return (a, b, c, d)


# Pose3d and Transform3d share their layout (pose3_t) and every accessor; the freelist
# lives on the base because Cython lets only a base class manage one.
@cython.freelist(64)
cdef class _Frame3d:
    """Shared accessors of Pose3d and Transform3d (a translation in m and a rotation)."""

    def __cinit__(self):
        # A bare __new__ is the identity, never an invalid (0, 0, 0, 0) rotation.
        self.p.q.w = 1.0

    cdef _Frame3d _new(self, pose3_t p):
        raise TypeError("_Frame3d is an abstract base; use Pose3d or Transform3d")

    @property
    def x(self):
        """X component of the translation, m."""
        return self.p.t.x

    @property
    def y(self):
        """Y component of the translation, m."""
        return self.p.t.y

    @property
    def z(self):
        """Z component of the translation, m."""
        return self.p.t.z

    def getX(self):
        """Return the x component of the translation, m."""
        return self.p.t.x

    def getY(self):
        """Return the y component of the translation, m."""
        return self.p.t.y

    def getZ(self):
        """Return the z component of the translation, m."""
        return self.p.t.z

    def getTranslation(self):
        """Return the translation part (Translation3d, m)."""
        return new_translation3d(self.p.t)

    def getRotation(self):
        """Return the rotation part (Rotation3d)."""
        return new_rotation3d(self.p.q)

    def times(self, double scalar):
        """Return (translation · scalar, rotation.times(scalar)): the rotation is scaled
        along the shortest path from the identity."""
        cdef pose3_t r = pose3_times(self.p, scalar)
        r.q = rotation_in_range(r.q, self.p.q, scalar, 0.0, "times()")
        return self._new(r)

    def div(self, double scalar):
        """Return ``times(1 / scalar)``."""
        cdef pose3_t r = pose3_times(self.p, 1.0 / scalar)
        r.q = rotation_in_range(r.q, self.p.q, scalar, 0.0, "div()")
        return self._new(r)

    def toMatrix(self):
        """Return the 4×4 homogeneous matrix ``[[R, t], [0, 0, 0, 1]]`` (float64 array)."""
        cdef double R[9]
        rot3_matrix(self.p.q, R)
        return np.array([[R[0], R[1], R[2], self.p.t.x],
                         [R[3], R[4], R[5], self.p.t.y],
                         [R[6], R[7], R[8], self.p.t.z],
                         [0.0, 0.0, 0.0, 1.0]])

    def __mul__(self, other):
        if is_number(other):
            return self.times(other)
        return NotImplemented

    def __rmul__(self, other):
        if is_number(other):
            return self.times(other)
        return NotImplemented

    def __truediv__(self, other):
        if is_number(other):
            return self.div(other)
        return NotImplemented

    def __eq__(self, other):
        if type(other) is type(self):
            return (v3_eq(self.p.t, (<_Frame3d>other).p.t)
                    and rot3_eq(self.p.q, (<_Frame3d>other).p.q))
        return NotImplemented

    __hash__ = None

    def __reduce__(self):
        return (type(self), (new_translation3d(self.p.t), new_rotation3d(self.p.q)))

    def __repr__(self):
        return (f"{type(self).__name__}({self.p.t.x!r}, {self.p.t.y!r}, {self.p.t.z!r}, "
                f"{new_rotation3d(self.p.q)!r})")

    def __str__(self):
        return (f"{type(self).__name__}({new_translation3d(self.p.t)}, "
                f"{new_rotation3d(self.p.q)})")


cdef class Pose3d(_Frame3d):
    """Pose3d() or Pose3d(translation, rotation) or Pose3d(x, y, z, rotation) or
    Pose3d(pose) or Pose3d(matrix)

    A pose in space: position in m and orientation as a :class:`Rotation3d`.
    ``Pose3d(pose)`` takes a :class:`Pose2d` (z = 0, its heading as the yaw);
    ``Pose3d(matrix)`` a 4×4 homogeneous float64 numpy array (see :meth:`toMatrix`;
    ValueError unless its bottom row is exactly (0, 0, 0, 1) and its rotation block a
    rotation matrix). Immutable; ``==`` compares the translation within 1e-9 m and the
    rotation as Rotation3d does.
    """

    def __init__(self, a=MISSING, b=MISSING, c=MISSING, d=MISSING, /, *,
                 translation=MISSING, rotation=MISSING, x=MISSING, y=MISSING, z=MISSING,
                 pose=MISSING):
        refuse_reinit(self.frozen, self)
        if (translation is MISSING and rotation is MISSING and x is MISSING and y is MISSING
                and z is MISSING and pose is MISSING):
            if type(a) is Translation3d and type(b) is Rotation3d and c is MISSING:
                self.p = pose3((<Translation3d>a).v, (<Rotation3d>b).q)
            else:
                self.p = frame_args("Pose3d", False, a, b, c, d, None)
        else:
            self.p = frame_args("Pose3d", False, a, b, c, d, given_keywords(
                ("translation", "rotation", "x", "y", "z", "pose"),
                (translation, rotation, x, y, z, pose)))
        self.frozen = True

    cdef _Frame3d _new(self, pose3_t p):
        return new_pose3d(p)

    def transformBy(self, other: Transform3d):
        """Return this pose moved by ``other``, expressed in this pose's frame: the
        translation rotated by this rotation and added; the rotation applied
        intrinsically."""
        check_type(other, Transform3d, "other")
        return new_pose3d(pose3_plus(self.p, (<Transform3d>other).p))

    def plus(self, other: Transform3d):
        """Same as :meth:`transformBy`."""
        check_type(other, Transform3d, "other")
        return new_pose3d(pose3_plus(self.p, (<Transform3d>other).p))

    def minus(self, other: Pose3d):
        """Return the Transform3d that maps ``other`` onto this pose."""
        check_type(other, Pose3d, "other")
        return new_transform3d(pose3_relative_to(self.p, (<Pose3d>other).p))

    def relativeTo(self, other: Pose3d):
        """Return this pose expressed in the frame of ``other``."""
        check_type(other, Pose3d, "other")
        return new_pose3d(pose3_relative_to(self.p, (<Pose3d>other).p))

    def rotateBy(self, other: Rotation3d):
        """Return the pose rotated by ``other`` about the origin (translation and
        rotation, extrinsically)."""
        check_type(other, Rotation3d, "other")
        return new_pose3d(pose3_rotate_by(self.p, (<Rotation3d>other).q))

    def rotateAround(self, point: Translation3d, rot: Rotation3d):
        """Return the pose rotated by ``rot`` about ``point``; the orientation turns by
        ``rot`` (extrinsically)."""
        check_type(point, Translation3d, "point")
        check_type(rot, Rotation3d, "rot")
        cdef vec3_t c = (<Translation3d>point).v
        cdef quat_t r = (<Rotation3d>rot).q
        return new_pose3d(pose3(v3_add(rot3_apply(r, v3_sub(self.p.t, c)), c),
                                rot3_rotate_by(self.p.q, r)))

    def toPose2d(self):
        """Return (x, y, yaw) as a Pose2d: z dropped, the heading the Euler yaw
        (:meth:`Rotation3d.getZ`)."""
        return new_pose(pose(vec(self.p.t.x, self.p.t.y), rot3_yaw(self.p.q)))

    def exp(self, twist: Twist3d):
        """Return ``self.plus(twist.exp())`` in one call (the WPILib 2026 ``Pose3d.exp``;
        2027 spells it ``pose.plus(twist.exp())`` and both give the same numbers)."""
        check_type(twist, Twist3d, "twist")
        return new_pose3d(pose3_plus(self.p, twist3_exp((<Twist3d>twist).t)))

    def log(self, end: Pose3d):
        """Return ``end.minus(self).log()`` (the WPILib 2026 ``Pose3d.log``)."""
        check_type(end, Pose3d, "end")
        return new_twist3d(pose3_log(pose3_relative_to((<Pose3d>end).p, self.p)))

    def nearest(self, poses):
        """Return the pose in ``poses`` closest to this one: smallest translation distance,
        ties broken by the smallest angle of the rotation between them (first on ties)."""
        cdef Pose3d best = None, q
        cdef double bd = 0.0, ba = 0.0, dd, a
        cdef vec3_t d
        for o in poses:
            # Exact type test: a typed loop variable would let None through.
            if type(o) is not Pose3d:
                raise TypeError(f"nearest() takes Pose3d objects, got {type_name(o)}")
            q = <Pose3d>o
            d = v3_sub(q.p.t, self.p.t)
            dd = norm3(d.x, d.y, d.z)
            a = rot3_angle(rot3_relative_to(self.p.q, q.p.q))
            if best is None or dd < bd or (dd == bd and a < ba):
                best, bd, ba = q, dd, a
        if best is None:
            raise ValueError("nearest() of an empty sequence")
        return best

    def interpolate(self, end_value: Pose3d, double t):
        """Interpolate along the screw motion (the twist) to ``end_value``.

        ``t < 0`` returns this pose and ``t ≥ 1`` returns ``end_value`` (WPILib's clamp,
        unlike :meth:`Rotation3d.interpolate`)."""
        check_type(end_value, Pose3d, "end_value")
        if t < 0.0:
            return self
        if t >= 1.0:
            return end_value
        return new_pose3d(pose3_interpolate(self.p, (<Pose3d>end_value).p, t))

    def __add__(self, other):
        if type(other) is Transform3d:
            return self.plus(other)
        return NotImplemented

    def __sub__(self, other):
        if type(other) is Pose3d:
            return self.minus(other)
        return NotImplemented

    @staticmethod
    def fromFeet(double x, double y, double z, r: Rotation3d):
        """Return the pose at (``x``, ``y``, ``z``) given in feet, in metres, with the
        orientation ``r``; robotpy-wpimath's ``Pose3d.fromFeet`` (1 ft = 0.3048 m, same
        bits)."""
        check_type(r, Rotation3d, "r")
        return new_pose3d(pose3(vec3(feet_to_meters(x), feet_to_meters(y), feet_to_meters(z)),
                                (<Rotation3d>r).q))


# ---------------------------------------------------------------------------------------
cdef class Transform3d(_Frame3d):
    """Transform3d() or Transform3d(translation, rotation) or Transform3d(x, y, z, rotation)
    or Transform3d(initial, final) or Transform3d(transform) or Transform3d(matrix)

    A rigid motion: a translation in m followed by a rotation, expressed in the frame it
    is applied to (applied intrinsically). ``Transform3d(initial, final)`` with two
    :class:`Pose3d` gives the transform that maps ``initial`` onto ``final``;
    ``Transform3d(transform)`` takes a :class:`Transform2d`; ``Transform3d(matrix)`` a
    4×4 homogeneous float64 numpy array (checked as for Pose3d). Immutable; ``==`` as for
    Pose3d.
    """

    def __init__(self, a=MISSING, b=MISSING, c=MISSING, d=MISSING, /, *,
                 translation=MISSING, rotation=MISSING, x=MISSING, y=MISSING, z=MISSING,
                 initial=MISSING, final=MISSING, transform=MISSING):
        refuse_reinit(self.frozen, self)
        if (translation is MISSING and rotation is MISSING and x is MISSING and y is MISSING
                and z is MISSING and initial is MISSING and final is MISSING
                and transform is MISSING):
            if type(a) is Translation3d and type(b) is Rotation3d and c is MISSING:
                self.p = pose3((<Translation3d>a).v, (<Rotation3d>b).q)
            else:
                self.p = frame_args("Transform3d", True, a, b, c, d, None)
        else:
            self.p = frame_args("Transform3d", True, a, b, c, d, given_keywords(
                ("translation", "rotation", "x", "y", "z", "initial", "final", "transform"),
                (translation, rotation, x, y, z, initial, final, transform)))
        self.frozen = True

    cdef _Frame3d _new(self, pose3_t p):
        return new_transform3d(p)

    def inverse(self):
        """Return the transform that undoes this one."""
        return new_transform3d(transform3_inverse(self.p))

    def plus(self, other: Transform3d):
        """Return this transform followed by ``other``."""
        check_type(other, Transform3d, "other")
        return new_transform3d(pose3_plus(self.p, (<Transform3d>other).p))

    def log(self):
        """Return the Twist3d whose :meth:`Twist3d.exp` is this transform (the screw
        motion; the inverse of exp). Exact to a few ulps at every rotation angle, where
        WPILib's closed form cancels below about 1e-3 rad."""
        return new_twist3d(pose3_log(self.p))

    def __add__(self, other):
        if type(other) is Transform3d:
            return self.plus(other)
        return NotImplemented


# ---------------------------------------------------------------------------------------
@cython.freelist(64)
cdef class Twist3d:
    """Twist3d(dx=0.0, dy=0.0, dz=0.0, rx=0.0, ry=0.0, rz=0.0)

    A screw motion: ``dx``, ``dy``, ``dz`` in m (in the start frame) and the rotation
    vector ``rx``, ``ry``, ``rz`` in rad. Mutable, like WPILib's public fields; ``==``
    compares each field within 1e-9, so instances are unhashable.
    """

    def __init__(self, double dx=0.0, double dy=0.0, double dz=0.0, double rx=0.0,
                 double ry=0.0, double rz=0.0):
        self.t.dx = dx
        self.t.dy = dy
        self.t.dz = dz
        self.t.rx = rx
        self.t.ry = ry
        self.t.rz = rz

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
    def dz(self):
        """Change along the start frame's z axis, m."""
        return self.t.dz

    @dz.setter
    def dz(self, double value):
        self.t.dz = value

    @property
    def rx(self):
        """X component of the rotation vector, rad."""
        return self.t.rx

    @rx.setter
    def rx(self, double value):
        self.t.rx = value

    @property
    def ry(self):
        """Y component of the rotation vector, rad."""
        return self.t.ry

    @ry.setter
    def ry(self, double value):
        self.t.ry = value

    @property
    def rz(self):
        """Z component of the rotation vector, rad."""
        return self.t.rz

    @rz.setter
    def rz(self, double value):
        self.t.rz = value

    def exp(self):
        """Return the Transform3d reached by following this screw motion from the origin.

        Exact to a few ulps at every rotation angle (WPILib's closed form cancels below
        about 1e-3 rad); the rotation is built from its quaternion directly:
        (cos θ/2, n̂ sin θ/2) for the rotation vector θ·n̂ = (rx, ry, rz), so w >= 0 for
        θ <= π. WPILib goes through the rotation matrix and its matrix-to-quaternion
        conversion, which above θ = 2π/3 (a matrix trace <= 0) may give the negated
        quaternion: the same rotation (``==`` holds), but ``getQuaternion()`` and the
        struct/protobuf bytes differ in sign."""
        return new_transform3d(twist3_exp(self.t))

    def __eq__(self, other):
        cdef Twist3d o
        if type(other) is Twist3d:
            o = <Twist3d>other
            return (fabs(self.t.dx - o.t.dx) < 1e-9 and fabs(self.t.dy - o.t.dy) < 1e-9
                    and fabs(self.t.dz - o.t.dz) < 1e-9 and fabs(self.t.rx - o.t.rx) < 1e-9
                    and fabs(self.t.ry - o.t.ry) < 1e-9 and fabs(self.t.rz - o.t.rz) < 1e-9)
        return NotImplemented

    __hash__ = None

    def __mul__(self, factor):
        """Return the twist with each component times ``factor`` (WPILib C++'s
        ``operator*``, robotpy's ``*``; Java has none)."""
        if not is_number(factor):
            return NotImplemented
        cdef double k = factor
        cdef twist3_t t = self.t
        t.dx = t.dx * k
        t.dy = t.dy * k
        t.dz = t.dz * k
        t.rx = t.rx * k
        t.ry = t.ry * k
        t.rz = t.rz * k
        return new_twist3d(t)

    def __rmul__(self, factor):
        return self.__mul__(factor)

    def __reduce__(self):
        return (Twist3d, (self.t.dx, self.t.dy, self.t.dz, self.t.rx, self.t.ry, self.t.rz))

    def __delattr__(self, name):
        refuse_delete(self, name)

    def __repr__(self):
        return (f"Twist3d(dx={self.t.dx!r}, dy={self.t.dy!r}, dz={self.t.dz!r}, "
                f"rx={self.t.rx!r}, ry={self.t.ry!r}, rz={self.t.rz!r})")

    def __str__(self):
        return (f"Twist3d(dX: {f2(self.t.dx)}, dY: {f2(self.t.dy)}, dZ: {f2(self.t.dz)}, "
                f"rX: {f2(self.t.rx)}, rY: {f2(self.t.ry)}, rZ: {f2(self.t.rz)})")

    @staticmethod
    def fromFeet(double dx=0.0, double dy=0.0, double dz=0.0, double rx=0.0, double ry=0.0,
                 double rz=0.0):
        """Return the twist with ``dx``, ``dy``, ``dz`` given in feet (converted to m) and
        ``rx``, ``ry``, ``rz`` in rad; robotpy-wpimath's ``Twist3d.fromFeet``
        (1 ft = 0.3048 m, same bits)."""
        return new_twist3d(twist3(feet_to_meters(dx), feet_to_meters(dy), feet_to_meters(dz),
                                  rx, ry, rz))


# ---------------------------------------------------------------------------------------
cdef class CoordinateAxis:
    """CoordinateAxis(x, y, z)

    A direction in a coordinate system, normalised to unit length: the building block of
    :class:`CoordinateSystem`. The presets :meth:`N` (+X), :meth:`S` (−X), :meth:`E` (−Y),
    :meth:`W` (+Y), :meth:`U` (+Z) and :meth:`D` (−Z) are NWU's directions. ValueError for
    a zero or non-finite vector (WPILib would store NaN). Immutable; compared by identity
    (WPILib defines no equality).
    """

    def __init__(self, double x, double y, double z):
        refuse_reinit(self.frozen, self)
        cdef double n = norm3(x, y, z)
        if not (0.0 < n < INFINITY):
            raise ValueError(f"CoordinateAxis needs a non-zero finite direction, got "
                             f"({x!r}, {y!r}, {z!r})")
        self.v = vec3(x / n, y / n, z / n)
        self.frozen = True

    @staticmethod
    def N():
        """Return the +X axis (north in NWU)."""
        return _AXES[0]

    @staticmethod
    def S():
        """Return the −X axis (south in NWU)."""
        return _AXES[1]

    @staticmethod
    def E():
        """Return the −Y axis (east in NWU)."""
        return _AXES[2]

    @staticmethod
    def W():
        """Return the +Y axis (west in NWU)."""
        return _AXES[3]

    @staticmethod
    def U():
        """Return the +Z axis (up in NWU)."""
        return _AXES[4]

    @staticmethod
    def D():
        """Return the −Z axis (down in NWU)."""
        return _AXES[5]

    def __reduce__(self):
        return (_coordinate_axis, (self.v.x, self.v.y, self.v.z))

    def __repr__(self):
        return f"CoordinateAxis({self.v.x!r}, {self.v.y!r}, {self.v.z!r})"


def _coordinate_axis(double x, double y, double z):
    """Rebuild a CoordinateAxis from its stored unit vector exactly (used by pickle)."""
    cdef CoordinateAxis a = CoordinateAxis.__new__(CoordinateAxis)
    if not fabs(norm3(x, y, z) - 1.0) <= 1e-9:
        raise ValueError(f"a CoordinateAxis needs a unit vector, got ({x!r}, {y!r}, {z!r})")
    a.v = vec3(x, y, z)
    a.frozen = True
    return a


cdef list _AXES = [CoordinateAxis(1.0, 0.0, 0.0), CoordinateAxis(-1.0, 0.0, 0.0),
                   CoordinateAxis(0.0, -1.0, 0.0), CoordinateAxis(0.0, 1.0, 0.0),
                   CoordinateAxis(0.0, 0.0, 1.0), CoordinateAxis(0.0, 0.0, -1.0)]


# ---------------------------------------------------------------------------------------
cdef class CoordinateSystem:
    """CoordinateSystem(positive_x, positive_y, positive_z)

    A coordinate system, given by the directions (:class:`CoordinateAxis`, in NWU terms)
    of its positive x, y and z axes; :meth:`convert` moves translations, rotations, poses
    and transforms between two of them. Presets: :meth:`NWU` (WPILib's field and robot
    frame), :meth:`EDN` (the OpenCV camera frame), :meth:`NED`. ValueError for a
    left-handed set of axes or axes that are not perpendicular. Immutable; compared by
    identity (WPILib defines no equality).
    """

    def __init__(self, positive_x: CoordinateAxis, positive_y: CoordinateAxis,
                 positive_z: CoordinateAxis):
        refuse_reinit(self.frozen, self)
        check_type(positive_x, CoordinateAxis, "positive_x")
        check_type(positive_y, CoordinateAxis, "positive_y")
        check_type(positive_z, CoordinateAxis, "positive_z")
        cdef vec3_t ax = (<CoordinateAxis>positive_x).v
        cdef vec3_t ay = (<CoordinateAxis>positive_y).v
        cdef vec3_t az = (<CoordinateAxis>positive_z).v
        # The axes are the columns of R.
        cdef double R[9]
        R[0] = ax.x
        R[1] = ay.x
        R[2] = az.x
        R[3] = ax.y
        R[4] = ay.y
        R[5] = az.y
        R[6] = ax.z
        R[7] = ay.z
        R[8] = az.z
        if fabs(matrix_det(R) + 1.0) < 1e-9:
            raise ValueError("CoordinateSystem requires a right-handed system, but a "
                             "left-handed one was provided")
        self.q = rotation_matrix(R, "CoordinateSystem")
        self.axes = (positive_x, positive_y, positive_z)
        self.frozen = True

    @staticmethod
    def NWU():
        """Return north-west-up: x forward, y left, z up (WPILib's field and robot
        frame)."""
        return _SYSTEMS[0]

    @staticmethod
    def EDN():
        """Return east-down-north: x right, y down, z forward (the OpenCV camera frame)."""
        return _SYSTEMS[1]

    @staticmethod
    def NED():
        """Return north-east-down: x forward, y right, z down."""
        return _SYSTEMS[2]

    @staticmethod
    def convert(translation=MISSING, from_: CoordinateSystem = MISSING,
                to: CoordinateSystem = MISSING, *, rotation=MISSING, pose=MISSING,
                transform=MISSING):
        """CoordinateSystem.convert(value, from_, to)

        Return the Translation3d, Rotation3d, Pose3d or Transform3d ``value`` (passed by
        position, or by keyword as ``translation``, ``rotation``, ``pose`` or
        ``transform``), expressed in the system ``from_``, converted to the system ``to``.
        A Transform3d's rotation is conjugated by the change of frame, so it stays
        intrinsic."""
        if from_ is not MISSING:
            check_type(from_, CoordinateSystem, "from_")
        if to is not MISSING:
            check_type(to, CoordinateSystem, "to")
        if from_ is MISSING or to is MISSING:
            raise TypeError("CoordinateSystem.convert() takes the value, from_ and to")
        value = _one_value(translation, rotation, pose, transform)
        cdef quat_t f = (<CoordinateSystem>from_).q
        cdef quat_t t_inv = rot3_inverse((<CoordinateSystem>to).q)
        cdef quat_t c
        cdef pose3_t p
        if type(value) is Translation3d:
            return new_translation3d(_convert_vector((<Translation3d>value).v, f, t_inv))
        if type(value) is Rotation3d:
            return new_rotation3d(rot3_rotate_by(rot3_rotate_by((<Rotation3d>value).q, f),
                                                 t_inv))
        if type(value) is Pose3d:
            p = (<Pose3d>value).p
            return new_pose3d(pose3(_convert_vector(p.t, f, t_inv),
                                    rot3_rotate_by(rot3_rotate_by(p.q, f), t_inv)))
        if type(value) is Transform3d:
            p = (<Transform3d>value).p
            # coordRot = from.R.rotateBy(to.R⁻¹); the rotation is
            # coordRot⁻¹.rotateBy(R.rotateBy(coordRot)) = coordRot·R·coordRot⁻¹.
            c = rot3_rotate_by(f, t_inv)
            return new_transform3d(pose3(_convert_vector(p.t, f, t_inv),
                                         rot3_rotate_by(rot3_inverse(c),
                                                        rot3_rotate_by(p.q, c))))
        raise TypeError("CoordinateSystem.convert() takes a Translation3d, Rotation3d, Pose3d "
                        f"or Transform3d, got {type_name(value)}")

    def __reduce__(self):
        return (CoordinateSystem, self.axes)

    def __repr__(self):
        if self.axes is None:
            return "<uninitialised CoordinateSystem>"
        return f"CoordinateSystem({self.axes[0]!r}, {self.axes[1]!r}, {self.axes[2]!r})"


cdef vec3_t _convert_vector(vec3_t v, quat_t f, quat_t t_inv) noexcept:
    # translation.rotateBy(from.R).rotateBy(to.R.inverse())
    return rot3_apply(t_inv, rot3_apply(f, v))


cdef object _one_value(object translation, object rotation, object pose, object transform):
    values = [v for v in (translation, rotation, pose, transform) if v is not MISSING]
    if len(values) != 1:
        raise TypeError("CoordinateSystem.convert() takes one value (translation, rotation, "
                        f"pose or transform), got {len(values)}")
    return values[0]


cdef list _SYSTEMS = [
    CoordinateSystem(_AXES[0], _AXES[3], _AXES[4]),
    CoordinateSystem(_AXES[2], _AXES[5], _AXES[0]),
    CoordinateSystem(_AXES[0], _AXES[2], _AXES[5]),
]


# WPILib's named constants.
drivekin_set_type_attr(Translation3d, "kZero", Translation3d())
drivekin_set_type_attr(Rotation3d, "kZero", Rotation3d())
drivekin_set_type_attr(Pose3d, "kZero", Pose3d())
drivekin_set_type_attr(Transform3d, "kZero", Transform3d())
