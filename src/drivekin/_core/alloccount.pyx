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

Allocator hooks form a chain: each one saved the allocator below it when it was installed
and calls it. A hook can only be taken out safely while it is on top of the chain, so
misuse is handled as follows, and no order of entering, leaving and
``tracemalloc.start()``/``stop()`` can make the chain call itself (a hang) or call freed
memory:

* Leaving while another hook sits on top of ours (tracemalloc started inside the block),
  or after ours was taken out from under us (tracemalloc started before entering and
  stopped inside): the chain is left exactly as it is and RuntimeError explains the order
  rule. Restoring our saved allocator would cut tracemalloc out of the chain while it
  still thinks it is tracing, and its ``stop()`` would later reinstall our hook. Instead
  our hook is *retired*: it stops counting and stays a pass-through to the allocator it
  saved. Its saved state lives in memory that is never reused, so the hook stays valid
  wherever it is still referenced (e.g. by tracemalloc). ``calls`` holds the count up to
  the failed exit; the counter is finished.
* Entering (or leaving cleanly) removes any retired hooks of ours found on top of the
  chain (e.g. put back by ``tracemalloc.stop()``), since they are pure pass-throughs, then
  installs a hook with fresh state, so a new hook never forwards to itself.
* Entering while a counter is active raises RuntimeError; leaving a counter that is not
  the active one does nothing. A counter dropped while active is stopped by its
  deallocation (silently, by the same rules).
