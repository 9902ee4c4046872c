"""``python -m drivekin``: the command line of the drivetrain demo in :mod:`drivekin.demo`.

This module only parses and validates the arguments and prints the report; the
simulation and the measurements live in :mod:`drivekin.demo`.
"""
from __future__ import annotations

import argparse
import json
import math
import sys

from drivekin.demo import DRIVETRAINS, DT, VISION_DRIVETRAINS, header, run, table


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
        epilog="Example: python -m drivekin --drivetrain mecanum --seconds 60 --max-speed 4",
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
    out = parser.add_mutually_exclusive_group()
    out.add_argument("--quiet", action="store_true",
                     help="print only the results table, without the header")
    out.add_argument("--json", action="store_true",
                     help="print the results as one JSON object instead of text")
    return parser.parse_args(argv)


def main(argv=None) -> int:
    args = parse_args(argv)
    if args.vision and args.drivetrain not in VISION_DRIVETRAINS:
        print(f"python -m drivekin: error: --vision is simulated for "
              f"{', '.join(VISION_DRIVETRAINS)} only, not {args.drivetrain}", file=sys.stderr)
        return 2
    steps = round(args.seconds / DT)
    result = run(args)
    if args.json:
        print(json.dumps(result, indent=2))
    else:
        if not args.quiet:
            print(header(args, steps))
        print(table(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
