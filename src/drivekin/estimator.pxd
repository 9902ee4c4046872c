# Pose estimators: odometry fused with vision measurements (WPILib 2027's PoseEstimator).
# _EstimatorBase holds what does not depend on the pose type, written once for the 2-D
# estimators here and the 3-D ones (drivekin.estimator3d): the pose history's and the
# vision records' bookkeeping in time (C arrays of structs whose first field is the time),
# the gains, the clock checks. Each subclass stores its own poses in those structs.
cimport cython
from libc.string cimport memmove
from drivekin._core.types cimport pose2_t, rot2_t, twist2_t
from drivekin.geometry cimport Pose2d, Rotation2d
from drivekin.mecanum cimport MecanumDriveWheelPositions
from drivekin.odometry cimport (DeadWheelOdometry, DifferentialDriveOdometry,
                                MecanumDriveOdometry, SwerveDriveOdometry,
                                TwoDeadWheelOdometry, _Odometry)


cdef struct stamp_t:
    # The head of every history sample.
    double t                     # s
    bint joined                  # the sample's step twist leads from the previous sample

cdef struct sample_t:
    stamp_t s
    pose2_t p                    # odometry pose at s.t (field frame, m)
    twist2_t tw                  # the odometry step from the previous sample to this one,
                                 # when s.joined (see history_slot)

cdef struct record_t:
    # A vision correction: at time t the odometry said ``odometry``, the corrected pose is
    # ``vision``; later odometry motion is replayed from there (compensate()).
    double t                     # s: first, as the shared bookkeeping reads it
    pose2_t vision
    pose2_t odometry
    pose2_t shift                # vision ∘ odometry⁻¹, so compensating is one composition


cdef extern from *:
    """
    #define DRIVEKIN_HISTORY 1.5
    """
    # s of odometry poses an estimator keeps (WPILib's kBufferDuration)
    const double HISTORY "DRIVEKIN_HISTORY"


cdef double clock_now() except? -1.0
cdef int finite_time(double t, str what) except -1
# (left m, right m) or (DifferentialDriveWheelPositions, None) into l, r.
cdef int wheel_pair(object first, object second, double* l, double* r, str call) except -1


cdef class _EstimatorBase:
    cdef char* buf               # samples of ssize bytes, ascending time: [start, start + count)
    cdef Py_ssize_t ssize, start, count, cap
    cdef bint tail_is_odometry   # the newest sample is the odometry's current pose
    cdef char* rec               # records of rsize bytes, ascending time: [0, nrec)
    cdef Py_ssize_t rsize, nrec, rcap
    cdef Py_ssize_t axes         # standard deviations per vector: 3 (x, y, θ) or 4 (x, y, z, θ)
    cdef double sd[4]            # state standard deviations (m, rad)
    cdef double k[4]             # per-axis vision gains
    cdef bint ready
    cdef bint clock_warned       # ClockMismatchWarning issued

    cdef int _init_history(self, Py_ssize_t axes, Py_ssize_t ssize, Py_ssize_t rsize,
                           object state_std_devs, object vision_std_devs) except -1
    cdef int _start(self) except -1
    cdef int _check(self) except -1
    cdef int _reserve(self) except -1
    @cython.final
    cdef int _admit(self, double timestamp, object std_devs, Py_ssize_t* floor,
                    Py_ssize_t* slot) except -1
    cdef int _set_vision_std_devs(self, object values) except -1
    cdef int _warn_clock(self, double timestamp, double newest) except -1
    cdef void _clear(self) noexcept


cdef inline stamp_t* stamp(char* buf, Py_ssize_t size, Py_ssize_t i) noexcept nogil:
    return <stamp_t*>(buf + i * size)


