"""3-D geometry with WPILib 2027 semantics: Quaternion, Rotation3d, Translation3d, Pose3d,
Transform3d, Twist3d, CoordinateAxis and CoordinateSystem.

Units: metres and radians. Frame: x forward, y left, z up (NWU), angles counter-clockwise
about their axis. A vector argument is any sequence of 3 floats (a list, a tuple, a
float64 numpy array); vectors and matrices come back as float64 numpy arrays of shape
(3,), (3, 3) and (4, 4). All classes except :class:`Twist3d` are immutable. Equality uses
WPILib's tolerances, so the values are deliberately unhashable (q and −q are the same
Rotation3d, and rotations within about 8.9e-5 rad of each other compare equal)."""

# Hand-written stub for the compiled module drivekin.geometry3d (geometry3d.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, Pose3d and Transform3d derive from the private base _Frame3d, which
# declares the members they share (typed with Self).

from collections.abc import Iterable, Iterator, Sequence
from typing import ClassVar, NoReturn, final, overload

import numpy as np
import numpy.typing as npt
from typing_extensions import Self, disjoint_base

from drivekin.geometry import Pose2d, Rotation2d, Transform2d, Translation2d

#: A Vector3 argument: a sequence of 3 floats or a float64 array of shape (3,) or (3, 1).
_Vector3 = Sequence[float] | npt.NDArray[np.float64]

@final
class Quaternion:
    """Quaternion(w=1.0, x=0.0, y=0.0, z=0.0)

    A quaternion w + xi + yj + zk (WPILib's Quaternion: not normalised automatically).
    Immutable; ``==`` is WPILib's: the same direction and the same norm, each within
    1e-9 (so q and −q differ as Quaternions, although they are the same rotation).
    """
    def __init__(self, w: float = 1.0, x: float = 0.0, y: float = 0.0,
                 z: float = 0.0) -> None: ...
    @property
    def w(self) -> float:
        """W (scalar) component."""
    @property
    def x(self) -> float:
        """X component."""
    @property
    def y(self) -> float:
        """Y component."""
    @property
    def z(self) -> float:
        """Z component."""
    def getW(self) -> float:
        """Return the W (scalar) component."""
    def getX(self) -> float:
        """Return the X component."""
    def getY(self) -> float:
        """Return the Y component."""
    def getZ(self) -> float:
        """Return the Z component."""
    def plus(self, other: Quaternion) -> Quaternion:
        """Return the component-wise sum."""
    def minus(self, other: Quaternion) -> Quaternion:
        """Return the component-wise difference."""
    def times(self, other: Quaternion | float) -> Quaternion:
        """Return the Hamilton product ``self·other`` for a Quaternion ``other``, or every
        component times ``other`` for a float."""
    def divide(self, scalar: float) -> Quaternion:
        """Return every component divided by ``scalar`` (no zero guard, as in WPILib)."""
    def conjugate(self) -> Quaternion:
        """Return (w, −x, −y, −z)."""
    def dot(self, other: Quaternion) -> float:
        """Return the sum of the component-wise products."""
    def inverse(self) -> Quaternion:
        """Return the conjugate divided by the squared norm. ValueError for the zero
        quaternion (WPILib's 0/0 NaNs), or if the result overflows."""
    def norm(self) -> float:
        """Return the Euclidean norm sqrt(w² + x² + y² + z²)."""
    def normalize(self) -> Quaternion:
        """Return this quaternion divided by its norm; a zero quaternion gives the
        identity (1, 0, 0, 0). WPILib C++'s bits wherever the squared norm is a normal
        double; outside, the quaternion is first scaled by an exact power of two (so
        subnormal and huge quaternions come out unit, not off-unit or zero)."""
    def pow(self, t: float) -> Quaternion:
        """Return this quaternion raised to the power ``t``: ``(log() · t).exp()``.
        ValueError if the result overflows (a norm beyond the largest double)."""
    def exp(self) -> Quaternion:
        """Return the quaternion exponential e^w (cos‖v‖, v sin‖v‖/‖v‖), v = (x, y, z).
        ValueError if e^w overflows (w > 709.78...)."""
    def log(self) -> Quaternion:
        """Return the quaternion logarithm (ln‖q‖, v·atan2(‖v‖, w)/‖v‖); a zero
        quaternion gives (0, 0, 0, 0) and w/‖q‖ = −1 gives (ln‖q‖, −π, 0, 0)."""
    def toRotationVector(self) -> npt.NDArray[np.float64]:
        """Return the rotation vector (rad) of the rotation this quaternion represents,
        the short way round (angle at most π), as a float64 array of shape (3,). It does
        not depend on the norm (WPILib's small-angle series, taken for ‖v‖ < 1e-9 alone,
        does for a non-unit quaternion); the zero quaternion gives (0, 0, 0), the identity,
        as :meth:`normalize` and ``Rotation3d(q)`` make it."""
    @staticmethod
    def fromRotationVector(rvec: _Vector3) -> Quaternion:
        """Return the quaternion (cos θ/2, rvec·sin(θ/2)/θ) of the rotation vector
        ``rvec`` (3 floats, rad), θ = ‖rvec‖."""
    def __add__(self, other: Quaternion, /) -> Quaternion: ...
    def __sub__(self, other: Quaternion, /) -> Quaternion: ...
    def __mul__(self, other: Quaternion | float, /) -> Quaternion: ...
    def __rmul__(self, other: float, /) -> Quaternion: ...
    def __truediv__(self, other: float, /) -> Quaternion: ...
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    from_rotation_vector = fromRotationVector
    to_rotation_vector = toRotationVector

