"""The setpoint generator's default mode (``compatibility=None``) keeps every limit between
consecutive outputs, for 2 to 6 modules anywhere (none at the centre):

(a) each module's speed (the norm of its velocity vector: a module may flip its angle by pi
    and negate its speed) rises by at most PathPlanner's per-module drive step with the
    module's accelerating torque, and falls by at most the step with its braking torque,
    for that previous setpoint, desired velocities and voltage (whatever torque
    PathPlanner's rule, by the desired speed, would pick for it);
(b) a moving module's direction of travel turns by at most min(dt * maxSteer, the
    centripetal cap dt * wheelFrictionForce / ((mass / N) * |v_prev|)); a stopped module's
    angle turns by at most dt * maxSteer (modulo pi);
(c) a held, reachable target is reached exactly: the output becomes
    ``SwerveDriveKinematics.desaturatedDiscretize(desired, dt, maxSpeed)`` (maxSpeed =
    maxDriveVelocityMPS * min(1, V / 12)), and its module velocities that target's;
(d) stopping reaches exactly zero, and a full reverse reaches the reversed target;
(e) the counter-example behind the default: with the steering limited to 1.5 rot/s,
    ``compatibility="pathplanner"`` (PathPlannerLib's generator) breaks (a) by more than 1 %
    in many module steps over 1,500 held random commands, while the default never does.

The per-module drive steps are computed here, independently of drivekin's generator, in plain
Python from PathPlannerLib's formulas (``pp_drive_steps``): motor currents at the module's
present speed forwards and in reverse on the (brownout-clamped) voltage, capped by the
current limit, torque = Kt * I, less the module's torque loss when accelerating and plus it
when braking, capped by the wheel-slip torque; the module forces along the direction of
travel, the chassis force and torque, a = F / m, alpha = T / MOI (then PathConstraints'
acceleration limits), and the step = |IK(ax, ay, alpha)_i| * dt. Where a rule of PathPlanner's
is decided by a tie within rounding (accelerating or braking when the desired speed equals
the previous one, the all-modules-flip case at exactly 90 degrees), both outcomes are
computed and the larger step allowed. The motor constants R, Kv and Kt are derived here from
the DCMotor's five measured constants; the desired velocities of the default mode come from
``desaturatedDiscretize`` (tested against robotpy-wpimath in test_desaturated_discretize.py).

Slack: 1e-9 relative plus 1e-12 m/s (1e-9 rad for headings), plus, where a previous module
velocity (as the setpoint reports it) is not the inverse kinematics of the previous chassis
velocities (a module that was stopped, at a speed <= 1e-6 m/s, reports its steering angle),
the distance between the two: the generator limits the reported vectors, the output moves
the kinematic ones. Headings are compared for modules faster than 1e-4 m/s in both
setpoints (slower ones' directions are rounding), stopped-module angles for modules at most
1e-6 m/s (PathPlanner's kEpsilon) in the previous one.

Two pinned counter-examples (``test_pinned_*``) are the ways Team 254's drive root lets (a)
fail: a module whose speed dips inside the step another module limits, and the cancellation
in its quadratic's leading coefficient when the step is nearly parallel and tiny.
"""
from __future__ import annotations

import itertools
import math
import random

import pytest
from hypothesis import Phase, example, given, settings
from hypothesis import strategies as st

import drivekin as dk
from drivekin import (
    ChassisVelocities,
    DCMotor,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveModuleVelocity,
    Translation2d,
)

EPS = 1e-6            # PathPlanner's kEpsilon
GRAVITY = 9.8         # PathPlanner's
BROWNOUT = 6.75       # the generator's default brownoutVoltage
REL = 1e-9
ABS = 1e-12
TIE = 1e-9            # a comparison this close is decided by rounding: allow both outcomes

MOTORS = ("getKrakenX60", "getKrakenX60Foc", "getNEO", "getFalcon500", "getCIM",
          "getNeoVortex")


# ---------------------------------------------------------------------------------------
# Robots


