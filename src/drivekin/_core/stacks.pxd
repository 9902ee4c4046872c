# The argument rules of drivekin.batch: numpy stacks validated once per call (float64,
# native-endian, C-contiguous, the expected shape) and the result buffers (``out=``:
# the result's shape, writeable, not overlapping an input), shared by batch.pyx and
# _core/batch3d.pyx. Each helper returns the validated array in a _Stack (the caller keeps
# it, so its data stays alive) with its data pointer; nothing is converted or copied.


cdef class _Stack:
    """One validated float64 argument: ``n`` samples of ``width`` doubles at ``data``."""
    cdef object array
    cdef double* data
    cdef Py_ssize_t n, width
    cdef bint single


# Samples per pass: the batch loops first compute every sample's sines, cosines and
# angles of a chunk (independent of each other, so a vector at a time), then run the
# per-sample arithmetic, and write angles out in a last pass. 32 samples keep a swerve
# replay's scratch well inside L1 (with vectorised trig, measured about 9 % faster than
# 256 for replay and swerve IK).
cdef enum:
    CHUNK = 32


cdef inline Py_ssize_t chunk_len(Py_ssize_t i0, Py_ssize_t count) noexcept nogil:
    return CHUNK if count - i0 > CHUNK else count - i0


cdef inline void wheel_major(Py_ssize_t k, Py_ssize_t n, const double* x, bint steered,
                             double* m, double* a) noexcept nogil:   # OUT m (and a)
    # k samples of n wheels (sample-major, as the stacks hold them) laid out wheel-major,
    # wheel j of sample i at m[k·j + i]: its value, or a steered module's magnitude there
    # and its angle at a[k·j + i].
    cdef Py_ssize_t i, j
    if steered:
        for j in range(n):
            for i in range(k):
                m[k * j + i] = x[2 * (n * i + j)]
                a[k * j + i] = x[2 * (n * i + j) + 1]
    else:
        for j in range(n):
            for i in range(k):
                m[k * j + i] = x[n * i + j]


# The shape of one wheel sample: W values, or a steered drivetrain's W modules of
# [magnitude, angle rad].
cdef inline tuple sample_shape(Py_ssize_t w, bint steered):
    if steered:
        return (w, 2)
    return (w,)


# ``x`` as one value of shape ``inner`` (when single_ok) or an (N,) + inner stack.
cdef _Stack _stack(object x, tuple inner, str name, bint single_ok=*)
# The wheel or module count of a value whose count is free: the last axis (cols = 0) or
# the one before a last axis of ``cols``.
cdef Py_ssize_t _rows(object x, Py_ssize_t cols, str name, str shapes) except -1
# One number per sample: a float (the same for every sample) or, beside a stack of n
# values, an (n,) float64 array. Always returned as n values.
cdef _Stack _per_sample(object x, Py_ssize_t n, bint single, str name)
# Two arguments of shape ``inner`` each, single or stacked, as (a, b): two stacks have one
# length; a single value goes with every sample of the other.
cdef tuple _pair(object a, object b, tuple inner, str name_a, str name_b)
# ``out`` validated for the result's shape (n samples of ``inner``), or a new array.
cdef _Stack _result(object out, Py_ssize_t n, bint single, tuple inner, tuple inputs,
                    str name)
cdef double* _scratch(Py_ssize_t count) except NULL
