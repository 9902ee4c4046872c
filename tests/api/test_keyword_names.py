"""Keyword (parameter) names are robotpy 2027's: snake_case, one spelling.

``tests/data/robotpy2027-names.json`` lists, for every robotpy-wpimath 2027 class, its
methods (robotpy name -> Java name), each method's overload forms (``params``: the keyword
names of each form) and its constructor forms (``init``). For every class drivekin has
(the 3-D classes it lacks are skipped) and every method robotpy has (matched through the
Java name, which is drivekin's method name):

* the names of at least one robotpy form are parameters of drivekin's embedded signature
  (the first line of ``__doc__``, Cython's ``embedsignature``), every other parameter
  having a default;
* every form is called with its names passed by keyword: a form whose names drivekin's
  argument parsing refuses is listed in ``NOT_KEYWORD_CALLABLE`` with the reason, and
  the list is exact;
* where drivekin's positional parameters are robotpy's names, they come in robotpy's order.

Every public method and constructor of the wpimath-like modules has snake_case parameter
names only (semiwrap's transform of the name is the name), and a few real calls by keyword
give what the positional call gives, while the camelCase keyword of 0.2.0 is refused.
"""
from __future__ import annotations

import inspect
import json
import re
from pathlib import Path

import pytest

import drivekin
from drivekin import (DCMotor, Pose2d, Rotation2d, SwerveDriveKinematics, SwerveDriveOdometry,
                      SwerveDrivePoseEstimator, SwerveModulePosition, Transform2d,
                      Translation2d)
from drivekin._core import catalog
from tests.api.test_robotpy_hints import _params

DATA = json.loads((Path(__file__).resolve().parents[1] / "data" /
                   "robotpy2027-names.json").read_text())

# The modules whose classes follow wpimath (drivekin.setpoint and drivekin.robotconfig keep
# PathPlannerLib's spellings; drivekin.batch has its own).
MODULES = ("geometry", "geometry3d", "chassis", "swervemodule", "swerve", "mecanum",
           "differential", "diffswerve", "deadwheel", "odometry", "estimator", "odometry3d",
           "estimator3d", "motor", "interpolation")

# semiwrap's name_transform word split (the JSON's ``rule``).
_WORDS = re.compile(r"[A-Z]+[0-9]*(?=[A-Z][a-z0-9]|_|$)|[A-Z]?[a-z0-9]+|[A-Z]+[0-9]*")


def snake(name: str) -> str:
    return "_".join(w.lower() for w in _WORDS.findall(name))


# (drivekin class, member, robotpy form) -> why the form's names cannot be passed by
# keyword. A member drivekin spells with one signature gets one name per position.
_TYPES_DECIDE = ("one signature whose argument types pick the form; a keyword-only "
                 "parameter per extra name would cost every positional construction "
                 "(measured: about +60 instructions on Translation2d(1.0, 2.0), +25 on "
                 "Rotation2d(0.5): 3-7 % of the call)")
_METH_O = ("a METH_O method (the one-argument fast call): its argument is positional "
           "only")
NOT_KEYWORD_CALLABLE = {
    ("Translation2d", "__init__", ("distance", "angle")): _TYPES_DECIDE,
    ("Translation2d", "__init__", ("vector",)): _TYPES_DECIDE,
    ("Rotation2d", "__init__", ("x", "y")): _TYPES_DECIDE + "; the first parameter is value",
    **{("Rotation3d", "__init__", form): _TYPES_DECIDE + "; the parameters are roll, pitch, yaw"
       for form in (("q",), ("axis", "angle"), ("rvec",), ("rotation_matrix",),
                    ("initial", "final"), ("rotation",))},
    **{("Translation3d", "__init__", form): _TYPES_DECIDE
       for form in (("distance", "angle"), ("vector",), ("translation",))},
    ("TimeInterpolatableBuffer", "__init__", ("history_size",)):
        "the constructor is Java's createBuffer(func, history_size): func has no default "
        "(createBuffer(history_size) is the one-argument form)",
    ("SwerveDriveKinematics", "toTwist2d", ("start", "end")):
        "toTwist2d(module_deltas, *more): the (start, end) form is positional",
    ("MecanumDriveKinematics", "toTwist2d", ("wheel_deltas",)):
        "toTwist2d(start, end=None): the deltas form is positional",
    ("DifferentialDriveKinematics", "toTwist2d", ("left_distance", "right_distance")):
        "toTwist2d(start, end): the distances form is positional",
    ("SwerveDriveKinematics", "desaturateWheelVelocities",
     ("module_velocities", "desired_chassis_velocity", "attainable_max_module_velocity",
      "attainable_max_robot_translation_velocity", "attainable_max_robot_rotation_velocity")):
        "the second parameter carries the two-argument form's name, "
        "attainable_max_velocity: the desired velocity goes by position",
    ("MecanumDriveWheelVelocities", "desaturate", ("attainable_max_velocity",)): _METH_O,
    ("DifferentialDriveWheelVelocities", "desaturate", ("attainable_max_velocity",)): _METH_O,
    **{(cls, "sampleAt", ("timestamp",)): _METH_O
       for cls in ("SwerveDrivePoseEstimator", "MecanumDrivePoseEstimator",
                   "DifferentialDrivePoseEstimator", "SwerveDrivePoseEstimator3d",
                   "MecanumDrivePoseEstimator3d", "DifferentialDrivePoseEstimator3d")},
}

