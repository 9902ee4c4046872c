"""Dead-wheel (tracking-wheel) kinematics: any number of unpowered wheels at any poses.

Units: m, m/s, m/s², rad, rad/s, rad/s². Robot frame: x forward, y left, CCW positive.

A dead wheel touching the floor at (x, y) and rolling along φ reads the robot's velocity
at that point projected on its rolling direction:

    d = cos φ·(dx − y·dθ) + sin φ·(dy + x·dθ)

Stacking the wheels gives d = M·t with t = (dx, dy, dθ). Without a gyro the wheels must
observe all three components and t is the least-squares solution M⁺·d (exact for three
wheels). With a gyro, dθ is taken from it and only (dx, dy) is fitted, which two
non-parallel wheels always observe. Redundant wheels are averaged in by the least-squares
fit, never ignored. Both pseudo-inverses are built once, at construction (drivekin's own,
the same bits on every platform).
"""
cimport cython
from drivekin._core.drivetrain cimport Drivetrain
cimport numpy as cnp
from cpython.mem cimport PyMem_Free, PyMem_Malloc
from cpython.ref cimport Py_INCREF
from cpython.float cimport PyFloat_FromDouble
from cpython.tuple cimport PyTuple_New, PyTuple_SET_ITEM
from libc.math cimport M_PI, fabs, isfinite
from drivekin._core.dkmath cimport atan2, hypot

import numpy as np

from drivekin._core.kernels cimport deadwheel_reading, deadwheel_solve, mat_vec_step
from drivekin._core.args cimport check_type, read_floats, vector_data
from drivekin.geometry cimport Pose2d, Rotation2d, Translation2d, new_twist
from drivekin._core.args cimport snapshot
from drivekin.chassis cimport (ChassisAccelerations, ChassisVelocities, _ChassisVector,
                               new_chassis_velocities)
from drivekin._core.drivetrain import pseudo_inverse
from drivekin._core.errors import type_name

cnp.import_array()

# Singular values below this fraction of the largest (columns scaled to unit length)
# count as zero: such a layout would turn encoder noise into errors ~1e8 times larger.
cdef double RANK_TOL = 1e-8
cdef double IN_TO_M = 0.0254


cdef inline double gyro_number(object value, str call) except? -1.0:
    # Converted before any wheel value is read into scratch memory: __float__ of a
    # user object is Python code, which must not run between reading and solving.
    try:
        return value
    except TypeError:
        raise TypeError(f"{call}: the gyro argument must be a number or None, got "
                        f"{type_name(value)}") from None


cdef str parallel_message(double c, double s):
    cdef double deg = atan2(s, c) * 180.0 / M_PI
    if fabs(s) < 1e-9:
        what = "they all roll along x, so lateral (y) motion"
    elif fabs(c) < 1e-9:
        what = "they all roll along y, so forward (x) motion"
    else:
        what = (f"they all roll along {deg:.6g}°, so motion along {deg + 90.0:.6g}° "
                "(robot frame)")
    return f"all wheels are parallel: {what} cannot be observed, even with a gyro"


cdef inline void readings(Py_ssize_t w, const double* rows, const double* x,
                          double* y) noexcept nogil:
    # The w wheels' readings for one chassis vector x.
    cdef Py_ssize_t j
    for j in range(w):
        y[j] = deadwheel_reading(rows + 3 * j, x[0], x[1], x[2])


cdef inline void twists(DeadWheelKinematics kin, Py_ssize_t k, const double* d,
                        const double* dth, double* out) noexcept nogil:
    # The drivetrain contract's _twists: deadwheel_solve for each sample.
    cdef Py_ssize_t i
    cdef double r[3]
    for i in range(k):
        deadwheel_solve(kin.n, kin.p3, kin.p2, kin.g, d + i, k, dth != NULL,
                        dth[i] if dth != NULL else 0.0, r)
        out[i] = r[0]
        out[k + i] = r[1]
        if dth == NULL:
            out[2 * k + i] = r[2]


