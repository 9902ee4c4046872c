# Differential swerve module: two motors drive one pod through a differential. Their sum
# turns the pod, their difference spins the wheel:
#     R_A·ω_pod = ω_m1 + ω_m2,    R_L·ω_wheel = ω_m1 − ω_m2,    ω_wheel = v / r
# (R = motor turns per output turn). A reversed motor 2 reads and takes −ω_m2.
# The kernels below work on C doubles only; the classes hold their state by value.
cimport cython
from libc.math cimport fabs
from drivekin._kernels cimport jmax
from drivekin._types cimport rot2_t
from drivekin._wheels cimport _WheelValues


cdef struct dswerve_t:
    double ra                    # azimuth gear ratio R_A, motor turns per pod turn
    double rl                    # wheel gear ratio R_L, motor turns per wheel turn
    double r                     # wheel radius, m
    double kv                    # R_L / r: motor rad per m of wheel travel
    double s2                    # +1, or -1 when motor 2 is mounted reversed
    double ira                   # 1 / R_A, for the inverse map
    double ikv                   # 1 / kv, m of wheel travel per motor rad


# ---------------------------------------------------------------------------------------
# Kernels (no Python objects; OUT parameters last)

cdef inline void dswerve_motors(const dswerve_t* g, double v, double w,
                                double* m1, double* m2       # OUT, rad/s as the motors read
                                ) noexcept nogil:
    # Halves taken before the sum so that large finite inputs cannot overflow in between.
    cdef double a = 0.5 * g.ra * w, b = 0.5 * g.kv * v
    m1[0] = a + b
    m2[0] = g.s2 * (a - b)

cdef inline void dswerve_module(const dswerve_t* g, double m1, double m2,
                                double* v, double* w         # OUT, m/s and rad/s
                                ) noexcept nogil:
    cdef double w2 = g.s2 * m2
    w[0] = (m1 + w2) * g.ira
    v[0] = (m1 - w2) * g.ikv

cdef inline double clamp_abs(double x, double limit) noexcept nogil:
    # Rounding in a + (limit − |a|) can land one ulp past the limit; this puts it back.
    if x > limit:
        return limit
    if x < -limit:
        return -limit
    return x

cdef inline void dswerve_desaturate(double s2, double m1, double m2, double limit,
                                    bint proportional,
                                    double* o1, double* o2   # OUT (may alias the inputs)
                                    ) noexcept nogil:
    # Java Math.max: a NaN motor makes peak NaN and the comparison false, so the pair
    # passes unchanged (as a NaN wheel speed does in WPILib's desaturation).
    cdef double peak = jmax(fabs(m1), fabs(m2))
    cdef double a, b, w2
    if not peak > limit:
        o1[0] = m1
        o2[0] = m2
        return
    if proportional:
        # WPILib's order of operations (m / peak * limit): the fastest lands on the limit.
        o1[0] = m1 / peak * limit
        o2[0] = m2 / peak * limit
        return
    # Steering part a (the pod's rate) and wheel part b: ω1 = a + b, ω2 = a − b, so the
    # fastest motor is |a| + |b|. Shrink b first; only a steering part beyond the limit
    # by itself is cut (and then the wheel stops).
    w2 = s2 * m2
    a = 0.5 * m1 + 0.5 * w2
    b = 0.5 * m1 - 0.5 * w2
    if fabs(a) >= limit:
        a = limit if a > 0.0 else -limit
        b = 0.0
    else:
        b = limit - fabs(a) if b > 0.0 else fabs(a) - limit
    o1[0] = clamp_abs(a + b, limit)
    o2[0] = s2 * clamp_abs(a - b, limit)

cdef inline double dswerve_drive_factor(const dswerve_t* g, Py_ssize_t n,
                                        const double* v, Py_ssize_t vstride,
                                        const double* w, double limit) noexcept nogil:
    # The largest k in [0, 1] with 0.5·|R_A·w_i| + k·0.5·|kv·v_i| <= limit for every pod.
    # A pod whose steering alone exceeds the limit forces k = 0. A NaN anywhere returns
    # 1 (no scaling), as a NaN wheel speed disables WPILib's desaturation.
    cdef Py_ssize_t i
    cdef double k = 1.0, a, b
    for i in range(n):
        a = fabs(0.5 * g.ra * w[i])
        b = fabs(0.5 * g.kv * v[i * vstride])
        if a != a or b != b:
            return 1.0
        if a + b > limit:
            if a >= limit:
                k = 0.0
            elif (limit - a) / b < k:
                k = (limit - a) / b
    return k


# ---------------------------------------------------------------------------------------
# Classes

@cython.final
cdef class DifferentialSwerveMotorVelocities(_WheelValues):
    pass

@cython.final
cdef class DifferentialSwerveModuleVelocities(_WheelValues):
    pass

@cython.final
cdef class DifferentialSwerveModuleKinematics:
    cdef dswerve_t g             # geometry; g.ra == 0 until __init__ has completed
    cdef double p1               # motor 1 position at the last reset, rad (as read)
    cdef double p2               # motor 2 position at the last reset, rad (as read)
    cdef rot2_t r0               # pod angle at the last reset
    cdef double a0               # the same angle in rad, atan2(r0): the hot path adds to it
    cdef int _ready(self) except -1
    cdef int _set_offset(self, rot2_t r, double p1, double p2) except -1
