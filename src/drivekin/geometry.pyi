"""2-D geometry with WPILib 2027 semantics: Translation2d, Rotation2d, Pose2d,
Transform2d and Twist2d.

Units: metres and radians. Frame: x forward, y left, angles counter-clockwise positive.
All classes except :class:`Twist2d` are immutable. Equality uses WPILib's tolerances
(1e-9), so the immutable classes are deliberately unhashable.
"""

# Hand-written stub for the compiled module drivekin.geometry (geometry.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, Pose2d and Transform2d derive from the private base _Frame2d, which
# declares the members they share (typed with Self).

from collections.abc import Iterable, Iterator
from typing import ClassVar, final, overload

import numpy as np
import numpy.typing as npt
from typing_extensions import Self, disjoint_base

@final
class Translation2d:
    """Translation2d(x=0.0, y=0.0) or Translation2d(distance, angle) or Translation2d(vector)

    A point or vector in the plane, in metres.

    ``Translation2d(x, y)`` takes the components in m; ``Translation2d(distance, angle)``
    takes a length in m and a :class:`Rotation2d` direction; ``Translation2d(vector)``
    takes a float64 numpy array of shape (2,). Immutable; ``==`` compares each component
    within 1e-9 m.
    """

    kZero: ClassVar[Translation2d]

    @overload
    def __init__(self, x: float = 0.0, y: float = 0.0) -> None: ...
    @overload
    def __init__(self, distance: float, angle: Rotation2d, /) -> None: ...
    @overload
    def __init__(self, vector: npt.NDArray[np.float64], /) -> None: ...
    @property
    def x(self) -> float:
        """X component, m."""

    @property
    def y(self) -> float:
        """Y component, m."""

    def getX(self) -> float:
        """Return the x component, m."""

    def getY(self) -> float:
        """Return the y component, m."""

    def getNorm(self) -> float:
        """Return the distance from the origin, m."""

    def getSquaredNorm(self) -> float:
        """Return the squared distance from the origin, m²."""

    def getDistance(self, other: Translation2d) -> float:
        """Return the distance to ``other``, m."""

    def getSquaredDistance(self, other: Translation2d) -> float:
        """Return the squared distance to ``other``, m²."""

    def getAngle(self) -> Rotation2d | None:
        """Return the direction of this vector as a Rotation2d, or ``None`` when its
        length is 1e-6 m or less (WPILib 2027 returns an empty Optional)."""

    def rotateBy(self, other: Rotation2d) -> Translation2d:
        """Return this vector rotated counter-clockwise by ``other`` about the origin."""

    def rotateAround(self, other: Translation2d, rot: Rotation2d) -> Translation2d:
        """Return this point rotated by ``rot`` about the point ``other``."""

    def plus(self, other: Translation2d) -> Translation2d:
        """Return the component-wise sum, m."""

    def minus(self, other: Translation2d) -> Translation2d:
        """Return the component-wise difference, m."""

    def unaryMinus(self) -> Translation2d:
        """Return the vector pointing the other way."""

    def times(self, scalar: float) -> Translation2d:
        """Return the vector scaled by ``scalar``."""

    def div(self, scalar: float) -> Translation2d:
        """Return the vector divided by ``scalar`` (no zero guard, as in WPILib)."""

    def dot(self, other: Translation2d) -> float:
        """Return the dot product, m²."""

    def cross(self, other: Translation2d) -> float:
        """Return the z component of the cross product, m² (x·other.y − y·other.x)."""

    def nearest(self, translations: Iterable[Translation2d]) -> Translation2d:
        """Return the element of ``translations`` closest to this point (first on ties)."""

    def interpolate(self, end_value: Translation2d, t: float) -> Translation2d:
        """Return the linear interpolation towards ``end_value``; ``t`` is not clamped."""

    def toVector(self) -> npt.NDArray[np.float64]:
        """Return ``numpy.array([x, y])``."""

    @overload
    @staticmethod
    def fromFeet(x: float, y: float) -> Translation2d:
        """Translation2d.fromFeet(x, y) or Translation2d.fromFeet(distance, angle)

        Return the translation (``x``, ``y``) given in feet, or the one of length
        ``distance`` ft in the direction ``angle`` (a :class:`Rotation2d`), in metres
        (1 ft = 0.3048 m; the same bits as robotpy-wpimath's ``Translation2d.fromFeet``)."""

    @overload
    @staticmethod
    def fromFeet(distance: float, angle: Rotation2d, /) -> Translation2d: ...
    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @property
    def x_feet(self) -> float:
        """X component of the translation, ft (``x`` in m)."""
    @property
    def y_feet(self) -> float:
        """Y component of the translation, ft (``y`` in m)."""
    def distance_feet(self, other: Translation2d, /) -> float:
        """Return the distance to ``other``, ft (``getDistance(other)`` in m)."""
    def norm_feet(self) -> float:
        """Return the distance from the origin, ft (``getNorm()`` in m)."""
    def __add__(self, other: Translation2d, /) -> Translation2d: ...
    def __sub__(self, other: Translation2d, /) -> Translation2d: ...
    def __neg__(self) -> Translation2d: ...
    def __mul__(self, other: float, /) -> Translation2d: ...
    def __rmul__(self, other: float, /) -> Translation2d: ...
    def __truediv__(self, other: float, /) -> Translation2d: ...
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]
    def __iter__(self) -> Iterator[float]: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    angle = getAngle
    distance = getDistance
    from_feet = fromFeet
    norm = getNorm
    rotate_around = rotateAround
    rotate_by = rotateBy
    squared_distance = getSquaredDistance
    squared_norm = getSquaredNorm
    to_vector = toVector
    unary_minus = unaryMinus

