"""3-D pose estimators: 3-D odometry fused with vision measurements (WPILib 2027's
PoseEstimator3d).

As the 2-D estimators (drivekin.estimator), with poses in 3-D: 1.5 s of odometry poses,
vision measurements compared with the estimate at their time, and the difference scaled
per axis by the steady-state Kalman gain k = q / (q + √(q·r)) from the state and vision
standard deviations, here four of each: x (m), y (m), z (m) and θ (rad). The θ gain
scales the correction's rotation as WPILib does: its extrinsic roll, pitch and yaw
(Rotation3d.getX/Y/Z) each times k, back through Rotation3d(roll, pitch, yaw). That is
not a geodesic scaling of the rotation: for a correction of Euler angles
(0.3, 0.3, 0.3) rad and k = 0.5 the result is 1.17° away from half the rotation about
its own axis (13.9° for (1, 1, 1) rad).

Timestamps, the clock (:class:`MathSharedStore`), stale measurements (ignored when older
than 1.5 s before the newest odometry sample, as WPILib's Java does), the
:class:`ClockMismatchWarning` and the bounded memory are the 2-D estimators'. After
warm-up, ``update``/``updateWithTime`` and ``addVisionMeasurement`` make no allocator
calls; returned poses come from the Pose3d freelist.
"""
cimport cython
from libc.math cimport fabs

from drivekin._core.args cimport check_type
from drivekin._core.kernels3d cimport (norm3, pose3, pose3_interpolate, pose3_plus,
                                       pose3_relative_to, q_from_euler, q_to_euler,
                                       transform3_inverse, twist3_exp, vec3)
from drivekin._core.types cimport pose3_t, twist3_t, vec3_t
from drivekin.estimator cimport (clock_now, finite_time, history_clamp, history_locate,
                                 history_slot, records_after, wheel_pair)
from drivekin.geometry3d cimport Pose3d, Rotation3d, Translation3d, new_pose3d
from drivekin.odometry3d cimport (DeadWheelOdometry3d, DifferentialDriveOdometry3d,
                                  MecanumDriveOdometry3d, SwerveDriveOdometry3d,
                                  TwoDeadWheelOdometry3d, _Odometry3d)
from drivekin._core.errors import type_name


cdef inline void set_shift(record3_t* r) noexcept nogil:
    r.shift = pose3_plus(r.vision, transform3_inverse(r.odometry))

cdef inline pose3_t compensate(const record3_t* r, pose3_t p) noexcept nogil:
    # WPILib's vision + (p − odometry), composed once ahead of time as the shift (equal up
    # to rounding; one composition instead of two on every update and sample).
    return pose3_plus(r.shift, p)


cdef inline pose3_t interpolate_samples(const sample3_t* a, const sample3_t* b,
                                        double f) noexcept nogil:
    # Pose3d.interpolate(a.p, b.p, f) for 0 < f < 1. When b was appended by the odometry
    # step after a, the log of b relative to a is that step's twist (to rounding), which
    # saves the log. Near a half turn the log's rotation may be the other way round, so
    # there, and for any other pair, the general form runs.
    cdef twist3_t tw
    if not b.s.joined or not norm3(b.tw.rx, b.tw.ry, b.tw.rz) < 3.0:
        return pose3_interpolate(a.p, b.p, f)
    tw.dx = b.tw.dx * f
    tw.dy = b.tw.dy * f
    tw.dz = b.tw.dz * f
    tw.rx = b.tw.rx * f
    tw.ry = b.tw.ry * f
    tw.rz = b.tw.rz * f
    return pose3_plus(a.p, twist3_exp(tw))


cdef inline pose3_t scaled_correction(pose3_t delta, const double* k) noexcept nogil:
    # WPILib's Transform3d(k0·x, k1·y, k2·z, Rotation3d(k3·roll, k3·pitch, k3·yaw)), the
    # angles being delta's extrinsic Euler angles.
    cdef vec3_t e = q_to_euler(delta.q)
    return pose3(vec3(k[0] * delta.t.x, k[1] * delta.t.y, k[2] * delta.t.z),
                 q_from_euler(k[3] * e.x, k[3] * e.y, k[3] * e.z))


