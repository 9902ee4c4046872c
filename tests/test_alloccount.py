"""The allocator-call counter used by the demo: it must see allocations and see none
where freelists serve every request."""
import pytest

from drivekin import ChassisVelocities, Pose2d, Rotation2d, Twist2d
from drivekin._alloccount import AllocationCounter


def _calls(fn, n=1000):
    loop = iter([None] * n)       # the iterator is made before counting starts
    for _ in range(100):
        fn()
    counter = AllocationCounter()
    on, off = counter.__enter__, counter.__exit__
    on()
    for _ in loop:
        fn()
    off(None, None, None)
    return counter.calls


def test_counts_every_allocation():
    # one list object and its item buffer each time
    assert _calls(lambda: [1, 2], n=1000) >= 1000


def test_counts_nothing_for_freelist_objects():
    pose, twist = Pose2d(1.0, 2.0, Rotation2d(0.5)), Twist2d(0.1, 0.0, 0.05)
    assert _calls(lambda: pose.exp(twist)) == 0


def test_in_place_chassis_conversion_makes_no_call():
    cv, angle = ChassisVelocities(1.0, 2.0, 3.0), Rotation2d(0.3)
    assert _calls(lambda: cv.toRobotRelativeInto(angle, cv)) == 0


def test_count_while_active_and_no_nesting():
    with AllocationCounter() as outer:
        data = [object() for _ in range(50)]
        assert outer.count() >= 50
        with pytest.raises(RuntimeError):
            AllocationCounter().__enter__()
    assert outer.calls >= 50 and outer.count() == outer.calls
    del data
