"""robotpy 2027's names resolve on drivekin, with robotpy's kinds (method, static method,
property), against robotpy's own wrapper tables (tests/data/robotpy2027-names.json, read
from mostrobotpy e51721a: its SOURCE field says how). A class drivekin does not have yet
(the 3-D ones) is skipped by name; every other class must resolve every name."""
from __future__ import annotations

import inspect
import json
import math
import re
from pathlib import Path

import pytest

import drivekin
from drivekin._core import catalog, pynames
from drivekin._core.renames import RENAMES, Renamed

TABLE = json.loads((Path(__file__).parents[1] / "data" / "robotpy2027-names.json")
                   .read_text(encoding="utf-8"))
CLASSES = TABLE["classes"]
DESCRIPTORS = (property, type(drivekin.Pose2d.x), type(drivekin.Twist2d.dx))


def _needed(name: str, spec: dict) -> str:
    """The drivekin class robotpy's class ``name`` is about (a buffer: its element)."""
    m = re.fullmatch(r"TimeInterpolatable(\w+)Buffer", name)
    return m.group(1) if m and m.group(1) != "Float" else spec["drivekinName"]


def _has(name: str) -> bool:
    return isinstance(getattr(drivekin, name, None), type)


def _kind(raw: object) -> str:
    if isinstance(raw, staticmethod) or inspect.isbuiltin(raw):
        return "static"
    if isinstance(raw, DESCRIPTORS):
        return "property"
    if callable(raw):
        return "method"
    return f"not a member ({type(raw).__name__})"


def _names(spec: dict) -> dict[str, str]:
    """robotpy name -> the kind robotpy gives it."""
    out = {n: ("static" if n in spec["static"] else "method") for n in spec["methods"]}
    out.update({n: "property" for n in spec["properties"]})
    return out


@pytest.mark.parametrize("name", sorted(CLASSES))
def test_every_robotpy_2027_name_resolves_with_robotpy_kind(name):
    spec = CLASSES[name]
    if not _has(_needed(name, spec)):
        pytest.skip(f"drivekin has no {_needed(name, spec)} yet")
    robotpy_cls = getattr(drivekin, name, None)
    assert robotpy_cls is not None, f"drivekin.{name} is missing (robotpy 2027's class name)"
    base = getattr(drivekin, spec["drivekinName"])
    errors = []
    for py, kind in _names(spec).items():
        try:
            raw = inspect.getattr_static(base, py)
        except AttributeError:
            errors.append(f"{name}.{py}: missing")
            continue
        if isinstance(raw, Renamed):
            errors.append(f"{name}.{py}: still a robotpy 2026 tripwire")
            continue
        if _kind(raw) != kind:
            errors.append(f"{name}.{py}: robotpy has a {kind}, drivekin a {_kind(raw)}")
        java = spec["methods"].get(py) or spec["propertyJava"].get(py)
        if java and not java.endswith("()") and java != py:
            # An alias is the Java member itself: no extra call, one docstring.
            if raw is not inspect.getattr_static(base, java):
                errors.append(f"{name}.{py} is not the same object as {java}")
        if kind == "static" and getattr(robotpy_cls, py) is not getattr(base, py):
            errors.append(f"{name}.{py}: not reachable through {name}")
    for op in spec["operators"]:
        # Defined by drivekin (object's __eq__ is identity, not robotpy's value equality).
        if not any(op in vars(k) and vars(k)[op] is not None for k in base.__mro__[:-1]):
            errors.append(f"{name}: no {op}")
    assert not errors, "\n".join(errors)


@pytest.mark.parametrize("name", sorted(CLASSES))
def test_robotpy_read_only_properties_are_read_only(name):
    spec = CLASSES[name]
    if not spec["readonlyProperties"] or not _has(_needed(name, spec)):
        pytest.skip("no read-only properties here" if spec["readonlyProperties"] else
                    f"drivekin has no {_needed(name, spec)} yet")
    example = catalog.BY_CLASS[getattr(drivekin, spec["drivekinName"])].example()
    for prop in spec["readonlyProperties"]:
        with pytest.raises(AttributeError):
            setattr(example, prop, 1.0)


def test_the_rule_reproduces_every_table_name_but_the_exceptions():
    # The rule (and EXCEPTIONS) derives each robotpy name from the Java one: a table name
    # it would miss fails here, so the table cannot drift from pynames.
    kinds = {e.cls.__name__: e.kind for e in catalog.ENTRIES}
    wrong = []
    for name, spec in CLASSES.items():
        kind = kinds.get(spec["drivekinName"])
        if kind is None:
            continue
        pairs = list(spec["methods"].items()) + [
            (p, j.rstrip("()")) for p, j in spec["propertyJava"].items()]
        for py, java in pairs:
            if java and pynames.python_name(spec["drivekinName"], kind, java) != py:
                wrong.append(f"{name}.{java} -> {py}")
    assert not wrong, wrong


