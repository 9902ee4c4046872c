"""3-D odometry for swerve, mecanum, differential and dead-wheel drivetrains (WPILib 2027's
Odometry3d).

Each ``update`` takes the gyro's change since the previous call as a body-frame rotation
Δ = gyro.relativeTo(previous gyro) with rotation vector ρ, and the wheel-position changes
through the drivetrain's forward kinematics as a planar twist (dx, dy) in the robot
frame; the pose moves by Twist3d(dx, dy, 0, ρ).exp(). The translation is integrated
along the robot's axes, so driving up a pitched ramp produces z; roll, pitch and heading
come from the gyro alone. The pose's rotation starts at the initial pose's rotation
(the identity by default), whatever the gyro reads: only the gyro's changes are
composed onto it.

``update`` returns the new pose; it allocates nothing beyond that Pose3d, which comes
from a freelist, so a 50 Hz loop runs without allocator calls.
"""
cimport cython
from cpython.mem cimport PyMem_Free, PyMem_Malloc
from libc.string cimport memcpy

from drivekin._core.args cimport check_type
from drivekin._core.drivetrain cimport Drivetrain, position_changes
from drivekin._core.kernels3d cimport pose3, q_identity, rot3_relative_to, rot3_z, vec3
from drivekin._core.types cimport pose3_t, quat_t
from drivekin._core.wheels cimport _WheelValues
from drivekin.chassis cimport new_chassis_velocities
from drivekin.deadwheel cimport DeadWheelKinematics
from drivekin.differential cimport DifferentialDriveKinematics
from drivekin.geometry cimport Pose2d, Rotation2d
from drivekin.geometry3d cimport Pose3d, Rotation3d, Translation3d, new_pose3d
from drivekin.mecanum cimport MecanumDriveKinematics, MecanumDriveWheelPositions
from drivekin.swerve cimport SwerveDriveKinematics
from drivekin.swervemodule cimport SwerveModulePosition
from drivekin._core.errors import type_name


cdef pose3_t initial(object p) except *:
    if p is None:
        return pose3(vec3(0.0, 0.0, 0.0), q_identity())
    if type(p) is not Pose3d:
        raise TypeError(f"initial_pose must be a Pose3d, got {type_name(p)}")
    return (<Pose3d>p).p


cdef int uninitialised(object odometry) except -1:
    # Callers test the flag inline; this cold path only builds the error.
    raise RuntimeError(f"{type(odometry).__name__}.__init__ has not completed")


cdef int refuse_reinit(_Odometry3d odometry) except -1:
    if odometry.ready:
        raise TypeError(f"{type(odometry).__name__} is already initialised: __init__ cannot "
                        "be called again (use resetPosition)")
    return 0