cdef class _PoseEstimator3d(_EstimatorBase):
    """Everything but the drivetrain: the pose history, the vision records and the four
    resets shared by every 3-D estimator."""

    cdef int _init(self, _Odometry3d odo, object state_std_devs,
                   object vision_std_devs) except -1:
        self._init_history(4, sizeof(sample3_t), sizeof(record3_t), state_std_devs,
                           vision_std_devs)
        self.odo = odo
        self.estimate = odo.pose
        self.ready = True
        return 0

    cdef Pose3d _at(self, double t, object gyro_angle, object a, object b):
        cdef Py_ssize_t i
        cdef sample3_t* s
        cdef pose3_t p
        if not self.ready:
            self._check()
        finite_time(t, "current_time")
        if self.start + self.count == self.cap:
            self._reserve()
        self.odo._step(<Rotation3d>gyro_angle, a, b)
        p = self.odo.pose
        i = history_slot(self, t)
        if i >= 0:
            s = <sample3_t*>self.buf + self.start + i
            s.p = p
            s.tw = self.odo.twist
        self.estimate = p if self.nrec == 0 else compensate(
            <record3_t*>self.rec + self.nrec - 1, p)
        return new_pose3d(self.estimate)

    cdef bint _sample(self, double t, pose3_t* out) noexcept:
        """The odometry pose at time t: clamped to the stored range, interpolated between
        neighbours (Pose3d.interpolate); False when there is none."""
        cdef double f
        cdef Py_ssize_t i
        cdef sample3_t* b
        if self.count == 0:
            return False
        i = history_locate(self, t, &f)
        b = <sample3_t*>self.buf + self.start + i
        out[0] = interpolate_samples(b, b + 1, f) if f > 0.0 else b.p
        return True

    cdef bint _sample_at(self, double t, pose3_t* out) noexcept:
        cdef Py_ssize_t i
        cdef pose3_t p
        if self.count == 0:
            return False
        t = history_clamp(self, t)
        self._sample(t, &p)
        i = records_after(self, t) - 1
        out[0] = p if i < 0 else compensate(<record3_t*>self.rec + i, p)
        return True

    cdef int _reset_done(self) except -1:
        self._clear()
        self.estimate = self.odo.pose
        return 0

    # -- public API -----------------------------------------------------------------------

    def getEstimatedPosition(self):
        """Return the current pose estimate (field frame, m)."""
        self._check()
        return new_pose3d(self.estimate)

    @cython.always_allow_keywords(False)   # METH_O: the 1-argument fast call
    def sampleAt(self, double timestamp):
        """Return the estimated pose at ``timestamp`` (s; clamped to the 1.5 s of stored
        history) with the vision corrections known for that time, or None before the
        first update after construction or a reset."""
        cdef pose3_t p
        self._check()
        finite_time(timestamp, "timestamp")
        if not self._sample_at(timestamp, &p):
            return None
        return new_pose3d(p)

    def setVisionMeasurementStdDevs(self, vision_measurement_std_devs):
        """Set how much vision is trusted: standard deviations of the measured x (m),
        y (m), z (m) and rotation (rad), any sequence of 4 numbers or a float64 array.
        Larger values trust vision less."""
        self._check()
        self._set_vision_std_devs(vision_measurement_std_devs)

    def addVisionMeasurement(self, vision_robot_pose: Pose3d, double timestamp,
                             vision_measurement_std_devs=None):
        """Fuse a vision measurement of the robot's field pose taken at ``timestamp`` (s,
        on the estimator's clock). With ``vision_measurement_std_devs`` (x m, y m, z m,
        θ rad) those become the standard deviations for this and later measurements (as
        :meth:`setVisionMeasurementStdDevs`). A measurement older than 1.5 s before the
        newest odometry sample is ignored, as is any before the first update.

        The correction's rotation is scaled as WPILib does: its extrinsic roll, pitch and
        yaw each times the θ gain (not a scaling about its own axis).

        A timestamp more than 10 s newer than the newest odometry sample, or more than
        11.5 s older, cannot be on the estimator's clock: the first such call on an
        estimator issues a :class:`ClockMismatchWarning`. A measurement that far ahead is
        applied as WPILib does, but replaces the earlier ones that far ahead instead of
        being kept with them, so such a stream keeps one record."""
        check_type(vision_robot_pose, Pose3d, "vision_robot_pose")
        cdef pose3_t odometry_sample, vision_sample
        cdef record3_t* r
        cdef Py_ssize_t i, lo
        if not self._admit(timestamp, vision_measurement_std_devs, &i, &lo):
            return
        self._sample(timestamp, &odometry_sample)
        vision_sample = odometry_sample if i < 0 else compensate(
            <record3_t*>self.rec + i, odometry_sample)
        r = <record3_t*>self.rec + lo
        r.t = timestamp
        r.vision = pose3_plus(vision_sample, scaled_correction(
            pose3_relative_to((<Pose3d>vision_robot_pose).p, vision_sample), self.k))
        r.odometry = odometry_sample
        set_shift(r)
        self.nrec = lo + 1
        self.estimate = compensate(r, self.odo.pose)

    def resetPose(self, pose: Pose3d):
        """Reset the estimate (and the odometry's pose) to ``pose``; forget the history
        and every vision correction."""
        check_type(pose, Pose3d, "pose")
        self._check()
        self.odo.resetPose(pose)
        self._reset_done()

    def resetTranslation(self, translation: Translation3d):
        """Reset the position, keeping the rotation and the latest vision correction of
        the rotation; the history is cleared."""
        check_type(translation, Translation3d, "translation")
        self._check()
        self.odo.resetTranslation(translation)
        self._keep_latest(True, (<Translation3d>translation).v, self.odo.pose)

    def resetRotation(self, rotation: Rotation3d):
        """Reset the rotation, keeping the position and the latest vision correction of
        the position; the history is cleared."""
        check_type(rotation, Rotation3d, "rotation")
        self._check()
        self.odo.resetRotation(rotation)
        self._keep_latest(False, self.odo.pose.t, self.odo.pose)

    cdef void _keep_latest(self, bint translation, vec3_t t, pose3_t odometry) noexcept:
        # WPILib: the newest record alone survives, both its poses given the new
        # translation (or the new rotation, which is the odometry's now).
        cdef record3_t latest
        cdef bint had = self.nrec > 0
        if had:
            latest = (<record3_t*>self.rec)[self.nrec - 1]
        self._clear()
        if not had:
            self.estimate = odometry
            return
        if translation:
            latest.vision.t = t
            latest.odometry.t = t
        else:
            latest.vision.q = odometry.q
            latest.odometry.q = odometry.q
        set_shift(&latest)
        (<record3_t*>self.rec)[0] = latest
        self.nrec = 1
        self.estimate = compensate(<record3_t*>self.rec, odometry)