# Positional order that is not robotpy's although the names are: (class, member) -> why.
POSITIONAL_ORDER_DIFFERS = {
    ("TimeInterpolatableBuffer", "__init__"):
        "Java's createBuffer(func, history_size); robotpy constructs "
        "TimeInterpolatable*Buffer(history_size, func)",
}


# ---- drivekin's signatures ---------------------------------------------------------------

def _signature(obj, name: str) -> list[tuple[str, bool, bool]] | None:
    """[(name, has a default, keyword-only)] of ``obj``'s signature: Cython's embedded
    line, or Python's own signature; ``*args``/``**kwargs`` left out."""
    if inspect.isfunction(obj) or (inspect.isclass(obj) and obj.__init__ is not object.__init__
                                   and inspect.isfunction(obj.__init__)):
        sig = inspect.signature(obj)
        return [(p.name, p.default is not p.empty, p.kind is p.KEYWORD_ONLY)
                for p in sig.parameters.values()
                if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD) and p.name != "self"]
    params = _params(obj.__doc__, name)
    return None if params is None else [(n, d, k) for n, _, d, k in params]


def _star_names(obj, name: str) -> list[str]:
    """The names of ``*args``/``**kwargs`` in the signature (they show in help())."""
    if inspect.isfunction(obj):
        return [p.name for p in inspect.signature(obj).parameters.values()
                if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]
    first = (obj.__doc__ or "").partition("\n")[0]
    m = re.fullmatch(rf"(?:\w+\.)?{re.escape(name)}\((.*)\)(?:\s*->.*)?", first)
    return re.findall(r"(?:^|,)\s*\*{1,2}(\w+)", m.group(1)) if m else []


def _member(cls: type, java: str):
    # getattr_static: the 2026 names only raise (drivekin._core.renames).
    member = inspect.getattr_static(cls, java)
    return member.__func__ if isinstance(member, (staticmethod, classmethod)) else member


# ---- the robotpy methods drivekin has -----------------------------------------------------

def _robotpy_members() -> dict[tuple[str, str], list[tuple[str, ...]]]:
    """(drivekin class, drivekin member) -> robotpy's forms (one entry for the fixed-N
    templates of a class: SwerveDrive2/3/4/6Kinematics are drivekin's one class)."""
    out: dict[tuple[str, str], list[tuple[str, ...]]] = {}
    for cls_name, c in DATA["classes"].items():
        cls = getattr(drivekin, c["drivekinName"], None)
        if cls is None:
            continue
        members = [("__init__", c["init"])]
        members += [(c["methods"][m], forms) for m, forms in c["params"].items()
                    if c["methods"].get(m)]
        for member, forms in members:
            seen = out.setdefault((cls.__name__, member), [])
            seen += [tuple(f) for f in forms if tuple(f) not in seen]
    return {k: v for k, v in out.items() if v}


MEMBERS = _robotpy_members()
MEMBER_IDS = [f"{c}.{m}" for c, m in MEMBERS]


def test_the_table_covers_drivekin():
    # drivekin has every robotpy class, and every Java method robotpy binds with parameters
    # is a drivekin method.
    lacking = {k for k, c in DATA["classes"].items() if not hasattr(drivekin, c["drivekinName"])}
    assert not lacking, sorted(lacking)
    for c in DATA["classes"].values():
        cls = getattr(drivekin, c["drivekinName"], None)
        for method in c["params"]:
            java = c["methods"].get(method)
            assert cls is None or java is None or hasattr(cls, java), (c["drivekinName"], java)
    assert len(MEMBERS) >= 100, len(MEMBERS)


def _fits(sig, form) -> bool:
    names = {n for n, _, _ in sig}
    return set(form) <= names and all(d for n, d, _ in sig if n not in form)


