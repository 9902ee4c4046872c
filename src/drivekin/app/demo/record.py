"""``--log`` and ``--plot``: the demo's simulated run as a WPILib DataLog and a PNG.

The measured passes are left alone: after them, a third simulation, identical to theirs
(the demo is deterministic), is stepped while every step's state is copied into numpy
arrays; the log and the plot are written from those arrays afterwards. Recording is
plain Python that allocates freely, so it must never run inside a measured loop.

Entries (sample k, the state after step k + 1, at (k + 1)·20 ms: a DataLog timestamp
of 0 would mean "now")::

    /Odometry/Robot                  struct:Pose2d      the drivetrain's odometry pose
    /Sim/TruePose                    struct:Pose2d      the simulated truth
    /Drive/Gyro                      struct:Rotation2d  the simulated gyro
    /Drive/ChassisVelocities         struct:ChassisVelocities  measured (forward kinematics)
    /Drive/Kinematics                struct:SwerveDriveKinematics__4 (or Mecanum-/Differential-
                                     DriveKinematics), once
    swerve, diffswerve:
    /Drive/ModulePositions           struct:SwerveModulePosition[]
    /Drive/ModuleStates/Commanded    struct:SwerveModuleVelocity[]  after desaturation
    /Drive/ModuleStates/Measured     struct:SwerveModuleVelocity[]
    mecanum, deadwheel:
    /Drive/WheelPositions            struct:MecanumDriveWheelPositions
    /Drive/WheelVelocities/Commanded struct:MecanumDriveWheelVelocities
    /Drive/WheelVelocities/Measured  struct:MecanumDriveWheelVelocities
    differential: the same three as DifferentialDriveWheel... structs
    deadwheel:   /Drive/DeadWheelPositions (double[], m) and /DriveEncoders/Pose
    --vision:    /PoseEstimator/Robot (struct:Pose2d)

The truth is the drivetrain's own where it simulates one (``--vision``, deadwheel,
diffswerve); otherwise it is the wheel model's motion (its forward kinematics
integrated exactly over each step), which the odometry follows up to rounding.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from drivekin import Pose2d, SwerveDriveKinematics, Twist2d
from drivekin._core.plotting import pyplot
from drivekin.app.demo.measure import Simulation
from drivekin.app.demo.script import DT

_DT_US = round(DT * 1e6)


def _pose(p: Pose2d) -> tuple[float, float, float]:
    return (p.x, p.y, p.getRotation().getRadians())


def _module(s: Any, field: str) -> tuple[float, float]:
    return (getattr(s, field), s.angle.getRadians())


def record(args: Any, steps: int) -> dict[str, Any]:
    """Step a fresh simulation ``steps`` times and return its recorded arrays (entry name
    → (type string, values)), the timestamps ``t`` (µs), the kinematics value and the
    final odometry pose."""
    sim = Simulation.from_args(args)
    drive: Any = sim.drive
    swerve = isinstance(getattr(drive, "kinematics", None), SwerveDriveKinematics)
    diff = args.drivetrain == "differential"
    own_truth = hasattr(drive, "truth") or hasattr(drive, "truth_odometry")
    rows: dict[str, list[Any]] = {}
    types: dict[str, str] = {}

    def put(name: str, type_string: str, value: Any) -> None:
        types[name] = type_string
        rows.setdefault(name, []).append(value)

    truth = Pose2d()
    for _ in range(steps):
        sim.step()
        m = drive.measured
        if hasattr(drive, "truth_odometry"):
            truth = drive.truth_odometry.getPose()
        elif own_truth:
            truth = drive.truth
        else:
            truth = truth.exp(Twist2d(m.vx * DT, m.vy * DT, m.omega * DT))
        put("/Odometry/Robot", "struct:Pose2d", _pose(drive.pose))
        put("/Sim/TruePose", "struct:Pose2d", _pose(truth))
        put("/Drive/Gyro", "struct:Rotation2d", drive.gyro.getRadians())
        put("/Drive/ChassisVelocities", "struct:ChassisVelocities", (m.vx, m.vy, m.omega))
        if swerve:
            measured = getattr(drive, "truth_states", None) or drive.states
            put("/Drive/ModulePositions", "struct:SwerveModulePosition[]",
                [_module(p, "distance") for p in drive.positions])
            put("/Drive/ModuleStates/Commanded", "struct:SwerveModuleVelocity[]",
                [_module(s, "velocity") for s in drive.targets])
            put("/Drive/ModuleStates/Measured", "struct:SwerveModuleVelocity[]",
                [_module(s, "velocity") for s in measured])
        elif diff:
            put("/Drive/WheelPositions", "struct:DifferentialDriveWheelPositions",
                (drive.left, drive.right))
            for label, w in (("Commanded", drive.targets), ("Measured", drive.wheels)):
                put(f"/Drive/WheelVelocities/{label}",
                    "struct:DifferentialDriveWheelVelocities", (w.left, w.right))
        else:
            p = drive.positions
            put("/Drive/WheelPositions", "struct:MecanumDriveWheelPositions",
                (p.frontLeft, p.frontRight, p.rearLeft, p.rearRight))
            for label, w in (("Commanded", drive.targets), ("Measured", drive.wheels)):
                put(f"/Drive/WheelVelocities/{label}", "struct:MecanumDriveWheelVelocities",
                    (w.frontLeft, w.frontRight, w.rearLeft, w.rearRight))
        if hasattr(drive, "dead_positions"):
            put("/Drive/DeadWheelPositions", "double[]", list(drive.dead_positions))
            put("/DriveEncoders/Pose", "struct:Pose2d", _pose(drive.wheel_pose))
        if hasattr(drive, "estimator"):
            put("/PoseEstimator/Robot", "struct:Pose2d",
                _pose(drive.estimator.getEstimatedPosition()))
    t = np.arange(1, steps + 1, dtype=np.int64) * _DT_US
    series = {name: (types[name], np.array(vals, dtype=np.float64))
              for name, vals in rows.items()}
    kinematics = getattr(drive, "kinematics", None)
    return {"t": t, "series": series, "kinematics": kinematics,
            "final_pose": drive.pose, "drivetrain": args.drivetrain,
            "dead_wheels": [(w.x, w.y, w.getRotation().getDegrees())
                            for w in drive.dead.getWheelPoses()]
            if hasattr(drive, "dead") else None}


def write_log(path: str, rec: dict[str, Any]) -> int:
    """Write the recording as a .wpilog; return the number of entries written."""
    from drivekin import datalog

    t = rec["t"]
    with datalog.Writer(path, extraHeader='{"producer":"python -m drivekin"}') as w:
        if rec["kinematics"] is not None:
            w.append("/Drive/Kinematics", rec["kinematics"], int(t[0]))
        for name, (type_string, values) in rec["series"].items():
            w.appendSeries(name, type_string, t, values)
    return len(rec["series"]) + (rec["kinematics"] is not None)


def plot_run(path: str, rec: dict[str, Any], title: str) -> None:
    """The demo's PNG: the true and odometry paths, and the odometry's position error."""
    plt = pyplot()
    series = rec["series"]
    truth = series["/Sim/TruePose"][1]
    odo = series["/Odometry/Robot"][1]
    seconds = rec["t"] / 1e6
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(12, 5.2),
                                  gridspec_kw={"width_ratios": [1.15, 1]})
    try:
        ax.plot(truth[:, 0], truth[:, 1], color="0.55", lw=3.0, alpha=0.6,
                label="truth (/Sim/TruePose)")
        ax.plot(odo[:, 0], odo[:, 1], color="tab:blue", lw=1.2,
                label="odometry (/Odometry/Robot)")
        if "/PoseEstimator/Robot" in series:
            est = series["/PoseEstimator/Robot"][1]
            ax.plot(est[:, 0], est[:, 1], color="tab:green", lw=1.0,
                    label="pose estimator (/PoseEstimator/Robot)")
        ax.plot([0.0], [0.0], "o", color="k", ms=5, label="start")
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)
        ax.set_title(title, fontsize=10)
        err = np.hypot(odo[:, 0] - truth[:, 0], odo[:, 1] - truth[:, 1])
        ax2.plot(seconds, err * 100.0, color="tab:blue",
                 label=f"odometry − truth: final {err[-1] * 100:.1f} cm, "
                       f"max {err.max() * 100:.1f} cm")
        if "/PoseEstimator/Robot" in series:
            est = series["/PoseEstimator/Robot"][1]
            e2 = np.hypot(est[:, 0] - truth[:, 0], est[:, 1] - truth[:, 1])
            ax2.plot(seconds, e2 * 100.0, color="tab:green",
                     label=f"estimator − truth: final {e2[-1] * 100:.1f} cm")
        ax2.set_xlabel("time (s)")
        ax2.set_ylabel("position error (cm)")
        ax2.grid(True, alpha=0.3)
        ax2.legend(loc="upper left", fontsize=8)
        ax2.set_title("position error against the simulated truth", fontsize=10)
        fig.tight_layout()
        fig.savefig(path, dpi=100, format="png")
    finally:
        plt.close(fig)


def matches(rec: dict[str, Any], final_pose: dict[str, float]) -> bool:
    """Whether the recorded run ended exactly where the measured run did (it must: the
    same script on the same simulation)."""
    p = rec["final_pose"]
    return final_pose == {"x_m": p.x, "y_m": p.y,
                          "heading_deg": p.getRotation().getDegrees()}
