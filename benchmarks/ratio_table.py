"""drivekin vs robotpy-wpimath: per-call times and ratios as a Markdown table.

    python benchmarks/ratio_table.py            # full run (about 20 s)
    python benchmarks/ratio_table.py --quick    # CI smoke run (about 2 s)
    python benchmarks/ratio_table.py --ir       # instruction counts under callgrind (~1 min)
    python benchmarks/ratio_table.py --from-json .benchmarks/run.json
        # table from `pytest benchmarks --benchmark-only --benchmark-json=.benchmarks/run.json`

Timing method (own timeit-style harness in one process, so every ratio compares numbers
taken seconds apart on the same CPU):
* every case of registry.OPERATIONS is the same one-line statement the pytest benchmarks
  run, with the same prebuilt inputs (``_common``), compiled into a local loop where each
  name is a LOAD_FAST; the loop overhead (about 5 ns/iteration) is not subtracted, for
  every variant alike;
* before timing, every variant's output is checked against robotpy's (1e-9);
* the process is pinned to one CPU (the last one, unless --cpu/--no-pin) and the garbage
  collector is off while timing;
* each sample runs the statement n times (n calibrated to about --sample-ms); a round
  takes --repeat samples of every case, cases interleaved and their order rotated each
  round; there are --rounds rounds. Samples are short (2 ms) on purpose: when other
  processes share the CPU, a short sample often fits between their time slices, so the
  minimum stays clean, where a 10–200 ms sample is always shared;
* reported ns/call = the chosen statistic (``--stat``: default ``min`` over all samples,
  the usual choice for microbenchmarks since VM noise only adds time; ``median`` = median of
  the per-round minima). Ratios are drivekin / robotpy of that statistic. The last column
  gives the range of the per-round ratios, a direct view of the noise.

``--ir`` counts instructions instead (valgrind callgrind, started and stopped around each
case through a 3-line C shim compiled into a temporary directory): deterministic, so it is
the form to enforce in CI on a noisy machine (perf-floor.md). Instruction ratios run a
little higher than time ratios, because robotpy spends more time per instruction (malloc,
cache misses). Needs ``valgrind`` (with its headers) and a C compiler.

Exit status: 0, or 1 with --strict when a target is missed or a value check fails.
"""
from __future__ import annotations

import argparse
import gc
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

# _common and registry are found next to this script (its folder is sys.path[0]).
from _common import (INNER, build_drivekin, build_drivekin_geometry, build_robotpy,
                     compile_timer, kinematics_available, machine_description)
from registry import (CALIBRATION, GROUPS, OPERATIONS, VARIANTS, baseline_of, evaluate,
                      reference_value, values_agree, with_baselines)


ROBOTS = ("4-module swerve at (±0.3, ±0.3) m, mecanum with wheels at the same points, "
          "differential with trackwidth 0.6 m")


# ---------------------------------------------------------------------------------------
# Cases

def prepare(ops):
    """Check every variant against robotpy (drivekin-only operations: against their
    ``expected`` numbers or their façade); return ([(key, variant, case, env)], failures).

    Calibration cases get key None. Each env is fresh (the check may mutate inputs)."""
    rp = build_robotpy()
    dk = build_drivekin() if kinematics_available() else build_drivekin_geometry()
    cases, failures = [], []
    for op in ops:
        ref = reference_value(op, rp, dk)
        for variant, case in op.variants().items():
            got = evaluate(case, case.setup(rp, dk))
            if not values_agree(ref, got):
                failures.append(f"{op.key} {variant}: {got} != "
                                f"{'reference' if op.drivekin_only else 'robotpy'} {ref}")
            cases.append((op.key, variant, case, case.setup(rp, dk)))
    cases += [(None, label, case, case.setup(rp, dk)) for label, case, *_ in CALIBRATION]
    return cases, failures


# ---------------------------------------------------------------------------------------
# Wall-clock timing

class Timed:
    """Samples of one case: per-round minimum seconds/call."""

    def __init__(self, key, variant, case, env):
        self.key, self.variant, self.case = key, variant, case
        self.timer = compile_timer(case.stmt, env)
        self.n = 0
        self.round_min: list[float] = []

    def calibrate(self, sample_s: float):
        self.timer(1000)  # warm freelists, heading memory, the specialising interpreter
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
        """ns/call."""
        s = min(self.round_min) if kind == "min" else statistics.median(self.round_min)
        return s * 1e9