@final
class Rotation2d:
    """Rotation2d(value=0.0) or Rotation2d(x, y) or Rotation2d(matrix)

    A rotation in the plane, stored as its unit vector (cos, sin) as in WPILib 2027.

    ``Rotation2d(value)`` takes an angle in radians. ``Rotation2d(x, y)`` takes any
    vector and normalises it; a vector of length 1e-6 or less gives the identity
    (WPILib reports an error there; drivekin returns the identity silently).
    ``Rotation2d(matrix)`` takes a 2×2 special orthogonal float64 numpy array (ValueError
    if the Frobenius norm of RRᵀ − I, or abs(det R − 1), exceeds 1e-9).
    The constructor angle is not remembered: ``Rotation2d(3π/2).getDegrees()`` is −90.
    """

    kZero: ClassVar[Rotation2d]
    kCW_Pi_2: ClassVar[Rotation2d]
    kCW_90deg: ClassVar[Rotation2d]
    kCCW_Pi_2: ClassVar[Rotation2d]
    kCCW_90deg: ClassVar[Rotation2d]
    kPi: ClassVar[Rotation2d]
    k180deg: ClassVar[Rotation2d]

    @overload
    def __init__(self, value: float = 0.0) -> None: ...
    @overload
    def __init__(self, x: float, y: float, /) -> None: ...
    @overload
    def __init__(self, matrix: npt.NDArray[np.float64], /) -> None: ...
    @staticmethod
    def fromRadians(radians: float) -> Rotation2d:
        """Return the rotation of ``radians`` rad."""

    @staticmethod
    def fromDegrees(degrees: float) -> Rotation2d:
        """Return the rotation of ``degrees`` degrees."""

    @staticmethod
    def fromRotations(rotations: float) -> Rotation2d:
        """Return the rotation of ``rotations`` full turns."""

    def getRadians(self) -> float:
        """Return the angle in rad, in [−π, π] (atan2 of the stored unit vector)."""

    def getDegrees(self) -> float:
        """Return the angle in degrees, in [−180, 180]."""

    def getRotations(self) -> float:
        """Return the angle in turns, in [−0.5, 0.5]."""

    def getCos(self) -> float:
        """Return the cosine of the angle."""

    def getSin(self) -> float:
        """Return the sine of the angle."""

    def getTan(self) -> float:
        """Return the tangent of the angle (sin / cos; ±inf or NaN at ±90°)."""

    def rotateBy(self, other: Rotation2d) -> Rotation2d:
        """Return this rotation followed by ``other`` (angles add)."""

    def plus(self, other: Rotation2d) -> Rotation2d:
        """Same as :meth:`rotateBy`."""

    def minus(self, other: Rotation2d) -> Rotation2d:
        """Return the rotation whose angle is this angle minus ``other``'s (wrapped)."""

    def relativeTo(self, other: Rotation2d) -> Rotation2d:
        """Return this rotation seen from ``other`` (same as :meth:`minus`)."""

    def unaryMinus(self) -> Rotation2d:
        """Return the inverse rotation."""

    def times(self, scalar: float) -> Rotation2d:
        """Return the rotation by ``getRadians() * scalar``; the *wrapped* angle is scaled
        (270° × 0.5 = −45° in WPILib 2027)."""

    def div(self, scalar: float) -> Rotation2d:
        """Return ``times(1 / scalar)``."""

    def interpolate(self, end_value: Rotation2d, t: float) -> Rotation2d:
        """Return ``self + (end_value − self) · t``, the short way round; ``t`` is not
        clamped (2027)."""

    def toMatrix(self) -> npt.NDArray[np.float64]:
        """Return the 2×2 rotation matrix ``[[cos, −sin], [sin, cos]]``."""

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @staticmethod
    def from_matrix(rotation_matrix: npt.NDArray[np.float64]) -> Rotation2d:
        """Return the rotation of a 2×2 rotation matrix ``[[cos, −sin], [sin, cos]]`` (a
        float64 numpy array): ``Rotation2d(rotation_matrix)``. ValueError unless it is special
        orthogonal (Frobenius norm of RRᵀ − I and abs(det R − 1) at most 1e-9)."""

    def __add__(self, other: Rotation2d, /) -> Rotation2d: ...
    def __sub__(self, other: Rotation2d, /) -> Rotation2d: ...
    def __neg__(self) -> Rotation2d: ...
    def __mul__(self, other: float, /) -> Rotation2d: ...
    def __rmul__(self, other: float, /) -> Rotation2d: ...
    def __truediv__(self, other: float, /) -> Rotation2d: ...
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    cos = getCos
    degrees = getDegrees
    from_degrees = fromDegrees
    from_radians = fromRadians
    from_rotations = fromRotations
    radians = getRadians
    relative_to = relativeTo
    rotate_by = rotateBy
    rotations = getRotations
    sin = getSin
    tan = getTan
    to_matrix = toMatrix
    unary_minus = unaryMinus

