"""Differential test: ``SwerveSetpointGenerator(config, maxSteer, compatibility="pathplanner")``
against robotpy-pathplannerlib 2026.1.2's ``pathplannerlib.util.swerve.SwerveSetpointGenerator``,
the Python port of PathPlannerLib Java 2026's generator.

The oracle, corrected to behave as PathPlannerLib Java. The Python port discards two results
that Java's in-place calls keep; both are corrected here, in this module only (a module-scoped
fixture patches two names of ``pathplannerlib.util.swerve`` and restores them afterwards):

* ``ret_speeds.discretize(ret_speeds, dt)``: robotpy's ``ChassisSpeeds.discretize`` is static
  and returns a new object, so the output is never discretized. The module's ``ChassisSpeeds``
  becomes a subclass whose ``discretize(self, other, dt)`` writes
  ``wpimath.kinematics.ChassisSpeeds.discretize(other, dt)`` into ``self`` (Java:
  ``retSpeeds = retSpeeds.discretize(dt)``).
* ``SwerveDrive4Kinematics.desaturateWheelSpeeds(desired_module_states, maxSpeed)``: robotpy
  returns the desaturated states as a new tuple and leaves its argument alone, so the desired
  velocities are never desaturated. The module's ``SwerveDrive4Kinematics`` (used there only)
  becomes a shim whose ``desaturateWheelSpeeds`` copies robotpy's result back into the states
  (Java desaturates the array in place).

Field mapping, oracle -> drivekin:
``SwerveSetpoint(robot_relative_speeds, module_states, feedforwards)`` ->
``SwerveSetpoint(robotRelativeVelocities, moduleVelocities, feedforwards)``;
``ChassisSpeeds(vx, vy, omega)`` -> ``ChassisVelocities(vx, vy, omega)``;
``SwerveModuleState(speed, angle)`` -> ``SwerveModuleVelocity(velocity, angle)``;
``DriveFeedforwards`` ``accelerationsMPS`` -> ``accelerationsMPSSq``, ``forcesNewtons`` ->
``linearForcesNewtons``, ``torqueCurrentsAmps``, ``robotRelativeForcesXNewtons``,
``robotRelativeForcesYNewtons`` -> same names; ``PathConstraints`` (same argument order);
``ModuleConfig`` / ``RobotConfig`` (same arguments), ``wpimath.system.plant.DCMotor.krakenX60(n)``
-> ``drivekin.DCMotor.getKrakenX60(n)`` (and NEO, falcon500, CIM, krakenX60FOC).
The oracle reads its brownout voltage from ``wpilib.RobotController.getBrownoutVoltage()``
(6.75 V in simulation); drivekin is given the same value explicitly. The input voltage is
always passed explicitly (the oracle would otherwise read the simulated battery).

How the runs are fed. Each step gives both implementations the same previous setpoint:
either the oracle runs in closed loop and drivekin is fed the oracle's previous output
(converted to drivekin's types), or drivekin runs in closed loop (its own outputs, in its own
representation of every module state, sign and angle, are its next inputs) and the oracle
is fed drivekin's; the random runs alternate, the deliberate scenarios run both ways. Both
generator objects, and so both heading memories, live through the whole run. Two
implementations each fed their own outputs cannot be compared to 1e-9: with the voltage and
dt changing every step PathPlanner's generator can settle into a period-2 oscillation
(module accelerations alternating in sign), and with a module near zero speed its drive
limit root (``findDriveMaxS``) amplifies a difference by 100-200x per step, so runs one ulp
apart at the start part by 1e-9 within a few steps (seen between the oracle and drivekin,
and between the oracle and an independent Python model of the generator).

Tolerance: absolute 1e-9 * max(1, |oracle value|) on every compared number (speeds, the unit
vectors of the module angles, and the five feedforward arrays); where that fails, drivekin's
numbers must lie within the oracle's own spread over ulp-nudged copies of the step (see
``Pair``: PathPlanner's discretize is ill-conditioned for small omega * dt), which the random
runs must need on at most 1 % of their steps.
"""
from __future__ import annotations

import math
import random

import numpy as np
import pytest

pytest.importorskip("pathplannerlib")
wk = pytest.importorskip("wpimath.kinematics")
wg = pytest.importorskip("wpimath.geometry")
plant = pytest.importorskip("wpimath.system.plant")

import pathplannerlib.util.swerve as ppswerve  # noqa: E402
from pathplannerlib.config import ModuleConfig as PPModuleConfig  # noqa: E402
from pathplannerlib.config import RobotConfig as PPRobotConfig  # noqa: E402
from pathplannerlib.path import PathConstraints as PPPathConstraints  # noqa: E402
from pathplannerlib.util import DriveFeedforwards as PPDriveFeedforwards  # noqa: E402
from wpilib import RobotController  # noqa: E402

import drivekin as dk  # noqa: E402
from drivekin import batch as dkbatch  # noqa: E402

TOL = 1e-9

