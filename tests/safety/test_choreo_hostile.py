"""drivekin.choreo.load against hostile and damaged ``.traj`` files: every one is refused
with a one-line ChoreoError (a ValueError) naming the file and the fault, in bounded
time and memory; nothing crashes, recurses without bound or raises another exception.
Sampling a trajectory whose values no robot has (the differential integrator's step
shrinking towards zero) is refused too, in bounded time, and a sampling call that fails
leaves ``sampleInto``'s output untouched. Forged pickles of samples and trajectories are
refused before anything is built."""
from __future__ import annotations

import copy
import json
import math
import time
import tracemalloc

import pytest

from drivekin import choreo
from drivekin._core import choreokernel


def _swerve_sample(t, x=0.0):
    return {"t": t, "x": x, "y": 1.0, "heading": 0.0, "vx": 1.0, "vy": 0.0, "omega": 0.0,
            "ax": 0.0, "ay": 0.0, "alpha": 0.0, "fx": [0.0, 0.0, 0.0, 0.0],
            "fy": [0.0, 0.0, 0.0, 0.0]}


def _valid():
    """A small valid schema-3 swerve trajectory (1 m/s along x for 0.2 s)."""
    return {
        "name": "hostile", "version": 3, "snapshot": None, "params": {},
        "trajectory": {
            "config": {"frontLeft": {"x": 0.3, "y": 0.3}, "backLeft": {"x": -0.3, "y": 0.3},
                       "mass": 60.0, "inertia": 6.0, "gearing": 6.5, "radius": 0.0508,
                       "vmax": 600.0, "tmax": 1.2, "cof": 1.5,
                       "bumper": {"front": 0.4, "side": 0.4, "back": 0.4},
                       "differentialTrackWidth": 0.6},
            "sampleType": "Swerve", "waypoints": [0.0, 0.2],
            "samples": [_swerve_sample(0.1 * k, 0.1 * k) for k in range(3)],
            "splits": [0]},
        "events": [{"name": "go", "from": {"target": 0, "targetTimestamp": 0.0,
                                           "offset": {"exp": "0 s", "val": 0.1}},
                    "event": None}],
    }


def _edit(change):
    def make():
        doc = copy.deepcopy(_valid())
        change(doc)
        return json.dumps(doc, allow_nan=True).encode()
    return make


def _set(path, value):
    def change(doc):
        *keys, last = path
        target = doc
        for k in keys:
            target = target[k]
        target[last] = value
    return _edit(change)


def _delete(path):
    def change(doc):
        *keys, last = path
        target = doc
        for k in keys:
            target = target[k]
        del target[last]
    return _edit(change)


