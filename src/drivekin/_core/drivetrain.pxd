# The drivetrain contract: what the code that loops over drivetrains needs from a
# kinematics class, on C memory. drivekin.batch's kinematics functions are written once
# against it, and so is odometry: drivekin.odometry's one 2-D implementation (and
# drivekin.odometry3d's 3-D one) turns wheel readings into motion with _twists only.
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
    # The odometry map: the robot's motion over k samples of wheel-position changes, each
    # the Twist2d of WPILib's toTwist2d (dx, dy in m in the frame of the pose the sample
    # starts from; dθ in rad, counter-clockwise).
    # d: the changes since the previous reading (m), wheel-major: wheel (or module) j of
    #    sample i at d[k·j + i]; steered: c, s the cos and sin of each module's angle in
    #    the same layout (the current reading's angle, as WPILib), otherwise NULL. The
    #    CALLER owns every buffer and the previous readings: it forms the changes
    #    (position_changes below), so the map itself keeps no state.
    # dth: NULL, or the k heading changes the caller knows (a gyro's, rad). Given, only
    #    (dx, dy) are computed, for that heading change: dead wheels fit them to the
    #    readings less the arcs the turn swept each wheel through (so 3-D odometry passes
    #    its yaw change); swerve, mecanum and differential ignore it (their (dx, dy) do not
    #    depend on dθ; odometry replaces their dθ by the gyro's, as WPILib does). NULL:
    #    dθ comes from the wheels too; call _forward_check(False, False) first (dead
    #    wheels that cannot observe rotation refuse).
    # out: 3k values: dx at out[i], dy at out[k + i], and with dth NULL dθ at out[2k + i]
    #    (with dth given, out[2k:] is not written). It must not overlap d, c, s or dth.
    # Reads only what is fixed at construction (the forward matrices), so it needs no
    # params copy and runs without the GIL; call _ready() first.
    cdef void _twists(self, Py_ssize_t k, const double* d, const double* c, const double* s,
                      const double* dth, double* out) noexcept nogil   # OUT
    # _twists of one sample (k = 1: out is dx, dy[, dθ]), for an update. The base calls
    # _twists; a drivetrain overrides it with the same arithmetic specialised for one
    # sample, since a per-call update pays for every instruction.
    cdef void _twist(self, const double* d, const double* c, const double* s,
                     const double* dth, double* out) noexcept nogil   # OUT


cdef inline void position_changes(Py_ssize_t n, double* cur,                    # IN/OUT
                                  double* prev) noexcept nogil:                 # IN/OUT
    # One sample's n readings (m) into the changes since prev, which becomes the readings:
    # what _twist takes, cur[j] ← cur[j] − prev[j], prev[j] ← the old cur[j].
    cdef Py_ssize_t j
    cdef double r
    for j in range(n):
        r = cur[j]
        cur[j] = r - prev[j]
        prev[j] = r