@final
class Rotation3d:
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
    kZero: ClassVar[Rotation3d]

    @overload
    def __init__(self) -> None: ...
    @overload
    def __init__(self, roll: float, pitch: float, yaw: float) -> None: ...
    @overload
    def __init__(self, q: Quaternion, /) -> None: ...
    @overload
    def __init__(self, axis: _Vector3, angle: float, /) -> None: ...
    @overload
    def __init__(self, rotation_matrix: npt.NDArray[np.float64], /) -> None: ...
    @overload
    def __init__(self, rvec: _Vector3, /) -> None: ...
    @overload
    def __init__(self, initial: _Vector3, final: _Vector3, /) -> None: ...
    @overload
    def __init__(self, rotation: Rotation2d, /) -> None: ...
    @staticmethod
    def fromRadians(roll: float, pitch: float, yaw: float) -> Rotation3d:
        """Return ``Rotation3d(roll, pitch, yaw)`` (extrinsic, rad)."""
    @staticmethod
    def fromDegrees(roll: float, pitch: float, yaw: float) -> Rotation3d:
        """Return the rotation of extrinsic ``roll``, ``pitch`` and ``yaw`` given in
        degrees."""
    @staticmethod
    def fromRotations(roll: float, pitch: float, yaw: float) -> Rotation3d:
        """Return the rotation of extrinsic ``roll``, ``pitch`` and ``yaw`` given in turns."""
    @property
    def x(self) -> float:
        """Roll, rad: the counter-clockwise rotation about the X axis (``getX()``)."""
    @property
    def y(self) -> float:
        """Pitch, rad: the counter-clockwise rotation about the Y axis (``getY()``)."""
    @property
    def z(self) -> float:
        """Yaw, rad: the counter-clockwise rotation about the Z axis (``getZ()``)."""
    @property
    def angle(self) -> float:
        """Rotation angle about :meth:`getAxis`, rad, in [0, 2π] (``getAngle()``)."""
    def getX(self) -> float:
        """Return the roll, rad, in [−π, π]: the extrinsic rotation about X (0 at gimbal
        lock, where pitch is ±π/2)."""
    def getY(self) -> float:
        """Return the pitch, rad, in [−π/2, π/2]: the extrinsic rotation about Y."""
    def getZ(self) -> float:
        """Return the yaw, rad, in [−π, π]: the extrinsic rotation about Z (at gimbal lock
        it carries roll and yaw together)."""
    def getAngle(self) -> float:
        """Return the rotation angle about :meth:`getAxis`, rad, 2·atan2(‖v‖, w) in
        [0, 2π]."""
    def getAxis(self) -> npt.NDArray[np.float64]:
        """Return the unit rotation axis as a float64 array of shape (3,); the identity
        gives (0, 0, 0)."""
    def getQuaternion(self) -> Quaternion:
        """Return the stored unit quaternion."""
    def toMatrix(self) -> npt.NDArray[np.float64]:
        """Return the 3×3 rotation matrix (float64 array)."""
    def toVector(self) -> npt.NDArray[np.float64]:
        """Return the rotation vector (axis times angle, rad) as a float64 array of shape
        (3,), the short way round (angle at most π)."""
    def toRotation2d(self) -> Rotation2d:
        """Return the yaw (:meth:`getZ`) as a Rotation2d (not a projection of the
        rotated x axis)."""
    def inverse(self) -> Rotation3d:
        """Return the rotation that undoes this one."""
    def rotateBy(self, other: Rotation3d) -> Rotation3d:
        """Return this rotation followed by ``other``, applied about the fixed (extrinsic)
        axes: the quaternion ``other·self``."""
    def relativeTo(self, other: Rotation3d) -> Rotation3d:
        """Return this rotation seen from ``other``: the quaternion ``other⁻¹·self`` (so
        ``a.relativeTo(b)`` applied after ``b``, intrinsically, gives ``a``)."""
    def times(self, scalar: float) -> Rotation3d:
        """Return the rotation scaled by ``scalar`` along the shortest path from the
        identity (``Rotation3d.kZero.interpolate(self, scalar)``, 2027)."""
    def div(self, scalar: float) -> Rotation3d:
        """Return ``times(1 / scalar)``."""
    def interpolate(self, end_value: Rotation3d, t: float) -> Rotation3d:
        """Return the spherical linear interpolation towards ``end_value``, the short way:
        ``(q1·q0⁻¹)^t·q0``; ``t`` is not clamped (2027)."""
    def integrate(self, roll_rate: float, pitch_rate: float, yaw_rate: float,
                  dt: float) -> Rotation3d:
        """Return this rotation after turning at the body-frame rates ``roll_rate``,
        ``pitch_rate`` and ``yaw_rate`` (rad/s, about the rotated axes) for ``dt`` s:
        ``q·exp(½ (0, roll_rate, pitch_rate, yaw_rate) dt)``."""
    def __mul__(self, other: float, /) -> Rotation3d: ...
    def __rmul__(self, other: float, /) -> Rotation3d: ...
    def __truediv__(self, other: float, /) -> Rotation3d: ...
    # WPILib 2027 has no Rotation3d + - or unary −: each raises TypeError naming
    # rotateBy / relativeTo / inverse.
    def __add__(self, other: object, /) -> NoReturn: ...
    def __sub__(self, other: object, /) -> NoReturn: ...
    def __neg__(self) -> NoReturn: ...
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @property
    def x_degrees(self) -> float:
        """Counter-clockwise rotation about the X axis (roll), degrees (``x`` in rad)."""
    @property
    def y_degrees(self) -> float:
        """Counter-clockwise rotation about the Y axis (pitch), degrees (``y`` in rad)."""
    @property
    def z_degrees(self) -> float:
        """Counter-clockwise rotation about the Z axis (yaw), degrees (``z`` in rad)."""
    @property
    def angle_degrees(self) -> float:
        """Angle of the rotation about its axis, degrees (``angle`` in rad)."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    axis = getAxis
    from_degrees = fromDegrees
    from_radians = fromRadians
    from_rotations = fromRotations
    get_quaternion = getQuaternion
    relative_to = relativeTo
    rotate_by = rotateBy
    to_matrix = toMatrix
    to_rotation2d = toRotation2d
    to_vector = toVector

@final
class Translation3d:
    """Translation3d(x=0.0, y=0.0, z=0.0) or Translation3d(distance, angle) or
    Translation3d(vector) or Translation3d(translation)

    A point or vector in space, in metres.

    ``Translation3d(x, y, z)`` takes the components in m; ``Translation3d(distance,
    angle)`` the vector (``distance`` m, 0, 0) rotated by the :class:`Rotation3d`
    ``angle``; ``Translation3d(vector)`` 3 floats (m); ``Translation3d(translation)`` a
    :class:`Translation2d` at z = 0. Immutable; ``==`` compares each component within
    1e-9 m.
    """
    kZero: ClassVar[Translation3d]

    @overload
    def __init__(self, x: float = 0.0, y: float = 0.0, z: float = 0.0) -> None: ...
    @overload
    def __init__(self, distance: float, angle: Rotation3d, /) -> None: ...
    @overload
    def __init__(self, vector: _Vector3, /) -> None: ...
    @overload
    def __init__(self, translation: Translation2d, /) -> None: ...
    @property
    def x(self) -> float:
        """X component, m."""
    @property
    def y(self) -> float:
        """Y component, m."""
    @property
    def z(self) -> float:
        """Z component, m."""
    def getX(self) -> float:
        """Return the x component, m."""
    def getY(self) -> float:
        """Return the y component, m."""
    def getZ(self) -> float:
        """Return the z component, m."""
    def getNorm(self) -> float:
        """Return the distance from the origin, m."""
    def getSquaredNorm(self) -> float:
        """Return the squared distance from the origin, m²."""
    def getDistance(self, other: Translation3d) -> float:
        """Return the distance to ``other``, m."""
    def getSquaredDistance(self, other: Translation3d) -> float:
        """Return the squared distance to ``other``, m²."""
    def toVector(self) -> npt.NDArray[np.float64]:
        """Return ``numpy.array([x, y, z])``."""
    def toTranslation2d(self) -> Translation2d:
        """Return (x, y) as a Translation2d (z dropped)."""
    def rotateBy(self, other: Rotation3d) -> Translation3d:
        """Return this vector rotated by ``other`` about the origin: q·(0, v)·q⁻¹."""
    def rotateAround(self, other: Translation3d, rot: Rotation3d) -> Translation3d:
        """Return this point rotated by ``rot`` about the point ``other``."""
    def dot(self, other: Translation3d) -> float:
        """Return the dot product, m²."""
    def cross(self, other: Translation3d) -> npt.NDArray[np.float64]:
        """Return the cross product ``self × other`` (m²) as a float64 array of shape (3,)
        (WPILib returns a Vector, not a Translation3d)."""
    def plus(self, other: Translation3d) -> Translation3d:
        """Return the component-wise sum, m."""
    def minus(self, other: Translation3d) -> Translation3d:
        """Return the component-wise difference, m."""
    def unaryMinus(self) -> Translation3d:
        """Return the vector pointing the other way."""
    def times(self, scalar: float) -> Translation3d:
        """Return the vector scaled by ``scalar``."""
    def div(self, scalar: float) -> Translation3d:
        """Return the vector divided by ``scalar`` (no zero guard, as in WPILib)."""
    def nearest(self, translations: Iterable[Translation3d]) -> Translation3d:
        """Return the element of ``translations`` closest to this point (first on ties)."""
    def interpolate(self, end_value: Translation3d, t: float) -> Translation3d:
        """Return the linear interpolation towards ``end_value``; ``t`` is not clamped."""
    @staticmethod
    def fromFeet(x: float, y: float, z: float) -> Translation3d:
        """Return the translation (``x``, ``y``, ``z``) given in feet, in metres
        (1 ft = 0.3048 m; the same bits as robotpy-wpimath's ``Translation3d.fromFeet``)."""
    def __add__(self, other: Translation3d, /) -> Translation3d: ...
    def __sub__(self, other: Translation3d, /) -> Translation3d: ...
    def __neg__(self) -> Translation3d: ...
    def __mul__(self, other: float, /) -> Translation3d: ...
    def __rmul__(self, other: float, /) -> Translation3d: ...
    def __truediv__(self, other: float, /) -> Translation3d: ...
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]
    def __iter__(self) -> Iterator[float]: ...

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @property
    def x_feet(self) -> float:
        """X component of the translation, ft (``x`` in m)."""
    @property
    def y_feet(self) -> float:
        """Y component of the translation, ft (``y`` in m)."""
    @property
    def z_feet(self) -> float:
        """Z component of the translation, ft (``z`` in m)."""
    def distance_feet(self, other: Translation3d, /) -> float:
        """Return the distance to ``other``, ft (``getDistance(other)`` in m)."""
    def norm_feet(self) -> float:
        """Return the distance from the origin, ft (``getNorm()`` in m)."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    distance = getDistance
    from_feet = fromFeet
    norm = getNorm
    rotate_around = rotateAround
    rotate_by = rotateBy
    squared_distance = getSquaredDistance
    squared_norm = getSquaredNorm
    to_translation2d = toTranslation2d
    to_vector = toVector
    unary_minus = unaryMinus

@disjoint_base
class _Frame3d:
    """Shared accessors of Pose3d and Transform3d (a translation in m and a rotation)."""
    @property
    def x(self) -> float:
        """X component of the translation, m."""
    @property
    def y(self) -> float:
        """Y component of the translation, m."""
    @property
    def z(self) -> float:
        """Z component of the translation, m."""
    def getX(self) -> float:
        """Return the x component of the translation, m."""
    def getY(self) -> float:
        """Return the y component of the translation, m."""
    def getZ(self) -> float:
        """Return the z component of the translation, m."""
    def getTranslation(self) -> Translation3d:
        """Return the translation part (Translation3d, m)."""
    def getRotation(self) -> Rotation3d:
        """Return the rotation part (Rotation3d)."""
    def times(self, scalar: float) -> Self:
        """Return (translation · scalar, rotation.times(scalar)): the rotation is scaled
        along the shortest path from the identity."""
    def div(self, scalar: float) -> Self:
        """Return ``times(1 / scalar)``."""
    def toMatrix(self) -> npt.NDArray[np.float64]:
        """Return the 4×4 homogeneous matrix ``[[R, t], [0, 0, 0, 1]]`` (float64 array)."""
    def __mul__(self, other: float, /) -> Self: ...
    def __rmul__(self, other: float, /) -> Self: ...
    def __truediv__(self, other: float, /) -> Self: ...
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    rotation = getRotation
    to_matrix = toMatrix
    translation = getTranslation

@final
class Pose3d(_Frame3d):
    """Pose3d() or Pose3d(translation, rotation) or Pose3d(x, y, z, rotation) or
    Pose3d(pose) or Pose3d(matrix)

    A pose in space: position in m and orientation as a :class:`Rotation3d`.
    ``Pose3d(pose)`` takes a :class:`Pose2d` (z = 0, its heading as the yaw);
    ``Pose3d(matrix)`` a 4×4 homogeneous float64 numpy array (see :meth:`toMatrix`;
    ValueError unless its bottom row is exactly (0, 0, 0, 1) and its rotation block a
    rotation matrix). Immutable; ``==`` compares the translation within 1e-9 m and the
    rotation as Rotation3d does.
    """
    kZero: ClassVar[Pose3d]

    @overload
    def __init__(self) -> None: ...
    @overload
    def __init__(self, translation: Translation3d, rotation: Rotation3d) -> None: ...
    @overload
    def __init__(self, x: float, y: float, z: float, rotation: Rotation3d) -> None: ...
    @overload
    def __init__(self, pose: Pose2d) -> None: ...
    @overload
    def __init__(self, matrix: npt.NDArray[np.float64], /) -> None: ...
    def transformBy(self, other: Transform3d) -> Pose3d:
        """Return this pose moved by ``other``, expressed in this pose's frame: the
        translation rotated by this rotation and added; the rotation applied
        intrinsically."""
    def plus(self, other: Transform3d) -> Pose3d:
        """Same as :meth:`transformBy`."""
    def minus(self, other: Pose3d) -> Transform3d:
        """Return the Transform3d that maps ``other`` onto this pose."""
    def relativeTo(self, other: Pose3d) -> Pose3d:
        """Return this pose expressed in the frame of ``other``."""
    def rotateBy(self, other: Rotation3d) -> Pose3d:
        """Return the pose rotated by ``other`` about the origin (translation and
        rotation, extrinsically)."""
    def rotateAround(self, point: Translation3d, rot: Rotation3d) -> Pose3d:
        """Return the pose rotated by ``rot`` about ``point``; the orientation turns by
        ``rot`` (extrinsically)."""
    def toPose2d(self) -> Pose2d:
        """Return (x, y, yaw) as a Pose2d: z dropped, the heading the Euler yaw
        (:meth:`Rotation3d.getZ`)."""
    def exp(self, twist: Twist3d) -> Pose3d:
        """Return ``self.plus(twist.exp())`` in one call (the WPILib 2026 ``Pose3d.exp``;
        2027 spells it ``pose.plus(twist.exp())`` and both give the same numbers)."""
    def log(self, end: Pose3d) -> Twist3d:
        """Return ``end.minus(self).log()`` (the WPILib 2026 ``Pose3d.log``)."""
    def nearest(self, poses: Iterable[Pose3d]) -> Pose3d:
        """Return the pose in ``poses`` closest to this one: smallest translation distance,
        ties broken by the smallest angle of the rotation between them (first on ties)."""
    def interpolate(self, end_value: Pose3d, t: float) -> Pose3d:
        """Interpolate along the screw motion (the twist) to ``end_value``.

        ``t < 0`` returns this pose and ``t ≥ 1`` returns ``end_value`` (WPILib's clamp,
        unlike :meth:`Rotation3d.interpolate`)."""
    @staticmethod
    def fromFeet(x: float, y: float, z: float, r: Rotation3d) -> Pose3d:
        """Return the pose at (``x``, ``y``, ``z``) given in feet, in metres, with the
        orientation ``r``; robotpy-wpimath's ``Pose3d.fromFeet`` (1 ft = 0.3048 m, same
        bits)."""
    def __add__(self, other: Transform3d, /) -> Pose3d: ...
    def __sub__(self, other: Pose3d, /) -> Transform3d: ...

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @staticmethod
    def from_matrix(matrix: npt.NDArray[np.float64]) -> Pose3d:
        """Return the pose of a 4×4 homogeneous matrix ``[[R, t], [0, 0, 0, 1]]`` in m (a
        float64 numpy array): ``Pose3d(matrix)``. ValueError unless the last row is exactly
        [0, 0, 0, 1] and R is special orthogonal."""
    @property
    def x_feet(self) -> float:
        """X component of the position, ft (``x`` in m)."""
    @property
    def y_feet(self) -> float:
        """Y component of the position, ft (``y`` in m)."""
    @property
    def z_feet(self) -> float:
        """Z component of the position, ft (``z`` in m)."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    from_feet = fromFeet
    relative_to = relativeTo
    rotate_around = rotateAround
    rotate_by = rotateBy
    to_pose2d = toPose2d
    transform_by = transformBy

