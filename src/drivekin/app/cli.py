"""``python -m drivekin``: the entry point. ``python -m drivekin replay ...`` goes to the
replay's command line (:mod:`drivekin.app.replay_cli`), ``python -m drivekin calibrate
...`` to the calibration's (:mod:`drivekin.app.calibrate_cli`), ``python -m drivekin
choreo check ...`` to the Choreo trajectory check's (:mod:`drivekin.app.choreo_cli`);
anything else is the command line of the drivetrain demo in :mod:`drivekin.app.demo`,
which this module holds.

This module only parses and validates the demo's arguments and prints its reports; the
simulation and the measurements live in :mod:`drivekin.app.demo`.
"""
from __future__ import annotations

import json
import math
import sys

from drivekin.app import calibrate_cli, choreo_cli, replay_cli
from drivekin.app.demo import (DRIVETRAINS, DT, SETPOINT_DRIVETRAINS, VISION_DRIVETRAINS,
                                header, run, table)
from drivekin.app.options import Parser, docs_url, need_extras, new_file, number_option


# Option ranges. The upper bounds keep a run's memory and time sane (--seconds sizes the
# per-step sample array) and the inputs physically meaningful; NaN and infinities fail
# every comparison and are refused with the rest.
SECONDS_RANGE = (0.02, 3600.0)          # one 20 ms step .. one hour of robot time
MAX_SPEED_RANGE = (0.0, 30.0)           # m/s, exclusive lower bound
MAX_OMEGA_RANGE = (0.0, 100.0)          # rad/s, exclusive lower bound


def parse_args(argv=None):
    parser = Parser(
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
               "python -m drivekin replay --help); find the robot's true geometry from its "
               "logs: python -m drivekin calibrate LOG.wpilog; check a Choreo trajectory "
               "against the robot's limits: python -m drivekin choreo check FILE.traj. "
               f"Documentation: {docs_url()}",
    )
    parser.add_argument("--seconds", type=number_option(*SECONDS_RANGE, "s", True),
                        default=180.0, metavar="S",
                        help="simulated robot time in seconds, 0.02 to 3600; "
                             "steps = S / 0.02 (default: 180, i.e. 9000 steps)")
    parser.add_argument("--max-speed", type=number_option(*MAX_SPEED_RANGE, "m/s", False),
                        default=4.5, metavar="MPS",
                        help="attainable wheel speed in m/s (up to 30): full stick "
                             "deflection and the desaturation limit (default: 4.5)")
    parser.add_argument("--max-omega", type=number_option(*MAX_OMEGA_RANGE, "rad/s", False),
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
    parser.add_argument("--setpoint-generator", action="store_true",
                        help="swerve only (with or without --vision): pass the robot-relative "
                             "command through a SwerveSetpointGenerator (default mode: "
                             "steering-rate, drive-torque and wheel-friction limits of a 60 kg "
                             "robot with Kraken X60 drives) with generateSetpointInto, and "
                             "drive the modules with its module velocities instead of "
                             "discretize, inverse kinematics and desaturation; reports the "
                             "generator's time per call and how many steps it limited")
    parser.add_argument("--log", type=new_file("--log"), metavar="FILE.wpilog",
                        help="also write the simulated run (true pose, odometry, gyro, module "
                             "or wheel positions, commanded and measured module states) as a "
                             "WPILib DataLog, recorded from a third, unmeasured run of the "
                             "same simulation (needs robotpy-wpiutil: "
                             "pip install \"drivekin[log]\")")
    parser.add_argument("--plot", type=new_file("--plot"), metavar="FILE.png",
                        help="also draw the true and odometry paths and the position error "
                             "into a PNG (needs matplotlib: pip install \"drivekin[plot]\")")
    out = parser.add_mutually_exclusive_group()
    out.add_argument("--quiet", action="store_true",
                     help="print only the results table, without the header")
    out.add_argument("--json", action="store_true",
                     help="print the results as one JSON object instead of text")
    args = parser.parse_args(argv)
    need_extras(parser, args.log is not None, args.plot is not None, "--log", "--plot")
    return args


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv[:1] == ["replay"]:
        return replay_cli.main(argv[1:])
    if argv[:1] == ["calibrate"]:
        return calibrate_cli.main(argv[1:])
    if argv[:1] == ["choreo"]:
        return choreo_cli.main(argv[1:])
    args = parse_args(argv)
    if args.vision and args.drivetrain not in VISION_DRIVETRAINS:
        print(f"python -m drivekin: error: --vision is simulated for "
              f"{', '.join(VISION_DRIVETRAINS)} only, not {args.drivetrain}", file=sys.stderr)
        return 2
    if args.setpoint_generator and args.drivetrain not in SETPOINT_DRIVETRAINS:
        print(f"python -m drivekin: error: --setpoint-generator is simulated for "
              f"{', '.join(SETPOINT_DRIVETRAINS)} only, not {args.drivetrain}",
              file=sys.stderr)
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
                " --vision" if args.vision else "") + (
                " --setpoint-generator" if args.setpoint_generator else "") + f", {steps * DT:g} s"
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