class Robot:
    def __init__(self, offsets, mass, moi, radius, vmax, cof, motor, gearing, ilim, nmotors,
                 max_steer):
        self.offsets = [tuple(o) for o in offsets]
        self.n = len(self.offsets)
        self.mass, self.moi, self.radius, self.vmax, self.cof = mass, moi, radius, vmax, cof
        self.motor, self.gearing, self.ilim, self.nmotors = motor, gearing, ilim, nmotors
        self.max_steer = max_steer
        gearbox = getattr(DCMotor, motor)(nmotors).withReduction(gearing)
        self.config = dk.RobotConfig(mass, moi, dk.ModuleConfig(radius, vmax, cof, gearbox,
                                                                ilim, nmotors),
                                     [Translation2d(x, y) for x, y in self.offsets])
        self.kin = SwerveDriveKinematics(*[Translation2d(x, y) for x, y in self.offsets])
        # the motor model from the gearbox's measured constants (WPILib's definitions)
        self.R = gearbox.nominalVoltage / gearbox.stallCurrent
        self.Kv = gearbox.freeSpeed / (gearbox.nominalVoltage - self.R * gearbox.freeCurrent)
        self.Kt = gearbox.stallTorque / gearbox.stallCurrent
        # PathPlanner's derived values
        self.current_limit = ilim * nmotors
        self.torque_loss = max(self.Kt * min(self.current(vmax / radius, 12.0),
                                             self.current_limit), 0.0)
        self.friction_force = cof * (mass / self.n) * GRAVITY
        self.max_torque_friction = self.friction_force * radius

    def current(self, w, volts):
        return (volts - w / self.Kv) / self.R

    def generator(self, compatibility=None, max_steer=None):
        return dk.SwerveSetpointGenerator(
            self.config, self.max_steer if max_steer is None else max_steer,
            compatibility=compatibility)

    def __repr__(self):
        return (f"Robot(offsets={self.offsets!r}, mass={self.mass!r}, moi={self.moi!r}, "
                f"radius={self.radius!r}, vmax={self.vmax!r}, cof={self.cof!r}, "
                f"motor={self.motor!r}, gearing={self.gearing!r}, ilim={self.ilim!r}, "
                f"nmotors={self.nmotors!r}, max_steer={self.max_steer!r})")


def free_speed(motor, gearing, radius):
    return getattr(DCMotor, motor)(1).freeSpeed / gearing * radius


def vmax_low(motor, ilim):
    # PathPlanner's torque loss is the torque of the current drawn at vmax on 12 V (capped
    # by the limit): keep that current under the limit, or the robot cannot start at all
    return max(0.8, 1.0 - 0.6 * ilim / getattr(DCMotor, motor)(1).stallCurrent)


@st.composite
def robots(draw, sizes=(2, 3, 4, 5, 6)):
    n = draw(st.sampled_from(sizes))
    offsets = []
    for k in range(n):
        # one module per sector, so they are apart, none near the centre
        angle = 2 * math.pi * k / n + draw(st.floats(-0.6, 0.6)) * math.pi / n
        dist = draw(st.floats(0.15, 0.6))
        offsets.append((dist * math.cos(angle), dist * math.sin(angle)))
    rot = draw(st.floats(-math.pi, math.pi))
    offsets = [(x * math.cos(rot) - y * math.sin(rot), x * math.sin(rot) + y * math.cos(rot))
               for x, y in offsets]
    motor = draw(st.sampled_from(MOTORS))
    gearing = draw(st.floats(5.0, 8.5))
    radius = draw(st.floats(0.038, 0.0635))
    ilim = draw(st.floats(30.0, 90.0))
    low = vmax_low(motor, ilim)
    vmax = free_speed(motor, gearing, radius) * (low + (0.98 - low) * draw(st.floats(0, 1)))
    return Robot(offsets, mass=draw(st.floats(25.0, 75.0)), moi=draw(st.floats(2.0, 9.0)),
                 radius=radius, vmax=vmax, cof=draw(st.floats(0.7, 1.6)), motor=motor,
                 gearing=gearing, ilim=ilim, nmotors=draw(st.sampled_from((1, 1, 2))),
                 max_steer=draw(st.floats(1.5 * math.pi, 12 * math.pi)))


def square_robot(max_steer):
    h = 0.29
    return Robot([(h, h), (h, -h), (-h, h), (-h, -h)], mass=55.0, moi=5.5, radius=0.0508,
                 vmax=4.3, cof=1.2, motor="getKrakenX60", gearing=6.75, ilim=60.0, nmotors=1,
                 max_steer=max_steer)


def at_rest(robot, angles):
    return dk.SwerveSetpoint(ChassisVelocities(),
                             [SwerveModuleVelocity(0.0, Rotation2d(a)) for a in angles],
                             dk.DriveFeedforwards.zeros(robot.n))


# ---------------------------------------------------------------------------------------
# PathPlanner's limits, computed independently


def effective_voltage(volts):
    return 12.0 if math.isnan(volts) else max(volts, BROWNOUT)


def max_speed(robot, volts):
    return robot.vmax * min(1.0, effective_voltage(volts) / 12.0)