# oracle DriveFeedforwards field -> drivekin DriveFeedforwards field
FF_FIELDS = (
    ("accelerationsMPS", "accelerationsMPSSq"),
    ("forcesNewtons", "linearForcesNewtons"),
    ("torqueCurrentsAmps", "torqueCurrentsAmps"),
    ("robotRelativeForcesXNewtons", "robotRelativeForcesXNewtons"),
    ("robotRelativeForcesYNewtons", "robotRelativeForcesYNewtons"),
)

# motor name -> (wpimath DCMotor factory, drivekin DCMotor factory)
MOTORS = {
    "krakenX60": ("krakenX60", "getKrakenX60"),
    "NEO": ("NEO", "getNEO"),
    "falcon500": ("falcon500", "getFalcon500"),
    "CIM": ("CIM", "getCIM"),
    "krakenX60FOC": ("krakenX60FOC", "getKrakenX60Foc"),
}
# Not the NEO Vortex: robotpy-wpimath 2026's has a free current of 3.615 A, drivekin's
# (WPILib 2027's) 3.6 A.


# ---------------------------------------------------------------------------------------
# The corrected oracle


class _DiscretizingChassisSpeeds(wk.ChassisSpeeds):
    """robotpy's ChassisSpeeds whose ``discretize(other, dt)`` updates ``self`` in place,
    so that the port's ``ret_speeds.discretize(ret_speeds, dt)`` does what Java's
    ``retSpeeds = retSpeeds.discretize(dt)`` does."""

    def discretize(self, other, dt):  # noqa: D401 - shadows the static overloads
        d = wk.ChassisSpeeds.discretize(other, dt)
        self.vx, self.vy, self.omega = d.vx, d.vy, d.omega


class _InPlaceDesaturate:
    """Stand-in for the name ``SwerveDrive4Kinematics`` in pathplannerlib.util.swerve, where
    it is used only for ``desaturateWheelSpeeds``: robotpy's result is copied back into the
    states, as Java's in-place ``SwerveDriveKinematics.desaturateWheelSpeeds`` does."""

    @staticmethod
    def desaturateWheelSpeeds(states, attainableMaxSpeed):
        result = wk.SwerveDrive4Kinematics.desaturateWheelSpeeds(states, attainableMaxSpeed)
        for state, desaturated in zip(states, result):
            state.speed = desaturated.speed


@pytest.fixture(scope="module", autouse=True)
def corrected_oracle():
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(ppswerve, "ChassisSpeeds", _DiscretizingChassisSpeeds)
        mp.setattr(ppswerve, "SwerveDrive4Kinematics", _InPlaceDesaturate)
        yield
    assert ppswerve.ChassisSpeeds is wk.ChassisSpeeds


def test_the_corrections_take_effect():
    """The two corrections change the oracle's output where they should: saturated desired
    speeds are desaturated, and a turning output is discretized."""
    robot = Robot.square()
    gen = robot.oracle_generator()
    desired = wk.ChassisSpeeds(30.0, 0.0, 25.0)      # far above the module limit
    sp = oracle_zero(robot, 0.3)
    for _ in range(400):
        sp = gen.generateSetpoint(sp, desired, 0.02, 12.0, None)
    top = max(abs(s.speed) for s in sp.module_states)
    # desaturated target, discretized: the fastest module is at the limit (the discretize
    # correction makes it a little faster than the continuous-time desaturated speeds)
    assert top == pytest.approx(robot.vmax, rel=0.05)
    target = wk.SwerveDrive4Kinematics.desaturateWheelSpeeds(
        robot.oracle_config().toSwerveModuleStates(desired), robot.vmax)
    cont = robot.oracle_config().toChassisSpeeds(target)
    disc = wk.ChassisSpeeds.discretize(cont, 0.02)
    got = sp.robot_relative_speeds
    assert (got.vx, got.vy, got.omega) == pytest.approx((disc.vx, disc.vy, disc.omega), abs=1e-9)
    assert abs(disc.vy - cont.vy) > 1e-3               # the discretize is visible


# ---------------------------------------------------------------------------------------
# Robots