@disjoint_base
class _Frame2d:
    """Shared accessors of Pose2d and Transform2d (a translation in m and a rotation)."""

    @property
    def x(self) -> float:
        """X component of the translation, m."""

    @property
    def y(self) -> float:
        """Y component of the translation, m."""

    def getX(self) -> float:
        """Return the x component of the translation, m."""

    def getY(self) -> float:
        """Return the y component of the translation, m."""

    def getTranslation(self) -> Translation2d:
        """Return the translation part (Translation2d, m)."""

    def getRotation(self) -> Rotation2d:
        """Return the rotation part (Rotation2d)."""

    def times(self, scalar: float) -> Self:
        """Return (translation · scalar, rotation.times(scalar))."""

    def div(self, scalar: float) -> Self:
        """Return ``times(1 / scalar)``."""

    def toMatrix(self) -> npt.NDArray[np.float64]:
        """Return the 3×3 homogeneous matrix ``[[cos, −sin, x], [sin, cos, y], [0, 0, 1]]``."""

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
class Pose2d(_Frame2d):
    """Pose2d() or Pose2d(translation, rotation) or Pose2d(x, y, rotation) or Pose2d(matrix)

    A robot pose on the field: position in m and heading as a :class:`Rotation2d`.
    ``Pose2d(matrix)`` takes a 3×3 homogeneous float64 numpy array (see :meth:`toMatrix`).
    Immutable; ``==`` compares translation within 1e-9 m and rotation within 1e-9.
    """

    kZero: ClassVar[Pose2d]

    @overload
    def __init__(self) -> None: ...
    @overload
    def __init__(self, translation: Translation2d, rotation: Rotation2d | float) -> None: ...
    @overload
    def __init__(self, x: float, y: float, rotation: Rotation2d | float) -> None: ...
    @overload
    def __init__(self, matrix: npt.NDArray[np.float64], /) -> None: ...
    def transformBy(self, other: Transform2d) -> Pose2d:
        """Return this pose moved by ``other``, expressed in this pose's frame."""

    def plus(self, other: Transform2d) -> Pose2d:
        """Same as :meth:`transformBy`."""

    def minus(self, other: Pose2d) -> Transform2d:
        """Return the Transform2d that maps ``other`` onto this pose."""

    def relativeTo(self, other: Pose2d) -> Pose2d:
        """Return this pose expressed in the frame of ``other``."""

    def rotateBy(self, other: Rotation2d) -> Pose2d:
        """Return the pose rotated about the field origin (position and heading)."""

    def rotateAround(self, point: Translation2d, rot: Rotation2d) -> Pose2d:
        """Return the pose rotated by ``rot`` about ``point``; the heading turns by ``rot``."""

    def exp(self, twist: Twist2d) -> Pose2d:
        """Return ``self.plus(twist.exp())`` in one call (the WPILib 2026 ``Pose2d.exp``;
        2027 spells it ``pose.plus(twist.exp())`` and both give the same numbers)."""

    def log(self, end: Pose2d) -> Twist2d:
        """Return ``end.minus(self).log()`` (the WPILib 2026 ``Pose2d.log``)."""

    def nearest(self, poses: Iterable[Pose2d]) -> Pose2d:
        """Return the pose in ``poses`` closest to this one: smallest translation distance,
        ties broken by the smallest heading difference."""

    def interpolate(self, end_value: Pose2d, t: float) -> Pose2d:
        """Interpolate along the constant-curvature arc to ``end_value``.

        ``t < 0`` returns this pose and ``t ≥ 1`` returns ``end_value`` (WPILib's clamp)."""

    @staticmethod
    def fromFeet(x: float, y: float, angle: Rotation2d | float) -> Pose2d:
        """Return the pose at (``x``, ``y``) given in feet, in metres, with heading
        ``angle`` (a :class:`Rotation2d`, or rad as a float); robotpy-wpimath's
        ``Pose2d.fromFeet`` (1 ft = 0.3048 m, same bits)."""

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @staticmethod
    def from_matrix(matrix: npt.NDArray[np.float64]) -> Pose2d:
        """Return the pose of a 3×3 homogeneous matrix ``[[cos, −sin, x], [sin, cos, y],
        [0, 0, 1]]`` in m (a float64 numpy array): ``Pose2d(matrix)``. ValueError unless the
        last row is exactly [0, 0, 1] and the rotation block is special orthogonal."""
    @property
    def x_feet(self) -> float:
        """X component of the position, ft (``x`` in m)."""
    @property
    def y_feet(self) -> float:
        """Y component of the position, ft (``y`` in m)."""

    def __add__(self, other: Transform2d, /) -> Pose2d: ...
    def __sub__(self, other: Pose2d, /) -> Transform2d: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    from_feet = fromFeet
    relative_to = relativeTo
    rotate_around = rotateAround
    rotate_by = rotateBy
    transform_by = transformBy

