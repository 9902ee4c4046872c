"""Every constructor parameter that a stub lets callers pass by keyword is accepted by
keyword at runtime.

mypy.stubtest cannot check this: the compiled methods (``binding=False``) expose no
introspectable signature, which is how ``Rotation2d(value=1.0)`` came to be rejected
although the stub declared ``value``. This test reads each ``__init__`` overload from
the stubs and calls the runtime class with the overload's keyword-capable parameters
passed by keyword (positional-only ones by position).
"""
from __future__ import annotations

import ast
from pathlib import Path

import numpy as np
import pytest

import drivekin
from drivekin import (
    DeadWheelKinematics,
    MecanumDriveKinematics,
    MecanumDriveWheelPositions,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    ChassisVelocities,
    DCMotor,
    DriveFeedforwards,
    ModuleConfig,
    RobotConfig,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Translation2d,
)

PKG_DIR = Path(drivekin.__file__).resolve().parent


def _kin4():
    return SwerveDriveKinematics(Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
                                 Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))


def _dead_wheel_poses():
    return [Pose2d(0.0, 0.2, Rotation2d()), Pose2d(0.0, -0.2, Rotation2d()),
            Pose2d(-0.1, 0.0, Rotation2d(0.0, 1.0))]


# One valid value per annotation (as spelled in the stubs).
SAMPLES = {
    "float": lambda: 0.75,
    "int": lambda: 2,
    "bool": lambda: True,
    "Translation2d": lambda: Translation2d(0.3, -0.2),
    "Rotation2d": lambda: Rotation2d(0.4),
    "Rotation2d | None": lambda: Rotation2d(0.4),
    "Rotation2d | float": lambda: Rotation2d(0.4),
    "Rotation2d | float | None": lambda: 0.4,
    "Pose2d": lambda: Pose2d(1.0, 2.0, Rotation2d(0.1)),
    "Pose2d | None": lambda: Pose2d(1.0, 2.0, Rotation2d(0.1)),
    "npt.NDArray[np.float64]": None,        # filled per parameter name below
    "SwerveDriveKinematics": _kin4,
    "MecanumDriveKinematics": lambda: MecanumDriveKinematics(
        Translation2d(0.3, 0.25), Translation2d(0.3, -0.25),
        Translation2d(-0.3, 0.25), Translation2d(-0.3, -0.25)),
    "MecanumDriveWheelPositions": lambda: MecanumDriveWheelPositions(0.1, 0.2, 0.3, 0.4),
    "Sequence[Translation2d]": lambda: [Translation2d(0.3, 0.3), Translation2d(-0.3, -0.3)],
    "Sequence[Pose2d]": lambda: _dead_wheel_poses(),
    "DeadWheelKinematics": lambda: DeadWheelKinematics(_dead_wheel_poses()),
    "Sequence[float] | npt.NDArray[np.float64]": lambda: [0.1, 0.2, 0.3],
    "_ModulePositions": lambda: [SwerveModulePosition(0.1, Rotation2d(0.2)) for _ in range(4)],
    "_WheelReadings": lambda: [0.1, 0.2, 0.3],
    "_StdDevs": lambda: (0.1, 0.2, 0.3),
    "Sequence[SwerveModulePosition] | npt.NDArray[np.float64]":
        lambda: [SwerveModulePosition(0.1, Rotation2d(0.2)) for _ in range(4)],
    "DCMotor": lambda: DCMotor.getNEO(1),
    "ModuleConfig": lambda: ModuleConfig(0.05, 4.0, 1.0, DCMotor.getNEO(1), 40.0),
    "RobotConfig": lambda: RobotConfig(50.0, 5.0, SAMPLES["ModuleConfig"](),
                                       SAMPLES["Sequence[Translation2d]"]()),
    "Literal['pathplanner'] | None": lambda: "pathplanner",
    "Sequence[float]": lambda: [0.1, 0.2],
    "Sequence[SwerveModuleVelocity]": lambda: [SwerveModuleVelocity(0.1, Rotation2d(0.2))
                                               for _ in range(2)],
    "ChassisVelocities": lambda: ChassisVelocities(0.1, 0.2, 0.3),
    "DriveFeedforwards": lambda: DriveFeedforwards.zeros(2),
    "Quaternion": lambda: drivekin.Quaternion(0.5, 0.5, -0.5, 0.5),
    "_Vector3": lambda: [0.1, -0.2, 0.3],
    "Rotation3d": lambda: drivekin.Rotation3d(0.1, -0.2, 0.3),
    "Translation3d": lambda: drivekin.Translation3d(1.0, -2.0, 0.5),
    "Pose3d": lambda: drivekin.Pose3d(1.0, -2.0, 0.5, drivekin.Rotation3d(0.1, -0.2, 0.3)),
    "Transform2d": lambda: drivekin.Transform2d(1.0, -2.0, Rotation2d(0.3)),
}
# The axes of a CoordinateSystem must differ (NWU).
AXES = {"positive_x": (1.0, 0.0, 0.0), "positive_y": (0.0, 1.0, 0.0),
        "positive_z": (0.0, 0.0, 1.0)}
ARRAYS = {"vector": np.array([1.0, 2.0]), "matrix": None}
# Floats that must differ (a DCMotor's free current is below its stall current).
FLOATS = {("DCMotor", "stall_current"): 105.0, ("DCMotor", "free_current"): 1.8}