class Robot:
    """One robot's parameters, and the two generators built from them."""

    def __init__(self, mass, moi, radius, vmax, cof, motor, gearing, ilim, nmotors,
                 offsets, max_steer):
        self.mass, self.moi, self.radius, self.vmax, self.cof = mass, moi, radius, vmax, cof
        self.motor, self.gearing, self.ilim, self.nmotors = motor, gearing, ilim, nmotors
        self.offsets, self.max_steer = list(offsets), max_steer

    def __repr__(self):
        return (f"Robot(mass={self.mass!r}, moi={self.moi!r}, radius={self.radius!r}, "
                f"vmax={self.vmax!r}, cof={self.cof!r}, motor={self.motor!r}, "
                f"gearing={self.gearing!r}, ilim={self.ilim!r}, nmotors={self.nmotors!r}, "
                f"offsets={self.offsets!r}, max_steer={self.max_steer!r})")

    @classmethod
    def square(cls, max_steer=2 * math.pi):
        h = 0.29
        return cls(55.0, 5.5, 0.0508, 4.3, 1.2, "krakenX60", 6.75, 60.0, 1,
                   [(h, h), (h, -h), (-h, h), (-h, -h)], max_steer)

    @classmethod
    def random(cls, rng):
        motor = rng.choice(sorted(MOTORS))
        gearing = rng.uniform(5.0, 8.5)
        radius = rng.uniform(0.038, 0.0635)
        free = getattr(plant.DCMotor, MOTORS[motor][0])(1).freeSpeed / gearing * radius
        kind = rng.randrange(3)
        if kind == 0:            # rectangle about the centre
            hx, hy = rng.uniform(0.15, 0.45), rng.uniform(0.15, 0.45)
            offsets = [(hx, hy), (hx, -hy), (-hx, hy), (-hx, -hy)]
        elif kind == 1:          # rectangle off the centre
            hx, hy = rng.uniform(0.15, 0.45), rng.uniform(0.15, 0.45)
            cx, cy = rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1)
            offsets = [(cx + hx, cy + hy), (cx + hx, cy - hy), (cx - hx, cy + hy),
                       (cx - hx, cy - hy)]
        else:                    # any four modules, none at the centre
            offsets = []
            while len(offsets) < 4:
                x, y = rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)
                if math.hypot(x, y) > 0.1 and all(math.hypot(x - a, y - b) > 0.15
                                                  for a, b in offsets):
                    offsets.append((x, y))
        ilim = rng.uniform(30.0, 90.0)
        stall = getattr(plant.DCMotor, MOTORS[motor][0])(1).stallCurrent
        # PathPlanner's torque loss is the torque of the current drawn at vmax (12 V, capped
        # by the limit): keep it under the limit, or the robot cannot start at all
        low = max(0.8, 1.0 - 0.6 * ilim / stall)
        return cls(mass=rng.uniform(25.0, 75.0), moi=rng.uniform(2.0, 9.0), radius=radius,
                   vmax=free * rng.uniform(low, 0.98), cof=rng.uniform(0.7, 1.6),
                   motor=motor, gearing=gearing, ilim=ilim,
                   nmotors=rng.choice((1, 1, 1, 2)), offsets=offsets,
                   max_steer=rng.choice((rng.uniform(1.5, 4.0) * math.pi,
                                         rng.uniform(4.0, 12.0) * math.pi)))

    def oracle_config(self):
        motor = getattr(plant.DCMotor, MOTORS[self.motor][0])(self.nmotors)
        mc = PPModuleConfig(self.radius, self.vmax, self.cof,
                            motor.withReduction(self.gearing), self.ilim, self.nmotors)
        return PPRobotConfig(self.mass, self.moi, mc,
                             [wg.Translation2d(x, y) for x, y in self.offsets])

    def drivekin_config(self):
        motor = getattr(dk.DCMotor, MOTORS[self.motor][1])(self.nmotors)
        mc = dk.ModuleConfig(self.radius, self.vmax, self.cof,
                             motor.withReduction(self.gearing), self.ilim, self.nmotors)
        return dk.RobotConfig(self.mass, self.moi, mc,
                              [dk.Translation2d(x, y) for x, y in self.offsets])

    def oracle_generator(self):
        # a fresh RobotConfig per generator: its kinematics object holds the heading memory
        return ppswerve.SwerveSetpointGenerator(self.oracle_config(), self.max_steer)

    def drivekin_generator(self):
        return dk.SwerveSetpointGenerator(self.drivekin_config(), self.max_steer,
                                          brownoutVoltage=RobotController.getBrownoutVoltage(),
                                          compatibility="pathplanner")


def oracle_zero(robot, angle=0.0):
    return ppswerve.SwerveSetpoint(
        wk.ChassisSpeeds(),
        [wk.SwerveModuleState(0.0, wg.Rotation2d(angle)) for _ in robot.offsets],
        PPDriveFeedforwards.zeros(4))


def drivekin_zero(robot, angle=0.0):
    return dk.SwerveSetpoint(
        dk.ChassisVelocities(),
        [dk.SwerveModuleVelocity(0.0, dk.Rotation2d(angle)) for _ in robot.offsets],
        dk.DriveFeedforwards.zeros(4))


# ---------------------------------------------------------------------------------------
# One step: the same inputs to both, compared


class Step:
    """One call's inputs: desired (vx, vy, omega), dt, input voltage and constraints
    (None, or the 4-tuple of PathConstraints' limits)."""

    __slots__ = ("desired", "dt", "voltage", "limits")

    def __init__(self, desired, dt, voltage, limits=None):
        self.desired, self.dt, self.voltage, self.limits = tuple(desired), dt, voltage, limits

    def __repr__(self):
        return (f"Step({self.desired!r}, dt={self.dt!r}, voltage={self.voltage!r}, "
                f"limits={self.limits!r})")


def _tol(a):
    return TOL * max(1.0, abs(a))


def oracle_values(sp):
    """(name, value) of every compared number of an oracle setpoint."""
    s = sp.robot_relative_speeds
    out = [("vx", s.vx), ("vy", s.vy), ("omega", s.omega)]
    for i, m in enumerate(sp.module_states):
        out += [(f"module {i} speed", m.speed), (f"module {i} cos", m.angle.cos()),
                (f"module {i} sin", m.angle.sin())]
    for oname, dname in FF_FIELDS:
        out += [(f"{dname}[{i}]", v) for i, v in enumerate(getattr(sp.feedforwards, oname))]
    return out


