"""``python -m drivekin``: the command line of the drivetrain demo in :mod:`drivekin.app.demo`,
and ``python -m drivekin replay LOG.wpilog ...``, the log replay of :mod:`drivekin.replay`.

This module only parses and validates the arguments and prints the reports; the
simulation and the measurements live in :mod:`drivekin.app.demo`, the replay in
:mod:`drivekin.replay`.
"""
from __future__ import annotations

import argparse
import importlib.util
import json
import math
import os
import sys
import time

from drivekin.app.demo import DRIVETRAINS, DT, VISION_DRIVETRAINS, header, run, table


# Option ranges. The upper bounds keep a run's memory and time sane (--seconds sizes the
# per-step sample array) and the inputs physically meaningful; NaN and infinities fail
# every comparison and are refused with the rest.
SECONDS_RANGE = (0.02, 3600.0)          # one 20 ms step .. one hour of robot time
MAX_SPEED_RANGE = (0.0, 30.0)           # m/s, exclusive lower bound
MAX_OMEGA_RANGE = (0.0, 100.0)          # rad/s, exclusive lower bound


def _number_option(low: float, high: float, unit: str, low_inclusive: bool):
    """An argparse ``type`` accepting a decimal number in the given range.

    It raises only ArgumentTypeError, whose message argparse prints as is (any other
    exception would make argparse name this function in the error)."""
    expected = (f"a number from {low:g} to {high:g} {unit}" if low_inclusive else
                f"a number greater than {low:g} and at most {high:g} {unit}")

    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        if not ((low <= value if low_inclusive else low < value) and value <= high):
            shown = text if len(text) <= 32 else text[:29] + "..."
            raise argparse.ArgumentTypeError(f"expected {expected}, got {shown!r}")
        return value

    return parse


def parse_args(argv=None):
    parser = argparse.ArgumentParser(
        prog="python -m drivekin",
        description=(
            "Simulate a 50 Hz drivetrain control loop (swerve, mecanum, differential or "
            "differential swerve) on "
            "drivekin's allocation-free path and report per-step latency against the 20 ms "
            "budget, allocator activity and the final odometry pose. A scripted driver "
            "(forward, strafe, spin, figure-eight while rotating, return, stop; repeating "
            "every 30 s) feeds the commands: field-relative for swerve, differential swerve "
            "and mecanum, "
            "arcade-style (forward and rotation only) for differential. Each step runs "
            "inverse kinematics, desaturates, applies a wheel response model (wheel-speed "
            "lag; for swerve also optimize, a steering rate limit and cosine scaling; for "
            "differential swerve pods motor velocities, a motor limit at the --max-speed of "
            "pure driving, simulated motors and module positions from motor positions, "
            "checked against the simulated truth) and "
            "updates the drivetrain's odometry class from the wheel distances and a "
            "simulated gyro. 'deadwheel' is the mecanum robot with wheel slip, localized "
            "both by its drive encoders and by three dead wheels, with both errors against "
            "the simulated truth. The loop runs as fast as it can (no sleeping); it is run twice "
            "on identical simulations: once timed with tracemalloc off, once under "
            "tracemalloc to count allocations."),
        epilog="Example: python -m drivekin --drivetrain mecanum --seconds 60 --max-speed 4. "
               "Replay a WPILib DataLog: python -m drivekin replay LOG.wpilog (see "
               "python -m drivekin replay --help).",
    )
    parser.add_argument("--seconds", type=_number_option(*SECONDS_RANGE, "s", True),
                        default=180.0, metavar="S",
                        help="simulated robot time in seconds, 0.02 to 3600; "
                             "steps = S / 0.02 (default: 180, i.e. 9000 steps)")
    parser.add_argument("--max-speed", type=_number_option(*MAX_SPEED_RANGE, "m/s", False),
                        default=4.5, metavar="MPS",
                        help="attainable wheel speed in m/s (up to 30): full stick "
                             "deflection and the desaturation limit (default: 4.5)")
    parser.add_argument("--max-omega", type=_number_option(*MAX_OMEGA_RANGE, "rad/s", False),
                        default=2.0 * math.pi, metavar="RADPS",
                        help="rotation rate in rad/s (up to 100) at full rotation stick "
                             "(default: 2π)")
    parser.add_argument("--drivetrain", choices=list(DRIVETRAINS), default="swerve",
                        help="drivetrain to simulate, with its kinematics and odometry classes "
                             "(default: swerve)")
    parser.add_argument("--vision", action="store_true",
                        help="swerve only: wheels that wear (odometry drifts) and a simulated "
                             "camera (AprilTag poses every 40 ms, 60 ms latency, noise) fed to "
                             "SwerveDrivePoseEstimator; reports odometry-only and estimator "
                             "error against the simulated truth")
    parser.add_argument("--log", type=_new_file("--log"), metavar="FILE.wpilog",
                        help="also write the simulated run (true pose, odometry, gyro, module "
                             "or wheel positions, commanded and measured module states) as a "
                             "WPILib DataLog, recorded from a third, unmeasured run of the "
                             "same simulation (needs robotpy-wpiutil: "
                             "pip install \"drivekin[log]\")")
    parser.add_argument("--plot", type=_new_file("--plot"), metavar="FILE.png",
                        help="also draw the true and odometry paths and the position error "
                             "into a PNG (needs matplotlib: pip install \"drivekin[plot]\")")
    out = parser.add_mutually_exclusive_group()
    out.add_argument("--quiet", action="store_true",
                     help="print only the results table, without the header")
    out.add_argument("--json", action="store_true",
                     help="print the results as one JSON object instead of text")
    args = parser.parse_args(argv)
    _need_extras(parser, args.log is not None, args.plot is not None, "--log", "--plot")
    return args