def test_the_snake_case_transform_is_semiwrap_s():
    cases = {"ToSwerveModuleVelocities": "to_swerve_module_velocities", "X": "x",
             "GetPose": "get_pose", "NEO550": "neo550", "toTwist2d": "to_twist2d",
             "getVex775Pro": "get_vex775_pro", "kZero": "zero", "NWU": "nwu",
             "getAndymarkRs775_125": "get_andymark_rs775_125", "Kv": "kv"}
    assert {k: pynames.snake_case(k) for k in cases} == cases


def test_2026_spellings_robotpy_2027_kept_have_2027_meaning():
    r = drivekin.Rotation2d(3 * math.pi / 2)
    assert r.degrees() == r.getDegrees() and math.isclose(r.degrees(), -90.0)
    assert drivekin.Translation2d(0.0, 0.0).angle() is None
    m = drivekin.DCMotor.getNEO(1)
    assert m.current(2.0) == m.getCurrent(2.0)
    alike = {("Rotation2d", n) for n in ("cos", "degrees", "radians", "sin", "tan")}
    for cls, names in RENAMES.items():
        assert not alike & {(cls, n) for n in names}


@pytest.mark.parametrize("n", catalog.SWERVE_MODULE_COUNTS)
def test_swerve_class_names_check_the_module_count(n):
    corners = [drivekin.Translation2d(math.cos(a), math.sin(a))
               for a in (2 * math.pi * i / n for i in range(n))]
    kin_cls = getattr(drivekin, f"SwerveDrive{n}Kinematics")
    kin = kin_cls(*corners)
    assert type(kin) is drivekin.SwerveDriveKinematics and isinstance(kin, kin_cls)
    other = 4 if n != 4 else 2
    assert not isinstance(kin, getattr(drivekin, f"SwerveDrive{other}Kinematics"))
    with pytest.raises(TypeError, match=f"SwerveDrive{other}Kinematics takes {other}"):
        getattr(drivekin, f"SwerveDrive{other}Kinematics")(*corners)
    zeros = [drivekin.SwerveModulePosition()] * n
    odo = getattr(drivekin, f"SwerveDrive{n}Odometry")(kin, drivekin.Rotation2d(), zeros)
    assert type(odo) is drivekin.SwerveDriveOdometry
    with pytest.raises(TypeError, match=f"{other}-module"):
        getattr(drivekin, f"SwerveDrive{other}PoseEstimator")(
            kin, drivekin.Rotation2d(), zeros, drivekin.Pose2d(), (0.1, 0.1, 0.1),
            (0.9, 0.9, 0.9))
    # Static methods through the robotpy class name are drivekin's own.
    assert kin_cls.desaturate_wheel_velocities is \
        drivekin.SwerveDriveKinematics.desaturateWheelVelocities


def test_buffer_class_names_build_drivekin_buffers():
    b = drivekin.TimeInterpolatablePose2dBuffer(1.5)
    b.add_sample(0.0, drivekin.Pose2d())
    b.add_sample(1.0, drivekin.Pose2d(2.0, 0.0, drivekin.Rotation2d()))
    assert isinstance(b, drivekin.TimeInterpolatableBuffer)
    assert b.sample(0.25).x == pytest.approx(0.5, abs=1e-15)
    f = drivekin.TimeInterpolatableFloatBuffer(5.0)
    f.add_sample(0.0, 1.0)
    f.add_sample(2.0, 3.0)
    assert f.sample(0.5) == 1.5
    g = drivekin.TimeInterpolatableFloatBuffer(5.0, lambda a, b, t: a)
    g.add_sample(0.0, 1.0)
    g.add_sample(2.0, 3.0)
    assert g.sample(1.5) == 1.0


def test_type_checkers_see_every_class_name():
    # __init__.py spells the names out under TYPE_CHECKING; they must be install()'s.
    source = Path(drivekin.__file__).read_text(encoding="utf-8")
    block = source[source.index("if TYPE_CHECKING:"):]
    spelled = set(re.findall(r"\b(SwerveDrive\d\w+|TimeInterpolatable\w+Buffer)\b", block))
    spelled.discard("TimeInterpolatableBuffer")
    built = {n for n in drivekin.__all__
             if isinstance(getattr(drivekin, n), pynames.RobotpyClass)}
    assert spelled == built


def test_a_robotpy_2027_robot_type_checks(tmp_path):
    # The stubs carry both spellings with types: mypy --strict accepts a robot written
    # with robotpy 2027's names (tests/_support/robotpy2027_robot.py).
    pytest.importorskip("mypy")
    import os
    import subprocess
    import sys
    root = Path(__file__).parents[2]
    if not (root / "src" / "drivekin" / "__init__.py").exists():
        pytest.skip("the stubs are not next to the tests (a wheel's test run)")
    env = dict(os.environ, MYPYPATH=str(root / "src"))
    done = subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", "--cache-dir", str(tmp_path),
         "--no-error-summary", str(root / "tests" / "_support" / "robotpy2027_robot.py")],
        capture_output=True, text=True, env=env, cwd=root)
    assert done.returncode == 0, done.stdout + done.stderr
