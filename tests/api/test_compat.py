"""What 0.1.0 users relied on keeps working after the 0.2.0 restructure: every public name
of every 0.1.0 module is still importable from that module (the lists in
``tests/data/api-0.1.0.json`` were read off the 0.1.0 build), and pickles written by 0.1.0
(``tests/data/pickles-0.1.0.json``, one per value and kinematics class) load into the
same class with the same state."""
from __future__ import annotations

import base64
import importlib
import json
import pickle
from pathlib import Path

import pytest

import drivekin

DATA = Path(__file__).resolve().parents[1] / "data"
API = json.loads((DATA / "api-0.1.0.json").read_text())["modules"]
PICKLES = json.loads((DATA / "pickles-0.1.0.json").read_text())["objects"]


@pytest.mark.parametrize("module", sorted(API))
def test_old_module_paths_export_the_same_names(module):
    mod = importlib.import_module(module)
    missing = [n for n in API[module] if not hasattr(mod, n)]
    assert not missing, f"{module} no longer has {missing}"


@pytest.mark.parametrize("module", sorted(m for m in API if m != "drivekin"))
def test_old_paths_give_the_public_objects(module):
    # The same objects as drivekin's own names, not copies: isinstance and pickling agree.
    mod = importlib.import_module(module)
    for name in API[module]:
        if name in drivekin.__all__:
            assert getattr(mod, name) is getattr(drivekin, name), (module, name)


# Value classes added after 0.1.0, which therefore has no pickles of them (their pickling
# is tested with the class: DCMotor in tests/reference/test_dcmotor_wpilib.py, the
# setpoint generator's values in tests/behaviour/test_setpoint.py, the 3-D geometry in
# tests/behaviour/test_geometry3d.py).
NEW_SINCE_0_1_0 = {"DCMotor", "DriveFeedforwards", "ModuleConfig", "PathConstraints",
                   "RobotConfig", "SwerveSetpoint", "Quaternion", "Rotation3d", "Translation3d",
                   "Pose3d", "Transform3d", "Twist3d", "CoordinateAxis", "CoordinateSystem"}


def test_pickle_data_covers_every_value_and_kinematics_class():
    from drivekin._core import catalog
    classes = {e.cls.__name__ for e in catalog.ENTRIES if e.kind in ("value", "kinematics")}
    assert classes - NEW_SINCE_0_1_0 == set(PICKLES)
    assert not NEW_SINCE_0_1_0 & set(PICKLES)


# The reprs spell constructor keywords, which are robotpy 2027's snake_case names since
# 0.1.0 recorded its reprs; the state they show is the same.
RENAMED_KEYWORDS = {"frontLeft=": "front_left=", "frontRight=": "front_right=",
                    "rearLeft=": "rear_left=", "rearRight=": "rear_right=",
                    "wheelVelocity=": "wheel_velocity=", "azimuthVelocity=": "azimuth_velocity=",
                    "azimuthGearRatio=": "azimuth_gear_ratio=",
                    "wheelGearRatio=": "wheel_gear_ratio=", "wheelRadius=": "wheel_radius=",
                    "motor2Inverted=": "motor2_inverted="}


def _renamed(text):
    for old, new in RENAMED_KEYWORDS.items():
        text = text.replace(old, new)
    return text


@pytest.mark.parametrize("name", sorted(PICKLES))
def test_pickles_written_by_0_1_0_load(name):
    record = PICKLES[name]
    obj = pickle.loads(base64.b64decode(record["pickle"]))
    assert type(obj) is getattr(drivekin, name)
    assert repr(obj) == _renamed(record["repr"])       # the state 0.1.0 pickled
    again = pickle.loads(pickle.dumps(obj))
    assert type(again) is type(obj) and repr(again) == repr(obj)
