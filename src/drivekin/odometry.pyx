"""Odometry for swerve, mecanum and differential drives (WPILib 2027).

Each ``update`` turns the wheel-position changes since the previous call into a twist
with the drivetrain's forward kinematics, replaces its heading change by the wrapped
gyro difference (the gyro is trusted for heading), and composes the pose with the
twist's exponential. The gyro reading need not match the pose heading: only its changes
matter. ``update`` returns the new pose; it allocates nothing beyond that Pose2d, which
comes from a freelist, so a 50 Hz loop runs without allocator calls.
"""
cimport cython
from cpython.mem cimport PyMem_Free, PyMem_Malloc

from drivekin._types cimport pose2_t
from drivekin._wheels cimport _WheelValues
from drivekin._kernels cimport forward_solve, mat_vec, odometry_step, pose, rot_xy, vec
from drivekin.geometry cimport Pose2d, Rotation2d, Translation2d, new_pose
from drivekin.kinematics cimport SwerveDriveKinematics, SwerveModulePosition
from drivekin.mecanum cimport MecanumDriveKinematics, MecanumDriveWheelPositions
from drivekin._errors import type_name


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

    def resetPose(self, Pose2d pose not None):
        """Set the pose; the gyro and wheel baselines are left as they are."""
        if not self.ready:
            uninitialised(self)
        self.pose = pose.p

    def resetTranslation(self, Translation2d translation not None):
        """Set the position and keep the heading."""
        if not self.ready:
            uninitialised(self)
        self.pose.t = translation.v

    def resetRotation(self, Rotation2d rotation not None):
        """Set the heading and keep the position. (robotpy-wpimath 2026 has a sign bug
        here that makes the next update report a wrong heading; drivekin does not.)"""
        if not self.ready:
            uninitialised(self)
        self.pose.r = rotation.r


cdef class SwerveDriveOdometry(_Odometry):
    """SwerveDriveOdometry(kinematics, gyroAngle, modulePositions, initialPose=Pose2d())

    Tracks a swerve robot's pose from N module positions (SwerveModulePosition objects or
    an (N, 2) float64 array ``[distance m, angle rad]``) and a gyro angle (Rotation2d).
    """

    def __cinit__(self, *args, **kwargs):
        self.prev = NULL

    def __init__(self, SwerveDriveKinematics kinematics not None, Rotation2d gyroAngle not None,
                 modulePositions, initialPose=None):
        cdef Py_ssize_t i
        self._start_init()
        cdef pose2_t p = initial(initialPose)
        kinematics._read(modulePositions, SwerveModulePosition, "modulePositions")
        self._start_init()      # again: reading an iterable ran Python code
        cdef double* prev = <double*>PyMem_Malloc(sizeof(double) * kinematics.n)
        if prev == NULL:
            raise MemoryError()
        for i in range(kinematics.n):
            prev[i] = kinematics.s0[i]
        self.prev = prev
        self.kin = kinematics
        self.prev_gyro = gyroAngle.r
        self.pose = p
        self.ready = True

    def __dealloc__(self):
        PyMem_Free(self.prev)

    def resetPosition(self, Rotation2d gyroAngle not None, modulePositions, Pose2d pose not None):
        """Reset the pose, the gyro baseline and the module-position baseline."""
        cdef Py_ssize_t i
        if not self.ready:
            uninitialised(self)
        self.kin._read(modulePositions, SwerveModulePosition, "modulePositions")
        for i in range(self.kin.n):
            self.prev[i] = self.kin.s0[i]
        self.prev_gyro = gyroAngle.r
        self.pose = pose.p

    def update(self, Rotation2d gyroAngle not None, modulePositions):
        """Integrate the module-distance changes since the last call (at the current module
        angles) and the gyro change; return the new pose."""
        cdef SwerveDriveKinematics k = self.kin
        cdef Py_ssize_t i
        cdef double d
        cdef double r[3]
        if not self.ready:
            uninitialised(self)
        k._read(modulePositions, SwerveModulePosition, "modulePositions")
        for i in range(k.n):
            d = k.s0[i]
            k.s0[i] = d - self.prev[i]
            self.prev[i] = d
        forward_solve(3, k.n, k.f1, k.s0, k.s1, k.s2, r)
        odometry_step(&self.pose, &self.prev_gyro, r[0], r[1], gyroAngle.r)
        return new_pose(self.pose)


