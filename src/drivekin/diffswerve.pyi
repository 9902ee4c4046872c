"""Differential swerve modules: two motors drive each pod through a differential.

Model (R = motor turns per output turn, so a ratio of 3 means the motor turns three times
per pod turn)::

    R_A · ω_pod   = ω_m1 + ω_m2          (the sum of the motors turns the pod)
    R_L · ω_wheel = ω_m1 − ω_m2          (their difference spins the wheel)
    ω_wheel       = v / r                (v: wheel ground speed, r: wheel radius)

With ``motor2_inverted=True`` motor 2 is mounted reversed: what it reads and what it is
commanded is −ω_m2. Units: m, m/s, rad, rad/s. The same linear map converts motor
position changes (rad) into the pod's rotation (rad) and the wheel's travel (m), so
integrating the velocity map and converting the integrated motor positions agree to
rounding (quail's ``calculateModuleAngle`` does not: it is off by a factor 2·R_s²).
"""

# Hand-written stub for the compiled module drivekin.diffswerve (diffswerve.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, the two value classes derive from the private base
# drivekin._core.wheels._WheelValues (_core/wheels.pyi), which declares the arithmetic
# they share (typed with Self).

from collections.abc import Sequence
from typing import ClassVar, final

import numpy as np
import numpy.typing as npt

from drivekin._core.wheels import _WheelValues
from drivekin.geometry import Rotation2d
from drivekin.swerve import SwerveModulePosition, SwerveModuleVelocity

@final
class DifferentialSwerveMotorVelocities(_WheelValues):
    """DifferentialSwerveMotorVelocities(motor1=0.0, motor2=0.0)

    The angular velocities of a differential swerve pod's two motors, rad/s, as each
    motor reads them (a reversed motor 2, ``motor2_inverted=True``, reads −ω_m2).
    Mutable; ``==`` compares each motor within 1e-9 rad/s (so instances are unhashable);
    unpacks as ``motor1, motor2 = velocities``.
    """

    def __init__(self, motor1: float = 0.0, motor2: float = 0.0) -> None: ...
    @property
    def motor1(self) -> float:
        """Motor 1 angular velocity, rad/s."""

    @motor1.setter
    def motor1(self, value: float) -> None: ...
    @property
    def motor2(self) -> float:
        """Motor 2 angular velocity, rad/s (as motor 2 reads it)."""

    @motor2.setter
    def motor2(self, value: float) -> None: ...
    def interpolate(
        self, end_value: DifferentialSwerveMotorVelocities, t: float
    ) -> DifferentialSwerveMotorVelocities:
        """Linear interpolation with ``t`` clamped to [0, 1]."""

    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

@final
class DifferentialSwerveModuleVelocities(_WheelValues):
    """DifferentialSwerveModuleVelocities(wheel_velocity=0.0, azimuth_velocity=0.0)

    The motion of one differential swerve pod: the wheel's ground speed ``wheel_velocity``
    in m/s and the pod's steering rate ``azimuth_velocity`` in rad/s (counter-clockwise
    positive). Mutable; ``==`` compares each field within 1e-9 (so instances are
    unhashable); unpacks as ``wheel_velocity, azimuth_velocity = velocities``.
    """

    def __init__(self, wheel_velocity: float = 0.0, azimuth_velocity: float = 0.0) -> None: ...
    @property
    def wheelVelocity(self) -> float:
        """Wheel ground speed, m/s."""

    @wheelVelocity.setter
    def wheelVelocity(self, value: float) -> None: ...
    @property
    def azimuthVelocity(self) -> float:
        """Pod steering rate, rad/s (counter-clockwise positive)."""

    @azimuthVelocity.setter
    def azimuthVelocity(self, value: float) -> None: ...
    def interpolate(
        self, end_value: DifferentialSwerveModuleVelocities, t: float
    ) -> DifferentialSwerveModuleVelocities:
        """Linear interpolation with ``t`` clamped to [0, 1]."""

    def __eq__(self, other: object, /) -> bool: ...
    __hash__: ClassVar[None]  # type: ignore[assignment]

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    @property
    def azimuth_velocity(self) -> float: ...
    @azimuth_velocity.setter
    def azimuth_velocity(self, value: float) -> None: ...
    @property
    def wheel_velocity(self) -> float: ...
    @wheel_velocity.setter
    def wheel_velocity(self, value: float) -> None: ...