cdef class _Odometry3d:
    """Pose state, the update and the resets shared by every 3-D odometry class."""

    def __cinit__(self, *args, **kwargs):
        self.prev = NULL

    def __dealloc__(self):
        PyMem_Free(self.prev)

    cdef int _begin(self, Drivetrain kin, Py_ssize_t width, bint yaw, object gyro_angle,
                    object a, object b, object initial_pose) except -1:
        cdef double* cur
        cdef const double* c
        cdef const double* s
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        refuse_reinit(self)
        cdef pose3_t p = initial(initial_pose)
        kin._ready()
        self.kin = kin               # read by _read; nothing computes before ``ready``
        self.width = width
        self._read(a, b, &cur, &c, &s)
        refuse_reinit(self)          # again: reading a sequence may have run Python code
        cdef double* prev = <double*>PyMem_Malloc(sizeof(double) * width)
        if prev == NULL:
            raise MemoryError()
        memcpy(prev, cur, sizeof(double) * width)
        PyMem_Free(self.prev)
        self.prev = prev
        self.yaw = yaw
        self.prev_gyro = (<Rotation3d>gyro_angle).q
        self.pose = p
        self.ready = True
        return 0

    cdef int _read(self, object a, object b, double** cur, const double** c,
                   const double** s) except -1:
        # Two wheel distances (m), as numbers: the differential drive's and the two dead
        # wheels'; the other drivetrains read their own forms.
        try:
            self.scratch[0] = a
            self.scratch[1] = b
        except TypeError:
            raise TypeError(f"the two wheel distances must be numbers (m), got "
                            f"{type_name(a)} and {type_name(b)}") from None
        cur[0] = self.scratch
        c[0] = NULL
        s[0] = NULL
        return 0

    cdef int _step(self, Rotation3d gyro_angle, object a, object b) except -1:
        cdef double* cur
        cdef const double* c
        cdef const double* s
        if not self.ready:
            uninitialised(self)
        self._read(a, b, &cur, &c, &s)
        self._move(gyro_angle.q, cur, c, s)
        return 0

    cdef void _move(self, quat_t gyro, double* cur, const double* c,
                    const double* s) noexcept nogil:
        # WPILib's Odometry3d.update: Δ = gyro.relativeTo(previous), the wheels' (dx, dy)
        # (their dθ ignored: swerve, mecanum and differential do not need one for (dx, dy);
        # dead wheels take the yaw of Δ for the arcs the turn swept them through, as
        # WPILib's two-dead-wheel draft does), pose ← pose + Twist3d(dx, dy, 0, ρ).exp().
        cdef quat_t turn = rot3_relative_to(gyro, self.prev_gyro)
        cdef double dth = rot3_z(turn) if self.yaw else 0.0
        cdef double out[3]
        position_changes(self.width, cur, self.prev)
        self.kin._twists(1, cur, c, s, &dth, out)
        odometry3d_move(&self.pose, &self.twist, out[0], out[1], turn)
        self.prev_gyro = gyro

    cdef int _reset(self, object gyro_angle, object a, object b, object pose) except -1:
        cdef double* cur
        cdef const double* c
        cdef const double* s
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        check_type(pose, Pose3d, "pose")
        if not self.ready:
            uninitialised(self)
        self._read(a, b, &cur, &c, &s)
        memcpy(self.prev, cur, sizeof(double) * self.width)
        self.prev_gyro = (<Rotation3d>gyro_angle).q
        self.pose = (<Pose3d>pose).p
        return 0

    def getPose(self):
        """Return the current pose estimate (field frame, m)."""
        if not self.ready:
            uninitialised(self)
        return new_pose3d(self.pose)

    def resetPose(self, pose: Pose3d):
        """Set the pose; the gyro and wheel baselines are left as they are."""
        check_type(pose, Pose3d, "pose")
        if not self.ready:
            uninitialised(self)
        self.pose = (<Pose3d>pose).p

    def resetTranslation(self, translation: Translation3d):
        """Set the position and keep the rotation."""
        check_type(translation, Translation3d, "translation")
        if not self.ready:
            uninitialised(self)
        self.pose.t = (<Translation3d>translation).v

    def resetRotation(self, rotation: Rotation3d):
        """Set the rotation and keep the position; later gyro changes are composed onto
        it."""
        check_type(rotation, Rotation3d, "rotation")
        if not self.ready:
            uninitialised(self)
        self.pose.q = (<Rotation3d>rotation).q


