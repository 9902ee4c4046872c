# The robot as PathPlannerLib's swerve setpoint generator sees it (drivekin.setpoint's
# generator reads these fields into its C state).
cimport cython
from drivekin.motor cimport DCMotor


@cython.final
cdef class ModuleConfig:
    cdef double radius           # wheel radius, m
    cdef double vmax             # top drive speed, m/s
    cdef double cof              # wheel coefficient of friction
    cdef double current_limit    # A, for the module's numMotors motors
    cdef double torque_loss      # N·m the module loses to friction at top speed
    cdef long long num_motors
    cdef DCMotor motor           # the drive gearbox, reduction included
    cdef bint frozen


@cython.final
cdef class RobotConfig:
    cdef double mass             # kg
    cdef double moi              # kg·m²
    cdef ModuleConfig module
    cdef tuple locations         # Translation2d per module, robot frame
    cdef tuple pivots            # |location| per module, m (floats)
    cdef bint frozen
