"""3-D pose estimators: 3-D odometry fused with vision measurements (WPILib 2027's
PoseEstimator3d).

As the 2-D estimators (drivekin.estimator), with poses in 3-D: 1.5 s of odometry poses,
vision measurements compared with the estimate at their time, and the difference scaled
per axis by the steady-state Kalman gain k = q / (q + √(q·r)) from the state and vision
standard deviations, here four of each: x (m), y (m), z (m) and θ (rad). The θ gain
scales the correction's rotation as WPILib does: its extrinsic roll, pitch and yaw
(Rotation3d.getX/Y/Z) each times k, back through Rotation3d(roll, pitch, yaw). That is
not a geodesic scaling of the rotation: for a correction of Euler angles
(0.3, 0.3, 0.3) rad and k = 0.5 the result is 1.17° away from half the rotation about
its own axis (13.9° for (1, 1, 1) rad).

Timestamps, the clock (:class:`MathSharedStore`), stale measurements (ignored when older
than 1.5 s before the newest odometry sample, as WPILib's Java does), the
:class:`ClockMismatchWarning` and the bounded memory are the 2-D estimators'. After
warm-up, ``update``/``updateWithTime`` and ``addVisionMeasurement`` make no allocator
calls; returned poses come from the Pose3d freelist.
"""

# Hand-written stub for the compiled module drivekin.estimator3d (estimator3d.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, the estimators derive from the private base _PoseEstimator3d, which
# declares the methods they share (its base, drivekin.estimator's _EstimatorBase, has no
# Python-visible members).

from collections.abc import Sequence
from typing import overload, final

import numpy as np
import numpy.typing as npt
from typing_extensions import disjoint_base

from drivekin.deadwheel import DeadWheelKinematics
from drivekin.differential import DifferentialDriveWheelPositions
from drivekin.estimator import _EstimatorBase
from drivekin.geometry3d import Pose3d, Rotation3d, Translation3d
from drivekin.mecanum import MecanumDriveKinematics, MecanumDriveWheelPositions
from drivekin.swerve import SwerveDriveKinematics, SwerveModulePosition

_StdDevs = Sequence[float] | npt.NDArray[np.float64]
_ModulePositions = Sequence[SwerveModulePosition] | npt.NDArray[np.float64]
_WheelReadings = Sequence[float] | npt.NDArray[np.float64]

@disjoint_base
class _PoseEstimator3d(_EstimatorBase):
    """Everything but the drivetrain: the pose history, the vision records and the four
    resets shared by every 3-D estimator.
    """

    def getEstimatedPosition(self) -> Pose3d:
        """Return the current pose estimate (field frame, m)."""

    def sampleAt(self, timestamp: float, /) -> Pose3d | None:
        """Return the estimated pose at ``timestamp`` (s; clamped to the 1.5 s of stored
        history) with the vision corrections known for that time, or None before the
        first update after construction or a reset."""

    def setVisionMeasurementStdDevs(self, vision_measurement_std_devs: _StdDevs) -> None:
        """Set how much vision is trusted: standard deviations of the measured x (m),
        y (m), z (m) and rotation (rad), any sequence of 4 numbers or a float64 array.
        Larger values trust vision less."""

    def addVisionMeasurement(
        self,
        vision_robot_pose: Pose3d,
        timestamp: float,
        vision_measurement_std_devs: _StdDevs | None = None,
    ) -> None:
        """Fuse a vision measurement of the robot's field pose taken at ``timestamp`` (s,
        on the estimator's clock). With ``vision_measurement_std_devs`` (x m, y m, z m,
        θ rad) those become the standard deviations for this and later measurements (as
        :meth:`setVisionMeasurementStdDevs`). A measurement older than 1.5 s before the
        newest odometry sample is ignored, as is any before the first update.

        The correction's rotation is scaled as WPILib does: its extrinsic roll, pitch and
        yaw each times the θ gain (not a scaling about its own axis).

        A timestamp more than 10 s newer than the newest odometry sample, or more than
        11.5 s older, cannot be on the estimator's clock: the first such call on an
        estimator issues a :class:`ClockMismatchWarning`. A measurement that far ahead is
        applied as WPILib does, but replaces the earlier ones that far ahead instead of
        being kept with them, so such a stream keeps one record."""

    def resetPose(self, pose: Pose3d) -> None:
        """Reset the estimate (and the odometry's pose) to ``pose``; forget the history
        and every vision correction."""

    def resetTranslation(self, translation: Translation3d) -> None:
        """Reset the position, keeping the rotation and the latest vision correction of
        the rotation; the history is cleared."""

    def resetRotation(self, rotation: Rotation3d) -> None:
        """Reset the rotation, keeping the position and the latest vision correction of
        the position; the history is cleared."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    add_vision_measurement = addVisionMeasurement
    get_estimated_position = getEstimatedPosition
    reset_pose = resetPose
    reset_rotation = resetRotation
    reset_translation = resetTranslation
    sample_at = sampleAt
    set_vision_measurement_std_devs = setVisionMeasurementStdDevs

@final
class SwerveDrivePoseEstimator3d(_PoseEstimator3d):
    """SwerveDrivePoseEstimator3d(kinematics, gyro_angle, module_positions, initial_pose, state_std_devs=(0.1, 0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9, 0.9))

    3-D swerve odometry (any N ≥ 2 modules) fused with vision. Module positions as for
    SwerveDriveOdometry3d (SwerveModulePosition objects or an (N, 2) float64 array);
    standard deviations of x (m), y (m), z (m) and rotation (rad).
    """

    def __init__(
        self,
        kinematics: SwerveDriveKinematics,
        gyro_angle: Rotation3d,
        module_positions: _ModulePositions,
        initial_pose: Pose3d,
        state_std_devs: _StdDevs = (0.1, 0.1, 0.1, 0.1),
        vision_measurement_std_devs: _StdDevs = (0.9, 0.9, 0.9, 0.9),
    ) -> None: ...
    def update(self, gyro_angle: Rotation3d, wheel_positions: _ModulePositions) -> Pose3d:
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""

    def updateWithTime(
        self, current_time: float, gyro_angle: Rotation3d, wheel_positions: _ModulePositions
    ) -> Pose3d:
        """Update the odometry with the gyro angle and module positions read at
        ``current_time`` (s); return the new estimate (Pose3d, field frame, m)."""

    def resetPosition(
        self, gyro_angle: Rotation3d, wheel_positions: _ModulePositions, pose: Pose3d
    ) -> None:
        """Reset the odometry (gyro and module baselines, pose) and forget the history
        and every vision correction."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    update_with_time = updateWithTime