cdef class SwerveDriveOdometry3d(_Odometry3d):
    """SwerveDriveOdometry3d(kinematics, gyro_angle, module_positions, initial_pose=Pose3d())

    Tracks a swerve robot's 3-D pose from N module positions (SwerveModulePosition objects
    or an (N, 2) float64 array ``[distance m, angle rad]``) and a gyro (Rotation3d). A
    later call with another number of modules raises ValueError and changes nothing.
    """

    def __init__(self, kinematics: SwerveDriveKinematics, gyro_angle: Rotation3d,
                 module_positions, initial_pose=None):
        check_type(kinematics, SwerveDriveKinematics, "kinematics")
        refuse_reinit(self)
        self._begin(<SwerveDriveKinematics>kinematics,
                    (<SwerveDriveKinematics>kinematics).n, False, gyro_angle,
                    module_positions, None, initial_pose)

    cdef int _read(self, object a, object b, double** cur, const double** c,
                   const double** s) except -1:
        cdef SwerveDriveKinematics k = <SwerveDriveKinematics>self.kin
        k._read(a, SwerveModulePosition, "wheel_positions")
        cur[0] = k.s0
        c[0] = k.s1
        s[0] = k.s2
        return 0

    def resetPosition(self, gyro_angle: Rotation3d, wheel_positions, pose: Pose3d):
        """Reset the pose, the gyro baseline and the module-position baseline."""
        self._reset(gyro_angle, wheel_positions, None, pose)

    def update(self, gyro_angle: Rotation3d, wheel_positions):
        """Integrate the module-distance changes since the last call (at the current module
        angles) and the gyro change; return the new pose."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        self._step(<Rotation3d>gyro_angle, wheel_positions, None)
        return new_pose3d(self.pose)


cdef class MecanumDriveOdometry3d(_Odometry3d):
    """MecanumDriveOdometry3d(kinematics, gyro_angle, wheel_positions, initial_pose=Pose3d())

    Tracks a mecanum robot's 3-D pose from MecanumDriveWheelPositions (m) and a gyro
    (Rotation3d).
    """

    def __init__(self, kinematics: MecanumDriveKinematics, gyro_angle: Rotation3d,
                 wheel_positions: MecanumDriveWheelPositions, initial_pose=None):
        check_type(kinematics, MecanumDriveKinematics, "kinematics")
        refuse_reinit(self)
        self._begin(<MecanumDriveKinematics>kinematics, 4, False, gyro_angle,
                    wheel_positions, None, initial_pose)

    cdef int _read(self, object a, object b, double** cur, const double** c,
                   const double** s) except -1:
        check_type(a, MecanumDriveWheelPositions, "wheel_positions")
        memcpy(self.scratch, (<_WheelValues>a).w, sizeof(double) * 4)
        cur[0] = self.scratch
        c[0] = NULL
        s[0] = NULL
        return 0

    def resetPosition(self, gyro_angle: Rotation3d,
                      wheel_positions: MecanumDriveWheelPositions, pose: Pose3d):
        """Reset the pose, the gyro baseline and the wheel-position baseline."""
        self._reset(gyro_angle, wheel_positions, None, pose)

    def update(self, gyro_angle: Rotation3d, wheel_positions: MecanumDriveWheelPositions):
        """Integrate the wheel-distance changes since the last call and the gyro change;
        return the new pose."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        self._step(<Rotation3d>gyro_angle, wheel_positions, None)
        return new_pose3d(self.pose)


cdef class DifferentialDriveOdometry3d(_Odometry3d):
    """DifferentialDriveOdometry3d(gyro_angle, left_distance, right_distance, initial_pose=Pose3d())

    Tracks a differential-drive robot's 3-D pose from the left and right wheel distances
    (m) and a gyro (Rotation3d). No trackwidth is needed: the rotation comes from the gyro.
    """

    def __init__(self, gyro_angle: Rotation3d, left_distance, right_distance,
                 initial_pose=None):
        refuse_reinit(self)
        # The trackwidth only sets the wheels' dθ, which 3-D odometry does not use.
        self._begin(DifferentialDriveKinematics(1.0), 2, False, gyro_angle, left_distance,
                    right_distance, initial_pose)

    def resetPosition(self, gyro_angle: Rotation3d, left_distance, right_distance,
                      pose: Pose3d):
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""
        self._reset(gyro_angle, left_distance, right_distance, pose)

    def update(self, gyro_angle: Rotation3d, left_distance, right_distance):
        """Integrate the wheel-distance changes since the last call (dx = mean change,
        dy = 0) and the gyro change; return the new pose."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        self._step(<Rotation3d>gyro_angle, left_distance, right_distance)
        return new_pose3d(self.pose)


cdef class DeadWheelOdometry3d(_Odometry3d):
    """DeadWheelOdometry3d(kinematics, wheel_positions, gyro_angle, initial_pose=Pose3d())

    Tracks a robot's 3-D pose from N dead wheels (DeadWheelKinematics) and a gyro
    (Rotation3d). ``wheel_positions`` are the wheels' distances (m): a list or tuple of
    floats or a 1-D float64 array, in the kinematics' wheel order. Every update fits the
    robot-frame (dx, dy) to the wheel changes less the arcs that the yaw of the gyro's
    change swept each wheel through; any layout that observes (dx, dy) works, since the
    rotation comes from the gyro.
    """

    def __init__(self, kinematics: DeadWheelKinematics, wheel_positions,
                 gyro_angle: Rotation3d, initial_pose=None):
        check_type(kinematics, DeadWheelKinematics, "kinematics")
        refuse_reinit(self)
        self._begin(<DeadWheelKinematics>kinematics, (<DeadWheelKinematics>kinematics).n,
                    True, gyro_angle, wheel_positions, None, initial_pose)

    cdef int _read(self, object a, object b, double** cur, const double** c,
                   const double** s) except -1:
        cdef DeadWheelKinematics k = <DeadWheelKinematics>self.kin
        k._read(a, k.s, "wheel_positions")
        cur[0] = k.s
        c[0] = NULL
        s[0] = NULL
        return 0

    def resetPosition(self, wheel_positions, gyro_angle: Rotation3d, pose: Pose3d):
        """Reset the pose, the wheel-position baselines and the gyro baseline."""
        self._reset(gyro_angle, wheel_positions, None, pose)

    def update(self, wheel_positions, gyro_angle: Rotation3d):
        """Integrate the wheel-distance changes (m) since the last call and the gyro
        change; return the new pose."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        self._step(<Rotation3d>gyro_angle, wheel_positions, None)
        return new_pose3d(self.pose)


