"""``python -m drivekin``: a simulated 50 Hz swerve control loop on the allocation-free path.

The demo drives a four-module swerve robot through a scripted joystick sequence for a few
minutes of robot time and reports how long each 20 ms control step took and whether the
loop allocated memory. One step is exactly what a robot program does every 20 ms::

    joystick script  -> ChassisVelocities (field-relative, one mutable object)
    toRobotRelativeInto(heading, cv)           field-relative -> robot-relative
    cv.discretizeInto(0.02, cv)                remove the translate-while-turning drift
    kin.toSwerveModuleVelocitiesInto(cv, targets)        inverse kinematics, in place
    SwerveDriveKinematics.desaturateWheelVelocitiesInPlace(targets, max_speed)
    module response model                      optimize, rate-limited steering, lagged wheel
    kin.toTwist2dInto(deltas, twist)           forward kinematics from the position deltas
    pose = pose.exp(twist)                     immutable Pose2d, recycled from a freelist

Measurement, in two passes over identical fresh simulations (so the poses must agree):

1. *Timing pass*, tracemalloc off: ``time.perf_counter_ns()`` around every step; the loop
   runs flat out (no sleeping), the 20 ms period is only the budget the latencies are
   compared with. The two clock reads (~0.1 µs) are included in each sample.
2. *Allocation pass*, tracemalloc on (it slows every allocation down, so it must not
   distort the timings): traced bytes are read once before the loop, the peak is reset,
   and after the loop the peak and current traced bytes are compared with the start;
   a snapshot diff counts the blocks still alive. Because CPython allocates a
   temporary before it frees the value it replaces, any per-step allocation raises the
   traced peak above the start; ``0 B`` means the steady-state loop did not call the
   allocator (floats and the drivekin value objects are recycled from freelists).

Before each pass: ``gc.collect()``, then the measured simulation is built, then a
throw-away simulation runs one full script cycle as warm-up (caches, specialised
bytecode) and is freed, refilling the freelists (see :func:`prepared_simulation`).

Only the standard library and drivekin are used. Drivetrains plug in through
:data:`DRIVETRAINS`: a class with ``pose``, ``distance``, ``describe()`` and
``step(command)``.
"""
from __future__ import annotations

import argparse
import gc
import itertools
import json
import math
import sys
import time
import tracemalloc
from array import array

import drivekin
from drivekin import (
    ChassisVelocities,
    Pose2d,
    Rotation2d,
    SwerveDriveKinematics,
    SwerveModulePosition,
    SwerveModuleVelocity,
    Translation2d,
    Twist2d,
)

DT = 0.02                   # control period, s (50 Hz)
BUDGET_NS = 20_000_000      # the same period in ns, for the budget columns

_cos = math.cos
_hypot = math.hypot
_from_radians = Rotation2d.fromRadians
_desaturate_in_place = SwerveDriveKinematics.desaturateWheelVelocitiesInPlace

# Hot-path rule for everything below: no Python ``for`` loops (list/tuple/range iterators
# are heap objects), no new attributes (``__slots__``), no ints above 256 (small ints are
# cached, larger ones are allocated), no containers built per step. Floats and drivekin
# values are fine: they come from freelists.


# ---------------------------------------------------------------------------------------
# Driver input