@final
class Transform3d(_Frame3d):
    """Transform3d() or Transform3d(translation, rotation) or Transform3d(x, y, z, rotation)
    or Transform3d(initial, final) or Transform3d(transform) or Transform3d(matrix)

    A rigid motion: a translation in m followed by a rotation, expressed in the frame it
    is applied to (applied intrinsically). ``Transform3d(initial, final)`` with two
    :class:`Pose3d` gives the transform that maps ``initial`` onto ``final``;
    ``Transform3d(transform)`` takes a :class:`Transform2d`; ``Transform3d(matrix)`` a
    4×4 homogeneous float64 numpy array (checked as for Pose3d). Immutable; ``==`` as for
    Pose3d.
    """
    kZero: ClassVar[Transform3d]

    @overload
    def __init__(self) -> None: ...
    @overload
    def __init__(self, translation: Translation3d, rotation: Rotation3d) -> None: ...
    @overload
    def __init__(self, x: float, y: float, z: float, rotation: Rotation3d) -> None: ...
    @overload
    def __init__(self, initial: Pose3d, final: Pose3d) -> None: ...
    @overload
    def __init__(self, transform: Transform2d) -> None: ...
    @overload
    def __init__(self, matrix: npt.NDArray[np.float64], /) -> None: ...
    def inverse(self) -> Transform3d:
        """Return the transform that undoes this one."""
    def plus(self, other: Transform3d) -> Transform3d:
        """Return this transform followed by ``other``."""
    def log(self) -> Twist3d:
        """Return the Twist3d whose :meth:`Twist3d.exp` is this transform (the screw
        motion; the inverse of exp). Exact to a few ulps at every rotation angle, where
        WPILib's closed form cancels below about 1e-3 rad."""
    def __add__(self, other: Transform3d, /) -> Transform3d: ...

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @staticmethod
    def from_matrix(matrix: npt.NDArray[np.float64]) -> Transform3d:
        """Return the transform of a 4×4 homogeneous matrix ``[[R, t], [0, 0, 0, 1]]`` in m (a
        float64 numpy array): ``Transform3d(matrix)``. ValueError unless the last row is
        exactly [0, 0, 0, 1] and R is special orthogonal."""
    @property
    def x_feet(self) -> float:
        """X component of the translation, ft (``x`` in m)."""
    @property
    def y_feet(self) -> float:
        """Y component of the translation, ft (``y`` in m)."""
    @property
    def z_feet(self) -> float:
        """Z component of the translation, ft (``z`` in m)."""