# ---------------------------------------------------------------------------------------
# Concrete estimators: each builds its odometry; the odometry reads the readings.

_DEFAULT_STATE = (0.1, 0.1, 0.1, 0.1)
_DEFAULT_VISION = (0.9, 0.9, 0.9, 0.9)


cdef class SwerveDrivePoseEstimator3d(_PoseEstimator3d):
    """SwerveDrivePoseEstimator3d(kinematics, gyro_angle, module_positions, initial_pose, state_std_devs=(0.1, 0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9, 0.9))

    3-D swerve odometry (any N ≥ 2 modules) fused with vision. Module positions as for
    SwerveDriveOdometry3d (SwerveModulePosition objects or an (N, 2) float64 array);
    standard deviations of x (m), y (m), z (m) and rotation (rad).
    """

    def __init__(self, kinematics, gyro_angle: Rotation3d, module_positions,
                 initial_pose: Pose3d, state_std_devs=_DEFAULT_STATE,
                 vision_measurement_std_devs=_DEFAULT_VISION):
        check_type(initial_pose, Pose3d, "initial_pose")
        self._start()
        odo = SwerveDriveOdometry3d(kinematics, gyro_angle, module_positions, initial_pose)
        self._init(odo, state_std_devs, vision_measurement_std_devs)

    def update(self, gyro_angle: Rotation3d, wheel_positions):
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        return self._at(clock_now(), gyro_angle, wheel_positions, None)

    def updateWithTime(self, double current_time, gyro_angle: Rotation3d, wheel_positions):
        """Update the odometry with the gyro angle and module positions read at
        ``current_time`` (s); return the new estimate (Pose3d, field frame, m)."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        return self._at(current_time, gyro_angle, wheel_positions, None)

    def resetPosition(self, gyro_angle: Rotation3d, wheel_positions, pose: Pose3d):
        """Reset the odometry (gyro and module baselines, pose) and forget the history
        and every vision correction."""
        self._check()
        self.odo._reset(gyro_angle, wheel_positions, None, pose)
        self._reset_done()


cdef class MecanumDrivePoseEstimator3d(_PoseEstimator3d):
    """MecanumDrivePoseEstimator3d(kinematics, gyro_angle, wheel_positions, initial_pose, state_std_devs=(0.1, 0.1, 0.1, 0.1), vision_measurement_std_devs=(0.45, 0.45, 0.45, 0.45))

    3-D mecanum odometry fused with vision; standard deviations of x (m), y (m), z (m) and
    rotation (rad).
    """

    def __init__(self, kinematics, gyro_angle: Rotation3d, wheel_positions,
                 initial_pose: Pose3d, state_std_devs=_DEFAULT_STATE,
                 vision_measurement_std_devs=(0.45, 0.45, 0.45, 0.45)):
        check_type(initial_pose, Pose3d, "initial_pose")
        self._start()
        odo = MecanumDriveOdometry3d(kinematics, gyro_angle, wheel_positions, initial_pose)
        self._init(odo, state_std_devs, vision_measurement_std_devs)

    def update(self, gyro_angle: Rotation3d, wheel_positions):
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        return self._at(clock_now(), gyro_angle, wheel_positions, None)

    def updateWithTime(self, double current_time, gyro_angle: Rotation3d, wheel_positions):
        """Update the odometry with the gyro angle and wheel positions (m) read at
        ``current_time`` (s); return the new estimate."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        return self._at(current_time, gyro_angle, wheel_positions, None)

    def resetPosition(self, gyro_angle: Rotation3d, wheel_positions, pose: Pose3d):
        """Reset the odometry and forget the history and every vision correction."""
        self._check()
        self.odo._reset(gyro_angle, wheel_positions, None, pose)
        self._reset_done()


