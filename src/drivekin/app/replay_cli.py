"""``python -m drivekin replay LOG.wpilog ...``: the command line of the log replay in
:mod:`drivekin.replay` (:mod:`drivekin.app.cli` hands it the arguments after ``replay``).

This module only parses and validates the arguments, reports progress and prints the
reports; the replay itself is :func:`drivekin.replay.replayLog`.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time

import numpy as np

from drivekin._core.display import escape
from drivekin.app.options import (Parser, attach_negative_values, docs_url, emit,
                                  need_extras, number_option)


def _point(option: str, n: int):
    """An argparse ``type`` for ``n`` comma-separated finite numbers."""
    what = {2: "X,Y in m", 3: "X,Y,DEG (m, m, degrees)"}[n]

    def parse(text: str):
        parts = text.split(",")
        try:
            values = tuple(float(p) for p in parts)
        except ValueError:
            values = ()
        if len(values) != n or not all(math.isfinite(v) for v in values):
            shown = text if len(text) <= 32 else text[:29] + "..."
            raise argparse.ArgumentTypeError(f"expected {what}, got {shown!r}")
        return values
    return parse


def _numbers(option: str, low: float, high: float):
    """An argparse ``type`` for one number, or several comma-separated ones, in (low,
    high] (a list unless there is exactly one)."""
    def parse(text: str):
        try:
            values = [float(p) for p in text.split(",")]
        except ValueError:
            values = []
        if not values or not all(low < v <= high for v in values):
            shown = text if len(text) <= 32 else text[:29] + "..."
            raise argparse.ArgumentTypeError(f"expected a number greater than {low:g} and "
                                             f"at most {high:g} (or several, "
                                             f"comma-separated), got {shown!r}")
        return values[0] if len(values) == 1 else values
    return parse


def add_log_options(p: argparse.ArgumentParser, verb: str) -> None:
    """The options of replay that say what a log holds (entries, units, geometry), shared
    with ``python -m drivekin calibrate``."""
    from drivekin._core.loglayouts import DRIVE_UNITS, GYRO_UNITS, SPEED_UNITS, TURN_UNITS
    from drivekin.replay import DRIVETRAINS

    p.add_argument("logs", nargs="+", metavar="LOG.wpilog", help=f"DataLog files to {verb}")
    p.add_argument("--drivetrain", choices=("auto",) + DRIVETRAINS, default="auto",
                   help="drivetrain (default: from the type of the positions entry)")
    p.add_argument("--positions", metavar="NAME",
                   help="entry of wheel or module positions, or the folder of per-module "
                        "entries that drivekin recognises (e.g. /Drive); a double[] entry "
                        "for dead wheels or [left, right]")
    p.add_argument("--module-entries", action="append", metavar="NAME=DRIVE,ANGLE",
                   help="a swerve module's drive (distance or velocity) and angle entries, "
                        "once per module in module order; or once as DRIVE,ANGLE with "
                        "{module} where the module's name goes (corner or numbered names: "
                        "ordered FL, FR, BL, BR)")
    p.add_argument("--gyro", metavar="NAME",
                   help="gyro entry: struct:Rotation2d, or double with --gyro-units")
    p.add_argument("--gyro-units", choices=GYRO_UNITS,
                   help="units of a double gyro entry (default: from its name or metadata)")
    p.add_argument("--drive-units", choices=DRIVE_UNITS + SPEED_UNITS,
                   help="units of drive positions that the log does not name: metres, feet, "
                        "or radians or rotations of the wheel (with --wheel-radius); a "
                        "speed unit (m/s, ...) says the drive entries are velocities")
    p.add_argument("--turn-units", choices=TURN_UNITS,
                   help="units of module angles logged as plain numbers")
    p.add_argument("--wheel-radius", type=number_option(0.0, 1.0, "m", False), metavar="M",
                   help="wheel radius in m, for drive positions in radians or rotations "
                        "(AdvantageKit's DrivePositionRad)")
    p.add_argument("--wheelbase", type=number_option(0.0, 100.0, "m", False), metavar="L",
                   help="with --trackwidth W: a rectangular swerve or mecanum drive, "
                        "modules at (±L/2, ±W/2) in the order FL, FR, BL, BR")
    p.add_argument("--odometry-rate", choices=("auto", "cycle"), default="auto",
                   help="auto (default): replay the odometry thread's high-rate samples "
                        "when the log holds them (AdvantageKit OdometryTimestamps); cycle: "
                        "the once-per-loop values")
    p.add_argument("--pose", metavar="NAME",
                   help="the robot's logged pose (struct:Pose2d, or struct:Pose3d compared "
                        "in the plane)")
    p.add_argument("--truth", metavar="NAME",
                   help="a second struct:Pose2d or struct:Pose3d entry to compare with (e.g. "
                        "a simulation's true pose)")
    p.add_argument("--module", type=_point("--module", 2), action="append", metavar="X,Y",
                   help="module (swerve) or wheel (mecanum: FL, FR, RL, RR) offset from the "
                        "robot centre in m, once per module in the log's order; default: "
                        "the log's SwerveDriveKinematics/MecanumDriveKinematics entry")
    p.add_argument("--dead-wheel", type=_point("--dead-wheel", 3), action="append",
                   metavar="X,Y,DEG",
                   help="dead wheel pose (contact point in m, rolling direction in degrees), "
                        "once per wheel in the order of the positions array")
    p.add_argument("--trackwidth", type=number_option(0.0, 100.0, "m", False),
                   metavar="W", help="trackwidth in m: a differential drive's, for --heading "
                                     "wheels; with --wheelbase, a rectangular swerve's")
    p.add_argument("--gyro-align", choices=("latest", "interpolate"), default="latest",
                   help="gyro sample used at each wheel sample (default: latest)")
    p.add_argument("--ragged", choices=("error", "drop"), default="error",
                   help="arrays that change length between records: stop (default) or drop "
                        "the records of other lengths")
    p.add_argument("--allow-truncated", action="store_true",
                   help="replay the complete records of a truncated log instead of stopping")


def log_config(args: argparse.Namespace, **more):
    """The ReplayConfig of :func:`add_log_options`' options (plus ``more``)."""
    from drivekin import replay
    return replay.ReplayConfig(
        drivetrain=args.drivetrain, positions=args.positions,
        moduleEntries=args.module_entries, gyro=args.gyro,
        pose=args.pose, truth=args.truth, gyroUnits=args.gyro_units,
        driveUnits=args.drive_units, turnUnits=args.turn_units, wheelRadius=args.wheel_radius,
        modules=args.module, wheelbase=args.wheelbase, odometryRate=args.odometry_rate,
        deadWheels=args.dead_wheel, trackwidth=args.trackwidth, gyroAlign=args.gyro_align,
        ragged=args.ragged, allowTruncated=args.allow_truncated, **more)


