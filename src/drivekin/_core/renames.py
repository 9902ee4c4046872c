"""robotpy-wpimath 2026 names on drivekin classes (docs/porting.md, "Renames"): one rule
for all of them. Using one raises an AttributeError that names the WPILib 2027
replacement, from an instance or from the class (``ChassisVelocities.
fromFieldRelativeSpeeds``). None is an alias: several 2026 names mean something else in
2027 (2026's ``optimize`` mutates, 2027's returns a new object), so working on would hide
the change. The names live in the type dictionaries as descriptors that raise, so the
classes' own attribute lookups cost nothing more.
"""
from __future__ import annotations

from typing import Any

_R = "2027 renamed it"

# class name -> {2026 name: what to use instead}
RENAMES: dict[str, dict[str, str]] = {
    "ChassisVelocities": {
        "fromFieldRelativeSpeeds": "ChassisVelocities(vx, vy, omega).toRobotRelative(robot_angle)",
        "fromRobotRelativeSpeeds": "ChassisVelocities(vx, vy, omega).toFieldRelative(robot_angle)",
    },
    "SwerveDriveKinematics": {
        "toSwerveModuleStates": "toSwerveModuleVelocities",
        "toChassisSpeeds": "toChassisVelocities",
        "desaturateWheelSpeeds": "desaturateWheelVelocities (a new tuple) or "
                                 "desaturateWheelVelocitiesInPlace",
    },
    "MecanumDriveKinematics": {"toWheelSpeeds": "toWheelVelocities",
                               "toChassisSpeeds": "toChassisVelocities"},
    "DifferentialDriveKinematics": {"toWheelSpeeds": "toWheelVelocities",
                                    "toChassisSpeeds": "toChassisVelocities",
                                    "trackWidth": "trackwidth"},
    "SwerveModuleVelocity": {"speed": "velocity"},
    "Rotation2d": {"radians": "getRadians()", "degrees": "getDegrees()",
                   "cos": "getCos()", "sin": "getSin()", "tan": "getTan()"},
    "Translation2d": {"norm": "getNorm()", "angle": "getAngle()",
                      "distance": "getDistance(other)", "X": "getX() or .x",
                      "Y": "getY() or .y"},
    "Pose2d": {"rotation": "getRotation()", "translation": "getTranslation()",
               "X": "getX() or .x", "Y": "getY() or .y"},
    "Transform2d": {"rotation": "getRotation()", "translation": "getTranslation()",
                    "X": "getX() or .x", "Y": "getY() or .y"},
    "DCMotor": {
        "current": "getCurrent", "torque": "getTorque", "voltage": "getVoltage",
        "speed": "getVelocity", "CIM": "getCIM", "miniCIM": "getMiniCIM", "bag": "getBag",
        "vex775Pro": "getVex775Pro", "RS775_125": "getAndymarkRs775_125",
        "banebotsRS775": "getBanebotsRs775", "andymark9015": "getAndymark9015",
        "banebotsRS550": "getBanebotsRs550", "NEO": "getNEO", "NEO550": "getNeo550",
        "falcon500": "getFalcon500", "falcon500FOC": "getFalcon500Foc",
        "romiBuiltIn": "getRomiBuiltIn", "krakenX60": "getKrakenX60",
        "krakenX60FOC": "getKrakenX60Foc", "krakenX44": "getKrakenX44",
        "krakenX44FOC": "getKrakenX44Foc", "minion": "getMinion",
        "neoVortex": "getNeoVortex",
    },
}


class Renamed:
    """A 2026 name in a class's dictionary: reading it raises AttributeError."""

    __slots__ = ("message",)

    def __init__(self, cls: str, old: str, new: str) -> None:
        self.message = (f"{cls} has no {old!r}: WPILib 2027 (and drivekin) use {new} "
                        f"(robotpy-wpimath 2026's name; see docs/porting.md, Renames)")

    def __get__(self, obj: object, owner: type | None = None) -> Any:
        raise AttributeError(self.message)


def install(namespace: dict[str, Any]) -> None:
    """Put every 2026 name into its class's dictionary (classes by name from
    ``namespace``, the package's); a name the class already has is an error."""
    from drivekin._core.wheels import set_type_attr
    for cls_name, names in RENAMES.items():
        cls = namespace[cls_name]
        for old, new in names.items():
            if old in vars(cls):
                raise RuntimeError(f"{cls_name}.{old} exists; it cannot be a 2026 name")
            set_type_attr(cls, old, Renamed(cls_name, old, new))
