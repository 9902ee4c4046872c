"""calibrate knows drivetrains only through their calibration models
(``drivekin._core.calibrationmodels``): one per drivetrain replay can replay, and no
drivetrain name is compared in calibrate's code."""
from __future__ import annotations

import ast
import pathlib

import drivekin
from drivekin import replay
from drivekin._core import calibrationmodels

SOURCES = ("calibrate.py", "_core/calibrationfit.py")


def test_one_model_per_replayable_drivetrain():
    assert sorted(m.drivetrain for m in calibrationmodels.MODELS) == sorted(replay.DRIVETRAINS)
    for m in calibrationmodels.MODELS:
        assert m.parameters[-1] == "gyroScale"
        assert set(m.windowEstimates) | set(m.undetermined) | {"gyroScale"} >= \
            set(m.parameters) - {"deadWheelPoses"}


def test_calibrate_compares_no_drivetrain_name():
    root = pathlib.Path(drivekin.__file__).parent
    for name in SOURCES:
        tree = ast.parse((root / name).read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Compare):
                consts = [n.value for n in ast.walk(node) if isinstance(n, ast.Constant)]
                assert not set(consts) & set(replay.DRIVETRAINS), (name, ast.unparse(node))
