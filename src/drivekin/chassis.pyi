"""Chassis velocities and accelerations (WPILib 2027).

Units: m/s, m/s², rad/s, rad/s², s. Robot frame: x forward, y left, CCW positive. Each
conversion has an object-returning form and an allocation-free ``...Into`` form.
"""

# Hand-written stub for the compiled module drivekin.chassis (chassis.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, ChassisVelocities and ChassisAccelerations derive from the private base
# _ChassisVector; each class declares only the members it defines itself (inherited ones
# are typed with Self).

from typing import ClassVar, final

from typing_extensions import Self, disjoint_base

from drivekin.geometry import Rotation2d, Twist2d

__all__ = ["ChassisAccelerations", "ChassisVelocities"]

@disjoint_base
class _ChassisVector:
    """Shared arithmetic of ChassisVelocities and ChassisAccelerations (x, y, angular)."""

    def toRobotRelative(self, robot_angle: Rotation2d) -> Self:
        """Convert field-relative values to robot-relative ones.

        ``robot_angle`` is the robot heading on the field; x and y are rotated by
        −robot_angle, the angular component is unchanged."""

    def toFieldRelative(self, robot_angle: Rotation2d) -> Self:
        """Convert robot-relative values to field-relative ones (rotate by robot_angle)."""

    def toRobotRelativeInto(self, robot_angle: Rotation2d, out: Self) -> None:
        """Allocation-free :meth:`toRobotRelative`: write the result into ``out`` (of the
        same class; may be ``self``)."""

    def toFieldRelativeInto(self, robot_angle: Rotation2d, out: Self) -> None:
        """Allocation-free :meth:`toFieldRelative`: write the result into ``out`` (of the
        same class; may be ``self``)."""

    def plus(self, other: Self) -> Self:
        """Return the component-wise sum."""

    def minus(self, other: Self) -> Self:
        """Return the component-wise difference."""

    def unaryMinus(self) -> Self:
        """Return the negation of every component."""

    def times(self, scalar: float) -> Self:
        """Return every component multiplied by ``scalar``."""

    def div(self, scalar: float) -> Self:
        """Return every component divided by ``scalar`` (no zero guard, as in WPILib)."""

    def interpolate(self, end_value: Self, t: float) -> Self:
        """Linear interpolation; ``t <= 0`` returns ``self`` and ``t >= 1`` returns
        ``end_value`` (the objects themselves, as WPILib does)."""

    def __add__(self, other: Self, /) -> Self: ...
    def __sub__(self, other: Self, /) -> Self: ...
    def __neg__(self) -> Self: ...
    def __mul__(self, other: float, /) -> Self: ...
    def __rmul__(self, other: float, /) -> Self: ...
    def __truediv__(self, other: float, /) -> Self: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    to_field_relative = toFieldRelative
    to_field_relative_into = toFieldRelativeInto
    to_robot_relative = toRobotRelative
    to_robot_relative_into = toRobotRelativeInto
    unary_minus = unaryMinus