def drivekin_values(sp):
    """The same numbers of a drivekin setpoint, in the same order."""
    s = sp.robotRelativeVelocities
    out = [("vx", s.vx), ("vy", s.vy), ("omega", s.omega)]
    for i, m in enumerate(sp.moduleVelocities):
        out += [(f"module {i} speed", m.velocity), (f"module {i} cos", m.angle.getCos()),
                (f"module {i} sin", m.angle.getSin())]
    for _, dname in FF_FIELDS:
        out += [(f"{dname}[{i}]", v) for i, v in enumerate(getattr(sp.feedforwards, dname))]
    return out


def describe_oracle(sp):
    s = sp.robot_relative_speeds
    mods = [(m.speed, m.angle.radians()) for m in sp.module_states]
    ff = {name: list(getattr(sp.feedforwards, name)) for name, _ in FF_FIELDS}
    return f"speeds=({s.vx!r}, {s.vy!r}, {s.omega!r}) modules={mods!r} ff={ff!r}"


def describe_drivekin(sp):
    s = sp.robotRelativeVelocities
    mods = [(m.velocity, m.angle.getRadians()) for m in sp.moduleVelocities]
    ff = {name: list(getattr(sp.feedforwards, name)) for _, name in FF_FIELDS}
    return f"velocities=({s.vx!r}, {s.vy!r}, {s.omega!r}) modules={mods!r} ff={ff!r}"


def mismatches(expected, got):
    """Names where the drivekin values ``got`` differ from the oracle values ``expected``
    (lists of (name, value) pairs) by more than the tolerance."""
    if [n for n, _ in expected] != [n for n, _ in got]:
        return ["the fields (number of modules?)"]
    return [n for (n, a), (_, b) in zip(expected, got) if not abs(a - b) <= _tol(a)]


def to_drivekin(sp):
    """The oracle's setpoint as a drivekin SwerveSetpoint."""
    s = sp.robot_relative_speeds
    ff = sp.feedforwards
    return dk.SwerveSetpoint(
        dk.ChassisVelocities(s.vx, s.vy, s.omega),
        [dk.SwerveModuleVelocity(m.speed, dk.Rotation2d(m.angle.cos(), m.angle.sin()))
         for m in sp.module_states],
        dk.DriveFeedforwards(*[list(getattr(ff, name)) for name, _ in FF_FIELDS]))


def to_oracle(sp):
    """drivekin's setpoint as an oracle SwerveSetpoint."""
    s = sp.robotRelativeVelocities
    ff = sp.feedforwards
    return ppswerve.SwerveSetpoint(
        wk.ChassisSpeeds(s.vx, s.vy, s.omega),
        [wk.SwerveModuleState(m.velocity, wg.Rotation2d(m.angle.getCos(), m.angle.getSin()))
         for m in sp.moduleVelocities],
        PPDriveFeedforwards(*[list(getattr(ff, name)) for _, name in FF_FIELDS]))


def _nudge(rng, v):
    """v moved by up to 16 ulps (relative 2**-52 steps)."""
    return v * (1.0 + rng.randint(-16, 16) * 2.0 ** -52)


class Oracle:
    """A corrected oracle generator whose heading memory (kept by its RobotConfig's
    kinematics) is tracked, so that it can be cloned; and whose recursion (the
    all-modules-flip case calls ``self.generateSetpoint`` again) is counted."""

    def __init__(self, robot, memory=None):
        self.robot = robot
        self.config = robot.oracle_config()
        self.gen = ppswerve.SwerveSetpointGenerator(self.config, robot.max_steer)
        if memory is not None:
            self.config._swerveKinematics.resetHeadings(tuple(memory))
        self.memory = tuple(memory) if memory is not None else (wg.Rotation2d(),) * 4
        inner_ik = self.config.toSwerveModuleStates

        def ik(speeds):
            # WPILib's IK returns each module's remembered heading when it does not move
            # it, and remembers what it returns: so the returned angles are the memory.
            states = inner_ik(speeds)
            self.memory = tuple(st.angle for st in states)
            return states

        self.config.toSwerveModuleStates = ik
        self.calls = 0
        inner = self.gen.generateSetpoint

        def counted(prev, desired, dt, input_voltage=None, constraints=None):
            self.calls += 1
            return inner(prev, desired, dt, input_voltage, constraints)

        self.gen.generateSetpoint = counted

    def __call__(self, prev, st):
        pc = None if st.limits is None else PPPathConstraints(*st.limits)
        self.calls = 0
        return self.gen.generateSetpoint(prev, wk.ChassisSpeeds(*st.desired), st.dt,
                                         st.voltage, pc)