S = ("trajectory", "samples")
HOSTILE = {
    "empty file": (lambda: b"", "not valid JSON"),
    "truncated": (lambda: json.dumps(_valid()).encode()[:300], "not valid JSON"),
    "not UTF-8": (lambda: b'{"name": "\xff\xfe"}', "not UTF-8"),
    "top level array": (lambda: b"[1, 2, 3]", "top level must be a JSON object"),
    "deep nesting": (lambda: b'{"a": ' + b"[" * 200_000 + b"]" * 200_000 + b"}",
                     "nested deeper"),
    "deep unbalanced": (lambda: b"[" * 1_000_000, "nested deeper"),
    "NaN literal": (_set(S + (1, "x"), math.nan), "not valid JSON"),
    "Infinity literal": (_set(S + (1, "vx"), math.inf), "not valid JSON"),
    "overflowing number": (lambda: _valid_text().replace(b'"x": 0.1', b'"x": 1e999'),
                           "finite"),
    "huge integer": (lambda: _valid_text().replace(b'"x": 0.1', b'"x": ' + b"9" * 400),
                     "finite"),
    "too many digits": (lambda: _valid_text().replace(b'"x": 0.1', b'"x": ' + b"9" * 5000),
                        "not valid JSON"),
    "version as string": (_set(("version",), "3"), "schema version '3'"),
    "version 2": (_set(("version",), 2), "schema version 2"),
    "version missing": (_delete(("version",)), "no 'version'"),
    "name not a string": (_set(("name",), 7), "name must be a string"),
    "trajectory missing": (_delete(("trajectory",)), "no 'trajectory'"),
    "trajectory an array": (_set(("trajectory",), []), "must be a JSON object"),
    "sampleType unknown": (_set(("trajectory", "sampleType"), "Tank"), "sampleType"),
    "samples an object": (_set(S, {}), "samples must be an array"),
    "samples empty": (_set(S, []), "samples is empty"),
    "sample a number": (_set(S + (1,), 3.0), r"samples\[1\] must be an object"),
    "sample key missing": (_delete(S + (1, "omega")), r"samples\[1\] has no 'omega'"),
    "time a string": (_set(S + (1, "t"), "0.1"), r"samples\[1\].t must be a finite"),
    "value a boolean": (_set(S + (1, "vy"), True), r"samples\[1\].vy must be a finite"),
    "value null": (_set(S + (2, "alpha"), None), r"samples\[2\].alpha must be a finite"),
    "three forces": (_set(S + (0, "fx"), [1.0, 2.0, 3.0]), "array of 4 module forces"),
    "force a string": (_set(S + (0, "fy"), [1.0, "2", 3.0, 4.0]), r"fy\[1\]"),
    "times repeat": (_set(S + (1, "t"), 0.0), "sample times must increase"),
    "times go back": (_set(S + (2, "t"), 0.05), "sample times must increase"),
    "split out of range": (_set(("trajectory", "splits"), [0, 3]), "splits"),
    "split negative": (_set(("trajectory", "splits"), [-1]), "splits"),
    "splits an object": (_set(("trajectory", "splits"), {"0": 0}), "splits must be an array"),
    "events missing": (_delete(("events",)), "no 'events'"),
    "event without from": (_delete(("events", 0, "from")), r"events\[0\] has no 'from'"),
    "event offset a string": (_set(("events", 0, "from", "offset", "val"), "1"),
                              "offset.val must be a finite number or null"),
    "config mass negative": (_set(("trajectory", "config", "mass"), -60.0),
                             "config.mass must be positive"),
    "config gearing missing": (_delete(("trajectory", "config", "gearing")), "no 'gearing'"),
    "config torque enormous": (_set(("trajectory", "config", "tmax"), 1e300),
                               "not a usable robot"),
    "config mass enormous": (_set(("trajectory", "config", "mass"), 1e200),
                             "not a usable robot"),
    "config module at centre": (_set(("trajectory", "config", "frontLeft"), {"x": 0, "y": 0}),
                                "not a usable robot"),
}


def _valid_text():
    return json.dumps(_valid()).encode()


@pytest.mark.parametrize("name", list(HOSTILE))
def test_hostile_file_is_refused_on_one_line(tmp_path, name):
    make, pattern = HOSTILE[name]
    path = tmp_path / "hostile.traj"
    path.write_bytes(make())
    start = time.process_time()
    with pytest.raises(choreo.ChoreoError, match=pattern) as info:
        choreo.load(path)
    assert time.process_time() - start < 2.0
    message = str(info.value)
    assert "\n" not in message and message.startswith(str(path))
    assert isinstance(info.value, ValueError)


def test_the_valid_base_loads(tmp_path):
    # The cases above differ from this file in one place each: their errors are theirs.
    path = tmp_path / "valid.traj"
    path.write_bytes(_valid_text())
    traj = choreo.load(path)
    assert traj.events == [(0.1, "go")] and len(traj.samples) == 3


def test_oversized_file_is_refused_before_parsing(tmp_path):
    path = tmp_path / "huge.traj"
    with open(path, "wb") as f:
        f.truncate(choreo.MAX_BYTES + 1)          # sparse: no disk written
    start = time.process_time()
    with pytest.raises(choreo.ChoreoError, match="larger than"):
        choreo.load(path)
    assert time.process_time() - start < 1.0


