# 3-D odometry (WPILib 2027's Odometry3d): one implementation for every drivetrain, on the
# drivetrain contract's odometry map (Drivetrain._twists). The public classes only read
# their wheel readings into C memory (_read) and keep the kinematics they need.
cimport cython
from drivekin._core.drivetrain cimport Drivetrain
from drivekin._core.types cimport pose3_t, quat_t, twist3_t
from drivekin.geometry3d cimport Rotation3d


cdef class _Odometry3d:
    cdef Drivetrain kin          # the drivetrain's odometry map
    cdef double* prev            # wheel (module) distances at the last update or reset, m
    cdef double scratch[4]       # the current readings, for drivetrains without a scratch
    cdef Py_ssize_t width        # readings per sample
    cdef bint yaw                # the map takes the gyro's yaw change (dead wheels)
    cdef pose3_t pose            # current pose estimate (field frame, m)
    cdef quat_t prev_gyro        # gyro reading at the last update or reset
    cdef twist3_t twist          # the last update's twist, in the previous pose's frame
    cdef bint ready              # set by a completed __init__; nothing computes before

    cdef int _begin(self, Drivetrain kin, Py_ssize_t width, bint yaw, object gyro_angle,
                    object a, object b, object initial_pose) except -1
    # Read one sample of readings (the public classes' one or two arguments) into C memory:
    # ``cur`` the distances (m, writable: they become the changes), ``c``/``s`` the module
    # directions of a steered drivetrain (else NULL). Raises without changing anything.
    cdef int _read(self, object a, object b, double** cur, const double** c,
                   const double** s) except -1
    # update without building the returned Pose3d (the estimators call it).
    cdef int _step(self, Rotation3d gyro_angle, object a, object b) except -1
    cdef int _reset(self, object gyro_angle, object a, object b, object pose) except -1
    cdef void _move(self, quat_t gyro, double* cur, const double* c,
                    const double* s) noexcept nogil


@cython.final
cdef class SwerveDriveOdometry3d(_Odometry3d):
    pass

@cython.final
cdef class MecanumDriveOdometry3d(_Odometry3d):
    pass

@cython.final
cdef class DifferentialDriveOdometry3d(_Odometry3d):
    pass

@cython.final
cdef class DeadWheelOdometry3d(_Odometry3d):
    pass

@cython.final
cdef class TwoDeadWheelOdometry3d(_Odometry3d):
    cdef double x_wheel_y        # x_wheel_y_pos: y of the forward-facing wheel, m
    cdef double y_wheel_x        # y_wheel_x_pos: x of the left-facing wheel, m
