# The argument rules of the façade (docs/DESIGN.md, "Memory safety"), one helper per rule,
# inlined into every module that takes arguments: exact type tests on borrowed pointers;
# sequences read through PySequence_Fast, with buffers and strings refused; strong
# references taken before anything can allocate (snapshot); numbers read without running
# Python code; numpy arguments float64, aligned and (where walked without strides)
# C-contiguous, writeable for results. Error messages import their helper on the cold
# path: a .pxd cannot import at module level.
cimport numpy as cnp
from cpython.buffer cimport PyObject_CheckBuffer
from cpython.float cimport PyFloat_Check
from cpython.long cimport PyLong_CheckExact
from cpython.list cimport PyList_CheckExact, PyList_GET_ITEM, PyList_GET_SIZE
from cpython.mem cimport PyMem_Free, PyMem_Malloc
from cpython.ref cimport Py_DECREF, Py_INCREF, PyObject
from cpython.sequence cimport PySequence_Fast, PySequence_Fast_GET_SIZE, PySequence_Fast_ITEMS
from cpython.tuple cimport PyTuple_CheckExact, PyTuple_New, PyTuple_SET_ITEM
from libc.math cimport isfinite


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


cdef extern from *:
    """
    static inline int drivekin_exact(PyObject *o, PyObject *t) {
        return Py_TYPE(o) == (PyTypeObject *)t;
    }
    """
    # Exact type test on a borrowed pointer: no reference counting on the hot loops.
    bint exact_type "drivekin_exact"(PyObject* o, PyObject* t) noexcept


# Typed parameters. A def parameter typed as an extension class gets Cython's own test,
# whose fixed message ("Argument 'pose' has incorrect type (expected
# drivekin.geometry.Pose2d, got wpimath.geometry._geometry.Pose2d)") cannot say how to
# convert a robotpy object. So the public methods and constructors take such parameters
# untyped, annotated with their class for the embedded signature (setup.py turns
# annotation typing off), test them with check_type first and cast them where they are
# used, ``(<Pose2d>pose).p``: the pointer compare of Cython's test, and no reference
# counting (a typed local would add an incref and a decref, about 5 instructions a
# parameter). The failure branch is a separate function that is never inlined, so the
# test inlines everywhere; it raises drivekin._core.errors.wrong_type's TypeError
# ("pose must be a Pose2d, got NoneType", and for a robotpy-wpimath object the
# drivekin.interop call that converts it).
cdef extern from *:
    """
    #if defined(__GNUC__)
    #define DRIVEKIN_NOINLINE __attribute__((noinline))
    #elif defined(_MSC_VER)
    #define DRIVEKIN_NOINLINE __declspec(noinline)
    #else
    #define DRIVEKIN_NOINLINE
    #endif

    static CYTHON_UNUSED DRIVEKIN_NOINLINE int drivekin_wrong_type(PyObject *obj,
                                                                   PyTypeObject *expected,
                                                                   PyObject *name) {
        PyObject *errors = PyImport_ImportModule("drivekin._core.errors");
        PyObject *exc;
        if (errors == NULL) return -1;
        exc = PyObject_CallMethod(errors, "wrong_type", "OOO", obj, expected, name);
        Py_DECREF(errors);
        if (exc != NULL) {
            PyErr_SetObject((PyObject *)Py_TYPE(exc), exc);
            Py_DECREF(exc);
        }
        return -1;
    }

    /* Exact type test: the value classes are final, so it is isinstance; None fails it. */
    static CYTHON_UNUSED inline int drivekin_check_type(PyObject *obj, PyTypeObject *expected,
                                                       PyObject *name) {
        if (Py_TYPE(obj) == expected) return 0;
        drivekin_wrong_type(obj, expected, name);
        return -1;                  /* a constant, so the caller's error test folds away */
    }
    """
    # ``name`` is the parameter's name. For a parameter of a shared base that must be of
    # the receiver's class (ChassisVelocities.plus), ``expected`` is type(self).
    int check_type "drivekin_check_type"(object obj, type expected, str name) except -1


cdef inline int refuse_reinit(bint frozen, object self) except -1:
    # Immutable values (and the shared constants such as Rotation2d.kZero) must not change
    # when someone calls __init__ on an existing instance.
    if frozen:
        raise TypeError(f"{type(self).__name__} is immutable: __init__ cannot be called "
                        "on an existing instance")
    return 0


cdef inline int positive_finite(double x, str name, str unit) except -1:
    if not (isfinite(x) and x > 0.0):
        raise ValueError(f"{name} must be a positive finite {unit}, got {x!r}")
    return 0


