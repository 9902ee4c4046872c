# The swerve module values. They hold C doubles by value (the angle is a rot2_t, not a
# Rotation2d object), so results can be written in place without creating Python objects.
cimport cython
from drivekin._core.types cimport rot2_t


cdef class _ModuleVector:
    cdef double m                # velocity m/s, distance m or acceleration m/s^2
    cdef rot2_t a                # module angle
    cdef _ModuleVector _new(self, double m, rot2_t a)
    cdef _ModuleVector _lerp(self, _ModuleVector end, double t)

@cython.final
cdef class SwerveModuleVelocity(_ModuleVector):
    pass

@cython.final
cdef class SwerveModulePosition(_ModuleVector):
    pass

@cython.final
cdef class SwerveModuleAcceleration(_ModuleVector):
    pass


cdef inline SwerveModuleVelocity new_module_velocity(double v, rot2_t a):
    cdef SwerveModuleVelocity o = SwerveModuleVelocity.__new__(SwerveModuleVelocity)
    o.m = v
    o.a = a
    return o

cdef inline SwerveModulePosition new_module_position(double d, rot2_t a):
    cdef SwerveModulePosition o = SwerveModulePosition.__new__(SwerveModulePosition)
    o.m = d
    o.a = a
    return o


cdef object new_modules(Py_ssize_t n, type cls)
