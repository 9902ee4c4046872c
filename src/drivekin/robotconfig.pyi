"""The robot as PathPlannerLib's swerve setpoint generator sees it: :class:`ModuleConfig`
(one module's drive) and :class:`RobotConfig` (mass, moment of inertia, module positions),
from code or from the PathPlanner GUI's ``settings.json`` (:meth:`RobotConfig.fromGUISettings`).

Units: m, m/s, kg, kg·m², N, N·m, A. Robot frame: x forward, y left. docs/setpoints.md
gives the PathPlanner → drivekin names; :mod:`drivekin.setpoint` exports these classes
too."""

# Hand-written stub for the compiled module drivekin.robotconfig (robotconfig.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.

from collections.abc import Sequence
from os import PathLike
from typing import ClassVar, final

from drivekin.geometry import Translation2d
from drivekin.motor import DCMotor

__all__ = ["ModuleConfig", "RobotConfig"]

@final
class ModuleConfig:
    """ModuleConfig(wheelRadiusMeters, maxDriveVelocityMPS, wheelCOF, driveMotor, driveCurrentLimit, numMotors=1)

    One swerve module's drive: wheel radius (m), the top speed it reaches while driving
    the robot at full output (m/s), the coefficient of friction between wheel and carpet
    (1.0 if unsure), the drive gearbox as a :class:`DCMotor` with its reduction
    (``DCMotor.getKrakenX60(1).withReduction(6.75)``), the current limit per motor (A)
    and the number of drive motors per module.

    As in PathPlannerLib, ``driveCurrentLimit`` reads back multiplied by ``numMotors``,
    and ``torqueLoss`` is the torque the motor still makes at top speed on 12 V (limited
    by the current limit), which models the module's friction. Every number must be
    positive and finite (ValueError), ``driveMotor`` a drivekin DCMotor (TypeError).
    Immutable; ``==`` compares every field."""

    def __init__(self, wheelRadiusMeters: float, maxDriveVelocityMPS: float, wheelCOF: float,
                 driveMotor: DCMotor, driveCurrentLimit: float, numMotors: int = 1) -> None: ...
    @property
    def wheelRadiusMeters(self) -> float:
        """Drive wheel radius, m."""
    @property
    def maxDriveVelocityMPS(self) -> float:
        """Top drive speed at full output, m/s."""
    @property
    def maxDriveVelocityRadPerSec(self) -> float:
        """Top wheel speed, rad/s: ``maxDriveVelocityMPS / wheelRadiusMeters``."""
    @property
    def wheelCOF(self) -> float:
        """Coefficient of friction between wheel and carpet."""
    @property
    def driveMotor(self) -> DCMotor:
        """The drive gearbox (DCMotor, reduction included)."""
    @property
    def driveCurrentLimit(self) -> float:
        """Current limit of the module's drive motors together, A (per motor × numMotors)."""
    @property
    def numMotors(self) -> int:
        """Drive motors per module."""
    @property
    def torqueLoss(self) -> float:
        """Torque lost to friction in the module, N·m."""
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

@final
class RobotConfig:
    """RobotConfig(massKG, MOI, moduleConfig, moduleOffsets)

    The robot as the setpoint generator sees it: mass including bumpers and battery (kg),
    moment of inertia about its centre (kg·m²), the :class:`ModuleConfig` shared by its
    modules, and the N ≥ 2 module positions (Translation2d, m, robot frame, none at the
    centre) in the order the setpoints use. PathPlannerLib's derived values are
    attributes: ``wheelFrictionForce = wheelCOF · (massKG / N) · 9.8`` (N) and
    ``maxTorqueFriction = wheelFrictionForce · wheelRadiusMeters`` (N·m).
    Immutable; ``==`` compares every field."""

    def __init__(self, massKG: float, MOI: float, moduleConfig: ModuleConfig,
                 moduleOffsets: Sequence[Translation2d]) -> None: ...
    @staticmethod
    def fromGUISettings(path: str | PathLike[str]) -> RobotConfig:
        """Read PathPlanner's ``settings.json`` (``deploy/pathplanner/settings.json`` in a
        robot project) at ``path`` (a str or os.PathLike; TypeError otherwise) into a
        RobotConfig: mass, MOI, wheel radius, gearing, top speed, wheel COF, drive motor
        type and current limit, and the four module positions. A file that is not a
        swerve (holonomic) robot's settings, lacks a key or holds a value of the wrong
        kind (a number must be finite as a float) raises ValueError naming it. So does a
        path that is not a regular file (a FIFO or a device is not opened), a file larger
        than 1 MiB (the GUI writes a few KB) or JSON nested deeper than 64 levels."""
    @property
    def massKG(self) -> float:
        """Robot mass, kg."""
    @property
    def MOI(self) -> float:
        """Moment of inertia about the robot's centre, kg·m²."""
    @property
    def moduleConfig(self) -> ModuleConfig:
        """The ModuleConfig of every module."""
    @property
    def moduleLocations(self) -> tuple[Translation2d, ...]:
        """Module positions (tuple of Translation2d, m, robot frame)."""
    @property
    def numModules(self) -> int:
        """Number of modules."""
    @property
    def modulePivotDistance(self) -> tuple[float, ...]:
        """Each module's distance from the robot's centre (tuple of floats, m)."""
    @property
    def wheelFrictionForce(self) -> float:
        """Friction force one wheel can transmit, N: ``wheelCOF · (massKG / N) · 9.8``."""
    @property
    def maxTorqueFriction(self) -> float:
        """Largest wheel torque before it slips, N·m."""
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]
