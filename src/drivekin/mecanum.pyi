"""Mecanum drive kinematics, WPILib 2027.

Units: m, m/s, m/s², rad, rad/s, rad/s². Wheel order everywhere: front left, front right,
rear left, rear right. For a wheel at (x, y) relative to the centre of rotation the
inverse rows are FL/RR ``[1, −1, −(x + y)]`` and FR/RL ``[1, 1, x − y]``.
"""

# Hand-written stub for the compiled module drivekin.mecanum (mecanum.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, the three wheel-value classes derive from the private bases _Wheel4
# (this module) and drivekin._core.wheels._WheelValues (_core/wheels.pyi), and
# MecanumDriveKinematics from drivekin._core.drivetrain.Drivetrain; each class declares
# only the members it defines itself (inherited ones are typed with Self).

from typing import ClassVar, final

from drivekin._core.drivetrain import Drivetrain
from drivekin._core.wheels import _WheelValues
from drivekin.chassis import ChassisAccelerations, ChassisVelocities
from drivekin.geometry import Translation2d, Twist2d

class _Wheel4(_WheelValues):
    """Front-left, front-right, rear-left and rear-right wheel values."""

    def __init__(
        self,
        front_left: float = 0.0,
        front_right: float = 0.0,
        rear_left: float = 0.0,
        rear_right: float = 0.0,
    ) -> None: ...
    @property
    def frontLeft(self) -> float:
        """Front-left wheel value (m/s, m or m/s² depending on the class)."""

    @frontLeft.setter
    def frontLeft(self, value: float) -> None: ...
    @property
    def frontRight(self) -> float:
        """Front-right wheel value."""

    @frontRight.setter
    def frontRight(self, value: float) -> None: ...
    @property
    def rearLeft(self) -> float:
        """Rear-left wheel value."""

    @rearLeft.setter
    def rearLeft(self, value: float) -> None: ...
    @property
    def rearRight(self) -> float:
        """Rear-right wheel value."""

    @rearRight.setter
    def rearRight(self, value: float) -> None: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    @property
    def front_left(self) -> float: ...
    @front_left.setter
    def front_left(self, value: float) -> None: ...
    @property
    def front_right(self) -> float: ...
    @front_right.setter
    def front_right(self, value: float) -> None: ...
    @property
    def rear_left(self) -> float: ...
    @rear_left.setter
    def rear_left(self, value: float) -> None: ...
    @property
    def rear_right(self) -> float: ...
    @rear_right.setter
    def rear_right(self, value: float) -> None: ...

@final
class MecanumDriveWheelVelocities(_Wheel4):
    """MecanumDriveWheelVelocities(front_left=0.0, front_right=0.0, rear_left=0.0, rear_right=0.0)

    Wheel velocities of a mecanum drive, m/s. Mutable. As in WPILib Java there is no value
    equality: ``==`` is identity.
    """

    @staticmethod
    def fromFeet(
        front_left: float, front_right: float, rear_left: float, rear_right: float
    ) -> MecanumDriveWheelVelocities:
        """Return the wheel velocities given in ft/s, in m/s (the same bits as
        robotpy-wpimath's ``MecanumDriveWheelSpeeds.fromFeet``)."""
    def desaturate(self, attainable_max_velocity: float, /) -> MecanumDriveWheelVelocities:
        """Return new velocities scaled so no wheel exceeds ``attainable_max_velocity`` (m/s),
        keeping their ratios; an unchanged copy if already within it (2027)."""

    def desaturateInPlace(self, attainable_max_velocity: float, /) -> None:
        """Allocation-free :meth:`desaturate`: rescale this object. Returns None."""

    def interpolate(
        self, end_value: MecanumDriveWheelVelocities, t: float
    ) -> MecanumDriveWheelVelocities:
        """Linear interpolation with ``t`` clamped to [0, 1]."""

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @property
    def front_left_fps(self) -> float:
        """Front-left wheel, ft/s (``frontLeft`` in m/s); assignable."""
    @front_left_fps.setter
    def front_left_fps(self, value: float) -> None: ...
    @property
    def front_right_fps(self) -> float:
        """Front-right wheel, ft/s (``frontRight`` in m/s); assignable."""
    @front_right_fps.setter
    def front_right_fps(self, value: float) -> None: ...
    @property
    def rear_left_fps(self) -> float:
        """Rear-left wheel, ft/s (``rearLeft`` in m/s); assignable."""
    @rear_left_fps.setter
    def rear_left_fps(self, value: float) -> None: ...
    @property
    def rear_right_fps(self) -> float:
        """Rear-right wheel, ft/s (``rearRight`` in m/s); assignable."""
    @rear_right_fps.setter
    def rear_right_fps(self, value: float) -> None: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    desaturate_in_place = desaturateInPlace
    from_feet = fromFeet

