"""Pose estimators against the worked sequences of
/work/shared/reference/followers-and-estimators.md §4 (gains, sampleAt, the timestamp
cases of addVisionMeasurement, the four resets) and the MathSharedStore clock.

The sequences drive a DifferentialDrivePoseEstimator with equal wheel distances (pure
forward motion, gyro fixed), so the odometry pose is known exactly; the estimator
machinery is shared by every drivetrain's class.
"""
import math
import tracemalloc
import warnings

import numpy as np
import pytest

from drivekin import (
    DeadWheelKinematics,
    DeadWheelPoseEstimator,
    DifferentialDrivePoseEstimator,
    DifferentialDriveWheelPositions,
    ClockMismatchWarning,
    MathSharedStore,
    Pose2d,
    Rotation2d,
    Translation2d,
)
from tests._support.wpilib_port import assert_close, assert_pose

R = Rotation2d



def estimator(state=(1.0, 1.0, 1.0), vision=(1.0, 1.0, 1.0), pose=Pose2d()):
    return DifferentialDrivePoseEstimator(R(), 0.0, 0.0, pose, state, vision)


def drive_to(e, t, x):
    """Odometry sample at time t with the robot driven to x m (heading 0)."""
    return e.updateWithTime(t, R(), x, x)


@pytest.mark.parametrize("state, vision, k", [
    (0.1, 0.9, 0.1), (1, 1, 0.5), (0.1, 0.45, 1 / 5.5), (0.02, 0.1, 1 / 6), (0.01, 0.1, 1 / 11),
    (0.2, 0.4, 1 / 3), (0.0, 5.0, 0.0), (0.3, 0.0, 1.0),
])
def test_gain(state, vision, k):
    # One sample at the origin; a vision pose 1 m ahead moves the estimate by k m.
    e = estimator((state, state, state), (vision, vision, vision))
    drive_to(e, 0.0, 0.0)
    e.addVisionMeasurement(Pose2d(1.0, 0.0, R()), 0.0)
    assert_close(k, e.getEstimatedPosition().getX(), 1e-15)


def test_estimate_exists_before_the_first_update_but_sample_does_not():
    e = estimator(pose=Pose2d(1, 2, R(0.3)))
    assert e.getEstimatedPosition() == Pose2d(1, 2, R(0.3))
    assert e.sampleAt(0.0) is None
    e.addVisionMeasurement(Pose2d(5, 5, R()), 0.0)         # no history: ignored
    assert e.getEstimatedPosition() == Pose2d(1, 2, R(0.3))


def test_sample_at_and_a_past_measurement():
    e = estimator()
    for i in range(51):
        t = 1.0 + 0.02 * i
        drive_to(e, t, t)
    assert_pose((1.02, 0, 0), e.sampleAt(1.02))
    assert_pose((1.01, 0, 0), e.sampleAt(1.01))
    assert_pose((1.0, 0, 0), e.sampleAt(0.5))
    assert_pose((2.0, 0, 0), e.sampleAt(2.5))
    e.addVisionMeasurement(Pose2d(2, 0, R(1.0)), 2.2)      # future: invisible to sampleAt
    assert_pose((1.02, 0, 0), e.sampleAt(1.02))
    assert_pose((2.0, 0, 0), e.sampleAt(2.5))
    e.addVisionMeasurement(Pose2d(1, 0.2, R()), 0.9)       # before the oldest: at 1.0
    assert_pose((1.02, 0.1, 0), e.sampleAt(1.02))
    assert_pose((1.01, 0.1, 0), e.sampleAt(1.01))
    assert_pose((1.0, 0.1, 0), e.sampleAt(1.0))
    assert_pose((2.0, 0.1, 0), e.sampleAt(2.5))


