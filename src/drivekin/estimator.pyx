"""Pose estimators: odometry fused with vision measurements (WPILib 2027).

Each estimator owns an odometry object of its drivetrain and keeps 1.5 s of its poses. A
vision measurement (a field-relative robot pose and the time it was taken) is compared
with the estimate at that time; the difference, scaled per axis by the steady-state
Kalman gain k = q / (q + √(q·r)) (q, r: the squared state and vision standard
deviations), becomes a correction that is replayed on every later odometry pose.

Timestamps are seconds on one monotonic clock. ``update`` reads
:meth:`MathSharedStore.getTimestamp` (``time.monotonic`` unless replaced with
:meth:`MathSharedStore.setTimestampSource`, e.g. for simulation or log replay); vision
timestamps passed alongside must use the same clock, or use ``updateWithTime``. Unlike
WPILib, timestamps must be finite (ValueError otherwise).

After warm-up, ``update``/``updateWithTime`` and ``addVisionMeasurement`` make no allocator
calls: the pose history and the vision records live in arrays that grow only when the
history needs more room, and returned poses come from the Pose2d freelist.
"""
cimport cython
from cpython.mem cimport PyMem_Free, PyMem_Malloc, PyMem_Realloc
from libc.math cimport INFINITY, fabs, isfinite, isinf, sqrt
from drivekin._core.dkmath cimport sincos
from libc.string cimport memmove
cimport numpy as cnp

import time
import warnings

from drivekin._core.types cimport pose2_t, rot2_t
from drivekin._core.args cimport check_type, read_floats
from drivekin._core.kernels cimport (pose, pose_interpolate, pose_relative_to,
                                     pose_transform_by, rot_cs, rot_times,
                                     transform_inverse, twist_exp_cs, vec)
from drivekin.geometry cimport Pose2d, Rotation2d, Translation2d, new_pose
from drivekin.mecanum cimport MecanumDriveWheelPositions
from drivekin.differential cimport DifferentialDriveWheelPositions
from drivekin._core.wheels cimport _WheelValues
from drivekin.odometry cimport (DeadWheelOdometry, DifferentialDriveOdometry,
                                MecanumDriveOdometry, SwerveDriveOdometry,
                                TwoDeadWheelOdometry, _Odometry)
from drivekin._core.errors import type_name

cnp.import_array()

# A vision timestamp more than CLOCK_GAP s newer than the newest odometry sample, or older
# than the history by more than that, cannot come from the estimator's clock: no robot
# runs vision 10 s ahead of its odometry or delivers a frame 11.5 s late.
cdef double CLOCK_GAP = 10.0
cdef Py_ssize_t INITIAL_SAMPLES = 128   # 1.5 s of updates at 85 Hz (50 Hz: 76 samples)
cdef Py_ssize_t INITIAL_RECORDS = 128  # 1.5 s of vision at 85 Hz
# What each standard deviation measures, by the length of the vectors.
cdef dict AXES = {3: "standard deviations (x m, y m, θ rad)",
                  4: "standard deviations (x m, y m, z m, θ rad)"}


# ---------------------------------------------------------------------------------------
# The clock

cdef object _clock = time.monotonic


class ClockMismatchWarning(UserWarning):
    """A vision timestamp that cannot be on the estimator's clock (see
    :meth:`_PoseEstimator.addVisionMeasurement`). Issued once per estimator; filter it with
    ``warnings.filterwarnings("ignore", category=ClockMismatchWarning)``."""


cdef class MathSharedStore:
    """The clock the estimators' ``update`` methods read (WPILib's MathSharedStore).

    Static methods only; seconds on a monotonic clock."""

    @staticmethod
    def getTimestamp():
        """Return the current time in seconds from the timestamp source
        (``time.monotonic`` by default)."""
        return clock_now()

    @staticmethod
    def setTimestampSource(source):
        """Make ``source()`` (a callable returning seconds as a float) the clock; None
        restores ``time.monotonic``. Use it to run estimators on simulated or recorded
        time."""
        global _clock
        if source is None:
            _clock = time.monotonic
        elif not callable(source):
            raise TypeError(f"the timestamp source must be a callable returning seconds or "
                            f"None, got {type_name(source)}")
        else:
            _clock = source


