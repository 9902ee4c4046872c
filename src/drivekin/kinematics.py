"""The 0.1.0 home of the chassis and swerve classes, kept so that old imports and pickles
(which name ``drivekin.kinematics``) still work. New code imports from
:mod:`drivekin.chassis` and :mod:`drivekin.swerve`, or from :mod:`drivekin` itself."""
from drivekin.chassis import ChassisAccelerations, ChassisVelocities
from drivekin.swerve import (
    SwerveDriveKinematics,
    SwerveModuleAcceleration,
    SwerveModulePosition,
    SwerveModuleVelocity,
)

__all__ = [
    "ChassisAccelerations",
    "ChassisVelocities",
    "SwerveDriveKinematics",
    "SwerveModuleAcceleration",
    "SwerveModulePosition",
    "SwerveModuleVelocity",
]
