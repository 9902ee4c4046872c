# Chassis-level value types: (vx, vy, omega) and (ax, ay, alpha) held by value as a vec3_t.
cimport cython
from libc.math cimport fabs
from drivekin._core.types cimport rot2_t, vec3_t


cdef class _ChassisVector:
    cdef vec3_t v                # (vx, vy, omega) or (ax, ay, alpha)
    cdef _ChassisVector _new(self, double x, double y, double z)
    cdef _rotated_into(self, rot2_t r, _ChassisVector out)

@cython.final
cdef class ChassisVelocities(_ChassisVector):
    pass

@cython.final
cdef class ChassisAccelerations(_ChassisVector):
    pass


cdef int check_discretize_fits(vec3_t v, double dt) except -1

cdef inline bint discretize_is_large(double vx, double vy, double omega) noexcept nogil:
    # discretize's result is (k·vx + h·vy, −h·vx + k·vy, ω or φ/dt) with 0 ≤ k ≤ 1,
    # |h| ≤ π/2 and |φ/dt| ≤ |ω| to rounding: it can exceed the doubles only where a
    # component is above 1e307 (check_discretize_fits then computes it to see).
    return fabs(vx) > 1e307 or fabs(vy) > 1e307 or fabs(omega) > 1e307


cdef inline ChassisVelocities new_chassis_velocities(double vx, double vy, double omega):
    cdef ChassisVelocities o = ChassisVelocities.__new__(ChassisVelocities)
    o.v.x = vx
    o.v.y = vy
    o.v.z = omega
    return o
