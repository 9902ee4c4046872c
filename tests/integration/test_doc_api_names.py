"""The docs site's API reference names robotpy 2027's spellings (docs/conf.py): what it
reads from the stubs' text is what drivekin installs at import (drivekin._core.pynames),
its autoapi hook hides the aliases and labels their Java members, and every robotpy class
name is named in the entry of the class it builds. What public modules export from
private ones is documented under the public module, and each imported name only once."""
from __future__ import annotations

import importlib
import pathlib
import pkgutil
import runpy

import pytest

import drivekin
from drivekin._core import pynames

ROOT = pathlib.Path(__file__).resolve().parents[2]  # tests/integration/ -> the root


@pytest.fixture(scope="module")
def conf():
    if not (ROOT / "src" / "drivekin" / "__init__.py").exists():
        pytest.skip("the stubs are not next to the tests (a wheel's test run)")
    pytest.importorskip("tomllib")                  # docs/conf.py needs Python >= 3.11
    return runpy.run_path(str(ROOT / "docs" / "conf.py"))


def test_the_spellings_read_from_the_stubs_are_the_installed_ones(conf):
    # Classes written in Python (Units, TimeInterpolatableBuffer) have their block in
    # their source, under ``if TYPE_CHECKING:``; the others in their stub.
    installed = {f"{cls.__module__}.{cls.__name__}": {java: py for py, java in names.items()}
                 for cls, names in pynames.INSTALLED.items()}
    assert len(installed) >= 30
    assert "drivekin.units.Units" in conf["SPELLINGS"]
    assert conf["SPELLINGS"] == installed


class _Documented:
    """What autoapi hands the hook: the object's parsed data and its docstring."""

    def __init__(self, docstring, inherited_from=None):
        self.docstring = docstring
        self.obj = {"inherited_from": {"full_name": inherited_from}} if inherited_from else {}


@pytest.mark.parametrize("what, name, inherited_from, line", [
    ("method", "drivekin.geometry.Rotation2d.getRadians", None, "``radians()``"),
    ("method", "drivekin.geometry.Pose2d.getRotation", "drivekin.geometry._Frame2d",
     "``rotation()``"),
    ("property", "drivekin.motor.DCMotor.stallTorque", None, "``stall_torque``"),
    ("method", "drivekin.estimator.SwerveDrivePoseEstimator.getEstimatedPosition",
     "drivekin.estimator._PoseEstimator", "``get_estimated_position()``"),
])
def test_a_java_member_shows_its_robotpy_spelling_and_the_alias_is_hidden(
        conf, what, name, inherited_from, line):
    hook = conf["_robotpy_spellings"]
    java = _Documented("Text.\n", inherited_from)
    assert hook(None, what, name, java, False, []) is None
    assert java.docstring == f"robotpy 2027: {line}\n\nText.\n"
    hook(None, what, name, java, False, [])          # autoapi may ask again
    assert java.docstring.count("robotpy 2027:") == 1
    alias = name.rpartition(".")[0] + "." + line.strip("`").removesuffix("()")
    attribute = "property" if what == "property" else "attribute"
    assert hook(None, attribute, alias, _Documented("", inherited_from), False, []) is True


def test_a_member_without_a_robotpy_spelling_is_left_alone(conf):
    same = _Documented("Text.\n")               # update is update in robotpy 2027 too
    assert conf["_robotpy_spellings"](
        None, "method", "drivekin.estimator.SwerveDrivePoseEstimator.update", same,
        False, []) is None
    assert same.docstring == "Text.\n"


def test_every_robotpy_class_name_is_in_its_class_entry(conf):
    built = {name: obj for name, obj in vars(drivekin).items()
             if isinstance(obj, pynames.RobotpyClass)}
    assert len(built) >= 16
    for name, obj in built.items():
        entry = _Documented("First paragraph.\n\nMore.\n")
        conf["_robotpy_spellings"](None, "class", f"drivekin.x.{obj._base.__name__}", entry,
                                   False, [])
        first, line, rest = entry.docstring.split("\n\n")
        assert (first, rest) == ("First paragraph.", "More.\n")
        assert f"``{name}``" in line, (name, line)


def test_what_a_public_module_exports_from_a_private_one_is_read_by_the_docs(conf):
    """The site reads no private module but those in REEXPORTED: a name in a public
    module's ``__all__`` defined in one of the others would have no entry at all."""
    read = {f"drivekin._core.{name.rsplit('.', 1)[0]}" for name in conf["REEXPORTED"]}
    homes = {}
    for info in pkgutil.iter_modules(drivekin.__path__):
        if info.name.startswith("_") or info.name == "app":
            continue
        module = importlib.import_module(f"drivekin.{info.name}")
        for name in getattr(module, "__all__", ()):
            home = getattr(getattr(module, name), "__module__", "")
            if home.startswith("drivekin._core"):
                homes[f"drivekin.{info.name}.{name}"] = home
    assert "drivekin.choreo.SwerveSample" in homes
    assert {name: home for name, home in homes.items() if home not in read} == {}


@pytest.mark.parametrize("what, name, original, skipped", [
    ("module", "drivekin._core.choreokernel", None, True),
    ("module", "drivekin.choreo", None, None),
    ("class", "drivekin.choreo.SwerveSample", "drivekin._core.choreokernel.SwerveSample", None),
    ("class", "drivekin.choreo.Pose2d", "drivekin.geometry.Pose2d", True),
    ("class", "drivekin.Pose2d", "drivekin.geometry.Pose2d", True),
])
def test_imported_names_are_documented_once(conf, what, name, original, skipped):
    entry = _Documented("Text.\n")
    if original:
        entry.obj["original_path"] = original
    assert conf["_private_and_reexported"](None, what, name, entry, False, []) is skipped