@pytest.mark.parametrize("cls_name, member", list(MEMBERS), ids=MEMBER_IDS)
def test_robotpy_names_are_the_signature(cls_name, member):
    cls = getattr(drivekin, cls_name)
    obj = cls if member == "__init__" else _member(cls, member)
    sig = _signature(obj, cls_name if member == "__init__" else member)
    assert sig is not None, f"{cls_name}.{member}: no embedded signature"
    forms = MEMBERS[cls_name, member]
    assert any(_fits(sig, f) for f in forms), \
        f"{cls_name}.{member}{tuple(n for n, _, _ in sig)} fits none of robotpy's {forms}"
    if (cls_name, member) in POSITIONAL_ORDER_DIFFERS:
        return
    positional = [n for n, _, kwonly in sig if not kwonly]
    for form in forms:
        if _fits(sig, form):
            order = [n for n in positional if n in form]
            assert order == [n for n in form if n in order], (cls_name, member, form)


# ---- calling every form by keyword --------------------------------------------------------

# What Python and Cython say when the arguments do not bind to the parameters (as opposed to
# drivekin's own TypeError about a value, which the placeholder values below all get).
_UNBOUND = re.compile(
    r"unexpected keyword argument|takes no keyword arguments|missing \d+ required|"
    r"takes (exactly|at least|at most|from) \d+|needs keyword-only argument|"
    r"got multiple values|required (positional|keyword)")


def _bound_by_keyword(cls: type, member: str, form: tuple[str, ...]) -> bool:
    """Call ``member`` (the constructor, a static method or a method of the catalog's
    example) with a placeholder for each of ``form``'s names, by keyword: True unless the
    arguments did not bind. Placeholders fail every type check, so nothing changes."""
    kwargs = {name: object() for name in form}
    if member == "__init__":
        target = cls
    elif isinstance(inspect.getattr_static(cls, member), staticmethod):
        target = getattr(cls, member)
    else:
        target = getattr(catalog.BY_CLASS[cls].example(), member)
    try:
        target(**kwargs)
    except TypeError as e:
        return not _UNBOUND.search(str(e))
    except (ValueError, RuntimeError):
        pass
    return True


def test_every_form_is_callable_by_keyword_but_the_listed_ones():
    refused = {}
    for (cls_name, member), forms in MEMBERS.items():
        for form in forms:
            if form and not _bound_by_keyword(getattr(drivekin, cls_name), member, form):
                refused[cls_name, member, form] = True
    assert set(refused) == set(NOT_KEYWORD_CALLABLE)
    # No member is left without a keyword form, but the METH_O ones.
    for (cls_name, member), forms in MEMBERS.items():
        open_forms = [f for f in forms if (cls_name, member, f) not in NOT_KEYWORD_CALLABLE]
        assert open_forms or all(NOT_KEYWORD_CALLABLE[cls_name, member, f] == _METH_O
                                 for f in forms), (cls_name, member)


# ---- snake_case everywhere ----------------------------------------------------------------

def _public_classes() -> list[type]:
    out = []
    for module in MODULES:
        mod = getattr(__import__(f"drivekin.{module}"), module)
        out += [obj for name, obj in vars(mod).items()
                if inspect.isclass(obj) and not name.startswith("_")
                and obj.__module__ == mod.__name__ and not issubclass(obj, Warning)]
    return out


def test_every_parameter_name_is_snake_case():
    offenders, checked = [], 0
    for cls in _public_classes():
        members = [("__init__", cls)]
        for name in sorted(dir(cls)):
            member = inspect.getattr_static(cls, name, None)
            if not name.startswith("_") and callable(member) and not inspect.isclass(member):
                members.append((name, _member(cls, name)))
        for name, obj in members:
            sig = _signature(obj, cls.__name__ if name == "__init__" else name)
            if sig is None:
                continue
            checked += 1
            names = [n for n, _, _ in sig] + _star_names(obj, cls.__name__ if name ==
                                                            "__init__" else name)
            # A trailing underscore keeps a Python keyword usable (robotpy's from_).
            offenders += [f"{cls.__name__}.{name}: {n}" for n in names
                          if snake(n) != n.removesuffix("_")]
    assert checked >= 300, checked
    assert not offenders, "camelCase parameters:\n" + "\n".join(offenders)


# ---- real calls by keyword ----------------------------------------------------------------

def _swerve():
    return SwerveDriveKinematics(Translation2d(0.3, 0.3), Translation2d(0.3, -0.3),
                                 Translation2d(-0.3, 0.3), Translation2d(-0.3, -0.3))


def _positions(d: float, a: float):
    return [SwerveModulePosition(d, Rotation2d(a + 0.1 * i)) for i in range(4)]


