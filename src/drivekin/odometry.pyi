"""Odometry for swerve, mecanum, differential and dead-wheel drivetrains (WPILib 2027).

Each ``update`` turns the wheel-position changes since the previous call into a twist
with the drivetrain's forward kinematics, replaces its heading change by the wrapped
gyro difference (the gyro is trusted for heading), and composes the pose with the
twist's exponential. The gyro reading need not match the pose heading: only its changes
matter. ``update`` returns the new pose; it allocates nothing beyond that Pose2d, which
comes from a freelist, so a 50 Hz loop runs without allocator calls.
"""

# Hand-written stub for the compiled module drivekin.odometry (odometry.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, the odometry classes derive from the private base _Odometry, which
# declares the methods they share.

from collections.abc import Sequence
from typing import final

import numpy as np
import numpy.typing as npt
from typing_extensions import disjoint_base

from drivekin.chassis import ChassisVelocities
from drivekin.deadwheel import DeadWheelKinematics
from drivekin.geometry import Pose2d, Rotation2d, Translation2d
from drivekin.mecanum import MecanumDriveKinematics, MecanumDriveWheelPositions
from drivekin.swerve import SwerveDriveKinematics, SwerveModulePosition

@disjoint_base
class _Odometry:
    """Pose state and the resets shared by every odometry class."""

    def getPose(self) -> Pose2d:
        """Return the current pose estimate (field frame, m)."""

    def resetPose(self, pose: Pose2d) -> None:
        """Set the pose; the gyro and wheel baselines are left as they are."""

    def resetTranslation(self, translation: Translation2d) -> None:
        """Set the position and keep the heading."""

    def resetRotation(self, rotation: Rotation2d) -> None:
        """Set the heading and keep the position. (robotpy-wpimath 2026 has a sign bug
        here that makes the next update report a wrong heading; drivekin does not.)"""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    get_pose = getPose
    reset_pose = resetPose
    reset_rotation = resetRotation
    reset_translation = resetTranslation

@final
class SwerveDriveOdometry(_Odometry):
    """SwerveDriveOdometry(kinematics, gyro_angle, module_positions, initial_pose=Pose2d())

    Tracks a swerve robot's pose from N module positions (SwerveModulePosition objects or
    an (N, 2) float64 array ``[distance m, angle rad]``) and a gyro angle (Rotation2d).
    """

    def __init__(
        self,
        kinematics: SwerveDriveKinematics,
        gyro_angle: Rotation2d,
        module_positions: Sequence[SwerveModulePosition] | npt.NDArray[np.float64],
        initial_pose: Pose2d | None = None,
    ) -> None: ...
    def resetPosition(
        self,
        gyro_angle: Rotation2d,
        wheel_positions: Sequence[SwerveModulePosition] | npt.NDArray[np.float64],
        pose: Pose2d,
    ) -> None:
        """Reset the pose, the gyro baseline and the module-position baseline."""

    def update(
        self,
        gyro_angle: Rotation2d,
        wheel_positions: Sequence[SwerveModulePosition] | npt.NDArray[np.float64],
    ) -> Pose2d:
        """Integrate the module-distance changes since the last call (at the current module
        angles) and the gyro change; return the new pose."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition

@final
class MecanumDriveOdometry(_Odometry):
    """MecanumDriveOdometry(kinematics, gyro_angle, wheel_positions, initial_pose=Pose2d())

    Tracks a mecanum robot's pose from MecanumDriveWheelPositions (m) and a gyro angle.
    """

    def __init__(
        self,
        kinematics: MecanumDriveKinematics,
        gyro_angle: Rotation2d,
        wheel_positions: MecanumDriveWheelPositions,
        initial_pose: Pose2d | None = None,
    ) -> None: ...
    def resetPosition(
        self, gyro_angle: Rotation2d, wheel_positions: MecanumDriveWheelPositions, pose: Pose2d
    ) -> None:
        """Reset the pose, the gyro baseline and the wheel-position baseline."""

    def update(self, gyro_angle: Rotation2d, wheel_positions: MecanumDriveWheelPositions) -> Pose2d:
        """Integrate the wheel-distance changes since the last call and the gyro change;
        return the new pose."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition

