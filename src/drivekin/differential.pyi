"""Differential (tank) drive kinematics, WPILib 2027.

Units: m, m/s, m/s², rad, rad/s, rad/s². The model is the same as Road Runner's
``TankKinematics``: v_left = vx − ω·W/2, v_right = vx + ω·W/2, with W the trackwidth.
"""

# Hand-written stub for the compiled module drivekin.differential (differential.pyx).
# The docstrings are written from the compiled module's ``__doc__`` (the .pyx
# docstrings) by scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun
# the script. tests/api/test_stubs.py checks that they match and that no public name is
# missing on either side.
#
# As at runtime, the three wheel-value classes derive from the private bases _Wheel2
# (this module) and drivekin._core.wheels._WheelValues (_core/wheels.pyi), and
# DifferentialDriveKinematics from drivekin._core.drivetrain.Drivetrain; each class
# declares only the members it defines itself (inherited ones are typed with Self).

from typing import ClassVar, final, overload

from drivekin._core.drivetrain import Drivetrain
from drivekin._core.wheels import _WheelValues
from drivekin.chassis import ChassisAccelerations, ChassisVelocities
from drivekin.geometry import Twist2d

class _Wheel2(_WheelValues):
    """Left and right wheel values."""

    def __init__(self, left: float = 0.0, right: float = 0.0) -> None: ...
    @property
    def left(self) -> float:
        """Left wheel value (m/s, m or m/s² depending on the class)."""

    @left.setter
    def left(self, value: float) -> None: ...
    @property
    def right(self) -> float:
        """Right wheel value (m/s, m or m/s² depending on the class)."""

    @right.setter
    def right(self, value: float) -> None: ...

@final
class DifferentialDriveWheelVelocities(_Wheel2):
    """DifferentialDriveWheelVelocities(left=0.0, right=0.0)

    Wheel velocities of a differential drive, m/s. Mutable. As in WPILib Java there is no
    value equality: ``==`` is identity (compare ``left``/``right`` yourself).
    """

    @staticmethod
    def fromFeet(left: float, right: float) -> DifferentialDriveWheelVelocities:
        """Return the wheel velocities given in ft/s, in m/s (the same bits as
        robotpy-wpimath's ``DifferentialDriveWheelSpeeds.fromFeet``)."""
    def desaturate(self, attainable_max_velocity: float, /) -> DifferentialDriveWheelVelocities:
        """Return new velocities scaled so neither wheel exceeds ``attainable_max_velocity``
        (m/s), keeping their ratio; unchanged copy if already within it (2027)."""

    def desaturateInPlace(self, attainable_max_velocity: float, /) -> None:
        """Allocation-free :meth:`desaturate`: rescale this object. Returns None."""

    def interpolate(
        self, end_value: DifferentialDriveWheelVelocities, t: float
    ) -> DifferentialDriveWheelVelocities:
        """Linear interpolation with ``t`` clamped to [0, 1]."""

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @property
    def left_fps(self) -> float:
        """Left wheel, ft/s (``left`` in m/s); assignable."""
    @left_fps.setter
    def left_fps(self, value: float) -> None: ...
    @property
    def right_fps(self) -> float:
        """Right wheel, ft/s (``right`` in m/s); assignable."""
    @right_fps.setter
    def right_fps(self, value: float) -> None: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    desaturate_in_place = desaturateInPlace
    from_feet = fromFeet

@final
class DifferentialDriveWheelPositions(_Wheel2):
    """DifferentialDriveWheelPositions(left, right)

    Distances driven by the left and right wheels, m. Mutable; ``==`` compares each
    wheel within 1e-9 m (so instances are unhashable).
    """

    def __init__(self, left: float, right: float) -> None: ...
    def copy(self) -> DifferentialDriveWheelPositions:
        """Return an independent copy."""

    def interpolate(
        self, end_value: DifferentialDriveWheelPositions, t: float
    ) -> DifferentialDriveWheelPositions:
        """Linear interpolation; ``t`` is not clamped."""

    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

