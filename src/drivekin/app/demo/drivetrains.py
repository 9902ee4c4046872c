"""The simulated drivetrains of the demo: each turns a command into wheel motion, a
simulated gyro and its drivekin odometry (or estimator) update, in one 20 ms step."""
from __future__ import annotations

import math
import random
import time
from array import array
from typing import Any

from drivekin import (
    ChassisVelocities,
    DCMotor,
    DeadWheelKinematics,
    DeadWheelOdometry,
    DifferentialDriveKinematics,
    DifferentialSwerveModuleKinematics,
    DifferentialSwerveModuleVelocities,
    DifferentialSwerveMotorVelocities,
    DifferentialDriveOdometry,
    DifferentialDriveWheelVelocities,
    DriveFeedforwards,
    MecanumDriveKinematics,
    MecanumDriveOdometry,
    MecanumDriveWheelPositions,
    MecanumDriveWheelVelocities,
    ModuleConfig,
    Pose2d,
    RobotConfig,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveDriveOdometry,
    SwerveDrivePoseEstimator,
    SwerveModulePosition,
    SwerveModuleVelocity,
    SwerveSetpoint,
    SwerveSetpointGenerator,
    Translation2d,
    Twist2d,
)
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


class SwerveModuleSim:
    """One swerve module's response to its target, updating caller-visible objects in
    place: ``state`` (measured SwerveModuleVelocity) and ``position`` (cumulative
    SwerveModulePosition at the current module angle, like the encoders).

    Model: WPILib's ``optimize`` (never steer more than 90°), steering rate-limited to
    ``max_steer_rate`` rad/s towards the target, wheel speed a first-order lag with time
    constant ``tau`` s towards the cosine-scaled target (a module that still points the
    wrong way does not push). With ``optimizeInPlace``/``cosineScaleInPlace`` available
    the target object itself is optimized and scaled; otherwise the returning forms are
    used (new objects, from a freelist). Both give the same numbers."""

    __slots__ = ("target", "state", "position", "_alpha", "_max_step")

    def __init__(self, target: SwerveModuleVelocity, tau: float, max_steer_rate: float):
        self.target = target
        self.state = SwerveModuleVelocity(0.0, Rotation2d())
        self.position = SwerveModulePosition(0.0, Rotation2d())
        self._alpha = 1.0 - math.exp(-DT / tau)
        self._max_step = max_steer_rate * DT

    def _steer(self, current: Rotation2d, goal: Rotation2d) -> Rotation2d:
        """The module angle after one period of rate-limited steering towards ``goal``."""
        error = goal.minus(current).getRadians()
        limit = self._max_step
        if error > limit:
            error = limit
        elif error < -limit:
            error = -limit
        return current.plus(_from_radians(error))

    def _drive(self, command: float, angle: Rotation2d) -> None:
        """Lag the wheel speed towards ``command``; advance the encoder at ``angle``."""
        state = self.state
        state.angle = angle                           # the setter copies the value
        v = state.velocity
        v = v + (command - v) * self._alpha
        state.velocity = v
        position = self.position
        position.distance = position.distance + v * DT
        position.angle = angle

    def update(self) -> None:
        target = self.target          # rewritten by inverse kinematics every step
        current = self.state.angle                    # Rotation2d (freelist)
        target.optimizeInPlace(current)
        angle = self._steer(current, target.angle)
        target.cosineScaleInPlace(angle)
        self._drive(target.velocity, angle)


