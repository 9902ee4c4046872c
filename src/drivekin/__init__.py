"""drivekin: robot drivetrain kinematics with WPILib 2027 names and numbers, on typed
Cython kernels.

Units are SI throughout (m, m/s, m/s², rad, rad/s, rad/s², s); x forward, y left,
angles counter-clockwise positive.
"""
from importlib import metadata as _metadata
from typing import TYPE_CHECKING

from drivekin.deadwheel import DeadWheelKinematics
from drivekin.differential import (
    DifferentialDriveKinematics,
    DifferentialDriveWheelAccelerations,
    DifferentialDriveWheelPositions,
    DifferentialDriveWheelVelocities,
)
from drivekin.diffswerve import (
    DifferentialSwerveModuleKinematics,
    DifferentialSwerveModuleVelocities,
    DifferentialSwerveMotorVelocities,
)
from drivekin.estimator import (
    ClockMismatchWarning,
    DeadWheelPoseEstimator,
    DifferentialDrivePoseEstimator,
    MathSharedStore,
    MecanumDrivePoseEstimator,
    SwerveDrivePoseEstimator,
    TwoDeadWheelPoseEstimator,
)
from drivekin.estimator3d import (
    DeadWheelPoseEstimator3d,
    DifferentialDrivePoseEstimator3d,
    MecanumDrivePoseEstimator3d,
    SwerveDrivePoseEstimator3d,
    TwoDeadWheelPoseEstimator3d,
)
from drivekin.geometry import Pose2d, Rotation2d, Transform2d, Translation2d, Twist2d
from drivekin.geometry3d import (
    CoordinateAxis,
    CoordinateSystem,
    Pose3d,
    Quaternion,
    Rotation3d,
    Transform3d,
    Translation3d,
    Twist3d,
)
from drivekin.interpolation import TimeInterpolatableBuffer
from drivekin.motor import DCMotor
from drivekin.setpoint import (
    DriveFeedforwards,
    ModuleConfig,
    PathConstraints,
    RobotConfig,
    SwerveSetpoint,
    SwerveSetpointGenerator,
)
from drivekin.chassis import ChassisAccelerations, ChassisVelocities
from drivekin.swerve import SwerveDriveKinematics
from drivekin.swervemodule import (
    SwerveModuleAcceleration,
    SwerveModulePosition,
    SwerveModuleVelocity,
)
from drivekin.mecanum import (
    MecanumDriveKinematics,
    MecanumDriveWheelAccelerations,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
)
from drivekin.odometry import (
    DeadWheelOdometry,
    DifferentialDriveOdometry,
    MecanumDriveOdometry,
    SwerveDriveOdometry,
    TwoDeadWheelOdometry,
)
from drivekin.odometry3d import (
    DeadWheelOdometry3d,
    DifferentialDriveOdometry3d,
    MecanumDriveOdometry3d,
    SwerveDriveOdometry3d,
    TwoDeadWheelOdometry3d,
)

try:
    # Single source: the version in pyproject.toml, as installed.
    __version__ = _metadata.version("drivekin")
except _metadata.PackageNotFoundError:  # a source tree on sys.path without an install
    __version__ = "0+unknown"

__all__ = [
    "ChassisAccelerations",
    "ChassisVelocities",
    "ClockMismatchWarning",
    "DCMotor",
    "DeadWheelKinematics",
    "DeadWheelOdometry",
    "DeadWheelPoseEstimator",
    "DifferentialDriveKinematics",
    "DifferentialDriveOdometry",
    "DifferentialDrivePoseEstimator",
    "DifferentialDriveWheelAccelerations",
    "DifferentialDriveWheelPositions",
    "DifferentialDriveWheelVelocities",
    "MathSharedStore",
    "MecanumDriveKinematics",
    "MecanumDriveOdometry",
    "MecanumDrivePoseEstimator",
    "MecanumDriveWheelAccelerations",
    "MecanumDriveWheelPositions",
    "MecanumDriveWheelVelocities",
    "Pose2d",
    "Rotation2d",
    "SwerveDriveKinematics",
    "SwerveDriveOdometry",
    "SwerveDrivePoseEstimator",
    "SwerveModuleAcceleration",
    "SwerveModulePosition",
    "SwerveModuleVelocity",
    "TimeInterpolatableBuffer",
    "Transform2d",
    "Translation2d",
    "Twist2d",
    "TwoDeadWheelOdometry",
    "TwoDeadWheelPoseEstimator",
]
# 3-D geometry (drivekin.geometry3d).
__all__ += [
    "CoordinateAxis",
    "CoordinateSystem",
    "Pose3d",
    "Quaternion",
    "Rotation3d",
    "Transform3d",
    "Translation3d",
    "Twist3d",
]
# Differential swerve pods (drivekin.diffswerve).
__all__ += [
    "DifferentialSwerveModuleKinematics",
    "DifferentialSwerveModuleVelocities",
    "DifferentialSwerveMotorVelocities",
]
# 3-D odometry and pose estimators (drivekin.odometry3d, drivekin.estimator3d).
__all__ += [
    "DeadWheelOdometry3d",
    "DeadWheelPoseEstimator3d",
    "DifferentialDriveOdometry3d",
    "DifferentialDrivePoseEstimator3d",
    "MecanumDriveOdometry3d",
    "MecanumDrivePoseEstimator3d",
    "SwerveDriveOdometry3d",
    "SwerveDrivePoseEstimator3d",
    "TwoDeadWheelOdometry3d",
    "TwoDeadWheelPoseEstimator3d",
]
# PathPlannerLib's swerve setpoint generator (drivekin.setpoint; ModuleConfig and RobotConfig
# live in drivekin.robotconfig, which drivekin.setpoint re-exports).
__all__ += [
    "DriveFeedforwards",
    "ModuleConfig",
    "PathConstraints",
    "RobotConfig",
    "SwerveSetpoint",
    "SwerveSetpointGenerator",
]
# WPILib's Units helper class (drivekin.units).
from drivekin.units import Units

