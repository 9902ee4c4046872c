"""A robotpy-wpimath object passed where a drivekin one belongs is refused with a TypeError
that names the parameter and the expected class and says how to convert the object
(``drivekin.interop.fromWpimath``, or ``fromWpimath3d`` for a 3-D one); None is refused
with the same message shape.

The parameters under test are found at runtime, not listed by hand: every public method
and constructor of the catalog's classes whose embedded signature (Cython's
``embedsignature``) annotates a parameter with a drivekin class (``pose: Pose2d``). Those
are the parameters drivekin checks itself (``_core/args.pxd``, ``check_type``) instead of
Cython's fixed "Argument 'pose' has incorrect type" message. Each is called on the
catalog's example with valid values for the parameters before it. The hint itself
(``_core/errors.type_name``) is tested on every catalogued robotpy-wpimath peer.
"""
from __future__ import annotations

import inspect
import re

import pytest

import drivekin
from drivekin._core import catalog
from drivekin._core.errors import type_name

HINT = "(a robotpy-wpimath object: convert it with drivekin.interop.fromWpimath(value))"
HINT_3D = ("(a robotpy-wpimath 3-D object: convert its 2-D part with "
           "drivekin.interop.fromWpimath3d(value))")
# drivekin's 2-D classes and the robotpy-wpimath 3-D classes fromWpimath3d flattens to them.
THREE_D = {"Pose2d": "Pose3d", "Transform2d": "Transform3d",
           "Translation2d": "Translation3d", "Rotation2d": "Rotation3d"}


# ---- the typed parameters, from the embedded signatures -----------------------------------

def _split(params: str) -> list[str]:
    out, depth, cur = [], 0, ""
    for ch in params:
        depth += (ch in "([{") - (ch in ")]}")
        if ch == "," and depth == 0:
            out.append(cur.strip())
            cur = ""
        else:
            cur += ch
    return out + ([cur.strip()] if cur.strip() else [])


def _params(doc: str | None, name: str) -> list[tuple[str, str | None, bool, bool]] | None:
    """The parameters of the signature line Cython embedded at the top of ``doc`` for the
    function ``name``: (name, annotation or C type or None, has a default, keyword-only);
    None without such a line."""
    first = (doc or "").partition("\n")[0]
    m = re.fullmatch(rf"(?:\w+\.)?{re.escape(name)}\((.*)\)(?:\s*->.*)?", first)
    if m is None:
        return None
    out, kwonly = [], False
    for p in _split(m.group(1)):
        if p in ("self", "/"):
            continue
        if p.startswith("*"):
            kwonly = True
            continue
        p, eq, _ = p.partition("=")
        p = p.strip()
        if ":" in p:
            pname, _, ann = p.partition(":")
            out.append((pname.strip(), ann.strip(), bool(eq), kwonly))
        else:
            words = p.split()
            out.append((words[-1], words[0] if len(words) == 2 else None, bool(eq), kwonly))
    return out


def _drivekin_class(annotation: str | None, owner: type) -> type | None:
    """The drivekin class an annotation names (a private base, such as _ChassisVector,
    means the receiver's own class: such parameters must be of it)."""
    if annotation is None or not re.fullmatch(r"\w+", annotation):
        return None
    if annotation.startswith("_"):
        return owner
    cls = getattr(drivekin, annotation, None)
    return cls if isinstance(cls, type) else None


def _targets() -> list:
    cases = []
    for entry in catalog.ENTRIES:
        cls = entry.cls
        if entry.example is None:
            continue
        callables = [("__init__", cls, _params(cls.__doc__, cls.__name__))]
        for name in sorted(dir(cls)):
            # getattr_static: the 2026 names only raise (drivekin._core.renames).
            member = inspect.getattr_static(cls, name)
            if not name.startswith("_") and callable(member):
                callables.append((name, cls, _params(member.__doc__, name)))
        for name, _, params in callables:
            for i, (pname, ann, _, _) in enumerate(params or ()):
                expected = _drivekin_class(ann, cls)
                if expected is not None:
                    cases.append(pytest.param(cls, name, params, i, expected,
                                              id=f"{cls.__name__}.{name}-{pname}"))
    return cases


TARGETS = _targets()


def test_targets_found():
    # Every geometry, chassis, swerve, mecanum, differential, odometry and estimator
    # family contributes; a regression in the signature parsing shows up here.
    assert len(TARGETS) >= 150, len(TARGETS)
    found = {(p.values[0].__name__, p.values[1]) for p in TARGETS}
    for call in [("Pose2d", "transformBy"), ("Rotation2d", "rotateBy"),
                 ("ChassisVelocities", "toRobotRelative"), ("ChassisAccelerations", "plus"),
                 ("SwerveDriveKinematics", "toSwerveModuleVelocities"),
                 ("SwerveModuleVelocity", "optimize"), ("MecanumDriveKinematics", "__init__"),
                 ("SwerveDriveOdometry", "__init__"), ("DifferentialDriveOdometry", "update"),
                 ("SwerveDrivePoseEstimator", "addVisionMeasurement"),
                 ("DifferentialSwerveModuleKinematics", "resetModulePosition")]:
        assert call in found, call