def _new_file(option: str):
    """An argparse ``type`` for an output file: its directory must exist."""
    def parse(text: str) -> str:
        shown = text if len(text) <= 60 else text[:57] + "..."
        if not text or text.endswith(os.sep) or os.path.isdir(text):
            raise argparse.ArgumentTypeError(f"expected a file name, got {shown!r}")
        folder = os.path.dirname(text) or "."
        if not os.path.isdir(folder):
            raise argparse.ArgumentTypeError(f"the folder of {shown!r} does not exist")
        return text
    return parse


def _need_extras(parser, log: bool, plot: bool, log_option: str, plot_option: str) -> None:
    """Refuse options whose optional dependency is missing before any work is done."""
    if log and importlib.util.find_spec("wpiutil") is None:
        parser.error(f'{log_option} needs robotpy-wpiutil: pip install "drivekin[log]"')
    if plot and importlib.util.find_spec("matplotlib") is None:
        parser.error(f'{plot_option} needs matplotlib: pip install "drivekin[plot]"')


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv[:1] == ["replay"]:
        return replay_main(argv[1:])
    args = parse_args(argv)
    if args.vision and args.drivetrain not in VISION_DRIVETRAINS:
        print(f"python -m drivekin: error: --vision is simulated for "
              f"{', '.join(VISION_DRIVETRAINS)} only, not {args.drivetrain}", file=sys.stderr)
        return 2
    steps = round(args.seconds / DT)
    result = run(args)
    written = []
    if args.log or args.plot:
        written = _record(args, steps, result)
        if written is None:
            return 1
    if args.json:
        print(json.dumps(result, indent=2))
    else:
        if not args.quiet:
            print(header(args, steps))
        print(table(result))
        for line in written:
            print(line)
    return 0


def _record(args, steps: int, result: dict):
    """--log/--plot: record a third run and write it; report lines, or None on error."""
    from drivekin.app.demo import record

    rec = record.record(args, steps)
    same = record.matches(rec, result["final_pose"])
    lines = []
    try:
        if args.log:
            n = record.write_log(args.log, rec)
            lines.append(f"wrote {args.log}: {n} entries, {steps} samples each at 50 Hz")
            result["log"] = {"path": args.log, "entries": n}
        if args.plot:
            title = f"python -m drivekin: {args.drivetrain}" + (
                " --vision" if args.vision else "") + f", {steps * DT:g} s"
            record.plot_run(args.plot, rec, title)
            lines.append(f"wrote {args.plot}")
            result["plot"] = {"path": args.plot}
    except OSError as e:
        print(f"python -m drivekin: error: {e}", file=sys.stderr)
        return None
    result["recorded_run_matches"] = same
    if not same:
        lines.append("warning: the recorded run did not end at the measured run's pose")
    return lines