def test_resets_keep_or_drop_corrections():
    e = estimator()
    e.resetPosition(R(), 0.0, 0.0, Pose2d(1, 0, R()))
    assert_pose((2, 0, 0), e.updateWithTime(1.0, R(), 1.0, 1.0))
    e.addVisionMeasurement(Pose2d(3, 0, R()), 1.0)
    assert_pose((2.5, 0, 0), e.getEstimatedPosition())
    e.resetRotation(R.fromDegrees(90))
    assert_pose((2.5, 0, math.pi / 2), e.getEstimatedPosition())
    assert e.sampleAt(1.0) is None                          # history cleared
    assert_pose((2.5, 1, math.pi / 2), e.updateWithTime(2.0, R(), 2.0, 2.0))
    e.addVisionMeasurement(Pose2d(2.5, 1, R.fromDegrees(180)), 2.0)
    assert_pose((2.5, 1, math.radians(135)), e.getEstimatedPosition())
    e.resetTranslation(Translation2d(-1, -1))
    assert_pose((-1, -1, math.radians(135)), e.getEstimatedPosition())
    e.resetPose(Pose2d())
    assert_pose((0, 0, 0), e.getEstimatedPosition())


def test_correction_in_the_sampled_pose_frame():
    e = estimator((0.1, 0.2, 0.0), (0.1, 0.4, 1.0), Pose2d(1, 1, R.fromDegrees(90)))
    drive_to(e, 0.0, 0.0)
    e.addVisionMeasurement(Pose2d(0.5, 3, R(math.pi / 2 + 0.3)), 0.0)
    assert_pose((5 / 6, 2, math.pi / 2), e.getEstimatedPosition(), 1e-12)


@pytest.mark.parametrize("ts, used", [(2.5, True), (2.4999, False), (2.0, False),
                                      (1.25, False)])
def test_stale_measurements(ts, used):
    e = estimator()
    for i in range(17):
        drive_to(e, 0.25 * i, 0.25 * i)
    # History 1.5 s: 4.0 − 2.5 = 1.5 is dropped, so the oldest kept sample is 2.75.
    e.addVisionMeasurement(Pose2d(2.75, 1, R()), ts)
    assert_close(0.5 if used else 0.0, e.getEstimatedPosition().getY())
    if used:
        assert_pose((2.75, 0.5, 0), e.sampleAt(0.0))
        assert_pose((4.0, 0.5, 0), e.sampleAt(4.0))


def test_future_measurement_then_an_earlier_one_deletes_it():
    e = estimator()
    drive_to(e, 0.0, 0.0)
    drive_to(e, 1.0, 1.0)
    e.addVisionMeasurement(Pose2d(1, 2, R()), 5.0)
    assert_pose((1, 1, 0), e.getEstimatedPosition())
    assert_pose((1, 0, 0), e.sampleAt(1.0))
    assert_pose((1.25, 1, 0), drive_to(e, 1.25, 1.25))
    e.addVisionMeasurement(Pose2d(0.5, 0, R()), 0.5)
    assert_pose((1.25, 0, 0), e.getEstimatedPosition())
    assert_pose((1.5, 0, 0), drive_to(e, 1.5, 1.5))


def test_repeated_measurements_at_one_time_all_count():
    e = DifferentialDrivePoseEstimator(R(), 0.0, 0.0, Pose2d())   # default std devs
    drive_to(e, 0.0, 0.0)
    targets = [Pose2d(0, 0, R()), Pose2d(3, 1, R.fromDegrees(90)),
               Pose2d(2, 4, R.fromDegrees(180))]
    for _ in range(1000):
        for p in targets:
            e.addVisionMeasurement(p, 0.0)
    est = e.getEstimatedPosition()
    for p in targets:
        d = est.getTranslation().getDistance(p.getTranslation())
        a = abs(est.getRotation().minus(p.getRotation()).getDegrees())
        assert d > 0.08 or a > 0.08