def ik(robot, vx, vy, omega):
    """Module velocity vectors of a chassis velocity (about the robot's centre)."""
    return [(vx - omega * y, vy + omega * x) for x, y in robot.offsets]


def clamp_desired(desired, limits):
    vx, vy, omega = desired
    if limits is not None:
        lin = math.hypot(vx, vy)
        if lin > limits[0]:
            vx, vy = vx * (limits[0] / lin), vy * (limits[0] / lin)
        omega = max(min(omega, limits[2]), -limits[2])
    return vx, vy, omega


def desired_modules(robot, desired, dt, volts, limits, mode):
    """The desired chassis velocities after the constraints and the speed limit, and their
    module vectors. Default mode: ``desaturatedDiscretize``; "pathplanner": the module
    speeds scaled down together (WPILib's desaturateWheelSpeeds)."""
    vx, vy, omega = clamp_desired(desired, limits)
    top = max_speed(robot, volts)
    if mode is None:
        d = robot.kin.desaturatedDiscretize(ChassisVelocities(vx, vy, omega), dt, top)
        d = (d.vx, d.vy, d.omega)
        return d, ik(robot, *d)
    vecs = ik(robot, vx, vy, omega)
    fastest = max(math.hypot(*v) for v in vecs)
    k = top / fastest if fastest > top else 1.0
    return (vx * k, vy * k, omega * k), [(x * k, y * k) for x, y in vecs]


def eps_zero(v):
    return all(abs(c) <= EPS for c in v)


def wrap(a):
    return math.remainder(a, 2 * math.pi)


def module_state(m):
    """(signed speed, angle) of a SwerveModuleVelocity."""
    return m.velocity, math.atan2(m.angle.getSin(), m.angle.getCos())


def desired_candidates(prev_chassis, prev_modules, d, d_vecs):
    """PathPlanner's desired module vectors: all zero if the desired velocities are zero
    (within kEpsilon) or if every module would have to turn more than 90 degrees while the
    robot moves (then it stops first). Both candidates where that test is a tie."""
    zero = [(0.0, 0.0)] * len(d_vecs)
    if eps_zero(d):
        return [zero]
    if eps_zero(prev_chassis):
        return [d_vecs]
    all_flip, tie = True, False
    for (p, a), (x, y) in zip(prev_modules, d_vecs):
        heading = a + math.pi if p < 0 else a
        if math.hypot(x, y) <= EPS:
            tie = True          # its heading is the kinematics' memory: either way
            continue
        turn = abs(wrap(math.atan2(y, x) - heading))
        if turn < math.pi / 2 - TIE:
            all_flip = False
        elif turn < math.pi / 2 + TIE:
            tie = True
    if not all_flip:
        return [d_vecs]
    return [d_vecs, zero] if tie else [zero]


def accelerating_options(p, a, vec):
    """PathPlanner's rule (after optimising the desired state against the previous angle):
    accelerate when stopped or when the desired speed is at least the previous one in the
    previous direction, brake otherwise. Returns the possible outcomes."""
    x, y = vec
    speed = math.hypot(x, y)
    signs = {1.0}
    if speed > EPS:
        delta = abs(wrap(math.atan2(y, x) - a))
        if delta > math.pi / 2 + TIE:
            signs = {-1.0}
        elif delta > math.pi / 2 - TIE:
            signs = {1.0, -1.0}
    out = set()
    for sign in signs:
        s = sign * speed
        for stopped in {abs(p) <= EPS * (1 - TIE), abs(p) <= EPS * (1 + TIE)}:
            out.add(stopped or (p > 0 and s >= p) or (p < 0 and s <= p))
        if abs(s - p) <= TIE * max(1.0, abs(p)):
            out.update((True, False))
    return sorted(out)


def drive_steps_for(robot, prev_modules, accelerating, dt, volts, limits):
    """The per-module drive steps for given accelerate/brake decisions."""
    volts = effective_voltage(volts)
    fx = fy = torque = 0.0
    for (p, a), acc, (lx, ly) in zip(prev_modules, accelerating, robot.offsets):
        w = abs(p / robot.radius)
        forward = min(max(robot.current(w, volts), 0.0), robot.current_limit)
        reverse = min(max(abs(robot.current(w, -volts)), 0.0), robot.current_limit)
        if acc:
            tq, sign = robot.Kt * forward - robot.torque_loss, 1.0
            angle = a + math.pi if p < 0 else a
        else:
            tq, sign = robot.Kt * reverse + robot.torque_loss, -1.0
            angle = a + math.pi if p > 0 else a
        tq = min(tq, robot.max_torque_friction)
        force = tq / robot.radius
        mx, my = force * sign * math.cos(angle), force * sign * math.sin(angle)
        fx += mx
        fy += my
        if math.hypot(mx, my) > EPS:
            theta = math.atan2(my, mx) - math.atan2(ly, lx)
            torque += force * math.hypot(lx, ly) * math.sin(theta)
    ax, ay, alpha = fx / robot.mass, fy / robot.mass, torque / robot.moi
    if limits is not None:
        lin = math.hypot(ax, ay)
        if lin > limits[1]:
            ax, ay = ax * (limits[1] / lin), ay * (limits[1] / lin)
        alpha = max(min(alpha, limits[3]), -limits[3])
    return [math.hypot(x, y) * dt for x, y in ik(robot, ax, ay, alpha)]