# ---------------------------------------------------------------------------------------
# python -m drivekin replay

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


def replay_parser() -> argparse.ArgumentParser:
    from drivekin.replay import DRIVETRAINS

    p = argparse.ArgumentParser(
        prog="python -m drivekin replay",
        description=(
            "Recompute a robot's odometry from WPILib DataLogs (.wpilog): the gyro and "
            "wheel or module positions the robot logged go through drivekin's odometry, "
            "optionally with corrected geometry, and the result is compared with the pose "
            "the robot logged. Entries are found by type (struct:SwerveModulePosition[], "
            "struct:MecanumDriveWheelPositions, struct:DifferentialDriveWheelPositions; "
            "gyro struct:Rotation2d; pose struct:Pose2d) unless named. The odometry is "
            "updated at every wheel-position sample with the latest gyro sample at or "
            "before it (or the gyro interpolated, --gyro-align interpolate). For each log "
            "it prints the drift statistics and writes LOG-replay.wpilog (the original "
            "entries plus /drivekin/ReplayPose and /drivekin/ReplayError); --plot also "
            "draws LOG-replay.png. Progress goes to stderr. Exit status: 0 if every log "
            "was replayed, 1 if any failed, 2 for bad options."),
        epilog="Example: python -m drivekin replay match.wpilog --wheel-scale 1.02 --plot")
    p.add_argument("logs", nargs="+", metavar="LOG.wpilog", help="DataLog files to replay")
    p.add_argument("--drivetrain", choices=("auto",) + DRIVETRAINS, default="auto",
                   help="drivetrain (default: from the type of the positions entry)")
    p.add_argument("--positions", metavar="NAME",
                   help="entry of wheel or module positions (a double[] entry for dead "
                        "wheels or [left, right])")
    p.add_argument("--gyro", metavar="NAME",
                   help="gyro entry: struct:Rotation2d, or double with --gyro-units")
    p.add_argument("--gyro-units", choices=("rad", "deg"),
                   help="units of a double gyro entry")
    p.add_argument("--pose", metavar="NAME", help="the robot's logged pose (struct:Pose2d)")
    p.add_argument("--truth", metavar="NAME",
                   help="a second struct:Pose2d entry to compare with (e.g. a simulation's "
                        "true pose)")
    p.add_argument("--module", type=_point("--module", 2), action="append", metavar="X,Y",
                   help="module (swerve) or wheel (mecanum: FL, FR, RL, RR) offset from the "
                        "robot centre in m, once per module in the log's order; default: "
                        "the log's SwerveDriveKinematics/MecanumDriveKinematics entry")
    p.add_argument("--dead-wheel", type=_point("--dead-wheel", 3), action="append",
                   metavar="X,Y,DEG",
                   help="dead wheel pose (contact point in m, rolling direction in degrees), "
                        "once per wheel in the order of the positions array")
    p.add_argument("--trackwidth", type=_number_option(0.0, 100.0, "m", False),
                   metavar="M", help="differential trackwidth, for --heading wheels")
    p.add_argument("--heading", choices=("gyro", "wheels"), default="gyro",
                   help="heading source; 'wheels' (differential only) ignores the gyro")
    p.add_argument("--wheel-scale", type=_number_option(0.0, 10.0, "", False), default=1.0,
                   metavar="K",
                   help="multiply every wheel distance by K (true wheel radius / the radius "
                        "the robot used; default 1)")
    p.add_argument("--gyro-align", choices=("latest", "interpolate"), default="latest",
                   help="gyro sample used at each wheel sample (default: latest)")
    p.add_argument("--start", choices=("logged", "origin"), default="logged",
                   help="start pose: the logged pose at the first sample (default) or the "
                        "origin")
    p.add_argument("--compare", choices=("hold", "interpolate"), default="hold",
                   help="replayed pose at a logged pose's timestamp: the latest one at or "
                        "before it, as the robot's getPose() (default), or interpolated")
    p.add_argument("--ragged", choices=("error", "drop"), default="error",
                   help="arrays that change length between records: stop (default) or drop "
                        "the records of other lengths")
    p.add_argument("--allow-truncated", action="store_true",
                   help="replay the complete records of a truncated log instead of stopping")
    p.add_argument("--out-dir", metavar="DIR",
                   help="folder for the outputs (default: beside each log)")
    p.add_argument("--no-write", action="store_true",
                   help="do not write LOG-replay.wpilog")
    p.add_argument("--plot", action="store_true",
                   help='draw LOG-replay.png (needs matplotlib: pip install "drivekin[plot]")')
    p.add_argument("--json", action="store_true",
                   help="print the results as a JSON list instead of text")
    return p


