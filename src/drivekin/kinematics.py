"""The 0.1.0 home of the chassis and swerve classes, kept so that old imports and pickles
(which name ``drivekin.kinematics``) still work. New code imports from
:mod:`drivekin.chassis`, :mod:`drivekin.swervemodule` and :mod:`drivekin.swerve`, or from
:mod:`drivekin` itself."""
from drivekin import chassis, swerve
from drivekin.chassis import *  # noqa: F403
from drivekin.swerve import *  # noqa: F403

__all__ = chassis.__all__ + swerve.__all__