def test_ignored_measurement_leaves_the_estimate_bit_for_bit():
    e = DifferentialDrivePoseEstimator(R(), 0.0, 0.0, Pose2d())
    t = 0.0
    while t < 4.0:
        e.updateWithTime(t, R(0.1 * t), t, 1.1 * t)
        t += 0.02
    before = e.getEstimatedPosition()
    e.addVisionMeasurement(Pose2d(10, 10, R(0.1)), 1.0, (0.1, 0.1, 0.1))
    after = e.getEstimatedPosition()
    assert (after.getX(), after.getY(), after.getRotation().getCos()) == \
        (before.getX(), before.getY(), before.getRotation().getCos())


def test_three_argument_form_keeps_the_std_devs_even_when_ignored():
    e = estimator()
    e.addVisionMeasurement(Pose2d(1, 0, R()), 0.0, [1.0, 1.0, 1.0])   # ignored (no history)
    drive_to(e, 0.0, 0.0)
    e.addVisionMeasurement(Pose2d(1, 0, R()), 0.0)
    assert_close(0.5, e.getEstimatedPosition().getX())
    e2 = estimator()
    e2.addVisionMeasurement(Pose2d(1, 0, R()), 0.0, np.array([0.0, 0.0, 0.0]))
    drive_to(e2, 0.0, 0.0)
    e2.addVisionMeasurement(Pose2d(1, 0, R()), 0.0)
    assert_close(1.0, e2.getEstimatedPosition().getX())


def test_wheel_positions_form_and_update_clock():
    e = estimator()
    e.update(R(), DifferentialDriveWheelPositions(0.5, 0.5))
    assert_pose((0.5, 0, 0), e.getEstimatedPosition())
    e.resetPosition(R(), DifferentialDriveWheelPositions(0.0, 0.0), Pose2d())
    assert_pose((0, 0, 0), e.getEstimatedPosition())
    times = iter([10.0, 10.5])
    MathSharedStore.setTimestampSource(lambda: next(times))
    try:
        assert MathSharedStore.getTimestamp() == 10.0
        e.update(R(), 1.0, 1.0)                      # stamped 10.5
        assert_pose((1.0, 0, 0), e.sampleAt(10.5))
    finally:
        MathSharedStore.setTimestampSource(None)
    t0 = MathSharedStore.getTimestamp()
    assert MathSharedStore.getTimestamp() >= t0


@pytest.mark.parametrize("call, exc, needle", [
    (lambda e: e.updateWithTime(math.nan, R(), 0.0, 0.0), ValueError, "finite time"),
    (lambda e: e.addVisionMeasurement(Pose2d(), math.inf), ValueError, "finite time"),
    (lambda e: e.sampleAt(math.nan), ValueError, "finite time"),
    (lambda e: e.setVisionMeasurementStdDevs([1.0, 2.0]), ValueError, "must hold 3"),
    (lambda e: e.setVisionMeasurementStdDevs([1.0, math.nan, 2.0]), ValueError, "finite"),
    (lambda e: e.setVisionMeasurementStdDevs("abc"), TypeError, "list or tuple of 3"),
    (lambda e: e.update(R(), 1.0), TypeError, "left and right distances"),
    (lambda e: MathSharedStore.setTimestampSource(3.0), TypeError, "callable"),
])
def test_bad_input(call, exc, needle):
    e = estimator()
    drive_to(e, 0.0, 0.0)
    before = e.getEstimatedPosition()
    with pytest.raises(exc) as info:
        call(e)
    assert needle in str(info.value)
    assert e.getEstimatedPosition() == before


# -- sampleAt interpolation: the odometry-step shortcut against the general form -------------
# Between two samples that the odometry appended one step apart, sampleAt reuses that step's
# twist instead of taking the log of one pose relative to the other (estimator.pyx,
# interpolate_samples). These drives mix appended, inserted and replaced samples, heading
# steps near and beyond ±π, and resets; a model of WPILib's buffer built from Pose2d.interpolate
# must agree everywhere.

