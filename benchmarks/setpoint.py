"""drivekin's SwerveSetpointGenerator against robotpy-pathplannerlib's, per call, in one run.

    python benchmarks/setpoint.py            # the table, about 5 s
    python benchmarks/setpoint.py --quick    # CI smoke run, about 1 s
    python benchmarks/setpoint.py --json FILE   # also the raw per-round numbers

The robot: four modules at (±0.3, ±0.3) m (``_common.INPUTS``), 60 kg, 6 kg·m², 0.0508 m
wheels, 4.5 m/s top speed, wheel COF 1.2, one Kraken X60 per module through a 6.75:1
reduction, 60 A current limit, module steering ≤ 10 rot/s (20π rad/s); dt 20 ms, input
voltage 12 V passed explicitly on both sides (pathplannerlib would otherwise read
``RobotController.getInputVoltage()``), no PathConstraints.

The commands are a closed loop over a ramped, changing target, not a constant: every call
takes the next of ``CYCLE`` = 200 prebuilt robot-relative commands (4 s at 50 Hz,
triangle waves: vx ±4 m/s over 4 s, vy ±2 m/s over 2 s, ω ±3 rad/s over 1 s, phased so
that their peaks meet and the desired module speeds exceed 4.5 m/s in 22 of the 200) and
the previous call's setpoint, as a robot program calls it.

Cases (each with its own generator, setpoint and command cycle):

* ``pathplannerlib``: ``pathplannerlib.util.swerve.SwerveSetpointGenerator.generateSetpoint
  (prev, desired, dt, input_voltage)`` on ``ChassisSpeeds``, its config a
  ``pathplannerlib.config.RobotConfig`` with ``ModuleConfig(..., DCMotor.krakenX60(1)
  .withReduction(6.75), 60, 1)``; as shipped (its two discarded results included, see
  docs/setpoints.md);
* drivekin ``generateSetpoint`` (returns a new SwerveSetpoint), default mode and
  ``compatibility="pathplanner"``;
* drivekin ``generateSetpointInto(prev, desired, dt, out=prev, inputVoltage)``, both modes
  (allocation-free: the setpoint is updated in place);
* ``drivekin.batch.generateSetpoints`` over the 200 commands as a (200, 3) array, from the
  loop's steady setpoint; reported per row (call time / 200).

Method: ratio_table.py's (``Timed``, ``pin``): one process pinned to one CPU, GC off, cases
interleaved with their order rotated every round, ``--rounds`` rounds of ``--repeat``
samples; µs/call = the minimum over all samples. Unlike the registry's statements these
calls carry state, so a sample runs whole command cycles (its call count is a multiple of
200) and every sample of every case averages the same commands; the setpoint is kept
across samples. Before timing: drivekin ``compatibility="pathplanner"`` must agree to 1e-9
with pathplannerlib once its two discarded results are corrected (each step fed the same
previous setpoint, over two cycles), and ``generateSetpoint``, ``generateSetpointInto`` and
the batch form must give bit-identical setpoints in each mode; the differences to
pathplannerlib as shipped are printed.

Not in ``registry.py``: its statements are stateless and all checked against their robotpy
case to 1e-9, while these carry a setpoint from call to call and pathplannerlib as shipped
agrees with neither drivekin mode.

Goal (the setpoint-generator issue): ≤ 2 µs per four-module generateSetpoint and ≥ 60×
pathplannerlib's speed. ``--strict`` exits 1 when a value check fails or a goal is missed.
"""
from __future__ import annotations

import argparse
import contextlib
import itertools
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

from _common import INPUTS, machine_description
from ratio_table import Timed, pin, run_rounds

CYCLE = 200                      # commands per cycle (4 s at 50 Hz)
DT = 0.02                        # s
VOLTS = 12.0                     # V, passed explicitly to both libraries
GOAL_US = 2.0                    # µs per four-module generateSetpoint
GOAL_SPEEDUP = 60.0              # pathplannerlib time / drivekin time
TOL = 1e-9

# The robot (both libraries get these numbers).
MASS, MOI = 60.0, 6.0            # kg, kg·m²
WHEEL_RADIUS, VMAX, COF = 0.0508, 4.5, 1.2   # m, m/s, -
GEARING, CURRENT_LIMIT = 6.75, 60.0          # :1, A
MAX_STEER = 10.0 * 2.0 * math.pi             # rad/s (10 rot/s)


