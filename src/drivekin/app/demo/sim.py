"""The base of the demo's simulated drivetrains (one 20 ms step: a command in, wheel
motion, a simulated gyro and the drivekin odometry update out) and the helpers they share."""
from __future__ import annotations

import math
import time
from typing import Any

from drivekin import ChassisVelocities, Pose2d, Rotation2d, SwerveDriveKinematics
from drivekin.app.demo.script import DT


_cos = math.cos
_hypot = math.hypot
_clock_ns = time.perf_counter_ns
_from_radians = Rotation2d.fromRadians
_desaturate_in_place = SwerveDriveKinematics.desaturateWheelVelocitiesInPlace

# Hot-path rule for everything below: no Python ``for`` loops (list/tuple/range iterators
# are heap objects), no new attributes (``__slots__``), no ints above 256 (small ints are
# cached, larger ones are allocated), no containers built per step. Floats and drivekin
# values are fine: they come from freelists.


def _pose_dict(pose) -> dict:
    return {"x_m": pose.x, "y_m": pose.y, "heading_deg": pose.getRotation().getDegrees()}


def _normal(uniform) -> float:
    """A standard normal deviate from ``uniform`` (a bound ``random.Random.random``: bound
    once, since binding a method per call would allocate). Box–Muller, one pair per
    deviate (the second normal is discarded)."""
    return math.sqrt(-2.0 * math.log(1.0 - uniform())) * _cos(2.0 * math.pi * uniform())


def _track(errors, i: int, x: float) -> None:
    """errors[i] := x (the latest position error, m); errors[i + 1] := the largest so far."""
    errors[i] = x
    if x > errors[i + 1]:
        errors[i + 1] = x


def localization_rows(truth: dict, errors) -> list:
    """Report rows: the true pose, then (label, {final, max} in m, what) per estimate."""
    return [("localization", "", ""),
            ("  true pose", f"x {truth['x_m']:.3f} m, y {truth['y_m']:.3f} m",
             f"heading {truth['heading_deg']:.2f}°")] + [
        (f"  {label}", f"{e['final'] * 100:.1f} cm",
         f"final; max {e['max'] * 100:.1f} cm"
         + (f", mean {e['mean'] * 100:.1f} cm" if "mean" in e else "") + f" ({what})")
        for label, e, what in errors]

class Drivetrain:
    """Shared state of the simulated drivetrains: the simulated gyro, the odometry pose and
    the path length. Subclasses set ``name``, ``ODOMETRY`` (the odometry class), ``INPUT``
    and ``CHAIN`` (header text; CHAIN is one string per line) and implement ``describe()``
    and ``step(command)``.

    The gyro is the robot's true heading: the chassis rotation rate the wheel model
    produces (its forward kinematics, ``toChassisVelocitiesInto`` of the measured wheel
    velocities) integrated over each period. It is read like a real gyro, as a
    continuous angle in a Rotation2d, and fed to the odometry together with the wheel
    distances; the odometry trusts it for the heading."""

    name = ""
    ODOMETRY: type = object
    INPUT = ""
    CHAIN: tuple[str, ...] = ()
    GYRO: tuple[str, str] = ("true heading integrated from the simulated",
                             "wheels (toChassisVelocitiesInto of the measured wheel velocities)")
    #: whether ``--setpoint-generator`` applies (the constructor then takes
    #: ``setpoint_generator=True``)
    SETPOINT_GENERATOR = False

    __slots__ = ("max_speed", "measured", "gyro", "odometry", "pose", "distance",
                 "_gyro_rad", "_x", "_y")
    odometry: Any                       # the subclass's odometry (or estimator) object

    def __init__(self, max_speed: float) -> None:
        self.max_speed = float(max_speed)
        self.measured = ChassisVelocities()   # wheel model's forward kinematics, per step
        self._gyro_rad = 0.0                  # continuous (unwrapped) gyro angle, rad
        self.gyro = Rotation2d()
        self.distance = 0.0     # odometry path length: sum of per-step position changes, m
        self._x = 0.0
        self._y = 0.0
        # Subclasses create ``self.odometry`` and then set ``self.pose`` from it.

    def describe(self) -> str:
        """One line (or a few) on the simulated robot, for the report's header."""
        raise NotImplementedError

    def chain(self) -> tuple[str, ...]:
        """The header's lines on what one step runs (``CHAIN`` unless an option changes it)."""
        return self.CHAIN

    def step(self, command: ChassisVelocities) -> None:
        """Run one 20 ms control period for the driver's ``command``."""
        raise NotImplementedError

    def results(self) -> dict:
        """Drivetrain-specific results for the report (JSON-ready); none by default."""
        return {}

    @classmethod
    def report_rows(cls, r: dict) -> list:
        """Extra rows (label, value, note) of the text report for a :func:`run` result."""
        return []

    def start_timing(self, steps: int) -> None:
        """Called before the timing pass (never before the allocation pass): drivetrains
        that time a part of their step allocate their sample array here."""

    def timing_results(self) -> dict:
        """Results of the timing pass only (JSON-ready); none by default."""
        return {}

    def _gyro_step(self) -> Rotation2d:
        """Advance the simulated gyro by the measured rotation rate; return the reading."""
        angle = self._gyro_rad + self.measured.omega * DT
        self._gyro_rad = angle
        gyro = _from_radians(angle)
        self.gyro = gyro
        return gyro

    def _record(self, pose: Pose2d) -> None:
        """Keep the pose ``update`` returned and add its position change to the path."""
        self.pose = pose
        x = pose.x
        y = pose.y
        self.distance += _hypot(x - self._x, y - self._y)
        self._x = x
        self._y = y
