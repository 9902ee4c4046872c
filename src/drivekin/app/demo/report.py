"""The demo's text report: header and results table."""
from __future__ import annotations

import drivekin
from drivekin.app.demo.drivetrains import drivetrain_class, make_drivetrain
from drivekin.app.demo.script import BUDGET_NS, DT, JoystickScript


def header(args, steps: int) -> str:
    """The text report's header: robot, script, step chain and run length."""
    drive = make_drivetrain(args.drivetrain, args.max_speed, args.vision,
                            getattr(args, "setpoint_generator", False))
    segments = " · ".join(f"{name} {d:g} s" for name, d in JoystickScript.SEGMENTS)
    return "\n".join([
        f"drivekin {drivekin.__version__} — simulated 50 Hz {drive.name} drive control loop, "
        "allocation-free path",
        f"  robot    {drive.describe()}",
        f"  odometry {drive.ODOMETRY.__name__}, gyro = {drive.GYRO[0]}",
        f"           {drive.GYRO[1]}",
        f"  limits   wheel speed {args.max_speed:g} m/s, joystick rotation "
        f"{args.max_omega:.2f} rad/s",
        f"  script   {drive.INPUT}, repeats every {JoystickScript.CYCLE:g} s:",
        f"           {segments}",
        *(f"  {'step' if i == 0 else '':<8} {line}" for i, line in enumerate(drive.chain())),
        f"  run      {steps * DT:g} s robot time = {steps} steps, flat out (no sleeping);",
        "           pass 1 times each step (tracemalloc off), pass 2 counts allocations",
        "           (tracemalloc on); one warm-up script cycle before each pass",
        "",
    ])


def table(r: dict) -> str:
    """The text report's results table for a :func:`run` result."""
    lat, bud, al, g, pose = (r["latency_us"], r["budget_pct"], r["allocations"], r["gc"],
                             r["final_pose"])
    growth = ", ".join(f"{v:+d}" for v in g["count_growth_timing_pass"])
    growth2 = ", ".join(f"{v:+d}" for v in g["count_growth_allocation_pass"])
    rows = [
        ("latency per step", "", ""),
        ("  p50", f"{lat['p50']:.2f} µs", f"{100 * lat['p50'] * 1e3 / BUDGET_NS:.3f} % of 20 ms"),
        ("  p99", f"{lat['p99']:.2f} µs", f"{bud['p99']:.3f} % of 20 ms"),
        ("  max", f"{lat['max']:.2f} µs", f"{100 * lat['max'] * 1e3 / BUDGET_NS:.3f} % of 20 ms"),
        ("  mean", f"{lat['mean']:.2f} µs", f"{bud['mean']:.3f} % of 20 ms"),
        ("  whole loop", f"{r['loop_wall_s'] * 1e3:.1f} ms",
         f"{r['realtime_factor']:,.0f}× real time"),
        ("allocations (pass 2)", "", ""),
        ("  allocator calls", f"{al['allocator_calls']}",
         f"PyMem/PyObject malloc+calloc+realloc in {r['steps']} steps"),
        ("  traced peak - start", f"{al['traced_peak_bytes']} B", "tracemalloc"),
        ("  traced end - start", f"{al['traced_net_bytes']} B", ""),
        ("  live blocks end - start", f"{al['net_blocks']}", "sys.getallocatedblocks()"),
        ("  gc.get_count() growth", f"{growth2}", f"gen 0, 1, 2 (pass 1: {growth})"),
        ("  gc collections", f"{g['collections_timing_pass']}", "during pass 1"),
        ("result", "", ""),
        ("  final pose", f"x {pose['x_m']:.3f} m, y {pose['y_m']:.3f} m",
         f"heading {pose['heading_deg']:.2f}°"),
        ("  distance travelled", f"{r['distance_m']:.2f} m", "odometry path length"),
        ("  passes agree", "yes" if r["passes_agree"] else "NO", "pass 1 pose == pass 2 pose"),
    ]
    rows += drivetrain_class(r["drivetrain"], r.get("vision", False)).report_rows(r)
    w0 = max(len(a) for a, _, _ in rows)
    w1 = max(len(b) for _, b, _ in rows)
    return "\n".join(f"{a:<{w0}}  {b:>{w1}}  {c}".rstrip() if b else a for a, b, c in rows)