def test_odometry_update_by_keyword():
    by_position = SwerveDriveOdometry(_swerve(), Rotation2d(0.2), _positions(0.0, 0.0))
    by_keyword = SwerveDriveOdometry(kinematics=_swerve(), gyro_angle=Rotation2d(0.2),
                                     module_positions=_positions(0.0, 0.0),
                                     initial_pose=Pose2d())
    want = by_position.update(Rotation2d(0.5), _positions(0.4, 0.3))
    got = by_keyword.update(gyro_angle=Rotation2d(0.5), wheel_positions=_positions(0.4, 0.3))
    assert (got.x, got.y, got.getRotation().getRadians()) == \
        (want.x, want.y, want.getRotation().getRadians())
    assert want.x != 0.0 and want.y != 0.0
    with pytest.raises(TypeError, match="gyroAngle"):
        by_keyword.update(gyroAngle=Rotation2d(0.5), wheel_positions=_positions(0.4, 0.3))
    with pytest.raises(TypeError, match="initialPose"):
        SwerveDriveOdometry(_swerve(), Rotation2d(), _positions(0.0, 0.0), initialPose=Pose2d())


def test_add_vision_measurement_by_keyword():
    def estimator():
        est = SwerveDrivePoseEstimator(_swerve(), Rotation2d(), _positions(0.0, 0.0), Pose2d())
        for i in range(10):
            est.updateWithTime(0.02 * i, Rotation2d(0.01 * i), _positions(0.02 * i, 0.0))
        return est

    vision, stds = Pose2d(0.3, -0.2, Rotation2d(0.2)), (0.2, 0.3, 0.4)
    a, b = estimator(), estimator()
    a.addVisionMeasurement(vision, 0.1, stds)
    b.addVisionMeasurement(vision_robot_pose=vision, timestamp=0.1,
                           vision_measurement_std_devs=stds)
    pa, pb = a.getEstimatedPosition(), b.getEstimatedPosition()
    assert (pa.x, pa.y, pa.getRotation().getRadians()) == \
        (pb.x, pb.y, pb.getRotation().getRadians())
    assert pa != estimator().getEstimatedPosition()     # the measurement moved the estimate
    with pytest.raises(TypeError, match="visionRobotPose"):
        b.addVisionMeasurement(visionRobotPose=vision, timestamp=0.1)
    with pytest.raises(TypeError, match="visionMeasurementStdDevs"):
        b.addVisionMeasurement(vision, 0.1, visionMeasurementStdDevs=stds)


def test_constructors_by_keyword():
    angle = Rotation2d(0.7)
    assert Translation2d(x=1.5, y=-2.0) == Translation2d(1.5, -2.0)
    # robotpy's Translation2d(distance=, angle=) form goes by position (NOT_KEYWORD_CALLABLE).
    with pytest.raises(TypeError, match="distance"):
        Translation2d(distance=2.0, angle=angle)
    start, end = Pose2d(1.0, 2.0, angle), Pose2d(-0.5, 0.25, Rotation2d(-1.2))
    assert Transform2d(initial=start, final=end) == Transform2d(start, end)
    assert Transform2d(start, end) != Transform2d()
    with pytest.raises(TypeError, match="last"):
        Transform2d(initial=start, last=end)
    keywords = dict(nominal_voltage=12.0, stall_torque=2.6, stall_current=105.0,
                    free_current=1.8, free_speed=594.0, num_motors=3)
    assert DCMotor(**keywords) == DCMotor(12.0, 2.6, 105.0, 1.8, 594.0, 3)
    assert DCMotor(**keywords) != DCMotor(12.0, 2.6, 105.0, 1.8, 594.0, 2)
    with pytest.raises(TypeError, match="nominalVoltage"):
        DCMotor(nominalVoltage=12.0, stall_torque=2.6, stall_current=105.0,
                free_current=1.8, free_speed=594.0)


def test_dcmotor_methods_by_keyword():
    neo = DCMotor.getNEO(num_motors=2)
    assert neo == DCMotor.getNEO(2) and neo != DCMotor.getNEO(1)
    assert neo.getCurrent(velocity=300.0, input_voltage=10.0) == neo.getCurrent(300.0, 10.0)
    assert neo.getCurrent(torque=1.5) == neo.getCurrent(1.5)
    assert neo.getVelocity(torque=1.5, input_voltage=10.0) == neo.getVelocity(1.5, 10.0)
    assert neo.withReduction(gearbox_reduction=4.0) == neo.withReduction(4.0)
    with pytest.raises(TypeError, match="numMotors"):
        DCMotor.getNEO(numMotors=2)
    with pytest.raises(TypeError, match="voltageInput"):
        neo.getCurrent(velocity=300.0, voltageInput=10.0)


def test_method_o_members_refuse_keywords():
    # The METH_O entries of NOT_KEYWORD_CALLABLE: positional calls work, keywords do not.
    wheels = drivekin.MecanumDriveWheelVelocities(1.0, 2.0, -3.0, 4.0)
    assert tuple(wheels.desaturate(2.0)) == (0.5, 1.0, -1.5, 2.0)
    with pytest.raises(TypeError, match="no keyword arguments"):
        wheels.desaturate(attainable_max_velocity=2.0)
    assert tuple(wheels) == (1.0, 2.0, -3.0, 4.0)