cdef double clock_now() except? -1.0:
    cdef object t = _clock()
    try:
        return t
    except TypeError:
        raise TypeError(f"the timestamp source returned {type_name(t)}, not seconds as a "
                        "float") from None


cdef int finite_time(double t, str what) except -1:
    if not isfinite(t):
        raise ValueError(f"{what} must be a finite time in s, got {t!r}")
    return 0


# ---------------------------------------------------------------------------------------
# Standard deviations and gains

cdef int read_std_devs(object values, Py_ssize_t n, str what, double* out) except -1:
    """n standard deviations (numbers; inf allowed, NaN not; the sign is ignored, as
    WPILib squares them) into ``out``, which is written only when all are valid."""
    cdef double v[4]
    cdef Py_ssize_t i
    read_floats(values, n, v, what, AXES[n])
    for i in range(n):
        if v[i] != v[i]:
            raise ValueError(f"{what}[{i}] must be finite, or inf for no confidence at "
                             f"all, got {v[i]!r}")
    for i in range(n):
        out[i] = v[i]
    return 0


cdef inline double gain(double s, double v) noexcept nogil:
    # Steady-state Kalman gain of a directly observed constant, per axis, from the state
    # and vision standard deviations: WPILib's closed form q / (q + sqrt(q·r)) with q = s²,
    # r = v², which is s / (s + v). WPILib's form (and its bits) wherever its squares are
    # normal numbers; beyond that the squares overflow or underflow (s = 1e200 gave
    # inf/inf = NaN) and s / (s + v) is used. No state uncertainty, or infinitely
    # uncertain vision, ignores vision; an infinitely uncertain state takes it whole.
    cdef double q = s * s, qr = q * (v * v)
    s = fabs(s)
    v = fabs(v)
    if s == 0.0 or isinf(v):
        return 0.0
    if isinf(s):
        return 1.0
    if 0.0 < q < INFINITY and (v == 0.0 or 0.0 < qr < INFINITY):
        return q / (q + sqrt(qr))
    return s / (s + v)


cdef inline void set_shift(record_t* r) noexcept nogil:
    r.shift = pose_transform_by(r.vision, transform_inverse(r.odometry))

cdef inline pose2_t compensate(const record_t* r, pose2_t p) noexcept nogil:
    # The corrected pose at r.t plus the odometry's motion since then: WPILib's
    # vision + (p − odometry), composed once ahead of time as the shift (equal up to
    # rounding; it saves two rotation normalisations on every update and sample).
    return pose_transform_by(r.shift, p)


cdef inline pose2_t interpolate_samples(const sample_t* a, const sample_t* b,
                                        double f) noexcept nogil:
    # Pose2d.interpolate(a.p, b.p, f). When b was appended by the odometry step after a,
    # the log of b relative to a is that step's twist (to rounding), which saves an atan2
    # and two normalisations. Near ±π the log's wrapped angle may differ from the step's,
    # so there, and for any other pair, the general form runs.
    cdef double theta = b.tw.dtheta * f, c, s
    cdef pose2_t step
    if f <= 0.0 or f >= 1.0 or not b.s.joined or not fabs(b.tw.dtheta) < 3.0:
        return pose_interpolate(a.p, b.p, f)
    sincos(theta, &s, &c)
    step = twist_exp_cs(b.tw.dx * f, b.tw.dy * f, theta, c, s)
    # The (cos, sin) pair is unit to an ulp and the composition below normalises its
    # rotation product anyway: a normalisation less on the sampling path.
    step.r = rot_cs(c, s)
    return pose_transform_by(a.p, step)


# ---------------------------------------------------------------------------------------

