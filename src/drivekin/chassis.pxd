# Chassis-level value types: (vx, vy, omega) and (ax, ay, alpha) held by value as a vec3_t.
cimport cython
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


cdef inline ChassisVelocities new_chassis_velocities(double vx, double vy, double omega):
    cdef ChassisVelocities o = ChassisVelocities.__new__(ChassisVelocities)
    o.v.x = vx
    o.v.y = vy
    o.v.z = omega
    return o
