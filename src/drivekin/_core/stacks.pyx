"""The argument rules of drivekin.batch (declared in stacks.pxd): float64 stacks and
``out=`` buffers, validated once per call."""
from cpython.mem cimport PyMem_Malloc
cimport numpy as cnp

import numpy as np

from drivekin._core.args cimport check_float64, check_memory
from drivekin._core.errors import type_name

cnp.import_array()


cdef class _Stack:
    pass


cdef str _shape_text(tuple inner):
    return "(" + ", ".join([str(d) for d in inner]) + ("," if len(inner) == 1 else "") + ")"


cdef _Stack _stack(object x, tuple inner, str name, bint single_ok=True):
    """Validate ``x`` as one value of shape ``inner`` or an (N,) + inner stack."""
    cdef _Stack s = _Stack.__new__(_Stack)
    cdef cnp.ndarray a
    cdef tuple shape
    cdef Py_ssize_t d
    if not cnp.PyArray_Check(x):
        raise TypeError(f"{name} must be a float64 numpy array, got {type_name(x)}")
    a = <cnp.ndarray>x
    check_float64(a, name)
    shape = (<object>a).shape
    if single_ok and shape == inner:
        s.single, s.n = True, 1
    elif len(shape) == len(inner) + 1 and shape[1:] == inner:
        s.single, s.n = False, shape[0]
    else:
        want = _shape_text(("N",) + inner)
        if single_ok:
            want = f"{_shape_text(inner)} or {want}"
        raise ValueError(f"{name} must have shape {want}, got {shape}")
    check_memory(a, name, True, False, " (np.ascontiguousarray makes a copy that is)")
    s.width = 1
    for d in inner:
        s.width *= d
    s.array = a
    s.data = <double*>cnp.PyArray_DATA(a)
    return s


cdef Py_ssize_t _rows(object x, Py_ssize_t cols, str name, str shapes) except -1:
    """The wheel or module count of a value whose count is free: the last axis (cols = 0)
    or the one before a last axis of ``cols``."""
    if not cnp.PyArray_Check(x):
        raise TypeError(f"{name} must be a float64 numpy array, got {type_name(x)}")
    cdef tuple shape = (<object>x).shape
    cdef Py_ssize_t nd = len(shape), base = 2 if cols else 1
    if nd != base and nd != base + 1:
        raise ValueError(f"{name} must have shape {shapes}, got {shape}")
    return shape[nd - 2] if cols else shape[nd - 1]


cdef _Stack _per_sample(object x, Py_ssize_t n, bint single, str name):
    """One number per sample: a float (the same for every sample) or, beside a stack of
    n values, an (n,) float64 array. Always returned as n values."""
    cdef _Stack s
    if cnp.PyArray_Check(x):
        s = _stack(x, (), name)
        if s.single or single or s.n != n:
            raise ValueError(f"{name} must be a float" + ("" if single else
                             f" or have shape ({n},) to match the other argument") +
                             f", got an array of shape {x.shape}")
        return s
    if not isinstance(x, (float, int)) or isinstance(x, bool):
        raise TypeError(f"{name} must be a float or a float64 array, got {type_name(x)}")
    return _stack(np.full(n, float(x)), (), name, False)


cdef _Stack _result(object out, Py_ssize_t n, bint single, tuple inner, tuple inputs,
                    str name):
    """``out`` validated for the result's shape, or a new array."""
    cdef tuple shape = inner if single else (n,) + inner
    cdef _Stack s
    cdef _Stack i
    if out is None:
        out = np.empty(shape)
    else:
        if not cnp.PyArray_Check(out):
            raise TypeError(f"out must be a float64 numpy array, got {type_name(out)}")
        if out.shape != shape:
            raise ValueError(f"out must have shape {shape} for this {name}, got {out.shape}")
        if not cnp.PyArray_ISWRITEABLE(<cnp.ndarray>out):
            raise ValueError("out must be writeable")
        for i in inputs:
            if np.may_share_memory(out, i.array):
                raise ValueError("out must not overlap an input array")
    s = _stack(out, inner, "out")
    return s


cdef double* _scratch(Py_ssize_t count) except NULL:
    cdef double* p = <double*>PyMem_Malloc(sizeof(double) * (count if count > 0 else 1))
    if p == NULL:
        raise MemoryError()
    return p



cdef tuple _pair(object a, object b, tuple inner, str name_a, str name_b):
    """``a`` and ``b`` (shape ``inner`` each, single or stacked); two stacks must have one
    length, and a single value goes with every sample of the other."""
    cdef _Stack sa = _stack(a, inner, name_a)
    cdef _Stack sb = _stack(b, inner, name_b)
    if not sa.single and not sb.single and sa.n != sb.n:
        raise ValueError(f"{name_a} has {sa.n} samples but {name_b} has {sb.n}: give one "
                         f"length, or one {_shape_text(inner)} value for every sample")
    return sa, sb