def pp_drive_steps(robot, prev, desired, dt, volts, limits, mode=None):
    """The largest speed change PathPlanner's drive limit allows each module in one step
    from ``prev`` (a drivekin SwerveSetpoint) towards ``desired`` (vx, vy, omega), the
    module's torque chosen by PathPlanner's rule (its desired speed)."""
    best = [0.0] * robot.n
    for options, steps_of in _drive_choices(robot, prev, desired, dt, volts, limits, mode):
        for choice in itertools.product(*options):
            best = [max(b, s) for b, s in zip(best, steps_of(choice))]
    return best


def pp_drive_bands(robot, prev, desired, dt, volts, limits, mode=None):
    """Each module's (up, down): the largest speed increase PathPlanner's drive step
    allows it with its accelerating torque, and the largest decrease with its braking
    torque, whatever its desired speed; the other modules' torques by PathPlanner's rule."""
    up, down = [0.0] * robot.n, [0.0] * robot.n
    for options, steps_of in _drive_choices(robot, prev, desired, dt, volts, limits, mode):
        for i in range(robot.n):
            for own, best in ((True, up), (False, down)):
                forced = options[:i] + [[own]] + options[i + 1:]
                for choice in itertools.product(*forced):
                    best[i] = max(best[i], steps_of(choice)[i])
    return up, down


def _drive_choices(robot, prev, desired, dt, volts, limits, mode):
    """For each desired-vector candidate: the modules' accelerate/brake options by
    PathPlanner's rule, and the function from a choice to the drive steps."""
    pv = prev.robotRelativeVelocities
    prev_chassis = (pv.vx, pv.vy, pv.omega)
    prev_modules = [module_state(m) for m in prev.moduleVelocities]
    d, d_vecs = desired_modules(robot, desired, dt, volts, limits, mode)
    for vecs in desired_candidates(prev_chassis, prev_modules, d, d_vecs):
        yield ([accelerating_options(p, a, v) for (p, a), v in zip(prev_modules, vecs)],
               lambda choice: drive_steps_for(robot, prev_modules, choice, dt, volts, limits))


def steering_caps(robot, prev, dt):
    """Each moving module's largest turn of its direction of travel in one step."""
    out = []
    for m in prev.moduleVelocities:
        cap = dt * robot.max_steer
        if abs(m.velocity) > EPS:
            cap = min(cap, dt * robot.friction_force / ((robot.mass / robot.n) * abs(m.velocity)))
        out.append(cap)
    return out


def vectors(sp):
    return [(m.velocity * m.angle.getCos(), m.velocity * m.angle.getSin())
            for m in sp.moduleVelocities]


def kinematic_mismatch(robot, sp):
    """How far each reported module velocity is from the IK of the chassis velocities."""
    v = sp.robotRelativeVelocities
    return [math.hypot(a - c, b - e)
            for (a, b), (c, e) in zip(vectors(sp), ik(robot, v.vx, v.vy, v.omega))]


