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
        raise TypeError(f"initialPose must be a Pose2d, got {type_name(p)}")
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
    """SwerveDriveOdometry(kinematics, gyroAngle, modulePositions, initialPose=Pose2d())

    Tracks a swerve robot's pose from N module positions (SwerveModulePosition objects or
    an (N, 2) float64 array ``[distance m, angle rad]``) and a gyro angle (Rotation2d).
    """

    def __cinit__(self, *args, **kwargs):
        self.prev = NULL

    def __init__(self, kinematics: SwerveDriveKinematics, gyroAngle: Rotation2d,
                 modulePositions, initialPose=None):
        cdef Py_ssize_t i
        check_type(kinematics, SwerveDriveKinematics, "kinematics")
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        cdef SwerveDriveKinematics kin = <SwerveDriveKinematics>kinematics
        self._start_init()
        cdef pose2_t p = initial(initialPose)
        kin._read(modulePositions, SwerveModulePosition, "modulePositions")
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
        self.prev_gyro = (<Rotation2d>gyroAngle).r
        self.pose = p
        self.ready = True

    def __dealloc__(self):
        PyMem_Free(self.prev)

    def resetPosition(self, gyroAngle: Rotation2d, modulePositions, pose: Pose2d):
        """Reset the pose, the gyro baseline and the module-position baseline."""
        cdef Py_ssize_t i
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self.kin._read(modulePositions, SwerveModulePosition, "modulePositions")
        for i in range(self.kin.n):
            self.prev[i] = self.kin.s0[i]
        self.prev_gyro = (<Rotation2d>gyroAngle).r
        self.pose = (<Pose2d>pose).p

    def update(self, gyroAngle: Rotation2d, modulePositions):
        """Integrate the module-distance changes since the last call (at the current module
        angles) and the gyro change; return the new pose."""
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        self._step(<Rotation2d>gyroAngle, modulePositions)
        return new_pose(self.pose)

    cdef int _step(self, Rotation2d gyroAngle, object modulePositions) except -1:
        cdef SwerveDriveKinematics k = self.kin
        if not self.ready:
            uninitialised(self)
        cdef double r[3]
        k._read(modulePositions, SwerveModulePosition, "modulePositions")
        self._motion(k.s0, k.s1, k.s2, r)
        odometry_step(&self.pose, &self.prev_gyro, &self.twist, r[0], r[1], gyroAngle.r)
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
    """MecanumDriveOdometry(kinematics, gyroAngle, wheelPositions, initialPose=Pose2d())

    Tracks a mecanum robot's pose from MecanumDriveWheelPositions (m) and a gyro angle.
    """

    def __init__(self, kinematics: MecanumDriveKinematics, gyroAngle: Rotation2d,
                 wheelPositions: MecanumDriveWheelPositions, initialPose=None):
        check_type(kinematics, MecanumDriveKinematics, "kinematics")
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        check_type(wheelPositions, MecanumDriveWheelPositions, "wheelPositions")
        self._start_init()
        (<MecanumDriveKinematics>kinematics)._ready()
        self.pose = initial(initialPose)
        self.kin = <MecanumDriveKinematics>kinematics
        self.prev = (<_WheelValues>wheelPositions).w
        self.width = 4
        self.gyro = True
        self.prev_gyro = (<Rotation2d>gyroAngle).r
        self.ready = True

    def resetPosition(self, gyroAngle: Rotation2d,
                      wheelPositions: MecanumDriveWheelPositions, pose: Pose2d):
        """Reset the pose, the gyro baseline and the wheel-position baseline."""
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        check_type(wheelPositions, MecanumDriveWheelPositions, "wheelPositions")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self.prev = (<_WheelValues>wheelPositions).w
        self.prev_gyro = (<Rotation2d>gyroAngle).r
        self.pose = (<Pose2d>pose).p

    def update(self, gyroAngle: Rotation2d,
               wheelPositions: MecanumDriveWheelPositions):
        """Integrate the wheel-distance changes since the last call and the gyro change;
        return the new pose."""
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        check_type(wheelPositions, MecanumDriveWheelPositions, "wheelPositions")
        self._step(<Rotation2d>gyroAngle, <MecanumDriveWheelPositions>wheelPositions)
        return new_pose(self.pose)

    cdef int _step(self, Rotation2d gyroAngle, MecanumDriveWheelPositions wheelPositions) except -1:
        if not self.ready:
            uninitialised(self)
        cdef double r[3]
        self._motion((<_WheelValues>wheelPositions).w, r)
        odometry_step(&self.pose, &self.prev_gyro, &self.twist, r[0], r[1], gyroAngle.r)
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
    """DifferentialDriveOdometry(gyroAngle, leftDistance, rightDistance, initialPose=Pose2d())

    Tracks a differential-drive robot's pose from the left and right wheel distances (m)
    and a gyro angle. No trackwidth is needed: the heading comes from the gyro.
    """

    def __init__(self, gyroAngle: Rotation2d, double leftDistance, double rightDistance,
                 initialPose=None):
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        self._start_init()
        self.pose = initial(initialPose)
        self.prev_l = leftDistance
        self.prev_r = rightDistance
        self.width = 2
        self.gyro = True
        self.prev_gyro = (<Rotation2d>gyroAngle).r
        self.ready = True

    def resetPosition(self, gyroAngle: Rotation2d, double leftDistance,
                      double rightDistance, pose: Pose2d):
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self.prev_l = leftDistance
        self.prev_r = rightDistance
        self.prev_gyro = (<Rotation2d>gyroAngle).r
        self.pose = (<Pose2d>pose).p

    def update(self, gyroAngle: Rotation2d, double leftDistance, double rightDistance):
        """Integrate the wheel-distance changes since the last call (dx = mean change,
        dy = 0) and the gyro change; return the new pose."""
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        self._step(<Rotation2d>gyroAngle, leftDistance, rightDistance)
        return new_pose(self.pose)

    cdef int _step(self, Rotation2d gyroAngle, double leftDistance,
                   double rightDistance) except -1:
        if not self.ready:
            uninitialised(self)
        cdef double r[3]
        self._motion(leftDistance, rightDistance, r)
        odometry_step(&self.pose, &self.prev_gyro, &self.twist, r[0], r[1], gyroAngle.r)
        return 0

    cdef void _motion(self, double leftDistance, double rightDistance,
                      double* r) noexcept nogil:
        cdef double dl = leftDistance - self.prev_l, dr = rightDistance - self.prev_r
        self.prev_l = leftDistance
        self.prev_r = rightDistance
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
    """TwoDeadWheelOdometry(xWheelYPos, yWheelXPos, xWheelPos, yWheelPos, gyroAngle, initialPose=Pose2d())

    WPILib's two-dead-wheel odometry (goBILDA Pinpoint's layout): a forward-facing wheel
    at y = ``xWheelYPos`` (m) reading forward motion, a left-facing wheel at
    x = ``yWheelXPos`` (m) reading leftward motion, and a gyro for the heading. The
    offsets are Pinpoint's: X-pod offset positive to the left, Y-pod offset positive
    forward. ``xWheelPos``/``yWheelPos`` are the wheels' current distances (m).
    Each update uses dθ = the wrapped gyro change, dx = Δx + dθ·xWheelYPos and
    dy = Δy − dθ·yWheelXPos.
    """

    def __init__(self, double xWheelYPos, double yWheelXPos, double xWheelPos,
                 double yWheelPos, gyroAngle: Rotation2d, initialPose=None):
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        self._start_init()
        if not (isfinite(xWheelYPos) and isfinite(yWheelXPos)):
            raise ValueError(f"wheel offsets must be finite (m), got xWheelYPos="
                             f"{xWheelYPos!r}, yWheelXPos={yWheelXPos!r}")
        self.pose = initial(initialPose)
        self.x_wheel_y = xWheelYPos
        self.y_wheel_x = yWheelXPos
        self.prev_x = xWheelPos
        self.prev_y = yWheelPos
        self.width = 2
        self.gyro = True
        self.prev_gyro = (<Rotation2d>gyroAngle).r
        self.ready = True

    def resetPosition(self, double xWheelPos, double yWheelPos, gyroAngle: Rotation2d,
                      pose: Pose2d):
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self.prev_x = xWheelPos
        self.prev_y = yWheelPos
        self.prev_gyro = (<Rotation2d>gyroAngle).r
        self.pose = (<Pose2d>pose).p

    def update(self, double xWheelPos, double yWheelPos, gyroAngle: Rotation2d):
        """Integrate the wheel-distance changes (m) since the last call and the gyro
        change; return the new pose."""
        check_type(gyroAngle, Rotation2d, "gyroAngle")
        self._step(xWheelPos, yWheelPos, <Rotation2d>gyroAngle)
        return new_pose(self.pose)

    cdef int _step(self, double xWheelPos, double yWheelPos, Rotation2d gyroAngle) except -1:
        if not self.ready:
            uninitialised(self)
        cdef double r[3]
        cdef rot2_t turn = gyro_turn(gyroAngle.r, &self.prev_gyro)
        cdef double dtheta = rot_radians(turn)
        self._motion(xWheelPos, yWheelPos, dtheta, r)
        odometry_move_cs(&self.pose, &self.twist, r[0], r[1], dtheta, turn.c, turn.s, True)
        return 0

    cdef void _motion(self, double xWheelPos, double yWheelPos, double dtheta,
                      double* r) noexcept nogil:
        # The wheels' readings minus the arcs the heading change dtheta swept them through.
        r[0] = xWheelPos - self.prev_x + dtheta * self.x_wheel_y
        r[1] = yWheelPos - self.prev_y - dtheta * self.y_wheel_x
        self.prev_x = xWheelPos
        self.prev_y = yWheelPos

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
        (vx + omega·xWheelYPos, vy − omega·yWheelXPos, omega)."""
        if not self.ready:
            uninitialised(self)
        return new_chassis_velocities(vx + omega * self.x_wheel_y,
                                      vy - omega * self.y_wheel_x, omega)


cdef class DeadWheelOdometry(_Odometry):
    """DeadWheelOdometry(kinematics, wheelPositions, gyroAngle=None, initialPose=Pose2d())

    Tracks a robot's pose from N dead wheels (DeadWheelKinematics) and, optionally, a
    gyro. ``wheelPositions`` are the wheels' distances (m): a list or tuple of floats or a
    1-D float64 array, in the kinematics' wheel order. With a gyro (``gyroAngle`` a
    Rotation2d) every update takes dθ from its wrapped change and fits (dx, dy) to the
    wheels; without one, all three come from the wheels (the layout must observe
    rotation). Whether a gyro is used is fixed here: ``update`` and ``resetPosition``
    must then always pass one, or never.
    """

    def __cinit__(self, *args, **kwargs):
        self.prev = NULL

    def __init__(self, kinematics: DeadWheelKinematics, wheelPositions,
                 gyroAngle=None, initialPose=None):
        check_type(kinematics, DeadWheelKinematics, "kinematics")
        cdef DeadWheelKinematics kin = <DeadWheelKinematics>kinematics
        self._start_init()
        kin._ready()
        if gyroAngle is None:
            if not kin.heading:
                kin._need_heading("DeadWheelOdometry")
        elif not isinstance(gyroAngle, Rotation2d):
            raise TypeError(f"gyroAngle must be a Rotation2d or None, got {type_name(gyroAngle)}")
        cdef pose2_t p = initial(initialPose)
        cdef double* prev = <double*>PyMem_Malloc(sizeof(double) * kin.n)
        if prev == NULL:
            raise MemoryError()
        try:
            kin._read(wheelPositions, prev, "wheelPositions")
        except BaseException:
            PyMem_Free(prev)
            raise
        self.prev = prev
        self.kin = kin
        self.width = kin.n
        self.gyro = gyroAngle is not None
        if self.gyro:
            self.prev_gyro = (<Rotation2d>gyroAngle).r
        self.pose = p
        self.ready = True

    def __dealloc__(self):
        PyMem_Free(self.prev)

    cdef int _gyro_arg(self, object gyroAngle, str call) except -1:
        if self.gyro:
            if not isinstance(gyroAngle, Rotation2d):
                raise TypeError(f"{call}: this DeadWheelOdometry uses a gyro, so gyroAngle "
                                f"must be a Rotation2d, got {type_name(gyroAngle)}")
        elif gyroAngle is not None:
            raise ValueError(f"{call}: this DeadWheelOdometry was constructed without a "
                             "gyro, so gyroAngle must be None")
        return 0

    def resetPosition(self, wheelPositions, gyroAngle, pose: Pose2d):
        """Reset the pose, the wheel-position baselines and (with a gyro) the gyro
        baseline; pass ``gyroAngle=None`` for an odometry without a gyro."""
        cdef Py_ssize_t i
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self._gyro_arg(gyroAngle, "resetPosition")
        self.kin._read(wheelPositions, self.kin.s, "wheelPositions")
        for i in range(self.kin.n):
            self.prev[i] = self.kin.s[i]
        if self.gyro:
            self.prev_gyro = (<Rotation2d>gyroAngle).r
        self.pose = (<Pose2d>pose).p

    def update(self, wheelPositions, gyroAngle=None):
        """Integrate the wheel-distance changes (m) since the last call (and the gyro
        change, with a gyro); return the new pose."""
        self._step(wheelPositions, gyroAngle)
        return new_pose(self.pose)

    cdef int _step(self, object wheelPositions, object gyroAngle) except -1:
        cdef DeadWheelKinematics k = self.kin
        if not self.ready:
            uninitialised(self)
        self._gyro_arg(gyroAngle, "update")
        k._read(wheelPositions, k.s, "wheelPositions")
        cdef double r[3]
        cdef rot2_t turn
        if self.gyro:
            turn = gyro_turn((<Rotation2d>gyroAngle).r, &self.prev_gyro)
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