def _sample(annotation: str | None, owner: type):
    cls = _drivekin_class(annotation, owner)
    if cls is not None:
        return catalog.BY_CLASS[cls].example()
    if annotation in ("double", "float"):
        return 0.5
    if annotation in ("int", "Py_ssize_t"):
        return 1
    if annotation == "bint":
        return True
    # An untyped parameter: its checks run after every typed parameter's.
    return object()


def _call(cls: type, name: str, params, index: int, value):
    """Call ``name`` on the catalog's example of ``cls`` (or the constructor) with
    ``value`` for parameter ``index``, valid values before it and every later required
    parameter filled in; every argument by keyword (the names are drivekin's API)."""
    kwargs = {}
    for i, (pname, ann, has_default, _) in enumerate(params):
        if i == index:
            kwargs[pname] = value
        elif not has_default:
            kwargs[pname] = _sample(ann, cls)
    if name == "__init__":
        return cls(**kwargs)
    return getattr(catalog.BY_CLASS[cls].example(), name)(**kwargs)


@pytest.mark.parametrize("cls, name, params, index, expected", TARGETS)
def test_none_is_refused_naming_the_parameter(cls, name, params, index, expected):
    pname = params[index][0]
    with pytest.raises(TypeError) as info:
        _call(cls, name, params, index, None)
    assert str(info.value) == f"{pname} must be a {expected.__name__}, got NoneType"


@pytest.mark.parametrize("cls, name, params, index, expected", TARGETS)
def test_robotpy_object_gets_the_conversion(cls, name, params, index, expected, wpimath_kin):
    from drivekin.interop import fromWpimath, toWpimath

    pname = params[index][0]
    entry = catalog.BY_CLASS[expected]
    if entry.peer is not None:
        value, hint = toWpimath(entry.example()), HINT
        assert type(fromWpimath(value)) is expected      # the hint's call gives an expected
    else:
        # No robotpy-wpimath counterpart (ChassisAccelerations, the wheel accelerations,
        # ...): a robotpy object of another meaning gets no hint.
        value, hint = wpimath_kin.ChassisSpeeds(1.0, 2.0, 3.0), None
    with pytest.raises(TypeError) as info:
        _call(cls, name, params, index, value)
    message = str(info.value)
    got = f"{type(value).__module__}.{type(value).__qualname__}"
    assert message.startswith(f"{pname} must be a {expected.__name__}, got {got}"), message
    if hint is None:
        assert "fromWpimath" not in message
    else:
        assert message.endswith(hint), message


@pytest.mark.parametrize("cls, name, params, index, expected",
                         [p for p in TARGETS if p.values[4].__name__ in THREE_D])
def test_robotpy_3d_object_gets_the_3d_conversion(cls, name, params, index, expected,
                                                  wpimath_geo):
    pname = params[index][0]
    value = getattr(wpimath_geo, THREE_D[expected.__name__])()
    with pytest.raises(TypeError, match=re.escape(f"{pname} must be a {expected.__name__}, got "
                                                  f"wpimath.geometry.")) as info:
        _call(cls, name, params, index, value)
    assert str(info.value).endswith(HINT_3D), info.value


def test_the_setter_of_a_module_angle(wpimath_geo):
    # Property setters carry no embedded signature; the one typed setter, by hand.
    from drivekin.interop import toWpimath

    state = drivekin.SwerveModuleVelocity(1.0, drivekin.Rotation2d(0.5))
    with pytest.raises(TypeError, match=re.escape(f"angle must be a Rotation2d, got "
                                                  f"wpimath.geometry._geometry.Rotation2d {HINT}")):
        state.angle = toWpimath(drivekin.Rotation2d(1.0))
    with pytest.raises(TypeError, match="^angle must be a Rotation2d, got NoneType$"):
        state.angle = None
    assert state.angle == drivekin.Rotation2d(0.5)