class Violations:
    """Checks (a) and (b) on one step; records (a)'s violations instead of failing when
    ``record`` (the counter-example needs to count them)."""

    def __init__(self, robot, mode=None, record=False):
        self.robot, self.mode, self.record = robot, mode, record
        self.drive = []          # (ratio of change to step, module, step index)
        self.steps = 0

    def check(self, prev, out, desired, dt, volts, limits):
        robot = self.robot
        up, down = pp_drive_bands(robot, prev, desired, dt, volts, limits, self.mode)
        slack = kinematic_mismatch(robot, prev)
        before, after = vectors(prev), vectors(out)
        ctx = (f"robot={robot!r}\nprev={prev!r}\nout={out!r}\ndesired={desired!r} dt={dt!r} "
               f"volts={volts!r} limits={limits!r} mode={self.mode!r}")
        for i, ((bx, by), (ax, ay)) in enumerate(zip(before, after)):
            change = math.hypot(ax, ay) - math.hypot(bx, by)
            bound, what = (up[i], "accelerating") if change > 0 else (down[i], "braking")
            allowed = bound * (1 + REL) + ABS + slack[i]
            if abs(change) > allowed:
                if not self.record:
                    raise AssertionError(f"module {i}: speed changed by {change!r}, more than "
                                         f"PathPlanner's {what} drive step {bound!r}\n{ctx}")
                self.drive.append((abs(change) / max(bound, 1e-300), i, self.steps))
        if self.record:
            self.steps += 1
            return
        caps = steering_caps(robot, prev, dt)
        for i, (pm, om) in enumerate(zip(prev.moduleVelocities, out.moduleVelocities)):
            (bx, by), (ax, ay) = before[i], after[i]
            if abs(pm.velocity) > 1e-4 and abs(om.velocity) > 1e-4:
                turn = abs(wrap(math.atan2(ay, ax) - math.atan2(by, bx)))
                allowed = caps[i] * (1 + REL) + 1e-9 + slack[i] / abs(om.velocity)
                assert turn <= allowed, (f"module {i}: direction of travel turned {turn!r}, "
                                         f"more than {caps[i]!r}\n{ctx}")
            elif abs(pm.velocity) <= EPS:
                turn = abs(math.remainder(math.atan2(om.angle.getSin(), om.angle.getCos())
                                          - math.atan2(pm.angle.getSin(), pm.angle.getCos()),
                                          math.pi))
                allowed = dt * robot.max_steer * (1 + REL) + 1e-9
                assert turn <= allowed, (f"stopped module {i}: angle turned {turn!r}, more "
                                         f"than {dt * robot.max_steer!r}\n{ctx}")
        self.steps += 1


# ---------------------------------------------------------------------------------------
# Commands


def random_voltage(rng):
    r = rng.random()
    if r < 0.15:
        return float("nan")
    if r < 0.3:
        return rng.uniform(0.0, 6.7)
    if r < 0.4:
        return rng.uniform(12.0, 14.5)
    return rng.uniform(6.8, 12.0)


def random_limits(rng, robot):
    if rng.random() < 0.6:
        return None
    return (rng.uniform(0.4, 1.2) * robot.vmax, rng.uniform(1.0, 12.0),
            rng.uniform(1.0, 12.0), rng.uniform(2.0, 30.0))


def random_target(rng, robot, last):
    reach = max(math.hypot(x, y) for x, y in robot.offsets)
    r = rng.random()
    if r < 0.1:
        return (0.0, 0.0, 0.0)
    if r < 0.2:
        return tuple(-v for v in last)
    if r < 0.27:
        return (0.0, 0.0, rng.uniform(-1.3, 1.3) * robot.vmax / reach)
    speed = rng.uniform(0.0, 1.3) * robot.vmax
    heading = rng.uniform(-math.pi, math.pi)
    omega = rng.choice((0.0, rng.uniform(-1.2, 1.2) * robot.vmax / reach))
    return (speed * math.cos(heading), speed * math.sin(heading), omega)


def random_commands(rng, robot, count, hold=(3, 40), ramps=True, voltages=True,
                    constraints=True):
    """(desired, dt, voltage, limits) tuples: targets held, sometimes ramped to."""
    out = []
    last = (0.0, 0.0, 0.0)
    limits = None
    while len(out) < count:
        target = random_target(rng, robot, last)
        if constraints and rng.random() < 0.3:
            limits = random_limits(rng, robot)
        ramp = rng.choice((0, 0, rng.randrange(1, 20))) if ramps else 0
        cmds = [tuple(a + (b - a) * k / ramp for a, b in zip(last, target))
                for k in range(1, ramp + 1)] + [target] * rng.randrange(*hold)
        for cmd in cmds:
            volts = random_voltage(rng) if voltages else 12.0
            out.append((cmd, rng.uniform(0.005, 0.05), volts, limits))
        last = target
    return out[:count]


def step(gen, prev, desired, dt, volts, limits):
    pc = None if limits is None else dk.PathConstraints(*limits)
    return gen.generateSetpoint(prev, ChassisVelocities(*desired), dt, inputVoltage=volts,
                                constraints=pc)


# ---------------------------------------------------------------------------------------
# (a) and (b): random closed-loop runs


# The closed-loop tests run hundreds of steps per example: no shrinking (the failure message
# names the robot and the step's inputs).
HEAVY = dict(phases=(Phase.explicit, Phase.reuse, Phase.generate))


