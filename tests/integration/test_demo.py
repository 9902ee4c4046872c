"""End-to-end tests of the ``python -m drivekin`` demo (src/drivekin/app/demo/, command line
in src/drivekin/app/cli.py).

Each test runs the demo in a subprocess with the interpreter running the tests, so the
demo is exercised exactly as a newcomer would start it. The subprocess gets this
process's environment, with the directory that holds the imported ``drivekin`` package
put first on PYTHONPATH, so it runs the same (in-place built) package.
"""
from __future__ import annotations

import json
import os
import re
import subprocess
import sys

import pytest

import drivekin

_PACKAGE_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(drivekin.__file__)))


def run_demo(*args: str) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        p for p in (_PACKAGE_ROOT, env.get("PYTHONPATH", "")) if p)
    return subprocess.run(
        [sys.executable, "-m", "drivekin", *args],
        env=env, capture_output=True, text=True, encoding="utf-8", timeout=300,
    )


def _row(text: str, label: str) -> str:
    """The value column of the table row starting with ``label``."""
    m = re.search(rf"^\s*{re.escape(label)}\s+(.+)$", text, re.MULTILINE)
    assert m, f"no row {label!r} in output:\n{text}"
    return m.group(1)


DRIVETRAINS = ("swerve", "mecanum", "differential", "deadwheel", "diffswerve")
ODOMETRY = {"swerve": "SwerveDriveOdometry", "mecanum": "MecanumDriveOdometry",
            "differential": "DifferentialDriveOdometry", "deadwheel": "DeadWheelOdometry",
            "diffswerve": "SwerveDriveOdometry"}


@pytest.fixture(scope="module", params=DRIVETRAINS)
def text_run(request) -> tuple[str, subprocess.CompletedProcess]:
    return request.param, run_demo("--drivetrain", request.param, "--seconds", "5")


def test_text_output_exit_code_and_sections(text_run):
    drivetrain, result = text_run
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    out = result.stdout
    assert "250 steps" in out
    for label in ("p50", "p99", "max", "mean"):
        assert re.search(rf"^\s*{label}\s+\d+\.\d+ µs\s+\d+\.\d+ % of 20 ms", out, re.MULTILINE), \
            f"latency row {label!r} missing:\n{out}"
    pose = _row(out, "final pose")
    assert re.match(r"x -?\d+\.\d+ m, y -?\d+\.\d+ m\s+heading -?\d+\.\d+°", pose), pose
    distance = re.match(r"(\d+\.\d+) m\b", _row(out, "distance travelled"))
    assert distance and float(distance.group(1)) > 0.0, out


def test_header_names_drivetrain_and_odometry(text_run):
    drivetrain, result = text_run
    first_line = result.stdout.splitlines()[0]
    assert f"50 Hz {drivetrain} drive control loop" in first_line, first_line
    assert re.search(rf"^\s*odometry\s+{ODOMETRY[drivetrain]}\b", result.stdout, re.MULTILINE), \
        result.stdout
    assert f"{ODOMETRY[drivetrain]}.update" in result.stdout     # in the step chain


def test_text_output_reports_zero_allocations(text_run):
    out = text_run[1].stdout
    assert _row(out, "allocator calls").split()[0] == "0"
    assert _row(out, "traced peak - start").startswith("0 B")
    assert _row(out, "traced end - start").startswith("0 B")
    # Live blocks may only fall: a float created before the window and replaced inside it
    # is freed for real when CPython's float freelist happens to be full (seen as -1 in
    # about 1 run in 15, 0.1.0 included). Growth would be a leak; the allocator-call count
    # above is the exact test that nothing was allocated.
    assert int(_row(out, "live blocks end - start").split()[0]) <= 0
    assert _row(out, "passes agree").startswith("yes")