@final
class Transform2d(_Frame2d):
    """Transform2d() or Transform2d(translation, rotation) or Transform2d(x, y, rotation)
    or Transform2d(initial, final) or Transform2d(matrix)

    A rigid motion: a translation in m followed by a rotation, expressed in the frame it
    is applied to. ``Transform2d(initial, final)`` with two :class:`Pose2d` gives the
    transform that maps ``initial`` onto ``final``. Immutable; ``==`` as for Pose2d.
    """

    kZero: ClassVar[Transform2d]

    @overload
    def __init__(self) -> None: ...
    @overload
    def __init__(self, translation: Translation2d, rotation: Rotation2d | float) -> None: ...
    @overload
    def __init__(self, x: float, y: float, rotation: Rotation2d | float) -> None: ...
    @overload
    def __init__(self, matrix: npt.NDArray[np.float64], /) -> None: ...
    @overload
    def __init__(self, initial: Pose2d, final: Pose2d) -> None: ...
    def inverse(self) -> Transform2d:
        """Return the transform that undoes this one."""

    def plus(self, other: Transform2d) -> Transform2d:
        """Return this transform followed by ``other``."""

    def log(self) -> Twist2d:
        """Return the Twist2d whose :meth:`Twist2d.exp` is this transform (the
        constant-curvature arc; the inverse of exp)."""

    @staticmethod
    def fromFeet(x: float, y: float, angle: Rotation2d | float) -> Transform2d:
        """Return the transform with translation (``x``, ``y``) given in feet, in metres,
        and rotation ``angle`` (a :class:`Rotation2d`, or rad as a float);
        robotpy-wpimath's ``Transform2d.fromFeet`` (1 ft = 0.3048 m, same bits)."""

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @staticmethod
    def from_matrix(matrix: npt.NDArray[np.float64]) -> Transform2d:
        """Return the transform of a 3×3 homogeneous matrix ``[[cos, −sin, x], [sin, cos, y],
        [0, 0, 1]]`` in m (a float64 numpy array): ``Transform2d(matrix)``. ValueError unless
        the last row is exactly [0, 0, 1] and the rotation block is special orthogonal."""
    @property
    def x_feet(self) -> float:
        """X component of the translation, ft (``x`` in m)."""
    @property
    def y_feet(self) -> float:
        """Y component of the translation, ft (``y`` in m)."""

    def __add__(self, other: Transform2d, /) -> Transform2d: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    from_feet = fromFeet

