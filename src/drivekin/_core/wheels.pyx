"""Shared behaviour of the mecanum and differential wheel value classes."""
cimport cython
from libc.math cimport fabs

from drivekin._core.errors import refuse_delete, type_name
from drivekin._core.format import f2
from drivekin._core.typedict cimport drivekin_set_type_attr, drivekin_slot_new


@cython.freelist(64)
cdef class _WheelValues:
    """Per-wheel values with component-wise arithmetic (operators + - * / and unary -)."""

    cdef _WheelValues _new(self):
        raise TypeError("_WheelValues is an abstract base; use a wheel values class")

    cdef _WheelValues _check(self, object other):
        if type(other) is not type(self):
            raise TypeError(f"expected a {type(self).__name__}, got {type_name(other)}")
        return <_WheelValues>other

    cdef _WheelValues _lerp(self, _WheelValues end, double t):
        cdef _WheelValues o = self._new()
        cdef Py_ssize_t i
        self._check(end)
        for i in range(self.k):
            o.w[i] = self.w[i] + (end.w[i] - self.w[i]) * t
        return o

    cdef bint _close(self, _WheelValues o) noexcept:
        cdef Py_ssize_t i
        for i in range(self.k):
            if not fabs(self.w[i] - o.w[i]) < 1e-9:
                return False
        return True

    cdef bint _equal(self, _WheelValues o) noexcept:
        # WPILib C++'s defaulted operator== (robotpy's ==): every wheel exactly equal.
        cdef Py_ssize_t i
        for i in range(self.k):
            if not self.w[i] == o.w[i]:
                return False
        return True

    cdef str _fmt(self, tuple labels, str unit):
        fields = ", ".join(f"{lab}: {f2(self.w[i])} {unit}" for i, lab in enumerate(labels))
        return f"{type(self).__name__}({fields})"

    def plus(self, other):
        """Return the wheel-by-wheel sum."""
        cdef _WheelValues o = self._check(other), out = self._new()
        cdef Py_ssize_t i
        for i in range(self.k):
            out.w[i] = self.w[i] + o.w[i]
        return out

    def minus(self, other):
        """Return the wheel-by-wheel difference."""
        cdef _WheelValues o = self._check(other), out = self._new()
        cdef Py_ssize_t i
        for i in range(self.k):
            out.w[i] = self.w[i] - o.w[i]
        return out

    def unaryMinus(self):
        """Return every wheel negated."""
        return self.times(-1.0)

    def times(self, double scalar):
        """Return every wheel multiplied by ``scalar``."""
        cdef _WheelValues out = self._new()
        cdef Py_ssize_t i
        for i in range(self.k):
            out.w[i] = self.w[i] * scalar
        return out

    def div(self, double scalar):
        """Return every wheel divided by ``scalar`` (no zero guard, as in WPILib)."""
        cdef _WheelValues out = self._new()
        cdef Py_ssize_t i
        for i in range(self.k):
            out.w[i] = self.w[i] / scalar
        return out

    def __add__(self, other):
        if type(other) is type(self):
            return self.plus(other)
        return NotImplemented

    def __sub__(self, other):
        if type(other) is type(self):
            return self.minus(other)
        return NotImplemented

    def __neg__(self):
        return self.unaryMinus()

    def __mul__(self, other):
        try:
            return self.times(other)
        except TypeError:
            return NotImplemented

    def __rmul__(self, other):
        return self.__mul__(other)

    def __truediv__(self, other):
        try:
            return self.div(other)
        except TypeError:
            return NotImplemented

    def __iter__(self):
        cdef Py_ssize_t i
        for i in range(self.k):
            yield self.w[i]

    def __reduce__(self):
        return (type(self), tuple([self.w[i] for i in range(self.k)]))

    def __delattr__(self, name):
        refuse_delete(self, name)



cdef int install_bare_new(tuple classes, Py_ssize_t count) except -1:
    """Give each of ``classes`` a Python-level ``__new__`` that returns a valid all-zero
    value with ``count`` wheels.

    Internal factories and ``__init__`` set the wheel count themselves; a ``__cinit__``
    doing it would cost every construction 16 instructions (7 % of a façade call), while
    this only runs for ``cls.__new__(cls)`` called from Python."""
    def __new__(cls, *args, **kwargs):
        if cls not in classes:
            raise TypeError(f"__new__(cls): cls must be one of "
                            f"{', '.join(c.__name__ for c in classes)}, got {cls!r}")
        o = drivekin_slot_new(cls)
        (<_WheelValues>o).k = count
        return o
    for cls in classes:
        drivekin_set_type_attr(cls, "__new__", staticmethod(__new__))
    return 0


def set_type_attr(type cls, str name, object value):
    """Put ``value`` into the dictionary of the extension type ``cls`` under ``name`` (what
    Python code cannot assign on a static type): the 2026 names of _core.renames."""
    drivekin_set_type_attr(cls, name, value)