@settings(max_examples=60, **HEAVY)
@given(robots(), st.integers(0, 2**32 - 1))
def test_drive_and_steering_limits_hold(robot, seed):
    rng = random.Random(seed)
    gen = robot.generator()
    prev = at_rest(robot, [rng.uniform(-math.pi, math.pi) for _ in range(robot.n)])
    check = Violations(robot)
    for desired, dt, volts, limits in random_commands(rng, robot, 250):
        out = step(gen, prev, desired, dt, volts, limits)
        check.check(prev, out, desired, dt, volts, limits)
        prev = out


def test_the_limits_are_active():
    """The checks above can fail: the limits bind (changes close to the bounds) in these
    runs, and a generator allowed to steer faster breaks (b)."""
    robot = square_robot(2 * math.pi)
    rng = random.Random(11)
    cmds = random_commands(rng, robot, 600, voltages=False, constraints=False)
    ratios_drive, ratios_turn = [], []
    for gen_steer, expect_ok in ((robot.max_steer, True), (3 * robot.max_steer, False)):
        gen = robot.generator(max_steer=gen_steer)
        prev = at_rest(robot, [0.0] * 4)
        check = Violations(robot)
        failed = False
        for desired, dt, volts, limits in cmds:
            out = step(gen, prev, desired, dt, volts, limits)
            if expect_ok:
                bounds = pp_drive_steps(robot, prev, desired, dt, volts, limits)
                caps = steering_caps(robot, prev, dt)
                for (bx, by), (ax, ay), b, c, pm in zip(vectors(prev), vectors(out), bounds,
                                                        caps, prev.moduleVelocities):
                    if b > 1e-6:
                        ratios_drive.append(abs(math.hypot(ax, ay) - math.hypot(bx, by)) / b)
                    if abs(pm.velocity) > 1e-3 and math.hypot(ax, ay) > 1e-3:
                        ratios_turn.append(abs(wrap(math.atan2(ay, ax) - math.atan2(by, bx))) / c)
                check.check(prev, out, desired, dt, volts, limits)
            else:
                try:
                    check.check(prev, out, desired, dt, volts, limits)
                except AssertionError:
                    failed = True
                    break
            prev = out
        assert failed is not expect_ok
    assert max(ratios_drive) > 0.999 and max(ratios_turn) > 0.999


def consistent(robot, chassis):
    """A setpoint at ``chassis`` whose modules are its inverse kinematics."""
    mods = [SwerveModuleVelocity(math.hypot(x, y), Rotation2d(math.atan2(y, x)))
            for x, y in ik(robot, *chassis)]
    return dk.SwerveSetpoint(ChassisVelocities(*chassis), mods,
                             dk.DriveFeedforwards.zeros(robot.n))


def test_pinned_a_module_whose_speed_dips_within_the_step():
    """Module 0 is to speed up a lot (+1.74 m/s) but its velocity vector's path passes
    close to zero first: its speed falls, then rises. Module 1 limits the step to s = 0.042,
    inside that dip, where module 0 is 0.0072 m/s slower, more than its drive step of
    0.0066 m/s. Team 254's drive root only looks for the crossing of |v0| + step (the
    direction the endpoint lies in), not for the first exit from [|v0| - step, |v0| + step]."""
    robot = square_robot(20.0)
    prev = consistent(robot, (-1.5, 1.4, -3.6))
    desired = (2.6, 0.8, 4.6)
    out = step(robot.generator(), prev, desired, 0.02, 12.0, None)
    Violations(robot).check(prev, out, desired, 0.02, 12.0, None)


def test_pinned_a_module_that_speeds_up_though_its_desired_speed_is_lower():
    """Module 2 turns by more than 90°, so its desired speed, optimised against its angle,
    is negative, below its previous one: PathPlanner's rule gives it the braking torque,
    whose step is the larger. Its velocity vector passes close to zero and comes out
    faster, by 1.5 times its accelerating step. Its speed gain is bounded by the step of
    its accelerating torque."""
    robot = square_robot(1000.0)
    prev = consistent(robot, (0.5303594170160151, 0.6229544043722721, 2.063469086491245))
    desired = (2.4488197319100298, 3.7336756177040735, -6.085201634243926)
    out = step(robot.generator(), prev, desired, 0.02, 12.0, None)
    Violations(robot).check(prev, out, desired, 0.02, 12.0, None)


def test_modules_keep_the_step_of_the_torque_they_use():
    """Single steps from random consistent setpoints towards random commands with fast
    steering (a module can swing through a reversal in one step): every speed gain within
    the accelerating torque's step, every loss within the braking torque's (with
    PathPlanner's rule, 31 of 3,000 such steps gained up to 6.7 times the accelerating
    step)."""
    robot = square_robot(1000.0)
    rng = random.Random(5)
    check = Violations(robot)
    for _ in range(400):
        prev = consistent(robot, (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-3, 3)))
        desired = (rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-10, 10))
        dt, volts = rng.choice((0.02, 0.05)), rng.choice((12.0, 8.0))
        check.check(prev, step(robot.generator(), prev, desired, dt, volts, None), desired, dt,
                    volts, None)


