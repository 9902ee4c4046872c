"""Hostile logs through ``python -m drivekin replay`` and ``calibrate`` (issue 30 §9):
entry names carrying terminal control characters, metadata nested 2,000 deep, NaN in a
logged or reference pose, a gyro that jumps by 1e9 rad, and a quote in the entry name
that the replay log's metadata names. Each gets one error line (or a clean report), an
exit status of 0, 1 or 2 and never a traceback, and nothing a terminal would act on.

The logs are written by robotpy-wpiutil's DataLogWriter (values packed by robotpy's
wpistruct) and read back, where a test reads an output, by robotpy-wpiutil's
DataLogReader: a swerve robot driving straight along x at 1 m/s for 2 s (50 Hz), all
four modules at angle 0, so the replayed pose is (t, 0, 0) exactly.
"""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys

import pytest

wpiutil = pytest.importorskip("wpiutil")

import wpiutil.log as wlog                                       # noqa: E402
import wpiutil.wpistruct as ws                                   # noqa: E402
from wpimath.geometry import Pose2d, Rotation2d                  # noqa: E402
from wpimath.kinematics import SwerveModulePosition              # noqa: E402

import drivekin                                                  # noqa: E402
from drivekin import datalog, replay                             # noqa: E402
from drivekin._core.display import escape                        # noqa: E402

_PACKAGE_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(drivekin.__file__)))
GEOMETRY = ("--trackwidth", "0.5", "--wheelbase", "0.5")
RATE_HZ = 50
SAMPLES = 100
T0_US = 1_000_000

# Names a hostile (or careless) robot program could write: ESC sequences (clear the
# screen, set the window title), BEL, CR, a C1 CSI, NUL, the right-to-left override,
# and visible non-ASCII text that must stay as it is.
POSITIONS = "/Drive/Modules\x1b]0;owned\x07"
GYRO = "/Drive/Gyro\r\u202eoryG"
POSE = "/RealOutputs/Odometry/Robot\x9b2J\x00é日本"
# Every character a terminal could act on, as escape() defines them.
CONTROLS = [chr(c) for c in (*range(0x20), *range(0x7F, 0xA0), 0x061C, 0x200E, 0x200F,
                             *range(0x2028, 0x202F), *range(0x2066, 0x206A)) if c != 0x0A]


def run_cli(*args: str, timeout: float = 120) -> subprocess.CompletedProcess:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (_PACKAGE_ROOT, env.get("PYTHONPATH", ""))
                                        if p)
    return subprocess.run([sys.executable, "-m", "drivekin", *args], env=env,
                          capture_output=True, text=True, encoding="utf-8", timeout=timeout)


def write_straight_log(path, *, positions=POSITIONS, gyro=GYRO, pose=POSE, extra_gyros=(),
                       gyro_values=None, pose_values=None, truth=None, metadata=""):
    """The straight-driving robot (module docstring). ``gyro_values``: the gyro's angle
    at each sample (default 0); ``pose_values``: (x, y, θ) per sample (default the true
    pose); ``truth``: (name, poses) of a second pose entry; ``metadata``: every entry's."""
    log = wpiutil.DataLogWriter(str(path))
    log.addStructSchema(SwerveModulePosition, 0)
    log.addStructSchema(Pose2d, 0)
    e_mod = log.start(positions, "struct:SwerveModulePosition[]", metadata, T0_US)
    e_gyros = [log.start(name, "struct:Rotation2d", metadata, T0_US)
               for name in (gyro, *extra_gyros)]
    e_pose = log.start(pose, "struct:Pose2d", metadata, T0_US)
    e_truth = log.start(truth[0], "struct:Pose2d", metadata, T0_US) if truth else None
    # A double whose metadata is read for its unit (a gyro candidate by its name).
    e_heading = log.start("/Drive/Heading", "double", metadata, T0_US)
    for i in range(SAMPLES):
        ts = T0_US + i * 1_000_000 // RATE_HZ
        d = i / RATE_HZ                                    # m, at 1 m/s
        log.appendRaw(e_mod, ws.packArray([SwerveModulePosition(d, Rotation2d(0.0))] * 4), ts)
        for e in e_gyros:
            g = 0.0 if gyro_values is None else gyro_values[i]
            log.appendRaw(e, ws.pack(Rotation2d(g)), ts)
        x, y, th = (d, 0.0, 0.0) if pose_values is None else pose_values[i]
        log.appendRaw(e_pose, ws.pack(Pose2d(x, y, Rotation2d(th))), ts)
        if e_truth is not None:
            x, y, th = truth[1][i]
            log.appendRaw(e_truth, ws.pack(Pose2d(x, y, Rotation2d(th))), ts)
        log.appendDouble(e_heading, 0.0, ts)
        if i % 20 == 0:
            log.flush()
    log.flush()
    log.stop()
    return path


