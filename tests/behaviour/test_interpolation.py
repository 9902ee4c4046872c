"""TimeInterpolatableBuffer against /work/shared/reference/followers-and-estimators.md §5
(WPILib 2027 Java semantics), and differentially against robotpy-wpimath's C++ buffers
on random sample sequences, apart from the C++ differences of §8 items 2–4, which are
kept out of the random sequences by construction and shown by their own tests."""
import math
import random

import pytest

from drivekin import Pose2d, Rotation2d, TimeInterpolatableBuffer, Translation2d

wi = pytest.importorskip("wpimath.interpolation")
wg = pytest.importorskip("wpimath.geometry")

TIB = TimeInterpolatableBuffer
EPS = 1e-12


def keys(buf):
    return [t for t, _ in buf.getInternalBuffer()]


# ---- §5 vectors ----------------------------------------------------------------------

def test_rotation_vectors():
    buf = TIB.createBuffer(10.0)
    buf.addSample(0.0, Rotation2d(0.0))
    buf.addSample(1.0, Rotation2d(1.0))
    buf.addSample(3.0, Rotation2d(2.0))
    assert buf.getSample(0.5).getRadians() == pytest.approx(0.5, abs=EPS)
    assert buf.getSample(2.0).getRadians() == pytest.approx(1.5, abs=EPS)
    buf.addSample(10.5, Rotation2d(2.0))        # 10.5 − 0 ≥ 10: t = 0 goes
    assert keys(buf) == [1.0, 3.0, 10.5]
    assert buf.getSample(0.0).getRadians() == pytest.approx(1.0, abs=EPS)


def test_pose_interpolates_along_the_arc():
    buf = TIB.createBuffer(10.0)
    buf.addSample(0.0, Pose2d(0.0, 0.0, Rotation2d.fromDegrees(90.0)))
    buf.addSample(1.0, Pose2d(1.0, 1.0, Rotation2d.fromDegrees(0.0)))
    p = buf.getSample(0.5)
    assert p.getX() == pytest.approx(1.0 - 1.0 / math.sqrt(2.0), abs=EPS)
    assert p.getY() == pytest.approx(1.0 / math.sqrt(2.0), abs=EPS)
    assert p.getRotation().getDegrees() == pytest.approx(45.0, abs=1e-10)


def test_removal_is_at_least_history_before_insert():
    buf = TIB.createDoubleBuffer(1.5)
    for t in (0.0, 1.0, 1.4375):
        buf.addSample(t, t)
    buf.addSample(1.5, 1.5)                     # 1.5 − 0 = 1.5 ≥ 1.5: removed
    assert keys(buf) == [1.0, 1.4375, 1.5]


def test_old_sample_removes_nothing_and_is_inserted():
    buf = TIB.createDoubleBuffer(1.0)
    buf.addSample(10.0, 4.0)
    buf.addSample(0.0, 2.0)
    assert keys(buf) == [0.0, 10.0]
    assert buf.getSample(5.0) == 3.0
    buf.addSample(10.5, 5.0)
    assert keys(buf) == [10.0, 10.5]


# ---- the rest of the contract ------------------------------------------------------

def test_empty_is_none_and_clear_empties():
    buf = TIB.createDoubleBuffer(1.0)
    assert buf.getSample(0.0) is None
    buf.addSample(0.0, 1.0)
    buf.clear()
    assert buf.getSample(0.0) is None
    assert buf.getInternalBuffer() == []


def test_clamps_outside_and_interpolates_inside():
    buf = TIB.createDoubleBuffer(5.0)
    buf.addSample(1.0, 10.0)
    buf.addSample(2.0, 20.0)
    assert buf.getSample(-3.0) == 10.0
    assert buf.getSample(9.0) == 20.0
    assert buf.getSample(1.25) == 12.5


def test_exact_hit_returns_the_stored_sample_without_interpolating():
    calls = []

    def f(a, b, t):
        calls.append((a, b, t))
        return Translation2d(0.0, 0.0)
    buf = TIB.createBuffer(f, 5.0)
    samples = [Translation2d(float(i), 1.0) for i in range(3)]
    for i, s in enumerate(samples):
        buf.addSample(float(i), s)
    for i, s in enumerate(samples):
        assert buf.getSample(float(i)) is s
    assert buf.getSample(-0.0) is samples[0]
    assert calls == []
    buf.getSample(0.25)
    assert calls == [(samples[0], samples[1], 0.25)]


