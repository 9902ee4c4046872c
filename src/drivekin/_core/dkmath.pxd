# drivekin's own sincos and atan2 (_core/dkmath.h): the same bits on every
# platform and in every path, per-call and batch. Kernels cimport these names instead of
# libc.math's; nothing in drivekin calls libm's trigonometry.

cdef extern from "_core/dkmath.h" nogil:
    void sincos "dk_sincos"(double x, double* s, double* c)
    double atan2 "dk_atan2"(double y, double x)

# The array forms (_core/trig_arrays.h): vectorised, the same bits as the scalar forms
# element by element; outputs must not overlap inputs.
cdef extern from "_core/trig_arrays.h" nogil:
    void sincos_n "dk_sincos_n"(Py_ssize_t n, const double* x, double* s, double* c)
    void atan2_n "dk_atan2_n"(Py_ssize_t n, const double* y, const double* x, double* r)
    const char* trig_isa "dk_trig_isa"()
    int trig_use "dk_trig_use"(const char* name)
