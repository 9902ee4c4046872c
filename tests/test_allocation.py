"""The allocation-free paths really allocate nothing in steady state.

Method: warm up (fills freelists, numpy's buffer-info cache, method caches), then start
tracemalloc from zero and run the call 10 000 times with the cyclic GC disabled.
* tracemalloc's peak must not rise above the starting traced size: any allocation made
  through Python's allocators (objects, PyMem_Malloc buffers, numpy's data via
  PyDataMem with tracemalloc hooks) would push it up, even if freed again;
* ``gc.get_count()[0]`` (GC-tracked allocations minus deallocations) must not grow.
The loop uses ``itertools.repeat`` so the harness itself creates no int objects, and a
control test proves the harness detects a deliberately allocating body.
"""
from __future__ import annotations

import gc
import itertools
import tracemalloc

import numpy as np
import pytest

from drivekin import (
    ChassisVelocities,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Translation2d,
    Twist2d,
)

WARMUP = 1000
CALLS = 10_000


def measure(fn, calls=CALLS, warmup=WARMUP):
    """Run ``fn()`` ``calls`` times after ``warmup`` calls.

    Returns ``(peak_growth_bytes, current_growth_bytes, gc_count_growth)``. The harness
    itself must not allocate between the two probes: the loop iterator is created before
    tracing starts, and each probe is called once beforehand so that its result tuple
    comes from CPython's tuple freelist (``test_harness_baseline_is_zero`` checks this).
    """
    if tracemalloc.is_tracing():  # e.g. python -X tracemalloc: numbers would be skewed
        pytest.skip("tracemalloc is already tracing")
    for _ in itertools.repeat(None, warmup):
        fn()
    loop = itertools.repeat(None, calls)
    counts, traced = gc.get_count, tracemalloc.get_traced_memory
    gc.collect()
    gc.disable()
    try:
        counts()
        traced()
        gc0 = counts()[0]
        tracemalloc.start()
        try:
            tracemalloc.reset_peak()
            start, _ = traced()
            start, _ = traced()
            tracemalloc.reset_peak()
            for _ in loop:
                fn()
            current, peak = traced()
        finally:
            tracemalloc.stop()
        gc1 = counts()[0]
    finally:
        gc.enable()
    return peak - start, current - start, gc1 - gc0


def assert_allocation_free(fn):
    peak, current, gc_growth = measure(fn)
    assert peak <= 0, f"traced memory peaked {peak} B above the start over {CALLS} calls"
    assert current <= 0, f"{current} B still allocated after {CALLS} calls"
    assert gc_growth <= 0, f"{gc_growth} GC-tracked objects created and not freed"


# ---------------------------------------------------------------------------------------
# The harness works


def test_harness_baseline_is_zero():
    assert measure(lambda: None) == (0, 0, 0)


def test_harness_detects_transient_allocation():
    peak, current, gc_growth = measure(lambda: [0.5, 1.5])
    assert peak > 0
    with pytest.raises(AssertionError):
        assert_allocation_free(lambda: [0.5, 1.5])


def test_harness_detects_leak_and_gc_objects():
    keep = []
    peak, current, gc_growth = measure(lambda: keep.append([1]), calls=1000, warmup=0)
    assert peak > 0 and current > 0 and gc_growth > 0


def test_harness_detects_object_returning_facade():
    # The object-returning façade builds a new tuple per call: the harness must see it.
    kin = _kin()
    cv = ChassisVelocities(1.0, 2.0, 3.0)
    with pytest.raises(AssertionError):
        assert_allocation_free(lambda: kin.toSwerveModuleVelocities(cv))


# ---------------------------------------------------------------------------------------
# Allocation-free operations


def _kin(n=4):
    mods = [Translation2d(0.3, 0.3), Translation2d(0.3, -0.3), Translation2d(-0.3, 0.3),
            Translation2d(-0.3, -0.3), Translation2d(0.5, 0.0), Translation2d(-0.5, 0.1)]
    return SwerveDriveKinematics(*mods[:n])


@pytest.mark.parametrize("n", [2, 4, 6])
def test_ik_into_objects(n):
    kin = _kin(n)
    cv = ChassisVelocities(1.0, 2.0, 3.0)
    out = [SwerveModuleVelocity() for _ in range(n)]
    assert_allocation_free(lambda: kin.toSwerveModuleVelocitiesInto(cv, out))


def test_ik_into_tuple_with_center_of_rotation():
    kin = _kin()
    cv = ChassisVelocities(1.0, 2.0, 3.0)
    cor = Translation2d(0.3, 0.3)
    out = tuple(SwerveModuleVelocity() for _ in range(4))
    assert_allocation_free(lambda: kin.toSwerveModuleVelocitiesInto(cv, out, cor))