cdef class _EstimatorBase:
    """The pose history's and the vision records' bookkeeping in time, the gains and the
    clock checks, shared by the 2-D and 3-D estimators."""

    def __cinit__(self, *args, **kwargs):
        self.buf = NULL
        self.rec = NULL

    def __dealloc__(self):
        PyMem_Free(self.buf)
        PyMem_Free(self.rec)

    cdef int _init_history(self, Py_ssize_t axes, Py_ssize_t ssize, Py_ssize_t rsize,
                           object state_std_devs, object vision_std_devs) except -1:
        # Called by the concrete constructors after they built the odometry and before
        # anything is stored; the subclass sets ``ready`` once it has its odometry.
        cdef double sd[4]
        cdef double vd[4]
        cdef Py_ssize_t i
        read_std_devs(state_std_devs, axes, "state_std_devs", sd)
        read_std_devs(vision_std_devs, axes, "vision_measurement_std_devs", vd)
        cdef char* buf = <char*>PyMem_Malloc(ssize * INITIAL_SAMPLES)
        cdef char* rec = <char*>PyMem_Malloc(rsize * INITIAL_RECORDS)
        if buf == NULL or rec == NULL:
            PyMem_Free(buf)
            PyMem_Free(rec)
            raise MemoryError()
        if self.ready:              # Python code ran while reading: refuse a second init
            PyMem_Free(buf)
            PyMem_Free(rec)
            raise TypeError(f"{type(self).__name__} is already initialised")
        PyMem_Free(self.buf)
        PyMem_Free(self.rec)
        self.buf, self.ssize, self.cap, self.start, self.count = buf, ssize, INITIAL_SAMPLES, 0, 0
        self.rec, self.rsize, self.rcap, self.nrec = rec, rsize, INITIAL_RECORDS, 0
        self.axes = axes
        for i in range(axes):
            self.sd[i] = sd[i]
            self.k[i] = gain(sd[i], vd[i])
        return 0

    cdef int _start(self) except -1:
        if self.ready:
            raise TypeError(f"{type(self).__name__} is already initialised: __init__ cannot "
                            "be called again (use resetPosition)")
        return 0

    cdef int _check(self) except -1:
        if not self.ready:
            raise RuntimeError(f"{type(self).__name__}.__init__ has not completed")
        return 0

    # -- pose history -------------------------------------------------------------------

    cdef int _reserve(self) except -1:
        """Make room for one more sample at the end (before the odometry moves, so that a
        failed allocation changes nothing)."""
        cdef char* grown
        if self.start + self.count < self.cap:
            return 0
        if self.start > 0:
            memmove(self.buf, self.buf + self.start * self.ssize, self.ssize * self.count)
            self.start = 0
            return 0
        grown = <char*>PyMem_Realloc(self.buf, self.ssize * 2 * self.cap)
        if grown == NULL:
            raise MemoryError()
        self.buf = grown
        self.cap *= 2
        return 0

    cdef void _clear(self) noexcept:
        self.start = 0
        self.count = 0
        self.nrec = 0

    cdef int _warn_clock(self, double timestamp, double newest) except -1:
        self.clock_warned = True
        if timestamp > newest:
            where = (f"{timestamp - newest:.6g} s newer than the newest odometry sample "
                     f"({newest:.6g} s); it is applied against the newest odometry pose and "
                     "kept only until the next such measurement")
        else:
            where = (f"{newest - timestamp:.6g} s older than the newest odometry sample "
                     f"({newest:.6g} s); it is ignored")
        warnings.warn(
            f"{type(self).__name__}.addVisionMeasurement: timestamp {timestamp:.6g} s is "
            f"{where}. Vision timestamps must be on the clock of update() "
            "(MathSharedStore.getTimestamp(), time.monotonic unless replaced) or of the times "
            "given to updateWithTime; a FPGA or Unix timestamp is not. (Warned once per "
            "estimator.)", ClockMismatchWarning, stacklevel=1)
        return 0

    @cython.final
    cdef int _admit(self, double timestamp, object std_devs, Py_ssize_t* floor,
                    Py_ssize_t* slot) except -1:
        """addVisionMeasurement up to the pose arithmetic: 0 when the measurement is
        ignored; else 1, with ``floor`` the record in force at the clamped timestamp (-1:
        none) and ``slot`` the index its record takes (every later one goes), room made."""
        cdef double clamped, newest
        cdef bint far_ahead
        cdef Py_ssize_t keep, lo
        cdef char* grown
        self._check()
        finite_time(timestamp, "timestamp")
        if std_devs is not None:
            self._set_vision_std_devs(std_devs)
        if self.count == 0:
            return 0
        newest = stamp(self.buf, self.ssize, self.start + self.count - 1).t
        far_ahead = timestamp - newest > CLOCK_GAP
        if not self.clock_warned and (far_ahead or newest - timestamp > HISTORY + CLOCK_GAP):
            self._warn_clock(timestamp, newest)
        if newest - HISTORY > timestamp:
            return 0
        # Room for one more record, before anything changes.
        if self.nrec == self.rcap:
            grown = <char*>PyMem_Realloc(self.rec, self.rsize * 2 * self.rcap)
            if grown == NULL:
                raise MemoryError()
            self.rec = grown
            self.rcap *= 2
        # Drop the records no stored sample needs: everything before the newest record at
        # or before the oldest sample.
        keep = records_after(self, stamp(self.buf, self.ssize, self.start).t) - 1
        if keep > 0:
            memmove(self.rec, self.rec + keep * self.rsize, self.rsize * (self.nrec - keep))
            self.nrec -= keep
        # sampleAt(timestamp) is the (clamped) odometry pose under the record in force at
        # the clamped time.
        floor[0] = records_after(self, history_clamp(self, timestamp)) - 1
        # Stored under the unclamped timestamp, replacing an equal one; later records go
        # (WPILib). A record from another clock replaces the earlier ones from it too, so
        # that such a stream keeps one record rather than all of them (WPILib keeps all).
        lo = records_after(self, newest + CLOCK_GAP if far_ahead else timestamp)
        if lo > 0 and (<double*>(self.rec + (lo - 1) * self.rsize))[0] == timestamp:
            lo -= 1
        slot[0] = lo
        return 1

    cdef int _set_vision_std_devs(self, object values) except -1:
        cdef double vd[4]
        cdef Py_ssize_t i
        read_std_devs(values, self.axes, "vision_measurement_std_devs", vd)
        for i in range(self.axes):
            self.k[i] = gain(self.sd[i], vd[i])
        return 0


