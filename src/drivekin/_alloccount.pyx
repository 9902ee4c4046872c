"""Count calls into CPython's memory allocators (a development aid for the allocation
checks of the demo and the tests).

``tracemalloc`` reports bytes, not calls, and a freed-then-reused block can hide from its
peak. This module wraps the RAW, MEM and OBJ allocator domains with counting hooks
(``PyMem_SetAllocator``), so ``count()`` is the exact number of malloc/calloc/realloc
calls made while counting was on. Freelist hits (drivekin's value objects, CPython's
floats and tuples) make no allocator call and so count zero.

Use it as a context manager; do not nest it, and start tracemalloc (if at all) before
entering and stop it after leaving, so the hooks are removed in the order they were
installed::

    with AllocationCounter() as counter:
        loop()
    assert counter.calls == 0
"""

cdef extern from *:
    """
    static PyMemAllocatorEx drivekin_orig[3];
    static const PyMemAllocatorDomain drivekin_domains[3] =
        {PYMEM_DOMAIN_RAW, PYMEM_DOMAIN_MEM, PYMEM_DOMAIN_OBJ};
    static unsigned long long drivekin_calls = 0;
    static int drivekin_active = 0;

    static void *drivekin_malloc(void *ctx, size_t n) {
        PyMemAllocatorEx *a = (PyMemAllocatorEx *)ctx;
        drivekin_calls++;
        return a->malloc(a->ctx, n);
    }
    static void *drivekin_calloc(void *ctx, size_t k, size_t n) {
        PyMemAllocatorEx *a = (PyMemAllocatorEx *)ctx;
        drivekin_calls++;
        return a->calloc(a->ctx, k, n);
    }
    static void *drivekin_realloc(void *ctx, void *p, size_t n) {
        PyMemAllocatorEx *a = (PyMemAllocatorEx *)ctx;
        drivekin_calls++;
        return a->realloc(a->ctx, p, n);
    }
    static void drivekin_free(void *ctx, void *p) {
        PyMemAllocatorEx *a = (PyMemAllocatorEx *)ctx;
        a->free(a->ctx, p);
    }
    static int drivekin_hook_start(void) {
        int d;
        if (drivekin_active) return -1;
        for (d = 0; d < 3; d++) {
            PyMemAllocatorEx hook;
            PyMem_GetAllocator(drivekin_domains[d], &drivekin_orig[d]);
            hook.ctx = &drivekin_orig[d];
            hook.malloc = drivekin_malloc;
            hook.calloc = drivekin_calloc;
            hook.realloc = drivekin_realloc;
            hook.free = drivekin_free;
            PyMem_SetAllocator(drivekin_domains[d], &hook);
        }
        drivekin_calls = 0;
        drivekin_active = 1;
        return 0;
    }
    static unsigned long long drivekin_hook_stop(void) {
        int d;
        unsigned long long n = drivekin_calls;
        if (!drivekin_active) return 0;
        for (d = 2; d >= 0; d--) PyMem_SetAllocator(drivekin_domains[d], &drivekin_orig[d]);
        drivekin_active = 0;
        return n;
    }
    static unsigned long long drivekin_hook_count(void) { return drivekin_calls; }
    """
    int drivekin_hook_start() nogil
    unsigned long long drivekin_hook_stop() nogil
    unsigned long long drivekin_hook_count() nogil


cdef class AllocationCounter:
    """Context manager counting allocator calls (RAW, MEM and OBJ domains) in its block.

    ``calls`` holds the count after the block (and the running count inside it).
    Entering while another counter is active raises RuntimeError.
    """

    cdef readonly unsigned long long calls
    cdef bint _on

    def __enter__(self):
        if drivekin_hook_start() != 0:
            raise RuntimeError("an AllocationCounter is already active")
        self._on = True
        self.calls = 0
        return self

    def __exit__(self, exc_type, exc, tb):
        self.calls = drivekin_hook_stop()
        self._on = False
        return False

    def count(self):
        """Return the calls counted so far (while active) or in the finished block."""
        return drivekin_hook_count() if self._on else self.calls