def pin(cpu):
    if not hasattr(os, "sched_setaffinity"):
        return
    cpus = sorted(os.sched_getaffinity(0))
    os.sched_setaffinity(0, {cpus[-1] if cpu is None else cpu})


def run_rounds(timed, args, log, every=1):
    """Calibrate each timed case, then run ``args.rounds`` rounds of ``args.repeat``
    samples, rotating which case goes first, with the garbage collector off; progress
    every ``every`` rounds."""
    gc_was = gc.isenabled()
    gc.disable()
    try:
        for t in timed:
            t.calibrate(args.sample_ms / 1000)
        for r in range(args.rounds):
            k = r % len(timed)
            for t in timed[k:] + timed[:k]:
                t.round(args.repeat)
            if (r + 1) % every == 0 or r + 1 == args.rounds:
                log(f"  round {r + 1}/{args.rounds} done")
    finally:
        if gc_was:
            gc.enable()
    return timed


def measure_time(cases, args, log):
    return run_rounds([Timed(*c) for c in cases], args, log)


# ---------------------------------------------------------------------------------------
# Instruction counts (callgrind)

CG_SHIM = r"""
#include <valgrind/callgrind.h>
void cg_start(void) { CALLGRIND_ZERO_STATS; CALLGRIND_START_INSTRUMENTATION; }
void cg_stop(void) { CALLGRIND_STOP_INSTRUMENTATION; CALLGRIND_DUMP_STATS; }
"""


def ir_child(tmp: Path, ops, n: int):
    """Runs under valgrind: one callgrind dump per case, in `cases` order."""
    import ctypes

    cg = ctypes.CDLL(str(tmp / "libcg.so"))
    cases, failures = prepare(ops)
    gc.disable()
    for _, _, case, env in cases:
        timer = compile_timer(case.stmt, env)
        timer(2000)
        cg.cg_start()
        timer(n)
        cg.cg_stop()
    (tmp / "cases.json").write_text(json.dumps(
        {"cases": [[k, v] for k, v, _, _ in cases], "failures": failures, "n": n}))


def measure_ir(args, log):
    """Re-run this script under callgrind; return ({(key, variant): Ir/call}, failures)."""
    valgrind, cc = shutil.which("valgrind"), shutil.which("cc") or shutil.which("gcc")
    if not valgrind or not cc:
        sys.exit("--ir needs valgrind and a C compiler on PATH")
    tmp = Path(tempfile.mkdtemp(prefix="drivekin-ir-"))
    try:
        (tmp / "cg.c").write_text(CG_SHIM)
        subprocess.run([cc, "-O2", "-shared", "-fPIC", "-o", str(tmp / "libcg.so"),
                        str(tmp / "cg.c")], check=True)
        cmd = [valgrind, "--tool=callgrind", "--instr-atstart=no",
               f"--callgrind-out-file={tmp / 'cg.out'}", sys.executable, str(Path(__file__)),
               "--_ir-child", str(tmp), "--ir-calls", str(args.ir_calls), "--only", args.only]
        log(f"running under callgrind ({args.ir_calls} calls per case) ...")
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        meta = json.loads((tmp / "cases.json").read_text())
        res = {}
        for i, (key, variant) in enumerate(meta["cases"], 1):
            text = (tmp / f"cg.out.{i}").read_text()
            total = int(re.search(r"^totals:\s+(\d+)", text, re.M).group(1))
            res[(key, variant)] = total / meta["n"]
        return res, meta["failures"]
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


# ---------------------------------------------------------------------------------------
# Table

def fmt(x: float) -> str:
    return f"{x:,.0f}" if x >= 100 else f"{x:.1f}"


def _targets(op):
    return "—" if op.targets is None else f"{op.targets[0]:.2f} / {op.targets[1]:.2f}"