@final
class ChassisVelocities(_ChassisVector):
    """ChassisVelocities(vx=0.0, vy=0.0, omega=0.0)

    Robot velocity: ``vx`` forward and ``vy`` left in m/s, ``omega`` counter-clockwise in
    rad/s. Robot-relative unless stated otherwise. Fields are mutable; ``==`` compares
    each field exactly (0.0 == −0.0, NaN != NaN), as WPILib does.
    """

    def __init__(self, vx: float = 0.0, vy: float = 0.0, omega: float = 0.0) -> None: ...
    @staticmethod
    def fromFeet(vx: float = 0.0, vy: float = 0.0, omega: float = 0.0) -> ChassisVelocities:
        """Return the velocity ``vx`` forward and ``vy`` left given in ft/s, ``omega`` in
        rad/s, in m/s (the same bits as robotpy-wpimath's ``ChassisSpeeds.fromFeet``)."""
    @property
    def vx(self) -> float:
        """Forward velocity, m/s."""

    @vx.setter
    def vx(self, value: float) -> None: ...
    @property
    def vy(self) -> float:
        """Leftward velocity, m/s."""

    @vy.setter
    def vy(self, value: float) -> None: ...
    @property
    def omega(self) -> float:
        """Angular velocity, rad/s, counter-clockwise positive."""

    @omega.setter
    def omega(self, value: float) -> None: ...
    def toTwist2d(self, dt: float) -> Twist2d:
        """Return the Twist2d ``(vx·dt, vy·dt, omega·dt)`` travelled in ``dt`` seconds."""

    def discretize(self, dt: float) -> ChassisVelocities:
        """Return the velocities that, held constant for ``dt`` s along a straight line in
        the rotating frame, end at the pose this constant twist would reach.

        This removes the drift of swerve/mecanum drives that translate while turning.
        ``omega·dt`` passes through a Rotation2d, so it is wrapped to [−π, π]
        (omega = 4, dt = 1 gives omega' = 4 − 2π); ``dt = 0`` divides by zero (NaN),
        as in WPILib. Finite input gives a finite result at any magnitude (ValueError if
        that result is beyond the largest double)."""

    def discretizeInto(self, dt: float, out: ChassisVelocities) -> None:
        """Allocation-free :meth:`discretize`: write the result into ``out`` (may be self)."""

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @property
    def vx_fps(self) -> float:
        """Forward velocity, ft/s (``vx`` in m/s); assignable."""
    @vx_fps.setter
    def vx_fps(self, value: float) -> None: ...
    @property
    def vy_fps(self) -> float:
        """Leftward velocity, ft/s (``vy`` in m/s); assignable."""
    @vy_fps.setter
    def vy_fps(self, value: float) -> None: ...
    @property
    def omega_dps(self) -> float:
        """Angular velocity, counter-clockwise positive, deg/s (``omega`` in rad/s); assignable."""
    @omega_dps.setter
    def omega_dps(self, value: float) -> None: ...

    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    discretize_into = discretizeInto
    from_feet = fromFeet
    to_twist2d = toTwist2d

@final
class ChassisAccelerations(_ChassisVector):
    """ChassisAccelerations(ax=0.0, ay=0.0, alpha=0.0)

    Robot acceleration: ``ax`` forward and ``ay`` left in m/s², ``alpha`` counter-clockwise
    in rad/s². Fields are mutable; ``==`` follows Java ``Double.compare`` (NaN == NaN,
    0.0 != −0.0).
    """

    def __init__(self, ax: float = 0.0, ay: float = 0.0, alpha: float = 0.0) -> None: ...
    @property
    def ax(self) -> float:
        """Forward acceleration, m/s²."""

    @ax.setter
    def ax(self, value: float) -> None: ...
    @property
    def ay(self) -> float:
        """Leftward acceleration, m/s²."""

    @ay.setter
    def ay(self, value: float) -> None: ...
    @property
    def alpha(self) -> float:
        """Angular acceleration, rad/s², counter-clockwise positive."""

    @alpha.setter
    def alpha(self, value: float) -> None: ...
    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @staticmethod
    def from_fps(ax: float = 0.0, ay: float = 0.0, alpha: float = 0.0) -> ChassisAccelerations:
        """Return the acceleration ``ax`` forward and ``ay`` left given in ft/s² (in m/s²)
        and ``alpha`` in rad/s²."""
    @property
    def ax_fpss(self) -> float:
        """Forward acceleration, ft/s² (``ax`` in m/s²); assignable."""
    @ax_fpss.setter
    def ax_fpss(self, value: float) -> None: ...
    @property
    def ay_fpss(self) -> float:
        """Leftward acceleration, ft/s² (``ay`` in m/s²); assignable."""
    @ay_fpss.setter
    def ay_fpss(self, value: float) -> None: ...
    @property
    def alpha_dpss(self) -> float:
        """Angular acceleration, counter-clockwise positive, deg/s² (``alpha`` in rad/s²); assignable."""
    @alpha_dpss.setter
    def alpha_dpss(self, value: float) -> None: ...
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]
