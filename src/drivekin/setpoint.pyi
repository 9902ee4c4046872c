"""Kinematically limited swerve setpoints: PathPlannerLib's ``SwerveSetpointGenerator``
(after Team 254's), for any number of modules.

Units: m, m/s, rad, rad/s, s, kg, kg·m², N, N·m, A, V. Robot frame: x forward, y left,
CCW positive.

Each call moves the previous setpoint towards the desired robot-relative velocities as
far as the robot can in one loop period: module steering rate, drive torque (motor
curve, current limit, battery voltage, wheel friction) and the optional
:class:`PathConstraints`. Two behaviours:

- the default enforces every limit between consecutive setpoints. The desired velocities
  are desaturated and discretized first, without skew
  (:meth:`SwerveDriveKinematics.desaturatedDiscretize`), and the step is then limited in
  that space; the drive limit's root is scaled by the steering limit's, as in Team 254's
  original;
- ``compatibility="pathplanner"`` reproduces PathPlannerLib Java/C++ 2026: it drops
  254's factor (so a module's drive limit is under-enforced once the step has been
  shortened, by steering or by another module's drive limit) and discretizes after
  limiting (so consecutive outputs can differ by more than the limits allow while the
  robot turns).

docs/setpoints.md gives the rules, the PathPlanner → drivekin names and the measured
differences."""

# Hand-written stub for the compiled module drivekin.setpoint (setpoint.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.

from collections.abc import Sequence
from typing import ClassVar, Literal, Protocol, final

from drivekin._core.setpointkernel import SetpointKernel
from drivekin.chassis import ChassisVelocities
from drivekin.robotconfig import ModuleConfig as ModuleConfig
from drivekin.robotconfig import RobotConfig as RobotConfig
from drivekin.swerve import SwerveModuleVelocity

__all__ = ["DriveFeedforwards", "ModuleConfig", "PathConstraints", "RobotConfig",
           "SwerveSetpoint", "SwerveSetpointGenerator"]

class _Constraints(Protocol):
    # pathplannerlib's PathConstraints, or anything else with these four numbers.
    @property
    def maxVelocityMps(self) -> float: ...
    @property
    def maxAccelerationMpsSq(self) -> float: ...
    @property
    def maxAngularVelocityRps(self) -> float: ...
    @property
    def maxAngularAccelerationRpsSq(self) -> float: ...

@final
class PathConstraints:
    """PathConstraints(maxVelocityMps, maxAccelerationMpsSq, maxAngularVelocityRps, maxAngularAccelerationRpsSq, nominalVoltage=12.0, unlimited=False)

    PathPlannerLib's limits on top of the robot's own: linear velocity (m/s) and
    acceleration (m/s²), angular velocity (rad/s) and angular acceleration (rad/s²).
    The maxima must be ≥ 0 (+inf for none); ``nominalVoltage`` (V) and ``unlimited`` are
    carried for PathPlanner's path follower and do not change the setpoint generator,
    as in PathPlannerLib. The generator also takes any object with these four attribute
    names (pathplannerlib's own PathConstraints). Immutable."""

    def __init__(self, maxVelocityMps: float, maxAccelerationMpsSq: float,
                 maxAngularVelocityRps: float, maxAngularAccelerationRpsSq: float,
                 nominalVoltage: float = 12.0, unlimited: bool = False) -> None: ...
    @staticmethod
    def unlimitedConstraints(nominalVoltage: float = 12.0) -> PathConstraints:
        """Constraints that limit nothing (every maximum +inf, ``unlimited`` True)."""
    @property
    def maxVelocityMps(self) -> float:
        """Largest linear speed, m/s."""
    @property
    def maxAccelerationMpsSq(self) -> float:
        """Largest linear acceleration, m/s²."""
    @property
    def maxAngularVelocityRps(self) -> float:
        """Largest angular speed, rad/s."""
    @property
    def maxAngularAccelerationRpsSq(self) -> float:
        """Largest angular acceleration, rad/s²."""
    @property
    def nominalVoltage(self) -> float:
        """Nominal battery voltage, V (unused by the setpoint generator)."""
    @property
    def unlimited(self) -> bool:
        """Whether these are the unlimited constraints."""
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

@final
class DriveFeedforwards:
    """DriveFeedforwards(accelerationsMPSSq, linearForcesNewtons, torqueCurrentsAmps, robotRelativeForcesXNewtons, robotRelativeForcesYNewtons)

    Per-module feedforwards of a setpoint, each a sequence of N floats in module order:
    drive acceleration (m/s²), linear force at the wheel along the module (N), the drive
    current that makes that force (A), and the wheel's force vector in the robot frame
    (x and y, N). The attributes return tuples. ``==`` compares every value."""

    def __init__(self, accelerationsMPSSq: Sequence[float],
                 linearForcesNewtons: Sequence[float], torqueCurrentsAmps: Sequence[float],
                 robotRelativeForcesXNewtons: Sequence[float],
                 robotRelativeForcesYNewtons: Sequence[float]) -> None: ...
    @staticmethod
    def zeros(numModules: int) -> DriveFeedforwards:
        """Feedforwards of zeros for ``numModules`` modules."""
    @property
    def accelerationsMPSSq(self) -> tuple[float, ...]:
        """Drive accelerations, m/s² (tuple, one per module)."""
    @property
    def linearForcesNewtons(self) -> tuple[float, ...]:
        """Linear forces at the wheels along the modules, N."""
    @property
    def torqueCurrentsAmps(self) -> tuple[float, ...]:
        """Drive currents that produce those forces, A."""
    @property
    def robotRelativeForcesXNewtons(self) -> tuple[float, ...]:
        """x components of the wheel force vectors, robot frame, N."""
    @property
    def robotRelativeForcesYNewtons(self) -> tuple[float, ...]:
        """y components of the wheel force vectors, robot frame, N."""
    def __len__(self) -> int: ...
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