@final
class MecanumDriveWheelPositions(_Wheel4):
    """MecanumDriveWheelPositions(front_left=0.0, front_right=0.0, rear_left=0.0, rear_right=0.0)

    Distances driven by each wheel, m. Mutable; ``==`` compares each wheel within 1e-9 m
    (so instances are unhashable).
    """

    def copy(self) -> MecanumDriveWheelPositions:
        """Return an independent copy."""

    def interpolate(
        self, end_value: MecanumDriveWheelPositions, t: float
    ) -> MecanumDriveWheelPositions:
        """Linear interpolation; ``t`` is not clamped."""

    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

@final
class MecanumDriveWheelAccelerations(_Wheel4):
    """MecanumDriveWheelAccelerations(front_left=0.0, front_right=0.0, rear_left=0.0, rear_right=0.0)

    Wheel accelerations of a mecanum drive, m/s². Mutable; ``==`` compares every wheel
    exactly (WPILib C++'s and robotpy's ``==``; Java has no ``equals``), so instances are
    unhashable.
    """

    def interpolate(
        self, end_value: MecanumDriveWheelAccelerations, t: float
    ) -> MecanumDriveWheelAccelerations:
        """Linear interpolation with ``t`` clamped to [0, 1]."""

    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

    # robotpy 2027's names without a Java counterpart (drivekin._core.robotpyextras).
    @staticmethod
    def from_fps(
        front_left: float = 0.0, front_right: float = 0.0, rear_left: float = 0.0,
        rear_right: float = 0.0
    ) -> MecanumDriveWheelAccelerations:
        """Return the wheel accelerations given in ft/s², in m/s²."""
    @property
    def front_left_fpss(self) -> float:
        """Front-left wheel, ft/s² (``frontLeft`` in m/s²); assignable."""
    @front_left_fpss.setter
    def front_left_fpss(self, value: float) -> None: ...
    @property
    def front_right_fpss(self) -> float:
        """Front-right wheel, ft/s² (``frontRight`` in m/s²); assignable."""
    @front_right_fpss.setter
    def front_right_fpss(self, value: float) -> None: ...
    @property
    def rear_left_fpss(self) -> float:
        """Rear-left wheel, ft/s² (``rearLeft`` in m/s²); assignable."""
    @rear_left_fpss.setter
    def rear_left_fpss(self, value: float) -> None: ...
    @property
    def rear_right_fpss(self) -> float:
        """Rear-right wheel, ft/s² (``rearRight`` in m/s²); assignable."""
    @rear_right_fpss.setter
    def rear_right_fpss(self, value: float) -> None: ...