def _progress(text: str) -> None:
    print(text, file=sys.stderr, flush=True)


def _join_negative_points(argv):
    """``--module -0.3,0.3``: argparse takes a value starting with '-' for an option, so
    the value is attached (``--module=-0.3,0.3``) before parsing."""
    out = []
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("--module", "--dead-wheel") and i + 1 < len(argv) \
                and argv[i + 1].startswith("-") and "," in argv[i + 1]:
            out.append(f"{a}={argv[i + 1]}")
            i += 2
            continue
        out.append(a)
        i += 1
    return out


def replay_main(argv) -> int:
    parser = replay_parser()
    args = parser.parse_args(_join_negative_points(list(argv)))
    if args.out_dir is not None and not os.path.isdir(args.out_dir):
        parser.error(f"argument --out-dir: {args.out_dir!r} is not a folder")
    if args.heading == "wheels" and args.trackwidth is None:
        parser.error("--heading wheels needs --trackwidth")
    if importlib.util.find_spec("wpiutil") is None:
        parser.error('reading .wpilog files needs robotpy-wpiutil: pip install "drivekin[log]"')
    _need_extras(parser, False, args.plot, "", "--plot")
    from drivekin import datalog, replay

    config = replay.ReplayConfig(
        drivetrain=args.drivetrain, positions=args.positions, gyro=args.gyro,
        pose=args.pose, truth=args.truth, gyroUnits=args.gyro_units, modules=args.module,
        deadWheels=args.dead_wheel, trackwidth=args.trackwidth, heading=args.heading,
        wheelScale=args.wheel_scale, gyroAlign=args.gyro_align, start=args.start,
        compare=args.compare,
        ragged=args.ragged, allowTruncated=args.allow_truncated)
    failed = 0
    results = []
    total = len(args.logs)
    for i, path in enumerate(args.logs, 1):
        tag = f"[{i}/{total}] {path}"
        t0 = time.perf_counter()
        try:
            _progress(f"{tag}: reading")
            log = datalog.read(path, allowTruncated=args.allow_truncated)
            _progress(f"{tag}: replaying")
            result = replay.replayLog(log, config)
            stem = os.path.splitext(os.path.basename(path))[0]
            folder = args.out_dir if args.out_dir is not None else (os.path.dirname(path) or ".")
            outputs = []
            if not args.no_write:
                out = os.path.join(folder, stem + "-replay.wpilog")
                _progress(f"{tag}: writing {out}")
                replay.writeReplayLog(result, out)
                outputs.append(out)
            if args.plot:
                png = os.path.join(folder, stem + "-replay.png")
                _progress(f"{tag}: plotting {png}")
                replay.plotReplay(result, png)
                outputs.append(png)
        except (datalog.DataLogError, OSError, ValueError, TypeError, ImportError) as e:
            failed += 1
            message = str(e) if isinstance(e, datalog.DataLogError) else (
                f"{e}" if isinstance(e, (OSError, ImportError)) else f"{type(e).__name__}: {e}")
            if isinstance(e, OSError) and e.filename and str(e.filename) not in message:
                message = f"{e.filename}: {message}"
            first = message if message.startswith(path) else f"{path}: {message}"
            print(f"python -m drivekin replay: error: {first}", file=sys.stderr)
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
            print(replay.report(result, tuple(outputs)))
    if args.json:
        print(json.dumps(results, indent=2))
    if total > 1:
        _progress(f"replayed {total - failed} of {total} logs")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
