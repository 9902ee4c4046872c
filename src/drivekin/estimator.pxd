# Pose estimators: odometry fused with vision measurements (WPILib 2027's PoseEstimator).
cimport cython
from drivekin._core.types cimport pose2_t, rot2_t, twist2_t
from drivekin.geometry cimport Pose2d, Rotation2d
from drivekin.mecanum cimport MecanumDriveWheelPositions
from drivekin.odometry cimport (DeadWheelOdometry, DifferentialDriveOdometry,
                                MecanumDriveOdometry, SwerveDriveOdometry,
                                TwoDeadWheelOdometry, _Odometry)


cdef struct sample_t:
    double t                     # s
    pose2_t p                    # odometry pose at t (field frame, m)
    twist2_t tw                  # the odometry step from the previous sample to this one,
    bint joined                  # when that is what it is (see _after_update)

cdef struct record_t:
    # A vision correction: at time t the odometry said ``odometry``, the corrected pose is
    # ``vision``; later odometry motion is replayed from there (compensate()).
    double t
    pose2_t vision
    pose2_t odometry
    pose2_t shift                # vision ∘ odometry⁻¹, so compensating is one composition


cdef class _PoseEstimator:
    cdef _Odometry odo           # the concrete estimator's odometry (typed there too)
    cdef double sd[3]            # state standard deviations (x m, y m, θ rad)
    cdef double k[3]             # per-axis vision gains
    cdef pose2_t estimate
    cdef sample_t* buf           # odometry poses, ascending time: buf[start : start + count]
    cdef Py_ssize_t start, count, cap
    cdef bint tail_is_odometry   # the newest sample is the odometry's current pose
    cdef record_t* rec           # vision records, ascending time: rec[0 : nrec]
    cdef Py_ssize_t nrec, rcap
    cdef bint ready
    cdef bint clock_warned       # ClockMismatchWarning issued

    cdef int _init(self, _Odometry odo, object state_std_devs, object vision_std_devs) except -1
    cdef int _start(self) except -1
    cdef int _check(self) except -1
    cdef int _reserve(self) except -1
    cdef int _set_vision_std_devs(self, object values) except -1
    cdef int _after_update(self, double t) except -1
    cdef void _clear(self) noexcept
    cdef bint _sample(self, double t, pose2_t* out) noexcept
    cdef bint _sample_at(self, double t, pose2_t* out) noexcept
    cdef Py_ssize_t _first_record_after(self, double t) noexcept
    cdef int _warn_clock(self, double timestamp, double newest) except -1
    cdef void _clear_keeping_latest(self, bint translation, double x, double y,
                                    rot2_t r) noexcept
    cdef int _reset_done(self) except -1


@cython.final
cdef class SwerveDrivePoseEstimator(_PoseEstimator):
    cdef SwerveDriveOdometry swerve
    cdef Pose2d _at(self, double t, Rotation2d gyro_angle, object wheel_positions)

@cython.final
cdef class MecanumDrivePoseEstimator(_PoseEstimator):
    cdef MecanumDriveOdometry mecanum
    cdef Pose2d _at(self, double t, Rotation2d gyro_angle,
                    MecanumDriveWheelPositions wheel_positions)

@cython.final
cdef class DifferentialDrivePoseEstimator(_PoseEstimator):
    cdef DifferentialDriveOdometry differential
    cdef Pose2d _at(self, double t, Rotation2d gyro_angle, object left_distance,
                    object right_distance)

@cython.final
cdef class TwoDeadWheelPoseEstimator(_PoseEstimator):
    cdef TwoDeadWheelOdometry two
    cdef Pose2d _at(self, double t, double x_wheel_pos, double y_wheel_pos,
                    Rotation2d gyro_angle)

@cython.final
cdef class DeadWheelPoseEstimator(_PoseEstimator):
    cdef DeadWheelOdometry dead
    cdef Pose2d _at(self, double t, object wheel_positions, object gyro_angle)