@final
class Twist2d:
    """Twist2d(dx=0.0, dy=0.0, dtheta=0.0)

    A motion along a constant-curvature arc: ``dx``, ``dy`` in m (in the start frame) and
    ``dtheta`` in rad. Mutable, like WPILib's public fields; ``==`` compares each field
    within 1e-9, so instances are unhashable.
    """

    def __init__(self, dx: float = 0.0, dy: float = 0.0, dtheta: float = 0.0) -> None: ...
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
    def dtheta(self) -> float:
        """Change in heading, rad."""

    @dtheta.setter
    def dtheta(self, value: float) -> None: ...
    def exp(self) -> Transform2d:
        """Return the Transform2d reached by following this arc from the origin.

        Uses the series form when ``|dtheta| < 1e-9``."""

    def __mul__(self, factor: float, /) -> Twist2d:
        """Return the twist with each component times ``factor`` (WPILib C++'s
        ``operator*``, robotpy's ``*``; Java has none)."""

    def __rmul__(self, factor: float, /) -> Twist2d: ...

    @staticmethod
    def fromFeet(dx: float = 0.0, dy: float = 0.0, dtheta: float = 0.0) -> Twist2d:
        """Return the twist with ``dx``, ``dy`` given in feet (converted to m) and
        ``dtheta`` in rad; robotpy-wpimath's ``Twist2d.fromFeet`` (1 ft = 0.3048 m, same
        bits)."""

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
    def dtheta_degrees(self) -> float:
        """Change in heading, degrees (``dtheta`` in rad); assignable."""
    @dtheta_degrees.setter
    def dtheta_degrees(self, value: float) -> None: ...

    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    from_feet = fromFeet
