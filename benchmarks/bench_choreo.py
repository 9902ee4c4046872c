"""drivekin.choreo's sampling against choreolib Python 2026.0.3's ``sample_at``, in one
process.

    python benchmarks/bench_choreo.py            # the table, about 10 s
    python benchmarks/bench_choreo.py --quick    # CI smoke run, about 2 s
    pytest benchmarks/bench_choreo.py --benchmark-only   # pytest-benchmark, same cases

Trajectories (../shared/choreo/trajs beside the repository; absent: the pytest cases skip
and the script exits 2): steelhawks_LOPAuton (swerve, 1,619 samples, 23.3 s) and
choreo_test_differential (29 samples: choreolib integrates it with wpimath's RKDP and a
Python callback). Each is sampled at one time between two samples (0.4123 of the total
time), blue and red.

Cases: ``ref.sample_at(T, flip)`` (choreolib, its trajectory loaded by
``load_*_trajectory_string``); drivekin ``traj.sampleAt(T, flip)`` (returns a new sample,
from its freelist); drivekin ``traj.sampleInto(T, out, flip)`` (allocation-free);
``traj.sampleAtMany(times)`` over 1,000 times, reported per row. Method: ratio_table.py's
(``Timed``, ``pin``): one process pinned to one CPU, GC off, cases interleaved with their
order rotated every round; ns/call = the minimum over all samples. Before timing every
drivekin case must agree with choreolib to 1e-9 (heading modulo 2π).

Goal (issue 31): sampleAt ≤ 1/20 of choreolib's time per call. ``--strict`` exits 1 when a
value check fails or the goal is missed.
"""
from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from _common import INNER, compile_body, machine_description
from ratio_table import Timed, pin, run_rounds

TRAJS = Path(__file__).resolve().parents[1] / ".." / "shared" / "choreo" / "trajs"
FILES = {"swerve": "steelhawks_LOPAuton.traj", "differential": "choreo_test_differential.traj"}
FRACTION = 0.4123                # of the total time: between two samples in both files
GOAL = 20.0                      # choreolib time / drivekin sampleAt time
MANY = 1000                      # times per sampleAtMany call
TOL = 1e-9


def load(kind: str) -> SimpleNamespace:
    """Both libraries' trajectory, the time, a sample for sampleInto, the batch times."""
    import choreo as choreolib
    from drivekin import choreo
    path = TRAJS / FILES[kind]
    traj = choreo.load(path)
    loader = (choreolib.load_swerve_trajectory_string if kind == "swerve"
              else choreolib.load_differential_trajectory_string)
    ref = loader(path.read_text(encoding="utf-8"))
    return SimpleNamespace(traj=traj, ref=ref, T=FRACTION * traj.totalTime,
                           out=traj.newSample(),
                           times=np.linspace(0.0, traj.totalTime, MANY))


def cases(kind: str, flip: bool) -> dict[str, str]:
    f = repr(flip)
    return {"choreolib": f"ref.sample_at(T, {f})",
            "sampleAt": f"traj.sampleAt(T, {f})",
            "sampleInto": f"traj.sampleInto(T, out, {f})"}


def _ref_row(s, kind):
    head = [s.timestamp, s.x, s.y, s.heading]
    if kind == "swerve":
        return head + [s.vx, s.vy, s.omega, s.ax, s.ay, s.alpha, *s.fx, *s.fy]
    return head + [s.vl, s.vr, s.omega, s.al, s.ar, s.alpha, s.fl, s.fr]


def values_agree(env: SimpleNamespace, kind: str, flip: bool) -> float:
    """The largest difference of drivekin's three forms from choreolib (heading mod 2π)."""
    want = np.array(_ref_row(env.ref.sample_at(env.T, flip), kind))
    traj = env.traj
    got = [traj.sampleAtMany([env.T], flip)[0]]
    for s in (traj.sampleAt(env.T, flip), traj.sampleInto(env.T, env.out, flip)):
        got.append(traj.sampleAtMany([s.t], flip)[0])   # same time: its row
        assert (s.x, s.y, s.heading, s.omega) == tuple(got[-1][[1, 2, 3, 6]])
    worst = 0.0
    for row in got:
        d = np.abs(row - want)
        d[3] = abs(math.remainder(row[3] - want[3], 2 * math.pi))
        worst = max(worst, float(d.max()))
    return worst