"""

cdef extern from *:
    """
    #include <stdlib.h>

    /* One installation of the hooks: per domain, the allocator that was on top when the
       hook was installed (the hook's ctx points at its layer). counting is cleared when
       the installation is stopped or retired; a retired installation is never freed or
       reused, because a hook pointing at it may still be in some chain. */
    typedef struct drivekin_layer {
        PyMemAllocatorEx below;
        int counting;
    } drivekin_layer;
    typedef struct drivekin_install {
        drivekin_layer layer[3];
    } drivekin_install;

    static const PyMemAllocatorDomain drivekin_domains[3] =
        {PYMEM_DOMAIN_RAW, PYMEM_DOMAIN_MEM, PYMEM_DOMAIN_OBJ};
    static unsigned long long drivekin_calls = 0;
    static drivekin_install *drivekin_active = NULL;  /* installed and counting */
    static drivekin_install *drivekin_spare = NULL;   /* cleanly removed, reusable */

    static void *drivekin_malloc(void *ctx, size_t n) {
        drivekin_layer *l = (drivekin_layer *)ctx;
        if (l->counting) drivekin_calls++;
        return l->below.malloc(l->below.ctx, n);
    }
    static void *drivekin_calloc(void *ctx, size_t k, size_t n) {
        drivekin_layer *l = (drivekin_layer *)ctx;
        if (l->counting) drivekin_calls++;
        return l->below.calloc(l->below.ctx, k, n);
    }
    static void *drivekin_realloc(void *ctx, void *p, size_t n) {
        drivekin_layer *l = (drivekin_layer *)ctx;
        if (l->counting) drivekin_calls++;
        return l->below.realloc(l->below.ctx, p, n);
    }
    static void drivekin_free(void *ctx, void *p) {
        drivekin_layer *l = (drivekin_layer *)ctx;
        l->below.free(l->below.ctx, p);
    }

    /* The layer of our hook on top of domain d, or NULL if the top is someone else's. */
    static drivekin_layer *drivekin_top(int d) {
        PyMemAllocatorEx cur;
        PyMem_GetAllocator(drivekin_domains[d], &cur);
        return cur.malloc == drivekin_malloc ? (drivekin_layer *)cur.ctx : NULL;
    }

    /* Take hooks of ours that no longer count off the top of domain d (they only
       forward calls, so the chain below them is what they stand for). Returns 1 if
       `mine` was among them. */
    static int drivekin_pop_retired(int d, const drivekin_layer *mine) {
        drivekin_layer *l;
        int found = 0;
        while ((l = drivekin_top(d)) != NULL && !l->counting) {
            if (l == mine) found = 1;
            PyMem_SetAllocator(drivekin_domains[d], &l->below);
        }
        return found;
    }

    /* 0: installed; -1: a counter is active; -2: out of memory. */
    static int drivekin_hook_start(void) {
        int d;
        drivekin_install *inst;
        if (drivekin_active != NULL) return -1;
        inst = drivekin_spare;
        if (inst == NULL) inst = (drivekin_install *)malloc(sizeof(drivekin_install));
        if (inst == NULL) return -2;
        drivekin_spare = NULL;
        drivekin_calls = 0;
        for (d = 0; d < 3; d++) {
            PyMemAllocatorEx hook;
            drivekin_pop_retired(d, NULL);
            PyMem_GetAllocator(drivekin_domains[d], &inst->layer[d].below);
            inst->layer[d].counting = 1;
            hook.ctx = &inst->layer[d];
            hook.malloc = drivekin_malloc;
            hook.calloc = drivekin_calloc;
            hook.realloc = drivekin_realloc;
            hook.free = drivekin_free;
            PyMem_SetAllocator(drivekin_domains[d], &hook);
        }
        drivekin_active = inst;
        return 0;
    }

    /* Stop the active installation; *count receives the calls counted.
       0: removed cleanly (or nothing was active); 1: retired, the chain was left as is
       in at least one domain because our hook was not on top of it. */
    static int drivekin_hook_stop(unsigned long long *count) {
        int d, retired = 0;
        drivekin_install *inst = drivekin_active;
        *count = drivekin_calls;
        if (inst == NULL) return 0;
        for (d = 0; d < 3; d++) inst->layer[d].counting = 0;
        for (d = 2; d >= 0; d--) {
            /* Ours no longer counts, so it is popped too if it is on top. If it is not,
               it is either below a foreign hook or was already taken out by someone
               else: the chain is left alone. */
            if (!drivekin_pop_retired(d, &inst->layer[d])) retired = 1;
        }
        drivekin_active = NULL;
        /* Our layers can only be reused if no chain can still reach them. That is
           certain only when every domain's top was ours and has been popped. */
        if (!retired) drivekin_spare = inst;
        return retired;
    }
    static unsigned long long drivekin_hook_count(void) { return drivekin_calls; }
    """
    int drivekin_hook_start() nogil
    int drivekin_hook_stop(unsigned long long *count) nogil
    unsigned long long drivekin_hook_count() nogil


_ORDER_RULE = ("start tracemalloc (or any other allocator hook) before entering an "
               "AllocationCounter and stop it after leaving")


cdef class AllocationCounter:
    """Context manager counting allocator calls (RAW, MEM and OBJ domains) in its block.

    ``calls`` holds the count after the block (and the running count inside it).
    Entering while another counter is active raises RuntimeError; so does leaving when
    another allocator hook was installed or removed inside the block (see the module
    docstring: the counter then stops counting and leaves the hook chain as it is).
    """

    cdef readonly unsigned long long calls
    cdef bint _on

    def __enter__(self):
        cdef int rc = drivekin_hook_start()
        if rc == -1:
            raise RuntimeError("an AllocationCounter is already active")
        if rc == -2:
            raise MemoryError("no memory for the AllocationCounter hooks")
        self._on = True
        self.calls = 0
        return self

    def __exit__(self, exc_type, exc, tb):
        cdef unsigned long long n = 0
        cdef int rc
        if not self._on:
            return False
        rc = drivekin_hook_stop(&n)
        self.calls = n
        self._on = False
        if rc != 0:
            raise RuntimeError(
                "AllocationCounter left while another allocator hook (e.g. tracemalloc) "
                "was installed or removed inside its block; the counting stopped and the "
                "allocator chain was left as it is, with this counter's hook as a "
                "pass-through. Rule: " + _ORDER_RULE)
        return False

    def count(self):
        """Return the calls counted so far (while active) or in the finished block."""
        return drivekin_hook_count() if self._on else self.calls

    def __dealloc__(self):
        cdef unsigned long long n
        if self._on:
            drivekin_hook_stop(&n)
