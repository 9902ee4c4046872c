# Swerve module values and SwerveDriveKinematics. The module values hold C doubles by
# value (the angle is a rot2_t, not a Rotation2d object), so results can be written in
# place without creating Python objects.
cimport cython
from drivekin._core.drivetrain cimport Drivetrain
from drivekin._core.types cimport vec3_t, rot2_t, vec2_t
from drivekin.chassis cimport ChassisVelocities
from drivekin.geometry cimport Translation2d


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


@cython.final
cdef class SwerveDriveKinematics(Drivetrain):
    cdef Py_ssize_t n            # number of modules
    cdef double* buf             # one allocation holding every array below
    cdef double* mx              # module x, m (robot frame)
    cdef double* my              # module y, m
    cdef double* rx              # module x minus centre of rotation, m
    cdef double* ry              # module y minus centre of rotation, m
    cdef double* hc              # heading memory, cos
    cdef double* hs              # heading memory, sin
    cdef double* f1              # 3 x 2n pseudo-inverse of the velocity matrix (CoR 0)
    cdef double* f2              # 4 x 2n pseudo-inverse of the acceleration matrix (CoR 0)
    cdef double* s0              # scratch, n
    cdef double* s1              # scratch, n
    cdef double* s2              # scratch, n
    cdef double* s3              # scratch, n
    cdef vec2_t cor              # centre of rotation the rx/ry rows were built for, m
    cdef tuple modules           # the Translation2d objects, constructor order

    cdef int _refuse_reinit(self) except -1
    cdef int _ik(self, ChassisVelocities cv, Translation2d cor) except -1
    cdef int _deltas(self, object start, object end) except -1
    cdef int _read(self, object states, type cls, str what) except -1
    cdef int _desaturated_discretize(self, vec3_t v, double dt, double limit,
                                     vec3_t* out) except -1


cdef int check_desaturated_discretize(vec3_t v, double dt, double limit) except -1