def assert_harmless(text: str) -> None:
    bad = sorted({f"U+{ord(c):04X}" for c in text if c in CONTROLS})
    assert not bad, f"control characters printed: {bad}\n{text[-600:]}"


def one_error(r: subprocess.CompletedProcess, verb: str, status: int = 1) -> str:
    assert r.returncode == status, (r.returncode, r.stderr[-800:])
    assert "Traceback" not in r.stderr
    errors = [line for line in r.stderr.splitlines() if "error:" in line]
    assert len(errors) == 1, r.stderr
    assert errors[0].startswith(f"python -m drivekin {verb}: error: "), errors[0]
    assert_harmless(r.stdout + r.stderr)
    return errors[0]


@pytest.fixture(scope="module")
def hostile(tmp_path_factory):
    return write_straight_log(tmp_path_factory.mktemp("hostile") / "hostile.wpilog")


# ---------------------------------------------------------------------------------------
# Entry names with terminal control characters

def test_escape_writes_controls_as_repr_does_and_keeps_visible_text():
    assert escape(POSE) == "/RealOutputs/Odometry/Robot\\x9b2J\\x00é日本"
    assert escape(GYRO) == "/Drive/Gyro\\r\\u202eoryG"
    assert escape("a\nb\tc\x7f\u2028\u2066") == "a\\nb\\tc\\x7f\\u2028\\u2066"
    for c in CONTROLS + ["\n"]:
        assert escape(c) == repr(c)[1:-1]
    assert escape(escape(POSE)) == escape(POSE)


def test_the_replay_report_prints_entry_names_escaped(hostile):
    r = run_cli("replay", str(hostile), "--no-write", *GEOMETRY)
    assert r.returncode == 0, r.stderr
    assert_harmless(r.stdout + r.stderr)
    for name in (POSITIONS, GYRO, POSE):
        assert escape(name) in r.stdout, r.stdout
    assert "Traceback" not in r.stderr


def test_list_prints_entry_names_escaped(hostile):
    r = run_cli("replay", str(hostile), "--list", *GEOMETRY)
    assert r.returncode == 0, r.stderr
    assert_harmless(r.stdout + r.stderr)
    for name in (POSITIONS, GYRO, POSE):
        assert escape(name) in r.stdout, r.stdout


def test_json_holds_the_names_exactly_in_ascii_escapes(hostile):
    r = run_cli("replay", str(hostile), "--no-write", "--json", *GEOMETRY)
    assert r.returncode == 0, r.stderr
    assert_harmless(r.stdout + r.stderr)
    assert r.stdout.isascii()
    entries = json.loads(r.stdout)[0]["entries"]
    assert (entries["positions"], entries["gyro"], entries["pose"]) == (POSITIONS, GYRO, POSE)


def test_an_error_listing_entry_names_is_one_escaped_line(tmp_path):
    other = "/Backup\x1b[2JGyro"
    path = write_straight_log(tmp_path / "two.wpilog", extra_gyros=[other])
    line = one_error(run_cli("replay", str(path), "--no-write", *GEOMETRY), "replay")
    assert "several gyro entries" in line and escape(other) in line and escape(GYRO) in line
    with pytest.raises(datalog.DataLogError) as info:          # the Python API's message
        replay.replayLog(path, replay.ReplayConfig(trackwidth=0.5, wheelbase=0.5))
    assert_harmless(str(info.value))
    assert escape(other) in str(info.value)