cdef class TwoDeadWheelOdometry3d(_Odometry3d):
    """TwoDeadWheelOdometry3d(x_wheel_y_pos, y_wheel_x_pos, x_wheel_pos, y_wheel_pos, gyro_angle, initial_pose=Pose3d())

    TwoDeadWheelOdometry in 3-D: a forward-facing wheel at y = ``x_wheel_y_pos`` (m), a
    left-facing wheel at x = ``y_wheel_x_pos`` (m) (goBILDA Pinpoint's pod offsets) and a
    gyro (Rotation3d). ``x_wheel_pos``/``y_wheel_pos`` are the wheels' distances (m). Each
    update uses dθ = the yaw of the gyro's change, dx = Δx + dθ·x_wheel_y_pos,
    dy = Δy − dθ·y_wheel_x_pos: a DeadWheelOdometry3d on those two wheels.
    """

    def __init__(self, double x_wheel_y_pos, double y_wheel_x_pos, x_wheel_pos, y_wheel_pos,
                 gyro_angle: Rotation3d, initial_pose=None):
        refuse_reinit(self)
        kin = DeadWheelKinematics((Pose2d(0.0, x_wheel_y_pos, Rotation2d(1.0, 0.0)),
                                   Pose2d(y_wheel_x_pos, 0.0, Rotation2d(0.0, 1.0))))
        self.x_wheel_y = x_wheel_y_pos
        self.y_wheel_x = y_wheel_x_pos
        self._begin(kin, 2, True, gyro_angle, x_wheel_pos, y_wheel_pos, initial_pose)

    def resetPosition(self, x_wheel_pos, y_wheel_pos, gyro_angle: Rotation3d, pose: Pose3d):
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""
        self._reset(gyro_angle, x_wheel_pos, y_wheel_pos, pose)

    def update(self, x_wheel_pos, y_wheel_pos, gyro_angle: Rotation3d):
        """Integrate the wheel-distance changes (m) since the last call and the gyro
        change; return the new pose."""
        check_type(gyro_angle, Rotation3d, "gyro_angle")
        self._step(<Rotation3d>gyro_angle, x_wheel_pos, y_wheel_pos)
        return new_pose3d(self.pose)

    def toChassisVelocities(self, double vx, double vy, double omega):
        """Return the robot velocity from the forward wheel's and left wheel's surface
        velocities ``vx``, ``vy`` (m/s) and the gyro's yaw rate ``omega`` (rad/s):
        (vx + omega·x_wheel_y_pos, vy − omega·y_wheel_x_pos, omega)."""
        if not self.ready:
            uninitialised(self)
        return new_chassis_velocities(vx + omega * self.x_wheel_y,
                                      vy - omega * self.y_wheel_x, omega)
