# Dead-wheel (tracking-wheel) kinematics over any number of wheels at any poses.
cimport cython
from drivekin._core.drivetrain cimport Drivetrain
from drivekin.chassis cimport _ChassisVector


@cython.final
cdef class DeadWheelKinematics(Drivetrain):
    cdef Py_ssize_t n            # number of wheels
    cdef double* buf             # one allocation holding every array below
    cdef double* m               # n x 3 model rows (cos φ, sin φ, x sin φ − y cos φ)
    cdef double* p3              # 3 x n pseudo-inverse of m (unused without heading)
    cdef double* p2              # 2 x n pseudo-inverse of m's first two columns (A⁺)
    cdef double* s               # scratch, n (wheel readings of the current call)
    cdef double g[2]             # A⁺·c: how a heading change shifts the fitted (dx, dy)
    cdef bint heading            # the wheels alone observe dθ (rank m = 3)
    cdef str no_heading          # why not, for the error a gyro-less call raises
    cdef tuple poses             # the Pose2d objects, constructor order

    cdef int _refuse_reinit(self) except -1
    cdef int _read(self, object values, double* out, str what) except -1
    cdef int _need_heading(self, str call) except -1
    cdef int _forward(self, object values, object gyro, str what, str call,
                      double* out) except -1
    cdef tuple _inverse(self, _ChassisVector v)
    cdef int _inverse_into(self, _ChassisVector v, object out, str what) except -1