cdef class DifferentialDrivePoseEstimator3d(_PoseEstimator3d):
    """DifferentialDrivePoseEstimator3d(gyro_angle, left_distance, right_distance, initial_pose, state_std_devs=(0.02, 0.02, 0.02, 0.01), vision_measurement_std_devs=(0.1, 0.1, 0.1, 0.1))

    3-D differential-drive odometry fused with vision (2027: no kinematics argument).
    Distances in m; ``update``, ``updateWithTime`` and ``resetPosition`` also take one
    DifferentialDriveWheelPositions instead of the two distances.
    """

    def __init__(self, gyro_angle: Rotation3d, left_distance, right_distance,
                 initial_pose: Pose3d, state_std_devs=(0.02, 0.02, 0.02, 0.01),
                 vision_measurement_std_devs=(0.1, 0.1, 0.1, 0.1)):
        check_type(initial_pose, Pose3d, "initial_pose")
        self._start()
        odo = DifferentialDriveOdometry3d(gyro_angle, left_distance, right_distance,
                                          initial_pose)
        self._init(odo, state_std_devs, vision_measurement_std_devs)

    def update(self, gyro_angle: Rotation3d, left_distance, right_distance=None):
        """update(gyro_angle, left_distance, right_distance) or update(gyro_angle,
        wheel_positions): updateWithTime at :meth:`MathSharedStore.getTimestamp`."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        return self._pair(clock_now(), gyro_angle, left_distance, right_distance)

    def updateWithTime(self, double current_time, gyro_angle: Rotation3d, left_distance,
                       right_distance=None):
        """Update the odometry with the gyro angle and the wheel distances (m) read at
        ``current_time`` (s); return the new estimate."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        return self._pair(current_time, gyro_angle, left_distance, right_distance)

    cdef Pose3d _pair(self, double t, object gyro_angle, object first, object second):
        cdef double l, r
        wheel_pair(first, second, &l, &r, "update")
        return self._at(t, gyro_angle, l, r)

    def resetPosition(self, gyro_angle: Rotation3d, left_distance, right_distance,
                      pose=None):
        """resetPosition(gyro_angle, left_distance, right_distance, pose) or
        resetPosition(gyro_angle, wheel_positions, pose): reset the odometry and forget the
        history and every vision correction."""
        cdef double l, r
        self._check()
        if pose is None:
            pose, right_distance = right_distance, None
        wheel_pair(left_distance, right_distance, &l, &r, "resetPosition")
        self.odo._reset(gyro_angle, l, r, pose)
        self._reset_done()


