# Odometry for every drivetrain (WPILib 2027 semantics), written once on the drivetrain
# contract (_core/drivetrain.pxd, Drivetrain._twists): _Odometry holds the state (pose,
# gyro and wheel baselines), does the step (odometry.pyx's advance: the readings' changes,
# the drivetrain's motion for the gyro's heading change, or the wheels' own without a
# gyro, and the pose move), the resets and the batch replay's half (_motions); each class
# only reads its WPILib arguments into C memory. ``_step`` is ``update`` without building
# the returned Pose2d, for the pose estimators.
cimport cython
from drivekin._core.drivetrain cimport Drivetrain
from drivekin._core.types cimport pose2_t, rot2_t, twist2_t
from drivekin.geometry cimport Rotation2d
from drivekin.mecanum cimport MecanumDriveWheelPositions


cdef class _Odometry:
    cdef pose2_t pose            # current pose estimate (field frame, m)
    cdef rot2_t prev_gyro        # gyro reading at the last update/reset
    cdef twist2_t twist          # the last update's motion, in the previous pose's frame
    cdef bint ready              # set by a completed __init__; nothing computes before
    cdef Drivetrain kin          # the drivetrain: the caller's kinematics or an internal one
    cdef double* prev            # the wheel readings at the last update/reset (width, m)
    cdef Py_ssize_t width        # position values per sample (steered: modules)
    cdef bint steered            # a sample is (width, 2) [distance m, angle rad]; else (width,)
    cdef bint gyro               # the heading change comes from a gyro (else from the wheels)
    cdef int _start_init(self) except -1
    # The end of every __init__: ``readings`` (width values in C memory) become the
    # baseline; gyro_angle is a Rotation2d, or None without a gyro.
    cdef int _setup(self, Drivetrain kin, Py_ssize_t width, bint steered, object gyro_angle,
                    pose2_t p, const double* readings) except -1
    # resetPosition's state change (gyro NULL without a gyro).
    cdef void _reset(self, const rot2_t* gyro, pose2_t p, const double* readings) noexcept
    # The odometry half of batch replay: k samples of readings, wheel-major x[k·j + i]
    # (overwritten with their changes), steered with the module directions c, s. With a
    # gyro, dth[i] is the heading change of sample i (given); without one it is solved and
    # written. Writes the robot-frame motion dx[i] = mxy[i], dy[i] = mxy[k + i] (mxy: 3k
    # values) and leaves the stored readings at the last sample.
    cdef void _motions(self, Py_ssize_t k, double* x, const double* c, const double* s,
                       double* dth, double* mxy) noexcept nogil   # OUT mxy

@cython.final
cdef class SwerveDriveOdometry(_Odometry):
    cdef int _step(self, Rotation2d gyro_angle, object wheel_positions) except -1

@cython.final
cdef class MecanumDriveOdometry(_Odometry):
    cdef int _step(self, Rotation2d gyro_angle,
                   MecanumDriveWheelPositions wheel_positions) except -1

@cython.final
cdef class DifferentialDriveOdometry(_Odometry):
    cdef int _step(self, Rotation2d gyro_angle, double left_distance,
                   double right_distance) except -1

@cython.final
cdef class TwoDeadWheelOdometry(_Odometry):
    cdef int _step(self, double x_wheel_pos, double y_wheel_pos,
                   Rotation2d gyro_angle) except -1

@cython.final
cdef class DeadWheelOdometry(_Odometry):
    cdef int _gyro_arg(self, object gyro_angle, str call) except -1
    cdef int _step(self, object wheel_positions, object gyro_angle) except -1