def _model_sample(history, t):
    times = sorted(history)
    if t <= times[0]:
        return history[times[0]]
    if t >= times[-1]:
        return history[times[-1]]
    hi = next(i for i, s in enumerate(times) if s >= t)
    a, b = times[hi - 1], times[hi]
    if b == t:
        return history[b]
    return history[a].interpolate(history[b], (t - a) / (b - a))


def _drive_and_compare(e, steps, step, rng):
    history = {}
    for _ in range(steps):
        t, pose = step(rng)
        history = {s: p for s, p in history.items() if t - s < 1.5}
        history[t] = pose
        times = sorted(history)
        probes = list(rng.uniform(times[0] - 0.05, times[-1] + 0.05, 4)) + times
        probes += [0.5 * (a + b) for a, b in zip(times, times[1:])]
        for q in probes:
            expected = _model_sample(history, q)
            got = e.sampleAt(q)
            assert_pose((expected.getX(), expected.getY(), expected.getRotation().getRadians()),
                        got, 1e-12)


@pytest.mark.parametrize("seed", range(6))
def test_sample_interpolation_with_appended_inserted_and_replaced_samples(seed):
    rng = np.random.default_rng(seed)
    e = estimator()
    state = {"t": 1.0, "l": 0.0, "r": 0.0, "gyro": 0.0}

    def step(rng):
        kind = rng.choice(["append", "append", "insert", "replace", "spin"])
        if kind == "append":
            state["t"] += rng.uniform(0.005, 0.04)
            t = state["t"]
        elif kind == "insert":
            t = state["t"] - rng.uniform(0.0, 0.3)
        elif kind == "replace":
            t = state["t"]
        else:                                   # heading steps of 2.9 .. 3.14 rad
            state["t"] += 0.02
            t = state["t"]
            state["gyro"] += rng.choice([-1, 1]) * rng.uniform(2.9, math.pi)
        state["l"] += rng.uniform(-0.05, 0.1)
        state["r"] += rng.uniform(-0.05, 0.1)
        state["gyro"] += rng.uniform(-0.2, 0.2)
        pose = e.updateWithTime(t, R(state["gyro"]), state["l"], state["r"])
        return t, pose

    _drive_and_compare(e, 60, step, rng)
    e.resetPose(Pose2d(1, 2, R(0.5)))
    _drive_and_compare(e, 20, step, rng)


def test_sample_interpolation_after_wheel_only_heading_steps_beyond_pi():
    # Without a gyro the dead-wheel heading change is not wrapped: a step of 4 rad is a
    # twist of 4 rad whose pose-to-pose log is 4 − 2π; the interpolation must follow the log.
    kin = DeadWheelKinematics([Pose2d(0, 0.2, R()), Pose2d(0, -0.2, R()), Pose2d(0.1, 0, R(math.pi / 2))])
    e = DeadWheelPoseEstimator(kin, [0.0, 0.0, 0.0])
    wheels = np.zeros(3)
    state = {"t": 0.0}

    def step(rng):
        state["t"] += 0.02
        spin = rng.choice([0.01, 4.0, -4.0, 3.05])
        wheels[:] += [-0.2 * spin + 0.05, 0.2 * spin + 0.05, 0.1 * spin + 0.01]
        return state["t"], e.updateWithTime(state["t"], wheels.copy())

    _drive_and_compare(e, 40, step, np.random.default_rng(7))


@pytest.mark.parametrize("state", [1e155, 1e200, 1.7e308, math.inf])
def test_huge_or_infinite_state_std_devs_take_vision_whole(state):
    # q = sd² overflowed and the gain became inf/inf = NaN for good (porting issue, item
    # 6). The gain's limit is 1: the vision pose at t = 0.01 replaces the odometry's
    # (0.01, 0) there, and the 0.01 m driven since are added: x = 1.0 + 0.01.
    e = DifferentialDrivePoseEstimator(R(), 0.0, 0.0, Pose2d(), (state,) * 3, (0.5,) * 3)
    e.updateWithTime(0.0, R(), 0.0, 0.0)
    e.updateWithTime(0.02, R(), 0.02, 0.02)
    e.addVisionMeasurement(Pose2d(1.0, 0.0, R()), 0.01)
    assert_pose((1.01, 0.0, 0.0), e.getEstimatedPosition())