cdef inline long long count_arg(object x, str name, long long low) except -1:
    # A count (motors, modules): an exact int from low to Java's int max.
    if not PyLong_CheckExact(x):
        from drivekin._core.errors import type_name
        raise TypeError(f"{name} must be an int, got {type_name(x)}")
    if not low <= x <= 2147483647:
        raise ValueError(f"{name} must be an int from {low} to 2147483647, got {x!r}")
    return <long long>x


cdef inline bint is_number(object x) noexcept:
    # A float (numpy.float64 included) or an exact int: what robotpy converts implicitly
    # to a Rotation2d in radians (never a bool, a str or an object with __float__).
    return PyFloat_Check(x) or PyLong_CheckExact(x)


# Sequences of value objects

cdef inline bint is_array(object x) noexcept:
    # A numpy array passed where a list or tuple of values is the other accepted form.
    return not (PyTuple_CheckExact(x) or PyList_CheckExact(x)) and cnp.PyArray_Check(x)


cdef inline object as_fast(object seq, str what, str expected="a sequence of objects",
                           str hint="; where an (N, 2) array is accepted, pass a float64 "
                                    "numpy array", bint numbers=False):
    """Return a list/tuple view of ``seq`` (no copy for lists and tuples). Buffers are
    refused: iterating them yields numbers, never value objects; so are strings where the
    items are ``numbers``. ``expected`` and ``hint`` complete that error message."""
    if PyTuple_CheckExact(seq) or PyList_CheckExact(seq):
        return seq
    if PyObject_CheckBuffer(seq) or (numbers and isinstance(seq, str)):
        from drivekin._core.errors import type_name
        raise TypeError(f"{what} must be {expected}, got {type_name(seq)}{hint}")
    try:
        return PySequence_Fast(seq, "")
    except TypeError:
        from drivekin._core.errors import type_name
        raise TypeError(f"{what} must be a sequence, got {type_name(seq)}") from None


cdef inline tuple snapshot(object seq, str what):
    """Return a tuple of the items of ``seq`` that owns a reference to each.

    ``tuple(a_list)`` is not enough: CPython allocates the tuple before copying the list's
    item pointers, and that allocation can run a finalizer that empties the list, leaving
    the copy reading freed items. Here the references are taken first, in memory whose
    allocation never runs the garbage collector."""
    cdef Py_ssize_t i, n
    cdef PyObject** refs
    cdef tuple t
    if PyTuple_CheckExact(seq):
        return <tuple>seq
    if not PyList_CheckExact(seq):
        return tuple(as_fast(seq, what))        # a fresh list or tuple: no one else sees it
    n = PyList_GET_SIZE(seq)
    refs = <PyObject**>PyMem_Malloc(sizeof(PyObject*) * (n + 1))
    if refs == NULL:
        raise MemoryError()
    for i in range(n):
        refs[i] = PyList_GET_ITEM(seq, i)
        Py_INCREF(<object>refs[i])
    try:
        t = PyTuple_New(n)
    except BaseException:
        for i in range(n):
            Py_DECREF(<object>refs[i])
        PyMem_Free(refs)
        raise
    for i in range(n):
        PyTuple_SET_ITEM(t, i, <object>refs[i])    # steals the reference taken above
    PyMem_Free(refs)
    return t


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


cdef inline double* float64_data(object arr, Py_ssize_t rows, Py_ssize_t cols,
                                 bint writable, str name) except NULL:
    """Validate a float64 C-contiguous aligned native-endian numpy array of shape (rows,)
    (cols = 0) or (rows, cols) (rows = -1: any) and return its data. Callers have checked
    PyArray_Check(arr)."""
    cdef cnp.ndarray a = <cnp.ndarray>arr
    cdef int ndim = 1 if cols == 0 else 2
    cdef str n
    check_float64(a, name)
    if (cnp.PyArray_NDIM(a) != ndim or (rows >= 0 and a.shape[0] != rows)
            or (cols > 0 and a.shape[1] != cols)):
        n = str(rows) if rows >= 0 else "N"
        raise ValueError(f"{name} must have shape {f'({n},)' if cols == 0 else f'({n}, {cols})'}, "
                         f"got {(<object>a).shape}")
    check_memory(a, name, True, writable)
    return <double*>cnp.PyArray_DATA(a)


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
                from drivekin._core.errors import type_name
                raise TypeError(f"{what}[{i}] must be a float, got {type_name(<object>seq[i])}")
            if bad == 2:
                raise ValueError(f"{what}[{i}] is an int too large for a float")
        return 0
    if not cnp.PyArray_Check(values):
        from drivekin._core.errors import type_name
        raise TypeError(f"{what} must be a list or tuple of {n} floats or a 1-D float64 "
                        f"array, got {type_name(values)}")
    data = vector_data(values, n, False, what, &stride)
    for i in range(n):
        out[i] = (<double*>(data + i * stride))[0]
    return 0