def triangle(t: float, period: float) -> float:
    """A triangle wave in [-1, 1], 0 at t = 0 and rising."""
    x = (t / period + 0.25) % 1.0
    return 4.0 * x - 1.0 if x < 0.5 else 3.0 - 4.0 * x


def commands() -> np.ndarray:
    """(CYCLE, 3) robot-relative [vx m/s, vy m/s, omega rad/s]."""
    t = [k * DT for k in range(CYCLE)]
    return np.array([[4.0 * triangle(x, 4.0), 2.0 * triangle(x + 0.5, 2.0),
                      3.0 * triangle(x + 0.25, 1.0)] for x in t], dtype=np.float64)


# ---------------------------------------------------------------------------------------
# The two libraries

def pp_objects():
    from pathplannerlib.config import ModuleConfig, RobotConfig
    from pathplannerlib.util import DriveFeedforwards
    from pathplannerlib.util.swerve import SwerveSetpoint, SwerveSetpointGenerator
    from wpimath.geometry import Translation2d
    from wpimath.kinematics import ChassisSpeeds, SwerveModuleState
    from wpimath.system.plant import DCMotor

    config = RobotConfig(MASS, MOI, ModuleConfig(
        WHEEL_RADIUS, VMAX, COF, DCMotor.krakenX60(1).withReduction(GEARING), CURRENT_LIMIT,
        1), [Translation2d(x, y) for x, y in INPUTS.modules])

    def generator():
        return SwerveSetpointGenerator(config, MAX_STEER)

    def zero():
        return SwerveSetpoint(ChassisSpeeds(), [SwerveModuleState() for _ in INPUTS.modules],
                              DriveFeedforwards.zeros(len(INPUTS.modules)))

    def speeds(cmds):
        return [ChassisSpeeds(*map(float, c)) for c in cmds]

    return generator, zero, speeds


def dk_objects():
    import drivekin as dk

    config = dk.RobotConfig(MASS, MOI, dk.ModuleConfig(
        WHEEL_RADIUS, VMAX, COF, dk.DCMotor.getKrakenX60(1).withReduction(GEARING),
        CURRENT_LIMIT, 1), [dk.Translation2d(x, y) for x, y in INPUTS.modules])

    def generator(compatibility=None):
        # pathplannerlib reads its brownout voltage from RobotController (6.75 V in
        # simulation); with 12 V in, neither library reaches it.
        return dk.SwerveSetpointGenerator(config, MAX_STEER, compatibility=compatibility)

    def zero():
        return dk.SwerveSetpoint(dk.ChassisVelocities(),
                                 [dk.SwerveModuleVelocity() for _ in INPUTS.modules],
                                 dk.DriveFeedforwards.zeros(len(INPUTS.modules)))

    def velocities(cmds):
        return [dk.ChassisVelocities(*map(float, c)) for c in cmds]

    return generator, zero, velocities


# ---------------------------------------------------------------------------------------
# Value checks

def pp_flat(s) -> list:
    c = s.robot_relative_speeds
    f = s.feedforwards
    return ([c.vx, c.vy, c.omega]
            + [x for m in s.module_states for x in (m.speed, m.angle.cos(), m.angle.sin())]
            + [x for row in (f.accelerationsMPS, f.forcesNewtons, f.torqueCurrentsAmps,
                             f.robotRelativeForcesXNewtons, f.robotRelativeForcesYNewtons)
               for x in row])


def dk_flat(s) -> list:
    c = s.robotRelativeVelocities
    f = s.feedforwards
    return ([c.vx, c.vy, c.omega]
            + [x for m in s.moduleVelocities
               for x in (m.velocity, m.angle.getCos(), m.angle.getSin())]
            + [x for row in (f.accelerationsMPSSq, f.linearForcesNewtons, f.torqueCurrentsAmps,
                             f.robotRelativeForcesXNewtons, f.robotRelativeForcesYNewtons)
               for x in row])


def rel_diff(a, b) -> float:
    return max(abs(x - y) / max(1.0, abs(x)) for x, y in zip(a, b))