def test_infinite_vision_std_devs_ignore_vision_on_that_axis():
    e = DifferentialDrivePoseEstimator(R(), 0.0, 0.0, Pose2d(), (0.1,) * 3,
                                       (math.inf, 0.5, math.inf))
    e.updateWithTime(0.0, R(), 0.0, 0.0)
    e.updateWithTime(0.02, R(), 0.02, 0.02)
    e.addVisionMeasurement(Pose2d(1.0, 1.0, R(0.3)), 0.01)
    p = e.getEstimatedPosition()
    # x and heading ignore vision; y moves by WPILib's gain q / (q + sqrt(q r)).
    q, r = 0.1 ** 2, 0.5 ** 2
    k = q / (q + math.sqrt(q * r))
    assert p.x == pytest.approx(0.02, abs=1e-12)
    assert p.getRotation().getRadians() == pytest.approx(0.0, abs=1e-12)
    assert p.y == pytest.approx(k * 1.0, abs=1e-9)


def test_a_clock_running_backwards_keeps_a_bounded_history():
    # Each update older than every stored sample was kept and inserted at the front (a
    # memmove each: quadratic time, unbounded memory; porting issue, item 9). Now only
    # samples within 1.5 s of the newest are kept: t = 0 and t = -0.02·i down to -1.48.
    import tracemalloc
    e = DifferentialDrivePoseEstimator(R(), 0.0, 0.0, Pose2d())
    for i in range(200):
        e.updateWithTime(-0.02 * i, R(), 0.001 * i, 0.001 * i)
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        for i in range(200, 20200):
            e.updateWithTime(-0.02 * i, R(), 0.001 * i, 0.001 * i)
        grown = tracemalloc.get_traced_memory()[0] - before
    finally:
        tracemalloc.stop()
    assert grown < 4096, grown
    assert_pose((0.074, 0.0, 0.0), e.sampleAt(-1.48))      # the oldest sample kept
    assert_pose((0.074, 0.0, 0.0), e.sampleAt(-100.0))     # clamped to it
    assert_pose((0.0, 0.0, 0.0), e.sampleAt(0.0))          # the newest
    assert_pose((20.199, 0.0, 0.0), e.getEstimatedPosition())  # the odometry, as always


def test_huge_finite_timestamps_give_no_nan():
    # (t - t0) / (t1 - t0) overflowed between samples at ±1e308 (porting issue, item 7):
    # the history now spans at most 1.5 s, so the -1e308 update is not stored.
    e = DifferentialDrivePoseEstimator(R(), 0.0, 0.0, Pose2d())
    e.updateWithTime(1e308, R(), 1.0, 1.0)
    e.updateWithTime(-1e308, R(), 0.0, 0.0)
    for t in (9e307, -9e307, 0.0):
        assert_pose((1.0, 0.0, 0.0), e.sampleAt(t))


# -- vision from another clock (porting issue, items 1 and 8) -----------------------------

def _warnings_from(call):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        call()
    return [w for w in caught if issubclass(w.category, ClockMismatchWarning)]