@final
class DifferentialDriveOdometry(_Odometry):
    """DifferentialDriveOdometry(gyro_angle, left_distance, right_distance, initial_pose=Pose2d())

    Tracks a differential-drive robot's pose from the left and right wheel distances (m)
    and a gyro angle. No trackwidth is needed: the heading comes from the gyro.
    """

    def __init__(
        self,
        gyro_angle: Rotation2d,
        left_distance: float,
        right_distance: float,
        initial_pose: Pose2d | None = None,
    ) -> None: ...
    def resetPosition(
        self, gyro_angle: Rotation2d, left_distance: float, right_distance: float, pose: Pose2d
    ) -> None:
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""

    def update(self, gyro_angle: Rotation2d, left_distance: float, right_distance: float) -> Pose2d:
        """Integrate the wheel-distance changes since the last call (dx = mean change,
        dy = 0) and the gyro change; return the new pose."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition

@final
class TwoDeadWheelOdometry(_Odometry):
    """TwoDeadWheelOdometry(x_wheel_y_pos, y_wheel_x_pos, x_wheel_pos, y_wheel_pos, gyro_angle, initial_pose=Pose2d())

    WPILib's two-dead-wheel odometry (goBILDA Pinpoint's layout): a forward-facing wheel
    at y = ``x_wheel_y_pos`` (m) reading forward motion, a left-facing wheel at
    x = ``y_wheel_x_pos`` (m) reading leftward motion, and a gyro for the heading. The
    offsets are Pinpoint's: X-pod offset positive to the left, Y-pod offset positive
    forward. ``x_wheel_pos``/``y_wheel_pos`` are the wheels' current distances (m).
    Each update uses dθ = the wrapped gyro change, dx = Δx + dθ·x_wheel_y_pos and
    dy = Δy − dθ·y_wheel_x_pos.
    """

    def __init__(
        self,
        x_wheel_y_pos: float,
        y_wheel_x_pos: float,
        x_wheel_pos: float,
        y_wheel_pos: float,
        gyro_angle: Rotation2d,
        initial_pose: Pose2d | None = None,
    ) -> None: ...
    def resetPosition(
        self, x_wheel_pos: float, y_wheel_pos: float, gyro_angle: Rotation2d, pose: Pose2d
    ) -> None:
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""

    def update(self, x_wheel_pos: float, y_wheel_pos: float, gyro_angle: Rotation2d) -> Pose2d:
        """Integrate the wheel-distance changes (m) since the last call and the gyro
        change; return the new pose."""

    def toChassisVelocities(self, vx: float, vy: float, omega: float) -> ChassisVelocities:
        """Return the robot velocity from the forward wheel's and left wheel's surface
        velocities ``vx``, ``vy`` (m/s) and the gyro rate ``omega`` (rad/s):
        (vx + omega·x_wheel_y_pos, vy − omega·y_wheel_x_pos, omega)."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    to_chassis_velocities = toChassisVelocities

@final
class DeadWheelOdometry(_Odometry):
    """DeadWheelOdometry(kinematics, wheel_positions, gyro_angle=None, initial_pose=Pose2d())

    Tracks a robot's pose from N dead wheels (DeadWheelKinematics) and, optionally, a
    gyro. ``wheel_positions`` are the wheels' distances (m): a list or tuple of floats or a
    1-D float64 array, in the kinematics' wheel order. With a gyro (``gyro_angle`` a
    Rotation2d) every update takes dθ from its wrapped change and fits (dx, dy) to the
    wheels; without one, all three come from the wheels (the layout must observe
    rotation). Whether a gyro is used is fixed here: ``update`` and ``resetPosition``
    must then always pass one, or never.
    """

    def __init__(
        self,
        kinematics: DeadWheelKinematics,
        wheel_positions: Sequence[float] | npt.NDArray[np.float64],
        gyro_angle: Rotation2d | None = None,
        initial_pose: Pose2d | None = None,
    ) -> None: ...
    def resetPosition(
        self,
        wheel_positions: Sequence[float] | npt.NDArray[np.float64],
        gyro_angle: Rotation2d | None,
        pose: Pose2d,
    ) -> None:
        """Reset the pose, the wheel-position baselines and (with a gyro) the gyro
        baseline; pass ``gyro_angle=None`` for an odometry without a gyro."""

    def update(
        self,
        wheel_positions: Sequence[float] | npt.NDArray[np.float64],
        gyro_angle: Rotation2d | None = None,
    ) -> Pose2d:
        """Integrate the wheel-distance changes (m) since the last call (and the gyro
        change, with a gyro); return the new pose."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition

