"""The allocator-call counter used by the demo: it must see allocations and see none
where freelists serve every request."""
import pytest

from drivekin import ChassisVelocities, Pose2d, Rotation2d, Twist2d
from drivekin._core.alloccount import AllocationCounter


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


# ---------------------------------------------------------------------------------------
# Misuse with tracemalloc (issue 6, defect 12). Each scenario runs in a fresh interpreter
# with a timeout: on 0.1.0 the issue's order made the next counter spin forever, and a
# broken hook chain can crash the process.

import os
import subprocess
import sys
import textwrap

import drivekin

_PACKAGE_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(drivekin.__file__)))

_PRELUDE = """
import tracemalloc
from drivekin._core.alloccount import AllocationCounter

def misuse(counter):
    try:
        counter.__exit__(None, None, None)
    except RuntimeError as e:
        assert "before entering" in str(e), e
    else:
        raise AssertionError("leaving out of order did not raise")

def baseline_calls():
    # A fresh counter must count allocations exactly once each: a stale hook of ours
    # still counting (or a second copy of the hook in the chain) would double it.
    with AllocationCounter() as c:
        data = [[i] for i in range(1000)]
    del data
    return c.calls

def check_tracemalloc_works():
    tracemalloc.start()
    data = [bytearray(100) for _ in range(100)]
    current, _ = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert current >= 100 * 100, current
    del data
"""


def _run_isolated(body: str) -> None:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        p for p in (_PACKAGE_ROOT, env.get("PYTHONPATH", "")) if p)
    code = _PRELUDE + textwrap.dedent(body) + "\nprint('done')\n"
    result = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                            text=True, timeout=30)
    assert result.returncode == 0 and result.stdout.strip().endswith("done"), (
        f"exit {result.returncode}\nstdout:\n{result.stdout}\nstderr:\n{result.stderr}")


def test_issue_order_raises_and_next_counter_works():
    # enter, tracemalloc.start() inside, leave (refused), tracemalloc.stop() outside,
    # then a second counter: on 0.1.0 it saved its own hook as the original and hung.
    _run_isolated("""
        base = baseline_calls()
        a = AllocationCounter().__enter__()
        tracemalloc.start()
        misuse(a)
        assert tracemalloc.is_tracing()
        junk = [bytearray(64) for _ in range(100)]
        assert tracemalloc.get_traced_memory()[0] >= 6400     # still tracing through us
        del junk
        tracemalloc.stop()
        again = baseline_calls()
        assert base // 2 < again < base * 3 // 2, (base, again)
        check_tracemalloc_works()
        assert base // 2 < baseline_calls() < base * 3 // 2
    """)


def test_tracemalloc_stopped_inside_the_block():
    # tracemalloc started before entering but stopped inside: our hook was taken out
    # from under us; leaving must not reinstall tracemalloc's stale hook.
    _run_isolated("""
        base = baseline_calls()
        tracemalloc.start()
        a = AllocationCounter().__enter__()
        tracemalloc.stop()
        misuse(a)
        assert not tracemalloc.is_tracing()
        assert base // 2 < baseline_calls() < base * 3 // 2
        check_tracemalloc_works()
    """)


def test_correct_orders_are_clean():
    _run_isolated("""
        base = baseline_calls()
        tracemalloc.start()
        with AllocationCounter() as c:
            junk = [bytearray(64) for _ in range(100)]
        assert c.calls >= 100
        assert tracemalloc.get_traced_memory()[0] >= 6400     # traced through our hook
        del junk
        tracemalloc.stop()
        with AllocationCounter():                              # started and stopped inside
            tracemalloc.start()
            tracemalloc.stop()
        assert base // 2 < baseline_calls() < base * 3 // 2
        check_tracemalloc_works()
    """)


def test_counter_started_while_a_retired_hook_is_under_tracemalloc():
    # A (retired, under tracemalloc), B entered over tracemalloc, then tracemalloc.stop()
    # puts A back on top and so removes B: B's exit is refused, nothing hangs.
    _run_isolated("""
        base = baseline_calls()
        a = AllocationCounter().__enter__()
        tracemalloc.start()
        misuse(a)
        b = AllocationCounter().__enter__()
        assert b.count() >= 0
        tracemalloc.stop()
        misuse(b)
        assert base // 2 < baseline_calls() < base * 3 // 2
        check_tracemalloc_works()
        assert base // 2 < baseline_calls() < base * 3 // 2
    """)


def test_random_orders_never_hang_or_crash():
    _run_isolated("""
        import random
        rng = random.Random(6)
        base = baseline_calls()
        active = None
        for step in range(3000):
            op = rng.randrange(5)
            if op == 0 and active is None:
                active = AllocationCounter().__enter__()
            elif op == 1 and active is not None:
                try:
                    active.__exit__(None, None, None)
                except RuntimeError:
                    pass
                active = None
            elif op == 2:
                tracemalloc.start()
            elif op == 3:
                tracemalloc.stop()
            elif op == 4:
                junk = [[i] for i in range(50)]        # exercise the chain
        if active is not None:
            try:
                active.__exit__(None, None, None)
            except RuntimeError:
                pass
        tracemalloc.stop()
        assert base // 2 < baseline_calls() < base * 3 // 2
        check_tracemalloc_works()
    """)


def test_exit_of_a_counter_that_is_not_active_does_nothing():
    with AllocationCounter() as outer:
        stray = AllocationCounter()
        stray.__exit__(None, None, None)          # never entered: must not stop `outer`
        data = [object() for _ in range(50)]
        assert outer.count() >= 50
    assert stray.calls == 0
    del data


def test_dropped_active_counter_releases_the_hooks():
    counter = AllocationCounter()
    counter.__enter__()
    del counter                                    # stopped by its deallocation
    with AllocationCounter() as c:
        data = [object() for _ in range(10)]
    assert c.calls >= 10
    del data