def oracle_envelope(robot, memory, prev, st, seed, count=24):
    """The oracle's outputs for ``count`` copies of the step whose previous setpoint and
    desired velocities are moved by up to 16 ulps each (same heading memory)."""
    rng = random.Random(seed)
    outs = []
    for _ in range(count):
        s = prev.robot_relative_speeds
        nudged = ppswerve.SwerveSetpoint(
            wk.ChassisSpeeds(_nudge(rng, s.vx), _nudge(rng, s.vy), _nudge(rng, s.omega)),
            [wk.SwerveModuleState(_nudge(rng, m.speed),
                                  wg.Rotation2d(_nudge(rng, m.angle.radians())))
             for m in prev.module_states],
            prev.feedforwards)
        desired = tuple(_nudge(rng, v) for v in st.desired)
        outs.append(oracle_values(Oracle(robot, memory)(nudged, Step(desired, st.dt, st.voltage,
                                                                     st.limits))))
    return outs


def outside_envelope(expected, envelope, got):
    """Names where ``got`` is outside [min, max] (widened by the tolerance) of the
    oracle's values over its ulp-nudged copies (and its own output ``expected``)."""
    bad = []
    for k, (name, b) in enumerate(got):
        vals = [expected[k][1]] + [e[k][1] for e in envelope]
        lo, hi = min(vals), max(vals)
        if not (lo - _tol(lo) <= b <= hi + _tol(hi)):
            bad.append(name)
    return bad


class Pair:
    """The corrected oracle and drivekin's generator for one robot, run side by side on the
    same inputs. ``fed="oracle"``: the oracle runs in closed loop and drivekin is fed the
    oracle's previous output, converted; ``fed="drivekin"``: drivekin runs in closed loop
    (its own outputs, with its own representation of every module state, are its next
    inputs) and the oracle is fed drivekin's previous output, converted. Either way each
    step's two outputs come from the same previous setpoint and must agree to the
    tolerance; both generator objects (and so both heading memories) live through the run.

    Where they do not agree, the step is retried on the oracle with its inputs nudged by
    up to 16 ulps (``oracle_envelope``): drivekin's numbers must then lie within the range
    of the oracle's own, widened by the tolerance. That is needed where PathPlanner's
    arithmetic is ill-conditioned: its discretize (WPILib 2026's ``Pose2d.log``) divides by
    ``cos(omega*dt) - 1``, so a few ulps of omega (from the forward kinematics'
    least-squares solve, QR in robotpy, another order of operations in drivekin) move the
    output by up to 1e-11 relative and the feedforwards (mass * dv / dt) by more than
    1e-9."""

    def __init__(self, robot, angle=0.0, use_into=False, fed="oracle", pp_constraints=False):
        assert fed in ("oracle", "drivekin")
        # drivekin also takes pathplannerlib's PathConstraints (any object with the names)
        self.constraints_type = PPPathConstraints if pp_constraints else dk.PathConstraints
        self.robot = robot
        self.fed = fed
        self.oracle = Oracle(robot)
        self.dg = robot.drivekin_generator()
        self.osp = oracle_zero(robot, angle)
        self.dsp = drivekin_zero(robot, angle)
        self.use_into = use_into
        self.buffers = [drivekin_zero(robot), drivekin_zero(robot)]
        self.history = []
        self.recursions = 0
        self.envelope_used = 0

    def _fail(self, what, bad, st, prev_o, prev_d, o, d):
        pytest.fail(
            f"drivekin differs from the oracle ({what}) in {bad} at step {len(self.history)}\n"
            f"robot: {self.robot!r}\ninputs: {st!r}\n"
            f"oracle prev:   {describe_oracle(prev_o)}\n"
            f"drivekin prev: {describe_drivekin(prev_d)}\n"
            f"oracle out:    {describe_oracle(o)}\n"
            f"drivekin out:  {describe_drivekin(d)}\n"
            f"(the earlier steps' inputs are in Pair.history: {len(self.history)} of them)")

    def step(self, st):
        pc_d = None if st.limits is None else self.constraints_type(*st.limits)
        desired = dk.ChassisVelocities(*st.desired)
        if self.fed == "oracle":
            prev_o = self.osp
            prev_d = to_drivekin(prev_o)
        else:
            prev_d = self.dsp
            prev_o = to_oracle(prev_d)
        memory = self.oracle.memory
        o = self.oracle(prev_o, st)
        self.recursions += self.oracle.calls - 1
        if self.use_into:
            # ping-pong between two buffers: the output never aliases the previous setpoint
            d = self.buffers[len(self.history) % 2]
            self.dg.generateSetpointInto(prev_d, desired, st.dt, d,
                                         inputVoltage=st.voltage, constraints=pc_d)
        else:
            d = self.dg.generateSetpoint(prev_d, desired, st.dt,
                                         inputVoltage=st.voltage, constraints=pc_d)
        expected, got = oracle_values(o), drivekin_values(d)
        if mismatches(expected, got):
            self.envelope_used += 1
            envelope = oracle_envelope(self.robot, memory, prev_o, st, len(self.history))
            bad = outside_envelope(expected, envelope, got)
            if bad:
                self._fail(f"fed the {self.fed}'s previous output", bad, st, prev_o, prev_d, o, d)
        self.history.append(st)
        self.osp, self.dsp = o, d
        return o

    def run(self, steps):
        return [self.step(st) for st in steps]


# ---------------------------------------------------------------------------------------
# Random closed-loop runs