def test_missing_file(tmp_path):
    with pytest.raises(choreo.ChoreoError, match="cannot be read"):
        choreo.load(tmp_path / "absent.traj")


def _differential(omega, dt):
    doc = _valid()
    doc["trajectory"]["sampleType"] = "Differential"
    doc["trajectory"]["samples"] = [
        {"t": t, "x": 0.0, "y": 0.0, "heading": 0.0, "vl": 1e3, "vr": 1e3, "omega": omega,
         "al": 0.0, "ar": 0.0, "alpha": 0.0, "fl": 0.0, "fr": 0.0} for t in (0.0, dt)]
    return doc


def test_unphysical_differential_is_refused_in_bounded_time(tmp_path):
    path = tmp_path / "spin.traj"
    path.write_text(json.dumps(_differential(1e6, 1e6)))
    traj = choreo.load(path)
    out = traj.newSample()
    before = (out.t, out.x, out.heading)
    start = time.process_time()
    for call in (lambda: traj.sampleAt(5e5), lambda: traj.sampleInto(5e5, out),
                 lambda: traj.sampleAtMany([0.0, 5e5])):
        with pytest.raises(ValueError, match="differential integrator"):
            call()
    assert time.process_time() - start < 5.0
    assert (out.t, out.x, out.heading) == before


def test_nan_time_is_refused(tmp_path):
    path = tmp_path / "valid.traj"
    path.write_bytes(_valid_text())
    traj = choreo.load(path)
    with pytest.raises(ValueError, match="nan"):
        traj.sampleAt(math.nan)
    with pytest.raises(ValueError, match="nan"):
        traj.sampleAtMany([0.0, math.nan])
    with pytest.raises(TypeError, match="SwerveSample"):
        traj.sampleInto(0.1, object())


def test_the_densest_file_under_the_cap_stays_in_bounded_memory(tmp_path, monkeypatch):
    # The most Python objects per byte JSON allows: one float per 4 bytes. Memory grows
    # with the size, so a 1 MiB cap (time under tracemalloc: 8 MiB takes 3 s) shows it.
    monkeypatch.setattr(choreo, "MAX_BYTES", 1 << 20)
    path = tmp_path / "dense.traj"
    count = (choreo.MAX_BYTES - 2) // 4
    path.write_text("[" + "0.5," * (count - 1) + "0.5]")
    tracemalloc.start()
    try:
        with pytest.raises(choreo.ChoreoError, match="must be a JSON object"):
            choreo.load(path)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 12 * choreo.MAX_BYTES


@pytest.mark.parametrize("swerve, values, error", [
    (True, (1.0,) * 12, ValueError),           # a differential's width for a swerve sample
    (False, [0.5] * 12, ValueError),           # a list, not the tuple a pickle holds
    (True, ("0.5",) * 18, TypeError),
    (False, (None,) * 12, TypeError),
    (True, None, ValueError),
])
def test_a_forged_pickled_sample_is_refused(swerve, values, error):
    with pytest.raises(error):
        choreokernel._sample_from_values(swerve, values)


@pytest.mark.parametrize("damage, message", [
    (lambda rows: rows.__setitem__((2, 5), math.nan), "not finite"),
    (lambda rows: rows.__setitem__((1, 0), math.inf), "not finite"),
    (lambda rows: rows.__setitem__((2, 0), rows[0, 0]), "times must increase"),
])
def test_a_forged_pickled_trajectory_is_refused(tmp_path, damage, message):
    path = tmp_path / "valid.traj"
    path.write_bytes(_valid_text())
    func, args = choreo.load(path).__reduce__()
    rows = args[2].copy()
    damage(rows)
    with pytest.raises(ValueError, match=message):
        func(*args[:2], rows, *args[3:])
