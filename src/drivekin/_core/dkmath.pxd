# drivekin's own sincos, atan2 and hypot (_core/dkmath.h): the same bits on every
# platform and in every path, per-call and batch. Kernels cimport these names instead of
# libc.math's; nothing in drivekin calls libm's trigonometry or hypot.

cdef extern from "_core/dkmath.h" nogil:
    void sincos "dk_sincos"(double x, double* s, double* c)
    double atan2 "dk_atan2"(double y, double x)
    double hypot "dk_hypot"(double x, double y)
    # sin and cos of a*b where that product overflows (its 53 bits, any exponent).
    void sincos_product "dk_sincos_product"(double a, double b, double* s, double* c)

# The array forms (_core/trig_arrays.h): vectorised, the same bits as the scalar forms
# element by element; outputs must not overlap inputs.
cdef extern from "_core/trig_arrays.h" nogil:
    void sincos_n "dk_sincos_n"(Py_ssize_t n, const double* x, double* s, double* c)
    void atan2_n "dk_atan2_n"(Py_ssize_t n, const double* y, const double* x, double* r)
    const char* trig_isa "dk_trig_isa"()
    int trig_use "dk_trig_use"(const char* name)
