# Differential swerve module: two motors drive one pod through a differential. Their sum
# turns the pod, their difference spins the wheel:
#     R_A·ω_pod = ω_m1 + ω_m2,    R_L·ω_wheel = ω_m1 − ω_m2,    ω_wheel = v / r
# (R = motor turns per output turn). A reversed motor 2 reads and takes −ω_m2.
# The kernels (drivekin._core.kernels) work on C doubles only; the classes hold their
# state by value.
cimport cython
from drivekin._core.types cimport dswerve_t, rot2_t
from drivekin._core.wheels cimport _WheelValues


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