@pytest.mark.parametrize("drivetrain", DRIVETRAINS)
def test_json_run_moves_and_is_deterministic(drivetrain):
    argv = ("--drivetrain", drivetrain, "--seconds", "5", "--json")
    first, second = run_demo(*argv), run_demo(*argv)
    assert first.returncode == 0, first.stderr
    assert second.returncode == 0, second.stderr
    a, b = json.loads(first.stdout), json.loads(second.stdout)
    assert a["drivetrain"] == drivetrain
    assert a["odometry"] == ODOMETRY[drivetrain]
    assert a["steps"] == 250
    assert a["distance_m"] > 0.0
    assert (a["final_pose"]["x_m"], a["final_pose"]["y_m"]) != (0.0, 0.0)
    # Deterministic: bit-identical across processes and between the two passes of a run.
    assert a["final_pose"] == b["final_pose"]
    assert a["distance_m"] == b["distance_m"]
    assert a["passes_agree"] and b["passes_agree"]
    allocations = dict(a["allocations"])
    assert allocations.pop("net_blocks") <= 0       # see test_text_output_reports_zero_allocations
    assert allocations == {"allocator_calls": 0, "traced_peak_bytes": 0, "traced_net_bytes": 0}
    lat = a["latency_us"]
    assert 0.0 < lat["p50"] <= lat["p99"] <= lat["max"]


def test_deadwheel_mode_reports_both_odometries_against_the_truth():
    r = run_demo("--drivetrain", "deadwheel", "--seconds", "30", "--json")
    assert r.returncode == 0, r.stderr
    a = json.loads(r.stdout)
    drive, dead = a["drive_encoder_error_m"], a["dead_wheel_error_m"]
    # The drive encoders miss the simulated slip; the dead wheels only see ticks and
    # noise. The bounds are loose physical expectations, not measured results.
    assert drive["final"] > 0.1 and drive["max"] >= drive["final"]
    assert 0.0 < dead["final"] < 0.02 and dead["max"] >= dead["final"]
    # The reported (dead-wheel) pose is the odometry's, close to the truth.
    truth, pose = a["true_pose"], a["final_pose"]
    assert abs(truth["x_m"] - pose["x_m"]) < 0.02 and abs(truth["y_m"] - pose["y_m"]) < 0.02
    text = run_demo("--drivetrain", "deadwheel", "--seconds", "1")
    assert "dead-wheel error" in text.stdout and "drive-encoder error" in text.stdout


def test_vision_mode_reports_odometry_and_estimator_against_the_truth():
    r = run_demo("--vision", "--seconds", "30", "--json")
    assert r.returncode == 0, r.stderr
    a = json.loads(r.stdout)
    assert a["odometry"] == "SwerveDrivePoseEstimator" and a["vision"] is True
    odo, est = a["odometry_error_m"], a["estimator_error_m"]
    # Worn wheels make the odometry drift by tens of cm over the script; the camera keeps
    # the estimator near the truth. Loose physical bounds, not measured results.
    assert odo["max"] > 0.2
    assert est["max"] < 0.5 * odo["max"] and est["mean"] < 0.5 * odo["mean"]
    allocations = dict(a["allocations"])
    assert allocations.pop("net_blocks") <= 0
    assert allocations == {"allocator_calls": 0, "traced_peak_bytes": 0, "traced_net_bytes": 0}
    lat = a["estimator_latency_us"]
    assert 0.0 < lat["p50"] <= lat["p99"] <= lat["max"] and lat["mean"] > 0.0
    text = run_demo("--vision", "--seconds", "1")
    assert "estimator error" in text.stdout and "odometry-only error" in text.stdout
    assert "estimator per step" in text.stdout
    refused = run_demo("--vision", "--drivetrain", "mecanum", "--seconds", "1")
    assert refused.returncode == 2 and "--vision" in refused.stderr


def test_setpoint_generator_mode_limits_steps_without_allocating():
    argv = ("--setpoint-generator", "--seconds", "5", "--json")
    first, second = run_demo(*argv), run_demo(*argv)
    plain = run_demo("--seconds", "5", "--json")
    for r in (first, second, plain):
        assert r.returncode == 0, r.stderr
    a, b, p = json.loads(first.stdout), json.loads(second.stdout), json.loads(plain.stdout)
    assert (a["drivetrain"], a["odometry"], a["steps"]) == ("swerve", "SwerveDriveOdometry", 250)
    # generateSetpointInto keeps the loop allocation-free.
    allocations = dict(a["allocations"])
    assert allocations.pop("net_blocks") <= 0       # see test_text_output_reports_zero_allocations
    assert allocations == {"allocator_calls": 0, "traced_peak_bytes": 0, "traced_net_bytes": 0}
    assert a["passes_agree"]
    sg = a["setpoint_generator"]
    assert sg["mode"] == "default" and sg["steps"] == 250
    # The script's first step asks for 2.25 m/s from rest, far beyond one 20 ms step of
    # a 60 kg robot's drive torque: the generator must limit some steps, and not all (the
    # commands hold still for seconds at a time).
    assert 0 < sg["limited_steps"] < 250
    assert sg["limited_fraction"] == pytest.approx(sg["limited_steps"] / 250, rel=1e-12)
    lat = a["setpoint_generator_latency_us"]
    assert 0.0 < lat["p50"] <= lat["p99"] <= lat["max"] and lat["mean"] > 0.0
    # Deterministic, and a different run from the one without the generator.
    assert a["final_pose"] == b["final_pose"] and sg == b["setpoint_generator"]
    assert a["final_pose"] != p["final_pose"]
    assert "setpoint_generator" not in p and "setpoint_generator_latency_us" not in p


