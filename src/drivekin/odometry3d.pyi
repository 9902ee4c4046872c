"""3-D odometry for swerve, mecanum, differential and dead-wheel drivetrains (WPILib 2027's
Odometry3d).

Each ``update`` takes the gyro's change since the previous call as a body-frame rotation
Δ = gyro.relativeTo(previous gyro) with rotation vector ρ, and the wheel-position changes
through the drivetrain's forward kinematics as a planar twist (dx, dy) in the robot
frame; the pose moves by Twist3d(dx, dy, 0, ρ).exp(). The translation is integrated
along the robot's axes, so driving up a pitched ramp produces z; roll, pitch and heading
come from the gyro alone. The pose's rotation starts at the initial pose's rotation
(the identity by default), whatever the gyro reads: only the gyro's changes are
composed onto it.

``update`` returns the new pose; it allocates nothing beyond that Pose3d, which comes
from a freelist, so a 50 Hz loop runs without allocator calls.
"""

# Hand-written stub for the compiled module drivekin.odometry3d (odometry3d.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, the odometry classes derive from the private base _Odometry3d, which
# declares the methods they share.

from collections.abc import Sequence
from typing import final

import numpy as np
import numpy.typing as npt
from typing_extensions import disjoint_base

from drivekin.chassis import ChassisVelocities
from drivekin.deadwheel import DeadWheelKinematics
from drivekin.geometry3d import Pose3d, Rotation3d, Translation3d
from drivekin.mecanum import MecanumDriveKinematics, MecanumDriveWheelPositions
from drivekin.swerve import SwerveDriveKinematics, SwerveModulePosition

_ModulePositions = Sequence[SwerveModulePosition] | npt.NDArray[np.float64]
_WheelReadings = Sequence[float] | npt.NDArray[np.float64]

@disjoint_base
class _Odometry3d:
    """Pose state, the update and the resets shared by every 3-D odometry class."""

    def getPose(self) -> Pose3d:
        """Return the current pose estimate (field frame, m)."""

    def resetPose(self, pose: Pose3d) -> None:
        """Set the pose; the gyro and wheel baselines are left as they are."""

    def resetTranslation(self, translation: Translation3d) -> None:
        """Set the position and keep the rotation."""

    def resetRotation(self, rotation: Rotation3d) -> None:
        """Set the rotation and keep the position; later gyro changes are composed onto
        it."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    get_pose = getPose
    reset_pose = resetPose
    reset_rotation = resetRotation
    reset_translation = resetTranslation

@final
class SwerveDriveOdometry3d(_Odometry3d):
    """SwerveDriveOdometry3d(kinematics, gyro_angle, module_positions, initial_pose=Pose3d())

    Tracks a swerve robot's 3-D pose from N module positions (SwerveModulePosition objects
    or an (N, 2) float64 array ``[distance m, angle rad]``) and a gyro (Rotation3d). A
    later call with another number of modules raises ValueError and changes nothing.
    """

    def __init__(
        self,
        kinematics: SwerveDriveKinematics,
        gyro_angle: Rotation3d,
        module_positions: _ModulePositions,
        initial_pose: Pose3d | None = None,
    ) -> None: ...
    def resetPosition(
        self, gyro_angle: Rotation3d, wheel_positions: _ModulePositions, pose: Pose3d
    ) -> None:
        """Reset the pose, the gyro baseline and the module-position baseline."""

    def update(self, gyro_angle: Rotation3d, wheel_positions: _ModulePositions) -> Pose3d:
        """Integrate the module-distance changes since the last call (at the current module
        angles) and the gyro change; return the new pose."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition

