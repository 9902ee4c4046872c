"""SwerveDriveKinematics.desaturatedDiscretize: discretize(k·v, dt) for the largest k in
[0, 1] that keeps every module within the limit. Checked through robotpy-wpimath's own
kinematics and exp (independent of drivekin's), for 2, 3, 4 and 6 modules:

* within the limit: no module of the result is faster than the limit;
* k maximal: when saturated, the fastest module is exactly at the limit;
* zero skew: held for dt, the result moves the robot along the commanded direction
  (exp(result·dt) ends on the line through (vx, vy)) and turns it by k·ω·dt.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from drivekin import ChassisVelocities, SwerveDriveKinematics, Translation2d, batch

wpimath = pytest.importorskip("wpimath")
from wpimath import geometry as wg, kinematics as wk                  # noqa: E402

KINEMATICS = {2: wk.SwerveDrive2Kinematics, 3: wk.SwerveDrive3Kinematics,
              4: wk.SwerveDrive4Kinematics, 6: wk.SwerveDrive6Kinematics}
coord = st.floats(-0.6, 0.6).filter(lambda v: abs(v) > 0.05)


@st.composite
def cases(draw):
    n = draw(st.sampled_from(sorted(KINEMATICS)))
    mods = [(draw(coord), draw(coord)) for _ in range(n)]
    if n == 2:
        mods[1] = (-mods[0][0], -mods[0][1])        # a pair either side of the centre
    v = (draw(st.floats(-6, 6)), draw(st.floats(-6, 6)), draw(st.floats(-12, 12)))
    dt = draw(st.sampled_from([0.005, 0.01, 0.02, 0.05]))
    limit = draw(st.floats(0.5, 6.0))
    return mods, v, dt, limit


def _peer(mods):
    return KINEMATICS[len(mods)](*[wg.Translation2d(x, y) for x, y in mods])


def _top(peer, r):
    states = peer.toSwerveModuleStates(wk.ChassisSpeeds(r.vx, r.vy, r.omega))
    return max(abs(s.speed) for s in states)


@given(cases())
def test_within_the_limit_and_k_maximal(case):
    mods, v, dt, limit = case
    kin = SwerveDriveKinematics(*[Translation2d(x, y) for x, y in mods])
    r = kin.desaturatedDiscretize(ChassisVelocities(*v), dt, limit)
    peer = _peer(mods)
    top = _top(peer, r)
    assert top <= limit * (1 + 1e-12) + 1e-12
    plain = wk.ChassisSpeeds.discretize(wk.ChassisSpeeds(*v), dt)
    if max(abs(s.speed) for s in peer.toSwerveModuleStates(plain)) > limit:
        assert top == pytest.approx(limit, rel=1e-9)       # the constraint is active
    else:                                                   # unsaturated: plain discretize
        assert (r.vx, r.vy, r.omega) == pytest.approx((plain.vx, plain.vy, plain.omega),
                                                      rel=1e-9, abs=1e-12)


@given(cases())
def test_no_skew(case):
    mods, v, dt, limit = case
    kin = SwerveDriveKinematics(*[Translation2d(x, y) for x, y in mods])
    r = kin.desaturatedDiscretize(ChassisVelocities(*v), dt, limit)
    end = wg.Pose2d().exp(wg.Twist2d(r.vx * dt, r.vy * dt, r.omega * dt))
    speed = math.hypot(v[0], v[1])
    moved = math.hypot(end.x, end.y)
    if speed > 1e-9 and moved > 1e-12:
        cross = (v[0] * end.y - v[1] * end.x) / (speed * moved)
        assert abs(cross) < 1e-9                  # on the commanded line...
        assert v[0] * end.x + v[1] * end.y > 0    # ...and forwards
        k = moved / (speed * dt)
        turn = end.rotation().radians()
        assert math.remainder(turn - k * v[2] * dt, 2 * math.pi) == pytest.approx(0.0, abs=1e-9)


def test_the_issues_example():
    # Modules at (±0.27, ±0.27) m, (4 m/s, 0, 2π rad/s), dt 0.02 s, limit 4 m/s.
    mods = [(0.27, 0.27), (0.27, -0.27), (-0.27, 0.27), (-0.27, -0.27)]
    kin = SwerveDriveKinematics(*[Translation2d(x, y) for x, y in mods])
    r = kin.desaturatedDiscretize(ChassisVelocities(4.0, 0.0, 2 * math.pi), 0.02, 4.0)
    assert r.omega / (2 * math.pi) == pytest.approx(0.6676, abs=5e-5)   # k
    assert _top(_peer(mods), r) == pytest.approx(4.0, rel=1e-12)
    # Desaturating after discretizing (robotpy) turns the direction of travel by
    # (k - 1)·ω·dt/2 = -1.2°; the scaled discretize keeps it.
    peer = _peer(mods)
    d = wk.ChassisSpeeds.discretize(wk.ChassisSpeeds(4.0, 0.0, 2 * math.pi), 0.02)
    states = peer.desaturateWheelSpeeds(peer.toSwerveModuleStates(d), 4.0)
    after = peer.toChassisSpeeds(states)
    end = wg.Pose2d().exp(wg.Twist2d(after.vx * 0.02, after.vy * 0.02, after.omega * 0.02))
    assert math.degrees(math.atan2(end.y, end.x)) == pytest.approx(-1.2, abs=0.05)
    mine = wg.Pose2d().exp(wg.Twist2d(r.vx * 0.02, r.vy * 0.02, r.omega * 0.02))
    assert abs(math.atan2(mine.y, mine.x)) < 1e-12


def test_batch_gives_the_per_call_bits():
    rng = np.random.default_rng(7)
    mods = [(0.3, 0.25), (0.3, -0.25), (-0.3, 0.25), (-0.3, -0.25), (0.0, 0.4)]
    kin = SwerveDriveKinematics(*[Translation2d(x, y) for x, y in mods])
    v = rng.uniform(-6, 6, (500, 3))
    dts = rng.uniform(0.005, 0.05, 500)
    got = batch.desaturatedDiscretize(kin, v, dts, 3.5)
    want = [kin.desaturatedDiscretize(ChassisVelocities(*row), float(t), 3.5)
            for row, t in zip(v, dts)]
    assert got.tobytes() == np.array([[w.vx, w.vy, w.omega] for w in want]).tobytes()
    one = batch.desaturatedDiscretize(kin, v[0], 0.02, 3.5)
    w = kin.desaturatedDiscretize(ChassisVelocities(*v[0]), 0.02, 3.5)
    assert one.tolist() == [w.vx, w.vy, w.omega]


@pytest.mark.parametrize("args, message", [
    ((ChassisVelocities(math.nan, 0, 0), 0.02, 4.0), "the chassis velocities must be finite"),
    ((ChassisVelocities(1, 0, 0), 0.0, 4.0), "dt must be a finite number of seconds > 0"),
    ((ChassisVelocities(1, 0, 0), math.nan, 4.0), "dt must be"),
    ((ChassisVelocities(1, 0, 0), 0.02, -1.0), "the module velocity limit must be >= 0"),
    ((ChassisVelocities(1, 0, 0), 0.02, math.nan), "the module velocity limit must be"),
])
def test_bad_input_is_refused_and_changes_nothing(args, message):
    kin = SwerveDriveKinematics(Translation2d(0.3, 0.3), Translation2d(-0.3, -0.3))
    out = ChassisVelocities(7.0, 8.0, 9.0)
    with pytest.raises(ValueError, match=message):
        kin.desaturatedDiscretize(*args)
    with pytest.raises(ValueError, match=message):
        kin.desaturatedDiscretizeInto(*args, out)
    assert (out.vx, out.vy, out.omega) == (7.0, 8.0, 9.0)
    # The bad sample is the second one (a bad dt or limit already fails the first).
    first = 1 if "chassis velocities" in message else 0
    buf = np.full((2, 3), 5.0)
    with pytest.raises(ValueError, match=f"sample {first}: " + message):
        batch.desaturatedDiscretize(kin, np.array([[0.0, 0.0, 0.0],
                                                   [args[0].vx, args[0].vy, args[0].omega]]),
                                    args[1], args[2], out=buf)
    assert (buf == 5.0).all()


def test_zero_and_infinite_limits():
    kin = SwerveDriveKinematics(Translation2d(0.3, 0.3), Translation2d(-0.3, -0.3))
    cv = ChassisVelocities(2.0, 1.0, 3.0)
    z = kin.desaturatedDiscretize(cv, 0.02, 0.0)
    assert (z.vx, z.vy, z.omega) == (0.0, 0.0, 0.0)
    assert kin.desaturatedDiscretize(cv, 0.02, math.inf) == cv.discretize(0.02)