def test_pinned_a_nearly_parallel_step_near_the_top_speed():
    """Straight ahead 10 nm/s under the speed limit, asked for more: the step allowed is
    2.9e-9 m/s (at the top speed the motor's torque barely exceeds the torque loss). In
    PathPlanner's quadratic, a = l0 + l1 - 2p = |v1 - v0|^2 = 1e-16 is computed as the
    difference of numbers of 18.5 and comes out 0, so its root is given up and the step is
    not limited (1e-8 m/s). ``a`` from the difference vector does not cancel."""
    robot = square_robot(3 * math.pi)
    v0 = 4.29999999
    prev = consistent(robot, (v0, 0.0, 0.0))
    out = step(robot.generator(), prev, (5.0, 0.0, 0.0), 0.02, 12.0, None)
    Violations(robot).check(prev, out, (5.0, 0.0, 0.0), 0.02, 12.0, None)


# ---------------------------------------------------------------------------------------
# (c) and (d): held targets are reached


# Robot time a held target may take. The slowest draw (2 modules, 75 kg, 30 A, a NEO on
# 12.5 V, where only 0.5 V / R = 4.4 A is left above the torque loss near the top speed)
# needs at most about 33 s if it never had more; over 1,500 draws the longest took 14.8 s
# (2,827 steps of 5 ms). A budget in steps would fail the slow robots at small dt.
REACH_SECONDS = 60.0


def reach(gen, robot, prev, desired, dt, volts, check, target):
    """Hold ``desired`` until the output equals ``target`` (chassis velocities, and the
    module velocity vectors their IK) within 1e-9, then 20 steps more; returns the last
    output."""
    want = ik(robot, *target)
    settled = 0
    max_steps = math.ceil(REACH_SECONDS / dt)
    for k in range(max_steps):
        out = step(gen, prev, desired, dt, volts, None)
        check.check(prev, out, desired, dt, volts, None)
        prev = out
        v = out.robotRelativeVelocities
        got = (v.vx, v.vy, v.omega)
        ok = all(abs(a - b) <= 1e-9 * max(1.0, abs(b)) for a, b in zip(got, target))
        ok = ok and all(math.hypot(a - c, b - e) <= 1e-9 * max(1.0, math.hypot(c, e))
                        for (a, b), (c, e) in zip(vectors(out), want))
        if ok:
            settled += 1
            if settled > 20:
                return out
        else:
            assert settled == 0, (f"left the target after reaching it: step {k}, {got!r} "
                                  f"vs {target!r}\nrobot={robot!r}")
    raise AssertionError(f"did not reach {target!r} holding {desired!r} (dt={dt!r}, "
                         f"volts={volts!r}) in {max_steps} steps: at {got!r}\nrobot={robot!r}")


@st.composite
def held_targets(draw):
    """A desired velocity (direction, share of the reachable speed, turn), dt and voltage.
    Saturated targets (module speeds above the limit) are drawn with more than 12 V: below,
    PathPlanner's torque loss (the motor's torque at vmax on 12 V) outgrows the motor's
    torque before the speed limit vmax * V / 12, and at 12 V the two meet at vmax, which is
    then approached only geometrically."""
    speed = draw(st.floats(0.05, 1.0))
    heading = draw(st.floats(-math.pi, math.pi))
    omega = draw(st.floats(-1.0, 1.0))
    saturated = draw(st.booleans())
    if saturated:
        volts = draw(st.floats(12.5, 14.0))
    else:
        volts = draw(st.one_of(st.just(float("nan")), st.floats(0.0, 14.0)))
    dt = draw(st.sampled_from((0.005, 0.01, 0.02, 0.05)))
    return speed, heading, omega, saturated, volts, dt


def reachable_speed(robot, volts):
    """The module speed up to which PathPlanner's accelerating torque (motor torque less
    the torque loss) is positive on this voltage, or the speed limit if lower."""
    loss_current = robot.torque_loss / robot.Kt
    v_star = robot.radius * robot.Kv * (effective_voltage(volts) - robot.R * loss_current)
    return min(max_speed(robot, volts), v_star)