@final
class SwerveSetpoint:
    """SwerveSetpoint(robotRelativeVelocities, moduleVelocities, feedforwards)

    A setpoint of the generator: robot-relative ChassisVelocities (m/s, rad/s), one
    SwerveModuleVelocity per module and their :class:`DriveFeedforwards`. The setpoint
    owns copies of what it is given; its attributes return those objects, which
    :meth:`SwerveSetpointGenerator.generateSetpointInto` updates in place when the
    setpoint is its ``out``. ``==`` compares every value."""

    def __init__(self, robotRelativeVelocities: ChassisVelocities,
                 moduleVelocities: Sequence[SwerveModuleVelocity],
                 feedforwards: DriveFeedforwards) -> None: ...
    @property
    def robotRelativeVelocities(self) -> ChassisVelocities:
        """Robot-relative chassis velocities (ChassisVelocities, m/s and rad/s)."""
    @property
    def moduleVelocities(self) -> tuple[SwerveModuleVelocity, ...]:
        """Module velocities (tuple of SwerveModuleVelocity, m/s and angle)."""
    @property
    def feedforwards(self) -> DriveFeedforwards:
        """The modules' DriveFeedforwards."""
    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

@final
class SwerveSetpointGenerator(SetpointKernel):
    """SwerveSetpointGenerator(config, maxSteerVelocityRadPerSec, brownoutVoltage=6.75, compatibility=None)

    Limits setpoints to what the robot in ``config`` (:class:`RobotConfig`) can do with
    modules that steer at most ``maxSteerVelocityRadPerSec`` (rad/s, > 0, +inf for no
    limit). ``brownoutVoltage`` (V, ≥ 0) is the lowest battery voltage the torque model
    assumes (SystemCore's default brownout is 6.75 V; PathPlannerLib reads the robot
    controller's). ``compatibility`` is None (every limit enforced between consecutive
    setpoints) or ``"pathplanner"`` (PathPlannerLib Java/C++ 2026's numbers, its
    under-enforced drive limit included); the module docstring says how they differ.

    Like PathPlannerLib's, whose heading memory lives in its RobotConfig's kinematics,
    the generator remembers each module's last heading (a module stopped in a moving
    robot keeps its angle). Not thread-safe; every call holds the GIL."""

    def __init__(self, config: RobotConfig, maxSteerVelocityRadPerSec: float,
                 brownoutVoltage: float = 6.75,
                 compatibility: Literal["pathplanner"] | None = None) -> None: ...
    @property
    def config(self) -> RobotConfig:
        """The RobotConfig."""
    @property
    def maxSteerVelocityRadPerSec(self) -> float:
        """Largest module steering rate, rad/s."""
    @property
    def brownoutVoltage(self) -> float:
        """Lowest voltage the torque model assumes, V."""
    @property
    def compatibility(self) -> Literal["pathplanner"] | None:
        """None or ``"pathplanner"``."""
    def generateSetpoint(self, prevSetpoint: SwerveSetpoint,
                         desiredRobotRelativeVelocities: ChassisVelocities, dt: float,
                         inputVoltage: float = ...,
                         constraints: PathConstraints | _Constraints | None = None
                         ) -> SwerveSetpoint:
        """Return the next :class:`SwerveSetpoint` from ``prevSetpoint`` (normally the
        previous call's result) towards ``desiredRobotRelativeVelocities`` (m/s, rad/s;
        not discretized: the generator does that) over ``dt`` (s, from 1e-9 to 1e6).
        Velocities (desired and previous) must be at most 1e100 in magnitude, so that
        every setpoint is finite; one that still overflows (a robot whose own numbers
        are extreme) raises ValueError.

        ``inputVoltage`` (V) is the drive motors' supply: NaN means 12 V, lower values
        are raised to ``brownoutVoltage``; the top speed scales by min(1, V/12).
        ``constraints`` (:class:`PathConstraints`, or None) adds PathPlanner's limits.
        Invalid arguments raise ValueError or TypeError and change nothing."""
    def generateSetpointInto(self, prevSetpoint: SwerveSetpoint,
                             desiredRobotRelativeVelocities: ChassisVelocities, dt: float,
                             out: SwerveSetpoint, inputVoltage: float = ...,
                             constraints: PathConstraints | _Constraints | None = None
                             ) -> None:
        """Allocation-free :meth:`generateSetpoint`: the result is written into ``out``
        (a SwerveSetpoint for this robot's modules, which may be ``prevSetpoint``), its
        ChassisVelocities, module velocities and feedforwards updated in place. Returns
        None."""
