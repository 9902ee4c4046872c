"""Replay and calibrate know drivetrains only through their specs on the catalog
(``_core/replayspec``, each holding its ``_core/calibrationmodels`` model): one per
drivetrain replay can replay, and no drivetrain name is compared in their code."""
from __future__ import annotations

import ast
import pathlib

import drivekin
from drivekin import replay
from drivekin._core import calibrationmodels, catalog

# replay and calibrate know drivetrains only through their specs on the catalog
SOURCES = ("calibrate.py", "_core/calibrationfit.py", "replay.py", "_core/replayinputs.py",
           "_core/listing.py", "app/replay_cli.py", "app/calibrate_cli.py")


def test_one_model_per_replayable_drivetrain():
    specs = catalog.replay_specs()
    assert tuple(s.name for s in specs) == replay.DRIVETRAINS
    assert tuple(e.drivetrain for e in catalog.entries("odometry") if e.replay) == \
        replay.DRIVETRAINS
    for s in specs:
        m = s.calibration
        assert isinstance(m, calibrationmodels.CalibrationModel)
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