@final
class MecanumDrivePoseEstimator3d(_PoseEstimator3d):
    """MecanumDrivePoseEstimator3d(kinematics, gyro_angle, wheel_positions, initial_pose, state_std_devs=(0.1, 0.1, 0.1, 0.1), vision_measurement_std_devs=(0.45, 0.45, 0.45, 0.45))

    3-D mecanum odometry fused with vision; standard deviations of x (m), y (m), z (m) and
    rotation (rad).
    """

    def __init__(
        self,
        kinematics: MecanumDriveKinematics,
        gyro_angle: Rotation3d,
        wheel_positions: MecanumDriveWheelPositions,
        initial_pose: Pose3d,
        state_std_devs: _StdDevs = (0.1, 0.1, 0.1, 0.1),
        vision_measurement_std_devs: _StdDevs = (0.45, 0.45, 0.45, 0.45),
    ) -> None: ...
    def update(self, gyro_angle: Rotation3d, wheel_positions: MecanumDriveWheelPositions) -> Pose3d:
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""

    def updateWithTime(
        self,
        current_time: float,
        gyro_angle: Rotation3d,
        wheel_positions: MecanumDriveWheelPositions,
    ) -> Pose3d:
        """Update the odometry with the gyro angle and wheel positions (m) read at
        ``current_time`` (s); return the new estimate."""

    def resetPosition(
        self, gyro_angle: Rotation3d, wheel_positions: MecanumDriveWheelPositions, pose: Pose3d
    ) -> None:
        """Reset the odometry and forget the history and every vision correction."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    update_with_time = updateWithTime

@final
class DifferentialDrivePoseEstimator3d(_PoseEstimator3d):
    """DifferentialDrivePoseEstimator3d(gyro_angle, left_distance, right_distance, initial_pose, state_std_devs=(0.02, 0.02, 0.02, 0.01), vision_measurement_std_devs=(0.1, 0.1, 0.1, 0.1))

    3-D differential-drive odometry fused with vision (2027: no kinematics argument).
    Distances in m; ``update``, ``updateWithTime`` and ``resetPosition`` also take one
    DifferentialDriveWheelPositions instead of the two distances.
    """

    def __init__(
        self,
        gyro_angle: Rotation3d,
        left_distance: float,
        right_distance: float,
        initial_pose: Pose3d,
        state_std_devs: _StdDevs = (0.02, 0.02, 0.02, 0.01),
        vision_measurement_std_devs: _StdDevs = (0.1, 0.1, 0.1, 0.1),
    ) -> None: ...
    @overload
    def update(self, gyro_angle: Rotation3d, left_distance: float, right_distance: float) -> Pose3d:
        """update(gyro_angle, left_distance, right_distance) or update(gyro_angle,
        wheel_positions): updateWithTime at :meth:`MathSharedStore.getTimestamp`."""

    @overload
    def update(
        self, gyro_angle: Rotation3d, left_distance: DifferentialDriveWheelPositions
    ) -> Pose3d: ...

    @overload
    def updateWithTime(
        self,
        current_time: float,
        gyro_angle: Rotation3d,
        left_distance: float,
        right_distance: float,
    ) -> Pose3d:
        """Update the odometry with the gyro angle and the wheel distances (m) read at
        ``current_time`` (s); return the new estimate."""

    @overload
    def updateWithTime(
        self, current_time: float, gyro_angle: Rotation3d,
        left_distance: DifferentialDriveWheelPositions,
    ) -> Pose3d: ...

    @overload
    def resetPosition(
        self, gyro_angle: Rotation3d, left_distance: float, right_distance: float, pose: Pose3d
    ) -> None:
        """resetPosition(gyro_angle, left_distance, right_distance, pose) or
        resetPosition(gyro_angle, wheel_positions, pose): reset the odometry and forget the
        history and every vision correction."""

    @overload
    def resetPosition(
        self, gyro_angle: Rotation3d, left_distance: DifferentialDriveWheelPositions,
        right_distance: Pose3d,
    ) -> None: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    update_with_time = updateWithTime

@final
class DeadWheelPoseEstimator3d(_PoseEstimator3d):
    """DeadWheelPoseEstimator3d(kinematics, wheel_positions, gyro_angle, initial_pose=Pose3d(), state_std_devs=(0.1, 0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9, 0.9))

    DeadWheelOdometry3d (any dead-wheel layout that observes (dx, dy), a gyro; distances in
    m) fused with vision.
    """

    def __init__(
        self,
        kinematics: DeadWheelKinematics,
        wheel_positions: _WheelReadings,
        gyro_angle: Rotation3d,
        initial_pose: Pose3d | None = None,
        state_std_devs: _StdDevs = (0.1, 0.1, 0.1, 0.1),
        vision_measurement_std_devs: _StdDevs = (0.9, 0.9, 0.9, 0.9),
    ) -> None: ...
    def update(self, wheel_positions: _WheelReadings, gyro_angle: Rotation3d) -> Pose3d:
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""

    def updateWithTime(
        self, current_time: float, wheel_positions: _WheelReadings, gyro_angle: Rotation3d
    ) -> Pose3d:
        """Update the odometry with the wheel distances (m) and the gyro angle read at
        ``current_time`` (s); return the new estimate."""

    def resetPosition(
        self, wheel_positions: _WheelReadings, gyro_angle: Rotation3d, pose: Pose3d
    ) -> None:
        """Reset the odometry and forget the history and every vision correction."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    update_with_time = updateWithTime

