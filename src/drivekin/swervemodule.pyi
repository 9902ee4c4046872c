"""Swerve module values (WPILib 2027): the velocity, position and acceleration of one
swerve module, each a scalar and the module angle.

Units: m, m/s, m/s², rad. Robot frame: x forward, y left, CCW positive.

The values hold C doubles (the angle as a cos/sin pair), so :mod:`drivekin.swerve`'s
kinematics reads and writes them without creating Python objects; they are importable
from :mod:`drivekin.swerve` too.
"""

# Hand-written stub for the compiled module drivekin.swervemodule (swervemodule.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, the three values derive from the private base _ModuleVector; each class
# declares only the members it defines itself (inherited ones are typed with Self).

from collections.abc import Iterator
from typing import ClassVar, final

from typing_extensions import Self, disjoint_base

from drivekin.geometry import Rotation2d

__all__ = ["SwerveModuleAcceleration", "SwerveModulePosition", "SwerveModuleVelocity"]

@disjoint_base
class _ModuleVector:
    """Shared behaviour of the swerve module values: a scalar and an angle."""

    @property
    def angle(self) -> Rotation2d:
        """Module angle (Rotation2d). Stored by value: assigning copies the rotation."""

    @angle.setter
    def angle(self, value: Rotation2d) -> None: ...
    def compareTo(self, other: Self) -> int:
        """Compare the scalar only, like Java ``Double.compare``: −1, 0 or 1. ``other``
        must be of the same class."""

    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]
    def __iter__(self) -> Iterator[float | Rotation2d]: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    compare_to = compareTo

@final
class SwerveModuleVelocity(_ModuleVector):
    """SwerveModuleVelocity(velocity=0.0, angle=Rotation2d())

    The velocity of one swerve module: wheel ``velocity`` in m/s (may be negative) and the
    module ``angle``. Mutable; ``==`` compares velocity within 1e-9 m/s and the angle
    within 1e-9. (WPILib 2026: ``SwerveModuleState(speed, angle)``.)
    """

    def __init__(self, velocity: float = 0.0, angle: Rotation2d | float | None = None) -> None: ...
    @property
    def velocity(self) -> float:
        """Wheel velocity, m/s."""

    @velocity.setter
    def velocity(self, value: float) -> None: ...
    def optimize(self, current_angle: Rotation2d) -> SwerveModuleVelocity:
        """Return the equivalent velocity that turns the module by at most 90°.

        If the target angle is more than 90° from ``current_angle``, the result drives the
        wheel backwards at the angle + 180°. Returns a new object (2027)."""

    def optimizeInPlace(self, current_angle: Rotation2d) -> None:
        """Allocation-free :meth:`optimize`: update this object (the WPILib 2026
        behaviour). Returns None."""

    def cosineScale(self, current_angle: Rotation2d) -> SwerveModuleVelocity:
        """Return the velocity scaled by cos(angle − current_angle), so a module that is
        still turning does not push sideways. Returns a new object (2027)."""

    def cosineScaleInPlace(self, current_angle: Rotation2d) -> None:
        """Allocation-free :meth:`cosineScale`: update this object. Returns None."""

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @property
    def velocity_fps(self) -> float:
        """Wheel velocity, ft/s (``velocity`` in m/s); assignable."""
    @velocity_fps.setter
    def velocity_fps(self, value: float) -> None: ...

    def interpolate(self, end_value: SwerveModuleVelocity, t: float) -> SwerveModuleVelocity:
        """Interpolate velocity linearly and the angle the short way; ``t`` is clamped to
        [0, 1]."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    cosine_scale = cosineScale
    cosine_scale_in_place = cosineScaleInPlace
    optimize_in_place = optimizeInPlace

@final
class SwerveModulePosition(_ModuleVector):
    """SwerveModulePosition(distance=0.0, angle=Rotation2d())

    The position of one swerve module: distance driven by the wheel in m and the module
    ``angle``. Mutable; ``==`` compares distance within 1e-9 m and the angle within 1e-9.
    """

    def __init__(self, distance: float = 0.0, angle: Rotation2d | float | None = None) -> None: ...
    @property
    def distance(self) -> float:
        """Distance driven by the wheel, m."""

    @distance.setter
    def distance(self, value: float) -> None: ...
    def copy(self) -> SwerveModulePosition:
        """Return an independent copy."""

    def interpolate(self, end_value: SwerveModulePosition, t: float) -> SwerveModulePosition:
        """Interpolate distance linearly and the angle the short way; ``t`` is not clamped."""

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @property
    def distance_ft(self) -> float:
        """Distance driven by the wheel, ft (``distance`` in m); assignable."""
    @distance_ft.setter
    def distance_ft(self, value: float) -> None: ...

@final
class SwerveModuleAcceleration(_ModuleVector):
    """SwerveModuleAcceleration(acceleration=0.0, angle=Rotation2d())

    The acceleration of one swerve module: magnitude in m/s² and the direction ``angle``
    of the acceleration vector. Mutable; ``==`` compares within 1e-9.
    """

    def __init__(self, acceleration: float = 0.0, angle: Rotation2d | float | None = None) -> None: ...
    @property
    def acceleration(self) -> float:
        """Acceleration magnitude, m/s²."""

    @acceleration.setter
    def acceleration(self, value: float) -> None: ...
    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @staticmethod
    def from_fps(
        acceleration: float = 0.0, angle: Rotation2d | float | None = None
    ) -> SwerveModuleAcceleration:
        """Return the module acceleration ``acceleration`` given in ft/s² (in m/s²) at
        ``angle`` (a Rotation2d, rad as a float, or None for Rotation2d())."""
    @property
    def acceleration_fpss(self) -> float:
        """Acceleration magnitude, ft/s² (``acceleration`` in m/s²); assignable."""
    @acceleration_fpss.setter
    def acceleration_fpss(self, value: float) -> None: ...

    def __add__(self, other: SwerveModuleAcceleration, /) -> SwerveModuleAcceleration: ...
    def __sub__(self, other: SwerveModuleAcceleration, /) -> SwerveModuleAcceleration: ...
    def __neg__(self) -> SwerveModuleAcceleration: ...
    def __mul__(self, scalar: float, /) -> SwerveModuleAcceleration: ...
    def __rmul__(self, scalar: float, /) -> SwerveModuleAcceleration: ...
    def __truediv__(self, scalar: float, /) -> SwerveModuleAcceleration: ...
    def interpolate(self, end_value: SwerveModuleAcceleration, t: float) -> SwerveModuleAcceleration:
        """Interpolate the magnitude linearly and the angle the short way; ``t`` is
        clamped to [0, 1]."""