def check_log_options(parser: argparse.ArgumentParser, args: argparse.Namespace) -> None:
    if (args.wheelbase is None) != (args.trackwidth is None) and args.wheelbase is not None:
        parser.error("--wheelbase needs --trackwidth (modules at (±L/2, ±W/2))")
    if args.wheelbase is not None and args.module:
        parser.error("give either --module or --trackwidth with --wheelbase, not both")


def build_parser() -> argparse.ArgumentParser:
    p = Parser(
        prog="python -m drivekin replay",
        description=(
            "Recompute a robot's odometry from WPILib DataLogs (.wpilog): the gyro and "
            "wheel or module positions the robot logged go through drivekin's odometry, "
            "optionally with corrected geometry, and the result is compared with the pose "
            "the robot logged. Entries are found through a table of log layouts "
            "(WPILib structs, AdvantageKit and robotpy-pykit inputs with their high-rate "
            "odometry arrays, CTRE's DriveState, per-module and left/right doubles, "
            "double[] wheel arrays, Field2d poses; --list shows what each entry would be "
            "used for) unless named. The odometry is updated at every wheel-position "
            "sample with the latest gyro sample at or before it (or the gyro "
            "interpolated, --gyro-align interpolate). For each log it prints the drift "
            "statistics and writes LOG-replay.wpilog (the original entries plus "
            "/drivekin/ReplayPose and /drivekin/ReplayError; an existing one only with "
            "--force); --plot also "
            "draws LOG-replay.png. Progress goes to stderr. Exit status: 0 if every log "
            "was replayed, 1 if any failed, 2 for bad options."),
        epilog="Example: python -m drivekin replay match.wpilog --wheel-scale 1.02 --plot. "
               f"Documentation: {docs_url()}")
    add_log_options(p, "replay")
    p.add_argument("--heading", choices=("gyro", "wheels"), default="gyro",
                   help="heading source; 'wheels' (differential only) ignores the gyro")
    p.add_argument("--wheel-scale", type=_numbers("--wheel-scale", 0.0, 10.0), default=1.0,
                   metavar="K[,K...]",
                   help="multiply every wheel distance by K (true wheel radius / the radius "
                        "the robot used; default 1), or each module's, wheel's or side's "
                        "by its own K (comma-separated, in the log's order)")
    p.add_argument("--gyro-scale", type=number_option(0.0, 10.0, "", False), default=1.0,
                   metavar="G", help="multiply the gyro's heading changes by G (true / "
                                     "measured; default 1)")
    p.add_argument("--steer-offsets", type=_numbers("--steer-offsets", -360.0, 360.0),
                   metavar="DEG,DEG,...",
                   help="add these angles (degrees, one per swerve module) to the logged "
                        "module angles")
    p.add_argument("--start", choices=("logged", "origin"), default="logged",
                   help="start pose: the logged pose at the first sample (default) or the "
                        "origin")
    p.add_argument("--compare", choices=("hold", "interpolate"), default="hold",
                   help="replayed pose at a logged pose's timestamp: the latest one at or "
                        "before it, as the robot's getPose() (default), or interpolated")
    p.add_argument("--out-dir", metavar="DIR",
                   help="folder for the outputs (default: beside each log)")
    p.add_argument("--no-write", action="store_true",
                   help="do not write LOG-replay.wpilog")
    p.add_argument("--force", action="store_true",
                   help="overwrite outputs that exist (default: stop before replaying)")
    p.add_argument("--list", action="store_true",
                   help="list each log's drivetrain candidates (positions, gyro, pose), "
                        "ranked, with why and the one replay would use, in at most 60 "
                        "lines, and replay nothing")
    p.add_argument("--all", action="store_true",
                   help="with --list: every entry, not only the candidates")
    p.add_argument("--plot", action="store_true",
                   help='draw LOG-replay.png (needs matplotlib: pip install "drivekin[plot]")')
    p.add_argument("--json", action="store_true",
                   help="print the results as a JSON list instead of text")
    return p