def build_table(ops, get, ranges, note, header, unit="ns"):
    """get(op_key, variant) -> value per call (unit) or None; ranges(op_key, variant) ->
    (lo, hi) of the per-round ratios, or ranges=None to leave that column out."""
    lines = list(header) + [
        "",
        f"| operation | robotpy {unit}/call | drivekin façade {unit}/call (ratio) "
        f"| drivekin allocation-free {unit}/call (ratio) | target ratios façade / alloc-free "
        "| met? |" + (" per-round ratio range façade; alloc-free |" if ranges else ""),
        "|---|---:|---:|---:|:---:|:---:|" + ("---|" if ranges else "")]
    missed, extras = [], []
    for op in ops:
        if op.drivekin_only:
            continue
        base = get(op.key, "robotpy")
        if base is None:
            lines.append(f"| {op.title} | n/a | n/a | n/a | {_targets(op)} | — |"
                         + (" — |" if ranges else ""))
            continue
        cells, met, rng = [], [], []
        for i, v in enumerate(VARIANTS[1:]):
            x = get(op.key, v)
            if x is None:
                cells.append("n/a")
                rng.append("—")
                continue
            ratio = x / base
            cells.append(f"{fmt(x)} ({ratio:.3f}×)")
            if op.targets is not None:
                ok = ratio <= op.targets[i]
                met.append("yes" if ok else "**NO**")
                if not ok:
                    missed.append(f"{op.title} {v}: {ratio:.3f}× > {op.targets[i]}")
            r = ranges(op.key, v) if ranges else None
            rng.append(f"{r[0]:.3f}–{r[1]:.3f}" if r else "—")
        lines.append(f"| {op.title} | {fmt(base)} | {cells[0]} | {cells[1]} | "
                     f"{_targets(op)} | {' / '.join(met) if met else '—'} |"
                     + (f" {'; '.join(rng)} |" if ranges else ""))
        for label, case in op.extras.items():
            x = get(op.key, label)
            if x is not None:
                extras.append(f"| {op.title} | {label} | `{case.stmt}` | {fmt(x)} | "
                              f"{x / base:.3f}× |")
    rows, group_missed = group_rows(ops, get, ranges is not None)
    lines += rows
    missed += group_missed
    if extras:
        lines += ["", "Extra variants (ratio to the robotpy column above):", "",
                  f"| operation | variant | statement | {unit}/call | × robotpy |",
                  "|---|---|---|---:|---:|"] + extras
    own_lines, own_missed = drivekin_only_table([op for op in ops if op.drivekin_only], get,
                                                unit)
    lines += own_lines
    missed += own_missed
    lines += ["", f"{unit}/call = {note}. Ratio = drivekin / robotpy (lower is faster); "
              "a target is met when ratio <= target."]
    if ops and any(op.needs_kinematics for op in ops) and not kinematics_available():
        lines += ["", "n/a: drivekin.kinematics is not built."]
    return lines, missed


def group_rows(ops, get, with_ranges):
    """A row per registry group whose operations all ran: the geometric mean of their
    ratios to robotpy, per drivekin column, against the group's target. Returns
    (lines, missed)."""
    lines, missed = [], []
    present = {op.key for op in ops}
    for group in GROUPS:
        if not set(group.keys) <= present:
            continue
        cells, met = [], []
        for v in VARIANTS[1:]:
            pairs = [(get(k, v), get(k, "robotpy")) for k in group.keys]
            if any(x is None or not base for x, base in pairs):
                cells.append("n/a")
                continue
            mean = math.exp(statistics.fmean(math.log(x / base) for x, base in pairs))
            cells.append(f"{mean:.3f}×")
            met.append("yes" if mean <= group.target else "**NO**")
            if mean > group.target:
                missed.append(f"{group.title} {v}: geometric mean {mean:.3f}× > {group.target}")
        lines.append(f"| **{group.title}: geometric mean of {len(group.keys)} rows** | — | "
                     f"{cells[0]} | {cells[1]} | {group.target:.2f} / {group.target:.2f} | "
                     f"{' / '.join(met) if met else '—'} |" + (" — |" if with_ranges else ""))
    return lines, missed