def test_the_converted_value_is_accepted(wpimath_geo, wpimath_kin):
    # Following the hint works: the drivekin value fromWpimath returns is taken.
    from drivekin.interop import fromWpimath

    g, k = wpimath_geo, wpimath_kin
    estimator = catalog.BY_CLASS[drivekin.SwerveDrivePoseEstimator].example()
    estimator.updateWithTime(0.0, drivekin.Rotation2d(), [drivekin.SwerveModulePosition()] * 4)
    vision = g.Pose2d(1.5, 2.0, g.Rotation2d(0.25))
    with pytest.raises(TypeError, match=re.escape(HINT)):
        estimator.addVisionMeasurement(vision, 0.0)
    estimator.addVisionMeasurement(fromWpimath(vision), 0.0)
    kin = catalog.BY_CLASS[drivekin.SwerveDriveKinematics].example()
    speeds = k.ChassisSpeeds(1.0, 0.5, 0.25)
    with pytest.raises(TypeError, match="chassis_velocities must be a ChassisVelocities"):
        kin.toSwerveModuleVelocities(speeds)
    assert kin.toSwerveModuleVelocities(fromWpimath(speeds)) == \
        kin.toSwerveModuleVelocities(drivekin.ChassisVelocities(1.0, 0.5, 0.25))


# ---- the hint: drivekin._core.errors.type_name ---------------------------------------------

PEERS = [pytest.param(e, id=e.cls.__name__) for e in catalog.ENTRIES if e.peer is not None]


@pytest.mark.parametrize("entry", PEERS)
def test_every_catalogued_peer_gets_the_hint(entry, wpimath_geo):
    from drivekin.interop import toWpimath

    value = toWpimath(entry.example())
    name = f"{type(value).__module__}.{type(value).__qualname__}"
    assert type_name(value) == f"{name} {HINT}"
    assert type_name(value, entry.cls) == f"{name} {HINT}"
    # Only where the conversion gives what is expected: a Twist2d's peer is no Pose2d.
    other = drivekin.Twist2d if entry.cls is not drivekin.Twist2d else drivekin.Pose2d
    assert type_name(value, other) == name


def test_a_subclass_of_a_robotpy_class_gets_the_hint(wpimath_geo):
    # interop converts subclasses of robotpy classes (their bases are looked up too).
    class MyPose(wpimath_geo.Pose2d):
        pass

    assert type_name(MyPose()) == f"{__name__}.{MyPose.__qualname__} {HINT}"


@pytest.mark.parametrize("name, expected, hint", [
    ("Pose3d", drivekin.Pose2d, True),
    ("Transform3d", drivekin.Transform2d, True),
    ("Translation3d", drivekin.Translation2d, True),
    ("Rotation3d", drivekin.Rotation2d, True),
    ("Pose3d", drivekin.Rotation2d, False),
    ("Rotation3d", drivekin.Pose2d, False),
])
def test_3d_objects_point_to_fromwpimath3d(name, expected, hint, wpimath_geo):
    # Where the 2-D value belongs; fromWpimath converts them to drivekin's 3-D ones.
    value = getattr(wpimath_geo, name)()
    full = f"{type(value).__module__}.{type(value).__qualname__}"
    assert type_name(value) == f"{full} {HINT}"
    assert type_name(value, expected) == (f"{full} {HINT_3D}" if hint else full)


def test_no_false_hint_for_robotpy_types_interop_does_not_convert(wpimath_geo, wpimath_kin):
    # Coordinate frames and 2-D shapes interop does not convert, and robotpy's stateful
    # classes.
    odometry = wpimath_kin.DifferentialDriveOdometry(wpimath_geo.Rotation2d(), 0.0, 0.0)
    for value in (wpimath_geo.CoordinateSystem.NWU(),
                  wpimath_geo.Rectangle2d(wpimath_geo.Pose2d(), 1.0, 2.0), odometry):
        assert type_name(value) == f"{type(value).__module__}.{type(value).__qualname__}"
    # Containers are named as such (interop converts only their items).
    assert type_name([wpimath_geo.Pose2d()]) == "list"


def test_no_hint_for_other_objects_and_no_failure_without_robotpy(monkeypatch):
    # Not robotpy's (a look-alike module name), and robotpy failing to load: the plain
    # name, and the error message itself never fails.
    from drivekin import interop

    fake = type("Pose2d", (), {"__module__": "wpimath.geometry._geometry"})()
    assert type_name(fake) == "wpimath.geometry._geometry.Pose2d"
    assert type_name(type("Pose2d", (), {"__module__": "wpimathx"})()) == "wpimathx.Pose2d"
    assert type_name(drivekin.Pose2d()) == "Pose2d"
    assert type_name(None) == "NoneType"

    def missing():
        raise ModuleNotFoundError("No module named 'wpimath'", name="wpimath")

    monkeypatch.setattr(interop, "_load", missing)
    assert type_name(fake) == "wpimath.geometry._geometry.Pose2d"
    with pytest.raises(TypeError, match=r"^other must be a Pose2d, got "
                                        r"wpimath\.geometry\._geometry\.Pose2d$"):
        drivekin.Pose2d().relativeTo(fake)