# ---------------------------------------------------------------------------------------
# pytest-benchmark

KINDS = list(FILES)


def _env(kind):
    pytest.importorskip("choreo")
    if not (TRAJS / FILES[kind]).is_file():
        pytest.skip("../shared/choreo/trajs is not beside the repository")
    return load(kind)


@pytest.mark.parametrize("flip", [False, True], ids=["blue", "red"])
@pytest.mark.parametrize("kind", KINDS)
def test_values_agree(kind, flip):
    assert values_agree(_env(kind), kind, flip) <= TOL


@pytest.mark.parametrize("case", ["choreolib", "sampleAt", "sampleInto"])
@pytest.mark.parametrize("flip", [False, True], ids=["blue", "red"])
@pytest.mark.parametrize("kind", KINDS)
def test_bench(benchmark, kind, flip, case):
    env = _env(kind)
    stmt = cases(kind, flip)[case]
    body = compile_body(stmt, vars(env), INNER)
    body()
    benchmark.group = f"choreo {kind} {'red' if flip else 'blue'}"
    benchmark.extra_info.update(stmt=stmt, inner_loop=INNER)
    benchmark(body)


# ---------------------------------------------------------------------------------------
# The table

def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--quick", action="store_true", help="CI smoke run (few short rounds)")
    p.add_argument("--rounds", type=int, default=20)
    p.add_argument("--repeat", type=int, default=5)
    p.add_argument("--sample-ms", type=float, default=2.0)
    p.add_argument("--cpu", type=int, default=None, help="CPU to pin to (default: the last)")
    p.add_argument("--strict", action="store_true", help="exit 1 on a failed check or goal")
    args = p.parse_args(argv)
    if args.quick:
        args.rounds, args.repeat, args.sample_ms = 3, 2, 1.0
    if not TRAJS.is_dir():
        print(f"{TRAJS} not found", file=sys.stderr)
        return 2
    pin(args.cpu)
    failed = False
    rows = []
    for kind in KINDS:
        env = load(kind)
        for flip in (False, True):
            worst = values_agree(env, kind, flip)
            failed |= worst > TOL
            timed = [Timed(kind, name, SimpleNamespace(stmt=stmt), vars(env))
                     for name, stmt in cases(kind, flip).items()]
            timed.append(Timed(kind, "sampleAtMany", SimpleNamespace(
                stmt=f"traj.sampleAtMany(times, {flip!r})"), vars(env)))
            run_rounds(timed, args, lambda msg: None)
            ns = {t.variant: t.stat("min") for t in timed}
            ns["sampleAtMany"] /= MANY
            rows.append((kind, flip, ns, worst))
    print("\n".join(f"<!-- {line} -->" for line in machine_description()))
    print("| trajectory | alliance | choreolib ns | sampleAt ns (ratio) | sampleInto ns (ratio) "
          "| sampleAtMany ns/row (ratio) | max diff |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for kind, flip, ns, worst in rows:
        c = ns["choreolib"]
        cells = [f"{ns[k]:.0f} ({c / ns[k]:.0f}×)" for k in ("sampleAt", "sampleInto",
                                                               "sampleAtMany")]
        print(f"| {FILES[kind][:-5]} ({kind}) | {'red' if flip else 'blue'} | {c:.0f} | "
              + " | ".join(cells) + f" | {worst:.1e} |")
        failed |= args.strict and c / ns["sampleAt"] < GOAL
    return 1 if (failed and args.strict) else 0


if __name__ == "__main__":
    sys.exit(main())