class corrected_pathplannerlib:
    """Context manager: pathplannerlib.util.swerve with its two discarded results made to
    take effect, as PathPlannerLib Java behaves (``ret_speeds.discretize(ret_speeds, dt)``
    writes the result into ret_speeds; ``SwerveDrive4Kinematics.desaturateWheelSpeeds``
    writes its result back into the states). Used for the value check only."""

    def __enter__(self):
        import pathplannerlib.util.swerve as ppsw
        import wpimath.kinematics as wk

        class CS(wk.ChassisSpeeds):
            def discretize(self, other, dt):
                d = wk.ChassisSpeeds.discretize(other, dt)
                self.vx, self.vy, self.omega = d.vx, d.vy, d.omega

        class K4(wk.SwerveDrive4Kinematics):
            @staticmethod
            def desaturateWheelSpeeds(states, v):
                for s, x in zip(states, wk.SwerveDrive4Kinematics.desaturateWheelSpeeds(states, v)):
                    s.speed, s.angle = x.speed, x.angle

        self.mod, self.saved = ppsw, (ppsw.ChassisSpeeds, ppsw.SwerveDrive4Kinematics)
        ppsw.ChassisSpeeds, ppsw.SwerveDrive4Kinematics = CS, K4
        return self

    def __exit__(self, *exc):
        self.mod.ChassisSpeeds, self.mod.SwerveDrive4Kinematics = self.saved


def grow(gap, a, b):
    """gap[i] := max(gap[i], |a - b|) for chassis velocity (m/s, rad/s), module speed
    (m/s), module angle (rad, from the unit vectors) and linear force (N)."""
    n = len(INPUTS.modules)
    gap[0] = max(gap[0], max(abs(x - y) for x, y in zip(a[:3], b[:3])))
    for m in range(n):
        i = 3 + 3 * m
        gap[1] = max(gap[1], abs(a[i] - b[i]))
        gap[2] = max(gap[2], 2.0 * math.asin(min(1.0, 0.5 * math.hypot(a[i + 1] - b[i + 1],
                                                                       a[i + 2] - b[i + 2]))))
    f = 3 + 3 * n + n                        # linearForcesNewtons
    gap[3] = max(gap[3], max(abs(x - y) for x, y in zip(a[f:f + n], b[f:f + n])))


def gap_text(gap) -> str:
    return (f"chassis {gap[0]:.3g} (m/s or rad/s), module speed {gap[1]:.3g} m/s, "
            f"module angle {gap[2]:.3g} rad, linear force {gap[3]:.3g} N")


def to_dk(s):
    import drivekin as dk

    c = s.robot_relative_speeds
    f = s.feedforwards
    return dk.SwerveSetpoint(
        dk.ChassisVelocities(c.vx, c.vy, c.omega),
        [dk.SwerveModuleVelocity(m.speed, dk.Rotation2d(m.angle.radians()))
         for m in s.module_states],
        dk.DriveFeedforwards(f.accelerationsMPS, f.forcesNewtons, f.torqueCurrentsAmps,
                             f.robotRelativeForcesXNewtons, f.robotRelativeForcesYNewtons))