class JoystickScript:
    """A deterministic driver: field-relative stick values, repeated every 30 s.

    Segments (stick values in [-1, 1]; translation scaled by ``max_speed`` m/s, rotation
    by ``max_omega`` rad/s):

    ========  ====  ====================================================================
    forward    3 s  +x at 0.5
    strafe     3 s  +y (left) at 0.5
    spin       3 s  rotate counter-clockwise at 0.5, no translation
    figure-8  16 s  one lemniscate-like loop (x ~ sin ωt, y ~ sin 2ωt, returns to its
                    start) while rotating at 0.35
    return     3 s  -x and -y at 0.5, back towards the start
    stop       2 s  sticks released
    ========  ====  ====================================================================
    """

    SEGMENTS = (
        ("forward", 3.0),
        ("strafe", 3.0),
        ("spin", 3.0),
        ("figure-8", 16.0),
        ("return", 3.0),
        ("stop", 2.0),
    )
    CYCLE = sum(d for _, d in SEGMENTS)

    __slots__ = ("_max_speed", "_max_omega", "_writers", "_durations", "_count", "_index",
                 "_t", "_fig8_w")

    def __init__(self, max_speed: float, max_omega: float) -> None:
        self._max_speed = float(max_speed)
        self._max_omega = float(max_omega)
        # Plain functions, not bound methods: bound methods stored on self would form a
        # reference cycle, leaving discarded simulations to the cyclic GC.
        cls = type(self)
        writers = {
            "forward": cls._forward, "strafe": cls._strafe, "spin": cls._spin,
            "figure-8": cls._figure8, "return": cls._return, "stop": cls._stop,
        }
        self._writers = tuple(writers[name] for name, _ in self.SEGMENTS)
        self._durations = tuple(d for _, d in self.SEGMENTS)
        self._count = len(self.SEGMENTS)
        self._fig8_w = 2.0 * math.pi / dict(self.SEGMENTS)["figure-8"]
        self._index = 0          # current segment (small int: no allocation)
        self._t = 0.0            # time inside the segment, s

    def write(self, cv: ChassisVelocities) -> None:
        """Write this step's field-relative command (m/s, rad/s) into ``cv`` and advance
        the script by one period."""
        t = self._t
        if t >= self._durations[self._index] - 1e-9:
            self._index = (self._index + 1) % self._count
            t = 0.0
        self._writers[self._index](self, t, cv)
        self._t = t + DT

    def _set(self, cv, jx, jy, jr):
        cv.vx = jx * self._max_speed
        cv.vy = jy * self._max_speed
        cv.omega = jr * self._max_omega

    def _forward(self, t, cv):
        self._set(cv, 0.5, 0.0, 0.0)

    def _strafe(self, t, cv):
        self._set(cv, 0.0, 0.5, 0.0)

    def _spin(self, t, cv):
        self._set(cv, 0.0, 0.0, 0.5)

    def _figure8(self, t, cv):
        w = self._fig8_w
        self._set(cv, 0.3 * _cos(w * t), 0.3 * _cos(2.0 * w * t), 0.35)

    def _return(self, t, cv):
        self._set(cv, -0.5, -0.5, 0.0)

    def _stop(self, t, cv):
        self._set(cv, 0.0, 0.0, 0.0)


# ---------------------------------------------------------------------------------------
# Swerve drivetrain

class SwerveModuleSim:
    """One swerve module's response to its target, updating caller-visible objects in
    place: ``state`` (measured SwerveModuleVelocity), ``position`` (cumulative
    SwerveModulePosition, like the encoders) and ``delta`` (the change of ``position``
    over the last step, at the new angle, as WPILib's odometry uses it).

    Model: WPILib's ``optimize`` (never steer more than 90°), steering rate-limited to
    ``max_steer_rate`` rad/s towards the target, wheel speed a first-order lag with time
    constant ``tau`` s towards the cosine-scaled target (a module that still points the
    wrong way does not push)."""

    __slots__ = ("target", "state", "position", "delta", "_alpha", "_max_step")

    def __init__(self, target: SwerveModuleVelocity, tau: float, max_steer_rate: float):
        self.target = target
        self.state = SwerveModuleVelocity(0.0, Rotation2d())
        self.position = SwerveModulePosition(0.0, Rotation2d())
        self.delta = SwerveModulePosition(0.0, Rotation2d())
        self._alpha = 1.0 - math.exp(-DT / tau)
        self._max_step = max_steer_rate * DT

    def update(self) -> None:
        state = self.state
        current = state.angle                         # Rotation2d (freelist)
        desired = self.target.optimize(current)       # new object (freelist)
        goal = desired.angle
        error = goal.minus(current).getRadians()
        limit = self._max_step
        if error > limit:
            error = limit
        elif error < -limit:
            error = -limit
        angle = current.plus(_from_radians(error))
        state.angle = angle                           # the setter copies the value
        command = desired.velocity * goal.minus(angle).getCos()
        v = state.velocity
        v = v + (command - v) * self._alpha
        state.velocity = v
        position = self.position
        last = position.distance
        position.distance = last + v * DT
        delta = self.delta
        delta.distance = position.distance - last     # encoder delta, as odometry does
        delta.angle = angle