def drivekin_only_table(ops, get, unit):
    """Rows for operations without a robotpy case: absolute times per variant, checked
    against ``target_ns`` (time runs only: instruction counts have no ns), and the ratio
    to the operation's drivekin baseline from the same run, checked against
    ``baseline_targets``. Returns (lines, missed)."""
    if not ops:
        return [], []
    lines = ["", "drivekin-only operations (no robotpy peer): times per call, and the ratio "
             "to a drivekin baseline operation timed in the same run:", "",
             f"| operation | drivekin façade {unit}/call | drivekin allocation-free "
             f"{unit}/call | target ns façade / alloc-free | baseline | baseline "
             f"{unit}/call | ratio to baseline façade / alloc-free | target ratios | met? |",
             "|---|---:|---:|:---:|---|---:|:---:|:---:|:---:|"]
    missed, extras = [], []
    for op in ops:
        times = [get(op.key, v) for v in VARIANTS[1:]]
        met = []
        if op.target_ns is not None and unit == "ns":
            for v, x, limit in zip(VARIANTS[1:], times, op.target_ns):
                if x is not None:
                    met.append("yes" if x <= limit else "**NO**")
                    if x > limit:
                        missed.append(f"{op.title} {v}: {x:.1f} ns > {limit:g} ns")
        ref = baseline_of(op)
        base = get(*ref) if ref else None
        ratios = [None if (x is None or not base) else x / base for x in times]
        if op.baseline_targets is not None:
            for v, r, limit in zip(VARIANTS[1:], ratios, op.baseline_targets):
                if r is not None:
                    met.append("yes" if r <= limit else "**NO**")
                    if r > limit:
                        missed.append(f"{op.title} {v}: {r:.3f}× {op.baseline} > {limit}")
        cell = (lambda x: "n/a" if x is None else fmt(x))
        ns_t = ("—" if op.target_ns is None else
                f"{op.target_ns[0]:g} / {op.target_ns[1]:g}")
        r_t = ("—" if op.baseline_targets is None else
               f"{op.baseline_targets[0]:.2f} / {op.baseline_targets[1]:.2f}")
        r_cells = " / ".join("—" if r is None else f"{r:.3f}×" for r in ratios)
        lines.append(f"| {op.title} | {cell(times[0])} | {cell(times[1])} | {ns_t} | "
                     f"{op.baseline or '—'} | {cell(base)} | {r_cells if ref else '—'} | "
                     f"{r_t} | {' / '.join(met) if met else '—'} |")
        for label, case in op.extras.items():
            x = get(op.key, label)
            if x is not None:
                extras.append(f"| {op.title} | {label} | `{case.stmt}` | {fmt(x)} | "
                              + (f"{x / base:.3f}× |" if base else "— |"))
    if extras:
        lines += ["", "Extra variants of the drivekin-only operations (ratio to their "
                  "baseline):", "",
                  f"| operation | variant | statement | {unit}/call | × baseline |",
                  "|---|---|---|---:|---:|"] + extras
    return lines, missed


def statements(ops):
    out = ["", "Statements measured (each name is a prebuilt local):", ""]
    for op in ops:
        parts = [f"{v}: `{c.stmt}`" + (f" ({c.note})" if c.note else "")
                 for v, c in op.variants().items()]
        out.append(f"* {op.title}: " + "; ".join(parts))
    return out


def calibration_lines(get_calib, unit):
    idx = 2 if unit == "ns" else 3
    lines = ["", "Call-floor calibration (same run; compare with perf-floor.md's machine):", ""]
    for entry in CALIBRATION:
        x = get_calib(entry[0])
        if x is not None:
            lines.append(f"* {entry[0]}: {fmt(x)} {unit} (perf-floor: {entry[idx]})")
    return lines


def from_json(path, ops):
    data = json.loads(Path(path).read_text())
    got = {}
    for b in data["benchmarks"]:
        ei = b.get("extra_info", {})
        if "operation" in ei:
            got[(ei["operation"], ei["variant"])] = (b["stats"]["min"] * 1e9
                                                     / ei.get("inner_loop", INNER))
    mi = data.get("machine_info", {})
    header = [f"* CPU: {mi.get('cpu', {}).get('brand_raw', '?')}",
              f"* Python: {mi.get('python_implementation', '')} "
              f"{mi.get('python_version', '')}",
              f"* source: pytest-benchmark JSON {path} ({data.get('datetime', '')})"]
    return build_table(ops, lambda k, v: got.get((k, v)), None,
                       f"pytest-benchmark min round / {INNER} calls per round", header)


