"""Odometry for swerve, mecanum, differential and dead-wheel drivetrains (WPILib 2027).

Each ``update`` turns the wheel-position changes since the previous call into a twist
with the drivetrain's forward kinematics, replaces its heading change by the wrapped
gyro difference (the gyro is trusted for heading), and composes the pose with the
twist's exponential. The gyro reading need not match the pose heading: only its changes
matter. ``update`` returns the new pose; it allocates nothing beyond that Pose2d, which
comes from a freelist, so a 50 Hz loop runs without allocator calls.
"""
cimport cython
from libc.math cimport isfinite
from cpython.mem cimport PyMem_Free, PyMem_Malloc

from drivekin._core.types cimport pose2_t, rot2_t
from drivekin._core.args cimport check_type
from drivekin._core.wheels cimport _WheelValues
from drivekin._core.kernels cimport (deadwheel_solve, forward_solve, forward_solve_many,
                                     gyro_turn, mat_vec,
                                odometry_move, odometry_move_cs, odometry_step, pose,
                                rot_radians, rot_xy, vec)
from drivekin.geometry cimport Pose2d, Rotation2d, Translation2d, new_pose
from drivekin.swerve cimport SwerveDriveKinematics
from drivekin.swervemodule cimport SwerveModulePosition
from drivekin.mecanum cimport MecanumDriveKinematics, MecanumDriveWheelPositions
from drivekin.deadwheel cimport DeadWheelKinematics
from drivekin.chassis cimport new_chassis_velocities
from drivekin._core.errors import type_name


cdef pose2_t initial(object p) except *:
    if p is None:
        return pose(vec(0.0, 0.0), rot_xy(1.0, 0.0))
    if not isinstance(p, Pose2d):
        raise TypeError(f"initial_pose must be a Pose2d, got {type_name(p)}")
    return (<Pose2d>p).p


cdef int uninitialised(object odometry) except -1:
    # Callers test the flag inline; this cold path only builds the error.
    raise RuntimeError(f"{type(odometry).__name__}.__init__ has not completed")


cdef class _Odometry:
    """Pose state and the resets shared by every odometry class."""

    cdef int _start_init(self) except -1:
        if self.ready:
            raise TypeError(f"{type(self).__name__} is already initialised: __init__ cannot "
                            "be called again (use resetPosition)")
        return 0

    def getPose(self):
        """Return the current pose estimate (field frame, m)."""
        if not self.ready:
            uninitialised(self)
        return new_pose(self.pose)

    def resetPose(self, pose: Pose2d):
        """Set the pose; the gyro and wheel baselines are left as they are."""
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self.pose = (<Pose2d>pose).p

    def resetTranslation(self, translation: Translation2d):
        """Set the position and keep the heading."""
        check_type(translation, Translation2d, "translation")
        if not self.ready:
            uninitialised(self)
        self.pose.t = (<Translation2d>translation).v

    def resetRotation(self, rotation: Rotation2d):
        """Set the heading and keep the position. (robotpy-wpimath 2026 has a sign bug
        here that makes the next update report a wrong heading; drivekin does not.)"""
        check_type(rotation, Rotation2d, "rotation")
        if not self.ready:
            uninitialised(self)
        self.pose.r = (<Rotation2d>rotation).r

    cdef void _motions(self, Py_ssize_t k, double* x, const double* c, const double* s,
                       double* dth, double* mxy, double* scratch) noexcept nogil:
        pass