class SwerveDrive:
    """Four-module swerve robot: inverse kinematics with desaturation, the module model,
    forward kinematics and pose integration, all writing into preallocated objects."""

    name = "swerve"
    HALF_TRACK = 0.3        # m, module offset from the robot centre in x and y
    WHEEL_TAU = 0.05        # s, wheel-speed time constant
    STEER_RATE = 4.0 * math.pi   # rad/s, steering rate limit

    __slots__ = ("max_speed", "kinematics", "targets", "deltas", "twist", "pose",
                 "distance", "_m0", "_m1", "_m2", "_m3")

    def __init__(self, max_speed: float) -> None:
        h = self.HALF_TRACK
        self.max_speed = float(max_speed)
        self.kinematics = SwerveDriveKinematics(
            Translation2d(h, h), Translation2d(h, -h), Translation2d(-h, h), Translation2d(-h, -h))
        self.targets = [SwerveModuleVelocity() for _ in range(4)]
        modules = [SwerveModuleSim(t, self.WHEEL_TAU, self.STEER_RATE) for t in self.targets]
        self._m0, self._m1, self._m2, self._m3 = modules
        self.deltas = [m.delta for m in modules]
        self.twist = Twist2d()
        self.pose = Pose2d()
        self.distance = 0.0     # path length of the robot centre, m

    def describe(self) -> str:
        h = self.HALF_TRACK
        return (f"swerve, 4 modules at (±{h:.2f}, ±{h:.2f}) m; wheel lag τ = "
                f"{self.WHEEL_TAU * 1000:.0f} ms, steering ≤ {self.STEER_RATE:.1f} rad/s")

    def step(self, command: ChassisVelocities) -> None:
        """Run one control period for a field-relative ``command`` (overwritten: it is the
        scratch object the chain works in)."""
        command.toRobotRelativeInto(self.pose.getRotation(), command)
        command.discretizeInto(DT, command)
        self.kinematics.toSwerveModuleVelocitiesInto(command, self.targets)
        _desaturate_in_place(self.targets, self.max_speed)
        # Unrolled on purpose: a ``for`` over the modules would allocate an iterator.
        self._m0.update()
        self._m1.update()
        self._m2.update()
        self._m3.update()
        twist = self.twist
        self.kinematics.toTwist2dInto(self.deltas, twist)
        self.pose = self.pose.exp(twist)
        self.distance += _hypot(twist.dx, twist.dy)   # arc length of a constant twist


DRIVETRAINS = {"swerve": SwerveDrive}


# ---------------------------------------------------------------------------------------
# Simulation and measurement

class Simulation:
    """Driver script + drivetrain; :meth:`step` is one 20 ms control period."""

    __slots__ = ("script", "drive", "command")

    def __init__(self, drivetrain: str, max_speed: float, max_omega: float) -> None:
        self.script = JoystickScript(max_speed, max_omega)
        self.drive = DRIVETRAINS[drivetrain](max_speed)
        self.command = ChassisVelocities()

    def step(self) -> None:
        self.script.write(self.command)
        self.drive.step(self.command)


def prepared_simulation(args) -> Simulation:
    """Return a fresh simulation (robot at the origin, script at t = 0) with the process
    warmed up for it.

    Order matters: ``gc.collect()`` first, so pending garbage is not collected inside the
    measured loop (a full collection also empties CPython's float/tuple freelists); then
    the measured simulation is built; then a throw-away simulation runs one script cycle
    (caches, specialised bytecode) and is freed by reference counting, which refills the
    freelists the measured loop draws from."""
    gc.collect()
    sim = Simulation(args.drivetrain, args.max_speed, args.max_omega)
    warm = Simulation(args.drivetrain, args.max_speed, args.max_omega)
    step = warm.step
    for _ in itertools.repeat(None, round(JoystickScript.CYCLE / DT)):
        step()
    del warm, step
    return sim


def timing_pass(args, steps: int):
    """Run ``steps`` steps on a fresh simulation, timing each one; tracemalloc is off."""
    sim = prepared_simulation(args)
    samples = array("q", bytes(8 * steps))
    step = sim.step
    clock = time.perf_counter_ns
    gc0 = gc.get_count()
    col0 = sum(s["collections"] for s in gc.get_stats())
    wall0 = clock()
    for i in range(steps):
        t0 = clock()
        step()
        samples[i] = clock() - t0
    wall = clock() - wall0
    gc1 = gc.get_count()
    col1 = sum(s["collections"] for s in gc.get_stats())
    return sim, samples, wall, tuple(b - a for a, b in zip(gc0, gc1)), col1 - col0


