"""WPILib's DC motor model (WPILib 2027 ``org.wpilib.math.system.DCMotor``).

Units: V, N·m, A, rad/s, ohm. A motor is described by five measured constants at its
nominal voltage (stall torque, stall current, free current, free speed); a gearbox of
``num_motors`` identical motors adds their torques and currents. The derived constants are
computed as WPILib computes them::

    R  = nominalVoltage / stallCurrent
    Kv = freeSpeed / (nominalVoltage − R · freeCurrent)
    Kt = stallTorque / stallCurrent
"""
cimport cython
from cpython.long cimport PyLong_CheckExact
from libc.math cimport M_PI, isfinite

from drivekin._core.args cimport positive_finite
from drivekin._core.errors import refuse_delete, type_name

__all__ = ["DCMotor"]

# Java's int: the largest gearbox WPILib can describe.
cdef long long MAX_MOTORS = 2147483647

cdef object MISSING = object()


cdef double motor_count(object num_motors) except -1.0:
    # An exact int (never a bool or a float) in 1 .. 2**31 - 1, as WPILib's int.
    if not PyLong_CheckExact(num_motors):
        raise TypeError(f"num_motors must be an int, got {type_name(num_motors)}")
    if not 1 <= num_motors <= MAX_MOTORS:
        raise ValueError(f"num_motors must be a number of motors from 1 to {MAX_MOTORS}, "
                         f"got {num_motors!r}")
    return <double>(<long long>num_motors)


cdef int set_constants(DCMotor m, double nominal_voltage, double stall_torque,
                       double stall_current, double free_current, double free_speed,
                       double n, str scale) except -1:
    """Validate the constants, scale them to ``n`` motors and derive R, Kv and Kt in
    WPILib's order of operations; ``scale`` names what multiplied them (num_motors, or
    gearbox_reduction for withReduction), for the overflow message."""
    cdef double ts, cs, fs, r, kv, kt
    positive_finite(nominal_voltage, "nominal_voltage", "voltage in V")
    positive_finite(stall_torque, "stall_torque", "torque in N·m")
    positive_finite(stall_current, "stall_current", "current in A")
    if not (isfinite(free_current) and free_current >= 0.0):
        raise ValueError(f"free_current must be a non-negative finite current in A, "
                         f"got {free_current!r}")
    if not free_current < stall_current:
        raise ValueError(f"free_current must be less than stall_current ({stall_current!r} A), "
                         f"got {free_current!r}")
    positive_finite(free_speed, "free_speed", "angular velocity in rad/s")
    ts = stall_torque * n
    cs = stall_current * n
    fs = free_current * n
    r = nominal_voltage / cs
    kv = free_speed / (nominal_voltage - r * fs)
    kt = ts / cs
    if not (isfinite(ts) and isfinite(cs) and isfinite(r) and r > 0.0
            and isfinite(kv) and kv > 0.0 and isfinite(kt) and kt > 0.0):
        raise ValueError(f"these constants give a motor without finite positive R, Kv and "
                         f"Kt (R = {r!r} ohm, Kv = {kv!r} (rad/s)/V, Kt = {kt!r} N·m/A; "
                         f"check the {scale} and the current constants)")
    m.v = nominal_voltage
    m.stall_torque = ts
    m.stall_current = cs
    m.free_current = fs
    m.free_speed = free_speed
    m.r = r
    m.kv = kv
    m.kt = kt
    m.frozen = True
    return 0


cdef DCMotor new_motor(double nominal_voltage, double stall_torque, double stall_current,
                       double free_current, double free_speed, object num_motors):
    cdef DCMotor m = DCMotor.__new__(DCMotor)
    set_constants(m, nominal_voltage, stall_torque, stall_current, free_current, free_speed,
                  motor_count(num_motors), "num_motors")
    return m


cdef inline double rpm(double x) noexcept:
    # WPILib's Units.rotationsPerMinuteToRadiansPerSecond: rpm * π / 30.
    return x * M_PI / 30.0


cdef int uninitialised() except -1:
    raise RuntimeError("DCMotor.__init__ has not completed")


