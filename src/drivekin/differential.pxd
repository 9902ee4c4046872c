# Differential (tank) drive kinematics and its wheel values (w[0] = left, w[1] = right).
cimport cython
from drivekin._core.drivetrain cimport Drivetrain
from drivekin._core.wheels cimport _WheelValues


cdef class _Wheel2(_WheelValues):
    pass

@cython.final
cdef class DifferentialDriveWheelVelocities(_Wheel2):
    pass

@cython.final
cdef class DifferentialDriveWheelPositions(_Wheel2):
    pass

@cython.final
cdef class DifferentialDriveWheelAccelerations(_Wheel2):
    pass

@cython.final
cdef class DifferentialDriveKinematics(Drivetrain):
    cdef double _trackwidth      # m, distance between the left and right wheels