@pytest.mark.parametrize("ts, warned", [
    (1.7e9, True),                 # Unix time against monotonic odometry
    (2.0 + 10.0 + 1e-9, True),     # more than 10 s ahead of the newest sample (2 s)
    (2.0 + 10.0, False),
    (2.0 - 11.5 - 1e-9, True),     # more than 10 s older than the 1.5 s history
    (2.0 - 11.5, False),
    (1.9, False),
])
def test_a_vision_timestamp_off_the_estimators_clock_warns(ts, warned):
    e = estimator()
    for i in range(101):
        drive_to(e, 0.02 * i, 0.01 * i)
    caught = _warnings_from(lambda: e.addVisionMeasurement(Pose2d(1.0, 0.5, R()), ts))
    assert len(caught) == warned
    if warned:
        w = caught[0]
        assert w.filename == __file__        # points at the caller's line
        text = str(w.message)
        assert "DifferentialDrivePoseEstimator.addVisionMeasurement" in text
        assert f"{ts:.6g}" in text and "newest odometry sample (2 s)" in text
        assert "MathSharedStore.getTimestamp()" in text and "updateWithTime" in text
        assert ("applied" in text) == (ts > 2.0) and ("ignored" in text) == (ts < 2.0)


def test_the_clock_warning_comes_once_per_estimator_and_can_be_filtered():
    assert issubclass(ClockMismatchWarning, UserWarning)
    a, b = estimator(), estimator()
    for e in (a, b):
        drive_to(e, 0.0, 0.0)
    assert len(_warnings_from(lambda: a.addVisionMeasurement(Pose2d(), 1.7e9))) == 1
    assert len(_warnings_from(lambda: a.addVisionMeasurement(Pose2d(), -1.7e9))) == 0
    a.resetPose(Pose2d())
    drive_to(a, 0.0, 0.0)
    assert len(_warnings_from(lambda: a.addVisionMeasurement(Pose2d(), 1.7e9))) == 0
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        warnings.filterwarnings("ignore", category=ClockMismatchWarning)
        b.addVisionMeasurement(Pose2d(), 1.7e9)
    assert caught == []


def test_vision_from_another_clock_keeps_bounded_memory():
    # Every record newer than every sample was kept and scanned linearly (13.6 MB and
    # 22 s for 100,000 calls on 0.1.0): a measurement more than 10 s ahead now replaces
    # the earlier ones that far ahead.
    e = estimator()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ClockMismatchWarning)
        for i in range(300):
            drive_to(e, 0.02 * i, 0.01 * i)
            e.addVisionMeasurement(Pose2d(0.01 * i, 1.0, R()), 1.7e9 + 0.02 * i)
        tracemalloc.start()
        try:
            before = tracemalloc.get_traced_memory()[0]
            for i in range(300, 20300):
                drive_to(e, 0.02 * i, 0.01 * i)
                e.addVisionMeasurement(Pose2d(0.01 * i, 1.0, R()), 1.7e9 + 0.02 * i)
            grown = tracemalloc.get_traced_memory()[0] - before
        finally:
            tracemalloc.stop()
    assert grown < 4096, grown
    # Each measurement still moves the estimate by its gain (0.5), against the raw
    # odometry, as in WPILib: y = 0.5 · 1 m.
    assert_pose((0.01 * 20299, 0.5, 0.0), e.getEstimatedPosition())


def test_only_the_newest_far_ahead_measurement_is_kept():
    # The documented difference from WPILib: of two measurements more than 10 s ahead,
    # only the newer is kept, so when the odometry reaches the older one's time it is not
    # applied there (WPILib would apply it between the two times).
    e = estimator()
    drive_to(e, 0.0, 0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ClockMismatchWarning)
        e.addVisionMeasurement(Pose2d(0.0, 1.0, R()), 20.0)
        e.addVisionMeasurement(Pose2d(0.0, 2.0, R()), 30.0)
    assert_pose((0.0, 1.0, 0.0), e.getEstimatedPosition())      # 0.5 · 2 m
    for i in range(1, 1251):
        drive_to(e, 0.02 * i, 0.0)                             # to t = 25 s
    assert_pose((0.0, 1.0, 0.0), e.getEstimatedPosition())      # the t = 30 record
    # WPILib: (0, 0.5, 0), from the t = 20 record (0.5 · 1 m); here that record is gone.
    assert_pose((0.0, 0.0, 0.0), e.sampleAt(25.0))