cdef class DeadWheelKinematics(Drivetrain):
    """DeadWheelKinematics(wheel_poses)

    Kinematics of N ≥ 2 dead (tracking) wheels. Each wheel is a Pose2d in the robot
    frame: its translation is the contact point (m), its rotation the direction in which
    the wheel's reading grows (0 for a wheel that reads forward motion, +90° for one that
    reads leftward motion). Wheel values are passed everywhere as a list or tuple of
    floats, or a 1-D float64 array, in the order of ``wheel_poses``.

    The layout must observe (dx, dy) — at least two non-parallel wheels — or ValueError
    names the direction it cannot see. Without a gyro it must also observe rotation (at
    least three wheels whose lines do not all meet in one point); a layout that cannot
    is valid, but every call must then pass the gyro (see :meth:`requiresGyro`).
    """

    def __cinit__(self, *args, **kwargs):
        self.buf = NULL

    cdef int _refuse_reinit(self) except -1:
        if self.buf != NULL:
            raise TypeError("DeadWheelKinematics is already initialised: __init__ cannot "
                            "be called again")
        return 0

    def __init__(self, wheel_poses):
        self._refuse_reinit()
        poses = snapshot(wheel_poses, "DeadWheelKinematics() takes a sequence of Pose2d "
                                     "wheel poses; wheel_poses")
        cdef Py_ssize_t n = len(poses), i, k
        if n < 2:
            raise ValueError(f"dead-wheel kinematics needs at least 2 wheels, got {n}")
        for i, p in enumerate(poses):
            if type(p) is not Pose2d:
                raise TypeError(f"wheel {i} must be a drivekin Pose2d (contact point in m, "
                                f"rolling direction), got {type_name(p)}")
            if not (isfinite((<Pose2d>p).p.t.x) and isfinite((<Pose2d>p).p.t.y)
                    and isfinite((<Pose2d>p).p.r.c) and isfinite((<Pose2d>p).p.r.s)):
                raise ValueError(f"wheel {i} pose must be finite, got {p!r}")
        rows = np.empty((n, 3))
        for i, p in enumerate(poses):
            c, s = (<Pose2d>p).p.r.c, (<Pose2d>p).p.r.s
            rows[i] = (c, s, (<Pose2d>p).p.t.x * s - (<Pose2d>p).p.t.y * c)
        a = rows[:, :2]
        sv = np.linalg.svd(a, compute_uv=False)
        if not sv[1] > RANK_TOL * sv[0]:
            raise ValueError(parallel_message(rows[0, 0], rows[0, 1]))
        cdef double[:, ::1] mr = rows
        cdef double[:, ::1] m2 = pseudo_inverse(a)
        cdef double shift[2]
        # A⁺c, summed in wheel order as the solve sums (numpy's @ may call a BLAS whose
        # order and fused multiply-adds depend on the build).
        mat_vec_step(2, n, &m2[0, 0], &mr[0, 2], 3, shift)
        g = (shift[0], shift[1])
        # Rank of M with the lever arms measured in units of the layout's size, so that
        # neither the choice of metres nor a small robot decides observability. Lever arms
        # that vanish on that scale (every wheel line through one point) leave rotation
        # about that point unobservable.
        size = max(hypot((<Pose2d>p).p.t.x, (<Pose2d>p).p.t.y) for p in poses)
        scaled = rows.copy()
        if size > 0.0:
            scaled[:, 2] /= size
        sv = np.linalg.svd(scaled, compute_uv=False)
        heading = n >= 3 and sv[2] > RANK_TOL * sv[0]
        if heading:
            p3 = pseudo_inverse(rows)
            why = None
        else:
            p3 = np.zeros((3, n))
            # The invisible rotation's centre, (g1, −g0); round-off below the layout's
            # scale is printed as 0.
            px, py = (0.0 if abs(v) <= 1e-12 * size else float(v) for v in (g[1], -g[0]))
            why = (f"{n} wheels cannot observe rotation" if n < 3 else
                   f"every wheel's line passes through ({px:.6g}, {py:.6g}) m, so a "
                   "rotation about that point cannot be observed")
        cdef double[:, ::1] m3 = p3
        # Reading a generic iterable ran Python code, which may have initialised this
        # object meanwhile; committing now would leak and replace that state.
        self._refuse_reinit()
        cdef double* buf = <double*>PyMem_Malloc(sizeof(double) * 9 * n)
        if buf == NULL:
            raise MemoryError()
        self.n = n
        self.nwheels = n
        self.gyro_forward = True
        self.m = buf
        self.p3 = buf + 3 * n
        self.p2 = buf + 6 * n
        self.s = buf + 8 * n
        for i in range(n):
            for k in range(3):
                self.m[3 * i + k] = mr[i, k]
                self.p3[k * n + i] = m3[k, i]
            for k in range(2):
                self.p2[k * n + i] = m2[k, i]
        self.g[0] = g[0]
        self.g[1] = g[1]
        self.heading = heading
        self.no_heading = why
        self.poses = poses
        # Set last: a non-NULL buf is what every method checks before computing.
        self.buf = buf

    def __dealloc__(self):
        PyMem_Free(self.buf)

    cdef int _ready(self) except -1:
        if self.buf == NULL:
            raise RuntimeError("DeadWheelKinematics.__init__ has not completed")
        return 0

    # -----------------------------------------------------------------------------------
    # The drivetrain contract (drivekin._core.drivetrain): W wheels, a gyro optional

    cdef int _forward_check(self, bint gyro, bint accel) except -1:
        if not gyro and not self.heading:
            self._need_heading("toChassisAccelerations" if accel else "toChassisVelocities")
        return 0

    cdef Py_ssize_t _params(self, double* params, bint forward, bint accel) noexcept:
        # Inverse: the model rows; forward: both pseudo-inverses and the heading shift.
        cdef Py_ssize_t j, n = self.n
        if params == NULL:
            return 5 * n + 2 if forward else 3 * n
        if not forward:
            for j in range(3 * n):
                params[j] = self.m[j]
            return 3 * n
        for j in range(3 * n):
            params[j] = self.p3[j]
        for j in range(2 * n):
            params[3 * n + j] = self.p2[j]
        params[5 * n] = self.g[0]
        params[5 * n + 1] = self.g[1]
        return 5 * n + 2

    cdef void _inverse_many(self, Py_ssize_t k, const double* chassis, const double* omega,
                            bint accel, double* params,
                            double* m, double* c, double* s) noexcept nogil:
        cdef Py_ssize_t i, w = self.n
        if w == 3:
            # The common three-wheel layout with a literal size, which the compiler unrolls
            # (as in the forward direction).
            for i in range(k):
                readings(3, params, chassis + 3 * i, m + 3 * i)
        else:
            for i in range(k):
                readings(w, params, chassis + 3 * i, m + w * i)

    cdef void _forward_many(self, Py_ssize_t k, const double* m, const double* c,
                            const double* s, const double* gyro, bint accel,
                            const double* params, double* out) noexcept nogil:
        cdef Py_ssize_t i, n = self.n
        if n == 3 and gyro == NULL:
            # The common three-wheel layout with a literal size: the same kernel, unrolled
            # by the compiler (same operations in the same order, so the same bits).
            for i in range(k):
                deadwheel_solve(3, params, params + 9, params + 15, m + 3 * i, 1, False, 0.0,
                                out + 3 * i)
        else:
            for i in range(k):
                deadwheel_solve(n, params, params + 3 * n, params + 5 * n, m + n * i, 1,
                                gyro != NULL, gyro[i] if gyro != NULL else 0.0, out + 3 * i)

    cdef void _twists(self, Py_ssize_t k, const double* d, const double* c, const double* s,
                      const double* dth, double* out) noexcept nogil:
        twists(self, k, d, dth, out)

    cdef void _twist(self, const double* d, const double* c, const double* s,
                     const double* dth, double* out) noexcept nogil:
        twists(self, 1, d, dth, out)

    cdef int _need_heading(self, str call) except -1:
        raise ValueError(f"{call} needs a gyro with this layout: {self.no_heading}")

    cdef int _read(self, object values, double* out, str what) except -1:
        """Copy the n wheel values into ``out`` (C memory), running no Python code."""
        return read_floats(values, self.n, out, what, "wheel values (one per wheel)")

    cdef int _forward(self, object values, object gyro, str what, str call,
                      double* out) except -1:
        # The gyro argument first (converting it may run Python code), then the wheels
        # into scratch, then the solve: nothing runs between reading and solving.
        cdef double w = 0.0
        self._ready()
        if gyro is not None:
            w = gyro_number(gyro, call)
        elif not self.heading:
            self._need_heading(call)
        self._read(values, self.s, what)
        deadwheel_solve(self.n, self.p3, self.p2, self.g, self.s, 1, gyro is not None, w, out)
        return 0

    cdef tuple _inverse(self, _ChassisVector v):
        # Each reading is computed as its float is created, from values copied into C
        # locals first, so an allocation that runs a finalizer cannot change the result.
        cdef double x = v.v.x, y = v.v.y, z = v.v.z
        cdef tuple t = PyTuple_New(self.n)
        cdef Py_ssize_t i
        cdef object f
        for i in range(self.n):
            f = PyFloat_FromDouble(deadwheel_reading(self.m + 3 * i, x, y, z))
            Py_INCREF(f)
            PyTuple_SET_ITEM(t, i, f)
        return t

    cdef int _inverse_into(self, _ChassisVector v, object out, str what) except -1:
        cdef Py_ssize_t i, stride
        if not cnp.PyArray_Check(out):
            raise TypeError(f"{what} must be a float64 numpy array of shape ({self.n},), "
                            f"got {type_name(out)}")
        cdef char* o = vector_data(out, self.n, True, what, &stride)
        cdef double x = v.v.x, y = v.v.y, z = v.v.z
        for i in range(self.n):
            (<double*>(o + i * stride))[0] = deadwheel_reading(self.m + 3 * i, x, y, z)
        return 0

    # -- construction from Road Runner 1.0's tuned parameters ---------------------------

    @staticmethod
    def fromRoadRunner(double par0_y_ticks, double par1_y_ticks, double perp_x_ticks,
                       double in_per_tick):
        """Three wheels from Road Runner 1.0's ``ThreeDeadWheelLocalizer`` parameters
        (paste the tuned numbers as they are): the two parallel wheels' ``par_y_ticks`` and
        the perpendicular wheel's ``perp_x_ticks`` (ticks), and ``in_per_tick`` (inches per
        tick). Wheels are in the order (par0, par1, perp).

        Road Runner's model is par = dx + par_y_ticks·dθ, so ``par_y_ticks`` is the *negative*
        of the wheel's physical y (its tuner reports a left wheel as negative); this
        factory applies that sign. Feed readings in metres: ticks × in_per_tick × 0.0254.
        The twist is then Road Runner's, with dx and dy in metres instead of inches."""
        cdef double k = in_per_tick * IN_TO_M
        _check_ticks(in_per_tick, par0_y_ticks=par0_y_ticks, par1_y_ticks=par1_y_ticks,
                     perp_x_ticks=perp_x_ticks)
        return DeadWheelKinematics((Pose2d(0.0, -par0_y_ticks * k, Rotation2d()),
                                    Pose2d(0.0, -par1_y_ticks * k, Rotation2d()),
                                    Pose2d(perp_x_ticks * k, 0.0, Rotation2d(0.0, 1.0))))

    @staticmethod
    def fromRoadRunnerTwoWheel(double par_y_ticks, double perp_x_ticks, double in_per_tick):
        """Two wheels (par, perp) from Road Runner 1.0's ``TwoDeadWheelLocalizer``
        parameters (ticks, and inches per tick), used with the IMU as the gyro. Same
        sign convention and units as :meth:`fromRoadRunner`."""
        cdef double k = in_per_tick * IN_TO_M
        _check_ticks(in_per_tick, par_y_ticks=par_y_ticks, perp_x_ticks=perp_x_ticks)
        return DeadWheelKinematics((Pose2d(0.0, -par_y_ticks * k, Rotation2d()),
                                    Pose2d(perp_x_ticks * k, 0.0, Rotation2d(0.0, 1.0))))

    # -- queries --------------------------------------------------------------------------

    def getWheelPoses(self):
        """Return the wheel poses (tuple of Pose2d, robot frame, m), constructor order."""
        self._ready()
        return self.poses

    def requiresGyro(self):
        """True if the wheels alone cannot observe rotation (fewer than three wheels, or
        all wheel lines meeting in one point): every call must then pass the gyro."""
        self._ready()
        return not self.heading

    def __reduce__(self):
        self._ready()
        return (DeadWheelKinematics, (self.poses,))

    def __repr__(self):
        if self.buf == NULL:
            return "<uninitialised DeadWheelKinematics>"
        return f"DeadWheelKinematics({list(self.poses)!r})"

    # -- forward and inverse maps ------------------------------------------------------

    def toChassisVelocities(self, wheel_velocities, gyro_rate=None):
        """Return the robot velocity (m/s, m/s, rad/s) from the wheels' surface velocities
        (m/s). With ``gyro_rate`` (rad/s) omega is the gyro's and (vx, vy) the wheels'
        least-squares fit; without, all three come from the wheels."""
        cdef double r[3]
        self._forward(wheel_velocities, gyro_rate, "wheel_velocities", "toChassisVelocities",
                      r)
        return new_chassis_velocities(r[0], r[1], r[2])

    def toChassisVelocitiesInto(self, wheel_velocities, out: ChassisVelocities,
                                gyro_rate=None):
        """Allocation-free :meth:`toChassisVelocities`: write into ``out``. Returns None."""
        cdef double r[3]
        check_type(out, ChassisVelocities, "out")
        self._forward(wheel_velocities, gyro_rate, "wheel_velocities",
                      "toChassisVelocitiesInto", r)
        (<ChassisVelocities>out).v.x = r[0]
        (<ChassisVelocities>out).v.y = r[1]
        (<ChassisVelocities>out).v.z = r[2]

    def toWheelVelocities(self, chassis_velocities: ChassisVelocities):
        """Return each wheel's surface velocity (tuple of floats, m/s) for a robot
        velocity."""
        check_type(chassis_velocities, ChassisVelocities, "chassis_velocities")
        self._ready()
        return self._inverse(<ChassisVelocities>chassis_velocities)

    def toWheelVelocitiesInto(self, chassis_velocities: ChassisVelocities, out):
        """Allocation-free :meth:`toWheelVelocities`: write into ``out``, a writeable
        float64 array of shape (N,) (any stride). Returns None."""
        check_type(chassis_velocities, ChassisVelocities, "chassis_velocities")
        self._ready()
        self._inverse_into(<ChassisVelocities>chassis_velocities, out, "out")

    def toTwist2d(self, wheel_deltas, gyro_delta=None):
        """Return the Twist2d (m, rad) for the wheel distance changes (m). With
        ``gyro_delta`` (rad, the heading change; wrap it to (−π, π] yourself) dθ is the
        gyro's and (dx, dy) the wheels' least-squares fit."""
        cdef double r[3]
        self._forward(wheel_deltas, gyro_delta, "wheel_deltas", "toTwist2d", r)
        return new_twist(r[0], r[1], r[2])

    def toChassisAccelerations(self, wheel_accelerations, angular_acceleration=None):
        """Return the robot acceleration (m/s², m/s², rad/s²) from the wheels' surface
        accelerations (m/s²): the velocity map applied to accelerations (no centripetal
        term). With ``angular_acceleration`` (rad/s²) alpha is fixed to it."""
        cdef double r[3]
        self._forward(wheel_accelerations, angular_acceleration, "wheel_accelerations",
                      "toChassisAccelerations", r)
        return ChassisAccelerations(r[0], r[1], r[2])

    def toWheelAccelerations(self, chassis_accelerations: ChassisAccelerations):
        """Return each wheel's surface acceleration (tuple of floats, m/s²)."""
        check_type(chassis_accelerations, ChassisAccelerations, "chassis_accelerations")
        self._ready()
        return self._inverse(<ChassisAccelerations>chassis_accelerations)


def _check_ticks(double in_per_tick, **ticks):
    if not (isfinite(in_per_tick) and in_per_tick > 0.0):
        raise ValueError(f"in_per_tick must be a positive finite number of inches per tick, "
                         f"got {in_per_tick!r}")
    for name, value in ticks.items():
        if not isfinite(value):
            raise ValueError(f"{name} must be finite (ticks), got {value!r}")
