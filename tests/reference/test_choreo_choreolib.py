"""drivekin.choreo against choreolib Python 2026.0.3 (PyPI sleipnirgroup-choreolib), the
library teams sample Choreo trajectories with, on every real trajectory beside the
repository (tests/_support/choreo_files.py), blue and red.

Pinned: load reads exactly the values choreolib reads (samples, splits, events, name);
sampleAt, sampleInto and every row of sampleAtMany equal choreolib's sample_at within 1e-9
(heading modulo 2π) at sample times (integrated from the previous sample by choreolib's
rule), between samples, before the start and after the end, unflipped and flipped for the
red alliance, the differential adaptive integrator included; getPose and
getChassisVelocities equal choreolib's get_pose and get_chassis_speeds; initial and final
poses agree; the files choreolib refuses (schema versions before 3) drivekin refuses too.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

choreolib = pytest.importorskip("choreo")

from drivekin import choreo  # noqa: E402
from tests._support.choreo_files import CURRENT, LEGACY, params  # noqa: E402

TOL = 1e-9


def _reference(path):
    text = path.read_text(encoding="utf-8")
    kind = choreo.load(path).kind
    loader = (choreolib.load_swerve_trajectory_string if kind == "swerve"
              else choreolib.load_differential_trajectory_string)
    return loader(text)


def _row(s, kind):
    """A choreolib sample as a row in drivekin's column order."""
    head = [s.timestamp, s.x, s.y, s.heading]
    if kind == "swerve":
        return head + [s.vx, s.vy, s.omega, s.ax, s.ay, s.alpha, *s.fx, *s.fy]
    return head + [s.vl, s.vr, s.omega, s.al, s.ar, s.alpha, s.fl, s.fr]


def _fields(s, kind):
    """A drivekin sample's fields in column order."""
    head = [s.t, s.x, s.y, s.heading]
    if kind == "swerve":
        return head + [s.vx, s.vy, s.omega, s.ax, s.ay, s.alpha, *s.fx, *s.fy]
    return head + [s.vl, s.vr, s.omega, s.al, s.ar, s.alpha, s.fl, s.fr]


def _pose(p):
    return [0.0, p.getX(), p.getY(), p.getRotation().getRadians()]


def _ref_pose(p):
    return [0.0, p.X(), p.Y(), p.rotation().radians()]


def _assert_close(got, want, what):
    got, want = np.asarray(got, dtype=float), np.asarray(want, dtype=float)
    diff = np.abs(got - want)
    diff[3] = abs(math.remainder(got[3] - want[3], 2 * math.pi))
    k = int(np.argmax(diff))
    assert diff[k] <= TOL, f"{what}: column {k} is {got[k]!r}, choreolib {want[k]!r}"


def _times(t):
    """A small set: the first, second and last sample times exactly, points between
    samples spread over the trajectory, before the start and after the end."""
    n = len(t)
    picks = sorted({1, 2, n // 3, n // 2, (2 * n) // 3, n - 1} & set(range(1, n)))
    fractions = (0.5, 0.13, 0.77, 0.5, 0.31, 0.99)
    between = [t[k - 1] + f * (t[k] - t[k - 1]) for k, f in zip(picks, fractions)]
    exact = [t[0], t[1] if n > 1 else t[0], t[n // 2], t[-1]]
    return [float(x) for x in exact + between + [t[0] - 0.5, t[-1] + 0.02, t[-1] + 100.0]]


@pytest.mark.parametrize("path", params(CURRENT))
def test_load_reads_what_choreolib_reads(path):
    traj, ref = choreo.load(path), _reference(path)
    assert traj.name == ref.name
    assert np.array_equal(traj.samples, [_row(s, traj.kind) for s in ref.samples])
    assert list(traj.splits) == ref.splits
    assert traj.events == [(e.timestamp, e.event) for e in ref.events]
    assert traj.totalTime == ref.get_total_time()
    for flip in (False, True):
        for mine, theirs in ((traj.getInitialPose(flip), ref.get_initial_pose(flip)),
                             (traj.getFinalPose(flip), ref.get_final_pose(flip))):
            _assert_close(_pose(mine),
                          _ref_pose(theirs), "pose")


@pytest.mark.parametrize("flip", [False, True], ids=["blue", "red"])
@pytest.mark.parametrize("path", params(CURRENT))
def test_sample_at_matches_choreolib(path, flip):
    traj, ref = choreo.load(path), _reference(path)
    times = _times(traj.times)
    rows = traj.sampleAtMany(times, flip)
    out = traj.newSample()
    for j, t in enumerate(times):
        want = ref.sample_at(t, flip)
        expected = _row(want, traj.kind)
        s = traj.sampleAt(t, flip)
        _assert_close(_fields(s, traj.kind), expected, f"sampleAt({t!r}, {flip})")
        _assert_close(rows[j], expected, f"sampleAtMany row {j} (t = {t!r})")
        assert _fields(traj.sampleInto(t, out, flip), traj.kind) == _fields(s, traj.kind)
        pose, ref_pose = s.getPose(), want.get_pose()
        _assert_close(_pose(pose),
                      _ref_pose(ref_pose), "getPose")
        v, ref_v = s.getChassisVelocities(), want.get_chassis_speeds()
        _assert_close([v.vx, v.vy, 0.0, 0.0, v.omega],
                      [ref_v.vx, ref_v.vy, 0.0, 0.0, ref_v.omega], "getChassisVelocities")


@pytest.mark.parametrize("path", params(LEGACY))
def test_older_schema_versions_are_refused_as_choreolib_refuses_them(path):
    with pytest.raises(ValueError, match="Wrong version"):
        choreolib.load_swerve_trajectory_string(path.read_text(encoding="utf-8"))
    with pytest.raises(choreo.ChoreoError, match="schema version"):
        choreo.load(path)