@final
class Twist3d:
    """Twist3d(dx=0.0, dy=0.0, dz=0.0, rx=0.0, ry=0.0, rz=0.0)

    A screw motion: ``dx``, ``dy``, ``dz`` in m (in the start frame) and the rotation
    vector ``rx``, ``ry``, ``rz`` in rad. Mutable, like WPILib's public fields; ``==``
    compares each field within 1e-9, so instances are unhashable.
    """
    def __init__(self, dx: float = 0.0, dy: float = 0.0, dz: float = 0.0, rx: float = 0.0,
                 ry: float = 0.0, rz: float = 0.0) -> None: ...
    @property
    def dx(self) -> float:
        """Change along the start frame's x axis, m."""
    @dx.setter
    def dx(self, value: float) -> None: ...
    @property
    def dy(self) -> float:
        """Change along the start frame's y axis, m."""
    @dy.setter
    def dy(self, value: float) -> None: ...
    @property
    def dz(self) -> float:
        """Change along the start frame's z axis, m."""
    @dz.setter
    def dz(self, value: float) -> None: ...
    @property
    def rx(self) -> float:
        """X component of the rotation vector, rad."""
    @rx.setter
    def rx(self, value: float) -> None: ...
    @property
    def ry(self) -> float:
        """Y component of the rotation vector, rad."""
    @ry.setter
    def ry(self, value: float) -> None: ...
    @property
    def rz(self) -> float:
        """Z component of the rotation vector, rad."""
    @rz.setter
    def rz(self, value: float) -> None: ...
    def exp(self) -> Transform3d:
        """Return the Transform3d reached by following this screw motion from the origin.

        Exact to a few ulps at every rotation angle (WPILib's closed form cancels below
        about 1e-3 rad); the rotation is built from its quaternion directly:
        (cos θ/2, n̂ sin θ/2) for the rotation vector θ·n̂ = (rx, ry, rz), so w >= 0 for
        θ <= π. WPILib goes through the rotation matrix and its matrix-to-quaternion
        conversion, which above θ = 2π/3 (a matrix trace <= 0) may give the negated
        quaternion: the same rotation (``==`` holds), but ``getQuaternion()`` and the
        struct/protobuf bytes differ in sign."""
    def __mul__(self, factor: float, /) -> Twist3d: ...
    def __rmul__(self, factor: float, /) -> Twist3d: ...
    @staticmethod
    def fromFeet(dx: float = 0.0, dy: float = 0.0, dz: float = 0.0, rx: float = 0.0,
                 ry: float = 0.0, rz: float = 0.0) -> Twist3d:
        """Return the twist with ``dx``, ``dy``, ``dz`` given in feet (converted to m) and
        ``rx``, ``ry``, ``rz`` in rad; robotpy-wpimath's ``Twist3d.fromFeet``
        (1 ft = 0.3048 m, same bits)."""
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @property
    def dx_feet(self) -> float:
        """Change along the start frame's x axis, ft (``dx`` in m); assignable."""
    @dx_feet.setter
    def dx_feet(self, value: float) -> None: ...
    @property
    def dy_feet(self) -> float:
        """Change along the start frame's y axis, ft (``dy`` in m); assignable."""
    @dy_feet.setter
    def dy_feet(self, value: float) -> None: ...
    @property
    def dz_feet(self) -> float:
        """Change along the start frame's z axis, ft (``dz`` in m); assignable."""
    @dz_feet.setter
    def dz_feet(self, value: float) -> None: ...
    @property
    def rx_degrees(self) -> float:
        """Rotation vector's x component, degrees (``rx`` in rad); assignable."""
    @rx_degrees.setter
    def rx_degrees(self, value: float) -> None: ...
    @property
    def ry_degrees(self) -> float:
        """Rotation vector's y component, degrees (``ry`` in rad); assignable."""
    @ry_degrees.setter
    def ry_degrees(self, value: float) -> None: ...
    @property
    def rz_degrees(self) -> float:
        """Rotation vector's z component, degrees (``rz`` in rad); assignable."""
    @rz_degrees.setter
    def rz_degrees(self, value: float) -> None: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    from_feet = fromFeet