@final
class DifferentialDriveWheelAccelerations(_Wheel2):
    """DifferentialDriveWheelAccelerations(left=0.0, right=0.0)

    Wheel accelerations of a differential drive, m/s². Mutable; ``==`` compares every wheel
    exactly (WPILib C++'s and robotpy's ``==``; Java has no ``equals``), so instances are
    unhashable.
    """

    def interpolate(
        self, end_value: DifferentialDriveWheelAccelerations, t: float
    ) -> DifferentialDriveWheelAccelerations:
        """Linear interpolation with ``t`` clamped to [0, 1]."""

    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @staticmethod
    def from_fps(left: float, right: float) -> DifferentialDriveWheelAccelerations:
        """Return the wheel accelerations given in ft/s², in m/s²."""
    @property
    def left_fpss(self) -> float:
        """Left wheel, ft/s² (``left`` in m/s²); assignable."""
    @left_fpss.setter
    def left_fpss(self, value: float) -> None: ...
    @property
    def right_fpss(self) -> float:
        """Right wheel, ft/s² (``right`` in m/s²); assignable."""
    @right_fpss.setter
    def right_fpss(self, value: float) -> None: ...

@final
class DifferentialDriveKinematics(Drivetrain):
    """DifferentialDriveKinematics(trackwidth)

    Kinematics of a differential drive whose left and right wheels are ``trackwidth`` m
    apart (use the effective, empirically tuned value if the wheels scrub). The
    trackwidth must be positive and finite (ValueError otherwise).
    """

    def __init__(self, trackwidth: float) -> None: ...
    @property
    def trackwidth(self) -> float:
        """Distance between the left and right wheels, m (read-only)."""

    def toChassisVelocities(
        self, wheel_velocities: DifferentialDriveWheelVelocities
    ) -> ChassisVelocities:
        """Return the robot velocity: vx = (left + right) / 2, vy = 0,
        omega = (right − left) / trackwidth."""

    def toChassisVelocitiesInto(
        self, wheel_velocities: DifferentialDriveWheelVelocities, out: ChassisVelocities
    ) -> None:
        """Allocation-free :meth:`toChassisVelocities`: write into ``out``. Returns None."""

    def toWheelVelocities(
        self, chassis_velocities: ChassisVelocities
    ) -> DifferentialDriveWheelVelocities:
        """Return the wheel velocities for a robot velocity; ``vy`` is ignored (a
        differential drive cannot strafe)."""

    def toWheelVelocitiesInto(
        self, chassis_velocities: ChassisVelocities, out: DifferentialDriveWheelVelocities
    ) -> None:
        """Allocation-free :meth:`toWheelVelocities`: write into ``out``. Returns None."""

    @overload
    def toTwist2d(self, start: float, end: float) -> Twist2d:
        """toTwist2d(left_distance, right_distance) or toTwist2d(start, end)

        Return the Twist2d (m, rad) for wheel distance changes: dx = (l + r) / 2, dy = 0,
        dtheta = (r − l) / trackwidth. With two DifferentialDriveWheelPositions the
        changes are end − start."""

    @overload
    def toTwist2d(
        self, start: DifferentialDriveWheelPositions, end: DifferentialDriveWheelPositions
    ) -> Twist2d: ...
    def toChassisAccelerations(
        self, wheel_accelerations: DifferentialDriveWheelAccelerations
    ) -> ChassisAccelerations:
        """Return (ax = (l + r) / 2, ay = 0, alpha = (r − l) / trackwidth), m/s² and rad/s²."""

    def toWheelAccelerations(
        self, chassis_accelerations: ChassisAccelerations
    ) -> DifferentialDriveWheelAccelerations:
        """Return the wheel accelerations (ax ∓ trackwidth/2 · alpha); ``ay`` is ignored."""

    def interpolate(
        self,
        start: DifferentialDriveWheelPositions,
        end: DifferentialDriveWheelPositions,
        t: float,
    ) -> DifferentialDriveWheelPositions:
        """Return ``start.interpolate(end, t)`` (not clamped)."""

    def copy(self, positions: DifferentialDriveWheelPositions) -> DifferentialDriveWheelPositions:
        """Return an independent copy of ``positions``."""

    def copyInto(
        self, positions: DifferentialDriveWheelPositions, output: DifferentialDriveWheelPositions
    ) -> None:
        """Copy ``positions`` into ``output``."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    copy_into = copyInto
    to_chassis_accelerations = toChassisAccelerations
    to_chassis_velocities = toChassisVelocities
    to_chassis_velocities_into = toChassisVelocitiesInto
    to_twist2d = toTwist2d
    to_wheel_accelerations = toWheelAccelerations
    to_wheel_velocities = toWheelVelocities
    to_wheel_velocities_into = toWheelVelocitiesInto
