# SwerveDriveKinematics; the module values it reads and writes are drivekin.swervemodule's.
cimport cython
from drivekin._core.drivetrain cimport Drivetrain
from drivekin._core.types cimport vec2_t, vec3_t
from drivekin.chassis cimport ChassisVelocities
from drivekin.geometry cimport Translation2d


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