def allocation_pass(args, steps: int):
    """Run ``steps`` steps on a fresh simulation under tracemalloc (no timing)."""
    sim = prepared_simulation(args)
    step = sim.step
    loop = itertools.repeat(None, steps)    # created before the measurement starts
    # Readings are stored into preallocated arrays, so the returned tuples and ints are
    # freed at once and do not show up as live blocks or as peak.
    mem = array("q", [0, 0, 0])             # traced bytes: start, end, peak
    gcc = array("q", [0] * 6)               # gc.get_count() before and after
    already = tracemalloc.is_tracing()
    if not already:
        tracemalloc.start()
    before = tracemalloc.take_snapshot()
    gcc[0], gcc[1], gcc[2] = gc.get_count()
    mem[0] = tracemalloc.get_traced_memory()[0]
    tracemalloc.reset_peak()                # peak := current == mem[0] (temporaries freed)
    for _ in loop:
        step()
    mem[1], mem[2] = tracemalloc.get_traced_memory()
    gcc[3], gcc[4], gcc[5] = gc.get_count()
    after = tracemalloc.take_snapshot()
    if not already:
        tracemalloc.stop()
    ignore = [tracemalloc.Filter(False, tracemalloc.__file__)]
    diff = after.filter_traces(ignore).compare_to(before.filter_traces(ignore), "filename")
    blocks = sum(d.count_diff for d in diff)
    return {
        "sim": sim,
        "peak_bytes": mem[2] - mem[0],
        "net_bytes": mem[1] - mem[0],
        "net_blocks": blocks,
        "gc_growth": (gcc[3] - gcc[0], gcc[4] - gcc[1], gcc[5] - gcc[2]),
    }


def _percentile(sorted_samples, p: float) -> int:
    """Nearest-rank percentile of an ascending sequence."""
    n = len(sorted_samples)
    return sorted_samples[max(0, min(n - 1, math.ceil(p / 100.0 * n) - 1))]


def _pose_dict(drive) -> dict:
    pose = drive.pose
    return {"x_m": pose.x, "y_m": pose.y, "heading_deg": pose.getRotation().getDegrees()}


def run(args) -> dict:
    steps = round(args.seconds / DT)
    sim1, samples, wall, gc_growth, collections = timing_pass(args, steps)
    alloc = allocation_pass(args, steps)
    ordered = sorted(samples)
    mean = sum(samples) / steps
    p50, p99, worst = _percentile(ordered, 50), _percentile(ordered, 99), ordered[-1]
    pose1, pose2 = _pose_dict(sim1.drive), _pose_dict(alloc["sim"].drive)
    return {
        "drivetrain": args.drivetrain,
        "robot_seconds": steps * DT,
        "steps": steps,
        "dt_s": DT,
        "max_speed_mps": args.max_speed,
        "max_omega_radps": args.max_omega,
        "latency_us": {"p50": p50 / 1e3, "p99": p99 / 1e3, "max": worst / 1e3,
                       "mean": mean / 1e3},
        "budget_pct": {"p99": 100.0 * p99 / BUDGET_NS, "mean": 100.0 * mean / BUDGET_NS},
        "loop_wall_s": wall / 1e9,
        "realtime_factor": steps * DT / (wall / 1e9),
        "allocations": {"traced_peak_bytes": alloc["peak_bytes"],
                        "traced_net_bytes": alloc["net_bytes"],
                        "net_blocks": alloc["net_blocks"]},
        "gc": {"count_growth_timing_pass": list(gc_growth),
               "count_growth_allocation_pass": list(alloc["gc_growth"]),
               "collections_timing_pass": collections},
        "final_pose": pose1,
        "distance_m": sim1.drive.distance,
        "passes_agree": pose1 == pose2 and sim1.drive.distance == alloc["sim"].drive.distance,
    }


# ---------------------------------------------------------------------------------------
# Output

def _header(args, steps: int) -> str:
    drive = DRIVETRAINS[args.drivetrain](args.max_speed)
    segments = " · ".join(f"{name} {d:g} s" for name, d in JoystickScript.SEGMENTS)
    return "\n".join([
        f"drivekin {drivekin.__version__} — simulated 50 Hz {args.drivetrain} control loop, "
        "allocation-free path",
        f"  robot    {drive.describe()}",
        f"  limits   wheel speed {args.max_speed:g} m/s, joystick rotation "
        f"{args.max_omega:.2f} rad/s",
        f"  script   field-relative, repeats every {JoystickScript.CYCLE:g} s: {segments}",
        "  step     toRobotRelativeInto → discretizeInto → toSwerveModuleVelocitiesInto →",
        "           desaturateWheelVelocitiesInPlace → module model → toTwist2dInto → pose.exp",
        f"  run      {steps * DT:g} s robot time = {steps} steps, flat out (no sleeping);",
        "           pass 1 times each step (tracemalloc off), pass 2 counts allocations",
        "           (tracemalloc on); one warm-up script cycle before each pass",
        "",
    ])


