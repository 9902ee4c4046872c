# Shared base of the per-wheel value classes (mecanum: 4 wheels, differential: 2).
cdef class _WheelValues:
    cdef double w[4]             # wheel values in the drivetrain's order (m/s, m or m/s^2)
    cdef Py_ssize_t k            # number of wheels used (2 or 4)
    cdef _WheelValues _new(self)
    cdef _WheelValues _check(self, object other)
    cdef _WheelValues _lerp(self, _WheelValues end, double t)
    cdef bint _close(self, _WheelValues o) noexcept
    cdef bint _equal(self, _WheelValues o) noexcept
    cdef str _fmt(self, tuple labels, str unit)

cdef int install_bare_new(tuple classes, Py_ssize_t count) except -1
