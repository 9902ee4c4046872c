"""drivekin.choreo.load on the real trajectories: the properties say what the file says.

Pinned, against the file read with the json module in the test: ``config`` carries the
embedded robot (mass, MOI, wheel radius, μ, module positions in Choreo's force order FL,
BL, BR, FR, or left/right at ±track/2), ``maxDriveVelocityMPS = radius · vmax / gearing``,
and the chosen drive motor's low-speed wheel torque ``min(stallTorque,
getTorque(limit))`` equals Choreo's ``tmax · gearing``, its free speed vmax / 0.8;
``samples`` is read-only and ``times``/``columns``/``moduleOrder``/``totalTime`` agree
with the file; events are kept and dropped as choreolib's ``load_event_marker`` keeps and
drops them. Trajectories and samples pickle to equal values."""
from __future__ import annotations

import json
import pickle

import numpy as np
import pytest

from drivekin import choreo
from tests._support.choreo_files import CURRENT, params


@pytest.mark.parametrize("path", params(CURRENT))
def test_properties_say_what_the_file_says(path):
    doc = json.loads(path.read_text(encoding="utf-8"))
    traj = choreo.load(path)
    raw = doc["trajectory"]["samples"]
    assert traj.kind == doc["trajectory"]["sampleType"].lower()
    assert traj.samples.shape == (len(raw), len(traj.columns))
    assert not traj.samples.flags.writeable
    with pytest.raises(ValueError):
        traj.samples[0, 0] = 1.0
    for j, c in enumerate(traj.columns):
        if c[:2] in ("fx", "fy") and traj.kind == "swerve":
            want = [s[c[:2]][int(c[2])] for s in raw]
        else:
            want = [s[c] for s in raw]
        assert np.array_equal(traj.samples[:, j], want), c
    assert np.array_equal(traj.times, [s["t"] for s in raw])
    assert traj.totalTime == raw[-1]["t"]
    assert traj.moduleOrder == (("FL", "BL", "BR", "FR") if traj.kind == "swerve"
                                else ("left", "right"))


@pytest.mark.parametrize("path", params(CURRENT))
def test_config_is_the_embedded_robot(path):
    c = json.loads(path.read_text(encoding="utf-8"))["trajectory"]["config"]
    config = choreo.load(path).config
    module = config.moduleConfig
    assert config.massKG == c["mass"] and config.MOI == c["inertia"]
    assert module.wheelRadiusMeters == c["radius"] and module.wheelCOF == c["cof"]
    assert module.maxDriveVelocityMPS == pytest.approx(c["radius"] * c["vmax"] / c["gearing"],
                                                       rel=1e-15)
    motor = module.driveMotor
    low_speed = min(motor.stallTorque, motor.getTorque(module.driveCurrentLimit))
    assert low_speed == pytest.approx(c["tmax"] * c["gearing"], rel=1e-12)
    # Choreo's "Motor Max Speed" is about 80 % of the free speed (the wheel's, geared)
    assert motor.freeSpeed == pytest.approx(c["vmax"] / 0.8 / c["gearing"], rel=1e-12)
    where = [(t.getX(), t.getY()) for t in config.moduleLocations]
    if len(where) == 4:
        fl, bl = c["frontLeft"], c["backLeft"]
        assert where == [(fl["x"], fl["y"]), (bl["x"], bl["y"]), (bl["x"], -bl["y"]),
                         (fl["x"], -fl["y"])]
    else:
        half = c["differentialTrackWidth"] / 2
        assert where == [(0.0, half), (0.0, -half)]


def _event(name, target, offset):
    return {"name": name, "from": {"target": 0, "targetTimestamp": target,
                                   "offset": {"exp": "", "val": offset}}, "event": None}


EVENTS = [_event("kept", 1.0, 0.25), _event("shifted", 1.0, -1.0), _event("early", 0.5, -1.0),
          _event("", 1.0, 0.0), _event(None, 1.0, 0.0), _event(3, 1.0, 0.0),
          _event("untimed", None, 0.0), _event("unoffset", 1.0, None), _event("last", 2, 0)]


def test_events_follow_choreolib(tmp_path):
    # choreolib's own rule is the oracle.
    load_event_marker = pytest.importorskip("choreo.trajectory").load_event_marker
    doc = {"name": "events", "version": 3, "events": EVENTS, "trajectory": {
        "config": None, "sampleType": "Differential", "splits": [], "samples": [
            {"t": t, "x": 0.0, "y": 0.0, "heading": 0.0, "vl": 0.0, "vr": 0.0,
             "omega": 0.0, "al": 0.0, "ar": 0.0, "alpha": 0.0, "fl": 0.0, "fr": 0.0}
            for t in (0.0, 1.0)]}}
    path = tmp_path / "events.traj"
    path.write_text(json.dumps(doc))
    traj = choreo.load(path)
    want = [(m.timestamp, m.event) for m in map(load_event_marker, EVENTS) if m is not None]
    assert traj.events == want == [(1.25, "kept"), (0.0, "shifted"), (2.0, "last")]
    assert traj.splits == (0,)                 # choreolib puts 0 first when it is missing


@pytest.mark.parametrize("path", params(CURRENT))
def test_a_trajectory_and_its_samples_pickle(path):
    traj = choreo.load(path)
    back = pickle.loads(pickle.dumps(traj))
    assert type(back) is choreo.ChoreoTrajectory
    assert np.array_equal(back.samples, traj.samples) and not back.samples.flags.writeable
    assert (back.name, back.kind, back.events, back.splits) == (
        traj.name, traj.kind, traj.events, traj.splits)
    if traj.config is not None:
        assert back.check().margins == traj.check().margins
    t = 0.37 * traj.totalTime
    assert np.array_equal(back.sampleAtMany([t], True), traj.sampleAtMany([t], True))
    sample = traj.sampleAt(t, True)
    copy = pickle.loads(pickle.dumps(sample))
    assert type(copy) is type(sample)
    assert repr(copy) == repr(sample) and copy.getPose() == sample.getPose()
    fields = ("alpha", "fx", "fy") if traj.kind == "swerve" else ("alpha", "fl", "fr")
    assert all(getattr(copy, f) == getattr(sample, f) for f in fields)