def _table(r: dict) -> str:
    lat, bud, al, g, pose = (r["latency_us"], r["budget_pct"], r["allocations"], r["gc"],
                             r["final_pose"])
    growth = ", ".join(f"{v:+d}" for v in g["count_growth_timing_pass"])
    growth2 = ", ".join(f"{v:+d}" for v in g["count_growth_allocation_pass"])
    rows = [
        ("latency per step", "", ""),
        ("  p50", f"{lat['p50']:.2f} µs", f"{100 * lat['p50'] * 1e3 / BUDGET_NS:.3f} % of 20 ms"),
        ("  p99", f"{lat['p99']:.2f} µs", f"{bud['p99']:.3f} % of 20 ms"),
        ("  max", f"{lat['max']:.2f} µs", f"{100 * lat['max'] * 1e3 / BUDGET_NS:.3f} % of 20 ms"),
        ("  mean", f"{lat['mean']:.2f} µs", f"{bud['mean']:.3f} % of 20 ms"),
        ("  whole loop", f"{r['loop_wall_s'] * 1e3:.1f} ms",
         f"{r['realtime_factor']:,.0f}× real time"),
        ("allocations (pass 2)", "", ""),
        ("  traced peak - start", f"{al['traced_peak_bytes']} B", "tracemalloc"),
        ("  traced end - start", f"{al['traced_net_bytes']} B", ""),
        ("  blocks still alive", f"{al['net_blocks']}", "snapshot diff"),
        ("  gc.get_count() growth", f"{growth}", f"gen 0, 1, 2 (pass 2: {growth2})"),
        ("  gc collections", f"{g['collections_timing_pass']}", "during pass 1"),
        ("result", "", ""),
        ("  final pose", f"x {pose['x_m']:.3f} m, y {pose['y_m']:.3f} m",
         f"heading {pose['heading_deg']:.2f}°"),
        ("  distance travelled", f"{r['distance_m']:.2f} m", "odometry path length"),
        ("  passes agree", "yes" if r["passes_agree"] else "NO", "pass 1 pose == pass 2 pose"),
    ]
    w0 = max(len(a) for a, _, _ in rows)
    w1 = max(len(b) for _, b, _ in rows)
    return "\n".join(f"{a:<{w0}}  {b:>{w1}}  {c}".rstrip() if b else a for a, b, c in rows)


def _positive_float(text: str) -> float:
    value = float(text)
    if not (value > 0.0 and math.isfinite(value)):
        raise argparse.ArgumentTypeError(f"must be a positive number, got {text}")
    return value


def parse_args(argv=None):
    parser = argparse.ArgumentParser(
        prog="python -m drivekin",
        description=(
            "Simulate a 50 Hz swerve drive control loop on drivekin's allocation-free path "
            "and report per-step latency against the 20 ms budget, allocator activity and "
            "the final odometry pose. A scripted driver (forward, strafe, spin, "
            "figure-eight while rotating, return, stop; repeating every 30 s) feeds "
            "field-relative commands; each step converts them to robot-relative, "
            "discretizes, runs inverse kinematics, desaturates, applies a module response "
            "model (steering rate limit, wheel-speed lag) and integrates the pose from the "
            "module position deltas. The loop runs as fast as it can (no sleeping); it is "
            "run twice on identical simulations: once timed with tracemalloc off, once "
            "under tracemalloc to count allocations."),
        epilog="Example: python -m drivekin --seconds 60 --max-speed 4",
    )
    parser.add_argument("--seconds", type=_positive_float, default=180.0, metavar="S",
                        help="simulated robot time in seconds; steps = S / 0.02 "
                             "(default: 180, i.e. 9000 steps)")
    parser.add_argument("--max-speed", type=_positive_float, default=4.5, metavar="MPS",
                        help="attainable wheel speed in m/s: full stick deflection and the "
                             "desaturation limit (default: 4.5)")
    parser.add_argument("--max-omega", type=_positive_float, default=2.0 * math.pi,
                        metavar="RADPS",
                        help="rotation rate in rad/s at full rotation stick (default: 2π)")
    parser.add_argument("--drivetrain", choices=sorted(DRIVETRAINS), default="swerve",
                        help="drivetrain to simulate (default: swerve)")
    out = parser.add_mutually_exclusive_group()
    out.add_argument("--quiet", action="store_true",
                     help="print only the results table, without the header")
    out.add_argument("--json", action="store_true",
                     help="print the results as one JSON object instead of text")
    return parser.parse_args(argv)


def main(argv=None) -> int:
    args = parse_args(argv)
    steps = round(args.seconds / DT)
    if steps < 1:
        print(f"--seconds {args.seconds} is shorter than one 20 ms step", file=sys.stderr)
        return 2
    result = run(args)
    if args.json:
        print(json.dumps(result, indent=2))
    else:
        if not args.quiet:
            print(_header(args, steps))
        print(_table(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
