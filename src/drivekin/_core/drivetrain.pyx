"""The drivetrain contract's base class (declared in drivetrain.pxd): the centre-of-rotation
rule written once, defaults for what most drivetrains do not need, and map bodies that
keep a subclass that does not override them from computing."""
from drivekin._core.kernels cimport vec
from drivekin._core.types cimport vec2_t
from drivekin.geometry cimport Translation2d


cdef class Drivetrain:

    cdef int _ready(self) except -1:
        raise TypeError(f"{type(self).__name__} does not implement the drivetrain contract")

    cdef int _center(self, object center_of_rotation) except -1:
        # Callers have checked that center_of_rotation is None or a Translation2d.
        if center_of_rotation is None:
            self._set_cor(vec(0.0, 0.0))
        elif self.centered:
            self._set_cor((<Translation2d>center_of_rotation).v)
        else:
            raise TypeError(f"{type(self).__name__} has no centre of rotation argument")
        return 0

    cdef void _set_cor(self, vec2_t cor) noexcept:
        pass

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

    cdef void _twists(self, Py_ssize_t k, const double* d, const double* c, const double* s,
                      const double* dth, double* out) noexcept nogil:
        pass
