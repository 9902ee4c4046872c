"""``python -m drivekin choreo check FILE.traj ...``: the command line of the feasibility
check of :mod:`drivekin.choreo` (:mod:`drivekin.app.cli` hands it the arguments after
``choreo``).

This module only parses and validates the arguments and prints the verdict; the check
itself is :meth:`drivekin.choreo.ChoreoTrajectory.check`.
"""
from __future__ import annotations

import argparse
import json
import sys
from typing import Any

from drivekin._core.display import escape
from drivekin.app.options import Parser, docs_url, emit, need_extras, new_file, number_option

PROG = "python -m drivekin choreo"
UNITS = {"moduleSpeed": "m/s", "driveTorque": "N·m", "current": "A", "friction": "N",
         "steerRate": "rad/s", "moduleOrder": "N·m"}
MAX_LINES = 12


def build_parser() -> argparse.ArgumentParser:
    p = Parser(prog=PROG, description="Work with Choreo trajectories (.traj, schema 3).",
               epilog=f"Documentation: {docs_url()}")
    sub = p.add_subparsers(dest="command", required=True, metavar="check")
    c = sub.add_parser(
        "check", prog=f"{PROG} check",
        description=(
            "Check a Choreo trajectory against the robot's real limits: per sample and "
            "module, the module speed against the top drive speed and the motor's free "
            "speed, the drive torque against the motor's torque-speed curve at --voltage "
            "and its current limit, the force against wheel friction, the steering rate "
            "(with --max-steer-velocity) and the torque balance of the forces in Choreo's "
            "module order. The robot is the one embedded in the file (drivekin models "
            "Choreo's tmax and vmax with Kraken X60 drives) or the .chor project's. "
            "Exit status: 0 feasible, 1 infeasible (one line per violated quantity), 2 bad "
            "options or a file that cannot be checked."),
        epilog=f"Example: {PROG} check deploy/choreo/Center.traj --max-steer-velocity 20. "
               f"Documentation: {docs_url()}")
    c.add_argument("traj", metavar="FILE.traj", help="the trajectory")
    c.add_argument("--config", metavar="FILE.chor",
                   help="check against the robot config of this Choreo project instead of "
                        "the one embedded in the trajectory")
    c.add_argument("--max-steer-velocity", type=number_option(0.0, 1e4, "rad/s", False),
                   metavar="R", help="steering rate limit of the modules, rad/s (default: "
                                     "not checked)")
    c.add_argument("--voltage", type=number_option(0.0, 1000.0, "V", False), default=12.0,
                   metavar="V", help="battery voltage for the motor curve (default: 12)")
    c.add_argument("--json", type=new_file("--json"), metavar="OUT",
                   help='write the report as JSON (top-level "ok") to OUT')
    c.add_argument("--plot", type=new_file("--plot"), metavar="OUT.png",
                   help='draw each limit\'s margin over time into OUT.png (needs '
                        'matplotlib: pip install "drivekin[plot]")')
    return p


def _project_config(path: str, kind: str) -> Any:
    """The RobotConfig of a ``.chor`` project: its expressions' SI values in the form the
    trajectory's embedded config has."""
    from drivekin import choreo

    data = choreo._parse(path)
    raw = data.get("config")

    def values(node: Any, depth: int) -> Any:
        if isinstance(node, dict) and set(node) >= {"exp", "val"} and depth:
            return node["val"]
        if isinstance(node, dict) and depth < 3:
            return {k: values(v, depth + 1) for k, v in node.items()}
        return node

    if not isinstance(raw, dict):
        raise choreo.ChoreoError(f"{path}: has no robot config object; is it a Choreo "
                                 f"project (.chor)?")
    return choreo._config(choreo._Reader(path), values(raw, 0), kind)


def _line(quantity: str, records: list[Any]) -> str:
    worst = max(records, key=lambda r: r.value / r.limit if r.limit > 0 else float("inf"))
    unit = UNITS[quantity]
    where = "the whole robot" if worst.module < 0 else f"module {worst.module}"
    times = sorted({r.time for r in records})
    return (f"{quantity}: {len(records)} over the limit from t = {times[0]:.3f} to "
            f"{times[-1]:.3f} s; worst {worst.value:.4g} {unit} against {worst.limit:.4g} "
            f"{unit} at t = {worst.time:.3f} s, {where}")


def main(argv: Any) -> int:
    parser = build_parser()
    args = parser.parse_args(list(argv))
    need_extras(parser, False, args.plot is not None, "", "--plot")
    from drivekin import choreo
    from drivekin._core import choreocheck

    try:
        traj = choreo.load(args.traj)
        config = None if args.config is None else _project_config(args.config, traj.kind)
        if config is None and traj.config is None:
            raise ValueError(f"{args.traj}: the trajectory carries no robot config: pass "
                             f"--config FILE.chor")
        report = traj.check(config, maxSteerVelocity=args.max_steer_velocity,
                            voltage=args.voltage)
        if args.json:
            with open(args.json, "w", encoding="utf-8") as f:
                json.dump({"file": args.traj, "name": traj.name, "kind": traj.kind,
                           "samples": len(traj.samples), **report.asdict()}, f, indent=1)
        if args.plot:
            choreocheck.plot(report, args.plot, traj.name)
    except (ValueError, OSError, ImportError, MemoryError) as e:
        message = str(e) if not isinstance(e, MemoryError) else "not enough memory"
        emit(f"{PROG} check: error: {escape(message)}", sys.stderr)
        return 2
    name = escape(traj.name)
    if report.ok:
        margins = ", ".join(f"{q} {m:.4f}" for q, m in report.margins.items())
        emit(f"{name}: feasible ({len(traj.samples)} samples, {traj.totalTime:g} s, "
             f"{len(report.warnings)} warnings within the file's rounding); least margin "
             f"1 - value/limit: {margins}")
        return 0
    by_quantity: dict[str, list[Any]] = {}
    for r in report.violations:
        by_quantity.setdefault(r.quantity, []).append(r)
    lines = [f"{name}: infeasible, {len(report.violations)} violations"]
    lines += [_line(q, recs) for q, recs in by_quantity.items()]
    emit("\n".join(lines[:MAX_LINES]))
    return 1
