# Odometry for every drivetrain (WPILib 2027 semantics): the pose is integrated from
# wheel-position changes, with the heading change taken from the gyro (or, for dead wheels
# without one, from the wheels). ``_step`` is ``update`` without building the returned
# Pose2d, for the pose estimators; ``_motion`` is the drivetrain's part of a step on
# readings already in C memory (wheel or module deltas to the robot-frame motion, updating
# the stored readings), shared with the batch replay (drivekin.batch), which handles the
# gyro for many samples at once.
cimport cython
from drivekin._core.types cimport pose2_t, rot2_t, twist2_t
from drivekin.geometry cimport Rotation2d
from drivekin.swerve cimport SwerveDriveKinematics
from drivekin.mecanum cimport MecanumDriveKinematics, MecanumDriveWheelPositions
from drivekin.deadwheel cimport DeadWheelKinematics


cdef class _Odometry:
    cdef pose2_t pose            # current pose estimate (field frame, m)
    cdef rot2_t prev_gyro        # gyro reading at the last update/reset
    cdef twist2_t twist          # the last update's motion, in the previous pose's frame
    cdef bint ready              # set by a completed __init__; nothing computes before
    cdef int _start_init(self) except -1

@cython.final
cdef class SwerveDriveOdometry(_Odometry):
    cdef SwerveDriveKinematics kin
    cdef double* prev            # module distances at the last update, m (n values)
    cdef int _step(self, Rotation2d gyroAngle, object modulePositions) except -1
    cdef void _motion(self, double* dist, const double* c, const double* s,
                      double* r) noexcept nogil

@cython.final
cdef class MecanumDriveOdometry(_Odometry):
    cdef MecanumDriveKinematics kin
    cdef double prev[4]          # wheel distances at the last update, m
    cdef int _step(self, Rotation2d gyroAngle, MecanumDriveWheelPositions wheelPositions) except -1
    cdef void _motion(self, const double* w, double* r) noexcept nogil

@cython.final
cdef class DifferentialDriveOdometry(_Odometry):
    cdef double prev_l, prev_r   # wheel distances at the last update, m
    cdef int _step(self, Rotation2d gyroAngle, double leftDistance,
                   double rightDistance) except -1
    cdef void _motion(self, double leftDistance, double rightDistance,
                      double* r) noexcept nogil

@cython.final
cdef class TwoDeadWheelOdometry(_Odometry):
    cdef double x_wheel_y        # xWheelYPos: y of the forward-facing wheel, m
    cdef double y_wheel_x        # yWheelXPos: x of the left-facing wheel, m
    cdef double prev_x, prev_y   # wheel distances at the last update, m
    cdef int _step(self, double xWheelPos, double yWheelPos, Rotation2d gyroAngle) except -1
    cdef void _motion(self, double xWheelPos, double yWheelPos, double dtheta,
                      double* r) noexcept nogil

@cython.final
cdef class DeadWheelOdometry(_Odometry):
    cdef DeadWheelKinematics kin
    cdef double* prev            # wheel distances at the last update, m (n values)
    cdef bint gyro               # fixed at construction: heading from a gyro
    cdef int _gyro_arg(self, object gyroAngle, str call) except -1
    cdef int _step(self, object wheelPositions, object gyroAngle) except -1
    cdef void _motion(self, double* dist, double dtheta, double* r) noexcept nogil