cdef class SwerveDriveOdometry(_Odometry):
    """SwerveDriveOdometry(kinematics, gyro_angle, module_positions, initial_pose=Pose2d())

    Tracks a swerve robot's pose from N module positions (SwerveModulePosition objects or
    an (N, 2) float64 array ``[distance m, angle rad]``) and a gyro angle (Rotation2d).
    """

    def __cinit__(self, *args, **kwargs):
        self.prev = NULL

    def __init__(self, kinematics: SwerveDriveKinematics, gyro_angle: Rotation2d,
                 module_positions, initial_pose=None):
        cdef Py_ssize_t i
        check_type(kinematics, SwerveDriveKinematics, "kinematics")
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        cdef SwerveDriveKinematics kin = <SwerveDriveKinematics>kinematics
        self._start_init()
        cdef pose2_t p = initial(initial_pose)
        kin._read(module_positions, SwerveModulePosition, "module_positions")
        self._start_init()      # again: reading an iterable ran Python code
        cdef double* prev = <double*>PyMem_Malloc(sizeof(double) * kin.n)
        if prev == NULL:
            raise MemoryError()
        for i in range(kin.n):
            prev[i] = kin.s0[i]
        self.prev = prev
        self.kin = kin
        self.width = kin.n
        self.steered = True
        self.gyro = True
        self.prev_gyro = (<Rotation2d>gyro_angle).r
        self.pose = p
        self.ready = True

    def __dealloc__(self):
        PyMem_Free(self.prev)

    def resetPosition(self, gyro_angle: Rotation2d, wheel_positions, pose: Pose2d):
        """Reset the pose, the gyro baseline and the module-position baseline."""
        cdef Py_ssize_t i
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self.kin._read(wheel_positions, SwerveModulePosition, "wheel_positions")
        for i in range(self.kin.n):
            self.prev[i] = self.kin.s0[i]
        self.prev_gyro = (<Rotation2d>gyro_angle).r
        self.pose = (<Pose2d>pose).p

    def update(self, gyro_angle: Rotation2d, wheel_positions):
        """Integrate the module-distance changes since the last call (at the current module
        angles) and the gyro change; return the new pose."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        self._step(<Rotation2d>gyro_angle, wheel_positions)
        return new_pose(self.pose)

    cdef int _step(self, Rotation2d gyro_angle, object wheel_positions) except -1:
        cdef SwerveDriveKinematics k = self.kin
        if not self.ready:
            uninitialised(self)
        cdef double r[3]
        k._read(wheel_positions, SwerveModulePosition, "wheel_positions")
        self._motion(k.s0, k.s1, k.s2, r)
        odometry_step(&self.pose, &self.prev_gyro, &self.twist, r[0], r[1], gyro_angle.r)
        return 0

    cdef void _motion(self, double* dist, const double* c, const double* s,
                      double* r) noexcept nogil:
        cdef Py_ssize_t i
        cdef double d
        for i in range(self.kin.n):
            d = dist[i]
            dist[i] = d - self.prev[i]
            self.prev[i] = d
        forward_solve(3, self.kin.n, self.kin.f1, dist, c, s, r)

    cdef void _motions(self, Py_ssize_t k, double* x, const double* c, const double* s,
                       double* dth, double* mxy, double* scratch) noexcept nogil:
        # Module-major, so both loops vectorise across samples: the distance changes,
        # then the solve for (dx, dy) (its dθ row is not needed: the gyro gives dθ).
        cdef Py_ssize_t i, j, n = self.kin.n
        cdef double d, last
        for j in range(n):
            last = self.prev[j]
            for i in range(k):
                d = x[k * j + i]
                x[k * j + i] = d - last
                last = d
            self.prev[j] = last
        forward_solve_many(2, n, k, self.kin.f1, x, c, s, mxy)


cdef class MecanumDriveOdometry(_Odometry):
    """MecanumDriveOdometry(kinematics, gyro_angle, wheel_positions, initial_pose=Pose2d())

    Tracks a mecanum robot's pose from MecanumDriveWheelPositions (m) and a gyro angle.
    """

    def __init__(self, kinematics: MecanumDriveKinematics, gyro_angle: Rotation2d,
                 wheel_positions: MecanumDriveWheelPositions, initial_pose=None):
        check_type(kinematics, MecanumDriveKinematics, "kinematics")
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(wheel_positions, MecanumDriveWheelPositions, "wheel_positions")
        self._start_init()
        (<MecanumDriveKinematics>kinematics)._ready()
        self.pose = initial(initial_pose)
        self.kin = <MecanumDriveKinematics>kinematics
        self.prev = (<_WheelValues>wheel_positions).w
        self.width = 4
        self.gyro = True
        self.prev_gyro = (<Rotation2d>gyro_angle).r
        self.ready = True

    def resetPosition(self, gyro_angle: Rotation2d,
                      wheel_positions: MecanumDriveWheelPositions, pose: Pose2d):
        """Reset the pose, the gyro baseline and the wheel-position baseline."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(wheel_positions, MecanumDriveWheelPositions, "wheel_positions")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self.prev = (<_WheelValues>wheel_positions).w
        self.prev_gyro = (<Rotation2d>gyro_angle).r
        self.pose = (<Pose2d>pose).p

    def update(self, gyro_angle: Rotation2d,
               wheel_positions: MecanumDriveWheelPositions):
        """Integrate the wheel-distance changes since the last call and the gyro change;
        return the new pose."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(wheel_positions, MecanumDriveWheelPositions, "wheel_positions")
        self._step(<Rotation2d>gyro_angle, <MecanumDriveWheelPositions>wheel_positions)
        return new_pose(self.pose)

    cdef int _step(self, Rotation2d gyro_angle,
                   MecanumDriveWheelPositions wheel_positions) except -1:
        if not self.ready:
            uninitialised(self)
        cdef double r[3]
        self._motion((<_WheelValues>wheel_positions).w, r)
        odometry_step(&self.pose, &self.prev_gyro, &self.twist, r[0], r[1], gyro_angle.r)
        return 0

    cdef void _motion(self, const double* w, double* r) noexcept nogil:
        cdef double d[4]
        cdef Py_ssize_t i
        for i in range(4):
            d[i] = w[i] - self.prev[i]
        for i in range(4):
            self.prev[i] = w[i]
        mat_vec(3, 4, self.kin.f, d, r)

    cdef void _motions(self, Py_ssize_t k, double* x, const double* c, const double* s,
                       double* dth, double* mxy, double* scratch) noexcept nogil:
        cdef Py_ssize_t i
        cdef double r[3]
        for i in range(k):
            self._motion(x + 4 * i, r)
            mxy[i] = r[0]
            mxy[k + i] = r[1]


cdef class DifferentialDriveOdometry(_Odometry):
    """DifferentialDriveOdometry(gyro_angle, left_distance, right_distance, initial_pose=Pose2d())

    Tracks a differential-drive robot's pose from the left and right wheel distances (m)
    and a gyro angle. No trackwidth is needed: the heading comes from the gyro.
    """

    def __init__(self, gyro_angle: Rotation2d, double left_distance, double right_distance,
                 initial_pose=None):
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        self._start_init()
        self.pose = initial(initial_pose)
        self.prev_l = left_distance
        self.prev_r = right_distance
        self.width = 2
        self.gyro = True
        self.prev_gyro = (<Rotation2d>gyro_angle).r
        self.ready = True

    def resetPosition(self, gyro_angle: Rotation2d, double left_distance,
                      double right_distance, pose: Pose2d):
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self.prev_l = left_distance
        self.prev_r = right_distance
        self.prev_gyro = (<Rotation2d>gyro_angle).r
        self.pose = (<Pose2d>pose).p

    def update(self, gyro_angle: Rotation2d, double left_distance, double right_distance):
        """Integrate the wheel-distance changes since the last call (dx = mean change,
        dy = 0) and the gyro change; return the new pose."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        self._step(<Rotation2d>gyro_angle, left_distance, right_distance)
        return new_pose(self.pose)

    cdef int _step(self, Rotation2d gyro_angle, double left_distance,
                   double right_distance) except -1:
        if not self.ready:
            uninitialised(self)
        cdef double r[3]
        self._motion(left_distance, right_distance, r)
        odometry_step(&self.pose, &self.prev_gyro, &self.twist, r[0], r[1], gyro_angle.r)
        return 0

    cdef void _motion(self, double left_distance, double right_distance,
                      double* r) noexcept nogil:
        cdef double dl = left_distance - self.prev_l, dr = right_distance - self.prev_r
        self.prev_l = left_distance
        self.prev_r = right_distance
        r[0] = (dl + dr) / 2.0
        r[1] = 0.0

    cdef void _motions(self, Py_ssize_t k, double* x, const double* c, const double* s,
                       double* dth, double* mxy, double* scratch) noexcept nogil:
        cdef Py_ssize_t i
        cdef double r[3]
        for i in range(k):
            self._motion(x[2 * i], x[2 * i + 1], r)
            mxy[i] = r[0]
            mxy[k + i] = r[1]