cdef class _PoseEstimator(_EstimatorBase):
    """Everything but the drivetrain: the pose history, the vision records and the four
    resets shared by every estimator."""

    cdef int _init(self, _Odometry odo, object state_std_devs, object vision_std_devs) except -1:
        self._init_history(3, sizeof(sample_t), sizeof(record_t), state_std_devs,
                           vision_std_devs)
        self.odo = odo
        self.estimate = odo.pose
        self.ready = True
        return 0

    cdef int _after_update(self, double t) except -1:
        """Store the odometry's new pose at time t (room was reserved) and refresh the
        estimate."""
        cdef pose2_t p = self.odo.pose
        cdef Py_ssize_t i = history_slot(self, t)
        cdef sample_t* s
        if i >= 0:
            s = <sample_t*>self.buf + self.start + i
            s.p = p
            s.tw = self.odo.twist
        self.estimate = p if self.nrec == 0 else compensate(
            <record_t*>self.rec + self.nrec - 1, p)
        return 0

    cdef bint _sample(self, double t, pose2_t* out) noexcept:
        """The odometry pose at time t: clamped to the stored range, interpolated along
        the arc between neighbours; False when there is none."""
        cdef double f
        cdef Py_ssize_t i
        cdef sample_t* b
        if self.count == 0:
            return False
        i = history_locate(self, t, &f)
        b = <sample_t*>self.buf + self.start + i
        out[0] = interpolate_samples(b, b + 1, f) if f > 0.0 else b.p
        return True

    cdef bint _sample_at(self, double t, pose2_t* out) noexcept:
        cdef Py_ssize_t i
        cdef pose2_t p
        if self.count == 0:
            return False
        t = history_clamp(self, t)
        self._sample(t, &p)
        i = records_after(self, t) - 1
        out[0] = p if i < 0 else compensate(<record_t*>self.rec + i, p)
        return True

    # -- public API -----------------------------------------------------------------------

    def getEstimatedPosition(self):
        """Return the current pose estimate (field frame, m)."""
        self._check()
        return new_pose(self.estimate)

    @cython.always_allow_keywords(False)   # METH_O: the 1-argument fast call
    def sampleAt(self, double timestamp):
        """Return the estimated pose at ``timestamp`` (s; clamped to the 1.5 s of stored
        history) with the vision corrections known for that time, or None before the
        first update after construction or a reset."""
        cdef pose2_t p
        self._check()
        finite_time(timestamp, "timestamp")
        if not self._sample_at(timestamp, &p):
            return None
        return new_pose(p)

    def setVisionMeasurementStdDevs(self, vision_measurement_std_devs):
        """Set how much vision is trusted: standard deviations of the measured x (m),
        y (m) and heading (rad), any sequence of 3 numbers or a float64 array. Larger
        values trust vision less."""
        self._check()
        self._set_vision_std_devs(vision_measurement_std_devs)

    def addVisionMeasurement(self, vision_robot_pose: Pose2d, double timestamp,
                             vision_measurement_std_devs=None):
        """Fuse a vision measurement of the robot's field pose taken at ``timestamp`` (s,
        on the estimator's clock). With ``vision_measurement_std_devs`` (x m, y m, θ rad) those
        become the standard deviations for this and later measurements (as
        :meth:`setVisionMeasurementStdDevs`). A measurement older than 1.5 s before the
        newest odometry sample is ignored, as is any before the first update.

        A timestamp more than 10 s newer than the newest odometry sample, or more than
        11.5 s older, cannot be on the estimator's clock: the first such call on an
        estimator issues a :class:`ClockMismatchWarning`. A measurement that far ahead is
        applied as WPILib does, but replaces the earlier ones that far ahead instead of
        being kept with them, so such a stream keeps one record."""
        check_type(vision_robot_pose, Pose2d, "vision_robot_pose")
        cdef pose2_t odometry_sample, vision_sample, delta, scaled
        cdef record_t* r
        cdef Py_ssize_t i, lo
        if not self._admit(timestamp, vision_measurement_std_devs, &i, &lo):
            return
        self._sample(timestamp, &odometry_sample)
        vision_sample = odometry_sample if i < 0 else compensate(
            <record_t*>self.rec + i, odometry_sample)
        delta = pose_relative_to((<Pose2d>vision_robot_pose).p, vision_sample)
        scaled = pose(vec(self.k[0] * delta.t.x, self.k[1] * delta.t.y),
                      rot_times(delta.r, self.k[2]))
        r = <record_t*>self.rec + lo
        r.t = timestamp
        r.vision = pose_transform_by(vision_sample, scaled)
        r.odometry = odometry_sample
        set_shift(r)
        self.nrec = lo + 1
        self.estimate = compensate(r, self.odo.pose)

    def resetPose(self, pose: Pose2d):
        """Reset the estimate (and the odometry's pose) to ``pose``; forget the history
        and every vision correction."""
        check_type(pose, Pose2d, "pose")
        self._check()
        self.odo.resetPose(pose)
        self._clear()
        self.estimate = self.odo.pose

    def resetTranslation(self, translation: Translation2d):
        """Reset the position, keeping the heading and the latest vision correction of
        the heading; the history is cleared."""
        check_type(translation, Translation2d, "translation")
        self._check()
        self.odo.resetTranslation(translation)
        self._clear_keeping_latest(True, (<Translation2d>translation).v.x,
                                   (<Translation2d>translation).v.y, self.odo.pose.r)

    def resetRotation(self, rotation: Rotation2d):
        """Reset the heading, keeping the position and the latest vision correction of
        the position; the history is cleared."""
        check_type(rotation, Rotation2d, "rotation")
        self._check()
        self.odo.resetRotation(rotation)
        self._clear_keeping_latest(False, 0.0, 0.0, (<Rotation2d>rotation).r)

    cdef void _clear_keeping_latest(self, bint translation, double x, double y,
                                    rot2_t r) noexcept:
        cdef record_t latest
        cdef bint had = self.nrec > 0
        if had:
            latest = (<record_t*>self.rec)[self.nrec - 1]
        self._clear()
        if not had:
            self.estimate = self.odo.pose
            return
        if translation:
            latest.vision.t = vec(x, y)
            latest.odometry.t = vec(x, y)
        else:
            latest.vision.r = r
            latest.odometry.r = r
        set_shift(&latest)
        (<record_t*>self.rec)[0] = latest
        self.nrec = 1
        self.estimate = compensate(<record_t*>self.rec, self.odo.pose)

    cdef int _reset_done(self) except -1:
        self._clear()
        self.estimate = self.odo.pose
        return 0


