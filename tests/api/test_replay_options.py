"""Every option of the log replay is validated where it is given (issue 30 §9): in the
Python API, ``ReplayConfig`` checks each field on construction and on every later
assignment (TypeError for the wrong kind, ValueError naming the allowed values or range);
on the command line, every option that takes a list accepts a first value that is
negative, exactly as ``calibrate`` prints it in its replay command."""
from __future__ import annotations

import dataclasses
import math
import shlex

import numpy as np
import pytest

from drivekin.app import replay_cli
from drivekin.calibrate import CalibrationResult
from drivekin.replay import ReplayConfig

NAN, INF = math.nan, math.inf

# (field, bad value, exception, words the message must hold)
BAD = [
    ("compare", "interp", ValueError, "'hold', 'interpolate', got 'interp'"),
    ("gyroAlign", "nearest", ValueError, "'latest', 'interpolate'"),
    ("start", "zero", ValueError, "'logged', 'origin'"),
    ("odometryRate", "fast", ValueError, "'auto', 'cycle'"),
    ("heading", "compass", ValueError, "'gyro', 'wheels'"),
    ("ragged", "pad", ValueError, "'error', 'drop'"),
    ("drivetrain", "tank", ValueError, "'auto', 'swerve'"),
    ("gyroUnits", "degrees", ValueError, "None, 'rad', 'deg', 'rot'"),
    ("driveUnits", "inches", ValueError, "'m'"),
    ("turnUnits", "grad", ValueError, "'deg'"),
    ("compare", 1, TypeError, "got int"),
    ("gyroScale", NAN, ValueError, "finite number greater than 0"),
    ("gyroScale", 0.0, ValueError, "finite number greater than 0"),
    ("gyroScale", -1.0, ValueError, "finite number greater than 0"),
    ("gyroScale", "1.0", TypeError, "got str"),
    ("steerOffsets", [0.0, NAN, 0.0, 0.0], ValueError, "finite numbers"),
    ("steerOffsets", [INF], ValueError, "finite numbers"),
    ("wheelScale", 0.0, ValueError, "greater than 0"),
    ("wheelScale", [1.0, -1.0], ValueError, "greater than 0"),
    ("wheelScale", [], ValueError, "shape (0,)"),
    ("wheelScale", INF, ValueError, "finite"),
    ("wheelRadius", 0.0, ValueError, "greater than 0"),
    ("wheelRadius", NAN, ValueError, "finite"),
    ("trackwidth", -0.5, ValueError, "greater than 0"),
    ("wheelbase", INF, ValueError, "finite"),
    ("modules", [(0.3, 0.3, 0.0)], ValueError, "(x, y) tuples"),
    ("modules", [(0.3, NAN)], ValueError, "finite"),
    ("modules", [(0.3, 0.3), (0.3,)], ValueError, "(x, y) tuples"),
    ("deadWheels", [(0.1, 0.2)], ValueError, "(x, y, deg) tuples"),
    ("pose", 5, TypeError, "entry name (str) or None, got int"),
    ("truth", 5, TypeError, "entry name (str) or None, got int"),
    ("positions", b"/Drive", TypeError, "entry name"),
    ("gyro", "", ValueError, "not empty"),
    ("allowTruncated", "yes", TypeError, "True or False"),
    ("moduleEntries", "FL=/a,/b", TypeError, "list of str"),
    ("moduleEntries", [], ValueError, "at least one non-empty string"),
]


@pytest.mark.parametrize("field, value, error, words", BAD,
                         ids=[f"{f}={v!r}" for f, v, _, _ in BAD])
def test_a_bad_option_fails_at_construction_and_on_assignment(field, value, error, words):
    with pytest.raises(error) as info:
        ReplayConfig(**{field: value})
    assert f"ReplayConfig.{field} must be" in str(info.value) and words in str(info.value)
    cfg = ReplayConfig()
    with pytest.raises(error):
        setattr(cfg, field, value)
    assert getattr(cfg, field) == getattr(ReplayConfig(), field)     # unchanged