cdef class TwoDeadWheelOdometry(_Odometry):
    """TwoDeadWheelOdometry(x_wheel_y_pos, y_wheel_x_pos, x_wheel_pos, y_wheel_pos, gyro_angle, initial_pose=Pose2d())

    WPILib's two-dead-wheel odometry (goBILDA Pinpoint's layout): a forward-facing wheel
    at y = ``x_wheel_y_pos`` (m) reading forward motion, a left-facing wheel at
    x = ``y_wheel_x_pos`` (m) reading leftward motion, and a gyro for the heading. The
    offsets are Pinpoint's: X-pod offset positive to the left, Y-pod offset positive
    forward. ``x_wheel_pos``/``y_wheel_pos`` are the wheels' current distances (m).
    Each update uses dθ = the wrapped gyro change, dx = Δx + dθ·x_wheel_y_pos and
    dy = Δy − dθ·y_wheel_x_pos.
    """

    def __init__(self, double x_wheel_y_pos, double y_wheel_x_pos, double x_wheel_pos,
                 double y_wheel_pos, gyro_angle: Rotation2d, initial_pose=None):
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        self._start_init()
        if not (isfinite(x_wheel_y_pos) and isfinite(y_wheel_x_pos)):
            raise ValueError(f"wheel offsets must be finite (m), got x_wheel_y_pos="
                             f"{x_wheel_y_pos!r}, y_wheel_x_pos={y_wheel_x_pos!r}")
        self.pose = initial(initial_pose)
        self.x_wheel_y = x_wheel_y_pos
        self.y_wheel_x = y_wheel_x_pos
        self.prev_x = x_wheel_pos
        self.prev_y = y_wheel_pos
        self.width = 2
        self.gyro = True
        self.prev_gyro = (<Rotation2d>gyro_angle).r
        self.ready = True

    def resetPosition(self, double x_wheel_pos, double y_wheel_pos, gyro_angle: Rotation2d,
                      pose: Pose2d):
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self.prev_x = x_wheel_pos
        self.prev_y = y_wheel_pos
        self.prev_gyro = (<Rotation2d>gyro_angle).r
        self.pose = (<Pose2d>pose).p

    def update(self, double x_wheel_pos, double y_wheel_pos, gyro_angle: Rotation2d):
        """Integrate the wheel-distance changes (m) since the last call and the gyro
        change; return the new pose."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        self._step(x_wheel_pos, y_wheel_pos, <Rotation2d>gyro_angle)
        return new_pose(self.pose)

    cdef int _step(self, double x_wheel_pos, double y_wheel_pos,
                   Rotation2d gyro_angle) except -1:
        if not self.ready:
            uninitialised(self)
        cdef double r[3]
        cdef rot2_t turn = gyro_turn(gyro_angle.r, &self.prev_gyro)
        cdef double dtheta = rot_radians(turn)
        self._motion(x_wheel_pos, y_wheel_pos, dtheta, r)
        odometry_move_cs(&self.pose, &self.twist, r[0], r[1], dtheta, turn.c, turn.s, True)
        return 0

    cdef void _motion(self, double x_wheel_pos, double y_wheel_pos, double dtheta,
                      double* r) noexcept nogil:
        # The wheels' readings minus the arcs the heading change dtheta swept them through.
        r[0] = x_wheel_pos - self.prev_x + dtheta * self.x_wheel_y
        r[1] = y_wheel_pos - self.prev_y - dtheta * self.y_wheel_x
        self.prev_x = x_wheel_pos
        self.prev_y = y_wheel_pos

    cdef void _motions(self, Py_ssize_t k, double* x, const double* c, const double* s,
                       double* dth, double* mxy, double* scratch) noexcept nogil:
        cdef Py_ssize_t i
        cdef double r[3]
        for i in range(k):
            self._motion(x[2 * i], x[2 * i + 1], dth[i], r)
            mxy[i] = r[0]
            mxy[k + i] = r[1]

    def toChassisVelocities(self, double vx, double vy, double omega):
        """Return the robot velocity from the forward wheel's and left wheel's surface
        velocities ``vx``, ``vy`` (m/s) and the gyro rate ``omega`` (rad/s):
        (vx + omega·x_wheel_y_pos, vy − omega·y_wheel_x_pos, omega)."""
        if not self.ready:
            uninitialised(self)
        return new_chassis_velocities(vx + omega * self.x_wheel_y,
                                      vy - omega * self.y_wheel_x, omega)


cdef class DeadWheelOdometry(_Odometry):
    """DeadWheelOdometry(kinematics, wheel_positions, gyro_angle=None, initial_pose=Pose2d())

    Tracks a robot's pose from N dead wheels (DeadWheelKinematics) and, optionally, a
    gyro. ``wheel_positions`` are the wheels' distances (m): a list or tuple of floats or a
    1-D float64 array, in the kinematics' wheel order. With a gyro (``gyro_angle`` a
    Rotation2d) every update takes dθ from its wrapped change and fits (dx, dy) to the
    wheels; without one, all three come from the wheels (the layout must observe
    rotation). Whether a gyro is used is fixed here: ``update`` and ``resetPosition``
    must then always pass one, or never.
    """

    def __cinit__(self, *args, **kwargs):
        self.prev = NULL

    def __init__(self, kinematics: DeadWheelKinematics, wheel_positions,
                 gyro_angle=None, initial_pose=None):
        check_type(kinematics, DeadWheelKinematics, "kinematics")
        cdef DeadWheelKinematics kin = <DeadWheelKinematics>kinematics
        self._start_init()
        kin._ready()
        if gyro_angle is None:
            if not kin.heading:
                kin._need_heading("DeadWheelOdometry")
        elif not isinstance(gyro_angle, Rotation2d):
            raise TypeError(f"gyro_angle must be a Rotation2d or None, "
                            f"got {type_name(gyro_angle)}")
        cdef pose2_t p = initial(initial_pose)
        cdef double* prev = <double*>PyMem_Malloc(sizeof(double) * kin.n)
        if prev == NULL:
            raise MemoryError()
        try:
            kin._read(wheel_positions, prev, "wheel_positions")
        except BaseException:
            PyMem_Free(prev)
            raise
        self.prev = prev
        self.kin = kin
        self.width = kin.n
        self.gyro = gyro_angle is not None
        if self.gyro:
            self.prev_gyro = (<Rotation2d>gyro_angle).r
        self.pose = p
        self.ready = True

    def __dealloc__(self):
        PyMem_Free(self.prev)

    cdef int _gyro_arg(self, object gyro_angle, str call) except -1:
        if self.gyro:
            if not isinstance(gyro_angle, Rotation2d):
                raise TypeError(f"{call}: this DeadWheelOdometry uses a gyro, so gyro_angle "
                                f"must be a Rotation2d, got {type_name(gyro_angle)}")
        elif gyro_angle is not None:
            raise ValueError(f"{call}: this DeadWheelOdometry was constructed without a "
                             "gyro, so gyro_angle must be None")
        return 0

    def resetPosition(self, wheel_positions, gyro_angle, pose: Pose2d):
        """Reset the pose, the wheel-position baselines and (with a gyro) the gyro
        baseline; pass ``gyro_angle=None`` for an odometry without a gyro."""
        cdef Py_ssize_t i
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self._gyro_arg(gyro_angle, "resetPosition")
        self.kin._read(wheel_positions, self.kin.s, "wheel_positions")
        for i in range(self.kin.n):
            self.prev[i] = self.kin.s[i]
        if self.gyro:
            self.prev_gyro = (<Rotation2d>gyro_angle).r
        self.pose = (<Pose2d>pose).p

    def update(self, wheel_positions, gyro_angle=None):
        """Integrate the wheel-distance changes (m) since the last call (and the gyro
        change, with a gyro); return the new pose."""
        self._step(wheel_positions, gyro_angle)
        return new_pose(self.pose)

    cdef int _step(self, object wheel_positions, object gyro_angle) except -1:
        cdef DeadWheelKinematics k = self.kin
        if not self.ready:
            uninitialised(self)
        self._gyro_arg(gyro_angle, "update")
        k._read(wheel_positions, k.s, "wheel_positions")
        cdef double r[3]
        cdef rot2_t turn
        if self.gyro:
            turn = gyro_turn((<Rotation2d>gyro_angle).r, &self.prev_gyro)
            self._motion(k.s, rot_radians(turn), r)
            odometry_move_cs(&self.pose, &self.twist, r[0], r[1], r[2], turn.c, turn.s,
                             True)
        else:
            self._motion(k.s, 0.0, r)
            odometry_move(&self.pose, &self.twist, r[0], r[1], r[2])
        return 0

    cdef void _motion(self, double* dist, double dtheta, double* r) noexcept nogil:
        # r = (dx, dy, dθ); with a gyro dθ is the given dtheta, without one it is fitted
        # from the wheels (dtheta is ignored).
        cdef Py_ssize_t i
        cdef double d
        for i in range(self.kin.n):
            d = dist[i]
            dist[i] = d - self.prev[i]
            self.prev[i] = d
        deadwheel_solve(self.kin.n, self.kin.p3, self.kin.p2, self.kin.g, dist, self.gyro,
                        dtheta, r)

    cdef void _motions(self, Py_ssize_t k, double* x, const double* c, const double* s,
                       double* dth, double* mxy, double* scratch) noexcept nogil:
        # _motion turns the distances into changes in place: a copy of each row.
        cdef Py_ssize_t i, j, n = self.width
        cdef double r[3]
        for i in range(k):
            for j in range(n):
                scratch[j] = x[n * i + j]
            self._motion(scratch, dth[i] if self.gyro else 0.0, r)
            if not self.gyro:
                dth[i] = r[2]
            mxy[i] = r[0]
            mxy[k + i] = r[1]