def random_voltage(rng):
    r = rng.random()
    if r < 0.1:
        return float("nan")
    if r < 0.2:
        return rng.uniform(0.0, 6.7)                 # below brownout: clamped up
    if r < 0.3:
        return rng.uniform(12.0, 14.5)               # above nominal: no extra speed
    return rng.uniform(6.8, 12.0)


def random_limits(rng, robot):
    r = rng.random()
    if r < 0.4:
        return None
    if r < 0.5:
        return (math.inf, math.inf, math.inf, math.inf)
    return (rng.uniform(0.5, 1.1) * robot.vmax, rng.uniform(1.0, 12.0),
            rng.uniform(1.0, 12.0), rng.uniform(2.0, 30.0))


def random_target(rng, robot, last):
    reach = max(math.hypot(x, y) for x, y in robot.offsets)
    r = rng.random()
    if r < 0.08:
        return (0.0, 0.0, 0.0)
    if r < 0.16:                                     # reverse the previous command
        return tuple(-v for v in last)
    if r < 0.22:                                     # turn in place
        return (0.0, 0.0, rng.uniform(-1.2, 1.2) * robot.vmax / reach)
    speed = rng.uniform(0.0, 1.3) * robot.vmax
    heading = rng.uniform(-math.pi, math.pi)
    omega = rng.choice((0.0, rng.uniform(-1.0, 1.0) * robot.vmax / reach))
    return (speed * math.cos(heading), speed * math.sin(heading), omega)


def random_steps(rng, robot, count):
    steps = []
    last = (0.0, 0.0, 0.0)
    limits = None
    while len(steps) < count:
        target = random_target(rng, robot, last)
        if rng.random() < 0.3:
            limits = random_limits(rng, robot)
        ramp = rng.choice((0, 0, rng.randrange(1, 25)))
        hold = rng.randrange(3, 60)
        for k in range(1, ramp + 1):
            t = k / ramp
            cmd = tuple(a + (b - a) * t for a, b in zip(last, target))
            steps.append(Step(cmd, rng.uniform(0.005, 0.05), random_voltage(rng), limits))
        for _ in range(hold):
            steps.append(Step(target, rng.uniform(0.005, 0.05), random_voltage(rng), limits))
        last = target
    return steps[:count]


@pytest.mark.parametrize("seed", range(16))
def test_random_closed_loop(seed):
    rng = random.Random(7919 * seed + 1)
    robot = Robot.random(rng)
    pair = Pair(robot, angle=rng.uniform(-math.pi, math.pi), use_into=seed % 3 == 2,
                fed=("oracle", "drivekin")[seed % 2], pp_constraints=seed % 4 == 3)
    outs = pair.run(random_steps(rng, robot, 2000))
    assert pair.envelope_used <= len(outs) // 100    # the ulp-nudged retry stays rare
    # the run went somewhere: it was fast and it was stopped at times
    speeds = [math.hypot(o.robot_relative_speeds.vx, o.robot_relative_speeds.vy) for o in outs]
    assert max(speeds) > 0.3 * robot.vmax
    assert min(speeds) < 1e-3 * robot.vmax


# ---------------------------------------------------------------------------------------
# Deliberate scenarios


@pytest.fixture(params=["oracle", "drivekin"])
def fed(request):
    """Which implementation runs in closed loop (see Pair)."""
    return request.param


def held(desired, n, dt=0.02, voltage=12.0, limits=None):
    return [Step(desired, dt, voltage, limits) for _ in range(n)]


def stopped_modules_rotated(prev_o, o, dt, max_steer):
    """True when the oracle rotated its stopped modules in place by exactly one steering
    step (the robot stays stopped)."""
    step = dt * max_steer
    s = o.robot_relative_speeds
    if max(abs(s.vx), abs(s.vy), abs(s.omega)) > 1e-12:
        return False
    for a, b in zip(prev_o.module_states, o.module_states):
        turn = abs(math.remainder(b.angle.radians() - a.angle.radians(), math.pi))
        if abs(turn - step) > 1e-9:
            return False
    return True


@pytest.mark.parametrize("heading_deg", [111.0, -137.0, 71.0])
def test_stopped_to_moving_with_a_big_steering_change(heading_deg, fed):
    robot = Robot.square(max_steer=1.5 * math.pi)
    pair = Pair(robot, angle=0.0, fed=fed)
    h = math.radians(heading_deg)
    desired = (3.1 * math.cos(h), 3.1 * math.sin(h), 0.0)
    prev = pair.osp
    first = pair.step(Step(desired, 0.02, 12.0))
    assert stopped_modules_rotated(prev, first, 0.02, robot.max_steer)   # steering limits first
    pair.run(held(desired, 150))
    s = pair.osp.robot_relative_speeds
    assert (s.vx, s.vy) == pytest.approx(desired[:2], abs=1e-9)


@pytest.mark.parametrize("desired", [(2.7, 0.1, 0.0), (1.9, -0.07, 0.3)])
def test_stopped_to_moving_with_a_small_steering_change(desired, fed):
    robot = Robot.square()
    pair = Pair(robot, angle=0.0, fed=fed)
    outs = pair.run(held(desired, 120))
    assert math.hypot(outs[0].robot_relative_speeds.vx, outs[0].robot_relative_speeds.vy) > 0
    assert max(abs(m.speed) for m in outs[-1].module_states) > 1.5


