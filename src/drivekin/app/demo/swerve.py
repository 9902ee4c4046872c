"""The demo's simulated swerve drive: its modules, the drive (with the setpoint generator
optionally) and the drive with vision measurements fused by a pose estimator."""
from __future__ import annotations

import math
import random
from array import array

from drivekin import (ChassisVelocities, DCMotor, DriveFeedforwards, ModuleConfig, Pose2d,
                      RobotConfig, Rotation2d, SwerveDriveKinematics, SwerveDriveOdometry,
                      SwerveDrivePoseEstimator, SwerveModulePosition, SwerveModuleVelocity,
                      SwerveSetpoint, SwerveSetpointGenerator, Translation2d, Twist2d)
from drivekin.app.demo.script import DT
from drivekin.app.demo.sim import (Drivetrain, _clock_ns, _desaturate_in_place, _from_radians,
                                   _hypot, _normal, _pose_dict, _track, localization_rows)

# The hot-path rule of sim.py holds for everything below.


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
