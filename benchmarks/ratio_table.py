"""drivekin vs robotpy-wpimath: per-call times and ratios as a Markdown table.

    python benchmarks/ratio_table.py            # full run (about a minute)
    python benchmarks/ratio_table.py --quick    # CI smoke run (a few seconds)
    python benchmarks/ratio_table.py --from-json .benchmarks/run.json
        # table from `pytest benchmarks --benchmark-only --benchmark-json=.benchmarks/run.json`

Method (own timeit-style harness, one process, so every ratio compares numbers taken
seconds apart on the same CPU):
* every case of registry.OPERATIONS is the same one-line statement that the pytest
  benchmarks run, with the same prebuilt inputs (``_common``), compiled into a local loop
  where each name is a LOAD_FAST; the loop overhead (about 5 ns/iteration) is not
  subtracted, for every variant alike;
* before timing, every variant's output is checked against robotpy's (1e-9);
* the process is pinned to one CPU (the last one, unless --cpu/--no-pin) and the garbage
  collector is off while timing;
* each sample runs the statement n times (n calibrated to about --sample-ms); a round
  takes --repeat samples of every case, cases interleaved and their order rotated each
  round; there are --rounds rounds;
* reported ns/call = the chosen statistic (``--stat``: default ``min`` over all samples,
  the usual choice for microbenchmarks since VM noise only adds time; ``median`` = median of
  the per-round minima). Ratios are drivekin / robotpy of that statistic. The last column
  gives the range of the per-round ratios, a direct view of the noise.

Exit status: 0, or 1 with --strict when a target is missed or a value check fails.
"""
from __future__ import annotations

import argparse
import gc
import json
import os
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _common import (INNER, build_drivekin, build_drivekin_geometry, build_robotpy,  # noqa: E402
                     compile_timer, kinematics_available, machine_description)
from registry import OPERATIONS, VARIANTS, evaluate, values_agree  # noqa: E402


# ---------------------------------------------------------------------------------------
# Measurement

class Timed:
    """Samples of one case: per-round minimum seconds/call."""

    def __init__(self, op, variant, case, env):
        self.op, self.variant, self.case = op, variant, case
        self.timer = compile_timer(case.stmt, env)
        self.n = 0
        self.round_min: list[float] = []

    def calibrate(self, sample_s: float):
        self.timer(1000)  # warm freelists, heading memory, specialising interpreter
        n = 100
        while True:
            t = self.timer(n)
            if t >= sample_s / 5 or n >= 10**8:
                break
            n *= 4
        self.n = max(100, int(n * sample_s / max(t, 1e-9)))

    def round(self, repeat: int):
        self.round_min.append(min(self.timer(self.n) for _ in range(repeat)) / self.n)

    def stat(self, kind: str) -> float:
        return min(self.round_min) if kind == "min" else statistics.median(self.round_min)


def pin(cpu):
    if not hasattr(os, "sched_setaffinity"):
        return
    cpus = sorted(os.sched_getaffinity(0))
    target = cpus[-1] if cpu is None else cpu
    os.sched_setaffinity(0, {target})


def measure(ops, args, log):
    rp = build_robotpy()
    dk = build_drivekin() if kinematics_available() else build_drivekin_geometry()
    timed, failures = [], []
    for op in ops:
        ref = evaluate(op.robotpy, op.robotpy.setup(rp, dk))
        for variant, case in op.variants().items():
            got = evaluate(case, case.setup(rp, dk))
            if not values_agree(ref, got):
                failures.append(f"{op.key} {variant}: {got} != robotpy {ref}")
            # fresh env for timing (the check above may have mutated in-place inputs)
            timed.append(Timed(op, variant, case, case.setup(rp, dk)))
    gc_was = gc.isenabled()
    gc.disable()
    try:
        for t in timed:
            t.calibrate(args.sample_ms / 1000)
        for r in range(args.rounds):
            k = r % len(timed)
            for t in timed[k:] + timed[:k]:
                t.round(args.repeat)
            log(f"  round {r + 1}/{args.rounds} done")
    finally:
        if gc_was:
            gc.enable()
    return {(t.op.key, t.variant): t for t in timed}, failures