@pytest.mark.parametrize("forward", [(3.4, 0.0, 0.0), (2.2, 1.3, 0.0), (2.5, -0.4, 1.1)])
def test_all_modules_flip_reverse_command(forward, fed):
    robot = Robot.square()
    pair = Pair(robot, fed=fed)
    pair.run(held(forward, 150))
    reverse = tuple(-v for v in forward)
    before = pair.recursions
    pair.run(held(reverse, 200))
    assert pair.recursions > before          # the oracle took the stop-and-flip recursion
    s = pair.osp.robot_relative_speeds
    assert s.vx * reverse[0] + s.vy * reverse[1] > 0


@pytest.mark.parametrize("dt", [0.005, 0.02, 0.05])
def test_strong_braking_from_full_speed(dt, fed):
    robot = Robot.square()
    pair = Pair(robot, fed=fed)
    pair.run(held((30.0, 0.0, 0.0), 300, dt=dt))              # saturated: top speed
    # (near the top speed PathPlanner's motor torque barely exceeds its torque loss)
    assert max(abs(m.speed) for m in pair.osp.module_states) == pytest.approx(robot.vmax, rel=1e-3)
    outs = pair.run(held((0.0, 0.0, 0.0), 300, dt=dt))
    assert any(abs(f) > 1.0 for o in outs[:3] for f in o.feedforwards.forcesNewtons)
    assert all(m.speed == 0.0 for m in outs[-1].module_states)
    # braking at top speed, then a sideways command at speed (a steering-limited turn)
    pair.run(held((30.0, 0.0, 0.0), 300, dt=dt))
    pair.run(held((0.0, -4.0, 0.3), 200, dt=dt))


def test_constraint_clamps(fed):
    robot = Robot.square()
    pair = Pair(robot, fed=fed)
    tight = (1.2, 2.5, 1.5, 3.0)
    outs = pair.run(held((3.0, 2.0, 4.0), 200, limits=tight))      # velocity and omega clamps
    s = outs[-1].robot_relative_speeds
    assert math.hypot(s.vx, s.vy) == pytest.approx(1.2, rel=0.02)   # discretized: not exact
    assert s.omega == pytest.approx(1.5, rel=1e-9)
    outs = pair.run(held((-3.0, 0.5, -4.0), 200, limits=(4.0, 0.8, 5.0, 0.5)))  # accel clamps
    pair.run(held((0.0, 0.0, 0.0), 200, limits=(0.5, 100.0, 0.2, 100.0)))
    pair.run(held((2.0, 0.0, 0.0), 50, limits=(math.inf, math.inf, math.inf, math.inf)))


@pytest.mark.parametrize("voltage", [float("nan"), 0.0, 3.0, 6.74, 6.75, 6.76, 9.0, 13.5])
def test_low_and_missing_voltage(voltage, fed):
    robot = Robot.square()
    pair = Pair(robot, fed=fed)
    pair.run(held((6.0, 1.0, 2.0), 150, voltage=voltage))
    pair.run(held((-2.0, 3.0, -1.0), 150, voltage=voltage))
    pair.run(held((0.0, 0.0, 0.0), 100, voltage=voltage))


def test_desired_equals_previous(fed):
    robot = Robot.square()
    pair = Pair(robot, fed=fed)
    pair.run(held((0.0, 0.0, 0.0), 5))                   # at rest, asked for rest
    pair.run(held((1.7, -0.6, 0.9), 100))
    for _ in range(50):                                  # asked for the previous output
        s = pair.osp.robot_relative_speeds
        pair.step(Step((s.vx, s.vy, s.omega), 0.02, 12.0))
    s = pair.osp.robot_relative_speeds
    pair.run(held((s.vx, s.vy, s.omega), 20, dt=0.01))


@pytest.mark.parametrize("module", range(4))
def test_a_zero_speed_module(module, fed):
    """Turning about one module: its desired speed is 0 and its angle comes from the heading
    memory (which the oracle keeps in its RobotConfig's kinematics)."""
    robot = Robot.random(random.Random(31 + module))
    pair = Pair(robot, angle=0.4, fed=fed)
    x, y = robot.offsets[module]
    kin = robot.oracle_config()
    for omega in (1.3, -2.1, 0.0, 2.6):
        desired = (omega * y, -omega * x, omega)
        assert kin.toSwerveModuleStates(wk.ChassisSpeeds(*desired))[module].speed < 1e-6
        pair.run(held(desired, 120))
    pair.run(held((0.0, 0.0, 0.0), 100))


