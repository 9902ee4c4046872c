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
from drivekin._core.drivetrain cimport Drivetrain, position_changes
from drivekin._core.wheels cimport _WheelValues
from drivekin._core.kernels cimport (gyro_turn, odometry_move, odometry_move_cs, pose,
                                     rot_radians, rot_xy, vec)
from drivekin.geometry cimport Pose2d, Rotation2d, Translation2d, new_pose
from drivekin.swerve cimport SwerveDriveKinematics
from drivekin.swervemodule cimport SwerveModulePosition
from drivekin.mecanum cimport MecanumDriveKinematics, MecanumDriveWheelPositions
from drivekin.differential cimport DifferentialDriveKinematics
from drivekin.deadwheel cimport DeadWheelKinematics
from drivekin.chassis cimport new_chassis_velocities
from drivekin._core.errors import type_name

# DifferentialDriveOdometry's drivetrain, as WPILib's: the trackwidth only scales the
# wheels' dθ, which the gyro's replaces.
cdef DifferentialDriveKinematics UNIT_TRACKWIDTH = DifferentialDriveKinematics(1.0)


cdef pose2_t initial(object p) except *:
    if p is None:
        return pose(vec(0.0, 0.0), rot_xy(1.0, 0.0))
    if not isinstance(p, Pose2d):
        raise TypeError(f"initial_pose must be a Pose2d, got {type_name(p)}")
    return (<Pose2d>p).p


cdef int uninitialised(object odometry) except -1:
    # Callers test the flag inline; this cold path only builds the error.
    raise RuntimeError(f"{type(odometry).__name__}.__init__ has not completed")


cdef inline void advance(_Odometry o, Py_ssize_t width, double* cur, const double* c,
                         const double* s, const rot2_t* gyro) noexcept:
    # The update on the width (= o.width: the classes that know it pass a literal, which
    # the compiler unrolls) readings already in C memory (cur: scratch, left holding the
    # changes; steered: c, s the module directions): the drivetrain's motion for the
    # heading change, which is the gyro's (gyro NULL: the wheels'), and the pose move.
    cdef double r[3]
    cdef double dth
    cdef rot2_t turn
    position_changes(width, cur, o.prev)
    if gyro != NULL:
        turn = gyro_turn(gyro[0], &o.prev_gyro)
        dth = rot_radians(turn)
        o.kin._twist(cur, c, s, &dth, r)
        odometry_move_cs(&o.pose, &o.twist, r[0], r[1], dth, turn.c, turn.s, True)
    else:
        o.kin._twist(cur, c, s, NULL, r)
        odometry_move(&o.pose, &o.twist, r[0], r[1], r[2])


cdef class _Odometry:
    """Pose state and the resets shared by every odometry class."""

    def __dealloc__(self):
        PyMem_Free(self.prev)

    cdef int _start_init(self) except -1:
        if self.ready:
            raise TypeError(f"{type(self).__name__} is already initialised: __init__ cannot "
                            "be called again (use resetPosition)")
        return 0

    cdef int _setup(self, Drivetrain kin, Py_ssize_t width, bint steered, object gyro_angle,
                    pose2_t p, const double* readings) except -1:
        # The end of every __init__, once its arguments are valid and ``readings`` (width
        # values) are in C memory; gyro_angle is a Rotation2d, or None without a gyro.
        cdef Py_ssize_t i
        self._start_init()      # again: reading the positions may have run Python code
        cdef double* prev = <double*>PyMem_Malloc(sizeof(double) * width)
        if prev == NULL:
            raise MemoryError()
        for i in range(width):
            prev[i] = readings[i]
        self.prev = prev
        self.kin = kin
        self.width = width
        self.steered = steered
        self.gyro = gyro_angle is not None
        if self.gyro:
            self.prev_gyro = (<Rotation2d>gyro_angle).r
        self.pose = p
        self.ready = True
        return 0

    cdef void _reset(self, const rot2_t* gyro, pose2_t p, const double* readings) noexcept:
        cdef Py_ssize_t i
        for i in range(self.width):
            self.prev[i] = readings[i]
        if gyro != NULL:
            self.prev_gyro = gyro[0]
        self.pose = p

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
                       double* dth, double* mxy) noexcept nogil:
        # Wheel-major, as _twists takes them, so both passes vectorise across samples.
        cdef Py_ssize_t i, j
        cdef double d, last
        for j in range(self.width):
            last = self.prev[j]
            for i in range(k):
                d = x[k * j + i]
                x[k * j + i] = d - last
                last = d
            self.prev[j] = last
        if self.gyro:
            self.kin._twists(k, x, c, s, dth, mxy)
        else:
            self.kin._twists(k, x, c, s, NULL, mxy)
            for i in range(k):
                dth[i] = mxy[2 * k + i]