# ---------------------------------------------------------------------------------------
# Concrete estimators: each builds its odometry, then steps it at C level.

_DEFAULT_STATE = (0.1, 0.1, 0.1)


cdef class SwerveDrivePoseEstimator(_PoseEstimator):
    """SwerveDrivePoseEstimator(kinematics, gyro_angle, module_positions, initial_pose, state_std_devs=(0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9))

    Swerve odometry (any N ≥ 2 modules) fused with vision. Module positions as for
    SwerveDriveOdometry (SwerveModulePosition objects or an (N, 2) float64 array);
    standard deviations of x (m), y (m) and heading (rad).
    """

    def __init__(self, kinematics, gyro_angle: Rotation2d,
                 module_positions, initial_pose: Pose2d,
                 state_std_devs=_DEFAULT_STATE, vision_measurement_std_devs=(0.9, 0.9, 0.9)):
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(initial_pose, Pose2d, "initial_pose")
        self._start()
        odo = SwerveDriveOdometry(kinematics, gyro_angle, module_positions, initial_pose)
        self._init(odo, state_std_devs, vision_measurement_std_devs)
        self.swerve = odo

    def update(self, gyro_angle: Rotation2d, wheel_positions):
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        return self._at(clock_now(), gyro_angle, wheel_positions)

    def updateWithTime(self, double current_time, gyro_angle: Rotation2d,
                       wheel_positions):
        """Update the odometry with the gyro angle and module positions read at
        ``current_time`` (s); return the new estimate (Pose2d, field frame, m)."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        return self._at(current_time, gyro_angle, wheel_positions)

    cdef Pose2d _at(self, double t, Rotation2d gyro_angle, object wheel_positions):
        if not self.ready:
            self._check()
        finite_time(t, "current_time")
        if self.start + self.count == self.cap:
            self._reserve()
        self.swerve._step(gyro_angle, wheel_positions)
        self._after_update(t)
        return new_pose(self.estimate)

    def resetPosition(self, gyro_angle: Rotation2d, wheel_positions,
                      pose: Pose2d):
        """Reset the odometry (gyro and module baselines, pose) and forget the history
        and every vision correction."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(pose, Pose2d, "pose")
        self._check()
        self.swerve.resetPosition(gyro_angle, wheel_positions, pose)
        self._reset_done()