class SwerveDrive(Drivetrain):
    """Four-module swerve robot: inverse kinematics with desaturation, the module model,
    the simulated gyro and SwerveDriveOdometry, all writing into preallocated objects.

    With ``setpoint_generator=True`` (``--setpoint-generator``) the robot-relative command
    goes through a :class:`~drivekin.SwerveSetpointGenerator` (default mode) instead of
    discretize, inverse kinematics and desaturation: ``generateSetpointInto`` updates one
    SwerveSetpoint in place every step, and its module velocities become the module
    targets. The generator's robot is :data:`SETPOINT_ROBOT` (the module model has no
    mass, so the generator's torque limits are its own), with ``max_speed`` as its top
    speed, reached at 95 % of the Kraken X60's free speed, and the module model's
    steering rate. The step also counts the steps the generator limited: those whose
    setpoint differs (by more than 1e-9 m/s or rad/s) from the desaturated, discretized
    command, which is the generator's own target
    (``SwerveDriveKinematics.desaturatedDiscretizeInto``)."""

    name = "swerve"
    ODOMETRY: type = SwerveDriveOdometry
    INPUT = "field-relative joystick"
    CHAIN: tuple[str, ...] = ("toRobotRelativeInto → discretizeInto → toSwerveModuleVelocitiesInto →",
             "desaturateWheelVelocitiesInPlace → module model: optimizeInPlace, steering limit,",
             "cosineScaleInPlace, wheel lag → SwerveDriveOdometry.update(gyro, positions)")
    #: what replaces CHAIN[:2] with --setpoint-generator
    SETPOINT_CHAIN: tuple[str, ...] = (
        "toRobotRelativeInto → SwerveSetpointGenerator.generateSetpointInto (default mode) →",
        "setpoint.moduleVelocities → module model: optimizeInPlace, steering limit,")
    HALF_TRACK = 0.3        # m, module offset from the robot centre in x and y
    WHEEL_TAU = 0.05        # s, wheel-speed time constant
    STEER_RATE = 4.0 * math.pi   # rad/s, steering rate limit
    SETPOINT_GENERATOR = True
    #: the generator's robot: mass kg, MOI kg·m², wheel radius m, wheel COF, drive current
    #: limit A (one Kraken X60 per module)
    SETPOINT_ROBOT = {"mass_kg": 60.0, "moi_kgm2": 6.0, "wheel_radius_m": 0.0508,
                      "wheel_cof": 1.2, "current_limit_a": 60.0}
    SETPOINT_VOLTS = 12.0   # V, the simulated battery (steady)
    LIMITED_TOL = 1e-9      # m/s, rad/s: a setpoint this close to its target was not limited

    __slots__ = ("kinematics", "targets", "states", "positions", "_m0", "_m1", "_m2", "_m3",
                 "generator", "setpoint", "wanted", "generated", "limited", "gearing",
                 "_sg_ns", "_sg_count")

    def __init__(self, max_speed: float, setpoint_generator: bool = False) -> None:
        super().__init__(max_speed)
        h = self.HALF_TRACK
        self.kinematics = SwerveDriveKinematics(
            Translation2d(h, h), Translation2d(h, -h), Translation2d(-h, h), Translation2d(-h, -h))
        self.targets = [SwerveModuleVelocity() for _ in range(4)]
        modules = [SwerveModuleSim(t, self.WHEEL_TAU, self.STEER_RATE) for t in self.targets]
        self._m0, self._m1, self._m2, self._m3 = modules
        self.states = [m.state for m in modules]
        self.positions = [m.position for m in modules]
        self.odometry = SwerveDriveOdometry(self.kinematics, self.gyro, self.positions)
        self.pose = self.odometry.getPose()
        self.generator: SwerveSetpointGenerator | None = None
        self._sg_ns: array | None = None        # generator time per step (timing pass)
        self._sg_count = 0
        # Steps through the generator, and those it limited (floats: no int allocation).
        self.generated = 0.0
        self.limited = 0.0
        if setpoint_generator:
            self._new_generator()

    def _new_generator(self) -> None:
        r = self.SETPOINT_ROBOT
        motor = DCMotor.getKrakenX60(1)
        # The reduction at which max_speed is 95 % of the motor's free speed (PathPlanner
        # counts the torque the motor still makes there as the module's friction).
        self.gearing = motor.freeSpeed * r["wheel_radius_m"] / (self.max_speed / 0.95)
        module = ModuleConfig(r["wheel_radius_m"], self.max_speed, r["wheel_cof"],
                              motor.withReduction(self.gearing), r["current_limit_a"], 1)
        config = RobotConfig(r["mass_kg"], r["moi_kgm2"], module,
                             self.kinematics.getModules())
        self.generator = SwerveSetpointGenerator(config, self.STEER_RATE)
        self.setpoint = SwerveSetpoint(ChassisVelocities(), [SwerveModuleVelocity()] * 4,
                                       DriveFeedforwards.zeros(4))
        self.wanted = ChassisVelocities()

    def describe(self) -> str:
        h = self.HALF_TRACK
        text = (f"swerve, 4 modules at (±{h:.2f}, ±{h:.2f}) m; wheel lag τ = "
                f"{self.WHEEL_TAU * 1000:.0f} ms, steering ≤ {self.STEER_RATE:.1f} rad/s")
        if self.generator is not None:
            r = self.SETPOINT_ROBOT
            text += (f";\n           setpoint generator: {r['mass_kg']:g} kg, "
                     f"{r['moi_kgm2']:g} kg·m², Kraken X60 {self.gearing:.2f}:1 per module, "
                     f"{r['current_limit_a']:g} A, wheel COF {r['wheel_cof']:g}, "
                     f"{self.SETPOINT_VOLTS:g} V")
        return text

    def chain(self) -> tuple[str, ...]:
        if self.generator is None:
            return self.CHAIN
        return self.SETPOINT_CHAIN + self.CHAIN[2:]

    def step(self, command: ChassisVelocities) -> None:
        """Run one control period for a field-relative ``command`` (overwritten: it is the
        scratch object the chain works in)."""
        command.toRobotRelativeInto(self.gyro, command)
        kinematics = self.kinematics
        if self.generator is None:
            command.discretizeInto(DT, command)
            kinematics.toSwerveModuleVelocitiesInto(command, self.targets)
            _desaturate_in_place(self.targets, self.max_speed)
        else:
            self._setpoint_step(command)
        # Unrolled on purpose: a ``for`` over the modules would allocate an iterator.
        self._m0.update()
        self._m1.update()
        self._m2.update()
        self._m3.update()
        kinematics.toChassisVelocitiesInto(self.states, self.measured)
        self._record(self.odometry.update(self._gyro_step(), self.positions))

    def _setpoint_step(self, command: ChassisVelocities) -> None:
        """The robot-relative ``command`` → the next setpoint (in place) → module targets."""
        setpoint = self.setpoint
        ns = self._sg_ns
        if ns is not None:
            t0 = _clock_ns()
        self.generator.generateSetpointInto(setpoint, command, DT, setpoint,
                                            self.SETPOINT_VOLTS)
        if ns is not None:
            # Only in the timing pass, where the ints this makes are not counted.
            ns[self._sg_count] = _clock_ns() - t0
            self._sg_count += 1
        self.generated = self.generated + 1.0
        # Limited? The generator's target is the desaturated, discretized command.
        wanted = self.wanted
        self.kinematics.desaturatedDiscretizeInto(command, DT, self.max_speed, wanted)
        got = setpoint.robotRelativeVelocities
        tol = self.LIMITED_TOL
        if (abs(got.vx - wanted.vx) > tol or abs(got.vy - wanted.vy) > tol
                or abs(got.omega - wanted.omega) > tol):
            self.limited = self.limited + 1.0
        # The module targets: copies, since the module model optimizes and scales them.
        modules = setpoint.moduleVelocities
        targets = self.targets
        _copy_module(modules[0], targets[0])
        _copy_module(modules[1], targets[1])
        _copy_module(modules[2], targets[2])
        _copy_module(modules[3], targets[3])

    def results(self) -> dict:
        if self.generator is None:
            return {}
        steps = self.generated
        return {"setpoint_generator": {
            "mode": "default", "steps": int(steps), "limited_steps": int(self.limited),
            "limited_fraction": self.limited / steps if steps else 0.0}}

    def start_timing(self, steps: int) -> None:
        if self.generator is not None:
            self._sg_ns = array("q", bytes(8 * steps))
            self._sg_count = 0

    def timing_results(self) -> dict:
        if self._sg_ns is None or self._sg_count == 0:
            return {}
        return {"setpoint_generator_latency_us": _latency_us(self._sg_ns[:self._sg_count])}

    @classmethod
    def report_rows(cls, r: dict) -> list:
        sg = r.get("setpoint_generator")
        if not sg:
            return []
        rows = [("setpoint generator", "", ""),
                ("  steps limited", f"{sg['limited_steps']} of {sg['steps']}",
                 f"{100 * sg['limited_fraction']:.1f} %: setpoint ≠ desaturated, discretized "
                 "command")]
        lat = r.get("setpoint_generator_latency_us")
        if lat:
            rows.append(("  generateSetpointInto", f"{lat['p50']:.2f} µs",
                         f"p50; p99 {lat['p99']:.2f} µs, max {lat['max']:.2f} µs, mean "
                         f"{lat['mean']:.2f} µs (pass 1)"))
        return rows