@final
class DifferentialSwerveModuleKinematics:
    """``DifferentialSwerveModuleKinematics(azimuth_gear_ratio, wheel_gear_ratio, wheel_radius, *, motor2_inverted=False)``

    Kinematics of one differential swerve pod (quail's model, made consistent):
    ``R_A·ω_pod = ω_m1 + ω_m2`` and ``R_L·ω_wheel = ω_m1 − ω_m2`` with ``ω_wheel = v / r``.

    ``azimuth_gear_ratio`` R_A and ``wheel_gear_ratio`` R_L are motor turns per output turn
    (pod turn, wheel turn); quail's ``R_s``/``R_d`` are output per motor turn, i.e.
    R_A = 1/R_s and R_L = 1/R_d. ``wheel_radius`` r is in m. All three must be positive and
    finite (ValueError naming the argument otherwise). ``motor2_inverted=True`` means
    motor 2 is mounted reversed: every motor-2 value this class takes or returns (velocity
    or position) is the negative of the ω_m2 in the equations.

    Motor velocities are rad/s and motor positions rad, as the motors' own encoders
    report them (convert from rotations or RPM first). The object also remembers the
    offset set by :meth:`resetModulePosition` (pod angle 0 and motor positions 0 until
    the first reset); it is not thread-safe against a concurrent reset, like WPILib's
    kinematics classes.
    """

    def __init__(
        self,
        azimuth_gear_ratio: float,
        wheel_gear_ratio: float,
        wheel_radius: float,
        *,
        motor2_inverted: bool = False,
    ) -> None: ...
    @property
    def azimuthGearRatio(self) -> float:
        """R_A: motor turns per pod (azimuth) turn (read-only)."""

    @property
    def wheelGearRatio(self) -> float:
        """R_L: motor turns per wheel turn (read-only)."""

    @property
    def wheelRadius(self) -> float:
        """Wheel radius, m (read-only)."""

    @property
    def motor2Inverted(self) -> bool:
        """True if motor 2 is mounted reversed (read-only)."""

    def toMotorVelocities(
        self, wheel_velocity: float, azimuth_velocity: float
    ) -> DifferentialSwerveMotorVelocities:
        """Return the motor velocities (DifferentialSwerveMotorVelocities, rad/s) that
        drive the wheel at ``wheel_velocity`` m/s while the pod turns at
        ``azimuth_velocity`` rad/s: ω_m1 = (R_A·ω_pod + R_L·v/r)/2,
        ω_m2 = (R_A·ω_pod − R_L·v/r)/2 (negated when motor 2 is inverted)."""

    def toMotorVelocitiesInto(
        self,
        wheel_velocity: float,
        azimuth_velocity: float,
        out: DifferentialSwerveMotorVelocities,
    ) -> None:
        """Allocation-free :meth:`toMotorVelocities`: write into ``out``. Returns None."""

    def toModuleVelocities(
        self, motor1: float, motor2: float
    ) -> DifferentialSwerveModuleVelocities:
        """Return the pod's motion (DifferentialSwerveModuleVelocities: wheel m/s,
        steering rad/s) for motor velocities ``motor1``, ``motor2`` in rad/s, the exact
        inverse of :meth:`toMotorVelocities`: ω_pod = (ω_m1 + ω_m2)/R_A,
        v = r·(ω_m1 − ω_m2)/R_L."""

    def toModuleVelocitiesInto(
        self, motor1: float, motor2: float, out: DifferentialSwerveModuleVelocities
    ) -> None:
        """Allocation-free :meth:`toModuleVelocities`: write into ``out``. Returns None."""

    def resetModulePosition(
        self, angle: Rotation2d, motor1_position: float, motor2_position: float
    ) -> None:
        """Declare that the pod points at ``angle`` while the motors read
        ``motor1_position`` and ``motor2_position`` (rad, finite; ValueError otherwise):
        :meth:`toModulePosition` measures from here. Call it once the pod's absolute
        angle is known (e.g. from an absolute encoder at start-up). Returns None."""

    def toModulePosition(
        self, motor1_position: float, motor2_position: float
    ) -> SwerveModulePosition:
        """Return the SwerveModulePosition for the motors' positions (rad): the distance
        (m) the wheel has rolled since the last :meth:`resetModulePosition` and the pod
        angle = reset angle + (Δθ_m1 + Δθ_m2)/R_A. Before any reset the offset is zero
        (angle 0 and distance 0 at motor positions 0). Feed the results to
        SwerveDriveOdometry as the module positions."""

    def toModulePositionInto(
        self, motor1_position: float, motor2_position: float, out: SwerveModulePosition
    ) -> None:
        """Allocation-free :meth:`toModulePosition`: write into ``out``. Returns None."""

    def desaturateMotorVelocities(
        self,
        motor_velocities: DifferentialSwerveMotorVelocities,
        max_motor_velocity: float,
        *,
        proportional: bool = False,
    ) -> DifferentialSwerveMotorVelocities:
        """Return new motor velocities each of magnitude at most ``max_motor_velocity`` (rad/s,
        ≥ 0; ValueError if negative or NaN; inf means no limit).

        By default the pod's steering rate is kept and the wheel speed is reduced first:
        the wheel slows until the faster motor is at the limit, and only when steering
        alone needs more than the limit is the steering rate cut (to the limit, with the
        wheel stopped). The pod then still reaches its commanded angle on time, which
        keeps the robot's path. ``proportional=True`` instead scales both motors by one
        factor (the fastest lands on the limit), which slows steering and wheel alike.
        Velocities already within the limit, or with a NaN motor, are returned unchanged.
        The input is not modified."""

    def desaturateMotorVelocitiesInPlace(
        self,
        motor_velocities: DifferentialSwerveMotorVelocities,
        max_motor_velocity: float,
        *,
        proportional: bool = False,
    ) -> None:
        """Allocation-free :meth:`desaturateMotorVelocities` (same rules and keyword):
        rescale ``motor_velocities`` itself. Returns None."""

    def desaturateModuleVelocitiesInPlace(
        self,
        module_velocities: Sequence[SwerveModuleVelocity] | npt.NDArray[np.float64],
        azimuth_velocities: Sequence[float] | npt.NDArray[np.float64],
        max_motor_velocity: float,
    ) -> float:
        """Drive-level desaturation for a swerve drive whose N pods are all built like this
        one: scale every module's wheel velocity by one common factor k in [0, 1], the
        largest for which no pod's motors exceed ``max_motor_velocity`` (rad/s, ≥ 0) while
        pod i steers at ``azimuth_velocities[i]`` rad/s. Because every wheel is scaled
        alike (angles untouched), the chassis keeps its direction of travel and its
        centre of rotation. Returns k (1.0 when nothing needed scaling).

        ``module_velocities`` are the N targets from SwerveDriveKinematics: a list/tuple
        of SwerveModuleVelocity (updated in place) or a float64 (N, 2) array
        ``[velocity m/s, angle rad]`` (column 0 rescaled in place).
        ``azimuth_velocities`` is a sequence of N numbers or a float64 (N,) array.
        Allocation-free for N ≤ 16. Every input is read and checked before anything is
        written, so a failed call changes nothing.

        Steering is never reduced here: if a pod's steering rate alone needs more than the
        limit, k is 0 (all wheels stop) and that pod's motors still exceed it; cut them
        with :meth:`desaturateMotorVelocities` afterwards. A NaN velocity or steering rate
        disables the scaling (k = 1), as a NaN wheel speed does in WPILib's
        desaturation. Up to rounding (a few ulps), the motors of the scaled targets are
        within the limit."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    @property
    def azimuth_gear_ratio(self) -> float: ...
    desaturate_module_velocities_in_place = desaturateModuleVelocitiesInPlace
    desaturate_motor_velocities = desaturateMotorVelocities
    desaturate_motor_velocities_in_place = desaturateMotorVelocitiesInPlace
    @property
    def motor2_inverted(self) -> bool: ...
    reset_module_position = resetModulePosition
    to_module_position = toModulePosition
    to_module_position_into = toModulePositionInto
    to_module_velocities = toModuleVelocities
    to_module_velocities_into = toModuleVelocitiesInto
    to_motor_velocities = toMotorVelocities
    to_motor_velocities_into = toMotorVelocitiesInto
    @property
    def wheel_gear_ratio(self) -> float: ...
    @property
    def wheel_radius(self) -> float: ...
