"""The demo's simulated differential swerve drive: each pod's two motors turn into wheel
speed and module angle."""
from __future__ import annotations

import math

from drivekin import (ChassisVelocities, DifferentialSwerveModuleKinematics,
                      DifferentialSwerveModuleVelocities, DifferentialSwerveMotorVelocities,
                      Rotation2d, SwerveDriveKinematics, SwerveDriveOdometry,
                      SwerveModulePosition, SwerveModuleVelocity, Translation2d)
from drivekin.app.demo.script import DT
from drivekin.app.demo.sim import Drivetrain, _from_radians, _hypot

# The hot-path rule of sim.py holds for everything below.


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
            self.AZIMUTH_RATIO, self.WHEEL_RATIO, self.WHEEL_RADIUS, motor2_inverted=True)
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