@final
class MecanumDriveOdometry3d(_Odometry3d):
    """MecanumDriveOdometry3d(kinematics, gyro_angle, wheel_positions, initial_pose=Pose3d())

    Tracks a mecanum robot's 3-D pose from MecanumDriveWheelPositions (m) and a gyro
    (Rotation3d).
    """

    def __init__(
        self,
        kinematics: MecanumDriveKinematics,
        gyro_angle: Rotation3d,
        wheel_positions: MecanumDriveWheelPositions,
        initial_pose: Pose3d | None = None,
    ) -> None: ...
    def resetPosition(
        self, gyro_angle: Rotation3d, wheel_positions: MecanumDriveWheelPositions, pose: Pose3d
    ) -> None:
        """Reset the pose, the gyro baseline and the wheel-position baseline."""

    def update(self, gyro_angle: Rotation3d, wheel_positions: MecanumDriveWheelPositions) -> Pose3d:
        """Integrate the wheel-distance changes since the last call and the gyro change;
        return the new pose."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition

@final
class DifferentialDriveOdometry3d(_Odometry3d):
    """DifferentialDriveOdometry3d(gyro_angle, left_distance, right_distance, initial_pose=Pose3d())

    Tracks a differential-drive robot's 3-D pose from the left and right wheel distances
    (m) and a gyro (Rotation3d). No trackwidth is needed: the rotation comes from the gyro.
    """

    def __init__(
        self,
        gyro_angle: Rotation3d,
        left_distance: float,
        right_distance: float,
        initial_pose: Pose3d | None = None,
    ) -> None: ...
    def resetPosition(
        self, gyro_angle: Rotation3d, left_distance: float, right_distance: float, pose: Pose3d
    ) -> None:
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""

    def update(self, gyro_angle: Rotation3d, left_distance: float, right_distance: float) -> Pose3d:
        """Integrate the wheel-distance changes since the last call (dx = mean change,
        dy = 0) and the gyro change; return the new pose."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition

@final
class DeadWheelOdometry3d(_Odometry3d):
    """DeadWheelOdometry3d(kinematics, wheel_positions, gyro_angle, initial_pose=Pose3d())

    Tracks a robot's 3-D pose from N dead wheels (DeadWheelKinematics) and a gyro
    (Rotation3d). ``wheel_positions`` are the wheels' distances (m): a list or tuple of
    floats or a 1-D float64 array, in the kinematics' wheel order. Every update fits the
    robot-frame (dx, dy) to the wheel changes less the arcs that the yaw of the gyro's
    change swept each wheel through; any layout that observes (dx, dy) works, since the
    rotation comes from the gyro.
    """

    def __init__(
        self,
        kinematics: DeadWheelKinematics,
        wheel_positions: _WheelReadings,
        gyro_angle: Rotation3d,
        initial_pose: Pose3d | None = None,
    ) -> None: ...
    def resetPosition(
        self, wheel_positions: _WheelReadings, gyro_angle: Rotation3d, pose: Pose3d
    ) -> None:
        """Reset the pose, the wheel-position baselines and the gyro baseline."""

    def update(self, wheel_positions: _WheelReadings, gyro_angle: Rotation3d) -> Pose3d:
        """Integrate the wheel-distance changes (m) since the last call and the gyro
        change; return the new pose."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition

@final
class TwoDeadWheelOdometry3d(_Odometry3d):
    """TwoDeadWheelOdometry3d(x_wheel_y_pos, y_wheel_x_pos, x_wheel_pos, y_wheel_pos, gyro_angle, initial_pose=Pose3d())

    TwoDeadWheelOdometry in 3-D: a forward-facing wheel at y = ``x_wheel_y_pos`` (m), a
    left-facing wheel at x = ``y_wheel_x_pos`` (m) (goBILDA Pinpoint's pod offsets) and a
    gyro (Rotation3d). ``x_wheel_pos``/``y_wheel_pos`` are the wheels' distances (m). Each
    update uses dθ = the yaw of the gyro's change, dx = Δx + dθ·x_wheel_y_pos,
    dy = Δy − dθ·y_wheel_x_pos: a DeadWheelOdometry3d on those two wheels.
    """

    def __init__(
        self,
        x_wheel_y_pos: float,
        y_wheel_x_pos: float,
        x_wheel_pos: float,
        y_wheel_pos: float,
        gyro_angle: Rotation3d,
        initial_pose: Pose3d | None = None,
    ) -> None: ...
    def resetPosition(
        self, x_wheel_pos: float, y_wheel_pos: float, gyro_angle: Rotation3d, pose: Pose3d
    ) -> None:
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""

    def update(self, x_wheel_pos: float, y_wheel_pos: float, gyro_angle: Rotation3d) -> Pose3d:
        """Integrate the wheel-distance changes (m) since the last call and the gyro
        change; return the new pose."""

    def toChassisVelocities(self, vx: float, vy: float, omega: float) -> ChassisVelocities:
        """Return the robot velocity from the forward wheel's and left wheel's surface
        velocities ``vx``, ``vy`` (m/s) and the gyro's yaw rate ``omega`` (rad/s):
        (vx + omega·x_wheel_y_pos, vy − omega·y_wheel_x_pos, omega)."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    to_chassis_velocities = toChassisVelocities
