"""The demo's simulated drivetrains with fixed wheels: mecanum, differential, and a
mecanum drive tracked by dead wheels."""
from __future__ import annotations

import math
import random
from array import array

from drivekin import (ChassisVelocities, DeadWheelKinematics, DeadWheelOdometry,
                      DifferentialDriveKinematics, DifferentialDriveOdometry,
                      DifferentialDriveWheelVelocities, MecanumDriveKinematics,
                      MecanumDriveOdometry, MecanumDriveWheelPositions,
                      MecanumDriveWheelVelocities, Pose2d, Rotation2d, Translation2d,
                      Twist2d)
from drivekin.app.demo.script import DT
from drivekin.app.demo.sim import Drivetrain, _hypot, _normal, _pose_dict, _track, localization_rows

# The hot-path rule of sim.py holds for everything below.


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
