# 3-D odometry (WPILib 2027's Odometry3d): one implementation for every drivetrain, on the
# drivetrain contract's odometry map (Drivetrain._twists). The public classes only read
# their wheel readings into C memory (_read) and keep the kinematics they need. The step's
# pose arithmetic is the inline kernel below, for any other code that must give the same
# bits (a batch replay).
cimport cython
from libc.math cimport sqrt
from drivekin._core.dkmath cimport atan2
from drivekin._core.drivetrain cimport Drivetrain
from drivekin._core.kernels3d cimport pose3, pose3_plus, quat, v3_cross, vec3
from drivekin._core.types cimport pose3_t, quat_t, twist3_t, vec3_t
from drivekin.geometry3d cimport Rotation3d


cdef inline void odometry3d_move(pose3_t* p,                            # IN/OUT
                                 twist3_t* tw,                          # OUT
                                 double dx, double dy, quat_t turn) noexcept nogil:
    # pose ← pose + Twist3d(dx, dy, 0, ρ).exp(), ρ = turn.toRotationVector() (the short
    # way, |ρ| <= π; turn is the gyro's unit change quaternion): WPILib's Odometry3d step.
    # exp's rotation is ±turn itself, and its half angle's (sin, cos) are turn's (‖v‖, |w|),
    # so only θ = 2·atan2(‖v‖, |w|) takes trigonometry; the translation V·u, u = (dx, dy, 0),
    # is twist3_exp's cancellation-free form. The twist is kept: the estimators' sampleAt
    # interpolates along it.
    cdef quat_t q = turn if turn.w >= 0.0 else quat(-turn.w, -turn.x, -turn.y, -turn.z)
    cdef double vn = sqrt(q.x * q.x + q.y * q.y + q.z * q.z)
    cdef double k, half, t2, b, c, inv
    cdef vec3_t a, c1, c2
    if vn < 1e-9:
        k = 2.0 / q.w - 2.0 / 3.0 * vn * vn / (q.w * q.w * q.w)   # toRotationVector's series
        half = 0.0
    else:
        half = atan2(vn, q.w)                              # θ/2
        inv = 1.0 / vn
        k = 2.0 * half * inv                               # θ/‖v‖
    tw.dx = dx
    tw.dy = dy
    tw.dz = 0.0
    tw.rx = k * q.x
    tw.ry = k * q.y
    tw.rz = k * q.z
    if half < 0.5e-3:
        t2 = k * vn
        t2 = t2 * t2                                       # θ²
        b = 0.5 - t2 / 24.0 + t2 * t2 / 720.0              # B
        c = 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0      # C
        a = vec3(tw.rx, tw.ry, tw.rz)
    else:
        b = vn * vn / half                                 # Bθ = 2 sin²(θ/2)/θ
        c = 1.0 - vn * q.w / half                          # Cθ² = 1 − sin θ/θ
        a = vec3(q.x * inv, q.y * inv, q.z * inv)          # the unit axis
    c1 = v3_cross(a, vec3(dx, dy, 0.0))
    c2 = v3_cross(a, c1)
    p[0] = pose3_plus(p[0], pose3(vec3(dx + b * c1.x + c * c2.x, dy + b * c1.y + c * c2.y,
                                       b * c1.z + c * c2.z), q))


cdef class _Odometry3d:
    cdef Drivetrain kin          # the drivetrain's odometry map
    cdef double* prev            # wheel (module) distances at the last update or reset, m
    cdef double scratch[4]       # the current readings, for drivetrains without a scratch
    cdef Py_ssize_t width        # readings per sample
    cdef bint yaw                # the map takes the gyro's yaw change (dead wheels)
    cdef pose3_t pose            # current pose estimate (field frame, m)
    cdef quat_t prev_gyro        # gyro reading at the last update or reset
    cdef twist3_t twist          # the last update's twist, in the previous pose's frame
    cdef bint ready              # set by a completed __init__; nothing computes before

    cdef int _begin(self, Drivetrain kin, Py_ssize_t width, bint yaw, object gyro_angle,
                    object a, object b, object initial_pose) except -1
    # Read one sample of readings (the public classes' one or two arguments) into C memory:
    # ``cur`` the distances (m, writable: they become the changes), ``c``/``s`` the module
    # directions of a steered drivetrain (else NULL). Raises without changing anything.
    # The base reads two numbers (the differential drive's and the two dead wheels').
    cdef int _read(self, object a, object b, double** cur, const double** c,
                   const double** s) except -1
    # update without building the returned Pose3d (the estimators call it).
    @cython.final
    cdef int _step(self, Rotation3d gyro_angle, object a, object b) except -1
    @cython.final
    cdef int _reset(self, object gyro_angle, object a, object b, object pose) except -1
    @cython.final
    cdef void _move(self, quat_t gyro, double* cur, const double* c,
                    const double* s) noexcept nogil


@cython.final
cdef class SwerveDriveOdometry3d(_Odometry3d):
    pass

@cython.final
cdef class MecanumDriveOdometry3d(_Odometry3d):
    pass

@cython.final
cdef class DifferentialDriveOdometry3d(_Odometry3d):
    pass

@cython.final
cdef class DeadWheelOdometry3d(_Odometry3d):
    pass

@cython.final
cdef class TwoDeadWheelOdometry3d(_Odometry3d):
    cdef double x_wheel_y        # x_wheel_y_pos: y of the forward-facing wheel, m
    cdef double y_wheel_x        # y_wheel_x_pos: x of the left-facing wheel, m
