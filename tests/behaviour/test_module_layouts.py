"""Per-module layouts of _core/modulelayouts: the velocity-integration rule against closed
forms, and --module-entries on logs written by robotpy-wpiutil's DataLogWriter."""
from __future__ import annotations

import numpy as np
import pytest

from drivekin import datalog, replay
from drivekin._core.modulelayouts import HELD_GAP, integral_at

pytest.importorskip("wpiutil")
from tests._support.wpilog_logs import RobotpyLog  # noqa: E402


def test_a_linear_velocity_is_integrated_exactly_between_and_after_records():
    # v(t) = 0.3 + 1.7 t on records every 20 ms: the trapezoid is exact for it; between
    # records the rule is the exact integral of the linear piece; after the last record
    # the last value is held.
    t = np.arange(0, 1_000_001, 20_000, dtype=np.int64)
    v = 0.3 + 1.7 * t / 1e6
    q = np.array([0, 7_000, 20_000, 513_777, 1_000_000], dtype=np.int64)
    s = q / 1e6
    assert np.allclose(integral_at(t, v, q), 0.3 * s + 0.85 * s * s, rtol=0, atol=1e-14)
    after = integral_at(t, v, np.array([1_500_000]))[0]
    assert after == pytest.approx(0.3 + 0.85 + 2.0 * 0.5, abs=1e-14)


def test_a_long_interval_holds_the_earlier_value_until_one_period_before_the_next():
    # 50 Hz records of 1 m/s, then none for 2 s (a writer that logs changes only), then
    # 3 m/s: 1 m/s is held until 20 ms before the new record, then linear to 3 m/s.
    t = np.concatenate([np.arange(0, 1_000_001, 20_000), [3_000_000]]).astype(np.int64)
    v = np.concatenate([np.ones(51), [3.0]])
    assert HELD_GAP * 20_000 < 2_000_000
    got = integral_at(t, v, np.array([2_000_000, 2_980_000, 3_000_000]))
    assert np.allclose(got, [2.0, 2.98, 2.98 + 0.02 * 2.0], rtol=0, atol=1e-13)


def _write(path, names_values, rate_us=20_000, n=200):
    log = RobotpyLog(str(path))
    entries = {name: log.start(name, "double", 1_000_000) for name in names_values}
    for k in range(n):
        for name, f in names_values.items():
            log.double(entries[name], float(f(k)), 1_000_000 + k * rate_us)
    log.close()
    return path


def _corner_log(tmp_path, labels):
    """Modules named ``labels`` driving straight ahead at 1 m/s, distances in m."""
    cols = {}
    for lb in labels:
        cols[f"/Robot/{lb} Swerve/{lb} Drive"] = lambda k: 0.02 * k
        cols[f"/Robot/{lb} Swerve/{lb} Angle"] = lambda k: 0.0
    cols["/Robot/Gyro Degrees"] = lambda k: 0.0
    return _write(tmp_path / "corners.wpilog", cols)


@pytest.mark.parametrize("labels", [("Left Front", "Right Front", "Left Back", "Right Back"),
                                    ("1", "2", "3", "4")])
def test_module_entries_with_a_placeholder_find_and_order_the_modules(tmp_path, labels):
    path = _corner_log(tmp_path, labels[::-1])       # written in reverse order
    cfg = replay.ReplayConfig(moduleEntries=["/Robot/{module} Swerve/{module} Drive,"
                                             "/Robot/{module} Swerve/{module} Angle"],
                              driveUnits="m", turnUnits="deg", gyroUnits="deg",
                              trackwidth=0.5, wheelbase=0.6)
    r = replay.replayLog(path, cfg)
    assert "(" + ", ".join(labels) + ")" in r.why["positions"]
    assert r.poses[-1, 0] == pytest.approx(0.02 * 199, abs=1e-12)
    assert abs(r.poses[-1, 1]) < 1e-12


def test_module_entries_name_form_keeps_the_order_given(tmp_path):
    path = _corner_log(tmp_path, ("a", "b", "c", "d"))
    specs = [f"{lb}=/Robot/{lb} Swerve/{lb} Drive,/Robot/{lb} Swerve/{lb} Angle"
             for lb in ("d", "c", "b", "a")]
    r = replay.replayLog(path, replay.ReplayConfig(
        moduleEntries=specs, driveUnits="m", turnUnits="deg", gyroUnits="deg",
        trackwidth=0.5, wheelbase=0.6))
    assert "(d, c, b, a)" in r.why["positions"]
    assert r.entries["positions"]


def test_module_entries_that_name_no_corner_ask_for_the_name_form(tmp_path):
    path = _corner_log(tmp_path, ("a", "b", "c", "d"))
    with pytest.raises(datalog.DataLogError, match="NAME=DRIVE,ANGLE"):
        replay.replayLog(path, replay.ReplayConfig(
            moduleEntries=["/Robot/{module} Swerve/{module} Drive,"
                           "/Robot/{module} Swerve/{module} Angle"],
            driveUnits="m", turnUnits="deg", gyroUnits="deg"))


@pytest.mark.parametrize("spec, message", [
    ("FL=/Robot/a Swerve/a Drive", "expected NAME=DRIVE_ENTRY,ANGLE_ENTRY"),
    ("FL=/Robot/nope,/Robot/a Swerve/a Angle", "no such entry"),
])
def test_malformed_module_entries_say_what_was_expected(tmp_path, spec, message):
    path = _corner_log(tmp_path, ("a", "b", "c", "d"))
    with pytest.raises(datalog.DataLogError, match=message):
        replay.replayLog(path, replay.ReplayConfig(moduleEntries=[spec, spec]))


def test_velocity_entries_named_feet_are_integrated_in_feet_per_second(tmp_path):
    labels = ("Module 1", "Module 2", "Module 3", "Module 4")
    cols = {}
    for lb in labels:
        cols[f"/SmartDashboard/{lb}/Drive Velocity Feet"] = lambda k: 1.0 / 0.3048
        cols[f"/SmartDashboard/{lb}/Steer Degrees"] = lambda k: 0.0
    cols["/Gyro/YawDeg"] = lambda k: 0.0
    path = _write(tmp_path / "feet.wpilog", cols)
    r = replay.replayLog(path, replay.ReplayConfig(trackwidth=0.5, wheelbase=0.5))
    assert r.entries["positions"].startswith("/SmartDashboard/")
    assert any("integrated from velocity states" in n for n in r.notes)
    # 1 m/s for 199 record intervals of 20 ms
    assert r.poses[-1, 0] == pytest.approx(199 * 0.02, abs=1e-12)


def test_positions_naming_a_folder_no_layout_reads_points_to_module_entries(tmp_path):
    path = _corner_log(tmp_path, ("a", "b", "c", "d"))
    with pytest.raises(datalog.DataLogError, match="folder of 9 entries.*--module-entries"):
        replay.replayLog(path, replay.ReplayConfig(positions="/Robot"))


def test_columns_are_integrated_as_each_alone():
    rng = np.random.default_rng(3)
    t = np.cumsum(rng.integers(5_000, 30_000, 300)).astype(np.int64)
    t[150:] += 2_000_000                               # a gap the held rule applies to
    v = rng.normal(size=(300, 4))
    q = np.sort(rng.integers(int(t[0]), int(t[-1]) + 500_000, 500))
    both = integral_at(t, v, q)
    for k in range(4):
        assert np.array_equal(both[:, k], integral_at(t, v[:, k], q))
