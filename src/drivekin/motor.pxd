# WPILib's DC motor model: the five measured constants (scaled to the gearbox) and the
# three derived ones, held by value.
cimport cython


@cython.final
cdef class DCMotor:
    cdef double v                # nominal voltage, V
    cdef double stall_torque     # N·m, for the whole gearbox
    cdef double stall_current    # A, for the whole gearbox
    cdef double free_current     # A, for the whole gearbox
    cdef double free_speed       # rad/s
    cdef double r                # resistance, ohm
    cdef double kv               # (rad/s)/V
    cdef double kt               # N·m/A
    cdef bint frozen             # set once constructed: __init__ may not run again


cdef inline double motor_current(double kv, double r, double w, double u) noexcept nogil:
    # DCMotor.getCurrent(velocity w, input_voltage u) in WPILib's order of operations.
    return -1.0 / kv / r * w + 1.0 / r * u