def test_equal_time_replaces():
    buf = TIB.createDoubleBuffer(5.0)
    buf.addSample(0.0, 1.0)
    buf.addSample(1.0, 2.0)
    buf.addSample(0.0, 3.0)
    buf.addSample(1.0, 4.0)
    assert buf.getInternalBuffer() == [(0.0, 3.0), (1.0, 4.0)]


def test_internal_buffer_is_a_snapshot():
    buf = TIB.createDoubleBuffer(5.0)
    buf.addSample(0.0, 1.0)
    snap = buf.getInternalBuffer()
    snap.append((9.0, 9.0))
    buf.addSample(1.0, 2.0)
    assert snap == [(0.0, 1.0), (9.0, 9.0)]
    assert buf.getInternalBuffer() == [(0.0, 1.0), (1.0, 2.0)]


def test_double_buffer_stores_floats():
    buf = TIB.createDoubleBuffer(5.0)
    buf.addSample(0, 1)
    assert buf.getInternalBuffer() == [(0.0, 1.0)]
    assert type(buf.getInternalBuffer()[0][1]) is float
    with pytest.raises(TypeError, match="sample must be a float"):
        buf.addSample(1.0, "2.0")
    with pytest.raises(TypeError, match="sample must be a float"):
        buf.addSample(1.0, None)
    assert keys(buf) == [0.0]


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, 10 ** 400])
def test_non_finite_times_are_refused(bad):
    buf = TIB.createDoubleBuffer(1.0)
    buf.addSample(0.0, 1.0)
    with pytest.raises(ValueError, match="time must be a (finite )?number of seconds"):
        buf.addSample(bad, 2.0)
    with pytest.raises(ValueError, match="time must be a (finite )?number of seconds"):
        buf.getSample(bad)
    assert buf.getInternalBuffer() == [(0.0, 1.0)]


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf])
def test_bad_history_is_refused(bad):
    for make in (TIB.createDoubleBuffer, TIB.createBuffer,
                 lambda h: TIB.createBuffer(lambda a, b, t: a, h)):
        with pytest.raises(ValueError, match="history_size"):
            make(bad)


def test_bad_arguments_raise_type_errors():
    with pytest.raises(TypeError, match="history_size must be a number"):
        TIB.createDoubleBuffer("1.5")
    with pytest.raises(TypeError, match="func must be a callable"):
        TIB.createBuffer(1.0, 1.5)
    with pytest.raises(TypeError, match="createBuffer takes"):
        TIB.createBuffer()
    buf = TIB.createDoubleBuffer(1.0)
    with pytest.raises(TypeError, match="time must be a number"):
        buf.getSample(None)
    with pytest.raises(TypeError, match="already initialised"):
        buf.__init__(lambda a, b, t: a, 1.0)
    with pytest.raises(RuntimeError, match="has not completed"):
        TIB.__new__(TIB).getSample(0.0)


# ---- against robotpy-wpimath (WPILib C++) ---------------------------------------------

HISTORY = 1.5


def _pose(rng):
    return Pose2d(rng.uniform(-5, 5), rng.uniform(-5, 5), Rotation2d(rng.uniform(-3, 3)))


def _to_w(p):
    return wg.Pose2d(p.getX(), p.getY(), wg.Rotation2d(p.getRotation().getRadians()))


def _sequence(rng, n):
    """Random times (continuous, so that no sample is exactly ``HISTORY`` older than a
    later one: §8 item 2 never applies), with repeats of stored times other than the
    oldest (§8 item 4 never applies) and old, late samples."""
    stored = []
    out = []
    newest = 0.0
    for _ in range(n):
        u = rng.random()
        if u < 0.15 and len(stored) > 1:
            t = rng.choice(stored[1:])               # replace a stored, non-oldest sample
        elif u < 0.25:
            t = newest - rng.uniform(0.0, 2.0)       # late (possibly out of the window)
        else:
            t = newest + rng.uniform(0.001, 0.4)
        if stored and t == stored[0]:
            continue
        stored = sorted({s for s in stored if t - s < HISTORY} | {t})
        newest = max(newest, t)
        out.append(t)
    return out


