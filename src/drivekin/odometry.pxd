# Odometry for the three drivetrains (WPILib 2027 semantics): the pose is integrated from
# wheel-position changes, with the heading change always taken from the gyro.
cimport cython
from drivekin._types cimport pose2_t, rot2_t
from drivekin.geometry cimport Rotation2d
from drivekin.kinematics cimport SwerveDriveKinematics
from drivekin.mecanum cimport MecanumDriveKinematics


cdef class _Odometry:
    cdef pose2_t pose            # current pose estimate (field frame, m)
    cdef rot2_t prev_gyro        # gyro reading at the last update/reset
    cdef bint ready              # set by a completed __init__; nothing computes before
    cdef int _start_init(self) except -1

@cython.final
cdef class SwerveDriveOdometry(_Odometry):
    cdef SwerveDriveKinematics kin
    cdef double* prev            # module distances at the last update, m (n values)

@cython.final
cdef class MecanumDriveOdometry(_Odometry):
    cdef MecanumDriveKinematics kin
    cdef double prev[4]          # wheel distances at the last update, m

@cython.final
cdef class DifferentialDriveOdometry(_Odometry):
    cdef double prev_l, prev_r   # wheel distances at the last update, m