cdef inline Py_ssize_t history_slot(_EstimatorBase e, double t) except -2:
    """Where the odometry's new pose at time t goes in e's history: the index (from
    ``start``) of the sample, whose time and ``joined`` flag are set here and whose pose
    the caller writes, or -1 when it is not stored. (Inline: it is most of an update's
    bookkeeping.)"""
    cdef Py_ssize_t lo, hi, mid, n, start, size = e.ssize
    cdef char* b
    cdef double newest = t
    # A call re-entered while the odometry read its inputs (a module-position sequence's
    # Python protocol) may have taken the slot reserved for this one.
    if e.start + e.count == e.cap:
        e._reserve()
    # Remove, oldest first, every sample at least HISTORY older than the newest time: t,
    # or the newest stored sample when t is older. (WPILib measures from t, so a clock
    # that runs backwards keeps every sample; here the history stays bounded.)
    start = e.start
    n = e.count
    b = e.buf + start * size
    if n > 0 and stamp(b, size, n - 1).t > t:
        newest = stamp(b, size, n - 1).t
    while n > 0 and newest - stamp(b, size, 0).t >= HISTORY:
        b += size
        start += 1
        n -= 1
    e.start = start
    e.count = n
    if n > 0 and newest - t >= HISTORY:
        # Older than the whole history: nothing would keep it, so it is not stored.
        e.tail_is_odometry = False
        return -1
    if n == 0 or t > stamp(b, size, n - 1).t:
        stamp(b, size, n).t = t
        stamp(b, size, n).joined = n > 0 and e.tail_is_odometry
        e.count = n + 1
        e.tail_is_odometry = True
        return n
    # The odometry pose lands between stored ones: neither it nor the sample after it
    # follows its predecessor by one odometry step.
    lo, hi = 0, n                # first index with time >= t
    while lo < hi:
        mid = (lo + hi) // 2
        if stamp(b, size, mid).t < t:
            lo = mid + 1
        else:
            hi = mid
    if stamp(b, size, lo).t != t:
        memmove(b + (lo + 1) * size, b + lo * size, size * (n - lo))
        stamp(b, size, lo).t = t
        e.count = n + 1
    stamp(b, size, lo).joined = False
    if lo + 1 < e.count:
        stamp(b, size, lo + 1).joined = False
    e.tail_is_odometry = lo + 1 == e.count
    return lo


cdef inline Py_ssize_t history_locate(_EstimatorBase e, double t, double* f) noexcept:
    """For the odometry pose at time t in e's history (count > 0; clamped to the stored
    range): the index i (from ``start``) of the sample at or before t and the fraction f
    of the way to sample i + 1 (0 for sample i itself)."""
    cdef Py_ssize_t n = e.count, lo, hi, mid, size = e.ssize
    cdef char* b = e.buf + e.start * size
    f[0] = 0.0
    if t <= stamp(b, size, 0).t:
        return 0
    if t >= stamp(b, size, n - 1).t:
        return n - 1
    lo, hi = 0, n - 1            # b[lo].t < t < b[hi].t, or an exact hit
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if stamp(b, size, mid).t <= t:
            lo = mid
        else:
            hi = mid
    if stamp(b, size, lo).t != t:
        # The history spans at most HISTORY (history_slot), so no overflow here.
        f[0] = (t - stamp(b, size, lo).t) / (stamp(b, size, hi).t - stamp(b, size, lo).t)
    return lo


cdef inline double history_clamp(_EstimatorBase e, double t) noexcept:
    """t clamped to the times in e's history (count > 0): records stamped after the
    newest sample are invisible to sampleAt."""
    cdef double lo = stamp(e.buf, e.ssize, e.start).t
    cdef double hi = stamp(e.buf, e.ssize, e.start + e.count - 1).t
    return lo if t < lo else hi if t > hi else t


cdef inline Py_ssize_t records_after(_EstimatorBase e, double t) noexcept:
    """Index of e's first record with time > t (nrec when there is none); the records are
    in strictly ascending time, each starting with its time."""
    cdef Py_ssize_t lo = 0, hi = e.nrec, mid
    while lo < hi:
        mid = (lo + hi) // 2
        if (<double*>(e.rec + mid * e.rsize))[0] <= t:
            lo = mid + 1
        else:
            hi = mid
    return lo


cdef class _PoseEstimator(_EstimatorBase):
    cdef _Odometry odo           # the concrete estimator's odometry (typed there too)
    cdef pose2_t estimate

    cdef int _init(self, _Odometry odo, object state_std_devs, object vision_std_devs) except -1
    cdef int _after_update(self, double t) except -1
    cdef bint _sample(self, double t, pose2_t* out) noexcept
    cdef bint _sample_at(self, double t, pose2_t* out) noexcept
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