def check(cmds, pp, dk_) -> tuple[list, list, object]:
    """The value checks; returns (notes, failures, steady drivekin setpoints by mode)."""
    import drivekin.batch as batch

    pp_gen, pp_zero, pp_speeds = pp
    dk_gen, dk_zero, dk_vel = dk_
    notes, failures = [], []
    cs, cv = pp_speeds(cmds), dk_vel(cmds)

    # 1. Resync over two cycles (the first from rest): pathplannerlib's setpoint of each step
    #    is fed, converted, to drivekin too. Closed loop, two correct implementations part
    #    by more than rounding (tests/reference/test_setpoint_pathplanner.py says why).
    worst = {"corrected": 0.0}
    gaps = {"shipped": [0.0] * 4, "default": [0.0] * 4}
    for label, fix in (("corrected", True), ("shipped", False)):
        gens = {m: dk_gen(m) for m in (None, "pathplanner")}
        with (corrected_pathplannerlib() if fix else contextlib.nullcontext()):
            g, s = pp_gen(), pp_zero()
            for k in range(2 * CYCLE):
                prev = to_dk(s)
                s = g.generateSetpoint(s, cs[k % CYCLE], DT, VOLTS)
                compat = gens["pathplanner"].generateSetpoint(prev, cv[k % CYCLE], DT, VOLTS)
                if fix:
                    worst[label] = max(worst[label], rel_diff(pp_flat(s), dk_flat(compat)))
                    default = gens[None].generateSetpoint(prev, cv[k % CYCLE], DT, VOLTS)
                    grow(gaps["default"], dk_flat(compat), dk_flat(default))
                else:
                    grow(gaps["shipped"], pp_flat(s), dk_flat(compat))
    if worst["corrected"] > TOL:
        failures.append(f"compatibility='pathplanner' vs corrected pathplannerlib: "
                        f"{worst['corrected']:.2e} > {TOL:g}")
    notes.append(f"compatibility='pathplanner' vs pathplannerlib with its two discarded "
                 f"results corrected: worst relative difference {worst['corrected']:.1e} "
                 f"over {2 * CYCLE} steps, each fed pathplannerlib's previous setpoint "
                 f"(tolerance {TOL:g}: max(1, |value|) · {TOL:g} on every number)")
    notes.append("pathplannerlib as shipped vs compatibility='pathplanner', same feeding "
                 "(the effect of its discarded discretize and desaturate), largest "
                 "differences: " + gap_text(gaps["shipped"]))
    notes.append("default mode vs compatibility='pathplanner', same feeding, largest "
                 "differences: " + gap_text(gaps["default"]))

    # 2. generateSetpoint == generateSetpointInto (closed loop, one cycle from rest), then
    #    batch.generateSetpoints over the next cycle == Into continued, bit for bit. The
    #    setpoint after the first cycle is also the batch cases' start.
    steady = {}
    for mode in (None, "pathplanner"):
        ga, gb = dk_gen(mode), dk_gen(mode)
        a, b = dk_zero(), dk_zero()
        same = True
        for k in range(CYCLE):
            a = ga.generateSetpoint(a, cv[k], DT, VOLTS)
            gb.generateSetpointInto(b, cv[k], DT, b, VOLTS)
            same = same and a == b
        steady[mode] = a
        velocities, modules, feedforwards = batch.generateSetpoints(ga, a, cmds, DT, VOLTS)
        rows = []
        for k in range(CYCLE):
            gb.generateSetpointInto(b, cv[k], DT, b, VOLTS)
            c, f = b.robotRelativeVelocities, b.feedforwards
            rows.append([c.vx, c.vy, c.omega]
                        + [x for m in b.moduleVelocities
                           for x in (m.velocity, m.angle.getRadians())]
                        + [x for r in (f.accelerationsMPSSq, f.linearForcesNewtons,
                                       f.torqueCurrentsAmps, f.robotRelativeForcesXNewtons,
                                       f.robotRelativeForcesYNewtons) for x in r])
        got = np.concatenate([velocities, modules.reshape(CYCLE, -1),
                              feedforwards.reshape(CYCLE, -1)], axis=1)
        batch_same = np.array_equal(got, np.array(rows))
        if not (same and batch_same):
            failures.append(f"mode {mode!r}: generateSetpoint == generateSetpointInto "
                            f"{same}, batch == generateSetpointInto {batch_same}")
    if not failures:
        notes.append("generateSetpoint, generateSetpointInto and batch.generateSetpoints: "
                     "bit-identical in both modes (closed loop, 2 cycles)")
    return notes, failures, steady


# ---------------------------------------------------------------------------------------
# Cases

def compile_stateful_timer(stmt: str, env: dict, state: list):
    """``timer(n) -> seconds`` running ``stmt`` n times, like _common.compile_timer, with
    ``s`` (the setpoint the statement reads and may rebind) kept in ``state[0]`` across
    calls; it is loaded before the clock starts and stored after it stops."""
    names = sorted(env)
    for n in names:
        if not n.isidentifier() or n.startswith("_") or n == "s":
            raise ValueError(f"bad benchmark local name {n!r}")
    params = "".join(f"{n}={n}, " for n in names)
    src = (f"def _timer(_n, {params}_box=_box, _rep=_rep, _clock=_clock):\n"
           f"    s = _box[0]\n"
           f"    _it = _rep(None, _n)\n"
           f"    _t0 = _clock()\n"
           f"    for _ in _it:\n"
           f"        {stmt}\n"
           f"    _t = _clock() - _t0\n"
           f"    _box[0] = s\n"
           f"    return _t\n")
    ns = dict(env, _box=state, _rep=itertools.repeat, _clock=time.perf_counter)
    exec(compile(src, f"<timer: {stmt}>", "exec"), ns)
    return ns["_timer"]


