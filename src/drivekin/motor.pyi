"""WPILib's DC motor model (WPILib 2027 ``org.wpilib.math.system.DCMotor``).

Units: V, N·m, A, rad/s, ohm. A motor is described by five measured constants at its
nominal voltage (stall torque, stall current, free current, free speed); a gearbox of
``num_motors`` identical motors adds their torques and currents. The derived constants are
computed as WPILib computes them::

    R  = nominalVoltage / stallCurrent
    Kv = freeSpeed / (nominalVoltage − R · freeCurrent)
    Kt = stallTorque / stallCurrent
"""

# Hand-written stub for the compiled module drivekin.motor (motor.pyx). The docstrings are
# written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.

from typing import ClassVar, final, overload

__all__ = ["DCMotor"]

@final
class DCMotor:
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

    def __init__(self, nominal_voltage: float, stall_torque: float, stall_current: float,
                 free_current: float, free_speed: float, num_motors: int = 1) -> None: ...
    @property
    def nominalVoltage(self) -> float:
        """Voltage at which the motor constants were measured, V."""

    @property
    def stallTorque(self) -> float:
        """Torque when stalled, N·m (the whole gearbox's)."""

    @property
    def stallCurrent(self) -> float:
        """Current draw when stalled, A (the whole gearbox's)."""

    @property
    def freeCurrent(self) -> float:
        """Current draw under no load, A (the whole gearbox's)."""

    @property
    def freeSpeed(self) -> float:
        """Angular velocity under no load, rad/s."""

    @property
    def R(self) -> float:
        """Motor internal resistance, ohm: ``nominalVoltage / stallCurrent``."""

    @property
    def Kv(self) -> float:
        """Motor velocity constant, (rad/s)/V: ``freeSpeed / (nominalVoltage − R ·
        freeCurrent)``."""

    @property
    def Kt(self) -> float:
        """Motor torque constant, N·m/A: ``stallTorque / stallCurrent``."""

    @overload
    def getCurrent(self, velocity: float, input_voltage: float) -> float:
        """getCurrent(velocity, input_voltage) or getCurrent(torque)

        The current drawn, A: by the motor turning at ``velocity`` (rad/s) with
        ``input_voltage`` (V) applied, ``−velocity / Kv / R + input_voltage / R``; or the
        current that produces ``torque`` (N·m), ``torque / Kt``. One positional argument
        is the torque."""

    @overload
    def getCurrent(self, *, torque: float) -> float: ...
    @overload
    def getCurrent(self, torque: float, /) -> float: ...
    def getTorque(self, current: float) -> float:
        """Return the torque produced with ``current`` (A) drawn, N·m: ``current · Kt``."""

    def getVoltage(self, torque: float, velocity: float) -> float:
        """Return the voltage applied to the motor producing ``torque`` (N·m) while
        turning at ``velocity`` (rad/s), V: ``velocity / Kv + R · torque / Kt``."""

    def getVelocity(self, torque: float, input_voltage: float) -> float:
        """Return the angular velocity of the motor producing ``torque`` (N·m) with
        ``input_voltage`` (V) applied, rad/s:
        ``input_voltage · Kv − torque · R · Kv / Kt``."""

    def withReduction(self, gearbox_reduction: float) -> DCMotor:
        """Return this motor behind a gearbox of ``gearbox_reduction`` motor turns per
        output turn (a new DCMotor): the stall torque times the reduction, the free speed
        divided by it, the currents unchanged. The reduction must be positive and
        finite."""

    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]
    @staticmethod
    def getCIM(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` CIM motors (12 V, 2.42 N·m, 133 A, 2.7 A,
        5310 rpm)."""

    @staticmethod
    def getVex775Pro(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` 775Pro motors (12 V, 0.71 N·m, 134 A, 0.7 A,
        18730 rpm)."""

    @staticmethod
    def getNEO(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` NEO motors (12 V, 2.6 N·m, 105 A, 1.8 A,
        5676 rpm)."""

    @staticmethod
    def getMiniCIM(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` MiniCIM motors (12 V, 1.41 N·m, 89 A, 3 A,
        5840 rpm)."""

    @staticmethod
    def getBag(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Bag motors (12 V, 0.43 N·m, 53 A, 1.8 A,
        13180 rpm)."""

    @staticmethod
    def getAndymarkRs775_125(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Andymark RS775-125 motors (12 V, 0.28 N·m,
        18 A, 1.6 A, 5800 rpm)."""

    @staticmethod
    def getBanebotsRs775(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Banebots RS775 motors (12 V, 0.72 N·m, 97 A,
        2.7 A, 13050 rpm)."""

    @staticmethod
    def getAndymark9015(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Andymark 9015 motors (12 V, 0.36 N·m, 71 A,
        3.7 A, 14270 rpm)."""

    @staticmethod
    def getBanebotsRs550(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Banebots RS 550 motors (12 V, 0.38 N·m,
        84 A, 0.4 A, 19000 rpm)."""

    @staticmethod
    def getNeo550(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` NEO 550 motors (12 V, 0.97 N·m, 100 A,
        1.4 A, 11000 rpm)."""

    @staticmethod
    def getFalcon500(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Falcon 500 motors (12 V, 4.69 N·m, 257 A,
        1.5 A, 6380 rpm)."""

    @staticmethod
    def getFalcon500Foc(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Falcon 500 motors with FOC (field-oriented
        control) enabled (12 V, 5.84 N·m, 304 A, 1.5 A, 6080 rpm)."""

    @staticmethod
    def getRomiBuiltIn(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Romi/TI_RSLK MAX motors (4.5 V, 0.1765 N·m,
        1.25 A, 0.13 A, 150 rpm)."""

    @staticmethod
    def getKrakenX60(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Kraken X60 motors (12 V, 7.09 N·m, 366 A,
        2 A, 6000 rpm)."""

    @staticmethod
    def getKrakenX60Foc(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Kraken X60 motors with FOC enabled (12 V,
        9.37 N·m, 483 A, 2 A, 5800 rpm)."""

    @staticmethod
    def getKrakenX44(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Kraken X44 motors (12 V, 4.11 N·m, 279 A,
        2 A, 7758 rpm)."""

    @staticmethod
    def getKrakenX44Foc(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Kraken X44 motors with FOC enabled (12 V,
        5.01 N·m, 329 A, 2 A, 7368 rpm)."""

    @staticmethod
    def getMinion(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` Minion motors (12 V, 3.17 N·m, 211 A, 2 A,
        7704 rpm)."""

    @staticmethod
    def getNeoVortex(num_motors: int = 1) -> DCMotor:
        """Return a gearbox of ``num_motors`` NEO Vortex motors (12 V, 3.60 N·m, 211 A,
        3.6 A, 6784 rpm)."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    andymark9015 = getAndymark9015
    bag = getBag
    banebots_rs550 = getBanebotsRs550
    banebots_rs775 = getBanebotsRs775
    cim = getCIM
    current = getCurrent
    falcon500 = getFalcon500
    falcon500_foc = getFalcon500Foc
    @property
    def free_current(self) -> float: ...
    @property
    def free_speed(self) -> float: ...
    kraken_x44 = getKrakenX44
    kraken_x44_foc = getKrakenX44Foc
    kraken_x60 = getKrakenX60
    kraken_x60_foc = getKrakenX60Foc
    @property
    def kt(self) -> float: ...
    @property
    def kv(self) -> float: ...
    mini_cim = getMiniCIM
    minion = getMinion
    neo = getNEO
    neo550 = getNeo550
    neo_vortex = getNeoVortex
    @property
    def nominal_voltage(self) -> float: ...
    @property
    def r(self) -> float: ...
    romi_built_in = getRomiBuiltIn
    rs775_125 = getAndymarkRs775_125
    @property
    def stall_current(self) -> float: ...
    @property
    def stall_torque(self) -> float: ...
    torque = getTorque
    velocity = getVelocity
    vex775_pro = getVex775Pro
    voltage = getVoltage
    with_reduction = withReduction
