# The drivetrain contract: what the code that loops over drivetrains needs from a
# kinematics class, on C memory. drivekin.batch's kinematics functions are written once
# against it; the odometry classes' step uses their own kinematics directly (see
# drivekin.odometry for the odometry half of the contract, _Odometry._motions).
#
# A wheel sample is what the class's forward map reads and its inverse map writes: W
# values (mecanum 4, differential 2 [left, right], dead wheels W), or for a steered
# drivetrain (swerve) W modules of [magnitude, angle rad]. For steered drivetrains the
# caller turns the angles into cos/sin (and back): that is the trigonometry of a batch,
# which drivekin.batch does with its array kernels (libmvec in the SIMD build).
#
# The batch methods work on k samples at a time with the GIL released, on a private copy
# of the parameters they read (``params``: another thread's per-call method may change
# the object's own caches, such as the swerve heading memory or a centre of rotation,
# while a batch runs). Dispatch costs one indirect call per chunk of samples.

from drivekin._core.types cimport vec2_t


cdef class Drivetrain:
    cdef Py_ssize_t nwheels      # W: wheel values or modules per sample
    cdef bint steered            # a sample is (W, 2) [magnitude, angle rad]; else (W,)
    cdef bint gyro_forward       # the forward map may take the heading rate per sample
    cdef bint centered           # the inverse maps take a centre of rotation

    cdef int _ready(self) except -1
    # Use ``center_of_rotation`` (a Translation2d or None) for the inverse maps that follow,
    # or refuse it (TypeError) if the drivetrain has none; _set_cor moves the rows.
    cdef int _center(self, object center_of_rotation) except -1
    cdef void _set_cor(self, vec2_t cor) noexcept
    # Refuse a forward map the layout cannot do (dead wheels that do not observe the
    # heading change, without a gyro).
    cdef int _forward_check(self, bint gyro, bint accel) except -1
    # After the inverse map: keep what it changed in ``params`` (the heading memory).
    cdef void _inverse_done(self, const double* params, bint accel) noexcept
    # Copy the parameters of the inverse (forward False) or forward map into ``params``
    # and return their count; with params NULL, only return the count.
    cdef Py_ssize_t _params(self, double* params, bint forward, bint accel) noexcept
    # Inverse map of k chassis rows (vx, vy, omega; or ax, ay, alpha with ``omega[i]`` the
    # angular velocity, steered accelerations only) into k wheel samples: m[W·i + j]
    # (and, steered, the module direction c, s).
    cdef void _inverse_many(self, Py_ssize_t k, const double* chassis, const double* omega,
                            bint accel, double* params,
                            double* m, double* c, double* s) noexcept nogil   # OUT m, c, s
    # Forward map of k wheel samples (m, and steered c, s; ``gyro[i]`` the heading rate,
    # or NULL) into k chassis rows.
    cdef void _forward_many(self, Py_ssize_t k, const double* m, const double* c,
                            const double* s, const double* gyro, bint accel,
                            const double* params, double* out) noexcept nogil   # OUT