def _value(annotation: str, name: str, cls_name: str):
    if annotation == "npt.NDArray[np.float64]":
        if name == "matrix" and cls_name in ("Pose3d", "Transform3d"):
            return drivekin.Pose3d(1.0, 2.0, 0.5, drivekin.Rotation3d(0.1, -0.2, 0.3)).toMatrix()
        if name == "rotation_matrix":
            return drivekin.Rotation3d(0.1, -0.2, 0.3).toMatrix()
        if name == "matrix":
            return (Rotation2d(0.3).toMatrix() if cls_name == "Rotation2d"
                    else Pose2d(1.0, 2.0, Rotation2d(0.3)).toMatrix())
        return ARRAYS[name]
    if annotation == "CoordinateAxis":
        return drivekin.CoordinateAxis(*AXES[name])
    if (cls_name, name) in FLOATS:
        return FLOATS[cls_name, name]
    return SAMPLES[annotation]()


def _init_overloads(trees: dict[str, ast.Module], module: str, name: str) -> list:
    """The ``__init__`` definitions of stub class ``name``: its own, or those inherited
    from its stub bases (in the same stub or imported from another drivekin stub, as
    ``_Wheel2.__init__`` is by the differential wheel values)."""
    tree = trees[module]
    classes = {n.name: n for n in tree.body if isinstance(n, ast.ClassDef)}
    imported = {alias.asname or alias.name: (n.module.removeprefix("drivekin."), alias.name)
                for n in tree.body if isinstance(n, ast.ImportFrom) and n.level == 0
                and (n.module or "").startswith("drivekin.") for alias in n.names}
    node = classes[name]
    own = [i for i in node.body if isinstance(i, ast.FunctionDef) and i.name == "__init__"]
    if own:
        return own
    for base in node.bases:
        if isinstance(base, ast.Name) and base.id in classes:
            inherited = _init_overloads(trees, module, base.id)
        elif isinstance(base, ast.Name) and imported.get(base.id, ("",))[0] in trees:
            inherited = _init_overloads(trees, *imported[base.id])
        else:
            continue
        if inherited:
            return inherited
    return []


def _module_name(stub: Path) -> str:
    """``geometry`` for ``drivekin/geometry.pyi``, ``_core.wheels`` for
    ``drivekin/_core/wheels.pyi`` (the names ``from drivekin.<name> import`` uses)."""
    return ".".join(stub.relative_to(PKG_DIR).with_suffix("").parts)


def _overloads():
    trees = {_module_name(stub): ast.parse(stub.read_text())
             for stub in sorted(PKG_DIR.rglob("*.pyi"))}
    cases = []
    for module, tree in trees.items():
        if any(part.startswith("_") for part in module.split(".")):
            continue        # private modules (drivekin._core): classes not in drivekin
        for node in tree.body:
            if not isinstance(node, ast.ClassDef) or node.name.startswith("_"):
                continue
            for item in _init_overloads(trees, module, node.name):
                # A *args constructor has no keyword parameters to check.
                if item.args.vararg is None:
                    cases.append(pytest.param(node.name, item.args,
                                              id=f"{node.name}-{item.lineno}"))
    return cases


OVERLOADS = _overloads()


def test_overloads_found():
    assert len(OVERLOADS) >= 30, len(OVERLOADS)


@pytest.mark.parametrize("cls_name, args", OVERLOADS)
def test_stub_keywords_are_accepted(cls_name, args):
    cls = getattr(drivekin, cls_name)
    positional = [_value(ast.unparse(a.annotation), a.arg, cls_name) for a in args.posonlyargs
                  if a.arg != "self"]
    keywords = {a.arg: _value(ast.unparse(a.annotation), a.arg, cls_name)
                for a in args.args + args.kwonlyargs if a.arg != "self"}
    obj = cls(*positional, **keywords)
    # Passing by keyword must mean the same as passing by position.
    if not args.kwonlyargs and keywords:
        same = cls(*positional, *keywords.values())
        assert _state(obj) == _state(same)


def _state(obj):
    # Odometry objects and estimators have no value repr; their pose is what the
    # arguments set (an estimator's gains show in a vision measurement's effect).
    if hasattr(obj, "getEstimatedPosition"):
        obj.updateWithTime(0.0, *_UPDATE_ARGS[type(obj).__name__]())
        obj.addVisionMeasurement(Pose2d(3.0, -1.0, Rotation2d(1.0)), 0.0)
        return repr(obj.getEstimatedPosition())
    return repr(obj.getPose()) if hasattr(obj, "getPose") else repr(obj)


# Arguments of an update that leaves the estimators above where they were built.
_UPDATE_ARGS = {
    "SwerveDrivePoseEstimator": lambda: (
        Rotation2d(0.4), [SwerveModulePosition(0.1, Rotation2d(0.2)) for _ in range(4)]),
    "MecanumDrivePoseEstimator": lambda: (
        Rotation2d(0.4), MecanumDriveWheelPositions(0.1, 0.2, 0.3, 0.4)),
    "DifferentialDrivePoseEstimator": lambda: (Rotation2d(0.4), 0.75, 0.75),
    "TwoDeadWheelPoseEstimator": lambda: (0.75, 0.75, Rotation2d(0.4)),
    "DeadWheelPoseEstimator": lambda: ([0.1, 0.2, 0.3], Rotation2d(0.4)),
}
