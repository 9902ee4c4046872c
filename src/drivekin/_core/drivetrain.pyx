"""The drivetrain contract's base class (declared in drivetrain.pxd). Every method is
overridden by each kinematics class; these bodies only keep a half-built subclass from
computing."""


cdef class Drivetrain:

    cdef int _ready(self) except -1:
        raise TypeError(f"{type(self).__name__} does not implement the drivetrain contract")

    cdef int _center(self, object centerOfRotation) except -1:
        if centerOfRotation is not None:
            raise TypeError(f"{type(self).__name__} has no centre of rotation argument")
        return 0

    cdef int _forward_check(self, bint gyro, bint accel) except -1:
        return 0

    cdef Py_ssize_t _params(self, double* params, bint forward, bint accel) noexcept:
        return 0

    cdef void _inverse_many(self, Py_ssize_t k, const double* chassis, const double* omega,
                            bint accel, double* params,
                            double* m, double* c, double* s) noexcept nogil:
        pass

    cdef void _inverse_done(self, const double* params, bint accel) noexcept:
        pass

    cdef void _forward_many(self, Py_ssize_t k, const double* m, const double* c,
                            const double* s, const double* gyro, bint accel,
                            const double* params, double* out) noexcept nogil:
        pass