def scaled_target(robot, t):
    """The desired velocities of ``held_targets``'s draw for this robot: unsaturated ones
    put the fastest module at most at 85 % of ``reachable_speed``, saturated ones at 1.2-3
    times the speed limit."""
    speed, heading, omega, saturated, volts, dt = t
    reach_ = max(math.hypot(x, y) for x, y in robot.offsets)
    raw = (math.cos(heading), math.sin(heading), omega / reach_)
    fastest = max(math.hypot(*v) for v in ik(robot, *raw))
    if saturated:
        k = (1.2 + 1.8 * speed) * max_speed(robot, volts) / fastest
    else:
        k = 0.85 * speed * reachable_speed(robot, volts) / fastest
    return tuple(k * c for c in raw)


def target_of(robot, desired, dt, volts):
    d = robot.kin.desaturatedDiscretize(ChassisVelocities(*desired), dt, max_speed(robot, volts))
    return (d.vx, d.vy, d.omega)


@settings(max_examples=40, **HEAVY)
@given(robots(), held_targets(), st.floats(-math.pi, math.pi))
# a heavy 2-module robot on a 30 A limit accelerates at 0.42 m/s^2: 11.5 s to its top speed
@example(Robot(offsets=[(-0.012596201446777255, -0.5206352638988522),
                        (0.2944839766201589, 0.4040781948014242)],
               mass=73.0189977458615, moi=2.0, radius=0.042802804630485865,
               vmax=4.785897086056344, cof=1.5583583095376965, motor="getKrakenX60Foc",
               gearing=5.229634114967105, ilim=30.0, nmotors=1, max_steer=26.524683283336415),
         (0.0625, 2.438139872665743, 5.3935485498036924e-46, True, 13.941289375920084, 0.005),
         0.0625)
def test_a_held_target_is_reached(robot, t, angle):
    desired = scaled_target(robot, t)
    volts, dt = t[4], t[5]
    gen = robot.generator()
    prev = at_rest(robot, [angle] * robot.n)
    reach(gen, robot, prev, desired, dt, volts, Violations(robot),
          target_of(robot, desired, dt, volts))


@settings(max_examples=30, **HEAVY)
@given(robots(), held_targets())
def test_stopping_and_reversing(robot, t):
    t = t[:3] + (False, float("nan"), t[5])       # unsaturated, 12 V
    desired = scaled_target(robot, t)
    dt = t[5]
    gen = robot.generator()
    check = Violations(robot)
    prev = at_rest(robot, [0.0] * robot.n)
    prev = reach(gen, robot, prev, desired, dt, 12.0, check, target_of(robot, desired, dt, 12.0))
    # stop: exactly zero
    for _ in range(1500):
        out = step(gen, prev, (0.0, 0.0, 0.0), dt, 12.0, None)
        check.check(prev, out, (0.0, 0.0, 0.0), dt, 12.0, None)
        prev = out
        v = out.robotRelativeVelocities
        if (v.vx, v.vy, v.omega) == (0.0, 0.0, 0.0):
            break
    else:
        raise AssertionError(f"did not stop: {prev!r}\nrobot={robot!r}")
    assert all(m.velocity == 0.0 for m in prev.moduleVelocities)
    # forwards again, then the full reverse
    prev = reach(gen, robot, prev, desired, dt, 12.0, check, target_of(robot, desired, dt, 12.0))
    reverse = tuple(-c for c in desired)
    reach(gen, robot, prev, reverse, dt, 12.0, check, target_of(robot, reverse, dt, 12.0))


# ---------------------------------------------------------------------------------------
# (e) The counter-example: PathPlannerLib's own generator breaks (a)


@pytest.mark.parametrize("seed", [1, 2])
def test_pathplanner_mode_breaks_the_drive_limit_and_the_default_does_not(seed):
    robot = square_robot(3 * math.pi)          # 1.5 rot/s
    rng = random.Random(seed)
    cmds = []
    last = (0.0, 0.0, 0.0)
    for _ in range(1500):                      # 1,500 random commands, each held a while
        last = random_target(rng, robot, last)
        dt = rng.uniform(0.005, 0.05)
        cmds += [(last, dt, 12.0, None)] * rng.randrange(4, 13)
    found = {}
    for mode in ("pathplanner", None):
        gen = robot.generator(compatibility=mode)
        check = Violations(robot, mode=mode, record=True)
        prev = at_rest(robot, [0.0] * 4)
        for desired, dt, volts, limits in cmds:
            out = step(gen, prev, desired, dt, volts, limits)
            check.check(prev, out, desired, dt, volts, limits)
            prev = out
        found[mode] = check.drive
    bad = [v for v in found["pathplanner"] if v[0] > 1.01]
    assert len(bad) >= 100, found["pathplanner"]
    assert found[None] == []