cdef class MecanumDriveOdometry(_Odometry):
    """MecanumDriveOdometry(kinematics, gyroAngle, wheelPositions, initialPose=Pose2d())

    Tracks a mecanum robot's pose from MecanumDriveWheelPositions (m) and a gyro angle.
    """

    def __init__(self, MecanumDriveKinematics kinematics not None, Rotation2d gyroAngle not None,
                 MecanumDriveWheelPositions wheelPositions not None, initialPose=None):
        self._start_init()
        kinematics._ready()
        self.pose = initial(initialPose)
        self.kin = kinematics
        self.prev = (<_WheelValues>wheelPositions).w
        self.prev_gyro = gyroAngle.r
        self.ready = True

    def resetPosition(self, Rotation2d gyroAngle not None,
                      MecanumDriveWheelPositions wheelPositions not None, Pose2d pose not None):
        """Reset the pose, the gyro baseline and the wheel-position baseline."""
        if not self.ready:
            uninitialised(self)
        self.prev = (<_WheelValues>wheelPositions).w
        self.prev_gyro = gyroAngle.r
        self.pose = pose.p

    def update(self, Rotation2d gyroAngle not None,
               MecanumDriveWheelPositions wheelPositions not None):
        """Integrate the wheel-distance changes since the last call and the gyro change;
        return the new pose."""
        cdef double d[4]
        cdef double r[3]
        cdef Py_ssize_t i
        cdef _WheelValues w = wheelPositions
        if not self.ready:
            uninitialised(self)
        for i in range(4):
            d[i] = w.w[i] - self.prev[i]
        self.prev = w.w
        mat_vec(3, 4, self.kin.f, d, r)
        odometry_step(&self.pose, &self.prev_gyro, r[0], r[1], gyroAngle.r)
        return new_pose(self.pose)


cdef class DifferentialDriveOdometry(_Odometry):
    """DifferentialDriveOdometry(gyroAngle, leftDistance, rightDistance, initialPose=Pose2d())

    Tracks a differential-drive robot's pose from the left and right wheel distances (m)
    and a gyro angle. No trackwidth is needed: the heading comes from the gyro.
    """

    def __init__(self, Rotation2d gyroAngle not None, double leftDistance, double rightDistance,
                 initialPose=None):
        self._start_init()
        self.pose = initial(initialPose)
        self.prev_l = leftDistance
        self.prev_r = rightDistance
        self.prev_gyro = gyroAngle.r
        self.ready = True

    def resetPosition(self, Rotation2d gyroAngle not None, double leftDistance,
                      double rightDistance, Pose2d pose not None):
        """Reset the pose, the gyro baseline and the wheel-distance baselines."""
        if not self.ready:
            uninitialised(self)
        self.prev_l = leftDistance
        self.prev_r = rightDistance
        self.prev_gyro = gyroAngle.r
        self.pose = pose.p

    def update(self, Rotation2d gyroAngle not None, double leftDistance, double rightDistance):
        """Integrate the wheel-distance changes since the last call (dx = mean change,
        dy = 0) and the gyro change; return the new pose."""
        if not self.ready:
            uninitialised(self)
        cdef double dl = leftDistance - self.prev_l, dr = rightDistance - self.prev_r
        self.prev_l = leftDistance
        self.prev_r = rightDistance
        odometry_step(&self.pose, &self.prev_gyro, (dl + dr) / 2.0, 0.0, gyroAngle.r)
        return new_pose(self.pose)