class Case:
    def __init__(self, key, label, stmt, env, state, rows=1):
        self.key, self.label, self.stmt, self.rows = key, label, stmt, rows
        self.env, self.state = env, state


class TimedCase(Timed):
    """ratio_table.Timed for a stateful case: samples of whole command cycles."""

    def __init__(self, case: Case):
        self.key, self.variant, self.case = case.key, case.label, case
        self.timer = compile_stateful_timer(case.stmt, case.env, case.state)
        self.n = 0
        self.round_min = []
        # calls per command cycle: CYCLE single calls, or one batch call of CYCLE rows
        self.unit = CYCLE // case.rows

    def calibrate(self, sample_s: float):
        self.timer(2 * self.unit)      # warm-up: two cycles (freelists, specialisation)
        t = self.timer(self.unit)
        self.n = self.unit * max(1, round(sample_s / max(t, 1e-9)))

    def per_row_us(self, kind):
        return self.stat(kind) / 1e3 / self.case.rows


def build_cases(cmds, pp, dk_, steady):
    import drivekin.batch as batch

    pp_gen, pp_zero, pp_speeds = pp
    dk_gen, dk_zero, dk_vel = dk_

    def cycle(objects):
        return itertools.cycle(objects).__next__

    cases = [Case("pathplannerlib", "pathplannerlib generateSetpoint",
                  "s = gen.generateSetpoint(s, t(), dt, v)",
                  dict(gen=pp_gen(), t=cycle(pp_speeds(cmds)), dt=DT, v=VOLTS), [pp_zero()])]
    for mode, name in ((None, "default"), ("pathplanner", "pathplanner")):
        cases.append(Case(f"generate.{name}", f"drivekin generateSetpoint [{name}]",
                          "s = gen.generateSetpoint(s, t(), dt, v)",
                          dict(gen=dk_gen(mode), t=cycle(dk_vel(cmds)), dt=DT, v=VOLTS),
                          [dk_zero()]))
        cases.append(Case(f"into.{name}", f"drivekin generateSetpointInto [{name}]",
                          "gen.generateSetpointInto(s, t(), dt, s, v)",
                          dict(gen=dk_gen(mode), t=cycle(dk_vel(cmds)), dt=DT, v=VOLTS),
                          [dk_zero()]))
        cases.append(Case(f"batch.{name}", f"drivekin batch.generateSetpoints [{name}], per row",
                          "batch(gen, s, c, dt, v)",
                          dict(batch=batch.generateSetpoints, gen=dk_gen(mode), c=cmds,
                               dt=DT, v=VOLTS), [steady[mode]], rows=CYCLE))
    return cases


# ---------------------------------------------------------------------------------------