@final
class CoordinateAxis:
    """CoordinateAxis(x, y, z)

    A direction in a coordinate system, normalised to unit length: the building block of
    :class:`CoordinateSystem`. The presets :meth:`N` (+X), :meth:`S` (−X), :meth:`E` (−Y),
    :meth:`W` (+Y), :meth:`U` (+Z) and :meth:`D` (−Z) are NWU's directions. ValueError for
    a zero or non-finite vector (WPILib would store NaN). Immutable; compared by identity
    (WPILib defines no equality).
    """
    def __init__(self, x: float, y: float, z: float) -> None: ...
    @staticmethod
    def N() -> CoordinateAxis:
        """Return the +X axis (north in NWU)."""
    @staticmethod
    def S() -> CoordinateAxis:
        """Return the −X axis (south in NWU)."""
    @staticmethod
    def E() -> CoordinateAxis:
        """Return the −Y axis (east in NWU)."""
    @staticmethod
    def W() -> CoordinateAxis:
        """Return the +Y axis (west in NWU)."""
    @staticmethod
    def U() -> CoordinateAxis:
        """Return the +Z axis (up in NWU)."""
    @staticmethod
    def D() -> CoordinateAxis:
        """Return the −Z axis (down in NWU)."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    d = D
    e = E
    n = N
    s = S
    u = U
    w = W

@final
class CoordinateSystem:
    """CoordinateSystem(positive_x, positive_y, positive_z)

    A coordinate system, given by the directions (:class:`CoordinateAxis`, in NWU terms)
    of its positive x, y and z axes; :meth:`convert` moves translations, rotations, poses
    and transforms between two of them. Presets: :meth:`NWU` (WPILib's field and robot
    frame), :meth:`EDN` (the OpenCV camera frame), :meth:`NED`. ValueError for a
    left-handed set of axes or axes that are not perpendicular. Immutable; compared by
    identity (WPILib defines no equality).
    """
    def __init__(self, positive_x: CoordinateAxis, positive_y: CoordinateAxis,
                 positive_z: CoordinateAxis) -> None: ...
    @staticmethod
    def NWU() -> CoordinateSystem:
        """Return north-west-up: x forward, y left, z up (WPILib's field and robot
        frame)."""
    @staticmethod
    def EDN() -> CoordinateSystem:
        """Return east-down-north: x right, y down, z forward (the OpenCV camera frame)."""
    @staticmethod
    def NED() -> CoordinateSystem:
        """Return north-east-down: x forward, y right, z down."""
    @overload
    @staticmethod
    def convert(translation: Translation3d, from_: CoordinateSystem,
                to: CoordinateSystem) -> Translation3d:
        """CoordinateSystem.convert(value, from_, to)

        Return the Translation3d, Rotation3d, Pose3d or Transform3d ``value`` (passed by
        position, or by keyword as ``translation``, ``rotation``, ``pose`` or
        ``transform``), expressed in the system ``from_``, converted to the system ``to``.
        A Transform3d's rotation is conjugated by the change of frame, so it stays
        intrinsic."""
    @overload
    @staticmethod
    def convert(translation: Rotation3d, from_: CoordinateSystem,
                to: CoordinateSystem) -> Rotation3d: ...
    @overload
    @staticmethod
    def convert(translation: Pose3d, from_: CoordinateSystem,
                to: CoordinateSystem) -> Pose3d: ...
    @overload
    @staticmethod
    def convert(translation: Transform3d, from_: CoordinateSystem,
                to: CoordinateSystem) -> Transform3d: ...
    @overload
    @staticmethod
    def convert(*, rotation: Rotation3d, from_: CoordinateSystem,
                to: CoordinateSystem) -> Rotation3d: ...
    @overload
    @staticmethod
    def convert(*, pose: Pose3d, from_: CoordinateSystem, to: CoordinateSystem) -> Pose3d: ...
    @overload
    @staticmethod
    def convert(*, transform: Transform3d, from_: CoordinateSystem,
                to: CoordinateSystem) -> Transform3d: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    edn = EDN
    ned = NED
    nwu = NWU
