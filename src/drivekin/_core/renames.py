"""robotpy-wpimath 2026 names on drivekin classes (docs/porting.md, "Renames"): one rule
for all of them. Using one raises an AttributeError that names the WPILib 2027
replacement, from an instance or from the class (``ChassisVelocities.
fromFieldRelativeSpeeds``). None is an alias: several 2026 names mean something else in
2027 (2026's ``optimize`` mutates, 2027's returns a new object), so working on would hide
the change. The 2026 names robotpy 2027 spells alike (``Rotation2d.degrees``,
``DCMotor.current``, ...) are not here: they are robotpy 2027 names (_core/pynames), with
2027's meaning. The names live in the type dictionaries as descriptors that raise, so the
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
    "Translation2d": {"X": "getX() or .x", "Y": "getY() or .y"},
    "Pose2d": {"X": "getX() or .x", "Y": "getY() or .y"},
    "Transform2d": {"X": "getX() or .x", "Y": "getY() or .y"},
    "Translation3d": {"X": "getX() or .x", "Y": "getY() or .y", "Z": "getZ() or .z",
                      "squaredNorm": "getSquaredNorm (robotpy 2027: squared_norm)",
                      "squaredDistance": "getSquaredDistance (robotpy 2027: squared_distance)",
                      "normFeet": "getNorm() in m (robotpy 2027: norm_feet)",
                      "distanceFeet": "getDistance(other) in m (robotpy 2027: distance_feet)"},
    "Rotation3d": {"X": "getX() or .x", "Y": "getY() or .y", "Z": "getZ() or .z"},
    "Quaternion": {"W": "getW() or .w", "X": "getX() or .x", "Y": "getY() or .y",
                   "Z": "getZ() or .z"},
    "Pose3d": {"X": "getX() or .x", "Y": "getY() or .y", "Z": "getZ() or .z",
               "fromMatrix": "Pose3d(matrix) (robotpy 2027: from_matrix)"},
    "Transform3d": {"X": "getX() or .x", "Y": "getY() or .y", "Z": "getZ() or .z",
                    "fromMatrix": "Transform3d(matrix) (robotpy 2027: from_matrix)"},
    "DCMotor": {
        "speed": "getVelocity (robotpy 2027: velocity)", "CIM": "getCIM (robotpy 2027: cim)",
        "miniCIM": "getMiniCIM (robotpy 2027: mini_cim)",
        "vex775Pro": "getVex775Pro (robotpy 2027: vex775_pro)",
        "RS775_125": "getAndymarkRs775_125 (robotpy 2027: rs775_125)",
        "banebotsRS775": "getBanebotsRs775 (robotpy 2027: banebots_rs775)",
        "banebotsRS550": "getBanebotsRs550 (robotpy 2027: banebots_rs550)",
        "NEO": "getNEO (robotpy 2027: neo)", "NEO550": "getNeo550 (robotpy 2027: neo550)",
        "falcon500FOC": "getFalcon500Foc (robotpy 2027: falcon500_foc)",
        "romiBuiltIn": "getRomiBuiltIn (robotpy 2027: romi_built_in)",
        "krakenX60": "getKrakenX60 (robotpy 2027: kraken_x60)",
        "krakenX60FOC": "getKrakenX60Foc (robotpy 2027: kraken_x60_foc)",
        "krakenX44": "getKrakenX44 (robotpy 2027: kraken_x44)",
        "krakenX44FOC": "getKrakenX44Foc (robotpy 2027: kraken_x44_foc)",
        "neoVortex": "getNeoVortex (robotpy 2027: neo_vortex)",
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