def _progress(text: str) -> None:
    emit(text, sys.stderr)


def parse(parser: argparse.ArgumentParser, argv) -> argparse.Namespace:
    """``argv`` parsed, values that start like negative numbers included."""
    return parser.parse_args(attach_negative_values(parser, list(argv)))


def main(argv) -> int:
    parser = build_parser()
    args = parse(parser, argv)
    if args.out_dir is not None and not os.path.isdir(args.out_dir):
        parser.error(f"argument --out-dir: {args.out_dir!r} is not a folder")
    if args.heading == "wheels" and args.trackwidth is None:
        parser.error("--heading wheels needs --trackwidth")
    check_log_options(parser, args)
    writes = not (args.no_write or args.list)
    need_extras(parser, writes, args.plot and not args.list, "writing LOG-replay.wpilog "
                "(--no-write skips it)", "--plot")
    from drivekin import datalog, replay

    config = log_config(
        args, heading=args.heading, wheelScale=args.wheel_scale, gyroScale=args.gyro_scale,
        steerOffsets=(None if args.steer_offsets is None else
                      [math.radians(a) for a in np.atleast_1d(args.steer_offsets)]),
        start=args.start, compare=args.compare)
    failed = 0
    results = []
    total = len(args.logs)
    for i, path in enumerate(args.logs, 1):
        tag = f"[{i}/{total}] {path}"
        t0 = time.perf_counter()
        try:
            _progress(f"{tag}: reading")
            log = datalog.read(path, allowTruncated=args.allow_truncated)
            if args.list:
                if results:
                    print()
                results.append(path)
                emit(replay.listing(log, config, showAll=args.all))
                continue
            stem = os.path.splitext(os.path.basename(path))[0]
            folder = args.out_dir if args.out_dir is not None else (os.path.dirname(path) or ".")
            planned = ([os.path.join(folder, stem + "-replay.wpilog")] if writes else []) + (
                [os.path.join(folder, stem + "-replay.png")] if args.plot else [])
            exists = [f for f in planned if os.path.exists(f)]
            if exists and not args.force:
                raise FileExistsError(f"{' and '.join(exists)} already exist"
                                      f"{'s' if len(exists) == 1 else ''}: pass --force to "
                                      f"overwrite, or --out-dir DIR")
            _progress(f"{tag}: replaying")
            result = replay.replayLog(log, config)
            outputs = []
            for out in planned:
                if out.endswith(".wpilog"):
                    _progress(f"{tag}: writing {out}")
                    replay.writeReplayLog(result, out)
                else:
                    _progress(f"{tag}: plotting {out}")
                    replay.plotReplay(result, out)
                outputs.append(out)
        except (datalog.DataLogError, OSError, ValueError, TypeError, ImportError,
                MemoryError) as e:
            failed += 1
            message = str(e) if isinstance(e, datalog.DataLogError) else (
                f"{e}" if isinstance(e, (OSError, ImportError)) else
                "not enough memory to read it" if isinstance(e, MemoryError) else
                f"{type(e).__name__}: {e}")
            if isinstance(e, OSError) and e.filename and str(e.filename) not in message:
                message = f"{e.filename}: {message}"
            first = message if message.startswith(path) else f"{path}: {message}"
            emit(f"python -m drivekin replay: error: {escape(first)}", sys.stderr)
            continue
        _progress(f"{tag}: done in {time.perf_counter() - t0:.2f} s "
                  f"({len(result.t)} samples)")
        if args.json:
            d = result.asdict()
            d["outputs"] = outputs
            results.append(d)
        else:
            if results:
                print()
            results.append(result)
            emit(replay.report(result, tuple(outputs)))
    if args.json and not args.list:
        print(json.dumps(results, indent=2))
    if total > 1 and not args.list:
        _progress(f"replayed {total - failed} of {total} logs")
    return 1 if failed else 0