def test_ik_into_alternating_center_of_rotation():
    # Switching CoR rebuilds the inverse rows in preallocated memory.
    kin = _kin()
    cv = ChassisVelocities(1.0, 2.0, 3.0)
    cors = itertools.cycle([Translation2d(0.3, 0.3), Translation2d()])
    out = [SwerveModuleVelocity() for _ in range(4)]
    nxt = cors.__next__
    assert_allocation_free(lambda: kin.toSwerveModuleVelocitiesInto(cv, out, nxt()))


def test_ik_into_array():
    kin = _kin()
    cv = ChassisVelocities(1.0, 2.0, 3.0)
    out = np.zeros((4, 2))
    assert_allocation_free(lambda: kin.toSwerveModuleVelocitiesInto(cv, out))


def test_ik_into_zero_velocity_heading_memory():
    kin = _kin()
    kin.toSwerveModuleVelocities(ChassisVelocities(1.0, 0.0, 1.0))
    cv = ChassisVelocities()
    out = [SwerveModuleVelocity() for _ in range(4)]
    assert_allocation_free(lambda: kin.toSwerveModuleVelocitiesInto(cv, out))


def test_fk_into_objects():
    kin = _kin()
    states = kin.toSwerveModuleVelocities(ChassisVelocities(1.0, 2.0, 3.0))
    out = ChassisVelocities()
    assert_allocation_free(lambda: kin.toChassisVelocitiesInto(states, out))


def test_fk_into_list_and_array():
    kin = _kin()
    states = list(kin.toSwerveModuleVelocities(ChassisVelocities(1.0, 2.0, 3.0)))
    arr = np.array([[s.velocity, s.angle.getRadians()] for s in states])
    out = ChassisVelocities()
    assert_allocation_free(lambda: kin.toChassisVelocitiesInto(states, out))
    assert_allocation_free(lambda: kin.toChassisVelocitiesInto(arr, out))


def test_to_twist_into():
    kin = _kin()
    deltas = [SwerveModulePosition(0.01 * i, Rotation2d(0.1 * i)) for i in range(4)]
    arr = np.array([[d.distance, d.angle.getRadians()] for d in deltas])
    out = Twist2d()
    assert_allocation_free(lambda: kin.toTwist2dInto(deltas, out))
    assert_allocation_free(lambda: kin.toTwist2dInto(arr, out))


def test_desaturate_in_place_objects_both_forms():
    states = [SwerveModuleVelocity(v, Rotation2d(0.3)) for v in (5.0, -6.0, 4.0, 7.0)]
    desired = ChassisVelocities(1.0, 0.0, 0.5)
    d = SwerveDriveKinematics.desaturateWheelVelocitiesInPlace
    assert_allocation_free(lambda: d(states, 5.5))
    assert_allocation_free(lambda: d(states, desired, 5.5, 5.5, 3.5))


def test_desaturate_in_place_array_both_forms():
    arr = np.array([[5.0, 0.1], [-6.0, 0.2], [4.0, 0.3], [7.0, 0.4]])
    desired = ChassisVelocities(1.0, 0.0, 0.5)
    d = SwerveDriveKinematics.desaturateWheelVelocitiesInPlace
    assert_allocation_free(lambda: d(arr, 5.5))
    assert_allocation_free(lambda: d(arr, desired, 5.5, 5.5, 3.5))


def test_chassis_into_methods():
    cv = ChassisVelocities(1.0, 2.0, 0.5)
    out = ChassisVelocities()
    r = Rotation2d(0.7)
    assert_allocation_free(lambda: cv.discretizeInto(0.02, out))
    assert_allocation_free(lambda: cv.toRobotRelativeInto(r, out))
    assert_allocation_free(lambda: cv.toFieldRelativeInto(r, out))
    assert_allocation_free(lambda: out.toFieldRelativeInto(r, out))  # out is self


class _Box:
    __slots__ = ("pose",)


def test_pose_exp_update():
    box = _Box()
    box.pose = Pose2d(1.0, 2.0, Rotation2d(0.3))
    tw = Twist2d(0.01, 0.002, 0.001)

    def step():
        box.pose = box.pose.exp(tw)

    assert_allocation_free(step)


def test_pose_plus_twist_exp_update():
    box = _Box()
    box.pose = Pose2d(1.0, 2.0, Rotation2d(0.3))
    tw = Twist2d(0.01, 0.002, 0.001)

    def step():
        box.pose = box.pose.plus(tw.exp())

    assert_allocation_free(step)


def test_odometry_style_loop():
    """The whole loop body a robot would run: FK twist from module deltas, pose update."""
    kin = _kin()
    deltas = [SwerveModulePosition(0.01, Rotation2d(0.1 * i)) for i in range(4)]
    tw = Twist2d()
    box = _Box()
    box.pose = Pose2d()

    def step():
        kin.toTwist2dInto(deltas, tw)
        box.pose = box.pose.plus(tw.exp())

    assert_allocation_free(step)