# ---------------------------------------------------------------------------------------

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true",
                    help="CI smoke run: 2 rounds x 2 samples of ~3 ms (with --ir: 2000 calls)")
    ap.add_argument("--rounds", type=int, default=None)
    ap.add_argument("--repeat", type=int, default=None)
    ap.add_argument("--sample-ms", type=float, default=None)
    ap.add_argument("--stat", choices=("min", "median"), default="min")
    ap.add_argument("--only", default="", help="comma-separated operation-key prefixes")
    ap.add_argument("--cpu", type=int, default=None, help="CPU to pin to (default: last)")
    ap.add_argument("--no-pin", action="store_true")
    ap.add_argument("--ir", action="store_true",
                    help="count instructions under callgrind instead of timing")
    ap.add_argument("--ir-calls", type=int, default=None, help="calls per case with --ir")
    ap.add_argument("--_ir-child", dest="ir_child", help=argparse.SUPPRESS)
    ap.add_argument("--json", dest="json_out", help="also write raw results to this file")
    ap.add_argument("--from-json", help="tabulate a pytest-benchmark --benchmark-json file")
    ap.add_argument("--strict", action="store_true",
                    help="exit 1 if a target is missed or a value check fails")
    args = ap.parse_args(argv)
    preset = (dict(rounds=2, repeat=2, sample_ms=3.0, ir_calls=2000) if args.quick
              else dict(rounds=30, repeat=5, sample_ms=2.0, ir_calls=10000))
    for k, v in preset.items():
        if getattr(args, k) is None:
            setattr(args, k, v)

    ops = OPERATIONS
    if args.only:
        prefixes = tuple(p.strip() for p in args.only.split(",") if p.strip())
        # Baselines of drivekin-only operations are timed with them, for their ratios.
        ops = with_baselines([op for op in ops if op.key.startswith(prefixes)])
    runnable = [op for op in ops if kinematics_available() or not op.needs_kinematics]

    if args.ir_child:
        ir_child(Path(args.ir_child), runnable, args.ir_calls)
        return 0
    if args.from_json:
        lines, missed = from_json(args.from_json, ops)
        print("\n".join(lines))
        return 1 if (args.strict and missed) else 0

    log = (lambda m: print(m, file=sys.stderr, flush=True))
    if not args.ir and not args.no_pin:
        pin(args.cpu)
    title = "## drivekin vs robotpy-wpimath" + (" (--quick smoke run)" if args.quick else "")
    machine = [f"* {m}" for m in machine_description()]
    if args.ir:
        res, failures = measure_ir(args, log)
        unit, ranges = "Ir", None
        note = (f"instructions per call (callgrind, {args.ir_calls} calls per case after 2000 "
                f"warm-up calls, loop overhead included). The targets are wall-time ratios, "
                f"applied here to instruction ratios as a stricter proxy (robotpy spends more "
                f"time per instruction, so its time ratios come out lower)")
        method = ["* method: valgrind callgrind instruction counts (deterministic); "
                  f"{ROBOTS}, prebuilt inputs"]

        def get(key, v):
            return res.get((key, v))
        raw = [{"operation": k, "variant": v, "ir_per_call": x} for (k, v), x in res.items()]
    else:
        cases, failures = prepare(runnable)
        log(f"timing {len(cases)} cases: {args.rounds} rounds x {args.repeat} samples x "
            f"~{args.sample_ms:g} ms")
        timed = measure_time(cases, args, log)
        by = {(t.key, t.variant): t for t in timed}
        unit = "ns"
        note = ("min over all samples" if args.stat == "min"
                else "median over rounds of the per-round minimum")
        method = [f"* method: {args.rounds} rounds x {args.repeat} samples per case, "
                  f"~{args.sample_ms:g} ms per sample, cases interleaved, GC off; "
                  f"{ROBOTS}, prebuilt inputs"]

        def get(key, v):
            t = by.get((key, v))
            return None if t is None else t.stat(args.stat)

        def ranges(key, v):
            a, b = by.get((key, v)), by.get((key, "robotpy"))
            if a is None or b is None:
                return None
            rs = [x / y for x, y in zip(a.round_min, b.round_min)]
            return min(rs), max(rs)
        raw = [{"operation": t.key, "variant": t.variant, "ns_per_call": t.stat(args.stat),
                "round_min_ns": [x * 1e9 for x in t.round_min], "n": t.n}
               for t in timed]

    lines, missed = build_table(ops, get, ranges, note, [title, ""] + machine + method, unit)
    lines += calibration_lines(lambda label: get(None, label), unit)
    lines += statements(runnable)
    if failures:
        lines += ["", "VALUE CHECK FAILURES:"] + [f"* {f}" for f in failures]
    if missed:
        lines += ["", "Targets missed: " + "; ".join(missed)]
    print("\n".join(lines))

    if args.json_out:
        Path(args.json_out).write_text(json.dumps({
            "machine": machine_description(), "unit": unit, "note": note,
            "results": raw, "targets": {op.key: op.targets for op in ops},
            "drivekin_only": {op.key: {"target_ns": op.target_ns, "baseline": op.baseline,
                                       "baseline_targets": op.baseline_targets}
                              for op in ops if op.drivekin_only},
            "missed": missed, "value_failures": failures}, indent=1))
    return 1 if (args.strict and (missed or failures)) else 0


if __name__ == "__main__":
    sys.exit(main())