@cython.freelist(16)
cdef class DCMotor:
    """DCMotor(nominal_voltage, stall_torque, stall_current, free_current, free_speed, num_motors=1)

    The constants of a DC motor, or of a gearbox of ``num_motors`` identical motors:
    ``nominal_voltage`` (V) at which the others were measured, ``stall_torque`` (N·m),
    ``stall_current`` and ``free_current`` (A), ``free_speed`` (rad/s). The gearbox's stall
    torque, stall current and free current are ``num_motors`` times the motor's; its free
    speed is the motor's. ``R``, ``Kv`` and ``Kt`` are derived from them as WPILib does.

    The constants must be positive and finite (``free_current`` may be 0 and must be less
    than ``stall_current``), ``num_motors`` an int from 1 to 2**31 − 1 (ValueError or
    TypeError otherwise; WPILib does not check). Immutable; ``==`` compares every
    constant exactly (so instances are unhashable, like drivekin's other values).
    """

    def __init__(self, double nominal_voltage, double stall_torque, double stall_current,
                 double free_current, double free_speed, num_motors=1):
        if self.frozen:
            raise TypeError("DCMotor is immutable: __init__ cannot be called on an "
                            "existing instance")
        set_constants(self, nominal_voltage, stall_torque, stall_current, free_current,
                      free_speed, motor_count(num_motors), "num_motors")

    # -- the constants ------------------------------------------------------------------

    @property
    def nominalVoltage(self):
        """Voltage at which the motor constants were measured, V."""
        return self.v

    @property
    def stallTorque(self):
        """Torque when stalled, N·m (the whole gearbox's)."""
        return self.stall_torque

    @property
    def stallCurrent(self):
        """Current draw when stalled, A (the whole gearbox's)."""
        return self.stall_current

    @property
    def freeCurrent(self):
        """Current draw under no load, A (the whole gearbox's)."""
        return self.free_current

    @property
    def freeSpeed(self):
        """Angular velocity under no load, rad/s."""
        return self.free_speed

    @property
    def R(self):
        """Motor internal resistance, ohm: ``nominalVoltage / stallCurrent``."""
        return self.r

    @property
    def Kv(self):
        """Motor velocity constant, (rad/s)/V: ``freeSpeed / (nominalVoltage − R ·
        freeCurrent)``."""
        return self.kv

    @property
    def Kt(self):
        """Motor torque constant, N·m/A: ``stallTorque / stallCurrent``."""
        return self.kt

    # -- the model ----------------------------------------------------------------------

    def getCurrent(self, *args, velocity=MISSING, input_voltage=MISSING, torque=MISSING):
        """getCurrent(velocity, input_voltage) or getCurrent(torque)

        The current drawn, A: by the motor turning at ``velocity`` (rad/s) with
        ``input_voltage`` (V) applied, ``−velocity / Kv / R + input_voltage / R``; or the
        current that produces ``torque`` (N·m), ``torque / Kt``. One positional argument
        is the torque."""
        cdef double w, u, t
        cdef Py_ssize_t n = len(args)
        if not self.frozen:
            uninitialised()
        if n and (velocity is not MISSING or input_voltage is not MISSING
                  or torque is not MISSING):
            n = 3                               # a mixture of positional and keywords
        if n == 2:
            velocity, input_voltage = args
        elif n == 1:
            torque = args[0]
        elif n:
            raise TypeError("getCurrent() takes (velocity, input_voltage) or (torque)")
        if torque is MISSING and input_voltage is not MISSING and velocity is not MISSING:
            w = velocity
            u = input_voltage
            return motor_current(self.kv, self.r, w, u)
        if torque is not MISSING and input_voltage is MISSING and velocity is MISSING:
            t = torque
            return t / self.kt
        raise TypeError("getCurrent() takes (velocity, input_voltage) or (torque)")

    def getTorque(self, double current):
        """Return the torque produced with ``current`` (A) drawn, N·m: ``current · Kt``."""
        if not self.frozen:
            uninitialised()
        return current * self.kt

    def getVoltage(self, double torque, double velocity):
        """Return the voltage applied to the motor producing ``torque`` (N·m) while
        turning at ``velocity`` (rad/s), V: ``velocity / Kv + R · torque / Kt``."""
        if not self.frozen:
            uninitialised()
        return 1.0 / self.kv * velocity + 1.0 / self.kt * self.r * torque

    def getVelocity(self, double torque, double input_voltage):
        """Return the angular velocity of the motor producing ``torque`` (N·m) with
        ``input_voltage`` (V) applied, rad/s:
        ``input_voltage · Kv − torque · R · Kv / Kt``."""
        if not self.frozen:
            uninitialised()
        return input_voltage * self.kv - 1.0 / self.kt * torque * self.r * self.kv

    def withReduction(self, double gearbox_reduction):
        """Return this motor behind a gearbox of ``gearbox_reduction`` motor turns per
        output turn (a new DCMotor): the stall torque times the reduction, the free speed
        divided by it, the currents unchanged. The reduction must be positive and
        finite."""
        cdef DCMotor m
        cdef double ts, fs
        if not self.frozen:
            uninitialised()
        positive_finite(gearbox_reduction, "gearbox_reduction", "ratio")
        ts = self.stall_torque * gearbox_reduction
        fs = self.free_speed / gearbox_reduction
        if not (isfinite(ts) and ts > 0.0 and isfinite(fs) and fs > 0.0):
            # The ratio's fault, not the constants' (1e-320 made the free speed inf).
            raise ValueError(f"gearbox_reduction {gearbox_reduction!r} is out of range for "
                             f"this motor: it makes the stall torque {ts!r} N·m and the free "
                             f"speed {fs!r} rad/s, which must be positive and finite")
        m = DCMotor.__new__(DCMotor)
        set_constants(m, self.v, ts, self.stall_current, self.free_current, fs, 1.0,
                      "gearbox_reduction")
        return m

    # -- value semantics ----------------------------------------------------------------

    def __eq__(self, other):
        cdef DCMotor o
        if type(other) is not DCMotor:
            return NotImplemented
        o = <DCMotor>other
        return (self.v == o.v and self.stall_torque == o.stall_torque
                and self.stall_current == o.stall_current
                and self.free_current == o.free_current and self.free_speed == o.free_speed
                and self.r == o.r and self.kv == o.kv and self.kt == o.kt)

    __hash__ = None

    def __reduce__(self):
        # The gearbox's constants as one motor: R, Kv and Kt come out the same bits.
        return (DCMotor, (self.v, self.stall_torque, self.stall_current, self.free_current,
                          self.free_speed))

    def __repr__(self):
        return (f"DCMotor(nominal_voltage={self.v!r}, stall_torque={self.stall_torque!r}, "
                f"stall_current={self.stall_current!r}, free_current={self.free_current!r}, "
                f"free_speed={self.free_speed!r})")

    def __delattr__(self, name):
        refuse_delete(self, name)

    # -- WPILib's motors ----------------------------------------------------------------

    @staticmethod
    def getCIM(num_motors=1):
        """Return a gearbox of ``num_motors`` CIM motors (12 V, 2.42 N·m, 133 A, 2.7 A,
        5310 rpm)."""
        return new_motor(12.0, 2.42, 133.0, 2.7, rpm(5310.0), num_motors)

    @staticmethod
    def getVex775Pro(num_motors=1):
        """Return a gearbox of ``num_motors`` 775Pro motors (12 V, 0.71 N·m, 134 A, 0.7 A,
        18730 rpm)."""
        return new_motor(12.0, 0.71, 134.0, 0.7, rpm(18730.0), num_motors)

    @staticmethod
    def getNEO(num_motors=1):
        """Return a gearbox of ``num_motors`` NEO motors (12 V, 2.6 N·m, 105 A, 1.8 A,
        5676 rpm)."""
        return new_motor(12.0, 2.6, 105.0, 1.8, rpm(5676.0), num_motors)

    @staticmethod
    def getMiniCIM(num_motors=1):
        """Return a gearbox of ``num_motors`` MiniCIM motors (12 V, 1.41 N·m, 89 A, 3 A,
        5840 rpm)."""
        return new_motor(12.0, 1.41, 89.0, 3.0, rpm(5840.0), num_motors)

    @staticmethod
    def getBag(num_motors=1):
        """Return a gearbox of ``num_motors`` Bag motors (12 V, 0.43 N·m, 53 A, 1.8 A,
        13180 rpm)."""
        return new_motor(12.0, 0.43, 53.0, 1.8, rpm(13180.0), num_motors)

    @staticmethod
    def getAndymarkRs775_125(num_motors=1):
        """Return a gearbox of ``num_motors`` Andymark RS775-125 motors (12 V, 0.28 N·m,
        18 A, 1.6 A, 5800 rpm)."""
        return new_motor(12.0, 0.28, 18.0, 1.6, rpm(5800.0), num_motors)

    @staticmethod
    def getBanebotsRs775(num_motors=1):
        """Return a gearbox of ``num_motors`` Banebots RS775 motors (12 V, 0.72 N·m, 97 A,
        2.7 A, 13050 rpm)."""
        return new_motor(12.0, 0.72, 97.0, 2.7, rpm(13050.0), num_motors)

    @staticmethod
    def getAndymark9015(num_motors=1):
        """Return a gearbox of ``num_motors`` Andymark 9015 motors (12 V, 0.36 N·m, 71 A,
        3.7 A, 14270 rpm)."""
        return new_motor(12.0, 0.36, 71.0, 3.7, rpm(14270.0), num_motors)

    @staticmethod
    def getBanebotsRs550(num_motors=1):
        """Return a gearbox of ``num_motors`` Banebots RS 550 motors (12 V, 0.38 N·m,
        84 A, 0.4 A, 19000 rpm)."""
        return new_motor(12.0, 0.38, 84.0, 0.4, rpm(19000.0), num_motors)

    @staticmethod
    def getNeo550(num_motors=1):
        """Return a gearbox of ``num_motors`` NEO 550 motors (12 V, 0.97 N·m, 100 A,
        1.4 A, 11000 rpm)."""
        return new_motor(12.0, 0.97, 100.0, 1.4, rpm(11000.0), num_motors)

    @staticmethod
    def getFalcon500(num_motors=1):
        """Return a gearbox of ``num_motors`` Falcon 500 motors (12 V, 4.69 N·m, 257 A,
        1.5 A, 6380 rpm)."""
        return new_motor(12.0, 4.69, 257.0, 1.5, rpm(6380.0), num_motors)

    @staticmethod
    def getFalcon500Foc(num_motors=1):
        """Return a gearbox of ``num_motors`` Falcon 500 motors with FOC (field-oriented
        control) enabled (12 V, 5.84 N·m, 304 A, 1.5 A, 6080 rpm)."""
        return new_motor(12.0, 5.84, 304.0, 1.5, rpm(6080.0), num_motors)

    @staticmethod
    def getRomiBuiltIn(num_motors=1):
        """Return a gearbox of ``num_motors`` Romi/TI_RSLK MAX motors (4.5 V, 0.1765 N·m,
        1.25 A, 0.13 A, 150 rpm)."""
        return new_motor(4.5, 0.1765, 1.25, 0.13, rpm(150.0), num_motors)

    @staticmethod
    def getKrakenX60(num_motors=1):
        """Return a gearbox of ``num_motors`` Kraken X60 motors (12 V, 7.09 N·m, 366 A,
        2 A, 6000 rpm)."""
        return new_motor(12.0, 7.09, 366.0, 2.0, rpm(6000.0), num_motors)

    @staticmethod
    def getKrakenX60Foc(num_motors=1):
        """Return a gearbox of ``num_motors`` Kraken X60 motors with FOC enabled (12 V,
        9.37 N·m, 483 A, 2 A, 5800 rpm)."""
        return new_motor(12.0, 9.37, 483.0, 2.0, rpm(5800.0), num_motors)

    @staticmethod
    def getKrakenX44(num_motors=1):
        """Return a gearbox of ``num_motors`` Kraken X44 motors (12 V, 4.11 N·m, 279 A,
        2 A, 7758 rpm)."""
        return new_motor(12.0, 4.11, 279.0, 2.0, rpm(7758.0), num_motors)

    @staticmethod
    def getKrakenX44Foc(num_motors=1):
        """Return a gearbox of ``num_motors`` Kraken X44 motors with FOC enabled (12 V,
        5.01 N·m, 329 A, 2 A, 7368 rpm)."""
        return new_motor(12.0, 5.01, 329.0, 2.0, rpm(7368.0), num_motors)

    @staticmethod
    def getMinion(num_motors=1):
        """Return a gearbox of ``num_motors`` Minion motors (12 V, 3.17 N·m, 211 A, 2 A,
        7704 rpm)."""
        return new_motor(12.0, 3.17, 211.0, 2.0, rpm(7704.0), num_motors)

    @staticmethod
    def getNeoVortex(num_motors=1):
        """Return a gearbox of ``num_motors`` NEO Vortex motors (12 V, 3.60 N·m, 211 A,
        3.6 A, 6784 rpm)."""
        return new_motor(12.0, 3.60, 211.0, 3.6, rpm(6784.0), num_motors)