def table(timed, args):
    base = timed[0]
    pp_us = base.per_row_us(args.stat)
    lines = ["## drivekin SwerveSetpointGenerator vs robotpy-pathplannerlib"
             + (" (--quick smoke run)" if args.quick else ""), ""]
    lines += [f"* {m}" for m in machine_description()]
    lines += [f"* robotpy-pathplannerlib: {_version('robotpy-pathplannerlib')}; "
              f"robotpy-wpilib {_version('wpilib')}",
              f"* method: {args.rounds} rounds x {args.repeat} samples per case, "
              f"~{args.sample_ms:g} ms per sample (at least one {CYCLE}-command cycle), cases "
              f"interleaved, GC off; 4 modules at (±0.3, ±0.3) m, dt {DT * 1000:g} ms, "
              f"{VOLTS:g} V, closed loop over ramped commands",
              "", "| case | µs per call | drivekin / pathplannerlib | speed-up | "
              "per-round speed-up range | goal (≤ 2 µs, ≥ 60×) |",
              "|---|---:|---:|---:|---:|:---:|"]
    missed = []
    lines.append(f"| {base.variant} | {pp_us:,.1f} | 1 | 1× | — | — |")
    for t in timed[1:]:
        us = t.per_row_us(args.stat)
        ratio = us / pp_us
        per_round = [(b / base.case.rows) / (x / t.case.rows)
                     for x, b in zip(t.round_min, base.round_min)]
        goal = "—"
        if t.key.startswith(("generate.", "into.")):
            ok = us <= GOAL_US and 1.0 / ratio >= GOAL_SPEEDUP
            goal = "yes" if ok else "**NO**"
            if not ok:
                missed.append(f"{t.variant}: {us:.2f} µs, {1 / ratio:.0f}×")
        lines.append(f"| {t.variant} | {us:.3f} | {ratio:.4f}× | {1 / ratio:,.0f}× | "
                     f"{min(per_round):,.0f}–{max(per_round):,.0f}× | {goal} |")
    stat = ("minimum over all samples" if args.stat == "min"
            else "median of the per-round minima")
    lines += ["", f"µs per call = {stat} "
              f"of (sample time / calls in the sample); the batch row is per row of a "
              f"{CYCLE}-row call. Speed-up = pathplannerlib time / drivekin time.", "",
              "Statements (every name a prebuilt local; t() = the next of the cycle's "
              "prebuilt commands):", ""]
    lines += [f"* {t.variant}: `{t.case.stmt}`" for t in timed]
    return lines, missed


def _version(dist):
    from importlib import metadata
    try:
        return metadata.version(dist)
    except metadata.PackageNotFoundError:
        return "not installed"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true",
                    help="CI smoke run: 2 rounds x 2 samples of ~3 ms")
    ap.add_argument("--rounds", type=int, default=None)
    ap.add_argument("--repeat", type=int, default=None)
    ap.add_argument("--sample-ms", type=float, default=None)
    ap.add_argument("--stat", choices=("min", "median"), default="min")
    ap.add_argument("--cpu", type=int, default=None, help="CPU to pin to (default: last)")
    ap.add_argument("--no-pin", action="store_true")
    ap.add_argument("--json", dest="json_out", help="also write raw results to this file")
    ap.add_argument("--strict", action="store_true",
                    help="exit 1 if a value check fails or a goal is missed")
    args = ap.parse_args(argv)
    preset = (dict(rounds=2, repeat=2, sample_ms=3.0) if args.quick
              else dict(rounds=30, repeat=5, sample_ms=2.0))
    for k, v in preset.items():
        if getattr(args, k) is None:
            setattr(args, k, v)
    log = (lambda m: print(m, file=sys.stderr, flush=True))
    if not args.no_pin:
        pin(args.cpu)

    cmds = commands()
    try:
        pp = pp_objects()
    except ImportError as e:
        sys.exit(f"benchmarks/setpoint.py needs robotpy-pathplannerlib 2026.1.2 "
                 f"(pip install robotpy-pathplannerlib==2026.1.2): {e}")
    dk_ = dk_objects()
    notes, failures, steady = check(cmds, pp, dk_)
    log("value checks done" + (" (FAILED)" if failures else ""))
    timed = [TimedCase(c) for c in build_cases(cmds, pp, dk_, steady)]
    log(f"timing {len(timed)} cases: {args.rounds} rounds x {args.repeat} samples x "
        f"~{args.sample_ms:g} ms")
    run_rounds(timed, args, log, every=10)
    lines, missed = table(timed, args)
    lines += ["", "Value checks:", ""] + [f"* {n}" for n in notes]
    if failures:
        lines += ["", "VALUE CHECK FAILURES:"] + [f"* {f}" for f in failures]
    if missed:
        lines += ["", "Goals missed: " + "; ".join(missed)]
    print("\n".join(lines))
    if args.json_out:
        Path(args.json_out).write_text(json.dumps({
            "machine": machine_description(), "stat": args.stat,
            "results": [{"case": t.key, "label": t.variant, "stmt": t.case.stmt,
                         "us_per_call": t.per_row_us(args.stat), "calls_per_sample": t.n,
                         "rows_per_call": t.case.rows,
                         "round_min_us": [x * 1e6 / t.case.rows for x in t.round_min]}
                        for t in timed],
            "notes": notes, "value_failures": failures, "missed": missed}, indent=1))
    return 1 if (args.strict and (missed or failures)) else 0


if __name__ == "__main__":
    sys.exit(main())
