# PathPlannerLib's swerve setpoint generator: the constraints it takes, the setpoint it
# produces, and the generator, whose kernel and C state live in _core/setpointkernel.pxd
# (shared with drivekin.batch); the robot description is drivekin.robotconfig's.
cimport cython
from drivekin._core.setpointkernel cimport SetpointKernel
from drivekin.chassis cimport ChassisVelocities
from drivekin cimport robotconfig
from drivekin.swerve cimport SwerveDriveKinematics


@cython.final
cdef class DriveFeedforwards:
    cdef Py_ssize_t n
    cdef double* d               # 5 rows of n: acceleration, force, current, force x, force y
    cdef tuple _row(self, int k)


@cython.final
cdef class PathConstraints:
    cdef double max_v, max_a, max_w, max_alpha, nominal
    cdef bint is_unlimited
    cdef bint frozen


@cython.final
cdef class SwerveSetpoint:
    cdef ChassisVelocities v
    cdef tuple modules           # SwerveModuleVelocity objects this setpoint owns
    cdef DriveFeedforwards ff
    cdef int _ready(self) except -1


@cython.final
cdef class SwerveSetpointGenerator(SetpointKernel):
    cdef robotconfig.RobotConfig cfg
    cdef SwerveDriveKinematics kin
    cdef object compat_name      # None or "pathplanner"
