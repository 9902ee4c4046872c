"""Pose estimators: odometry fused with vision measurements (WPILib 2027).

Each estimator owns an odometry object of its drivetrain and keeps 1.5 s of its poses. A
vision measurement (a field-relative robot pose and the time it was taken) is compared
with the estimate at that time; the difference, scaled per axis by the steady-state
Kalman gain k = q / (q + √(q·r)) (q, r: the squared state and vision standard
deviations), becomes a correction that is replayed on every later odometry pose.

Timestamps are seconds on one monotonic clock. ``update`` reads
:meth:`MathSharedStore.getTimestamp` (``time.monotonic`` unless replaced with
:meth:`MathSharedStore.setTimestampSource`, e.g. for simulation or log replay); vision
timestamps passed alongside must use the same clock, or use ``updateWithTime``. Unlike
WPILib, timestamps must be finite (ValueError otherwise).

After warm-up, ``update``/``updateWithTime`` and ``addVisionMeasurement`` make no allocator
calls: the pose history and the vision records live in arrays that grow only when the
history needs more room, and returned poses come from the Pose2d freelist.
"""

# Hand-written stub for the compiled module drivekin.estimator (estimator.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, the estimators derive from the private base _PoseEstimator, which
# declares the methods they share (its own base, _EstimatorBase, the bookkeeping shared
# with drivekin.estimator3d, has no Python-visible members).

from collections.abc import Callable, Sequence
from typing import final, overload

import numpy as np
import numpy.typing as npt
from typing_extensions import disjoint_base

from drivekin.deadwheel import DeadWheelKinematics
from drivekin.differential import DifferentialDriveWheelPositions
from drivekin.geometry import Pose2d, Rotation2d, Translation2d
from drivekin.mecanum import MecanumDriveKinematics, MecanumDriveWheelPositions
from drivekin.swerve import SwerveDriveKinematics, SwerveModulePosition

_StdDevs = Sequence[float] | npt.NDArray[np.float64]
_ModulePositions = Sequence[SwerveModulePosition] | npt.NDArray[np.float64]
_WheelReadings = Sequence[float] | npt.NDArray[np.float64]

class ClockMismatchWarning(UserWarning):
    """A vision timestamp that cannot be on the estimator's clock (see
    :meth:`_PoseEstimator.addVisionMeasurement`). Issued once per estimator; filter it with
    ``warnings.filterwarnings("ignore", category=ClockMismatchWarning)``."""