@final
class TwoDeadWheelPoseEstimator3d(_PoseEstimator3d):
    """TwoDeadWheelPoseEstimator3d(x_wheel_y_pos, y_wheel_x_pos, x_wheel_pos, y_wheel_pos, gyro_angle, initial_pose, state_std_devs=(0.1, 0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9, 0.9))

    TwoDeadWheelOdometry3d (a forward wheel at y = x_wheel_y_pos, a left wheel at
    x = y_wheel_x_pos, m; distances in m; a gyro) fused with vision.
    """

    def __init__(
        self,
        x_wheel_y_pos: float,
        y_wheel_x_pos: float,
        x_wheel_pos: float,
        y_wheel_pos: float,
        gyro_angle: Rotation3d,
        initial_pose: Pose3d,
        state_std_devs: _StdDevs = (0.1, 0.1, 0.1, 0.1),
        vision_measurement_std_devs: _StdDevs = (0.9, 0.9, 0.9, 0.9),
    ) -> None: ...
    def update(self, x_wheel_pos: float, y_wheel_pos: float, gyro_angle: Rotation3d) -> Pose3d:
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""

    def updateWithTime(
        self, current_time: float, x_wheel_pos: float, y_wheel_pos: float, gyro_angle: Rotation3d
    ) -> Pose3d:
        """Update the odometry with the wheel distances (m) and the gyro angle read at
        ``current_time`` (s); return the new estimate."""

    def resetPosition(
        self, x_wheel_pos: float, y_wheel_pos: float, gyro_angle: Rotation3d, pose: Pose3d
    ) -> None:
        """Reset the odometry and forget the history and every vision correction."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    update_with_time = updateWithTime
