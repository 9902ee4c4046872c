"""``python -m drivekin calibrate LOG.wpilog [LOG ...]``: the command line of
:mod:`drivekin.calibrate` (:mod:`drivekin.app.cli` hands it the arguments after
``calibrate``).

This module only parses the arguments, reports progress and prints or writes the results;
the fits are :func:`drivekin.calibrate.calibrate`. Nothing is written unless every log
was calibrated.
"""
from __future__ import annotations

import argparse
import importlib.util
import json
import os
import sys
import time

from drivekin._core.display import escape
from drivekin.app.options import Parser, docs_url, emit, new_file
from drivekin.app.replay_cli import add_log_options, check_log_options, log_config, parse


def build_parser() -> argparse.ArgumentParser:
    p = Parser(
        prog="python -m drivekin calibrate",
        description=(
            "Estimate a robot's true geometry from its WPILib DataLogs (.wpilog): wheel "
            "radius scale per module or side, a differential drive's effective trackwidth, "
            "dead-wheel positions, swerve steer offsets and, against a reference pose "
            "(--truth: vision, or a simulation's true pose), the gyro scale and a joint fit "
            "of them all that minimises the drift. The logs are replayed as python -m "
            "drivekin replay does (the same options say what they hold and the geometry "
            "the robot used), cut into spin-in-place, straight and turning windows, and "
            "each parameter is fitted where it is observable, with a 95 % interval; one "
            "the logs cannot determine is reported as such, with the manoeuvre or "
            "reference that would. Prints a table, the windows, the drift before and "
            "after, and the replay command line with the fitted values. Exit status: 0 "
            "if the logs were calibrated, 1 if not, 2 for bad options."),
        epilog="Example: python -m drivekin calibrate practice.wpilog --truth /Vision/Pose "
               f"--json fit.json. Needs scipy: pip install \"drivekin[calibrate]\". "
               f"Documentation: {docs_url()}")
    add_log_options(p, "calibrate from")
    p.add_argument("--json", metavar="FILE", type=new_file("--json"),
                   help='write {"parameters": {NAME: {"value", "uncertainty", "determined", '
                        '"why"}}, ...} to FILE (uncertainty: the half-width of the 95 %% '
                        'interval)')
    p.add_argument("--plot", metavar="FILE.png", type=new_file("--plot"),
                   help='draw the replay before and after the fit (needs matplotlib: pip '
                        'install "drivekin[plot]")')
    p.add_argument("--force", action="store_true",
                   help="overwrite --json and --plot files that exist")
    p.add_argument("--list", action="store_true",
                   help="list each log's entries as python -m drivekin replay LOG --list "
                        "does (what the replay would use each for) and calibrate nothing")
    return p


def _progress(text: str) -> None:
    emit(text, sys.stderr)


def _error(message: str) -> int:
    print(f"python -m drivekin calibrate: error: {message}", file=sys.stderr)
    return 1


def _list(paths, config, allow_truncated: bool) -> int:
    """What ``replay LOG --list`` prints, for each log."""
    from drivekin import datalog, replay

    for i, path in enumerate(paths):
        try:
            log = datalog.read(path, allowTruncated=allow_truncated)
            text = replay.listing(log, config)
        except (datalog.DataLogError, OSError, ValueError) as e:
            return _error(str(e) if isinstance(e, datalog.DataLogError) or
                          getattr(e, "filename", None) is None else f"{e.filename}: {e}")
        print(("\n" if i else "") + text)
    return 0


def main(argv) -> int:
    parser = build_parser()
    args = parse(parser, argv)
    check_log_options(parser, args)
    if args.list:
        return _list(args.logs, log_config(args), args.allow_truncated)
    try:
        scipy = importlib.util.find_spec("scipy")
    except (ImportError, ValueError):          # a broken installation
        scipy = None
    if scipy is None:
        return _error('calibrate needs scipy: pip install "drivekin[calibrate]"')
    if args.plot and importlib.util.find_spec("matplotlib") is None:
        parser.error('--plot needs matplotlib: pip install "drivekin[plot]"')
    for out in (args.json, args.plot):
        if out and os.path.exists(out) and not args.force:
            parser.error(f"{out} already exists: pass --force to overwrite it")
    from drivekin import calibrate, datalog

    config = log_config(args)
    t0 = time.perf_counter()
    try:
        _progress(f"calibrating from {len(args.logs)} log(s)")
        result = calibrate.calibrate(args.logs, config)
        if args.plot:
            _progress(f"plotting {args.plot}")
            calibrate.plotCalibration(result, args.plot)
        if args.json:
            _progress(f"writing {args.json}")
            text = json.dumps(result.asdict(), indent=2)
            with open(args.json, "w", encoding="utf-8") as f:
                f.write(text + "\n")
    except (datalog.DataLogError, OSError, ValueError, TypeError, ImportError,
            MemoryError) as e:
        message = str(e) if isinstance(e, datalog.DataLogError) else (
            "not enough memory to read the logs" if isinstance(e, MemoryError) else
            f"{e}" if isinstance(e, (OSError, ImportError)) else f"{type(e).__name__}: {e}")
        if isinstance(e, OSError) and e.filename and str(e.filename) not in message:
            message = f"{e.filename}: {message}"
        emit(f"python -m drivekin calibrate: error: {escape(message)}", sys.stderr)
        return 1
    _progress(f"done in {time.perf_counter() - t0:.2f} s")
    emit(calibrate.report(result))
    return 0
