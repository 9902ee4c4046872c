# The numpy argument rules (dtype, alignment, contiguity, writeability), shared by every
# module that takes arrays; and reading a fixed number of floats from a list, tuple or
# float64 array into C memory without running Python code (no __float__, no iteration
# protocol), so nothing can run between reading the values and using them (the dead-wheel
# readings and the estimators' standard deviations).
cimport numpy as cnp
from cpython.list cimport PyList_CheckExact
from cpython.ref cimport PyObject
from cpython.sequence cimport PySequence_Fast_GET_SIZE, PySequence_Fast_ITEMS
from cpython.tuple cimport PyTuple_CheckExact


cdef extern from *:
    """
    /* One value: a float (or subclass, e.g. numpy.float64, whose value is read without
       running Python code) or an exact int. Returns 1 for anything else and 2 for an
       int too large for a double. */
    static inline int drivekin_read_number(PyObject *o, double *out) {
        if (PyFloat_Check(o)) { *out = PyFloat_AS_DOUBLE(o); return 0; }
        if (PyLong_CheckExact(o)) {
            *out = PyLong_AsDouble(o);
            if (*out == -1.0 && PyErr_Occurred()) { PyErr_Clear(); return 2; }
            return 0;
        }
        return 1;
    }
    """
    int read_number "drivekin_read_number"(PyObject* o, double* out) noexcept


# The rules every numpy argument in drivekin follows (callers have checked PyArray_Check).

cdef inline int check_float64(cnp.ndarray a, str what) except -1:
    # float64 in native byte order, never converted: object arrays would run __float__
    # code, ints hide a caller's mistake, and the kernels read the bytes as C doubles.
    if cnp.PyArray_TYPE(a) != cnp.NPY_DOUBLE or not cnp.PyArray_ISNOTSWAPPED(a):
        raise TypeError(f"{what} must have dtype float64 (native byte order), got {a.dtype}")
    return 0


cdef inline int check_memory(cnp.ndarray a, str what, bint contiguous, bint writable,
                             str hint='') except -1:
    # Read (or written) through C pointers: aligned, C-contiguous where the caller walks it
    # without strides, writeable for results.
    if (contiguous and not cnp.PyArray_IS_C_CONTIGUOUS(a)) or not cnp.PyArray_ISALIGNED(a):
        raise ValueError(f"{what} must be {'C-contiguous and ' if contiguous else ''}"
                         f"aligned{hint}")
    if writable and not cnp.PyArray_ISWRITEABLE(a):
        raise ValueError(f"{what} must be writeable")
    return 0


cdef inline char* vector_data(object arr, Py_ssize_t n, bint writable, str what,
                              Py_ssize_t* stride) except NULL:
    """Validate a 1-D float64 array of n values (any stride; callers have checked
    PyArray_Check) and return its data, with its stride in ``stride[0]``."""
    cdef cnp.ndarray a = <cnp.ndarray>arr
    check_float64(a, what)
    if cnp.PyArray_NDIM(a) != 1 or a.shape[0] != n:
        raise ValueError(f"{what} must have shape ({n},), got {arr.shape}")
    check_memory(a, what, False, writable)
    stride[0] = cnp.PyArray_STRIDES(a)[0]
    return <char*>cnp.PyArray_DATA(a)


cdef inline int read_floats(object values, Py_ssize_t n, double* out, str what,
                            str items) except -1:
    """Copy n numbers from a list or tuple of floats/ints or a 1-D float64 array into
    ``out``; ``items`` names them in the length error. Other iterables are refused."""
    cdef Py_ssize_t i, size, stride
    cdef int bad
    cdef PyObject** seq
    cdef char* data
    if PyList_CheckExact(values) or PyTuple_CheckExact(values):
        size = PySequence_Fast_GET_SIZE(values)
        if size != n:
            raise ValueError(f"{what} must hold {n} {items}, got {size}")
        seq = PySequence_Fast_ITEMS(values)
        for i in range(size):
            bad = read_number(seq[i], &out[i])
            if bad == 1:
                from drivekin._errors import type_name
                raise TypeError(f"{what}[{i}] must be a float, got {type_name(<object>seq[i])}")
            if bad == 2:
                raise ValueError(f"{what}[{i}] is an int too large for a float")
        return 0
    if not cnp.PyArray_Check(values):
        from drivekin._errors import type_name
        raise TypeError(f"{what} must be a list or tuple of {n} floats or a 1-D float64 "
                        f"array, got {type_name(values)}")
    data = vector_data(values, n, False, what, &stride)
    for i in range(n):
        out[i] = (<double*>(data + i * stride))[0]
    return 0