cdef class SwerveDriveOdometry(_Odometry):
    """SwerveDriveOdometry(kinematics, gyro_angle, module_positions, initial_pose=Pose2d())

    Tracks a swerve robot's pose from N module positions (SwerveModulePosition objects or
    an (N, 2) float64 array ``[distance m, angle rad]``) and a gyro angle (Rotation2d).
    """

    def __init__(self, kinematics: SwerveDriveKinematics, gyro_angle: Rotation2d,
                 module_positions, initial_pose=None):
        check_type(kinematics, SwerveDriveKinematics, "kinematics")
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        cdef SwerveDriveKinematics kin = <SwerveDriveKinematics>kinematics
        self._start_init()
        cdef pose2_t p = initial(initial_pose)
        kin._read(module_positions, SwerveModulePosition, "module_positions")
        self._setup(kin, kin.n, True, gyro_angle, p, kin.s0)

    def resetPosition(self, gyro_angle: Rotation2d, wheel_positions, pose: Pose2d):
        """Reset the pose, the gyro baseline and the module-position baseline."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        cdef SwerveDriveKinematics k = <SwerveDriveKinematics>self.kin
        k._read(wheel_positions, SwerveModulePosition, "wheel_positions")
        self._reset(&(<Rotation2d>gyro_angle).r, (<Pose2d>pose).p, k.s0)

    def update(self, gyro_angle: Rotation2d, wheel_positions):
        """Integrate the module-distance changes since the last call (at the current module
        angles) and the gyro change; return the new pose."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        self._step(<Rotation2d>gyro_angle, wheel_positions)
        return new_pose(self.pose)

    cdef int _step(self, Rotation2d gyro_angle, object wheel_positions) except -1:
        if not self.ready:
            uninitialised(self)
        cdef SwerveDriveKinematics k = <SwerveDriveKinematics>self.kin
        k._read(wheel_positions, SwerveModulePosition, "wheel_positions")
        advance(self, k.n, k.s0, k.s1, k.s2, &gyro_angle.r)
        return 0


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
        cdef pose2_t p = initial(initial_pose)
        self._setup(<MecanumDriveKinematics>kinematics, 4, False, gyro_angle, p,
                    (<_WheelValues>wheel_positions).w)

    def resetPosition(self, gyro_angle: Rotation2d,
                      wheel_positions: MecanumDriveWheelPositions, pose: Pose2d):
        """Reset the pose, the gyro baseline and the wheel-position baseline."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(wheel_positions, MecanumDriveWheelPositions, "wheel_positions")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self._reset(&(<Rotation2d>gyro_angle).r, (<Pose2d>pose).p,
                    (<_WheelValues>wheel_positions).w)

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
        cdef double cur[4]
        cur = (<_WheelValues>wheel_positions).w
        advance(self, 4, cur, NULL, NULL, &gyro_angle.r)
        return 0


cdef class DifferentialDriveOdometry(_Odometry):
    """DifferentialDriveOdometry(gyro_angle, left_distance, right_distance, initial_pose=Pose2d())

    Tracks a differential-drive robot's pose from the left and right wheel distances (m)
    and a gyro angle. No trackwidth is needed: the heading comes from the gyro.
    """

    def __init__(self, gyro_angle: Rotation2d, double left_distance, double right_distance,
                 initial_pose=None):
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        self._start_init()
        cdef double w[2]
        w[0] = left_distance
        w[1] = right_distance
        self._setup(UNIT_TRACKWIDTH, 2, False, gyro_angle, initial(initial_pose), w)

    def resetPosition(self, gyro_angle: Rotation2d, double left_distance,
                      double right_distance, pose: Pose2d):
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        cdef double w[2]
        w[0] = left_distance
        w[1] = right_distance
        self._reset(&(<Rotation2d>gyro_angle).r, (<Pose2d>pose).p, w)

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
        cdef double cur[2]
        cur[0] = left_distance
        cur[1] = right_distance
        advance(self, 2, cur, NULL, NULL, &gyro_angle.r)
        return 0


cdef inline void two_wheel_twists(double xy, double yx, Py_ssize_t k, const double* d,
                                  const double* dth, double* out) noexcept nogil:
    # The wheels' readings minus the arcs the heading change swept them through.
    cdef Py_ssize_t i
    for i in range(k):
        out[i] = d[i] + dth[i] * xy
        out[k + i] = d[k + i] - dth[i] * yx


@cython.final
cdef class _TwoDeadWheels(Drivetrain):
    """TwoDeadWheelOdometry's wheels as a drivetrain: a forward-facing wheel at y = xy, a
    left-facing one at x = yx (m). They cannot observe rotation: _twists needs dth."""
    cdef double xy
    cdef double yx

    cdef int _ready(self) except -1:
        return 0

    cdef int _forward_check(self, bint gyro, bint accel) except -1:
        if not gyro:
            raise ValueError("two dead wheels cannot observe rotation: pass the gyro's")
        return 0

    cdef void _twists(self, Py_ssize_t k, const double* d, const double* c, const double* s,
                      const double* dth, double* out) noexcept nogil:
        two_wheel_twists(self.xy, self.yx, k, d, dth, out)

    cdef void _twist(self, const double* d, const double* c, const double* s,
                     const double* dth, double* out) noexcept nogil:
        two_wheel_twists(self.xy, self.yx, 1, d, dth, out)


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
        cdef pose2_t p = initial(initial_pose)
        cdef _TwoDeadWheels wheels = _TwoDeadWheels.__new__(_TwoDeadWheels)
        wheels.nwheels = 2
        wheels.gyro_forward = True
        wheels.xy = x_wheel_y_pos
        wheels.yx = y_wheel_x_pos
        cdef double w[2]
        w[0] = x_wheel_pos
        w[1] = y_wheel_pos
        self._setup(wheels, 2, False, gyro_angle, p, w)

    def resetPosition(self, double x_wheel_pos, double y_wheel_pos, gyro_angle: Rotation2d,
                      pose: Pose2d):
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""
        check_type(gyro_angle, Rotation2d, "gyro_angle")
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        cdef double w[2]
        w[0] = x_wheel_pos
        w[1] = y_wheel_pos
        self._reset(&(<Rotation2d>gyro_angle).r, (<Pose2d>pose).p, w)

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
        cdef double cur[2]
        cur[0] = x_wheel_pos
        cur[1] = y_wheel_pos
        advance(self, 2, cur, NULL, NULL, &gyro_angle.r)
        return 0

    def toChassisVelocities(self, double vx, double vy, double omega):
        """Return the robot velocity from the forward wheel's and left wheel's surface
        velocities ``vx``, ``vy`` (m/s) and the gyro rate ``omega`` (rad/s):
        (vx + omega·x_wheel_y_pos, vy − omega·y_wheel_x_pos, omega)."""
        if not self.ready:
            uninitialised(self)
        cdef _TwoDeadWheels w = <_TwoDeadWheels>self.kin
        return new_chassis_velocities(vx + omega * w.xy, vy - omega * w.yx, omega)


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
        kin._read(wheel_positions, kin.s, "wheel_positions")
        self._setup(kin, kin.n, False, gyro_angle, p, kin.s)

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
        check_type(pose, Pose2d, "pose")
        if not self.ready:
            uninitialised(self)
        self._gyro_arg(gyro_angle, "resetPosition")
        cdef DeadWheelKinematics k = <DeadWheelKinematics>self.kin
        k._read(wheel_positions, k.s, "wheel_positions")
        self._reset(&(<Rotation2d>gyro_angle).r if self.gyro else NULL, (<Pose2d>pose).p,
                    k.s)

    def update(self, wheel_positions, gyro_angle=None):
        """Integrate the wheel-distance changes (m) since the last call (and the gyro
        change, with a gyro); return the new pose."""
        self._step(wheel_positions, gyro_angle)
        return new_pose(self.pose)

    cdef int _step(self, object wheel_positions, object gyro_angle) except -1:
        if not self.ready:
            uninitialised(self)
        self._gyro_arg(gyro_angle, "update")
        cdef DeadWheelKinematics k = <DeadWheelKinematics>self.kin
        k._read(wheel_positions, k.s, "wheel_positions")
        advance(self, k.n, k.s, NULL, NULL, &(<Rotation2d>gyro_angle).r if self.gyro else NULL)
        return 0
