# The swerve setpoint generator's kernel and the C state it runs on, shared by
# drivekin.setpoint (the per-call methods) and drivekin.batch (generateSetpoints).
from drivekin._core.types cimport vec3_t

cdef enum:
    SCRATCH = 20                 # arrays of n in generator_t.scratch
    CONSTANTS = 5                # pd, lc, ls, kx, ky
    SAVED = 2                    # arrays of n in SetpointKernel.saved


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
    double* scratch              # SCRATCH arrays of n


cdef void generate(generator_t* g, const double* prev, vec3_t desired, double dt,
                   double voltage, const limits_t* lim, double* out) noexcept nogil

# sample ≥ 0: the batch form's sample, named in the messages; -1 for the per-call form.
cdef int check_step(vec3_t want, double dt, double voltage, Py_ssize_t sample) except -1


# The generator's C state; drivekin.setpoint.SwerveSetpointGenerator derives from it and
# fills it. _load reads the previous setpoint into prev and the constraints into lim
# (returning 1 when there are constraints); the base class refuses.
cdef class SetpointKernel:
    cdef generator_t g
    cdef double* buf             # per-module constants, scratch, prev and out
    cdef double* prev            # 3 + 3n: chassis, speeds, cos, sin
    cdef double* out             # 3 + 8n: chassis, speeds, cos, sin, 5 feedforward rows
    cdef double* saved           # 2n: the heading memory before the call (keep_headings)

    cdef int _load(self, object prevSetpoint, object constraints, limits_t* lim) except -1


# Around generate: keep_headings before the call (or the batch), check_output after each
# step; an output that is not finite restores the kept heading memory and raises.
cdef void keep_headings(SetpointKernel k) noexcept
cdef int check_output(SetpointKernel k, Py_ssize_t sample) except -1
