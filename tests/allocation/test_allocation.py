"""The allocation-free paths really allocate nothing in steady state, and the
allocation harness (``tests/_support/alloc.py``, shared with ``test_allocation_drivetrains.py``)
is not vacuous: it reports zero for an empty body and sees deliberately allocating ones.

Method (details in ``alloc.py``): warm up, ``gc.collect()``, warm up again, then start
tracemalloc from zero and run the call 10 000 times with the cyclic GC disabled; the traced
peak, the traced size and ``gc.get_count()[0]`` must not grow.
"""
from __future__ import annotations

import itertools

import numpy as np
import pytest

from tests._support.alloc import (assert_allocation_free, assert_no_allocations, calls_of,
                                  count_allocator_calls, measure, measure_loop)
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

# ---------------------------------------------------------------------------------------
# The harness works


def test_harness_baseline_is_zero():
    assert measure(lambda: None) == (0, 0, 0)
    assert count_allocator_calls(calls_of(lambda: None)) == 0


def test_allocator_call_counter_sees_every_call():
    # The list object itself comes from CPython's list freelist; its item array is a real
    # PyMem allocation on every call, freed again at once.
    assert count_allocator_calls(calls_of(lambda: [0.5, 1.5]), calls=1000) >= 1000


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
    # The object-returning façade builds a new tuple of 4 SwerveModuleVelocity per call. Once
    # warmed up these come from freelists (CPython's tuple freelist, drivekin's Cython
    # freelists), which are not allocator calls, so the full harness reports 0 for it. With
    # no warm-up after gc.collect() (which empties the tuple freelist) the objects of the
    # first calls are real allocations, and the harness must see them.
    kin = _kin()
    cv = ChassisVelocities(1.0, 2.0, 3.0)
    peak, current, _ = measure(lambda: kin.toSwerveModuleVelocities(cv), warmup=0)
    assert peak > 0 and current > 0


def test_harness_detects_allocations():
    # The loop form used by test_allocation_drivetrains.py (body inside ``for _ in it:``).
    def empty(it):
        for _ in it:
            pass

    def temporary(it):
        for _ in it:
            object()                                # freed at once: only the peak shows it

    def tracked(it, keep=[]):
        for _ in it:
            keep.append([[]])

    assert measure_loop(empty) == (0, 0, 0)
    peak, current, _ = measure_loop(temporary)
    assert current == 0 and peak > 0
    with pytest.raises(AssertionError):
        assert_no_allocations(temporary, "object()")
    peak, current, growth = measure_loop(tracked, calls=100)
    assert current > 0 and peak > 0 and growth > 0


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


def test_desaturated_discretize_into():
    T = Translation2d
    kin = SwerveDriveKinematics(T(0.27, 0.27), T(0.27, -0.27), T(-0.27, 0.27), T(-0.27, -0.27))
    cv = ChassisVelocities(4.0, 0.0, 6.283185307179586)        # saturated: k < 1
    out = ChassisVelocities()
    assert_allocation_free(lambda: kin.desaturatedDiscretizeInto(cv, 0.02, 4.0, out))
    assert_allocation_free(lambda: kin.desaturatedDiscretizeInto(out, 0.02, 4.0, out))


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