cdef class MecanumDrivePoseEstimator(_PoseEstimator):
    """MecanumDrivePoseEstimator(kinematics, gyro_angle, wheel_positions, initial_pose, state_std_devs=(0.1, 0.1, 0.1), vision_measurement_std_devs=(0.45, 0.45, 0.45))

    Mecanum odometry fused with vision; standard deviations of x (m), y (m) and heading
    (rad).
    """

    def __init__(self, kinematics, gyro_angle: Rotation2d,
                 wheel_positions: MecanumDriveWheelPositions, initial_pose: Pose2d,
                 state_std_devs=_DEFAULT_STATE, vision_measurement_std_devs=(0.45, 0.45, 0.45)):
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(wheel_positions, MecanumDriveWheelPositions, "wheel_positions")
        check_type(initial_pose, Pose2d, "initial_pose")
        self._start()
        odo = MecanumDriveOdometry(kinematics, gyro_angle, wheel_positions, initial_pose)
        self._init(odo, state_std_devs, vision_measurement_std_devs)
        self.mecanum = odo

    def update(self, gyro_angle: Rotation2d,
               wheel_positions: MecanumDriveWheelPositions):
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(wheel_positions, MecanumDriveWheelPositions, "wheel_positions")
        return self._at(clock_now(), gyro_angle, wheel_positions)

    def updateWithTime(self, double current_time, gyro_angle: Rotation2d,
                       wheel_positions: MecanumDriveWheelPositions):
        """Update the odometry with the gyro angle and wheel positions (m) read at
        ``current_time`` (s); return the new estimate."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(wheel_positions, MecanumDriveWheelPositions, "wheel_positions")
        return self._at(current_time, gyro_angle, wheel_positions)

    cdef Pose2d _at(self, double t, Rotation2d gyro_angle,
                    MecanumDriveWheelPositions wheel_positions):
        if not self.ready:
            self._check()
        finite_time(t, "current_time")
        if self.start + self.count == self.cap:
            self._reserve()
        self.mecanum._step(gyro_angle, wheel_positions)
        self._after_update(t)
        return new_pose(self.estimate)

    def resetPosition(self, gyro_angle: Rotation2d,
                      wheel_positions: MecanumDriveWheelPositions, pose: Pose2d):
        """Reset the odometry and forget the history and every vision correction."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(wheel_positions, MecanumDriveWheelPositions, "wheel_positions")
        check_type(pose, Pose2d, "pose")
        self._check()
        self.mecanum.resetPosition(gyro_angle, wheel_positions, pose)
        self._reset_done()


