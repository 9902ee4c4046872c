# 3-D pose estimators (WPILib 2027's PoseEstimator3d): 3-D odometry fused with vision. The
# history's and records' bookkeeping in time is drivekin.estimator's _EstimatorBase, shared
# with the 2-D estimators; this module stores 3-D poses in it.
cimport cython
from drivekin._core.types cimport pose3_t, twist3_t, vec3_t
from drivekin.estimator cimport _EstimatorBase, stamp_t
from drivekin.geometry3d cimport Pose3d
from drivekin.odometry3d cimport _Odometry3d


cdef struct sample3_t:
    stamp_t s
    pose3_t p                    # odometry pose at s.t (field frame, m)
    twist3_t tw                  # the odometry step from the previous sample, when s.joined

cdef struct record3_t:
    # A vision correction (see drivekin.estimator's record_t).
    double t                     # s: first, as the shared bookkeeping reads it
    pose3_t vision
    pose3_t odometry
    pose3_t shift                # vision ∘ odometry⁻¹, so compensating is one composition


cdef class _PoseEstimator3d(_EstimatorBase):
    cdef _Odometry3d odo         # the concrete estimator's odometry
    cdef pose3_t estimate

    cdef int _init(self, _Odometry3d odo, object state_std_devs,
                   object vision_std_devs) except -1
    # updateWithTime; the caller has checked that gyro_angle is a Rotation3d, and the
    # odometry reads a and b (its one or two wheel-reading arguments).
    cdef Pose3d _at(self, double t, object gyro_angle, object a, object b)
    cdef bint _sample(self, double t, pose3_t* out) noexcept
    cdef bint _sample_at(self, double t, pose3_t* out) noexcept
    cdef int _reset_done(self) except -1
    cdef void _keep_latest(self, bint translation, vec3_t t, pose3_t odometry) noexcept


@cython.final
cdef class SwerveDrivePoseEstimator3d(_PoseEstimator3d):
    pass

@cython.final
cdef class MecanumDrivePoseEstimator3d(_PoseEstimator3d):
    pass

@cython.final
cdef class DifferentialDrivePoseEstimator3d(_PoseEstimator3d):
    cdef Pose3d _pair(self, double t, object gyro_angle, object first, object second)

@cython.final
cdef class DeadWheelPoseEstimator3d(_PoseEstimator3d):
    pass

@cython.final
cdef class TwoDeadWheelPoseEstimator3d(_PoseEstimator3d):
    pass