def test_an_ill_conditioned_step():
    """A step (found by the random runs with an earlier layout generator) where the oracle's
    discretize is ill-conditioned: omega * dt = 0.0047, so ``cos(omega*dt) - 1`` keeps 5
    digits, and moving omega by a few ulps moves the feedforwards by ~4e-9. drivekin's
    output must lie within the oracle's own range over ulp-nudged inputs; a 1e-7 N error
    must not."""
    robot = Robot(mass=58.79840612888878, moi=2.58085502248525, radius=0.06010367576051358,
                  vmax=4.137837467089755, cof=0.748350934474173, motor="CIM",
                  gearing=7.622621378814212, ilim=87.73621773604361, nmotors=1,
                  offsets=[(0.2906248213102649, -0.4158778543397236),
                           (0.20891011544976978, 0.4602486243816398),
                           (0.13980353767344156, 0.3097324585683322),
                           (0.1799122346370935, -0.2777940355127325)],
                  max_steer=9.79356593623267)
    st = Step((-0.19899404994690092, -0.8982338067640976, 0.13356313621893087),
              dt=0.03500546774832451, voltage=10.368414867720563,
              limits=(2.6008729534271535, 2.4615062991818295, 9.000417059949676,
                      29.29209518189665))
    modules = [(0.8711759061928546, -1.739059265679938), (0.9086541570311026, -1.8643383139579428),
               (0.911935960542811, -1.8403056240154185), (0.8889815792134309, -1.7567276393543523)]
    prev = ppswerve.SwerveSetpoint(
        wk.ChassisSpeeds(-0.20144184373419924, -0.8976891907675622, 0.1335631362189309),
        [wk.SwerveModuleState(v, wg.Rotation2d(a)) for v, a in modules],
        PPDriveFeedforwards.zeros(4))
    expected = oracle_values(Oracle(robot)(prev, st))
    d = robot.drivekin_generator().generateSetpoint(
        to_drivekin(prev), dk.ChassisVelocities(*st.desired), st.dt,
        inputVoltage=st.voltage, constraints=dk.PathConstraints(*st.limits))
    got = drivekin_values(d)
    envelope = oracle_envelope(robot, (wg.Rotation2d(),) * 4, prev, st, 0)
    widths = [max(e[k][1] for e in envelope) - min(e[k][1] for e in envelope)
              for k in range(len(expected))]
    assert max(widths) > 1e-9                      # the oracle's own spread is that large
    assert outside_envelope(expected, envelope, got) == []
    wrong = [(n, v + 1e-7 if n == "linearForcesNewtons[0]" else v) for n, v in got]
    assert outside_envelope(expected, envelope, wrong) == ["linearForcesNewtons[0]"]


# ---------------------------------------------------------------------------------------
# drivekin.batch.generateSetpoints and generateSetpointInto: the same closed loop as
# generateSetpoint (which the tests above compare with the oracle)


@pytest.mark.parametrize("seed", range(3))
def test_batch_matches_generate_setpoint(seed):
    rng = random.Random(104729 + seed)
    robot = Robot.random(rng)
    limits = random_limits(rng, robot)
    pc = None if limits is None else dk.PathConstraints(*limits)
    steps = random_steps(rng, robot, 600)
    gen = robot.drivekin_generator()
    sp = drivekin_zero(robot, 0.3)
    expected = []
    for st in steps:
        sp = gen.generateSetpoint(sp, dk.ChassisVelocities(*st.desired), st.dt,
                                  inputVoltage=st.voltage, constraints=pc)
        expected.append(sp)
    vel, mods, ff = dkbatch.generateSetpoints(
        robot.drivekin_generator(), drivekin_zero(robot, 0.3),
        np.array([st.desired for st in steps], dtype=np.float64),
        np.array([st.dt for st in steps], dtype=np.float64),
        np.array([st.voltage for st in steps], dtype=np.float64), pc)
    assert vel.shape == (len(steps), 3) and mods.shape == (len(steps), 4, 2)
    assert ff.shape == (len(steps), 5, 4)
    for t, e in enumerate(expected):
        got = [("vx", vel[t, 0]), ("vy", vel[t, 1]), ("omega", vel[t, 2])]
        for i in range(4):
            got += [(f"module {i} speed", mods[t, i, 0]),
                    (f"module {i} cos", math.cos(mods[t, i, 1])),
                    (f"module {i} sin", math.sin(mods[t, i, 1]))]
        for k, (_, dname) in enumerate(FF_FIELDS):
            got += [(f"{dname}[{i}]", ff[t, k, i]) for i in range(4)]
        want = drivekin_values(e)
        assert not mismatches(want, got), (t, steps[t], mismatches(want, got), want, got)


def test_generate_setpoint_into_matches():
    rng = random.Random(5)
    robot = Robot.random(rng)
    a, b = robot.drivekin_generator(), robot.drivekin_generator()
    sa = drivekin_zero(robot)
    bufs = [drivekin_zero(robot), drivekin_zero(robot)]
    sb = drivekin_zero(robot)
    for t, st in enumerate(random_steps(rng, robot, 400)):
        pc = None if st.limits is None else dk.PathConstraints(*st.limits)
        desired = dk.ChassisVelocities(*st.desired)
        sa = a.generateSetpoint(sa, desired, st.dt, inputVoltage=st.voltage, constraints=pc)
        out = bufs[t % 2]
        b.generateSetpointInto(sb, desired, st.dt, out, inputVoltage=st.voltage, constraints=pc)
        sb = out
        assert drivekin_values(sa) == drivekin_values(sb), (t, st)