def test_setpoint_generator_text_report_and_where_it_applies():
    out = run_demo("--setpoint-generator", "--seconds", "1").stdout
    assert "SwerveSetpointGenerator.generateSetpointInto (default mode)" in out   # step chain
    assert "setpoint generator: 60 kg" in out                                     # robot
    assert re.match(r"\d+ of 50\s+\d+\.\d %", _row(out, "steps limited")), out
    assert re.match(r"\d+\.\d+ µs\s+p50; p99", _row(out, "generateSetpointInto")), out
    assert _row(out, "allocator calls").split()[0] == "0"
    vision = run_demo("--setpoint-generator", "--vision", "--seconds", "1", "--json")
    assert vision.returncode == 0, vision.stderr
    v = json.loads(vision.stdout)
    assert v["vision"] is True and v["setpoint_generator"]["steps"] == 50
    assert v["allocations"]["allocator_calls"] == 0
    assert "estimator_latency_us" in v and "setpoint_generator_latency_us" in v
    for drivetrain in ("mecanum", "differential", "deadwheel", "diffswerve"):
        refused = run_demo("--setpoint-generator", "--drivetrain", drivetrain, "--seconds", "1")
        assert refused.returncode == 2 and "--setpoint-generator" in refused.stderr
        assert refused.stdout == ""


def test_default_drivetrain_is_swerve():
    result = run_demo("--seconds", "0.1", "--json")
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    assert (data["drivetrain"], data["odometry"]) == ("swerve", "SwerveDriveOdometry")


def test_help_documents_every_option():
    result = run_demo("--help")
    assert result.returncode == 0
    for option in ("--seconds", "--max-speed", "--max-omega", "--drivetrain", "--quiet",
                   "--json", "--vision", "--setpoint-generator"):
        assert option in result.stdout
    for drivetrain in DRIVETRAINS:
        assert drivetrain in result.stdout


def test_rejects_non_positive_seconds():
    result = run_demo("--seconds", "0")
    assert result.returncode == 2
    assert "--seconds" in result.stderr


def test_rejects_unknown_drivetrain():
    result = run_demo("--drivetrain", "bogus")
    assert result.returncode == 2
    assert result.stdout == ""
    assert "--drivetrain" in result.stderr and "invalid choice" in result.stderr


def test_diffswerve_odometry_matches_the_plant_and_respects_the_motor_limit():
    # --max-speed 1.0 makes the spin segment saturate the motors: the drive-level factor
    # must drop below 1 and no motor command may exceed the limit.
    result = run_demo("--drivetrain", "diffswerve", "--seconds", "30", "--max-speed", "1.0",
                      "--json")
    assert result.returncode == 0, result.stderr
    d = json.loads(result.stdout)["diffswerve"]
    limit = 0.5 * 14.0 / 0.0508 * 1.0              # R_L / r · max speed / 2
    assert d["motor_limit_radps"] == pytest.approx(limit, rel=1e-15)
    assert d["peak_motor_command_radps"] <= d["motor_limit_radps"]
    assert d["peak_motor_command_radps"] > 0.99 * d["motor_limit_radps"]
    assert 0.0 < d["min_drive_factor"] < 1.0
    # Module positions from motor positions agree with the plant's own integration (the
    # consistency quail's position formula lacks): only rounding separates the paths.
    assert d["max_position_error_m"] < 1e-9
    assert d["max_pod_angle_error_rad"] < 1e-9


def test_diffswerve_text_report_has_its_rows():
    out = run_demo("--drivetrain", "diffswerve", "--seconds", "1", "--quiet").stdout
    for label in ("motor limit", "peak motor command", "min drive-level factor",
                  "odometry vs truth", "pod angle vs truth"):
        _row(out, label)
