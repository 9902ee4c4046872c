"""Hostile command lines and AllocationCounter misuse: one clear line and exit status 2
for bad arguments, and misuse that raises instead of hanging. Each runs in its own
interpreter with a timeout, so a hang or crash fails only that test."""
from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest


def _run(args, timeout=30):
    return subprocess.run([sys.executable, *args], capture_output=True, text=True,
                          timeout=timeout)


@pytest.mark.parametrize("seconds", ["1e12", "abc", "nan", "inf", "-1"])
def test_bad_seconds_get_one_clear_line(seconds):
    p = _run(["-m", "drivekin", "--seconds", seconds])
    assert p.returncode == 2, (p.returncode, p.stderr[-500:])
    assert "Traceback" not in p.stderr, p.stderr[-500:]
    assert "_positive_float" not in p.stderr, p.stderr
    assert "--seconds" in p.stderr, p.stderr


def test_allocation_counter_misuse_raises_and_never_hangs():
    script = textwrap.dedent("""
        import tracemalloc
        from drivekin._core.alloccount import AllocationCounter
        raised = []
        def step(f):
            try:
                f()
            except Exception as e:
                raised.append(type(e).__name__)
        c1 = AllocationCounter()
        step(c1.__enter__)
        step(tracemalloc.start)
        step(lambda: c1.__exit__(None, None, None))
        step(tracemalloc.stop)
        c2 = AllocationCounter()
        step(c2.__enter__)
        step(lambda: c2.__exit__(None, None, None))
        x = [object() for _ in range(1000)]  # the allocator still works
        print("done", raised)
    """)
    try:
        p = _run(["-c", script], timeout=10)
    except subprocess.TimeoutExpired:
        pytest.fail("AllocationCounter misuse hung for 10 s")
    assert p.returncode == 0, (p.returncode, p.stderr[-800:])
    assert "done" in p.stdout
    assert "RuntimeError" in p.stdout or "ValueError" in p.stdout, (
        f"the misuse went unnoticed: {p.stdout}")
