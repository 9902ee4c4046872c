# Odometry for every drivetrain (WPILib 2027 semantics): the pose is integrated from
# wheel-position changes, with the heading change taken from the gyro (or, for dead wheels
# without one, from the wheels). ``_step`` is ``update`` without building the returned
# Pose2d, for the pose estimators. The odometry half of the drivetrain contract is
# ``_motions``: the drivetrain's part of k steps on readings already in C memory (wheel or
# module positions to the robot-frame motion, updating the stored readings), which the
# batch replay (drivekin.batch) composes with the gyro and the pose for many samples at
# once. Each class's ``_step`` does the same arithmetic for one sample.
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
    cdef Py_ssize_t width        # position values per sample (steered: modules)
    cdef bint steered            # a sample is (width, 2) [distance m, angle rad]; else (width,)
    cdef bint gyro               # the heading change comes from a gyro (else from the wheels)
    cdef int _start_init(self) except -1
    # The odometry half of the drivetrain contract: k samples of positions; for a steered
    # drivetrain module-major distances x[k·j + i] (overwritten) with the module directions
    # c, s, otherwise rows x[width·i + j]. With a gyro, dth[i] is the heading change of
    # sample i (given); without one it is solved and written. Writes the robot-frame
    # motion dx[i] = mxy[i], dy[i] = mxy[k + i] and leaves the stored readings at the last
    # sample; ``scratch`` holds ``width`` doubles.
    cdef void _motions(self, Py_ssize_t k, double* x, const double* c, const double* s,
                       double* dth, double* mxy, double* scratch) noexcept nogil   # OUT mxy

@cython.final
cdef class SwerveDriveOdometry(_Odometry):
    cdef SwerveDriveKinematics kin
    cdef double* prev            # module distances at the last update, m (n values)
    cdef int _step(self, Rotation2d gyro_angle, object wheel_positions) except -1
    cdef void _motion(self, double* dist, const double* c, const double* s,
                      double* r) noexcept nogil

@cython.final
cdef class MecanumDriveOdometry(_Odometry):
    cdef MecanumDriveKinematics kin
    cdef double prev[4]          # wheel distances at the last update, m
    cdef int _step(self, Rotation2d gyro_angle,
                   MecanumDriveWheelPositions wheel_positions) except -1
    cdef void _motion(self, const double* w, double* r) noexcept nogil

@cython.final
cdef class DifferentialDriveOdometry(_Odometry):
    cdef double prev_l, prev_r   # wheel distances at the last update, m
    cdef int _step(self, Rotation2d gyro_angle, double left_distance,
                   double right_distance) except -1
    cdef void _motion(self, double left_distance, double right_distance,
                      double* r) noexcept nogil

@cython.final
cdef class TwoDeadWheelOdometry(_Odometry):
    cdef double x_wheel_y        # x_wheel_y_pos: y of the forward-facing wheel, m
    cdef double y_wheel_x        # y_wheel_x_pos: x of the left-facing wheel, m
    cdef double prev_x, prev_y   # wheel distances at the last update, m
    cdef int _step(self, double x_wheel_pos, double y_wheel_pos,
                   Rotation2d gyro_angle) except -1
    cdef void _motion(self, double x_wheel_pos, double y_wheel_pos, double dtheta,
                      double* r) noexcept nogil

@cython.final
cdef class DeadWheelOdometry(_Odometry):
    cdef DeadWheelKinematics kin
    cdef double* prev            # wheel distances at the last update, m (n values)
    cdef int _gyro_arg(self, object gyro_angle, str call) except -1
    cdef int _step(self, object wheel_positions, object gyro_angle) except -1
    cdef void _motion(self, double* dist, double dtheta, double* r) noexcept nogil
