# PathPlannerLib's swerve setpoint generator: the robot description it needs, the setpoint
# it produces, and the generator, whose kernel (generate) the batch module shares.
cimport cython
from drivekin._core.types cimport vec3_t
from drivekin.chassis cimport ChassisVelocities
from drivekin.motor cimport DCMotor
from drivekin.swerve cimport SwerveDriveKinematics


@cython.final
cdef class ModuleConfig:
    cdef double radius           # wheel radius, m
    cdef double vmax             # top drive speed, m/s
    cdef double cof              # wheel coefficient of friction
    cdef double current_limit    # A, for the module's numMotors motors
    cdef double torque_loss      # N·m the module loses to friction at top speed
    cdef long long num_motors
    cdef DCMotor motor           # the drive gearbox, reduction included
    cdef bint frozen


@cython.final
cdef class RobotConfig:
    cdef double mass             # kg
    cdef double moi              # kg·m²
    cdef ModuleConfig module
    cdef tuple locations         # Translation2d per module, robot frame
    cdef tuple pivots            # |location| per module, m (floats)
    cdef bint frozen


@cython.final
cdef class DriveFeedforwards:
    cdef Py_ssize_t n
    cdef double* d               # 5 rows of n: acceleration, force, current, force x, force y
    cdef tuple _row(self, int k)


@cython.final
cdef class PathConstraints:
    cdef double max_v, max_a, max_w, max_alpha, nominal
    cdef bint is_unlimited
    cdef bint frozen


@cython.final
cdef class SwerveSetpoint:
    cdef ChassisVelocities v
    cdef tuple modules           # SwerveModuleVelocity objects this setpoint owns
    cdef DriveFeedforwards ff
    cdef int _ready(self) except -1


# Limits from PathConstraints, read into C before the kernel runs.
cdef struct limits_t:
    double max_v, max_a, max_w, max_alpha


# Everything the kernel reads: constants of the robot, per-module constants, heading
# memory and scratch (all arrays n long, in one allocation).
cdef struct generator_t:
    Py_ssize_t n
    bint compat                  # PathPlannerLib's arithmetic (no min_s factor, discretize last)
    double mass, moi, radius, vmax, friction_force, max_torque_friction
    double current_limit, torque_loss, kv, r, kt
    double max_steer, brownout
    const double* mx             # module positions (the kinematics object's), m
    const double* my
    const double* f1             # 3 x 2n forward-kinematics pseudo-inverse
    double* hc                   # heading memory (the kinematics object's)
    double* hs
    double* pd                   # pivot distance |r_i|, m
    double* lc                   # direction of r_i
    double* ls
    double* kx                   # force kinematics: wheel force = F/n + (kx, ky)·τ/n
    double* ky
    double* scratch              # 20 arrays of n


cdef void generate(generator_t* g, const double* prev, vec3_t desired, double dt,
                   double voltage, const limits_t* lim, double* out) noexcept nogil


@cython.final
cdef class SwerveSetpointGenerator:
    cdef RobotConfig cfg
    cdef SwerveDriveKinematics kin
    cdef generator_t g
    cdef double* buf             # per-module constants, scratch, prev and out
    cdef double* prev            # 3 + 3n: chassis, speeds, cos, sin
    cdef double* out             # 3 + 8n: chassis, speeds, cos, sin, 5 feedforward rows
    cdef object compat_name      # None or "pathplanner"

    cdef int _load(self, object prevSetpoint, object constraints, limits_t* lim) except -1


cdef int check_step(vec3_t want, double dt, double voltage, str where) except -1