def test_calibrate_prints_entry_names_escaped(hostile):
    pytest.importorskip("scipy")
    # The robot never turns: calibrate refuses it, naming the gyro.
    line = one_error(run_cli("calibrate", str(hostile), *GEOMETRY), "calibrate")
    assert "turn" in line


def test_a_path_with_control_characters_is_printed_escaped(tmp_path):
    path = tmp_path / "bad\x1b[31mname.wpilog"
    line = one_error(run_cli("replay", str(path), "--no-write"), "replay")
    assert "bad\\x1b[31mname.wpilog" in line


# ---------------------------------------------------------------------------------------
# Metadata nested 2,000 deep (under the 4 KiB cap)

DEEP = '{"unit":' + "[" * 2000 + "]" * 2000 + "}"


@pytest.fixture(scope="module")
def deep(tmp_path_factory):
    assert len(DEEP) < 4096
    return write_straight_log(tmp_path_factory.mktemp("deep") / "deep.wpilog",
                              metadata=DEEP)


@pytest.mark.parametrize("extra", [(), ("--list",), ("--json",)],
                         ids=["replay", "list", "json"])
def test_deeply_nested_metadata_is_ignored_by_replay(deep, extra):
    r = run_cli("replay", str(deep), "--no-write", *GEOMETRY, *extra)
    assert r.returncode == 0, r.stderr[-800:]
    assert "Traceback" not in r.stderr and "RecursionError" not in r.stderr


def test_deeply_nested_metadata_is_ignored_by_calibrate(deep):
    pytest.importorskip("scipy")
    line = one_error(run_cli("calibrate", str(deep), *GEOMETRY), "calibrate")
    assert "RecursionError" not in line


def test_metadata_parser_bounds_depth_without_recursing():
    from drivekin._core import metadata
    assert metadata.depth(DEEP) == 2001
    assert metadata.parse(DEEP) is None
    assert metadata.depth('{"a": "[[[{{{\\"[[", "b": [[1]]}') == 3
    assert metadata.parse('{"unit": "m", "b": [[1]]}') == {"unit": "m", "b": [[1]]}
    assert metadata.parse("[1]") is None and metadata.parse("{nope") is None


# ---------------------------------------------------------------------------------------
# The replay log's metadata is JSON, whatever the pose entry is called

def test_replay_log_metadata_is_json_encoded(tmp_path):
    name = '/Pose "quoted" \\ {"x": 1}'
    path = write_straight_log(tmp_path / "quote.wpilog", pose=name)
    r = run_cli("replay", str(path), *GEOMETRY, "--pose", name)
    assert r.returncode == 0, r.stderr
    metadata = {}
    for record in wlog.DataLogReader(str(tmp_path / "quote-replay.wpilog")):
        if record.isStart():
            start = record.getStartData()
            metadata[start.name] = start.metadata
    assert json.loads(metadata[replay.ERROR_ENTRY]) == {"unit": "m", "against": name}


# ---------------------------------------------------------------------------------------
# NaN in a logged pose and in --truth

def _true(i: int) -> tuple[float, float, float]:
    return (i / RATE_HZ, 0.0, 0.0)


NAN = (math.nan, math.nan, math.nan)


def test_nan_in_the_logged_pose_is_skipped_and_counted(tmp_path):
    poses = [NAN if i in (30, 40, 41) else _true(i) for i in range(SAMPLES)]
    path = write_straight_log(tmp_path / "nanpose.wpilog", pose_values=poses)
    r = run_cli("replay", str(path), "--no-write", "--json", *GEOMETRY)
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)[0]
    assert any(f"3 of the {SAMPLES} poses of pose entry" in n for n in d["notes"]), d["notes"]
    # The replay of the straight path is the closed form (t, 0, 0): tiny drift, not NaN.
    assert d["vs_logged"]["count"] == SAMPLES - 3
    assert d["vs_logged"]["max_position_m"] < 1e-9