@pytest.mark.parametrize("seed", range(40))
def test_float_buffer_matches_robotpy(seed):
    rng = random.Random(seed)
    ours, theirs = TIB.createDoubleBuffer(HISTORY), wi.TimeInterpolatableFloatBuffer(HISTORY)
    assert ours.getSample(0.0) is None and theirs.sample(0.0) is None
    for t in _sequence(rng, 120):
        v = rng.uniform(-10, 10)
        ours.addSample(t, v)
        theirs.addSample(t, v)
        assert ours.getInternalBuffer() == theirs.getInternalBuffer()
        stored = keys(ours)
        for q in [rng.uniform(stored[0] - 0.5, stored[-1] + 0.5) for _ in range(4)]:
            assert ours.getSample(q) == pytest.approx(theirs.sample(q), rel=1e-15, abs=1e-15)
        # Exact hits: C++ computes lerp(floor, hit, 1) (§8 item 3), which may differ from
        # the stored value by rounding; ours returns the stored value itself.
        for k, v_stored in ours.getInternalBuffer():
            assert ours.getSample(k) == v_stored
            assert theirs.sample(k) == pytest.approx(v_stored, rel=1e-15, abs=1e-14)


@pytest.mark.parametrize("seed", range(40))
def test_pose_buffer_matches_robotpy(seed):
    rng = random.Random(1000 + seed)
    ours = TIB.createBuffer(HISTORY)
    theirs = wi.TimeInterpolatablePose2dBuffer(HISTORY)
    for t in _sequence(rng, 120):
        p = _pose(rng)
        ours.addSample(t, p)
        theirs.addSample(t, _to_w(p))
        assert keys(ours) == [k for k, _ in theirs.getInternalBuffer()]
        stored = keys(ours)
        queries = [rng.uniform(stored[0] - 0.5, stored[-1] + 0.5) for _ in range(4)]
        for q in queries + stored:
            a, b = ours.getSample(q), theirs.sample(q)
            assert a.getX() == pytest.approx(b.X(), abs=1e-9)
            assert a.getY() == pytest.approx(b.Y(), abs=1e-9)
            d = a.getRotation().getRadians() - b.rotation().radians()
            assert abs(math.remainder(d, 2 * math.pi)) <= 1e-9


# ---- the documented C++ differences (§8 items 2–4), shown rather than skipped ----------

def test_cpp_difference_2_buffer_boundary():
    ours, theirs = TIB.createDoubleBuffer(1.5), wi.TimeInterpolatableFloatBuffer(1.5)
    for t in (0.0, 1.0, 1.5):
        ours.addSample(t, t)
        theirs.addSample(t, t)
    assert keys(ours) == [1.0, 1.5]
    assert [k for k, _ in theirs.getInternalBuffer()] == [0.0, 1.0, 1.5]


def test_cpp_difference_3_exact_hits_call_the_interpolator():
    calls = []

    def f(a, b, t):
        calls.append(t)
        return a + (b - a) * t
    theirs = wi.TimeInterpolatableFloatBuffer(5.0, f)
    ours = TIB.createBuffer(f, 5.0)
    for t in (0.0, 1.0, 2.0):
        theirs.addSample(t, t)
        ours.addSample(t, t)
    assert ours.getSample(1.0) == 1.0 and calls == []
    assert theirs.sample(1.0) == 1.0 and calls == [1.0]


def test_cpp_difference_4_duplicate_first_timestamp():
    ours, theirs = TIB.createDoubleBuffer(5.0), wi.TimeInterpolatableFloatBuffer(5.0)
    for buf in (ours, theirs):
        buf.addSample(0.0, 1.0)
        buf.addSample(0.0, 2.0)
    assert ours.getInternalBuffer() == [(0.0, 2.0)] and ours.getSample(0.0) == 2.0
    assert len(theirs.getInternalBuffer()) == 2 and theirs.sample(0.0) == 1.0


def test_huge_finite_timestamps_interpolate_without_overflow():
    # The span 1e308 - (-1e308) overflows; the fraction must not become inf/inf = NaN
    # (porting issue, item 7). Closed form: (9e307 + 1e308) / 2e308 = 0.95.
    b = TimeInterpolatableBuffer.createDoubleBuffer(1.5)
    b.addSample(1e308, 1.0)
    b.addSample(-1e308, 0.0)
    assert b.getSample(9e307) == pytest.approx(0.95, rel=1e-15)
    assert b.getSample(-1e308) == 0.0 and b.getSample(1e308) == 1.0