# ---------------------------------------------------------------------------------------
# Table

def fmt_ns(s: float) -> str:
    ns = s * 1e9
    return f"{ns:,.0f}" if ns >= 100 else f"{ns:.1f}"


def build_table(ops, get, ranges, stat_label, header):
    """get(op_key, variant) -> seconds/call or None; ranges(op_key, variant) -> (lo, hi)."""
    lines = list(header)
    lines += ["",
              "| operation | robotpy ns/call | drivekin façade ns/call (ratio) "
              "| drivekin allocation-free ns/call (ratio) | target ratios façade / alloc-free "
              "| met? | per-round ratio range façade; alloc-free |",
              "|---|---:|---:|---:|:---:|:---:|---|"]
    missed, extras = [], []
    for op in ops:
        base = get(op.key, "robotpy")
        if base is None:
            lines.append(f"| {op.title} | n/a | n/a | n/a | "
                         f"{_targets(op)} | — | drivekin.kinematics not built |")
            continue
        cells, met, rng = [], [], []
        for i, v in enumerate(VARIANTS[1:]):
            t = get(op.key, v)
            ratio = t / base
            cells.append(f"{fmt_ns(t)} ({ratio:.3f}×)")
            if op.targets is not None:
                ok = ratio <= op.targets[i]
                met.append("yes" if ok else "**NO**")
                if not ok:
                    missed.append(f"{op.title} {v}: {ratio:.3f}× > {op.targets[i]}")
            r = ranges(op.key, v)
            rng.append(f"{r[0]:.3f}–{r[1]:.3f}" if r else "—")
        lines.append(f"| {op.title} | {fmt_ns(base)} | {cells[0]} | {cells[1]} | "
                     f"{_targets(op)} | {' / '.join(met) if met else '—'} | "
                     f"{'; '.join(rng)} |")
        for label, case in op.extras.items():
            t = get(op.key, label)
            if t is not None:
                extras.append(f"| {op.title} | {label} | `{case.stmt}` | {fmt_ns(t)} | "
                              f"{t / base:.3f}× |")
    if extras:
        lines += ["", "Extra variants (ratio to the robotpy column above):", "",
                  "| operation | variant | statement | ns/call | × robotpy |",
                  "|---|---|---|---:|---:|"] + extras
    lines += ["", f"ns/call = {stat_label}. Ratio = drivekin / robotpy (lower is faster); "
              "a target is met when ratio <= target."]
    return lines, missed


def _targets(op):
    return "—" if op.targets is None else f"{op.targets[0]:.2f} / {op.targets[1]:.2f}"


def statements(ops):
    out = ["", "Statements timed (each name is a prebuilt local):", ""]
    for op in ops:
        parts = [f"{v}: `{c.stmt}`" + (f" ({c.note})" if c.note else "")
                 for v, c in op.variants().items()]
        out.append(f"* {op.title}: " + "; ".join(parts))
    return out


def from_json(path, ops):
    data = json.loads(Path(path).read_text())
    got = {}
    for b in data["benchmarks"]:
        ei = b.get("extra_info", {})
        if "operation" in ei:
            got[(ei["operation"], ei["variant"])] = b["stats"]["min"] / ei.get("inner_loop",
                                                                               INNER)
    mi = data.get("machine_info", {})
    header = [f"CPU: {mi.get('cpu', {}).get('brand_raw', '?')}",
              f"Python: {mi.get('python_implementation', '')} {mi.get('python_version', '')}",
              f"source: pytest-benchmark JSON {path} ({data.get('datetime', '')})"]
    lines, missed = build_table(ops, lambda k, v: got.get((k, v)), lambda k, v: None,
                                f"pytest-benchmark min round / {INNER} calls per round",
                                header)
    return lines, missed