cdef int wheel_pair(object first, object second, double* l, double* r, str call) except -1:
    # (left m, right m) or (DifferentialDriveWheelPositions, omitted).
    if type(first) is DifferentialDriveWheelPositions:
        if second is not None:
            raise TypeError(f"{call}: pass either a DifferentialDriveWheelPositions or the "
                            "left and right distances, not both")
        l[0] = (<_WheelValues>first).w[0]
        r[0] = (<_WheelValues>first).w[1]
        return 0
    if second is None:
        raise TypeError(f"{call}: expected the left and right distances (m) or a "
                        f"DifferentialDriveWheelPositions, got {type_name(first)}")
    try:
        l[0] = first
        r[0] = second
    except TypeError:
        raise TypeError(f"{call}: the left and right distances must be numbers (m), got "
                        f"{type_name(first)} and {type_name(second)}") from None
    return 0


cdef class DifferentialDrivePoseEstimator(_PoseEstimator):
    """DifferentialDrivePoseEstimator(gyro_angle, left_distance, right_distance, initial_pose, state_std_devs=(0.02, 0.02, 0.01), vision_measurement_std_devs=(0.1, 0.1, 0.1))

    Differential-drive odometry fused with vision (2027: no kinematics argument).
    Distances in m; ``update``, ``updateWithTime`` and ``resetPosition`` also take one
    DifferentialDriveWheelPositions instead of the two distances.
    """

    def __init__(self, gyro_angle: Rotation2d, double left_distance,
                 double right_distance, initial_pose: Pose2d,
                 state_std_devs=(0.02, 0.02, 0.01), vision_measurement_std_devs=(0.1, 0.1, 0.1)):
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(initial_pose, Pose2d, "initial_pose")
        self._start()
        odo = DifferentialDriveOdometry(gyro_angle, left_distance, right_distance, initial_pose)
        self._init(odo, state_std_devs, vision_measurement_std_devs)
        self.differential = odo

    def update(self, gyro_angle: Rotation2d, left_distance, right_distance=None):
        """update(gyro_angle, left_distance, right_distance) or update(gyro_angle,
        wheel_positions): updateWithTime at :meth:`MathSharedStore.getTimestamp`."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        return self._at(clock_now(), gyro_angle, left_distance, right_distance)

    def updateWithTime(self, double current_time, gyro_angle: Rotation2d, left_distance,
                       right_distance=None):
        """Update the odometry with the gyro angle and the wheel distances (m) read at
        ``current_time`` (s); return the new estimate."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        return self._at(current_time, gyro_angle, left_distance, right_distance)

    cdef Pose2d _at(self, double t, Rotation2d gyro_angle, object left_distance,
                    object right_distance):
        cdef double l, r
        if not self.ready:
            self._check()
        finite_time(t, "current_time")
        wheel_pair(left_distance, right_distance, &l, &r, "update")
        if self.start + self.count == self.cap:
            self._reserve()
        self.differential._step(gyro_angle, l, r)
        self._after_update(t)
        return new_pose(self.estimate)

    def resetPosition(self, gyro_angle: Rotation2d, left_distance, right_distance,
                      pose=None):
        """resetPosition(gyro_angle, left_distance, right_distance, pose) or
        resetPosition(gyro_angle, wheel_positions, pose): reset the odometry and forget the
        history and every vision correction."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        cdef double l, r
        self._check()
        if pose is None:
            pose, right_distance = right_distance, None
        if type(pose) is not Pose2d:
            raise TypeError(f"pose must be a Pose2d, got {type_name(pose)}")
        wheel_pair(left_distance, right_distance, &l, &r, "resetPosition")
        self.differential.resetPosition(gyro_angle, l, r, pose)
        self._reset_done()


cdef class TwoDeadWheelPoseEstimator(_PoseEstimator):
    """TwoDeadWheelPoseEstimator(x_wheel_y_pos, y_wheel_x_pos, x_wheel_pos, y_wheel_pos, gyro_angle, initial_pose, state_std_devs=(0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9))

    TwoDeadWheelOdometry (a forward wheel at y = x_wheel_y_pos, a left wheel at
    x = y_wheel_x_pos, m; distances in m; a gyro) fused with vision.
    """

    def __init__(self, double x_wheel_y_pos, double y_wheel_x_pos, double x_wheel_pos,
                 double y_wheel_pos, gyro_angle: Rotation2d, initial_pose: Pose2d,
                 state_std_devs=_DEFAULT_STATE, vision_measurement_std_devs=(0.9, 0.9, 0.9)):
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(initial_pose, Pose2d, "initial_pose")
        self._start()
        odo = TwoDeadWheelOdometry(x_wheel_y_pos, y_wheel_x_pos, x_wheel_pos, y_wheel_pos,
                                   gyro_angle, initial_pose)
        self._init(odo, state_std_devs, vision_measurement_std_devs)
        self.two = odo

    def update(self, double x_wheel_pos, double y_wheel_pos, gyro_angle: Rotation2d):
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        return self._at(clock_now(), x_wheel_pos, y_wheel_pos, gyro_angle)

    def updateWithTime(self, double current_time, double x_wheel_pos, double y_wheel_pos,
                       gyro_angle: Rotation2d):
        """Update the odometry with the wheel distances (m) and gyro angle read at
        ``current_time`` (s); return the new estimate."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        return self._at(current_time, x_wheel_pos, y_wheel_pos, gyro_angle)

    cdef Pose2d _at(self, double t, double x_wheel_pos, double y_wheel_pos,
                    Rotation2d gyro_angle):
        if not self.ready:
            self._check()
        finite_time(t, "current_time")
        if self.start + self.count == self.cap:
            self._reserve()
        self.two._step(x_wheel_pos, y_wheel_pos, gyro_angle)
        self._after_update(t)
        return new_pose(self.estimate)

    def resetPosition(self, double x_wheel_pos, double y_wheel_pos, gyro_angle: Rotation2d,
                      pose: Pose2d):
        """Reset the odometry and forget the history and every vision correction."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(pose, Pose2d, "pose")
        self._check()
        self.two.resetPosition(x_wheel_pos, y_wheel_pos, gyro_angle, pose)
        self._reset_done()


cdef class DeadWheelPoseEstimator(_PoseEstimator):
    """DeadWheelPoseEstimator(kinematics, wheel_positions, gyro_angle=None, initial_pose=Pose2d(), state_std_devs=(0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9))

    DeadWheelOdometry (any dead-wheel layout, with or without a gyro; distances in m)
    fused with vision.
    """

    def __init__(self, kinematics, wheel_positions,
                 gyro_angle=None, initial_pose=None, state_std_devs=_DEFAULT_STATE,
                 vision_measurement_std_devs=(0.9, 0.9, 0.9)):
        self._start()
        odo = DeadWheelOdometry(kinematics, wheel_positions, gyro_angle, initial_pose)
        self._init(odo, state_std_devs, vision_measurement_std_devs)
        self.dead = odo

    def update(self, wheel_positions, gyro_angle=None):
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""
        return self._at(clock_now(), wheel_positions, gyro_angle)

    def updateWithTime(self, double current_time, wheel_positions, gyro_angle=None):
        """Update the odometry with the wheel distances (m) (and the gyro angle, when it
        has one) read at ``current_time`` (s); return the new estimate."""
        return self._at(current_time, wheel_positions, gyro_angle)

    cdef Pose2d _at(self, double t, object wheel_positions, object gyro_angle):
        if not self.ready:
            self._check()
        finite_time(t, "current_time")
        if self.start + self.count == self.cap:
            self._reserve()
        self.dead._step(wheel_positions, gyro_angle)
        self._after_update(t)
        return new_pose(self.estimate)

    def resetPosition(self, wheel_positions, gyro_angle, pose: Pose2d):
        """Reset the odometry (``gyro_angle`` None without a gyro) and forget the history
        and every vision correction."""
        check_type(pose, Pose2d, "pose")
        self._check()
        self.dead.resetPosition(wheel_positions, gyro_angle, pose)
        self._reset_done()
