# drivekin's own sin, cos, sincos and atan2 (_core/dkmath.h): the same bits on every
# platform and in every path, per-call and batch. Kernels cimport these names instead of
# libc.math's; nothing in drivekin calls libm's trigonometry.

cdef extern from "_core/dkmath.h" nogil:
    double sin "dk_sin"(double x)
    double cos "dk_cos"(double x)
    void sincos "dk_sincos"(double x, double* s, double* c)
    double atan2 "dk_atan2"(double y, double x)