# ---------------------------------------------------------------------------------------

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true",
                    help="CI smoke run: 2 rounds x 2 samples of ~3 ms")
    ap.add_argument("--rounds", type=int, default=None)
    ap.add_argument("--repeat", type=int, default=None)
    ap.add_argument("--sample-ms", type=float, default=None)
    ap.add_argument("--stat", choices=("min", "median"), default="min")
    ap.add_argument("--only", default="", help="comma-separated operation-key prefixes")
    ap.add_argument("--cpu", type=int, default=None, help="CPU to pin to (default: last)")
    ap.add_argument("--no-pin", action="store_true")
    ap.add_argument("--json", dest="json_out", help="also write raw results to this file")
    ap.add_argument("--from-json", help="tabulate a pytest-benchmark --benchmark-json file")
    ap.add_argument("--strict", action="store_true",
                    help="exit 1 if a target is missed or a value check fails")
    args = ap.parse_args(argv)
    quick = dict(rounds=2, repeat=2, sample_ms=3.0)
    full = dict(rounds=9, repeat=3, sample_ms=20.0)
    for k, v in (quick if args.quick else full).items():
        if getattr(args, k) is None:
            setattr(args, k, v)

    ops = OPERATIONS
    if args.only:
        prefixes = tuple(p.strip() for p in args.only.split(",") if p.strip())
        ops = [op for op in ops if op.key.startswith(prefixes)]

    if args.from_json:
        lines, missed = from_json(args.from_json, ops)
        print("\n".join(lines))
        return 1 if (args.strict and missed) else 0

    have_kin = kinematics_available()
    runnable = [op for op in ops if have_kin or not op.needs_kinematics]
    if not args.no_pin:
        pin(args.cpu)
    log = (lambda m: print(m, file=sys.stderr, flush=True))
    log(f"timing {sum(len(op.variants()) for op in runnable)} cases: {args.rounds} rounds x "
        f"{args.repeat} samples x ~{args.sample_ms:g} ms")
    res, failures = measure(runnable, args, log)

    def get(key, v):
        t = res.get((key, v))
        return None if t is None else t.stat(args.stat)

    def ranges(key, v):
        a, b = res.get((key, v)), res.get((key, "robotpy"))
        if a is None or b is None:
            return None
        rs = [x / y for x, y in zip(a.round_min, b.round_min)]
        return min(rs), max(rs)

    stat_label = ("min over all samples" if args.stat == "min"
                  else "median over rounds of the per-round minimum")
    header = ["## drivekin vs robotpy-wpimath" + (" (--quick smoke run)" if args.quick else ""),
              ""] + [f"* {m}" for m in machine_description()] + [
        f"* method: {args.rounds} rounds x {args.repeat} samples per case, ~{args.sample_ms:g} "
        f"ms per sample, cases interleaved, GC off; 4-module swerve at (±0.3, ±0.3) m, "
        f"prebuilt inputs"]
    lines, missed = build_table(ops, get, ranges, stat_label, header)
    lines += statements(runnable)
    if failures:
        lines += ["", "VALUE CHECK FAILURES:"] + [f"* {f}" for f in failures]
    if missed:
        lines += ["", "Targets missed: " + "; ".join(missed)]
    print("\n".join(lines))

    if args.json_out:
        Path(args.json_out).write_text(json.dumps({
            "machine": machine_description(), "stat": args.stat,
            "args": {k: getattr(args, k) for k in ("rounds", "repeat", "sample_ms", "quick")},
            "results": [{"operation": k, "variant": v, "ns_per_call": t.stat(args.stat) * 1e9,
                         "round_min_ns": [x * 1e9 for x in t.round_min], "n": t.n,
                         "stmt": t.case.stmt} for (k, v), t in res.items()],
            "targets": {op.key: op.targets for op in ops},
            "missed": missed, "value_failures": failures}, indent=1))
    return 1 if (args.strict and (missed or failures)) else 0


if __name__ == "__main__":
    sys.exit(main())