@final
class MathSharedStore:
    """The clock the estimators' ``update`` methods read (WPILib's MathSharedStore).

    Static methods only; seconds on a monotonic clock.
    """

    @staticmethod
    def getTimestamp() -> float:
        """Return the current time in seconds from the timestamp source
        (``time.monotonic`` by default)."""

    @staticmethod
    def setTimestampSource(source: Callable[[], float] | None) -> None:
        """Make ``source()`` (a callable returning seconds as a float) the clock; None
        restores ``time.monotonic``. Use it to run estimators on simulated or recorded
        time."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    get_timestamp = getTimestamp
    set_timestamp_source = setTimestampSource

@disjoint_base
class _EstimatorBase:
    """The pose history's and the vision records' bookkeeping in time, the gains and the
    clock checks, shared by the 2-D and 3-D estimators.
    """

@disjoint_base
class _PoseEstimator(_EstimatorBase):
    """Everything but the drivetrain: the pose history, the vision records and the four
    resets shared by every estimator.
    """

    def getEstimatedPosition(self) -> Pose2d:
        """Return the current pose estimate (field frame, m)."""

    def sampleAt(self, timestamp: float, /) -> Pose2d | None:
        """Return the estimated pose at ``timestamp`` (s; clamped to the 1.5 s of stored
        history) with the vision corrections known for that time, or None before the
        first update after construction or a reset."""

    def setVisionMeasurementStdDevs(self, vision_measurement_std_devs: _StdDevs) -> None:
        """Set how much vision is trusted: standard deviations of the measured x (m),
        y (m) and heading (rad), any sequence of 3 numbers or a float64 array. Larger
        values trust vision less."""

    def addVisionMeasurement(
        self,
        vision_robot_pose: Pose2d,
        timestamp: float,
        vision_measurement_std_devs: _StdDevs | None = None,
    ) -> None:
        """Fuse a vision measurement of the robot's field pose taken at ``timestamp`` (s,
        on the estimator's clock). With ``vision_measurement_std_devs`` (x m, y m, θ rad) those
        become the standard deviations for this and later measurements (as
        :meth:`setVisionMeasurementStdDevs`). A measurement older than 1.5 s before the
        newest odometry sample is ignored, as is any before the first update.

        A timestamp more than 10 s newer than the newest odometry sample, or more than
        11.5 s older, cannot be on the estimator's clock: the first such call on an
        estimator issues a :class:`ClockMismatchWarning`. A measurement that far ahead is
        applied as WPILib does, but replaces the earlier ones that far ahead instead of
        being kept with them, so such a stream keeps one record."""

    def resetPose(self, pose: Pose2d) -> None:
        """Reset the estimate (and the odometry's pose) to ``pose``; forget the history
        and every vision correction."""

    def resetTranslation(self, translation: Translation2d) -> None:
        """Reset the position, keeping the heading and the latest vision correction of
        the heading; the history is cleared."""

    def resetRotation(self, rotation: Rotation2d) -> None:
        """Reset the heading, keeping the position and the latest vision correction of
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
class SwerveDrivePoseEstimator(_PoseEstimator):
    """SwerveDrivePoseEstimator(kinematics, gyro_angle, module_positions, initial_pose, state_std_devs=(0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9))

    Swerve odometry (any N ≥ 2 modules) fused with vision. Module positions as for
    SwerveDriveOdometry (SwerveModulePosition objects or an (N, 2) float64 array);
    standard deviations of x (m), y (m) and heading (rad).
    """

    def __init__(
        self,
        kinematics: SwerveDriveKinematics,
        gyro_angle: Rotation2d,
        module_positions: _ModulePositions,
        initial_pose: Pose2d,
        state_std_devs: _StdDevs = (0.1, 0.1, 0.1),
        vision_measurement_std_devs: _StdDevs = (0.9, 0.9, 0.9),
    ) -> None: ...
    def update(self, gyro_angle: Rotation2d, wheel_positions: _ModulePositions) -> Pose2d:
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""

    def updateWithTime(
        self, current_time: float, gyro_angle: Rotation2d, wheel_positions: _ModulePositions
    ) -> Pose2d:
        """Update the odometry with the gyro angle and module positions read at
        ``current_time`` (s); return the new estimate (Pose2d, field frame, m)."""

    def resetPosition(
        self, gyro_angle: Rotation2d, wheel_positions: _ModulePositions, pose: Pose2d
    ) -> None:
        """Reset the odometry (gyro and module baselines, pose) and forget the history
        and every vision correction."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    update_with_time = updateWithTime

@final
class MecanumDrivePoseEstimator(_PoseEstimator):
    """MecanumDrivePoseEstimator(kinematics, gyro_angle, wheel_positions, initial_pose, state_std_devs=(0.1, 0.1, 0.1), vision_measurement_std_devs=(0.45, 0.45, 0.45))

    Mecanum odometry fused with vision; standard deviations of x (m), y (m) and heading
    (rad).
    """

    def __init__(
        self,
        kinematics: MecanumDriveKinematics,
        gyro_angle: Rotation2d,
        wheel_positions: MecanumDriveWheelPositions,
        initial_pose: Pose2d,
        state_std_devs: _StdDevs = (0.1, 0.1, 0.1),
        vision_measurement_std_devs: _StdDevs = (0.45, 0.45, 0.45),
    ) -> None: ...
    def update(self, gyro_angle: Rotation2d, wheel_positions: MecanumDriveWheelPositions) -> Pose2d:
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""

    def updateWithTime(
        self,
        current_time: float,
        gyro_angle: Rotation2d,
        wheel_positions: MecanumDriveWheelPositions,
    ) -> Pose2d:
        """Update the odometry with the gyro angle and wheel positions (m) read at
        ``current_time`` (s); return the new estimate."""

    def resetPosition(
        self, gyro_angle: Rotation2d, wheel_positions: MecanumDriveWheelPositions, pose: Pose2d
    ) -> None:
        """Reset the odometry and forget the history and every vision correction."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    update_with_time = updateWithTime

@final
class DifferentialDrivePoseEstimator(_PoseEstimator):
    """DifferentialDrivePoseEstimator(gyro_angle, left_distance, right_distance, initial_pose, state_std_devs=(0.02, 0.02, 0.01), vision_measurement_std_devs=(0.1, 0.1, 0.1))

    Differential-drive odometry fused with vision (2027: no kinematics argument).
    Distances in m; ``update``, ``updateWithTime`` and ``resetPosition`` also take one
    DifferentialDriveWheelPositions instead of the two distances.
    """

    def __init__(
        self,
        gyro_angle: Rotation2d,
        left_distance: float,
        right_distance: float,
        initial_pose: Pose2d,
        state_std_devs: _StdDevs = (0.02, 0.02, 0.01),
        vision_measurement_std_devs: _StdDevs = (0.1, 0.1, 0.1),
    ) -> None: ...
    @overload
    def update(self, gyro_angle: Rotation2d, left_distance: float, right_distance: float) -> Pose2d:
        """update(gyro_angle, left_distance, right_distance) or update(gyro_angle,
        wheel_positions): updateWithTime at :meth:`MathSharedStore.getTimestamp`."""

    @overload
    def update(
        self, gyro_angle: Rotation2d, left_distance: DifferentialDriveWheelPositions
    ) -> Pose2d: ...

    @overload
    def updateWithTime(
        self,
        current_time: float,
        gyro_angle: Rotation2d,
        left_distance: float,
        right_distance: float,
    ) -> Pose2d:
        """Update the odometry with the gyro angle and the wheel distances (m) read at
        ``current_time`` (s); return the new estimate."""

    @overload
    def updateWithTime(
        self, current_time: float, gyro_angle: Rotation2d,
        left_distance: DifferentialDriveWheelPositions,
    ) -> Pose2d: ...

    @overload
    def resetPosition(
        self, gyro_angle: Rotation2d, left_distance: float, right_distance: float, pose: Pose2d
    ) -> None:
        """resetPosition(gyro_angle, left_distance, right_distance, pose) or
        resetPosition(gyro_angle, wheel_positions, pose): reset the odometry and forget the
        history and every vision correction."""

    @overload
    def resetPosition(
        self, gyro_angle: Rotation2d, left_distance: DifferentialDriveWheelPositions,
        right_distance: Pose2d,
    ) -> None: ...

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    update_with_time = updateWithTime

@final
class TwoDeadWheelPoseEstimator(_PoseEstimator):
    """TwoDeadWheelPoseEstimator(x_wheel_y_pos, y_wheel_x_pos, x_wheel_pos, y_wheel_pos, gyro_angle, initial_pose, state_std_devs=(0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9))

    TwoDeadWheelOdometry (a forward wheel at y = x_wheel_y_pos, a left wheel at
    x = y_wheel_x_pos, m; distances in m; a gyro) fused with vision.
    """

    def __init__(
        self,
        x_wheel_y_pos: float,
        y_wheel_x_pos: float,
        x_wheel_pos: float,
        y_wheel_pos: float,
        gyro_angle: Rotation2d,
        initial_pose: Pose2d,
        state_std_devs: _StdDevs = (0.1, 0.1, 0.1),
        vision_measurement_std_devs: _StdDevs = (0.9, 0.9, 0.9),
    ) -> None: ...
    def update(self, x_wheel_pos: float, y_wheel_pos: float, gyro_angle: Rotation2d) -> Pose2d:
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""

    def updateWithTime(
        self, current_time: float, x_wheel_pos: float, y_wheel_pos: float, gyro_angle: Rotation2d
    ) -> Pose2d:
        """Update the odometry with the wheel distances (m) and gyro angle read at
        ``current_time`` (s); return the new estimate."""

    def resetPosition(
        self, x_wheel_pos: float, y_wheel_pos: float, gyro_angle: Rotation2d, pose: Pose2d
    ) -> None:
        """Reset the odometry and forget the history and every vision correction."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    update_with_time = updateWithTime

@final
class DeadWheelPoseEstimator(_PoseEstimator):
    """DeadWheelPoseEstimator(kinematics, wheel_positions, gyro_angle=None, initial_pose=Pose2d(), state_std_devs=(0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9))

    DeadWheelOdometry (any dead-wheel layout, with or without a gyro; distances in m)
    fused with vision.
    """

    def __init__(
        self,
        kinematics: DeadWheelKinematics,
        wheel_positions: _WheelReadings,
        gyro_angle: Rotation2d | None = None,
        initial_pose: Pose2d | None = None,
        state_std_devs: _StdDevs = (0.1, 0.1, 0.1),
        vision_measurement_std_devs: _StdDevs = (0.9, 0.9, 0.9),
    ) -> None: ...
    def update(
        self, wheel_positions: _WheelReadings, gyro_angle: Rotation2d | None = None
    ) -> Pose2d:
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""

    def updateWithTime(
        self,
        current_time: float,
        wheel_positions: _WheelReadings,
        gyro_angle: Rotation2d | None = None,
    ) -> Pose2d:
        """Update the odometry with the wheel distances (m) (and the gyro angle, when it
        has one) read at ``current_time`` (s); return the new estimate."""

    def resetPosition(
        self, wheel_positions: _WheelReadings, gyro_angle: Rotation2d | None, pose: Pose2d
    ) -> None:
        """Reset the odometry (``gyro_angle`` None without a gyro) and forget the history
        and every vision correction."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    reset_position = resetPosition
    update_with_time = updateWithTime