cdef class DeadWheelPoseEstimator3d(_PoseEstimator3d):
    """DeadWheelPoseEstimator3d(kinematics, wheel_positions, gyro_angle, initial_pose=Pose3d(), state_std_devs=(0.1, 0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9, 0.9))

    DeadWheelOdometry3d (any dead-wheel layout that observes (dx, dy), a gyro; distances in
    m) fused with vision.
    """

    def __init__(self, kinematics, wheel_positions, gyro_angle: Rotation3d,
                 initial_pose=None, state_std_devs=_DEFAULT_STATE,
                 vision_measurement_std_devs=_DEFAULT_VISION):
        self._start()
        odo = DeadWheelOdometry3d(kinematics, wheel_positions, gyro_angle, initial_pose)
        self._init(odo, state_std_devs, vision_measurement_std_devs)

    def update(self, wheel_positions, gyro_angle: Rotation3d):
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        return self._at(clock_now(), gyro_angle, wheel_positions, None)

    def updateWithTime(self, double current_time, wheel_positions, gyro_angle: Rotation3d):
        """Update the odometry with the wheel distances (m) and the gyro angle read at
        ``current_time`` (s); return the new estimate."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        return self._at(current_time, gyro_angle, wheel_positions, None)

    def resetPosition(self, wheel_positions, gyro_angle: Rotation3d, pose: Pose3d):
        """Reset the odometry and forget the history and every vision correction."""
        self._check()
        self.odo._reset(gyro_angle, wheel_positions, None, pose)
        self._reset_done()


cdef class TwoDeadWheelPoseEstimator3d(_PoseEstimator3d):
    """TwoDeadWheelPoseEstimator3d(x_wheel_y_pos, y_wheel_x_pos, x_wheel_pos, y_wheel_pos, gyro_angle, initial_pose, state_std_devs=(0.1, 0.1, 0.1, 0.1), vision_measurement_std_devs=(0.9, 0.9, 0.9, 0.9))

    TwoDeadWheelOdometry3d (a forward wheel at y = x_wheel_y_pos, a left wheel at
    x = y_wheel_x_pos, m; distances in m; a gyro) fused with vision.
    """

    def __init__(self, double x_wheel_y_pos, double y_wheel_x_pos, x_wheel_pos, y_wheel_pos,
                 gyro_angle: Rotation3d, initial_pose: Pose3d, state_std_devs=_DEFAULT_STATE,
                 vision_measurement_std_devs=_DEFAULT_VISION):
        check_type(initial_pose, Pose3d, "initial_pose")
        self._start()
        odo = TwoDeadWheelOdometry3d(x_wheel_y_pos, y_wheel_x_pos, x_wheel_pos, y_wheel_pos,
                                     gyro_angle, initial_pose)
        self._init(odo, state_std_devs, vision_measurement_std_devs)

    def update(self, x_wheel_pos, y_wheel_pos, gyro_angle: Rotation3d):
        """updateWithTime at :meth:`MathSharedStore.getTimestamp`; returns the estimate."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        return self._at(clock_now(), gyro_angle, x_wheel_pos, y_wheel_pos)

    def updateWithTime(self, double current_time, x_wheel_pos, y_wheel_pos,
                       gyro_angle: Rotation3d):
        """Update the odometry with the wheel distances (m) and the gyro angle read at
        ``current_time`` (s); return the new estimate."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        return self._at(current_time, gyro_angle, x_wheel_pos, y_wheel_pos)

    def resetPosition(self, x_wheel_pos, y_wheel_pos, gyro_angle: Rotation3d, pose: Pose3d):
        """Reset the odometry and forget the history and every vision correction."""
        self._check()
        self.odo._reset(gyro_angle, x_wheel_pos, y_wheel_pos, pose)
        self._reset_done()
