"""Dead-wheel (tracking-wheel) kinematics: any number of unpowered wheels at any poses.

Units: m, m/s, m/s², rad, rad/s, rad/s². Robot frame: x forward, y left, CCW positive.

A dead wheel touching the floor at (x, y) and rolling along φ reads the robot's velocity
at that point projected on its rolling direction:

    d = cos φ·(dx − y·dθ) + sin φ·(dy + x·dθ)

Stacking the wheels gives d = M·t with t = (dx, dy, dθ). Without a gyro the wheels must
observe all three components and t is the least-squares solution M⁺·d (exact for three
wheels). With a gyro, dθ is taken from it and only (dx, dy) is fitted, which two
non-parallel wheels always observe. Redundant wheels are averaged in by the least-squares
fit, never ignored. Both pseudo-inverses are built once, at construction (drivekin's own,
the same bits on every platform).
"""

# Hand-written stub for the compiled module drivekin.deadwheel (deadwheel.pyx). The
# docstrings are written from the compiled module's ``__doc__`` (the .pyx docstrings) by
# scripts/stub_docstrings.py: edit them in the .pyx, rebuild and rerun the script.
# tests/api/test_stubs.py checks that they match and that no public name is missing on
# either side.
#
# As at runtime, DeadWheelKinematics derives from drivekin._core.drivetrain.Drivetrain
# (_core/drivetrain.pyi), which has no Python-visible members.

from collections.abc import Sequence
from typing import final

import numpy as np
import numpy.typing as npt

from drivekin._core.drivetrain import Drivetrain
from drivekin.chassis import ChassisAccelerations, ChassisVelocities
from drivekin.geometry import Pose2d, Twist2d

_WheelReadings = Sequence[float] | npt.NDArray[np.float64]

@final
class DeadWheelKinematics(Drivetrain):
    """DeadWheelKinematics(wheel_poses)

    Kinematics of N ≥ 2 dead (tracking) wheels. Each wheel is a Pose2d in the robot
    frame: its translation is the contact point (m), its rotation the direction in which
    the wheel's reading grows (0 for a wheel that reads forward motion, +90° for one that
    reads leftward motion). Wheel values are passed everywhere as a list or tuple of
    floats, or a 1-D float64 array, in the order of ``wheel_poses``.

    The layout must observe (dx, dy) — at least two non-parallel wheels — or ValueError
    names the direction it cannot see. Without a gyro it must also observe rotation (at
    least three wheels whose lines do not all meet in one point); a layout that cannot
    is valid, but every call must then pass the gyro (see :meth:`requiresGyro`).
    """

    def __init__(self, wheel_poses: Sequence[Pose2d]) -> None: ...
    @staticmethod
    def fromRoadRunner(
        par0_y_ticks: float, par1_y_ticks: float, perp_x_ticks: float, in_per_tick: float
    ) -> DeadWheelKinematics:
        """Three wheels from Road Runner 1.0's ``ThreeDeadWheelLocalizer`` parameters
        (paste the tuned numbers as they are): the two parallel wheels' ``par_y_ticks`` and
        the perpendicular wheel's ``perp_x_ticks`` (ticks), and ``in_per_tick`` (inches per
        tick). Wheels are in the order (par0, par1, perp).

        Road Runner's model is par = dx + par_y_ticks·dθ, so ``par_y_ticks`` is the *negative*
        of the wheel's physical y (its tuner reports a left wheel as negative); this
        factory applies that sign. Feed readings in metres: ticks × in_per_tick × 0.0254.
        The twist is then Road Runner's, with dx and dy in metres instead of inches."""

    @staticmethod
    def fromRoadRunnerTwoWheel(
        par_y_ticks: float, perp_x_ticks: float, in_per_tick: float
    ) -> DeadWheelKinematics:
        """Two wheels (par, perp) from Road Runner 1.0's ``TwoDeadWheelLocalizer``
        parameters (ticks, and inches per tick), used with the IMU as the gyro. Same
        sign convention and units as :meth:`fromRoadRunner`."""

    def getWheelPoses(self) -> tuple[Pose2d, ...]:
        """Return the wheel poses (tuple of Pose2d, robot frame, m), constructor order."""

    def requiresGyro(self) -> bool:
        """True if the wheels alone cannot observe rotation (fewer than three wheels, or
        all wheel lines meeting in one point): every call must then pass the gyro."""

    def toChassisVelocities(
        self, wheel_velocities: _WheelReadings, gyro_rate: float | None = None
    ) -> ChassisVelocities:
        """Return the robot velocity (m/s, m/s, rad/s) from the wheels' surface velocities
        (m/s). With ``gyro_rate`` (rad/s) omega is the gyro's and (vx, vy) the wheels'
        least-squares fit; without, all three come from the wheels."""

    def toChassisVelocitiesInto(
        self,
        wheel_velocities: _WheelReadings,
        out: ChassisVelocities,
        gyro_rate: float | None = None,
    ) -> None:
        """Allocation-free :meth:`toChassisVelocities`: write into ``out``. Returns None."""

    def toWheelVelocities(self, chassis_velocities: ChassisVelocities) -> tuple[float, ...]:
        """Return each wheel's surface velocity (tuple of floats, m/s) for a robot
        velocity."""

    def toWheelVelocitiesInto(
        self, chassis_velocities: ChassisVelocities, out: npt.NDArray[np.float64]
    ) -> None:
        """Allocation-free :meth:`toWheelVelocities`: write into ``out``, a writeable
        float64 array of shape (N,) (any stride). Returns None."""

    def toTwist2d(self, wheel_deltas: _WheelReadings, gyro_delta: float | None = None) -> Twist2d:
        """Return the Twist2d (m, rad) for the wheel distance changes (m). With
        ``gyro_delta`` (rad, the heading change; wrap it to (−π, π] yourself) dθ is the
        gyro's and (dx, dy) the wheels' least-squares fit."""

    def toChassisAccelerations(
        self, wheel_accelerations: _WheelReadings, angular_acceleration: float | None = None
    ) -> ChassisAccelerations:
        """Return the robot acceleration (m/s², m/s², rad/s²) from the wheels' surface
        accelerations (m/s²): the velocity map applied to accelerations (no centripetal
        term). With ``angular_acceleration`` (rad/s²) alpha is fixed to it."""

    def toWheelAccelerations(
        self, chassis_accelerations: ChassisAccelerations
    ) -> tuple[float, ...]:
        """Return each wheel's surface acceleration (tuple of floats, m/s²)."""

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    from_road_runner = fromRoadRunner
    from_road_runner_two_wheel = fromRoadRunnerTwoWheel
    get_wheel_poses = getWheelPoses
    requires_gyro = requiresGyro
    to_chassis_accelerations = toChassisAccelerations
    to_chassis_velocities = toChassisVelocities
    to_chassis_velocities_into = toChassisVelocitiesInto
    to_twist2d = toTwist2d
    to_wheel_accelerations = toWheelAccelerations
    to_wheel_velocities = toWheelVelocities
    to_wheel_velocities_into = toWheelVelocitiesInto