@final
class MecanumDriveKinematics(Drivetrain):
    """MecanumDriveKinematics(front_left_wheel, front_right_wheel, rear_left_wheel, rear_right_wheel)

    Kinematics of a mecanum drive with the four wheel positions (Translation2d, m, robot
    frame). The forward (pseudo-inverse) matrix is computed once for the robot origin and
    never changes; a ``center_of_rotation`` passed to inverse kinematics moves only the
    inverse rows and stays in effect until a different one is passed (within 1e-9 m).
    """

    def __init__(
        self,
        front_left_wheel: Translation2d,
        front_right_wheel: Translation2d,
        rear_left_wheel: Translation2d,
        rear_right_wheel: Translation2d,
    ) -> None: ...
    def getFrontLeft(self) -> Translation2d:
        """Return the front-left wheel position (Translation2d, m)."""

    def getFrontRight(self) -> Translation2d:
        """Return the front-right wheel position (Translation2d, m)."""

    def getRearLeft(self) -> Translation2d:
        """Return the rear-left wheel position (Translation2d, m)."""

    def getRearRight(self) -> Translation2d:
        """Return the rear-right wheel position (Translation2d, m)."""

    def toWheelVelocities(
        self, chassis_velocities: ChassisVelocities, center_of_rotation: Translation2d = ...
    ) -> MecanumDriveWheelVelocities:
        """Return the wheel velocities (m/s) for a robot-relative chassis velocity,
        rotating about ``center_of_rotation`` (robot frame, m). Not desaturated."""

    def toWheelVelocitiesInto(
        self,
        chassis_velocities: ChassisVelocities,
        out: MecanumDriveWheelVelocities,
        center_of_rotation: Translation2d = ...,
    ) -> None:
        """Allocation-free :meth:`toWheelVelocities`: write into ``out``. Returns None."""

    def toChassisVelocities(
        self, wheel_velocities: MecanumDriveWheelVelocities
    ) -> ChassisVelocities:
        """Return the least-squares robot velocity for measured wheel velocities."""

    def toChassisVelocitiesInto(
        self, wheel_velocities: MecanumDriveWheelVelocities, out: ChassisVelocities
    ) -> None:
        """Allocation-free :meth:`toChassisVelocities`: write into ``out``. Returns None."""

    def toTwist2d(
        self, start: MecanumDriveWheelPositions, end: MecanumDriveWheelPositions | None = None
    ) -> Twist2d:
        """toTwist2d(wheel_deltas) or toTwist2d(start, end)

        Return the Twist2d (m, rad) for wheel distance changes, either given directly or
        as ``end − start`` of two MecanumDriveWheelPositions."""

    def toWheelAccelerations(
        self, chassis_accelerations: ChassisAccelerations, center_of_rotation: Translation2d = ...
    ) -> MecanumDriveWheelAccelerations:
        """Return the wheel accelerations (m/s²) for a chassis acceleration; the same
        matrix as for velocities (no centripetal term, as in WPILib)."""

    def toChassisAccelerations(
        self, wheel_accelerations: MecanumDriveWheelAccelerations
    ) -> ChassisAccelerations:
        """Return the least-squares chassis acceleration for wheel accelerations."""

    def interpolate(
        self,
        start: MecanumDriveWheelPositions,
        end: MecanumDriveWheelPositions,
        t: float,
    ) -> MecanumDriveWheelPositions:
        """Return ``start.interpolate(end, t)`` (not clamped)."""

    def copy(self, positions: MecanumDriveWheelPositions) -> MecanumDriveWheelPositions:
        """Return an independent copy of ``positions``."""

    def copyInto(
        self, positions: MecanumDriveWheelPositions, output: MecanumDriveWheelPositions
    ) -> None:
        """Copy ``positions`` into ``output``."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    copy_into = copyInto
    get_front_left = getFrontLeft
    get_front_right = getFrontRight
    get_rear_left = getRearLeft
    get_rear_right = getRearRight
    to_chassis_accelerations = toChassisAccelerations
    to_chassis_velocities = toChassisVelocities
    to_chassis_velocities_into = toChassisVelocitiesInto
    to_twist2d = toTwist2d
    to_wheel_accelerations = toWheelAccelerations
    to_wheel_velocities = toWheelVelocities
    to_wheel_velocities_into = toWheelVelocitiesInto
