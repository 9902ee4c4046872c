"""drivekin: robot drivetrain kinematics with WPILib 2027 names and numbers, on typed
Cython kernels.

Units are SI throughout (m, m/s, m/s², rad, rad/s, rad/s², s); x forward, y left,
angles counter-clockwise positive.
"""
from importlib import metadata as _metadata

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
from drivekin.geometry import Pose2d, Rotation2d, Transform2d, Translation2d, Twist2d
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
# Differential swerve pods (drivekin.diffswerve).
__all__ += [
    "DifferentialSwerveModuleKinematics",
    "DifferentialSwerveModuleVelocities",
    "DifferentialSwerveMotorVelocities",
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

# robotpy 2027's names without a Java counterpart (from_feet, x_feet, vx_fps, from_matrix...).
from drivekin._core import robotpyextras as _robotpyextras

_robotpyextras.install_extras(globals())
del _robotpyextras