__all__ += ["Units"]

# robotpy-wpimath 2026 names on these classes raise an AttributeError naming the 2027 one.
from drivekin._core import renames as _renames

_renames.install(globals())
del _renames

# robotpy 2027's spellings: snake_case names on every class (the Java ones stay the
# documented ones) and robotpy's class names (SwerveDrive4Kinematics, ...).
from drivekin._core import pynames as _pynames

__all__ += _pynames.install(globals())
del _pynames

if TYPE_CHECKING:
    # For type checkers, which cannot see the names install() adds: what each one builds
    # (tests/api/test_robotpy_names.py checks this list against them).
    from typing import Callable, Optional

    SwerveDrive2Kinematics = SwerveDrive3Kinematics = SwerveDriveKinematics
    SwerveDrive4Kinematics = SwerveDrive6Kinematics = SwerveDriveKinematics
    SwerveDrive2Odometry = SwerveDrive3Odometry = SwerveDriveOdometry
    SwerveDrive4Odometry = SwerveDrive6Odometry = SwerveDriveOdometry
    SwerveDrive2PoseEstimator = SwerveDrive3PoseEstimator = SwerveDrivePoseEstimator
    SwerveDrive4PoseEstimator = SwerveDrive6PoseEstimator = SwerveDrivePoseEstimator
    SwerveDrive2Odometry3d = SwerveDrive3Odometry3d = SwerveDriveOdometry3d
    SwerveDrive4Odometry3d = SwerveDrive6Odometry3d = SwerveDriveOdometry3d
    SwerveDrive2PoseEstimator3d = SwerveDrive3PoseEstimator3d = SwerveDrivePoseEstimator3d
    SwerveDrive4PoseEstimator3d = SwerveDrive6PoseEstimator3d = SwerveDrivePoseEstimator3d

    class TimeInterpolatablePose2dBuffer(TimeInterpolatableBuffer[Pose2d]):
        def __init__(self, history_size: float,
                     func: Optional[Callable[[Pose2d, Pose2d, float], Pose2d]] = None
                     ) -> None: ...

    class TimeInterpolatableRotation2dBuffer(TimeInterpolatableBuffer[Rotation2d]):
        def __init__(self, history_size: float,
                     func: Optional[Callable[[Rotation2d, Rotation2d, float], Rotation2d]]
                     = None) -> None: ...

    class TimeInterpolatableTranslation2dBuffer(TimeInterpolatableBuffer[Translation2d]):
        def __init__(self, history_size: float,
                     func: Optional[Callable[[Translation2d, Translation2d, float],
                                             Translation2d]] = None) -> None: ...

    class TimeInterpolatablePose3dBuffer(TimeInterpolatableBuffer[Pose3d]):
        def __init__(self, history_size: float,
                     func: Optional[Callable[[Pose3d, Pose3d, float], Pose3d]] = None
                     ) -> None: ...

    class TimeInterpolatableRotation3dBuffer(TimeInterpolatableBuffer[Rotation3d]):
        def __init__(self, history_size: float,
                     func: Optional[Callable[[Rotation3d, Rotation3d, float], Rotation3d]]
                     = None) -> None: ...

    class TimeInterpolatableTranslation3dBuffer(TimeInterpolatableBuffer[Translation3d]):
        def __init__(self, history_size: float,
                     func: Optional[Callable[[Translation3d, Translation3d, float],
                                             Translation3d]] = None) -> None: ...

    class TimeInterpolatableFloatBuffer(TimeInterpolatableBuffer[float]):
        def __init__(self, history_size: float,
                     func: Optional[Callable[[float, float, float], float]] = None
                     ) -> None: ...
