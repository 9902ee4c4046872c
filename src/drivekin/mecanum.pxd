# Mecanum drive kinematics and its wheel values. Wheel order everywhere: front left,
# front right, rear left, rear right (WPILib's; Road Runner uses a different order).
cimport cython
from drivekin._core.drivetrain cimport Drivetrain
from drivekin._core.types cimport vec2_t
from drivekin._core.wheels cimport _WheelValues


cdef class _Wheel4(_WheelValues):
    pass

@cython.final
cdef class MecanumDriveWheelVelocities(_Wheel4):
    pass

@cython.final
cdef class MecanumDriveWheelPositions(_Wheel4):
    pass

@cython.final
cdef class MecanumDriveWheelAccelerations(_Wheel4):
    pass

@cython.final
cdef class MecanumDriveKinematics(Drivetrain):
    cdef double wx[4]            # wheel x, m (robot frame)
    cdef double wy[4]            # wheel y, m
    cdef double m[12]            # 4 x 3 inverse matrix for the current centre of rotation
    cdef double f[12]            # 3 x 4 pseudo-inverse, fixed at CoR = 0
    cdef vec2_t cor              # centre of rotation m was built for, m
    cdef tuple wheels            # the Translation2d objects

    cdef void _inverse(self, const double* x, object cor, double* out) except *
