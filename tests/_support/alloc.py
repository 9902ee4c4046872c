"""The allocation-measuring harness shared by the allocation tests.

Imported by the test modules as ``from tests._support.alloc import ...``. Its self-tests --
it reports zero for an empty loop and does see a deliberately allocating one -- are in
``tests/allocation/test_allocation.py``.

Method: warm up (fills drivekin's freelists, numpy's buffer-info cache, method caches), run
``gc.collect()``, then warm up *again*, because ``gc.collect()`` empties CPython's own
freelists (without the second warm-up a body that returns floats, e.g. ``pose.getX()``,
would show 24 B per float still alive at the end: a harness artefact, not an allocation).
Then start tracemalloc and run the body ``calls`` times with the cyclic GC disabled:

* tracemalloc's *peak* must not rise above the starting traced size: any allocation made
  through Python's allocators (objects, PyMem_Malloc buffers, numpy's data via PyDataMem
  with tracemalloc hooks) pushes it up, even when it is freed again within the same call;
* the traced size must not have grown at the end (nothing kept);
* ``gc.get_count()[0]`` (GC-tracked allocations minus deallocations) must not grow;
* in a second pass, drivekin's allocator hooks (``drivekin._core.alloccount``) must count zero
  malloc/calloc/realloc calls in the RAW, MEM and OBJ domains.

Objects drawn from a freelist (drivekin's Cython freelists, CPython's float and tuple
freelists) are not allocator calls; that is how ``pose = odo.update(...)`` stays free.

The harness itself must not allocate between its two probes: the loop iterator is
created before tracing starts and is an ``itertools.repeat`` (no int objects), and each
probe is called once beforehand so that its result tuple comes from CPython's tuple
freelist.
"""
from __future__ import annotations

import gc
import itertools
import tracemalloc

import pytest

CALLS = 10_000           # measured calls per test
WARMUP = 1000


def calls_of(fn):
    """A ``loop(it)`` that calls ``fn()`` once per item of ``it``."""

    def loop(it):
        for _ in it:
            fn()

    return loop


def measure_loop(loop, calls=CALLS, warmup=WARMUP):
    """Run ``loop(iterator)`` over ``calls`` items after the warm-ups.

    ``loop`` is a function whose body is the code under test inside ``for _ in it:``, so
    the iteration itself makes no objects. Returns ``(peak_growth_bytes,
    current_growth_bytes, gc_count_growth)`` of the measured run.
    """
    if tracemalloc.is_tracing():  # e.g. python -X tracemalloc: numbers would be skewed
        pytest.skip("tracemalloc is already tracing")
    loop(itertools.repeat(None, warmup))
    it = itertools.repeat(None, calls)
    counts, traced = gc.get_count, tracemalloc.get_traced_memory
    enabled = gc.isenabled()
    gc.collect()
    gc.disable()
    try:
        loop(itertools.repeat(None, warmup))       # refill the freelists gc.collect emptied
        counts()                                    # warm the probes' result tuples
        traced()
        tracemalloc.start()
        try:
            tracemalloc.reset_peak()
            start, _ = traced()
            start, _ = traced()
            # The GC count is read right around the loop: on CPython 3.14 starting
            # tracemalloc and its first probe count as GC allocations of their own.
            counts()
            gc0 = counts()[0]
            tracemalloc.reset_peak()
            loop(it)
            gc1 = counts()[0]
            current, peak = traced()
        finally:
            tracemalloc.stop()
    finally:
        if enabled:
            gc.enable()
    return peak - start, current - start, gc1 - gc0


def count_allocator_calls(loop, calls=CALLS, warmup=WARMUP):
    """Exact number of PyMem/PyObject malloc/calloc/realloc calls made by ``loop(it)``
    over ``calls`` items, counted by drivekin's allocator hooks (``drivekin._core.alloccount``) after
    the same warm-ups as :func:`measure_loop`. tracemalloc sees bytes; this sees calls,
    so a block freed and reallocated within one iteration cannot hide."""
    from drivekin._core.alloccount import AllocationCounter

    loop(itertools.repeat(None, warmup))
    it = itertools.repeat(None, calls)
    counter = AllocationCounter()
    on, off = counter.__enter__, counter.__exit__     # bound before counting starts
    enabled = gc.isenabled()
    gc.collect()
    gc.disable()
    try:
        loop(itertools.repeat(None, warmup))
        on()
        loop(it)
        off(None, None, None)
    finally:
        if enabled:
            gc.enable()
    return counter.calls


def measure(fn, calls=CALLS, warmup=WARMUP):
    """:func:`measure_loop` for the body ``fn()`` (one call per iteration)."""
    return measure_loop(calls_of(fn), calls, warmup)


def assert_no_allocations(loop, what, calls=CALLS):
    """``loop(it)`` (see :func:`measure_loop`) makes no allocations over ``calls`` items."""
    peak, current, gc_growth = measure_loop(loop, calls)
    assert (peak, current, gc_growth) == (0, 0, 0), (
        f"{what}: over {calls} iterations traced memory peaked {peak} B above the start, "
        f"{current} B were still allocated at the end, {gc_growth} GC-tracked objects were "
        "created and not freed")
    n = count_allocator_calls(loop, calls)
    assert n == 0, f"{what}: {n} allocator calls over {calls} iterations"


def assert_allocation_free(fn, what=None):
    """``fn()``, called :data:`CALLS` times in a loop, makes no allocations."""
    assert_no_allocations(calls_of(fn), what or repr(fn))