def test_a_nan_first_pose_starts_the_replay_at_the_first_finite_one(tmp_path):
    poses = [NAN if i == 0 else _true(i) for i in range(SAMPLES)]
    path = write_straight_log(tmp_path / "nanfirst.wpilog", pose_values=poses)
    r = replay.replayLog(path, replay.ReplayConfig(trackwidth=0.5, wheelbase=0.5))
    assert tuple(r.poses[0]) == pytest.approx(_true(1), abs=1e-12)
    assert math.isfinite(r.vsLogged.maxPosition) and r.vsLogged.count == SAMPLES - 1
    assert any(f"1 of the {SAMPLES} poses" in n for n in r.notes)


def test_a_logged_pose_with_no_finite_value_is_refused(tmp_path):
    path = write_straight_log(tmp_path / "allnan.wpilog", pose_values=[NAN] * SAMPLES)
    line = one_error(run_cli("replay", str(path), "--no-write", *GEOMETRY), "replay")
    assert f"pose entry {POSE!r} holds no finite pose: all {SAMPLES}" in line


def test_nan_in_the_truth_is_skipped_and_counted(tmp_path):
    truth = [NAN if i % 10 == 3 else _true(i) for i in range(SAMPLES)]
    path = write_straight_log(tmp_path / "nantruth.wpilog", truth=("/Sim/TruePose", truth))
    r = run_cli("replay", str(path), "--no-write", "--json", *GEOMETRY,
                "--truth", "/Sim/TruePose")
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)[0]
    assert any("10 of the 100 poses of --truth entry '/Sim/TruePose'" in n
               for n in d["notes"]), d["notes"]
    assert d["vs_truth"]["count"] == SAMPLES - 10
    assert d["vs_truth"]["max_position_m"] < 1e-9


def test_a_truth_with_no_finite_value_is_refused(tmp_path):
    path = write_straight_log(tmp_path / "alltruth.wpilog",
                              truth=("/Sim/TruePose", [NAN] * SAMPLES))
    for verb in ("replay", "calibrate"):
        if verb == "calibrate" and not _has_scipy():
            continue
        line = one_error(run_cli(verb, str(path), *GEOMETRY, "--truth", "/Sim/TruePose",
                                 *(["--no-write"] if verb == "replay" else [])), verb)
        assert "--truth entry '/Sim/TruePose' holds no finite pose" in line


def _has_scipy() -> bool:
    import importlib.util
    return importlib.util.find_spec("scipy") is not None


# ---------------------------------------------------------------------------------------
# A gyro jump of 1e9 rad (1e9 wraps to 0.58 rad: no longer hidden by the wrap)

def test_a_gyro_jump_of_1e9_rad_is_refused(tmp_path):
    gyro = [1e9 if i == 50 else 0.0 for i in range(SAMPLES)]
    path = write_straight_log(tmp_path / "jump.wpilog", gyro_values=gyro)
    line = one_error(run_cli("replay", str(path), "--no-write", *GEOMETRY), "replay")
    assert "turns by up to 1e+09 rad between samples" in line
    assert "corrupt or in the wrong units" in line


def test_a_gyro_wrapping_at_a_half_turn_is_not_a_jump(tmp_path):
    # Turning at 1 rad/s, read in (-π, π]: it wraps by a whole turn, which is no step.
    gyro = [math.remainder(0.02 * i + 3.0, 2 * math.pi) for i in range(SAMPLES)]
    path = write_straight_log(tmp_path / "wrap.wpilog", gyro_values=gyro,
                              pose_values=None)
    r = run_cli("replay", str(path), "--no-write", "--json", *GEOMETRY, "--start", "origin")
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout)[0]
    assert d["final_pose"]["heading_deg"] == pytest.approx(
        math.degrees(math.remainder(0.02 * (SAMPLES - 1), 2 * math.pi)), abs=1e-9)
