"""The demo's two measured passes over identical simulations: per-step timing
(tracemalloc off) and allocation counting (tracemalloc and the allocator-call counter)."""
from __future__ import annotations

import gc
import itertools
import math
import sys
import time
import tracemalloc
from array import array

from drivekin import ChassisVelocities
from drivekin._core.alloccount import AllocationCounter
from drivekin.app.demo.drivetrains import drivetrain_class, make_drivetrain
from drivekin.app.demo.sim import _pose_dict
from drivekin.app.demo.script import BUDGET_NS, DT, JoystickScript


class Simulation:
    """Driver script + drivetrain; :meth:`step` is one 20 ms control period."""

    __slots__ = ("script", "drive", "command")

    def __init__(self, drivetrain: str, max_speed: float, max_omega: float,
                 vision: bool = False, setpoint_generator: bool = False) -> None:
        self.script = JoystickScript(max_speed, max_omega)
        self.drive = make_drivetrain(drivetrain, max_speed, vision, setpoint_generator)
        self.command = ChassisVelocities()

    @classmethod
    def from_args(cls, args) -> "Simulation":
        """The simulation the command line's ``args`` describe."""
        return cls(args.drivetrain, args.max_speed, args.max_omega, args.vision,
                   getattr(args, "setpoint_generator", False))

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
    sim = Simulation.from_args(args)
    warm = Simulation.from_args(args)
    step = warm.step
    for _ in itertools.repeat(None, round(JoystickScript.CYCLE / DT)):
        step()
    del warm, step
    return sim


def timing_pass(args, steps: int):
    """Run ``steps`` steps on a fresh simulation, timing each one; tracemalloc is off."""
    sim = prepared_simulation(args)
    samples = array("q", bytes(8 * steps))
    sim.drive.start_timing(steps)           # drivetrains that time a part of their step
    step = sim.step
    clock = time.perf_counter_ns
    gcc = array("q", [0] * 6)               # gc.get_count(): start, end (as in pass 2)
    col0 = sum(s["collections"] for s in gc.get_stats())
    gcc[0], gcc[1], gcc[2] = gc.get_count()
    wall0 = clock()
    for i in range(steps):
        t0 = clock()
        step()
        samples[i] = clock() - t0
    wall = clock() - wall0
    gcc[3], gcc[4], gcc[5] = gc.get_count()
    col1 = sum(s["collections"] for s in gc.get_stats())
    growth = (gcc[3] - gcc[0], gcc[4] - gcc[1], gcc[5] - gcc[2])
    return sim, samples, wall, growth, col1 - col0


def allocation_pass(args, steps: int):
    """Run ``steps`` steps on a fresh simulation under tracemalloc (no timing)."""
    sim = prepared_simulation(args)
    step = sim.step
    loop = itertools.repeat(None, steps)    # created before the measurement starts
    # Readings are stored into preallocated arrays, so the tuples and ints the calls
    # return are freed at once and count neither as live blocks nor towards the peak.
    mem = array("q", [0, 0, 0])             # traced bytes: start, end, peak
    blk = array("q", [0, 0])                # sys.getallocatedblocks(): start, end
    gcc = array("q", [0] * 6)               # gc.get_count(): start, end
    counter = AllocationCounter()
    # Bound once here: looking the methods up inside the measured region would allocate.
    count_on, count_off = counter.__enter__, counter.__exit__
    already = tracemalloc.is_tracing()
    if not already:
        tracemalloc.start()
    gcc[0], gcc[1], gcc[2] = gc.get_count()
    blk[0] = sys.getallocatedblocks()
    mem[0] = tracemalloc.get_traced_memory()[0]
    tracemalloc.reset_peak()                # peak := current == mem[0] (temporaries freed)
    count_on()                              # hooks the allocators on top of tracemalloc's
    for _ in loop:
        step()
    count_off(None, None, None)
    mem[1], mem[2] = tracemalloc.get_traced_memory()
    blk[1] = sys.getallocatedblocks()
    gcc[3], gcc[4], gcc[5] = gc.get_count()
    if not already:
        tracemalloc.stop()
    return {
        "sim": sim,
        "allocator_calls": counter.calls,
        "peak_bytes": mem[2] - mem[0],
        "net_bytes": mem[1] - mem[0],
        "net_blocks": blk[1] - blk[0],
        "gc_growth": (gcc[3] - gcc[0], gcc[4] - gcc[1], gcc[5] - gcc[2]),
    }


def _percentile(sorted_samples, p: float) -> int:
    """Nearest-rank percentile of an ascending sequence."""
    n = len(sorted_samples)
    return sorted_samples[max(0, min(n - 1, math.ceil(p / 100.0 * n) - 1))]


def run(args) -> dict:
    """Run both passes and return the results as a JSON-ready dict.

    ``args`` needs ``drivetrain`` (a key of :data:`DRIVETRAINS`), ``vision``, ``seconds``,
    ``max_speed`` and ``max_omega``, and may have ``setpoint_generator``; the command line
    validates them."""
    steps = round(args.seconds / DT)
    sim1, samples, wall, gc_growth, collections = timing_pass(args, steps)
    alloc = allocation_pass(args, steps)
    ordered = sorted(samples)
    mean = sum(samples) / steps
    p50, p99, worst = _percentile(ordered, 50), _percentile(ordered, 99), ordered[-1]
    pose1, pose2 = _pose_dict(sim1.drive.pose), _pose_dict(alloc["sim"].drive.pose)
    return {
        "drivetrain": args.drivetrain,
        "odometry": drivetrain_class(args.drivetrain, args.vision).ODOMETRY.__name__,
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
        "allocations": {"allocator_calls": alloc["allocator_calls"],
                        "traced_peak_bytes": alloc["peak_bytes"],
                        "traced_net_bytes": alloc["net_bytes"],
                        "net_blocks": alloc["net_blocks"]},
        "gc": {"count_growth_timing_pass": list(gc_growth),
               "count_growth_allocation_pass": list(alloc["gc_growth"]),
               "collections_timing_pass": collections},
        "final_pose": pose1,
        "distance_m": sim1.drive.distance,
        "passes_agree": (pose1 == pose2 and sim1.drive.distance == alloc["sim"].drive.distance
                         and sim1.drive.results() == alloc["sim"].drive.results()),
        **sim1.drive.results(),
        **sim1.drive.timing_results(),
    }