def test_every_field_refuses_an_arbitrary_object():
    # A field added without its check fails here (and a misspelt option is refused).
    for f in dataclasses.fields(ReplayConfig):
        with pytest.raises(TypeError, match=f"ReplayConfig.{f.name} must be"):
            ReplayConfig(**{f.name: object()})
    with pytest.raises(AttributeError, match="no option 'gyroscale'"):
        ReplayConfig().gyroscale = 1.02                  # type: ignore[attr-defined]


def test_good_values_of_every_kind_are_kept():
    cfg = ReplayConfig(
        drivetrain="swerve", positions="/Drive", gyro="/Gyro", pose="/Pose", truth=None,
        moduleEntries=["FL=/FL/Drive,/FL/Angle"],
        gyroUnits="deg", driveUnits="rot", turnUnits="rot", wheelRadius=np.float64(0.05),
        modules=[(0.3, 0.3), (0.3, -0.3), (-0.3, 0.3), (-0.3, -0.3)], wheelbase=0.6,
        deadWheels=np.zeros((3, 3)), trackwidth=1, odometryRate="cycle",
        heading="wheels", wheelScale=np.array([1.01, 0.99, 1.0, 1.0]), gyroScale=1.02,
        steerOffsets=(-0.01, 0.02, 0.0, 0.0), gyroAlign="interpolate", start="origin",
        compare="interpolate", ragged="drop", allowTruncated=True)
    assert cfg.wheelRadius == 0.05 and cfg.trackwidth == 1 and cfg.steerOffsets[0] == -0.01
    assert dataclasses.replace(cfg, compare="hold").compare == "hold"
    with pytest.raises(ValueError, match="ReplayConfig.compare"):
        dataclasses.replace(cfg, compare="interp")


# ---------------------------------------------------------------------------------------
# List options with a negative first value (calibrate's printed replay command)

def _printed_command(options: dict) -> list[str]:
    result = CalibrationResult(["match.wpilog"], "swerve", {}, [], None, [], [], options)
    words = shlex.split(result.replayCommand())
    assert words[:4] == ["python", "-m", "drivekin", "replay"]
    return words[4:]


def test_calibrates_printed_replay_command_parses_with_negative_values():
    steer = [-0.573, 1.2, -3.5, 0.25]
    scales = [0.98, 1.01, 0.99, 1.0]
    argv = _printed_command({"steer-offsets": steer, "wheel-scale": scales,
                             "gyro-scale": 1.02})
    assert "--steer-offsets=-0.573,1.2,-3.5,0.25" in argv
    args = replay_cli.parse(replay_cli.build_parser(), argv)
    assert args.steer_offsets == steer
    assert args.wheel_scale == scales and args.gyro_scale == 1.02
    assert args.logs == ["match.wpilog"]


@pytest.mark.parametrize("argv, field, expected", [
    (["--module", "-0.3,0.3", "--module", "-0.3,-0.3"], "module",
     [(-0.3, 0.3), (-0.3, -0.3)]),
    (["--dead-wheel", "-0.1,0.2,90"], "dead_wheel", [(-0.1, 0.2, 90.0)]),
    (["--steer-offsets", "-1.5"], "steer_offsets", -1.5),
    (["--steer-offsets", "-0.573,1.2,-3.5,0.25"], "steer_offsets",    # the form that failed
     [-0.573, 1.2, -3.5, 0.25]),
    (["--steer-offsets", "-.5,2"], "steer_offsets", [-0.5, 2.0]),
])
def test_every_list_option_takes_a_negative_first_value(argv, field, expected):
    args = replay_cli.parse(replay_cli.build_parser(), ["log.wpilog", *argv])
    assert getattr(args, field) == expected


def test_a_negative_value_out_of_range_is_one_argparse_line(capsys):
    with pytest.raises(SystemExit) as info:
        replay_cli.parse(replay_cli.build_parser(),
                         ["log.wpilog", "--wheel-scale", "-1,1"])
    assert info.value.code == 2
    err = capsys.readouterr().err
    errors = [line for line in err.splitlines() if "error:" in line]
    assert errors == ["python -m drivekin replay: error: argument --wheel-scale: expected a "
                      "number greater than 0 and at most 10 (or several, comma-separated), "
                      "got '-1,1'"]

