"""The demo's simulated drivetrains by name (``--drivetrain``, ``--vision``,
``--setpoint-generator``); each turns a command into wheel motion, a simulated gyro and
its drivekin odometry (or estimator) update, in one 20 ms step."""
from __future__ import annotations

from drivekin.app.demo.diffswerve import DiffSwerveDrive
from drivekin.app.demo.sim import Drivetrain
from drivekin.app.demo.swerve import SwerveDrive, VisionSwerveDrive
from drivekin.app.demo.wheeled import DeadWheelDrive, DifferentialDrive, MecanumDrive


DRIVETRAINS = {cls.name: cls for cls in (SwerveDrive, MecanumDrive, DifferentialDrive,
                                         DeadWheelDrive, DiffSwerveDrive)}


VISION_DRIVETRAINS = {"swerve": VisionSwerveDrive}


SETPOINT_DRIVETRAINS = tuple(name for name, cls in DRIVETRAINS.items() if cls.SETPOINT_GENERATOR)


def drivetrain_class(name: str, vision: bool = False) -> type[Drivetrain]:
    """The simulated drivetrain for ``--drivetrain name`` (with ``--vision``)."""
    if vision:
        if name not in VISION_DRIVETRAINS:
            raise ValueError(f"--vision is simulated for {', '.join(VISION_DRIVETRAINS)} only")
        return VISION_DRIVETRAINS[name]
    return DRIVETRAINS[name]


def make_drivetrain(name: str, max_speed: float, vision: bool = False,
                    setpoint_generator: bool = False) -> Drivetrain:
    """A new simulated drivetrain for ``--drivetrain name`` (with ``--vision``,
    ``--setpoint-generator``)."""
    cls = drivetrain_class(name, vision)
    if not setpoint_generator:
        return cls(max_speed)
    if not cls.SETPOINT_GENERATOR:
        raise ValueError(f"--setpoint-generator is simulated for "
                         f"{', '.join(SETPOINT_DRIVETRAINS)} only")
    return cls(max_speed, setpoint_generator=True)