def _copy_module(source: SwerveModuleVelocity, target: SwerveModuleVelocity) -> None:
    target.velocity = source.velocity
    target.angle = source.angle                   # the setter copies the value


def _latency_us(samples) -> dict:
    """p50, p99, max and mean of ns samples, in µs."""
    ordered = sorted(samples)
    n = len(ordered)
    return {"p50": ordered[(n - 1) // 2] / 1e3, "p99": ordered[min(n - 1, (99 * n) // 100)] / 1e3,
            "max": ordered[-1] / 1e3, "mean": sum(ordered) / n / 1e3}


class MecanumDrive(Drivetrain):
    """Four-wheel mecanum robot: inverse kinematics, desaturation, a first-order lag per
    wheel, wheel distances in one mutable MecanumDriveWheelPositions, the simulated gyro
    and MecanumDriveOdometry."""

    name = "mecanum"
    ODOMETRY: type = MecanumDriveOdometry
    INPUT = "field-relative joystick"
    CHAIN: tuple[str, ...] = ("toRobotRelativeInto → discretizeInto → toWheelVelocitiesInto → desaturateInPlace",
             "→ wheel lag → MecanumDriveWheelPositions (in place) → "
             "MecanumDriveOdometry.update")
    HALF_LENGTH = 0.3       # m, wheel offset from the robot centre in x
    HALF_WIDTH = 0.25       # m, wheel offset from the robot centre in y
    WHEEL_TAU = 0.05        # s, wheel-speed time constant

    __slots__ = ("kinematics", "targets", "wheels", "positions", "_alpha")

    def __init__(self, max_speed: float) -> None:
        super().__init__(max_speed)
        x, y = self.HALF_LENGTH, self.HALF_WIDTH
        self.kinematics = MecanumDriveKinematics(
            Translation2d(x, y), Translation2d(x, -y), Translation2d(-x, y), Translation2d(-x, -y))
        self.targets = MecanumDriveWheelVelocities()
        self.wheels = MecanumDriveWheelVelocities()      # measured wheel velocities
        self.positions = MecanumDriveWheelPositions()    # encoder distances
        self._alpha = 1.0 - math.exp(-DT / self.WHEEL_TAU)
        self.odometry = MecanumDriveOdometry(self.kinematics, self.gyro, self.positions)
        self.pose = self.odometry.getPose()

    def describe(self) -> str:
        return (f"mecanum, 4 wheels at (±{self.HALF_LENGTH:.2f}, ±{self.HALF_WIDTH:.2f}) m; "
                f"wheel lag τ = {self.WHEEL_TAU * 1000:.0f} ms")

    def step(self, command: ChassisVelocities) -> None:
        """Run one control period for a field-relative ``command`` (overwritten)."""
        p = self._mecanum_step(command, self.measured)
        self._record(self.odometry.update(self._gyro_step(), p))

    def _mecanum_step(self, command: ChassisVelocities,
                      measured: ChassisVelocities) -> MecanumDriveWheelPositions:
        """Command → wheels → wheel lag → encoder distances (returned); the wheels'
        forward kinematics goes into ``measured``."""
        command.toRobotRelativeInto(self.gyro, command)
        command.discretizeInto(DT, command)
        kinematics = self.kinematics
        t = self.targets
        kinematics.toWheelVelocitiesInto(command, t)
        t.desaturateInPlace(self.max_speed)
        w = self.wheels
        p = self.positions
        a = self._alpha
        v = w.frontLeft
        v = v + (t.frontLeft - v) * a
        w.frontLeft = v
        p.frontLeft = p.frontLeft + v * DT
        v = w.frontRight
        v = v + (t.frontRight - v) * a
        w.frontRight = v
        p.frontRight = p.frontRight + v * DT
        v = w.rearLeft
        v = v + (t.rearLeft - v) * a
        w.rearLeft = v
        p.rearLeft = p.rearLeft + v * DT
        v = w.rearRight
        v = v + (t.rearRight - v) * a
        w.rearRight = v
        p.rearRight = p.rearRight + v * DT
        kinematics.toChassisVelocitiesInto(w, measured)
        return p


class DifferentialDrive(Drivetrain):
    """Differential (tank) robot driven arcade-style: the forward and rotation sticks are
    robot-relative vx and omega, the sideways stick is unused (a differential drive cannot
    strafe). Inverse kinematics, desaturation, a first-order lag per side, the simulated
    gyro and DifferentialDriveOdometry."""

    name = "differential"
    ODOMETRY = DifferentialDriveOdometry
    INPUT = "arcade joystick (robot-relative; sideways stick unused)"
    CHAIN = ("vy := 0 → toWheelVelocitiesInto → desaturateInPlace → wheel lag → distances →",
             "DifferentialDriveOdometry.update(gyro, left, right)")
    TRACKWIDTH = 0.6        # m, distance between the left and right wheels
    WHEEL_TAU = 0.05        # s, wheel-speed time constant

    __slots__ = ("kinematics", "targets", "wheels", "left", "right", "_alpha")

    def __init__(self, max_speed: float) -> None:
        super().__init__(max_speed)
        self.kinematics = DifferentialDriveKinematics(self.TRACKWIDTH)
        self.targets = DifferentialDriveWheelVelocities()
        self.wheels = DifferentialDriveWheelVelocities()  # measured wheel velocities
        self.left = 0.0         # encoder distances, m
        self.right = 0.0
        self._alpha = 1.0 - math.exp(-DT / self.WHEEL_TAU)
        self.odometry = DifferentialDriveOdometry(self.gyro, self.left, self.right)
        self.pose = self.odometry.getPose()

    def describe(self) -> str:
        return (f"differential, trackwidth {self.TRACKWIDTH:.2f} m; "
                f"wheel lag τ = {self.WHEEL_TAU * 1000:.0f} ms")

    def step(self, command: ChassisVelocities) -> None:
        """Run one control period for the stick values in ``command`` (overwritten)."""
        command.vy = 0.0        # documents the choice; toWheelVelocitiesInto ignores vy
        kinematics = self.kinematics
        t = self.targets
        kinematics.toWheelVelocitiesInto(command, t)
        t.desaturateInPlace(self.max_speed)
        w = self.wheels
        a = self._alpha
        v = w.left
        v = v + (t.left - v) * a
        w.left = v
        left = self.left + v * DT
        self.left = left
        v = w.right
        v = v + (t.right - v) * a
        w.right = v
        right = self.right + v * DT
        self.right = right
        kinematics.toChassisVelocitiesInto(w, self.measured)
        self._record(self.odometry.update(self._gyro_step(), left, right))


class DeadWheelDrive(MecanumDrive):
    """The mecanum robot of :class:`MecanumDrive`, localized twice: by its drive encoders
    (MecanumDriveOdometry) and by three dead wheels (DeadWheelOdometry on Road Runner's
    standard layout), both with the gyro, against a simulated truth.

    Mecanum rollers slip: the robot moves less than its wheel encoders claim, strafing
    least efficiently. The truth is the drive encoders' forward kinematics scaled by
    ``EFFICIENCY`` (vx, vy, omega); the gyro integrates the true rotation. The dead wheels
    roll on the floor, so they read the true motion (their inverse kinematics applied to
    the true velocity) plus encoder noise of ``NOISE`` m per reading (seeded, so runs are
    reproducible). Both odometries are compared with the true pose every step."""

    name = "deadwheel"
    ODOMETRY = DeadWheelOdometry
    INPUT = "field-relative joystick"
    CHAIN = ("mecanum chain (as --drivetrain mecanum) → wheel slip → true motion →",
             "MecanumDriveOdometry.update(gyro, drive encoders) and",
             "DeadWheelOdometry.update([par0, par1, perp], gyro) → errors against the truth")
    GYRO = ("true heading: the robot's true rotation rate (after slip)",
            "integrated over each step")
    # Road Runner's standard three-wheel layout (peers.md §1.7), inches: parallel wheels
    # at y = ±7.1, perpendicular wheel at x = −3.75.
    PAR_Y = 7.1 * 0.0254
    PERP_X = -3.75 * 0.0254
    EFFICIENCY = (0.97, 0.85, 0.93)     # true / encoder-claimed vx, vy, omega
    TICK = 0.035 * math.pi / 2000       # m per encoder tick: 35 mm wheel, 2000 counts/rev
    NOISE = 2e-5                        # m, extra per-reading noise (1 σ): bumps, scrub
    SEED = 5190

    __slots__ = ("dead", "dead_positions", "wheel_odometry", "wheel_pose", "truth",
                 "_uniform", "_rolled", "_claimed", "_errors")

    def __init__(self, max_speed: float) -> None:
        super().__init__(max_speed)
        self.wheel_odometry = self.odometry          # MecanumDriveOdometry
        self.wheel_pose = self.pose
        self.dead = DeadWheelKinematics([
            Pose2d(0.0, self.PAR_Y, Rotation2d()), Pose2d(0.0, -self.PAR_Y, Rotation2d()),
            Pose2d(self.PERP_X, 0.0, Rotation2d.kCCW_Pi_2)])
        self.dead_positions = [0.0, 0.0, 0.0]        # encoder distances, m (in place)
        self._rolled = array("d", [0.0, 0.0, 0.0])   # true distances the wheels rolled, m
        self.odometry = DeadWheelOdometry(self.dead, self.dead_positions, self.gyro)
        self.pose = self.odometry.getPose()
        self.truth = Pose2d()
        self._claimed = ChassisVelocities()          # the drive encoders' forward kinematics
        # Bound once: binding a method per call would allocate a method object.
        self._uniform = random.Random(self.SEED).random
        # final and max error of the drive-encoder and dead-wheel odometry, m
        self._errors = array("d", [0.0, 0.0, 0.0, 0.0])

    def describe(self) -> str:
        e = self.EFFICIENCY
        return (super().describe() + ";\n           3 dead wheels (Road Runner's standard "
                f"layout): parallel at y = ±{self.PAR_Y:.3f} m,\n           perpendicular "
                f"at x = {self.PERP_X:.3f} m; {self.TICK * 1e3:.3f} mm ticks, noise σ = "
                f"{self.NOISE * 1e3:g} mm;\n           slip: the robot moves {e[0]:g}·vx, "
                f"{e[1]:g}·vy, {e[2]:g}·ω of what the drive encoders claim")

    def _reading(self, i: int, rolled: float) -> float:
        """Wheel i's encoder after rolling ``rolled`` m more: noise, then whole ticks."""
        x = self._rolled[i] + rolled + self.NOISE * _normal(self._uniform)
        self._rolled[i] = x
        return x - math.fmod(x, self.TICK)

    def step(self, command: ChassisVelocities) -> None:
        """Run one control period for a field-relative ``command`` (overwritten)."""
        p = self._mecanum_step(command, self._claimed)
        c = self._claimed
        t = self.measured                  # the truth: what the gyro integrates
        e = self.EFFICIENCY
        t.vx = c.vx * e[0]
        t.vy = c.vy * e[1]
        t.omega = c.omega * e[2]
        gyro = self._gyro_step()
        self.truth = self.truth.exp(Twist2d(t.vx * DT, t.vy * DT, t.omega * DT))
        self.wheel_pose = self.wheel_odometry.update(gyro, p)
        r0, r1, r2 = self.dead.toWheelVelocities(t)
        d = self.dead_positions
        d[0] = self._reading(0, r0 * DT)
        d[1] = self._reading(1, r1 * DT)
        d[2] = self._reading(2, r2 * DT)
        pose = self.odometry.update(d, gyro)
        self._record(pose)
        truth = self.truth
        err = self._errors
        wheel = self.wheel_pose
        _track(err, 0, _hypot(wheel.x - truth.x, wheel.y - truth.y))
        _track(err, 2, _hypot(pose.x - truth.x, pose.y - truth.y))

    def results(self) -> dict:
        e = self._errors
        return {"true_pose": _pose_dict(self.truth),
                "drive_encoder_error_m": {"final": e[0], "max": e[1]},
                "dead_wheel_error_m": {"final": e[2], "max": e[3]}}

    @classmethod
    def report_rows(cls, r: dict) -> list:
        return localization_rows(r["true_pose"], (
            ("drive-encoder error", r["drive_encoder_error_m"], "MecanumDriveOdometry"),
            ("dead-wheel error", r["dead_wheel_error_m"], "DeadWheelOdometry")))



class DiffSwervePodSim:
    """One differential swerve pod: its steering controller, its two motor commands, two
    simulated motors and the plant, and the sensing, all in caller-visible objects.

    Each period runs in two phases, because the drive-level desaturation needs every
    pod's steering rate first:

    * :meth:`steer`: optimize the target against the sensed pod angle and command a
      steering rate proportional to the angle error (``kp`` 1/s, at most ``max_rate``);
    * :meth:`drive`: cosine-scale the (desaturated) target, convert wheel speed and
      steering rate to motor velocities (``toMotorVelocitiesInto``), cut them to the motor
      limit (``desaturateMotorVelocitiesInPlace``: steering kept, wheel slowed first),
      lag each motor (time constant ``tau``), run the plant and read the encoders.

    Plant ("truth"): the differential's own equations on the actual motor speeds,
    integrated here: pod angle += (ω1 + ω2)/R_A·dt, wheel travel += r·(ω1 − ω2)/R_L·dt
    (ω2 of a reversed motor negated). Sensing: the motors' integrated positions through
    ``toModulePositionInto`` (the odometry input) and their speeds through
    ``toModuleVelocitiesInto``. The two routes agree to rounding; quail's position
    formula would not (by a factor 2·R_s²)."""

    __slots__ = ("kin", "target", "command", "module", "position", "truth", "truth_state",
                 "limit", "rate", "peak", "_alpha", "_kp", "_max_rate", "_m1", "_m2",
                 "_p1", "_p2", "_theta", "_dist", "_ra", "_kv", "_s2")

    def __init__(self, kin, target, limit, tau, kp, max_rate):
        self.kin = kin
        self.target = target            # rewritten by inverse kinematics every step
        self.command = DifferentialSwerveMotorVelocities()
        self.module = DifferentialSwerveModuleVelocities()
        self.position = SwerveModulePosition(0.0, Rotation2d())    # from the encoders
        self.truth = SwerveModulePosition(0.0, Rotation2d())       # the plant's own
        self.truth_state = SwerveModuleVelocity(0.0, Rotation2d())
        self.limit = limit
        self.rate = 0.0                 # commanded steering rate, rad/s
        self.peak = 0.0                 # largest |motor command| sent, rad/s
        self._alpha = 1.0 - math.exp(-DT / tau)
        self._kp = kp
        self._max_rate = max_rate
        self._m1 = 0.0                  # actual motor speeds (as the motors read), rad/s
        self._m2 = 0.0
        self._p1 = 0.0                  # encoder positions, rad
        self._p2 = 0.0
        self._theta = 0.0               # plant pod angle, rad
        self._dist = 0.0                # plant wheel travel, m
        self._ra = kin.azimuthGearRatio
        self._kv = kin.wheelGearRatio / kin.wheelRadius
        self._s2 = -1.0 if kin.motor2Inverted else 1.0
        kin.resetModulePosition(Rotation2d(), 0.0, 0.0)     # pod homed at 0 rad

    def steer(self) -> float:
        """Phase 1: the steering-rate command (rad/s) towards the optimized target."""
        current = self.position.angle
        target = self.target
        target.optimizeInPlace(current)
        rate = target.angle.minus(current).getRadians() * self._kp
        limit = self._max_rate
        if rate > limit:
            rate = limit
        elif rate < -limit:
            rate = -limit
        self.rate = rate
        return rate

    def drive(self) -> None:
        """Phase 2: motor commands, motors, plant and encoders for one period."""
        kin = self.kin
        target = self.target
        target.cosineScaleInPlace(self.position.angle)
        command = self.command
        kin.toMotorVelocitiesInto(target.velocity, self.rate, command)
        kin.desaturateMotorVelocitiesInPlace(command, self.limit)
        c1 = command.motor1
        c2 = command.motor2
        peak = abs(c1) if abs(c1) >= abs(c2) else abs(c2)
        if peak > self.peak:
            self.peak = peak
        a = self._alpha
        m1 = self._m1
        m1 = m1 + (c1 - m1) * a
        self._m1 = m1
        m2 = self._m2
        m2 = m2 + (c2 - m2) * a
        self._m2 = m2
        # Plant: the differential itself, in the equations' sign convention.
        w2 = self._s2 * m2
        theta = self._theta + (m1 + w2) / self._ra * DT
        self._theta = theta
        wheel = (m1 - w2) / self._kv
        self._dist = self._dist + wheel * DT
        truth = self.truth
        angle = _from_radians(theta)
        truth.distance = self._dist
        truth.angle = angle
        state = self.truth_state
        state.velocity = wheel
        state.angle = angle
        # Encoders: integrated motor positions, converted by drivekin.
        self._p1 = self._p1 + m1 * DT
        self._p2 = self._p2 + m2 * DT
        kin.toModulePositionInto(self._p1, self._p2, self.position)
        kin.toModuleVelocitiesInto(m1, m2, self.module)


class DiffSwerveDrive(Drivetrain):
    """Four-pod swerve robot whose pods are differential swerves: inverse kinematics,
    per-pod steering control, drive-level motor-limit desaturation (one factor for every
    wheel), motor velocities with per-pod desaturation, simulated motors and plant,
    module positions from motor positions, SwerveDriveOdometry — compared with the
    plant's own path (same gyro, truth module positions)."""

    name = "diffswerve"
    ODOMETRY = SwerveDriveOdometry
    INPUT = "field-relative joystick"
    GYRO = ("true heading: the simulated pods' own motion (toChassisVelocitiesInto",
            "of the plant's module velocities) integrated over each step")
    CHAIN = ("toRobotRelativeInto → discretizeInto → toSwerveModuleVelocitiesInto → per pod:",
             "optimizeInPlace, steering rate → desaturateModuleVelocitiesInPlace (motor limit,",
             "one factor) → cosineScaleInPlace → toMotorVelocitiesInto → "
             "desaturateMotorVelocitiesInPlace",
             "→ motor lag, plant → toModulePositionInto (encoders) → "
             "SwerveDriveOdometry.update(gyro, positions)")
    HALF_TRACK = 0.3        # m, pod offset from the robot centre in x and y
    AZIMUTH_RATIO = 4.0     # motor turns per pod turn
    WHEEL_RATIO = 14.0      # motor turns per wheel turn
    WHEEL_RADIUS = 0.0508   # m (4 in wheel)
    MOTOR_TAU = 0.03        # s, motor-speed time constant
    STEER_KP = 20.0         # 1/s, steering rate per rad of angle error
    STEER_RATE = 4.0 * math.pi   # rad/s, steering rate limit

    __slots__ = ("kinematics", "pod", "targets", "rates", "positions", "truths",
                 "truth_states", "truth_odometry", "motor_limit", "min_factor", "max_error",
                 "max_angle_error", "_m0", "_m1", "_m2", "_m3")

    DETAILS = (
        ("motor_limit_radps", "  motor limit", "{:.1f} rad/s", "= --max-speed of pure driving"),
        ("peak_motor_command_radps", "  peak motor command", "{:.1f} rad/s",
         "after both desaturations"),
        ("min_drive_factor", "  min drive-level factor", "{:.4f}",
         "desaturateModuleVelocitiesInPlace (1 = never scaled)"),
        ("max_position_error_m", "  odometry vs truth", "{:.2e} m",
         "largest position difference, any step"),
        ("max_pod_angle_error_rad", "  pod angle vs truth", "{:.2e} rad",
         "largest, any pod and step"),
    )

    def __init__(self, max_speed: float) -> None:
        super().__init__(max_speed)
        h = self.HALF_TRACK
        self.kinematics = SwerveDriveKinematics(
            Translation2d(h, h), Translation2d(h, -h), Translation2d(-h, h), Translation2d(-h, -h))
        pods = [DifferentialSwerveModuleKinematics(
            self.AZIMUTH_RATIO, self.WHEEL_RATIO, self.WHEEL_RADIUS, motor2Inverted=True)
            for _ in range(4)]
        self.pod = pods[0]          # the drive-level desaturation needs one of the (equal) pods
        # Pure driving at max_speed puts both motors exactly on the limit.
        self.motor_limit = 0.5 * self.WHEEL_RATIO / self.WHEEL_RADIUS * self.max_speed
        self.targets = [SwerveModuleVelocity() for _ in range(4)]
        self.rates = [0.0, 0.0, 0.0, 0.0]
        sims = [DiffSwervePodSim(k, t, self.motor_limit, self.MOTOR_TAU, self.STEER_KP,
                                 self.STEER_RATE) for k, t in zip(pods, self.targets)]
        self._m0, self._m1, self._m2, self._m3 = sims
        self.positions = [m.position for m in sims]
        self.truths = [m.truth for m in sims]
        self.truth_states = [m.truth_state for m in sims]
        self.min_factor = 1.0
        self.max_error = 0.0
        self.max_angle_error = 0.0
        self.odometry = SwerveDriveOdometry(self.kinematics, self.gyro, self.positions)
        self.truth_odometry = SwerveDriveOdometry(self.kinematics, self.gyro, self.truths)
        self.pose = self.odometry.getPose()

    def describe(self) -> str:
        h = self.HALF_TRACK
        return (f"differential swerve, 4 pods at (±{h:.2f}, ±{h:.2f}) m; R_A "
                f"{self.AZIMUTH_RATIO:g}, R_L {self.WHEEL_RATIO:g}, wheel radius "
                f"{self.WHEEL_RADIUS:g} m, motor 2 reversed; motor limit "
                f"{self.motor_limit:.0f} rad/s, motor lag τ = {self.MOTOR_TAU * 1000:.0f} ms")

    def results(self) -> dict:
        worst = self._m0.peak
        for m in (self._m1, self._m2, self._m3):
            worst = m.peak if m.peak > worst else worst
        return {"diffswerve": {
            "motor_limit_radps": self.motor_limit, "peak_motor_command_radps": worst,
            "min_drive_factor": self.min_factor, "max_position_error_m": self.max_error,
            "max_pod_angle_error_rad": self.max_angle_error}}

    @classmethod
    def report_rows(cls, r: dict) -> list:
        return [("differential swerve", "", "")] + [
            (label, fmt.format(r["diffswerve"][key]), note)
            for key, label, fmt, note in cls.DETAILS]

    def _angle_error(self, pod) -> None:
        e = abs(pod.position.angle.minus(pod.truth.angle).getRadians())
        if e > self.max_angle_error:
            self.max_angle_error = e

    def step(self, command: ChassisVelocities) -> None:
        """Run one control period for a field-relative ``command`` (overwritten)."""
        command.toRobotRelativeInto(self.gyro, command)
        command.discretizeInto(DT, command)
        kinematics = self.kinematics
        kinematics.toSwerveModuleVelocitiesInto(command, self.targets)
        # Unrolled on purpose: a ``for`` over the pods would allocate an iterator.
        rates = self.rates
        rates[0] = self._m0.steer()
        rates[1] = self._m1.steer()
        rates[2] = self._m2.steer()
        rates[3] = self._m3.steer()
        factor = self.pod.desaturateModuleVelocitiesInPlace(self.targets, rates,
                                                             self.motor_limit)
        if factor < self.min_factor:
            self.min_factor = factor
        self._m0.drive()
        self._m1.drive()
        self._m2.drive()
        self._m3.drive()
        self._angle_error(self._m0)
        self._angle_error(self._m1)
        self._angle_error(self._m2)
        self._angle_error(self._m3)
        kinematics.toChassisVelocitiesInto(self.truth_states, self.measured)
        gyro = self._gyro_step()
        truth = self.truth_odometry.update(gyro, self.truths)
        self._record(self.odometry.update(gyro, self.positions))
        error = _hypot(self.pose.x - truth.x, self.pose.y - truth.y)
        if error > self.max_error:
            self.max_error = error



_swerve_step = SwerveDrive.step


class VisionSwerveDrive(SwerveDrive):
    """The swerve robot of :class:`SwerveDrive` whose odometry drifts (its wheels are worn:
    the robot moves ``EFFICIENCY`` of what the encoders claim), localized twice against
    a simulated truth: by SwerveDriveOdometry alone and by SwerveDrivePoseEstimator fed
    with simulated AprilTag poses (``--vision``).

    The camera sees the true pose every ``VISION_EVERY`` steps, with ``LATENCY`` s of
    delay and Gaussian noise (``NOISE_XY`` m, ``NOISE_THETA`` rad, seeded); the
    measurement is added with its capture timestamp. Time is the simulation's (steps ×
    20 ms), passed with ``updateWithTime``."""

    name = "swerve"
    ODOMETRY = SwerveDrivePoseEstimator
    CHAIN = SwerveDrive.CHAIN[:2] + (
        "cosineScaleInPlace, wheel lag → SwerveDriveOdometry.update (odometry only) and",
        "SwerveDrivePoseEstimator.updateWithTime + addVisionMeasurement (camera)")
    GYRO = ("true heading: the robot's true rotation rate integrated over each step", "")
    EFFICIENCY = 0.95                   # true / encoder-claimed translation (worn wheels)
    VISION_EVERY = 2                    # steps between camera frames (25 Hz)
    LATENCY = 0.06                      # s from capture to addVisionMeasurement (3 steps)
    NOISE_XY = 0.03                     # m, 1 σ
    NOISE_THETA = 0.02                  # rad, 1 σ
    SEED = 4915

    __slots__ = ("estimator", "truth", "_past", "_uniform", "_step_index", "_t", "_errors",
                 "_est_ns", "_est_count")

    def __init__(self, max_speed: float, setpoint_generator: bool = False) -> None:
        super().__init__(max_speed, setpoint_generator)
        self.estimator = SwerveDrivePoseEstimator(
            self.kinematics, self.gyro, self.positions, Pose2d(),
            (0.1, 0.1, 0.1), (0.5, 0.5, 0.5))
        self.truth = Pose2d()
        lag = round(self.LATENCY / DT)
        self._past = [Pose2d()] * (lag + 1)      # true poses of the last lag + 1 steps
        self._uniform = random.Random(self.SEED).random
        self._step_index = 0
        self._t = 0.0
        # final, max and summed error of the odometry-only and the estimated pose, m
        self._errors = array("d", [0.0] * 6)
        self._est_ns: array | None = None       # estimator time per step (timing pass)
        self._est_count = 0

    def describe(self) -> str:
        return (super().describe() + f";\n           worn wheels: the robot moves "
                f"{self.EFFICIENCY:g} of what the encoders claim; camera every "
                f"{self.VISION_EVERY * DT * 1000:.0f} ms,\n           {self.LATENCY * 1000:.0f} ms "
                f"latency, noise σ = {self.NOISE_XY * 100:g} cm, "
                f"{math.degrees(self.NOISE_THETA):.1f}°")

    def step(self, command: ChassisVelocities) -> None:
        """Run one control period for a field-relative ``command`` (overwritten)."""
        # Odometry only; self.measured = the encoders' claim. (super() would allocate.)
        _swerve_step(self, command)
        m = self.measured
        e = self.EFFICIENCY
        # The truth: the claimed motion shrunk by the wheels' wear (the gyro is exact).
        self.truth = self.truth.exp(Twist2d(m.vx * DT * e, m.vy * DT * e, m.omega * DT))
        t = self._t + DT
        self._t = t
        past = self._past
        i = self._step_index
        lag = len(past) - 1
        past[i % (lag + 1)] = self.truth
        frame = None                    # this step's camera measurement, if any
        if i >= lag and i % self.VISION_EVERY == 0:
            seen = past[(i - lag) % (lag + 1)]
            u = self._uniform
            frame = Pose2d(seen.x + self.NOISE_XY * _normal(u),
                           seen.y + self.NOISE_XY * _normal(u),
                           seen.getRotation().plus(_from_radians(self.NOISE_THETA * _normal(u))))
        ns = self._est_ns
        if ns is not None:
            t0 = _clock_ns()
        estimate = self.estimator.updateWithTime(t, self.gyro, self.positions)
        if frame is not None:
            self.estimator.addVisionMeasurement(frame, t - lag * DT)
            estimate = self.estimator.getEstimatedPosition()
        if ns is not None:
            # Only in the timing pass, where the ints this makes are not counted.
            ns[self._est_count] = _clock_ns() - t0
            self._est_count += 1
        self._step_index = i + 1 if i < 200 else i + 1 - self.VISION_EVERY * (lag + 1)
        truth = self.truth
        err = self._errors
        pose = self.pose
        _track(err, 0, _hypot(pose.x - truth.x, pose.y - truth.y))
        _track(err, 2, _hypot(estimate.x - truth.x, estimate.y - truth.y))
        err[4] += err[0]
        err[5] += err[2]

    def results(self) -> dict:
        e = self._errors
        n = max(1, round(self._t / DT))
        return {**super().results(),
                "vision": True, "true_pose": _pose_dict(self.truth),
                "estimated_pose": _pose_dict(self.estimator.getEstimatedPosition()),
                "odometry_error_m": {"final": e[0], "max": e[1], "mean": e[4] / n},
                "estimator_error_m": {"final": e[2], "max": e[3], "mean": e[5] / n}}

    def start_timing(self, steps: int) -> None:
        super().start_timing(steps)
        self._est_ns = array("q", bytes(8 * steps))
        self._est_count = 0

    def timing_results(self) -> dict:
        out = super().timing_results()
        if self._est_ns is None or self._est_count == 0:
            return out
        return {**out, "estimator_latency_us": _latency_us(self._est_ns[:self._est_count])}

    @classmethod
    def report_rows(cls, r: dict) -> list:
        rows = localization_rows(r["true_pose"], (
            ("odometry-only error", r["odometry_error_m"], "SwerveDriveOdometry"),
            ("estimator error", r["estimator_error_m"], "SwerveDrivePoseEstimator + vision")))
        lat = r.get("estimator_latency_us")
        if lat:
            rows.append(("  estimator per step", f"{lat['p50']:.2f} µs",
                         f"p50; p99 {lat['p99']:.2f} µs, max {lat['max']:.2f} µs "
                         "(updateWithTime + addVisionMeasurement, pass 1)"))
        return rows + super().report_rows(r)


DRIVETRAINS = {cls.name: cls for cls in (SwerveDrive, MecanumDrive, DifferentialDrive,
                                         DeadWheelDrive, DiffSwerveDrive)}


VISION_DRIVETRAINS = {"swerve": VisionSwerveDrive}


SETPOINT_DRIVETRAINS = tuple(name for name, cls in DRIVETRAINS.items() if cls.SETPOINT_GENERATOR)


def drivetrain_class(name: str, vision: bool = False) -> type[Drivetrain]:
    """The simulated drivetrain for ``--drivetrain name`` (with ``--vision``)."""
    if vision:
        if name not in VISION_DRIVETRAINS:
            raise ValueError(f"--vision is simulated for {', '.join(VISION_DRIVETRAINS)} only")
        return VISION_DRIVETRAINS[name]
    return DRIVETRAINS[name]


def make_drivetrain(name: str, max_speed: float, vision: bool = False,
                    setpoint_generator: bool = False) -> Drivetrain:
    """A new simulated drivetrain for ``--drivetrain name`` (with ``--vision``,
    ``--setpoint-generator``)."""
    cls = drivetrain_class(name, vision)
    if not setpoint_generator:
        return cls(max_speed)
    if not cls.SETPOINT_GENERATOR:
        raise ValueError(f"--setpoint-generator is simulated for "
                         f"{', '.join(SETPOINT_DRIVETRAINS)} only")
    return cls(max_speed, setpoint_generator=True)
