"""Allocation tests for Choreo trajectory sampling (drivekin.choreo).

``sampleInto`` (the robot loop's form) makes no allocator calls, swerve and differential
(its adaptive integrator), blue and red, between samples, on a sample time and past the
end; ``sampleAt`` neither when its result is dropped each cycle (the sample comes from
its class's freelist)."""
from __future__ import annotations

import itertools
import json

import pytest

from drivekin import choreo
from tests._support.alloc import assert_no_allocations


def _write(tmp_path, kind):
    if kind == "swerve":
        rows = [{"t": 0.1 * k, "x": 0.1 * k, "y": 1.0, "heading": 0.2 * k, "vx": 1.0,
                 "vy": 0.5, "omega": 2.0, "ax": 0.5, "ay": 0.0, "alpha": 1.0,
                 "fx": [1.0, 2.0, 3.0, 4.0], "fy": [4.0, 3.0, 2.0, 1.0]} for k in range(5)]
    else:
        rows = [{"t": 0.1 * k, "x": 0.1 * k, "y": 1.0, "heading": 0.2 * k, "vl": 1.0,
                 "vr": 1.4, "omega": 2.0, "al": 0.5, "ar": 0.2, "alpha": 1.0, "fl": 10.0,
                 "fr": 12.0} for k in range(5)]
    doc = {"name": kind, "version": 3, "events": [],
           "trajectory": {"config": None, "sampleType": kind.capitalize(), "samples": rows,
                          "splits": [0]}}
    path = tmp_path / f"{kind}.traj"
    path.write_text(json.dumps(doc))
    return choreo.load(path)


TIMES = [0.05, 0.1, 0.2371, 0.399, 1.0, -1.0]


@pytest.mark.parametrize("flip", [False, True], ids=["blue", "red"])
@pytest.mark.parametrize("kind", ["swerve", "differential"])
def test_sample_into_is_allocation_free(tmp_path, kind, flip):
    traj = _write(tmp_path, kind)
    out = traj.newSample()
    times = itertools.cycle(TIMES)

    def loop(it):
        for _ in it:
            traj.sampleInto(next(times), out, flip)

    assert_no_allocations(loop, f"{kind} sampleInto (flip={flip})")


@pytest.mark.parametrize("kind", ["swerve", "differential"])
def test_sample_at_draws_from_the_freelist(tmp_path, kind):
    traj = _write(tmp_path, kind)
    times = itertools.cycle(TIMES)

    def loop(it):
        for _ in it:
            traj.sampleAt(next(times))

    assert_no_allocations(loop, f"{kind} sampleAt")
