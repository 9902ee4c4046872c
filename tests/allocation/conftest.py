"""The allocation tests need an interpreter that makes no allocator calls of its own in
a loop: CPython 3.11 and later. CPython 3.10's evaluation loop does (a loop of
``lambda: None`` calls peaks about 50 B above its start under tracemalloc, and the
allocator counter sees one or two calls in 1,000 iterations), so the tests would measure
the interpreter, not drivekin; they are skipped there."""
import sys

import pytest


@pytest.fixture(autouse=True)
def _quiet_interpreter():
    if sys.version_info < (3, 11):
        pytest.skip("CPython 3.10 makes allocator calls of its own inside a loop of no-ops")
